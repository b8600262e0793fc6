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
    let mut record = Record {
        case: c,
        outcomes: Vec::new(),
        skipped: Vec::new(),
    };
    let (float32_sum_ulps, float32_sum_skipped) = barycentric_checks(&mut record);
    mesh_checks(&mut record);
    triangle_checks(&mut record);
    line_checks(&mut record);
    polygon_checks(&mut record);
    clip_polygon_checks(&mut record);
    segment_clip_check(&mut record);
    float_clip_checks(&mut record);
    CaseRun {
        mesh_family: c.mesh_family,
        outcomes: record.outcomes,
        skipped: record.skipped,
        float32_sum_ulps,
        float32_sum_skipped,
    }
}

/// What the checkers found on one case, in the order they ran.
struct Record<'a> {
    case: &'a Case,
    outcomes: Vec<CheckOutcome>,
    skipped: Vec<Skip>,
}

impl Record<'_> {
    /// An outcome of `model` (labelled by the algorithm) on `scene`.
    fn push(
        &mut self,
        invariant: &'static str,
        model: Model,
        label: &'static str,
        result: Result<(), Violation>,
        scene: Scene,
    ) {
        self.outcomes.push(CheckOutcome {
            invariant,
            model,
            label,
            result,
            scene,
        });
    }

    /// An outcome of `model` (labelled by the model) on a `canvas` x `canvas` scene of
    /// `triangles`.
    fn push_triangles(
        &mut self,
        invariant: &'static str,
        model: Model,
        result: Result<(), Violation>,
        triangles: &[Triangle],
        canvas: u32,
    ) {
        let scene = scene(self.case, canvas, triangles);
        self.push(invariant, model, model.name(), result, scene);
    }

    /// A check of `model` (labelled by the algorithm) that could not run.
    fn skip_labelled(&mut self, invariant: &'static str, model: Model, label: &'static str, reason: &'static str) {
        self.skipped.push(Skip {
            invariant,
            model,
            label,
            reason,
        });
    }

    /// A check of `model` (labelled by the model) that could not run.
    fn skip(&mut self, invariant: &'static str, model: Model, reason: &'static str) {
        self.skip_labelled(invariant, model, model.name(), reason);
    }

    /// The case's scene of its one triangle.
    fn triangle_scene(&self) -> Scene {
        scene(self.case, CANVAS, std::slice::from_ref(&self.case.triangle))
    }

    /// A `CANVAS`-sized scene of no primitive, in the case's preset.
    fn empty_scene(&self) -> Scene {
        scene(self.case, CANVAS, &[])
    }
}

/// The barycentric invariant on the case's triangle: exact sums at a few samples (a
/// zero-area triangle has none: the checker would pass it vacuously), integer sums where
/// the envelope allows. Returns the float32 barycentric sum errors (ulps of 1) and the
/// number of samples where none could be measured.
fn barycentric_checks(r: &mut Record) -> (Vec<f64>, u64) {
    let c = r.case;
    let tri_target = target(CANVAS, c.preset);
    let samples = [(0u32, 0u32), (CANVAS / 2, CANVAS / 3), (CANVAS - 1, CANVAS - 1)];
    let points: Vec<Point> = samples.iter().map(|&(x, y)| sample_exact(x, y, &tri_target)).collect();
    if barycentric_exact(&c.triangle, &points[0]).is_none() {
        r.skip(
            "barycentric sum",
            Model::Exact,
            "the triangle has zero area (no barycentrics)",
        );
    } else {
        let exact_sum = points.iter().try_for_each(|p| check_barycentric_exact(&c.triangle, p));
        r.push(
            "barycentric sum",
            Model::Exact,
            Model::Exact.name(),
            exact_sum,
            r.triangle_scene(),
        );
    }
    let measured: Vec<Option<f64>> = points.iter().map(|p| float_sum_error_ulps(&c.triangle, p)).collect();
    let ulps_skipped = measured.iter().filter(|u| u.is_none()).count() as u64;
    let ulps: Vec<f64> = measured.into_iter().flatten().collect();
    match c.triangle.snapped(&tri_target.convention).to_fixed() {
        Ok(f) => {
            let sum = samples
                .iter()
                .try_for_each(|&(x, y)| check_barycentric_fixed(&f, x, y, &tri_target));
            r.push(
                "integer edge sum",
                Model::Fixed,
                Model::Fixed.name(),
                sum,
                r.triangle_scene(),
            );
        }
        Err(_) => r.skip(
            "integer edge sum",
            Model::Fixed,
            "the snapped triangle is outside the integer envelope",
        ),
    }
    (ulps, ulps_skipped)
}

