//! `rasterproof check`: the invariant suite on random cases.

use std::collections::BTreeMap;
use std::path::Path;
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressStyle};
use num_rational::BigRational;
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use rasterproof::check::{
    check_agreement, check_barycentric_exact, check_barycentric_fixed, check_clip_raster, check_diamond_agreement,
    check_inside, check_line_pixels, check_line_reference, check_line_symmetry, check_rotation_and_winding,
    check_segment_clip, check_translation, check_triangulation, check_watertight, float_sum_error_ulps, Violation,
};
use rasterproof::clip::halfplane::HalfPlane;
use rasterproof::clip::sutherland_hodgman::{self, clip_polygon};
use rasterproof::clip::{cohen_sutherland, Window};
use rasterproof::convention::{Preset, Target, MAX_CANVAS};
use rasterproof::fill::triangulate::{triangulate, validate};
use rasterproof::geom::{FixedTriangle, Point, Polygon, Triangle};
use rasterproof::line::{bresenham, dda, BresenhamTie, Line, LineRule};
use rasterproof::model::{render, render_triangles, Model, Primitives};
use rasterproof::scene::Scene;
use rasterproof::strategy::clip::{any_window, rect_window};
use rasterproof::strategy::polygon::{any_polygon, simple_polygon};
use rasterproof::strategy::{
    any_triangle, delaunay_mesh, diamond_line, long_pixel_line, pixel_line, tie_heavy_coordinate, tie_heavy_mesh, Mesh,
};

/// Canvas side of the ordinary cases.
const CANVAS: u32 = 32;

/// One generated case.
struct Case {
    mesh: Mesh,
    /// A far-from-origin mesh on a fine 2^-16 px grid, for the float models only (snapping
    /// it to 8 bits could fold thin triangles, so it is no input for the snapped models).
    fine_mesh: Mesh,
    /// A Bresenham line on and around the canvas.
    line: ([i64; 2], [i64; 2]),
    /// A diamond-exit line with tie-heavy endpoints.
    diamond: Line,
    /// A line up to 1000 px long, around 0, 2^16, 2^20 or 2^23, for the DDA.
    long_line: ([i64; 2], [i64; 2]),
    mesh_canvas: u32,
    mesh_family: &'static str,
    triangle: Triangle,
    shift: (i64, i64),
    preset: Preset,
    /// Any polygon: simple, with a hole, tangled, stellated, tie-heavy.
    polygon: Polygon,
    /// A simple polygon (star-shaped, maybe with a hole), for the triangulation.
    simple: Polygon,
    /// A clip window (rectangle or convex) and a rectangle for segments.
    window: Window,
    rect: Window,
    /// A segment with tie-heavy endpoints.
    segment: (Point, Point),
}

/// One checker's verdict.
struct Outcome {
    invariant: &'static str,
    model: Model,
    /// The model's name in the table (`bresenham`, `dda32`... for lines).
    label: &'static str,
    result: Result<(), Violation>,
    /// What to write out as a scene if it failed.
    repro: Repro,
}

/// The primitives, clip window and canvas of a case, for its scene file.
#[derive(Default)]
struct Repro {
    canvas: u32,
    triangles: Vec<Triangle>,
    lines: Vec<Line>,
    polygons: Vec<Polygon>,
    window: Option<Window>,
}

fn runner_for(seed: u64, case: u64) -> TestRunner {
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&seed.to_le_bytes());
    bytes[8..16].copy_from_slice(&case.to_le_bytes());
    TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &bytes))
}

fn draw<T: std::fmt::Debug>(runner: &mut TestRunner, s: impl Strategy<Value = T>) -> Result<T, String> {
    Ok(s.new_tree(runner)
        .map_err(|e| format!("case generation failed: {e}"))?
        .current())
}

