//! A scene's plan: per primitive, the arithmetic the planned exact engine runs it in and
//! the bound that forced it, a summary by width, and which fixed-width models (`fixed`,
//! `scanline`, `float32`, `float64`) are exact for the scene, with the first primitive
//! that breaks each (`rasterproof plan`, and `render`'s summary line).
//!
//! Fixed-width verdicts:
//! - `fixed`, `scanline`: exact (equal to `exact-snapped`) exactly when the model takes
//!   the scene: inside the envelope, their arithmetic is proven (`crate::num::fixed`);
//!   outside, they refuse it, and the refusal is the breaking primitive.
//! - `float32`, `float64` (with the tie rule): proven exact (equal to `exact`) for a
//!   triangle or polygon when every vertex and sample is a multiple of one `2^-k`, and
//!   every value the float edge function `(p.x - a.x)(b.y - a.y) - (p.y - a.y)(b.x - a.x)`
//!   computes over the pixel range (of the vertices and of the vertices rounded to the
//!   float type, whose box the float model loops over; the differences, both products, the result), scaled by
//!   `2^k` or `2^2k` to an integer, is at most `2^24` (f32) or `2^53` (f64): then each
//!   operation's exact result is a float, so IEEE arithmetic returns it unchanged. Lines
//!   and clipping in floats are not analysed: "not proven".

use std::collections::BTreeMap;

use serde_json::{json, Value};

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use crate::convention::Target;
use crate::geom::Point;
use crate::num::plan::{scale_of, scaled, Plan, Width};
use crate::raster::exact_sample_range;

use super::{prepare, Model, Primitives};

/// One primitive's plan.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PrimitivePlan {
    /// `triangle`, `line`, `polygon`, `clip-space triangle`, or `clipped triangle`.
    pub kind: &'static str,
    /// Its index among the scene's primitives of that kind.
    pub index: usize,
    /// Its id in the coverage.
    pub id: u32,
    /// The plan; `None` when it covers nothing (zero area, off the canvas) or is not
    /// planned (a Bresenham line: its ideal line is stepped in rationals).
    pub plan: Option<Plan>,
    /// Why there is no plan, when there is none: [`COVERS_NO_PIXEL`] or [`BRESENHAM`].
    pub unplanned: Option<&'static str>,
}

/// [`PrimitivePlan::unplanned`] of a primitive that covers no pixel of the canvas (zero
/// area, or off the canvas): nothing to plan.
pub const COVERS_NO_PIXEL: &str = "covers no pixel";

/// [`PrimitivePlan::unplanned`] of a Bresenham line: its endpoints are pixels and its
/// ideal line is stepped exactly, with no plan needed.
pub const BRESENHAM: &str = "a Bresenham line";

/// Whether a fixed-width model is exact for a scene.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Verdict {
    /// The model.
    pub model: Model,
    /// Proven exact for every primitive of the scene.
    pub exact: bool,
    /// The first primitive that breaks it and why; `None` when exact.
    pub broken_by: Option<String>,
}

/// A scene's plan under one exact model.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ScenePlan {
    /// The model planned (`exact` or `exact-snapped`; the plain oracles and the other
    /// models plan nothing).
    pub model: Model,
    /// Every primitive, in id order.
    pub primitives: Vec<PrimitivePlan>,
    /// The fixed-width models' verdicts.
    pub fixed_width: Vec<Verdict>,
}

impl ScenePlan {
    /// How many primitives run in each width.
    pub fn by_width(&self) -> BTreeMap<Width, usize> {
        by_width(&self.primitives)
    }

    /// One line: see [`summary`].
    pub fn summary(&self) -> String {
        summary(&self.primitives)
    }

    /// The plan for a person (`rasterproof plan`): a line per primitive (its width, bound
    /// and scale, or why it is not planned), the summary, and each fixed-width model's
    /// verdict. `name` names the scene and `convention` the convention it was planned under.
    pub fn to_text(&self, name: &str, convention: &str) -> String {
        let mut s = format!("{name}: model {}, {convention}\n", self.model);
        for p in &self.primitives {
            let what = match &p.plan {
                Some(q) => q.to_string(),
                None => format!("not planned: {}", p.unplanned.unwrap_or(COVERS_NO_PIXEL)),
            };
            s.push_str(&format!("{} {} (id {}): {what}\n", p.kind, p.index, p.id));
        }
        s.push_str(&format!("summary: {}\n", self.summary()));
        s.push_str("fixed-width models:\n");
        for v in &self.fixed_width {
            let verdict = match &v.broken_by {
                None => "exact for this scene".to_string(),
                Some(why) => format!("not exact (or not proven): {why}"),
            };
            s.push_str(&format!("  {:<9} {verdict}\n", v.model.name()));
        }
        s.pop();
        s
    }

