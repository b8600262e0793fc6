//! The polygon oracle: every sample of the bounding box tested in exact arithmetic, by
//! its moved sample's winding number around each contour; under all-inclusive and
//! all-exclusive, by the closed or the open shape.
//!
//! # All-inclusive and all-exclusive
//!
//! For a triangle these rules read "every edge owns its samples" and "no edge does": the
//! closed and the open triangle. For a polygon the same two sets are the closure and the
//! interior of the filled region (the points on no edge whose winding numbers the fill
//! rule holds). A sample on no edge is in both or in neither, as under every directional
//! rule. A sample on an edge is the apex of the angular sectors between the edges through
//! it; the winding number is constant in each sector near the apex, so the sample is in
//! the closure when one sector is inside, and in the interior when every sector is. Each
//! sector is tested at a point moved from the sample by `t d`, `t -> 0+`, for a direction
//! `d` strictly inside it: `u + v` for the sector between rays `u` and `v` when it is
//! narrower than a half turn, `u` turned a quarter turn towards `v` otherwise. A sample on
//! an edge inside the region (a self-overlapping contour, the inner edges of a nonzero
//! pentagram) is in the interior; on the same edges under even-odd, it is not.

use std::cmp::Ordering;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::{closed_edges, crosses_moved_row};
use crate::convention::{AnyTieRule, MovedSample, Target, TieRule};
use crate::coverage::samples::SampleCoverage;
use crate::coverage::CoverageSink;
use crate::edge::exact::edge_function;
use crate::geom::{Point, Polygon};
use crate::pattern::SamplePattern;
use crate::raster::{exact_pixel_range, exact_sample_range, ExactGrid};

/// The winding number of the moved sample of `p` around one closed contour, exactly
/// (see the [module docs](super)), in the contour's own orientation.
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
    let moved = rule.moved_sample();
    closed_edges(contour).map(|(a, b)| crossing_moved(a, b, p, moved)).sum()
}

/// Whether the moved sample of `p` is inside `poly`: the fill rule holds for its winding
/// number around the outline and for none of the holes'.
pub fn contains_exact(p: &Point, poly: &Polygon, rule: TieRule) -> bool {
    contains_exact_with(p, poly, rule.into())
}

/// Whether `poly` covers the sample `p` under any of the six tie rules: a directional
/// rule tests the moved sample; all-inclusive asks whether `p` is in the closure of the
/// filled region, all-exclusive whether it is in its interior (the module docs).
///
/// ```
/// use rasterproof::convention::AnyTieRule;
/// use rasterproof::fill::polygon::contains_exact_with;
/// use rasterproof::geom::{FillRule, Point, Polygon};
/// // The square [0, 2] x [0, 2]: its corner (0, 0) is in the closed square only; its
/// // top-left corner belongs to the top-left rule, its top-right corner to top-right.
/// let sq = Polygon::new([(0, 0), (2, 0), (2, 2), (0, 2)].iter().map(|&(x, y)| Point::from_ints(x, y)).collect(), FillRule::NonZero);
/// let at = |x, y, rule| contains_exact_with(&Point::from_ints(x, y), &sq, rule);
/// assert!(at(0, 0, AnyTieRule::AllInclusive));
/// assert!(!at(0, 0, AnyTieRule::AllExclusive));
/// assert!(at(0, 0, AnyTieRule::TopLeft) && !at(0, 0, AnyTieRule::TopRight));
/// assert!(at(2, 0, AnyTieRule::TopRight) && !at(2, 0, AnyTieRule::BottomRight));
/// assert!(at(1, 1, AnyTieRule::AllExclusive));
/// ```
pub fn contains_exact_with(p: &Point, poly: &Polygon, rule: AnyTieRule) -> bool {
    if let Some(moved) = rule.moved_sample() {
        return filled_by(poly, |a, b| crossing_moved(a, b, p, moved));
    }
    let directions = sector_directions(p, poly);
    if directions.is_empty() {
        // On no edge: every rule gives the same answer; ask the top-left move.
        return contains_exact(p, poly, TieRule::TopLeft);
    }
    let sector_inside = |d: &[BigRational; 2]| filled_by(poly, |a, b| crossing_towards(a, b, p, d));
    match rule {
        AnyTieRule::AllInclusive => directions.iter().any(sector_inside),
        _ => directions.iter().all(sector_inside),
    }
}

