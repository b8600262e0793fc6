//! Pictures (a) and (b) of the trade: speed against error per workload with the Pareto
//! front, and error against coordinate magnitude, one line per contender; each for the
//! binary models' workloads and again for the area family's (whose picture (b) also shows
//! the largest coverage error in quanta).

use plotters::coord::ranged1d::ValueFormatter;
use plotters::prelude::*;

use super::{colour, err, frame, legend, legend_entries, Area, SANS};
use crate::trade::report::{Axis, Outcome, SpeedOutcome, TradeReport, WorkloadReport};
use crate::trade::{Family, Magnitude};

/// A rate of 0 is drawn here, on the tick labelled `0`.
const ZERO: f64 = 0.1;
/// Non-zero rates below it are drawn at it, so that none sits on the `0` line.
const SMALLEST: f64 = 0.2;
/// The log axes' ends (per million).
const BOTTOM: f64 = 0.06;
const TOP: f64 = 4e6;

fn speed_label(v: f64) -> String {
    if v >= 1.0 || v == 0.0 {
        format!("{v:.0}")
    } else {
        format!("{v:.1e}")
    }
}

/// A workload's headline rate per million at `m` for `contender` (`None`: refused or
/// not run).
pub(super) fn headline(w: &WorkloadReport, contender: &str, m: Magnitude) -> Option<f64> {
    let c = w.cell(contender, m)?;
    match &c.outcome {
        Outcome::Refused(_) => None,
        Outcome::Measured { metrics, .. } => {
            let h = metrics.first()?;
            Some(if h.is_zero() {
                ZERO
            } else {
                h.per_million().unwrap_or(0.0).max(SMALLEST)
            })
        }
    }
}

/// The magnitude picture (a) shows: the largest run at or below 2^20 px (fixed's
/// envelope), else the smallest run.
pub(crate) fn speed_error_magnitude(r: &TradeReport) -> Magnitude {
    let limit = 1u64 << 20;
    r.config
        .magnitudes
        .iter()
        .rev()
        .find(|m| m.px() <= limit)
        .or(r.config.magnitudes.first())
        .copied()
        .unwrap_or(Magnitude::DEFAULT[0])
}

fn grid_shape(n: usize) -> (usize, usize) {
    let cols = if n <= 4 { n.max(1) } else { 4 };
    (n.div_ceil(cols).max(1), cols)
}

/// The workloads of the area family (`area`) or of the binary families (every family but
/// `area` and `values`, which draw their own).
pub(super) fn workloads_of(r: &TradeReport, area: bool) -> Vec<&WorkloadReport> {
    r.workloads
        .iter()
        .filter(|w| match w.family {
            Family::Area => area,
            Family::Values => false,
            _ => !area,
        })
        .collect()
}

/// The name of a workload's headline metric (its first).
fn headline_name(w: &WorkloadReport) -> &'static str {
    w.cells
        .iter()
        .find_map(|c| c.outcome.headline().map(|h| h.name()))
        .unwrap_or("errors")
}

/// Picture (a): the binary models' workloads, or (`area`) the area family's.
pub(super) fn speed_error<DB: DrawingBackend>(root: &Area<DB>, r: &TradeReport, area: bool) -> Result<(), String> {
    let m = speed_error_magnitude(r);
    let workloads = workloads_of(r, area);
    let what = if area { "Area coverage: speed" } else { "Speed" };
    let title = format!(
        "{what} against error at {m} px from the origin, per workload: each contender a point; ringed and joined \
         in black: the Pareto front"
    );
    let (panels, bottom) = frame(root, &title, 26, grid_shape(workloads.len()))?;
    for (panel, w) in panels.iter().zip(workloads.iter().copied()) {
        speed_error_panel(panel, w, m, &YAxis::headline(headline_name(w)))?;
    }
    let note = if area {
        "Circles: exact models; triangles: the contenders. Speed: each model's own function at the origin, median of \
         the round-robin repetitions.\nError: pixels whose coverage is off the exact value by more than 1/2 quantum \
         (1/510), per million pixels that the exact answer or the model covers; 0 is exactly zero."
    } else {
        "Circles: exact and integer models; triangles: float models. Speed: drawing the prepared workload at the \
         origin, median of the round-robin repetitions.\nError: per million pixels the exact answer or the model covers (lines: \
         line pixels; clipping: output vertices); 0 is exactly zero. A refused contender is not drawn."
    };
    legend(&bottom, &legend_entries(&workloads), 6, note)
}