    /// The plan as one JSON object (`rasterproof plan --format json`; the schema is in
    /// docs/cli.md, `plan`).
    pub fn to_json(&self, name: &str, convention: &str) -> String {
        let primitives: Vec<Value> = self
            .primitives
            .iter()
            .map(|p| match &p.plan {
                Some(q) => json!({
                    "kind": p.kind,
                    "index": p.index,
                    "id": p.id,
                    "width": q.width.name(),
                    "bound": q.bound.value.to_string(),
                    "bound_bits": q.bound.bits(),
                    "bound_at": q.bound.what,
                    "scale": q.scale.to_string(),
                }),
                None => json!({
                    "kind": p.kind,
                    "index": p.index,
                    "id": p.id,
                    "width": null,
                    "unplanned": p.unplanned.unwrap_or(COVERS_NO_PIXEL),
                }),
            })
            .collect();
        let by_width: serde_json::Map<String, Value> = self
            .by_width()
            .into_iter()
            .map(|(w, n)| (w.name().to_string(), json!(n)))
            .collect();
        let fixed: Vec<Value> = self
            .fixed_width
            .iter()
            .map(|v| json!({"model": v.model.name(), "exact": v.exact, "broken_by": v.broken_by}))
            .collect();
        json!({
            "scene": name,
            "model": self.model.name(),
            "convention": convention,
            "primitives": primitives,
            "by_width": by_width,
            "fixed_width": fixed,
        })
        .to_string()
    }
}

/// How many of `plans` run in each width.
pub fn by_width(plans: &[PrimitivePlan]) -> BTreeMap<Width, usize> {
    let mut m = BTreeMap::new();
    for p in plans.iter().filter_map(|p| p.plan.as_ref()) {
        *m.entry(p.width).or_insert(0) += 1;
    }
    m
}

/// One line: `312 primitives: 300 i32, 10 i64, 2 i128`, and how many are not planned
/// and why (`1 covers no pixel`, `2 Bresenham lines`).
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::model::{prepare, plan::summary, Model, Primitives};
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
/// let off = Triangle::new(Point::from_ints(50, 50), Point::from_ints(54, 50), Point::from_ints(50, 54));
/// let target = Target::new(4, 4, Convention::default()).unwrap();
/// let prepared = prepare(&Primitives::from_triangles(&[t, off]), &target, Model::ExactSnapped).unwrap();
/// assert_eq!(summary(&prepared.plans()), "2 primitives: 1 i32; not planned: 1 covers no pixel");
/// ```
pub fn summary(plans: &[PrimitivePlan]) -> String {
    let widths: Vec<String> = by_width(plans).iter().map(|(w, n)| format!("{n} {w}")).collect();
    let mut unplanned: BTreeMap<&str, usize> = BTreeMap::new();
    for p in plans.iter().filter(|p| p.plan.is_none()) {
        *unplanned.entry(p.unplanned.unwrap_or(COVERS_NO_PIXEL)).or_default() += 1;
    }
    let mut s = match plans.len() {
        1 => "1 primitive".to_string(),
        n => format!("{n} primitives"),
    };
    if !widths.is_empty() {
        s.push_str(&format!(": {}", widths.join(", ")));
    }
    if !unplanned.is_empty() {
        let why: Vec<String> = unplanned
            .iter()
            .map(|(&why, &n)| match (why, n) {
                (BRESENHAM, 1) => "1 Bresenham line".to_string(),
                (BRESENHAM, n) => format!("{n} Bresenham lines"),
                (COVERS_NO_PIXEL, 1) => "1 covers no pixel".to_string(),
                (COVERS_NO_PIXEL, n) => format!("{n} cover no pixel"),
                (why, n) => format!("{n}: {why}"),
            })
            .collect();
        s.push_str(&format!("; not planned: {}", why.join(", ")));
    }
    s
}

/// Plans `primitives` for `model` on `target`.
///
/// # Errors
/// What [`prepare`] refuses for `model`.
pub fn plan_scene(primitives: &Primitives, target: &Target, model: Model) -> Result<ScenePlan, super::ModelError> {
    let prepared = prepare(primitives, target, model)?;
    let fixed_width = [Model::Fixed, Model::Scanline, Model::Float32, Model::Float64]
        .into_iter()
        .map(|m| verdict(m, primitives, target))
        .collect();
    Ok(ScenePlan {
        model,
        primitives: prepared.plans(),
        fixed_width,
    })
}

