//! The values family's pictures: error against canvas offset and against attribute
//! scale (the largest and the 99th percentile of the ulps, and the wrong UNORM8 levels, one
//! line per contender), and speed against error at the origin and at 2^24 px, with the
//! Pareto front.

use plotters::prelude::*;

use super::charts::{magnitude_panel, speed_error_panel, YAxis};
use super::{frame, legend, legend_entries, Area};
use crate::trade::report::{Axis, SpeedOutcome, TradeReport, WorkloadReport};
use crate::trade::values::{ULPS, WRONG_UNORM};
use crate::trade::{Family, Magnitude, Metric};

/// An error of 0 ulps is drawn here, on the tick labelled `0` (the smallest non-zero error
/// is 1).
const ULPS_ZERO: f64 = 0.1;
/// A rate of 0 per million is drawn here; non-zero rates below [`RATE_SMALLEST`] at it.
const RATE_ZERO: f64 = 0.1;
const RATE_SMALLEST: f64 = 0.2;

/// The values workloads on `axis`.
fn workloads_on(r: &TradeReport, axis: Axis) -> Vec<&WorkloadReport> {
    r.workloads
        .iter()
        .filter(|w| w.family == Family::Values && w.axis == axis)
        .collect()
}

/// The ulps' tail of `contender` at `m`, through `pick` (`p99` or `max`); 0 at
/// [`ULPS_ZERO`].
fn tail(w: &WorkloadReport, contender: &str, m: Magnitude, pick: fn(f64, f64) -> f64) -> Option<f64> {
    match w.cell(contender, m)?.outcome.metric(ULPS)? {
        Metric::UlpTail { p99, max, .. } => {
            let v = pick(*p99, *max);
            Some(if v == 0.0 { ULPS_ZERO } else { v })
        }
        _ => None,
    }
}

fn max_ulps(w: &WorkloadReport, contender: &str, m: Magnitude) -> Option<f64> {
    tail(w, contender, m, |_, max| max)
}

fn p99_ulps(w: &WorkloadReport, contender: &str, m: Magnitude) -> Option<f64> {
    tail(w, contender, m, |p99, _| p99)
}

/// Wrong UNORM8 levels per million values; 0 at [`RATE_ZERO`].
fn wrong_levels(w: &WorkloadReport, contender: &str, m: Magnitude) -> Option<f64> {
    let metric = w.cell(contender, m)?.outcome.metric(WRONG_UNORM)?;
    Some(if metric.is_zero() {
        RATE_ZERO
    } else {
        metric.per_million()?.max(RATE_SMALLEST)
    })
}

/// The ulps axis: 0 to 2^34 (a NaN counts 2^32).
fn ulps_axis(value: fn(&WorkloadReport, &str, Magnitude) -> Option<f64>, what: &str) -> YAxis {
    YAxis {
        value,
        bottom: 0.05,
        top: 2e10,
        zero: ULPS_ZERO,
        cross: 8e9,
        desc: format!("{what} ulps from the correctly rounded f32 (log)"),
    }
}

fn axes() -> [YAxis; 3] {
    [
        ulps_axis(max_ulps, "largest:"),
        ulps_axis(p99_ulps, "99th percentile:"),
        YAxis {
            value: wrong_levels,
            bottom: 0.06,
            top: 4e6,
            zero: RATE_ZERO,
            cross: 1.5e6,
            desc: "wrong UNORM8 levels per million values".into(),
        },
    ]
}

