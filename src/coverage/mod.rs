//! The output every model writes: which primitives cover which pixel. Models write through
//! the [`CoverageSink`] trait; [`Coverage`] keeps the owner list of every covered pixel
//! (in 64x64 tiles allocated on demand, so memory follows the touched area) and writes the
//! JSON interface as a stream; [`CountBuffer`] only counts (for benchmarks). The ids PNG
//! for programs is in [`ids`]. Pictures for people (the palette, the
//! scaled PNG, its legend, the ASCII grid) are in [`picture`].

use std::collections::BTreeMap;
use std::fmt;

pub mod ids;
mod json;
pub mod picture;
pub mod samples;
mod tiles;

pub(crate) use tiles::Spare;
use tiles::TileGrid;

pub use ids::IdOutOfRange;

pub use tiles::TILE;

pub use picture::{primitive_colour, IdRun, Scale, ScaleError, ASCII_GRID_MAX_SIDE, DOUBLE_COVER_COLOUR};

/// Where a rasterizer writes covered pixels.
pub trait CoverageSink {
    /// Pixel `(x, y)` is covered by primitive `id`.
    fn cover(&mut self, x: u32, y: u32, id: u32);

    /// Pixels `x0..=x1` of row `y` are covered by primitive `id`.
    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, id: u32) {
        for x in x0..=x1 {
            self.cover(x, y, id);
        }
    }

    /// Pixel `x0 + i` of row `y` is covered by primitive `id` for every set bit `i` of
    /// `mask` (none when it is 0; a set bit is always a pixel of the canvas). What the
    /// block traversals write, one row of at most 32 pixels at a time: a sink that can
    /// add a whole mask without a branch per pixel overrides it; by default each run of
    /// set bits is one [`CoverageSink::cover_span`].
    #[inline]
    fn cover_mask(&mut self, y: u32, x0: u32, mask: u32, id: u32) {
        let mut rest = mask;
        while rest != 0 {
            let first = rest.trailing_zeros();
            // the run of set bits from `first`
            let len = (!(rest >> first)).trailing_zeros();
            self.cover_span(y, x0 + first, x0 + first + len - 1, id);
            let end = first + len;
            rest = if end >= u32::BITS { 0 } else { rest >> end << end };
        }
    }

    /// Whether the triangle traversals should hand this sink masks
    /// ([`CoverageSink::cover_mask`], [`CoverageSink::cover_block`]): `true` for a sink
    /// that overrides those two with something faster than a span per run of set bits (a
    /// SIMD or SWAR add of the mask), which then gets the block traversal's masks.
    /// `false` by default, for a sink of pixels and spans: a triangle within one 8x8
    /// block then reaches it pixel by pixel ([`CoverageSink::cover`]), and a larger one
    /// of the integer engines (`fixed`, and the planned engine's triangles on the subpixel
    /// grid) as one [`CoverageSink::cover_span`] per row, walked along its edges. The
    /// pixels are the same either way; only the calls differ.
    #[inline]
    fn prefers_masks(&self) -> bool {
        false
    }

    /// The masks of up to eight consecutive rows of at most eight pixels at once, byte `i`
    /// of `block` being row `y0 + i`'s [`CoverageSink::cover_mask`] (bit `8 i + j` covers
    /// pixel `(x0 + j, y0 + i)`; a set bit is always a pixel of the canvas, and the rows
    /// past the last non-zero byte may not exist). What the block traversals write for a
    /// block the triangle's edges cross: a sink that can step from row to row without
    /// finding each row again overrides it; by default each non-zero byte is one
    /// `cover_mask`.
    #[inline]
    fn cover_block(&mut self, y0: u32, x0: u32, block: u64, id: u32) {
        let mut rest = block;
        let mut y = y0;
        while rest != 0 {
            let row = u32::from(rest.to_le_bytes()[0]);
            if row != 0 {
                self.cover_mask(y, x0, row, id);
            }
            rest >>= 8;
            y += 1;
        }
    }
}

/// A sink that passes on only the pixels of rows `y0..y1` (a band of the canvas): what
/// each thread of a parallel render draws through, so that the thread owns its rows.
pub struct RowBand<'a, S: CoverageSink + ?Sized> {
    sink: &'a mut S,
    y0: u32,
    y1: u32,
}

