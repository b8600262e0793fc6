//! Explaining one pixel: a triangle's exact edge evidence at a sample ([`triangle_at`]:
//! each oriented edge's value, side, inclusive flag and distance, and the verdict), and
//! that evidence as one line ([`explain_sample`]). The oracle's explanations
//! (`oracle::evidence`) re-export it.

use std::cmp::Ordering;
use std::fmt::{self, Write as _};

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::convention::{AnyTieRule, Target};
use crate::edge::exact::{edge_function, oriented};
use crate::geom::{Point, Triangle};
use crate::num::exact::{exact_text, pair_text};
use crate::raster::sample_exact;

/// Which side of its triangle an edge is, from its direction once the triangle is
/// oriented so its interior is `E > 0` (y down).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Side {
    /// Runs down the screen, the interior to its right.
    Left,
    /// Runs up the screen.
    Right,
    /// Horizontal, the interior below it.
    Top,
    /// Horizontal, the interior above it.
    Bottom,
}

impl Side {
    /// Of an oriented edge `(dx, dy)`.
    pub fn of(dx: Ordering, dy: Ordering) -> Side {
        match (dy, dx) {
            (Ordering::Greater, _) => Side::Left,
            (Ordering::Less, _) => Side::Right,
            (Ordering::Equal, Ordering::Less) => Side::Top,
            (Ordering::Equal, _) => Side::Bottom,
        }
    }

    /// `left`, `right`, `top` or `bottom`.
    pub fn name(self) -> &'static str {
        match self {
            Side::Left => "left",
            Side::Right => "right",
            Side::Top => "top",
            Side::Bottom => "bottom",
        }
    }
}

/// One edge of an oriented triangle at a sample.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EdgeAt {
    /// 0, 1 or 2: the edge v0->v1, v1->v2, v2->v0 of the oriented triangle.
    pub index: usize,
    /// Its start.
    pub from: Point,
    /// Its end.
    pub to: Point,
    /// `E` at the sample, exactly.
    pub value: BigRational,
    /// Which side of the triangle it is.
    pub side: Side,
    /// Whether it owns the samples on it under the rule asked for.
    pub inclusive: bool,
    /// The squared distance from the sample to the edge (the segment), exactly.
    pub distance2: BigRational,
}

/// A triangle at a sample: its oriented edges and the verdict.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TriangleAt {
    /// The three edges.
    pub edges: [EdgeAt; 3],
    /// Every edge has `E > 0`, or `E == 0` and is inclusive.
    pub inside: bool,
}

/// Triangle `t` at sample `p` under `rule`; `None` for a zero-area triangle (it covers
/// nothing under any rule).
pub fn triangle_at(t: &Triangle, p: &Point, rule: AnyTieRule) -> Option<TriangleAt> {
    let t = oriented(t)?;
    let edge = |index: usize| {
        let (a, b) = (&t.v[index], &t.v[(index + 1) % 3]);
        let zero = BigRational::zero();
        let (dx, dy) = ((&b.x - &a.x).cmp(&zero), (&b.y - &a.y).cmp(&zero));
        EdgeAt {
            index,
            from: a.clone(),
            to: b.clone(),
            value: edge_function(a, b, p),
            side: Side::of(dx, dy),
            inclusive: rule.is_inclusive(dx, dy),
            distance2: segment_distance2(p, a, b),
        }
    };
    let edges = [edge(0), edge(1), edge(2)];
    let inside = edges
        .iter()
        .all(|e| e.value.is_positive() || (e.value.is_zero() && e.inclusive));
    Some(TriangleAt { edges, inside })
}

/// Whether triangle `t` covers sample `p` under `rule`: [`triangle_at`]'s `inside`
/// without its evidence (no distances, no copies of the vertices), for the searches that
/// ask it many times (`false` for a zero-area triangle, as there).
///
/// Where the four points are dyadic (power-of-two denominators up to `2^DYADIC_BITS`) and
/// lie within `2^DYADIC_LIMIT_BITS` once scaled to integers, the same decision is taken in
/// i128 (each edge function a difference of two products below `2^122`: exact); beyond,
/// in big rationals. The two agree everywhere (`tests/oracle.rs`, at both bounds).
pub fn triangle_covers(t: &Triangle, p: &Point, rule: AnyTieRule) -> bool {
    if let Some(covered) = covers_dyadic(t, p, rule) {
        return covered;
    }
    let Some(t) = oriented(t) else { return false };
    let zero = BigRational::zero();
    (0..3).all(|i| {
        let (a, b) = (&t.v[i], &t.v[(i + 1) % 3]);
        let e = edge_function(a, b, p);
        e.is_positive() || (e.is_zero() && rule.is_inclusive((&b.x - &a.x).cmp(&zero), (&b.y - &a.y).cmp(&zero)))
    })
}

