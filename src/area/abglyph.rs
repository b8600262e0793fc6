//! ab_glyph_rasterizer 0.1.10's rasterizer (the crate `ab_glyph_rasterizer`,
//! `src/raster.rs`: `Rasterizer::draw_line` and `Rasterizer::for_each_pixel`; forked from
//! font-rs, `src/raster.rs`, by Raph Levien) as the ab_glyph adapter
//! (`adapters/ab-glyph/main.rs`) feeds it, a contender: a port of its f32 arithmetic,
//! operation for operation, that gives its values bit for bit.
//!
//! What the adapter does, and the model with it:
//!
//! - **one rasterizer** for the whole scene: every contour of every shape (shapes in id
//!   order, each its outline then its holes), each edge `p[k] -> p[k+1]` and the closing
//!   one, drawn into one f32 buffer, so the winding numbers of all the contours add;
//! - **widened** to hold every point: the columns `lo..hi` with `lo = min(0, floor(min
//!   x))` and `hi = max(width, ceil(max x))`, the scene moved right by `-lo` whole pixels
//!   exactly, then each coordinate rounded once to the nearest f32; the canvas's columns
//!   are cut out of the wider buffer at the end (rows above and below it the crate skips
//!   itself);
//! - `draw_line`: an edge whose two y differ by at most `f32::EPSILON` is skipped; the
//!   others are walked top to bottom, one row at a time, `x` advanced by `dxdy x dy` in
//!   f32 (from the row's start, moved to y = 0 first when the edge starts above), and each
//!   row's piece deposits its closed-form trapezoid areas (`d - d xmf` and `d xmf` in one
//!   or two cells; `d a0`, `d (a1 - a0)`, `d s` each, `d (1 - a2 - am)`, `d am` across
//!   more) into the buffer, a cell index off its end skipping what is left of that
//!   deposit's loop (the crate's `continue`, which also leaves `x` unadvanced when it
//!   falls in the row loop);
//! - `for_each_pixel`: **one running f32 sum over the whole buffer**, row after row,
//!   never reset, each pixel's value its absolute value, no clamp (overlapping contours of
//!   one orientation give more than 1);
//! - the adapter's 16-bit level ([`levels`]): `round(min(max(a, 0), 1) x 65535)`, ties to
//!   even, exact in f64.
//!
//! **Range envelope.** The widened buffer holds at most 2^28 cells (the adapter's bound),
//! so every x the walk sees lies within a few pixels of `0..=2^28` and its `i32`
//! conversions and sums do not overflow; y is any f32 (the row loop runs over the canvas's
//! rows only). One index the crate computes in `usize`, `linestart + xi as usize` for a
//! column `xi` left of -1, overflows: this repository builds it with overflow checks (the
//! test and release profiles), so the crate panics there; the model returns an error
//! instead. The widening keeps every x at -1 or more but for f32 extrapolation error, so
//! no scene the adapter draws has met it.
//!
//! **Refused** (an error naming the reason): an even-odd shape (ab_glyph_rasterizer has no
//! fill rule: its value is the nonzero accumulation, `|sum|`, unclamped), a coordinate
//! that is not an f32 (beyond its range), a widened buffer of more than 2^28 cells.
//! Lines, clip windows and clip-space triangles are the adapter's to refuse: the model
//! takes the shapes of a scene that has none.

use num_rational::BigRational;
use num_traits::ToPrimitive;

use super::AreaShape;
use crate::geom::{FillRule, Point};

/// The most cells the widened buffer may have (the adapter's bound): 2^28 f32s.
pub const MAX_CELLS: u64 = 1 << 28;

/// A point in f32, `[x, y]`.
type P = [f32; 2];

/// ab_glyph_rasterizer's `Rasterizer`: its width, height and buffer (`width x height + 4`
/// cells, as the crate allocates).
struct Rasterizer {
    width: usize,
    height: usize,
    a: Vec<f32>,
}

