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
//!   theirs, the difference by kind (missing, beyond, the band covered or not).

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::binary::{html_escape as escape, html_page, view_block, EMPTY_COLOUR, MATCHED_COLOUR};
use super::conservative::ConservativeReport;
use super::grey::{GreyClass, GreyReport};
use super::samples::SampleCompareReport;
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
