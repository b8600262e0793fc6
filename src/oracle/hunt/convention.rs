//! The convention a hunt states in its scenes when it follows a fit of their renderer's
//! output ([`hunt_convention`], [`preferred`]), and the fit made before a hunt
//! ([`fit_convention`], `hunt --fit-first`).

use super::{generate_scene, HuntConfig, SceneFamily};
use crate::convention::{AnyTieRule, PixelCentre, TieRule};
use crate::model::Model;
use crate::oracle::compare::fit::{fit, Candidate};
use crate::oracle::renderer::program::Renderer;
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
