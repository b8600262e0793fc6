//! Triangle rasterizers, one file per numeric model, each with the same shape:
//! `rasterize(triangle, id, &Target, &mut sink)`, the triangle in the model's own input
//! form (exact [`crate::geom::Triangle`], fixed [`crate::geom::FixedTriangle`], glam
//! vectors for float). [`crate::model`] converts a scene's exact triangles for each.

pub mod exact;
pub mod fixed;
pub mod float;
pub mod scanline;

use num_bigint::BigInt;
use num_rational::BigRational;

use crate::convention::Target;
use crate::geom::Point;

/// A pixel index from an exact integer, saturating by sign: anything beyond i64 is far off
/// any canvas either way, on the side its sign says.
pub(crate) fn saturating_index(v: num_bigint::BigInt) -> i64 {
    use num_traits::ToPrimitive;
    v.to_i64().unwrap_or(if v.sign() == num_bigint::Sign::Minus {
        i64::MIN
    } else {
        i64::MAX
    })
}

/// An inclusive rectangle of pixels `x0..=x1`, `y0..=y1` on the canvas.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PixelRange {
    /// First column.
    pub x0: u32,
    /// Last column.
    pub x1: u32,
    /// First row.
    pub y0: u32,
    /// Last row.
    pub y1: u32,
}

impl PixelRange {
    /// The pixels whose sample index lies in `[lo, hi]` on each axis (already rounded
    /// inwards to integers), clamped to a `width` x `height` canvas; `None` when empty.
    pub fn clamped(lo: [i64; 2], hi: [i64; 2], width: u32, height: u32) -> Option<PixelRange> {
        let clamp = |v: i64, side: u32| -> i64 { v.clamp(0, i64::from(side) - 1) };
        if hi[0] < 0 || hi[1] < 0 || lo[0] >= i64::from(width) || lo[1] >= i64::from(height) {
            return None;
        }
        if lo[0] > hi[0] || lo[1] > hi[1] {
            return None;
        }
        let to_u32 = |v: i64| u32::try_from(v).expect("clamped to the canvas");
        Some(PixelRange {
            x0: to_u32(clamp(lo[0], width)),
            x1: to_u32(clamp(hi[0], width)),
            y0: to_u32(clamp(lo[1], height)),
            y1: to_u32(clamp(hi[1], height)),
        })
    }
}

/// The exact sample coordinate of pixel index `i`: `i + centre`.
pub(crate) fn sample_coordinate(i: u32, centre: &BigRational) -> BigRational {
    BigRational::from_integer(BigInt::from(i)) + centre
}

/// The exact sample of pixel `(x, y)`: `(x + centre, y + centre)`.
pub(crate) fn sample_point(x: u32, y: u32, centre: &BigRational) -> Point {
    Point::new(sample_coordinate(x, centre), sample_coordinate(y, centre))
}

/// The pixels whose sample lies in the closed bounding box of `points` (exact), on the
/// canvas; `None` when empty. Only a speed-up for the oracles: no sample outside the box
/// can be inside the primitive.
pub(crate) fn exact_sample_range<'a, I>(points: I, target: &Target) -> Option<PixelRange>
where
    I: Iterator<Item = &'a Point> + Clone,
{
    let centre = target.convention.pixel_centre.offset();
    let xs = points.clone().map(|p| &p.x);
    let ys = points.map(|p| &p.y);
    let (min_x, max_x) = (xs.clone().min()?, xs.max()?);
    let (min_y, max_y) = (ys.clone().min()?, ys.max()?);
    // sample i + c >= min  <=>  i >= ceil(min - c);  i + c <= max  <=>  i <= floor(max - c)
    let lo = |m: &BigRational| saturating_index((m - &centre).ceil().to_integer());
    let hi = |m: &BigRational| saturating_index((m - &centre).floor().to_integer());
    PixelRange::clamped(
        [lo(min_x), lo(min_y)],
        [hi(max_x), hi(max_y)],
        target.width,
        target.height,
    )
}

/// The pixels whose sample lies in the closed bounding box of `points` (subpixels, one
/// pixel = `one`, sample offset `centre`), on the canvas; `None` when empty.
pub(crate) fn fixed_sample_range<I>(points: I, one: i64, centre: i64, target: &Target) -> Option<PixelRange>
where
    I: Iterator<Item = [i64; 2]> + Clone,
{
    let min = |axis: usize| points.clone().map(|p| p[axis]).min();
    let max = |axis: usize| points.clone().map(|p| p[axis]).max();
    // i * one + centre >= min  <=>  i >= ceil((min - centre) / one)
    let lo = |m: i64| -(-(m - centre)).div_euclid(one);
    let hi = |m: i64| (m - centre).div_euclid(one);
    PixelRange::clamped(
        [lo(min(0)?), lo(min(1)?)],
        [hi(max(0)?), hi(max(1)?)],
        target.width,
        target.height,
    )
}
