//! Fixed point: snapping exact coordinates to a 2^-S pixel grid, and the [`SubPixel`]
//! newtype that carries the integer models' range envelope.
//!
//! # The envelope of the i64 models
//!
//! A [`SubPixel`] holds `v` with `|v| <= 2^29` (`FIXED_ENVELOPE_BITS`). Sample positions
//! lie in `0 <= s < 16384 * 2^16 = 2^30` (canvas at most 16384 pixels, at most 16
//! subpixel bits). An edge function `E = (px - ax)*dy - (py - ay)*dx` then has
//! `|p - a| < 2^30 + 2^29` and `|dx|, |dy| <= 2^30`, so
//! `|E| < 2 * 1.5 * 2^30 * 2^30 = 3 * 2^60 < 2^62`: every edge value of every sample
//! on the canvas, and every increment between them, fits an i64 with a bit to spare. (The
//! incremental stepper also computes, and discards, the value one sample past the canvas
//! edge: `p < (16384 + 1) * 2^16` keeps it below `3.1 * 2^60`.)
//! The unit tests below check this bound right at its edge.

use std::fmt;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;

use super::exact::{round_to_integer, shortened, Rounding};

/// Coordinates of the integer models satisfy `|v| <= 2^FIXED_ENVELOPE_BITS` subpixels.
pub const FIXED_ENVELOPE_BITS: u32 = 29;

/// The largest subpixel magnitude the integer models accept: `2^29`.
pub const MAX_SUBPIXEL_MAGNITUDE: i64 = 1 << FIXED_ENVELOPE_BITS;

/// The most subpixel bits a convention may ask for (the envelope proof assumes it).
pub const MAX_SUBPIXEL_BITS: u32 = 16;

/// A coordinate in units of 2^-S pixel, guaranteed inside the integer models' envelope.
///
/// # Guarantees
/// - `|value| <= 2^29` (see the module docs for why that makes every edge value fit i64).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct SubPixel(i64);

impl SubPixel {
    /// The integer value in subpixels.
    #[inline]
    pub fn get(self) -> i64 {
        self.0
    }

    /// Accepts `value` when it is inside the envelope.
    pub fn new(value: i64) -> Option<SubPixel> {
        (value.unsigned_abs() <= MAX_SUBPIXEL_MAGNITUDE.unsigned_abs()).then_some(SubPixel(value))
    }

    /// Accepts an arbitrary-precision snapped value when it is inside the envelope.
    pub fn try_from_bigint(value: &BigInt, bits: u32) -> Result<SubPixel, EnvelopeError> {
        value.to_i64().and_then(SubPixel::new).ok_or_else(|| EnvelopeError {
            subpixels: value.clone(),
            bits,
        })
    }
}

/// A snapped coordinate outside the integer models' envelope.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EnvelopeError {
    /// The snapped value, in subpixels.
    pub subpixels: BigInt,
    /// The subpixel bits of the grid it was snapped to.
    pub bits: u32,
}

impl fmt::Display for EnvelopeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let pixels = BigRational::new(self.subpixels.clone(), BigInt::from(1) << self.bits);
        let limit_px = BigRational::new(BigInt::from(MAX_SUBPIXEL_MAGNITUDE), BigInt::from(1) << self.bits);
        write!(
            f,
            "{} px ({} subpixels at {} bits) is outside the integer models' envelope |v| <= 2^{FIXED_ENVELOPE_BITS} subpixels ({limit_px} px)",
            shortened(&pixels.to_string()),
            shortened(&self.subpixels.to_string()),
            self.bits
        )
    }
}

impl std::error::Error for EnvelopeError {}

/// Snaps `x` (pixels) to the 2^-bits grid: returns the nearest integer number of subpixels,
/// halfway cases decided by `rounding`.
///
/// ```
/// use rasterproof::num::{fixed::snap, parse_rational, Rounding};
/// // 1/512 px is exactly half a subpixel at 8 bits: a tie.
/// let x = parse_rational("1/512").unwrap();
/// assert_eq!(snap(&x, 8, Rounding::NearestEven), 0.into());
/// assert_eq!(snap(&x, 8, Rounding::HalfAwayFromZero), 1.into());
/// ```
///
/// A numerator and denominator that fit i64 (nearly every coordinate) are snapped in
/// i128 (`n 2^bits` below `2^126` for `bits <= 62`, then one division); others in big
/// rationals. Both give [`round_to_integer`]'s answer (unit tests, at the limits).
pub fn snap(x: &BigRational, bits: u32, rounding: Rounding) -> BigInt {
    if let (Some(n), Some(d), true) = (x.numer().to_i64(), x.denom().to_i64(), bits <= 62) {
        return BigInt::from(round_quotient(i128::from(n) << bits, i128::from(d), rounding));
    }
    let scaled = x * BigRational::from_integer(BigInt::from(1) << bits);
    round_to_integer(&scaled, rounding)
}