fn verdict(model: Model, primitives: &Primitives, target: &Target) -> Verdict {
    // A model that refuses the scene is not exact for it, whether or not the refused
    // primitive reaches a sample (the float models refuse a coordinate beyond their type
    // even on a primitive that covers nothing, which the float analysis skips).
    let refused = prepare(primitives, target, model).err().map(|e| e.to_string());
    let broken_by = match model {
        Model::Fixed | Model::Scanline => refused,
        Model::Float32 => refused.or_else(|| float_breaker(primitives, target, 24)),
        _ => refused.or_else(|| float_breaker(primitives, target, 53)),
    };
    Verdict {
        model,
        exact: broken_by.is_none(),
        broken_by,
    }
}

/// The first primitive a float model with `bits` of significand is not proven exact on.
fn float_breaker(p: &Primitives, target: &Target, bits: u32) -> Option<String> {
    if p.clip.is_some() {
        return Some("clip: clipping in floats rounds the intersections (not proven)".into());
    }
    if !p.clip_space_triangles.is_empty() {
        return Some("clip_space_triangles[0]: the divide and viewport in floats (not proven)".into());
    }
    if !p.lines.is_empty() {
        return Some("lines[0]: lines in floats are not analysed (not proven)".into());
    }
    for (k, t) in p.triangles.iter().enumerate() {
        if let Err(why) = float_exact(&t.to_triangle().v, target, bits) {
            return Some(format!("triangles[{k}]: {why}"));
        }
    }
    for (k, poly) in p.polygons.iter().enumerate() {
        let contours: Vec<&[Point]> = poly.contours().collect();
        let vertices: Vec<Point> = contours.iter().flat_map(|c| c.iter().cloned()).collect();
        let edges = contours
            .iter()
            .flat_map(|c| c.iter().zip(c.iter().cycle().skip(1)))
            .map(|(a, b)| [a.clone(), b.clone()])
            .collect::<Vec<_>>();
        if let Err(why) = float_exact_edges(&vertices, &edges, target, bits) {
            return Some(format!("polygons[{k}]: {why}"));
        }
    }
    None
}

/// `v` rounded to the nearest float of a `bits`-bit significand (24: f32, 53: f64), as the
/// float models round a vertex; `None` when it does not fit the type.
fn nearest_float(v: &Point, bits: u32) -> Option<Point> {
    let [x, y] = if bits == 24 {
        let p = v.to_f32()?;
        [f64::from(p.x), f64::from(p.y)]
    } else {
        let p = v.to_f64()?;
        [p.x, p.y]
    };
    Some(Point::new(BigRational::from_float(x)?, BigRational::from_float(y)?))
}

/// Whether the float edge function is exact over a triangle's range (every ordered pair
/// of vertices as an edge, so the orientation swap cannot matter).
fn float_exact(v: &[Point; 3], target: &Target, bits: u32) -> Result<(), String> {
    let mut edges = Vec::new();
    for i in 0..3 {
        for j in 0..3 {
            if i != j {
                edges.push([v[i].clone(), v[j].clone()]);
            }
        }
    }
    float_exact_edges(v, &edges, target, bits)
}

