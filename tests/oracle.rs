//! The oracle for other implementations (`rasterproof::oracle`, `compare`, `explain`):
//! identical outputs compare equal in every format and for every model that equals the
//! oracle; each reason class is found on a renderer made to differ in exactly that way
//! (the expected class derived from how it was made to differ); float models' differences
//! are all classified and none is gross; bad input exits 2 and names the file.

use assert_cmd::Command;
use proptest::prelude::*;
use rasterproof::convention::{AnyTieRule, Preset, Rounding, TieRule};
use rasterproof::coverage::{Coverage, CoverageSink};
use rasterproof::model::{prepare, render, Model, Primitives, Shape};
use rasterproof::oracle::{compare, CompareReport, Format, PixelKind, Reason, ReasonClass, Relation, Theirs};
use rasterproof::scene::{parse_scene, Scene};
use rasterproof::strategy::polygon::any_polygon;
use rasterproof::strategy::{any_triangle, diamond_line, pixel_line, tie_heavy_mesh};

use crate::tempdir;

fn bin() -> Command {
    Command::cargo_bin("rasterproof").unwrap()
}

fn scene(text: &str) -> Scene {
    parse_scene(text, "test.json").unwrap()
}

/// `theirs` (a coverage of the scene's canvas) compared in `format` against `model`.
fn report(s: &Scene, theirs: &Coverage, format: Format, model: Model) -> CompareReport {
    let target = s.target().unwrap();
    compare(
        &s.primitives(),
        &target,
        &Theirs::from_coverage(theirs, format),
        &model.into(),
    )
    .unwrap()
}

/// The scene rendered by `model` under the scene's convention changed by `change`.
fn rendered_with(s: &Scene, model: Model, change: impl FnOnce(&mut Scene)) -> Coverage {
    let mut other = s.clone();
    change(&mut other);
    render(&other.primitives(), &other.target().unwrap(), model).unwrap()
}

fn classes(r: &CompareReport) -> Vec<ReasonClass> {
    let mut v: Vec<ReasonClass> = r
        .pixels
        .iter()
        .flat_map(|p| p.findings.iter().map(|f| f.reason.class()))
        .collect();
    v.sort();
    v.dedup();
    v
}

const HALF_PIXEL_SQUARES: &str = r#"{"width": 8, "height": 6, "triangles": [
    {"v": [[0, 0.5], [8, 0.5], [8, 4.5]]}, {"v": [[0, 0.5], [8, 4.5], [0, 4.5]]}]}"#;

#[test]
fn identical_outputs_compare_equal_in_every_format() {
    for text in [
        HALF_PIXEL_SQUARES,
        include_str!("../examples/scenes/polygons.json"),
        include_str!("../examples/scenes/lines.json"),
        include_str!("../examples/scenes/seed003.json"),
    ] {
        let s = scene(text);
        let target = s.target().unwrap();
        // The plain oracles on the small scenes only (on seed003's 512 x 512 canvas they
        // took 10 s, and they equal the planned ones: tests/planned.rs).
        let plain = target.width * target.height <= 128 * 128;
        for model in [
            Model::Exact,
            Model::ExactSnapped,
            Model::ExactPlain,
            Model::ExactSnappedPlain,
        ] {
            if !plain && matches!(model, Model::ExactPlain | Model::ExactSnappedPlain) {
                continue;
            }
            let ours = render(&s.primitives(), &s.target().unwrap(), model).unwrap();
            for format in [Format::Mask, Format::Ids, Format::Json] {
                let r = report(&s, &ours, format, model);
                assert!(r.identical(), "{model} {format:?}: {}", r.to_text("s", "t", 3));
                assert_eq!(r.ours_covered, ours.covered_pixels());
            }
        }
        // The integer models equal the snapped oracle, so they compare equal too.
        for model in [Model::Fixed, Model::Scanline] {
            if let Ok(theirs) = render(&s.primitives(), &target, model) {
                assert!(
                    report(&s, &theirs, Format::Json, Model::ExactSnapped).identical(),
                    "{model}"
                );
            }
        }
    }
}

/// Their renderer follows bottom-left where the scene says top-left: every difference is
/// a tie on a horizontal edge, and every finding names bottom-left among the rules.
#[test]
fn another_tie_rule_is_a_tie_naming_the_rule() {
    let s = scene(HALF_PIXEL_SQUARES);
    let theirs = rendered_with(&s, Model::ExactSnapped, |s| s.preset = Preset::Gl);
    for format in [Format::Mask, Format::Ids, Format::Json] {
        let r = report(&s, &theirs, format, Model::ExactSnapped);
        // Rows 0 (y = 1/2, the top edge) and 4 (y = 9/2, the bottom edge): 8 pixels each.
        assert_eq!(r.pixels.len(), 16, "{format:?}");
        assert_eq!(classes(&r), [ReasonClass::Tie], "{format:?}");
        for p in &r.pixels {
            assert!(p.y == 0 || p.y == 4);
            let kind = if p.y == 0 { PixelKind::Missing } else { PixelKind::Extra };
            assert_eq!(p.kind, kind, "{format:?} {p:?}");
            for f in &p.findings {
                let Reason::Tie { edges, rules } = &f.reason else {
                    unreachable!()
                };
                assert!(rules.contains(&AnyTieRule::BottomLeft), "{rules:?}");
                assert!(!rules.contains(&AnyTieRule::TopLeft), "{rules:?}");
                assert_eq!(edges.len(), 1);
                let side = if p.y == 0 { "top" } else { "bottom" };
                assert_eq!(edges[0].side.name(), side);
            }
        }
    }
}

/// Their renderer snaps to 2 subpixel bits: every difference is explained by snapping
/// with at most 2 bits (the search reports the fewest, after the oracle's own 8 bits with
/// other roundings, which never move a vertex by a quarter pixel).
#[test]
fn coarser_snapping_is_snapping_with_at_most_its_bits() {
    let s = scene(
        r#"{"width": 16, "height": 16, "triangles": [
        {"v": [["1/3", "0.1"], ["15.9", "2/7"], ["4.77", "15.03"]]},
        {"v": [["15.9", "2/7"], ["15.97", "15.5"], ["4.77", "15.03"]]}]}"#,
    );
    let theirs = rendered_with(&s, Model::ExactSnapped, |s| s.overrides.subpixel_bits = Some(2));
    let r = report(&s, &theirs, Format::Json, Model::ExactSnapped);
    assert!(!r.identical(), "the scene must move under 2-bit snapping");
    for p in &r.pixels {
        for f in &p.findings {
            match &f.reason {
                Reason::Snapping {
                    bits: Some(b),
                    roundings,
                } => {
                    assert!(*b <= 2, "{p:?}");
                    if *b == 2 {
                        assert!(roundings.contains(&Rounding::NearestEven), "{roundings:?}");
                    }
                }
                other => panic!("({}, {}): {other:?}", p.x, p.y),
            }
        }
    }
    // The unsnapped renderer is explained by "unsnapped" or by finer bits.
    let unsnapped = rendered_with(&s, Model::Exact, |_| {});
    let r = report(&s, &unsnapped, Format::Json, Model::ExactSnapped);
    assert!(
        r.pixels.iter().all(|p| p.findings.iter().all(|f| matches!(
            f.reason,
            Reason::Snapping { bits: None, .. } | Reason::Snapping { bits: Some(9..), .. }
        ))),
        "{}",
        r.to_text("s", "t", 5)
    );
}

/// A floor-rounding renderer is explained by snapping that names floor (or, where the
/// sample lies on one of the oracle's edges, by a tie).
#[test]
fn directed_rounding_is_named() {
    let s = scene(
        r#"{"width": 16, "height": 16, "triangles": [{"v": [["1/3", "0.3"], ["15.7", "4/3"], ["2.9", "47/3"]]}],
            "subpixel_bits": 2}"#,
    );
    let theirs = rendered_with(&s, Model::ExactSnapped, |s| {
        s.overrides.rounding = Some(Rounding::Floor)
    });
    let r = report(&s, &theirs, Format::Json, Model::ExactSnapped);
    let mut floor = 0;
    for f in r.pixels.iter().flat_map(|p| &p.findings) {
        match &f.reason {
            // The oracle's own 2 bits with another rounding come first.
            Reason::Snapping {
                bits: Some(2),
                roundings,
            } => {
                assert!(!roundings.contains(&Rounding::NearestEven), "{f:?}");
                floor += usize::from(roundings.contains(&Rounding::Floor));
            }
            Reason::Tie { .. } => {}
            other => panic!("{other:?}"),
        }
    }
    assert!(floor > 0, "{}", r.to_text("s", "t", 5));
}

