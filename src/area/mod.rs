//! Anti-aliased area coverage, exactly: for each pixel the fraction of its unit square that
//! a shape covers, as an exact rational.
//!
//! Font and vector renderers do not take one sample per pixel: they output the *area* of
//! the pixel inside the shape, quantized to a grey level. Two semantics are in use, and
//! they differ where contours overlap, so every output names its [`Semantics`]:
//!
//! - **true coverage** ([`Semantics::True`]): the area of `{p in the pixel : p is inside
//!   under the fill rule}`;
//! - **accumulated coverage** ([`Semantics::Accumulated`]): the integral of the winding
//!   number over the pixel, then folded as FreeType's smooth rasterizer folds its signed
//!   cell areas (`ftgrays.c`, `gray_hline`): nonzero `min(1, |acc|)`, even-odd `|acc|`
//!   reduced modulo 2 and reflected above 1. It is what scanline accumulation renderers
//!   compute (libart, FreeType's `ftgrays.c`, font-rs, ab_glyph_rasterizer), and equals
//!   true coverage wherever the contours do not overlap;
//! - [`Semantics::AccumulatedUnclamped`]: `|acc|` with no fold, as font-rs and
//!   ab_glyph_rasterizer leave it (overlapping contours exceed 1).
//!
//! A scene's pixel value is, under true coverage, the area of the union of its shapes
//! (a mesh of abutting triangles covers its pixels exactly once: no seam, no double
//! count); under the accumulated semantics, the sum over the shapes of each shape's folded
//! value (what a renderer that adds each shape into one accumulation buffer computes).
//!
//! The family: [`exact`], the plain oracle (each pixel cut into trapezoids between the
//! edges, each trapezoid's area and winding numbers exact); [`cells`], the accumulated
//! semantics by signed-area cell accumulation (the scanline renderers' method), exactly;
//! [`planned`], the same accumulation in machine integers where the shape's numbers allow
//! it (the planned engine, equal to the others);
//! the contenders: [`float`], the same accumulation in f32 (font-rs, ab_glyph_rasterizer),
//! [`ftgrays`], FreeType's smooth rasterizer's integer method (26.6 points, 24.8 cells,
//! 8-bit levels),
//! [`supersample`], k x k point samples per pixel counted exactly, and [`conflate`], the
//! shapes' own values blended one by one (source-over);
//! and two real renderers modelled exactly, each as its adapter feeds it the whole scene
//! as one path: [`abglyph`], ab_glyph_rasterizer 0.1.10's f32 arithmetic (one widened
//! buffer, one running sum, 16-bit levels), and [`zeno`], zeno 0.3.3's integers
//! (FreeType's walk y down, 24.8 straight from f32, a 32-bit reciprocal, 8-bit levels).
//! A grey image quantizes the exact values by a named [`Quantization`].
//!
//! [`method`] is the family's one list ([`AreaMethod::ALL`]): each method's name, what it
//! computes and how it draws, which the trade and `compare --as grey --fit` both walk.

pub mod abglyph;
pub mod cells;
pub mod conflate;
pub mod exact;
pub mod float;
pub mod ftgrays;
pub mod method;
pub mod planned;
pub mod supersample;
pub mod zeno;

pub use method::{AreaMethod, AreaOutput};

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::geom::{FillRule, Point, Polygon, Triangle};
use crate::num::exact::{round_to_integer, Rounding};

/// Which area a pixel's value measures (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Semantics {
    /// The area of the pixel inside the shape under its fill rule.
    True,
    /// The integral of the winding number over the pixel, folded as FreeType does.
    Accumulated,
    /// The absolute integral of the winding number, not folded (font-rs, ab_glyph).
    AccumulatedUnclamped,
}

impl Semantics {
    /// Every semantics, in the order of the documentation.
    pub const ALL: [Semantics; 3] = [Semantics::True, Semantics::Accumulated, Semantics::AccumulatedUnclamped];

