//! The pixel grid: where each pixel's sample sits, in every arithmetic, and which pixels'
//! samples lie in a box.
//!
//! Pixel `(i, j)` is the square `[i, i+1) x [j, j+1)` (x right, y down, origin top-left);
//! its sample sits at `(i + c, j + c)`, `c` the convention's pixel centre (1/2, or 0 in
//! the D3D9 style). Every model, checker and the CLI asks this module for sample positions
//! and pixel ranges, so the grid is written once:
//!
//! | arithmetic | sample of pixel `i` | here |
//! |---|---|---|
//! | exact | `i + c` (a rational) | [`ExactGrid`], [`sample_exact`] |
//! | fixed | `i * 2^S + c * 2^S` subpixels | [`FixedGrid`] |
//! | f64 / f32 | `i + c`, exact in both types on any canvas | [`sample_f64`], [`sample_f32`] |
//!
//! ```
//! use rasterproof::convention::{Convention, Target};
//! use rasterproof::geom::Point;
//! use rasterproof::raster::{exact_sample_range, sample_exact, FixedGrid};
//! let target = Target::new(8, 8, Convention::default()).unwrap();
//! assert_eq!(sample_exact(2, 3, &target), Point::from_fractions(5, 2, 7, 2));
//! // 8 subpixel bits: pixel 2's sample is at 2 * 256 + 128 subpixels.
//! assert_eq!(FixedGrid::of(&target.convention).sample(2), 640);
//! // The samples in the closed box [1, 3] x [0, 1/2]: columns 1 and 2 of row 0.
//! let pts = [Point::from_ints(1, 0), Point::from_fractions(3, 1, 1, 2)];
//! let r = exact_sample_range(pts.iter(), &target).unwrap();
//! assert_eq!((r.x0, r.x1, r.y0, r.y1), (1, 2, 0, 0));
//! ```

use glam::{DVec2, Vec2};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};

use crate::convention::{Convention, Target};
use crate::geom::Point;

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
    #[inline]
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

/// A pixel index from an exact integer, saturating by sign: anything beyond i64 is far off
/// any canvas either way, on the side its sign says.
pub fn saturating_index(v: BigInt) -> i64 {
    v.to_i64().unwrap_or(if v.sign() == num_bigint::Sign::Minus {
        i64::MIN
    } else {
        i64::MAX
    })
}

/// The sample grid in exact rationals: pixel `i`'s sample is at `i + centre`. Built once
/// per primitive (the centre is a `BigRational`), then asked per pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExactGrid {
    /// The sample's offset inside its pixel: 1/2 or 0.
    pub centre: BigRational,
}

impl ExactGrid {
    /// The grid of `target`'s convention.
    pub fn of(target: &Target) -> ExactGrid {
        ExactGrid {
            centre: target.convention.pixel_centre.offset(),
        }
    }

    /// The sample coordinate of pixel index `i` (`u32` on the canvas, `i64` for pixels off
    /// it) on either axis: `i + c`.
    pub fn coordinate(&self, i: impl Into<BigInt>) -> BigRational {
        BigRational::from_integer(i.into()) + &self.centre
    }

    /// The sample of pixel `(x, y)`: `(x + c, y + c)`.
    pub fn sample(&self, x: u32, y: u32) -> Point {
        Point::new(self.coordinate(x), self.coordinate(y))
    }

    /// The first pixel index whose sample is at or after `v`: `ceil(v - c)`, saturating
    /// (not clamped to the canvas).
    pub fn first_at_or_after(&self, v: &BigRational) -> i64 {
        saturating_index((v - &self.centre).ceil().to_integer())
    }

    /// The last pixel index whose sample is at or before `v`: `floor(v - c)`, saturating.
    pub fn last_at_or_before(&self, v: &BigRational) -> i64 {
        saturating_index((v - &self.centre).floor().to_integer())
    }
}

/// The exact sample coordinate of pixel index `i` on either axis ([`ExactGrid::coordinate`]).
pub fn sample_coordinate_exact(i: impl Into<BigInt>, target: &Target) -> BigRational {
    ExactGrid::of(target).coordinate(i)
}

