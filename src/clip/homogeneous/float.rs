//! The float forms of homogeneous clipping (f32 and f64 with glam): the same planes, cases,
//! divide and interpolation as the exact forms in the parent module, rounded at every step.

use glam::{DMat4, DVec2, DVec3, DVec4, Mat4, Vec2, Vec3, Vec4};
use num_rational::BigRational;

use super::{clip_planes, ClipVertex, DepthRange, NdcY, ProjectError, Viewport};
use crate::clip::sutherland_hodgman::merged;
use crate::interp::{barycentric_f32, barycentric_f64};

/// An object-space point `(x, y, z, 1)` into clip space by `m`, in f64.
///
/// ```
/// use glam::{DMat4, DVec3, DVec4};
/// use rasterproof::clip::homogeneous::transform_f64;
/// let m = DMat4::from_scale(DVec3::new(2.0, 3.0, 4.0));
/// assert_eq!(transform_f64(&m, DVec3::new(1.0, 1.0, 1.0)), DVec4::new(2.0, 3.0, 4.0, 1.0));
/// ```
pub fn transform_f64(m: &DMat4, object: DVec3) -> DVec4 {
    *m * object.extend(1.0)
}

/// An object-space point `(x, y, z, 1)` into clip space by `m`, in f32.
///
/// ```
/// use glam::{Mat4, Vec3, Vec4};
/// use rasterproof::clip::homogeneous::transform_f32;
/// let m = Mat4::from_translation(Vec3::new(1.0, 0.0, 0.0));
/// assert_eq!(transform_f32(&m, Vec3::ZERO), Vec4::new(1.0, 0.0, 0.0, 1.0));
/// ```
pub fn transform_f32(m: &Mat4, object: Vec3) -> Vec4 {
    *m * object.extend(1.0)
}

