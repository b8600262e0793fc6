//! The trade report as JSON: [`TradeReport::to_json`], schema version [`SCHEMA_VERSION`].

use serde_json::{json, Value};

use super::{Outcome, SpeedOutcome, TradeReport, WorkloadReport};
use crate::trade::metric::Metric;

/// The JSON schema version.
pub const SCHEMA_VERSION: u64 = 1;

impl TradeReport {
    /// The report as one JSON object, schema version 1:
    ///
    /// ```text
    /// {"format": "rasterproof trade report", "version": 1, "rasterproof": "0.1.0",
    ///  "quick": bool, "seed": u64, "canvas": side px, "repetitions": n,
    ///  "families": ["triangles", ..., "area", "values"], "magnitudes": [{"label": "2^24", "px": 16777216}, ...],
    ///  "workloads": [{
    ///     "name", "family", "description",
    ///     "axis" ("canvas offset" | "attribute scale": what its magnitudes measure),
    ///     "magnitudes": [{"label", "px"}] (the magnitudes its errors were measured at: the
    ///                   run's, or the values family's own; on the attribute-scale axis
    ///                   "px" is the factor, not pixels),
    ///     "primitives", "unit" ("Mpix/s" | "Mprim/s"),
    ///     "baseline" (the contender ratios divide by), "on_grid" (snapping moves nothing),
    ///     "plans": [{"model", "by_width": {"i32": n, ...}, "summary"}],
    ///     "contenders": [{"name", "exact" (exact or integer), "reference",
    ///                     "speed": {"status": "measured", "median", "min", "max" (draw
    ///                               of the prepared workload), "ratio" (median over the
    ///                               baseline's, or null), "with_prepare" (median of
    ///                               prepare and draw, or null), "elements" (work of one
    ///                               run), "subset"} | {"status": "refused", "reason"}}],
    ///     "errors": [{"magnitude" (label), "px", "contender",
    ///                 "status": "measured", "placement" ("on the canvas" | "translated" |
    ///                 "at the magnitude"), "metrics": [METRIC, ...]}
    ///              | {"magnitude", "px", "contender", "status": "refused", "reason"}],
    ///     "cheapest_exact": [{"magnitude", "contender" (or null), "median"}]}],
    ///  "onsets": [{"workload", "contender", "metric", "first" (label or null)}],
    ///  "headlines": ["..."],
    ///  "predicate_map": {"magnitude", "edge": [[x, y], [x, y]] (exact text),
    ///                    "side", "panels": [{"model", "wrong", "points"}]}}
    /// ```
    ///
    /// `METRIC` is `{"metric", "kind": "rate", "count", "of", "per_million"}` (events out
    /// of opportunities: `wrong pixels` of the pixels the exact answer or the model covers; `gaps`,
    /// `double covers` of the samples next to a shared mesh edge; `Gouraud channels off`
    /// of the channels sampled; `line pixels > 1/2 px off`, `line pixels off the
    /// reference` of the reference's line pixels; `clipped vertices outside` of the
    /// output vertices; `barycentric sums not exact` of the samples) or `{"metric",
    /// "kind": "ulps", "median", "max", "samples"}` (`barycentric sum error (ulps)`, in
    /// ulps of 1 of the model's float type) or `{"metric", "kind": "quanta", "max", "mean",
    /// "pixels"}` (family `area`: `coverage error`, the absolute error of a pixel's
    /// coverage in quanta of 1/255, largest and mean over the pixels where the exact value
    /// or the model's is not zero). Area rates: `pixels off by > 1/2 quantum` and (ftgrays)
    /// `levels off its quantization of the exact value`, of those pixels. Family `values`:
    /// `{"metric", "kind": "ulp-tail", "p99", "max", "samples"}` (`error in f32 steps`: per
    /// channel value at a covered pixel centre, the f32 steps from the exact value's
    /// nearest f32 to the model's, its 99th percentile and largest; a NaN counts 2^32) and
    /// the rate `wrong UNORM8 levels` of the same values. The first metric is the family's
    /// headline.
    pub fn to_json(&self) -> Value {
        let magnitudes: Vec<Value> = self
            .config
            .magnitudes
            .iter()
            .map(|m| json!({"label": m.label(), "px": m.px()}))
            .collect();
        let workloads: Vec<Value> = self.workloads.iter().map(workload_json).collect();
        let onsets: Vec<Value> = self
            .onsets()
            .iter()
            .map(|o| {
                json!({"workload": o.workload, "contender": o.contender, "metric": o.metric,
                       "first": o.first.map(|m| m.label())})
            })
            .collect();
        json!({
            "format": "rasterproof trade report",
            "version": SCHEMA_VERSION,
            "rasterproof": env!("CARGO_PKG_VERSION"),
            "quick": self.config.quick,
            "seed": self.config.seed,
            "canvas": self.canvas,
            "repetitions": self.repetitions,
            "families": self.config.families.iter().map(|f| f.name()).collect::<Vec<_>>(),
            "magnitudes": magnitudes,
            "workloads": workloads,
            "onsets": onsets,
            "headlines": self.headlines(),
            "predicate_map": self.predicate_map.to_json(),
        })
    }
}

