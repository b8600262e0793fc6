//! The evidence at one differing pixel: a primitive's [`PixelFinding`] (named by their output,
//! or guessed as the primitive that explains the pixel best), the oracle's exact evidence
//! for a shape at a sample, one line ([`evidence`]), and the coarse spatial index of the
//! shapes' boxes that proposes the candidates (`Candidates`).

use num_rational::BigRational;

use super::{PixelKind, Relation};
use crate::convention::{PixelCentre, Target};
use crate::geom::Point;
use crate::model::{Primitives, Shape};
use crate::num::exact::{decimal_pair_text, pair_text};
use crate::oracle::evidence::{polygon_at, shape_distance2, triangle_at};
use crate::oracle::reason::{decide, primitive_name, Classifier, Found, Reason, ReasonClass, Support};
use crate::oracle::theirs::TheirPixel;
use crate::raster::sample_exact;

/// One primitive's difference at one pixel, explained.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PixelFinding {
    /// The primitive (`None`: their output names an owner no primitive explains).
    pub id: Option<u32>,
    /// Its scene field and index (`triangles[3]`); `None` with `id`, or for an id their
    /// output names that is not in the scene.
    pub primitive: Option<String>,
    /// Missing or extra.
    pub relation: Relation,
    /// True when their output names no owner here (a mask, a double cover's second owner)
    /// and `id` is the primitive that explains the pixel best.
    pub guessed: bool,
    /// Why.
    pub reason: Reason,
    /// The squared distance from the sample to the primitive's nearest edge, exactly
    /// (whatever the class; `None` when no primitive is named or guessed).
    pub distance2: Option<BigRational>,
    /// The oracle's exact evidence for this primitive at the sample (edge values and
    /// flags, winding numbers, the line test), one line.
    pub evidence: String,
}

/// A pixel where their output differs from the oracle's.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DiffPixel {
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// How it differs.
    pub kind: PixelKind,
    /// The oracle's owners, ascending.
    pub ours: Vec<u32>,
    /// Theirs.
    pub theirs: TheirPixel,
    /// Whether it was classified ([`super::pick_classified`]): when not, `findings` is
    /// empty.
    pub classified: bool,
    /// Per primitive, why.
    pub findings: Vec<PixelFinding>,
}

/// The squared distance from pixel `(x, y)`'s sample to `shape`'s nearest edge.
fn distance_at(shape: &Shape, x: u32, y: u32, target: &Target) -> BigRational {
    shape_distance2(shape, &sample_exact(x, y, target), [i64::from(x), i64::from(y)])
}

/// The finding for a primitive their output (or the oracle) names, with what the searches
/// found (its reason here is the one judged alone; [`super::compare`] decides it again
/// with the whole comparison's support).
pub(super) fn named(
    classifier: &mut Classifier<'_>,
    primitives: &Primitives,
    id: u32,
    relation: Relation,
    x: u32,
    y: u32,
    target: &Target,
) -> (PixelFinding, Found) {
    let k = usize::try_from(id).ok().filter(|&k| k < classifier.shapes().len());
    let Some(k) = k else {
        let reason = Reason::Gross { distance2: None };
        let finding = PixelFinding {
            id: Some(id),
            primitive: None,
            relation,
            guessed: false,
            reason: reason.clone(),
            distance2: None,
            evidence: format!("id {id} is not a primitive of the scene"),
        };
        return (finding, Found::Decided(reason));
    };
    let found = classifier.found(k, x, y, relation == Relation::Extra);
    let shape = &classifier.shapes()[k];
    let finding = PixelFinding {
        id: Some(id),
        primitive: primitive_name(primitives, id),
        relation,
        guessed: false,
        reason: decide(found.clone(), &Support::of(&found)),
        distance2: Some(distance_at(shape, x, y, target)),
        evidence: evidence(shape, x, y, target),
    };
    (finding, found)
}

