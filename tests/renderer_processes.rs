//! An external renderer's children do not outlive it: the renderer runs in a process
//! group of its own, and the whole group is killed when it times out, after it exits
//! (what it left running in the background), and when `hunt` is interrupted (Ctrl-C).
//! Each test's renderer is a shell script that starts a child (`sleep 30 &`, its pid
//! written to a file) and then hangs or exits; the child must be gone afterwards.

#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use num_rational::BigRational;
use rasterproof::geom::{Point, Triangle};
use rasterproof::oracle::renderer::program::{FailureKind, Program};
use rasterproof::oracle::{Background, Format};
use rasterproof::scene::Scene;

use crate::tempdir;

/// A shell script in `dir` that starts `sleep 30` in the background, writes its pid to its
/// first argument, then runs `then`.
fn wrapper(dir: &Path, name: &str, then: &str) -> PathBuf {
    use std::os::unix::fs::PermissionsExt as _;
    let path = dir.join(name);
    std::fs::write(&path, format!("#!/bin/sh\nsleep 30 &\necho $! > \"$1\"\n{then}\n")).unwrap();
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755)).unwrap();
    path
}

/// Whether process `pid` is alive (exists and is not a zombie waiting to be reaped).
fn alive(pid: u32) -> bool {
    match std::fs::read_to_string(format!("/proc/{pid}/stat")) {
        // The state follows the parenthesised command name.
        Ok(stat) => stat
            .rsplit_once(')')
            .is_some_and(|(_, rest)| !rest.trim_start().starts_with('Z')),
        Err(_) => false,
    }
}

