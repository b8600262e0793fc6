//! Another renderer's output, read: a PNG (as a coverage mask, as an ids PNG, or as the
//! grey levels of anti-aliased coverage) or the JSON of `render --format json`. Every error names the file and what is wrong with it;
//! nothing here panics on a file's content.

use std::fmt;

use image::DynamicImage;
use serde_json::Value;

use crate::coverage::{Coverage, CoverageSink, MAX_ID};

/// A grey image: one level per pixel, row-major, of `bits` bits (8 or 16).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GreyImage {
    /// Width.
    pub width: u32,
    /// Height.
    pub height: u32,
    /// Bits per level: 8 or 16.
    pub bits: u32,
    /// The levels, row-major.
    pub levels: Vec<u16>,
}

impl GreyImage {
    /// A grey PNG (8- or 16-bit grey, with or without alpha, whose alpha is ignored),
    /// named `name` in errors.
    ///
    /// # Errors
    /// Not a PNG, or another colour type: the error names the file and what it holds.
    pub fn read_png(bytes: &[u8], name: &str) -> Result<GreyImage, String> {
        // The crate's guarded decoder: a malformed palette or a hostile size is an error,
        // not a panic inside the decoder or an allocation of gigabytes.
        let image = crate::fill::flood::decode_png_as_decoded(bytes, name, crate::convention::MAX_CANVAS)
            .map_err(|e| format!("{name}: not a PNG this reader takes: {}", e.detail()))?;
        let (width, height) = (image.width(), image.height());
        match image {
            image::DynamicImage::ImageLuma8(_) | image::DynamicImage::ImageLumaA8(_) => Ok(GreyImage {
                width,
                height,
                bits: 8,
                levels: image.to_luma8().into_raw().into_iter().map(u16::from).collect(),
            }),
            image::DynamicImage::ImageLuma16(_) | image::DynamicImage::ImageLumaA16(_) => Ok(GreyImage {
                width,
                height,
                bits: 16,
                levels: image.to_luma16().into_raw(),
            }),
            other => Err(format!(
                "{name}: a {:?} PNG; --as grey reads 8- or 16-bit grey (with or without alpha)",
                other.color()
            )),
        }
    }
}

/// Values another renderer wrote: `channels` numbers a pixel, row-major.
#[derive(Debug, Clone, PartialEq)]
pub struct ValueImage {
    /// Width.
    pub width: u32,
    /// Height.
    pub height: u32,
    /// Channels a pixel (1 to 4).
    pub channels: usize,
    /// The numbers, `channels` a pixel, row-major.
    pub samples: ValueSamples,
}

/// The numbers of a [`ValueImage`].
#[derive(Debug, Clone, PartialEq)]
pub enum ValueSamples {
    /// Float32 samples, bit for bit as written.
    F32(Vec<f32>),
    /// UNORM levels of `bits` bits (8 or 16): level `l` stands for `l / (2^bits - 1)`.
    Unorm {
        /// 8 or 16.
        bits: u32,
        /// The levels.
        levels: Vec<u16>,
    },
}

