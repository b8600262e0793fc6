//! The values hunt (`rasterproof hunt --as values`): another renderer's interpolated
//! values against the exact ones, scene after scene, each distinct class of wrong value
//! shrunk with their renderer in the loop.
//!
//! Each case is a scene of the hunt's families (triangles only) given one varying `c` of
//! three channels, declared with the hunt's interpolation and provoking vertex, and at
//! every vertex a `w` (a power of two from 1/4 to 8, so that a renderer's f32 inputs are
//! exact) and three values (integers up to 1000 over 1, 3, 10 or 256), drawn from the
//! case's number. The renderer answers with a values image (`compare --as values`: a float32
//! TIFF or a UNORM PNG), judged by [`compare_values`]; a case's signatures are the classes
//! off it shows ([`ValueClass::is_off`]: `affine`, `provoking-vertex`, `gross`...) or how
//! the renderer failed. Each signature's first scene is shrunk while it still shows it.

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, Ordering};

use num_rational::BigRational;
use serde_json::{json, Value};

use super::cases::{run_cases, shrink_budget, AskOnce, CaseCounts};
use super::{HuntConfig, SceneFamily};
use crate::harness::shrink::shrink_batched;
use crate::interp::values::{Interpolation, ProvokingVertex, Sampling, Varying, Varyings};
use crate::model::Model;
use crate::oracle::compare::values::{compare_values, ValueClass, ValueOptions, ValueReport};
use crate::oracle::compare::Comparison;
use crate::oracle::renderer::program::{FailureKind, RenderFailure, Renderer, RendererRuns};
use crate::oracle::theirs::Theirs;
use crate::scene::{Scene, VertexValues};

/// The families a values hunt draws from unless told otherwise: triangles only.
pub const VALUE_FAMILIES: [SceneFamily; 4] = [
    SceneFamily::Triangles,
    SceneFamily::Mesh,
    SceneFamily::Delaunay,
    SceneFamily::Slivers,
];

/// How a values hunt runs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ValueHuntConfig {
    /// Cases, seed, families, canvas, preset, oracle model, f32 coordinates, shrink runs,
    /// shard, budget.
    pub hunt: HuntConfig,
    /// The varying's interpolation in every scene.
    pub interpolation: Interpolation,
    /// The scenes' provoking vertex.
    pub provoking: ProvokingVertex,
    /// Where the varying is sampled (`centroid` and `sample` differ from `centre` only
    /// under a pattern of several samples: `hunt --samples N`).
    pub sampling: Sampling,
}

impl ValueHuntConfig {
    /// A values hunt over `hunt`'s scenes with the interpolation, provoking vertex and
    /// sampling named as a scene file names them (`smooth`, `noperspective`, `flat`;
    /// `first`, `last`; `centre`, `centroid`, `sample`).
    ///
    /// # Errors
    /// An unknown name: one line naming the option.
    pub fn named(
        hunt: HuntConfig,
        interpolation: &str,
        provoking: &str,
        sampling: &str,
    ) -> Result<ValueHuntConfig, String> {
        Ok(ValueHuntConfig {
            hunt,
            interpolation: Interpolation::parse(interpolation).ok_or_else(|| {
                format!(
                    "--interpolation: unknown interpolation {interpolation:?} (expected smooth, noperspective or flat)"
                )
            })?,
            provoking: ProvokingVertex::parse(provoking)
                .ok_or_else(|| format!("--provoking: {provoking:?} is not first or last"))?,
            sampling: Sampling::parse(sampling)
                .ok_or_else(|| format!("--sampling: {sampling:?} is not centre, centroid or sample"))?,
        })
    }
}

/// The verdict on one scene.
#[derive(Debug, Clone, PartialEq)]
pub enum ValueVerdict {
    /// Every value exact or inside the f32 envelope.
    Same(Box<ValueReport>),
    /// Some value off.
    Differs(Box<ValueReport>),
    /// The renderer failed.
    Failed(RenderFailure),
    /// The comparison could not be made (their image, the scene).
    Refused(String),
}

/// What a failing case shows: a class off, or how the renderer failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ValueSignature {
    /// Pixels of this class.
    Class(ValueClass),
    /// The renderer failed this way.
    Failure(FailureKind),
}

impl ValueSignature {
    /// Its name in reports: the class, or `failure: KIND`.
    pub fn describe(self) -> String {
        match self {
            ValueSignature::Class(c) => c.name().to_string(),
            ValueSignature::Failure(k) => format!("failure: {}", k.name()),
        }
    }
}

/// The varying every case declares.
fn varyings(config: &ValueHuntConfig) -> Varyings {
    Varyings {
        list: vec![Varying {
            name: "c".to_string(),
            channels: 3,
            interpolation: config.interpolation,
            sampling: config.sampling,
        }],
        provoking: config.provoking,
    }
}

