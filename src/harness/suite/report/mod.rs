//! The report of a run of the suite: the table ([`Tally`]) with what produced it (seed,
//! cases, shard, how many ran) and every failing case with its scene and explanation.
//! `check --report FILE.json` writes it ([`Report::to_json`]), `check-merge` reads shard
//! reports back ([`Report::from_json`]) and merges them into the report of the whole run
//! ([`Report::merge`]), and `check --junit FILE.xml` writes it as JUnit XML
//! ([`Report::junit`]).
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

pub(crate) use json::{j as json_value, object as json_object};
pub(crate) use junit::escape as xml_escape;

use std::collections::BTreeMap;

use super::tally::Tally;
use super::{CaseRun, Outcome, Shards};

/// `format` of a report file.
pub const FORMAT: &str = "rasterproof check report";

/// `version` of the schema this rasterproof writes and reads.
pub const VERSION: u64 = 1;

/// One failing outcome of one case.
#[derive(Debug, Clone, PartialEq)]
pub struct Failure {
    /// The case's index in the run.
    pub case: u64,
    /// The invariant, as the table names it.
    pub invariant: String,
    /// The model's label in the table ([`Outcome::label`]).
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
pub struct Finding<'a> {
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
    pub first: &'a Failure,
}

/// The report of a run (or of some shards of it) of the suite: see the [module
/// documentation](self) for its JSON.
///
/// ```
/// use rasterproof::harness::suite::{Plan, Report, Shard};
/// let whole = Plan::new(7, 2).run().unwrap();
/// let shards: Vec<Report> = (1..=2)
///     .map(|k| Plan { shard: Shard::new(k, 2).unwrap(), ..Plan::new(7, 2) }.run().unwrap())
///     .collect();
/// let merged = Report::merge(shards.into_iter().map(|r| ("a shard".to_string(), r))).unwrap();
/// assert_eq!(merged, whole);
/// assert_eq!(Report::from_json(&whole.to_json(), "whole.json").unwrap(), whole);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    rasterproof: String,
    seed: u64,
    cases: u64,
    shards: Shards,
    stopped: Vec<String>,
    families: BTreeMap<String, u64>,
    tally: Tally,
    failures: Vec<Failure>,
}

