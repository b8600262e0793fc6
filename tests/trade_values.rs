//! `rasterproof trade --family values` (issue 47, point 6): on the quick run shared with
//! `tests/trade.rs`, the exact contenders show no error anywhere, the planned path equals
//! the plain definition on every pixel of the workloads, the f32 origin plane's error grows
//! with the canvas offset, the fixed-point DDA moves with neither the offset nor (inside its
//! envelope) anything but the scale, a float model with neither, and the report carries its
//! fields. Golden values come from hand derivations.

use num_rational::BigRational;
use rasterproof::geom::Point;
use rasterproof::interp::dda::{DdaTriangle, GouraudDda};
use rasterproof::interp::planned::{FastPlan, PlannedValue, TriangleF64};
use rasterproof::interp::values::{Interpolation, ProvokingVertex, ValueSetup, ValueTriangle};
use rasterproof::num::exact::nearest_f32;
use rasterproof::trade::values::{ulp_steps, workloads, ValueContender, NAN_STEPS, ULPS, WRONG_UNORM};
use rasterproof::trade::{Axis, Config, Family, Magnitude, Metric, Outcome, WorkloadReport};

use crate::trade::quick;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

fn values_workloads() -> Vec<&'static WorkloadReport> {
    let w: Vec<_> = quick()
        .workloads
        .iter()
        .filter(|w| w.family == Family::Values)
        .collect();
    let names: Vec<&str> = w.iter().map(|w| w.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "smooth triangles",
            "noperspective triangles",
            "values mesh",
            "smooth triangles by attribute scale",
            "noperspective triangles by attribute scale"
        ]
    );
    w
}

/// `(p99, max)` of a cell's ulps.
fn tail(w: &WorkloadReport, contender: &str, m: &str) -> (f64, f64) {
    let c = w.cell(contender, Magnitude::parse(m).unwrap()).unwrap();
    match c.outcome.metric(ULPS) {
        Some(Metric::UlpTail { p99, max, .. }) => (*p99, *max),
        other => panic!("{} / {contender} at {m}: {other:?}", w.name),
    }
}

#[test]
fn the_exact_contenders_show_no_error_at_any_offset_or_scale() {
    for w in values_workloads() {
        let mags = w.magnitudes();
        let expected = match w.axis {
            Axis::Offset => 7,
            Axis::AttributeScale => 9,
        };
        assert_eq!(mags.len(), expected, "{}", w.name);
        for c in ValueContender::ALL.iter().filter(|c| c.is_exact()) {
            for &m in &mags {
                let cell = w.cell(c.name(), m).unwrap();
                let Outcome::Measured { metrics, .. } = &cell.outcome else {
                    panic!("{} / {} at {m}: {cell:?}", w.name, c.name())
                };
                assert!(
                    metrics.iter().all(Metric::is_zero),
                    "{} / {} at {m}: {metrics:?}",
                    w.name,
                    c.name()
                );
                match &metrics[..] {
                    [Metric::UlpTail { samples, .. }, Metric::Rate { name, of, .. }] => {
                        assert!(
                            *samples > 0 && samples == of,
                            "{} / {}: nothing measured",
                            w.name,
                            c.name()
                        );
                        assert_eq!(*name, WRONG_UNORM);
                    }
                    other => panic!("{other:?}"),
                }
            }
        }
    }
    assert_eq!(quick().exact_errors(), Vec::<String>::new());
}

/// The planned path (`FastPlan`, then `PlannedValue`) and the plain definition
/// (`ValueSetup::value`, rounded by `nearest_f32`) agree on every channel of every covered
/// pixel of the quick workloads, at the origin and 2^24 px out.
#[test]
fn planned_equals_plain_on_every_pixel_of_the_workloads() {
    let half = q(1, 2);
    let mut compared = 0;
    let mut fast_decided = 0;
    for w in workloads(&Config::quick()) {
        for offset in [0u32, 1 << 24] {
            for (t, pixels) in w.triangles.iter().zip(&w.pixels) {
                let setup = t.setup(offset.into(), 1);
                let plans = PlannedValue::channels(&setup, w.interpolation, ProvokingVertex::First, 0..3, &half);
                let fast = TriangleF64::of(&setup, 0..3)
                    .map(|f| FastPlan::new(&f, w.interpolation, ProvokingVertex::First, (0.5, 0.5)));
                let mut decided = [None; 3];
                for &(x, y) in pixels {
                    let (x, y) = (x + offset, y + offset);
                    let centre = |v: u32| BigRational::from_integer(v.into()) + &half;
                    let plain = setup
                        .value(
                            w.interpolation,
                            ProvokingVertex::First,
                            0..3,
                            &Point::new(centre(x), centre(y)),
                        )
                        .unwrap();
                    if let Some(f) = &fast {
                        f.nearest_f32(x, y, &mut decided);
                    }
                    for c in 0..3 {
                        let exact = nearest_f32(&plain[c]);
                        assert_eq!(plans[c].nearest_f32(x, y).unwrap(), exact, "{} ({x}, {y})", w.name);
                        if let Some(d) = decided[c] {
                            assert_eq!(Some(d), exact, "{}: FastPlan at ({x}, {y})", w.name);
                            fast_decided += 1;
                        }
                        compared += 1;
                    }
                }
            }
        }
    }
    assert!(compared > 50_000, "{compared}");
    assert!(
        fast_decided * 10 > compared * 9,
        "FastPlan decided {fast_decided} of {compared}"
    );
}

