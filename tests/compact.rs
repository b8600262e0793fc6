//! The compact exact form against the big-rational one: `Compact::parse` reads every text
//! as `parse_rational` does (value or error), snaps as `snap` does, a compact triangle
//! reaches the integer models' form as the big one does (at the envelope's edge too), and
//! the fast scene reader gives what the slow one gives, scene or error, on scene texts
//! near and off its path.

use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;
use rasterproof::convention::{Convention, Preset};
use rasterproof::coverage::Coverage;
use rasterproof::geom::{CompactTriangle, Point, Triangle};
use rasterproof::num::compact::Compact;
use rasterproof::num::fixed::{snap, MAX_SUBPIXEL_MAGNITUDE};
use rasterproof::num::{parse_rational, Rounding};
use rasterproof::scene::parse::parse_scene_slow;
use rasterproof::scene::{parse_scene, parse_scene_with, ParseOptions};
use rasterproof::tri::planned::PlannedTriangle;

use crate::common::config;

const ROUNDINGS: [Rounding; 5] = [
    Rounding::NearestEven,
    Rounding::HalfAwayFromZero,
    Rounding::Floor,
    Rounding::Ceiling,
    Rounding::TowardsZero,
];

/// Number-like texts: decimals and fractions of every length around the 18-digit edge of
/// the small form, exponents around its limits, and near-misses of the grammar.
fn number_text() -> impl Strategy<Value = String> {
    prop_oneof![
        "[+-]?[0-9]{0,21}(\\.[0-9]{0,21})?([eE][+-]?[0-9]{1,5})?",
        "[+-]?[0-9]{1,20}/[+-]?[0-9]{1,20}",
        "[-+0-9./eE ]{0,12}",
        Just("9223372036854775807".to_string()),
        Just("-9223372036854775808".to_string()),
        Just("922337203685477580.7e1".to_string()),
    ]
}

/// A value near the edges of i64 and of the 2^29-subpixel envelope, as a fraction.
fn edge_value() -> impl Strategy<Value = BigRational> {
    let big = prop_oneof![
        Just(i64::MAX),
        Just(i64::MIN + 1),
        Just(MAX_SUBPIXEL_MAGNITUDE),
        -1_000_000_000i64..1_000_000_000,
        any::<i64>(),
    ];
    (
        big,
        prop_oneof![Just(1i64), Just(2), Just(3), Just(256), Just(65536), 1i64..1_000_000],
    )
        .prop_map(|(n, d)| BigRational::new(n.into(), d.into()))
}

