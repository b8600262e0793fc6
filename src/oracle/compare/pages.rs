//! The HTML pages of the comparisons beyond one sample per pixel, each one
//! self-contained page in the binary page's frame ([`super::view_block`]: the oracle's
//! image, theirs and the difference side by side, zoomed and panned together; hover a
//! pixel for both answers, click it for its explanation):
//!
//! - grey levels ([`GreyReport::to_html`]): the levels judged against and theirs in grey,
//!   the difference coloured by grey class;
//! - every sample index ([`SampleCompareReport::to_html`]): one block per sample index,
//!   each the binary page's views of that index's comparison (`#sample=S&pixel=X,Y`
//!   opens one pixel of index S);
//! - a conservative set ([`ConservativeReport::to_html`]): the must-pixels, the band and
//!   theirs, the difference by kind (missing, beyond, the band covered or not);
//! - one varying's values ([`ValueReport::to_html`]): the counts by class, the exact
//!   values' first channel and theirs in grey, the classes per pixel (one block per sample
//!   index of a pattern), and the pixels listed with their exact values and theirs.

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::binary::{html_escape as escape, html_page, view_block, EMPTY_COLOUR, MATCHED_COLOUR};
use super::conservative::ConservativeReport;
use super::grey::{GreyClass, GreyReport};
use super::samples::SampleCompareReport;
use super::values::{JudgedValue, TheirValue, ValueClass, ValuePicture, ValueReport};
use super::{Comparison, HtmlInputs};

/// `#rrggbb`.
fn hex(c: [u8; 3]) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// A grey class's colour in the difference view.
fn class_colour(class: GreyClass) -> [u8; 3] {
    match class {
        GreyClass::Quantization => [90, 160, 255],
        GreyClass::Accumulation => [255, 160, 40],
        GreyClass::Conflation => [190, 90, 255],
        GreyClass::Precision => [60, 200, 90],
        GreyClass::Supersampling(_) => [40, 210, 210],
        GreyClass::Gross => [255, 40, 40],
    }
}

/// What a grey class says, in a sentence (its full definition is in the docs of
/// [`GreyClass`]).
fn class_meaning(class: GreyClass) -> &'static str {
    match class {
        GreyClass::Quantization => "their level is another legal rounding of the exact value (or of each shape's own value, the levels added)",
        GreyClass::Accumulation => "their level is (within their arithmetic's reach) a rounding of another semantics' value: they integrate the winding number where the stated semantics is true coverage, or the other way round, or draw the scene as one path",
        GreyClass::Conflation => "their level is (within their arithmetic's reach) a rounding of the shapes blended one by one, source-over: a seam between abutting shapes",
        GreyClass::Precision => "their level lies within fixed- or floating-point error of the exact value: two quanta, or 1/256 of coverage and 2/256 per edge meeting the pixel",
        GreyClass::Supersampling(_) => "their level is a rounding of the share of k x k samples covered, samples on an edge under some tie rule: they supersample",
        GreyClass::Gross => "no class explains their level",
    }
}

/// The page's headline and the two lines every page ends with: the summary, the scene
/// and the command.
fn page(title: &str, blocks: &str, summary: &str, page: &HtmlInputs<'_>) -> String {
    let mut body = format!("<h1>{}</h1>\n{blocks}", escape(title));
    let _ = writeln!(
        body,
        "<details open><summary>Summary</summary><pre id=\"summary\">{}</pre></details>",
        escape(summary)
    );
    let _ = writeln!(
        body,
        "<details><summary>The scene</summary><pre id=\"scene\">{}</pre></details>",
        escape(page.scene_json)
    );
    let _ = writeln!(
        body,
        "<p>Reproduce: <code id=\"command\">{}</code></p>",
        escape(page.command)
    );
    html_page(title, &body)
}

