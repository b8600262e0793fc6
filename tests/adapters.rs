//! The adapters for real renderers (adapters/README.md): tiny-skia (the example
//! `tiny-skia-adapter`) and Mesa's llvmpipe and softpipe through OSMesa
//! (`adapters/osmesa/render.py`), each run on small fixed scenes and judged by `compare`.
//!
//! What is asserted, and why it should hold independently of these runs:
//! - a scene with no sample on any edge (checked exactly below) and every vertex on the
//!   1/64 grid reads the same under every tie rule and every snapping of 6 or more bits,
//!   so llvmpipe (8 subpixel bits, `FIXED_ORDER` in lp_setup_tri.c) and softpipe (float
//!   setup, no snapping) must equal the oracle exactly, several owners included (the
//!   adapters' alpha-254 mark); tiny-skia may differ there only in its 16.16 edge walk's
//!   error (`snapping` or `near-edge`), never by a tie or a gross difference;
//! - on a grid whose vertices lie on pixel centres (every edge through samples),
//!   llvmpipe equals the `gl` preset (bottom-left in the y-down image: GL's top-left in
//!   its y-up window, which the adapter flips) and differs from `d3d11` by ties alone,
//!   each explained by bottom-left; softpipe's ties are all top-right; tiny-skia's all
//!   bottom-right (edge.rs and scan/path.rs: rows `[round(y0), round(y1))`, spans
//!   `[round(xl), round(xr))`, so bottom and right edges own their samples);
//! - on a mesh with vertices on a 1/4096 grid, llvmpipe equals the oracle with 8 bits
//!   nearest-even and softpipe the unsnapped oracle (`--model exact`);
//! - llvmpipe's diamond-exit lines and a convex clip window (drawn through the stencil)
//!   equal the `gl` preset's.
//!
//! The OSMesa tests need /usr/bin/python3 (or `RASTERPROOF_ADAPTER_PYTHON`) with Debian's
//! python3-opengl, python3-numpy, python3-pil and libosmesa6: without them they print a
//! skip message, unless the environment variable `CI` is set (.ci/run installs them),
//! where they fail.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use rasterproof::convention::Target;
use rasterproof::edge::exact::edge_function;
use rasterproof::raster::sample_exact;
use rasterproof::scene::{parse_scene, parse_scene_with, ParseOptions};
use serde_json::Value;

use crate::tempdir;

/// The interpreter Debian's python3-* packages are installed for (another one:
/// `RASTERPROOF_ADAPTER_PYTHON`).
fn python() -> String {
    std::env::var("RASTERPROOF_ADAPTER_PYTHON").unwrap_or_else(|_| "/usr/bin/python3".to_string())
}

/// Six overlapping triangles on a 16x16 canvas, vertices on the 1/64 grid, no sample on
/// any edge (12 pixels have several owners).
const NO_TIES: &str = include_str!("../adapters/scenes/no-ties.json");

/// A 3x3 grid of squares of side 3 on a 10x10 canvas, vertices on pixel centres, each
/// square split along a diagonal (alternating): every edge runs through samples.
const TIE_GRID: &str = include_str!("../adapters/scenes/tie-grid.json");

/// Four polygons on a 10x10 canvas (a square, a triangle, an L and an even-odd diamond),
/// vertices on pixel centres: axis-aligned and 45-degree edges run through samples.
const POLYGON_TIES: &str = include_str!("../adapters/scenes/polygon-ties.json");

/// An 8x8 mesh of 8 px cells on a 64x64 canvas, interior vertices moved off the grid by
/// multiples of 1/4096 px (up to 1.5 px), no overlaps.
const FINE_MESH: &str = include_str!("../adapters/scenes/fine-mesh.json");

/// Twelve diamond-exit lines on a 32x32 canvas, endpoints on the 1/256 grid.
const DIAMOND_LINES: &str = include_str!("../adapters/scenes/diamond-lines.json");

/// Six triangles on the 1/256 grid under a convex clip window.
const CLIP_CONVEX: &str = include_str!("../adapters/scenes/clip-convex.json");

