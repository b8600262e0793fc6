//! Polygon fill, one file per model: `exact.rs`, the oracle (a plain loop over the samples,
//! the winding number of each moved sample counted edge by edge); `scanline.rs`, the
//! scanline filler with an active edge table (Foley, van Dam et al., "Computer Graphics:
//! Principles and Practice") on the snapped polygon, exact integer arithmetic; `rows.rs`,
//! the same sweep row by row on the polygon as written, in rationals; `float.rs`, the
//! per-sample winding test in f32 and f64 (the float side of the trade). This module holds
//! what they share: the crossing rule, the contours' edges and the span sweep.
//!
//! # The rule, and why it equals the triangles' tie rule
//!
//! A sample `p` is tested as the moved sample `p' = p + (ε, ±ε²)` of the tie rule
//! ([`crate::convention::TieRule`]: `+` for top-left, `-` for bottom-left). `p'` lies on
//! no edge of positive length, so its winding number around each contour is well
//! defined: count the contour's edges crossing the horizontal ray from `p'` to the right,
//! `-1` for an edge going down the screen and `+1` for one going up. The sample is inside
//! when the fill rule holds for the outline's winding number and for no hole's
//! ([`Polygon`](crate::geom::Polygon)); both rules ignore a contour's orientation. An
//! edge `a -> b` with `a.y != b.y` crosses the row of `p'` when
//! `min(a.y, b.y) <= p.y < max(a.y, b.y)` (top-left; `<`, `<=` for bottom-left), and
//! the crossing is right of `p'` when `E(p')` and `dy` have different signs, where
//! `E(p') = E(p) + ε dy ∓ ε² dx` has the sign of `E(p)`, or of `dy` when `E(p) = 0`.
//! For a triangle this is exactly the edge-function rule with the inclusive flags of
//! `TieRule::is_inclusive`, and winding numbers add up over a triangulation (the moved
//! sample is on no shared edge), so a polygon's fill is the disjoint union of its
//! triangulation's coverage. Both statements are property tests (`tests/polygons.rs`).

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::convention::{MovedSample, Target};
use crate::coverage::CoverageSink;
use crate::edge::exact::edge_function;
use crate::geom::{FillRule, Point};

mod exact;
mod float;
pub mod planned;
mod rows;
mod scanline;

pub use exact::{
    contains_exact, contains_exact_with, contour_winding_exact, rasterize_exact, rasterize_exact_samples,
    rasterize_exact_with,
};
pub use float::{contour_winding_f32, contour_winding_f64, rasterize_f32, rasterize_f64, PolygonF32, PolygonF64};
pub use planned::PlannedPolygon;
pub use rows::rasterize_rows_exact;
pub use scanline::rasterize;

/// The closed contour's edges `(v[i], v[i+1])`, the last one back to the first vertex.
fn closed_edges<T>(contour: &[T]) -> impl Iterator<Item = (&T, &T)> {
    contour.iter().zip(contour.iter().cycle().skip(1))
}

/// Twice the signed area of a contour in the orientation the triangles use (positive
/// when the interior is on the `E > 0` side of its edges), exactly.
pub fn area2_exact(contour: &[Point]) -> BigRational {
    closed_edges(contour).fold(BigRational::zero(), |acc, (a, b)| acc + (&b.x * &a.y - &a.x * &b.y))
}

/// Whether the edge `a -> b` crosses the row of a moved sample at height `y`: never when
/// horizontal; otherwise `min <= y < max` (the top rules: the sample moves down by ε²) or
/// `min < y <= max` (the bottom rules).
fn crosses_moved_row(a: &Point, b: &Point, y: &BigRational, moved: MovedSample) -> bool {
    let (lo, hi) = if a.y <= b.y { (&a.y, &b.y) } else { (&b.y, &a.y) };
    if moved.down {
        lo <= y && y < hi
    } else {
        lo < y && y <= hi
    }
}

/// Where a point lies against a closed contour (the point itself, not moved).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Location {
    /// Winding number not zero.
    Inside,
    /// On an edge (endpoints included).
    Boundary,
    /// Winding number zero.
    Outside,
}

