//! The block kernel the two block engines share, [`crate::tri::planned`] (exact, in the
//! planned width) and [`crate::tri::fixed`] (snapped, in i32 or i64): per edge `E - bias`
//! at the range's first sample and its steps one pixel right and down ([`Edges`]), the
//! traversal over them (Pineda 1988, `E(x+L, y) = E + L dY`), and the exact bound of
//! every value it holds ([`bound_of`]), on which the planned engine plans its width.
//!
//! **Traversal.** The pixel range in [`BLOCK`] x [`BLOCK`] blocks: a block with all four
//! corners outside one edge is skipped, one with all corners inside all three is filled
//! as spans, a run of them along a block row as one span per row, and the rest is tested
//! a row at a time ([`Lane::row_masks`]), the block's masks written at once
//! ([`CoverageSink::cover_block`]) to a sink that
//! [prefers masks](CoverageSink::prefers_masks), pixel by pixel to any other. Every
//! value is reached by addition only, and never beyond the range: block origins are
//! stepped by `BLOCK` steps, corners by `w` and `h` steps, pixels by single steps, each
//! added only when the next point exists. Per block and edge only two corners are evaluated: the one where `E` is largest (the block is
//! outside when it is negative) and the opposite one (inside when it is not).
//!
//! **The bound.** Every value the traversal holds is either `E - bias` at a sample of the
//! pixel range, whose magnitude is at most its largest at the range's four corners (`E`
//! is linear), or a multiple `k L dY` / `k L dX` with `k <= min(BLOCK, range side)`, or
//! the step from a block's first sample to its largest or smallest corner (each a
//! difference of two samples' values). [`bound_of`] computes the largest of all of them
//! exactly.

use crate::coverage::CoverageSink;
use crate::num::lane::{Lane, SetupInt, HALF_ROW, ROW};
use crate::num::plan::Bound;
use crate::raster::PixelRange;

/// Block side, in pixels (the L of Pineda's `E(x+L, y) = E + L dY`).
pub const BLOCK: u32 = 8;

// A block's row is one row mask.
const _: () = assert!(BLOCK as usize == ROW);

/// Per edge: `E - bias` at the range's first sample and the two steps (the planned engine
/// holds them in its planned width, [`crate::tri::fixed`] in i32 or i64).
#[derive(Debug, Clone)]
pub(crate) struct Edges<T> {
    /// `E - bias` at the first sample of the range.
    pub(crate) origin: [T; 3],
    /// One pixel right.
    pub(crate) step_x: [T; 3],
    /// One pixel down.
    pub(crate) step_y: [T; 3],
}

impl<T: Lane> Edges<T> {
    /// The exact edges (set up in `N`) in lane type `T`: every value is within the plan's
    /// bound, so exact.
    pub(crate) fn from_exact<N: SetupInt>(e: &Edges<N>) -> Edges<T> {
        let lane = |v: &[N; 3]| v.each_ref().map(N::to_lane);
        Edges {
            origin: lane(&e.origin),
            step_x: lane(&e.step_x),
            step_y: lane(&e.step_y),
        }
    }
}

/// Which value a bound is, put in words once ([`Bound::what`]).
#[derive(Debug, Clone, Copy)]
enum What {
    /// Edge `k`'s value at pixel `(x, y)`.
    Corner(usize, u32, u32),
    /// Edge `k`'s step over `n` columns.
    Columns(usize, u32),
    /// Edge `k`'s step over `n` rows.
    Rows(usize, u32),
    /// Edge `k`'s step to the corner of a `w` x `h` block.
    BlockCorner(usize, u32, u32),
}

impl std::fmt::Display for What {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            What::Corner(k, x, y) => write!(f, "edge {k} at pixel ({x}, {y})"),
            What::Columns(k, n) => write!(f, "edge {k}'s step over {n} columns"),
            What::Rows(k, n) => write!(f, "edge {k}'s step over {n} rows"),
            What::BlockCorner(k, w, h) => write!(f, "edge {k}'s step to a {w}x{h} block's corner"),
        }
    }
}

