//! The planned exact engine for triangles: the oracle's decisions, computed incrementally
//! in the narrowest arithmetic that provably holds them ([`crate::num::plan`]).
//!
//! TriangleSetup, once per triangle, in exact integers (checked `i128` when every coordinate
//! is a small [`crate::num::compact::Compact`] and nothing overflows, big integers otherwise:
//! one generic setup, `setup_scaled`): the scale `L` that makes every vertex
//! coordinate and the pixel centre integers, the vertices taken relative to the first
//! sample of the triangle's pixel range, and per edge (oriented so the interior is
//! `E > 0`) the value `E - bias` at that sample and its steps, `L dY` one pixel right and
//! `-L dX` one pixel down (Pineda 1988; `bias` is 1 on an edge the tie rule leaves out,
//! 0 on an inclusive one, so that `E - bias >= 0` is the oracle's test on integers).
//! `E` scaled by `L^2 > 0` keeps its sign, so every decision is the oracle's.
//!
//! Traversal and bound: the block kernel this engine shares with [`crate::tri::fixed`]
//! (`tri/blocks.rs`): the pixel range in [`BLOCK`] x [`BLOCK`] blocks, a block outside
//! one edge skipped, one inside all three filled as spans, the rest tested a row at a
//! time, every value reached by addition only and never beyond the range. Every value it
//! holds is `E - bias` at a sample of the range (at most its largest at the range's four
//! corners: `E` is linear) or a difference of two of them (a multiple of a step, or the
//! step to a block's extreme corner); [`PlannedTriangle::new`] computes the largest of
//! all of them exactly and plans the width on it.
//!
//! [`BLOCK`]: crate::tri::fixed::BLOCK

use num_bigint::BigInt;

use crate::convention::{AnyTieRule, PixelCentre, Target};
use crate::coverage::CoverageSink;
use crate::geom::{CompactTriangle, Triangle};
use crate::num::compact::Compact;
use crate::num::lane::{InWidth, Lane, LaneState, LaneStateI128, Planned, SetupInt};
use crate::num::plan::{scale_of, scaled, Bound, Plan, Width};
use crate::raster::{exact_sample_range, PixelRange};

use super::blocks::{bound_of, traverse, Edges};

/// A triangle's state in each width: its edges.
#[derive(Debug, Clone)]
struct TriangleLanes;

impl LaneState for TriangleLanes {
    type In<T: Lane> = Edges<T>;
    fn convert<T: Lane>(exact: &Edges<BigInt>) -> Edges<T> {
        Edges::from_exact(exact)
    }
}

impl LaneStateI128 for TriangleLanes {
    fn convert_i128<T: Lane>(exact: &Edges<i128>) -> Edges<T> {
        Edges::from_exact(exact)
    }
}

/// The block traversal of one triangle's pixel range, run in the planned width.
struct Traverse<'a, S: ?Sized> {
    range: &'a PixelRange,
    id: u32,
    sink: &'a mut S,
}

impl<S: CoverageSink + ?Sized> InWidth<TriangleLanes> for Traverse<'_, S> {
    type Output = ();
    #[inline]
    fn run<T: Lane>(self, edges: &Edges<T>) {
        traverse(edges, self.range, self.id, self.sink);
    }
}

/// A triangle set up for the planned engine: its pixel range, its plan and its edges in
/// the planned width.
#[derive(Debug, Clone)]
pub struct PlannedTriangle {
    range: PixelRange,
    planned: Planned<TriangleLanes>,
}

/// The exact setup: range, scale, edges and the bound, in `N` (`i128` or [`BigInt`]).
struct TriangleSetup<N> {
    range: PixelRange,
    scale: N,
    edges: Edges<N>,
    bound: Bound,
}

/// The setup of `tri` in big integers: scale, range, then [`setup_scaled`].
fn setup(tri: &Triangle, target: &Target, rule: AnyTieRule) -> Option<TriangleSetup<BigInt>> {
    let range = exact_sample_range(tri.v.iter(), target)?;
    let centre = target.convention.pixel_centre.offset();
    let scale = scale_of(tri.v.iter().flat_map(|p| [&p.x, &p.y]).chain([&centre]));
    let c = scaled(&centre, &scale);
    let v = tri.v.each_ref().map(|p| [scaled(&p.x, &scale), scaled(&p.y, &scale)]);
    setup_scaled(v, c, scale, range, rule).expect("big integers do not overflow")
}

