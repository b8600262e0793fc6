//! Exact area coverage (`area::exact`, the plain oracle), checked against what other roads
//! give: Sutherland-Hodgman clipping summed by the shoelace formula, inclusion-exclusion
//! of two triangles, the polygon's whole area, a spade triangulation's hull, rotations,
//! reversals and whole-pixel moves, and the one-sample oracles at the pixel centre.

use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;

use crate::common::{canvas, config, grey_options};
use rasterproof::area::exact::{pixel, rasterize, value};
use rasterproof::area::{cells, float, ftgrays, supersample, AreaImage, Quantization};
use rasterproof::area::{path_signed_area, shoelace, triangle_shape, AreaShape, Semantics};
use rasterproof::check::triangle_covers;
use rasterproof::check::{check_area_additivity, check_area_bounds, check_area_conservation};
use rasterproof::clip::sutherland_hodgman::clip_exact;
use rasterproof::clip::Window;
use rasterproof::convention::AnyTieRule;
use rasterproof::fill::polygon::contains_exact_with;
use rasterproof::geom::{FillRule, Point, Polygon, Triangle};
use rasterproof::strategy::polygon::{any_polygon, star_polygon};
use rasterproof::strategy::{any_triangle, delaunay_mesh};

fn int(v: i64) -> BigRational {
    BigRational::from_integer(v.into())
}

