//! The diamond-exit rule (D3D11 §3.4.3) in f32 and f64: the plain reading of
//! [`super::exact::diamond_exits`] with every quantity in the float type, as a float
//! renderer would write it. Not exact: the parameters `(r - g0) / g1` of the segment's
//! chord through a diamond are rounded, and a pixel whose chord ends on the diamond's
//! boundary can flip. The float side of the trade for diamond lines.

use glam::{DVec2, Vec2};

use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::raster::{sample_f64, PixelRange};

macro_rules! float_diamond {
    ($contains:ident, $exits:ident, $draw:ident, $vec:ty, $float:ty, $name:literal) => {
        #[doc = concat!("[`super::exact::diamond_contains`] in ", $name, ": whether `(u, v)`, relative to")]
        /// the pixel's sample, is in the diamond test area `|u| + |v| < r` plus the lower
        /// edges and corner (and the right corner for a y-major line).
        pub fn $contains(u: $float, v: $float, r: $float, x_major: bool) -> bool {
            let s = u.abs() + v.abs();
            if s != r {
                return s < r;
            }
            if v != 0.0 {
                v > 0.0
            } else {
                u > 0.0 && !x_major
            }
        }

        #[doc = concat!("[`super::exact::diamond_exits`] in ", $name, " for pixel `(i, j)`: the segment")]
        /// `a -> b` meets the pixel's diamond test area and leaves it.
        pub fn $exits(a: $vec, b: $vec, i: u32, j: u32, target: &Target) -> bool {
            let s = sample_f64(i, j, target);
            #[allow(clippy::cast_possible_truncation)] // canvas samples are exact in f32
            let (cx, cy) = (s.x as $float, s.y as $float);
            let r: $float = 0.5;
            let (dx, dy) = (b.x - a.x, b.y - a.y);
            let x_major = dx.abs() >= dy.abs();
            let (ua, va) = (a.x - cx, a.y - cy);
            if $contains(b.x - cx, b.y - cy, r, x_major) {
                return false; // the end lies in the test area: it never leaves
            }
            let (mut t0, mut t1): ($float, $float) = (0.0, 1.0);
            for (su, sv) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
                // su*u(t) + sv*v(t) <= r, with u(t) = ua + t dx, v(t) = va + t dy
                let g0: $float = su * ua + sv * va;
                let g1: $float = su * dx + sv * dy;
                if g1 == 0.0 {
                    if g0 > r {
                        return false;
                    }
                } else if g1 > 0.0 {
                    t1 = t1.min((r - g0) / g1);
                } else {
                    t0 = t0.max((r - g0) / g1);
                }
            }
            if t0 > t1 {
                return false;
            }
            let mid = (t0 + t1) / 2.0;
            [t0, t1, mid]
                .iter()
                .any(|&t| $contains(ua + t * dx, va + t * dy, r, x_major))
        }

        #[doc = concat!("Draws a diamond-exit line in ", $name, ": every pixel of the segment's bounding")]
        /// box (grown by one) on the canvas is tested, as the exact reading does.
        pub fn $draw<S: CoverageSink + ?Sized>(a: $vec, b: $vec, id: u32, target: &Target, sink: &mut S) {
            #[allow(clippy::cast_possible_truncation)] // `as` saturates; out of range is off the canvas
            let index = |v: $float| f64::from(v).clamp(-1e18, 1e18) as i64;
            let (lo, hi) = (a.min(b), a.max(b));
            let Some(range) = PixelRange::clamped(
                [index(lo.x.floor()) - 1, index(lo.y.floor()) - 1],
                [index(hi.x.ceil()) + 1, index(hi.y.ceil()) + 1],
                target.width,
                target.height,
            ) else {
                return;
            };
            for j in range.y0..=range.y1 {
                for i in range.x0..=range.x1 {
                    if $exits(a, b, i, j, target) {
                        sink.cover(i, j, id);
                    }
                }
            }
        }
    };
}

float_diamond!(
    diamond_contains_f32,
    diamond_exits_f32,
    rasterize_diamond_f32,
    Vec2,
    f32,
    "f32"
);
float_diamond!(
    diamond_contains_f64,
    diamond_exits_f64,
    rasterize_diamond_f64,
    DVec2,
    f64,
    "f64"
);
