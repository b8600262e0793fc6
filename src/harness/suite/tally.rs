//! The suite's table: outcomes counted per invariant and model, and the summary lines.

use std::collections::BTreeMap;
use std::fmt;

use super::CaseRun;

/// The outcomes of a run of the suite, accumulated case by case, and the text
/// `rasterproof check` prints: a header, one row per (invariant, model) with its cases and
/// violations, the mesh violations by family, the float32 barycentric sum error, and a
/// verdict line.
///
/// ```
/// use rasterproof::harness::{generate, run_case, Tally};
/// let mut tally = Tally::new(3);
/// tally.add(&run_case(&generate(3, 0).unwrap()));
/// assert_eq!(tally.cases(), 1);
/// assert_eq!(tally.fatal(), 0);
/// assert!(tally.lines().iter().any(|l| l.starts_with("watertight               fixed")));
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Tally {
    seed: u64,
    cases: u64,
    /// (invariant, label) -> (outcomes, violations).
    rows: BTreeMap<(&'static str, &'static str), (u64, u64)>,
    /// (mesh family, label) -> mesh violations (watertight and mesh agreement).
    families: BTreeMap<(&'static str, &'static str), u64>,
    /// float32 barycentric sum errors, ulps of 1, in the order measured.
    ulps: Vec<f64>,
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

    /// The rows of the table in order: invariant, model label, outcomes, violations.
    pub fn rows(&self) -> impl Iterator<Item = (&'static str, &'static str, u64, u64)> + '_ {
        self.rows
            .iter()
            .map(|(&(invariant, label), &(n, bad))| (invariant, label, n, bad))
    }

    /// The report, one string per line (no newlines): what `rasterproof check` prints.
    pub fn lines(&self) -> Vec<String> {
        let mut lines = vec![
            format!(
                "rasterproof check: {} cases, seed {}, presets d3d11/gl",
                self.cases, self.seed
            ),
            format!(
                "{:<24} {:<18} {:>7} {:>10}",
                "invariant", "model", "cases", "violations"
            ),
        ];
        for (invariant, model, n, bad) in self.rows() {
            lines.push(format!("{invariant:<24} {model:<18} {n:>7} {bad:>10}"));
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
            lines.push(format!(
                "float32 barycentric sum error, ulps of 1 ({} samples): median {:.1}, mean {:.1}, max {:.1}",
                ulps.len(),
                ulps[ulps.len() / 2],
                mean,
                ulps[ulps.len() - 1]
            ));
        }
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