/// Pixels far from every edge are gross; an id that names another primitive is a wrong
/// owner, the extra id gross when it is far from that primitive.
#[test]
fn far_pixels_are_gross_and_wrong_ids_are_wrong_owners() {
    let s = scene(
        r#"{"width": 32, "height": 8, "triangles": [{"v": [[0, 0], [6, 0], [0, 6]]}, {"v": [[26, 0], [32, 0], [32, 6]]}]}"#,
    );
    let target = s.target().unwrap();
    let mut theirs = render(&s.primitives(), &target, Model::ExactSnapped).unwrap();
    theirs.cover(15, 4, 0); // 9 px and more from both triangles
    let r = report(&s, &theirs, Format::Json, Model::ExactSnapped);
    assert_eq!(r.pixels.len(), 1);
    assert_eq!(r.pixels[0].kind, PixelKind::Extra);
    let f = &r.pixels[0].findings[0];
    assert_eq!((f.id, f.relation), (Some(0), Relation::Extra));
    assert_eq!(f.reason.class(), ReasonClass::Gross);
    // As a mask the owner is unknown: no primitive explains it.
    let r = report(&s, &theirs, Format::Mask, Model::ExactSnapped);
    let f = &r.pixels[0].findings[0];
    assert_eq!((f.id, f.guessed, f.reason.class()), (None, true, ReasonClass::Gross));

    // Pixel (1, 1) of triangle 0 drawn with id 1: wrong owner; 0 missing there (deep
    // inside it: gross), 1 extra (far from triangle 1: gross).
    let mut swapped = Coverage::new(32, 8);
    for (x, y, ids) in render(&s.primitives(), &target, Model::ExactSnapped).unwrap().iter() {
        let id = if (x, y) == (1, 1) { 1 } else { ids[0] };
        swapped.cover(x, y, id);
    }
    for format in [Format::Ids, Format::Json] {
        let r = report(&s, &swapped, format, Model::ExactSnapped);
        assert_eq!(r.pixels.len(), 1, "{format:?}");
        let p = &r.pixels[0];
        assert_eq!((p.x, p.y, p.kind), (1, 1, PixelKind::WrongOwner));
        let found: Vec<(Option<u32>, Relation, ReasonClass)> = p
            .findings
            .iter()
            .map(|f| (f.id, f.relation, f.reason.class()))
            .collect();
        assert_eq!(
            found,
            [
                (Some(0), Relation::Missing, ReasonClass::Gross),
                (Some(1), Relation::Extra, ReasonClass::Gross)
            ],
            "{format:?}"
        );
    }
    // An id the scene does not have.
    let mut stranger = render(&s.primitives(), &target, Model::ExactSnapped).unwrap();
    stranger.cover(20, 7, 9);
    let r = report(&s, &stranger, Format::Ids, Model::ExactSnapped);
    let f = &r.pixels[0].findings[0];
    assert_eq!(
        (f.id, f.primitive.as_deref(), f.reason.class()),
        (Some(9), None, ReasonClass::Gross)
    );
    assert!(f.evidence.contains("not a primitive of the scene"), "{}", f.evidence);
}

/// Shared edges drawn by both neighbours: a double cover in JSON (ids listed), in an ids
/// PNG (alpha 254 where the oracle has one owner), explained as a tie on the shared edge.
#[test]
fn all_inclusive_edges_are_double_covers_and_ties() {
    // Two triangles sharing the diagonal x + y = 8 on which the samples (i + 1/2, j + 1/2)
    // with i + j = 7 lie.
    let s = scene(
        r#"{"width": 8, "height": 8, "triangles": [{"v": [[0, 0], [8, 0], [0, 8]]}, {"v": [[8, 0], [8, 8], [0, 8]]}]}"#,
    );
    let target = s.target().unwrap();
    let ours = render(&s.primitives(), &target, Model::ExactSnapped).unwrap();
    let mut theirs = ours.clone();
    for i in 0..8 {
        let owner = ours.owners(i, 7 - i)[0];
        theirs.cover(i, 7 - i, 1 - owner);
    }
    for format in [Format::Ids, Format::Json] {
        let r = report(&s, &theirs, format, Model::ExactSnapped);
        assert_eq!(r.pixels.len(), 8, "{format:?}");
        for p in &r.pixels {
            assert_eq!(p.kind, PixelKind::Double, "{format:?}");
            assert_eq!(p.findings.len(), 1);
            let f = &p.findings[0];
            let Reason::Tie { rules, .. } = &f.reason else {
                panic!("{f:?}")
            };
            assert!(rules.contains(&AnyTieRule::AllInclusive), "{rules:?}");
            // JSON names the second owner; an ids PNG does not, and the best explanation
            // is the neighbour.
            assert_eq!(f.guessed, format == Format::Ids);
            assert_eq!(f.id, Some(1 - ours.owners(p.x, p.y)[0]));
        }
    }
}

#[test]
fn lines_polygons_and_windows_have_their_classes() {
    // Bresenham with the other tie: the line (0,0) -> (4,1) has a tie at x = 2.
    let s = scene(
        r#"{"width": 6, "height": 3, "lines": [{"from": [0, 0], "to": [4, 1], "rule": "bresenham", "tie": "stay"}]}"#,
    );
    let theirs = rendered_with(&s, Model::ExactSnapped, |s| {
        s.lines[0].rule = rasterproof::line::LineRule::Bresenham(rasterproof::line::BresenhamTie::Step);
    });
    let r = report(&s, &theirs, Format::Json, Model::ExactSnapped);
    assert!(!r.identical());
    for f in r.pixels.iter().flat_map(|p| &p.findings) {
        let Reason::LineRule { rules } = &f.reason else {
            panic!("{f:?}")
        };
        assert!(rules.contains(&"bresenham (step)"), "{rules:?}");
    }

    // A pentagram filled even-odd where the scene says nonzero: the centre differs, by the
    // fill rule, with winding number ±2.
    let star = include_str!("../examples/scenes/polygons.json");
    let s = scene(star);
    let theirs = rendered_with(&s, Model::ExactSnapped, |s| {
        s.polygons[0].fill_rule = rasterproof::geom::FillRule::EvenOdd
    });
    let r = report(&s, &theirs, Format::Json, Model::ExactSnapped);
    assert!(!r.identical());
    for f in r.pixels.iter().flat_map(|p| &p.findings) {
        let Reason::FillRule { winding, fill_rule } = &f.reason else {
            panic!("{f:?}")
        };
        assert_eq!((winding.abs(), *fill_rule), (2, rasterproof::geom::FillRule::EvenOdd));
    }

    // A window they ignored: every extra pixel is the clip class.
    let s = scene(
        r#"{"width": 8, "height": 8, "triangles": [{"v": [[0, 0], [8, 0], [0, 8]]}], "clip": {"rect": [0, 0, 3, 8]}}"#,
    );
    let theirs = rendered_with(&s, Model::ExactSnapped, |s| s.clip = None);
    let r = report(&s, &theirs, Format::Mask, Model::ExactSnapped);
    assert!(!r.identical());
    for f in r.pixels.iter().flat_map(|p| &p.findings) {
        assert_eq!(f.reason, Reason::Clip { unclipped_covers: true }, "{f:?}");
    }
}

/// D3D11's diamond test area holds its bottom corner, not its top one (§3.4.3); a y-up
/// window (GL's, as llvmpipe draws) mirrors that. Derived by hand on a 1x1 canvas, pixel
/// (0, 0), diamond |x - 1/2| + |y - 1/2| < 1/2 with corners (1/2, 0) top, (1/2, 1) bottom:
/// - (-13/2, -5) -> (4, 5/2) has slope 7.5 / 10.5 = 5/7 and y = -5 + (5/7)(7) = 0 at
///   x = 1/2: it touches the top corner only (|slope| < 1), so the oracle leaves the pixel
///   out and the mirrored rule takes it;
/// - (-13/2, -4) -> (4, 7/2): y = 1 at x = 1/2, the bottom corner: the oracle takes the
///   pixel, the mirrored rule leaves it out.
#[test]
fn diamond_corners_mirrored_in_y_are_a_line_rule() {
    use rasterproof::oracle::reason::DIAMOND_MIRRORED;
    for (line, oracle_covers) in [
        ("[-6.5, -5], \"to\": [4, 2.5]", false),
        ("[-6.5, -4], \"to\": [4, 3.5]", true),
    ] {
        let s = scene(&format!(
            r#"{{"width": 1, "height": 1, "preset": "gl", "lines": [{{"from": {line}, "rule": "diamond"}}]}}"#
        ));
        let ours = render(&s.primitives(), &s.target().unwrap(), Model::ExactSnapped).unwrap();
        assert_eq!(ours.covered_pixels() == 1, oracle_covers, "{line}");
        let mut theirs = Coverage::new(1, 1);
        if !oracle_covers {
            theirs.cover(0, 0, 0);
        }
        let r = report(&s, &theirs, Format::Ids, Model::ExactSnapped);
        let findings: Vec<_> = r.pixels.iter().flat_map(|p| &p.findings).collect();
        assert_eq!(findings.len(), 1, "{line}");
        let Reason::LineRule { rules } = &findings[0].reason else {
            panic!("{line}: {:?}", findings[0])
        };
        assert!(rules.contains(&DIAMOND_MIRRORED), "{line}: {rules:?}");
    }
}

