//! Reading the flood fill's input: PNG (any colour type) as 8-bit RGBA, with a size limit
//! checked from the header before any pixel is decoded, and errors that name the file.

use std::fmt;
use std::io::{BufRead, BufReader, Cursor, Seek};
use std::path::Path;

use image::codecs::png::PngDecoder;
use image::{DynamicImage, ImageDecoder, ImageError, RgbaImage};

use crate::convention::MAX_CANVAS;

/// The largest width and height [`load_png`] and [`decode_png`] accept: the crate's
/// [`MAX_CANVAS`]. An image at the limit takes 1 GiB as 8-bit RGBA (2 GiB more while a
/// 16-bit PNG is being converted).
pub const MAX_IMAGE_SIDE: u32 = MAX_CANVAS;

/// The PNG signature every PNG file starts with.
const PNG_SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];

/// Why a PNG could not be loaded. `Display` names the file and what is wrong.
#[derive(Debug)]
pub enum PngError {
    /// The file could not be opened or read.
    Unreadable {
        /// The file.
        file: String,
        /// The I/O error.
        error: std::io::Error,
    },
    /// The file is empty.
    Empty {
        /// The file.
        file: String,
    },
    /// The data does not start with the PNG signature.
    NotPng {
        /// The file.
        file: String,
    },
    /// The data ends before the image does.
    Truncated {
        /// The file.
        file: String,
        /// The decoder's message.
        detail: String,
    },
    /// The data is not a valid PNG (bad chunk, checksum, compressed data, header).
    Corrupt {
        /// The file.
        file: String,
        /// The decoder's message.
        detail: String,
    },
    /// The image is wider or taller than the limit.
    TooLarge {
        /// The file.
        file: String,
        /// The width the header states.
        width: u32,
        /// The height the header states.
        height: u32,
        /// The largest side accepted.
        limit: u32,
    },
}

impl fmt::Display for PngError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PngError::Unreadable { file, error } => write!(f, "{file}: cannot read: {error}"),
            PngError::Empty { file } => write!(f, "{file}: not a PNG file (the file is empty)"),
            PngError::NotPng { file } => write!(f, "{file}: not a PNG file (it does not start with the PNG signature)"),
            PngError::Truncated { file, detail } => write!(f, "{file}: truncated PNG: the data ends early ({detail})"),
            PngError::Corrupt { file, detail } => write!(f, "{file}: corrupt PNG: {detail}"),
            PngError::TooLarge {
                file,
                width,
                height,
                limit,
            } => write!(
                f,
                "{file}: the image is {width}x{height}, larger than the limit of {limit} pixels per side"
            ),
        }
    }
}

impl std::error::Error for PngError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            PngError::Unreadable { error, .. } => Some(error),
            _ => None,
        }
    }
}

/// Reads a PNG file as 8-bit RGBA, at most [`MAX_IMAGE_SIDE`] pixels per side. Errors
/// name the file (as `path` displays). See [`decode_png`] for the conversion.
pub fn load_png(path: &Path) -> Result<RgbaImage, PngError> {
    let file = path.display().to_string();
    let opened = std::fs::File::open(path).map_err(|error| PngError::Unreadable {
        file: file.clone(),
        error,
    })?;
    decode(BufReader::new(opened), &file, MAX_IMAGE_SIDE)
}

/// Decodes PNG bytes as 8-bit RGBA, at most [`MAX_IMAGE_SIDE`] pixels per side; `file`
/// names the source in errors. Never panics.
///
/// Every PNG colour type is accepted and converted: grey and palette images expand to RGB,
/// a missing alpha becomes 255, and 16-bit channels are rounded to 8 bits, so two 16-bit
/// colours that round alike become one colour (and one region).
///
/// ```
/// use rasterproof::fill::flood::decode_png;
/// let err = decode_png(b"GIF89a...", "cat.gif").unwrap_err();
/// assert_eq!(err.to_string(), "cat.gif: not a PNG file (it does not start with the PNG signature)");
/// ```
pub fn decode_png(bytes: &[u8], file: &str) -> Result<RgbaImage, PngError> {
    decode_png_within(bytes, file, MAX_IMAGE_SIDE)
}

