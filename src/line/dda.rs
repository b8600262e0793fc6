//! The naive float DDA: step the major axis by one, add the slope `m` to the minor
//! coordinate in floating point, draw the rounded value. Error accumulates with every
//! addition: the fast, inexact end of the trade for lines.

use super::{cover_if_on_canvas, Axes};
use crate::convention::Target;
use crate::coverage::CoverageSink;

macro_rules! dda {
    ($walk:ident, $pixels:ident, $float:ty, $doc:literal) => {
        #[doc = $doc]
        ///
        /// Calls `visit` with each pixel, from `from` to `to`; endpoints within ±2^24.
        #[allow(clippy::cast_possible_truncation, clippy::cast_precision_loss)] // coordinates within ±2^24
        pub fn $walk(from: [i64; 2], to: [i64; 2], mut visit: impl FnMut([i64; 2])) {
            let axes = Axes::of(from, to);
            let (mut major, minor0) = axes.split(from);
            let m: $float = if axes.major_len == 0 {
                0.0
            } else {
                (axes.minor_sign * axes.minor_len) as $float / axes.major_len as $float
            };
            let mut minor = minor0 as $float;
            for _ in 0..=axes.major_len {
                visit(axes.join(major, (minor + 0.5).floor() as i64));
                minor += m;
                major += axes.major_sign;
            }
        }

        #[doc = $doc]
        ///
        /// The pixels in order.
        pub fn $pixels(from: [i64; 2], to: [i64; 2]) -> Vec<[i64; 2]> {
            let mut out = Vec::new();
            $walk(from, to, |p| out.push(p));
            out
        }
    };
}

dda!(
    walk_f32,
    pixels_f32,
    f32,
    "The DDA in f32: `minor += m` per step, pixel `floor(minor + 1/2)`."
);
dda!(
    walk_f64,
    pixels_f64,
    f64,
    "The DDA in f64: `minor += m` per step, pixel `floor(minor + 1/2)`."
);

/// Which float the DDA runs in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DdaFloat {
    /// f32.
    F32,
    /// f64.
    F64,
}

/// Draws the DDA line into `sink`, skipping pixels off the canvas (no allocation).
pub fn rasterize<S: CoverageSink + ?Sized>(
    from: [i64; 2],
    to: [i64; 2],
    float: DdaFloat,
    id: u32,
    target: &Target,
    sink: &mut S,
) {
    let mut visit = |p| cover_if_on_canvas(p, id, target, sink);
    match float {
        DdaFloat::F32 => walk_f32(from, to, &mut visit),
        DdaFloat::F64 => walk_f64(from, to, &mut visit),
    }
}
