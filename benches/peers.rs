//! The crate's integer models side by side with their peers and the textbook baselines, in
//! one process, single thread, round-robin (every repetition runs each contender once, so
//! drift hits all alike), median of 9 repetitions. Every contender writes +1 per covered
//! pixel into a `width x height` buffer of `u8` (the "u8 target"), cleared before each
//! repetition outside the timer; Mpix/s is covered pixels (the +1 writes) per second.
//!
//! `cargo bench --features bench --bench peers` (about a minute). To profile one contender alone:
//! `PEERS_WORKLOADS=b PEERS_ONLY="crate fixed" PEERS_REPS=50 cargo bench --features bench --bench peers`
//! (workload letters; the contenders whose name contains the text are timed, the
//! reference is still drawn once, untimed, to check them). The bench profile inherits the crate's
//! `[profile.release] overflow-checks = true`, and the header says whether checks are on;
//! `CARGO_PROFILE_BENCH_OVERFLOW_CHECKS=false cargo bench --features bench --bench peers` measures without.
//!
//! Workloads (the generators of `benches/models.rs` and `benches/lines.rs`, the 1/256 grid):
//! (a) 10k medium triangles (spread 24 px) at 1024x1024; (b) 100k small triangles (spread
//! 4 px) at 1024x1024; (c) one triangle covering half of 4096x4096; (d) 100k random lines
//! (integer pixel endpoints, major length 1..=1000) with both ends on a 1024x1024 canvas;
//! (e) the same kind of lines as `benches/lines.rs` draws, ends anywhere (some run off the
//! canvas, so clipping counts).
//!
//! Triangle contenders (all on the `cts` preset's grid: 8 subpixel bits, half away from
//! zero, top-left rule, sample at the pixel centre; each crate model also as `... span-only`,
//! drawn through a sink that implements only `cover` and `cover_span` with a plain +1
//! loop, as a user's sink would: it keeps the trait's default `prefers_masks` (false), so
//! the traversals hand it a small triangle's pixels one by one and a larger one's rows as
//! spans, walked along the edges):
//! - `crate fixed`, `crate scanline`, `crate exact-snapped`: the crate's models through
//!   `prepare` (outside the timer) and `PreparedScene::render` into [`Grid`], a
//!   `CoverageSink` whose `cover` and `cover_span` write through a row slice (a span of
//!   at most eight pixels as one eight-byte add), `cover_mask` eight cells a time as one
//!   `u64` and `cover_block` a block's row masks from one offset stepped by the row
//!   length, and whose `prefers_masks` says so (only `exact-snapped`'s setup is in
//!   `prepare`: `fixed` and `scanline` set each triangle up in `draw`; on this grid every
//!   `exact-snapped` triangle lies on the subpixel grid, so the planned engine draws it
//!   with the integer engine);
//! - `baseline plain`: a textbook i64 incremental edge-function loop over the bounding box
//!   (E stepped by addition per pixel and per row, `e0 >= 0 && e1 >= 0 && e2 >= 0`);
//! - `baseline branch-free`: the same loop adding the mask `(e0 | e1 | e2) >= 0`;
//! - `baseline 8x8 blocks`: 8x8 blocks stepped by addition, one trivial-reject and one
//!   trivial-accept corner per edge, accepted blocks as row spans (through the sink's
//!   `cover_span`, as the crate's), partial blocks per pixel branch-free. The baselines
//!   snap the exact vertices themselves (i64, 8 bits, half away from zero) and do their
//!   whole setup inside the timer, as the crate's draw does;
//! - `tiny-skia fill`: tiny-skia's non-AA path fill (`anti_alias: false`,
//!   `FillRule::Winding`, identity transform, opaque source-over, so its fast span path),
//!   one `fill_path` per triangle (one path of all of them would merge overlaps), into a
//!   premultiplied RGBA `Pixmap` (paths built outside the timer, f32 vertices, exact on
//!   this grid): its "+1" is its own 4-byte pixel write;
//! - `tiny-skia plus`: the same fill with `BlendMode::Plus` and alpha 1/255, a true +1 per
//!   covered pixel in the alpha channel (the general pipeline: slower). Its alpha sum is
//!   tiny-skia's covered-pixel count for both tiny-skia rows.
//!
//! Line contenders (`crate *` and `line_drawing` skip pixels off the canvas one by one):
//! - `crate fixed`: `Model::Fixed` on `Line`s with `LineRule::Bresenham(BresenhamTie::Stay)`
//!   through `prepare` and `draw`; `crate bresenham::rasterize`: the same walk called directly;
//! - `line_drawing`: `line_drawing::Bresenham`, both ends included; it draws
//!   `floor(k dy / dx)`, not the nearest pixel, so its pixels differ (its count does not
//!   while both ends are on the canvas);
//! - `clipline`: `Clip::line_b_proj` (the segment clipped to the canvas as a whole, then
//!   its Bresenham iterator); half-open (the last pixel is not drawn) and ties step the
//!   minor axis (our `BresenhamTie::Step`): its pixels are checked equal to ours with
//!   `Step` less each line's last pixel.
//!
//! Every table prints each contender's count; the crate models and the baselines must
//! cover the same pixels (checked pixel for pixel against `baseline plain` on a `u32` grid
//! before the timed runs, and each timed run's `u8` buffer against its own `u32` pass;
//! lines: against `crate bresenham::rasterize`); tiny-skia's sampling is its own, so its
//! count and the pixels where it differs are printed. "vs best" is the ratio of Mpix/s to
//! the best peer or baseline of the workload.

