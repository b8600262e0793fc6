//! Flood fill on a raster (Smith 1979, Heckbert 1990): the 4- or 8-connected region of pixels whose RGBA
//! colour equals a seed pixel's exactly, found by a span (scanline) seed fill with an
//! explicit stack, with a plain breadth-first search beside it as the oracle.
//!
//! The textbook brute force (Foley, van Dam et al.), in a lecture's words: starting at
//! the seed, recursively, "is the current point's colour the seed point's colour? no ->
//! stop; yes -> recolour it and restart for every neighbour" (four neighbours: up,
//! down, left, right; eight: those and the corners); the lecture warns that "recursion
//! is very crude". It is: one call per pixel, nested as deep as the region is long, so
//! a 4096x4096 region overflows any thread's stack. Nothing here recurses.
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

use image::{Rgba, RgbaImage};

mod png;
mod region;

pub use png::{decode_png, decode_png_as_decoded, decode_png_within, load_png, PngError, MAX_IMAGE_SIDE};
pub use region::{Pixels, Region};

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
        self.push_row(seed.1, true, a, b);
        self.push_row(seed.1, false, a, b);
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
    fn push_row(&mut self, y: u32, down: bool, a: u32, b: u32) {
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
            parent: (a, b),
        });
    }

    /// After filling the run `a..=b` found while searching `span`: queue the row ahead in
    /// full, and the row behind (the parent's row) only beyond the parent run, which is
    /// filled already. A run wider than its parent can touch pixels the parent could not
    /// (U-turns): they are the stretches past the parent's ends.
    fn push_children(&mut self, span: Span, a: u32, b: u32) {
        let y = span.y;
        self.push_row(y, span.down, a, b);
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
    if (width, height) != (region.width(), region.height()) {
        for (x, y) in region {
            if x < width && y < height {
                image.put_pixel(x, y, colour);
            }
        }
        return;
    }
    // Same size: write the RGBA bytes of each index directly.
    let raw: &mut [u8] = image;
    let mut pixels = region.iter();
    while let Some(i) = pixels.next_index() {
        raw[4 * i..4 * i + 4].copy_from_slice(&colour.0);
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

/// `rasterproof flood`'s one-line summary of the `connectivity` region of `seed` in the
/// image named `file` (no newline): its pixel count, the seed and the image size (the
/// region's), then, when it was `recoloured` into an image file, the colour and the path.
///
/// ```
/// use image::Rgba;
/// use rasterproof::fill::flood::{region_summary, Connectivity, Region};
/// let region = Region::from_fn(3, 2, |x, _| x > 0);
/// assert_eq!(
///     region_summary("in.png", &region, (1, 0), Connectivity::Four, None),
///     "in.png: 4 pixels in the 4-connected region of (1, 0) (3x2 image)"
/// );
/// let out = std::path::Path::new("out.png");
/// assert_eq!(
///     region_summary("in.png", &region, (1, 0), Connectivity::Eight, Some((Rgba([255, 0, 0, 255]), out))),
///     "in.png: 4 pixels in the 8-connected region of (1, 0) (3x2 image), recoloured 255,0,0,255 into out.png"
/// );
/// ```
pub fn region_summary(
    file: &str,
    region: &Region,
    seed: (u32, u32),
    connectivity: Connectivity,
    recoloured: Option<(Rgba<u8>, &std::path::Path)>,
) -> String {
    let mut summary = format!(
        "{file}: {} pixel{} in the {connectivity} region of ({}, {}) ({}x{} image)",
        region.len(),
        if region.len() == 1 { "" } else { "s" },
        seed.0,
        seed.1,
        region.width(),
        region.height()
    );
    if let Some((colour, path)) = recoloured {
        let [r, g, b, a] = colour.0;
        summary.push_str(&format!(", recoloured {r},{g},{b},{a} into {}", path.display()));
    }
    summary
}

/// `rasterproof flood --format json`: the `connectivity` region of `seed` as one line of
/// JSON with its newline,
/// `{"width":W,"height":H,"at":[x,y],"connectivity":4,"pixels":[[x,y],...]}`, the pixels
/// row-major (by y, then x), streamed to `out`.
///
/// ```
/// use rasterproof::fill::flood::{write_region_json, Connectivity, Region};
/// let region = Region::from_fn(3, 2, |x, y| x == y);
/// let mut out = Vec::new();
/// write_region_json(&mut out, &region, (0, 0), Connectivity::Eight).unwrap();
/// assert_eq!(
///     String::from_utf8(out).unwrap(),
///     "{\"width\":3,\"height\":2,\"at\":[0,0],\"connectivity\":8,\"pixels\":[[0,0],[1,1]]}\n"
/// );
/// ```
///
/// # Errors
/// Writing to `out` fails.
pub fn write_region_json(
    out: &mut dyn std::io::Write,
    region: &Region,
    seed: (u32, u32),
    connectivity: Connectivity,
) -> std::io::Result<()> {
    write!(
        out,
        "{{\"width\":{},\"height\":{},\"at\":[{},{}],\"connectivity\":{},\"pixels\":[",
        region.width(),
        region.height(),
        seed.0,
        seed.1,
        connectivity.number()
    )?;
    for (k, (x, y)) in region.iter().enumerate() {
        if k > 0 {
            out.write_all(b",")?;
        }
        write!(out, "[{x},{y}]")?;
    }
    out.write_all(b"]}\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A region of another size paints only the pixels inside the image.
    #[test]
    fn paint_clips_a_region_of_another_size() {
        let (black, red) = (Rgba([0, 0, 0, 255]), Rgba([255, 0, 0, 255]));
        let mut img = RgbaImage::from_pixel(3, 2, black);
        paint(&mut img, &Region::from_fn(4, 4, |x, y| x == y), red);
        let painted: Vec<(u32, u32)> = img
            .enumerate_pixels()
            .filter(|p| *p.2 == red)
            .map(|p| (p.0, p.1))
            .collect();
        assert_eq!(painted, [(0, 0), (1, 1)]);
        paint(&mut img, &Region::from_fn(3, 2, |x, _| x == 2), red);
        assert_eq!(img.pixels().filter(|p| **p == red).count(), 4);
    }
}