impl ValueImage {
    /// Reads a float32 TIFF (IEEE floating-point samples: 1 a pixel (grey), 3 (RGB) or 4
    /// (RGBA); uncompressed, LZW or Deflate) or a UNORM PNG (8 or 16 bits; grey, grey and
    /// alpha, RGB, RGBA).
    ///
    /// # Errors
    /// Neither, another sample type (an integer TIFF, a palette PNG), a canvas beyond
    /// the crate's largest: the message names what the file holds.
    pub fn read(bytes: &[u8]) -> Result<ValueImage, String> {
        if bytes.starts_with(b"\x89PNG\r\n\x1a\n") {
            return ValueImage::read_png(bytes);
        }
        if !(bytes.starts_with(b"II*\0") || bytes.starts_with(b"MM\0*")) {
            return Err("neither a TIFF nor a PNG file (--as values reads a float32 TIFF or a UNORM PNG)".to_string());
        }
        let tiff_err = |e: tiff::TiffError| format!("cannot decode the TIFF: {e}");
        let mut decoder = tiff::decoder::Decoder::new(std::io::Cursor::new(bytes)).map_err(tiff_err)?;
        let (width, height) = decoder.dimensions().map_err(tiff_err)?;
        if width.max(height) > crate::convention::MAX_CANVAS {
            return Err(format!(
                "a {width}x{height} image; the largest canvas is {0}x{0}",
                crate::convention::MAX_CANVAS
            ));
        }
        let channels = match decoder.colortype().map_err(tiff_err)? {
            tiff::ColorType::Gray(32) => 1,
            tiff::ColorType::RGB(32) => 3,
            tiff::ColorType::RGBA(32) => 4,
            other => {
                return Err(format!(
                    "a TIFF of {other:?} samples; --as values reads 32-bit float grey, RGB or RGBA"
                ))
            }
        };
        match decoder.read_image().map_err(tiff_err)? {
            tiff::decoder::DecodingResult::F32(samples) if samples.len() == pixel_count(width, height) * channels => {
                Ok(ValueImage {
                    width,
                    height,
                    channels,
                    samples: ValueSamples::F32(samples),
                })
            }
            tiff::decoder::DecodingResult::F32(_) => {
                Err("a float TIFF whose sample count is not its size's".to_string())
            }
            _ => Err("a TIFF of 32-bit integer samples; --as values reads float samples (SampleFormat 3)".to_string()),
        }
    }

    fn read_png(bytes: &[u8]) -> Result<ValueImage, String> {
        let image = crate::fill::flood::decode_png_as_decoded(bytes, "", crate::convention::MAX_CANVAS)
            .map_err(|e| format!("cannot decode the PNG: {}", e.detail()))?;
        let (width, height) = (image.width(), image.height());
        let channels = usize::from(image.color().channel_count());
        let (bits, levels) = match image {
            DynamicImage::ImageLuma8(_)
            | DynamicImage::ImageLumaA8(_)
            | DynamicImage::ImageRgb8(_)
            | DynamicImage::ImageRgba8(_) => (8, image.into_bytes().into_iter().map(u16::from).collect()),
            DynamicImage::ImageLuma16(i) => (16, i.into_raw()),
            DynamicImage::ImageLumaA16(i) => (16, i.into_raw()),
            DynamicImage::ImageRgb16(i) => (16, i.into_raw()),
            DynamicImage::ImageRgba16(i) => (16, i.into_raw()),
            other => {
                return Err(format!(
                    "a {:?} PNG; --as values reads 8- or 16-bit UNORM",
                    other.color()
                ))
            }
        };
        Ok(ValueImage {
            width,
            height,
            channels,
            samples: ValueSamples::Unorm { bits, levels },
        })
    }

    /// Whether pixel `k` (row-major) has a channel that is not zero.
    fn nonzero(&self, k: usize) -> bool {
        let range = k * self.channels..(k + 1) * self.channels;
        match &self.samples {
            ValueSamples::F32(s) => s[range].iter().any(|&v| v != 0.0),
            ValueSamples::Unorm { levels, .. } => levels[range].iter().any(|&v| v != 0),
        }
    }
}

/// How to read the other renderer's file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Format {
    /// A PNG: a pixel is covered when it differs from the background colour. Names no
    /// owner, so it shows missing and extra pixels only.
    Mask,
    /// An ids PNG (the format of [`crate::coverage::ids`]): `id + 1` in R (low byte), G,
    /// B (high byte), 0 uncovered; alpha 254 marks a pixel with several owners (its RGB is
    /// the highest). 8-bit RGBA or RGB.
    Ids,
    /// The JSON of `render --format json`: every pixel's owner list.
    Json,
    /// A grey PNG of anti-aliased coverage, 8 or 16 bits ([`GreyImage`]), for
    /// `compare --as grey` and the grey hunt; as a mask, a pixel is covered where its
    /// level is not zero.
    Grey,
    /// Values written at covered pixels, for `compare --as values`: a float32 TIFF (1, 3
    /// or 4 samples a pixel) or a UNORM PNG (8 or 16 bits; grey, grey and alpha, RGB or
    /// RGBA) ([`ValueImage`]); as a mask, a pixel is covered where a channel is not zero.
    Values,
}

