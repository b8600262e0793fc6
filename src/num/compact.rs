//! [`Compact`]: an exact rational in 16 bytes when it is small (a numerator and a
//! denominator that fit 63 bits: every decimal of up to 18 digits, every everyday fraction),
//! a boxed [`BigRational`] only when it is not.
//!
//! A frame of a million triangles holds six million coordinates. As big rationals each
//! costs two heap allocations and about 100 bytes; as a `Compact` it costs 16 bytes and no
//! allocation, and it snaps to a subpixel grid in one `i128` division. The value is the
//! same number either way: [`Compact::parse`] reads exactly what
//! [`parse_rational`] reads (one grammar, the same errors; the small forms are read here
//! directly, every other text is handed to [`parse_rational`]), and a value has one form
//! only (small whenever it fits), so equality and hashing are equality of numbers.

use std::fmt;
use std::num::NonZeroU64;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::ToPrimitive;

use super::exact::{exact_text, parse_rational, MAX_NUMBER_LEN};
use super::fixed::{round_quotient, snap};
use super::{NumberError, Rounding};

/// An exact rational number: small ones inline, others boxed. See the module docs.
///
/// ```
/// use rasterproof::num::compact::Compact;
/// use rasterproof::num::parse_rational;
/// let x = Compact::parse("491.407").unwrap();
/// assert_eq!(x.small(), Some((491_407, 1000)));
/// assert_eq!(x.to_big(), parse_rational("491.407").unwrap());
/// let huge = Compact::parse("1e300").unwrap();
/// assert_eq!(huge.small(), None);
/// assert_eq!(Compact::from_big(huge.to_big()), huge);
/// assert_eq!(std::mem::size_of::<Compact>(), 16);
/// ```
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Compact(Repr);

#[derive(Clone, PartialEq, Eq, Hash)]
enum Repr {
    /// `num / den` in lowest terms, `den >= 1`, `|num|` and `den` at most `i64::MAX`.
    Small { num: i64, den: NonZeroU64 },
    /// Every value that is not small.
    Big(Box<BigRational>),
}

/// The most decimal digits read directly: `10^18 - 1 < 2^63`.
const SMALL_DIGITS: usize = 18;

/// 10^k for k in 0..=18.
const POW10: [u64; 19] = {
    let mut p = [1u64; 19];
    let mut k = 1;
    while k < 19 {
        p[k] = p[k - 1] * 10;
        k += 1;
    }
    p
};

/// Zero.
impl Default for Compact {
    fn default() -> Compact {
        Compact::ZERO
    }
}

impl Compact {
    /// Zero.
    pub const ZERO: Compact = Compact(Repr::Small {
        num: 0,
        den: NonZeroU64::MIN,
    });

    /// The integer `n`.
    pub fn from_int(n: i64) -> Compact {
        Compact::small_reduced(i128::from(n), 1).unwrap_or_else(|| Compact::big(BigRational::from_integer(n.into())))
    }

    /// `x`, small when it fits.
    pub fn from_big(x: BigRational) -> Compact {
        match (x.numer().to_i64(), x.denom().to_u64()) {
            (Some(n), Some(d)) if n != i64::MIN && d <= i64::MAX as u64 => Compact(Repr::Small {
                num: n,
                den: NonZeroU64::new(d).expect("a rational's denominator is positive"),
            }),
            _ => Compact::big(x),
        }
    }

    fn big(x: BigRational) -> Compact {
        Compact(Repr::Big(Box::new(x)))
    }

    /// `num / den` (`den > 0`) in lowest terms, when both then fit the small form.
    fn small_reduced(num: i128, den: i128) -> Option<Compact> {
        debug_assert!(den > 0);
        let g = match (u64::try_from(num.unsigned_abs()), u64::try_from(den)) {
            (Ok(n), Ok(d)) => i128::from(n.gcd(&d)),
            _ => num.gcd(&den),
        };
        let (num, den) = (num / g, den / g);
        let limit = i128::from(i64::MAX);
        if num.abs() > limit || den > limit {
            return None;
        }
        Some(Compact(Repr::Small {
            num: i64::try_from(num).ok()?,
            den: NonZeroU64::new(u64::try_from(den).ok()?)?,
        }))
    }

