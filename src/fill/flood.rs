//! Flood fill on a raster (seed 002): the 4- or 8-connected region of pixels whose RGBA
//! colour equals a seed pixel's exactly, found by a span (scanline) seed fill with an
//! explicit stack, with a plain breadth-first search beside it as the oracle.
//!
//! Seed 002 states the brute force: starting at the seed, recursively, "is the current
//! point's colour the seed point's colour? no -> stop; yes -> recolour it and restart for
//! every neighbour" (four neighbours: up, down, left, right; eight: those and the
//! corners), and warns that "recursion is very crude". It is: one call per pixel, nested as
//! deep as the region is long, so a 4096x4096 region overflows any thread's stack. Nothing
//! here recurses.
//!
//! - [`span_region`] is the seed fill of Smith ("Tint Fill", SIGGRAPH 1979) in the form of
//!   Heckbert ("A Seed Fill Algorithm", Graphics Gems I, 1990): fill a whole horizontal
//!   run, then remember the stretches of the rows above and below that touch it, on an
//!   explicit stack of spans. For 8-connectivity the stretch is one pixel wider on each
//!   side, because a pixel diagonally past either end of a run touches it.
//! - [`bfs_region`] is the oracle: a queue, a visited flag per pixel, and each pixel's
//!   four or eight neighbours, written to be read.
//!
//! Both compute the region without changing the image and return it as a [`Region`] (one
//! bit per pixel); [`flood_fill`] then recolours it, so filling with the seed's own colour
//! terminates and changes nothing. [`load_png`] and [`decode_png`] read the input with a
//! size limit and errors that name the file.

use std::collections::VecDeque;
use std::fmt;
use std::io::{BufRead, BufReader, Cursor, Seek};
use std::path::Path;

use image::codecs::png::PngDecoder;
use image::{DynamicImage, ImageDecoder, ImageError, Rgba, RgbaImage};

use crate::convention::MAX_CANVAS;

/// Which neighbours of a pixel are adjacent to it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Connectivity {
    /// Up, down, left and right.
    Four,
    /// Those four and the four diagonal corners.
    Eight,
}

impl Connectivity {
    /// Both, four first.
    pub const ALL: [Connectivity; 2] = [Connectivity::Four, Connectivity::Eight];

    /// 4 or 8, as written on the command line.
    pub fn number(self) -> u8 {
        match self {
            Connectivity::Four => 4,
            Connectivity::Eight => 8,
        }
    }

    /// Parses the number written by [`Connectivity::number`].
    ///
    /// ```
    /// use rasterproof::fill::flood::Connectivity;
    /// assert_eq!(Connectivity::from_number(8), Some(Connectivity::Eight));
    /// assert_eq!(Connectivity::from_number(6), None);
    /// ```
    pub fn from_number(n: u32) -> Option<Connectivity> {
        match n {
            4 => Some(Connectivity::Four),
            8 => Some(Connectivity::Eight),
            _ => None,
        }
    }

    /// The offsets `(dx, dy)` of the neighbours, in the order up, down, left, right, then
    /// (for eight) the corners clockwise from the top left.
    pub fn offsets(self) -> &'static [(i32, i32)] {
        const OFFSETS: [(i32, i32); 8] = [(0, -1), (0, 1), (-1, 0), (1, 0), (-1, -1), (1, -1), (1, 1), (-1, 1)];
        match self {
            Connectivity::Four => &OFFSETS[..4],
            Connectivity::Eight => &OFFSETS,
        }
    }

    /// How far past each end of a run the rows above and below must be searched.
    fn reach(self) -> u32 {
        match self {
            Connectivity::Four => 0,
            Connectivity::Eight => 1,
        }
    }
}

impl fmt::Display for Connectivity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}-connected", self.number())
    }
}

/// The seed pixel lies outside the image.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SeedOutside {
    /// The seed `(x, y)`.
    pub seed: (u32, u32),
    /// The image width.
    pub width: u32,
    /// The image height.
    pub height: u32,
}

impl fmt::Display for SeedOutside {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let ((x, y), w, h) = (self.seed, self.width, self.height);
        write!(
            f,
            "seed ({x}, {y}) is outside the {w}x{h} image (x must be in 0..{w}, y in 0..{h})"
        )
    }
}

impl std::error::Error for SeedOutside {}