impl<'a, S: CoverageSink + ?Sized> RowBand<'a, S> {
    /// The rows `y0..y1` of `sink`.
    pub fn new(sink: &'a mut S, y0: u32, y1: u32) -> RowBand<'a, S> {
        RowBand { sink, y0, y1 }
    }

    #[inline]
    fn holds(&self, y: u32) -> bool {
        (self.y0..self.y1).contains(&y)
    }
}

impl<S: CoverageSink + ?Sized> CoverageSink for RowBand<'_, S> {
    #[inline]
    fn prefers_masks(&self) -> bool {
        self.sink.prefers_masks()
    }

    #[inline]
    fn cover(&mut self, x: u32, y: u32, id: u32) {
        if self.holds(y) {
            self.sink.cover(x, y, id);
        }
    }

    #[inline]
    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, id: u32) {
        if self.holds(y) {
            self.sink.cover_span(y, x0, x1, id);
        }
    }

    #[inline]
    fn cover_mask(&mut self, y: u32, x0: u32, mask: u32, id: u32) {
        if self.holds(y) {
            self.sink.cover_mask(y, x0, mask, id);
        }
    }

    #[inline]
    fn cover_block(&mut self, y0: u32, x0: u32, block: u64, id: u32) {
        // Byte i is row y0 + i: keep the bytes of the band's rows, and start the block at
        // its first kept row.
        let skip = self.y0.saturating_sub(y0);
        let keep = self.y1.saturating_sub(y0);
        if skip >= 8 || keep <= skip {
            return;
        }
        let mut b = block >> (8 * skip);
        let rows = keep - skip;
        if rows < 8 {
            b &= (1u64 << (8 * rows)) - 1;
        }
        if b != 0 {
            self.sink.cover_block(y0 + skip, x0, b, id);
        }
    }
}

/// The largest primitive id a [`Coverage`] takes: `u32::MAX - 2` (the two values above it
/// mark a pixel's slot as uncovered or shared). Scenes stay far below it: a scene file has
/// at most `scene::parse::MAX_TRIANGLES` (10^7) primitives, ids `0..` in file order.
pub const MAX_ID: u32 = tiles::SHARED - 1;

/// The covering primitive ids of every covered pixel. Memory follows the touched area: one
/// `u32` per pixel in 64x64 tiles allocated on demand (an empty 16384² coverage holds no
/// tile), the owner stored in the pixel's slot, and the pixels with two or more owners in
/// a side table (ids ascending, repeats kept: a model that covers a pixel twice for one
/// primitive is reported, not hidden).
///
/// # Guarantees
/// - every id is at most [`MAX_ID`] ([`CoverageSink::cover`] panics beyond it);
/// - a tile is allocated iff a pixel in it is covered, so two coverages with the same
///   owners are equal whatever order they were drawn in.
#[derive(Clone, PartialEq, Eq)]
pub struct Coverage {
    width: u32,
    height: u32,
    /// The owner of each pixel with one owner; [`tiles::SHARED`] where `shared` has them.
    tiles: TileGrid,
    /// Keyed by (y, x): the owners of each pixel with two or more, ascending.
    shared: BTreeMap<(u32, u32), Vec<u32>>,
    /// The number of covered pixels.
    covered: usize,
}

impl fmt::Debug for Coverage {
    /// `Coverage { width, height, pixels: {(y, x): [ids], ...} }`, covered pixels only.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let pixels = PixelsDebug(self);
        f.debug_struct("Coverage")
            .field("width", &self.width)
            .field("height", &self.height)
            .field("pixels", &pixels)
            .finish()
    }
}

/// The covered pixels of a coverage as a `{(y, x): [ids]}` map, for `Debug`.
struct PixelsDebug<'a>(&'a Coverage);

impl fmt::Debug for PixelsDebug<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_map()
            .entries(self.0.iter().map(|(x, y, ids)| ((y, x), ids)))
            .finish()
    }
}

/// Adds `id` to the owners of `(x, y)`, whose slot is `slot`.
fn add_owner(
    slot: &mut u32,
    (x, y): (u32, u32),
    id: u32,
    shared: &mut BTreeMap<(u32, u32), Vec<u32>>,
    covered: &mut usize,
) {
    match *slot {
        tiles::EMPTY => {
            *slot = id;
            *covered += 1;
        }
        tiles::SHARED => {
            let ids = shared.get_mut(&(y, x)).expect("a shared slot has its owner list");
            let at = ids.partition_point(|&i| i <= id);
            ids.insert(at, id);
        }
        first => {
            shared.insert((y, x), vec![first.min(id), first.max(id)]);
            *slot = tiles::SHARED;
        }
    }
}