impl Format {
    /// The name on the command line (`--as`).
    pub fn name(self) -> &'static str {
        match self {
            Format::Mask => "mask",
            Format::Ids => "ids",
            Format::Json => "json",
            Format::Grey => "grey",
            Format::Values => "values",
        }
    }

    /// Parses a name written by [`Format::name`].
    pub fn from_name(name: &str) -> Option<Format> {
        [Format::Mask, Format::Ids, Format::Json, Format::Grey, Format::Values]
            .into_iter()
            .find(|f| f.name() == name)
    }
}

/// The colour of an uncovered pixel in a mask PNG, 8 bits per channel (a 16-bit PNG
/// compares against each channel times 257). `None` for alpha: transparent black for
/// images with alpha (alpha 0, whatever the colour), black for images without.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Background {
    /// Red, green, blue.
    pub rgb: [u8; 3],
    /// Alpha, when given (`--background R,G,B,A`).
    pub alpha: Option<u8>,
}

/// A file that cannot be read as the other renderer's output.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TheirsError {
    /// The file, as named on the command line.
    pub file: String,
    /// What is wrong, naming the field and value where there is one.
    pub message: String,
}

impl fmt::Display for TheirsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.file, self.message)
    }
}

impl std::error::Error for TheirsError {}

/// One pixel of their output.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct TheirPixel {
    /// Covered at all.
    pub covered: bool,
    /// Its owners, ascending (a mask names none; an ids PNG names the highest).
    pub ids: Vec<u32>,
    /// An ids PNG marked it as having several owners (alpha 254).
    pub several: bool,
}

#[derive(Debug, Clone, PartialEq)]
enum Data {
    Mask(Vec<bool>),
    Ids { values: Vec<u32>, several: Vec<bool> },
    Json(Coverage),
    Grey(GreyImage),
    Values(ValueImage),
}

/// Another renderer's output for one canvas.
#[derive(Debug, Clone, PartialEq)]
pub struct Theirs {
    width: u32,
    height: u32,
    format: Format,
    data: Data,
}

impl Theirs {
    /// A coverage as their output in `format`: what a renderer writing that format would
    /// have written for it (`Mask`: covered or not; `Ids`: the highest owner, several
    /// marked; `Json`: every owner; `Grey`: 8-bit levels, 255 where covered). For tests
    /// and for renderers driven from Rust.
    pub fn from_coverage(coverage: &Coverage, format: Format) -> Theirs {
        let (width, height) = (coverage.width(), coverage.height());
        let n = pixel_count(width, height);
        let data = match format {
            Format::Json => Data::Json(coverage.clone()),
            Format::Mask => {
                let mut mask = vec![false; n];
                for (x, y, _) in coverage.iter() {
                    mask[index(width, x, y)] = true;
                }
                Data::Mask(mask)
            }
            Format::Ids => {
                let (mut values, mut several) = (vec![0; n], vec![false; n]);
                for (x, y, ids) in coverage.iter() {
                    let k = index(width, x, y);
                    values[k] = ids.last().map_or(0, |&id| id.saturating_add(1));
                    several[k] = ids.len() > 1;
                }
                Data::Ids { values, several }
            }
            Format::Grey => {
                let mut levels = vec![0; n];
                for (x, y, _) in coverage.iter() {
                    levels[index(width, x, y)] = 255;
                }
                Data::Grey(GreyImage {
                    width,
                    height,
                    bits: 8,
                    levels,
                })
            }
            Format::Values => {
                let mut samples = vec![0.0; n];
                for (x, y, _) in coverage.iter() {
                    samples[index(width, x, y)] = 1.0;
                }
                Data::Values(ValueImage {
                    width,
                    height,
                    channels: 1,
                    samples: ValueSamples::F32(samples),
                })
            }
        };
        Theirs {
            width,
            height,
            format,
            data,
        }
    }

