//! Mesa llvmpipe's interpolated values through OSMesa (`adapters/osmesa/values.py`, a
//! float32 colour buffer read back bit for bit), judged by `compare --as values` and
//! fitted by `--fit`:
//!
//! - on random triangles (both windings, w powers of two from 1/4 to 8, values in thirds,
//!   sevenths, tenths and 256ths), at canvas offsets 0 and up to 2^14 px, the one float
//!   model "origin-plane fma ccw rcp f32 y-down" reproduces every value bit for bit: a
//!   plane anchored at the framebuffer's origin, evaluated with fused multiply-adds, the
//!   setup reordering clockwise triangles, the smooth quotient as a multiply by the
//!   reciprocal (what Mesa's `lp_state_setup.c` and `lp_bld_interp.c` build);
//! - the plain comparison calls none of llvmpipe's values off;
//! - a deliberate fault (the scene drawn noperspective where it says smooth, or flat from
//!   the last vertex where it says the first) is named by its class at every pixel.
//!
//! Needs /usr/bin/python3 with python3-opengl, python3-numpy, python3-tifffile and
//! libosmesa6: without them the tests print a skip message, unless `CI` is set.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

use crate::cli_json::{compare, fit_exact};
use crate::tempdir;

/// The llvmpipe model: what `--fit` must name.
const LLVMPIPE: &str = "origin-plane fma ccw rcp f32 y-down";

fn python() -> String {
    std::env::var("RASTERPROOF_ADAPTER_PYTHON").unwrap_or_else(|_| "/usr/bin/python3".to_string())
}

fn scene(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/scenes").join(name)
}

/// Whether the Python side is there; without it: skip, or fail under CI.
fn available() -> bool {
    let probe = Command::new(python())
        .args(["-c", "import numpy, tifffile; from OpenGL import osmesa, GL"])
        .env("PYOPENGL_PLATFORM", "osmesa")
        .output();
    if matches!(&probe, Ok(o) if o.status.success()) {
        return true;
    }
    let message =
        "the OSMesa values stack is missing: install libosmesa6 python3-opengl python3-numpy python3-tifffile";
    assert!(
        std::env::var_os("CI").is_none(),
        "CI is set, so this is an error: {message}"
    );
    eprintln!("skipping the OSMesa values tests: {message}");
    false
}

/// llvmpipe's values of `scene` as a TIFF in `dir`.
fn draw(dir: &tempdir::Dir, scene: &Path) -> PathBuf {
    let out = dir
        .path()
        .join(format!("{}.tiff", scene.file_stem().unwrap().to_string_lossy()));
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/osmesa/values.py");
    let output = Command::new(python())
        .arg(script)
        .arg(scene)
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "values.py: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(String::from_utf8_lossy(&output.stderr).contains("renderer: llvmpipe"));
    out
}

/// The scene `name` with `edit` applied to its JSON, written into `dir` as `as_name`.
fn edited(dir: &tempdir::Dir, name: &str, as_name: &str, edit: impl Fn(&mut Value)) -> PathBuf {
    let mut v: Value = serde_json::from_str(&std::fs::read_to_string(scene(name)).unwrap()).unwrap();
    edit(&mut v);
    let path = dir.path().join(as_name);
    std::fs::write(&path, v.to_string()).unwrap();
    path
}

#[test]
fn llvmpipe_values_are_one_float_model_bit_for_bit() {
    if !available() {
        return;
    }
    let dir = tempdir::Dir::new("llvmpipe-values");
    for (name, unique) in [
        ("values-smooth.json", false),
        ("values-smooth-far.json", true),
        ("values-noperspective-far.json", false),
    ] {
        let path = scene(name);
        let theirs = draw(&dir, &path);
        let (code, fit) = compare(&path, &theirs, &["--fit"]);
        assert_eq!(code, 0, "{name}: {fit}");
        let exact = fit_exact(&fit);
        assert!(exact.contains(&LLVMPIPE), "{name}: {exact:?}");
        assert!(fit["judged"].as_u64().unwrap() > 1000, "{name}: {fit}");
        // A smooth scene with the last vertex provoking tells the reordering and the
        // reciprocal apart: one model is left.
        if unique {
            assert_eq!(exact, [LLVMPIPE], "{name}");
        }
        let (code, report) = compare(&path, &theirs, &[]);
        assert_eq!(code, 0, "{name}: {report}");
        assert_eq!(report["off"], 0, "{name}");
        // Far from the origin, the origin-anchored plane's error shows as its class.
        if name.contains("far") {
            assert!(
                report["counts"]["far-anchor"].as_u64().unwrap() > 0,
                "{name}: {}",
                report["counts"]
            );
        }
    }
}

