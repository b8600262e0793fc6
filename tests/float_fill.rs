//! The float models on mixed scenes (issue 10): polygons by a float winding test,
//! diamond-exit lines read in floats, and errors that name the coordinate a float type
//! cannot hold. Where every product is exact in the float type, the float reading with the
//! tie rule must equal the oracle pixel for pixel: that is the proof the float code reads
//! the same rule; elsewhere its departures are the measured trade.

use crate::common;

use common::config;
use num_rational::BigRational;
use proptest::prelude::*;
use rasterproof::check::differing_pixels;
use rasterproof::convention::{Preset, Target};
use rasterproof::coverage::Coverage;
use rasterproof::geom::{FillRule, Point, Polygon, Triangle};
use rasterproof::line::{BresenhamTie, Line, LineRule};
use rasterproof::model::{render, Model, Primitives};
use rasterproof::strategy::polygon::any_polygon;

fn polygons(p: Vec<Polygon>) -> Primitives {
    Primitives {
        polygons: p,
        ..Primitives::default()
    }
}

fn lines(l: Vec<Line>) -> Primitives {
    Primitives {
        lines: l,
        ..Primitives::default()
    }
}

fn pts(v: &[(i64, i64)]) -> Vec<Point> {
    v.iter().map(|&(x, y)| Point::from_ints(x, y)).collect()
}

fn row(c: &Coverage, y: u32) -> Vec<u32> {
    c.iter().filter(|p| p.1 == y).map(|p| p.0).collect()
}

/// The pentagram of tests/polygons.rs, whose rows 10 and 50 are derived there by hand:
/// row 10 is pixels 47..=52 under both rules; row 50 is 24..=75 (nonzero), and 24..=33
/// plus 66..=75 (even-odd). Integer vertices below 100 and half-pixel samples keep every
/// edge value below 2^15: exact in f32, so the float models with the tie rule must agree.
#[test]
fn float_models_fill_the_pentagram_as_derived_by_hand() {
    let star = pts(&[(50, 0), (79, 90), (2, 35), (98, 35), (21, 90)]);
    let target = Target::new(100, 100, Preset::D3d11.convention()).unwrap();
    for model in [Model::Float32, Model::Float64, Model::Float32Naive, Model::Float64Naive] {
        let fill = |rule| render(&polygons(vec![Polygon::new(star.clone(), rule)]), &target, model).unwrap();
        let (nonzero, even_odd) = (fill(FillRule::NonZero), fill(FillRule::EvenOdd));
        assert_eq!(row(&nonzero, 10), (47..=52).collect::<Vec<_>>(), "{model}");
        assert_eq!(row(&even_odd, 10), (47..=52).collect::<Vec<_>>(), "{model}");
        assert_eq!(row(&nonzero, 50), (24..=75).collect::<Vec<_>>(), "{model}");
        let expected: Vec<u32> = (24..=33).chain(66..=75).collect();
        assert_eq!(row(&even_odd, 50), expected, "{model}");
    }
}

/// Samples exactly on a polygon's edges: the 4x4 square (1, 1)..(5, 5) sampled at integer
/// points (pixel centre 0). Top-left owns the left and top edges: samples x, y in 1..=4,
/// i.e. pixels 1..=4 of rows 1..=4 (16). The naive PNPOLY test has its own half-open
/// rule: `(a.y > y) != (b.y > y)` keeps the top row and drops the bottom one, and
/// `x < x_crossing` keeps the left column and drops the right one: the same 16 here.
/// Under bottom-left the rows shift down: rows 2..=5.
#[test]
fn samples_on_polygon_edges_follow_each_rule() {
    let sq = Polygon::new(pts(&[(1, 1), (5, 1), (5, 5), (1, 5)]), FillRule::NonZero);
    for preset in [Preset::D3d11, Preset::Gl] {
        let conv = rasterproof::convention::Convention {
            pixel_centre: rasterproof::convention::PixelCentre::Corner,
            ..preset.convention()
        };
        let target = Target::new(8, 8, conv).unwrap();
        let rows: Vec<u32> = if preset == Preset::Gl {
            (2..=5).collect()
        } else {
            (1..=4).collect()
        };
        for model in [Model::Exact, Model::Float32, Model::Float64] {
            let c = render(&polygons(vec![sq.clone()]), &target, model).unwrap();
            for y in 0..8 {
                let expected: Vec<u32> = if rows.contains(&y) { (1..=4).collect() } else { vec![] };
                assert_eq!(row(&c, y), expected, "{model} {preset:?} row {y}");
            }
        }
        let naive = render(&polygons(vec![sq.clone()]), &target, Model::Float64Naive).unwrap();
        assert_eq!(naive.covered_pixels(), 16);
        assert_eq!(row(&naive, 1), (1..=4).collect::<Vec<_>>(), "naive keeps the top row");
        assert!(row(&naive, 5).is_empty(), "naive drops the bottom row");
    }
}