/// One workload's panel of picture (a): each contender's speed against its error on `axis`
/// at magnitude `m`, the Pareto front ringed and joined (a values workload's caption
/// names `m`).
pub(super) fn speed_error_panel<DB: DrawingBackend>(
    panel: &Area<DB>,
    w: &WorkloadReport,
    m: Magnitude,
    axis: &YAxis,
) -> Result<(), String> {
    let error = |contender: &str| (axis.value)(w, contender, m);
    let points: Vec<(String, f64, f64, bool)> = w
        .speed
        .iter()
        .filter_map(|s| match s.outcome {
            SpeedOutcome::Measured { median, .. } if median > 0.0 => {
                Some((s.contender.clone(), median, error(&s.contender)?, s.exact))
            }
            _ => None,
        })
        .collect();
    let refused: Vec<&str> = w
        .speed
        .iter()
        .filter(|s| error(&s.contender).is_none())
        .map(|s| s.contender.as_str())
        .collect();
    let lo = points.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
    let hi = points.iter().map(|p| p.1).fold(0.0, f64::max);
    let name = match w.axis {
        Axis::Offset if w.family == Family::Values => format!("{} at {m} px", w.name),
        _ => w.name.clone(),
    };
    let caption = if refused.is_empty() {
        name
    } else {
        format!("{name} (refused: {})", refused.join(", "))
    };
    let builder = |panel| {
        let mut b = ChartBuilder::on(panel);
        b.caption(caption.clone(), (SANS, 16))
            .margin(10)
            .x_label_area_size(44)
            .y_label_area_size(64);
        b
    };
    let y = (axis.bottom..axis.top).log_scale();
    if lo.is_finite() && hi > 0.0 && hi <= 10.0 * lo {
        // Speeds within a factor of 10 of each other: a linear axis from 0, where they
        // spread over the panel and their ratios read as lengths.
        let chart = builder(panel).build_cartesian_2d(0.0..hi * 1.15, y).map_err(err)?;
        speed_error_points(chart, &points, axis, &format!("speed, {}", w.unit))
    } else {
        let (lo, hi) = if lo.is_finite() && hi > 0.0 {
            (lo / 3.0, hi * 3.0)
        } else {
            (1e-3, 1e3)
        };
        let chart = builder(panel)
            .build_cartesian_2d((lo..hi).log_scale(), y)
            .map_err(err)?;
        speed_error_points(chart, &points, axis, &format!("speed, {} (log)", w.unit))
    }
}

/// Picture (a)'s panel on its axes: the mesh, the Pareto front ringed and joined, and
/// each contender's point.
fn speed_error_points<DB: DrawingBackend, X>(
    mut chart: ChartContext<'_, DB, Cartesian2d<X, LogCoord<f64>>>,
    points: &[(String, f64, f64, bool)],
    axis: &YAxis,
    x_desc: &str,
) -> Result<(), String>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let zero = axis.zero;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(axis.desc.clone())
        .x_labels(5)
        .y_labels(8)
        .x_label_formatter(&|v| speed_label(*v))
        .y_label_formatter(&|v| axis_label(*v, zero))
        .axis_desc_style((SANS, 14))
        .label_style((SANS, 12))
        .draw()
        .map_err(err)?;
    let front = pareto_front(points);
    let mut steps = Vec::new();
    for (k, &(s, e)) in front.iter().enumerate() {
        if k > 0 {
            steps.push((s, front[k - 1].1));
        }
        steps.push((s, e));
    }
    chart
        .draw_series(LineSeries::new(steps, BLACK.stroke_width(2)))
        .map_err(err)?;
    for &(s, e) in &front {
        chart
            .draw_series(std::iter::once(Circle::new((s, e), 11, BLACK.stroke_width(2))))
            .map_err(err)?;
    }
    for (name, s, e, exact) in points {
        let c = colour(name);
        if *exact {
            chart.draw_series(std::iter::once(Circle::new((*s, *e), 6, c.filled())))
        } else {
            chart.draw_series(std::iter::once(TriangleMarker::new((*s, *e), 8, c.filled())))
        }
        .map_err(err)?;
    }
    Ok(())
}

