//! `rasterproof hunt` and `oracle::hunt`: renderers made wrong in one known way are found
//! and shrunk to at most 2 primitives on at most 4x4 pixels; an honest renderer, and a
//! wrong one hunted under its own fitted convention, give nothing; a renderer that exits
//! non-zero, hangs, writes garbage or nothing is a finding of that kind; bad `--cmd`s exit
//! 2; no temporary file is left behind.

use assert_cmd::Command;
use rasterproof::convention::AnyTieRule;
use rasterproof::coverage::Coverage;
use rasterproof::model::{render, Model};
use rasterproof::oracle::hunt::{hunt, primitive_count, HuntConfig, Signature, Verdict};
use rasterproof::oracle::program::FailureKind;
use rasterproof::oracle::{Format, PixelKind, ReasonClass, Theirs};
use rasterproof::tri::planned::PlannedTriangle;

#[path = "common/tempdir.rs"]
mod tempdir;

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
        assert!(stdout.contains(&format!(", {class}, ")), "{wrong}: {stdout}");
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

/// The library with a Rust closure as the renderer: top-right ties (the planned engine
/// under that rule) are found as ties on triangles, shrunk to at most 2 triangles on at
/// most 4x4 pixels, and the minimal scene still shows the failure.
#[test]
fn a_closure_renderer_is_hunted_and_its_failures_shrunk() {
    let top_right = |s: &rasterproof::scene::Scene| {
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
        for (x, y, ids) in render(Model::ExactSnapped, &rest, &target).unwrap().iter() {
            for id in ids {
                rasterproof::coverage::CoverageSink::cover(&mut c, x, y, id + offset);
            }
        }
        Ok(Theirs::from_coverage(&c, Format::Json))
    };
    let config = HuntConfig {
        cases: 32,
        families: vec![rasterproof::oracle::hunt::Family::Mesh],
        ..HuntConfig::default()
    };
    let report = hunt(&config, &top_right, 2, &|| {}).unwrap();
    assert!(report.differing > 0);
    assert!(!report.findings.is_empty());
    for f in &report.findings {
        let Signature::Pixel(_, class, kind) = &f.signature else {
            panic!("{f:?}")
        };
        assert_eq!((*class, kind.as_str()), (ReasonClass::Tie, "triangles"));
        assert!(
            primitive_count(&f.minimal) <= 2 && f.minimal.width <= 4 && f.minimal.height <= 4,
            "{}",
            f.minimal.to_json()
        );
        let Verdict::Differs(r) = &f.verdict else {
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
