//! What a hunt found: its [`HuntFinding`]s and the [`HuntReport`], written as JSON
//! ([`HuntReport::to_json`], format [`HUNT_REPORT_FORMAT`] version [`HUNT_REPORT_VERSION`]) or JUnit
//! XML ([`HuntReport::junit`]).

use std::fmt::Write as _;
use std::path::Path;

use super::verdict::{pixel_kinds, CaseOutcome, HuntVerdict, Signature};
use super::HuntConfig;
use crate::harness::junit::{JunitFailure, TestCase, TestSuite, TestSuites};
use crate::harness::shrink::primitive_count;
use crate::harness::suite::report::{json_object as object, json_value as j};
use crate::harness::suite::Shard;
use num_rational::BigRational;

use crate::num::exact::exact_text;
use crate::oracle::compare::PixelKind;
use crate::oracle::renderer::program::RendererRuns;
use crate::scene::Scene;

/// A distinct failure, shrunk.
#[derive(Debug, Clone)]
pub struct HuntFinding {
    /// What it is: one cause (a reason class and a primitive kind, or a failure).
    pub signature: Signature,
    /// The kinds of differing pixels its cases showed (missing, extra, wrong owner,
    /// double), in [`PixelKind`] order; empty for a renderer failure.
    pub kinds: Vec<PixelKind>,
    /// The first case that showed it.
    pub case: u64,
    /// How many cases showed it.
    pub cases: u64,
    /// That case's scene.
    pub original: Scene,
    /// The scene after shrinking: no step of the shrinker keeps the failure.
    pub minimal: Scene,
    /// Their verdict on the minimal scene.
    pub verdict: HuntVerdict,
    /// Scenes the shrink tried.
    pub runs: usize,
    /// Of those, the distinct ones, each rendered once (a scene tried again is answered
    /// from the first try).
    pub renderer_calls: usize,
}

/// One sample index of a multisample hunt (`hunt --samples N`), over the cases run.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SampleIndexSummary {
    /// The sample index.
    pub index: usize,
    /// The position the scenes state for it (within the pixel, from its top-left corner).
    pub position: [BigRational; 2],
    /// The cases where its image differed from the oracle's.
    pub cases: u64,
    /// Its differing pixels over those cases.
    pub pixels: u64,
    /// The positions on the 1/16 px grid that give its image on every finding's first and
    /// minimal scene where it differs
    /// ([`crate::oracle::compare::fit::samples::fit_positions`]), in grid order; `None`
    /// when no such scene shows it differing, or their renderer failed on one when asked
    /// again.
    pub fits: Option<Vec<[BigRational; 2]>>,
}

impl SampleIndexSummary {
    /// One line: `sample 2 at (1/8, 5/8): differs in 13 cases (32 pixels); on the findings'
    /// scenes where it differs, 1 position of the 1/16 px grid gives its image: (1/8, 1/2)
    /// (not its own position)`.
    pub fn to_text(&self) -> String {
        let point = |p: &[BigRational; 2]| format!("({}, {})", exact_text(&p[0]), exact_text(&p[1]));
        let head = format!("sample {} at {}", self.index, point(&self.position));
        if self.cases == 0 {
            return format!("{head}: the oracle's image in every case");
        }
        let fits = match &self.fits {
            None => String::new(),
            Some(f) if f.is_empty() => {
                "; on the findings' scenes no position of the 1/16 px grid gives its image (not a moved sample)"
                    .to_string()
            }
            Some(f) => {
                let own = if f.contains(&self.position) {
                    "its own position among them"
                } else {
                    "not its own position"
                };
                let shown: Vec<String> = f.iter().take(8).map(point).collect();
                let more = if f.len() > 8 {
                    format!(" and {} more", f.len() - 8)
                } else {
                    String::new()
                };
                format!(
                    "; on the findings' scenes where it differs, {} of the 1/16 px grid {} its image: {}{more} ({own})",
                    crate::num::exact::counted(f.len() as u64, "position"),
                    if f.len() == 1 { "gives" } else { "give" },
                    shown.join(", ")
                )
            }
        };
        format!(
            "{head}: differs in {} ({}){fits}",
            crate::num::exact::counted(self.cases, "case"),
            crate::num::exact::counted(self.pixels, "pixel")
        )
    }
}

