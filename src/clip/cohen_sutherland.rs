//! Cohen-Sutherland (Sproull & Sutherland 1968; Newman & Sproull 1973): each endpoint gets
//! a 4-bit outcode TBRL = (y > ymax, y < ymin, x > xmax, x < xmin); `a | b == 0` keeps the
//! segment, `a & b != 0` rejects it, otherwise an outside endpoint is moved to the
//! boundary of one of its set bits and the test repeats. The exact form computes every
//! intersection as a rational; the float forms round at each step (the new point's clipped
//! coordinate is set to the boundary value exactly, so a bit once cleared is not set again
//! by that coordinate, and the loop is capped at 8 rounds in case rounding sets another).

use glam::{DVec2, Vec2};
use num_rational::BigRational;

use super::Rect;
use crate::geom::Point;

/// `x < xmin`.
pub const LEFT: u8 = 1;
/// `x > xmax`.
pub const RIGHT: u8 = 2;
/// `y < ymin`.
pub const BOTTOM: u8 = 4;
/// `y > ymax`.
pub const TOP: u8 = 8;

/// The TBRL outcode of `p`.
///
/// ```
/// use rasterproof::clip::{cohen_sutherland::{outcode, LEFT, TOP}, Window, Rect};
/// use rasterproof::geom::Point;
/// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
/// let Window::Rect(r) = Window::rect(q(0), q(0), q(10), q(10)).unwrap() else { unreachable!() };
/// assert_eq!(outcode(&Point::from_ints(-1, 11), &r), LEFT | TOP);
/// assert_eq!(outcode(&Point::from_ints(10, 0), &r), 0); // the boundary is inside
/// ```
pub fn outcode(p: &Point, r: &Rect) -> u8 {
    let mut code = 0;
    if p.x < r.xmin {
        code |= LEFT;
    } else if p.x > r.xmax {
        code |= RIGHT;
    }
    if p.y < r.ymin {
        code |= BOTTOM;
    } else if p.y > r.ymax {
        code |= TOP;
    }
    code
}

/// The part of segment `a -> b` inside `r` (boundary included), endpoints in the original
/// direction, exactly; `None` when nothing is inside.
///
/// ```
/// use rasterproof::clip::{cohen_sutherland::clip_exact, Window};
/// use rasterproof::geom::Point;
/// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
/// let Window::Rect(r) = Window::rect(q(0), q(0), q(10), q(10)).unwrap() else { unreachable!() };
/// // (-5, 1) -> (15, 5): y = 1 + (x + 5) / 5, so x = 0 gives y = 2 and x = 10 gives y = 4.
/// let (p, e) = clip_exact(&Point::from_ints(-5, 1), &Point::from_ints(15, 5), &r).unwrap();
/// assert_eq!((p, e), (Point::from_ints(0, 2), Point::from_ints(10, 4)));
/// assert!(clip_exact(&Point::from_ints(-5, -1), &Point::from_ints(15, -1), &r).is_none());
/// ```
pub fn clip_exact(a: &Point, b: &Point, r: &Rect) -> Option<(Point, Point)> {
    let (mut p, mut q) = (a.clone(), b.clone());
    // Each round clears one bit of one endpoint for good (the new point lies on that
    // boundary and on the segment), so at most 4 rounds can happen.
    for _ in 0..=4 {
        let (cp, cq) = (outcode(&p, r), outcode(&q, r));
        if cp | cq == 0 {
            return Some((p, q));
        }
        if cp & cq != 0 {
            return None;
        }
        let code = if cp != 0 { cp } else { cq };
        let moved = boundary_point(a, b, code, r);
        if cp != 0 {
            p = moved;
        } else {
            q = moved;
        }
    }
    unreachable!("Cohen-Sutherland ends within 4 rounds in exact arithmetic")
}

