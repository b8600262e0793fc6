//! Sample patterns: where the samples of a pixel sit when a pixel's answer is more than
//! one sample (multisampling).
//!
//! A pattern is a list of positions inside the pixel square, each an exact fraction of a
//! pixel measured from the pixel's top-left corner (x right, y down, as window
//! coordinates are): sample `s` of pixel `(i, j)` is the point `(i + x_s, j + y_s)`.
//! Sample index `s` is the position's place in the list, as a GPU numbers the bits of
//! `gl_SampleMaskIn` / `SV_Coverage`.
//!
//! The standard patterns are those of the Vulkan specification ("Multisampling", the
//! table of standard sample locations, used when `standardSampleLocations` is true) and
//! of Direct3D 11's `D3D11_STANDARD_MULTISAMPLE_PATTERN` (the same positions). They are
//! given there in 1/16 pixel from the pixel centre; Mesa's `u_sample_positions.c` and
//! VK-GL-CTS's `getStandardSampleLocations` hold the same tables:
//!
//! | count | positions, (x, y) in 1/16 px from the centre, y down |
//! |---|---|
//! | 1 | (0, 0) |
//! | 2 | (4, 4) (-4, -4) |
//! | 4 | (-2, -6) (6, -2) (-6, 2) (2, 6) |
//! | 8 | (1, -3) (-1, 3) (5, 1) (-3, -5) (-5, 5) (-7, -1) (3, 7) (7, -7) |
//! | 16 | (1, 1) (-1, -3) (-3, 2) (4, -1) (-5, -2) (2, 5) (5, 3) (3, -5) (-2, 6) (0, -7) (-4, -6) (-6, 4) (-8, 0) (7, -4) (6, 7) (-7, -8) |
//!
//! A custom pattern (a scene's `samples` as a list) is any 1 to [`MAX_SAMPLES`] distinct
//! positions in `[0, 1) x [0, 1)`.
//!
//! ```
//! use rasterproof::pattern::SamplePattern;
//! let four = SamplePattern::standard(4).unwrap();
//! // Sample 0 sits 2/16 left of and 6/16 above the centre: at (6/16, 2/16) of the pixel.
//! assert_eq!(four.position_text(0), "(3/8, 1/8)");
//! assert!(SamplePattern::standard(3).is_none());
//! ```

use std::fmt;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use crate::convention::Convention;
use crate::num::exact::exact_text;

/// The most samples a pattern may have (a sample mask is a `u64`).
pub const MAX_SAMPLES: usize = 64;

/// The counts with a standard pattern.
pub const STANDARD_COUNTS: [usize; 5] = [1, 2, 4, 8, 16];

/// The standard positions in 1/16 pixel from the pixel centre, y down.
const STANDARD: [&[[i8; 2]]; 5] = [
    &[[0, 0]],
    &[[4, 4], [-4, -4]],
    &[[-2, -6], [6, -2], [-6, 2], [2, 6]],
    &[[1, -3], [-1, 3], [5, 1], [-3, -5], [-5, 5], [-7, -1], [3, 7], [7, -7]],
    &[
        [1, 1],
        [-1, -3],
        [-3, 2],
        [4, -1],
        [-5, -2],
        [2, 5],
        [5, 3],
        [3, -5],
        [-2, 6],
        [0, -7],
        [-4, -6],
        [-6, 4],
        [-8, 0],
        [7, -4],
        [6, 7],
        [-7, -8],
    ],
];

/// Where a pixel's samples sit (see the module docs).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct SamplePattern {
    positions: Vec<[BigRational; 2]>,
    standard: bool,
}

/// A custom pattern that is not a pattern.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PatternError {
    /// No position at all.
    Empty,
    /// More than [`MAX_SAMPLES`] positions.
    TooMany(usize),
    /// A coordinate outside `[0, 1)`: the sample would belong to another pixel.
    Outside {
        /// The sample index.
        index: usize,
        /// `'x'` or `'y'`.
        axis: char,
        /// The coordinate, as exact text.
        value: String,
    },
    /// Two samples at the same position.
    Duplicate {
        /// The first sample index.
        first: usize,
        /// The later one.
        second: usize,
    },
}

impl fmt::Display for PatternError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PatternError::Empty => write!(f, "a sample pattern needs at least one position"),
            PatternError::TooMany(n) => write!(f, "{n} samples; a pattern holds at most {MAX_SAMPLES}"),
            PatternError::Outside { index, axis, value } => write!(
                f,
                "sample {index}'s {axis} is {value}, outside the pixel: a position is a fraction of the pixel in [0, 1)"
            ),
            PatternError::Duplicate { first, second } => {
                write!(f, "samples {first} and {second} sit at the same position")
            }
        }
    }
}