    /// Its name on the command line and in JSON: `true`, `accumulated`, `unclamped`.
    pub fn name(self) -> &'static str {
        match self {
            Semantics::True => "true",
            Semantics::Accumulated => "accumulated",
            Semantics::AccumulatedUnclamped => "unclamped",
        }
    }

    /// The semantics named `name` ([`Semantics::name`]).
    pub fn from_name(name: &str) -> Option<Semantics> {
        Semantics::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// The shape whose area is measured: a [`Polygon`] (a triangle is a polygon of one
/// contour, [`triangle_shape`]), read as the crate reads it everywhere: inside where the
/// outline's winding number is inside under the fill rule and no hole's is. Contours may
/// cross, overlap, touch and be degenerate.
///
/// Its *path* (what a scanline renderer accumulates) is its contours as given, the outline
/// and the holes alike: their winding numbers add ([`path_winding`]). A hole that runs
/// against the outline (as glyph outlines are drawn) winds 0 inside, so for a simple
/// outline with disjoint simple holes accumulated coverage equals true coverage; a hole
/// that runs the outline's way winds 2 there, which nonzero accumulation fills, as
/// FreeType does.
pub type AreaShape = Polygon;

/// A triangle as an [`AreaShape`]: its one contour, nonzero.
pub fn triangle_shape(t: &Triangle) -> AreaShape {
    Polygon::new(t.v.to_vec(), FillRule::NonZero)
}

/// Whether a point whose winding numbers about `poly`'s contours (the outline, then each
/// hole) are `windings` is inside `poly`.
pub fn inside(poly: &Polygon, windings: &[i64]) -> bool {
    let rule = |w: i64| match poly.fill_rule {
        FillRule::NonZero => w != 0,
        FillRule::EvenOdd => w % 2 != 0,
    };
    rule(windings[0]) && !windings[1..].iter().any(|&w| rule(w))
}

/// The winding number of `poly`'s path (see [`AreaShape`]) at a point whose winding
/// numbers about its contours are `windings`: their sum.
pub fn path_winding(windings: &[i64]) -> i64 {
    windings.iter().sum()
}

/// The signed area of `poly`'s path: the integral of [`path_winding`] over the plane, the
/// sum of its contours' shoelace sums.
pub fn path_signed_area(poly: &Polygon) -> BigRational {
    poly.contours().map(shoelace).sum()
}

/// The accumulated value `acc` (the integral of the path's winding number over a pixel)
/// folded under `semantics` for `fill_rule` (`True` is not a fold of `acc`: it is
/// returned as `|acc|`, right for a shape whose path winds at most once).
pub fn fold(fill_rule: FillRule, acc: &BigRational, semantics: Semantics) -> BigRational {
    let a = acc.abs();
    match (semantics, fill_rule) {
        (Semantics::AccumulatedUnclamped, _) | (Semantics::True, _) => a,
        (Semantics::Accumulated, FillRule::NonZero) => a.min(BigRational::one()),
        (Semantics::Accumulated, FillRule::EvenOdd) => {
            let two = BigRational::from_integer(2.into());
            let m = &a - (&a / &two).floor() * &two;
            if m > BigRational::one() {
                two - m
            } else {
                m
            }
        }
    }
}

/// The signed area of a closed contour: half the sum of `x_i y_(i+1) - x_(i+1) y_i`.
pub fn shoelace(contour: &[Point]) -> BigRational {
    let n = contour.len();
    let twice: BigRational = (0..n)
        .map(|i| {
            let (a, b) = (&contour[i], &contour[(i + 1) % n]);
            &a.x * &b.y - &b.x * &a.y
        })
        .sum();
    twice / BigRational::from_integer(2.into())
}

/// How exact coverage becomes a grey level: the value `v` (clamped to `[0, 1]` first,
/// except where said) to an integer of the image's bit depth.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Quantization {
    /// `v x 255` rounded to the nearest, ties to even (8 bits).
    Round8,
    /// `v x 255` rounded towards zero (8 bits).
    Truncate8,
    /// FreeType's smooth rasterizer: the area in 1/256 units truncated, 256 clamped to 255
    /// (`ftgrays.c`: `coverage >> (PIXEL_BITS * 2 + 1 - 8)`, then `if (coverage >= 256)
    /// coverage = 255`), that is `min(255, floor(v x 256))` (8 bits).
    FtGrays,
    /// `v x 65535` rounded to the nearest, ties to even (16 bits).
    Round16,
}

impl Quantization {
    /// Every quantization.
    pub const ALL: [Quantization; 4] = [
        Quantization::Round8,
        Quantization::Truncate8,
        Quantization::FtGrays,
        Quantization::Round16,
    ];

