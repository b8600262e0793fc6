//! The trade report as Markdown: [`TradeReport::to_markdown`], per workload its speed and
//! error tables, then where the inexact contenders start to fail.

use std::fmt::Write as _;

use super::{Onset, Outcome, SpeedOutcome, TradeReport, WorkloadReport};
use crate::trade::metric::{short, Metric};
use crate::trade::Family;

impl TradeReport {
    /// The tables in Markdown: per workload the speed (median, min-max, ratio to the
    /// baseline, the plan), the headline error by magnitude (`refused` with the reason
    /// below), the other metrics at each magnitude; then where the floats start to fail,
    /// and the headlines.
    pub fn to_markdown(&self) -> String {
        let mut s = String::new();
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
        if self.workloads.iter().any(|w| w.family == Family::Values) {
            let _ = writeln!(s, "\n{}", crate::trade::values::TABLES_NOTE);
        }
        for w in &self.workloads {
            workload_markdown(&mut s, w);
        }
        onsets_markdown(&mut s, &self.onsets());
        s
    }
}

fn workload_markdown(s: &mut String, w: &WorkloadReport) {
    let mags = &w.magnitudes();
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
    // Errors: one table per metric name, contenders x magnitudes, in the unit of the
    // metric's kind.
    let mut names: Vec<(&'static str, &'static str)> = Vec::new();
    for c in &w.cells {
        if let Outcome::Measured { metrics, .. } = &c.outcome {
            for m in metrics {
                if !names.iter().any(|&(n, _)| n == m.name()) {
                    names.push((m.name(), m.unit()));
                }
            }
        }
    }
    let mut refusals: Vec<String> = Vec::new();
    for (name, unit) in names {
        let _ = writeln!(
            s,
            "\n| {name} ({unit}) | {} |",
            mags.iter().map(|&m| w.axis.label(m)).collect::<Vec<_>>().join(" | ")
        );
        let _ = writeln!(s, "|---|{}", "---|".repeat(mags.len()));
        for e in &w.speed {
            let cells: Vec<String> = mags
                .iter()
                .map(|&m| match w.cell(&e.contender, m).map(|c| &c.outcome) {
                    None => String::new(),
                    Some(Outcome::Refused(reason)) => {
                        let note = format!("`{}` at {}: {reason}", e.contender, w.axis.label(m));
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
            Some((name, v)) => format!("{}: `{name}` {} {}", w.axis.label(m), short(v), w.unit),
            None => format!("{}: none", w.axis.label(m)),
        })
        .collect();
    let _ = writeln!(s, "\nCheapest exact answer: {}.", cheapest.join("; "));
}

fn onsets_markdown(s: &mut String, onsets: &[Onset]) {
    let _ = writeln!(
        s,
        "\n## Where the inexact contenders start to fail\n\nThe first magnitude (px from the origin, or the \
         attribute scale) with a non-zero count; `never`: none at the magnitudes its workload was run at.\n"
    );
    let _ = writeln!(s, "| workload | contender | metric | first fails at |");
    let _ = writeln!(s, "|---|---|---|---|");
    for o in onsets {
        let first = o.first.map_or_else(|| "never".to_string(), |m| o.axis.label(m));
        let _ = writeln!(s, "| {} | `{}` | {} | {first} |", o.workload, o.contender, o.metric);
    }
}
