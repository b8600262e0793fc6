//! Minimised crashes of the fuzz targets (fuzz/README.md), each a named regression test
//! with the scene `cargo fuzz fmt` printed for it. Numbered on from the two earlier ones,
//! which live beside the code they cover: `scene::parse::tests::fuzz_case_01_huge_exponent_round_trip`
//! (scene_parse) and `tests/polygons.rs`'s `fuzz_case_01_hole_of_a_degenerate_outline`
//! (polygon_fill).

use rasterproof::model::plan::plan_scene;
use rasterproof::model::{render, Model};
use rasterproof::scene::parse_scene;

/// Found by planned_exact (its plan-verdict check): a zero-area triangle with a vertex
/// beyond f32's range. The float analysis skips a primitive that reaches no sample, so
/// the plan called float32 exact while the float32 model refuses the coordinate. A model
/// that refuses the scene is not exact for it: the verdict now names the refusal.
#[test]
fn fuzz_case_02_float_verdict_on_a_coordinate_beyond_f32() {
    let scene = parse_scene(
        r#"{
  "width": 4,
  "height": 1,
  "preset": "d3d11",
  "triangles": [
    {"v": [["-2084229497390748088713169470519580295168","-4"], ["-4","-4"], ["-4","-4"]]}
  ]
}"#,
        "fuzz_case_02.json",
    )
    .unwrap();
    let (primitives, target) = (scene.primitives(), scene.target().unwrap());
    let plan = plan_scene(&primitives, &target, Model::Exact).unwrap();
    for v in &plan.fixed_width {
        let refused = render(&primitives, &target, v.model).err();
        assert_eq!(v.exact, refused.is_none(), "{}: {:?}", v.model, v.broken_by);
        if let Some(e) = refused {
            assert_eq!(v.broken_by.as_deref(), Some(e.to_string().as_str()), "{}", v.model);
        }
    }
    let float32 = plan.fixed_width.iter().find(|v| v.model == Model::Float32).unwrap();
    assert!(!float32.exact);
    assert!(float32
        .broken_by
        .as_deref()
        .unwrap()
        .contains("does not fit the float32 model's float type"));
    // float64 holds the coordinate, and the triangle covers nothing: exact, as exact says.
    let float64 = plan.fixed_width.iter().find(|v| v.model == Model::Float64).unwrap();
    assert!(float64.exact, "{:?}", float64.broken_by);
    assert_eq!(
        render(&primitives, &target, Model::Float64).unwrap(),
        render(&primitives, &target, Model::Exact).unwrap()
    );
}

/// Found by theirs_read: a 2x4 palette PNG whose PLTE chunk is 13 bytes (four entries and
/// a stray byte), followed by an APNG fcTL chunk and a cut IDAT. The png crate (0.18.1)
/// accepts the palette and then panics while expanding it ("range end index 3 out of
/// range for slice of length 1" in `create_rgba_palette`). PNG 1.2 section 4.1.2 makes a
/// PLTE length not divisible by 3 an error: both PNG readers now refuse it, naming the
/// file and the chunk, before the decoder runs.
#[test]
fn fuzz_case_03_palette_of_thirteen_bytes() {
    use rasterproof::fill::flood::{decode_png, PngError};
    use rasterproof::oracle::theirs::{Background, Format};
    use rasterproof::oracle::Theirs;
    let bytes: &[u8] = &[
        0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
        0x00, 0x02, 0x00, 0x00, 0x00, 0x04, 0x02, 0x03, 0x00, 0x00, 0x00, 0xd4, 0x9f, 0x76, 0xed, 0x00, 0x00, 0x00,
        0x0d, 0x50, 0x4c, 0x54, 0x45, 0x00, 0x00, 0x00, 0xff, 0x00, 0x00, 0x00, 0xff, 0x00, 0xf4, 0x66, 0x63, 0x54,
        0x4c, 0x7e, 0x83, 0x00, 0xbf, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x00, 0x83, 0x82,
    ];
    match decode_png(bytes, "crash.png") {
        Err(e @ PngError::Corrupt { .. }) => assert_eq!(
            e.to_string(),
            "crash.png: corrupt PNG: its PLTE chunk is 13 bytes, not 1 to 256 entries of 3 bytes"
        ),
        other => panic!("{other:?}"),
    }
    for format in [Format::Mask, Format::Ids] {
        let e = Theirs::read(bytes, "theirs.png", format, Background::default()).unwrap_err();
        let text = e.to_string();
        assert!(text.starts_with("theirs.png: "), "{text}");
        assert!(text.contains("PLTE chunk is 13 bytes"), "{text}");
    }
    // The same file with a 12-byte palette (its four whole entries) is a palette PNG the
    // readers take up to the cut IDAT: an error again, but the decoder's own, no panic.
    let mut twelve = bytes.to_vec();
    twelve[36] = 12;
    twelve.remove(45 + 4);
    let e = decode_png(&twelve, "twelve.png").unwrap_err().to_string();
    assert!(e.starts_with("twelve.png: ") && !e.contains("PLTE chunk is"), "{e}");
}

