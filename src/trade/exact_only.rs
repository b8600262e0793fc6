//! Workloads whose contenders are all exact or integer models (diamond-exit lines,
//! polygon fills): speed at the origin, the plan, and at each magnitude the model's own
//! refusal of the placed workload or its wrong pixels (the same at every accepted
//! magnitude: the answer is translation-invariant, see the module docs of
//! [`crate::trade`]).

use crate::convention::{Preset, Target};
use crate::model::plan::plan_scene;
use crate::model::{prepare, Model, Primitives};

use super::measure::{corner_subset, departure_metrics, departures, Pairs};
use super::report::{Axis, Cell, Outcome, Placement, PlanSummary, WorkloadReport};
use super::speed::{entries, model_jobs, refusal, Contender};
use super::triangles::SUBSET_SIDE;
use super::{Config, Family, Sizes};

/// One workload of exact contenders.
pub(crate) struct Spec<'a> {
    /// Its name.
    pub(crate) name: &'static str,
    /// Its family.
    pub(crate) family: Family,
    /// How it is built.
    pub(crate) description: String,
    /// How many primitives.
    pub(crate) count: usize,
    /// The primitives of these indices (ascending), at the origin.
    pub(crate) select: &'a dyn Fn(&[usize]) -> Primitives,
    /// All of them placed at a magnitude (px).
    pub(crate) place: &'a dyn Fn(i64) -> Primitives,
    /// The contenders: `(name, model)`.
    pub(crate) models: &'a [(&'static str, Model)],
    /// The baseline of the speed ratios.
    pub(crate) baseline: &'static str,
    /// Snapping moves no vertex.
    pub(crate) on_grid: bool,
}

fn reference(model: Model) -> Model {
    if model.snaps() {
        Model::ExactSnapped
    } else {
        Model::Exact
    }
}

fn plain(model: Model) -> bool {
    model.is_plain()
}

fn pairs(model: Model, prims: &Primitives, target: &Target) -> Result<Pairs, String> {
    let prepared = prepare(prims, target, model).map_err(|e| e.to_string())?;
    let mut p = Pairs::default();
    prepared.render(target, &mut p);
    Ok(p.sorted())
}

/// Measures one workload.
pub(crate) fn measure(spec: &Spec<'_>, config: &Config, sizes: &Sizes) -> WorkloadReport {
    let conv = Preset::D3d11.convention();
    let target = Target::new(sizes.canvas, sizes.canvas, conv).expect("a valid canvas");
    let corner = Target::new(SUBSET_SIDE, SUBSET_SIDE, conv).expect("a valid canvas");
    let all = (spec.select)(&(0..spec.count).collect::<Vec<_>>());
    let on_corner = pairs(Model::Exact, &all, &corner).expect("the planned engine takes every finite primitive");
    let sub = (spec.select)(&corner_subset(&on_corner, spec.count, sizes.plain_pixels));
    let inputs = |m: Model| if plain(m) { (&sub, &corner) } else { (&all, &target) };
    let reference_pairs = |m: Model| {
        let (prims, t) = inputs(m);
        pairs(reference(m), prims, t).expect("the planned engine takes every finite primitive")
    };
    let references: Vec<(Model, Pairs)> = spec.models.iter().map(|&(_, m)| (m, reference_pairs(m))).collect();

    let contenders = spec
        .models
        .iter()
        .zip(&references)
        .map(|(&(name, m), (_, r))| {
            let (prims, t) = inputs(m);
            Contender {
                name: name.into(),
                exact: m.is_exact(),
                reference: reference(m).name(),
                elements: r.0.len() as u64,
                subset: plain(m),
                jobs: model_jobs(m, prims, t),
            }
        })
        .collect();
    let speed = entries(contenders, sizes.repetitions, sizes.min_pass_seconds);

    let plans = [Model::Exact, Model::ExactSnapped]
        .into_iter()
        .filter(|m| spec.models.iter().any(|&(_, c)| reference(c) == *m))
        .filter_map(|m| {
            let p = plan_scene(&all, &target, m).ok()?;
            Some(PlanSummary {
                model: m.name(),
                by_width: p.by_width().into_iter().map(|(w, n)| (w.name(), n)).collect(),
                summary: p.summary(),
            })
        })
        .collect();

    let origin: Vec<Outcome> = spec
        .models
        .iter()
        .zip(&references)
        .map(|(&(_, m), (_, r))| {
            let (prims, t) = inputs(m);
            match pairs(m, prims, t) {
                Err(e) => Outcome::Refused(e),
                Ok(p) => Outcome::Measured {
                    placement: Placement::OnCanvas,
                    metrics: departure_metrics(&departures(r, &p, None), false),
                },
            }
        })
        .collect();
    let mut cells = Vec::new();
    for &mag in &config.magnitudes {
        let placed = (spec.place)(mag.px_i64());
        for (&(name, m), at_origin) in spec.models.iter().zip(&origin) {
            let outcome = if mag.px() == 0 {
                at_origin.clone()
            } else if let Err(e) = refusal(m, &placed, &target) {
                Outcome::Refused(e)
            } else {
                match at_origin {
                    Outcome::Measured { metrics, .. } => Outcome::Measured {
                        placement: Placement::Translated,
                        metrics: metrics.clone(),
                    },
                    refused => refused.clone(),
                }
            };
            cells.push(Cell {
                magnitude: mag,
                contender: name.into(),
                outcome,
            });
        }
    }
    WorkloadReport {
        name: spec.name.into(),
        family: spec.family,
        description: spec.description.clone(),
        primitives: spec.count,
        unit: "Mpix/s",
        baseline: spec.baseline,
        on_grid: spec.on_grid,
        plans,
        speed,
        cells,
        axis: Axis::Offset,
    }
}
