//! `rasterproof hunt` and `oracle::hunt`: renderers made wrong in one known way are found
//! and shrunk to at most 2 primitives on at most 4x4 pixels; an honest renderer, and a
//! wrong one hunted under its own fitted convention, give nothing; a renderer that exits
//! non-zero, hangs, writes garbage or nothing is a finding of that kind; bad `--cmd`s exit
//! 2; no temporary file is left behind.

use assert_cmd::Command;
use rasterproof::convention::AnyTieRule;
use rasterproof::coverage::Coverage;
use rasterproof::model::{render, Model};
use rasterproof::oracle::hunt::{hunt, primitive_count, HuntConfig, HuntVerdict, Signature};
use rasterproof::oracle::renderer::program::FailureKind;
use rasterproof::oracle::{Format, PixelKind, ReasonClass, Theirs};
use rasterproof::tri::planned::PlannedTriangle;

use crate::tempdir;

/// A folder with a tag unique in this test binary.
fn fresh_dir(what: &str) -> tempdir::Dir {
    static N: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    tempdir::Dir::new(&format!(
        "{what}-{}",
        N.fetch_add(1, std::sync::atomic::Ordering::Relaxed)
    ))
}

fn rasterproof() -> String {
    assert_cmd::cargo::cargo_bin("rasterproof").display().to_string()
}

