//! Golden tests from independent sources: seed 003's triangle counted by a hand
//! derivation, and a hand-derived square whose diagonal passes through pixel centres.

use crate::common;

use common::q;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;
use rasterproof::convention::{Preset, Target};
use rasterproof::geom::{Point, Triangle};
use rasterproof::model::{prepare, render, render_triangles, Model, Primitives};
use rasterproof::scene::parse_scene;

const SEED003: &str = include_str!("../examples/scenes/seed003.json");

/// Seed 003's right triangle: vertical left edge x = L, horizontal bottom edge y = B,
/// hypotenuse from (L, T) to (R, B). Column by column, a sample (i+1/2, j+1/2) is inside
/// when L < x, and yh(x) < y < B, where yh is the hypotenuse solved for y. This counts
/// those samples with floor arithmetic on the line equation (no edge functions), and
/// asserts no sample lies exactly on an edge, so the tie rule cannot matter.
fn count_by_columns(l: &BigRational, t: &BigRational, r: &BigRational, b: &BigRational) -> u64 {
    let half = q(1, 2);
    let slope = (b - t) / (r - l);
    let mut total = 0u64;
    for i in 0..512i64 {
        let x = BigRational::from_integer(i.into()) + &half;
        assert_ne!(&x, l, "a sample on the left edge");
        if &x <= l || &x >= r {
            continue;
        }
        let yh = t + (&x - l) * &slope;
        // j + 1/2 > yh  <=>  j > yh - 1/2  <=>  j >= floor(yh - 1/2) + 1 (when not an integer)
        let lo = &yh - &half;
        assert!(!lo.is_integer(), "a sample on the hypotenuse at column {i}");
        let j_min = lo.floor().to_integer() + 1;
        let hi = b - &half;
        assert!(!hi.is_integer(), "a sample on the bottom edge");
        let j_max = hi.floor().to_integer(); // j + 1/2 < B
        if j_max >= j_min {
            let n: BigInt = j_max - j_min + 1;
            total += n.to_u64().unwrap();
        }
    }
    total
}

#[test]
fn seed003_exact_matches_a_column_count() {
    let scene = parse_scene(SEED003, "seed003.json").unwrap();
    let target = scene.target().unwrap();
    let cov = render_triangles(&scene.triangles(), &target, Model::Exact).unwrap();
    let expected = count_by_columns(
        &q(148_593, 1000),
        &q(685_928, 10_000),
        &q(491_407, 1000),
        &q(411_407, 1000),
    );
    assert_eq!(cov.covered_pixels() as u64, expected);
    assert_eq!(cov.double_covered().count(), 0);
}

/// Snapped to 1/256: L = 38040/256 = 148.59375, T = 17560/256 = 68.59375,
/// R = 125800/256 = 491.40625, B = 105320/256 = 411.40625. The hypotenuse becomes
/// y = x - 80 exactly, through every sample (i + 1/2, i - 79.5): all ties. It is a right
/// edge (moving a sample right by ε leaves the triangle), so those samples are out.
/// Column i (149..=490) then holds rows i-79..=410: 490 - i samples, in all
/// 0 + 1 + ... + 341 = 341 * 342 / 2 = 58311.
#[test]
fn seed003_snapped_matches_the_hand_count() {
    let scene = parse_scene(SEED003, "seed003.json").unwrap();
    let target = scene.target().unwrap();
    for model in [Model::ExactSnapped, Model::Fixed] {
        let cov = render_triangles(&scene.triangles(), &target, model).unwrap();
        assert_eq!(cov.covered_pixels(), 341 * 342 / 2, "{model}");
        assert_eq!(cov.owners(149, 70), &[0], "{model}: first pixel of column 149");
        assert!(
            cov.owners(149, 69).is_empty(),
            "{model}: the tie sample (149.5, 69.5) is out"
        );
        assert!(
            cov.owners(490, 410).is_empty(),
            "{model}: column 490 holds 490 - 490 = 0"
        );
        assert_eq!(cov.owners(489, 410), &[0], "{model}: column 489 holds row 410 only");
        assert!(cov.owners(489, 409).is_empty(), "{model}");
    }
}

