//! The stay-alive protocol against a deliberately misbehaving program (a Python script
//! whose behaviour the scene's width picks): every way it breaks the protocol is a clear
//! failure of one scene, with its stderr, never a hang; the next scene starts a fresh
//! program; a well-behaved answer is read as a per-scene run's would be. And `hunt
//! --serve` with the tiny-skia adapter finds what `hunt --cmd` finds, with two program
//! starts instead of one per scene.

#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use rasterproof::oracle::renderer::program::FailureKind;
use rasterproof::oracle::renderer::stay_alive::StayAlive;
use rasterproof::oracle::{Background, Format};
use rasterproof::scene::Scene;

use crate::tempdir;

/// The misbehaving program. By the scene's width: 1 writes garbage; 2 half a line, then
/// exits; 3 a line of 100 000 bytes; 4 never answers; 5 answers twice; 6 answers, then
/// exits; 7 kills itself with SIGSEGV before answering; 8 answers `ok: false`; 9 answers
/// another id; 10 answers ok without writing the output; any other width answers as it
/// should, writing an empty ids PNG (a valid answer for an empty scene).
const MISBEHAVING: &str = r#"#!/usr/bin/env python3
import json, os, signal, struct, sys, time, zlib

def png(w, h):
    def chunk(kind, data):
        c = kind + data
        return struct.pack(">I", len(data)) + c + struct.pack(">I", zlib.crc32(c) & 0xffffffff)
    raw = b"".join(b"\x00" + b"\x00" * (4 * w) for _ in range(h))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))

def say(obj):
    sys.stdout.write(json.dumps(obj) + "\n")
    sys.stdout.flush()

for line in sys.stdin:
    r = json.loads(line)
    w, h = r["scene"]["width"], r["scene"]["height"]
    print("asked for scene", r["id"], "of width", w, file=sys.stderr, flush=True)
    if w == 1:
        sys.stdout.write("this is not json\n"); sys.stdout.flush()
    elif w == 2:
        sys.stdout.write('{"id": '); sys.stdout.flush(); sys.exit(0)
    elif w == 3:
        sys.stdout.write("x" * 100000 + "\n"); sys.stdout.flush()
    elif w == 4:
        time.sleep(60)
    elif w == 7:
        os.kill(os.getpid(), signal.SIGSEGV)
    elif w == 8:
        say({"id": r["id"], "ok": False, "error": "cannot draw this"})
    elif w == 9:
        say({"id": r["id"] + 1000, "ok": True})
    elif w == 10:
        say({"id": r["id"], "ok": True})
    else:
        with open(r["out"], "wb") as f:
            f.write(png(w, h))
        say({"id": r["id"], "ok": True})
        if w == 5:
            say({"id": r["id"], "ok": True})
        if w == 6:
            sys.exit(0)
"#;

fn program(dir: &Path) -> PathBuf {
    use std::os::unix::fs::PermissionsExt as _;
    let path = dir.join("misbehaving.py");
    std::fs::write(&path, MISBEHAVING).unwrap();
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755)).unwrap();
    path
}

fn scene(width: u32) -> Scene {
    Scene::new(width, 2, Vec::new())
}