/// `n / d` as a rational.
fn r(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// The point `(x, y)`.
fn p(x: BigRational, y: BigRational) -> Point {
    Point::new(x, y)
}

/// The pixels `(px, py)` that the shapes' bounding box meets (negative ones too).
fn pixels_of(shapes: &[AreaShape]) -> Vec<(i64, i64)> {
    let points: Vec<&Point> = shapes.iter().flat_map(Polygon::contours).flatten().collect();
    let lo = |f: fn(&Point) -> &BigRational| points.iter().map(|p| f(p).floor().to_integer()).min().unwrap();
    let hi = |f: fn(&Point) -> &BigRational| points.iter().map(|p| f(p).ceil().to_integer()).max().unwrap();
    let to = |b: num_bigint::BigInt| i64::try_from(b).unwrap();
    let (x0, x1, y0, y1) = (to(lo(|p| &p.x)), to(hi(|p| &p.x)), to(lo(|p| &p.y)), to(hi(|p| &p.y)));
    (y0..y1).flat_map(|y| (x0..x1).map(move |x| (x, y))).collect()
}

/// The half-planes of the pixel square `(px, py)`.
fn pixel_window(px: i64, py: i64) -> Window {
    Window::rect(int(px), int(py), int(px + 1), int(py + 1)).unwrap()
}

/// A triangle with vertices on the quarter-pixel grid of `[-1, 5]^2` (degenerate ones too).
fn small_triangle() -> impl Strategy<Value = Triangle> {
    let c = (-4i64..=20).prop_map(|q| BigRational::new(q.into(), 4.into()));
    let v = (c.clone(), c).prop_map(|(x, y)| Point::new(x, y));
    [v.clone(), v.clone(), v].prop_map(|[a, b, c]| Triangle::new(a, b, c))
}

/// Runs `rasterproof ARGS`: its exit code, stdout and stderr.
fn rasterproof(args: &[&str]) -> (Option<i32>, String, String) {
    let out = assert_cmd::Command::cargo_bin("rasterproof")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

fn shape_of(poly: &Polygon) -> AreaShape {
    poly.clone()
}

fn moved(s: &AreaShape, f: impl Fn(&Point) -> Point) -> AreaShape {
    Polygon {
        outline: s.outline.iter().map(&f).collect(),
        holes: s.holes.iter().map(|c| c.iter().map(&f).collect()).collect(),
        fill_rule: s.fill_rule,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..config("proptest-regressions/area.txt") })]

    /// The accumulated value of a pixel is the signed area of each contour clipped to the
    /// pixel (Sutherland-Hodgman keeps the winding number inside a convex window), summed:
    /// for tangled, stellated and holed polygons alike.
    #[test]
    fn accumulated_is_the_clipped_shoelace(poly in any_polygon(5, 7)) {
        let shape = shape_of(&poly);
        let shapes = [shape.clone()];
        for (px, py) in pixels_of(&shapes) {
            let planes = pixel_window(px, py).half_planes();
            let clipped: BigRational = poly.contours().map(|c| shoelace(&clip_exact(c, &planes))).sum();
            let (_, acc) = pixel(&shapes, px, py);
            prop_assert_eq!(&acc[0], &clipped, "pixel ({}, {})", px, py);
        }
    }

    /// Cell accumulation (the scanline renderers' method, exactly) gives the plain
    /// oracle's signed integral at every pixel of the canvas, and the same folded images.
    #[test]
    fn cells_equal_the_plain_oracle(poly in any_polygon(5, 7), t in small_triangle()) {
        let shapes = [shape_of(&poly), triangle_shape(&t)];
        for shape in &shapes {
            let one = std::slice::from_ref(shape);
            let got: std::collections::BTreeMap<(u32, u32), BigRational> =
                cells::accumulate(shape, 6, 6).into_iter().map(|(x, y, v)| ((x, y), v)).collect();
            for y in 0..6u32 {
                for x in 0..6u32 {
                    let (_, acc) = pixel(one, i64::from(x), i64::from(y));
                    let cell = got.get(&(x, y)).cloned().unwrap_or_else(BigRational::zero);
                    prop_assert_eq!(&cell, &acc[0], "pixel ({}, {})", x, y);
                }
            }
        }
        for s in [Semantics::Accumulated, Semantics::AccumulatedUnclamped] {
            prop_assert_eq!(cells::rasterize(&shapes, 6, 6, s), Some(rasterize(&shapes, 6, 6, s)));
        }
        prop_assert_eq!(cells::rasterize(&shapes, 6, 6, Semantics::True), None);
    }

    /// Area conservation: the accumulated values of every pixel add up to the polygon's
    /// path's signed area; true coverage lies in [0, 1], and so do the folded values.
    #[test]
    fn conservation_and_bounds(poly in any_polygon(5, 7)) {
        let shape = shape_of(&poly);
        let shapes = [shape.clone()];
        let mut total = BigRational::zero();
        for (px, py) in pixels_of(&shapes) {
            let (union, acc) = pixel(&shapes, px, py);
            total += &acc[0];
            prop_assert!(!union.is_negative() && union <= BigRational::one());
            let folded = value(&shapes, px, py, Semantics::Accumulated);
            prop_assert!(!folded.is_negative() && folded <= BigRational::one());
        }
        prop_assert_eq!(total, path_signed_area(&shape));
    }

    /// A simple polygon: true and accumulated coverage agree at every pixel and add up to
    /// its area.
    #[test]
    fn simple_polygons_accumulate_their_true_area(poly in star_polygon(6, 9, false, 4)) {
        let shapes = [shape_of(&poly)];
        let mut total = BigRational::zero();
        for (px, py) in pixels_of(&shapes) {
            let t = value(&shapes, px, py, Semantics::True);
            prop_assert_eq!(&t, &value(&shapes, px, py, Semantics::Accumulated));
            total += t;
        }
        prop_assert_eq!(total, shoelace(&poly.outline).abs());
    }

    /// Two triangles: their union's area in a pixel is each one's area less the area of
    /// their intersection (one clipped by the other, a convex window, then by the pixel).
    #[test]
    fn union_is_inclusion_exclusion(a in small_triangle(), b in small_triangle()) {
        let shapes = [triangle_shape(&a), triangle_shape(&b)];
        let both = Window::convex(b.v.to_vec()).ok().map(|w| clip_exact(&a.v, &w.half_planes()));
        for (px, py) in pixels_of(&shapes) {
            let planes = pixel_window(px, py).half_planes();
            let area = |c: &[Point]| shoelace(&clip_exact(c, &planes)).abs();
            let overlap = both.as_ref().map_or_else(BigRational::zero, |c| area(c));
            let expected = area(&a.v) + area(&b.v) - overlap;
            prop_assert_eq!(value(&shapes, px, py, Semantics::True), expected, "pixel ({}, {})", px, py);
        }
    }

    /// Additivity: the triangles of a spade triangulation cover every pixel exactly as
    /// their convex hull does, summed one by one (no seam, no overlap) and as a union.
    #[test]
    fn a_triangulation_adds_up_to_its_hull(mesh in delaunay_mesh([0, 0], 4, 2, 7)) {
        let hull = [Polygon::new(mesh.outline.clone(), FillRule::NonZero)];
        let triangles: Vec<AreaShape> = mesh.triangles.iter().map(triangle_shape).collect();
        for (px, py) in pixels_of(&hull) {
            let whole = value(&hull, px, py, Semantics::True);
            let (union, acc) = pixel(&triangles, px, py);
            let summed: BigRational = acc.iter().map(Signed::abs).sum();
            prop_assert_eq!(&union, &whole, "pixel ({}, {})", px, py);
            prop_assert_eq!(&summed, &whole, "pixel ({}, {})", px, py);
            prop_assert_eq!(value(&triangles, px, py, Semantics::Accumulated), whole);
        }
    }

    /// The checkers pass the exact images: a triangulation's triangles add up to the hull
    /// (pixel by pixel and in total), every value in [0, 1]. Supersampling adds up too
    /// (each sample has one owner). f32 accumulation stays within 2^-16 of the exact
    /// value at every pixel here (quarter-pixel coordinates, a 4x4 canvas).
    #[test]
    fn the_checkers_pass_the_exact_images(mesh in delaunay_mesh([0, 0], 4, 2, 7)) {
        let hull = [Polygon::new(mesh.outline.clone(), FillRule::NonZero)];
        let whole = rasterize(&hull, 4, 4, Semantics::True);
        let pieces: Vec<AreaImage> = mesh
            .triangles
            .iter()
            .map(|t| rasterize(&[triangle_shape(t)], 4, 4, Semantics::True))
            .collect();
        prop_assert_eq!(check_area_additivity(&pieces, &whole), Ok(()));
        prop_assert_eq!(check_area_bounds(&whole), Ok(()));
        prop_assert_eq!(check_area_conservation(&whole, &shoelace(&mesh.outline).abs()), Ok(()));
        let sampled: Vec<AreaImage> =
            mesh.triangles.iter().map(|t| supersample::rasterize(&[triangle_shape(t)], 4, 4, 4)).collect();
        prop_assert_eq!(check_area_additivity(&sampled, &supersample::rasterize(&hull, 4, 4, 4)), Ok(()));
        let f = float::rasterize(&hull, 4, 4, Semantics::Accumulated);
        let bound = BigRational::new(1.into(), 65536.into());
        let got = AreaImage::from_f32(4, 4, Semantics::Accumulated, &f).unwrap();
        for y in 0..4 {
            for x in 0..4 {
                let err = (got.value(x, y) - whole.value(x, y)).abs();
                prop_assert!(err <= bound, "pixel ({}, {}): f32 off by {}", x, y, err);
            }
        }
    }

    /// FreeType's method stays within a level and two per edge meeting the pixel (of 255)
    /// of the exact value quantized as FreeType quantizes it, on polygons whose points lie
    /// on its 1/64 px grid (its reciprocal divisions and `~` are its only departures
    /// there): nonzero and even-odd.
    #[test]
    fn ftgrays_is_near_the_exact_levels(poly in any_polygon(4, 7)) {
        // The polygon on FreeType's 1/64 px grid first (its own rounding is another error).
        let grid = BigRational::from_integer(64.into());
        let poly = moved(&poly, |p| Point::new((&p.x * &grid).round() / &grid, (&p.y * &grid).round() / &grid));
        let shapes = [poly.clone()];
        let levels = ftgrays::rasterize(&shapes, 4, 4).unwrap();
        let exact = rasterize(&shapes, 4, 4, Semantics::Accumulated).levels(Quantization::FtGrays);
        for (k, (&got, &want)) in levels.iter().zip(&exact).enumerate() {
            let off = (i32::from(got) - i32::from(want)).abs();
            // A level per crossing its reciprocal division makes short, and one for the
            // truncation (tests/fuzz_cases.rs, fuzz_case_04: 3 levels over 9 edges).
            let (x, y) = (k as i64 % 4, k as i64 / 4);
            let edges = i32::try_from(rasterproof::area::exact::explain(&shapes, x, y).edges.len()).unwrap();
            prop_assert!(off <= 1 + 2 * edges, "pixel ({}, {}): FreeType's method {} against {} exactly", x, y, got, want);
        }
    }

    /// Rotating by a quarter turn, reversing every contour and moving by whole pixels
    /// change no pixel's value under any semantics.
    #[test]
    fn rotation_reversal_translation(poly in any_polygon(4, 6), dx in -3i64..4, dy in -3i64..4) {
        let shape = shape_of(&poly);
        let shapes = [shape.clone()];
        // (x, y) -> (-y, x) takes pixel (px, py) to (-py - 1, px).
        let turned = [moved(&shape, |p| Point::new(-p.y.clone(), p.x.clone()))];
        let shifted = [moved(&shape, |p| Point::new(&p.x + int(dx), &p.y + int(dy)))];
        let mut reversed = shape.clone();
        reversed.outline.reverse();
        for c in &mut reversed.holes {
            c.reverse();
        }
        let reversed = [reversed];
        for (px, py) in pixels_of(&shapes) {
            for s in Semantics::ALL {
                let v = value(&shapes, px, py, s);
                prop_assert_eq!(&value(&turned, -py - 1, px, s), &v);
                prop_assert_eq!(&value(&shifted, px + dx, py + dy, s), &v);
                prop_assert_eq!(&value(&reversed, px, py, s), &v);
            }
        }
    }

    /// The one-sample oracles agree: a pixel a shape covers wholly has its centre covered
    /// under every tie rule, and a pixel it does not touch (area 0) under none.
    #[test]
    fn whole_and_empty_pixels_agree_with_the_sample(poly in any_polygon(4, 6), t in any_triangle(4)) {
        let shapes = [shape_of(&poly)];
        let half = BigRational::new(1.into(), 2.into());
        for (px, py) in pixels_of(&shapes) {
            let t = value(&shapes, px, py, Semantics::True);
            let centre = Point::new(int(px) + &half, int(py) + &half);
            for rule in AnyTieRule::ALL {
                let covered = contains_exact_with(&centre, &poly, rule);
                if t.is_one() {
                    prop_assert!(covered, "pixel ({}, {}) whole, centre not covered under {:?}", px, py, rule);
                }
                if t.is_zero() {
                    prop_assert!(!covered, "pixel ({}, {}) empty, centre covered under {:?}", px, py, rule);
                }
            }
        }
        // A triangle, by its edge functions, in the pixels near the canvas.
        let shapes = [triangle_shape(&t)];
        for py in -1..5 {
            for px in -1..5 {
                let v = value(&shapes, px, py, Semantics::True);
                let centre = Point::new(int(px) + &half, int(py) + &half);
                for rule in AnyTieRule::ALL {
                    let covered = triangle_covers(&t, &centre, rule);
                    prop_assert!(!v.is_one() || covered, "({}, {}) whole, {:?}", px, py, rule);
                    prop_assert!(!v.is_zero() || !covered, "({}, {}) empty, {:?}", px, py, rule);
                }
            }
        }
    }
}