/// True when no pixel sample of the scene's canvas lies on an edge of any triangle.
fn tie_free(text: &str) -> bool {
    let scene = parse_scene(text, "scene").expect("a valid scene");
    let target = Target::new(scene.width, scene.height, scene.convention()).expect("a valid canvas");
    scene.triangles().iter().all(|t| {
        (0..3).all(|k| {
            let (a, b) = (&t.v[k], &t.v[(k + 1) % 3]);
            (0..scene.height).all(|y| {
                (0..scene.width).all(|x| !num_traits::Zero::is_zero(&edge_function(a, b, &sample_exact(x, y, &target))))
            })
        })
    })
}

fn write(dir: &tempdir::Dir, name: &str, text: &str) -> PathBuf {
    let path = dir.path().join(name);
    std::fs::write(&path, text).unwrap();
    path
}

fn text(output: &Output) -> String {
    format!(
        "status {:?}\nstdout:\n{}\nstderr:\n{}",
        output.status.code(),
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    )
}

/// The tiny-skia adapter's executable (see [`example`]).
pub fn tiny_skia_adapter() -> PathBuf {
    example("tiny-skia-adapter")
}

/// The executable of the example `name`, built (if stale) with the profile `cargo test`
/// builds examples with, so that a plain `cargo test` finds it up to date.
pub fn example(name: &str) -> PathBuf {
    let output = Command::new(env!("CARGO"))
        .args([
            "build",
            "--profile",
            "test",
            "--example",
            name,
            "--message-format=json-render-diagnostics",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        // A test binary run with RUSTC_BOOTSTRAP=1 (for `-Z unstable-options
        // --report-time`) would otherwise rebuild the example and its dependencies under
        // another fingerprint, a 3-minute "slow test" that is cargo's.
        .env_remove("RUSTC_BOOTSTRAP")
        .output()
        .expect("cargo runs");
    // Diagnostics are rendered on stderr; stdout holds the JSON artifact messages.
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "building the example failed:\n{stderr}");
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter_map(|line| serde_json::from_str::<Value>(line).ok())
        .filter(|m| m["reason"] == "compiler-artifact" && m["target"]["name"] == name)
        .find_map(|m| m["executable"].as_str().map(PathBuf::from))
        .expect("cargo names the example's executable")
}

/// Whether /usr/bin/python3 has the OSMesa stack; without it: skip, or fail under CI.
fn osmesa_available() -> bool {
    let probe = Command::new(python())
        .args(["-c", "import numpy, PIL; from OpenGL import osmesa, GL"])
        .env("PYOPENGL_PLATFORM", "osmesa")
        .output();
    let missing = match probe {
        Ok(o) if o.status.success() => return true,
        Ok(o) => String::from_utf8_lossy(&o.stderr)
            .lines()
            .last()
            .unwrap_or("")
            .trim()
            .to_string(),
        Err(e) => format!("{}: {e}", python()),
    };
    let message = format!(
        "the OSMesa Python stack is missing ({missing}); install libosmesa6 python3-opengl python3-numpy python3-pil"
    );
    assert!(
        std::env::var_os("CI").is_none(),
        "CI is set, so this is an error: {message}"
    );
    eprintln!("skipping the OSMesa adapter tests: {message}");
    false
}

/// Runs the OSMesa adapter with `driver`; asserts it succeeded and ran that driver.
fn osmesa(driver: &str, scene: &Path, out: &Path) {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/osmesa/render.py");
    let output = Command::new(python())
        .arg(script)
        .args([scene.as_os_str(), out.as_os_str()])
        .args(["--driver", driver])
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "render.py --driver {driver}:\n{}",
        text(&output)
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains(&format!("renderer: {driver}")), "{stderr}");
}

fn tiny_skia(adapter: &Path, scene: &Path, out: &Path) {
    let output = Command::new(adapter).arg(scene).arg(out).output().unwrap();
    assert!(output.status.success(), "tiny-skia-adapter:\n{}", text(&output));
}

/// `rasterproof compare SCENE THEIRS --as ids --format json ARGS`: (exit code, report).
fn compare(scene: &Path, theirs: &Path, args: &[&str]) -> (i32, Value) {
    let output = assert_cmd::Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("compare")
        .arg(scene)
        .arg(theirs)
        .args(["--as", "ids", "--format", "json"])
        .args(args)
        .output()
        .unwrap();
    let code = output.status.code().expect("compare exits");
    assert!(code == 0 || code == 1, "compare {args:?}:\n{}", text(&output));
    (code, serde_json::from_slice(&output.stdout).expect("compare's JSON"))
}

