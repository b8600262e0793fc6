//! The planned exact engine for triangles: the oracle's decisions, computed incrementally
//! in the narrowest arithmetic that provably holds them ([`crate::num::plan`]).
//!
//! Setup, once per triangle, in exact integers: the scale `L` that makes every vertex
//! coordinate and the pixel centre integers, the vertices taken relative to the first
//! sample of the triangle's pixel range, and per edge (oriented so the interior is
//! `E > 0`) the value `E - bias` at that sample and its steps, `L dY` one pixel right and
//! `-L dX` one pixel down (Pineda 1988; `bias` is 1 on an edge the tie rule leaves out,
//! 0 on an inclusive one, so that `E - bias >= 0` is the oracle's test on integers).
//! `E` scaled by `L^2 > 0` keeps its sign, so every decision is the oracle's.
//!
//! Traversal: the pixel range in [`BLOCK`] x [`BLOCK`] blocks as in [`crate::tri::fixed`]
//! (a block with all four corners outside one edge is skipped, one with all corners inside
//! all three is filled as spans, a run of them along a block row as one span per row, the
//! rest is tested pixel by pixel), but every value is
//! reached by addition only, and never beyond the range: block origins are stepped by
//! `BLOCK` steps, corners by `w` and `h` steps, pixels by single steps, each added only
//! when the next point exists.
//!
//! Per block and edge only two corners are evaluated: the one where `E` is largest (the
//! block is outside when it is negative) and the opposite one (inside when it is not);
//! a partial block is filled one span per row (a triangle meets a row in one interval).
//!
//! **The bound.** Every value the traversal holds is either `E - bias` at a sample of the
//! pixel range, whose magnitude is at most its largest at the range's four corners (`E`
//! is linear), or a multiple `k L dY` / `k L dX` with `k <= min(BLOCK, range side)`, or
//! the step from a block's first sample to its largest or smallest corner (each a
//! difference of two samples' values). [`PlannedTriangle::new`] computes the largest of
//! all of them exactly and plans the width on it.

use num_bigint::BigInt;
use num_traits::{Signed, Zero};

use crate::convention::{AnyTieRule, Target};
use crate::coverage::CoverageSink;
use crate::geom::Triangle;
use crate::num::lane::{Lane, HALF_ROW, ROW};
use crate::num::plan::{scale_of, scaled, Bound, Plan, Width};
use crate::raster::{exact_sample_range, PixelRange};

use super::fixed::BLOCK;

// A block's row is one row mask.
const _: () = assert!(BLOCK as usize == ROW);

/// Per edge: `E - bias` at the range's first sample and the two steps (shared with
/// [`crate::tri::fixed`], which runs the same traversal in i64).
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
    fn from_big(e: &Edges<BigInt>) -> Edges<T> {
        let lane = |v: &[BigInt; 3]| v.each_ref().map(T::from_big);
        Edges {
            origin: lane(&e.origin),
            step_x: lane(&e.step_x),
            step_y: lane(&e.step_y),
        }
    }
}

/// The edges in the planned width.
#[derive(Debug, Clone)]
enum Lanes {
    F32(Edges<f32>),
    I32(Edges<i32>),
    F64(Edges<f64>),
    I64(Edges<i64>),
    I128(Edges<i128>),
    Big(Box<Edges<BigInt>>),
}

/// A triangle set up for the planned engine: its pixel range, its plan and its edges in
/// the planned width.
#[derive(Debug, Clone)]
pub struct PlannedTriangle {
    range: PixelRange,
    plan: Plan,
    lanes: Lanes,
}

/// The exact setup: range, scale, edges and the bound.
struct Setup {
    range: PixelRange,
    scale: BigInt,
    edges: Edges<BigInt>,
    bound: Bound,
}

