//! The triangle workloads (pixel-sized, medium, huge, sliver; a tie-heavy and a random
//! spade mesh) and every triangle model on them: speed at the origin, the plan, and per
//! magnitude the wrong pixels, the meshes' gaps and double covers, barycentric sums and
//! Gouraud channels.

use glam::{DVec2, Vec2};

use crate::check::{check_barycentric_exact, check_barycentric_fixed, float_sum_error_ulps};
use crate::convention::{Preset, Target};
use crate::geom::{Rgb, Triangle};
use crate::interp::{barycentric_f32, barycentric_f64, gouraud_exact, gouraud_f32, gouraud_f64, to_channel};
use crate::model::plan::plan_scene;
use crate::model::{prepare, Model, Primitives};
use crate::raster::sample_exact;
use crate::strategy::{triangle, TriangleScale};
use crate::tri::float::{self, FloatRule};

use super::far::FarWindow;
use super::measure::{
    corner_subset, departure_metrics, departures, median_max, shared_edge_pixels, Pairs, BARYCENTRIC_EXACT,
    BARYCENTRIC_ULPS, GOURAUD,
};
use super::metric::Metric;
use super::report::{Axis, Cell, Outcome, Placement, PlanSummary, SpeedEntry, WorkloadReport};
use super::speed::{entries, model_jobs, refusal, Contender};
use super::workloads::{colours, draw_n, mesh, place_triangles, runner};
use super::{Config, Family, Sizes};

/// The contenders, in report order: every model of [`Model::ALL`], the exact ones first,
/// unsnapped before snapped and each plain oracle just before its planned engine
/// (`exact-plain`, `exact`, `exact-snapped-plain`, `exact-snapped`), then the integer and
/// float models in their [`Model::ALL`] order. A new model joins the trade by itself.
fn models() -> Vec<Model> {
    let mut all = Model::ALL.to_vec();
    // A stable sort: the models of one key keep their order in `ALL`.
    all.sort_by_key(|&m| {
        if m.is_unbounded() {
            (u8::from(m.snaps()), u8::from(!m.is_plain()))
        } else {
            (2, 0)
        }
    });
    all
}

/// The side of the plain oracles' corner.
pub(crate) const SUBSET_SIDE: u32 = 32;

/// One triangle workload.
struct Workload {
    name: &'static str,
    description: String,
    triangles: Vec<Triangle>,
    colours: Vec<[Rgb; 3]>,
    /// A mesh: count gaps and double covers.
    mesh: bool,
}

fn workloads(config: &Config, sizes: &Sizes) -> Vec<Workload> {
    let (s, n) = (sizes.canvas, sizes.count);
    let family = |name: &'static str, scale: TriangleScale, count: usize, what: &str| {
        let mut r = runner(config.seed, name);
        let triangles = draw_n(&mut r, &triangle(scale, s), count);
        let colours = colours(&mut r, count);
        Workload {
            name,
            description: format!("{count} random triangles: {what} (strategy::TriangleScale::{scale:?})."),
            triangles,
            colours,
            mesh: false,
        }
    };
    let meshed = |name: &'static str, bits: u32, points: usize, what: &str| {
        let mut r = runner(config.seed, name);
        let m = mesh(&mut r, s, bits, points);
        let colours = colours(&mut r, m.triangles.len());
        Workload {
            name,
            description: format!(
                "A spade Delaunay triangulation of {points} random points on the {what} grid ({} triangles).",
                m.triangles.len()
            ),
            triangles: m.triangles,
            colours,
            mesh: true,
        }
    };
    vec![
        family(
            "pixel triangles",
            TriangleScale::Pixel,
            2000 * n,
            "vertices within 2 px of each other, 1/256 px grid",
        ),
        family(
            "medium triangles",
            TriangleScale::Medium,
            10 * n,
            "vertices anywhere on the canvas, 1/256 px grid",
        ),
        family(
            "huge triangles",
            TriangleScale::Huge,
            2 * n,
            "two vertices up to 2^21 px away, one on the canvas",
        ),
        family(
            "sliver triangles",
            TriangleScale::Sliver,
            100 * n,
            "long and thin, the third vertex within 4/256 px of the line (1/65536 px grid)",
        ),
        meshed(
            "tie-heavy mesh",
            1,
            100 * n,
            "half-pixel (vertices on pixel centres and corners)",
        ),
        meshed("random mesh", 8, 100 * n, "1/256 px"),
    ]
}