/// A triangle's pixels by hand, on the quarter grid: (1/2, 1/2) (5/2, 1/2) (1/2, 5/2).
/// Pixel (0, 0): the square [1/2, 1]^2, 1/4. Pixel (1, 0): x in [1, 2], y in [1/2, 1]
/// under x + y <= 3: wholly under it, 1/2. Pixel (1, 1): x, y >= 1, x + y <= 3: the
/// triangle (1,1) (2,1) (1,2), 1/2. Pixel (2, 0): x in [2, 5/2], y from 1/2 to 3 - x (at
/// most 1): the triangle (2,1/2) (5/2,1/2) (2,1), 1/8. The whole: (2 x 2) / 2 = 2.
#[test]
fn quarter_grid_triangle_by_hand() {
    let q = |n: i64| BigRational::new(n.into(), 2.into());
    let t = Triangle::new(Point::new(q(1), q(1)), Point::new(q(5), q(1)), Point::new(q(1), q(5)));
    let shapes = [triangle_shape(&t)];
    let v = |x, y| value(&shapes, x, y, Semantics::True);
    assert_eq!(v(0, 0), r(1, 4));
    assert_eq!(v(1, 0), r(1, 2));
    assert_eq!(v(1, 1), r(1, 2));
    assert_eq!(v(2, 0), r(1, 8));
    assert_eq!(v(2, 2), r(0, 1));
    let total: BigRational = pixels_of(&shapes).into_iter().map(|(x, y)| v(x, y)).sum();
    assert_eq!(total, r(2, 1));
}

