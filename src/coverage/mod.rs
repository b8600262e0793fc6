//! The output every model writes: which primitives cover which pixel. Models write through
//! the [`CoverageSink`] trait; [`Coverage`] keeps the owner list of every covered pixel,
//! [`CountBuffer`] only counts (for benchmarks). Pictures for people (the palette, the
//! scaled PNG, its legend, the ASCII grid) are in [`picture`].

use std::collections::BTreeMap;
use std::fmt::Write as _;

pub mod picture;

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
}

/// The covering primitive ids of every covered pixel, sparse (a 16384² canvas with one
/// small triangle costs only that triangle's pixels).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Coverage {
    width: u32,
    height: u32,
    /// Keyed by (y, x) so iteration is row-major; ids ascending, repeats kept (a model
    /// that covers a pixel twice for one primitive is reported, not hidden).
    pixels: BTreeMap<(u32, u32), Vec<u32>>,
}

impl CoverageSink for Coverage {
    fn cover(&mut self, x: u32, y: u32, id: u32) {
        debug_assert!(x < self.width && y < self.height, "({x},{y}) off the canvas");
        let ids = self.pixels.entry((y, x)).or_default();
        let at = ids.partition_point(|&i| i <= id);
        ids.insert(at, id);
    }
}

impl Coverage {
    /// An empty coverage of a `width` x `height` canvas.
    pub fn new(width: u32, height: u32) -> Coverage {
        Coverage {
            width,
            height,
            pixels: BTreeMap::new(),
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

    /// The ids covering `(x, y)`, ascending; empty when uncovered.
    pub fn owners(&self, x: u32, y: u32) -> &[u32] {
        self.pixels.get(&(y, x)).map_or(&[], Vec::as_slice)
    }

    /// Covered pixels as `(x, y, ids)`, sorted by y then x.
    pub fn iter(&self) -> impl Iterator<Item = (u32, u32, &[u32])> + '_ {
        self.pixels.iter().map(|(&(y, x), ids)| (x, y, ids.as_slice()))
    }

    /// The number of covered pixels.
    pub fn covered_pixels(&self) -> usize {
        self.pixels.len()
    }

    /// Pixels covered more than once, as `(x, y, ids)`.
    pub fn double_covered(&self) -> impl Iterator<Item = (u32, u32, &[u32])> + '_ {
        self.iter().filter(|(_, _, ids)| ids.len() > 1)
    }

    /// The coverage moved by whole pixels, dropping what leaves the canvas.
    pub fn translated(&self, dx: i64, dy: i64) -> Coverage {
        let mut out = Coverage::new(self.width, self.height);
        for (x, y, ids) in self.iter() {
            let (nx, ny) = (i64::from(x) + dx, i64::from(y) + dy);
            if let (Ok(nx), Ok(ny)) = (u32::try_from(nx), u32::try_from(ny)) {
                if nx < self.width && ny < self.height {
                    out.pixels.insert((ny, nx), ids.to_vec());
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
                out.pixels.insert((y, x), ids.to_vec());
            }
        }
        out
    }

    /// The machine interface: `{"width":W,"height":H,"pixels":[[x,y,[ids...]],...]}`,
    /// covered pixels only, sorted by y then x, ids ascending, no whitespace.
    ///
    /// ```
    /// use rasterproof::coverage::{Coverage, CoverageSink};
    /// let mut c = Coverage::new(4, 3);
    /// c.cover(2, 1, 7);
    /// c.cover(0, 2, 1);
    /// c.cover(2, 1, 3);
    /// assert_eq!(c.to_json(), r#"{"width":4,"height":3,"pixels":[[2,1,[3,7]],[0,2,[1]]]}"#);
    /// ```
    pub fn to_json(&self) -> String {
        let mut s = format!("{{\"width\":{},\"height\":{},\"pixels\":[", self.width, self.height);
        for (n, (x, y, ids)) in self.iter().enumerate() {
            if n > 0 {
                s.push(',');
            }
            let _ = write!(s, "[{x},{y},[");
            for (k, id) in ids.iter().enumerate() {
                if k > 0 {
                    s.push(',');
                }
                let _ = write!(s, "{id}");
            }
            s.push_str("]]");
        }
        s.push_str("]}");
        s
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
    fn cover(&mut self, x: u32, y: u32, _id: u32) {
        self.counts[y as usize * self.width as usize + x as usize] += 1;
    }

    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, _id: u32) {
        let row = y as usize * self.width as usize;
        for c in &mut self.counts[row + x0 as usize..=row + x1 as usize] {
            *c += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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

    #[test]
    fn translation_drops_what_leaves() {
        let mut c = Coverage::new(3, 3);
        c.cover(0, 0, 0);
        c.cover(2, 2, 1);
        let t = c.translated(1, 0);
        assert_eq!(t.owners(1, 0), &[0]);
        assert_eq!(t.covered_pixels(), 1);
    }
}
