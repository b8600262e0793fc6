//! The integer model against the oracle: on any triangle, `Model::Fixed` must cover exactly
//! the pixels `Model::ExactSnapped` covers, or refuse the triangle with
//! `ModelError::Envelope`, and refuse it exactly when a snapped coordinate is beyond
//! 2^29 subpixels. The snapping itself is checked against an independent i128 rounding.

#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;

mod common;
use common::{convention, snap_i128, PresetChoice};
use num_bigint::BigInt;
use num_rational::BigRational;
use rasterproof::convention::Target;
use rasterproof::geom::{Point, Triangle};
use rasterproof::model::{render_triangles, Model, ModelError};
use rasterproof::num::fixed::MAX_SUBPIXEL_MAGNITUDE;

/// One coordinate: `num / den` pixels, placed according to `mode`.
#[derive(Debug, Clone, Copy, Arbitrary)]
struct Coord {
    num: i64,
    /// High bit set: `2^(den % 12)`; otherwise `den & 0x7f`, with 0 read as 1.
    den: u8,
    /// `% 4`: 0 as written; 1 and 3 folded onto the canvas and a margin around it;
    /// 2 next to the envelope edge `+-2^29` subpixels.
    mode: u8,
}

#[derive(Debug, Clone, Arbitrary)]
struct Input {
    coords: [Coord; 6],
    preset: PresetChoice,
    /// Optional subpixel-bits override, read as `1 + bits % 16`.
    bits: Option<u8>,
    /// Sample at the pixel corner instead of the centre.
    corner: bool,
    /// Canvas sides, read as `1 + w % 48`.
    width: u8,
    height: u8,
}

impl Coord {
    fn denominator(self) -> i128 {
        if self.den & 0x80 != 0 {
            1 << (self.den % 12)
        } else {
            i128::from((self.den & 0x7f).max(1))
        }
    }

    /// The coordinate as an exact fraction `(numerator, denominator > 0)` of pixels.
    fn fraction(self, bits: u32) -> (i128, i128) {
        let den = self.denominator();
        let num = i128::from(self.num);
        match self.mode % 4 {
            0 => (num, den),
            2 => {
                // +-2^(29 - bits) px (exactly the envelope edge) plus a small offset.
                let edge = i128::from(MAX_SUBPIXEL_MAGNITUDE >> bits);
                let sign = if self.num < 0 { -1 } else { 1 };
                let small = i128::from(self.num as i16);
                (sign * edge * den + small, den)
            }
            _ => (num.rem_euclid(64 * den) - 8 * den, den),
        }
    }
}

fuzz_target!(|input: Input| {
    let conv = convention(input.preset, input.bits, input.corner);
    let bits = conv.subpixel_bits;
    let (w, h) = (1 + u32::from(input.width % 48), 1 + u32::from(input.height % 48));
    let target = Target::new(w, h, conv).expect("sides 1..=48 and bits 1..=16 are valid");

    let fractions = input.coords.map(|c| c.fraction(bits));
    let q = |k: usize| {
        let (n, d) = fractions[k];
        BigRational::new(BigInt::from(n), BigInt::from(d))
    };
    let p = |k: usize| Point::new(q(2 * k), q(2 * k + 1));
    let triangle = Triangle::new(p(0), p(1), p(2));

    // Snapping, checked independently.
    let snapped = triangle.snapped(&conv);
    assert_eq!(snapped.bits, bits);
    for (k, &(n, d)) in fractions.iter().enumerate() {
        let expected = BigInt::from(snap_i128(n, d, bits, conv.rounding));
        assert_eq!(snapped.v[k / 2][k % 2], expected, "snap of coordinate {k} ({n}/{d})");
    }
    // The first snapped coordinate (v0.x, v0.y, v1.x, ...) outside the envelope, if any.
    let (hi, lo) = (
        BigInt::from(MAX_SUBPIXEL_MAGNITUDE),
        BigInt::from(-MAX_SUBPIXEL_MAGNITUDE),
    );
    let first_outside = (0..6).find(|&k| {
        let s = &snapped.v[k / 2][k % 2];
        s > &hi || s < &lo
    });

    let exact = render_triangles(std::slice::from_ref(&triangle), &target, Model::ExactSnapped)
        .expect("the exact-snapped model takes every triangle");
    match render_triangles(std::slice::from_ref(&triangle), &target, Model::Fixed) {
        Ok(fixed) => {
            assert_eq!(first_outside, None, "fixed accepted a coordinate beyond 2^29 subpixels");
            assert_eq!(fixed, exact, "fixed and exact-snapped disagree on {triangle:?}");
        }
        Err(ModelError::Envelope {
            triangle: t,
            vertex,
            axis,
            error,
        }) => {
            let k = first_outside.expect("envelope error with every coordinate inside 2^29");
            assert_eq!(t, 0);
            assert_eq!((vertex, axis), (k / 2, if k % 2 == 0 { 'x' } else { 'y' }));
            assert_eq!(error.subpixels, snapped.v[k / 2][k % 2]);
            assert_eq!(error.bits, bits);
        }
        Err(e) => panic!("fixed model failed with a non-envelope error: {e}"),
    }
});
