//! Polygons far beyond the old 4096-vertex cap (issue 31): a regular N-gon with exact
//! 3-decimal vertices renders in every model but `fixed` (its triangulation keeps an 8192-vertex cap); the
//! scanline and snapped exact models agree
//! pixel for pixel, the planned engine equals the plain oracle on a small canvas, and the
//! covered count lies between the areas of the polygon shrunk and grown by a pixel's
//! diagonal (derived from the inscribed polygon's area `N/2 R^2 sin(2 pi / N)`). The scene's
//! vertex limit is refused with the field, the count and the limit.

use rasterproof::model::{render, Model};
use rasterproof::scene::parse::{parse_scene, parse_scene_with_vertex_limit, MAX_SCENE_VERTICES};
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
    // `fixed` still validates simplicity pair by pair (O(n^2)) and refuses, clearly,
    // beyond its own cap.
    let target = scene.target().unwrap();
    let err = render(&scene.primitives(), &target, Model::Fixed)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("20000 vertices, triangulation takes at most 8192"),
        "{err}"
    );
    for model in [Model::Exact, Model::Float32, Model::Float64] {
        #[allow(clippy::cast_precision_loss)]
        let c = covered(&scene, model) as f64;
        assert!(lo <= c && c <= hi, "{model}: {c} pixels, expected {lo:.0}..={hi:.0}");
    }
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
    let text = ngon_text(5000, 10.0, 24);
    assert!(parse_scene_with_vertex_limit(&text, "s.json", 5000).is_ok());
    assert_eq!(
        parse_scene_with_vertex_limit(&text, "s.json", 4999)
            .unwrap_err()
            .to_string(),
        "s.json: polygons[0].v: 5000 vertices make 5000 polygon and clip-window vertices in the scene, at most 4999"
    );
    let with_hole_and_clip = r#"{"width": 8, "height": 8,
        "polygons": [{"v": [[0,0],[8,0],[8,8],[0,8]], "holes": [[[2,2],[4,2],[2,4]]]}],
        "clip": {"convex": [[0,0],[6,0],[6,6],[0,6]]}}"#;
    assert!(parse_scene_with_vertex_limit(with_hole_and_clip, "c.json", 11).is_ok());
    assert_eq!(
        parse_scene_with_vertex_limit(with_hole_and_clip, "c.json", 10)
            .unwrap_err()
            .to_string(),
        "c.json: clip.convex: 4 vertices make 11 polygon and clip-window vertices in the scene, at most 10"
    );
    assert_eq!(
        parse_scene_with_vertex_limit(with_hole_and_clip, "c.json", 6)
            .unwrap_err()
            .to_string(),
        "c.json: polygons[0].holes[0]: 3 vertices make 7 polygon and clip-window vertices in the scene, at most 6"
    );
    // A larger limit than the crate's is lowered to it: the same scene parses.
    assert!(parse_scene_with_vertex_limit(with_hole_and_clip, "c.json", usize::MAX).is_ok());
}
