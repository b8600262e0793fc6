//! Glyph outlines of a real font as a rasterproof scene: a workload of real inputs for the
//! area-coverage models, the adapters and the trade.
//!
//! ```sh
//! cargo run --release --example glyph-scene -- /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf 'g@&B' --px 24 > glyphs.json
//! target/release/rasterproof render glyphs.json --coverage area --semantics accumulated
//! ```
//!
//! The font is read with ttf-parser (Debian's `fonts-dejavu-core` has DejaVu Sans). Text is
//! laid out left to right by the glyphs' horizontal advances (no kerning, no shaping), the
//! baseline `margin + ascender` below the top, `--px` pixels per em. Each glyph's contours
//! become polygons: a contour running the way of the glyph's largest contour is an outline,
//! one running against it a hole of the smallest outline that holds its first point (as
//! TrueType draws counters), every polygon nonzero, contours as the font draws them.
//!
//! Curves are flattened at the parameters `t = k / 2^depth` (`--depth`, default 3: 8
//! segments a curve), so every point is an exact dyadic fraction of a font unit, and the
//! scene is exactly the polygon FreeType or any renderer would get from the same
//! flattening: `x = margin + (pen + u) px / units_per_em`, `y = baseline - v px /
//! units_per_em`, written as fractions.
//!
//! Exit status 0 with the scene on stdout; 2 with one line on stderr (an unreadable font,
//! a character the font lacks, bad arguments).

use std::process::ExitCode;

use serde_json::{json, Value};
use ttf_parser::{Face, OutlineBuilder};

/// The name every message starts with.
const NAME: &str = "glyph-scene";

/// One contour in units of `1 / 8^depth` font unit, relative to the glyph's origin.
type Contour = Vec<(i128, i128)>;

/// Collects a glyph's contours, flattening its curves at dyadic parameters.
struct Flattener {
    /// `2^depth`: the segments per curve.
    steps: i128,
    /// `8^depth`: the units of a point.
    unit: i128,
    contours: Vec<Contour>,
    current: Contour,
}

impl Flattener {
    fn point(&mut self, p: (i128, i128)) {
        if self.current.last() != Some(&p) {
            self.current.push(p);
        }
    }

    /// A font-unit coordinate in the flattener's units.
    fn scaled(&self, v: f32) -> i128 {
        // ttf-parser hands integer font units as f32 (exact below 2^24).
        #[allow(clippy::cast_possible_truncation)]
        let v = v as i128;
        v * self.unit
    }

    fn last(&self) -> (i128, i128) {
        *self.current.last().unwrap_or(&(0, 0))
    }
}

impl OutlineBuilder for Flattener {
    fn move_to(&mut self, x: f32, y: f32) {
        self.close();
        let p = (self.scaled(x), self.scaled(y));
        self.point(p);
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let p = (self.scaled(x), self.scaled(y));
        self.point(p);
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        // B(t) = (1-t)^2 P0 + 2t(1-t) P1 + t^2 P2 at t = k/n: over n^2, then times 8^d / n^2
        // (8^d = n^3, so the point is whole in units of 1/8^d).
        let (n, p0) = (self.steps, self.last());
        let (p1, p2) = ((self.scaled(x1), self.scaled(y1)), (self.scaled(x), self.scaled(y)));
        for k in 1..=n {
            let (a, b, c) = ((n - k) * (n - k), 2 * k * (n - k), k * k);
            let at = |u: i128, v: i128, w: i128| (a * u + b * v + c * w) / (n * n);
            self.point((at(p0.0, p1.0, p2.0), at(p0.1, p1.1, p2.1)));
        }
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (n, p0) = (self.steps, self.last());
        let (p1, p2, p3) = (
            (self.scaled(x1), self.scaled(y1)),
            (self.scaled(x2), self.scaled(y2)),
            (self.scaled(x), self.scaled(y)),
        );
        for k in 1..=n {
            let m = n - k;
            let (a, b, c, d) = (m * m * m, 3 * k * m * m, 3 * k * k * m, k * k * k);
            let at = |u: i128, v: i128, w: i128, z: i128| (a * u + b * v + c * w + d * z) / (n * n * n);
            self.point((at(p0.0, p1.0, p2.0, p3.0), at(p0.1, p1.1, p2.1, p3.1)));
        }
    }

    fn close(&mut self) {
        let mut contour = std::mem::take(&mut self.current);
        if contour.len() > 1 && contour.first() == contour.last() {
            contour.pop();
        }
        if contour.len() >= 3 {
            self.contours.push(contour);
        }
    }
}

/// A contour with its twice signed area.
type Measured<'a> = (&'a Contour, i128);

