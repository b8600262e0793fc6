//! The grey hunt (`rasterproof hunt --as grey`): another renderer's anti-aliased output
//! against exact area coverage, scene after scene, each distinct failure shrunk with their
//! renderer in the loop.
//!
//! It runs as [`super::hunt`] does (the same families, seeds, shards and time budget, the
//! same shrinker), but judges a grey image ([`judge_grey`]: [`compare_grey`] under a named
//! semantics and quantization) and tells failures apart by [`GreySignature`]: the reason
//! class of a differing pixel ([`GreyClass`]) and whether their level is above or below the
//! exact value, or how their renderer failed. Each signature's report carries, over every
//! case that showed it, the pixels it explained and the largest error in quanta: the
//! table of what a renderer gets wrong, by class, with its size.

use std::collections::{BTreeMap, HashMap};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;
use std::time::Instant;

use num_rational::BigRational;
use num_traits::{Signed, Zero};
use serde_json::json;

use super::{generate_scene, lock, HuntConfig, SceneFamily};
use crate::area::{Quantization, Semantics};
use crate::harness::runner::{RunError, Runner};
use crate::harness::shrink::shrink_batched;
use crate::model::Model;
use crate::num::exact::{exact_text, nearest_f64, round_to_integer, Rounding};
use crate::oracle::compare::grey::{compare_grey_scene, GreyClass, GreyOptions, GreyReport};
use crate::oracle::renderer::program::{FailureKind, RenderFailure, Renderer};
use crate::oracle::theirs::GreyImage;
use crate::oracle::theirs::Theirs;
use crate::scene::Scene;

/// The families a grey hunt draws from unless told otherwise: shapes with area (no lines).
/// Polygons (with holes, tangled, stellated: glyph-like outlines and overlapping contours),
/// meshes of abutting triangles (seams), random triangles, slivers, and huge triangles
/// reaching far off the canvas (overflow).
pub const AREA_FAMILIES: [SceneFamily; 6] = [
    SceneFamily::Polygons,
    SceneFamily::Delaunay,
    SceneFamily::Mesh,
    SceneFamily::Triangles,
    SceneFamily::Slivers,
    SceneFamily::Huge,
];

/// How a grey hunt runs: the scenes as [`HuntConfig`] says (its `model`, `preset` and
/// `overrides` are not used: area coverage does not snap and has no tie rule), and how
/// their levels are read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GreyHuntConfig {
    /// Cases, seed, families, canvas, f32 coordinates, shrink runs, shard, budget.
    pub hunt: HuntConfig,
    /// The semantics their renderer is held to.
    pub semantics: Semantics,
    /// How their levels quantize coverage (it fixes their bit depth).
    pub quantization: Quantization,
    /// Every coordinate rounded to the nearest multiple of `2^-bits` px (ties to even),
    /// for a renderer whose input is fixed point (FreeType's 26.6 outlines: 6), so that
    /// what it is judged on is its arithmetic, not its input's precision. `None`: as drawn.
    pub grid: Option<u32>,
}

/// What their renderer did with one scene.
#[derive(Debug, Clone)]
pub enum GreyVerdict {
    /// Every level is the exact value's under the named quantization.
    Same,
    /// Some differ: the comparison.
    Differs(Box<GreyReport>),
    /// Their renderer failed (an image of the wrong size or bit depth included).
    Failed(RenderFailure),
    /// The oracle refused the scene (no shape with area, or an invalid canvas).
    Refused(String),
}

/// Judges their output (or failure) on `scene` against exact area coverage.
pub fn judge_grey(
    scene: &Scene,
    theirs: Result<Theirs, RenderFailure>,
    semantics: Semantics,
    quantization: Quantization,
) -> GreyVerdict {
    let theirs = match theirs {
        Ok(t) => t,
        Err(f) => return GreyVerdict::Failed(f),
    };
    let Some(target) = scene.target() else {
        return GreyVerdict::Refused("invalid canvas or convention".to_string());
    };
    let options = GreyOptions {
        model: Model::Exact,
        semantics,
        quantization,
    };
    // Their output at fault (not grey, another size or depth) is their failure; the scene
    // refused (no shape with area) is the oracle's.
    match compare_grey_scene(&scene.primitives(), &target, &theirs, &options) {
        Ok(r) if r.identical() => GreyVerdict::Same,
        Ok(r) => GreyVerdict::Differs(Box::new(r)),
        Err(e) if e.is_theirs() => GreyVerdict::Failed(RenderFailure {
            kind: FailureKind::BadOutput,
            message: e.to_string(),
        }),
        Err(e) => GreyVerdict::Refused(e.to_string()),
    }
}

