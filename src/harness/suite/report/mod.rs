//! The report of a run of the suite: the table ([`Tally`]) with what produced it (seed,
//! cases, shard, how many ran) and every failing case with its scene and explanation.
//! `check --report FILE.json` writes it ([`SuiteReport::to_json`]), `check-merge` reads shard
//! reports back ([`SuiteReport::from_json`]) and merges them into the report of the whole run
//! ([`SuiteReport::merge`]), and `check --junit FILE.xml` writes it as JUnit XML
//! ([`SuiteReport::junit`]).
//!
//! # The JSON schema, version 1
//!
//! One object; the fields in this order (numbers are JSON integers unless said):
//!
//! | field | value |
//! |---|---|
//! | `format` | `"rasterproof check report"` |
//! | `version` | `1`, this schema; a reader refuses any other |
//! | `rasterproof` | the version of rasterproof that ran the cases, e.g. `"0.1.0"` |
//! | `seed` | the run's seed |
//! | `cases` | the whole run's cases, `0..cases` (`--cases`), whatever the shard |
//! | `shard` | `{"count": N, "indices": [K, ...]}`: the report holds the cases `k` of `0..cases` with `k mod N + 1` among the `indices` ([`super::shard`]); the whole run is `{"count": 1, "indices": [1]}` |
//! | `cases_run` | how many of those ran |
//! | `complete` | whether all of them ran (`false`: stopped by `--time` or an interrupt; the cases that ran are the first `cases_run` of each shard's, in index order) |
//! | `stopped` | why not, one line per shard that stopped: `["the time budget (2s) ran out after 5 of 8 cases"]`; `[]` when complete |
//! | `cases_by_family` | cases run per mesh family: `{"random mesh": 3, "tie-heavy mesh": 3, "far-from-origin mesh": 2}` |
//! | `fatal` | violations by a model that must hold ([`super::must_hold`]) |
//! | `passed` | `fatal == 0` |
//! | `rows` | every row of the table, in its order: `{"invariant", "model", "must_hold", "cases", "violations", "skipped"}` (`model` is the table's label, e.g. `"bresenham/stay"`; `must_hold`: its violations are fatal) |
//! | `skipped` | the reasons a check could not run: `{"invariant", "model", "reason", "cases"}` |
//! | `mesh_violations_by_family` | `{"family", "model", "violations"}`: watertight and mesh-agreement violations by mesh family |
//! | `float32_sum_ulps` | `{"skipped": S, "errors": [[E, n], ...]}`: the float32 barycentric sum errors E (ulps of 1, a JSON number that reads back to the same f64) with how many samples had each, ascending; S samples could not be measured |
//! | `findings` | the failures grouped by (`invariant`, `model`, `reason`): `{"invariant", "model", "reason", "fatal", "count", "first"}` with `first` the failure of the lowest case (as in `failures`); derived from `failures`, so a reader may ignore it |
//! | `failures` | every failing outcome, by case: `{"case", "invariant", "model", "fatal", "reason", "explanation", "scene", "scene_path"?}` |
//!
//! A failure's `explanation` is the checker's whole message ([`crate::check::Violation`]'s
//! text); its `reason` is the first line of the message with each number written `N` and
//! each bracketed group `(..)` or `[..]` ([`reason_of`]), so that failures of one kind
//! share it. `scene` is the scene that reproduces the failure, as a scene file's JSON
//! object (what [`crate::scene::Scene::to_json`] writes), and `scene_path`, present when
//! `check --out` wrote the scene, the path it was written to.
//!
//! Merging shard reports of one run gives exactly the report of the unsharded run
//! (`shard` 1/1 once every shard is in); the table printed from it is the same.

mod json;
mod junit;
mod merge;
mod reason;
#[cfg(test)]
mod tests;

pub(crate) use json::{j as json_value, object as json_object};
pub use reason::reason_of;

use std::collections::BTreeMap;

use super::tally::Tally;
use super::{CaseRun, CheckOutcome, Shards};

/// `format` of a report file.
pub const FORMAT: &str = "rasterproof check report";