/// `render --coverage area` on a scene derived by hand: the triangle (0,0) (3,0) (0,3) on a
/// 3x3 canvas, unsnapped. Pixels on the diagonal below it are whole ((0,0), (1,0), (0,1)),
/// those the hypotenuse x + y = 3 crosses diagonally are halves ((2,0), (1,1), (0,2)), the
/// rest empty; total 9/2. The grey PNG: whole 255, half 127.5 -> 128 (round, ties to
/// even) or 128 (ftgrays: 128 of 256); 16-bit 65535 and 32768. JSON holds the fractions.
#[test]
fn render_area_cli_by_hand() {
    let dir = crate::tempdir::Dir::new("area-cli");
    let scene = dir.path().join("t.json");
    std::fs::write(
        &scene,
        r#"{"width": 3, "height": 3, "triangles": [{"v": [[0, 0], [3, 0], [0, 3]]}]}"#,
    )
    .unwrap();
    let run = |args: &[&str]| rasterproof(&[&["render", scene.to_str().unwrap()], args].concat());
    let (code, text, _) = run(&["--coverage", "area", "--model", "exact"]);
    assert_eq!(code, Some(0));
    assert!(text.starts_with("##5\n#5.\n5..\n"), "{text}");
    assert!(
        text.contains("6 pixels with area, 3 of them whole; total 9/2 = 4.5"),
        "{text}"
    );
    let (code, json, _) = run(&["--coverage", "area", "--model", "exact", "--format", "json"]);
    assert_eq!(code, Some(0));
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(v["semantics"], "true");
    assert_eq!(
        v["pixels"],
        serde_json::json!([
            [0, 0, "1"],
            [1, 0, "1"],
            [2, 0, "1/2"],
            [0, 1, "1"],
            [1, 1, "1/2"],
            [0, 2, "1/2"]
        ])
    );
    for (q, whole, half) in [
        ("round", 255u16, 128u16),
        ("ftgrays", 255, 128),
        ("truncate", 255, 127),
        ("round16", 65535, 32768),
    ] {
        let png = dir.path().join(format!("{q}.png"));
        let (code, _, err) = run(&[
            "--coverage",
            "area",
            "--model",
            "exact",
            "--quantization",
            q,
            "--grey-out",
            png.to_str().unwrap(),
        ]);
        assert_eq!(code, Some(0), "{err}");
        let img = image::open(&png).unwrap();
        let grey = img.to_luma16();
        let level = |x, y| {
            let l = grey.get_pixel(x, y).0[0];
            // to_luma16 widens 8-bit levels by x 257.
            if q == "round16" {
                l
            } else {
                l / 257
            }
        };
        assert_eq!(
            [level(0, 0), level(2, 0), level(1, 1), level(2, 2)],
            [whole, half, half, 0],
            "{q}"
        );
    }
    // Bad input: lines, a non-exact model, an unknown semantics, a picture flag.
    let lines = dir.path().join("l.json");
    std::fs::write(
        &lines,
        r#"{"width": 3, "height": 3, "lines": [{"from": [0, 0], "to": [2, 2]}]}"#,
    )
    .unwrap();
    let (code, _, err) = rasterproof(&["render", lines.to_str().unwrap(), "--coverage", "area"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("lines have no area"), "{err}");
    for (args, says) in [
        (
            &["--coverage", "area", "--model", "fixed"][..],
            "model fixed is not one of",
        ),
        (
            &["--coverage", "area", "--semantics", "mean"][..],
            "--semantics: unknown semantics \"mean\"",
        ),
        (
            &["--coverage", "area", "-o", "x.png"][..],
            "-o, --colors-out, --values-out, --ids-out and --scale are for --coverage sample",
        ),
        (&["--semantics", "accumulated"][..], "need --coverage area"),
        (&["--coverage", "areas"][..], "--coverage: unknown kind \"areas\""),
    ] {
        let (code, _, err) = run(args);
        assert_eq!(code, Some(2), "{args:?}");
        assert!(err.contains(says), "{args:?}: {err}");
    }
}

/// The contenders break what the exact models keep, and the checkers say by how much.
/// Supersampling 4x4 the triangle (0,0) (1,0) (0,1) (y down): of the 16 samples
/// ((i + 1/2)/4, (j + 1/2)/4), 6 lie strictly inside (i + j <= 2) and 4 on the hypotenuse
/// (i + j = 3), the triangle's lower-right edge, which the top-left rule does not give it:
/// 6/16 = 3/8, not 1/2. f32 accumulation of a triangle of area 1/3 cannot add up to 1/3
/// (a sum of f32 values has a power-of-two denominator).
#[test]
fn the_contenders_break_conservation() {
    let t = Triangle::new(p(r(0, 1), r(0, 1)), p(r(1, 1), r(0, 1)), p(r(0, 1), r(1, 1)));
    let sampled = supersample::rasterize(&[triangle_shape(&t)], 1, 1, 4);
    assert_eq!(sampled.value(0, 0), r(3, 8));
    let v = check_area_conservation(&sampled, &r(1, 2)).unwrap_err();
    assert!(v.message.contains("3/8") && v.message.contains("off by -1/8"), "{v}");
    // Exact: 1/2.
    let exact = rasterize(&[triangle_shape(&t)], 1, 1, Semantics::True);
    assert_eq!(check_area_conservation(&exact, &r(1, 2)), Ok(()));
    // A third: (0,0) (1,0) (0,2/3).
    let third = Triangle::new(p(r(0, 1), r(0, 1)), p(r(1, 1), r(0, 1)), p(r(0, 1), r(2, 3)));
    let f = float::rasterize(&[triangle_shape(&third)], 2, 2, Semantics::Accumulated);
    let got = AreaImage::from_f32(2, 2, Semantics::Accumulated, &f).unwrap();
    let v = check_area_conservation(&got, &r(1, 3)).unwrap_err();
    assert!(v.message.contains("the area drawn is 1/3"), "{v}");
    assert_eq!(
        check_area_conservation(&rasterize(&[triangle_shape(&third)], 2, 2, Semantics::True), &r(1, 3)),
        Ok(())
    );
    // FreeType's envelope: 24.8 coordinates within 2^31, so |v| < 2^23 px.
    let far = Triangle::new(p(r(0, 1), r(0, 1)), p(r(1 << 23, 1), r(0, 1)), p(r(0, 1), r(1, 1)));
    let e = ftgrays::rasterize(&[triangle_shape(&far)], 2, 2).unwrap_err();
    assert!(
        e.contains("shape 0: (8388608, 0) is outside FreeType's 24.8 envelope"),
        "{e}"
    );
    let near = Triangle::new(
        p(r(0, 1), r(0, 1)),
        p(r((1 << 23) - 1, 1), r(0, 1)),
        p(r(0, 1), r(1, 1)),
    );
    assert!(ftgrays::rasterize(&[triangle_shape(&near)], 2, 2).is_ok());
    // Bad input: a NaN in a renderer's output, and a wrong length.
    let e = AreaImage::from_f32(2, 1, Semantics::True, &[0.5, f32::NAN]).unwrap_err();
    assert!(e.contains("pixel (1, 0)") && e.contains("not a number"), "{e}");
    assert!(AreaImage::from_f32(2, 2, Semantics::True, &[0.0; 3])
        .unwrap_err()
        .contains("3 values for a 2x2 canvas"));
}

/// f32 accumulation leaves seams and overlaps between abutting shapes that the exact
/// models do not: an 8x4 quadrilateral split along the diagonal (0,0)-(8,4), one corner at
/// (8, 1/3) (not an f32). The exact halves add up to the whole at every pixel; the f32
/// halves do not, and the checker names the pixel.
#[test]
fn f32_accumulation_leaves_seams() {
    // A square split along a shallow diagonal; the f32 values of the halves are added in
    // f32 per pixel by the renderer (its accumulation buffer), then read exactly.
    let (a, b, c, d) = (
        p(r(0, 1), r(0, 1)),
        p(r(8, 1), r(1, 3)),
        p(r(8, 1), r(4, 1)),
        p(r(0, 1), r(4, 1)),
    );
    let halves = [
        Triangle::new(a.clone(), b.clone(), c.clone()),
        Triangle::new(a.clone(), c.clone(), d.clone()),
    ];
    let whole = [Polygon::new(vec![a, b, c, d], FillRule::NonZero)];
    let exact_pieces: Vec<AreaImage> = halves
        .iter()
        .map(|t| rasterize(&[triangle_shape(t)], 8, 4, Semantics::True))
        .collect();
    assert_eq!(
        check_area_additivity(&exact_pieces, &rasterize(&whole, 8, 4, Semantics::True)),
        Ok(())
    );
    let f32_image = |shapes: &[AreaShape]| {
        AreaImage::from_f32(
            8,
            4,
            Semantics::Accumulated,
            &float::rasterize(shapes, 8, 4, Semantics::Accumulated),
        )
        .unwrap()
    };
    let f32_pieces: Vec<AreaImage> = halves.iter().map(|t| f32_image(&[triangle_shape(t)])).collect();
    let v = check_area_additivity(&f32_pieces, &f32_image(&whole)).unwrap_err();
    assert!(v.message.contains("pixel(s) differ"), "{v}");
}

/// `explain X,Y --coverage area` on two overlapping squares traced as one even-odd
/// contour (as in the oracle's unit test): pixel (0, 0) holds 3/4 of true coverage (the
/// square [0, 1]^2 less the overlap [1/2, 1]^2), the integral 1 + 1/4 = 5/4, folded
/// to 2 - 5/4 = 3/4; the edges meeting the pixel are the first square's top and left
/// sides, the joining segment both ways, and the second square's top and left sides.
#[test]
fn explain_area_cli_by_hand() {
    let dir = crate::tempdir::Dir::new("area-explain");
    let scene = dir.path().join("sq.json");
    std::fs::write(
        &scene,
        r#"{"width": 3, "height": 3, "polygons": [{"v": [[0, 0], [1.5, 0], [1.5, 1.5], [0, 1.5], [0, 0], [0.5, 0.5], [2, 0.5], [2, 2], [0.5, 2], [0.5, 0.5]], "fill_rule": "even-odd"}]}"#,
    )
    .unwrap();
    let sq = scene.to_str().unwrap();
    let (code, text, err) = rasterproof(&["explain", sq, "0,0", "--coverage", "area", "--model", "exact"]);
    assert_eq!(code, Some(0), "{err}");
    for line in [
        "true         3/4 (= 0.75)",
        "accumulated  3/4 (= 0.75)",
        "unclamped    5/4 (= 1.25)",
        "shape 0: integral of its path's winding number 5/4",
        "edge: shape 0 outline edge 0: (0, 0) -> (3/2, 0)",
        "edge: shape 0 outline edge 9: (1/2, 1/2) -> (0, 0)",
    ] {
        assert!(text.contains(line), "{line:?} not in\n{text}");
    }
    assert_eq!(text.matches("edge: shape 0").count(), 6, "{text}");
    // Off the canvas, and --svg with area: exit 2 with the reason.
    for (args, says) in [
        (&["3,0", "--coverage", "area"][..], "off the 3x3 canvas"),
        (
            &["0,0", "--coverage", "area", "--svg", "x.svg"][..],
            "--svg draws the sample's neighbourhood",
        ),
        (&["0,0", "--model", "exact"][..], "--model is for --coverage area"),
    ] {
        let (code, _, err) = rasterproof(&[&["explain", sq], args].concat());
        assert_eq!(code, Some(2), "{args:?}");
        assert!(err.contains(says), "{args:?}: {err}");
    }
}

/// FreeType's method on a rectangle derived by hand: [1/4, 11/4] x [1/2, 5/2] on a 3x3
/// canvas. Pixel (0, 0) holds 3/4 x 1/2 = 3/8 of its area (96/256), (1, 0) 1/2 (128),
/// (2, 0) 3/4 x 1/2 (96), (0, 1) 3/4 (192), (1, 1) whole (255 after the clamp), row 2 as
/// row 0. Drawn one way round the values are FreeType's quantization of the exact ones;
/// the other way round they come out negative and `~v` takes one off the partial pixels.
#[test]
fn ftgrays_rectangle_by_hand() {
    let rect = vec![
        p(r(1, 4), r(1, 2)),
        p(r(11, 4), r(1, 2)),
        p(r(11, 4), r(5, 2)),
        p(r(1, 4), r(5, 2)),
    ];
    let expected = [96u8, 128, 96, 192, 255, 192, 96, 128, 96];
    let mut reversed = rect.clone();
    reversed.reverse();
    let one_way = ft_levels(&rect);
    let other = ft_levels(&reversed);
    let exact = rasterize(&[Polygon::new(rect.clone(), FillRule::NonZero)], 3, 3, Semantics::True);
    let quantized: Vec<u8> = exact
        .levels(Quantization::FtGrays)
        .into_iter()
        .map(|l| u8::try_from(l).unwrap())
        .collect();
    assert_eq!(quantized, expected);
    let (equal, less) = if one_way == expected {
        (one_way, other)
    } else {
        (other, one_way)
    };
    assert_eq!(equal, expected);
    let one_less: Vec<u8> = expected.iter().map(|&l| if l == 255 { 255 } else { l - 1 }).collect();
    assert_eq!(less, one_less);
}

fn ft_levels(outline: &[Point]) -> Vec<u8> {
    ftgrays::rasterize(&[Polygon::new(outline.to_vec(), FillRule::NonZero)], 3, 3).unwrap()
}

/// Their grey image as a `GreyImage` from 8-bit levels.
fn grey8(width: u32, height: u32, levels: &[u8]) -> rasterproof::oracle::GreyImage {
    rasterproof::oracle::GreyImage {
        width,
        height,
        bits: 8,
        levels: levels.iter().map(|&l| u16::from(l)).collect(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, ..config("proptest-regressions/area.txt") })]

    /// What the grey comparison's cheap test of supersampling rests on: a `k x k`
    /// supersampled value, under any tie rule, lies within `E (2k - 1) / k^2` of the exact
    /// true coverage, `E` the edges that meet the pixel (only a cell whose interior an edge
    /// crosses can have a sample decision other than its share of area, and an edge
    /// crosses at most `2k - 1` of a pixel's `k x k` cells); and the blend of the shapes'
    /// own supersampled values lies as near the blend of their own exact values (each
    /// factor of the blend lies in [0, 1]).
    #[test]
    fn supersampling_stays_within_its_edges_reach(poly in any_polygon(5, 7), t in small_triangle()) {
        use rasterproof::area::conflate::{blend, own_values, Boxes, Own};
        use rasterproof::area::exact::crossing_edges;
        let shapes = [shape_of(&poly), triangle_shape(&t)];
        let boxes = Boxes::of(&shapes);
        for (x, y) in (0..6u32).flat_map(|y| (0..6u32).map(move |x| (x, y))) {
            let (px, py) = (i64::from(x), i64::from(y));
            let edges = i64::try_from(crossing_edges(&shapes, px, py).len()).unwrap();
            let exact = value(&shapes, px, py, Semantics::True);
            let exact_blend = blend(&own_values(&shapes, &boxes, x, y, Own::Exact(Semantics::True)));
            for k in [2i64, 4, 8] {
                let reach = r(edges * (2 * k - 1), k * k);
                let side = u32::try_from(k).unwrap();
                for sampled in supersample::pixel_under_each_rule(&shapes, x, y, side) {
                    prop_assert!((&sampled - &exact).abs() <= reach, "({x}, {y}) {k}x{k}: {sampled} vs {exact}");
                }
                let blended = blend(&own_values(&shapes, &boxes, x, y, Own::Supersampled(side)));
                prop_assert!((&blended - &exact_blend).abs() <= reach, "({x}, {y}) {k}x{k} blended");
            }
        }
    }

    /// A correct `k x k` supersampler (top-left ties, rounded to 8 bits) is never called
    /// `gross` under true coverage: the test that spares a gross pixel its samples never
    /// rules out a real supersampler.
    #[test]
    fn a_supersampler_is_never_gross(poly in any_polygon(5, 7), t in small_triangle(), k in prop::sample::select(vec![2u32, 4, 8, 16])) {
        use rasterproof::oracle::compare::grey::{compare_grey, GreyClass};
        let shapes = [shape_of(&poly), triangle_shape(&t)];
        let levels: Vec<u8> = supersample::rasterize(&shapes, 6, 6, k)
            .levels(Quantization::Round8)
            .into_iter()
            .map(|l| u8::try_from(l).unwrap())
            .collect();
        let report = compare_grey(
            &shapes,
            &canvas(6, 6),
            &grey8(6, 6, &levels),
            &grey_options(Semantics::True, Quantization::Round8),
        )
        .unwrap();
        let gross: Vec<_> = report.pixels.iter().filter(|p| p.class == GreyClass::Gross).collect();
        prop_assert!(gross.is_empty(), "{k}x{k}: {gross:?}");
    }

    /// The shrinker's question, `compare_grey_shows` (does a pixel of this class and sign
    /// exist? stopping at the first), answers what the whole comparison's pixels say, for
    /// every class and sign, on a supersampler's image with levels moved by up to 3 and
    /// some by up to 60 (every class, gross ones too).
    #[test]
    fn the_shrinkers_question_is_the_comparisons_answer(
        poly in any_polygon(5, 7),
        t in small_triangle(),
        k in prop::sample::select(vec![1u32, 2, 4]),
        moves in prop::collection::vec(prop_oneof![4 => -3i32..=3, 1 => -60i32..=60], 36),
    ) {
        use rasterproof::oracle::compare::grey::{compare_grey, compare_grey_shows, GreyClass};
        let shapes = [shape_of(&poly), triangle_shape(&t)];
        let levels: Vec<u8> = supersample::rasterize(&shapes, 6, 6, k)
            .levels(Quantization::Round8)
            .into_iter()
            .zip(&moves)
            .map(|(l, m)| u8::try_from((i32::from(l) + m).clamp(0, 255)).unwrap())
            .collect();
        let (target, theirs) = (canvas(6, 6), grey8(6, 6, &levels));
        let options = grey_options(Semantics::True, Quantization::Round8);
        let report = compare_grey(&shapes, &target, &theirs, &options).unwrap();
        let classes = [
            GreyClass::Quantization,
            GreyClass::Accumulation,
            GreyClass::Conflation,
            GreyClass::Precision,
            GreyClass::Supersampling(2),
            GreyClass::Supersampling(4),
            GreyClass::Supersampling(8),
            GreyClass::Supersampling(16),
            GreyClass::Gross,
        ];
        for class in classes {
            for over in [false, true] {
                let whole = report.pixels.iter().any(|p| p.class == class && p.error.is_positive() == over);
                let shows = compare_grey_shows(&shapes, &target, &theirs, &options, (class, over)).unwrap();
                prop_assert_eq!(shows, whole, "{:?} over {}", class, over);
            }
        }
    }
}

