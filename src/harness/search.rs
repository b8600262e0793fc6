//! The counterexample search for your own triangle rasterizer: random triangles of
//! every family (tie-heavy ones included) are rendered by your rasterizer and by the
//! oracle; the first disagreement is shrunk by proptest, then further towards zero
//! coordinate by coordinate, and reported as a minimal scene file with the exact
//! explanation of the first differing pixel.
//!
//! "Minimal" is checkable: in the reported scene no vertex coordinate can move one
//! subpixel towards zero (or to zero, or half way there) with the disagreement staying,
//! and the canvas is cropped to the differing pixel when that keeps it.

use proptest::strategy::Strategy;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestError, TestRng, TestRunner};

use crate::check::{check_agreement, differing_pixels, Violation};
use crate::convention::{Preset, Target};
use crate::coverage::{Coverage, CoverageSink};
use crate::geom::FixedTriangle;
use crate::num::SubPixel;
use crate::scene::Scene;
use crate::strategy::any_triangle;

/// How the harness searches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct HarnessConfig {
    /// Random triangles to try before declaring no counterexample.
    pub cases: u32,
    /// Canvas side, pixels.
    pub canvas: u32,
    /// The convention.
    pub preset: Preset,
    /// Seed of the case generator (same seed, same cases).
    pub seed: u64,
}

impl Default for HarnessConfig {
    fn default() -> Self {
        HarnessConfig {
            cases: 1000,
            canvas: 16,
            preset: Preset::D3d11,
            seed: 0,
        }
    }
}

/// A minimal disagreement between a rasterizer and the oracle.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Counterexample {
    /// The triangle, snapped (subpixels of the preset's grid).
    pub triangle: FixedTriangle,
    /// A scene file holding just that triangle on the cropped canvas.
    pub scene: Scene,
    /// The disagreement, with the exact explanation of its first pixel.
    pub violation: Violation,
}

/// Runs `rasterizer` (same shape as the crate's integer rasterizers: triangle, id, target,
/// sink; it must cover with the id it is given) against the oracle on random snapped
/// triangles; `None` when all `config.cases` agree.
///
/// ```
/// use rasterproof::harness::{find_counterexample, HarnessConfig};
/// // The crate's own integer model has no counterexample.
/// let config = HarnessConfig { cases: 64, ..HarnessConfig::default() };
/// assert!(find_counterexample(|t, id, target, sink| rasterproof::tri::fixed::rasterize(t, id, target, sink), &config).is_none());
/// ```
///
/// # Panics
/// When `config.canvas` is not a valid canvas side (`1..=16384`).
pub fn find_counterexample<F>(rasterizer: F, config: &HarnessConfig) -> Option<Counterexample>
where
    F: Fn(&FixedTriangle, u32, &Target, &mut dyn CoverageSink),
{
    let target = Target::new(config.canvas, config.canvas, config.preset.convention()).expect("a valid canvas side");
    let conv = target.convention;
    let strategy =
        any_triangle(config.canvas).prop_filter_map("outside the envelope", move |t| t.snapped(&conv).to_fixed().ok());
    let mut seed = [0u8; 32];
    seed[..8].copy_from_slice(&config.seed.to_le_bytes());
    let mut runner = TestRunner::new_with_rng(
        Config {
            cases: config.cases,
            failure_persistence: None,
            ..Config::default()
        },
        TestRng::from_seed(RngAlgorithm::ChaCha, &seed),
    );
    let result = runner.run(&strategy, |t| match disagreement(&rasterizer, &t, &target) {
        None => Ok(()),
        Some(v) => Err(TestCaseError::fail(v.to_string())),
    });
    let Err(TestError::Fail(_, shrunk)) = result else {
        return None;
    };
    let triangle = towards_zero(&rasterizer, shrunk, &target);
    let target = cropped(&rasterizer, &triangle, target);
    let triangle = towards_zero(&rasterizer, triangle, &target);
    let violation = disagreement(&rasterizer, &triangle, &target).expect("the minimised triangle still disagrees");
    let mut scene = Scene::new(target.width, target.height, vec![triangle.to_exact()]);
    scene.preset = config.preset;
    Some(Counterexample {
        triangle,
        scene,
        violation,
    })
}

/// The oracle's and the rasterizer's coverage of `t`, each with id 0.
fn render_both<F>(rasterizer: &F, t: &FixedTriangle, target: &Target) -> (Coverage, Coverage)
where
    F: Fn(&FixedTriangle, u32, &Target, &mut dyn CoverageSink),
{
    let mut reference = Coverage::new(target.width, target.height);
    crate::tri::exact::rasterize(&t.to_exact(), 0, target, &mut reference);
    let mut candidate = Coverage::new(target.width, target.height);
    rasterizer(t, 0, target, &mut candidate);
    (reference, candidate)
}

/// The agreement violation of `rasterizer` on `t`, if any.
fn disagreement<F>(rasterizer: &F, t: &FixedTriangle, target: &Target) -> Option<Violation>
where
    F: Fn(&FixedTriangle, u32, &Target, &mut dyn CoverageSink),
{
    let (reference, candidate) = render_both(rasterizer, t, target);
    check_agreement("oracle", &reference, "candidate", &candidate, &[t.to_exact()], target).err()
}

/// Moves coordinates towards zero (to zero, half way, one subpixel) while the
/// disagreement stays, until no single move keeps it. Terminates: every accepted move
/// lowers the sum of the coordinates' magnitudes.
fn towards_zero<F>(rasterizer: &F, mut t: FixedTriangle, target: &Target) -> FixedTriangle
where
    F: Fn(&FixedTriangle, u32, &Target, &mut dyn CoverageSink),
{
    loop {
        let mut moved = false;
        for k in 0..6 {
            let c = t.v[k / 2][k % 2].get();
            for candidate in [0, c / 2, c - c.signum()] {
                if candidate == c {
                    continue;
                }
                let mut next = t;
                next.v[k / 2][k % 2] = SubPixel::new(candidate).expect("closer to zero: inside the envelope");
                if disagreement(rasterizer, &next, target).is_some() {
                    t = next;
                    moved = true;
                    break;
                }
            }
        }
        if !moved {
            return t;
        }
    }
}

/// The canvas cropped to just include the first differing pixel, when the disagreement
/// survives the crop.
fn cropped<F>(rasterizer: &F, t: &FixedTriangle, target: Target) -> Target
where
    F: Fn(&FixedTriangle, u32, &Target, &mut dyn CoverageSink),
{
    let (reference, candidate) = render_both(rasterizer, t, &target);
    let Some(first) = differing_pixels(&reference, &candidate).into_iter().next() else {
        return target;
    };
    match Target::new(first.x + 1, first.y + 1, target.convention) {
        Some(small) if disagreement(rasterizer, t, &small).is_some() => small,
        _ => target,
    }
}
