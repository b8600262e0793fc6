//! Exact values at covered samples: for each covered sample, which primitive it shows and
//! what each of the scene's varyings holds there ([`exact_values`]).
//!
//! Coverage decides which samples hold a value (any model's, per sample of a pattern);
//! the value is the readable definition of [`crate::interp::values`], evaluated at the
//! scene's exact vertices. A sample covered by several primitives shows the last drawn
//! (the highest id), as a renderer without a depth test writes it. Where a varying is
//! evaluated:
//!
//! - `centre`: the pixel's sample point under the convention (its centre, or its corner
//!   with `pixel_centre: 0`), covered or not: the plane is extrapolated there;
//! - `centroid`: Direct3D's rule, exact: the centre when the primitive covers every
//!   sample of the pixel, otherwise its first covered sample in index order (with one
//!   sample per pixel, the sample). Vulkan allows any point of the pixel inside the
//!   primitive, a range this module does not give yet;
//! - `sample`: each covered sample's own position.
//!
//! `centre` and `centroid` give every covered sample of a pixel the same value (the
//! fragment's); `sample` gives each its own.

use std::fmt::Write as _;

use image::{DynamicImage, ImageBuffer};
use num_rational::BigRational;
use num_traits::Signed;

use crate::convention::Target;
use crate::coverage::samples::SampleCoverage;
use crate::coverage::Coverage;
use crate::geom::Point;
use crate::interp::values::{NoValue, Sampling, ValueSetup, Varyings};
use crate::num::exact::{exact_text, nearest_f32};
use crate::num::unorm::{unorm_levels, UnormRule};
use crate::pattern::SamplePattern;
use crate::raster::sample_exact;

/// One covered sample's values.
#[derive(Debug, Clone, PartialEq)]
pub struct SampleValues {
    /// The pixel's column.
    pub x: u32,
    /// The pixel's row.
    pub y: u32,
    /// The sample's index in the pattern (0 with one sample per pixel).
    pub sample: usize,
    /// The primitive shown: the highest id of the sample's owners.
    pub id: u32,
    /// Per varying, in declaration order: its channels, or why there is no value.
    pub values: Vec<Result<Vec<BigRational>, NoValue>>,
}

/// The exact values of every covered sample of `coverage` (one [`crate::coverage::Coverage`]
/// per sample of `pattern`), sorted by row, column and sample. `setups[id]` is primitive
/// `id`'s interpolation setup, `None` for a primitive that carries no values (a polygon):
/// its samples get [`NoValue::NotCarried`].
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::coverage::samples::SampleCoverage;
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::interp::values::{Interpolation, Sampling, ValueSetup, ValueTriangle, Varying, Varyings};
/// use rasterproof::model::{exact_values, render_triangles, Model};
/// use rasterproof::pattern::SamplePattern;
/// let q = |n: i64, d: i64| num_rational::BigRational::new(n.into(), d.into());
/// let (a, b, c) = (Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
/// let target = Target::new(4, 4, Convention::default()).unwrap();
/// let coverage = render_triangles(&[Triangle::new(a.clone(), b.clone(), c.clone())], &target, Model::Exact).unwrap();
/// // One channel, 0 at (0, 0), 4 at (4, 0), 0 at (0, 4): the value is x.
/// let one = q(1, 1);
/// let setup = ValueSetup::Triangle(Box::new(ValueTriangle::window(
///     [&a, &b, &c],
///     [&one, &one, &one],
///     [vec![q(0, 1)], vec![q(4, 1)], vec![q(0, 1)]],
/// )));
/// let varyings = Varyings {
///     list: vec![Varying { name: "x".into(), channels: 1, interpolation: Interpolation::Smooth, sampling: Sampling::Centre }],
///     ..Varyings::default()
/// };
/// let pattern = SamplePattern::single(&target.convention);
/// let all = exact_values(&SampleCoverage::from_samples(vec![coverage]), &pattern, &[Some(setup)], &varyings, &target);
/// // Pixel (1, 1)'s centre is (3/2, 3/2), inside (x + y = 3 < 4): the value is 3/2.
/// let v = all.iter().find(|v| (v.x, v.y) == (1, 1)).unwrap();
/// assert_eq!(v.values, [Ok(vec![q(3, 2)])]);
/// ```
pub fn exact_values(
    coverage: &SampleCoverage,
    pattern: &SamplePattern,
    setups: &[Option<ValueSetup>],
    varyings: &Varyings,
    target: &Target,
) -> Vec<SampleValues> {
    let count = coverage.sample_count();
    let mut out = Vec::new();
    for (x, y) in coverage.covered_pixels() {
        let centre = sample_exact(x, y, target);
        for s in 0..count {
            let Some(&id) = coverage.owners(x, y, s).last() else {
                continue;
            };
            let values = match setups.get(id as usize).and_then(Option::as_ref) {
                None => vec![Err(NoValue::NotCarried); varyings.list.len()],
                Some(setup) => {
                    // The sample's own point and its pixel's centroid, found once for
                    // every varying that asks.
                    let sample = pattern.sample(x, y, s);
                    let centroid = centroid(coverage, pattern, x, y, id, &centre);
                    varyings
                        .ranges()
                        .map(|(varying, channels)| {
                            let at = match varying.sampling {
                                Sampling::Centre => &centre,
                                Sampling::Sample => &sample,
                                Sampling::Centroid => &centroid,
                            };
                            setup.value(varying.interpolation, varyings.provoking, channels, at)
                        })
                        .collect()
                }
            };
            out.push(SampleValues {
                x,
                y,
                sample: s,
                id,
                values,
            });
        }
    }
    out
}

