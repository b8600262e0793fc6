//! `rasterproof trade` (issue 14): the quick run's report keeps the promises the trade
//! exists to show (exact and integer models without error wherever they accept a
//! workload, every float model wrong somewhere, the integer envelope refused with its
//! reason), its JSON has the documented schema, its pictures decode; the command writes
//! its files all or nothing and refuses bad options with exit 2. Never a time.

use std::sync::OnceLock;

use assert_cmd::Command;
use rasterproof::trade::{run, Config, Magnitude, Outcome, TradeReport};
use serde_json::Value;

use crate::tempdir;

/// One quick run, shared by the tests of this file.
fn quick() -> &'static TradeReport {
    static REPORT: OnceLock<TradeReport> = OnceLock::new();
    REPORT.get_or_init(|| run(&Config::quick(), &mut |_| {}))
}

fn bin() -> Command {
    Command::cargo_bin("rasterproof").unwrap()
}

#[test]
fn exact_and_integer_models_show_no_error_wherever_they_accept() {
    let r = quick();
    assert_eq!(r.exact_errors(), Vec::<String>::new());
    // And they were measured at all: in every workload each exact contender is measured
    // somewhere, or refuses the whole workload with its reason (fixed cannot triangulate
    // self-intersecting polygons).
    for w in &r.workloads {
        for s in w.speed.iter().filter(|s| s.exact) {
            let cells: Vec<_> = w.cells.iter().filter(|c| c.contender == s.contender).collect();
            let measured = cells
                .iter()
                .any(|c| matches!(&c.outcome, Outcome::Measured { metrics, .. } if !metrics.is_empty()));
            let refused_with_reason = cells
                .iter()
                .all(|c| matches!(&c.outcome, Outcome::Refused(reason) if !reason.is_empty()));
            assert!(
                measured || refused_with_reason,
                "{} / {}: {cells:?}",
                w.name,
                s.contender
            );
        }
    }
    let any = r.workloads.iter().find(|w| w.name == "any polygons").unwrap();
    match &any.cell("fixed", Magnitude::new(0).unwrap()).unwrap().outcome {
        Outcome::Refused(reason) => assert!(reason.contains("triangulate"), "{reason}"),
        other => panic!("fixed took self-intersecting polygons: {other:?}"),
    }
}

#[test]
fn every_float_model_is_wrong_at_some_magnitude() {
    let r = quick();
    let floats = [
        "float32",
        "float64",
        "float32-naive",
        "float64-naive",
        "dda32",
        "dda64",
        "cs-f32",
        "cs-f64",
        "sh-f32",
        "sh-f64",
    ];
    for name in floats {
        let wrong = r.workloads.iter().flat_map(|w| &w.cells).any(|c| {
            c.contender == name
                && matches!(&c.outcome, Outcome::Measured { metrics, .. } if metrics.iter().any(|m| !m.is_zero()))
        });
        assert!(wrong, "{name} shows no error anywhere: the workloads lack teeth");
    }
    // Wrong pixels specifically, for f32 far from the origin.
    let pixel = r.workloads.iter().find(|w| w.name == "medium triangles").unwrap();
    let far = pixel.cell("float32", Magnitude::parse("2^24").unwrap()).unwrap();
    assert!(!far.outcome.headline().unwrap().is_zero(), "{far:?}");
}