/// See the module docs: every value of `(p.x - a.x)(b.y - a.y) - (p.y - a.y)(b.x - a.x)`
/// over the samples of the range (and at the vertices, for the area) scaled to integers
/// at most `2^bits`.
fn float_exact_edges(vertices: &[Point], edges: &[[Point; 2]], target: &Target, bits: u32) -> Result<(), String> {
    // The float model rounds each vertex to its type first and loops over the samples of
    // the rounded vertices' box, so the range is over both: a vertex just past a sample
    // can round onto it (tests/fuzz_cases.rs, fuzz case 06).
    let rounded: Vec<Point> = vertices.iter().filter_map(|v| nearest_float(v, bits)).collect();
    let Some(range) = exact_sample_range(vertices.iter().chain(&rounded), target) else {
        return Ok(()); // neither covers anything: nothing computed per sample
    };
    let centre = target.convention.pixel_centre.offset();
    let l = scale_of(vertices.iter().flat_map(|p| [&p.x, &p.y]).chain([&centre]));
    if !(&l & (&l - BigInt::one())).is_zero() {
        return Err(format!("a coordinate is not dyadic (scale {l}): no float holds it"));
    }
    let limit = BigInt::one() << bits;
    let s = |v: &BigRational| scaled(v, &l);
    let sample = |i: u32| BigInt::from(i) * &l + s(&centre);
    let mut points: Vec<[BigInt; 2]> = vec![];
    for x in [range.x0, range.x1] {
        for y in [range.y0, range.y1] {
            points.push([sample(x), sample(y)]);
        }
    }
    points.extend(vertices.iter().map(|p| [s(&p.x), s(&p.y)]));
    let check = |v: BigInt, what: &dyn Fn() -> String| {
        if v.abs() > limit {
            Err(format!("{} reaches {} > 2^{bits}", what(), v.abs()))
        } else {
            Ok(())
        }
    };
    for p in &points {
        check(p[0].clone(), &|| "a sample coordinate".into())?;
        check(p[1].clone(), &|| "a sample coordinate".into())?;
    }
    // Every point lies in the box of `points`, so for an edge from `a`, |p.x - a.x| is at
    // most the larger of its distances to the box's sides (U; V for y) and the edge value
    // at most U |dy| + V |dx|: an edge whose bounds all stay within the limit fails no
    // check below and is skipped, which keeps a polygon's cost linear in its vertices
    // (the checks, and so the first failure named, are the same).
    let extent = |k: usize| {
        let lo = points
            .iter()
            .map(|p| &p[k])
            .min()
            .expect("four corners at least")
            .clone();
        let hi = points
            .iter()
            .map(|p| &p[k])
            .max()
            .expect("four corners at least")
            .clone();
        (lo, hi)
    };
    let (xs, ys) = (extent(0), extent(1));
    let farthest = |(lo, hi): &(BigInt, BigInt), a: &BigInt| (lo - a).abs().max((hi - a).abs());
    for [a, b] in edges {
        let (a, b) = ([s(&a.x), s(&a.y)], [s(&b.x), s(&b.y)]);
        let (dx, dy) = (&b[0] - &a[0], &b[1] - &a[1]);
        let (u, v) = (farthest(&xs, &a[0]), farthest(&ys, &a[1]));
        let (first, second) = (&u * dy.abs(), &v * dx.abs());
        let within = [&dx.abs(), &dy.abs(), &u, &v, &first, &second, &(&first + &second)]
            .iter()
            .all(|x| **x <= limit);
        if within {
            continue;
        }
        check(dx.clone(), &|| "an edge's dx".into())?;
        check(dy.clone(), &|| "an edge's dy".into())?;
        for p in &points {
            let (u, v) = (&p[0] - &a[0], &p[1] - &a[1]);
            check(u.clone(), &|| "p.x - a.x".into())?;
            check(v.clone(), &|| "p.y - a.y".into())?;
            let (first, second) = (&u * &dy, &v * &dx);
            let e = &first - &second;
            check(first, &|| "(p.x - a.x)(b.y - a.y)".into())?;
            check(second, &|| "(p.y - a.y)(b.x - a.x)".into())?;
            check(e, &|| "an edge value".into())?;
        }
    }
    // Every value is linear in the sample, so the range's corners bound them all.
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::{Convention, Target};
    use crate::geom::{Point, Triangle};
    use crate::line::{BresenhamTie, Line, LineRule};

    /// The summary counts in words a person reads: one primitive, and why the others
    /// have no plan (a Bresenham line; a triangle off the canvas covers no pixel).
    #[test]
    fn the_summary_says_one_primitive_and_why_others_are_not_planned() {
        let target = Target::new(4, 4, Convention::default()).unwrap();
        let on = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
        let off = Triangle::new(
            Point::from_ints(50, 50),
            Point::from_ints(54, 50),
            Point::from_ints(50, 54),
        );
        let one = plan_scene(
            &Primitives::from_triangles(std::slice::from_ref(&on)),
            &target,
            Model::ExactSnapped,
        )
        .unwrap();
        assert_eq!(one.summary(), "1 primitive: 1 i32");
        let line = Line {
            from: Point::from_ints(0, 0),
            to: Point::from_ints(3, 1),
            rule: LineRule::Bresenham(BresenhamTie::Stay),
        };
        let both = Primitives {
            lines: vec![line.clone(), line],
            ..Primitives::from_triangles(&[on, off.clone(), off])
        };
        let plan = plan_scene(&both, &target, Model::ExactSnapped).unwrap();
        assert_eq!(
            plan.summary(),
            "5 primitives: 1 i32; not planned: 2 Bresenham lines, 2 cover no pixel"
        );
        let text = plan.to_text("s.json", "d3d11");
        assert!(
            text.contains("\ntriangle 1 (id 1): not planned: covers no pixel\n"),
            "{text}"
        );
        assert!(
            text.contains("\nline 0 (id 3): not planned: a Bresenham line\n"),
            "{text}"
        );
    }
}