/// The exact sample of pixel `(x, y)` ([`ExactGrid::sample`]); in a loop over pixels, build
/// the [`ExactGrid`] once instead.
pub fn sample_exact(x: u32, y: u32, target: &Target) -> Point {
    ExactGrid::of(target).sample(x, y)
}

/// The first pixel index whose sample is at or after `v` ([`ExactGrid::first_at_or_after`]).
pub fn first_sample_at_or_after(v: &BigRational, target: &Target) -> i64 {
    ExactGrid::of(target).first_at_or_after(v)
}

/// The last pixel index whose sample is at or before `v` ([`ExactGrid::last_at_or_before`]).
pub fn last_sample_at_or_before(v: &BigRational, target: &Target) -> i64 {
    ExactGrid::of(target).last_at_or_before(v)
}

/// The f64 sample of pixel `(x, y)`: exact (integers below 2^32 plus 1/2).
pub fn sample_f64(x: u32, y: u32, target: &Target) -> DVec2 {
    let c = target.convention.pixel_centre.offset_f64();
    DVec2::new(f64::from(x) + c, f64::from(y) + c)
}

/// The f32 sample of pixel `(x, y)` on the canvas: exact, since canvas indices are below
/// 2^14 ([`crate::convention::MAX_CANVAS`]) and `i + 1/2` needs 15 of f32's 24 bits.
pub fn sample_f32(x: u32, y: u32, target: &Target) -> Vec2 {
    let p = sample_f64(x, y, target);
    #[allow(clippy::cast_possible_truncation)] // exact for canvas indices (see above)
    Vec2::new(p.x as f32, p.y as f32)
}

/// The sample grid in subpixels of the convention's 2^-S grid: pixel `i`'s sample is at
/// `i * one + centre`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FixedGrid {
    /// One pixel, `2^S` subpixels.
    pub one: i64,
    /// The sample's offset inside its pixel, in subpixels (`2^(S-1)` or 0).
    pub centre: i64,
}

impl FixedGrid {
    /// The grid of `conv` (`S = conv.subpixel_bits`, `1..=16`).
    #[inline]
    pub fn of(conv: &Convention) -> FixedGrid {
        FixedGrid {
            one: 1i64 << conv.subpixel_bits,
            centre: conv.pixel_centre.offset_subpixels(conv.subpixel_bits),
        }
    }

    /// The sample coordinate of pixel index `i`, in subpixels (below 2^49: no overflow).
    #[inline]
    pub fn sample(&self, i: u32) -> i64 {
        i64::from(i) * self.one + self.centre
    }

    /// The sample of pixel `(x, y)`, in subpixels.
    #[inline]
    pub fn sample_point(&self, x: u32, y: u32) -> [i64; 2] {
        [self.sample(x), self.sample(y)]
    }

    /// The first pixel index whose sample is at or after `v` subpixels: `ceil((v - centre) / one)`.
    #[inline]
    pub fn first_at_or_after(&self, v: i64) -> i64 {
        // `one` is 2^S: an arithmetic shift is the floor division, and ceil(a) = -floor(-a)
        -((self.centre - v) >> self.one.trailing_zeros())
    }

    /// The last pixel index whose sample is at or before `v` subpixels: `floor((v - centre) / one)`.
    #[inline]
    pub fn last_at_or_before(&self, v: i64) -> i64 {
        (v - self.centre) >> self.one.trailing_zeros()
    }
}

/// The pixels whose sample lies in the closed bounding box of `points` (exact), on the
/// canvas; `None` when empty. Only a speed-up for the oracles: no sample outside the box
/// can be inside the primitive.
pub fn exact_sample_range<'a, I>(points: I, target: &Target) -> Option<PixelRange>
where
    I: Iterator<Item = &'a Point> + Clone,
{
    let [min_x, min_y, max_x, max_y] = bounding_box(points)?;
    let grid = ExactGrid::of(target);
    let lo = |m: &BigRational| grid.first_at_or_after(m);
    let hi = |m: &BigRational| grid.last_at_or_before(m);
    PixelRange::clamped(
        [lo(min_x), lo(min_y)],
        [hi(max_x), hi(max_y)],
        target.width,
        target.height,
    )
}

