//! The wgpu adapter (adapters/wgpu/, its own crate: a real GPU API as the renderer; Mesa's
//! lavapipe, a Vulkan driver on the CPU, in CI), run on small fixed scenes.
//!
//! What is asserted, and why it should hold independently of these runs:
//! - one sample per pixel: a conformant Vulkan rasterizer with 8 subpixel bits
//!   (lavapipe's `subPixelPrecisionBits`), the top-left rule and samples at pixel centres
//!   is the `vulkan` preset, so scenes whose vertices are f32-exact and reach the GPU
//!   exactly (the adapter's mapping, adapters/wgpu/src/main.rs) must equal the oracle
//!   pixel for pixel, ties and several owners (alpha 254) included: a grid whose edges run
//!   through pixel centres, a mesh on the 1/4096 grid, a scene with vertices off the
//!   canvas (negative, so the adapter's integer offset is used); `--fit` must name
//!   top-left and no fewer than 8 bits; and a stay-alive hunt of the families the
//!   adapter draws finds nothing;
//! - four samples: the expected sample masks are derived by hand from Vulkan's standard
//!   4x positions (below), not taken from the adapter;
//! - a polygon, an unsupported sample count and (where the adapter lacks it)
//!   `--conservative` are refused with one clear line; `--info` is one JSON line.
//!
//! The adapter is looked for at adapters/wgpu/target/release/rasterproof-wgpu-adapter
//! (`cargo build --release --manifest-path adapters/wgpu/Cargo.toml`). Missing, or no
//! GPU adapter found (`apt-get install mesa-vulkan-drivers libvulkan1` gives lavapipe):
//! the tests print a skip message, unless the environment variable `CI` is set (.ci/run
//! builds it and installs lavapipe), where they fail.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::Value;

use crate::cli_json::{self, fit_exact};
use crate::tempdir;

/// A 3x3 grid of squares of side 3 on a 10x10 canvas, vertices on pixel centres (every
/// edge runs through samples).
const TIE_GRID: &str = include_str!("../adapters/scenes/tie-grid.json");

/// Six overlapping triangles, vertices on the 1/64 grid, no sample on an edge.
const NO_TIES: &str = include_str!("../adapters/scenes/no-ties.json");

/// An 8x8 mesh of 8 px cells on a 64x64 canvas, vertices on the 1/4096 grid.
const FINE_MESH: &str = include_str!("../adapters/scenes/fine-mesh.json");

/// A 13x7 canvas: two triangles sharing the edge (13, 0)-(0, 7), which passes through the
/// sample (6.5, 3.5), one with a vertex at (-3, -2) and one reaching (16, 9) (off the
/// canvas: the adapter's target is 32 px with the canvas at offset (3, 2)); over them two
/// triangles on pixel centres (edges through samples, several owners).
const THIRTEEN_BY_SEVEN: &str = r#"{"width": 13, "height": 7, "triangles": [
  {"v": [["-3", "-2"], ["13", "0"], ["0", "7"]]},
  {"v": [["13", "0"], ["16", "9"], ["0", "7"]]},
  {"v": [["1/2", "1/2"], ["25/2", "1/2"], ["13/2", "13/2"]]},
  {"v": [["13/2", "1/2"], ["25/2", "13/2"], ["1/2", "13/2"]]}
]}"#;

/// The adapter's executable, when it is built and finds a GPU adapter; otherwise `None`
/// after a skip message (a failure when `CI` is set).
fn adapter() -> Option<PathBuf> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/wgpu/target/release/rasterproof-wgpu-adapter");
    let missing = if path.is_file() {
        match Command::new(&path).arg("--info").output() {
            Ok(o) if o.status.success() => return Some(path),
            Ok(o) => format!(
                "it finds no usable GPU adapter ({}); apt-get install mesa-vulkan-drivers libvulkan1 gives lavapipe",
                String::from_utf8_lossy(&o.stderr).trim()
            ),
            Err(e) => format!("{}: {e}", path.display()),
        }
    } else {
        format!(
            "{} is not built (cargo build --release --manifest-path adapters/wgpu/Cargo.toml)",
            path.display()
        )
    };
    let message = format!("the wgpu adapter cannot run: {missing}");
    assert!(
        std::env::var_os("CI").is_none(),
        "CI is set, so this is an error: {message}"
    );
    eprintln!("skipping the wgpu adapter tests: {message}");
    None
}

fn write(dir: &tempdir::Dir, name: &str, text: &str) -> PathBuf {
    let path = dir.path().join(name);
    std::fs::write(&path, text).unwrap();
    path
}

fn text(output: &Output) -> String {
    format!(
        "status {:?}\nstdout:\n{}\nstderr:\n{}",
        output.status.code(),
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    )
}

/// Runs the adapter with `args` then `SCENE OUT`; asserts it succeeded.
fn render(adapter: &Path, args: &[&str], scene: &Path, out: &Path) {
    let output = Command::new(adapter).args(args).arg(scene).arg(out).output().unwrap();
    assert!(output.status.success(), "wgpu adapter {args:?}:\n{}", text(&output));
}

/// `rasterproof compare SCENE THEIRS --as ids --format json ARGS`: (exit code, report).
fn compare(scene: &Path, theirs: &Path, args: &[&str]) -> (i32, Value) {
    compare_as("ids", scene, theirs, args)
}

/// `rasterproof compare SCENE THEIRS --as AS --format json ARGS`: (exit code, report);
/// asserts it exited 0 or 1.
fn compare_as(format: &str, scene: &Path, theirs: &Path, args: &[&str]) -> (i32, Value) {
    let with_format: Vec<&str> = ["--as", format].into_iter().chain(args.iter().copied()).collect();
    cli_json::compare(scene, theirs, &with_format)
}

