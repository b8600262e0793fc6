//! Every checker of the suite on one case.

use num_rational::BigRational;

use super::{models, Case, CaseRun, CheckOutcome, Skip, CANVAS};
use crate::check::{
    check_agreement, check_barycentric_exact, check_barycentric_fixed, check_clip_raster, check_diamond_agreement,
    check_inside, check_line_pixels, check_line_reference, check_line_symmetry, check_rotation_and_winding,
    check_segment_clip, check_translation, check_triangulation, check_watertight, check_watertight_samples,
    float_sum_error_ulps, Violation,
};
use crate::clip::halfplane::HalfPlane;
use crate::clip::sutherland_hodgman::{self, clip_polygon};
use crate::clip::{cohen_sutherland, Window};
use crate::convention::{Preset, Target, MAX_CANVAS};
use crate::fill::triangulate::{triangulate, validate};
use crate::geom::{FixedTriangle, Point, Polygon, Triangle};
use crate::interp::barycentric_exact;
use crate::line::{bresenham, dda, BresenhamTie, Line, LineRule};
use crate::model::{render, render_samples, render_triangles, Model, Primitives};
use crate::pattern::SamplePattern;
use crate::raster::sample_exact;
use crate::scene::Scene;

fn target(side: u32, preset: Preset) -> Target {
    Target::new(side, side, preset.convention()).expect("suite canvases are valid")
}

/// A `side` x `side` scene of `triangles` in the case's preset (other primitives are set
/// by the caller).
fn scene(c: &Case, side: u32, triangles: &[Triangle]) -> Scene {
    let mut scene = Scene::new(side, side, triangles.to_vec());
    scene.preset = c.preset;
    scene
}

/// Runs every checker of the suite on `c`: triangles, meshes, lines, polygons and
/// clipping, each outcome with the scene that reproduces it, each check that could not
/// run with its reason, and the float32 barycentric sum errors measured at the case's
/// samples.
///
/// ```
/// use rasterproof::harness::{generate, run_case};
/// let run = run_case(&generate(7, 0).unwrap());
/// assert!(run.outcomes.iter().all(|o| !o.is_fatal()));
/// ```
pub fn run_case(c: &Case) -> CaseRun {
    let mut out = Vec::new();
    let mut skipped = Vec::new();
    let (float32_sum_ulps, float32_sum_skipped) = triangle_checks(c, &mut out, &mut skipped);
    line_checks(c, &mut out);
    polygon_checks(c, &mut out, &mut skipped);
    clip_checks(c, &mut out, &mut skipped);
    CaseRun {
        mesh_family: c.mesh_family,
        outcomes: out,
        skipped,
        float32_sum_ulps,
        float32_sum_skipped,
    }
}

/// A check of `model` (named by the model) that could not run.
fn skip(invariant: &'static str, model: Model, reason: &'static str) -> Skip {
    Skip {
        invariant,
        model,
        label: model.name(),
        reason,
    }
}