/// The finding for an extra owner their output does not name: the candidate primitive
/// that explains it best, or none (gross) when none does; with what the searches found.
pub(super) fn guessed(
    classifier: &mut Classifier<'_>,
    primitives: &Primitives,
    candidates: &[usize],
    x: u32,
    y: u32,
    target: &Target,
) -> (PixelFinding, Found) {
    let best = classifier
        .best_extra(candidates, x, y)
        .map(|(k, found)| (k, decide(found.clone(), &Support::of(&found)), found));
    match best {
        Some((k, reason, found)) if reason.class() != ReasonClass::Gross => {
            let id = u32::try_from(k).expect("ids fit u32");
            let shape = &classifier.shapes()[k];
            let finding = PixelFinding {
                id: Some(id),
                primitive: primitive_name(primitives, id),
                relation: Relation::Extra,
                guessed: true,
                reason,
                distance2: Some(distance_at(shape, x, y, target)),
                evidence: evidence(shape, x, y, target),
            };
            (finding, found)
        }
        best => {
            let distance2 = best.and_then(|(_, r, _)| match r {
                Reason::Gross { distance2 } => distance2,
                _ => None,
            });
            let reason = Reason::Gross {
                distance2: distance2.clone(),
            };
            let finding = PixelFinding {
                id: None,
                primitive: None,
                relation: Relation::Extra,
                guessed: true,
                reason: reason.clone(),
                distance2,
                evidence: format!(
                    "no primitive has an edge within 1 px of the sample {}",
                    point_text(&sample_exact(x, y, target))
                ),
            };
            (finding, Found::Decided(reason))
        }
    }
}

/// A point as `(x, y)`, each coordinate exact.
pub(super) fn point_text(p: &Point) -> String {
    pair_text(&p.x, &p.y)
}

/// The oracle's evidence for `shape` at pixel `(x, y)`, one line.
pub(crate) fn evidence(shape: &Shape, x: u32, y: u32, target: &Target) -> String {
    let p = sample_exact(x, y, target);
    match shape {
        Shape::Triangle(_) | Shape::Polygon(_) => evidence_at(shape, &p, target),
        Shape::Diamond { .. } | Shape::Bresenham { .. } => line_evidence(shape, &p, x, y, target),
    }
}

/// The oracle's evidence for an area `shape` (a triangle or a polygon) at the point `p`
/// (a pixel's sample, or one sample of a pattern), one line; a line's is its pixel's.
pub(crate) fn evidence_at(shape: &Shape, p: &Point, target: &Target) -> String {
    let rule = target.convention.tie_rule;
    let s = format!("sample {}{}: ", point_text(p), decimal_pair_text(&p.x, &p.y));
    match shape {
        Shape::Triangle(t) => match triangle_at(t, p, rule.into()) {
            Some(at) => s + &at.to_string(),
            None => s + "zero-area triangle -> outside",
        },
        Shape::Polygon(poly) => {
            let at = polygon_at(poly, p, rule);
            format!("{s}{} ({}) {at}", "polygon", poly.fill_rule.name())
        }
        Shape::Diamond { .. } | Shape::Bresenham { .. } => s + "a line has no samples",
    }
}

/// A line's evidence at its pixel `(x, y)` (sample `p`).
fn line_evidence(shape: &Shape, p: &Point, x: u32, y: u32, target: &Target) -> String {
    let s = format!("sample {}{}: ", point_text(p), decimal_pair_text(&p.x, &p.y));
    match shape {
        Shape::Triangle(_) | Shape::Polygon(_) => evidence_at(shape, p, target),
        Shape::Diamond { from, to } => {
            let exits = crate::line::exact::diamond_exits(from, to, i64::from(x), i64::from(y), target);
            format!(
                "{s}diamond-exit line {} -> {}: {}",
                point_text(from),
                point_text(to),
                if exits {
                    "exits the pixel's diamond -> covered"
                } else {
                    "does not exit the pixel's diamond -> not covered"
                }
            )
        }
        Shape::Bresenham { from, to, tie } => format!(
            "Bresenham line ({}, {}) -> ({}, {}), ties {}; pixel ({x}, {y})",
            from[0],
            from[1],
            to[0],
            to[1],
            tie.name()
        ),
    }
}

