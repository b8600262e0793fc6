//! The planned values (`interp::planned`): at every pixel centre the same exact value and
//! the same nearest f32 as the plain definition (`ValueSetup::value`), and the same
//! answer to "within a bound of an f32", on random triangles (window-space with w,
//! clip-space with a vertex behind the eye), segments, values placed exactly on f32
//! midpoints, and canvases far from the origin.

use num_rational::BigRational;
use num_traits::Signed;
use proptest::prelude::*;
use proptest::test_runner::Config;
use rasterproof::geom::Point;
use rasterproof::interp::planned::{FastPlan, PlannedValue, TriangleF64};
use rasterproof::interp::values::{Interpolation, ProvokingVertex, ValueSegment, ValueSetup, ValueTriangle};
use rasterproof::num::exact::nearest_f32;

use crate::common::config;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// A value: thirds, tenths, 256ths, or exactly the midpoint of two f32 neighbours near
/// the given magnitude (1 + 2^-24 times a power of two), which a filter must not round.
fn value() -> impl Strategy<Value = BigRational> {
    prop_oneof![
        (-4000i64..4000, prop::sample::select(vec![1i64, 3, 10, 256])).prop_map(|(n, d)| q(n, d)),
        (-20i32..20, any::<bool>(), -1i64..2).prop_map(|(e, neg, nudge)| {
            // The midpoint, or a hair (2^-70) beside it, which f64 cannot hold.
            let mid = q((1 << 24) + 1, 1 << 24) + BigRational::new(nudge.into(), num_bigint::BigInt::from(1) << 70);
            let scaled = if e >= 0 {
                mid * q(1 << e, 1)
            } else {
                mid / q(1 << -e, 1)
            };
            if neg {
                -scaled
            } else {
                scaled
            }
        }),
    ]
}

fn setup() -> impl Strategy<Value = (ValueSetup, i64)> {
    let coordinate = (0i64..48 * 256).prop_map(|n| q(n, 256));
    prop_oneof![
        // A window-space triangle with w in 1/4 .. 8, at an offset.
        (
            prop::array::uniform3((coordinate.clone(), coordinate.clone())),
            prop::array::uniform3(prop::sample::select(vec![q(1, 4), q(1, 1), q(2, 1), q(7, 3), q(8, 1)])),
            prop::array::uniform3(prop::array::uniform2(value())),
            prop::sample::select(vec![0i64, 1 << 12, (1 << 24) - 64]),
        )
            .prop_map(|(p, w, v, offset)| {
                let points = p.map(|(x, y)| Point::new(x + q(offset, 1), y));
                let t = ValueTriangle::window(
                    [&points[0], &points[1], &points[2]],
                    [&w[0], &w[1], &w[2]],
                    v.map(|v| v.to_vec()),
                );
                (ValueSetup::Triangle(Box::new(t)), offset)
            }),
        // Homogeneous vertices, one of them possibly behind the eye.
        (
            prop::array::uniform3(prop::array::uniform3(-64i64..64)),
            prop::array::uniform3(prop::array::uniform2(value())),
        )
            .prop_map(|(h, v)| {
                let t = ValueTriangle {
                    h: h.map(|c| [q(c[0] * 4, 1), q(c[1] * 4, 1), q(c[2], 16)]),
                    values: v.map(|v| v.to_vec()),
                };
                (ValueSetup::Triangle(Box::new(t)), 0)
            }),
        // A segment.
        (
            prop::array::uniform2((coordinate.clone(), coordinate)),
            prop::array::uniform2(prop::array::uniform2(value())),
        )
            .prop_map(|(e, v)| {
                let s = ValueSegment {
                    ends: e.map(|(x, y)| Point::new(x, y)),
                    values: v.map(|v| v.to_vec()),
                };
                (ValueSetup::Segment(Box::new(s)), 0)
            }),
    ]
}

fn interpolation() -> impl Strategy<Value = Interpolation> {
    prop::sample::select(Interpolation::ALL.to_vec())
}

