//! The incremental integer rasterizer on the snapped scene: one setup per triangle, then
//! `E(x+1, y) = E + dY`, `E(x, y+1) = E - dX` (Pineda 1988), traversed in [`BLOCK`] x
//! [`BLOCK`] blocks: a block whose four corner samples are all outside one edge is
//! skipped, a block whose corners are inside all three edges is filled as spans, only the
//! rest is tested per pixel. i64 throughout; the envelope of [`crate::num::fixed`]
//! guarantees no value can overflow (see there for the bound).

use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::edge::fixed::{triangle_edges, FixedEdge};
use crate::geom::FixedTriangle;
use crate::raster::{fixed_sample_range, FixedGrid, PixelRange};

/// Block side, in pixels (the L of Pineda's `E(x+L, y) = E + L dY`).
pub const BLOCK: u32 = 8;

/// Covers every pixel whose sample is inside `tri` (already snapped, inside the envelope).
/// Equal, pixel for pixel, to [`crate::tri::exact::rasterize`] on the same snapped triangle.
///
/// # Panics
/// When `tri` was snapped to another grid than `target`'s subpixel bits (a caller bug:
/// the coordinates would be read in the wrong unit).
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::coverage::Coverage;
/// use rasterproof::geom::{Point, Triangle};
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
/// let target = Target::new(4, 4, Convention::default()).unwrap();
/// let fixed = t.snapped(&target.convention).to_fixed().unwrap();
/// let (mut a, mut b) = (Coverage::new(4, 4), Coverage::new(4, 4));
/// rasterproof::tri::fixed::rasterize(&fixed, 0, &target, &mut a);
/// rasterproof::tri::exact::rasterize(&t, 0, &target, &mut b);
/// assert_eq!(a, b);
/// ```
pub fn rasterize<S: CoverageSink + ?Sized>(tri: &FixedTriangle, id: u32, target: &Target, sink: &mut S) {
    let Some(Setup { edges, grid, range }) = setup(tri, target) else {
        return;
    };
    let (one, sample) = (grid.one, |x: u32, y: u32| grid.sample_point(x, y));
    // One pixel right adds dY (in pixel units: dY * 2^S); one pixel down subtracts dX.
    let step_x = edges.map(|e| e.dy * one);
    let step_y = edges.map(|e| -e.dx * one);

    for by in (range.y0..=range.y1).step_by(BLOCK as usize) {
        let by1 = (by + BLOCK - 1).min(range.y1);
        for bx in (range.x0..=range.x1).step_by(BLOCK as usize) {
            let bx1 = (bx + BLOCK - 1).min(range.x1);
            let origin = edges.map(|e: FixedEdge| e.biased_value(sample(bx, by)));
            let (w, h) = (i64::from(bx1 - bx), i64::from(by1 - by));
            let mut all_inside = true;
            let mut rejected = false;
            for k in 0..3 {
                let e00 = origin[k];
                let e10 = e00 + w * step_x[k];
                let e01 = e00 + h * step_y[k];
                let e11 = e10 + h * step_y[k];
                let corners = [e00, e10, e01, e11];
                // E is linear, so its extremes over the block's samples are at the corners.
                if corners.iter().all(|&e| e < 0) {
                    rejected = true;
                    break;
                }
                all_inside &= corners.iter().all(|&e| e >= 0);
            }
            if rejected {
                continue;
            }
            if all_inside {
                for y in by..=by1 {
                    sink.cover_span(y, bx, bx1, id);
                }
                continue;
            }
            let mut row = origin;
            for y in by..=by1 {
                let mut e = row;
                for x in bx..=bx1 {
                    if e[0] >= 0 && e[1] >= 0 && e[2] >= 0 {
                        sink.cover(x, y, id);
                    }
                    for k in 0..3 {
                        e[k] += step_x[k];
                    }
                }
                for k in 0..3 {
                    row[k] += step_y[k];
                }
            }
        }
    }
}

/// The per-triangle setup shared by the integer rasterizers.
pub(crate) struct Setup {
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
pub(crate) fn setup(tri: &FixedTriangle, target: &Target) -> Option<Setup> {
    let conv = &target.convention;
    assert_eq!(
        tri.bits, conv.subpixel_bits,
        "triangle snapped to another grid than the target's"
    );
    let edges = triangle_edges(tri, conv.tie_rule)?;
    let range = fixed_sample_range(tri.coords().into_iter(), target)?;
    Some(Setup {
        edges,
        grid: FixedGrid::of(conv),
        range,
    })
}
