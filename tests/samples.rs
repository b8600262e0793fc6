//! Sample patterns (multisampling): every model decides every sample of a pattern as the
//! plain per-sample oracle does; the oracle agrees with an independent integer reading
//! (`tests/common`, the ε form of the tie rule at each sample's subpixel position) and
//! with hand derivations; the one-sample pattern is today's rendering; the invariants hold
//! per sample (no double cover and watertightness on meshes, rotation, winding and
//! whole-pixel translation); scene files and the CLI refuse what is not a pattern.

use crate::common;

use assert_cmd::Command;
use common::{config, coverage_map, q, render_at, Conv, Rule};
use num_rational::BigRational;
use proptest::prelude::*;
use proptest::test_runner::Config;
use rasterproof::check::{check_no_double_cover, check_watertight_samples};
use rasterproof::clip::{Rect, Window};
use rasterproof::convention::{PixelCentre, Preset, Rounding, Target};
use rasterproof::coverage::samples::SampleCoverage;
use rasterproof::geom::{Point, Polygon, Triangle};
use rasterproof::model::{render, render_samples, Model, ModelError, Primitives};
use rasterproof::pattern::{SamplePattern, STANDARD_COUNTS};
use rasterproof::scene::parse_scene;
use rasterproof::strategy::polygon::any_polygon;
use rasterproof::strategy::{any_triangle, delaunay_mesh, tie_heavy_mesh, tie_heavy_triangle};

fn cfg() -> Config {
    config("proptest-regressions/samples.txt")
}

const SIDE: u32 = 12;

fn target(preset: Preset, rounding: Rounding) -> Target {
    let mut conv = preset.convention();
    conv.rounding = rounding;
    Target::new(SIDE, SIDE, conv).unwrap()
}

fn models() -> impl Iterator<Item = Model> {
    Model::ALL.into_iter().filter(|m| m.is_exact())
}

/// A standard pattern, or a custom one of 1..=6 positions on the 1/16 grid (off every
/// standard table), or one with thirds (which only the models that do not snap take).
fn pattern() -> impl Strategy<Value = SamplePattern> {
    let standard = prop::sample::select(STANDARD_COUNTS.to_vec()).prop_map(|n| SamplePattern::standard(n).unwrap());
    let sixteenths = prop::collection::btree_set((0i64..16, 0i64..16), 1..=6)
        .prop_map(|set| SamplePattern::custom(set.into_iter().map(|(x, y)| [q(x, 16), q(y, 16)]).collect()).unwrap());
    let thirds = prop::collection::btree_set((0i64..3, 0i64..3), 1..=4)
        .prop_map(|set| SamplePattern::custom(set.into_iter().map(|(x, y)| [q(x, 3), q(y, 3)]).collect()).unwrap());
    prop_oneof![3 => standard, 2 => sixteenths, 1 => thirds]
}

fn rounding() -> impl Strategy<Value = Rounding> {
    prop::sample::select(vec![
        Rounding::NearestEven,
        Rounding::HalfAwayFromZero,
        Rounding::TowardsZero,
        Rounding::Floor,
    ])
}

/// Triangles of every kind, a polygon (holes, self-crossing, both fill rules), and
/// sometimes a clip window.
fn scene() -> impl Strategy<Value = Primitives> {
    let triangles = prop::collection::vec(prop_oneof![any_triangle(SIDE), tie_heavy_triangle(SIDE)], 1..=3);
    let polygon = prop::option::of(any_polygon(SIDE, 7));
    let window = prop::option::of((0i64..4, 0i64..4, 6i64..12, 6i64..12));
    (triangles, polygon, window).prop_map(|(triangles, polygon, window)| Primitives {
        triangles: triangles.into_iter().map(Into::into).collect(),
        polygons: polygon.into_iter().collect(),
        clip: window.map(|(x0, y0, x1, y1)| {
            let r = |v: i64| BigRational::new(v.into(), 2.into()) + q(1, 4);
            Window::Rect(Box::new(Rect {
                xmin: r(x0),
                ymin: r(y0),
                xmax: r(x1),
                ymax: r(y1),
            }))
        }),
        ..Primitives::default()
    })
}

/// The reference of `model` (`exact-plain` or `exact-snapped-plain`) per sample.
fn reference(p: &Primitives, target: &Target, pattern: &SamplePattern, model: Model) -> SampleCoverage {
    render_samples(p, target, pattern, model.reference()).expect("the plain oracles take every scene")
}