/// A set of pixels of a `width` x `height` image, one bit per pixel.
///
/// # Guarantees
/// - [`Region::len`] is the number of pixels in the set.
/// - [`Region::iter`] yields each pixel once, in row-major order (y, then x), all inside
///   `width` x `height`.
///
/// Two regions are equal when they have the same size and the same pixels. `Debug` draws
/// a region of at most 64x64 pixels as rows of `#` (in) and `.` (out).
#[derive(Clone, PartialEq, Eq)]
pub struct Region {
    width: u32,
    height: u32,
    /// Bit `i % 64` of word `i / 64` is pixel `i = y * width + x`.
    words: Vec<u64>,
    len: usize,
}

impl Region {
    /// The empty region of a `width` x `height` image.
    pub fn empty(width: u32, height: u32) -> Region {
        let pixels = width as usize * height as usize;
        Region {
            width,
            height,
            words: vec![0; pixels.div_ceil(64)],
            len: 0,
        }
    }

    /// The pixels `(x, y)` of a `width` x `height` image for which `inside(x, y)` holds.
    ///
    /// ```
    /// use rasterproof::fill::flood::Region;
    /// let diagonal = Region::from_fn(3, 3, |x, y| x == y);
    /// assert_eq!(diagonal.len(), 3);
    /// assert!(diagonal.contains(2, 2) && !diagonal.contains(2, 1));
    /// ```
    pub fn from_fn(width: u32, height: u32, mut inside: impl FnMut(u32, u32) -> bool) -> Region {
        let mut region = Region::empty(width, height);
        for y in 0..height {
            for x in 0..width {
                if inside(x, y) {
                    region.insert(region.index(x, y));
                }
            }
        }
        region
    }

    /// The image width.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// The image height.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The number of pixels in the region.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when the region has no pixel.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Whether `(x, y)` is in the region (false outside the image).
    pub fn contains(&self, x: u32, y: u32) -> bool {
        x < self.width && y < self.height && self.bit(self.index(x, y))
    }

    /// The pixels `(x, y)`, row-major: by y, then by x.
    pub fn iter(&self) -> Pixels<'_> {
        Pixels {
            region: self,
            word: 0,
            bits: self.words.first().copied().unwrap_or(0),
        }
    }

    /// Whether every pixel of `self` is in `other` (false when the sizes differ).
    pub fn is_subset_of(&self, other: &Region) -> bool {
        (self.width, self.height) == (other.width, other.height)
            && self.words.iter().zip(&other.words).all(|(a, b)| a & !b == 0)
    }

    fn index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
    }

    fn bit(&self, i: usize) -> bool {
        self.words[i / 64] >> (i % 64) & 1 == 1
    }

    /// Adds pixel `i`; it must not be in the region yet.
    fn insert(&mut self, i: usize) {
        debug_assert!(!self.bit(i), "pixel {i} inserted twice");
        self.words[i / 64] |= 1 << (i % 64);
        self.len += 1;
    }

    /// Adds pixels `start..end` (by index), none of them in the region yet.
    fn insert_range(&mut self, start: usize, end: usize) {
        let mut i = start;
        while i < end {
            let (word, bit) = (i / 64, i % 64);
            let n = (64 - bit).min(end - i);
            let mask = if n == 64 { u64::MAX } else { ((1u64 << n) - 1) << bit };
            debug_assert_eq!(self.words[word] & mask, 0, "a pixel of {start}..{end} inserted twice");
            self.words[word] |= mask;
            i += n;
        }
        self.len += end - start;
    }
}

impl fmt::Debug for Region {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Region {}x{}, {} pixels", self.width, self.height, self.len)?;
        if self.width <= 64 && self.height <= 64 {
            for y in 0..self.height {
                f.write_str("\n")?;
                for x in 0..self.width {
                    f.write_str(if self.contains(x, y) { "#" } else { "." })?;
                }
            }
        }
        Ok(())
    }
}

/// The pixels of a [`Region`], row-major. Made by [`Region::iter`].
#[derive(Debug, Clone)]
pub struct Pixels<'a> {
    region: &'a Region,
    /// The word being read and its bits not yet yielded.
    word: usize,
    bits: u64,
}

