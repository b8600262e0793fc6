//! The row-by-row exact polygon filler: each edge's crossing with each sample row computed
//! in rationals on the polygon as written, the spans swept as in the scanline filler.

use num_traits::Signed;

use super::{closed_edges, crosses_moved_row, Crossing, Sweep};
use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::geom::{Point, Polygon};
use crate::raster::{exact_sample_range, ExactGrid};

/// A second exact model, row by row on the polygon as written (rationals, no snapping):
/// for each row, the crossing of every edge with the moved sample's row is computed
/// exactly, `x_c = a.x + (y - a.y) dx / dy`, its pixel threshold is `ceil(x_c - c)`, and
/// the spans follow as in [`rasterize`](super::rasterize). `O(rows x edges)` rational
/// operations at most instead of the oracle's `O(pixels x edges)`, and `O(n log n + rows x
/// edges per row)` as run: each row looks only at the edges that reach it (a sweep of the
/// edges sorted by their top); proven equal to
/// [`rasterize_exact`](super::rasterize_exact) by the property tests. Used where a whole canvas must be filled exactly (clip windows).
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
    let rule = target.convention.tie_rule.moved_sample();
    let grid = ExactGrid::of(target);
    let mut crossings: Vec<Crossing> = Vec::new();
    let mut sweep = Sweep::new(poly.contours().count(), poly.fill_rule);
    // The edges sorted by their top; a row looks only at those that reach it.
    let mut edges: Vec<(usize, &Point, &Point)> = poly
        .contours()
        .enumerate()
        .flat_map(|(k, c)| closed_edges(c).map(move |(a, b)| (k, a, b)))
        .filter(|(_, a, b)| a.y != b.y)
        .collect();
    edges.sort_by(|x, y| std::cmp::min(&x.1.y, &x.2.y).cmp(std::cmp::min(&y.1.y, &y.2.y)));
    let mut next = 0;
    let mut active: Vec<(usize, &Point, &Point)> = Vec::new();
    for j in range.y0..=range.y1 {
        let sy = grid.coordinate(j);
        while next < edges.len() && (edges[next].1.y <= sy || edges[next].2.y <= sy) {
            active.push(edges[next]);
            next += 1;
        }
        active.retain(|(_, a, b)| a.y >= sy || b.y >= sy);
        crossings.clear();
        for &(k, a, b) in &active {
            if !crosses_moved_row(a, b, &sy, rule) {
                continue;
            }
            let dy = &b.y - &a.y;
            let xc = &a.x + (&sy - &a.y) * (&b.x - &a.x) / &dy;
            let threshold = i128::from(grid.first_at_or_after(&xc));
            crossings.push(Crossing {
                threshold,
                contour: k,
                winding: if dy.is_positive() { -1 } else { 1 },
            });
        }
        sweep.emit_spans(i64::from(j), &mut crossings, id, target, sink);
    }
}
