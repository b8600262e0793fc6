//! The exact evidence behind a verdict at one sample: a triangle's edge values, inclusive
//! flags and which side of the triangle each edge is ([`triangle_at`], computed by
//! [`crate::check`] and re-exported here); a polygon's winding numbers; the distance from
//! a sample to a primitive's nearest edge, exact (its square is rational).

use std::fmt::{self, Write as _};

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

pub use crate::check::{segment_distance2, triangle_at, EdgeAt, Side, TriangleAt};
use crate::convention::TieRule;
use crate::fill::polygon::{contour_winding_exact, locate_exact, Location};
use crate::geom::{Point, Polygon};
use crate::model::Shape;
use crate::num::exact::{exact_text, nearest_f64, terminating_decimal};

/// A polygon at a sample: the winding number of the moved sample around each contour,
/// whether the sample itself lies on an edge, and the verdict.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PolygonAt {
    /// The winding number around the outline, then each hole.
    pub windings: Vec<i64>,
    /// The sample (not moved) lies on an edge of some contour.
    pub on_boundary: bool,
    /// The fill rule holds for the outline's winding number and for no hole's.
    pub inside: bool,
    /// The squared distance to the nearest edge of any contour.
    pub distance2: BigRational,
}

/// Polygon `poly` at sample `p` under `rule`.
pub fn polygon_at(poly: &Polygon, p: &Point, rule: TieRule) -> PolygonAt {
    let windings = windings(poly, p, rule);
    let inside = inside_of(poly, &windings);
    let on_boundary = poly.contours().any(|c| locate_exact(p, c) == Location::Boundary);
    let distance2 = poly
        .contours()
        .flat_map(|c| (0..c.len()).map(move |k| (&c[k], &c[(k + 1) % c.len()])))
        .map(|(a, b)| segment_distance2(p, a, b))
        .min()
        .unwrap_or_else(BigRational::zero);
    PolygonAt {
        windings,
        on_boundary,
        inside,
        distance2,
    }
}

/// Whether `poly` covers the sample `p` under `rule`: [`polygon_at`]'s `inside`, without
/// the boundary and distance evidence (what the reason classifier asks of every
/// alternative convention, many times a pixel).
pub fn polygon_inside(poly: &Polygon, p: &Point, rule: TieRule) -> bool {
    inside_of(poly, &windings(poly, p, rule))
}

/// The winding number of `p` around each contour (the outline first, then the holes).
fn windings(poly: &Polygon, p: &Point, rule: TieRule) -> Vec<i64> {
    poly.contours().map(|c| contour_winding_exact(p, c, rule)).collect()
}

/// Inside the outline by the fill rule and inside none of the holes.
fn inside_of(poly: &Polygon, windings: &[i64]) -> bool {
    poly.fill_rule.inside(windings[0]) && !windings[1..].iter().any(|&w| poly.fill_rule.inside(w))
}

impl fmt::Display for PolygonAt {
    /// `winding 1 (holes: 0), on an edge -> inside`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "winding number {}", self.windings[0])?;
        if self.windings.len() > 1 {
            let holes: Vec<String> = self.windings[1..].iter().map(i64::to_string).collect();
            write!(f, " (holes: {})", holes.join(", "))?;
        }
        if self.on_boundary {
            f.write_str(", the sample lies on an edge")?;
        }
        f.write_str(if self.inside { " -> inside" } else { " -> outside" })
    }
}

/// The squared distance from `p` to a shape's nearest edge (a line's segment). Bresenham
/// lines are measured between pixel addresses (the line runs between pixel centres, so
/// this is the distance between the sample and the ideal line in window space).
pub fn shape_distance2(shape: &Shape, p: &Point, address: [i64; 2]) -> BigRational {
    match shape {
        Shape::Triangle(t) => (0..3)
            .map(|k| segment_distance2(p, &t.v[k], &t.v[(k + 1) % 3]))
            .min()
            .expect("three edges"),
        Shape::Polygon(poly) => polygon_at(poly, p, TieRule::TopLeft).distance2,
        Shape::Diamond { from, to } => segment_distance2(p, from, to),
        Shape::Bresenham { from, to, .. } => {
            let pt = |c: [i64; 2]| Point::from_ints(c[0], c[1]);
            segment_distance2(&pt(address), &pt(*from), &pt(*to))
        }
    }
}