/// One sample per pixel: every scene identical to the oracle under `--preset vulkan`.
#[test]
fn single_sample_equals_the_vulkan_preset() {
    let Some(adapter) = adapter() else { return };
    let dir = tempdir::Dir::new("wgpu-single");
    for (name, scene) in [
        ("tie-grid", TIE_GRID),
        ("no-ties", NO_TIES),
        ("fine-mesh", FINE_MESH),
        ("thirteen", THIRTEEN_BY_SEVEN),
    ] {
        let scene = write(&dir, &format!("{name}.json"), scene);
        let out = dir.path().join(format!("{name}.png"));
        render(&adapter, &[], &scene, &out);
        let (code, report) = compare(&scene, &out, &["--preset", "vulkan"]);
        assert_eq!(code, 0, "{name}: not identical under the vulkan preset: {report}");
    }
}

/// `--fit`: the ties of the grid and of the 13x7 scene are top-left's alone; the fine
/// mesh fits 8 bits (nearest-even) and nothing coarser; samples at pixel centres.
#[test]
fn fit_names_top_left_and_8_bits() {
    let Some(adapter) = adapter() else { return };
    let dir = tempdir::Dir::new("wgpu-fit");
    for (name, scene) in [("tie-grid", TIE_GRID), ("thirteen", THIRTEEN_BY_SEVEN)] {
        let scene = write(&dir, &format!("{name}.json"), scene);
        let out = dir.path().join(format!("{name}.png"));
        render(&adapter, &[], &scene, &out);
        let (code, report) = compare(&scene, &out, &["--fit"]);
        assert_eq!(code, 0, "{name}: no convention fits: {report}");
        let exact = report["exact"].as_array().expect("exact fits");
        assert!(!exact.is_empty(), "{report}");
        for fit in exact {
            assert_eq!(fit["tie_rule"], "top-left", "{name}: {report}");
        }
    }
    let scene = write(&dir, "fine-mesh.json", FINE_MESH);
    let out = dir.path().join("fine-mesh.png");
    render(&adapter, &[], &scene, &out);
    let (code, report) = compare(&scene, &out, &["--fit"]);
    assert_eq!(code, 0, "fine mesh: no convention fits: {report}");
    let exact = report["exact"].as_array().expect("exact fits");
    let bits: Vec<u64> = exact.iter().filter_map(|f| f["subpixel_bits"].as_u64()).collect();
    assert_eq!(bits.iter().min(), Some(&8), "{report}");
    assert!(
        exact
            .iter()
            .any(|f| f["subpixel_bits"] == 8 && f["rounding"] == "nearest-even"),
        "{report}"
    );
    for fit in exact {
        assert_eq!(fit["pixel_centre"], "0.5", "{report}");
    }
}

/// `rasterproof hunt` against the adapter (started with `adapter_args`, then `--serve`),
/// 200 scenes of the families whose vertices its target holds, under the vulkan preset,
/// with `hunt_args`: asserts all 200 are identical (`hunt` exits 0).
fn hunt_finds_nothing(adapter: &Path, adapter_args: &str, hunt_args: &[&str]) {
    let dir = tempdir::Dir::new("wgpu-hunt");
    let output = assert_cmd::Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("hunt")
        .arg("--serve")
        .arg(format!("{} {adapter_args}--serve", adapter.display()))
        .args(hunt_args)
        .args(["--preset", "vulkan", "--float32-exact", "--cases", "200", "--jobs", "2"])
        .args(["--family", "mesh,delaunay,slivers,fine", "--quiet", "--out"])
        .arg(dir.path())
        .output()
        .unwrap();
    assert!(output.status.success(), "hunt found something:\n{}", text(&output));
    assert!(
        String::from_utf8_lossy(&output.stdout).contains("200 identical"),
        "{}",
        text(&output)
    );
}

/// The stay-alive protocol under a hunt: 200 scenes, all identical.
#[test]
fn stay_alive_hunt_finds_nothing() {
    let Some(adapter) = adapter() else { return };
    hunt_finds_nothing(&adapter, "", &[]);
}

/// The same at four samples per pixel: `hunt --samples 4` writes the standard 4x pattern
/// into every scene, the adapter draws a 4-sample target and reads every sample back, and
/// each sample index is judged on its own; 200 scenes, all identical.
#[test]
fn four_sample_hunt_finds_nothing() {
    let Some(adapter) = adapter() else { return };
    hunt_finds_nothing(&adapter, "--samples 4 ", &["--samples", "4"]);
}