/// `hunt` with `args`, its temporaries in a fresh folder (TMPDIR) that must be empty
/// afterwards: (exit code, stdout, stderr).
fn hunt_cli(args: &[&str]) -> (i32, String, String) {
    let tmp = fresh_dir("hunt-tmp");
    let out = Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("hunt")
        .args(args)
        .arg("--quiet")
        .env("TMPDIR", tmp.path())
        .output()
        .unwrap();
    let left: Vec<_> = std::fs::read_dir(tmp.path()).unwrap().collect();
    assert!(left.is_empty(), "temporaries left behind: {left:?}");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// Every finding's minimal scene, read back from `dir`.
fn minimal_scenes(dir: &std::path::Path) -> Vec<rasterproof::scene::Scene> {
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    files
        .iter()
        .map(|p| rasterproof::scene::parse_scene(&std::fs::read_to_string(p).unwrap(), "f.json").unwrap())
        .collect()
}

#[test]
fn wrong_tie_rule_and_coarse_snapping_are_found_and_shrunk() {
    for (wrong, class) in [("--preset gl", "tie"), ("--subpixel-bits 4", "snapping")] {
        let dir = fresh_dir("hunt-out");
        let cmd = format!("{} render {{scene}} {wrong} --ids-out {{out}}", rasterproof());
        let (code, stdout, stderr) = hunt_cli(&["--cmd", &cmd, "--cases", "40", "--out", dir.path().to_str().unwrap()]);
        assert_eq!(code, 1, "{wrong}: {stdout}{stderr}");
        assert!(stdout.contains(&format!(" {class}, ")), "{wrong}: {stdout}");
        let scenes = minimal_scenes(dir.path());
        assert!(!scenes.is_empty());
        for s in &scenes {
            assert!(primitive_count(s) <= 2, "{wrong}: {}", s.to_json());
            assert!(s.width <= 4 && s.height <= 4, "{wrong}: {}", s.to_json());
        }
        let test = std::fs::read_to_string(dir.path().join("finding-01.rs")).unwrap();
        assert!(
            test.contains("#[test]") && test.contains("fn hunt_finding_01_"),
            "{test}"
        );
        assert!(test.contains("assert_eq!(oracle.owners("), "{test}");
        let txt = std::fs::read_to_string(dir.path().join("finding-01.txt")).unwrap();
        assert!(txt.contains(class), "{txt}");
    }
}

#[test]
fn honest_and_fitted_renderers_give_nothing() {
    let honest = format!("{} render {{scene}} --ids-out {{out}}", rasterproof());
    let (code, stdout, _) = hunt_cli(&["--cmd", &honest, "--cases", "24", "--jobs", "2"]);
    assert_eq!(code, 0, "{stdout}");
    assert!(
        stdout.contains("24 identical") || stdout.contains("refused"),
        "{stdout}"
    );
    // The GL renderer hunted under the convention fitted to it: bottom-left, found first.
    let gl = format!("{} render {{scene}} --preset gl --ids-out {{out}}", rasterproof());
    let (code, stdout, stderr) = hunt_cli(&["--cmd", &gl, "--cases", "24", "--fit-first"]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(stderr.contains("fit: hunting under tie rule bottom-left"), "{stderr}");
    assert!(stdout.contains("tie rule bottom-left"), "{stdout}");
}

#[test]
fn failing_programs_are_findings_and_bad_commands_exit_2() {
    for (cmd, kind) in [
        ("sh -c 'exit 3' {scene} {out}", "non-zero exit"),
        ("sh -c 'kill -SEGV $$' {scene} {out}", "crash"),
        ("sh -c 'sleep 5' {scene} {out}", "timeout"),
        ("sh -c 'echo junk > \"$1\"' {scene} {out}", "unreadable output"),
        ("true {scene} {out}", "no output"),
    ] {
        let (code, stdout, stderr) =
            hunt_cli(&["--cmd", cmd, "--cases", "2", "--timeout", "0.3", "--shrink-runs", "5"]);
        assert_eq!(code, 1, "{cmd}: {stdout}{stderr}");
        assert!(stdout.contains(&format!("01   {kind}")), "{cmd}: {stdout}");
        assert!(stdout.contains("2 failed"), "{cmd}: {stdout}");
    }
    for (cmd, message) in [
        ("no-such-program-anywhere {scene} {out}", "not found"),
        ("true {scene}", "has no {out} placeholder"),
        ("", "--cmd: empty"),
        ("true '{scene} {out}", "cannot split"),
    ] {
        let (code, _, stderr) = hunt_cli(&["--cmd", cmd, "--cases", "2"]);
        assert_eq!(code, 2, "{cmd}: {stderr}");
        assert!(
            stderr.starts_with("error: ") && stderr.contains(message),
            "{cmd}: {stderr}"
        );
    }
    let (code, _, stderr) = hunt_cli(&["--cmd", "true {scene} {out}", "--family", "cubes"]);
    assert_eq!(code, 2);
    assert!(stderr.contains("--family: unknown family \"cubes\""), "{stderr}");
}

/// The planned engine under the top-right tie rule for triangles (lines and polygons drawn
/// honestly): a renderer wrong at ties only.
pub(crate) fn top_right(
    s: &rasterproof::scene::Scene,
) -> Result<Theirs, rasterproof::oracle::renderer::program::RenderFailure> {
    let target = s.target().unwrap();
    let mut c = Coverage::new(s.width, s.height);
    for (k, t) in s.triangles().iter().enumerate() {
        let t = t.snapped(&target.convention).to_exact();
        if let Some(p) = PlannedTriangle::with_rule(&t, &target, AnyTieRule::TopRight) {
            p.rasterize(u32::try_from(k).unwrap(), &mut c);
        }
    }
    // Lines and polygons drawn honestly.
    let rest = rasterproof::model::Primitives {
        triangles: Vec::new(),
        ..s.primitives()
    };
    let offset = u32::try_from(s.triangles.len()).unwrap();
    for (x, y, ids) in render(&rest, &target, Model::ExactSnapped).unwrap().iter() {
        for id in ids {
            rasterproof::coverage::CoverageSink::cover(&mut c, x, y, id + offset);
        }
    }
    Ok(Theirs::from_coverage(&c, Format::Json))
}

/// The library with a Rust closure as the renderer: top-right ties (the planned engine
/// under that rule) are found as ties on triangles, shrunk to at most 2 triangles on at
/// most 4x4 pixels, and the minimal scene still shows the failure.
#[test]
fn a_closure_renderer_is_hunted_and_its_failures_shrunk() {
    let config = HuntConfig {
        cases: 32,
        families: vec![rasterproof::oracle::hunt::SceneFamily::Mesh],
        ..HuntConfig::default()
    };
    let report = hunt(&top_right, &config, 2, &|| {}).unwrap();
    assert!(report.differing > 0);
    // One cause, one finding: the wrong tie rule shows as pixels of several kinds
    // (wrong owner on shared edges, missing or extra on the mesh's outline), listed in it.
    assert_eq!(
        report.findings.len(),
        1,
        "{:?}",
        report
            .findings
            .iter()
            .map(|f| f.signature.describe())
            .collect::<Vec<_>>()
    );
    assert!(report.findings[0].kinds.len() >= 2, "{:?}", report.findings[0].kinds);
    for f in &report.findings {
        let Signature::Pixel(class, kind) = &f.signature else {
            panic!("{f:?}")
        };
        assert_eq!((*class, kind.as_str()), (ReasonClass::Tie, "triangles"));
        assert!(
            primitive_count(&f.minimal) <= 2 && f.minimal.width <= 4 && f.minimal.height <= 4,
            "{}",
            f.minimal.to_json()
        );
        let HuntVerdict::Differs(r) = &f.verdict else {
            panic!("{:?}", f.verdict)
        };
        assert!(r.pixels.iter().any(|p| matches!(
            p.kind,
            PixelKind::Missing | PixelKind::Extra | PixelKind::WrongOwner | PixelKind::Double
        )));
    }
    assert_eq!(report.same + report.differing + report.failed + report.refused, 32);
    let _ = FailureKind::Exit;
}

/// `hunt --fit-first` on a renderer with top-right ties: the fit identifies the rule, and
/// since a scene file cannot state it, that is the answer (what the renderer follows),
/// not an error: the CLI prints it and exits 1, as `compare --fit` does for its findings.
#[test]
fn a_fit_first_that_finds_an_unstatable_rule_names_it() {
    let found = rasterproof::oracle::hunt::fit_convention(&top_right, &HuntConfig::default()).unwrap();
    let rasterproof::oracle::hunt::FitFirst::Unstatable(fits) = found else {
        panic!("expected an unstatable fit, got {found:?}")
    };
    assert!(!fits.is_empty());
    assert!(fits.iter().all(|c| c.tie_rule == AnyTieRule::TopRight), "{fits:?}");
}

/// The renderer that snaps to 1/16 px instead of 1/256 (wrong in every family), as a
/// `--cmd`.
fn coarse_cmd() -> String {
    format!("{} render {{scene}} --subpixel-bits 4 --ids-out {{out}}", rasterproof())
}

/// `hunt` with `args` and `--report` into a fresh folder: (exit code, the report as JSON,
/// stdout and stderr).
fn hunt_report(args: &[&str]) -> (i32, serde_json::Value, String) {
    let dir = fresh_dir("hunt-report");
    let path = dir.path().join("report.json");
    let mut all = args.to_vec();
    all.extend(["--report", path.to_str().unwrap()]);
    let (code, stdout, stderr) = hunt_cli(&all);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{args:?}: no report ({e}): {stdout}{stderr}"));
    let report = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{args:?}: {e}: {text}"));
    (code, report, format!("{stdout}{stderr}"))
}

/// A JSON number as u64.
fn n(v: &serde_json::Value) -> u64 {
    v.as_u64().unwrap_or_else(|| panic!("not a count: {v}"))
}

/// The four counts of a report, and their sum.
fn counts(r: &serde_json::Value) -> ([u64; 4], u64) {
    let c = &r["counts"];
    let four = [n(&c["same"]), n(&c["differ"]), n(&c["failed"]), n(&c["refused"])];
    (four, four.iter().sum())
}

/// A report's findings by signature: (first case, cases, minimal scene).
fn findings_by_signature(r: &serde_json::Value) -> std::collections::BTreeMap<String, (u64, u64, serde_json::Value)> {
    r["findings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            (
                f["signature"].as_str().unwrap().to_string(),
                (n(&f["first_case"]), n(&f["cases"]), f["scene"].clone()),
            )
        })
        .collect()
}

