//! What their renderer did with one scene: the [`HuntVerdict`] ([`judge`]), the case's
//! [`CaseOutcome`] that hunt counts, and the [`Signature`]s hunt deduplicates failures by
//! ([`signatures`]).

use crate::model::Model;
use crate::oracle::compare::samples::{compare_samples, SampleCompareReport, SampleOptions};
use crate::oracle::compare::{compare, CompareReport, PixelKind, CLASSIFY_AT_MOST};
use crate::oracle::reason::ReasonClass;
use crate::oracle::renderer::program::{FailureKind, RenderFailure};
use crate::oracle::theirs::Theirs;
use crate::scene::Scene;

/// What their renderer did with one scene.
#[derive(Debug, Clone)]
pub enum HuntVerdict {
    /// Identical to the oracle.
    Same,
    /// Different: the comparison.
    Differs(Box<CompareReport>),
    /// Different under a pattern of several samples: every sample index's comparison.
    DiffersPerSample(Box<SampleCompareReport>),
    /// Their renderer failed.
    Failed(RenderFailure),
    /// The oracle refused the scene (it is outside the model's envelope): not their fault.
    Refused(String),
}

/// Compares their output (or failure) on `scene` with `model`'s: sample index by sample
/// index when the scene has a pattern of several samples (their output is then the
/// stacked per-sample image).
pub fn judge(scene: &Scene, theirs: Result<Theirs, RenderFailure>, model: Model) -> HuntVerdict {
    let theirs = match theirs {
        Ok(t) => t,
        Err(f) => return HuntVerdict::Failed(f),
    };
    let Ok(target) = scene.target() else {
        return HuntVerdict::Refused("invalid canvas or convention".to_string());
    };
    if let Some(pattern) = scene.samples.as_ref().filter(|p| !p.is_single(&target.convention)) {
        let options = SampleOptions {
            pattern: pattern.clone(),
            model,
            classify_at_most: Some(CLASSIFY_AT_MOST),
        };
        return match compare_samples(&scene.primitives(), &target, &theirs, &options) {
            Ok(r) if r.identical() => HuntVerdict::Same,
            Ok(r) => HuntVerdict::DiffersPerSample(Box::new(r)),
            Err(crate::oracle::CompareError::Samples(message)) => HuntVerdict::Failed(RenderFailure {
                kind: FailureKind::BadOutput,
                message,
            }),
            Err(e) => HuntVerdict::Refused(e.to_string()),
        };
    }
    match compare(&scene.primitives(), &target, &theirs, &model.into()) {
        Ok(r) if r.identical() => HuntVerdict::Same,
        Ok(r) => HuntVerdict::Differs(Box::new(r)),
        Err(e) => HuntVerdict::Refused(e.to_string()),
    }
}

/// How one case ended, as hunt counts it: its [`HuntVerdict`] without the evidence.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum CaseOutcome {
    /// Identical to the oracle.
    Same,
    /// Different.
    Differs,
    /// Their renderer failed.
    Failed,
    /// The oracle refused the scene.
    Refused,
}

impl CaseOutcome {
    /// The outcome of `verdict`.
    pub(super) fn of(verdict: &HuntVerdict) -> CaseOutcome {
        match verdict {
            HuntVerdict::Same => CaseOutcome::Same,
            HuntVerdict::Differs(_) | HuntVerdict::DiffersPerSample(_) => CaseOutcome::Differs,
            HuntVerdict::Failed(_) => CaseOutcome::Failed,
            HuntVerdict::Refused(_) => CaseOutcome::Refused,
        }
    }

    /// In one word: `same`, `differs`, `failed` or `refused`.
    pub(super) fn name(self) -> &'static str {
        match self {
            CaseOutcome::Same => "same",
            CaseOutcome::Differs => "differs",
            CaseOutcome::Failed => "failed",
            CaseOutcome::Refused => "refused",
        }
    }
}

/// A distinct failure: what hunt deduplicates by.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Signature {
    /// Differing pixels of one cause: the reason class and the primitive kind
    /// (`triangles`, `lines`, `polygons`, or `none` when no primitive explains it). The
    /// pixels' kinds (missing, extra, wrong owner, double) are not part of it: one tie bug
    /// shows as missing and extra pixels at once, and is one finding ([`pixel_kinds`]
    /// lists its kinds).
    Pixel(ReasonClass, String),
    /// Their renderer failed this way.
    Failure(FailureKind),
}

impl Signature {
    /// In words: `tie, triangles`.
    pub fn describe(&self) -> String {
        match self {
            Signature::Pixel(class, primitive) => format!("{}, {primitive}", class.name()),
            Signature::Failure(kind) => kind.name().to_string(),
        }
    }

    /// For file and test names: `tie_triangles`.
    pub fn slug(&self) -> String {
        self.describe()
            .chars()
            .map(|c| {
                if c.is_ascii_alphanumeric() {
                    c.to_ascii_lowercase()
                } else {
                    '_'
                }
            })
            .collect::<String>()
            .split('_')
            .filter(|s| !s.is_empty())
            .collect::<Vec<_>>()
            .join("_")
    }
}

/// The comparisons a verdict holds: one, or one per sample index.
fn reports(verdict: &HuntVerdict) -> Vec<&CompareReport> {
    match verdict {
        HuntVerdict::Differs(r) => vec![r],
        HuntVerdict::DiffersPerSample(r) => r.samples.iter().collect(),
        _ => Vec::new(),
    }
}

/// Every signature a verdict shows (none for `Same` and `Refused`).
pub fn signatures(verdict: &HuntVerdict) -> Vec<Signature> {
    let mut out = Vec::new();
    match verdict {
        HuntVerdict::Differs(_) | HuntVerdict::DiffersPerSample(_) => {
            for r in reports(verdict) {
                for p in &r.pixels {
                    for f in &p.findings {
                        out.push(Signature::Pixel(f.reason.class(), primitive_kind(f)));
                    }
                }
            }
        }
        HuntVerdict::Failed(f) => out.push(Signature::Failure(f.kind)),
        HuntVerdict::Same | HuntVerdict::Refused(_) => {}
    }
    out.sort();
    out.dedup();
    out
}

/// The kinds of the differing pixels (missing, extra, wrong owner, double) that show
/// `signature` in `verdict`, in [`PixelKind`] order; empty for a renderer failure.
pub fn pixel_kinds(verdict: &HuntVerdict, signature: &Signature) -> Vec<PixelKind> {
    let mut out = Vec::new();
    if let Signature::Pixel(class, primitive) = signature {
        for p in reports(verdict).into_iter().flat_map(|r| &r.pixels) {
            if p.findings
                .iter()
                .any(|f| f.reason.class() == *class && primitive_kind(f) == *primitive)
            {
                out.push(p.kind);
            }
        }
    }
    out.sort();
    out.dedup();
    out
}

/// The kind of primitive a finding names: `triangles`, `lines`, `polygons`, or `none`.
fn primitive_kind(f: &crate::oracle::PixelFinding) -> String {
    f.primitive
        .as_deref()
        .and_then(|n| n.split('[').next())
        .unwrap_or("none")
        .to_string()
}