/// The setup of a compact triangle whose coordinates are all small, in `i128`: the same
/// scale, range, edges and bound as [`setup`] computes in big integers. `None` when a
/// coordinate is not small or a value overflows `i128` (then [`setup`] runs); `Some(None)`
/// when the triangle covers nothing.
fn setup_small(tri: &CompactTriangle, target: &Target, rule: AnyTieRule) -> Option<Option<TriangleSetup<i128>>> {
    let small = |c: &Compact| c.small().map(|(n, d)| (i128::from(n), i128::from(d)));
    let mut coords = [[(0i128, 1i128); 2]; 3];
    for (k, [x, y]) in tri.v.iter().enumerate() {
        coords[k] = [small(x)?, small(y)?];
    }
    let (cn, cd): (i128, i128) = match target.convention.pixel_centre {
        PixelCentre::Half => (1, 2),
        PixelCentre::Corner => (0, 1),
    };
    // The lcm of the denominators (each below 2^63), kept below 2^62 so that every scaled
    // coordinate stays below 2^125.
    let mut scale: i128 = cd;
    for &(_, d) in coords.iter().flatten() {
        scale = (scale / num_integer::gcd(scale, d)).checked_mul(d)?;
        if scale >= 1 << 62 {
            return None;
        }
    }
    let v = coords.map(|p| p.map(|(n, d)| n * (scale / d)));
    let c = cn * (scale / cd);
    // The pixels whose sample (i L + C) lies in the closed box: ceil((min - C) / L) to
    // floor((max - C) / L) on each axis, as `raster::exact_sample_range` reads the box.
    let index = |q: i128| i64::try_from(q).unwrap_or(if q < 0 { i64::MIN } else { i64::MAX });
    let axis = |a: usize| {
        let (lo, hi) = (v.iter().map(|p| p[a]).min()?, v.iter().map(|p| p[a]).max()?);
        Some((index(-(c - lo).div_euclid(scale)), index((hi - c).div_euclid(scale))))
    };
    let ((x0, x1), (y0, y1)) = (axis(0)?, axis(1)?);
    let Some(range) = PixelRange::clamped([x0, y0], [x1, y1], target.width, target.height) else {
        return Some(None);
    };
    setup_scaled(v, c, scale, range, rule)
}

/// The setup from the vertices and the pixel centre times `scale` (integers): the vertices
/// relative to the range's first sample, the orientation, and per edge `E - bias` there and
/// its steps; then the bound. `None` on overflow of `N`; `Some(None)` for zero area.
fn setup_scaled<N: SetupInt>(
    v: [[N; 2]; 3],
    centre: N,
    scale: N,
    range: PixelRange,
    rule: AnyTieRule,
) -> Option<Option<TriangleSetup<N>>> {
    let first = |i: u32| N::from_i64(i.into()).mul_exact(&scale)?.add_exact(&centre);
    let origin = [first(range.x0)?, first(range.y0)?];
    let local = |p: &[N; 2]| Some([p[0].sub_exact(&origin[0])?, p[1].sub_exact(&origin[1])?]);
    let [a, mut b, mut c] = [local(&v[0])?, local(&v[1])?, local(&v[2])?];
    let edge = |a: &[N; 2], b: &[N; 2]| Some([b[0].sub_exact(&a[0])?, b[1].sub_exact(&a[1])?]);
    // E_{ab}(p) = (p.x - a.x) dy - (p.y - a.y) dx; at p = 0: a.y dx - a.x dy.
    let area2 = {
        let [dx, dy] = edge(&a, &b)?;
        let [cx, cy] = edge(&a, &c)?;
        cx.mul_exact(&dy)?.sub_exact(&cy.mul_exact(&dx)?)?
    };
    if area2.equals_zero() {
        return Some(None);
    }
    if area2.below_zero() {
        std::mem::swap(&mut b, &mut c);
    }
    let zero = N::from_i64(0);
    let mut edges = Edges {
        origin: [zero.clone(), zero.clone(), zero.clone()],
        step_x: [zero.clone(), zero.clone(), zero.clone()],
        step_y: [zero.clone(), zero.clone(), zero.clone()],
    };
    for (k, (from, to)) in [(&a, &b), (&b, &c), (&c, &a)].into_iter().enumerate() {
        let [dx, dy] = edge(from, to)?;
        let bias = i64::from(!rule.is_inclusive(dx.cmp(&zero), dy.cmp(&zero)));
        edges.origin[k] = from[1]
            .mul_exact(&dx)?
            .sub_exact(&from[0].mul_exact(&dy)?)?
            .sub_exact(&N::from_i64(bias))?;
        // A step the traversal never takes (a range one pixel wide or high) is left at
        // zero, so that it need not fit the width.
        if range.x1 > range.x0 {
            edges.step_x[k] = dy.mul_exact(&scale)?;
        }
        if range.y1 > range.y0 {
            edges.step_y[k] = dx.mul_exact(&scale)?.neg_exact()?;
        }
    }
    let bound = bound_of(&edges, &range)?;
    Some(Some(TriangleSetup {
        range,
        scale,
        edges,
        bound,
    }))
}

