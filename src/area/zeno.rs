//! zeno 0.3.3's mask rasterizer (the crate `zeno`, `src/raster.rs` and `src/mask.rs`) as
//! the zeno adapter (`adapters/zeno/main.rs`) calls it, a contender: a model of its
//! integers that gives its 8-bit levels exactly.
//!
//! What the adapter does: every contour of the scene, shapes in id order, each its outline
//! then its holes, into **one** path (`MoveTo` the first point, `LineTo` the others,
//! `Close`), filled by `Mask::new(&path).size(width, height).style(fill).render()` under
//! the scene's one rule. Read from zeno's source, that is FreeType's smooth rasterizer
//! (`ftgrays.c`, whose integer method [`super::ftgrays`] models) with these departures:
//!
//! - **y down**: zeno's `Origin::TopLeft` grid is the canvas's, nothing is flipped, cell
//!   row `r` is canvas row `r`. FreeType's `~` on a negative value (one level below
//!   `-v`) therefore lands on the other orientation of the contours;
//! - **no 26.6 rounding**: each coordinate is rounded once to the nearest f32 (the
//!   adapter's `Point::to_f32`), then `to_fixed` takes `(v x 256).to_int_unchecked()`:
//!   the f32 product (exact: a power of two) truncated towards zero, straight to 24.8;
//! - **the 32-bit reciprocal**: `line_to` prepares `0x00FFFFFF / d` (i32, truncated
//!   towards zero) where FreeType prepares `(2^56 - 1) / d`, and divides by
//!   `(a as u64 x r as u64) >> 24` where FreeType shifts by 56. An exit point can fall
//!   short of the floor by one unit of 1/256 px (two or more for `|d|` past 2^16 units,
//!   256 px, where the reciprocal keeps few bits);
//! - **one pass**: the whole path's cells are summed, then swept once; the levels are
//!   written, not added;
//! - the same walk (`prod`, the four exits, the pieces' cover and area) and the same
//!   sweep (`cover x 512 - area`, shifted right by 9); the level's fold (its
//!   `coverage`) complements a negative value only under nonzero, where FreeType's
//!   `gray_hline` complements under both rules: under even-odd `v & 511` reflected above
//!   255 is the same level either way, so [`super::ftgrays`]'s fold is shared;
//! - cells left of the canvas are merged into column -1 (their cover alone is read),
//!   cells right of it and outside its rows are dropped, an edge wholly above or below
//!   the rows is skipped: none of it changes a level on the canvas, so the model keeps
//!   every cell and lets the sweep read the canvas's, as [`super::ftgrays`] does.
//!
//! The walk and the sweep are [`super::ftgrays`]'s (`add_edge`, `sweep`, `level`), with
//! zeno's reciprocal and frame.
//!
//! **Range envelope.** zeno computes in i32 (and `to_int_unchecked` is undefined past the
//! i32 range): the model takes, as the adapter does, coordinates whose nearest f32 is
//! below 4096 px in magnitude, so a 24.8 coordinate is below 2^20 and every value of the
//! walk (`prod`, its four corner tests, `d x 256`) is at most `256 (|dx| + |dy|) < 2^30`;
//! a path of fewer than 2^14 edges, so that a cell's sum of pieces (each at most `256 x
//! 512 = 2^17`) stays within i32 too; a canvas of fewer than 2^32 pixels (zeno sizes its
//! buffer in u32) and sides below 2^31. Every row value the sweep reads is checked to lie
//! within i32 (zeno's wrapping sums then equal the model's exact ones).
//!
//! **Refused** (an error naming the reason): a scene that mixes nonzero and even-odd shapes
//! (one path has one rule; triangles are nonzero), a coordinate at or beyond 4096 px (or
//! not an f32 at all), a path of 2^14 edges or more, a canvas beyond the envelope.
//! Lines, clip windows and clip-space triangles are the adapter's to refuse: the model
//! takes the shapes of a scene that has none.

use super::ftgrays::{add_edge, level, sweep, Cells, Reciprocal, PIXEL_BITS};
use super::AreaShape;
use crate::geom::FillRule;

/// The largest coordinate magnitude (exclusive), in px, as the adapter's `LIMIT`.
pub const LIMIT: f32 = 4096.0;

/// The most edges a path may have (exclusive).
pub const MAX_EDGES: usize = 1 << 14;

