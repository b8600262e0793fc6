//! The polygon workloads: simple polygons (star-shaped, some with a hole) and any
//! polygons (tangled, stellated, with tangled holes), filled by the plain oracle, the
//! planned engine, the active edge table and triangulate-then-`fixed` (which refuses
//! what is not simple). All exact contenders: see [`super::exact_only`].

use crate::convention::Preset;
use crate::model::{Model, Primitives};
use crate::strategy::polygon::{any_polygon, simple_polygon};

use super::exact_only::{self, Spec};
use super::report::WorkloadReport;
use super::workloads::{draw_n, place_polygons, runner};
use super::{Config, Family, Sizes};

const MODELS: [(&str, Model); 4] = [
    ("exact-snapped-plain", Model::ExactSnappedPlain),
    ("exact-snapped", Model::ExactSnapped),
    ("scanline", Model::Scanline),
    ("fixed", Model::Fixed),
];

/// Measures the polygon workloads.
pub(crate) fn run(config: &Config, sizes: &Sizes, progress: &mut dyn FnMut(&str)) -> Vec<WorkloadReport> {
    let conv = Preset::D3d11.convention();
    let count = 10 * sizes.count;
    [
        (
            "simple polygons",
            simple_polygon(sizes.canvas, 12),
            "simple polygons (star-shaped, some with a hole; strategy::polygon::simple_polygon)",
        ),
        (
            "any polygons",
            any_polygon(sizes.canvas, 12),
            "polygons of every kind (simple, tangled, stellated, with tangled holes; \
             strategy::polygon::any_polygon), fill rule nonzero or even-odd",
        ),
    ]
    .into_iter()
    .map(|(name, strategy, what)| {
        progress(&format!("polygons: {name}"));
        let polygons = draw_n(&mut runner(config.seed, name), &strategy, count);
        let select = |ids: &[usize]| Primitives {
            polygons: ids.iter().map(|&k| polygons[k].clone()).collect(),
            ..Primitives::default()
        };
        let place = |m: i64| Primitives {
            polygons: place_polygons(&polygons, m),
            ..Primitives::default()
        };
        let on_grid = polygons.iter().all(|p| p.snapped_exact(&conv) == *p);
        exact_only::measure(
            &Spec {
                name,
                family: Family::Polygons,
                description: format!("{count} {what}."),
                count,
                select: &select,
                place: &place,
                models: &MODELS,
                baseline: "fixed",
                on_grid,
            },
            config,
            sizes,
        )
    })
    .collect()
}
