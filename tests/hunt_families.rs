//! `hunt --family all-triangles`: the six triangle-only families at once, for a renderer
//! that draws nothing but triangles; `--help` says which families need lines and polygons.

use assert_cmd::Command;

use crate::tempdir;

#[test]
fn all_triangles_is_every_triangle_only_family() {
    let dir = tempdir::Dir::new("hunt-families");
    let report = dir.path().join("report.json");
    let out = Command::cargo_bin("rasterproof")
        .unwrap()
        .args([
            "hunt",
            "--cmd",
            "true {scene} {out}",
            "--cases",
            "6",
            "--shrink-runs",
            "2",
            "--quiet",
        ])
        .args(["--family", "all-triangles", "--report"])
        .arg(&report)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    // `true` writes no output: every case is a finding, exit 1.
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    let r: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&report).unwrap()).unwrap();
    assert_eq!(
        r["families"],
        serde_json::json!(["mesh", "delaunay", "triangles", "slivers", "huge", "fine"])
    );
    let help = Command::cargo_bin("rasterproof")
        .unwrap()
        .args(["hunt", "--help"])
        .output()
        .unwrap();
    let help = String::from_utf8_lossy(&help.stdout);
    assert!(
        help.contains("lines (needs lines)") && help.contains("polygons (needs") && help.contains("all-triangles"),
        "{help}"
    );
}
