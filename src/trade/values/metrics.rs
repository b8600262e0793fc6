//! The values family's error metrics: f32 steps from the correctly rounded value
//! ([`ulp_steps`]), their tail, and wrong UNORM8 levels (the module docs of
//! [`crate::trade::values`] state the rules).

use crate::trade::metric::Metric;

/// The headline: f32 steps from the correctly rounded value.
pub const ULPS: &str = "error in f32 steps";
/// Values whose 8-bit UNORM level differs from the correctly rounded value's.
pub const WRONG_UNORM: &str = "wrong UNORM8 levels";

/// A NaN's distance, in f32 steps: more than any two f32 values are apart.
pub const NAN_STEPS: u64 = 1 << 32;

/// The UNORM8 level of `v / scale` (module docs: clamped, times 255, to nearest even; NaN
/// to 0). Exact in f64: a power-of-two scale, and an f32 times 255 fits 32 bits.
fn unorm8(v: f32, scale: f64) -> u8 {
    if v.is_nan() {
        return 0;
    }
    let r = (f64::from(v) / scale).clamp(0.0, 1.0) * 255.0;
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)] // 0..=255
    let level = r.round_ties_even() as u8;
    level
}

/// `f`'s place on the f32 number line: consecutive f32s are consecutive integers, both
/// zeros 0.
fn ordered(f: f32) -> i64 {
    let bits = i64::from(f.to_bits());
    if bits & 0x8000_0000 == 0 {
        bits
    } else {
        -(bits & 0x7fff_ffff)
    }
}

/// The f32 steps from `reference` to `v` ([`NAN_STEPS`] for a NaN).
pub fn ulp_steps(v: f32, reference: f32) -> u64 {
    if v.is_nan() {
        NAN_STEPS
    } else {
        (ordered(v) - ordered(reference)).unsigned_abs()
    }
}

/// The metrics of `values` against the exact values' nearest f32s `refs` (the first
/// `values.len()` of them) at attribute scale `scale`: the ulps' tail, then wrong UNORM8
/// levels (module docs).
pub(super) fn metrics(refs: &[Option<f32>], values: &[f32], scale: u64) -> Vec<Metric> {
    #[allow(clippy::cast_precision_loss)] // a power of two up to 2^32: exact
    let scale_f = scale as f64;
    let mut steps = Vec::with_capacity(values.len());
    let mut wrong = 0u64;
    for (r, &v) in refs.iter().zip(values) {
        let Some(r) = *r else { continue };
        steps.push(ulp_steps(v, r));
        wrong += u64::from(unorm8(v, scale_f) != unorm8(r, scale_f));
    }
    let samples = steps.len() as u64;
    let max = steps.iter().copied().max().unwrap_or(0);
    let p99 = if steps.is_empty() {
        0
    } else {
        // The smallest distance at least 99 % of the values are within.
        let k = (steps.len() * 99).div_ceil(100).max(1) - 1;
        *steps.select_nth_unstable(k).1
    };
    #[allow(clippy::cast_precision_loss)] // at most 2^32: exact
    let (p99, max) = (p99 as f64, max as f64);
    vec![
        Metric::UlpTail {
            name: ULPS,
            p99,
            max,
            samples,
        },
        Metric::Rate {
            name: WRONG_UNORM,
            count: wrong,
            of: samples,
        },
    ]
}

#[cfg(test)]
mod tests {
    use num_rational::BigRational;

    use super::*;
    use crate::num::exact::nearest_f32;
    use crate::num::unorm::{unorm_levels, UnormRule};

    /// f32 steps by hand: 1 and its neighbours, across zero, to a NaN.
    #[test]
    fn ulp_steps_count_f32_values() {
        let next = f32::from_bits(1.0f32.to_bits() + 1);
        assert_eq!(ulp_steps(next, 1.0), 1);
        assert_eq!(ulp_steps(1.0, next), 1);
        assert_eq!(ulp_steps(-0.0, 0.0), 0);
        // The smallest subnormals either side of zero are two steps apart.
        assert_eq!(ulp_steps(f32::from_bits(1), -f32::from_bits(1)), 2);
        assert_eq!(ulp_steps(f32::NAN, 1.0), NAN_STEPS);
        // 2 is 2^23 steps above 1 (one binade).
        assert_eq!(ulp_steps(2.0, 1.0), 1 << 23);
    }

    /// UNORM8 by hand: 0.5 is 127.5, a tie, to the even 128; 1/255 is level 1; clamped
    /// outside [0, 1]; NaN to 0; divided by the scale first. 3/10 is 76.5/255, a tie the
    /// exact value rounds to the even 76, but its nearest f32 (0.300000011920928955078125)
    /// is above it: 77, the reference level of the values trade.
    #[test]
    fn unorm8_by_hand() {
        assert_eq!(unorm8(0.5, 1.0), 128);
        assert_eq!(unorm8(1.0 / 255.0, 1.0), 1);
        assert_eq!(unorm8(-3.0, 1.0), 0);
        assert_eq!(unorm8(7.0, 1.0), 255);
        assert_eq!(unorm8(f32::NAN, 1.0), 0);
        assert_eq!(unorm8(128.0, 256.0), 128);
        assert_eq!(unorm8(0.3, 1.0), 77);
        let three_tenths = BigRational::new(3.into(), 10.into());
        assert_eq!(unorm_levels(&three_tenths, 8, UnormRule::Nearest), 76..=76);
        assert_eq!(nearest_f32(&three_tenths), Some(0.3));
    }

    /// The percentile: of 100 values 0..100, the 99th is 98; of one value, that value.
    #[test]
    fn p99_is_the_smallest_bound_of_99_percent() {
        let refs = vec![Some(1.0f32); 100];
        let values: Vec<f32> = (0..100).map(|k| f32::from_bits(1.0f32.to_bits() + k)).collect();
        match &metrics(&refs, &values, 1)[0] {
            Metric::UlpTail { p99, max, samples, .. } => assert_eq!((*p99, *max, *samples), (98.0, 99.0, 100)),
            other => panic!("{other:?}"),
        }
        match &metrics(&refs[..1], &[f32::NAN], 1)[..] {
            [Metric::UlpTail { p99, max, .. }, Metric::Rate { count, of, .. }] => {
                assert_eq!((*p99, *max, *count, *of), (4_294_967_296.0, 4_294_967_296.0, 1, 1));
            }
            other => panic!("{other:?}"),
        }
    }
}
