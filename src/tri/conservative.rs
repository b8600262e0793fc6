//! Conservative rasterization of one triangle, exactly: whether a pixel's square meets the
//! triangle (overestimation) or lies inside it (underestimation, "inner coverage"), with
//! the square grown by an uncertainty band where a rule allows one.
//!
//! Both tests are plain exact geometry on the closed pixel square `[i, i + 1] x [j, j + 1]`:
//!
//! - **meets**: a square and a triangle (possibly degenerate: a segment or a point) are
//!   convex, so they meet exactly when no axis separates them; the axes to try are the
//!   square's two and the normals of the triangle's edges (the separating axis theorem).
//!   With `closed` the projections may touch (the closed square against the closed
//!   triangle: touching at an edge or a corner counts, as Vulkan's "including its edges
//!   ... including its sides"); without, they must overlap in more than a point (the open
//!   square against the closed triangle: touching alone does not count).
//! - **inside**: the square's four corners lie in the closed triangle (which is convex);
//!   never for a triangle of zero area.
//!
//! Written to be read: exact rationals, one pixel at a time.

use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use crate::geom::{Point, Triangle};

/// The closed square of pixel `(i, j)` grown by `grow` on every side (`grow` may be
/// negative: shrunk), as `[x0, y0, x1, y1]`.
pub fn pixel_square(i: i64, j: i64, grow: &BigRational) -> [BigRational; 4] {
    let (x, y) = (BigRational::from_integer(i.into()), BigRational::from_integer(j.into()));
    let one = BigRational::one();
    [&x - grow, &y - grow, x + &one + grow, y + one + grow]
}

/// The square's corners, clockwise in a y-down image from the top left.
fn corners(sq: &[BigRational; 4]) -> [Point; 4] {
    let [x0, y0, x1, y1] = sq;
    [
        Point::new(x0.clone(), y0.clone()),
        Point::new(x1.clone(), y0.clone()),
        Point::new(x1.clone(), y1.clone()),
        Point::new(x0.clone(), y1.clone()),
    ]
}

/// One separating axis `a x + b y` and the triangle's extent along it.
#[derive(Debug, Clone)]
struct Axis {
    a: BigRational,
    b: BigRational,
    lo: BigRational,
    hi: BigRational,
}

impl Axis {
    /// The axis `(a, b)` with `points`' smallest and largest `a x + b y`.
    fn new(a: BigRational, b: BigRational, points: &[Point]) -> Axis {
        let dots: Vec<BigRational> = points.iter().map(|p| &a * &p.x + &b * &p.y).collect();
        let lo = dots.iter().min().expect("a triangle has points").clone();
        let hi = dots.iter().max().expect("a triangle has points").clone();
        Axis { a, b, lo, hi }
    }

    /// Whether the square `[x0, y0, x1, y1]`'s extent along the axis overlaps the
    /// triangle's: touching counts with `closed`. The square's extent is read from the
    /// signs of `a` and `b` (the smallest `a x` is at `x0` when `a >= 0`), no corner
    /// needed.
    fn overlaps(&self, sq: &[BigRational; 4], closed: bool) -> bool {
        let [x0, y0, x1, y1] = sq;
        let (ax_lo, ax_hi) = if self.a.is_negative() { (x1, x0) } else { (x0, x1) };
        let (by_lo, by_hi) = if self.b.is_negative() { (y1, y0) } else { (y0, y1) };
        let s_lo = &self.a * ax_lo + &self.b * by_lo;
        let s_hi = &self.a * ax_hi + &self.b * by_hi;
        if closed {
            s_hi >= self.lo && self.hi >= s_lo
        } else {
            s_hi > self.lo && self.hi > s_lo
        }
    }
}

/// A triangle ready for the conservative tests at every pixel: its separating axes with
/// its extent along each, and its orientation, computed once.
#[derive(Debug, Clone)]
pub struct ConservativeTriangle {
    v: [Point; 3],
    axes: Vec<Axis>,
    /// `Some(true)` for a positive signed area (`cross(b - a, c - a) > 0`), `None` for
    /// zero area.
    positive: Option<bool>,
}

impl ConservativeTriangle {
    /// The axes of `tri`: the square's two, and the normals of its non-degenerate edges.
    pub fn new(tri: &Triangle) -> ConservativeTriangle {
        let (zero, one) = (BigRational::zero(), BigRational::one());
        let mut axes = vec![
            Axis::new(one.clone(), zero.clone(), &tri.v),
            Axis::new(zero, one, &tri.v),
        ];
        for k in 0..3 {
            let (a, b) = (&tri.v[k], &tri.v[(k + 1) % 3]);
            let (dx, dy) = (&b.x - &a.x, &b.y - &a.y);
            if !(dx.is_zero() && dy.is_zero()) {
                axes.push(Axis::new(-dy, dx, &tri.v));
            }
        }
        let area = cross(&tri.v[0], &tri.v[1], &tri.v[2]);
        ConservativeTriangle {
            v: tri.v.clone(),
            axes,
            positive: (!area.is_zero()).then(|| area.is_positive()),
        }
    }