use std::hint::black_box;
use std::time::Instant;

use clipline::Clip;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;
use rasterproof::convention::{Preset, Target};
use rasterproof::coverage::CoverageSink;
use rasterproof::geom::{Point, Triangle};
use rasterproof::line::{bresenham, BresenhamTie, Line, LineRule};
use rasterproof::model::{prepare, Model, PreparedScene, Primitives};
use tiny_skia::{BlendMode, Color, FillRule, Paint, Path, PathBuilder, Pixmap, Transform};

#[path = "../tests/common/rng.rs"]
mod rng;
#[path = "common/workloads.rs"]
mod workloads;
use workloads::{half_canvas, lines, triangles, Segment};

/// Round-robin repetitions per contender (`PEERS_REPS` overrides, for profiling).
fn reps() -> usize {
    std::env::var("PEERS_REPS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(9)
}

/// Whether workload `letter` runs (`PEERS_WORKLOADS`, letters; all by default).
fn wanted(letter: char) -> bool {
    std::env::var("PEERS_WORKLOADS").map_or(true, |v| v.contains(letter))
}

/// Whether contender `name` is timed (`PEERS_ONLY`, a part of the name; all by default).
fn timed(name: &str) -> bool {
    std::env::var("PEERS_ONLY").map_or(true, |v| name.contains(v.as_str()))
}

// ---------------------------------------------------------------------------------------
// Workloads.

// ---------------------------------------------------------------------------------------
// The target: one cell per pixel, +1 per covered pixel.

/// A pixel cell: `u8` in the timed runs (the u8 target), `u32` for the exact
/// counts and the pixel-for-pixel comparison.
trait Cell: Copy + Default + PartialEq {
    /// +1 (wrapping: a `u8` cell covered 256 times reads 0; the `u32` pass sees it).
    fn bump(&mut self);
    /// +1 when `inside`, without a branch.
    fn bump_if(&mut self, inside: bool);
    /// The cell's count.
    fn count(self) -> u64;
    /// The count mod 256 (what a `u8` cell holds).
    fn low_byte(self) -> u8;
    /// +1 on `cells[i]` for each set bit `i` of `mask` (the sink's `cover_mask`): the
    /// baselines' `bump_if`, one bit at a time.
    #[inline(always)]
    fn add_mask(cells: &mut [Self], mask: u32) {
        let mut rest = mask;
        for cell in cells.iter_mut() {
            if rest == 0 {
                break;
            }
            cell.bump_if(rest & 1 != 0);
            rest >>= 1;
        }
    }
    /// `add_mask` on eight cells and an eight-bit mask.
    #[inline(always)]
    fn add_mask8(cells: &mut [Self; 8], mask: u8) {
        Self::add_mask(cells, u32::from(mask));
    }
}

/// Each 8-bit mask as eight bytes, byte `i` 1 where bit `i` is set (the SWAR `add_mask`'s
/// spread, one load instead of a multiply and four masks).
const BYTE_ONES: [u64; 256] = {
    let mut table = [0; 256];
    let mut m = 0;
    while m < 256 {
        let mut i = 0;
        while i < 8 {
            if m >> i & 1 != 0 {
                table[m] |= 1 << (8 * i);
            }
            i += 1;
        }
        m += 1;
    }
    table
};

impl Cell for u8 {
    #[inline(always)]
    fn bump(&mut self) {
        *self = self.wrapping_add(1);
    }
    #[inline(always)]
    fn bump_if(&mut self, inside: bool) {
        *self = self.wrapping_add(u8::from(inside));
    }
    fn count(self) -> u64 {
        u64::from(self)
    }
    fn low_byte(self) -> u8 {
        self
    }
    /// Eight cells at a time as one `u64` (SWAR: each byte's +0/+1 without a carry into
    /// the next), while the row has eight cells left.
    #[inline(always)]
    fn add_mask(cells: &mut [u8], mask: u32) {
        let mut rest = mask;
        let mut at = 0;
        while rest != 0 {
            let Some(chunk) = cells.get_mut(at..at + 8) else {
                // fewer than eight cells left in the row
                for cell in &mut cells[at..] {
                    cell.bump_if(rest & 1 != 0);
                    rest >>= 1;
                }
                return;
            };
            Self::add_mask8(chunk.try_into().expect("eight cells"), rest.to_le_bytes()[0]);
            rest >>= 8;
            at += 8;
        }
    }
    /// Each byte's +0/+1 without a carry into the next.
    #[inline(always)]
    fn add_mask8(cells: &mut [u8; 8], mask: u8) {
        const HIGH: u64 = 0x8080_8080_8080_8080;
        let ones = BYTE_ONES[usize::from(mask)];
        let v = u64::from_le_bytes(*cells);
        *cells = (((v & !HIGH) + ones) ^ (v & HIGH)).to_le_bytes();
    }
}

impl Cell for u32 {
    #[inline(always)]
    fn bump(&mut self) {
        *self = self.wrapping_add(1);
    }
    #[inline(always)]
    fn bump_if(&mut self, inside: bool) {
        *self = self.wrapping_add(u32::from(inside));
    }
    fn count(self) -> u64 {
        u64::from(self)
    }
    fn low_byte(self) -> u8 {
        self.to_le_bytes()[0]
    }
}

/// `u32` to an index (lossless on every target this bench runs on).
#[inline(always)]
fn ix(v: u32) -> usize {
    usize::try_from(v).expect("u32 fits usize")
}

/// A dense `width x height` grid of cells, row-major.
struct Grid<T> {
    width: usize,
    height: usize,
    cells: Vec<T>,
}

impl<T: Cell> Grid<T> {
    fn new(width: u32, height: u32) -> Grid<T> {
        Grid {
            width: ix(width),
            height: ix(height),
            cells: vec![T::default(); ix(width) * ix(height)],
        }
    }

    fn clear(&mut self) {
        self.cells.fill(T::default());
    }

    /// Row `y`.
    #[inline(always)]
    fn row(&mut self, y: usize) -> &mut [T] {
        &mut self.cells[y * self.width..][..self.width]
    }

    /// The +1 writes: the sum of all cells.
    fn total(&self) -> u64 {
        self.cells.iter().map(|c| c.count()).sum()
    }

    /// Pixels covered at least once.
    fn union(&self) -> u64 {
        self.cells.iter().map(|&c| u64::from(c != T::default())).sum()
    }

    /// The largest cell.
    fn max(&self) -> u64 {
        self.cells.iter().map(|c| c.count()).max().unwrap_or(0)
    }

    /// A digest of the cells mod 256, to compare a `u8` run with a `u32` one.
    fn digest(&self) -> u64 {
        self.cells.iter().fold(0xcbf2_9ce4_8422_2325, |h: u64, c| {
            (h ^ u64::from(c.low_byte())).wrapping_mul(0x0100_0000_01b3)
        })
    }
}

impl<T: Cell> CoverageSink for Grid<T> {
    /// Its `cover_mask` and `cover_block` add masks without a branch per pixel.
    #[inline]
    fn prefers_masks(&self) -> bool {
        true
    }

    #[inline]
    fn cover(&mut self, x: u32, y: u32, _id: u32) {
        self.row(ix(y))[ix(x)].bump();
    }

    #[inline]
    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, _id: u32) {
        if x0 > x1 {
            return;
        }
        let (row, x0, len) = (self.row(ix(y)), ix(x0), ix(x1 - x0) + 1);
        match row.get_mut(x0..x0 + 8) {
            // a short span with eight cells on the canvas from its start: one eight-cell add
            // (longer ones vectorise as they are)
            Some(cells) if len <= 8 => {
                T::add_mask8(
                    cells.try_into().expect("eight cells"),
                    (0xffff_u16 >> (16 - len)).to_le_bytes()[0],
                );
            }
            _ => row[x0..x0 + len].iter_mut().for_each(Cell::bump),
        }
    }

    /// Each bit added to its cell, branch-free ([`Cell::add_mask`]).
    #[inline(always)]
    fn cover_mask(&mut self, y: u32, x0: u32, mask: u32, _id: u32) {
        T::add_mask(&mut self.row(ix(y))[ix(x0)..], mask);
    }

    /// The rows' masks from one offset stepped by the row length, when the block's eight
    /// columns are all on the canvas; else row by row.
    #[inline(always)]
    fn cover_block(&mut self, y0: u32, x0: u32, block: u64, id: u32) {
        let rows = ix((71 - block.leading_zeros()) / 8); // up to the last non-zero byte
        let masks = block.to_le_bytes().into_iter().take(rows);
        let (x, y) = (ix(x0), ix(y0));
        if x + 8 > self.width || y + rows > self.height {
            for (y, mask) in (y0..).zip(masks) {
                self.cover_mask(y, x0, u32::from(mask), id);
            }
            return;
        }
        let mut at = y * self.width + x;
        for mask in masks {
            T::add_mask8((&mut self.cells[at..at + 8]).try_into().expect("eight cells"), mask);
            at += self.width;
        }
    }
}