/// As [`decode_png`], with at most `max_side` pixels per side (for callers with less
/// memory to spend, such as the fuzz target).
pub fn decode_png_within(bytes: &[u8], file: &str, max_side: u32) -> Result<RgbaImage, PngError> {
    decode(Cursor::new(bytes), file, max_side)
}

/// The PNG decoder's own allocations besides the image (text, ICC profile and other
/// metadata chunks, row buffers). 64 MiB is far above what real metadata needs and keeps
/// a hostile file from asking for gigabytes of chunk data.
const METADATA_BUDGET: u64 = 64 << 20;

fn decode<R: BufRead + Seek>(mut reader: R, file: &str, max_side: u32) -> Result<RgbaImage, PngError> {
    let mut signature = [0u8; 8];
    let mut got = 0;
    while got < signature.len() {
        match reader.read(&mut signature[got..]) {
            Ok(0) => break,
            Ok(n) => got += n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(error) => {
                return Err(PngError::Unreadable {
                    file: file.to_string(),
                    error,
                })
            }
        }
    }
    if got == 0 {
        return Err(PngError::Empty { file: file.to_string() });
    }
    if signature[..got] != PNG_SIGNATURE[..got] {
        return Err(PngError::NotPng { file: file.to_string() });
    }
    if got < signature.len() {
        return Err(PngError::Truncated {
            file: file.to_string(),
            detail: format!("{got} of the 8 signature bytes"),
        });
    }
    reader.rewind().map_err(|error| PngError::Unreadable {
        file: file.to_string(),
        error,
    })?;
    let fail = |e: ImageError| classify(e, file);
    let mut limits = image::Limits::no_limits();
    limits.max_alloc = Some(METADATA_BUDGET);
    let decoder = PngDecoder::with_limits(reader, limits).map_err(fail)?;
    let (width, height) = decoder.dimensions();
    if width > max_side || height > max_side {
        return Err(PngError::TooLarge {
            file: file.to_string(),
            width,
            height,
            limit: max_side,
        });
    }
    let image = DynamicImage::from_decoder(decoder).map_err(fail)?;
    Ok(match image {
        DynamicImage::ImageRgba8(rgba) => rgba,
        other => other.to_rgba8(),
    })
}

/// Sorts a decoder error: the png crate reports data that stops early (anywhere, from the
/// header to the last chunk) as an I/O error of kind `UnexpectedEof`.
fn classify(error: ImageError, file: &str) -> PngError {
    let file = file.to_string();
    match error {
        ImageError::IoError(e) if e.kind() == std::io::ErrorKind::UnexpectedEof => PngError::Truncated {
            file,
            detail: e.to_string(),
        },
        ImageError::IoError(error) => PngError::Unreadable { file, error },
        other => PngError::Corrupt {
            file,
            detail: other.to_string(),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use image::Rgba;

    /// Every cut of a valid PNG before its final chunk (IEND, 12 bytes) is reported as
    /// truncated, never as corrupt or as a panic.
    #[test]
    fn every_cut_png_is_truncated() {
        let img = RgbaImage::from_fn(40, 30, |x, y| {
            Rgba([
                (x * 7 % 256).try_into().unwrap(),
                (y * 5 % 256).try_into().unwrap(),
                0,
                255,
            ])
        });
        let mut bytes = Vec::new();
        img.write_to(&mut Cursor::new(&mut bytes), image::ImageFormat::Png)
            .unwrap();
        assert_eq!(decode_png(&bytes, "a.png").unwrap(), img);
        for n in 1..bytes.len() - 12 {
            match decode_png(&bytes[..n], "a.png") {
                Err(PngError::Truncated { file, .. }) => assert_eq!(file, "a.png"),
                other => panic!("cut at {n} of {}: {other:?}", bytes.len()),
            }
        }
        assert!(matches!(decode_png(&[], "a.png"), Err(PngError::Empty { .. })));
    }
}
