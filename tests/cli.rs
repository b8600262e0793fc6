//! The command line: the JSON machine interface against the independent oracle, bad input
//! (exit code 2, one clear line, no panic), and the check command.

use crate::common;

use assert_cmd::Command;
use common::{parse_coverage_json, Conv, Rule};
use num_rational::BigRational;
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use rasterproof::scene::Scene;
use rasterproof::strategy::tie_heavy_triangle;

fn bin() -> Command {
    Command::cargo_bin("rasterproof").unwrap()
}

fn write(dir: &tempdir::Dir, name: &str, text: &str) -> std::path::PathBuf {
    let p = dir.path().join(name);
    std::fs::write(&p, text).unwrap();
    p
}

use crate::tempdir;

/// `render --format json` agrees with the independent oracle (tests/common) on seeded
/// tie-heavy scenes, for d3d11 and gl, with exact-snapped and fixed alike.
#[test]
fn json_output_matches_the_independent_oracle() {
    let dir = tempdir::Dir::new("json");
    let mut runner = TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &[7; 32]));
    let strategy = proptest::collection::vec(tie_heavy_triangle(10), 1..6);
    for case in 0..12 {
        let tris = strategy.new_tree(&mut runner).unwrap().current();
        let scene = Scene::new(10, 10, tris.clone());
        let path = write(&dir, &format!("s{case}.json"), &scene.to_json());
        let raw: Vec<[[BigRational; 2]; 3]> = tris.iter().map(|t| t.v.clone().map(|p| [p.x, p.y])).collect();
        for (preset, rule) in [("d3d11", Rule::TopLeft), ("gl", Rule::BottomLeft)] {
            let expected = common::render(
                &raw,
                10,
                10,
                Conv {
                    rule,
                    bits: 8,
                    half_away: false,
                },
            );
            for model in ["exact-snapped", "fixed"] {
                let out = bin()
                    .args([
                        "render",
                        path.to_str().unwrap(),
                        "--format",
                        "json",
                        "--preset",
                        preset,
                        "--model",
                        model,
                    ])
                    .output()
                    .unwrap();
                assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
                let (w, h, got) = parse_coverage_json(std::str::from_utf8(&out.stdout).unwrap());
                assert_eq!((w, h), (10, 10));
                assert_eq!(got, expected, "case {case} {preset} {model}:\n{}", scene.to_json());
            }
        }
    }
}

/// The exact byte format of the machine interface, on the hand-derived square of
/// tests/golden.rs cut down to 2x2: T0 = (0,0)(2,0)(2,2) owns the diagonal.
#[test]
fn json_format_is_exact() {
    let dir = tempdir::Dir::new("format");
    let p = write(
        &dir,
        "sq.json",
        r#"{"width": 2, "height": 3, "triangles": [{"v": [[0,0],[2,0],[2,2]]}, {"v": [[0,0],[2,2],[0,2]]}]}"#,
    );
    bin()
        .args(["render", p.to_str().unwrap(), "--format", "json"])
        .assert()
        .success()
        .stdout("{\"width\":2,\"height\":3,\"pixels\":[[0,0,[0]],[1,0,[0]],[0,1,[1]],[1,1,[0]]]}\n");
}