/// The u8 target as a user's sink would be: `cover` and `cover_span` only (a plain +1 loop
/// over the span), the trait's defaults for `cover_mask` and `cover_block`.
struct SpanOnly<'a, T>(&'a mut Grid<T>);

impl<T: Cell> CoverageSink for SpanOnly<'_, T> {
    #[inline]
    fn cover(&mut self, x: u32, y: u32, _id: u32) {
        self.0.row(ix(y))[ix(x)].bump();
    }

    #[inline]
    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, _id: u32) {
        for cell in &mut self.0.row(ix(y))[ix(x0)..=ix(x1)] {
            cell.bump();
        }
    }
}

// ---------------------------------------------------------------------------------------
// The textbook baselines: i64 fixed point, 8 subpixel bits, top-left rule, centre samples.

/// Subpixel bits.
const S: u32 = 8;
/// One pixel in subpixels.
const ONE: i64 = 1 << S;
/// The sample's offset inside its pixel.
const HALF: i64 = ONE / 2;

/// A triangle snapped to the 2^-8 grid, `[x, y]` in subpixels.
type Snapped = [[i64; 2]; 3];

/// `v` in subpixels, rounded half away from zero (the `cts` preset's snapping).
fn snap(v: &BigRational) -> i64 {
    let scaled = v * BigRational::from_integer(BigInt::from(ONE));
    scaled.round().to_integer().to_i64().expect("coordinates fit i64")
}

