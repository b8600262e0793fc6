//! Conventions: tie rule, sample position, subpixel grid and rounding, bundled as presets.
//!
//! References: D3D11 functional spec §3.4.2.1 (top-left rule, 8 subpixel bits),
//! the Vulkan spec (polygon rasterization, `subPixelPrecisionBits`), the Khronos CTS
//! reference rasterizer (half-away-from-zero snapping).

use std::cmp::Ordering;
use std::fmt;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

pub use crate::num::Rounding;

/// Which edges own the samples that lie exactly on them.
///
/// Top-left reads as "test the sample moved right by ε and down by ε²"; bottom-left as
/// "right by ε and up by ε²" (GL's lower-left origin seen in a y-down image).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TieRule {
    /// D3D11 / Vulkan: left edges and top edges are inclusive.
    TopLeft,
    /// GL in a y-down image: left edges and bottom edges are inclusive.
    BottomLeft,
}

impl TieRule {
    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            TieRule::TopLeft => "top-left",
            TieRule::BottomLeft => "bottom-left",
        }
    }

    /// Parses a name written by [`TieRule::name`].
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "top-left" => Some(TieRule::TopLeft),
            "bottom-left" => Some(TieRule::BottomLeft),
            _ => None,
        }
    }

    /// The move this rule tests the sample with (see [`MovedSample`]).
    pub fn moved_sample(self) -> MovedSample {
        MovedSample {
            right: true,
            down: self == TieRule::TopLeft,
        }
    }

    /// Whether an edge owns the samples on it. This is the one place the flag is derived;
    /// every model (exact, integer, float-with-rule) calls it with the signs of its own
    /// edge vector `(dx, dy) = b - a`, for an edge oriented so the interior is `E > 0`.
    ///
    /// With `E(p) = (p.x - a.x) dy - (p.y - a.y) dx`, moving the sample by `(ε, ±ε²)`
    /// changes `E` by `ε dy ∓ ε² dx`: the sign of `dy` decides, and for a horizontal
    /// edge the sign of `dx` does.
    ///
    /// ```
    /// use std::cmp::Ordering::*;
    /// use rasterproof::convention::TieRule;
    /// // A left edge (going down the screen, interior to its right) is inclusive.
    /// assert!(TieRule::TopLeft.is_inclusive(Equal, Greater));
    /// // A top edge (horizontal, interior below, so it runs right to left) is inclusive.
    /// assert!(TieRule::TopLeft.is_inclusive(Less, Equal));
    /// // The bottom edge of the same triangle is not, under top-left; it is under bottom-left.
    /// assert!(!TieRule::TopLeft.is_inclusive(Greater, Equal));
    /// assert!(TieRule::BottomLeft.is_inclusive(Greater, Equal));
    /// ```
    #[inline]
    pub fn is_inclusive(self, dx: Ordering, dy: Ordering) -> bool {
        match dy {
            Ordering::Greater => true,
            Ordering::Less => false,
            Ordering::Equal => match self {
                TieRule::TopLeft => dx == Ordering::Less,
                TieRule::BottomLeft => dx == Ordering::Greater,
            },
        }
    }
}

/// Every tie rule a renderer may follow: the two the models render ([`TieRule`]), the two
/// mirrored ones, and "every edge owns its samples" / "no edge does". What
/// [`crate::oracle`] names when it explains a pixel another renderer decided differently.
///
/// The four directional rules read as moving the sample by `(±ε, ±ε²)`: top-left
/// `(+ε, +ε²)`, bottom-left `(+ε, -ε²)`, top-right `(-ε, +ε²)`, bottom-right `(-ε, -ε²)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AnyTieRule {
    /// Left and top edges own their samples (D3D11, Vulkan).
    TopLeft,
    /// Right and top edges.
    TopRight,
    /// Left and bottom edges (GL in a y-down image).
    BottomLeft,
    /// Right and bottom edges.
    BottomRight,
    /// Every edge owns its samples: a sample on a shared edge is covered twice.
    AllInclusive,
    /// No edge does: a sample on a shared edge is covered by neither triangle.
    AllExclusive,
}

impl AnyTieRule {
    /// Every rule, the models' two first.
    pub const ALL: [AnyTieRule; 6] = [
        AnyTieRule::TopLeft,
        AnyTieRule::BottomLeft,
        AnyTieRule::TopRight,
        AnyTieRule::BottomRight,
        AnyTieRule::AllInclusive,
        AnyTieRule::AllExclusive,
    ];