/// [`exact_values`] with one sample per pixel, the convention's: every covered pixel of
/// `coverage` with its values.
pub fn exact_pixel_values(
    coverage: &Coverage,
    setups: &[Option<ValueSetup>],
    varyings: &Varyings,
    target: &Target,
) -> Vec<SampleValues> {
    let one = SampleCoverage::from_samples(vec![coverage.clone()]);
    exact_values(
        &one,
        &SamplePattern::single(&target.convention),
        setups,
        varyings,
        target,
    )
}

/// Why [`values_image`] cannot draw a varying.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ValuesImageError {
    /// A PNG pixel holds 1 to 4 channels.
    TooManyChannels {
        /// The varying's name.
        name: String,
        /// Its channel count.
        channels: usize,
    },
    /// UNORM PNGs are 8 or 16 bits a channel.
    Bits(u32),
    /// A stacked image taller than a TIFF's 2^32 - 1 rows.
    TooTall {
        /// The rows it would need.
        rows: usize,
    },
}

impl std::fmt::Display for ValuesImageError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ValuesImageError::TooManyChannels { name, channels } => write!(
                f,
                "the varying {name:?} has {channels} channels, and a PNG pixel holds 1 to 4 (grey, grey and alpha, RGB, RGBA)"
            ),
            ValuesImageError::Bits(b) => write!(f, "{b} bits a channel: a UNORM PNG has 8 or 16"),
            ValuesImageError::TooTall { rows } => {
                write!(f, "{rows} rows of stacked samples: an image has at most 4294967295")
            }
        }
    }
}

/// Varying `k`'s values at sample 0 of each pixel as a UNORM PNG image of `bits` (8 or
/// 16) a channel: each level the one nearest the exact value scaled by `2^bits - 1`
/// (ties to even, clamped to `[0, 1]`: [`UnormRule::Nearest`]). One channel is a grey
/// image, two grey and alpha, three RGB, four RGBA; a pixel without a covered sample 0 or
/// without a value is 0 in every channel.
///
/// ```
/// use rasterproof::interp::values::{Interpolation, Sampling, Varying, Varyings};
/// use rasterproof::model::{values_image, SampleValues};
/// let q = |n: i64, d: i64| num_rational::BigRational::new(n.into(), d.into());
/// let varyings = Varyings {
///     list: vec![Varying { name: "c".into(), channels: 1, interpolation: Interpolation::Flat, sampling: Sampling::Centre }],
///     ..Varyings::default()
/// };
/// let half = SampleValues { x: 1, y: 0, sample: 0, id: 0, values: vec![Ok(vec![q(1, 2)])] };
/// let image = values_image(&[half], &varyings, 0, 2, 1, 8).unwrap();
/// // 1/2 of 255 is 127.5: the even level, 128.
/// assert_eq!(image.to_luma8().into_raw(), [0, 128]);
/// ```
///
/// # Errors
/// More than four channels, or `bits` other than 8 or 16.
///
/// # Panics
/// When `k` is not a varying of `varyings`.
pub fn values_image(
    values: &[SampleValues],
    varyings: &Varyings,
    k: usize,
    width: u32,
    height: u32,
    bits: u32,
) -> Result<DynamicImage, ValuesImageError> {
    let channels = pixel_channels(varyings, k)?;
    if bits != 8 && bits != 16 {
        return Err(ValuesImageError::Bits(bits));
    }
    let mut levels = vec![0u16; width as usize * height as usize * channels];
    for v in values.iter().filter(|v| v.sample == 0) {
        if let Ok(value) = &v.values[k] {
            let at = (v.y as usize * width as usize + v.x as usize) * channels;
            for (c, channel) in value.iter().enumerate() {
                let level = *unorm_levels(channel, bits, UnormRule::Nearest).start();
                levels[at + c] = u16::try_from(level).expect("at most 16 bits");
            }
        }
    }
    let narrow = |raw: Vec<u16>| -> Vec<u8> { raw.into_iter().map(|l| u8::try_from(l).expect("8 bits")).collect() };
    let size = "the image's size";
    Ok(match (channels, bits) {
        (1, 8) => DynamicImage::ImageLuma8(ImageBuffer::from_raw(width, height, narrow(levels)).expect(size)),
        (2, 8) => DynamicImage::ImageLumaA8(ImageBuffer::from_raw(width, height, narrow(levels)).expect(size)),
        (3, 8) => DynamicImage::ImageRgb8(ImageBuffer::from_raw(width, height, narrow(levels)).expect(size)),
        (4, 8) => DynamicImage::ImageRgba8(ImageBuffer::from_raw(width, height, narrow(levels)).expect(size)),
        (1, _) => DynamicImage::ImageLuma16(ImageBuffer::from_raw(width, height, levels).expect(size)),
        (2, _) => DynamicImage::ImageLumaA16(ImageBuffer::from_raw(width, height, levels).expect(size)),
        (3, _) => DynamicImage::ImageRgb16(ImageBuffer::from_raw(width, height, levels).expect(size)),
        _ => DynamicImage::ImageRgba16(ImageBuffer::from_raw(width, height, levels).expect(size)),
    })
}