    /// Its name on the command line: `round`, `truncate`, `ftgrays`, `round16`.
    pub fn name(self) -> &'static str {
        match self {
            Quantization::Round8 => "round",
            Quantization::Truncate8 => "truncate",
            Quantization::FtGrays => "ftgrays",
            Quantization::Round16 => "round16",
        }
    }

    /// The quantization named `name`.
    pub fn from_name(name: &str) -> Option<Quantization> {
        Quantization::ALL.into_iter().find(|q| q.name() == name)
    }

    /// The quantization of the same kind that makes `bits`-bit levels: rounding at 8 and
    /// at 16 bits are each other's; truncation and FreeType's levels are 8-bit only
    /// (`None` at 16).
    ///
    /// ```
    /// use rasterproof::area::Quantization;
    /// assert_eq!(Quantization::Round8.at_depth(16), Some(Quantization::Round16));
    /// assert_eq!(Quantization::Round16.at_depth(8), Some(Quantization::Round8));
    /// assert_eq!(Quantization::FtGrays.at_depth(16), None);
    /// ```
    pub fn at_depth(self, bits: u32) -> Option<Quantization> {
        match (self, bits) {
            (Quantization::Round8 | Quantization::Round16, 8) => Some(Quantization::Round8),
            (Quantization::Round8 | Quantization::Round16, 16) => Some(Quantization::Round16),
            (q, b) => (q.bits() == b).then_some(q),
        }
    }

    /// Bits per grey level: 8 or 16.
    pub fn bits(self) -> u32 {
        match self {
            Quantization::Round16 => 16,
            _ => 8,
        }
    }

    /// The grey level of the exact value `v` (clamped to `[0, 1]`).
    pub fn level(self, v: &BigRational) -> u16 {
        let v = v.clone().max(BigRational::zero()).min(BigRational::one());
        let scaled = |k: i64| &v * BigRational::from_integer(k.into());
        let level: BigInt = match self {
            Quantization::Round8 => round_to_integer(&scaled(255), Rounding::NearestEven),
            Quantization::Truncate8 => round_to_integer(&scaled(255), Rounding::Floor),
            Quantization::FtGrays => round_to_integer(&scaled(256), Rounding::Floor).min(BigInt::from(255)),
            Quantization::Round16 => round_to_integer(&scaled(65535), Rounding::NearestEven),
        };
        level.to_u16().unwrap_or(u16::MAX)
    }
}

/// A scene's exact area coverage: the pixels with a non-zero value, row by row.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AreaImage {
    /// Canvas width.
    pub width: u32,
    /// Canvas height.
    pub height: u32,
    /// The semantics of every value.
    pub semantics: Semantics,
    /// `(x, y, value)` for every pixel whose value is not zero, by row, then column.
    pub pixels: Vec<(u32, u32, BigRational)>,
}

impl AreaImage {
    /// The value of pixel `(x, y)` (zero where none is stored).
    pub fn value(&self, x: u32, y: u32) -> BigRational {
        self.pixels
            .binary_search_by(|(px, py, _)| (*py, *px).cmp(&(y, x)))
            .map_or_else(|_| BigRational::zero(), |k| self.pixels[k].2.clone())
    }

    /// The sum of every pixel's value.
    pub fn total(&self) -> BigRational {
        self.pixels.iter().map(|(_, _, v)| v).sum()
    }

    /// Values a renderer produced in f32, row-major (`width x height` of them), read
    /// exactly (every finite f32 is a fraction with a power-of-two denominator).
    ///
    /// # Errors
    /// A value that is not finite (named by its pixel), or a length that is not
    /// `width x height`.
    pub fn from_f32(width: u32, height: u32, semantics: Semantics, values: &[f32]) -> Result<AreaImage, String> {
        if values.len() != width as usize * height as usize {
            return Err(format!(
                "{} values for a {width}x{height} canvas ({} expected)",
                values.len(),
                width as usize * height as usize
            ));
        }
        let mut pixels = Vec::new();
        let positions = (0..height).flat_map(|y| (0..width).map(move |x| (x, y)));
        for (&v, (x, y)) in values.iter().zip(positions) {
            let exact =
                BigRational::from_float(v).ok_or_else(|| format!("pixel ({x}, {y}): the value {v} is not a number"))?;
            if !exact.is_zero() {
                pixels.push((x, y, exact));
            }
        }
        Ok(AreaImage {
            width,
            height,
            semantics,
            pixels,
        })
    }

    /// Hands out the image row by row: `emit(y, pixels)` for every row of the canvas, top
    /// first, with the row's `(x, value)` by column.
    pub fn for_each_row(self, mut emit: impl FnMut(u32, Vec<(u32, BigRational)>)) {
        let mut pixels = self.pixels.into_iter().peekable();
        for y in 0..self.height {
            let mut row = Vec::new();
            while let Some((x, _, v)) = pixels.next_if(|p| p.1 == y) {
                row.push((x, v));
            }
            emit(y, row);
        }
    }

