//! The planned exact engine for diamond-exit lines (the Direct3D 11.3 functional
//! specification, §3.4.3, aliased line rasterization; Vulkan's and GL's diamond-exit
//! lines): the decisions of [`rasterize_diamond`](super::exact::rasterize_diamond), the rule read
//! plainly in rationals, for any rational endpoints, computed in the narrowest arithmetic
//! that provably holds every value the test reaches ([`crate::num::plan`]).
//!
//! **LineSetup**, once per segment, in exact integers. The scale `L` is the least common
//! multiple of the denominators of the endpoints, of the pixel centre `c` and of the
//! diamond's radius `1/2`, so the radius is the integer `r = L/2`. The candidate pixels
//! are those a drawn pixel can be: if the segment meets pixel `(i, j)`'s closed diamond at
//! a point `p`, the sample `S` is within `r` of `p` on the major axis, and, as the line's
//! slope is at most 1 in magnitude, within `r` of the line on the minor axis at `S`'s
//! major coordinate. So per major index `k` (sample within `r` of the segment's major
//! extent) the candidates are the minor indices `j0(k)` and `j0(k) + 1`, with
//! `j0(k) = floor((y(k) - c - r) / L)` and `y(k)` the line's minor coordinate at the
//! sample's major coordinate; the major indices are cut at setup to those where one of
//! the two is on the canvas. `j0` is an exact integer DDA over `k` in the form of
//! [`crate::num::dda::CeilDda`]: `floor(N(k) / D)` with `D = L |dmaj'|`,
//! `dmaj' = dmaj / g`, `g = gcd(dmaj, dmin)`, `N` stepped by `L dmin'`; its quotient is a
//! pixel index (its step is -1, 0 or 1) and stays in `i64`, its remainder is planned.
//! Coordinates are taken relative to the first candidate's sample, so a segment far from
//! the origin costs what it costs at the origin.
//!
//! **The test** per candidate, in homogeneous integers as [`super::diamond`] does it on
//! snapped endpoints: with `(ua, va) = a - S`, `(ub, vb) = b - S` and `(dx, dy) = b - a`,
//! a pixel is drawn when `b` is not in its test area and the part `[t0, t1]` of the
//! segment inside the closed diamond (clipped against `su u + sv v <= r`, parameters
//! `n / m` with `m = |su dx + sv dy|`) meets it. Two equivalences keep every product of
//! degree two:
//! - a candidate parameter below 0 for `t1`, or above 1 for `t0`, empties the chord at
//!   once, and one above 1 for `t1`, or below 0 for `t0`, changes nothing; so the
//!   parameters that are compared satisfy `0 <= n <= m`;
//! - the oracle's third point, the chord's midpoint, is in the open diamond unless the
//!   chord runs along one edge (a chord of a convex polygon with a point in its interior
//!   has its whole relative interior there); it runs along the edge of plane `(su, sv)`
//!   exactly when `su dx + sv dy = 0` and `su ua + sv va = r`, and then the midpoint has
//!   that edge's status: in for the two lower edges (`sv = +1`), out for the upper ones.
//!   So a chord of positive length is drawn unless it lies on an upper edge, where its
//!   ends decide, as they do for a single point.
//!
//! **The bound.** With `G = |dx| + |dy|` (at least every `m`), and `UA`, `VA`, `UB`, `VB`
//! the largest `|ua|`, `|va|`, `|ub|`, `|vb|` over the box of tested samples (the
//! candidates on the canvas), every value the walk and the test compute is at most one
//! of: an endpoint's or a sample's local coordinate; `G`; the DDA's divisor `D` (its
//! remainders stay in `(-D, D)`); `UB + VB` (`|ub| + |vb|`); `UA + VA + r`
//! (`su ua + sv va` and the parameter numerators `±(r - g0)`); `G^2` (the cross-products
//! `n0 m1` comparing two parameters, `0 <= n <= m <= G`); and, at a chord's end,
//! `(|dx| + r) G` and `(|dy| + r) G`: there the point `p(t)` is in the sample's closed
//! diamond, so `|ua| <= t |dx| + r`, the products `ua m`, `dx n <= |dx| G` and `r m` are
//! within it, and their sum `m u(t)` is at most `r m` in magnitude.
//! [`PlannedSegment::new`] computes the largest of them exactly and plans the width on
//! it. The terms bound the box, so the test need not reach the largest; the boundary
//! tests of `tests/planned_polygons_lines.rs` use segments where it reaches the largest,
//! `UA + VA + r`, exactly.

