//! Polygons far beyond the old 4096-vertex cap (issue 31): a regular N-gon with exact
//! 3-decimal vertices renders in every model (`fixed` too: its triangulation validates by a
//! sweep, without a vertex cap); the scanline, snapped exact and `fixed` models agree
//! pixel for pixel, a 100,000-vertex polygon with holes triangulates, the planned engine equals the plain oracle on a small canvas, and the
//! covered count lies between the areas of the polygon shrunk and grown by a pixel's
//! diagonal (derived from the inscribed polygon's area `N/2 R^2 sin(2 pi / N)`). The scene's
//! vertex limit is refused with the field, the count and the limit.

use rasterproof::convention::{Preset, Target};
use rasterproof::fill::triangulate::triangulate;
use rasterproof::geom::{FillRule, Point, Polygon};
use rasterproof::model::{render, Model, Primitives};
use rasterproof::scene::parse::{parse_scene, parse_scene_with, ParseOptions, MAX_SCENE_VERTICES};
use rasterproof::scene::Scene;

/// The text of a scene: a `size` x `size` canvas and one regular `n`-gon of radius `r`
/// about its centre, vertices rounded to 3 decimals.
fn ngon_text(n: usize, r: f64, size: u32) -> String {
    let c = f64::from(size) / 2.0;
    let vertices: Vec<String> = (0..n)
        .map(|k| {
            #[allow(clippy::cast_precision_loss)] // k, n < 2^24
            let a = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            format!("[\"{:.3}\",\"{:.3}\"]", c + r * a.cos(), c + r * a.sin())
        })
        .collect();
    format!(
        r#"{{"width": {size}, "height": {size}, "polygons": [{{"v": [{}]}}]}}"#,
        vertices.join(",")
    )
}

fn covered(scene: &Scene, model: Model) -> usize {
    let target = scene.target().expect("a valid canvas");
    render(&scene.primitives(), &target, model)
        .unwrap_or_else(|e| panic!("{model}: {e}"))
        .covered_pixels()
}

/// 20,000 vertices, radius 500 on a 1024^2 canvas. A pixel is covered when its centre is
/// inside, so every pixel within the polygon shrunk by d = sqrt(2)/2 (plus the 3-decimal
/// rounding, under 0.001) is covered and every covered one lies within it grown by d: the
/// count lies between the areas of the regular polygons of inradius `r_in -+ d`, which are
/// `A ((r_in -+ d) / r_in)^2` with `A = N/2 R^2 sin(2 pi / N)` and `r_in = R cos(pi / N)`.
#[test]
fn a_20000_vertex_polygon_renders_in_every_model() {
    let (n, r) = (20_000usize, 500.0f64);
    let scene = parse_scene(&ngon_text(n, r, 1024), "ngon.json").unwrap();
    assert_eq!(scene.polygons[0].outline.len(), n);
    #[allow(clippy::cast_precision_loss)]
    let nf = n as f64;
    let area = nf / 2.0 * r * r * (2.0 * std::f64::consts::PI / nf).sin();
    let r_in = r * (std::f64::consts::PI / nf).cos();
    let d = std::f64::consts::SQRT_2 / 2.0 + 0.001;
    let (lo, hi) = (area * ((r_in - d) / r_in).powi(2), area * ((r_in + d) / r_in).powi(2));
    let snapped = covered(&scene, Model::ExactSnapped);
    #[allow(clippy::cast_precision_loss)]
    let count = snapped as f64;
    assert!(
        lo <= count && count <= hi,
        "{snapped} pixels, expected {lo:.0}..={hi:.0}"
    );
    assert_eq!(covered(&scene, Model::Scanline), snapped, "scanline");
    // `fixed` triangulates the snapped polygon (validated by a sweep, no vertex cap):
    // the same pixels as the snapped oracle.
    assert_eq!(covered(&scene, Model::Fixed), snapped, "fixed");
    for model in [Model::Exact, Model::Fixed, Model::Float32, Model::Float64] {
        #[allow(clippy::cast_precision_loss)]
        let c = covered(&scene, model) as f64;
        assert!(lo <= c && c <= hi, "{model}: {c} pixels, expected {lo:.0}..={hi:.0}");
    }
}

/// A regular `n`-gon of radius `r` about `(cx, cy)`, counterclockwise or (`reversed`) not,
/// vertices rounded to 3 decimals.
fn ngon(n: usize, cx: f64, cy: f64, r: f64, reversed: bool) -> Vec<Point> {
    let sign = if reversed { -1.0 } else { 1.0 };
    (0..n)
        .map(|k| {
            #[allow(clippy::cast_precision_loss)] // k, n < 2^24
            let a = sign * 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            #[allow(clippy::cast_possible_truncation)] // below 2^20
            let milli = |v: f64| (v * 1000.0).round() as i64;
            Point::from_fractions(milli(cx + r * a.cos()), 1000, milli(cy + r * a.sin()), 1000)
        })
        .collect()
}

