//! Watertightness: a triangulation of a convex region covers every sample inside the region
//! exactly once and nothing outside; no pixel is covered twice.
//!
//! "Inside the region" is decided independently of the triangles: against the region's
//! own outline, with the same ε reading of the tie rule (a sample on the outline is
//! inside only if the moved sample is).

use std::fmt::Write as _;

use num_rational::BigRational;
use num_traits::Zero;

use super::explain::explain_sample;
use super::Violation;
use crate::convention::Target;
use crate::coverage::samples::SampleCoverage;
use crate::coverage::Coverage;
use crate::edge::exact::ExactEdge;
use crate::geom::{Point, Triangle};
use crate::pattern::SamplePattern;

/// No pixel has more than one owner.
pub fn check_no_double_cover(coverage: &Coverage) -> Result<(), Violation> {
    match coverage.double_covered().next() {
        None => Ok(()),
        Some((x, y, ids)) => Err(Violation::new(
            "no double cover",
            format!(
                "pixel ({x}, {y}) covered by {ids:?} ({} pixels covered more than once)",
                coverage.double_covered().count()
            ),
        )),
    }
}

/// `coverage` (of `mesh`, rendered by some model) owns every sample strictly inside the
/// convex `outline` (after the ε move of the tie rule) exactly once, and nothing else.
/// `outline` lists the region's vertices in order, either orientation, no repeats.
pub fn check_watertight(
    mesh: &[Triangle],
    outline: &[Point],
    coverage: &Coverage,
    target: &Target,
) -> Result<(), Violation> {
    let edges = outline_edges(outline, target);
    let grid = crate::raster::ExactGrid::of(target);
    let inside = |x: u32, y: u32| {
        let p = grid.sample(x, y);
        !edges.is_empty() && edges.iter().all(|e| e.contains(&p))
    };
    let mut problems = Vec::new();
    // Every covered pixel must be inside and owned once.
    for (x, y, ids) in coverage.iter() {
        if ids.len() != 1 || !inside(x, y) {
            problems.push((x, y, ids.to_vec()));
        }
    }
    // Every inside pixel must be covered (scan the outline's bounding box on the canvas).
    if let Some((x0, x1, y0, y1)) = bbox(outline, target) {
        for y in y0..=y1 {
            for x in x0..=x1 {
                if coverage.owners(x, y).is_empty() && inside(x, y) {
                    problems.push((x, y, Vec::new()));
                }
            }
        }
    }
    let Some((x, y, ids)) = problems.first().cloned() else {
        return Ok(());
    };
    let what = problem_text(&ids);
    let mut msg = format!("pixel ({x}, {y}) {what}; {} such pixels", problems.len());
    for (k, t) in mesh.iter().enumerate() {
        let why = explain_sample(t, x, y, target);
        if ids.contains(&u32::try_from(k).unwrap_or(u32::MAX)) || why.contains("E=0") {
            let _ = write!(msg, "\n  triangle {k}: {why}");
        }
    }
    Err(Violation::new("watertight", msg))
}

/// [`check_watertight`] at every sample of `pattern`: each sample of each pixel strictly
/// inside the convex `outline` (after the ε move of the tie rule) is owned exactly once in
/// `coverage`, and no other sample is covered. The samples are the exact points
/// `(i + x_s, j + y_s)`.
pub fn check_watertight_samples(
    mesh: &[Triangle],
    outline: &[Point],
    coverage: &SampleCoverage,
    pattern: &SamplePattern,
    target: &Target,
) -> Result<(), Violation> {
    let edges = outline_edges(outline, target);
    let inside = |p: &Point| !edges.is_empty() && edges.iter().all(|e| e.contains(p));
    let mut problems = Vec::new();
    for s in 0..coverage.sample_count() {
        for (x, y, ids) in coverage.sample(s).iter() {
            if ids.len() != 1 || !inside(&pattern.sample(x, y, s)) {
                problems.push((x, y, s, ids.to_vec()));
            }
        }
    }
    if let Some(r) = crate::raster::exact_pixel_range(outline.iter(), target) {
        for y in r.y0..=r.y1 {
            for x in r.x0..=r.x1 {
                for s in 0..pattern.len() {
                    if coverage.owners(x, y, s).is_empty() && inside(&pattern.sample(x, y, s)) {
                        problems.push((x, y, s, Vec::new()));
                    }
                }
            }
        }
    }
    let Some((x, y, s, ids)) = problems.first().cloned() else {
        return Ok(());
    };
    let what = problem_text(&ids);
    Err(Violation::new(
        "watertight",
        format!(
            "sample {s} {} of pixel ({x}, {y}) {what}; {} such samples, of a mesh of {} triangles",
            pattern.position_text(s),
            problems.len(),
            mesh.len()
        ),
    ))
}

/// What is wrong with a sample whose owners are `ids`: none (a gap), several, or one
/// outside the region.
fn problem_text(ids: &[u32]) -> String {
    if ids.is_empty() {
        "is inside the region but covered by no triangle (a gap)".to_string()
    } else if ids.len() > 1 {
        format!("is covered {} times, by {ids:?}", ids.len())
    } else {
        format!("is outside the region but covered by {ids:?}")
    }
}

/// The outline's edges oriented so that its interior is `E > 0`.
fn outline_edges(outline: &[Point], target: &Target) -> Vec<ExactEdge> {
    let n = outline.len();
    if n < 3 {
        return Vec::new();
    }
    // Shoelace sum; E > 0 inside corresponds to a negative shoelace sum (y down).
    let mut shoelace = BigRational::zero();
    for k in 0..n {
        let (a, b) = (&outline[k], &outline[(k + 1) % n]);
        shoelace += &a.x * &b.y - &b.x * &a.y;
    }
    let mut pts: Vec<&Point> = outline.iter().collect();
    if shoelace > BigRational::zero() {
        pts.reverse();
    }
    (0..n)
        .map(|k| ExactEdge::new(pts[k], pts[(k + 1) % n], target.convention.tie_rule))
        .collect()
}

fn bbox(outline: &[Point], target: &Target) -> Option<(u32, u32, u32, u32)> {
    let r = crate::raster::exact_sample_range(outline.iter(), target)?;
    Some((r.x0, r.x1, r.y0, r.y1))
}
