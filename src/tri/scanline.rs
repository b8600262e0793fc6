//! Edge walking (Luebke, "Drawing triangles"): the triangle scan-converted row by row. On each scanline the
//! span runs from the largest left bound to the smallest right bound of the three edges
//! (sorting the vertices into a left and a right chain amounts to the same max and min),
//! and each bound is advanced from row to row by an exact integer DDA: quotient and
//! remainder, no floats, no division per row. A horizontal edge admits a whole row or
//! none. Same snapped input, tie rule and samples as [`crate::tri::fixed`], so it must
//! equal `exact-snapped` pixel for pixel: the property tests are its proof (Luebke's
//! University of Virginia lecture slides call this algorithm "lots of finicky special cases").
//!
//! Arithmetic in i128: the numerators reach `|N| < 2^63` inside the envelope
//! (`|a| <= 2^29`, `|dx|, |dy| <= 2^30`, samples below 2^30 subpixels) and the divisors
//! `2^S |dy| <= 2^46`.

use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::edge::fixed::FixedEdge;
use crate::geom::FixedTriangle;
use crate::num::dda::CeilDda;
use crate::tri::fixed::{setup, Setup};

/// One edge's bound on the pixel index `i`, walked down the rows: `ceil(value / d)` (a
/// left edge: `i >= bound`) or `floor(value / d)` (a right edge: `i <= bound`), both as
/// a [`CeilDda`] (a floor is the ceil of `value - (d - 1)`).
#[derive(Debug, Clone, Copy)]
struct Walker {
    left: bool,
    bound: CeilDda,
}

impl Walker {
    /// The bound from edge `e` for the row whose sample is at `sy` subpixels.
    fn new(e: &FixedEdge, sy: i128, one: i128, c: i128) -> Walker {
        let (ax, ay, dx, dy) = (
            i128::from(e.a[0]),
            i128::from(e.a[1]),
            i128::from(e.dx),
            i128::from(e.dy),
        );
        // Inside: (px - ax) dy - (sy - ay) dx - bias >= 0  <=>  px dy >= n, with px = i one + c:
        // i (one dy) >= n - c dy.
        let n = i128::from(e.bias) + ax * dy + (sy - ay) * dx - c * dy;
        let left = dy > 0;
        // left: i >= ceil(n / (one dy)); right (dy < 0): i <= floor(-n / (one |dy|)).
        // Per row, sy grows by one, so n grows by one dx.
        let bound = if left {
            CeilDda::new(n, one * dx, one * dy)
        } else {
            let d = -one * dy;
            CeilDda::new(-n - (d - 1), -one * dx, d)
        };
        Walker { left, bound }
    }
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
    let Some(Setup { edges, grid, range }) = setup(tri, target) else {
        return;
    };
    let (one, c) = (i128::from(grid.one), i128::from(grid.centre));
    let sy0 = i128::from(range.y0) * one + c;
    // Per edge: a walker for a sloped edge, or the edge itself for a horizontal one.
    let mut walkers: [Option<Walker>; 3] = edges.map(|e| (e.dy != 0).then(|| Walker::new(&e, sy0, one, c)));
    let horizontal: [Option<FixedEdge>; 3] = edges.map(|e| (e.dy == 0).then_some(e));
    for j in range.y0..=range.y1 {
        let sy = i128::from(j) * one + c;
        // A horizontal edge: inside iff -(sy - ay) dx - bias >= 0, the same for the whole row.
        let row_open = horizontal
            .iter()
            .flatten()
            .all(|e| -(sy - i128::from(e.a[1])) * i128::from(e.dx) - i128::from(e.bias) >= 0);
        let mut lo = i128::from(range.x0);
        let mut hi = i128::from(range.x1);
        for w in walkers.iter().flatten() {
            if w.left {
                lo = lo.max(w.bound.get());
            } else {
                hi = hi.min(w.bound.get());
            }
        }
        if row_open && lo <= hi {
            let lo = u32::try_from(lo).expect("clamped to the canvas range");
            let hi = u32::try_from(hi).expect("clamped to the canvas range");
            sink.cover_span(j, lo, hi, id);
        }
        walkers.iter_mut().flatten().for_each(|w| w.bound.step());
    }
}