impl Iterator for Pixels<'_> {
    type Item = (u32, u32);

    fn next(&mut self) -> Option<(u32, u32)> {
        while self.bits == 0 {
            self.word += 1;
            self.bits = *self.region.words.get(self.word)?;
        }
        let i = self.word * 64 + self.bits.trailing_zeros() as usize;
        self.bits &= self.bits - 1;
        let width = self.region.width as usize;
        // i < width * height, so both quotients fit the u32 sides.
        let (x, y) = (i % width, i / width);
        Some((
            u32::try_from(x).expect("x < width"),
            u32::try_from(y).expect("y < height"),
        ))
    }
}

impl<'a> IntoIterator for &'a Region {
    type Item = (u32, u32);
    type IntoIter = Pixels<'a>;

    fn into_iter(self) -> Pixels<'a> {
        self.iter()
    }
}

fn check_seed(image: &RgbaImage, seed: (u32, u32)) -> Result<(), SeedOutside> {
    let (width, height) = image.dimensions();
    if seed.0 < width && seed.1 < height {
        Ok(())
    } else {
        Err(SeedOutside { seed, width, height })
    }
}

/// The region of `seed` by breadth-first search: the oracle.
///
/// The seed is visited first; then, in queue order, every visited pixel's neighbours
/// (by [`Connectivity::offsets`]) that lie inside the image, are not yet visited, and have
/// exactly the seed's RGBA colour are visited and queued. The visited pixels are the
/// region. Memory: a flag per pixel and a queue of at most one entry per pixel.
///
/// ```
/// use image::{Rgba, RgbaImage};
/// use rasterproof::fill::flood::{bfs_region, Connectivity};
/// // Two white pixels touching only at a corner; black elsewhere.
/// //   # .
/// //   . #
/// let white = Rgba([255, 255, 255, 255]);
/// let img = RgbaImage::from_fn(2, 2, |x, y| if x == y { white } else { Rgba([0, 0, 0, 255]) });
/// assert_eq!(bfs_region(&img, (0, 0), Connectivity::Four).unwrap().len(), 1);
/// assert_eq!(bfs_region(&img, (0, 0), Connectivity::Eight).unwrap().len(), 2);
/// assert!(bfs_region(&img, (2, 0), Connectivity::Four).is_err());
/// ```
pub fn bfs_region(image: &RgbaImage, seed: (u32, u32), connectivity: Connectivity) -> Result<Region, SeedOutside> {
    check_seed(image, seed)?;
    let (width, height) = image.dimensions();
    let colour = *image.get_pixel(seed.0, seed.1);
    let index = |x: u32, y: u32| y as usize * width as usize + x as usize;
    let mut visited = vec![false; width as usize * height as usize];
    let mut queue = VecDeque::from([seed]);
    visited[index(seed.0, seed.1)] = true;
    while let Some((x, y)) = queue.pop_front() {
        for &(dx, dy) in connectivity.offsets() {
            let (Some(nx), Some(ny)) = (x.checked_add_signed(dx), y.checked_add_signed(dy)) else {
                continue; // left of column 0 or above row 0
            };
            if nx >= width || ny >= height || visited[index(nx, ny)] || *image.get_pixel(nx, ny) != colour {
                continue;
            }
            visited[index(nx, ny)] = true;
            queue.push_back((nx, ny));
        }
    }
    Ok(Region::from_fn(width, height, |x, y| visited[index(x, y)]))
}