/// The fill rule on the outline's winding number and on no hole's, each contour's winding
/// counted by `crossing` edge by edge.
fn filled_by(poly: &Polygon, crossing: impl Fn(&Point, &Point) -> i64) -> bool {
    let inside = |c: &[Point]| {
        poly.fill_rule
            .inside(closed_edges(c).map(|(a, b)| crossing(a, b)).sum())
    };
    inside(&poly.outline) && !poly.holes.iter().any(|h| inside(h))
}

/// The contribution of the edge `a -> b` to the winding number of `p`'s moved sample
/// `p + (±ε, ±ε²)`: its crossing with the moved sample's row, when right of it, counts
/// `-1` going down the screen and `+1` going up. `E(p')` has the sign of `E(p)`, or when
/// that is 0 the sign of `±dy`.
fn crossing_moved(a: &Point, b: &Point, p: &Point, moved: MovedSample) -> i64 {
    if !crosses_moved_row(a, b, &p.y, moved) {
        return 0;
    }
    let dy = &b.y - &a.y;
    let e = edge_function(a, b, p);
    let right = if e.is_zero() {
        !moved.right
    } else {
        e.is_positive() != dy.is_positive()
    };
    winding_of(right, &dy)
}

/// The contribution of the edge `a -> b` to the winding number of `p + t d`, `t -> 0+`,
/// for a direction `d` along no edge through `p`: the same count, each sign read first on
/// the value at `p`, then on its rate of change along `d`.
fn crossing_towards(a: &Point, b: &Point, p: &Point, d: &[BigRational; 2]) -> i64 {
    let dy = &b.y - &a.y;
    if dy.is_zero() {
        return 0;
    }
    let above = |v: &Point| first_sign(&(&p.y - &v.y), &d[1]) != Ordering::Less;
    if above(a) == above(b) {
        return 0; // both ends below the moved row, or both at or above it
    }
    let dx = &b.x - &a.x;
    let e = first_sign(&edge_function(a, b, p), &(&d[0] * &dy - &d[1] * &dx));
    let right = e != Ordering::Equal && (e == Ordering::Greater) != dy.is_positive();
    winding_of(right, &dy)
}

/// `-1` for a crossing right of the sample going down the screen, `+1` going up.
fn winding_of(right: bool, dy: &BigRational) -> i64 {
    match (right, dy.is_positive()) {
        (false, _) => 0,
        (true, true) => -1,
        (true, false) => 1,
    }
}

/// The sign of `v + t rate` for an infinitesimal `t > 0`.
fn first_sign(v: &BigRational, rate: &BigRational) -> Ordering {
    match v.cmp(&BigRational::zero()) {
        Ordering::Equal => rate.cmp(&BigRational::zero()),
        o => o,
    }
}