/// The Pareto front of (name, speed, error, exact) points as (speed, error): fastest
/// first, keeping each point with less error than every faster one.
fn pareto_front(points: &[(String, f64, f64, bool)]) -> Vec<(f64, f64)> {
    let mut sorted = points.to_vec();
    sorted.sort_by(|a, b| b.1.total_cmp(&a.1));
    let mut front: Vec<(f64, f64)> = Vec::new();
    for p in &sorted {
        let better = match front.last() {
            None => true,
            Some(&(_, e)) => p.2 < e,
        };
        if better {
            front.push((p.1, p.2));
        }
    }
    front
}

/// A y axis of picture (b): what it shows and its log range.
pub(super) struct YAxis {
    /// The value of a contender at a magnitude (`None`: refused or not run); an exact zero
    /// is [`YAxis::zero`].
    pub(super) value: fn(&WorkloadReport, &str, Magnitude) -> Option<f64>,
    /// The axis's ends.
    pub(super) bottom: f64,
    pub(super) top: f64,
    /// Where zero is drawn (labelled `0`).
    pub(super) zero: f64,
    /// Where the refusal crosses start.
    pub(super) cross: f64,
    /// Its description.
    pub(super) desc: String,
}

impl YAxis {
    /// The headline rate per million, as the binary workloads' panels show it.
    pub(super) fn headline(first: &str) -> YAxis {
        YAxis {
            value: headline,
            bottom: BOTTOM,
            top: TOP,
            zero: ZERO,
            cross: 1.5e6,
            desc: format!("{first} per million"),
        }
    }
}

/// The largest coverage error in quanta of 1/255 at `m` (the area family's
/// [`Metric::Quanta`](crate::trade::Metric::Quanta)); zero at [`QUANTA_ZERO`].
pub(super) fn max_quanta(w: &WorkloadReport, contender: &str, m: Magnitude) -> Option<f64> {
    let c = w.cell(contender, m)?;
    match &c.outcome {
        Outcome::Refused(_) => None,
        Outcome::Measured { metrics, .. } => metrics.iter().find_map(|x| match x {
            crate::trade::Metric::Quanta { max, .. } if *max == 0.0 => Some(QUANTA_ZERO),
            crate::trade::Metric::Quanta { max, .. } => Some(max.max(QUANTA_SMALLEST)),
            _ => None,
        }),
    }
}

/// A coverage error of 0 quanta is drawn here; non-zero errors below
/// [`QUANTA_SMALLEST`] at it.
pub(super) const QUANTA_ZERO: f64 = 1e-7;
const QUANTA_SMALLEST: f64 = 2e-7;

/// A y axis's tick: `0` at `zero`, nothing below it, whole numbers from 1 (`1e5` and up as
/// powers of ten), one significant digit below 1.
fn axis_label(v: f64, zero: f64) -> String {
    if (v / zero - 1.0).abs() < 1e-6 {
        "0".into()
    } else if v < zero {
        String::new()
    } else if v >= 1e5 {
        format!("{v:.0e}")
    } else if v >= 1.0 {
        format!("{v:.0}")
    } else {
        format!("{v:.0e}")
    }
}