impl std::error::Error for PatternError {}

impl SamplePattern {
    /// The standard pattern of `count` samples (1, 2, 4, 8 or 16); `None` for another count.
    pub fn standard(count: usize) -> Option<SamplePattern> {
        let k = STANDARD_COUNTS.iter().position(|&c| c == count)?;
        let sixteenth = |v: i8| BigRational::new(BigInt::from(i32::from(v) + 8), BigInt::from(16));
        let positions = STANDARD[k].iter().map(|&[x, y]| [sixteenth(x), sixteenth(y)]).collect();
        Some(SamplePattern {
            positions,
            standard: true,
        })
    }

    /// A pattern of these positions (fractions of the pixel from its top-left corner).
    ///
    /// # Errors
    /// No position, more than [`MAX_SAMPLES`], a coordinate outside `[0, 1)`, two equal
    /// positions. A list equal to a standard pattern is that pattern.
    pub fn custom(positions: Vec<[BigRational; 2]>) -> Result<SamplePattern, PatternError> {
        if positions.is_empty() {
            return Err(PatternError::Empty);
        }
        if positions.len() > MAX_SAMPLES {
            return Err(PatternError::TooMany(positions.len()));
        }
        for (index, p) in positions.iter().enumerate() {
            for (axis, v) in ['x', 'y'].into_iter().zip(p) {
                if v.is_negative() || *v >= BigRational::one() {
                    return Err(PatternError::Outside {
                        index,
                        axis,
                        value: exact_text(v),
                    });
                }
            }
            if let Some(first) = positions[..index].iter().position(|q| q == p) {
                return Err(PatternError::Duplicate { first, second: index });
            }
        }
        let standard = SamplePattern::standard(positions.len()).is_some_and(|s| s.positions == positions);
        Ok(SamplePattern { positions, standard })
    }

    /// The single sample of `convention`: the pixel centre (`0.5`) or corner (`0`). Its
    /// coverage is exactly what every model renders without a pattern.
    pub fn single(convention: &Convention) -> SamplePattern {
        let c = convention.pixel_centre.offset();
        SamplePattern {
            positions: vec![[c.clone(), c]],
            standard: false,
        }
    }

    /// How many samples a pixel has.
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// Always false: a pattern has at least one sample.
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// Whether this is the standard pattern of its count.
    pub fn is_standard(&self) -> bool {
        self.standard
    }

    /// The positions in sample-index order.
    pub fn positions(&self) -> &[[BigRational; 2]] {
        &self.positions
    }

    /// Sample `s`'s position as text, `(x, y)` in exact fractions of the pixel.
    pub fn position_text(&self, s: usize) -> String {
        let [x, y] = &self.positions[s];
        format!("({}, {})", exact_text(x), exact_text(y))
    }

    /// Sample `s` of pixel `(i, j)`: the exact point `(i + x_s, j + y_s)`.
    pub fn sample(&self, i: u32, j: u32, s: usize) -> crate::geom::Point {
        let [x, y] = &self.positions[s];
        crate::geom::Point::new(
            BigRational::from_integer(i.into()) + x,
            BigRational::from_integer(j.into()) + y,
        )
    }

    /// How far sample `s` sits from `convention`'s one sample, `(dx, dy)` in pixels: moving
    /// a scene by `(-dx, -dy)` brings sample `s` of every pixel to where that one sample is.
    pub fn offset(&self, s: usize, convention: &Convention) -> [BigRational; 2] {
        let c = convention.pixel_centre.offset();
        let [x, y] = &self.positions[s];
        [x - &c, y - &c]
    }

    /// Sample `s`'s offset (as [`SamplePattern::offset`]) in whole subpixels of
    /// `convention`'s `2^-bits` grid, or `None` when it is not on that grid.
    pub fn offset_subpixels(&self, s: usize, convention: &Convention) -> Option<[i64; 2]> {
        let scale = BigRational::from_integer(BigInt::one() << convention.subpixel_bits);
        let [dx, dy] = self.offset(s, convention);
        let whole = |v: BigRational| {
            let v = v * &scale;
            v.is_integer().then(|| i64::try_from(v.to_integer()).ok()).flatten()
        };
        Some([whole(dx)?, whole(dy)?])
    }