/// Gouraud colours of seed 003: red + green + blue must sum to 255 up to the rounding of
/// each channel (barycentrics sum to 1 and the vertex colours are the unit axes times 255),
/// and one channel is derived by hand below.
#[test]
fn seed003_colours_sum_to_255() {
    let scene = parse_scene(SEED003, "seed003.json").unwrap();
    let target = scene.target().unwrap();
    let prepared = prepare(&scene.primitives(), &target, Model::Exact).unwrap();
    let colours = scene.triangles[0].colours.unwrap();
    for (x, y) in [(149, 410), (300, 300), (489, 409), (150, 72)] {
        let c = prepared.shade(0, &colours, x, y, &target);
        let sum: i32 = c.iter().map(|&v| i32::from(v)).sum();
        assert!((254..=256).contains(&sum), "({x},{y}) {c:?}");
    }
    // (149.5, 410.5): green weight = (B - y) / (B - T) exactly (v1 is the only vertex off the
    // bottom edge), = (411.407 - 410.5) / (411.407 - 68.5928) = 0.907 / 342.8142 -> 0.67 of 255.
    let c = prepared.shade(0, &colours, 149, 410, &target);
    let green = q(907, 1000) / q(3_428_142, 10_000) * BigRational::from_integer(BigInt::from(255));
    assert_eq!(i64::from(c[1]), green.round().to_integer().to_i64().unwrap());
}

/// Prints the float32-vs-exact figures for the note, and asserts every pixel float32 gets
/// wrong lies within 1/1000 px of an edge (float error only moves samples that are
/// nearly on an edge).
#[test]
fn seed003_float32_differs_only_near_edges() {
    let scene = parse_scene(SEED003, "seed003.json").unwrap();
    let target = scene.target().unwrap();
    let tris = scene.triangles();
    let exact = render_triangles(&tris, &target, Model::Exact).unwrap();
    let float = render_triangles(&tris, &target, Model::Float32).unwrap();
    let diffs = rasterproof::check::differing_pixels(&exact, &float);
    let t = &tris[0];
    for d in &diffs {
        let p = Point::new(q(2 * i64::from(d.x) + 1, 2), q(2 * i64::from(d.y) + 1, 2));
        let near = (0..3).any(|k| {
            let (a, b) = (&t.v[k], &t.v[(k + 1) % 3]);
            let e = rasterproof::edge::exact::edge_function(a, b, &p);
            let len2 = (&b.x - &a.x) * (&b.x - &a.x) + (&b.y - &a.y) * (&b.y - &a.y);
            // distance^2 = E^2 / |b - a|^2 < (1/1000)^2
            &e * &e / len2 < q(1, 1_000_000)
        });
        assert!(near, "float32 differs at ({}, {}) far from every edge", d.x, d.y);
    }
    let prepared_e = prepare(&Primitives::from_triangles(&tris), &target, Model::Exact).unwrap();
    let prepared_f = prepare(&Primitives::from_triangles(&tris), &target, Model::Float32).unwrap();
    let colours = scene.triangles[0].colours.unwrap();
    let mut colour_diffs = 0;
    for (x, y, _) in exact.iter() {
        if !float.owners(x, y).is_empty()
            && prepared_e.shade(0, &colours, x, y, &target) != prepared_f.shade(0, &colours, x, y, &target)
        {
            colour_diffs += 1;
        }
    }
    println!(
        "seed 003: exact covers {} pixels, float32 {}; coverage differs at {} pixels; colour differs at {} of the pixels both cover",
        exact.covered_pixels(),
        float.covered_pixels(),
        diffs.len(),
        colour_diffs
    );
}

/// The square (0,0)-(4,4) split along its diagonal from (0,0) to (4,4):
/// T0 = (0,0) (4,0) (4,4) is the upper-right half {y < x}, T1 = (0,0) (4,4) (0,4) the
/// lower-left half {y > x}. The diagonal samples (k+1/2, k+1/2) lie on the shared edge.
/// Moving such a sample right by ε gives y < x: it lands in T0, under top-left and
/// bottom-left alike (the ε² term only matters for horizontal edges). No other sample
/// touches an edge (edges are at integers, samples at halves). So, by hand:
///
/// ```text
///   row 0:  0 0 0 0
///   row 1:  1 0 0 0
///   row 2:  1 1 0 0
///   row 3:  1 1 1 0
/// ```
const SQUARE_OWNERS: [[u32; 4]; 4] = [[0, 0, 0, 0], [1, 0, 0, 0], [1, 1, 0, 0], [1, 1, 1, 0]];

fn square() -> Vec<Triangle> {
    let p = Point::from_ints;
    vec![
        Triangle::new(p(0, 0), p(4, 0), p(4, 4)),
        Triangle::new(p(0, 0), p(4, 4), p(0, 4)),
    ]
}

#[test]
fn square_diagonal_owned_once_by_hand() {
    for preset in [Preset::D3d11, Preset::Gl, Preset::Vulkan, Preset::Cts] {
        let target = Target::new(4, 4, preset.convention()).unwrap();
        for model in [Model::Exact, Model::ExactSnapped, Model::Fixed] {
            let cov = render_triangles(&square(), &target, model).unwrap();
            for (y, row) in SQUARE_OWNERS.iter().enumerate() {
                for (x, owner) in row.iter().enumerate() {
                    assert_eq!(
                        cov.owners(x as u32, y as u32),
                        &[*owner],
                        "{model} {} pixel ({x},{y})",
                        preset.name()
                    );
                }
            }
        }
    }
}

