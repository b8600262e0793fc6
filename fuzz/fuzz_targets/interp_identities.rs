//! Barycentrics and interpolation (`rasterproof::interp`), their identities checked on
//! any triangle and point (rational coordinates with 32-bit numerators and
//! denominators, zero-area triangles included):
//!
//! 1. Exact: `barycentric_exact` is `None` exactly for zero area; otherwise the λ sum to
//!    exactly 1, `Σ λ_i v_i == p` on both axes, and at a vertex they are one-hot.
//! 2. `Plane::setup` (Luebke's 3x3 solve) is `None` exactly for zero area; the plane takes
//!    each vertex's value there, and at `p` equals `Σ λ_i value_i`.
//! 3. `gouraud_exact == Σ λ_i c_i` per channel, and `to_channel` rounds it half-to-even
//!    and clamps to 0..=255 (checked against a rounding written here).
//! 4. Integer: for the snapped triangle, inside the envelope, at any `u32` pixel (on the
//!    canvas or far off it), `barycentric_fixed`'s w sum to twice the area, and each `w_i`
//!    is the exact edge function at the exact sample times 4^bits.
//! 5. The models' Gouraud colours (`PreparedScene::shade`): `exact` and `exact-snapped`
//!    give `to_channel(gouraud_exact)` of the triangle as written / snapped; `fixed` and
//!    `scanline` equal `exact-snapped`.
//! 6. Floats: on a triangle of 1/16-px coordinates within ±2^10 px (every edge value
//!    exact in f64), `gouraud_f64` is `None` exactly when the area is zero and within 1
//!    of the exact channel; the f32 forms and `float_sum_error_ulps` never panic.
//!
//! `Debug` is the input struct (Rust).

#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;

mod common;
use common::{convention, PresetChoice};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use rasterproof::check::{check_barycentric_exact, check_barycentric_fixed, float_sum_error_ulps};
use rasterproof::convention::Target;
use rasterproof::edge::exact::{area2, edge_function};
use rasterproof::geom::{Point, Rgb, Triangle};
use rasterproof::interp::{
    barycentric_exact, barycentric_f32, barycentric_fixed, gouraud_exact, gouraud_f32, gouraud_f64, to_channel, Plane,
};
use rasterproof::model::{prepare, Model, Primitives};
use rasterproof::raster::{sample_exact, sample_f32, sample_f64};

/// `num / den`: `den` is `2^(d % 32)` when its high bit is set, else `1 + d`. (32-bit
/// numerators and denominators: the identities are algebraic, and wider ones only make
/// each gcd slower.)
#[derive(Debug, Clone, Copy, Arbitrary)]
struct Coord {
    num: i32,
    d: u8,
}

impl Coord {
    fn value(self) -> BigRational {
        let den = if self.d & 0x80 != 0 {
            BigInt::one() << (self.d % 32)
        } else {
            BigInt::from(1 + u32::from(self.d))
        };
        BigRational::new(BigInt::from(self.num), den)
    }
}

#[derive(Debug, Clone, Arbitrary)]
struct Input {
    v: [[Coord; 2]; 3],
    p: [Coord; 2],
    values: [i32; 3],
    colours: [Rgb; 3],
    preset: PresetChoice,
    bits: Option<u8>,
    corner: bool,
    /// Any pixel, for the integer edge values.
    pixel: (u32, u32),
    /// The float triangle: `v / 16` px, `v` folded into ±2^14.
    small: [[i16; 2]; 3],
    /// Its sample: pixel `(x % 16, y % 16)` of a 16x16 canvas.
    sample: (u8, u8),
}

fn q(n: i64) -> BigRational {
    BigRational::from_integer(BigInt::from(n))
}

/// Round half to even, then clamp to 0..=255, written out independently.
fn channel(c: &BigRational) -> u8 {
    let floor = c.floor();
    let frac = c - &floor;
    let half = BigRational::new(BigInt::one(), BigInt::from(2));
    let mut r = floor.to_integer();
    if frac > half || (frac == half && (&r % 2u8) != BigInt::zero()) {
        r += 1;
    }
    u8::try_from(r.clamp(BigInt::zero(), BigInt::from(255))).expect("clamped")
}

fn exact_identities(t: &Triangle, p: &Point, input: &Input) {
    let zero_area = area2(t).is_zero();
    check_barycentric_exact(t, p).unwrap_or_else(|v| panic!("{v}"));
    let bary = barycentric_exact(t, p);
    assert_eq!(
        bary.is_none(),
        zero_area,
        "barycentrics exist exactly for non-zero area"
    );
    let values = input.values.map(|v| q(i64::from(v)));
    let plane = Plane::setup(t, &values);
    assert_eq!(plane.is_none(), zero_area, "the plane exists exactly for non-zero area");
    let (Some(l), Some(plane)) = (bary, plane) else {
        assert!(gouraud_exact(t, &input.colours, p).is_none());
        return;
    };
    assert_eq!(&l[0] + &l[1] + &l[2], q(1));
    let along = |f: &dyn Fn(&Point) -> &BigRational| (0..3).fold(q(0), |acc, i| acc + &l[i] * f(&t.v[i]));
    assert_eq!(along(&|v| &v.x), p.x, "Σ λ_i x_i != x");
    assert_eq!(along(&|v| &v.y), p.y, "Σ λ_i y_i != y");
    for (k, (v, value)) in t.v.iter().zip(&values).enumerate() {
        let at_vertex = barycentric_exact(t, v).expect("non-zero area");
        for (i, li) in at_vertex.iter().enumerate() {
            assert_eq!(*li, q(i64::from(i == k)), "λ at vertex {k} not one-hot");
        }
        assert_eq!(plane.eval(v), *value, "the plane misses vertex {k}'s value");
    }
    let weighted = (0..3).fold(q(0), |acc, i| acc + &l[i] * &values[i]);
    assert_eq!(plane.eval(p), weighted, "plane != Σ λ_i value_i");
    let colour = gouraud_exact(t, &input.colours, p).expect("non-zero area");
    for (ch, c) in colour.iter().enumerate() {
        let want = (0..3).fold(q(0), |acc, i| acc + &l[i] * q(i64::from(input.colours[i][ch])));
        assert_eq!(*c, want, "gouraud channel {ch}");
        assert_eq!(to_channel(c), channel(c), "to_channel of {c}");
    }
}

