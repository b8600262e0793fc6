//! The storage under [`super::Coverage`]: one `u32` slot per pixel, in 64x64 tiles
//! allocated on the first write into them, so memory follows the touched area (a 16384²
//! canvas with one small triangle costs the grid of empty tile pointers, 512 KiB, and the
//! few tiles the triangle touches, 16 KiB each). 64x64 is the tile size of Mesa
//! llvmpipe's binned rasterizer.

/// The side of a tile in pixels.
pub const TILE: u32 = 64;
/// Slots per tile.
const TILE_AREA: usize = (TILE * TILE) as usize;

/// The slot value of an uncovered pixel.
pub const EMPTY: u32 = u32::MAX;
/// The slot value of a pixel with two or more owners, whose list lives beside the grid.
pub const SHARED: u32 = u32::MAX - 1;

/// One tile's slots, row-major.
type Tile = Box<[u32; TILE_AREA]>;

/// A `width` x `height` grid of slots, [`EMPTY`] until written.
pub struct TileGrid {
    /// Tiles across (`ceil(width / 64)`).
    across: usize,
    /// Row-major over the tile grid; `None` = every slot of the tile is [`EMPTY`].
    tiles: Vec<Option<Tile>>,
    /// Tiles of a grid that is done, written into before new memory is asked for; not
    /// part of the grid's value.
    spare: Spare,
}

/// The tiles a finished grid leaves ([`TileGrid::into_spare`]), for the next grid
/// ([`TileGrid::with_spare`]): a band of a frame drawn after another on one thread writes
/// into memory it already holds, instead of memory the system must map and zero again.
#[derive(Default)]
pub struct Spare(Vec<Tile>);

impl Clone for TileGrid {
    /// The same slots; the spare tiles stay behind.
    fn clone(&self) -> TileGrid {
        TileGrid {
            across: self.across,
            tiles: self.tiles.clone(),
            spare: Spare::default(),
        }
    }
}

impl PartialEq for TileGrid {
    /// The same slots (spare tiles aside).
    fn eq(&self, other: &TileGrid) -> bool {
        self.across == other.across && self.tiles == other.tiles
    }
}

impl Eq for TileGrid {}

impl TileGrid {
    /// An all-[`EMPTY`] grid; allocates the tile pointers only, and takes its tiles from
    /// `spare` while it has any.
    pub fn with_spare(width: u32, height: u32, spare: Spare) -> TileGrid {
        let across = width.div_ceil(TILE) as usize;
        let down = height.div_ceil(TILE) as usize;
        TileGrid {
            across,
            tiles: vec![None; across * down],
            spare,
        }
    }

    /// Every tile of the grid, its spare ones too, for another grid to reuse.
    pub fn into_spare(self) -> Spare {
        let mut spare = self.spare;
        spare.0.extend(self.tiles.into_iter().flatten());
        spare
    }

    /// Moves the tiles of rows `y0..y1` (on tile boundaries, `y1` possibly the height)
    /// from `other`, a grid of the same size, into this one.
    ///
    /// # Panics
    /// Rows not on tile boundaries, or grids of different sizes.
    pub fn take_rows(&mut self, other: TileGrid, y0: u32, y1: u32) {
        assert!(y0 % TILE == 0, "band start {y0} on a tile boundary");
        assert_eq!(
            (self.across, self.tiles.len()),
            (other.across, other.tiles.len()),
            "one grid"
        );
        let from = (y0 / TILE) as usize * self.across;
        let to = ((y1.div_ceil(TILE) as usize) * self.across).min(self.tiles.len());
        for (mine, theirs) in self.tiles[from..to].iter_mut().zip(other.tiles.into_iter().skip(from)) {
            if theirs.is_some() {
                *mine = theirs;
            }
        }
    }

    /// The number of allocated tiles.
    pub fn allocated(&self) -> usize {
        self.tiles.iter().filter(|t| t.is_some()).count()
    }

    /// The tile holding `(x, y)` and the slot's index inside it.
    fn locate(&self, x: u32, y: u32) -> (usize, usize) {
        let tile = (y / TILE) as usize * self.across + (x / TILE) as usize;
        (tile, ((y % TILE) * TILE + x % TILE) as usize)
    }

    /// The slot of `(x, y)`.
    pub fn get(&self, x: u32, y: u32) -> &u32 {
        let (tile, at) = self.locate(x, y);
        self.tiles[tile].as_ref().map_or(&EMPTY, |t| &t[at])
    }

    /// The slots `x0..=x1` of row `y` (inside one tile row), a tile at a time, as
    /// `(first x, slots)`; allocates the tiles they lie in.
    pub fn row_mut(&mut self, y: u32, x0: u32, x1: u32, mut each: impl FnMut(u32, &mut [u32])) {
        let mut x = x0;
        while x <= x1 {
            let last = x1.min(x | (TILE - 1));
            let (tile, at) = self.locate(x, y);
            let spare = &mut self.spare;
            let slots = self.tiles[tile].get_or_insert_with(|| match spare.0.pop() {
                Some(mut t) => {
                    t.fill(EMPTY);
                    t
                }
                None => empty_tile(),
            });
            each(x, &mut slots[at..=at + (last - x) as usize]);
            match last.checked_add(1) {
                Some(next) => x = next,
                None => break,
            }
        }
    }

    /// Row `y`'s slots that are not [`EMPTY`], as `(x, slot)`, left to right.
    pub fn row(&self, y: u32) -> impl Iterator<Item = (u32, &u32)> + '_ {
        let first = (y / TILE) as usize * self.across;
        let offset = ((y % TILE) * TILE) as usize;
        let tiles = &self.tiles[first..first + self.across];
        (0u32..)
            .zip(tiles)
            .filter_map(move |(tx, t)| t.as_ref().map(|t| (tx * TILE, &t[offset..offset + TILE as usize])))
            .flat_map(|(x0, slots)| (x0..).zip(slots).filter(|&(_, &v)| v != EMPTY))
    }

    /// Whether tile row `y / 64` has any tile allocated (rows of empty tile rows are
    /// skipped without looking at their slots).
    pub fn row_touched(&self, y: u32) -> bool {
        let first = (y / TILE) as usize * self.across;
        self.tiles[first..first + self.across].iter().any(Option::is_some)
    }
}

/// A fresh tile, allocated on the heap directly (no 16 KiB array on the stack).
fn empty_tile() -> Tile {
    vec![EMPTY; TILE_AREA]
        .into_boxed_slice()
        .try_into()
        .expect("TILE_AREA slots")
}