/// One panel of picture (b): `w`'s contenders over the magnitudes it was measured at, on
/// `axis`.
pub(super) fn magnitude_panel<DB: DrawingBackend>(
    panel: &Area<DB>,
    w: &WorkloadReport,
    axis: &YAxis,
) -> Result<(), String> {
    let mags = &w.magnitudes();
    let labels: Vec<String> = mags.iter().map(|m| m.label()).collect();
    let n = mags.len();
    let last = u32::try_from(n.saturating_sub(1)).map_err(err)?;
    let mut chart = ChartBuilder::on(panel)
        .caption(w.name.clone(), (SANS, 16))
        .margin(10)
        .x_label_area_size(44)
        .y_label_area_size(64)
        .build_cartesian_2d((0u32..last).into_segmented(), (axis.bottom..axis.top).log_scale())
        .map_err(err)?;
    let label_of = |v: &SegmentValue<u32>| match v {
        SegmentValue::CenterOf(i) | SegmentValue::Exact(i) => labels
            .get(usize::try_from(*i).unwrap_or(usize::MAX))
            .cloned()
            .unwrap_or_default(),
        SegmentValue::Last => String::new(),
    };
    let zero = axis.zero;
    let x_desc = match w.axis {
        Axis::Offset => "magnitude M, px (2^k)",
        Axis::AttributeScale => "attribute scale: every value times 2^k",
    };
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(axis.desc.clone())
        .x_labels(n)
        .y_labels(8)
        .x_label_formatter(&label_of)
        .y_label_formatter(&|v| axis_label(*v, zero))
        .axis_desc_style((SANS, 14))
        .label_style((SANS, 12))
        .draw()
        .map_err(err)?;
    let mut refusing = 0;
    for s in &w.speed {
        let c = colour(&s.contender);
        let mut run: Vec<(SegmentValue<u32>, f64)> = Vec::new();
        let any_refused = w
            .cells
            .iter()
            .any(|c| c.contender == s.contender && matches!(c.outcome, Outcome::Refused(_)));
        // Each refusing contender's crosses a little lower than the last one's.
        let cross_y = axis.cross / 2f64.powi(refusing);
        if any_refused {
            refusing += 1;
        }
        let mut runs = Vec::new();
        for (k, &m) in mags.iter().enumerate() {
            let x = SegmentValue::CenterOf(u32::try_from(k).map_err(err)?);
            match w.cell(&s.contender, m).map(|c| &c.outcome) {
                Some(Outcome::Measured { .. }) => {
                    run.push((x, (axis.value)(w, &s.contender, m).unwrap_or(axis.zero)));
                }
                Some(Outcome::Refused(_)) => {
                    runs.push(std::mem::take(&mut run));
                    chart
                        .draw_series(std::iter::once(Cross::new((x, cross_y), 7, c.stroke_width(3))))
                        .map_err(err)?;
                }
                None => runs.push(std::mem::take(&mut run)),
            }
        }
        runs.push(run);
        for line in runs.into_iter().filter(|l| !l.is_empty()) {
            let width = if s.exact { 2 } else { 3 };
            chart
                .draw_series(LineSeries::new(line.clone(), c.stroke_width(width)))
                .map_err(err)?;
            for p in line {
                if s.exact {
                    chart.draw_series(std::iter::once(Circle::new(p, 4, c.filled())))
                } else {
                    chart.draw_series(std::iter::once(TriangleMarker::new(p, 6, c.filled())))
                }
                .map_err(err)?;
            }
        }
    }
    Ok(())
}

/// Picture (b): the binary models' workloads, one panel each on the headline rate.
pub(super) fn error_magnitude<DB: DrawingBackend>(root: &Area<DB>, r: &TradeReport) -> Result<(), String> {
    let workloads = workloads_of(r, false);
    let (panels, bottom) = frame(
        root,
        "Error against coordinate magnitude (the window at M px from the origin), one line per contender",
        26,
        grid_shape(workloads.len()),
    )?;
    for (panel, w) in panels.iter().zip(workloads.iter().copied()) {
        magnitude_panel(panel, w, &YAxis::headline(headline_name(w)))?;
    }
    legend(
        &bottom,
        &legend_entries(&workloads),
        6,
        "A cross near the top: the model refuses the workload there (integer envelope, Bresenham endpoints beyond \
         2^24, float range). Error per million as in the tables; 0 is exactly zero.",
    )
}

/// The area picture of error against magnitude: one column per area workload, the
/// pixels off by more than half a quantum per million above, the largest coverage error
/// in quanta of 1/255 below.
pub(super) fn area_error_magnitude<DB: DrawingBackend>(root: &Area<DB>, r: &TradeReport) -> Result<(), String> {
    let workloads = workloads_of(r, true);
    let cols = workloads.len().max(1);
    let (panels, bottom) = frame(
        root,
        "Area coverage: error against coordinate magnitude (the window at M px from the origin), one line per \
         contender",
        26,
        (2, cols),
    )?;
    let quanta = YAxis {
        value: max_quanta,
        bottom: 3e-8,
        top: 1e5,
        zero: QUANTA_ZERO,
        cross: 5e4,
        desc: "largest coverage error, quanta of 1/255".into(),
    };
    for (k, w) in workloads.iter().enumerate() {
        let rate = YAxis::headline(crate::trade::area::OFF_HALF_QUANTUM);
        magnitude_panel(&panels[k], w, &rate)?;
        magnitude_panel(&panels[cols + k], w, &quanta)?;
    }
    legend(
        &bottom,
        &legend_entries(&workloads),
        7,
        "Above: pixels off the exact coverage by more than 1/2 quantum (1/510) per million covered; below: the \
         largest error in quanta of 1/255 (log; 0 is exactly zero). Circles: exact models; triangles: the contenders.\n\
         A cross near the top: refused (ftgrays's 24.8 envelope ends at 2^23 px). Exact models, supersampling and \
         multisampling: translation-invariant, measured at the origin; f32 and ftgrays: computed at the placed coordinates.",
    )
}