/// One direction strictly inside each angular sector around `p` between the edges
/// through it (the module docs); empty when `p` lies on no edge.
fn sector_directions(p: &Point, poly: &Polygon) -> Vec<[BigRational; 2]> {
    let mut rays: Vec<[BigRational; 2]> = Vec::new();
    for (a, b) in poly.contours().flat_map(closed_edges) {
        let within = |u: &BigRational, v: &BigRational, t: &BigRational| u.min(v) <= t && t <= u.max(v);
        if !edge_function(a, b, p).is_zero() || !within(&a.x, &b.x, &p.x) || !within(&a.y, &b.y, &p.y) {
            continue;
        }
        rays.extend(
            [a, b]
                .into_iter()
                .filter(|v| *v != p)
                .map(|v| [&v.x - &p.x, &v.y - &p.y]),
        );
    }
    let cross = |u: &[BigRational; 2], v: &[BigRational; 2]| &u[0] * &v[1] - &u[1] * &v[0];
    // Counter-clockwise from the positive x axis (in the x-right, y-up reading of these
    // signs): the half turn [0, π) first, then [π, 2π), each by the cross product.
    let half = |v: &[BigRational; 2]| !(v[1].is_positive() || (v[1].is_zero() && v[0].is_positive()));
    rays.sort_by(|u, v| {
        half(u)
            .cmp(&half(v))
            .then_with(|| BigRational::zero().cmp(&cross(u, v)))
    });
    rays.dedup_by(|v, u| half(u) == half(v) && cross(u, v).is_zero());
    (0..rays.len())
        .map(|k| {
            let (u, v) = (&rays[k], &rays[(k + 1) % rays.len()]);
            if rays.len() > 1 && cross(u, v).is_positive() {
                [&u[0] + &v[0], &u[1] + &v[1]]
            } else {
                [-&u[1], u[0].clone()] // a half turn or more: a quarter turn from u
            }
        })
        .collect()
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
    rasterize_exact_with(poly, id, target, target.convention.tie_rule.into(), sink);
}

/// [`rasterize_exact`] under any of the six tie rules ([`contains_exact_with`]), the
/// target's own aside.
///
/// ```
/// use rasterproof::convention::{AnyTieRule, Convention, PixelCentre, Target};
/// use rasterproof::coverage::Coverage;
/// use rasterproof::fill::polygon::rasterize_exact_with;
/// use rasterproof::geom::{FillRule, Point, Polygon};
/// // The square [1, 3] x [1, 3] with samples at pixel corners: 3 x 3 samples in the
/// // closed square, 1 in the open one, 2 x 2 under each directional rule.
/// let sq = Polygon::new([(1, 1), (3, 1), (3, 3), (1, 3)].iter().map(|&(x, y)| Point::from_ints(x, y)).collect(), FillRule::NonZero);
/// let target = Target::new(4, 4, Convention { pixel_centre: PixelCentre::Corner, ..Convention::default() }).unwrap();
/// let count = |rule| {
///     let mut c = Coverage::new(4, 4);
///     rasterize_exact_with(&sq, 0, &target, rule, &mut c);
///     c.covered_pixels()
/// };
/// assert_eq!(count(AnyTieRule::AllInclusive), 9);
/// assert_eq!(count(AnyTieRule::AllExclusive), 1);
/// assert_eq!(count(AnyTieRule::BottomRight), 4);
/// ```
pub fn rasterize_exact_with<S: CoverageSink + ?Sized>(
    poly: &Polygon,
    id: u32,
    target: &Target,
    rule: AnyTieRule,
    sink: &mut S,
) {
    let Some(range) = exact_sample_range(poly.outline.iter().chain(poly.holes.iter().flatten()), target) else {
        return;
    };
    let grid = ExactGrid::of(target);
    for j in range.y0..=range.y1 {
        for i in range.x0..=range.x1 {
            let sample = grid.sample(i, j);
            if contains_exact_with(&sample, poly, rule) {
                sink.cover(i, j, id);
            }
        }
    }
}

/// Covers every sample of `pattern` inside `poly` under `target`'s tie rule
/// ([`contains_exact`] at the exact point `(i + x_s, j + y_s)` of each sample `s` of each
/// pixel `(i, j)`). The plain per-sample oracle.
pub fn rasterize_exact_samples(
    poly: &Polygon,
    id: u32,
    target: &Target,
    pattern: &SamplePattern,
    sink: &mut SampleCoverage,
) {
    let Some(range) = exact_pixel_range(poly.outline.iter().chain(poly.holes.iter().flatten()), target) else {
        return;
    };
    for j in range.y0..=range.y1 {
        for i in range.x0..=range.x1 {
            for s in 0..pattern.len() {
                if contains_exact(&pattern.sample(i, j, s), poly, target.convention.tie_rule) {
                    sink.cover(i, j, s, id);
                }
            }
        }
    }
}
