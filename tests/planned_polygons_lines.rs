//! The planned exact engines for polygons ([`PlannedPolygon`]) and diamond-exit lines
//! ([`PlannedSegment`]) equal their plain oracles, pixel for pixel: on random polygons of
//! every family (holes, self-crossing, both fill rules), on unsnapped rational vertices,
//! on polygons out of exact Sutherland-Hodgman clipping (large denominators), on rational
//! segments in every direction and far off the canvas; under every preset and both pixel
//! centres; in every width that holds the bound; and at the boundaries of i32 and i64,
//! where the plan must switch widths exactly there.

use crate::common;

use common::config;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::One;
use proptest::prelude::*;
use proptest::test_runner::Config;
use rasterproof::check::differing_pixels;
use rasterproof::clip::sutherland_hodgman::clip_polygon;
use rasterproof::convention::{AnyTieRule, PixelCentre, Preset, Target};
use rasterproof::coverage::Coverage;
use rasterproof::fill::polygon::{rasterize_exact, rasterize_exact_with, PlannedPolygon};
use rasterproof::geom::{FillRule, Point, Polygon};
use rasterproof::line::exact::rasterize_diamond;
use rasterproof::line::planned::PlannedSegment;
use rasterproof::num::plan::Width;
use rasterproof::strategy::clip::any_window;
use rasterproof::strategy::diamond_line;
use rasterproof::strategy::polygon::any_polygon;

/// The oracles are slow: 96 cases per property unless `PROPTEST_CASES` says otherwise.
fn cfg() -> Config {
    let mut c = config("proptest-regressions/planned_polygons_lines.txt");
    if std::env::var("PROPTEST_CASES").is_err() {
        c.cases = 96;
    }
    c
}

fn target_with(side: u32, preset: Preset, corner: bool) -> Target {
    let mut conv = preset.convention();
    if corner {
        conv.pixel_centre = PixelCentre::Corner;
    }
    Target::new(side, side, conv).unwrap()
}

fn preset() -> impl Strategy<Value = Preset> {
    prop::sample::select(Preset::ALL.to_vec())
}

fn big(v: &BigInt) -> BigRational {
    BigRational::from_integer(v.clone())
}

fn pow2(k: u32) -> BigInt {
    BigInt::one() << k
}

// ---------------------------------------------------------------------------------------
// Polygons

fn oracle_fill(poly: &Polygon, target: &Target) -> Coverage {
    let mut c = Coverage::new(target.width, target.height);
    rasterize_exact(poly, 0, target, &mut c);
    c
}

fn planned_fill(p: Option<&PlannedPolygon>, target: &Target) -> Coverage {
    let mut c = Coverage::new(target.width, target.height);
    if let Some(p) = p {
        p.rasterize(0, &mut c);
    }
    c
}

/// The planned fill (in the planned width) against the oracle.
fn check_polygon(poly: &Polygon, target: &Target) -> Result<(), TestCaseError> {
    let planned = PlannedPolygon::new(poly, target);
    let got = planned_fill(planned.as_ref(), target);
    let want = oracle_fill(poly, target);
    let plan = planned.as_ref().map(|p| p.plan().to_string());
    prop_assert_eq!(differing_pixels(&want, &got), vec![], "plan {:?}\n{:?}", plan, poly);
    Ok(())
}

/// `poly` in every width: the ones that hold the bound equal the oracle, the others refuse
/// with the plan `new` makes; a bound within f32's `2^24` must run in all six.
fn check_polygon_every_width(poly: &Polygon, target: &Target) -> Result<(), TestCaseError> {
    let want = oracle_fill(poly, target);
    let Some(plan) = PlannedPolygon::new(poly, target).map(|p| p.plan().clone()) else {
        prop_assert_eq!(want.covered_pixels(), 0);
        return Ok(());
    };
    let fits_f32 = Width::F32.holds(&plan.bound.value);
    for w in Width::ALL {
        match PlannedPolygon::forced(poly, target, w) {
            Ok(Some(p)) => {
                prop_assert_eq!(p.plan().width, w);
                let got = planned_fill(Some(&p), target);
                prop_assert_eq!(differing_pixels(&want, &got), vec![], "{} {:?}", w, poly);
            }
            Ok(None) => prop_assert!(false, "forced lost the polygon in {}", w),
            Err(refused) => {
                prop_assert!(!fits_f32, "{} refused a bound within 2^24: {}", w, refused);
                prop_assert_eq!(&refused, &plan);
                prop_assert!(!w.holds(&plan.bound.value));
            }
        }
    }
    Ok(())
}

