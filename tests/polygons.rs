//! Polygon fill (issue 5): the scanline filler equals the exact oracle on every polygon
//! family and convention; the oracle's fill of a triangle equals the triangle oracle
//! (the tie rule's ε reading carries over); a simple polygon's fill is the disjoint union
//! of its triangulation's coverage; even-odd and nonzero agree on simple polygons and
//! differ where a contour winds twice. Goldens derived by hand.

use crate::common;

use common::config;
use proptest::prelude::*;
use rasterproof::check::triangle_covers;
use rasterproof::check::{check_agreement, check_no_double_cover, differing_pixels};
use rasterproof::convention::{AnyTieRule, Convention, PixelCentre, Preset, Target};
use rasterproof::coverage::Coverage;
use rasterproof::fill::polygon::{contains_exact_with, rasterize, rasterize_exact, rasterize_exact_with};
use rasterproof::fill::triangulate::{triangulate, validate, TriangulateError};
use rasterproof::geom::{FillRule, FixedPolygon, Point, Polygon, Triangle};
use rasterproof::model::{render, Model, Primitives};
use rasterproof::strategy::any_triangle;
use rasterproof::strategy::polygon::{any_polygon, simple_polygon, stellated_polygon};

fn pts(v: &[(i64, i64)]) -> Vec<Point> {
    v.iter().map(|&(x, y)| Point::from_ints(x, y)).collect()
}

fn fill(poly: &Polygon, target: &Target, model: Model) -> Coverage {
    render(
        &Primitives {
            polygons: vec![poly.clone()],
            ..Primitives::default()
        },
        target,
        model,
    )
    .unwrap()
}

/// The pixels of row `y`, as column numbers.
fn row(c: &Coverage, y: u32) -> Vec<u32> {
    c.iter().filter(|&(_, py, _)| py == y).map(|(x, _, _)| x).collect()
}

fn target_with(side: u32, preset: Preset, bits: u32, corner: bool) -> Target {
    let mut conv = preset.convention();
    conv.subpixel_bits = bits;
    if corner {
        conv.pixel_centre = PixelCentre::Corner;
    }
    Target::new(side, side, conv).unwrap()
}

/// The pentagram of the doc examples: vertices (50,0) (79,90) (2,35) (98,35) (21,90).
fn pentagram(rule: FillRule) -> Polygon {
    Polygon::new(pts(&[(50, 0), (79, 90), (2, 35), (98, 35), (21, 90)]), rule)
}

/// By hand, samples at pixel centres. Row 10 (y = 10.5) crosses only the two edges from
/// the top vertex (50, 0): x = 50 -+ 29 * 10.5 / 90 = 50 -+ 3.383, so samples 47.5..=52.5:
/// pixels 47..=52, winding 1, under both rules.
/// Row 50 (y = 50.5) crosses four edges: (79,90)->(2,35) at 2 + 77 * 15.5 / 55 = 23.7,
/// (21,90)->(50,0) at 50 - 29 * 50.5 / 90 = 33.727.., (50,0)->(79,90) at 66.272.., and
/// (98,35)->(21,90) at 98 - 21.7 = 76.3. The winding is 1, 2, 1 between them: nonzero
/// fills samples 24.5..=75.5 (pixels 24..=75), even-odd only 24..=33 and 66..=75.
#[test]
fn pentagram_by_hand() {
    let target = Target::new(100, 100, Preset::D3d11.convention()).unwrap();
    for model in [Model::Exact, Model::ExactSnapped, Model::Scanline] {
        let nonzero = fill(&pentagram(FillRule::NonZero), &target, model);
        let even_odd = fill(&pentagram(FillRule::EvenOdd), &target, model);
        assert_eq!(row(&nonzero, 10), (47..=52).collect::<Vec<_>>(), "{model}");
        assert_eq!(row(&even_odd, 10), (47..=52).collect::<Vec<_>>(), "{model}");
        assert_eq!(row(&nonzero, 50), (24..=75).collect::<Vec<_>>(), "{model}");
        assert_eq!(
            row(&even_odd, 50),
            (24..=33).chain(66..=75).collect::<Vec<_>>(),
            "{model}"
        );
        // The centre: in nonzero, not in even-odd.
        assert_eq!(nonzero.owners(50, 50), &[0]);
        assert!(even_odd.owners(50, 50).is_empty());
    }
}

