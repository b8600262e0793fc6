//! FreeType's smooth rasterizer's method (`src/smooth/ftgrays.c`), a contender, in
//! integers: its numbers, not its code.
//!
//! - The outline's points are in 26.6 fixed point (1/64 px), in FreeType's frame: y up,
//!   so the canvas is flipped (`y' = height - y`, exactly) and then each coordinate
//!   rounded to the nearest 1/64, ties away from zero, as the FreeType adapter
//!   (`adapters/freetype/render.py`) writes them; upscaled to 24.8 (`PIXEL_BITS = 8`).
//!   FreeType's row `r'` is our row `height - 1 - r'`.
//! - Each edge is walked cell by cell as `gray_render_line` walks it (its 64-bit form):
//!   the exact integer `prod = dx fy1 - dy fx1` decides through which side the edge
//!   leaves the cell, and the exit point's other coordinate is a division done as FreeType
//!   does it, by a multiplication with the reciprocal `(2^56 - 1) / d` and a shift right
//!   by 56 (`FT_UDIVPREP`, `FT_UDIV`), which can fall one unit of 1/256 px short of the
//!   floor. A piece from `(fx1, fy1)` to `(fx2, fy2)` within its cell (local 24.8
//!   coordinates, 0..=256) adds `fy2 - fy1` to the cell's cover and
//!   `(fy2 - fy1) (fx1 + fx2)` to its area.
//! - Each row swept left to right: a cell's value is `cover_sum x 512 - area` (the
//!   covers of the cells left of it and its own), shifted right by 9 (floor) to the
//!   0..=256 range; a negative value is complemented (`~v`, that is `-v - 1`); nonzero
//!   clamps 256 to 255, even-odd keeps the value modulo 512 and reflects it above 255
//!   (`511 - v`). Cells left of the canvas carry their cover into the row.
//!
//! It departs from the exact area by the 1/64 px rounding of the points, the reciprocal
//! divisions and the truncation to 8 bits (and the asymmetry of `~` on negative values).
//! Its levels equal FreeType 2.12.1's (Debian 12's libfreetype6) through the adapter,
//! pixel for pixel: `tests/adapters.rs` checks it on every run where the library is
//! installed.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive};

use super::AreaShape;
use crate::geom::{FillRule, Point, Polygon};

/// Subpixel bits of a cell coordinate (24.8).
pub(super) const PIXEL_BITS: u32 = 8;
/// One pixel in cell units.
pub(super) const ONE_PIXEL: i64 = 1 << PIXEL_BITS;
/// The envelope: a 24.8 coordinate lies within `±2^31`, so `|v| < 2^23` px.
const LIMIT: i64 = 1 << 31;

/// `v` in 24.8 as FreeType holds it: rounded to 26.6 (nearest, ties away from zero), then
/// shifted up by 2; `None` outside the envelope.
fn to_24_8(v: &BigRational) -> Option<i64> {
    let scaled = v * BigRational::from_integer(BigInt::from(64));
    let rounded = scaled.round().to_integer().to_i64()?;
    let out = rounded.checked_mul(4)?;
    (out.abs() < LIMIT).then_some(out)
}

/// The cells of a path: `(row, column) -> (cover, area)`, in the walk's frame (FreeType's,
/// y up, here; zeno's, y down, in [`super::zeno`]).
pub(super) type Cells = std::collections::BTreeMap<(i64, i64), (i64, i64)>;

/// How the walk divides: a reciprocal prepared once per edge and coordinate, then a
/// multiplication and a shift per exit point (FreeType's `FT_UDIVPREP` and `FT_UDIV`).
/// FreeType's 64-bit form is [`FreeType64`]; zeno's 32-bit form is in [`super::zeno`].
pub(super) trait Reciprocal {
    /// The reciprocal for repeated division by `d` (not zero).
    fn prepare(d: i64) -> i64;
    /// `a` divided by the `d` that `r` was prepared for (`a >= 0`, `r >= 0` on every path
    /// of the walk).
    fn divide(a: i64, r: i64) -> i64;
}

/// FreeType's 64-bit division by multiplication.
pub(super) struct FreeType64;