#[test]
fn llvmpipe_with_a_deliberate_fault_is_named() {
    if !available() {
        return;
    }
    let dir = tempdir::Dir::new("llvmpipe-faults");
    let truth = scene("values-smooth.json");
    // Drawn noperspective where the scene says smooth.
    let affine = edited(&dir, "values-smooth.json", "affine.json", |v| {
        v["varyings"][0]["interpolation"] = "noperspective".into();
    });
    let (code, report) = compare(&truth, &draw(&dir, &affine), &[]);
    assert_eq!(code, 1);
    assert_eq!(
        report["counts"].as_object().unwrap().keys().collect::<Vec<_>>(),
        ["affine"],
        "{}",
        report["counts"]
    );
    // Flat from the last vertex where the scene says the first.
    let flat = edited(&dir, "values-smooth.json", "flat.json", |v| {
        v["varyings"][0]["interpolation"] = "flat".into();
    });
    let last = edited(&dir, "values-smooth.json", "last.json", |v| {
        v["varyings"][0]["interpolation"] = "flat".into();
        v["provoking_vertex"] = "last".into();
    });
    let (code, report) = compare(&flat, &draw(&dir, &last), &[]);
    assert_eq!(code, 1);
    assert_eq!(
        report["counts"].as_object().unwrap().keys().collect::<Vec<_>>(),
        ["provoking-vertex"],
        "{}",
        report["counts"]
    );
}

/// `hunt --as values` with the adapter's command: (exit code, report).
fn hunt(args: &[&str], fault: Option<&str>) -> (i32, Value) {
    let dir = tempdir::Dir::new("values-hunt");
    let report = dir.path().join("report.json");
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/osmesa/values.py");
    let mut cmd = format!("{} {} {{scene}} {{out}}", python(), script.display());
    if let Some(f) = fault {
        cmd.push_str(&format!(" --fault {f}"));
    }
    let output = assert_cmd::Command::cargo_bin("rasterproof")
        .unwrap()
        .args([
            "hunt",
            "--as",
            "values",
            "--cmd",
            &cmd,
            "--preset",
            "gl",
            "--float32-exact",
            "--jobs",
            "2",
        ])
        .args(["--shrink-runs", "40", "--report"])
        .arg(&report)
        .args(args)
        .output()
        .unwrap();
    let code = output.status.code().unwrap();
    assert!(code <= 1, "{}", String::from_utf8_lossy(&output.stderr));
    (
        code,
        serde_json::from_str(&std::fs::read_to_string(&report).unwrap()).unwrap(),
    )
}

/// The signatures of a hunt's findings and their minimal scenes' triangle counts.
fn found(report: &Value) -> Vec<(String, usize)> {
    report["findings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            let triangles = f["minimal"]["triangles"].as_array().map_or(0, Vec::len);
            (f["signature"].as_str().unwrap().to_string(), triangles)
        })
        .collect()
}

#[test]
fn the_values_hunt_names_a_deliberate_fault_and_nothing_else() {
    if !available() {
        return;
    }
    // The renderer as it is: nothing off, smooth and flat (provoking last).
    let (code, report) = hunt(&["--cases", "4"], None);
    assert_eq!((code, report["same"].as_u64()), (0, Some(4)), "{report}");
    let (code, report) = hunt(
        &["--cases", "3", "--interpolation", "flat", "--provoking", "last"],
        None,
    );
    assert_eq!((code, report["same"].as_u64()), (0, Some(3)), "{report}");
    // No perspective correction: found as `affine`, shrunk to one triangle.
    let (code, report) = hunt(&["--cases", "3", "--seed", "3"], Some("affine"));
    assert_eq!(code, 1);
    let findings = found(&report);
    assert!(findings.contains(&("affine".to_string(), 1)), "{findings:?}");
    // The wrong provoking vertex of a flat varying.
    let (code, report) = hunt(&["--cases", "3", "--interpolation", "flat"], Some("provoking"));
    assert_eq!(code, 1);
    assert_eq!(found(&report), [("provoking-vertex".to_string(), 1)], "{report}");
}