/// A 10x10 square with a 4x4 square hole at (3,3)-(7,7), both wound the same way: the
/// hole is still a hole under nonzero (each contour is judged on its own), 100 - 16 = 84 pixels.
/// The L-shape (0,0) (6,0) (6,2) (2,2) (2,6) (0,6): a 6x2 bar and a 2x4 leg, 12 + 8 = 20.
#[test]
fn hole_and_concave_by_hand() {
    let target = Target::new(12, 12, Preset::D3d11.convention()).unwrap();
    let square = |a: i64, b: i64| pts(&[(a, a), (b, a), (b, b), (a, b)]);
    for rule in [FillRule::NonZero, FillRule::EvenOdd] {
        let mut p = Polygon::new(square(0, 10), rule);
        p.holes.push(square(3, 7));
        for model in [Model::Exact, Model::Scanline, Model::Fixed] {
            let c = fill(&p, &target, model);
            assert_eq!(c.covered_pixels(), 84, "{model} {rule:?}");
            assert!(c.owners(5, 5).is_empty() && c.owners(2, 5) == [0] && c.owners(7, 5) == [0]);
        }
        let l = Polygon::new(pts(&[(0, 0), (6, 0), (6, 2), (2, 2), (2, 6), (0, 6)]), rule);
        for model in [Model::Exact, Model::Scanline, Model::Fixed] {
            assert_eq!(fill(&l, &target, model).covered_pixels(), 20, "{model} {rule:?}");
        }
    }
}

/// Samples on the outline follow the tie rule: a 4x4 square from (0.5, 0.5) to
/// (4.5, 4.5) has samples on all four sides. Top-left owns its top and left sides: rows
/// and columns 0..=3, 16 pixels at (0..=3, 0..=3). Bottom-left owns the bottom and left:
/// rows 1..=4.
#[test]
fn outline_samples_follow_the_tie_rule() {
    let p = Polygon::new(
        vec![
            Point::from_fractions(1, 2, 1, 2),
            Point::from_fractions(9, 2, 1, 2),
            Point::from_fractions(9, 2, 9, 2),
            Point::from_fractions(1, 2, 9, 2),
        ],
        FillRule::NonZero,
    );
    for (preset, rows) in [(Preset::D3d11, 0..=3), (Preset::Gl, 1..=4)] {
        let target = Target::new(8, 8, preset.convention()).unwrap();
        for model in [Model::Exact, Model::Scanline, Model::Fixed] {
            let c = fill(&p, &target, model);
            let expected: Vec<(u32, u32)> = rows.clone().flat_map(|y| (0..=3).map(move |x| (x, y))).collect();
            let got: Vec<(u32, u32)> = c.iter().map(|(x, y, _)| (x, y)).collect();
            assert_eq!(got, expected, "{preset:?} {model}");
        }
    }
}