/// Found by area_invariants (its bound on FreeType's method): a tangled outline with a
/// tangled hole, integer vertices, on a 2x2 canvas. Pixel (1, 0)'s exact accumulated value
/// is 1/4 (64 of 256, the level FreeType's quantization gives it), but FreeType's smooth
/// rasterizer draws 61: its reciprocal divisions (`FT_UDIV`) fall short at each of the
/// many crossings in that pixel. 61 is what FreeType 2.12.1 drew through
/// `adapters/freetype/render.py` ([255, 61, 192, 64] for the four pixels), and what
/// `area::ftgrays` computes; the fuzz target's bound was 2 levels and is now 1 plus 2 per
/// edge meeting the pixel.
#[test]
fn fuzz_case_04_freetype_three_levels_short() {
    use rasterproof::area::{exact, ftgrays, Quantization, Semantics};
    let scene = parse_scene(
        r#"{"width": 2, "height": 2, "polygons": [{"v": [[0,1],[1,2],[2,0],[1,2],[1,0],[0,1],[2,2],[0,0]],
            "holes": [[[1,1],[1,0],[0,1],[2,0]]], "fill_rule": "nonzero"}]}"#,
        "fuzz_case_04.json",
    )
    .unwrap();
    let target = scene.target().unwrap();
    let shapes = rasterproof::model::area_shapes(&scene.primitives(), &target, Model::Exact).unwrap();
    let exact_levels = exact::rasterize(&shapes, 2, 2, Semantics::Accumulated).levels(Quantization::FtGrays);
    assert_eq!(exact_levels, vec![255, 64, 192, 64]);
    assert_eq!(ftgrays::rasterize(&shapes, 2, 2).unwrap(), vec![255, 61, 192, 64]);
}

/// Found by theirs_read once it read every input as a grey image too: a palette PNG whose
/// PLTE chunk holds 13 bytes (not a whole number of RGB entries) panicked inside the png
/// crate when `--as grey` decoded it with `image::load_from_memory` (the readers of mask
/// and ids PNGs already went through the crate's guarded decoder, `seed-crash-03` of the
/// corpus). The grey reader now takes the same decoder: a clear error naming the file.
#[test]
fn fuzz_case_05_grey_png_with_a_13_byte_palette() {
    let bytes: [u8; 72] = [
        137, 80, 78, 71, 13, 10, 26, 10, 0, 0, 0, 13, 73, 72, 68, 82, 0, 0, 0, 2, 0, 0, 0, 4, 2, 3, 0, 0, 0, 212, 159,
        118, 237, 0, 0, 0, 13, 80, 76, 84, 69, 0, 0, 0, 255, 0, 0, 0, 255, 0, 244, 102, 99, 84, 76, 126, 131, 0, 191,
        0, 0, 12, 73, 68, 65, 84, 120, 156, 99, 0, 131, 130,
    ];
    let e = rasterproof::oracle::Theirs::read(
        &bytes,
        "theirs.png",
        rasterproof::oracle::Format::Grey,
        rasterproof::oracle::Background::default(),
    )
    .unwrap_err();
    assert!(e.to_string().starts_with("theirs.png: "), "{e}");
    assert!(
        e.to_string().contains("PLTE") || e.to_string().contains("palette"),
        "{e}"
    );
    let e = rasterproof::oracle::GreyImage::read_png(&bytes, "theirs.png").unwrap_err();
    assert!(e.starts_with("theirs.png: not a PNG this reader takes"), "{e}");
}