/// The exact bounding box of `points`, `[min_x, min_y, max_x, max_y]`; `None` when empty.
fn bounding_box<'a, I>(points: I) -> Option<[&'a BigRational; 4]>
where
    I: Iterator<Item = &'a Point> + Clone,
{
    let xs = points.clone().map(|p| &p.x);
    let ys = points.map(|p| &p.y);
    Some([xs.clone().min()?, ys.clone().min()?, xs.max()?, ys.max()?])
}

/// The pixels whose closed square `[i, i + 1] x [j, j + 1]` meets the closed bounding box
/// of `points` (exact), on the canvas; `None` when empty. Every sample of a pattern
/// ([`crate::pattern`]) that lies in the box belongs to one of them: the per-sample
/// oracles' loop.
pub fn exact_pixel_range<'a, I>(points: I, target: &Target) -> Option<PixelRange>
where
    I: Iterator<Item = &'a Point> + Clone,
{
    exact_pixel_range_grown(points, &BigRational::zero(), target)
}

/// [`exact_pixel_range`] with each pixel's square grown by `grow` on every side: the
/// pixels whose square `[i - grow, i + 1 + grow] x [j - grow, j + 1 + grow]` meets the box
/// (what conservative rasterization's uncertainty region reaches).
pub fn exact_pixel_range_grown<'a, I>(points: I, grow: &BigRational, target: &Target) -> Option<PixelRange>
where
    I: Iterator<Item = &'a Point> + Clone,
{
    let [min_x, min_y, max_x, max_y] = bounding_box(points)?;
    let lo = |m: &BigRational| saturating_index((m - grow).ceil().to_integer() - 1);
    let hi = |m: &BigRational| saturating_index((m + grow).floor().to_integer());
    PixelRange::clamped(
        [lo(min_x), lo(min_y)],
        [hi(max_x), hi(max_y)],
        target.width,
        target.height,
    )
}

/// The pixels whose sample lies in the closed bounding box of `points` (in subpixels of
/// `target`'s grid), on the canvas; `None` when empty.
#[inline]
pub fn fixed_sample_range<I>(points: I, target: &Target) -> Option<PixelRange>
where
    I: Iterator<Item = [i64; 2]>,
{
    let mut points = points;
    let first = points.next()?;
    let (mut min, mut max) = (first, first);
    for p in points {
        for axis in 0..2 {
            min[axis] = min[axis].min(p[axis]);
            max[axis] = max[axis].max(p[axis]);
        }
    }
    let grid = FixedGrid::of(&target.convention);
    let lo = |m: i64| grid.first_at_or_after(m);
    let hi = |m: i64| grid.last_at_or_before(m);
    PixelRange::clamped(
        [lo(min[0]), lo(min[1])],
        [hi(max[0]), hi(max[1])],
        target.width,
        target.height,
    )
}

/// The pixels whose sample lies in the closed box `[min, max]` (floats, as the float
/// models compute it), on the canvas; `None` when empty. Indices saturate, so an infinite
/// or huge box is clamped, never wrapped; a NaN bound gives an empty range.
pub fn float_sample_range(min: [f64; 2], max: [f64; 2], target: &Target) -> Option<PixelRange> {
    float_sample_range_at(min, max, [0, 0], target)
}

/// [`float_sample_range`] over a canvas-sized window of the plane whose first pixel is
/// pixel `origin`: the plane's pixel indices are found in f64 as on the canvas, then
/// shifted by `origin` in integers (so no rounding is added) and clamped to the window.
pub fn float_sample_range_at(min: [f64; 2], max: [f64; 2], origin: [i64; 2], target: &Target) -> Option<PixelRange> {
    let c = target.convention.pixel_centre.offset_f64();
    if min.iter().chain(&max).any(|v| v.is_nan()) {
        return None;
    }
    PixelRange::clamped(
        [
            index_ceil(min[0] - c).saturating_sub(origin[0]),
            index_ceil(min[1] - c).saturating_sub(origin[1]),
        ],
        [
            index_floor(max[0] - c).saturating_sub(origin[0]),
            index_floor(max[1] - c).saturating_sub(origin[1]),
        ],
        target.width,
        target.height,
    )
}