/// Error against the magnitudes of `axis`: one column per workload, the largest ulps, the
/// 99th percentile and the wrong UNORM8 levels in three rows.
pub(super) fn error_by<DB: DrawingBackend>(root: &Area<DB>, r: &TradeReport, axis: Axis) -> Result<(), String> {
    let workloads = workloads_on(r, axis);
    let title = match axis {
        Axis::Offset => "Interpolated values: error against canvas offset (every coordinate moved by (M, M)), one line per contender",
        Axis::AttributeScale => "Interpolated values: error against attribute scale (every value times 2^k, the window at the origin)",
    };
    let cols = workloads.len().max(1);
    let (panels, bottom) = frame(root, title, 26, (3, cols))?;
    for (row, y) in axes().iter().enumerate() {
        for (k, w) in workloads.iter().enumerate() {
            magnitude_panel(&panels[row * cols + k], w, y)?;
        }
    }
    let note = match axis {
        Axis::Offset => {
            "Rows: the largest and the 99th percentile of the f32 steps from the exact value's nearest f32 (log; 0 is \
             exactly it; a NaN counts 2^32), and the values whose UNORM8 level (round to nearest, ties to even) \
             differs from that f32's, per million. Every contender computes with the placed coordinates.\nFrom 2^16 \
             px the vertex plane, the barycentrics and f64 coincide: all read f32 positions, which hold 1/256 px only \
             below 2^16 px. Circles: exact contenders; triangles: float and fixed-point models."
        }
        Axis::AttributeScale => {
            "Rows as in the offset picture; UNORM8 levels of the value divided by the scale. Scaling by a power of two \
             commutes with every float rounding, so the float models' lines are flat;\nthe fixed-point DDA's precision \
             is absolute (2^-32): its error in ulps falls as the values grow, until its Q32.32 envelope refuses them \
             (a cross near the top)."
        }
    };
    legend(&bottom, &legend_entries(&workloads), 7, note)
}

/// Speed against the largest error in ulps, per offset workload at the origin (top row)
/// and at the largest offset (bottom row), the Pareto front ringed and joined.
pub(super) fn speed_error<DB: DrawingBackend>(root: &Area<DB>, r: &TradeReport) -> Result<(), String> {
    let workloads = workloads_on(r, Axis::Offset);
    let cols = workloads.len().max(1);
    let (panels, bottom) = frame(
        root,
        "Interpolated values: speed against the largest error, at the origin (above) and at the largest offset \
         (below); ringed and joined in black: the Pareto front",
        24,
        (2, cols),
    )?;
    let y = ulps_axis(max_ulps, "largest:");
    // The plain definition (thousands of pixels a second, on a subset) left out, so that
    // the others, within a factor of a few of each other, separate.
    let shown: Vec<WorkloadReport> = workloads
        .iter()
        .map(|&w| {
            let mut w = w.clone();
            w.speed
                .retain(|s| !matches!(s.outcome, SpeedOutcome::Measured { subset: true, .. }));
            w
        })
        .collect();
    for (k, w) in shown.iter().enumerate() {
        let mags = w.magnitudes();
        for (row, m) in [mags.first(), mags.last()].into_iter().enumerate() {
            if let Some(&m) = m {
                speed_error_panel(&panels[row * cols + k], w, m, &y)?;
            }
        }
    }
    legend(
        &bottom,
        &legend_entries(&shown.iter().collect::<Vec<_>>()),
        7,
        "Speed: every contender over the origin's covered pixels, three channels each, set up per triangle from \
         inputs in its own number type; median of the round-robin repetitions. Not shown: exact-plain, the readable \
         definition in big rationals,\nat 0.01 Mpix/s on a subset. Error: the largest f32 steps from the correctly \
         rounded value (log; 0 is exactly it; a NaN counts 2^32).",
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trade::Outcome;

    #[test]
    fn zero_ulps_are_drawn_on_the_zero_tick() {
        let w = WorkloadReport {
            name: "w".into(),
            family: Family::Values,
            description: String::new(),
            primitives: 1,
            unit: "Mpix/s",
            baseline: "f32-origin-plane",
            on_grid: true,
            plans: Vec::new(),
            speed: Vec::new(),
            cells: vec![crate::trade::Cell {
                magnitude: Magnitude::new(0).unwrap(),
                contender: "planned".into(),
                outcome: Outcome::Measured {
                    placement: crate::trade::Placement::OnCanvas,
                    metrics: vec![
                        Metric::UlpTail {
                            name: ULPS,
                            p99: 0.0,
                            max: 3.0,
                            samples: 10,
                        },
                        Metric::Rate {
                            name: WRONG_UNORM,
                            count: 0,
                            of: 10,
                        },
                    ],
                },
            }],
            axis: Axis::Offset,
        };
        let m = Magnitude::new(0).unwrap();
        assert_eq!(max_ulps(&w, "planned", m), Some(3.0));
        assert_eq!(p99_ulps(&w, "planned", m), Some(ULPS_ZERO));
        assert_eq!(wrong_levels(&w, "planned", m), Some(RATE_ZERO));
        assert_eq!(max_ulps(&w, "dda-q32.32", m), None);
    }
}
