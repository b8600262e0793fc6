//! Every integration test, in one test binary: one compile and one link instead of one
//! per file. Each file under `tests/` stays where it was and is a module here, loaded by
//! `#[path]` so that its own `mod common;` and `#[path]` modules resolve beside it as
//! before. `cargo test --test it NAME` runs the tests whose path contains NAME:
//! `cargo test --test it properties::` runs one file's tests. The test at the end checks
//! that every `tests/*.rs` file is listed.

// The helpers every file shares, declared once (a file names them `crate::common`,
// `crate::rng`, ...).
#[path = "common/cli_json.rs"]
mod cli_json;
mod common;
#[path = "common/mat4.rs"]
mod mat4;
#[path = "common/raster.rs"]
mod raster;
#[path = "common/rng.rs"]
mod rng;
#[path = "common/tempdir.rs"]
mod tempdir;

// The test files.
#[path = "adapters.rs"]
mod adapters;
#[path = "adapters_aa_crates.rs"]
mod adapters_aa_crates;
#[path = "adapters_area.rs"]
mod adapters_area;
#[path = "adapters_euc.rs"]
mod adapters_euc;
mod adapters_values;
#[path = "adapters_wgpu.rs"]
mod adapters_wgpu;
#[path = "area.rs"]
mod area;
#[path = "area_crates_models.rs"]
mod area_crates_models;
#[path = "area_planned.rs"]
mod area_planned;
#[path = "big_polygons.rs"]
mod big_polygons;
#[path = "check_cli.rs"]
mod check_cli;
#[path = "check_scale.rs"]
mod check_scale;
#[path = "cli.rs"]
mod cli;
#[path = "clip.rs"]
mod clip;
#[path = "clip_scene.rs"]
mod clip_scene;
#[path = "compact.rs"]
mod compact;
#[path = "conservative.rs"]
mod conservative;
#[path = "float_fill.rs"]
mod float_fill;
#[path = "float_teeth.rs"]
mod float_teeth;
#[path = "flood.rs"]
mod flood;
#[path = "flood_cli.rs"]
mod flood_cli;
#[path = "fuzz_cases.rs"]
mod fuzz_cases;
#[path = "fuzz_layout.rs"]
mod fuzz_layout;
#[path = "golden.rs"]
mod golden;
#[path = "grey_hunt.rs"]
mod grey_hunt;
#[path = "homogeneous.rs"]
mod homogeneous;
#[path = "html_report.rs"]
mod html_report;
#[path = "hunt.rs"]
mod hunt;
#[path = "hunt_families.rs"]
mod hunt_families;
#[path = "ids_png.rs"]
mod ids_png;
#[path = "import.rs"]
mod import;
#[path = "layering.rs"]
mod layering;
#[path = "line_drawing_diff.rs"]
mod line_drawing_diff;
#[path = "lines.rs"]
mod lines;
#[path = "oracle.rs"]
mod oracle;
#[path = "outputs.rs"]
mod outputs;
#[path = "parallel.rs"]
mod parallel;
#[path = "planned.rs"]
mod planned;
#[path = "planned_polygons_lines.rs"]
mod planned_polygons_lines;
#[path = "polygons.rs"]
mod polygons;
#[path = "properties.rs"]
mod properties;
#[path = "renderer_processes.rs"]
mod renderer_processes;
#[path = "samples.rs"]
mod samples;
#[path = "scanline.rs"]
mod scanline;
#[path = "scene_file_errors.rs"]
mod scene_file_errors;
#[path = "shrink_simple.rs"]
mod shrink_simple;
#[path = "speed_hack.rs"]
mod speed_hack;
#[path = "stay_alive.rs"]
mod stay_alive;
#[path = "suite.rs"]
mod suite;
#[path = "trade.rs"]
mod trade;
#[path = "trade_values.rs"]
mod trade_values;
#[path = "values.rs"]
mod values;
mod values_compare;
mod values_explain;
mod values_invariants;
mod values_planned;

/// Every `tests/*.rs` file is a module of this binary: with `autotests = false` in
/// Cargo.toml, a file left out of the list above would never compile or run.
#[test]
fn every_test_file_is_a_module_of_this_binary() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let this = std::fs::read_to_string(dir.join("it.rs")).expect("tests/it.rs");
    let mut missing = Vec::new();
    for entry in std::fs::read_dir(&dir).expect("tests/") {
        let name = entry
            .expect("a tests/ entry")
            .file_name()
            .to_string_lossy()
            .into_owned();
        let Some(module) = name.strip_suffix(".rs") else {
            continue;
        };
        if module != "it" && !this.lines().any(|l| l == format!("mod {module};")) {
            missing.push(name);
        }
    }
    assert!(missing.is_empty(), "tests/it.rs does not list {missing:?}");
}