fn fixed_identities(t: &Triangle, input: &Input, target: &Target) {
    let snapped = t.snapped(&target.convention);
    let Ok(fixed) = snapped.to_fixed() else {
        return; // outside the envelope
    };
    let (x, y) = input.pixel;
    check_barycentric_fixed(&fixed, x, y, target).unwrap_or_else(|v| panic!("{v}"));
    let b = barycentric_fixed(&fixed, x, y, target);
    let exact = fixed.to_exact();
    let [v0, v1, v2] = &exact.v;
    let p = sample_exact(x, y, target);
    let scale = BigRational::from_integer(BigInt::one() << (2 * target.convention.subpixel_bits));
    let want = [
        edge_function(v1, v2, &p),
        edge_function(v2, v0, &p),
        edge_function(v0, v1, &p),
    ];
    for (i, (w, e)) in b.w.iter().zip(&want).enumerate() {
        assert_eq!(
            BigRational::from_integer((*w).into()),
            e * &scale,
            "w[{i}] at ({x}, {y})"
        );
    }
    assert_eq!(BigRational::from_integer(b.area2.into()), area2(&exact) * &scale);
}

fn shades(t: &Triangle, input: &Input, target: &Target) {
    let (x, y) = (
        u32::from(input.sample.0) % target.width,
        u32::from(input.sample.1) % target.height,
    );
    let one = Primitives::from_triangles(std::slice::from_ref(t));
    let shade = |m: Model| {
        prepare(&one, target, m)
            .ok()
            .map(|p| p.shade(0, &input.colours, x, y, target))
    };
    let at = sample_exact(x, y, target);
    let expect = |tri: &Triangle| gouraud_exact(tri, &input.colours, &at).map_or([0; 3], |c| c.each_ref().map(channel));
    assert_eq!(shade(Model::Exact), Some(expect(t)), "exact shade");
    let snapped = shade(Model::ExactSnapped);
    assert_eq!(
        snapped,
        Some(expect(&t.snapped(&target.convention).to_exact())),
        "exact-snapped shade"
    );
    for m in [Model::Fixed, Model::Scanline] {
        if let Some(c) = shade(m) {
            assert_eq!(Some(c), snapped, "{m} shade differs from exact-snapped");
        }
    }
    for m in [Model::Float32, Model::Float64, Model::Float32Naive, Model::Float64Naive] {
        let _ = shade(m);
    }
}

fn floats(input: &Input, target: &Target) {
    let v: Vec<Point> = input
        .small
        .iter()
        .map(|c| {
            let f = |n: i16| i64::from(n).rem_euclid(1 << 15) - (1 << 14);
            Point::from_fractions(f(c[0]), 16, f(c[1]), 16)
        })
        .collect();
    let t = Triangle::new(v[0].clone(), v[1].clone(), v[2].clone());
    let (x, y) = (u32::from(input.sample.0) % 16, u32::from(input.sample.1) % 16);
    let exact = gouraud_exact(&t, &input.colours, &sample_exact(x, y, target)).map(|c| c.each_ref().map(channel));
    let t64 = t.to_f64().expect("small dyadics fit f64");
    let float = gouraud_f64(&t64, &input.colours, sample_f64(x, y, target));
    match (exact, float) {
        (None, None) => {}
        (Some(e), Some(f)) => {
            for ch in 0..3 {
                assert!(
                    e[ch].abs_diff(f[ch]) <= 1,
                    "f64 Gouraud {f:?} vs exact {e:?} on {t:?} at ({x}, {y})"
                );
            }
        }
        (e, f) => panic!("exact {e:?}, f64 {f:?}: the f64 area of an exactly representable triangle is wrong"),
    }
    let t32 = t.to_f32().expect("small dyadics fit f32");
    let _ = gouraud_f32(&t32, &input.colours, sample_f32(x, y, target));
    let _ = barycentric_f32(&t32, sample_f32(x, y, target));
    if let Some(u) = float_sum_error_ulps(&t, &sample_exact(x, y, target)) {
        assert!(u >= 0.0 || u.is_nan(), "ulps {u}");
    }
}

fuzz_target!(|input: Input| {
    let conv = convention(input.preset, input.bits, input.corner);
    let target = Target::new(16, 16, conv).expect("valid");
    let point = |c: &[Coord; 2]| Point::new(c[0].value(), c[1].value());
    let t = Triangle::new(point(&input.v[0]), point(&input.v[1]), point(&input.v[2]));
    let p = point(&input.p);
    exact_identities(&t, &p, &input);
    fixed_identities(&t, &input, &target);
    shades(&t, &input, &target);
    floats(&input, &target);
});