impl CoverageSink for Coverage {
    /// # Panics
    /// `id` above [`MAX_ID`], or `(x, y)` off the canvas.
    #[inline]
    fn cover(&mut self, x: u32, y: u32, id: u32) {
        self.cover_span(y, x, x, id);
    }

    /// Fills the row a tile at a time.
    ///
    /// # Panics
    /// `id` above [`MAX_ID`], or the span off the canvas.
    #[inline]
    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, id: u32) {
        assert!(id <= MAX_ID, "primitive id {id} above the largest, {MAX_ID}");
        assert!(
            x0 > x1 || (x1 < self.width && y < self.height),
            "({x1},{y}) off the canvas"
        );
        let (shared, covered) = (&mut self.shared, &mut self.covered);
        self.tiles.row_mut(y, x0, x1, |first, slots| {
            // Most writes land on pixels nobody covers yet: one comparison of the run
            // and one fill, which the compiler turns into vector code.
            if slots.iter().all(|&s| s == tiles::EMPTY) {
                slots.fill(id);
                *covered += slots.len();
                return;
            }
            for (x, slot) in (first..).zip(slots) {
                add_owner(slot, (x, y), id, shared, covered);
            }
        });
    }
}

impl Coverage {
    /// An empty coverage of a `width` x `height` canvas.
    pub fn new(width: u32, height: u32) -> Coverage {
        Coverage::with_spare(width, height, Spare::default())
    }

    /// An empty coverage that writes into `spare`'s tiles before it asks for memory.
    pub(crate) fn with_spare(width: u32, height: u32, spare: Spare) -> Coverage {
        Coverage {
            width,
            height,
            tiles: TileGrid::with_spare(width, height, spare),
            shared: BTreeMap::new(),
            covered: 0,
        }
    }

    /// This coverage's tiles, for the next one ([`Coverage::with_spare`]).
    pub(crate) fn into_spare(self) -> Spare {
        self.tiles.into_spare()
    }

    /// Canvas width.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Canvas height.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The owner list that slot `slot` of `(x, y)` stands for.
    fn owners_of<'a>(&'a self, slot: &'a u32, x: u32, y: u32) -> &'a [u32] {
        match *slot {
            tiles::EMPTY => &[],
            tiles::SHARED => &self.shared[&(y, x)],
            _ => std::slice::from_ref(slot),
        }
    }

    /// The ids covering `(x, y)`, ascending; empty when uncovered (or off the canvas).
    pub fn owners(&self, x: u32, y: u32) -> &[u32] {
        if x >= self.width || y >= self.height {
            return &[];
        }
        self.owners_of(self.tiles.get(x, y), x, y)
    }

    /// Covered pixels as `(x, y, ids)`, sorted by y then x.
    pub fn iter(&self) -> impl Iterator<Item = (u32, u32, &[u32])> + '_ {
        (0..self.height)
            .filter(|&y| self.tiles.row_touched(y))
            .flat_map(move |y| {
                self.tiles
                    .row(y)
                    .map(move |(x, slot)| (x, y, self.owners_of(slot, x, y)))
            })
    }

    /// The number of covered pixels.
    pub fn covered_pixels(&self) -> usize {
        self.covered
    }

    /// Takes over the rows `y0..y1` of `band`, a coverage of the same canvas that covers
    /// nothing outside them (drawn through [`RowBand`]), into this one, which covers
    /// nothing inside them: the parallel render's merge. `y0` is a multiple of the tile
    /// side [`tiles::TILE`] and `y1` one too or the canvas height, so whole tiles move.
    ///
    /// # Panics
    /// A different canvas, or rows not on tile boundaries.
    pub fn absorb_rows(&mut self, band: Coverage, y0: u32, y1: u32) {
        assert_eq!((self.width, self.height), (band.width, band.height), "one canvas");
        self.tiles.take_rows(band.tiles, y0, y1);
        self.shared.extend(band.shared);
        self.covered += band.covered;
    }

    /// Pixels covered more than once, as `(x, y, ids)`, sorted by y then x.
    pub fn double_covered(&self) -> impl Iterator<Item = (u32, u32, &[u32])> + '_ {
        self.shared.iter().map(|(&(y, x), ids)| (x, y, ids.as_slice()))
    }

    /// The number of allocated 64x64 tiles (what the coverage costs beyond its grid).
    #[doc(hidden)]
    pub fn allocated_tiles(&self) -> usize {
        self.tiles.allocated()
    }

    /// Adds every id of `ids` (ascending) to `(x, y)`.
    fn cover_all(&mut self, x: u32, y: u32, ids: &[u32]) {
        for &id in ids {
            self.cover(x, y, id);
        }
    }

    /// The coverage moved by whole pixels, dropping what leaves the canvas.
    pub fn translated(&self, dx: i64, dy: i64) -> Coverage {
        let mut out = Coverage::new(self.width, self.height);
        for (x, y, ids) in self.iter() {
            let (nx, ny) = (i64::from(x) + dx, i64::from(y) + dy);
            if let (Ok(nx), Ok(ny)) = (u32::try_from(nx), u32::try_from(ny)) {
                if nx < self.width && ny < self.height {
                    out.cover_all(nx, ny, ids);
                }
            }
        }
        out
    }

    /// Only the pixels inside the rectangle `[x0, x1) x [y0, y1)`.
    pub fn restricted(&self, x0: u32, y0: u32, x1: u32, y1: u32) -> Coverage {
        let mut out = Coverage::new(self.width, self.height);
        for (x, y, ids) in self.iter() {
            if (x0..x1).contains(&x) && (y0..y1).contains(&y) {
                out.cover_all(x, y, ids);
            }
        }
        out
    }
}