/// Lines in the JSON output: ids after the triangles; seed 001's example by hand.
#[test]
fn lines_render_after_triangles() {
    let dir = tempdir::Dir::new("lines");
    let p = write(
        &dir,
        "l.json",
        r#"{"width": 12, "height": 12, "triangles": [{"v": [[0,0],[2,0],[0,2]]}], "lines": [{"from": [5, 8], "to": [9, 11]}]}"#,
    );
    // At x = 7 the ideal line is at y = 9.5 exactly: Bresenham's default tie (stay) keeps
    // y = 9; the DDA's floor(y + 1/2) rounds the exactly representable 9.5 up to 10.
    for (model, seventh) in [("exact", 9), ("bresenham", 9), ("dda32", 10), ("dda64", 10)] {
        bin()
            .args(["render", p.to_str().unwrap(), "--format", "json", "--model", model])
            .assert()
            .success()
            .stdout(format!(
                "{{\"width\":12,\"height\":12,\"pixels\":[[0,0,[0]],[5,8,[1]],[6,9,[1]],[7,{seventh},[1]],[8,10,[1]],[9,11,[1]]]}}\n"
            ));
    }
    let bad = write(
        &dir,
        "frac.json",
        r#"{"width": 12, "height": 12, "lines": [{"from": [0.5, 8], "to": [9, 11]}]}"#,
    );
    let out = bin().args(["render", bad.to_str().unwrap()]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("lines[0].from[0]: 1/2 is not an integer"), "{err}");
    let far = write(
        &dir,
        "far.json",
        r#"{"width": 12, "height": 12, "lines": [{"from": [16777217, 8], "to": [9, 11]}]}"#,
    );
    let out = bin().args(["render", far.to_str().unwrap()]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8(out.stderr)
        .unwrap()
        .contains("lines[0].from[0]: 16777217 is outside +-2^24"));
    let missing = write(
        &dir,
        "missing.json",
        r#"{"width": 12, "height": 12, "lines": [{"from": [1, 8]}]}"#,
    );
    let out = bin().args(["render", missing.to_str().unwrap()]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8(out.stderr)
        .unwrap()
        .contains("lines[0].to: missing (required)"));
    let diamond_far = write(
        &dir,
        "dfar.json",
        r#"{"width": 12, "height": 12, "lines": [{"from": [0, 0], "to": [2097153, 1], "rule": "diamond"}]}"#,
    );
    let out = bin()
        .args(["render", diamond_far.to_str().unwrap(), "--model", "fixed"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8(out.stderr)
        .unwrap()
        .contains("lines[0].to.x: 2097153 px"));
}

#[test]
fn render_writes_pngs_and_names_the_preset() {
    let dir = tempdir::Dir::new("png");
    let cov = dir.path().join("cov.png");
    let col = dir.path().join("col.png");
    let out = bin()
        .args([
            "render",
            "examples/scenes/seed003.json",
            "--model",
            "fixed",
            "-o",
            cov.to_str().unwrap(),
        ])
        .args(["--colors-out", col.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("model fixed, preset d3d11"), "{text}");
    assert!(text.contains("58311 pixels covered"), "{text}");
    let img = image::open(&col).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (512, 512));
    // (489, 410) is the last pixel of column 489 (see tests/golden.rs): near v0, mostly red.
    let px = img.get_pixel(489, 410).0;
    assert!(px[0] > 200 && px[1] < 30, "{px:?}");
    assert_eq!(image::open(&cov).unwrap().to_rgb8().get_pixel(0, 0).0, [0, 0, 0]);
}

/// Polygons in the JSON output, ids after triangles and lines; the 3x3 square with a
/// 1x1 hole counted by hand: 9 - 1 = 8 pixels, all models that fill polygons agree.
#[test]
fn polygons_render_after_triangles_and_lines() {
    let dir = tempdir::Dir::new("polygons");
    let p = write(
        &dir,
        "p.json",
        r#"{"width": 6, "height": 6, "triangles": [{"v": [[0,0],[1,0],[0,1]]}], "lines": [{"from": [5, 0], "to": [5, 0]}],
            "polygons": [{"v": [[2,2],[5,2],[5,5],[2,5]], "holes": [[[3,3],[4,3],[4,4],[3,4]]], "fill_rule": "even-odd"}]}"#,
    );
    // The triangle (0,0) (1,0) (0,1) holds no sample (its hypotenuse passes through
    // (0.5, 0.5): a right edge, excluded); the line is one pixel.
    let ring: Vec<String> = [(2, 2), (3, 2), (4, 2), (2, 3), (4, 3), (2, 4), (3, 4), (4, 4)]
        .iter()
        .map(|(x, y)| format!("[{x},{y},[2]]"))
        .collect();
    let expected = format!(
        "{{\"width\":6,\"height\":6,\"pixels\":[[5,0,[1]],{}]}}\n",
        ring.join(",")
    );
    for model in ["exact", "exact-snapped", "scanline", "fixed"] {
        bin()
            .args(["render", p.to_str().unwrap(), "--format", "json", "--model", model])
            .assert()
            .success()
            .stdout(expected.clone());
    }
}

