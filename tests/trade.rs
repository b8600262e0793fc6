//! `rasterproof trade` (issue 14): the quick run's report keeps the promises the trade
//! exists to show (exact and integer models without error wherever they accept a
//! workload, every float model wrong somewhere, the integer envelope refused with its
//! reason), its JSON has the documented schema, its pictures decode; the command writes
//! its files all or nothing and refuses bad options with exit 2. Never a time.

use std::sync::OnceLock;

use assert_cmd::Command;
use num_rational::BigRational;
use rasterproof::area::{planned, triangle_shape, AreaMethod, AreaOutput, AreaShape, Quantization, Semantics};
use rasterproof::geom::{FillRule, Point, Polygon, Triangle};
use rasterproof::trade::area::{area_metrics, AreaContender, COVERAGE_ERROR, OFF_HALF_QUANTUM};
use rasterproof::trade::{run, Config, Magnitude, Metric, Outcome, TradeReport};
use serde_json::Value;

use crate::tempdir;

/// One quick run, shared by the tests of this file: `run(&Config::quick())`, its families
/// on threads of their own. Each workload draws from its own seeded runner (the run's seed
/// and the workload's name), so a family run alone gives the workloads it gives in the
/// whole run, and the report is theirs in family order. (The other tests of this file wait
/// for it on their test threads: run on one thread, it left a core idle for half a minute.
/// Its speeds, measured side by side here, are asserted nowhere.)
pub(crate) fn quick() -> &'static TradeReport {
    static REPORT: OnceLock<TradeReport> = OnceLock::new();
    REPORT.get_or_init(|| {
        let config = Config::quick();
        let parts: Vec<TradeReport> = std::thread::scope(|s| {
            let runs: Vec<_> = config
                .families
                .iter()
                .map(|&family| {
                    let one = Config {
                        families: vec![family],
                        ..config.clone()
                    };
                    s.spawn(move || run(&one, &mut |_| {}))
                })
                .collect();
            runs.into_iter().map(|r| r.join().unwrap()).collect()
        });
        let mut parts = parts.into_iter();
        let mut report = parts.next().expect("a family");
        report.config = config;
        for part in parts {
            report.workloads.extend(part.workloads);
        }
        report
    })
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
        has(w, "axis", |v| {
            ["canvas offset", "attribute scale"].contains(&v.as_str().unwrap_or(""))
        });
        has(w, "magnitudes", |v| v.as_array().is_some_and(|a| !a.is_empty()));
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
                            "ulp-tail" => {
                                has(m, "p99", Value::is_number);
                                has(m, "max", Value::is_number);
                                has(m, "samples", Value::is_u64);
                            }
                            "quanta" => {
                                has(m, "max", Value::is_number);
                                has(m, "mean", Value::is_number);
                                has(m, "pixels", Value::is_u64);
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
    for w in j["workloads"].as_array().unwrap() {
        let contenders = w["contenders"].as_array().unwrap().len();
        // Every family at the run's magnitudes, the values family at its own.
        let mags = if w["family"] == "values" {
            w["magnitudes"].as_array().unwrap().len()
        } else {
            assert_eq!(w["magnitudes"].as_array().unwrap().len(), Magnitude::DEFAULT.len());
            Magnitude::DEFAULT.len()
        };
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
    for f in ["triangles", "lines", "polygons", "clipping", "area", "values"] {
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
    for stem in [
        "speed-vs-error",
        "error-vs-magnitude",
        "area-speed-vs-error",
        "area-error-vs-magnitude",
        "values-error-vs-offset",
        "values-error-vs-scale",
        "values-speed-vs-error",
        "predicate-map",
    ] {
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
            "area-error-vs-magnitude.png",
            "area-error-vs-magnitude.svg",
            "area-speed-vs-error.png",
            "area-speed-vs-error.svg",
            "error-vs-magnitude.png",
            "error-vs-magnitude.svg",
            "predicate-map.png",
            "predicate-map.svg",
            "speed-vs-error.png",
            "speed-vs-error.svg",
            "trade.json",
            "trade.md",
            "values-error-vs-offset.png",
            "values-error-vs-offset.svg",
            "values-error-vs-scale.png",
            "values-error-vs-scale.svg",
            "values-speed-vs-error.png",
            "values-speed-vs-error.svg",
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

/// The area family: every exact contender (the planned engine, exact cells, the plain
/// oracle) shows exactly zero error at every magnitude, on every area workload; f32
/// accumulation is off by more than half a quantum somewhere by 2^24 px; ftgrays is
/// measured at 2^20 px and refused, with its envelope named, from 2^23 px.
#[test]
fn area_exact_contenders_are_exact_and_ftgrays_refuses_past_its_envelope() {
    let r = quick();
    let area: Vec<_> = r.workloads.iter().filter(|w| w.family.name() == "area").collect();
    let names: Vec<&str> = area.iter().map(|w| w.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "glyphs at 9 px/em",
            "glyphs at 24 px/em",
            "glyphs at 64 px/em",
            "glyphs at 200 px/em",
            "abutting mesh",
            "area slivers"
        ]
    );
    for w in &area {
        for name in ["area-plain", "area-cells", "area-planned"] {
            for &m in &r.config.magnitudes {
                let c = w.cell(name, m).unwrap_or_else(|| panic!("{} / {name} at {m}", w.name));
                let Outcome::Measured { metrics, .. } = &c.outcome else {
                    panic!("{} / {name} at {m}: {c:?}", w.name)
                };
                match c.outcome.metric(COVERAGE_ERROR) {
                    Some(Metric::Quanta { max, mean, pixels, .. }) => {
                        assert_eq!((*max, *mean), (0.0, 0.0), "{} / {name} at {m}", w.name);
                        assert!(*pixels > 0, "{} / {name}: nothing measured", w.name);
                    }
                    other => panic!("{} / {name} at {m}: {other:?}", w.name),
                }
                assert!(
                    metrics.iter().all(Metric::is_zero),
                    "{} / {name} at {m}: {metrics:?}",
                    w.name
                );
            }
        }
        let at = |name: &str, m: &str| &w.cell(name, Magnitude::parse(m).unwrap()).unwrap().outcome;
        assert!(matches!(at("ftgrays", "2^20"), Outcome::Measured { .. }), "{}", w.name);
        for m in ["2^23", "2^24", "2^30"] {
            match at("ftgrays", m) {
                Outcome::Refused(reason) => assert!(reason.contains("24.8 envelope"), "{reason}"),
                other => panic!("{} / ftgrays at {m}: {other:?}", w.name),
            }
        }
    }
    let glyphs = area.iter().find(|w| w.name == "glyphs at 24 px/em").unwrap();
    let f32_far = glyphs.cell("f32-accum", Magnitude::parse("2^24").unwrap()).unwrap();
    assert!(!f32_far.outcome.headline().unwrap().is_zero(), "{f32_far:?}");
    assert_eq!(f32_far.outcome.headline().unwrap().name(), OFF_HALF_QUANTUM);
    // The Markdown has the area tables, in quanta.
    let md = r.to_markdown();
    assert!(md.contains("## glyphs at 24 px/em (area)"), "no area section");
    assert!(md.contains("| coverage error (1/255 max/mean) |"), "no quanta table");
}

fn int(v: i64) -> BigRational {
    BigRational::from_integer(v.into())
}

/// A half-pixel rectangle `[0, 1/2] x [0, 1]` placed at `(M, M)`: exactly 1/2 of pixel
/// (0, 0) of the window. Below 2^23 every coordinate `M + 1/2` is an f32 (at 2^22 the f32
/// step is 1/2), so f32 accumulation is exact; at 2^23 the step is 1 and `M + 1/2` ties to
/// the even `M`: the rectangle has no width, the pixel reads 0, off by exactly 1/2, that
/// is 127.5 quanta, one pixel in one off by more than half a quantum.
#[test]
fn f32_accumulation_loses_a_half_pixel_at_2_23_by_hand() {
    let half = BigRational::new(1.into(), 2.into());
    let rect = |m: i64| -> Vec<AreaShape> {
        let p = |x: BigRational, y: i64| Point::new(x + int(m), int(y + m));
        vec![Polygon::new(
            vec![p(int(0), 0), p(half.clone(), 0), p(half.clone(), 1), p(int(0), 1)],
            FillRule::NonZero,
        )]
    };
    let reference = planned::rasterize(&rect(0), 2, 2, Semantics::Accumulated);
    assert_eq!(reference.value(0, 0), half);
    let metrics = |m: i64| {
        area_metrics(
            &reference,
            &AreaOutput::F32(rasterproof::area::float::rasterize_at(
                &rect(m),
                m,
                2,
                2,
                Semantics::Accumulated,
            )),
            None,
        )
    };
    let at22 = metrics(1 << 22);
    assert!(at22.iter().all(Metric::is_zero), "{at22:?}");
    let at23 = metrics(1 << 23);
    assert_eq!(
        at23[0],
        Metric::Rate {
            name: OFF_HALF_QUANTUM,
            count: 1,
            of: 1
        }
    );
    assert_eq!(
        at23[1],
        Metric::Quanta {
            name: COVERAGE_ERROR,
            max: 127.5,
            mean: 127.5,
            pixels: 1
        }
    );
}

/// The triangle (0,0) (1,0) (0,1) covers exactly 1/2 of its pixel. Of its 4 x 4 samples
/// `((i + 1/2)/4, (j + 1/2)/4)`, the 6 with `i + j < 3` are inside and the 4 with
/// `i + j = 3` lie on the hypotenuse, all taken or all left by the top-left rule: 6/16 or
/// 10/16, off by exactly 1/8 = 31.875 quanta either way. The exact contenders are off by 0.
#[test]
fn supersampling_is_off_by_an_eighth_by_hand() {
    let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(1, 0), Point::from_ints(0, 1));
    let shapes = [triangle_shape(&t)];
    let reference = planned::rasterize(&shapes, 1, 1, Semantics::Accumulated);
    assert_eq!(reference.value(0, 0), BigRational::new(1.into(), 2.into()));
    let ss = AreaContender::Method(AreaMethod::Supersample(4))
        .draw(&shapes, 1, 1)
        .unwrap();
    let m = area_metrics(&reference, &ss, None);
    assert_eq!(
        m[1],
        Metric::Quanta {
            name: COVERAGE_ERROR,
            max: 31.875,
            mean: 31.875,
            pixels: 1
        }
    );
    assert_eq!(m[0].per_million(), Some(1e6));
    for exact in [AreaMethod::Plain, AreaMethod::Cells, AreaMethod::Planned].map(AreaContender::Method) {
        let out = exact.draw(&shapes, 1, 1).unwrap();
        assert!(
            area_metrics(&reference, &out, None).iter().all(Metric::is_zero),
            "{exact:?}"
        );
    }
    // ftgrays: the hypotenuse leaves the cell above through its corner (1, 1), and the
    // reciprocal division (FT_UDIV: 2^16 x (2^48 - 1) >> 56 = 255) puts that exit at
    // x = 255/256: the area is short by 1/512, floor(256 x (1/2 - 1/512)) = 127, where its
    // own quantization of the exact 1/2 is 128. Read as 127/255 it is off by exactly
    // 1/510, half a quantum (not more).
    let ft = AreaContender::Method(AreaMethod::FtGrays).draw(&shapes, 1, 1).unwrap();
    assert_eq!(ft, AreaOutput::levels8(vec![127]));
    let m = area_metrics(&reference, &ft, Some(Quantization::FtGrays));
    assert_eq!(m[0].per_million(), Some(0.0));
    assert_eq!(m[2].per_million(), Some(1e6));
    match &m[1] {
        Metric::Quanta { max, .. } => assert_eq!(*max, 0.5),
        other => panic!("{other:?}"),
    }
}

/// ftgrays's envelope at the placed coordinates, one unit either side: a unit square whose
/// right side lands on `2^23 - 1` px is drawn; one pixel further, at `2^23` px, it is
/// refused with the model's own message.
#[test]
fn ftgrays_is_refused_beyond_its_envelope_by_hand() {
    let square = vec![Polygon::new(
        vec![
            Point::from_ints(0, 0),
            Point::from_ints(1, 0),
            Point::from_ints(1, 1),
            Point::from_ints(0, 1),
        ],
        FillRule::NonZero,
    )];
    let inside = rasterproof::area::ftgrays::rasterize_at(&square, (1 << 23) - 2, 2, 2).unwrap();
    assert_eq!(inside, vec![255, 0, 0, 0]);
    let err = rasterproof::area::ftgrays::rasterize_at(&square, (1 << 23) - 1, 2, 2).unwrap_err();
    assert!(err.contains("24.8 envelope") && err.contains("8388608"), "{err}");
}

/// The committed tables (`docs/trade/trade.json`, a full run) are the code's: the `--quick`
/// run shared by this file's tests (`trade --quick --format json`'s document), whose glyph workloads are the full run's (the same scenes and
/// canvases, the same subset window), gives every error figure the committed tables give
/// where both measured the same pixels (the same `of` or `pixels`; the abutting mesh and
/// slivers are smaller in a quick run). Stale tables (a model changed, the tables not
/// regenerated: `rasterproof trade --out docs/trade`) fail here.
#[test]
fn the_committed_tables_match_a_quick_run_where_they_overlap() {
    let committed: Value = serde_json::from_str(
        &std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/trade/trade.json"))
            .unwrap(),
    )
    .unwrap();
    let quick = quick().to_json();
    let mut compared = 0;
    for w in quick["workloads"].as_array().unwrap() {
        let Some(full) = committed["workloads"]
            .as_array()
            .unwrap()
            .iter()
            .find(|f| f["name"] == w["name"] && f["description"] == w["description"])
        else {
            continue;
        };
        for e in w["errors"].as_array().unwrap() {
            let Some(f) = full["errors"]
                .as_array()
                .unwrap()
                .iter()
                .find(|f| f["contender"] == e["contender"] && f["magnitude"] == e["magnitude"])
            else {
                continue;
            };
            assert_eq!(e["status"], f["status"], "{} {}", w["name"], e);
            let (ours, theirs) = (e["metrics"].as_array(), f["metrics"].as_array());
            let (Some(ours), Some(theirs)) = (ours, theirs) else {
                continue;
            };
            for m in ours {
                let Some(c) = theirs
                    .iter()
                    .find(|c| c["metric"] == m["metric"] && c["kind"] == m["kind"])
                else {
                    continue;
                };
                if m["of"] != c["of"] || m["pixels"] != c["pixels"] {
                    continue;
                }
                let near = |a: &Value, b: &Value| match (a.as_f64(), b.as_f64()) {
                    (Some(a), Some(b)) => (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1.0),
                    _ => a == b,
                };
                for key in ["count", "max", "mean"] {
                    assert!(
                        near(&m[key], &c[key]),
                        "docs/trade is stale: {} {} at {}: {} {key} {} now, {} committed",
                        w["name"],
                        e["contender"],
                        e["magnitude"],
                        m["metric"],
                        m[key],
                        c[key]
                    );
                }
                compared += 1;
            }
        }
    }
    assert!(
        compared >= 100,
        "only {compared} figures overlap: the test no longer tests"
    );
}
