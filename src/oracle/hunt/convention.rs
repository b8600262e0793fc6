//! The convention a hunt states in its scenes when it follows a fit of their renderer's
//! output ([`hunt_convention`], [`preferred`]), and the fit made before a hunt
//! ([`fit_convention`], `hunt --fit-first`; under a pattern of several samples also the
//! sample positions, [`fit_sample_convention`]).

use super::{generate_scene, HuntConfig, SceneFamily};
use num_rational::BigRational;

use crate::convention::{AnyTieRule, PixelCentre, Target, TieRule};
use crate::model::Model;
use crate::oracle::compare::fit::samples::{fit_positions, fit_samples, SampleFitOptions, POSITION_GRID};
use crate::oracle::compare::fit::{fit, Candidate};
use crate::oracle::renderer::program::Renderer;
use crate::pattern::SamplePattern;
use crate::scene::Overrides;

/// How many tie-heavy probe scenes [`fit_convention`] renders: the conventions that
/// explain every one of them are kept (one scene rarely tells every rule and snapping
/// apart).
pub const FIT_PROBES: u64 = 6;

/// What the fit before a hunt ([`fit_convention`]) found about the renderer.
#[derive(Debug, Clone, PartialEq)]
pub enum FitFirst {
    /// A convention that explains every probe and that a scene file can state: hunt
    /// under it (set `overrides` and `model` on the config).
    Statable {
        /// The fit ([`preferred`] among the exact ones).
        fit: Candidate,
        /// The scene overrides that state it.
        overrides: Overrides,
        /// The oracle model that draws it.
        model: Model,
    },
    /// Conventions that explain every probe, none of which a scene file can state (a tie
    /// rule other than top-left and bottom-left, or a 0-bit grid): what the renderer
    /// follows, found; a hunt under any other convention would report its every tie.
    Unstatable(Vec<Candidate>),
    /// No convention explains every probe; the last probe's fit, as text.
    NoneExplains(String),
}

/// `hunt --fit-first`: the conventions that explain `render`'s images of [`FIT_PROBES`]
/// tie-heavy probe scenes (mesh scenes drawn from `config`'s seed and convention), and
/// whether hunt can state one of them ([`FitFirst`]).
///
/// # Errors
/// A probe scene cannot be made, the renderer fails on one, or the fit refuses one.
pub fn fit_convention(renderer: &dyn Renderer, config: &HuntConfig) -> Result<FitFirst, String> {
    let probe = HuntConfig {
        families: vec![SceneFamily::Mesh],
        ..config.clone()
    };
    let mut exact: Option<Vec<Candidate>> = None;
    let mut last = None;
    for k in 0..FIT_PROBES {
        let scene = generate_scene(&probe, u64::MAX - k)?;
        let target = scene
            .target()
            .map_err(|e| format!("--fit-first: invalid probe scene: {e}"))?;
        let theirs = renderer
            .render(&scene)
            .map_err(|f| format!("--fit-first: the renderer failed on a probe scene: {f}"))?;
        let found = fit(&scene.primitives(), &target, &theirs).map_err(|e| format!("--fit-first: {e}"))?;
        exact = Some(match exact {
            None => found.exact.clone(),
            Some(kept) => kept.into_iter().filter(|c| found.exact.contains(c)).collect(),
        });
        last = Some(found);
    }
    let exact = exact.unwrap_or_default();
    if exact.is_empty() {
        return Ok(FitFirst::NoneExplains(last.map(|f| f.fit_text()).unwrap_or_default()));
    }
    let Some(fit) = preferred(&exact) else {
        return Ok(FitFirst::Unstatable(exact));
    };
    let (overrides, model) = hunt_convention(&fit).expect("preferred only returns statable conventions");
    Ok(FitFirst::Statable { fit, overrides, model })
}

