//! [`Region`]: a set of pixels of an image, one bit per pixel, listed row-major.

use std::fmt;

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

    pub(super) fn index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
    }

    pub(super) fn bit(&self, i: usize) -> bool {
        self.words[i / 64] >> (i % 64) & 1 == 1
    }

    /// Adds pixel `i`; it must not be in the region yet.
    fn insert(&mut self, i: usize) {
        debug_assert!(!self.bit(i), "pixel {i} inserted twice");
        self.words[i / 64] |= 1 << (i % 64);
        self.len += 1;
    }

    /// Adds pixels `start..end` (by index), none of them in the region yet.
    pub(super) fn insert_range(&mut self, start: usize, end: usize) {
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

impl Pixels<'_> {
    /// The next pixel's index `y * width + x`.
    pub(super) fn next_index(&mut self) -> Option<usize> {
        while self.bits == 0 {
            self.word += 1;
            self.bits = *self.region.words.get(self.word)?;
        }
        let i = self.word * 64 + self.bits.trailing_zeros() as usize;
        self.bits &= self.bits - 1;
        Some(i)
    }
}

impl Iterator for Pixels<'_> {
    type Item = (u32, u32);

    fn next(&mut self) -> Option<(u32, u32)> {
        let i = self.next_index()?;
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
}