/// Measures every triangle workload.
pub(crate) fn run(config: &Config, sizes: &Sizes, progress: &mut dyn FnMut(&str)) -> Vec<WorkloadReport> {
    workloads(config, sizes)
        .iter()
        .map(|w| {
            progress(&format!("triangles: {}", w.name));
            measure(w, config, sizes)
        })
        .collect()
}

/// The planned exact engine a model's errors are counted against.
fn reference(model: Model) -> Model {
    if model.snaps() {
        Model::ExactSnapped
    } else {
        Model::Exact
    }
}

/// A model's covered pairs on `target`.
fn pairs(model: Model, triangles: &[Triangle], target: &Target) -> Result<Pairs, String> {
    let prepared = prepare(&Primitives::from_triangles(triangles), target, model).map_err(|e| e.to_string())?;
    let mut p = Pairs::default();
    prepared.render(target, &mut p);
    Ok(p.sorted())
}

/// The reference of one size: its pairs and the mesh mask.
struct Reference {
    pairs: Pairs,
    mask: Option<(Vec<bool>, u32)>,
}

impl Reference {
    fn new(model: Model, triangles: &[Triangle], target: &Target, mesh: bool) -> Reference {
        let pairs = pairs(model, triangles, target).expect("the planned engine takes every finite triangle");
        let mask = mesh.then(|| (shared_edge_pixels(&pairs, target.width).0, target.width));
        Reference { pairs, mask }
    }

    fn mask(&self) -> Option<(&[bool], u32)> {
        self.mask.as_ref().map(|(m, s)| (m.as_slice(), *s))
    }
}

/// The plain oracles' subset: the triangles that cover the corner, until `pixels`, with
/// their colours.
fn subset(w: &Workload, corner: &Target, pixels: u64) -> (Vec<Triangle>, Vec<[Rgb; 3]>) {
    let exact = pairs(Model::Exact, &w.triangles, corner).expect("the planned engine takes every finite triangle");
    let ids = corner_subset(&exact, w.triangles.len(), pixels);
    (
        ids.iter().map(|&k| w.triangles[k].clone()).collect(),
        ids.iter().map(|&k| w.colours[k]).collect(),
    )
}

/// A workload with the exact answers its models are measured against: the whole
/// canvas's, and the corner subset's (for the plain oracles, slow by design).
struct Stage<'a> {
    w: &'a Workload,
    target: Target,
    corner: Target,
    sub: Vec<Triangle>,
    sub_colours: Vec<[Rgb; 3]>,
    /// The unsnapped and snapped planned engines' answers on the whole workload.
    full_refs: [Reference; 2],
    /// The same on the corner subset.
    sub_refs: [Reference; 2],
}

