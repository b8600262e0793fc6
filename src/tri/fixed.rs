//! The incremental integer rasterizer on the snapped scene: one setup per triangle, then
//! `E(x+1, y) = E + dY`, `E(x, y+1) = E - dX` (Pineda 1988), traversed in [`BLOCK`] x
//! [`BLOCK`] blocks by the block kernel it shares with the planned engine
//! ([`crate::tri::planned`]; `tri/blocks.rs`): per edge, the block corner where E is
//! largest rejects the block when negative and the opposite corner accepts it when not (a
//! run of accepted blocks along a block row is written as one span per row); only the rest
//! is tested, a row of up to eight pixels at a time as one SIMD bit mask, and a block's
//! masks written at once ([`CoverageSink::cover_block`]). Block origins are stepped by
//! addition.
//!
//! Traversal, per triangle and sink: blocks and their masks for a sink that
//! [prefers masks](CoverageSink::prefers_masks); for a sink of pixels and spans (the
//! default), a triangle within one block is written pixel by pixel from its masks, and a
//! larger one as one span per row by edge walking ([`crate::tri::scanline`], the same
//! pixels), which such a sink takes fastest.
//!
//! Width, per triangle: i32 when a bound computed from the setup shows every value of
//! the traversal fits (eight lanes per SIMD test; most triangles of a canvas-sized scene),
//! else i64, where the envelope of [`crate::num::fixed`] guarantees no value can overflow
//! (see there for the bound).

use crate::convention::{Target, TieRule};
use crate::coverage::CoverageSink;
use crate::geom::FixedTriangle;
use crate::num::lane::Lane;
use crate::raster::{FixedGrid, PixelRange};

pub use super::blocks::BLOCK;
use super::blocks::{traverse, Edges};
use super::scanline;

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
    if let Some((lanes, range, span)) = edges_at_first_sample(tri, target) {
        if !sink.prefers_masks() && (range.x1 - range.x0 >= BLOCK || range.y1 - range.y0 >= BLOCK) {
            // A sink of spans, a triangle larger than a block: one span per row, walked
            // along the edges (the peer bench through a span-only sink, one run: medium
            // triangles 3.73 ms against 6.28 ms by blocks, masks turned into spans).
            scanline::rasterize(tri, id, target, sink);
            return;
        }
        // The planned engine's block traversal: in i32 when this triangle's values fit
        // (eight pixels per SIMD row test instead of four), else in i64, where every value
        // it reaches is an edge value at a sample of the range or a multiple of a step by
        // at most BLOCK, all far below 2^62 inside the envelope.
        match narrowed(&lanes, span) {
            Some(narrow) => traverse(&narrow, &range, id, sink),
            None => traverse_large(&lanes, &range, id, sink),
        }
    }
}

/// The i64 traversal, for triangles too large for i32, kept out of line: inlined beside
/// the i32 one into the caller's loop it ran the peer bench's one large triangle (c)
/// about 30 % slower, and its call costs nothing next to the pixels of a large triangle.
#[inline(never)]
fn traverse_large<S: CoverageSink + ?Sized>(lanes: &Edges<i64>, range: &PixelRange, id: u32, sink: &mut S) {
    traverse(lanes, range, id, sink);
}

/// The largest side, in subpixels, of a triangle's bounding box that [`narrowed`] runs in
/// i32: `4 * 23170^2 + 2 <= i32::MAX < 4 * 23171^2` (about 90 pixels at 8 subpixel bits).
const I32_SPAN: i64 = 23_170;

/// The lanes in i32 when every value the traversal can reach fits i32, a plan made per
/// triangle like the planned engine's width (most triangles of a scene on a canvas-sized
/// grid are small enough: at 8 subpixel bits, up to about 90 px on a side).
///
/// The bound, from `span`, the larger side `B` of the triangle's bounding box in
/// subpixels: every value the traversal holds is `E - bias` at a sample of the pixel
/// range, or a difference of two of them (a multiple of a step by at most the range's
/// side, to the next block or a block's corner, or the row ramp's steps within the range),
/// or a step itself. A sample `p` of the range lies in the bounding box, as do the
/// vertices, so `|p - a| <= B` and `|dx|, |dy| <= B` give `|E| <= 2 B^2`, `|E - bias| <=
/// 2 B^2 + 1` and a difference at most `4 B^2`; a step is `|d| 2^S <= B 2^16 < 2^31`. So
/// `B <= I32_SPAN` keeps every value in i32 (the test below checks it against the exact
/// largest value of the traversal; an unused step, of a range one pixel wide or high, is
/// held but never added).
#[inline(always)]
fn narrowed(lanes: &Edges<i64>, span: i64) -> Option<Edges<i32>> {
    if span > I32_SPAN {
        return None;
    }
    // Each value is within the bound just proven, so each conversion is exact.
    #[allow(clippy::cast_possible_truncation)]
    let narrow = |v: &[i64; 3]| v.map(|v| v as i32);
    Some(Edges {
        origin: narrow(&lanes.origin),
        step_x: narrow(&lanes.step_x),
        step_y: narrow(&lanes.step_y),
    })
}