/// A 4x case: name, scene, canvas width and height, the expected id + 1 of each pixel
/// (row order) at samples 0..4.
type Case = (&'static str, &'static str, u32, u32, [&'static [u32]; 4]);

/// Vulkan's standard 4x sample positions (the spec's table "Standard sample locations";
/// D3D's too), within a pixel, y down: sample 0 (0.375, 0.125), 1 (0.875, 0.375),
/// 2 (0.125, 0.625), 3 (0.625, 0.875).
///
/// Each scene's expected ids per sample (id + 1, 0 uncovered), pixels in row order,
/// derived from those positions:
/// - A (2x2): one triangle whose right edge is the vertical x = 3/2 (the other two edges
///   far to the left): pixel column 0 is covered at every sample; in column 1, the
///   samples at x = 1.375 (0) and 1.125 (2) lie left of the edge, those at 1.875 (1) and
///   1.625 (3) right of it.
/// - B (1x1): a triangle below the horizontal edge y = 1/2: samples 2 (y 0.625) and 3
///   (0.875) only.
/// - C (1x1): a triangle on the side x − y > 3/8 of the edge through (-9.625, -10) and
///   (10.375, 10): x − y at the samples is 0.25, 0.5, −0.5, −0.25, so sample 1 only.
/// - D (1x1): two triangles sharing the vertical edge x = 3/8, which passes exactly
///   through sample 0 (0.375, 0.125): id 0 left of it, id 1 right. Sample 2 (x 0.125) is
///   id 0's; samples 1 and 3 id 1's; sample 0 lies on the edge, which is id 1's left edge
///   (owned under the top-left rule) and id 0's right edge (not owned): id 1's alone, no
///   second owner (alpha 255).
#[test]
fn four_samples_hold_the_hand_derived_masks() {
    let Some(adapter) = adapter() else { return };
    let info = info(&adapter);
    let counts: Vec<u64> = info["sample_counts"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(Value::as_u64)
        .collect();
    if !counts.contains(&4) {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI (lavapipe) offers 4 samples: {info}"
        );
        eprintln!("skipping the 4x test: this adapter offers {counts:?} samples");
        return;
    }
    let cases: [Case; 4] = [
        (
            "A",
            r#"{"width": 2, "height": 2, "triangles": [{"v": [["3/2", "-10"], ["3/2", "10"], ["-20", "0"]]}]}"#,
            2,
            2,
            [&[1, 1, 1, 1], &[1, 0, 1, 0], &[1, 1, 1, 1], &[1, 0, 1, 0]],
        ),
        (
            "B",
            r#"{"width": 1, "height": 1, "triangles": [{"v": [["-10", "1/2"], ["10", "1/2"], ["0", "20"]]}]}"#,
            1,
            1,
            [&[0], &[0], &[1], &[1]],
        ),
        (
            "C",
            r#"{"width": 1, "height": 1, "triangles": [{"v": [["-9.625", "-10"], ["10.375", "10"], ["10.375", "-10"]]}]}"#,
            1,
            1,
            [&[0], &[1], &[0], &[0]],
        ),
        (
            "D",
            r#"{"width": 1, "height": 1, "triangles": [
                {"v": [["0.375", "-10"], ["0.375", "10"], ["-20", "0"]]},
                {"v": [["0.375", "-10"], ["20", "0"], ["0.375", "10"]]}]}"#,
            1,
            1,
            [&[2], &[2], &[1], &[2]],
        ),
    ];
    let dir = tempdir::Dir::new("wgpu-4x");
    for (name, scene, w, h, expected) in cases {
        let scene = write(&dir, &format!("{name}.json"), scene);
        let out = dir.path().join(format!("{name}.png"));
        render(&adapter, &["--samples", "4"], &scene, &out);
        let image = image::open(&out).unwrap().to_rgba8();
        assert_eq!(image.dimensions(), (w, 4 * h), "{name}: the stacked PNG is W x 4H");
        for (s, ids) in expected.iter().enumerate() {
            let s = u32::try_from(s).unwrap();
            let got: Vec<u32> = (0..h)
                .flat_map(|y| (0..w).map(move |x| (x, y)))
                .map(|(x, y)| {
                    let [r, g, b, a] = image.get_pixel(x, s * h + y).0;
                    assert!(a == 0 || a == 255, "{name}: sample {s} ({x}, {y}): alpha {a}");
                    u32::from(r) | u32::from(g) << 8 | u32::from(b) << 16
                })
                .collect();
            assert_eq!(&got, ids, "{name}: sample {s}");
        }
    }
}

/// `--info`: one JSON line with the adapter and what it offers.
fn info(adapter: &Path) -> Value {
    let output = Command::new(adapter).arg("--info").output().unwrap();
    assert!(output.status.success(), "--info:\n{}", text(&output));
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert_eq!(stdout.lines().count(), 1, "{stdout}");
    serde_json::from_str(&stdout).expect("--info prints JSON")
}

#[test]
fn info_is_json_with_the_fields() {
    let Some(adapter) = adapter() else { return };
    let info = info(&adapter);
    for field in ["adapter", "backend", "driver", "driver_info"] {
        assert!(info[field].is_string(), "{field}: {info}");
    }
    let counts = info["sample_counts"].as_array().expect("sample_counts");
    assert!(counts.contains(&Value::from(1)), "{info}");
    assert!(info["r32uint_sample_counts"].is_array(), "{info}");
    assert!(info["conservative_rasterization"].is_boolean(), "{info}");
}

/// Runs the adapter expecting a refusal: exit 2, one line on stderr; returns it.
fn refusal(adapter: &Path, args: &[&str], scene: &Path, out: &Path) -> String {
    let output = Command::new(adapter).args(args).arg(scene).arg(out).output().unwrap();
    assert_eq!(output.status.code(), Some(2), "{args:?}:\n{}", text(&output));
    let stderr = String::from_utf8_lossy(&output.stderr).to_string();
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    stderr
}