fn workload_json(w: &WorkloadReport) -> Value {
    let contenders: Vec<Value> = w
        .speed
        .iter()
        .map(|s| {
            let speed = match &s.outcome {
                SpeedOutcome::Refused(reason) => json!({"status": "refused", "reason": reason}),
                SpeedOutcome::Measured {
                    median,
                    min,
                    max,
                    with_prepare,
                    elements,
                    subset,
                } => json!({
                    "status": "measured", "median": median, "min": min, "max": max,
                    "ratio": w.ratio(&s.contender), "with_prepare": with_prepare,
                    "elements": elements, "subset": subset,
                }),
            };
            json!({"name": s.contender, "exact": s.exact, "reference": s.reference, "speed": speed})
        })
        .collect();
    let errors: Vec<Value> = w
        .cells
        .iter()
        .map(|c| {
            let head = json!({"magnitude": c.magnitude.label(), "px": c.magnitude.px(), "contender": c.contender});
            let mut v = head;
            let obj = v.as_object_mut().expect("an object");
            match &c.outcome {
                Outcome::Refused(reason) => {
                    obj.insert("status".into(), "refused".into());
                    obj.insert("reason".into(), reason.clone().into());
                }
                Outcome::Measured { placement, metrics } => {
                    obj.insert("status".into(), "measured".into());
                    obj.insert("placement".into(), placement.name().into());
                    obj.insert("metrics".into(), metrics.iter().map(metric_json).collect());
                }
            }
            v
        })
        .collect();
    let plans: Vec<Value> = w
        .plans
        .iter()
        .map(|p| {
            let by_width: serde_json::Map<String, Value> =
                p.by_width.iter().map(|(k, n)| ((*k).to_string(), json!(n))).collect();
            json!({"model": p.model, "by_width": by_width, "summary": p.summary})
        })
        .collect();
    let cheapest: Vec<Value> = w
        .magnitudes()
        .iter()
        .map(|&m| {
            let c = w.cheapest_exact(m);
            json!({"magnitude": m.label(), "contender": c.map(|c| c.0), "median": c.map(|c| c.1)})
        })
        .collect();
    let points: Vec<Value> = w
        .magnitudes()
        .iter()
        .map(|m| json!({"label": m.label(), "px": m.px()}))
        .collect();
    json!({
        "name": w.name, "family": w.family.name(), "description": w.description,
        "axis": w.axis.name(), "magnitudes": points,
        "primitives": w.primitives, "unit": w.unit, "baseline": w.baseline, "on_grid": w.on_grid,
        "plans": plans, "contenders": contenders, "errors": errors, "cheapest_exact": cheapest,
    })
}

/// One metric as JSON: `{"metric", "kind": "rate", "count", "of", "per_million"}`,
/// `{"metric", "kind": "ulps", "median", "max", "samples"}`, `{"metric", "kind":
/// "ulp-tail", "p99", "max", "samples"}` or `{"metric", "kind": "quanta", "max", "mean",
/// "pixels"}`.
fn metric_json(m: &Metric) -> Value {
    match m {
        Metric::Rate { name, count, of } => json!({
            "metric": name, "kind": "rate", "count": count, "of": of,
            "per_million": m.per_million(),
        }),
        Metric::Ulps {
            name,
            median,
            max,
            samples,
        } => json!({"metric": name, "kind": "ulps", "median": median, "max": max, "samples": samples}),
        Metric::UlpTail {
            name,
            p99,
            max,
            samples,
        } => json!({"metric": name, "kind": "ulp-tail", "p99": p99, "max": max, "samples": samples}),
        Metric::Quanta {
            name,
            max,
            mean,
            pixels,
        } => {
            json!({"metric": name, "kind": "quanta", "max": max, "mean": mean, "pixels": pixels})
        }
    }
}
