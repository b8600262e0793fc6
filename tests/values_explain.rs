//! `explain --as values`: one pixel's values derived exactly, checked against values worked
//! out by hand (barycentrics, the smooth and noperspective values, the nearest f32's bits
//! and the distance in f32 steps to a hand-made image of theirs), per sample under a
//! pattern, and the CLI's errors.

use assert_cmd::Command;
use num_rational::BigRational;
use rasterproof::interp::values::{Interpolation, Sampling, Varying, Varyings};
use rasterproof::model::{values_tiff, SampleValues};
use serde_json::Value;

use crate::tempdir;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// One triangle on a 4x4 canvas: (0, 0) at w = 1, (4, 0) at w = 2, (0, 4) at w = 4, with
/// the smooth value `s` = 0, 8, 16 and the flat value `k` = 3, 4, 5 (provoking vertex
/// last); `samples` 1 or 4, `s` taken at `sampling`.
fn scene_text(samples: usize, sampling: &str) -> String {
    format!(
        r#"{{"width": 4, "height": 4, "samples": {samples}, "provoking_vertex": "last",
            "varyings": [{{"name": "s", "channels": 1, "interpolation": "smooth", "sampling": "{sampling}"}},
                         {{"name": "k", "channels": 1, "interpolation": "flat"}}],
            "triangles": [{{"v": [[0, 0], [4, 0], [0, 4]], "w": [1, 2, 4], "varyings": {{"s": [[0], [8], [16]], "k": [[3], [4], [5]]}}}}]}}"#
    )
}

/// Their one-channel float32 TIFF of the 4x4 canvas (stacked `samples` times), written by
/// the crate's own writer: `(x, y, sample, f32 bits)`, 0 elsewhere.
fn their_tiff(samples: usize, values: &[(u32, u32, usize, u32)]) -> Vec<u8> {
    let varyings = Varyings {
        list: vec![Varying {
            name: "s".into(),
            channels: 1,
            interpolation: Interpolation::Smooth,
            sampling: Sampling::Centre,
        }],
        ..Varyings::default()
    };
    let values: Vec<SampleValues> = values
        .iter()
        .map(|&(x, y, sample, bits)| SampleValues {
            x,
            y,
            sample,
            id: 0,
            // An f32 exactly: the writer's rounding to the nearest f32 keeps it.
            values: vec![Ok(vec![
                BigRational::from_float(f64::from(f32::from_bits(bits))).unwrap()
            ])],
        })
        .collect();
    values_tiff(&values, &varyings, 0, 4, 4, samples).unwrap()
}