/// Every finding of a report: (class, the tie rules its reason names).
fn findings(report: &Value) -> Vec<(String, Vec<String>)> {
    let pixels = report["pixels"].as_array().expect("pixels");
    pixels
        .iter()
        .flat_map(|p| p["findings"].as_array().expect("findings").iter())
        .map(|f| {
            let rules = f["reason"]["rules"]
                .as_array()
                .map(|r| r.iter().filter_map(|s| s.as_str().map(str::to_string)).collect())
                .unwrap_or_default();
            (f["class"].as_str().expect("class").to_string(), rules)
        })
        .collect()
}

/// Asserts that the report differs, by ties alone, each explained by `rule`.
fn only_ties_explained_by(report: &Value, rule: &str, who: &str) {
    let all = findings(report);
    assert!(!all.is_empty(), "{who}: expected tie differences, found none");
    for (class, rules) in &all {
        assert_eq!(class, "tie", "{who}: a difference of class {class}: {report}");
        assert!(
            rules.iter().any(|r| r == rule),
            "{who}: a tie not explained by {rule} ({rules:?})"
        );
    }
}

#[test]
fn the_fixed_scenes_are_what_the_assertions_say() {
    assert!(tie_free(NO_TIES));
    assert!(!tie_free(TIE_GRID));
    assert!(parse_scene(FINE_MESH, "mesh").is_ok());
}

#[test]
fn tiny_skia_follows_bottom_right_and_its_edge_walk() {
    let adapter = tiny_skia_adapter();
    let dir = tempdir::Dir::new("adapters-tiny-skia");

    let scene = write(&dir, "no-ties.json", NO_TIES);
    let out = dir.path().join("no-ties.png");
    tiny_skia(&adapter, &scene, &out);
    let (_, report) = compare(&scene, &out, &["--subpixel-bits", "6", "--rounding", "towards-zero"]);
    for (class, _) in findings(&report) {
        assert!(
            class == "snapping" || class == "near-edge",
            "tiny-skia, no ties: class {class}: {report}"
        );
    }
    assert!(report["differing"].as_u64().unwrap() <= 4, "{report}");

    let scene = write(&dir, "grid.json", TIE_GRID);
    let out = dir.path().join("grid.png");
    tiny_skia(&adapter, &scene, &out);
    for preset in ["d3d11", "gl"] {
        let (code, report) = compare(&scene, &out, &["--preset", preset]);
        assert_eq!(code, 1);
        only_ties_explained_by(&report, "bottom-right", &format!("tiny-skia against {preset}"));
    }
}

/// tiny-skia's polygon ties are bottom-right, as its triangles' are: `--fit` names that
/// rule alone for a polygon scene whose edges run through samples (every exact fit is
/// bottom-right), and against the `gl` preset every difference is a tie that
/// bottom-right explains. Before the polygon engines had the six rules no convention fit.
#[test]
fn tiny_skia_polygons_follow_bottom_right() {
    let adapter = tiny_skia_adapter();
    let dir = tempdir::Dir::new("adapters-tiny-skia-polygons");
    let scene = write(&dir, "polygon-ties.json", POLYGON_TIES);
    let out = dir.path().join("polygon-ties.png");
    tiny_skia(&adapter, &scene, &out);
    let (code, report) = compare(&scene, &out, &["--fit"]);
    assert_eq!(code, 0, "{report}");
    let exact = report["exact"].as_array().expect("exact fits");
    assert!(!exact.is_empty(), "{report}");
    assert!(report["not_searched"].is_null(), "{report}");
    for fit in exact {
        assert_eq!(fit["tie_rule"], "bottom-right", "{report}");
    }
    let (code, report) = compare(&scene, &out, &["--preset", "gl"]);
    assert_eq!(code, 1);
    only_ties_explained_by(&report, "bottom-right", "tiny-skia's polygons against gl");
}