/// What a hunt found.
#[derive(Debug, Clone)]
pub struct HuntReport {
    /// The configuration it ran with (its shard, budget, convention and oracle model).
    pub config: HuntConfig,
    /// The cases asked for: the shard's cases among `0..config.cases`.
    pub requested: u64,
    /// Cases run: the first `cases` of the shard's, in order (all of them unless the
    /// time budget stopped the hunt).
    pub cases: u64,
    /// Whether the time budget stopped the hunt before every requested case ran.
    pub stopped_by_time: bool,
    /// Whether it was interrupted (Ctrl-C): the cases that ran are reported, their
    /// findings not shrunk.
    pub interrupted: bool,
    /// Identical to the oracle.
    pub same: u64,
    /// Differing.
    pub differing: u64,
    /// Their renderer failed.
    pub failed: u64,
    /// The oracle refused the scene.
    pub refused: u64,
    /// Every distinct failure, by its first case.
    pub findings: Vec<HuntFinding>,
    /// What the hunt cost the renderer, when it is a program: scenes asked for and
    /// programs started.
    pub renderer_runs: Option<RendererRuns>,
    /// Under a pattern of several samples (`config.samples`), each sample index over the
    /// cases run, in index order; empty for one sample per pixel.
    pub per_sample: Vec<SampleIndexSummary>,
}

/// The `format` of a hunt report ([`HuntReport::to_json`]).
pub const HUNT_REPORT_FORMAT: &str = "rasterproof hunt report";

/// The schema version of a hunt report ([`HuntReport::to_json`]).
pub const HUNT_REPORT_VERSION: u64 = 2;

impl HuntFinding {
    /// Its pixel kinds in words, after the signature: the minimal scene's, and the kinds
    /// its cases showed where they differ (a shrink keeps the cause, not always the kind):
    /// ` (extra pixels; its cases showed missing and wrong owner pixels)`; empty for a
    /// renderer failure.
    pub fn kinds_text(&self) -> String {
        let words = |kinds: &[PixelKind]| {
            let names: Vec<&str> = kinds.iter().map(|k| k.name()).collect();
            match names.as_slice() {
                [] => None,
                [one] => Some(format!("{one} pixels")),
                [rest @ .., last] => Some(format!("{} and {last} pixels", rest.join(", "))),
            }
        };
        let minimal = pixel_kinds(&self.verdict, &self.signature);
        match (words(&minimal), words(&self.kinds)) {
            (Some(m), Some(c)) if minimal != self.kinds => format!(" ({m}; its cases showed {c})"),
            (Some(m), _) => format!(" ({m})"),
            (None, Some(c)) => format!(" (its cases showed {c})"),
            (None, None) => String::new(),
        }
    }

    /// The finding's `finding-NN.txt` (`n`: its number, from 1): what it is, its minimal
    /// scene's comparison (as `finding-NN.json`, the first 50 pixels) or failure, and the
    /// first scene that showed it.
    pub fn to_text(&self, n: usize) -> String {
        let mut s = format!(
            "finding {n:02}: {}{} (first in case {}, {} cases; shrunk in {} steps, {} renderer calls)\n\n",
            self.signature.describe(),
            self.kinds_text(),
            self.case,
            self.cases,
            self.runs,
            self.renderer_calls
        );
        match &self.verdict {
            HuntVerdict::Differs(r) => s.push_str(&r.to_text(&format!("finding-{n:02}.json"), "their output", 50)),
            HuntVerdict::DiffersPerSample(r) => {
                s.push_str(&r.to_text(&format!("finding-{n:02}.json"), "their output", 50));
            }
            HuntVerdict::Failed(failure) => s.push_str(&format!("their renderer: {failure}\n")),
            HuntVerdict::Same => s.push_str("(the minimal scene no longer fails: the renderer is not deterministic)\n"),
            HuntVerdict::Refused(e) => s.push_str(&format!("the oracle refused the minimal scene: {e}\n")),
        }
        s.push_str("\nthe original scene:\n");
        s.push_str(&self.original.to_json());
        s
    }
}

