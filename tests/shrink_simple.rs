//! The shrinker tries the simplest values first: a failure that survives at integer
//! coordinates is shrunk to a scene whose coordinates are integers (or halves), even
//! from a scene of tiny ugly fractions such as -1/16777216, and well within the budget of
//! renderer runs.

use num_rational::BigRational;
use rasterproof::coverage::Coverage;
use rasterproof::geom::{Point, Triangle};
use rasterproof::model::{render, Model};
use rasterproof::oracle::hunt::{judge, shrink, HuntVerdict};
use rasterproof::oracle::program::RenderFailure;
use rasterproof::oracle::{Format, Theirs};
use rasterproof::scene::Scene;

/// A renderer that draws nothing of a scene with a negative coordinate (it culls such a
/// scene) and draws everything else as the exact oracle does: under `--model exact` the
/// failure needs a negative coordinate, however tiny, and survives at integers.
fn culls_negative(s: &Scene) -> Result<Theirs, RenderFailure> {
    let target = s.target().unwrap();
    let negative = s
        .clone()
        .coordinates_mut()
        .iter()
        .any(|c| **c < BigRational::from_integer(0.into()));
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
    let coordinates: Vec<String> = minimal
        .clone()
        .coordinates_mut()
        .iter()
        .map(|c| c.to_string())
        .collect();
    assert!(
        runs < budget,
        "the shrink spent its whole budget ({runs} runs); coordinates {coordinates:?}"
    );
    assert!(
        minimal.clone().coordinates_mut().iter().all(|c| *c.denom() <= 2.into()),
        "coordinates not integers or halves: {coordinates:?}"
    );
}
