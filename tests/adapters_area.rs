//! The anti-aliasing adapters (adapters/README.md): FreeType's smooth rasterizer through
//! `adapters/freetype/render.py` (Debian's libfreetype6 by ctypes), judged against the
//! exact area coverage.
//!
//! What is asserted, and why it should hold independently of these runs:
//! - `area::ftgrays` is written from FreeType's method (ftgrays.c's `gray_render_line`,
//!   its reciprocal division and `gray_hline`'s levels), not from its output; on every
//!   scene here (polygons with holes, nonzero and even-odd, tangled, on the 1/64, 1/256
//!   and thirds grids, partly off the canvas, several triangles) the library's levels and
//!   the model's must be the same, pixel for pixel;
//! - `compare --as grey --fit` then names FreeType's method, alone, as the one that gives
//!   FreeType's image (no exact quantization does: FreeType's divisions fall short).
//!
//! The tests need /usr/bin/python3 (or `RASTERPROOF_ADAPTER_PYTHON`) with python3-pil and
//! libfreetype6: without them they print a skip message, unless `CI` is set (.ci/run
//! installs them), where they fail.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use rasterproof::area::ftgrays;
use rasterproof::model::{area_shapes, Model};
use rasterproof::scene::parse_scene;
use serde_json::{json, Value};

use crate::rng::Rng;
use crate::tempdir;

fn python() -> String {
    std::env::var("RASTERPROOF_ADAPTER_PYTHON").unwrap_or_else(|_| "/usr/bin/python3".to_string())
}

fn adapter() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/freetype/render.py")
}

/// Whether the FreeType adapter can run here; without it: skip, or fail under CI.
fn freetype_available() -> bool {
    let probe = Command::new(python())
        .args(["-c", "import ctypes, PIL; ctypes.CDLL('libfreetype.so.6')"])
        .output();
    let missing = match probe {
        Ok(o) if o.status.success() => return true,
        Ok(o) => String::from_utf8_lossy(&o.stderr)
            .lines()
            .last()
            .unwrap_or("")
            .to_string(),
        Err(e) => format!("{}: {e}", python()),
    };
    let message = format!("FreeType or PIL is missing ({missing}); install libfreetype6 python3-pil");
    assert!(
        std::env::var_os("CI").is_none(),
        "CI is set, so this is an error: {message}"
    );
    eprintln!("skipping the FreeType adapter tests: {message}");
    false
}

/// Scene `k` of the family, on a 16x16 canvas, coordinates on a grid of 1/64, 1/256 or
/// 1/3 px: three triangles in [-4, 20]^2; a tangled polygon of 3 to 9 random points there
/// (nonzero or even-odd); or a star-shaped polygon of 5 to 9 points (radii 3 to 10 px
/// about a point of [2, 14]^2) with a star-shaped hole of 3 to 5 points (radii 0.4 to
/// 1 px), running either way. (`tests/adapters_aa_crates.rs` and
/// `tests/area_crates_models.rs` draw the same scenes.)
#[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation)]
pub fn scene(k: u64) -> Value {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15 ^ (k + 1).wrapping_mul(0x2545_F491_4F6C_DD1D));
    let d: i64 = [64, 64, 256, 3][usize::try_from(rng.below(4)).unwrap()];
    let on_grid = |v: f64| format!("{}/{d}", (v * d as f64).round() as i64);
    let random_point = |rng: &mut Rng| {
        json!([
            on_grid(rng.range(-4 * d, 20 * d) as f64 / d as f64),
            on_grid(rng.range(-4 * d, 20 * d) as f64 / d as f64)
        ])
    };
    let rule = if rng.below(2) == 0 { "nonzero" } else { "even-odd" };
    match rng.below(3) {
        0 => {
            let triangles: Vec<Value> = (0..3)
                .map(|_| json!({"v": [random_point(&mut rng), random_point(&mut rng), random_point(&mut rng)]}))
                .collect();
            json!({"width": 16, "height": 16, "triangles": triangles})
        }
        1 => {
            let outline: Vec<Value> = (0..3 + rng.below(7)).map(|_| random_point(&mut rng)).collect();
            json!({"width": 16, "height": 16, "polygons": [{"v": outline, "fill_rule": rule}]})
        }
        _ => {
            let (cx, cy) = (
                rng.range(2 * 64, 14 * 64) as f64 / 64.0,
                rng.range(2 * 64, 14 * 64) as f64 / 64.0,
            );
            let star = |n: i64, r_lo: f64, r_hi: f64, rng: &mut Rng| -> Vec<Value> {
                (0..n)
                    .map(|i| {
                        let jitter = (rng.below(1001) as f64 / 1000.0 - 0.5) * std::f64::consts::PI / n as f64;
                        let a = 2.0 * std::f64::consts::PI * i as f64 / n as f64 + jitter;
                        let r = r_lo + (r_hi - r_lo) * rng.below(1001) as f64 / 1000.0;
                        json!([on_grid(cx + r * a.cos()), on_grid(cy + r * a.sin())])
                    })
                    .collect()
            };
            let outline = star(5 + rng.below(5), 3.0, 10.0, &mut rng);
            let mut hole = star(3 + rng.below(3), 0.4, 1.0, &mut rng);
            if rng.below(2) == 0 {
                hole.reverse();
            }
            json!({"width": 16, "height": 16, "polygons": [{"v": outline, "holes": [hole], "fill_rule": rule}]})
        }
    }
}