/// Float models: on tie-heavy meshes float32-naive's differences (double covers and
/// extra pixels on shared edges) are all ties; far from the origin on a fine grid
/// float32's are all within a pixel of an edge. None is gross, and there are some.
#[test]
fn float_differences_are_classified_and_never_gross() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
    use rasterproof::strategy::delaunay_mesh;
    let far = i64::from(rasterproof::convention::MAX_CANVAS) - 48;
    // The float teeth tests' families and seeds (tests/float_teeth.rs).
    let cases = [
        (
            Model::Float32Naive,
            24,
            tie_heavy_mesh(24, 16).boxed(),
            Model::ExactPlain,
            1,
            12,
        ),
        (
            Model::Float32,
            16384,
            delaunay_mesh([far, far], 48, 16, 32).boxed(),
            Model::Exact,
            2,
            48,
        ),
    ];
    for (model, side, strategy, oracle, seed, n) in cases {
        let mut runner =
            TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]));
        let mut found = std::collections::BTreeMap::new();
        for _ in 0..n {
            let mesh = strategy.new_tree(&mut runner).unwrap().current();
            let s = Scene::new(side, side, mesh.triangles);
            let theirs = render(&s.primitives(), &s.target().unwrap(), model).unwrap();
            let r = report(&s, &theirs, Format::Json, oracle);
            for f in r.pixels.iter().flat_map(|p| &p.findings) {
                assert_ne!(f.reason.class(), ReasonClass::Gross, "{model}: {f:?}");
                *found.entry(f.reason.class()).or_insert(0) += 1;
            }
        }
        println!("{model} against {oracle}: findings by class {found:?}");
        assert!(!found.is_empty(), "{model}: the workload has no teeth");
        if model == Model::Float32Naive {
            assert_eq!(found.keys().copied().collect::<Vec<_>>(), [ReasonClass::Tie]);
        }
    }
}

/// What `PreparedScene::shapes` returns is what the model draws: each shape rendered by
/// the plain oracles equals the model's coverage.
#[test]
fn shapes_are_what_the_exact_models_draw() {
    for text in [
        include_str!("../examples/scenes/polygons.json"),
        include_str!("../examples/scenes/lines.json"),
        include_str!("../examples/scenes/seed003.json"),
        r#"{"width": 8, "height": 8, "triangles": [{"v": [[0, 0], [8, 0], ["0.3", 8]]}], "clip": {"rect": [0, 0, 3, 8]},
            "lines": [{"from": [0, 7], "to": [7, 7]}, {"from": ["0.5", "1.25"], "to": ["7.5", "3.5"], "rule": "diamond"}]}"#,
    ] {
        let s = scene(text);
        let target = s.target().unwrap();
        for model in [Model::Exact, Model::ExactSnapped] {
            let prepared = prepare(&s.primitives(), &target, model).unwrap();
            let mut drawn = Coverage::new(target.width, target.height);
            for (k, shape) in prepared.shapes().unwrap().iter().enumerate() {
                let id = u32::try_from(k).unwrap();
                let mut one = Primitives::default();
                match shape {
                    Shape::Triangle(t) => one.triangles.push(t.into()),
                    Shape::Polygon(p) => one.polygons.push(p.clone()),
                    Shape::Bresenham { from, to, tie } => one.lines.push(rasterproof::line::Line {
                        from: rasterproof::geom::Point::from_ints(from[0], from[1]),
                        to: rasterproof::geom::Point::from_ints(to[0], to[1]),
                        rule: rasterproof::line::LineRule::Bresenham(*tie),
                    }),
                    Shape::Diamond { from, to } => one.lines.push(rasterproof::line::Line {
                        from: from.clone(),
                        to: to.clone(),
                        rule: rasterproof::line::LineRule::Diamond,
                    }),
                }
                // Lines keep their window (the pixels whose samples are in it).
                if matches!(shape, Shape::Bresenham { .. } | Shape::Diamond { .. }) {
                    one.clip = s.clip.clone();
                }
                for (x, y, ids) in render(&one, &target, Model::ExactPlain).unwrap().iter() {
                    for _ in ids {
                        drawn.cover(x, y, id);
                    }
                }
            }
            assert_eq!(drawn, prepared.coverage(&target), "{model}: {text}");
        }
    }
    assert!(prepare(
        &scene(HALF_PIXEL_SQUARES).primitives(),
        &scene(HALF_PIXEL_SQUARES).target().unwrap(),
        Model::Fixed
    )
    .unwrap()
    .shapes()
    .is_none());
}

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: 48,
        failure_persistence: Some(Box::new(proptest::test_runner::FileFailurePersistence::Direct(
            "proptest-regressions/oracle.txt",
        ))),
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config())]

    /// Any scene compared with the exact models' own output, in every format, is
    /// identical; and with the other tie rule's output, every difference is a tie.
    #[test]
    fn own_output_is_identical_and_the_other_rule_is_ties(
        ts in prop::collection::vec(any_triangle(12), 1..4),
        mesh in tie_heavy_mesh(12, 12),
        lines in prop::collection::vec(pixel_line(12, 2), 0..3),
        diamonds in prop::collection::vec(diamond_line(12), 0..2),
        polys in prop::collection::vec(any_polygon(12, 6), 0..2),
        preset in prop::sample::select(vec![Preset::D3d11, Preset::Gl, Preset::Cts]),
    ) {
        let mut s = Scene::new(12, 12, ts.into_iter().chain(mesh.triangles).collect());
        s.preset = preset;
        s.lines = lines.into_iter().map(|(a, b)| rasterproof::line::Line {
            from: rasterproof::geom::Point::from_ints(a[0], a[1]),
            to: rasterproof::geom::Point::from_ints(b[0], b[1]),
            rule: rasterproof::line::LineRule::Bresenham(rasterproof::line::BresenhamTie::Stay),
        }).chain(diamonds).collect();
        s.polygons = polys;
        let target = s.target().unwrap();
        for model in [Model::Exact, Model::ExactSnapped] {
            let ours = render(&s.primitives(), &target, model).unwrap();
            for format in [Format::Mask, Format::Ids, Format::Json] {
                prop_assert!(report(&s, &ours, format, model).identical());
            }
        }
        let other = if preset == Preset::Gl { TieRule::TopLeft } else { TieRule::BottomLeft };
        let theirs = rendered_with(&s, Model::ExactSnapped, |s| s.overrides.tie_rule = Some(other));
        let r = report(&s, &theirs, Format::Json, Model::ExactSnapped);
        for f in r.pixels.iter().flat_map(|p| &p.findings) {
            let Reason::Tie { rules, .. } = &f.reason else {
                return Err(TestCaseError::fail(format!("{f:?}")));
            };
            prop_assert!(rules.contains(&AnyTieRule::from(other)), "{:?}", rules);
        }
    }
}

// ---- the command line ----