/// The origin plane extrapolates each plane to the framebuffer's origin and multiplies its
/// gradient by the pixel's coordinates: its error grows with the offset, by orders of
/// magnitude by 2^20 px (where f32 holds positions only to 1/8 px).
#[test]
fn the_f32_origin_plane_error_grows_with_the_offset() {
    for w in &values_workloads()[..3] {
        let (p0, max0) = tail(w, "f32-origin-plane", "0");
        let (p20, max20) = tail(w, "f32-origin-plane", "2^20");
        assert!(max0 > 0.0, "{}: the origin plane is exact at 0", w.name);
        assert!(max20 > 1000.0 * max0, "{}: {max0} at 0, {max20} at 2^20", w.name);
        assert!(p20 > 100.0 * p0.max(1.0), "{}: p99 {p0} at 0, {p20} at 2^20", w.name);
        // Up the offsets the p99 does not fall.
        let p99s: Vec<f64> = ["2^8", "2^12", "2^16", "2^20", "2^24"]
            .iter()
            .map(|m| tail(w, "f32-origin-plane", m).0)
            .collect();
        assert!(p99s.windows(2).all(|p| p[0] <= p[1]), "{}: {p99s:?}", w.name);
    }
}

/// The DDA works relative to its triangle's bounding box in integers: the same integers at
/// every offset (all on the 1/256 px grid, within its 2^44 px envelope), so the same error.
/// A power-of-two scale commutes with every float rounding, so the float models' errors
/// are the same at every scale; the DDA's absolute precision makes its error fall as the
/// values grow, until its Q32.32 envelope refuses them (with its reason).
#[test]
fn what_moves_with_offset_and_scale() {
    let w = values_workloads();
    for w in &w[..3] {
        let origin = &w.cell("dda-q32.32", Magnitude::parse("0").unwrap()).unwrap().outcome;
        for m in ["2^4", "2^12", "2^24"] {
            let far = &w.cell("dda-q32.32", Magnitude::parse(m).unwrap()).unwrap().outcome;
            assert_eq!(origin.metric(ULPS), far.metric(ULPS), "{} at {m}", w.name);
            assert_eq!(origin.metric(WRONG_UNORM), far.metric(WRONG_UNORM), "{} at {m}", w.name);
        }
    }
    for w in &w[3..] {
        for c in [
            "f32-origin-plane",
            "f32-vertex-plane",
            "f32-barycentric",
            "f64-origin-plane",
        ] {
            let at = |m: &str| w.cell(c, Magnitude::parse(m).unwrap()).unwrap().outcome.clone();
            for m in ["2^4", "2^16", "2^32"] {
                assert_eq!(at("2^0"), at(m), "{} / {c} at {m}", w.name);
            }
        }
        let (_, unit) = tail(w, "dda-q32.32", "2^0");
        let (_, scaled) = tail(w, "dda-q32.32", "2^16");
        assert!(
            scaled < unit,
            "{}: the DDA's error at 2^16 ({scaled}) not below 2^0's ({unit})",
            w.name
        );
        match &w.cell("dda-q32.32", Magnitude::parse("2^32").unwrap()).unwrap().outcome {
            Outcome::Refused(reason) => assert!(reason.contains("envelope"), "{reason}"),
            other => panic!("{}: the DDA took values of 2^32: {other:?}", w.name),
        }
    }
}

