//! The planned exact engine for triangles equals the plain oracle, pixel for pixel: on
//! every triangle family, as written and snapped, every preset, both sample positions,
//! unsnapped rational vertices (denominators 3, 7, 1000, large primes), every width forced,
//! and at each width's boundary (a hand-derived bound one coordinate unit below and above
//! the limit). Regressions land in proptest-regressions/.

use crate::common;

use common::config;
use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;
use proptest::test_runner::Config;
use rasterproof::convention::{Convention, PixelCentre, Preset, Target, MAX_CANVAS};
use rasterproof::coverage::{Coverage, CoverageSink};
use rasterproof::geom::{Point, Triangle};
use rasterproof::model::{prepare, render_triangles, Model, Primitives};
use rasterproof::num::plan::Width;
use rasterproof::strategy::{any_triangle, tie_heavy_triangle, triangle, TriangleScale};
use rasterproof::tri::exact;
use rasterproof::tri::planned::PlannedTriangle;

const CANVAS: u32 = 24;
/// A canvas wide enough for runs of 8x8 blocks.
const WIDE: u32 = 96;

fn convention() -> impl Strategy<Value = Convention> {
    (prop::sample::select(Preset::ALL.to_vec()), any::<bool>()).prop_map(|(p, corner)| {
        let mut c = p.convention();
        if corner {
            c.pixel_centre = PixelCentre::Corner;
        }
        c
    })
}

fn oracle(t: &Triangle, target: &Target) -> Coverage {
    let mut c = Coverage::new(target.width, target.height);
    exact::rasterize(t, 0, target, &mut c);
    c
}

fn planned(t: &Triangle, target: &Target) -> Coverage {
    let mut c = Coverage::new(target.width, target.height);
    if let Some(p) = PlannedTriangle::new(t, target) {
        p.rasterize(0, &mut c);
    }
    c
}

fn same(t: &Triangle, target: &Target) -> Result<(), TestCaseError> {
    let (a, b) = (oracle(t, target), planned(t, target));
    let width = PlannedTriangle::new(t, target).map(|p| p.plan().to_string());
    prop_assert_eq!(a, b, "plan {:?}", width);
    Ok(())
}

/// A coordinate `n / d` with a denominator that is not a power of two.
fn rational(canvas: i64) -> impl Strategy<Value = BigRational> {
    let den = prop::sample::select(vec![1i64, 3, 7, 1000, 1_000_003, 2_147_483_647, 1 << 40]);
    (den, -2i64..canvas + 2, any::<u32>()).prop_map(|(d, whole, frac)| {
        let n = BigInt::from(whole) * d + BigInt::from(frac) % d;
        BigRational::new(n, d.into())
    })
}

fn rational_triangle(canvas: i64) -> impl Strategy<Value = Triangle> {
    prop::array::uniform6(rational(canvas))
        .prop_map(|[a, b, c, d, e, f]| Triangle::new(Point::new(a, b), Point::new(c, d), Point::new(e, f)))
}

