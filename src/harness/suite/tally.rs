//! The suite's table: outcomes counted per invariant and model, the skipped checks with
//! their reasons, the summary lines and the legend.

use std::collections::BTreeMap;
use std::fmt;

use super::{legend, CaseRun};

/// One row of the table: an invariant checked on one model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Row {
    /// The invariant.
    pub invariant: &'static str,
    /// The model's label.
    pub label: &'static str,
    /// Cases on which the check ran.
    pub cases: u64,
    /// Cases on which it did not hold.
    pub violations: u64,
    /// Cases on which it could not run.
    pub skipped: u64,
}

/// The outcomes of a run of the suite, accumulated case by case, and the text
/// `rasterproof check` prints: a header, one row per (invariant, model) with its cases,
/// violations and skipped cases, the reasons for the skipped ones, the mesh violations by
/// family, the float32 barycentric sum error, the legend (one line per column, invariant
/// and model in the table: [`super::legend`]) and a verdict line.
///
/// ```
/// use rasterproof::harness::{generate, run_case, Tally};
/// let mut tally = Tally::new(3);
/// tally.add(&run_case(&generate(3, 0).unwrap()));
/// assert_eq!(tally.cases(), 1);
/// assert_eq!(tally.fatal(), 0);
/// assert!(tally.lines().iter().any(|l| l.starts_with("watertight               fixed")));
/// assert!(tally.lines().iter().any(|l| l.starts_with("  watertight               a mesh covers each sample")));
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Tally {
    seed: u64,
    cases: u64,
    /// (invariant, label) -> (outcomes, violations, skipped).
    rows: BTreeMap<(&'static str, &'static str), (u64, u64, u64)>,
    /// (invariant, label, reason) -> skipped cases.
    reasons: BTreeMap<(&'static str, &'static str, &'static str), u64>,
    /// (mesh family, label) -> mesh violations (watertight and mesh agreement).
    families: BTreeMap<(&'static str, &'static str), u64>,
    /// float32 barycentric sum errors, ulps of 1, in the order measured.
    ulps: Vec<f64>,
    /// Samples where the float32 sum error could not be measured.
    ulps_skipped: u64,
    /// Violations by a model that must hold.
    fatal: u64,
}

impl Tally {
    /// An empty tally of a run seeded `seed` (the seed is only named in the header).
    pub fn new(seed: u64) -> Tally {
        Tally {
            seed,
            ..Tally::default()
        }
    }

    /// Counts one case's outcomes and measurements.
    pub fn add(&mut self, run: &CaseRun) {
        self.cases += 1;
        self.ulps.extend_from_slice(&run.float32_sum_ulps);
        self.ulps_skipped += run.float32_sum_skipped;
        for s in &run.skipped {
            self.rows.entry((s.invariant, s.label)).or_default().2 += 1;
            *self.reasons.entry((s.invariant, s.label, s.reason)).or_default() += 1;
        }
        for o in &run.outcomes {
            let entry = self.rows.entry((o.invariant, o.label)).or_default();
            entry.0 += 1;
            if o.result.is_err() {
                entry.1 += 1;
                if o.invariant == "watertight" || o.invariant == "agreement (mesh)" {
                    *self.families.entry((run.mesh_family, o.label)).or_default() += 1;
                }
                if o.is_fatal() {
                    self.fatal += 1;
                }
            }
        }
    }

    /// Cases counted.
    pub fn cases(&self) -> u64 {
        self.cases
    }

    /// Violations by a model that must hold (see [`super::must_hold`]); the run fails when
    /// there is any.
    pub fn fatal(&self) -> u64 {
        self.fatal
    }

    /// Whether every must-hold model held every invariant.
    pub fn passed(&self) -> bool {
        self.fatal == 0
    }

    /// The rows of the table in order (by invariant, then label).
    pub fn rows(&self) -> impl Iterator<Item = Row> + '_ {
        self.rows
            .iter()
            .map(|(&(invariant, label), &(cases, violations, skipped))| Row {
                invariant,
                label,
                cases,
                violations,
                skipped,
            })
    }

    /// The skipped checks: invariant, label, reason and how many cases, in table order.
    pub fn skip_reasons(&self) -> impl Iterator<Item = (&'static str, &'static str, &'static str, u64)> + '_ {
        self.reasons
            .iter()
            .map(|(&(invariant, label, reason), &n)| (invariant, label, reason, n))
    }

    /// The legend, one line per column, invariant and model label that this table shows
    /// (see [`legend::describe`]), under a heading line.
    pub fn legend(&self) -> Vec<String> {
        let mut names: Vec<&str> = vec!["cases", "violations", "skipped"];
        if !self.families.is_empty() {
            names.push("by family");
        }
        if !self.ulps.is_empty() {
            names.push("ulps of 1");
        }
        let mut invariants: Vec<&str> = self.rows.keys().map(|&(i, _)| i).collect();
        invariants.dedup();
        let mut labels: Vec<&str> = self.rows.keys().map(|&(_, l)| l).collect();
        labels.sort_unstable();
        labels.dedup();
        let mut lines = vec!["legend:".to_string()];
        for (heading, group) in [("columns", names), ("invariants", invariants), ("models", labels)] {
            lines.push(format!(" {heading}:"));
            for name in group {
                let text = legend::describe(name).unwrap_or("(not described)");
                lines.push(format!("  {name:<24} {text}"));
            }
        }
        lines
    }

    /// The report, one string per line (no newlines): what `rasterproof check` prints.
    pub fn lines(&self) -> Vec<String> {
        let mut lines = vec![
            format!(
                "rasterproof check: {} cases, seed {}, presets d3d11/gl",
                self.cases, self.seed
            ),
            format!(
                "{:<24} {:<18} {:>7} {:>10} {:>7}",
                "invariant", "model", "cases", "violations", "skipped"
            ),
        ];
        for r in self.rows() {
            lines.push(format!(
                "{:<24} {:<18} {:>7} {:>10} {:>7}",
                r.invariant, r.label, r.cases, r.violations, r.skipped
            ));
        }
        if !self.reasons.is_empty() {
            lines.push("skipped (the check could not run on the case):".to_string());
            for (invariant, label, reason, n) in self.skip_reasons() {
                lines.push(format!("  {invariant:<22} {label:<18} {n:>5}: {reason}"));
            }
        }
        if !self.families.is_empty() {
            lines.push("mesh violations by family:".to_string());
            for ((family, model), n) in &self.families {
                lines.push(format!("  {family:<22} {model:<18} {n:>5}"));
            }
        }
        if !self.ulps.is_empty() {
            let mut ulps = self.ulps.clone();
            ulps.sort_by(f64::total_cmp);
            // Summed in sorted order, as the report always has been.
            let mean = ulps.iter().sum::<f64>() / ulps.len() as f64;
            let skipped = match self.ulps_skipped {
                0 => String::new(),
                n => format!(", {n} skipped: the triangle has zero area in f32 or does not fit it"),
            };
            lines.push(format!(
                "float32 barycentric sum error, ulps of 1 ({} samples{skipped}): median {:.1}, mean {:.1}, max {:.1}",
                ulps.len(),
                ulps[ulps.len() / 2],
                mean,
                ulps[ulps.len() - 1]
            ));
        } else if self.ulps_skipped > 0 {
            lines.push(format!(
                "float32 barycentric sum error: not measured ({} samples skipped: the triangle has zero area in f32 or does not fit it)",
                self.ulps_skipped
            ));
        }
        lines.extend(self.legend());
        lines.push(if self.fatal > 0 {
            format!(
                "FAILED: {} violations by an exact or integer model (exact, exact-snapped, fixed, scanline)",
                self.fatal
            )
        } else {
            "ok: the exact and integer models (exact, exact-snapped, fixed, scanline) hold every invariant".to_string()
        });
        lines
    }
}

/// The report's [lines](Tally::lines), each ending in a newline.
impl fmt::Display for Tally {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for line in self.lines() {
            writeln!(f, "{line}")?;
        }
        Ok(())
    }
}
