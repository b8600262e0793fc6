//! `rasterproof flood`: the JSON machine interface against the library's oracle, the
//! recoloured image, and bad input (exit code 2, one `error:` line naming the problem, no
//! panic).

use std::path::{Path, PathBuf};
use std::process::Output;

use assert_cmd::Command;
use image::{ImageBuffer, Luma, Rgba, RgbaImage};
use rasterproof::fill::flood::{bfs_region, span_region, Connectivity};

use crate::rng;
use rng::Rng;

use crate::tempdir;

const BLACK: Rgba<u8> = Rgba([0, 0, 0, 255]);
const WHITE: Rgba<u8> = Rgba([255, 255, 255, 255]);
const RED: Rgba<u8> = Rgba([255, 0, 0, 255]);

fn save(dir: &tempdir::Dir, name: &str, img: &RgbaImage) -> PathBuf {
    let p = dir.path().join(name);
    img.save_with_format(&p, image::ImageFormat::Png).unwrap();
    p
}

fn flood(args: &[&str]) -> Output {
    Command::cargo_bin("rasterproof")
        .unwrap()
        .arg("flood")
        .args(args)
        .output()
        .unwrap()
}

fn text(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Exit code 2, nothing on stdout, one `error: ` line on stderr containing every needle.
fn assert_bad_input(args: &[&str], needles: &[&str]) {
    let out = flood(args);
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(
        out.stdout.is_empty(),
        "{args:?}: stdout {:?}",
        String::from_utf8_lossy(&out.stdout)
    );
    assert!(
        err.starts_with("error: ") && err.lines().count() == 1,
        "{args:?}: {err}"
    );
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    eprintln!("{err}");
    for needle in needles {
        assert!(err.contains(needle), "{args:?}: {err:?} does not name {needle:?}");
    }
}

/// Noise in two colours, `p_white` in 1000 of the pixels white.
fn noise(w: u32, h: u32, p_white: i64, seed: u64) -> RgbaImage {
    let mut rng = Rng(seed);
    RgbaImage::from_fn(w, h, |_, _| if rng.below(1000) < p_white { WHITE } else { BLACK })
}

/// `(width, height, at, connectivity, pixels)` from the JSON output.
type FloodJson = (u64, u64, [u64; 2], u64, Vec<(u32, u32)>);

fn parse_json(stdout: &[u8]) -> FloodJson {
    let v: serde_json::Value = serde_json::from_slice(stdout).expect("valid JSON");
    let obj = v.as_object().unwrap();
    let mut keys: Vec<&str> = obj.keys().map(String::as_str).collect();
    keys.sort_unstable();
    assert_eq!(keys, ["at", "connectivity", "height", "pixels", "width"]);
    let n = |v: &serde_json::Value| v.as_u64().unwrap();
    let u = |v: &serde_json::Value| u32::try_from(v.as_u64().unwrap()).unwrap();
    let pixels = v["pixels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            assert_eq!(p.as_array().unwrap().len(), 2);
            (u(&p[0]), u(&p[1]))
        })
        .collect();
    (
        n(&v["width"]),
        n(&v["height"]),
        [n(&v["at"][0]), n(&v["at"][1])],
        n(&v["connectivity"]),
        pixels,
    )
}

/// `--format json` lists exactly the oracle's region, row-major, on noise images either
/// side of the percolation threshold and at the image's corners and edges.
#[test]
fn json_matches_the_oracle() {
    let dir = tempdir::Dir::new("json");
    for (case, (w, h, p)) in [(17u32, 11u32, 650), (9, 23, 450), (30, 30, 700), (1, 12, 500)]
        .into_iter()
        .enumerate()
    {
        let img = noise(w, h, p, 11 + case as u64);
        let path = save(&dir, &format!("n{case}.png"), &img);
        for at in [(0, 0), (w - 1, h - 1), (w / 2, h / 2), (w - 1, 0)] {
            for conn in Connectivity::ALL {
                let args = [
                    text(&path),
                    "--at",
                    &format!("{},{}", at.0, at.1),
                    "--connectivity",
                    &conn.number().to_string(),
                    "--format",
                    "json",
                ];
                let out = flood(&args);
                assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
                let (jw, jh, jat, jconn, pixels) = parse_json(&out.stdout);
                assert_eq!((jw, jh), (u64::from(w), u64::from(h)));
                assert_eq!(jat, [u64::from(at.0), u64::from(at.1)]);
                assert_eq!(jconn, u64::from(conn.number()));
                let oracle: Vec<(u32, u32)> = bfs_region(&img, at, conn).unwrap().iter().collect();
                let mut row_major = oracle.clone();
                row_major.sort_by_key(|&(x, y)| (y, x));
                assert_eq!(oracle, row_major);
                assert_eq!(pixels, oracle, "{args:?}");
                let library: Vec<(u32, u32)> = span_region(&img, at, conn).unwrap().iter().collect();
                assert_eq!(pixels, library, "{args:?}");
            }
        }
    }
}

