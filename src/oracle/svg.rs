//! A pixel's neighbourhood as an SVG picture ([`neighbourhood_svg`], `explain --svg`): the
//! picture a bug report needs. The 5x5 pixels around it with their grid and samples, every
//! primitive that reaches them as the oracle draws it (snapped, for `exact-snapped`): a
//! triangle's edges solid where they own the samples on them under the tie rule and
//! dashed where they do not, a polygon with its fill rule and the winding number at the
//! sample, a diamond-exit line with the diamond around the sample; the pixel's sample
//! ringed, filled where the oracle covers it.

use std::fmt::Write as _;

use num_traits::ToPrimitive;

use crate::check::triangle_at;
use crate::convention::Target;
use crate::geom::{FillRule, Point};
use crate::model::{prepare, Model, ModelError, Primitives, Shape};
use crate::oracle::evidence::polygon_at;
use crate::raster::{sample_exact, ExactGrid};

/// Pixels drawn on each side of the chosen one.
const REACH: i64 = 2;
/// Picture units per pixel.
const UNIT: f64 = 96.0;
/// Room above the pixels for the caption.
const TOP: f64 = 64.0;

/// The picture of pixel `(x, y)`'s neighbourhood under `model` (an exact model: `exact`,
/// `exact-snapped`...), or `None` when `(x, y)` is off the canvas.
///
/// # Errors
/// The scene cannot be prepared for `model` (a coordinate outside its envelope).
pub fn neighbourhood_svg(
    primitives: &Primitives,
    target: &Target,
    x: u32,
    y: u32,
    model: Model,
) -> Result<Option<String>, ModelError> {
    if x >= target.width || y >= target.height {
        return Ok(None);
    }
    let prepared = prepare(primitives, target, model)?;
    let coverage = prepared.coverage(target);
    let shapes = prepared.shapes().unwrap_or_default();
    let owners = coverage.owners(x, y).to_vec();
    let mut view = View::new(target, x, y);
    let svg = view.header(&owners, model);
    view.pixels();
    for (id, shape) in shapes.iter().enumerate() {
        let colour = hue(id);
        match shape {
            Shape::Triangle(t) => view.triangle(id, t, &colour),
            Shape::Polygon(poly) => view.polygon(id, poly, &colour),
            Shape::Diamond { from, to } => view.diamond(from, to, &colour),
            Shape::Bresenham { from, to, .. } => view.bresenham(from, to, &colour),
        }
    }
    view.samples(&owners);
    Ok(Some(format!(
        "{svg}<g clip-path=\"url(#window)\">\n{}</g>\n</svg>\n",
        view.body
    )))
}

/// The 5x5 pixels around pixel `(x, y)` being drawn: where they sit, the sample, the
/// labels placed so far, and the picture's body.
struct View<'a> {
    target: &'a Target,
    x: u32,
    y: u32,
    /// The top-left pixel of the window.
    x0: i64,
    y0: i64,
    sample: Point,
    grid: ExactGrid,
    labels: Vec<(f64, f64)>,
    body: String,
}