macro_rules! float_forms {
    (
        float: $float:ty, vec4: $vec4:ty, vec2: $vec2:ty, to_float: $to_float:ident, nearest: $nearest:ident,
        vertex: $vertex:ident, window_vertex: $window_vertex:ident, viewport: $viewport:ident,
        clip: $clip:ident, project: $project:ident, clip_to_window: $clip_to_window:ident,
        interpolate: $interpolate:ident, barycentric: $barycentric:ident, name: $name:literal
    ) => {
        #[doc = concat!("A clip-space vertex in ", $name, ".")]
        #[derive(Debug, Clone, PartialEq)]
        pub struct $vertex {
            /// `(x, y, z, w)`.
            pub pos: $vec4,
            /// The attributes.
            pub attrs: Vec<$float>,
        }

        #[doc = concat!("A window-space vertex in ", $name, " (see [`WindowVertex`](super::WindowVertex)).")]
        #[derive(Debug, Clone, PartialEq)]
        pub struct $window_vertex {
            /// Window position, pixels.
            pub point: $vec2,
            /// Window depth.
            pub z: $float,
            /// `1 / w`.
            pub inv_w: $float,
            /// The attributes.
            pub attrs: Vec<$float>,
        }

        #[doc = concat!("A [`Viewport`] in ", $name, ".")]
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub struct $viewport {
            /// `(x, y)` of the top-left corner.
            pub origin: $vec2,
            /// `(width, height)`.
            pub size: $vec2,
            /// Which NDC y is at the top.
            pub y_axis: NdcY,
            /// The depth range.
            pub depth: DepthRange,
        }

        impl Viewport {
            #[doc = concat!("The nearest ", $name, " viewport (`None` when a number does not fit).")]
            pub fn $to_float(&self) -> Option<$viewport> {
                let f = |v: &BigRational| crate::num::exact::$nearest(v);
                Some($viewport {
                    origin: <$vec2>::new(f(&self.x)?, f(&self.y)?),
                    size: <$vec2>::new(f(&self.width)?, f(&self.height)?),
                    y_axis: self.y_axis,
                    depth: self.depth,
                })
            }
        }

        #[doc = concat!("[`clip_exact`](super::clip_exact) in ", $name, ": the same planes and cases, each `t` and ")]
        #[doc = "intersection rounded (so an output can land just outside the volume)."]
        pub fn $clip(poly: &[$vertex], depth: DepthRange) -> Vec<$vertex> {
            let mut poly = poly.to_vec();
            for plane in clip_planes(depth) {
                let p = <$vec4>::from_array(plane.map(<$float>::from));
                let n = poly.len();
                let mut out = Vec::with_capacity(n + 2);
                for (k, e) in poly.iter().enumerate() {
                    let s = &poly[(k + n - 1) % n];
                    let (ds, de) = (p.dot(s.pos), p.dot(e.pos));
                    let (s_in, e_in) = (ds >= 0.0, de >= 0.0);
                    if s_in != e_in {
                        let t = ds / (ds - de);
                        out.push($vertex {
                            pos: s.pos + (e.pos - s.pos) * t,
                            attrs: s
                                .attrs
                                .iter()
                                .zip(&e.attrs)
                                .map(|(a, b)| a + (b - a) * t)
                                .collect(),
                        });
                    }
                    if e_in {
                        out.push(e.clone());
                    }
                }
                poly = merged(out);
            }
            poly
        }

        #[doc = concat!("[`project_exact`](super::project_exact) in ", $name, ".")]
        ///
        /// # Errors
        /// [`ProjectError::NotInFront`] for the first vertex whose `w` is not `> 0` (NaN included).
        pub fn $project(poly: &[$vertex], viewport: &$viewport) -> Result<Vec<$window_vertex>, ProjectError> {
            poly.iter()
                .enumerate()
                .map(|(vertex, v)| {
                    let w = v.pos.w;
                    if w.is_nan() || w <= 0.0 {
                        return Err(ProjectError::NotInFront {
                            vertex,
                            w: w.to_string(),
                        });
                    }
                    let ndc = v.pos / w;
                    let half = viewport.size * 0.5;
                    let y = match viewport.y_axis {
                        NdcY::Down => ndc.y + 1.0,
                        NdcY::Up => 1.0 - ndc.y,
                    };
                    let z = match viewport.depth {
                        DepthRange::ZeroToOne => ndc.z,
                        DepthRange::MinusOneToOne => (ndc.z + 1.0) * 0.5,
                    };
                    Ok($window_vertex {
                        point: viewport.origin + <$vec2>::new(ndc.x + 1.0, y) * half,
                        z,
                        inv_w: 1.0 / w,
                        attrs: v.attrs.clone(),
                    })
                })
                .collect()
        }

        impl ClipVertex {
            #[doc = concat!("The nearest ", $name, " vertex (`None` when a number does not fit).")]
            pub fn $to_float(&self) -> Option<$vertex> {
                let f = |v: &BigRational| crate::num::exact::$nearest(v);
                let [x, y, z, w] = &self.pos;
                Some($vertex {
                    pos: <$vec4>::new(f(x)?, f(y)?, f(z)?, f(w)?),
                    attrs: self.attrs.iter().map(f).collect::<Option<_>>()?,
                })
            }
        }

        #[doc = concat!("[`clip_to_window_exact`](super::clip_to_window_exact) in ", $name, ": clipped, the eye point (the only ")]
        #[doc = "clipped vertex that can have `w <= 0`) dropped, divided and mapped."]
        pub fn $clip_to_window(poly: &[$vertex], viewport: &$viewport) -> Vec<$window_vertex> {
            let in_front: Vec<$vertex> = $clip(poly, viewport.depth)
                .into_iter()
                .filter(|v| v.pos.w > 0.0)
                .collect();
            $project(&in_front, viewport).expect("every vertex has w > 0")
        }

        #[doc = concat!("[`interpolate_exact`](super::interpolate_exact) in ", $name, " (`None` for a zero-area triangle ")]
        #[doc = "or where `Σ b_i / w_i` is 0)."]
        pub fn $interpolate(tri: &[$window_vertex; 3], p: $vec2) -> Option<$window_vertex> {
            let b = $barycentric(&[tri[0].point, tri[1].point, tri[2].point], p)?;
            let affine =
                |value: &dyn Fn(&$window_vertex) -> $float| -> $float { (0..3).map(|i| b[i] * value(&tri[i])).sum() };
            let inv_w = affine(&|v| v.inv_w);
            if inv_w == 0.0 {
                return None;
            }
            let count = tri.iter().map(|v| v.attrs.len()).min().unwrap_or(0);
            Some($window_vertex {
                point: p,
                z: affine(&|v| v.z),
                inv_w,
                attrs: (0..count)
                    .map(|k| affine(&|v| v.attrs[k] * v.inv_w) / inv_w)
                    .collect(),
            })
        }
    };
}

float_forms!(
    float: f64, vec4: DVec4, vec2: DVec2, to_float: to_f64, nearest: nearest_f64,
    vertex: ClipVertexF64, window_vertex: WindowVertexF64, viewport: ViewportF64,
    clip: clip_f64, project: project_f64, clip_to_window: clip_to_window_f64,
    interpolate: interpolate_f64, barycentric: barycentric_f64, name: "f64"
);
float_forms!(
    float: f32, vec4: Vec4, vec2: Vec2, to_float: to_f32, nearest: nearest_f32,
    vertex: ClipVertexF32, window_vertex: WindowVertexF32, viewport: ViewportF32,
    clip: clip_f32, project: project_f32, clip_to_window: clip_to_window_f32,
    interpolate: interpolate_f32, barycentric: barycentric_f32, name: "f32"
);
