//! Accumulated coverage in f32, a contender: signed-area cell accumulation as font-rs and
//! ab_glyph_rasterizer do it (their method, not their code): each edge walked row by row
//! in f32, each row's piece cut at the columns it crosses, every area and cover rounded to
//! f32 as it is added, the row summed left to right in f32. Its departures from the exact
//! values ([`super::cells`]) are what the trade measures and what the area checkers report.

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

/// The f32 accumulation buffer of one shape: per pixel `(cover, area)`, row-major.
struct Buffer {
    width: usize,
    height: usize,
    cells: Vec<[f32; 2]>,
}

impl Buffer {
    /// Adds a piece in cell (`column`, `row`) going down by `dy` at mean x `xm` (canvas
    /// coordinates); cells left of the canvas give their cover to column 0.
    #[allow(clippy::cast_possible_truncation, clippy::cast_precision_loss)]
    fn add(&mut self, column: f32, row: usize, dy: f32, xm: f32) {
        if row >= self.height || column >= self.width as f32 {
            return;
        }
        let k = row * self.width;
        if column < 0.0 {
            self.cells[k][1] += dy; // all of column 0 lies right of it
            self.cells[k][0] += dy;
            return;
        }
        let c = column as usize;
        self.cells[k + c][1] += dy * (1.0 - (xm - column));
        self.cells[k + c][0] += dy;
    }
}

/// Walks the edge `a -> b` into `buffer`, row by row, each row's piece cut at the columns.
#[allow(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_precision_loss
)]
fn walk(buffer: &mut Buffer, a: P, b: P) {
    if a[1] == b[1] || !(a[0].is_finite() && a[1].is_finite() && b[0].is_finite() && b[1].is_finite()) {
        return;
    }
    let dxdy = (b[0] - a[0]) / (b[1] - a[1]);
    let (top, bottom) = (a[1].min(b[1]), a[1].max(b[1]));
    let sign = if b[1] > a[1] { 1.0 } else { -1.0 };
    let first = top.floor().max(0.0);
    let last = bottom.ceil().min(buffer.height as f32);
    let mut row = first;
    while row < last {
        let y0 = top.max(row);
        let y1 = bottom.min(row + 1.0);
        let (x0, x1) = (a[0] + (y0 - a[1]) * dxdy, a[0] + (y1 - a[1]) * dxdy);
        let dy = (y1 - y0) * sign;
        let (lo, hi) = (x0.min(x1), x0.max(x1));
        let (c0, c1) = (lo.floor(), hi.ceil().max(lo.floor() + 1.0));
        if c1 - c0 <= 1.0 {
            buffer.add(c0, row as usize, dy, (x0 + x1) * 0.5);
        } else {
            // Cut at each column: the part of dy in each is its share of the x run.
            let mut c = c0;
            while c < c1 {
                let (from, to) = (lo.max(c), hi.min(c + 1.0));
                let share = (to - from) / (hi - lo);
                buffer.add(c, row as usize, dy * share, (from + to) * 0.5);
                c += 1.0;
            }
        }
        row += 1.0;
    }
}

/// The shapes' accumulated coverage in f32 on a `width` x `height` canvas, row-major:
/// each shape's row sums folded under `semantics` (`True` is read as `Accumulated`:
/// accumulation has no inside test) in f32, summed over the shapes.
pub fn rasterize(shapes: &[AreaShape], width: u32, height: u32, semantics: Semantics) -> Vec<f32> {
    let (w, h) = (width as usize, height as usize);
    let mut out = vec![0f32; w * h];
    for shape in shapes {
        let mut buffer = Buffer {
            width: w,
            height: h,
            cells: vec![[0.0; 2]; w * h],
        };
        for (a, b) in path_f32(shape) {
            walk(&mut buffer, a, b);
        }
        for y in 0..h {
            let mut carry = 0f32;
            for x in 0..w {
                let [cover, area] = buffer.cells[y * w + x];
                let acc = (carry + area).abs();
                carry += cover;
                out[y * w + x] += match (semantics, shape.fill_rule) {
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
                };
            }
        }
    }
    out
}
