//! Lines: seed 001's worked examples and hand-derived diamond-exit cases (golden), and the
//! line invariants as properties (256 cases each by default).

use crate::common;

use common::config;
use proptest::prelude::*;
use rasterproof::check::{
    check_diamond_agreement, check_line_pixels, check_line_reference, check_line_symmetry, line_departures,
};
use rasterproof::convention::{PixelCentre, Preset, Target};
use rasterproof::geom::Point;
use rasterproof::line::{bresenham, dda, BresenhamTie, Line, LineRule};
use rasterproof::model::{render, Model, Primitives};
use rasterproof::strategy::{diamond_line, long_pixel_line, pixel_line};

const TIES: [BresenhamTie; 2] = [BresenhamTie::Stay, BresenhamTie::Step];

/// A symmetry of the pixel grid.
type Reflection = Box<dyn Fn([i64; 2]) -> [i64; 2]>;

/// The 8 symmetries of the square grid: (x, y) -> (±x, ±y), optionally swapped.
fn reflections() -> Vec<Reflection> {
    let mut out: Vec<Reflection> = Vec::new();
    for swap in [false, true] {
        for sx in [1, -1] {
            for sy in [1, -1] {
                out.push(Box::new(move |[x, y]: [i64; 2]| {
                    let (x, y) = (sx * x, sy * y);
                    if swap {
                        [y, x]
                    } else {
                        [x, y]
                    }
                }));
            }
        }
    }
    out
}

/// Seed 001: (5,8) -> (9,11), dx = 4, dy = 3: d = 2 (NE), 0 (E: ties go E), 6 (NE), 4 (NE).
#[test]
fn seed001_worked_example() {
    let mut steps = Vec::new();
    bresenham::walk([5, 8], [9, 11], BresenhamTie::Stay, |p, d| steps.push((p, d)));
    assert_eq!(
        steps,
        vec![
            ([5, 8], Some(2)),
            ([6, 9], Some(0)),
            ([7, 9], Some(6)),
            ([8, 10], Some(4)),
            ([9, 11], None)
        ]
    );
    // Seed 002's convention steps at the tie instead: (7, 10) after (6, 9)... no: the tie is
    // the decision *after* (6, 9), so (7, 9) becomes (7, 10).
    assert_eq!(
        bresenham::pixels([5, 8], [9, 11], BresenhamTie::Step),
        vec![[5, 8], [6, 9], [7, 10], [8, 10], [9, 11]]
    );
}

/// Seed 001's other demonstrations, derived by hand from the ideal lines, in all eight
/// reflections of the grid.
/// (0,4) -> (4,2): y = 4 - x/2: x=1 gives 3.5 and x=3 gives 2.5, both ties.
///   stay (keep y at a tie): (0,4) (1,4) (2,3) (3,3) (4,2); step: (0,4) (1,3) (2,3) (3,2) (4,2).
/// (1,2) -> (3,6): x = 1 + (y-2)/2: y=3 gives 1.5 and y=5 gives 2.5, ties.
///   stay: (1,2) (1,3) (2,4) (2,5) (3,6); step: (1,2) (2,3) (2,4) (3,5) (3,6).
#[test]
fn seed001_demonstrations_in_all_reflections() {
    type Case = ([i64; 2], [i64; 2], BresenhamTie, Vec<[i64; 2]>);
    let cases: [Case; 4] = [
        (
            [0, 4],
            [4, 2],
            BresenhamTie::Stay,
            vec![[0, 4], [1, 4], [2, 3], [3, 3], [4, 2]],
        ),
        (
            [0, 4],
            [4, 2],
            BresenhamTie::Step,
            vec![[0, 4], [1, 3], [2, 3], [3, 2], [4, 2]],
        ),
        (
            [1, 2],
            [3, 6],
            BresenhamTie::Stay,
            vec![[1, 2], [1, 3], [2, 4], [2, 5], [3, 6]],
        ),
        (
            [1, 2],
            [3, 6],
            BresenhamTie::Step,
            vec![[1, 2], [2, 3], [2, 4], [3, 5], [3, 6]],
        ),
    ];
    for (a, b, tie, expected) in cases {
        for t in reflections() {
            let want: Vec<[i64; 2]> = expected.iter().map(|&p| t(p)).collect();
            assert_eq!(
                bresenham::pixels(t(a), t(b), tie),
                want,
                "{a:?} -> {b:?} {tie:?} reflected to {:?} -> {:?}",
                t(a),
                t(b)
            );
        }
    }
}

