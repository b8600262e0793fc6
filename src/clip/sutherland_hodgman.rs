//! Sutherland-Hodgman ("Reentrant Polygon Clipping", Sutherland & Hodgman 1974): the
//! subject polygon is clipped against each half-plane of a convex window in turn. Walking
//! the edges `s -> e` of the current polygon, the four cases are:
//!
//! | s | e | emit |
//! |---|---|---|
//! | in | in | `e` |
//! | in | out | the intersection |
//! | out | in | the intersection, then `e` (the case a widely copied lecture pseudo-code forgets) |
//! | out | out | nothing |
//!
//! "In" includes the boundary. A concave subject can come out with degenerate edges
//! running along the window's boundary and back (two pieces of the subject joined along
//! the boundary): they enclose no area, and since a moved sample never lies on them they
//! change no winding number, so the fill is still right (`tests/clip.rs` checks it).
//! Repeated consecutive vertices (a vertex on the boundary is emitted once as a vertex and
//! once as an intersection) are merged.

use glam::{DVec2, Vec2};

use super::halfplane::{HalfPlane, HalfPlaneF32, HalfPlaneF64};
use super::Window;
use crate::geom::{Point, Polygon};

/// `subject` clipped against every half-plane in `planes`, exactly. Empty when nothing
/// of it is inside.
///
/// ```
/// use rasterproof::clip::{sutherland_hodgman::clip_exact, Window};
/// use rasterproof::geom::Point;
/// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
/// let w = Window::rect(q(0), q(0), q(4), q(4)).unwrap();
/// // A triangle poking out of the right side: (2,1) (6,1) (2,3) is cut at x = 4, where its
/// // hypotenuse x + 2y = 8 is at y = 2.
/// let tri = [Point::from_ints(2, 1), Point::from_ints(6, 1), Point::from_ints(2, 3)];
/// let out = clip_exact(&tri, &w.half_planes());
/// assert_eq!(out, vec![Point::from_ints(2, 1), Point::from_ints(4, 1), Point::from_ints(4, 2), Point::from_ints(2, 3)]);
/// ```
pub fn clip_exact(subject: &[Point], planes: &[HalfPlane]) -> Vec<Point> {
    let mut poly = subject.to_vec();
    for h in planes {
        let mut out = Vec::with_capacity(poly.len() + 2);
        for (k, e) in poly.iter().enumerate() {
            let s = &poly[(k + poly.len() - 1) % poly.len()];
            let (s_in, e_in) = (h.contains(s), h.contains(e));
            if s_in != e_in {
                out.push(h.intersect(s, e).expect("one end in, one out: not parallel"));
            }
            if e_in {
                out.push(e.clone());
            }
        }
        poly = merged(out);
    }
    poly
}

/// Without repeated consecutive vertices (the last compared with the first too).
pub(crate) fn merged<T: PartialEq>(mut points: Vec<T>) -> Vec<T> {
    points.dedup();
    while points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    points
}

/// Every contour of `poly` clipped against `window`, exactly; the fill rule is kept, and
/// a contour with nothing inside becomes empty (it then covers nothing).
pub fn clip_polygon(poly: &Polygon, window: &Window) -> Polygon {
    let planes = window.half_planes();
    Polygon {
        outline: clip_exact(&poly.outline, &planes),
        holes: poly.holes.iter().map(|h| clip_exact(h, &planes)).collect(),
        fill_rule: poly.fill_rule,
    }
}

macro_rules! float_sutherland_hodgman {
    ($name:ident, $plane:ty, $vec:ty, $doc:literal) => {
        #[doc = $doc]
        pub fn $name(subject: &[$vec], planes: &[$plane]) -> Vec<$vec> {
            let mut poly = subject.to_vec();
            for h in planes {
                let mut out = Vec::with_capacity(poly.len() + 2);
                for (k, &e) in poly.iter().enumerate() {
                    let s = poly[(k + poly.len() - 1) % poly.len()];
                    let (s_in, e_in) = (h.contains(s), h.contains(e));
                    if s_in != e_in {
                        out.push(h.intersect(s, e));
                    }
                    if e_in {
                        out.push(e);
                    }
                }
                poly = merged(out);
            }
            poly
        }
    };
}

float_sutherland_hodgman!(
    clip_f64,
    HalfPlaneF64,
    DVec2,
    "Sutherland-Hodgman in f64: the same four cases, each intersection rounded."
);
float_sutherland_hodgman!(
    clip_f32,
    HalfPlaneF32,
    Vec2,
    "Sutherland-Hodgman in f32: the same four cases, each intersection rounded."
);