/// A dense per-pixel count, the cheapest sink: what the benchmarks write into.
#[derive(Debug, Clone)]
pub struct CountBuffer {
    width: u32,
    counts: Vec<u32>,
}

impl CountBuffer {
    /// A zeroed buffer for a `width` x `height` canvas.
    pub fn new(width: u32, height: u32) -> CountBuffer {
        CountBuffer {
            width,
            counts: vec![0; width as usize * height as usize],
        }
    }

    /// How many times `(x, y)` was covered.
    pub fn count(&self, x: u32, y: u32) -> u32 {
        self.counts[y as usize * self.width as usize + x as usize]
    }

    /// The sum of all counts (covered pixel-primitive pairs).
    pub fn total(&self) -> u64 {
        self.counts.iter().map(|&c| u64::from(c)).sum()
    }
}

impl CoverageSink for CountBuffer {
    /// Its [`CoverageSink::cover_mask`] adds a mask without a branch per pixel.
    #[inline]
    fn prefers_masks(&self) -> bool {
        true
    }

    #[inline]
    fn cover(&mut self, x: u32, y: u32, _id: u32) {
        self.counts[y as usize * self.width as usize + x as usize] += 1;
    }

    #[inline]
    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, _id: u32) {
        let row = y as usize * self.width as usize;
        for c in &mut self.counts[row + x0 as usize..=row + x1 as usize] {
            *c += 1;
        }
    }

    /// Adds each bit of the mask to its pixel, without a branch per pixel (8 pixels at a
    /// time while the row has them).
    #[inline]
    fn cover_mask(&mut self, y: u32, x0: u32, mask: u32, _id: u32) {
        let row = y as usize * self.width as usize;
        let cells = &mut self.counts[row + x0 as usize..row + self.width as usize];
        let mut rest = mask;
        for chunk in cells.chunks_mut(8) {
            if rest == 0 {
                break;
            }
            for c in chunk.iter_mut() {
                *c += rest & 1;
                rest >>= 1;
            }
        }
        debug_assert_eq!(rest, 0, "a mask bit beyond the canvas");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A span over pixels partly covered already, across a tile boundary (x 64): the new
    /// owner joins each pixel's list, the pixels nobody covered get it alone, and the count
    /// of covered pixels grows by those only.
    #[test]
    fn a_span_over_covered_pixels_keeps_their_owners() {
        let mut c = Coverage::new(100, 2);
        c.cover(66, 1, 0);
        c.cover_span(1, 70, 71, 3);
        c.cover_span(1, 60, 70, 7);
        assert_eq!(c.covered_pixels(), 12);
        for x in 60..=70 {
            let expected: &[u32] = match x {
                66 => &[0, 7],
                70 => &[3, 7],
                _ => &[7],
            };
            assert_eq!(c.owners(x, 1), expected, "x {x}");
        }
        assert_eq!(c.owners(71, 1), &[3]);
        assert!(c.owners(59, 1).is_empty() && c.owners(66, 0).is_empty());
        assert_eq!(c.double_covered().count(), 2);
    }

    #[test]
    fn owners_stay_sorted_and_repeats_are_kept() {
        let mut c = Coverage::new(2, 2);
        c.cover(1, 1, 5);
        c.cover(1, 1, 2);
        c.cover(1, 1, 5);
        assert_eq!(c.owners(1, 1), &[2, 5, 5]);
        assert_eq!(c.owners(0, 0), &[] as &[u32]);
        assert_eq!(c.double_covered().count(), 1);
    }

    #[test]
    fn spans_and_counts_agree() {
        let mut a = CountBuffer::new(5, 2);
        a.cover_span(1, 1, 3, 0);
        a.cover(2, 1, 1);
        assert_eq!(
            (a.count(0, 1), a.count(1, 1), a.count(2, 1), a.count(4, 1)),
            (0, 1, 2, 0)
        );
        assert_eq!(a.total(), 4);
    }

    /// A sink that records the spans it is given (the default `cover_mask`).
    #[derive(Default)]
    struct Spans(Vec<(u32, u32, u32)>);

    impl CoverageSink for Spans {
        fn cover(&mut self, x: u32, y: u32, _id: u32) {
            self.0.push((y, x, x));
        }
        fn cover_span(&mut self, y: u32, x0: u32, x1: u32, _id: u32) {
            self.0.push((y, x0, x1));
        }
    }

    /// The default `cover_mask`: each run of set bits is one span, by hand.
    #[test]
    fn a_mask_is_its_runs_of_set_bits() {
        let spans = |mask: u32| {
            let mut s = Spans::default();
            s.cover_mask(3, 10, mask, 0);
            s.0
        };
        assert_eq!(spans(0), vec![]);
        assert_eq!(spans(1), vec![(3, 10, 10)]);
        // 0b1011_0110: bits 1-2, 4-5, 7
        assert_eq!(spans(0b1011_0110), vec![(3, 11, 12), (3, 14, 15), (3, 17, 17)]);
        assert_eq!(spans(0x8000_0000), vec![(3, 41, 41)]);
        assert_eq!(spans(u32::MAX), vec![(3, 10, 41)]);
        assert_eq!(spans(0xF000_000F), vec![(3, 10, 13), (3, 38, 41)]);
    }

    /// The default `cover_block`: byte `i` is row `y0 + i`'s mask, zero bytes write
    /// nothing, and nothing past the last non-zero byte is touched (by hand).
    #[test]
    fn a_block_is_its_rows_masks() {
        let spans = |block: u64| {
            let mut s = Spans::default();
            s.cover_block(5, 10, block, 0);
            s.0
        };
        assert_eq!(spans(0), vec![]);
        assert_eq!(spans(1), vec![(5, 10, 10)]);
        // row 0: 0b0000_0101 (pixels 10, 12); row 1: none; row 2: 0xff (10..=17)
        assert_eq!(spans(0x00ff_0005), vec![(5, 10, 10), (5, 12, 12), (7, 10, 17)]);
        // the last row's top bit: pixel (17, 12)
        assert_eq!(spans(0x8000_0000_0000_0000), vec![(12, 17, 17)]);
        assert_eq!(spans(u64::MAX).len(), 8);
        assert_eq!(spans(u64::MAX)[7], (12, 10, 17));
    }

    /// `CountBuffer::cover_mask` adds exactly the mask's bits, up to the row's last pixel
    /// (masks ending there, and one in the middle of the row).
    #[test]
    fn count_buffer_masks_add_their_bits() {
        for (x0, mask) in [
            (0u32, 0b1u32),
            (3, 0b1110_0111),
            (30, 0b11),
            (20, 0xFFF),
            (0, u32::MAX),
            (0, 0x8000_0001),
        ] {
            let mut a = CountBuffer::new(32, 2);
            let mut b = CountBuffer::new(32, 2);
            a.cover_mask(1, x0, mask, 0);
            for i in 0..32 {
                if mask >> i & 1 == 1 {
                    b.cover(x0 + i, 1, 0);
                }
            }
            assert_eq!(a.counts, b.counts, "mask {mask:#b} at {x0}");
            assert_eq!(a.total(), u64::from(mask.count_ones()));
        }
    }

    #[test]
    fn translation_drops_what_leaves() {
        let mut c = Coverage::new(3, 3);
        c.cover(0, 0, 0);
        c.cover(2, 2, 1);
        let t = c.translated(1, 0);
        assert_eq!(t.owners(1, 0), &[0]);
        assert_eq!(t.covered_pixels(), 1);
    }

    #[test]
    fn tile_boundaries_63_and_64() {
        let mut c = Coverage::new(130, 70);
        c.cover_span(63, 60, 70, 1);
        c.cover(63, 64, 2);
        c.cover(64, 63, 3);
        assert_eq!(c.allocated_tiles(), 3);
        let row: Vec<u32> = c.iter().filter(|p| p.1 == 63).map(|p| p.0).collect();
        assert_eq!(row, (60..=70).collect::<Vec<_>>());
        assert_eq!((c.owners(63, 63), c.owners(64, 63)), (&[1][..], &[1, 3][..]));
        assert_eq!((c.owners(63, 64), c.owners(64, 64)), (&[2][..], &[][..]));
        assert_eq!(c.covered_pixels(), 12);
    }

    #[test]
    fn the_last_partial_tile() {
        let mut c = Coverage::new(100, 65);
        c.cover_span(64, 0, 99, 9);
        assert_eq!(c.allocated_tiles(), 2);
        assert_eq!(c.owners(99, 64), &[9]);
        assert_eq!(c.owners(100, 64), &[] as &[u32]);
        assert_eq!(c.owners(99, 65), &[] as &[u32]);
        let xs: Vec<u32> = c
            .iter()
            .map(|(x, y, _)| {
                assert_eq!(y, 64);
                x
            })
            .collect();
        assert_eq!(xs, (0..100).collect::<Vec<_>>());
    }

    #[test]
    fn three_owners_of_one_pixel() {
        let mut c = Coverage::new(65, 65);
        c.cover(64, 64, 8);
        c.cover(64, 64, 3);
        c.cover_span(64, 0, 64, 8);
        assert_eq!(c.owners(64, 64), &[3, 8, 8]);
        assert_eq!(c.covered_pixels(), 65);
        let double: Vec<_> = c.double_covered().collect();
        assert_eq!(double, vec![(64, 64, &[3, 8, 8][..])]);
        assert_eq!(c.iter().last(), Some((64, 64, &[3, 8, 8][..])));
    }

    #[test]
    fn drawing_order_does_not_matter() {
        let mut a = Coverage::new(200, 100);
        let mut b = Coverage::new(200, 100);
        a.cover_span(10, 5, 150, 1);
        a.cover(70, 10, 0);
        a.cover(199, 99, 2);
        b.cover(199, 99, 2);
        b.cover(70, 10, 0);
        for x in (5..=150).rev() {
            b.cover(x, 10, 1);
        }
        assert_eq!(a, b);
        assert_eq!(format!("{a:?}"), format!("{b:?}"));
        b.cover(0, 0, 0);
        assert_ne!(a, b);
    }

    #[test]
    fn an_empty_large_coverage_has_no_tiles() {
        let c = Coverage::new(16384, 16384);
        assert_eq!(c.allocated_tiles(), 0);
        assert_eq!((c.iter().count(), c.covered_pixels()), (0, 0));
        assert_eq!(c.to_json(), r#"{"width":16384,"height":16384,"pixels":[]}"#);
    }

    #[test]
    fn debug_lists_pixels_as_before() {
        let mut c = Coverage::new(3, 2);
        c.cover(2, 1, 4);
        c.cover(2, 1, 1);
        assert_eq!(
            format!("{c:?}"),
            "Coverage { width: 3, height: 2, pixels: {(1, 2): [1, 4]} }"
        );
    }

    #[test]
    fn streamed_json_equals_the_string() {
        let mut big = Coverage::new(300, 200);
        for y in 0..200 {
            big.cover_span(y, y / 2, 299 - y, y % 7);
        }
        big.cover(150, 100, 9);
        let mut small = Coverage::new(4, 3);
        small.cover(2, 1, 7);
        small.cover(2, 1, 3);
        for c in [Coverage::new(1, 1), small, big.translated(-3, 5), big] {
            let mut out = Vec::new();
            c.write_json(&mut out).unwrap();
            assert_eq!(out, c.to_json().as_bytes());
        }
    }

    #[test]
    fn restriction_keeps_the_inside() {
        let mut c = Coverage::new(130, 130);
        c.cover_span(64, 0, 129, 1);
        c.cover(64, 64, 2);
        let r = c.restricted(60, 60, 70, 70);
        assert_eq!(r.covered_pixels(), 10);
        assert_eq!(r.owners(64, 64), &[1, 2]);
        assert_eq!(r.allocated_tiles(), 2);
    }
}
