//! The binary's JSON answers as the adapter tests read them.

use std::path::Path;

use serde_json::Value;

/// `rasterproof compare SCENE THEIRS --format json ARGS`: the exit code (0 or 1; anything
/// else fails the test with the binary's stderr) and the report.
pub fn compare(scene: &Path, theirs: &Path, args: &[&str]) -> (i32, Value) {
    let output = assert_cmd::Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("compare")
        .arg(scene)
        .arg(theirs)
        .args(["--format", "json"])
        .args(args)
        .output()
        .unwrap();
    let code = output.status.code().unwrap();
    assert!(code <= 1, "{}", String::from_utf8_lossy(&output.stderr));
    (code, serde_json::from_slice(&output.stdout).unwrap())
}

/// The models a values fit names as reproducing their output bit for bit (`"exact"`).
pub fn fit_exact(fit: &Value) -> Vec<&str> {
    fit["exact"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m.as_str().unwrap())
        .collect()
}
