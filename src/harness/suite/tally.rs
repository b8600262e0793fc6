//! The suite's table: outcomes counted per invariant and model, the skipped checks with
//! their reasons, the summary lines and the legend.

use std::borrow::Cow;
use std::collections::BTreeMap;
use std::fmt;

use super::{legend, must_hold, CaseRun};

/// One row of the table: an invariant checked on one model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Row<'a> {
    /// The invariant.
    pub invariant: &'a str,
    /// The model's label.
    pub label: &'a str,
    /// Cases on which the check ran.
    pub cases: u64,
    /// Cases on which it did not hold.
    pub violations: u64,
    /// Cases on which it could not run.
    pub skipped: u64,
}

/// A name in the table: the suite's own (`&'static str`) or one read from a report.
pub(super) type Name = Cow<'static, str>;

/// The counts of one row of the table.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(super) struct Counts {
    /// Outcomes: cases on which the check ran.
    pub cases: u64,
    /// Of those, the ones that failed.
    pub violations: u64,
    /// Cases on which it could not run.
    pub skipped: u64,
    /// Whether the row's model [must hold](super::must_hold): its violations are fatal.
    pub must_hold: bool,
}

/// The outcomes of a run of the suite, accumulated case by case, and the text
/// `rasterproof check` prints: a header, one row per (invariant, model) with its cases,
/// violations and skipped cases, the reasons for the skipped ones, the mesh violations by
/// family, the float32 barycentric sum error, the legend (one line per column, invariant
/// and model in the table: [`super::legend`]) and a verdict line.
///
/// Two tallies of disjoint sets of cases [merge](Tally::merge) into the tally of their
/// union, exactly as if its cases had been added one by one (the float32 sum errors are
/// kept as a multiset, so that the median and the sum in sorted order come out the same).
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
    pub(super) seed: u64,
    pub(super) cases: u64,
    /// (invariant, label) -> its counts.
    pub(super) rows: BTreeMap<(Name, Name), Counts>,
    /// (invariant, label, reason) -> skipped cases.
    pub(super) reasons: BTreeMap<(Name, Name, Name), u64>,
    /// (mesh family, label) -> mesh violations (watertight and mesh agreement).
    pub(super) families: BTreeMap<(Name, Name), u64>,
    /// float32 barycentric sum errors, ulps of 1: [`ulps_key`] of the error -> samples.
    pub(super) ulps: BTreeMap<u64, u64>,
    /// Samples where the float32 sum error could not be measured.
    pub(super) ulps_skipped: u64,
    /// Violations by a model that must hold.
    pub(super) fatal: u64,
}

/// `x`'s bits, reordered so that comparing them as integers orders the numbers as
/// [`f64::total_cmp`] does (negatives flipped, the sign bit set on the rest).
pub(super) fn ulps_key(x: f64) -> u64 {
    let bits = x.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | (1 << 63)
    }
}