impl PlannedTriangle {
    /// Sets up `tri` (exact vertices: as written, or snapped and converted back) for
    /// `target`, in the cheapest width its bound allows; `None` when it covers nothing
    /// (zero area, or no sample of the canvas in its bounding box).
    pub fn new(tri: &Triangle, target: &Target) -> Option<PlannedTriangle> {
        Self::with_rule(tri, target, target.convention.tie_rule.into())
    }

    /// As [`PlannedTriangle::new`] with the edges' inclusive flags from `rule` instead of
    /// the target's tie rule: any of the six rules a renderer may follow (what
    /// `compare --fit` searches).
    pub fn with_rule(tri: &Triangle, target: &Target, rule: AnyTieRule) -> Option<PlannedTriangle> {
        let s = setup(tri, target, rule)?;
        let planned = Planned::new(s.scale, s.bound, s.edges);
        Some(PlannedTriangle {
            range: s.range,
            planned,
        })
    }

    /// [`PlannedTriangle::new`] of a compact triangle: the same plan and edges, set up in
    /// `i128` when every coordinate is small and no value of the setup overflows it (no
    /// big integer but the plan's scale and bound), in big integers otherwise.
    pub fn from_compact(tri: &CompactTriangle, target: &Target) -> Option<PlannedTriangle> {
        let rule = target.convention.tie_rule.into();
        match setup_small(tri, target, rule) {
            Some(s) => {
                let s = s?;
                let planned = Planned::new_i128(BigInt::from(s.scale), s.bound, s.edges);
                Some(PlannedTriangle {
                    range: s.range,
                    planned,
                })
            }
            None => Self::with_rule(&tri.to_triangle(), target, rule),
        }
    }

    /// As [`PlannedTriangle::new`] but in `width`: `Ok(None)` when it covers nothing,
    /// `Err(plan)` (the plan it would have) when `width` cannot hold its bound. For tests
    /// and benches that run every width.
    pub fn forced(tri: &Triangle, target: &Target, width: Width) -> Result<Option<PlannedTriangle>, Plan> {
        let Some(s) = setup(tri, target, target.convention.tie_rule.into()) else {
            return Ok(None);
        };
        let planned = Planned::forced(s.scale, s.bound, s.edges, width)?;
        Ok(Some(PlannedTriangle {
            range: s.range,
            planned,
        }))
    }

    /// The plan: scale, bound and width.
    pub fn plan(&self) -> &Plan {
        self.planned.plan()
    }

    /// The first and last row of its pixel range (the only rows it can cover).
    pub fn rows(&self) -> (u32, u32) {
        (self.range.y0, self.range.y1)
    }