fn snapped(tris: &[Triangle]) -> Vec<Snapped> {
    tris.iter()
        .map(|t| t.v.each_ref().map(|p| [snap(&p.x), snap(&p.y)]))
        .collect()
}

/// One triangle's traversal state: the pixel box, E at the box's first sample (bias
/// included: inside is `E >= 0`), and E's steps one pixel right and one pixel down.
struct Setup {
    x0: usize,
    x1: usize,
    y0: usize,
    y1: usize,
    e: [i64; 3],
    step_x: [i64; 3],
    step_y: [i64; 3],
}

#[inline(always)]
fn setup(t: &Snapped, width: usize, height: usize) -> Option<Setup> {
    let edge = |a: [i64; 2], b: [i64; 2], p: [i64; 2]| (p[0] - a[0]) * (b[1] - a[1]) - (p[1] - a[1]) * (b[0] - a[0]);
    let [a, mut b, mut c] = *t;
    let area = edge(a, b, c);
    if area == 0 {
        return None;
    }
    if area < 0 {
        std::mem::swap(&mut b, &mut c);
    }
    // The first pixel whose sample is at or after m, the last at or before it.
    let first = |m: i64| (m - HALF + ONE - 1) >> S;
    let last = |m: i64| (m - HALF) >> S;
    let (w, h) = (
        i64::try_from(width).expect("canvas fits i64"),
        i64::try_from(height).expect("canvas fits i64"),
    );
    let x0 = first(a[0].min(b[0]).min(c[0])).max(0);
    let x1 = last(a[0].max(b[0]).max(c[0])).min(w - 1);
    let y0 = first(a[1].min(b[1]).min(c[1])).max(0);
    let y1 = last(a[1].max(b[1]).max(c[1])).min(h - 1);
    if x0 > x1 || y0 > y1 {
        return None;
    }
    let p = [x0 * ONE + HALF, y0 * ONE + HALF];
    let mut e = [0; 3];
    let mut step_x = [0; 3];
    let mut step_y = [0; 3];
    for (k, (from, to)) in [(a, b), (b, c), (c, a)].into_iter().enumerate() {
        let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
        // Top-left: an edge going down, or a horizontal edge going left, owns its samples.
        let inclusive = dy > 0 || (dy == 0 && dx < 0);
        e[k] = edge(from, to, p) - i64::from(!inclusive);
        step_x[k] = dy * ONE;
        step_y[k] = -dx * ONE;
    }
    let index = |v: i64| usize::try_from(v).expect("clamped to the canvas");
    Some(Setup {
        x0: index(x0),
        x1: index(x1),
        y0: index(y0),
        y1: index(y1),
        e,
        step_x,
        step_y,
    })
}

/// `e += d`, edge by edge.
#[inline(always)]
fn add3(e: &mut [i64; 3], d: &[i64; 3]) {
    e[0] += d[0];
    e[1] += d[1];
    e[2] += d[2];
}

/// Baseline 1: the plain incremental loop over the bounding box, three branches a pixel.
fn baseline_plain<T: Cell>(tris: &[Snapped], grid: &mut Grid<T>) {
    let (width, height) = (grid.width, grid.height);
    for t in tris {
        let Some(s) = setup(t, width, height) else {
            continue;
        };
        let mut row_e = s.e;
        for y in s.y0..=s.y1 {
            let mut e = row_e;
            for cell in &mut grid.row(y)[s.x0..=s.x1] {
                if e[0] >= 0 && e[1] >= 0 && e[2] >= 0 {
                    cell.bump();
                }
                add3(&mut e, &s.step_x);
            }
            add3(&mut row_e, &s.step_y);
        }
    }
}

/// Baseline 2: the bounding-box loop, branch-free: the sign bit of `e0 | e1 | e2` is the mask.
fn baseline_branch_free<T: Cell>(tris: &[Snapped], grid: &mut Grid<T>) {
    let (width, height) = (grid.width, grid.height);
    for t in tris {
        let Some(s) = setup(t, width, height) else {
            continue;
        };
        let mut row_e = s.e;
        for y in s.y0..=s.y1 {
            let mut e = row_e;
            for cell in &mut grid.row(y)[s.x0..=s.x1] {
                cell.bump_if((e[0] | e[1] | e[2]) >= 0);
                add3(&mut e, &s.step_x);
            }
            add3(&mut row_e, &s.step_y);
        }
    }
}

/// Block side of baseline 3.
const BLOCK: usize = 8;

