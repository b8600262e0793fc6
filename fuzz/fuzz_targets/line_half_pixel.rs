//! Lines against their definitions, in exact rationals written here (independent of
//! `rasterproof::line::exact`):
//!
//! 1. Integer Bresenham (`bresenham::pixels`), for endpoints within ±2000 and either tie
//!    convention: `max(|dx|, |dy|) + 1` pixels from `from` to `to`, 8-connected, none
//!    twice, one per step of the major axis (x when `|dx| >= |dy|`), each within 1/2 pixel
//!    of the ideal line on the minor axis; at an exact tie (distance exactly 1/2) `Stay`
//!    keeps the candidate nearer the start on the minor axis and `Step` the farther one;
//!    and `to -> from` with the other convention is the same pixels in reverse.
//! 2. Diamond-exit lines with fractional endpoints (small numerators over powers of two,
//!    canvases up to 24x24, presets d3d11/gl/cts, optional subpixel-bits and pixel-corner
//!    overrides): `Model::Fixed` equals `Model::ExactSnapped` pixel for pixel, or fails with
//!    `ModelError::LineEnvelope` exactly when a snapped coordinate exceeds 2^29 subpixels.
//! 3. The naive float DDA (`line::dda`, f32 and f64) on the Bresenham endpoints: one pixel
//!    per major step from `from`, 8-connected, `max(|dx|, |dy|) + 1` of them, ending at
//!    `to` in f64; the float models draw both kinds of line without panicking.

#![no_main]

use std::collections::HashSet;

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;

mod common;
use common::{convention, snap_i128, PresetChoice};
use num_bigint::BigInt;
use num_rational::BigRational;
use rasterproof::check::{
    check_diamond_agreement, check_line_pixels, check_line_reference, check_line_symmetry, line_departures,
};
use rasterproof::convention::Target;
use rasterproof::geom::Point;
use rasterproof::line::{bresenham, dda, BresenhamTie, Line, LineRule};
use rasterproof::model::{render, Model, ModelError, Primitives};
use rasterproof::num::fixed::MAX_SUBPIXEL_MAGNITUDE;

/// The largest |Bresenham endpoint coordinate| drawn (keeps each run fast).
const MAX_COORD: i64 = 2000;

#[derive(Debug, Clone, Copy, Arbitrary)]
enum Tie {
    Stay,
    Step,
}

/// One diamond-line coordinate: `num / 2^(den_exp % 11)` pixels, placed by `mode`.
#[derive(Debug, Clone, Copy, Arbitrary)]
struct Coord {
    num: i32,
    den_exp: u8,
    /// `% 8`: 7 next to the envelope edge `±2^29` subpixels; otherwise folded onto the
    /// canvas and a margin of 4 px around it.
    mode: u8,
}

#[derive(Debug, Clone, Arbitrary)]
struct Input {
    from: [i16; 2],
    to: [i16; 2],
    tie: Tie,
    diamond: [Coord; 4],
    preset: PresetChoice,
    /// Optional subpixel-bits override, read as `1 + bits % 16`.
    bits: Option<u8>,
    /// Sample at the pixel corner instead of the centre.
    corner: bool,
    /// Canvas sides, read as `1 + w % 24`.
    width: u8,
    height: u8,
}

fn fold(v: i16) -> i64 {
    i64::from(v) % (MAX_COORD + 1)
}

