//! Exact values at covered samples: the scene's varyings, `model::exact_values` against an
//! independent rational computation (window-space barycentrics from edge functions; for
//! clip-space triangles, clipping first, then the divide and the window polygon's fan),
//! the scene fields' errors and `render --format json`.

use assert_cmd::Command;
use num_rational::BigRational;
use num_traits::One;
use proptest::prelude::*;
use proptest::test_runner::Config;
use rasterproof::clip::homogeneous::{clip_to_window_exact, interpolate_exact, ClipVertex, WindowVertex};
use rasterproof::coverage::samples::SampleCoverage;
use rasterproof::geom::{Point, Triangle};
use rasterproof::interp::barycentric_exact;
use rasterproof::interp::values::{Interpolation, NoValue, Sampling, Varyings};
use rasterproof::model::{exact_values, render_samples, Model, SampleValues};
use rasterproof::pattern::SamplePattern;
use rasterproof::scene::{parse_scene, Scene};

use crate::common::config;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// An exact coordinate `n/d` in `[lo, hi)`, `d` one of 1, 3, 10 and 256 (whole numbers,
/// thirds, decimals, the 1/256 grid), as a scene file writes it.
fn coordinate(lo: i64, hi: i64) -> impl Strategy<Value = String> {
    (prop::sample::select(vec![1i64, 3, 10, 256]), lo..hi, 0i64..256)
        .prop_map(|(d, whole, frac)| format!("\"{}/{d}\"", whole * d + frac % d))
}

fn interpolation() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec!["smooth", "noperspective", "flat"])
}

fn sampling() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec!["centre", "centroid", "sample"])
}