impl GreyReport {
    /// The page: the levels judged against (the exact value's under the named
    /// quantization, or the method's) and theirs in grey, the difference coloured by grey
    /// class; a click on a differing pixel shows its line of the text report and what its
    /// class means. `REPORT.html#pixel=X,Y` opens pixel (X, Y).
    pub fn to_html(&self, inputs: &HtmlInputs<'_>) -> String {
        let title = format!(
            "rasterproof compare --as grey: {} against {}",
            inputs.theirs, inputs.scene
        );
        page(
            &title,
            &self.html_views(""),
            &self.to_text(inputs.scene, inputs.theirs, 0),
            inputs,
        )
    }

    /// The interactive views of the comparison, element ids ending in `suffix` (a grey
    /// hunt's page holds one per finding).
    pub fn html_views(&self, suffix: &str) -> String {
        let headline = if self.identical() {
            "identical: every level is the one judged against".to_string()
        } else {
            // The summary's first line, and the methods that give every level when some
            // do (the first of several named).
            let text = self.levels_text(0);
            let mut lines = text.lines().map(str::trim);
            let mut headline = lines.next().unwrap_or_default().to_string();
            if let Some(methods) = lines
                .next()
                .filter(|l| l.contains("give every level") || l.contains("gives every level"))
            {
                match methods.strip_suffix(':') {
                    Some(many) => {
                        let first = lines.next().unwrap_or_default();
                        headline = format!("{headline}; {many}, the first: {first}");
                    }
                    None => headline = format!("{headline}; {methods}"),
                }
            }
            headline
        };
        view_block(suffix, &headline, &self.html_data())
    }

    /// The views' data: levels per pixel (`levels`, the top level), the difference's
    /// palette index (0 the same level 0, 1 the same level, 2 + the class's place among
    /// the classes present) and each differing pixel's explanation.
    fn html_data(&self) -> Value {
        let classes: Vec<GreyClass> = self.classes().into_keys().collect();
        let mut diff: Vec<u8> = self.judged_levels.iter().map(|&l| u8::from(l != 0)).collect();
        let mut explain = serde_json::Map::new();
        let report = self.levels_text(usize::MAX);
        // The pixel lines of the text report, in the order of `pixels`.
        let lines: Vec<&str> = report.lines().filter(|l| l.starts_with("  (")).collect();
        for (k, p) in self.pixels.iter().enumerate() {
            let i = usize::try_from(u64::from(p.y) * u64::from(self.width) + u64::from(p.x)).unwrap_or(usize::MAX);
            let place = classes.iter().position(|&c| c == p.class).unwrap_or(0);
            if let Some(d) = diff.get_mut(i) {
                *d = u8::try_from(2 + place).unwrap_or(u8::MAX);
            }
            let line = lines.get(k).map_or("", |l| l.trim());
            let text = format!(
                "{line}\n\n{}: {}.\n{}.",
                p.class.name(),
                class_meaning(p.class),
                match self.method {
                    Some(m) => format!("Judged against {} (--method {})", m.describe(), m.name()),
                    None => format!(
                        "Judged against its exact {} coverage quantized by {}",
                        self.semantics.name(),
                        self.quantization.name()
                    ),
                }
            );
            explain.insert(format!("{},{}", p.x, p.y), Value::String(text));
        }
        let palette: Vec<String> = [EMPTY_COLOUR, MATCHED_COLOUR]
            .into_iter()
            .chain(classes.iter().map(|&c| class_colour(c)))
            .map(hex)
            .collect();
        let kinds: Vec<String> = ["the same level, 0".to_string(), "the same level".to_string()]
            .into_iter()
            .chain(classes.iter().map(|c| c.name()))
            .collect();
        let top = (1u32 << self.quantization.bits()) - 1;
        json!({
            "width": self.width,
            "height": self.height,
            "levels": top,
            "ours": self.judged_levels,
            "theirs": self.their_levels,
            "diff": diff,
            "palette": palette,
            "kinds": kinds,
            "explain": explain,
        })
    }
}

