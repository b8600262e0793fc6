//! Clipping: points against half-planes, segments against an axis-aligned window
//! (Cohen-Sutherland; Sproull & Sutherland 1968), polygons against a convex window
//! (Sutherland & Hodgman 1974), each exact (BigRational) and in f32 / f64.
//!
//! # Samples on the window's boundary
//!
//! The clipped geometry keeps the window's boundary (points on it are inside, as in
//! point clipping). What a rasterizer then covers follows the tie rule's ε reading: a sample on
//! the window's boundary belongs to the clipped polygon exactly when its moved sample
//! `p + (ε, ±ε²)` lies inside the window, so
//! `raster(clip(P, W)) == raster(P) ∩ raster(W)` pixel for pixel, with `raster(W)` the
//! window filled as a polygon (top-left: samples on its left and top sides are in, on
//! its right and bottom sides out). Property test: `tests/clip.rs`.
//!
//! # Results without area
//!
//! Clipping an area primitive (a triangle, a polygon's contour) can leave a point or a
//! segment: a triangle that touches the window at a corner, or shares only part of an
//! edge with it. Such a result has no interior, so its moved samples `p + (ε, ±ε²)` (never
//! on a line) have winding number 0 and it covers no sample under any tie rule, as
//! `raster(P) ∩ raster(W)` says; [`area_or_empty`] turns it into the empty contour. A
//! clipped *segment* that shrinks to one point is a real result (a segment of length
//! zero: the one point of the closed segment in the closed window) and is kept.

pub mod arithmetic;
pub mod cohen_sutherland;
pub mod halfplane;
pub mod homogeneous;
pub mod mask;
pub mod sutherland_hodgman;

use std::fmt;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::edge::exact::edge_function;
use crate::geom::Point;
use halfplane::HalfPlane;

/// An axis-aligned rectangle `[xmin, xmax] x [ymin, ymax]`, `xmin < xmax`, `ymin < ymax`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Rect {
    /// Left.
    pub xmin: BigRational,
    /// Top (y down).
    pub ymin: BigRational,
    /// Right.
    pub xmax: BigRational,
    /// Bottom.
    pub ymax: BigRational,
}

/// A clip window: a rectangle, or a strictly convex polygon in either orientation.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Window {
    /// Axis-aligned.
    Rect(Box<Rect>),
    /// Strictly convex, vertices in order.
    Convex(Vec<Point>),
}

/// A window that is not a window.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum WindowError {
    /// `min >= max` on an axis.
    Empty {
        /// `'x'` or `'y'`.
        axis: char,
        /// The minimum, as exact text.
        min: String,
        /// The maximum, as exact text.
        max: String,
    },
    /// Fewer than 3 vertices.
    TooFewVertices(usize),
    /// Not strictly convex at a corner: the turn there is straight, reversed, or the
    /// other way from the first corner's.
    NotConvex {
        /// The corner's vertex.
        vertex: usize,
    },
    /// Every corner turns the same way, but the outline winds round more than once.
    WindsMoreThanOnce,
}

impl fmt::Display for WindowError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WindowError::Empty { axis, min, max } => {
                write!(f, "empty window: {axis}min {min} >= {axis}max {max}")
            }
            WindowError::TooFewVertices(n) => write!(f, "a convex window needs at least 3 vertices, found {n}"),
            WindowError::NotConvex { vertex } => write!(
                f,
                "not a strictly convex polygon: the corner at vertex {vertex} goes straight on or turns the other way"
            ),
            WindowError::WindsMoreThanOnce => {
                write!(f, "not a convex polygon: the outline winds round more than once")
            }
        }
    }
}

impl std::error::Error for WindowError {}

impl Window {
    /// The rectangle `[xmin, xmax] x [ymin, ymax]`.
    ///
    /// # Errors
    /// When it is empty (`xmin >= xmax` or `ymin >= ymax`).
    pub fn rect(
        xmin: BigRational,
        ymin: BigRational,
        xmax: BigRational,
        ymax: BigRational,
    ) -> Result<Window, WindowError> {
        for (axis, min, max) in [('x', &xmin, &xmax), ('y', &ymin, &ymax)] {
            if min >= max {
                return Err(WindowError::Empty {
                    axis,
                    min: crate::num::exact::exact_text(min),
                    max: crate::num::exact::exact_text(max),
                });
            }
        }
        Ok(Window::Rect(Box::new(Rect { xmin, ymin, xmax, ymax })))
    }