/// Twice the signed area of a contour (font units, y up).
fn twice_area(c: &Contour) -> i128 {
    (0..c.len())
        .map(|i| {
            let (a, b) = (c[i], c[(i + 1) % c.len()]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum()
}

/// Whether `p` is inside `c` (its winding number is not zero).
fn holds(c: &Contour, p: (i128, i128)) -> bool {
    let mut winding = 0;
    for i in 0..c.len() {
        let (a, b) = (c[i], c[(i + 1) % c.len()]);
        let side = (b.0 - a.0) * (p.1 - a.1) - (p.0 - a.0) * (b.1 - a.1);
        if a.1 <= p.1 && b.1 > p.1 && side > 0 {
            winding += 1;
        } else if a.1 > p.1 && b.1 <= p.1 && side < 0 {
            winding -= 1;
        }
    }
    winding != 0
}

/// The arguments: the font, the text, `--px`, `--depth`, `--margin`.
struct Args {
    font: String,
    text: String,
    px: i128,
    depth: u32,
    margin: i128,
}

fn args() -> Result<Args, String> {
    let mut plain = Vec::new();
    let (mut px, mut depth, mut margin) = (32, 3, 2);
    let mut it = std::env::args().skip(1);
    while let Some(a) = it.next() {
        let mut number = |what: &str, lo: i128, hi: i128| -> Result<i128, String> {
            let v = it.next().ok_or(format!("{what} needs a value"))?;
            v.parse::<i128>()
                .ok()
                .filter(|n| (lo..=hi).contains(n))
                .ok_or(format!("{what}: {v:?} is not a whole number in {lo}..={hi}"))
        };
        match a.as_str() {
            "--px" => px = number("--px", 1, 4096)?,
            "--depth" => depth = u32::try_from(number("--depth", 0, 8)?).unwrap_or(3),
            "--margin" => margin = number("--margin", 0, 1024)?,
            _ => plain.push(a),
        }
    }
    let [font, text] = <[String; 2]>::try_from(plain)
        .map_err(|_| format!("usage: {NAME} FONT.ttf TEXT [--px N] [--depth D] [--margin M]"))?;
    Ok(Args {
        font,
        text,
        px,
        depth,
        margin,
    })
}

fn scene(a: &Args) -> Result<Value, String> {
    let data = std::fs::read(&a.font).map_err(|e| format!("{}: cannot read: {e}", a.font))?;
    let face = Face::parse(&data, 0).map_err(|e| format!("{}: not a font ttf-parser reads: {e}", a.font))?;
    let upem = i128::from(face.units_per_em());
    let unit = 8i128.pow(a.depth);
    let (ascender, descender) = (i128::from(face.ascender()), i128::from(face.descender()));
    // A point (u, v) in units of 1/unit font unit, of a glyph whose pen is at `pen` font
    // units: x = margin + (pen + u/unit) px / upem, y = margin + (ascender - v/unit) px / upem.
    let denominator = upem * unit;
    let coordinate = |whole: i128, offset: i128, v: i128, sign: i128| {
        format!(
            "{}/{denominator}",
            whole * denominator + (offset * unit + sign * v) * a.px
        )
    };
    let mut polygons = Vec::new();
    let mut pen = 0i128;
    for ch in a.text.chars() {
        let glyph = face
            .glyph_index(ch)
            .ok_or(format!("{}: the font has no glyph for {ch:?}", a.font))?;
        let mut f = Flattener {
            steps: 1 << a.depth,
            unit,
            contours: Vec::new(),
            current: Vec::new(),
        };
        face.outline_glyph(glyph, &mut f);
        f.close();
        // Each contour with its twice signed area, once; zero-area contours dropped.
        let areas: Vec<Measured> = f
            .contours
            .iter()
            .map(|c| (c, twice_area(c)))
            .filter(|(_, a)| *a != 0)
            .collect();
        let outer_sign = areas
            .iter()
            .map(|(_, a)| *a)
            .max_by_key(|a| a.abs())
            .map_or(1, i128::signum);
        let (outlines, holes): (Vec<Measured>, Vec<Measured>) =
            areas.into_iter().partition(|(_, a)| a.signum() == outer_sign);
        let mut held: Vec<Vec<&Contour>> = vec![Vec::new(); outlines.len()];
        for (hole, _) in holes {
            let owner = (0..outlines.len())
                .filter(|&k| holds(outlines[k].0, hole[0]))
                .min_by_key(|&k| outlines[k].1.abs())
                .ok_or(format!(
                    "{ch:?}: a counter outside every outline (the font's contours run an unexpected way)"
                ))?;
            held[owner].push(hole);
        }
        let text = |c: &Contour| -> Vec<Value> {
            c.iter()
                .map(|&(u, v)| json!([coordinate(a.margin, pen, u, 1), coordinate(a.margin, ascender, v, -1)]))
                .collect()
        };
        for ((outline, _), holes) in outlines.iter().zip(held) {
            let holes: Vec<Vec<Value>> = holes.iter().map(|h| text(h)).collect();
            polygons.push(json!({"v": text(outline), "holes": holes, "fill_rule": "nonzero"}));
        }
        pen += i128::from(face.glyph_hor_advance(glyph).unwrap_or(0));
    }
    let ceil_px = |units: i128| (units * a.px + upem - 1) / upem;
    Ok(json!({
        "width": 2 * a.margin + ceil_px(pen),
        "height": 2 * a.margin + ceil_px(ascender - descender),
        "polygons": polygons,
    }))
}

fn main() -> ExitCode {
    match args().and_then(|a| scene(&a)) {
        Ok(scene) => {
            println!("{scene}");
            ExitCode::SUCCESS
        }
        Err(message) => {
            eprintln!("{NAME}: {message}");
            ExitCode::from(2)
        }
    }
}