#[test]
fn refusals_are_one_clear_line() {
    let Some(adapter) = adapter() else { return };
    let dir = tempdir::Dir::new("wgpu-refusals");
    let out = dir.path().join("out.png");
    let polygon = write(
        &dir,
        "polygon.json",
        r#"{"width": 4, "height": 4, "polygons": [{"v": [[0, 0], [4, 0], [0, 4]]}]}"#,
    );
    let message = refusal(&adapter, &[], &polygon, &out);
    assert!(
        message.contains("triangles only") && message.contains("polygons"),
        "{message}"
    );
    let triangle = write(
        &dir,
        "triangle.json",
        r#"{"width": 4, "height": 4, "triangles": [{"v": [[0, 0], [4, 0], [0, 4]]}]}"#,
    );
    // No API offers 3 samples; the message names the counts this adapter does offer.
    let message = refusal(&adapter, &["--samples", "3"], &triangle, &out);
    assert!(message.contains("not 3") && message.contains("[1"), "{message}");
    // A vertex far beyond the largest target: refused, unless --clip lets the GPU clip.
    let far = write(
        &dir,
        "far.json",
        r#"{"width": 4, "height": 4, "triangles": [{"v": [[0, 0], [4, 0], [0, 1000000]]}]}"#,
    );
    let message = refusal(&adapter, &[], &far, &out);
    assert!(message.contains("beyond") && message.contains("--clip"), "{message}");
    render(&adapter, &["--clip"], &far, &out);
    if info(&adapter)["conservative_rasterization"] == false {
        let message = refusal(&adapter, &["--conservative"], &triangle, &out);
        assert!(
            message.contains("does not offer conservative rasterization"),
            "{message}"
        );
    }
    // Under --serve, a refusal is an `ok: false` answer and the next scene is drawn.
    let request = |id: u32, scene: &str| {
        serde_json::json!({"rasterproof": 1, "id": id, "scene": serde_json::from_str::<Value>(scene).unwrap(), "out": out})
            .to_string()
    };
    let input = format!(
        "{}\n{}\n",
        request(
            1,
            r#"{"width": 4, "height": 4, "polygons": [{"v": [[0, 0], [4, 0], [0, 4]]}]}"#
        ),
        request(
            2,
            r#"{"width": 4, "height": 4, "triangles": [{"v": [[0, 0], [4, 0], [0, 4]]}]}"#
        )
    );
    let output = assert_cmd::Command::new(&adapter)
        .arg("--serve")
        .write_stdin(input)
        .output()
        .unwrap();
    assert!(output.status.success(), "{}", text(&output));
    let answers: Vec<Value> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(answers.len(), 2, "{}", text(&output));
    assert_eq!(answers[0]["ok"], false);
    assert!(answers[0]["error"].as_str().unwrap().contains("triangles only"));
    assert_eq!(answers[1], serde_json::json!({"id": 2, "ok": true}));
}

/// The committed 4x findings (adapters/fixtures/wgpu-lavapipe/, found with `--clip`: the
/// GPU clips a far vertex in floats): `compare` finds the signature in the committed
/// stacked PNG (no GPU needed), and the adapter, where it runs, still draws that PNG.
#[test]
fn the_clipping_fixtures_show_their_findings() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/fixtures/wgpu-lavapipe");
    let fixtures = [
        ("01-near-edge-clipped-far-vertex-4x", "near-edge, triangles", 0),
        ("02-snapping-clipped-vertex-left-of-target-4x", "snapping, triangles", 1),
    ];
    let adapter = adapter();
    for (name, signature, sample) in fixtures {
        let scene = root.join(format!("{name}.json"));
        let png = root.join(format!("{name}.png"));
        let (code, report) = compare(&scene, &png, &[]);
        assert_eq!(code, 1, "{name}");
        assert_eq!(report["differing_samples"], 1, "{name}");
        let pixels = &report["samples"][sample]["report"]["pixels"];
        let classes: Vec<String> = pixels[0]["findings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f["class"].as_str().unwrap().to_string())
            .collect();
        assert!(signature.starts_with(classes[0].as_str()), "{name}: {classes:?}");
        if let Some(adapter) = &adapter {
            let dir = tempdir::Dir::new("wgpu-fixture");
            let out = dir.path().join("out.png");
            render(adapter, &["--samples", "4", "--clip"], &scene, &out);
            assert_eq!(
                image::open(&out).unwrap().to_rgba8(),
                image::open(&png).unwrap().to_rgba8(),
                "{name}"
            );
        }
    }
}

// ---------------------------------------------------------------------------------------
// Interpolated values (`--values`, issue 47 point 5): lavapipe's interpolator through wgpu.
//
// What is asserted, and why it should hold independently of these runs:
// - on random triangles (both windings, w powers of two from 1/4 to 8, values in thirds,
//   sevenths, tenths and 256ths, vertices on the 1/256 grid) at canvas offsets 0 and
//   16320 (2^14 − 64), `compare --fit` names the float model LAVAPIPE with 0 differing
//   values: llvmpipe's setup and interpolation code (`lp_state_setup.c`,
//   `lp_bld_interp.c`), which lavapipe shares, with Vulkan's provoking vertex (the first)
//   for every triangle. A scene whose `provoking_vertex` is `last` leaves that model
//   alone: the adapter draws smooth varyings in the scene's order and Vulkan keeps vertex
//   0 as the plane's anchor, where llvmpipe under GL's last convention reorders clockwise
//   triangles to (v1, v0, v2) (`ccw`);
// - the plain comparison calls none of lavapipe's values off;
// - a deliberate fault (`--fault affine`, `--fault provoking`) is named by its class at
//   every pixel, by compare and by a stay-alive `hunt --as values`, which shrinks it to
//   one triangle;
// - at 4 samples, the stacked TIFF holds each sample's values where the oracle covers it
//   (0 elsewhere), within 2^-8 relative of the exact value (f32 error with w ratios up to
//   32 reaches about 2^-11) for the sampling points whose arithmetic lavapipe gets right
//   (centre; a noperspective varying at its sample or centroid), and a centroid drawn at
//   the centre (`--fault centroid`) is off at some partly covered pixels;
// - refusals (too many channels, w <= 0, no varyings, a varying it does not declare, a
//   vertex the GPU would clip) exit 2 with the field named.
// ---------------------------------------------------------------------------------------