#[test]
fn triangulation_refuses_what_it_cannot_take() {
    let poly = |contours: Vec<Vec<[i64; 2]>>| FixedPolygon::new(contours, FillRule::NonZero, 8).unwrap();
    let not_simple = |p: &FixedPolygon| matches!(triangulate(p), Err(TriangulateError::NotSimple { .. }));
    // bow tie; figure eight touching at a vertex; a spike folding back along an edge;
    // a vertex on a non-adjacent edge
    assert!(not_simple(&poly(vec![vec![[0, 0], [8, 8], [8, 0], [0, 8]]])));
    assert!(not_simple(&poly(vec![vec![
        [0, 0],
        [4, 4],
        [8, 0],
        [8, 8],
        [4, 4],
        [0, 8]
    ]])));
    assert!(not_simple(&poly(vec![vec![[0, 0], [8, 0], [4, 0], [4, 8]]])));
    assert!(not_simple(&poly(vec![vec![[0, 0], [8, 0], [8, 8], [4, 0], [0, 8]]])));
    // holes: outside, inside another hole, crossing the outline
    let outline = vec![[0, 0], [100, 0], [100, 100], [0, 100]];
    let tri = |x: i64, y: i64, s: i64| vec![[x, y], [x + s, y], [x, y + s]];
    assert_eq!(
        triangulate(&poly(vec![outline.clone(), tri(200, 200, 10)])),
        Err(TriangulateError::HoleOutside { hole: 0 })
    );
    assert_eq!(
        triangulate(&poly(vec![outline.clone(), tri(10, 10, 60), tri(20, 20, 5)])),
        Err(TriangulateError::HoleInHole { hole: 1, other: 0 })
    );
    assert!(not_simple(&poly(vec![outline.clone(), tri(90, 50, 30)])));
    // Many vertices are no reason to refuse: 9000 points in a tangle still get an answer
    // (the pair of edges that meet), not a count.
    let many: Vec<[i64; 2]> = (0..9000).map(|k| [k, k * k % 7919]).collect();
    assert!(not_simple(&poly(vec![many])));
    // Degenerate outlines cover nothing and triangulate to nothing: all collinear, or
    // fewer than 3 distinct vertices after snapping merged them.
    assert_eq!(triangulate(&poly(vec![vec![[0, 0], [4, 4], [8, 8]]])), Ok(vec![]));
    assert_eq!(triangulate(&poly(vec![vec![[0, 0], [0, 0], [8, 8]]])), Ok(vec![]));
    // A hole with no area removes nothing: the square still triangulates.
    assert_eq!(
        triangulate(&poly(vec![outline, vec![[10, 10], [20, 20], [30, 30]]]))
            .unwrap()
            .len(),
        2
    );
}

/// A polygon far beyond the old 8192-vertex cap of the triangulation: a 9,000-vertex
/// concave star (alternating radii 28 and 26 px about the centre of a 64x64 canvas,
/// vertices rounded to 1/256 px) with four square holes and one 600-vertex round hole.
/// It triangulates into n + 2h - 2 triangles (n vertices, h holes: no vertex added), no
/// pixel is covered twice, and their coverage is the exact fill of the snapped polygon,
/// pixel for pixel; the `fixed` model renders it the same.
#[test]
fn a_9000_vertex_polygon_with_holes_triangulates() {
    #[allow(clippy::cast_possible_truncation, clippy::cast_precision_loss)] // small values
    let ring = |n: usize, centre: f64, r: f64, dent: f64| -> Vec<Point> {
        (0..n)
            .map(|k| {
                let a = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
                let r = if k % 2 == 1 { r - dent } else { r };
                let v = |c: f64| (c * 256.0).round() as i64;
                Point::from_fractions(v(centre + r * a.cos()), 256, v(centre + r * a.sin()), 256)
            })
            .collect()
    };
    let mut p = Polygon::new(ring(9000, 32.0, 28.0, 2.0), FillRule::NonZero);
    for (x, y) in [(20, 20), (40, 20), (20, 40), (40, 40)] {
        p.holes.push(pts(&[(x, y), (x + 4, y), (x + 4, y + 4), (x, y + 4)]));
    }
    p.holes.push(ring(600, 32.0, 5.0, 0.0));
    let target = Target::new(64, 64, Preset::D3d11.convention()).unwrap();
    let fixed = p.to_fixed(&target.convention).unwrap();
    let tris = triangulate(&fixed).unwrap();
    assert_eq!(tris.len(), 9000 + 4 * 4 + 600 + 2 * 5 - 2);
    let (union, each) = triangulation_coverage(&tris, &target);
    check_no_double_cover(&each).unwrap();
    let filled = fill(&p, &target, Model::ExactSnapped);
    assert!(filled.covered_pixels() > 1500, "{}", filled.covered_pixels());
    assert_eq!(differing_pixels(&filled, &union), vec![]);
    assert_eq!(differing_pixels(&filled, &fill(&p, &target, Model::Fixed)), vec![]);
}

