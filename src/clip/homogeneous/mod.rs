//! Homogeneous clipping (Blinn & Newell 1978: clip in homogeneous clip space, after the
//! projective transform and before the divide): polygons with clip-space vertices
//! `(x, y, z, w)` are clipped by Sutherland-Hodgman in 4D against the six planes
//! `-w <= x <= w`, `-w <= y <= w` and the depth range, then divided by `w` and mapped to
//! the window. Exact over `BigRational` (the oracle), and in f32 / f64 with glam.
//!
//! - **Planes.** A vertex `v` is inside plane `p` when `p . v >= 0`; the boundary is kept
//!   (as by every clipper of [`crate::clip`]). An edge `s -> e` with `d_s = p . s`, `d_e = p . e` of opposite sides is cut
//!   at `t = d_s / (d_s - d_e)`, and position and attributes are interpolated linearly in
//!   `t`: linear interpolation is right in clip space, before the divide.
//! - **Why before the divide.** The only clip-volume point with `w <= 0` is the eye
//!   itself (`|x| <= w` forces `w >= 0`, and `w = 0` forces `x = y = z = 0`), so what
//!   survives is in front of the eye. Dividing first sends a vertex behind the eye to the
//!   wrong side of the screen; [`divide_then_clip_exact`] therefore refuses `w <= 0`.
//! - **Window space** is the crate's: x right, y down. The NDC square `[-1, 1]^2` maps to
//!   the [`Viewport`] rectangle; which NDC y is at the top is the viewport's [`NdcY`]
//!   (Vulkan: `-1` at the top; GL and D3D: `+1`). Window depth is in `[0, 1]` for both
//!   [`DepthRange`]s (a depth viewport of `minDepth = 0`, `maxDepth = 1`).
//! - **Interpolation.** `z/w`, `1/w` and `a/w` are affine in window space, `a` is not:
//!   [`interpolate_exact`] gives `a = Σ b_i a_i / w_i / Σ b_i / w_i` with window-space
//!   barycentrics `b_i` (perspective-correct; Heckbert & Moreton 1991, Blinn 1992
//!   "Hyperbolic interpolation").
//!
//! Files by concern: `volume.rs` (the clip planes and clipping in clip space),
//! `viewport.rs` (the divide, the viewport mapping and the after-divide path), `interp.rs`
//! (perspective-correct interpolation), `float.rs` (the f32 and f64 forms of all three).
//!
//! Reference: Blinn & Newell, "Clipping using homogeneous coordinates", SIGGRAPH 1978;
//! Vulkan spec §"Primitive Clipping" and §"Coordinate Transformations".

use std::fmt;

use num_bigint::BigInt;
use num_rational::BigRational;

use crate::geom::Point;

mod float;
mod interp;
mod viewport;
mod volume;

pub use float::{
    clip_f32, clip_f64, clip_to_window_f32, clip_to_window_f64, interpolate_f32, interpolate_f64, project_f32,
    project_f64, transform_f32, transform_f64, ClipVertexF32, ClipVertexF64, ViewportF32, ViewportF64, WindowVertexF32,
    WindowVertexF64,
};
pub use interp::interpolate_exact;
pub use viewport::{clip_to_window_exact, divide_then_clip_exact, project_exact, to_window_exact, Viewport};
pub use volume::{clip_exact, clip_planes};

/// The depth range of the clip volume (the z planes).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DepthRange {
    /// D3D and Vulkan: `0 <= z <= w`.
    ZeroToOne,
    /// OpenGL: `-w <= z <= w`.
    MinusOneToOne,
}

/// Which way NDC y points in the y-down window.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NdcY {
    /// Vulkan: NDC `y = -1` is the top of the viewport, y grows downwards as in the window.
    Down,
    /// OpenGL and D3D: NDC `y = +1` is the top of the viewport (the image is flipped).
    Up,
}

/// A clip-space vertex with exact coordinates and attributes (all vertices of a polygon
/// carry the same number of attributes).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct ClipVertex {
    /// `[x, y, z, w]`.
    pub pos: [BigRational; 4],
    /// The attributes (colours, texture coordinates, ...), interpolated linearly in clip space.
    pub attrs: Vec<BigRational>,
}

fn rational(n: i64) -> BigRational {
    BigRational::from_integer(BigInt::from(n))
}

impl ClipVertex {
    /// A vertex from integers.
    ///
    /// ```
    /// use rasterproof::clip::homogeneous::ClipVertex;
    /// let v = ClipVertex::from_ints([1, 2, 3, 4], &[5]);
    /// assert_eq!(v.pos[3], num_rational::BigRational::from_integer(4.into()));
    /// assert_eq!(v.attrs.len(), 1);
    /// ```
    pub fn from_ints(pos: [i64; 4], attrs: &[i64]) -> ClipVertex {
        ClipVertex {
            pos: pos.map(rational),
            attrs: attrs.iter().copied().map(rational).collect(),
        }
    }
}

/// A window-space vertex: the divided, viewport-mapped point, its depth, `1/w` and the
/// attributes (undivided), everything perspective-correct interpolation needs.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct WindowVertex {
    /// Window position, pixels (x right, y down).
    pub point: Point,
    /// Window depth, `[0, 1]` inside the clip volume.
    pub z: BigRational,
    /// `1 / w`.
    pub inv_w: BigRational,
    /// The attributes.
    pub attrs: Vec<BigRational>,
}

/// Why a vertex cannot be divided, or a primitive cannot be clipped after the divide.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ProjectError {
    /// Vertex `vertex` has `w <= 0` (or not a number, in the float forms): it is at or
    /// behind the eye, and dividing would put it on the wrong side of the screen.
    NotInFront {
        /// Its index in the input.
        vertex: usize,
        /// Its `w`, as exact text (or the float's text).
        w: String,
    },
    /// The triangle projects to zero area (seen edge-on), so its attributes cannot be
    /// recovered from window space; it covers no sample.
    EdgeOn,
}

impl fmt::Display for ProjectError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ProjectError::NotInFront { vertex, w } => write!(
                f,
                "vertex {vertex} has w = {w} <= 0: it is not in front of the eye, so it cannot be divided; \
                 clip in clip space first (clip_exact)"
            ),
            ProjectError::EdgeOn => write!(f, "the triangle projects to zero area (seen edge-on)"),
        }
    }
}

impl std::error::Error for ProjectError {}
