//! Accumulated coverage in f32, a contender: signed-area cell accumulation as font-rs and
//! ab_glyph_rasterizer do it (their method, not their code): each edge walked row by row
//! in f32, each row's piece cut at the columns it crosses, every area and cover rounded to
//! f32 as it is added, the row summed left to right in f32. Its departures from the exact
//! values ([`super::cells`]) are what the trade measures and what the area checkers report.
//! [`rasterize_at`] is the one walk, with the canvas origin anywhere: in the placed
//! coordinates far from 0, as the trade measures it at a magnitude; [`rasterize`] is it at
//! the origin.

use num_traits::ToPrimitive;

use super::{AreaShape, Semantics};
use crate::geom::FillRule;

/// A point in f32.
type P = [f32; 2];

/// `shape`'s path in f32 (each coordinate rounded to the nearest f32; contours as given).
fn path_f32(shape: &AreaShape) -> Vec<(P, P)> {
    let f = |v: &num_rational::BigRational| v.to_f32().unwrap_or(f32::NAN);
    let mut out = Vec::new();
    for contour in shape.contours() {
        let n = contour.len();
        for i in 0..n {
            let (a, b) = (&contour[i], &contour[(i + 1) % n]);
            out.push(([f(&a.x), f(&a.y)], [f(&b.x), f(&b.y)]));
        }
    }
    out
}

/// The shapes' accumulated coverage in f32 on a `width` x `height` canvas, row-major:
/// each shape's row sums folded under `semantics` (`True` is read as `Accumulated`:
/// accumulation has no inside test) in f32, summed over the shapes ([`rasterize_at`] with
/// the canvas at the origin).
pub fn rasterize(shapes: &[AreaShape], width: u32, height: u32, semantics: Semantics) -> Vec<f32> {
    rasterize_at(shapes, 0, width, height, semantics)
}

/// A pixel's accumulated `|cover + area|` in f32 folded under `semantics` and `rule`: kept
/// (unclamped), clamped to 1 (nonzero) or reflected modulo 2 (even-odd).
fn fold(acc: f32, semantics: Semantics, rule: FillRule) -> f32 {
    match (semantics, rule) {
        (Semantics::AccumulatedUnclamped, _) => acc,
        (_, FillRule::NonZero) => acc.min(1.0),
        (_, FillRule::EvenOdd) => {
            let m = acc % 2.0;
            if m > 1.0 {
                2.0 - m
            } else {
                m
            }
        }
    }
}

/// The accumulation with the canvas origin at `(origin, origin)`: the shapes (placed
/// coordinates, each rounded to the nearest f32) walked in f32 over the window
/// `[origin, origin + width) x [origin, origin + height)`, row by row, each row's piece cut
/// at the columns, every area and cover rounded to f32 as it is added, each row summed
/// left to right in f32, folded under `semantics` and added over the shapes. The part of
/// a row's piece left of the window adds its cover to the window's first column in one
/// piece, so a shape far to the left costs what one at the edge does. The row and
/// column boundaries are the integers `origin + i` rounded to f32, exact below 2^24; past
/// it they collapse as f32 collapses them (a row or column whose boundaries round to one
/// value gets nothing). Equal to [`rasterize`] on a canvas that reaches the window,
/// restricted to it, where no shape reaches left of the window (tested at 2^10).
pub fn rasterize_at(shapes: &[AreaShape], origin: i64, width: u32, height: u32, semantics: Semantics) -> Vec<f32> {
    let (w, h) = (width as usize, height as usize);
    let mut out = vec![0f32; w * h];
    for shape in shapes {
        let path = path_f32(shape);
        let ys = path.iter().flat_map(|(a, b)| [a[1], b[1]]).filter(|v| v.is_finite());
        let (lo, hi) = ys.fold((f32::INFINITY, f32::NEG_INFINITY), |(l, u), v| (l.min(v), u.max(v)));
        if lo > hi {
            continue;
        }
        let first = f32_floor(lo).max(origin);
        let last = f32_ceil(hi).min(origin + i64::from(height));
        if first >= last {
            continue;
        }
        let mut buffer = Buffer {
            origin,
            first,
            width: w,
            rows: usize::try_from(last - first).unwrap_or(0),
            cells: vec![[0.0; 2]; usize::try_from(last - first).unwrap_or(0) * w],
        };
        for (a, b) in path {
            buffer.walk(a, b, i64::from(height));
        }
        let row0 = usize::try_from(first - origin).unwrap_or(0);
        for r in 0..buffer.rows {
            let mut carry = 0f32;
            for x in 0..w {
                let [cover, area] = buffer.cells[r * w + x];
                let acc = (carry + area).abs();
                carry += cover;
                out[(row0 + r) * w + x] += fold(acc, semantics, shape.fill_rule);
            }
        }
    }
    out
}