/// Triangles from a triangulation, all with id 0, and each with its own id.
fn triangulation_coverage(tris: &[rasterproof::geom::FixedTriangle], target: &Target) -> (Coverage, Coverage) {
    let (mut union, mut each) = (
        Coverage::new(target.width, target.height),
        Coverage::new(target.width, target.height),
    );
    for (k, t) in tris.iter().enumerate() {
        rasterproof::tri::fixed::rasterize(t, 0, target, &mut union);
        rasterproof::tri::fixed::rasterize(t, u32::try_from(k).unwrap(), target, &mut each);
    }
    (union, each)
}

/// Triangles on the half-pixel grid of an 8x8 canvas: horizontal and vertical edges
/// through sample rows and columns, vertices on samples — the ties, often.
fn half_grid_triangle() -> impl Strategy<Value = Triangle> {
    prop::array::uniform6(-2i64..=18).prop_map(|c| {
        let p = |x: i64, y: i64| Point::from_fractions(x, 2, y, 2);
        Triangle::new(p(c[0], c[1]), p(c[2], c[3]), p(c[4], c[5]))
    })
}

proptest! {
    #![proptest_config(config("proptest-regressions/polygons.txt"))]

    /// The same on the half-pixel grid of a small canvas, where most triangles have a
    /// sample on an edge or a vertex.
    #[test]
    fn triangle_as_polygon_equals_triangle_at_ties(
        t in half_grid_triangle(),
        preset in prop::sample::select(Preset::ALL.to_vec()),
        corner in any::<bool>(),
    ) {
        let target = target_with(8, preset, 8, corner);
        let poly = Polygon::new(t.v.to_vec(), FillRule::NonZero);
        let (mut a, mut b) = (Coverage::new(8, 8), Coverage::new(8, 8));
        rasterproof::tri::exact::rasterize(&t, 0, &target, &mut a);
        rasterize_exact(&poly, 0, &target, &mut b);
        prop_assert_eq!(differing_pixels(&a, &b), vec![]);
    }

    /// Under each of the six tie rules, the polygon oracle on a triangle decides every
    /// sample as the triangle's edge functions with that rule's inclusive flags do
    /// (all-inclusive: the closed triangle; all-exclusive: the open one), either winding,
    /// either fill rule, on the half-pixel grid where samples lie on edges and vertices.
    #[test]
    fn triangle_as_polygon_equals_triangle_under_every_rule(
        t in half_grid_triangle(),
        rule in prop::sample::select(AnyTieRule::ALL.to_vec()),
        reversed in any::<bool>(),
        even_odd in any::<bool>(),
    ) {
        let mut v = t.v.to_vec();
        if reversed {
            v.reverse();
        }
        let poly = Polygon::new(v, if even_odd { FillRule::EvenOdd } else { FillRule::NonZero });
        for y in -2..=18i64 {
            for x in -2..=18i64 {
                let p = Point::from_fractions(x, 2, y, 2);
                prop_assert_eq!(
                    contains_exact_with(&p, &poly, rule),
                    triangle_covers(&t, &p, rule),
                    "{:?} at ({}/2, {}/2) of {:?}", rule, x, y, t
                );
            }
        }
    }

    /// The active-edge-table filler equals the oracle on the same snapped polygon: simple,
    /// with holes, tangled, stellated, tie-heavy; both fill rules; every preset; 1..=10
    /// subpixel bits; centre and corner samples.
    #[test]
    fn scanline_equals_oracle(
        poly in any_polygon(32, 12),
        preset in prop::sample::select(Preset::ALL.to_vec()),
        bits in 1u32..=10,
        corner in any::<bool>(),
    ) {
        let target = target_with(32, preset, bits, corner);
        let exact = fill(&poly, &target, Model::ExactSnapped);
        let scan = fill(&poly, &target, Model::Scanline);
        check_agreement("exact-snapped", &exact, "scanline", &scan, &[], &target)
            .map_err(|v| TestCaseError::fail(format!("{v}\n{poly:?}")))?;
    }

    /// The row-by-row exact model equals the oracle on polygons as written (unsnapped),
    /// every family, both fill rules, every preset, centre and corner samples.
    #[test]
    fn rows_exact_equals_oracle(
        poly in any_polygon(24, 12),
        preset in prop::sample::select(Preset::ALL.to_vec()),
        corner in any::<bool>(),
    ) {
        let target = target_with(24, preset, 8, corner);
        let (mut a, mut b) = (Coverage::new(24, 24), Coverage::new(24, 24));
        rasterize_exact(&poly, 0, &target, &mut a);
        rasterproof::fill::polygon::rasterize_rows_exact(&poly, 0, &target, &mut b);
        prop_assert_eq!(differing_pixels(&a, &b), vec![]);
    }

    /// The polygon oracle on a triangle equals the triangle oracle (the tie rule's ε
    /// reading is the same rule), either winding, either fill rule, unsnapped.
    #[test]
    fn triangle_as_polygon_equals_triangle(
        t in any_triangle(24),
        preset in prop::sample::select(Preset::ALL.to_vec()),
        reversed in any::<bool>(),
        even_odd in any::<bool>(),
    ) {
        let t = if reversed { t.reversed() } else { t };
        let target = Target::new(24, 24, preset.convention()).unwrap();
        let rule = if even_odd { FillRule::EvenOdd } else { FillRule::NonZero };
        let poly = Polygon::new(t.v.to_vec(), rule);
        let (mut a, mut b) = (Coverage::new(24, 24), Coverage::new(24, 24));
        rasterproof::tri::exact::rasterize(&t, 0, &target, &mut a);
        rasterize_exact(&poly, 0, &target, &mut b);
        prop_assert_eq!(differing_pixels(&a, &b), vec![]);
    }

    /// A simple polygon's fill is the union of its triangulation's coverage, pixel for
    /// pixel, and no pixel is covered by two of its triangles; even-odd equals nonzero.
    #[test]
    fn fill_is_the_union_of_the_triangulation(
        poly in simple_polygon(40, 14),
        preset in prop::sample::select(Preset::ALL.to_vec()),
    ) {
        let target = Target::new(40, 40, preset.convention()).unwrap();
        let fixed = poly.to_fixed(&target.convention).unwrap();
        prop_assume!(validate(&fixed).is_ok()); // grid rounding can fold a tiny star
        let tris = triangulate(&fixed).unwrap();
        let (union, each) = triangulation_coverage(&tris, &target);
        let filled = fill(&poly, &target, Model::ExactSnapped);
        check_agreement("polygon fill", &filled, "union of the triangulation", &union, &[], &target)
            .map_err(|v| TestCaseError::fail(v.to_string()))?;
        check_no_double_cover(&each).map_err(|v| TestCaseError::fail(v.to_string()))?;
        let other = Polygon {
            fill_rule: match poly.fill_rule {
                FillRule::NonZero => FillRule::EvenOdd,
                FillRule::EvenOdd => FillRule::NonZero,
            },
            ..poly.clone()
        };
        prop_assert_eq!(differing_pixels(&filled, &fill(&other, &target, Model::Scanline)), vec![]);
    }

    /// On stellated polygons the rules differ exactly where the winding number is even
    /// and non-zero: even-odd is a subset of nonzero, and where they differ the oracle's
    /// winding number is 2 or -2 (for these stars, never more).
    #[test]
    fn rules_differ_where_the_contour_winds_twice(star in stellated_polygon(40, 1)) {
        let target = Target::new(40, 40, Preset::D3d11.convention()).unwrap();
        let nonzero = fill(&Polygon { fill_rule: FillRule::NonZero, ..star.clone() }, &target, Model::Scanline);
        let even_odd = fill(&Polygon { fill_rule: FillRule::EvenOdd, ..star.clone() }, &target, Model::Scanline);
        let snapped = star.snapped_exact(&target.convention);
        for d in differing_pixels(&nonzero, &even_odd) {
            prop_assert!(d.candidate.is_empty(), "even-odd covers ({}, {}) where nonzero does not", d.x, d.y);
            let sample = Point::from_fractions(2 * i64::from(d.x) + 1, 2, 2 * i64::from(d.y) + 1, 2);
            let w = rasterproof::fill::polygon::contour_winding_exact(&sample, &snapped.outline, target.convention.tie_rule);
            prop_assert_eq!(w.abs(), 2);
        }
    }

    /// The `fixed` model (triangulation) equals the scanline model on simple polygons.
    #[test]
    fn fixed_equals_scanline_on_simple_polygons(poly in simple_polygon(32, 10), bits in 1u32..=8) {
        let target = target_with(32, Preset::Gl, bits, false);
        let fixed = poly.to_fixed(&target.convention).unwrap();
        prop_assume!(validate(&fixed).is_ok());
        prop_assert_eq!(differing_pixels(&fill(&poly, &target, Model::Scanline), &fill(&poly, &target, Model::Fixed)), vec![]);
    }
}

