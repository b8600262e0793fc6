//! The invariants of interpolated values (`check::values`): they hold exactly for the
//! exact definition on random triangles (window-space with w, thirds, tenths and the 1/256
//! grid), and each checker fails on a planted counterexample. For the float models of
//! `interp::float` the same invariants are measured: how often each breaks, in one run.

use num_rational::BigRational;
use proptest::prelude::*;
use proptest::test_runner::Config;
use rasterproof::check::{
    check_values_flat, check_values_hull, check_values_rotation, check_values_shared_edge, check_values_translation,
};
use rasterproof::geom::Point;
use rasterproof::interp::float::{FloatInterpolator, FloatTriangle};
use rasterproof::interp::values::{Interpolation, ProvokingVertex, ValueTriangle};

use crate::common::config;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

fn coordinate() -> impl Strategy<Value = BigRational> {
    (prop::sample::select(vec![1i64, 3, 10, 256]), 0i64..32, 0i64..256)
        .prop_map(|(d, whole, f)| q(whole * d + f % d, d))
}

fn triangle() -> impl Strategy<Value = ValueTriangle> {
    (
        prop::array::uniform3((coordinate(), coordinate())),
        prop::array::uniform3(prop::sample::select(vec![q(1, 4), q(1, 1), q(3, 2), q(5, 1)])),
        prop::array::uniform3(prop::array::uniform2((
            -500i64..500,
            prop::sample::select(vec![1i64, 3, 7]),
        ))),
    )
        .prop_map(|(p, w, v)| {
            let points = p.map(|(x, y)| Point::new(x, y));
            ValueTriangle::window(
                [&points[0], &points[1], &points[2]],
                [&w[0], &w[1], &w[2]],
                v.map(|c| c.iter().map(|&(n, d)| q(n, d)).collect()),
            )
        })
}

fn interpolation() -> impl Strategy<Value = Interpolation> {
    prop::sample::select(Interpolation::ALL.to_vec())
}

proptest! {
    #![proptest_config(Config { cases: 128, ..config("proptest-regressions/values_invariants.txt") })]

    #[test]
    fn the_exact_values_keep_every_invariant(
        t in triangle(),
        interpolation in interpolation(),
        p in (coordinate(), coordinate()),
        shift in (-64i64..64, -64i64..64),
        s in 0i64..=16,
        last in any::<bool>(),
    ) {
        let p = Point::new(p.0, p.1);
        let provoking = if last { ProvokingVertex::Last } else { ProvokingVertex::First };
        prop_assert_eq!(check_values_hull(&t, interpolation, 0..2, &p), Ok(()));
        prop_assert_eq!(check_values_rotation(&t, interpolation, 0..2, &p), Ok(()));
        let (dx, dy) = (q(shift.0, 3), q(shift.1, 256));
        prop_assert_eq!(check_values_translation(&t, interpolation, provoking, 0..2, &p, (&dx, &dy)), Ok(()));
        prop_assert_eq!(check_values_flat(&t, provoking, 0..2, &p), Ok(()));
        // A second triangle on the edge 0-1 with a vertex of its own.
        let mut other = t.clone();
        other.h[2] = [q(7, 1), q(-9, 2), q(2, 1)];
        other.values[2] = vec![q(1, 1), q(-1, 1)];
        prop_assert_eq!(
            check_values_shared_edge(&t, &other, ((0, 1), (0, 1)), interpolation, 0..2, &q(s, 16)),
            Ok(())
        );
    }
}

/// What the checkers claim and do not: no hull claim with a vertex behind the eye, the
/// flat value of either provoking vertex, and edges that are not shared refused. (The
/// exact definition keeps every invariant, so their teeth are the property above failing
/// on a broken definition: `cargo mutants -f src/interp/values.rs`.)
#[test]
fn the_checkers_claim_what_they_say() {
    let (a, b, c) = (Point::from_ints(0, 0), Point::from_ints(8, 0), Point::from_ints(0, 8));
    let one = q(1, 1);
    let t = ValueTriangle::window(
        [&a, &b, &c],
        [&one, &one, &one],
        [vec![q(0, 1)], vec![q(8, 1)], vec![q(4, 1)]],
    );
    let inside = Point::from_ints(2, 2);
    // A vertex behind the eye makes no hull claim: the checker skips it.
    let mut behind = t.clone();
    behind.h[2] = [q(0, 1), q(-8, 1), q(-1, 1)];
    assert_eq!(check_values_hull(&behind, Interpolation::Smooth, 0..1, &inside), Ok(()));
    assert_eq!(check_values_flat(&t, ProvokingVertex::Last, 0..1, &inside), Ok(()));
    assert_eq!(check_values_flat(&t, ProvokingVertex::First, 0..1, &inside), Ok(()));
    let mut other = t.clone();
    other.values[1] = vec![q(9, 1)];
    let e = check_values_shared_edge(&t, &other, ((0, 1), (0, 1)), Interpolation::Smooth, 0..1, &q(1, 2)).unwrap_err();
    assert!(e.message.contains("do not share"), "{e}");
    // Edge 0-2 is shared; the value there agrees.
    assert_eq!(
        check_values_shared_edge(&t, &other, ((0, 2), (0, 2)), Interpolation::Smooth, 0..1, &q(1, 3)),
        Ok(())
    );
}