/// The edges of a shape as segments (a Bresenham line between its pixel addresses), and
/// the point a sample is measured from (for Bresenham lines the pixel's address).
fn segments(shape: &Shape, p: &Point, address: [i64; 2]) -> (Vec<(Point, Point)>, Point) {
    match shape {
        Shape::Triangle(t) => (
            (0..3).map(|k| (t.v[k].clone(), t.v[(k + 1) % 3].clone())).collect(),
            p.clone(),
        ),
        Shape::Polygon(poly) => (
            poly.contours()
                .flat_map(|c| (0..c.len()).map(move |k| (c[k].clone(), c[(k + 1) % c.len()].clone())))
                .collect(),
            p.clone(),
        ),
        Shape::Diamond { from, to } => (vec![(from.clone(), to.clone())], p.clone()),
        Shape::Bresenham { from, to, .. } => {
            let pt = |c: [i64; 2]| Point::from_ints(c[0], c[1]);
            (vec![(pt(*from), pt(*to))], pt(address))
        }
    }
}

/// Whether the sample `p` (pixel `address`) lies within float32's error of the shape's
/// nearest edge: at distance `d <= 2^-20 M^2 / L`, `M` the largest coordinate magnitude of
/// that edge's endpoints and the sample (at least 1 px), `L` the edge's length (a
/// zero-length edge: `d == 0`). `2^-20 M^2` is 8 units in the last place of a float32 at
/// `M^2` (24 significant bits: an ulp at `v` is at most `2^-23 v`), the error of a few
/// roundings of an edge function `A x + B y + C` whose terms reach `M^2`; divided by `L`
/// it is how far that moves the edge. Decided exactly: `d^2 L^2 2^40 <= M^4`.
pub fn within_float_error(shape: &Shape, p: &Point, address: [i64; 2]) -> bool {
    let (edges, q) = segments(shape, p, address);
    let Some((d2, (a, b))) = edges
        .into_iter()
        .map(|(a, b)| (segment_distance2(&q, &a, &b), (a, b)))
        .min_by(|x, y| x.0.cmp(&y.0))
    else {
        return false;
    };
    let (dx, dy) = (&b.x - &a.x, &b.y - &a.y);
    let l2 = &dx * &dx + &dy * &dy;
    if l2.is_zero() {
        return d2.is_zero();
    }
    let mut m = BigRational::one();
    for v in [&a.x, &a.y, &b.x, &b.y, &q.x, &q.y] {
        let v = v.abs();
        if v > m {
            m = v;
        }
    }
    let m2 = &m * &m;
    d2 * l2 * BigRational::from_integer(BigInt::from(1u64 << 40)) <= &m2 * &m2
}

/// A distance whose square is `d2`, for people: the exact value (`1/2`, or `√(1/8)` when
/// it is not rational) and a decimal.
pub fn distance_text(d2: &BigRational) -> String {
    let mut s = exact_distance(d2);
    let _ = write!(s, " ≈ {:.4} px", distance_f64(d2));
    s
}