    /// A strictly convex polygon: every turn goes the same way (no straight or reversed
    /// corner, no repeated vertex), and the outline goes round exactly once (the sign of
    /// its edges' `dy` changes exactly twice around the loop; a star that turns the same
    /// way at every corner but winds twice changes it four times). Linear time.
    ///
    /// # Errors
    /// Fewer than 3 vertices, the first corner that breaks convexity, or an outline that
    /// winds more than once.
    pub fn convex(points: Vec<Point>) -> Result<Window, WindowError> {
        let n = points.len();
        if n < 3 {
            return Err(WindowError::TooFewVertices(n));
        }
        let mut side: Option<bool> = None;
        for i in 0..n {
            let (a, b, c) = (&points[i], &points[(i + 1) % n], &points[(i + 2) % n]);
            let turn = edge_function(a, b, c);
            let positive = turn.is_positive();
            if turn.is_zero() || side.is_some_and(|s| s != positive) {
                return Err(WindowError::NotConvex { vertex: (i + 1) % n });
            }
            side = Some(positive);
        }
        let signs: Vec<bool> = (0..n)
            .map(|i| &points[(i + 1) % n].y - &points[i].y)
            .filter(|dy| !dy.is_zero())
            .map(|dy| dy.is_positive())
            .collect();
        let changes = (0..signs.len())
            .filter(|&i| signs[i] != signs[(i + 1) % signs.len()])
            .count();
        if changes != 2 {
            return Err(WindowError::WindsMoreThanOnce);
        }
        Ok(Window::Convex(points))
    }

    /// The window's vertices in order (a rectangle from its top-left corner).
    pub fn outline(&self) -> Vec<Point> {
        match self {
            Window::Rect(r) => vec![
                Point::new(r.xmin.clone(), r.ymin.clone()),
                Point::new(r.xmax.clone(), r.ymin.clone()),
                Point::new(r.xmax.clone(), r.ymax.clone()),
                Point::new(r.xmin.clone(), r.ymax.clone()),
            ],
            Window::Convex(p) => p.clone(),
        }
    }

    /// The half-planes whose intersection is the window (boundary included).
    pub fn half_planes(&self) -> Vec<HalfPlane> {
        let outline = self.outline();
        let n = outline.len();
        // Orientation: the third vertex's side of the first edge says where the inside is.
        let positive = edge_function(&outline[0], &outline[1], &outline[2]).is_positive();
        (0..n)
            .map(|i| {
                let (a, b) = (&outline[i], &outline[(i + 1) % n]);
                let (p, q) = if positive { (a, b) } else { (b, a) };
                HalfPlane::inside_of_edge(p, q).expect("distinct consecutive vertices")
            })
            .collect()
    }

    /// Whether `p` is in the window (boundary included), exactly. Builds the half-planes on
    /// every call: for many points, take [`Window::half_planes`] once.
    pub fn contains(&self, p: &Point) -> bool {
        self.half_planes().iter().all(|h| h.contains(p))
    }
}

/// Whether a closed contour encloses any area: false when all its vertices lie on one
/// line (no vertex, one point, a segment, or collinear points), exactly.
///
/// ```
/// use rasterproof::clip::encloses_area;
/// use rasterproof::geom::Point;
/// assert!(encloses_area(&[Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4)]));
/// assert!(!encloses_area(&[Point::from_ints(0, 0), Point::from_ints(2, 2), Point::from_ints(4, 4)]));
/// assert!(!encloses_area(&[Point::from_ints(3, 3)]));
/// ```
pub fn encloses_area(contour: &[Point]) -> bool {
    let Some(first) = contour.first() else {
        return false;
    };
    let Some(second) = contour.iter().find(|p| *p != first) else {
        return false;
    };
    contour.iter().any(|p| !edge_function(first, second, p).is_zero())
}

/// `contour` when it encloses area, else the empty contour: the rule for a clipped area
/// primitive (see [Results without area](self#results-without-area)).
///
/// ```
/// use rasterproof::clip::{area_or_empty, sutherland_hodgman::clip_exact, Window};
/// use rasterproof::geom::Point;
/// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
/// let w = Window::rect(q(0), q(0), q(8), q(8)).unwrap();
/// // Touching the window at its corner (8, 8) only: Sutherland-Hodgman keeps that point.
/// let corner = [Point::from_ints(8, 8), Point::from_ints(12, 8), Point::from_ints(8, 12)];
/// let cut = clip_exact(&corner, &w.half_planes());
/// assert_eq!(cut, vec![Point::from_ints(8, 8)]);
/// assert_eq!(area_or_empty(cut), vec![]);
/// ```
pub fn area_or_empty(contour: Vec<Point>) -> Vec<Point> {
    if encloses_area(&contour) {
        contour
    } else {
        Vec::new()
    }
}
