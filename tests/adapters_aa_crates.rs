//! Two anti-aliasing crates as adapters (adapters/README.md): `ab_glyph_rasterizer` (the
//! example `ab-glyph-adapter`, f32 signed-area accumulation, a 16-bit grey PNG) and `zeno`
//! (the example `zeno-adapter`, a Rust port of FreeType's smooth rasterizer, its 8-bit
//! mask), real renderers judged against the exact area coverage.
//!
//! Both draw the whole scene as **one path** (one ab_glyph `Rasterizer`, one zeno path):
//! the winding numbers of all the contours add. The exact reference for them is therefore
//! the scene's contours as one path ([`one_path`]): the integral of the summed winding
//! number, folded under the rule (the crate's accumulated semantics of one shape). That
//! equals the crate's per-shape accumulated coverage wherever shapes do not overlap (a
//! polygon scene, glyphs), and departs from it where they do (see
//! `overlapping_contours_add_in_one_path`).
//!
//! What is asserted, and why it should hold independently of these runs:
//! - hand scenes, derived from each crate's method: a unit square gives full coverage at
//!   its pixel alone (65535, 255: zeno's mask is not moved to the path's bounds), half a
//!   pixel gives ab_glyph exactly 0.5 (32767.5, ties to even: 32768) either way round,
//!   and zeno 128 or 127 depending on the orientation (FreeType's reciprocal division and
//!   `~`, derived step by step below);
//! - on the FreeType tests' scenes (the same random generator as `tests/adapters_area.rs`,
//!   the glyph scenes of `adapters/scenes/`), each adapter's levels are within a measured
//!   bound of the exact one-path coverage, in quanta of its own quantization, explained
//!   per crate below;
//! - `fit_grey` on `glyph.json` names each renderer's own method first, with no pixel
//!   off (`area::abglyph`, `area::zeno`), ahead of the exact coverage quantized the
//!   adapter's way;
//! - overlapping contours: ab_glyph's (clamped) sum against the exact true coverage is
//!   `accumulation`, and shapes of opposite orientation cancel in the one buffer;
//! - `--serve` answers the PNG the per-scene command writes, byte for byte.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use num_rational::BigRational;
use rasterproof::area::{exact, AreaMethod, AreaShape, Quantization, Semantics};
use rasterproof::geom::{FillRule, Polygon};
use rasterproof::model::{area_shapes, Model};
use rasterproof::oracle::compare::fit::grey::{fit_grey, GreyMethod};
use rasterproof::oracle::compare::grey::{compare_grey, GreyClass};
use rasterproof::oracle::GreyImage;
use rasterproof::scene::parse_scene;
use serde_json::{json, Value};

use crate::common::{canvas, grey_options};
use crate::tempdir;

/// The ab_glyph adapter's executable (built if stale, as `cargo test` builds examples).
fn ab_glyph() -> PathBuf {
    crate::adapters::example("ab-glyph-adapter")
}

/// The zeno adapter's executable.
fn zeno() -> PathBuf {
    crate::adapters::example("zeno-adapter")
}

