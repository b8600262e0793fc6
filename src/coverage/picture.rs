//! Pictures of a [`Coverage`] for people: a palette that separates neighbouring ids, one
//! marking for pixels with several owners, integer scaling so pixels are visible, a legend
//! table (id, colour, primitive, pixels) to write beside the PNG, and an ASCII grid for
//! small canvases.
//!
//! The palette is the golden-ratio hue sequence (Ankerl, "How to Generate Random Colors
//! Programmatically", 2009): id `n` gets hue `n / φ` turns, at fixed saturation and value,
//! so consecutive ids are 137.5° apart and no two of the first few dozen ids look alike.
//! The machine interfaces (`render --format json`, an ids PNG) do not depend on it.

use std::collections::BTreeMap;
use std::fmt::{self, Write as _};
use std::path::{Path, PathBuf};

use image::{ImageFormat, Rgb, RgbImage};

use super::Coverage;

/// The colour of a pixel with several owners (white), also of a pixel one primitive
/// covered twice. No primitive gets it: every [`primitive_colour`] has its smallest
/// channel at 70 and its largest at 235, so it is never white, grey or black.
pub const DOUBLE_COVER_COLOUR: [u8; 3] = [255, 255, 255];

/// The colour of an uncovered pixel (black).
pub const BACKGROUND_COLOUR: [u8; 3] = [0, 0, 0];

/// The largest value of a palette channel (value 235/255 ≈ 0.92: bright on black, still
/// clearly apart from the white of [`DOUBLE_COVER_COLOUR`]).
const PALETTE_MAX: u8 = 235;
/// The smallest value of a palette channel (saturation (235 - 70) / 235 ≈ 0.70).
const PALETTE_MIN: u8 = 70;
/// 2^32 / φ = 2654435769.497..., rounded to the odd 2654435769 (Knuth's multiplicative
/// hash constant): `id * GOLDEN mod 2^32` is the fractional part of `id / φ` in units of
/// 2^-32 turns, and, being odd, it sends different ids to different hues.
const GOLDEN: u32 = 0x9E37_79B9;

/// The colour of primitive `id` in the coverage picture: hue `frac(id / φ)` turns (the
/// golden-ratio sequence, computed exactly as `id * 0x9E3779B9 mod 2^32` in units of
/// 2^-32 turns), saturation ≈ 0.70, value ≈ 0.92, in integer HSV: the hue's sextant picks
/// which channel is 235, which is 70 and which ramps between them by
/// `70 + floor(165 * f)` (rising) or `70 + floor(165 * (1 - f))` (falling), `f` the
/// position inside the sextant.
///
/// Consecutive ids are 137.5° of hue apart; id `n` and `n + 8` (which the old 8-colour
/// cycle painted alike) are 20° apart. Never [`DOUBLE_COVER_COLOUR`] nor black.
///
/// ```
/// use rasterproof::coverage::primitive_colour;
/// assert_eq!(primitive_colour(0), [235, 70, 70]); // hue 0: red
/// assert_eq!(primitive_colour(1), [70, 118, 235]); // hue 0.618 turns: blue
/// ```
pub fn primitive_colour(id: u32) -> [u8; 3] {
    const TURN: u64 = 1 << 32;
    let sextants = u64::from(id.wrapping_mul(GOLDEN)) * 6;
    let (sextant, f) = (sextants >> 32, sextants & (TURN - 1));
    let ramp = |f: u64| {
        let step = (u64::from(PALETTE_MAX - PALETTE_MIN) * f) >> 32;
        // f <= 2^32, so step <= 165 and the sum stays <= 235.
        PALETTE_MIN + u8::try_from(step).expect("step <= 165")
    };
    let (max, min, up, down) = (PALETTE_MAX, PALETTE_MIN, ramp(f), ramp(TURN - f));
    match sextant {
        0 => [max, up, min],
        1 => [down, max, min],
        2 => [min, max, up],
        3 => [min, down, max],
        4 => [up, min, max],
        _ => [max, min, down],
    }
}

/// The largest side of a scaled picture: the largest canvas at scale 1. Beyond it a
/// picture costs gigabytes (3 bytes a pixel) and no viewer shows it whole.
pub const MAX_PICTURE_SIDE: u32 = 16384;