    /// How a scene file and reports write it: the count of a standard pattern, or the list
    /// of positions as exact text.
    pub fn to_json(&self) -> serde_json::Value {
        if self.standard {
            serde_json::Value::from(self.positions.len())
        } else {
            let text = |p: &[BigRational; 2]| serde_json::json!([exact_text(&p[0]), exact_text(&p[1])]);
            serde_json::Value::Array(self.positions.iter().map(text).collect())
        }
    }

    /// `standard 4x` or `custom 3x`.
    pub fn name(&self) -> String {
        let kind = if self.standard { "standard" } else { "custom" };
        format!("{kind} {}x", self.positions.len())
    }

    /// Whether the pattern is `convention`'s one sample (rendering it is rendering without
    /// a pattern).
    pub fn is_single(&self, convention: &Convention) -> bool {
        self.positions.len() == 1 && self.offset(0, convention).iter().all(Zero::is_zero)
    }
}

impl fmt::Display for SamplePattern {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.name())?;
        if !self.standard {
            let text: Vec<String> = (0..self.len()).map(|s| self.position_text(s)).collect();
            write!(f, " {}", text.join(" "))?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn standard_four_is_vulkans_table_in_the_pixel() {
        // Vulkan's table in framebuffer coordinates: (0.375, 0.125) (0.875, 0.375)
        // (0.125, 0.625) (0.625, 0.875).
        let p = SamplePattern::standard(4).unwrap();
        let want = [[3, 1], [7, 3], [1, 5], [5, 7]].map(|[x, y]| [q(x, 8), q(y, 8)]);
        assert_eq!(p.positions(), &want);
        assert!(p.is_standard());
        assert_eq!(p.to_json(), serde_json::json!(4));
    }

    #[test]
    fn every_standard_pattern_is_distinct_and_inside() {
        for n in STANDARD_COUNTS {
            let p = SamplePattern::standard(n).unwrap();
            assert_eq!(p.len(), n);
            let again = SamplePattern::custom(p.positions().to_vec()).unwrap();
            assert!(again.is_standard(), "{n}");
        }
        // The 16x pattern's (-8, 0) is the pixel's left edge: x = 0, inside [0, 1).
        assert_eq!(SamplePattern::standard(16).unwrap().position_text(12), "(0, 1/2)");
    }

    #[test]
    fn custom_patterns_refuse_what_is_not_a_pattern() {
        assert_eq!(SamplePattern::custom(vec![]), Err(PatternError::Empty));
        let outside = SamplePattern::custom(vec![[q(1, 2), q(1, 1)]]).unwrap_err();
        assert!(
            outside.to_string().contains("sample 0's y is 1, outside the pixel"),
            "{outside}"
        );
        let negative = SamplePattern::custom(vec![[q(1, 2), q(1, 2)], [q(-1, 3), q(0, 1)]]).unwrap_err();
        assert!(negative.to_string().contains("sample 1's x is -1/3"), "{negative}");
        let twice = SamplePattern::custom(vec![[q(1, 3), q(1, 3)], [q(1, 2), q(1, 2)], [q(2, 6), q(1, 3)]]);
        assert_eq!(twice, Err(PatternError::Duplicate { first: 0, second: 2 }));
        let many: Vec<_> = (0..65).map(|k| [q(k, 65), q(0, 1)]).collect();
        assert_eq!(SamplePattern::custom(many), Err(PatternError::TooMany(65)));
        let sixty_four: Vec<_> = (0..64).map(|k| [q(k, 64), q(0, 1)]).collect();
        assert!(!SamplePattern::custom(sixty_four).unwrap().is_standard());
    }

    #[test]
    fn offsets_from_the_centre_and_on_the_grid() {
        let conv = Convention::default(); // centre 1/2, 8 bits
        let p = SamplePattern::standard(4).unwrap();
        assert_eq!(p.offset(0, &conv), [q(-1, 8), q(-3, 8)]);
        assert_eq!(p.offset_subpixels(0, &conv), Some([-32, -96]));
        let coarse = Convention {
            subpixel_bits: 2,
            ..conv
        };
        assert_eq!(p.offset_subpixels(0, &coarse), None, "-1/8 is not a quarter");
        let third = SamplePattern::custom(vec![[q(1, 3), q(1, 2)]]).unwrap();
        assert_eq!(third.offset_subpixels(0, &conv), None);
        assert!(SamplePattern::single(&conv).is_single(&conv));
        assert!(SamplePattern::standard(1).unwrap().is_single(&conv));
        assert!(!p.is_single(&conv));
    }
}
