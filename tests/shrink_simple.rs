//! The shrinker tries the simplest values first: a failure that survives at integer
//! coordinates is shrunk to a scene whose coordinates are integers (or halves), even
//! from a scene of tiny ugly fractions such as -1/16777216, and well within the budget of
//! renderer runs.

use num_rational::BigRational;
use proptest::prelude::*;

use crate::common::config;
use rasterproof::coverage::Coverage;
use rasterproof::geom::{Point, Triangle};
use rasterproof::model::{render, Model};
use rasterproof::oracle::hunt::{judge, shrink, shrink_batched, HuntVerdict};
use rasterproof::oracle::renderer::program::RenderFailure;
use rasterproof::oracle::{Format, Theirs};
use rasterproof::scene::Scene;

/// A renderer that draws nothing of a scene with a negative coordinate (it culls such a
/// scene) and draws everything else as the exact oracle does: under `--model exact` the
/// failure needs a negative coordinate, however tiny, and survives at integers.
fn culls_negative(s: &Scene) -> Result<Theirs, RenderFailure> {
    let target = s.target().unwrap();
    let negative = s.coordinates().iter().any(|c| *c < BigRational::from_integer(0.into()));
    let c = if negative {
        Coverage::new(s.width, s.height)
    } else {
        render(&s.primitives(), &target, Model::Exact).unwrap()
    };
    Ok(Theirs::from_coverage(&c, Format::Json))
}

#[test]
fn tiny_fractions_shrink_to_integers_within_the_budget() {
    let r = |n: i64, d: i64| BigRational::new(n.into(), d.into());
    let p = |x, y| Point::new(x, y);
    let scene = Scene::new(
        16,
        16,
        vec![
            Triangle {
                v: [
                    p(r(-1, 16_777_216), r(1, 536_870_912)),
                    p(r(12 * 1_048_576 + 7, 1_048_576), r(3, 4_194_304)),
                    p(r(5, 8_388_608), r(11 * 33_554_432 - 1, 33_554_432)),
                ],
            },
            Triangle {
                v: [
                    p(r(3_000_001, 1_000_000), r(3, 1)),
                    p(r(8, 1), r(22, 7)),
                    p(r(3, 1), r(9, 1)),
                ],
            },
        ],
    );
    let budget = 400;
    let mut keeps = |s: &Scene| matches!(judge(s, culls_negative(s), Model::Exact), HuntVerdict::Differs(_));
    assert!(keeps(&scene));
    let (minimal, runs) = shrink(&scene, &mut keeps, budget, None);
    assert!(keeps(&minimal));
    let coordinates: Vec<String> = minimal.coordinates().iter().map(|c| c.to_string()).collect();
    assert!(
        runs < budget,
        "the shrink spent its whole budget ({runs} runs); coordinates {coordinates:?}"
    );
    assert!(
        minimal.coordinates().iter().all(|c| *c.denom() <= 2.into()),
        "coordinates not integers or halves: {coordinates:?}"
    );
}

/// A scene of `n` triangles with vertices on the quarter-pixel grid of a 16x16 canvas.
fn quarter_scene() -> impl Strategy<Value = Scene> {
    let coord = (-8i64..72).prop_map(|q| BigRational::new(q.into(), 4.into()));
    let vertex = (coord.clone(), coord).prop_map(|(x, y)| Point::new(x, y));
    let triangle = [vertex.clone(), vertex.clone(), vertex].prop_map(|v| Triangle { v });
    prop::collection::vec(triangle, 1..5).prop_map(|t| Scene::new(16, 16, t))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..config("proptest-regressions/shrink_simple.txt") })]

    /// Trying a step's candidates several at a time shrinks to the same scene in the same
    /// runs as one at a time, for a failure that needs some triangles with a coordinate at
    /// or beyond a threshold and a canvas no smaller than a size, under every budget.
    #[test]
    fn batches_shrink_as_one_at_a_time(
        scene in quarter_scene(),
        need in 1usize..3,
        at_least in -2i64..40,
        side in 1u32..10,
        budget in 0usize..200,
    ) {
        let threshold = BigRational::new(at_least.into(), 4.into());
        // Which triangles are dropped matters: those reaching the threshold are needed.
        let keeps = |s: &Scene| {
            let reaching = s
                .triangles
                .iter()
                .filter(|t| t.triangle.to_triangle().v.iter().any(|p| p.x >= threshold || p.y >= threshold))
                .count();
            reaching >= need && s.width.min(s.height) >= side
        };
        prop_assume!(keeps(&scene));
        let one = shrink(&scene, &mut |s: &Scene| keeps(s), budget, None);
        for width in [2, 3, 7] {
            let mut batches = 0usize;
            let mut tried = 0usize;
            let mut first_kept = |batch: &[Scene]| {
                assert!(!batch.is_empty() && batch.len() <= width);
                batches += 1;
                tried += batch.len();
                batch.iter().position(&keeps)
            };
            let (minimal, runs) = shrink_batched(&scene, &mut first_kept, width, budget, None);
            prop_assert_eq!(&minimal, &one.0, "width {}", width);
            prop_assert_eq!(runs, one.1, "width {}", width);
            prop_assert!(batches <= runs && runs <= tried);
        }
    }
}