fn write(dir: &tempdir::Dir, name: &str, bytes: &[u8]) -> std::path::PathBuf {
    let p = dir.path().join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

fn run(args: &[&std::ffi::OsStr]) -> (i32, String, String) {
    let out = bin().args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

macro_rules! os {
    ($($a:expr),* $(,)?) => { [$(std::ffi::OsStr::new($a)),*] };
}

#[test]
fn compare_command_exit_codes_outputs_and_bad_input() {
    let dir = tempdir::Dir::new("oracle-cli");
    let scene = write(&dir, "s.json", HALF_PIXEL_SQUARES.as_bytes());
    let ids = dir.path().join("ours.png");
    let gl = dir.path().join("gl.png");
    let json = dir.path().join("ours.json");
    let sp = scene.to_str().unwrap();
    assert!(bin()
        .args(["render", sp, "--ids-out", ids.to_str().unwrap()])
        .output()
        .unwrap()
        .status
        .success());
    assert!(bin()
        .args(["render", sp, "--preset", "gl", "--ids-out", gl.to_str().unwrap()])
        .output()
        .unwrap()
        .status
        .success());
    let out = bin().args(["render", sp, "--format", "json"]).output().unwrap();
    std::fs::write(&json, out.stdout).unwrap();

    let (code, stdout, _) = run(&os!("compare", sp, ids.to_str().unwrap()));
    assert_eq!(code, 0, "{stdout}");
    assert!(stdout.contains("identical"), "{stdout}");
    let (code, stdout, _) = run(&os!("compare", sp, json.to_str().unwrap()));
    assert_eq!(code, 0, "{stdout}");

    let diff = dir.path().join("diff.png");
    let (code, stdout, stderr) = run(&os!(
        "compare",
        sp,
        gl.to_str().unwrap(),
        "--diff-out",
        diff.to_str().unwrap(),
        "--limit",
        "1"
    ));
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stdout.contains("16 differ") && stdout.contains("tie rule bottom-left"),
        "{stdout}"
    );
    assert!(stdout.contains("the first 1 of 16"), "{stdout}");
    let picture = image::open(&diff).unwrap().to_rgb8();
    assert_eq!(picture.width() % 8, 0);
    let k = picture.width() / 8;
    assert!(k > 1, "a small canvas is scaled up");
    // Pixel (0, 0) is missing (red), (0, 1) matched (grey), (0, 5) empty (black).
    assert_eq!(picture.get_pixel(0, 0).0, PixelKind::Missing.colour());
    assert_eq!(picture.get_pixel(0, k).0, [128, 128, 128]);
    assert_eq!(picture.get_pixel(0, 5 * k).0, [0, 0, 0]);
    let legend = std::fs::read_to_string(dir.path().join("diff.legend.txt")).unwrap();
    assert!(
        legend.contains("#e62828  missing") && legend.contains("16x16 picture pixels") == (k == 16),
        "{legend}"
    );

    let (code, stdout, _) = run(&os!("compare", sp, gl.to_str().unwrap(), "--format", "json"));
    assert_eq!(code, 1);
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(v["version"], 1);
    assert_eq!(v["differing"], 16);
    assert_eq!(v["pixels"].as_array().unwrap().len(), 16);
    assert_eq!(v["pixels"][0]["findings"][0]["class"], "tie");
    assert_eq!(v["pixels"][0]["findings"][0]["reason"]["edges"][0]["side"], "top");

    // Bad input: exit 2, one line naming the file, no diff picture written.
    let wrong = write(&dir, "wrong.json", br#"{"width": 4, "height": 6, "pixels": []}"#);
    let unsorted = write(
        &dir,
        "unsorted.json",
        br#"{"width": 8, "height": 6, "pixels": [[1,1,[0]],[0,1,[0]]]}"#,
    );
    let off = write(&dir, "off.json", br#"{"width": 8, "height": 6, "pixels": [[8,1,[0]]]}"#);
    let garbage = write(&dir, "garbage.png", b"not a png at all");
    let grey16 = dir.path().join("grey16.png");
    image::DynamicImage::ImageLuma16(image::ImageBuffer::new(8, 6))
        .save(&grey16)
        .unwrap();
    let missing = dir.path().join("nothing-here.png");
    let fresh = dir.path().join("fresh.png");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec![wrong.to_str().unwrap()], "4x6 but the scene's canvas is 8x6"),
        (vec![unsorted.to_str().unwrap()], "out of order"),
        (vec![off.to_str().unwrap()], "x is not a pixel"),
        (vec![garbage.to_str().unwrap()], "not a PNG file"),
        (vec![grey16.to_str().unwrap()], "an ids PNG must be 8-bit"),
        (vec![missing.to_str().unwrap()], "cannot read"),
        (vec![ids.to_str().unwrap(), "--as", "bmp"], "--as: unknown format"),
        (
            vec![ids.to_str().unwrap(), "--model", "fixed"],
            "the oracle must be an exact model",
        ),
        (vec![ids.to_str().unwrap(), "--background", "1,2"], "--background"),
        (
            vec![ids.to_str().unwrap(), "--rounding", "up"],
            "--rounding: unknown rounding",
        ),
    ];
    for (extra, message) in cases {
        let mut args = vec!["compare", sp];
        args.extend(extra.iter().copied());
        args.extend(["--diff-out", fresh.to_str().unwrap()]);
        let out = bin().args(&args).output().unwrap();
        let stderr = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.starts_with("error: ") && stderr.contains(message),
            "{args:?}: {stderr}"
        );
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(!fresh.exists(), "{args:?} wrote a picture");
    }
    // A mask PNG: grey 16-bit is read (all black: nothing covered, every pixel missing).
    let (code, stdout, stderr) = run(&os!("compare", sp, grey16.to_str().unwrap(), "--as", "mask"));
    assert_eq!(code, 1, "{stderr}");
    assert!(stdout.contains("theirs 0;"), "{stdout}");
}

#[test]
fn explain_command() {
    let dir = tempdir::Dir::new("oracle-explain");
    let scene = write(&dir, "s.json", HALF_PIXEL_SQUARES.as_bytes());
    let sp = scene.to_str().unwrap();
    let (code, stdout, _) = run(&os!("explain", sp, "3,4"));
    assert_eq!(code, 0);
    assert!(stdout.contains("sample (7/2, 9/2)"), "{stdout}");
    assert!(stdout.contains("E=0 (exclusive)"), "{stdout}");
    assert!(stdout.contains("float32-naive   covered by 1"), "{stdout}");
    let (code, stdout, _) = run(&os!("explain", sp, "3,4", "--preset", "gl", "--format", "json"));
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let fixed = v["models"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["model"] == "fixed")
        .unwrap()
        .clone();
    assert_eq!(
        fixed["owners"],
        serde_json::json!([1]),
        "under gl the bottom edge owns its samples"
    );
    for (pixel, message) in [
        ("9,0", "off the 8x6 canvas"),
        ("a,b", "is not X,Y"),
        ("1", "is not X,Y"),
    ] {
        let (code, _, stderr) = run(&os!("explain", sp, pixel));
        assert_eq!(code, 2);
        assert!(stderr.contains(message), "{stderr}");
    }
}

// ---- the convention fit ----

/// The scene mirrored left to right about x = W/2 (pixel i's sample i + 1/2 goes to
/// pixel W - 1 - i's). Exact: `W - x` is a rational like `x`, so the mirror of the scene as
/// written is rendered unsnapped (`Model::Exact`), as the planned engine under test is.
fn mirrored(s: &Scene) -> Scene {
    let mut m = s.clone();
    let w = num_rational::BigRational::from_integer(s.width.into());
    for t in &mut m.triangles {
        t.triangle = rasterproof::geom::Triangle {
            v: t.triangle
                .to_triangle()
                .v
                .map(|p| rasterproof::geom::Point::new(&w - &p.x, p.y)),
        }
        .into();
    }
    m
}

/// Top-right and bottom-right, derived independently of the planned engine: the mirror
/// image of the scene under top-left / bottom-left, mirrored back (moving the sample left
/// by ε is moving the mirrored sample right by ε).
fn mirror_rule_image(s: &Scene, rule: TieRule) -> Coverage {
    let mut conv = s.convention();
    conv.tie_rule = rule;
    let m = mirrored(s);
    let target = rasterproof::convention::Target::new(s.width, s.height, conv).unwrap();
    let image = render(&m.primitives(), &target, Model::Exact).unwrap();
    let mut back = Coverage::new(s.width, s.height);
    for (x, y, ids) in image.iter() {
        for &id in ids {
            back.cover(s.width - 1 - x, y, id);
        }
    }
    back
}

proptest! {
    #![proptest_config(config())]

    /// The planned engine under every tie rule equals the plain exact reading of that rule
    /// (`evidence::triangle_at`, sample by sample); the right-hand rules equal the mirror
    /// images of the left-hand ones.
    #[test]
    fn planned_triangles_follow_every_tie_rule(
        ts in prop::collection::vec(rasterproof::strategy::tie_heavy_triangle(10), 1..4),
        corner in any::<bool>(),
    ) {
        use rasterproof::oracle::evidence::triangle_at;
        use rasterproof::tri::planned::PlannedTriangle;
        let mut s = Scene::new(10, 10, ts);
        if corner {
            s.overrides.pixel_centre = Some(rasterproof::convention::PixelCentre::Corner);
        }
        let target = s.target().unwrap();
        for rule in AnyTieRule::ALL {
            let mut planned = Coverage::new(10, 10);
            let mut plain = Coverage::new(10, 10);
            for (k, t) in s.triangles().iter().enumerate() {
                let id = u32::try_from(k).unwrap();
                if let Some(p) = PlannedTriangle::with_rule(t, &target, rule) {
                    p.rasterize(id, &mut planned);
                }
                for y in 0..10 {
                    for x in 0..10 {
                        let sample = rasterproof::raster::sample_exact(x, y, &target);
                        if triangle_at(t, &sample, rule).is_some_and(|a| a.inside) {
                            plain.cover(x, y, id);
                        }
                    }
                }
            }
            prop_assert_eq!(&planned, &plain, "{}", rule.name());
            if !corner {
                let mirror = match rule {
                    AnyTieRule::TopRight => Some(TieRule::TopLeft),
                    AnyTieRule::BottomRight => Some(TieRule::BottomLeft),
                    _ => None,
                };
                if let Some(left) = mirror {
                    prop_assert_eq!(&planned, &mirror_rule_image(&s, left), "{}", rule.name());
                }
            }
        }
    }
}