/// A scene file of `adapters/scenes/`.
fn fixed(name: &str) -> Value {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/scenes").join(name);
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// Runs `exe SCENE OUT` on `scene` (written into `dir` as `name.json`); the output and
/// the PNG's path.
fn run_once(exe: &Path, scene: &Value, dir: &Path, name: &str) -> (Output, PathBuf) {
    let (input, out) = (dir.join(format!("{name}.json")), dir.join(format!("{name}.png")));
    std::fs::write(&input, scene.to_string()).unwrap();
    (Command::new(exe).arg(&input).arg(&out).output().unwrap(), out)
}

/// The grey image `exe` draws of `scene` (asserting success).
fn draw(exe: &Path, scene: &Value, dir: &Path, name: &str) -> GreyImage {
    let (output, out) = run_once(exe, scene, dir, name);
    assert!(
        output.status.success(),
        "{name}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    GreyImage::read_png(&std::fs::read(&out).unwrap(), name).unwrap()
}

/// Every scene through one `exe --serve`: per scene the PNG's path, or the refusal.
fn serve(exe: &Path, scenes: &[Value], dir: &Path) -> Vec<Result<PathBuf, String>> {
    let requests: Vec<Value> = scenes
        .iter()
        .enumerate()
        .map(|(k, s)| json!({"rasterproof": 1, "id": k, "scene": s, "out": dir.join(format!("serve-{k}.png"))}))
        .collect();
    let (answers, _) = crate::adapters_area::serve_answers(Command::new(exe), &requests);
    answers
        .iter()
        .enumerate()
        .map(|(k, a)| {
            assert_eq!(a["id"], k);
            if a["ok"] == true {
                Ok(dir.join(format!("serve-{k}.png")))
            } else {
                Err(a["error"].as_str().unwrap_or("").to_string())
            }
        })
        .collect()
}

/// The scene's exact shapes and canvas.
fn shapes(scene: &Value) -> (Vec<AreaShape>, u32, u32) {
    let parsed = parse_scene(&scene.to_string(), "scene").unwrap();
    let target = parsed.target().unwrap();
    let shapes = area_shapes(&parsed.primitives(), &target, Model::Exact).unwrap();
    (shapes, target.width, target.height)
}

/// Every contour of `shapes`, as written, as the contours of one shape under `rule`: what
/// one accumulation buffer (one ab_glyph `Rasterizer`, one zeno path) sums. Its
/// accumulated value is the folded integral of the summed winding number.
fn one_path(shapes: &[AreaShape], rule: FillRule) -> Vec<AreaShape> {
    let mut contours = shapes.iter().flat_map(|s| s.contours().map(<[_]>::to_vec));
    let Some(outline) = contours.next() else {
        return Vec::new();
    };
    vec![Polygon {
        outline,
        holes: contours.collect(),
        fill_rule: rule,
    }]
}

/// The scene's one fill rule (triangles are nonzero).
fn rule_of(shapes: &[AreaShape]) -> FillRule {
    shapes.first().map_or(FillRule::NonZero, |s| s.fill_rule)
}

/// A rational from integers.
fn r(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// The one lit pixel of a level image: `(x, y, level)` of every non-zero level.
fn lit(image: &GreyImage) -> Vec<(u32, u32, u16)> {
    (0..image.height)
        .flat_map(|y| (0..image.width).map(move |x| (x, y)))
        .filter_map(|(x, y)| {
            let l = image.levels[(y * image.width + x) as usize];
            (l != 0).then_some((x, y, l))
        })
        .collect()
}

/// Hand scenes on a 6x6 canvas:
///
/// - the unit square (2, 3)-(3, 4) (two triangles of one orientation, so one path winds
///   once there): pixel (2, 3) fully covered, nothing else. ab_glyph: its two vertical
///   edges put +-1 into cells 2 and 3 of row 3 (the horizontal ones are skipped), the
///   running sum is 1 on pixel (2, 3) alone: 65535. zeno: with an explicit size and no
///   offset its mask is placed at (0, 0) (`Placement { left: 0, top: 0 }`), so its pixel
///   (2, 3) is the canvas's: 255 (FreeType's 256, clamped), 0 elsewhere;
/// - the half pixel below the diagonal of pixel (2, 3), both ways round. ab_glyph: the
///   diagonal (2, 3) -> (3, 4) has its mean x 2.5 in column 2, so it adds `d (1 - 0.5)` to
///   cell 2 and `d 0.5` to cell 3, the vertical edge at x = 2 adds `-d` to cell 2: the sum
///   at pixel (2, 3) is `|-0.5|` = 0.5 exactly, `0.5 x 65535 = 32767.5`, ties to even:
///   32768 either way round. zeno (24.8 fixed point, FreeType's walk with a 32-bit
///   reciprocal `0xFFFFFF / d`, `(a r) >> 24`): for `(2,3), (3,4), (2,4)` the diagonal
///   leaves cell (2, 3) through its right side at `fy2 = (65536 x 65535) >> 24 = 255`
///   (the reciprocal falls 1/256 px short), giving the cell cover 255 and area
///   `255 x 256 = 65280`; the vertical edge going up gives cover -256: the cell's value
///   `-1 x 512 - 65280 = -65792`, `>> 9` = -129, complemented by `~`: **128** (= 0.5 x
///   256). The other way round, `(2,3), (2,4), (3,4)`, the diagonal leaves cell (3, 4)
///   by its top at `fx2 = 255` and crosses cell (2, 3) from x = 255/256 to 0: area
///   `-256 x 255 = -65280`, cover 0, value `+65280 >> 9` = **127** (one level short: the
///   same reciprocal shortfall, now on a positive value).
#[test]
fn hand_scenes_give_derived_levels() {
    let dir = tempdir::Dir::new("aa-hand");
    let square = json!({"width": 6, "height": 6, "triangles": [
        {"v": [[2, 3], [3, 3], [3, 4]]}, {"v": [[2, 3], [3, 4], [2, 4]]}]});
    let half_cw = json!({"width": 6, "height": 6, "triangles": [{"v": [[2, 3], [3, 4], [2, 4]]}]});
    let half_ccw = json!({"width": 6, "height": 6, "triangles": [{"v": [[2, 3], [2, 4], [3, 4]]}]});
    let (ab, z) = (ab_glyph(), zeno());
    let image = draw(&ab, &square, dir.path(), "ab-square");
    assert_eq!(image.bits, 16);
    assert_eq!(lit(&image), [(2, 3, 65535)]);
    let image = draw(&z, &square, dir.path(), "zeno-square");
    assert_eq!(image.bits, 8);
    assert_eq!(lit(&image), [(2, 3, 255)]);
    for (name, half) in [("cw", &half_cw), ("ccw", &half_ccw)] {
        assert_eq!(
            lit(&draw(&ab, half, dir.path(), &format!("ab-{name}"))),
            [(2, 3, 32768)],
            "{name}"
        );
    }
    assert_eq!(lit(&draw(&z, &half_cw, dir.path(), "zeno-cw")), [(2, 3, 128)]);
    assert_eq!(lit(&draw(&z, &half_ccw, dir.path(), "zeno-ccw")), [(2, 3, 127)]);
    // The crate's own quantizations of the exact 1/2 agree with the first two readings.
    assert_eq!(Quantization::Round16.level(&r(1, 2)), 32768);
    assert_eq!(Quantization::FtGrays.level(&r(1, 2)), 128);
}

/// What each adapter cannot draw is refused with exit status 2 and one line naming it:
/// ab_glyph has no even-odd rule; neither draws lines, clip windows or clip-space
/// triangles; zeno fills one path under one rule (no mix) and takes coordinates within
/// +-4096 px (its i32 walk). Under `--serve` a refusal is an `ok: false` answer and the
/// loop goes on.
#[test]
fn refusals_are_clear() {
    let dir = tempdir::Dir::new("aa-refuse");
    let tri = json!({"v": [[0, 0], [4, 0], [0, 4]]});
    let even_odd = json!({"v": [[0, 0], [4, 0], [0, 4]], "fill_rule": "even-odd"});
    let line = json!({"from": [0, 0], "to": [3, 3]});
    let cases = [
        (
            "ab",
            ab_glyph(),
            json!({"width": 4, "height": 4, "polygons": [even_odd]}),
            "even-odd",
        ),
        (
            "ab",
            ab_glyph(),
            json!({"width": 4, "height": 4, "lines": [line]}),
            "lines",
        ),
        (
            "zeno",
            zeno(),
            json!({"width": 4, "height": 4, "lines": [line]}),
            "lines",
        ),
        (
            "ab",
            ab_glyph(),
            json!({"width": 4, "height": 4, "triangles": [tri], "clip": {"convex": [[0, 0], [2, 0], [0, 2]]}}),
            "clip",
        ),
        (
            "zeno",
            zeno(),
            json!({"width": 4, "height": 4, "triangles": [tri], "clip": {"convex": [[0, 0], [2, 0], [0, 2]]}}),
            "clip",
        ),
        (
            "zeno",
            zeno(),
            json!({"width": 4, "height": 4, "triangles": [tri], "polygons": [even_odd]}),
            "mixes",
        ),
        (
            "zeno",
            zeno(),
            json!({"width": 4, "height": 4, "triangles": [{"v": [[0, 0], [5000, 0], [0, 4]]}]}),
            "4096",
        ),
    ];
    for (k, (who, exe, scene, word)) in cases.iter().enumerate() {
        let (output, out) = run_once(exe, scene, dir.path(), &format!("refused-{k}"));
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{who} {scene}: {stderr}");
        assert!(stderr.contains(word) && stderr.lines().count() == 1, "{who}: {stderr}");
        assert!(!out.exists());
    }
    let answers = serve(
        &ab_glyph(),
        &[cases[0].2.clone(), json!({"width": 2, "height": 2})],
        dir.path(),
    );
    assert!(
        answers[0].as_ref().is_err_and(|e| e.contains("even-odd")),
        "{answers:?}"
    );
    assert!(answers[1].is_ok(), "{answers:?}");
}

/// ab_glyph against the exact coverage of the scene as one path (accumulated, which for
/// nonzero is `min(1, |acc|)`: the adapter's clamp), quantized by `round16` (the
/// adapter's exact rounding of ab_glyph's f32). Its departures are f32 error: ab_glyph
/// walks each edge in f32 (`x += dxdy dy` row by row, positions at the magnitude of the
/// canvas: ulp(16) = 2^-19 px, ulp(100) = 2^-17 px, 0.5 quanta of 1/65535), deposits
/// closed-form trapezoid areas, and reads the pixels as **one running f32 sum over the
/// whole buffer** (never reset at a row's end), so the rounding of each row's sum
/// carries into the rows below. Measured: at most 1.05 quanta on the nonzero scenes of
/// the FreeType family (16x16, shapes reaching 4 px past the canvas) and on
/// `glyph.json`, 3.44 quanta on `dejavu.json` (102x32, 7 glyphs), every pixel within 4
/// levels of the exact value's.
///
/// `area::float` (the crate's f32 accumulation, "ab_glyph's method") does not reproduce
/// it pixel for pixel: it cuts each row's piece at every column and sums each row on its
/// own, ab_glyph uses its closed-form per-row trapezoids and one running sum (and the
/// crate folds each shape before adding them). Measured on the same scenes: up to 46 of
/// 256 pixels of a triangle scene and 4 of `glyph.json`'s 1024 differ by a level.
#[test]
fn ab_glyph_is_within_f32_error_of_the_exact_coverage() {
    let dir = tempdir::Dir::new("aa-ab-exact");
    let mut scenes: Vec<Value> = (0..60).map(crate::adapters_area::scene).collect();
    scenes.push(fixed("glyph.json"));
    let dejavu = scenes.len();
    scenes.push(fixed("dejavu.json"));
    let outs = serve(&ab_glyph(), &scenes, dir.path());
    let (mut drawn, mut lit_pixels) = (0, 0);
    for (k, (s, out)) in scenes.iter().zip(&outs).enumerate() {
        let (sh, w, h) = shapes(s);
        if rule_of(&sh) == FillRule::EvenOdd {
            assert!(
                out.as_ref().is_err_and(|e| e.contains("even-odd")),
                "scene {k}: {out:?}"
            );
            continue;
        }
        let theirs = GreyImage::read_png(&std::fs::read(out.as_ref().unwrap()).unwrap(), "ab").unwrap();
        let report = compare_grey(
            &one_path(&sh, FillRule::NonZero),
            &canvas(w, h),
            &theirs,
            &grey_options(Semantics::Accumulated, Quantization::Round16),
        )
        .unwrap();
        let bound = if k == dejavu { r(7, 2) } else { r(11, 10) };
        assert!(report.max_error <= bound, "scene {k} {s}: {}", report.levels_text(10));
        assert!(
            report.histogram.keys().all(|&d| d <= 4),
            "scene {k}: {:?}",
            report.histogram
        );
        drawn += 1;
        lit_pixels += theirs.levels.iter().filter(|l| **l != 0).count();
    }
    assert!(
        drawn >= 30 && lit_pixels > 3000,
        "{drawn} scenes, {lit_pixels} lit pixels"
    );
}

/// zeno against the exact coverage of the scene as one path under its rule (accumulated),
/// quantized by `ftgrays` (`min(255, floor(256 v))`, FreeType's levels, which zeno's are).
/// Its departures: the floor (up to one level below), `~` on a negative accumulation (one
/// more level below), the 24.8 truncation of each coordinate (1/3-grid scenes), and its
/// 32-bit reciprocal divisions (`0xFFFFFF / d`, `>> 24`: an exit point up to 1/256 px
/// short, about a level in that cell). Measured on every scene of the FreeType family
/// (even-odd included), `glyph.json`, `glyph-even-odd.json` and `dejavu.json`: at most
/// 2.44 quanta of 1/256, every pixel within 3 levels of the exact value's.
///
/// The crate's `area::ftgrays` model (FreeType's method in FreeType's y-up frame, 26.6
/// points, a 64-bit reciprocal) does not reproduce zeno: zeno is y down (so `~` falls on
/// the other orientation), keeps 24.8 from f32 and divides with the 32-bit reciprocal.
/// Measured: 59 of `glyph.json`'s 1024 pixels differ from the model, 43 from the exact
/// value quantized by `ftgrays`.
#[test]
fn zeno_is_within_its_fixed_point_error_of_the_exact_coverage() {
    let dir = tempdir::Dir::new("aa-zeno-exact");
    let mut scenes: Vec<Value> = (0..60).map(crate::adapters_area::scene).collect();
    for f in ["glyph.json", "glyph-even-odd.json", "dejavu.json"] {
        scenes.push(fixed(f));
    }
    let outs = serve(&zeno(), &scenes, dir.path());
    let mut lit_pixels = 0;
    for (k, (s, out)) in scenes.iter().zip(&outs).enumerate() {
        let (sh, w, h) = shapes(s);
        let theirs = GreyImage::read_png(&std::fs::read(out.as_ref().unwrap()).unwrap(), "zeno").unwrap();
        let report = compare_grey(
            &one_path(&sh, rule_of(&sh)),
            &canvas(w, h),
            &theirs,
            &grey_options(Semantics::Accumulated, Quantization::FtGrays),
        )
        .unwrap();
        assert!(report.max_error <= r(5, 2), "scene {k} {s}: {}", report.levels_text(10));
        assert!(
            report.histogram.keys().all(|&d| d <= 3),
            "scene {k}: {:?}",
            report.histogram
        );
        lit_pixels += theirs.levels.iter().filter(|l| **l != 0).count();
    }
    assert!(lit_pixels > 5000, "{lit_pixels} lit pixels");
}

/// `compare --as grey --fit` (`fit_grey`) on `glyph.json` (one polygon with a counter
/// running against it: every semantics gives the same values) names, for each adapter,
/// its own method first, alone with no pixel off (`area::abglyph`, `area::zeno`: the
/// models proven equal to the crates in `tests/area_crates_models.rs`), then an exact
/// coverage quantized the adapter's way:
///
/// - ab_glyph (16-bit): exact, `round16`, 3 of 1024 pixels off (each one level: f32
///   error next to a rounding boundary); the generic f32 accumulation (`area::float`,
///   each row on its own) is 4 off;
/// - zeno (8-bit): exact, `ftgrays`, 43 off; FreeType's method (`area::ftgrays`, y up,
///   64-bit reciprocal) is 59 off.
#[test]
fn fit_names_each_renderer_first() {
    let dir = tempdir::Dir::new("aa-fit");
    let glyph = fixed("glyph.json");
    let (sh, w, h) = shapes(&glyph);
    for (exe, own, q, best, float_or_ft) in [
        (
            ab_glyph(),
            GreyMethod::own(AreaMethod::AbGlyph),
            Quantization::Round16,
            3,
            (
                GreyMethod::quantized(AreaMethod::Float, Semantics::Accumulated, Quantization::Round16),
                4,
            ),
        ),
        (
            zeno(),
            GreyMethod::own(AreaMethod::Zeno),
            Quantization::FtGrays,
            43,
            (GreyMethod::own(AreaMethod::FtGrays), 59),
        ),
    ] {
        let theirs = draw(&exe, &glyph, dir.path(), q.name());
        let fit = fit_grey(&sh, &canvas(w, h), &theirs, Model::Exact).unwrap().methods;
        assert_eq!(fit[0], (own, 0), "{fit:?}");
        assert!(fit[1..].iter().all(|(_, n)| *n >= best), "{fit:?}");
        assert_eq!(
            fit[1],
            (GreyMethod::quantized(AreaMethod::Planned, Semantics::True, q), best),
            "{fit:?}"
        );
        for s in Semantics::ALL {
            assert!(
                fit.contains(&(GreyMethod::quantized(AreaMethod::Planned, s, q), best)),
                "{fit:?}"
            );
        }
        assert!(fit.contains(&float_or_ft), "{fit:?}");
    }
}

/// Overlapping contours.
///
/// - One polygon whose hole runs the outline's way (the outline [0, 4]^2 and the hole
///   [1, 5/2]^2, both clockwise on screen), on a 4x4 canvas: the path winds 2 inside the
///   hole. Exact true coverage (inside the outline, in no hole): pixel (1, 1) 0, (2, 1)
///   and (1, 2) 1/2 (32767.5: 32768), (2, 2) 3/4 (49151.25: 49151). ab_glyph sums the
///   winding numbers: 2, 3/2, 3/2 and 5/4, past 1 (its note counts the 4 pixels, up to
///   2), clamped by the adapter to 65535: the accumulated semantics' level (FreeType's
///   fold, `min(1, |acc|)`, is also 1 there). Against the exact true coverage, these four
///   pixels and no other differ, each of the `accumulation` class.
/// - Two polygons of opposite orientations, A = [1, 5/2] x [1, 3] and B = [2, 4] x [1,
///   5/2] reversed: one buffer cancels. Pixel (2, 2) (A its left half, B its top half)
///   is `|1/2 - 1/2|` = 0, pixel (2, 1) (A half, B all) `|1/2 - 1|` = 1/2 (32768):
///   levels none of the crate's semantics gives (they fold each shape and add: true 3/4
///   and 1, accumulated 1 and 1.5), but exactly what the scene as one path gives; zeno's
///   one path cancels the same way (0, and 128 or 127).
#[test]
fn overlapping_contours_add_in_one_path() {
    let dir = tempdir::Dir::new("aa-overlap");
    let rect = |x0: &str, y0: &str, x1: &str, y1: &str| json!([[x0, y0], [x1, y0], [x1, y1], [x0, y1]]);
    let at = |image: &GreyImage, x: u32, y: u32| image.levels[(y * image.width + x) as usize];

    let same_way = json!({"width": 4, "height": 4, "polygons": [
        {"v": rect("0", "0", "4", "4"), "holes": [rect("1", "1", "5/2", "5/2")]}]});
    let (output, out) = run_once(&ab_glyph(), &same_way, dir.path(), "same-way");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    assert!(stderr.contains("exceeds 1 at 4 pixel(s) (up to 2:"), "{stderr}");
    let theirs = GreyImage::read_png(&std::fs::read(out).unwrap(), "same-way").unwrap();
    assert!(theirs.levels.iter().all(|l| *l == 65535), "{:?}", theirs.levels);
    let (sh, w, h) = shapes(&same_way);
    let report = compare_grey(
        &sh,
        &canvas(w, h),
        &theirs,
        &grey_options(Semantics::True, Quantization::Round16),
    )
    .unwrap();
    let differing: Vec<(u32, u32, u16, u16, GreyClass)> = report
        .pixels
        .iter()
        .map(|p| (p.x, p.y, p.theirs, p.ours, p.class))
        .collect();
    assert_eq!(
        differing,
        [
            (1, 1, 65535, 0, GreyClass::Accumulation),
            (2, 1, 65535, 32768, GreyClass::Accumulation),
            (1, 2, 65535, 32768, GreyClass::Accumulation),
            (2, 2, 65535, 49151, GreyClass::Accumulation),
        ],
        "{}",
        report.levels_text(10)
    );

    let mut b_reversed = rect("2", "1", "4", "5/2").as_array().unwrap().clone();
    b_reversed.reverse();
    let opposite = json!({"width": 4, "height": 4, "polygons": [{"v": rect("1", "1", "5/2", "3")}, {"v": b_reversed}]});
    let (sh, w, h) = shapes(&opposite);
    assert_eq!(exact::value(&sh, 2, 2, Semantics::True), r(3, 4));
    let theirs = draw(&ab_glyph(), &opposite, dir.path(), "opposite");
    assert_eq!((at(&theirs, 2, 2), at(&theirs, 2, 1)), (0, 32768));
    for s in Semantics::ALL {
        let levels = (
            Quantization::Round16.level(&exact::value(&sh, 2, 2, s)),
            Quantization::Round16.level(&exact::value(&sh, 2, 1, s)),
        );
        assert_ne!(levels, (0, 32768), "{}", s.name());
    }
    let path = one_path(&sh, FillRule::NonZero);
    let report = compare_grey(
        &path,
        &canvas(w, h),
        &theirs,
        &grey_options(Semantics::Accumulated, Quantization::Round16),
    )
    .unwrap();
    assert!(report.pixels.is_empty(), "{}", report.levels_text(10));
    let z = draw(&zeno(), &opposite, dir.path(), "zeno-opposite");
    assert_eq!(at(&z, 2, 2), 0);
    assert!([127, 128].contains(&at(&z, 2, 1)), "{}", at(&z, 2, 1));
}

/// `--serve` answers with the PNG the per-scene command writes, byte for byte (the same
/// render function and encoder behind both), for both adapters on hand, random and glyph
/// scenes.
#[test]
fn serve_answers_the_per_scene_png() {
    let dir = tempdir::Dir::new("aa-serve");
    let scenes = vec![
        json!({"width": 6, "height": 6, "triangles": [{"v": [[2, 3], [3, 4], [2, 4]]}]}),
        crate::adapters_area::scene(0),
        crate::adapters_area::scene(2),
        fixed("glyph.json"),
    ];
    for (name, exe) in [("ab", ab_glyph()), ("zeno", zeno())] {
        let sub = dir.path().join(name);
        std::fs::create_dir_all(&sub).unwrap();
        let served = serve(&exe, &scenes, &sub);
        for (k, (s, png)) in scenes.iter().zip(&served).enumerate() {
            let (output, once) = run_once(&exe, s, &sub, &format!("once-{k}"));
            assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
            let served = std::fs::read(png.as_ref().unwrap()).unwrap();
            assert_eq!(served, std::fs::read(once).unwrap(), "{name} scene {k}");
            assert!(GreyImage::read_png(&served, "served").is_ok());
        }
    }
}
