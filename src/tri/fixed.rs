//! The incremental integer rasterizer on the snapped scene: one setup per triangle, then
//! `E(x+1, y) = E + dY`, `E(x, y+1) = E - dX` (Pineda 1988), traversed in [`BLOCK`] x
//! [`BLOCK`] blocks by the planned engine's traversal ([`crate::tri::planned`]) run in
//! i64: per edge, the block corner where E is largest rejects the block when negative and
//! the opposite corner accepts it when not (the block is filled as spans); only the rest
//! is tested per pixel, one span per row. Block origins are stepped by addition. i64
//! throughout; the envelope of [`crate::num::fixed`] guarantees no value can overflow
//! (see there for the bound).

use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::edge::fixed::{triangle_edges, FixedEdge};
use crate::geom::FixedTriangle;
use crate::raster::{fixed_sample_range, FixedGrid, PixelRange};
use crate::tri::planned::{traverse, Edges};

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
#[inline]
pub fn rasterize<S: CoverageSink + ?Sized>(tri: &FixedTriangle, id: u32, target: &Target, sink: &mut S) {
    let Some(Setup { edges, grid, range }) = setup(tri, target) else {
        return;
    };
    // One pixel right adds dY (in pixel units: dY * 2^S); one pixel down subtracts dX.
    let shift = grid.one.trailing_zeros();
    let first = grid.sample_point(range.x0, range.y0);
    let lanes = Edges {
        origin: edges.map(|e: FixedEdge| e.biased_value(first)),
        step_x: edges.map(|e| e.dy << shift),
        step_y: edges.map(|e| -(e.dx << shift)),
    };
    // The planned engine's block traversal, in i64: every value it reaches is an edge
    // value at a sample of the range or a multiple of a step by at most BLOCK, all far
    // below 2^62 inside the envelope.
    traverse(&lanes, &range, id, sink);
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
#[inline]
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