/// The pid in `file`, waiting up to 10 s for the script to write it.
fn pid_in(file: &Path) -> u32 {
    let start = Instant::now();
    loop {
        if let Ok(text) = std::fs::read_to_string(file) {
            if let Ok(pid) = text.trim().parse() {
                return pid;
            }
        }
        assert!(
            start.elapsed() < Duration::from_secs(10),
            "{} was never written",
            file.display()
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Asserts that `pid` is gone within 2 s (a killed orphan is reaped by init), else kills it
/// and fails with `what`.
fn assert_gone(pid: u32, what: &str) {
    let start = Instant::now();
    while alive(pid) && start.elapsed() < Duration::from_secs(2) {
        std::thread::sleep(Duration::from_millis(20));
    }
    if alive(pid) {
        let _ = std::process::Command::new("kill")
            .arg("-9")
            .arg(pid.to_string())
            .status();
        panic!("{what}: the renderer's child {pid} is still running");
    }
}

fn scene() -> Scene {
    let r = |n: i64| BigRational::from_integer(n.into());
    let p = |x, y| Point::new(r(x), r(y));
    Scene::new(
        4,
        4,
        vec![Triangle {
            v: [p(0, 0), p(4, 0), p(0, 4)],
        }],
    )
}

/// A renderer that hangs past the timeout: the timeout kills its child too.
#[test]
fn a_timeout_kills_the_renderers_children() {
    let dir = tempdir::Dir::new("procs-timeout");
    let script = wrapper(dir.path(), "hang.sh", "sleep 30");
    let pidfile = dir.path().join("child.pid");
    let cmd = format!("{} {} {{scene}} {{out}}", script.display(), pidfile.display());
    let program = Program::new(&cmd, Format::Ids, Background::default(), Duration::from_secs(1)).unwrap();
    let failure = program.render(&scene()).unwrap_err();
    assert_eq!(failure.kind, FailureKind::Timeout, "{failure}");
    assert_gone(pid_in(&pidfile), "after the timeout");
}

/// A renderer that exits (here non-zero, at once) leaving a child in the background: the
/// child is killed when the renderer is done.
#[test]
fn a_renderers_background_children_are_killed_when_it_exits() {
    let dir = tempdir::Dir::new("procs-exit");
    let script = wrapper(dir.path(), "leave.sh", "exit 3");
    let pidfile = dir.path().join("child.pid");
    let cmd = format!("{} {} {{scene}} {{out}}", script.display(), pidfile.display());
    let program = Program::new(&cmd, Format::Ids, Background::default(), Duration::from_secs(10)).unwrap();
    let failure = program.render(&scene()).unwrap_err();
    assert_eq!(failure.kind, FailureKind::Exit, "{failure}");
    assert_gone(pid_in(&pidfile), "after the renderer exited");
}

/// `rasterproof hunt` interrupted twice (SIGINT, as Ctrl-C sends it) while its renderer
/// hangs: the first asks for the report of the cases done (the hanging one would finish
/// at its timeout), the second stops at once: the renderer's child is killed with it, and
/// the hunt exits 130.
#[test]
fn an_interrupted_hunt_kills_the_renderers_children() {
    let dir = tempdir::Dir::new("procs-interrupt");
    let script = wrapper(dir.path(), "hang.sh", "sleep 30");
    let pidfile = dir.path().join("child.pid");
    let cmd = format!("{} {} {{scene}} {{out}}", script.display(), pidfile.display());
    let mut hunt = std::process::Command::new(assert_cmd::cargo::cargo_bin("rasterproof"))
        .args(["hunt", "--cmd", &cmd, "--cases", "1", "--timeout", "60", "--quiet"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let child = pid_in(&pidfile);
    for _ in 0..2 {
        let sent = std::process::Command::new("kill")
            .args(["-INT", &hunt.id().to_string()])
            .status()
            .unwrap();
        assert!(sent.success());
        std::thread::sleep(Duration::from_millis(300));
    }
    let start = Instant::now();
    let status = loop {
        if let Some(status) = hunt.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > Duration::from_secs(20) {
            let _ = hunt.kill();
            panic!("hunt did not stop on SIGINT");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    assert_eq!(status.code(), Some(130));
    assert_gone(child, "after Ctrl-C");
}

/// One Ctrl-C stops a long hunt early and leaves a valid report of the cases done: no case
/// starts after it, the running ones finish, the report (JSON, written whole) says
/// `"interrupted": true`, its counts add up to the cases run, its findings are unshrunk
/// first cases among them, and the hunt exits 130.
#[test]
fn one_ctrl_c_leaves_the_report_of_the_cases_done() {
    let dir = tempdir::Dir::new("procs-interrupt-report");
    let exe = assert_cmd::cargo::cargo_bin("rasterproof");
    let script = dir.path().join("slow.sh");
    std::fs::write(
        &script,
        format!(
            "#!/bin/sh\nsleep 0.05\nexec {} render \"$1\" --subpixel-bits 4 --ids-out \"$2\"\n",
            exe.display()
        ),
    )
    .unwrap();
    {
        use std::os::unix::fs::PermissionsExt as _;
        std::fs::set_permissions(&script, std::fs::Permissions::from_mode(0o755)).unwrap();
    }
    let report = dir.path().join("report.json");
    let cmd = format!("{} {{scene}} {{out}}", script.display());
    let mut hunt = std::process::Command::new(&exe)
        .args(["hunt", "--cmd", &cmd, "--cases", "100000", "--quiet", "--report"])
        .arg(&report)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(1500));
    let sent = std::process::Command::new("kill")
        .args(["-INT", &hunt.id().to_string()])
        .status()
        .unwrap();
    assert!(sent.success());
    let start = Instant::now();
    let status = loop {
        if let Some(status) = hunt.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > Duration::from_secs(30) {
            let _ = hunt.kill();
            panic!("hunt did not stop after one SIGINT");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    assert_eq!(status.code(), Some(130));
    let r: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&report).expect("the report")).unwrap();
    assert_eq!(r["interrupted"], true);
    assert_eq!(r["stopped_by_time"], false);
    let run = r["cases_run"].as_u64().unwrap();
    assert!(run > 0 && run < 100_000, "{run} cases run");
    let c = &r["counts"];
    let sum: u64 = ["same", "differ", "failed", "refused"]
        .iter()
        .map(|k| c[k].as_u64().unwrap())
        .sum();
    assert_eq!(sum, run);
    for f in r["findings"].as_array().unwrap() {
        assert!(f["first_case"].as_u64().unwrap() < run);
        assert_eq!(f["shrink_runs"], 0, "not shrunk after the interrupt");
    }
}
