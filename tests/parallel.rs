//! Parallel drawing (`PreparedScene::coverage_parallel`, `render --jobs N`): the canvas cut
//! into bands of 64-row tiles, each drawn by its own thread; the result is the one-thread
//! coverage bit for bit, for every model, on scenes of every primitive kind whose shapes
//! cross the bands' edges, and the CLI's outputs are byte-identical. The same bands one at
//! a time (`PreparedScene::visit_bands`, what `render` counts a big frame with when it
//! writes only its summary) hold the same pixels.

use assert_cmd::Command;
use num_rational::BigRational;
use proptest::prelude::*;
use rasterproof::convention::{Preset, Target};
use rasterproof::coverage::{Coverage, CoverageSink, RowBand};
use rasterproof::geom::{Point, Triangle};
use rasterproof::line::{Line, LineRule};
use rasterproof::model::{prepare, prepare_parallel, Model, PreparedScene, Primitives};
use rasterproof::strategy::clip::any_window;
use rasterproof::strategy::polygon::any_polygon;
use rasterproof::strategy::{any_triangle, diamond_line, pixel_line, tie_heavy_triangle};

use crate::common::config;
use crate::tempdir;

/// Tall enough for four 64-row bands and a partial fifth.
const HEIGHT: u32 = 280;
const WIDTH: u32 = 48;

/// A triangle with its vertices on or next to the bands' edges (rows 64, 128, ...), often
/// with a flat edge there (two vertices on one row: an edge a tie rule may include): where
/// a band that skipped a triangle it meets would lose pixels.
fn band_edge_triangle() -> impl Strategy<Value = Triangle> {
    let y = (
        1i64..=4,
        prop::sample::select(vec![
            (-1, 1),
            (-3, 4),
            (-1, 2),
            (-1, 256),
            (0, 1),
            (1, 256),
            (1, 2),
            (3, 4),
            (1, 1),
            (5, 4),
        ]),
    )
        .prop_map(|(k, (n, d))| BigRational::from_integer((64 * k).into()) + BigRational::new(n.into(), d.into()));
    let x = || (0i64..=4 * i64::from(WIDTH)).prop_map(|n| BigRational::new(n.into(), 4.into()));
    let far = (0i64..i64::from(HEIGHT)).prop_map(|n| BigRational::from_integer(n.into()));
    let p = |x: BigRational, y: BigRational| Point::new(x, y);
    prop_oneof![
        prop::array::uniform3((x(), y.clone())).prop_map(move |[a, b, c]| Triangle::new(
            p(a.0, a.1),
            p(b.0, b.1),
            p(c.0, c.1)
        )),
        (x(), x(), x(), y, far).prop_map(move |(xa, xb, xc, flat, other)| {
            Triangle::new(p(xa, flat.clone()), p(xb, flat), p(xc, other))
        }),
    ]
}

fn scene() -> impl Strategy<Value = Primitives> {
    let triangles = prop::collection::vec(
        prop_oneof![
            any_triangle(HEIGHT),
            tie_heavy_triangle(HEIGHT),
            band_edge_triangle(),
            band_edge_triangle()
        ],
        1..=6,
    );
    let polygon = prop::option::of(any_polygon(HEIGHT, 9));
    let bresenham = prop::option::of(pixel_line(i64::from(HEIGHT), 4));
    let diamond = prop::option::of(diamond_line(HEIGHT));
    let window = prop::option::of(any_window(HEIGHT));
    (triangles, polygon, bresenham, diamond, window).prop_map(|(triangles, polygon, bresenham, diamond, clip)| {
        let mut lines = Vec::new();
        if let Some((from, to)) = bresenham {
            lines.push(Line {
                from: Point::from_ints(from[0], from[1]),
                to: Point::from_ints(to[0], to[1]),
                rule: LineRule::Bresenham(rasterproof::line::BresenhamTie::Stay),
            });
        }
        lines.extend(diamond);
        Primitives {
            triangles: triangles.into_iter().map(Into::into).collect(),
            lines,
            polygons: polygon.into_iter().collect(),
            clip,
            ..Primitives::default()
        }
    })
}