/// The exact bytes, on a 3x2 image drawn by hand (# white, . black):
///
/// ```text
///   . # .
///   # . .
/// ```
///
/// From (0, 0): four-connected, (0, 0) alone (its right and lower neighbours are #);
/// eight-connected, (0, 0) reaches (1, 1) diagonally, then (2, 1) and (2, 0): 4 pixels.
#[test]
fn json_format_is_exact() {
    let dir = tempdir::Dir::new("format");
    let img = RgbaImage::from_fn(3, 2, |x, y| {
        if (x, y) == (1, 0) || (x, y) == (0, 1) {
            WHITE
        } else {
            BLACK
        }
    });
    let p = save(&dir, "a.png", &img);
    let out = flood(&[text(&p), "--at", "0,0", "--format", "json"]);
    assert!(out.status.success());
    assert_eq!(
        String::from_utf8(out.stdout).unwrap(),
        "{\"width\":3,\"height\":2,\"at\":[0,0],\"connectivity\":4,\"pixels\":[[0,0]]}\n"
    );
    let out = flood(&[text(&p), "--at", "0,0", "--connectivity", "8", "--format", "json"]);
    assert_eq!(
        String::from_utf8(out.stdout).unwrap(),
        "{\"width\":3,\"height\":2,\"at\":[0,0],\"connectivity\":8,\"pixels\":[[0,0],[2,0],[1,1],[2,1]]}\n"
    );
    // The text form: count, connectivity, seed and file on one line.
    let out = flood(&[text(&p), "--at", "2,1", "--connectivity", "8"]);
    let line = String::from_utf8(out.stdout).unwrap();
    assert_eq!(line.lines().count(), 1);
    assert!(
        line.contains("4 pixels") && line.contains("8-connected") && line.contains("(2, 1)") && line.contains("a.png"),
        "{line}"
    );
}

/// `-o` writes the input with exactly the oracle's region in the fill colour (red by
/// default, or `--color`), every other pixel unchanged.
#[test]
fn out_recolours_exactly_the_region() {
    let dir = tempdir::Dir::new("out");
    let img = noise(40, 25, 620, 5);
    let p = save(&dir, "in.png", &img);
    let o = dir.path().join("out.png");
    for (conn, colour_arg, colour) in [
        ("4", None, RED),
        ("8", Some("0,128,255"), Rgba([0, 128, 255, 255])),
        ("4", Some("1,2,3,4"), Rgba([1, 2, 3, 4])),
    ] {
        let mut args = vec![text(&p), "--at", "20,12", "--connectivity", conn, "-o", text(&o)];
        if let Some(c) = colour_arg {
            args.extend(["--color", c]);
        }
        let out = flood(&args);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let connectivity = Connectivity::from_number(conn.parse().unwrap()).unwrap();
        let region = bfs_region(&img, (20, 12), connectivity).unwrap();
        assert!(region.len() > 1, "the test image should give a real region");
        let written = image::open(&o).unwrap().to_rgba8();
        assert_eq!(written.dimensions(), img.dimensions());
        for (x, y, px) in written.enumerate_pixels() {
            let want = if region.contains(x, y) {
                colour
            } else {
                *img.get_pixel(x, y)
            };
            assert_eq!(*px, want, "{args:?} at ({x}, {y})");
        }
    }
    // Filling with the region's own colour writes the image unchanged.
    let white_seed = img
        .enumerate_pixels()
        .find(|p| *p.2 == WHITE)
        .map(|p| (p.0, p.1))
        .unwrap();
    let at = format!("{},{}", white_seed.0, white_seed.1);
    let out = flood(&[text(&p), "--at", &at, "--color", "255,255,255", "-o", text(&o)]);
    assert!(out.status.success());
    assert_eq!(image::open(&o).unwrap().to_rgba8(), img);
}

/// Grey (and 16-bit) PNGs are read as RGBA: the region is the same as for the RGBA image.
#[test]
fn grey_png_is_read_as_rgba() {
    let dir = tempdir::Dir::new("grey");
    let rgba = noise(12, 12, 600, 3);
    let grey: ImageBuffer<Luma<u8>, Vec<u8>> = ImageBuffer::from_fn(12, 12, |x, y| Luma([rgba.get_pixel(x, y).0[0]]));
    let p = dir.path().join("grey.png");
    grey.save_with_format(&p, image::ImageFormat::Png).unwrap();
    let grey16: ImageBuffer<Luma<u16>, Vec<u16>> =
        ImageBuffer::from_fn(12, 12, |x, y| Luma([u16::from(rgba.get_pixel(x, y).0[0]) * 257]));
    let p16 = dir.path().join("grey16.png");
    grey16.save_with_format(&p16, image::ImageFormat::Png).unwrap();
    let oracle: Vec<(u32, u32)> = bfs_region(&rgba, (6, 6), Connectivity::Four).unwrap().iter().collect();
    for path in [&p, &p16] {
        let out = flood(&[text(path), "--at", "6,6", "--format", "json"]);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        assert_eq!(parse_json(&out.stdout).4, oracle);
    }
}

