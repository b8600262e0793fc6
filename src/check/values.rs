//! Invariants of interpolated values: what every correct interpolator's answer satisfies,
//! whatever its arithmetic, checked on the exact definition ([`crate::interp::values`]) or
//! on any model that gives a value at a point.
//!
//! - **hull**: at a point inside a triangle (window-space barycentrics all `>= 0`) whose
//!   vertices have `w > 0`, every channel lies between the least and the greatest of the
//!   vertices' values: the value is a convex combination (the perspective-correct weights
//!   `mu_i / w_i / sum mu_j / w_j` are non-negative too);
//! - **rotation**: the value does not depend on which vertex is listed first (`smooth` and
//!   `noperspective`; a `flat` value moves with its provoking vertex by definition);
//! - **translation**: moving the triangle and the point by the same window offset leaves
//!   the value;
//! - **shared edge**: two triangles that share an edge, with the same `w` and values at its
//!   two vertices, give the same value at every point of it;
//! - **flat**: a `flat` value is exactly one vertex's, the provoking vertex's.
//!
//! Barycentrics summing to 1 is [`crate::check::check_barycentric_exact`]'s.

use std::ops::Range;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::Violation;
use crate::geom::Point;
use crate::interp::values::{Interpolation, ProvokingVertex, ValueTriangle};
use crate::num::exact::{exact_text, pair_text};

/// The values at `p`, or `None` where the definition gives none (a degenerate triangle, a
/// horizon).
fn value_at(
    t: &ValueTriangle,
    interpolation: Interpolation,
    provoking: ProvokingVertex,
    channels: Range<usize>,
    p: &Point,
) -> Option<Vec<BigRational>> {
    t.value(interpolation, provoking, channels, p).ok()
}

fn texts(v: &[BigRational]) -> String {
    v.iter().map(exact_text).collect::<Vec<_>>().join(", ")
}

/// The hull invariant at `p` (module docs); a point outside the triangle, a vertex with
/// `w <= 0` or no value pass.
///
/// ```
/// use rasterproof::check::check_values_hull;
/// use rasterproof::geom::Point;
/// use rasterproof::interp::values::{Interpolation, ValueTriangle};
/// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
/// let (a, b, c) = (Point::from_ints(0, 0), Point::from_ints(8, 0), Point::from_ints(0, 8));
/// let t = ValueTriangle::window([&a, &b, &c], [&q(1), &q(4), &q(2)], [vec![q(0)], vec![q(10)], vec![q(5)]]);
/// assert!(check_values_hull(&t, Interpolation::Smooth, 0..1, &Point::from_ints(2, 3)).is_ok());
/// ```
///
/// # Errors
/// A channel outside its vertices' range, with the exact value and range.
pub fn check_values_hull(
    t: &ValueTriangle,
    interpolation: Interpolation,
    channels: Range<usize>,
    p: &Point,
) -> Result<(), Violation> {
    if t.h.iter().any(|h| !h[2].is_positive()) {
        return Ok(());
    }
    let Ok(b) = t.barycentrics(p) else {
        return Ok(());
    };
    // Window barycentrics mu_i = b_i w_i: inside when all are >= 0 (w > 0, so b_i's sign).
    if b.iter().any(Signed::is_negative) {
        return Ok(());
    }
    let Some(values) = value_at(t, interpolation, ProvokingVertex::First, channels.clone(), p) else {
        return Ok(());
    };
    for (c, v) in channels.zip(&values) {
        let vertex = t.values.iter().map(|vs| &vs[c]);
        let lo = vertex.clone().min().expect("three");
        let hi = vertex.max().expect("three");
        if v < lo || v > hi {
            return Err(Violation::new(
                "values-hull",
                format!(
                    "channel {c} at {} is {}, outside its vertices' range [{}, {}]",
                    pair_text(&p.x, &p.y),
                    exact_text(v),
                    exact_text(lo),
                    exact_text(hi)
                ),
            ));
        }
    }
    Ok(())
}

/// `t` with its vertices listed from vertex `k` on.
fn rotated(t: &ValueTriangle, k: usize) -> ValueTriangle {
    ValueTriangle {
        h: [0, 1, 2].map(|i| t.h[(i + k) % 3].clone()),
        values: [0, 1, 2].map(|i| t.values[(i + k) % 3].clone()),
    }
}

/// The rotation invariant at `p` (module docs; `flat` passes).
///
/// # Errors
/// A rotation that changes a value, with both.
pub fn check_values_rotation(
    t: &ValueTriangle,
    interpolation: Interpolation,
    channels: Range<usize>,
    p: &Point,
) -> Result<(), Violation> {
    if interpolation == Interpolation::Flat {
        return Ok(());
    }
    let first = value_at(t, interpolation, ProvokingVertex::First, channels.clone(), p);
    for k in 1..3 {
        let other = value_at(
            &rotated(t, k),
            interpolation,
            ProvokingVertex::First,
            channels.clone(),
            p,
        );
        if other != first {
            return Err(Violation::new(
                "values-rotation",
                format!(
                    "at {} the value is [{}] as listed and [{}] listed from vertex {k}",
                    pair_text(&p.x, &p.y),
                    first.as_deref().map_or("none".to_string(), texts),
                    other.as_deref().map_or("none".to_string(), texts)
                ),
            ));
        }
    }
    Ok(())
}