fn generate(seed: u64, k: u64) -> Result<Case, String> {
    let mut runner = runner_for(seed, k);
    let far = i64::from(MAX_CANVAS) - 48;
    let (mesh, mesh_canvas, mesh_family) = match k % 3 {
        0 => (
            draw(&mut runner, delaunay_mesh([0, 0], i64::from(CANVAS), 8, 16))?,
            CANVAS,
            "random mesh",
        ),
        1 => (draw(&mut runner, tie_heavy_mesh(CANVAS, 16))?, CANVAS, "tie-heavy mesh"),
        _ => (
            draw(&mut runner, delaunay_mesh([far, far], 48, 8, 16))?,
            MAX_CANVAS,
            "far-from-origin mesh",
        ),
    };
    let fine_mesh = draw(&mut runner, delaunay_mesh([far, far], 48, 16, 24))?;
    let triangle = draw(&mut runner, any_triangle(CANVAS))?;
    let line = draw(&mut runner, pixel_line(i64::from(CANVAS), 8))?;
    let diamond = draw(&mut runner, diamond_line(CANVAS))?;
    let origin = draw(
        &mut runner,
        proptest::sample::select(vec![0i64, 1 << 16, 1 << 20, 1 << 23]),
    )?;
    let long_line = draw(&mut runner, long_pixel_line(origin, 500))?;
    let shift = draw(&mut runner, (-5i64..=5, -5i64..=5))?;
    let preset = draw(&mut runner, proptest::sample::select(vec![Preset::D3d11, Preset::Gl]))?;
    let polygon = draw(&mut runner, any_polygon(CANVAS, 12))?;
    let simple = draw(&mut runner, simple_polygon(CANVAS, 12))?;
    let window = draw(&mut runner, any_window(CANVAS))?;
    let rect = draw(&mut runner, rect_window(CANVAS))?;
    let ends = draw(&mut runner, proptest::array::uniform4(tie_heavy_coordinate(CANVAS)))?;
    let [ax, ay, bx, by] = ends;
    Ok(Case {
        mesh,
        fine_mesh,
        line,
        diamond,
        long_line,
        mesh_canvas,
        mesh_family,
        triangle,
        shift,
        preset,
        polygon,
        simple,
        window,
        rect,
        segment: (Point::new(ax, ay), Point::new(bx, by)),
    })
}

fn target(side: u32, preset: Preset) -> Target {
    Target::new(side, side, preset.convention()).expect("suite canvases are valid")
}