/// Locates `p` against `contour`, exactly: on an edge, or inside / outside by its
/// winding number (half-open crossing rule, so a ray through a vertex counts once).
///
/// ```
/// use rasterproof::fill::polygon::{locate_exact, Location};
/// use rasterproof::geom::Point;
/// let sq: Vec<Point> = [(0, 0), (4, 0), (4, 4), (0, 4)].iter().map(|&(x, y)| Point::from_ints(x, y)).collect();
/// assert_eq!(locate_exact(&Point::from_ints(2, 2), &sq), Location::Inside);
/// assert_eq!(locate_exact(&Point::from_ints(4, 2), &sq), Location::Boundary);
/// assert_eq!(locate_exact(&Point::from_ints(5, 0), &sq), Location::Outside);
/// ```
pub fn locate_exact(p: &Point, contour: &[Point]) -> Location {
    let mut w = 0i64;
    for (a, b) in closed_edges(contour) {
        let e = edge_function(a, b, p);
        let within = |u: &BigRational, v: &BigRational, t: &BigRational| u.min(v) <= t && t <= u.max(v);
        if e.is_zero() && within(&a.x, &b.x, &p.x) && within(&a.y, &b.y, &p.y) {
            return Location::Boundary;
        }
        if a.y <= p.y && p.y < b.y && e.is_negative() {
            w -= 1; // going down the screen, crossing right of p
        } else if b.y <= p.y && p.y < a.y && e.is_positive() {
            w += 1;
        }
    }
    if w == 0 {
        Location::Outside
    } else {
        Location::Inside
    }
}

/// One edge crossing a row: pixels `i >= threshold` are at or right of it.
#[derive(Debug, Clone, Copy)]
struct Crossing {
    threshold: i128,
    contour: usize,
    winding: i64,
}

/// The left-to-right sweep of one row: each contour's winding number left of the current
/// pixel, and how many holes currently hold the pixel (so the test per crossing is O(1)).
struct Sweep {
    rule: FillRule,
    sums: Vec<i64>,
    holes_inside: usize,
}

impl Sweep {
    fn new(contours: usize, rule: FillRule) -> Sweep {
        Sweep {
            rule,
            sums: vec![0; contours],
            holes_inside: 0,
        }
    }

    /// Fills row `row` from its crossings. A crossing is right of pixel `i` when its
    /// threshold is above `i`, and a contour's crossings along a whole row sum to zero, so
    /// the winding number at `i` is minus the sum of the crossings with threshold `<= i`.
    fn emit_spans<S: CoverageSink + ?Sized>(
        &mut self,
        row: i64,
        crossings: &mut [Crossing],
        id: u32,
        target: &Target,
        sink: &mut S,
    ) {
        crossings.sort_unstable_by_key(|c| c.threshold);
        self.sums.iter_mut().for_each(|s| *s = 0);
        self.holes_inside = 0;
        let width = i128::from(target.width);
        for m in 0..crossings.len() {
            let c = crossings[m];
            let held = |sum: i64| self.rule.inside(-sum);
            let before = held(self.sums[c.contour]);
            self.sums[c.contour] += c.winding;
            let after = held(self.sums[c.contour]);
            if c.contour > 0 && before != after {
                if after {
                    self.holes_inside += 1;
                } else {
                    self.holes_inside -= 1;
                }
            }
            let end = crossings.get(m + 1).map_or(c.threshold, |n| n.threshold); // exclusive
            if c.threshold < end && held(self.sums[0]) && self.holes_inside == 0 {
                let (lo, hi) = (c.threshold.max(0), (end - 1).min(width - 1));
                if lo <= hi {
                    let row = u32::try_from(row).expect("row on the canvas");
                    let lo = u32::try_from(lo).expect("clamped to the canvas");
                    let hi = u32::try_from(hi).expect("clamped to the canvas");
                    sink.cover_span(row, lo, hi, id);
                }
            }
        }
    }
}
