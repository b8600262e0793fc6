//! Polygon fill: the exact oracle (a plain loop over the samples, the winding number of
//! each moved sample counted edge by edge) and the scanline filler of seed 002 (an active
//! edge table on the snapped polygon, exact integer arithmetic).
//!
//! # The rule, and why it equals the triangles' tie rule
//!
//! A sample `p` is tested as the moved sample `p' = p + (ε, ±ε²)` of the tie rule
//! ([`crate::convention::TieRule`]: `+` for top-left, `-` for bottom-left). `p'` lies on
//! no edge of positive length, so its winding number around each contour is well
//! defined: count the contour's edges crossing the horizontal ray from `p'` to the right,
//! `-1` for an edge going down the screen and `+1` for one going up. The sample is inside
//! when the fill rule holds for the outline's winding number and for no hole's
//! ([`Polygon`]); both rules ignore a contour's orientation. An edge `a -> b` with `a.y != b.y` crosses the row of `p'` when
//! `min(a.y, b.y) <= p.y < max(a.y, b.y)` (top-left; `<`, `<=` for bottom-left), and
//! the crossing is right of `p'` when `E(p')` and `dy` have different signs, where
//! `E(p') = E(p) + ε dy ∓ ε² dx` has the sign of `E(p)`, or of `dy` when `E(p) = 0`.
//! For a triangle this is exactly the edge-function rule with the inclusive flags of
//! `TieRule::is_inclusive`, and winding numbers add up over a triangulation (the moved
//! sample is on no shared edge), so a polygon's fill is the disjoint union of its
//! triangulation's coverage. Both statements are property tests (`tests/polygons.rs`).

use std::cmp::Ordering;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::convention::{Target, TieRule};
use crate::coverage::CoverageSink;
use crate::edge::exact::edge_function;
use crate::geom::{FillRule, FixedPolygon, Point, Polygon};
use crate::num::dda::CeilDda;
use crate::tri::{exact_sample_range, fixed_sample_range, sample_coordinate, sample_point};

/// The closed contour's edges `(v[i], v[i+1])`, the last one back to the first vertex.
fn closed_edges<T>(contour: &[T]) -> impl Iterator<Item = (&T, &T)> {
    contour.iter().zip(contour.iter().cycle().skip(1))
}

/// Twice the signed area of a contour in the orientation the triangles use (positive
/// when the interior is on the `E > 0` side of its edges), exactly.
pub fn area2_exact(contour: &[Point]) -> BigRational {
    closed_edges(contour).fold(BigRational::zero(), |acc, (a, b)| acc + (&b.x * &a.y - &a.x * &b.y))
}

/// The winding number of the moved sample of `p` around one closed contour, exactly
/// (see the module docs), in the contour's own orientation.
///
/// ```
/// use rasterproof::convention::TieRule;
/// use rasterproof::fill::polygon::contour_winding_exact;
/// use rasterproof::geom::Point;
/// // A pentagram drawn as one self-crossing contour: its centre winds twice, a tip once.
/// let star: Vec<Point> = [(50, 0), (79, 90), (2, 35), (98, 35), (21, 90)].iter().map(|&(x, y)| Point::from_ints(x, y)).collect();
/// let w = |x, y| contour_winding_exact(&Point::from_ints(x, y), &star, TieRule::TopLeft);
/// assert_eq!(w(50, 50).abs(), 2);
/// assert_eq!(w(50, 10).abs(), 1);
/// assert_eq!(w(50, 50), 2 * w(50, 10)); // the same direction
/// assert_eq!(w(5, 5), 0);
/// ```
pub fn contour_winding_exact(p: &Point, contour: &[Point], rule: TieRule) -> i64 {
    closed_edges(contour).map(|(a, b)| crossing_exact(a, b, p, rule)).sum()
}