/// A rational coordinate in `-4..=side + 4` with a denominator of 1, 2, 3, 7, 256 or 1000.
fn rational(side: i64) -> impl Strategy<Value = BigRational> {
    (prop::sample::select(vec![1i64, 2, 3, 7, 256, 1000]), any::<u64>()).prop_map(move |(d, raw)| {
        let span = u64::try_from((side + 8) * d + 1).unwrap();
        let n = -4 * d + i64::try_from(raw % span).unwrap();
        BigRational::new(n.into(), d.into())
    })
}

fn rational_point(side: i64) -> impl Strategy<Value = Point> {
    (rational(side), rational(side)).prop_map(|(x, y)| Point::new(x, y))
}

/// Polygons with unsnapped rational vertices: a random (often self-crossing) outline and,
/// half of the time, a random hole; either fill rule.
fn rational_polygon(side: i64) -> impl Strategy<Value = Polygon> {
    (
        prop::collection::vec(rational_point(side), 3..=8),
        prop::collection::vec(rational_point(side), 0..=5),
        any::<bool>(),
    )
        .prop_map(|(outline, hole, even_odd)| {
            let rule = if even_odd { FillRule::EvenOdd } else { FillRule::NonZero };
            let mut poly = Polygon::new(outline, rule);
            if hole.len() >= 3 {
                poly.holes.push(hole);
            }
            poly
        })
}

/// A triangle with one edge from (0, 0) to (1, m): its divisor is `L dy' = m` (L = 1 with
/// corner samples and integer vertices; gcd(1, m) = 1), the edge steps over rows 1..=15
/// of a 16x16 canvas, and the other edges' divisors are at most m.
/// Polygons of 3 to 8 vertices on the half-pixel grid of a 16x16 canvas, a vertex often
/// at the height or the abscissa of the one before it: horizontal and vertical edges on
/// sample rows and columns, vertices on samples (ties everywhere, under either sample
/// position); nonzero or even-odd.
fn half_grid_polygon() -> impl Strategy<Value = Polygon> {
    let vertex = (-2i64..=34, -2i64..=34, 0u8..4);
    (prop::collection::vec(vertex, 3..=8), any::<bool>()).prop_map(|(raw, even_odd)| {
        let mut v: Vec<(i64, i64)> = Vec::new();
        for (x, y, keep) in raw {
            let prev = v.last().copied();
            v.push(match (prev, keep) {
                (Some((_, py)), 0) => (x, py),
                (Some((px, _)), 1) => (px, y),
                _ => (x, y),
            });
        }
        let outline = v.iter().map(|&(x, y)| Point::from_fractions(x, 2, y, 2)).collect();
        Polygon::new(outline, if even_odd { FillRule::EvenOdd } else { FillRule::NonZero })
    })
}

fn tall_triangle(m: &BigInt) -> Polygon {
    let p = |x: i64, y: &BigInt| Point::new(BigRational::from_integer(x.into()), big(y));
    Polygon::new(
        vec![p(0, &BigInt::from(0)), p(1, m), p(8, &BigInt::from(0))],
        FillRule::NonZero,
    )
}

fn corner_target(side: u32) -> Target {
    target_with(side, Preset::D3d11, true)
}