proptest! {
    // Each case draws every model twice on a 48 x 280 canvas (the plain oracles too): 10
    // cases (40 took a fifth of a fresh clone's test time, 16 still 21 to 35 s; PROPTEST_CASES
    // does not change it).
    #![proptest_config(ProptestConfig { cases: 10, ..config("proptest-regressions/parallel.txt") })]

    /// Every model, 2, 3 and 7 threads: the coverage of one thread, owners and order.
    #[test]
    fn parallel_coverage_is_the_one_thread_coverage(
        p in scene(),
        preset in prop::sample::select(Preset::ALL.to_vec()),
        jobs in prop::sample::select(vec![2usize, 3, 7]),
    ) {
        let target = Target::new(WIDTH, HEIGHT, preset.convention()).unwrap();
        for model in Model::ALL {
            let Ok(prepared) = prepare(&p, &target, model) else { continue };
            let one = prepared.coverage(&target);
            // Prepared on several threads too, as `render --jobs` prepares.
            let prepared = prepare_parallel(&p, &target, model, jobs).unwrap();
            let many = prepared.coverage_parallel(&target, jobs, &|| {});
            prop_assert_eq!(&many, &one, "{} on {} threads", model.name(), jobs);
            prop_assert_eq!(many.covered_pixels(), one.covered_pixels());
            // Band by band, a thread reusing its last band's tiles: each band has the
            // one-thread coverage's pixels of its rows and nothing else, and the bands
            // follow each other down the canvas.
            let bands = prepared.visit_bands(&target, jobs, |y0, y1, band| (y0, y1, band.clone()), &|| {});
            prop_assert_eq!(bands.len(), PreparedScene::visited_band_count(&target, jobs));
            let mut next = 0;
            for (y0, y1, band) in bands {
                prop_assert_eq!(y0, next, "{} on {} threads", model.name(), jobs);
                prop_assert_eq!(&band, &one.restricted(0, y0, WIDTH, y1), "{} on {} threads, rows {}..{}", model.name(), jobs, y0, y1);
                next = y1;
            }
            prop_assert_eq!(next, HEIGHT);
        }
    }

    /// Preparing on several threads refuses a scene with the error one thread gives: the
    /// first triangle (in id order) that the model cannot take, wherever the runs of the
    /// threads cut the triangles. Triangles beyond the integer envelope (2^21 px at 8
    /// subpixel bits) are refused by `fixed` and `scanline`, beyond f32 by the f32 models.
    #[test]
    fn parallel_prepare_refuses_the_first_triangle_one_thread_refuses(
        kinds in prop::collection::vec(0u8..6, 1..24),
        jobs in prop::sample::select(vec![2usize, 3, 7]),
    ) {
        let target = Target::new(WIDTH, HEIGHT, Preset::D3d11.convention()).unwrap();
        let triangle = |k: usize, kind: u8| {
            let x = i64::try_from(k % 40).unwrap();
            let far = match kind {
                0 => "4194304",  // 2^22 px: beyond the integer envelope
                1 => "1e39",     // beyond f32
                _ => "3",
            };
            let v = |a: &str, b: i64| Point::new(rasterproof::num::parse_rational(a).unwrap(), BigRational::from_integer(b.into()));
            Triangle::new(v(&x.to_string(), 0), v(far, 5), v("0", 9))
        };
        let p = Primitives {
            triangles: kinds.iter().enumerate().map(|(k, &kind)| (&triangle(k, kind)).into()).collect(),
            ..Primitives::default()
        };
        for model in Model::ALL {
            let one = prepare(&p, &target, model).map(|s| s.coverage(&target)).map_err(|e| e.to_string());
            let many = prepare_parallel(&p, &target, model, jobs).map(|s| s.coverage(&target)).map_err(|e| e.to_string());
            prop_assert_eq!(many, one, "{} on {} threads", model.name(), jobs);
        }
    }
}