proptest! {
    #![proptest_config(config("proptest-regressions/planned.txt"))]

    /// As written and snapped, every family, every preset, both sample positions.
    #[test]
    fn planned_equals_plain(t in any_triangle(CANVAS), conv in convention()) {
        let target = Target::new(CANVAS, CANVAS, conv).unwrap();
        same(&t, &target)?;
        same(&t.snapped(&conv).to_exact(), &target)?;
    }

    /// Small triangles near the far corner of the largest canvas.
    #[test]
    fn planned_equals_plain_far_from_origin(t in triangle(TriangleScale::FarFromOrigin, MAX_CANVAS), conv in convention()) {
        let target = Target::new(MAX_CANVAS, MAX_CANVAS, conv).unwrap();
        same(&t, &target)?;
    }

    /// Vertices with denominators 3, 7, 1000, large primes and 2^40: the scale is their
    /// least common multiple, and the plan ranges from i32 to bigint.
    #[test]
    fn planned_equals_plain_on_rational_vertices(t in rational_triangle(i64::from(CANVAS)), conv in convention()) {
        let target = Target::new(CANVAS, CANVAS, conv).unwrap();
        same(&t, &target)?;
    }

    /// Every width that holds the bound, forced, equals the oracle (most tie-heavy
    /// triangles of a 12x12 canvas have bounds below 2^24, so all six widths run them).
    #[test]
    fn every_width_equals_plain(t in tie_heavy_triangle(12), conv in convention()) {
        let target = Target::new(12, 12, conv).unwrap();
        let want = oracle(&t, &target);
        for width in Width::ALL {
            let mut got = Coverage::new(12, 12);
            match PlannedTriangle::forced(&t, &target, width) {
                Ok(p) => p.iter().for_each(|p| p.rasterize(0, &mut got)),
                // refused: only when the bound is truly beyond the width's limit
                Err(plan) => {
                    prop_assert!(plan.bound.value > width.limit().unwrap(), "{} refused {}", width, plan);
                    continue;
                }
            }
            prop_assert_eq!(&got, &want, "width {}", width);
        }
    }

    /// The model names: `exact` / `exact-snapped` (planned) equal `exact-plain` /
    /// `exact-snapped-plain` on whole scenes (several triangles, ids).
    #[test]
    fn models_equal_their_plain_oracles(ts in prop::collection::vec(any_triangle(CANVAS), 1..5), conv in convention()) {
        let target = Target::new(CANVAS, CANVAS, conv).unwrap();
        for (planned, plain) in [(Model::Exact, Model::ExactPlain), (Model::ExactSnapped, Model::ExactSnappedPlain)] {
            prop_assert_eq!(
                render_triangles(&ts, &target, planned).unwrap(),
                render_triangles(&ts, &target, plain).unwrap()
            );
        }
    }
}

/// A [`Coverage`] behind a sink that prefers masks: the block traversals hand it their
/// masks ([`CoverageSink::cover_block`]), where a plain `Coverage` (a sink of spans) gets
/// pixels and spans.
struct Masks<'a>(&'a mut Coverage);

impl CoverageSink for Masks<'_> {
    fn cover(&mut self, x: u32, y: u32, id: u32) {
        self.0.cover(x, y, id);
    }

    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, id: u32) {
        self.0.cover_span(y, x0, x1, id);
    }

    fn prefers_masks(&self) -> bool {
        true
    }
}

/// What a sink of spans was handed, call by call.
#[derive(Default)]
struct Calls {
    pixels: usize,
    spans: Vec<(u32, u32, u32)>,
    masks: usize,
}

impl CoverageSink for Calls {
    fn cover(&mut self, _: u32, _: u32, _: u32) {
        self.pixels += 1;
    }

    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, _: u32) {
        self.spans.push((y, x0, x1));
    }

    fn cover_mask(&mut self, _: u32, _: u32, _: u32, _: u32) {
        self.masks += 1;
    }

    fn cover_block(&mut self, _: u32, _: u32, _: u64, _: u32) {
        self.masks += 1;
    }
}

/// `model`'s coverage of `ts` through a sink of spans and through one that prefers masks.
fn both_sinks(ts: &[Triangle], target: &Target, model: Model) -> (Coverage, Coverage) {
    let prepared = prepare(&Primitives::from_triangles(ts), target, model).unwrap();
    let (mut spans, mut masks) = (
        Coverage::new(target.width, target.height),
        Coverage::new(target.width, target.height),
    );
    prepared.render(target, &mut spans);
    prepared.render(target, &mut Masks(&mut masks));
    (spans, masks)
}