/// The convention a fit names, as scene overrides and the oracle model, when hunt can
/// state it in a scene file: a top-left or bottom-left rule and 1..=16 bits (the oracle
/// `exact-snapped`) or no snapping (`exact`).
pub fn hunt_convention(c: &Candidate) -> Option<(Overrides, Model)> {
    let tie_rule = match c.tie_rule {
        AnyTieRule::TopLeft => TieRule::TopLeft,
        AnyTieRule::BottomLeft => TieRule::BottomLeft,
        _ => return None,
    };
    let mut o = Overrides {
        tie_rule: Some(tie_rule),
        pixel_centre: Some(c.pixel_centre),
        ..Overrides::default()
    };
    match c.snapping.bits {
        None => Some((o, Model::Exact)),
        Some(0) => None,
        Some(b) => {
            o.subpixel_bits = Some(b);
            o.rounding = Some(c.snapping.rounding);
            Some((o, Model::ExactSnapped))
        }
    }
}

/// The fit hunt prefers among exact ones: one it can state ([`hunt_convention`]), at the
/// usual 8 bits or else the most bits, nearest-even, pixel centre 0.5, top-left.
pub fn preferred(exact: &[Candidate]) -> Option<Candidate> {
    exact
        .iter()
        .copied()
        .filter(|c| hunt_convention(c).is_some())
        .min_by_key(|c| {
            let bits = c
                .snapping
                .bits
                .map_or(17, |b| if b == 8 { 0 } else { 17 - i64::from(b) });
            (
                bits,
                c.snapping.rounding != crate::num::Rounding::NearestEven,
                c.pixel_centre != PixelCentre::Half,
                c.tie_rule != AnyTieRule::TopLeft,
            )
        })
}

/// A sample index whose position [`fit_sample_convention`] moved: the pattern's position,
/// the one taken, and how many grid positions gave its image on every probe.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MovedSample {
    /// The sample index.
    pub index: usize,
    /// The position the hunt's pattern states for it.
    pub from: [BigRational; 2],
    /// The position taken: of those that fit, the nearest to `from` (then the first in
    /// grid order).
    pub to: [BigRational; 2],
    /// How many positions of the 1/16 px grid gave its image on every probe.
    pub fitting: usize,
}

/// What [`fit_sample_convention`] found: the convention (as [`fit_convention`] says it),
/// and when it is statable, the pattern to hunt under and the samples moved in it.
#[derive(Debug, Clone, PartialEq)]
pub struct SampleFitFirst {
    /// The convention found.
    pub convention: FitFirst,
    /// The pattern to hunt under: `config.samples` with the moved samples at their fitted
    /// positions.
    pub pattern: SamplePattern,
    /// The sample indices whose position moved, in index order.
    pub moved: Vec<MovedSample>,
}