/// lavapipe's interpolation arithmetic, as `compare --fit` names it.
const LAVAPIPE: &str = "origin-plane fma as-given rcp f32 y-down";

/// A random values scene: `triangles` triangles near canvas column `offset` of a
/// (offset + 64) x 32 canvas (vertices on the 1/256 grid, both windings), a 3-channel
/// varying `c` of `interpolation` at `sampling`, `w` a power of two from 1/4 to 8 (never
/// the same at all three vertices, so that smooth and noperspective differ), values in
/// thirds, sevenths, tenths and 256ths.
fn values_scene(seed: u64, offset: i64, interpolation: &str, provoking: &str, sampling: &str) -> String {
    let mut rng = crate::rng::Rng(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1);
    let (width, height) = (offset + 64, 32);
    let mut triangles = Vec::new();
    for _ in 0..12 {
        let (cx, cy) = (rng.range(offset * 256, width * 256), rng.range(0, height * 256));
        let v: Vec<Value> = (0..3)
            .map(|_| {
                let x = (cx + rng.range(-20 * 256, 20 * 256)).clamp(0, width * 256);
                let y = (cy + rng.range(-20 * 256, 20 * 256)).clamp(0, height * 256);
                serde_json::json!([format!("{x}/256"), format!("{y}/256")])
            })
            .collect();
        let w = loop {
            let w: Vec<i64> = (0..3).map(|_| rng.range(-2, 3)).collect();
            if w[0] != w[1] || w[1] != w[2] {
                break w;
            }
        };
        let w: Vec<String> = w
            .iter()
            .map(|&k| {
                if k < 0 {
                    format!("1/{}", 1 << -k)
                } else {
                    (1 << k).to_string()
                }
            })
            .collect();
        let values: Vec<Vec<String>> = (0..3)
            .map(|_| {
                (0..3)
                    .map(|_| {
                        let d = [3, 7, 10, 256][usize::try_from(rng.below(4)).unwrap()];
                        format!("{}/{d}", rng.range(-1000, 1000))
                    })
                    .collect()
            })
            .collect();
        triangles.push(serde_json::json!({"v": v, "w": w, "varyings": {"c": values}}));
    }
    serde_json::json!({
        "width": width, "height": height, "preset": "vulkan", "provoking_vertex": provoking,
        "varyings": [{"name": "c", "channels": 3, "interpolation": interpolation, "sampling": sampling}],
        "triangles": triangles,
    })
    .to_string()
}

/// The adapter's values TIFF of `scene` with `args` (after `--values`).
fn draw_values(adapter: &Path, args: &[&str], scene: &Path) -> PathBuf {
    let out = scene.with_extension(format!("{}.tiff", args.join("").replace('-', "")));
    let output = Command::new(adapter)
        .arg("--values")
        .args(args)
        .arg(scene)
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "wgpu adapter --values {args:?}:\n{}",
        text(&output)
    );
    out
}

/// `rasterproof compare SCENE THEIRS --as values --format json ARGS`: (exit code, report).
fn compare_values(scene: &Path, theirs: &Path, args: &[&str]) -> (i32, Value) {
    compare_as("values", scene, theirs, args)
}

/// The classes a plain values comparison counted.
fn classes(report: &Value) -> Vec<String> {
    report["counts"].as_object().unwrap().keys().cloned().collect()
}

#[test]
fn lavapipe_values_are_one_float_model_bit_for_bit() {
    let Some(adapter) = adapter() else { return };
    let dir = tempdir::Dir::new("wgpu-values-fit");
    for (seed, offset, interpolation, provoking) in [
        (1, 0, "smooth", "first"),
        (2, 0, "smooth", "last"),
        (3, 16320, "smooth", "first"),
        (4, 16320, "smooth", "last"),
        (5, 0, "noperspective", "first"),
        (6, 16320, "noperspective", "last"),
        (7, 16320, "flat", "last"),
    ] {
        let name = format!("{seed}-{offset}-{interpolation}-{provoking}");
        let scene = write(
            &dir,
            &format!("{name}.json"),
            &values_scene(seed, offset, interpolation, provoking, "centre"),
        );
        let theirs = draw_values(&adapter, &[], &scene);
        let (code, fit) = compare_values(&scene, &theirs, &["--fit"]);
        assert_eq!(code, 0, "{name}: {fit}");
        let exact = fit_exact(&fit);
        assert!(exact.contains(&LAVAPIPE), "{name}: {exact:?}");
        assert!(fit["judged"].as_u64().unwrap() > 500, "{name}: {fit}");
        // Smooth, provoking last: the one model whose anchor is vertex 0 whatever the
        // winding.
        if interpolation == "smooth" && provoking == "last" {
            assert_eq!(exact, [LAVAPIPE], "{name}");
        }
        let (code, report) = compare_values(&scene, &theirs, &[]);
        // Far from the origin, the origin-anchored plane's error shows as its class.
        if offset > 0 && interpolation != "flat" {
            assert!(report["counts"]["far-anchor"].as_u64().unwrap() > 0, "{name}: {report}");
        }
        assert_eq!((code, &report["off"]), (0, &Value::from(0)), "{name}: {report}");
        assert!(!classes(&report).contains(&"gross".to_string()), "{name}: {report}");
    }
}