/// The crate's `linestart + xi as usize` (`xi` an i32 sign-extended): an error where that
/// sum overflows (the crate's panic), a huge index where `xi` is negative but the sum does
/// not wrap (`get_mut` then finds nothing).
#[allow(clippy::cast_sign_loss, clippy::cast_possible_wrap)]
fn index(linestart: usize, xi: i32) -> Result<usize, String> {
    linestart.checked_add(xi as isize as usize).ok_or_else(|| {
        format!(
            "ab_glyph_rasterizer's index {linestart} + {xi} as usize overflows (a column left of -1): the crate \
             panics here under overflow checks"
        )
    })
}

impl Rasterizer {
    /// `Rasterizer::new(width, height)`.
    fn new(width: usize, height: usize) -> Rasterizer {
        Rasterizer {
            width,
            height,
            a: vec![0.0; width * height + 4],
        }
    }

    /// `Rasterizer::draw_line(p0, p1)` (its `draw_line_scalar`, which every SIMD dispatch
    /// of the crate calls), operation for operation.
    #[allow(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        clippy::cast_precision_loss,
        clippy::cast_possible_wrap,
        clippy::float_cmp
    )]
    fn draw_line(&mut self, p0: P, p1: P) -> Result<(), String> {
        // `self.a[i] += v`, or, where `i` is off the buffer, `continue` (the crate's
        // `add_assign_a_idx!`): the innermost loop around goes on.
        macro_rules! add {
            ($index:expr, $value:expr) => {
                match self.a.get_mut($index) {
                    Some(v) => *v += $value,
                    None => continue,
                }
            };
        }
        if (p0[1] - p1[1]).abs() <= f32::EPSILON {
            return Ok(());
        }
        let (dir, p0, p1) = if p0[1] < p1[1] {
            (1.0f32, p0, p1)
        } else {
            (-1.0, p1, p0)
        };
        let dxdy = (p1[0] - p0[0]) / (p1[1] - p0[1]);
        let mut x = p0[0];
        let y0 = p0[1] as usize; // saturating: 0 above the buffer
        if p0[1] < 0.0 {
            x -= p0[1] * dxdy;
        }
        for y in y0..self.height.min(p1[1].ceil() as usize) {
            let linestart = y * self.width;
            let dy = ((y + 1) as f32).min(p1[1]) - (y as f32).max(p0[1]);
            let xnext = x + dxdy * dy;
            let d = dy * dir;
            let (x0, x1) = if x < xnext { (x, xnext) } else { (xnext, x) };
            let x0floor = x0.floor();
            let x0i = x0floor as i32;
            let x1ceil = x1.ceil();
            let x1i = x1ceil as i32;
            let linestart_x0i = linestart as isize + x0i as isize;
            if linestart_x0i < 0 {
                continue;
            }
            if x1i <= x0i + 1 {
                let xmf = 0.5 * (x + xnext) - x0floor;
                add!(linestart_x0i as usize, d - d * xmf);
                add!(linestart_x0i as usize + 1, d * xmf);
            } else {
                let s = (x1 - x0).recip();
                let x0f = x0 - x0floor;
                let a0 = 0.5 * s * (1.0 - x0f) * (1.0 - x0f);
                let x1f = x1 - x1ceil + 1.0;
                let am = 0.5 * s * x1f * x1f;
                add!(linestart_x0i as usize, d * a0);
                if x1i == x0i + 2 {
                    add!(linestart_x0i as usize + 1, d * (1.0 - a0 - am));
                } else {
                    let a1 = s * (1.5 - x0f);
                    add!(linestart_x0i as usize + 1, d * (a1 - a0));
                    for xi in x0i + 2..x1i - 1 {
                        add!(index(linestart, xi)?, d * s);
                    }
                    let a2 = a1 + (x1i - x0i - 3) as f32 * s;
                    add!(index(linestart, x1i - 1)?, d * (1.0 - a2 - am));
                }
                add!(index(linestart, x1i)?, d * am);
            }
            x = xnext;
        }
        Ok(())
    }

    /// `Rasterizer::for_each_pixel`: one running f32 sum over the first `width x height`
    /// cells, each pixel handed its absolute value.
    fn for_each_pixel(&self, mut px_fn: impl FnMut(usize, f32)) {
        let mut acc = 0.0f32;
        for (idx, c) in self.a[..self.width * self.height].iter().enumerate() {
            acc += c;
            px_fn(idx, acc.abs());
        }
    }
}