proptest! {
    #![proptest_config(Config { cases: 512, ..config("proptest-regressions/values_planned.txt") })]

    #[test]
    fn planned_values_are_the_plain_ones(
        (setup, offset) in setup(),
        interpolation in interpolation(),
        last in any::<bool>(),
        half in any::<bool>(),
        px in 0u32..56,
        py in 0u32..56,
        channel in 0usize..2,
        steps in -3i32..4,
        bound_exp in -30i32..4,
        sample in prop::option::of((0i64..16, 0i64..16)),
    ) {
        let provoking = if last { ProvokingVertex::Last } else { ProvokingVertex::First };
        let centre = if half { q(1, 2) } else { q(0, 1) };
        // The pixel's centre, or a sample position on the 1/16 grid.
        let offset_point = match sample {
            Some((sx, sy)) => Point::new(q(sx, 16), q(sy, 16)),
            None => Point::new(centre.clone(), centre.clone()),
        };
        let x = u32::try_from(offset).unwrap() + px;
        let p = Point::new(q(i64::from(x), 1) + &offset_point.x, q(i64::from(py), 1) + &offset_point.y);
        let plain = setup.value(interpolation, provoking, channel..channel + 1, &p).map(|v| v[0].clone());
        let planned = PlannedValue::channels_at(&setup, interpolation, provoking, channel..channel + 1, &offset_point)
            .pop()
            .unwrap();
        prop_assert_eq!(planned.exact(x, py), plain.clone());
        prop_assert_eq!(planned.nearest_f32(x, py), plain.clone().map(|v| nearest_f32(&v)));
        // The f64 filter: where it decides, the plain value's nearest f32.
        if let Some(t) = TriangleF64::of(&setup, channel..channel + 1) {
            let f = |v: &BigRational| num_traits::ToPrimitive::to_f64(v).unwrap();
            let fast = FastPlan::new(&t, interpolation, provoking, (f(&offset_point.x), f(&offset_point.y)));
            let mut out = [None];
            fast.nearest_f32(x, py, &mut out);
            let nearest = plain.clone().map(|v| nearest_f32(&v));
            if let Some(decided) = out[0] {
                prop_assert_eq!(Ok(Some(decided)), nearest.clone());
            }
            // Where it does not, the sign of the exact inputs, when it decides.
            if let Some(decided) = fast.nearest_f32_exact(&setup, channel, x, py, 0) {
                prop_assert_eq!(Ok(Some(decided)), nearest.clone());
            }
            // Four pixels at once: this one and three along its row and column.
            let (xs, ys) = ([x, x + 1, x, x + 3], [py, py, py + 1, py + 2]);
            let mut four = [[0.0f32; 4]; 4];
            let undecided = fast.nearest_f32_x4(xs, ys, &mut four);
            for i in 0..4 {
                if undecided & (1 << i) == 0 {
                    let at = Point::new(q(i64::from(xs[i]), 1) + &offset_point.x, q(i64::from(ys[i]), 1) + &offset_point.y);
                    let exact = setup.value(interpolation, provoking, channel..channel + 1, &at).map(|v| nearest_f32(&v[0]));
                    prop_assert_eq!(Ok(Some(four[0][i])), exact, "lane {}", i);
                }
            }
        }
        // Within a bound of an f32 a few steps from the nearest: both ways of deciding.
        if let Ok(v) = plain {
            if let Some(n) = nearest_f32(&v).filter(|n| n.is_finite() && *n != 0.0) {
                let t = f32::from_bits(n.to_bits().wrapping_add_signed(steps));
                let bound = 2f64.powi(bound_exp) * f64::from(n).abs() * 1e-6;
                let exact = (BigRational::from_float(f64::from(t)).unwrap() - &v).abs()
                    <= BigRational::from_float(bound).unwrap();
                prop_assert_eq!(planned.within(x, py, t, bound), Ok(exact));
            }
        }
    }
}

