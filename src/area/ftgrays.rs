//! FreeType's smooth rasterizer's method (`src/smooth/ftgrays.c`), a contender, in
//! integers: its numbers, not its code.
//!
//! - The outline's points are in 26.6 fixed point (1/64 px; each coordinate rounded to the
//!   nearest, ties away from zero, as an adapter handing our scene to FreeType writes
//!   them), upscaled to 24.8 (`PIXEL_BITS = 8`), in FreeType's frame: y up, so the canvas
//!   is flipped (`y' = height - y`) and row `r'` is our row `height - 1 - r'`.
//! - Each edge is cut at every cell (pixel) boundary it crosses, each crossing point's
//!   other coordinate taken by floor division; a piece from `(fx1, fy1)` to `(fx2, fy2)`
//!   within its cell (local 24.8 coordinates, 0..=256) adds `fy2 - fy1` to the cell's
//!   cover and `(fy2 - fy1) (fx1 + fx2)` to its area.
//! - Each row swept left to right: a cell's value is `cover_sum x 512 - area` (the
//!   covers of the cells left of it and its own), shifted right by 9 (floor) to the
//!   0..=256 range; a negative value is complemented (`~v`, that is `-v - 1`); nonzero
//!   clamps 256 to 255, even-odd keeps the value modulo 512 and reflects it above 255
//!   (`511 - v`). Cells left of the canvas carry their cover into the row.
//!
//! It departs from the exact area by the 1/64 px rounding of the points, the floor
//! divisions and the truncation to 8 bits (and the asymmetry of `~` on negative values).
//! FreeType computes the crossing points with a reciprocal multiplication where this
//! takes the exact floor; both are within one unit of 1/256 px.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;

use super::AreaShape;
use crate::geom::FillRule;

/// Subpixel bits of a cell coordinate (24.8).
const PIXEL_BITS: u32 = 8;
/// One pixel in cell units.
const ONE_PIXEL: i64 = 1 << PIXEL_BITS;
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

/// Floor division.
fn floor_div(a: i64, b: i64) -> i64 {
    a.div_euclid(b) - i64::from(b < 0 && a.rem_euclid(b) != 0)
}

/// The cells of one shape: `(row, column) -> (cover, area)`, in FreeType's frame.
type Cells = std::collections::BTreeMap<(i64, i64), (i64, i64)>;

/// Adds one piece within cell `(ex, ey)`, from `(x1, y1)` to `(x2, y2)` (24.8, absolute).
fn add_piece(cells: &mut Cells, ex: i64, ey: i64, (x1, y1): (i64, i64), (x2, y2): (i64, i64)) {
    let dy = y2 - y1;
    if dy == 0 {
        return;
    }
    let (fx1, fx2) = (x1 - ex * ONE_PIXEL, x2 - ex * ONE_PIXEL);
    let cell = cells.entry((ey, ex)).or_insert((0, 0));
    cell.0 += dy;
    cell.1 += dy * (fx1 + fx2);
}

/// `from`, every cell boundary (a multiple of `ONE_PIXEL`) strictly between `from` and
/// `to` in the order of travel, and `to`.
fn boundaries(from: i64, to: i64) -> Vec<i64> {
    let (lo, hi) = (from.min(to), from.max(to));
    let mut out = vec![from];
    let mut k = floor_div(lo, ONE_PIXEL) + 1;
    while k * ONE_PIXEL < hi {
        out.push(k * ONE_PIXEL);
        k += 1;
    }
    if to < from {
        out[1..].reverse();
    }
    out.push(to);
    out
}

/// Walks the edge `(x1, y1) -> (x2, y2)` (24.8) through the cells, row by row and, within a
/// row, column by column.
fn add_edge(cells: &mut Cells, (x1, y1): (i64, i64), (x2, y2): (i64, i64)) {
    if y1 == y2 {
        return;
    }
    let (dx, dy) = (x2 - x1, y2 - y1);
    let x_at = |y: i64| x1 + floor_div((y - y1) * dx, dy);
    let ys = boundaries(y1, y2);
    for w in ys.windows(2) {
        let (ya, yb) = (w[0], w[1]);
        let ey = floor_div(ya.min(yb), ONE_PIXEL);
        let xa = if ya == y1 { x1 } else { x_at(ya) };
        let xb = if yb == y2 { x2 } else { x_at(yb) };
        let xs = boundaries(xa, xb);
        let mut from = (xa, ya);
        for pair in xs.windows(2) {
            let xe = pair[1];
            let to = if xe == xb {
                (xb, yb)
            } else {
                (xe, ya + floor_div((xe - xa) * (yb - ya), xb - xa))
            };
            let ex = floor_div(from.0.min(to.0), ONE_PIXEL);
            add_piece(cells, ex, ey, from, to);
            from = to;
        }
    }
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
                let (Some(x), Some(y)) = (to_24_8(&p.x), to_24_8(&p.y)) else {
                    return Err(format!(
                        "shape {k}: ({}, {}) is outside FreeType's 24.8 envelope (|v| < 2^23 px)",
                        p.x, p.y
                    ));
                };
                // FreeType's frame: y up.
                points.push((x, h * ONE_PIXEL - y));
            }
            for i in 0..points.len() {
                add_edge(&mut cells, points[i], points[(i + 1) % points.len()]);
            }
        }
        sweep(&cells, shape.fill_rule, w, h, &mut out);
    }
    Ok(out)
}

/// Sweeps the cells row by row into `out` (our rows: FreeType's row `r'` is `h - 1 - r'`).
fn sweep(cells: &Cells, rule: FillRule, w: i64, h: i64, out: &mut [u8]) {
    let level = |v: i64| -> i64 {
        let mut c = v >> (PIXEL_BITS * 2 + 1 - 8);
        if c < 0 {
            c = !c;
        }
        match rule {
            FillRule::EvenOdd => {
                c &= 511;
                if c >= 256 {
                    511 - c
                } else {
                    c
                }
            }
            FillRule::NonZero => c.min(255),
        }
    };
    let mut put = |x: i64, row_ft: i64, v: i64| {
        let y = h - 1 - row_ft;
        if let (true, Ok(k)) = ((0..w).contains(&x) && (0..h).contains(&y), usize::try_from(y * w + x)) {
            out[k] = out[k].saturating_add(u8::try_from(level(v)).unwrap_or(u8::MAX));
        }
    };
    let mut rows = cells.iter().peekable();
    while let Some((&(row, _), _)) = rows.peek() {
        let mut cover = 0i64;
        let mut x = i64::MIN;
        while let Some(((_, column), &(c, a))) = rows.next_if(|((r, _), _)| *r == row) {
            if cover != 0 && x != i64::MIN {
                for between in x.max(0)..(*column).min(w) {
                    put(between, row, cover * (ONE_PIXEL * 2));
                }
            }
            cover += c;
            put(*column, row, cover * (ONE_PIXEL * 2) - a);
            x = column + 1;
        }
        // A closed path's covers add up to zero across a row: nothing is left to its right.
    }
}