/// Every request of `requests` (one JSON object each) through one `command` kept alive
/// (the stay-alive protocol): its answers, one per request, in order, and its stderr.
pub fn serve_answers(mut command: Command, requests: &[Value]) -> (Vec<Value>, String) {
    let mut child = command
        .arg("--serve")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    {
        let mut stdin = child.stdin.take().unwrap();
        for request in requests {
            writeln!(stdin, "{request}").unwrap();
        }
    }
    let output = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr).to_string();
    assert!(output.status.success(), "{stderr}");
    let answers: Vec<Value> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(answers.len(), requests.len(), "one answer per request");
    (answers, stderr)
}

/// FreeType's levels for each scene, through one adapter kept alive (the stay-alive
/// protocol), row by row.
fn freetype_levels(scenes: &[Value], dir: &Path) -> Vec<Vec<u8>> {
    let mut command = Command::new(python());
    command.arg(adapter());
    let requests: Vec<Value> = scenes
        .iter()
        .enumerate()
        .map(|(k, s)| json!({"rasterproof": 1, "id": k, "scene": s, "out": dir.join(format!("ft-{k}.png")), "as": "grey"}))
        .collect();
    let (answers, stderr) = serve_answers(command, &requests);
    for (k, answer) in answers.iter().enumerate() {
        assert_eq!(*answer, json!({"id": k, "ok": true}), "{stderr}");
    }
    (0..scenes.len())
        .map(|k| {
            image::open(dir.join(format!("ft-{k}.png")))
                .unwrap()
                .to_luma8()
                .into_raw()
        })
        .collect()
}

#[test]
fn freetype_draws_what_the_ftgrays_model_computes() {
    if !freetype_available() {
        return;
    }
    let dir = tempdir::Dir::new("freetype");
    let mut scenes: Vec<Value> = (0..60).map(scene).collect();
    for fixed in ["glyph.json", "glyph-even-odd.json"] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("adapters/scenes")
            .join(fixed);
        scenes.push(serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap());
    }
    let theirs = freetype_levels(&scenes, dir.path());
    for (k, (s, levels)) in scenes.iter().zip(&theirs).enumerate() {
        let parsed = parse_scene(&s.to_string(), "scene").unwrap();
        let target = parsed.target().unwrap();
        let shapes = area_shapes(&parsed.primitives(), &target, Model::Exact).unwrap();
        let ours = ftgrays::rasterize(&shapes, target.width, target.height).unwrap();
        let differing: Vec<(usize, u8, u8)> = ours
            .iter()
            .zip(levels)
            .enumerate()
            .filter(|(_, (a, b))| a != b)
            .map(|(i, (a, b))| (i, *a, *b))
            .collect();
        assert!(
            differing.is_empty(),
            "scene {k} {s}: (pixel, ours, FreeType's) {differing:?}"
        );
    }
    // Not all blank: the scenes exercise the walk.
    let lit: usize = theirs.iter().map(|l| l.iter().filter(|v| **v != 0).count()).sum();
    assert!(lit > 5000, "{lit} lit pixels");
}

/// Runs an adapter's command on `scene` into `out`; asserts it succeeded.
fn draw(command: &mut Command, scene: &Path, out: &Path) {
    let output = command.arg(scene).arg(out).output().unwrap();
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
}

/// `rasterproof compare SCENE THEIRS --as grey --fit --format json`: the report.
fn grey_fit(scene: &Path, theirs: &Path) -> Value {
    let output = assert_cmd::Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("compare")
        .arg(scene)
        .arg(theirs)
        .args(["--as", "grey", "--fit", "--format", "json"])
        .output()
        .unwrap();
    serde_json::from_slice(&output.stdout).unwrap()
}

#[test]
fn compare_fit_names_freetype() {
    if !freetype_available() {
        return;
    }
    let dir = tempdir::Dir::new("freetype-fit");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/scenes/glyph.json");
    let out = dir.path().join("glyph.png");
    draw(Command::new(python()).arg(adapter()), &scene, &out);
    let report = grey_fit(&scene, &out);
    let exact: Vec<&str> = report["methods"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|m| m["differing"] == 0)
        .map(|m| m["method"].as_str().unwrap())
        .collect();
    assert_eq!(
        exact,
        ["FreeType's smooth rasterizer (ftgrays.c's integer method)"],
        "{report}"
    );
}

