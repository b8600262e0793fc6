//! Clipping in scenes and on the command line (issue 4): the `clip` window and
//! clip-space triangles in scene files, `render` honouring them in every model, the
//! `clip` command's exact output, bad input.

use crate::common;

use assert_cmd::Command;
use common::config;
use num_rational::BigRational;
use proptest::prelude::*;
use rasterproof::check::differing_pixels;
use rasterproof::clip::cohen_sutherland;
use rasterproof::clip::halfplane::clip_segment_exact;
use rasterproof::clip::mask::ClipMask;
use rasterproof::clip::Window;
use rasterproof::convention::{PixelCentre, Preset, Target};
use rasterproof::coverage::Coverage;
use rasterproof::geom::{FillRule, Point, Polygon};
use rasterproof::model::{render, Model};
use rasterproof::scene::{parse_scene, Scene};
use rasterproof::strategy::clip::{any_window, rect_window};
use rasterproof::strategy::polygon::simple_polygon;
use rasterproof::strategy::{any_triangle, tie_heavy_coordinate};

fn bin() -> Command {
    Command::cargo_bin("rasterproof").unwrap()
}

use crate::tempdir;

/// A scene file in a fresh temporary folder (removed when the folder is dropped).
fn scene_file(tag: &str, text: &str) -> (tempdir::Dir, std::path::PathBuf) {
    let dir = tempdir::Dir::new(&format!("clip-{tag}"));
    let p = dir.path().join("scene.json");
    std::fs::write(&p, text).unwrap();
    (dir, p)
}

const SCENE: &str = r#"{"width": 16, "height": 16,
 "triangles": [{"v": [[2,1],[20,1],[2,10]]}],
 "lines": [{"from": [-3, 4], "to": [20, 6]}],
 "polygons": [{"v": [[0,0],[16,0],[16,16],[0,16]], "holes": [[[4,4],[8,4],[8,8]]]}],
 "clip_space_triangles": [{"v": [[0,0,0,1],[2,0,0,1],[0,1,0,-2]]}],
 "clip": {"rect": [1, 2, 12, "29/2"]}}"#;