impl HuntReport {
    /// The summary `rasterproof hunt` prints, a newline after each line: the counts with
    /// the canvas, convention and oracle (and the shard, when not the whole run), a line
    /// when the time budget stopped the hunt, a table of the findings (number, signature,
    /// cases, first case, primitives and canvas of the minimal scene), and, when there
    /// are findings and `out` names the folder their files went to, where.
    pub fn to_text(&self, out: Option<&Path>) -> String {
        let config = &self.config;
        let convention = config.overrides.apply(config.preset);
        let shard = if config.shard == Shard::WHOLE {
            String::new()
        } else {
            format!("shard {} of {} cases, ", config.shard, config.cases)
        };
        let mut lines = vec![format!(
            "hunt: {} scenes ({shard}{} px canvas, {}{}, oracle {}): {} identical, {} differ, {} failed, {} refused by the oracle",
            self.cases,
            config.canvas,
            match config.samples.as_ref().filter(|p| p.len() > 1) {
                Some(p) => format!("samples {p}, "),
                None => String::new(),
            },
            convention,
            config.model.name(),
            self.same,
            self.differing,
            self.failed,
            self.refused
        )];
        if let Some(r) = self.renderer_runs {
            lines.push(format!(
                "renderer: {} scene{} asked for, {} program start{}",
                r.calls,
                if r.calls == 1 { "" } else { "s" },
                r.starts,
                if r.starts == 1 { "" } else { "s" }
            ));
        }
        if self.interrupted {
            lines.push(format!(
                "stopped: interrupted after {} of {} cases; the findings are those cases' scenes, not shrunk",
                self.cases, self.requested
            ));
        }
        if self.stopped_by_time {
            lines.push(format!(
                "stopped: the time budget ({:?}) ran out after {} of {} cases",
                config.budget.unwrap_or_default(),
                self.cases,
                self.requested
            ));
        }
        if self.per_sample.iter().any(|p| p.cases > 0) {
            lines.push("by sample index:".to_string());
            lines.extend(self.per_sample.iter().map(|p| format!("  {}", p.to_text())));
        }
        if !self.findings.is_empty() {
            lines.push(format!(
                "{:<4} {:<44} {:>6} {:>6} {:>10} {:>7}",
                "", "finding", "cases", "first", "primitives", "canvas"
            ));
        }
        for (n, f) in self.findings.iter().enumerate() {
            lines.push(format!(
                "{:<4} {:<44} {:>6} {:>6} {:>10} {:>7}",
                format!("{:02}", n + 1),
                f.signature.describe(),
                f.cases,
                f.case,
                primitive_count(&f.minimal),
                format!("{}x{}", f.minimal.width, f.minimal.height)
            ));
        }
        if let (Some(dir), false) = (out, self.findings.is_empty()) {
            lines.push(format!(
                "wrote finding-NN.json / .txt / .rs for each into {}",
                dir.display()
            ));
        }
        lines.iter().map(|l| format!("{l}\n")).collect()
    }

    /// `per_sample`: `[{"index", "position", "cases", "pixels", "fits"}]` (positions as
    /// `[x, y]` fraction strings; `fits` null when not found), `null` for one sample.
    fn per_sample_json(&self) -> String {
        if self.per_sample.is_empty() {
            return "null".to_string();
        }
        let point = |p: &[BigRational; 2]| serde_json::json!([exact_text(&p[0]), exact_text(&p[1])]);
        let entries: Vec<serde_json::Value> = self
            .per_sample
            .iter()
            .map(|p| {
                serde_json::json!({
                    "index": p.index,
                    "position": point(&p.position),
                    "cases": p.cases,
                    "pixels": p.pixels,
                    "fits": p.fits.as_ref().map(|f| f.iter().map(point).collect::<Vec<_>>()),
                })
            })
            .collect();
        serde_json::Value::Array(entries).to_string()
    }

    /// The convention every scene stated, as a JSON object: `{"preset", "tie_rule",
    /// "pixel_centre", "subpixel_bits", "rounding"}`.
    fn convention_json(&self) -> String {
        let c = self.config.overrides.apply(self.config.preset);
        object(&[
            ("preset", j(c.preset.name())),
            ("tie_rule", j(c.tie_rule.name())),
            ("pixel_centre", j(c.pixel_centre.name())),
            ("subpixel_bits", j(&c.subpixel_bits)),
            ("rounding", j(c.rounding.name())),
        ])
    }

