//! `compare --as values` and its fit: their values classed against the exact ones (each
//! class produced by hand from a deliberate fault), the float models of
//! `interp::float` held inside the f32 envelope on random triangles (a correct float
//! interpolator is never called off), and the CLI's errors.

use assert_cmd::Command;
use num_rational::BigRational;
use proptest::prelude::*;
use proptest::test_runner::Config;
use rasterproof::convention::Target;
use rasterproof::geom::Point;
use rasterproof::interp::envelope::value_envelope;
use rasterproof::interp::float::{FloatInterpolator, FloatTriangle};
use rasterproof::interp::values::{Interpolation, ProvokingVertex, ValueSetup, ValueTriangle};
use rasterproof::model::Model;
use rasterproof::num::exact::nearest_f32;
use rasterproof::num::unorm::UnormRule;
use rasterproof::oracle::compare::values::{compare_values, ValueClass, ValueOptions};
use rasterproof::oracle::{Format, Theirs};
use rasterproof::raster::sample_exact;
use rasterproof::scene::{parse_scene, Scene};

use crate::common::config;
use crate::tempdir;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// One triangle on a 16x8 canvas: vertex values (0, 10, 100), (8, 20, 0), (1/3, 0, 50),
/// w = 1, 2, 4.
fn scene(interpolation: &str, provoking: &str) -> Scene {
    parse_scene(
        &format!(
            r#"{{"width": 16, "height": 8, "provoking_vertex": "{provoking}",
                "varyings": [{{"name": "c", "channels": 3, "interpolation": "{interpolation}"}}],
                "triangles": [{{"v": [[0.5, 0.25], [15.5, 1], [2, 7.75]], "w": [1, 2, 4],
                    "varyings": {{"c": [[0, 10, 100], [8, 20, 0], ["1/3", 0, 50]]}}}}]}}"#
        ),
        "scene",
    )
    .unwrap()
}

fn options(scene: &Scene) -> ValueOptions {
    ValueOptions {
        model: Model::ExactSnapped,
        setups: scene.value_setups(),
        varyings: scene.varyings.clone(),
        varying: 0,
        unorm: UnormRule::Nearest,
    }
}

/// Their float32 TIFF: at each covered pixel, `f` of the exact value at its centre of
/// `values_of` (another scene: the fault) and of the pixel.
fn their_tiff(truth: &Scene, values_of: &Scene, f: impl Fn(u32, u32, Vec<f32>) -> Vec<f32>) -> Theirs {
    let target = Target::new(truth.width, truth.height, truth.convention()).unwrap();
    let coverage = rasterproof::model::render(&truth.primitives(), &target, Model::ExactSnapped).unwrap();
    let setups = values_of.value_setups();
    let (w, h) = (truth.width, truth.height);
    let mut samples = vec![0f32; (w * h * 3) as usize];
    for (x, y, ids) in coverage.iter() {
        let setup = setups[*ids.last().unwrap() as usize].as_ref().unwrap();
        let v = setup
            .value(
                values_of.varyings.list[0].interpolation,
                values_of.varyings.provoking,
                0..3,
                &sample_exact(x, y, &target),
            )
            .unwrap();
        let exact: Vec<f32> = v.iter().map(|c| nearest_f32(c).unwrap()).collect();
        let at = ((y * w + x) * 3) as usize;
        samples[at..at + 3].copy_from_slice(&f(x, y, exact));
    }
    let mut bytes = std::io::Cursor::new(Vec::new());
    tiff::encoder::TiffEncoder::new(&mut bytes)
        .unwrap()
        .write_image::<tiff::encoder::colortype::RGB32Float>(w, h, &samples)
        .unwrap();
    Theirs::read(&bytes.into_inner(), "theirs.tiff", Format::Values, Default::default()).unwrap()
}

fn classes(truth: &Scene, theirs: &Theirs) -> Vec<(ValueClass, usize)> {
    let target = Target::new(truth.width, truth.height, truth.convention()).unwrap();
    compare_values(&truth.primitives(), &target, theirs, &options(truth))
        .unwrap()
        .counts
}

fn step(f: f32, n: i32) -> f32 {
    f32::from_bits(f.to_bits().wrapping_add_signed(n))
}