/// Found by planned_exact's campaign: a triangle whose leftmost vertex lies 2^-44 px right
/// of the last sample column (x = 3.5 + 2^-44 on a 4-pixel canvas), so it covers no
/// sample, and the plan skipped it ("covers nothing") and called float32 exact. But f32
/// holds 24 significant bits: 3.5 + 2^-44 rounds to 3.5, onto the column, and the float32
/// model covers a pixel there. The float analysis now takes the range of the vertices and
/// of their rounded floats together; f64 holds the vertex exactly and still covers nothing.
#[test]
fn fuzz_case_06_a_vertex_that_rounds_onto_a_sample_in_f32() {
    let scene = parse_scene(
        r#"{
  "width": 4,
  "height": 3,
  "preset": "cts",
  "tie_rule": "top-left",
  "triangles": [
    {"v": [["49/13","6"], ["61572651155457/17592186044416","5/2"], ["6","-4"]]}
  ]
}"#,
        "fuzz_case_06.json",
    )
    .unwrap();
    assert_eq!(61_572_651_155_457_i64, 7 * (1_i64 << 43) + 1, "3.5 + 2^-44 over 2^44");
    let (primitives, target) = (scene.primitives(), scene.target().unwrap());
    let exact = render(&primitives, &target, Model::Exact).unwrap();
    assert_eq!(exact.iter().count(), 0, "every vertex right of x = 3.5");
    let float32 = render(&primitives, &target, Model::Float32).unwrap();
    assert_ne!(float32, exact, "the vertex rounded to 3.5 puts a sample on the edge");
    let plan = plan_scene(&primitives, &target, Model::Exact).unwrap();
    let snapped = render(&primitives, &target, Model::ExactSnapped).unwrap();
    for v in plan.fixed_width.iter().filter(|v| v.exact) {
        let want = if v.model.snaps() { &snapped } else { &exact };
        assert_eq!(
            &render(&primitives, &target, v.model).unwrap(),
            want,
            "{} called exact",
            v.model
        );
    }
    let verdict = |m: Model| plan.fixed_width.iter().find(|v| v.model == m).unwrap();
    assert!(!verdict(Model::Float32).exact);
    assert!(
        verdict(Model::Float32)
            .broken_by
            .as_deref()
            .unwrap()
            .starts_with("triangles[0]: "),
        "{:?}",
        verdict(Model::Float32).broken_by
    );
    assert!(verdict(Model::Float64).exact, "{:?}", verdict(Model::Float64).broken_by);
}

/// Found by values_invariants: a second triangle on the shared edge whose own vertex lies
/// on that edge's line, (13/16, 0) beside (0, 0) and (57599/256, 0), is degenerate and has
/// no value anywhere (the coordinates before the target folds them into 128 px). The
/// shared-edge checker called that a difference; a degenerate
/// triangle covers nothing, so there is nothing to agree with.
#[test]
fn fuzz_case_07_a_shared_edge_beside_a_degenerate_triangle() {
    use num_rational::BigRational;
    use rasterproof::check::check_values_shared_edge;
    use rasterproof::geom::Point;
    use rasterproof::interp::values::{Interpolation, ValueTriangle};
    let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
    let (a, b, c) = (
        Point::new(q(57599, 256), q(0, 1)),
        Point::new(q(0, 1), q(0, 1)),
        Point::new(q(38109, 256), q(624, 256)),
    );
    let t = ValueTriangle::window(
        [&a, &b, &c],
        [&q(1, 1), &q(2, 1), &q(1, 4)],
        [
            vec![q(30507, 8), q(-22288, 8)],
            vec![q(0, 1), q(-8960, 8)],
            vec![q(28820, 8), q(-31230, 8)],
        ],
    );
    let mut other = t.clone();
    other.h[2] = [q(208, 256), q(0, 1), q(1, 1)];
    assert_eq!(
        check_values_shared_edge(&t, &other, ((0, 1), (0, 1)), Interpolation::Smooth, 0..2, &q(0, 16)),
        Ok(())
    );
    // The same edge beside a triangle with area agrees, and a value there exists.
    other.h[2] = [q(208, 256), q(5, 1), q(1, 1)];
    assert_eq!(
        check_values_shared_edge(&t, &other, ((0, 1), (0, 1)), Interpolation::Smooth, 0..2, &q(3, 16)),
        Ok(())
    );
}

