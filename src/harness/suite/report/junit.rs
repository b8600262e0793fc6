//! A report as JUnit XML (`check --junit`), the format CI systems display: one test case
//! per row of the table, failed when the row's model must hold and it has violations,
//! written by the JUnit writer [`crate::harness::junit`].

use std::fmt::Write as _;

use super::SuiteReport;
use crate::harness::junit::{JunitFailure, TestCase, TestSuite, TestSuites};

/// How many failing cases a test case's `<failure>` lists before "and N more".
const LISTED: usize = 10;

impl SuiteReport {
    /// The report as JUnit XML: one `<testsuite>` in a `<testsuites>`, with the seed,
    /// cases, shard and version as properties, and one `<testcase classname="rasterproof.check"
    /// name="INVARIANT / MODEL">` per row of the table, in its order. A row whose model
    /// must hold and that has violations holds a `<failure>` (its message counts them, its
    /// text gives the first cases' explanations and scenes' paths); a row whose every case
    /// was skipped holds `<skipped>`; a float model's violations (the measured trade) are
    /// counted in `<system-out>`, not failed. Every text is escaped for XML; characters
    /// XML cannot hold become U+FFFD.
    ///
    /// ```
    /// use rasterproof::harness::suite::SuiteConfig;
    /// let xml = SuiteConfig::new(7, 1).run().unwrap().junit();
    /// assert!(xml.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites "));
    /// assert!(xml.contains("name=\"watertight / fixed\""));
    /// ```
    pub fn junit(&self) -> String {
        let t = self.tally();
        let cases = t
            .rows()
            .map(|r| {
                let of = format!("{} of {} cases", r.violations, r.cases);
                let failed = r.violations > 0 && t.row_must_hold(r.invariant, r.label);
                TestCase {
                    classname: "rasterproof.check".to_string(),
                    name: format!("{} / {}", r.invariant, r.label),
                    failure: failed.then(|| JunitFailure {
                        kind: "violation".to_string(),
                        message: format!("{of} violate {} on {}", r.invariant, r.label),
                        text: self.failure_text(r.invariant, r.label),
                    }),
                    skipped: (r.cases == 0)
                        .then(|| format!("all {} cases skipped (the check could not run)", r.skipped)),
                    system_out: (!failed && r.cases > 0 && r.violations > 0)
                        .then(|| format!("{of} violate it: a float model's measured trade, not a failure")),
                }
            })
            .collect();
        let properties = [
            ("rasterproof", self.rasterproof_version().to_string()),
            ("seed", self.seed().to_string()),
            ("cases", self.cases().to_string()),
            ("shard", self.shards().to_string()),
            ("cases_run", self.cases_run().to_string()),
            ("complete", self.is_complete().to_string()),
        ];
        TestSuites {
            name: "rasterproof check".to_string(),
            suites: vec![TestSuite {
                name: format!("rasterproof check, seed {}, shard {}", self.seed(), self.shards()),
                properties: properties.map(|(name, value)| (name.to_string(), value)).to_vec(),
                cases,
            }],
        }
        .to_xml()
    }

    /// The first failing cases of the row (`invariant`, `label`): case, explanation and
    /// scene path, then how many more.
    fn failure_text(&self, invariant: &str, label: &str) -> String {
        let mine: Vec<_> = self
            .failures()
            .iter()
            .filter(|f| f.invariant == invariant && f.model == label)
            .collect();
        let mut s = String::new();
        for f in mine.iter().take(LISTED) {
            let _ = write!(s, "case {}: {}", f.case, f.explanation);
            if let Some(p) = &f.scene_path {
                let _ = write!(s, "\n  scene: {p}");
            }
            s.push('\n');
        }
        if mine.len() > LISTED {
            let _ = writeln!(s, "and {} more", mine.len() - LISTED);
        }
        s
    }
}