    /// Covers every pixel whose sample is inside the triangle: equal, pixel for pixel, to
    /// [`crate::tri::exact::rasterize`] on the same triangle and target (the property
    /// tests of `tests/planned.rs` are the proof).
    ///
    /// ```
    /// use rasterproof::convention::{Convention, Target};
    /// use rasterproof::coverage::Coverage;
    /// use rasterproof::geom::{Point, Triangle};
    /// use rasterproof::num::plan::Width;
    /// use rasterproof::tri::planned::PlannedTriangle;
    /// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
    /// let target = Target::new(4, 4, Convention::default()).unwrap();
    /// let planned = PlannedTriangle::new(&t, &target).unwrap();
    /// // Integer vertices, samples at half pixels: scale 2, every value tiny.
    /// assert_eq!(planned.plan().width, Width::I32);
    /// let (mut a, mut b) = (Coverage::new(4, 4), Coverage::new(4, 4));
    /// planned.rasterize(0, &mut a);
    /// rasterproof::tri::exact::rasterize(&t, 0, &target, &mut b);
    /// assert_eq!(a, b);
    /// assert_eq!(a.covered_pixels(), 6);
    /// ```
    pub fn rasterize<S: CoverageSink + ?Sized>(&self, id: u32, sink: &mut S) {
        let range = &self.range;
        self.planned.run(Traverse { range, id, sink });
    }
}