/// A value exactly on the midpoint of 1 and its f32 successor rounds to even (1); a
/// hair (2^-70) above it, which its f64 estimate cannot hold, rounds up.
#[test]
fn a_value_on_an_f32_midpoint_rounds_to_even() {
    let mid = q((1 << 24) + 1, 1 << 24);
    let above = &mid + BigRational::new(1.into(), num_bigint::BigInt::from(1) << 70);
    let (a, b, c) = (Point::from_ints(0, 0), Point::from_ints(8, 0), Point::from_ints(0, 8));
    for (v, expected) in [(mid, 1.0), (above, 1.0 + f32::EPSILON)] {
        let t = ValueTriangle::window(
            [&a, &b, &c],
            [&q(1, 1), &q(1, 1), &q(1, 1)],
            [vec![v.clone()], vec![v.clone()], vec![v]],
        );
        let planned = PlannedValue::new(
            &ValueSetup::Triangle(Box::new(t)),
            Interpolation::Smooth,
            ProvokingVertex::First,
            0,
            &q(1, 2),
        );
        assert_eq!(planned.nearest_f32(2, 3), Ok(Some(expected)));
    }
}

/// The f64 filter leaves a value on an f32 midpoint (or 2^-70 beside it) to the exact
/// path, and decides a plain one: at the centres of a 32x32 triangle with thirds, w = 1, 3
/// and 1/4, far from any midpoint, every pixel.
#[test]
fn the_f64_filter_decides_plain_values_and_leaves_midpoints() {
    let (a, b, c) = (Point::from_ints(0, 0), Point::from_ints(32, 0), Point::from_ints(0, 32));
    let setup = |v: [BigRational; 3], w: [BigRational; 3]| {
        ValueSetup::Triangle(Box::new(ValueTriangle::window(
            [&a, &b, &c],
            [&w[0], &w[1], &w[2]],
            v.map(|v| vec![v]),
        )))
    };
    let mid = q((1 << 24) + 1, 1 << 24);
    let above = &mid + BigRational::new(1.into(), num_bigint::BigInt::from(1) << 70);
    for v in [mid, above] {
        let s = setup([v.clone(), v.clone(), v.clone()], [q(1, 1), q(1, 1), q(1, 1)]);
        let fast = FastPlan::new(
            &TriangleF64::of(&s, 0..1).unwrap(),
            Interpolation::Smooth,
            ProvokingVertex::First,
            (0.5, 0.5),
        );
        let mut out = [Some(0.0)];
        fast.nearest_f32(2, 3, &mut out);
        assert_eq!(out, [None]);
        let mut four = [[0.0; 4]; 4];
        assert_eq!(fast.nearest_f32_x4([2, 3, 4, 5], [3, 3, 3, 3], &mut four), 0b1111);
        // The exact inputs' sign decides: the midpoint itself ties to even (1), the value
        // 2^-70 above it rounds up.
        let expected = if v == q((1 << 24) + 1, 1 << 24) {
            1.0
        } else {
            1.0 + f32::EPSILON
        };
        assert_eq!(fast.nearest_f32_exact(&s, 0, 2, 3, 0), Some(expected));
    }
    let s = setup([q(1, 3), q(-7, 3), q(100, 3)], [q(1, 1), q(3, 1), q(1, 4)]);
    for interpolation in [Interpolation::Smooth, Interpolation::NoPerspective] {
        let fast = FastPlan::new(
            &TriangleF64::of(&s, 0..1).unwrap(),
            interpolation,
            ProvokingVertex::First,
            (0.5, 0.5),
        );
        let (mut decided, mut inside) = (0, 0);
        for y in 0..32u32 {
            for x in 0..32 - y {
                let p = Point::new(q(2 * i64::from(x) + 1, 2), q(2 * i64::from(y) + 1, 2));
                let exact = s.value(interpolation, ProvokingVertex::First, 0..1, &p).unwrap();
                let mut out = [None];
                fast.nearest_f32(x, y, &mut out);
                inside += 1;
                if let Some(f) = out[0] {
                    assert_eq!(Some(f), nearest_f32(&exact[0]), "({x}, {y}) {interpolation:?}");
                    decided += 1;
                }
                // The uniform bound alone decides every covered pixel here too.
                let mut four = [[0.0; 4]; 4];
                assert_eq!(fast.nearest_f32_x4([x; 4], [y; 4], &mut four), 0, "({x}, {y})");
                assert_eq!(Some(four[0][0]), nearest_f32(&exact[0]));
            }
        }
        assert_eq!(decided, inside, "{interpolation:?}");
    }
}