use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::geom::Point;
use crate::num::lane::{InWidth, Lane, LaneState, Planned};
use crate::num::plan::{ceil_div, floor_div, index, indices_above, scale_of, scaled, Bound, Plan, Width};

/// The four half-planes `su u + sv v <= r` of the diamond, in [`super::diamond`]'s order.
const PLANES: [(i8, i8); 4] = [(1, 1), (1, -1), (-1, 1), (-1, -1)];

/// What the test and the walk hold in the planned width (local coordinates, `L` units).
#[derive(Debug, Clone)]
struct Seg<T> {
    zero: T,
    /// `L`, one pixel.
    l: T,
    /// The diamond's radius `L / 2`.
    r: T,
    a: [T; 2],
    b: [T; 2],
    d: [T; 2],
    /// `|su dx + sv dy|` per plane of [`PLANES`].
    m: [T; 4],
    /// The DDA: remainder at the first step, divisor, remainder step.
    e0: T,
    dd: T,
    step_r: T,
    /// `floor(L dmin' / D) L`: the minor sample's step (`-L`, 0 or `L`) before a carry.
    step_minor: T,
}

impl<T: Lane> Seg<T> {
    fn from_big(s: &Seg<BigInt>) -> Seg<T> {
        let f = T::from_big;
        Seg {
            zero: f(&s.zero),
            l: f(&s.l),
            r: f(&s.r),
            a: s.a.each_ref().map(f),
            b: s.b.each_ref().map(f),
            d: s.d.each_ref().map(f),
            m: s.m.each_ref().map(f),
            e0: f(&s.e0),
            dd: f(&s.dd),
            step_r: f(&s.step_r),
            step_minor: f(&s.step_minor),
        }
    }
}

/// A segment's state in each width: its values.
#[derive(Debug, Clone)]
struct SegLanes;

impl LaneState for SegLanes {
    type In<T: Lane> = Seg<T>;
    fn convert<T: Lane>(exact: &Seg<BigInt>) -> Seg<T> {
        Seg::from_big(exact)
    }
}

/// The candidate walk of one segment, run in the planned width.
struct Draw<'a, S: ?Sized> {
    walk: &'a Walk,
    id: u32,
    sink: &'a mut S,
}

impl<S: CoverageSink + ?Sized> InWidth<SegLanes> for Draw<'_, S> {
    type Output = ();
    #[inline]
    fn run<T: Lane>(self, seg: &Seg<T>) {
        walk(self.walk, seg, self.id, self.sink);
    }
}

/// The walk, independent of the width.
#[derive(Debug, Clone, Copy)]
struct Walk {
    x_major: bool,
    /// The first candidate's global major and minor indices.
    k0: i64,
    j0: i64,
    /// Major steps after the first.
    steps: i64,
    /// `floor(L dmin' / D)`: -1, 0 or 1.
    step_q: i64,
    /// The canvas side on the minor axis.
    side_minor: i64,
    /// The sign of `su dx + sv dy` per plane.
    signs: [Sign; 4],
}

/// A diamond-exit segment set up for the planned engine: its walk, its plan and its values
/// in the planned width.
#[derive(Debug, Clone)]
pub struct PlannedSegment {
    walk: Walk,
    planned: Planned<SegLanes>,
}

/// The exact setup.
struct LineSetup {
    walk: Walk,
    scale: BigInt,
    seg: Seg<BigInt>,
    bound: Bound,
}

