//! A trade run's result: per workload its contenders' speed, its plan and its errors at
//! every magnitude; written as JSON ([`Report::to_json`], the documented schema), as
//! Markdown tables ([`Report::to_markdown`]) and as pictures ([`Report::pictures`]).

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::predicate_map::PredicateMap;
use super::{Config, Family, Magnitude};

/// How a contender met the window at a magnitude.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Placement {
    /// At magnitude 0: the workload on the canvas, drawn by the model itself.
    OnCanvas,
    /// An exact or integer model beyond the canvas: prepared on the placed workload (its
    /// refusals are real), drawn at the origin (its answer is translation-invariant).
    Translated,
    /// Computed with the placed coordinates: the float rasterizer over the window at
    /// `M`, the DDA, Bresenham or a clipper on the placed inputs.
    AtMagnitude,
}

impl Placement {
    /// The name in the report.
    pub fn name(self) -> &'static str {
        match self {
            Placement::OnCanvas => "on the canvas",
            Placement::Translated => "translated",
            Placement::AtMagnitude => "at the magnitude",
        }
    }
}

/// One measured error.
#[derive(Debug, Clone, PartialEq)]
pub enum Metric {
    /// `count` events out of `of` opportunities (wrong pixels of the covered pixels, ...).
    Rate {
        /// What is counted (`wrong pixels`, `gaps`, ...).
        name: &'static str,
        /// How many.
        count: u64,
        /// Out of how many.
        of: u64,
    },
    /// A distribution in ulps (barycentric sums).
    Ulps {
        /// What is measured.
        name: &'static str,
        /// The median.
        median: f64,
        /// The largest.
        max: f64,
        /// How many samples.
        samples: u64,
    },
}

impl Metric {
    /// The metric's name.
    pub fn name(&self) -> &'static str {
        match self {
            Metric::Rate { name, .. } | Metric::Ulps { name, .. } => name,
        }
    }

    /// Whether it shows no error at all.
    pub fn is_zero(&self) -> bool {
        match self {
            Metric::Rate { count, .. } => *count == 0,
            Metric::Ulps { max, .. } => *max == 0.0,
        }
    }

    /// A rate per million opportunities (`None` for ulps, or nothing to count).
    pub fn per_million(&self) -> Option<f64> {
        match self {
            Metric::Rate { count, of, .. } if *of > 0 => Some(ratio(*count, *of) * 1e6),
            _ => None,
        }
    }

    /// A short cell: `123.4` per million (`0` exactly), or `median/max` ulps.
    pub fn cell(&self) -> String {
        match self {
            Metric::Rate { count: 0, .. } => "0".into(),
            Metric::Rate { .. } => self.per_million().map_or_else(|| "-".into(), short),
            Metric::Ulps {
                median, max, samples, ..
            } => format!("{}/{} (n={samples})", short(*median), short(*max)),
        }
    }

    fn to_json(&self) -> Value {
        match self {
            Metric::Rate { name, count, of } => json!({
                "metric": name, "kind": "rate", "count": count, "of": of,
                "per_million": self.per_million(),
            }),
            Metric::Ulps {
                name,
                median,
                max,
                samples,
            } => json!({"metric": name, "kind": "ulps", "median": median, "max": max, "samples": samples}),
        }
    }
}

/// `a / b` as f64 (both far below 2^53 here).
#[allow(clippy::cast_precision_loss)] // counts below 2^53
fn ratio(a: u64, b: u64) -> f64 {
    a as f64 / b as f64
}

/// A number in 4 significant digits at most, no exponent below 10^7.
fn short(v: f64) -> String {
    if v == 0.0 {
        "0".into()
    } else if v.abs() >= 1e7 {
        format!("{v:.2e}")
    } else if v.abs() >= 100.0 {
        format!("{v:.0}")
    } else if v.abs() >= 1.0 {
        format!("{v:.3}").trim_end_matches('0').trim_end_matches('.').into()
    } else {
        format!("{v:.2e}")
    }
}

/// What one contender did at one magnitude.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// The model refused the placed workload; the reason is its own error message.
    Refused(String),
    /// Measured.
    Measured {
        /// How it met the window.
        placement: Placement,
        /// Every metric, the family's headline first.
        metrics: Vec<Metric>,
    },
}