/// `ceil(v)` as a pixel index, saturating (any saturated value is off the canvas).
#[allow(clippy::cast_possible_truncation)] // `as` saturates; out-of-range means off-canvas
fn index_ceil(v: f64) -> i64 {
    v.ceil().clamp(-1e18, 1e18) as i64
}

/// `floor(v)` as a pixel index, saturating.
#[allow(clippy::cast_possible_truncation)]
fn index_floor(v: f64) -> i64 {
    v.floor().clamp(-1e18, 1e18) as i64
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::{PixelCentre, Preset};

    fn target(centre: PixelCentre, bits: u32) -> Target {
        let conv = Convention {
            pixel_centre: centre,
            subpixel_bits: bits,
            ..Preset::D3d11.convention()
        };
        Target::new(16, 16, conv).unwrap()
    }

    #[test]
    fn the_three_arithmetics_name_the_same_sample() {
        for centre in [PixelCentre::Half, PixelCentre::Corner] {
            for bits in [1, 4, 8, 16] {
                let t = target(centre, bits);
                let grid = FixedGrid::of(&t.convention);
                for (x, y) in [(0, 0), (3, 7), (15, 15)] {
                    let exact = sample_exact(x, y, &t);
                    let fixed = grid.sample_point(x, y);
                    let scale = BigRational::from_integer(BigInt::from(grid.one));
                    assert_eq!(BigRational::from_integer(fixed[0].into()), &exact.x * &scale);
                    assert_eq!(BigRational::from_integer(fixed[1].into()), &exact.y * &scale);
                    let f = sample_f64(x, y, &t);
                    assert_eq!(BigRational::from_float(f.x).unwrap(), exact.x);
                    assert_eq!(f64::from(sample_f32(x, y, &t).y), f.y);
                }
            }
        }
    }

    #[test]
    fn ranges_keep_samples_on_the_box_boundary() {
        // Box [1/2, 5/2] on the half grid: samples 0.5, 1.5, 2.5 -> pixels 0..=2.
        let t = target(PixelCentre::Half, 8);
        let pts = [Point::from_fractions(1, 2, 1, 2), Point::from_fractions(5, 2, 5, 2)];
        let r = exact_sample_range(pts.iter(), &t).unwrap();
        assert_eq!((r.x0, r.x1, r.y0, r.y1), (0, 2, 0, 2));
        // The same box in subpixels (128 ..= 640 at 8 bits), and in floats.
        let f = fixed_sample_range([[128, 128], [640, 640]].into_iter(), &t).unwrap();
        assert_eq!(f, r);
        assert_eq!(float_sample_range([0.5, 0.5], [2.5, 2.5], &t), Some(r));
        // Just inside the samples: one pixel fewer on each side.
        let f = fixed_sample_range([[129, 129], [639, 639]].into_iter(), &t).unwrap();
        assert_eq!((f.x0, f.x1), (1, 1));
        // Corner samples: box [0, 2] holds samples 0, 1, 2.
        let t = target(PixelCentre::Corner, 8);
        let pts = [Point::from_ints(0, 0), Point::from_ints(2, 2)];
        let r = exact_sample_range(pts.iter(), &t).unwrap();
        assert_eq!((r.x0, r.x1), (0, 2));
    }

    #[test]
    fn ranges_off_the_canvas_are_empty_or_clamped() {
        let t = target(PixelCentre::Half, 8);
        assert_eq!(float_sample_range([-5.0, -5.0], [0.25, 3.0], &t), None);
        assert_eq!(float_sample_range([f64::NAN, 0.0], [3.0, 3.0], &t), None);
        let r = float_sample_range([-1e300, 0.0], [f64::INFINITY, 0.5], &t).unwrap();
        assert_eq!((r.x0, r.x1, r.y0, r.y1), (0, 15, 0, 0));
        let huge = BigRational::from_integer(BigInt::from(1) << 80);
        assert_eq!(last_sample_at_or_before(&huge, &t), i64::MAX);
        assert_eq!(first_sample_at_or_after(&-huge, &t), i64::MIN);
    }
}