impl Reciprocal for FreeType64 {
    /// `FT_UDIVPREP`: `(2^56 - 1) / d`, truncated towards zero (`2^64 - 1` shifted right by
    /// `PIXEL_BITS`, over a signed `d`).
    fn prepare(d: i64) -> i64 {
        ((1i64 << (64 - PIXEL_BITS)) - 1) / d
    }

    /// `FT_UDIV`: `a x r` in 64-bit unsigned arithmetic (wrapping, as C's `unsigned long`
    /// does), shifted right by `64 - PIXEL_BITS`.
    #[allow(clippy::cast_sign_loss, clippy::cast_possible_wrap)]
    fn divide(a: i64, r: i64) -> i64 {
        ((a as u64).wrapping_mul(r as u64) >> (64 - PIXEL_BITS)) as i64
    }
}

/// The current cell of the walk, its cover and area, as FreeType's worker holds them.
struct Walker<'a> {
    cells: &'a mut Cells,
    ex: i64,
    ey: i64,
    cover: i64,
    area: i64,
}

impl Walker<'_> {
    /// Records the current cell's cover and area and moves to `(ex, ey)`.
    fn set_cell(&mut self, ex: i64, ey: i64) {
        if self.cover != 0 || self.area != 0 {
            let cell = self.cells.entry((self.ey, self.ex)).or_insert((0, 0));
            cell.0 += self.cover;
            cell.1 += self.area;
        }
        (self.ex, self.ey, self.cover, self.area) = (ex, ey, 0, 0);
    }
}

/// Walks the edge `(x1, y1) -> (x2, y2)` (24.8) through the cells as FreeType's
/// `gray_render_line` does (the 64-bit form; zeno's `line_to` is the same walk): from the
/// cell of the start, one step per cell boundary crossed, the side of the exit decided by
/// the exact integer `prod = dx fy1 - dy fx1` (the start's local position against the
/// edge's direction), the exit point's other coordinate by `R`'s reciprocal division
/// (the reciprocal of `dx` prepared only when the edge changes column, of `dy` only when
/// it changes row, as `FT_UDIVPREP( ex1 != ex2, dx )` does); each piece adds `fy2 - fy1`
/// to its cell's cover and `(fy2 - fy1) (fx1 + fx2)` to its area.
pub(super) fn add_edge<R: Reciprocal>(cells: &mut Cells, (x1, y1): (i64, i64), (x2, y2): (i64, i64)) {
    let one = ONE_PIXEL;
    let (mut ex1, ex2) = (x1 >> PIXEL_BITS, x2 >> PIXEL_BITS);
    let (mut ey1, ey2) = (y1 >> PIXEL_BITS, y2 >> PIXEL_BITS);
    let mut w = Walker {
        cells,
        ex: ex1,
        ey: ey1,
        cover: 0,
        area: 0,
    };
    let (dx, dy) = (x2 - x1, y2 - y1);
    let (mut fx1, mut fy1) = (x1 - ex1 * one, y1 - ey1 * one);
    if ex1 == ex2 && ey1 == ey2 {
        // Inside one cell: only the last piece.
    } else if dy == 0 {
        ex1 = ex2;
        w.set_cell(ex1, ey1);
    } else if dx == 0 {
        let (to, from, step) = if dy > 0 { (one, 0, 1) } else { (0, one, -1) };
        while ey1 != ey2 {
            w.cover += to - fy1;
            w.area += (to - fy1) * fx1 * 2;
            fy1 = from;
            ey1 += step;
            w.set_cell(ex1, ey1);
        }
    } else {
        let mut prod = dx * fy1 - dy * fx1;
        let rx = if ex1 == ex2 { 0 } else { R::prepare(dx) };
        let ry = if ey1 == ey2 { 0 } else { R::prepare(dy) };
        loop {
            let (fx2, fy2);
            if prod <= 0 && prod - dx * one > 0 {
                // Out through the left side.
                fx2 = 0;
                fy2 = R::divide(-prod, -rx);
                prod -= dy * one;
                (w.cover, w.area) = (w.cover + fy2 - fy1, w.area + (fy2 - fy1) * (fx1 + fx2));
                (fx1, fy1) = (one, fy2);
                ex1 -= 1;
            } else if prod - dx * one <= 0 && prod - dx * one + dy * one > 0 {
                // Out through the side of greater y (the top in FreeType's frame).
                prod -= dx * one;
                fx2 = R::divide(-prod, ry);
                fy2 = one;
                (w.cover, w.area) = (w.cover + fy2 - fy1, w.area + (fy2 - fy1) * (fx1 + fx2));
                (fx1, fy1) = (fx2, 0);
                ey1 += 1;
            } else if prod - dx * one + dy * one <= 0 && prod + dy * one >= 0 {
                // Out through the right side.
                prod += dy * one;
                fx2 = one;
                fy2 = R::divide(prod, rx);
                (w.cover, w.area) = (w.cover + fy2 - fy1, w.area + (fy2 - fy1) * (fx1 + fx2));
                (fx1, fy1) = (0, fy2);
                ex1 += 1;
            } else {
                // Out through the side of smaller y.
                fx2 = R::divide(prod, -ry);
                fy2 = 0;
                prod += dx * one;
                (w.cover, w.area) = (w.cover + fy2 - fy1, w.area + (fy2 - fy1) * (fx1 + fx2));
                (fx1, fy1) = (fx2, one);
                ey1 -= 1;
            }
            w.set_cell(ex1, ey1);
            if ex1 == ex2 && ey1 == ey2 {
                break;
            }
        }
    }
    let (fx2, fy2) = (x2 - ex2 * one, y2 - ey2 * one);
    w.cover += fy2 - fy1;
    w.area += (fy2 - fy1) * (fx1 + fx2);
    w.set_cell(ex2, ey2);
}

