//! Homogeneous clipping (seed 002: "clip in homogeneous clip space after the projective
//! transform and before the divide — the simplest"): polygons with clip-space vertices
//! `(x, y, z, w)` are clipped by Sutherland-Hodgman in 4D against the six planes
//! `-w <= x <= w`, `-w <= y <= w` and the depth range, then divided by `w` and mapped to
//! the window. Exact over `BigRational` (the oracle), and in f32 / f64 with glam.
//!
//! - **Planes.** A vertex `v` is inside plane `p` when `p . v >= 0`; the boundary is kept
//!   (seed 002). An edge `s -> e` with `d_s = p . s`, `d_e = p . e` of opposite sides is cut
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
//! Reference: Blinn & Newell, "Clipping using homogeneous coordinates", SIGGRAPH 1978;
//! Vulkan spec §"Primitive Clipping" and §"Coordinate Transformations".

use std::fmt;

use glam::DMat4;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::halfplane::HalfPlane;
use super::sutherland_hodgman::{self, merged};
use crate::geom::{Point, Triangle};
use crate::interp::{barycentric_exact, Plane};

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

/// The six clip planes as small integer 4-vectors `p`, inside where `p . (x, y, z, w) >= 0`,
/// in the order they are applied: `x >= -w`, `x <= w`, `y >= -w`, `y <= w`, near, far.
///
/// ```
/// use rasterproof::clip::homogeneous::{clip_planes, DepthRange};
/// // GL's near plane z >= -w is z + w >= 0; D3D's is z >= 0; both far planes are z <= w.
/// assert_eq!(clip_planes(DepthRange::MinusOneToOne)[4], [0, 0, 1, 1]);
/// assert_eq!(clip_planes(DepthRange::ZeroToOne)[4], [0, 0, 1, 0]);
/// assert_eq!(clip_planes(DepthRange::ZeroToOne)[5], [0, 0, -1, 1]);
/// ```
pub fn clip_planes(depth: DepthRange) -> [[i8; 4]; 6] {
    let near = match depth {
        DepthRange::ZeroToOne => [0, 0, 1, 0],
        DepthRange::MinusOneToOne => [0, 0, 1, 1],
    };
    [
        [1, 0, 0, 1],
        [-1, 0, 0, 1],
        [0, 1, 0, 1],
        [0, -1, 0, 1],
        near,
        [0, 0, -1, 1],
    ]
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

    /// `p . pos`: the vertex's signed distance (scaled) to plane `p`; inside when `>= 0`.
    pub fn plane_distance(&self, plane: &[i8; 4]) -> BigRational {
        plane
            .iter()
            .zip(&self.pos)
            .map(|(&c, x)| rational(i64::from(c)) * x)
            .fold(BigRational::zero(), |acc, v| acc + v)
    }

    /// Whether the vertex is inside the clip volume, boundary included.
    ///
    /// ```
    /// use rasterproof::clip::homogeneous::{ClipVertex, DepthRange};
    /// // z = -1, w = 2: inside GL's -w <= z, outside D3D's 0 <= z.
    /// let v = ClipVertex::from_ints([2, -2, -1, 2], &[]);
    /// assert!(v.inside(DepthRange::MinusOneToOne));
    /// assert!(!v.inside(DepthRange::ZeroToOne));
    /// ```
    pub fn inside(&self, depth: DepthRange) -> bool {
        clip_planes(depth).iter().all(|p| !self.plane_distance(p).is_negative())
    }

    /// `self + t (other - self)`, position and attributes.
    fn lerp(&self, other: &ClipVertex, t: &BigRational) -> ClipVertex {
        let mix = |a: &BigRational, b: &BigRational| a + t * (b - a);
        ClipVertex {
            pos: std::array::from_fn(|k| mix(&self.pos[k], &other.pos[k])),
            attrs: self.attrs.iter().zip(&other.attrs).map(|(a, b)| mix(a, b)).collect(),
        }
    }
}

