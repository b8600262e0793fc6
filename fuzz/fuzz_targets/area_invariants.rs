//! Exact area coverage: on any polygon (self-intersecting, with holes, degenerate) lying
//! on a small canvas, the cell accumulation and the planned engine (i128) equal the plain
//! oracle's signed integral at every pixel, and the planned engine's images equal the
//! oracle's under the accumulated semantics; the integrals add up to the path's signed area; true and folded values lie
//! in [0, 1]; FreeType's integer method (within a level and two per edge meeting the
//! pixel) and f32 accumulation stay near the exact values; the supersampling sweep
//! counts each sample row as the plain test of every sample does, under every tie rule;
//! and a spade triangulation of the outline's points adds up, pixel by pixel, to its hull.

#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use rasterproof::area::{
    cells, exact, float, ftgrays, path_signed_area, planned, supersample, triangle_shape, AreaImage, Quantization,
    Semantics,
};
use rasterproof::convention::AnyTieRule;
use rasterproof::check::{check_area_additivity, check_area_bounds, check_area_conservation};
use rasterproof::geom::{FillRule, Point, Polygon};
use rasterproof::strategy::triangulate;

#[derive(Debug, Clone, Arbitrary)]
struct Input {
    outline: Vec<(u8, u8)>,
    holes: Vec<Vec<(u8, u8)>>,
    /// Coordinates are `v / (1 + den % 4)` px, folded onto the canvas.
    den: u8,
    even_odd: bool,
    /// Canvas sides, read as `1 + w % 6`.
    width: u8,
    height: u8,
    /// Supersampling `k x k`, read as `1 + k % 4` (the vertices' 1/1..1/4 px grid puts
    /// many of them, and so edges, on the samples of k = 2 and 4).
    k: u8,
}