/// By hand: `tall_triangle(m)` on a 16x16 canvas with corner samples (`L = 1`, the first
/// sample is (0, 0) itself). Edge 0, (0,0) -> (1,m): dx = 1, dy = m, g = 1, d = m; under
/// top-left it crosses rows 0..=15 (clamped), `N_j = j`: row 0 has `N = 0` (threshold 0,
/// a lead row), rows 1..=15 are the middle (thresholds 1), so it steps and holds `d = m`.
/// Edge 1, (1,m) -> (8,0) (going up: top (8,0), dx = -7, dy = m): d = m / gcd(7, m) <= m.
/// Edge 2 is horizontal. So the bound is exactly m, and the width is the first of the
/// planner's order (i32, i64, f32, f64, i128, bigint) whose limit holds m: one unit past
/// i32's limit `2^31 - 1` is i64, one past i64's `2^63 - 1` is i128.
#[test]
fn polygon_width_boundaries_by_hand() {
    let target = corner_target(16);
    let cases = [
        (pow2(31) - 2, Width::I32),
        (pow2(31) - 1, Width::I32),
        (pow2(31), Width::I64),
        (pow2(63) - 2, Width::I64),
        (pow2(63) - 1, Width::I64),
        (pow2(63), Width::I128),
        (pow2(127) - 1, Width::I128),
        (pow2(127), Width::Big),
    ];
    for (m, width) in cases {
        let poly = tall_triangle(&m);
        // The pixels first: a bound too small fails here, in the lanes (a value beyond the
        // planned width), before the plan is read.
        let p = PlannedPolygon::new(&poly, &target).unwrap();
        let want = oracle_fill(&poly, &target);
        assert_eq!(want.covered_pixels(), 15 * 7 + 8, "m = {m}"); // row 0: 0..=7, rows 1..=15: 1..=7
        assert_eq!(planned_fill(Some(&p), &target), want, "m = {m}");
        assert_eq!(p.plan().bound.value, m, "{}", p.plan());
        assert_eq!(
            p.plan().bound.what,
            "the step divisor of contour 0's edge 0, rows 1..=15: its height in units, over the gcd of its width and height"
        );
        assert_eq!(p.plan().width, width, "m = {m}");
        // Every width that holds m gives the same pixels; the narrower ones refuse.
        for w in Width::ALL {
            match PlannedPolygon::forced(&poly, &target, w) {
                Ok(Some(p)) => assert_eq!(planned_fill(Some(&p), &target), want, "{w} m = {m}"),
                Ok(None) => panic!("lost"),
                Err(plan) => assert!(!w.holds(&m) && plan.width == width, "{w} m = {m}"),
            }
        }
    }
}

/// By hand, with a large denominator instead of a large extent: (0,0) -> (1/q, 16) ->
/// (8, 0) with corner samples, so `L = q`; edge 0 in `L` units: dx = 1, dy = 16 q, g = 1,
/// `d = L dy' = 16 q^2`; edge 1 (going up, top (8 q, 0), dx = 1 - 8q, dy = 16 q,
/// gcd(8q - 1, 16 q) = 1 as 8q - 1 is odd and prime to q): also `16 q^2`, found second.
/// q = 11585: 16 q^2 = 2147395600 <= 2^31 - 1 (i32); q = 11586: 2147766336 (i64).
#[test]
fn polygon_i32_boundary_by_denominator() {
    let target = corner_target(16);
    for (q, width) in [(11585i64, Width::I32), (11586, Width::I64)] {
        let poly = Polygon::new(
            vec![
                Point::from_ints(0, 0),
                Point::from_fractions(1, q, 16, 1),
                Point::from_ints(8, 0),
            ],
            FillRule::EvenOdd,
        );
        let p = PlannedPolygon::new(&poly, &target).unwrap();
        assert_eq!(planned_fill(Some(&p), &target), oracle_fill(&poly, &target));
        assert_eq!(p.plan().scale, BigInt::from(q));
        assert_eq!(p.plan().bound.value, BigInt::from(16 * q * q));
        assert_eq!(p.plan().width, width);
    }
}

