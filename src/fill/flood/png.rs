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

impl PngError {
    /// The file it names.
    pub fn file(&self) -> &str {
        match self {
            PngError::Unreadable { file, .. }
            | PngError::Empty { file }
            | PngError::NotPng { file }
            | PngError::Truncated { file, .. }
            | PngError::Corrupt { file, .. }
            | PngError::TooLarge { file, .. } => file,
        }
    }

    /// What is wrong, without the file's name (`Display` is `FILE: DETAIL`).
    pub fn detail(&self) -> String {
        match self {
            PngError::Unreadable { error, .. } => format!("cannot read: {error}"),
            PngError::Empty { .. } => "not a PNG file (the file is empty)".to_string(),
            PngError::NotPng { .. } => "not a PNG file (it does not start with the PNG signature)".to_string(),
            PngError::Truncated { detail, .. } => format!("truncated PNG: the data ends early ({detail})"),
            PngError::Corrupt { detail, .. } => format!("corrupt PNG: {detail}"),
            PngError::TooLarge {
                width, height, limit, ..
            } => format!("the image is {width}x{height}, larger than the limit of {limit} pixels per side"),
        }
    }
}

impl fmt::Display for PngError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.file(), self.detail())
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
    decode(BufReader::new(opened), &file, MAX_IMAGE_SIDE).map(into_rgba8)
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
    decode(Cursor::new(bytes), file, max_side).map(into_rgba8)
}

/// As [`decode_png_within`], the image as decoded (its colour type kept: the readers of
/// another renderer's mask and ids PNGs tell an 8-bit RGBA ids image from a converted one).
pub fn decode_png_as_decoded(bytes: &[u8], file: &str, max_side: u32) -> Result<DynamicImage, PngError> {
    decode(Cursor::new(bytes), file, max_side)
}

fn into_rgba8(image: DynamicImage) -> RgbaImage {
    match image {
        DynamicImage::ImageRgba8(rgba) => rgba,
        other => other.to_rgba8(),
    }
}

/// The PNG decoder's own allocations besides the image (text, ICC profile and other
/// metadata chunks, row buffers). 64 MiB is far above what real metadata needs and keeps
/// a hostile file from asking for gigabytes of chunk data.
const METADATA_BUDGET: u64 = 64 << 20;

fn decode<R: BufRead + Seek>(mut reader: R, file: &str, max_side: u32) -> Result<DynamicImage, PngError> {
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
    check_palette(&mut reader, file)?;
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
    // A last guard: the png crate has panicked on malformed files (a short palette, see
    // `check_palette`); whatever else it may panic on is a corrupt file, not a crash.
    let decoded = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| DynamicImage::from_decoder(decoder)));
    match decoded {
        Ok(image) => image.map_err(fail),
        Err(panic) => Err(PngError::Corrupt {
            file: file.to_string(),
            detail: format!(
                "the PNG decoder failed on it ({})",
                panic
                    .downcast_ref::<String>()
                    .map(String::as_str)
                    .or_else(|| panic.downcast_ref::<&str>().copied())
                    .unwrap_or("a panic")
            ),
        }),
    }
}

/// Refuses a PLTE chunk whose length is not 1 to 256 entries of 3 bytes (PNG 1.2,
/// section 4.1.2: "a chunk length not divisible by 3 is an error"). The png crate 0.18
/// accepts such a chunk and then panics while expanding the palette (an index past the
/// palette's end); this reads only the chunk headers, before the decoder runs. Reading
/// stops at the first header that is cut short or at IEND (the decoder reports those).
fn check_palette<R: BufRead + Seek>(reader: &mut R, file: &str) -> Result<(), PngError> {
    let mut header = [0u8; 8];
    if reader.read_exact(&mut header).is_err() {
        return Ok(());
    }
    loop {
        if reader.read_exact(&mut header).is_err() {
            return Ok(());
        }
        let length = u32::from_be_bytes([header[0], header[1], header[2], header[3]]);
        let kind = &header[4..8];
        if kind == b"PLTE" && (length == 0 || length % 3 != 0 || length > 3 * 256) {
            return Err(PngError::Corrupt {
                file: file.to_string(),
                detail: format!("its PLTE chunk is {length} bytes, not 1 to 256 entries of 3 bytes"),
            });
        }
        if kind == b"IEND" {
            return Ok(());
        }
        // The chunk's data and its CRC.
        if reader.seek_relative(i64::from(length) + 4).is_err() {
            return Ok(());
        }
    }
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

    /// A PNG's chunk headers: the signature, then each `(type, length)` with `length`
    /// bytes of data and a 4-byte CRC (never checked here: `check_palette` reads headers).
    fn chunks(list: &[(&[u8; 4], u32)]) -> Vec<u8> {
        let mut out = PNG_SIGNATURE.to_vec();
        for (kind, len) in list {
            out.extend_from_slice(&len.to_be_bytes());
            out.extend_from_slice(*kind);
            out.extend(std::iter::repeat_n(7u8, usize::try_from(*len).unwrap()));
            out.extend_from_slice(&[0, 0, 0, 0]);
        }
        out
    }

    fn palette_verdict(bytes: &[u8]) -> Result<(), PngError> {
        check_palette(&mut Cursor::new(bytes), "t.png")
    }

    /// PNG 1.2 section 4.1.2: a PLTE chunk holds 1 to 256 entries of 3 bytes; any other
    /// length is an error, found wherever the chunk lies and not after IEND.
    #[test]
    fn a_palette_is_one_to_256_entries_of_three_bytes() {
        for (len, ok) in [
            (0, false),
            (1, false),
            (2, false),
            (3, true),
            (12, true),
            (13, false),
            (765, true),
            (768, true),
            (769, false),
            (771, false),
        ] {
            let bytes = chunks(&[(b"IHDR", 13), (b"PLTE", len), (b"IDAT", 20), (b"IEND", 0)]);
            assert_eq!(palette_verdict(&bytes).is_ok(), ok, "PLTE of {len} bytes");
        }
        // Past a long chunk: the walk skips data and CRC exactly.
        let long = chunks(&[(b"IHDR", 13), (b"tEXt", 1000), (b"PLTE", 13), (b"IEND", 0)]);
        match palette_verdict(&long) {
            Err(e) => assert_eq!(
                e.to_string(),
                "t.png: corrupt PNG: its PLTE chunk is 13 bytes, not 1 to 256 entries of 3 bytes"
            ),
            Ok(()) => panic!("the PLTE after tEXt was not found"),
        }
        // After IEND nothing is read; a cut header ends the walk (the decoder reports it).
        assert!(palette_verdict(&chunks(&[(b"IHDR", 13), (b"IEND", 0), (b"PLTE", 13)])).is_ok());
        let mut cut = chunks(&[(b"IHDR", 13)]);
        cut.extend_from_slice(&[0, 0, 0]);
        assert!(palette_verdict(&cut).is_ok());
    }

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
