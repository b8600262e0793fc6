//! Precision planning: "model only what a scene requires". The one place that decides, for
//! each primitive, which arithmetic evaluates it exactly and as cheaply as possible.
//!
//! A primitive is planned in three steps (the engines that follow a plan are
//! [`crate::tri::planned`], [`crate::fill::polygon::planned`] and [`crate::line::planned`]):
//!
//! 1. **Scale to integers.** Its coordinates and the sample lattice are multiplied by one
//!    integer `L` that makes them all integers: the least common multiple of the
//!    denominators of its vertices and of the pixel centre ([`scale_of`]). On the snapped
//!    scene that divides `2^S`; a decimal such as `491.407` brings 1000, `1/3` brings 3.
//!    Coordinates are then taken relative to the primitive's first sample, so a triangle
//!    `2^30` px from the origin costs what it costs at the origin.
//! 2. **Bound every value the evaluation can reach**, exactly, in [`BigInt`]: each engine
//!    lists them (edge values at the corners of its pixel range and the steps it adds, for
//!    triangles) and takes the largest magnitude: the [`Bound`].
//! 3. **Choose** the first [`Width`] of [`CHEAPEST_FIRST`] whose [`Width::limit`] holds the
//!    bound ([`choose`]). Every engine computes through [`Lane`] (add, subtract, multiply,
//!    compare; [`crate::num::lane`]), and every operand and result it computes is one of
//!    the bounded values, so no operation in the chosen width can round or overflow.
//!
//! The widths are measured against each other by `benches/widths.rs` on this crate's
//! traversal (see [`CHEAPEST_FIRST`] for the figures and the order they give).
//!
//! [`Lane`]: crate::num::lane::Lane

use std::fmt;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// An arithmetic a planned engine can run in: machine floats holding integers exactly,
/// machine integers, or arbitrary-precision integers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Width {
    /// `f32` holding integers: exact for every integer of magnitude `<= 2^24`.
    F32,
    /// `i32`.
    I32,
    /// `f64` holding integers: exact for every integer of magnitude `<= 2^53`.
    F64,
    /// `i64`.
    I64,
    /// `i128`.
    I128,
    /// Arbitrary-precision integers (`num_bigint::BigInt`; no gcd, no rationals).
    Big,
}

impl Width {
    /// Every width, narrowest first.
    pub const ALL: [Width; 6] = [Width::F32, Width::I32, Width::F64, Width::I64, Width::I128, Width::Big];

    /// The name used in `plan` output and JSON.
    pub fn name(self) -> &'static str {
        match self {
            Width::F32 => "f32",
            Width::I32 => "i32",
            Width::F64 => "f64",
            Width::I64 => "i64",
            Width::I128 => "i128",
            Width::Big => "bigint",
        }
    }

    /// Parses a name written by [`Width::name`].
    pub fn from_name(name: &str) -> Option<Width> {
        Width::ALL.into_iter().find(|w| w.name() == name)
    }

    /// The largest magnitude `m` such that every integer in `[-m, m]` is held exactly, and
    /// the sum of two of them is exact whenever it lies in `[-m, m]` too; `None` for
    /// [`Width::Big`] (unbounded).
    ///
    /// - f32: 24-bit significand, so every integer up to `2^24` is a float and a sum of
    ///   integers that is one is returned exactly (round to nearest returns a representable
    ///   exact result unchanged); `2^24 + 1` is not an f32.
    /// - i32 / i64 / i128: `2^(n-1) - 1`, the two's complement maximum (the minimum,
    ///   `-2^(n-1)`, is left out so that the range is symmetric).
    /// - f64: 53-bit significand, `2^53`.
    pub fn limit(self) -> Option<BigInt> {
        let pow = |k: u32| BigInt::one() << k;
        match self {
            Width::F32 => Some(pow(24)),
            Width::I32 => Some(pow(31) - 1),
            Width::F64 => Some(pow(53)),
            Width::I64 => Some(pow(63) - 1),
            Width::I128 => Some(pow(127) - 1),
            Width::Big => None,
        }
    }

    /// Whether every value of magnitude up to `bound` is exact in this width.
    pub fn holds(self, bound: &BigInt) -> bool {
        self.limit().is_none_or(|m| bound.abs() <= m)
    }
}