/// The integer filler directly, far from the origin and at the envelope edge: a big
/// square reaching 2^21 px (2^29 subpixels at 8 bits) covers the whole canvas.
#[test]
fn scanline_at_the_envelope_edge() {
    let far = 1i64 << 21;
    let p = Polygon::new(
        pts(&[(-far, -far), (far, -far), (far, far), (-far, far)]),
        FillRule::NonZero,
    );
    let target = Target::new(16, 16, Preset::D3d11.convention()).unwrap();
    let fixed = p.to_fixed(&target.convention).unwrap();
    let mut c = Coverage::new(16, 16);
    rasterize(&fixed, 0, &target, &mut c);
    assert_eq!(c.covered_pixels(), 256);
    // A slanted edge from far away through the canvas: agrees with the oracle.
    let p = Polygon::new(pts(&[(-far, -far), (far, -far + 7), (3, 9)]), FillRule::EvenOdd);
    let exact = fill(&p, &target, Model::ExactSnapped);
    assert!(exact.covered_pixels() > 0);
    assert_eq!(differing_pixels(&exact, &fill(&p, &target, Model::Scanline)), vec![]);
    // One subpixel further is refused, naming the vertex.
    let beyond = Polygon::new(
        vec![
            Point::from_ints(0, 0),
            Point::from_fractions(far * 256 + 1, 256, 0, 1),
            Point::from_ints(0, 4),
        ],
        FillRule::NonZero,
    );
    let err = render(
        &Primitives {
            polygons: vec![beyond],
            ..Primitives::default()
        },
        &target,
        Model::Scanline,
    )
    .unwrap_err();
    assert!(err.to_string().starts_with("polygons[0].v[1].x: "), "{err}");
}

