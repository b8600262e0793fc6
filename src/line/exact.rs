//! Exact references for lines, over `BigRational`:
//!
//! - the ideal line: at every step of the major axis, the exact minor coordinate of the
//!   segment between the two pixel centres, and the pixel(s) within 1/2 of it (two at an
//!   exact tie);
//! - a plain reading of the diamond-exit rule: per pixel, does the segment meet the
//!   pixel's diamond test area, and does it leave it.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};

use super::{cover_if_on_canvas, Axes, BresenhamTie};
use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::geom::Point;
use crate::raster::{sample_coordinate_exact, saturating_index, PixelRange};

/// One step of the ideal line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct IdealStep {
    /// The major-axis coordinate of this step.
    pub major: i64,
    /// The exact minor coordinate of the ideal line there.
    pub minor: BigRational,
    /// The minor coordinates within 1/2 of it: one, or two at an exact tie (ascending).
    pub candidates: Vec<i64>,
}

impl IdealStep {
    /// The pixel of this step under `tie`: the only candidate, or at an exact tie the one
    /// nearer the start on the minor axis (`Stay`) or the farther one (`Step`);
    /// `minor_sign` is the direction of travel on the minor axis.
    pub fn pick(&self, minor_sign: i64, tie: BresenhamTie) -> i64 {
        let (lo, hi) = (self.candidates[0], self.candidates[self.candidates.len() - 1]);
        let (nearer, farther) = if minor_sign >= 0 { (lo, hi) } else { (hi, lo) };
        match tie {
            BresenhamTie::Stay => nearer,
            BresenhamTie::Step => farther,
        }
    }
}

/// The ideal line `from -> to` between pixel centres, step by step.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct IdealLine {
    /// The axes of the walk.
    pub axes: Axes,
    /// Every step, from `from` to `to`.
    pub steps: Vec<IdealStep>,
}

fn q(n: i64) -> BigRational {
    BigRational::from_integer(BigInt::from(n))
}

/// The ideal line's steps whose index k (0 = `from`) lies in `ks`.
fn steps_in(from: [i64; 2], to: [i64; 2], ks: std::ops::RangeInclusive<i64>) -> IdealLine {
    let axes = Axes::of(from, to);
    let (major0, minor0) = axes.split(from);
    let (_, minor1) = axes.split(to);
    let half = BigRational::new(BigInt::from(1), BigInt::from(2));
    let steps = ks
        .map(|k| {
            // minor(k) = minor0 + k * (minor1 - minor0) / major_len
            let minor = if axes.major_len == 0 {
                q(minor0)
            } else {
                q(minor0) + q(k) * q(minor1 - minor0) / q(axes.major_len)
            };
            let below = (&minor - &half).ceil().to_integer(); // lowest pixel within 1/2
            let above = (&minor + &half).floor().to_integer(); // highest pixel within 1/2
            let candidates = num_iter(below, above);
            IdealStep {
                major: major0 + k * axes.major_sign,
                minor,
                candidates,
            }
        })
        .collect();
    IdealLine { axes, steps }
}

fn num_iter(lo: BigInt, hi: BigInt) -> Vec<i64> {
    let (lo, hi) = (
        lo.to_i64().expect("line coordinates fit i64"),
        hi.to_i64().expect("fit"),
    );
    (lo..=hi).collect()
}

/// Every step of the ideal line from pixel `from` to pixel `to`.
///
/// ```
/// use rasterproof::line::exact::ideal;
/// // (0,4) -> (4,2): y = 4 - x/2, ties at x = 1 (3.5) and x = 3 (2.5).
/// let line = ideal([0, 4], [4, 2]);
/// let c: Vec<Vec<i64>> = line.steps.iter().map(|s| s.candidates.clone()).collect();
/// assert_eq!(c, vec![vec![4], vec![3, 4], vec![3], vec![2, 3], vec![2]]);
/// ```
pub fn ideal(from: [i64; 2], to: [i64; 2]) -> IdealLine {
    let len = Axes::of(from, to).major_len;
    steps_in(from, to, 0..=len)
}

/// The reference pixels of a Bresenham line: at each step the one candidate, or at a tie
/// the one the convention picks (`Stay`: the candidate nearer the start on the minor
/// axis; `Step`: the farther one).
pub fn resolve(line: &IdealLine, tie: BresenhamTie) -> Vec<[i64; 2]> {
    line.steps
        .iter()
        .map(|s| line.axes.join(s.major, s.pick(line.axes.minor_sign, tie)))
        .collect()
}