/// Varying `k`'s values as a float32 TIFF: each channel the exact value rounded once to
/// the nearest f32 (ties to even). With `samples` 1, sample 0 of each pixel on the
/// `width` x `height` canvas; with more, one such image per sample index stacked (width
/// W, height `samples` x H, sample s in rows `s H` to `(s + 1) H - 1`), as a multisampled
/// target read back sample by sample. One channel is a grey image, two or three RGB (a
/// two-channel varying's blue is 0), four RGBA; uncompressed, IEEE floating-point samples
/// (TIFF 6.0's `SampleFormat` 3), which tifffile, libtiff, ImageMagick and GIMP read bit
/// for bit. A sample not covered or without a value is 0 in every channel; a value beyond
/// f32's range is an infinity of its sign.
///
/// ```
/// use rasterproof::interp::values::{Interpolation, Sampling, Varying, Varyings};
/// use rasterproof::model::{values_tiff, SampleValues};
/// let q = |n: i64, d: i64| num_rational::BigRational::new(n.into(), d.into());
/// let varyings = Varyings {
///     list: vec![Varying { name: "c".into(), channels: 1, interpolation: Interpolation::Flat, sampling: Sampling::Centre }],
///     ..Varyings::default()
/// };
/// let third = SampleValues { x: 1, y: 0, sample: 0, id: 0, values: vec![Ok(vec![q(1, 3)])] };
/// let tiff = values_tiff(&[third], &varyings, 0, 2, 1, 1).unwrap();
/// assert_eq!(&tiff[..4], b"II*\0");
/// ```
///
/// # Errors
/// More than four channels.
///
/// # Panics
/// When `k` is not a varying of `varyings`.
pub fn values_tiff(
    values: &[SampleValues],
    varyings: &Varyings,
    k: usize,
    width: u32,
    height: u32,
    samples: usize,
) -> Result<Vec<u8>, ValuesImageError> {
    use tiff::encoder::{colortype, TiffEncoder};
    let channels = pixel_channels(varyings, k)?;
    let stride = if channels == 2 { 3 } else { channels };
    let count = samples;
    let rows = height as usize * count;
    let stacked = u32::try_from(rows).map_err(|_| ValuesImageError::TooTall { rows })?;
    let (canvas_height, height) = (height, stacked);
    let mut samples = vec![0f32; width as usize * rows * stride];
    for v in values.iter().filter(|v| v.sample < count) {
        if let Ok(value) = &v.values[k] {
            let row = v.sample * canvas_height as usize + v.y as usize;
            let at = (row * width as usize + v.x as usize) * stride;
            for (c, channel) in value.iter().enumerate() {
                samples[at + c] = nearest_f32(channel).unwrap_or(if channel.is_negative() {
                    f32::NEG_INFINITY
                } else {
                    f32::INFINITY
                });
            }
        }
    }
    let mut out = std::io::Cursor::new(Vec::new());
    let mut encoder = TiffEncoder::new(&mut out).expect("writing to memory");
    let written = match stride {
        1 => encoder.write_image::<colortype::Gray32Float>(width, height, &samples),
        3 => encoder.write_image::<colortype::RGB32Float>(width, height, &samples),
        _ => encoder.write_image::<colortype::RGBA32Float>(width, height, &samples),
    };
    written.expect("a TIFF of the image's own size, in memory");
    Ok(out.into_inner())
}