/// A window triangle of the values fuzz cases: exact (for the definition and the
/// envelope) and as a renderer holds it (each number rounded to f32, `1 / w` an f32
/// division).
fn values_case(
    points: [(i64, i64); 3],
    w: [(i64, i64); 3],
    values: [[i64; 2]; 3],
) -> (
    rasterproof::interp::values::ValueSetup,
    rasterproof::interp::float::FloatTriangle,
) {
    use num_rational::BigRational;
    use rasterproof::geom::Point;
    use rasterproof::interp::values::{ValueSetup, ValueTriangle};
    let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
    let points = points.map(|(x, y)| Point::new(q(x, 256), q(y, 256)));
    let w = w.map(|(n, d)| q(n, d));
    let values = values.map(|v| v.iter().map(|&n| q(n, 8)).collect::<Vec<_>>());
    let f = |r: &BigRational| rasterproof::num::exact::nearest_f32(r).unwrap();
    let tri = rasterproof::interp::float::FloatTriangle {
        x: [0, 1, 2].map(|i| f(&points[i].x)),
        y: [0, 1, 2].map(|i| f(&points[i].y)),
        inv_w: [0, 1, 2].map(|i| 1.0 / f(&w[i])),
        values: values.clone().map(|v| v.iter().map(f).collect()),
    };
    let setup = ValueSetup::Triangle(Box::new(ValueTriangle::window(
        [&points[0], &points[1], &points[2]],
        [&w[0], &w[1], &w[2]],
        values,
    )));
    (setup, tri)
}

/// The triangle of `fuzz_case_08` and `fuzz_case_10`: a 1/2.6 px edge at (127.6, 128) and
/// (128, 128), a third vertex at (33, 116.2), w 2, 2 and 1/2.
fn case_08_triangle() -> (
    rasterproof::interp::values::ValueSetup,
    rasterproof::interp::float::FloatTriangle,
) {
    values_case(
        [(32660, 32767), (32767, 32767), (8447, 29752)],
        [(2, 1), (2, 1), (1, 2)],
        [[8653, -14395], [-3588, 12760], [-15960, 8408]],
    )
}

/// Every float model the envelope bounds, at pixel `pixel` of a 160 px canvas (centre
/// 1/2), noperspective with the first vertex provoking, lands within the envelope's far
/// bound of the exact value in both channels; gives the models checked.
fn enveloped_models_inside_far(
    setup: &rasterproof::interp::values::ValueSetup,
    tri: &rasterproof::interp::float::FloatTriangle,
    pixel: (u32, u32),
) -> Vec<rasterproof::interp::float::FloatInterpolator> {
    use rasterproof::interp::values::{Interpolation, ProvokingVertex};
    enveloped_models_inside_far_as(setup, tri, pixel, Interpolation::NoPerspective, ProvokingVertex::First)
}