#[test]
fn seed_outside_the_image_names_at_value_and_size() {
    let dir = tempdir::Dir::new("outside");
    let p = save(&dir, "a.png", &RgbaImage::from_pixel(5, 4, BLACK));
    assert_bad_input(&[text(&p), "--at", "5,0"], &["--at", "5,0", "5x4", "a.png"]);
    assert_bad_input(&[text(&p), "--at", "0,4"], &["--at", "0,4", "5x4"]);
    assert_bad_input(
        &[text(&p), "--at", "4294967295,4294967295"],
        &["--at", "4294967295,4294967295", "5x4"],
    );
}

#[test]
fn malformed_options_are_named() {
    let dir = tempdir::Dir::new("opts");
    let p = save(&dir, "a.png", &RgbaImage::from_pixel(5, 4, BLACK));
    let p = text(&p);
    for at in ["3;4", "3", "", "-1,2", "a,b", "1,2,3", "1.5,2", "4294967296,0"] {
        assert_bad_input(&[p, "--at", at], &["--at", &format!("{at:?}"), "X,Y"]);
    }
    for colour in ["256,0,0", "1,2", "red", "1,2,3,4,5", "-1,0,0"] {
        assert_bad_input(
            &[p, "--at", "0,0", "--color", colour],
            &["--color", &format!("{colour:?}")],
        );
    }
    for conn in ["6", "four", "", "0"] {
        assert_bad_input(
            &[p, "--at", "0,0", "--connectivity", conn],
            &["--connectivity", &format!("{conn:?}"), "4 or 8"],
        );
    }
}

#[test]
fn unreadable_files_are_named() {
    let dir = tempdir::Dir::new("files");
    let missing = dir.path().join("missing.png");
    assert_bad_input(&[text(&missing), "--at", "0,0"], &["missing.png", "cannot read"]);
    assert_bad_input(&[text(dir.path()), "--at", "0,0"], &["cannot read"]);

    let not_png = dir.path().join("scene.png");
    std::fs::write(&not_png, "{\"width\": 4, \"height\": 4}").unwrap();
    assert_bad_input(&[text(&not_png), "--at", "0,0"], &["scene.png", "not a PNG"]);
    let empty = dir.path().join("empty.png");
    std::fs::write(&empty, "").unwrap();
    assert_bad_input(&[text(&empty), "--at", "0,0"], &["empty.png", "not a PNG", "empty"]);

    // A valid PNG cut in half, and cut inside its signature.
    let whole = save(&dir, "whole.png", &noise(64, 64, 500, 9));
    let bytes = std::fs::read(&whole).unwrap();
    let half = dir.path().join("half.png");
    std::fs::write(&half, &bytes[..bytes.len() / 2]).unwrap();
    assert_bad_input(&[text(&half), "--at", "0,0"], &["half.png", "truncated PNG"]);
    let stub = dir.path().join("stub.png");
    std::fs::write(&stub, &bytes[..5]).unwrap();
    assert_bad_input(&[text(&stub), "--at", "0,0"], &["stub.png", "truncated PNG"]);

    // A flipped byte inside the compressed data: the chunk checksum fails.
    let mut flipped = bytes.clone();
    let k = bytes.len() / 2;
    flipped[k] ^= 0x55;
    let corrupt = dir.path().join("corrupt.png");
    std::fs::write(&corrupt, &flipped).unwrap();
    assert_bad_input(&[text(&corrupt), "--at", "0,0"], &["corrupt.png", "corrupt PNG"]);
}

/// One pixel over the 16384 limit, either way (a 16385x1 PNG is a few dozen bytes).
#[test]
fn images_over_the_size_limit_are_refused() {
    let dir = tempdir::Dir::new("large");
    for (w, h) in [(16385, 1), (1, 16385)] {
        let p = save(&dir, &format!("{w}x{h}.png"), &RgbaImage::from_pixel(w, h, WHITE));
        assert_bad_input(&[text(&p), "--at", "0,0"], &[&format!("{w}x{h}"), "16384"]);
    }
    // At the limit, it works.
    let p = save(&dir, "edge.png", &RgbaImage::from_pixel(16384, 1, WHITE));
    let out = flood(&[text(&p), "--at", "16383,0"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8(out.stdout).unwrap().contains("16384 pixels"));
}