/// Varying `k`'s channel count, when an image pixel holds it (1 to 4).
fn pixel_channels(varyings: &Varyings, k: usize) -> Result<usize, ValuesImageError> {
    let varying = &varyings.list[k];
    if varying.channels > 4 {
        return Err(ValuesImageError::TooManyChannels {
            name: varying.name.clone(),
            channels: varying.channels,
        });
    }
    Ok(varying.channels)
}

/// Direct3D's centroid of primitive `id` in pixel `(x, y)` of `coverage` (one coverage
/// per sample of `pattern`): `centre` when it covers every sample, otherwise its first
/// covered sample (the Direct3D 11.3 functional specification's centroid sampling).
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::coverage::samples::SampleCoverage;
/// use rasterproof::geom::Point;
/// use rasterproof::model::centroid;
/// use rasterproof::pattern::SamplePattern;
/// let four = SamplePattern::standard(4).unwrap();
/// let mut coverage = SampleCoverage::new(1, 1, 4);
/// coverage.cover(0, 0, 2, 0);
/// let centre = Point::new(num_rational::BigRational::new(1.into(), 2.into()), num_rational::BigRational::new(1.into(), 2.into()));
/// // Sample 2 of the standard 4x pattern sits at (1/8, 5/8) of the pixel.
/// assert_eq!(centroid(&coverage, &four, 0, 0, 0, &centre), four.sample(0, 0, 2));
/// coverage.cover(0, 0, 0, 0);
/// coverage.cover(0, 0, 1, 0);
/// coverage.cover(0, 0, 3, 0);
/// assert_eq!(centroid(&coverage, &four, 0, 0, 0, &centre), centre);
/// ```
pub fn centroid(coverage: &SampleCoverage, pattern: &SamplePattern, x: u32, y: u32, id: u32, centre: &Point) -> Point {
    let count = coverage.sample_count();
    let mask = coverage.mask_of(x, y, id);
    let all = if count >= 64 { u64::MAX } else { (1u64 << count) - 1 };
    if mask & all == all {
        return centre.clone();
    }
    let first = mask.trailing_zeros() as usize;
    pattern.sample(x, y, first)
}

/// `coverage_json` (a `render --format json` object) with the field `"values"` added:
/// `{"varyings":[{"name","channels","interpolation","sampling"}...],"provoking_vertex",
/// "samples":[[x,y,sample,id,[value per varying]]...]}`, where a value is its channels as
/// exact strings (`["1/3","2"]`) or, when there is none, the reason: `"not-carried"` (a
/// polygon), `"horizon"` (a smooth value where 1/w = 0) or `"degenerate"`.
///
/// ```
/// use rasterproof::interp::values::Varyings;
/// use rasterproof::model::values_json;
/// assert_eq!(
///     values_json(r#"{"width":1,"height":1,"pixels":[]}"#.to_string(), &Varyings::default(), &[]),
///     r#"{"width":1,"height":1,"pixels":[],"values":{"varyings":[],"provoking_vertex":"first","samples":[]}}"#
/// );
/// ```
///
/// # Panics
/// When `coverage_json` does not end with `}` (it is not a JSON object).
pub fn values_json(mut coverage_json: String, varyings: &Varyings, values: &[SampleValues]) -> String {
    let end = coverage_json.trim_end().len();
    coverage_json.truncate(end);
    assert_eq!(coverage_json.pop(), Some('}'), "a JSON object");
    let s = &mut coverage_json;
    s.push_str(",\"values\":{\"varyings\":[");
    for (k, v) in varyings.list.iter().enumerate() {
        let _ = write!(
            s,
            "{}{{\"name\":{},\"channels\":{},\"interpolation\":\"{}\",\"sampling\":\"{}\"}}",
            if k == 0 { "" } else { "," },
            serde_json::Value::from(v.name.as_str()),
            v.channels,
            v.interpolation.name(),
            v.sampling.name()
        );
    }
    let _ = write!(
        s,
        "],\"provoking_vertex\":\"{}\",\"samples\":[",
        varyings.provoking.name()
    );
    for (k, v) in values.iter().enumerate() {
        let _ = write!(
            s,
            "{}[{},{},{},{},[",
            if k == 0 { "" } else { "," },
            v.x,
            v.y,
            v.sample,
            v.id
        );
        for (j, value) in v.values.iter().enumerate() {
            if j > 0 {
                s.push(',');
            }
            match value {
                Ok(channels) => {
                    s.push('[');
                    for (c, channel) in channels.iter().enumerate() {
                        let _ = write!(s, "{}\"{}\"", if c == 0 { "" } else { "," }, exact_text(channel));
                    }
                    s.push(']');
                }
                Err(e) => {
                    let _ = write!(s, "\"{}\"", e.name());
                }
            }
        }
        s.push_str("]]");
    }
    s.push_str("]}}");
    coverage_json
}
