//! A trade run's result: per workload its contenders' speed, its plan and its errors at
//! every magnitude; written as JSON ([`TradeReport::to_json`], the documented schema: `json`),
//! as Markdown tables ([`TradeReport::to_markdown`]: `markdown`) and as pictures
//! ([`TradeReport::pictures`], drawn beside the plotting code in `trade::plot`).

mod json;
mod markdown;

use super::metric::{short, Metric};
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

/// What a workload's magnitudes measure: the x axis of its tables and pictures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Axis {
    /// The window's distance from the origin, px: every coordinate moved by `(M, M)`.
    Offset,
    /// The factor every attribute value is multiplied by (exactly: a power of two), the
    /// window at the origin (the values family's attribute sweep).
    AttributeScale,
}

impl Axis {
    /// The name in the report: `canvas offset` or `attribute scale`.
    pub fn name(self) -> &'static str {
        match self {
            Axis::Offset => "canvas offset",
            Axis::AttributeScale => "attribute scale",
        }
    }

    /// A magnitude on this axis as a table's header writes it: `2^24 px`, or `x 2^8`.
    pub fn label(self, m: Magnitude) -> String {
        match self {
            Axis::Offset => format!("{m} px"),
            Axis::AttributeScale => format!("x {m}"),
        }
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
    /// What the cells' magnitudes measure.
    pub axis: Axis,
}

impl WorkloadReport {
    /// The magnitudes its cells were measured at, ascending (the run's for every family but
    /// `values`, which has its own: [`crate::trade::values`]).
    pub fn magnitudes(&self) -> Vec<Magnitude> {
        let mut out: Vec<Magnitude> = self.cells.iter().map(|c| c.magnitude).collect();
        out.sort_unstable();
        out.dedup();
        out
    }

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
pub struct TradeReport {
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

impl TradeReport {
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
                        axis: w.axis,
                    });
                }
            }
        }
        out
    }

    /// One sentence per workload at the largest magnitude it was run at: each float
    /// contender's headline error there, and the cheapest exact answer.
    pub fn headlines(&self) -> Vec<String> {
        let mut out = Vec::new();
        for w in &self.workloads {
            let Some(&m) = w.magnitudes().last() else {
                continue;
            };
            let floats: Vec<String> = w
                .speed
                .iter()
                .filter(|s| !s.exact)
                .filter_map(|s| {
                    let c = w.cell(&s.contender, m)?;
                    Some(match &c.outcome {
                        Outcome::Refused(_) => format!("{} refuses it", s.contender),
                        Outcome::Measured { metrics, .. } => match metrics.first()? {
                            h @ Metric::Rate { .. } => {
                                format!("{} has {} {} per million", s.contender, h.cell(), h.name())
                            }
                            h @ Metric::UlpTail { .. } => {
                                format!("{} is off by {} {}", s.contender, h.cell(), h.unit())
                            }
                            h => format!("{} shows {} {} ({})", s.contender, h.name(), h.cell(), h.unit()),
                        },
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
            out.push(format!("{} at {}: {floats}; {exact}.", w.name, w.axis.label(m)));
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
    /// What the magnitude measures.
    pub axis: Axis,
}

/// `1990 i32, 10 i64`.
fn widths_text(by_width: &[(&'static str, usize)]) -> String {
    by_width
        .iter()
        .map(|(w, n)| format!("{n} {w}"))
        .collect::<Vec<_>>()
        .join(", ")
}