proptest! {
    #![proptest_config(cfg())]

    /// Every exact and integer model equals its plain oracle at every sample, under every
    /// preset and several roundings; a snapping model refuses exactly the patterns off its
    /// grid.
    #[test]
    fn every_model_equals_the_plain_oracle_per_sample(
        p in scene(),
        pattern in pattern(),
        preset in prop::sample::select(Preset::ALL.to_vec()),
        rounding in rounding(),
    ) {
        let target = target(preset, rounding);
        let plain = reference(&p, &target, &pattern, Model::ExactPlain);
        let snapped = reference(&p, &target, &pattern, Model::ExactSnappedPlain);
        let off_grid = (0..pattern.len()).any(|s| pattern.offset_subpixels(s, &target.convention).is_none());
        for model in models() {
            let want = if model.snaps() { &snapped } else { &plain };
            match render_samples(&p, &target, &pattern, model) {
                Ok(got) => {
                    prop_assert!(!(model.snaps() && off_grid && !model.is_plain()), "{model} took an off-grid pattern");
                    for s in 0..pattern.len() {
                        prop_assert_eq!(
                            coverage_map(got.sample(s)),
                            coverage_map(want.sample(s)),
                            "{} at sample {} {} of {}", model, s, pattern.position_text(s), pattern
                        );
                    }
                }
                Err(ModelError::SampleOffGrid { .. }) => prop_assert!(model.snaps() && off_grid),
                // The fixed model triangulates polygons, simple ones only.
                Err(e @ ModelError::Triangulate { .. }) => prop_assert!(model == Model::Fixed, "{e}"),
                Err(ModelError::AtSample { error, .. }) if matches!(*error, ModelError::Triangulate { .. }) => {
                    prop_assert!(model == Model::Fixed);
                }
                Err(e) => prop_assert!(false, "{model}: {e}"),
            }
        }
    }

    /// The snapped per-sample oracle on triangles equals the independent integer reading
    /// of `tests/common` at each sample's subpixel position.
    #[test]
    fn the_snapped_oracle_per_sample_equals_an_independent_reading(
        tris in prop::collection::vec(prop_oneof![any_triangle(SIDE), tie_heavy_triangle(SIDE)], 1..=4),
        count in prop::sample::select(STANDARD_COUNTS.to_vec()),
        bottom_left in any::<bool>(),
        half_away in any::<bool>(),
    ) {
        let mut conv = if bottom_left { Preset::Gl } else { Preset::D3d11 }.convention();
        conv.rounding = if half_away { Rounding::HalfAwayFromZero } else { Rounding::NearestEven };
        let target = Target::new(SIDE, SIDE, conv).unwrap();
        let pattern = SamplePattern::standard(count).unwrap();
        let got = render_samples(&Primitives::from_triangles(&tris), &target, &pattern, Model::ExactSnappedPlain).unwrap();
        let exact: Vec<[[BigRational; 2]; 3]> =
            tris.iter().map(|t| t.v.clone().map(|p| [p.x, p.y])).collect();
        let independent = Conv { rule: if bottom_left { Rule::BottomLeft } else { Rule::TopLeft }, bits: 8, half_away };
        for (s, [x, y]) in pattern.positions().iter().enumerate() {
            let sub = |v: &BigRational| i128::try_from((v * BigRational::from_integer(256.into())).to_integer()).unwrap();
            let want = render_at(&exact, SIDE, SIDE, independent, [sub(x), sub(y)]);
            prop_assert_eq!(coverage_map(got.sample(s)), want, "sample {}", s);
        }
    }

    /// Per sample, a Delaunay mesh covers every sample inside its hull exactly once, in
    /// every exact and integer model and pattern.
    #[test]
    fn meshes_are_watertight_per_sample(
        mesh in prop_oneof![tie_heavy_mesh(SIDE, 9), delaunay_mesh([1, 1], 10, 3, 9)],
        pattern in pattern(),
    ) {
        let target = Target::new(SIDE, SIDE, Preset::D3d11.convention()).unwrap();
        let scene = Primitives::from_triangles(&mesh.triangles);
        for model in models() {
            let Ok(c) = render_samples(&scene, &target, &pattern, model) else {
                prop_assert!(model.snaps(), "{model} refused");
                continue;
            };
            for s in 0..pattern.len() {
                prop_assert!(check_no_double_cover(c.sample(s)).is_ok(), "{model} sample {s}");
            }
            let checked = check_watertight_samples(&mesh.triangles, &mesh.outline, &c, &pattern, &target);
            prop_assert!(checked.is_ok(), "{model}: {}", checked.unwrap_err());
        }
    }

    /// Rotating a triangle's vertices, reversing its winding, or moving it by whole pixels
    /// leaves every sample's answer the same (moved with it).
    #[test]
    fn samples_are_invariant_under_rotation_winding_and_whole_pixel_moves(
        t in prop_oneof![any_triangle(SIDE), tie_heavy_triangle(SIDE)],
        pattern in pattern(),
        dx in -2i64..=2,
        dy in -2i64..=2,
    ) {
        let target = Target::new(SIDE, SIDE, Preset::D3d11.convention()).unwrap();
        let one = |t: &Triangle| render_samples(&Primitives::from_triangles(std::slice::from_ref(t)), &target, &pattern, Model::ExactSnapped);
        let Ok(base) = one(&t) else { return Ok(()); };
        prop_assert_eq!(&one(&t.rotated()).unwrap(), &base);
        prop_assert_eq!(&one(&t.reversed()).unwrap(), &base);
        let moved = one(&t.translated(dx, dy)).unwrap();
        for s in 0..pattern.len() {
            // Compare where both are on the canvas.
            let shifted = base.sample(s).translated(dx, dy);
            for y in 0..SIDE {
                for x in 0..SIDE {
                    let inside = |v: u32, d: i64| (0..i64::from(SIDE)).contains(&(i64::from(v) - d));
                    if inside(x, dx) && inside(y, dy) {
                        prop_assert_eq!(moved.owners(x, y, s), shifted.owners(x, y), "sample {} at ({}, {})", s, x, y);
                    }
                }
            }
        }
    }

    /// The convention's one sample as a pattern is the model's rendering without one.
    #[test]
    fn one_sample_is_todays_rendering(p in scene(), corner in any::<bool>()) {
        let mut conv = Preset::D3d11.convention();
        if corner {
            conv.pixel_centre = PixelCentre::Corner;
        }
        let target = Target::new(SIDE, SIDE, conv).unwrap();
        for model in Model::ALL {
            let Ok(today) = render(&p, &target, model) else { continue };
            let single = render_samples(&p, &target, &SamplePattern::single(&conv), model).unwrap();
            prop_assert_eq!(single.sample_count(), 1);
            prop_assert_eq!(coverage_map(single.sample(0)), coverage_map(&today), "{}", model);
        }
    }
}