/// By hand: the value `x / 3 * 2^-20` (0, 2^-20, 0 at (0, 0), (3, 0), (0, 3)),
/// noperspective. Vertex 1's input is 2^-20 = 4096 in Q32.32; twice the area is 768^2
/// subpixels, so `A = 256 * 4096 * 768 / 768^2 = 4096 / 3 = 1365.33`, rounded to 1365; the
/// first sample (1/2, 1/2) gets `round(1365 * 128 / 256) = round(682.5) = 682` (a tie, to
/// even). At pixel (2, 0), two steps on: `682 + 2 * 1365 = 3412`, the f32 3412 * 2^-32
/// exactly, which is 13975552 * 2^-44. The exact value there, at (5/2, 1/2), is 5/6 *
/// 2^-20, whose nearest f32 is 13981013 * 2^-44 (5/6 * 2^24 = 13981013.33): 5461 f32 steps
/// apart. The DDA's absolute precision, 2^-32, is thousands of f32 steps at values of
/// 2^-20.
#[test]
fn the_dda_at_small_values_by_hand() {
    let (a, b, c) = (Point::from_ints(0, 0), Point::from_ints(3, 0), Point::from_ints(0, 3));
    let one = q(1, 1);
    let t = ValueSetup::Triangle(Box::new(ValueTriangle::window(
        [&a, &b, &c],
        [&one, &one, &one],
        [vec![q(0, 1)], vec![q(1, 1 << 20)], vec![q(0, 1)]],
    )));
    let inputs = DdaTriangle::of(&t, Interpolation::NoPerspective, ProvokingVertex::First, 0..1, &q(1, 2)).unwrap();
    let dda = GouraudDda::new(&inputs).unwrap();
    assert_eq!(
        (dda.planes()[0].start, dda.planes()[0].dx, dda.planes()[0].dy),
        (682, 1365, 0)
    );
    let mut span = dda.span(0, 0).unwrap();
    span.step();
    span.step();
    assert_eq!(span.fixed(), (&[3412i64][..], None));
    let mut out = [0.0];
    span.values(&mut out);
    let ours = 13_975_552.0f32 * 2f32.powi(-44);
    assert_eq!(out[0], ours);
    let exact = t
        .value(
            Interpolation::NoPerspective,
            ProvokingVertex::First,
            0..1,
            &Point::from_fractions(5, 2, 1, 2),
        )
        .unwrap();
    assert_eq!(exact[0], q(5, 6 << 20));
    let nearest = nearest_f32(&exact[0]).unwrap();
    assert_eq!(nearest, 13_981_013.0f32 * 2f32.powi(-44));
    assert_eq!(ulp_steps(out[0], nearest), 5461);
    assert_eq!(ulp_steps(f32::NAN, nearest), NAN_STEPS);
}

/// The report's JSON carries the values family: its axis and magnitudes, every contender
/// at every one of them, the ulps' tail and the UNORM rate.
#[test]
fn the_json_has_the_values_fields() {
    let j = quick().to_json();
    let values: Vec<&serde_json::Value> = j["workloads"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|w| w["family"] == "values")
        .collect();
    assert_eq!(values.len(), 5);
    for w in values {
        let axis = w["axis"].as_str().unwrap();
        let mags = w["magnitudes"].as_array().unwrap();
        let labels: Vec<&str> = mags.iter().map(|m| m["label"].as_str().unwrap()).collect();
        if axis == "canvas offset" {
            assert_eq!(labels, ["0", "2^4", "2^8", "2^12", "2^16", "2^20", "2^24"]);
        } else {
            assert_eq!(axis, "attribute scale");
            assert_eq!(labels.first(), Some(&"2^0"));
            assert_eq!(labels.last(), Some(&"2^32"));
        }
        let contenders = w["contenders"].as_array().unwrap();
        assert_eq!(contenders.len(), ValueContender::ALL.len());
        assert_eq!(w["baseline"], "f32-origin-plane");
        assert_eq!(w["errors"].as_array().unwrap().len(), contenders.len() * mags.len());
        let planned = &w["plans"][0];
        assert_eq!(planned["model"], "planned");
        assert!(planned["by_width"]["f64"].as_u64().unwrap() > 0);
        for e in w["errors"].as_array().unwrap() {
            if e["status"] != "measured" {
                assert_eq!(e["contender"], "dda-q32.32", "{e}");
                continue;
            }
            let m = &e["metrics"];
            assert_eq!(m[0]["metric"], ULPS);
            assert_eq!(m[0]["kind"], "ulp-tail");
            for k in ["p99", "max"] {
                assert!(m[0][k].as_f64().unwrap() >= 0.0, "{e}");
            }
            assert!(m[0]["samples"].as_u64().unwrap() > 0);
            assert_eq!(m[1]["metric"], WRONG_UNORM);
            assert_eq!(m[1]["kind"], "rate");
            assert_eq!(m[1]["of"], m[0]["samples"]);
        }
    }
    let md = quick().to_markdown();
    assert!(md.contains("## values mesh (values)"));
    assert!(md.contains("| error in f32 steps (ulps p99/max) | 0 px | 2^4 px"));
    assert!(md.contains("| x 2^0 | x 2^4 |"));
}
