//! `rasterproof check` on the command line (issue 10): the table's `skipped` column and
//! reasons, the legend under it, and which failing cases `--out` / `--out-float` write.

use assert_cmd::Command;
use rasterproof::fill::triangulate::validate;
use rasterproof::harness::generate;

use crate::tempdir;

fn bin() -> Command {
    Command::cargo_bin("rasterproof").unwrap()
}

/// Seed 7's first 3 cases: one of each mesh family.
const SEED: &str = "7";
const CASES: u64 = 3;

/// One row of the table: invariant, label, cases, violations, skipped.
type Row = (String, String, u64, u64, u64);

/// The rows of the table in `text` (between the header and the first line after it that
/// is not a row), read by the table's fixed columns: 24 + 1 + 18 + numbers.
fn table(text: &str) -> Vec<Row> {
    let mut lines = text.lines().skip_while(|l| !l.starts_with("invariant "));
    let header = lines.next().expect("a header");
    assert_eq!(
        header.split_whitespace().collect::<Vec<_>>(),
        ["invariant", "model", "cases", "violations", "skipped"]
    );
    lines
        .take_while(|l| !l.starts_with(' ') && l.len() > 43 && !l.contains(':'))
        .map(|l| {
            let n: Vec<u64> = l[43..].split_whitespace().map(|x| x.parse().unwrap()).collect();
            assert_eq!(n.len(), 3, "{l}");
            (
                l[..24].trim().to_string(),
                l[25..43].trim().to_string(),
                n[0],
                n[1],
                n[2],
            )
        })
        .collect()
}

fn check(extra: &[&str]) -> (String, std::process::Output) {
    let cases = CASES.to_string();
    let mut args = vec!["check", "--cases", &cases, "--seed", SEED, "--quiet"];
    args.extend_from_slice(extra);
    let out = bin().args(&args).output().unwrap();
    (String::from_utf8(out.stdout.clone()).unwrap(), out)
}

/// The table counts each row once per case, checked or skipped; the triangulation's skips
/// are the cases whose simple polygon the library's own validation refuses once snapped,
/// each under a reason line; the legend below explains every invariant and label; the
/// verdict is the last line.
#[test]
fn check_reports_skipped_cases_and_explains_its_terms() {
    let (text, out) = check(&[]);
    assert!(out.status.success(), "{text}\n{}", String::from_utf8_lossy(&out.stderr));
    let rows = table(&text);
    assert!(rows.len() > 30, "{text}");
    for (invariant, label, cases, _, skipped) in &rows {
        assert_eq!(cases + skipped, CASES, "{invariant} {label}");
    }
    // Independently of the suite: which cases' simple polygons fold when snapped.
    let folded = (0..CASES)
        .filter(|&k| {
            let case = generate(7, k).unwrap();
            let fixed = case.simple.to_fixed(&case.preset.convention()).unwrap();
            validate(&fixed).is_err()
        })
        .count() as u64;
    assert!(folded >= 1, "seed 7 was chosen for a folded polygon in its first cases");
    let triangulation = rows.iter().find(|r| r.0 == "triangulation").unwrap();
    assert_eq!((triangulation.2, triangulation.4), (CASES - folded, folded));
    assert!(
        text.contains(&format!(
            "\nskipped (the check could not run on the case):\n  triangulation          fixed                  {folded}: snapping folded the polygon (not simple on the subpixel grid)\n"
        )),
        "{text}"
    );
    let legend: Vec<&str> = text.lines().skip_while(|l| *l != "legend:").collect();
    for (invariant, label, ..) in &rows {
        for name in [invariant, label] {
            let prefix = format!("  {name:<24} ");
            assert!(
                legend.iter().any(|l| l.starts_with(&prefix)),
                "{name} missing from the legend:\n{text}"
            );
        }
    }
    for column in ["cases", "violations", "skipped"] {
        assert!(
            legend.iter().any(|l| l.starts_with(&format!("  {column:<24} "))),
            "{column}"
        );
    }
    assert_eq!(
        text.lines().last(),
        Some("ok: the exact and integer models (exact, exact-snapped, fixed, scanline) hold every invariant")
    );
}

/// The files `check` wrote into `dir`: their names (sorted), each `.json` parsed back.
fn written(dir: &std::path::Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    for n in names.iter().filter(|n| n.ends_with(".json")) {
        let text = std::fs::read_to_string(dir.join(n)).unwrap();
        assert!(rasterproof::scene::parse_scene(&text, n).is_ok(), "{n}");
    }
    names
}

/// `--out` writes the exact and integer models' failures only (none here: the run passes,
/// so nothing, though float models failed); `--out-float` adds the float ones, a `.json`
/// and a `.txt` per violation counted in the table, each named after a float label.
#[test]
fn out_writes_float_failures_only_with_out_float() {
    let dir = tempdir::Dir::new("check-out");
    let (text, out) = check(&["--out", dir.path().to_str().unwrap()]);
    assert!(out.status.success(), "{text}");
    let float_violations: u64 = table(&text).iter().map(|r| r.3).sum();
    assert!(
        float_violations > 0,
        "the run should show some float violations:\n{text}"
    );
    assert_eq!(written(dir.path()), Vec::<String>::new());

    let dir = tempdir::Dir::new("check-out-float");
    let (text, out) = check(&["--out", dir.path().to_str().unwrap(), "--out-float"]);
    assert!(out.status.success(), "{text}");
    let names = written(dir.path());
    assert_eq!(names.len() as u64, 2 * float_violations, "{names:?}");
    let float_labels = ["float32", "float64", "sh-f32", "sh-f64", "dda32", "dda64"];
    for n in &names {
        assert!(float_labels.iter().any(|l| n.contains(l)), "{n}");
    }
}

/// `--out-float` needs `--out`: a usage error (exit 2) naming both.
#[test]
fn out_float_without_out_is_a_usage_error() {
    let (_, out) = check(&["--out-float"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("--out-float") && err.contains("--out <DIR>"), "{err}");
}