proptest! {
    #![proptest_config(cfg())]

    /// Every family of the polygon strategies (simple, with holes, tangled, stellated,
    /// tangled with a tangled hole, tie-heavy on the half-pixel grid), both fill rules,
    /// every preset, centre and corner samples.
    #[test]
    fn planned_polygon_equals_oracle(poly in any_polygon(24, 10), preset in preset(), corner in any::<bool>()) {
        check_polygon(&poly, &target_with(24, preset, corner))?;
    }

    /// Unsnapped rational vertices (denominators 3, 7, 256, 1000...), outline and hole.
    #[test]
    fn planned_polygon_equals_oracle_on_rational_vertices(
        poly in rational_polygon(24),
        preset in preset(),
        corner in any::<bool>(),
    ) {
        check_polygon(&poly, &target_with(24, preset, corner))?;
    }

    /// Polygons out of exact Sutherland-Hodgman clipping against rectangles and convex
    /// windows: vertices with large denominators, often i64 or i128 plans.
    #[test]
    fn planned_polygon_equals_oracle_after_clipping(
        poly in prop_oneof![any_polygon(24, 10), rational_polygon(24)],
        window in any_window(24),
        preset in preset(),
        corner in any::<bool>(),
    ) {
        let cut = clip_polygon(&poly, &window);
        check_polygon(&cut, &target_with(24, preset, corner))?;
    }

    /// Under each of the six tie rules the planned fill equals the oracle's in every width
    /// that holds its bound: the directional rules through the edge table, all-inclusive
    /// and all-exclusive through the samples on edges decided apart. Polygons on the
    /// half-pixel grid (samples on edges and vertices everywhere) and with rational
    /// vertices, both fill rules, centre and corner samples.
    #[test]
    fn planned_polygon_equals_oracle_under_every_rule(
        poly in prop_oneof![any_polygon(16, 8), half_grid_polygon()],
        rule in prop::sample::select(AnyTieRule::ALL.to_vec()),
        corner in any::<bool>(),
        width in prop::sample::select(Width::ALL.to_vec()),
    ) {
        let target = target_with(16, Preset::D3d11, corner);
        let mut want = Coverage::new(16, 16);
        rasterize_exact_with(&poly, 0, &target, rule, &mut want);
        let planned = PlannedPolygon::with_rule(&poly, &target, rule);
        prop_assert_eq!(differing_pixels(&want, &planned_fill(planned.as_ref(), &target)), vec![], "{:?} {:?}", rule, poly);
        if let Ok(forced) = PlannedPolygon::forced_with_rule(&poly, &target, rule, width) {
            prop_assert_eq!(differing_pixels(&want, &planned_fill(forced.as_ref(), &target)), vec![], "{:?} in {}", rule, width);
        }
    }

    /// The same on rational vertices (denominators 1, 2, 3, 7, 256, 1000).
    #[test]
    fn planned_polygon_equals_oracle_under_every_rule_on_rational_vertices(
        poly in rational_polygon(12),
        rule in prop::sample::select(AnyTieRule::ALL.to_vec()),
        corner in any::<bool>(),
    ) {
        let target = target_with(12, Preset::D3d11, corner);
        let mut want = Coverage::new(12, 12);
        rasterize_exact_with(&poly, 0, &target, rule, &mut want);
        let planned = PlannedPolygon::with_rule(&poly, &target, rule);
        prop_assert_eq!(differing_pixels(&want, &planned_fill(planned.as_ref(), &target)), vec![], "{:?} {:?}", rule, poly);
    }

    /// Every width on small polygons: all six when the bound is within 2^24.
    #[test]
    fn planned_polygon_every_width(
        poly in prop_oneof![any_polygon(12, 8), rational_polygon(12)],
        preset in preset(),
        corner in any::<bool>(),
    ) {
        check_polygon_every_width(&poly, &target_with(12, preset, corner))?;
    }

    /// Polygons whose vertices lie up to 2^20 px away, crossing a small canvas: the far
    /// edges keep constant thresholds, the plan stays small.
    #[test]
    fn planned_polygon_equals_oracle_far_off(
        far in prop::collection::vec((-(1i64 << 20)..(1i64 << 20), -(1i64 << 20)..(1i64 << 20)), 1..=3),
        near in prop::collection::vec(rational_point(16), 2..=4),
        preset in preset(),
        corner in any::<bool>(),
        even_odd in any::<bool>(),
    ) {
        let mut outline: Vec<Point> = far.iter().map(|&(x, y)| Point::from_ints(x, y)).collect();
        outline.extend(near);
        let rule = if even_odd { FillRule::EvenOdd } else { FillRule::NonZero };
        check_polygon(&Polygon::new(outline, rule), &target_with(16, preset, corner))?;
    }
}

