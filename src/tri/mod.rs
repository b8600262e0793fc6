//! Triangle rasterizers, one file per numeric model, each with the same shape:
//! `rasterize(triangle, id, &Target, &mut sink)`, the triangle in the model's own input
//! form (exact [`crate::geom::Triangle`], fixed [`crate::geom::FixedTriangle`], glam
//! vectors for float). [`crate::model`] converts a scene's exact triangles for each.

pub mod exact;
pub mod fixed;
pub mod float;
pub mod scanline;

/// A pixel index from an exact integer, saturating by sign: anything beyond i64 is far off
/// any canvas either way, on the side its sign says.
pub(crate) fn saturating_index(v: num_bigint::BigInt) -> i64 {
    use num_traits::ToPrimitive;
    v.to_i64().unwrap_or(if v.sign() == num_bigint::Sign::Minus {
        i64::MIN
    } else {
        i64::MAX
    })
}

/// An inclusive rectangle of pixels `x0..=x1`, `y0..=y1` on the canvas.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PixelRange {
    /// First column.
    pub x0: u32,
    /// Last column.
    pub x1: u32,
    /// First row.
    pub y0: u32,
    /// Last row.
    pub y1: u32,
}

impl PixelRange {
    /// The pixels whose sample index lies in `[lo, hi]` on each axis (already rounded
    /// inwards to integers), clamped to a `width` x `height` canvas; `None` when empty.
    pub fn clamped(lo: [i64; 2], hi: [i64; 2], width: u32, height: u32) -> Option<PixelRange> {
        let clamp = |v: i64, side: u32| -> i64 { v.clamp(0, i64::from(side) - 1) };
        if hi[0] < 0 || hi[1] < 0 || lo[0] >= i64::from(width) || lo[1] >= i64::from(height) {
            return None;
        }
        if lo[0] > hi[0] || lo[1] > hi[1] {
            return None;
        }
        let to_u32 = |v: i64| u32::try_from(v).expect("clamped to the canvas");
        Some(PixelRange {
            x0: to_u32(clamp(lo[0], width)),
            x1: to_u32(clamp(hi[0], width)),
            y0: to_u32(clamp(lo[1], height)),
            y1: to_u32(clamp(hi[1], height)),
        })
    }
}