/// The drops of one round, derived by hand: of triangles A, B, C (the failure needs C), the
/// shrinker tries without C (no), without B (yes), then without A from what is left (yes),
/// each triangle once, and after a drop goes on with the triangle before it.
#[test]
fn drops_go_on_with_the_primitive_before() {
    let r = |n: i64| BigRational::from_integer(n.into());
    let t = |x: i64| Triangle {
        v: [
            Point::new(r(x), r(0)),
            Point::new(r(x + 1), r(0)),
            Point::new(r(x), r(1)),
        ],
    };
    let scene = Scene::new(8, 8, vec![t(0), t(2), t(4)]);
    let name = |s: &Scene| -> String {
        s.triangles
            .iter()
            .map(
                |k| match k.triangle.to_triangle().v[0].x.to_integer().to_string().as_str() {
                    "0" => "A",
                    "2" => "B",
                    _ => "C",
                },
            )
            .collect()
    };
    for width in [1, 2, 3] {
        let mut tried = Vec::new();
        let mut first_kept = |batch: &[Scene]| {
            let kept = batch.iter().position(|s| name(s).contains('C'));
            tried.extend(batch[..kept.map_or(batch.len(), |k| k + 1)].iter().map(&name));
            kept
        };
        let (minimal, _) = shrink_batched(&scene, &mut first_kept, width, 3, None);
        assert_eq!(tried, ["AB", "AC", "C"], "width {width}");
        assert_eq!(name(&minimal), "C");
    }
}

/// The shape a grey hunt's finding kept before the shrinker dropped polygon parts: an
/// outline with repeated points and a hole of three copies of (1, 1), against a
/// renderer whose failure needs only a polygon with area at pixel (0, 0). The shrinker
/// drops the repeated points and the empty hole: one hole-less polygon of three vertices,
/// none repeated, is left.
#[test]
fn polygon_repeated_points_and_empty_holes_are_dropped() {
    use rasterproof::geom::{FillRule, Polygon};
    let q = |x: i64, y: i64| Point::from_ints(x, y);
    let polygon = Polygon {
        outline: vec![q(0, 0), q(0, 0), q(4, 0), q(4, 0), q(4, 4), q(0, 4), q(0, 4), q(0, 0)],
        holes: vec![vec![q(1, 1), q(1, 1), q(1, 1)]],
        fill_rule: FillRule::NonZero,
    };
    let scene = Scene {
        polygons: vec![polygon],
        ..Scene::new(4, 4, vec![])
    };
    // The failure: pixel (0, 0) covered by the exact oracle (a polygon with area there).
    let mut keeps = |s: &Scene| {
        let target = s.target().unwrap();
        render(&s.primitives(), &target, Model::Exact).is_ok_and(|c| !c.owners(0, 0).is_empty())
    };
    assert!(keeps(&scene));
    let (minimal, _) = shrink(&scene, &mut keeps, 400, None);
    assert!(keeps(&minimal));
    assert_eq!(minimal.polygons.len(), 1);
    let p = &minimal.polygons[0];
    assert!(p.holes.is_empty(), "the empty hole is dropped: {p:?}");
    assert_eq!(p.outline.len(), 3, "a triangle is left: {:?}", p.outline);
    for k in 0..3 {
        assert_ne!(
            p.outline[k],
            p.outline[(k + 1) % 3],
            "no repeated point: {:?}",
            p.outline
        );
    }
}