/// [`Scale::default_for`] makes the picture at least this wide...
pub const DEFAULT_MIN_WIDTH: u32 = 256;

/// ...unless that would make a side longer than this.
pub const DEFAULT_MAX_SIDE: u32 = 4096;

/// The biggest canvas side [`Coverage::to_ascii`] is meant for: `render --format text`
/// prints the grid up to 64x64 and only the summary beyond.
pub const ASCII_GRID_MAX_SIDE: u32 = 64;

/// How much a picture is enlarged: each canvas pixel becomes a `K` x `K` block.
///
/// # Guarantees
/// - `K >= 1`.
/// - Built by [`Scale::new`] or [`Scale::default_for`] for a canvas, the scaled picture
///   is at most [`MAX_PICTURE_SIDE`] px per side when `K > 1` (scale 1 is the canvas
///   itself and always accepted).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Scale(u32);

/// Why a scale was refused.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ScaleError {
    /// Zero: a pixel must become at least a 1x1 block.
    Zero,
    /// The picture would be longer than [`MAX_PICTURE_SIDE`] px on a side.
    TooLarge {
        /// The scale asked for.
        scale: u32,
        /// Canvas width.
        width: u32,
        /// Canvas height.
        height: u32,
        /// The largest scale this canvas accepts.
        max: u32,
    },
}

impl fmt::Display for ScaleError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ScaleError::Zero => f.write_str("0 is not a scale (each pixel becomes a KxK block, K at least 1)"),
            ScaleError::TooLarge {
                scale,
                width,
                height,
                max,
            } => write!(
                f,
                "{scale} makes the {width}x{height} canvas a {}x{} picture, over {MAX_PICTURE_SIDE} px \
                 per side (at most {max} for this canvas)",
                u64::from(*width) * u64::from(*scale),
                u64::from(*height) * u64::from(*scale),
            ),
        }
    }
}

impl std::error::Error for ScaleError {}

impl Scale {
    /// Scale 1: the picture is the canvas.
    pub const ONE: Scale = Scale(1);

    /// Scale `k` for a `width` x `height` canvas.
    ///
    /// # Errors
    /// `k == 0`, or `k > 1` with a scaled side over [`MAX_PICTURE_SIDE`].
    ///
    /// ```
    /// use rasterproof::coverage::{Scale, ScaleError};
    /// assert_eq!(Scale::new(4, 100, 30).unwrap().get(), 4);
    /// assert_eq!(Scale::new(0, 100, 30), Err(ScaleError::Zero));
    /// assert!(Scale::new(200, 100, 30).is_err()); // 20000 px wide
    /// ```
    pub fn new(k: u32, width: u32, height: u32) -> Result<Scale, ScaleError> {
        let max = Scale::largest(width, height);
        match k {
            0 => Err(ScaleError::Zero),
            1 => Ok(Scale(1)),
            _ if k <= max => Ok(Scale(k)),
            _ => Err(ScaleError::TooLarge {
                scale: k,
                width,
                height,
                max,
            }),
        }
    }

    /// The default: the smallest `K` that makes the picture at least [`DEFAULT_MIN_WIDTH`]
    /// px wide, lowered so that no side exceeds [`DEFAULT_MAX_SIDE`] (never below 1).
    ///
    /// ```
    /// use rasterproof::coverage::Scale;
    /// assert_eq!(Scale::default_for(16, 16).get(), 16); // 256 px
    /// assert_eq!(Scale::default_for(100, 100).get(), 3); // 300 px
    /// assert_eq!(Scale::default_for(512, 512).get(), 1);
    /// assert_eq!(Scale::default_for(10, 1000).get(), 4); // 4000 px tall, not 26 * 1000
    /// ```
    pub fn default_for(width: u32, height: u32) -> Scale {
        let wide_enough = DEFAULT_MIN_WIDTH.div_ceil(width.max(1));
        let fits = DEFAULT_MAX_SIDE / width.max(height).max(1);
        Scale(wide_enough.min(fits).max(1))
    }

    /// The largest scale a `width` x `height` canvas accepts (at least 1).
    fn largest(width: u32, height: u32) -> u32 {
        (MAX_PICTURE_SIDE / width.max(height).max(1)).max(1)
    }