proptest! {
    #![proptest_config(config("proptest-regressions/compact.txt"))]

    /// The compact reading of any text is parse_rational's, value or error, and one form
    /// per value.
    #[test]
    fn compact_reads_what_parse_rational_reads(text in number_text()) {
        let compact = Compact::parse(&text);
        prop_assert_eq!(compact.clone().map(|c| c.to_big()), parse_rational(&text));
        if let Ok(c) = compact {
            prop_assert_eq!(Compact::from_big(c.to_big()), c);
        }
    }

    /// Snapping a compact value is snapping its big rational, in every rounding and at
    /// every grid a convention may ask for, and beyond.
    #[test]
    fn compact_snaps_as_snap_does(x in edge_value(), bits in 0u32..=20, r in 0usize..5) {
        let c = Compact::from_big(x.clone());
        prop_assert_eq!(c.snap(bits, ROUNDINGS[r]), snap(&x, bits, ROUNDINGS[r]));
    }

    /// A compact triangle reaches the integer models' form, or the envelope error, as its
    /// big-rational triangle does: values at and beyond 2^29 subpixels included.
    #[test]
    fn compact_triangles_snap_to_the_same_fixed_triangle(
        coords in prop::array::uniform6(edge_value()),
        bits in 1u32..=16,
        r in 0usize..5,
    ) {
        let p = |k: usize| Point::new(coords[2 * k].clone(), coords[2 * k + 1].clone());
        let t = Triangle::new(p(0), p(1), p(2));
        let conv = Convention { subpixel_bits: bits, rounding: ROUNDINGS[r], ..Preset::D3d11.convention() };
        let c = CompactTriangle::from(&t);
        prop_assert_eq!(c.to_triangle(), t.clone());
        prop_assert_eq!(c.to_fixed(&conv), t.snapped(&conv).to_fixed());
        prop_assert_eq!(c.snapped(&conv), t.snapped(&conv));
    }

    /// The planned engine set up from a compact triangle (in i128 when its coordinates are
    /// small and nothing overflows) has the plan of the big-integer setup (scale, bound and
    /// its words, width) and draws the same pixels: decimals, fractions of any denominator,
    /// dyadic values, coordinates near 2^62 and beyond, both pixel centres.
    #[test]
    fn planned_setup_from_compact_equals_the_big_setup(
        coords in prop::array::uniform6(planned_value()),
        corner in any::<bool>(),
        rule in prop::sample::select(vec![rasterproof::convention::TieRule::TopLeft, rasterproof::convention::TieRule::BottomLeft]),
    ) {
        let p = |k: usize| Point::new(coords[2 * k].clone(), coords[2 * k + 1].clone());
        let t = Triangle::new(p(0), p(1), p(2));
        let mut conv = Preset::D3d11.convention();
        conv.tie_rule = rule;
        if corner {
            conv.pixel_centre = rasterproof::convention::PixelCentre::Corner;
        }
        let target = rasterproof::convention::Target::new(24, 20, conv).unwrap();
        let compact = PlannedTriangle::from_compact(&CompactTriangle::from(&t), &target);
        let big = PlannedTriangle::new(&t, &target);
        prop_assert_eq!(compact.as_ref().map(|p| p.plan().clone()), big.as_ref().map(|p| p.plan().clone()));
        let (mut a, mut b) = (Coverage::new(24, 20), Coverage::new(24, 20));
        if let (Some(c), Some(g)) = (compact, big) {
            c.rasterize(0, &mut a);
            g.rasterize(0, &mut b);
        }
        prop_assert_eq!(a, b);
    }

    /// The fast reader gives the slow reader's scene or error on scene texts built from
    /// pieces on and off its path: numbers of any form, strings, escapes, colours,
    /// unknown and repeated keys, wrong shapes, other fields around the triangles.
    #[test]
    fn fast_and_slow_readers_agree(
        triangles in prop::collection::vec(triangle_text(), 0..5),
        sep in prop::sample::select(vec![", ", ",", ",\n  ", " ,\t", " "]),
        before in prop::sample::select(vec!["", "\"extra\": {\"triangles\": [{\"v\": 1}, {\"v\": 2}]},", "\"preset\": \"vulkan\",", "\"lines\": [{\"from\": [0, 0], \"to\": [3, 2]}],", "\"clip\": {\"rect\": [0, 0, 4, 4]},", "\"width\": 3,"]),
        after in prop::sample::select(vec!["", ", \"subpixel_bits\": 4", ", \"polygons\": [{\"v\": [[0,0],[4,0],[0,4]]}]", ", \"triangles\": []", ", \"clip\": {\"rect\": [0, 0, 4, 4], \"rect\": [0, 0, 2, 2]}", ", \"samples\": 4", ", \"bogus\": 1", "]"]),
    ) {
        let text = format!(
            "{{{before} \"width\": 8, \"height\": 8, \"triangles\": [{}]{after}}}",
            triangles.join(sep)
        );
        let fast = parse_scene(&text, "s.json").map_err(|e| e.to_string());
        let slow = parse_scene_slow(&text, "s.json").map_err(|e| e.to_string());
        prop_assert_eq!(&fast, &slow, "{}", text);
        // On several threads (the triangles cut into runs, each read on its own): the same
        // scene or error, and the same primitives copied on several threads.
        for jobs in [2, 3] {
            let parallel = parse_scene_with(text.as_bytes(), "s.json", &ParseOptions::with_jobs(jobs)).map_err(|e| e.to_string());
            prop_assert_eq!(&parallel, &slow, "{} jobs: {}", jobs, text);
        }
        if let Ok(scene) = &fast {
            prop_assert_eq!(scene.primitives_parallel(2), scene.primitives());
        }
    }
}