/// [`enveloped_models_inside_far`] under `interpolation`, with `provoking` the provoking
/// vertex (which moves a reordering model's anchor).
fn enveloped_models_inside_far_as(
    setup: &rasterproof::interp::values::ValueSetup,
    tri: &rasterproof::interp::float::FloatTriangle,
    pixel: (u32, u32),
    interpolation: rasterproof::interp::values::Interpolation,
    provoking: rasterproof::interp::values::ProvokingVertex,
) -> Vec<rasterproof::interp::float::FloatInterpolator> {
    use rasterproof::geom::Point;
    use rasterproof::interp::envelope::value_envelope;
    use rasterproof::interp::float::FloatInterpolator;
    let centre = |c: u32| num_rational::BigRational::new((2 * i64::from(c) + 1).into(), 2.into());
    let p = Point::new(centre(pixel.0), centre(pixel.1));
    let exact = setup.value(interpolation, provoking, 0..2, &p).unwrap();
    let bounds = value_envelope(setup, interpolation, 0..2, &p, 160);
    let models: Vec<FloatInterpolator> = FloatInterpolator::all()
        .into_iter()
        .filter(FloatInterpolator::enveloped)
        .collect();
    for model in &models {
        for ch in 0..2 {
            let v = model.value(tri, interpolation, provoking, ch, pixel, 160, 0.5);
            let d = distance(v, &exact[ch]).unwrap();
            let bound = bounds[ch].far.unwrap();
            assert!(d <= bound, "{} channel {ch}: {d} beyond {bound}", model.name());
        }
    }
    models
}

/// `|v - exact|` for a finite `v`; `None` for an infinity or NaN.
fn distance(v: f32, exact: &num_rational::BigRational) -> Option<f64> {
    let v = num_rational::BigRational::from_float(f64::from(v))?;
    num_traits::ToPrimitive::to_f64(&num_traits::Signed::abs(&(v - exact)))
}

/// Found by values_invariants: on a 160 px canvas, a triangle with a 1/2.6 px edge at
/// (127.6, 128) and (128, 128) and a third vertex at (33, 116.2), noperspective, evaluated
/// at pixel (192, 79), 64 px beyond it, where the value is about -10^6. Barycentrics from
/// edge functions (`sum E_i a_i / sum E_i`) landed 52 from it against a bound of 46: the
/// envelope bounded their denominator by the area's own rounding, but it is the sum of
/// three edge functions of about 10^4 that cancel down to the area. It now bounds it by
/// their absolute values.
#[test]
fn fuzz_case_08_barycentrics_whose_denominator_cancels() {
    let (setup, tri) = case_08_triangle();
    enveloped_models_inside_far(&setup, &tri, (192, 79));
}

/// Found by values_invariants: a sliver 1/256 px wide at the origin reaching (89.5,
/// 23/256), noperspective, at pixel (153, 126). Some float models divide by an f32 area
/// or edge-function sum that rounds to zero and give an infinity or NaN, which no bound
/// holds; the envelope gave one anyway. Where f32 cannot tell the area from zero the
/// envelope now bounds nothing (and `compare` judges such values by the exact searches).
#[test]
fn fuzz_case_09_an_area_f32_cannot_tell_from_zero() {
    use rasterproof::geom::Point;
    use rasterproof::interp::envelope::value_envelope;
    use rasterproof::interp::float::FloatInterpolator;
    use rasterproof::interp::values::{Interpolation, ProvokingVertex};
    let (setup, tri) = values_case(
        [(1, 0), (0, 0), (22903, 23)],
        [(1, 4), (1, 4), (1, 4)],
        [[0, 2045], [32503, 16080], [2303, -2297]],
    );
    let p = Point::new(
        num_rational::BigRational::new(307.into(), 2.into()),
        num_rational::BigRational::new(253.into(), 2.into()),
    );
    let exact = setup
        .value(Interpolation::NoPerspective, ProvokingVertex::First, 0..2, &p)
        .unwrap();
    let bounds = value_envelope(&setup, Interpolation::NoPerspective, 0..2, &p, 160);
    let mut unbounded_wrong = 0;
    for model in FloatInterpolator::all()
        .into_iter()
        .filter(FloatInterpolator::enveloped)
    {
        for ch in 0..2 {
            let v = model.value(
                &tri,
                Interpolation::NoPerspective,
                ProvokingVertex::First,
                ch,
                (153, 126),
                160,
                0.5,
            );
            match (bounds[ch].far, distance(v, &exact[ch])) {
                (Some(bound), Some(d)) => assert!(d <= bound, "{} channel {ch}: {d} beyond {bound}", model.name()),
                (Some(bound), None) => panic!("{} channel {ch}: {v} under the bound {bound}", model.name()),
                (None, d) => unbounded_wrong += usize::from(d.is_none()),
            }
        }
    }
    // Some model does give a non-finite value here: the reason there is no bound.
    assert!(unbounded_wrong > 0);
}