fn setup(a: &Point, b: &Point, target: &Target) -> Option<LineSetup> {
    if a == b {
        return None; // a point never leaves a diamond
    }
    let centre = target.convention.pixel_centre.offset();
    let half = BigRational::new(1.into(), 2.into());
    let l = scale_of([&a.x, &a.y, &b.x, &b.y, &centre, &half]);
    let (c, r) = (scaled(&centre, &l), scaled(&half, &l));
    let pa = [scaled(&a.x, &l), scaled(&a.y, &l)];
    let pb = [scaled(&b.x, &l), scaled(&b.y, &l)];
    let d = [&pb[0] - &pa[0], &pb[1] - &pa[1]];
    let x_major = d[0].abs() >= d[1].abs();
    let (maj, min) = if x_major { (0, 1) } else { (1, 0) };
    let (side_major, side_minor) = if x_major {
        (target.width, target.height)
    } else {
        (target.height, target.width)
    };
    let (side_major, side_minor) = (i64::from(side_major), i64::from(side_minor));
    // Major indices k whose sample k L + c is within r of the segment's major extent.
    let (lo, hi) = if d[maj].is_positive() {
        (&pa[maj], &pb[maj])
    } else {
        (&pb[maj], &pa[maj])
    };
    let k_first = ceil_div(&(lo - &r - &c), &l).max(BigInt::zero());
    let k_last = floor_div(&(hi + &r - &c), &l).min(BigInt::from(side_major - 1));
    if k_first > k_last {
        return None;
    }
    let (k_first, k_last) = (index(&k_first), index(&k_last));
    // j0(k) = floor(N(k) / D): N(k) = (an - c - r) dmaj' + (k L + c - am) dmin', D = L dmaj'.
    let g = d[maj].gcd(&d[min]);
    let (mut dmaj, mut dmin) = (&d[maj] / &g, &d[min] / &g);
    if dmaj.is_negative() {
        (dmaj, dmin) = (-dmaj, -dmin);
    }
    let dd = &l * &dmaj;
    let inc = &l * &dmin;
    let n_at = |k: i64| (&pa[min] - &c - &r) * &dmaj + (BigInt::from(k) * &l + &c - &pa[maj]) * &dmin;
    // Keep the k with j0(k) in -1..=side_minor - 1 (a candidate j0 or j0 + 1 on the canvas):
    // N(k) > -D - 1 and not N(k) > side_minor D - 1.
    let (low, high) = (-&dd - 1, BigInt::from(side_minor) * &dd - 1);
    let n_first = n_at(k_first);
    let (k0, k1) = match inc.sign() {
        Sign::Plus => {
            let (s_low, _) = indices_above(&n_first, &inc, k_first, k_last, &low);
            let (s_high, _) = indices_above(&n_first, &inc, k_first, k_last, &high);
            (s_low, s_high - 1)
        }
        Sign::Minus => {
            let (_, e_low) = indices_above(&n_first, &inc, k_first, k_last, &low);
            let (_, e_high) = indices_above(&n_first, &inc, k_first, k_last, &high);
            (e_high + 1, e_low)
        }
        Sign::NoSign => {
            if n_first > low && n_first <= high {
                (k_first, k_last)
            } else {
                return None;
            }
        }
    };
    if k0 > k1 {
        return None;
    }
    let n0 = n_at(k0);
    let j0 = floor_div(&n0, &dd);
    // The DDA runs ceil((N + 1) / D) = j0 + 1 (CeilDda's form): remainder in [0, D).
    let e0 = (&j0 + 1) * &dd - (&n0 + 1);
    let step_q = floor_div(&inc, &dd);
    let step_r = &inc - &step_q * &dd;
    let (j0, step_q) = (index(&j0), index(&step_q));
    // Local coordinates: relative to the first candidate's sample.
    let origin_major = BigInt::from(k0) * &l + &c;
    let origin_minor = BigInt::from(j0) * &l + &c;
    let origin = if x_major {
        [origin_major, origin_minor]
    } else {
        [origin_minor, origin_major]
    };
    let la = [&pa[0] - &origin[0], &pa[1] - &origin[1]];
    let lb = [&pb[0] - &origin[0], &pb[1] - &origin[1]];
    let steps = k1 - k0;
    let q_end = index(&floor_div(&n_at(k1), &dd)) - j0;
    let (q_min, q_max) = (q_end.min(0), q_end.max(0));
    let signs = PLANES.map(|(su, sv)| (BigInt::from(su) * &d[0] + BigInt::from(sv) * &d[1]).sign());
    let m = PLANES.map(|(su, sv)| (BigInt::from(su) * &d[0] + BigInt::from(sv) * &d[1]).abs());
    let walk = Walk {
        x_major,
        k0,
        j0,
        steps,
        step_q,
        side_minor,
        signs,
    };
    let bound = bound_of(&walk, &l, &r, &la, &lb, &d, &dd, [q_min, q_max]);
    let seg = Seg {
        zero: BigInt::zero(),
        step_minor: BigInt::from(step_q) * &l,
        l,
        r,
        a: la,
        b: lb,
        d,
        m,
        e0,
        dd,
        step_r,
    };
    Some(LineSetup {
        walk,
        scale: seg.l.clone(),
        seg,
        bound,
    })
}