/// The barycentric invariant, the watertightness invariant, the agreement invariant and
/// the invariance invariant on the case's triangle and meshes; returns the float32
/// barycentric sum errors (ulps of 1) and the number of samples where none could be
/// measured.
fn triangle_checks(c: &Case, out: &mut Vec<CheckOutcome>, skipped: &mut Vec<Skip>) -> (Vec<f64>, u64) {
    let tri_target = target(CANVAS, c.preset);
    let tri = std::slice::from_ref(&c.triangle);
    let mut push = |invariant, model: Model, result, triangles: &[Triangle], canvas| {
        out.push(CheckOutcome {
            invariant,
            model,
            label: model.name(),
            result,
            scene: scene(c, canvas, triangles),
        });
    };

    // The barycentric invariant: exact sums at a few samples (a zero-area triangle has
    // none: the checker would pass it vacuously), integer sums where the envelope allows.
    let samples = [(0u32, 0u32), (CANVAS / 2, CANVAS / 3), (CANVAS - 1, CANVAS - 1)];
    let points: Vec<Point> = samples.iter().map(|&(x, y)| sample_exact(x, y, &tri_target)).collect();
    if barycentric_exact(&c.triangle, &points[0]).is_none() {
        skipped.push(skip(
            "barycentric sum",
            Model::Exact,
            "the triangle has zero area (no barycentrics)",
        ));
    } else {
        let exact_sum = points.iter().try_for_each(|p| check_barycentric_exact(&c.triangle, p));
        push("barycentric sum", Model::Exact, exact_sum, tri, CANVAS);
    }
    let measured: Vec<Option<f64>> = points.iter().map(|p| float_sum_error_ulps(&c.triangle, p)).collect();
    let ulps_skipped = measured.iter().filter(|u| u.is_none()).count() as u64;
    let ulps: Vec<f64> = measured.into_iter().flatten().collect();
    match c.triangle.snapped(&tri_target.convention).to_fixed() {
        Ok(f) => {
            let sum = samples
                .iter()
                .try_for_each(|&(x, y)| check_barycentric_fixed(&f, x, y, &tri_target));
            push("integer edge sum", Model::Fixed, sum, tri, CANVAS);
        }
        Err(_) => skipped.push(skip(
            "integer edge sum",
            Model::Fixed,
            "the snapped triangle is outside the integer envelope",
        )),
    }

    // The watertightness invariant on the meshes, and the agreement invariant on them:
    // every model against its plain oracle (exact-snapped-plain for the models that snap,
    // exact-plain for the others).
    let meshes = [
        (
            &c.mesh,
            c.mesh_canvas,
            ("watertight", "agreement (mesh)"),
            models::mesh(),
        ),
        (
            &c.fine_mesh,
            MAX_CANVAS,
            ("watertight (fine mesh)", "agreement (fine mesh)"),
            models::fine_mesh(),
        ),
    ];
    for (mesh, side, (w_name, a_name), models) in meshes {
        let mesh_target = target(side, c.preset);
        let reference_exact = render_triangles(&mesh.triangles, &mesh_target, Model::ExactPlain);
        let reference_snapped = render_triangles(&mesh.triangles, &mesh_target, Model::ExactSnappedPlain);
        for model in models {
            let (watertight, agreement) = match render_triangles(&mesh.triangles, &mesh_target, model) {
                Err(e) => {
                    let v = Violation::new("watertight", e.to_string());
                    (Err(v.clone()), Err(v))
                }
                Ok(cov) => {
                    let reference = if model.snaps() {
                        &reference_snapped
                    } else {
                        &reference_exact
                    };
                    let name = model.reference().name();
                    let agreement = match reference {
                        Ok(r) => check_agreement(name, r, model.name(), &cov, &mesh.triangles, &mesh_target),
                        Err(e) => Err(Violation::new("agreement", e.to_string())),
                    };
                    (
                        check_watertight(&mesh.triangles, &mesh.outline, &cov, &mesh_target),
                        agreement,
                    )
                }
            };
            push(w_name, model, watertight, &mesh.triangles, side);
            push(a_name, model, agreement, &mesh.triangles, side);
        }
    }

    // The watertightness invariant per sample: the case's mesh at the standard 4x
    // positions, every sample inside its outline owned once, in each model that must hold.
    let four = SamplePattern::standard(4).expect("the standard 4x pattern");
    let mesh_target = target(c.mesh_canvas, c.preset);
    let mesh_scene = Primitives::from_triangles(&c.mesh.triangles);
    for model in models::must_hold() {
        let result = render_samples(&mesh_scene, &mesh_target, &four, model)
            .map_err(|e| Violation::new("watertight", e.to_string()))
            .and_then(|cov| check_watertight_samples(&c.mesh.triangles, &c.mesh.outline, &cov, &four, &mesh_target));
        push("watertight (4x)", model, result, &c.mesh.triangles, c.mesh_canvas);
    }

    // The agreement invariant on a single random triangle (every family), against the
    // plain oracle.
    for model in models::must_hold() {
        let reference = model.reference();
        match render_triangles(tri, &tri_target, reference) {
            Ok(expected) => {
                let result = render_triangles(tri, &tri_target, model)
                    .map_err(|e| Violation::new("agreement", e.to_string()))
                    .and_then(|cov| check_agreement(reference.name(), &expected, model.name(), &cov, tri, &tri_target));
                push("agreement (triangle)", model, result, tri, CANVAS);
            }
            Err(_) => skipped.push(skip(
                "agreement (triangle)",
                model,
                "the plain oracle refused the triangle (no reference)",
            )),
        }
    }

    // The invariance invariant: rotation and winding, whole-pixel translation.
    for model in models::rotation() {
        push(
            "rotation/winding",
            model,
            check_rotation_and_winding(&c.triangle, &tri_target, model),
            tri,
            CANVAS,
        );
    }
    for model in models::translation() {
        let (dx, dy) = c.shift;
        push(
            "translation",
            model,
            check_translation(&c.triangle, &tri_target, dx, dy, model),
            tri,
            CANVAS,
        );
    }
    (ulps, ulps_skipped)
}