/// SplitMix64: a case's numbers from its number, the triangle, the vertex and the slot.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// `scene` with the hunt's varying and every triangle's `w` and values, drawn from case
/// `k` (module docs); its lines, polygons and clip-space triangles dropped.
pub fn with_values(mut scene: Scene, k: u64, config: &ValueHuntConfig) -> Scene {
    scene.lines.clear();
    scene.line_values.clear();
    scene.polygons.clear();
    scene.clip_space_triangles.clear();
    scene.varyings = varyings(config);
    let draw = |t: usize, v: usize, slot: u64| mix(mix(mix(k ^ config.hunt.seed) ^ t as u64) ^ (v as u64 * 8 + slot));
    for (t, tri) in scene.triangles.iter_mut().enumerate() {
        let w = [0, 1, 2].map(|v| {
            let e = i32::try_from(draw(t, v, 0) % 6).expect("small") - 2;
            if e >= 0 {
                BigRational::from_integer((1i64 << e).into())
            } else {
                BigRational::new(1.into(), (1i64 << -e).into())
            }
        });
        let values = [0, 1, 2].map(|v| {
            (1..=3u64)
                .map(|slot| {
                    let r = draw(t, v, slot);
                    let n = i64::try_from(r % 2001).expect("small") - 1000;
                    let d = [1i64, 3, 10, 256][usize::try_from((r >> 20) % 4).expect("small")];
                    BigRational::new(n.into(), d.into())
                })
                .collect()
        });
        tri.values = Some(Box::new(VertexValues { w: Some(w), values }));
    }
    scene
}

/// Judges their answer for `scene` (one with the hunt's varying).
pub fn judge_values(scene: &Scene, theirs: Result<Theirs, RenderFailure>, model: Model) -> ValueVerdict {
    let theirs = match theirs {
        Ok(t) => t,
        Err(e) => return ValueVerdict::Failed(e),
    };
    let target = match scene.target() {
        Ok(t) => t,
        Err(e) => return ValueVerdict::Refused(e.to_string()),
    };
    let options = ValueOptions {
        model,
        setups: scene.value_setups(),
        varyings: scene.varyings.clone(),
        varying: 0,
        unorm: crate::num::unorm::UnormRule::Nearest,
        pattern: None,
        picture: false,
    }
    .with_pattern(scene.samples.clone(), &target.convention);
    match compare_values(&scene.primitives(), &target, &theirs, &options) {
        Ok(report) if report.identical() => ValueVerdict::Same(Box::new(report)),
        Ok(report) => ValueVerdict::Differs(Box::new(report)),
        Err(e) => ValueVerdict::Refused(e.to_string()),
    }
}

/// A verdict's signatures, each with its pixels.
pub fn value_signatures(verdict: &ValueVerdict) -> BTreeMap<ValueSignature, u64> {
    match verdict {
        ValueVerdict::Differs(report) => report
            .counts
            .iter()
            .filter(|(c, _)| c.is_off())
            .map(|&(c, n)| (ValueSignature::Class(c), n as u64))
            .collect(),
        ValueVerdict::Failed(f) => BTreeMap::from([(ValueSignature::Failure(f.kind), 0)]),
        ValueVerdict::Same(_) | ValueVerdict::Refused(_) => BTreeMap::new(),
    }
}

/// One distinct failure: where it was first seen, and its scene shrunk.
#[derive(Debug, Clone, PartialEq)]
pub struct ValueFinding {
    /// What it shows.
    pub signature: ValueSignature,
    /// The first case that showed it.
    pub case: u64,
    /// Cases that showed it.
    pub cases: u64,
    /// Pixels of its class over those cases.
    pub pixels: u64,
    /// The first case's scene.
    pub original: Scene,
    /// The smallest scene found that still shows it.
    pub minimal: Scene,
    /// The minimal scene's verdict.
    pub verdict: ValueVerdict,
    /// Renderer runs the shrink took.
    pub runs: usize,
}

/// A values hunt's report.
#[derive(Debug, Clone, PartialEq)]
pub struct ValueHuntReport {
    /// How it ran.
    pub config: ValueHuntConfig,
    /// Cases asked for.
    pub requested: u64,
    /// Cases run.
    pub cases: u64,
    /// Cases judged right.
    pub same: u64,
    /// Cases with a value off.
    pub differing: u64,
    /// Cases the renderer failed.
    pub failed: u64,
    /// Cases that could not be compared.
    pub refused: u64,
    /// The distinct failures, by first case.
    pub findings: Vec<ValueFinding>,
    /// Whether Ctrl-C stopped it.
    pub interrupted: bool,
    /// The renderer's runs.
    pub renderer_runs: Option<RendererRuns>,
}

/// A signature as first seen: the case, its scene, the cases and the pixels.
type FirstSeen = (u64, Scene, u64, u64);