/// A coordinate on the 2^-k grid for k up to 10: on the 8-bit subpixel grid or off it.
fn dyadic(canvas: i64) -> impl Strategy<Value = BigRational> {
    (0u32..=10, -2i64..canvas + 2, any::<u16>()).prop_map(|(k, whole, frac)| {
        let den = 1i64 << k;
        BigRational::new(BigInt::from(whole * den + i64::from(frac) % den), BigInt::from(den))
    })
}

proptest! {
    // 64 cases: each draws a triangle of up to 96x72 pixels with the plain oracle three
    // times (about 20 s at 256 cases in a fresh clone's test build).
    #![proptest_config(Config { cases: 64, ..config("proptest-regressions/planned.txt") })]

    /// Triangles at least four blocks wide (the traversal writes each row of a run of
    /// inside blocks as one span), as written and snapped, and the fixed model on them.
    #[test]
    fn wide_triangles_equal_plain(t in any_triangle(WIDE), conv in convention()) {
        let target = Target::new(WIDE, WIDE * 3 / 4, conv).unwrap();
        same(&t, &target)?;
        let snapped = t.snapped(&conv);
        same(&snapped.to_exact(), &target)?;
        let mut fixed = Coverage::new(target.width, target.height);
        rasterproof::tri::fixed::rasterize(&snapped.to_fixed().unwrap(), 0, &target, &mut fixed);
        prop_assert_eq!(fixed, oracle(&snapped.to_exact(), &target));
    }
}

proptest! {
    // 48 cases of up to 3 triangles on the wide canvas, each drawn by four models through
    // two sinks and by the plain oracles.
    #![proptest_config(Config { cases: 48, ..config("proptest-regressions/planned.txt") })]

    /// The traversal depends on the sink (masks for a sink that prefers them; pixels,
    /// spans per row and the scanline walk for a sink of spans) and on the triangle (the
    /// planned engine draws a triangle on the subpixel grid with the integer engine):
    /// every model that chooses covers the oracle's pixels through both kinds of sink, on
    /// triangles of every size, on and off the grid, across the one-block threshold.
    #[test]
    fn every_traversal_equals_the_oracle(
        ts in prop::collection::vec(prop_oneof![
            any_triangle(WIDE),
            prop::array::uniform6(dyadic(i64::from(WIDE))).prop_map(|c| {
                let [a, b, c, d, e, f] = c;
                Triangle::new(Point::new(a, b), Point::new(c, d), Point::new(e, f))
            }),
        ], 1..4),
        conv in convention(),
    ) {
        let target = Target::new(WIDE, WIDE, conv).unwrap();
        for (model, plain) in [
            (Model::Exact, Model::ExactPlain),
            (Model::ExactSnapped, Model::ExactSnappedPlain),
            (Model::Fixed, Model::ExactSnappedPlain),
            (Model::Scanline, Model::ExactSnappedPlain),
        ] {
            let want = render_triangles(&ts, &target, plain).unwrap();
            let (spans, masks) = both_sinks(&ts, &target, model);
            prop_assert_eq!(&spans, &want, "{:?} through a sink of spans", model);
            prop_assert_eq!(&masks, &want, "{:?} through a sink of masks", model);
        }
    }
}