    /// Parses a decimal (`12`, `-0.1`, `1.5e-3`) or a fraction (`1/3`) exactly: the number
    /// [`parse_rational`] reads, or its error.
    ///
    /// # Errors
    /// [`parse_rational`]'s, for the same text.
    pub fn parse(text: &str) -> Result<Compact, NumberError> {
        if text.len() <= MAX_NUMBER_LEN {
            if let Some(x) = parse_small(text.as_bytes()) {
                return Ok(x);
            }
        }
        parse_rational(text).map(Compact::from_big)
    }

    /// `n / 2^bits` (a snapped coordinate in pixels), `bits <= 62`.
    pub fn dyadic(n: i64, bits: u32) -> Compact {
        assert!(bits <= 62, "at most 62 bits");
        if n == 0 {
            return Compact::ZERO;
        }
        let shift = n.trailing_zeros().min(bits);
        // i64::MIN (whose negation does not fit) may not be small: read it as a big
        // rational, which from_big reduces to its one form.
        match n.checked_neg() {
            Some(_) => Compact(Repr::Small {
                num: n >> shift,
                den: NonZeroU64::new(1u64 << (bits - shift)).expect("a power of two"),
            }),
            None => Compact::from_big(BigRational::new(n.into(), BigInt::from(1) << bits)),
        }
    }

    /// The `n` with `self = n / 2^bits` ([`Compact::dyadic`]'s inverse), when the value
    /// is small and lies on the `2^-bits` grid, `bits <= 62`, and `n` fits i64: the value
    /// in subpixels when snapping would leave it as it is.
    pub fn on_grid(&self, bits: u32) -> Option<i64> {
        let (num, den) = self.small()?;
        let shift = bits
            .checked_sub(den.trailing_zeros())
            .filter(|_| den.is_power_of_two() && bits <= 62)?;
        num.checked_mul(1i64 << shift)
    }

    /// `(numerator, denominator)` in lowest terms, when the value is small.
    pub fn small(&self) -> Option<(i64, u64)> {
        match &self.0 {
            Repr::Small { num, den } => Some((*num, den.get())),
            Repr::Big(_) => None,
        }
    }

    /// The value as a big rational.
    pub fn to_big(&self) -> BigRational {
        match &self.0 {
            Repr::Small { num, den } => BigRational::new_raw(BigInt::from(*num), BigInt::from(den.get())),
            Repr::Big(x) => (**x).clone(),
        }
    }

    /// The value snapped to the `2^-bits` grid by `rounding`, in subpixels: what
    /// [`snap`] gives for [`Compact::to_big`], without a big number when the value is small.
    pub fn snap(&self, bits: u32, rounding: Rounding) -> BigInt {
        match self.snap_i64(bits, rounding) {
            Some(s) => BigInt::from(s),
            None => snap(&self.to_big(), bits, rounding),
        }
    }

    /// [`Compact::snap`] when the value is small, `bits <= 62` and the result fits i64.
    pub fn snap_i64(&self, bits: u32, rounding: Rounding) -> Option<i64> {
        match &self.0 {
            Repr::Small { num, den } if bits <= 62 => {
                let d = i128::from(den.get());
                i64::try_from(round_quotient(i128::from(*num) << bits, d, rounding)).ok()
            }
            _ => None,
        }
    }
}