fn tri(v: [[i64; 2]; 3]) -> Triangle {
    let [a, b, c] = v.map(|[x, y]| Point::from_ints(x, y));
    Triangle::new(a, b, c)
}

/// Two triangles sharing the diagonal x = y of the pixel square [0, 1]^2 (scaled by 1 on
/// a 1x1 canvas). Standard 4x (3/8, 1/8) (7/8, 3/8) (1/8, 5/8) (5/8, 7/8): samples 0 and
/// 1 have x > y (the upper-right triangle), samples 2 and 3 have x < y. No sample is on
/// the diagonal, so each sample has exactly one owner. 8x: (9/16, 5/16) (7/16, 11/16)
/// (13/16, 9/16) (5/16, 3/16) (3/16, 13/16) (1/16, 7/16) (11/16, 15/16) (15/16, 1/16):
/// x > y for samples 0, 2, 3, 7.
#[test]
fn a_pixel_split_on_its_diagonal_by_hand() {
    let upper = tri([[0, 0], [1, 0], [1, 1]]);
    let lower = tri([[0, 0], [1, 1], [0, 1]]);
    let target = Target::new(1, 1, Preset::Vulkan.convention()).unwrap();
    let scene = Primitives::from_triangles(&[upper, lower]);
    for model in models() {
        let four = render_samples(&scene, &target, &SamplePattern::standard(4).unwrap(), model).unwrap();
        assert_eq!(
            [four.mask_of(0, 0, 0), four.mask_of(0, 0, 1)],
            [0b0011, 0b1100],
            "{model}"
        );
        let eight = render_samples(&scene, &target, &SamplePattern::standard(8).unwrap(), model).unwrap();
        assert_eq!(eight.mask_of(0, 0, 0), 0b1000_1101, "{model}");
        assert_eq!(eight.mask_of(0, 0, 1), 0b0111_0010, "{model}");
    }
}

/// Samples exactly on edges: the 2x pattern (3/4, 3/4) (1/4, 1/4) against the square
/// [1/4, 3/4]^2 of one pixel (as a polygon). Sample 1 sits on the square's top-left
/// corner: on a top edge and a left edge, so the top-left rule includes it. Sample 0 sits
/// on the bottom-right corner: on a bottom and a right edge, excluded. Under the
/// bottom-left rule (gl), the top-left corner is on a top edge (excluded) and the
/// bottom-right one on a right edge (excluded): neither.
#[test]
fn samples_on_edges_follow_the_tie_rule_by_hand() {
    let sq: Vec<Point> = [[1, 1], [3, 1], [3, 3], [1, 3]]
        .iter()
        .map(|&[x, y]| Point::from_fractions(x, 4, y, 4))
        .collect();
    let scene = Primitives {
        polygons: vec![Polygon::new(sq, rasterproof::geom::FillRule::NonZero)],
        ..Primitives::default()
    };
    let two = SamplePattern::standard(2).unwrap();
    for (preset, want) in [(Preset::D3d11, 0b10), (Preset::Gl, 0b00)] {
        let target = Target::new(1, 1, preset.convention()).unwrap();
        for model in models() {
            let c = render_samples(&scene, &target, &two, model).unwrap();
            assert_eq!(c.mask(0, 0), want, "{model} {}", preset.name());
        }
    }
}

/// A custom pattern off the 8-bit grid (a third): the models that do not snap place it
/// exactly; the snapping ones refuse it, naming the sample and the grid.
#[test]
fn a_pattern_off_the_grid_is_refused_by_the_snapping_models() {
    let third = SamplePattern::custom(vec![[q(1, 3), q(1, 2)], [q(2, 3), q(1, 2)]]).unwrap();
    // The half plane x < 1/2 of pixel 0: sample 0 (x = 1/3) in, sample 1 (x = 2/3) out.
    let t = Triangle::new(
        Point::from_ints(-4, -4),
        Point::from_fractions(1, 2, -4, 1),
        Point::from_fractions(1, 2, 4, 1),
    );
    let target = Target::new(1, 1, Preset::D3d11.convention()).unwrap();
    let scene = Primitives::from_triangles(&[t]);
    for model in models() {
        match render_samples(&scene, &target, &third, model) {
            Ok(c) => {
                assert!(!model.snaps() || model.is_plain(), "{model}");
                assert_eq!(c.mask(0, 0), 0b01, "{model}");
            }
            Err(e) => {
                assert!(model.snaps(), "{model}: {e}");
                assert!(
                    e.to_string()
                        .contains("samples[0]: (1/3, 1/2) is not a whole number of subpixels (1/2^8)"),
                    "{e}"
                );
            }
        }
    }
}

#[test]
fn lines_under_a_pattern_are_refused() {
    let scene = parse_scene(
        r#"{"width": 4, "height": 4, "samples": 4, "lines": [{"from": [0, 0], "to": [3, 2], "rule": "diamond"}]}"#,
        "lines.json",
    )
    .unwrap();
    let target = Target::new(4, 4, scene.convention()).unwrap();
    let e = render_samples(
        &scene.primitives(),
        &target,
        scene.samples.as_ref().unwrap(),
        Model::ExactSnapped,
    );
    assert!(e
        .unwrap_err()
        .to_string()
        .starts_with("lines: 1 line(s) under the standard 4x sample pattern"));
}