    /// The report as a JSON document (schema version [`HUNT_REPORT_VERSION`]; also in README's
    /// `hunt` section), `renderer` naming what was hunted (`hunt --cmd`'s command): one
    /// object, one field a line in this order, each finding on a line of its own, ending in
    /// a newline.
    ///
    /// - `format` (`"rasterproof hunt report"`), `version` (2: a finding is one cause,
    ///   its pixel kinds listed; version 1 had one finding per kind), `rasterproof` (the version
    ///   that ran it), `cmd` (`renderer`), `seed`;
    /// - `shard`: `{"k": K, "n": N}` (`{"k": 1, "n": 1}`: the whole run);
    /// - `cases` (the whole run's, `0..cases`), `cases_requested` (the shard's among them),
    ///   `cases_run` (the first of the shard's, in order), `stopped_by_time` (the budget
    ///   stopped the hunt before every requested case ran);
    /// - `families` (names), `canvas`, `float32_exact`, `samples` (the sample pattern every
    ///   scene states, as a scene writes it; `null`: one sample), `shrink_runs` (the runs allowed
    ///   per shrink), `time_budget_ms` (`null`: none), `convention` (`{"preset",
    ///   "tie_rule", "pixel_centre", "subpixel_bits", "rounding"}`), `model` (the oracle:
    ///   `exact-snapped` or `exact`);
    /// - `counts`: `{"same", "differ", "failed", "refused"}` over the cases run;
    /// - `renderer_runs`: `{"calls", "starts"}` for a program, else `null`;
    /// - `per_sample`: under a pattern of several samples, each sample index
    ///   ([`SampleIndexSummary`]): `{"index", "position", "cases", "pixels", "fits"}`;
    ///   `null` for one sample;
    /// - `findings`, by first case: `{"signature"` ([`Signature::describe`]), `"slug"`
    ///   ([`Signature::slug`]), `"kinds"` (the pixel kinds its cases showed: `["missing",
    ///   "extra"]`; `[]` for a renderer failure), `"first_case"`, `"cases"` (how many showed it),
    ///   `"primitives"` (of the minimal scene), `"scene"` (the minimal scene: the JSON
    ///   object [`Scene::to_json`] writes), `"shrink_runs"` (renderer runs the shrink
    ///   took), `"minimal_verdict"` (`differs`, `failed`, or `same` / `refused` when the
    ///   minimal scene no longer fails)`}`.
    ///
    /// ```
    /// use rasterproof::oracle::hunt::{hunt, HuntConfig};
    /// use rasterproof::oracle::renderer::program::{RenderFailure, FailureKind};
    /// // A renderer that always fails: one finding.
    /// let broken = |_: &rasterproof::scene::Scene| {
    ///     Err(RenderFailure { kind: FailureKind::Exit, message: "exit status 3".to_string() })
    /// };
    /// let config = HuntConfig { cases: 3, shrink_runs: 4, ..HuntConfig::default() };
    /// let report = hunt(&broken, &config, 1, &|| {}).unwrap();
    /// let v: serde_json::Value = serde_json::from_str(&report.to_json("broken")).unwrap();
    /// assert_eq!(v["format"], "rasterproof hunt report");
    /// assert_eq!(v["counts"]["failed"], 3);
    /// assert_eq!(v["findings"][0]["signature"], "non-zero exit");
    /// assert_eq!(v["findings"][0]["kinds"], serde_json::json!([]));
    /// assert!(v["findings"][0]["scene"]["triangles"].is_array());
    /// ```
    pub fn to_json(&self, renderer: &str) -> String {
        let c = &self.config;
        let findings: Vec<String> = self
            .findings
            .iter()
            .map(|f| {
                let scene = serde_json::from_str::<serde_json::Value>(&f.minimal.to_json())
                    .map_or_else(|_| j(&f.minimal.to_json()), |v| j(&v));
                object(&[
                    ("signature", j(&f.signature.describe())),
                    ("slug", j(&f.signature.slug())),
                    ("kinds", j(&f.kinds.iter().map(|k| k.name()).collect::<Vec<_>>())),
                    ("first_case", j(&f.case)),
                    ("cases", j(&f.cases)),
                    ("primitives", j(&primitive_count(&f.minimal))),
                    ("scene", scene),
                    ("shrink_runs", j(&f.runs)),
                    ("shrink_renderer_calls", j(&f.renderer_calls)),
                    ("minimal_verdict", j(CaseOutcome::of(&f.verdict).name())),
                ])
            })
            .collect();
        let findings = if findings.is_empty() {
            "[]".to_string()
        } else {
            format!("[\n    {}\n  ]", findings.join(",\n    "))
        };
        let families: Vec<&str> = c.families.iter().map(|f| f.name()).collect();
        let runs = self
            .renderer_runs
            .map(|r| object(&[("calls", j(&r.calls)), ("starts", j(&r.starts))]));
        let fields: [(&str, String); 23] = [
            ("format", j(HUNT_REPORT_FORMAT)),
            ("version", j(&HUNT_REPORT_VERSION)),
            ("rasterproof", j(env!("CARGO_PKG_VERSION"))),
            ("cmd", j(renderer)),
            ("seed", j(&c.seed)),
            (
                "shard",
                object(&[("k", j(&c.shard.index())), ("n", j(&c.shard.count()))]),
            ),
            ("cases", j(&c.cases)),
            ("cases_requested", j(&self.requested)),
            ("cases_run", j(&self.cases)),
            ("stopped_by_time", j(&self.stopped_by_time)),
            ("interrupted", j(&self.interrupted)),
            ("families", j(&families)),
            ("canvas", j(&c.canvas)),
            ("float32_exact", j(&c.float32_exact)),
            (
                "samples",
                c.samples
                    .as_ref()
                    .map_or_else(|| "null".to_string(), |p| p.to_json().to_string()),
            ),
            ("shrink_runs", j(&c.shrink_runs)),
            ("time_budget_ms", j(&c.budget.map(|b| b.as_millis()))),
            ("convention", self.convention_json()),
            ("model", j(c.model.name())),
            (
                "counts",
                object(&[
                    ("same", j(&self.same)),
                    ("differ", j(&self.differing)),
                    ("failed", j(&self.failed)),
                    ("refused", j(&self.refused)),
                ]),
            ),
            ("renderer_runs", runs.unwrap_or_else(|| "null".to_string())),
            ("per_sample", self.per_sample_json()),
            ("findings", findings),
        ];
        let body: Vec<String> = fields
            .iter()
            .map(|(key, value)| format!("  {}: {value}", j(key)))
            .collect();
        format!("{{\n{}\n}}\n", body.join(",\n"))
    }

