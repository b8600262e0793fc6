//! Interpolated values (`interp::values`, `interp::planned`, `interp::envelope`,
//! `check::values`) on any window-space triangle of the 1/256 grid within ±128 px (w from
//! 1/4 to 8, zero-area triangles included) and any pixel near it:
//!
//! 1. The invariants of `check::values` hold for the exact definition: hull, rotation,
//!    translation (by any offset of the 1/256 grid), a shared edge, flat copies.
//! 2. The planned value (`PlannedValue`) at the pixel's centre is the plain one, and so is
//!    its nearest f32; so is the f64 filter's (`FastPlan`) wherever it decides one (a
//!    pixel at a time, four at a time, and by the exact inputs' sign).
//! 3. Every float model of `interp::float` lands within the envelope's `far` bound.
//!
//! `Debug` is the input struct (Rust).

#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive};
use rasterproof::check::{
    check_values_flat, check_values_hull, check_values_rotation, check_values_shared_edge, check_values_translation,
};
use rasterproof::geom::Point;
use rasterproof::interp::envelope::value_envelope;
use rasterproof::interp::float::{FloatInterpolator, FloatTriangle};
use rasterproof::interp::planned::{FastPlan, PlannedValue, TriangleF64};
use rasterproof::interp::values::{Interpolation, ProvokingVertex, ValueSetup, ValueTriangle};
use rasterproof::num::exact::nearest_f32;

#[derive(Debug, Clone, Arbitrary)]
struct Input {
    /// Vertices in 1/256 px, folded into 0..2^15 (0..128 px).
    v: [[u16; 2]; 3],
    /// Each w: 2^(e % 6 - 2).
    w: [u8; 3],
    /// Each vertex's two values over 8.
    values: [[i16; 2]; 3],
    /// The pixel: (x % 160, y % 160).
    pixel: (u8, u8),
    interpolation: u8,
    last: bool,
    /// A translation in 1/256 px.
    shift: (i16, i16),
    /// The fourth vertex of a triangle on the edge 0-1, and where on the edge (of 16).
    fourth: [u16; 2],
    along: u8,
}

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

fuzz_target!(|input: Input| {
    let coord = |c: u16| q(i64::from(c % (1 << 15)), 256);
    let points = input.v.map(|[x, y]| Point::new(coord(x), coord(y)));
    let w = input.w.map(|e| {
        let e = i32::from(e % 6) - 2;
        if e >= 0 { q(1 << e, 1) } else { q(1, 1 << -e) }
    });
    let values = input.values.map(|v| v.iter().map(|&c| q(i64::from(c), 8)).collect::<Vec<_>>());
    let t = ValueTriangle::window([&points[0], &points[1], &points[2]], [&w[0], &w[1], &w[2]], values.clone());
    let interpolation = Interpolation::ALL[usize::from(input.interpolation % 3)];
    let provoking = if input.last { ProvokingVertex::Last } else { ProvokingVertex::First };
    let (px, py) = (u32::from(input.pixel.0 % 160), u32::from(input.pixel.1 % 160));
    let p = Point::new(q(2 * i64::from(px) + 1, 2), q(2 * i64::from(py) + 1, 2));

    // 1. The invariants.
    check_values_hull(&t, interpolation, 0..2, &p).unwrap();
    check_values_rotation(&t, interpolation, 0..2, &p).unwrap();
    let (dx, dy) = (q(i64::from(input.shift.0), 256), q(i64::from(input.shift.1), 256));
    check_values_translation(&t, interpolation, provoking, 0..2, &p, (&dx, &dy)).unwrap();
    check_values_flat(&t, provoking, 0..2, &p).unwrap();
    let mut other = t.clone();
    other.h[2] = [coord(input.fourth[0]), coord(input.fourth[1]), q(1, 1)];
    check_values_shared_edge(&t, &other, ((0, 1), (0, 1)), interpolation, 0..2, &q(i64::from(input.along % 17), 16))
        .unwrap();

    // 2. Planned against plain.
    let setup = ValueSetup::Triangle(Box::new(t.clone()));
    for c in 0..2 {
        let plain = setup.value(interpolation, provoking, c..c + 1, &p).map(|v| v[0].clone());
        let planned = PlannedValue::new(&setup, interpolation, provoking, c, &q(1, 2));
        assert_eq!(planned.exact(px, py), plain);
        assert_eq!(planned.nearest_f32(px, py), plain.clone().map(|v| nearest_f32(&v)));
    }
    if let Some(t64) = TriangleF64::of(&setup, 0..2) {
        let fast = FastPlan::new(&t64, interpolation, provoking, (0.5, 0.5));
        let mut out = [None; 2];
        fast.nearest_f32(px, py, &mut out);
        let mut four = [[0.0f32; 4]; 4];
        let undecided = fast.nearest_f32_x4([px; 4], [py; 4], &mut four);
        for (c, decided) in out.iter().enumerate() {
            let plain = || setup.value(interpolation, provoking, c..c + 1, &p).map(|v| nearest_f32(&v[0]));
            if let Some(f) = decided {
                assert_eq!(plain(), Ok(Some(*f)), "channel {c}");
            }
            if undecided & 1 == 0 {
                assert_eq!(plain(), Ok(Some(four[c][0])), "channel {c}, four at once");
            }
            if let Some(f) = fast.nearest_f32_exact(&setup, 0, px, py, c) {
                assert_eq!(plain(), Ok(Some(f)), "channel {c}, the exact inputs' sign");
            }
        }
    }

    // 3. The float models inside the envelope.
    if interpolation == Interpolation::Flat {
        return;
    }
    let f = |r: &BigRational| nearest_f32(r).expect("small");
    let tri = FloatTriangle {
        x: points.clone().map(|p| f(&p.x)),
        y: points.map(|p| f(&p.y)),
        inv_w: w.map(|w| 1.0 / f(&w)),
        values: values.map(|v| v.iter().map(f).collect()),
    };
    let Ok(exact) = setup.value(interpolation, provoking, 0..2, &p) else { return };
    let envelope = value_envelope(&setup, interpolation, 0..2, &p, 160);
    for model in FloatInterpolator::all().into_iter().filter(FloatInterpolator::enveloped) {
        for c in 0..2 {
            let Some(bound) = envelope[c].far else { continue };
            let v = model.value(&tri, interpolation, provoking, c, (px, py), 160, 0.5);
            let d = (BigRational::from_float(f64::from(v)).expect("finite") - &exact[c]).abs();
            assert!(d.to_f64().expect("finite") <= bound, "{}: {v} against {} (bound {bound})", model.name(), exact[c]);
        }
    }
});
