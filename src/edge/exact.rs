//! Exact edge functions over `BigRational`: the arithmetic of the oracle.

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::convention::TieRule;
use crate::geom::{Point, Triangle};

/// `E(p)` for the edge `a -> b`, in Pineda's (1988) form, exactly.
///
/// ```
/// use rasterproof::edge::exact::edge_function;
/// use rasterproof::geom::Point;
/// // |E| is twice the area of (a, b, p): here a 4x3 right triangle, area 6.
/// let e = edge_function(&Point::from_ints(0, 0), &Point::from_ints(4, 0), &Point::from_ints(0, 3));
/// assert_eq!(e, num_rational::BigRational::from_integer((-12).into()));
/// ```
pub fn edge_function(a: &Point, b: &Point, p: &Point) -> BigRational {
    (&p.x - &a.x) * (&b.y - &a.y) - (&p.y - &a.y) * (&b.x - &a.x)
}

/// Twice the signed area of a triangle: `E_{v0 v1}(v2)`.
pub fn area2(t: &Triangle) -> BigRational {
    edge_function(&t.v[0], &t.v[1], &t.v[2])
}

/// The triangle with v1 and v2 swapped when needed so that `E > 0` is its interior;
/// `None` for a zero-area triangle (it covers nothing).
pub fn oriented(t: &Triangle) -> Option<Triangle> {
    let area = area2(t);
    if area.is_zero() {
        None
    } else if area.is_positive() {
        Some(t.clone())
    } else {
        Some(t.reversed())
    }
}

/// One edge of an oriented triangle, with its inclusive flag.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExactEdge {
    /// The start vertex.
    pub a: Point,
    /// `b.x - a.x`.
    pub dx: BigRational,
    /// `b.y - a.y`.
    pub dy: BigRational,
    /// Whether samples with `E == 0` are inside (from the tie rule).
    pub inclusive: bool,
}

impl ExactEdge {
    /// The edge `a -> b` of a triangle whose interior is `E > 0`.
    pub fn new(a: &Point, b: &Point, rule: TieRule) -> ExactEdge {
        let dx = &b.x - &a.x;
        let dy = &b.y - &a.y;
        let inclusive = rule.is_inclusive(dx.cmp(&BigRational::zero()), dy.cmp(&BigRational::zero()));
        ExactEdge {
            a: a.clone(),
            dx,
            dy,
            inclusive,
        }
    }

    /// `E(p)`, exactly.
    pub fn value(&self, p: &Point) -> BigRational {
        (&p.x - &self.a.x) * &self.dy - (&p.y - &self.a.y) * &self.dx
    }

    /// Whether `p` is on the inside of this edge: `E > 0`, or `E == 0` on an inclusive edge.
    pub fn contains(&self, p: &Point) -> bool {
        let e = self.value(p);
        e.is_positive() || (e.is_zero() && self.inclusive)
    }
}

/// The three edges v0->v1, v1->v2, v2->v0 of the oriented triangle; `None` for zero area.
pub fn triangle_edges(t: &Triangle, rule: TieRule) -> Option<[ExactEdge; 3]> {
    let t = oriented(t)?;
    let [a, b, c] = &t.v;
    Some([
        ExactEdge::new(a, b, rule),
        ExactEdge::new(b, c, rule),
        ExactEdge::new(c, a, rule),
    ])
}
