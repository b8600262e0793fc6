//! Fitting an interpolator: which float model of [`crate::interp::float`] reproduces
//! their float32 values bit for bit ([`fit_values`]).
//!
//! Every model of [`FloatInterpolator::all`] runs on the renderer's inputs as the models
//! assume it held them (each window position, `w` and value rounded to the nearest f32,
//! `1 / w` an f32 division) at every pixel the oracle covers, and its f32 result is
//! compared with theirs bit for bit. Models that agree everywhere are named; otherwise the
//! closest five, with their differing pixels and largest distance in f32 steps.

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::super::values::{covered_owners, their_channels, their_values, Plans, TheirValue, ValueOptions};
use super::super::{CompareError, Comparison};
use crate::convention::Target;
use crate::interp::float::{FloatInterpolator, FloatTriangle};
use crate::model::Primitives;
use crate::oracle::theirs::{Theirs, ValueSamples};

/// One model's agreement with their values.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelFit {
    /// The model.
    pub model: FloatInterpolator,
    /// Channels (of judged pixels) where its f32 differs from theirs.
    pub differing: usize,
    /// The largest distance in f32 steps between its value and theirs.
    pub max_steps: u64,
}

/// The models ordered by how well they reproduce their values.
#[derive(Debug, Clone, PartialEq)]
pub struct ValueFitReport {
    /// The varying fitted.
    pub varying: String,
    /// Channels judged (pixels times channels).
    pub judged: usize,
    /// Pixels the models do not cover (a primitive other than a window-space triangle,
    /// or an input beyond f32).
    pub skipped: usize,
    /// Every model, the fewest differences first.
    pub models: Vec<ModelFit>,
}

impl ValueFitReport {
    /// The models that reproduce every judged value.
    pub fn exact(&self) -> Vec<&ModelFit> {
        self.models.iter().filter(|m| m.differing == 0).collect()
    }
}

/// Which float models reproduce their float32 values of `options.varying` (module docs).
///
/// # Errors
/// Their image is not float32 values of the canvas's size with the varying's channels;
/// the oracle model is not exact or refuses the scene.
pub fn fit_values(
    primitives: &Primitives,
    target: &Target,
    theirs: &Theirs,
    options: &ValueOptions,
) -> Result<ValueFitReport, CompareError> {
    let (image, varying, range) = their_values(target, theirs, options)?;
    if !matches!(image.samples, ValueSamples::F32(_)) {
        return Err(CompareError::Values(
            "--fit reproduces float32 values bit for bit; their image holds UNORM levels".to_string(),
        ));
    }
    if let Some(pattern) = &options.pattern {
        return Err(CompareError::Values(format!(
            "--fit runs the float models at pixel centres, one sample per pixel; their image is stacked for the {pattern} pattern (compare it without --fit, or fit a one-sample rendering)"
        )));
    }
    let owners = covered_owners(primitives, target, options)?;
    let mut plans = Plans::new(options, range.clone(), target);
    let models = FloatInterpolator::all();
    let mut fits: Vec<ModelFit> = models
        .iter()
        .map(|&model| ModelFit {
            model,
            differing: 0,
            max_steps: 0,
        })
        .collect();
    let mut triangles: Vec<Option<Option<FloatTriangle>>> = vec![None; options.setups.len()];
    let (mut judged_channels, mut skipped) = (0, 0);
    let centre = if target.convention.pixel_centre.offset() == num_rational::BigRational::new(1.into(), 2.into()) {
        0.5
    } else {
        0.0
    };
    for &(x, y, id) in &owners {
        // A pixel without an exact value (a polygon's, on a horizon) is not judged.
        if plans.of(id).is_none_or(|p| p.nearest(x, y).is_err()) {
            continue;
        }
        let id = id as usize;
        let triangle = triangles[id]
            .get_or_insert_with(|| options.setups[id].as_ref().and_then(FloatTriangle::of))
            .as_ref();
        let Some(triangle) = triangle else {
            skipped += 1;
            continue;
        };
        let theirs_here = their_channels(image, x, y, varying.channels);
        for (c, t) in theirs_here.iter().enumerate() {
            let TheirValue::F32(t) = *t else { continue };
            judged_channels += 1;
            for fit in &mut fits {
                let v = fit.model.value(
                    triangle,
                    varying.interpolation,
                    options.varyings.provoking,
                    range.start + c,
                    (x, y),
                    target.height,
                    centre,
                );
                if v.to_bits() != t.to_bits() {
                    fit.differing += 1;
                    fit.max_steps = fit.max_steps.max(super::super::values::f32_steps(v, t));
                }
            }
        }
    }
    fits.sort_by_key(|f| (f.differing, f.max_steps));
    Ok(ValueFitReport {
        varying: varying.name.clone(),
        judged: judged_channels,
        skipped,
        models: fits,
    })
}

impl Comparison for ValueFitReport {
    fn identical(&self) -> bool {
        !self.exact().is_empty()
    }

    fn counts(&self) -> Vec<(String, usize)> {
        self.exact().iter().map(|m| (m.model.name(), 0)).collect()
    }

    fn to_text(&self, scene: &str, theirs: &str, limit: usize) -> String {
        let mut s = format!(
            "{theirs} against {scene}, values of {:?}: {} channel values judged",
            self.varying, self.judged
        );
        if self.skipped > 0 {
            let _ = write!(s, " ({} pixels skipped: not a window-space triangle's)", self.skipped);
        }
        s.push('\n');
        let exact = self.exact();
        if exact.is_empty() {
            s.push_str("no model reproduces every value bit for bit; the closest:\n");
        } else {
            let _ = writeln!(s, "{} models reproduce every value bit for bit:", exact.len());
        }
        let shown = if exact.is_empty() { 5 } else { exact.len() };
        for m in self.models.iter().take(shown.min(limit.max(5))) {
            let _ = writeln!(
                s,
                "  {:<48} {} differing, at most {} f32 steps",
                m.model.name(),
                m.differing,
                m.max_steps
            );
        }
        s
    }

    fn to_json(&self, scene: &str, theirs: &str) -> Value {
        let models: Vec<Value> = self
            .models
            .iter()
            .map(|m| json!({"model": m.model.name(), "differing": m.differing, "max_f32_steps": m.max_steps}))
            .collect();
        json!({
            "scene": scene,
            "theirs": theirs,
            "as": "values",
            "fit": true,
            "varying": self.varying,
            "judged": self.judged,
            "skipped": self.skipped,
            "exact": self.exact().iter().map(|m| m.model.name()).collect::<Vec<_>>(),
            "models": models,
        })
    }
}