#[test]
fn zero_length_lines() {
    assert_eq!(bresenham::pixels([3, 3], [3, 3], BresenhamTie::Stay), vec![[3, 3]]);
    let target = Target::new(8, 8, Preset::D3d11.convention()).unwrap();
    let p = Point::from_fractions(7, 2, 7, 2);
    let point = Line {
        from: p.clone(),
        to: p,
        rule: LineRule::Diamond,
    };
    for model in [Model::Exact, Model::ExactSnapped, Model::Fixed] {
        assert_eq!(
            render(
                &Primitives {
                    lines: vec![point.clone()],
                    ..Primitives::default()
                },
                &target,
                model
            )
            .unwrap()
            .covered_pixels(),
            0,
            "{model}"
        );
    }
}

fn diamond(a: (i64, i64, i64, i64), target: &Target) -> Vec<(u32, u32)> {
    let (x0, y0, x1, y1) = a; // in half pixels
    let line = Line {
        from: Point::from_fractions(x0, 2, y0, 2),
        to: Point::from_fractions(x1, 2, y1, 2),
        rule: LineRule::Diamond,
    };
    let exact = render(
        &Primitives {
            lines: vec![line.clone()],
            ..Primitives::default()
        },
        target,
        Model::Exact,
    )
    .unwrap();
    let fixed = render(
        &Primitives {
            lines: vec![line],
            ..Primitives::default()
        },
        target,
        Model::Fixed,
    )
    .unwrap();
    assert_eq!(exact, fixed);
    exact.iter().map(|(x, y, _)| (x, y)).collect()
}

/// Hand-derived diamond-exit cases (D3D11 §3.4.3: the test area is the open diamond plus
/// the lower-left and lower-right edges and the bottom corner; y-major lines add the right
/// corner). Coordinates in half pixels.
#[test]
fn diamond_exit_by_hand() {
    let t = Target::new(8, 8, Preset::D3d11.convention()).unwrap();
    // (a) Through the centres of row 0, from the centre of (0,0) to the centre of (4,0): it
    // leaves the diamonds of (0,0)..(3,0); it ends inside (4,0)'s, which is not drawn.
    assert_eq!(diamond((1, 1, 9, 1), &t), vec![(0, 0), (1, 0), (2, 0), (3, 0)]);
    // (b) Along y = 1, the row boundary: through the bottom corners of row 0's diamonds
    // (in) and the top corners of row 1's (out). The end (4.5, 1) is (4,0)'s bottom corner.
    assert_eq!(diamond((1, 2, 9, 2), &t), vec![(0, 0), (1, 0), (2, 0), (3, 0)]);
    // (c) Along x = 1, y-major: through the right corners of column 0 (in, for y-major) and
    // the left corners of column 1 (out).
    assert_eq!(diamond((2, 1, 2, 9), &t), vec![(0, 0), (0, 1), (0, 2), (0, 3)]);
    // (d) The diagonal y = x - 1/2 from (1, 1/2) to (3, 5/2), x-major (|dx| = |dy|). It runs
    // along the lower-left edges (in) of (1,0) and (2,1), and along the upper-right edges
    // (out) of (1,1) and (2,2); it touches (0,0) only at its right corner (out for x-major)
    // and ends on the left corner of (3,2) (out).
    assert_eq!(diamond((2, 1, 6, 5), &t), vec![(1, 0), (2, 1)]);
    // (e) The same diagonal reversed: now it ends on the right corner of (0,0) (out) and
    // starts on (3,2)'s left corner (out): the same two diamonds are left.
    assert_eq!(diamond((6, 5, 2, 1), &t), vec![(1, 0), (2, 1)]);
}

/// Samples at pixel corners (D3D9 style) move every diamond by half a pixel.
#[test]
fn diamond_exit_with_corner_samples() {
    let mut conv = Preset::D3d11.convention();
    conv.pixel_centre = PixelCentre::Corner;
    let t = Target::new(8, 8, conv).unwrap();
    // Through the samples (0,0)..(4,0) at y = 0: the same shape as case (a), shifted.
    assert_eq!(diamond((0, 0, 8, 0), &t), vec![(0, 0), (1, 0), (2, 0), (3, 0)]);
}