/// `poly` (a triangle or any polygon, vertices in order) clipped against the clip volume,
/// exactly: Sutherland-Hodgman against the six [`clip_planes`] in turn, the four in/out
/// cases of [`sutherland_hodgman`], repeated consecutive vertices merged. Empty when
/// nothing is inside. Every output vertex is inside the volume, so it has `w > 0` or is
/// the eye `(0, 0, 0, 0)` (a primitive through the eye is seen edge-on).
///
/// ```
/// use rasterproof::clip::homogeneous::{clip_exact, ClipVertex, DepthRange};
/// // The triangle (0,0) (4,0) (0,4) at w = 2 (attribute = x) against x <= 2 and y <= 2:
/// // x + y <= 4 holds on all of [0,2]^2, so the square is left. x <= w cuts the edges at
/// // t = 1/2, giving (2,0) and (2,2); y <= w then cuts (0,4) -> (0,0) at (0,2), emitted
/// // first (out -> in at the first vertex), and (2,2) -> (0,4) at t = 0, merged with (2,2).
/// let v = |x, y| ClipVertex::from_ints([x, y, 0, 2], &[x]);
/// let out = clip_exact(&[v(0, 0), v(4, 0), v(0, 4)], DepthRange::ZeroToOne);
/// assert_eq!(out, vec![v(0, 2), v(0, 0), v(2, 0), v(2, 2)]);
/// ```
pub fn clip_exact(poly: &[ClipVertex], depth: DepthRange) -> Vec<ClipVertex> {
    let mut poly = poly.to_vec();
    for plane in clip_planes(depth) {
        let n = poly.len();
        let mut out = Vec::with_capacity(n + 2);
        for (k, e) in poly.iter().enumerate() {
            let s = &poly[(k + n - 1) % n];
            let (ds, de) = (s.plane_distance(&plane), e.plane_distance(&plane));
            let (s_in, e_in) = (!ds.is_negative(), !de.is_negative());
            if s_in != e_in {
                // one side >= 0, the other < 0: ds != de
                let t = &ds / (&ds - &de);
                out.push(s.lerp(e, &t));
            }
            if e_in {
                out.push(e.clone());
            }
        }
        poly = merged(out);
    }
    poly
}

/// Where NDC goes in the window: the square `[-1, 1]^2` onto `[x, x + width] x [y, y + height]`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Viewport {
    /// Left edge, window pixels.
    pub x: BigRational,
    /// Top edge, window pixels (y down).
    pub y: BigRational,
    /// Width, `> 0`.
    pub width: BigRational,
    /// Height, `> 0`.
    pub height: BigRational,
    /// Which NDC y is at the top.
    pub y_axis: NdcY,
    /// The clip volume's depth range (how NDC z maps to window depth `[0, 1]`).
    pub depth: DepthRange,
}

impl Viewport {
    /// A viewport; `None` unless `width > 0` and `height > 0`.
    ///
    /// ```
    /// use rasterproof::clip::homogeneous::{DepthRange, NdcY, Viewport};
    /// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
    /// assert!(Viewport::new(q(0), q(0), q(0), q(8), NdcY::Down, DepthRange::ZeroToOne).is_none());
    /// assert!(Viewport::new(q(-3), q(0), q(8), q(8), NdcY::Up, DepthRange::ZeroToOne).is_some());
    /// ```
    pub fn new(
        x: BigRational,
        y: BigRational,
        width: BigRational,
        height: BigRational,
        y_axis: NdcY,
        depth: DepthRange,
    ) -> Option<Viewport> {
        (width.is_positive() && height.is_positive()).then_some(Viewport {
            x,
            y,
            width,
            height,
            y_axis,
            depth,
        })
    }

    /// The window point and depth of NDC `(x, y, z)`:
    /// `x_win = x0 + (x + 1) width / 2`, `y_win = y0 + (y + 1) height / 2` ([`NdcY::Down`]) or
    /// `y0 + (1 - y) height / 2` ([`NdcY::Up`]), depth `z` ([`DepthRange::ZeroToOne`]) or
    /// `(z + 1) / 2` ([`DepthRange::MinusOneToOne`]).
    ///
    /// ```
    /// use rasterproof::clip::homogeneous::{DepthRange, NdcY, Viewport};
    /// use rasterproof::geom::Point;
    /// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
    /// let vp = Viewport::new(q(10), q(20), q(8), q(4), NdcY::Up, DepthRange::MinusOneToOne).unwrap();
    /// // NDC (1, 1) is the top-right corner (18, 20) when +1 is up; z = 0 is depth 1/2.
    /// let (p, z) = vp.map_ndc(&q(1), &q(1), &q(0));
    /// assert_eq!(p, Point::from_ints(18, 20));
    /// assert_eq!(z, num_rational::BigRational::new(1.into(), 2.into()));
    /// ```
    pub fn map_ndc(&self, x: &BigRational, y: &BigRational, z: &BigRational) -> (Point, BigRational) {
        let one = rational(1);
        let two = rational(2);
        let wx = &self.x + (x + &one) * &self.width / &two;
        let wy = match self.y_axis {
            NdcY::Down => &self.y + (y + &one) * &self.height / &two,
            NdcY::Up => &self.y + (&one - y) * &self.height / &two,
        };
        let depth = match self.depth {
            DepthRange::ZeroToOne => z.clone(),
            DepthRange::MinusOneToOne => (z + &one) / &two,
        };
        (Point::new(wx, wy), depth)
    }