impl fmt::Display for Width {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The order the planner tries the widths in: cheapest first, as measured by
/// `cargo bench --features bench --bench widths` (the planned triangle traversal forced into each width on
/// 10k medium triangles with integer vertices at 1024x1024, every value below 2^24 so
/// that every width runs it; round-robin in one process, median of 21 repetitions; two
/// runs on the 2-core development machine, 2026-12-01):
///
/// | width | run 1 Mpix/s | vs i32 | run 2 Mpix/s | vs i32 |
/// |---|---|---|---|---|
/// | i32 | 36.6 | 1.00 | 50.5 | 1.00 |
/// | i64 | 34.5 | 0.94 | 48.8 | 0.97 |
/// | f32 | 34.3 | 0.94 | 43.6 | 0.86 |
/// | f64 | 33.8 | 0.92 | 45.2 | 0.89 |
/// | i128 | 29.3 | 0.80 | 39.9 | 0.79 |
/// | bigint | 3.9 | 0.11 | 4.5 | 0.09 |
///
/// i32 and i64 run the same scalar loop (one add per edge per pixel) within noise of each
/// other; f32 and f64 are no faster than the integers and hold less (2^24 < 2^31,
/// 2^53 < 2^63), so they are never the cheapest that holds a bound: they stay in the
/// order (and in the tests, forced) but the planner never picks them. i128 is two adds
/// with carry per value; the arbitrary-precision fallback is about a tenth of i32.
pub const CHEAPEST_FIRST: [Width; 6] = [Width::I32, Width::I64, Width::F32, Width::F64, Width::I128, Width::Big];

/// The cheapest width that holds every value of magnitude up to `bound`.
///
/// ```
/// use num_bigint::BigInt;
/// use rasterproof::num::plan::{choose, Width};
/// assert_eq!(choose(&BigInt::from(i32::MAX)), Width::I32);
/// assert_eq!(choose(&(BigInt::from(i32::MAX) + 1)), Width::I64);
/// assert_eq!(choose(&(BigInt::from(1) << 200)), Width::Big);
/// ```
pub fn choose(bound: &BigInt) -> Width {
    CHEAPEST_FIRST
        .into_iter()
        .find(|w| w.holds(bound))
        .expect("Width::Big holds every bound")
}

/// What forced a plan: the largest value the evaluation can reach, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Bound {
    /// The largest magnitude of any value the engine computes.
    pub value: BigInt,
    /// Which value that is, in words (e.g. `edge 2 at pixel (0, 31)`).
    pub what: String,
}

impl Bound {
    /// The bits of the bound's magnitude (`|value| < 2^bits`).
    pub fn bits(&self) -> u64 {
        self.value.abs().bits()
    }
}

/// A primitive's plan: the integer scale, the bound and the width chosen for it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Plan {
    /// The scale `L`: every coordinate and sample times `L` is an integer.
    pub scale: BigInt,
    /// The largest value the evaluation reaches.
    pub bound: Bound,
    /// The width that runs it.
    pub width: Width,
}

impl Plan {
    /// The plan for `bound` at `scale`: the cheapest width that holds it.
    pub fn new(scale: BigInt, bound: Bound) -> Plan {
        let width = choose(&bound.value);
        Plan { scale, bound, width }
    }

    /// The plan for `bound` at `scale` in a given width, or `None` when the width cannot
    /// hold the bound (for tests and benches that force each width).
    pub fn forced(scale: BigInt, bound: Bound, width: Width) -> Option<Plan> {
        width.holds(&bound.value).then_some(Plan { scale, bound, width })
    }
}

impl fmt::Display for Plan {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: every value within ±{} < 2^{} (the largest: {}); coordinates in units of 1/{} px",
            self.width,
            self.bound.value,
            self.bound.bits(),
            self.bound.what,
            self.scale
        )
    }
}

/// The least common multiple of the denominators of `values`: the smallest positive `L`
/// with every `v * L` an integer.
///
/// ```
/// use num_rational::BigRational;
/// use rasterproof::num::exact::parse_rational;
/// use rasterproof::num::plan::scale_of;
/// let v = [parse_rational("491.407").unwrap(), BigRational::new(1.into(), 2.into())];
/// assert_eq!(scale_of(v.iter()), 1000.into());
/// let third = [BigRational::new(1.into(), 3.into()), BigRational::new(1.into(), 2.into())];
/// assert_eq!(scale_of(third.iter()), 6.into());
/// ```
pub fn scale_of<'a>(values: impl IntoIterator<Item = &'a BigRational>) -> BigInt {
    values.into_iter().fold(BigInt::one(), |l, v| l.lcm(v.denom()))
}

/// `v * scale` as an integer.
///
/// # Panics
/// When `scale` is not a multiple of `v`'s denominator (a caller bug: use [`scale_of`]).
pub fn scaled(v: &BigRational, scale: &BigInt) -> BigInt {
    let (q, r) = (v.numer() * scale).div_rem(v.denom());
    assert!(r.is_zero(), "scale {scale} does not clear the denominator of {v}");
    q
}