/// Baseline 3: 8x8 blocks from the box's first pixel, block origins stepped by addition.
/// Per edge one corner tells all: E is largest at the corner its steps point to (reject
/// the block when that is < 0) and smallest at the opposite one (the block is inside the
/// edge when that is >= 0). The corners are those of the whole 8x8 block even where the
/// box cuts it, which only makes the tests conservative.
fn baseline_blocks<T: Cell>(tris: &[Snapped], grid: &mut Grid<T>) {
    let (width, height) = (grid.width, grid.height);
    let last = i64::try_from(BLOCK - 1).expect("small");
    let side = i64::try_from(BLOCK).expect("small");
    for t in tris {
        let Some(s) = setup(t, width, height) else {
            continue;
        };
        let (sx, sy) = (s.step_x, s.step_y);
        let hi = [0, 1, 2].map(|k| last * (sx[k].max(0) + sy[k].max(0)));
        let lo = [0, 1, 2].map(|k| last * (sx[k].min(0) + sy[k].min(0)));
        let block_x = sx.map(|v| v * side);
        let block_y = sy.map(|v| v * side);
        let mut row_e = s.e;
        for by in (s.y0..=s.y1).step_by(BLOCK) {
            let by1 = (by + BLOCK - 1).min(s.y1);
            let mut e = row_e;
            for bx in (s.x0..=s.x1).step_by(BLOCK) {
                let bx1 = (bx + BLOCK - 1).min(s.x1);
                let rejected = ((e[0] + hi[0]) | (e[1] + hi[1]) | (e[2] + hi[2])) < 0;
                if !rejected {
                    if ((e[0] + lo[0]) | (e[1] + lo[1]) | (e[2] + lo[2])) >= 0 {
                        // the sink's span writer, as the crate's accepted blocks use
                        let at = |v: usize| u32::try_from(v).expect("on the canvas");
                        for y in by..=by1 {
                            grid.cover_span(at(y), at(bx), at(bx1), 0);
                        }
                    } else {
                        let mut pe_row = e;
                        for y in by..=by1 {
                            let mut pe = pe_row;
                            for cell in &mut grid.row(y)[bx..=bx1] {
                                cell.bump_if((pe[0] | pe[1] | pe[2]) >= 0);
                                add3(&mut pe, &sx);
                            }
                            add3(&mut pe_row, &sy);
                        }
                    }
                }
                add3(&mut e, &block_x);
            }
            add3(&mut row_e, &block_y);
        }
    }
}

// ---------------------------------------------------------------------------------------
// The line peers.

/// `line_drawing::Bresenham`, pixels off the canvas skipped.
fn line_drawing_draw<T: Cell>(ls: &[Segment], grid: &mut Grid<T>) {
    let (width, height) = (grid.width, grid.height);
    for &(a, b) in ls {
        for (x, y) in line_drawing::Bresenham::new((a[0], a[1]), (b[0], b[1])) {
            if let (Ok(x), Ok(y)) = (usize::try_from(x), usize::try_from(y)) {
                if x < width && y < height {
                    grid.row(y)[x].bump();
                }
            }
        }
    }
}

/// `clipline`: each segment clipped to the canvas, then walked (half-open).
fn clipline_draw<T: Cell>(ls: &[[i32; 4]], clip: &Clip<i32>, grid: &mut Grid<T>) {
    for &[x0, y0, x1, y1] in ls {
        if let Some(line) = clip.line_b_proj(x0, y0, x1, y1) {
            line.for_each(|(x, y)| grid.row(ix(y))[ix(x)].bump());
        }
    }
}

/// The crate's Bresenham called directly.
fn crate_bresenham_draw<T: Cell>(ls: &[Segment], tie: BresenhamTie, target: &Target, grid: &mut Grid<T>) {
    for (k, &(a, b)) in ls.iter().enumerate() {
        bresenham::rasterize(a, b, tie, u32::try_from(k).expect("ids fit u32"), target, grid);
    }
}

// ---------------------------------------------------------------------------------------
// Contenders and the round-robin.

#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// One of the crate's models.
    Crate,
    /// Another library.
    Peer,
    /// A textbook loop written here.
    Baseline,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::Crate => "crate",
            Kind::Peer => "peer",
            Kind::Baseline => "baseline",
        }
    }
}

