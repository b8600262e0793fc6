//! Differential testing of another renderer (`rasterproof hunt`): scenes drawn from the
//! suite's families, rendered by their renderer and compared with the oracle; every
//! distinct failure shrunk with their renderer in the loop to a minimal scene, with its
//! explanation and a ready-to-paste Rust test.
//!
//! Their renderer is any `Fn(&Scene) -> Result<Theirs, RenderFailure>`: an external program
//! ([`crate::oracle::renderer::program::Program`]) or a Rust closure.
//!
//! At scale, as `check` runs: one [`Shard`] of the cases (N machines run disjoint cases
//! and together exactly the unsharded hunt's), within a time budget (the cases that ran
//! are the first of the shard's, in order), into a [`HuntReport`] written as JSON
//! ([`HuntReport::to_json`]) or JUnit XML ([`HuntReport::junit`]).
//!
//! This module holds the configuration ([`HuntConfig`]) and the run loop ([`hunt`]); its
//! parts, each re-exported here: the scene families (`families`), the verdict on one
//! scene and the signatures of a failure (`verdict`), the report (`report`), a finding as
//! a Rust test (`test_text`), the convention a fit names (`convention`), and the grey
//! hunt (`grey`: anti-aliased output against exact area coverage, [`hunt_grey`]). The shrinker
//! is the harness's ([`crate::harness::shrink`], re-exported here as [`shrink`]), run
//! with no grid step.

mod convention;
mod families;
mod grey;
mod html;
mod merge;
mod report;
mod test_text;
mod verdict;

use std::collections::{BTreeMap, HashMap};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, MutexGuard, PoisonError};
use std::time::{Duration, Instant};

pub use crate::harness::shrink::{primitive_count, shrink, shrink_batched};
pub use convention::{fit_convention, hunt_convention, preferred, FitFirst, FIT_PROBES};
pub use families::{float32_exact, generate_scene, SceneFamily};
pub use grey::{
    grey_signatures, hunt_grey, judge_grey, on_grid, GreyFinding, GreyHuntConfig, GreyHuntReport, GreySignature,
    GreyVerdict, AREA_FAMILIES,
};
pub use merge::merge_reports;
pub use report::{HuntFinding, HuntReport, HUNT_REPORT_FORMAT, HUNT_REPORT_VERSION};
pub use test_text::rust_test;
pub use verdict::{judge, pixel_kinds, signatures, HuntVerdict, Signature};

use verdict::CaseOutcome;

use crate::convention::Preset;
use crate::harness::runner::{RunError, Runner};
use crate::harness::suite::Shard;
use crate::model::Model;
use crate::oracle::compare::PixelKind;
use crate::oracle::renderer::program::Renderer;
use crate::pattern::SamplePattern;
use crate::scene::{Overrides, Scene};

/// How a hunt runs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct HuntConfig {
    /// How many scenes.
    pub cases: u64,
    /// Seed of the scene generator (same seed, same scenes).
    pub seed: u64,
    /// The families, case `k` drawing from `families[k % len]`.
    pub families: Vec<SceneFamily>,
    /// Canvas side of every scene.
    pub canvas: u32,
    /// The convention every scene states: a preset and overrides.
    pub preset: Preset,
    /// The overrides.
    pub overrides: Overrides,
    /// The oracle: `exact-snapped`, or `exact` for a renderer that does not snap.
    pub model: Model,
    /// Round every coordinate to the nearest f32 (for programs that read floats).
    pub float32_exact: bool,
    /// Runs of their renderer allowed per shrink.
    pub shrink_runs: usize,
    /// The shard to run: the cases `k` of `0..cases` with `k mod N == K - 1` (case `k`'s
    /// scene is the same in every shard; [`Shard::WHOLE`] runs them all).
    pub shard: Shard,
    /// No case starts once this much time has passed since the hunt started (the running
    /// ones finish, and what was found is still shrunk); `None`: no limit.
    pub budget: Option<Duration>,
    /// The sample pattern every scene states (`samples`): their renderer answers with the
    /// stacked per-sample image and each sample index is judged; `None`: one sample.
    pub samples: Option<SamplePattern>,
}

