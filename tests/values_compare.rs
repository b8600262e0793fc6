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
        pattern: None,
        picture: false,
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

/// Under the standard 4x pattern, a centroid varying: the triangle (0, 0), (23/8, 0),
/// (0, 23/8) with the value x + y (w = 1) on a 4x4 canvas, their image stacked per sample.
/// By hand: the standard 4x samples sit at (3/8, 1/8), (7/8, 3/8), (1/8, 5/8), (5/8, 7/8)
/// of the pixel, so sample s of pixel (i, j) has x + y = i + j + (1/2, 5/4, 3/4, 3/2)[s],
/// inside where that is below 23/8 (never equal: the sums are quarters). Pixel (1, 1):
/// samples 0 and 2 inside (5/2, 11/4), 1 and 3 outside (13/4, 7/2); its centre (3/2, 3/2)
/// at 3 is outside too. Direct3D's centroid is sample 0, value 5/2. The region of the pixel
/// inside the triangle runs from (1, 1) (value 2) to the edge (value 23/8): any value in
/// [2, 23/8] is a point Vulkan's centroid allows; 3, the centre's, is not.
#[test]
fn a_centroid_per_sample_is_judged_by_hand() {
    let truth = parse_scene(
        r#"{"width": 4, "height": 4, "samples": 4,
            "varyings": [{"name": "c", "channels": 1, "interpolation": "smooth", "sampling": "centroid"}],
            "triangles": [{"v": [[0, 0], ["23/8", 0], [0, "23/8"]], "varyings": {"c": [[0], ["23/8"], ["23/8"]]}}]}"#,
        "centroid",
    )
    .unwrap();
    let target = Target::new(4, 4, truth.convention()).unwrap();
    let offsets = [0.5f32, 1.25, 0.75, 1.5];
    let grey = |samples: &[f32], height: u32| {
        let mut bytes = std::io::Cursor::new(Vec::new());
        tiff::encoder::TiffEncoder::new(&mut bytes)
            .unwrap()
            .write_image::<tiff::encoder::colortype::Gray32Float>(4, height, samples)
            .unwrap();
        Theirs::read(&bytes.into_inner(), "theirs.tiff", Format::Values, Default::default()).unwrap()
    };
    let stacked = |pixel_1_1: f32| {
        let mut samples = vec![0f32; 4 * 16];
        for j in 0..4u32 {
            for i in 0..4u32 {
                let inside: Vec<bool> = offsets.iter().map(|o| (i + j) as f32 + o < 2.875).collect();
                // The fragment's value: the centre's when every sample is inside, else
                // the first inside sample's.
                let value = if inside.iter().all(|&b| b) {
                    (i + j) as f32 + 1.0
                } else if let Some(first) = inside.iter().position(|&b| b) {
                    (i + j) as f32 + offsets[first]
                } else {
                    continue;
                };
                let value = if (i, j) == (1, 1) { pixel_1_1 } else { value };
                for (s, _) in inside.iter().enumerate().filter(|&(_, &b)| b) {
                    samples[(s as u32 * 16 + j * 4 + i) as usize] = value;
                }
            }
        }
        grey(&samples, 16)
    };
    let options = options(&truth).with_pattern(truth.samples.clone(), &target.convention);
    let judge = |theirs: &Theirs| compare_values(&truth.primitives(), &target, theirs, &options).unwrap();
    // Pixels (0, 0), (1, 0), (0, 1) wholly inside; (2, 0), (0, 2), (1, 1) in part: 3 x 4 +
    // 3 x 2 samples (pixel (2, 0): sums 5/2 and 11/4 inside, as (1, 1)).
    let right = judge(&stacked(2.5));
    assert_eq!(right.counts, [(ValueClass::Exact, 18)], "{right:?}");
    assert_eq!(right.samples, 4);
    let at_centre = judge(&stacked(3.0));
    assert_eq!(at_centre.counts, [(ValueClass::Exact, 16), (ValueClass::AtCentre, 2)]);
    let off: Vec<(u32, u32, usize)> = at_centre.pixels.iter().map(|p| (p.x, p.y, p.sample)).collect();
    assert_eq!(off, [(1, 1, 0), (1, 1, 2)]);
    // Sample 2's value, 11/4: another covered sample, inside the region.
    let vulkan = judge(&stacked(2.75));
    assert_eq!(vulkan.counts, [(ValueClass::Exact, 16), (ValueClass::CentroidRange, 2)]);
    assert_eq!(vulkan.off(), 0);
    // The region's corner and its far edge are its extremes, give or take f32's error
    // (a few steps); 1/64 beyond is not allowed.
    assert_eq!(judge(&stacked(2.0)).counts[1], (ValueClass::CentroidRange, 2));
    assert_eq!(judge(&stacked(step(2.0, -2))).counts[1], (ValueClass::CentroidRange, 2));
    assert_eq!(judge(&stacked(2.875)).counts[1], (ValueClass::CentroidRange, 2));
    assert_eq!(judge(&stacked(2.0 - 1.0 / 64.0)).counts[1].0, ValueClass::Gross);
    assert_eq!(judge(&stacked(2.875 + 1.0 / 64.0)).counts[1].0, ValueClass::Gross);
    // An image of the canvas's size, not stacked: refused with both sizes named.
    let flat = grey(&[0.0; 16], 4);
    let error = compare_values(&truth.primitives(), &target, &flat, &options)
        .unwrap_err()
        .to_string();
    assert!(error.contains("4x4") && error.contains("4x16"), "{error}");
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
    // Under 4 samples: the stacked TIFF (32 rows), judged per sample; the one-sample TIFF
    // refused with both sizes; a PNG --values-out refused.
    let stacked = dir.path().join("stacked.tiff");
    let render4 = |out: &std::path::Path| {
        Command::cargo_bin("rasterproof")
            .unwrap()
            .arg("render")
            .arg(&scene)
            .args(["--samples", "4", "--values-out"])
            .arg(out)
            .output()
            .unwrap()
    };
    assert!(render4(&stacked).status.success());
    let (code, text) = compare(&[
        scene.as_os_str(),
        stacked.as_os_str(),
        "--samples".as_ref(),
        "4".as_ref(),
    ]);
    assert_eq!(code, 0, "{text}");
    assert!(
        text.contains("4 samples a pixel") && text.contains("samples judged"),
        "{text}"
    );
    let (code, text) = compare(&[scene.as_os_str(), tiff.as_os_str(), "--samples".as_ref(), "4".as_ref()]);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("8x4") && text.contains("8x16"), "{text}");
    let refused = render4(&png);
    assert_eq!(refused.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&refused.stderr).contains("a PNG --values-out"));
}
