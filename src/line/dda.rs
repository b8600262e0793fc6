//! The float DDA of seed 002: step the major axis by one, add the slope `m` to the minor
//! coordinate in floating point, draw the rounded value. Error accumulates with every
//! addition: the fast, inexact end of the trade for lines.

use super::{cover_if_on_canvas, Axes};
use crate::convention::Target;
use crate::coverage::CoverageSink;

macro_rules! dda {
    ($name:ident, $float:ty, $doc:literal) => {
        #[doc = $doc]
        #[allow(clippy::cast_possible_truncation, clippy::cast_precision_loss)] // coordinates within ±2^24
        pub fn $name(from: [i64; 2], to: [i64; 2]) -> Vec<[i64; 2]> {
            let axes = Axes::of(from, to);
            let (mut major, minor0) = axes.split(from);
            let m: $float = if axes.major_len == 0 {
                0.0
            } else {
                (axes.minor_sign * axes.minor_len) as $float / axes.major_len as $float
            };
            let mut minor = minor0 as $float;
            let mut out = Vec::with_capacity(usize::try_from(axes.major_len + 1).unwrap_or(0));
            for _ in 0..=axes.major_len {
                out.push(axes.join(major, (minor + 0.5).floor() as i64));
                minor += m;
                major += axes.major_sign;
            }
            out
        }
    };
}

dda!(
    pixels_f32,
    f32,
    "The DDA in f32: `minor += m` per step, pixel `floor(minor + 1/2)`."
);
dda!(
    pixels_f64,
    f64,
    "The DDA in f64: `minor += m` per step, pixel `floor(minor + 1/2)`."
);

/// Draws `pixels` (from [`pixels_f32`] or [`pixels_f64`]) into `sink`, skipping those off the canvas.
pub fn draw<S: CoverageSink + ?Sized>(pixels: &[[i64; 2]], id: u32, target: &Target, sink: &mut S) {
    for &p in pixels {
        cover_if_on_canvas(p, id, target, sink);
    }
}