/// `version` of the schema this rasterproof writes and reads.
pub const VERSION: u64 = 1;

/// One failing outcome of one case.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseFailure {
    /// The case's index in the run.
    pub case: u64,
    /// The invariant, as the table names it.
    pub invariant: String,
    /// The model's label in the table ([`CheckOutcome::label`]).
    pub model: String,
    /// Whether it fails the run (a model that [must hold](super::must_hold)).
    pub fatal: bool,
    /// The explanation's kind ([`reason_of`]): failures of one finding share it.
    pub reason: String,
    /// The checker's explanation, whole.
    pub explanation: String,
    /// The scene that reproduces it, as a scene file's JSON.
    pub scene: serde_json::Value,
    /// Where `check --out` wrote the scene, if it did.
    pub scene_path: Option<String>,
}

/// The failures of one kind: one (invariant, model, reason), how many, and the first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FailureGroup<'a> {
    /// The invariant.
    pub invariant: &'a str,
    /// The model's label.
    pub model: &'a str,
    /// The explanation's kind ([`reason_of`]).
    pub reason: &'a str,
    /// Whether these failures fail the run.
    pub fatal: bool,
    /// How many failing outcomes.
    pub count: u64,
    /// The one of the lowest case.
    pub first: &'a CaseFailure,
}

/// The report of a run (or of some shards of it) of the suite: see the [module
/// documentation](self) for its JSON.
///
/// ```
/// use rasterproof::harness::suite::{SuiteConfig, SuiteReport, Shard};
/// let whole = SuiteConfig::new(7, 2).run().unwrap();
/// let shards: Vec<SuiteReport> = (1..=2)
///     .map(|k| SuiteConfig { shard: Shard::new(k, 2).unwrap(), ..SuiteConfig::new(7, 2) }.run().unwrap())
///     .collect();
/// let merged = SuiteReport::merge(shards.into_iter().map(|r| ("a shard".to_string(), r))).unwrap();
/// assert_eq!(merged, whole);
/// assert_eq!(SuiteReport::from_json(&whole.to_json(), "whole.json").unwrap(), whole);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct SuiteReport {
    rasterproof: String,
    seed: u64,
    cases: u64,
    shards: Shards,
    stopped: Vec<String>,
    families: BTreeMap<String, u64>,
    tally: Tally,
    failures: Vec<CaseFailure>,
}

impl SuiteReport {
    /// An empty report of the run seeded `seed` of `cases` cases, for the cases of
    /// `shards`, by this version of rasterproof.
    pub fn new(seed: u64, cases: u64, shards: impl Into<Shards>) -> SuiteReport {
        SuiteReport {
            rasterproof: env!("CARGO_PKG_VERSION").to_string(),
            seed,
            cases,
            shards: shards.into(),
            stopped: Vec::new(),
            families: BTreeMap::new(),
            tally: Tally::new(seed),
            failures: Vec::new(),
        }
    }

    /// Counts case `k`'s outcomes and records each failing one; `scene_path` says where
    /// a failing outcome's scene was written, if it was.
    pub fn add(&mut self, k: u64, run: &CaseRun, scene_path: &dyn Fn(&CheckOutcome) -> Option<String>) {
        self.tally.add(run);
        *self.families.entry(run.mesh_family.to_string()).or_default() += 1;
        let mut at = self.failures.partition_point(|f| f.case <= k);
        for o in &run.outcomes {
            let Some((scene, v)) = o.repro() else { continue };
            let text = scene.to_json();
            let failure = CaseFailure {
                case: k,
                invariant: o.invariant.to_string(),
                model: o.label.to_string(),
                fatal: o.is_fatal(),
                reason: reason_of(&v.message),
                explanation: v.to_string(),
                scene: serde_json::from_str(&text).unwrap_or(serde_json::Value::String(text)),
                scene_path: scene_path(o),
            };
            self.failures.insert(at, failure);
            at += 1;
        }
    }

    /// Records why not every case ran (one line, e.g. "the time budget (2s) ran out after
    /// 5 of 8 cases").
    pub fn stop(&mut self, why: impl Into<String>) {
        self.stopped.push(why.into());
    }