/// A sink of spans gets what suits it: a large triangle one span per covered row and no
/// mask, a triangle within one block its pixels one by one; a sink that prefers masks gets
/// masks. Counted by hand: the right triangle (0,0) (40,0) (0,40) at pixel centres covers
/// row `y` from 0 to `38 - y` (the hypotenuse's samples `x + y = 39` are outside under
/// top-left: the interior lies above it and to its left) for `y` 0..=38; the one at
/// (0,0) (4,0) (0,4), within one block, covers `x + y <= 2`: 3 + 2 + 1 = 6 pixels; the
/// tall one (0,0) (4,0) (0,40), four pixels wide but more than a block tall, covers
/// `10 (x + 1/2) + (y + 1/2) <= 40`, so row `y` from 0 to `(34 - y) / 10` for `y` 0..=34
/// (no sample lies on its long edge).
#[test]
fn a_sink_gets_the_calls_that_suit_it() {
    let target = Target::new(64, 64, Preset::Cts.convention()).unwrap();
    let right = |n: i64| Triangle::new(Point::from_ints(0, 0), Point::from_ints(n, 0), Point::from_ints(0, n));
    for model in [Model::Fixed, Model::ExactSnapped, Model::Exact] {
        let calls = |t: Triangle| {
            let prepared = prepare(&Primitives::from_triangles(&[t]), &target, model).unwrap();
            let mut calls = Calls::default();
            prepared.render(&target, &mut calls);
            calls
        };
        let large = calls(right(40));
        let rows: Vec<(u32, u32, u32)> = (0..=38).map(|y| (y, 0, 38 - y)).collect();
        assert_eq!((large.pixels, large.masks, large.spans), (0, 0, rows), "{model:?}");
        let small = calls(right(4));
        assert_eq!((small.pixels, small.masks, small.spans.len()), (6, 0, 0), "{model:?}");
        let tall = calls(Triangle::new(
            Point::from_ints(0, 0),
            Point::from_ints(4, 0),
            Point::from_ints(0, 40),
        ));
        let rows: Vec<(u32, u32, u32)> = (0..=34).map(|y| (y, 0, (34 - y) / 10)).collect();
        assert_eq!((tall.pixels, tall.masks, tall.spans), (0, 0, rows), "{model:?}");
    }
}

/// The triangle (0,0) (n,0) (0,n) on a 1x1 canvas: one sample, (1/2, 1/2), so no step is
/// taken and the bound is the largest `|E - bias|` there. Scale L = 2, vertices relative
/// to the sample (-1,-1), (2n-1,-1), (-1,2n-1); oriented (E_ab(c) = -4n^2 < 0, b and c
/// swap) the hypotenuse runs (-1,2n-1) -> (2n-1,-1): dx = 2n, dy = -2n, not inclusive
/// under top-left, and at the sample E = a.y dx - a.x dy = (2n-1) 2n - 2n = 4n^2 - 4n,
/// bias 1: E - bias = 4n^2 - 4n - 1. The other two edges have E = 2n. Bound:
/// 4n^2 - 4n - 1.
fn corner_triangle(n: i64) -> Triangle {
    Triangle::new(Point::from_ints(0, 0), Point::from_ints(n, 0), Point::from_ints(0, n))
}

/// Its mirror image on an N x N canvas, (N,N) (N-n,N) (N,N-n): the largest value now sits
/// at the last pixel, (N-1, N-1), reached by additions only. Point reflection keeps every
/// E value at the mirrored sample, and turns the hypotenuse into an edge with dx < 0,
/// dy > 0, inclusive (bias 0): the bound is 4n^2 - 4n.
fn mirrored_triangle(n: i64, side: i64) -> Triangle {
    Triangle::new(
        Point::from_ints(side, side),
        Point::from_ints(side - n, side),
        Point::from_ints(side, side - n),
    )
}

/// `(n, expected width below, expected width above)`: the largest n whose bound fits the
/// limit, found by hand from the bounds above.
/// - i32, limit 2^31 - 1: 4n^2 - 4n - 1 <= 2^31 - 1 iff n^2 - n <= 2^29 = 536870912;
///   23170^2 - 23170 = 536825730 fits, 23171^2 - 23171 = 536872070 does not (and the
///   mirrored 4n^2 - 4n <= 2^31 - 1 gives the same n).
/// - i64, limit 2^63 - 1: n^2 - n <= 2^61 = 2305843009213693952; n = 1518500250:
///   n^2 - n = 2305843007731562250 fits; n = 1518500251: 2305843010768562750 does not.
/// - i128, limit 2^127 - 1: n^2 - n <= 2^125 = 42535295865117307932921825928971026432;
///   n = 6521908912666391106 gives n^2 - n = 42535295865117307924120041537489512130 fits,
///   n + 1 gives 42535295865117307937163859362822294342 > 2^125.
const BOUNDARIES: [(i64, Width, Width); 3] = [
    (23170, Width::I32, Width::I64),
    (1_518_500_250, Width::I64, Width::I128),
    (6_521_908_912_666_391_106, Width::I128, Width::Big),
];