fuzz_target!(|input: Input| {
    let (w, h) = (1 + u32::from(input.width % 6), 1 + u32::from(input.height % 6));
    let den = 1 + i64::from(input.den % 4);
    let (sx, sy) = (i64::from(w) * den + 1, i64::from(h) * den + 1);
    // Every vertex on the canvas, edges included: [0, w] x [0, h].
    let grid = |&(x, y): &(u8, u8)| (i64::from(x) % sx, i64::from(y) % sy);
    let point = |(x, y): (i64, i64)| Point::from_fractions(x, den, y, den);
    let contour = |c: &[(u8, u8)]| -> Vec<Point> { c.iter().take(8).map(|v| point(grid(v))).collect() };
    let outline = contour(&input.outline);
    let holes: Vec<Vec<Point>> = input.holes.iter().take(2).map(|c| contour(c)).collect();
    if outline.len() < 3 || holes.iter().any(|c| c.len() < 3) {
        return;
    }
    let fill_rule = if input.even_odd {
        FillRule::EvenOdd
    } else {
        FillRule::NonZero
    };
    let poly = Polygon {
        outline,
        holes,
        fill_rule,
    };
    let one = std::slice::from_ref(&poly);

    // Cells against the plain oracle, and conservation of the signed integral.
    let from_cells: std::collections::BTreeMap<(u32, u32), BigRational> = cells::accumulate(&poly, w, h)
        .into_iter()
        .map(|(x, y, v)| ((x, y), v))
        .collect();
    let mut total = BigRational::zero();
    for y in 0..h {
        for x in 0..w {
            let (_, acc) = exact::pixel(one, i64::from(x), i64::from(y));
            let cell = from_cells.get(&(x, y)).cloned().unwrap_or_else(BigRational::zero);
            assert_eq!(cell, acc[0], "pixel ({x}, {y}) of {poly:?}");
            total += &acc[0];
        }
    }
    assert_eq!(total, path_signed_area(&poly), "{poly:?}");
    let from_planned: std::collections::BTreeMap<(u32, u32), BigRational> = planned::accumulate(&poly, w, h)
        .into_iter()
        .map(|(x, y, v)| ((x, y), v))
        .collect();
    assert_eq!(from_planned, from_cells, "{poly:?}");
    for s in [Semantics::Accumulated, Semantics::AccumulatedUnclamped] {
        assert_eq!(
            planned::rasterize(one, w, h, s),
            exact::rasterize(one, w, h, s),
            "{poly:?}"
        );
    }
    for s in [Semantics::True, Semantics::Accumulated] {
        let image = exact::rasterize(one, w, h, s);
        if let Err(v) = check_area_bounds(&image) {
            panic!("{v}: {poly:?}");
        }
    }

    // The supersampling sweep against the plain test of every sample against every edge.
    let k = 1 + u32::from(input.k % 4);
    for rule in AnyTieRule::ALL {
        let mut rows = 0;
        supersample::for_each_row_counts(one, w, h, k, rule, |y, counts| {
            rows += 1;
            for x in 0..w {
                let plain = supersample::row_counts_with(one, x, y, k, rule);
                let swept = &counts[(x * k) as usize..((x + 1) * k) as usize];
                assert_eq!(swept, &plain[..], "{rule:?} {k}x{k} pixel ({x}, {y}): {poly:?}");
            }
        });
        assert_eq!(rows, h, "{rule:?} {k}x{k}: {poly:?}");
    }

    // The contenders never panic; on points on FreeType's 1/64 px grid (exact in f32: the
    // halves and quarters here, not the thirds) FreeType's method stays within 2 levels of
    // the exact value as it quantizes it, and f32 accumulation within 2^-16.
    let folded = exact::rasterize(one, w, h, Semantics::Accumulated);
    let ft = ftgrays::rasterize(one, w, h).expect("small coordinates are in the 24.8 envelope");
    let f = float::rasterize(one, w, h, Semantics::Accumulated);
    let got = AreaImage::from_f32(w, h, Semantics::Accumulated, &f).expect("finite values");
    if den != 3 {
        // FreeType's reciprocal division falls at most 1/256 px short at each crossing:
        // a level per crossing point, two per edge meeting the pixel, and one for the
        // truncation (fuzz_case_04 in tests/fuzz_cases.rs: 3 levels over 9 edges).
        let levels = folded.levels(Quantization::FtGrays);
        for (k, (&got, &want)) in ft.iter().zip(&levels).enumerate() {
            let (x, y) = (k as i64 % i64::from(w), k as i64 / i64::from(w));
            let edges = exact::explain(one, x, y).edges.len() as i32;
            assert!(
                (i32::from(got) - i32::from(want)).abs() <= 1 + 2 * edges,
                "pixel {k}: FreeType's method {got}, exactly {want}, {edges} edges: {poly:?}"
            );
        }
        let bound = BigRational::new(1.into(), 65536.into());
        for y in 0..h {
            for x in 0..w {
                let err = got.value(x, y) - folded.value(x, y);
                assert!(err.abs() <= bound, "pixel ({x}, {y}): f32 off by {err}: {poly:?}");
            }
        }
    }

    // A triangulation of the outline's points adds up to its hull.
    let quarter: Vec<[i64; 2]> = input
        .outline
        .iter()
        .take(8)
        .map(|v| {
            let (x, y) = grid(v);
            // On the quarter-pixel grid: x / den rounded down to quarters.
            [x * 4 / den, y * 4 / den]
        })
        .collect();
    if let Some(mesh) = triangulate(&quarter, 2) {
        let hull = [Polygon::new(mesh.outline.clone(), FillRule::NonZero)];
        let whole = exact::rasterize(&hull, w, h, Semantics::True);
        let pieces: Vec<_> = mesh
            .triangles
            .iter()
            .map(|t| exact::rasterize(&[triangle_shape(t)], w, h, Semantics::True))
            .collect();
        if let Err(v) = check_area_additivity(&pieces, &whole) {
            panic!("{v}: {mesh:?}");
        }
        let area = rasterproof::area::shoelace(&mesh.outline);
        let area = if area < BigRational::zero() { -area } else { area };
        if let Err(v) = check_area_conservation(&whole, &area) {
            panic!("{v}: {mesh:?}");
        }
    }
});