/// `--shard 1/2` and `--shard 2/2` with the unsharded hunt's seed and cases: each runs its
/// half (13 and 12 of 25, its findings' first cases in its residue class), their counts
/// add up to the unsharded run's, every signature's case count is the sum of the shards',
/// its first case the lower of theirs, and the shard holding that case shrinks it to the
/// unsharded run's minimal scene.
#[test]
fn sharded_hunts_add_up_to_the_unsharded_one() {
    let cmd = coarse_cmd();
    let common = [
        "--cmd",
        cmd.as_str(),
        "--cases",
        "25",
        "--seed",
        "3",
        "--shrink-runs",
        "20",
    ];
    let (code, whole, out) = hunt_report(&common);
    assert_eq!(code, 1, "{out}");
    let (whole_counts, whole_sum) = counts(&whole);
    assert_eq!(whole_sum, 25);
    assert_eq!((n(&whole["cases_requested"]), n(&whole["cases_run"])), (25, 25));
    let mut shards = Vec::new();
    for (k, expected) in [(1u64, 13u64), (2, 12)] {
        let shard = format!("{k}/2");
        let mut args = common.to_vec();
        args.extend(["--shard", shard.as_str()]);
        let (code, r, out) = hunt_report(&args);
        assert_eq!(r["shard"], serde_json::json!({"k": k, "n": 2}), "{out}");
        assert_eq!(n(&r["cases"]), 25);
        assert_eq!(
            (n(&r["cases_requested"]), n(&r["cases_run"])),
            (expected, expected),
            "{out}"
        );
        assert_eq!(r["stopped_by_time"], false);
        assert_eq!(counts(&r).1, expected, "{out}");
        assert!(
            out.contains(&format!("hunt: {expected} scenes (shard {k}/2 of 25 cases")),
            "{out}"
        );
        let found = findings_by_signature(&r);
        assert_eq!(code, if found.is_empty() { 0 } else { 1 }, "{out}");
        for (sig, (first, _, _)) in &found {
            assert_eq!(first % 2, k - 1, "{sig}: case {first} is not in shard {k}/2");
        }
        shards.push((counts(&r).0, found));
    }
    for (i, whole) in whole_counts.iter().enumerate() {
        assert_eq!(shards[0].0[i] + shards[1].0[i], *whole, "count {i}");
    }
    let whole_found = findings_by_signature(&whole);
    let union: std::collections::BTreeSet<&String> = shards.iter().flat_map(|s| s.1.keys()).collect();
    assert_eq!(union, whole_found.keys().collect(), "signatures");
    assert!(
        shards.iter().all(|s| !s.1.is_empty()),
        "each shard finds something: {whole_found:?}"
    );
    for (sig, (first, cases, scene)) in &whole_found {
        let parts: Vec<_> = shards.iter().filter_map(|s| s.1.get(sig)).collect();
        assert_eq!(parts.iter().map(|p| p.1).sum::<u64>(), *cases, "{sig}: cases");
        let lowest = parts.iter().min_by_key(|p| p.0).unwrap();
        assert_eq!(lowest.0, *first, "{sig}: first case");
        assert_eq!(&lowest.2, scene, "{sig}: the same case shrinks to the same scene");
    }
}

