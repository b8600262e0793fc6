//! The ids PNG (`render --ids-out`): what a renderer produces from an integer id buffer,
//! so another program compares its own id buffer with ours byte for byte.
//!
//! 8-bit RGBA; a pixel holds `id + 1` as a little-endian 24-bit number, R the low byte, G
//! the middle, B the high; `0` (and alpha 0) is uncovered. Alpha is 255 where one
//! primitive covers the pixel once. A pixel with several owners (or one owner twice) holds
//! its **highest** id, with alpha **254**, so a reader sees both a plausible id (what a
//! depth-less "last writer wins" renderer drawing in id order would leave) and the mark.

use std::fmt;

use image::{Rgba, RgbaImage};

use super::Coverage;

/// The largest id an ids PNG holds: 2^24 - 2 (`id + 1` fills 24 bits; 0 means uncovered).
pub const MAX_PNG_ID: u32 = (1 << 24) - 2;

/// Alpha of a pixel with exactly one owner.
pub const ALPHA_ONE_OWNER: u8 = 255;
/// Alpha of a pixel with several owners (its RGB is the highest id's).
pub const ALPHA_SEVERAL_OWNERS: u8 = 254;

/// A coverage holds an id the ids PNG cannot: the first such pixel in row-major order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IdOutOfRange {
    /// The id.
    pub id: u32,
    /// The pixel it covers.
    pub x: u32,
    /// The pixel's row.
    pub y: u32,
}

impl fmt::Display for IdOutOfRange {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "primitive id {} (at pixel ({}, {})) does not fit an ids PNG, which holds ids up to \
             {MAX_PNG_ID} (2^24 - 2)",
            self.id, self.x, self.y
        )
    }
}

impl std::error::Error for IdOutOfRange {}

/// The RGBA of a pixel with owners `ids` (ascending, not empty).
fn ids_pixel(ids: &[u32]) -> Option<Rgba<u8>> {
    let &highest = ids.last()?;
    let [r, g, b, _] = (highest + 1).to_le_bytes();
    let alpha = if ids.len() == 1 {
        ALPHA_ONE_OWNER
    } else {
        ALPHA_SEVERAL_OWNERS
    };
    Some(Rgba([r, g, b, alpha]))
}

impl Coverage {
    /// The ids picture (the format: [`crate::coverage::ids`]): `id + 1` in R (low
    /// byte), G, B (high byte), alpha 255; several owners: the highest id, alpha 254;
    /// uncovered: all zero.
    ///
    /// ```
    /// use rasterproof::coverage::{Coverage, CoverageSink};
    /// let mut c = Coverage::new(2, 1);
    /// c.cover(1, 0, 256);
    /// let png = c.to_ids_image().unwrap();
    /// assert_eq!(png.as_raw(), &[0, 0, 0, 0, 1, 1, 0, 255]); // 257 = 0x000101
    /// ```
    ///
    /// # Errors
    /// An id above [`MAX_PNG_ID`]: the first such pixel.
    pub fn to_ids_image(&self) -> Result<RgbaImage, IdOutOfRange> {
        let mut image = RgbaImage::new(self.width(), self.height());
        for (x, y, ids) in self.iter() {
            if let Some(&id) = ids.iter().find(|&&id| id > MAX_PNG_ID) {
                return Err(IdOutOfRange { id, x, y });
            }
            if let Some(p) = ids_pixel(ids) {
                image.put_pixel(x, y, p);
            }
        }
        Ok(image)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coverage::CoverageSink;

    #[test]
    fn ids_by_hand() {
        let mut c = Coverage::new(3, 2);
        c.cover(0, 0, 0); // 1 = 0x000001
        c.cover(1, 0, 255); // 256 = 0x000100
        c.cover(2, 0, 256); // 257 = 0x000101
        c.cover(0, 1, 65536); // 65537 = 0x010001
        c.cover(1, 1, 7); // several owners: 300 + 1 = 0x00012D, alpha 254
        c.cover(1, 1, 300);
        let png = c.to_ids_image().unwrap();
        #[rustfmt::skip]
        let expected: [u8; 24] = [
            1, 0, 0, 255,   0, 1, 0, 255,     1, 1, 0, 255,
            1, 0, 1, 255,   0x2D, 1, 0, 254,  0, 0, 0, 0,
        ];
        assert_eq!(png.as_raw().as_slice(), &expected);
    }

    #[test]
    fn the_largest_id_fits_and_the_next_does_not() {
        let mut c = Coverage::new(2, 1);
        c.cover(0, 0, MAX_PNG_ID);
        assert_eq!(c.to_ids_image().unwrap().as_raw()[..4], [255, 255, 255, 255]);
        c.cover(1, 0, MAX_PNG_ID + 1);
        let e = c.to_ids_image().unwrap_err();
        assert_eq!(
            e,
            IdOutOfRange {
                id: MAX_PNG_ID + 1,
                x: 1,
                y: 0
            }
        );
        assert!(e.to_string().contains("16777214"), "{e}");
    }
}