/// The clipping invariant: exact Sutherland-Hodgman output inside the window and
/// rasterizing to raster(P) ∩ raster(W); exact Cohen-Sutherland keeping exactly the part
/// inside; the float forms' outputs outside the window counted (the measured trade).
fn clip_checks(c: &Case, out: &mut Vec<CheckOutcome>, skipped: &mut Vec<Skip>) {
    let target = target(CANVAS, c.preset);
    let polygon_case = || Scene {
        polygons: vec![c.polygon.clone()],
        clip: Some(c.window.clone()),
        ..scene(c, CANVAS, &[])
    };
    let mut push = |invariant, model: Model, label, result, scene| {
        out.push(CheckOutcome {
            invariant,
            model,
            label,
            result,
            scene,
        });
    };
    let cut = clip_polygon(&c.polygon, &c.window);
    let all_inside = std::iter::once(&cut.outline)
        .chain(&cut.holes)
        .try_for_each(|contour| check_inside(contour, &c.window));
    push(
        "clip inside",
        Model::Exact,
        "sutherland-hodgman",
        all_inside,
        polygon_case(),
    );
    push(
        "clip raster",
        Model::Exact,
        "sutherland-hodgman",
        check_clip_raster(&c.polygon, &cut, &c.window, &target),
        polygon_case(),
    );
    // The planned engines on the clipped polygon (rational vertices out of exact
    // clipping) equal the plain oracle.
    for model in models::clip_agreement() {
        let reference = model.reference();
        let scene = polygon_case();
        let drawn =
            |m| render(&scene.primitives(), &target, m).map_err(|e| Violation::new("clip agreement", e.to_string()));
        let result = drawn(reference)
            .and_then(|expected| Ok((expected, drawn(model)?)))
            .and_then(|(expected, theirs)| {
                check_agreement(reference.name(), &expected, model.name(), &theirs, &[], &target)
            });
        push("clip agreement", model, model.name(), result, scene);
    }
    let (a, b) = &c.segment;
    if let Window::Rect(r) = &c.rect {
        let kept = cohen_sutherland::clip_exact(a, b, r);
        push(
            "segment clip",
            Model::Exact,
            "cohen-sutherland",
            check_segment_clip(a, b, r, kept.as_ref()),
            Scene {
                lines: vec![Line {
                    from: a.clone(),
                    to: b.clone(),
                    rule: LineRule::Diamond,
                }],
                clip: Some(c.rect.clone()),
                ..scene(c, CANVAS, &[])
            },
        );
    } else {
        skipped.push(Skip {
            invariant: "segment clip",
            model: Model::Exact,
            label: "cohen-sutherland",
            reason: "the case's rect window is not a rectangle",
        });
    }
    // Float Sutherland-Hodgman: every output vertex read back exactly and checked exactly;
    // a non-finite one is a violation in itself.
    let inside = |pts: Vec<glam::DVec2>| -> Result<(), Violation> {
        let exact = pts
            .iter()
            .map(|p| Some(Point::new(BigRational::from_float(p.x)?, BigRational::from_float(p.y)?)))
            .collect::<Option<Vec<_>>>()
            .ok_or_else(|| Violation::new("clip inside", format!("a float output is not finite: {pts:?}")))?;
        check_inside(&exact, &c.window)
    };
    let planes = c.window.half_planes();
    let subject = &c.polygon.outline;
    let p64 = planes.iter().map(HalfPlane::to_f64).collect::<Option<Vec<_>>>();
    let s64 = subject.iter().map(Point::to_f64).collect::<Option<Vec<_>>>();
    if let (Some(p64), Some(s64)) = (p64, s64) {
        push(
            "clip inside",
            Model::Float64,
            "sh-f64",
            inside(sutherland_hodgman::clip_f64(&s64, &p64)),
            polygon_case(),
        );
    } else {
        skipped.push(Skip {
            invariant: "clip inside",
            model: Model::Float64,
            label: "sh-f64",
            reason: "a vertex or window line does not fit f64",
        });
    }
    let p32 = planes.iter().map(HalfPlane::to_f32).collect::<Option<Vec<_>>>();
    let s32 = subject.iter().map(Point::to_f32).collect::<Option<Vec<_>>>();
    if let (Some(p32), Some(s32)) = (p32, s32) {
        let pts = sutherland_hodgman::clip_f32(&s32, &p32);
        push(
            "clip inside",
            Model::Float32,
            "sh-f32",
            inside(pts.into_iter().map(|p| p.as_dvec2()).collect()),
            polygon_case(),
        );
    } else {
        skipped.push(Skip {
            invariant: "clip inside",
            model: Model::Float32,
            label: "sh-f32",
            reason: "a vertex or window line does not fit f32",
        });
    }
}