    /// The version of rasterproof that ran the cases.
    pub fn rasterproof_version(&self) -> &str {
        &self.rasterproof
    }

    /// The run's seed.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The whole run's cases (`0..cases`), whatever the shard.
    pub fn cases(&self) -> u64 {
        self.cases
    }

    /// The shards this report holds.
    pub fn shards(&self) -> &Shards {
        &self.shards
    }

    /// How many cases ran.
    pub fn cases_run(&self) -> u64 {
        self.tally.cases()
    }

    /// Whether every case of its shards ran.
    pub fn is_complete(&self) -> bool {
        self.cases_run() == self.shards.case_count(self.cases)
    }

    /// Why not every case ran, one line per shard that stopped early.
    pub fn stopped(&self) -> &[String] {
        &self.stopped
    }

    /// Cases run per mesh family.
    pub fn cases_by_family(&self) -> &BTreeMap<String, u64> {
        &self.families
    }

    /// The table.
    pub fn tally(&self) -> &Tally {
        &self.tally
    }

    /// Every failing outcome, by case (in the order the checks ran within a case).
    pub fn failures(&self) -> &[CaseFailure] {
        &self.failures
    }

    /// Whether every must-hold model held every invariant on the cases that ran.
    pub fn passed(&self) -> bool {
        self.tally.passed()
    }

    /// The failures grouped by (invariant, model, reason), in that order, each with its
    /// count and the failure of the lowest case.
    pub fn findings(&self) -> Vec<FailureGroup<'_>> {
        let mut groups: BTreeMap<(&str, &str, &str), FailureGroup<'_>> = BTreeMap::new();
        for f in &self.failures {
            groups
                .entry((&f.invariant, &f.model, &f.reason))
                .and_modify(|g| g.count += 1)
                .or_insert(FailureGroup {
                    invariant: &f.invariant,
                    model: &f.model,
                    reason: &f.reason,
                    fatal: f.fatal,
                    count: 1,
                    first: f,
                });
        }
        groups.into_values().collect()
    }

    /// What `rasterproof check` and `check-merge` print, one string per line: the
    /// table's header, the shard and how many cases ran when it is not the whole run,
    /// the table, the findings (the failures grouped by invariant, model and kind of
    /// reason, each with its first case's reason, values and all), the legend and the
    /// verdict.
    pub fn lines(&self) -> Vec<String> {
        let mut lines = vec![self.tally.header()];
        if !self.shards.is_whole() {
            lines.push(format!(
                "shard {}: the cases k of 0..{} with k mod {} + 1 = {} ({})",
                self.shards,
                self.cases,
                self.shards.count(),
                self.shards
                    .indices()
                    .map(|k| k.to_string())
                    .collect::<Vec<_>>()
                    .join(" or "),
                crate::num::exact::counted(self.shards.case_count(self.cases), "case")
            ));
        }
        if !self.is_complete() {
            lines.push(format!(
                "incomplete: {} of {} cases ran",
                self.cases_run(),
                self.shards.case_count(self.cases)
            ));
            lines.extend(self.stopped.iter().map(|s| format!("stopped: {s}")));
        }
        lines.extend(self.tally.body());
        let findings = self.findings();
        if !findings.is_empty() {
            lines.push(
                "findings (the failures by invariant, model and kind of reason; the first case's reason):".to_string(),
            );
            for f in findings {
                let fatal = if f.fatal { " (FATAL)" } else { "" };
                // The checker's message, without the `INVARIANT violated: ` the row says.
                let e = &f.first.explanation;
                let first = e.split_once(" violated: ").map_or(e.as_str(), |(_, m)| m);
                let first = first.lines().next().unwrap_or("");
                lines.push(format!(
                    "  {:<22} {:<18} {:>5}x, first case {}{fatal}: {first}",
                    f.invariant, f.model, f.count, f.first.case
                ));
            }
        }
        lines.extend(self.tally.legend());
        lines.push(self.tally.verdict());
        lines
    }
}