/// adapters/scenes/values-far-steep-w.json: one triangle near x = 16000 whose w run from
/// 1/4 to 8. lavapipe's values are its float model's bit for bit, yet plain `compare`
/// called pixel (15992, 22) `gross` (68435 f32 steps in channel 0) before the `unbounded`
/// class: the origin-anchored plane of 1/w there is `a0 + dadx x` with `a0` = 21840.84 and
/// `dadx x` = −21836.7, whose cancellation leaves 1/w = 0.1746 with a 0.47 % error, and
/// f32's bound on that plane exceeds 1/w itself: nothing can be said of the value, which
/// is `unbounded`, not off.
#[test]
fn far_values_are_never_gross() {
    let Some(adapter) = adapter() else { return };
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/scenes/values-far-steep-w.json");
    let dir = tempdir::Dir::new("wgpu-values-far");
    let copy = dir.path().join("far.json");
    std::fs::copy(&scene, &copy).unwrap();
    let theirs = draw_values(&adapter, &[], &copy);
    let (code, fit) = compare_values(&copy, &theirs, &["--fit"]);
    assert_eq!(code, 0, "{fit}");
    let (code, report) = compare_values(&copy, &theirs, &[]);
    assert_eq!((code, &report["off"]), (0, &Value::from(0)), "{report}");
    assert!(classes(&report).contains(&"unbounded".to_string()), "{report}");
}

#[test]
fn lavapipe_with_a_deliberate_fault_is_named() {
    let Some(adapter) = adapter() else { return };
    let dir = tempdir::Dir::new("wgpu-values-faults");
    // No perspective correction: every pixel `affine`.
    let smooth = write(&dir, "smooth.json", &values_scene(11, 0, "smooth", "first", "centre"));
    let (code, report) = compare_values(&smooth, &draw_values(&adapter, &["--fault", "affine"], &smooth), &[]);
    assert_eq!((code, classes(&report)), (1, vec!["affine".to_string()]), "{report}");
    // The other provoking vertex, either way round.
    for provoking in ["first", "last"] {
        let flat = write(
            &dir,
            &format!("flat-{provoking}.json"),
            &values_scene(12, 0, "flat", provoking, "centre"),
        );
        let (code, report) = compare_values(&flat, &draw_values(&adapter, &["--fault", "provoking"], &flat), &[]);
        assert_eq!(
            (code, classes(&report)),
            (1, vec!["provoking-vertex".to_string()]),
            "{provoking}: {report}"
        );
    }
}

/// `hunt --as values` against the adapter kept alive (`--values ADAPTER_ARGS --serve`)
/// with `hunt_args`, on the families whose vertices lie on the canvas: (exit code, the
/// findings' signatures and minimal triangle counts, the report).
fn values_hunt(adapter: &Path, adapter_args: &str, hunt_args: &[&str]) -> (i32, Vec<(String, usize)>, Value) {
    let dir = tempdir::Dir::new("wgpu-values-hunt");
    let report = dir.path().join("report.json");
    let output = assert_cmd::Command::cargo_bin("rasterproof")
        .unwrap()
        .args(["hunt", "--as", "values", "--serve"])
        .arg(format!("{} --values {adapter_args}--serve", adapter.display()))
        .args([
            "--preset",
            "vulkan",
            "--float32-exact",
            "--family",
            "mesh,delaunay,fine",
        ])
        .args(["--jobs", "2", "--shrink-runs", "40", "--report"])
        .arg(&report)
        .args(hunt_args)
        .output()
        .unwrap();
    let code = output.status.code().unwrap();
    assert!(code <= 1, "{}", text(&output));
    let report: Value = serde_json::from_str(&std::fs::read_to_string(&report).unwrap()).unwrap();
    let found = report["findings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            let triangles = f["minimal"]["triangles"].as_array().map_or(0, Vec::len);
            (f["signature"].as_str().unwrap().to_string(), triangles)
        })
        .collect();
    (code, found, report)
}

#[test]
fn the_values_hunt_names_a_deliberate_fault_and_nothing_else() {
    let Some(adapter) = adapter() else { return };
    let (code, found, report) = values_hunt(&adapter, "", &["--cases", "12"]);
    assert_eq!(
        (code, found, report["same"].as_u64()),
        (0, vec![], Some(12)),
        "{report}"
    );
    let (code, found, report) = values_hunt(
        &adapter,
        "",
        &["--cases", "6", "--interpolation", "flat", "--provoking", "last"],
    );
    assert_eq!((code, found, report["same"].as_u64()), (0, vec![], Some(6)), "{report}");
    let (code, found, report) = values_hunt(&adapter, "--fault affine ", &["--cases", "3"]);
    assert_eq!(code, 1, "{report}");
    assert!(found.contains(&("affine".to_string(), 1)), "{found:?}");
    let (code, found, report) = values_hunt(
        &adapter,
        "--fault provoking ",
        &["--cases", "3", "--interpolation", "flat"],
    );
    assert_eq!(code, 1, "{report}");
    assert_eq!(found, [("provoking-vertex".to_string(), 1)], "{report}");
}

/// A float TIFF's width, height and samples (channels per pixel interleaved).
fn read_float_tiff(path: &Path) -> (u32, u32, Vec<f32>) {
    let mut decoder = tiff::decoder::Decoder::new(std::io::Cursor::new(std::fs::read(path).unwrap())).unwrap();
    let (w, h) = decoder.dimensions().unwrap();
    match decoder.read_image().unwrap() {
        tiff::decoder::DecodingResult::F32(v) => (w, h, v),
        _ => panic!("{}: not float32", path.display()),
    }
}

