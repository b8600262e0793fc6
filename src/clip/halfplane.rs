//! Point clipping against half-planes: a point is kept when `<p - p0, n> >= 0` for a point `p0` on the
//! boundary and a normal `n` pointing inside, or, in homogeneous line coordinates,
//! when `e . (x, y, 1) = a x + b y + c >= 0`. Points on the boundary are kept.
//! Exact over `BigRational`, and in f32 / f64 with glam.

use glam::{DVec2, Vec2};
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::geom::Point;

/// The half-plane `a x + b y + c >= 0`, exactly (`(a, b) != (0, 0)`).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct HalfPlane {
    /// `a`.
    pub a: BigRational,
    /// `b`.
    pub b: BigRational,
    /// `c`.
    pub c: BigRational,
}

impl HalfPlane {
    /// From homogeneous line coordinates `e = (a, b, c)`; `None` when `a = b = 0`.
    pub fn from_line(a: BigRational, b: BigRational, c: BigRational) -> Option<HalfPlane> {
        (!(a.is_zero() && b.is_zero())).then_some(HalfPlane { a, b, c })
    }

    /// The points `p` with `<p - point, normal> >= 0`; `None` for a zero normal.
    ///
    /// ```
    /// use rasterproof::clip::halfplane::HalfPlane;
    /// use rasterproof::geom::Point;
    /// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
    /// // x >= 2: through (2, 0) with normal (1, 0).
    /// let h = HalfPlane::from_point_normal(&Point::from_ints(2, 0), [q(1), q(0)]).unwrap();
    /// assert!(h.contains(&Point::from_ints(2, 7))); // on the boundary: kept
    /// assert!(!h.contains(&Point::from_fractions(3, 2, 0, 1)));
    /// assert_eq!(h, HalfPlane::from_line(q(1), q(0), q(-2)).unwrap());
    /// ```
    pub fn from_point_normal(point: &Point, normal: [BigRational; 2]) -> Option<HalfPlane> {
        let [a, b] = normal;
        let c = -(&a * &point.x + &b * &point.y);
        HalfPlane::from_line(a, b, c)
    }

    /// The half-plane to the left of the directed line `p -> q` in a y-down image, i.e.
    /// where the edge function `E_{pq}` is `>= 0`; `None` when `p == q`.
    pub fn inside_of_edge(p: &Point, q: &Point) -> Option<HalfPlane> {
        // E(x, y) = (x - p.x) dy - (y - p.y) dx
        let (dx, dy) = (&q.x - &p.x, &q.y - &p.y);
        let c = &p.y * &dx - &p.x * &dy;
        HalfPlane::from_line(dy, -dx, c)
    }

    /// `a x + b y + c` at `p`.
    pub fn value(&self, p: &Point) -> BigRational {
        &self.a * &p.x + &self.b * &p.y + &self.c
    }

    /// Whether `p` is kept: `value >= 0`.
    pub fn contains(&self, p: &Point) -> bool {
        !self.value(p).is_negative()
    }

    /// The point where segment `p -> q` meets the boundary line, exactly:
    /// `p + t (q - p)` with `t = v(p) / (v(p) - v(q))`. `None` when the segment is
    /// parallel to the line (`v(p) == v(q)`).
    pub fn intersect(&self, p: &Point, q: &Point) -> Option<Point> {
        let (vp, vq) = (self.value(p), self.value(q));
        let den = &vp - &vq;
        if den.is_zero() {
            return None;
        }
        let t = vp / den;
        Some(Point::new(&p.x + &t * (&q.x - &p.x), &p.y + &t * (&q.y - &p.y)))
    }

    /// The nearest f64 coefficients (`None` when one does not fit).
    pub fn to_f64(&self) -> Option<HalfPlaneF64> {
        use num_traits::ToPrimitive;
        let f = |v: &BigRational| v.to_f64().filter(|x| x.is_finite());
        Some(HalfPlaneF64 {
            n: DVec2::new(f(&self.a)?, f(&self.b)?),
            c: f(&self.c)?,
        })
    }