/// The largest magnitude the traversal reaches (see the module docs): `E - bias` at the
/// range's corners, and the step multiples it adds. `None` when a value overflows `N`
/// (`i128`; never in [`BigInt`]).
pub(crate) fn bound_of<N: SetupInt>(edges: &Edges<N>, range: &PixelRange) -> Option<Bound> {
    let (w, h) = (range.x1 - range.x0, range.y1 - range.y0);
    let mut best: Option<(N, What)> = None;
    let mut consider = |v: N, what: What| -> Option<()> {
        let v = v.abs_exact()?;
        if best.as_ref().is_none_or(|(b, _)| v > *b) {
            best = Some((v, what));
        }
        Some(())
    };
    for k in 0..3 {
        let (sx, sy) = (&edges.step_x[k], &edges.step_y[k]);
        for (u, v) in [(0, 0), (w, 0), (0, h), (w, h)] {
            let e = edges.origin[k]
                .add_exact(&sx.mul_count(u)?)?
                .add_exact(&sy.mul_count(v)?)?;
            consider(e, What::Corner(k, range.x0 + u, range.y0 + v))?;
        }
        // A range within one block is filled row by row: one step down per row, the row
        // ramp's up to BLOCK - 1 steps across (`Lane::ramp`); a larger one also steps by
        // up to BLOCK columns or rows and to each block's extreme corners (see `traverse`).
        let one_block = w < BLOCK && h < BLOCK;
        let ramp = w.min(BLOCK - 1);
        let (kx, ky) = if one_block {
            (ramp, h.min(1))
        } else {
            (w.min(BLOCK), h.min(BLOCK))
        };
        consider(sx.mul_count(kx)?, What::Columns(k, kx))?;
        consider(sy.mul_count(ky)?, What::Rows(k, ky))?;
        if one_block {
            continue;
        }
        for cx in [(BLOCK - 1).min(w), w % BLOCK] {
            for cy in [(BLOCK - 1).min(h), h % BLOCK] {
                for high in [true, false] {
                    let mut v = N::from_i64(0);
                    if sx.below_zero() != high {
                        v = v.add_exact(&sx.mul_count(cx)?)?;
                    }
                    if sy.below_zero() != high {
                        v = v.add_exact(&sy.mul_count(cy)?)?;
                    }
                    consider(v, What::BlockCorner(k, cx + 1, cy + 1))?;
                }
            }
        }
    }
    let (value, what) = best?;
    Some(Bound {
        value: value.to_big(),
        what: what.to_string(),
    })
}

/// `n` times `step` (every multiple used is a difference of two samples' values in the
/// range, so within the bound, when `n` is at most the range's side).
#[inline(always)]
fn times<T: Lane>(step: &[T; 3], n: u32) -> [T; 3] {
    step.each_ref().map(|s| s.scaled_by(n))
}

/// Per edge, the step to the block corner where `E` is largest (`high`) and smallest
/// (`low`): `E` is linear, so that is the far column when it grows along x, the far row
/// when it grows along y.
#[derive(Debug, Clone)]
struct CornerSteps<T> {
    high: [T; 3],
    low: [T; 3],
}

impl<T: Lane> CornerSteps<T> {
    fn of(step_x: &[T; 3], step_y: &[T; 3], along_x: &[T; 3], along_y: &[T; 3]) -> CornerSteps<T> {
        let pick = |k: usize, high: bool| {
            let mut v = T::zero_value();
            for (step, along) in [(step_x, along_x), (step_y, along_y)] {
                if step[k].non_negative() == high {
                    v.add_to(&along[k]);
                }
            }
            v
        };
        CornerSteps {
            high: std::array::from_fn(|k| pick(k, true)),
            low: std::array::from_fn(|k| pick(k, false)),
        }
    }
}

#[inline(always)]
fn add3<T: Lane>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
    [a[0].plus(&b[0]), a[1].plus(&b[1]), a[2].plus(&b[2])]
}