/// The covered samples of `scene` at 4x whose value in the adapter's stacked TIFF (drawn
/// with `args` after `--samples 4`) is more than 2^-8 relative (at least 2^-8 absolute)
/// from the exact value of
/// `render --samples 4 --format json`, of all covered; asserts the TIFF's size and that
/// every uncovered sample is 0.
fn four_sample_values_off(adapter: &Path, scene: &Path, args: &[&str]) -> (usize, usize) {
    let mut all = vec!["--samples", "4"];
    all.extend_from_slice(args);
    let (w, h, pixels) = read_float_tiff(&draw_values(adapter, &all, scene));
    assert_eq!((w, h), (64, 4 * 32));
    let output = assert_cmd::Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("render")
        .arg(scene)
        .args(["--samples", "4", "--format", "json"])
        .output()
        .unwrap();
    assert!(output.status.success(), "{}", text(&output));
    let exact: Value = serde_json::from_slice(&output.stdout).unwrap();
    let mut covered = vec![false; (w * h) as usize];
    let mut off = 0;
    for s in exact["values"]["samples"].as_array().unwrap() {
        let [x, y, sample] = [0, 1, 2].map(|k| usize::try_from(s[k].as_u64().unwrap()).unwrap());
        let at = sample * 32 * 64 + y * 64 + x;
        covered[at] = true;
        let wrong = s[4][0].as_array().unwrap().iter().enumerate().any(|(c, q)| {
            let q = q.as_str().unwrap();
            let (n, d) = q.split_once('/').unwrap_or((q, "1"));
            let e = n.parse::<f64>().unwrap() / d.parse::<f64>().unwrap();
            (f64::from(pixels[3 * at + c]) - e).abs() > e.abs().max(1.0) * 2f64.powi(-8)
        });
        off += usize::from(wrong);
    }
    for (at, covered) in covered.iter().enumerate() {
        if !covered {
            assert_eq!(
                pixels[3 * at..3 * at + 3],
                [0.0; 3],
                "{}: row {}",
                scene.display(),
                at / 64
            );
        }
    }
    (off, covered.iter().filter(|&&c| c).count())
}

#[test]
fn four_sample_values_are_stacked_per_sample() {
    let Some(adapter) = adapter() else { return };
    let dir = tempdir::Dir::new("wgpu-values-4x");
    let scene = |interpolation: &str, sampling: &str| {
        write(
            &dir,
            &format!("{interpolation}-{sampling}.json"),
            &values_scene(21, 0, interpolation, "first", sampling),
        )
    };
    for (interpolation, sampling) in [
        ("smooth", "centre"),
        ("noperspective", "centre"),
        ("noperspective", "sample"),
        ("noperspective", "centroid"),
    ] {
        let (off, covered) = four_sample_values_off(&adapter, &scene(interpolation, sampling), &[]);
        assert_eq!(off, 0, "{interpolation} at {sampling}: {off} of {covered} samples off");
        assert!(covered > 500, "{interpolation} at {sampling}");
    }
    // A centroid drawn at the centre: off where a pixel is partly covered, only there.
    let centroid = scene("noperspective", "centroid");
    let (off, covered) = four_sample_values_off(&adapter, &centroid, &["--fault", "centroid"]);
    assert!(off > 0 && off < covered / 2, "{off} of {covered}");
}

/// `compare --as values --samples 4` on lavapipe's stacked 4x values: right at every
/// covered sample for a noperspective varying at its centroid or sample and a smooth one at
/// the centre; a centroid drawn at the centre (`--fault centroid`) named `at-centre` where
/// the centre lies outside the primitive (`centroid-range` where it lies inside, which
/// Vulkan allows); and lavapipe's own smooth varying at its sample named `w-at-centre`:
/// Mesa 22.3 takes f/w at the sample and 1/w at the pixel's centre (adapters/README.md).
#[test]
fn four_sample_values_are_judged_per_sample() {
    let Some(adapter) = adapter() else { return };
    let dir = tempdir::Dir::new("wgpu-values-4x-compare");
    let scene = |interpolation: &str, sampling: &str| {
        write(
            &dir,
            &format!("{interpolation}-{sampling}.json"),
            &values_scene(23, 0, interpolation, "first", sampling),
        )
    };
    let judged = |scene: &Path, args: &[&str]| {
        let mut all = vec!["--samples", "4"];
        all.extend_from_slice(args);
        compare_values(scene, &draw_values(&adapter, &all, scene), &["--samples", "4"])
    };
    for (interpolation, sampling) in [
        ("noperspective", "centroid"),
        ("noperspective", "sample"),
        ("smooth", "centre"),
    ] {
        let (code, report) = judged(&scene(interpolation, sampling), &[]);
        let counts = &report["counts"];
        assert_eq!(
            (code, &report["off"]),
            (0, &Value::from(0)),
            "{interpolation} at {sampling}: {counts}"
        );
        assert_eq!(report["samples"], 4);
        assert!(report["judged"].as_u64().unwrap() > 500, "{counts}");
    }
    let (code, report) = judged(&scene("noperspective", "centroid"), &["--fault", "centroid"]);
    let (found, counts) = (classes(&report), &report["counts"]);
    assert_eq!(code, 1, "{counts}");
    assert!(found.contains(&"at-centre".to_string()), "{counts}");
    for class in &found {
        assert!(
            ["exact", "f32", "centroid-range", "at-centre"].contains(&class.as_str()),
            "{class}: {counts}"
        );
    }
    // Off only as w-at-centre (a few samples outside their triangle, where the 1/w plane
    // nears zero, are `unbounded`).
    let (code, report) = judged(&scene("smooth", "sample"), &[]);
    let counts = &report["counts"];
    assert_eq!(code, 1, "{counts}");
    let off: Vec<String> = classes(&report)
        .into_iter()
        .filter(|c| !["exact", "f32", "far-anchor", "unbounded"].contains(&c.as_str()))
        .collect();
    assert_eq!(off, ["w-at-centre"], "{counts}");
}