/// Found by values_invariants (its seed `seed-fuzz-case-08b`): the triangle of
/// `fuzz_case_08` at pixel (32, 79) of a 160 px canvas, noperspective. The models that set
/// up in GL's window coordinates (y up: `y' = 160 - y`) anchor their origin plane at the
/// canvas's bottom-left corner, 160 px from the top-left one the envelope's far bound
/// measured from; a value they gave lay beyond it. The far bound now takes the plane
/// anchored at either corner.
#[test]
fn fuzz_case_10_an_origin_plane_anchored_at_the_bottom_left() {
    let (setup, tri) = case_08_triangle();
    let checked = enveloped_models_inside_far(&setup, &tri, (32, 79));
    assert!(
        checked.iter().any(|m| m.y_up),
        "the y-up models are among those checked"
    );
}

/// Found by values_invariants once it checked the f64 filter (`FastPlan`): vertices 1 and 2
/// both at the origin, w = 1/4, 1/4 and 8, smooth, at pixel (0, 0). The triangle has no
/// area, so the plain definition gives no value (`Degenerate`); but with unequal w the
/// filter's `N / D` is finite off the triangle's line, and it decided 2198.6775 there. The
/// filter now leaves every value of a triangle whose area's sign it cannot certify to the
/// exact path.
#[test]
fn fuzz_case_11_the_f64_filter_on_a_triangle_without_area() {
    use rasterproof::geom::Point;
    use rasterproof::interp::planned::{FastPlan, TriangleF64};
    use rasterproof::interp::values::{Interpolation, NoValue, ProvokingVertex};
    let (setup, _) = values_case(
        [(31207, 175), (0, 0), (0, 0)],
        [(1, 4), (1, 4), (8, 1)],
        [[-1184, 4848], [17049, 11965], [296, 0]],
    );
    let p = Point::new(
        num_rational::BigRational::new(1.into(), 2.into()),
        num_rational::BigRational::new(1.into(), 2.into()),
    );
    assert_eq!(
        setup.value(Interpolation::Smooth, ProvokingVertex::First, 0..2, &p),
        Err(NoValue::Degenerate)
    );
    let fast = FastPlan::new(
        &TriangleF64::of(&setup, 0..2).unwrap(),
        Interpolation::Smooth,
        ProvokingVertex::First,
        (0.5, 0.5),
    );
    let mut out = [Some(0.0); 2];
    fast.nearest_f32(0, 0, &mut out);
    assert_eq!(out, [None, None]);
}

/// Found by values_invariants: a sliver on a 160 px canvas, two vertices 0.4 px apart on
/// y = 0 ((0.43, 0) and (0.03, 0)) and the third at (128, 128), w 1/4 each, smooth, the
/// last vertex provoking, at pixel (0, 0) just outside it. llvmpipe's reordering of a
/// clockwise triangle with the last vertex provoking, `(v1, v0, v2)`, sets the plane up
/// from the far vertex, where the differences are 128 px long and the area (about 51 px^2)
/// cancels from products of 16384: `origin-plane fma ccw rcp f32 y-down` gave 1.2573242
/// against 8483081/6684468 (1.2691), 0.0117 away, and the envelope, which summed the
/// gradient's absolute values from vertex 0 only (0.4 px differences there), allowed
/// 0.0074. The envelope now takes the largest sums over the three vertices a renderer may
/// set the gradient up from.
#[test]
fn fuzz_case_12_a_sliver_set_up_from_its_far_vertex() {
    use rasterproof::interp::values::{Interpolation, ProvokingVertex};
    let (setup, tri) = values_case(
        [(110, 0), (32767, 32767), (8, 0)],
        [(1, 4), (1, 4), (1, 4)],
        [[0, 2821], [2049, -2267], [2, 0]],
    );
    let checked = enveloped_models_inside_far_as(&setup, &tri, (0, 0), Interpolation::Smooth, ProvokingVertex::Last);
    assert!(
        checked
            .iter()
            .any(|m| m.name() == "origin-plane fma ccw rcp f32 y-down"),
        "the reordering model is among those checked"
    );
}
