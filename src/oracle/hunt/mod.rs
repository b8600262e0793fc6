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

mod cases;
mod convention;
mod families;
mod grey;
mod grey_page;
mod html;
mod merge;
mod report;
mod test_text;
mod values;
mod verdict;

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

pub use crate::harness::shrink::{primitive_count, shrink, shrink_batched};
pub use convention::{
    fit_convention, fit_sample_convention, hunt_convention, preferred, FitFirst, MovedSample, SampleFitFirst,
    FIT_PROBES,
};
pub use families::{float32_exact, generate_scene, SceneFamily};
pub use grey::{
    fit_grey_method, grey_signatures, hunt_grey, judge_grey, on_grid, GreyFinding, GreyFitFirst, GreyHuntConfig,
    GreyHuntReport, GreySignature, GreyVerdict, AREA_FAMILIES, GREY_HUNT_REPORT_FORMAT, GREY_HUNT_REPORT_VERSION,
};
pub use grey_page::grey_rust_test;
pub use merge::{merge_reports, per_sample_summaries};
pub use report::{HuntFinding, HuntReport, SampleIndexSummary, HUNT_REPORT_FORMAT, HUNT_REPORT_VERSION};
pub use test_text::rust_test;
pub use values::{
    hunt_values, judge_values, value_signatures, with_values, ValueFinding, ValueHuntConfig, ValueHuntReport,
    ValueSignature, ValueVerdict, VALUE_FAMILIES,
};
pub use verdict::{judge, pixel_kinds, signatures, HuntVerdict, Signature};

use cases::{run_cases, shrink_budget, AskOnce, CaseCounts};
use verdict::CaseOutcome;

use crate::convention::Preset;
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

/// One case's scene, signatures and outcome, and under a pattern of several samples each
/// sample index's differing pixels (empty otherwise).
type CaseResult = (u64, Scene, Vec<(Signature, Vec<PixelKind>)>, CaseOutcome, Vec<u64>);

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
    let case = |k: u64, scene: Scene| -> CaseResult {
        let verdict = judge(&scene, render(&scene), config.model);
        let sigs = signatures(&verdict)
            .into_iter()
            .map(|s| {
                let kinds = pixel_kinds(&verdict, &s);
                (s, kinds)
            })
            .collect();
        let per_sample = match &verdict {
            HuntVerdict::DiffersPerSample(r) => r.samples.iter().map(|c| c.pixels.len() as u64).collect(),
            _ => Vec::new(),
        };
        (k, scene, sigs, CaseOutcome::of(&verdict), per_sample)
    };
    let (requested, results) = run_cases(config, jobs, "rasterproof-hunt", tick, interrupted, &case)?;
    let cases = results.len() as u64;
    let per_sample_tally = per_sample_tally(&results);
    let (tally, first) = first_seen(results);
    // Each finding's first case is shrunk on its own, `jobs` at a time (the results do not
    // depend on it: each shrink sees only its own scene and renderer answers). Jobs left
    // over (fewer findings than jobs) try each shrinking step's candidates side by side,
    // `width` at a time: the same minimal scene, sooner, for a few renderer calls more.
    let width = jobs.max(1) / first.len().clamp(1, jobs.max(1));
    let mut findings = crate::chunks::map_each(first.into_iter().collect(), jobs, |(signature, seen)| {
        shrink_finding(renderer, config, signature, seen, width, interrupted)
    });
    findings.sort_by_key(|f| (f.case, f.signature.clone()));
    let per_sample = match &config.samples {
        Some(pattern) if pattern.len() > 1 => {
            sample_summaries(renderer, config.model, pattern, &per_sample_tally, &findings)
        }
        _ => Vec::new(),
    };
    Ok(HuntReport {
        config: config.clone(),
        requested,
        cases,
        stopped_by_time: cases < requested && !interrupted.load(Ordering::SeqCst),
        interrupted: interrupted.load(Ordering::SeqCst),
        same: tally.same,
        differing: tally.differing,
        failed: tally.failed,
        refused: tally.refused,
        findings,
        renderer_runs: renderer.runs(),
        per_sample,
    })
}

/// Per sample index, the cases where it differed and its differing pixels over them.
fn per_sample_tally(results: &[CaseResult]) -> Vec<(u64, u64)> {
    let mut out: Vec<(u64, u64)> = Vec::new();
    for (.., per_sample) in results {
        if out.len() < per_sample.len() {
            out.resize(per_sample.len(), (0, 0));
        }
        for (slot, &pixels) in out.iter_mut().zip(per_sample) {
            slot.0 += u64::from(pixels > 0);
            slot.1 += pixels;
        }
    }
    out
}