/// `--time 0s` runs no case and says so; a short budget stops a long hunt early with the
/// first cases of its shard run: its findings' first cases are among them, its counts add
/// up to the cases run, and the exit code follows the findings.
#[test]
fn a_time_budget_stops_the_hunt_and_the_report_says_so() {
    let cmd = coarse_cmd();
    let (code, r, out) = hunt_report(&["--cmd", &cmd, "--cases", "10", "--time", "0s"]);
    assert_eq!(code, 0, "{out}");
    assert_eq!((n(&r["cases_requested"]), n(&r["cases_run"])), (10, 0));
    assert_eq!(r["stopped_by_time"], true);
    assert_eq!(r["time_budget_ms"], 0);
    assert_eq!(counts(&r).1, 0);
    assert_eq!(r["findings"], serde_json::json!([]));
    assert!(
        out.contains("stopped: the time budget (0ns) ran out after 0 of 10 cases"),
        "{out}"
    );

    let (code, r, out) = hunt_report(&[
        "--cmd",
        &cmd,
        "--cases",
        "3000",
        "--shard",
        "2/3",
        "--time",
        "400ms",
        "--shrink-runs",
        "3",
        "--jobs",
        "2",
    ]);
    let run = n(&r["cases_run"]);
    assert_eq!(n(&r["cases_requested"]), 1000);
    assert!(run < 1000, "{out}");
    assert_eq!(r["stopped_by_time"], true, "{out}");
    assert_eq!(counts(&r).1, run, "{out}");
    let found = findings_by_signature(&r);
    assert_eq!(code, if found.is_empty() { 0 } else { 1 }, "{out}");
    for (sig, (first, cases, _)) in &found {
        assert_eq!(first % 3, 1, "{sig}");
        assert!(
            (first - 1) / 3 < run,
            "{sig}: case {first} is not among the first {run} of shard 2/3"
        );
        assert!(*cases <= run, "{sig}");
    }
}

/// Whether `xml` is well-formed as far as these reports go: one root element, every
/// element closed in order, attribute values quoted, and no `<` or bare `&` in text or
/// attribute values (only the five named entities and character references).
pub(crate) fn well_formed(xml: &str) -> Result<(), String> {
    fn entities_ok(s: &str) -> Result<(), String> {
        let mut rest = s;
        while let Some(i) = rest.find('&') {
            rest = &rest[i + 1..];
            let end = rest.find(';').ok_or_else(|| format!("bare & in {s:?}"))?;
            let name = &rest[..end];
            let ok = ["amp", "lt", "gt", "quot", "apos"].contains(&name)
                || name
                    .strip_prefix('#')
                    .is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()));
            if !ok {
                return Err(format!("bad entity &{name}; in {s:?}"));
            }
        }
        if s.contains('<') {
            return Err(format!("< in {s:?}"));
        }
        Ok(())
    }
    let body = match xml.strip_prefix("<?xml") {
        Some(rest) => &rest[rest.find("?>").ok_or("unclosed prolog")? + 2..],
        None => xml,
    };
    let mut stack: Vec<String> = Vec::new();
    let mut roots = 0;
    let mut rest = body;
    while !rest.is_empty() {
        let Some(open) = rest.find('<') else {
            entities_ok(rest)?;
            if !rest.trim().is_empty() && stack.is_empty() {
                return Err(format!("text outside the root: {rest:?}"));
            }
            break;
        };
        entities_ok(&rest[..open])?;
        rest = &rest[open + 1..];
        if let Some(after) = rest.strip_prefix('/') {
            let end = after.find('>').ok_or("unclosed end tag")?;
            let name = after[..end].trim();
            if stack.pop().as_deref() != Some(name) {
                return Err(format!("</{name}> closes nothing open"));
            }
            rest = &after[end + 1..];
            continue;
        }
        // A start tag: the name, then name="value" pairs, then > or />.
        let name_end = rest
            .find(|c: char| c.is_whitespace() || c == '>' || c == '/')
            .ok_or("unclosed tag")?;
        let name = rest[..name_end].to_string();
        if name.is_empty() {
            return Err("a tag without a name".to_string());
        }
        rest = &rest[name_end..];
        loop {
            rest = rest.trim_start();
            if let Some(r) = rest.strip_prefix("/>") {
                rest = r;
                if stack.is_empty() {
                    roots += 1;
                }
                break;
            }
            if let Some(r) = rest.strip_prefix('>') {
                rest = r;
                if stack.is_empty() {
                    roots += 1;
                }
                stack.push(name.clone());
                break;
            }
            let eq = rest
                .find('=')
                .ok_or_else(|| format!("<{name}: attribute without a value"))?;
            let value = rest[eq + 1..]
                .strip_prefix('"')
                .ok_or_else(|| format!("<{name}: unquoted attribute"))?;
            let close = value.find('"').ok_or_else(|| format!("<{name}: unclosed attribute"))?;
            entities_ok(&value[..close])?;
            rest = &value[close + 1..];
        }
    }
    if !stack.is_empty() {
        return Err(format!("unclosed: {stack:?}"));
    }
    if roots != 1 {
        return Err(format!("{roots} root elements"));
    }
    Ok(())
}

#[test]
fn the_well_formedness_check_has_teeth() {
    assert_eq!(
        well_formed("<?xml version=\"1.0\"?>\n<a x=\"1 &amp; 2\"><b/>t &lt; u</a>\n"),
        Ok(())
    );
    for bad in [
        "<a><b></a></b>",
        "<a>x & y</a>",
        "<a x=\"<\"/>",
        "<a x=1/>",
        "<a></a><b/>",
        "<a>",
        "<a>&bogus;</a>",
    ] {
        assert!(well_formed(bad).is_err(), "{bad}");
    }
}

