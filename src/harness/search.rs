//! The counterexample search for your own triangle rasterizer: random triangles of
//! every family (tie-heavy ones included) are rendered by your rasterizer and by the
//! oracle; the first disagreement is shrunk by proptest, then as a one-triangle scene by
//! the crate's one shrinker ([`crate::harness::shrink`], with one subpixel as its smallest
//! step, every candidate kept on the preset's subpixel grid and inside the integer
//! envelope), and reported as a minimal scene file with the exact explanation of the
//! first differing pixel.
//!
//! "Minimal" is checkable: in the reported scene no vertex coordinate can move one
//! subpixel towards zero (nor to zero, half way there, to the integer towards zero or to
//! a coarser grid towards zero, nor one pixel towards zero) with the disagreement
//! staying, and no crop of the canvas (to either half, or one pixel off a side, the
//! scene moved by whole pixels with it) keeps it. The shrink has [`SHRINK_RUNS`] runs of
//! the rasterizer; every step it accepts shrinks the canvas or lowers a coordinate's
//! magnitude on a fixed grid, so it ends at such a scene unless it spends them all.

use proptest::strategy::Strategy;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestError, TestRng, TestRunner};

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::One;

use super::shrink::shrink;
use crate::check::{check_agreement, Violation};
use crate::convention::{Preset, Target};
use crate::coverage::{Coverage, CoverageSink};
use crate::geom::FixedTriangle;
use crate::scene::Scene;
use crate::strategy::any_triangle;

/// Runs of the rasterizer (each against the oracle) the shrink after proptest's may take:
/// a backstop far above what a shrink takes on the default 16x16 canvas (tens of runs),
/// against a rasterizer that keeps disagreeing along a very long path.
pub const SHRINK_RUNS: usize = 100_000;

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
/// The rasterizer receives each triangle as a [`FixedTriangle`]: its vertices in
/// subpixels of the preset's grid (`t.coords()`, `t.bits` fractional bits: `x` pixels is
/// `x << t.bits` subpixels), as a rasterizer that snaps its input holds them.
///
/// Triangles only: the search draws triangle families and shrinks one triangle. For a
/// line drawer or a polygon fill, give [`crate::oracle::hunt::hunt`] the renderer as a
/// closure (a scene in, its pixels out): it draws lines and polygons too and shrinks
/// what it finds with the same shrinker.
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
    let mut scene = Scene::new(target.width, target.height, vec![shrunk.to_exact()]);
    scene.preset = config.preset;
    let mut keeps = |s: &Scene| match (s.target(), on_the_grid(s)) {
        (Ok(target), Some(t)) => disagreement(&rasterizer, &t, &target).is_some(),
        _ => false,
    };
    let step = BigRational::new(BigInt::one(), BigInt::one() << conv.subpixel_bits);
    let (scene, _) = shrink(&scene, &mut keeps, SHRINK_RUNS, Some(&step));
    let triangle = on_the_grid(&scene).expect("the shrunk scene is one triangle on the grid");
    let target = scene.target().expect("the shrunk canvas is no larger");
    let violation = disagreement(&rasterizer, &triangle, &target).expect("the shrunk triangle still disagrees");
    Some(Counterexample {
        triangle,
        scene,
        violation,
    })
}

/// The scene's one triangle in subpixels of its convention's grid: `None` unless the scene
/// is exactly one triangle (no clip window) whose coordinates all lie on the grid and
/// inside the integer models' envelope.
fn on_the_grid(scene: &Scene) -> Option<FixedTriangle> {
    let [t] = scene.triangles.as_slice() else {
        return None;
    };
    if !(scene.lines.is_empty()
        && scene.polygons.is_empty()
        && scene.clip_space_triangles.is_empty()
        && scene.clip.is_none())
    {
        return None;
    }
    let snapped = t.triangle.snapped(&scene.convention());
    if snapped.to_exact() != t.triangle.to_triangle() {
        return None;
    }
    snapped.to_fixed().ok()
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