#[test]
fn tiny_skia_adapter_refuses_clearly() {
    let adapter = tiny_skia_adapter();
    let dir = tempdir::Dir::new("adapters-tiny-skia-bad");
    let clip_space = write(
        &dir,
        "clip-space.json",
        r#"{"width": 4, "height": 4, "clip_space_triangles": [{"v": [[0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, 1]]}]}"#,
    );
    let out = dir.path().join("out.png");
    let missing = dir.path().join("missing.json");
    let cases: [(Vec<&Path>, &str); 3] = [
        (vec![], "usage"),
        (vec![&missing, &out], "missing.json"),
        (vec![&clip_space, &out], "clip_space_triangles"),
    ];
    for (args, needle) in cases {
        let output = Command::new(&adapter).args(&args).output().unwrap();
        assert_eq!(output.status.code(), Some(2), "{args:?}:\n{}", text(&output));
        assert!(
            String::from_utf8_lossy(&output.stderr).contains(needle),
            "{}",
            text(&output)
        );
        assert!(!out.exists());
    }
}

#[test]
fn llvmpipe_is_the_gl_preset_exactly() {
    if !osmesa_available() {
        return;
    }
    let dir = tempdir::Dir::new("adapters-llvmpipe");
    let no_ties = write(&dir, "no-ties.json", NO_TIES);
    let grid = write(&dir, "grid.json", TIE_GRID);
    let mesh = write(&dir, "mesh.json", FINE_MESH);
    let out = |name: &str| dir.path().join(name);

    osmesa("llvmpipe", &no_ties, &out("no-ties.png"));
    for preset in ["d3d11", "gl"] {
        let (code, report) = compare(&no_ties, &out("no-ties.png"), &["--preset", preset]);
        assert_eq!(code, 0, "llvmpipe, no ties, {preset}: {report}");
    }

    osmesa("llvmpipe", &grid, &out("grid.png"));
    let (code, report) = compare(&grid, &out("grid.png"), &["--preset", "gl"]);
    assert_eq!(code, 0, "llvmpipe, tie grid, gl: {report}");
    let (_, report) = compare(&grid, &out("grid.png"), &["--preset", "d3d11"]);
    only_ties_explained_by(&report, "bottom-left", "llvmpipe against d3d11");

    osmesa("llvmpipe", &mesh, &out("mesh.png"));
    let (code, report) = compare(&mesh, &out("mesh.png"), &["--preset", "gl"]);
    assert_eq!(code, 0, "llvmpipe, 1/4096 mesh, gl (8 bits, nearest-even): {report}");
    let (code, _) = compare(&mesh, &out("mesh.png"), &["--preset", "gl", "--subpixel-bits", "4"]);
    assert_eq!(code, 1, "4 subpixel bits must not explain llvmpipe's mesh");

    // GL draws lines by the diamond-exit rule (GL 4.6 section 14.5.1), as the oracle does.
    let lines = write(&dir, "lines.json", DIAMOND_LINES);
    osmesa("llvmpipe", &lines, &out("lines.png"));
    let (code, report) = compare(&lines, &out("lines.png"), &["--preset", "gl"]);
    assert_eq!(code, 0, "llvmpipe, diamond-exit lines, gl: {report}");

    // The window through the stencil is GL's own raster of it, and the oracle's
    // raster(clip(P, W)) is raster(P) and raster(W) (property-tested in the crate).
    let clip = write(&dir, "clip.json", CLIP_CONVEX);
    osmesa("llvmpipe", &clip, &out("clip.png"));
    let (code, report) = compare(&clip, &out("clip.png"), &["--preset", "gl"]);
    assert_eq!(code, 0, "llvmpipe, convex clip window, gl: {report}");
}

#[test]
fn softpipe_is_unsnapped_with_top_right_ties() {
    if !osmesa_available() {
        return;
    }
    let dir = tempdir::Dir::new("adapters-softpipe");
    let no_ties = write(&dir, "no-ties.json", NO_TIES);
    let grid = write(&dir, "grid.json", TIE_GRID);
    let mesh = write(&dir, "mesh.json", FINE_MESH);
    let out = |name: &str| dir.path().join(name);

    osmesa("softpipe", &no_ties, &out("no-ties.png"));
    let (code, report) = compare(&no_ties, &out("no-ties.png"), &[]);
    assert_eq!(code, 0, "softpipe, no ties: {report}");

    osmesa("softpipe", &grid, &out("grid.png"));
    for preset in ["d3d11", "gl"] {
        let (_, report) = compare(&grid, &out("grid.png"), &["--preset", preset]);
        only_ties_explained_by(&report, "top-right", &format!("softpipe against {preset}"));
    }

    osmesa("softpipe", &mesh, &out("mesh.png"));
    let (code, report) = compare(&mesh, &out("mesh.png"), &["--model", "exact"]);
    assert_eq!(code, 0, "softpipe, 1/4096 mesh, unsnapped: {report}");
}