/// Triangles, lines and polygons in one render: ids in that order.
#[test]
fn polygon_ids_follow_triangles_and_lines() {
    let target = Target::new(16, 16, Preset::D3d11.convention()).unwrap();
    let tri = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
    let line = rasterproof::line::Line {
        from: Point::from_ints(8, 0),
        to: Point::from_ints(8, 3),
        rule: rasterproof::line::LineRule::Bresenham(rasterproof::line::BresenhamTie::Stay),
    };
    let poly = Polygon::new(pts(&[(10, 10), (14, 10), (14, 14), (10, 14)]), FillRule::NonZero);
    let c = render(
        &Primitives {
            triangles: vec![tri.into()],
            lines: vec![line],
            polygons: vec![poly],
            ..Primitives::default()
        },
        &target,
        Model::Scanline,
    )
    .unwrap();
    assert_eq!(c.owners(0, 0), &[0]);
    assert_eq!(c.owners(8, 1), &[1]);
    assert_eq!(c.owners(12, 12), &[2]);
    // The float models fill polygons too (issue 10): the pentagram's integer vertices
    // keep every edge value exact in f32, so float32 equals the oracle here.
    let star = Primitives {
        polygons: vec![pentagram(FillRule::NonZero)],
        ..Primitives::default()
    };
    let big = Target::new(100, 100, Preset::D3d11.convention()).unwrap();
    let float = render(&star, &big, Model::Float32).unwrap();
    assert_eq!(
        differing_pixels(&render(&star, &big, Model::Exact).unwrap(), &float),
        vec![]
    );
    assert!(float.covered_pixels() > 0);
}