/// Whether the moved sample of `p` is inside `poly`: the fill rule holds for its winding
/// number around the outline and for none of the holes'.
pub fn contains_exact(p: &Point, poly: &Polygon, rule: TieRule) -> bool {
    let inside = |c: &[Point]| poly.fill_rule.inside(contour_winding_exact(p, c, rule));
    inside(&poly.outline) && !poly.holes.iter().any(|h| inside(h))
}

/// Whether the edge `a -> b` crosses the row of a moved sample at height `y`: never when
/// horizontal; otherwise `min <= y < max` (top-left: the sample moves down by ε²) or
/// `min < y <= max` (bottom-left).
fn crosses_moved_row(a: &Point, b: &Point, y: &BigRational, rule: TieRule) -> bool {
    let (lo, hi) = if a.y <= b.y { (&a.y, &b.y) } else { (&b.y, &a.y) };
    match rule {
        TieRule::TopLeft => lo <= y && y < hi,
        TieRule::BottomLeft => lo < y && y <= hi,
    }
}

/// The contribution of the edge `a -> b` to the winding number of `p`'s moved sample.
fn crossing_exact(a: &Point, b: &Point, p: &Point, rule: TieRule) -> i64 {
    if !crosses_moved_row(a, b, &p.y, rule) {
        return 0;
    }
    let dy = &b.y - &a.y;
    let e = edge_function(a, b, p);
    let right = !e.is_zero() && e.is_positive() != dy.is_positive();
    match (right, dy.is_positive()) {
        (false, _) => 0,
        (true, true) => -1,
        (true, false) => 1,
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

/// The oracle: covers every pixel whose moved sample is inside `poly` under its fill
/// rule, testing each sample of the bounding box in exact arithmetic. Run it on a scene's
/// polygon as written (model `exact`) or snapped (`exact-snapped`).
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::coverage::Coverage;
/// use rasterproof::fill::polygon::rasterize_exact;
/// use rasterproof::geom::{FillRule, Point, Polygon};
/// // An 8x8 square with a 4x4 hole in the middle, samples at pixel centres:
/// // 64 - 16 = 48 pixels, none of them in rows and columns 2..=5 at once.
/// let sq = |a: i64, b: i64| vec![Point::from_ints(a, a), Point::from_ints(b, a), Point::from_ints(b, b), Point::from_ints(a, b)];
/// let mut poly = Polygon::new(sq(0, 8), FillRule::NonZero);
/// poly.holes.push(sq(2, 6));
/// let target = Target::new(8, 8, Convention::default()).unwrap();
/// let mut c = Coverage::new(8, 8);
/// rasterize_exact(&poly, 0, &target, &mut c);
/// assert_eq!(c.covered_pixels(), 48);
/// assert!(c.owners(3, 3).is_empty());
/// assert_eq!(c.owners(1, 3), &[0]);
/// ```
pub fn rasterize_exact<S: CoverageSink + ?Sized>(poly: &Polygon, id: u32, target: &Target, sink: &mut S) {
    let Some(range) = exact_sample_range(poly.outline.iter().chain(poly.holes.iter().flatten()), target) else {
        return;
    };
    let centre = target.convention.pixel_centre.offset();
    for j in range.y0..=range.y1 {
        for i in range.x0..=range.x1 {
            let sample = sample_point(i, j, &centre);
            if contains_exact(&sample, poly, target.convention.tie_rule) {
                sink.cover(i, j, id);
            }
        }
    }
}

/// One polygon edge in the edge table: oriented downwards (`dy > 0`), with the rows whose
/// moved sample it crosses and its winding contribution.
#[derive(Debug, Clone, Copy)]
struct TableEdge {
    first_row: i64,
    last_row: i64,
    top: [i128; 2],
    dx: i128,
    dy: i128,
    /// Which contour (0 the outline).
    contour: usize,
    /// `-1` for an edge going down the screen, `+1` going up.
    winding: i64,
}

/// An edge on the active list: its winding and the first pixel index at or right of its
/// crossing, `ceil((xc - centre) / one)`, walked down the rows.
#[derive(Debug, Clone, Copy)]
struct ActiveEdge {
    last_row: i64,
    contour: usize,
    winding: i64,
    threshold: CeilDda,
}

/// The scanline filler (seed 002's active edge list) on the snapped polygon: edges sorted
/// by their first row enter the active list, leave after their last, and on each row
/// their crossings, sorted, delimit spans of constant winding number. Each crossing's
/// pixel threshold `ceil((xc - c) / one)` is an exact integer DDA in i128 (no floats, no
/// division per row). Equal to [`rasterize_exact`] on the same snapped polygon, pixel for
/// pixel, self-intersecting or not.
///
/// Envelope: coordinates `|v| <= 2^29` subpixels ([`FixedPolygon`] guarantees it), so
/// numerators stay below `2^62` and denominators below `2^46`.
///
/// # Panics
/// When `poly` was snapped to another grid than `target`'s subpixel bits.
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::coverage::Coverage;
/// use rasterproof::fill::polygon::{rasterize, rasterize_exact};
/// use rasterproof::geom::{FillRule, Point, Polygon};
/// let l_shape = [(0, 0), (6, 0), (6, 2), (2, 2), (2, 6), (0, 6)];
/// let poly = Polygon::new(l_shape.iter().map(|&(x, y)| Point::from_ints(x, y)).collect(), FillRule::EvenOdd);
/// let target = Target::new(8, 8, Convention::default()).unwrap();
/// let fixed = poly.to_fixed(&target.convention).unwrap();
/// let (mut a, mut b) = (Coverage::new(8, 8), Coverage::new(8, 8));
/// rasterize(&fixed, 0, &target, &mut a);
/// rasterize_exact(&poly, 0, &target, &mut b);
/// assert_eq!(a, b);
/// assert_eq!(a.covered_pixels(), 6 * 2 + 2 * 4); // the 6x2 bar and the 2x4 leg
/// ```
pub fn rasterize<S: CoverageSink + ?Sized>(poly: &FixedPolygon, id: u32, target: &Target, sink: &mut S) {
    let conv = &target.convention;
    assert_eq!(
        poly.bits, conv.subpixel_bits,
        "polygon snapped to another grid than the target's"
    );
    let one = 1i64 << conv.subpixel_bits;
    let centre = conv.pixel_centre.offset_subpixels(conv.subpixel_bits);
    let Some(range) = fixed_sample_range(poly.contours().iter().flatten().copied(), one, centre, target) else {
        return;
    };
    let (y0, y1) = (i64::from(range.y0), i64::from(range.y1));
    let mut table = edge_table(poly, conv.tie_rule, one, centre);
    table.retain(|e| e.first_row <= e.last_row && e.last_row >= y0 && e.first_row <= y1);
    table.sort_by_key(|e| e.first_row);
    let (one, c) = (i128::from(one), i128::from(centre));

    let mut next = 0;
    let mut active: Vec<ActiveEdge> = Vec::new();
    let mut crossings: Vec<Crossing> = Vec::new();
    let mut sweep = Sweep::new(poly.contours().len(), poly.fill_rule);
    for j in y0..=y1 {
        while next < table.len() && table[next].first_row.max(y0) == j {
            let e = &table[next];
            // Threshold numerator at row j: (tx - c) dy + (sy - ty) dx, sy = j one + c.
            let sy = i128::from(j) * one + c;
            let value = (e.top[0] - c) * e.dy + (sy - e.top[1]) * e.dx;
            active.push(ActiveEdge {
                last_row: e.last_row,
                contour: e.contour,
                winding: e.winding,
                threshold: CeilDda::new(value, one * e.dx, one * e.dy),
            });
            next += 1;
        }
        active.retain(|a| a.last_row >= j);
        crossings.clear();
        crossings.extend(active.iter().map(|a| Crossing {
            threshold: a.threshold.get(),
            contour: a.contour,
            winding: a.winding,
        }));
        sweep.emit_spans(j, &mut crossings, id, target, sink);
        active.iter_mut().for_each(|a| a.threshold.step());
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

/// A second exact model, row by row on the polygon as written (rationals, no snapping):
/// for each row, the crossing of every edge with the moved sample's row is computed
/// exactly, `x_c = a.x + (y - a.y) dx / dy`, its pixel threshold is `ceil(x_c - c)`, and
/// the spans follow as in [`rasterize`]. `O(rows x edges)` rational operations instead
/// of the oracle's `O(pixels x edges)`; proven equal to [`rasterize_exact`] by the
/// property tests. Used where a whole canvas must be filled exactly (clip windows).
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::coverage::Coverage;
/// use rasterproof::fill::polygon::{rasterize_exact, rasterize_rows_exact};
/// use rasterproof::geom::{FillRule, Point, Polygon};
/// let poly = Polygon::new(vec![Point::from_fractions(1, 3, 0, 1), Point::from_ints(7, 2), Point::from_fractions(2, 1, 15, 2)], FillRule::NonZero);
/// let target = Target::new(8, 8, Convention::default()).unwrap();
/// let (mut a, mut b) = (Coverage::new(8, 8), Coverage::new(8, 8));
/// rasterize_rows_exact(&poly, 0, &target, &mut a);
/// rasterize_exact(&poly, 0, &target, &mut b);
/// assert_eq!(a, b);
/// ```
pub fn rasterize_rows_exact<S: CoverageSink + ?Sized>(poly: &Polygon, id: u32, target: &Target, sink: &mut S) {
    let Some(range) = exact_sample_range(poly.outline.iter().chain(poly.holes.iter().flatten()), target) else {
        return;
    };
    let centre = target.convention.pixel_centre.offset();
    let rule = target.convention.tie_rule;
    let mut crossings: Vec<Crossing> = Vec::new();
    let mut sweep = Sweep::new(poly.contours().count(), poly.fill_rule);
    for j in range.y0..=range.y1 {
        let sy = sample_coordinate(j, &centre);
        crossings.clear();
        for (k, contour) in poly.contours().enumerate() {
            for (a, b) in closed_edges(contour) {
                if !crosses_moved_row(a, b, &sy, rule) {
                    continue;
                }
                let dy = &b.y - &a.y;
                let xc = &a.x + (&sy - &a.y) * (&b.x - &a.x) / &dy;
                let threshold = i128::from(crate::tri::saturating_index((xc - &centre).ceil().to_integer()));
                crossings.push(Crossing {
                    threshold,
                    contour: k,
                    winding: if dy.is_positive() { -1 } else { 1 },
                });
            }
        }
        sweep.emit_spans(i64::from(j), &mut crossings, id, target, sink);
    }
}

/// Every non-horizontal edge, oriented downwards, with its rows (before clamping to the
/// canvas), its contour and its direction.
fn edge_table(poly: &FixedPolygon, rule: TieRule, one: i64, centre: i64) -> Vec<TableEdge> {
    let mut table = Vec::new();
    for (k, contour) in poly.contours().iter().enumerate() {
        for (a, b) in closed_edges(contour) {
            let (top, bottom, down) = match a[1].cmp(&b[1]) {
                Ordering::Equal => continue,
                Ordering::Less => (a, b, true),
                Ordering::Greater => (b, a, false),
            };
            // Rows j whose sample sy = j one + centre satisfies ty <= sy < by (top-left)
            // or ty < sy <= by (bottom-left).
            let ceil = |v: i64| -(-(v - centre)).div_euclid(one);
            let floor = |v: i64| (v - centre).div_euclid(one);
            let (first_row, last_row) = match rule {
                TieRule::TopLeft => (ceil(top[1]), ceil(bottom[1]) - 1),
                TieRule::BottomLeft => (floor(top[1]) + 1, floor(bottom[1])),
            };
            table.push(TableEdge {
                first_row,
                last_row,
                top: [i128::from(top[0]), i128::from(top[1])],
                dx: i128::from(bottom[0] - top[0]),
                dy: i128::from(bottom[1] - top[1]),
                contour: k,
                winding: if down { -1 } else { 1 },
            });
        }
    }
    table
}