    /// Whether the square `sq` (`[x0, y0, x1, y1]`, `x0 < x1`, `y0 < y1`) meets the
    /// triangle: the closed square against the closed triangle with `closed`, the open
    /// square against the closed triangle without (see the module docs).
    pub fn meets(&self, sq: &[BigRational; 4], closed: bool) -> bool {
        self.axes.iter().all(|axis| axis.overlaps(sq, closed))
    }

    /// Whether the square `sq` lies inside the closed triangle (all four corners in it);
    /// false for a triangle of zero area.
    pub fn contains_square(&self, sq: &[BigRational; 4]) -> bool {
        let Some(positive) = self.positive else {
            return false;
        };
        let [a, b, c] = &self.v;
        let inside = |p: &Point| {
            [cross(a, b, p), cross(b, c, p), cross(c, a, p)]
                .iter()
                .all(|e| e.is_zero() || e.is_positive() == positive)
        };
        corners(sq).iter().all(inside)
    }

    /// Whether the triangle has zero area.
    pub fn is_degenerate(&self) -> bool {
        self.positive.is_none()
    }
}

/// `cross(q - p, r - p)`: twice the signed area of `p, q, r`.
fn cross(p: &Point, q: &Point, r: &Point) -> BigRational {
    (&q.x - &p.x) * (&r.y - &p.y) - (&q.y - &p.y) * (&r.x - &p.x)
}

/// Whether the square `sq` (`[x0, y0, x1, y1]`, `x0 < x1`, `y0 < y1`) meets `tri`: closed
/// square against the closed triangle with `closed`, open square against the closed
/// triangle without (see the module docs). One test; at many pixels, set the triangle up
/// once with [`ConservativeTriangle`].
///
/// ```
/// use num_rational::BigRational;
/// use num_traits::Zero;
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::tri::conservative::{pixel_square, square_meets};
/// // (0,0) (2,0) (0,2): its hypotenuse x + y = 2 touches pixel (1, 1) at its corner only.
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(2, 0), Point::from_ints(0, 2));
/// let p11 = pixel_square(1, 1, &BigRational::zero());
/// assert!(square_meets(&t, &p11, true));
/// assert!(!square_meets(&t, &p11, false));
/// ```
pub fn square_meets(tri: &Triangle, sq: &[BigRational; 4], closed: bool) -> bool {
    ConservativeTriangle::new(tri).meets(sq, closed)
}

/// Whether the square `sq` lies inside the closed triangle `tri` (all four corners in it);
/// false for a triangle of zero area.
///
/// ```
/// use num_rational::BigRational;
/// use num_traits::Zero;
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::tri::conservative::{pixel_square, square_inside};
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
/// assert!(square_inside(&t, &pixel_square(1, 1, &BigRational::zero())));   // x + y <= 4 at (2, 2)
/// assert!(!square_inside(&t, &pixel_square(2, 1, &BigRational::zero())));  // (3, 2): 5 > 4
/// ```
pub fn square_inside(tri: &Triangle, sq: &[BigRational; 4]) -> bool {
    ConservativeTriangle::new(tri).contains_square(sq)
}

/// Whether `tri` has zero area.
pub fn is_degenerate(tri: &Triangle) -> bool {
    cross(&tri.v[0], &tri.v[1], &tri.v[2]).is_zero()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn a_segment_meets_the_squares_it_crosses() {
        // The degenerate triangle along y = 1/2 from x = 1/2 to x = 5/2.
        let p = |x: i64| Point::from_fractions(x, 2, 1, 2);
        let seg = Triangle::new(p(1), p(5), p(3));
        let sq = |i| pixel_square(i, 0, &BigRational::zero());
        assert!(square_meets(&seg, &sq(0), false) && square_meets(&seg, &sq(2), false));
        assert!(!square_meets(&seg, &sq(3), true));
        assert!(!square_meets(&seg, &pixel_square(0, 1, &BigRational::zero()), true));
        // Along the row boundary y = 1: touches pixels of rows 0 and 1, inside neither.
        let edge = Triangle::new(Point::from_ints(0, 1), Point::from_ints(2, 1), Point::from_ints(1, 1));
        assert!(square_meets(&edge, &sq(0), true) && !square_meets(&edge, &sq(0), false));
        assert!(is_degenerate(&edge) && !square_inside(&edge, &sq(0)));
    }

    #[test]
    fn grown_squares_reach_further() {
        // (0,0) (2,0) (0,2) and pixel (1, 1): the hypotenuse is 0 px from its corner;
        // pixel (2, 0)'s square [2,3]x[0,1] touches the vertex (2, 0) only.
        let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(2, 0), Point::from_ints(0, 2));
        assert!(!square_meets(&t, &pixel_square(2, 0, &BigRational::zero()), false));
        assert!(square_meets(&t, &pixel_square(2, 0, &q(1, 256)), false));
        // Pixel (3, 0) is 1 px away: a 1/2 px band does not reach it.
        assert!(!square_meets(&t, &pixel_square(3, 0, &q(1, 2)), true));
        assert!(square_meets(&t, &pixel_square(3, 0, &BigRational::one()), true));
        // Pixel (0, 0) is inside; grown by 1/256 it is not.
        assert!(square_inside(&t, &pixel_square(0, 0, &BigRational::zero())));
        assert!(!square_inside(&t, &pixel_square(0, 0, &q(1, 256))));
    }
}