#[test]
fn the_integer_envelope_is_refused_with_its_reason() {
    let r = quick();
    let w = r.workloads.iter().find(|w| w.name == "pixel triangles").unwrap();
    let at = |m: &str| &w.cell("fixed", Magnitude::parse(m).unwrap()).unwrap().outcome;
    assert!(matches!(at("2^20"), Outcome::Measured { .. }), "{:?}", at("2^20"));
    match at("2^23") {
        Outcome::Refused(reason) => assert!(reason.contains("envelope") || reason.contains("2^"), "{reason}"),
        other => panic!("fixed at 2^23 px: {other:?}"),
    }
    // Bresenham endpoints are pixel addresses within 2^24: refused beyond.
    let lines = r.workloads.iter().find(|w| w.name == "bresenham lines").unwrap();
    let cell = lines.cell("dda32", Magnitude::parse("2^30").unwrap()).unwrap();
    assert!(matches!(cell.outcome, Outcome::Refused(_)), "{cell:?}");
    // The exact models refuse no area primitive (Bresenham endpoints are addresses the
    // scene format bounds, for every model).
    for w in r.workloads.iter().filter(|w| w.name != "bresenham lines") {
        for c in w.cells.iter().filter(|c| c.contender.starts_with("exact")) {
            assert!(matches!(c.outcome, Outcome::Measured { .. }), "{} {c:?}", w.name);
        }
    }
}

/// Asserts `v[key]` exists and satisfies `ok`.
fn has(v: &Value, key: &str, ok: fn(&Value) -> bool) {
    let x = v.get(key).unwrap_or_else(|| panic!("missing {key:?} in {v}"));
    assert!(ok(x), "{key:?} = {x}");
}

fn check_schema(j: &Value) {
    has(j, "format", |v| v == "rasterproof trade report");
    has(j, "version", |v| v == 1);
    for k in ["quick", "seed", "canvas", "repetitions", "families", "magnitudes"] {
        has(j, k, |v| !v.is_null());
    }
    has(j, "headlines", Value::is_array);
    has(j, "onsets", Value::is_array);
    for m in j["magnitudes"].as_array().unwrap() {
        has(m, "label", Value::is_string);
        has(m, "px", Value::is_u64);
    }
    let workloads = j["workloads"].as_array().unwrap();
    assert!(!workloads.is_empty());
    for w in workloads {
        for k in ["name", "family", "description", "unit", "baseline"] {
            has(w, k, Value::is_string);
        }
        has(w, "primitives", Value::is_u64);
        has(w, "on_grid", Value::is_boolean);
        has(w, "plans", Value::is_array);
        has(w, "cheapest_exact", Value::is_array);
        for c in w["contenders"].as_array().unwrap() {
            has(c, "name", Value::is_string);
            has(c, "exact", Value::is_boolean);
            let s = &c["speed"];
            match s["status"].as_str().unwrap() {
                "measured" => {
                    for k in ["median", "min", "max"] {
                        has(s, k, Value::is_f64);
                    }
                    has(s, "elements", Value::is_u64);
                    has(s, "subset", Value::is_boolean);
                }
                "refused" => has(s, "reason", |v| v.as_str().is_some_and(|r| !r.is_empty())),
                other => panic!("speed status {other}"),
            }
        }
        for e in w["errors"].as_array().unwrap() {
            has(e, "magnitude", Value::is_string);
            has(e, "px", Value::is_u64);
            has(e, "contender", Value::is_string);
            match e["status"].as_str().unwrap() {
                "measured" => {
                    has(e, "placement", |v| {
                        ["on the canvas", "translated", "at the magnitude"].contains(&v.as_str().unwrap())
                    });
                    for m in e["metrics"].as_array().unwrap() {
                        has(m, "metric", Value::is_string);
                        match m["kind"].as_str().unwrap() {
                            "rate" => {
                                has(m, "count", Value::is_u64);
                                has(m, "of", Value::is_u64);
                            }
                            "ulps" => {
                                has(m, "median", Value::is_number);
                                has(m, "max", Value::is_number);
                                has(m, "samples", Value::is_u64);
                            }
                            other => panic!("metric kind {other}"),
                        }
                    }
                }
                "refused" => has(e, "reason", |v| v.as_str().is_some_and(|r| !r.is_empty())),
                other => panic!("error status {other}"),
            }
        }
    }
    let map = &j["predicate_map"];
    has(map, "side", Value::is_u64);
    assert_eq!(map["panels"].as_array().unwrap().len(), 4);
}