/// The small forms read directly: `[+-]? digits [. digits]? ([eE] [+-]? digits)?` with at
/// most 18 digits and a value whose numerator and power-of-ten denominator fit, or
/// `[+-]? digits / digits` with at most 18 digits each and a non-zero denominator. `None`
/// hands the text to [`parse_rational`] (which also gives every error).
fn parse_small(text: &[u8]) -> Option<Compact> {
    if let Some(slash) = text.iter().position(|&b| b == b'/') {
        let (negative, num) = sign(&text[..slash]);
        let num = digits(num)?;
        let den = digits(&text[slash + 1..])?;
        if den == 0 {
            return None;
        }
        let num = i128::from(num);
        return Compact::small_reduced(if negative { -num } else { num }, i128::from(den));
    }
    let (negative, body) = sign(text);
    let (mantissa, exponent) = match body.iter().position(|&b| b == b'e' || b == b'E') {
        Some(at) => (&body[..at], Some(&body[at + 1..])),
        None => (body, None),
    };
    let (int_part, frac_part) = match mantissa.iter().position(|&b| b == b'.') {
        Some(at) => (&mantissa[..at], &mantissa[at + 1..]),
        None => (mantissa, &[][..]),
    };
    if int_part.is_empty() && frac_part.is_empty() {
        return None;
    }
    if int_part.len() + frac_part.len() > SMALL_DIGITS {
        return None;
    }
    let mut m: u64 = 0;
    for &b in int_part.iter().chain(frac_part) {
        if !b.is_ascii_digit() {
            return None;
        }
        m = m * 10 + u64::from(b - b'0');
    }
    let exp = match exponent {
        None => 0,
        Some(e) => {
            let (neg, e) = sign(e);
            // Four digits at most here: a larger exponent is parse_rational's to refuse
            // or to read.
            if e.len() > 4 {
                return None;
            }
            let e = i64::try_from(digits(e)?).ok()?;
            if neg {
                -e
            } else {
                e
            }
        }
    };
    let exp = exp - i64::try_from(frac_part.len()).ok()?;
    let signed = |m: u64| -> Option<i64> {
        let m = i64::try_from(m).ok()?;
        Some(if negative { -m } else { m })
    };
    if exp >= 0 {
        let scale = POW10.get(usize::try_from(exp).ok()?)?;
        return Some(Compact(Repr::Small {
            num: signed(m.checked_mul(*scale)?)?,
            den: NonZeroU64::MIN,
        }));
    }
    // m / 10^k in lowest terms: 10^k's only prime factors are 2 and 5, so the common
    // factor is 2^min(twos of m, k) 5^min(fives of m, k).
    let k = u32::try_from(-exp).ok()?;
    if k > 18 {
        return None;
    }
    if m == 0 {
        return Some(Compact::ZERO);
    }
    let twos = m.trailing_zeros().min(k);
    let mut m = m >> twos;
    let mut fives = 0;
    while fives < k && m % 5 == 0 {
        m /= 5;
        fives += 1;
    }
    let den = (1u64 << (k - twos)) * 5u64.pow(k - fives);
    Some(Compact(Repr::Small {
        num: signed(m)?,
        den: NonZeroU64::new(den)?,
    }))
}

/// The sign and the rest, as [`parse_rational`] reads a sign.
fn sign(text: &[u8]) -> (bool, &[u8]) {
    match text.first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    }
}

/// A run of 1 to 18 ASCII digits.
fn digits(text: &[u8]) -> Option<u64> {
    if text.is_empty() || text.len() > SMALL_DIGITS {
        return None;
    }
    text.iter().try_fold(0u64, |acc, &b| {
        b.is_ascii_digit().then(|| acc * 10 + u64::from(b - b'0'))
    })
}

/// The exact text ([`exact_text`]): `-7/2`, `3`.
impl fmt::Display for Compact {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Repr::Small { num, den } if den.get() == 1 => write!(f, "{num}"),
            Repr::Small { num, den } => write!(f, "{num}/{den}"),
            Repr::Big(x) => f.write_str(&exact_text(x)),
        }
    }
}