/// Found by the polygon_fill fuzz target: an outline with no area (two of its three
/// vertices coincide) and a hole with area. Under the first rule (winding numbers summed
/// over normalised contours) the hole's inside was filled while triangulation returned no
/// triangles. Under the rule now (outline minus holes, each contour judged on its own)
/// the polygon is empty: every model and the triangulation agree on nothing.
#[test]
fn fuzz_case_01_hole_of_a_degenerate_outline() {
    let mut p = Polygon::new(pts(&[(9, 9), (9, 9), (-1, -6)]), FillRule::NonZero);
    p.holes.push(pts(&[(9, 9), (5, -3), (-8, -8)]));
    let target = Target::new(16, 16, Preset::D3d11.convention()).unwrap();
    let fixed = p.to_fixed(&target.convention).unwrap();
    assert_eq!(triangulate(&fixed), Ok(vec![]));
    for model in [Model::Exact, Model::ExactSnapped, Model::Scanline, Model::Fixed] {
        assert_eq!(fill(&p, &target, model).covered_pixels(), 0, "{model}");
    }
}

/// Found in review: a self-crossing outline with a hole, clipped. Summing normalised
/// windings made the clipped outline count the other way (its smaller loop has the
/// opposite area sign), so clip-then-fill lost pixels (10, 7) and (10, 8). Each contour
/// judged on its own keeps clipping exact: raster(clip(P, W)) == raster(P) ∩ raster(W).
#[test]
fn review_case_01_bow_tie_with_a_hole_clipped() {
    let mut p = Polygon::new(pts(&[(0, 0), (12, 12), (12, 4), (0, 16)]), FillRule::NonZero);
    p.holes.push(vec![
        Point::from_ints(9, 8),
        Point::from_fractions(23, 2, 6, 1),
        Point::from_fractions(23, 2, 10, 1),
    ]);
    let q = |n: i64| num_rational::BigRational::from_integer(n.into());
    let w = rasterproof::clip::Window::rect(q(9), q(0), q(16), q(16)).unwrap();
    let target = Target::new(16, 16, Preset::D3d11.convention()).unwrap();
    let cut = rasterproof::clip::sutherland_hodgman::clip_polygon(&p, &w);
    rasterproof::check::check_clip_raster(&p, &cut, &w, &target).unwrap();
    // Sample (10.5, 7.5) is in the right lobe of the bow tie and in the hole (at y = 7.5
    // the hole spans 9 + 2.5 * 0.5 / 2 = 9.625 < x < 11.5): not filled, clipped or not.
    let whole = fill(&p, &target, Model::Exact);
    assert!(whole.owners(10, 7).is_empty());
    // (11.5, 10.5): in the right lobe (triangle (8,8) (12,4) (12,12), x from 10.5 to 12 on
    // that row), below the hole (y 6..10): filled, clipped or not.
    assert_eq!(whole.owners(11, 10), &[0]);
    let clipped = fill(&cut, &target, Model::Exact);
    assert_eq!(clipped.owners(11, 10), &[0]);
    assert_eq!(
        differing_pixels(&clipped, &fill(&p, &target, Model::Scanline).restricted(9, 0, 16, 16)),
        vec![]
    );
}