#[test]
fn osmesa_adapter_refuses_clearly() {
    if !osmesa_available() {
        return;
    }
    let dir = tempdir::Dir::new("adapters-osmesa-bad");
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/osmesa/render.py");
    let out = dir.path().join("out.png");
    let cases = [
        (
            r#"{"width": 4, "height": 4, "viewport": {"x": "1/2", "y": 0, "width": 4, "height": 4},
                "clip_space_triangles": [{"v": [[0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, 1]]}]}"#,
            "viewport",
        ),
        (
            r#"{"width": 4, "height": 4, "triangles": [{"v": [[0, 0], ["x", 0], [0, 1]]}]}"#,
            "triangles[0].v[1][0]",
        ),
        (r#"{"width": 4, "height": 4, "ellipses": []}"#, "ellipses"),
    ];
    for (k, (scene, needle)) in cases.into_iter().enumerate() {
        let path = write(&dir, &format!("bad{k}.json"), scene);
        let output = Command::new(python())
            .arg(&script)
            .arg(&path)
            .arg(&out)
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2), "{}", text(&output));
        assert!(
            String::from_utf8_lossy(&output.stderr).contains(needle),
            "{}",
            text(&output)
        );
        assert!(!out.exists());
    }
}

// ---- the committed minimal repros (adapters/fixtures/) ----

/// One fixture of adapters/fixtures/fixtures.json: a hunt's minimal scene, the ids PNG the
/// renderer drew for it, and the finding it shows.
struct Fixture {
    renderer: String,
    scene: PathBuf,
    /// None for a renderer failure (the signature names its kind: `non-zero exit`, ...).
    theirs: Option<PathBuf>,
    model: rasterproof::model::Model,
    signature: String,
}

fn fixtures() -> Vec<Fixture> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/fixtures");
    let manifest: Value =
        serde_json::from_str(&std::fs::read_to_string(root.join("fixtures.json")).unwrap()).expect("fixtures.json");
    manifest["fixtures"]
        .as_array()
        .expect("fixtures")
        .iter()
        .map(|f| {
            let field = |name: &str| f[name].as_str().unwrap_or_else(|| panic!("{name} in {f}")).to_string();
            Fixture {
                renderer: field("renderer"),
                scene: root.join(field("scene")),
                theirs: f["theirs"].as_str().map(|t| root.join(t)),
                model: rasterproof::model::Model::from_name(&field("model")).expect("a model"),
                signature: field("signature"),
            }
        })
        .collect()
}

/// The signatures (`tie, triangles`, ...) `theirs` shows against the oracle.
fn signatures_of(scene: &Path, theirs: &Path, model: rasterproof::model::Model) -> Vec<String> {
    use rasterproof::oracle::hunt::{judge, signatures};
    use rasterproof::oracle::{Background, Format, Theirs};
    let s = parse_scene(&std::fs::read_to_string(scene).unwrap(), "fixture").expect("a valid scene");
    let bytes = std::fs::read(theirs).unwrap();
    let t = Theirs::read(
        &bytes,
        &theirs.display().to_string(),
        Format::Ids,
        Background::default(),
    )
    .expect("an ids PNG");
    signatures(&judge(&s, Ok(t), model))
        .iter()
        .map(|s| s.describe())
        .collect()
}