/// The number whose [`ulps_key`] is `key`.
pub(super) fn ulps_from_key(key: u64) -> f64 {
    f64::from_bits(if key >> 63 == 1 { key & !(1 << 63) } else { !key })
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
        for &u in &run.float32_sum_ulps {
            *self.ulps.entry(ulps_key(u)).or_default() += 1;
        }
        self.ulps_skipped += run.float32_sum_skipped;
        for s in &run.skipped {
            let row = self.rows.entry((s.invariant.into(), s.label.into())).or_default();
            row.skipped += 1;
            row.must_hold |= must_hold(s.model);
            *self
                .reasons
                .entry((s.invariant.into(), s.label.into(), s.reason.into()))
                .or_default() += 1;
        }
        for o in &run.outcomes {
            let row = self.rows.entry((o.invariant.into(), o.label.into())).or_default();
            row.cases += 1;
            row.must_hold |= must_hold(o.model);
            if o.result.is_err() {
                row.violations += 1;
                if o.invariant == "watertight" || o.invariant == "agreement (mesh)" {
                    *self
                        .families
                        .entry((run.mesh_family.into(), o.label.into()))
                        .or_default() += 1;
                }
                if o.is_fatal() {
                    self.fatal += 1;
                }
            }
        }
    }

    /// Adds `other`'s counts to this tally's: the tally of both runs' cases (which must
    /// be disjoint for the result to mean anything; [`super::SuiteReport::merge`] checks that).
    /// The seed stays this tally's.
    pub fn merge(&mut self, other: &Tally) {
        self.cases += other.cases;
        for (key, c) in &other.rows {
            let row = self.rows.entry(key.clone()).or_default();
            row.cases += c.cases;
            row.violations += c.violations;
            row.skipped += c.skipped;
            row.must_hold |= c.must_hold;
        }
        for (key, n) in &other.reasons {
            *self.reasons.entry(key.clone()).or_default() += n;
        }
        for (key, n) in &other.families {
            *self.families.entry(key.clone()).or_default() += n;
        }
        for (&key, n) in &other.ulps {
            *self.ulps.entry(key).or_default() += n;
        }
        self.ulps_skipped += other.ulps_skipped;
        self.fatal += other.fatal;
    }

    /// The seed named in the header.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// Whether the row (`invariant`, `label`) is one of a model that [must
    /// hold](super::must_hold), so that its violations fail the run; `false` for a row
    /// the table does not have.
    pub fn row_must_hold(&self, invariant: &str, label: &str) -> bool {
        self.rows
            .iter()
            .any(|((i, l), c)| i == invariant && l == label && c.must_hold)
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
    pub fn rows(&self) -> impl Iterator<Item = Row<'_>> + '_ {
        self.rows.iter().map(|((invariant, label), c)| Row {
            invariant,
            label,
            cases: c.cases,
            violations: c.violations,
            skipped: c.skipped,
        })
    }

    /// The skipped checks: invariant, label, reason and how many cases, in table order.
    pub fn skip_reasons(&self) -> impl Iterator<Item = (&str, &str, &str, u64)> + '_ {
        self.reasons
            .iter()
            .map(|((invariant, label, reason), &n)| (&**invariant, &**label, &**reason, n))
    }

    /// The float32 sum errors' sample count, median (the middle one, the upper of two),
    /// mean (summed in sorted order) and maximum; `None` when none was measured.
    fn ulps_stats(&self) -> Option<UlpsStats> {
        let samples: u64 = self.ulps.values().sum();
        let (&last, _) = self.ulps.last_key_value()?;
        let middle = samples / 2;
        let (mut seen, mut median, mut sum) = (0u64, 0.0, 0.0);
        for (&key, &n) in &self.ulps {
            let u = ulps_from_key(key);
            if seen <= middle && middle < seen + n {
                median = u;
            }
            seen += n;
            for _ in 0..n {
                sum += u;
            }
        }
        Some(UlpsStats {
            samples,
            median,
            mean: sum / samples as f64,
            max: ulps_from_key(last),
        })
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
        let mut invariants: Vec<&str> = self.rows.keys().map(|(i, _)| &**i).collect();
        invariants.dedup();
        let mut labels: Vec<&str> = self.rows.keys().map(|(_, l)| &**l).collect();
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

    /// The table as text, one string per line (no newlines): the [header](Tally::header),
    /// the [table](Tally::body), the [legend](Tally::legend) and the
    /// [verdict](Tally::verdict). `rasterproof check` prints [`super::SuiteReport::lines`]: these
    /// with the shard, how many cases ran and the findings.
    pub fn lines(&self) -> Vec<String> {
        let mut lines = vec![self.header()];
        lines.extend(self.body());
        lines.extend(self.legend());
        lines.push(self.verdict());
        lines
    }

    /// The first line: cases, seed and presets.
    pub fn header(&self) -> String {
        format!(
            "rasterproof check: {}, seed {}, presets d3d11/gl",
            crate::num::exact::counted(self.cases, "case"),
            self.seed
        )
    }

    /// The table (column heads and rows), the skipped checks' reasons, the mesh
    /// violations by family and the float32 barycentric sum error line.
    pub fn body(&self) -> Vec<String> {
        let mut lines = vec![format!(
            "{:<24} {:<18} {:>7} {:>10} {:>7}",
            "invariant", "model", "cases", "violations", "skipped"
        )];
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
        if let Some(stats) = self.ulps_stats() {
            let skipped = match self.ulps_skipped {
                0 => String::new(),
                n => format!(", {n} skipped: the triangle has zero area in f32 or does not fit it"),
            };
            let samples = match stats.samples {
                1 => "1 sample".to_string(),
                n => format!("{n} samples"),
            };
            lines.push(format!(
                "float32 barycentric sum error, ulps of 1 ({samples}{skipped}): median {:.1}, mean {:.1}, max {:.1} \
                 (the float32 model's measured rounding, not a failure: it grows on thin and far-from-origin \
                 triangles, whose f32 edge values cancel; the exact models' sum is exactly 1)",
                stats.median, stats.mean, stats.max
            ));
        } else if self.ulps_skipped > 0 {
            lines.push(format!(
                "float32 barycentric sum error: not measured ({} samples skipped: the triangle has zero area in f32 or does not fit it)",
                self.ulps_skipped
            ));
        }
        lines
    }

    /// The last line: `ok: ...` or `FAILED: N violations ...`.
    pub fn verdict(&self) -> String {
        if self.fatal > 0 {
            format!(
                "FAILED: {} violations by an exact or integer model (exact, exact-snapped, fixed, scanline)",
                self.fatal
            )
        } else {
            "ok: the exact and integer models (exact, exact-snapped, fixed, scanline) hold every invariant".to_string()
        }
    }
}

/// What the table says of the float32 barycentric sum errors.
struct UlpsStats {
    samples: u64,
    median: f64,
    mean: f64,
    max: f64,
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