#[test]
fn fit_names_the_convention_of_a_renderer_made_to_follow_it() {
    // A tie-heavy mesh on half-pixel vertices, so that the tie rule shows.
    let s = scene(
        r#"{"width": 12, "height": 10, "triangles": [
        {"v": [[0.5, 0.5], [6.5, 0.5], [0.5, 6.5]]}, {"v": [[6.5, 0.5], [6.5, 6.5], [0.5, 6.5]]},
        {"v": [[6.5, 0.5], [11.5, 3.5], [6.5, 6.5]]}, {"v": [[0.5, 6.5], [11.5, 9.5], [6.5, 6.5]]}]}"#,
    );
    let target = s.target().unwrap();
    let fit = |theirs: &Coverage| {
        rasterproof::oracle::fit(&s.primitives(), &target, &Theirs::from_coverage(theirs, Format::Ids)).unwrap()
    };
    // Under GL: every exact fit is a bottom rule, bottom-left at 8 bits nearest-even among them.
    let gl = rendered_with(&s, Model::ExactSnapped, |s| s.preset = Preset::Gl);
    let found = fit(&gl);
    assert!(
        found
            .exact
            .iter()
            .all(|c| matches!(c.tie_rule, AnyTieRule::BottomLeft | AnyTieRule::BottomRight)),
        "{}",
        found.fit_text()
    );
    assert!(found.exact.iter().any(|c| c.tie_rule == AnyTieRule::BottomLeft
        && c.snapping.bits == Some(8)
        && c.snapping.rounding == Rounding::NearestEven
        && c.pixel_centre == rasterproof::convention::PixelCentre::Half));
    // Top-right, from the mirror construction: top-right is found, top-left is not.
    let tr = mirror_rule_image(&s, TieRule::TopLeft);
    let found = fit(&tr);
    assert!(
        found.exact.iter().any(|c| c.tie_rule == AnyTieRule::TopRight),
        "{}",
        found.fit_text()
    );
    assert!(
        found.exact.iter().all(|c| c.tie_rule != AnyTieRule::TopLeft),
        "{}",
        found.fit_text()
    );
    // Their image with one stray pixel: nothing fits; the closest is one pixel away.
    let mut stray = render(&s.primitives(), &target, Model::ExactSnapped).unwrap();
    stray.cover(11, 0, 0);
    let found = fit(&stray);
    assert!(found.exact.is_empty());
    assert_eq!(found.closest[0].total(), 1, "{}", found.fit_text());
    assert_eq!(found.closest[0].candidate.tie_rule, AnyTieRule::TopLeft);
    assert!(found.fit_text().contains("no convention explains their image exactly"));
}

/// When no convention is exact and the closest tie, the fit keeps every one at each of the
/// closest counts and lists them together, part by part: a triangle whose edges pass
/// through no sample (every tie rule draws it alike) with one stray pixel is one pixel off
/// under every tie rule at each snapping, and the image cannot tell the rules apart.
#[test]
fn fit_closest_ties_are_listed_together() {
    let s = parse_scene(
        r#"{"width": 8, "height": 8, "triangles": [{"v": [[0.1, 0.2], [7.3, 0.4], [0.3, 6.9]]}]}"#,
        "s.json",
    )
    .unwrap();
    let target = s.target().unwrap();
    let mut stray = render(&s.primitives(), &target, Model::ExactSnapped).unwrap();
    stray.cover(7, 7, 0);
    let found =
        rasterproof::oracle::fit(&s.primitives(), &target, &Theirs::from_coverage(&stray, Format::Ids)).unwrap();
    assert!(found.exact.is_empty());
    let best: Vec<_> = found.closest.iter().filter(|f| f.total() == 1).collect();
    // All six rules, at every snapping that leaves the image as it is: more than the five a
    // list cut at five would keep.
    assert!(
        best.len() > rasterproof::oracle::compare::fit::CLOSEST,
        "{}",
        found.fit_text()
    );
    let rules: std::collections::BTreeSet<_> = best.iter().map(|f| f.candidate.tie_rule.name()).collect();
    assert_eq!(rules.len(), 6);
    let text = found.fit_text();
    assert!(text.contains("1 differing pixel (1 extra), "), "{text}");
    assert!(
        text.contains("tie rule: not observable here (no sample lies on an edge: the six rules draw one image)"),
        "{text}"
    );
    // The one-pixel answer is not repeated per rule: one entry where the rules draw one
    // image, one where they do not.
    assert!(text.matches("1 differing pixel").count() <= 2, "{text}");
}

#[test]
fn fit_command() {
    let dir = tempdir::Dir::new("oracle-fit");
    let scene = write(&dir, "s.json", HALF_PIXEL_SQUARES.as_bytes());
    let sp = scene.to_str().unwrap();
    let gl = dir.path().join("gl.png");
    assert!(bin()
        .args(["render", sp, "--preset", "gl", "--ids-out", gl.to_str().unwrap()])
        .output()
        .unwrap()
        .status
        .success());
    let (code, stdout, stderr) = run(&os!("compare", sp, gl.to_str().unwrap(), "--fit"));
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("tie rule bottom-left, pixel centre 0.5: 1..=16 bits (any rounding); unsnapped"),
        "{stdout}"
    );
    let (code, stdout, _) = run(&os!("compare", sp, gl.to_str().unwrap(), "--fit", "--format", "json"));
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(v["searched"], 1032);
    assert!(v["exact"]
        .as_array()
        .unwrap()
        .iter()
        .all(|c| c["tie_rule"].as_str().unwrap().starts_with("bottom")));
    let clip_space = write(
        &dir,
        "cs.json",
        br#"{"width": 8, "height": 6, "clip_space_triangles": [{"v": [[0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, 1]]}]}"#,
    );
    let (code, _, stderr) = run(&os!(
        "compare",
        clip_space.to_str().unwrap(),
        gl.to_str().unwrap(),
        "--fit"
    ));
    assert_eq!(code, 2);
    assert!(
        stderr.contains("--fit does not search scenes with clip_space_triangles"),
        "{stderr}"
    );
}

// ---- renderers with known defects, each classified as what it is ----

use crate::rng;

/// Findings by class name (a pixel with two primitives' findings counts twice).
fn class_counts(r: &CompareReport) -> std::collections::BTreeMap<&'static str, usize> {
    let mut out = std::collections::BTreeMap::new();
    for f in r.pixels.iter().flat_map(|p| &p.findings) {
        *out.entry(f.reason.class().name()).or_insert(0) += 1;
    }
    out
}

/// `n` non-degenerate triangles with vertices `k / denom` inside `[lo, hi]` on each axis,
/// drawn by the seeded generator, on a `width x height` canvas (the `d3d11` preset: 8
/// subpixel bits, top-left, centre 1/2).
fn random_scene(seed: u64, [width, height]: [u32; 2], n: usize, lo: [i64; 2], hi: [i64; 2], denom: i64) -> Scene {
    use rasterproof::geom::{Point, Triangle};
    let mut g = rng::Rng(seed);
    let mut ts = Vec::new();
    while ts.len() < n {
        let v: Vec<[i64; 2]> = (0..3)
            .map(|_| {
                [
                    g.range(lo[0] * denom, hi[0] * denom),
                    g.range(lo[1] * denom, hi[1] * denom),
                ]
            })
            .collect();
        let area = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[2][0] - v[0][0]) * (v[1][1] - v[0][1]);
        if area.abs() < 40 * denom * denom {
            continue;
        }
        let p = |a: [i64; 2]| {
            let q = |c: i64| num_rational::BigRational::new(c.into(), denom.into());
            Point::new(q(a[0]), q(a[1]))
        };
        ts.push(Triangle::new(p(v[0]), p(v[1]), p(v[2])));
    }
    Scene::new(width, height, ts)
}

/// A renderer that decides each pixel of each triangle's box (grown by 2 px) with
/// `covers(triangle, x, y)`, drawing triangle k with id k.
fn drawn_per_pixel(s: &Scene, covers: impl Fn(&rasterproof::geom::Triangle, u32, u32) -> bool) -> Coverage {
    use num_traits::ToPrimitive;
    let mut out = Coverage::new(s.width, s.height);
    for (k, t) in s.triangles().iter().enumerate() {
        let axis = |a: usize, side: u32| {
            let vs: Vec<f64> =
                t.v.iter()
                    .map(|p| if a == 0 { &p.x } else { &p.y }.to_f64().unwrap())
                    .collect();
            let lo = vs.iter().copied().fold(f64::INFINITY, f64::min) - 2.0;
            let hi = vs.iter().copied().fold(f64::NEG_INFINITY, f64::max) + 2.0;
            let c = |v: f64| v.floor().clamp(0.0, f64::from(side - 1)) as u32;
            c(lo)..=c(hi)
        };
        for y in axis(1, s.height) {
            for x in axis(0, s.width) {
                if covers(t, x, y) {
                    out.cover(x, y, u32::try_from(k).unwrap());
                }
            }
        }
    }
    out
}