fn setup(tri: &Triangle, target: &Target, rule: AnyTieRule) -> Option<Setup> {
    let range = exact_sample_range(tri.v.iter(), target)?;
    let centre = target.convention.pixel_centre.offset();
    let scale = scale_of(tri.v.iter().flat_map(|p| [&p.x, &p.y]).chain([&centre]));
    let c = scaled(&centre, &scale);
    let origin = [
        BigInt::from(range.x0) * &scale + &c,
        BigInt::from(range.y0) * &scale + &c,
    ];
    let local = |i: usize| {
        let p = &tri.v[i];
        [scaled(&p.x, &scale) - &origin[0], scaled(&p.y, &scale) - &origin[1]]
    };
    let [a, mut b, mut c3] = [local(0), local(1), local(2)];
    let edge = |a: &[BigInt; 2], b: &[BigInt; 2]| [&b[0] - &a[0], &b[1] - &a[1]];
    // E_{ab}(p) = (p.x - a.x) dy - (p.y - a.y) dx; at p = 0: a.y dx - a.x dy.
    let area2 = {
        let [dx, dy] = edge(&a, &b);
        (&c3[0] - &a[0]) * &dy - (&c3[1] - &a[1]) * &dx
    };
    if area2.is_zero() {
        return None;
    }
    if area2.is_negative() {
        std::mem::swap(&mut b, &mut c3);
    }
    let mut edges = Edges {
        origin: std::array::from_fn(|_| BigInt::zero()),
        step_x: std::array::from_fn(|_| BigInt::zero()),
        step_y: std::array::from_fn(|_| BigInt::zero()),
    };
    for (k, (from, to)) in [(&a, &b), (&b, &c3), (&c3, &a)].into_iter().enumerate() {
        let [dx, dy] = edge(from, to);
        let zero = BigInt::zero();
        let bias = i32::from(!rule.is_inclusive(dx.cmp(&zero), dy.cmp(&zero)));
        edges.origin[k] = &from[1] * &dx - &from[0] * &dy - bias;
        // A step the traversal never takes (a range one pixel wide or high) is left at
        // zero, so that it need not fit the width.
        if range.x1 > range.x0 {
            edges.step_x[k] = &dy * &scale;
        }
        if range.y1 > range.y0 {
            edges.step_y[k] = -(&dx * &scale);
        }
    }
    let bound = bound_of(&edges, &range);
    Some(Setup {
        range,
        scale,
        edges,
        bound,
    })
}