/// All-inclusive and all-exclusive on a polygon are its closed and its open region, by
/// hand, with samples at pixel corners (integer coordinates):
/// - the pentagram's horizontal edge y = 35 runs from (2, 35) to (98, 35); the sample
///   (50, 35) lies on it between the top tip (winding 1, above) and the centre pentagon
///   (winding 2, below). Under nonzero both sides are inside, so the sample is in the open
///   region too: both rules cover it. Under even-odd the centre is outside, so the sample
///   is on the region's boundary: all-inclusive covers it, all-exclusive does not; the
///   top rules move it down into the centre (outside), the bottom rules up into the tip;
/// - the top vertex (50, 0) is a sample: the closed region holds it under either fill
///   rule, the open one does not, and no directional rule does (moved by (±ε, ±ε²) it
///   leaves the tip, whose sides rise at 90/29 to the vertex);
/// - the sample (4, 35) on the same edge but left of the pentagram's inner crossing lies
///   between the left arm (winding 1, below: x on the edge (79,90)->(2,35) at y = 35 + δ
///   is 2 + 77 δ / 55 < 4) and the outside (above): on the boundary under both fill
///   rules, held by the top rules (moved down) and not by the bottom ones.
#[test]
fn closed_and_open_polygon_by_hand() {
    let at = |fill: FillRule, x: i64, y: i64, rule: AnyTieRule| {
        contains_exact_with(&Point::from_ints(x, y), &pentagram(fill), rule)
    };
    for fill in [FillRule::NonZero, FillRule::EvenOdd] {
        assert!(at(fill, 50, 0, AnyTieRule::AllInclusive), "{fill:?}");
        assert!(!at(fill, 50, 0, AnyTieRule::AllExclusive), "{fill:?}");
        for rule in &AnyTieRule::ALL[..4] {
            assert!(!at(fill, 50, 0, *rule), "{fill:?} {rule:?}");
        }
        assert!(at(fill, 4, 35, AnyTieRule::AllInclusive), "{fill:?}");
        assert!(!at(fill, 4, 35, AnyTieRule::AllExclusive), "{fill:?}");
        // the top rules move it down into the arm, the bottom rules up out of it
        assert!(at(fill, 4, 35, AnyTieRule::TopLeft) && at(fill, 4, 35, AnyTieRule::TopRight));
        assert!(!at(fill, 4, 35, AnyTieRule::BottomLeft) && !at(fill, 4, 35, AnyTieRule::BottomRight));
    }
    for rule in AnyTieRule::ALL {
        assert!(at(FillRule::NonZero, 50, 35, rule), "{rule:?}");
    }
    let even_odd = |rule| at(FillRule::EvenOdd, 50, 35, rule);
    assert!(even_odd(AnyTieRule::AllInclusive) && !even_odd(AnyTieRule::AllExclusive));
    assert!(!even_odd(AnyTieRule::TopLeft) && !even_odd(AnyTieRule::TopRight));
    assert!(even_odd(AnyTieRule::BottomLeft) && even_odd(AnyTieRule::BottomRight));
    // The whole image: under nonzero the open region loses exactly the samples on the
    // outer boundary and the closed one gains them, so all-inclusive minus all-exclusive
    // is the samples on the ten outer segments, and no directional rule leaves that band.
    let target = Target::new(
        100,
        91,
        Convention {
            pixel_centre: PixelCentre::Corner,
            ..Convention::default()
        },
    )
    .unwrap();
    let image = |rule| {
        let mut c = Coverage::new(100, 91);
        rasterize_exact_with(&pentagram(FillRule::NonZero), 0, &target, rule, &mut c);
        c
    };
    let (closed, open) = (image(AnyTieRule::AllInclusive), image(AnyTieRule::AllExclusive));
    for rule in &AnyTieRule::ALL[..4] {
        let c = image(*rule);
        assert!(c.covered_pixels() > open.covered_pixels() && c.covered_pixels() < closed.covered_pixels());
        // open ⊆ c ⊆ closed
        assert!(differing_pixels(&c, &open)
            .iter()
            .all(|d| d.reference == [0] && closed.owners(d.x, d.y) == [0]));
    }
}