impl Outcome {
    /// The headline metric (the first), when measured.
    pub fn headline(&self) -> Option<&Metric> {
        match self {
            Outcome::Measured { metrics, .. } => metrics.first(),
            Outcome::Refused(_) => None,
        }
    }

    /// The metric named `name`, when measured.
    pub fn metric(&self, name: &str) -> Option<&Metric> {
        match self {
            Outcome::Measured { metrics, .. } => metrics.iter().find(|m| m.name() == name),
            Outcome::Refused(_) => None,
        }
    }
}

/// One contender of one workload at one magnitude.
#[derive(Debug, Clone, PartialEq)]
pub struct Cell {
    /// The magnitude.
    pub magnitude: Magnitude,
    /// The contender's name.
    pub contender: String,
    /// What happened.
    pub outcome: Outcome,
}

/// A contender's speed.
#[derive(Debug, Clone, PartialEq)]
pub enum SpeedOutcome {
    /// The model refused the workload at the origin.
    Refused(String),
    /// Timed.
    Measured {
        /// Median over the repetitions, in the workload's unit.
        median: f64,
        /// Slowest repetition.
        min: f64,
        /// Fastest repetition.
        max: f64,
        /// The median of prepare-and-draw from the exact scene (its conversion, snapping,
        /// the plan), where the contender has a preparation.
        with_prepare: Option<f64>,
        /// The work of one pass: covered pixels of the exact answer (primitives for
        /// clipping).
        elements: u64,
        /// Timed on the plain-oracle subset, not the whole workload.
        subset: bool,
    },
}

/// One contender of a workload: what it is and how fast it ran.
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedEntry {
    /// The contender's name (a model name, or `bresenham/step`, `cs-f32`, ...).
    pub contender: String,
    /// Exact or integer: must show no error wherever it accepts the workload.
    pub exact: bool,
    /// What its errors are counted against: `exact`, `exact-snapped`, or the exact check.
    pub reference: &'static str,
    /// Its speed.
    pub outcome: SpeedOutcome,
}

/// The planned engine's widths for a workload.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PlanSummary {
    /// `exact` or `exact-snapped`.
    pub model: &'static str,
    /// Primitives per width, narrowest first.
    pub by_width: Vec<(&'static str, usize)>,
    /// `model::plan::summary`'s line.
    pub summary: String,
}

/// One workload's trade.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkloadReport {
    /// Its name (`pixel triangles`, ...).
    pub name: String,
    /// Its family.
    pub family: Family,
    /// How it is built.
    pub description: String,
    /// Its primitives.
    pub primitives: usize,
    /// The speed unit: `Mpix/s`, or `Mprim/s` for clipping.
    pub unit: &'static str,
    /// The contender speeds are divided by.
    pub baseline: &'static str,
    /// Snapping moves no vertex (then the snapped models answer the scene as written).
    pub on_grid: bool,
    /// The planned engine's widths (none for Bresenham lines and clipping).
    pub plans: Vec<PlanSummary>,
    /// Every contender, with its speed at the origin.
    pub speed: Vec<SpeedEntry>,
    /// Every contender at every magnitude.
    pub cells: Vec<Cell>,
}

impl WorkloadReport {
    /// The median speed of `contender`, when measured.
    pub fn median(&self, contender: &str) -> Option<f64> {
        self.speed
            .iter()
            .find(|s| s.contender == contender)
            .and_then(|s| match s.outcome {
                SpeedOutcome::Measured { median, .. } => Some(median),
                SpeedOutcome::Refused(_) => None,
            })
    }

    /// `contender`'s median over the baseline's.
    pub fn ratio(&self, contender: &str) -> Option<f64> {
        Some(self.median(contender)? / self.median(self.baseline)?)
    }

    /// The cell of `contender` at `m`.
    pub fn cell(&self, contender: &str, m: Magnitude) -> Option<&Cell> {
        self.cells.iter().find(|c| c.contender == contender && c.magnitude == m)
    }

    /// The fastest contender that is exact for the workload as written at `m`: an exact
    /// contender measured there, with the unsnapped reference unless snapping moves
    /// nothing; with its median speed.
    pub fn cheapest_exact(&self, m: Magnitude) -> Option<(&str, f64)> {
        self.speed
            .iter()
            .filter(|s| s.exact && (self.on_grid || s.reference != "exact-snapped"))
            .filter(|s| matches!(self.cell(&s.contender, m), Some(c) if matches!(c.outcome, Outcome::Measured { .. })))
            .filter_map(|s| Some((s.contender.as_str(), self.median(&s.contender)?)))
            .max_by(|a, b| a.1.total_cmp(&b.1))
    }
}

