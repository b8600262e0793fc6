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
/// `|p - a| <= 2m`, `|dx|, |dy| <= 2m`, so `|E| <= 8 m^2`: that many magnitude bits plus one
/// for the sign.
pub fn edge_value_bits(max_abs: &BigInt) -> u64 {
    let m = max_abs.abs();
    let bound: BigInt = m.clone() * m * 8;
    bound.bits() + 1
}

/// The narrowest [`Width`] that holds every edge value for coordinates bounded by `max_abs`.
///
/// ```
/// use rasterproof::num::plan::{plan, Width};
/// // A 256x256 canvas at 8 subpixel bits: 2^16 subpixels.
/// assert_eq!(plan(&(1i64 << 16).into()), Width::I64);
/// assert_eq!(plan(&(1i64 << 13).into()), Width::I32);
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

    /// Hand check at the boundary: m = 2^13 gives 8 m^2 = 2^29, 30 bits + sign = 31 <= 32;
    /// m = 2^14 gives 2^31, 33 bits: too wide for i32.
    #[test]
    fn boundaries_by_hand() {
        assert_eq!(edge_value_bits(&BigInt::from(1 << 13)), 31);
        assert_eq!(plan(&BigInt::from(1 << 13)), Width::I32);
        assert_eq!(plan(&BigInt::from(1 << 14)), Width::I64);
        assert_eq!(plan(&BigInt::from(1i64 << 29)), Width::I64);
        assert_eq!(plan(&BigInt::from(1i64 << 30)), Width::I128);
        assert_eq!(plan(&(BigInt::from(1) << 70)), Width::Big);
    }

    /// The bound is attained: the worst-case edge value for m really needs the planned bits.
    #[test]
    fn worst_case_needs_the_planned_bits() {
        for m in [3i128, 1000, 1 << 13, (1 << 14) + 5, 1 << 29] {
            // a = (-m, -m), b = (m, m - 2m) ... choose p = (m, -m), a = (-m, m), b = (m, -m)+(0,2m)
            let (ax, ay, bx, by, px, py) = (-m, m, m, -m, m, m);
            let e = (px - ax) * (by - ay) - (py - ay) * (bx - ax);
            let needed = 128 - e.unsigned_abs().leading_zeros() + 1;
            assert!(u64::from(needed) <= edge_value_bits(&BigInt::from(m)), "m={m} e={e}");
        }
    }
}