// ---------------------------------------------------------------------------------------
// Lines

fn oracle_line(a: &Point, b: &Point, target: &Target) -> Coverage {
    let mut c = Coverage::new(target.width, target.height);
    rasterize_diamond(a, b, 0, target, &mut c);
    c
}

fn planned_line(p: Option<&PlannedSegment>, target: &Target) -> Coverage {
    let mut c = Coverage::new(target.width, target.height);
    if let Some(p) = p {
        p.rasterize(0, &mut c);
    }
    c
}

fn check_line(a: &Point, b: &Point, target: &Target) -> Result<(), TestCaseError> {
    let planned = PlannedSegment::new(a, b, target);
    let got = planned_line(planned.as_ref(), target);
    let want = oracle_line(a, b, target);
    let plan = planned.as_ref().map(|p| p.plan().to_string());
    prop_assert_eq!(
        differing_pixels(&want, &got),
        vec![],
        "plan {:?}\n{:?} -> {:?}",
        plan,
        a,
        b
    );
    Ok(())
}

fn check_line_every_width(a: &Point, b: &Point, target: &Target) -> Result<(), TestCaseError> {
    let want = oracle_line(a, b, target);
    let Some(plan) = PlannedSegment::new(a, b, target).map(|p| p.plan().clone()) else {
        prop_assert_eq!(want.covered_pixels(), 0);
        return Ok(());
    };
    let fits_f32 = Width::F32.holds(&plan.bound.value);
    for w in Width::ALL {
        match PlannedSegment::forced(a, b, target, w) {
            Ok(Some(p)) => {
                prop_assert_eq!(p.plan().width, w);
                let got = planned_line(Some(&p), target);
                prop_assert_eq!(differing_pixels(&want, &got), vec![], "{} {:?} -> {:?}", w, a, b);
            }
            Ok(None) => prop_assert!(false, "forced lost the segment in {}", w),
            Err(refused) => {
                prop_assert!(!fits_f32, "{} refused a bound within 2^24: {}", w, refused);
                prop_assert_eq!(&refused, &plan);
            }
        }
    }
    Ok(())
}

/// A coordinate up to `2^reach` px from the canvas, with a denominator of 1, 2, 3, 7 or
/// 1000.
fn far_rational(reach: u32) -> impl Strategy<Value = BigRational> {
    (
        prop::sample::select(vec![1i64, 2, 3, 7, 1000]),
        -(1i64 << reach)..(1i64 << reach),
        0i64..1000,
    )
        .prop_map(|(d, whole, frac)| BigRational::new((whole * d + frac % d).into(), d.into()))
}