/// One hunt writing both `--report` and `--junit`: the report has the documented fields,
/// each finding's minimal scene parses as a scene file and, rendered again by the same
/// program, still shows its signature; the JUnit XML is well-formed (the command's `<&>`
/// escaped), with one failed test case per finding and one passing one.
#[test]
fn the_report_and_junit_describe_every_finding() {
    let dir = fresh_dir("hunt-report-junit");
    let (json, xml) = (dir.path().join("hunt.json"), dir.path().join("hunt.xml"));
    let cmd = format!(
        "sh -c 'exec \"$0\" render \"$1\" --subpixel-bits 4 --ids-out \"$2\" # <&>' {} {{scene}} {{out}}",
        rasterproof()
    );
    let args = [
        "--cmd",
        &cmd,
        "--cases",
        "12",
        "--seed",
        "5",
        "--shrink-runs",
        "25",
        "--family",
        "mesh,triangles,lines",
    ];
    let mut all = args.to_vec();
    all.extend(["--report", json.to_str().unwrap(), "--junit", xml.to_str().unwrap()]);
    let (code, stdout, stderr) = hunt_cli(&all);
    assert_eq!(code, 1, "{stdout}{stderr}");
    let r: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(r["format"], "rasterproof hunt report");
    assert_eq!(r["version"], 2);
    assert_eq!(r["rasterproof"], env!("CARGO_PKG_VERSION"));
    assert_eq!(r["cmd"], cmd.as_str());
    assert_eq!(
        (
            n(&r["seed"]),
            n(&r["cases"]),
            n(&r["cases_requested"]),
            n(&r["cases_run"])
        ),
        (5, 12, 12, 12)
    );
    assert_eq!(r["shard"], serde_json::json!({"k": 1, "n": 1}));
    assert_eq!(r["stopped_by_time"], false);
    assert_eq!(r["families"], serde_json::json!(["mesh", "triangles", "lines"]));
    assert_eq!(r["model"], "exact-snapped");
    assert_eq!(r["convention"]["preset"], "d3d11");
    assert_eq!(r["convention"]["subpixel_bits"], 8);
    assert_eq!(r["convention"]["tie_rule"], "top-left");
    assert_eq!(counts(&r).1, 12);
    let findings = r["findings"].as_array().unwrap();
    assert!(!findings.is_empty());
    assert!(stdout.contains(&format!("{:02}   ", findings.len())), "{stdout}");
    // Each pixel finding lists the kinds of pixels its cause showed; a failure none.
    for f in findings {
        let kinds = f["kinds"].as_array().unwrap();
        // A pixel signature is `class, primitive kind`; a failure's is one name.
        let pixel = f["signature"].as_str().unwrap().contains(", ");
        assert_eq!(!kinds.is_empty(), pixel, "{f}");
    }

    let program = rasterproof::oracle::renderer::program::Program::new(
        &cmd,
        Format::Ids,
        rasterproof::oracle::Background::default(),
        std::time::Duration::from_secs(10),
    )
    .unwrap();
    for f in findings {
        let sig = f["signature"].as_str().unwrap();
        let scene_text = serde_json::to_string(&f["scene"]).unwrap();
        let scene = rasterproof::scene::parse_scene(&scene_text, "finding.json").unwrap();
        assert_eq!(n(&f["primitives"]), primitive_count(&scene) as u64, "{sig}");
        assert!(n(&f["cases"]) >= 1 && n(&f["first_case"]) < 12, "{sig}");
        assert!(n(&f["shrink_runs"]) <= 25, "{sig}");
        assert_eq!(f["minimal_verdict"], "differs", "{sig}");
        let again = rasterproof::oracle::hunt::signatures(&rasterproof::oracle::hunt::judge(
            &scene,
            program.render(&scene),
            Model::ExactSnapped,
        ));
        let shown = again.iter().find(|s| s.describe() == sig);
        let shown = shown.unwrap_or_else(|| panic!("{sig}: the minimal scene shows only {again:?}"));
        assert_eq!(f["slug"], shown.slug().as_str());
        assert!(shown
            .slug()
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_'));
    }
    drop(program);

    let x = std::fs::read_to_string(&xml).unwrap();
    well_formed(&x).unwrap_or_else(|e| panic!("{e}: {x}"));
    assert_eq!(x.matches("<testcase ").count(), findings.len() + 1, "{x}");
    assert_eq!(x.matches("<failure ").count(), findings.len(), "{x}");
    assert!(
        x.contains(&format!(
            "<testsuite name=\"rasterproof hunt\" tests=\"{}\" failures=\"{}\"",
            findings.len() + 1,
            findings.len()
        )),
        "{x}"
    );
    assert!(x.contains("# &lt;&amp;&gt;"), "the command is escaped: {x}");
    assert!(x.contains("name=\"identical to the oracle\""), "{x}");
    let (c, sum) = counts(&r);
    assert!(
        x.contains(&format!(
            "{} identical, {} differ, {} failed, {} refused",
            c[0], c[1], c[2], c[3]
        )) && sum == 12,
        "{x}"
    );
    for f in findings {
        let sig = f["signature"].as_str().unwrap();
        assert!(
            x.contains(&format!("<testcase classname=\"rasterproof.hunt\" name=\"{sig}\">")),
            "{sig}: {x}"
        );
        assert!(
            x.contains(&format!("first case: {}", n(&f["first_case"]))),
            "{sig}: {x}"
        );
    }
    assert!(
        x.contains("&quot;triangles&quot;"),
        "the minimal scenes are in the failures: {x}"
    );
}

/// Bad `--shard` and `--time` values, and `--report` and `--junit` naming one file, exit 2
/// naming the option (and write nothing).
#[test]
fn bad_shard_time_and_output_options_exit_2() {
    let cmd = coarse_cmd();
    for (option, value, message) in [
        ("--shard", "3/2", "K must be in 1..=2"),
        ("--shard", "0/2", "K must be in 1..=2"),
        ("--shard", "2", "expected K/N"),
        ("--time", "nonsense", "expected a duration"),
        ("--time", "90", "expected a duration"),
    ] {
        let (code, stdout, stderr) = hunt_cli(&["--cmd", &cmd, "--cases", "2", option, value]);
        assert_eq!(code, 2, "{option} {value}: {stdout}{stderr}");
        assert!(
            stderr.starts_with("error: ")
                && stderr.contains(option)
                && stderr.contains(value)
                && stderr.contains(message),
            "{option} {value}: {stderr}"
        );
    }
    let dir = fresh_dir("hunt-same-file");
    let same = dir.path().join("out.json");
    let same = same.to_str().unwrap();
    let (code, _, stderr) = hunt_cli(&["--cmd", &cmd, "--cases", "2", "--report", same, "--junit", same]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("--report and --junit: both name"), "{stderr}");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    let missing = dir.path().join("no-such-folder").join("r.json");
    let (code, _, stderr) = hunt_cli(&["--cmd", &cmd, "--cases", "2", "--report", missing.to_str().unwrap()]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("cannot write: no folder"), "{stderr}");
}

/// The library: a time-limited hunt on two threads runs exactly the first cases of its
/// shard (an honest renderer, which is never called by a shrink, records every scene it
/// was given), and the shards of a closure hunt partition it whatever the threads.
#[test]
fn a_time_limited_hunt_runs_the_first_cases_of_its_shard() {
    use rasterproof::harness::suite::Shard;
    use rasterproof::oracle::hunt::{generate_scene, SceneFamily};
    let seen = std::sync::Mutex::new(Vec::new());
    let honest = |s: &rasterproof::scene::Scene| {
        seen.lock().unwrap().push(s.to_json());
        std::thread::sleep(std::time::Duration::from_millis(10));
        let c = render(&s.primitives(), &s.target().unwrap(), Model::ExactSnapped).unwrap();
        Ok(Theirs::from_coverage(&c, Format::Json))
    };
    let config = HuntConfig {
        cases: 600,
        families: vec![SceneFamily::Mesh, SceneFamily::Delaunay],
        shard: Shard::new(2, 3).unwrap(),
        budget: Some(std::time::Duration::from_millis(150)),
        ..HuntConfig::default()
    };
    let report = hunt(&honest, &config, 2, &|| {}).unwrap();
    assert_eq!(report.requested, 200);
    assert!(report.stopped_by_time && report.cases < 200, "{}", report.cases);
    assert_eq!(
        report.same + report.differing + report.failed + report.refused,
        report.cases
    );
    let mut seen = seen.into_inner().unwrap();
    let mut expected: Vec<String> = (0..report.cases)
        .map(|j| generate_scene(&config, 1 + 3 * j).unwrap().to_json())
        .collect();
    seen.sort();
    expected.sort();
    assert!(
        seen == expected,
        "the scenes rendered are not those of the shard's first {} cases",
        report.cases
    );
    assert!(report.findings.is_empty());
}

/// Shards of a hunt with a wrong closure renderer ([`top_right`]), each on
/// its own number of threads, partition it: counts and per-signature cases add up, first
/// cases are the lowest of the shards' and in the shard's residue class, and the minimal
/// scenes agree.
#[test]
fn shards_of_a_closure_hunt_partition_it() {
    use rasterproof::harness::suite::Shard;
    use rasterproof::oracle::hunt::SceneFamily;
    let base = HuntConfig {
        cases: 30,
        seed: 11,
        families: vec![SceneFamily::Mesh, SceneFamily::Delaunay, SceneFamily::Triangles],
        shrink_runs: 100,
        ..HuntConfig::default()
    };
    let whole = hunt(&top_right, &base, 1, &|| {}).unwrap();
    assert!(!whole.findings.is_empty());
    let shards: Vec<_> = (1..=4)
        .map(|k| {
            let config = HuntConfig {
                shard: Shard::new(k, 4).unwrap(),
                ..base.clone()
            };
            hunt(&top_right, &config, usize::try_from(k).unwrap(), &|| {}).unwrap()
        })
        .collect();
    assert_eq!(shards.iter().map(|r| r.cases).collect::<Vec<_>>(), [8, 8, 7, 7]);
    assert_eq!(shards.iter().map(|r| r.same).sum::<u64>(), whole.same);
    assert_eq!(shards.iter().map(|r| r.differing).sum::<u64>(), whole.differing);
    assert_eq!(shards.iter().map(|r| r.refused).sum::<u64>(), whole.refused);
    for f in &whole.findings {
        let parts: Vec<_> = shards
            .iter()
            .flat_map(|r| r.findings.iter().filter(|g| g.signature == f.signature))
            .collect();
        let sig = f.signature.describe();
        assert_eq!(parts.iter().map(|g| g.cases).sum::<u64>(), f.cases, "{sig}: cases");
        let first = parts.iter().min_by_key(|g| g.case).unwrap();
        assert_eq!(first.case, f.case, "{sig}: first case");
        assert_eq!(first.minimal.to_json(), f.minimal.to_json(), "{sig}: minimal scene");
    }
    assert!(shards.iter().filter(|r| !r.findings.is_empty()).count() >= 2);
    let all: usize = shards.iter().map(|r| r.findings.len()).sum();
    assert!(all >= whole.findings.len());
    for (k, r) in shards.iter().enumerate() {
        assert!(r.findings.iter().all(|g| g.case % 4 == k as u64), "shard {}", k + 1);
    }
}

/// The renderer is asked once per distinct scene while shrinking: every call is a case, a
/// distinct scene a shrink tried, or a minimal scene's final verdict, and no more (a
/// shrink that tries a scene twice answers the second try from the first).
#[test]
fn shrinking_asks_the_renderer_once_per_distinct_scene() {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let calls = AtomicUsize::new(0);
    let counted = |s: &rasterproof::scene::Scene| {
        calls.fetch_add(1, Ordering::Relaxed);
        top_right(s)
    };
    let config = HuntConfig {
        cases: 24,
        shrink_runs: 400,
        ..HuntConfig::default()
    };
    let report = hunt(&counted, &config, 1, &|| {}).unwrap();
    assert!(!report.findings.is_empty());
    let shrinking: usize = report.findings.iter().map(|f| f.renderer_calls).sum();
    let tried: usize = report.findings.iter().map(|f| f.runs).sum();
    assert!(
        shrinking < tried,
        "some scene was tried twice: {tried} tried, {shrinking} distinct"
    );
    assert_eq!(
        calls.load(Ordering::Relaxed),
        24 + shrinking + report.findings.len(),
        "cases + distinct shrink scenes + final verdicts"
    );
}

/// A hunt split in three shards (as a CI matrix or a Kubernetes Indexed Job would run
/// it: `--shard $((JOB_COMPLETION_INDEX + 1))/3`), merged by `hunt-merge`, is the
/// unsharded hunt's report: the same counts, cases and findings (first cases, case counts,
/// pixel kinds, minimal scenes, their shrinking), in the same order; only what the
/// renderer was asked differs (each shard shrinks its own first case of each signature).
/// Two of the three merge into a partial report that says which shards it holds; a shard
/// given twice, or one of another hunt, is refused naming the file.
#[test]
fn merged_shards_equal_the_unsharded_hunt() {
    let cmd = coarse_cmd();
    let common = [
        "--cmd",
        cmd.as_str(),
        "--cases",
        "30",
        "--seed",
        "5",
        "--shrink-runs",
        "20",
    ];
    let (_, whole, _) = hunt_report(&common);
    let dir = fresh_dir("hunt-merge");
    let mut paths = Vec::new();
    for k in 1..=3 {
        let path = dir.path().join(format!("shard-{k}.json"));
        let shard = format!("{k}/3");
        let mut args = common.to_vec();
        args.extend(["--shard", shard.as_str(), "--report", path.to_str().unwrap()]);
        let (code, out, err) = hunt_cli(&args);
        assert!(code == 0 || code == 1, "{out}{err}");
        paths.push(path);
    }
    let merged_path = dir.path().join("merged.json");
    let mut args: Vec<&str> = vec!["hunt-merge"];
    args.extend(paths.iter().map(|p| p.to_str().unwrap()));
    args.extend(["--report", merged_path.to_str().unwrap()]);
    let out = Command::cargo_bin("rasterproof").unwrap().args(&args).output().unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    assert_eq!(
        out.status.code(),
        Some(1),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        stdout.starts_with("hunt-merge: 3 reports (every shard): 30 scenes"),
        "{stdout}"
    );
    let mut merged: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&merged_path).unwrap()).unwrap();
    let mut whole = whole;
    let (m_runs, w_runs) = (merged["renderer_runs"].take(), whole["renderer_runs"].take());
    assert!(n(&m_runs["calls"]) >= n(&w_runs["calls"]), "{m_runs} {w_runs}");
    assert_eq!(merged, whole);
    assert!(!whole["findings"].as_array().unwrap().is_empty());

    // Two of three: a partial report, which says so.
    let out = Command::cargo_bin("rasterproof")
        .unwrap()
        .args(["hunt-merge", paths[0].to_str().unwrap(), paths[2].to_str().unwrap()])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(
        stdout.starts_with("hunt-merge: 2 reports (shards [1,3] of 3)"),
        "{stdout}"
    );
    // Refusals.
    let refused = |args: &[&str], says: &str| {
        let out = Command::cargo_bin("rasterproof").unwrap().args(args).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr).to_string();
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains(says), "{err}");
    };
    let p0 = paths[0].to_str().unwrap();
    refused(&["hunt-merge", p0, p0], "is given twice");
    let other = dir.path().join("other.json");
    let mut text = std::fs::read_to_string(&paths[1]).unwrap();
    text = text.replace("\"seed\": 5", "\"seed\": 6");
    std::fs::write(&other, text).unwrap();
    refused(&["hunt-merge", p0, other.to_str().unwrap()], "seed 6, but");
    let check = dir.path().join("not-hunt.json");
    std::fs::write(&check, "{\"format\": \"something else\"}").unwrap();
    refused(&["hunt-merge", check.to_str().unwrap()], "not a hunt report");
}