/// A distance whose square is `d2` with a decimal beside it: `15725/32 (491.40625) px`
/// (the decimal exact when the distance is a fraction whose decimal ends within 20
/// places), `√(1/8) (≈ 0.353553) px` otherwise.
pub fn distance_decimal_text(d2: &BigRational) -> String {
    let exact = exact_distance(d2);
    let root = |n: &BigInt| {
        let r = n.sqrt();
        (&r * &r == *n).then_some(r)
    };
    let decimal = match (root(d2.numer()), root(d2.denom())) {
        (Some(n), Some(d)) => terminating_decimal(&BigRational::new(n, d)),
        _ => None,
    };
    match decimal {
        Some(dec) if dec == exact => format!("{exact} px"),
        Some(dec) => format!("{exact} ({dec}) px"),
        None => format!("{exact} (≈ {:.6}) px", distance_f64(d2)),
    }
}

/// The exact distance whose square is `d2`: a fraction when `d2` is a rational square,
/// else `√(d2)`.
pub fn exact_distance(d2: &BigRational) -> String {
    let root = |n: &BigInt| {
        let r = n.sqrt();
        (&r * &r == *n).then_some(r)
    };
    match (root(d2.numer()), root(d2.denom())) {
        (Some(n), Some(d)) => exact_text(&BigRational::new(n, d)),
        _ => format!("√({})", exact_text(d2)),
    }
}

/// The distance whose square is `d2`, as the nearest float's square root.
pub fn distance_f64(d2: &BigRational) -> f64 {
    nearest_f64(d2).map_or(f64::INFINITY, f64::sqrt)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn distances_by_hand() {
        let (a, b) = (Point::from_ints(0, 0), Point::from_ints(4, 0));
        // Above the middle: the perpendicular, 3.
        assert_eq!(segment_distance2(&Point::from_ints(2, 3), &a, &b), q(9, 1));
        // Beyond the end (6, 3): to b, 2^2 + 3^2 = 13.
        assert_eq!(segment_distance2(&Point::from_ints(6, 3), &a, &b), q(13, 1));
        // The diagonal x = y from (0,0) to (4,4) and the point (1, 0): 1/√2, squared 1/2.
        let d = segment_distance2(&Point::from_ints(1, 0), &a, &Point::from_ints(4, 4));
        assert_eq!(d, q(1, 2));
        assert_eq!(exact_distance(&d), "√(1/2)");
        assert_eq!(exact_distance(&q(9, 4)), "3/2");
        assert_eq!(distance_text(&q(1, 4)), "1/2 ≈ 0.5000 px");
        assert_eq!(
            distance_decimal_text(&q(15725 * 15725, 32 * 32)),
            "15725/32 (491.40625) px"
        );
        assert_eq!(distance_decimal_text(&q(1, 400)), "1/20 (0.05) px");
        assert_eq!(distance_decimal_text(&q(9, 1)), "3 px");
        assert_eq!(distance_decimal_text(&q(1, 9)), "1/3 (≈ 0.333333) px");
        assert_eq!(distance_decimal_text(&q(1, 8)), "√(1/8) (≈ 0.353553) px");
        // A degenerate segment is its point.
        assert_eq!(segment_distance2(&Point::from_ints(3, 4), &a, &a), q(25, 1));
    }

    #[test]
    fn polygon_windings_by_hand() {
        let sq = |a: i64, b: i64| {
            vec![
                Point::from_ints(a, a),
                Point::from_ints(b, a),
                Point::from_ints(b, b),
                Point::from_ints(a, b),
            ]
        };
        let mut poly = Polygon::new(sq(0, 8), crate::geom::FillRule::NonZero);
        poly.holes.push(sq(2, 6));
        let at = polygon_at(&poly, &Point::new(q(7, 2), q(7, 2)), TieRule::TopLeft);
        assert_eq!(at.windings.iter().map(|w| w.abs()).collect::<Vec<_>>(), [1, 1]);
        assert!(!at.inside && !at.on_boundary);
        // 3.5 is 1.5 from the hole's edge at 2 and from its edge at 6 (squared 9/4).
        assert_eq!(at.distance2, q(9, 4));
        let edge = polygon_at(&poly, &Point::new(q(0, 1), q(1, 2)), TieRule::TopLeft);
        assert!(edge.on_boundary && edge.inside);
    }
}
