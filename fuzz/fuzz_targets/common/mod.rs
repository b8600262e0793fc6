//! What the fuzz targets share: the convention an input picks, an independent i128
//! snapping to check the crate's against, and whole scenes as fuzz inputs ([`scene`]).

#![allow(dead_code)] // each target uses a part

pub mod scene;

use arbitrary::Arbitrary;
use rasterproof::convention::{Convention, PixelCentre, Preset, Rounding};

/// The preset a fuzz input starts from.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum PresetChoice {
    D3d11,
    Gl,
    Cts,
}

/// The preset's convention, with `1 + bits % 16` subpixel bits when given and corner
/// samples when `corner`.
pub fn convention(preset: PresetChoice, bits: Option<u8>, corner: bool) -> Convention {
    let mut conv = match preset {
        PresetChoice::D3d11 => Preset::D3d11,
        PresetChoice::Gl => Preset::Gl,
        PresetChoice::Cts => Preset::Cts,
    }
    .convention();
    if let Some(b) = bits {
        conv.subpixel_bits = 1 + u32::from(b % 16);
    }
    if corner {
        conv.pixel_centre = PixelCentre::Corner;
    }
    conv
}

/// `num / den * 2^bits` rounded to an integer by `rounding` (nearest with its tie rule, or
/// directed), in plain i128 (`den > 0`).
pub fn snap_i128(num: i128, den: i128, bits: u32, rounding: Rounding) -> i128 {
    let scaled = num << bits;
    let (q, r) = (scaled.div_euclid(den), scaled.rem_euclid(den));
    let up = q + i128::from(r != 0);
    match rounding {
        Rounding::Floor => return q,
        Rounding::Ceiling => return up,
        Rounding::TowardsZero => return if scaled < 0 { up } else { q },
        Rounding::NearestEven | Rounding::HalfAwayFromZero => {}
    }
    match (2 * r).cmp(&den) {
        std::cmp::Ordering::Less => q,
        std::cmp::Ordering::Greater => q + 1,
        std::cmp::Ordering::Equal => match rounding {
            Rounding::NearestEven => q + (q & 1),
            // The value is q + 1/2: positive exactly when q >= 0.
            Rounding::HalfAwayFromZero => {
                if q >= 0 {
                    q + 1
                } else {
                    q
                }
            }
            Rounding::Floor | Rounding::Ceiling | Rounding::TowardsZero => unreachable!("returned above"),
        },
    }
}