/// The largest power-of-two denominator the i128 path of [`triangle_covers`] takes.
pub const DYADIC_BITS: u32 = 32;
/// Scaled coordinates of [`triangle_covers`]'s i128 path lie below `2^DYADIC_LIMIT_BITS`
/// in magnitude: differences below `2^61`, products below `2^122`, their difference below
/// `2^123`.
pub const DYADIC_LIMIT_BITS: u32 = 60;

/// [`triangle_covers`] in i128, or `None` when a coordinate is not dyadic within
/// [`DYADIC_BITS`] or its scaled value reaches `2^DYADIC_LIMIT_BITS`.
fn covers_dyadic(t: &Triangle, p: &Point, rule: AnyTieRule) -> Option<bool> {
    let coordinates = [
        &t.v[0].x, &t.v[0].y, &t.v[1].x, &t.v[1].y, &t.v[2].x, &t.v[2].y, &p.x, &p.y,
    ];
    // Each denominator's exponent (a power of two, or give up).
    let mut exponents = [0u32; 8];
    for (e, v) in exponents.iter_mut().zip(coordinates) {
        let d = v.denom();
        let bits = u32::try_from(d.bits()).ok()?;
        if bits == 0 || bits - 1 > DYADIC_BITS || d.trailing_zeros() != Some(u64::from(bits - 1)) {
            return None;
        }
        *e = bits - 1;
    }
    let shift = exponents.iter().copied().max().unwrap_or(0);
    let mut scaled = [0i128; 8];
    for ((out, v), e) in scaled.iter_mut().zip(coordinates).zip(exponents) {
        let n = num_traits::ToPrimitive::to_i128(v.numer())?;
        let s = n.checked_mul(1i128 << (shift - e))?;
        if s.unsigned_abs() >= 1u128 << DYADIC_LIMIT_BITS {
            return None;
        }
        *out = s;
    }
    let [ax, ay, bx, by, cx, cy, px, py] = scaled;
    let e = |(ax, ay): (i128, i128), (bx, by): (i128, i128), (px, py): (i128, i128)| {
        (px - ax) * (by - ay) - (py - ay) * (bx - ax)
    };
    let (a, mut b, mut c) = ((ax, ay), (bx, by), (cx, cy));
    let area = e(a, b, c);
    if area == 0 {
        return Some(false);
    }
    if area < 0 {
        std::mem::swap(&mut b, &mut c);
    }
    let sample = (px, py);
    Some([(a, b), (b, c), (c, a)].into_iter().all(|(from, to)| {
        let v = e(from, to, sample);
        v > 0 || (v == 0 && rule.is_inclusive((to.0 - from.0).cmp(&0), (to.1 - from.1).cmp(&0)))
    }))
}

impl TriangleAt {
    /// The edges the sample lies on (`E == 0`).
    pub fn zero_edges(&self) -> impl Iterator<Item = &EdgeAt> + '_ {
        self.edges.iter().filter(|e| e.value.is_zero())
    }

    /// The squared distance to the nearest edge.
    pub fn distance2(&self) -> BigRational {
        self.edges
            .iter()
            .map(|e| e.distance2.clone())
            .min()
            .expect("three edges")
    }
}

impl fmt::Display for TriangleAt {
    /// `edge 0 (a -> b, left): E=v (inclusive); ... -> inside`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, e) in self.edges.iter().enumerate() {
            if k > 0 {
                f.write_str("; ")?;
            }
            write!(
                f,
                "edge {} ({} -> {}, {}): E={} ({})",
                e.index,
                pair_text(&e.from.x, &e.from.y),
                pair_text(&e.to.x, &e.to.y),
                e.side.name(),
                exact_text(&e.value),
                if e.inclusive { "inclusive" } else { "exclusive" }
            )?;
        }
        f.write_str(if self.inside { " -> inside" } else { " -> outside" })
    }
}