#[test]
fn every_protocol_breach_is_a_failure_of_one_scene() {
    let dir = tempdir::Dir::new("stay-alive");
    let cmd = program(dir.path()).display().to_string();
    let renderer = StayAlive::new(&cmd, Format::Ids, Background::default(), Duration::from_secs(2)).unwrap();
    let good = |r: &StayAlive| {
        let t = r.render(&scene(16)).expect("a well-behaved answer");
        assert_eq!((t.width(), t.height(), t.covered_pixels()), (16, 2, 0));
    };
    good(&renderer);
    good(&renderer);
    assert_eq!(renderer.starts(), 1, "one program for consecutive good scenes");
    let cases: [(u32, FailureKind, &str); 8] = [
        (1, FailureKind::Protocol, "not JSON"),
        (2, FailureKind::Protocol, "not JSON"),
        (3, FailureKind::Protocol, "over 65536 bytes"),
        (4, FailureKind::Timeout, "no answer after 2 s"),
        (7, FailureKind::Crash, "signal 11"),
        (8, FailureKind::Exit, "it answered an error: cannot draw this"),
        (9, FailureKind::Protocol, "does not answer request"),
        (10, FailureKind::NoOutput, "it wrote no"),
    ];
    for (width, kind, says) in cases {
        let start = Instant::now();
        let starts = renderer.starts();
        let failure = renderer.render(&scene(width)).expect_err("a failure");
        assert_eq!(failure.kind, kind, "width {width}: {failure}");
        assert!(failure.message.contains(says), "width {width}: {failure}");
        assert!(
            failure.message.contains(&format!("of width {width}")),
            "width {width}: its stderr is in the message: {failure}"
        );
        assert!(
            start.elapsed() < Duration::from_secs(5),
            "width {width} took {:?}",
            start.elapsed()
        );
        // The next scene is answered by a fresh program.
        good(&renderer);
        assert_eq!(renderer.starts(), starts + 1, "width {width}: one restart");
    }
    // Answering twice: the stray second answer fails the next request, found before it
    // is sent or read as its answer (whichever comes first); then a fresh program.
    good(&renderer);
    renderer.render(&scene(5)).expect("the first answer is right");
    let failure = renderer.render(&scene(16)).expect_err("the stray answer");
    assert_eq!(failure.kind, FailureKind::Protocol, "{failure}");
    assert!(
        failure.message.contains("a line nobody asked for") || failure.message.contains("does not answer request"),
        "{failure}"
    );
    good(&renderer);
    // Exiting between requests: the next request finds it gone (before it is sent, or
    // when it is sent or waits for its answer).
    renderer.render(&scene(6)).expect("it answered before it exited");
    let failure = renderer.render(&scene(16)).expect_err("it exited");
    assert_eq!(failure.kind, FailureKind::Exit, "{failure}");
    assert!(
        ["between requests", "before it read the request", "without answering"]
            .iter()
            .any(|w| failure.message.contains(w)),
        "{failure}"
    );
    good(&renderer);
}

/// Several threads at once: each scene gets an idle program or a new one, and every
/// answer is its own scene's (the canvas sizes differ per thread).
#[test]
fn jobs_share_the_programs() {
    let dir = tempdir::Dir::new("stay-alive-jobs");
    let cmd = program(dir.path()).display().to_string();
    let renderer = StayAlive::new(&cmd, Format::Ids, Background::default(), Duration::from_secs(5)).unwrap();
    std::thread::scope(|s| {
        for k in 0..3u32 {
            let renderer = &renderer;
            s.spawn(move || {
                for _ in 0..20 {
                    let t = renderer.render(&scene(11 + k)).unwrap();
                    assert_eq!(t.width(), 11 + k);
                }
            });
        }
    });
    assert_eq!(renderer.requests(), 60);
    assert!((1..=3).contains(&renderer.starts()), "{} starts", renderer.starts());
}

/// Bad commands are refused before anything runs.
#[test]
fn bad_serve_commands_are_refused() {
    let e = StayAlive::new("", Format::Ids, Background::default(), Duration::from_secs(1)).unwrap_err();
    assert!(e.contains("--serve: empty"), "{e}");
    let e = StayAlive::new(
        "/no/such/program --serve",
        Format::Ids,
        Background::default(),
        Duration::from_secs(1),
    )
    .unwrap_err();
    assert!(e.contains("not found"), "{e}");
    let e = StayAlive::new(
        "prog 'unclosed",
        Format::Ids,
        Background::default(),
        Duration::from_secs(1),
    )
    .unwrap_err();
    assert!(e.contains("cannot split"), "{e}");
}
