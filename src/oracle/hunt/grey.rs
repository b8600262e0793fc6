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

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, Ordering};

use num_rational::BigRational;
use num_traits::{Signed, Zero};
use serde_json::json;

use super::cases::{run_cases, shrink_budget, AskOnce, CaseCounts};
use super::{HuntConfig, SceneFamily};
use crate::area::{Quantization, Semantics};
use crate::harness::shrink::shrink_batched;
use crate::model::Model;
use crate::num::exact::{exact_text, nearest_f64, round_to_integer, Rounding};
use crate::oracle::compare::fit::grey::GreyMethod;
use crate::oracle::compare::grey::{compare_grey_scene, compare_grey_scene_shows, GreyClass, GreyOptions, GreyReport};
use crate::oracle::renderer::program::{FailureKind, RenderFailure, Renderer, RendererRuns};
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
    /// A method of the area family to judge against (`hunt --method`, or the method
    /// `--fit-first` found): a pixel differs where their level is not its level. `None`:
    /// against the exact value's level under `quantization`.
    pub method: Option<GreyMethod>,
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

/// Judges their output (or failure) on `scene` against exact area coverage under
/// `semantics` and `quantization`, or against `method`'s levels when one is given (each
/// pixel that differs from them classed against the exact value).
pub fn judge_grey(
    scene: &Scene,
    theirs: Result<Theirs, RenderFailure>,
    semantics: Semantics,
    quantization: Quantization,
    method: Option<GreyMethod>,
) -> GreyVerdict {
    let theirs = match theirs {
        Ok(t) => t,
        Err(f) => return GreyVerdict::Failed(f),
    };
    let Ok(target) = scene.target() else {
        return GreyVerdict::Refused("invalid canvas or convention".to_string());
    };
    let options = hunt_options(semantics, quantization, method);
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

/// How a grey hunt compares: their levels against the shapes as written (`exact`, what
/// anti-aliasing renderers draw) under the hunt's semantics, quantization and method.
fn hunt_options(semantics: Semantics, quantization: Quantization, method: Option<GreyMethod>) -> GreyOptions {
    GreyOptions {
        model: Model::Exact,
        semantics,
        quantization,
        method,
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
    /// What the hunt cost the renderer, when it is a program: scenes asked for and
    /// programs started.
    pub renderer_runs: Option<RendererRuns>,
}

/// The `format` of a grey hunt report ([`GreyHuntReport::to_json`]).
pub const GREY_HUNT_REPORT_FORMAT: &str = "rasterproof grey hunt report";

/// The schema version of a grey hunt report ([`GreyHuntReport::to_json`]): 2 added
/// `format`, `version`, `rasterproof` and `renderer_runs`, and a failure's `failure` as
/// its kind and message; 3 added `method` (the method judged against, or null) and each
/// comparison's `method` and `explained_by`.
pub const GREY_HUNT_REPORT_VERSION: u64 = 3;

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
///     method: None,
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
    let case = |k: u64, mut scene: Scene| -> (u64, Scene, GreyVerdict) {
        if let Some(bits) = config.grid {
            on_grid(&mut scene, bits);
        }
        let verdict = judge_grey(
            &scene,
            renderer.render(&scene),
            config.semantics,
            config.quantization,
            config.method,
        );
        (k, scene, verdict)
    };
    let (requested, results) = run_cases(hunt, jobs, "rasterproof-grey-hunt", tick, interrupted, &case)?;
    let cases = results.len() as u64;
    let (tally, first) = first_seen(results);
    let mut findings: Vec<GreyFinding> = first
        .into_iter()
        .map(|(signature, seen)| shrink_finding(renderer, config, signature, seen, jobs.max(1), interrupted))
        .collect();
    findings.sort_by_key(|f| (f.case, f.signature));
    Ok(GreyHuntReport {
        config: config.clone(),
        requested,
        cases,
        same: tally.same,
        differing: tally.differing,
        failed: tally.failed,
        refused: tally.refused,
        findings,
        interrupted: interrupted.load(Ordering::SeqCst),
        renderer_runs: renderer.runs(),
    })
}

/// A grey signature as the cases first showed it: the first case and its scene, the
/// cases, the pixels and the largest error.
type FirstSeen = (u64, Scene, u64, u64, BigRational);

/// The cases counted by outcome, and each signature as first seen.
fn first_seen(results: Vec<(u64, Scene, GreyVerdict)>) -> (CaseCounts, BTreeMap<GreySignature, FirstSeen>) {
    let mut tally = CaseCounts::default();
    let mut first: BTreeMap<GreySignature, FirstSeen> = BTreeMap::new();
    for (k, scene, verdict) in results {
        *match verdict {
            GreyVerdict::Same => &mut tally.same,
            GreyVerdict::Differs(_) => &mut tally.differing,
            GreyVerdict::Failed(_) => &mut tally.failed,
            GreyVerdict::Refused(_) => &mut tally.refused,
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
    (tally, first)
}

/// One grey finding: its first scene shrunk while it keeps `signature` (candidates tried
/// `width` at a time; not shrunk once the hunt is `interrupted`), and the minimal scene's
/// image and verdict.
fn shrink_finding<R>(
    renderer: &R,
    config: &GreyHuntConfig,
    signature: GreySignature,
    (case, original, cases, pixels, max_error): FirstSeen,
    width: usize,
    interrupted: &AtomicBool,
) -> GreyFinding
where
    R: Renderer + ?Sized,
{
    let judge = |s: &Scene| {
        judge_grey(
            s,
            renderer.render(s),
            config.semantics,
            config.quantization,
            config.method,
        )
    };
    // Whether a candidate still shows the signature: for a class, the first pixel of it
    // (of its sign) ends the comparison ([`compare_grey_scene_shows`]).
    let shows = |s: &Scene| match signature {
        GreySignature::Class { class, over } => {
            let (Ok(theirs), Ok(target)) = (renderer.render(s), s.target()) else {
                return false;
            };
            let options = hunt_options(config.semantics, config.quantization, config.method);
            matches!(
                compare_grey_scene_shows(&s.primitives(), &target, &theirs, &options, (class, over)),
                Ok(true)
            )
        }
        GreySignature::Failure(_) => grey_signatures(&judge(s)).contains_key(&signature),
    };
    let ask = AskOnce::new(shows);
    let budget = shrink_budget(config.hunt.shrink_runs, interrupted);
    let (minimal, runs) = shrink_batched(&original, &mut |batch| ask.first_kept(batch), width, budget, None);
    let drawn = renderer.render(&minimal);
    let theirs = drawn.as_ref().ok().and_then(Theirs::grey).cloned();
    let verdict = judge_grey(&minimal, drawn, config.semantics, config.quantization, config.method);
    GreyFinding {
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
    }
}

/// What `hunt --as grey --fit-first` found: the method to hunt under, or that none
/// explains the probes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum GreyFitFirst {
    /// These methods give every level of every probe, in the order of
    /// [`GreyMethod::all`]: the hunt judges against the first.
    Found(Vec<GreyMethod>),
    /// No method gives every level of every probe: the last probe's fit, as text.
    NoneExplains(String),
}

/// `hunt --as grey --fit-first`: the methods of the area family
/// ([`crate::oracle::compare::fit::grey::fit_grey`]) that give every level of the
/// renderer's images of [`super::FIT_PROBES`] probe scenes, drawn from `config`'s
/// families and seed (on its grid when it has one).
///
/// # Errors
/// A probe scene cannot be made, the renderer fails on one or answers with no grey
/// image, or the fit refuses one.
pub fn fit_grey_method<R>(renderer: &R, config: &GreyHuntConfig) -> Result<GreyFitFirst, String>
where
    R: Renderer + ?Sized,
{
    let mut exact: Option<Vec<GreyMethod>> = None;
    let mut last = String::new();
    for k in 0..super::FIT_PROBES {
        let mut scene = super::generate_scene(&config.hunt, u64::MAX - k)?;
        if let Some(bits) = config.grid {
            on_grid(&mut scene, bits);
        }
        let target = scene
            .target()
            .map_err(|e| format!("--fit-first: invalid probe scene: {e}"))?;
        let theirs = renderer
            .render(&scene)
            .map_err(|f| format!("--fit-first: the renderer failed on a probe scene: {f}"))?;
        let grey = theirs
            .grey()
            .ok_or("--fit-first: the renderer's answer to a probe scene is not a grey image")?;
        let shapes = crate::model::area_shapes(&scene.primitives(), &target, Model::Exact)
            .map_err(|e| format!("--fit-first: {e}"))?;
        let found = crate::oracle::compare::fit::grey::fit_grey(&shapes, &target, grey, Model::Exact)
            .map_err(|e| format!("--fit-first: {e}"))?;
        exact = Some(match exact {
            None => found.exact(),
            Some(kept) => kept.into_iter().filter(|m| found.exact().contains(m)).collect(),
        });
        last = crate::oracle::Comparison::to_text(&found, "the probe scene", "their image", 0);
    }
    Ok(match exact {
        Some(methods) if !methods.is_empty() => GreyFitFirst::Found(methods),
        _ => GreyFitFirst::NoneExplains(last),
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

impl GreyFinding {
    /// Its first line, after its number: what it is, where it was first seen, its size (a
    /// failure has no pixels) and how it was shrunk.
    pub fn header(&self) -> String {
        let size = match self.signature {
            GreySignature::Failure(_) => String::new(),
            GreySignature::Class { .. } => {
                format!(
                    ", {}, max error {} quanta",
                    crate::num::exact::counted(self.pixels, "pixel"),
                    quanta(&self.max_error)
                )
            }
        };
        format!(
            "{} (first in case {}; {} cases{size}); shrunk in {} runs to {} primitive(s)",
            self.signature.describe(),
            self.case,
            self.cases,
            self.runs,
            super::primitive_count(&self.minimal)
        )
    }

    /// What their renderer did with the minimal scene: its comparison (up to `pixels`
    /// pixels), or its failure with the whole message (the exit status, the end of its
    /// stderr, what it answered).
    pub fn verdict_text(&self, pixels: usize) -> String {
        match &self.verdict {
            GreyVerdict::Differs(r) => r.levels_text(pixels),
            GreyVerdict::Failed(e) => format!("their renderer failed ({}): {}\n", e.kind.name(), e.message),
            GreyVerdict::Same => {
                "(the minimal scene no longer differs: the renderer is not deterministic)\n".to_string()
            }
            GreyVerdict::Refused(e) => format!("(the oracle refused the minimal scene: {e})\n"),
        }
    }

    /// The finding's `finding-NN.txt` (`n`: its number, from 1): its header, the minimal
    /// scene's comparison (every pixel) or failure, and the first scene that showed it.
    pub fn to_text(&self, n: usize) -> String {
        format!(
            "finding {n:02}: {}\n\n{}\nthe original scene:\n{}",
            self.header(),
            self.verdict_text(usize::MAX),
            self.original.to_json()
        )
    }
}

impl GreyHuntReport {
    /// As text: the counts, then each finding with its size and its minimal scene's
    /// comparison (up to `pixels` pixels each).
    pub fn to_text(&self, pixels: usize) -> String {
        let against = match self.config.method {
            Some(m) => format!("{} (--method {})", m.describe(), m.name()),
            None => format!(
                "exact {} coverage quantized by {}",
                self.config.semantics.name(),
                self.config.quantization.name()
            ),
        };
        let mut s = format!(
            "grey hunt: {} of {} cases ({} same, {} differing, {} failed, {} refused) against {against}\n",
            self.cases, self.requested, self.same, self.differing, self.failed, self.refused,
        );
        for (n, f) in self.findings.iter().enumerate() {
            s.push_str(&format!("\nfinding {}: {}:\n", n + 1, f.header()));
            for line in f.verdict_text(pixels).lines() {
                s.push_str(&format!("  {line}\n"));
            }
        }
        if let Some(r) = self.renderer_runs {
            s.push_str(&format!(
                "\nthe renderer: {} scenes asked for, {} programs started\n",
                r.calls, r.starts
            ));
        }
        s
    }

    /// As JSON: `{"format","version","rasterproof","renderer","renderer_runs","semantics",
    /// "quantization","method","seed","canvas","families","requested","cases","same","differing",
    /// "failed","refused","findings":[{"signature","class","over","case","cases","pixels",
    /// "max_error","runs","minimal","comparison"}]}` (`format`
    /// [`GREY_HUNT_REPORT_FORMAT`], `version` [`GREY_HUNT_REPORT_VERSION`];
    /// `renderer_runs` `{"calls","starts"}` for a program, else null; `max_error` an exact
    /// fraction of quanta; `minimal` the scene; `comparison` the minimal scene's grey
    /// comparison, or `failure` `{"kind","message"}`).
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
                    GreyVerdict::Failed(e) => {
                        entry["failure"] = json!({"kind": e.kind.name(), "message": e.message});
                    }
                    GreyVerdict::Refused(e) => entry["refused"] = json!(e),
                    GreyVerdict::Same => {}
                }
                entry
            })
            .collect();
        json!({
            "format": GREY_HUNT_REPORT_FORMAT,
            "version": GREY_HUNT_REPORT_VERSION,
            "rasterproof": env!("CARGO_PKG_VERSION"),
            "renderer": renderer,
            "renderer_runs": self.renderer_runs.map(|r| json!({"calls": r.calls, "starts": r.starts})),
            "semantics": self.config.semantics.name(),
            "quantization": self.config.quantization.name(),
            "method": self.config.method.map(GreyMethod::name),
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