impl Report {
    /// An empty report of the run seeded `seed` of `cases` cases, for the cases of
    /// `shards`, by this version of rasterproof.
    pub fn new(seed: u64, cases: u64, shards: impl Into<Shards>) -> Report {
        Report {
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
    pub fn add(&mut self, k: u64, run: &CaseRun, scene_path: &dyn Fn(&Outcome) -> Option<String>) {
        self.tally.add(run);
        *self.families.entry(run.mesh_family.to_string()).or_default() += 1;
        let mut at = self.failures.partition_point(|f| f.case <= k);
        for o in &run.outcomes {
            let Some((scene, v)) = o.repro() else { continue };
            let text = scene.to_json();
            let failure = Failure {
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
    pub fn failures(&self) -> &[Failure] {
        &self.failures
    }

    /// Whether every must-hold model held every invariant on the cases that ran.
    pub fn passed(&self) -> bool {
        self.tally.passed()
    }

    /// The failures grouped by (invariant, model, reason), in that order, each with its
    /// count and the failure of the lowest case.
    pub fn findings(&self) -> Vec<Finding<'_>> {
        let mut groups: BTreeMap<(&str, &str, &str), Finding<'_>> = BTreeMap::new();
        for f in &self.failures {
            groups
                .entry((&f.invariant, &f.model, &f.reason))
                .and_modify(|g| g.count += 1)
                .or_insert(Finding {
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

    /// Merges the reports of disjoint shards of one run (each with the name of its file,
    /// for the errors) into the report of their cases together: the report of the whole
    /// run once every shard is in. The order of the reports does not matter.
    ///
    /// # Errors
    /// No report; two reports of different versions of rasterproof, seeds, case counts or
    /// shard counts; two reports holding the same shard: one line naming both files.
    pub fn merge(reports: impl IntoIterator<Item = (String, Report)>) -> Result<Report, String> {
        let mut parts: Vec<(String, Report)> = reports.into_iter().collect();
        parts.sort_by_key(|(_, r)| r.shards.indices().next());
        let mut parts = parts.into_iter();
        let (first_name, mut merged) = parts.next().ok_or("no report to merge")?;
        let mut holder: BTreeMap<u64, String> = merged.shards.indices().map(|k| (k, first_name.clone())).collect();
        for (name, r) in parts {
            let a = &first_name;
            if r.rasterproof != merged.rasterproof {
                return Err(format!(
                    "{a} and {name}: written by different versions of rasterproof ({} and {}): their cases differ",
                    merged.rasterproof, r.rasterproof
                ));
            }
            if r.seed != merged.seed {
                return Err(format!(
                    "{a} and {name}: different seeds ({} and {}): not shards of one run",
                    merged.seed, r.seed
                ));
            }
            if r.cases != merged.cases {
                return Err(format!(
                    "{a} and {name}: different case counts (--cases {} and {}): not shards of one run",
                    merged.cases, r.cases
                ));
            }
            if r.shards.count() != merged.shards.count() {
                return Err(format!(
                    "{a} and {name}: shards of different counts ({} and {}): not shards of one partition",
                    merged.shards, r.shards
                ));
            }
            if let Some(&k) = merged.shards.overlap(&r.shards).first() {
                return Err(format!(
                    "{} and {name}: both hold shard {k}/{}: the same cases twice",
                    holder[&k],
                    r.shards.count()
                ));
            }
            holder.extend(r.shards.indices().map(|k| (k, name.clone())));
            merged.absorb(r);
        }
        if merged.is_complete() {
            merged.shards = merged.shards.normalised();
        }
        Ok(merged)
    }

    /// Adds `other`'s cases (disjoint shards of the same run) to this report's.
    fn absorb(&mut self, other: Report) {
        self.shards = self.shards.union(&other.shards);
        self.stopped.extend(other.stopped);
        for (family, n) in other.families {
            *self.families.entry(family).or_default() += n;
        }
        self.tally.merge(&other.tally);
        self.failures.extend(other.failures);
        self.failures.sort_by_key(|f| f.case);
    }

    /// What `rasterproof check` and `check-merge` print, one string per line: the
    /// table's header, the shard and how many cases ran when it is not the whole run,
    /// the table, the findings (the failures grouped by invariant, model and reason, with
    /// their first case), the legend and the verdict.
    pub fn lines(&self) -> Vec<String> {
        let mut lines = vec![self.tally.header()];
        if !self.shards.is_whole() {
            lines.push(format!(
                "shard {}: the cases k of 0..{} with k mod {} + 1 = {} ({} cases)",
                self.shards,
                self.cases,
                self.shards.count(),
                self.shards
                    .indices()
                    .map(|k| k.to_string())
                    .collect::<Vec<_>>()
                    .join(" or "),
                self.shards.case_count(self.cases)
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
            lines.push("findings (the failures by invariant, model and reason):".to_string());
            for f in findings {
                let fatal = if f.fatal { " (FATAL)" } else { "" };
                lines.push(format!(
                    "  {:<22} {:<18} {:>5}x, first case {}{fatal}: {}",
                    f.invariant, f.model, f.count, f.first.case, f.reason
                ));
            }
        }
        lines.extend(self.tally.legend());
        lines.push(self.tally.verdict());
        lines
    }
}

/// The kind of a checker's explanation: the first line of `message` with each number
/// (a run of digits, `/`, `.` not inside a word, with its sign) written `N` and each
/// bracketed group written `(..)` or `[..]`, so that explanations that differ only in
/// coordinates, pixels and counts share it.
///
/// ```
/// use rasterproof::harness::suite::report::reason_of;
/// assert_eq!(
///     reason_of("pixel (29, 1) is covered 2 times, by [5, 6]; 15 such pixels\n  triangle 5: ..."),
///     "pixel (..) is covered N times, by [..]; N such pixels"
/// );
/// assert_eq!(
///     reason_of("vertex 9 (1/2, 41/2) is outside window edge 3: a x + b y + c = -39/2097152"),
///     "vertex N (..) is outside window edge N: a x + b y + c = N"
/// );
/// assert_eq!(reason_of("float32-naive [5] f32"), "float32-naive [..] f32");
/// ```
pub fn reason_of(message: &str) -> String {
    let line = message.lines().next().unwrap_or("");
    let chars: Vec<char> = line.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let after_word = i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_');
        if let Some(close) = closing(c) {
            let end = matching(&chars, i, c, close);
            out.push(c);
            out.push_str("..");
            out.push(close);
            i = end + 1;
        } else if !after_word && starts_number(&chars, i) {
            out.push('N');
            let start = i;
            i += 1;
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '/' || chars[i] == '.') {
                i += 1;
            }
            // A trailing `.` or `/` ends the sentence, not the number.
            while i > start + 1 && matches!(chars[i - 1], '.' | '/') {
                i -= 1;
            }
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}

/// The closing bracket of `c`, if it opens a group.
fn closing(c: char) -> Option<char> {
    match c {
        '(' => Some(')'),
        '[' => Some(']'),
        _ => None,
    }
}

/// The index of the bracket closing the one at `open`, nested groups counted; the last
/// index when it is never closed.
fn matching(chars: &[char], open: usize, c: char, close: char) -> usize {
    let mut depth = 0u32;
    for (j, &d) in chars.iter().enumerate().skip(open) {
        if d == c {
            depth += 1;
        } else if d == close {
            depth -= 1;
            if depth == 0 {
                return j;
            }
        }
    }
    chars.len() - 1
}

/// Whether a number starts at `i`: a digit, or a `-` before one.
fn starts_number(chars: &[char], i: usize) -> bool {
    chars[i].is_ascii_digit() || (chars[i] == '-' && chars.get(i + 1).is_some_and(char::is_ascii_digit))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::Violation;
    use crate::harness::suite::{Shard, Skip};
    use crate::model::Model;
    use crate::scene::Scene;

    fn outcome(invariant: &'static str, model: Model, result: Result<(), Violation>) -> Outcome {
        Outcome {
            invariant,
            model,
            label: model.name(),
            result,
            scene: Scene::new(4, 4, Vec::new()),
        }
    }

    fn gap(n: u32) -> Result<(), Violation> {
        Err(Violation::new(
            "watertight",
            format!("pixel ({n}, 1) is covered 0 times, by []"),
        ))
    }

    /// A hand-made case: `fixed` fails watertight when `fixed_fails`, float32-naive always
    /// does; one skipped check; three float32 sum errors (NaN and infinity among them).
    fn case(fixed_fails: bool, n: u32) -> CaseRun {
        CaseRun {
            mesh_family: "random mesh",
            outcomes: vec![
                outcome("watertight", Model::Fixed, if fixed_fails { gap(n) } else { Ok(()) }),
                outcome("watertight", Model::Float32Naive, gap(n + 1)),
            ],
            skipped: vec![Skip {
                invariant: "triangulation",
                model: Model::Fixed,
                label: "fixed",
                reason: "snapping <folded> the polygon & more",
            }],
            float32_sum_ulps: vec![0.5, f64::NAN, f64::INFINITY],
            float32_sum_skipped: 1,
        }
    }

    /// Cases 0..4 of seed 5 as shards of 2: case k in shard k % 2 + 1; `fixed` fails on
    /// case 3.
    fn report(shard: Shard) -> Report {
        let mut r = Report::new(5, 4, shard);
        for k in shard.cases(4) {
            let path = move |o: &Outcome| o.is_fatal().then(|| format!("out/case-{k}.json"));
            r.add(k, &case(k == 3, u32::try_from(k).unwrap()), &path);
        }
        r
    }

    #[test]
    fn findings_group_failures_by_invariant_model_and_reason() {
        let r = report(Shard::WHOLE);
        assert_eq!(r.failures().len(), 5);
        assert!(r.failures().windows(2).all(|w| w[0].case <= w[1].case));
        let findings = r.findings();
        assert_eq!(findings.len(), 2);
        assert_eq!(
            (
                findings[0].model,
                findings[0].count,
                findings[0].first.case,
                findings[0].fatal
            ),
            ("fixed", 1, 3, true)
        );
        assert_eq!(findings[0].reason, "pixel (..) is covered N times, by [..]");
        assert_eq!(findings[0].first.scene_path.as_deref(), Some("out/case-3.json"));
        assert_eq!(
            (findings[1].model, findings[1].count, findings[1].first.case),
            ("float32-naive", 4, 0)
        );
        assert!(!r.passed());
        let lines = r.lines();
        assert!(lines.contains(
            &"  watertight             fixed                  1x, first case 3 (FATAL): pixel (..) is covered N times, by [..]"
                .to_string()
        ));
        assert_eq!(lines.last().unwrap(), &r.tally().verdict());
    }

    #[test]
    fn json_reads_back_to_the_same_report() {
        for r in [report(Shard::WHOLE), report(Shard::new(2, 2).unwrap())] {
            let text = r.to_json();
            let back = Report::from_json(&text, "r.json").unwrap();
            assert_eq!(back, r);
            assert_eq!(back.to_json(), text);
            assert_eq!(back.lines(), r.lines());
        }
        let mut stopped = report(Shard::WHOLE);
        stopped.stop("interrupted after 4 of 4 cases");
        assert_eq!(Report::from_json(&stopped.to_json(), "s").unwrap(), stopped);
    }

    #[test]
    fn shards_merge_into_the_whole_run_in_any_order() {
        let whole = report(Shard::WHOLE);
        let a = report(Shard::new(1, 2).unwrap());
        let b = report(Shard::new(2, 2).unwrap());
        assert_eq!(
            a.lines()[1],
            "shard 1/2: the cases k of 0..4 with k mod 2 + 1 = 1 (2 cases)"
        );
        for parts in [[a.clone(), b.clone()], [b.clone(), a.clone()]] {
            let merged = Report::merge(parts.into_iter().map(|r| ("x".to_string(), r))).unwrap();
            assert_eq!(merged, whole);
            assert_eq!(merged.to_json(), whole.to_json());
        }
    }

    #[test]
    fn merge_refuses_other_runs_and_overlaps_naming_the_files() {
        let a = report(Shard::new(1, 2).unwrap());
        let b = report(Shard::new(2, 2).unwrap());
        let named = |x: &Report, y: &Report| [("a.json".to_string(), x.clone()), ("b.json".to_string(), y.clone())];
        let mut other_seed = b.clone();
        other_seed.seed = 6;
        let mut other_version = b.clone();
        other_version.rasterproof = "9.9.9".into();
        let mut other_cases = b.clone();
        other_cases.cases = 5;
        let thirds = report(Shard::new(2, 3).unwrap());
        for (y, words) in [
            (&other_seed, "different seeds (5 and 6)"),
            (&other_version, "different versions of rasterproof (0.1.0 and 9.9.9)"),
            (&other_cases, "different case counts"),
            (&thirds, "shards of different counts (1/2 and 2/3)"),
            (&a, "both hold shard 1/2"),
        ] {
            let e = Report::merge(named(&a, y)).unwrap_err();
            assert!(e.starts_with("a.json and b.json: ") && e.contains(words), "{e}");
        }
        assert!(Report::merge(Vec::new()).is_err());
    }

    #[test]
    fn junit_has_a_test_case_per_row_and_fails_the_fatal_one() {
        let r = report(Shard::WHOLE);
        let xml = r.junit();
        let rows = r.tally().rows().count();
        assert_eq!(rows, 3);
        assert_eq!(xml.matches("<testcase ").count(), rows);
        assert!(xml
            .contains("<testsuites name=\"rasterproof check\" tests=\"3\" failures=\"1\" errors=\"0\" skipped=\"1\">"));
        assert!(xml.contains(
            "<testcase classname=\"rasterproof.check\" name=\"watertight / fixed\">\n      <failure type=\"violation\" message=\"1 of 4 cases violate watertight on fixed\">case 3: watertight violated: pixel (3, 1) is covered 0 times, by []\n  scene: out/case-3.json\n</failure>"
        ), "{xml}");
        assert!(xml.contains("name=\"triangulation / fixed\">\n      <skipped message=\"all 4 cases skipped"));
        assert!(xml.contains("4 of 4 cases violate it: a float model&apos;s measured trade"));
        assert_eq!(xml.matches("<failure ").count(), 1);
        assert_eq!(xml.matches("</failure>").count(), 1);
        assert!(!xml.contains('\u{1}'));
        // A report without failures fails no test case.
        let passing = Report::new(5, 0, Shard::WHOLE).junit();
        assert!(passing.contains("tests=\"0\" failures=\"0\""), "{passing}");
    }

    #[test]
    fn bad_report_files_are_refused_naming_the_field() {
        let good = report(Shard::WHOLE).to_json();
        let cut = &good[..good.len() / 2];
        // `findings` repeats failures but is not read: change the failures themselves.
        let at = good.find("\"failures\"").unwrap();
        let in_failures = |from: &str, to: &str| format!("{}{}", &good[..at], good[at..].replacen(from, to, 1));
        let cases = [
            (
                cut.to_string(),
                "r.json: not a JSON check report (truncated or damaged?)",
            ),
            (
                "[1]".to_string(),
                "r.json: expected a check report (a JSON object), found [1]",
            ),
            ("{}".to_string(), "r.json: not a check report"),
            (good.replace("\"version\": 1", "\"version\": 2"), "r.json: version 2"),
            (
                good.replace("\"seed\": 5", "\"seed\": -5"),
                "r.json: seed: expected a non-negative integer, found -5",
            ),
            (
                good.replace("\"count\": 1, \"indices\": [1]", "\"count\": 1, \"indices\": [2]"),
                "r.json: shard: 2/1: K must be in 1..=1",
            ),
            (
                good.replace("\"cases_run\": 4", "\"cases_run\": 3"),
                "r.json: cases_run 3",
            ),
            (in_failures("\"case\": 0", "\"case\": 9"), "r.json: failures[0].case 9"),
            (
                in_failures("\"scene\": {", "\"scene_path\": 3, \"scene\": {"),
                "r.json: failures[0].scene_path: expected a string, found 3",
            ),
            (
                good.replacen("\"must_hold\": true", "\"must_hold\": 1", 1),
                "r.json: rows[0].must_hold: expected true or false, found 1",
            ),
        ];
        for (text, expected) in cases {
            assert_ne!(text, good, "{expected}");
            let e = Report::from_json(&text, "r.json").unwrap_err();
            assert!(e.starts_with(expected), "{expected}\n{e}");
        }
    }

    #[test]
    fn reasons_keep_words_and_drop_numbers_and_groups() {
        assert_eq!(
            reason_of("[1, 2] -> [3, 4]: endpoints not included: first Some([1, 2]), last Some([3, 5])"),
            "[..] -> [..]: endpoints not included: first Some(..), last Some(..)"
        );
        assert_eq!(
            reason_of("21 differing pixels; first (3, 4): exact-plain [], float32-naive [5, 6]"),
            "N differing pixels; first (..): exact-plain [..], float32-naive [..]"
        );
        assert_eq!(reason_of("a 2^-16 grid, 1.5 px. Then 3."), "a N^N grid, N px. Then N.");
        assert_eq!(reason_of("unclosed (1, [2"), "unclosed (..)");
        assert_eq!(reason_of(""), "");
    }
}