/// Exact coverage of `t` at the sample `(x + ox, y + oy)` under `rule`.
fn exact_at(t: &rasterproof::geom::Triangle, x: u32, y: u32, [ox, oy]: [i64; 2], rule: AnyTieRule) -> bool {
    let q = |v: u32, o: i64| num_rational::BigRational::new((2 * i64::from(v) + o).into(), 2.into());
    let p = rasterproof::geom::Point::new(q(x, ox), q(y, oy));
    rasterproof::oracle::evidence::triangle_at(t, &p, rule).is_some_and(|a| a.inside)
}

/// Edge functions in f32, in the `A x + B y + C` form with `C = x0 y1 - x1 y0` (the
/// vertices rounded to f32 once), no snapping, no tie rule (`E > 0` on every edge).
fn f32_edge_functions(t: &rasterproof::geom::Triangle, x: u32, y: u32) -> bool {
    use num_traits::ToPrimitive;
    let v: Vec<[f32; 2]> =
        t.v.iter()
            .map(|p| [p.x.to_f32().unwrap(), p.y.to_f32().unwrap()])
            .collect();
    let (px, py) = (x as f32 + 0.5, y as f32 + 0.5);
    let e = |a: [f32; 2], b: [f32; 2]| (a[1] - b[1]) * px + (b[0] - a[0]) * py + (a[0] * b[1] - b[0] * a[1]);
    let es = [e(v[0], v[1]), e(v[1], v[2]), e(v[2], v[0])];
    es.iter().all(|&e| e > 0.0) || es.iter().all(|&e| e < 0.0)
}

/// Vertices snapped to 4 subpixel bits (nearest, ties up), then decided exactly at the
/// pixel centre under top-left.
fn snapped_to_4_bits(t: &rasterproof::geom::Triangle, x: u32, y: u32) -> bool {
    use num_rational::BigRational;
    let snap = |v: &BigRational| {
        let sixteen = BigRational::from_integer(16.into());
        ((v * &sixteen) + BigRational::new(1.into(), 2.into())).floor() / sixteen
    };
    let s = rasterproof::geom::Triangle::new(
        rasterproof::geom::Point::new(snap(&t.v[0].x), snap(&t.v[0].y)),
        rasterproof::geom::Point::new(snap(&t.v[1].x), snap(&t.v[1].y)),
        rasterproof::geom::Point::new(snap(&t.v[2].x), snap(&t.v[2].y)),
    );
    exact_at(&s, x, y, [1, 1], AnyTieRule::TopLeft)
}

/// A scanline renderer whose edges are walked in 16.16 fixed point: vertices rounded to
/// 2^-16, each edge's slope dx/dy truncated to 16.16, its x at the first row's sample
/// computed once and then stepped by the slope row by row; a row covers the samples in
/// `[left x, right x)` of the rows whose sample y lies in `[top y, bottom y)`.
fn walked_16_16(s: &Scene) -> Coverage {
    use num_rational::BigRational;
    let mut out = Coverage::new(s.width, s.height);
    let one = 1i64 << 16;
    let fx = |v: &BigRational| {
        (v * BigRational::from_integer(one.into()) + BigRational::new(1.into(), 2.into()))
            .floor()
            .to_integer()
            .try_into()
            .unwrap()
    };
    for (k, t) in s.triangles().iter().enumerate() {
        let v: Vec<[i64; 2]> = t.v.iter().map(|p| [fx(&p.x), fx(&p.y)]).collect();
        let ys = |j: i64| j * one + one / 2;
        let ymin = v.iter().map(|p| p[1]).min().unwrap();
        let ymax = v.iter().map(|p| p[1]).max().unwrap();
        // Per edge (not horizontal): its rows and its walked x on each.
        let mut edges: Vec<(i64, i64, Vec<i64>)> = Vec::new();
        for e in 0..3 {
            let (mut a, mut b) = (v[e], v[(e + 1) % 3]);
            if a[1] == b[1] {
                continue;
            }
            if a[1] > b[1] {
                std::mem::swap(&mut a, &mut b);
            }
            let slope = ((b[0] - a[0]) << 16) / (b[1] - a[1]);
            let first = (a[1] - one / 2 + one - 1).div_euclid(one); // first j with ys(j) >= a.y
            let last = (b[1] - one / 2 + one - 1).div_euclid(one) - 1; // last j with ys(j) < b.y
            let mut x = a[0] + (((ys(first) - a[1]) * slope) >> 16);
            let mut xs = Vec::new();
            for _ in first..=last {
                xs.push(x);
                x += slope;
            }
            edges.push((first, last, xs));
        }
        let top = (ymin - one / 2 + one - 1).div_euclid(one).max(0);
        let bottom = ((ymax - one / 2 + one - 1).div_euclid(one) - 1).min(i64::from(s.height) - 1);
        for j in top..=bottom {
            let xs: Vec<i64> = edges
                .iter()
                .filter(|(f, l, _)| (*f..=*l).contains(&j))
                .map(|(f, _, xs)| xs[usize::try_from(j - f).unwrap()])
                .collect();
            if xs.len() != 2 {
                continue;
            }
            let (l, r) = (xs[0].min(xs[1]), xs[0].max(xs[1]));
            for i in 0..i64::from(s.width) {
                let sx = i * one + one / 2;
                if l <= sx && sx < r {
                    out.cover(
                        u32::try_from(i).unwrap(),
                        u32::try_from(j).unwrap(),
                        u32::try_from(k).unwrap(),
                    );
                }
            }
        }
    }
    out
}

/// Five renderers of known, different defects, each compared on several scenes with the
/// model its author would choose, and each classified as what it is: the class counts
/// over all the scenes are asserted (a near-edge at a tiny exact distance must not be
/// named snapping or sample position, and a sample-position defect must not be named
/// snapping).
#[test]
fn defective_renderers_are_classified_as_what_they_are() {
    // f32 edge functions, no snapping, compared with `--model exact`: far from the
    // origin every difference is float error at a tiny distance from an edge.
    let mut f32_counts = std::collections::BTreeMap::new();
    for seed in 1..=6 {
        let s = random_scene(seed, [4096, 4096], 6, [3900, 3900], [4090, 4090], 1000);
        let r = report(&s, &drawn_per_pixel(&s, f32_edge_functions), Format::Json, Model::Exact);
        for (c, n) in class_counts(&r) {
            *f32_counts.entry(c).or_insert(0) += n;
        }
    }
    println!("f32 edge functions: {f32_counts:?}");
    assert_eq!(f32_counts, [("near-edge", 38)].into(), "{f32_counts:?}");

    // Sampling at the pixel corner (i, j): every difference is the sample position.
    let mut corner = std::collections::BTreeMap::new();
    for seed in 11..=14 {
        let s = random_scene(seed, [32, 32], 3, [-2, -2], [34, 34], 256);
        let theirs = drawn_per_pixel(&s, |t, x, y| exact_at(t, x, y, [0, 0], AnyTieRule::TopLeft));
        let r = report(&s, &theirs, Format::Json, Model::ExactSnapped);
        for (c, n) in class_counts(&r) {
            *corner.entry(c).or_insert(0) += n;
        }
    }
    println!("pixel corner: {corner:?}");
    assert_eq!(corner, [("sample-position", 281)].into(), "{corner:?}");

    // Snapping to 4 subpixel bits: every difference is snapping.
    let mut four = std::collections::BTreeMap::new();
    for seed in 21..=26 {
        let s = random_scene(seed, [32, 32], 6, [0, 0], [32, 32], 256);
        let r = report(
            &s,
            &drawn_per_pixel(&s, snapped_to_4_bits),
            Format::Json,
            Model::ExactSnapped,
        );
        for (c, n) in class_counts(&r) {
            *four.entry(c).or_insert(0) += n;
        }
        for f in r.pixels.iter().flat_map(|p| &p.findings) {
            if let Reason::Snapping { bits, roundings } = &f.reason {
                assert_eq!(*bits, Some(4), "{f:?}");
                assert!(roundings.contains(&Rounding::HalfAwayFromZero), "{f:?}");
            }
        }
    }
    println!("4 subpixel bits: {four:?}");
    assert_eq!(four, [("snapping", 24)].into(), "{four:?}");

    // Bottom-right ties on vertices at pixel centres: every difference is a tie.
    let mut ties = std::collections::BTreeMap::new();
    for seed in 31..=34 {
        let s = random_scene(seed, [24, 24], 4, [0, 0], [23, 23], 1);
        let s = {
            let mut m = s.clone();
            for t in &mut m.triangles {
                let half = num_rational::BigRational::new(1.into(), 2.into());
                t.triangle = rasterproof::geom::Triangle {
                    v: t.triangle
                        .to_triangle()
                        .v
                        .map(|p| rasterproof::geom::Point::new(p.x + &half, p.y + &half)),
                }
                .into();
            }
            m
        };
        let theirs = drawn_per_pixel(&s, |t, x, y| exact_at(t, x, y, [1, 1], AnyTieRule::BottomRight));
        let r = report(&s, &theirs, Format::Json, Model::ExactSnapped);
        for (c, n) in class_counts(&r) {
            *ties.entry(c).or_insert(0) += n;
        }
    }
    println!("bottom-right ties: {ties:?}");
    assert_eq!(ties, [("tie", 107)].into(), "{ties:?}");

    // A 16.16 edge walk compared with `--model exact`: its error grows along each edge
    // (the truncated slope, 2^-16 a row), a tiny distance from it: near-edge.
    let mut walk = std::collections::BTreeMap::new();
    for seed in 41..=43 {
        let s = random_scene(seed, [256, 2048], 2, [0, 0], [256, 2048], 256);
        let r = report(&s, &walked_16_16(&s), Format::Json, Model::Exact);
        for (c, n) in class_counts(&r) {
            *walk.entry(c).or_insert(0) += n;
        }
    }
    println!("16.16 edge walk: {walk:?}");
    assert_eq!(walk, [("near-edge", 34)].into(), "{walk:?}");
}