/// tiny-skia's anti-aliased fill of the glyph (the tiny-skia adapter's `--grey`): `compare
/// --fit` names tiny-skia's method (4x4 samples and its levels) first, ahead of every
/// quantization of the exact values and of plain 4x4 supersampling; where it differs, it
/// is by one sample's 16 levels (tiny-skia's fixed-point edges move a sample within about
/// 1/256 px of an edge), at no more than 2 of the 1024 pixels.
#[test]
fn compare_fit_names_tiny_skia_aa() {
    let dir = tempdir::Dir::new("tiny-skia-aa");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/scenes/glyph.json");
    let out = dir.path().join("glyph.png");
    draw(
        Command::new(crate::adapters::tiny_skia_adapter()).arg("--grey"),
        &scene,
        &out,
    );
    let report = grey_fit(&scene, &out);
    let methods = report["methods"].as_array().unwrap();
    assert_eq!(
        methods[0]["method"], "tiny-skia's anti-aliasing (4x4 supersampling, its 8-bit levels)",
        "{report}"
    );
    let best = methods[0]["differing"].as_u64().unwrap();
    assert!(best <= 2, "{report}");
    assert!(
        methods[1..]
            .iter()
            .all(|m| m["differing"].as_u64().unwrap() > best + 10),
        "{report}"
    );
    // Each differing pixel is one sample off.
    let parsed = parse_scene(&std::fs::read_to_string(&scene).unwrap(), "glyph").unwrap();
    let target = parsed.target().unwrap();
    let shapes = area_shapes(&parsed.primitives(), &target, Model::Exact).unwrap();
    let ours = rasterproof::area::supersample::tiny_skia_levels(&shapes, target.width, target.height);
    let theirs = image::open(&out).unwrap().to_luma8().into_raw();
    let off: Vec<i32> = ours
        .iter()
        .zip(&theirs)
        .filter(|(a, b)| a != b)
        .map(|(a, b)| i32::from(*b) - i32::from(*a))
        .collect();
    assert_eq!(off.len() as u64, best);
    assert!(off.iter().all(|d| d.abs() == 16), "{off:?}");
}

/// Where Debian's fonts-dejavu-core puts DejaVu Sans.
const DEJAVU: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// Real glyphs: DejaVu Sans's "g@&B%" as the `glyph-scene` example flattens them (every
/// point an exact dyadic fraction), at 9, 13, 24, 64 and 200 px per em. FreeType draws
/// each exactly as the `area::ftgrays` model computes it, pixel for pixel; and the 24 px
/// scene is the one committed as `adapters/scenes/dejavu.json` (the workload of the area
/// bench), so that file is what the example makes.
#[test]
fn freetype_draws_real_glyphs_as_the_model() {
    if !freetype_available() {
        return;
    }
    if !Path::new(DEJAVU).exists() {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI is set, so this is an error: {DEJAVU} is missing (fonts-dejavu-core)"
        );
        eprintln!("skipping the real-glyph test: {DEJAVU} is missing (install fonts-dejavu-core)");
        return;
    }
    let example = crate::adapters::example("glyph-scene");
    let dir = tempdir::Dir::new("freetype-glyphs");
    let mut scenes = Vec::new();
    for px in ["9", "13", "24", "64", "200"] {
        let output = Command::new(&example)
            .args([DEJAVU, "g@&B%", "--px", px])
            .output()
            .unwrap();
        assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
        let scene: Value = serde_json::from_slice(&output.stdout).unwrap();
        if px == "24" {
            let committed =
                std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/scenes/dejavu.json"))
                    .unwrap();
            assert_eq!(
                scene,
                serde_json::from_str::<Value>(&committed).unwrap(),
                "adapters/scenes/dejavu.json is stale"
            );
        }
        scenes.push(scene);
    }
    let theirs = freetype_levels(&scenes, dir.path());
    for (s, levels) in scenes.iter().zip(&theirs) {
        let parsed = parse_scene(&s.to_string(), "glyphs").unwrap();
        let target = parsed.target().unwrap();
        let shapes = area_shapes(&parsed.primitives(), &target, Model::Exact).unwrap();
        let ours = ftgrays::rasterize(&shapes, target.width, target.height).unwrap();
        let differing = ours.iter().zip(levels).filter(|(a, b)| a != b).count();
        assert_eq!(
            differing, 0,
            "{}x{}: {differing} pixels differ",
            target.width, target.height
        );
        assert!(levels.iter().filter(|v| **v != 0).count() > 100, "the glyphs are drawn");
    }
}
