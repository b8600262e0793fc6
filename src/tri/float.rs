//! Float rasterizers with glam (Scratchapixel style): bounding box, three float
//! edge functions per sample. [`FloatRule::Naive`] is Scratchapixel's `w >= 0` test (samples on
//! a shared edge go to both triangles); [`FloatRule::WithTieRule`] applies the convention's
//! inclusive flags to the float values. Neither is exact: rounding in the products moves
//! samples across edges, and the harness counts how often.

use glam::{DVec2, Vec2};

use crate::convention::{Convention, Target};
use crate::coverage::CoverageSink;
use crate::edge::float::{edge_f32, edge_f64, is_inclusive};
use crate::raster::float_sample_range_at;

/// How a float model decides a sample with `w == 0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FloatRule {
    /// `w >= 0` on all edges (Scratchapixel, "Rasterization: a Practical Implementation", as written).
    Naive,
    /// `w > 0`, or `w == 0` on an edge the tie rule makes inclusive.
    WithTieRule,
}

/// The largest |origin| of [`rasterize_f32_at`] / [`rasterize_f64_at`] on each axis:
/// `origin + i + c` (i < 2^14, c = 0 or 1/2) then needs at most 42 bits, exact in f64.
pub(crate) const MAX_SAMPLE_ORIGIN: i64 = 1 << 40;

macro_rules! float_rasterizer {
    ($name:ident, $at:ident, $vec:ty, $float:ty, $edge:ident, $doc:literal) => {
        #[doc = $doc]
        pub fn $name<S: CoverageSink + ?Sized>(
            tri: &[$vec; 3],
            id: u32,
            target: &Target,
            rule: FloatRule,
            sink: &mut S,
        ) {
            $at(tri, id, [0, 0], target, rule, sink);
        }

        /// The same rasterizer over a canvas-sized window of the plane whose first pixel
        /// is pixel `origin` (each |origin| at most [`MAX_SAMPLE_ORIGIN`]): output pixel
        /// `(i, j)` is sampled at `origin + (i, j) + c`, computed exactly in f64 and rounded
        /// once to the model's type, as the canvas sample is. `origin = [0, 0]` is the
        /// model itself; `trade` uses the rest for windows no canvas reaches.
        pub(crate) fn $at<S: CoverageSink + ?Sized>(
            tri: &[$vec; 3],
            id: u32,
            origin: [i64; 2],
            target: &Target,
            rule: FloatRule,
            sink: &mut S,
        ) {
            debug_assert!(origin.iter().all(|o| o.abs() <= MAX_SAMPLE_ORIGIN), "{origin:?}");
            let [v0, mut v1, mut v2] = *tri;
            let area = $edge(v0, v1, v2);
            if area == 0.0 || !area.is_finite() {
                return;
            }
            if area < 0.0 {
                std::mem::swap(&mut v1, &mut v2);
            }
            let conv = &target.convention;
            let inclusive = |a: $vec, b: $vec| match rule {
                FloatRule::Naive => true,
                FloatRule::WithTieRule => is_inclusive(
                    [f64::from(a.x), f64::from(a.y)],
                    [f64::from(b.x), f64::from(b.y)],
                    conv.tie_rule,
                ),
            };
            let incl = [inclusive(v1, v2), inclusive(v2, v0), inclusive(v0, v1)];
            let min = v0.min(v1).min(v2);
            let max = v0.max(v1).max(v2);
            let wide = |v: $vec| [f64::from(v.x), f64::from(v.y)];
            let Some(range) = float_sample_range_at(wide(min), wide(max), origin, target) else {
                return;
            };
            let passes = |w: $float, inclusive: bool| w > 0.0 || (w == 0.0 && inclusive);
            #[allow(clippy::cast_possible_truncation)] // rounding the exact f64 sample to the type is the model's
            for j in range.y0..=range.y1 {
                let sy = sample_at(origin[1], j, conv) as $float;
                for i in range.x0..=range.x1 {
                    let p = <$vec>::new(sample_at(origin[0], i, conv) as $float, sy);
                    let w0 = $edge(v1, v2, p);
                    let w1 = $edge(v2, v0, p);
                    let w2 = $edge(v0, v1, p);
                    if passes(w0, incl[0]) && passes(w1, incl[1]) && passes(w2, incl[2]) {
                        sink.cover(i, j, id);
                    }
                }
            }
        }
    };
}

/// The f64 sample of window pixel `i` on one axis: `origin + i + c`, exact (|origin| <=
/// 2^40); at origin 0, [`crate::raster::sample_f64`]'s.
#[allow(clippy::cast_precision_loss)] // |origin + i| < 2^41: exact in f64
pub(crate) fn sample_at(origin: i64, i: u32, conv: &Convention) -> f64 {
    (origin + i64::from(i)) as f64 + conv.pixel_centre.offset_f64()
}

float_rasterizer!(
    rasterize_f32,
    rasterize_f32_at,
    Vec2,
    f32,
    edge_f32,
    "Scratchapixel's rasterizer in f32. Vertices as given (not snapped)."
);
float_rasterizer!(
    rasterize_f64,
    rasterize_f64_at,
    DVec2,
    f64,
    edge_f64,
    "Scratchapixel's rasterizer in f64. Vertices as given (not snapped)."
);