proptest! {
    #![proptest_config(config("proptest-regressions/lines.txt"))]

    /// Bresenham: count, endpoints, 8-connected, no repeats, within 1/2 of the ideal line,
    /// equal to the exact reference with its tie convention, all octants.
    #[test]
    fn bresenham_holds_every_line_invariant((a, b) in pixel_line(40, 40), stay in any::<bool>()) {
        let tie = if stay { BresenhamTie::Stay } else { BresenhamTie::Step };
        let pixels = bresenham::pixels(a, b, tie);
        check_line_pixels(a, b, &pixels).map_err(|v| TestCaseError::fail(v.to_string()))?;
        check_line_reference(a, b, tie, &pixels).map_err(|v| TestCaseError::fail(v.to_string()))?;
    }

    /// a -> b and b -> a differ only at exact ties.
    #[test]
    fn bresenham_reversal_differs_only_at_ties((a, b) in pixel_line(40, 40), stay in any::<bool>()) {
        let tie = if stay { BresenhamTie::Stay } else { BresenhamTie::Step };
        let report = check_line_symmetry(a, b, tie).map_err(|v| TestCaseError::fail(v.to_string()))?;
        prop_assert!(report.differing.len() <= report.ties);
    }

    /// Reflecting the endpoints reflects the pixels (the tie conventions are defined by the
    /// direction of travel, so they commute with the grid's symmetries).
    #[test]
    fn bresenham_commutes_with_reflections((a, b) in pixel_line(30, 30)) {
        for tie in TIES {
            let base = bresenham::pixels(a, b, tie);
            for t in reflections() {
                let want: Vec<[i64; 2]> = base.iter().map(|&p| t(p)).collect();
                prop_assert_eq!(bresenham::pixels(t(a), t(b), tie), want);
            }
        }
    }

    /// The exact model draws the reference, the integer model draws Bresenham: equal.
    #[test]
    fn exact_and_integer_bresenham_render_alike((a, b) in pixel_line(24, 8), stay in any::<bool>()) {
        let tie = if stay { BresenhamTie::Stay } else { BresenhamTie::Step };
        let line = Line { from: Point::from_ints(a[0], a[1]), to: Point::from_ints(b[0], b[1]), rule: LineRule::Bresenham(tie) };
        let target = Target::new(24, 24, Preset::D3d11.convention()).unwrap();
        let exact = render(&Primitives { lines: vec![line.clone()], ..Primitives::default() }, &target, Model::Exact).unwrap();
        let fixed = render(&Primitives { lines: vec![line], ..Primitives::default() }, &target, Model::Fixed).unwrap();
        prop_assert_eq!(exact, fixed);
    }

    /// Diamond-exit: the integer model equals the exact reading, on tie-heavy endpoints, for
    /// every preset.
    #[test]
    fn diamond_integer_equals_exact_reading(line in diamond_line(12), p in prop::sample::select(Preset::ALL.to_vec())) {
        let target = Target::new(12, 12, p.convention()).unwrap();
        check_diamond_agreement(&line, Model::Fixed, &target).map_err(|v| TestCaseError::fail(v.to_string()))?;
    }

    /// Diamond-exit on long lines far off the canvas on one side: only the candidate walk
    /// differs from the bounding-box scan, and it must not miss anything.
    #[test]
    fn diamond_integer_equals_exact_on_long_lines(
        x0 in -4000i64..4000, y0 in -4000i64..4000, x1 in -4000i64..4000, y1 in -4000i64..4000,
    ) {
        let line = Line { from: Point::from_fractions(x0, 256, y0 * 3, 256), to: Point::from_fractions(x1 * 2, 256, y1, 256), rule: LineRule::Diamond };
        let target = Target::new(40, 40, Preset::D3d11.convention()).unwrap();
        check_diamond_agreement(&line, Model::Fixed, &target).map_err(|v| TestCaseError::fail(v.to_string()))?;
    }
}

/// The DDA's departures from the ideal line, by coordinate magnitude: the harness must find
/// them for f32 far from the origin (f32 has no fraction bits left above 2^23), and f64
/// must stay clean there. Rates are printed for the notes.
#[test]
fn dda_departures_by_magnitude() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
    let mut runner = TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &[5; 32]));
    let mut f32_far = 0;
    for (origin, max_len) in [(0i64, 100i64), (0, 1000), (1 << 20, 1000), (1 << 23, 1000)] {
        let strategy = long_pixel_line(origin, max_len / 2);
        let (mut lines, mut px, mut dep32, mut dep64) = (0, 0, 0, 0);
        for _ in 0..40 {
            let (a, b) = strategy.new_tree(&mut runner).unwrap().current();
            lines += 1;
            px += bresenham::pixels(a, b, BresenhamTie::Stay).len();
            dep32 += line_departures(a, b, &dda::pixels_f32(a, b));
            dep64 += line_departures(a, b, &dda::pixels_f64(a, b));
        }
        println!("DDA at |coord| ~ {origin}, length <= {max_len}: {lines} lines, {px} px: f32 {dep32} departures, f64 {dep64}");
        if origin == 1 << 23 {
            f32_far = dep32;
        }
        assert_eq!(dep64, 0, "f64 DDA departs at |coord| ~ {origin}");
    }
    assert!(f32_far > 0, "the checker found no f32 DDA departure at 2^23");
}