impl SampleCompareReport {
    /// The page: per sample index its position, how far the scene was moved to bring it
    /// to the pixel's sample, and the binary page's views of its comparison (element ids
    /// ending in `-S`); `REPORT.html#sample=S&pixel=X,Y` opens pixel (X, Y) of index S.
    pub fn to_html(&self, inputs: &HtmlInputs<'_>) -> String {
        let title = format!(
            "rasterproof compare: {} against {}, {} samples",
            inputs.theirs, inputs.scene, self.pattern
        );
        let mut blocks = String::new();
        for (s, report) in self.samples.iter().enumerate() {
            let moved = self.moved_by.get(s).map_or_else(String::new, |[dx, dy]| {
                format!(" (the scene moved by ({dx}, {dy}) to bring it to the pixel's sample)")
            });
            // A sample index that differs is open; an identical one closed (its views
            // are there for a look, and `#sample=S&pixel=X,Y` opens it).
            let _ = writeln!(
                blocks,
                "<details class=\"sample\" id=\"sample-{s}\"{}><summary><h2 style=\"display: inline\">Sample {s} at {}{}: {}</h2></summary>",
                if report.identical() { "" } else { " open" },
                escape(&self.pattern.position_text(s)),
                escape(&moved),
                match report.pixels.len() {
                    0 => "identical".to_string(),
                    1 => "1 pixel differs".to_string(),
                    n => format!("{n} pixels differ"),
                }
            );
            blocks.push_str(&report.html_views(&format!("-{s}")));
            blocks.push_str("</details>\n");
        }
        page(&title, &blocks, &self.to_text(inputs.scene, inputs.theirs, 0), inputs)
    }
}

impl ConservativeReport {
    /// The page: the rule's pixels (white must be covered, grey may be: the band) and
    /// theirs, the difference by kind (missing, beyond, the band covered or not); a click
    /// on a pixel of a kind shows its line of the text report.
    pub fn to_html(&self, inputs: &HtmlInputs<'_>) -> String {
        let title = format!(
            "rasterproof compare --conservative {}: {} against {}",
            self.rule, inputs.theirs, inputs.scene
        );
        let headline = if self.identical() {
            "right: every must-pixel covered, none beyond the may-pixels".to_string()
        } else {
            format!(
                "{} missing, {} beyond the uncertainty region, {} degenerate triangles vanished",
                self.missing.len(),
                self.beyond.len(),
                self.vanished.len()
            )
        };
        let blocks = view_block("", &headline, &self.html_data());
        page(&title, &blocks, &self.to_text(inputs.scene, inputs.theirs, 0), inputs)
    }

    /// The views' data: the rule's answer (0 must not, 1 may, 2 must) and theirs (0 or 1)
    /// as labelled values, the difference (0 neither, 1 covered where it must be, 2 the
    /// band covered, 3 the band left, 4 missing, 5 beyond) and each kind's explanation.
    fn html_data(&self) -> Value {
        let diff: Vec<u8> = self
            .oracle
            .iter()
            .zip(&self.covered)
            .map(|(&rule, &covered)| match (rule, covered) {
                (2, true) => 1,
                (1, true) => 2,
                (1, false) => 3,
                (2, false) => 4,
                (0, true) => 5,
                _ => 0,
            })
            .collect();
        let mut explain = serde_json::Map::new();
        for (x, y, ids) in &self.missing {
            explain.insert(
                format!("{x},{y}"),
                json!(format!(
                    "({x}, {y}) missing: triangles {ids:?} overlap the pixel's square, so it must be covered"
                )),
            );
        }
        for (x, y) in &self.beyond {
            explain.insert(
                format!("{x},{y}"),
                json!(format!(
                    "({x}, {y}) beyond: no triangle's uncertainty region reaches the pixel, so it must not be covered"
                )),
            );
        }
        for (x, y, ids) in &self.band_covered {
            explain.insert(
                format!("{x},{y}"),
                json!(format!(
                    "({x}, {y}) band, covered: within the uncertainty region of triangles {ids:?}, not overlapped: either answer is right"
                )),
            );
        }
        let palette: Vec<String> = [
            EMPTY_COLOUR,
            MATCHED_COLOUR,
            [150, 200, 150],
            [60, 60, 90],
            [255, 40, 40],
            [255, 200, 0],
        ]
        .into_iter()
        .map(hex)
        .collect();
        json!({
            "width": self.width,
            "height": self.height,
            "levels": 2,
            "ours": self.oracle,
            "ours_labels": ["must not be covered", "may be covered (the band)", "must be covered"],
            "theirs": self.covered.iter().map(|&c| u8::from(c) * 2).collect::<Vec<u8>>(),
            "theirs_labels": ["not covered", "", "covered"],
            "diff": diff,
            "palette": palette,
            "kinds": ["neither", "covered, must be", "the band, covered", "the band, not covered", "missing", "beyond"],
            "explain": explain,
        })
    }
}