#[test]
fn each_width_boundary_by_hand() {
    let one = Target::new(1, 1, Convention::default()).unwrap();
    let side = 16;
    let sixteen = Target::new(side as u32, side as u32, Convention::default()).unwrap();
    for (n, below, above) in BOUNDARIES {
        for (n, width) in [(n, below), (n + 1, above)] {
            let nn = BigInt::from(n);
            let corner = corner_triangle(n);
            let p = PlannedTriangle::new(&corner, &one).unwrap();
            assert_eq!(p.plan().bound.value, &nn * &nn * 4 - &nn * 4 - 1, "n={n}");
            assert_eq!(p.plan().width, width, "n={n}");
            assert_eq!(planned(&corner, &one), oracle(&corner, &one), "n={n}");
            let mirrored = mirrored_triangle(n, side);
            let p = PlannedTriangle::new(&mirrored, &sixteen).unwrap();
            assert_eq!(p.plan().bound.value, &nn * &nn * 4 - &nn * 4, "n={n}");
            assert_eq!(p.plan().bound.what, "edge 1 at pixel (15, 15)", "n={n}");
            assert_eq!(p.plan().width, width, "n={n}");
            assert_eq!(planned(&mirrored, &sixteen), oracle(&mirrored, &sixteen), "n={n}");
        }
    }
}

/// The floats' limits, forced: 4n^2 - 4n <= 2^24 iff n^2 - n <= 2^22 = 4194304; n = 2048:
/// 4192256 fits, n = 2049: 4196352 does not. 2^53: n^2 - n <= 2^51 =
/// 2251799813685248; n = 47453133: 2251799784062556 fits; n = 47453134: 2251799878968822
/// does not.
#[test]
fn float_width_boundaries_by_hand() {
    let side = 16;
    let target = Target::new(side as u32, side as u32, Convention::default()).unwrap();
    for (n, width) in [(2048, Width::F32), (47_453_133, Width::F64)] {
        let fits = mirrored_triangle(n, side);
        let p = PlannedTriangle::forced(&fits, &target, width).unwrap().unwrap();
        let mut got = Coverage::new(16, 16);
        p.rasterize(0, &mut got);
        assert_eq!(got, oracle(&fits, &target), "{width} n={n}");
        assert!(
            PlannedTriangle::forced(&mirrored_triangle(n + 1, side), &target, width).is_err(),
            "{width} n={}",
            n + 1
        );
    }
}

/// A triangle is planned on its extent, not its position: the same shape at the origin
/// and at the far corner of the largest canvas has the same bound (coordinates are taken
/// relative to its first sample).
#[test]
fn position_does_not_widen_the_plan() {
    let target = Target::new(MAX_CANVAS, MAX_CANVAS, Convention::default()).unwrap();
    let at = |x: i64, y: i64| {
        Triangle::new(
            Point::from_fractions(x * 256 + 3, 256, y * 256, 256),
            Point::from_fractions(x * 256 + 7 * 256, 256, y * 256 + 100, 256),
            Point::from_fractions(x * 256 + 2 * 256 + 1, 256, y * 256 + 6 * 256, 256),
        )
    };
    let far = i64::from(MAX_CANVAS) - 10;
    let (p, q) = (
        PlannedTriangle::new(&at(0, 0), &target).unwrap(),
        PlannedTriangle::new(&at(far, far), &target).unwrap(),
    );
    assert_eq!(p.plan().bound.value, q.plan().bound.value);
    assert_eq!(q.plan().width, Width::I32);
    assert_eq!(planned(&at(far, far), &target), oracle(&at(far, far), &target));
}