/// A coordinate for the planned setup: mostly on or near the 24 x 20 canvas with small
/// denominators, sometimes huge numerators or denominators (up to and beyond the i128
/// setup's limits), so that both setups and the fallback between them are exercised.
fn planned_value() -> impl Strategy<Value = BigRational> {
    let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
    prop_oneof![
        6 => (-40i64..400, prop::sample::select(vec![1i64, 2, 3, 4, 10, 256, 1000, 7])).prop_map(move |(n, d)| q(n * d / 10, d)),
        2 => (-30_000i64..300_000, 1i64..100_000).prop_map(move |(n, d)| q(n, d)),
        1 => (any::<i64>(), 1i64..=i64::MAX).prop_map(move |(n, d)| q(n, d)),
        1 => (-4i64..30, 40u32..63).prop_map(move |(n, k)| q(n << k.min(20), 1i64 << k.min(62)) + q(1, 1i64 << k)),
        1 => (any::<i64>()).prop_map(move |n| q(n, 1)),
    ]
}

/// One triangle object's text: mostly well-formed, sometimes not.
fn triangle_text() -> impl Strategy<Value = String> {
    let coordinate = prop_oneof![
        4 => (-20i64..20, 0u32..4).prop_map(|(n, k)| format!("{}", n as f64 / 10f64.powi(k as i32))),
        2 => (-20i64..20, 1i64..9).prop_map(|(n, d)| format!("\"{n}/{d}\"")),
        1 => number_text(),
        1 => number_text().prop_map(|t| format!("\"{t}\"")),
        1 => prop::sample::select(vec!["\"1\\u002f3\"", "\"\"", "true", "null", "[1]", "{}", "1e400", "\"0x1\"", "-0", "1E+2", "\"+.5\""]).prop_map(str::to_string),
    ];
    let point = prop_oneof![
        8 => (coordinate.clone(), coordinate.clone()).prop_map(|(x, y)| format!("[{x}, {y}]")),
        1 => coordinate.clone().prop_map(|x| format!("[{x}]")),
        1 => (coordinate.clone(), coordinate.clone(), coordinate).prop_map(|(x, y, z)| format!("[{x}, {y}, {z}]")),
    ];
    let vertices = prop_oneof![
        8 => prop::array::uniform3(point.clone()).prop_map(|[a, b, c]| format!("[{a}, {b}, {c}]")),
        1 => prop::collection::vec(point, 0..5).prop_map(|ps| format!("[{}]", ps.join(", "))),
    ];
    let colours = prop_oneof![
        "[0-9]{1,3}".prop_map(|c| format!(", \"colors\": [[{c}, 0, 0], [0, 255, 0], [0, 0, 255]]")),
        Just(", \"colors\": [[1, 2], [0, 255, 0], [0, 0, 255]]".to_string()),
        Just(", \"colors\": [[1.0, 2, 3], [0, 255, 0], [0, 0, 255]]".to_string()),
    ];
    let extra = prop::sample::select(vec!["", "", "", "", ", \"w\": 1", ", \"v\": [[0,0],[1,0],[0,1]]"]);
    (vertices, prop::option::of(colours), extra, any::<bool>()).prop_map(|(v, c, extra, colours_first)| {
        let c = c.unwrap_or_default();
        if colours_first && !c.is_empty() {
            format!("{{{}, \"v\": {v}{extra}}}", &c[2..])
        } else {
            format!("{{\"v\": {v}{c}{extra}}}")
        }
    })
}