/// Each sample index of `pattern` over the cases (`tally`), with the grid positions that
/// give its image on every finding's first and minimal scene where it differs: their
/// renderer asked again for each such scene, judged under `model`, its per-sample images
/// fitted
/// ([`crate::oracle::compare::fit::samples::fit_positions`], under the scene's convention
/// and oracle model).
fn sample_summaries<R>(
    renderer: &R,
    model: Model,
    pattern: &crate::pattern::SamplePattern,
    tally: &[(u64, u64)],
    findings: &[HuntFinding],
) -> Vec<SampleIndexSummary>
where
    R: Renderer + ?Sized,
{
    use crate::oracle::compare::fit::samples::{fit_positions, POSITION_GRID};
    let mut fits: Vec<Option<Vec<[num_rational::BigRational; 2]>>> = vec![None; pattern.len()];
    let mut failed = false;
    // Each finding's first scene and its minimal one: the first constrains the positions
    // more (more edges), the minimal one is what the finding shows.
    let scenes = findings.iter().flat_map(|f| [&f.original, &f.minimal]);
    for scene in scenes {
        let fitted = (|| {
            let target = scene.target().ok()?;
            let theirs = renderer.render(scene).ok()?;
            let per_sample = theirs.unstack(pattern.len(), target.height).ok()?;
            let HuntVerdict::DiffersPerSample(r) = judge(scene, Ok(theirs.clone()), model) else {
                return Some(None);
            };
            let fitted =
                fit_positions(&scene.primitives(), &target, pattern, &per_sample, model, POSITION_GRID).ok()?;
            Some(Some((r, fitted)))
        })();
        let Some(fitted) = fitted else {
            failed = true;
            continue;
        };
        let Some((r, fitted)) = fitted else { continue };
        for (s, report) in r.samples.iter().enumerate() {
            if report.pixels.is_empty() {
                continue;
            }
            let Some(found) = fitted.iter().find(|p| p.index == s) else {
                continue;
            };
            fits[s] = Some(match fits[s].take() {
                None => found.fits.clone(),
                Some(kept) => kept.into_iter().filter(|p| found.fits.contains(p)).collect(),
            });
        }
    }
    pattern
        .positions()
        .iter()
        .enumerate()
        .map(|(index, position)| {
            let (cases, pixels) = tally.get(index).copied().unwrap_or((0, 0));
            SampleIndexSummary {
                index,
                position: position.clone(),
                cases,
                pixels,
                fits: if failed { None } else { fits[index].clone() },
            }
        })
        .collect()
}

/// A signature as the cases first showed it: the first case and its scene, the number of
/// cases that showed it, and the kinds of pixels it was seen on.
type FirstSeen = (u64, Scene, u64, Vec<PixelKind>);

/// The cases counted by outcome, and each signature as first seen.
fn first_seen(results: Vec<CaseResult>) -> (CaseCounts, BTreeMap<Signature, FirstSeen>) {
    let mut tally = CaseCounts::default();
    let mut first: BTreeMap<Signature, FirstSeen> = BTreeMap::new();
    for (k, scene, sigs, outcome, _) in results {
        *match outcome {
            CaseOutcome::Same => &mut tally.same,
            CaseOutcome::Differs => &mut tally.differing,
            CaseOutcome::Failed => &mut tally.failed,
            CaseOutcome::Refused => &mut tally.refused,
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
    (tally, first)
}

/// One finding: its first scene shrunk while it keeps `signature` (candidates tried
/// `width` at a time; not shrunk once the hunt is `interrupted`), and the minimal scene's
/// verdict.
fn shrink_finding<R>(
    renderer: &R,
    config: &HuntConfig,
    signature: Signature,
    (case, original, cases, mut kinds): FirstSeen,
    width: usize,
    interrupted: &AtomicBool,
) -> HuntFinding
where
    R: Renderer + ?Sized,
{
    kinds.sort();
    let budget = shrink_budget(config.shrink_runs, interrupted);
    let ask = AskOnce::new(|s: &Scene| signatures(&judge(s, renderer.render(s), config.model)).contains(&signature));
    let (minimal, runs) = shrink_batched(&original, &mut |batch| ask.first_kept(batch), width, budget, None);
    let renderer_calls = ask.asked();
    let verdict = judge(&minimal, renderer.render(&minimal), config.model);
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
}