/// `n / d` (`d > 0`) rounded to an integer by `rounding`, as [`round_to_integer`] rounds.
pub(crate) fn round_quotient(n: i128, d: i128, rounding: Rounding) -> i128 {
    let (floor, rem) = (n.div_euclid(d), n.rem_euclid(d));
    let ceiling = floor + i128::from(rem != 0);
    match rounding {
        Rounding::Floor => floor,
        Rounding::Ceiling => ceiling,
        Rounding::TowardsZero => {
            if n < 0 {
                ceiling
            } else {
                floor
            }
        }
        Rounding::NearestEven | Rounding::HalfAwayFromZero => match (2 * rem).cmp(&d) {
            std::cmp::Ordering::Less => floor,
            std::cmp::Ordering::Greater => floor + 1,
            std::cmp::Ordering::Equal => match rounding {
                Rounding::HalfAwayFromZero if n < 0 => floor,
                Rounding::HalfAwayFromZero => floor + 1,
                _ if floor % 2 == 0 => floor,
                _ => floor + 1,
            },
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The i128 snap equals the big-rational rounding for every rounding, at the ends of
    /// i64, at ties and at `bits` 0, 8, 16 and 62 (the last the i128 path takes) and 63
    /// (the first it leaves), 64 and 65.
    #[test]
    fn snap_in_i128_equals_the_rational_rounding() {
        let numerators = [
            0,
            1,
            -1,
            3,
            -3,
            5,
            -5,
            7,
            255,
            -255,
            1 << 40,
            -(1 << 40) - 1,
            i64::MAX,
            i64::MIN,
            i64::MIN + 1,
            i64::MAX - 1,
        ];
        let denominators = [1, 2, 3, 4, 6, 7, 512, 1000, (1 << 40) + 3, i64::MAX, i64::MAX - 1];
        for &n in &numerators {
            for &d in &denominators {
                let x = BigRational::new(n.into(), d.into());
                for bits in [0, 1, 8, 16, 61, 62, 63, 64, 65] {
                    for rounding in Rounding::ALL {
                        let scaled = &x * BigRational::from_integer(BigInt::from(1) << bits);
                        assert_eq!(
                            snap(&x, bits, rounding),
                            round_to_integer(&scaled, rounding),
                            "{x} at {bits} bits, {rounding:?}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn envelope_edge_is_inclusive() {
        assert!(SubPixel::new(1 << 29).is_some());
        assert!(SubPixel::new(-(1 << 29)).is_some());
        assert!(SubPixel::new((1 << 29) + 1).is_none());
        assert!(SubPixel::new(-(1 << 29) - 1).is_none());
        assert!(SubPixel::new(i64::MIN).is_none());
        let err = SubPixel::try_from_bigint(&BigInt::from((1i64 << 29) + 1), 8).unwrap_err();
        assert!(err.to_string().contains("536870913 subpixels"), "{err}");
    }

    /// The worst case of the envelope proof, evaluated in i128: the largest possible edge
    /// value stays below 2^62.
    #[test]
    fn worst_edge_value_fits_i64() {
        let m: i128 = 1 << 29;
        let sample_max: i128 = (16384i128 << MAX_SUBPIXEL_BITS) - 1;
        let diff = sample_max + m; // |p - a|
        let d = 2 * m; // |b - a|
        let worst = diff * d + diff * d;
        assert!(worst < (1i128 << 62), "worst {worst}");
        // and the bound is not slack by more than a factor 2: this is the edge.
        assert!(worst > (1i128 << 61));
    }

    #[test]
    fn snapping_rounds_to_nearest() {
        let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
        assert_eq!(snap(&q(1, 3), 8, Rounding::NearestEven), BigInt::from(85)); // 85.33
        assert_eq!(snap(&q(2, 3), 8, Rounding::NearestEven), BigInt::from(171)); // 170.67
        assert_eq!(snap(&q(3, 512), 8, Rounding::NearestEven), BigInt::from(2)); // 1.5 -> 2
        assert_eq!(snap(&q(5, 512), 8, Rounding::NearestEven), BigInt::from(2)); // 2.5 -> 2
        assert_eq!(snap(&q(-5, 512), 8, Rounding::HalfAwayFromZero), BigInt::from(-3));
    }
}