/// The float models against the same invariants, measured: on 300 random triangles of
/// the 1/256 grid (w powers of two, values over 8), at every pixel centre inside each,
/// how often a model's f32 value leaves the f32 hull of the vertex values, changes when
/// the vertices are listed from another vertex, or changes when the triangle and pixel
/// move by (1024, 512) px. Printed (`cargo test values_invariants -- --nocapture`); the
/// exact definition keeps all three (above); llvmpipe's model breaks rotation and
/// translation somewhere, which is what the checkers are for.
#[test]
fn float_models_break_the_invariants_at_measured_rates() {
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut next = |n: u64| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed % n
    };
    let mut triangles = Vec::new();
    for _ in 0..300 {
        let c = |n: &mut dyn FnMut(u64) -> u64| n(24 * 256) as f32 / 256.0;
        let x = [c(&mut next), c(&mut next), c(&mut next)];
        let y = [c(&mut next), c(&mut next), c(&mut next)];
        let w = [0, 1, 2].map(|_| [0.5f32, 1.0, 2.0, 4.0][next(4) as usize]);
        let values = [0, 1, 2].map(|_| vec![(next(2001) as f32 - 1000.0) / 8.0]);
        triangles.push(FloatTriangle {
            x,
            y,
            inv_w: w.map(|w| 1.0 / w),
            values,
        });
    }
    let models = [
        FloatInterpolator::all()[0],
        *FloatInterpolator::all()
            .iter()
            .find(|m| m.name() == "origin-plane fma ccw rcp f32 y-down")
            .unwrap(),
        *FloatInterpolator::all()
            .iter()
            .find(|m| m.name() == "barycentric no-fma as-given div f32 y-down")
            .unwrap(),
        *FloatInterpolator::all()
            .iter()
            .find(|m| m.name() == "vertex-plane fma as-given rcp f64 y-down")
            .unwrap(),
    ];
    let mut llvmpipe_breaks = (0, 0);
    for model in models {
        let (mut samples, mut hull, mut rotation, mut translation) = (0u64, 0u64, 0u64, 0u64);
        for t in &triangles {
            let rotate = |t: &FloatTriangle| FloatTriangle {
                x: [t.x[1], t.x[2], t.x[0]],
                y: [t.y[1], t.y[2], t.y[0]],
                inv_w: [t.inv_w[1], t.inv_w[2], t.inv_w[0]],
                values: [t.values[1].clone(), t.values[2].clone(), t.values[0].clone()],
            };
            let moved = FloatTriangle {
                x: t.x.map(|x| x + 1024.0),
                y: t.y.map(|y| y + 512.0),
                ..t.clone()
            };
            let area = (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.x[2] - t.x[0]) * (t.y[1] - t.y[0]);
            for py in 0..24u32 {
                for px in 0..24u32 {
                    let (cx, cy) = (px as f32 + 0.5, py as f32 + 0.5);
                    let e = |i: usize, j: usize| (t.x[j] - t.x[i]) * (cy - t.y[i]) - (t.y[j] - t.y[i]) * (cx - t.x[i]);
                    let inside = [e(0, 1), e(1, 2), e(2, 0)].iter().all(|&v| v * area.signum() > 0.0);
                    if !inside || area == 0.0 {
                        continue;
                    }
                    samples += 1;
                    let at = |m: &FloatInterpolator, t: &FloatTriangle, p: (u32, u32)| {
                        m.value(t, Interpolation::Smooth, ProvokingVertex::First, 0, p, 2048, 0.5)
                    };
                    let v = at(&model, t, (px, py));
                    let (lo, hi) = t
                        .values
                        .iter()
                        .fold((f32::MAX, f32::MIN), |(lo, hi), v| (lo.min(v[0]), hi.max(v[0])));
                    hull += u64::from(!(lo..=hi).contains(&v));
                    rotation += u64::from(at(&model, &rotate(t), (px, py)).to_bits() != v.to_bits());
                    translation += u64::from(at(&model, &moved, (px + 1024, py + 512)).to_bits() != v.to_bits());
                }
            }
        }
        let per = |n: u64| 100.0 * n as f64 / samples as f64;
        eprintln!(
            "{:<45} {samples} samples: hull {:.3}%, rotation {:.3}%, translation {:.3}%",
            model.name(),
            per(hull),
            per(rotation),
            per(translation)
        );
        if model.name() == "origin-plane fma ccw rcp f32 y-down" {
            llvmpipe_breaks = (rotation, translation);
        }
        assert!(samples > 10_000, "{samples}");
    }
    assert!(llvmpipe_breaks.0 > 0 && llvmpipe_breaks.1 > 0, "{llvmpipe_breaks:?}");
}