/// The setup of [`rasterize`], in one pass over the vertices and inlined into it: the
/// oriented edges' values `E - bias` at the first sample of the pixel range, their steps
/// one pixel right (`dY * 2^S`) and down (`-dX * 2^S`), the range, and the larger side
/// of the bounding box in subpixels; `None` when the triangle covers nothing (zero area,
/// or off the canvas). The same values as `triangle_edges` and `fixed_sample_range` give
/// (the setup [`crate::tri::scanline`] runs on), computed with shifts by `S` instead of
/// divisions (the grid's `first_at_or_after` and `last_at_or_before`). Written out rather than
/// built on `setup`: with `setup`'s helpers made `#[inline]` and this calling them, the
/// peer bench's workload (b) ran 15-20 % slower (3 runs each, back to back: 18.4-18.7 ms
/// against 15.1-16.2 ms); the property tests hold both routes equal to the oracle.
///
/// # Panics
/// When `tri` was snapped to another grid than `target`'s subpixel bits.
#[inline(always)]
fn edges_at_first_sample(tri: &FixedTriangle, target: &Target) -> Option<(Edges<i64>, PixelRange, i64)> {
    let conv = &target.convention;
    assert_eq!(
        tri.bits, conv.subpixel_bits,
        "triangle snapped to another grid than the target's"
    );
    // Lane arithmetic (checked under debug assertions, wrapping otherwise) for the edge
    // values: the envelope of `crate::num::fixed` is the proof that nothing here overflows
    // (coordinates within 2^29, samples below 2^30, so differences within 2^31 and every
    // product and edge value below 2^62); the test profile keeps the checks on. The
    // grid's own rounding stays checked (3 % of workload (b) with checks on, measured).
    let sub = |a: i64, b: i64| a.minus(&b);
    let mul = |a: i64, b: i64| a.times(&b);
    let [a, b, c] = tri.coords();
    // Oriented so that the interior is E > 0: twice the area is E_ab(c).
    let area2 = sub(
        mul(sub(c[0], a[0]), sub(b[1], a[1])),
        mul(sub(c[1], a[1]), sub(b[0], a[0])),
    );
    let (b, c) = match area2.cmp(&0) {
        std::cmp::Ordering::Equal => return None,
        std::cmp::Ordering::Greater => (b, c),
        std::cmp::Ordering::Less => (c, b),
    };
    let shift = conv.subpixel_bits;
    let grid = FixedGrid::of(conv);
    let min = |k: usize| a[k].min(b[k]).min(c[k]);
    let max = |k: usize| a[k].max(b[k]).max(c[k]);
    let (min, max) = ([min(0), min(1)], [max(0), max(1)]);
    let lo = |k: usize| grid.first_at_or_after(min[k]);
    let hi = |k: usize| grid.last_at_or_before(max[k]);
    let range = PixelRange::clamped([lo(0), lo(1)], [hi(0), hi(1)], target.width, target.height)?;
    let span = sub(max[0], min[0]).max(sub(max[1], min[1]));
    let first = grid.sample_point(range.x0, range.y0);
    // The tie rule's `is_inclusive` without a branch: an edge going down owns its
    // samples, and a horizontal one (dx != 0: no edge of a triangle with area has length
    // zero) when it runs left under top-left, right under bottom-left.
    let bottom_left = conv.tie_rule == TieRule::BottomLeft;
    let mut lanes = Edges {
        origin: [0; 3],
        step_x: [0; 3],
        step_y: [0; 3],
    };
    for (k, (from, to)) in [(a, b), (b, c), (c, a)].into_iter().enumerate() {
        let (dx, dy) = (sub(to[0], from[0]), sub(to[1], from[1]));
        let inclusive = (dy > 0) | ((dy == 0) & ((dx > 0) == bottom_left));
        debug_assert_eq!(inclusive, conv.tie_rule.is_inclusive(dx.cmp(&0), dy.cmp(&0)));
        let bias = i64::from(!inclusive);
        lanes.origin[k] = sub(
            sub(mul(sub(first[0], from[0]), dy), mul(sub(first[1], from[1]), dx)),
            bias,
        );
        // One pixel right adds dY (in pixel units: dY * 2^S); one pixel down subtracts dX.
        lanes.step_x[k] = dy << shift;
        lanes.step_y[k] = sub(0, dx << shift);
    }
    Some((lanes, range, span))
}