#[inline(always)]
fn add3_to<T: Lane>(a: &mut [T; 3], b: &[T; 3]) {
    for (a, b) in a.iter_mut().zip(b) {
        a.add_to(b);
    }
}

/// The block traversal, generic over the lane type (see the module docs).
#[inline]
pub(crate) fn traverse<T: Lane, S: CoverageSink + ?Sized>(e: &Edges<T>, range: &PixelRange, id: u32, sink: &mut S) {
    let (width, height) = (range.x1 - range.x0, range.y1 - range.y0);
    let last = BLOCK - 1;
    // `i * step_x` for the columns of a block's row (or of the range, when narrower).
    let ramp = T::ramp(&e.step_x, last.min(width));
    if width < BLOCK && height < BLOCK {
        // One block: its corners are the range's, where the triangle's bounding box
        // leaves rarely anything to reject; go straight to the rows.
        let at = [range.x0, range.y0];
        if (width as usize) < HALF_ROW {
            fill_rows::<T, S, true>(e, &ramp, &e.origin, at, [width, height], id, sink);
        } else {
            fill_rows::<T, S, false>(e, &ramp, &e.origin, at, [width, height], id, sink);
        }
        return;
    }
    blocks(e, &ramp, range, id, sink);
}

/// [`traverse`] over more than one block, kept out of line: inlined, its state crowded
/// the one-block path's registers (`fixed` on the peer bench, two runs each: 100k small
/// triangles 5.06-5.11 ms inlined against 4.59-4.63 ms out of line, 10k medium ones
/// 3.78-3.91 against 3.45-3.49 ms), and its call costs nothing next to several blocks.
#[inline(never)]
fn blocks<T: Lane, S: CoverageSink + ?Sized>(
    e: &Edges<T>,
    ramp: &[[T; ROW]; 3],
    range: &PixelRange,
    id: u32,
    sink: &mut S,
) {
    let (width, height) = (range.x1 - range.x0, range.y1 - range.y0);
    let last = BLOCK - 1;
    // Steps to the next block (used only when there is one) and to a block's far corners,
    // for full blocks and for the last, partial one on each axis.
    let block_x = times(&e.step_x, if width >= BLOCK { BLOCK } else { 0 });
    let block_y = times(&e.step_y, if height >= BLOCK { BLOCK } else { 0 });
    let (full_x, part_x) = (times(&e.step_x, last.min(width)), times(&e.step_x, width % BLOCK));
    let (full_y, part_y) = (times(&e.step_y, last.min(height)), times(&e.step_y, height % BLOCK));
    let corners = |x: &[T; 3], y: &[T; 3]| CornerSteps::of(&e.step_x, &e.step_y, x, y);
    // [full or partial row of blocks][full or partial column]
    let steps = [
        [corners(&full_x, &full_y), corners(&part_x, &full_y)],
        [corners(&full_x, &part_y), corners(&part_x, &part_y)],
    ];

    // Runs of inside blocks pay off from a few blocks across; narrower ranges write each
    // inside block at once (measured on the peer bench: merging cost 4 % on its 24 px
    // triangles and gained 60 % on its half-canvas one).
    let merge = width >= 4 * BLOCK;
    let mut row_origin = e.origin.clone();
    let mut by = 0;
    loop {
        let h = last.min(height - by);
        let rows = &steps[usize::from(h != last)];
        let mut block = row_origin.clone();
        let mut bx = 0;
        // The run of whole blocks inside the triangle that ends at the current block:
        // written as one span per row when it ends (for a large triangle, a row of the
        // interior is one span however many blocks it crosses).
        let mut run: Option<[u32; 2]> = None;
        let y0 = range.y0 + by;
        let flush = |run: &mut Option<[u32; 2]>, sink: &mut S| {
            if let Some([x0, x1]) = run.take() {
                for y in y0..=y0 + h {
                    sink.cover_span(y, x0, x1, id);
                }
            }
        };
        loop {
            let w = last.min(width - bx);
            let c = &rows[usize::from(w != last)];
            let x0 = range.x0 + bx;
            if visit_block(e, ramp, &block, c, [x0, y0], [w, h], id, sink) {
                run = Some([run.map_or(x0, |[start, _]| start), x0 + w]);
                if !merge {
                    flush(&mut run, sink);
                }
            } else {
                flush(&mut run, sink);
            }
            if width - bx < BLOCK {
                break;
            }
            bx += BLOCK;
            add3_to(&mut block, &block_x);
        }
        flush(&mut run, sink);
        if height - by < BLOCK {
            break;
        }
        by += BLOCK;
        add3_to(&mut row_origin, &block_y);
    }
}

