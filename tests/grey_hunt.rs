//! The grey comparison's conflation and per-shape quantization classes, derived by hand;
//! `--fit` naming shapes blended one by one; their output read as a grey image; the grey
//! hunt's verdicts; and the committed grey fixtures (adapters/fixtures/grey.json): each
//! still shows its signature, and each real renderer still draws it as committed.

use std::path::{Path, PathBuf};
use std::process::Command;

use num_rational::BigRational;
use rasterproof::area::{conflate, AreaMethod, Quantization, Semantics};
use rasterproof::geom::{FillRule, Point, Polygon};
use rasterproof::oracle::compare::fit::grey::{fit_grey, GreyMethod};
use rasterproof::oracle::compare::grey::{compare_grey, GreyClass};
use rasterproof::oracle::hunt::{judge_grey, GreySignature, GreyVerdict};
use rasterproof::oracle::renderer::program::FailureKind;
use rasterproof::oracle::GreyImage;
use rasterproof::oracle::{Background, Format, Theirs};
use rasterproof::scene::{parse_scene, Scene};
use serde_json::Value;

use crate::common::{canvas, grey_options};
use crate::tempdir;

fn r(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// The rectangle `[x0, x1] x [0, 1]` (fractions of a pixel), nonzero.
fn strip(x0: BigRational, x1: BigRational) -> Polygon {
    let p = |x: &BigRational, y: i64| Point::new(x.clone(), r(y, 1));
    Polygon::new(vec![p(&x0, 0), p(&x1, 0), p(&x1, 1), p(&x0, 1)], FillRule::NonZero)
}

fn one_pixel(level: u16, bits: u32) -> GreyImage {
    GreyImage {
        width: 1,
        height: 1,
        bits,
        levels: vec![level],
    }
}

/// Two strips covering the left and right halves of pixel (0, 0): 1/2 + 1/2 = 1 exactly
/// (level 255); blended source-over, `1 - (1/2)(1/2) = 3/4`, rounded `191.25 -> 191`, is
/// conflation, 64 quanta under. Level 255 is the same; 191 for one strip of 3/4 is the same
/// too (one shape: nothing to conflate).
#[test]
fn conflation_by_hand() {
    let halves = [strip(r(0, 1), r(1, 2)), strip(r(1, 2), r(1, 1))];
    let report = compare_grey(
        &halves,
        &canvas(1, 1),
        &one_pixel(191, 8),
        &grey_options(Semantics::True, Quantization::Round8),
    )
    .unwrap();
    assert_eq!(report.pixels.len(), 1);
    assert_eq!(report.pixels[0].class, GreyClass::Conflation);
    assert_eq!(report.pixels[0].error, r(-64, 1));
    assert_eq!(
        conflate::pixel(&halves, 0, 0, conflate::Own::Exact(Semantics::True)),
        r(3, 4)
    );
    let same = compare_grey(
        &halves,
        &canvas(1, 1),
        &one_pixel(255, 8),
        &grey_options(Semantics::True, Quantization::Round8),
    )
    .unwrap();
    assert!(same.pixels.is_empty());
    let single = [strip(r(0, 1), r(3, 4))];
    let report = compare_grey(
        &single,
        &canvas(1, 1),
        &one_pixel(191, 8),
        &grey_options(Semantics::True, Quantization::Round8),
    )
    .unwrap();
    assert!(report.pixels.is_empty());
    // 192 rounds 191.25 up: quantization; 190 is no rounding of it, and one shape cannot
    // conflate: precision (1.25 quanta off).
    let at = |level| {
        let report = compare_grey(
            &single,
            &canvas(1, 1),
            &one_pixel(level, 8),
            &grey_options(Semantics::True, Quantization::Round8),
        )
        .unwrap();
        report.pixels[0].class
    };
    assert_eq!(at(192), GreyClass::Quantization);
    assert_eq!(at(190), GreyClass::Precision);
}

/// Two strips of 3/10 each: 6/10 of the pixel, `153.6` in FreeType's 1/256 units, level
/// 153. A renderer that truncates each shape on its own draws `76 + 76 = 152`: no rounding
/// of 153.6, but a sum of roundings of `76.8` each: quantization (per shape), not
/// precision. 151 is below every such sum: precision (within two quanta).
#[test]
fn per_shape_quantization_by_hand() {
    let strips = [strip(r(0, 1), r(3, 10)), strip(r(3, 10), r(6, 10))];
    let q = Quantization::FtGrays;
    let at = |level| {
        let report = compare_grey(
            &strips,
            &canvas(1, 1),
            &one_pixel(level, 8),
            &grey_options(Semantics::Accumulated, q),
        )
        .unwrap();
        report.pixels.first().map(|p| p.class)
    };
    assert_eq!(at(153), None);
    assert_eq!(at(152), Some(GreyClass::Quantization));
    assert_eq!(at(154), Some(GreyClass::Quantization));
    assert_eq!(at(151), Some(GreyClass::Precision));
}

/// A 4x1 canvas cut by two slanted edges into three abutting shapes: A left of the edge
/// from (3/2, 0) to (5/2, 1), C right of the edge from (11/4, 0) to (9/4, 1), B between.
/// By hand: pixel 1 is A's but for the triangle (3/2, 0) (2, 0) (2, 1/2) of area 1/8, so A
/// holds 7/8 and B 1/8, blended `1 - (1/8)(7/8) = 57/64`, `227.1` of 255: 227. In pixel
/// 2, A holds the triangle (2, 1/2) (5/2, 1) (2, 1) of area 1/8, C the trapezoid right of
/// `x = 11/4 - y/2` of area `1/4 + 1/4 = 1/2`, B the rest 3/8: `1 - (7/8)(5/8)(1/2) =
/// 93/128`, `185.3`: 185. Pixels 0 and 3 are whole: 255. `--fit` names the shapes blended
/// one by one first, with no pixel wrong, ahead of every exact semantics (1 everywhere:
/// both seam pixels wrong).
#[test]
fn fit_names_shapes_blended_one_by_one() {
    let p = |x: i64, d: i64, y: i64| Point::new(r(x, d), r(y, 1));
    let shapes = [
        Polygon::new(vec![p(0, 1, 0), p(3, 2, 0), p(5, 2, 1), p(0, 1, 1)], FillRule::NonZero),
        Polygon::new(vec![p(3, 2, 0), p(11, 4, 0), p(9, 4, 1), p(5, 2, 1)], FillRule::NonZero),
        Polygon::new(vec![p(11, 4, 0), p(4, 1, 0), p(4, 1, 1), p(9, 4, 1)], FillRule::NonZero),
    ];
    let levels = conflate::rasterize(&shapes, 4, 1, Semantics::Accumulated).levels(Quantization::Round8);
    assert_eq!(levels, vec![255, 227, 185, 255]);
    let theirs = GreyImage {
        width: 4,
        height: 1,
        bits: 8,
        levels,
    };
    let fits = fit_grey(&shapes, &canvas(4, 1), &theirs, rasterproof::model::Model::Exact)
        .unwrap()
        .methods;
    assert_eq!(
        fits[0],
        (
            GreyMethod::quantized(AreaMethod::Conflated, Semantics::Accumulated, Quantization::Round8),
            0
        ),
        "{fits:?}"
    );
    let exact = fits
        .iter()
        .find(|(m, _)| *m == GreyMethod::quantized(AreaMethod::Planned, Semantics::Accumulated, Quantization::Round8))
        .unwrap();
    assert_eq!(exact.1, 2, "{fits:?}");
}

/// Their output read as `--as grey`: an 8-bit grey PNG's levels; an RGB PNG is an error
/// naming the file; as a mask, a pixel is covered where its level is not zero.
#[test]
fn their_grey_png_is_read() {
    let mut png = Vec::new();
    image::GrayImage::from_raw(3, 1, vec![0, 7, 255])
        .unwrap()
        .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .unwrap();
    let theirs = Theirs::read(&png, "theirs.png", Format::Grey, Background::default()).unwrap();
    assert_eq!(theirs.grey().unwrap().levels, vec![0, 7, 255]);
    assert_eq!(theirs.covered(), vec![(1, 0), (2, 0)]);
    assert_eq!(Format::from_name("grey"), Some(Format::Grey));
    let mut rgb = Vec::new();
    image::RgbImage::new(2, 2)
        .write_to(&mut std::io::Cursor::new(&mut rgb), image::ImageFormat::Png)
        .unwrap();
    let e = Theirs::read(&rgb, "theirs.png", Format::Grey, Background::default()).unwrap_err();
    assert_eq!(e.file, "theirs.png");
    assert!(e.message.contains("Rgb8"), "{e}");
}

/// The grey hunt's verdicts: the exact levels are the same; a 16-bit image where 8 bits
/// are asked for is their renderer's failure (unreadable output); an ids image is too.
#[test]
fn grey_verdicts() {
    let scene = parse_scene(
        r#"{"width":2,"height":1,"polygons":[{"v":[["0","0"],["3/2","0"],["3/2","1"],["0","1"]]}]}"#,
        "s",
    )
    .unwrap();
    let grey = |bits, levels: Vec<u16>| {
        Ok(Theirs::from_grey(GreyImage {
            width: 2,
            height: 1,
            bits,
            levels,
        }))
    };
    let q = Quantization::Round8;
    assert!(matches!(
        judge_grey(&scene, grey(8, vec![255, 128]), Semantics::True, q, None),
        GreyVerdict::Same
    ));
    let verdict = judge_grey(&scene, grey(8, vec![255, 127]), Semantics::True, q, None);
    let sigs = rasterproof::oracle::hunt::grey_signatures(&verdict);
    let sig = GreySignature::Class {
        class: GreyClass::Quantization,
        over: false,
    };
    assert_eq!(sigs.get(&sig), Some(&(1, r(1, 2))), "{sigs:?}");
    assert_eq!(sig.slug(), "quantization-under");
    let GreyVerdict::Failed(f) = judge_grey(&scene, grey(16, vec![65535, 32768]), Semantics::True, q, None) else {
        panic!("a 16-bit image read as 8-bit levels is a failure");
    };
    assert_eq!(f.kind, FailureKind::BadOutput);
    assert!(f.message.contains("16-bit"), "{f}");
    // The message names the quantization that reads their depth.
    assert!(f.message.contains("16-bit levels is round16"), "{f}");
    let ids = rasterproof::coverage::Coverage::new(2, 1);
    assert!(matches!(
        judge_grey(
            &scene,
            Ok(Theirs::from_coverage(&ids, Format::Ids)),
            Semantics::True,
            q,
            None
        ),
        GreyVerdict::Failed(_)
    ));
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The committed grey fixtures: `(renderer, scene, theirs, semantics, quantization,
/// signature)`.
fn fixtures() -> Vec<Value> {
    let text = std::fs::read_to_string(root().join("adapters/fixtures/grey.json")).unwrap();
    let v: Value = serde_json::from_str(&text).unwrap();
    v["fixtures"].as_array().unwrap().clone()
}

fn shapes_of(scene: &Scene) -> Vec<Polygon> {
    let target = scene.target().unwrap();
    rasterproof::model::area_shapes(&scene.primitives(), &target, rasterproof::model::Model::Exact).unwrap()
}

/// Every grey fixture's committed PNG shows its signature against exact coverage (no
/// renderer needed), and fails to without it: the comparison names the class.
#[test]
fn grey_fixtures_show_their_signatures() {
    let all = fixtures();
    assert!(all.len() >= 6, "{} fixtures", all.len());
    for f in &all {
        if f["theirs"].is_null() {
            // A failure: the renderer refused the scene (renderers_still_draw_the_grey_fixtures).
            assert!(f["signature"].as_str().unwrap().starts_with("failure: "), "{f}");
            continue;
        }
        let scene_path = root().join("adapters/fixtures").join(f["scene"].as_str().unwrap());
        let scene = parse_scene(&std::fs::read_to_string(&scene_path).unwrap(), "fixture").unwrap();
        let png = std::fs::read(root().join("adapters/fixtures").join(f["theirs"].as_str().unwrap())).unwrap();
        let theirs = Theirs::read(&png, "fixture", Format::Grey, Background::default()).unwrap();
        let semantics = Semantics::from_name(f["semantics"].as_str().unwrap()).unwrap();
        let q = Quantization::from_name(f["quantization"].as_str().unwrap()).unwrap();
        let verdict = judge_grey(&scene, Ok(theirs), semantics, q, None);
        let names: Vec<String> = rasterproof::oracle::hunt::grey_signatures(&verdict)
            .keys()
            .map(|s| s.describe())
            .collect();
        assert!(
            names.iter().any(|n| n == f["signature"].as_str().unwrap()),
            "{}: {names:?}",
            f["scene"]
        );
        assert!(!shapes_of(&scene).is_empty());
    }
}

/// The command that draws a fixture's renderer, or `None` when it cannot run here.
fn renderer(name: &str) -> Option<Vec<String>> {
    match name {
        "freetype" => {
            let python = std::env::var("RASTERPROOF_ADAPTER_PYTHON").unwrap_or_else(|_| "/usr/bin/python3".into());
            let ok = Command::new(&python)
                .args(["-c", "import ctypes, PIL; ctypes.CDLL('libfreetype.so.6')"])
                .output()
                .is_ok_and(|o| o.status.success());
            assert!(ok || std::env::var_os("CI").is_none(), "CI is set: FreeType must run");
            ok.then(|| vec![python, root().join("adapters/freetype/render.py").display().to_string()])
        }
        "tiny-skia" => Some(vec![
            crate::adapters::tiny_skia_adapter().display().to_string(),
            "--grey".to_string(),
        ]),
        "ab-glyph" => Some(vec![crate::adapters::example("ab-glyph-adapter").display().to_string()]),
        "zeno" => Some(vec![crate::adapters::example("zeno-adapter").display().to_string()]),
        other => panic!("unknown renderer {other}"),
    }
}

/// Each real renderer, where it runs, still draws every fixture exactly as committed.
#[test]
fn renderers_still_draw_the_grey_fixtures() {
    let dir = tempdir::Dir::new("grey-fixtures");
    for (k, f) in fixtures().iter().enumerate() {
        let Some(command) = renderer(f["renderer"].as_str().unwrap()) else {
            continue;
        };
        let scene = root().join("adapters/fixtures").join(f["scene"].as_str().unwrap());
        if f["signature"].as_str().unwrap().starts_with("failure") {
            let out = dir.path().join(format!("{k}.png"));
            let status = Command::new(&command[0])
                .args(&command[1..])
                .arg(&scene)
                .arg(&out)
                .status()
                .unwrap();
            assert!(!status.success(), "{}: the renderer no longer fails", f["scene"]);
            continue;
        }
        let out = dir.path().join(format!("{k}.png"));
        let status = Command::new(&command[0])
            .args(&command[1..])
            .arg(&scene)
            .arg(&out)
            .status()
            .unwrap();
        assert!(status.success(), "{}", f["scene"]);
        let drawn = image::open(&out).unwrap().to_luma8();
        let committed = image::open(root().join("adapters/fixtures").join(f["theirs"].as_str().unwrap()))
            .unwrap()
            .to_luma8();
        assert_eq!(drawn, committed, "{}", f["scene"]);
    }
}

/// `rasterproof hunt --as grey` against tiny-skia through the stay-alive protocol, a
/// short hunt: it finds something (tiny-skia supersamples), exits 1, writes each
/// finding's minimal scene and tiny-skia's PNG of it, and every finding is of a class a
/// tiny-skia fixture shows (a new kind of difference fails until it is understood).
#[test]
fn grey_hunt_against_tiny_skia() {
    let adapter = crate::adapters::tiny_skia_adapter();
    let serve = format!("{} --grey --serve", adapter.display());
    short_hunt("tiny-skia", &serve, &["--quantization", "round", "--float32-exact"]);
}

/// The same against ab_glyph_rasterizer (16-bit levels) and zeno.
#[test]
fn grey_hunt_against_ab_glyph_and_zeno() {
    let ab = crate::adapters::example("ab-glyph-adapter");
    short_hunt(
        "ab-glyph",
        &format!("{} --serve", ab.display()),
        &["--quantization", "round16", "--float32-exact"],
    );
    let zeno = crate::adapters::example("zeno-adapter");
    short_hunt(
        "zeno",
        &format!("{} --serve", zeno.display()),
        &["--quantization", "ftgrays", "--float32-exact"],
    );
}

/// The same against FreeType (its adapter's `--serve`), on its 1/64 px grid (`--grid 6`).
#[test]
fn grey_hunt_against_freetype() {
    let Some(command) = renderer("freetype") else {
        return;
    };
    let serve = format!("{} {} --serve", command[0], command[1]);
    short_hunt("freetype", &serve, &["--quantization", "ftgrays", "--grid", "6"]);
}

/// A 12-scene grey hunt (seed 2026, 8x8, accumulated semantics) of `serve` with `args`:
/// it finds something, exits 1, writes each finding's scene and PNG, and every finding is
/// of a class one of `name`'s fixtures shows.
fn short_hunt(name: &str, serve: &str, args: &[&str]) {
    let dir = tempdir::Dir::new("grey-hunt");
    let out = dir.path().join("found");
    let report = dir.path().join("report.json");
    let output = assert_cmd::Command::cargo_bin("rasterproof")
        .unwrap()
        .args(["hunt", "--as", "grey", "--semantics", "accumulated", "--quiet"])
        .args(args)
        .args([
            "--cases",
            "12",
            "--seed",
            "2026",
            "--canvas",
            "8",
            "--shrink-runs",
            "40",
        ])
        .arg("--serve")
        .arg(serve)
        .arg("--out")
        .arg(&out)
        .arg("--report")
        .arg(&report)
        .output()
        .unwrap();
    assert_eq!(
        output.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let report: Value = serde_json::from_str(&std::fs::read_to_string(&report).unwrap()).unwrap();
    assert_eq!(report["cases"], 12);
    let known: Vec<String> = fixtures()
        .iter()
        .filter(|f| f["renderer"] == name)
        .map(|f| f["signature"].as_str().unwrap().to_string())
        .collect();
    let findings = report["findings"].as_array().unwrap();
    assert!(!findings.is_empty());
    for (n, f) in findings.iter().enumerate() {
        let sig = f["signature"].as_str().unwrap();
        assert!(
            known.iter().any(|k| k == sig),
            "{sig} is not among {name}'s fixtures {known:?}"
        );
        let json = out.join(format!("finding-{:02}.json", n + 1));
        assert!(Path::new(&json).is_file(), "finding {}", n + 1);
        let png = out.join(format!("finding-{:02}.png", n + 1));
        assert_eq!(
            Path::new(&png).is_file(),
            !sig.starts_with("failure"),
            "finding {}",
            n + 1
        );
    }
}

/// The grey hunt's options are checked: `--semantics` or `--method` without `--as grey`,
/// `--model` with it, an unknown method (the message lists the names), a method with a
/// quantization, and an unknown quantization are errors naming the option.
#[test]
fn grey_hunt_options_are_checked() {
    let run = |args: &[&str]| {
        let output = assert_cmd::Command::cargo_bin("rasterproof")
            .unwrap()
            .args(["hunt", "--cmd", "true {scene} {out}"])
            .args(args)
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        String::from_utf8_lossy(&output.stderr).to_string()
    };
    assert!(run(&["--semantics", "accumulated"]).contains("--semantics"));
    assert!(run(&["--as", "grey", "--model", "exact"]).contains("--model"));
    assert!(run(&["--method", "ftgrays"]).contains("--method are for --as grey"));
    let unknown = run(&["--as", "grey", "--method", "ss4"]);
    assert!(
        unknown.contains("--method: no grey method named \"ss4\"") && unknown.contains("supersample-4x4-round"),
        "{unknown}"
    );
    // A method names its own quantization.
    assert!(run(&["--as", "grey", "--method", "ftgrays", "--quantization", "round16"]).contains("--quantization"));
    assert!(run(&["--as", "grey", "--quantization", "half"]).contains("--quantization: unknown quantization \"half\""));
    assert!(run(&["--as", "grey", "--grid", "20"]).contains("--grid: 20"));
}

/// A renderer that prints garbage: the grey hunt's finding is a failure whose text shows
/// what it answered (not only "protocol error"), whose summary line gives no pixels and no
/// error in quanta (a failure has none), and whose report names its format, version and
/// the failure's kind and message.
#[test]
fn a_failing_renderer_is_reported_with_its_answer() {
    use rasterproof::oracle::hunt::{hunt_grey, GreyHuntConfig, HuntConfig, AREA_FAMILIES};
    use rasterproof::oracle::renderer::program::RenderFailure;
    let garbage = |_: &Scene| -> Result<Theirs, RenderFailure> {
        Err(RenderFailure {
            kind: FailureKind::Protocol,
            message: "its answer was not an image: \"hello, world\"".to_string(),
        })
    };
    let config = GreyHuntConfig {
        hunt: HuntConfig {
            cases: 3,
            canvas: 4,
            families: AREA_FAMILIES.to_vec(),
            shrink_runs: 20,
            ..HuntConfig::default()
        },
        semantics: Semantics::True,
        quantization: Quantization::Round8,
        grid: None,
        method: None,
    };
    let report = hunt_grey(&garbage, &config, 1, &|| {}, &Default::default()).unwrap();
    assert_eq!(report.failed + report.refused, 3);
    let [finding] = report.findings.as_slice() else {
        panic!("one failure signature: {:?}", report.findings);
    };
    assert_eq!(finding.signature, GreySignature::Failure(FailureKind::Protocol));
    let text = finding.to_text(1);
    assert!(
        text.starts_with("finding 01: failure: protocol error (first in case"),
        "{text}"
    );
    assert!(text.contains("\"hello, world\""), "{text}");
    assert!(text.contains("the original scene:"), "{text}");
    let summary = report.to_text(8);
    assert!(!summary.contains("quanta") && !summary.contains("pixels,"), "{summary}");
    assert!(summary.contains("hello, world"), "{summary}");
    let json = report.to_json("garbage");
    assert_eq!(json["format"], "rasterproof grey hunt report");
    assert_eq!(json["version"], 3);
    assert_eq!(json["rasterproof"], env!("CARGO_PKG_VERSION"));
    assert_eq!(json["renderer_runs"], Value::Null, "a closure is not a program");
    assert_eq!(json["findings"][0]["failure"]["kind"], "protocol error");
    assert!(json["findings"][0]["failure"]["message"]
        .as_str()
        .unwrap()
        .contains("hello, world"));
}

/// `--limit 0` asks for the counts alone: the grey text lists no pixel and says nothing of
/// "more" of them; `--limit 1` lists one and says how many more.
#[test]
fn limit_zero_lists_no_pixels() {
    let shapes = [strip(r(0, 1), r(3, 2))];
    let theirs = GreyImage {
        width: 2,
        height: 1,
        bits: 8,
        levels: vec![250, 120],
    };
    let report = compare_grey(
        &shapes,
        &canvas(2, 1),
        &theirs,
        &grey_options(Semantics::True, Quantization::Round8),
    )
    .unwrap();
    assert_eq!(report.pixels.len(), 2);
    let none = report.levels_text(0);
    assert!(!none.contains("more") && !none.contains("theirs 250"), "{none}");
    let one = report.levels_text(1);
    assert!(one.contains("theirs 250") && one.contains("... and 1 more"), "{one}");
}

/// A plain 4 x 4 supersampler (each sample tested against every edge, top-left ties),
/// rounded to 8 bits: the renderer the method tests judge.
fn supersampled_4x4(scene: &Scene) -> Result<Theirs, rasterproof::oracle::renderer::program::RenderFailure> {
    let target = scene.target().unwrap();
    let shapes =
        rasterproof::model::area_shapes(&scene.primitives(), &target, rasterproof::model::Model::Exact).unwrap();
    let mut levels = Vec::new();
    for y in 0..scene.height {
        for x in 0..scene.width {
            let n: u32 = rasterproof::area::supersample::row_counts_with(
                &shapes,
                x,
                y,
                4,
                rasterproof::convention::AnyTieRule::TopLeft,
            )
            .iter()
            .sum();
            // round(255 n / 16), ties to even: the one tie is n = 8 (255 = -1 mod 16, so
            // 255 n = 8 mod 16 only there), 127.5, to 128; elsewhere floor(255 n / 16 + 1/2).
            let level = if n == 8 { 128 } else { (510 * n + 16) / 32 };
            levels.push(u16::try_from(level).unwrap());
        }
    }
    Ok(Theirs::from_grey(GreyImage {
        width: scene.width,
        height: scene.height,
        bits: 8,
        levels,
    }))
}

/// Judging against a method (`GreyOptions::method`): a plain 4 x 4 supersampler's image of
/// a triangle differs from the exact value's levels at its edge pixels, and from the
/// 4 x 4 method at none; judged against the exact levels as a method
/// (`exact-true-round`), the pixels listed are those where its level is not the exact
/// value's (the exact value by the plain area oracle, pixel by pixel), each with the
/// method's level. `judge` names the method in the headline (`explained_by`).
#[test]
fn judging_against_a_method_lists_the_pixels_it_misses() {
    use rasterproof::oracle::compare::grey::GreyOptions;
    let scene = parse_scene(
        r#"{"width":4,"height":4,"triangles":[{"v":[["1/3","0"],["4","5/7"],["0","4"]]}]}"#,
        "s",
    )
    .unwrap();
    let theirs = supersampled_4x4(&scene).unwrap();
    let grey = theirs.grey().unwrap().clone();
    let target = scene.target().unwrap();
    let shapes =
        rasterproof::model::area_shapes(&scene.primitives(), &target, rasterproof::model::Model::Exact).unwrap();
    let against = |name: &str| {
        let method = GreyMethod::from_name(name, 8).unwrap();
        let (semantics, quantization) = method.judged_as(8);
        let options = GreyOptions {
            model: rasterproof::model::Model::Exact,
            semantics,
            quantization,
            method: Some(method),
        };
        compare_grey(&shapes, &target, &grey, &options).unwrap()
    };
    let same = against("supersample-4x4-round");
    assert!(same.identical(), "{}", same.levels_text(10));
    let exact = against("exact-true-round");
    let mut expected = Vec::new();
    for y in 0..4u32 {
        for x in 0..4u32 {
            let v = rasterproof::area::exact::value(&shapes, i64::from(x), i64::from(y), Semantics::True);
            let level = Quantization::Round8.level(&v);
            let theirs = grey.levels[(y * 4 + x) as usize];
            if theirs != level {
                expected.push((x, y, theirs, Some(level)));
            }
        }
    }
    assert!(
        !expected.is_empty(),
        "the triangle's edges cut samples unevenly somewhere"
    );
    let listed: Vec<_> = exact.pixels.iter().map(|p| (p.x, p.y, p.theirs, p.method)).collect();
    assert_eq!(listed, expected);
    assert!(
        exact.levels_text(5).contains("(--method exact-true-round)"),
        "{}",
        exact.levels_text(5)
    );
    // The plain comparison finds the same pixels, and `judge` names the method that gives
    // every level.
    let question = rasterproof::oracle::Question::Grey(grey_options(Semantics::True, Quantization::Round8));
    let judged = rasterproof::oracle::judge(&scene.primitives(), &target, &theirs, &question).unwrap();
    let text = rasterproof::oracle::Comparison::to_text(&judged, "s", "t", 0);
    assert!(
        text.contains("one method gives every level of their image: 4x4 supersampling, quantized by round (--method supersample-4x4-round)"),
        "{text}"
    );
}

/// The grey hunt against a method: a plain 4 x 4 supersampler hunted against the exact
/// levels has findings (its sampling is not the exact area), against the 4 x 4 method none;
/// `--fit-first`'s search (`fit_grey_method`) finds the 4 x 4 method first.
#[test]
fn the_grey_hunt_judges_against_a_method() {
    use rasterproof::oracle::hunt::{
        fit_grey_method, hunt_grey, GreyFitFirst, GreyHuntConfig, HuntConfig, AREA_FAMILIES,
    };
    let config = |method: Option<&str>| GreyHuntConfig {
        hunt: HuntConfig {
            cases: 8,
            canvas: 5,
            families: AREA_FAMILIES.to_vec(),
            shrink_runs: 30,
            ..HuntConfig::default()
        },
        semantics: Semantics::True,
        quantization: Quantization::Round8,
        grid: None,
        method: method.map(|m| GreyMethod::from_name(m, 8).unwrap()),
    };
    let plain = hunt_grey(&supersampled_4x4, &config(None), 1, &|| {}, &Default::default()).unwrap();
    assert!(!plain.findings.is_empty() && plain.differing > 0);
    let against = hunt_grey(
        &supersampled_4x4,
        &config(Some("supersample-4x4-round")),
        1,
        &|| {},
        &Default::default(),
    )
    .unwrap();
    assert!(against.findings.is_empty(), "{}", against.to_text(5));
    assert_eq!(against.same, against.cases);
    assert!(against
        .to_text(0)
        .contains("against 4x4 supersampling, quantized by round (--method supersample-4x4-round)"));
    let GreyFitFirst::Found(methods) = fit_grey_method(&supersampled_4x4, &config(None)).unwrap() else {
        panic!("the 4x4 method gives every level");
    };
    assert_eq!(methods[0].name(), "supersample-4x4-round");
}

/// `hunt --as grey --fit-first` and `--method` with a real renderer, rasterproof's own
/// `render --coverage area` truncating its levels: the fit names the truncating method
/// and the hunt against it finds nothing (exit 0); against rounding it finds the
/// truncation (exit 1); `compare --method` likewise.
#[test]
fn hunt_and_compare_against_a_method_from_the_command_line() {
    let bin = assert_cmd::cargo::cargo_bin("rasterproof");
    let cmd = format!(
        "{} render {{scene}} --coverage area --quantization truncate --grey-out {{out}}",
        bin.display()
    );
    let hunt = |args: &[&str]| {
        let output = Command::new(&bin)
            .args([
                "hunt",
                "--as",
                "grey",
                "--cmd",
                &cmd,
                "--cases",
                "6",
                "--canvas",
                "6",
                "--shrink-runs",
                "20",
            ])
            .args(args)
            .output()
            .unwrap();
        let text = format!(
            "{}{}",
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        );
        (output.status.code(), text)
    };
    let (code, text) = hunt(&["--fit-first"]);
    assert_eq!(code, Some(0), "{text}");
    assert!(
        text.contains("fit: hunting against exact true coverage, quantized by truncate (--method exact-true-truncate)"),
        "{text}"
    );
    let (code, text) = hunt(&["--method", "exact-true-truncate"]);
    assert_eq!(code, Some(0), "{text}");
    let (code, text) = hunt(&["--method", "exact-true-round"]);
    assert_eq!(code, Some(1), "{text}");
    assert!(text.contains("quantization, under"), "{text}");
    // compare: the headline names the truncating methods; judged against one, no pixel differs.
    let dir = tempdir::Dir::new("method-compare");
    let scene = root().join("adapters/scenes/glyph.json");
    let png = dir.path().join("t.png");
    let rendered = Command::new(&bin)
        .args([
            "render",
            scene.to_str().unwrap(),
            "--coverage",
            "area",
            "--quantization",
            "truncate",
            "--grey-out",
            png.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(rendered.status.success());
    let compare = |args: &[&str]| {
        let output = Command::new(&bin)
            .args([
                "compare",
                scene.to_str().unwrap(),
                png.to_str().unwrap(),
                "--as",
                "grey",
                "--limit",
                "0",
            ])
            .args(args)
            .output()
            .unwrap();
        (
            output.status.code(),
            String::from_utf8_lossy(&output.stdout).to_string(),
        )
    };
    let (code, text) = compare(&[]);
    assert_eq!(code, Some(1));
    assert!(
        text.contains("methods give every level of their image (the image cannot tell them apart)"),
        "{text}"
    );
    assert!(text.contains("(--method exact-true-truncate)"), "{text}");
    let (code, text) = compare(&["--method", "exact-true-truncate"]);
    assert_eq!(code, Some(0), "{text}");
    assert!(
        text.contains("0 of 1024 pixels differ from exact true coverage, quantized by truncate"),
        "{text}"
    );
}
