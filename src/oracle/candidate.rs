//! One convention another renderer may follow ([`Candidate`]: a tie rule, a snapping and a
//! sample position) and the exact image of a scene under it: what [`super::fit`] searches
//! and what [`super::compare`] draws to check a two-part explanation.

use std::fmt;

use num_rational::BigRational;

use super::reason::Snapping;
use crate::convention::{AnyTieRule, Convention, PixelCentre, Target, TieRule};
use crate::coverage::{Coverage, CoverageSink};
use crate::fill::polygon::PlannedPolygon;
use crate::geom::{Point, Polygon, Triangle};
use crate::line::{Line, LineRule};
use crate::model::{prepare, Model, ModelError, Primitives};
use crate::num::exact::dyadic;
use crate::num::fixed::snap;
use crate::num::Rounding;
use crate::tri::planned::PlannedTriangle;

/// The largest subpixel precision searched.
pub const MAX_FIT_BITS: u32 = 16;

/// One convention a renderer may follow.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Candidate {
    /// The tie rule.
    pub tie_rule: AnyTieRule,
    /// The snapping (`bits: None`: unsnapped; `Some(0)`: whole pixels).
    pub snapping: Snapping,
    /// Where the sample sits.
    pub pixel_centre: PixelCentre,
}

impl fmt::Display for Candidate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "tie rule {}, {}, pixel centre {}",
            self.tie_rule.name(),
            self.snapping.describe(),
            self.pixel_centre.name()
        )
    }
}

/// Every snapping searched, in order: bits 0..=16 with each rounding, then unsnapped.
pub(crate) fn snappings() -> Vec<Snapping> {
    let mut out: Vec<Snapping> = (0..=MAX_FIT_BITS)
        .flat_map(|bits| {
            Rounding::ALL.into_iter().map(move |rounding| Snapping {
                bits: Some(bits),
                rounding,
            })
        })
        .collect();
    out.push(Snapping {
        bits: None,
        rounding: Rounding::NearestEven,
    });
    out
}

fn snap_point(p: &Point, s: Snapping) -> Point {
    match s.bits {
        None => p.clone(),
        Some(bits) => {
            let f = |v: &BigRational| dyadic(&snap(v, bits, s.rounding), bits);
            Point::new(f(&p.x), f(&p.y))
        }
    }
}

/// `primitives` with every window-space vertex snapped by `s` (Bresenham lines keep their
/// pixel addresses; the clip window is exact and stays).
pub(crate) fn snapped(primitives: &Primitives, s: Snapping) -> Primitives {
    let polygon = |p: &Polygon| Polygon {
        outline: p.outline.iter().map(|v| snap_point(v, s)).collect(),
        holes: p
            .holes
            .iter()
            .map(|h| h.iter().map(|v| snap_point(v, s)).collect())
            .collect(),
        fill_rule: p.fill_rule,
    };
    Primitives {
        triangles: primitives
            .triangles
            .iter()
            .map(|t| {
                Triangle {
                    v: t.to_triangle().v.map(|v| snap_point(&v, s)),
                }
                .into()
            })
            .collect(),
        lines: primitives
            .lines
            .iter()
            .map(|l| match l.rule {
                LineRule::Diamond => Line {
                    from: snap_point(&l.from, s),
                    to: snap_point(&l.to, s),
                    rule: l.rule,
                },
                LineRule::Bresenham(_) => l.clone(),
            })
            .collect(),
        polygons: primitives.polygons.iter().map(polygon).collect(),
        ..primitives.clone()
    }
}

/// Adds `offset` to every id (the lines drawn after the triangles).
struct Offset<'a>(&'a mut Coverage, u32);

impl CoverageSink for Offset<'_> {
    fn cover(&mut self, x: u32, y: u32, id: u32) {
        self.0.cover(x, y, id + self.1);
    }

    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, id: u32) {
        self.0.cover_span(y, x0, x1, id + self.1);
    }
}

/// The exact image of `primitives` (already snapped) under `candidate`; `Ok(None)` when
/// the candidate's rule does not apply to the scene's clip window.
pub(crate) fn image(
    primitives: &Primitives,
    target: &Target,
    candidate: &Candidate,
) -> Result<Option<Coverage>, ModelError> {
    let directional = match candidate.tie_rule {
        AnyTieRule::TopLeft => Some(TieRule::TopLeft),
        AnyTieRule::BottomLeft => Some(TieRule::BottomLeft),
        _ => None,
    };
    let conv = Convention {
        tie_rule: directional.unwrap_or(TieRule::TopLeft),
        pixel_centre: candidate.pixel_centre,
        ..target.convention
    };
    let t = Target {
        convention: conv,
        ..*target
    };
    if directional.is_some() {
        return Ok(Some(prepare(primitives, &t, Model::Exact)?.coverage(&t)));
    }
    if primitives.clip.is_some() {
        return Ok(None);
    }
    let mut coverage = Coverage::new(t.width, t.height);
    for (k, tri) in primitives.triangles.iter().enumerate() {
        if let Some(p) = PlannedTriangle::with_rule(&tri.to_triangle(), &t, candidate.tie_rule) {
            p.rasterize(u32::try_from(k).expect("ids fit u32"), &mut coverage);
        }
    }
    if !primitives.lines.is_empty() {
        let lines = Primitives {
            lines: primitives.lines.clone(),
            ..Primitives::default()
        };
        let offset = u32::try_from(primitives.triangles.len()).expect("ids fit u32");
        prepare(&lines, &t, Model::Exact)?.render(&t, &mut Offset(&mut coverage, offset));
    }
    let first_polygon = primitives.triangles.len() + primitives.lines.len();
    for (k, poly) in primitives.polygons.iter().enumerate() {
        if let Some(p) = PlannedPolygon::with_rule(poly, &t, candidate.tie_rule) {
            p.rasterize(u32::try_from(first_polygon + k).expect("ids fit u32"), &mut coverage);
        }
    }
    Ok(Some(coverage))
}