proptest! {
    #![proptest_config(cfg())]

    /// Rational endpoints in and around the canvas (partly off it), every direction,
    /// every preset, centre and corner samples.
    #[test]
    fn planned_segment_equals_oracle(
        a in rational_point(24),
        b in rational_point(24),
        preset in preset(),
        corner in any::<bool>(),
    ) {
        check_line(&a, &b, &target_with(24, preset, corner))?;
    }

    /// Tie-heavy endpoints: pixel centres, corners, diamond corners, k/512.
    #[test]
    fn planned_segment_equals_oracle_at_ties(line in diamond_line(16), preset in preset(), corner in any::<bool>()) {
        check_line(&line.from, &line.to, &target_with(16, preset, corner))?;
    }

    /// One end near the canvas, the other up to 2^20 px away (or both far, crossing it):
    /// long segments of which only a part is on the canvas.
    #[test]
    fn planned_segment_equals_oracle_far_off(
        near in rational_point(16),
        fx in far_rational(20),
        fy in far_rational(20),
        both_far in any::<bool>(),
        preset in preset(),
        corner in any::<bool>(),
    ) {
        let far = Point::new(fx, fy);
        // both far: the reflection of `far` through `near`, so the segment passes near it
        let a = if both_far {
            Point::new(&near.x * BigRational::from_integer(2.into()) - &far.x, &near.y * BigRational::from_integer(2.into()) - &far.y)
        } else {
            near
        };
        check_line(&a, &far, &target_with(16, preset, corner))?;
        check_line(&far, &a, &target_with(16, preset, corner))?;
    }

    /// Every width on short segments: all six when the bound is within 2^24.
    #[test]
    fn planned_segment_every_width(
        a in rational_point(12),
        b in rational_point(12),
        preset in preset(),
        corner in any::<bool>(),
    ) {
        check_line_every_width(&a, &b, &target_with(12, preset, corner))?;
    }
}

/// A tiny horizontal segment leaving pixel (2, 2)'s diamond: with corner samples the
/// sample is (2, 2), `a = (2, 2) + (u, -w) / L` lies inside the diamond and
/// `b = a + (delta, 0) / L` on its upper-right edge (out of the test area).
fn tiny_exit(l: &BigInt, u: &BigInt, w: i64, delta: i64) -> (Point, Point) {
    let q = |n: BigInt| BigRational::new(n, l.clone());
    let two_l = l * 2;
    let y = q(&two_l - w);
    (
        Point::new(q(&two_l + u), y.clone()),
        Point::new(q(&two_l + u + delta), y),
    )
}

/// By hand, for `tiny_exit` on an 8x8 canvas with corner samples, `L = 2^k + 2` (even, so
/// `r = L/2` is an integer, `c = 0`): `a.y = (2L - w)/L` has denominator `L` (w = 1) or
/// `L/2` (w = 2, odd), and with the radius's 2 the scale is exactly `L`.
/// - Major (x) indices: `ceil((2L + u - r)/L) = 2` to `floor((2L + u + delta + r)/L) = 2`
///   (as `u + delta < r`): one column, K = 0. `j0 = floor((2L - w - r)/L) = 1`: rows 1
///   and 2. Local origin (2L, L): `a = (u, L - w)`, `b = (u + delta, L - w)`; the tested
///   box is x in [0, 0], y in [0, L].
/// - `UA = u`, `VA = L - w`, `UB = u + delta`, `VB = L - w`; `G = delta`, `D = L`.
/// - Terms: `UA + VA + r = 3L/2 + u - w`; `UB + VB = L + u + delta - w` (smaller by
///   `r - delta`); endpoint `L - w`; sample `L`; `G^2 <= 4`; `(|dx| + r) G <= L + 4`;
///   `(|dy| + r) G <= L`. So the bound is `3L/2 + u - w`, and it is reached: at pixel
///   (2, 1) the plane (-1, -1) has `g1 = -delta < 0` and the test computes
///   `n = g0 - r = -(u + L - w) - r`.
/// - Inside: `u + w <= r - 1`; `b` on the edge: `u + delta + w = r`.
///
/// With `L = 2^30 + 2` (`3L/2 = 2^31 - 2^29 + 3`, `r = 2^29 + 1`):
/// `(u, w, delta) = (r - 4, 2, 2)`: `2L - 6 = 2^31 - 2`; `(r - 3, 2, 1)`: `2L - 5 = 2^31 - 1`;
/// `(r - 3, 1, 2)`: `2L - 4 = 2^31`. With `L = 2^62 + 2` the same give `2^63 - 2`,
/// `2^63 - 1`, `2^63`. Each draws pixel (2, 2) alone.
#[test]
fn segment_width_boundaries_by_hand() {
    let target = corner_target(8);
    for (k, narrow, wide) in [(30u32, Width::I32, Width::I64), (62, Width::I64, Width::I128)] {
        let l = pow2(k) + 2;
        let r = &l / 2;
        let limit = narrow.limit().unwrap();
        let cases = [
            (&r - 4, 2, 2, &limit - 1, narrow),
            (&r - 3, 2, 1, limit.clone(), narrow),
            (&r - 3, 1, 2, &limit + 1, wide),
        ];
        for (u, w, delta, bound, width) in cases {
            let (a, b) = tiny_exit(&l, &u, w, delta);
            // The pixels first: a bound too small fails here, in the planned width's
            // arithmetic (overflow checks are on in tests), before the plan is read.
            let p = PlannedSegment::new(&a, &b, &target).unwrap();
            let want = oracle_line(&a, &b, &target);
            assert_eq!(want.iter().map(|(x, y, _)| (x, y)).collect::<Vec<_>>(), vec![(2, 2)]);
            assert_eq!(planned_line(Some(&p), &target), want);
            assert_eq!(p.plan().scale, l);
            assert_eq!(p.plan().bound.value, bound, "{}", p.plan());
            assert_eq!(p.plan().bound.what, "|ua| + |va| + r at a tested sample");
            assert_eq!(p.plan().width, width, "{}", p.plan());
            for w in Width::ALL {
                match PlannedSegment::forced(&a, &b, &target, w) {
                    Ok(Some(p)) => assert_eq!(planned_line(Some(&p), &target), want, "{w}"),
                    Ok(None) => panic!("lost"),
                    Err(plan) => assert!(!w.holds(&bound) && plan == *p.plan(), "{w}"),
                }
            }
        }
    }
}

