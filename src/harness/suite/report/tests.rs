//! Tests of the suite's report: findings, JSON read back, merging shards and refusing
//! other runs, JUnit XML, bad report files.

use super::*;
use crate::check::Violation;
use crate::harness::suite::{Shard, Skip};
use crate::model::Model;
use crate::scene::Scene;

fn outcome(invariant: &'static str, model: Model, result: Result<(), Violation>) -> CheckOutcome {
    CheckOutcome {
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
fn report(shard: Shard) -> SuiteReport {
    let mut r = SuiteReport::new(5, 4, shard);
    for k in shard.cases(4) {
        let path = move |o: &CheckOutcome| o.is_fatal().then(|| format!("out/case-{k}.json"));
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
        &"  watertight             fixed                  1x, first case 3 (FATAL): pixel (3, 1) is covered 0 times, by []"
            .to_string()
    ));
    assert_eq!(lines.last().unwrap(), &r.tally().verdict());
}

#[test]
fn json_reads_back_to_the_same_report() {
    for r in [report(Shard::WHOLE), report(Shard::new(2, 2).unwrap())] {
        let text = r.to_json();
        let back = SuiteReport::from_json(&text, "r.json").unwrap();
        assert_eq!(back, r);
        assert_eq!(back.to_json(), text);
        assert_eq!(back.lines(), r.lines());
    }
    let mut stopped = report(Shard::WHOLE);
    stopped.stop("interrupted after 4 of 4 cases");
    assert_eq!(SuiteReport::from_json(&stopped.to_json(), "s").unwrap(), stopped);
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
        let merged = SuiteReport::merge(parts.into_iter().map(|r| ("x".to_string(), r))).unwrap();
        assert_eq!(merged, whole);
        assert_eq!(merged.to_json(), whole.to_json());
    }
}

#[test]
fn merge_refuses_other_runs_and_overlaps_naming_the_files() {
    let a = report(Shard::new(1, 2).unwrap());
    let b = report(Shard::new(2, 2).unwrap());
    let named =
        |x: &SuiteReport, y: &SuiteReport| [("a.json".to_string(), x.clone()), ("b.json".to_string(), y.clone())];
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
        let e = SuiteReport::merge(named(&a, y)).unwrap_err();
        assert!(e.starts_with("a.json and b.json: ") && e.contains(words), "{e}");
    }
    assert!(SuiteReport::merge(Vec::new()).is_err());
}

#[test]
fn junit_has_a_test_case_per_row_and_fails_the_fatal_one() {
    let r = report(Shard::WHOLE);
    let xml = r.junit();
    let rows = r.tally().rows().count();
    assert_eq!(rows, 3);
    assert_eq!(xml.matches("<testcase ").count(), rows);
    assert!(
        xml.contains("<testsuites name=\"rasterproof check\" tests=\"3\" failures=\"1\" errors=\"0\" skipped=\"1\">")
    );
    assert!(xml.contains(
        "<testcase classname=\"rasterproof.check\" name=\"watertight / fixed\">\n      <failure type=\"violation\" message=\"1 of 4 cases violate watertight on fixed\">case 3: watertight violated: pixel (3, 1) is covered 0 times, by []\n  scene: out/case-3.json\n</failure>"
    ), "{xml}");
    assert!(xml.contains("name=\"triangulation / fixed\">\n      <skipped message=\"all 4 cases skipped"));
    assert!(xml.contains("4 of 4 cases violate it: a float model&apos;s measured trade"));
    assert_eq!(xml.matches("<failure ").count(), 1);
    assert_eq!(xml.matches("</failure>").count(), 1);
    assert!(!xml.contains('\u{1}'));
    // A report without failures fails no test case.
    let passing = SuiteReport::new(5, 0, Shard::WHOLE).junit();
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
        let e = SuiteReport::from_json(&text, "r.json").unwrap_err();
        assert!(e.starts_with(expected), "{expected}\n{e}");
    }
}
