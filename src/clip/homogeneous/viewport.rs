//! The divide by `w` and the viewport mapping to window space, exactly, and the
//! after-divide clipping path kept for comparison.

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::{clip_exact, interpolate_exact, rational, ClipVertex, DepthRange, NdcY, ProjectError, WindowVertex};
use crate::clip::halfplane::HalfPlane;
use crate::clip::sutherland_hodgman;
use crate::geom::{Point, Triangle};
use crate::interp::Plane;

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

    /// The 2D homogeneous window position `[x_win w, y_win w, w]` of the clip-space
    /// position `[x, y, z, w]`: [`Viewport::map_ndc`]'s window map multiplied through by
    /// `w`, defined for every `w` (a vertex behind the eye too). What
    /// [`crate::interp::values::ValueTriangle`] interpolates with.
    ///
    /// ```
    /// use rasterproof::clip::homogeneous::{DepthRange, NdcY, Viewport};
    /// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
    /// let vp = Viewport::new(q(10), q(20), q(8), q(4), NdcY::Up, DepthRange::ZeroToOne).unwrap();
    /// // Clip (2, 2, 0, 2) is NDC (1, 1): window (18, 20), times w = 2.
    /// assert_eq!(vp.homogeneous(&[q(2), q(2), q(0), q(2)]), [q(36), q(40), q(2)]);
    /// // Behind the eye, w = -1: NDC (0, 0) is the window centre (14, 22), times -1.
    /// assert_eq!(vp.homogeneous(&[q(0), q(0), q(0), q(-1)]), [q(-14), q(-22), q(-1)]);
    /// ```
    pub fn homogeneous(&self, pos: &[BigRational; 4]) -> [BigRational; 3] {
        let [x, y, _, w] = pos;
        let two = rational(2);
        let xw = &self.x * w + (x + w) * &self.width / &two;
        let yw = match self.y_axis {
            NdcY::Down => &self.y * w + (y + w) * &self.height / &two,
            NdcY::Up => &self.y * w + (w - y) * &self.height / &two,
        };
        [xw, yw, w.clone()]
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
    // depth as a plane over the window, depth(x, y) = a x + b y + c (plane-equation setup, as in Luebke's "Drawing triangles" slides)
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