/// The shapes as FreeType's smooth rasterizer draws them, each in its own pass (its own
/// cells and sweep) with the 8-bit levels of the passes added, saturating (a renderer
/// compositing the glyphs additively): row-major levels.
///
/// # Errors
/// A coordinate outside the 24.8 envelope (|v| >= 2^23 px), named with its shape.
pub fn rasterize(shapes: &[AreaShape], width: u32, height: u32) -> Result<Vec<u8>, String> {
    let (w, h) = (i64::from(width), i64::from(height));
    let mut out = vec![0u8; width as usize * height as usize];
    for (k, shape) in shapes.iter().enumerate() {
        let mut cells = Cells::new();
        for contour in shape.contours() {
            let mut points = Vec::with_capacity(contour.len());
            for p in contour {
                let flipped = BigRational::from_integer(h.into()) - &p.y;
                let (Some(x), Some(y)) = (to_24_8(&p.x), to_24_8(&flipped)) else {
                    return Err(format!(
                        "shape {k}: ({}, {}) is outside FreeType's 24.8 envelope (|v| < 2^23 px)",
                        p.x, p.y
                    ));
                };
                // FreeType's frame: y up.
                points.push((x, y));
            }
            for i in 0..points.len() {
                add_edge::<FreeType64>(&mut cells, points[i], points[(i + 1) % points.len()]);
            }
        }
        sweep_into(&cells, shape.fill_rule, w, h, &mut out);
    }
    Ok(out)
}

/// Sweeps the cells row by row into `out` (our rows: FreeType's row `r'` is `h - 1 - r'`),
/// adding each pass's levels, saturating.
fn sweep_into(cells: &Cells, rule: FillRule, w: i64, h: i64, out: &mut [u8]) {
    sweep(cells, w, |row_ft, x, v| {
        let y = h - 1 - row_ft;
        if let (true, Ok(k)) = ((0..h).contains(&y), usize::try_from(y * w + x)) {
            out[k] = out[k].saturating_add(level(v, rule));
        }
    });
}