/// A value class's colour in the class view: greys and blues for the classes inside the
/// envelope, warm and saturated colours for those off.
fn value_colour(class: ValueClass) -> [u8; 3] {
    match class {
        ValueClass::Exact => MATCHED_COLOUR,
        ValueClass::F32 => [90, 170, 255],
        ValueClass::FarAnchor => [40, 100, 210],
        ValueClass::Unbounded => [160, 150, 230],
        ValueClass::CentroidRange => [60, 210, 200],
        ValueClass::Affine => [255, 140, 0],
        ValueClass::Perspective => [255, 205, 130],
        ValueClass::ProvokingVertex => [240, 230, 40],
        ValueClass::AtCentre => [230, 60, 230],
        ValueClass::WAtCentre => [255, 110, 170],
        ValueClass::AtSample => [170, 90, 255],
        ValueClass::ChannelsSwapped => [40, 200, 70],
        ValueClass::VerticesPermuted => [160, 240, 80],
        ValueClass::UnormRule => [190, 130, 80],
        ValueClass::Gross => [255, 30, 30],
    }
}

/// At most this many pixels are listed in a values page's table (the off ones first);
/// the views explain every listed pixel.
const VALUES_LISTED_AT_MOST: usize = 200;

impl ValueReport {
    /// The page: the counts by class with their colours and meanings; the views (one block
    /// per sample index under a pattern, `#sample=S&pixel=X,Y` opens one): the exact
    /// values' first channel (rounded to f32) and theirs in grey on a common scale, and the
    /// class of each judged pixel; a click on a listed pixel shows its line of the text
    /// report, what its class means and how to derive it (`explain --as values`); then the
    /// listed pixels (off first) with their exact values and theirs. The views need the
    /// report made with [`super::values::ValueOptions::picture`] (`compare --html` asks
    /// for it); without, the page says so.
    pub fn to_html(&self, inputs: &HtmlInputs<'_>) -> String {
        let title = format!(
            "rasterproof compare --as values: {} against {}",
            inputs.theirs, inputs.scene
        );
        let mut blocks = self.counts_table();
        match &self.picture {
            Some(picture) => blocks.push_str(&self.views(picture, inputs)),
            None => blocks.push_str(
                "<p id=\"no-picture\">No picture: the report was made without the judged samples (ValueOptions::picture).</p>\n",
            ),
        }
        blocks.push_str(&self.listed_table());
        page(&title, &blocks, &self.to_text(inputs.scene, inputs.theirs, 0), inputs)
    }

    /// The counts by class: colour, name, count, whether off, meaning.
    fn counts_table(&self) -> String {
        let unit = if self.samples > 1 { "samples" } else { "pixels" };
        let mut out = format!(
            "<table id=\"counts\"><caption>{} judged {unit} of {:?} ({}, {}), read as {} ({} off)</caption>\n\
             <tr><th></th><th>class</th><th>{unit}</th><th>off</th><th>meaning</th></tr>\n",
            self.judged,
            escape(&self.varying),
            self.interpolation.name(),
            self.sampling.name(),
            escape(&self.read_as),
            self.off()
        );
        for (class, n) in &self.counts {
            let _ = writeln!(
                out,
                "<tr class=\"{}\"><td><i style=\"background: {}\"></i></td><td class=\"class\">{}</td><td class=\"num\">{n}</td><td>{}</td><td>{}</td></tr>",
                if class.is_off() { "off" } else { "inside" },
                hex(value_colour(*class)),
                class.name(),
                if class.is_off() { "off" } else { "no" },
                escape(class.meaning())
            );
        }
        out.push_str("</table>\n");
        out
    }