/// Every finding, whatever its class, carries the exact distance from the sample to the
/// primitive's nearest edge: in the text report with a decimal beside the fraction, in
/// JSON as the finding's `distance`.
#[test]
fn every_finding_prints_its_exact_distance() {
    // Ties: the samples lie on the edges, distance 0.
    let s = scene(HALF_PIXEL_SQUARES);
    let theirs = rendered_with(&s, Model::ExactSnapped, |s| s.preset = Preset::Gl);
    let r = report(&s, &theirs, Format::Json, Model::ExactSnapped);
    let text = r.to_text("s", "t", 100);
    assert_eq!(text.matches("nearest edge: 0 px").count(), 16, "{text}");
    // The pixel-corner renderer: sample-position, each with its distance.
    let s = random_scene(11, [32, 32], 3, [-2, -2], [34, 34], 256);
    let theirs = drawn_per_pixel(&s, |t, x, y| exact_at(t, x, y, [0, 0], AnyTieRule::TopLeft));
    let r = report(&s, &theirs, Format::Json, Model::ExactSnapped);
    let findings: usize = r.pixels.iter().map(|p| p.findings.len()).sum();
    assert!(findings > 0);
    let text = r.to_text("s", "t", usize::MAX);
    assert_eq!(text.matches("\n    nearest edge: ").count(), findings, "{text}");
    assert!(
        text.contains("sample-position: their answer is the exact answer at the sample (i, j)"),
        "{text}"
    );
    let v = r.to_json("s", "t");
    for f in v["pixels"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|p| p["findings"].as_array().unwrap())
    {
        assert_eq!(f["class"], "sample-position", "{f}");
        let offsets = f["reason"]["offsets"].as_array().unwrap();
        assert!(offsets.contains(&serde_json::json!([0, 0])), "{f}");
        let d = &f["distance"];
        assert!(
            d["squared"].is_string() && d["exact"].is_string() && d["approx"].is_number(),
            "{f}"
        );
        assert!(d["approx"].as_f64().unwrap() <= 1.0, "{f}");
    }
}

/// A renderer that draws nothing, against a 64x64 square of two triangles: all 4096
/// pixels differ (missing), and the comparison finds and counts every one of them by kind
/// but classifies only as many as it is told to: the first half of them in row order and
/// the rest spread evenly down the picture, each with its findings; the others none.
/// Default `compare` classifies at most `CLASSIFY_AT_MOST` of them. The text says how
/// many were classified, and the JSON marks each pixel.
#[test]
fn a_renderer_wrong_everywhere_is_counted_whole_and_classified_in_part() {
    use rasterproof::oracle::compare::{CompareOptions, CLASSIFY_AT_MOST};
    let scene = parse_scene(
        r#"{"width": 64, "height": 64, "triangles": [
            {"v": [[0, 0], [64, 0], [64, 64]]}, {"v": [[0, 0], [64, 64], [0, 64]]}]}"#,
        "square.json",
    )
    .unwrap();
    let target = scene.target().unwrap();
    let nothing = Theirs::from_coverage(&Coverage::new(64, 64), Format::Json);
    let r = compare(
        &scene.primitives(),
        &target,
        &nothing,
        &CompareOptions {
            model: Model::ExactSnapped,
            classify_at_most: Some(10),
            jobs: 1,
        },
    )
    .unwrap();
    assert_eq!(r.pixels.len(), 64 * 64);
    assert_eq!(r.pixels_by_kind().get(&PixelKind::Missing), Some(&4096));
    assert_eq!(r.classified(), 10);
    let classified: Vec<(u32, u32)> = r.pixels.iter().filter(|p| p.classified).map(|p| (p.x, p.y)).collect();
    // The first 5 in row order, then pixel 5 + floor(j * 4091 / 5) for j = 0..5: 5, 823,
    // 1641, 2459, 3277, i.e. (5, 0), (55, 12), (41, 25), (27, 38), (13, 51).
    assert_eq!(
        classified,
        vec![
            (0, 0),
            (1, 0),
            (2, 0),
            (3, 0),
            (4, 0),
            (5, 0),
            (55, 12),
            (41, 25),
            (27, 38),
            (13, 51)
        ]
    );
    assert!(r.pixels.iter().all(|p| p.classified != p.findings.is_empty()));
    let text = r.to_text("square.json", "nothing", 0);
    assert!(text.contains("classified: 10 of the 4096 differing pixels"), "{text}");
    let json = r.to_json("square.json", "nothing");
    assert_eq!(
        (json["differing"].as_u64(), json["classified"].as_u64()),
        (Some(4096), Some(10))
    );
    assert_eq!(json["unclassified_by_kind"]["missing"].as_u64(), Some(4086));
    let default = compare(&scene.primitives(), &target, &nothing, &Model::ExactSnapped.into()).unwrap();
    assert_eq!((default.pixels.len(), default.classified()), (4096, CLASSIFY_AT_MOST));
}

/// A renderer that samples at the pixel's corner (pixel centre 0) against the oracle at
/// the centre: every difference is the sample position (i, j), and the report says so at
/// its top, before the table (text and JSON). A renderer with top-right ties gets its
/// rule named the same way; the oracle against itself has no headline.
#[test]
fn one_convention_that_explains_every_difference_is_named_at_the_top() {
    use rasterproof::convention::{Convention, PixelCentre, Target};
    let scene = parse_scene(
        r#"{"width": 64, "height": 64, "triangles": [{"v": [[0.3, 0.2], [60.7, 5.1], [10.2, 50.9]]}]}"#,
        "t.json",
    )
    .unwrap();
    let target = scene.target().unwrap();
    let corner = Target {
        convention: Convention {
            pixel_centre: PixelCentre::Corner,
            ..target.convention
        },
        ..target
    };
    let theirs = Theirs::from_coverage(
        &render(&scene.primitives(), &corner, Model::ExactSnapped).unwrap(),
        Format::Json,
    );
    let r = compare(&scene.primitives(), &target, &theirs, &Model::ExactSnapped.into()).unwrap();
    assert!(!r.identical());
    let expected = "every classified difference is explained by one convention: the sample at (i, j)";
    assert_eq!(r.headline().as_deref(), Some(expected));
    assert!(
        r.to_text("t.json", "theirs", 0).lines().nth(2) == Some(expected),
        "{}",
        r.to_text("t.json", "theirs", 0)
    );
    assert_eq!(r.to_json("t.json", "theirs")["headline"].as_str(), Some(expected));
    let same = Theirs::from_coverage(
        &render(&scene.primitives(), &target, Model::ExactSnapped).unwrap(),
        Format::Json,
    );
    let r = compare(&scene.primitives(), &target, &same, &Model::ExactSnapped.into()).unwrap();
    assert_eq!(r.headline(), None);
    // Edges through pixel centres: the top, the left and the hypotenuse (a right edge).
    let ties = parse_scene(
        r#"{"width": 8, "height": 8, "triangles": [{"v": [[0.5, 0.5], [6.5, 0.5], [0.5, 6.5]]}]}"#,
        "ties.json",
    )
    .unwrap();
    let theirs = crate::hunt::top_right(&ties).unwrap();
    let r = compare(
        &ties.primitives(),
        &ties.target().unwrap(),
        &theirs,
        &Model::ExactSnapped.into(),
    )
    .unwrap();
    let h = r.headline().expect("one tie rule explains every difference");
    assert!(
        h.starts_with("every classified difference is explained by one convention: the tie rule ")
            && h.contains("top-right"),
        "{h}"
    );
}