#[cfg(test)]
mod tests {
    use num_bigint::BigInt;

    use super::*;
    use crate::convention::{Convention, Preset};
    use crate::coverage::Coverage;
    use crate::geom::{Point, Triangle};
    use crate::tri::blocks::bound_of;

    /// The exact largest magnitude the traversal reaches from these lanes (the planned
    /// engine's bound, proven against a recording lane in `tri::planned`'s tests).
    fn exact_bound(lanes: &Edges<i64>, range: &PixelRange) -> BigInt {
        let big = |v: &[i64; 3]| v.map(BigInt::from);
        let e = Edges {
            origin: big(&lanes.origin),
            step_x: big(&lanes.step_x),
            step_y: big(&lanes.step_y),
        };
        bound_of(&e, range).expect("big integers do not overflow").value
    }

    fn fixed_of(t: &Triangle, target: &Target) -> FixedTriangle {
        t.snapped(&target.convention).to_fixed().expect("inside the envelope")
    }

    fn equal_to_oracle(t: &Triangle, target: &Target) {
        let (mut a, mut b) = (
            Coverage::new(target.width, target.height),
            Coverage::new(target.width, target.height),
        );
        rasterize(&fixed_of(t, target), 0, target, &mut a);
        crate::tri::exact::rasterize(&fixed_of(t, target).to_exact(), 0, target, &mut b);
        assert_eq!(a, b, "{t:?}");
    }

    /// Triangles from one pixel to a few hundred, at 8 and 16 subpixel bits: the bound
    /// that picks i32 is never below the exact largest value of the traversal, so a
    /// triangle traversed in i32 never holds a value i32 cannot.
    #[test]
    fn the_i32_plan_bounds_every_value_the_traversal_reaches() {
        // splitmix64, seeded: the coordinates only need to be spread
        let mut state = 7u64;
        let mut next = move || {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let z = (state ^ (state >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            let z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^ (z >> 31)
        };
        let (mut narrow, mut wide) = (0, 0);
        for bits in [8, 16] {
            let conv = Convention {
                subpixel_bits: bits,
                ..Preset::Cts.convention()
            };
            let target = Target::new(512, 512, conv).unwrap();
            for k in 0..600u64 {
                let side = 1 + (k % 60) * (k % 7 + 1);
                let mut p = || {
                    let c = |r: u64| i64::try_from(r % (side * 97)).unwrap() - 20;
                    Point::from_fractions(c(next()) + 100 * 97, 97, c(next()) + 100 * 97, 97)
                };
                let t = Triangle::new(p(), p(), p());
                let Some((lanes, range, span)) = edges_at_first_sample(&fixed_of(&t, &target), &target) else {
                    continue;
                };
                if narrowed(&lanes, span).is_some() {
                    let exact = exact_bound(&lanes, &range);
                    // the proof's bound, and under it the largest value the traversal holds
                    assert!(exact <= BigInt::from(4 * span * span + 2), "{t:?}");
                    assert!(exact <= BigInt::from(i32::MAX), "{t:?}");
                    let steps = [lanes.step_x, lanes.step_y].concat();
                    assert!(steps.iter().all(|s| i32::try_from(*s).is_ok()), "{t:?}");
                    narrow += 1;
                } else {
                    wide += 1;
                }
            }
        }
        // both plans were exercised
        assert!(narrow > 100 && wide > 100, "{narrow} in i32, {wide} in i64");
    }

    /// At the i32 plan's edge: the right triangle (0,0) (n,0) (0,n) subpixels, grown one
    /// subpixel at a time; the last n traversed in i32 is the proof's 23170 subpixels
    /// (`4 n^2 + 2 <= i32::MAX` for it, not for the next), the next runs in i64, and both
    /// equal the oracle.
    #[test]
    fn both_sides_of_the_i32_plan_equal_the_oracle() {
        let target = Target::new(160, 160, Preset::Cts.convention()).unwrap();
        let tri = |n: i64| {
            Triangle::new(
                Point::from_ints(0, 0),
                Point::from_fractions(n, 256, 0, 1),
                Point::from_fractions(0, 1, n, 256),
            )
        };
        let fits = |n: i64| {
            let (lanes, _, span) = edges_at_first_sample(&fixed_of(&tri(n), &target), &target).unwrap();
            narrowed(&lanes, span).is_some()
        };
        let lo = crate::num::last_where(256, 160 * 256, fits);
        let hi = lo + 1;
        assert_eq!(lo, 23_170, "the edge");
        assert!(4 * lo * lo + 2 <= i64::from(i32::MAX) && 4 * hi * hi + 2 > i64::from(i32::MAX));
        equal_to_oracle(&tri(lo), &target);
        equal_to_oracle(&tri(hi), &target);
    }
}