/// The largest magnitude the traversal reaches (see the module docs): `E - bias` at the
/// range's corners, and the step multiples it adds.
pub(crate) fn bound_of(edges: &Edges<BigInt>, range: &PixelRange) -> Bound {
    let (w, h) = (range.x1 - range.x0, range.y1 - range.y0);
    let mut best = Bound {
        value: BigInt::zero(),
        what: "nothing".into(),
    };
    let mut consider = |v: BigInt, what: &dyn Fn() -> String| {
        if v.abs() > best.value.abs() || best.what == "nothing" {
            best = Bound {
                value: v.abs(),
                what: what(),
            };
        }
    };
    for k in 0..3 {
        for (u, v) in [(0, 0), (w, 0), (0, h), (w, h)] {
            let e = &edges.origin[k] + &edges.step_x[k] * u + &edges.step_y[k] * v;
            consider(e, &|| format!("edge {k} at pixel ({}, {})", range.x0 + u, range.y0 + v));
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
        consider(&edges.step_x[k] * kx, &|| format!("edge {k}'s step over {kx} columns"));
        consider(&edges.step_y[k] * ky, &|| format!("edge {k}'s step over {ky} rows"));
        if one_block {
            continue;
        }
        let (sx, sy) = (&edges.step_x[k], &edges.step_y[k]);
        for cx in [(BLOCK - 1).min(w), w % BLOCK] {
            for cy in [(BLOCK - 1).min(h), h % BLOCK] {
                for high in [true, false] {
                    let mut v = BigInt::zero();
                    if sx.is_negative() != high {
                        v += sx * cx;
                    }
                    if sy.is_negative() != high {
                        v += sy * cy;
                    }
                    consider(v, &|| {
                        format!("edge {k}'s step to a {}x{} block's corner", cx + 1, cy + 1)
                    });
                }
            }
        }
    }
    best
}

impl PlannedTriangle {
    /// Sets up `tri` (exact vertices: as written, or snapped and converted back) for
    /// `target`, in the cheapest width its bound allows; `None` when it covers nothing
    /// (zero area, or no sample of the canvas in its bounding box).
    pub fn new(tri: &Triangle, target: &Target) -> Option<PlannedTriangle> {
        Self::with_rule(tri, target, target.convention.tie_rule.into())
    }

    /// As [`PlannedTriangle::new`] with the edges' inclusive flags from `rule` instead of
    /// the target's tie rule: any of the six rules a renderer may follow (what
    /// `compare --fit` searches).
    pub fn with_rule(tri: &Triangle, target: &Target, rule: AnyTieRule) -> Option<PlannedTriangle> {
        let s = setup(tri, target, rule)?;
        let plan = Plan::new(s.scale, s.bound);
        Some(Self::in_width(s.range, plan, &s.edges))
    }

    /// As [`PlannedTriangle::new`] but in `width`: `Ok(None)` when it covers nothing,
    /// `Err(plan)` (the plan it would have) when `width` cannot hold its bound. For tests
    /// and benches that run every width.
    pub fn forced(tri: &Triangle, target: &Target, width: Width) -> Result<Option<PlannedTriangle>, Plan> {
        let Some(s) = setup(tri, target, target.convention.tie_rule.into()) else {
            return Ok(None);
        };
        match Plan::forced(s.scale.clone(), s.bound.clone(), width) {
            Some(plan) => Ok(Some(Self::in_width(s.range, plan, &s.edges))),
            None => Err(Plan::new(s.scale, s.bound)),
        }
    }

    fn in_width(range: PixelRange, plan: Plan, edges: &Edges<BigInt>) -> PlannedTriangle {
        let lanes = match plan.width {
            Width::F32 => Lanes::F32(Edges::from_big(edges)),
            Width::I32 => Lanes::I32(Edges::from_big(edges)),
            Width::F64 => Lanes::F64(Edges::from_big(edges)),
            Width::I64 => Lanes::I64(Edges::from_big(edges)),
            Width::I128 => Lanes::I128(Edges::from_big(edges)),
            Width::Big => Lanes::Big(Box::new(edges.clone())),
        };
        PlannedTriangle { range, plan, lanes }
    }

    /// The plan: scale, bound and width.
    pub fn plan(&self) -> &Plan {
        &self.plan
    }

    /// Covers every pixel whose sample is inside the triangle: equal, pixel for pixel, to
    /// [`crate::tri::exact::rasterize`] on the same triangle and target (the property
    /// tests of `tests/planned.rs` are the proof).
    ///
    /// ```
    /// use rasterproof::convention::{Convention, Target};
    /// use rasterproof::coverage::Coverage;
    /// use rasterproof::geom::{Point, Triangle};
    /// use rasterproof::num::plan::Width;
    /// use rasterproof::tri::planned::PlannedTriangle;
    /// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
    /// let target = Target::new(4, 4, Convention::default()).unwrap();
    /// let planned = PlannedTriangle::new(&t, &target).unwrap();
    /// // Integer vertices, samples at half pixels: scale 2, every value tiny.
    /// assert_eq!(planned.plan().width, Width::I32);
    /// let (mut a, mut b) = (Coverage::new(4, 4), Coverage::new(4, 4));
    /// planned.rasterize(0, &mut a);
    /// rasterproof::tri::exact::rasterize(&t, 0, &target, &mut b);
    /// assert_eq!(a, b);
    /// assert_eq!(a.covered_pixels(), 6);
    /// ```
    pub fn rasterize<S: CoverageSink + ?Sized>(&self, id: u32, sink: &mut S) {
        match &self.lanes {
            Lanes::F32(e) => traverse(e, &self.range, id, sink),
            Lanes::I32(e) => traverse(e, &self.range, id, sink),
            Lanes::F64(e) => traverse(e, &self.range, id, sink),
            Lanes::I64(e) => traverse(e, &self.range, id, sink),
            Lanes::I128(e) => traverse(e, &self.range, id, sink),
            Lanes::Big(e) => traverse(e, &self.range, id, sink),
        }
    }
}

/// Plans and rasterizes `tri` in one call (see [`PlannedTriangle`]).
pub fn rasterize<S: CoverageSink + ?Sized>(tri: &Triangle, id: u32, target: &Target, sink: &mut S) {
    if let Some(p) = PlannedTriangle::new(tri, target) {
        p.rasterize(id, sink);
    }
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

/// The block traversal, generic over the planned width (see the module docs).
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
    if block != 0 {
        sink.cover_block(y0, x0, block, id);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::Convention;
    use crate::coverage::Coverage;
    use crate::geom::Point;

    /// A hand-derived plan: (0,0) (4,0) (0,4) on a 4x4 canvas, centres at 1/2, so L = 2,
    /// the range is pixels 0..=3 on both axes and the first sample is (1, 1) in L units.
    /// Relative to it the vertices are a = (-1,-1), b = (7,-1), c = (-1,7); E_ab(c) =
    /// 0 * 0 - 8 * 8 = -64 < 0, so b and c swap: a -> (-1,7) -> (7,-1) -> a.
    /// - edge 0, (-1,-1) -> (-1,7): dx = 0, dy = 8, inclusive (dy > 0), bias 0;
    ///   E = 8 (p.x + 1): 8 at pixel column 0 (p.x = 0), 56 at column 3 (p.x = 6).
    /// - edge 1, (-1,7) -> (7,-1): dx = 8, dy = -8, not inclusive, bias 1;
    ///   E - 1 = 47 - 8 (p.x + p.y): 47 at pixel (0,0), -49 at pixel (3,3).
    /// - edge 2, (7,-1) -> (-1,-1): horizontal running left, a top edge, bias 0;
    ///   E = 8 (p.y + 1): at most 56.
    /// - steps: the range fits one block, so it is filled row by row with single steps:
    ///   L dy = 16 (edge 0), edge 1 16 both ways, edge 2 16 down.
    ///
    /// So the bound is 56, first reached by edge 0 at pixel (3, 0).
    #[test]
    fn bound_by_hand() {
        let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
        let target = Target::new(4, 4, Convention::default()).unwrap();
        let p = PlannedTriangle::new(&t, &target).unwrap();
        assert_eq!(p.plan().scale, BigInt::from(2));
        assert_eq!(p.plan().bound.value, BigInt::from(56));
        assert_eq!(p.plan().bound.what, "edge 0 at pixel (3, 0)");
        assert_eq!(p.plan().width, Width::I32);
    }

    #[test]
    fn forced_refuses_a_width_that_cannot_hold_the_bound() {
        // A triangle 2^13 px wide at L = 2: values about 2 * (2^14)^2 = 2^29... fits i32
        // but not f32 (2^24).
        let s: u32 = 1 << 13;
        let v = i64::from(s);
        let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(v, 0), Point::from_ints(0, v));
        let target = Target::new(s, s, Convention::default()).unwrap();
        assert!(PlannedTriangle::forced(&t, &target, Width::F32).is_err());
        let p = PlannedTriangle::forced(&t, &target, Width::I64).unwrap().unwrap();
        assert_eq!(p.plan().width, Width::I64);
        let mut c = Coverage::new(s, s);
        p.rasterize(0, &mut c);
        // x + y < s for samples (i + 1/2, j + 1/2): i + j <= s - 2, plus the hypotenuse's
        // samples i + j = s - 1 (x + y = s exactly: a right edge, out): s (s - 1) / 2.
        assert_eq!(c.covered_pixels(), (s * (s - 1) / 2) as usize);
    }

    /// A lane that records the largest magnitude of every value the traversal computes.
    #[derive(Debug, Clone)]
    struct Track(BigInt);

    thread_local! {
        static LARGEST: std::cell::RefCell<BigInt> = std::cell::RefCell::new(BigInt::zero());
    }

    fn seen(v: BigInt) -> Track {
        LARGEST.with(|m| {
            if v.abs() > *m.borrow() {
                *m.borrow_mut() = v.abs();
            }
        });
        Track(v)
    }

    impl Lane for Track {
        const WIDTH: Width = Width::Big;
        fn from_big(v: &BigInt) -> Self {
            seen(v.clone())
        }
        fn zero_value() -> Self {
            Track(BigInt::zero())
        }
        fn plus(&self, other: &Self) -> Self {
            seen(&self.0 + &other.0)
        }
        fn add_to(&mut self, other: &Self) {
            *self = self.plus(other);
        }
        fn minus(&self, other: &Self) -> Self {
            seen(&self.0 - &other.0)
        }
        fn times(&self, other: &Self) -> Self {
            seen(&self.0 * &other.0)
        }
        fn scaled_by(&self, k: u32) -> Self {
            seen(&self.0 * k)
        }
        fn less(&self, other: &Self) -> bool {
            self.0 < other.0
        }
        fn non_negative(&self) -> bool {
            !self.0.is_negative()
        }
    }

    /// Every value the traversal computes, recorded through [`Track`], is within the
    /// plan's bound, and the bound is reached: on triangles whose ranges are one block,
    /// a few blocks, and partial blocks on either axis (where the steps to a block's
    /// corners can exceed every edge value at the range's corners).
    #[test]
    fn the_bound_holds_every_value_the_traversal_computes() {
        let target = Target::new(40, 40, Convention::default()).unwrap();
        let q = |n: i64, d: i64| Point::from_fractions(n, d, 0, 1);
        let mut checked = 0;
        for (k, (a, b, c)) in [
            ((0, 0), (4, 0), (0, 4)),
            ((-3, 5), (13, 0), (5, 12)),
            ((1, 1), (39, 2), (20, 38)),
            ((-50, 4), (90, 5), (4, 60)),
            ((0, 9), (9, 0), (100, 100)),
            ((7, -30), (8, 70), (-60, 20)),
            // 9 and 12 px ranges: a partial block on each axis, where the hypotenuse's
            // step to a block's far corner (7 of the 8 or 11 columns and rows) exceeds
            // its value at any corner of the range
            ((0, 0), (9, 0), (0, 9)),
            ((2, 3), (14, 3), (2, 15)),
        ]
        .into_iter()
        .enumerate()
        {
            for d in [1, 3, 7] {
                let p = |(x, y): (i64, i64)| Point::new(q(x * d + 1, d).x, Point::from_fractions(y * d + 2, d, 0, 1).x);
                let t = Triangle::new(p(a), p(b), p(c));
                let Some(setup) = setup(&t, &target, target.convention.tie_rule.into()) else {
                    continue;
                };
                let bound = bound_of(&setup.edges, &setup.range);
                LARGEST.with(|m| *m.borrow_mut() = BigInt::zero());
                let edges: Edges<Track> = Edges::from_big(&setup.edges);
                let mut cov = Coverage::new(40, 40);
                traverse(&edges, &setup.range, 0, &mut cov);
                let largest = LARGEST.with(|m| m.borrow().clone());
                assert!(largest <= bound.value, "case {k}, d {d}: {largest} > {}", bound.value);
                assert_eq!(
                    largest, bound.value,
                    "case {k}, d {d}: the bound ({}) is reached",
                    bound.what
                );
                checked += 1;
            }
        }
        assert!(checked >= 15);
    }
}