/// What a contender draws and how.
enum Job<'a> {
    /// A crate model's prepared scene.
    Prepared(PreparedScene),
    /// The same drawn through [`SpanOnly`], a sink as a user writes one.
    SpanOnly(PreparedScene),
    Plain(&'a [Snapped]),
    BranchFree(&'a [Snapped]),
    Blocks(&'a [Snapped]),
    /// tiny-skia: the paths and the paint.
    TinySkia(&'a [Path], Paint<'static>),
    CrateBresenham(&'a [Segment]),
    LineDrawing(&'a [Segment]),
    Clipline(&'a [[i32; 4]], Clip<i32>),
}

struct Contender<'a> {
    name: String,
    kind: Kind,
    job: Job<'a>,
}

impl<'a> Contender<'a> {
    fn new(name: &str, kind: Kind, job: Job<'a>) -> Contender<'a> {
        Contender {
            name: name.to_string(),
            kind,
            job,
        }
    }

    /// Draws into `grid` (every job but tiny-skia's).
    fn draw<T: Cell>(&self, target: &Target, grid: &mut Grid<T>) {
        match &self.job {
            Job::Prepared(p) => p.render(target, grid),
            Job::SpanOnly(p) => p.render(target, &mut SpanOnly(grid)),
            Job::Plain(ts) => baseline_plain(ts, grid),
            Job::BranchFree(ts) => baseline_branch_free(ts, grid),
            Job::Blocks(ts) => baseline_blocks(ts, grid),
            Job::CrateBresenham(ls) => crate_bresenham_draw(ls, BresenhamTie::Stay, target, grid),
            Job::LineDrawing(ls) => line_drawing_draw(ls, grid),
            Job::Clipline(ls, clip) => clipline_draw(ls, clip, grid),
            Job::TinySkia(..) => unreachable!("tiny-skia draws into its pixmap"),
        }
    }

    /// Fills every path into `pixmap` (tiny-skia's job only).
    fn fill(&self, pixmap: &mut Pixmap) {
        let Job::TinySkia(paths, paint) = &self.job else {
            unreachable!("only tiny-skia fills a pixmap")
        };
        for path in *paths {
            pixmap.fill_path(path, paint, FillRule::Winding, Transform::identity(), None);
        }
    }

    fn is_tiny_skia(&self) -> bool {
        matches!(self.job, Job::TinySkia(..))
    }
}

/// The alpha channel of a pixmap.
fn alphas(pixmap: &Pixmap) -> impl Iterator<Item = u8> + '_ {
    pixmap.data().chunks_exact(4).map(|p| p[3])
}

/// What the untimed pass found for one contender.
struct Counted {
    /// The +1 writes.
    total: u64,
    /// Pixels covered at least once.
    union: u64,
    /// The digest a timed `u8` run must reproduce (`None` for tiny-skia).
    digest: Option<u64>,
}

/// One line of a table.
struct Row {
    name: String,
    kind: Kind,
    seconds: f64,
    total: u64,
    union: u64,
}

impl Row {
    fn mpix(&self) -> f64 {
        self.total as f64 / self.seconds / 1e6
    }
}

/// The median; NaN for a contender that was not timed (see [`timed`]).
fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

/// The untimed pass: each contender once into a `u32` grid (exact counts; the crate's
/// models and the baselines compared pixel for pixel with `contenders[reference]`), then
/// `reps()` round-robin timed runs (of the contenders [`timed`] keeps) into the `u8` grid (or the pixmap), each contender's first
/// checked against its `u32` pass. Returns the rows and the notes for the table.
fn measure(contenders: &[Contender], reference: usize, target: &Target) -> (Vec<Row>, Vec<String>) {
    let (w, h) = (target.width, target.height);
    let mut notes = Vec::new();
    let reference_name = &contenders[reference].name;
    let mut reference_grid = Grid::<u32>::new(w, h);
    contenders[reference].draw(target, &mut reference_grid);
    let mut counted = Vec::new();
    let mut pixmap = Pixmap::new(w, h).expect("a pixmap of the canvas");
    let mut tiny_alpha: Option<Vec<u8>> = None;
    for c in contenders {
        if c.is_tiny_skia() {
            pixmap.fill(Color::TRANSPARENT);
            c.fill(&mut pixmap);
            let union = alphas(&pixmap).filter(|&a| a != 0).count() as u64;
            let plus = matches!(&c.job, Job::TinySkia(_, p) if p.blend_mode == BlendMode::Plus);
            if plus {
                let max = alphas(&pixmap).max().unwrap_or(0);
                if max == u8::MAX {
                    notes.push(format!("WARNING: {}: alpha saturated at 255, its count is low", c.name));
                }
                tiny_alpha = Some(alphas(&pixmap).collect());
            }
            counted.push(Counted {
                total: if plus { alphas(&pixmap).map(u64::from).sum() } else { 0 },
                union,
                digest: None,
            });
            continue;
        }
        let mut grid = Grid::<u32>::new(w, h);
        c.draw(target, &mut grid);
        if grid.max() > u64::from(u8::MAX) {
            notes.push(format!(
                "WARNING: {}: a pixel is covered {} times, beyond a u8 cell",
                c.name,
                grid.max()
            ));
        }
        counted.push(Counted {
            total: grid.total(),
            union: grid.union(),
            digest: Some(grid.digest()),
        });
        if c.kind != Kind::Peer {
            let differing = reference_grid
                .cells
                .iter()
                .zip(&grid.cells)
                .filter(|(a, b)| a != b)
                .count();
            if differing != 0 {
                notes.push(format!(
                    "MISMATCH: {} differs from {reference_name} at {differing} pixels",
                    c.name
                ));
            }
        }
    }
    // tiny-skia's opaque row takes its count from the Plus row (same scan converter).
    if let Some(plus_total) = contenders
        .iter()
        .zip(&counted)
        .find(|(c, _)| matches!(&c.job, Job::TinySkia(_, p) if p.blend_mode == BlendMode::Plus))
        .map(|(_, n)| n.total)
    {
        for (c, n) in contenders.iter().zip(counted.iter_mut()) {
            if c.is_tiny_skia() && n.total == 0 {
                n.total = plus_total;
            }
        }
    }
    if let Some(alpha) = &tiny_alpha {
        let (mut only_tiny, mut only_ref) = (0u64, 0u64);
        for (&a, &b) in alpha.iter().zip(&reference_grid.cells) {
            let (a, b) = (u64::from(a), u64::from(b));
            only_tiny += a.saturating_sub(b);
            only_ref += b.saturating_sub(a);
        }
        notes.push(format!(
            "tiny-skia vs {reference_name}: {only_tiny} pixel writes only tiny-skia makes, {only_ref} only \
             {reference_name} makes (its own sampling rule)"
        ));
    }
    drop(reference_grid);

    let mut grid = Grid::<u8>::new(w, h);
    let mut times: Vec<Vec<f64>> = vec![Vec::new(); contenders.len()];
    for rep in 0..reps() {
        for (k, c) in contenders.iter().enumerate().filter(|(_, c)| timed(&c.name)) {
            if c.is_tiny_skia() {
                pixmap.fill(Color::TRANSPARENT);
                let start = Instant::now();
                c.fill(&mut pixmap);
                times[k].push(start.elapsed().as_secs_f64());
                black_box(&pixmap);
            } else {
                grid.clear();
                let start = Instant::now();
                c.draw(target, &mut grid);
                times[k].push(start.elapsed().as_secs_f64());
                black_box(&grid);
                if rep == 0 && Some(grid.digest()) != counted[k].digest {
                    notes.push(format!("MISMATCH: {}: the timed u8 run drew other pixels", c.name));
                }
            }
        }
    }
    let rows = contenders
        .iter()
        .zip(counted)
        .zip(times)
        .map(|((c, n), t)| Row {
            name: c.name.clone(),
            kind: c.kind,
            seconds: median(t),
            total: n.total,
            union: n.union,
        })
        .collect();
    (rows, notes)
}

fn print_table(title: &str, rows: &[Row], notes: &[String]) {
    let best = rows
        .iter()
        .filter(|r| r.kind != Kind::Crate && !r.seconds.is_nan())
        .max_by(|a, b| a.mpix().total_cmp(&b.mpix()));
    let best_mpix = best.map_or(f64::NAN, Row::mpix);
    println!("\n{title}");
    println!(
        "{:<26} {:<9} {:>9} {:>9} {:>11} {:>11} {:>8}",
        "contender", "kind", "ms", "Mpix/s", "covered", "union", "vs best"
    );
    for r in rows {
        println!(
            "{:<26} {:<9} {:>9.3} {:>9.1} {:>11} {:>11} {:>8.2}",
            r.name,
            r.kind.name(),
            r.seconds * 1e3,
            r.mpix(),
            r.total,
            r.union,
            r.mpix() / best_mpix
        );
    }
    if let Some(best) = best {
        println!("best peer or baseline: {} ({:.1} Mpix/s)", best.name, best_mpix);
    }
    for n in notes {
        println!("{n}");
    }
}

// ---------------------------------------------------------------------------------------
// The workloads' contender lists.

fn tiny_skia_paths(tris: &[Triangle]) -> Vec<Path> {
    let f = |v: &BigRational| v.to_f32().expect("a finite coordinate");
    tris.iter()
        .filter_map(|t| {
            let mut pb = PathBuilder::new();
            pb.move_to(f(&t.v[0].x), f(&t.v[0].y));
            pb.line_to(f(&t.v[1].x), f(&t.v[1].y));
            pb.line_to(f(&t.v[2].x), f(&t.v[2].y));
            pb.close();
            // `None` for a path with no area to its bounds: it covers nothing.
            pb.finish()
        })
        .collect()
}

fn paint(blend_mode: BlendMode, alpha: u8) -> Paint<'static> {
    let mut paint = Paint {
        anti_alias: false,
        blend_mode,
        ..Paint::default()
    };
    paint.set_color_rgba8(255, 255, 255, alpha);
    paint
}

fn triangle_workload(title: &str, side: u32, tris: &[Triangle]) {
    let target = Target::new(side, side, Preset::Cts.convention()).expect("a valid target");
    let primitives = Primitives::from_triangles(tris);
    let model = |m: Model| prepare(&primitives, &target, m).expect("the workload is inside every envelope");
    let snapped = snapped(tris);
    let paths = tiny_skia_paths(tris);
    let contenders = vec![
        Contender::new("crate fixed", Kind::Crate, Job::Prepared(model(Model::Fixed))),
        Contender::new("crate scanline", Kind::Crate, Job::Prepared(model(Model::Scanline))),
        Contender::new(
            "crate exact-snapped",
            Kind::Crate,
            Job::Prepared(model(Model::ExactSnapped)),
        ),
        Contender::new("crate fixed span-only", Kind::Crate, Job::SpanOnly(model(Model::Fixed))),
        Contender::new(
            "crate scanline span-only",
            Kind::Crate,
            Job::SpanOnly(model(Model::Scanline)),
        ),
        Contender::new(
            "crate exact-snapped span-only",
            Kind::Crate,
            Job::SpanOnly(model(Model::ExactSnapped)),
        ),
        Contender::new("baseline plain", Kind::Baseline, Job::Plain(&snapped)),
        Contender::new("baseline branch-free", Kind::Baseline, Job::BranchFree(&snapped)),
        Contender::new("baseline 8x8 blocks", Kind::Baseline, Job::Blocks(&snapped)),
        Contender::new(
            "tiny-skia fill (RGBA)",
            Kind::Peer,
            Job::TinySkia(&paths, paint(BlendMode::SourceOver, 255)),
        ),
        Contender::new(
            "tiny-skia plus (a+=1)",
            Kind::Peer,
            Job::TinySkia(&paths, paint(BlendMode::Plus, 1)),
        ),
    ];
    // The reference: the plain baseline, the simplest loop, independent of the crate's code.
    let plain = contenders
        .iter()
        .position(|c| matches!(c.job, Job::Plain(_)))
        .expect("the plain baseline");
    let (rows, mut notes) = measure(&contenders, plain, &target);
    let reference = rows[plain].total;
    let off: Vec<String> = rows
        .iter()
        .filter(|r| r.kind != Kind::Peer && r.total != reference)
        .map(|r| {
            format!(
                "{} {} ({:+})",
                r.name,
                r.total,
                i128::from(r.total) - i128::from(reference)
            )
        })
        .collect();
    if off.is_empty() {
        notes.insert(
            0,
            format!("counts: crate models and baselines equal ({reference} covered pixels)"),
        );
    } else {
        notes.insert(
            0,
            format!(
                "MISMATCH: counts differ from baseline plain's {reference}: {}",
                off.join(", ")
            ),
        );
    }
    if let Some(tiny) = rows.iter().find(|r| r.kind == Kind::Peer) {
        let diff = i128::from(tiny.total) - i128::from(reference);
        notes.insert(
            1,
            format!("tiny-skia covers {} ({diff:+} vs the baselines)", tiny.total),
        );
    }
    notes.push(
        "tiny-skia writes premultiplied RGBA (4 B/px, its fast opaque span path); the plus row adds 1 to alpha"
            .to_string(),
    );
    print_table(title, &rows, &notes);
}

fn line_workload(title: &str, side: u32, ls: &[Segment]) {
    let target = Target::new(side, side, Preset::Cts.convention()).expect("a valid target");
    let primitives = Primitives {
        lines: ls
            .iter()
            .map(|&(a, b)| Line {
                from: Point::from_ints(a[0], a[1]),
                to: Point::from_ints(b[0], b[1]),
                rule: LineRule::Bresenham(BresenhamTie::Stay),
            })
            .collect(),
        ..Primitives::default()
    };
    let fixed = prepare(&primitives, &target, Model::Fixed).expect("endpoints inside the envelope");
    let narrow = |v: i64| i32::try_from(v).expect("endpoints fit i32");
    let clip_ls: Vec<[i32; 4]> = ls
        .iter()
        .map(|&(a, b)| [narrow(a[0]), narrow(a[1]), narrow(b[0]), narrow(b[1])])
        .collect();
    let clip = Clip::<i32>::from_size(side, side).expect("a valid clip");
    let contenders = vec![
        Contender::new("crate fixed (Line model)", Kind::Crate, Job::Prepared(fixed)),
        Contender::new("crate bresenham::rasterize", Kind::Crate, Job::CrateBresenham(ls)),
        Contender::new("line_drawing Bresenham", Kind::Peer, Job::LineDrawing(ls)),
        Contender::new(
            "clipline line_b_proj",
            Kind::Peer,
            Job::Clipline(&clip_ls, clip.clone()),
        ),
    ];
    let (rows, mut notes) = measure(&contenders, 1, &target);

    // clipline against ours with its tie rule (Step), less each line's last pixel.
    let mut step = Grid::<u32>::new(side, side);
    crate_bresenham_draw(ls, BresenhamTie::Step, &target, &mut step);
    let (w, h) = (step.width, step.height);
    for &(_, b) in ls {
        if let (Ok(x), Ok(y)) = (usize::try_from(b[0]), usize::try_from(b[1])) {
            if x < w && y < h {
                step.row(y)[x] -= 1;
            }
        }
    }
    let mut clipped = Grid::<u32>::new(side, side);
    clipline_draw(&clip_ls, &clip, &mut clipped);
    let equal = step.cells == clipped.cells;
    notes.insert(
        0,
        format!(
            "clipline {} ours with BresenhamTie::Step less each line's last pixel ({} pixels, clipline {})",
            if equal { "equals" } else { "MISMATCH: differs from" },
            step.total(),
            clipped.total()
        ),
    );
    let mut stay = Grid::<u32>::new(side, side);
    crate_bresenham_draw(ls, BresenhamTie::Stay, &target, &mut stay);
    let mut ld = Grid::<u32>::new(side, side);
    line_drawing_draw(ls, &mut ld);
    let moved: u64 = stay
        .cells
        .iter()
        .zip(&ld.cells)
        .map(|(&a, &b)| u64::from(a.abs_diff(b)))
        .sum();
    notes.insert(
        0,
        format!(
            "line_drawing covers {} ({:+} vs ours with Stay); its floor rule moves pixels: \
             cells differ by {moved} writes in all",
            ld.total(),
            i128::from(ld.total()) - i128::from(stay.total())
        ),
    );
    if rows[0].total != rows[1].total {
        notes.insert(
            0,
            "MISMATCH: the Line model and bresenham::rasterize differ".to_string(),
        );
    }
    print_table(title, &rows, &notes);
}

/// Whether this build checks integer overflow (the bench profile inherits release's).
fn overflow_checks_on() -> bool {
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let on = std::panic::catch_unwind(|| black_box(u8::MAX) + black_box(1u8)).is_err();
    std::panic::set_hook(hook);
    on
}

fn main() {
    println!(
        "peer bench: single thread, round-robin, median of {} reps, +1 per covered pixel in a u8 target, \
         cts preset; overflow checks {}",
        reps(),
        if overflow_checks_on() { "ON" } else { "off" }
    );
    if wanted('a') {
        triangle_workload(
            "(a) 10k medium triangles (spread 24 px), 1024x1024",
            1024,
            &triangles(10_000, 1024, 24, 1),
        );
    }
    if wanted('b') {
        triangle_workload(
            "(b) 100k small triangles (spread 4 px), 1024x1024",
            1024,
            &triangles(100_000, 1024, 4, 2),
        );
    }
    if wanted('c') {
        triangle_workload("(c) one triangle, half of 4096x4096", 4096, &half_canvas(4096));
    }
    if wanted('d') {
        line_workload(
            "(d) 100k random lines, both ends on the 1024x1024 canvas",
            1024,
            &lines(100_000, 1024, true, 1),
        );
    }
    if wanted('e') {
        line_workload(
            "(e) 100k random lines as benches/lines.rs, ends anywhere (clipping)",
            1024,
            &lines(100_000, 1024, false, 1),
        );
    }
}
