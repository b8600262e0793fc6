//! Polygon fill: on any polygon (self-intersecting, with holes, degenerate, tie-heavy),
//! the scanline filler must equal the oracle on the snapped polygon; when triangulation
//! accepts the polygon, its triangles must cover exactly the fill, each pixel once; and
//! spade must never be handed something it refuses (validation comes first).

#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;

mod common;
use common::{convention, PresetChoice};
use rasterproof::check::{check_agreement, check_triangulation};
use rasterproof::convention::Target;
use rasterproof::fill::triangulate::{triangulate, TriangulateError};
use rasterproof::geom::{FillRule, FixedTriangle, Point, Polygon};
use rasterproof::model::{render, Model, Primitives};

#[derive(Debug, Clone, Arbitrary)]
struct Input {
    outline: Vec<(i16, i16)>,
    holes: Vec<Vec<(i16, i16)>>,
    /// Coordinates are `v / (1 + den % 8)` px after folding onto the canvas and a margin.
    den: u8,
    even_odd: bool,
    preset: PresetChoice,
    bits: Option<u8>,
    corner: bool,
    /// Canvas sides, read as `1 + w % 32`.
    width: u8,
    height: u8,
}

fuzz_target!(|input: Input| {
    let conv = convention(input.preset, input.bits, input.corner);
    let (w, h) = (1 + u32::from(input.width % 32), 1 + u32::from(input.height % 32));
    let target = Target::new(w, h, conv).expect("valid canvas");
    let den = 1 + i64::from(input.den % 8);
    // Fold onto [-8, side + 8) px (times den), so most polygons cross the canvas.
    let span = 2 * (i64::from(w.max(h)) + 8) * den;
    let point = |&(x, y): &(i16, i16)| {
        let fold = |v: i16| i64::from(v).rem_euclid(span) - 8 * den;
        Point::from_fractions(fold(x), den, fold(y), den)
    };
    let contour = |c: &[(i16, i16)]| -> Vec<Point> { c.iter().take(12).map(point).collect() };
    let outline = contour(&input.outline);
    let holes: Vec<Vec<Point>> = input.holes.iter().take(2).map(|h| contour(h)).collect();
    if outline.len() < 3 || holes.iter().any(|h| h.len() < 3) {
        return; // the parser refuses these
    }
    let rule = if input.even_odd {
        FillRule::EvenOdd
    } else {
        FillRule::NonZero
    };
    let poly = Polygon {
        outline,
        holes,
        fill_rule: rule,
    };
    let one = std::slice::from_ref(&poly);

    let reference = render(
        &Primitives {
            polygons: one.to_vec(),
            ..Primitives::default()
        },
        &target,
        Model::ExactSnapped,
    )
    .expect("the oracle takes any polygon");
    let scan = render(
        &Primitives {
            polygons: one.to_vec(),
            ..Primitives::default()
        },
        &target,
        Model::Scanline,
    )
    .expect("small coordinates are in the envelope");
    if let Err(v) = check_agreement("exact-snapped", &reference, "scanline", &scan, &[], &target) {
        panic!("{v}\n{poly:?}");
    }

    let fixed = poly.to_fixed(&conv).expect("small coordinates are in the envelope");
    match triangulate(&fixed) {
        Ok(tris) => {
            let tris: Vec<_> = tris.iter().map(FixedTriangle::to_exact).collect();
            if let Err(v) = check_triangulation(&fixed.to_exact(), &tris, &target) {
                panic!("{v}\n{poly:?}");
            }
        }
        Err(TriangulateError::Spade(msg)) => panic!("spade refused a validated polygon: {msg}\n{poly:?}"),
        Err(_) => {}
    }
});