/// Runs every checker on one case; also returns the f32 barycentric sum errors (ulps of 1)
/// measured at the case's samples.
fn run_case(c: &Case) -> (Vec<Outcome>, Vec<f64>) {
    let mut out = Vec::new();
    let tri_target = target(CANVAS, c.preset);
    let tri = std::slice::from_ref(&c.triangle);
    let mut push = |invariant, model: Model, result, triangles: &[Triangle], canvas| {
        out.push(Outcome {
            invariant,
            model,
            label: model.name(),
            result,
            repro: Repro {
                canvas,
                triangles: triangles.to_vec(),
                ..Repro::default()
            },
        });
    };

    // 1. barycentrics: exact sums at a few samples, integer sums where the envelope allows.
    let samples = [(0u32, 0u32), (CANVAS / 2, CANVAS / 3), (CANVAS - 1, CANVAS - 1)];
    let exact_sum = samples.iter().try_for_each(|&(x, y)| {
        let p = Point::from_fractions(2 * i64::from(x) + 1, 2, 2 * i64::from(y) + 1, 2);
        check_barycentric_exact(&c.triangle, &p)
    });
    push("barycentric sum", Model::Exact, exact_sum, tri, CANVAS);
    let ulps: Vec<f64> = samples
        .iter()
        .filter_map(|&(x, y)| {
            let p = Point::from_fractions(2 * i64::from(x) + 1, 2, 2 * i64::from(y) + 1, 2);
            float_sum_error_ulps(&c.triangle, &p)
        })
        .collect();
    if let Ok(f) = c.triangle.snapped(&tri_target.convention).to_fixed() {
        let sum = samples
            .iter()
            .try_for_each(|&(x, y)| check_barycentric_fixed(&f, x, y, &tri_target));
        push("integer edge sum", Model::Fixed, sum, tri, CANVAS);
    }

    // 2. watertight meshes, and 3. agreement on them: the snapped models against
    // exact-snapped, the float models against exact (the scene as written).
    let meshes = [
        (
            &c.mesh,
            c.mesh_canvas,
            "",
            &[
                Model::ExactSnapped,
                Model::Fixed,
                Model::Scanline,
                Model::Float32,
                Model::Float64,
                Model::Float32Naive,
            ][..],
        ),
        (&c.fine_mesh, MAX_CANVAS, " fine", &[Model::Float32, Model::Float64][..]),
    ];
    for (mesh, side, tag, models) in meshes {
        let mesh_target = target(side, c.preset);
        let reference_exact = render_triangles(Model::Exact, &mesh.triangles, &mesh_target);
        let reference_snapped = render_triangles(Model::ExactSnapped, &mesh.triangles, &mesh_target);
        for &model in models {
            let (watertight, agreement) = match render_triangles(model, &mesh.triangles, &mesh_target) {
                Err(e) => {
                    let v = Violation {
                        invariant: "watertight",
                        message: e.to_string(),
                    };
                    (Err(v.clone()), Err(v))
                }
                Ok(cov) => {
                    let (name, reference) = match model {
                        Model::ExactSnapped | Model::Fixed | Model::Scanline => ("exact-snapped", &reference_snapped),
                        _ => ("exact", &reference_exact),
                    };
                    let agreement = match reference {
                        Ok(r) => check_agreement(name, r, model.name(), &cov, &mesh.triangles, &mesh_target),
                        Err(e) => Err(Violation {
                            invariant: "agreement",
                            message: e.to_string(),
                        }),
                    };
                    (
                        check_watertight(&mesh.triangles, &mesh.outline, &cov, &mesh_target),
                        agreement,
                    )
                }
            };
            let (w_name, a_name) = if tag.is_empty() {
                ("watertight", "agreement (mesh)")
            } else {
                ("watertight (fine mesh)", "agreement (fine mesh)")
            };
            push(w_name, model, watertight, &mesh.triangles, side);
            push(a_name, model, agreement, &mesh.triangles, side);
        }
    }

    // 3. agreement on a single random triangle (every family).
    if let Ok(reference) = render_triangles(Model::ExactSnapped, tri, &tri_target) {
        for model in [Model::Fixed, Model::Scanline] {
            let result = render_triangles(model, tri, &tri_target)
                .map_err(|e| Violation {
                    invariant: "agreement",
                    message: e.to_string(),
                })
                .and_then(|cov| check_agreement("exact-snapped", &reference, model.name(), &cov, tri, &tri_target));
            push("agreement (triangle)", model, result, tri, CANVAS);
        }
    }

    // 4. invariance.
    for model in [Model::ExactSnapped, Model::Fixed, Model::Float32] {
        push(
            "rotation/winding",
            model,
            check_rotation_and_winding(model, &c.triangle, &tri_target),
            tri,
            CANVAS,
        );
    }
    for model in [Model::ExactSnapped, Model::Fixed] {
        let (dx, dy) = c.shift;
        push(
            "translation",
            model,
            check_translation(model, &c.triangle, dx, dy, &tri_target),
            tri,
            CANVAS,
        );
    }
    line_checks(c, &mut out);
    polygon_checks(c, &mut out);
    clip_checks(c, &mut out);
    (out, ulps)
}