/// The other diagonal, from (4,0) to (0,4): samples (k+1/2, 3-k+1/2) lie on it.
/// A = (0,0) (4,0) (0,4) is the upper-left half {x + y < 4}, B = (4,0) (4,4) (0,4) the
/// lower-right half {x + y > 4}. Moving a diagonal sample right by ε gives x + y > 4: it
/// lands in B. So the anti-diagonal pixels (3,0) (2,1) (1,2) (0,3) belong to B (id 1).
#[test]
fn square_anti_diagonal_by_hand() {
    let p = Point::from_ints;
    let mesh = [
        Triangle::new(p(0, 0), p(4, 0), p(0, 4)),
        Triangle::new(p(4, 0), p(4, 4), p(0, 4)),
    ];
    for preset in [Preset::D3d11, Preset::Gl] {
        let target = Target::new(4, 4, preset.convention()).unwrap();
        for model in [Model::ExactSnapped, Model::Fixed] {
            let cov = render_triangles(&mesh, &target, model).unwrap();
            for y in 0..4u32 {
                for x in 0..4u32 {
                    let expected = if x + y >= 3 { 1 } else { 0 };
                    assert_eq!(cov.owners(x, y), &[expected], "{model} {} ({x},{y})", preset.name());
                }
            }
        }
    }
}

/// A horizontal shared edge through sample centres: two triangles sharing the edge
/// y = 1.5 from x = 0 to x = 4, one above
/// (apex (2, -2.5)) and one below (apex (2, 5.5)). Samples (k+1/2, 1.5) lie on it. Top-left:
/// moving down by ε² puts them in the lower triangle; bottom-left: moving up, the upper one.
#[test]
fn horizontal_shared_edge_follows_the_eps_squared_term() {
    let e = |x: i64, y2: i64| Point::from_fractions(x, 1, y2, 2);
    let upper = Triangle::new(e(0, 3), e(4, 3), e(2, -5));
    let lower = Triangle::new(e(0, 3), e(4, 3), e(2, 11));
    for (preset, owner) in [(Preset::D3d11, 1u32), (Preset::Gl, 0u32)] {
        let target = Target::new(4, 4, preset.convention()).unwrap();
        for model in [Model::ExactSnapped, Model::Fixed] {
            let cov = render_triangles(&[upper.clone(), lower.clone()], &target, model).unwrap();
            // (1,1) and (2,1): well inside both apex spans; their samples (1.5,1.5), (2.5,1.5) are on the edge.
            for x in [1u32, 2] {
                assert_eq!(cov.owners(x, 1), &[owner], "{model} {}", preset.name());
            }
        }
    }
}

/// Review finds (named regressions): an exact diamond-exit line with an endpoint at the i64
/// limits must not overflow, and one far beyond the canvas must not scan the whole canvas;
/// the public integer-barycentric checker must not overflow for an off-canvas pixel.
#[test]
fn review_case_01_exact_diamond_line_at_i64_limits() {
    for (a, b) in [
        ("\"-9223372036854775808\"", "3"),
        ("3", "\"9223372036854775807\""),
        ("\"1e19\"", "\"1e20\""),
    ] {
        let text = format!(
            r#"{{"width": 400, "height": 400, "lines": [{{"from": [{a}, "1/2"], "to": [{b}, "5/2"], "rule": "diamond"}}]}}"#
        );
        let s = parse_scene(&text, "s.json").unwrap();
        let target = s.target().unwrap();
        let c = render(
            &Primitives {
                lines: s.lines.clone(),
                ..Primitives::default()
            },
            &target,
            Model::Exact,
        )
        .unwrap();
        // Only lines that cross the canvas cover anything; none of these is near row 0..3 of
        // columns < 400 except the first two, which do cross it.
        assert!(c.covered_pixels() <= 400, "{a} -> {b}");
    }
}

#[test]
fn review_case_02_barycentric_checker_off_canvas() {
    let mut conv = Preset::D3d11.convention();
    conv.subpixel_bits = 16;
    let target = Target::new(16, 16, conv).unwrap();
    let t = Triangle::new(
        Point::from_ints(0, -8192),
        Point::from_ints(1, 8192),
        Point::from_ints(-8192, 0),
    );
    let f = t.snapped(&conv).to_fixed().unwrap();
    assert!(rasterproof::check::check_barycentric_fixed(&f, 1_000_000, u32::MAX, &target).is_ok());
}