    /// The grey levels, row by row (`width x height`), under `q`.
    pub fn levels(&self, q: Quantization) -> Vec<u16> {
        let mut out = vec![0u16; self.width as usize * self.height as usize];
        for (x, y, v) in &self.pixels {
            out[*y as usize * self.width as usize + *x as usize] = q.level(v);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn quantizations_by_hand() {
        // 1/2: 127.5 -> 128 (even), truncated 127, ftgrays 128, 16 bits 32767.5 -> 32768.
        let half = r(1, 2);
        let q = |q: Quantization, v: &BigRational| q.level(v);
        assert_eq!(q(Quantization::Round8, &half), 128);
        assert_eq!(q(Quantization::Truncate8, &half), 127);
        assert_eq!(q(Quantization::FtGrays, &half), 128);
        assert_eq!(q(Quantization::Round16, &half), 32768);
        // 3/510 x 255 = 1.5 -> 2 (even); 1/510 x 255 = 0.5 -> 0 (even).
        assert_eq!(q(Quantization::Round8, &r(3, 510)), 2);
        assert_eq!(q(Quantization::Round8, &r(1, 510)), 0);
        // Full coverage: ftgrays clamps 256 to 255; above 1 and below 0 are clamped.
        assert_eq!(q(Quantization::FtGrays, &r(1, 1)), 255);
        assert_eq!(q(Quantization::FtGrays, &r(255, 256)), 255);
        assert_eq!(q(Quantization::FtGrays, &r(254, 256)), 254);
        assert_eq!(q(Quantization::Round8, &r(5, 4)), 255);
        assert_eq!(q(Quantization::Truncate8, &r(-1, 4)), 0);
    }

    #[test]
    fn folds_by_hand() {
        let f = |rule, acc: BigRational, sem| fold(rule, &acc, sem);
        let (nz, eo) = (FillRule::NonZero, FillRule::EvenOdd);
        assert_eq!(f(nz, r(-5, 4), Semantics::Accumulated), r(1, 1));
        assert_eq!(f(nz, r(-5, 4), Semantics::AccumulatedUnclamped), r(5, 4));
        // Even-odd: 5/4 -> 2 - 5/4; 9/4 -> 1/4; 2 -> 0; 3/4 stays.
        assert_eq!(f(eo, r(5, 4), Semantics::Accumulated), r(3, 4));
        assert_eq!(f(eo, r(-9, 4), Semantics::Accumulated), r(1, 4));
        assert_eq!(f(eo, r(2, 1), Semantics::Accumulated), r(0, 1));
        assert_eq!(f(eo, r(3, 4), Semantics::Accumulated), r(3, 4));
    }

    #[test]
    fn holes_add_to_the_path_as_given() {
        let p = |x: i64, y: i64| Point::new(r(x, 1), r(y, 1));
        let outline = vec![p(0, 0), p(4, 0), p(4, 4), p(0, 4)];
        let same = vec![p(1, 1), p(2, 1), p(2, 2), p(1, 2)];
        let mut against = same.clone();
        against.reverse();
        // Inside the hole: winding 1 about the outline, +-1 about the hole; the hole is
        // outside the polygon either way, and the path winds 2 or 0 there.
        for (hole, w, path, area) in [(same, 1, 2, 17), (against, -1, 0, 15)] {
            let poly = Polygon {
                outline: outline.clone(),
                holes: vec![hole],
                fill_rule: FillRule::NonZero,
            };
            assert_eq!(path_winding(&[1, w]), path);
            assert!(!inside(&poly, &[1, w]));
            assert!(inside(&poly, &[1, 0]));
            assert_eq!(path_signed_area(&poly), r(area, 1));
        }
    }

    #[test]
    fn shoelace_by_hand() {
        let p = |x: i64, y: i64| Point::new(r(x, 1), r(y, 1));
        // A 2x3 rectangle, counter-clockwise in y-up terms: +6; reversed: -6.
        let rect = [p(0, 0), p(2, 0), p(2, 3), p(0, 3)];
        assert_eq!(shoelace(&rect), r(6, 1));
        let mut rev = rect.to_vec();
        rev.reverse();
        assert_eq!(shoelace(&rev), r(-6, 1));
    }
}