/// `hunt --samples N --fit-first`: the convention and the sample positions that explain
/// `renderer`'s stacked per-sample images of [`FIT_PROBES`] tie-heavy probe scenes under
/// `config.samples`.
///
/// Each sample index's image is fitted against every convention, the scene moved to the
/// pattern's position for it ([`fit_samples`]), and the conventions kept that explain it
/// on every probe. When one convention explains every index, the pattern stands. When
/// not, the indices explained by the convention that explains the most of them
/// ([`preferred`] among those) are taken to sit where the pattern says; under that
/// convention each other index's image is fitted
/// against every position of the 1/16 px grid ([`fit_positions`]) on every probe, and the
/// nearest fitting one to the pattern's is taken (a moved sample, as a programmable or
/// mistaken position moves it).
///
/// # Errors
/// `config.samples` is not a pattern of several samples; a probe scene cannot be made,
/// the renderer fails on one, or the fit refuses one.
pub fn fit_sample_convention(renderer: &dyn Renderer, config: &HuntConfig) -> Result<SampleFitFirst, String> {
    let Some(pattern) = config.samples.clone().filter(|p| p.len() > 1) else {
        return Err("--fit-first: a multisample fit needs a pattern of several samples".to_string());
    };
    let probe = HuntConfig {
        families: vec![SceneFamily::Mesh],
        ..config.clone()
    };
    let mut probes = Vec::new();
    // Per sample index, the conventions that explain its image on every probe so far.
    let mut explained: Vec<Option<Vec<Candidate>>> = vec![None; pattern.len()];
    for k in 0..FIT_PROBES {
        let scene = generate_scene(&probe, u64::MAX - k)?;
        let target = scene
            .target()
            .map_err(|e| format!("--fit-first: invalid probe scene: {e}"))?;
        let theirs = renderer
            .render(&scene)
            .map_err(|f| format!("--fit-first: the renderer failed on a probe scene: {f}"))?;
        let options = SampleFitOptions {
            pattern: pattern.clone(),
            grid: 1,
        };
        let found =
            fit_samples(&scene.primitives(), &target, &theirs, &options).map_err(|e| format!("--fit-first: {e}"))?;
        for (kept, fit) in explained.iter_mut().zip(&found.samples) {
            *kept = Some(match kept.take() {
                None => fit.exact.clone(),
                Some(kept) => kept.into_iter().filter(|c| fit.exact.contains(c)).collect(),
            });
        }
        let per_sample = theirs
            .unstack(pattern.len(), target.height)
            .map_err(|e| format!("--fit-first: {e}"))?;
        probes.push((scene, target, per_sample));
    }
    let explained: Vec<Vec<Candidate>> = explained.into_iter().map(Option::unwrap_or_default).collect();
    // The conventions that explain the most sample indices (all of them, for a renderer
    // at the pattern's positions).
    let explains = |c: &Candidate| explained.iter().filter(|e| e.contains(c)).count();
    let most = explained.iter().flatten().map(explains).max().unwrap_or(0);
    let mut best: Vec<Candidate> = Vec::new();
    for c in explained.iter().flatten() {
        if explains(c) == most && !best.contains(c) {
            best.push(*c);
        }
    }
    let standing = |convention| SampleFitFirst {
        convention,
        pattern: pattern.clone(),
        moved: Vec::new(),
    };
    if most == 0 {
        return Ok(standing(FitFirst::NoneExplains(format!(
            "no convention explains any sample index's image at the pattern's position ({pattern})"
        ))));
    }
    let Some(fit) = preferred(&best) else {
        return Ok(standing(FitFirst::Unstatable(best)));
    };
    let (overrides, model) = hunt_convention(&fit).expect("preferred only returns statable conventions");
    let statable = FitFirst::Statable { fit, overrides, model };
    let placed: Vec<usize> = (0..pattern.len()).filter(|&s| explained[s].contains(&fit)).collect();
    if placed.len() == pattern.len() {
        return Ok(standing(statable));
    }
    let mut positions = pattern.positions().to_vec();
    let mut moved = Vec::new();
    for s in (0..pattern.len()).filter(|s| !placed.contains(s)) {
        let mut fitting: Option<Vec<[BigRational; 2]>> = None;
        for (scene, target, per_sample) in &probes {
            let target = Target {
                convention: overrides.apply(target.convention.preset),
                ..*target
            };
            let found = fit_positions(&scene.primitives(), &target, &pattern, per_sample, model, POSITION_GRID)
                .map_err(|e| format!("--fit-first: {e}"))?;
            let here = &found[s].fits;
            fitting = Some(match fitting {
                None => here.clone(),
                Some(kept) => kept.into_iter().filter(|p| here.contains(p)).collect(),
            });
        }
        let fitting = fitting.unwrap_or_default();
        let from = pattern.positions()[s].clone();
        let distance = |p: &[BigRational; 2]| {
            let (dx, dy) = (&p[0] - &from[0], &p[1] - &from[1]);
            &dx * &dx + &dy * &dy
        };
        let Some(to) = fitting.iter().min_by_key(|p| distance(p)).cloned() else {
            return Ok(standing(FitFirst::NoneExplains(format!(
                "sample {s} at {}: under {fit}, which explains the other sample indices, no position of the \
                 1/{POSITION_GRID} px grid gives its image on every probe",
                pattern.position_text(s)
            ))));
        };
        positions[s] = to.clone();
        moved.push(MovedSample {
            index: s,
            from,
            to,
            fitting: fitting.len(),
        });
    }
    let pattern = SamplePattern::custom(positions).map_err(|e| format!("--fit-first: the fitted positions: {e}"))?;
    Ok(SampleFitFirst {
        convention: statable,
        pattern,
        moved,
    })
}