/// The columns the widened rasterizer holds: `lo..hi`, the canvas's and every point's.
fn columns(shapes: &[AreaShape], width: u32) -> Result<(i64, i64), String> {
    let (mut lo, mut hi) = (0i64, i64::from(width));
    for (k, shape) in shapes.iter().enumerate() {
        for p in shape.contours().flatten() {
            match (p.x.floor().to_integer().to_i64(), p.x.ceil().to_integer().to_i64()) {
                (Some(f), Some(c)) => (lo, hi) = (lo.min(f), hi.max(c)),
                _ => return Err(format!("shape {k}: a point at x = {}: beyond any f32 rasterizer", p.x)),
            }
        }
    }
    Ok((lo, hi))
}

/// The shapes as the ab_glyph adapter draws them with ab_glyph_rasterizer 0.1.10 (see the
/// module documentation): one widened `Rasterizer`, every edge drawn with `draw_line`, the
/// canvas's columns of `for_each_pixel`'s values, row-major (`width x height`): each the
/// absolute running sum, unclamped.
///
/// # Errors
/// What the module documentation lists as refused: an even-odd shape, a coordinate that
/// is not an f32, a widened buffer of more than 2^28 cells; and the index overflow at
/// which the crate panics (which the widening rules out but for f32 extrapolation error).
pub fn rasterize(shapes: &[AreaShape], width: u32, height: u32) -> Result<Vec<f32>, String> {
    if let Some(k) = shapes.iter().position(|s| s.fill_rule == FillRule::EvenOdd) {
        return Err(format!(
            "shape {k}: an even-odd shape: refused, ab_glyph_rasterizer has no fill rule (it accumulates signed \
             area: nonzero, as |sum|, unclamped)"
        ));
    }
    let (lo, hi) = columns(shapes, width)?;
    let wide = hi - lo;
    let cells = u64::try_from(wide)
        .unwrap_or(u64::MAX)
        .saturating_mul(u64::from(height));
    if cells > MAX_CELLS {
        return Err(format!(
            "the shapes span columns {lo}..{hi}: a rasterizer of {wide} x {height} cells (more than 2^28) is refused"
        ));
    }
    let shift = BigRational::from_integer((-lo).into());
    let w = usize::try_from(wide).map_err(|_| "internal: a negative width".to_string())?;
    let mut rasterizer = Rasterizer::new(w, height as usize);
    for (k, shape) in shapes.iter().enumerate() {
        for contour in shape.contours() {
            let mut points = Vec::with_capacity(contour.len());
            for p in contour {
                let moved = Point::new(&p.x + &shift, p.y.clone());
                let v = moved
                    .to_f32()
                    .ok_or_else(|| format!("shape {k}: {moved} does not fit f32 (ab_glyph's coordinate type)"))?;
                points.push([v.x, v.y]);
            }
            for (i, &a) in points.iter().enumerate() {
                rasterizer.draw_line(a, points[(i + 1) % points.len()])?;
            }
        }
    }
    let x0 = usize::try_from(-lo).map_err(|_| "internal: a positive left column".to_string())?;
    let canvas = width as usize;
    let mut out = vec![0f32; canvas * height as usize];
    rasterizer.for_each_pixel(|index, a| {
        let (x, y) = (index % w, index / w);
        if x >= x0 && x - x0 < canvas {
            out[y * canvas + x - x0] = a;
        }
    });
    Ok(out)
}

/// The adapter's 16-bit level of ab_glyph's value `a`: `round(min(max(a, 0), 1) x
/// 65535)`, ties to even (exact: an f32 times 65535 needs at most 40 of an f64's 53 bits).
#[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
pub fn level(a: f32) -> u16 {
    (f64::from(a.clamp(0.0, 1.0)) * 65535.0).round_ties_even() as u16
}

/// The adapter's 16-bit levels of the shapes ([`rasterize`], then [`level`]), row-major.
///
/// # Errors
/// As [`rasterize`].
pub fn levels(shapes: &[AreaShape], width: u32, height: u32) -> Result<Vec<u16>, String> {
    Ok(rasterize(shapes, width, height)?.into_iter().map(level).collect())
}