    /// Reads `bytes` (the file `file`, for errors) as `format`.
    ///
    /// PNGs: 8- or 16-bit grey, grey+alpha, RGB or RGBA; palette PNGs are expanded to RGB(A)
    /// by the decoder. An ids PNG must be 8-bit RGB or RGBA (ids do not survive a
    /// conversion). JSON: `{"width":W,"height":H,"pixels":[[x,y,[ids...]],...]}`, pixels on
    /// the canvas, sorted by y then x, each once, ids ascending (repeats allowed: a primitive
    /// covering a pixel twice).
    ///
    /// # Errors
    /// Not a PNG / not JSON, an unsupported pixel type, a malformed or out-of-order pixel
    /// list: a [`TheirsError`] naming `file`, the field and the value.
    pub fn read(bytes: &[u8], file: &str, format: Format, background: Background) -> Result<Theirs, TheirsError> {
        let err = |message: String| TheirsError {
            file: file.to_string(),
            message,
        };
        match format {
            Format::Json => read_json(bytes).map_err(err),
            Format::Values => {
                let image = ValueImage::read(bytes).map_err(err)?;
                Ok(Theirs {
                    width: image.width,
                    height: image.height,
                    format,
                    data: Data::Values(image),
                })
            }
            Format::Grey => {
                let grey = GreyImage::read_png(bytes, file).map_err(|e| TheirsError {
                    file: file.to_string(),
                    message: e.strip_prefix(&format!("{file}: ")).unwrap_or(&e).to_string(),
                })?;
                Ok(Theirs::from_grey(grey))
            }
            Format::Mask | Format::Ids => {
                if !bytes.starts_with(b"\x89PNG\r\n\x1a\n") {
                    return Err(err(format!(
                        "not a PNG file (--as {} reads PNG images; use --as json for render's JSON)",
                        format.name()
                    )));
                }
                let image = crate::fill::flood::decode_png_as_decoded(bytes, file, crate::convention::MAX_CANVAS)
                    .map_err(|e| err(format!("cannot decode the PNG: {}", e.detail())))?;
                if format == Format::Mask {
                    read_mask(&image, background).map_err(err)
                } else {
                    read_ids(&image).map_err(err)
                }
            }
        }
    }

    /// A multisampled output read as one image of `samples` images stacked (width `W`,
    /// height `samples x H`, sample `s` in rows `s H .. (s + 1) H`, as `render --ids-out`
    /// writes under a pattern), split into one output per sample index.
    ///
    /// # Errors
    /// A height that is not `samples` times the canvas's `height`; a format that is not a
    /// stacked PNG (`mask` or `ids`).
    pub fn unstack(&self, samples: usize, height: u32) -> Result<Vec<Theirs>, String> {
        let stacked = u32::try_from(samples).ok().and_then(|n| n.checked_mul(height));
        if samples == 0 || stacked != Some(self.height) {
            return Err(format!(
                "their image is {}x{}; {samples} sample images of the {}x{height} canvas stacked are {}x{}",
                self.width,
                self.height,
                self.width,
                self.width,
                u64::try_from(samples)
                    .unwrap_or(u64::MAX)
                    .saturating_mul(u64::from(height))
            ));
        }
        let h = height;
        let rows = pixel_count(self.width, h);
        let part = |v: usize| v * rows..(v + 1) * rows;
        (0..samples)
            .map(|v| {
                let data = match &self.data {
                    Data::Mask(m) => Data::Mask(m[part(v)].to_vec()),
                    Data::Ids { values, several } => Data::Ids {
                        values: values[part(v)].to_vec(),
                        several: several[part(v)].to_vec(),
                    },
                    Data::Json(_) | Data::Grey(_) | Data::Values(_) => {
                        return Err(format!(
                            "a multisampled output is a stacked PNG, read --as ids or mask, not --as {}",
                            self.format.name()
                        ))
                    }
                };
                Ok(Theirs {
                    width: self.width,
                    height: h,
                    format: self.format,
                    data,
                })
            })
            .collect()
    }