fn check_bresenham(from: [i64; 2], to: [i64; 2], tie: BresenhamTie) {
    let pixels = bresenham::pixels(from, to, tie);
    let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
    let len = dx.abs().max(dy.abs());
    let ctx = format!("{from:?} -> {to:?} {tie:?}");
    assert_eq!(pixels.len() as i64, len + 1, "{ctx}: pixel count");
    assert_eq!(pixels[0], from, "{ctx}: first pixel");
    assert_eq!(*pixels.last().unwrap(), to, "{ctx}: last pixel");
    for w in pixels.windows(2) {
        let cheb = (w[1][0] - w[0][0]).abs().max((w[1][1] - w[0][1]).abs());
        assert_eq!(cheb, 1, "{ctx}: {:?} -> {:?} not a king's move", w[0], w[1]);
    }
    let distinct: HashSet<[i64; 2]> = pixels.iter().copied().collect();
    assert_eq!(distinct.len(), pixels.len(), "{ctx}: a pixel drawn twice");
    // Walking back with the other convention picks the same candidate at every tie (the
    // one nearer `from`, or the one nearer `to`): the same pixels, reversed.
    let other = match tie {
        BresenhamTie::Stay => BresenhamTie::Step,
        BresenhamTie::Step => BresenhamTie::Stay,
    };
    let mut back = bresenham::pixels(to, from, other);
    back.reverse();
    assert_eq!(back, pixels, "{ctx}: not the reverse of {to:?} -> {from:?} {other:?}");

    if len <= 64 {
        crate_checkers(from, to, tie, &pixels, &ctx);
    }

    // (major, minor) by |dx| >= |dy|; the ideal line is minor(k) = minor0 + k * dmin / len.
    let x_major = dx.abs() >= dy.abs();
    let split = |p: [i64; 2]| if x_major { (p[0], p[1]) } else { (p[1], p[0]) };
    let (major0, minor0) = split(from);
    let (major1, minor1) = split(to);
    let (major_sign, dmin) = ((major1 - major0).signum(), minor1 - minor0);
    // Every value of a line is kept over the one denominator 2 * len (unreduced), so each
    // comparison is exact and costs one integer comparison (no gcd per step).
    let l = len.max(1);
    let over = |numerator: i64| BigRational::new_raw(BigInt::from(numerator), BigInt::from(2 * l));
    let (zero, half) = (over(0), over(l));
    for (k, &p) in pixels.iter().enumerate() {
        let k = k as i64;
        let (major, minor) = split(p);
        assert_eq!(major, major0 + k * major_sign, "{ctx}: step {k} is {p:?}");
        // ideal minor(k) = (minor0 * len + k * dmin) / len, exactly
        let ideal = || BigRational::new(BigInt::from(minor0 * l + k * dmin), BigInt::from(l));
        let off = over(2 * (minor * l - (minor0 * l + k * dmin))); // signed, on the minor axis
        let dist = if off < zero { -off.clone() } else { off.clone() };
        assert!(
            dist <= half,
            "{ctx}: step {k} pixel {p:?} is {} from the ideal minor {}",
            dist.reduced(),
            ideal()
        );
        if dist == half {
            // toward the end when off has the sign of the minor direction
            let toward_end = (off > zero) == (dmin > 0);
            let want_toward_end = matches!(tie, BresenhamTie::Step);
            assert_eq!(
                toward_end,
                want_toward_end,
                "{ctx}: tie at step {k} (ideal {}) resolved to {p:?}",
                ideal()
            );
        }
    }
}

/// The crate's own line checkers (`check::line`, what `check` runs) accept these pixels
/// and refuse them with one pixel moved two off the line on the minor axis. Called on
/// lines of at most 64 steps: they read the ideal line in BigRational (40 ms a 4000-step
/// line, which would take the target from thousands of inputs a second to tens).
fn crate_checkers(from: [i64; 2], to: [i64; 2], tie: BresenhamTie, pixels: &[[i64; 2]], ctx: &str) {
    let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
    check_line_pixels(from, to, pixels).unwrap_or_else(|v| panic!("{ctx}: {v}"));
    check_line_reference(from, to, tie, pixels).unwrap_or_else(|v| panic!("{ctx}: {v}"));
    check_line_symmetry(from, to, tie).unwrap_or_else(|v| panic!("{ctx}: {v}"));
    assert_eq!(line_departures(from, to, pixels), 0, "{ctx}");
    if pixels.len() > 2 {
        let mut moved = pixels.to_vec();
        let k = pixels.len() / 2;
        let minor = usize::from(dx.abs() >= dy.abs());
        moved[k][minor] += 2;
        assert!(
            check_line_pixels(from, to, &moved).is_err(),
            "{ctx}: moved pixel {k} accepted"
        );
        assert!(
            check_line_reference(from, to, tie, &moved).is_err(),
            "{ctx}: moved pixel {k} accepted"
        );
        assert!(
            line_departures(from, to, &moved) > 0,
            "{ctx}: moved pixel {k} not counted"
        );
    }
}

impl Coord {
    /// `(numerator, denominator)` in pixels.
    fn fraction(self, bits: u32, side: u32) -> (i128, i128) {
        let den = 1i128 << (self.den_exp % 11);
        let num = i128::from(self.num);
        if self.mode % 8 == 7 {
            let edge = i128::from(MAX_SUBPIXEL_MAGNITUDE >> bits);
            let sign = if self.num < 0 { -1 } else { 1 };
            (sign * edge * den + i128::from(self.num as i16), den)
        } else {
            let span = (i128::from(side) + 8) * den;
            (num.rem_euclid(span) - 4 * den, den)
        }
    }
}

