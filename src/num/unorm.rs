//! An exact value's n-bit UNORM levels under the conversion rules the APIs state.
//!
//! The value is clamped to `[0, 1]` and scaled: `r = clamp(v) * (2^n - 1)`. Then:
//!
//! - [`UnormRule::Nearest`]: the level nearest `r`, a tie (`r` half way) to the even one;
//! - [`UnormRule::Vulkan`]: the Vulkan specification ("Conversion from Floating-Point to
//!   Normalized Fixed-Point") returns "one of the two unsigned binary integer values with
//!   exactly b bits which are closest to" `r`: `floor(r)` or `ceil(r)`, one level when `r`
//!   is whole (it "should" round to nearest, and need not);
//! - [`UnormRule::D3d`]: the Direct3D 11.3 functional specification's FLOAT to UNORM
//!   conversion allows 0.6 unit-last-place of error: every level within `6/10` of `r`.
//!
//! Each rule's answer is a contiguous range of levels: one level, or two.

use std::ops::RangeInclusive;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};

/// How a value becomes a UNORM level (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum UnormRule {
    /// Round to the nearest level, ties to even.
    Nearest,
    /// Vulkan: either of the two nearest levels.
    Vulkan,
    /// Direct3D: any level within 0.6 of the exact scaled value.
    D3d,
}

impl UnormRule {
    /// Every rule, in the order their names are listed.
    pub const ALL: [UnormRule; 3] = [UnormRule::Nearest, UnormRule::Vulkan, UnormRule::D3d];

    /// The rule's name: `nearest`, `vulkan` or `d3d`.
    pub fn name(self) -> &'static str {
        match self {
            UnormRule::Nearest => "nearest",
            UnormRule::Vulkan => "vulkan",
            UnormRule::D3d => "d3d",
        }
    }

    /// The rule named `name`.
    pub fn parse(name: &str) -> Option<UnormRule> {
        UnormRule::ALL.into_iter().find(|r| r.name() == name)
    }
}

/// The `bits`-bit UNORM levels `value` may become under `rule`.
///
/// ```
/// use num_rational::BigRational;
/// use rasterproof::num::unorm::{unorm_levels, UnormRule};
/// let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
/// // 1/2 of 255 is 127.5: nearest-even 128, Vulkan 127 or 128, D3D 127 or 128.
/// assert_eq!(unorm_levels(&q(1, 2), 8, UnormRule::Nearest), 128..=128);
/// assert_eq!(unorm_levels(&q(1, 2), 8, UnormRule::Vulkan), 127..=128);
/// assert_eq!(unorm_levels(&q(1, 2), 8, UnormRule::D3d), 127..=128);
/// // 2/255 is exactly level 2, under every rule.
/// assert_eq!(unorm_levels(&q(2, 255), 8, UnormRule::Vulkan), 2..=2);
/// // Out of [0, 1] clamps.
/// assert_eq!(unorm_levels(&q(-3, 1), 16, UnormRule::Vulkan), 0..=0);
/// assert_eq!(unorm_levels(&q(7, 5), 16, UnormRule::D3d), 65535..=65535);
/// ```
///
/// # Panics
/// When `bits` is not in `1..=32`.
pub fn unorm_levels(value: &BigRational, bits: u32, rule: UnormRule) -> RangeInclusive<u32> {
    assert!((1..=32).contains(&bits), "UNORM bits {bits} not in 1..=32");
    let max = (BigInt::one() << bits) - BigInt::one();
    let clamped = if value < &BigRational::zero() {
        BigRational::zero()
    } else if value > &BigRational::one() {
        BigRational::one()
    } else {
        value.clone()
    };
    let r = clamped * BigRational::from_integer(max.clone());
    let floor = r.floor().to_integer();
    let level = |n: &BigInt| n.to_u32().expect("a level of at most 32 bits");
    if r.is_integer() {
        return level(&floor)..=level(&floor);
    }
    let ceil = &floor + BigInt::one();
    let frac = &r - BigRational::from_integer(floor.clone());
    let half = BigRational::new(1.into(), 2.into());
    match rule {
        UnormRule::Nearest => {
            let n = if frac < half || (frac == half && floor.is_even()) {
                floor
            } else {
                ceil
            };
            level(&n)..=level(&n)
        }
        UnormRule::Vulkan => level(&floor)..=level(&ceil),
        UnormRule::D3d => {
            let tolerance = BigRational::new(6.into(), 10.into());
            let low = if frac <= tolerance { &floor } else { &ceil };
            let high = if BigRational::one() - &frac <= tolerance {
                &ceil
            } else {
                &floor
            };
            level(low)..=level(high)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    /// Hand values at 8 bits (255 levels apart): r = v * 255.
    /// - 1/10: r = 25.5, a tie: nearest-even 26; Vulkan 25 or 26; D3D both (0.5 <= 0.6).
    /// - 1/3: r = 85, whole: 85 under every rule.
    /// - 3/10: r = 76.5: nearest-even 76.
    /// - 1/5 + 1/1000 = 201/1000: r = 51.255: nearest 51; Vulkan 51 or 52; D3D 51 only
    ///   (52 is 0.745 away).
    /// - 207/1000: r = 52.785: nearest 53; D3D 52 (0.785 away: no) .. 53: 53 only.
    /// - 2/15 + 1/510 = 69/510 = 23/170: r = 34.5: nearest-even 34.
    /// - 0.2 + 0.45/255: r = 51.45: nearest 51; D3D 51 (0.45) and 52 (0.55).
    #[test]
    fn levels_by_hand() {
        let cases = [
            (q(1, 10), [25..=26u32, 26..=26, 25..=26, 25..=26]),
            (q(1, 3), [85..=85, 85..=85, 85..=85, 85..=85]),
            (q(3, 10), [76..=77, 76..=76, 76..=77, 76..=77]),
            (q(201, 1000), [51..=52, 51..=51, 51..=52, 51..=51]),
            (q(207, 1000), [52..=53, 53..=53, 52..=53, 53..=53]),
            (q(23, 170), [34..=35, 34..=34, 34..=35, 34..=35]),
            (q(5145, 25500), [51..=52, 51..=51, 51..=52, 51..=52]),
        ];
        for (v, [around, nearest, vulkan, d3d]) in cases {
            let r = &v * q(255, 1);
            assert!(
                BigRational::from_integer((*around.start()).into()) <= r
                    && r <= BigRational::from_integer((*around.end()).into()),
                "{v}"
            );
            assert_eq!(unorm_levels(&v, 8, UnormRule::Nearest), nearest, "{v} nearest");
            assert_eq!(unorm_levels(&v, 8, UnormRule::Vulkan), vulkan, "{v} vulkan");
            assert_eq!(unorm_levels(&v, 8, UnormRule::D3d), d3d, "{v} d3d");
        }
        for rule in UnormRule::ALL {
            assert_eq!(UnormRule::parse(rule.name()), Some(rule));
            assert_eq!(unorm_levels(&q(1, 1), 32, rule), u32::MAX..=u32::MAX);
            assert_eq!(unorm_levels(&q(0, 1), 1, rule), 0..=0);
        }
    }
}