/// What tells one grey failure from another.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum GreySignature {
    /// Pixels of this class, their level above (`over`) or below the exact value.
    Class {
        /// The reason class.
        class: GreyClass,
        /// Their level is above the exact value.
        over: bool,
    },
    /// Their renderer failed this way.
    Failure(FailureKind),
}

impl GreySignature {
    /// In words: `conflation, under`, `failure: crash`.
    pub fn describe(self) -> String {
        match self {
            GreySignature::Class { class, over } => {
                format!("{}, {}", class.name(), if over { "over" } else { "under" })
            }
            GreySignature::Failure(kind) => format!("failure: {}", kind.name()),
        }
    }

    /// As a file name part: `conflation-under`, `supersampling-4x4-over`, `failure-crash`.
    pub fn slug(self) -> String {
        let mut s: String = self
            .describe()
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '-' })
            .collect();
        while s.contains("--") {
            s = s.replace("--", "-");
        }
        s.trim_matches('-').to_string()
    }
}

/// The signatures a verdict shows, with for each the pixels it explains and the largest
/// `|error|` among them in quanta (a failure: one "pixel", error zero).
pub fn grey_signatures(verdict: &GreyVerdict) -> BTreeMap<GreySignature, (u64, BigRational)> {
    let mut out: BTreeMap<GreySignature, (u64, BigRational)> = BTreeMap::new();
    match verdict {
        GreyVerdict::Differs(report) => {
            for p in &report.pixels {
                let sig = GreySignature::Class {
                    class: p.class,
                    over: p.error.is_positive(),
                };
                let entry = out.entry(sig).or_insert_with(|| (0, BigRational::zero()));
                entry.0 += 1;
                entry.1 = entry.1.clone().max(p.error.abs());
            }
        }
        GreyVerdict::Failed(f) => {
            out.insert(GreySignature::Failure(f.kind), (1, BigRational::zero()));
        }
        GreyVerdict::Same | GreyVerdict::Refused(_) => {}
    }
    out
}

/// One distinct failure: its first case shrunk, and its size over every case.
#[derive(Debug, Clone)]
pub struct GreyFinding {
    /// What it is.
    pub signature: GreySignature,
    /// The first case that showed it.
    pub case: u64,
    /// How many cases showed it.
    pub cases: u64,
    /// How many pixels it explained over those cases.
    pub pixels: u64,
    /// The largest `|their level - exact value|` among them, in quanta.
    pub max_error: BigRational,
    /// The first case's scene.
    pub original: Scene,
    /// The smallest scene that still shows it.
    pub minimal: Scene,
    /// Their output on the minimal scene, judged.
    pub verdict: GreyVerdict,
    /// Their grey image of the minimal scene (`None` when they failed on it).
    pub theirs: Option<GreyImage>,
    /// Shrinking steps tried.
    pub runs: usize,
}

/// What a grey hunt found.
#[derive(Debug, Clone)]
pub struct GreyHuntReport {
    /// How it ran.
    pub config: GreyHuntConfig,
    /// Cases asked for (the shard's).
    pub requested: u64,
    /// Cases run.
    pub cases: u64,
    /// Cases identical to the oracle.
    pub same: u64,
    /// Cases that differed.
    pub differing: u64,
    /// Cases their renderer failed.
    pub failed: u64,
    /// Cases the oracle refused.
    pub refused: u64,
    /// Each distinct failure, by first case.
    pub findings: Vec<GreyFinding>,
    /// It was interrupted: the findings are as first seen, not shrunk.
    pub interrupted: bool,
}