/// FreeType's method (`area::ftgrays`, bit for bit FreeType's smooth rasterizer in the
/// adapter tests) on a polygon whose hole lies outside its outline, judged under true
/// coverage: pixel (1, 2) holds only the hole, true coverage 0; FreeType accumulates the
/// hole's path (its 1/16 of the pixel, level 16 under ftgrays) and its division leaves it a
/// level under, 15. Accumulation and precision compose: `accumulation`, not `gross` (it
/// was `gross` before the classes composed).
#[test]
fn freetype_accumulated_and_a_level_off_is_accumulation() {
    use rasterproof::oracle::compare::grey::{compare_grey, GreyClass};
    let shapes = [Polygon {
        outline: vec![p(r(0, 1), r(3, 2)), p(r(1, 2), r(1, 2)), p(r(7, 2), r(2, 1))],
        holes: vec![vec![p(r(1, 1), r(3, 2)), p(r(1, 1), r(5, 2)), p(r(3, 2), r(3, 2))]],
        fill_rule: FillRule::NonZero,
    }];
    let levels = ftgrays::rasterize(&shapes, 6, 6).unwrap();
    assert_eq!(
        levels[2 * 6 + 1],
        15,
        "FreeType's method draws the hole a level under 1/16"
    );
    assert_eq!(value(&shapes, 1, 2, Semantics::True), r(0, 1));
    let report = compare_grey(
        &shapes,
        &canvas(6, 6),
        &grey8(6, 6, &levels),
        &grey_options(Semantics::True, Quantization::FtGrays),
    )
    .unwrap();
    let at = report
        .pixels
        .iter()
        .find(|px| (px.x, px.y) == (1, 2))
        .expect("pixel (1, 2) differs");
    assert_eq!(at.class, GreyClass::Accumulation, "{at:?}");
}