/// The region of `seed` by span seed fill (Smith 1979, Heckbert 1990), with an explicit
/// stack and no recursion. Equal to [`bfs_region`] for every image, seed and connectivity
/// (tests/flood.rs and the `flood_fill` fuzz target check it); faster, and its stack holds
/// at most three entries per horizontal run of the region.
///
/// A seed pixel's colour is compared exactly, all four channels. The image is not changed.
///
/// ```
/// use image::{Rgba, RgbaImage};
/// use rasterproof::fill::flood::{span_region, Connectivity};
/// // A ring of # with a diagonal gap at its lower right corner (x right, y down):
/// //
/// //   y=0  . . . . .
/// //   y=1  . # # # .
/// //   y=2  . # o # .      o = the seed (2, 2), a . like the others
/// //   y=3  . # # . .      (3, 3) is the gap: a . diagonal to the seed
/// //   y=4  . . . . .
/// //
/// // Four: the seed's up, down, left and right neighbours are all #, so the region is the
/// // seed alone: 1 pixel. Eight: the seed reaches (3, 3) through the corner, and (3, 3)
/// // reaches the outside. Counting by hand: 25 pixels - 7 # = 18 dots, all of them.
/// // The outside alone (seed (0, 0), four) is 18 - 1 = 17; the ring is 7 either way.
/// let (dot, hash) = (Rgba([255, 255, 255, 255]), Rgba([0, 0, 0, 255]));
/// let ring = [(1, 1), (2, 1), (3, 1), (1, 2), (3, 2), (1, 3), (2, 3)];
/// let img = RgbaImage::from_fn(5, 5, |x, y| if ring.contains(&(x, y)) { hash } else { dot });
/// assert_eq!(span_region(&img, (2, 2), Connectivity::Four).unwrap().len(), 1);
/// assert_eq!(span_region(&img, (2, 2), Connectivity::Eight).unwrap().len(), 18);
/// assert_eq!(span_region(&img, (0, 0), Connectivity::Four).unwrap().len(), 17);
/// assert!(!span_region(&img, (0, 0), Connectivity::Four).unwrap().contains(2, 2));
/// assert_eq!(span_region(&img, (1, 1), Connectivity::Four).unwrap().len(), 7);
/// ```
pub fn span_region(image: &RgbaImage, seed: (u32, u32), connectivity: Connectivity) -> Result<Region, SeedOutside> {
    check_seed(image, seed)?;
    let (width, height) = image.dimensions();
    let mut fill = SpanFill {
        raw: image.as_raw(),
        width,
        height,
        colour: image.get_pixel(seed.0, seed.1).0,
        reach: connectivity.reach(),
        region: Region::empty(width, height),
        stack: Vec::new(),
    };
    fill.run(seed);
    Ok(fill.region)
}

/// Row `y`, pixels `lo..=hi`, still to search; reached from the filled run
/// `parent.0..=parent.1` of the row before it (`y - 1` when going `down`, else `y + 1`).
#[derive(Debug, Clone, Copy)]
struct Span {
    y: u32,
    lo: u32,
    hi: u32,
    down: bool,
    parent: (u32, u32),
}

/// The state of one [`span_region`] call.
struct SpanFill<'a> {
    /// The image's RGBA8 bytes, row-major.
    raw: &'a [u8],
    width: u32,
    height: u32,
    /// The seed's colour.
    colour: [u8; 4],
    /// 0 for four neighbours, 1 for eight.
    reach: u32,
    /// The pixels filled so far.
    region: Region,
    /// The spans still to search.
    stack: Vec<Span>,
}

impl SpanFill<'_> {
    /// Has the seed's colour and is not filled yet.
    fn inside(&self, x: u32, y: u32) -> bool {
        let i = self.region.index(x, y);
        !self.region.bit(i) && self.raw[4 * i..4 * i + 4] == self.colour
    }

    fn run(&mut self, seed: (u32, u32)) {
        let (a, b) = self.fill_run(seed.0, seed.1);
        // The seed run is the parent of both rows beside it.
        self.push_row(seed.1, true, a, b, (a, b));
        self.push_row(seed.1, false, a, b, (a, b));
        while let Some(span) = self.stack.pop() {
            let mut x = span.lo;
            while x <= span.hi {
                if !self.inside(x, span.y) {
                    x += 1;
                    continue;
                }
                let (a, b) = self.fill_run(x, span.y);
                self.push_children(span, a, b);
                // b + 1 is outside the region (or the image): the next run starts later.
                x = b.saturating_add(2);
            }
        }
    }

    /// Fills the maximal run of inside pixels through `(x, y)` (an inside pixel) and
    /// returns its ends `(a, b)`, inclusive.
    fn fill_run(&mut self, x: u32, y: u32) -> (u32, u32) {
        let (mut a, mut b) = (x, x);
        while a > 0 && self.inside(a - 1, y) {
            a -= 1;
        }
        while b + 1 < self.width && self.inside(b + 1, y) {
            b += 1;
        }
        let row = self.region.index(0, y);
        self.region.insert_range(row + a as usize, row + b as usize + 1);
        (a, b)
    }

    /// Queues the stretch of the row after `y` (in direction `down`) that touches the run
    /// `a..=b` of row `y`: `a - reach ..= b + reach`, clipped to the image.
    fn push_row(&mut self, y: u32, down: bool, a: u32, b: u32, parent: (u32, u32)) {
        let next = if down { y.checked_add(1) } else { y.checked_sub(1) };
        let Some(next) = next.filter(|&n| n < self.height) else {
            return;
        };
        let lo = a.saturating_sub(self.reach);
        let hi = (b + self.reach).min(self.width - 1);
        self.stack.push(Span {
            y: next,
            lo,
            hi,
            down,
            parent,
        });
    }

    /// After filling the run `a..=b` found while searching `span`: queue the row ahead in
    /// full, and the row behind (the parent's row) only beyond the parent run, which is
    /// filled already. A run wider than its parent can touch pixels the parent could not
    /// (U-turns): they are the stretches past the parent's ends.
    fn push_children(&mut self, span: Span, a: u32, b: u32) {
        let y = span.y;
        self.push_row(y, span.down, a, b, (a, b));
        let back = if span.down { y.checked_sub(1) } else { y.checked_add(1) };
        let Some(back) = back.filter(|&n| n < self.height) else {
            return;
        };
        let lo = a.saturating_sub(self.reach);
        let hi = (b + self.reach).min(self.width - 1);
        let (parent_lo, parent_hi) = span.parent;
        let mut push = |lo: u32, hi: u32| {
            self.stack.push(Span {
                y: back,
                lo,
                hi,
                down: !span.down,
                parent: (a, b),
            });
        };
        if lo < parent_lo {
            push(lo, hi.min(parent_lo - 1));
        }
        if hi > parent_hi {
            push(lo.max(parent_hi + 1), hi);
        }
    }
}