/// The largest magnitude the walk and the test can reach (see the module docs).
#[allow(clippy::too_many_arguments)]
fn bound_of(
    walk: &Walk,
    l: &BigInt,
    r: &BigInt,
    a: &[BigInt; 2],
    b: &[BigInt; 2],
    d: &[BigInt; 2],
    dd: &BigInt,
    [q_min, q_max]: [i64; 2],
) -> Bound {
    // The tested samples' box, in local L units: major 0..=steps, minor the DDA's range
    // cut to the canvas.
    let n_lo = q_min.max(-walk.j0);
    let n_hi = (q_max + 1).min(walk.side_minor - 1 - walk.j0);
    let major = [BigInt::zero(), BigInt::from(walk.steps) * l];
    let minor = [BigInt::from(n_lo) * l, BigInt::from(n_hi) * l];
    let (xs, ys) = if walk.x_major { (major, minor) } else { (minor, major) };
    let far = |p: &BigInt, span: &[BigInt; 2]| (p - &span[0]).abs().max((p - &span[1]).abs());
    let (ua, va) = (far(&a[0], &xs), far(&a[1], &ys));
    let (ub, vb) = (far(&b[0], &xs), far(&b[1], &ys));
    let g = d[0].abs() + d[1].abs();
    let endpoint = a.iter().chain(b).map(Signed::abs).max().expect("four coordinates");
    let sample = [
        BigInt::from(walk.steps) * l,
        BigInt::from(q_min - 1).abs() * l,
        BigInt::from(q_max + 1).abs() * l,
    ]
    .into_iter()
    .max()
    .expect("three");
    // At a chord's end p(t) is in the sample's closed diamond, so |ua| <= t |dx| + r.
    let terms: [(BigInt, &str); 10] = [
        (endpoint, "an endpoint's local coordinate"),
        (sample, "a sample's local coordinate"),
        (g.clone(), "|dx| + |dy|"),
        (dd.clone(), "the DDA's divisor L |dmajor| / g"),
        (&ub + &vb, "|ub| + |vb| at a tested sample"),
        (&ua + &va + r, "|ua| + |va| + r at a tested sample"),
        (&g * &g, "a cross-product of two clip parameters, (|dx| + |dy|)^2"),
        ((d[0].abs() + r) * &g, "ua m at a chord's end, (|dx| + r) (|dx| + |dy|)"),
        ((d[1].abs() + r) * &g, "va m at a chord's end, (|dy| + r) (|dx| + |dy|)"),
        (l.clone(), "L"),
    ];
    let (value, what) = terms
        .into_iter()
        .reduce(|best, t| if t.0 > best.0 { t } else { best })
        .expect("ten terms");
    Bound {
        value,
        what: what.to_string(),
    }
}

impl PlannedSegment {
    /// Sets up the diamond-exit segment `a -> b` (exact endpoints, as written or snapped)
    /// for `target`, in the cheapest width its bound allows; `None` when it draws nothing
    /// (zero length, or no candidate pixel on the canvas).
    pub fn new(a: &Point, b: &Point, target: &Target) -> Option<PlannedSegment> {
        let s = setup(a, b, target)?;
        let planned = Planned::new(s.scale, s.bound, s.seg);
        Some(PlannedSegment { walk: s.walk, planned })
    }