/// The watertightness invariant on the meshes, and the agreement invariant on them: every
/// model against its plain oracle (exact-snapped-plain for the models that snap,
/// exact-plain for the others); then watertightness per sample: the case's mesh at the
/// standard 4x positions, every sample inside its outline owned once, in each model that
/// must hold.
fn mesh_checks(r: &mut Record) {
    let c = r.case;
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
            r.push_triangles(w_name, model, watertight, &mesh.triangles, side);
            r.push_triangles(a_name, model, agreement, &mesh.triangles, side);
        }
    }

    let four = SamplePattern::standard(4).expect("the standard 4x pattern");
    let mesh_target = target(c.mesh_canvas, c.preset);
    let mesh_scene = Primitives::from_triangles(&c.mesh.triangles);
    for model in models::must_hold() {
        let result = render_samples(&mesh_scene, &mesh_target, &four, model)
            .map_err(|e| Violation::new("watertight", e.to_string()))
            .and_then(|cov| check_watertight_samples(&c.mesh.triangles, &c.mesh.outline, &cov, &four, &mesh_target));
        r.push_triangles("watertight (4x)", model, result, &c.mesh.triangles, c.mesh_canvas);
    }
}

/// The agreement invariant on the case's single random triangle (every family), against
/// the plain oracle; then the invariance invariant: rotation and winding, whole-pixel
/// translation.
fn triangle_checks(r: &mut Record) {
    let c = r.case;
    let tri_target = target(CANVAS, c.preset);
    let tri = std::slice::from_ref(&c.triangle);
    for model in models::must_hold() {
        let reference = model.reference();
        match render_triangles(tri, &tri_target, reference) {
            Ok(expected) => {
                let result = render_triangles(tri, &tri_target, model)
                    .map_err(|e| Violation::new("agreement", e.to_string()))
                    .and_then(|cov| check_agreement(reference.name(), &expected, model.name(), &cov, tri, &tri_target));
                r.push_triangles("agreement (triangle)", model, result, tri, CANVAS);
            }
            Err(_) => r.skip(
                "agreement (triangle)",
                model,
                "the plain oracle refused the triangle (no reference)",
            ),
        }
    }
    for model in models::rotation() {
        let result = check_rotation_and_winding(&c.triangle, &tri_target, model);
        r.push_triangles("rotation/winding", model, result, tri, CANVAS);
    }
    for model in models::translation() {
        let (dx, dy) = c.shift;
        let result = check_translation(&c.triangle, &tri_target, dx, dy, model);
        r.push_triangles("translation", model, result, tri, CANVAS);
    }
}

/// The case's polygon clipped by its window, as a scene.
fn clipped_polygon_scene(r: &Record) -> Scene {
    Scene {
        polygons: vec![r.case.polygon.clone()],
        clip: Some(r.case.window.clone()),
        ..r.empty_scene()
    }
}

/// The clipping invariant on polygons: exact Sutherland-Hodgman output inside the window
/// and rasterizing to raster(P) ∩ raster(W); the planned engines on the clipped polygon
/// (rational vertices out of exact clipping) equal to the plain oracle.
fn clip_polygon_checks(r: &mut Record) {
    let c = r.case;
    let target = target(CANVAS, c.preset);
    let cut = clip_polygon(&c.polygon, &c.window);
    let all_inside = std::iter::once(&cut.outline)
        .chain(&cut.holes)
        .try_for_each(|contour| check_inside(contour, &c.window));
    let sh = "sutherland-hodgman";
    r.push("clip inside", Model::Exact, sh, all_inside, clipped_polygon_scene(r));
    let raster = check_clip_raster(&c.polygon, &cut, &c.window, &target);
    r.push("clip raster", Model::Exact, sh, raster, clipped_polygon_scene(r));
    for model in models::clip_agreement() {
        let reference = model.reference();
        let scene = clipped_polygon_scene(r);
        let drawn =
            |m| render(&scene.primitives(), &target, m).map_err(|e| Violation::new("clip agreement", e.to_string()));
        let result = drawn(reference)
            .and_then(|expected| Ok((expected, drawn(model)?)))
            .and_then(|(expected, theirs)| {
                check_agreement(reference.name(), &expected, model.name(), &theirs, &[], &target)
            });
        r.push("clip agreement", model, model.name(), result, scene);
    }
}

/// The clipping invariant on segments: exact Cohen-Sutherland keeps exactly the part
/// inside the case's rectangle.
fn segment_clip_check(r: &mut Record) {
    let c = r.case;
    let (a, b) = &c.segment;
    let Window::Rect(rect) = &c.rect else {
        r.skip_labelled(
            "segment clip",
            Model::Exact,
            "cohen-sutherland",
            "the case's rect window is not a rectangle",
        );
        return;
    };
    let kept = cohen_sutherland::clip_exact(a, b, rect);
    let scene = Scene {
        lines: vec![Line {
            from: a.clone(),
            to: b.clone(),
            rule: LineRule::Diamond,
        }],
        clip: Some(c.rect.clone()),
        ..r.empty_scene()
    };
    let result = check_segment_clip(a, b, rect, kept.as_ref());
    r.push("segment clip", Model::Exact, "cohen-sutherland", result, scene);
}