    /// A grey image as their output (`Format::Grey`).
    pub fn from_grey(grey: GreyImage) -> Theirs {
        Theirs {
            width: grey.width,
            height: grey.height,
            format: Format::Grey,
            data: Data::Grey(grey),
        }
    }

    /// Their grey levels, when they were read as `Format::Grey`.
    pub fn grey(&self) -> Option<&GreyImage> {
        match &self.data {
            Data::Grey(g) => Some(g),
            _ => None,
        }
    }

    /// Their values, when they were read as `Format::Values`.
    pub fn values(&self) -> Option<&ValueImage> {
        match &self.data {
            Data::Values(v) => Some(v),
            _ => None,
        }
    }

    /// Canvas width.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Canvas height.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The format it was read as.
    pub fn format(&self) -> Format {
        self.format
    }

    /// Pixel `(x, y)` (on the canvas).
    pub fn pixel(&self, x: u32, y: u32) -> TheirPixel {
        let k = index(self.width, x, y);
        match &self.data {
            Data::Mask(m) => TheirPixel {
                covered: m[k],
                ..TheirPixel::default()
            },
            Data::Grey(g) => TheirPixel {
                covered: g.levels[k] != 0,
                ..TheirPixel::default()
            },
            Data::Values(v) => TheirPixel {
                covered: v.nonzero(k),
                ..TheirPixel::default()
            },
            Data::Ids { values, several } => TheirPixel {
                covered: values[k] != 0,
                ids: values[k].checked_sub(1).into_iter().collect(),
                several: several[k],
            },
            Data::Json(c) => {
                let ids = c.owners(x, y).to_vec();
                TheirPixel {
                    covered: !ids.is_empty(),
                    several: ids.len() > 1,
                    ids,
                }
            }
        }
    }

    /// Their covered pixels, row-major, as `(x, y)`.
    pub fn covered(&self) -> Vec<(u32, u32)> {
        let w = usize::try_from(self.width).expect("fits");
        let at = |k: usize| {
            let (x, y) = (k % w, k / w);
            (u32::try_from(x).expect("fits"), u32::try_from(y).expect("fits"))
        };
        match &self.data {
            Data::Mask(m) => m.iter().enumerate().filter(|&(_, &c)| c).map(|(k, _)| at(k)).collect(),
            Data::Ids { values, .. } => values
                .iter()
                .enumerate()
                .filter(|&(_, &v)| v != 0)
                .map(|(k, _)| at(k))
                .collect(),
            Data::Json(c) => c.iter().map(|(x, y, _)| (x, y)).collect(),
            Data::Grey(g) => g
                .levels
                .iter()
                .enumerate()
                .filter(|&(_, &v)| v != 0)
                .map(|(k, _)| at(k))
                .collect(),
            Data::Values(v) => (0..pixel_count(v.width, v.height))
                .filter(|&k| v.nonzero(k))
                .map(at)
                .collect(),
        }
    }

    /// How many pixels they cover.
    pub fn covered_pixels(&self) -> usize {
        match &self.data {
            Data::Mask(m) => m.iter().filter(|&&c| c).count(),
            Data::Ids { values, .. } => values.iter().filter(|&&v| v != 0).count(),
            Data::Json(c) => c.covered_pixels(),
            Data::Grey(g) => g.levels.iter().filter(|&&v| v != 0).count(),
            Data::Values(v) => (0..pixel_count(v.width, v.height)).filter(|&k| v.nonzero(k)).count(),
        }
    }
}

fn pixel_count(width: u32, height: u32) -> usize {
    usize::try_from(u64::from(width) * u64::from(height)).expect("a canvas fits memory")
}