/// Runs the values hunt (module docs) with `renderer` on `jobs` threads.
///
/// # Errors
/// A scene could not be generated, or threads could not be started.
pub fn hunt_values<R>(
    renderer: &R,
    config: &ValueHuntConfig,
    jobs: usize,
    tick: &(dyn Fn() + Sync),
    interrupted: &AtomicBool,
) -> Result<ValueHuntReport, String>
where
    R: Renderer + ?Sized,
{
    let model = config.hunt.model;
    let case = |k: u64, scene: Scene| -> (u64, Scene, ValueVerdict) {
        let scene = with_values(scene, k, config);
        let verdict = judge_values(&scene, renderer.render(&scene), model);
        (k, scene, verdict)
    };
    let (requested, results) = run_cases(&config.hunt, jobs, "rasterproof-values-hunt", tick, interrupted, &case)?;
    let cases = results.len() as u64;
    let mut tally = CaseCounts::default();
    let mut first: BTreeMap<ValueSignature, FirstSeen> = BTreeMap::new();
    for (k, scene, verdict) in results {
        *match verdict {
            ValueVerdict::Same(_) => &mut tally.same,
            ValueVerdict::Differs(_) => &mut tally.differing,
            ValueVerdict::Failed(_) => &mut tally.failed,
            ValueVerdict::Refused(_) => &mut tally.refused,
        } += 1;
        for (sig, pixels) in value_signatures(&verdict) {
            let entry = first.entry(sig).or_insert_with(|| (k, scene.clone(), 0, 0));
            entry.2 += 1;
            entry.3 += pixels;
        }
    }
    let mut findings: Vec<ValueFinding> = first
        .into_iter()
        .map(|(signature, (case, original, cases, pixels))| {
            let shows =
                |s: &Scene| value_signatures(&judge_values(s, renderer.render(s), model)).contains_key(&signature);
            let ask = AskOnce::new(shows);
            let budget = shrink_budget(config.hunt.shrink_runs, interrupted);
            let (minimal, runs) =
                shrink_batched(&original, &mut |batch| ask.first_kept(batch), jobs.max(1), budget, None);
            let verdict = judge_values(&minimal, renderer.render(&minimal), model);
            ValueFinding {
                signature,
                case,
                cases,
                pixels,
                original,
                minimal,
                verdict,
                runs,
            }
        })
        .collect();
    findings.sort_by_key(|f| (f.case, f.signature));
    Ok(ValueHuntReport {
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

impl ValueFinding {
    /// The finding for people: its signature, where it was seen, the minimal scene's size
    /// and the first pixels of its verdict.
    pub fn to_text(&self, n: usize) -> String {
        let mut s = format!(
            "finding {n}: {} (first in case {}, in {} cases, {} pixels); shrunk to {} triangles in {} runs\n",
            self.signature.describe(),
            self.case,
            self.cases,
            self.pixels,
            self.minimal.triangles.len(),
            self.runs
        );
        match &self.verdict {
            ValueVerdict::Same(r) | ValueVerdict::Differs(r) => s.push_str(&r.to_text("minimal scene", "theirs", 5)),
            ValueVerdict::Failed(f) => s.push_str(&format!("  the renderer failed: {}\n", f.message)),
            ValueVerdict::Refused(e) => s.push_str(&format!("  not compared: {e}\n")),
        }
        s
    }
}

impl ValueHuntReport {
    /// The summary for people.
    pub fn to_text(&self) -> String {
        let mut s = format!(
            "values hunt ({} {}, provoking {}): {} of {} cases run: {} right, {} with values off, {} failed, {} not compared{}\n",
            self.config.interpolation.name(),
            "varying c",
            self.config.provoking.name(),
            self.cases,
            self.requested,
            self.same,
            self.differing,
            self.failed,
            self.refused,
            if self.interrupted { " (interrupted)" } else { "" }
        );
        if self.findings.is_empty() {
            s.push_str("nothing found\n");
        }
        for (n, f) in self.findings.iter().enumerate() {
            s.push_str(&f.to_text(n + 1));
        }
        s
    }

    /// Everything, as JSON: the counts and each finding with its minimal scene.
    pub fn to_json(&self, renderer: &str) -> Value {
        let findings: Vec<Value> = self
            .findings
            .iter()
            .map(|f| {
                json!({
                    "signature": f.signature.describe(),
                    "case": f.case,
                    "cases": f.cases,
                    "pixels": f.pixels,
                    "runs": f.runs,
                    "minimal": serde_json::from_str::<Value>(&f.minimal.to_json()).unwrap_or(Value::Null),
                })
            })
            .collect();
        json!({
            "renderer": renderer,
            "as": "values",
            "interpolation": self.config.interpolation.name(),
            "provoking_vertex": self.config.provoking.name(),
            "sampling": self.config.sampling.name(),
            "samples": self.config.hunt.samples.as_ref().map_or(1, |p| p.len()),
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