#[test]
fn the_json_has_the_documented_schema_and_every_contender_at_every_magnitude() {
    let r = quick();
    let j = r.to_json();
    check_schema(&j);
    let mags = Magnitude::DEFAULT.len();
    for w in j["workloads"].as_array().unwrap() {
        let contenders = w["contenders"].as_array().unwrap().len();
        assert_eq!(
            w["errors"].as_array().unwrap().len(),
            contenders * mags,
            "{}",
            w["name"]
        );
    }
    let families: Vec<&str> = j["workloads"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w["family"].as_str().unwrap())
        .collect();
    for f in ["triangles", "lines", "polygons", "clipping"] {
        assert!(families.contains(&f), "{f}");
    }
    let md = r.to_markdown();
    for w in &r.workloads {
        assert!(md.contains(&format!("## {}", w.name)), "{}", w.name);
    }
    assert!(md.contains("refused"));
}

#[test]
fn the_pictures_decode() {
    let pictures = quick().pictures().unwrap();
    let names: Vec<&str> = pictures.iter().map(|p| p.name.as_str()).collect();
    for stem in ["speed-vs-error", "error-vs-magnitude", "predicate-map"] {
        for ext in ["png", "svg"] {
            assert!(names.contains(&format!("{stem}.{ext}").as_str()), "{stem}.{ext}");
        }
    }
    for p in &pictures {
        if p.name.ends_with(".png") {
            let img = image::load_from_memory(&p.bytes).unwrap();
            assert!(img.width() >= 1000 && img.height() >= 1000, "{}", p.name);
        } else {
            let text = String::from_utf8(p.bytes.clone()).unwrap();
            assert!(text.starts_with("<svg") && text.contains("</svg>"), "{}", p.name);
        }
    }
}

#[test]
fn the_command_writes_every_file_and_prints_the_json() {
    let dir = tempdir::Dir::new("trade-out");
    let out = dir.path().join("report");
    let assert = bin()
        .args([
            "trade",
            "--quick",
            "--quiet",
            "--family",
            "clipping",
            "--magnitudes",
            "0,2^24",
            "--format",
            "json",
        ])
        .arg("--out")
        .arg(&out)
        .assert()
        .success();
    let j: Value = serde_json::from_slice(&assert.get_output().stdout).unwrap();
    check_schema(&j);
    assert_eq!(j["families"], serde_json::json!(["clipping"]));
    let mut files: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    files.sort();
    assert_eq!(
        files,
        [
            "error-vs-magnitude.png",
            "error-vs-magnitude.svg",
            "predicate-map.png",
            "predicate-map.svg",
            "speed-vs-error.png",
            "speed-vs-error.svg",
            "trade.json",
            "trade.md",
        ]
    );
    let written: Value = serde_json::from_slice(&std::fs::read(out.join("trade.json")).unwrap()).unwrap();
    assert_eq!(written["workloads"], j["workloads"]);
}

#[test]
fn bad_options_exit_2_and_write_nothing() {
    let dir = tempdir::Dir::new("trade-bad");
    let file = dir.path().join("a-file");
    std::fs::write(&file, "keep").unwrap();
    let fresh = dir.path().join("fresh");
    let cases: [(&[&str], &str); 4] = [
        (&["--family", "triangles,nope"], "--family: unknown family \"nope\""),
        (&["--magnitudes", "0,2^41"], "--magnitudes"),
        (&["--magnitudes", "x"], "--magnitudes"),
        (&["--format", "xml"], "xml"),
    ];
    for (args, message) in cases {
        let out = bin().arg("trade").args(args).arg("--out").arg(&fresh).assert().code(2);
        let err = String::from_utf8_lossy(&out.get_output().stderr).to_string();
        assert!(err.contains(message), "{args:?}: {err}");
        assert!(!fresh.exists(), "{args:?} created the output folder");
    }
    let out = bin().args(["trade", "--quick", "--out"]).arg(&file).assert().code(2);
    let err = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert!(err.contains("names a file"), "{err}");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "keep");
}