/// The grey comparison's classes, each from a renderer whose behaviour is known by hand:
/// - FreeType's method on the rectangle of `ftgrays_rectangle_by_hand`, walked the way
///   round that complements negative values: its 8 partial pixels are one level under the
///   exact value's (96 -> 95, 128 -> 127, 192 -> 191), and no rounding, other semantics or
///   supersampling gives that: `precision`, off by -1 quantum; the whole pixel has the
///   exact value's level (255, the clamp of 256: itself a quantum under it).
/// - 4x4 supersampling of the triangle (0,0) (1,0) (0,1): 6 samples of 16, 3/8 x 255 =
///   95.625, level 96, where the exact 1/2 is 127.5 (level 128): `supersampling (4x4)`.
/// - A bow tie (0,0) (1,1) (1,0) (0,1) inside one pixel: its two lobes wind +1 and -1,
///   true coverage 1/2, the integral 0: a renderer that accumulates gives 0,
///   `accumulation`.
/// - Level 200 for that triangle: none of these, `gross`; 127 for it: another rounding of
///   127.5, `quantization`.
#[test]
fn grey_classes_by_hand() {
    use rasterproof::oracle::compare::grey::{compare_grey, GreyClass};
    let rect = vec![
        p(r(1, 4), r(1, 2)),
        p(r(11, 4), r(1, 2)),
        p(r(11, 4), r(5, 2)),
        p(r(1, 4), r(5, 2)),
    ];
    let exact_levels: Vec<u8> = vec![96, 128, 96, 192, 255, 192, 96, 128, 96];
    let mut found_precision = false;
    for outline in [rect.clone(), rect.iter().rev().cloned().collect()] {
        let shapes = [Polygon::new(outline, FillRule::NonZero)];
        let levels = ftgrays::rasterize(&shapes, 3, 3).unwrap();
        let report = compare_grey(
            &shapes,
            &canvas(3, 3),
            &grey8(3, 3, &levels),
            &grey_options(Semantics::True, Quantization::FtGrays),
        )
        .unwrap();
        if levels == exact_levels {
            assert!(report.pixels.is_empty());
        } else {
            found_precision = true;
            assert_eq!(report.pixels.len(), 8);
            assert!(
                report
                    .pixels
                    .iter()
                    .all(|px| px.class == GreyClass::Precision && px.error == r(-1, 1)),
                "{report:?}"
            );
            assert_eq!(report.max_error, r(1, 1));
            // The whole pixel too is a quantum under 256 (the clamp to 255), not differing.
            assert_eq!(report.mean_error, r(1, 1));
        }
    }
    assert!(found_precision);
    let t = Triangle::new(p(r(0, 1), r(0, 1)), p(r(1, 1), r(0, 1)), p(r(0, 1), r(1, 1)));
    let shapes = [triangle_shape(&t)];
    let sampled = supersample::rasterize(&shapes, 1, 1, 4).levels(Quantization::Round8);
    assert_eq!(sampled, [96]);
    let class = |level: u8, shapes: &[AreaShape]| {
        let report = compare_grey(
            shapes,
            &canvas(1, 1),
            &grey8(1, 1, &[level]),
            &grey_options(Semantics::True, Quantization::Round8),
        )
        .unwrap();
        report.pixels.first().map(|px| px.class)
    };
    assert_eq!(class(96, &shapes), Some(GreyClass::Supersampling(4)));
    assert_eq!(class(128, &shapes), None);
    assert_eq!(class(127, &shapes), Some(GreyClass::Quantization));
    assert_eq!(class(200, &shapes), Some(GreyClass::Gross));
    let bow = [Polygon::new(
        vec![
            p(r(0, 1), r(0, 1)),
            p(r(1, 1), r(1, 1)),
            p(r(1, 1), r(0, 1)),
            p(r(0, 1), r(1, 1)),
        ],
        FillRule::NonZero,
    )];
    assert_eq!(value(&bow, 0, 0, Semantics::True), r(1, 2));
    assert_eq!(value(&bow, 0, 0, Semantics::Accumulated), r(0, 1));
    assert_eq!(class(0, &bow), Some(GreyClass::Accumulation));
    // Bad input: another size, another bit depth.
    let e = compare_grey(
        &shapes,
        &canvas(1, 1),
        &grey8(2, 1, &[0, 0]),
        &grey_options(Semantics::True, Quantization::Round8),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("their image is 2x1, the scene's canvas 1x1"), "{e}");
    let e = compare_grey(
        &shapes,
        &canvas(1, 1),
        &grey8(1, 1, &[0]),
        &grey_options(Semantics::True, Quantization::Round16),
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("8-bit levels; the quantization round16 makes 16-bit ones"),
        "{e}"
    );
}

/// `compare --as grey` from the command line: the oracle's own grey PNG is identical
/// (exit 0); an RGB PNG and a missing file are refused (exit 2) naming the file.
#[test]
fn compare_grey_cli() {
    let dir = crate::tempdir::Dir::new("area-grey");
    let scene = dir.path().join("t.json");
    std::fs::write(
        &scene,
        r#"{"width": 3, "height": 3, "triangles": [{"v": [[0, 0], [3, 0], [0, 3]]}]}"#,
    )
    .unwrap();
    let s = scene.to_str().unwrap();
    // The oracle's own grey PNG of the scene under `quantization`.
    let render_grey = |name: &str, quantization: &str| {
        let grey = dir.path().join(name);
        let (code, _, err) = rasterproof(&[
            "render",
            s,
            "--coverage",
            "area",
            "--model",
            "exact",
            "--quantization",
            quantization,
            "--grey-out",
            grey.to_str().unwrap(),
        ]);
        assert_eq!(code, Some(0), "{err}");
        grey
    };
    let grey = render_grey("g.png", "round");
    let run = |theirs: &std::path::Path, extra: &[&str]| {
        rasterproof(
            &[
                &[
                    "compare",
                    s,
                    theirs.to_str().unwrap(),
                    "--as",
                    "grey",
                    "--model",
                    "exact",
                ],
                extra,
            ]
            .concat(),
        )
    };
    let (code, text, _) = run(&grey, &[]);
    assert_eq!(code, Some(0), "{text}");
    assert!(text.contains("0 of 9 pixels differ"), "{text}");
    let (code, text, _) = rasterproof(&["compare", s, grey.to_str().unwrap(), "--as", "grey", "--fit"]);
    assert_eq!(code, Some(0), "{text}");
    assert!(
        text.contains("exact true coverage, quantized by round (--method exact-true-round): 0 pixels differ"),
        "{text}"
    );
    // Truncated instead of rounded: the half pixels are 127 where rounding gives 128.
    let (code, text, _) = run(&grey, &["--quantization", "truncate"]);
    assert_eq!(code, Some(1), "{text}");
    assert!(
        text.contains("3 of 9 pixels differ") && text.contains("quantization: 3 pixels"),
        "{text}"
    );
    let rgb = dir.path().join("rgb.png");
    image::RgbImage::new(3, 3).save(&rgb).unwrap();
    let (code, _, err) = run(&rgb, &[]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("rgb.png: a Rgb8 PNG; --as grey reads 8- or 16-bit grey"),
        "{err}"
    );
    let (code, _, err) = run(&dir.path().join("none.png"), &[]);
    assert_eq!(code, Some(2));
    assert!(err.contains("none.png: cannot read"), "{err}");
    // A 16-bit grey PNG: `round` (the default) reads it at its depth; a quantization of
    // 8-bit levels is refused naming the one that reads 16.
    let grey16 = render_grey("g16.png", "round16");
    let (code, text, err) = run(&grey16, &[]);
    assert_eq!(code, Some(0), "{text}{err}");
    assert!(
        text.contains("0 of 9 pixels differ") && text.contains("round16"),
        "{text}"
    );
    let (code, _, err) = run(&grey16, &["--quantization", "truncate"]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains(
            "16-bit levels; the quantization truncate makes 8-bit ones (the quantization of 16-bit levels is round16)"
        ),
        "{err}"
    );
}