/// The squared distance from `p` to the segment `a b`, exactly: to the nearer end when
/// `p` projects outside it, else `E^2 / |b - a|^2`.
pub fn segment_distance2(p: &Point, a: &Point, b: &Point) -> BigRational {
    let (dx, dy) = (&b.x - &a.x, &b.y - &a.y);
    let len2 = &dx * &dx + &dy * &dy;
    let to = |q: &Point| {
        let (ux, uy) = (&p.x - &q.x, &p.y - &q.y);
        &ux * &ux + &uy * &uy
    };
    if len2.is_zero() {
        return to(a);
    }
    let along = (&p.x - &a.x) * &dx + (&p.y - &a.y) * &dy;
    if !along.is_positive() {
        to(a)
    } else if along >= len2 {
        to(b)
    } else {
        let e = edge_function(a, b, p);
        &e * &e / len2
    }
}

/// Why the exact model puts pixel `(x, y)` inside or outside `tri`: the sample, each
/// edge's exact value and inclusive flag (from [`triangle_at`]), and the verdict.
///
/// ```
/// use rasterproof::check::explain_sample;
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::geom::{Point, Triangle};
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
/// let target = Target::new(4, 4, Convention::default()).unwrap();
/// let why = explain_sample(&t, 1, 2, &target);
/// assert!(why.contains("E=0 (exclusive)"), "{why}");
/// assert!(why.ends_with("-> outside"), "{why}");
/// ```
pub fn explain_sample(tri: &Triangle, x: u32, y: u32, target: &Target) -> String {
    let p = sample_exact(x, y, target);
    let mut s = format!("sample {p}");
    let Some(at) = triangle_at(tri, &p, target.convention.tie_rule.into()) else {
        s.push_str(": zero-area triangle -> outside");
        return s;
    };
    for e in &at.edges {
        let flag = if e.inclusive { "inclusive" } else { "exclusive" };
        let _ = write!(s, "; edge {}: E={} ({flag})", e.index, exact_text(&e.value));
    }
    s.push_str(if at.inside { " -> inside" } else { " -> outside" });
    s
}

#[cfg(test)]
mod tests {
    /// The verdict alone equals the evidence's, on every sample of a small grid (pixel
    /// corners, centres and quarter points, so many on an edge) for triangles of both
    /// windings, a zero-area one and every tie rule.
    #[test]
    fn the_verdict_alone_is_the_evidences_verdict() {
        use crate::convention::AnyTieRule;
        let q = |n: i64| BigRational::new(n.into(), 4.into());
        let tris = [
            [(0, 0), (16, 0), (0, 16)],
            [(0, 0), (0, 16), (16, 0)],
            [(2, 1), (14, 9), (5, 15)],
            [(0, 0), (8, 8), (16, 16)],
        ];
        for v in tris {
            let [a, b, c] = v.map(|(x, y)| Point::new(q(x), q(y)));
            let t = Triangle::new(a, b, c);
            for rule in AnyTieRule::ALL {
                for (x, y) in (0..=16).flat_map(|y| (0..=16).map(move |x| (x, y))) {
                    let p = Point::new(q(x), q(y));
                    let want = triangle_at(&t, &p, rule).is_some_and(|at| at.inside);
                    assert_eq!(triangle_covers(&t, &p, rule), want, "{v:?} {rule:?} at ({x}, {y})/4");
                }
            }
        }
    }

    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn sides_and_verdicts_by_hand() {
        // (0,0) (0,4) (4,0) oriented: v0 (0,0) -> v1 (0,4) runs down: the left edge;
        // (0,4) -> (4,0) runs up: right; (4,0) -> (0,0) runs left: top.
        let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(0, 4), Point::from_ints(4, 0));
        let at = triangle_at(&t, &Point::new(q(0, 1), q(1, 2)), AnyTieRule::TopLeft).unwrap();
        let sides: Vec<&str> = at.edges.iter().map(|e| e.side.name()).collect();
        assert_eq!(sides, ["left", "right", "top"]);
        // (0, 1/2) lies on the left edge: inside under top-left, outside under top-right.
        assert!(at.inside);
        assert_eq!(at.zero_edges().map(|e| e.index).collect::<Vec<_>>(), [0]);
        assert!(at.to_string().ends_with("-> inside"), "{at}");
        let right = triangle_at(&t, &Point::new(q(0, 1), q(1, 2)), AnyTieRule::TopRight).unwrap();
        assert!(!right.inside);
        assert_eq!(at.distance2(), q(0, 1));
        assert!(triangle_at(
            &Triangle::new(Point::from_ints(0, 0), Point::from_ints(1, 1), Point::from_ints(2, 2)),
            &Point::from_ints(1, 1),
            AnyTieRule::AllInclusive
        )
        .is_none());
    }
}