    /// The report as JUnit XML, `renderer` naming what was hunted: one `<testsuite
    /// name="rasterproof hunt">` in a `<testsuites>`, with the seed, shard, cases, budget
    /// stop, convention, model and `renderer` as properties; one `<testcase
    /// classname="rasterproof.hunt" name="SIGNATURE">` per finding (by first case), holding
    /// a `<failure>` whose message is the signature and whose text gives the first case,
    /// how many cases showed it, and the minimal scene; then one passing `<testcase
    /// name="identical to the oracle">` whose `<system-out>` carries the counts. Every
    /// text is escaped for XML.
    ///
    /// ```
    /// use rasterproof::oracle::hunt::{hunt, HuntConfig};
    /// use rasterproof::oracle::renderer::program::{RenderFailure, FailureKind};
    /// let broken = |_: &rasterproof::scene::Scene| {
    ///     Err(RenderFailure { kind: FailureKind::Exit, message: "exit <3> & more".to_string() })
    /// };
    /// let config = HuntConfig { cases: 2, shrink_runs: 4, ..HuntConfig::default() };
    /// let xml = hunt(&broken, &config, 1, &|| {}).unwrap().junit("a < b");
    /// assert!(xml.contains("<testsuite name=\"rasterproof hunt\" tests=\"2\" failures=\"1\""));
    /// assert!(xml.contains("value=\"a &lt; b\""));
    /// assert!(xml.contains("exit &lt;3&gt; &amp; more"));
    /// assert_eq!(xml.matches("<testcase ").count(), 2);
    /// ```
    pub fn junit(&self, renderer: &str) -> String {
        let c = &self.config;
        let mut cases: Vec<TestCase> = self.findings.iter().map(finding_case).collect();
        let mut out = format!(
            "{} identical, {} differ, {} failed, {} refused by the oracle, of {} cases run ({} requested)",
            self.same, self.differing, self.failed, self.refused, self.cases, self.requested
        );
        if self.stopped_by_time {
            out.push_str("; stopped by the time budget");
        }
        cases.push(TestCase {
            classname: "rasterproof.hunt".to_string(),
            name: "identical to the oracle".to_string(),
            failure: None,
            skipped: None,
            system_out: Some(out),
        });
        let properties = [
            ("rasterproof", env!("CARGO_PKG_VERSION").to_string()),
            ("cmd", renderer.to_string()),
            ("seed", c.seed.to_string()),
            ("shard", c.shard.to_string()),
            ("cases", c.cases.to_string()),
            ("cases_requested", self.requested.to_string()),
            ("cases_run", self.cases.to_string()),
            ("stopped_by_time", self.stopped_by_time.to_string()),
            ("convention", c.overrides.apply(c.preset).to_string()),
            ("model", c.model.name().to_string()),
        ];
        TestSuites {
            name: "rasterproof hunt".to_string(),
            suites: vec![TestSuite {
                name: "rasterproof hunt".to_string(),
                properties: properties.map(|(name, value)| (name.to_string(), value)).to_vec(),
                cases,
            }],
        }
        .to_xml()
    }
}

