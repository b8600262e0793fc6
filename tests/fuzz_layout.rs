//! The fuzzing layout kept whole (fuzz/README.md): every fuzz target in
//! `fuzz/fuzz_targets/` is a `[[bin]]` of `fuzz/Cargo.toml`, has its options
//! (`fuzz/options/TARGET.options`: a `max_len`, and a `dict` that exists) and a committed
//! seed corpus (`fuzz/corpus/TARGET/seed-*`), and the seeds are what their target reads:
//! scene files for the scene targets (after `compare_oracle`'s 16 parameter bytes), check
//! reports for `check_report`, PNGs where they are named `.png`. The ClusterFuzzLite files name the language and build
//! every target. This is the fast, static half of the layout check; `fuzz/check-layout`
//! builds and runs the targets.

#![cfg(feature = "proptest")]

use std::collections::BTreeSet;
use std::fs;
use std::path::Path;

use rasterproof::harness::suite::SuiteReport;
use rasterproof::scene::{parse_scene_with, ParseOptions};

fn targets() -> BTreeSet<String> {
    fs::read_dir("fuzz/fuzz_targets")
        .expect("fuzz/fuzz_targets")
        .filter_map(|e| {
            let name = e.expect("entry").file_name().into_string().expect("UTF-8");
            name.strip_suffix(".rs").map(str::to_string)
        })
        .collect()
}

fn option(target: &str, key: &str) -> Option<String> {
    let text = fs::read_to_string(format!("fuzz/options/{target}.options")).expect("the target's options");
    text.lines()
        .filter_map(|l| l.split_once('='))
        .find(|(k, _)| k.trim() == key)
        .map(|(_, v)| v.trim().to_string())
}

fn seeds(target: &str) -> Vec<(String, Vec<u8>)> {
    let mut out: Vec<(String, Vec<u8>)> = fs::read_dir(format!("fuzz/corpus/{target}"))
        .unwrap_or_else(|e| panic!("fuzz/corpus/{target}: {e}"))
        .map(|e| e.expect("entry").path())
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("seed-"))
        })
        .map(|p| (p.display().to_string(), fs::read(&p).expect("a seed")))
        .collect();
    out.sort();
    out
}

#[test]
fn every_target_is_built_configured_and_seeded() {
    let manifest = fs::read_to_string("fuzz/Cargo.toml").expect("fuzz/Cargo.toml");
    let targets = targets();
    assert!(targets.len() >= 12, "{targets:?}");
    for t in &targets {
        assert!(
            manifest.contains(&format!("name = \"{t}\"\npath = \"fuzz_targets/{t}.rs\"")),
            "{t} is not a [[bin]] of fuzz/Cargo.toml"
        );
        let max_len: usize = option(t, "max_len")
            .unwrap_or_else(|| panic!("{t}: no max_len"))
            .parse()
            .expect("max_len is a number");
        if let Some(dict) = option(t, "dict") {
            let text = fs::read_to_string(Path::new("fuzz").join(&dict)).expect("the named dictionary");
            let entries = text.lines().filter(|l| l.starts_with('"')).count();
            assert!(entries > 10, "{dict}: {entries} entries");
        }
        let seeds = seeds(t);
        assert!(!seeds.is_empty(), "{t}: no committed seeds");
        for (path, bytes) in &seeds {
            assert!(
                bytes.len() <= max_len,
                "{path}: {} bytes, above {t}'s max_len {max_len}",
                bytes.len()
            );
        }
    }
    // Every options file belongs to a target.
    for e in fs::read_dir("fuzz/options").expect("fuzz/options") {
        let name = e.expect("entry").file_name().into_string().expect("UTF-8");
        let t = name.strip_suffix(".options").expect("only .options files");
        assert!(targets.contains(t), "fuzz/options/{name} names no target");
    }
}

#[test]
fn scene_seeds_are_scenes_and_report_seeds_are_reports() {
    for t in ["planned_exact", "scene_parse"] {
        let parsed = seeds(t)
            .iter()
            .filter(|(_, b)| parse_scene_with(b, "seed", &ParseOptions::default()).is_ok())
            .count();
        // scene_parse's seeds include refused files on purpose (seed-error-*).
        let refused = seeds(t).iter().filter(|(p, _)| p.contains("seed-error-")).count();
        assert_eq!(
            parsed + refused,
            seeds(t).len(),
            "{t}: a seed that is neither a scene nor an error case"
        );
    }
    for (path, bytes) in seeds("compare_oracle") {
        assert!(bytes.len() > 16, "{path}");
        parse_scene_with(&bytes[16..], &path, &ParseOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    }
    for (path, bytes) in seeds("check_report") {
        let text = String::from_utf8(bytes).expect("UTF-8");
        SuiteReport::from_json(&text, &path).unwrap_or_else(|e| panic!("{e}"));
    }
    for (path, bytes) in seeds("flood_fill").iter().chain(&seeds("theirs_read")) {
        if path.ends_with(".png") {
            assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"), "{path} is not a PNG");
        }
    }
}

#[test]
fn clusterfuzzlite_builds_every_target() {
    let project = fs::read_to_string(".clusterfuzzlite/project.yaml").expect("project.yaml");
    assert!(project.lines().any(|l| l.trim() == "language: rust"));
    let docker = fs::read_to_string(".clusterfuzzlite/Dockerfile").expect("Dockerfile");
    assert!(docker.contains("FROM gcr.io/oss-fuzz-base/base-builder-rust"));
    let build = fs::read_to_string(".clusterfuzzlite/build.sh").expect("build.sh");
    for needle in [
        "cargo fuzz build -O",
        "fuzz/fuzz_targets/*.rs",
        "_seed_corpus.zip",
        ".options",
        ".dict",
    ] {
        assert!(build.contains(needle), "build.sh lacks {needle}");
    }
    for (file, mode) in [
        ("cflite_pr.yml", "code-change"),
        ("cflite_batch.yml", "batch"),
        ("cflite_cron.yml", "prune"),
    ] {
        let text = fs::read_to_string(format!(".github/workflows/{file}")).expect("a workflow");
        assert!(text.contains(&format!("mode: '{mode}'")), "{file}: no {mode} mode");
        assert!(text.contains("language: rust"), "{file}: not language rust");
    }
}