/// Each bad input: exit code 2, one line on stderr naming the field and value, no panic.
#[test]
fn bad_inputs_exit_2_with_a_clear_line() {
    let dir = tempdir::Dir::new("bad");
    let tri = |v: &str| format!(r#"{{"width": 8, "height": 8, "triangles": [{{"v": {v}}}]}}"#);
    let poly = |body: &str| format!(r#"{{"width": 8, "height": 8, "polygons": [{{{body}}}]}}"#);
    let far = 1i64 << 21;
    let cases: Vec<(String, &str, &str)> = vec![
        ("{\"width\": 8,".into(), "exact-snapped", "malformed JSON"),
        (r#"{"height": 8}"#.into(), "exact-snapped", "width: missing"),
        (r#"{"width": "8", "height": 8}"#.into(), "exact-snapped", "width: expected a non-negative integer, found \"8\""),
        (tri(r#"[[0,0],[4,"NaN"],[0,4]]"#), "exact-snapped", "triangles[0].v[1][1]: \"NaN\" is not a finite number"),
        (tri(r#"[[0,0],[4,"inf"],[0,4]]"#), "exact", "triangles[0].v[1][1]: \"inf\""),
        (tri(r#"[[0,0],[4,"1/0"],[0,4]]"#), "exact", "\"1/0\" has a zero denominator"),
        (r#"{"width": 0, "height": 8}"#.into(), "exact", "width: 0 is outside 1..=16384"),
        (r#"{"width": 8, "height": 16385}"#.into(), "exact", "height: 16385 is outside 1..=16384"),
        (tri(r#"[[0,0],[4,0],[0,4],[1,1]]"#), "exact", "triangles[0].v: a triangle needs exactly 3 vertices, found 4"),
        (
            r#"{"width": 8, "height": 8, "triangles": [{"v": [[0,0],[4,0],[0,4]], "colors": [[0,0,0],[300,0,0],[0,0,0]]}]}"#.into(),
            "exact",
            "triangles[0].colors[1][0]: 300 is not an integer in 0..=255",
        ),
        (tri(&format!("[[0,0],[4,0],[{},4]]", far + 1)), "fixed", "triangles[0].v[2].x: 2097153 px"),
        (r#"{"width": 8, "height": 8, "preset": "dx9"}"#.into(), "exact", "preset: unknown preset \"dx9\""),
        (
            tri("[[0,0],[4,0],[1e39,4]]"),
            "float32",
            // 1e39 written exactly: 1 and 39 zeros; f32's largest finite value is about 3.4e38.
            "triangles[0].v[2].x: 1000000000000000000000000000000000000000 does not fit the float32 model's float type f32",
        ),
        (poly(r#""v": [[0,0],[4,0]]"#), "exact", "polygons[0].v: a polygon contour needs at least 3 vertices, found 2"),
        (
            poly(r#""v": [[0,0],[4,0],[4,4]], "holes": [[[1,1],[2,1]]]"#),
            "exact",
            "polygons[0].holes[0]: a polygon contour needs at least 3 vertices, found 2",
        ),
        (
            poly(r#""v": [[0,0],[8,0],[8,8],[0,8]], "holes": [[[9,2],[1,1],[2,1]]]"#),
            "scanline",
            "polygons[0].holes[0][0]: (9, 2) lies outside the outline polygons[0].v",
        ),
        (poly(r#""v": [[0,0],[8,0],[0,8]], "fill_rule": "winding""#), "exact", "polygons[0].fill_rule: unknown fill rule \"winding\""),
        (poly(r#""v": [[0,0],[8,0],["NaN",8]]"#), "exact", "polygons[0].v[2][0]: \"NaN\" is not a finite number"),
        (poly(r#""v": [[0,0],[8,8],[8,0],[0,8]]"#), "fixed", "polygons[0]: cannot triangulate for the fixed model: not a simple polygon: outline edge 0 and outline edge 2 meet at (4, 4) px"),
        (poly(&format!(r#""v": [[0,0],[8,0],[0,{}]]"#, far + 1)), "scanline", "polygons[0].v[2].y: 2097153 px"),
        (poly(r#""v": [[0,0],[8,0],[0,8]], "colour": 3"#), "exact", "polygons[0].colour: unknown field"),
    ];
    for (k, (text, model, needle)) in cases.iter().enumerate() {
        let p = write(&dir, &format!("bad{k}.json"), text);
        let out = bin()
            .args(["render", p.to_str().unwrap(), "--model", model])
            .output()
            .unwrap();
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "case {k}: {err}");
        assert!(err.contains(needle), "case {k}: {err:?} lacks {needle:?}");
        assert!(
            err.contains(&format!("bad{k}.json")),
            "case {k}: the file is not named: {err}"
        );
        assert_eq!(err.lines().count(), 1, "case {k}: {err}");
        assert!(!err.contains("panicked"));
    }
    // unknown model and preset on the command line
    let ok = write(&dir, "ok.json", &tri("[[0,0],[4,0],[0,4]]"));
    for (args, needle) in [
        (vec!["--model", "float16"], "--model: unknown model \"float16\""),
        (vec!["--preset", "metal"], "--preset: unknown preset \"metal\""),
    ] {
        let out = bin()
            .args(["render", ok.to_str().unwrap()])
            .args(&args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2));
        assert!(String::from_utf8(out.stderr).unwrap().contains(needle));
    }
    // a missing file
    let out = bin().args(["render", "no/such/scene.json"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8(out.stderr)
        .unwrap()
        .contains("no/such/scene.json: cannot read"));
}

/// `check` on a few cases: the exact and fixed models hold everything (exit 0), the table
/// lists every invariant, and failing float cases are written as scene files that parse.
#[test]
fn check_runs_the_suite() {
    let dir = tempdir::Dir::new("check");
    let out = bin()
        .args([
            "check",
            "--cases",
            "12",
            "--seed",
            "3",
            "--quiet",
            "--out",
            dir.path().to_str().unwrap(),
        ])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(out.status.success(), "{text}\n{}", String::from_utf8_lossy(&out.stderr));
    for needle in [
        "watertight",
        "agreement (mesh)",
        "agreement (triangle)",
        "rotation/winding",
        "translation",
        "barycentric sum",
        "integer edge sum",
        "polygon agreement",
        "triangulation",
        "clip inside",
        "clip raster",
        "segment clip",
    ] {
        assert!(text.contains(needle), "{needle} missing:\n{text}");
    }
    assert!(
        text.contains("ok: the exact and integer models (exact, exact-snapped, fixed, scanline) hold every invariant")
    );
    for entry in std::fs::read_dir(dir.path()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "json") {
            let text = std::fs::read_to_string(&path).unwrap();
            assert!(
                rasterproof::scene::parse_scene(&text, "case").is_ok(),
                "{}",
                path.display()
            );
        }
    }
}

/// Issue 10's small scene, 6x4: triangle 0 = (0,0) (4,0) (0,4) holds the samples with
/// x + y < 4 (x + y = 4 lies on its hypotenuse, a bottom-right edge: excluded), i.e.
/// (0..=2, 0), (0..=1, 1), (0, 2); line 1 runs along row 1 from x = 1 to 4, so (1, 1) has
/// two owners; lines 2..=11 are single pixels (2..=7 along row 3, 8, 9, 10 down column 5,
/// 11 at (4, 2)), so ids 10 and 11 show their last digits 0 and 1.
const GRID_SCENE: &str = r#"{"width": 6, "height": 4, "triangles": [{"v": [[0,0],[4,0],[0,4]]}],
    "lines": [{"from": [1,1], "to": [4,1]},
              {"from": [0,3], "to": [0,3]}, {"from": [1,3], "to": [1,3]}, {"from": [2,3], "to": [2,3]},
              {"from": [3,3], "to": [3,3]}, {"from": [4,3], "to": [4,3]}, {"from": [5,3], "to": [5,3]},
              {"from": [5,0], "to": [5,0]}, {"from": [5,1], "to": [5,1]}, {"from": [5,2], "to": [5,2]},
              {"from": [4,2], "to": [4,2]}]}"#;

/// `--format text` draws small canvases as a grid (row 0 first) above the summary.
#[test]
fn text_format_draws_the_grid() {
    let dir = tempdir::Dir::new("grid");
    let p = write(&dir, "grid.json", GRID_SCENE);
    let out = bin().args(["render", p.to_str().unwrap()]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[..4], ["000..8", "0#1119", "0...10", "234567"], "{text}");
    assert_eq!(lines.len(), 5, "{text}");
    // 4 + 6 + 3 + 6 covered pixels, (1, 1) twice.
    assert!(
        lines[4].contains("19 pixels covered, 1 covered more than once"),
        "{text}"
    );
    // 65 pixels wide: the summary only.
    let wide = write(
        &dir,
        "wide.json",
        r#"{"width": 65, "height": 2, "lines": [{"from": [0,0], "to": [3,0]}]}"#,
    );
    let out = bin().args(["render", wide.to_str().unwrap()]).output().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text.lines().count(), 1, "{text}");
    assert!(text.contains("4 pixels covered"), "{text}");
}

/// The picture is scaled (default: the smallest K with a width of at least 256 px, here
/// ceil(256 / 6) = 43), a pixel with two owners is white, and the legend beside it names
/// every id with its colour. Colours by hand (src/coverage/picture.rs derives them): id 0
/// hue 0 = (235, 70, 70); id 1 hue 0.618 turns = (70, 118, 235); id 2 = (166, 235, 70).
#[test]
fn picture_is_scaled_and_has_a_legend() {
    let dir = tempdir::Dir::new("picture");
    let p = write(&dir, "grid.json", GRID_SCENE);
    let cov = dir.path().join("cov.png");
    let col = dir.path().join("col.png");
    let out = bin()
        .args(["render", p.to_str().unwrap(), "-o", cov.to_str().unwrap()])
        .args(["--colors-out", col.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let img = image::open(&cov).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (6 * 43, 4 * 43));
    assert_eq!(image::open(&col).unwrap().to_rgb8().dimensions(), (6 * 43, 4 * 43));
    let block = |x: u32, y: u32| {
        let want = img.get_pixel(x * 43, y * 43).0;
        for dy in 0..43 {
            for dx in 0..43 {
                assert_eq!(img.get_pixel(x * 43 + dx, y * 43 + dy).0, want, "block ({x}, {y})");
            }
        }
        want
    };
    assert_eq!(block(0, 0), [235, 70, 70]);
    assert_eq!(block(1, 1), [255, 255, 255]);
    assert_eq!(block(2, 1), [70, 118, 235]);
    assert_eq!(block(0, 3), [166, 235, 70]);
    assert_eq!(block(3, 0), [0, 0, 0]);
    let legend = std::fs::read_to_string(dir.path().join("cov.legend.txt")).unwrap();
    let rows: Vec<&str> = legend.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(rows.len(), 12, "{legend}");
    assert_eq!(
        rows[..3],
        [
            "0 #eb4646 triangles[0] 6",
            "1 #4676eb lines[0] 4",
            "2 #a6eb46 lines[1] 1"
        ],
        "{legend}"
    );
    assert!(
        rows[11].starts_with("11 #") && rows[11].ends_with(" lines[10] 1"),
        "{legend}"
    );
    assert!(legend.contains("scale 43"), "{legend}");
    assert!(legend.contains("several owners #ffffff"), "{legend}");

    // --scale K, then bad scales: exit 2, one line naming --scale and the value, no file.
    let small = dir.path().join("small.png");
    let out = bin()
        .args([
            "render",
            p.to_str().unwrap(),
            "--scale",
            "2",
            "-o",
            small.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(image::open(&small).unwrap().to_rgb8().dimensions(), (12, 8));
    let never = dir.path().join("never.png");
    for (k, needle) in [
        ("0", "--scale: 0 is not a scale"),
        ("abc", "--scale: \"abc\" is not a whole number"),
        ("-3", "--scale: \"-3\" is not a whole number"),
        // 16384 / 6 = 2730.67: 2731 makes the picture 16386 px wide.
        (
            "2731",
            "--scale: 2731 makes the 6x4 canvas a 16386x10924 picture, over 16384 px per side (at most 2730",
        ),
    ] {
        let out = bin()
            .args([
                "render",
                p.to_str().unwrap(),
                "--scale",
                k,
                "-o",
                never.to_str().unwrap(),
            ])
            .output()
            .unwrap();
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "{k}: {err}");
        assert!(
            err.contains(needle) && err.lines().count() == 1,
            "{k}: {err:?} lacks {needle:?}"
        );
        assert!(!never.exists(), "{k}");
    }
}

/// Every command's help states the exit codes; `render --help` says what exact-snapped is.
#[test]
fn help_states_exit_codes_and_the_exact_models() {
    for command in ["render", "clip", "flood", "check"] {
        let out = bin().args([command, "--help"]).output().unwrap();
        assert!(out.status.success());
        let help = String::from_utf8(out.stdout).unwrap();
        assert!(help.contains("Exit codes:"), "{command}:\n{help}");
        assert!(
            help.contains("0  success") && help.contains("2  bad input"),
            "{command}:\n{help}"
        );
        assert!(
            help.contains("1  an invariant of an exact or integer model"),
            "{command}:\n{help}"
        );
    }
    let help = String::from_utf8(bin().args(["render", "--help"]).output().unwrap().stdout).unwrap();
    assert!(
        help.contains("exact-snapped  first rounds every vertex to the subpixel grid"),
        "{help}"
    );
    assert!(
        help.contains("exact          takes the vertices exactly as the scene file writes them"),
        "{help}"
    );
}

/// `plan` lists every primitive in id order (triangles first, then lines), in both
/// formats: the triangle is planned in some width, a Bresenham line is not planned (it
/// runs in i64 whatever the plan), and the JSON says the same as the text.
#[test]
fn plan_lists_primitives_in_id_order_in_text_and_json() {
    let dir = tempdir::Dir::new("plan");
    let scene = write(
        &dir,
        "s.json",
        r#"{"width": 8, "height": 8,
            "lines": [{"from": [0, 0], "to": [7, 3], "rule": "bresenham"}],
            "triangles": [{"v": [[0, 0], [4, 0], [0, 4]]}]}"#,
    );
    let run = |format: &str| {
        let out = bin()
            .args(["plan", scene.to_str().unwrap(), "--format", format])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
        String::from_utf8(out.stdout).unwrap()
    };
    let text = run("text");
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[0].ends_with("model exact-snapped, preset d3d11 (tie rule top-left, pixel centre 0.5, 8 subpixel bits, rounding nearest-even)"), "{text}");
    assert!(lines[1].starts_with("triangle 0 (id 0): "), "{text}");
    assert!(!lines[1].contains("not planned"), "{text}");
    assert_eq!(lines[2], "line 0 (id 1): not planned: a Bresenham line", "{text}");
    assert!(lines[3].starts_with("summary: "), "{text}");
    assert_eq!(lines[4], "fixed-width models:", "{text}");
    let json: serde_json::Value = serde_json::from_str(&run("json")).unwrap();
    let prims = json["primitives"].as_array().unwrap();
    assert_eq!(prims.len(), 2);
    assert_eq!(
        (prims[0]["kind"].as_str(), prims[0]["id"].as_u64()),
        (Some("triangle"), Some(0))
    );
    assert!(prims[0]["width"].is_string(), "{json}");
    assert_eq!(
        (prims[1]["kind"].as_str(), prims[1]["id"].as_u64()),
        (Some("line"), Some(1))
    );
    assert_eq!(prims[1]["unplanned"].as_str(), Some("a Bresenham line"), "{json}");
    assert!(prims[1]["width"].is_null(), "{json}");
    assert_eq!(json["model"], "exact-snapped");
    let planned: u64 = json["by_width"]
        .as_object()
        .unwrap()
        .values()
        .map(|n| n.as_u64().unwrap())
        .sum();
    assert_eq!(planned, 1, "{json}");
}

/// The long flags that clap's `--help` text defines: each option line (`  -o, --out
/// <OUT>`, `      --model <MODEL>`), not the flags its descriptions mention.
fn help_flags(help: &str) -> std::collections::BTreeSet<String> {
    help.lines()
        .map(str::trim_start)
        .filter(|l| l.starts_with('-'))
        .flat_map(|l| l.split([' ', ',']).filter(|w| w.starts_with("--")).take(1))
        .map(|w| w.split('=').next().unwrap_or(w).to_string())
        .filter(|f| f != "--help" && f != "--version")
        .collect()
}

/// The flags a synopsis names (`--name`; `-o` is `--out`), each once, sorted.
fn synopsis_flags(text: &str) -> std::collections::BTreeSet<String> {
    let mut out = std::collections::BTreeSet::new();
    for word in text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-')) {
        if word == "-o" {
            out.insert("--out".to_string());
        } else if word.len() > 2 && word.starts_with("--") && word[2..].starts_with(|c: char| c.is_ascii_lowercase()) {
            out.insert(word.to_string());
        }
    }
    out
}

/// docs/cli.md's synopses name every flag that each subcommand's `--help` has, and no
/// other: a flag added to the command without its synopsis (or the other way round) fails
/// here, naming the subcommand and the flags.
#[test]
fn the_synopses_name_every_flag_of_help() {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/cli.md")).unwrap();
    let start = doc.find("## Command line").expect("docs/cli.md has its synopses");
    let block = doc[start..].split("```").nth(1).expect("the synopses' block");
    let mut subcommands: Vec<&str> = block
        .lines()
        .filter_map(|l| l.strip_prefix("rasterproof "))
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    subcommands.dedup();
    assert!(subcommands.len() >= 12, "{subcommands:?}");
    let mut wrong = Vec::new();
    for sub in subcommands {
        let synopsis: String = block
            .lines()
            .filter(|l| l.strip_prefix("rasterproof ").and_then(|l| l.split_whitespace().next()) == Some(sub))
            .collect::<Vec<_>>()
            .join("\n");
        let out = bin().args([sub, "--help"]).output().unwrap();
        assert!(out.status.success(), "{sub} --help");
        let help = help_flags(&String::from_utf8_lossy(&out.stdout));
        let documented = synopsis_flags(&synopsis);
        let missing: Vec<&String> = help.difference(&documented).collect();
        let extra: Vec<&String> = documented.difference(&help).collect();
        if !missing.is_empty() || !extra.is_empty() {
            wrong.push(format!(
                "{sub}: --help has {missing:?} the synopsis lacks; the synopsis has {extra:?} --help lacks"
            ));
        }
    }
    assert!(
        wrong.is_empty(),
        "docs/cli.md's synopses against --help:\n{}",
        wrong.join("\n")
    );
}