/// The float forms of Sutherland-Hodgman (the measured trade): every output vertex read
/// back exactly and checked inside the window exactly; a non-finite one is a violation in
/// itself.
fn float_clip_checks(r: &mut Record) {
    let c = r.case;
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
        let result = inside(sutherland_hodgman::clip_f64(&s64, &p64));
        r.push(
            "clip inside",
            Model::Float64,
            "sh-f64",
            result,
            clipped_polygon_scene(r),
        );
    } else {
        r.skip_labelled(
            "clip inside",
            Model::Float64,
            "sh-f64",
            "a vertex or window line does not fit f64",
        );
    }
    let p32 = planes.iter().map(HalfPlane::to_f32).collect::<Option<Vec<_>>>();
    let s32 = subject.iter().map(Point::to_f32).collect::<Option<Vec<_>>>();
    if let (Some(p32), Some(s32)) = (p32, s32) {
        let pts = sutherland_hodgman::clip_f32(&s32, &p32);
        let result = inside(pts.into_iter().map(|p| p.as_dvec2()).collect());
        r.push(
            "clip inside",
            Model::Float32,
            "sh-f32",
            result,
            clipped_polygon_scene(r),
        );
    } else {
        r.skip_labelled(
            "clip inside",
            Model::Float32,
            "sh-f32",
            "a vertex or window line does not fit f32",
        );
    }
}

/// The polygon invariant: the scanline filler equals the oracle on any polygon; a simple
/// polygon's triangulation covers exactly its fill, once (the `fixed` model's route).
fn polygon_checks(r: &mut Record) {
    let c = r.case;
    let target = target(CANVAS, c.preset);
    let polygon_scene = |r: &Record, polygon: &Polygon| Scene {
        polygons: vec![polygon.clone()],
        ..r.empty_scene()
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
        r.push(
            "polygon agreement",
            model,
            model.name(),
            agreement,
            polygon_scene(r, &c.polygon),
        );
    }
    // Grid rounding can fold a tiny star: only simple polygons are triangulated.
    let Ok(fixed) = c.simple.to_fixed(&target.convention) else {
        r.skip(
            "triangulation",
            Model::Fixed,
            "a snapped vertex is outside the integer envelope",
        );
        return;
    };
    if validate(&fixed).is_err() {
        r.skip(
            "triangulation",
            Model::Fixed,
            "snapping folded the polygon (not simple on the subpixel grid)",
        );
        return;
    }
    let result = triangulate(&fixed)
        .map_err(|e| Violation::new("triangulation", e.to_string()))
        .and_then(|tris| {
            let tris: Vec<Triangle> = tris.iter().map(FixedTriangle::to_exact).collect();
            check_triangulation(&fixed.to_exact(), &tris, &target)
        });
    let fixed_name = Model::Fixed.name();
    r.push(
        "triangulation",
        Model::Fixed,
        fixed_name,
        result,
        polygon_scene(r, &c.simple),
    );
}

/// The line invariant: Bresenham (both ties), its reversal, diamond-exit agreement, and
/// the DDA's departures (the float trade for lines).
fn line_checks(r: &mut Record) {
    let c = r.case;
    let as_line = |(a, b): ([i64; 2], [i64; 2]), tie| Line {
        from: Point::from_ints(a[0], a[1]),
        to: Point::from_ints(b[0], b[1]),
        rule: LineRule::Bresenham(tie),
    };
    let line_scene = |r: &Record, line: Line| Scene {
        lines: vec![line],
        ..r.empty_scene()
    };
    for tie in [BresenhamTie::Stay, BresenhamTie::Step] {
        let (a, b) = c.line;
        let pixels = bresenham::pixels(a, b, tie);
        let label = if tie == BresenhamTie::Stay {
            "bresenham/stay"
        } else {
            "bresenham/step"
        };
        let line = as_line(c.line, tie);
        let found = check_line_pixels(a, b, &pixels);
        r.push("line pixels", Model::Fixed, label, found, line_scene(r, line.clone()));
        let reference = check_line_reference(a, b, tie, &pixels);
        r.push(
            "line reference",
            Model::Fixed,
            label,
            reference,
            line_scene(r, line.clone()),
        );
        let symmetry = check_line_symmetry(a, b, tie).map(|_| ());
        r.push("line symmetry", Model::Fixed, label, symmetry, line_scene(r, line));
    }
    let target = target(CANVAS, c.preset);
    for model in models::diamond() {
        // The integer models share one diamond-exit walk, named by the algorithm.
        let label = if model.is_integer() { "diamond" } else { model.name() };
        let result = check_diamond_agreement(&c.diamond, model, &target);
        r.push(
            "diamond agreement",
            model,
            label,
            result,
            line_scene(r, c.diamond.clone()),
        );
    }
    let (a, b) = c.long_line;
    for (model, label, pixels) in [
        (Model::Float32, "dda32", dda::pixels_f32(a, b)),
        (Model::Float64, "dda64", dda::pixels_f64(a, b)),
    ] {
        let result = check_line_pixels(a, b, &pixels);
        let line = as_line(c.long_line, BresenhamTie::Stay);
        r.push("line pixels (long)", model, label, result, line_scene(r, line));
    }
}