/// The level of a cell's value `v` (`cover_sum x 512 - area`, FreeType's `gray_hline`):
/// shifted right by 9 (floor) to the 0..=256 range, a negative value complemented (`~v`,
/// that is `-v - 1`); nonzero clamps 256 to 255, even-odd keeps the value modulo 512 and
/// reflects it above 255 (`511 - v`). zeno's `coverage` complements only under nonzero:
/// under even-odd its `v & 511` reflected is the same level (reflection maps `v mod 512`
/// and `~v mod 512 = 511 - v mod 512` to one value).
pub(super) fn level(v: i64, rule: FillRule) -> u8 {
    let mut c = v >> (PIXEL_BITS * 2 + 1 - 8);
    if c < 0 {
        c = !c;
    }
    let c = match rule {
        FillRule::EvenOdd => {
            c &= 511;
            if c >= 256 {
                511 - c
            } else {
                c
            }
        }
        FillRule::NonZero => c.min(255),
    };
    u8::try_from(c).unwrap_or(u8::MAX)
}

/// Sweeps the cells row by row, each row left to right as `gray_sweep` and `gray_hline`
/// do: `emit(row, x, v)` for each column `x` in `0..w` the row's cells reach, `v` the
/// value `cover_sum x 512 - area` (the covers of the cells left of it and its own) at a
/// cell, `cover_sum x 512` between cells where `cover_sum` is not zero. Cells left of the
/// canvas carry their cover into the row; nothing is emitted right of the last cell (a
/// closed path's covers add up to zero across a row).
pub(super) fn sweep(cells: &Cells, w: i64, mut emit: impl FnMut(i64, i64, i64)) {
    let mut rows = cells.iter().peekable();
    while let Some(&(&(row, _), _)) = rows.peek() {
        let mut cover = 0i64;
        let mut x = i64::MIN;
        while let Some(((_, column), &(c, a))) = rows.next_if(|((r, _), _)| *r == row) {
            if cover != 0 && x != i64::MIN {
                for between in x.max(0)..(*column).min(w) {
                    emit(row, between, cover * (ONE_PIXEL * 2));
                }
            }
            cover += c;
            if (0..w).contains(column) {
                emit(row, *column, cover * (ONE_PIXEL * 2) - a);
            }
            x = column + 1;
        }
    }
}

/// [`rasterize`] on the window at `(origin, origin)` of the placed shapes: each placed
/// coordinate `x + origin` rounded to 26.6 as the model rounds it (nearest 1/64, ties away
/// from zero) and checked against its 24.8 envelope (`|v| < 2^23` px) there; the model
/// then runs on the window's canvas with the rounded coordinates moved back by
/// `-origin`, a whole number of cells: its walk uses only cell indices (moved by whole
/// numbers), cell-local offsets and differences (unchanged), so its levels are those of
/// the placed walk. y needs no moving: the model's frame is flipped about the canvas's
/// bottom (`y' = H - y`), and on a canvas reaching the window, `H = origin + height`, so
/// `y'` is the window's own. Equal to the model on such a canvas, restricted to the
/// window (tested at 2^10).
///
/// # Errors
/// A placed coordinate outside the 24.8 envelope, named with its shape (the model's own
/// message).
pub fn rasterize_at(shapes: &[AreaShape], origin: i64, width: u32, height: u32) -> Result<Vec<u8>, String> {
    let m = BigRational::from_integer(origin.into());
    let sixty_four = BigRational::from_integer(64.into());
    let limit = BigInt::from(1i64 << 31);
    let mut local = Vec::with_capacity(shapes.len());
    for (k, shape) in shapes.iter().enumerate() {
        let mut bad = None;
        let mut mv = |c: &[Point]| -> Vec<Point> {
            c.iter()
                .map(|p| {
                    let placed = &p.x + &m;
                    // round(): to the nearest, ties away from zero, as the model's to_24_8.
                    let units = (&placed * &sixty_four).round().to_integer();
                    if (&units * BigInt::from(4)).abs() >= limit {
                        bad.get_or_insert_with(|| (placed.clone(), &p.y + &m));
                    }
                    Point::new(BigRational::new(units, 64.into()) - &m, p.y.clone())
                })
                .collect()
        };
        let moved = Polygon {
            outline: mv(&shape.outline),
            holes: shape.holes.iter().map(|h| mv(h)).collect(),
            fill_rule: shape.fill_rule,
        };
        if let Some((x, y)) = bad {
            return Err(format!(
                "shape {k}: ({x}, {y}) is outside FreeType's 24.8 envelope (|v| < 2^23 px)"
            ));
        }
        local.push(moved);
    }
    rasterize(&local, width, height)
}