/// The translation invariant at `p` for the window offset `(dx, dy)` (module docs).
///
/// # Errors
/// A value that moves, with both.
pub fn check_values_translation(
    t: &ValueTriangle,
    interpolation: Interpolation,
    provoking: ProvokingVertex,
    channels: Range<usize>,
    p: &Point,
    (dx, dy): (&BigRational, &BigRational),
) -> Result<(), Violation> {
    // (x w, y w, w) of the window point moved by (dx, dy): (x w + dx w, y w + dy w, w).
    let moved = ValueTriangle {
        h: t.h.clone().map(|[xw, yw, w]| [xw + dx * &w, yw + dy * &w, w]),
        values: t.values.clone(),
    };
    let there = Point::new(&p.x + dx, &p.y + dy);
    let here = value_at(t, interpolation, provoking, channels.clone(), p);
    let moved_value = value_at(&moved, interpolation, provoking, channels, &there);
    if here != moved_value {
        return Err(Violation::new(
            "values-translation",
            format!(
                "at {} the value is [{}]; moved by {} it is [{}]",
                pair_text(&p.x, &p.y),
                here.as_deref().map_or("none".to_string(), texts),
                pair_text(dx, dy),
                moved_value.as_deref().map_or("none".to_string(), texts)
            ),
        ));
    }
    Ok(())
}

/// The shared-edge invariant: `a`'s vertices `ea` and `b`'s vertices `eb` are the same
/// two vertices (homogeneous position and values); at the point a fraction `s` of the way
/// along the edge in window space both triangles give the same value (a degenerate
/// triangle, which covers nothing, passes).
///
/// # Errors
/// The edges are not shared, or the values differ on them.
pub fn check_values_shared_edge(
    a: &ValueTriangle,
    b: &ValueTriangle,
    (ea, eb): ((usize, usize), (usize, usize)),
    interpolation: Interpolation,
    channels: Range<usize>,
    s: &BigRational,
) -> Result<(), Violation> {
    let same = |i: usize, j: usize| a.h[i] == b.h[j] && a.values[i] == b.values[j];
    if !(same(ea.0, eb.0) && same(ea.1, eb.1)) {
        return Err(Violation::new(
            "values-shared-edge",
            "the two triangles do not share that edge",
        ));
    }
    if interpolation == Interpolation::Flat || a.h[ea.0][2].is_zero() || a.h[ea.1][2].is_zero() {
        return Ok(());
    }
    let window = |h: &[BigRational; 3]| Point::new(&h[0] / &h[2], &h[1] / &h[2]);
    let (p0, p1) = (window(&a.h[ea.0]), window(&a.h[ea.1]));
    let one = BigRational::from_integer(1.into());
    let p = Point::new(&p0.x * (&one - s) + &p1.x * s, &p0.y * (&one - s) + &p1.y * s);
    let va = value_at(a, interpolation, ProvokingVertex::First, channels.clone(), &p);
    let vb = value_at(b, interpolation, ProvokingVertex::First, channels, &p);
    // A degenerate triangle covers nothing: no value of its to agree with.
    if va.is_none() || vb.is_none() {
        return Ok(());
    }
    if va != vb {
        return Err(Violation::new(
            "values-shared-edge",
            format!(
                "at {} on the shared edge one triangle gives [{}], the other [{}]",
                pair_text(&p.x, &p.y),
                va.as_deref().map_or("none".to_string(), texts),
                vb.as_deref().map_or("none".to_string(), texts)
            ),
        ));
    }
    Ok(())
}

/// The flat invariant at `p`: the `flat` value is exactly the provoking vertex's.
///
/// # Errors
/// Another value, with both.
pub fn check_values_flat(
    t: &ValueTriangle,
    provoking: ProvokingVertex,
    channels: Range<usize>,
    p: &Point,
) -> Result<(), Violation> {
    let v = value_at(t, Interpolation::Flat, provoking, channels.clone(), p);
    let expected = t.values[provoking.vertex(3)][channels].to_vec();
    if v.as_ref() != Some(&expected) {
        return Err(Violation::new(
            "values-flat",
            format!(
                "at {} the flat value is [{}], not the {} vertex's [{}]",
                pair_text(&p.x, &p.y),
                v.as_deref().map_or("none".to_string(), texts),
                provoking.name(),
                texts(&expected)
            ),
        ));
    }
    Ok(())
}