/// A whole run.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// What was run.
    pub config: Config,
    /// The canvas (and window) side, px.
    pub canvas: u32,
    /// Timed repetitions per contender.
    pub repetitions: usize,
    /// Every workload, in family order.
    pub workloads: Vec<WorkloadReport>,
    /// Picture (c)'s data.
    pub predicate_map: PredicateMap,
}

impl Report {
    /// The pictures, PNG and SVG: `speed-vs-error`, `error-vs-magnitude`,
    /// `predicate-map` (see the module docs of [`crate::trade`]).
    ///
    /// # Errors
    /// Drawing fails (the compiled-in font unreadable, an encoder error).
    pub fn pictures(&self) -> Result<Vec<super::Picture>, String> {
        super::plot::pictures(self)
    }

    /// Every exact or integer contender's non-zero error: `workload / contender at M:
    /// metric count of N`. Empty when the exact models kept every promise.
    pub fn exact_errors(&self) -> Vec<String> {
        let mut out = Vec::new();
        for w in &self.workloads {
            for s in w.speed.iter().filter(|s| s.exact) {
                for c in w.cells.iter().filter(|c| c.contender == s.contender) {
                    if let Outcome::Measured { metrics, .. } = &c.outcome {
                        for m in metrics.iter().filter(|m| !m.is_zero()) {
                            out.push(format!(
                                "{} / {} at {}: {} {}",
                                w.name,
                                c.contender,
                                c.magnitude,
                                m.name(),
                                m.cell()
                            ));
                        }
                    }
                }
            }
        }
        out
    }

    /// Where each float contender starts to fail: per workload, contender and rate
    /// metric, the first magnitude with a non-zero count (`None`: never, at the magnitudes
    /// run), and the magnitudes at which it refused.
    pub fn onsets(&self) -> Vec<Onset> {
        let mut out = Vec::new();
        for w in &self.workloads {
            for s in w.speed.iter().filter(|s| !s.exact) {
                let cells: Vec<&Cell> = w.cells.iter().filter(|c| c.contender == s.contender).collect();
                let mut names: Vec<&'static str> = Vec::new();
                for c in &cells {
                    if let Outcome::Measured { metrics, .. } = &c.outcome {
                        for m in metrics.iter().filter(|m| matches!(m, Metric::Rate { .. })) {
                            if !names.contains(&m.name()) {
                                names.push(m.name());
                            }
                        }
                    }
                }
                for name in names {
                    let first = cells
                        .iter()
                        .find(|c| c.outcome.metric(name).is_some_and(|m| !m.is_zero()))
                        .map(|c| c.magnitude);
                    out.push(Onset {
                        workload: w.name.clone(),
                        contender: s.contender.clone(),
                        metric: name,
                        first,
                    });
                }
            }
        }
        out
    }

    /// One sentence per workload at the largest magnitude run: each float contender's
    /// headline error there, and the cheapest exact answer.
    pub fn headlines(&self) -> Vec<String> {
        let Some(&m) = self.config.magnitudes.last() else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for w in &self.workloads {
            let floats: Vec<String> = w
                .speed
                .iter()
                .filter(|s| !s.exact)
                .filter_map(|s| {
                    let c = w.cell(&s.contender, m)?;
                    Some(match &c.outcome {
                        Outcome::Refused(_) => format!("{} refuses it", s.contender),
                        Outcome::Measured { metrics, .. } => {
                            let h = metrics.first()?;
                            format!("{} has {} {} per million", s.contender, h.cell(), h.name())
                        }
                    })
                })
                .collect();
            let exact = match w.cheapest_exact(m) {
                Some((name, speed)) => {
                    let plan = w
                        .plans
                        .iter()
                        .find(|p| p.model == name || (name.starts_with(p.model) && !name.ends_with("plain")))
                        .map(|p| format!(" (planned widths: {})", widths_text(&p.by_width)))
                        .unwrap_or_default();
                    format!("exactly: {name} at {} {}{plan}", short(speed), w.unit)
                }
                None => "no exact contender takes it".into(),
            };
            let floats = if floats.is_empty() {
                "every contender is exact".to_string()
            } else {
                floats.join(", ")
            };
            out.push(format!("{} at {} px: {floats}; {exact}.", w.name, m));
        }
        out
    }
}

