//! Edge walking (Luebke, "Drawing triangles"): the triangle scan-converted row by row. On each scanline the
//! span runs from the largest left bound to the smallest right bound of the three edges
//! (sorting the vertices into a left and a right chain amounts to the same max and min),
//! and each bound is advanced from row to row by an exact integer DDA: quotient and
//! remainder, no floats, no division per row. A horizontal edge admits a whole row or
//! none. Same snapped input, tie rule and samples as [`crate::tri::fixed`], so it must
//! equal `exact-snapped` pixel for pixel: the property tests are its proof (Luebke's
//! University of Virginia lecture slides call this algorithm "lots of finicky special cases").
//!
//! Arithmetic: i64 throughout, each bound a [`CeilDda64`]. Every value a
//! walk passes through is an edge value `E - bias` at a point `(c, sy)` (`c` the column-0
//! sample offset, `sy` a row's sample, one row past the last included) less at most
//! `2^S |dy| <= 2^46`: inside the envelope of [`crate::num::fixed`] (`|a| <= 2^29`,
//! `|dx|, |dy| <= 2^30`, samples below `(16384 + 1) 2^16`) that is below `3.1 * 2^60`,
//! within [`CeilDda64`]'s `2^62`. The setup checks it anyway (a failed check is a wrong
//! proof, and panics). A horizontal edge does not walk: it admits the rows on its inner
//! side, which narrows the rows walked.

use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::edge::fixed::triangle_edges;
use crate::edge::fixed::FixedEdge;
use crate::geom::FixedTriangle;
use crate::num::dda::CeilDda64;
use crate::raster::FixedGrid;
use crate::raster::{fixed_sample_range, PixelRange};

/// The magnitude every value of a walk stays below: [`CeilDda64`]'s envelope.
const WALK_LIMIT: u64 = 1 << 62;

/// One edge's bound on the pixel index `i`, walked down the rows: `ceil(value / d)` (a
/// left edge: `i >= bound`) or `floor(value / d)` (a right edge: `i <= bound`), both as
/// a [`CeilDda64`] (a floor is the ceil of `value - (d - 1)`).
#[derive(Debug, Clone, Copy)]
struct Walker {
    left: bool,
    bound: CeilDda64,
}

impl Walker {
    /// The bound from edge `e` from the row whose sample is at `sy` subpixels, for `rows`
    /// rows.
    ///
    /// # Panics
    /// When a value of the walk reaches `2^62` (impossible inside the envelope: see the
    /// module docs).
    fn new(e: &FixedEdge, sy: i64, rows: i64, grid: &FixedGrid) -> Walker {
        let (one, c) = (grid.one, grid.centre);
        let ([ax, ay], dx, dy) = (e.a, e.dx, e.dy);
        // Inside: (px - ax) dy - (sy - ay) dx - bias >= 0  <=>  px dy >= n, with px = i one + c:
        // i (one dy) >= n - c dy. In i64: |ax dy| <= 2^59, |(sy - ay) dx| < 1.5 * 2^60 and
        // |c dy| <= 2^45 inside the envelope (see the module docs), so |n| < 2^61.
        let n = e.bias + ax * dy + (sy - ay) * dx - c * dy;
        // left (dy > 0): i >= ceil(n / (one dy)); right (dy < 0): i <= floor(-n / (one |dy|)).
        // Per row, sy grows by one, so n grows by one dx.
        let left = dy > 0;
        let (value, inc, d) = if left {
            (n, one * dx, one * dy)
        } else {
            let d = -one * dy;
            (-n - (d - 1), -one * dx, d)
        };
        // The value one step past the last row: below 2^61 + 16385 * 2^46 < 2^62.
        walk_value(value + rows * inc);
        Walker {
            left,
            bound: CeilDda64::new(walk_value(value), walk_value(inc), walk_value(d)),
        }
    }
}

/// A value of a walk, checked below `2^62` ([`CeilDda64`]'s envelope).
///
/// # Panics
/// At `2^62` or beyond (a wrong envelope proof).
fn walk_value(v: i64) -> i64 {
    assert!(
        v.unsigned_abs() < WALK_LIMIT,
        "scanline walk value {v} beyond 2^62: the envelope proof is wrong"
    );
    v
}