/// Sets every pixel of `region` that lies inside `image` to `colour`.
pub fn paint(image: &mut RgbaImage, region: &Region, colour: Rgba<u8>) {
    let (width, height) = image.dimensions();
    for (x, y) in region {
        if x < width && y < height {
            image.put_pixel(x, y, colour);
        }
    }
}

/// Recolours the region of `seed` ([`span_region`]) with `colour` and returns its number
/// of pixels. Filling with the seed's own colour changes nothing (and still returns the
/// region's size).
///
/// ```
/// use image::{Rgba, RgbaImage};
/// use rasterproof::fill::flood::{flood_fill, Connectivity};
/// // A 3x2 image, black with one white pixel at (1, 0):
/// //   . # .
/// //   . . .
/// // Four-connected from (0, 0), the black region is the 5 other pixels.
/// let (black, white, red) = (Rgba([0, 0, 0, 255]), Rgba([255, 255, 255, 255]), Rgba([255, 0, 0, 255]));
/// let mut img = RgbaImage::from_pixel(3, 2, black);
/// img.put_pixel(1, 0, white);
/// assert_eq!(flood_fill(&mut img, (0, 0), Connectivity::Four, red).unwrap(), 5);
/// assert_eq!(*img.get_pixel(2, 0), red);
/// assert_eq!(*img.get_pixel(1, 0), white);
/// let before = img.clone();
/// assert_eq!(flood_fill(&mut img, (0, 1), Connectivity::Four, red).unwrap(), 5);
/// assert_eq!(img, before);
/// ```
pub fn flood_fill(
    image: &mut RgbaImage,
    seed: (u32, u32),
    connectivity: Connectivity,
    colour: Rgba<u8>,
) -> Result<usize, SeedOutside> {
    let region = span_region(image, seed, connectivity)?;
    paint(image, &region, colour);
    Ok(region.len())
}

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

    #[test]
    fn region_bits_span_word_boundaries() {
        let mut r = Region::empty(130, 1);
        r.insert_range(60, 129);
        assert_eq!(r.len(), 69);
        assert_eq!(r.iter().count(), 69);
        assert_eq!(r.iter().next(), Some((60, 0)));
        assert_eq!(r.iter().last(), Some((128, 0)));
        assert!(!r.contains(59, 0) && !r.contains(129, 0) && r.contains(64, 0));
        assert_eq!(r, Region::from_fn(130, 1, |x, _| (60..129).contains(&x)));
    }

    #[test]
    fn empty_image_regions() {
        let r = Region::empty(0, 5);
        assert!(r.is_empty());
        assert_eq!(r.iter().next(), None);
        assert!(!r.contains(0, 0));
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