/// The findings (shrunk in parallel, one finding per thread) do not depend on the number
/// of jobs: the same report with 1 and 3 threads, but for the program starts.
#[test]
fn the_findings_do_not_depend_on_the_jobs() {
    let cmd = coarse_cmd();
    let run = |jobs: &str| {
        let (code, mut r, out) = hunt_report(&[
            "--cmd",
            &cmd,
            "--cases",
            "20",
            "--seed",
            "9",
            "--shrink-runs",
            "30",
            "--jobs",
            jobs,
        ]);
        assert_eq!(code, 1, "{out}");
        r["renderer_runs"].take();
        // Spare jobs try a step's candidates side by side: the calls may grow, nothing else.
        for f in r["findings"].as_array_mut().unwrap() {
            f["shrink_renderer_calls"].take();
        }
        r
    };
    let one = run("1");
    let findings = one["findings"].as_array().unwrap().len();
    assert!((2..=4).contains(&findings), "{one}");
    assert_eq!(one, run("3"));
    // 8 jobs for at most 4 findings: each shrink tries 2 or more candidates at once.
    assert_eq!(one, run("8"));
}

/// A finding's header names the kinds of pixels its minimal scene shows; where its cases
/// showed other kinds, it says so after them: a shrink keeps the cause, not always the
/// kind (seen: a minimal scene with an extra pixel under a header of missing and wrong
/// owner pixels).
#[test]
fn a_finding_header_names_its_minimal_scenes_kinds() {
    use rasterproof::coverage::CoverageSink;
    use rasterproof::oracle::hunt::{judge, signatures, HuntFinding};
    let scene = rasterproof::scene::parse_scene(
        r#"{"width":4,"height":4,"triangles":[{"v":[[0,0],[2,0],[0,2]]}]}"#,
        "s.json",
    )
    .unwrap();
    let target = scene.target().unwrap();
    // The oracle's coverage and one pixel more, far from the triangle: an extra pixel.
    let mut theirs = render(&scene.primitives(), &target, Model::ExactSnapped).unwrap();
    theirs.cover(3, 3, 0);
    let verdict = judge(
        &scene,
        Ok(Theirs::from_coverage(&theirs, Format::Json)),
        Model::ExactSnapped,
    );
    let signature = signatures(&verdict).into_iter().next().expect("a signature");
    let finding = |kinds: Vec<PixelKind>| HuntFinding {
        signature: signature.clone(),
        kinds,
        case: 0,
        cases: 1,
        original: scene.clone(),
        minimal: scene.clone(),
        verdict: verdict.clone(),
        runs: 0,
        renderer_calls: 0,
    };
    assert_eq!(finding(vec![PixelKind::Extra]).kinds_text(), " (extra pixels)");
    assert_eq!(
        finding(vec![PixelKind::Missing, PixelKind::WrongOwner]).kinds_text(),
        " (extra pixels; its cases showed missing and wrong owner pixels)"
    );
}

