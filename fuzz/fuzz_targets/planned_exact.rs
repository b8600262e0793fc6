//! The planned exact engines against the plain oracles, on whole scenes (triangles,
//! Bresenham and diamond-exit lines, polygons with holes, clip-space triangles, clip
//! windows; coordinates from tie points to 2^139 px and 2^-99 px off a sample):
//!
//! 1. `Model::Exact == Model::ExactPlain` and `Model::ExactSnapped ==
//!    Model::ExactSnappedPlain`, pixel for pixel (or the same error).
//! 2. Every width the planner could pick, forced (one width per scene, chosen from its
//!    text, so each width is forced over many scenes at a sixth of the cost): without a
//!    clip window, each triangle and polygon (as written and snapped) and diamond-exit
//!    line rasterized by `PlannedTriangle::forced`, `PlannedPolygon::forced`,
//!    `PlannedSegment::forced` in that width, when it holds the bound, covers exactly
//!    the primitive's pixels in the plain oracle's render of the scene.
//! 3. The plan's verdicts: where `plan_scene` says `fixed` / `scanline` are exact they
//!    equal `exact-snapped`, and where it says `float32` / `float64` are exact they equal
//!    `exact`.
//!
//! The input is a scene file when the bytes parse as one, else structured; its `Debug` is
//! the scene file (see `common::scene`).

#![no_main]

use libfuzzer_sys::fuzz_target;

mod common;
use common::scene::FuzzScene;
use rasterproof::convention::Target;
use rasterproof::coverage::{Coverage, CoverageSink};
use rasterproof::fill::polygon::planned::PlannedPolygon;
use rasterproof::line::planned::PlannedSegment;
use rasterproof::line::LineRule;
use rasterproof::model::plan::plan_scene;
use rasterproof::model::{render, Model, Primitives};
use rasterproof::num::plan::{Plan, Width};
use rasterproof::scene::Scene;
use rasterproof::tri::planned::PlannedTriangle;

/// Renders with the planned and the plain model; they must agree. The plain coverage.
fn same(planned: Model, plain: Model, primitives: &Primitives, target: &Target) -> Option<Coverage> {
    match (render(primitives, target, planned), render(primitives, target, plain)) {
        (Ok(a), Ok(b)) => {
            assert_eq!(a, b, "{planned} differs from {plain}");
            Some(b)
        }
        (Err(a), Err(b)) => {
            assert_eq!(a.to_string(), b.to_string(), "{planned} and {plain} refuse differently");
            None
        }
        (a, b) => panic!("{planned}: {:?}, {plain}: {:?}", a.err(), b.err()),
    }
}

/// The pixels primitive `id` covers in `all` (the plain oracle's render of the whole
/// scene: without a clip window, each primitive's pixels are its own oracle's).
fn only(all: &Coverage, id: u32) -> Coverage {
    let mut c = Coverage::new(all.width(), all.height());
    for (x, y, ids) in all.iter() {
        if ids.contains(&id) {
            c.cover(x, y, id);
        }
    }
    c
}

/// One width per scene, the same each time the scene is run: each width is forced
/// over many inputs, at a sixth of the cost.
fn width_for(scene: &Scene) -> Width {
    let sum: usize = scene.to_json().bytes().map(usize::from).sum();
    Width::ALL[sum % Width::ALL.len()]
}

/// A forced-width rasterization against the oracle's pixels.
fn check_forced<P>(
    what: &str,
    forced: Result<Option<P>, Plan>,
    width: Width,
    oracle: &Coverage,
    draw: impl Fn(&P, &mut Coverage),
) {
    match forced {
        Ok(Some(p)) => {
            let mut c = Coverage::new(oracle.width(), oracle.height());
            draw(&p, &mut c);
            assert_eq!(&c, oracle, "{what} forced into {}", width.name());
        }
        Ok(None) => assert_eq!(oracle.covered_pixels(), 0, "planned says the {what} covers nothing"),
        Err(plan) => assert_ne!(plan.width, width, "refused the width it plans"),
    }
}

/// Every primitive forced into `width`, against its pixels in the plain oracle's render
/// of the scene as written (`written`) and snapped (`snapped`).
fn forced_widths(primitives: &Primitives, target: &Target, width: Width, written: &Coverage, snapped: &Coverage) {
    let conv = &target.convention;
    let first_polygon = primitives.triangles.len() + primitives.lines.len();
    for (k, t) in primitives.triangles.iter().enumerate() {
        let id = u32::try_from(k).expect("few primitives");
        for (t, all) in [(t.to_triangle(), written), (t.snapped(conv).to_exact(), snapped)] {
            let forced = PlannedTriangle::forced(&t, target, width);
            check_forced("triangle", forced, width, &only(all, id), |p, c| p.rasterize(id, c));
        }
    }
    for (k, line) in primitives.lines.iter().enumerate() {
        if line.rule != LineRule::Diamond {
            continue;
        }
        let id = u32::try_from(primitives.triangles.len() + k).expect("few primitives");
        let forced = PlannedSegment::forced(&line.from, &line.to, target, width);
        check_forced("diamond line", forced, width, &only(written, id), |p, c| {
            p.rasterize(id, c)
        });
    }
    for (k, poly) in primitives.polygons.iter().enumerate() {
        let id = u32::try_from(first_polygon + k).expect("few primitives");
        for (poly, all) in [(poly.clone(), written), (poly.snapped_exact(conv), snapped)] {
            let forced = PlannedPolygon::forced(&poly, target, width);
            check_forced("polygon", forced, width, &only(all, id), |p, c| p.rasterize(id, c));
        }
    }
}

/// The plan's verdicts against the renders: `written` and `snapped` are the exact
/// models' coverages (equal to the plain oracles'), rendered once above.
fn verdicts(primitives: &Primitives, target: &Target, written: &Coverage, snapped: &Coverage) {
    let Ok(plan) = plan_scene(primitives, target, Model::Exact) else {
        return;
    };
    for v in plan.fixed_width.iter().filter(|v| v.exact) {
        let (reference, want) = if v.model.snaps() {
            (Model::ExactSnapped, snapped)
        } else {
            (Model::Exact, written)
        };
        match render(primitives, target, v.model) {
            Ok(got) => assert_eq!(
                &got, want,
                "plan says {} is exact, but it differs from {reference}",
                v.model
            ),
            Err(e) => panic!("plan says {} is exact, but it refuses the scene: {e}", v.model),
        }
    }
}

fuzz_target!(|input: FuzzScene| {
    let scene = &input.scene;
    let target = scene.target().expect("a bounded canvas");
    let primitives = scene.primitives();
    let written = same(Model::Exact, Model::ExactPlain, &primitives, &target);
    let snapped = same(Model::ExactSnapped, Model::ExactSnappedPlain, &primitives, &target);
    let (Some(written), Some(snapped)) = (written, snapped) else {
        return;
    };
    if primitives.clip.is_none() {
        forced_widths(&primitives, &target, width_for(scene), &written, &snapped);
    }
    verdicts(&primitives, &target, &written, &snapped);
});