#[test]
fn each_fault_is_named_by_its_class() {
    let smooth = scene("smooth", "first");
    let covered = |s: &Scene| {
        let t = Target::new(s.width, s.height, s.convention()).unwrap();
        rasterproof::model::render(&s.primitives(), &t, Model::ExactSnapped)
            .unwrap()
            .covered_pixels()
    };
    let n = covered(&smooth);
    assert!(n > 40, "{n}");
    // The correctly rounded values: every pixel exact.
    let same = their_tiff(&smooth, &smooth, |_, _, v| v);
    assert_eq!(classes(&smooth, &same), [(ValueClass::Exact, n)]);
    // One f32 step off in every channel: inside the envelope.
    let near = their_tiff(&smooth, &smooth, |_, _, v| v.into_iter().map(|c| step(c, 1)).collect());
    assert_eq!(classes(&smooth, &near), [(ValueClass::F32, n)]);
    // The noperspective values of a smooth varying.
    let affine = their_tiff(&smooth, &scene("noperspective", "first"), |_, _, v| v);
    assert_eq!(classes(&smooth, &affine), [(ValueClass::Affine, n)]);
    assert_eq!(
        classes(
            &scene("noperspective", "first"),
            &their_tiff(&scene("noperspective", "first"), &smooth, |_, _, v| v)
        ),
        [(ValueClass::Perspective, n)]
    );
    // Flat from the last vertex where the scene says first.
    let flat_first = scene("flat", "first");
    let last = their_tiff(&flat_first, &scene("flat", "last"), |_, _, v| v);
    assert_eq!(classes(&flat_first, &last), [(ValueClass::ProvokingVertex, n)]);
    // Red and blue exchanged.
    let swapped = their_tiff(&smooth, &smooth, |_, _, v| vec![v[2], v[1], v[0]]);
    assert_eq!(classes(&smooth, &swapped), [(ValueClass::ChannelsSwapped, n)]);
    // A value 1 larger at one pixel: gross there only.
    let gross = their_tiff(&smooth, &smooth, |x, y, v| {
        if (x, y) == (4, 2) {
            vec![v[0] + 1.0, v[1], v[2]]
        } else {
            v
        }
    });
    assert_eq!(
        classes(&smooth, &gross),
        [(ValueClass::Exact, n - 1), (ValueClass::Gross, 1)]
    );
}

#[test]
fn vertices_in_another_order_are_named() {
    let smooth = scene("smooth", "first");
    let text = r#"{"width": 16, "height": 8,
        "varyings": [{"name": "c", "channels": 3, "interpolation": "smooth"}],
        "triangles": [{"v": [[0.5, 0.25], [15.5, 1], [2, 7.75]], "w": [1, 2, 4],
            "varyings": {"c": [[8, 20, 0], [0, 10, 100], ["1/3", 0, 50]]}}]}"#;
    let permuted = parse_scene(text, "permuted").unwrap();
    let theirs = their_tiff(&smooth, &permuted, |_, _, v| v);
    let counts = classes(&smooth, &theirs);
    let vertices = counts
        .iter()
        .find(|(c, _)| *c == ValueClass::VerticesPermuted)
        .map_or(0, |(_, n)| *n);
    // Where the two value planes cross a pixel may hold the same value under both orders.
    let total: usize = counts.iter().map(|(_, n)| n).sum();
    assert!(vertices + 2 >= total, "{counts:?}");
}

/// A window triangle as `FloatTriangle` and as the exact setup, from small integers over
/// 256 (positions) and over 8 (values), with `w` a power of two.
fn triangles() -> impl Strategy<Value = (FloatTriangle, ValueSetup)> {
    (
        prop::array::uniform3((0i64..40 * 256, 0i64..16 * 256)),
        prop::array::uniform3(0u32..4),
        prop::array::uniform3(prop::array::uniform2(-800i64..800)),
        0i64..(1 << 14) - 64,
    )
        .prop_map(|(pos, w, values, offset)| {
            let points = pos.map(|(x, y)| Point::new(q(x + offset * 256, 256), q(y, 256)));
            let ws = w.map(|e| q(1 << e, 1));
            let vals = values.map(|v| v.map(|c| q(c, 8)).to_vec());
            let setup = ValueSetup::Triangle(Box::new(ValueTriangle::window(
                [&points[0], &points[1], &points[2]],
                [&ws[0], &ws[1], &ws[2]],
                vals.clone(),
            )));
            let f = |r: &BigRational| nearest_f32(r).unwrap();
            let tri = FloatTriangle {
                x: [0, 1, 2].map(|i| f(&points[i].x)),
                y: [0, 1, 2].map(|i| f(&points[i].y)),
                inv_w: [0, 1, 2].map(|i| 1.0 / f(&ws[i])),
                values: vals.map(|v| v.iter().map(f).collect()),
            };
            (tri, setup)
        })
}

