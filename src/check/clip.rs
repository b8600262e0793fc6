//! Invariants of clipping, checked exactly: outputs inside the window, Cohen-Sutherland's
//! kept part equal to the part of the segment inside the window (an independent
//! parametric computation of the t-interval), and `raster(clip(P, W)) == raster(P) ∩
//! raster(W)`.

use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use super::{differing_pixels, Violation};
use crate::clip::{Rect, Window};
use crate::convention::Target;
use crate::coverage::Coverage;
use crate::fill::polygon::rasterize_exact;
use crate::geom::{FillRule, Point, Polygon};
use crate::num::exact::exact_text;

/// Every point satisfies every half-plane of `window` (boundary included), exactly.
pub fn check_inside(points: &[Point], window: &Window) -> Result<(), Violation> {
    let planes = window.half_planes();
    for (k, p) in points.iter().enumerate() {
        for (i, h) in planes.iter().enumerate() {
            let v = h.value(p);
            if v.is_negative() {
                return Err(Violation::new(
                    "clip inside",
                    format!(
                        "vertex {k} {} is outside window edge {i}: a x + b y + c = {}",
                        p,
                        exact_text(&v)
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// The parameter interval `[t0, t1]` of `a + t (b - a)`, `0 <= t <= 1`, inside `r`; `None`
/// when empty. Written independently of Cohen-Sutherland: each side is one linear
/// inequality in `t` (Liang-Barsky's reading).
pub fn inside_interval(a: &Point, b: &Point, r: &Rect) -> Option<(BigRational, BigRational)> {
    let (mut t0, mut t1) = (BigRational::zero(), BigRational::one());
    let d = [&b.x - &a.x, &b.y - &a.y];
    let start = [&a.x, &a.y];
    for (axis, lo, hi) in [(0, &r.xmin, &r.xmax), (1, &r.ymin, &r.ymax)] {
        // lo <= start + t d <= hi
        if d[axis].is_zero() {
            if start[axis] < lo || start[axis] > hi {
                return None;
            }
            continue;
        }
        let at_lo = (lo - start[axis]) / &d[axis];
        let at_hi = (hi - start[axis]) / &d[axis];
        let (enter, leave) = if d[axis].is_positive() {
            (at_lo, at_hi)
        } else {
            (at_hi, at_lo)
        };
        t0 = t0.max(enter);
        t1 = t1.min(leave);
    }
    (t0 <= t1).then_some((t0, t1))
}

/// Cohen-Sutherland's `result` for `a -> b` is exactly the part inside `r`: `None`
/// exactly when nothing is inside, otherwise the endpoints at the interval's ends, in
/// the segment's direction (so both lie on the original segment).
pub fn check_segment_clip(a: &Point, b: &Point, r: &Rect, result: Option<&(Point, Point)>) -> Result<(), Violation> {
    let at = |t: &BigRational| Point::new(&a.x + t * (&b.x - &a.x), &a.y + t * (&b.y - &a.y));
    let expected = inside_interval(a, b, r).map(|(t0, t1)| (at(&t0), at(&t1)));
    if expected.as_ref() == result {
        return Ok(());
    }
    let fmt = |s: Option<&(Point, Point)>| s.map_or("nothing".to_string(), |(p, q)| format!("{} -> {}", p, q));
    Err(Violation::new(
        "segment clip",
        format!(
            "{} -> {}: kept {}, but the part inside is {}",
            a,
            b,
            fmt(result),
            fmt(expected.as_ref())
        ),
    ))
}

/// `clipped` (the polygon `poly` clipped against `window`) covers, by the exact oracle,
/// exactly the samples that `poly` covers and the window (filled as a polygon, so its
/// boundary samples follow the tie rule) covers.
pub fn check_clip_raster(poly: &Polygon, clipped: &Polygon, window: &Window, target: &Target) -> Result<(), Violation> {
    let render = |p: &Polygon| {
        let mut c = Coverage::new(target.width, target.height);
        rasterize_exact(p, 0, target, &mut c);
        c
    };
    let (whole, inside, cut) = (
        render(poly),
        render(&Polygon::new(window.outline(), FillRule::NonZero)),
        render(clipped),
    );
    let mut expected = Coverage::new(target.width, target.height);
    for (x, y, _) in whole.iter() {
        if !inside.owners(x, y).is_empty() {
            crate::coverage::CoverageSink::cover(&mut expected, x, y, 0);
        }
    }
    let d = differing_pixels(&expected, &cut);
    match d.first() {
        None => Ok(()),
        Some(first) => Err(Violation::new(
            "clip raster",
            format!(
                "{} pixels differ; first ({}, {}): raster(P) ∩ raster(W) {:?}, raster(clip(P, W)) {:?}",
                d.len(),
                first.x,
                first.y,
                first.reference,
                first.candidate
            ),
        )),
    }
}