/// Runs the grey hunt: the cases of `config.hunt.shard` rendered by `renderer` on `jobs`
/// threads and judged ([`judge_grey`]); each signature's first case shrunk (every
/// shrinking step's candidates tried `jobs` at a time). `tick` is called once per case.
/// Once `interrupted` is set (a Ctrl-C handler), no case starts and nothing more is
/// shrunk: the findings of the cases that ran are reported as first seen.
///
/// ```
/// use rasterproof::area::{Quantization, Semantics};
/// use rasterproof::model::render_area;
/// use rasterproof::model::Model;
/// use rasterproof::oracle::GreyImage;
/// use rasterproof::oracle::hunt::{hunt_grey, GreyHuntConfig, HuntConfig, AREA_FAMILIES};
/// use rasterproof::oracle::Theirs;
/// // A renderer that truncates the exact value where the hunt expects it rounded.
/// let truncating = |s: &rasterproof::scene::Scene| {
///     let target = s.target().unwrap();
///     let exact = render_area(&s.primitives(), &target, Model::Exact, Semantics::Accumulated).unwrap();
///     let levels = exact.levels(Quantization::Truncate8);
///     Ok(Theirs::from_grey(GreyImage { width: s.width, height: s.height, bits: 8, levels }))
/// };
/// let config = GreyHuntConfig {
///     hunt: HuntConfig { cases: 6, canvas: 6, families: AREA_FAMILIES.to_vec(), ..HuntConfig::default() },
///     semantics: Semantics::Accumulated,
///     quantization: Quantization::Round8,
///     grid: None,
/// };
/// let report = hunt_grey(&truncating, &config, 1, &|| {}, &Default::default()).unwrap();
/// // Truncation is a legal rounding: a quantization class, always under the exact value.
/// assert!(!report.findings.is_empty());
/// assert!(report.findings.iter().all(|f| f.signature.describe() == "quantization, under"));
/// ```
///
/// # Errors
/// A scene could not be generated, or threads could not be started.
pub fn hunt_grey<R>(
    renderer: &R,
    config: &GreyHuntConfig,
    jobs: usize,
    tick: &(dyn Fn() + Sync),
    interrupted: &AtomicBool,
) -> Result<GreyHuntReport, String>
where
    R: Renderer + ?Sized,
{
    let hunt = &config.hunt;
    let judge = |s: &Scene| judge_grey(s, renderer.render(s), config.semantics, config.quantization);
    let requested = hunt.shard.case_count(hunt.cases);
    let deadline = hunt.budget.and_then(|b| Instant::now().checked_add(b));
    let stop = || deadline.is_some_and(|d| Instant::now() >= d) || interrupted.load(Ordering::SeqCst);
    type Case = (u64, Scene, GreyVerdict);
    let case = |i: u64| -> Result<Case, String> {
        let k = hunt
            .shard
            .case_at(i)
            .ok_or_else(|| format!("the shard has no case at position {i}"))?;
        let mut scene = generate_scene(hunt, k)?;
        if let Some(bits) = config.grid {
            on_grid(&mut scene, bits);
        }
        let verdict = judge(&scene);
        tick();
        Ok((k, scene, verdict))
    };
    let runner = Runner {
        threads: jobs.max(1),
        name: "rasterproof-grey-hunt",
        ..Runner::default()
    };
    let mut results: Vec<Case> = Vec::new();
    runner
        .run(requested, &stop, &case, &mut |_, r| r.map(|r| results.push(r)))
        .map_err(|e| match e {
            RunError::Spawn(e) => format!("cannot start {jobs} threads: {e}"),
            RunError::Case(e) => e,
        })?;
    let cases = results.len() as u64;
    let (mut same, mut differing, mut failed, mut refused) = (0u64, 0u64, 0u64, 0u64);
    // Per signature: first case and scene, cases, pixels, largest error.
    let mut first: BTreeMap<GreySignature, (u64, Scene, u64, u64, BigRational)> = BTreeMap::new();
    for (k, scene, verdict) in results {
        *match verdict {
            GreyVerdict::Same => &mut same,
            GreyVerdict::Differs(_) => &mut differing,
            GreyVerdict::Failed(_) => &mut failed,
            GreyVerdict::Refused(_) => &mut refused,
        } += 1;
        for (sig, (pixels, max)) in grey_signatures(&verdict) {
            let entry = first
                .entry(sig)
                .or_insert_with(|| (k, scene.clone(), 0, 0, BigRational::zero()));
            entry.2 += 1;
            entry.3 += pixels;
            entry.4 = entry.4.clone().max(max);
        }
    }
    let mut findings = Vec::new();
    for (signature, (case, original, cases, pixels, max_error)) in first {
        // The renderer is asked once per distinct scene the shrinker tries.
        let seen: Mutex<HashMap<String, bool>> = Mutex::new(HashMap::new());
        let keeps = |s: &Scene| {
            let key = s.to_json();
            if let Some(&kept) = lock(&seen).get(&key) {
                return kept;
            }
            let kept = grey_signatures(&judge(s)).contains_key(&signature);
            lock(&seen).insert(key, kept);
            kept
        };
        let mut first_kept = |batch: &[Scene]| -> Option<usize> {
            let kept = crate::chunks::map_each(batch.iter().collect(), batch.len(), keeps);
            kept.iter().position(|&k| k)
        };
        let budget = if interrupted.load(Ordering::SeqCst) {
            0
        } else {
            hunt.shrink_runs
        };
        let (minimal, runs) = shrink_batched(&original, &mut first_kept, jobs.max(1), budget, None);
        let drawn = renderer.render(&minimal);
        let theirs = drawn.as_ref().ok().and_then(Theirs::grey).cloned();
        let verdict = judge_grey(&minimal, drawn, config.semantics, config.quantization);
        findings.push(GreyFinding {
            signature,
            case,
            cases,
            pixels,
            max_error,
            original,
            minimal,
            verdict,
            theirs,
            runs,
        });
    }
    findings.sort_by_key(|f| (f.case, f.signature));
    Ok(GreyHuntReport {
        config: config.clone(),
        requested,
        cases,
        same,
        differing,
        failed,
        refused,
        findings,
        interrupted: interrupted.load(Ordering::SeqCst),
    })
}