    /// The pixels listed, off first, at most [`VALUES_LISTED_AT_MOST`]: per channel the
    /// exact value, its nearest f32, theirs and the distance in f32 steps.
    fn listed_table(&self) -> String {
        let listed = self.listed();
        if listed.is_empty() {
            return "<p id=\"listed\">Every judged value is exact: nothing to list.</p>\n".to_string();
        }
        let sample = if self.samples > 1 { "<th>sample</th>" } else { "" };
        let mut out = format!(
            "<table id=\"listed\"><caption>{} listed (every one off, then the first {} inside the envelope), off first</caption>\n\
             <tr><th>pixel</th>{sample}<th>primitive</th><th>class</th><th>channel</th><th>exact</th><th>its nearest f32</th><th>theirs</th><th>f32 steps</th></tr>\n",
            listed.len(),
            super::values::LISTED_INSIDE
        );
        for p in listed.iter().take(VALUES_LISTED_AT_MOST) {
            let rows = p.exact.len().max(1);
            let sample = if self.samples > 1 {
                format!("<td rowspan=\"{rows}\">{}</td>", p.sample)
            } else {
                String::new()
            };
            let _ = write!(
                out,
                "<tr class=\"{}\"><td rowspan=\"{rows}\" class=\"num\">({}, {})</td>{sample}<td rowspan=\"{rows}\">{}</td><td rowspan=\"{rows}\" class=\"class\">{}</td>",
                if p.class.is_off() { "off" } else { "inside" },
                p.x,
                p.y,
                p.id,
                p.class.name()
            );
            for (c, exact) in p.exact.iter().enumerate() {
                if c > 0 {
                    out.push_str("<tr>");
                }
                let nearest = crate::num::exact::nearest_f32(exact)
                    .map_or_else(|| "beyond f32".to_string(), |f| format!("{f:e}"));
                let theirs = p.theirs.get(c).map_or_else(String::new, |t| t.text());
                let steps = p
                    .ulps
                    .get(c)
                    .copied()
                    .flatten()
                    .map_or_else(|| "-".to_string(), |u| u.to_string());
                let _ = writeln!(
                    out,
                    "<td>{c}</td><td class=\"exact\">{}</td><td class=\"num\">{nearest}</td><td class=\"num\">{}</td><td class=\"num\">{steps}</td></tr>",
                    escape(&crate::num::exact::exact_text(exact)),
                    escape(&theirs)
                );
            }
        }
        if listed.len() > VALUES_LISTED_AT_MOST {
            let _ = writeln!(
                out,
                "<tr><td colspan=\"9\">and {} more (compare --format json lists every one)</td></tr>",
                listed.len() - VALUES_LISTED_AT_MOST
            );
        }
        out.push_str("</table>\n");
        out
    }