/// A fixed-point renderer: vertices truncated to 1/64 px (6 bits, towards zero) and
/// bottom-right ties, compared under the `gl` preset (8 bits, nearest-even, bottom-left).
/// Its differences are of two classes, ties (on the half-pixel triangles) and snapping
/// (on the 1/1000 px ones): no one class explains them all, but the two parts together
/// do, and drawn under both at once the scene gives their answer at every differing
/// pixel, which the headline says.
#[test]
fn a_grid_and_a_tie_rule_together_are_one_headline() {
    let mut s = random_scene(11, [24, 24], 6, [0, 0], [24, 24], 2);
    s.triangles
        .extend(random_scene(12, [24, 24], 12, [0, 0], [24, 24], 1000).triangles);
    s.preset = Preset::Gl;
    let target = s.target().unwrap();
    let fixed = rasterproof::convention::Convention {
        subpixel_bits: 6,
        rounding: Rounding::TowardsZero,
        ..target.convention
    };
    let mut theirs = Coverage::new(24, 24);
    for (k, t) in s.triangles().iter().enumerate() {
        let t = t.snapped(&fixed).to_exact();
        if let Some(p) = rasterproof::tri::planned::PlannedTriangle::with_rule(&t, &target, AnyTieRule::BottomRight) {
            p.rasterize(u32::try_from(k).unwrap(), &mut theirs);
        }
    }
    let r = report(&s, &theirs, Format::Json, Model::ExactSnapped);
    let counts = class_counts(&r);
    assert!(counts["tie"] > 0 && counts["snapping"] > 0, "{counts:?}");
    assert_eq!(
        counts.values().sum::<usize>(),
        counts["tie"] + counts["snapping"],
        "{counts:?}"
    );
    let h = r.headline().expect("a two-part headline");
    let prefix = "every classified difference is explained by one convention: snapping to ";
    assert!(h.starts_with(prefix), "{h}");
    // The coarsest grid that explains the snapping findings: at most the renderer's 6 bits.
    let bits: u32 = h[prefix.len()..].split(' ').next().unwrap().parse().unwrap();
    assert!(bits <= 6, "{h}");
    assert!(
        h.contains("towards-zero")
            && h.contains("with the tie rule")
            && h.contains("bottom-right")
            && h.ends_with("the scene gives their answer at every classified pixel"),
        "{h}"
    );
}

/// `explain --svg`: the picture of a pixel on the shared diagonal of two triangles (a
/// square split from (13/2, 1/2) to (1/2, 13/2)); pixel (3, 3)'s sample (7/2, 7/2) lies on
/// it. By hand, under top-left: for the upper triangle the diagonal is a right edge
/// (exclusive, dashed), for the lower one a left edge (inclusive, solid), so the lower one
/// (id 1) covers the sample: the ringed sample is filled. The picture is well-formed XML,
/// 5x5 pixels of 96 units under a 64-unit caption: the sample at (2.5 * 96, 64 + 2.5 * 96).
#[test]
fn explain_draws_the_pixels_neighbourhood() {
    let dir = tempdir::Dir::new("explain-svg");
    let scene = write(
        &dir,
        "split.json",
        br#"{"width": 8, "height": 8, "triangles": [{"v": [[0.5, 0.5], [6.5, 0.5], [0.5, 6.5]]}, {"v": [[6.5, 0.5], [6.5, 6.5], [0.5, 6.5]]}]}"#,
    );
    let svg_path = dir.path().join("px.svg");
    let (code, out, err) = run(&[
        "explain".as_ref(),
        scene.as_os_str(),
        "3,3".as_ref(),
        "--svg".as_ref(),
        svg_path.as_os_str(),
    ]);
    assert_eq!(code, 0, "{out}{err}");
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    crate::hunt::well_formed(&svg).unwrap();
    assert!(
        svg.contains("pixel (3, 3), sample (7/2, 7/2): covered by 1 (exact-snapped)"),
        "{svg}"
    );
    let edge = |id: u32, flag: &str| {
        svg.lines()
            .filter(|l| l.contains(&format!("class=\"edge {flag}\" data-primitive=\"{id}\"")))
            .count()
    };
    // Upper triangle: left and top inclusive, the diagonal (a right edge) exclusive;
    // lower triangle: the diagonal (a left edge) inclusive, right and bottom exclusive.
    assert_eq!((edge(0, "inclusive"), edge(0, "exclusive")), (2, 1), "{svg}");
    assert_eq!((edge(1, "inclusive"), edge(1, "exclusive")), (1, 2), "{svg}");
    assert!(
        svg.contains("class=\"edge exclusive\" data-primitive=\"0\" data-edge=\"1\""),
        "{svg}"
    );
    assert!(
        svg.contains("<circle class=\"sample chosen\" cx=\"240.00\" cy=\"304.00\" r=\"6\" fill=\"#000000\""),
        "{svg}"
    );
    assert_eq!(svg.matches("class=\"sample\"").count(), 24);
    // Off the canvas: refused, nothing written.
    let missing = dir.path().join("off.svg");
    let (code, _, err) = run(&[
        "explain".as_ref(),
        scene.as_os_str(),
        "8,0".as_ref(),
        "--svg".as_ref(),
        missing.as_os_str(),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(!missing.exists());
}

/// A coordinate for the i128 path of `triangle_covers`, over 2^(k + 0..3) (mixed
/// denominators: the path scales each to the largest): with `small`, a small numerator
/// (ties, zero areas); else also near the scaled limit 2^60 on either side, at the ends of
/// i64, or anywhere.
fn dyadic_near_limits(k: u32, small: bool) -> impl Strategy<Value = num_rational::BigRational> {
    let limit = 1i64 << rasterproof::check::DYADIC_LIMIT_BITS;
    let numerator = if small {
        (-8i64..8).boxed()
    } else {
        prop_oneof![
            -8i64..8,
            (0i64..3).prop_map(move |j| limit - 1 - j),
            (0i64..3).prop_map(move |j| -(limit - 1 - j)),
            (0i64..3).prop_map(move |j| limit + j),
            (0i64..3).prop_map(move |j| -(limit + j)),
            Just(i64::MAX),
            Just(i64::MIN + 1),
            any::<i64>(),
        ]
        .boxed()
    };
    (numerator, 0u32..3).prop_map(move |(n, extra)| {
        num_rational::BigRational::new(n.into(), num_bigint::BigInt::from(1) << (k + extra))
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..config() })]

    /// `triangle_covers` (i128 where the points are dyadic and small enough, big rationals
    /// beyond) decides as the full evidence (`triangle_at`, big rationals throughout)
    /// under every tie rule: denominators on both sides of 2^32 and mixed, scaled
    /// coordinates on both sides of 2^60 and at the ends of i64, samples on edges and at
    /// vertices, zero-area triangles, and thirds.
    #[test]
    fn triangle_covers_in_i128_equals_the_rational_evidence(
        c in prop_oneof![Just(0u32), Just(31), Just(32), Just(33), 0u32..40]
            .prop_flat_map(|k| (Just(k), any::<bool>()))
            .prop_flat_map(|(k, small)| prop::collection::vec(dyadic_near_limits(k, small), 8)),
        sample in 0u8..4,
        third in any::<bool>(),
        degenerate in any::<bool>(),
    ) {
        let point = |i: usize| rasterproof::geom::Point::new(c[i].clone(), c[i + 1].clone());
        let half = num_rational::BigRational::new(1.into(), 2.into());
        let mut v = [point(0), point(2), point(4)];
        if degenerate {
            // On the line of the first two: zero area, covering nothing.
            v[2] = rasterproof::geom::Point::new((&v[0].x + &v[1].x) * &half, (&v[0].y + &v[1].y) * &half);
        }
        let t = rasterproof::geom::Triangle::new(v[0].clone(), v[1].clone(), v[2].clone());
        let mut p = match sample {
            0 => rasterproof::geom::Point::new((&v[0].x + &v[1].x) * &half, (&v[0].y + &v[1].y) * &half),
            1 => v[2].clone(),
            _ => point(6),
        };
        if third {
            p.x = &p.x + num_rational::BigRational::new(1.into(), 3.into());
        }
        for rule in AnyTieRule::ALL {
            let evidence = rasterproof::check::triangle_at(&t, &p, rule).is_some_and(|a| a.inside);
            prop_assert_eq!(rasterproof::check::triangle_covers(&t, &p, rule), evidence, "{:?} {:?} {:?}", t, p, rule);
        }
    }
}
