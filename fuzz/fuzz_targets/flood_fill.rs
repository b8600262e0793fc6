//! Flood fill against its oracle, and the PNG loader against arbitrary bytes:
//!
//! 1. An arbitrary small image (sides `1 + w % 64`, pixels drawn from a palette of 1 to 3
//!    arbitrary RGBA colours, often differing in one channel only) and seed:
//!    `span_region == bfs_region` for four and eight, the four-connected region lies
//!    inside the eight-connected one, and `flood_fill` recolours exactly the region.
//! 2. The raw input bytes, as they are and behind the 8-byte PNG signature (so the
//!    decoder gets past its first check), into `decode_png_within` with a 64-pixel limit:
//!    `Ok` or `Err`, never a panic; an image it returns goes through the checks of 1.

#![no_main]

use arbitrary::{Arbitrary, Unstructured};
use image::{Rgba, RgbaImage};
use libfuzzer_sys::fuzz_target;
use rasterproof::fill::flood::{bfs_region, decode_png_within, flood_fill, span_region, Connectivity};

/// The largest side decoded here: keeps each run's memory and time small.
const MAX_SIDE: u32 = 64;
const PNG_SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];

#[derive(Debug, Arbitrary)]
struct Input {
    /// Sides, read as `1 + w % 64`.
    width: u8,
    height: u8,
    /// The first colour; the others are it with one channel changed by `tweak`, or
    /// arbitrary when `tweak` is 0.
    base: [u8; 4],
    tweaks: [(u8, u8); 2],
    /// 1 + colours % 3 colours in use.
    colours: u8,
    /// Palette indices, repeated to fill the image.
    pixels: Vec<u8>,
    seed: (u8, u8),
}

impl Input {
    fn image(&self) -> RgbaImage {
        let (w, h) = (
            1 + u32::from(self.width) % MAX_SIDE,
            1 + u32::from(self.height) % MAX_SIDE,
        );
        let mut palette = vec![Rgba(self.base)];
        for &(channel, tweak) in &self.tweaks {
            let mut c = self.base;
            let k = usize::from(channel % 4);
            c[k] = if tweak == 0 { channel } else { c[k].wrapping_add(tweak) };
            palette.push(Rgba(c));
        }
        let n = 1 + usize::from(self.colours % 3);
        RgbaImage::from_fn(w, h, |x, y| {
            let i = (y * w + x) as usize;
            let k = if self.pixels.is_empty() {
                0
            } else {
                self.pixels[i % self.pixels.len()]
            };
            palette[usize::from(k) % n]
        })
    }
}

fn check(img: &RgbaImage, seed: (u32, u32)) {
    let seed = (seed.0 % img.width(), seed.1 % img.height());
    let mut regions = Vec::new();
    for c in Connectivity::ALL {
        let span = span_region(img, seed, c).expect("seed inside");
        let bfs = bfs_region(img, seed, c).expect("seed inside");
        assert_eq!(span, bfs, "span fill differs from the oracle at seed {seed:?}, {c}");
        regions.push(span);
    }
    assert!(
        regions[0].is_subset_of(&regions[1]),
        "four not inside eight at seed {seed:?}"
    );
    let mark = Rgba([img.get_pixel(seed.0, seed.1).0[0].wrapping_add(1), 7, 7, 7]);
    let mut painted = img.clone();
    let n = flood_fill(&mut painted, seed, Connectivity::Eight, mark).expect("seed inside");
    assert_eq!(n, regions[1].len());
    for (x, y, p) in painted.enumerate_pixels() {
        let want = if regions[1].contains(x, y) {
            mark
        } else {
            *img.get_pixel(x, y)
        };
        assert_eq!(*p, want, "flood_fill at ({x}, {y})");
    }
}

fuzz_target!(|data: &[u8]| {
    if let Ok(img) = decode_png_within(data, "<fuzz>", MAX_SIDE) {
        check(&img, (0, 0));
    }
    let signed: Vec<u8> = PNG_SIGNATURE.iter().chain(data).copied().collect();
    if let Ok(img) = decode_png_within(&signed, "<fuzz>", MAX_SIDE) {
        check(&img, (img.width() / 2, img.height() / 2));
    }
    if let Ok(input) = Input::arbitrary(&mut Unstructured::new(data)) {
        check(&input.image(), (u32::from(input.seed.0), u32::from(input.seed.1)));
    }
});