/// Covers every pixel whose sample is inside `tri` (snapped, inside the envelope), span by
/// span. Equal to [`crate::tri::fixed::rasterize`] and to the oracle on the snapped triangle.
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::coverage::Coverage;
/// use rasterproof::geom::{Point, Triangle};
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(8, 0), Point::from_fractions(3, 2, 8, 1));
/// let target = Target::new(8, 8, Convention::default()).unwrap();
/// let fixed = t.snapped(&target.convention).to_fixed().unwrap();
/// let (mut a, mut b) = (Coverage::new(8, 8), Coverage::new(8, 8));
/// rasterproof::tri::scanline::rasterize(&fixed, 0, &target, &mut a);
/// rasterproof::tri::exact::rasterize(&t, 0, &target, &mut b);
/// assert_eq!(a, b);
/// ```
///
/// # Panics
/// When `tri` was snapped to another grid than `target`'s subpixel bits.
pub fn rasterize<S: CoverageSink + ?Sized>(tri: &FixedTriangle, id: u32, target: &Target, sink: &mut S) {
    let Some(FixedSetup { edges, grid, range }) = setup(tri, target) else {
        return;
    };
    // A horizontal edge: inside iff -(sy - ay) dx - bias >= 0, the same for the whole row.
    // With bias in {0, 1} and |dx| >= 1: dx > 0 admits sy <= ay - bias, dx < 0 sy >= ay + bias.
    let (mut y0, mut y1) = (i64::from(range.y0), i64::from(range.y1));
    for e in edges.iter().filter(|e| e.dy == 0) {
        if e.dx > 0 {
            y1 = y1.min(grid.last_at_or_before(e.a[1] - e.bias));
        } else {
            y0 = y0.max(grid.first_at_or_after(e.a[1] + e.bias));
        }
    }
    if y0 > y1 {
        return;
    }
    let row = |v: i64| u32::try_from(v).expect("within the range's rows");
    let (y0, y1) = (row(y0), row(y1));
    let (sy0, rows) = (grid.sample(y0), i64::from(y1 - y0) + 1);
    // At most two edges on a side (the dy of a closed triangle sum to zero), and at least
    // one: the rows walk two or three bounds.
    let unused = CeilDda64::new(0, 0, 1);
    let (mut left, mut right) = ([unused; 2], [unused; 2]);
    let (mut nl, mut nr) = (0, 0);
    for e in edges.iter().filter(|e| e.dy != 0) {
        let w = Walker::new(e, sy0, rows, &grid);
        let (side, n) = if w.left {
            (&mut left, &mut nl)
        } else {
            (&mut right, &mut nr)
        };
        side[*n] = w.bound;
        *n += 1;
    }
    let (x, y) = ([range.x0, range.x1], [y0, y1]);
    match (nl, nr) {
        (1, 1) => spans([left[0]], [right[0]], x, y, id, sink),
        (2, 1) => spans(left, [right[0]], x, y, id, sink),
        (1, 2) => spans([left[0]], right, x, y, id, sink),
        _ => unreachable!("a triangle with area has one or two edges on each side"),
    }
}

/// The spans of rows `y[0]..=y[1]` within columns `x[0]..=x[1]`: from the largest left
/// bound to the smallest right bound (one loop per count of bounds on each side, so no
/// row steps a bound that is not there).
#[inline(always)]
fn spans<const L: usize, const R: usize, S: CoverageSink + ?Sized>(
    mut left: [CeilDda64; L],
    mut right: [CeilDda64; R],
    x: [u32; 2],
    y: [u32; 2],
    id: u32,
    sink: &mut S,
) {
    let (x0, x1) = (i64::from(x[0]), i64::from(x[1]));
    for j in y[0]..=y[1] {
        let lo = left.iter().fold(x0, |lo, b| lo.max(b.get()));
        let hi = right.iter().fold(x1, |hi, b| hi.min(b.get()));
        if lo <= hi {
            // x0 <= lo <= hi <= x1, both u32: exact
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
            sink.cover_span(j, lo as u32, hi as u32, id);
        }
        for b in left.iter_mut().chain(right.iter_mut()) {
            b.step();
        }
    }
}

/// The per-triangle setup of the edge walk (`fixed` computes the same values its own
/// way, with shifts, in `tri/fixed.rs`).
pub(crate) struct FixedSetup {
    /// The oriented edges with their tie-rule biases.
    pub edges: [FixedEdge; 3],
    /// The sample grid in subpixels.
    pub grid: FixedGrid,
    /// The pixels whose sample lies in the bounding box, on the canvas.
    pub range: PixelRange,
}

/// Orients `tri` and finds its pixel range; `None` when it covers nothing (zero area, or
/// off the canvas).
///
/// # Panics
/// When `tri` was snapped to another grid than `target`'s subpixel bits.
#[inline]
pub(crate) fn setup(tri: &FixedTriangle, target: &Target) -> Option<FixedSetup> {
    let conv = &target.convention;
    assert_eq!(
        tri.bits, conv.subpixel_bits,
        "triangle snapped to another grid than the target's"
    );
    let edges = triangle_edges(tri, conv.tie_rule)?;
    let range = fixed_sample_range(tri.coords().into_iter(), target)?;
    Some(FixedSetup {
        edges,
        grid: FixedGrid::of(conv),
        range,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The walk's envelope, one unit each side: `2^62 - 1` is a walk value, `2^62` and
    /// `-2^62` are not.
    #[test]
    fn a_walk_value_is_below_2_to_the_62() {
        assert_eq!(walk_value((1 << 62) - 1), (1 << 62) - 1);
        assert_eq!(walk_value(1 - (1 << 62)), 1 - (1 << 62));
        for v in [1i64 << 62, -(1i64 << 62), i64::MIN] {
            assert!(std::panic::catch_unwind(|| walk_value(v)).is_err(), "{v}");
        }
    }
}