proptest! {
    #![proptest_config(config("proptest-regressions/float_fill.txt"))]

    /// Every polygon family on the 1/256 grid of a 32x32 canvas: edge values need under
    /// 30 bits, exact in f64, so `float64` must equal the oracle on the scene as written.
    #[test]
    fn float64_equals_the_oracle_where_its_products_are_exact(
        poly in any_polygon(32, 12),
        preset in prop::sample::select(vec![Preset::D3d11, Preset::Gl]),
    ) {
        let target = Target::new(32, 32, preset.convention()).unwrap();
        let exact = render(&polygons(vec![poly.clone()]), &target, Model::ExactPlain).unwrap();
        let float = render(&polygons(vec![poly]), &target, Model::Float64).unwrap();
        prop_assert_eq!(differing_pixels(&exact, &float), vec![]);
    }

    /// Integer vertices on a 32x32 canvas: edge values below 2^14, exact in f32.
    #[test]
    fn float32_equals_the_oracle_on_integer_polygons(
        v in prop::collection::vec((0i64..=32, 0i64..=32), 3..10),
        hole in prop::collection::vec((8i64..=24, 8i64..=24), 3..6),
        rule in prop::sample::select(vec![FillRule::NonZero, FillRule::EvenOdd]),
        preset in prop::sample::select(vec![Preset::D3d11, Preset::Gl]),
    ) {
        let mut poly = Polygon::new(pts(&v), rule);
        poly.holes.push(pts(&hole));
        let target = Target::new(32, 32, preset.convention()).unwrap();
        let exact = render(&polygons(vec![poly.clone()]), &target, Model::ExactPlain).unwrap();
        let float = render(&polygons(vec![poly]), &target, Model::Float32).unwrap();
        prop_assert_eq!(differing_pixels(&exact, &float), vec![]);
    }

    /// Diamond-exit lines whose arithmetic is exact in floats: endpoints on the 1/4 grid,
    /// one of the eight axis and diagonal directions, a power-of-two length. Every chord
    /// parameter `(r - g0) / g1` divides by a power of two, so f32 and f64 read the rule
    /// exactly and must equal the exact reading.
    #[test]
    fn float_diamond_equals_the_exact_reading_where_exact(
        x in 0i64..=96, y in 0i64..=96,
        dir in 0usize..8, len in 0u32..4,
    ) {
        let (dx, dy) = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1)][dir];
        let l = 1i64 << len;
        let q = |n: i64| BigRational::new(n.into(), 4.into());
        let line = Line {
            from: Point::new(q(x), q(y)),
            to: Point::new(q(x + 4 * l * dx), q(y + 4 * l * dy)),
            rule: LineRule::Diamond,
        };
        let target = Target::new(32, 32, Preset::D3d11.convention()).unwrap();
        let exact = render(&lines(vec![line.clone()]), &target, Model::ExactPlain).unwrap();
        for model in [Model::Float32, Model::Float64] {
            let float = render(&lines(vec![line.clone()]), &target, model).unwrap();
            prop_assert_eq!(differing_pixels(&exact, &float), vec![], "{}", model);
        }
    }
}

/// By hand: the diamond-exit line (0.5, 0.5) -> (4.5, 0.5) runs through the centres of
/// pixels 0..=4 of row 0. It leaves the diamonds of pixels 0..=3 and ends in pixel 4's
/// (the end inside a test area never leaves it): pixels 0..=3, in every model.
#[test]
fn a_diamond_line_through_pixel_centres_by_hand() {
    let q = |n: i64| BigRational::new(n.into(), 2.into());
    let line = Line {
        from: Point::new(q(1), q(1)),
        to: Point::new(q(9), q(1)),
        rule: LineRule::Diamond,
    };
    let target = Target::new(8, 8, Preset::D3d11.convention()).unwrap();
    for model in Model::ALL {
        let c = render(&lines(vec![line.clone()]), &target, model).unwrap();
        assert_eq!(row(&c, 0), vec![0, 1, 2, 3], "{model}");
        assert_eq!(c.covered_pixels(), 4, "{model}");
    }
}

/// By hand: the vertical diamond-exit line (0.5, 2.5) -> (0.5, 0) starts at pixel (0, 2)'s
/// centre, passes through (0, 1)'s, enters (0, 0)'s diamond at its bottom corner (in the
/// test area) and ends on its top corner (not in it: the upper corner belongs to the pixel
/// above), so it leaves all three: pixels (0, 0), (0, 1), (0, 2).
#[test]
fn a_diamond_line_ending_on_a_top_corner_by_hand() {
    let q = |n: i64| BigRational::new(n.into(), 2.into());
    let line = Line {
        from: Point::new(q(1), q(5)),
        to: Point::new(q(1), q(0)),
        rule: LineRule::Diamond,
    };
    let target = Target::new(4, 4, Preset::D3d11.convention()).unwrap();
    for model in Model::ALL {
        let c = render(&lines(vec![line.clone()]), &target, model).unwrap();
        let got: Vec<(u32, u32)> = c.iter().map(|(x, y, _)| (x, y)).collect();
        assert_eq!(got, vec![(0, 0), (0, 1), (0, 2)], "{model}");
    }
}