    /// As [`PlannedSegment::new`] but in `width`: `Ok(None)` when it draws nothing,
    /// `Err(plan)` (the plan it would have) when `width` cannot hold its bound. For tests
    /// and benches that run every width.
    pub fn forced(a: &Point, b: &Point, target: &Target, width: Width) -> Result<Option<PlannedSegment>, Plan> {
        let Some(s) = setup(a, b, target) else {
            return Ok(None);
        };
        let planned = Planned::forced(s.scale, s.bound, s.seg, width)?;
        Ok(Some(PlannedSegment { walk: s.walk, planned }))
    }

    /// The plan: scale, bound and width.
    pub fn plan(&self) -> &Plan {
        self.planned.plan()
    }

    /// Draws every pixel the segment leaves the diamond of: equal, pixel for pixel, to
    /// [`rasterize_diamond`](super::exact::rasterize_diamond) on the same endpoints and target (the
    /// property tests of `tests/planned_polygons_lines.rs` are the proof).
    ///
    /// ```
    /// use rasterproof::convention::{Convention, Target};
    /// use rasterproof::coverage::Coverage;
    /// use rasterproof::geom::Point;
    /// use rasterproof::line::exact::rasterize_diamond;
    /// use rasterproof::line::planned::PlannedSegment;
    /// use rasterproof::num::plan::Width;
    /// let (a, b) = (Point::from_fractions(1, 3, 1, 2), Point::from_fractions(13, 2, 7, 2));
    /// let target = Target::new(8, 8, Convention::default()).unwrap();
    /// let planned = PlannedSegment::new(&a, &b, &target).unwrap();
    /// assert_eq!(planned.plan().scale, 6.into()); // lcm(3, 2)
    /// assert_eq!(planned.plan().width, Width::I32);
    /// let (mut p, mut q) = (Coverage::new(8, 8), Coverage::new(8, 8));
    /// planned.rasterize(0, &mut p);
    /// rasterize_diamond(&a, &b, 0, &target, &mut q);
    /// assert_eq!(p, q);
    /// assert_eq!(p.covered_pixels(), 6); // one per column 0..=5; the end's pixel is not left
    /// ```
    pub fn rasterize<S: CoverageSink + ?Sized>(&self, id: u32, sink: &mut S) {
        let walk = &self.walk;
        self.planned.run(Draw { walk, id, sink });
    }
}

/// Plans and draws the diamond-exit segment `a -> b` in one call (see [`PlannedSegment`]).
pub fn rasterize<S: CoverageSink + ?Sized>(a: &Point, b: &Point, id: u32, target: &Target, sink: &mut S) {
    if let Some(p) = PlannedSegment::new(a, b, target) {
        p.rasterize(id, sink);
    }
}

/// The walk over the candidates, generic over the planned width: per major step the
/// sample's major coordinate grows by `L`, the DDA gives `j0`, and the two candidates
/// `j0`, `j0 + 1` on the canvas are tested.
fn walk<T: Lane, S: CoverageSink + ?Sized>(w: &Walk, s: &Seg<T>, id: u32, sink: &mut S) {
    let mut major = s.zero.clone();
    let mut minor = s.zero.clone();
    let mut e = s.e0.clone();
    let mut q = 0i64;
    for k in 0..=w.steps {
        for dj in 0..2 {
            let j = w.j0 + q + dj;
            if j < 0 || j >= w.side_minor {
                continue;
            }
            let y = if dj == 0 { minor.clone() } else { minor.plus(&s.l) };
            let (sx, sy) = if w.x_major { (&major, &y) } else { (&y, &major) };
            if exits(w, s, sx, sy) {
                let (i, j) = if w.x_major { (w.k0 + k, j) } else { (j, w.k0 + k) };
                let on_canvas = |v: i64| u32::try_from(v).expect("a candidate on the canvas");
                sink.cover(on_canvas(i), on_canvas(j), id);
            }
        }
        if k < w.steps {
            major.add_to(&s.l);
            q += w.step_q;
            minor.add_to(&s.step_minor);
            e = e.minus(&s.step_r);
            if !e.non_negative() {
                e.add_to(&s.dd);
                q += 1;
                minor.add_to(&s.l);
            }
        }
    }
}