/// A values hunt at 4x (`--samples 4 --sampling centroid`) finds the deliberate centroid
/// fault, names it `at-centre` and shrinks it to one triangle; the adapter as it is gives
/// nothing for a noperspective centroid.
#[test]
fn a_four_sample_values_hunt_names_the_centroid_fault() {
    let Some(adapter) = adapter() else { return };
    let args = [
        "--samples",
        "4",
        "--sampling",
        "centroid",
        "--interpolation",
        "noperspective",
    ];
    let (code, found, report) = values_hunt(&adapter, "--samples 4 ", &[&["--cases", "4"][..], &args[..]].concat());
    assert_eq!((code, found, report["same"].as_u64()), (0, vec![], Some(4)), "{report}");
    let (code, found, report) = values_hunt(
        &adapter,
        "--samples 4 --fault centroid ",
        &[&["--cases", "4"][..], &args[..]].concat(),
    );
    assert_eq!(code, 1, "{report}");
    assert_eq!(found, [("at-centre".to_string(), 1)], "{report}");
}

/// The committed values finding (adapters/fixtures/wgpu-lavapipe-values/): `compare`
/// names `w-at-centre` in the committed TIFF (no renderer needed) at the three samples of
/// the partly covered pixel (1, 0), and the adapter, where it runs, still draws that TIFF
/// bit for bit.
#[test]
fn the_values_fixture_shows_lavapipes_divide_at_the_centre() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/fixtures/wgpu-lavapipe-values");
    let scene = root.join("01-w-at-centre-smooth-centroid-4x.json");
    let tiff = root.join("01-w-at-centre-smooth-centroid-4x.tiff");
    let (code, report) = compare_values(&scene, &tiff, &[]);
    assert_eq!(code, 1, "{report}");
    let off: Vec<(u64, u64, u64, &str)> = report["pixels"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|p| p["class"] != "f32")
        .map(|p| {
            let n = |k: &str| p[k].as_u64().unwrap();
            (n("x"), n("y"), n("sample"), p["class"].as_str().unwrap())
        })
        .collect();
    assert_eq!(
        off,
        [
            (1, 0, 0, "w-at-centre"),
            (1, 0, 1, "w-at-centre"),
            (1, 0, 2, "w-at-centre")
        ],
        "{report}"
    );
    let Some(adapter) = adapter() else { return };
    let dir = tempdir::Dir::new("wgpu-values-fixture");
    let copy = dir.path().join("fixture.json");
    std::fs::copy(&scene, &copy).unwrap();
    let drawn = draw_values(&adapter, &["--samples", "4"], &copy);
    assert_eq!(read_float_tiff(&drawn), read_float_tiff(&tiff));
}

#[test]
fn values_refusals_name_the_field() {
    let Some(adapter) = adapter() else { return };
    let dir = tempdir::Dir::new("wgpu-values-refusals");
    let out = dir.path().join("out.tiff");
    let scene = |name: &str, varyings: &str, triangle: &str| {
        write(
            &dir,
            name,
            &format!(r#"{{"width": 8, "height": 8, "varyings": [{varyings}], "triangles": [{triangle}]}}"#),
        )
    };
    let five = scene(
        "five.json",
        r#"{"name": "c", "channels": 5}"#,
        r#"{"v": [[0, 0], [8, 0], [0, 8]], "varyings": {"c": [[1, 2, 3, 4, 5], [1, 2, 3, 4, 5], [1, 2, 3, 4, 5]]}}"#,
    );
    let message = refusal(&adapter, &["--values"], &five, &out);
    assert!(message.contains("varyings[0].channels: 5"), "{message}");
    let w0 = scene(
        "w0.json",
        r#"{"name": "c", "channels": 1}"#,
        r#"{"v": [[0, 0], [8, 0], [0, 8]], "w": [1, 0, 1], "varyings": {"c": [[1], [2], [3]]}}"#,
    );
    let message = refusal(&adapter, &["--values"], &w0, &out);
    assert!(message.contains("triangles[0].w[1]"), "{message}");
    let none = write(
        &dir,
        "none.json",
        r#"{"width": 8, "height": 8, "triangles": [{"v": [[0, 0], [8, 0], [0, 8]]}]}"#,
    );
    let message = refusal(&adapter, &["--values"], &none, &out);
    assert!(message.contains("varyings: the scene declares none"), "{message}");
    let one = scene(
        "one.json",
        r#"{"name": "c", "channels": 1}"#,
        r#"{"v": [[0, 0], [8, 0], [0, 8]], "varyings": {"c": [[1], [2], [3]]}}"#,
    );
    let message = refusal(&adapter, &["--values", "--varying", "uv"], &one, &out);
    assert!(message.contains("no varying named \"uv\""), "{message}");
    let outside = scene(
        "outside.json",
        r#"{"name": "c", "channels": 1}"#,
        r#"{"v": [[-1, 0], [8, 0], [0, 8]], "varyings": {"c": [[1], [2], [3]]}}"#,
    );
    let message = refusal(&adapter, &["--values"], &outside, &out);
    assert!(message.contains("--clip"), "{message}");
    let message = refusal(&adapter, &["--fault", "affine"], &one, &out);
    assert!(message.contains("--values"), "{message}");
    let message = refusal(&adapter, &["--values", "--fault", "nothing"], &one, &out);
    assert!(message.contains("--fault"), "{message}");
}