/// 100,000 vertices in all: a 96,000-gon of radius 250 about the centre of a 512^2 canvas
/// with four holes, 1,000-gons of radius 50 centred 125 px from the centre on the
/// diagonals, wound the other way. The triangulation takes them all (a validation by pairs
/// of edges would compare 5 * 10^9 pairs; the sweep takes a fraction of a second), gives
/// n + 2h - 2 triangles, and `fixed` covers exactly the snapped oracle's pixels. No time is
/// asserted: a quadratic step would show as a test that does not finish.
#[test]
fn a_100000_vertex_polygon_with_holes_triangulates() {
    let (c, r) = (256.0, 250.0);
    let d = r / 2.0 / std::f64::consts::SQRT_2;
    let mut poly = Polygon::new(ngon(96_000, c, c, r, false), FillRule::NonZero);
    for (dx, dy) in [(-d, -d), (d, -d), (-d, d), (d, d)] {
        poly.holes.push(ngon(1000, c + dx, c + dy, r / 5.0, true));
    }
    let target = Target::new(512, 512, Preset::D3d11.convention()).unwrap();
    let fixed = poly.to_fixed(&target.convention).unwrap();
    let vertices: usize = fixed.contours().iter().map(Vec::len).sum();
    assert_eq!(vertices, 100_000);
    let tris = triangulate(&fixed).unwrap();
    assert_eq!(tris.len(), 100_000 + 2 * 4 - 2);
    let p = Primitives {
        polygons: vec![poly],
        ..Primitives::default()
    };
    let snapped = render(&p, &target, Model::ExactSnapped).unwrap();
    // pi (250^2 - 4 * 50^2) = 164,934 pixels, give or take the outline's pixels.
    assert!(
        (160_000..170_000).contains(&snapped.covered_pixels()),
        "{}",
        snapped.covered_pixels()
    );
    assert_eq!(render(&p, &target, Model::Fixed).unwrap(), snapped);
}

/// The plain oracle tests every edge at every pixel of the box: a 5,000-vertex polygon of
/// radius 10 on a 24^2 canvas keeps that quick, and the planned engine equals it (written
/// and snapped).
#[test]
fn a_5000_vertex_polygon_equals_the_plain_oracle() {
    let scene = parse_scene(&ngon_text(5000, 10.0, 24), "small.json").unwrap();
    let target = scene.target().unwrap();
    let p = scene.primitives();
    for (planned, plain) in [
        (Model::Exact, Model::ExactPlain),
        (Model::ExactSnapped, Model::ExactSnappedPlain),
    ] {
        let a = render(&p, &target, planned).unwrap();
        let b = render(&p, &target, plain).unwrap();
        assert_eq!(a, b, "{planned} against {plain}");
        // About pi 10^2 = 314 pixels: between the discs of radius 10 -+ sqrt(2) (one
        // pixel's diagonal), pi 8.586^2 = 231.6 and pi 11.414^2 = 409.3.
        assert!((232..=409).contains(&a.covered_pixels()), "{}", a.covered_pixels());
    }
}

/// The limit counts every polygon contour and the clip window together; one vertex over it
/// is refused naming the field that crosses it, its count, the total and the limit.
#[test]
fn the_scene_vertex_limit_is_refused_with_field_and_count() {
    assert_eq!(MAX_SCENE_VERTICES, 10_000_000);
    let limited = |text: &str, source: &str, max_vertices: usize| {
        let options = ParseOptions {
            max_vertices,
            ..ParseOptions::default()
        };
        parse_scene_with(text.as_bytes(), source, &options)
    };
    let text = ngon_text(5000, 10.0, 24);
    assert!(limited(&text, "s.json", 5000).is_ok());
    assert_eq!(
        limited(&text, "s.json", 4999).unwrap_err().to_string(),
        "s.json: polygons[0].v: 5000 vertices make 5000 polygon and clip-window vertices in the scene, at most 4999"
    );
    let with_hole_and_clip = r#"{"width": 8, "height": 8,
        "polygons": [{"v": [[0,0],[8,0],[8,8],[0,8]], "holes": [[[2,2],[4,2],[2,4]]]}],
        "clip": {"convex": [[0,0],[6,0],[6,6],[0,6]]}}"#;
    assert!(limited(with_hole_and_clip, "c.json", 11).is_ok());
    assert_eq!(
        limited(with_hole_and_clip, "c.json", 10).unwrap_err().to_string(),
        "c.json: clip.convex: 4 vertices make 11 polygon and clip-window vertices in the scene, at most 10"
    );
    assert_eq!(
        limited(with_hole_and_clip, "c.json", 6).unwrap_err().to_string(),
        "c.json: polygons[0].holes[0]: 3 vertices make 7 polygon and clip-window vertices in the scene, at most 6"
    );
    // A larger limit than the crate's is lowered to it: the same scene parses.
    assert!(limited(with_hole_and_clip, "c.json", usize::MAX).is_ok());
}