/// Hand-checked readings on and off the fast path (the values derived in the comments).
#[test]
fn the_fast_reader_reads_decimals_fractions_and_strings_exactly() {
    let s = parse_scene(
        r#"{"width": 8, "height": 8, "triangles": [{"v": [[0.125, "1/3"], [-2.50, 1e2], ["7.5e-1", 491.407]]}]}"#,
        "s.json",
    )
    .unwrap();
    let t = s.triangles[0].triangle.to_triangle();
    let q = |n: i64, d: i64| BigRational::new(BigInt::from(n), BigInt::from(d));
    // 0.125 = 1/8; "1/3"; -2.50 = -5/2; 1e2 = 100; "7.5e-1" = 3/4; 491.407 = 491407/1000.
    assert_eq!(t.v[0], Point::new(q(1, 8), q(1, 3)));
    assert_eq!(t.v[1], Point::new(q(-5, 2), q(100, 1)));
    assert_eq!(t.v[2], Point::new(q(3, 4), q(491_407, 1000)));
    assert_eq!(s.triangles[0].triangle.v[2][1].small(), Some((491_407, 1000)));
    // 1e30 is not small: held as a big rational, the same number.
    let s = parse_scene(
        r#"{"width": 8, "height": 8, "triangles": [{"v": [[1e30, 0], [1, 0], [0, 1]]}]}"#,
        "s.json",
    )
    .unwrap();
    let x = &s.triangles[0].triangle.v[0][0];
    assert_eq!(x.small(), None);
    assert_eq!(x.to_big(), BigRational::from_integer(BigInt::from(10).pow(30)));
}

/// A triangle costs 96 bytes of compact coordinates (six of 16 bytes), not kilobytes.
#[test]
fn a_compact_triangle_is_96_bytes() {
    assert_eq!(std::mem::size_of::<Compact>(), 16);
    assert_eq!(std::mem::size_of::<CompactTriangle>(), 96);
}

/// A file bigger than the slow path takes, which the fast path declines, is refused with
/// the line and column where the fast path stopped (the slow path's tree would cost some
/// ten times the text); one it reads is read however big.
#[test]
fn a_huge_file_the_fast_reader_declines_is_refused_with_the_position() {
    use rasterproof::scene::parse::MAX_SLOW_BYTES;
    let pad = "x".repeat(MAX_SLOW_BYTES);
    // An unknown field in the first triangle, at line 2: the fast path declines there.
    let text = format!(
        "{{\"width\": 8, \"height\": 8,\n\"triangles\": [{{\"v\": [[0,0],[1,0],[0,1]], \"w\": 1}}], \"pad\": \"{pad}\"}}"
    );
    let e = parse_scene(&text, "big.json").unwrap_err().to_string();
    assert!(
        e.starts_with(&format!(
            "big.json: {} bytes: the fast reader stopped at line 2, column ",
            text.len()
        )),
        "{e}"
    );
    assert!(e.contains(&format!("(at most {MAX_SLOW_BYTES} bytes)")), "{e}");
    assert!(!e.contains("  "), "one space between words: {e}");
    // Without the unknown field the same file is read (the pad is an unknown top-level
    // field: the schema's own error, without the slow path).
    let text = text.replace(", \"w\": 1", "");
    let e = parse_scene(&text, "big.json").unwrap_err().to_string();
    assert!(
        e.starts_with("big.json: pad: unknown field (expected one of: width, height,"),
        "{e}"
    );
}

/// A scene file over 1 GiB is refused before it is read (a sparse file: no disk used).
#[test]
fn a_scene_file_over_a_gibibyte_is_refused_unread() {
    let dir = crate::tempdir::Dir::new("huge-scene");
    let path = dir.path().join("huge.json");
    let f = std::fs::File::create(&path).unwrap();
    f.set_len((1 << 30) + 1).unwrap();
    let out = assert_cmd::Command::cargo_bin("rasterproof")
        .unwrap()
        .args(["render", path.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(
        err.trim_end(),
        format!(
            "error: {}: 1073741825 bytes, at most 1073741824 (1 GiB) per scene file",
            path.display()
        )
    );
}