/// The decoded RGBA pixels of a PNG.
fn rgba(path: &Path) -> Vec<u8> {
    image::open(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .to_rgba8()
        .into_raw()
}

/// The same hunt once per scene (`--cmd`) and kept alive (`--serve`) finds the same
/// signatures in the same cases: the protocol changes how scenes reach the renderer,
/// nothing else.
#[test]
fn once_per_scene_and_kept_alive_hunts_agree() {
    let adapter = tiny_skia_adapter();
    let args = [
        "--preset",
        "gl",
        "--subpixel-bits",
        "6",
        "--rounding",
        "towards-zero",
        "--cases",
        "40",
        "--shrink-runs",
        "10",
    ];
    let per_scene = short_hunt("--cmd", &format!("{} {{scene}} {{out}}", adapter.display()), &args);
    let kept = short_hunt("--serve", &format!("{} --serve", adapter.display()), &args);
    assert_eq!(per_scene.0, kept.0);
    assert_eq!(per_scene.1, kept.1);
    assert_eq!(per_scene.2 .0, per_scene.2 .1, "once per scene: a start per scene");
    assert!(kept.2 .1 < per_scene.2 .1 / 4, "{:?} against {:?}", kept.2, per_scene.2);
}

/// Every fixture drawn through the stay-alive protocol (one program per renderer for all
/// its fixtures) is the committed PNG, and tiny-skia's failure fixture is a non-zero exit
/// there too (its panic ends the program without an answer).
#[test]
fn the_fixtures_draw_the_same_through_the_protocol() {
    use rasterproof::oracle::renderer::program::FailureKind;
    use rasterproof::oracle::renderer::stay_alive::StayAlive;
    use rasterproof::oracle::{Background, Format, Theirs};
    let serve = |cmd: String| {
        StayAlive::new(
            &cmd,
            Format::Ids,
            Background::default(),
            std::time::Duration::from_secs(60),
        )
        .unwrap()
    };
    let tiny = serve(format!("{} --serve", tiny_skia_adapter().display()));
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("adapters/osmesa/render.py");
    let mesa = |driver: &str| serve(format!("{} {} --serve --driver {driver}", python(), script.display()));
    let (llvmpipe, softpipe) = if osmesa_available() {
        (Some(mesa("llvmpipe")), Some(mesa("softpipe")))
    } else {
        (None, None)
    };
    for f in fixtures() {
        let renderer = match f.renderer.as_str() {
            "tiny-skia" => &tiny,
            "llvmpipe" => match &llvmpipe {
                Some(r) => r,
                None => continue,
            },
            _ => match &softpipe {
                Some(r) => r,
                None => continue,
            },
        };
        let scene = parse_scene_with(&std::fs::read(&f.scene).unwrap(), "fixture", &ParseOptions::default()).unwrap();
        let got = renderer.render(&scene);
        match &f.theirs {
            None => {
                let failure = got.expect_err("the failure fixture still fails");
                assert_eq!(failure.kind, FailureKind::Exit, "{failure}");
                assert!(failure.message.contains("101"), "{failure}");
            }
            Some(png) => {
                let want =
                    Theirs::read(&std::fs::read(png).unwrap(), "png", Format::Ids, Background::default()).unwrap();
                assert_eq!(got.unwrap(), want, "{}: {}", f.renderer, f.scene.display());
            }
        }
    }
    assert!(tiny.starts() <= 2, "{} starts", tiny.starts());
}

#[test]
fn every_fixture_shows_its_finding() {
    let all = fixtures();
    assert!(all.len() >= 3, "fixtures.json lists {} fixtures", all.len());
    for f in &all {
        let Some(theirs) = &f.theirs else {
            continue; // a failure: the_renderers_still_draw_the_fixtures_so runs it
        };
        let found = signatures_of(&f.scene, theirs, f.model);
        assert!(
            found.contains(&f.signature),
            "{}: {} shows {found:?}, not {:?}",
            f.renderer,
            f.scene.display(),
            f.signature
        );
    }
}

#[test]
fn the_renderers_still_draw_the_fixtures_so() {
    let tiny = tiny_skia_adapter();
    let osmesa_here = osmesa_available();
    let dir = tempdir::Dir::new("adapters-fixtures");
    for (k, f) in fixtures().iter().enumerate() {
        let out = dir.path().join(format!("{k}.png"));
        if f.theirs.is_none() {
            // A failure fixture: the renderer must still fail on the scene (tiny-skia
            // panics: exit status 101).
            assert_eq!(f.renderer, "tiny-skia", "only tiny-skia has failure fixtures");
            assert_eq!(f.signature, "non-zero exit");
            let output = Command::new(&tiny).arg(&f.scene).arg(&out).output().unwrap();
            assert_eq!(output.status.code(), Some(101), "{}", text(&output));
            assert!(
                String::from_utf8_lossy(&output.stderr).contains("panicked"),
                "{}",
                text(&output)
            );
            assert!(!out.exists());
            continue;
        }
        match f.renderer.as_str() {
            "tiny-skia" => tiny_skia(&tiny, &f.scene, &out),
            driver @ ("llvmpipe" | "softpipe") if osmesa_here => osmesa(driver, &f.scene, &out),
            "llvmpipe" | "softpipe" => continue,
            other => panic!("fixtures.json: unknown renderer {other:?}"),
        }
        let theirs = f.theirs.as_ref().expect("not a failure");
        assert!(
            rgba(&out) == rgba(theirs),
            "{} draws {} differently from {}",
            f.renderer,
            f.scene.display(),
            theirs.display()
        );
    }
}

/// `rasterproof hunt` against `cmd` (`how`: `--cmd` once per scene, or `--serve` kept
/// alive) with a fixed seed: the signatures it found (from its summary table), its first
/// line and its `renderer:` line (scenes asked for, program starts).
fn short_hunt(how: &str, cmd: &str, args: &[&str]) -> (Vec<String>, String, (u64, u64)) {
    let output = assert_cmd::Command::cargo_bin("rasterproof")
        .unwrap()
        .args([
            "hunt",
            how,
            cmd,
            "--float32-exact",
            "--seed",
            "2026",
            "--jobs",
            "2",
            "--quiet",
        ])
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let code = output.status.code();
    assert!(code == Some(0) || code == Some(1), "hunt {args:?}:\n{}", text(&output));
    let stdout = String::from_utf8_lossy(&output.stdout).to_string();
    let found = stdout
        .lines()
        .filter(|l| l.len() > 4 && l.as_bytes()[..2].iter().all(u8::is_ascii_digit) && l.as_bytes()[2] == b' ')
        .map(|l| l[4..].split("  ").next().unwrap().trim().to_string())
        .collect();
    let runs = stdout
        .lines()
        .find_map(|l| l.strip_prefix("renderer: "))
        .map(|l| {
            let n: Vec<u64> = l.split(' ').filter_map(|w| w.parse().ok()).collect();
            (n[0], n[1])
        })
        .expect("a renderer: line");
    (found, stdout.lines().next().unwrap_or("").to_string(), runs)
}

/// The reason class of a signature (`tie, triangles` -> `tie`).
fn class_of(signature: &str) -> &str {
    signature.split(", ").next().unwrap_or(signature)
}

#[test]
fn short_hunts_find_only_the_classes_of_the_fixtures() {
    let all = fixtures();
    let mut hunts = vec![(
        "tiny-skia",
        format!("{} --serve", tiny_skia_adapter().display()),
        vec![
            "--preset",
            "gl",
            "--subpixel-bits",
            "6",
            "--rounding",
            "towards-zero",
            "--cases",
            "48",
            "--shrink-runs",
            "20",
        ],
    )];
    if osmesa_available() {
        let script = format!("{} adapters/osmesa/render.py --serve --driver", python());
        hunts.push((
            "llvmpipe",
            format!("{script} llvmpipe"),
            vec!["--preset", "gl", "--cases", "16", "--shrink-runs", "10"],
        ));
        hunts.push((
            "softpipe",
            format!("{script} softpipe"),
            vec![
                "--preset",
                "gl",
                "--model",
                "exact",
                "--cases",
                "16",
                "--shrink-runs",
                "10",
            ],
        ));
    }
    for (renderer, cmd, args) in hunts {
        let known: Vec<&str> = all
            .iter()
            .filter(|f| f.renderer == renderer)
            .map(|f| class_of(&f.signature))
            .collect();
        let (found, summary, (calls, starts)) = short_hunt("--serve", &cmd, &args);
        eprintln!("{renderer}: {summary}; {found:?}; {calls} scenes, {starts} program starts");
        // Kept alive: a program per job, and a fresh one after each failure of the
        // renderer (tiny-skia's hairline panic).
        assert!(starts * 4 <= calls, "{renderer}: {starts} starts for {calls} scenes");
        for s in &found {
            assert!(
                known.contains(&class_of(s)),
                "{renderer}: hunt found {s:?}, a class no fixture of it shows ({known:?})"
            );
        }
    }
}