fn explain(args: &[&std::ffi::OsStr]) -> (i32, String, String) {
    let out = Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("explain")
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn os(s: &str) -> &std::ffi::OsStr {
    s.as_ref()
}

/// `explain ARGS --format json`, which succeeds: its JSON.
fn explain_json(args: &[&std::ffi::OsStr]) -> Value {
    let mut all = args.to_vec();
    all.extend([os("--format"), os("json")]);
    let (code, json, err) = explain(&all);
    assert_eq!(code, 0, "{err}");
    serde_json::from_str(&json).unwrap()
}

/// By hand, pixel (1, 1) at its centre p = (3/2, 3/2). Window barycentrics over (0, 0),
/// (4, 0), (0, 4): mu_1 = x / 4 = 3/8, mu_2 = y / 4 = 3/8, mu_0 = 1/4. Homogeneous
/// barycentrics b_i = mu_i / w_i = (1/4, 3/16, 3/32), their sum 1/w = 17/32. Smooth:
/// (3/16 x 8 + 3/32 x 16) / (17/32) = 3 x 32/17 = 96/17; the weights b_i / (17/32) are
/// (8/17, 6/17, 3/17). 96/17 = 4 x 24/17, exponent 2 (biased 129, 0x40800000); the
/// fraction 7/17 of 2^23 is 3454132.7..., rounded up: 3454133 = 0x34b4b5, so the nearest
/// f32 is 0x40b4b4b5. Theirs there is two steps below, 0x40b4b4b3: -2 steps, inside the
/// envelope (two steps of 2^-21 beside sixteen roundings of numbers near 16), class f32.
///
/// Pixel (0, 2) at (1/2, 5/2): mu = (1/4, 1/8, 5/8), b = (1/4, 1/16, 5/32), 1/w = 15/32;
/// smooth (1/2 + 5/2) / (15/32) = 32/5; noperspective 1/8 x 8 + 5/8 x 16 = 11. Theirs is
/// 11 (0x41300000): the affine value. 32/5 = 4 x 1.6: the fraction 0.6 of 2^23 is
/// 5033164.8, rounded up, 0x4ccccd: 0x40cccccd; 0x41300000 - 0x40cccccd = 0x633333 =
/// 6501171 steps above.
#[test]
fn a_pixels_values_are_derived_as_by_hand() {
    let dir = tempdir::Dir::new("values-explain");
    let scene = dir.path().join("s.json");
    std::fs::write(&scene, scene_text(1, "centre")).unwrap();
    let theirs = dir.path().join("theirs.tiff");
    std::fs::write(
        &theirs,
        their_tiff(1, &[(1, 1, 0, 0x40b4_b4b3), (0, 2, 0, 0x4130_0000)]),
    )
    .unwrap();
    let why = explain_json(&[scene.as_os_str(), os("1,1"), theirs.as_os_str()]);
    assert_eq!(why["read_as"], "float32");
    assert_eq!(why["varying"]["name"], "s");
    let sample = &why["samples"][0];
    assert_eq!(sample["owners"], serde_json::json!([0]));
    let shown = &sample["shown"];
    assert_eq!(shown["id"], 0);
    assert_eq!(shown["primitive"], "triangles[0]");
    assert_eq!(shown["point"], serde_json::json!(["3/2", "3/2"]));
    let d = &shown["derivation"];
    assert_eq!(
        d["homogeneous_barycentrics"],
        serde_json::json!(["1/4", "3/16", "3/32"])
    );
    assert_eq!(d["inverse_w"], "17/32");
    assert_eq!(d["window_barycentrics"], serde_json::json!(["1/4", "3/8", "3/8"]));
    assert_eq!(d["weights"], serde_json::json!(["8/17", "6/17", "3/17"]));
    let c = &shown["channels"][0];
    assert_eq!(c["exact"], "96/17");
    assert_eq!(c["nearest_f32_bits"], "0x40b4b4b5");
    assert_eq!(c["theirs_bits"], "0x40b4b4b3");
    assert_eq!(c["f32_steps"], -2);
    assert!(c["formula"].as_str().unwrap().ends_with("= 96/17"), "{c}");
    assert!(c["envelope"]["near"].as_f64().unwrap() > 0.0);
    assert_eq!(sample["class"], "f32");
    assert_eq!(sample["off"], false);

    let why = explain_json(&[scene.as_os_str(), os("0,2"), theirs.as_os_str()]);
    let sample = &why["samples"][0];
    let c = &sample["shown"]["channels"][0];
    assert_eq!(c["exact"], "32/5");
    assert_eq!(c["nearest_f32_bits"], "0x40cccccd");
    assert_eq!(c["f32_steps"], 6_501_171);
    assert_eq!(sample["class"], "affine");
    assert_eq!(sample["off"], true);

    // The text says the same, and names the class's meaning.
    let (code, text, _) = explain(&[scene.as_os_str(), os("0,2"), theirs.as_os_str()]);
    assert_eq!(code, 0);
    assert!(
        text.contains("b = (1/4, 1/16, 5/32); 1/w = b0 + b1 + b2 = 15/32"),
        "{text}"
    );
    assert!(text.contains("= 32/5\n"), "{text}");
    assert!(text.contains("theirs 1.1e1 (0x41300000): +6501171 f32 steps"), "{text}");
    assert!(text.contains("class affine (off): the screen-linear value"), "{text}");

    // Without their image: the exact values alone; the flat varying `k` is the provoking
    // (last) vertex's 5.
    let why = explain_json(&[
        scene.as_os_str(),
        os("1,1"),
        os("--as"),
        os("values"),
        os("--varying"),
        os("k"),
    ]);
    let sample = &why["samples"][0];
    assert_eq!(sample["shown"]["channels"][0]["exact"], "5");
    assert!(sample["shown"]["channels"][0]["formula"]
        .as_str()
        .unwrap()
        .contains("the provoking vertex: the last"));
    assert_eq!(sample["theirs"], Value::Null);
    assert_eq!(sample["class"], Value::Null);
    assert_eq!(why["read_as"], Value::Null);
}

/// Under the standard 4x pattern with `sampling: sample`, pixel (1, 1)'s sample 0 sits at
/// (1 + 3/8, 1 + 1/8) = (11/8, 9/8): mu = (1 - 5/8, 11/32, 9/32) = (3/8, 11/32, 9/32), b
/// = (3/8, 11/64, 9/128), 1/w = (48 + 22 + 9)/128 = 79/128, smooth (11/8 + 9/8) / (79/128)
/// = 320/79. Sample 3 at (13/8, 15/8) (x + y = 7/2 < 4: covered): mu = (1/8, 13/32,
/// 15/32), b = (1/8, 13/64, 15/128), 1/w = (16 + 26 + 15)/128 = 57/128, smooth (13/8 +
/// 15/8) / (57/128) = 448/57. Their stacked image holds 320/79 rounded at sample 0 (row
/// 1) and 100 at sample 3 (row 13): exact and gross.
#[test]
fn each_sample_of_a_pattern_is_derived_at_its_own_point() {
    let dir = tempdir::Dir::new("values-explain-4x");
    let scene = dir.path().join("s.json");
    std::fs::write(&scene, scene_text(4, "sample")).unwrap();
    let nearest = rasterproof::num::exact::nearest_f32(&q(320, 79)).unwrap();
    let theirs = dir.path().join("stacked.tiff");
    std::fs::write(
        &theirs,
        their_tiff(4, &[(1, 1, 0, nearest.to_bits()), (1, 1, 3, 100f32.to_bits())]),
    )
    .unwrap();
    let why = explain_json(&[scene.as_os_str(), os("1,1"), theirs.as_os_str()]);
    let samples = why["samples"].as_array().unwrap();
    assert_eq!(samples.len(), 4);
    let s0 = &samples[0]["shown"];
    assert_eq!(s0["point"], serde_json::json!(["11/8", "9/8"]));
    assert_eq!(s0["derivation"]["inverse_w"], "79/128");
    assert_eq!(s0["channels"][0]["exact"], "320/79");
    assert_eq!(s0["channels"][0]["f32_steps"], 0);
    assert_eq!(samples[0]["class"], "exact");
    let s3 = &samples[3]["shown"];
    assert_eq!(s3["point"], serde_json::json!(["13/8", "15/8"]));
    assert_eq!(s3["channels"][0]["exact"], "448/57");
    assert_eq!(s3["channels"][0]["theirs"], 100.0);
    assert_eq!(samples[3]["class"], "gross");
    assert_eq!(samples[3]["position"], "(5/8, 7/8)");
}

#[test]
fn bad_input_exits_2_naming_the_field() {
    let dir = tempdir::Dir::new("values-explain-errors");
    let scene = dir.path().join("s.json");
    std::fs::write(&scene, scene_text(1, "centre")).unwrap();
    let bare = dir.path().join("bare.json");
    std::fs::write(
        &bare,
        r#"{"width": 4, "height": 4, "triangles": [{"v": [[0, 0], [4, 0], [0, 4]]}]}"#,
    )
    .unwrap();
    let theirs = dir.path().join("theirs.tiff");
    std::fs::write(&theirs, their_tiff(1, &[])).unwrap();
    let tall = dir.path().join("tall.tiff");
    std::fs::write(&tall, their_tiff(2, &[])).unwrap();
    let cases: Vec<(Vec<&std::ffi::OsStr>, &str)> = vec![
        (
            vec![scene.as_os_str(), os("4,0"), theirs.as_os_str()],
            "pixel: (4, 0) is off the 4x4 canvas",
        ),
        (
            vec![bare.as_os_str(), os("1,1"), os("--as"), os("values")],
            "declares no varyings",
        ),
        (
            vec![
                scene.as_os_str(),
                os("1,1"),
                theirs.as_os_str(),
                os("--varying"),
                os("q"),
            ],
            "--varying: ",
        ),
        (
            vec![scene.as_os_str(), os("1,1"), tall.as_os_str()],
            "their image is 4x8 but the scene's canvas is 4x4",
        ),
        (
            vec![scene.as_os_str(), os("1,1"), scene.as_os_str(), os("--as"), os("ids")],
            "explain reads THEIRS as values only",
        ),
        (
            vec![
                scene.as_os_str(),
                os("1,1"),
                theirs.as_os_str(),
                os("--coverage"),
                os("area"),
            ],
            "--coverage area is for coverage",
        ),
        (
            vec![scene.as_os_str(), os("1,1"), os("--varying"), os("s")],
            "--varying and --unorm-rule are for --as values",
        ),
        (
            vec![
                scene.as_os_str(),
                os("1,1"),
                theirs.as_os_str(),
                os("--model"),
                os("float32"),
            ],
            "the oracle must be an exact model",
        ),
    ];
    for (args, message) in cases {
        let (code, out, err) = explain(&args);
        assert_eq!(code, 2, "{args:?}: {out}{err}");
        assert!(err.contains(message), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}