/// A band keeps its rows only, in every write a traversal makes; the rows it drops and
/// keeps are counted by hand.
#[test]
fn a_row_band_keeps_its_rows_only() {
    let mut c = Coverage::new(16, 32);
    {
        let mut band = RowBand::new(&mut c, 8, 12);
        band.cover(0, 7, 1); // above: dropped
        band.cover(0, 8, 1); // kept
        band.cover_span(11, 2, 4, 2); // kept: 3 pixels
        band.cover_span(12, 2, 4, 2); // below: dropped
        band.cover_mask(9, 0, 0b101, 3); // kept: 2 pixels
                                         // Rows 4..12 of an 8-row block, every row all 8 pixels: rows 8..12 kept, 4 x 8.
        band.cover_block(4, 8, u64::MAX, 4);
        // Rows 10..18: rows 10 and 11 kept, pixel 0 of each (bit 0 of each byte).
        band.cover_block(10, 0, 0x0101_0101_0101_0101, 5);
    }
    assert_eq!(c.covered_pixels(), 1 + 3 + 2 + 32 + 2);
    assert_eq!(c.owners(0, 8), [1]);
    assert!(c.owners(0, 7).is_empty() && c.owners(2, 12).is_empty());
    assert_eq!((c.owners(0, 9), c.owners(2, 9)), (&[3][..], &[3][..]));
    assert_eq!((c.owners(0, 10), c.owners(0, 11)), (&[5][..], &[5][..]));
    assert!(c.owners(0, 12).is_empty());
    assert_eq!((c.owners(8, 8), c.owners(15, 11)), (&[4][..], &[4][..]));
    assert!(c.owners(8, 12).is_empty() && c.owners(8, 7).is_empty());
}

/// `render --jobs 1` and `--jobs 2` (and 3) write byte-identical ids PNGs, coverage PNGs
/// and JSON for every model.
#[test]
fn render_jobs_outputs_are_byte_identical() {
    let dir = tempdir::Dir::new("jobs");
    let scene = dir.path().join("scene.json");
    std::fs::write(
        &scene,
        r#"{"width": 40, "height": 300, "preset": "vulkan",
            "triangles": [{"v": [[0, 0], [40, 10.5], [3.25, 299]]}, {"v": [[40, 10.5], [3.25, 299], [39, "1000/3"]]},
                          {"v": [[5, 60], [30, 64], [20, 70]]}, {"v": [[0, 128], [40, 128], [20, 192]]}],
            "lines": [{"from": [1, 1], "to": [38, 290]}, {"from": [0.5, 250], "to": [39.5, 63.5], "rule": "diamond"}],
            "polygons": [{"v": [[2, 100], [38, 140], [38, 220], [2, 180]], "fill_rule": "even-odd"}]}"#,
    )
    .unwrap();
    for model in Model::ALL {
        let mut outputs = Vec::new();
        for jobs in ["1", "2", "3"] {
            let ids = dir.path().join(format!("ids-{jobs}.png"));
            let png = dir.path().join(format!("cov-{jobs}.png"));
            let out = Command::cargo_bin("rasterproof")
                .unwrap()
                .args([
                    "render",
                    scene.to_str().unwrap(),
                    "--model",
                    model.name(),
                    "--jobs",
                    jobs,
                    "--format",
                    "json",
                ])
                .arg("--ids-out")
                .arg(&ids)
                .arg("-o")
                .arg(&png)
                .output()
                .unwrap();
            assert!(
                out.status.success(),
                "{} --jobs {jobs}: {}",
                model.name(),
                String::from_utf8_lossy(&out.stderr)
            );
            outputs.push((out.stdout, std::fs::read(&ids).unwrap(), std::fs::read(&png).unwrap()));
        }
        assert!(!outputs[0].0.is_empty());
        assert_eq!(outputs[1], outputs[0], "{}: --jobs 2", model.name());
        assert_eq!(outputs[2], outputs[0], "{}: --jobs 3", model.name());
    }
}