impl fmt::Debug for Compact {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

impl From<BigRational> for Compact {
    fn from(x: BigRational) -> Compact {
        Compact::from_big(x)
    }
}

impl From<&BigRational> for Compact {
    fn from(x: &BigRational) -> Compact {
        Compact::from_big(x.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn same(text: &str) {
        let big = parse_rational(text);
        let compact = Compact::parse(text);
        assert_eq!(compact.clone().map(|c| c.to_big()), big, "{text:?}");
        if let Ok(c) = compact {
            assert_eq!(c, Compact::from_big(big.unwrap()), "{text:?}: one form per value");
        }
    }

    #[test]
    fn reads_what_parse_rational_reads() {
        for t in [
            "0",
            "-0",
            "+0",
            "12",
            "-0.1",
            "0.10",
            ".5",
            "5.",
            "1e3",
            "1E-3",
            "-1.5e+2",
            "491.407",
            "999999999999999999",
            "9999999999999999999",
            "0.000000000000000001",
            "1e18",
            "1e19",
            "9.223372036854775807e18",
            "-9223372036854775807",
            "1/3",
            "-7/2",
            "+7/2",
            "6/4",
            "0/5",
            "1/0",
            "1/-3",
            "-1/-3",
            "1e",
            "e1",
            ".",
            "",
            "-",
            "1.2.3",
            "NaN",
            "inf",
            "1e400",
            "1e401",
            "1e-9999",
            "00000000000000000001",
            "1/999999999999999999",
            "123456789012345678/3",
            "123456789012345678901/7",
            "7/123456789012345678901",
            "1_0",
            " 1",
            "1 ",
            "0x10",
            "1e+",
            "--1",
            "+-1",
            "1/3/4",
        ] {
            same(t);
        }
    }

    #[test]
    fn small_and_big_forms() {
        assert_eq!(Compact::parse("0.5").unwrap().small(), Some((1, 2)));
        assert_eq!(Compact::parse("-6/4").unwrap().small(), Some((-3, 2)));
        assert_eq!(Compact::parse("0").unwrap().small(), Some((0, 1)));
        // i64::MIN is not small (its negation must be), i64::MAX is; nor is a denominator
        // beyond i64::MAX. One form per value, however the value was made.
        assert_eq!(Compact::from_int(i64::MIN).small(), None);
        assert_eq!(Compact::from_int(i64::MAX).small(), Some((i64::MAX, 1)));
        let min = BigRational::from_integer(i64::MIN.into());
        assert_eq!(Compact::from_big(min.clone()).small(), None);
        assert_eq!(Compact::from_big(min), Compact::from_int(i64::MIN));
        let tiny = BigRational::new(1.into(), BigInt::from(1u64 << 63));
        assert_eq!(Compact::from_big(tiny.clone()).small(), None);
        assert_eq!(Compact::from_big(tiny.clone()).to_big(), tiny);
        let widest = BigRational::new(1.into(), BigInt::from(i64::MAX));
        assert_eq!(Compact::from_big(widest).small(), Some((1, i64::MAX as u64)));
        assert_eq!(Compact::parse("1e30").unwrap().small(), None);
        assert_eq!(
            Compact::parse("1e30").unwrap().to_string(),
            "1000000000000000000000000000000"
        );
        assert_eq!(Compact::parse("-7/2").unwrap().to_string(), "-7/2");
    }

    #[test]
    fn dyadic_is_the_exact_dyadic() {
        for n in [
            0,
            1,
            -1,
            3,
            -6,
            256,
            1 << 40,
            -(1 << 62),
            i64::MAX,
            i64::MIN,
            i64::MIN + 1,
        ] {
            for bits in [0, 1, 8, 16, 61, 62] {
                let c = Compact::dyadic(n, bits);
                assert_eq!(c.to_big(), crate::num::exact::dyadic(&n.into(), bits), "{n} {bits}");
                assert_eq!(c, Compact::from_big(c.to_big()), "{n} {bits}: one form");
                // on the grid it was made on; i64::MIN at 0 bits is held big
                let small = n != i64::MIN || bits > 0;
                assert_eq!(c.on_grid(bits), small.then_some(n), "{n} {bits}: back");
            }
        }
        // off the grid: a finer power of two, or not a power of two; too fine a grid
        assert_eq!(Compact::dyadic(1, 9).on_grid(8), None);
        assert_eq!(Compact::parse("1/3").unwrap().on_grid(8), None);
        assert_eq!(Compact::parse("0.75").unwrap().on_grid(8), Some(192));
        assert_eq!(Compact::from_int(1).on_grid(63), None);
        // on the grid, but n beyond i64
        assert_eq!(Compact::from_int(1 << 60).on_grid(8), None);
    }

    #[test]
    fn snaps_as_snap_does() {
        let modes = [
            Rounding::NearestEven,
            Rounding::HalfAwayFromZero,
            Rounding::Floor,
            Rounding::Ceiling,
            Rounding::TowardsZero,
        ];
        for t in [
            "1/512",
            "-1/512",
            "3/512",
            "-3/512",
            "0.1",
            "-2.5",
            "1e30",
            "9223372036854775807",
            "1/3",
        ] {
            let c = Compact::parse(t).unwrap();
            for bits in [0, 1, 8, 16, 62, 63] {
                for m in modes {
                    assert_eq!(c.snap(bits, m), snap(&c.to_big(), bits, m), "{t} {bits} {m:?}");
                }
            }
        }
        // Beyond i64 after scaling: the big path.
        assert_eq!(Compact::from_int(i64::MAX).snap_i64(8, Rounding::Floor), None);
    }
}
