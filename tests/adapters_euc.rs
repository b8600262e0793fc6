//! euc 0.5.3, a pure-Rust software renderer, through its values adapter
//! (`adapters/euc/`, its own workspace), judged by `compare --as ids` and `--as values`:
//!
//! - its coverage is the exact model's, unsnapped, pixel centres at 1/2, with both sides
//!   of every edge inclusive (`compare --as ids --fit` names the tie rule all-inclusive;
//!   `compare` offers top-left and bottom-left only, under which the other ties show as
//!   `tie`), on a canvas small enough for its setup (adapters/README.md);
//! - on random triangles (both windings, w powers of two from 1/4 to 8, values in thirds,
//!   sevenths, tenths and 256ths), smooth and noperspective, the float model
//!   "homogeneous-64 fma rev div f32 y-down" reproduces every value bit for bit, and no
//!   other (on these scenes): euc's 2D homogeneous weights on its 64-pixel target, the value a fused
//!   `fma(a, w_a, fma(b, w_b, c w_c))`, a triangle clockwise in NDC set up reversed
//!   (`interp::float`'s module docs);
//! - the plain comparison calls none of its values off there;
//! - what euc cannot draw (a `flat` varying) is refused, exit 2, naming the field.
//!
//! The adapter is looked for at adapters/euc/target/release/rasterproof-euc-adapter
//! (`cargo build --release --manifest-path adapters/euc/Cargo.toml`); missing, the tests
//! print a skip message, unless `CI` is set (.ci/run builds it first).

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::{json, Value};

use crate::cli_json::{compare, fit_exact};
use crate::rng::Rng;
use crate::tempdir;

/// euc's arithmetic on a 64-pixel target: what `--fit` must name.
const EUC_64: &str = "homogeneous-64 fma rev div f32 y-down";

/// The adapter, when it is built; otherwise `None` after a skip message (a failure when
/// `CI` is set).
fn adapter() -> Option<PathBuf> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/euc/target/release/rasterproof-euc-adapter");
    if path.is_file() {
        return Some(path);
    }
    let message = format!(
        "{} is not built (cargo build --release --manifest-path adapters/euc/Cargo.toml)",
        path.display()
    );
    assert!(
        std::env::var_os("CI").is_none(),
        "CI is set, so this is an error: {message}"
    );
    eprintln!("skipping the euc adapter tests: {message}");
    None
}

/// A random scene: `n` triangles on a 64x32 canvas, vertices on the 1/256 grid, both
/// windings, w a power of two from 1/4 to 8, three channels in thirds, sevenths, tenths
/// and 256ths.
fn random_scene(seed: u64, n: usize, interpolation: &str) -> Value {
    let mut rng = Rng(seed);
    let grid = |rng: &mut Rng, side: i64| format!("{}/256", rng.below(side * 256));
    let triangles: Vec<Value> = (0..n)
        .map(|_| {
            let v: Vec<Value> = (0..3)
                .map(|_| json!([grid(&mut rng, 64), grid(&mut rng, 32)]))
                .collect();
            let w: Vec<&str> = (0..3)
                .map(|_| ["1/4", "1/2", "1", "2", "4", "8"][rng.below(6) as usize])
                .collect();
            let values: Vec<Vec<String>> = (0..3)
                .map(|_| {
                    (0..3)
                        .map(|_| format!("{}/{}", rng.range(-1000, 1000), [3, 7, 10, 256][rng.below(4) as usize]))
                        .collect()
                })
                .collect();
            json!({"v": v, "w": w, "varyings": {"c": values}})
        })
        .collect();
    json!({
        "width": 64,
        "height": 32,
        "varyings": [{"name": "c", "channels": 3, "interpolation": interpolation}],
        "triangles": triangles,
    })
}

/// The adapter run on `scene` (written into `dir` as `name`): (exit code, stderr, the
/// values TIFF, the ids PNG).
fn draw(adapter: &Path, dir: &tempdir::Dir, name: &str, scene: &Value) -> (i32, String, PathBuf, PathBuf) {
    let path = dir.path().join(format!("{name}.json"));
    std::fs::write(&path, scene.to_string()).unwrap();
    let (tiff, ids) = (
        dir.path().join(format!("{name}.tiff")),
        dir.path().join(format!("{name}.png")),
    );
    let output = Command::new(adapter)
        .arg(&path)
        .arg(&tiff)
        .arg("--ids-out")
        .arg(&ids)
        .output()
        .unwrap();
    (
        output.status.code().unwrap(),
        String::from_utf8_lossy(&output.stderr).into_owned(),
        tiff,
        ids,
    )
}