fn index(width: u32, x: u32, y: u32) -> usize {
    usize::try_from(u64::from(y) * u64::from(width) + u64::from(x)).expect("a canvas fits memory")
}

/// The decoder's pixel type, named for messages.
fn colour_name(image: &DynamicImage) -> String {
    format!("{:?}", image.color())
}

fn read_mask(image: &DynamicImage, background: Background) -> Result<Theirs, String> {
    use image::ColorType as C;
    let (width, height) = (image.width(), image.height());
    let has_alpha = image.color().has_alpha();
    let sixteen = match image.color() {
        C::L8 | C::La8 | C::Rgb8 | C::Rgba8 => false,
        C::L16 | C::La16 | C::Rgb16 | C::Rgba16 => true,
        _ => {
            return Err(format!(
                "unsupported PNG pixel type {} for --as mask",
                colour_name(image)
            ))
        }
    };
    let widen = |v: u8| if sixteen { u16::from(v) * 257 } else { u16::from(v) };
    let bg_rgb = background.rgb.map(widen);
    let bg_alpha = background.alpha.map(widen);
    let rgba = image.to_rgba16();
    let scale = |v: u16| if sixteen { v } else { v / 257 };
    let mask = rgba
        .pixels()
        .map(|p| {
            let [r, g, b, a] = p.0.map(scale);
            match (has_alpha, bg_alpha) {
                (true, None) => a != 0,
                (true, Some(ba)) => [r, g, b, a] != [bg_rgb[0], bg_rgb[1], bg_rgb[2], ba],
                (false, _) => [r, g, b] != bg_rgb,
            }
        })
        .collect();
    Ok(Theirs {
        width,
        height,
        format: Format::Mask,
        data: Data::Mask(mask),
    })
}

fn read_ids(image: &DynamicImage) -> Result<Theirs, String> {
    let rgba = match image {
        DynamicImage::ImageRgba8(i) => i.clone(),
        DynamicImage::ImageRgb8(i) => DynamicImage::ImageRgb8(i.clone()).to_rgba8(),
        other => {
            return Err(format!(
                "an ids PNG must be 8-bit RGBA or RGB, this one is {} (ids do not survive a conversion)",
                colour_name(other)
            ))
        }
    };
    let (width, height) = rgba.dimensions();
    let mut values = Vec::with_capacity(pixel_count(width, height));
    let mut several = Vec::with_capacity(values.capacity());
    for p in rgba.pixels() {
        let [r, g, b, a] = p.0;
        let v = u32::from_le_bytes([r, g, b, 0]);
        values.push(v);
        several.push(v != 0 && a == crate::coverage::ids::ALPHA_SEVERAL_OWNERS);
    }
    Ok(Theirs {
        width,
        height,
        format: Format::Ids,
        data: Data::Ids { values, several },
    })
}