/// Rounds every coordinate of `scene` to the nearest multiple of `2^-bits` (ties to even).
pub fn on_grid(scene: &mut Scene, bits: u32) {
    let unit = BigRational::from_integer(num_bigint::BigInt::from(1) << bits);
    scene.map_coordinates(|_, v| {
        let whole = round_to_integer(&(v * &unit), Rounding::NearestEven);
        BigRational::from_integer(whole) / &unit
    });
}

/// An exact number of quanta in words: `3/2` as `1.5000`, or its fraction when f64 does
/// not hold it.
fn quanta(v: &BigRational) -> String {
    nearest_f64(v).map_or_else(|| exact_text(v), |f| format!("{f:.4}"))
}

impl GreyHuntReport {
    /// As text: the counts, then each finding with its size and its minimal scene's
    /// comparison (up to `pixels` pixels each).
    pub fn to_text(&self, pixels: usize) -> String {
        let mut s = format!(
            "grey hunt: {} of {} cases ({} same, {} differing, {} failed, {} refused) against exact {} coverage quantized by {}\n",
            self.cases,
            self.requested,
            self.same,
            self.differing,
            self.failed,
            self.refused,
            self.config.semantics.name(),
            self.config.quantization.name()
        );
        for (n, f) in self.findings.iter().enumerate() {
            s.push_str(&format!(
                "\nfinding {}: {} (first in case {}; {} cases, {} pixels, max error {} quanta); shrunk in {} runs to {} primitive(s):\n",
                n + 1,
                f.signature.describe(),
                f.case,
                f.cases,
                f.pixels,
                quanta(&f.max_error),
                f.runs,
                super::primitive_count(&f.minimal)
            ));
            match &f.verdict {
                GreyVerdict::Differs(r) => {
                    for line in r.levels_text(pixels).lines() {
                        s.push_str(&format!("  {line}\n"));
                    }
                }
                GreyVerdict::Failed(e) => s.push_str(&format!("  their renderer failed: {e}\n")),
                GreyVerdict::Same => s.push_str("  (the minimal scene no longer differs)\n"),
                GreyVerdict::Refused(e) => s.push_str(&format!("  (the oracle refused the minimal scene: {e})\n")),
            }
        }
        s
    }

    /// As JSON: `{"renderer","semantics","quantization","seed","canvas","families",
    /// "requested","cases","same","differing","failed","refused","findings":[{"signature",
    /// "class","over","case","cases","pixels","max_error","runs","minimal","comparison"}]}`
    /// (`max_error` an exact fraction of quanta; `minimal` the scene; `comparison` the
    /// minimal scene's grey comparison, or `failure`).
    pub fn to_json(&self, renderer: &str) -> serde_json::Value {
        let findings: Vec<serde_json::Value> = self
            .findings
            .iter()
            .map(|f| {
                let (class, over) = match f.signature {
                    GreySignature::Class { class, over } => (Some(class.name()), Some(over)),
                    GreySignature::Failure(_) => (None, None),
                };
                let mut entry = json!({
                    "signature": f.signature.describe(),
                    "class": class,
                    "over": over,
                    "case": f.case,
                    "cases": f.cases,
                    "pixels": f.pixels,
                    "max_error": exact_text(&f.max_error),
                    "runs": f.runs,
                    "minimal": serde_json::from_str::<serde_json::Value>(&f.minimal.to_json()).unwrap_or_default(),
                });
                match &f.verdict {
                    GreyVerdict::Differs(r) => entry["comparison"] = r.levels_json(),
                    GreyVerdict::Failed(e) => entry["failure"] = json!(e.to_string()),
                    GreyVerdict::Refused(e) => entry["refused"] = json!(e),
                    GreyVerdict::Same => {}
                }
                entry
            })
            .collect();
        json!({
            "renderer": renderer,
            "semantics": self.config.semantics.name(),
            "quantization": self.config.quantization.name(),
            "grid_bits": self.config.grid,
            "seed": self.config.hunt.seed,
            "canvas": self.config.hunt.canvas,
            "families": self.config.hunt.families.iter().map(|f| f.name()).collect::<Vec<_>>(),
            "requested": self.requested,
            "cases": self.cases,
            "same": self.same,
            "differing": self.differing,
            "failed": self.failed,
            "refused": self.refused,
            "interrupted": self.interrupted,
            "findings": findings,
        })
    }
}