fn abs<T: Lane>(zero: &T, v: &T) -> T {
    if v.non_negative() {
        v.clone()
    } else {
        zero.minus(v)
    }
}

/// [`super::exact::diamond_contains`] on homogeneous integers: `(u, v)` from the sample,
/// radius `r`, all scaled by the same positive number.
fn contains<T: Lane>(zero: &T, u: &T, v: &T, r: &T, x_major: bool) -> bool {
    let s = abs(zero, u).plus(&abs(zero, v));
    if s.less(r) {
        return true;
    }
    if r.less(&s) {
        return false;
    }
    if zero.less(v) {
        true // lower edges and the bottom corner
    } else if !v.non_negative() {
        false // upper edges and the top corner
    } else {
        zero.less(u) && !x_major // the right corner for y-major lines
    }
}

/// `n0 / m0 < n1 / m1` for positive denominators.
fn before<T: Lane>(t0: (&T, &T), t1: (&T, &T)) -> bool {
    t0.0.times(t1.1).less(&t1.0.times(t0.1))
}

/// A clipped end of the chord: the numerator `n` of its parameter and the plane whose `m`
/// is its denominator; `None` is the segment's own end (`t0 = 0`, `t1 = 1`).
type ChordEnd<T> = Option<(T, usize)>;

/// Whether the segment draws the pixel whose sample is `(sx, sy)` (local): the test of the
/// module docs.
fn exits<T: Lane>(w: &Walk, s: &Seg<T>, sx: &T, sy: &T) -> bool {
    let z = &s.zero;
    if contains(z, &s.b[0].minus(sx), &s.b[1].minus(sy), &s.r, w.x_major) {
        return false; // the end lies in the test area: it never leaves
    }
    let (ua, va) = (s.a[0].minus(sx), s.a[1].minus(sy));
    let (sum, diff) = (ua.plus(&va), ua.minus(&va));
    let g0 = [z.minus(&diff), z.minus(&sum)];
    let g0 = [&sum, &diff, &g0[0], &g0[1]];
    let (mut t0, mut t1): (ChordEnd<T>, ChordEnd<T>) = (None, None);
    let mut on_upper_edge = false;
    let mut on_lower_edge = false;
    for p in 0..4 {
        let m = &s.m[p];
        match w.signs[p] {
            Sign::NoSign => {
                if s.r.less(g0[p]) {
                    return false;
                }
                if !g0[p].less(&s.r) {
                    // the segment's line is this edge's line
                    if PLANES[p].1 > 0 {
                        on_lower_edge = true;
                    } else {
                        on_upper_edge = true;
                    }
                }
            }
            Sign::Plus => {
                // t <= (r - g0) / m
                let n = s.r.minus(g0[p]);
                if !n.non_negative() {
                    return false;
                }
                if n.less(m) && t1.as_ref().is_none_or(|(n1, p1)| before((&n, m), (n1, &s.m[*p1]))) {
                    t1 = Some((n, p));
                }
            }
            Sign::Minus => {
                // t >= (g0 - r) / m
                let n = g0[p].minus(&s.r);
                if !z.less(&n) {
                    continue;
                }
                if m.less(&n) {
                    return false;
                }
                if t0.as_ref().is_none_or(|(n0, p0)| before((n0, &s.m[*p0]), (&n, m))) {
                    t0 = Some((n, p));
                }
            }
        }
    }
    let positive_length = match (&t0, &t1) {
        (None, None) => true,
        (None, Some((n1, _))) => z.less(n1),
        (Some((n0, p0)), None) => n0.less(&s.m[*p0]),
        (Some((n0, p0)), Some((n1, p1))) => {
            let (a, b) = ((n0, &s.m[*p0]), (n1, &s.m[*p1]));
            if before(b, a) {
                return false; // t1 < t0: the segment misses the closed diamond
            }
            before(a, b)
        }
    };
    if positive_length && (on_lower_edge || !on_upper_edge) {
        return true; // the chord's midpoint is in the test area
    }
    let end = |t: &(T, usize)| {
        let (n, m) = (&t.0, &s.m[t.1]);
        let u = ua.times(m).plus(&s.d[0].times(n));
        let v = va.times(m).plus(&s.d[1].times(n));
        contains(z, &u, &v, &s.r.times(m), w.x_major)
    };
    // t0 = 0 is a itself; t1 = 1 is b, already known to be out.
    let start = match &t0 {
        None => contains(z, &ua, &va, &s.r, w.x_major),
        Some(t) => end(t),
    };
    start || t1.as_ref().is_some_and(end)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::{Convention, PixelCentre, Preset};
    use crate::coverage::Coverage;
    use crate::line::exact::rasterize_diamond;

    fn oracle(a: &Point, b: &Point, target: &Target) -> Coverage {
        let mut c = Coverage::new(target.width, target.height);
        rasterize_diamond(a, b, 0, target, &mut c);
        c
    }

    fn planned(a: &Point, b: &Point, target: &Target, width: Option<Width>) -> Coverage {
        let mut c = Coverage::new(target.width, target.height);
        let p = match width {
            None => PlannedSegment::new(a, b, target),
            Some(w) => PlannedSegment::forced(a, b, target, w).expect("width holds the bound"),
        };
        if let Some(p) = p {
            p.rasterize(0, &mut c);
        }
        c
    }

    #[test]
    fn indices_above_by_brute_force() {
        for n_first in -9..=9i64 {
            for inc in [-7i64, -3, -1, 1, 2, 5] {
                for v in -12..=12i64 {
                    for (first, last) in [(0i64, 0i64), (0, 5), (3, 9)] {
                        let want: Vec<i64> = (first..=last).filter(|k| n_first + (k - first) * inc > v).collect();
                        let (lo, hi) = indices_above(&n_first.into(), &inc.into(), first, last, &v.into());
                        assert_eq!(
                            (lo..=hi).collect::<Vec<_>>(),
                            want,
                            "{n_first} {inc} {v} {first} {last}"
                        );
                    }
                }
            }
        }
    }

    /// A hand-derived plan: (1, 1) -> (4, 2) on an 8x8 canvas, samples at pixel centres.
    /// `L = lcm(1, 1, 2, 2) = 2`, `r = 1`, `c = 1`; in L units a = (2, 2), b = (8, 4),
    /// (dx, dy) = (6, 2): x-major, G = |dx| + |dy| = 8, g = gcd(6, 2) = 2, (3, 1), D = L 3 = 6.
    /// - Major indices: samples 2k + 1 within r = 1 of [2, 8]: k from ceil((2 - 1 - 1) / 2)
    ///   = 0 to floor((8 + 1 - 1) / 2) = 4.
    /// - j0(k) = floor(N(k) / 6), N(k) = (2 - 1 - 1) 3 + (2k + 1 - 2) 1 = 2k - 1: -1, 0, 0,
    ///   0, 1 for k = 0..=4 (all within -1..=7: no cut). The first candidate is pixel (0, -1),
    ///   whose sample (1/2, -1/2) is (1, -1) in L units: a = (1, 3), b = (7, 5) locally, and
    ///   q runs 0..=2 (q_end = 1 - (-1) = 2).
    /// - Tested box: major 0..=4 -> x in [0, 8]; minor q in max(0, 1) = 1 (row 0, the canvas
    ///   cuts row -1) ..= min(2 + 1, 7 + 1) = 3 -> y in [2, 6].
    ///   UA = max(|1 - 0|, |1 - 8|) = 7, VA = max(|3 - 2|, |3 - 6|) = 3; UB = 7, VB = 3.
    /// - Terms: endpoint 7; sample max(4 * 2, |0 - 1| 2, |2 + 1| 2) = 8; G = 8; D = 6;
    ///   UB + VB = 10; UA + VA + r = 11; G^2 = 64; (|dx| + r) G = 56; (|dy| + r) G = 24;
    ///   L = 2.
    ///
    /// So the bound is 64, the cross-product term.
    #[test]
    fn bound_by_hand() {
        let (a, b) = (Point::from_ints(1, 1), Point::from_ints(4, 2));
        let target = Target::new(8, 8, Convention::default()).unwrap();
        let p = PlannedSegment::new(&a, &b, &target).unwrap();
        assert_eq!(p.plan().scale, BigInt::from(2));
        assert_eq!(p.plan().bound.value, BigInt::from(64));
        assert_eq!(
            p.plan().bound.what,
            "a cross-product of two clip parameters, (|dx| + |dy|)^2"
        );
        assert_eq!(p.plan().width, Width::I32);
        assert_eq!((p.walk.k0, p.walk.j0, p.walk.steps), (0, -1, 4));
        assert_eq!(planned(&a, &b, &target, None), oracle(&a, &b, &target));
    }

    /// Every width draws rational segments in all directions, under every preset and both
    /// centres, and equals the oracle.
    #[test]
    fn every_width_equals_the_oracle() {
        let ends = [
            ((1, 3, 1, 2), (23, 2, 7, 3)),
            ((11, 1, 1, 7), (1, 2, 21, 2)),
            ((5, 2, 0, 1), (7, 2, 12, 1)),
            ((12, 1, 11, 1), (0, 1, 1, 2)),
            ((3, 1, 3, 1), (9, 1, 9, 1)),
            ((-3, 1, 5, 2), (17, 1, 5, 2)),
        ];
        for preset in Preset::ALL {
            for centre in [PixelCentre::Half, PixelCentre::Corner] {
                let mut conv = preset.convention();
                conv.pixel_centre = centre;
                let target = Target::new(12, 12, conv).unwrap();
                for &((an, ad, bn, bd), (cn, cd, dn, d_d)) in &ends {
                    let a = Point::from_fractions(an, ad, bn, bd);
                    let b = Point::from_fractions(cn, cd, dn, d_d);
                    let want = oracle(&a, &b, &target);
                    assert!(want.covered_pixels() >= 5, "{a:?} {b:?}");
                    for w in Width::ALL {
                        assert_eq!(
                            planned(&a, &b, &target, Some(w)),
                            want,
                            "{a:?} {b:?} {preset:?} {centre:?} {w}"
                        );
                    }
                }
            }
        }
    }

    /// The tie-heavy corners of one diamond: every segment between points of the half-pixel
    /// lattice around pixel (2, 2), both centres, equals the oracle (edges, corners, chords
    /// along an edge).
    #[test]
    fn half_pixel_lattice_equals_the_oracle() {
        let lattice: Vec<Point> = (2..=8)
            .flat_map(|x| (2..=8).map(move |y| Point::from_fractions(x, 2, y, 2)))
            .collect();
        for centre in [PixelCentre::Half, PixelCentre::Corner] {
            let mut conv = Preset::D3d11.convention();
            conv.pixel_centre = centre;
            let target = Target::new(6, 6, conv).unwrap();
            for a in &lattice {
                for b in &lattice {
                    assert_eq!(
                        planned(a, b, &target, None),
                        oracle(a, b, &target),
                        "{a:?} -> {b:?} {centre:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn nothing_on_the_canvas_plans_nothing() {
        let target = Target::new(8, 8, Convention::default()).unwrap();
        let p = |x: i64, y: i64| Point::from_ints(x, y);
        assert!(PlannedSegment::new(&p(2, 2), &p(2, 2), &target).is_none());
        assert!(PlannedSegment::new(&p(20, 2), &p(30, 3), &target).is_none());
        // x-major, entirely below the canvas: the minor cut empties it.
        assert!(PlannedSegment::new(&p(0, 20), &p(8, 24), &target).is_none());
        assert!(matches!(
            PlannedSegment::forced(&p(0, 20), &p(8, 24), &target, Width::F32),
            Ok(None)
        ));
    }
}