/// zeno's 32-bit division by multiplication (`line_to`'s `dx_r`, `dy_r` and `udiv`).
struct Zeno32;

impl Reciprocal for Zeno32 {
    /// `0x00FFFFFF / d` in i32, truncated towards zero.
    fn prepare(d: i64) -> i64 {
        0x00FF_FFFF / d
    }

    /// `((a as u64 * r as u64) >> 24) as i32`: `a` and `r` are i32 there, sign-extended to
    /// u64 (both non-negative on every path of the walk, the product below 2^54).
    #[allow(clippy::cast_sign_loss, clippy::cast_possible_truncation)]
    fn divide(a: i64, r: i64) -> i64 {
        i64::from(((a as u64).wrapping_mul(r as u64) >> (32 - PIXEL_BITS)) as i32)
    }
}

/// zeno's `to_fixed`: `(v x 256)` in f32, truncated towards zero (`|v| < 4096`, so the
/// product is exact and below 2^20).
#[allow(clippy::cast_possible_truncation)]
fn to_fixed(v: f32) -> i64 {
    i64::from((v * 256.0).trunc() as i32)
}

/// The scene's one fill rule: the shapes' common rule (nonzero when there are none).
fn one_rule(shapes: &[AreaShape]) -> Result<FillRule, String> {
    let has = |rule| shapes.iter().any(|s| s.fill_rule == rule);
    match (has(FillRule::NonZero), has(FillRule::EvenOdd)) {
        (true, true) => Err(
            "the shapes mix nonzero (triangles or polygons) and even-odd polygons: refused, zeno fills one path \
             under one rule"
                .into(),
        ),
        (false, true) => Ok(FillRule::EvenOdd),
        _ => Ok(FillRule::NonZero),
    }
}

/// The shapes as the zeno adapter draws them with zeno 0.3.3: every contour in one path,
/// filled under the shapes' one rule; zeno's 8-bit levels, row-major (`width x height`).
///
/// # Errors
/// What the module documentation lists as refused: mixed fill rules, a coordinate of 4096
/// px or more (or beyond f32), a path of 2^14 edges or more, a canvas of 2^32 pixels or
/// more or a side of 2^31; a row value beyond i32 (which the envelope rules out).
pub fn rasterize(shapes: &[AreaShape], width: u32, height: u32) -> Result<Vec<u8>, String> {
    let rule = one_rule(shapes)?;
    if u64::from(width) * u64::from(height) >= 1 << 32 || width >= 1 << 31 || height >= 1 << 31 {
        return Err(format!(
            "a {width}x{height} canvas: refused, zeno's mask holds fewer than 2^32 pixels"
        ));
    }
    let edges: usize = shapes.iter().flat_map(AreaShape::contours).map(<[_]>::len).sum();
    if edges >= MAX_EDGES {
        return Err(format!(
            "{edges} edges in one path: refused, the model keeps zeno's i32 sums exact below 2^14 edges"
        ));
    }
    let mut cells = Cells::new();
    for (k, shape) in shapes.iter().enumerate() {
        for contour in shape.contours() {
            let mut points = Vec::with_capacity(contour.len());
            for p in contour {
                let v = p
                    .to_f32()
                    .filter(|v| v.x.abs() < LIMIT && v.y.abs() < LIMIT)
                    .ok_or_else(|| {
                        format!("shape {k}: {p}: refused, zeno's i32 edge walk takes coordinates within ±{LIMIT} px")
                    })?;
                points.push((to_fixed(v.x), to_fixed(v.y)));
            }
            for i in 0..points.len() {
                add_edge::<Zeno32>(&mut cells, points[i], points[(i + 1) % points.len()]);
            }
        }
    }
    let (w, h) = (i64::from(width), i64::from(height));
    let mut out = vec![0u8; width as usize * height as usize];
    let mut beyond = None;
    sweep(&cells, w, |row, x, v| {
        if !(0..h).contains(&row) {
            return;
        }
        if i32::try_from(v).is_err() {
            beyond = Some((x, row, v));
        }
        if let Ok(k) = usize::try_from(row * w + x) {
            out[k] = level(v, rule);
        }
    });
    match beyond {
        Some((x, y, v)) => Err(format!(
            "pixel ({x}, {y}): the row value {v} is beyond zeno's i32 sums: refused"
        )),
        None => Ok(out),
    }
}