    /// The nearest f32 coefficients (`None` when one does not fit).
    pub fn to_f32(&self) -> Option<HalfPlaneF32> {
        let f = crate::num::exact::nearest_f32;
        Some(HalfPlaneF32 {
            n: Vec2::new(f(&self.a)?, f(&self.b)?),
            c: f(&self.c)?,
        })
    }
}

/// The part of segment `a -> b` inside every half-plane (Cyrus-Beck: each half-plane
/// bounds the parameter `t` of `a + t (b - a)` from one side), endpoints in the segment's
/// direction, exactly; `None` when nothing is inside. For a convex window this is what
/// Cohen-Sutherland computes for a rectangle.
///
/// ```
/// use rasterproof::clip::halfplane::{clip_segment_exact, HalfPlane};
/// use rasterproof::geom::Point;
/// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
/// // x + y <= 4 and x >= 0: (-2, 1) -> (6, 1) keeps x in [0, 3].
/// let planes = [HalfPlane::from_line(q(-1), q(-1), q(4)).unwrap(), HalfPlane::from_line(q(1), q(0), q(0)).unwrap()];
/// let kept = clip_segment_exact(&Point::from_ints(-2, 1), &Point::from_ints(6, 1), &planes);
/// assert_eq!(kept, Some((Point::from_ints(0, 1), Point::from_ints(3, 1))));
/// ```
pub fn clip_segment_exact(a: &Point, b: &Point, planes: &[HalfPlane]) -> Option<(Point, Point)> {
    let (mut t0, mut t1) = (BigRational::zero(), BigRational::from_integer(1.into()));
    for h in planes {
        // v(t) = v(a) + t (v(b) - v(a)) >= 0
        let (va, vb) = (h.value(a), h.value(b));
        let slope = &vb - &va;
        if slope.is_zero() {
            if va.is_negative() {
                return None;
            }
            continue;
        }
        let t = -&va / &slope;
        if slope.is_positive() {
            t0 = t0.max(t);
        } else {
            t1 = t1.min(t);
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: &BigRational| Point::new(&a.x + t * (&b.x - &a.x), &a.y + t * (&b.y - &a.y));
    Some((at(&t0), at(&t1)))
}

macro_rules! float_half_plane {
    ($name:ident, $float:ty, $vec:ty, $doc:literal) => {
        #[doc = $doc]
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub struct $name {
            /// `(a, b)`.
            pub n: $vec,
            /// `c`.
            pub c: $float,
        }

        impl $name {
            /// `a x + b y + c` at `p`, in this float type.
            pub fn value(&self, p: $vec) -> $float {
                self.n.dot(p) + self.c
            }

            /// Whether `p` is kept: `value >= 0`.
            pub fn contains(&self, p: $vec) -> bool {
                self.value(p) >= 0.0
            }

            /// The part of segment `a -> b` inside every half-plane (Cyrus-Beck), rounded
            /// at every step; `None` when nothing is inside.
            pub fn clip_segment(a: $vec, b: $vec, planes: &[$name]) -> Option<($vec, $vec)> {
                let (mut t0, mut t1): ($float, $float) = (0.0, 1.0);
                for h in planes {
                    let (va, vb) = (h.value(a), h.value(b));
                    let slope = vb - va;
                    if slope == 0.0 {
                        if va < 0.0 {
                            return None;
                        }
                        continue;
                    }
                    let t = -va / slope;
                    if slope > 0.0 {
                        t0 = t0.max(t);
                    } else {
                        t1 = t1.min(t);
                    }
                }
                (t0 <= t1).then(|| (a + (b - a) * t0, a + (b - a) * t1))
            }

            /// Where segment `p -> q` meets the boundary line: `p + t (q - p)` with
            /// `t = v(p) / (v(p) - v(q))`, rounded at every step.
            pub fn intersect(&self, p: $vec, q: $vec) -> $vec {
                let (vp, vq) = (self.value(p), self.value(q));
                p + (q - p) * (vp / (vp - vq))
            }
        }
    };
}

float_half_plane!(HalfPlaneF64, f64, DVec2, "A half-plane `n . p + c >= 0` in f64.");
float_half_plane!(HalfPlaneF32, f32, Vec2, "A half-plane `n . p + c >= 0` in f32.");