/// By hand, window [1, 12] x [2, 29/2]:
/// - the triangle (2,1) (20,1) (2,10): its hypotenuse is x + 2y = 22; the top edge y = 1
///   is above the window, so the window's top y = 2 cuts it from x = 2 to x = 18, then
///   x = 12 cuts the hypotenuse at y = 5: (2,2) (12,2) (12,5) (2,10);
/// - the line (-3,4) -> (20,6), y = 4 + 2 (x + 3) / 23: at x = 1, y = 100/23; at x = 12,
///   y = 122/23;
/// - the square [0,16]^2 becomes the window itself; its hole lies inside and stays;
/// - the clip-space triangle (0,0,0,1) (2,0,0,1) (0,1,0,-2) clips to the NDC square
///   [0,1]^2 (its third vertex is behind the eye; the planes x <= w and y <= w cut it
///   at w > 0); the default viewport of a d3d11 scene maps NDC x to 8 (x + 1) and y to
///   8 (1 - y) (y up), so the square is [8,16] x [0,8], and the window cuts it to
///   [8,12] x [2,8].
#[test]
fn clip_command_output_by_hand() {
    let (dir, p) = scene_file("golden", SCENE);
    let out = bin().args(["clip", p.to_str().unwrap()]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    let expected = concat!(
        r#"{"triangles":[[["2","2"],["12","2"],["12","5"],["2","10"]]],"#,
        r#""lines":[[["1","100/23"],["12","122/23"]]],"#,
        r#""polygons":[[[["1","29/2"],["1","2"],["12","2"],["12","29/2"]],[["4","4"],["8","4"],["8","8"]]]],"#,
        r#""clip_space_triangles":[[["12","2"],["8","2"],["8","8"],["12","8"]]]}"#,
        "\n"
    );
    assert_eq!(text, expected);
    // The float models clip the same geometry; the line's ends are the nearest floats.
    let out = bin()
        .args(["clip", p.to_str().unwrap(), "--model", "float32"])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with(r#"{"triangles":[[["2","2"],["12","2"],["12","5"],["2","10"]]],"lines":[[["1","#));
    assert!(!text.contains("100/23"), "f32 cannot hold 100/23: {text}");
    // The after-divide path refuses the vertex behind the eye.
    let out = bin()
        .args(["clip", p.to_str().unwrap(), "--divide-first"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("clip_space_triangles[0]: vertex 2 has w = -2"), "{err}");
    drop(dir);
}

/// A primitive clipped away entirely is an empty list.
#[test]
fn clipped_away_is_an_empty_list() {
    let (dir, p) = scene_file(
        "empty",
        r#"{"width": 8, "height": 8, "triangles": [{"v": [[20,20],[30,20],[20,30]]}],
            "lines": [{"from": [-5, -5], "to": [-1, -3]}], "polygons": [{"v": [[9,9],[12,9],[9,12]]}],
            "clip": {"convex": [[0,0],[8,0],[0,8]]}}"#,
    );
    bin()
        .args(["clip", p.to_str().unwrap()])
        .assert()
        .success()
        .stdout("{\"triangles\":[[]],\"lines\":[[]],\"polygons\":[[]],\"clip_space_triangles\":[]}\n");
    drop(dir);
}

/// The window `[5/2, 21/2]^2` (its sides run through samples: pixel (i, j)'s sample is
/// (i + 1/2, j + 1/2)) and primitives that touch it without entering it.
const TOUCHING: &str = r#"{"width": 16, "height": 16,
 "triangles": [{"v": [["21/2","21/2"],["25/2","21/2"],["21/2","25/2"]]},
               {"v": [["21/2","5/2"],["29/2","13/2"],["21/2","21/2"]]},
               {"v": [[9,9],[12,9],[9,12]]}],
 "lines": [{"from": ["25/2","17/2"], "to": ["17/2","25/2"], "rule": "diamond"}],
 "polygons": [{"v": [["21/2",4],[14,4],[14,8],["21/2",8]]}],
 "clip": {"rect": ["5/2", "5/2", "21/2", "21/2"]}}"#;

/// An area primitive left with no area is `[]`; a line left with one point keeps it. By
/// hand, window [5/2, 21/2]^2:
/// - triangle 0 meets it only at its corner (21/2, 21/2): a point, no area: `[]`;
/// - triangle 1 meets it only along x = 21/2 from y = 5/2 to 21/2: a segment: `[]`;
/// - triangle 2 (9,9) (12,9) (9,12), hypotenuse x + y = 21, keeps the square [9, 21/2]^2
///   (the hypotenuse meets x = 21/2 at y = 21/2, the window's corner). Sutherland-Hodgman
///   takes the sides top, right, bottom, left: the right side x <= 21/2 gives
///   (9,9) (21/2,9) (21/2,21/2) (9,12); the bottom side y <= 21/2 enters at (9, 21/2)
///   on the way from (9,12) to (9,9), then keeps (9,9) (21/2,9) (21/2,21/2), and leaves at
///   (21/2,21/2) itself (merged): (9,21/2) (9,9) (21/2,9) (21/2,21/2);
/// - the line x + y = 21 from (25/2, 17/2) to (17/2, 25/2) has one point in the closed
///   window, the corner (21/2, 21/2): a segment of length zero, both ends there;
/// - the polygon [21/2, 14] x [4, 8] shares only part of the window's right side: `[]`.
#[test]
fn touching_the_window_at_a_corner_or_along_an_edge() {
    let (dir, p) = scene_file("touching", TOUCHING);
    let out = bin().args(["clip", p.to_str().unwrap()]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(
        String::from_utf8(out.stdout).unwrap(),
        concat!(
            r#"{"triangles":[[],[],[["9","21/2"],["9","9"],["21/2","9"],["21/2","21/2"]]],"#,
            r#""lines":[[["21/2","21/2"],["21/2","21/2"]]],"#,
            r#""polygons":[[]],"clip_space_triangles":[]}"#,
            "\n"
        )
    );
    // The float clippers read the same halves exactly and agree on what covers nothing.
    for model in ["float32", "float64"] {
        let out = bin()
            .args(["clip", p.to_str().unwrap(), "--model", model])
            .output()
            .unwrap();
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(text.starts_with(r#"{"triangles":[[],[],[["#), "{model}: {text}");
        assert!(
            text.ends_with("\"polygons\":[[]],\"clip_space_triangles\":[]}\n"),
            "{model}: {text}"
        );
    }
    let out = bin()
        .args(["clip", p.to_str().unwrap(), "--format", "text"])
        .output()
        .unwrap();
    assert!(String::from_utf8(out.stdout)
        .unwrap()
        .contains("1/3 triangles, 1/1 lines, 0/1 polygons, 0/0 clip-space triangles keep something"));
    drop(dir);
}

/// Why `[]` is right for the corner triangle: raster(clip(P, W)) = raster(P) ∩ raster(W).
/// Alone, triangle 0 (21/2,21/2) (25/2,21/2) (21/2,25/2) covers, under top-left, the
/// samples on its top and left edges: (21/2, 21/2) (its top-left vertex), (23/2, 21/2)
/// and (21/2, 23/2); (23/2, 23/2) lies on the hypotenuse, a bottom-right edge: 3 pixels.
/// The window's sample (21/2, 21/2) is on its right and bottom sides, so raster(W) does
/// not hold it: with the window, nothing; the same for triangle 1 on the right side.
#[test]
fn a_primitive_touching_the_window_covers_nothing() {
    let mut scene = parse_scene(TOUCHING, "s.json").unwrap();
    scene.triangles.truncate(2);
    scene.lines.clear();
    scene.polygons.clear();
    let target = scene.target().unwrap();
    let alone = Scene {
        triangles: scene.triangles[..1].to_vec(),
        clip: None,
        ..scene.clone()
    };
    assert_eq!(
        render(&alone.primitives(), &target, Model::Exact)
            .unwrap()
            .covered_pixels(),
        3
    );
    for model in [Model::Exact, Model::ExactSnapped, Model::Fixed, Model::Scanline] {
        assert_eq!(
            render(&scene.primitives(), &target, model).unwrap().covered_pixels(),
            0,
            "{model}"
        );
    }
}

/// `render` honours `clip` in every exact and integer model alike (the exact models clip
/// the geometry, the integer ones mask with raster(W)); by hand for the triangle: the
/// clipped polygon (2,2) (12,2) (12,5) (2,10) covers, row by row at y = j + 1/2, the
/// samples 2.5 <= x + 1/2 < min(12, 22 - 2y): rows 2..=4 columns 2..=11 (10 each), row 5
/// (y = 5.5: x < 11) columns 2..=10, row 6 (x < 9) 2..=8, row 7 (x < 7) 2..=6, row 8
/// (x < 5) 2..=4, row 9 (x < 3) column 2: 30 + 9 + 7 + 5 + 3 + 1 = 55 pixels.
#[test]
fn render_honours_clip() {
    let mut scene = parse_scene(SCENE, "s.json").unwrap();
    scene.lines.clear();
    scene.polygons.clear();
    scene.clip_space_triangles.clear();
    let target = scene.target().unwrap();
    let exact = render(&scene.primitives(), &target, Model::Exact).unwrap();
    assert_eq!(exact.covered_pixels(), 55);
    for model in [
        Model::ExactPlain,
        Model::ExactSnapped,
        Model::ExactSnappedPlain,
        Model::Fixed,
        Model::Scanline,
        Model::Float32,
        Model::Float64,
    ] {
        assert_eq!(
            differing_pixels(&exact, &render(&scene.primitives(), &target, model).unwrap()),
            vec![],
            "{model}"
        );
    }
}

#[test]
fn bad_clip_input_exits_2() {
    let cases = [
        (
            r#""clip": {"rect": [3, 0, 3, 4]}"#,
            "clip.rect: empty window: xmin 3 >= xmax 3",
        ),
        (
            r#""clip": {"rect": [0, 5, 4, 4]}"#,
            "clip.rect: empty window: ymin 5 >= ymax 4",
        ),
        (
            r#""clip": {"rect": [0, 0, 4]}"#,
            "clip.rect: expected [xmin, ymin, xmax, ymax], found 3 values",
        ),
        (
            r#""clip": {"rect": [0, 0, "NaN", 4]}"#,
            "clip.rect[2]: \"NaN\" is not a finite number",
        ),
        (
            r#""clip": {"convex": [[0,0],[4,0],[2,1],[4,4],[0,4]]}"#,
            "clip.convex: not a strictly convex polygon",
        ),
        (
            r#""clip": {"convex": [[0,0],[2,0],[4,0]]}"#,
            "clip.convex: not a strictly convex polygon",
        ),
        (
            r#""clip": {"convex": [[0,0],[2,0]]}"#,
            "clip.convex: a convex window needs at least 3 vertices, found 2",
        ),
        (
            r#""clip": {"rect": [0, 0, 4, 4], "convex": [[0,0],[4,0],[0,4]]}"#,
            "clip: expected exactly one of",
        ),
        (r#""clip": {"circle": 3}"#, "clip.circle: unknown field"),
        (
            r#""clip_space_triangles": [{"v": [[0,0,0],[1,0,0,1],[0,1,0,1]]}]"#,
            "clip_space_triangles[0].v[0]: a clip-space vertex is [x, y, z, w], found 3 values",
        ),
        (
            r#""clip_space_triangles": [{"v": [[0,0,0,"inf"],[1,0,0,1],[0,1,0,1]]}]"#,
            "clip_space_triangles[0].v[0][3]: \"inf\" is not a finite number",
        ),
        (r#""viewport": {"width": 0}"#, "viewport.width: 0 is not positive"),
        (
            r#""viewport": {"ndc_y": "sideways"}"#,
            "viewport.ndc_y: unknown \"sideways\"",
        ),
    ];
    for (k, (field, needle)) in cases.iter().enumerate() {
        let (dir, p) = scene_file(&format!("bad{k}"), &format!(r#"{{"width": 8, "height": 8, {field}}}"#));
        for command in ["render", "clip"] {
            let out = bin().args([command, p.to_str().unwrap()]).output().unwrap();
            let err = String::from_utf8(out.stderr).unwrap();
            assert_eq!(out.status.code(), Some(2), "case {k} {command}: {err}");
            assert!(err.contains(needle), "case {k} {command}: {err:?} lacks {needle:?}");
            assert!(err.contains("scene.json"), "case {k}: the file is not named: {err}");
            assert!(!err.contains("panicked"));
        }
        drop(dir);
    }
    let (dir, p) = scene_file("badmodel", r#"{"width": 8, "height": 8}"#);
    let out = bin()
        .args(["clip", p.to_str().unwrap(), "--model", "fixed"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8(out.stderr)
        .unwrap()
        .contains("--model: unknown model \"fixed\" for clip"));
    drop(dir);
}

/// Review findings: the exact `clip` takes windows no float can hold; float errors name
/// the primitive; f32 values are rounded once, straight from the rational (1 + 2^-24 +
/// 2^-80 is just above the halfway point between the f32 neighbours 1 and 1 + 2^-23,
/// so it rounds up to 1 + 2^-23 = 8388609/8388608; through f64 it would first become
/// 1 + 2^-24, a tie, and then round to even: 1); a clip-space vertex outside the integer
/// envelope names the window-space vertex and keeps the message short.
#[test]
fn clip_conversions_and_messages() {
    let huge = format!("1{}", "0".repeat(400));
    let run = |tag: &str, text: String, args: &[&str]| {
        let (dir, p) = scene_file(tag, &text);
        let out = bin()
            .arg(args[0])
            .arg(p.to_str().unwrap())
            .args(&args[1..])
            .output()
            .unwrap();
        drop(dir);
        (
            out.status.code(),
            String::from_utf8(out.stdout).unwrap(),
            String::from_utf8(out.stderr).unwrap(),
        )
    };
    let (code, _, err) = run(
        "hugewin",
        format!(
            r#"{{"width": 8, "height": 8, "triangles": [{{"v": [[0,0],[4,0],[0,4]]}}], "clip": {{"rect": [0, 0, "{huge}", 8]}}}}"#
        ),
        &["clip"],
    );
    assert_eq!(code, Some(0), "{err}");
    let (code, _, err) = run(
        "f32big",
        r#"{"width": 8, "height": 8, "triangles": [{"v": [[0,0],["1e39",0],[0,8]]}], "clip": {"rect": [0, 0, 8, 8]}}"#
            .into(),
        &["clip", "--model", "float32"],
    );
    assert_eq!(code, Some(2));
    assert!(err.contains("triangles[0]: a coordinate does not fit f32"), "{err}");
    // 1 + 2^-24 + 2^-80 as a fraction
    let den = num_bigint::BigInt::from(1) << 80;
    let num = &den + (num_bigint::BigInt::from(1) << 56) + 1;
    let (code, out, err) = run(
        "f32once",
        format!(
            r#"{{"width": 8, "height": 8, "triangles": [{{"v": [["{num}/{den}",0],[4,0],[0,4]]}}], "clip": {{"rect": [-8, -8, 8, 8]}}}}"#
        ),
        &["clip", "--model", "float32"],
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(out.starts_with(r#"{"triangles":[[["8388609/8388608","0"]"#), "{out}");
    let (code, _, err) = run(
        "envelope",
        format!(
            r#"{{"width": 8, "height": 8, "clip_space_triangles": [{{"v": [[0,0,0,1],[1,0,0,1],[0,1,0,1]]}}], "viewport": {{"x": "{huge}"}}}}"#
        ),
        &["render", "--model", "fixed"],
    );
    assert_eq!(code, Some(2));
    assert!(err.contains("clip_space_triangles[0]: window-space vertex 0"), "{err}");
    assert!(err.contains("characters)") && err.len() < 400, "{err}");
}

#[test]
fn clip_fields_round_trip() {
    let text = r#"{"width": 9, "height": 7, "preset": "vulkan",
        "clip_space_triangles": [{"v": [["1/3",0,0,1],[1,0,"0.5",1],[0,1,0,2]]}],
        "viewport": {"x": 1, "y": "1/2", "width": 6, "height": 5, "depth": "minus-one-to-one"},
        "clip": {"convex": [[0,0],["9/2",0],[0,7]]}}"#;
    let s = parse_scene(text, "s").unwrap();
    assert_eq!(s.viewport().y_axis, rasterproof::clip::homogeneous::NdcY::Down); // vulkan's default
    assert_eq!(parse_scene(&s.to_json(), "again").unwrap(), s);
    let r = parse_scene(r#"{"width": 4, "height": 4, "clip": {"rect": [0, "0.5", 3, 4]}}"#, "r").unwrap();
    assert_eq!(parse_scene(&r.to_json(), "again").unwrap(), r);
}

fn tie_point() -> impl Strategy<Value = Point> {
    (tie_heavy_coordinate(16), tie_heavy_coordinate(16)).prop_map(|(x, y)| Point::new(x, y))
}

proptest! {
    #![proptest_config(config("proptest-regressions/clip_scene.txt"))]

    /// Clipping the geometry (exact models) and masking the coverage with raster(W)
    /// (integer models) give the same pixels, for triangles and simple polygons, any
    /// window, presets and samples.
    #[test]
    fn every_model_clips_alike(
        tris in prop::collection::vec(any_triangle(16), 1..4),
        poly in simple_polygon(16, 8),
        window in any_window(16),
        preset in prop::sample::select(Preset::ALL.to_vec()),
        corner in any::<bool>(),
    ) {
        let mut scene = Scene::new(16, 16, tris);
        scene.preset = preset;
        if corner {
            scene.overrides.pixel_centre = Some(PixelCentre::Corner);
        }
        scene.polygons.push(Polygon { fill_rule: FillRule::NonZero, ..poly });
        scene.clip = Some(window);
        let target = scene.target().unwrap();
        let Ok(fixed) = render(&scene.primitives(), &target, Model::Fixed) else {
            return Err(TestCaseError::reject("outside the envelope or not triangulable"));
        };
        let exact = render(&scene.primitives(), &target, Model::ExactSnappedPlain).unwrap();
        prop_assert_eq!(differing_pixels(&exact, &fixed), vec![]);
        prop_assert_eq!(differing_pixels(&exact, &render(&scene.primitives(), &target, Model::ExactSnapped).unwrap()), vec![]);
        prop_assert_eq!(differing_pixels(&exact, &render(&scene.primitives(), &target, Model::Scanline).unwrap()), vec![]);
    }

    /// Cyrus-Beck on a rectangle's half-planes keeps exactly what Cohen-Sutherland keeps.
    #[test]
    fn cyrus_beck_equals_cohen_sutherland(a in tie_point(), b in tie_point(), w in rect_window(16)) {
        let Window::Rect(r) = &w else { unreachable!() };
        prop_assert_eq!(clip_segment_exact(&a, &b, &w.half_planes()), cohen_sutherland::clip_exact(&a, &b, r));
    }

    /// The masks: raster(W) equals the oracle's fill of the window; the point mask holds
    /// the pixels whose sample is in the closed window.
    #[test]
    fn masks_are_exact(w in any_window(16), preset in prop::sample::select(Preset::ALL.to_vec()), corner in any::<bool>()) {
        let mut conv = preset.convention();
        if corner {
            conv.pixel_centre = PixelCentre::Corner;
        }
        let target = Target::new(16, 16, conv).unwrap();
        let mut filled = Coverage::new(16, 16);
        rasterproof::fill::polygon::rasterize_exact(&Polygon::new(w.outline(), FillRule::NonZero), 0, &target, &mut filled);
        let (areas, points) = (ClipMask::for_areas(&w, &target), ClipMask::for_points(&w, &target));
        let c = conv.pixel_centre.offset();
        for y in 0..16u32 {
            for x in 0..16u32 {
                prop_assert_eq!(areas.contains(x, y), !filled.owners(x, y).is_empty(), "area mask at ({}, {})", x, y);
                let sample = Point::new(BigRational::from_integer(x.into()) + &c, BigRational::from_integer(y.into()) + &c);
                prop_assert_eq!(points.contains(x, y), w.contains(&sample), "point mask at ({}, {})", x, y);
            }
        }
    }
}