impl<'a> View<'a> {
    fn new(target: &'a Target, x: u32, y: u32) -> View<'a> {
        View {
            target,
            x,
            y,
            x0: i64::from(x) - REACH,
            y0: i64::from(y) - REACH,
            sample: sample_exact(x, y, target),
            grid: ExactGrid::of(target),
            labels: Vec::new(),
            body: String::new(),
        }
    }

    /// Picture coordinates of an exact point.
    fn at(&self, p: &Point) -> (f64, f64) {
        let f = |v: &num_rational::BigRational| v.to_f64().unwrap_or(0.0);
        (
            (f(&p.x) - self.x0 as f64) * UNIT,
            TOP + (f(&p.y) - self.y0 as f64) * UNIT,
        )
    }

    /// A label's place, moved down until it clears those already placed.
    fn place(&mut self, (lx, mut ly): (f64, f64)) -> (f64, f64) {
        while self
            .labels
            .iter()
            .any(|&(px, py)| (px - lx).abs() < 150.0 && (py - ly).abs() < 15.0)
        {
            ly += 16.0;
        }
        self.labels.push((lx, ly));
        (lx, ly)
    }

    /// The `<svg>` element's opening, the window's clip path and the caption.
    fn header(&self, owners: &[u32], model: Model) -> String {
        let side = (2 * REACH + 1) as f64 * UNIT;
        let mut svg = String::new();
        let _ = writeln!(
            svg,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" font-family=\"sans-serif\" font-size=\"13\">",
            w = side,
            h = side + TOP
        );
        let _ = writeln!(
            svg,
            "<defs><clipPath id=\"window\"><rect x=\"0\" y=\"{TOP}\" width=\"{side}\" height=\"{side}\"/></clipPath></defs>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>"
        );
        let covered = if owners.is_empty() {
            "covered by nothing".to_string()
        } else {
            let ids: Vec<String> = owners.iter().map(u32::to_string).collect();
            format!("covered by {}", ids.join(", "))
        };
        let _ = writeln!(
            svg,
            "<text x=\"8\" y=\"20\" font-weight=\"bold\">pixel ({}, {}), sample ({}, {}): {covered} ({})</text>",
            self.x,
            self.y,
            self.sample.x,
            self.sample.y,
            model.name()
        );
        let _ = writeln!(
            svg,
            "<text x=\"8\" y=\"40\">tie rule {}: solid edges own their samples, dashed ones do not</text>",
            self.target.convention.tie_rule.name()
        );
        svg
    }

    /// The pixels: off-canvas ones grey, the chosen one tinted, the grid.
    fn pixels(&mut self) {
        for j in 0..=2 * REACH {
            for i in 0..=2 * REACH {
                let (px, py) = (self.x0 + i, self.y0 + j);
                let on_canvas =
                    px >= 0 && py >= 0 && px < i64::from(self.target.width) && py < i64::from(self.target.height);
                let fill = if (px, py) == (i64::from(self.x), i64::from(self.y)) {
                    "#fff4c2"
                } else if on_canvas {
                    "#ffffff"
                } else {
                    "#e4e4e4"
                };
                let _ = writeln!(
                    self.body,
                    "<rect x=\"{}\" y=\"{}\" width=\"{UNIT}\" height=\"{UNIT}\" fill=\"{fill}\" stroke=\"#c8c8c8\"/>",
                    i as f64 * UNIT,
                    TOP + j as f64 * UNIT
                );
            }
        }
    }

    /// A triangle that reaches the sample's neighbourhood: its fill, each edge drawn 3
    /// units inside it, solid where it owns the samples on it, with its edge value.
    fn triangle(&mut self, id: usize, t: &crate::geom::Triangle, colour: &str) {
        let Some(evidence) = triangle_at(t, &self.sample, self.target.convention.tie_rule.into()) else {
            return;
        };
        let points: Vec<String> =
            t.v.iter()
                .map(|p| self.at(p))
                .map(|(a, b)| format!("{a:.2},{b:.2}"))
                .collect();
        let _ = writeln!(
            self.body,
            "<polygon class=\"primitive\" points=\"{}\" fill=\"{colour}\" fill-opacity=\"0.18\" stroke=\"none\"/>",
            points.join(" ")
        );
        for e in &evidence.edges {
            let ((ax, ay), (bx, by)) = (self.at(&e.from), self.at(&e.to));
            // Drawn 3 units inside the triangle (the side where E > 0, along (dy, -dx)),
            // so two triangles sharing the edge show both flags.
            let (dx, dy) = (bx - ax, by - ay);
            let len = (dx * dx + dy * dy).sqrt().max(1e-9);
            let (ox, oy) = (3.0 * dy / len, -3.0 * dx / len);
            let ((ax, ay), (bx, by)) = ((ax + ox, ay + oy), (bx + ox, by + oy));
            let (class, dash) = if e.inclusive {
                ("edge inclusive", "")
            } else {
                ("edge exclusive", " stroke-dasharray=\"10 7\"")
            };
            let _ = writeln!(
                self.body,
                "<line class=\"{class}\" data-primitive=\"{id}\" data-edge=\"{}\" x1=\"{ax:.2}\" y1=\"{ay:.2}\" x2=\"{bx:.2}\" y2=\"{by:.2}\" stroke=\"{colour}\" stroke-width=\"3\"{dash}/>",
                e.index
            );
            let label = label_point(&e.from, &e.to, &self.sample, &|p: &Point| self.at(p));
            let (lx, ly) = self.place(label);
            let _ = writeln!(
                self.body,
                "<text x=\"{lx:.1}\" y=\"{ly:.1}\" fill=\"{colour}\">#{id} e{} {} E={}</text>",
                e.index,
                e.side.name(),
                e.value
            );
        }
    }

    /// A polygon: its path under its fill rule, and its winding number at the sample
    /// where the sample is inside or on an edge.
    fn polygon(&mut self, id: usize, poly: &crate::geom::Polygon, colour: &str) {
        let mut d = String::new();
        for contour in poly.contours() {
            for (k, v) in contour.iter().enumerate() {
                let (a, b) = self.at(v);
                let _ = write!(d, "{}{a:.2},{b:.2} ", if k == 0 { "M" } else { "L" });
            }
            d.push_str("Z ");
        }
        let rule = match poly.fill_rule {
            FillRule::NonZero => "nonzero",
            FillRule::EvenOdd => "evenodd",
        };
        let _ = writeln!(
            self.body,
            "<path class=\"primitive\" d=\"{}\" fill=\"{colour}\" fill-opacity=\"0.18\" fill-rule=\"{rule}\" stroke=\"{colour}\" stroke-width=\"3\"/>",
            d.trim_end()
        );
        let w = polygon_at(poly, &self.sample, self.target.convention.tie_rule);
        if w.windings.iter().all(|&k| k == 0) && !w.on_boundary {
            return;
        }
        let (sx, sy) = self.at(&self.sample);
        let (sx, sy) = self.place((sx + 10.0, sy - 10.0));
        let _ = writeln!(
            self.body,
            "<text class=\"winding\" x=\"{:.1}\" y=\"{:.1}\" fill=\"{colour}\">#{id} winding {}{}</text>",
            sx,
            sy,
            w.windings[0],
            if w.on_boundary { ", on an edge" } else { "" }
        );
    }

    /// A diamond-exit line, with the diamond `|dx| + |dy| < 1/2` around the pixel's centre.
    fn diamond(&mut self, from: &Point, to: &Point, colour: &str) {
        let ((ax, ay), (bx, by)) = (self.at(from), self.at(to));
        let _ = writeln!(
            self.body,
            "<line class=\"line\" x1=\"{ax:.2}\" y1=\"{ay:.2}\" x2=\"{bx:.2}\" y2=\"{by:.2}\" stroke=\"{colour}\" stroke-width=\"3\"/>"
        );
        let c = self.at(&Point::new(
            self.grid.coordinate(i64::from(self.x)),
            self.grid.coordinate(i64::from(self.y)),
        ));
        let r = UNIT / 2.0;
        let _ = writeln!(
            self.body,
            "<polygon class=\"diamond\" points=\"{:.1},{:.1} {:.1},{:.1} {:.1},{:.1} {:.1},{:.1}\" fill=\"none\" stroke=\"{colour}\" stroke-dasharray=\"4 4\"/>",
            c.0,
            c.1 - r,
            c.0 + r,
            c.1,
            c.0,
            c.1 + r,
            c.0 - r,
            c.1
        );
    }

    /// A Bresenham line, between its endpoint pixels' centres.
    fn bresenham(&mut self, from: &[i64; 2], to: &[i64; 2], colour: &str) {
        let centre = |p: &[i64; 2]| {
            (
                (p[0] - self.x0) as f64 * UNIT + UNIT / 2.0,
                TOP + (p[1] - self.y0) as f64 * UNIT + UNIT / 2.0,
            )
        };
        let ((ax, ay), (bx, by)) = (centre(from), centre(to));
        let _ = writeln!(
            self.body,
            "<line class=\"line\" x1=\"{ax:.2}\" y1=\"{ay:.2}\" x2=\"{bx:.2}\" y2=\"{by:.2}\" stroke=\"{colour}\" stroke-width=\"3\" stroke-dasharray=\"2 4\"/>"
        );
    }

    /// Every pixel's sample; the chosen one ringed, filled when covered.
    fn samples(&mut self, owners: &[u32]) {
        for j in 0..=2 * REACH {
            for i in 0..=2 * REACH {
                let (px, py) = (self.x0 + i, self.y0 + j);
                let p = Point::new(self.grid.coordinate(px), self.grid.coordinate(py));
                let (cx, cy) = self.at(&p);
                if (px, py) == (i64::from(self.x), i64::from(self.y)) {
                    let fill = if owners.is_empty() { "#ffffff" } else { "#000000" };
                    let _ = writeln!(
                        self.body,
                        "<circle class=\"sample chosen\" cx=\"{cx:.2}\" cy=\"{cy:.2}\" r=\"6\" fill=\"{fill}\" stroke=\"#000000\" stroke-width=\"2\"/>\n<circle cx=\"{cx:.2}\" cy=\"{cy:.2}\" r=\"12\" fill=\"none\" stroke=\"#d00000\" stroke-width=\"2\"/>"
                    );
                } else {
                    let _ = writeln!(
                        self.body,
                        "<circle class=\"sample\" cx=\"{cx:.2}\" cy=\"{cy:.2}\" r=\"3\" fill=\"#808080\"/>"
                    );
                }
            }
        }
    }
}

/// Where an edge's label goes: the point of the edge nearest the sample (in the window
/// whenever the edge passes near the sample), moved off the line a little.
fn label_point(a: &Point, b: &Point, sample: &Point, at: &impl Fn(&Point) -> (f64, f64)) -> (f64, f64) {
    let ((ax, ay), (bx, by), (sx, sy)) = (at(a), at(b), at(sample));
    let (dx, dy) = (bx - ax, by - ay);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((sx - ax) * dx + (sy - ay) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (ax + t * dx + 6.0, ay + t * dy - 6.0)
}

/// A colour per primitive id (golden-ratio hues).
fn hue(id: usize) -> String {
    let h = (id as f64 * 0.618_033_988_75).fract() * 360.0;
    format!("hsl({h:.0}, 70%, 38%)")
}