/// A finding as a failed JUnit test case named by its signature: the message counts its
/// cases, the text gives its first case, the minimal scene and, when their renderer
/// failed on that scene, how.
fn finding_case(f: &HuntFinding) -> TestCase {
    let description = f.signature.describe();
    let message = format!("{description}: {} cases, first case {}", f.cases, f.case);
    let mut text = format!(
        "{description}\nfirst case: {} ({} cases showed it)\nminimal scene ({} primitives, {}x{}, {} shrink runs):\n{}",
        f.case,
        f.cases,
        primitive_count(&f.minimal),
        f.minimal.width,
        f.minimal.height,
        f.runs,
        f.minimal.to_json()
    );
    if let HuntVerdict::Failed(failure) = &f.verdict {
        let _ = write!(text, "\ntheir renderer on the minimal scene: {failure}");
    }
    TestCase {
        classname: "rasterproof.hunt".to_string(),
        name: description,
        failure: Some(JunitFailure {
            kind: "finding".to_string(),
            message,
            text,
        }),
        skipped: None,
        system_out: None,
    }
}

#[cfg(test)]
mod tests {
    use std::time::Duration;

    use super::*;
    use crate::harness::suite::Shard;
    use crate::oracle::hunt::hunt;
    use crate::oracle::renderer::program::RenderFailure;
    use crate::oracle::theirs::Theirs;

    /// A report of no case is still a whole document: every field, empty findings.
    #[test]
    fn an_empty_report_has_every_field() {
        let config = HuntConfig {
            cases: 4,
            shard: Shard::new(3, 3).unwrap(),
            budget: Some(Duration::from_millis(1500)),
            ..HuntConfig::default()
        };
        let never = |_: &Scene| -> Result<Theirs, RenderFailure> { unreachable!("no case runs") };
        let report = hunt(
            &never,
            &HuntConfig {
                budget: Some(Duration::ZERO),
                ..config.clone()
            },
            1,
            &|| {},
        )
        .unwrap();
        let report = HuntReport { config, ..report };
        let v: serde_json::Value = serde_json::from_str(&report.to_json("r \"q\"")).unwrap();
        let keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
        for key in [
            "format",
            "version",
            "rasterproof",
            "cmd",
            "seed",
            "shard",
            "cases",
            "cases_requested",
            "cases_run",
            "stopped_by_time",
            "interrupted",
            "families",
            "canvas",
            "float32_exact",
            "samples",
            "shrink_runs",
            "time_budget_ms",
            "convention",
            "model",
            "counts",
            "renderer_runs",
            "per_sample",
            "findings",
        ] {
            assert!(keys.contains(&key), "{key}: {keys:?}");
        }
        assert_eq!(keys.len(), 23);
        assert_eq!(v["samples"], serde_json::Value::Null, "one sample per pixel");
        assert_eq!(v["per_sample"], serde_json::Value::Null, "one sample per pixel");
        assert_eq!(
            v["renderer_runs"],
            serde_json::Value::Null,
            "a closure is not a program"
        );
        assert_eq!(v["cmd"], "r \"q\"");
        assert_eq!(v["shard"], serde_json::json!({"k": 3, "n": 3}));
        assert_eq!((&v["cases_requested"], &v["cases_run"]), (&1.into(), &0.into()));
        assert_eq!(v["time_budget_ms"], 1500);
        assert_eq!(v["stopped_by_time"], true);
        let x = report.junit("r \"q\"");
        assert!(
            x.contains("value=\"r &quot;q&quot;\"") && x.contains("stopped by the time budget"),
            "{x}"
        );
        assert_eq!(x.matches("<testcase ").count(), 1);
    }
}