/// The point of line `a b` on the boundary named by the lowest set bit of `code`.
fn boundary_point(a: &Point, b: &Point, code: u8, r: &Rect) -> Point {
    let along_x = |x: &BigRational| {
        // t = (x - a.x) / (b.x - a.x); y = a.y + t (b.y - a.y)
        let t = (x - &a.x) / (&b.x - &a.x);
        Point::new(x.clone(), &a.y + t * (&b.y - &a.y))
    };
    let along_y = |y: &BigRational| {
        let t = (y - &a.y) / (&b.y - &a.y);
        Point::new(&a.x + t * (&b.x - &a.x), y.clone())
    };
    if code & LEFT != 0 {
        along_x(&r.xmin)
    } else if code & RIGHT != 0 {
        along_x(&r.xmax)
    } else if code & BOTTOM != 0 {
        along_y(&r.ymin)
    } else {
        along_y(&r.ymax)
    }
}

macro_rules! float_cohen_sutherland {
    ($name:ident, $rect:ident, $float:ty, $vec:ty, $doc:literal) => {
        /// A rectangle in the float type: `min` and `max` corners.
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub struct $rect {
            /// `(xmin, ymin)`.
            pub min: $vec,
            /// `(xmax, ymax)`.
            pub max: $vec,
        }

        impl $rect {
            /// The TBRL outcode of `p`.
            pub fn outcode(&self, p: $vec) -> u8 {
                let mut code = 0;
                if p.x < self.min.x {
                    code |= LEFT;
                } else if p.x > self.max.x {
                    code |= RIGHT;
                }
                if p.y < self.min.y {
                    code |= BOTTOM;
                } else if p.y > self.max.y {
                    code |= TOP;
                }
                code
            }
        }

        #[doc = $doc]
        pub fn $name(a: $vec, b: $vec, r: &$rect) -> Option<($vec, $vec)> {
            let (mut p, mut q) = (a, b);
            for _ in 0..8 {
                let (cp, cq) = (r.outcode(p), r.outcode(q));
                if cp | cq == 0 {
                    return Some((p, q));
                }
                if cp & cq != 0 {
                    return None;
                }
                let code = if cp != 0 { cp } else { cq };
                let d = b - a;
                let moved = if code & (LEFT | RIGHT) != 0 {
                    let x = if code & LEFT != 0 { r.min.x } else { r.max.x };
                    <$vec>::new(x, a.y + (x - a.x) / d.x * d.y)
                } else {
                    let y = if code & BOTTOM != 0 { r.min.y } else { r.max.y };
                    <$vec>::new(a.x + (y - a.y) / d.y * d.x, y)
                };
                if cp != 0 {
                    p = moved;
                } else {
                    q = moved;
                }
            }
            // Rounding kept setting bits: return what the loop has (the harness counts
            // such outputs as outside the window).
            Some((p, q))
        }
    };
}

float_cohen_sutherland!(
    clip_f64,
    RectF64,
    f64,
    DVec2,
    "Cohen-Sutherland in f64 (see the module docs for how rounding is contained)."
);
float_cohen_sutherland!(
    clip_f32,
    RectF32,
    f32,
    Vec2,
    "Cohen-Sutherland in f32 (see the module docs for how rounding is contained)."
);

impl Rect {
    /// The nearest f64 rectangle (`None` when a bound does not fit).
    pub fn to_f64(&self) -> Option<RectF64> {
        use num_traits::ToPrimitive;
        let f = |v: &BigRational| v.to_f64().filter(|x| x.is_finite());
        Some(RectF64 {
            min: DVec2::new(f(&self.xmin)?, f(&self.ymin)?),
            max: DVec2::new(f(&self.xmax)?, f(&self.ymax)?),
        })
    }

    /// The nearest f32 rectangle (`None` when a bound does not fit).
    pub fn to_f32(&self) -> Option<RectF32> {
        let f = crate::num::exact::nearest_f32;
        Some(RectF32 {
            min: Vec2::new(f(&self.xmin)?, f(&self.ymin)?),
            max: Vec2::new(f(&self.xmax)?, f(&self.ymax)?),
        })
    }
}