/// Two triangles on pixel centres sharing their hypotenuse: samples on a left, a top, a
/// right and a bottom edge, and on the shared edge.
fn tie_scene() -> Value {
    let values = json!({"c": [[0, 0, 0], [1, 1, 1], [2, 2, 2]]});
    json!({
        "width": 16,
        "height": 16,
        "varyings": [{"name": "c", "channels": 3}],
        "triangles": [
            {"v": [["1/2", "1/2"], ["17/2", "1/2"], ["1/2", "17/2"]], "varyings": values},
            {"v": [["17/2", "1/2"], ["17/2", "17/2"], ["1/2", "17/2"]], "varyings": values},
        ],
    })
}

#[test]
fn euc_covers_both_sides_of_every_edge() {
    let Some(adapter) = adapter() else { return };
    let dir = tempdir::Dir::new("euc-ties");
    let (code, stderr, _, ids) = draw(&adapter, &dir, "ties", &tie_scene());
    assert_eq!(code, 0, "{stderr}");
    let scene = dir.path().join("ties.json");
    let (code, fit) = compare(&scene, &ids, &["--as", "ids", "--fit"]);
    assert_eq!(code, 0, "{fit}");
    // The tie rule is all-inclusive under every convention that draws the image, the
    // unsnapped one with centres at 1/2 among them (its rounding and bits null).
    let exact = fit["exact"].as_array().unwrap();
    assert!(exact.iter().all(|c| c["tie_rule"] == "all-inclusive"), "{fit}");
    assert!(
        exact.contains(
            &json!({"pixel_centre": "0.5", "rounding": null, "subpixel_bits": null, "tie_rule": "all-inclusive"})
        ),
        "{fit}"
    );
    // Under top-left, only the ties differ: the right and bottom edges' samples are extra,
    // the shared edge's doubly covered.
    let (code, report) = compare(&scene, &ids, &["--as", "ids", "--model", "exact"]);
    assert_eq!(code, 1, "{report}");
    for row in report["summary"].as_array().unwrap() {
        assert_eq!(row["class"], "tie", "{report}");
    }
}

#[test]
fn euc_values_are_one_float_model_bit_for_bit() {
    let Some(adapter) = adapter() else { return };
    let dir = tempdir::Dir::new("euc-values");
    for (seed, interpolation) in [(1, "smooth"), (2, "smooth"), (3, "noperspective")] {
        let name = format!("{interpolation}-{seed}");
        let (code, stderr, tiff, ids) = draw(&adapter, &dir, &name, &random_scene(seed, 12, interpolation));
        assert_eq!(code, 0, "{name}: {stderr}");
        assert!(stderr.contains("0 of 72 NDC coordinates not exact"), "{name}: {stderr}");
        let scene = dir.path().join(format!("{name}.json"));
        // Coverage: the exact model's, but for a tie on a right or bottom edge.
        let (_, report) = compare(&scene, &ids, &["--as", "ids", "--model", "exact"]);
        for row in report["summary"].as_array().unwrap() {
            assert_eq!(
                (&row["class"], &row["kind"]),
                (&json!("tie"), &json!("extra")),
                "{name}: {report}"
            );
        }
        // Values: one model, bit for bit.
        let (code, fit) = compare(&scene, &tiff, &["--as", "values", "--fit"]);
        assert_eq!(code, 0, "{name}: {fit}");
        assert!(fit["judged"].as_u64().unwrap() > 1000, "{name}: {fit}");
        let exact = fit_exact(&fit);
        assert_eq!(exact, [EUC_64], "{name}: {fit}");
        // The plain comparison: nothing off, nothing gross.
        let (code, report) = compare(&scene, &tiff, &["--as", "values"]);
        assert_eq!((code, &report["off"]), (0, &json!(0)), "{name}: {report}");
        assert!(report["counts"].get("gross").is_none(), "{name}: {}", report["counts"]);
    }
}

#[test]
fn what_euc_cannot_draw_is_refused_naming_the_field() {
    let Some(adapter) = adapter() else { return };
    let dir = tempdir::Dir::new("euc-refusals");
    let (code, stderr, _, _) = draw(&adapter, &dir, "flat", &random_scene(4, 2, "flat"));
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("varyings[0].interpolation"), "{stderr}");
    assert_eq!(stderr.trim().lines().count(), 1, "{stderr}");
    let mut lines = random_scene(5, 1, "smooth");
    lines["lines"] = json!([{"from": [0, 0], "to": [3, 4], "varyings": {"c": [[0, 0, 0], [1, 1, 1]]}}]);
    let (code, stderr, _, _) = draw(&adapter, &dir, "lines", &lines);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains(": lines:"), "{stderr}");
}
