//! The readers of another renderer's output (`oracle::Theirs::read`: a mask PNG, an ids
//! PNG, render's JSON, a values image: a float32 TIFF or a UNORM PNG) on arbitrary bytes,
//! as they are and behind the PNG and TIFF signatures:
//! `Ok` or `Err` naming the file, never a panic; what they accept is self-consistent
//! (`covered()` lists exactly the pixels `pixel()` calls covered, row-major, and
//! `covered_pixels()` counts them; an ids pixel names exactly one owner; a JSON pixel's
//! owners ascend), and a JSON coverage rebuilt from its pixels is the same `Theirs`.
//!
//! Bounded here, not in the crate: a PNG whose header declares more than 2^16 pixels is
//! skipped (the decoder would allocate for all of them; the crate reads PNGs up to
//! 16384 px a side, `MAX_CANVAS`, and `compare` then refuses a size that is not the
//! scene's). `Debug` is the bytes, which paste into a test as a byte string.

#![no_main]

use libfuzzer_sys::fuzz_target;
use rasterproof::coverage::{Coverage, CoverageSink};
use rasterproof::oracle::theirs::{Background, Format};
use rasterproof::oracle::Theirs;

const PNG_SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];
/// The most pixels a PNG header may declare for the decoder to be run on it.
const MAX_PIXELS: u64 = 1 << 16;

/// Whether `bytes` is a PNG whose IHDR declares at most [`MAX_PIXELS`] (or no IHDR at
/// all: the decoder refuses it before allocating).
fn small_enough(bytes: &[u8]) -> bool {
    let Some(ihdr) = bytes.get(16..24) else {
        return true;
    };
    let side = |b: &[u8]| u64::from(u32::from_be_bytes([b[0], b[1], b[2], b[3]]));
    side(&ihdr[..4]) * side(&ihdr[4..]) <= MAX_PIXELS
}

fn consistent(t: &Theirs) {
    if u64::from(t.width()) * u64::from(t.height()) > MAX_PIXELS {
        // A JSON coverage may declare any canvas up to 16384 x 16384: check its listed
        // pixels only.
        let covered = t.covered();
        assert_eq!(t.covered_pixels(), covered.len());
        assert!(covered.iter().all(|&(x, y)| t.pixel(x, y).covered));
        return;
    }
    let mut listed = Vec::new();
    for y in 0..t.height() {
        for x in 0..t.width() {
            let p = t.pixel(x, y);
            if p.covered {
                listed.push((x, y));
            }
            match t.format() {
                Format::Mask => assert!(p.ids.is_empty() && !p.several),
                Format::Grey => {
                    assert!(p.ids.is_empty() && !p.several);
                    let level = t.grey().expect("read as grey").levels[(y * t.width() + x) as usize];
                    assert_eq!(
                        p.covered,
                        level != 0,
                        "a grey pixel is covered where its level is not 0"
                    );
                }
                Format::Values => {
                    assert!(p.ids.is_empty() && !p.several);
                    let v = t.values().expect("read as values");
                    assert!((1..=4).contains(&v.channels), "{} channels", v.channels);
                }
                Format::Ids => assert_eq!(p.ids.len(), usize::from(p.covered), "an ids pixel names one owner"),
                Format::Json => {
                    assert_eq!(p.covered, !p.ids.is_empty());
                    assert!(p.ids.windows(2).all(|w| w[0] <= w[1]), "owners ascend");
                }
            }
        }
    }
    assert_eq!(t.covered(), listed);
    assert_eq!(t.covered_pixels(), listed.len());
    if t.format() == Format::Json {
        let mut c = Coverage::new(t.width(), t.height());
        for &(x, y) in &listed {
            for id in t.pixel(x, y).ids {
                c.cover(x, y, id);
            }
        }
        assert_eq!(
            Theirs::from_coverage(&c, Format::Json),
            *t,
            "the JSON coverage rebuilt differs"
        );
    }
}

fn read(bytes: &[u8], background: Background) {
    for format in [Format::Mask, Format::Ids, Format::Json, Format::Grey, Format::Values] {
        if format != Format::Json && bytes.starts_with(&PNG_SIGNATURE) && !small_enough(bytes) {
            continue;
        }
        match Theirs::read(bytes, "theirs.bin", format, background) {
            Ok(t) => consistent(&t),
            Err(e) => assert!(e.to_string().starts_with("theirs.bin: "), "{e}"),
        }
    }
}

fuzz_target!(|data: &[u8]| {
    // The last four bytes, when there are at least 12, pick a mask background.
    let background = match data.len() {
        n if n >= 12 => {
            let b = &data[n - 4..];
            Background {
                rgb: [b[0], b[1], b[2]],
                alpha: (b[3] & 1 == 1).then_some(b[3]),
            }
        }
        _ => Background::default(),
    };
    read(data, background);
    if !data.starts_with(&PNG_SIGNATURE) {
        let signed: Vec<u8> = PNG_SIGNATURE.iter().chain(data).copied().collect();
        read(&signed, background);
    }
    if !data.starts_with(b"II*\0") {
        let tiff: Vec<u8> = b"II*\0".iter().chain(data).copied().collect();
        read(&tiff, background);
    }
});