/// Invariant 6 (clipping): exact Sutherland-Hodgman output inside the window and
/// rasterizing to raster(P) ∩ raster(W); exact Cohen-Sutherland keeping exactly the part
/// inside; the float forms' outputs outside the window counted (the measured trade).
fn clip_checks(c: &Case, out: &mut Vec<Outcome>) {
    let target = target(CANVAS, c.preset);
    let polygon_case = || Repro {
        canvas: CANVAS,
        polygons: vec![c.polygon.clone()],
        window: Some(c.window.clone()),
        ..Repro::default()
    };
    let mut push = |invariant, model: Model, label, result, repro| {
        out.push(Outcome {
            invariant,
            model,
            label,
            result,
            repro,
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
    let (a, b) = &c.segment;
    if let Window::Rect(r) = &c.rect {
        let kept = cohen_sutherland::clip_exact(a, b, r);
        push(
            "segment clip",
            Model::Exact,
            "cohen-sutherland",
            check_segment_clip(a, b, r, kept.as_ref()),
            Repro {
                canvas: CANVAS,
                lines: vec![Line {
                    from: a.clone(),
                    to: b.clone(),
                    rule: LineRule::Diamond,
                }],
                window: Some(c.rect.clone()),
                ..Repro::default()
            },
        );
    }
    // Float Sutherland-Hodgman: every output vertex read back exactly and checked exactly;
    // a non-finite one is a violation in itself.
    let inside = |pts: Vec<glam::DVec2>| -> Result<(), Violation> {
        let exact = pts
            .iter()
            .map(|p| Some(Point::new(BigRational::from_float(p.x)?, BigRational::from_float(p.y)?)))
            .collect::<Option<Vec<_>>>()
            .ok_or_else(|| Violation {
                invariant: "clip inside",
                message: format!("a float output is not finite: {pts:?}"),
            })?;
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
    }
}

/// Invariant 7: the scanline filler equals the oracle on any polygon; a simple polygon's
/// triangulation covers exactly its fill, once (the `fixed` model's route).
fn polygon_checks(c: &Case, out: &mut Vec<Outcome>) {
    let target = target(CANVAS, c.preset);
    let mut push = |invariant, model: Model, result, polygon: &Polygon| {
        out.push(Outcome {
            invariant,
            model,
            label: model.name(),
            result,
            repro: Repro {
                canvas: CANVAS,
                polygons: vec![polygon.clone()],
                ..Repro::default()
            },
        });
    };
    let fill = |model, p: &Polygon| {
        render(
            model,
            &Primitives {
                polygons: vec![p.clone()],
                ..Primitives::default()
            },
            &target,
        )
        .map_err(|e| Violation {
            invariant: "polygon agreement",
            message: e.to_string(),
        })
    };
    let agreement = fill(Model::ExactSnapped, &c.polygon).and_then(|reference| {
        let scan = fill(Model::Scanline, &c.polygon)?;
        check_agreement("exact-snapped", &reference, "scanline", &scan, &[], &target)
    });
    push("polygon agreement", Model::Scanline, agreement, &c.polygon);
    // Grid rounding can fold a tiny star: only simple polygons are triangulated.
    let Ok(fixed) = c.simple.to_fixed(&target.convention) else {
        return;
    };
    if validate(&fixed).is_err() {
        return;
    }
    let result = triangulate(&fixed)
        .map_err(|e| Violation {
            invariant: "triangulation",
            message: e.to_string(),
        })
        .and_then(|tris| {
            let tris: Vec<Triangle> = tris.iter().map(FixedTriangle::to_exact).collect();
            check_triangulation(&fixed.to_exact(), &tris, &target)
        });
    push("triangulation", Model::Fixed, result, &c.simple);
}

/// Invariant 5: Bresenham (both ties), its reversal, diamond-exit agreement, and the DDA's
/// departures (the float trade for lines).
fn line_checks(c: &Case, out: &mut Vec<Outcome>) {
    let as_line = |(a, b): ([i64; 2], [i64; 2]), tie| Line {
        from: Point::from_ints(a[0], a[1]),
        to: Point::from_ints(b[0], b[1]),
        rule: LineRule::Bresenham(tie),
    };
    let mut push = |invariant, model: Model, label, result, line: Line| {
        out.push(Outcome {
            invariant,
            model,
            label,
            result,
            repro: Repro {
                canvas: CANVAS,
                lines: vec![line],
                ..Repro::default()
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
    push(
        "diamond agreement",
        Model::Fixed,
        "diamond",
        check_diamond_agreement(&c.diamond, &target),
        c.diamond.clone(),
    );
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

/// Models whose violations fail the run (the float models' violations are the measured trade).
fn must_hold(model: Model) -> bool {
    matches!(
        model,
        Model::Exact | Model::ExactSnapped | Model::Fixed | Model::Scanline
    )
}

pub fn run(cases: u64, seed: u64, out: Option<&Path>, quiet: bool) -> Result<ExitCode, String> {
    if let Some(dir) = out {
        std::fs::create_dir_all(dir).map_err(|e| format!("--out {}: cannot create: {e}", dir.display()))?;
    }
    let bar = if quiet {
        ProgressBar::hidden()
    } else {
        ProgressBar::new(cases)
    };
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} cases, {elapsed} ({eta} left)").expect("static template"),
    );
    let mut tally: BTreeMap<(&'static str, &'static str), (u64, u64)> = BTreeMap::new();
    let mut fatal = 0u64;
    let mut families: BTreeMap<(&'static str, &'static str), u64> = BTreeMap::new();
    let mut ulps: Vec<f64> = Vec::new();
    for k in 0..cases {
        let case = generate(seed, k)?;
        let (outcomes, errors) = run_case(&case);
        ulps.extend(errors);
        for o in outcomes {
            let entry = tally.entry((o.invariant, o.label)).or_default();
            entry.0 += 1;
            if let Err(v) = &o.result {
                entry.1 += 1;
                if o.invariant == "watertight" || o.invariant == "agreement (mesh)" {
                    *families.entry((case.mesh_family, o.label)).or_default() += 1;
                }
                if must_hold(o.model) {
                    fatal += 1;
                    bar.suspend(|| eprintln!("case {k}: {} ({}): {v}", o.invariant, o.label));
                }
                if let Some(dir) = out {
                    write_case(dir, k, &o, case.preset, v)?;
                }
            }
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    println!("rasterproof check: {cases} cases, seed {seed}, presets d3d11/gl");
    println!(
        "{:<24} {:<18} {:>7} {:>10}",
        "invariant", "model", "cases", "violations"
    );
    for ((invariant, model), (n, bad)) in &tally {
        println!("{invariant:<24} {model:<18} {n:>7} {bad:>10}");
    }
    if !families.is_empty() {
        println!("mesh violations by family:");
        for ((family, model), n) in &families {
            println!("  {family:<22} {model:<18} {n:>5}");
        }
    }
    if !ulps.is_empty() {
        ulps.sort_by(f64::total_cmp);
        let mean = ulps.iter().sum::<f64>() / ulps.len() as f64;
        println!(
            "float32 barycentric sum error, ulps of 1 ({} samples): median {:.1}, mean {:.1}, max {:.1}",
            ulps.len(),
            ulps[ulps.len() / 2],
            mean,
            ulps[ulps.len() - 1]
        );
    }
    if fatal > 0 {
        println!("FAILED: {fatal} violations by an exact or integer model (exact, exact-snapped, fixed, scanline)");
        Ok(ExitCode::from(1))
    } else {
        println!("ok: the exact and integer models (exact, exact-snapped, fixed, scanline) hold every invariant");
        Ok(ExitCode::SUCCESS)
    }
}

fn write_case(dir: &Path, k: u64, o: &Outcome, preset: Preset, v: &Violation) -> Result<(), String> {
    let slug: String = o
        .invariant
        .chars()
        .map(|ch| if ch.is_ascii_alphanumeric() { ch } else { '-' })
        .collect();
    let label: String = o.label.chars().map(|ch| if ch == '/' { '-' } else { ch }).collect();
    let stem = dir.join(format!("case-{k}-{slug}-{label}"));
    let r = &o.repro;
    let mut scene = Scene::new(r.canvas, r.canvas, r.triangles.clone());
    scene.lines = r.lines.clone();
    scene.polygons = r.polygons.clone();
    scene.clip = r.window.clone();
    scene.preset = preset;
    let json = stem.with_extension("json");
    std::fs::write(&json, scene.to_json()).map_err(|e| format!("{}: cannot write: {e}", json.display()))?;
    let txt = stem.with_extension("txt");
    std::fs::write(&txt, format!("{v}\n")).map_err(|e| format!("{}: cannot write: {e}", txt.display()))
}