impl Default for HuntConfig {
    fn default() -> Self {
        HuntConfig {
            cases: 200,
            seed: 0,
            families: SceneFamily::ALL.to_vec(),
            canvas: 16,
            preset: Preset::D3d11,
            overrides: Overrides::default(),
            model: Model::ExactSnapped,
            float32_exact: false,
            shrink_runs: 400,
            shard: Shard::WHOLE,
            budget: None,
            samples: None,
        }
    }
}

/// One case's scene, signatures and outcome.
type CaseResult = (u64, Scene, Vec<(Signature, Vec<PixelKind>)>, CaseOutcome);

/// Runs the hunt: the scenes of `config.shard`'s cases among `0..config.cases` rendered by
/// `render` on `jobs` threads, each compared with the oracle; every distinct signature's
/// first case shrunk. `tick` is called once per case (a progress bar).
///
/// With `config.budget`, no case starts once the budget has passed: the running ones
/// finish, and the cases that ran are the first of the shard's, in order (a case is
/// claimed, in order, only while the budget lasts, and every claimed case runs), so a
/// time-limited hunt's counts and findings are those of a shorter hunt. What was found is
/// shrunk whatever the budget.
///
/// ```
/// use rasterproof::harness::suite::Shard;
/// use rasterproof::model::{render, Model};
/// use rasterproof::oracle::hunt::{hunt, HuntConfig};
/// use rasterproof::oracle::{Format, Theirs};
/// // A renderer that is the oracle itself finds nothing.
/// let honest = |s: &rasterproof::scene::Scene| {
///     let c = render(&s.primitives(), &s.target().unwrap(), Model::ExactSnapped).unwrap();
///     Ok(Theirs::from_coverage(&c, Format::Json))
/// };
/// let config = HuntConfig { cases: 16, ..HuntConfig::default() };
/// let report = hunt(&honest, &config, 1, &|| {}).unwrap();
/// assert!(report.findings.is_empty());
/// assert_eq!(report.same + report.refused, 16);
/// // Shard 2 of 3: cases 1, 4, 7, 10, 13; a zero budget runs none of them.
/// let shard = HuntConfig { shard: Shard::new(2, 3).unwrap(), ..config.clone() };
/// assert_eq!(hunt(&honest, &shard, 2, &|| {}).unwrap().cases, 5);
/// let none = HuntConfig { budget: Some(std::time::Duration::ZERO), ..shard };
/// let report = hunt(&honest, &none, 1, &|| {}).unwrap();
/// assert_eq!((report.requested, report.cases, report.stopped_by_time), (5, 0, true));
/// ```
///
/// # Errors
/// A scene could not be generated.
pub fn hunt<R>(renderer: &R, config: &HuntConfig, jobs: usize, tick: &(dyn Fn() + Sync)) -> Result<HuntReport, String>
where
    R: Renderer + ?Sized,
{
    hunt_interruptible(renderer, config, jobs, tick, &AtomicBool::new(false))
}