/// Where a float contender starts to fail on one metric.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Onset {
    /// The workload.
    pub workload: String,
    /// The contender.
    pub contender: String,
    /// The metric.
    pub metric: &'static str,
    /// The first magnitude with a non-zero count; `None` when none had one.
    pub first: Option<Magnitude>,
}

/// `1990 i32, 10 i64`.
fn widths_text(by_width: &[(&'static str, usize)]) -> String {
    by_width
        .iter()
        .map(|(w, n)| format!("{n} {w}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The JSON schema version.
pub const SCHEMA_VERSION: u64 = 1;

impl Report {
    /// The report as one JSON object, schema version 1:
    ///
    /// ```text
    /// {"format": "rasterproof trade report", "version": 1, "rasterproof": "0.1.0",
    ///  "quick": bool, "seed": u64, "canvas": side px, "repetitions": n,
    ///  "families": ["triangles", ...], "magnitudes": [{"label": "2^24", "px": 16777216}, ...],
    ///  "workloads": [{
    ///     "name", "family", "description", "primitives", "unit" ("Mpix/s" | "Mprim/s"),
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
    /// of opportunities: `wrong pixels` of the pixels the exact answer covers; `gaps`,
    /// `double covers` of the samples next to a shared mesh edge; `Gouraud channels off`
    /// of the channels sampled; `line pixels > 1/2 px off`, `line pixels off the
    /// reference` of the reference's line pixels; `clipped vertices outside` of the
    /// output vertices; `barycentric sums not exact` of the samples) or `{"metric",
    /// "kind": "ulps", "median", "max", "samples"}` (`barycentric sum error (ulps)`, in
    /// ulps of 1 of the model's float type). The first metric is the family's headline.
    pub fn to_json(&self) -> Value {
        let magnitudes: Vec<Value> = self
            .config
            .magnitudes
            .iter()
            .map(|m| json!({"label": m.label(), "px": m.px()}))
            .collect();
        let workloads: Vec<Value> = self.workloads.iter().map(|w| workload_json(w, &self.config)).collect();
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

fn workload_json(w: &WorkloadReport, config: &Config) -> Value {
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
                    obj.insert("metrics".into(), metrics.iter().map(Metric::to_json).collect());
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
    let cheapest: Vec<Value> = config
        .magnitudes
        .iter()
        .map(|&m| {
            let c = w.cheapest_exact(m);
            json!({"magnitude": m.label(), "contender": c.map(|c| c.0), "median": c.map(|c| c.1)})
        })
        .collect();
    json!({
        "name": w.name, "family": w.family.name(), "description": w.description,
        "primitives": w.primitives, "unit": w.unit, "baseline": w.baseline, "on_grid": w.on_grid,
        "plans": plans, "contenders": contenders, "errors": errors, "cheapest_exact": cheapest,
    })
}

impl Report {
    /// The tables in Markdown: per workload the speed (median, min-max, ratio to the
    /// baseline, the plan), the headline error by magnitude (`refused` with the reason
    /// below), the other metrics at each magnitude; then where the floats start to fail,
    /// and the headlines.
    pub fn to_markdown(&self) -> String {
        let mut s = String::new();
        let mags = &self.config.magnitudes;
        let _ = writeln!(
            s,
            "# The trade\n\n{} run, seed {}, canvas {}x{} px (the window at each magnitude), {} timed repetitions \
             per contender, round-robin. Errors are counted exactly against the planned exact engine on the same \
             scene (`exact` for models that do not snap, `exact-snapped` for those that do); rates are per million \
             (`0` is exactly zero); ulps are median/max.\n",
            if self.config.quick { "Quick" } else { "Full" },
            self.config.seed,
            self.canvas,
            self.canvas,
            self.repetitions
        );
        let _ = writeln!(s, "## Headlines\n");
        for h in self.headlines() {
            let _ = writeln!(s, "- {h}");
        }
        for w in &self.workloads {
            workload_markdown(&mut s, w, mags);
        }
        onsets_markdown(&mut s, &self.onsets(), mags);
        s
    }
}

fn workload_markdown(s: &mut String, w: &WorkloadReport, mags: &[Magnitude]) {
    let _ = writeln!(
        s,
        "\n## {} ({})\n\n{} {} primitives.",
        w.name, w.family, w.description, w.primitives
    );
    for p in &w.plans {
        let _ = writeln!(s, "Plan ({}): {}.", p.model, p.summary);
    }
    let _ = writeln!(
        s,
        "\n| contender | {u} median | min-max | / `{}` | {u} with prepare |",
        w.baseline,
        u = w.unit
    );
    let _ = writeln!(s, "|---|---|---|---|---|");
    for e in &w.speed {
        let (median, range, ratio, full) = match &e.outcome {
            SpeedOutcome::Refused(_) => ("refused".to_string(), String::new(), String::new(), String::new()),
            SpeedOutcome::Measured {
                median,
                min,
                max,
                subset,
                with_prepare,
                ..
            } => (
                format!("{}{}", short(*median), if *subset { " (subset)" } else { "" }),
                format!("{} - {}", short(*min), short(*max)),
                w.ratio(&e.contender).map(short).unwrap_or_default(),
                with_prepare.map(short).unwrap_or_default(),
            ),
        };
        let kind = if e.exact { "exact" } else { "inexact" };
        let _ = writeln!(
            s,
            "| `{}` ({kind}) | {median} | {range} | {ratio} | {full} |",
            e.contender
        );
    }
    // Errors: one table per metric name, contenders x magnitudes.
    let mut names: Vec<&'static str> = Vec::new();
    for c in &w.cells {
        if let Outcome::Measured { metrics, .. } = &c.outcome {
            for m in metrics {
                if !names.contains(&m.name()) {
                    names.push(m.name());
                }
            }
        }
    }
    let mut refusals: Vec<String> = Vec::new();
    for name in names {
        let unit = if name == super::measure::BARYCENTRIC_ULPS {
            "ulps median/max"
        } else {
            "per million"
        };
        let _ = writeln!(
            s,
            "\n| {name} ({unit}) | {} |",
            mags.iter().map(|m| format!("{m} px")).collect::<Vec<_>>().join(" | ")
        );
        let _ = writeln!(s, "|---|{}", "---|".repeat(mags.len()));
        for e in &w.speed {
            let cells: Vec<String> = mags
                .iter()
                .map(|&m| match w.cell(&e.contender, m).map(|c| &c.outcome) {
                    None => String::new(),
                    Some(Outcome::Refused(reason)) => {
                        let note = format!("`{}` at {m} px: {reason}", e.contender);
                        if !refusals.contains(&note) {
                            refusals.push(note);
                        }
                        "refused".into()
                    }
                    Some(o) => o.metric(name).map(Metric::cell).unwrap_or_default(),
                })
                .collect();
            let has_metric = w
                .cells
                .iter()
                .any(|c| c.contender == e.contender && c.outcome.metric(name).is_some());
            if !has_metric {
                continue;
            }
            let _ = writeln!(s, "| `{}` | {} |", e.contender, cells.join(" | "));
        }
    }
    if !refusals.is_empty() {
        let _ = writeln!(s, "\nRefused (the model's own message):\n");
        for r in refusals {
            let _ = writeln!(s, "- {r}");
        }
    }
    let cheapest: Vec<String> = mags
        .iter()
        .map(|&m| match w.cheapest_exact(m) {
            Some((name, v)) => format!("{m} px: `{name}` {} {}", short(v), w.unit),
            None => format!("{m} px: none"),
        })
        .collect();
    let _ = writeln!(s, "\nCheapest exact answer: {}.", cheapest.join("; "));
}

fn onsets_markdown(s: &mut String, onsets: &[Onset], mags: &[Magnitude]) {
    let _ = writeln!(
        s,
        "\n## Where the inexact contenders start to fail\n\nThe first magnitude (px from the origin) with a \
         non-zero count; `never` up to {} px.\n",
        mags.last().map(|m| m.label()).unwrap_or_default()
    );
    let _ = writeln!(s, "| workload | contender | metric | first fails at |");
    let _ = writeln!(s, "|---|---|---|---|");
    for o in onsets {
        let first = o.first.map_or_else(|| "never".to_string(), |m| format!("{m} px"));
        let _ = writeln!(s, "| {} | `{}` | {} | {first} |", o.workload, o.contender, o.metric);
    }
}