/// One block: `origin` holds `E - bias` at its first sample `at`; `size` is `[w, h]` (the
/// last column and row, relative). Per edge, only two corners are evaluated: the largest
/// (all outside when it is negative) and the smallest (all inside when it is not). A
/// block all inside is left to the caller, which writes runs of them as spans: `true`.
#[inline(always)]
#[allow(clippy::too_many_arguments)] // the block's state, passed by reference to an inlined body
fn visit_block<T: Lane, S: CoverageSink + ?Sized>(
    e: &Edges<T>,
    ramp: &[[T; ROW]; 3],
    origin: &[T; 3],
    c: &CornerSteps<T>,
    at: [u32; 2],
    size: [u32; 2],
    id: u32,
    sink: &mut S,
) -> bool {
    let high = add3(origin, &c.high);
    if !T::all_non_negative(&high) {
        return false; // outside one edge at its largest
    }
    if T::all_non_negative(&add3(origin, &c.low)) {
        return true;
    }
    fill_rows::<T, S, false>(e, ramp, origin, at, size, id, sink);
    false
}

/// The samples of a `[w, h]` rectangle of pixels from `at`, `origin` holding `E - bias` at
/// its first, `ramp` the steps across a row: each row's inside samples are one mask
/// ([`Lane::row_masks`], half rows when `HALF` says `w < HALF_ROW`), and the rectangle's
/// masks one write ([`CoverageSink::cover_block`]: with the rows' writes between them,
/// `fixed` on the peer bench's 10k medium triangles took 3.05-3.13 ms against 2.73-2.86,
/// its 100k small ones 4.53-4.73 against 4.35-4.46; two alternating runs of each build,
/// overflow checks off).
#[inline(always)]
fn fill_rows<T: Lane, S: CoverageSink + ?Sized, const HALF: bool>(
    e: &Edges<T>,
    ramp: &[[T; ROW]; 3],
    origin: &[T; 3],
    at: [u32; 2],
    size: [u32; 2],
    id: u32,
    sink: &mut S,
) {
    let [x0, y0] = at;
    let [w, h] = size;
    debug_assert!(w < BLOCK, "rows are at most a block wide");
    // every row's mask first, then one write: byte `i` row `i`, `cover_block`'s layout
    // (a row's mask fits its byte and the rows the block's eight bytes)
    const { assert!(ROW <= 8 && BLOCK <= 8, "a block's masks fill one u64") };
    let mut block = 0u64;
    T::row_masks::<HALF>(origin, &e.step_y, ramp, w, h, |i, mask| {
        block |= u64::from(mask) << (i * 8);
    });
    if block == 0 {
        return;
    }
    if sink.prefers_masks() {
        sink.cover_block(y0, x0, block, id);
    } else {
        // pixel by pixel: a small triangle's rows are a few pixels each, and one loop over
        // the block's bits costs a sink of spans less than a span per row (the peer bench's
        // 100k small triangles through a span-only sink, `fixed`, two runs: 4.94 ms pixel
        // by pixel against 6.24 ms as spans, the best baseline 5.97 and 5.88 ms)
        let mut rest = block;
        while rest != 0 {
            let i = rest.trailing_zeros();
            sink.cover(x0 + i % 8, y0 + i / 8, id);
            rest &= rest - 1;
        }
    }
}