/// Plans and rasterizes `tri` in one call (see [`PlannedTriangle`]).
pub fn rasterize<S: CoverageSink + ?Sized>(tri: &Triangle, id: u32, target: &Target, sink: &mut S) {
    if let Some(p) = PlannedTriangle::new(tri, target) {
        p.rasterize(id, sink);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::Convention;
    use crate::coverage::Coverage;
    use crate::geom::Point;
    use num_traits::{Signed, Zero};

    /// A hand-derived plan: (0,0) (4,0) (0,4) on a 4x4 canvas, centres at 1/2, so L = 2,
    /// the range is pixels 0..=3 on both axes and the first sample is (1, 1) in L units.
    /// Relative to it the vertices are a = (-1,-1), b = (7,-1), c = (-1,7); E_ab(c) =
    /// 0 * 0 - 8 * 8 = -64 < 0, so b and c swap: a -> (-1,7) -> (7,-1) -> a.
    /// - edge 0, (-1,-1) -> (-1,7): dx = 0, dy = 8, inclusive (dy > 0), bias 0;
    ///   E = 8 (p.x + 1): 8 at pixel column 0 (p.x = 0), 56 at column 3 (p.x = 6).
    /// - edge 1, (-1,7) -> (7,-1): dx = 8, dy = -8, not inclusive, bias 1;
    ///   E - 1 = 47 - 8 (p.x + p.y): 47 at pixel (0,0), -49 at pixel (3,3).
    /// - edge 2, (7,-1) -> (-1,-1): horizontal running left, a top edge, bias 0;
    ///   E = 8 (p.y + 1): at most 56.
    /// - steps: the range fits one block, so it is filled row by row with single steps:
    ///   L dy = 16 (edge 0), edge 1 16 both ways, edge 2 16 down.
    ///
    /// So the bound is 56, first reached by edge 0 at pixel (3, 0).
    #[test]
    fn bound_by_hand() {
        let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
        let target = Target::new(4, 4, Convention::default()).unwrap();
        let p = PlannedTriangle::new(&t, &target).unwrap();
        assert_eq!(p.plan().scale, BigInt::from(2));
        assert_eq!(p.plan().bound.value, BigInt::from(56));
        assert_eq!(p.plan().bound.what, "edge 0 at pixel (3, 0)");
        assert_eq!(p.plan().width, Width::I32);
    }

    #[test]
    fn forced_refuses_a_width_that_cannot_hold_the_bound() {
        // A triangle 2^13 px wide at L = 2: values about 2 * (2^14)^2 = 2^29... fits i32
        // but not f32 (2^24).
        let s: u32 = 1 << 13;
        let v = i64::from(s);
        let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(v, 0), Point::from_ints(0, v));
        let target = Target::new(s, s, Convention::default()).unwrap();
        assert!(PlannedTriangle::forced(&t, &target, Width::F32).is_err());
        let p = PlannedTriangle::forced(&t, &target, Width::I64).unwrap().unwrap();
        assert_eq!(p.plan().width, Width::I64);
        let mut c = Coverage::new(s, s);
        p.rasterize(0, &mut c);
        // x + y < s for samples (i + 1/2, j + 1/2): i + j <= s - 2, plus the hypotenuse's
        // samples i + j = s - 1 (x + y = s exactly: a right edge, out): s (s - 1) / 2.
        assert_eq!(c.covered_pixels(), (s * (s - 1) / 2) as usize);
    }

    /// A lane that records the largest magnitude of every value the traversal computes.
    #[derive(Debug, Clone)]
    struct Track(BigInt);

    thread_local! {
        static LARGEST: std::cell::RefCell<BigInt> = std::cell::RefCell::new(BigInt::zero());
    }

    fn seen(v: BigInt) -> Track {
        LARGEST.with(|m| {
            if v.abs() > *m.borrow() {
                *m.borrow_mut() = v.abs();
            }
        });
        Track(v)
    }

    impl Lane for Track {
        const WIDTH: Width = Width::Big;
        fn from_big(v: &BigInt) -> Self {
            seen(v.clone())
        }
        fn zero_value() -> Self {
            Track(BigInt::zero())
        }
        fn plus(&self, other: &Self) -> Self {
            seen(&self.0 + &other.0)
        }
        fn add_to(&mut self, other: &Self) {
            *self = self.plus(other);
        }
        fn minus(&self, other: &Self) -> Self {
            seen(&self.0 - &other.0)
        }
        fn times(&self, other: &Self) -> Self {
            seen(&self.0 * &other.0)
        }
        fn scaled_by(&self, k: u32) -> Self {
            seen(&self.0 * k)
        }
        fn less(&self, other: &Self) -> bool {
            self.0 < other.0
        }
        fn non_negative(&self) -> bool {
            !self.0.is_negative()
        }
    }

    /// Every value the traversal computes, recorded through [`Track`], is within the
    /// plan's bound, and the bound is reached: on triangles whose ranges are one block,
    /// a few blocks, and partial blocks on either axis (where the steps to a block's
    /// corners can exceed every edge value at the range's corners).
    #[test]
    fn the_bound_holds_every_value_the_traversal_computes() {
        let target = Target::new(40, 40, Convention::default()).unwrap();
        let q = |n: i64, d: i64| Point::from_fractions(n, d, 0, 1);
        let mut checked = 0;
        for (k, (a, b, c)) in [
            ((0, 0), (4, 0), (0, 4)),
            ((-3, 5), (13, 0), (5, 12)),
            ((1, 1), (39, 2), (20, 38)),
            ((-50, 4), (90, 5), (4, 60)),
            ((0, 9), (9, 0), (100, 100)),
            ((7, -30), (8, 70), (-60, 20)),
            // 9 and 12 px ranges: a partial block on each axis, where the hypotenuse's
            // step to a block's far corner (7 of the 8 or 11 columns and rows) exceeds
            // its value at any corner of the range
            ((0, 0), (9, 0), (0, 9)),
            ((2, 3), (14, 3), (2, 15)),
        ]
        .into_iter()
        .enumerate()
        {
            for d in [1, 3, 7] {
                let p = |(x, y): (i64, i64)| Point::new(q(x * d + 1, d).x, Point::from_fractions(y * d + 2, d, 0, 1).x);
                let t = Triangle::new(p(a), p(b), p(c));
                let Some(setup) = setup(&t, &target, target.convention.tie_rule.into()) else {
                    continue;
                };
                let bound = bound_of(&setup.edges, &setup.range).unwrap();
                LARGEST.with(|m| *m.borrow_mut() = BigInt::zero());
                let edges: Edges<Track> = Edges::from_exact(&setup.edges);
                let mut cov = Coverage::new(40, 40);
                traverse(&edges, &setup.range, 0, &mut cov);
                let largest = LARGEST.with(|m| m.borrow().clone());
                assert!(largest <= bound.value, "case {k}, d {d}: {largest} > {}", bound.value);
                assert_eq!(
                    largest, bound.value,
                    "case {k}, d {d}: the bound ({}) is reached",
                    bound.what
                );
                checked += 1;
            }
        }
        assert!(checked >= 15);
    }
}