/// Two overlapping rectangles (two triangles each) across row 512 of a 16384 x 1024 canvas,
/// 2^24 pixels: `render` writing only its summary visits the frame in bands of at most
/// 2^23 pixels, two on one thread, and says what the whole coverage says. By hand: the
/// rectangle [100, 110) x [460, 560) covers 10 x 100 pixels, [105, 120) x [500, 520)
/// 15 x 20, both of them [105, 110) x [500, 520), 5 x 20.
#[test]
fn render_counts_a_big_frame_band_by_band() {
    let dir = tempdir::Dir::new("bands");
    let rect = |x0: u32, y0: u32, x1: u32, y1: u32| {
        format!(
            r#"{{"v": [[{x0}, {y0}], [{x1}, {y0}], [{x1}, {y1}]]}}, {{"v": [[{x0}, {y0}], [{x1}, {y1}], [{x0}, {y1}]]}}"#
        )
    };
    let rects = format!("{}, {}", rect(100, 460, 110, 560), rect(105, 500, 120, 520));
    let scene_with = |extra: &str| format!(r#"{{"width": 16384, "height": 1024, "triangles": [{rects}]{extra}}}"#);
    let scene = dir.path().join("scene.json");
    std::fs::write(&scene, scene_with("")).unwrap();
    // With a window around the canvas, the exact and float models clip the triangles to
    // polygons, which every band would draw whole: `render` draws the whole coverage
    // there, to the same counts.
    let window = r#", "clip": {"rect": [0, 0, 16384, 1024]}"#;
    let clipped = dir.path().join("clipped.json");
    std::fs::write(&clipped, scene_with(window)).unwrap();
    let parsed = rasterproof::scene::parse_scene(&scene_with(""), "scene.json").unwrap();
    let target = parsed.target().unwrap();
    assert_eq!(PreparedScene::visited_band_count(&target, 1), 2);
    let expected = "1200 pixels covered, 100 covered more than once";
    for model in Model::ALL {
        for file in [&scene, &clipped] {
            for jobs in ["1", "2", "3"] {
                let out = Command::cargo_bin("rasterproof")
                    .unwrap()
                    .args([
                        "render",
                        file.to_str().unwrap(),
                        "--model",
                        model.name(),
                        "--jobs",
                        jobs,
                    ])
                    .output()
                    .unwrap();
                let stdout = String::from_utf8_lossy(&out.stdout);
                let stderr = String::from_utf8_lossy(&out.stderr);
                assert!(out.status.success(), "{} --jobs {jobs}: {stderr}", model.name());
                assert!(stdout.contains(expected), "{} --jobs {jobs}: {stdout}", model.name());
            }
        }
    }
    // Which scenes bands draw cheaply: triangles only, unclipped. A line, a polygon, or a
    // window under a model that clips triangles to polygons is drawn by every band.
    let bands_skip_all = |extra: &str, model: Model| {
        let scene = rasterproof::scene::parse_scene(&scene_with(extra), "s.json").unwrap();
        prepare(&scene.primitives(), &target, model).unwrap().bands_skip_all()
    };
    for model in Model::ALL {
        let integer = matches!(model, Model::Fixed | Model::Scanline);
        assert!(bands_skip_all("", model), "{}", model.name());
        assert_eq!(bands_skip_all(window, model), integer, "{} with a window", model.name());
        for extra in [
            r#", "lines": [{"from": [0, 0], "to": [5, 5]}]"#,
            r#", "polygons": [{"v": [[0, 0], [5, 0], [0, 5]]}]"#,
        ] {
            assert!(!bands_skip_all(extra, model), "{} with {extra}", model.name());
        }
    }
}