fn check_diamond(input: &Input) -> (Line, Target) {
    let conv = convention(input.preset, input.bits, input.corner);
    let bits = conv.subpixel_bits;
    let (w, h) = (1 + u32::from(input.width % 24), 1 + u32::from(input.height % 24));
    let target = Target::new(w, h, conv).expect("sides 1..=24 and bits 1..=16 are valid");
    let sides = [w, h, w, h];
    let fractions: [(i128, i128); 4] = std::array::from_fn(|k| input.diamond[k].fraction(bits, sides[k]));
    let r = |k: usize| BigRational::new(BigInt::from(fractions[k].0), BigInt::from(fractions[k].1));
    let line = Line {
        from: Point::new(r(0), r(1)),
        to: Point::new(r(2), r(3)),
        rule: LineRule::Diamond,
    };
    // from.x, from.y, to.x, to.y: the first snapped coordinate beyond the envelope
    let limit = i128::from(MAX_SUBPIXEL_MAGNITUDE);
    let snapped = fractions.map(|(n, d)| snap_i128(n, d, bits, conv.rounding));
    let first_outside = (0..4).find(|&k| snapped[k].abs() > limit);

    let lines = std::slice::from_ref(&line);
    let exact = render(
        &Primitives {
            lines: lines.to_vec(),
            ..Primitives::default()
        },
        &target,
        Model::ExactSnapped,
    )
    .expect("exact-snapped takes every diamond line");
    match render(
        &Primitives {
            lines: lines.to_vec(),
            ..Primitives::default()
        },
        &target,
        Model::Fixed,
    ) {
        Ok(fixed) => {
            assert_eq!(first_outside, None, "fixed accepted a coordinate beyond 2^29 subpixels");
            assert_eq!(
                fixed, exact,
                "fixed and exact-snapped disagree on {line:?} ({target:?})"
            );
            // And so says the crate's checker (`check::line`).
            check_diamond_agreement(&line, Model::Fixed, &target).unwrap_or_else(|v| panic!("{v}"));
        }
        Err(ModelError::LineEnvelope {
            line: l,
            end,
            axis,
            error,
        }) => {
            let k = first_outside.expect("envelope error with every coordinate inside 2^29");
            assert_eq!(l, 0);
            assert_eq!(
                (end, axis),
                (if k < 2 { "from" } else { "to" }, if k % 2 == 0 { 'x' } else { 'y' })
            );
            assert_eq!(error.subpixels, BigInt::from(snapped[k]));
            assert_eq!(error.bits, bits);
        }
        Err(e) => panic!("fixed model failed with a non-envelope error: {e}"),
    }
    (line, target)
}

/// The naive float DDA (`line::dda`) on the same endpoints: not within 1/2 pixel (that is
/// its measured error), but one pixel per major step from `from`, each a king's move from
/// the last (|slope| <= 1), `max(|dx|, |dy|) + 1` of them, ending at `to` in f64 (its
/// accumulated error over at most 4000 steps stays far below 1/2 pixel).
fn check_dda(from: [i64; 2], to: [i64; 2]) {
    let len = (to[0] - from[0]).abs().max((to[1] - from[1]).abs());
    for (name, pixels) in [("f32", dda::pixels_f32(from, to)), ("f64", dda::pixels_f64(from, to))] {
        let ctx = format!("{name} DDA {from:?} -> {to:?}");
        assert_eq!(pixels.len() as i64, len + 1, "{ctx}: pixel count");
        assert_eq!(pixels[0], from, "{ctx}: first pixel");
        for w in pixels.windows(2) {
            let cheb = (w[1][0] - w[0][0]).abs().max((w[1][1] - w[0][1]).abs());
            assert_eq!(cheb, 1, "{ctx}: {:?} -> {:?} not a king's move", w[0], w[1]);
        }
        if name == "f64" {
            assert_eq!(*pixels.last().unwrap(), to, "{ctx}: last pixel");
        }
    }
}

/// The float models draw both kinds of line without panicking (a DDA for Bresenham
/// lines, the diamond test in floats for diamond-exit ones).
fn float_lines(from: [i64; 2], to: [i64; 2], diamond: &Line, target: &Target) {
    let bresenham = Line {
        from: Point::from_ints(from[0], from[1]),
        to: Point::from_ints(to[0], to[1]),
        rule: LineRule::Bresenham(BresenhamTie::Stay),
    };
    let lines = vec![bresenham, diamond.clone()];
    for m in [Model::Float32, Model::Float64, Model::Float32Naive, Model::Float64Naive] {
        let _ = render(
            &Primitives {
                lines: lines.clone(),
                ..Primitives::default()
            },
            target,
            m,
        );
    }
}

fuzz_target!(|input: Input| {
    let tie = match input.tie {
        Tie::Stay => BresenhamTie::Stay,
        Tie::Step => BresenhamTie::Step,
    };
    check_bresenham(input.from.map(fold), input.to.map(fold), tie);
    check_dda(input.from.map(fold), input.to.map(fold));
    let (diamond, target) = check_diamond(&input);
    float_lines(input.from.map(fold), input.to.map(fold), &diamond, &target);
});