    /// `K`.
    pub fn get(self) -> u32 {
        self.0
    }
}

/// `image` with each pixel repeated into a `K` x `K` block.
///
/// # Panics
/// When a scaled side overflows `u32` (a [`Scale`] made for this image's size never does).
pub fn upscale(image: &RgbImage, scale: Scale) -> RgbImage {
    let k = scale.get();
    if k == 1 {
        return image.clone();
    }
    let side = |n: u32| n.checked_mul(k).expect("scaled side fits u32");
    RgbImage::from_fn(side(image.width()), side(image.height()), |x, y| {
        *image.get_pixel(x / k, y / k)
    })
}

/// Where the legend of the picture `png` goes: beside it, the extension replaced by
/// `legend.txt` (`out.png` -> `out.legend.txt`, `out` -> `out.legend.txt`).
///
/// ```
/// use std::path::Path;
/// use rasterproof::coverage::picture::legend_path;
/// assert_eq!(legend_path(Path::new("pics/out.png")), Path::new("pics/out.legend.txt"));
/// ```
pub fn legend_path(png: &Path) -> PathBuf {
    png.with_extension("legend.txt")
}

/// A run of consecutive ids of one kind of primitive, for the legend: `count`
/// primitives named `name[0]`, `name[1]`, ... (the scene file's field and index, as error
/// messages name them). The runs of a scene follow its id order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IdRun<'a> {
    /// The kind, as the scene file's field: `triangles`, `lines`, ...
    pub name: &'a str,
    /// How many primitives of it.
    pub count: usize,
}

impl Coverage {
    /// The coverage picture at scale 1: [`BACKGROUND_COLOUR`] where uncovered, the
    /// owner's [`primitive_colour`] where one primitive covers the pixel,
    /// [`DOUBLE_COVER_COLOUR`] where several do (or one does twice).
    pub fn to_image(&self) -> RgbImage {
        let mut img = RgbImage::from_pixel(self.width, self.height, Rgb(BACKGROUND_COLOUR));
        for (x, y, ids) in self.iter() {
            let colour = match ids {
                [id] => primitive_colour(*id),
                _ => DOUBLE_COVER_COLOUR,
            };
            img.put_pixel(x, y, Rgb(colour));
        }
        img
    }

    /// [`Coverage::to_image`] with every pixel a `K` x `K` block: canvas pixel `(x, y)` is
    /// picture pixels `[x*K, (x+1)*K) x [y*K, (y+1)*K)`.
    pub fn picture(&self, scale: Scale) -> RgbImage {
        upscale(&self.to_image(), scale)
    }

    /// Writes [`Coverage::to_image`] (scale 1) as a PNG.
    ///
    /// # Errors
    /// The file cannot be written.
    pub fn save_png(&self, path: &Path) -> Result<(), image::ImageError> {
        self.to_image().save_with_format(path, ImageFormat::Png)
    }