/// Draws the reference pixels of a Bresenham line, computing only the steps whose major
/// coordinate lies on the canvas.
pub fn rasterize_bresenham<S: CoverageSink + ?Sized>(
    from: [i64; 2],
    to: [i64; 2],
    tie: BresenhamTie,
    id: u32,
    target: &Target,
    sink: &mut S,
) {
    let axes = Axes::of(from, to);
    let (major0, _) = axes.split(from);
    let side = i64::from(if axes.x_major { target.width } else { target.height });
    // major(k) = major0 + k * sign must lie in [0, side)
    let (lo, hi) = match axes.major_sign {
        0 => (0, 0),
        1 => (-major0, side - 1 - major0),
        _ => (major0 - (side - 1), major0),
    };
    let (lo, hi) = (lo.max(0), hi.min(axes.major_len));
    if lo > hi {
        return;
    }
    for p in resolve(&steps_in(from, to, lo..=hi), tie) {
        cover_if_on_canvas(p, id, target, sink);
    }
}

/// Membership of the diamond test area of a pixel, for a point at `(u, v)` from the
/// pixel's sample (y down) and diamond radius `r` (1/2 pixel): the open diamond
/// `|u| + |v| < r`, plus, on its boundary, the lower-left and lower-right edges and the
/// bottom corner; the right corner too for y-major lines (D3D11 §3.4.3). The top corner,
/// left corner and upper edges are out.
///
/// Scale-free: multiplying `u`, `v` and `r` by the same positive number changes nothing,
/// which is what lets the integer model work in homogeneous coordinates.
pub fn diamond_contains(u: &BigRational, v: &BigRational, r: &BigRational, x_major: bool) -> bool {
    let s = u.abs() + v.abs();
    if s < *r {
        return true;
    }
    if s > *r {
        return false;
    }
    if v.is_positive() {
        true // lower edges and the bottom corner
    } else if v.is_negative() {
        false // upper edges and the top corner
    } else {
        // v == 0: the left (u < 0) or right (u > 0) corner
        u.is_positive() && !x_major
    }
}

/// The diamond-exit rule for pixel `(i, j)`, read plainly in exact arithmetic: the segment
/// `a -> b` meets the pixel's diamond test area, and `b` is not in it (so the segment
/// leaves it: the area is convex, the segment enters it at most once).
///
/// "Meets" is decided on the part of the segment inside the closed diamond, `[p(t0),
/// p(t1)]` (clipped against the four closed half-planes `±u ± v <= r`): it meets the
/// test area when `p(t0)`, `p(t1)` or their midpoint is in it. (A chord of a convex
/// polygon has its relative interior inside the polygon unless it runs along one edge,
/// where the midpoint carries the edge's status and the ends carry the corners'.)
pub fn diamond_exits(a: &Point, b: &Point, i: i64, j: i64, target: &Target) -> bool {
    let (cx, cy) = (sample_coordinate_exact(i, target), sample_coordinate_exact(j, target));
    let r = BigRational::new(BigInt::from(1), BigInt::from(2));
    let (dx, dy) = (&b.x - &a.x, &b.y - &a.y);
    let x_major = dx.abs() >= dy.abs();
    let (ua, va) = (&a.x - &cx, &a.y - &cy);
    let inside = |u: &BigRational, v: &BigRational| diamond_contains(u, v, &r, x_major);
    if inside(&(&b.x - &cx), &(&b.y - &cy)) {
        return false; // the end lies in the test area: it never leaves
    }
    let (mut t0, mut t1) = (BigRational::zero(), q(1));
    for (su, sv) in [(1, 1), (1, -1), (-1, 1), (-1, -1)] {
        // su*u(t) + sv*v(t) <= r, with u(t) = ua + t dx, v(t) = va + t dy
        let g0 = q(su) * &ua + q(sv) * &va;
        let g1 = q(su) * &dx + q(sv) * &dy;
        if g1.is_zero() {
            if g0 > r {
                return false;
            }
        } else if g1.is_positive() {
            t1 = t1.min((&r - &g0) / &g1);
        } else {
            t0 = t0.max((&r - &g0) / &g1);
        }
    }
    if t0 > t1 {
        return false;
    }
    let mid = (&t0 + &t1) / q(2);
    [t0, t1, mid].iter().any(|t| inside(&(&ua + t * &dx), &(&va + t * &dy)))
}

/// Draws a diamond-exit line with the plain exact reading: every pixel of the segment's
/// bounding box (grown by one) on the canvas is tested.
pub fn rasterize_diamond<S: CoverageSink + ?Sized>(a: &Point, b: &Point, id: u32, target: &Target, sink: &mut S) {
    let lo = |u: &BigRational, v: &BigRational| saturating_index(u.min(v).floor().to_integer()).saturating_sub(1);
    let hi = |u: &BigRational, v: &BigRational| saturating_index(u.max(v).ceil().to_integer()).saturating_add(1);
    let Some(range) = PixelRange::clamped(
        [lo(&a.x, &b.x), lo(&a.y, &b.y)],
        [hi(&a.x, &b.x), hi(&a.y, &b.y)],
        target.width,
        target.height,
    ) else {
        return;
    };
    for j in range.y0..=range.y1 {
        for i in range.x0..=range.x1 {
            if diamond_exits(a, b, i64::from(i), i64::from(j), target) {
                sink.cover(i, j, id);
            }
        }
    }
}