/// The `varyings` declaration: `a` of 2 channels and `b` of 1, each with its
/// interpolation and sampling point.
fn declaration() -> impl Strategy<Value = String> {
    (
        interpolation(),
        sampling(),
        interpolation(),
        sampling(),
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(|(ia, sa, ib, sb, last, four)| {
            format!(
                r#""varyings": [{{"name": "a", "channels": 2, "interpolation": "{ia}", "sampling": "{sa}"}},
                   {{"name": "b", "channels": 1, "interpolation": "{ib}", "sampling": "{sb}"}}],
                   "provoking_vertex": "{}"{}"#,
                if last { "last" } else { "first" },
                if four { r#", "samples": 4"# } else { "" }
            )
        })
}

/// A vertex's values of `a` and `b`.
fn vertex_values() -> impl Strategy<Value = [String; 3]> {
    [coordinate(-50, 50), coordinate(-50, 50), coordinate(-50, 50)]
}

fn values_field(v: &[[String; 3]; 3]) -> String {
    format!(
        r#""varyings": {{"a": [[{}, {}], [{}, {}], [{}, {}]], "b": [[{}], [{}], [{}]]}}"#,
        v[0][0], v[0][1], v[1][0], v[1][1], v[2][0], v[2][1], v[0][2], v[1][2], v[2][2]
    )
}

/// A window-space triangle with values, and `w` or not.
fn window_triangle() -> impl Strategy<Value = String> {
    let w = prop::sample::select(vec!["1", "2", "\"1/3\"", "\"5/2\"", "0.7"]);
    (
        [
            coordinate(-2, 10),
            coordinate(-2, 10),
            coordinate(-2, 10),
            coordinate(-2, 10),
            coordinate(-2, 10),
            coordinate(-2, 10),
        ],
        [vertex_values(), vertex_values(), vertex_values()],
        prop::option::of([w.clone(), w.clone(), w]),
    )
        .prop_map(|(c, values, w)| {
            let w = w.map_or(String::new(), |w| format!(r#", "w": [{}, {}, {}]"#, w[0], w[1], w[2]));
            format!(
                r#"{{"v": [[{}, {}], [{}, {}], [{}, {}]]{w}, {}}}"#,
                c[0],
                c[1],
                c[2],
                c[3],
                c[4],
                c[5],
                values_field(&values)
            )
        })
}

/// A clip-space triangle with values: `w` from -1 to 3 (some vertices behind the eye),
/// `x` and `y` mostly inside `[-w, w]`.
fn clip_triangle() -> impl Strategy<Value = String> {
    fn vertex() -> impl Strategy<Value = String> {
        (
            coordinate(-3, 3),
            coordinate(-3, 3),
            coordinate(0, 1),
            prop::sample::select(vec!["-1", "\"1/2\"", "1", "2", "3"]),
        )
            .prop_map(|(x, y, z, w)| format!("[{x}, {y}, {z}, {w}]"))
    }
    (
        [vertex(), vertex(), vertex()],
        [vertex_values(), vertex_values(), vertex_values()],
    )
        .prop_map(|(v, values)| format!(r#"{{"v": [{}, {}, {}], {}}}"#, v[0], v[1], v[2], values_field(&values)))
}

/// The scene's coverage (the exact model's, at every sample of its pattern) and the
/// library's values.
fn library_values(scene: &Scene) -> (SampleCoverage, SamplePattern, Vec<SampleValues>) {
    let target = scene.target().unwrap();
    let pattern = scene
        .samples
        .clone()
        .unwrap_or_else(|| SamplePattern::single(&target.convention));
    let coverage = render_samples(&scene.primitives(), &target, &pattern, Model::Exact).unwrap();
    let values = exact_values(&coverage, &pattern, &scene.value_setups(), &scene.varyings, &target);
    (coverage, pattern, values)
}

/// Where varying `k` of `scene` is evaluated for sample `v`, by the rules as the
/// specifications state them (pixel centres at +1/2: the scenes use the d3d11 preset).
fn point_of(scene: &Scene, k: usize, v: &SampleValues, coverage: &SampleCoverage, pattern: &SamplePattern) -> Point {
    let centre = Point::new(q(2 * i64::from(v.x) + 1, 2), q(2 * i64::from(v.y) + 1, 2));
    match scene.varyings.list[k].sampling {
        Sampling::Centre => centre,
        Sampling::Sample => pattern.sample(v.x, v.y, v.sample),
        Sampling::Centroid => {
            let covered: Vec<usize> = (0..pattern.len())
                .filter(|&s| coverage.owners(v.x, v.y, s).contains(&v.id))
                .collect();
            if covered.len() == pattern.len() {
                centre
            } else {
                pattern.sample(v.x, v.y, covered[0])
            }
        }
    }
}

/// Varying `k`'s channels within a vertex's values.
fn channels(varyings: &Varyings, k: usize) -> std::ops::Range<usize> {
    varyings.ranges().nth(k).unwrap().1
}

/// The value of a window-space triangle, independently: barycentrics from edge functions
/// (`interp::barycentric_exact`), then the specification's formulas.
fn window_value(scene: &Scene, id: usize, k: usize, p: &Point) -> Result<Vec<BigRational>, NoValue> {
    let t = &scene.triangles[id];
    let tri = t.triangle.to_triangle();
    let values = t.values.as_ref().unwrap();
    let w = values
        .w
        .clone()
        .unwrap_or_else(|| [BigRational::one(), BigRational::one(), BigRational::one()]);
    let range = channels(&scene.varyings, k);
    let provoking = scene.varyings.provoking.vertex(3);
    let l = barycentric_exact(&tri, p).ok_or(NoValue::Degenerate)?;
    let f = |i: usize, c: usize| values.values[i][c].clone();
    Ok(range
        .map(|c| match scene.varyings.list[k].interpolation {
            Interpolation::Flat => f(provoking, c),
            Interpolation::NoPerspective => (0..3).map(|i| &l[i] * f(i, c)).sum(),
            Interpolation::Smooth => {
                let num: BigRational = (0..3).map(|i| &l[i] * f(i, c) / &w[i]).sum();
                let den: BigRational = (0..3).map(|i| &l[i] / &w[i]).sum();
                num / den
            }
        })
        .collect())
}

/// The first fan triangle of the window polygon with area.
fn first_fan_triangle(poly: &[WindowVertex]) -> Option<[WindowVertex; 3]> {
    (1..poly.len().saturating_sub(1))
        .map(|i| [poly[0].clone(), poly[i].clone(), poly[i + 1].clone()])
        .find(|t| {
            let tri = Triangle::new(t[0].point.clone(), t[1].point.clone(), t[2].point.clone());
            barycentric_exact(&tri, &t[0].point).is_some()
        })
}

/// The value of a clip-space triangle, independently: clipped against the view volume
/// (attributes linear in clip space), divided, mapped, and interpolated over a triangle
/// of the window polygon's fan (every triangle of one plane gives the same projective
/// function, so any with area will do, inside the polygon or not). `smooth` is
/// perspective-correct over that triangle (`clip::homogeneous::interpolate_exact`);
/// `noperspective` clips `f w` instead of `f`, divides by the clipped vertex's `w`
/// (OpenGL 4.6 section 13.7's adjusted `t`) and interpolates linearly in window space.
fn clip_value(scene: &Scene, id: usize, k: usize, p: &Point) -> Result<Vec<BigRational>, NoValue> {
    let t = &scene.clip_space_triangles[id - scene.triangles.len()];
    let range = channels(&scene.varyings, k);
    let viewport = scene.viewport();
    match scene.varyings.list[k].interpolation {
        Interpolation::Flat => Ok(t[scene.varyings.provoking.vertex(3)].attrs[range].to_vec()),
        Interpolation::Smooth => {
            let poly = clip_to_window_exact(t, &viewport);
            let fan = first_fan_triangle(&poly).expect("a covered triangle has area");
            let v = interpolate_exact(&fan, p).ok_or(NoValue::Horizon)?;
            Ok(v.attrs[range].to_vec())
        }
        Interpolation::NoPerspective => {
            let premultiplied: Vec<ClipVertex> = t
                .iter()
                .map(|v| ClipVertex {
                    pos: v.pos.clone(),
                    attrs: v.attrs.iter().map(|a| a * &v.pos[3]).collect(),
                })
                .collect();
            let poly = clip_to_window_exact(&premultiplied, &viewport);
            let fan = first_fan_triangle(&poly).expect("a covered triangle has area");
            let tri = Triangle::new(fan[0].point.clone(), fan[1].point.clone(), fan[2].point.clone());
            let l = barycentric_exact(&tri, p).unwrap();
            Ok(range
                .map(|c| (0..3).map(|i| &l[i] * &fan[i].attrs[c] * &fan[i].inv_w).sum())
                .collect())
        }
    }
}

/// Every covered sample's library values equal the independent ones.
fn agree(scene: &Scene) -> Result<usize, TestCaseError> {
    let (coverage, pattern, values) = library_values(scene);
    // Every covered sample once, showing the last drawn of its owners.
    let covered: usize = coverage
        .covered_pixels()
        .iter()
        .map(|&(x, y)| {
            (0..pattern.len())
                .filter(|&s| !coverage.owners(x, y, s).is_empty())
                .count()
        })
        .sum();
    prop_assert_eq!(values.len(), covered);
    for v in &values {
        prop_assert_eq!(Some(&v.id), coverage.owners(v.x, v.y, v.sample).iter().max());
        for k in 0..scene.varyings.list.len() {
            let p = point_of(scene, k, v, &coverage, &pattern);
            let id = v.id as usize;
            let want = if id < scene.triangles.len() {
                window_value(scene, id, k, &p)
            } else {
                clip_value(scene, id, k, &p)
            };
            prop_assert_eq!(
                &v.values[k],
                &want,
                "pixel ({}, {}) sample {} varying {}",
                v.x,
                v.y,
                v.sample,
                k
            );
        }
    }
    Ok(values.len())
}

/// The 8x8 scene of a `varyings` declaration, window-space and clip-space triangles.
fn scene_of(declaration: &str, triangles: &[String], clip_space: &[String]) -> Scene {
    let text = format!(
        r#"{{"width": 8, "height": 8, {declaration}, "triangles": [{}], "clip_space_triangles": [{}]}}"#,
        triangles.join(", "),
        clip_space.join(", ")
    );
    parse_scene(&text, "values.json").unwrap()
}

proptest! {
    #![proptest_config(Config { cases: 96, ..config("proptest-regressions/values.txt") })]

    /// Window-space triangles (with and without `w`) with thirds, decimals and 1/256
    /// coordinates and values: smooth, noperspective and flat values, at the centre, the
    /// centroid and each sample, with one sample and the standard 4.
    #[test]
    fn window_values_equal_an_independent_rational_computation(
        declaration in declaration(),
        triangles in prop::collection::vec(window_triangle(), 1..4),
    ) {
        agree(&scene_of(&declaration, &triangles, &[]))?;
    }

    /// Clip-space triangles, some vertices behind the eye: the values seen through the
    /// homogeneous barycentrics, unclipped, equal those of the clipped and divided polygon.
    #[test]
    fn clip_space_values_equal_the_clipped_polygons(
        declaration in declaration(),
        triangles in prop::collection::vec(clip_triangle(), 1..3),
    ) {
        agree(&scene_of(&declaration, &[], &triangles))?;
    }

    /// A scene with varyings written by `Scene::to_json` reads back as the same scene.
    #[test]
    fn scenes_with_values_read_back(
        declaration in declaration(),
        triangles in prop::collection::vec(window_triangle(), 1..3),
        clip in prop::collection::vec(clip_triangle(), 0..2),
    ) {
        let scene = scene_of(&declaration, &triangles, &clip);
        prop_assert_eq!(parse_scene(&scene.to_json(), "again.json").unwrap(), scene);
    }
}

/// The independent computation has teeth: the clip-space test's scenes do cover samples,
/// and with a vertex behind the eye.
#[test]
fn the_clip_space_family_covers_samples_behind_the_eye() {
    let text = r#"{"width": 8, "height": 8,
        "varyings": [{"name": "a", "channels": 2}, {"name": "b", "channels": 1, "interpolation": "noperspective"}],
        "clip_space_triangles": [{"v": [[-1, -1, 0, 1], [1, -1, 0, 1], [0, 2, "1/2", -1]],
            "varyings": {"a": [[0, 1], [8, 1], [16, 1]], "b": [[0], [8], [16]]}}]}"#;
    let scene = parse_scene(text, "behind.json").unwrap();
    let covered = agree(&scene).unwrap();
    assert!(covered > 8, "{covered}");
}

/// `rasterproof render PATH` with `args`: its exit status and outputs.
fn render(path: &std::path::Path, args: &[&str]) -> std::process::Output {
    Command::cargo_bin("rasterproof")
        .unwrap()
        .args(["render", path.to_str().unwrap()])
        .args(args)
        .output()
        .unwrap()
}

/// `render PATH --model exact --format json`, which must succeed: its JSON.
fn render_json(path: &std::path::Path) -> serde_json::Value {
    let out = render(path, &["--model", "exact", "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

/// By hand: the triangle (0,0) (4,0) (0,4) with w = 1, 3, 1 and the value 0, 1, 0. Pixel
/// (1, 0)'s centre (3/2, 1/2) has barycentrics (1 - 3/8 - 1/8, 3/8, 1/8) = (1/2, 3/8, 1/8):
/// smooth (3/8 / 3) / (1/2 + 3/8 / 3 + 1/8) = (1/8) / (3/4) = 1/6; noperspective 3/8;
/// flat with the last vertex provoking: 0. Pixel (0, 0) has (3/4, 1/8, 1/8): smooth
/// (1/24) / (3/4 + 1/24 + 1/8) = (1/24) / (22/24) = 1/22.
#[test]
fn render_json_gives_the_values_by_hand() {
    let dir = crate::tempdir::Dir::new("values-json");
    let path = dir.path().join("w.json");
    std::fs::write(
        &path,
        r#"{"width": 4, "height": 1,
            "varyings": [{"name": "s", "channels": 1}, {"name": "n", "channels": 1, "interpolation": "noperspective"},
                         {"name": "f", "channels": 1, "interpolation": "flat"}],
            "provoking_vertex": "last",
            "triangles": [{"v": [[0, 0], [4, 0], [0, 4]], "w": [1, 3, 1],
                           "varyings": {"s": [[0], [1], [0]], "n": [[0], [1], [0]], "f": [[7], [8], [0]]}}]}"#,
    )
    .unwrap();
    let json = render_json(&path);
    let values = &json["values"];
    assert_eq!(values["provoking_vertex"], "last");
    assert_eq!(values["varyings"][1]["interpolation"], "noperspective");
    let samples = values["samples"].as_array().unwrap();
    let at = |x: u64| {
        samples
            .iter()
            .find(|s| s[0] == x)
            .unwrap_or_else(|| panic!("pixel {x} in {samples:?}"))
    };
    assert_eq!(at(1)[4], serde_json::json!([["1/6"], ["3/8"], ["0"]]));
    assert_eq!(at(0)[4], serde_json::json!([["1/22"], ["1/8"], ["0"]]));
    assert_eq!(json["pixels"].as_array().unwrap().len(), samples.len());
}

/// Two triangles over one pixel: the pixel shows the last drawn, as a renderer without a
/// depth test writes it.
#[test]
fn the_last_drawn_triangle_is_shown() {
    let text = r#"{"width": 2, "height": 1,
        "varyings": [{"name": "f", "channels": 1, "interpolation": "flat"}],
        "triangles": [{"v": [[0, 0], [4, 0], [0, 4]], "varyings": {"f": [[1], [1], [1]]}},
                      {"v": [[0, 0], ["3/2", 0], [0, "3/2"]], "varyings": {"f": [[2], [2], [2]]}}]}"#;
    let scene = parse_scene(text, "two.json").unwrap();
    let (_, _, values) = library_values(&scene);
    let got: Vec<_> = values.iter().map(|v| (v.x, v.id, v.values[0].clone())).collect();
    // Pixel 0's centre (1/2, 1/2) is inside both triangles (x + y = 1 < 3/2); pixel 1's
    // centre (3/2, 1/2) is inside the first only (x + y = 2: < 4, > 3/2).
    assert_eq!(got, vec![(0, 1, Ok(vec![q(2, 1)])), (1, 0, Ok(vec![q(1, 1)]))]);
}

/// A polygon carries no values: where it is drawn last, a sample has none, and says why.
#[test]
fn a_polygon_drawn_last_has_no_value() {
    let text = r#"{"width": 2, "height": 1,
        "varyings": [{"name": "f", "channels": 1, "interpolation": "flat"}],
        "triangles": [{"v": [[0, 0], [4, 0], [0, 4]], "varyings": {"f": [[1], [1], [1]]}}],
        "polygons": [{"v": [[1, 0], [2, 0], [2, 1], [1, 1]]}]}"#;
    let scene = parse_scene(text, "polygon.json").unwrap();
    let (_, _, values) = library_values(&scene);
    let got: Vec<_> = values.iter().map(|v| (v.x, v.id, v.values[0].clone())).collect();
    assert_eq!(got, vec![(0, 0, Ok(vec![q(1, 1)])), (1, 1, Err(NoValue::NotCarried))]);
    assert_eq!(NoValue::NotCarried.name(), "not-carried");
}

/// Lines interpolate along the segment, by hand. The Bresenham line from pixel 0 to
/// pixel 3 of a 4x1 canvas has its ends at those pixels' centres (1/2, 1/2) and
/// (7/2, 1/2): pixel x's centre has t = x / 3, so `s` (0 to 3) is x; `f` is flat, the
/// last end's 7 (`provoking_vertex: last`). The diamond-exit line from (1/4, 1/2) to
/// (15/4, 1/2) has t = (x + 1/2 - 1/4) / (7/2) = (4x + 1) / 14 at pixel x's centre: `s`
/// (0 to 14) is 4x + 1.
#[test]
fn lines_interpolate_along_the_segment_by_hand() {
    let line = |from: &str, to: &str, rule: &str, last: &str| {
        format!(
            r#"{{"width": 4, "height": 1, "provoking_vertex": "last",
                "varyings": [{{"name": "s", "channels": 1, "interpolation": "noperspective"}},
                             {{"name": "f", "channels": 1, "interpolation": "flat"}}],
                "lines": [{{"from": {from}, "to": {to}, "rule": "{rule}",
                           "varyings": {{"s": [[0], [{last}]], "f": [[5], [7]]}}}}]}}"#
        )
    };
    let scene = parse_scene(&line("[0, 0]", "[3, 0]", "bresenham", "3"), "b.json").unwrap();
    let (_, _, values) = library_values(&scene);
    let got: Vec<_> = values.iter().map(|v| (v.x, v.values.clone())).collect();
    let want: Vec<_> = (0..4)
        .map(|x| (x, vec![Ok(vec![q(i64::from(x), 1)]), Ok(vec![q(7, 1)])]))
        .collect();
    assert_eq!(got, want);
    let scene = parse_scene(
        &line(r#"["1/4", "1/2"]"#, r#"["15/4", "1/2"]"#, "diamond", "14"),
        "d.json",
    )
    .unwrap();
    let (_, _, values) = library_values(&scene);
    assert!(values.len() >= 3, "{values:?}");
    for v in &values {
        assert_eq!(v.values[0], Ok(vec![q(4 * i64::from(v.x) + 1, 1)]), "pixel {}", v.x);
    }
    assert_eq!(parse_scene(&scene.to_json(), "again.json").unwrap(), scene);
}

/// A scene without varyings reads as before, and its JSON has no `values`.
#[test]
fn old_scenes_have_no_values() {
    let scene = parse_scene(
        r#"{"width": 4, "height": 4, "triangles": [{"v": [[0, 0], [4, 0], [0, 4]]}]}"#,
        "old.json",
    )
    .unwrap();
    assert_eq!(scene.varyings, Varyings::default());
    assert!(scene.triangles[0].values.is_none());
    assert!(!scene.to_json().contains("varyings"));
    assert_eq!(scene.value_setups(), vec![None]);
}

/// Bad value fields: exit 2 from the command line, each error naming the field and the value.
#[test]
fn bad_value_fields_name_the_field() {
    let tri = |extra: &str| format!(r#"{{"v": [[0, 0], [4, 0], [0, 4]]{extra}}}"#);
    let decl = r#""varyings": [{"name": "uv", "channels": 2}]"#;
    let good = r#", "varyings": {"uv": [[0, 0], [1, 0], [0, 1]]}"#;
    let cases = [
        (
            format!(
                r#"{decl}, "triangles": [{}]"#,
                tri(r#", "varyings": {"uv": [[0, 0], [1, 0, 5], [0, 1]]}"#)
            ),
            "triangles[0].varyings.uv[1]: expected 2 channels (varyings[0].channels), found 3",
        ),
        (
            format!(
                r#"{decl}, "triangles": [{}]"#,
                tri(r#", "varyings": {"uv": [[0, 0], [1, "inf"], [0, 1]]}"#)
            ),
            "triangles[0].varyings.uv[1][1]: \"inf\"",
        ),
        (
            format!(
                r#"{decl}, "triangles": [{}]"#,
                tri(&format!(r#", "w": [1, 0, 2]{good}"#))
            ),
            "triangles[0].w[1]: 0 is not positive",
        ),
        (
            format!(
                r#"{decl}, "triangles": [{}]"#,
                tri(&format!(r#", "w": [1, "-1/2", 2]{good}"#))
            ),
            "triangles[0].w[1]: \"-1/2\" is not positive",
        ),
        (
            format!(r#"{decl}, "triangles": [{}]"#, tri("")),
            "triangles[0].varyings: missing: the scene declares varyings (uv)",
        ),
        (
            format!(
                r#"{decl}, "triangles": [{}]"#,
                tri(r#", "varyings": {"uv": [[0, 0], [1, 0], [0, 1]], "st": []}"#)
            ),
            "triangles[0].varyings.st: unknown field (expected one of: uv)",
        ),
        (
            format!(
                r#"{decl}, "triangles": [{}]"#,
                tri(r#", "varyings": {"uv": [[0, 0], [1, 0]]}"#)
            ),
            "triangles[0].varyings.uv: expected 3 vertices' values, found 2",
        ),
        (
            format!(r#""triangles": [{}]"#, tri(good)),
            "triangles[0].varyings: the scene declares no varyings",
        ),
        (
            format!(r#""triangles": [{}]"#, tri(r#", "w": [1, 1, 1]"#)),
            "triangles[0].w: w only serves perspective-correct varyings",
        ),
        (
            format!(r#"{decl}, "lines": [{{"from": [0, 0], "to": [3, 1]}}]"#),
            "lines[0].varyings: missing: the scene declares varyings (uv)",
        ),
        (
            format!(
                r#"{decl}, "lines": [{{"from": [0, 0], "to": [3, 1], "varyings": {{"uv": [[0, 0], [1, 0], [0, 1]]}}}}]"#
            ),
            "lines[0].varyings.uv: expected 2 vertices' values, found 3",
        ),
        (
            r#""varyings": [{"name": "uv", "channels": 0}]"#.to_string(),
            "varyings[0].channels: 0 is not in 1..=128",
        ),
        (
            r#""varyings": [{"name": "uv", "channels": 2}, {"name": "uv", "channels": 1}]"#.to_string(),
            "varyings[1].name: \"uv\" is declared twice (also varyings[0])",
        ),
        (
            r#""varyings": [{"name": "uv", "channels": 2, "interpolation": "linear"}]"#.to_string(),
            "varyings[0].interpolation: unknown interpolation \"linear\" (expected smooth, noperspective or flat)",
        ),
        (
            r#""varyings": [{"name": "uv", "channels": 2, "sampling": "center"}]"#.to_string(),
            "varyings[0].sampling: unknown sampling point \"center\" (expected centre, centroid or sample)",
        ),
        (
            r#""provoking_vertex": "middle""#.to_string(),
            "provoking_vertex: unknown rule \"middle\" (expected first or last)",
        ),
        (
            format!(r#"{decl}, "clip_space_triangles": [{{"v": [[0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, 1]]}}]"#),
            "clip_space_triangles[0].varyings: missing",
        ),
    ];
    let dir = crate::tempdir::Dir::new("values-errors");
    for (k, (fields, want)) in cases.iter().enumerate() {
        let path = dir.path().join(format!("bad{k}.json"));
        std::fs::write(&path, format!(r#"{{"width": 4, "height": 4, {fields}}}"#)).unwrap();
        let out = render(&path, &["--format", "json"]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{fields}: {stderr}");
        assert!(
            stderr.contains(&format!("bad{k}.json")) && stderr.contains(want),
            "{fields}\nwant {want}\ngot {stderr}"
        );
        assert!(out.stdout.is_empty());
    }
}

/// The value at a point outside a triangle extrapolates the plane: a pixel centre outside
/// the triangle under 4x multisampling gets the plane's value there, by hand. The
/// triangle (0,0) (1,0) (0,1) with the value x + 2y (0, 1, 2 at its vertices) covers
/// samples 0 and 2 of pixel (0, 0) (the standard 4x positions (3/8, 1/8), (1/8, 5/8));
/// its centre (1/2, 1/2) lies on its hypotenuse: x + 2y = 3/2 there. The centroid is the
/// first covered sample, (3/8, 1/8): 5/8; per sample, sample 2 (1/8, 5/8): 11/8.
#[test]
fn centre_centroid_and_sample_by_hand() {
    let text = r#"{"width": 1, "height": 1, "samples": 4,
        "varyings": [{"name": "c", "channels": 1, "sampling": "centre"},
                     {"name": "d", "channels": 1, "sampling": "centroid"},
                     {"name": "s", "channels": 1, "sampling": "sample"}],
        "triangles": [{"v": [[0, 0], [1, 0], [0, 1]],
                       "varyings": {"c": [[0], [1], [2]], "d": [[0], [1], [2]], "s": [[0], [1], [2]]}}]}"#;
    let dir = crate::tempdir::Dir::new("values-msaa");
    let path = dir.path().join("msaa.json");
    std::fs::write(&path, text).unwrap();
    let json = render_json(&path);
    assert_eq!(json["samples"], 4);
    assert_eq!(
        json["values"]["samples"],
        serde_json::json!([
            [0, 0, 0, 0, [["3/2"], ["5/8"], ["5/8"]]],
            [0, 0, 2, 0, [["3/2"], ["5/8"], ["11/8"]]]
        ])
    );
    let scene = parse_scene(text, "msaa.json").unwrap();
    let (_, _, values) = library_values(&scene);
    let got: Vec<_> = values.iter().map(|v| (v.sample, v.values.clone())).collect();
    let v = |n, d| Ok(vec![q(n, d)]);
    assert_eq!(
        got,
        vec![
            (0, vec![v(3, 2), v(5, 8), v(5, 8)]),
            (2, vec![v(3, 2), v(5, 8), v(11, 8)]),
        ]
    );
}

/// `--values-out`: one varying as a UNORM PNG, by hand. The triangle (0,0) (4,0) (0,4)
/// covers pixels 0 to 2 of a 4x1 canvas (pixel 3's centre (7/2, 1/2) is on its
/// hypotenuse, a right edge). `s` is 0, 1, 0 at the vertices: x / 4, so 1/8, 3/8, 5/8 at
/// the centres; times 255: 31.875, 95.625, 159.375, levels 32, 96, 159; times 65535:
/// 8191.875, 24575.625, 40959.375, levels 8192, 24576, 40959. `c` is flat (1/2, 1, 0):
/// 127.5 is a tie, to the even 128.
#[test]
fn values_out_writes_unorm_levels_by_hand() {
    let dir = crate::tempdir::Dir::new("values-out");
    let scene = dir.path().join("s.json");
    std::fs::write(
        &scene,
        r#"{"width": 4, "height": 1,
            "varyings": [{"name": "s", "channels": 1}, {"name": "c", "channels": 3, "interpolation": "flat"},
                         {"name": "wide", "channels": 5, "interpolation": "flat"}],
            "triangles": [{"v": [[0, 0], [4, 0], [0, 4]],
                "varyings": {"s": [[0], [1], [0]], "c": [["1/2", 1, 0], [0, 0, 0], [0, 0, 0]],
                             "wide": [[0, 0, 0, 0, 0], [0, 0, 0, 0, 0], [0, 0, 0, 0, 0]]}}]}"#,
    )
    .unwrap();
    let render = |args: &[&str]| render(&scene, &[&["--model", "exact"], args].concat());
    let png = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    for (args, file) in [
        (vec!["--values-out", &png("s8.png")], "s8.png"),
        (vec!["--values-out", &png("s16.png"), "--unorm", "16"], "s16.png"),
        (vec!["--values-out", &png("c.png"), "--varying", "c"], "c.png"),
    ] {
        let out = render(&args);
        assert!(
            out.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(dir.path().join(file).exists());
    }
    let s8 = image::open(dir.path().join("s8.png")).unwrap();
    assert_eq!(s8.as_luma8().unwrap().as_raw(), &[32, 96, 159, 0]);
    let s16 = image::open(dir.path().join("s16.png")).unwrap();
    assert_eq!(s16.as_luma16().unwrap().as_raw(), &[8192, 24576, 40959, 0]);
    let c = image::open(dir.path().join("c.png")).unwrap();
    assert_eq!(
        c.as_rgb8().unwrap().as_raw(),
        &[128, 255, 0, 128, 255, 0, 128, 255, 0, 0, 0, 0]
    );
    for (args, want) in [
        (
            vec!["--values-out", "x.png", "--varying", "t"],
            "s.json declares no varying \"t\" (it declares s, c, wide)",
        ),
        (
            vec!["--values-out", "x.png", "--unorm", "12"],
            "--values-out: 12 bits a channel: a UNORM PNG has 8 or 16",
        ),
        (
            vec!["--values-out", "x.png", "--varying", "wide"],
            "the varying \"wide\" has 5 channels, and a PNG pixel holds 1 to 4",
        ),
        (vec!["--unorm", "16"], "--varying and --unorm need --values-out"),
    ] {
        let out = render(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(want), "{args:?}\nwant {want}\ngot {stderr}");
        assert!(!std::path::Path::new("x.png").exists());
    }
}