/// A renderer that drew nothing is told so in the headline, not left to read its
/// scene's edge pixels as ties (seen: an all-transparent PNG against `tie-grid.json`
/// reported as 63 `tie` and 18 `near-edge` pixels).
#[test]
fn an_empty_image_is_headlined_as_drawing_nothing() {
    use rasterproof::coverage::CoverageSink;
    use rasterproof::oracle::{compare, CompareOptions};
    let scene =
        rasterproof::scene::parse_scene(include_str!("../adapters/scenes/tie-grid.json"), "tie-grid.json").unwrap();
    let target = scene.target().unwrap();
    let nothing = Theirs::from_coverage(&Coverage::new(target.width, target.height), Format::Mask);
    let options = CompareOptions {
        model: Model::ExactSnapped,
        classify_at_most: None,
        jobs: 1,
    };
    let report = compare(&scene.primitives(), &target, &nothing, &options).unwrap();
    let headline = report.headline().expect("a headline");
    assert!(
        headline.starts_with("their image covers no pixel: their renderer drew nothing"),
        "{headline}"
    );
    assert!(report.to_text("tie-grid.json", "empty.png", 0).contains(&headline));
    // One pixel drawn is not nothing: the headline is the classes' again.
    let mut one = Coverage::new(target.width, target.height);
    let (x, y) = (report.pixels[0].x, report.pixels[0].y);
    one.cover(x, y, 0);
    let some = compare(
        &scene.primitives(),
        &target,
        &Theirs::from_coverage(&one, Format::Mask),
        &options,
    )
    .unwrap();
    assert!(!some.headline().unwrap_or_default().contains("drew nothing"));
}