proptest! {
    #![proptest_config(Config { cases: 64, ..config("proptest-regressions/values_compare.txt") })]

    /// Every float model of an interpolator, at pixels inside and near the triangle, lands
    /// within the envelope's `far` bound of the exact value: the envelope never calls a
    /// correct f32 interpolator off (offsets up to 2^14 px).
    #[test]
    fn float_models_stay_inside_the_envelope((tri, setup) in triangles(), px in 0u32..40, py in 0u32..16) {
        let ValueSetup::Triangle(t) = &setup else { unreachable!() };
        let x0 = (t.h[0][0].clone() / t.h[0][2].clone()).floor().to_integer();
        let px = u32::try_from(x0).unwrap() + px;
        let p = Point::new(q(i64::from(px), 1) + q(1, 2), q(i64::from(py), 1) + q(1, 2));
        for interpolation in [Interpolation::Smooth, Interpolation::NoPerspective] {
            let Ok(exact) = setup.value(interpolation, ProvokingVertex::First, 0..2, &p) else { continue };
            let envelope = value_envelope(&setup, interpolation, 0..2, &p, 16);
            for model in FloatInterpolator::all().into_iter().filter(FloatInterpolator::enveloped) {
                for c in 0..2 {
                    let v = model.value(&tri, interpolation, ProvokingVertex::First, c, (px, py), 16, 0.5);
                    let Some(bound) = envelope[c].far else { continue };
                    let d = num_traits::Signed::abs(&(BigRational::from_float(f64::from(v)).unwrap() - &exact[c]));
                    prop_assert!(
                        num_traits::ToPrimitive::to_f64(&d).unwrap() <= bound,
                        "{} {interpolation}: {v} against {} (bound {bound})",
                        model.name(),
                        exact[c]
                    );
                }
            }
        }
    }
}

fn compare(args: &[&std::ffi::OsStr]) -> (i32, String) {
    let out = Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("compare")
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ),
    )
}

#[test]
fn the_cli_reads_values_and_names_its_errors() {
    let dir = tempdir::Dir::new("values-compare");
    let scene = dir.path().join("s.json");
    std::fs::write(
        &scene,
        r#"{"width": 8, "height": 4, "varyings": [{"name": "uv", "channels": 2}, {"name": "k", "channels": 1, "interpolation": "flat"}],
            "triangles": [{"v": [[0, 0], [8, 0], [0, 4]], "varyings": {"uv": [[0, 0], [1, 0], [0, 1]], "k": [[3], [4], [5]]}}]}"#,
    )
    .unwrap();
    let tiff = dir.path().join("v.tiff");
    let png = dir.path().join("v.png");
    for (out, extra) in [(&tiff, None), (&png, Some("--unorm"))] {
        let mut cmd = Command::cargo_bin("rasterproof").unwrap();
        cmd.arg("render").arg(&scene).arg("--values-out").arg(out);
        if let Some(e) = extra {
            cmd.args([e, "16"]);
        }
        assert!(cmd.output().unwrap().status.success());
    }
    // The oracle's own images: exact (the TIFF by extension, the PNG by --as).
    let (code, text) = compare(&[scene.as_os_str(), tiff.as_os_str()]);
    assert_eq!(code, 0, "{text}");
    assert!(text.contains("right:") && text.contains("exact"), "{text}");
    let (code, text) = compare(&[scene.as_os_str(), png.as_os_str(), "--as".as_ref(), "values".as_ref()]);
    assert_eq!(code, 0, "{text}");
    assert!(text.contains("read as unorm16 (nearest rule)"), "{text}");
    // The 2-channel TIFF judged as the flat varying `k` (1 channel): uv's u is not 3, 4 or 5.
    let (code, text) = compare(&[scene.as_os_str(), tiff.as_os_str(), "--varying".as_ref(), "k".as_ref()]);
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("gross"), "{text}");
    // Errors name what is wrong.
    let (code, text) = compare(&[scene.as_os_str(), tiff.as_os_str(), "--varying".as_ref(), "w".as_ref()]);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("declares no varying \"w\""), "{text}");
    let (code, text) = compare(&[
        scene.as_os_str(),
        png.as_os_str(),
        "--as".as_ref(),
        "values".as_ref(),
        "--fit".as_ref(),
    ]);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("UNORM levels"), "{text}");
    let (code, text) = compare(&[scene.as_os_str(), scene.as_os_str(), "--as".as_ref(), "values".as_ref()]);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("neither a TIFF nor a PNG"), "{text}");
    let (code, text) = compare(&[scene.as_os_str(), png.as_os_str(), "--varying".as_ref(), "k".as_ref()]);
    assert_eq!(code, 2, "{text}");
    assert!(
        text.contains("--varying and --unorm-rule are for --as values"),
        "{text}"
    );
}