/// The polygon invariant: the scanline filler equals the oracle on any polygon; a simple
/// polygon's triangulation covers exactly its fill, once (the `fixed` model's route).
fn polygon_checks(c: &Case, out: &mut Vec<CheckOutcome>, skipped: &mut Vec<Skip>) {
    let target = target(CANVAS, c.preset);
    let mut push = |invariant, model: Model, result, polygon: &Polygon| {
        out.push(CheckOutcome {
            invariant,
            model,
            label: model.name(),
            result,
            scene: Scene {
                polygons: vec![polygon.clone()],
                ..scene(c, CANVAS, &[])
            },
        });
    };
    let fill = |model, p: &Polygon| {
        render(
            &Primitives {
                polygons: vec![p.clone()],
                ..Primitives::default()
            },
            &target,
            model,
        )
        .map_err(|e| Violation::new("polygon agreement", e.to_string()))
    };
    for model in models::polygon_agreement() {
        let reference = model.reference();
        let agreement = fill(reference, &c.polygon).and_then(|expected| {
            let theirs = fill(model, &c.polygon)?;
            check_agreement(reference.name(), &expected, model.name(), &theirs, &[], &target)
        });
        push("polygon agreement", model, agreement, &c.polygon);
    }
    // Grid rounding can fold a tiny star: only simple polygons are triangulated.
    let Ok(fixed) = c.simple.to_fixed(&target.convention) else {
        skipped.push(skip(
            "triangulation",
            Model::Fixed,
            "a snapped vertex is outside the integer envelope",
        ));
        return;
    };
    if validate(&fixed).is_err() {
        skipped.push(skip(
            "triangulation",
            Model::Fixed,
            "snapping folded the polygon (not simple on the subpixel grid)",
        ));
        return;
    }
    let result = triangulate(&fixed)
        .map_err(|e| Violation::new("triangulation", e.to_string()))
        .and_then(|tris| {
            let tris: Vec<Triangle> = tris.iter().map(FixedTriangle::to_exact).collect();
            check_triangulation(&fixed.to_exact(), &tris, &target)
        });
    push("triangulation", Model::Fixed, result, &c.simple);
}

/// The line invariant: Bresenham (both ties), its reversal, diamond-exit agreement, and
/// the DDA's departures (the float trade for lines).
fn line_checks(c: &Case, out: &mut Vec<CheckOutcome>) {
    let as_line = |(a, b): ([i64; 2], [i64; 2]), tie| Line {
        from: Point::from_ints(a[0], a[1]),
        to: Point::from_ints(b[0], b[1]),
        rule: LineRule::Bresenham(tie),
    };
    let mut push = |invariant, model: Model, label, result, line: Line| {
        out.push(CheckOutcome {
            invariant,
            model,
            label,
            result,
            scene: Scene {
                lines: vec![line],
                ..scene(c, CANVAS, &[])
            },
        });
    };
    for tie in [BresenhamTie::Stay, BresenhamTie::Step] {
        let (a, b) = c.line;
        let pixels = bresenham::pixels(a, b, tie);
        let label = if tie == BresenhamTie::Stay {
            "bresenham/stay"
        } else {
            "bresenham/step"
        };
        push(
            "line pixels",
            Model::Fixed,
            label,
            check_line_pixels(a, b, &pixels),
            as_line(c.line, tie),
        );
        push(
            "line reference",
            Model::Fixed,
            label,
            check_line_reference(a, b, tie, &pixels),
            as_line(c.line, tie),
        );
        let symmetry = check_line_symmetry(a, b, tie).map(|_| ());
        push("line symmetry", Model::Fixed, label, symmetry, as_line(c.line, tie));
    }
    let target = target(CANVAS, c.preset);
    for model in models::diamond() {
        // The integer models share one diamond-exit walk, named by the algorithm.
        let label = if model.is_integer() { "diamond" } else { model.name() };
        push(
            "diamond agreement",
            model,
            label,
            check_diamond_agreement(&c.diamond, model, &target),
            c.diamond.clone(),
        );
    }
    let (a, b) = c.long_line;
    for (model, label, pixels) in [
        (Model::Float32, "dda32", dda::pixels_f32(a, b)),
        (Model::Float64, "dda64", dda::pixels_f64(a, b)),
    ] {
        push(
            "line pixels (long)",
            model,
            label,
            check_line_pixels(a, b, &pixels),
            as_line(c.long_line, BresenhamTie::Stay),
        );
    }
}