    /// Its name (`top-right`, `all-inclusive`, ...).
    pub fn name(self) -> &'static str {
        match self {
            AnyTieRule::TopLeft => "top-left",
            AnyTieRule::TopRight => "top-right",
            AnyTieRule::BottomLeft => "bottom-left",
            AnyTieRule::BottomRight => "bottom-right",
            AnyTieRule::AllInclusive => "all-inclusive",
            AnyTieRule::AllExclusive => "all-exclusive",
        }
    }

    /// Whether an edge `(dx, dy) = b - a`, oriented so the interior is `E > 0`, owns the
    /// samples on it. With `E(p) = (p.x - a.x) dy - (p.y - a.y) dx`, moving the sample by
    /// `(sx ε, sy ε²)` changes `E` by `sx ε dy - sy ε² dx`; the edge owns its samples when
    /// that is positive.
    ///
    /// ```
    /// use std::cmp::Ordering::*;
    /// use rasterproof::convention::{AnyTieRule, TieRule};
    /// // A left edge (going down the screen) belongs to the left rules only.
    /// assert!(AnyTieRule::TopLeft.is_inclusive(Equal, Greater));
    /// assert!(!AnyTieRule::TopRight.is_inclusive(Equal, Greater));
    /// // A bottom edge (horizontal, running left to right) to the bottom rules.
    /// assert!(AnyTieRule::BottomRight.is_inclusive(Greater, Equal));
    /// assert!(!AnyTieRule::TopRight.is_inclusive(Greater, Equal));
    /// ```
    pub fn is_inclusive(self, dx: Ordering, dy: Ordering) -> bool {
        let Some(moved) = self.moved_sample() else {
            return self == AnyTieRule::AllInclusive;
        };
        // sign(sx * dy), or when dy is 0, sign(-sy * dx).
        match dy {
            Ordering::Equal => dx != Ordering::Equal && (dx == Ordering::Less) == moved.down,
            _ => (dy == Ordering::Greater) == moved.right,
        }
    }

    /// The move of a directional rule, `(sx ε, sy ε²)`; `None` for all-inclusive and
    /// all-exclusive, which no single move stands for (they ask whether the sample is in
    /// the closed or the open shape).
    ///
    /// ```
    /// use rasterproof::convention::{AnyTieRule, MovedSample};
    /// assert_eq!(AnyTieRule::BottomRight.moved_sample(), Some(MovedSample { right: false, down: false }));
    /// assert_eq!(AnyTieRule::AllInclusive.moved_sample(), None);
    /// ```
    pub fn moved_sample(self) -> Option<MovedSample> {
        let (right, down) = match self {
            AnyTieRule::AllInclusive | AnyTieRule::AllExclusive => return None,
            AnyTieRule::TopLeft => (true, true),
            AnyTieRule::BottomLeft => (true, false),
            AnyTieRule::TopRight => (false, true),
            AnyTieRule::BottomRight => (false, false),
        };
        Some(MovedSample { right, down })
    }
}

/// How a directional tie rule moves the sample before testing it: by `(±ε, ±ε²)` for an
/// infinitesimal `ε > 0`, so the moved sample lies on no edge of positive length. Top-left
/// moves it right and down (in a y-down image): the edges left of and above the sample
/// then hold it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct MovedSample {
    /// `+ε` in x (the left rules); `-ε` otherwise (the right rules).
    pub right: bool,
    /// `+ε²` in y, down the image (the top rules); `-ε²` otherwise (the bottom rules).
    pub down: bool,
}

impl From<TieRule> for AnyTieRule {
    fn from(rule: TieRule) -> AnyTieRule {
        match rule {
            TieRule::TopLeft => AnyTieRule::TopLeft,
            TieRule::BottomLeft => AnyTieRule::BottomLeft,
        }
    }
}

/// Where the sample of pixel (i, j) sits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PixelCentre {
    /// (i + 1/2, j + 1/2): D3D10+, Vulkan, GL.
    Half,
    /// (i, j): D3D9 style.
    Corner,
}

impl PixelCentre {
    /// Its value as scene files and reports write it: `0.5` or `0`.
    pub fn name(self) -> &'static str {
        match self {
            PixelCentre::Half => "0.5",
            PixelCentre::Corner => "0",
        }
    }

    /// The offset as an exact rational (1/2 or 0).
    pub fn offset(self) -> BigRational {
        match self {
            PixelCentre::Half => BigRational::new(BigInt::from(1), BigInt::from(2)),
            PixelCentre::Corner => BigRational::zero(),
        }
    }

    /// The offset in subpixels of a 2^-bits grid (`bits >= 1`).
    #[inline]
    pub fn offset_subpixels(self, bits: u32) -> i64 {
        match self {
            PixelCentre::Half => 1i64 << (bits - 1),
            PixelCentre::Corner => 0,
        }
    }

    /// The offset as a float (exact in both f32 and f64).
    pub fn offset_f64(self) -> f64 {
        match self {
            PixelCentre::Half => 0.5,
            PixelCentre::Corner => 0.0,
        }
    }
}

/// A named bundle of choices.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Preset {
    /// Top-left, centre 0.5, 8 subpixel bits, nearest-even.
    D3d11,
    /// As D3D11 (Vulkan implementations commonly report 8 `subPixelPrecisionBits`).
    Vulkan,
    /// Bottom-left in a y-down image, centre 0.5, 8 bits, nearest-even.
    Gl,
    /// Top-left, centre 0.5, 8 bits, half-away-from-zero (Khronos CTS reference).
    Cts,
}

impl Preset {
    /// Every preset.
    pub const ALL: [Preset; 4] = [Preset::D3d11, Preset::Vulkan, Preset::Gl, Preset::Cts];