#[test]
fn scene_files_name_the_bad_pattern() {
    let err = |samples: &str| {
        parse_scene(
            &format!(r#"{{"width": 4, "height": 4, "samples": {samples}}}"#),
            "s.json",
        )
        .unwrap_err()
        .to_string()
    };
    assert_eq!(
        err("3"),
        "s.json: samples: 3 has no standard pattern (standard counts: 1, 2, 4, 8, 16); give the positions as a list of [x, y] instead"
    );
    assert_eq!(
        err(r#"[["1/2", "1/2"], ["1/4", "5/4"]]"#),
        "s.json: samples[1][1]: sample 1's y is 5/4, outside the pixel: a position is a fraction of the pixel in [0, 1)"
    );
    assert_eq!(
        err(r#"[[0.5, 0.5], ["1/2", "2/4"]]"#),
        "s.json: samples[1]: samples 0 and 1 sit at the same position"
    );
    assert_eq!(
        err("[]"),
        "s.json: samples: a sample pattern needs at least one position"
    );
    let many: Vec<String> = (0..65).map(|k| format!("[\"{k}/65\", 0]")).collect();
    assert_eq!(
        err(&format!("[{}]", many.join(","))),
        "s.json: samples: 65 entries, at most 64"
    );
    assert!(err(r#"[[0.5]]"#).contains("samples[0]: a point is [x, y], found 1 values"));
    assert!(err("-1").contains("samples: expected a non-negative integer"));
    // A pattern written back reads the same.
    let scene = parse_scene(
        r#"{"width": 4, "height": 4, "samples": [["1/3", 0], [0.5, 0.25]]}"#,
        "s.json",
    )
    .unwrap();
    let again = parse_scene(&scene.to_json(), "again.json").unwrap();
    assert_eq!(again.samples, scene.samples);
    let standard = parse_scene(
        r#"{"width": 4, "height": 4, "samples": [[0.75, 0.75], [0.25, 0.25]]}"#,
        "s.json",
    )
    .unwrap();
    assert!(
        standard.to_json().contains("\"samples\": 2"),
        "the 2x table is the standard pattern"
    );
}

/// The CLI: the stacked ids PNG, the count PNG, the JSON masks, the count grid, and the
/// refusals, on the diagonal scene of [`a_pixel_split_on_its_diagonal_by_hand`] drawn
/// on a 2x1 canvas (pixel 1 empty).
#[test]
fn render_writes_every_form_of_the_masks() {
    let dir = crate::tempdir::Dir::new("samples-cli");
    let scene = dir.path().join("diag.json");
    std::fs::write(
        &scene,
        r#"{"width": 2, "height": 1, "preset": "vulkan", "samples": 4,
            "triangles": [{"v": [[0, 0], [1, 0], [1, 1]]}, {"v": [[0, 0], [1, 1], [0, 1]]}]}"#,
    )
    .unwrap();
    let ids = dir.path().join("ids.png");
    let count = dir.path().join("count.png");
    let out = Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("render")
        .arg(&scene)
        .args(["--format", "json", "--ids-out"])
        .arg(&ids)
        .arg("--count-out")
        .arg(&count)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(
        String::from_utf8(out.stdout).unwrap().trim(),
        r#"{"width":2,"height":1,"samples":4,"pixels":[[0,0,15,[0],[0],[1],[1]]]}"#
    );
    let ids = image::open(&ids).unwrap().to_rgba8();
    assert_eq!(ids.dimensions(), (2, 4));
    let id_at = |s: u32| ids.get_pixel(0, s).0;
    assert_eq!(
        [id_at(0), id_at(1), id_at(2), id_at(3)],
        [[1, 0, 0, 255], [1, 0, 0, 255], [2, 0, 0, 255], [2, 0, 0, 255]]
    );
    assert_eq!(ids.get_pixel(1, 2).0, [0, 0, 0, 0]);
    assert_eq!(image::open(&count).unwrap().to_luma8().as_raw(), &[255, 0]);

    let text = Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("render")
        .arg(&scene)
        .args(["--samples", "16"])
        .output()
        .unwrap();
    let text = String::from_utf8(text.stdout).unwrap();
    assert!(text.starts_with("#.\n"), "{text}");
    assert!(
        text.contains("standard 16x samples: 16 samples covered, 1 pixel with some, 1 with all"),
        "{text}"
    );

    let refused = |args: &[&str]| {
        let out = Command::cargo_bin("rasterproof")
            .unwrap()
            .arg("render")
            .arg(&scene)
            .args(args)
            .output()
            .unwrap();
        assert!(!out.status.success());
        String::from_utf8(out.stderr).unwrap()
    };
    assert!(refused(&["--samples", "5"]).contains("--samples: 5 has no standard pattern"));
    let picture = dir.path().join("p.png");
    assert!(refused(&["-o", picture.to_str().unwrap()])
        .contains("under the standard 4x sample pattern render writes --ids-out"));
    assert!(!picture.exists(), "nothing written");
    assert!(
        refused(&["--samples", "1", "--count-out", "c.png"]).contains("--count-out needs a pattern of several samples")
    );
}

/// A model that snaps is handed the scene snapped first, then moved to each sample: moving
/// first and snapping after is not the same under half-away rounding. Vertex 2's y is
/// 43/512 = 21.5 subpixels, snapped away from zero to 22; sample 2 of the 4x pattern sits
/// 1/8 = 32 subpixels above the centre, so the snapped vertex moved to it is at -10. Moved
/// first, it is at -21/512 = -10.5 subpixels, snapped away from zero to -11: another
/// triangle, which decides sample 2 of pixel (1, 0) otherwise.
#[test]
fn snapping_models_snap_before_moving_to_a_sample() {
    let conv = rasterproof::convention::Convention {
        rounding: Rounding::HalfAwayFromZero,
        ..Preset::D3d11.convention()
    };
    let target = Target::new(2, 2, conv).unwrap();
    let four = SamplePattern::standard(4).unwrap();
    let t = Triangle::new(
        Point::from_fractions(115, 512, 775, 512),
        Point::from_fractions(149, 256, 193, 512),
        Point::from_fractions(855, 512, 43, 512),
    );
    let scene = Primitives::from_triangles(std::slice::from_ref(&t));
    let plain = render_samples(&scene, &target, &four, Model::ExactSnappedPlain).unwrap();
    for model in models().filter(|m| m.snaps()) {
        assert_eq!(render_samples(&scene, &target, &four, model).unwrap(), plain, "{model}");
    }
    let [dx, dy] = four.offset(2, &conv);
    let v = t.v.clone().map(|p| Point::new(&p.x - &dx, &p.y - &dy));
    let moved_first = render(
        &Primitives::from_triangles(&[Triangle::new(v[0].clone(), v[1].clone(), v[2].clone())]),
        &target,
        Model::ExactSnapped,
    )
    .unwrap();
    assert_ne!(
        coverage_map(&moved_first),
        coverage_map(plain.sample(2)),
        "the case tells the two orders apart"
    );
}

/// The 4x4 scene (standard 4x pattern) whose horizontal edges sit at y = 1/8, written into
/// `dir`: triangles 0 and 1 below the edge, triangle 2 above it.
fn edge_scene(dir: &crate::tempdir::Dir) -> std::path::PathBuf {
    let scene = dir.path().join("edge.json");
    std::fs::write(
        &scene,
        r#"{"width": 4, "height": 4, "samples": 4, "triangles": [
            {"v": [[0, "1/8"], [4, "1/8"], [0, 4]]}, {"v": [[4, "1/8"], [4, 4], [0, 4]]},
            {"v": [[4, "1/8"], [0, "1/8"], [2, -3]]}]}"#,
    )
    .unwrap();
    scene
}

/// `compare` per sample: a scene whose horizontal edges sit at y = 1/8, the height of
/// sample 0 of the 4x pattern in every pixel of row 0 (and of nothing else). Rendered
/// under gl's bottom-left rule, sample 0 of the four pixels of row 0 goes to the triangle
/// below the edge instead of the one above (a top edge is exclusive there, a bottom edge
/// inclusive): 4 samples differ, all at sample index 0, each a tie; `--fit` finds
/// bottom-left and not top-left for every sample.
#[test]
fn compare_judges_each_sample_index() {
    let dir = crate::tempdir::Dir::new("samples-compare");
    let scene = edge_scene(&dir);
    let cli = || Command::cargo_bin("rasterproof").unwrap();
    let ids = |preset: &str| {
        let path = dir.path().join(format!("{preset}.png"));
        let out = cli()
            .arg("render")
            .arg(&scene)
            .args(["--preset", preset, "--ids-out"])
            .arg(&path)
            .output()
            .unwrap();
        assert!(out.status.success());
        path
    };
    let (d3d, gl) = (ids("d3d11"), ids("gl"));
    let same = cli().arg("compare").arg(&scene).arg(&d3d).output().unwrap();
    assert_eq!(same.status.code(), Some(0));
    assert!(String::from_utf8(same.stdout)
        .unwrap()
        .contains("standard 4x samples: identical at every sample"));

    let differ = cli()
        .arg("compare")
        .arg(&scene)
        .arg(&gl)
        .args(["--format", "json"])
        .output()
        .unwrap();
    assert_eq!(differ.status.code(), Some(1));
    let json: serde_json::Value = serde_json::from_slice(&differ.stdout).unwrap();
    assert_eq!(json["differing_samples"], 4);
    let samples = json["samples"].as_array().unwrap();
    assert_eq!(samples[0]["position"], serde_json::json!(["3/8", "1/8"]));
    assert_eq!(samples[0]["moved_by"], serde_json::json!(["1/8", "3/8"]));
    let pixels = samples[0]["report"]["pixels"].as_array().unwrap();
    let at: Vec<_> = pixels
        .iter()
        .map(|p| (p["x"].as_u64().unwrap(), p["y"].as_u64().unwrap()))
        .collect();
    assert_eq!(at, [(0, 0), (1, 0), (2, 0), (3, 0)]);
    for (s, sample) in samples.iter().enumerate().skip(1) {
        assert_eq!(sample["report"]["pixels"].as_array().unwrap().len(), 0, "sample {s}");
    }
    let text = String::from_utf8(cli().arg("compare").arg(&scene).arg(&gl).output().unwrap().stdout).unwrap();
    assert!(text.contains("sample 0 at (3/8, 1/8): 4 pixels differ"), "{text}");
    assert!(text.contains("tie: the sample lies on edge"), "{text}");

    let fit = cli()
        .arg("compare")
        .arg(&scene)
        .arg(&gl)
        .args(["--fit", "--format", "json"])
        .output()
        .unwrap();
    assert_eq!(fit.status.code(), Some(0));
    let fit: serde_json::Value = serde_json::from_slice(&fit.stdout).unwrap();
    let every: Vec<&str> = fit["every_sample"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_str().unwrap())
        .collect();
    assert!(
        every
            .iter()
            .any(|c| c.starts_with("tie rule bottom-left, 8 subpixel bits")),
        "{every:?}"
    );
    assert!(!every.iter().any(|c| c.starts_with("tie rule top-left")), "{every:?}");

    let wrong = cli()
        .arg("compare")
        .arg(&scene)
        .arg(&gl)
        .args(["--samples", "8"])
        .output()
        .unwrap();
    assert_eq!(wrong.status.code(), Some(2));
    let err = String::from_utf8(wrong.stderr).unwrap();
    assert!(
        err.contains("their image is 4x16; 8 sample images of the 4x4 canvas stacked are 4x32"),
        "{err}"
    );
}

/// `explain X,Y` under a pattern lists every sample: on the edge scene of
/// [`compare_judges_each_sample_index`], sample 0 of pixel (1, 0) is the point (11/8, 1/8)
/// on the shared horizontal edge y = 1/8: a top edge of triangle 0 (inclusive, top-left)
/// and a bottom edge of triangle 2 (exclusive); samples 1 to 3 lie below it, in triangle
/// 0. Every model's owners per sample index are listed.
#[test]
fn explain_lists_every_sample() {
    let dir = crate::tempdir::Dir::new("samples-explain");
    let scene = edge_scene(&dir);
    let out = Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("explain")
        .arg(&scene)
        .args(["1,0", "--format", "json"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let why: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(why["pattern"], "standard 4x");
    let sample0 = &why["samples"][0];
    assert_eq!(sample0["position"], "(3/8, 1/8)");
    assert!(sample0["point"].as_str().unwrap().starts_with("(11/8, 1/8)"));
    let evidence: Vec<&str> = sample0["primitives"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["as_written"].as_str().unwrap())
        .collect();
    assert!(
        evidence[0].contains("E=0 (inclusive)") && evidence[0].ends_with("-> inside"),
        "{evidence:?}"
    );
    assert!(
        evidence[2].contains("E=0 (exclusive)") && evidence[2].ends_with("-> outside"),
        "{evidence:?}"
    );
    let models = why["models"].as_array().unwrap();
    assert_eq!(models.len(), Model::ALL.len() - 2);
    for m in models
        .iter()
        .filter(|m| ["exact", "exact-snapped", "fixed", "scanline"].contains(&m["model"].as_str().unwrap()))
    {
        assert_eq!(m["owners"], serde_json::json!([[0], [0], [0], [0]]), "{m}");
    }
    let text = Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("explain")
        .arg(&scene)
        .args(["1,0", "--samples", "2"])
        .output()
        .unwrap();
    let text = String::from_utf8(text.stdout).unwrap();
    assert!(
        text.contains("pixel (1, 0), standard 2x samples") && text.contains("sample 1 at (1/4, 1/4)"),
        "{text}"
    );
}

/// A clip-space triangle moves with its viewport: NDC (-1, 1) (0, 1) (0, -1) at w = 1,
/// through the default viewport of a 2x2 canvas (d3d11: NDC y up), is the window-space
/// triangle (0, 0) (1, 0) (1, 2): inside where y <= 2x and x <= 1. Of pixel (0, 0)'s
/// standard 4x samples, (3/8, 1/8), (7/8, 3/8) and (5/8, 7/8) are (1/8 <= 3/4, 3/8 <= 7/4,
/// 7/8 <= 5/4), (1/8, 5/8) is not (5/8 > 1/4); none lies on an edge, so every model,
/// floats included, has mask 0b1011 there, and pixel (1, 0)'s samples (x > 1) none.
#[test]
fn clip_space_triangles_are_drawn_per_sample() {
    let scene = parse_scene(
        r#"{"width": 2, "height": 2, "samples": 4,
            "clip_space_triangles": [{"v": [[-1, 1, 0, 1], [0, 1, 0, 1], [0, -1, 0, 1]]}]}"#,
        "clip-space.json",
    )
    .unwrap();
    let target = scene.target().unwrap();
    let four = scene.samples.clone().unwrap();
    for model in Model::ALL {
        let c = render_samples(&scene.primitives(), &target, &four, model).unwrap();
        assert_eq!(c.mask(0, 0), 0b1011, "{model}");
        assert_eq!(c.mask(1, 0), 0, "{model}");
    }
}

/// `compare --fit` under a pattern names where their samples sit: their image is drawn
/// at the 4x pattern with sample 2 moved from (1/8, 5/8) to (3/16, 9/16) (a renderer with
/// a programmable position); the fit says the standard position does not give sample 2's
/// image and lists (3/16, 9/16) among the 1/16 px positions that do, while the three other
/// standard positions fit.
#[test]
fn fit_names_a_moved_sample_position() {
    let dir = crate::tempdir::Dir::new("samples-fit-positions");
    let triangles = r#""triangles": [{"v": [[0, 0], [8, "3/16"], ["1/16", 8]]}, {"v": [[8, "3/16"], [8, 8], ["1/16", 8]]},
        {"v": [["1/32", "5/2"], [8, "7/3"], [5, "43/8"]]}, {"v": [["2/3", "1/8"], ["7/2", 8], ["3/16", "9/2"]]}]"#;
    let scene = dir.path().join("scene.json");
    std::fs::write(&scene, format!(r#"{{"width": 8, "height": 8, {triangles}}}"#)).unwrap();
    let moved = dir.path().join("moved.json");
    std::fs::write(
        &moved,
        format!(r#"{{"width": 8, "height": 8, "samples": [["3/8", "1/8"], ["7/8", "3/8"], ["3/16", "9/16"], ["5/8", "7/8"]], {triangles}}}"#),
    )
    .unwrap();
    let theirs = dir.path().join("theirs.png");
    let cli = || Command::cargo_bin("rasterproof").unwrap();
    assert!(cli()
        .arg("render")
        .arg(&moved)
        .arg("--ids-out")
        .arg(&theirs)
        .output()
        .unwrap()
        .status
        .success());
    let out = cli()
        .arg("compare")
        .arg(&scene)
        .arg(&theirs)
        .args(["--samples", "4", "--fit", "--format", "json"])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(1),
        "no convention fits sample 2 at the standard position"
    );
    let fit: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let positions = fit["positions"].as_array().unwrap();
    let fits = |s: usize| positions[s]["pattern_fits"].as_bool().unwrap();
    assert_eq!([fits(0), fits(1), fits(2), fits(3)], [true, true, false, true]);
    let listed: Vec<&str> = positions[2]["fits"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p.as_str().unwrap())
        .collect();
    assert!(
        listed.contains(&"(3/16, 9/16)") && !listed.contains(&"(1/8, 5/8)"),
        "{listed:?}"
    );
}

/// A 4x MSAA renderer with sample 2 moved from the standard (1/8, 5/8) to (1/8, 1/2): the
/// oracle's own per-sample rendering under the moved pattern, stacked into one ids PNG.
fn moved_sample_renderer(
    scene: &rasterproof::scene::Scene,
) -> Result<rasterproof::oracle::Theirs, rasterproof::oracle::renderer::program::RenderFailure> {
    let moved = SamplePattern::custom(vec![
        [q(3, 8), q(1, 8)],
        [q(7, 8), q(3, 8)],
        [q(1, 8), q(1, 2)],
        [q(5, 8), q(7, 8)],
    ])
    .unwrap();
    Ok(stacked_at(scene, &moved))
}

/// The oracle's per-sample rendering of `scene` under `pattern`, stacked into one ids PNG
/// and read back as a renderer's answer.
fn stacked_at(scene: &rasterproof::scene::Scene, pattern: &SamplePattern) -> rasterproof::oracle::Theirs {
    let target = scene.target().unwrap();
    let drawn = render_samples(&scene.primitives(), &target, pattern, Model::ExactSnapped).unwrap();
    let mut png = Vec::new();
    image::DynamicImage::ImageRgba8(drawn.to_stacked_ids_image().unwrap())
        .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .unwrap();
    rasterproof::oracle::Theirs::read(&png, "stacked", rasterproof::oracle::Format::Ids, Default::default()).unwrap()
}

/// `hunt --samples 4` against a renderer with one moved sample: its findings may be of
/// several signatures, but the summary names the sample by index, says the three others
/// drew the oracle's image in every case, and lists (1/8, 1/2), not the standard
/// (1/8, 5/8), among the 1/16 px positions that give sample 2's image on every finding.
#[test]
fn a_multisample_hunt_names_the_moved_sample() {
    use rasterproof::oracle::hunt::{hunt, HuntConfig, SceneFamily};
    let config = HuntConfig {
        cases: 24,
        canvas: 8,
        families: vec![SceneFamily::Mesh, SceneFamily::Triangles],
        samples: SamplePattern::standard(4),
        shrink_runs: 40,
        ..HuntConfig::default()
    };
    let report = hunt(&moved_sample_renderer, &config, 1, &|| {}).unwrap();
    assert!(!report.findings.is_empty());
    let by_index: Vec<u64> = report.per_sample.iter().map(|p| p.cases).collect();
    assert_eq!(by_index.len(), 4);
    assert!(
        by_index[2] > 0 && by_index[0] == 0 && by_index[1] == 0 && by_index[3] == 0,
        "{by_index:?}"
    );
    let fits = report.per_sample[2].fits.clone().expect("positions fitted");
    assert!(fits.contains(&[q(1, 8), q(1, 2)]), "{fits:?}");
    assert!(!fits.contains(&[q(1, 8), q(5, 8)]), "{fits:?}");
    let text = report.to_text(None);
    assert!(text.contains("by sample index:"), "{text}");
    assert!(text.contains("sample 2 at (1/8, 5/8): differs in"), "{text}");
    assert!(
        text.contains("sample 0 at (3/8, 1/8): the oracle's image in every case"),
        "{text}"
    );
    assert!(
        text.contains("(1/8, 1/2)") && text.contains("not its own position"),
        "{text}"
    );
    let json: serde_json::Value = serde_json::from_str(&report.to_json("moved")).unwrap();
    assert_eq!(json["per_sample"][2]["position"], serde_json::json!(["1/8", "5/8"]));
    assert!(json["per_sample"][2]["fits"]
        .as_array()
        .unwrap()
        .contains(&serde_json::json!(["1/8", "1/2"])));

    // The same hunt in two shards, merged: each index's cases and pixels add up to the
    // whole run's, and sample 2's fits still hold its moved position.
    let shards: Vec<(String, serde_json::Value)> = (1..=2)
        .map(|k| {
            let shard = rasterproof::harness::suite::Shard::new(k, 2).unwrap();
            let part = hunt(
                &moved_sample_renderer,
                &HuntConfig {
                    shard,
                    ..config.clone()
                },
                1,
                &|| {},
            )
            .unwrap();
            (
                format!("shard-{k}.json"),
                serde_json::from_str(&part.to_json("moved")).unwrap(),
            )
        })
        .collect();
    let merged = rasterproof::oracle::hunt::merge_reports(&shards).unwrap();
    for (i, whole) in report.per_sample.iter().enumerate() {
        assert_eq!(
            merged["per_sample"][i]["cases"],
            serde_json::json!(whole.cases),
            "{merged}"
        );
        assert_eq!(
            merged["per_sample"][i]["pixels"],
            serde_json::json!(whole.pixels),
            "{merged}"
        );
    }
    let back = rasterproof::oracle::hunt::per_sample_summaries(&merged).unwrap();
    let fits = back[2].fits.clone().expect("merged positions");
    assert!(
        fits.contains(&[q(1, 8), q(1, 2)]) && !fits.contains(&[q(1, 8), q(5, 8)]),
        "{fits:?}"
    );
}

/// The fit before a multisample hunt (`hunt --samples 4 --fit-first`) on the renderer with
/// sample 2 moved to (1/8, 1/2): the three other samples are explained at the standard
/// positions by the scenes' own convention (top-left, 8 bits, nearest-even, centre 1/2),
/// sample 2 is moved to (1/8, 1/2), and a hunt under the fitted pattern finds nothing.
#[test]
fn the_fit_before_a_multisample_hunt_moves_the_sample() {
    use rasterproof::oracle::hunt::{fit_sample_convention, hunt, FitFirst, HuntConfig, SceneFamily};
    let config = HuntConfig {
        cases: 24,
        canvas: 8,
        families: vec![SceneFamily::Mesh, SceneFamily::Triangles],
        samples: SamplePattern::standard(4),
        shrink_runs: 40,
        ..HuntConfig::default()
    };
    let found = fit_sample_convention(&moved_sample_renderer, &config).unwrap();
    let FitFirst::Statable { fit, overrides, model } = found.convention else {
        panic!("{:?}", found.convention);
    };
    assert_eq!(
        fit.to_string(),
        "tie rule top-left, 8 subpixel bits, nearest-even, pixel centre 0.5"
    );
    assert_eq!(found.moved.len(), 1, "{:?}", found.moved);
    let moved = &found.moved[0];
    assert_eq!(
        (moved.index, &moved.from, &moved.to),
        (2, &[q(1, 8), q(5, 8)], &[q(1, 8), q(1, 2)])
    );
    assert!(moved.fitting >= 1);
    assert_eq!(found.pattern.positions()[2], [q(1, 8), q(1, 2)]);
    assert_eq!(found.pattern.positions()[0], [q(3, 8), q(1, 8)]);
    let under = HuntConfig {
        overrides,
        model,
        samples: Some(found.pattern),
        ..config.clone()
    };
    let report = hunt(&moved_sample_renderer, &under, 1, &|| {}).unwrap();
    assert!(report.findings.is_empty(), "{}", report.to_text(None));
    assert_eq!(report.same, 24);

    // A renderer at the standard positions: the pattern stands, under the same convention.
    let standard = |scene: &rasterproof::scene::Scene| Ok(stacked_at(scene, &SamplePattern::standard(4).unwrap()));
    let found = fit_sample_convention(&standard, &config).unwrap();
    assert!(found.moved.is_empty(), "{:?}", found.moved);
    assert_eq!(found.pattern, SamplePattern::standard(4).unwrap());
    let FitFirst::Statable { fit, .. } = found.convention else {
        panic!("{:?}", found.convention);
    };
    assert_eq!(
        fit.to_string(),
        "tie rule top-left, 8 subpixel bits, nearest-even, pixel centre 0.5"
    );
}

/// `hunt --samples 4` with a real program: a shell script that draws every scene with
/// sample 2 at (1/8, 1/2) (`rasterproof render` of the scene with its `samples` replaced).
/// The plain hunt finds it and names sample 2 in its summary; `--fit-first` moves sample 2
/// there, says so, and the hunt under that pattern finds nothing.
#[test]
fn hunt_samples_fit_first_from_the_command_line() {
    let dir = crate::tempdir::Dir::new("samples-hunt-fit-first");
    let script = dir.path().join("moved.sh");
    std::fs::write(
        &script,
        format!(
            "#!/bin/sh\nset -e\nsed 's|\"samples\": .*|\"samples\": [[\"3/8\", \"1/8\"], [\"7/8\", \"3/8\"], [\"1/8\", \"1/2\"], [\"5/8\", \"7/8\"]]|' \"$1\" > \"$2.scene.json\"\nexec {} render \"$2.scene.json\" --ids-out \"$2\"\n",
            assert_cmd::cargo::cargo_bin("rasterproof").display()
        ),
    )
    .unwrap();
    let cmd = format!("sh {} {{scene}} {{out}}", script.display());
    let hunt = |extra: &[&str]| {
        let out = Command::cargo_bin("rasterproof")
            .unwrap()
            .args([
                "hunt",
                "--samples",
                "4",
                "--cmd",
                &cmd,
                "--cases",
                "12",
                "--canvas",
                "8",
            ])
            .args(["--shrink-runs", "10", "--quiet"])
            .args(extra)
            .output()
            .unwrap();
        let text = format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        (out.status.code(), text)
    };
    let (code, text) = hunt(&[]);
    assert_eq!(code, Some(1), "{text}");
    assert!(text.contains("by sample index:"), "{text}");
    assert!(text.contains("sample 2 at (1/8, 5/8): differs in"), "{text}");
    assert!(
        text.contains("sample 1 at (7/8, 3/8): the oracle's image in every case"),
        "{text}"
    );
    let (code, text) = hunt(&["--fit-first"]);
    assert_eq!(code, Some(0), "{text}");
    assert!(
        text.contains("fit: hunting under tie rule top-left, 8 subpixel bits, nearest-even, pixel centre 0.5 (oracle exact-snapped), sample 2 at (1/8, 1/2), not the pattern's (1/8, 5/8)"),
        "{text}"
    );
}