/// [`hunt`] that stops early once `interrupted` is set (what `rasterproof hunt`'s Ctrl-C
/// handler does): no case starts after it, the running ones finish, and the findings of
/// the cases that ran are reported as they were first seen, not shrunk
/// ([`HuntReport::interrupted`]), so an interrupted hunt still leaves a valid report of the
/// cases done.
///
/// # Errors
/// A scene could not be generated.
pub fn hunt_interruptible<R>(
    renderer: &R,
    config: &HuntConfig,
    jobs: usize,
    tick: &(dyn Fn() + Sync),
    interrupted: &AtomicBool,
) -> Result<HuntReport, String>
where
    R: Renderer + ?Sized,
{
    let render = |s: &Scene| renderer.render(s);
    let requested = config.shard.case_count(config.cases);
    let deadline = config.budget.and_then(|b| Instant::now().checked_add(b));
    // The cases that ran are the first of the shard's, in order (the runner hands on an
    // unbroken prefix), whatever the number of threads.
    let stop = || deadline.is_some_and(|d| Instant::now() >= d) || interrupted.load(Ordering::SeqCst);
    let case = |i: u64| -> Result<CaseResult, String> {
        let k = config
            .shard
            .case_at(i)
            .ok_or_else(|| format!("the shard has no case at position {i}"))?;
        let scene = generate_scene(config, k)?;
        let verdict = judge(&scene, render(&scene), config.model);
        let sigs = signatures(&verdict)
            .into_iter()
            .map(|s| {
                let kinds = pixel_kinds(&verdict, &s);
                (s, kinds)
            })
            .collect();
        let outcome = CaseOutcome::of(&verdict);
        tick();
        Ok((k, scene, sigs, outcome))
    };
    let runner = Runner {
        threads: jobs.max(1),
        name: "rasterproof-hunt",
        ..Runner::default()
    };
    let mut results: Vec<CaseResult> = Vec::new();
    runner
        .run(requested, &stop, &case, &mut |_, r| r.map(|r| results.push(r)))
        .map_err(|e| match e {
            RunError::Spawn(e) => format!("cannot start {jobs} threads: {e}"),
            RunError::Case(e) => e,
        })?;
    let cases = results.len() as u64;
    let (mut same, mut differing, mut failed, mut refused) = (0u64, 0u64, 0u64, 0u64);
    let mut first: BTreeMap<Signature, (u64, Scene, u64, Vec<PixelKind>)> = BTreeMap::new();
    for (k, scene, sigs, outcome) in results {
        *match outcome {
            CaseOutcome::Same => &mut same,
            CaseOutcome::Differs => &mut differing,
            CaseOutcome::Failed => &mut failed,
            CaseOutcome::Refused => &mut refused,
        } += 1;
        for (sig, kinds) in sigs {
            let entry = first.entry(sig).or_insert_with(|| (k, scene.clone(), 0, Vec::new()));
            entry.2 += 1;
            for kind in kinds {
                if !entry.3.contains(&kind) {
                    entry.3.push(kind);
                }
            }
        }
    }
    // Each finding's first case is shrunk on its own, `jobs` at a time (the results do not
    // depend on it: each shrink sees only its own scene and renderer answers). Jobs left
    // over (fewer findings than jobs) try each shrinking step's candidates side by side,
    // `width` at a time: the same minimal scene, sooner, for a few renderer calls more.
    let width = jobs.max(1) / first.len().clamp(1, jobs.max(1));
    let shrink_one =
        |(signature, (case, original, cases, mut kinds)): (Signature, (u64, Scene, u64, Vec<PixelKind>))| {
            kinds.sort();
            // The shrinker may try one scene twice (two steps reaching it): the renderer is
            // asked once per distinct scene.
            let seen: Mutex<HashMap<String, bool>> = Mutex::new(HashMap::new());
            let keeps = |s: &Scene| {
                let key = s.to_json();
                if let Some(&kept) = lock(&seen).get(&key) {
                    return kept;
                }
                let kept = signatures(&judge(s, render(s), config.model)).contains(&signature);
                lock(&seen).insert(key, kept);
                kept
            };
            let mut first_kept = |batch: &[Scene]| -> Option<usize> {
                if batch.len() == 1 {
                    return keeps(&batch[0]).then_some(0);
                }
                let kept = crate::chunks::map_each(batch.iter().collect(), batch.len(), keeps);
                kept.iter().position(|&k| k)
            };
            let budget = if interrupted.load(Ordering::SeqCst) {
                0
            } else {
                config.shrink_runs
            };
            let (minimal, runs) = shrink_batched(&original, &mut first_kept, width, budget, None);
            let renderer_calls = lock(&seen).len();
            let verdict = judge(&minimal, render(&minimal), config.model);
            HuntFinding {
                signature,
                kinds,
                case,
                cases,
                original,
                minimal,
                verdict,
                runs,
                renderer_calls,
            }
        };
    let mut findings = crate::chunks::map_each(first.into_iter().collect(), jobs, shrink_one);
    findings.sort_by_key(|f| (f.case, f.signature.clone()));
    Ok(HuntReport {
        config: config.clone(),
        requested,
        cases,
        stopped_by_time: cases < requested && !interrupted.load(Ordering::SeqCst),
        interrupted: interrupted.load(Ordering::SeqCst),
        same,
        differing,
        failed,
        refused,
        findings,
        renderer_runs: renderer.runs(),
    })
}

/// `m` locked, whether or not a thread panicked holding it (the data is a cache or a
/// queue: every state it can be left in is valid).
fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(PoisonError::into_inner)
}