/// `v.floor()` as an i64 (f32 integers are exact; saturating beyond i64).
#[allow(clippy::cast_possible_truncation)]
fn f32_floor(v: f32) -> i64 {
    v.floor() as i64
}

/// `v.ceil()` as an i64.
#[allow(clippy::cast_possible_truncation)]
fn f32_ceil(v: f32) -> i64 {
    v.ceil() as i64
}

/// The integer `v` rounded to the nearest f32, ties to even.
#[allow(clippy::cast_precision_loss)]
fn to_f32(v: i64) -> f32 {
    v as f32
}

/// One shape's f32 cells `(cover, area)` over the rows `first..first + rows` of the window
/// at `origin`, row-major.
struct Buffer {
    origin: i64,
    first: i64,
    width: usize,
    rows: usize,
    cells: Vec<[f32; 2]>,
}

impl Buffer {
    /// Adds a piece in plane column `column` (its f32 value `cf`) and plane row `row`,
    /// going down by `dy` at mean x `xm`; columns left of the window give their cover to
    /// its first column.
    fn add(&mut self, column: i64, cf: f32, row: i64, dy: f32, xm: f32) {
        let Some(r) = usize::try_from(row - self.first).ok().filter(|&r| r < self.rows) else {
            return;
        };
        let first = r * self.width;
        if column < self.origin {
            self.cells[first][1] += dy; // all of the first column lies right of it
            self.cells[first][0] += dy;
            return;
        }
        let Some(c) = usize::try_from(column - self.origin).ok().filter(|&c| c < self.width) else {
            return;
        };
        self.cells[first + c][1] += dy * (1.0 - (xm - cf));
        self.cells[first + c][0] += dy;
    }

    /// Walks the edge `a -> b` (plane coordinates in f32) row by row, each row's piece cut
    /// at the columns.
    fn walk(&mut self, a: P, b: P, height: i64) {
        if a[1] == b[1] || !(a[0].is_finite() && a[1].is_finite() && b[0].is_finite() && b[1].is_finite()) {
            return;
        }
        let dxdy = (b[0] - a[0]) / (b[1] - a[1]);
        let (top, bottom) = (a[1].min(b[1]), a[1].max(b[1]));
        let sign = if b[1] > a[1] { 1.0 } else { -1.0 };
        let first = f32_floor(top).max(self.origin);
        let last = f32_ceil(bottom).min(self.origin + height);
        let right = self.origin + i64::try_from(self.width).unwrap_or(i64::MAX);
        for row in first..last {
            let y0 = top.max(to_f32(row));
            let y1 = bottom.min(to_f32(row + 1));
            if y1 <= y0 {
                continue; // the row's f32 boundaries collapsed: it has no height
            }
            let (x0, x1) = (a[0] + (y0 - a[1]) * dxdy, a[0] + (y1 - a[1]) * dxdy);
            let dy = (y1 - y0) * sign;
            let (lo, hi) = (x0.min(x1), x0.max(x1));
            let (c0, c1) = (lo.floor(), hi.ceil().max(lo.floor() + 1.0));
            if c1 - c0 <= 1.0 {
                self.add(f32_floor(c0), c0, row, dy, (x0 + x1) * 0.5);
            } else {
                let mut from_column = f32_floor(c0);
                let left = to_f32(self.origin);
                if lo < left {
                    // The part left of the window, in one piece: all of the first
                    // column lies right of it.
                    let to = hi.min(left);
                    self.add(
                        self.origin - 1,
                        left - 1.0,
                        row,
                        dy * ((to - lo) / (hi - lo)),
                        (lo + to) * 0.5,
                    );
                    from_column = self.origin;
                }
                for c in from_column..f32_ceil(c1).min(right) {
                    let (cf, cn) = (to_f32(c), to_f32(c + 1));
                    if cf >= c1 {
                        break;
                    }
                    let (from, to) = (lo.max(cf), hi.min(cn));
                    let share = (to - from) / (hi - lo);
                    self.add(c, cf, row, dy * share, (from + to) * 0.5);
                }
            }
        }
    }
}
