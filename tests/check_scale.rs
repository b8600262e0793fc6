//! `rasterproof check` at scale (issue 15): `--jobs`, `--shard`, `--time`, `--report`,
//! `--junit` and `check-merge`. The runs are small (a few cases each): the suite is slow.

use assert_cmd::Command;

use crate::tempdir;

fn bin() -> Command {
    Command::cargo_bin("rasterproof").unwrap()
}

/// Runs `rasterproof ARGS` in `dir`: exit code, stdout, stderr.
fn run(dir: &std::path::Path, args: &[&str]) -> (Option<i32>, String, String) {
    let out = bin().current_dir(dir).args(args).output().unwrap();
    (
        out.status.code(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// `check --cases N --seed S --quiet` plus `extra`, which must succeed: its stdout.
fn check(dir: &std::path::Path, cases: &str, seed: &str, extra: &[&str]) -> String {
    let mut args = vec!["check", "--cases", cases, "--seed", seed, "--quiet"];
    args.extend_from_slice(extra);
    let (code, stdout, stderr) = run(dir, &args);
    assert_eq!(code, Some(0), "{args:?}\n{stdout}\n{stderr}");
    stdout
}

fn read(dir: &std::path::Path, name: &str) -> String {
    std::fs::read_to_string(dir.join(name)).unwrap()
}

/// The table's rows (the lines between the column heads and the first line that is not
/// a row).
fn rows(text: &str) -> Vec<&str> {
    text.lines()
        .skip_while(|l| !l.starts_with("invariant "))
        .skip(1)
        .take_while(|l| !l.starts_with(' ') && !l.contains(':'))
        .collect()
}

/// Seed 7's 3 cases: the unsharded run on two threads, the same on one, and shards 1/3,
/// 2/3, 3/3 merged (given in another order) give the same report, byte for byte, the same
/// printed table and the same JUnit XML; each shard ran its one case and says which; the
/// JUnit file has one test case per row of the table.
#[test]
fn shards_merged_and_threads_give_the_unsharded_report() {
    let dir = tempdir::Dir::new("check-scale-shards");
    let d = dir.path();
    let two = check(
        d,
        "3",
        "7",
        &["--jobs", "2", "--report", "two.json", "--junit", "two.xml"],
    );
    let one = check(d, "3", "7", &["--jobs", "1", "--report", "one.json"]);
    assert_eq!(one, two);
    assert_eq!(read(d, "one.json"), read(d, "two.json"));
    for k in 1..=3 {
        let shard = format!("{k}/3");
        let text = check(d, "3", "7", &["--shard", &shard, "--report", &format!("s{k}.json")]);
        assert!(text.starts_with("rasterproof check: 1 case, seed 7"), "{text}");
        assert!(
            text.contains(&format!(
                "\nshard {shard}: the cases k of 0..3 with k mod 3 + 1 = {k} (1 case)\n"
            )),
            "{text}"
        );
    }
    let (code, merged, stderr) = run(
        d,
        &[
            "check-merge",
            "s2.json",
            "s3.json",
            "s1.json",
            "--report",
            "merged.json",
            "--junit",
            "merged.xml",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(merged, two);
    assert!(rows(&merged).len() > 30, "{merged}");
    assert_eq!(rows(&merged), rows(&two));
    assert_eq!(read(d, "merged.json"), read(d, "two.json"));
    let xml = read(d, "merged.xml");
    assert_eq!(xml, read(d, "two.xml"));
    let n = rows(&two).len();
    assert_eq!(xml.matches("<testcase ").count(), n);
    assert!(xml.contains(&format!(
        "<testsuites name=\"rasterproof check\" tests=\"{n}\" failures=\"0\""
    )));
    assert!(xml.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n") && xml.ends_with("</testsuites>\n"));
    let report = read(d, "two.json");
    for field in [
        "\"seed\": 7",
        "\"cases\": 3",
        "\"cases_run\": 3",
        "\"complete\": true",
        "\"shard\": {\"count\": 1",
    ] {
        assert!(report.contains(field), "{field}");
    }
    let s2 = read(d, "s2.json");
    assert!(s2.contains("\"shard\": {\"count\": 3, \"indices\": [2]}") && s2.contains("\"cases_run\": 1"));
}

/// A time budget far below the run's length stops it cleanly: exit 0, the cases that ran
/// counted in the header, the report and the "incomplete" line.
#[test]
fn time_budget_stops_early_and_reports_the_count() {
    let dir = tempdir::Dir::new("check-scale-time");
    let d = dir.path();
    let text = check(d, "100000", "3", &["--time", "1s", "--report", "t.json"]);
    let header = text.lines().next().unwrap();
    let ran: u64 = header
        .strip_prefix("rasterproof check: ")
        .and_then(|h| h.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("{header}"));
    assert!(ran < 100_000, "{header}");
    assert!(
        text.contains(&format!(
            "\nincomplete: {ran} of 100000 cases ran\nstopped: the time budget (1s) ran out after {ran} of 100000 cases\n"
        )),
        "{text}"
    );
    let report = read(d, "t.json");
    assert!(report.contains(&format!("\"cases_run\": {ran},")), "{report}");
    assert!(report.contains("\"complete\": false,"));
}

/// Bad values of the new options: exit 2, one message naming the option and the value.
#[test]
fn bad_shard_jobs_and_time_are_usage_errors() {
    let dir = tempdir::Dir::new("check-scale-bad");
    for (args, words) in [
        (["--shard", "0/0"], "N must be at least 1"),
        (["--shard", "4/3"], "K must be in 1..=3"),
        (["--shard", "x"], "expected K/N"),
        (["--jobs", "0"], "expected a number of threads"),
        (["--time", "abc"], "expected a duration"),
        (["--time", "90"], "expected a duration"),
    ] {
        let (code, _, stderr) = run(dir.path(), &["check", "--cases", "1", "--quiet", args[0], args[1]]);
        assert_eq!(code, Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains(&format!("'{}'", args[1])) && stderr.contains(args[0]) && stderr.contains(words),
            "{args:?}: {stderr}"
        );
    }
    let (code, _, stderr) = run(
        dir.path(),
        &["check", "--cases", "1", "--report", "x.json", "--junit", "x.json"],
    );
    assert_eq!(
        (code, stderr.trim()),
        (Some(2), "error: --report and --junit: both name x.json")
    );
}

/// check-merge refuses reports of different seeds, the same shard twice, a truncated
/// file and a missing one: exit 2 naming the files, and no output file written.
#[test]
fn check_merge_refuses_what_is_not_one_run() {
    let dir = tempdir::Dir::new("check-scale-merge");
    let d = dir.path();
    check(d, "2", "1", &["--shard", "1/2", "--report", "a.json"]);
    check(d, "2", "2", &["--shard", "2/2", "--report", "b.json"]);
    let a = read(d, "a.json");
    std::fs::write(d.join("cut.json"), &a[..a.len() / 2]).unwrap();
    for (files, message) in [
        (
            ["a.json", "b.json"],
            "a.json and b.json: different seeds (1 and 2): not shards of one run",
        ),
        (
            ["a.json", "a.json"],
            "a.json and a.json: both hold shard 1/2: the same cases twice",
        ),
        (
            ["a.json", "cut.json"],
            "cut.json: not a JSON check report (truncated or damaged?): EOF while parsing",
        ),
        (["a.json", "none.json"], "none.json: cannot read:"),
    ] {
        let (code, stdout, stderr) = run(d, &["check-merge", files[0], files[1], "--report", "m.json"]);
        assert_eq!(code, Some(2), "{files:?}: {stdout}");
        assert!(stderr.starts_with(&format!("error: {message}")), "{files:?}: {stderr}");
        assert!(!d.join("m.json").exists());
    }
    // One shard alone merges into itself: its table, its incompleteness said.
    let (code, stdout, _) = run(d, &["check-merge", "a.json"]);
    assert_eq!(code, Some(0));
    assert!(
        stdout.contains("\nshard 1/2: the cases k of 0..2 with k mod 2 + 1 = 1 (1 case)\n"),
        "{stdout}"
    );
}

/// Ctrl-C (SIGINT) stops the run at the next case: the report of the cases done is
/// written and printed, saying it was interrupted.
#[cfg(unix)]
#[test]
fn interrupt_writes_the_report_of_the_cases_done() {
    let dir = tempdir::Dir::new("check-scale-int");
    let d = dir.path();
    let child = std::process::Command::new(assert_cmd::cargo::cargo_bin("rasterproof"))
        .current_dir(d)
        .args(["check", "--cases", "100000", "--quiet", "--report", "i.json"])
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(std::time::Duration::from_millis(1500));
    let killed = std::process::Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    let out = child.wait_with_output().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(0), "{text}");
    let ran = text
        .lines()
        .find_map(|l| l.strip_prefix("stopped: interrupted after "))
        .and_then(|rest| rest.strip_suffix(" of 100000 cases"))
        .unwrap_or_else(|| panic!("{text}"));
    let report = read(d, "i.json");
    assert!(report.contains(&format!("\"cases_run\": {ran},")), "{report}");
    assert!(report.contains("\"stopped\": [\n    \"interrupted after "), "{report}");
}