/// A coarse index of the shapes' bounding boxes (grown by 1 px), for the extra pixels
/// whose owner their output does not name.
pub(super) struct Candidates {
    cell: u32,
    columns: u32,
    cells: Vec<Vec<usize>>,
}

impl Candidates {
    const CELL: u32 = 32;

    pub(super) fn new(shapes: &[Shape], target: &Target) -> Candidates {
        let cell = Candidates::CELL;
        let columns = target.width.div_ceil(cell);
        let rows = target.height.div_ceil(cell);
        let mut cells = vec![Vec::new(); usize::try_from(columns * rows).expect("fits")];
        let c = target.convention.pixel_centre;
        for (k, s) in shapes.iter().enumerate() {
            let Some([x0, y0, x1, y1]) = pixel_box(s, c, target) else {
                continue;
            };
            for cy in y0 / cell..=y1 / cell {
                for cx in x0 / cell..=x1 / cell {
                    cells[usize::try_from(cy * columns + cx).expect("fits")].push(k);
                }
            }
        }
        Candidates { cell, columns, cells }
    }

    pub(super) fn near(&self, x: u32, y: u32) -> Vec<usize> {
        self.cells[usize::try_from((y / self.cell) * self.columns + x / self.cell).expect("fits")].clone()
    }
}

/// Whether pixel `(x, y)` lies in `shape`'s pixel box ([`pixel_box`]).
pub(crate) fn pixel_box_holds(shape: &Shape, x: u32, y: u32, target: &Target) -> bool {
    pixel_box(shape, target.convention.pixel_centre, target)
        .is_some_and(|[x0, y0, x1, y1]| (x0..=x1).contains(&x) && (y0..=y1).contains(&y))
}

/// The pixels whose samples lie within 2 px of `shape`'s bounding box, clamped to the
/// canvas; `None` when off it.
fn pixel_box(shape: &Shape, centre: PixelCentre, target: &Target) -> Option<[u32; 4]> {
    use num_traits::ToPrimitive;
    let points: Vec<[f64; 2]> = match shape {
        Shape::Triangle(t) => t.v.iter().map(|p| [f(&p.x), f(&p.y)]).collect(),
        Shape::Polygon(poly) => poly.contours().flatten().map(|p| [f(&p.x), f(&p.y)]).collect(),
        Shape::Diamond { from, to } => [from, to].iter().map(|p| [f(&p.x), f(&p.y)]).collect(),
        Shape::Bresenham { from, to, .. } => [from, to]
            .iter()
            .map(|a| [a[0].to_f64().unwrap_or(0.0), a[1].to_f64().unwrap_or(0.0)])
            .collect(),
    };
    let off = centre.offset_f64();
    let lo = |axis: usize| points.iter().map(|p| p[axis]).fold(f64::INFINITY, f64::min) - off - 2.0;
    let hi = |axis: usize| points.iter().map(|p| p[axis]).fold(f64::NEG_INFINITY, f64::max) - off + 2.0;
    let clamp = |v: f64, side: u32| -> u32 { v.floor().clamp(0.0, f64::from(side - 1)).to_u32().unwrap_or(0) };
    let (x0, x1, y0, y1) = (lo(0), hi(0), lo(1), hi(1));
    if x1 < 0.0 || y1 < 0.0 || x0 > f64::from(target.width) || y0 > f64::from(target.height) {
        return None;
    }
    Some([
        clamp(x0, target.width),
        clamp(y0, target.height),
        clamp(x1, target.width),
        clamp(y1, target.height),
    ])
}

/// A coordinate as the nearest f64 (for the coarse index only; ±inf when out of range).
fn f(v: &num_rational::BigRational) -> f64 {
    use num_traits::Signed;
    crate::num::exact::nearest_f64(v).unwrap_or(if v.is_negative() {
        f64::NEG_INFINITY
    } else {
        f64::INFINITY
    })
}