    /// The window rectangle's four half-planes in the order of the first four
    /// [`clip_planes`] (NDC `x >= -1`, `x <= 1`, `y >= -1`, `y <= 1`).
    fn half_planes(&self) -> [HalfPlane; 4] {
        let (left, top) = (self.x.clone(), self.y.clone());
        let (right, bottom) = (&self.x + &self.width, &self.y + &self.height);
        let one = rational(1);
        let zero = BigRational::zero();
        let at_least = |a: &BigRational, b: &BigRational, min: &BigRational| HalfPlane {
            a: a.clone(),
            b: b.clone(),
            c: -min,
        };
        let at_most = |a: &BigRational, b: &BigRational, max: &BigRational| HalfPlane {
            a: -a,
            b: -b,
            c: max.clone(),
        };
        let (y_low, y_high) = match self.y_axis {
            NdcY::Down => (at_least(&zero, &one, &top), at_most(&zero, &one, &bottom)),
            NdcY::Up => (at_most(&zero, &one, &bottom), at_least(&zero, &one, &top)),
        };
        [
            at_least(&one, &zero, &left),
            at_most(&one, &zero, &right),
            y_low,
            y_high,
        ]
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

/// Divides one vertex by its `w` and maps it through `viewport`; `vertex` names it in the
/// error when `w <= 0`.
///
/// ```
/// use rasterproof::clip::homogeneous::{to_window_exact, ClipVertex, DepthRange, NdcY, Viewport};
/// use rasterproof::geom::Point;
/// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
/// let vp = Viewport::new(q(0), q(0), q(8), q(8), NdcY::Down, DepthRange::ZeroToOne).unwrap();
/// // (2, -2, 1, 4): NDC (1/2, -1/2, 1/4) -> window (6, 2), depth 1/4, 1/w = 1/4.
/// let v = to_window_exact(&ClipVertex::from_ints([2, -2, 1, 4], &[7]), 0, &vp).unwrap();
/// assert_eq!(v.point, Point::from_ints(6, 2));
/// assert_eq!(v.z, num_rational::BigRational::new(1.into(), 4.into()));
/// assert_eq!(v.inv_w, v.z);
/// assert_eq!(v.attrs, vec![q(7)]);
/// assert!(to_window_exact(&ClipVertex::from_ints([0, 0, 0, 0], &[]), 3, &vp).is_err());
/// ```
///
/// # Errors
/// [`ProjectError::NotInFront`] when `w <= 0`.
pub fn to_window_exact(v: &ClipVertex, vertex: usize, viewport: &Viewport) -> Result<WindowVertex, ProjectError> {
    let [x, y, z, w] = &v.pos;
    if !w.is_positive() {
        return Err(ProjectError::NotInFront {
            vertex,
            w: crate::num::exact::exact_text(w),
        });
    }
    let (point, z) = viewport.map_ndc(&(x / w), &(y / w), &(z / w));
    Ok(WindowVertex {
        point,
        z,
        inv_w: w.recip(),
        attrs: v.attrs.clone(),
    })
}

/// Every vertex of `poly` divided and mapped ([`to_window_exact`]).
///
/// # Errors
/// [`ProjectError::NotInFront`] for the first vertex with `w <= 0`.
pub fn project_exact(poly: &[ClipVertex], viewport: &Viewport) -> Result<Vec<WindowVertex>, ProjectError> {
    poly.iter()
        .enumerate()
        .map(|(k, v)| to_window_exact(v, k, viewport))
        .collect()
}

/// The pipeline: [`clip_exact`] against the viewport's depth range, then divide and map.
/// Total: the clipped vertices have `w > 0` except the eye `(0, 0, 0, 0)`, which is
/// dropped (a primitive through the eye projects to a line and covers nothing either way).
///
/// ```
/// use rasterproof::clip::homogeneous::{clip_to_window_exact, ClipVertex, DepthRange, NdcY, Viewport};
/// use rasterproof::geom::Point;
/// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
/// let vp = Viewport::new(q(0), q(0), q(8), q(8), NdcY::Down, DepthRange::ZeroToOne).unwrap();
/// // Entirely behind the eye (w = -1 everywhere): nothing is drawn.
/// let behind = [[0, 0, 0, -1], [1, 0, 0, -1], [0, 1, 0, -1]].map(|p| ClipVertex::from_ints(p, &[]));
/// assert!(clip_to_window_exact(&behind, &vp).is_empty());
/// // The NDC square itself at w = 1 fills the viewport's corners.
/// let square = [[-1, -1, 0, 1], [1, -1, 0, 1], [1, 1, 0, 1], [-1, 1, 0, 1]].map(|p| ClipVertex::from_ints(p, &[]));
/// let out = clip_to_window_exact(&square, &vp);
/// assert_eq!(out.iter().map(|v| v.point.clone()).collect::<Vec<_>>(),
///            vec![Point::from_ints(0, 0), Point::from_ints(8, 0), Point::from_ints(8, 8), Point::from_ints(0, 8)]);
/// ```
pub fn clip_to_window_exact(poly: &[ClipVertex], viewport: &Viewport) -> Vec<WindowVertex> {
    clip_exact(poly, viewport.depth)
        .iter()
        .filter(|v| v.pos[3].is_positive())
        .map(|v| to_window_exact(v, 0, viewport).expect("w > 0"))
        .collect()
}

/// The vertex at window point `p` of the window-space triangle `tri`, perspective-correct:
/// with window-space barycentrics `b_i`, depth `Σ b_i z_i` and `1/w = Σ b_i / w_i` (both
/// affine in window space), attribute `a = Σ b_i a_i / w_i / Σ b_i / w_i`. `None` when
/// the triangle has zero area, or at a `p` outside it where `Σ b_i / w_i = 0` (the horizon).
///
/// ```
/// use rasterproof::clip::homogeneous::{interpolate_exact, WindowVertex};
/// use rasterproof::geom::Point;
/// let q = |n: i64, d: i64| num_rational::BigRational::new(n.into(), d.into());
/// let v = |x, y, w, a| WindowVertex { point: Point::from_ints(x, y), z: q(0, 1), inv_w: q(1, w), attrs: vec![q(a, 1)] };
/// // Attribute 0 at w = 1, 1 at w = 3. At the screen midpoint b = (1/2, 1/2, 0):
/// // (1/2 * 1/3) / (1/2 + 1/2 * 1/3) = 1/4, not the affine 1/2.
/// let tri = [v(0, 0, 1, 0), v(4, 0, 3, 1), v(0, 4, 1, 0)];
/// let mid = interpolate_exact(&tri, &Point::from_ints(2, 0)).unwrap();
/// assert_eq!(mid.attrs, vec![q(1, 4)]);
/// assert_eq!(mid.inv_w, q(2, 3));
/// ```
pub fn interpolate_exact(tri: &[WindowVertex; 3], p: &Point) -> Option<WindowVertex> {
    let screen = Triangle::new(tri[0].point.clone(), tri[1].point.clone(), tri[2].point.clone());
    let b = barycentric_exact(&screen, p)?;
    let affine = |value: &dyn Fn(&WindowVertex) -> BigRational| -> BigRational {
        (0..3).fold(BigRational::zero(), |acc, i| acc + &b[i] * value(&tri[i]))
    };
    let inv_w = affine(&|v| v.inv_w.clone());
    if inv_w.is_zero() {
        return None;
    }
    let count = tri.iter().map(|v| v.attrs.len()).min().unwrap_or(0);
    let attrs = (0..count)
        .map(|k| affine(&|v| &v.attrs[k] * &v.inv_w) / &inv_w)
        .collect();
    Some(WindowVertex {
        point: p.clone(),
        z: affine(&|v| v.z.clone()),
        inv_w,
        attrs,
    })
}

/// The after-divide path, for comparison: divide the triangle's vertices first (refusing
/// `w <= 0`), clip the window-space triangle with the 2D [`sutherland_hodgman::clip_exact`]
/// against the viewport rectangle and the depth range (depth is affine in window space,
/// so `0 <= depth <= 1` is a half-plane there), then recover each output vertex's depth,
/// `1/w` and attributes with [`interpolate_exact`] on the projected triangle. For a
/// triangle in front of the eye this equals [`clip_to_window_exact`] exactly
/// (`tests/homogeneous.rs`).
///
/// ```
/// use rasterproof::clip::homogeneous::{divide_then_clip_exact, ClipVertex, DepthRange, NdcY, ProjectError, Viewport};
/// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
/// let vp = Viewport::new(q(0), q(0), q(8), q(8), NdcY::Down, DepthRange::ZeroToOne).unwrap();
/// let tri = [[0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, -2]].map(|p| ClipVertex::from_ints(p, &[]));
/// assert_eq!(divide_then_clip_exact(&tri, &vp), Err(ProjectError::NotInFront { vertex: 2, w: "-2".into() }));
/// ```
///
/// # Errors
/// [`ProjectError::NotInFront`] for the first vertex with `w <= 0`;
/// [`ProjectError::EdgeOn`] when the projected triangle has zero area.
pub fn divide_then_clip_exact(tri: &[ClipVertex; 3], viewport: &Viewport) -> Result<Vec<WindowVertex>, ProjectError> {
    let projected: Vec<WindowVertex> = project_exact(tri, viewport)?;
    let projected: [WindowVertex; 3] = projected.try_into().expect("three vertices");
    let points: Vec<Point> = projected.iter().map(|v| v.point.clone()).collect();
    // depth as a plane over the window, depth(x, y) = a x + b y + c (seed 004's setup)
    let screen = Triangle::new(points[0].clone(), points[1].clone(), points[2].clone());
    let depths = [projected[0].z.clone(), projected[1].z.clone(), projected[2].z.clone()];
    let Plane { a, b, c } = Plane::setup(&screen, &depths).ok_or(ProjectError::EdgeOn)?;
    let mut planes = viewport.half_planes().to_vec();
    let one = rational(1);
    match HalfPlane::from_line(a.clone(), b.clone(), c.clone()) {
        // depth >= 0 and depth <= 1
        Some(near) => {
            planes.push(near);
            planes.push(HalfPlane {
                a: -a,
                b: -b,
                c: one - c,
            });
        }
        // constant depth: all in or all out
        None if c.is_negative() || c > one => return Ok(Vec::new()),
        None => {}
    }
    let clipped = sutherland_hodgman::clip_exact(&points, &planes);
    Ok(clipped
        .iter()
        .map(|p| interpolate_exact(&projected, p).expect("inside the triangle: 1/w > 0"))
        .collect())
}

/// A 4x4 exact matrix, row-major (`m[row][col]`), acting on column vectors as glam does:
/// `v' = M v`.
pub type Mat4Exact = [[BigRational; 4]; 4];

/// `a b` (apply `b` first), exactly.
///
/// ```
/// use rasterproof::clip::homogeneous::{mat_mul_exact, Mat4Exact};
/// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
/// // translate x by 1 after scaling x by 2: x -> 2x + 1
/// let m = |rows: [[i64; 4]; 4]| -> Mat4Exact { rows.map(|r| r.map(q)) };
/// let translate = m([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]);
/// let scale = m([[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]);
/// assert_eq!(mat_mul_exact(&translate, &scale)[0], [q(2), q(0), q(0), q(1)]);
/// ```
pub fn mat_mul_exact(a: &Mat4Exact, b: &Mat4Exact) -> Mat4Exact {
    std::array::from_fn(|r| {
        std::array::from_fn(|c| (0..4).fold(BigRational::zero(), |acc, k| acc + &a[r][k] * &b[k][c]))
    })
}

/// `m v`, exactly.
///
/// ```
/// use rasterproof::clip::homogeneous::transform_exact;
/// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
/// // A perspective matrix that copies -z into w: (1, 2, -4, 1) -> w = 4.
/// let mut m: [[_; 4]; 4] = std::array::from_fn(|r| std::array::from_fn(|c| q(i64::from(r == c))));
/// m[3] = [q(0), q(0), q(-1), q(0)];
/// assert_eq!(transform_exact(&m, &[q(1), q(2), q(-4), q(1)])[3], q(4));
/// ```
pub fn transform_exact(m: &Mat4Exact, v: &[BigRational; 4]) -> [BigRational; 4] {
    std::array::from_fn(|r| (0..4).fold(BigRational::zero(), |acc, k| acc + &m[r][k] * &v[k]))
}

/// The exact value of an f64 matrix (`None` if an entry is not finite).
///
/// ```
/// use rasterproof::clip::homogeneous::mat_exact_from_f64;
/// let m = mat_exact_from_f64(&glam::DMat4::from_translation(glam::DVec3::new(0.5, 0.0, 0.0))).unwrap();
/// assert_eq!(m[0][3], num_rational::BigRational::new(1.into(), 2.into())); // row 0, column 3
/// ```
pub fn mat_exact_from_f64(m: &DMat4) -> Option<Mat4Exact> {
    let cols = m.to_cols_array_2d();
    let mut out: Mat4Exact = std::array::from_fn(|_| std::array::from_fn(|_| BigRational::zero()));
    for (c, col) in cols.iter().enumerate() {
        for (r, &x) in col.iter().enumerate() {
            out[r][c] = BigRational::from_float(x)?;
        }
    }
    Some(out)
}

mod float;
pub use float::*;
