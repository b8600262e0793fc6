//! The polygon oracle: every sample of the bounding box tested in exact arithmetic, by
//! its moved sample's winding number around each contour.

use num_traits::{Signed, Zero};

use super::{closed_edges, crosses_moved_row};
use crate::convention::{Target, TieRule};
use crate::coverage::CoverageSink;
use crate::edge::exact::edge_function;
use crate::geom::{Point, Polygon};
use crate::raster::{exact_sample_range, ExactGrid};

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
    closed_edges(contour).map(|(a, b)| crossing_exact(a, b, p, rule)).sum()
}

/// Whether the moved sample of `p` is inside `poly`: the fill rule holds for its winding
/// number around the outline and for none of the holes'.
pub fn contains_exact(p: &Point, poly: &Polygon, rule: TieRule) -> bool {
    let inside = |c: &[Point]| poly.fill_rule.inside(contour_winding_exact(p, c, rule));
    inside(&poly.outline) && !poly.holes.iter().any(|h| inside(h))
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
    let grid = ExactGrid::of(target);
    for j in range.y0..=range.y1 {
        for i in range.x0..=range.x1 {
            let sample = grid.sample(i, j);
            if contains_exact(&sample, poly, target.convention.tie_rule) {
                sink.cover(i, j, id);
            }
        }
    }
}