impl<'a> Stage<'a> {
    fn new(w: &'a Workload, sizes: &Sizes) -> Stage<'a> {
        let conv = Preset::D3d11.convention();
        let target = Target::new(sizes.canvas, sizes.canvas, conv).expect("a valid canvas");
        let corner = Target::new(SUBSET_SIDE, SUBSET_SIDE, conv).expect("a valid canvas");
        let (sub, sub_colours) = subset(w, &corner, sizes.plain_pixels);
        let full_refs = [
            Reference::new(Model::Exact, &w.triangles, &target, w.mesh),
            Reference::new(Model::ExactSnapped, &w.triangles, &target, w.mesh),
        ];
        let sub_refs = [
            Reference::new(Model::Exact, &sub, &corner, w.mesh),
            Reference::new(Model::ExactSnapped, &sub, &corner, w.mesh),
        ];
        Stage {
            w,
            target,
            corner,
            sub,
            sub_colours,
            full_refs,
            sub_refs,
        }
    }

    /// What `model` is measured on: the triangles, the target, the reference and the
    /// colours (the corner subset for the plain oracles, the whole workload otherwise).
    fn pick(&self, m: Model) -> (&[Triangle], &Target, &Reference, &[[Rgb; 3]]) {
        let k = usize::from(reference(m) == Model::ExactSnapped);
        if m.is_plain() {
            (&self.sub, &self.corner, &self.sub_refs[k], &self.sub_colours)
        } else {
            (&self.w.triangles, &self.target, &self.full_refs[k], &self.w.colours)
        }
    }
}

fn measure(w: &Workload, config: &Config, sizes: &Sizes) -> WorkloadReport {
    let stage = Stage::new(w, sizes);
    let models = models();
    let speed = speed_at_origin(&stage, &models, sizes);
    let plans = plans(&stage);
    let origin = errors_at_origin(&stage, &models, sizes.samples);
    let cells = errors_by_magnitude(&stage, &origin, config, sizes);
    let conv = stage.target.convention;
    let on_grid = w.triangles.iter().all(|t| t.snapped(&conv).to_exact() == *t);
    WorkloadReport {
        name: w.name.into(),
        family: Family::Triangles,
        description: w.description.clone(),
        primitives: w.triangles.len(),
        unit: "Mpix/s",
        baseline: Model::Fixed.name(),
        on_grid,
        plans,
        speed,
        cells,
        axis: Axis::Offset,
    }
}

/// Speed at the origin, round-robin: the draw of the prepared workload, and prepare and
/// draw.
fn speed_at_origin(stage: &Stage<'_>, models: &[Model], sizes: &Sizes) -> Vec<SpeedEntry> {
    let prims: Vec<Primitives> = models
        .iter()
        .map(|&m| Primitives::from_triangles(stage.pick(m).0))
        .collect();
    let contenders = models
        .iter()
        .zip(&prims)
        .map(|(&m, p)| {
            let (_, t, r, _) = stage.pick(m);
            Contender {
                name: m.name().into(),
                exact: m.is_exact(),
                reference: reference(m).name(),
                elements: r.pairs.0.len() as u64,
                subset: m.is_plain(),
                jobs: model_jobs(m, p, t),
            }
        })
        .collect();
    entries(contenders, sizes.repetitions, sizes.min_pass_seconds)
}

/// The exact engines' plans of the whole workload.
fn plans(stage: &Stage<'_>) -> Vec<PlanSummary> {
    let prims = Primitives::from_triangles(&stage.w.triangles);
    [Model::Exact, Model::ExactSnapped]
        .into_iter()
        .filter_map(|m| {
            let p = plan_scene(&prims, &stage.target, m).ok()?;
            Some(PlanSummary {
                model: m.name(),
                by_width: p.by_width().into_iter().map(|(w, n)| (w.name(), n)).collect(),
                summary: p.summary(),
            })
        })
        .collect()
}

/// Errors at the origin, for every model (the exact and integer ones keep them at every
/// magnitude).
fn errors_at_origin(stage: &Stage<'_>, models: &[Model], samples: usize) -> Vec<(Model, Outcome)> {
    models
        .iter()
        .map(|&m| {
            let (tris, t, r, colours) = stage.pick(m);
            let outcome = match origin_metrics(m, tris, colours, t, r, samples) {
                Ok(metrics) => Outcome::Measured {
                    placement: Placement::OnCanvas,
                    metrics,
                },
                Err(e) => Outcome::Refused(e),
            };
            (m, outcome)
        })
        .collect()
}

/// Every model's errors at every magnitude: the origin's where the model keeps them
/// (exact models translate, refusals stay), measured far away for the others.
fn errors_by_magnitude(stage: &Stage<'_>, origin: &[(Model, Outcome)], config: &Config, sizes: &Sizes) -> Vec<Cell> {
    let w = stage.w;
    // The exact colours at the float models' samples, once.
    let exact_colours: Vec<Option<Rgb>> = samples(&stage.full_refs[0], sizes.samples)
        .iter()
        .map(|&(x, y, k)| {
            gouraud_exact(
                &w.triangles[index(k)],
                &w.colours[index(k)],
                &sample_exact(x, y, &stage.target),
            )
            .map(|v| v.each_ref().map(to_channel))
        })
        .collect();
    let mut cells = Vec::new();
    for &mag in &config.magnitudes {
        let placed = place_triangles(&w.triangles, mag.px_i64());
        let placed_prims = Primitives::from_triangles(&placed);
        for (m, at_origin) in origin {
            let outcome = if mag.px() == 0 {
                at_origin.clone()
            } else if let Err(e) = refusal(*m, &placed_prims, &stage.target) {
                Outcome::Refused(e)
            } else if m.is_exact() {
                match at_origin {
                    Outcome::Measured { metrics, .. } => Outcome::Measured {
                        placement: Placement::Translated,
                        metrics: metrics.clone(),
                    },
                    refused => refused.clone(),
                }
            } else {
                let (_, _, r, _) = stage.pick(*m);
                let window = FarWindow {
                    origin: mag.px_i64(),
                    side: sizes.canvas,
                };
                let samples = (sizes.samples, exact_colours.as_slice());
                Outcome::Measured {
                    placement: Placement::AtMagnitude,
                    metrics: far_metrics(*m, w, &placed, &window, &stage.target, r, samples),
                }
            };
            cells.push(Cell {
                magnitude: mag,
                contender: m.name().into(),
                outcome,
            });
        }
    }
    cells
}

/// The barycentric and Gouraud samples: spread over the reference's covered pairs.
fn samples(r: &Reference, n: usize) -> Vec<(u32, u32, u32)> {
    r.pairs.spread(n)
}

fn index(id: u32) -> usize {
    usize::try_from(id).expect("an id")
}

/// A model's metrics on the workload at the origin, by the model's own code.
fn origin_metrics(
    model: Model,
    triangles: &[Triangle],
    colours: &[[Rgb; 3]],
    target: &Target,
    r: &Reference,
    n: usize,
) -> Result<Vec<Metric>, String> {
    let prims = Primitives::from_triangles(triangles);
    let prepared = prepare(&prims, target, model).map_err(|e| e.to_string())?;
    let mut p = Pairs::default();
    prepared.render(target, &mut p);
    let d = departures(&r.pairs, &p.sorted(), r.mask());
    let mut metrics = departure_metrics(&d, r.mask.is_some());
    let picks = samples(r, n);
    let conv = &target.convention;
    // Barycentric sums.
    if model.is_exact() {
        let failures = picks
            .iter()
            .filter(|&&(x, y, k)| {
                let t = &triangles[index(k)];
                if model.snaps() {
                    let s = t.snapped(conv);
                    match s.to_fixed() {
                        Ok(f) if model.is_integer() => check_barycentric_fixed(&f, x, y, target).is_err(),
                        _ => check_barycentric_exact(&s.to_exact(), &sample_exact(x, y, target)).is_err(),
                    }
                } else {
                    check_barycentric_exact(t, &sample_exact(x, y, target)).is_err()
                }
            })
            .count();
        metrics.push(Metric::Rate {
            name: BARYCENTRIC_EXACT,
            count: failures as u64,
            of: picks.len() as u64,
        });
    } else {
        let mut ulps: Vec<f64> = picks
            .iter()
            .filter_map(|&(x, y, k)| {
                let t = &triangles[index(k)];
                let p = sample_exact(x, y, target);
                if is_f32(model) {
                    float_sum_error_ulps(t, &p)
                } else {
                    let l = barycentric_f64(&t.to_f64()?, p.to_f64()?)?;
                    Some(((l[0] + l[1] + l[2]) - 1.0).abs() / f64::EPSILON)
                }
            })
            .collect();
        let (median, max) = median_max(&mut ulps);
        metrics.push(Metric::Ulps {
            name: BARYCENTRIC_ULPS,
            median,
            max,
            samples: ulps.len() as u64,
        });
    }
    // Gouraud: the model's own shading against the exact colour of the triangle it
    // draws (snapped for the models that snap).
    let mut off = 0u64;
    for &(x, y, k) in &picks {
        let t = &triangles[index(k)];
        let exact_t = if model.snaps() {
            t.snapped(conv).to_exact()
        } else {
            t.clone()
        };
        let c = &colours[index(k)];
        let exact = gouraud_exact(&exact_t, c, &sample_exact(x, y, target)).map(|v| v.each_ref().map(to_channel));
        let ours = prepared.shade(index(k), c, x, y, target);
        off += channels_off(exact, Some(ours));
    }
    metrics.push(Metric::Rate {
        name: GOURAUD,
        count: off,
        of: 3 * picks.len() as u64,
    });
    Ok(metrics)
}

fn is_f32(model: Model) -> bool {
    model.is_f32()
}

/// Channels where `ours` is one or more off `exact` (a missing colour on either side
/// counts all three when the other has one).
fn channels_off(exact: Option<Rgb>, ours: Option<Rgb>) -> u64 {
    match (exact, ours) {
        (Some(e), Some(o)) => e.iter().zip(&o).filter(|(a, b)| a != b).count() as u64,
        (None, None) => 0,
        _ => 3,
    }
}

/// A float model over the window at a magnitude: coverage, barycentric sums and Gouraud
/// colours computed with the placed coordinates.
fn far_metrics(
    model: Model,
    w: &Workload,
    placed: &[Triangle],
    window: &FarWindow,
    target: &Target,
    r: &Reference,
    (n, exact_colours): (usize, &[Option<Rgb>]),
) -> Vec<Metric> {
    let conv = &target.convention;
    let rule = model.float_rule().unwrap_or(FloatRule::WithTieRule);
    let mut p = Pairs::default();
    // The placed coordinates fit both types (|M| <= 2^40): prepare accepted them.
    let t32: Vec<Option<[Vec2; 3]>> = placed.iter().map(Triangle::to_f32).collect();
    let t64: Vec<Option<[DVec2; 3]>> = placed.iter().map(Triangle::to_f64).collect();
    for k in 0..placed.len() {
        let id = u32::try_from(k).expect("ids fit u32");
        if is_f32(model) {
            if let Some(t) = &t32[k] {
                float::rasterize_f32_at(t, id, window.origin(), target, rule, &mut p);
            }
        } else if let Some(t) = &t64[k] {
            float::rasterize_f64_at(t, id, window.origin(), target, rule, &mut p);
        }
    }
    let d = departures(&r.pairs, &p.sorted(), r.mask());
    let mut metrics = departure_metrics(&d, r.mask.is_some());
    let picks = samples(r, n);
    #[allow(clippy::cast_possible_truncation)] // rounding the sample to f32 is the model's
    let at = |x: u32, y: u32| {
        let s = DVec2::new(window.sample(x, conv), window.sample(y, conv));
        (s, Vec2::new(s.x as f32, s.y as f32))
    };
    let mut ulps = Vec::new();
    let mut off = 0u64;
    for (&(x, y, k), &exact) in picks.iter().zip(exact_colours) {
        let k = index(k);
        let (s64, s32) = at(x, y);
        let c = &w.colours[k];
        let (sum, colour) = if is_f32(model) {
            let Some(t) = &t32[k] else { continue };
            let sum = barycentric_f32(t, s32).map(|l| f64::from(l[0]) + f64::from(l[1]) + f64::from(l[2]));
            (
                sum.map(|s| (s - 1.0).abs() / f64::from(f32::EPSILON)),
                gouraud_f32(t, c, s32),
            )
        } else {
            let Some(t) = &t64[k] else { continue };
            let sum = barycentric_f64(t, s64).map(|l| l[0] + l[1] + l[2]);
            (sum.map(|s| (s - 1.0).abs() / f64::EPSILON), gouraud_f64(t, c, s64))
        };
        ulps.extend(sum);
        off += channels_off(exact, colour);
    }
    let (median, max) = median_max(&mut ulps);
    metrics.push(Metric::Ulps {
        name: BARYCENTRIC_ULPS,
        median,
        max,
        samples: ulps.len() as u64,
    });
    metrics.push(Metric::Rate {
        name: GOURAUD,
        count: off,
        of: 3 * picks.len() as u64,
    });
    metrics
}

#[cfg(test)]
mod tests {
    /// The contenders derived from `Model::ALL` are today's, in today's report order.
    #[test]
    fn the_contenders_are_every_model_in_report_order() {
        let names: Vec<&str> = super::models().iter().map(|m| m.name()).collect();
        assert_eq!(
            names,
            [
                "exact-plain",
                "exact",
                "exact-snapped-plain",
                "exact-snapped",
                "fixed",
                "scanline",
                "float32",
                "float64",
                "float32-naive",
                "float64-naive",
            ]
        );
    }
}