/// The positive side, by hand: `a = (2, 2) + (0, 1 - r) / L` (just below the top corner of
/// pixel (2, 2)'s diamond, corner samples, `L` even) and `b = a - (1, 0) / L` on its
/// upper-left edge (out), so the segment leaves the diamond and draws (2, 2). One column
/// (K = 0), rows 1 and 2, local origin (2L, L): `a = (0, r + 1)`, `b = (-1, r + 1)`,
/// `UA = 0`, `VA = r + 1`, `UB = 1`, `VB = r + 1`, `G = 1`, `D = L`. The largest term is
/// `UA + VA + r = L + 1`, and here the test reaches it with a plus sign: at pixel (2, 1)
/// the plane (-1, -1) has `g1 = -dx - dy = 1 > 0`, `g0 = -(r + 1)`, `n = r - g0 = L + 1`.
/// `L = 2^31 - 2` gives `2^31 - 1` (i32's limit, held); `L = 2^31` gives `2^31 + 1` (i64).
#[test]
fn segment_width_boundary_reached_positively() {
    let target = corner_target(8);
    for (l, width) in [
        (pow2(31) - 2, Width::I32),
        (pow2(31), Width::I64),
        (pow2(63), Width::I128),
    ] {
        let r = &l / 2;
        let q = |n: BigInt| BigRational::new(n, l.clone());
        let two_l: BigInt = &l * 2u32;
        let y = q(&two_l + 1u32 - &r);
        let (a, b) = (Point::new(q(two_l.clone()), y.clone()), Point::new(q(&two_l - 1u32), y));
        let p = PlannedSegment::new(&a, &b, &target).unwrap();
        let want = oracle_line(&a, &b, &target);
        assert_eq!(want.iter().map(|(x, y, _)| (x, y)).collect::<Vec<_>>(), vec![(2, 2)]);
        assert_eq!(planned_line(Some(&p), &target), want);
        assert_eq!(p.plan().scale, l);
        assert_eq!(p.plan().bound.value, &l + 1, "{}", p.plan());
        assert_eq!(p.plan().bound.what, "|ua| + |va| + r at a tested sample");
        assert_eq!(p.plan().width, width, "{}", p.plan());
    }
}