/// `--fit` for grey images names the method that draws their image, from images whose
/// method is known: FreeType's integer method on the rectangle, either way round (walked
/// the way that complements negative values its 95s and 127s are also truncations), and 4x4
/// supersampling of the triangle (0,0) (3,0) (0,3) (its three diagonal pixels 6/16 of their
/// samples: level 96; 8x8 gives 28/64, level 112; the exact value 1/2, level 128).
#[test]
fn grey_fit_names_the_method() {
    use rasterproof::area::AreaMethod;
    use rasterproof::oracle::compare::fit::grey::{fit_grey, GreyMethod};
    let rect = vec![
        p(r(1, 4), r(1, 2)),
        p(r(11, 4), r(1, 2)),
        p(r(11, 4), r(5, 2)),
        p(r(1, 4), r(5, 2)),
    ];
    for outline in [rect.clone(), rect.iter().rev().cloned().collect()] {
        let shapes = [Polygon::new(outline, FillRule::NonZero)];
        let levels = ftgrays::rasterize(&shapes, 3, 3).unwrap();
        let found = fit_grey(
            &shapes,
            &canvas(3, 3),
            &grey8(3, 3, &levels),
            rasterproof::model::Model::Exact,
        )
        .unwrap()
        .methods;
        let exact: Vec<GreyMethod> = found.iter().filter(|(_, n)| *n == 0).map(|(m, _)| *m).collect();
        assert!(exact.contains(&GreyMethod::own(AreaMethod::FtGrays)), "{found:?}");
        if levels != [96, 128, 96, 192, 255, 192, 96, 128, 96] {
            // 95, 127, 191 are also v x 255 truncated (95.6, 127.5, 191.25): this image
            // cannot tell FreeType's method from truncation, and the fit says both; no
            // rounding to the nearest gives it.
            assert!(
                exact.contains(&GreyMethod::quantized(
                    AreaMethod::Planned,
                    Semantics::True,
                    Quantization::Truncate8
                )),
                "{exact:?}"
            );
            assert!(
                !exact.iter().any(|m| m.area.is_exact()
                    && matches!(m.quantization, Some(Quantization::Round8 | Quantization::FtGrays))),
                "{exact:?}"
            );
        }
    }
    let t = Triangle::new(p(r(0, 1), r(0, 1)), p(r(3, 1), r(0, 1)), p(r(0, 1), r(3, 1)));
    let shapes = [triangle_shape(&t)];
    let sampled = supersample::rasterize(&shapes, 3, 3, 4).levels(Quantization::Round8);
    assert_eq!(sampled[2], 96);
    let levels: Vec<u8> = sampled.iter().map(|&l| u8::try_from(l).unwrap()).collect();
    let found = fit_grey(
        &shapes,
        &canvas(3, 3),
        &grey8(3, 3, &levels),
        rasterproof::model::Model::Exact,
    )
    .unwrap()
    .methods;
    let exact: Vec<GreyMethod> = found.iter().filter(|(_, n)| *n == 0).map(|(m, _)| *m).collect();
    assert!(
        exact.contains(&GreyMethod::quantized(
            AreaMethod::Supersample(4),
            Semantics::True,
            Quantization::Round8
        )),
        "{found:?}"
    );
    assert!(
        !exact
            .iter()
            .any(|m| m.area.is_exact() || matches!(m.area, AreaMethod::Supersample(8 | 16))),
        "{exact:?}"
    );
}

/// tiny-skia's levels by hand, one pixel each (4 x 4 samples at odd eighths): a rectangle
/// over the top three sample rows is 3 x 4 x 16 = 192; over the bottom three, 192 less 1
/// for the full bottom row (64 - 1 on the pixel's last sub-scanline); the left half of the
/// pixel, 8 samples, no full row, 128; the whole pixel 255 (not 256). Samples on an edge
/// go by the bottom-right rule: the top eighth holds the top sample row on its bottom
/// edge, 64; the bottom eighth holds the bottom row on its top edge only, 0; the half below
/// the diagonal `x + y = 1` holds the 6 samples below it and the 4 on it (a right edge),
/// 160. (tiny-skia 0.11.4 draws 64, 0 and 160.)
#[test]
fn tiny_skia_levels_by_hand() {
    let rect = |x0: BigRational, y0: BigRational, x1: BigRational, y1: BigRational| {
        Polygon::new(
            vec![
                Point::new(x0.clone(), y0.clone()),
                Point::new(x1.clone(), y0),
                Point::new(x1, y1.clone()),
                Point::new(x0, y1),
            ],
            FillRule::NonZero,
        )
    };
    let cases = [
        (rect(r(0, 1), r(0, 1), r(1, 1), r(3, 4)), 192),
        (rect(r(0, 1), r(1, 4), r(1, 1), r(1, 1)), 191),
        (rect(r(0, 1), r(0, 1), r(1, 2), r(1, 1)), 128),
        (rect(r(0, 1), r(0, 1), r(1, 1), r(1, 1)), 255),
        (rect(r(0, 1), r(7, 8), r(1, 1), r(1, 1)), 0),
        (rect(r(0, 1), r(0, 1), r(1, 1), r(1, 8)), 64),
        (
            Polygon::new(
                vec![
                    Point::new(r(0, 1), r(1, 1)),
                    Point::new(r(0, 1), r(0, 1)),
                    Point::new(r(1, 1), r(0, 1)),
                ],
                FillRule::NonZero,
            ),
            160,
        ),
    ];
    for (shape, level) in cases {
        assert_eq!(
            supersample::tiny_skia_levels(std::slice::from_ref(&shape), 1, 1),
            vec![level],
            "{shape:?}"
        );
    }
}

/// A shape reaching 2^30 px left of the canvas: f32 accumulation takes the part of each
/// row left of the canvas in one piece, so it ends at once (a walk column by column in
/// f32 would never end: past 2^24, `c + 1.0 == c`). The triangle (-2^30, 0) (2, 0) (2, 1)
/// covers of pixel (x, 0) the part under the line `y = (u + 2^30) / (2^30 + 2)`: pixel 0
/// `(2^30 + 1/2) / (2^30 + 2)`, pixel 1 `(2^30 + 3/2) / (2^30 + 2)`, both within 2^-29
/// of 1, so f32 gives 1 for each (its ulp at 1 is 2^-23), and the rows below nothing.
#[test]
fn f32_accumulation_of_a_shape_far_left_ends_and_is_right() {
    let far = -(1i64 << 30);
    let t = Triangle::new(p(r(far, 1), r(0, 1)), p(r(2, 1), r(0, 1)), p(r(2, 1), r(1, 1)));
    let shapes = [triangle_shape(&t)];
    let exact = rasterize(&shapes, 2, 2, Semantics::Accumulated);
    let d = r(-far + 2, 1);
    assert_eq!(exact.value(0, 0), (r(-far, 1) + r(1, 2)) / &d);
    assert_eq!(exact.value(1, 0), (r(-far, 1) + r(3, 2)) / &d);
    assert_eq!(
        float::rasterize(&shapes, 2, 2, Semantics::Accumulated),
        vec![1.0, 1.0, 0.0, 0.0]
    );
    // Far from the origin too: the window at 2^20, the triangle moved with it.
    let placed = [triangle_shape(&t).translated(1 << 20, 1 << 20)];
    assert_eq!(
        float::rasterize_at(&placed, 1 << 20, 2, 2, Semantics::Accumulated),
        vec![1.0, 1.0, 0.0, 0.0]
    );
}

/// `poly` with every coordinate rounded down to a multiple of `1/d` and moved by
/// `(dx, dy)` px: vertices on the sample rows and columns of a `k x k` pattern when `2k`
/// divides `d`, the ties the supersampling sweep must decide as the plain test does.
fn snapped(poly: &Polygon, d: i64, shift: (i64, i64)) -> AreaShape {
    let snap = |v: &BigRational, s: i64| (v * int(d)).floor() / int(d) + int(s);
    let contour =
        |c: &[Point]| -> Vec<Point> { c.iter().map(|q| p(snap(&q.x, shift.0), snap(&q.y, shift.1))).collect() };
    Polygon {
        outline: contour(&poly.outline),
        holes: poly.holes.iter().map(|h| contour(h)).collect(),
        fill_rule: poly.fill_rule,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..config("proptest-regressions/area.txt") })]

    /// The supersampling sweep (`supersample::for_each_row_counts`, a pass over each sample
    /// row's edge crossings, and `pixel_row_counts`, the sweep of one pixel) counts what the plain test of every sample
    /// (`supersample::row_counts_with`, each sample against every edge) counts: every
    /// pixel, sample row, side `k` and tie rule, polygons (tangled, with holes) with
    /// vertices on the samples' grid or off it, reaching off the canvas on every side.
    #[test]
    fn the_supersampling_sweep_is_the_plain_test(
        poly in any_polygon(5, 7),
        t in small_triangle(),
        k in 1u32..=4,
        d in prop::sample::select(vec![8i64, 24, 1 << 10]),
        shift in (-2i64..=2, -2i64..=2),
    ) {
        let shapes = [snapped(&poly, d, shift), snapped(&triangle_shape(&t), d, (0, 0))];
        let (width, height) = (5u32, 4u32);
        for rule in AnyTieRule::ALL {
            let mut rows_seen = 0;
            supersample::for_each_row_counts(&shapes, width, height, k, rule, |y, counts| {
                rows_seen += 1;
                for x in 0..width {
                    let plain = supersample::row_counts_with(&shapes, x, y, k, rule);
                    let swept = &counts[(x * k) as usize..((x + 1) * k) as usize];
                    assert_eq!(swept, &plain[..], "{rule:?} {k}x{k} pixel ({x}, {y}): {shapes:?}");
                    let alone = supersample::pixel_row_counts(&shapes, x, y, k, rule);
                    assert_eq!(alone, plain, "{rule:?} {k}x{k} pixel ({x}, {y}) alone: {shapes:?}");
                }
            });
            prop_assert_eq!(rows_seen, height);
        }
        // Each pixel's values under the six rules, each once: the sweep's (which sweeps once
        // where no sample lies on an edge) and the plain test's.
        let of = i64::from(k * k);
        for (x, y) in (0..height).flat_map(|y| (0..width).map(move |x| (x, y))) {
            let mut plain: Vec<BigRational> = AnyTieRule::ALL
                .iter()
                .map(|&rule| r(supersample::row_counts_with(&shapes, x, y, k, rule).iter().sum::<u32>().into(), of))
                .collect();
            plain.sort();
            plain.dedup();
            let mut swept = supersample::pixel_under_each_rule(&shapes, x, y, k);
            swept.sort();
            prop_assert_eq!(swept, plain, "pixel ({}, {})", x, y);
        }
    }
}

