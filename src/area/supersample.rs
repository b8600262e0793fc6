//! Coverage by supersampling, a contender: `k x k` point samples per pixel, at
//! `((i + 1/2) / k, (j + 1/2) / k)` from its top-left corner, each decided exactly by the
//! polygon oracle under the top-left rule, the count over `k^2` as the pixel's value. It is
//! what 2D renderers with `k` sub-scanlines approximate (tiny-skia supersamples 4, Skia's
//! supersampling path 16) and what a multisampling GPU resolves; its departures from the
//! exact area are at most a sample's share per crossing edge, and it adds up exactly
//! across a triangulation (each sample has one owner).

use num_rational::BigRational;
use num_traits::Zero;

use super::{AreaImage, AreaShape, Semantics};
use crate::convention::AnyTieRule;
use crate::fill::polygon::contains_exact_with;
use crate::geom::Point;

/// The shapes' supersampled coverage on a `width` x `height` canvas: for each pixel the
/// share of its `k x k` samples inside any shape (true coverage's counterpart). `k` of 0 is
/// read as 1.
pub fn rasterize(shapes: &[AreaShape], width: u32, height: u32, k: u32) -> AreaImage {
    let mut pixels = Vec::new();
    for y in 0..height {
        for x in 0..width {
            let v = pixel(shapes, x, y, k);
            if !v.is_zero() {
                pixels.push((x, y, v));
            }
        }
    }
    AreaImage {
        width,
        height,
        semantics: Semantics::True,
        pixels,
    }
}

/// Pixel `(x, y)`'s supersampled value: the share of its `k x k` samples inside any shape
/// (`k` of 0 read as 1).
pub fn pixel(shapes: &[AreaShape], x: u32, y: u32, k: u32) -> BigRational {
    let k = k.max(1);
    let count: u32 = row_counts(shapes, x, y, k).iter().sum();
    BigRational::new(count.into(), (u64::from(k) * u64::from(k)).into())
}

/// How many of pixel `(x, y)`'s samples inside any shape lie in each of its `k` sample
/// rows, top to bottom (`k` of 0 read as 1), samples on an edge decided by the top-left
/// rule.
pub fn row_counts(shapes: &[AreaShape], x: u32, y: u32, k: u32) -> Vec<u32> {
    row_counts_with(shapes, x, y, k, AnyTieRule::TopLeft)
}

/// [`row_counts`] with samples on an edge decided by `rule`.
pub fn row_counts_with(shapes: &[AreaShape], x: u32, y: u32, k: u32, rule: AnyTieRule) -> Vec<u32> {
    let k = k.max(1);
    let step = |i: u32| BigRational::new((2 * i64::from(i) + 1).into(), (2 * i64::from(k)).into());
    (0..k)
        .map(|j| {
            let inside = (0..k).filter(|&i| {
                let p = Point::new(
                    BigRational::from_integer(x.into()) + step(i),
                    BigRational::from_integer(y.into()) + step(j),
                );
                shapes.iter().any(|s| contains_exact_with(&p, s, rule))
            });
            u32::try_from(inside.count()).unwrap_or(u32::MAX)
        })
        .collect()
}

/// Pixel `(x, y)`'s supersampled value under each tie rule of [`AnyTieRule::ALL`] (the
/// share of its `k x k` samples inside any shape, samples on an edge decided by that rule),
/// each value once.
pub fn pixel_under_each_rule(shapes: &[AreaShape], x: u32, y: u32, k: u32) -> Vec<BigRational> {
    let k = k.max(1);
    let mut out: Vec<BigRational> = Vec::new();
    for rule in AnyTieRule::ALL {
        let count: u32 = row_counts_with(shapes, x, y, k, rule).iter().sum();
        let v = BigRational::new(count.into(), (u64::from(k) * u64::from(k)).into());
        if !out.contains(&v) {
            out.push(v);
        }
    }
    out
}

/// The 8-bit levels of tiny-skia's anti-aliased fill (after Skia's supersampling
/// scan converter, `SkScan_AntiPath.cpp`; tiny-skia's `scan/path_aa.rs`), from exact 4 x 4
/// samples, row by row: four sub-scanlines per pixel, each adding 16 per sample inside,
/// except that a sub-scanline whose four samples are all inside adds the full-run value
/// `64 - 1` on the pixel's last (bottom) sub-scanline, so that a whole pixel is 255, not
/// 256. A pixel is `16 n`, less 1 when its bottom sample row is full. A sample on an edge
/// goes by the bottom-right rule: its edges' rows start and its spans' ends are rounded
/// half up (`SkFDot6Round`), so a bottom or right edge takes the samples on it, a top or
/// left edge does not (tiny-skia 0.11.4 draws 64 for the top eighth of a pixel, 0 for the
/// bottom eighth). Shapes are taken as one union of samples (tiny-skia composites separate
/// paths source-over: [`super::conflate`]), and tiny-skia's own fixed-point edges can move
/// a sample that lies within about 1/256 px of an edge.
pub fn tiny_skia_levels(shapes: &[AreaShape], width: u32, height: u32) -> Vec<u8> {
    let mut out = Vec::with_capacity(width as usize * height as usize);
    for y in 0..height {
        for x in 0..width {
            let rows = row_counts_with(shapes, x, y, 4, AnyTieRule::BottomRight);
            let n: u32 = rows.iter().sum();
            let level = 16 * n - u32::from(rows[3] == 4);
            out.push(u8::try_from(level.min(255)).unwrap_or(u8::MAX));
        }
    }
    out
}