/// A mixed scene (triangle, Bresenham line, diamond line, polygon with a hole) renders
/// in every model; ids follow triangles, lines, polygons.
#[test]
fn every_model_renders_a_mixed_scene() {
    let mut poly = Polygon::new(pts(&[(16, 16), (30, 16), (30, 30), (16, 30)]), FillRule::NonZero);
    poly.holes.push(pts(&[(20, 20), (26, 20), (26, 26), (20, 26)]));
    let scene = Primitives {
        triangles: vec![Triangle::new(Point::from_ints(0, 0), Point::from_ints(8, 0), Point::from_ints(0, 8)).into()],
        lines: vec![
            Line {
                from: Point::from_ints(0, 12),
                to: Point::from_ints(12, 12),
                rule: LineRule::Bresenham(BresenhamTie::Stay),
            },
            Line {
                from: Point::from_fractions(1, 2, 29, 2),
                to: Point::from_fractions(25, 2, 29, 2),
                rule: LineRule::Diamond,
            },
        ],
        polygons: vec![poly],
        ..Primitives::default()
    };
    let target = Target::new(32, 32, Preset::D3d11.convention()).unwrap();
    let exact = render(&scene, &target, Model::Exact).unwrap();
    for model in Model::ALL {
        let c = render(&scene, &target, model).unwrap();
        assert_eq!(c.owners(1, 1), &[0], "{model}");
        assert_eq!(c.owners(5, 12), &[1], "{model}");
        assert_eq!(c.owners(5, 14), &[2], "{model}");
        assert_eq!(c.owners(17, 17), &[3], "{model}");
        assert!(c.owners(22, 22).is_empty(), "{model}: the hole");
        // Small integers: every model reads this scene exactly, but for the naive float
        // test `w >= 0`, which also takes the samples on the triangle's right edge
        // x + y = 8 (a tie the top-left rule leaves out): pixels (7 - y, y), by hand.
        let naive_extra: Vec<(u32, u32)> = (0..=7).map(|y| (7 - y, y)).collect();
        let extra: Vec<(u32, u32)> = differing_pixels(&exact, &c).iter().map(|d| (d.x, d.y)).collect();
        if matches!(model, Model::Float32Naive | Model::Float64Naive) {
            let mut expected = naive_extra.clone();
            expected.sort_by_key(|&(x, y)| (y, x));
            assert_eq!(extra, expected, "{model}");
        } else {
            assert_eq!(extra, vec![], "{model}");
        }
    }
}

/// A coordinate a float type cannot hold is named with its path and value.
#[test]
fn float_range_errors_name_the_coordinate_and_value() {
    let target = Target::new(8, 8, Preset::D3d11.convention()).unwrap();
    let big = |digits: usize| BigRational::from_integer(format!("1{}", "0".repeat(digits)).parse().unwrap());
    let tri = Triangle::new(
        Point::from_ints(0, 0),
        Point::from_ints(4, 0),
        Point::new(BigRational::from_integer(4.into()), big(400)),
    );
    let err = render(&Primitives::from_triangles(&[tri]), &target, Model::Float64)
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with("triangles[0].v[2].y: 100000000000000000000000... (401 characters) does not fit"),
        "{err}"
    );
    assert!(err.contains("float64 model's float type f64"), "{err}");
    // 10^39 fits f64 but not f32 (f32::MAX is about 3.4 * 10^38).
    let line = Line {
        from: Point::from_ints(0, 0),
        to: Point::new(big(39), BigRational::from_integer(1.into())),
        rule: LineRule::Diamond,
    };
    let err = render(&lines(vec![line.clone()]), &target, Model::Float32)
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with(
            "lines[0].to.x: 1000000000000000000000000000000000000000 does not fit the float32 model's float type f32"
        ),
        "{err}"
    );
    assert!(render(&lines(vec![line]), &target, Model::Float64).is_ok());
    let mut poly = Polygon::new(pts(&[(0, 0), (8, 0), (8, 8)]), FillRule::NonZero);
    poly.holes.push(vec![
        Point::from_ints(1, 1),
        Point::new(big(39), BigRational::from_integer(1.into())),
        Point::from_ints(2, 2),
    ]);
    let err = render(&polygons(vec![poly]), &target, Model::Float32Naive)
        .unwrap_err()
        .to_string();
    assert!(err.starts_with("polygons[0].holes[0][1].x: "), "{err}");
}