/// The sweep's tie decisions, by hand: the square [1/8, 5/8]^2 has 4 x 4 samples at
/// 1/8, 3/8, 5/8, 7/8 on its edges and corners. Top-left takes its left and top edges
/// (x, y in {1/8, 3/8}: 4 samples), bottom-right its bottom and right ones ({3/8, 5/8}:
/// 4), all-inclusive the closed square (3 x 3 = 9), all-exclusive the open one (3/8
/// alone: 1); bottom-left takes x in {1/8, 3/8}, y in {3/8, 5/8} (4).
#[test]
fn the_supersampling_sweep_decides_ties_by_hand() {
    let square = Polygon::new(
        vec![
            p(r(1, 8), r(1, 8)),
            p(r(5, 8), r(1, 8)),
            p(r(5, 8), r(5, 8)),
            p(r(1, 8), r(5, 8)),
        ],
        FillRule::NonZero,
    );
    for (rule, want, rows) in [
        (AnyTieRule::TopLeft, 4, [2, 2, 0, 0]),
        (AnyTieRule::BottomRight, 4, [0, 2, 2, 0]),
        (AnyTieRule::BottomLeft, 4, [0, 2, 2, 0]),
        (AnyTieRule::AllInclusive, 9, [3, 3, 3, 0]),
        (AnyTieRule::AllExclusive, 1, [0, 1, 0, 0]),
    ] {
        assert_eq!(
            supersample::counts(std::slice::from_ref(&square), 1, 1, 4, rule),
            vec![want],
            "{rule:?}"
        );
        supersample::for_each_row_counts(std::slice::from_ref(&square), 1, 1, 4, rule, |_, counts| {
            assert_eq!(counts, &rows[..], "{rule:?}");
        });
    }
    // Reversed (clockwise in the image) the square covers the same samples.
    let mut reversed = square.clone();
    reversed.outline.reverse();
    assert_eq!(supersample::counts(&[reversed], 1, 1, 4, AnyTieRule::TopLeft), vec![4]);
}

/// The tangled polygon a fresh clone's seed of the property test below found (issue 46,
/// point 3), on FreeType's 1/64 px grid: its hole crosses its outline, so at pixel (0, 3)
/// the winding numbers +1 and -1 meet. True coverage is 0.1884 (level 48 of 256), the
/// accumulated integral of the winding number 0.1594 (40.8); FreeType's method draws 39,
/// 1.8 levels from the accumulated value (its divisions, over the 4 edges meeting the
/// pixel) and 9.2 from the true one: past precision's reach of the true value (1 + 2 x 4
/// levels), and the accumulated value itself lies within that reach of the true one, so
/// neither class alone names it. Composed, `accumulation`; never `gross`.
#[test]
fn freetype_on_a_tangled_polygon_is_accumulation_and_precision() {
    use rasterproof::area::exact;
    use rasterproof::oracle::compare::grey::{compare_grey, GreyClass};
    let shapes = [Polygon {
        outline: vec![
            p(r(0, 1), r(263, 64)),
            p(r(119, 32), r(237, 64)),
            p(r(59, 8), r(171, 64)),
            p(r(-25, 32), r(127, 32)),
        ],
        holes: vec![vec![
            p(r(9, 32), r(125, 32)),
            p(r(35, 16), r(13, 16)),
            p(r(9, 8), r(33, 32)),
            p(r(1, 2), r(65, 16)),
        ]],
        fill_rule: FillRule::NonZero,
    }];
    let levels = ftgrays::rasterize(&shapes, 6, 6).unwrap();
    assert_eq!(levels[3 * 6], 39, "FreeType's method at (0, 3)");
    let (values, _) = exact::values(&shapes, 0, 3);
    let of = |s: Semantics| values.iter().find(|(k, _)| *k == s).unwrap().1.clone();
    let (truth, accumulated) = (of(Semantics::True), of(Semantics::Accumulated));
    assert_eq!(exact::crossing_edges(&shapes, 0, 3).len(), 4);
    let levels_of = |v: &BigRational| v * int(256);
    assert!(levels_of(&truth) > r(48, 1) && levels_of(&truth) < r(49, 1), "{truth}");
    assert!(
        levels_of(&accumulated) > r(40, 1) && levels_of(&accumulated) < r(41, 1),
        "{accumulated}"
    );
    let report = compare_grey(
        &shapes,
        &canvas(6, 6),
        &grey8(6, 6, &levels),
        &grey_options(Semantics::True, Quantization::FtGrays),
    )
    .unwrap();
    let at = report
        .pixels
        .iter()
        .find(|px| (px.x, px.y) == (0, 3))
        .expect("pixel (0, 3) differs");
    assert_eq!(at.class, GreyClass::Accumulation, "{at:?}");
    let gross: Vec<_> = report.pixels.iter().filter(|p| p.class == GreyClass::Gross).collect();
    assert!(gross.is_empty(), "{gross:?}");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..config("proptest-regressions/area.txt") })]

    /// FreeType's method (`area::ftgrays`, bit for bit FreeType's smooth rasterizer in the
    /// adapter tests) on any polygon, tangled and self-overlapping ones included, judged
    /// under true coverage: it accumulates the winding number (another semantics) and its
    /// divisions round (precision), and where both meet at one pixel the two compose; a
    /// correct renderer is never called `gross`.
    #[test]
    fn freetype_is_never_gross_under_true_coverage(poly in any_polygon(6, 7)) {
        use rasterproof::oracle::compare::grey::{compare_grey, GreyClass};
        // FreeType reads 26.6 fixed point: the shape on its 1/64 px grid (as `hunt --as
        // grey --grid 6` puts it), so that its arithmetic is judged, not its input.
        let mut scene = rasterproof::scene::Scene { polygons: vec![poly], ..rasterproof::scene::Scene::new(6, 6, vec![]) };
        rasterproof::oracle::hunt::on_grid(&mut scene, 6);
        let shapes = [shape_of(&scene.polygons[0])];
        let Ok(levels) = ftgrays::rasterize(&shapes, 6, 6) else {
            return Ok(());
        };
        let report = compare_grey(
            &shapes,
            &canvas(6, 6),
            &grey8(6, 6, &levels),
            &grey_options(Semantics::True, Quantization::FtGrays),
        )
        .unwrap();
        let gross: Vec<_> = report.pixels.iter().filter(|p| p.class == GreyClass::Gross).collect();
        prop_assert!(gross.is_empty(), "{gross:?}");
    }
}