    /// The views, one block per sample index (each in a `<details>`, open where a sample
    /// is off, under a pattern).
    fn views(&self, picture: &ValuePicture, inputs: &HtmlInputs<'_>) -> String {
        let classes: Vec<ValueClass> = self.counts.iter().map(|&(c, _)| c).collect();
        let number = |t: TheirValue| match t {
            TheirValue::F32(f) => Some(f),
            TheirValue::Level(l) => {
                let top = if self.read_as.starts_with("unorm16") {
                    65535.0
                } else {
                    255.0
                };
                #[allow(clippy::cast_precision_loss)] // a level of at most 16 bits
                Some(l as f32 / top)
            }
        };
        // One grey scale for every view: the least and greatest finite value shown.
        let finite = picture
            .judged
            .iter()
            .flat_map(|j| [j.exact, j.theirs.and_then(number)])
            .flatten()
            .filter(|f| f.is_finite());
        let (lo, hi) = finite.fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), f| (lo.min(f), hi.max(f)));
        let range = if lo <= hi { [lo, hi] } else { [0.0, 1.0] };
        let mut out = String::new();
        for s in 0..self.samples {
            let here: Vec<&JudgedValue> = picture.judged.iter().filter(|j| j.sample == s).collect();
            let off = here.iter().filter(|j| j.class.is_off()).count();
            let headline = format!(
                "{off} of {} judged off; the first two views show channel 0 in grey from {} (dark) to {} (white), black where nothing is judged",
                here.len(),
                range[0],
                range[1]
            );
            let suffix = if self.samples > 1 {
                format!("-{s}")
            } else {
                String::new()
            };
            let data = self.view_data(picture, s, &classes, range, number, inputs);
            let block = view_block(&suffix, &headline, &data);
            if self.samples > 1 {
                let _ = writeln!(
                    out,
                    "<details class=\"sample\" id=\"sample-{s}\"{}><summary><h2 style=\"display: inline\">Sample {s}: {}</h2></summary>\n{block}</details>",
                    if off > 0 { " open" } else { "" },
                    match off {
                        0 => "nothing off".to_string(),
                        1 => "1 value off".to_string(),
                        n => format!("{n} values off"),
                    }
                );
            } else {
                out.push_str(&block);
            }
        }
        out
    }

    /// Sample index `sample`'s block's data: per pixel the exact value's first channel and theirs (`null`
    /// where not judged), the class's palette index (0 not judged, 1 + its place among the
    /// classes present), and each listed pixel's explanation.
    fn view_data(
        &self,
        picture: &ValuePicture,
        sample: usize,
        classes: &[ValueClass],
        range: [f32; 2],
        number: impl Fn(TheirValue) -> Option<f32>,
        inputs: &HtmlInputs<'_>,
    ) -> Value {
        let n = usize::try_from(u64::from(picture.width) * u64::from(picture.height)).unwrap_or(0);
        let index = |x: u32, y: u32| usize::try_from(u64::from(y) * u64::from(picture.width) + u64::from(x)).ok();
        let mut ours: Vec<Option<f32>> = vec![None; n];
        let mut theirs: Vec<Option<f32>> = vec![None; n];
        let mut diff = vec![0u8; n];
        for j in picture.judged.iter().filter(|j| j.sample == sample) {
            let Some(i) = index(j.x, j.y).filter(|&i| i < n) else {
                continue;
            };
            ours[i] = j.exact.filter(|f| f.is_finite());
            theirs[i] = j.theirs.and_then(&number).filter(|f| f.is_finite());
            let place = classes.iter().position(|&c| c == j.class).unwrap_or(0);
            diff[i] = u8::try_from(1 + place).unwrap_or(u8::MAX);
        }
        let mut explain = serde_json::Map::new();
        for p in self.pixels.iter().filter(|p| p.sample == sample) {
            let samples = if self.samples > 1 {
                format!(" --samples {}", self.samples)
            } else {
                String::new()
            };
            let text = format!(
                "{}\n\n{}: {}.\nIts derivation: rasterproof explain {} {},{} --as values {}{samples} (with the options of the comparison).",
                self.pixel_text(p),
                p.class.name(),
                p.class.meaning(),
                inputs.scene,
                p.x,
                p.y,
                inputs.theirs
            );
            explain.insert(format!("{},{}", p.x, p.y), Value::String(text));
        }
        let palette: Vec<String> = std::iter::once(EMPTY_COLOUR)
            .chain(classes.iter().map(|&c| value_colour(c)))
            .map(hex)
            .collect();
        let kinds: Vec<&str> = std::iter::once("not judged")
            .chain(classes.iter().map(|c| c.name()))
            .collect();
        json!({
            "width": picture.width,
            "height": picture.height,
            "range": range,
            "ours": ours,
            "theirs": theirs,
            "diff": diff,
            "palette": palette,
            "kinds": kinds,
            "explain": explain,
        })
    }
}