/// `floor(a / b)` for `b > 0` (the planned engines' setup arithmetic).
pub(crate) fn floor_div(a: &BigInt, b: &BigInt) -> BigInt {
    a.div_floor(b)
}

/// `ceil(a / b)` for `b > 0`.
pub(crate) fn ceil_div(a: &BigInt, b: &BigInt) -> BigInt {
    -(-a).div_floor(b)
}

/// A local index known to lie within a primitive's range (or one past it).
pub(crate) fn index(v: &BigInt) -> i64 {
    v.to_i64().expect("an index clamped to the range")
}

/// The indices of `first..=last` where `N(k) = n_first + (k - first) inc > v`, for
/// `inc != 0`: a suffix when `inc > 0`, a prefix when `inc < 0`, as an inclusive pair
/// (empty when the first exceeds the second). Shared by the planned polygon rows and the
/// planned line's candidate walk.
pub(crate) fn indices_above(n_first: &BigInt, inc: &BigInt, first: i64, last: i64, v: &BigInt) -> (i64, i64) {
    let span = BigInt::from(last - first);
    if inc.is_positive() {
        // (k - first) inc > v - n_first  <=>  k - first >= floor((v - n_first) / inc) + 1
        let k: BigInt = (floor_div(&(v - n_first), inc) + BigInt::one()).clamp(BigInt::zero(), &span + 1);
        (first + index(&k), last)
    } else {
        // (k - first) (-inc) < n_first - v  <=>  k - first <= ceil((n_first - v) / -inc) - 1
        let k: BigInt = (ceil_div(&(n_first - v), &-inc) - BigInt::one()).clamp(-BigInt::one(), span);
        (first, first + index(&k))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Hand check of each limit at its boundary, in the type itself: the limit is held and
    /// sums to it are exact; one more is not held (or, for the floats, not representable).
    #[test]
    fn limits_by_hand() {
        let big = |v: i128| BigInt::from(v);
        assert_eq!(Width::I32.limit(), Some(big(2_147_483_647)));
        assert_eq!(Width::I64.limit(), Some(big(9_223_372_036_854_775_807)));
        assert_eq!(Width::I128.limit(), Some(big(i128::MAX)));
        // f32: 16777216 = 2^24 is a float, 16777217 is not (it rounds to 2^24).
        assert_eq!(Width::F32.limit(), Some(big(16_777_216)));
        assert_eq!(16_777_216.0f32 - 1.0 + 1.0, 16_777_216.0);
        assert_eq!(16_777_217i32 as f32, 16_777_216.0);
        // f64: 2^53 = 9007199254740992 is, 2^53 + 1 is not.
        assert_eq!(Width::F64.limit(), Some(big(9_007_199_254_740_992)));
        assert_eq!(9_007_199_254_740_993i64 as f64, 9_007_199_254_740_992.0);
        for w in Width::ALL {
            if let Some(m) = w.limit() {
                assert!(w.holds(&m) && w.holds(&-m.clone()), "{w}");
                assert!(!w.holds(&(m.clone() + 1)) && !w.holds(&(-m - 1)), "{w}");
            } else {
                assert!(w.holds(&(big(1) << 4000)));
            }
        }
    }

    /// The order: each bound goes to the first width of the measured order that holds it,
    /// so one unit past i32's limit is i64 (f32 holds less than i32 and comes later), one
    /// past i64's is i128 (f64 holds less than i64), one past i128's is bigint.
    #[test]
    fn choose_at_each_boundary() {
        let pow = |k: u32| BigInt::one() << k;
        assert_eq!(choose(&BigInt::zero()), Width::I32);
        assert_eq!(choose(&(pow(31) - 1)), Width::I32);
        assert_eq!(choose(&pow(31)), Width::I64);
        assert_eq!(choose(&-pow(31)), Width::I64);
        assert_eq!(choose(&(pow(63) - 1)), Width::I64);
        assert_eq!(choose(&pow(63)), Width::I128);
        assert_eq!(choose(&(pow(127) - 1)), Width::I128);
        assert_eq!(choose(&pow(127)), Width::Big);
    }

    #[test]
    fn scale_clears_every_denominator() {
        let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
        let vs = [q(1, 3), q(5, 4), q(7, 1), q(1, 2)];
        let l = scale_of(vs.iter());
        assert_eq!(l, BigInt::from(12));
        let ints: Vec<BigInt> = vs.iter().map(|v| scaled(v, &l)).collect();
        assert_eq!(ints, [4, 15, 84, 6].map(BigInt::from));
    }
}