    /// The legend of [`Coverage::picture`] as text: `#` comment lines (canvas, scale, the
    /// background and several-owners colours), then one line per id, `id colour primitive
    /// pixels`, columns separated by spaces: every id of `runs` (in order, a primitive
    /// that covers nothing included) and any other id the coverage holds (primitive `?`).
    /// `pixels` counts the pixels the id covers, alone or shared.
    ///
    /// ```
    /// use rasterproof::coverage::{Coverage, CoverageSink, IdRun, Scale};
    /// let mut c = Coverage::new(2, 1);
    /// c.cover(0, 0, 0);
    /// c.cover(1, 0, 0);
    /// c.cover(1, 0, 1);
    /// let runs = [IdRun { name: "triangles", count: 1 }, IdRun { name: "lines", count: 2 }];
    /// let legend = c.legend(&runs, Scale::new(3, 2, 1).unwrap());
    /// let rows: Vec<&str> = legend.lines().filter(|l| !l.starts_with('#')).collect();
    /// assert_eq!(rows, ["0 #eb4646 triangles[0] 2", "1 #4676eb lines[0] 1", "2 #a6eb46 lines[1] 0"]);
    /// ```
    pub fn legend(&self, runs: &[IdRun<'_>], scale: Scale) -> String {
        let mut pixels: BTreeMap<u32, usize> = BTreeMap::new();
        for (_, _, ids) in self.iter() {
            let mut ids = ids.to_vec();
            ids.dedup(); // ascending, so repeats are adjacent
            for id in ids {
                *pixels.entry(id).or_default() += 1;
            }
        }
        let hex = |[r, g, b]: [u8; 3]| format!("#{r:02x}{g:02x}{b:02x}");
        let k = scale.get();
        let mut s = format!(
            "# rasterproof coverage picture: {}x{} canvas at scale {k} (each pixel a {k}x{k} block)\n\
             # uncovered {} (black); several owners {} (white; also one primitive covering a pixel twice)\n\
             # id colour primitive pixels\n",
            self.width,
            self.height,
            hex(BACKGROUND_COLOUR),
            hex(DOUBLE_COVER_COLOUR),
        );
        let mut row = |id: u32, name: &str, pixels: &mut BTreeMap<u32, usize>| {
            let n = pixels.remove(&id).unwrap_or(0);
            let _ = writeln!(s, "{id} {} {name} {n}", hex(primitive_colour(id)));
        };
        let mut next: u64 = 0;
        for run in runs {
            for index in 0..run.count {
                if let Ok(id) = u32::try_from(next) {
                    row(id, &format!("{}[{index}]", run.name), &mut pixels);
                }
                next += 1;
            }
        }
        let unnamed: Vec<u32> = pixels.keys().copied().collect();
        for id in unnamed {
            row(id, "?", &mut pixels);
        }
        s
    }

    /// The coverage as text, one character per pixel, row 0 first, each row ended by a
    /// newline: `.` uncovered, the last decimal digit of the owner's id (`id % 10`) for
    /// one owner, `#` for several (or one primitive twice). Meant for canvases up to
    /// [`ASCII_GRID_MAX_SIDE`] px a side.
    ///
    /// ```
    /// use rasterproof::coverage::{Coverage, CoverageSink};
    /// let mut c = Coverage::new(4, 3);
    /// c.cover(0, 0, 0);
    /// c.cover(1, 0, 0);
    /// c.cover(1, 1, 12);
    /// c.cover(1, 1, 0);
    /// c.cover(3, 2, 12);
    /// assert_eq!(c.to_ascii(), "00..\n.#..\n...2\n");
    /// ```
    pub fn to_ascii(&self) -> String {
        let mut s = String::with_capacity((self.width as usize + 1) * self.height as usize);
        for y in 0..self.height {
            for x in 0..self.width {
                s.push(match self.owners(x, y) {
                    [] => '.',
                    [id] => char::from_digit(id % 10, 10).expect("a digit"),
                    _ => '#',
                });
            }
            s.push('\n');
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coverage::CoverageSink;

    #[test]
    fn picture_marks_double_cover() {
        let mut c = Coverage::new(2, 1);
        c.cover(0, 0, 0);
        c.cover(1, 0, 0);
        c.cover(1, 0, 1);
        let img = c.to_image();
        assert_eq!(img.get_pixel(1, 0).0, DOUBLE_COVER_COLOUR);
        assert_eq!(img.get_pixel(0, 0).0, primitive_colour(0));
    }

    /// By hand: id 2's hue is 2 * 2654435769 - 2^32 = 1013904242 (units of 2^-32 turns);
    /// times 6 it is 1 * 2^32 + 1788458156, sextant 1 (yellow to green: red falls, green
    /// is 235, blue 70), red = 70 + floor(165 * (2^32 - 1788458156) / 2^32)
    /// = 70 + floor(96.29) = 166. Id 1: 6 * 2654435769 = 3 * 2^32 + 3041712726, sextant 3
    /// (cyan to blue: green falls), green = 70 + floor(165 * 1253254570 / 2^32) = 118.
    #[test]
    fn palette_matches_the_hand_derivation() {
        assert_eq!(primitive_colour(0), [235, 70, 70]);
        assert_eq!(primitive_colour(1), [70, 118, 235]);
        assert_eq!(primitive_colour(2), [166, 235, 70]);
    }

    /// The old palette cycled 8 colours (`id % 8`): ids 0 and 8 were alike. Now the first
    /// 64 ids are 64 different colours, and neighbours differ by at least 100 in some
    /// channel.
    #[test]
    fn palette_separates_ids() {
        let colours: Vec<[u8; 3]> = (0..64).map(primitive_colour).collect();
        for (a, ca) in colours.iter().enumerate() {
            for (b, cb) in colours.iter().enumerate().skip(a + 1) {
                assert_ne!(ca, cb, "ids {a} and {b}");
            }
        }
        for id in 0..10_000u32 {
            let (p, q) = (primitive_colour(id), primitive_colour(id + 1));
            let apart = (0..3).map(|ch| p[ch].abs_diff(q[ch])).max().unwrap();
            assert!(apart >= 100, "ids {id} and {}: {p:?} {q:?}", id + 1);
        }
    }

    /// Fixed saturation and value: the smallest channel is 70, the largest 235, so a
    /// primitive is never the white of several owners nor the black background.
    #[test]
    fn palette_never_gives_the_markings() {
        for id in (0..200_000u32).chain([u32::MAX - 1, u32::MAX]) {
            let c = primitive_colour(id);
            assert_eq!(
                (c.iter().min(), c.iter().max()),
                (Some(&70), Some(&235)),
                "id {id}: {c:?}"
            );
        }
    }

    #[test]
    fn scale_is_validated_and_defaults_stay_in_bounds() {
        assert_eq!(Scale::new(0, 4, 4), Err(ScaleError::Zero));
        assert_eq!(Scale::new(4096, 4, 4).map(Scale::get), Ok(4096));
        let too_big = Scale::new(4097, 4, 4).unwrap_err();
        assert_eq!(
            too_big.to_string(),
            "4097 makes the 4x4 canvas a 16388x16388 picture, over 16384 px per side (at most 4096 for this canvas)"
        );
        // The largest canvas accepts scale 1 only; scale 1 is always accepted.
        assert!(Scale::new(2, 16384, 1).is_err());
        assert_eq!(Scale::new(1, 16384, 16384), Ok(Scale::ONE));
        // Defaults: ceil(256 / w), capped at floor(4096 / longest side), at least 1.
        for (w, h, k) in [
            (1, 1, 256),
            (3, 2, 86),
            (16, 16, 16),
            (255, 10, 2),
            (256, 9, 1),
            (1, 4096, 1),
            (1, 16384, 1),
            (16384, 16384, 1),
        ] {
            assert_eq!(Scale::default_for(w, h).get(), k, "{w}x{h}");
            assert!(Scale::new(k, w, h).is_ok());
        }
    }

    #[test]
    fn upscale_repeats_each_pixel_into_a_block() {
        let mut c = Coverage::new(2, 1);
        c.cover(1, 0, 3);
        let img = c.picture(Scale::new(3, 2, 1).unwrap());
        assert_eq!(img.dimensions(), (6, 3));
        for (x, y, px) in img.enumerate_pixels() {
            let want = if x >= 3 { primitive_colour(3) } else { BACKGROUND_COLOUR };
            assert_eq!(px.0, want, "({x}, {y})");
        }
    }

    /// Ids the runs do not name still appear (as `?`), with their pixel counts; a pixel
    /// one id covers twice counts once for it.
    #[test]
    fn legend_lists_every_id() {
        let mut c = Coverage::new(3, 1);
        c.cover(0, 0, 5);
        c.cover(0, 0, 5);
        c.cover(2, 0, 0);
        let legend = c.legend(
            &[IdRun {
                name: "triangles",
                count: 1,
            }],
            Scale::ONE,
        );
        let lines: Vec<&str> = legend.lines().collect();
        assert_eq!(
            lines[0],
            "# rasterproof coverage picture: 3x1 canvas at scale 1 (each pixel a 1x1 block)"
        );
        assert!(
            lines[1].contains("#000000") && lines[1].contains("#ffffff"),
            "{}",
            lines[1]
        );
        assert_eq!(lines[2], "# id colour primitive pixels");
        assert_eq!(lines[3], "0 #eb4646 triangles[0] 1");
        assert_eq!(lines[4], format!("5 #{} ? 1", hex(primitive_colour(5))));
        assert_eq!(lines.len(), 5);
    }

    fn hex(c: [u8; 3]) -> String {
        format!("{:02x}{:02x}{:02x}", c[0], c[1], c[2])
    }
}