    /// The name used in scene files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Preset::D3d11 => "d3d11",
            Preset::Vulkan => "vulkan",
            Preset::Gl => "gl",
            Preset::Cts => "cts",
        }
    }

    /// Parses a name written by [`Preset::name`].
    pub fn from_name(name: &str) -> Option<Self> {
        Preset::ALL.into_iter().find(|p| p.name() == name)
    }

    /// The convention the preset stands for.
    pub fn convention(self) -> Convention {
        let base = Convention {
            preset: self,
            tie_rule: TieRule::TopLeft,
            pixel_centre: PixelCentre::Half,
            subpixel_bits: 8,
            rounding: Rounding::NearestEven,
        };
        match self {
            Preset::D3d11 | Preset::Vulkan => base,
            Preset::Gl => Convention {
                tie_rule: TieRule::BottomLeft,
                ..base
            },
            Preset::Cts => Convention {
                rounding: Rounding::HalfAwayFromZero,
                ..base
            },
        }
    }
}

/// Every choice a model needs. Built from a [`Preset`], then optionally overridden.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Convention {
    /// The preset this convention started from (named in every output).
    pub preset: Preset,
    /// Which edges own the samples on them.
    pub tie_rule: TieRule,
    /// Where each pixel's sample sits.
    pub pixel_centre: PixelCentre,
    /// S: vertices snap to a 2^-S pixel grid; `1..=16`.
    pub subpixel_bits: u32,
    /// How snapping breaks ties.
    pub rounding: Rounding,
}

impl Default for Convention {
    fn default() -> Self {
        Preset::D3d11.convention()
    }
}

impl Convention {
    /// True when this is exactly the preset's convention, with no override.
    pub fn is_plain_preset(&self) -> bool {
        *self == self.preset.convention()
    }
}

impl fmt::Display for Convention {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "preset {} (tie rule {}, pixel centre {}, {} subpixel bits, rounding {})",
            self.preset.name(),
            self.tie_rule.name(),
            self.pixel_centre.name(),
            self.subpixel_bits,
            self.rounding.name()
        )
    }
}

/// The canvas and the convention every model renders with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Target {
    /// Canvas width in pixels, `1..=MAX_CANVAS`.
    pub width: u32,
    /// Canvas height in pixels, `1..=MAX_CANVAS`.
    pub height: u32,
    /// The convention.
    pub convention: Convention,
}

/// The largest canvas side accepted (pixels). The integer envelope proof assumes it.
pub const MAX_CANVAS: u32 = 16384;

impl Target {
    /// A target; `None` when a side is 0 or above [`MAX_CANVAS`], or the subpixel bits are
    /// outside `1..=16`.
    pub fn new(width: u32, height: u32, convention: Convention) -> Option<Target> {
        let sides_ok = (1..=MAX_CANVAS).contains(&width) && (1..=MAX_CANVAS).contains(&height);
        let bits_ok = (1..=crate::num::MAX_SUBPIXEL_BITS).contains(&convention.subpixel_bits);
        (sides_ok && bits_ok).then_some(Target {
            width,
            height,
            convention,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SIGNS: [Ordering; 3] = [Ordering::Less, Ordering::Equal, Ordering::Greater];

    fn int(o: Ordering) -> i64 {
        match o {
            Ordering::Less => -1,
            Ordering::Equal => 0,
            Ordering::Greater => 1,
        }
    }

    #[test]
    fn the_models_rules_read_the_same_in_both_enums() {
        for rule in [TieRule::TopLeft, TieRule::BottomLeft] {
            for dx in SIGNS {
                for dy in SIGNS {
                    assert_eq!(
                        AnyTieRule::from(rule).is_inclusive(dx, dy),
                        rule.is_inclusive(dx, dy),
                        "{rule:?} ({dx:?}, {dy:?})"
                    );
                    assert_eq!(AnyTieRule::from(rule).name(), rule.name());
                }
            }
        }
    }

    /// The directional rules equal the moved sample, computed: `E` at the sample moved by
    /// `(sx ε, sy ε²)` with ε = 1/1000, for an edge through the sample (E = 0 there).
    #[test]
    fn directional_rules_are_the_moved_sample() {
        let moves = [
            (AnyTieRule::TopLeft, 1, 1),
            (AnyTieRule::BottomLeft, 1, -1),
            (AnyTieRule::TopRight, -1, 1),
            (AnyTieRule::BottomRight, -1, -1),
        ];
        for (rule, sx, sy) in moves {
            for dx in SIGNS {
                for dy in SIGNS {
                    if dx == Ordering::Equal && dy == Ordering::Equal {
                        continue;
                    }
                    // E(p + m) - E(p) = mx * dy - my * dx, in units of 10^-6 (ε = 10^-3).
                    let change = sx * 1000 * int(dy) - sy * int(dx);
                    assert_eq!(rule.is_inclusive(dx, dy), change > 0, "{rule:?} ({dx:?}, {dy:?})");
                }
            }
        }
        for dx in SIGNS {
            for dy in SIGNS {
                assert!(AnyTieRule::AllInclusive.is_inclusive(dx, dy));
                assert!(!AnyTieRule::AllExclusive.is_inclusive(dx, dy));
            }
        }
    }
}
