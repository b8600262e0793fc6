//! The scanline polygon filler: an active edge table on the snapped polygon, each
//! crossing's pixel threshold an exact integer DDA.

use std::cmp::Ordering;

use super::{closed_edges, Crossing, Sweep};
use crate::convention::{Target, TieRule};
use crate::coverage::CoverageSink;
use crate::geom::FixedPolygon;
use crate::num::dda::CeilDda;
use crate::raster::{fixed_sample_range, FixedGrid};

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

/// The scanline filler (the active edge table of Foley, van Dam et al.) on the snapped
/// polygon: edges sorted by their first row enter the active list, leave after their
/// last, and on each row their crossings, sorted, delimit spans of constant winding
/// number. Each crossing's pixel threshold `ceil((xc - c) / one)` is an exact integer DDA
/// in i128 (no floats, no division per row). Equal to
/// [`rasterize_exact`](super::rasterize_exact) on the same snapped polygon, pixel for
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
    let grid = FixedGrid::of(conv);
    let Some(range) = fixed_sample_range(poly.contours().iter().flatten().copied(), target) else {
        return;
    };
    let (y0, y1) = (i64::from(range.y0), i64::from(range.y1));
    let mut table = edge_table(poly, conv.tie_rule, grid);
    table.retain(|e| e.first_row <= e.last_row && e.last_row >= y0 && e.first_row <= y1);
    table.sort_by_key(|e| e.first_row);
    let (one, c) = (i128::from(grid.one), i128::from(grid.centre));

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

/// Every non-horizontal edge, oriented downwards, with its rows (before clamping to the
/// canvas), its contour and its direction.
fn edge_table(poly: &FixedPolygon, rule: TieRule, grid: FixedGrid) -> Vec<TableEdge> {
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
            let ceil = |v: i64| grid.first_at_or_after(v);
            let floor = |v: i64| grid.last_at_or_before(v);
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
