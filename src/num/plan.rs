//! Precision planning: "model only what a scene requires". Given a scene's bounds, the
//! narrowest machine integer whose edge-function arithmetic is provably exact.

use std::fmt;

use num_bigint::BigInt;
use num_traits::Signed;

/// The integer width an edge-function evaluation needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Width {
    /// Fits `i32`.
    I32,
    /// Fits `i64`.
    I64,
    /// Fits `i128`.
    I128,
    /// Needs arbitrary precision.
    Big,
}

impl fmt::Display for Width {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Width::I32 => "i32",
            Width::I64 => "i64",
            Width::I128 => "i128",
            Width::Big => "bigint",
        })
    }
}

/// The bits an edge value can need when every coordinate (vertex or sample) has
/// magnitude at most `max_abs` subpixels, sign included.
///
/// `E(p)` is twice the signed area of the triangle (a, b, p), whose vertices lie in a square
/// of side 2m; such a triangle has area at most half the square, so `|E| <= 4 m^2`. Each of
/// the two products `(p.x - a.x)(b.y - a.y)` is at most `(2m)^2 = 4 m^2` too. That many
/// magnitude bits plus one for the sign.
pub fn edge_value_bits(max_abs: &BigInt) -> u64 {
    let m = max_abs.abs();
    let bound: BigInt = m.clone() * m * 4;
    bound.bits() + 1
}

/// The narrowest [`Width`] that holds every edge value for coordinates bounded by `max_abs`.
///
/// ```
/// use rasterproof::num::plan::{plan, Width};
/// // A 256x256 canvas at 8 subpixel bits: 2^16 subpixels.
/// assert_eq!(plan(&(1i64 << 16).into()), Width::I64);
/// // A 64x64 canvas at 8 bits fits i32.
/// assert_eq!(plan(&(1i64 << 14).into()), Width::I32);
/// ```
pub fn plan(max_abs: &BigInt) -> Width {
    match edge_value_bits(max_abs) {
        0..=32 => Width::I32,
        33..=64 => Width::I64,
        65..=128 => Width::I128,
        _ => Width::Big,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Hand check at the boundaries. i32 holds |E| < 2^31, so 4 m^2 < 2^31, m < 2^14.5:
    /// 4 * 23170^2 = 2147395600 < 2^31 = 2147483648 <= 4 * 23171^2 = 2147580964.
    /// i64: 4 m^2 < 2^63, m < 2^30.5 ~ 1518500249.98.
    #[test]
    fn boundaries_by_hand() {
        assert_eq!(edge_value_bits(&BigInt::from(1 << 14)), 32);
        assert_eq!(plan(&BigInt::from(23170)), Width::I32);
        assert_eq!(plan(&BigInt::from(23171)), Width::I64);
        assert_eq!(plan(&BigInt::from(1_518_500_249i64)), Width::I64);
        assert_eq!(plan(&BigInt::from(1_518_500_250i64)), Width::I128);
        assert_eq!(plan(&(BigInt::from(1) << 70)), Width::Big);
    }

    /// The bound is attained: a = (-m, -m), b = (m, -m), p = (m, m) give
    /// E = (2m)(0) - (2m)(2m) = -4 m^2, which needs exactly the planned bits (two's
    /// complement: -2^k needs k + 1 bits, so for m a power of two one bit is to spare,
    /// and one more than m needs it all).
    #[test]
    fn worst_case_is_attained() {
        for m in [3i128, 1000, 1 << 14, (1 << 14) + 1, 1 << 29, (1 << 30) + 1] {
            let (ax, ay, bx, by, px, py) = (-m, -m, m, -m, m, m);
            let e = (px - ax) * (by - ay) - (py - ay) * (bx - ax);
            assert_eq!(e, -4 * m * m);
            let magnitude_bits = 128 - e.unsigned_abs().leading_zeros();
            assert_eq!(
                u64::from(magnitude_bits) + 1,
                edge_value_bits(&BigInt::from(m)),
                "m={m}"
            );
        }
    }
}