fn read_json(bytes: &[u8]) -> Result<Theirs, String> {
    let root: Value = serde_json::from_slice(bytes).map_err(|e| format!("not JSON: {e}"))?;
    let obj = root
        .as_object()
        .ok_or("not a coverage: expected an object {\"width\", \"height\", \"pixels\"}")?;
    let side = |name: &str| -> Result<u32, String> {
        let v = obj.get(name).ok_or(format!("missing field {name:?}"))?;
        v.as_u64()
            .and_then(|n| u32::try_from(n).ok())
            .filter(|&n| (1..=crate::convention::MAX_CANVAS).contains(&n))
            .ok_or(format!(
                "{name}: {v} is not a canvas side (1..={})",
                crate::convention::MAX_CANVAS
            ))
    };
    let (width, height) = (side("width")?, side("height")?);
    let pixels = obj
        .get("pixels")
        .ok_or("missing field \"pixels\"")?
        .as_array()
        .ok_or("pixels: not an array")?;
    let mut coverage = Coverage::new(width, height);
    let mut last: Option<(u32, u32)> = None;
    for (k, p) in pixels.iter().enumerate() {
        let at = |what: &str| format!("pixels[{k}]: {what}: {p}");
        let entry = p
            .as_array()
            .filter(|a| a.len() == 3)
            .ok_or_else(|| at("expected [x, y, [ids...]]"))?;
        let coord = |v: &Value, side: u32, axis: &str| {
            v.as_u64()
                .and_then(|n| u32::try_from(n).ok())
                .filter(|&n| n < side)
                .ok_or_else(|| at(&format!("{axis} is not a pixel of the {width}x{height} canvas")))
        };
        let (x, y) = (coord(&entry[0], width, "x")?, coord(&entry[1], height, "y")?);
        if last.is_some_and(|l| l >= (y, x)) {
            return Err(at("pixels out of order (sorted by y then x, each pixel once)"));
        }
        last = Some((y, x));
        let ids = entry[2].as_array().ok_or_else(|| at("ids: not an array"))?;
        if ids.is_empty() {
            return Err(at("ids: empty (list covered pixels only)"));
        }
        let mut previous = 0;
        for v in ids {
            let id = v
                .as_u64()
                .and_then(|n| u32::try_from(n).ok())
                .filter(|&n| n <= MAX_ID)
                .ok_or_else(|| at(&format!("id {v} is not a primitive id (0..={MAX_ID})")))?;
            if id < previous {
                return Err(at("ids not ascending"));
            }
            previous = id;
            coverage.cover(x, y, id);
        }
    }
    Ok(Theirs {
        width,
        height,
        format: Format::Json,
        data: Data::Json(coverage),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn json(text: &str) -> Result<Theirs, TheirsError> {
        Theirs::read(text.as_bytes(), "t.json", Format::Json, Background::default())
    }

    #[test]
    fn json_reads_what_render_writes() {
        let mut c = Coverage::new(4, 3);
        c.cover(2, 1, 7);
        c.cover(2, 1, 3);
        c.cover(0, 2, 1);
        let t = json(&c.to_json()).unwrap();
        assert_eq!(t, Theirs::from_coverage(&c, Format::Json));
        assert_eq!(t.pixel(2, 1).ids, vec![3, 7]);
        assert!(t.pixel(2, 1).several);
        assert!(!t.pixel(1, 1).covered);
        assert_eq!(t.covered_pixels(), 2);
    }

    #[test]
    fn bad_json_is_named() {
        let e = |text| json(text).unwrap_err().to_string();
        assert!(e("[1,").starts_with("t.json: not JSON"), "{}", e("[1,"));
        assert!(e(r#"{"width":4,"height":3}"#).contains("missing field \"pixels\""));
        assert!(e(r#"{"width":0,"height":3,"pixels":[]}"#).contains("width: 0 is not a canvas side"));
        let off = e(r#"{"width":4,"height":3,"pixels":[[4,0,[1]]]}"#);
        assert!(
            off.contains("pixels[0]") && off.contains("x is not a pixel of the 4x3 canvas"),
            "{off}"
        );
        let order = e(r#"{"width":4,"height":3,"pixels":[[1,1,[1]],[0,1,[1]]]}"#);
        assert!(order.contains("pixels[1]") && order.contains("out of order"), "{order}");
        let twice = e(r#"{"width":4,"height":3,"pixels":[[1,1,[1]],[1,1,[2]]]}"#);
        assert!(twice.contains("out of order"), "{twice}");
        assert!(e(r#"{"width":4,"height":3,"pixels":[[1,1,[2,1]]]}"#).contains("ids not ascending"));
        assert!(e(r#"{"width":4,"height":3,"pixels":[[1,1,[-1]]]}"#).contains("id -1 is not a primitive id"));
        assert!(e(r#"{"width":4,"height":3,"pixels":[[1,1,[]]]}"#).contains("ids: empty"));
    }

    fn png(image: &DynamicImage) -> Vec<u8> {
        let mut bytes = std::io::Cursor::new(Vec::new());
        image.write_to(&mut bytes, image::ImageFormat::Png).unwrap();
        bytes.into_inner()
    }

    #[test]
    fn ids_png_round_trips_and_marks_several() {
        let mut c = Coverage::new(3, 2);
        c.cover(0, 0, 0);
        c.cover(1, 0, 65536);
        c.cover(2, 1, 4);
        c.cover(2, 1, 9);
        let bytes = png(&DynamicImage::ImageRgba8(c.to_ids_image().unwrap()));
        let t = Theirs::read(&bytes, "i.png", Format::Ids, Background::default()).unwrap();
        assert_eq!(t, Theirs::from_coverage(&c, Format::Ids));
        assert_eq!(t.pixel(1, 0).ids, vec![65536]);
        assert_eq!(
            t.pixel(2, 1),
            TheirPixel {
                covered: true,
                ids: vec![9],
                several: true
            }
        );
        assert!(!t.pixel(0, 1).covered);
    }

    #[test]
    fn pngs_that_are_not_ids_pngs_are_refused_clearly() {
        let grey16 = png(&DynamicImage::ImageLuma16(image::ImageBuffer::new(2, 2)));
        let e = Theirs::read(&grey16, "g.png", Format::Ids, Background::default()).unwrap_err();
        assert!(
            e.to_string().starts_with("g.png: an ids PNG must be 8-bit RGBA or RGB"),
            "{e}"
        );
        let e = Theirs::read(b"GIF89a....", "x.gif", Format::Mask, Background::default()).unwrap_err();
        assert!(e.to_string().contains("not a PNG file"), "{e}");
        let mut truncated = png(&DynamicImage::ImageRgb8(image::ImageBuffer::new(2, 2)));
        truncated.truncate(40);
        let e = Theirs::read(&truncated, "t.png", Format::Mask, Background::default()).unwrap_err();
        assert!(e.to_string().contains("cannot decode the PNG"), "{e}");
    }

    #[test]
    fn masks_against_the_background() {
        // RGB: black is uncovered unless another background is given.
        let mut rgb = image::RgbImage::new(2, 1);
        rgb.put_pixel(1, 0, image::Rgb([10, 0, 0]));
        let bytes = png(&DynamicImage::ImageRgb8(rgb));
        let t = Theirs::read(&bytes, "m.png", Format::Mask, Background::default()).unwrap();
        assert_eq!((t.pixel(0, 0).covered, t.pixel(1, 0).covered), (false, true));
        let red = Background {
            rgb: [10, 0, 0],
            alpha: None,
        };
        let t = Theirs::read(&bytes, "m.png", Format::Mask, red).unwrap();
        assert_eq!((t.pixel(0, 0).covered, t.pixel(1, 0).covered), (true, false));
        // RGBA: alpha 0 is uncovered whatever the colour; 16-bit compares channel * 257.
        let mut rgba = image::ImageBuffer::<image::Rgba<u16>, Vec<u16>>::new(3, 1);
        rgba.put_pixel(0, 0, image::Rgba([500, 0, 0, 0]));
        rgba.put_pixel(1, 0, image::Rgba([0, 0, 0, 1]));
        rgba.put_pixel(2, 0, image::Rgba([257 * 10, 0, 0, 65535]));
        let bytes = png(&DynamicImage::ImageRgba16(rgba));
        let t = Theirs::read(&bytes, "m16.png", Format::Mask, Background::default()).unwrap();
        assert_eq!(
            (t.pixel(0, 0).covered, t.pixel(1, 0).covered, t.pixel(2, 0).covered),
            (false, true, true)
        );
        let opaque_red = Background {
            rgb: [10, 0, 0],
            alpha: Some(255),
        };
        let t = Theirs::read(&bytes, "m16.png", Format::Mask, opaque_red).unwrap();
        assert_eq!((t.pixel(0, 0).covered, t.pixel(2, 0).covered), (true, false));
    }
}
