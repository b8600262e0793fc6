//! The area family's one list: every way this crate computes a pixel's grey value
//! ([`AreaMethod::ALL`]), each with its name, the semantics it computes, and how it draws
//! shapes on a canvas ([`AreaMethod::draw`], and [`AreaMethod::draw_at`] with the canvas
//! far from the origin), into one [`AreaOutput`]. The trade measures these methods against
//! the exact value, and `compare --as grey --fit` tries each under every quantization:
//! a method added here is measured and tried by both.
//!
//! How shapes combine follows the semantics (see the module documentation of
//! [`crate::area`]): under [`Semantics::True`] a method that tests samples takes the
//! shapes as one union; under the accumulated semantics each shape is drawn alone and the
//! outputs added (counts exactly, 8-bit levels saturating, as FreeType's passes add),
//! which is what a renderer adding each shape into one buffer computes.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

use super::{abglyph, cells, conflate, exact, float, ftgrays, planned, supersample, zeno};
use super::{AreaImage, AreaShape, Quantization, Semantics};
use crate::convention::AnyTieRule;

/// The supersampling sides in the list: `k x k` samples per pixel.
pub const SUPERSAMPLE_SIDES: [u32; 4] = [2, 4, 8, 16];

/// One way to compute a pixel's area or grey level.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AreaMethod {
    /// [`exact`], the plain oracle: trapezoids between the edges, exact.
    Plain,
    /// [`cells`], signed-area cell accumulation in big rationals, exact (no inside test:
    /// the accumulated semantics only).
    Cells,
    /// [`planned`], the same accumulation in machine integers where the shape's numbers
    /// allow it: the fastest exact engine, the reference.
    Planned,
    /// [`supersample`]: the share of `k x k` point samples covered, counted exactly.
    Supersample(u32),
    /// [`float`]: signed-area accumulation in f32 (font-rs and ab_glyph_rasterizer's
    /// method), folded as FreeType folds.
    Float,
    /// [`conflate`]: each shape's exact value blended source-over onto the shapes before it.
    Conflated,
    /// [`ftgrays`]: FreeType's smooth rasterizer's integer method, its 8-bit levels, each
    /// shape its own pass.
    FtGrays,
    /// [`supersample::tiny_skia_levels`]: tiny-skia's anti-aliasing, 4 x 4 samples and its
    /// 8-bit levels.
    TinySkia,
    /// [`abglyph`]: ab_glyph_rasterizer's f32 accumulation of every shape in one buffer,
    /// 16-bit levels rounded from its value clamped to 1.
    AbGlyph,
    /// [`zeno`]: zeno's rasterizer, FreeType's method with a 32-bit reciprocal and f32
    /// input, every shape in one path, 8-bit levels.
    Zeno,
}

impl AreaMethod {
    /// Every method: the exact engines first, then those that depart from the exact value
    /// and quantize it, then those that make their own levels.
    pub const ALL: [AreaMethod; 13] = [
        AreaMethod::Plain,
        AreaMethod::Cells,
        AreaMethod::Planned,
        AreaMethod::Supersample(SUPERSAMPLE_SIDES[0]),
        AreaMethod::Supersample(SUPERSAMPLE_SIDES[1]),
        AreaMethod::Supersample(SUPERSAMPLE_SIDES[2]),
        AreaMethod::Supersample(SUPERSAMPLE_SIDES[3]),
        AreaMethod::Float,
        AreaMethod::Conflated,
        AreaMethod::FtGrays,
        AreaMethod::TinySkia,
        AreaMethod::Zeno,
        AreaMethod::AbGlyph,
    ];

    /// Its short name (the trade's contender name). A supersampling side outside
    /// [`SUPERSAMPLE_SIDES`] is named `supersample-kxk`.
    pub fn name(self) -> &'static str {
        match self {
            AreaMethod::Plain => "area-plain",
            AreaMethod::Cells => "area-cells",
            AreaMethod::Planned => "area-planned",
            AreaMethod::Supersample(2) => "supersample-2x2",
            AreaMethod::Supersample(4) => "supersample-4x4",
            AreaMethod::Supersample(8) => "supersample-8x8",
            AreaMethod::Supersample(16) => "supersample-16x16",
            AreaMethod::Supersample(_) => "supersample-kxk",
            AreaMethod::Float => "f32-accum",
            AreaMethod::Conflated => "conflated",
            AreaMethod::FtGrays => "ftgrays",
            AreaMethod::TinySkia => "tiny-skia-4x4",
            AreaMethod::AbGlyph => "ab-glyph",
            AreaMethod::Zeno => "zeno",
        }
    }

    /// In words, computing under `semantics`.
    pub fn describe(self, semantics: Semantics) -> String {
        match self {
            AreaMethod::Plain | AreaMethod::Cells | AreaMethod::Planned => {
                format!("exact {} coverage", semantics.name())
            }
            AreaMethod::Supersample(k) => format!("{k}x{k} supersampling"),
            AreaMethod::Float => "f32 accumulation".to_string(),
            AreaMethod::Conflated => {
                "each shape's exact accumulated coverage blended source-over (conflation)".to_string()
            }
            AreaMethod::FtGrays => "FreeType's smooth rasterizer (ftgrays.c's integer method)".to_string(),
            AreaMethod::TinySkia => "tiny-skia's anti-aliasing (4x4 supersampling, its 8-bit levels)".to_string(),
            AreaMethod::AbGlyph => {
                "ab_glyph_rasterizer's f32 accumulation (one buffer, round16 of its value clamped to 1)".to_string()
            }
            AreaMethod::Zeno => "zeno's rasterizer (FreeType's method, 32-bit reciprocal, f32 input)".to_string(),
        }
    }

    /// Its answer is the exact value (every exact engine gives the same one).
    pub fn is_exact(self) -> bool {
        matches!(self, AreaMethod::Plain | AreaMethod::Cells | AreaMethod::Planned)
    }

    /// The exact engine to ask for the exact value: the fastest.
    pub const REFERENCE: AreaMethod = AreaMethod::Planned;

    /// The bits of the levels it makes itself (`None` where it computes a value that a
    /// [`Quantization`] turns into levels).
    pub fn own_bits(self) -> Option<u32> {
        match self {
            AreaMethod::FtGrays | AreaMethod::TinySkia | AreaMethod::Zeno => Some(8),
            AreaMethod::AbGlyph => Some(16),
            _ => None,
        }
    }

    /// The semantics it computes when it draws the scene as one (the union for sample
    /// tests, the accumulation for the scanline methods).
    pub fn native_semantics(self) -> Semantics {
        match self {
            AreaMethod::Plain | AreaMethod::Planned | AreaMethod::Supersample(_) | AreaMethod::TinySkia => {
                Semantics::True
            }
            _ => Semantics::Accumulated,
        }
    }

    /// Computes `semantics` (see [`AreaMethod::draw`]).
    pub fn computes(self, semantics: Semantics) -> bool {
        match self {
            AreaMethod::Plain | AreaMethod::Planned | AreaMethod::Conflated => true,
            AreaMethod::Cells | AreaMethod::Float => semantics != Semantics::True,
            AreaMethod::Supersample(_) | AreaMethod::TinySkia => semantics != Semantics::AccumulatedUnclamped,
            AreaMethod::FtGrays | AreaMethod::AbGlyph | AreaMethod::Zeno => semantics == Semantics::Accumulated,
        }
    }

    /// The method's output for `shapes` on a `width` x `height` canvas at the origin,
    /// under `semantics`: the exact engines and conflation under any; the sample methods
    /// (supersampling, tiny-skia) the union under `True` and each shape alone, added,
    /// under `Accumulated`; f32 accumulation both accumulated semantics; FreeType's,
    /// ab_glyph's and zeno's methods `Accumulated`, the one they compute.
    ///
    /// # Errors
    /// A semantics the method does not compute ([`AreaMethod::computes`]), or the
    /// method's own refusal (FreeType's 24.8 envelope, ab_glyph's and zeno's limits).
    pub fn draw(
        self,
        shapes: &[AreaShape],
        width: u32,
        height: u32,
        semantics: Semantics,
    ) -> Result<AreaOutput, String> {
        if !self.computes(semantics) {
            return Err(format!(
                "{} does not compute {} coverage",
                self.name(),
                semantics.name()
            ));
        }
        let each_alone = semantics != Semantics::True;
        Ok(match self {
            AreaMethod::Plain => AreaOutput::Exact(exact::rasterize(shapes, width, height, semantics)),
            AreaMethod::Cells => AreaOutput::Exact(
                cells::rasterize(shapes, width, height, semantics).ok_or("cells compute the accumulated semantics")?,
            ),
            AreaMethod::Planned => AreaOutput::Exact(planned::rasterize(shapes, width, height, semantics)),
            AreaMethod::Supersample(k) if each_alone => supersample_counts(shapes, width, height, k),
            AreaMethod::Supersample(k) => AreaOutput::Exact(supersample::rasterize(shapes, width, height, k)),
            AreaMethod::Float => AreaOutput::F32(float::rasterize(shapes, width, height, semantics)),
            AreaMethod::Conflated => AreaOutput::Exact(conflate::rasterize(shapes, width, height, semantics)),
            AreaMethod::FtGrays => AreaOutput::levels8(ftgrays::rasterize(shapes, width, height)?),
            AreaMethod::TinySkia if each_alone => {
                let mut levels = vec![0u8; width as usize * height as usize];
                for s in shapes {
                    let one = supersample::tiny_skia_levels(std::slice::from_ref(s), width, height);
                    for (l, v) in levels.iter_mut().zip(one) {
                        *l = l.saturating_add(v);
                    }
                }
                AreaOutput::levels8(levels)
            }
            AreaMethod::TinySkia => AreaOutput::levels8(supersample::tiny_skia_levels(shapes, width, height)),
            AreaMethod::AbGlyph => AreaOutput::Levels {
                levels: abglyph::levels(shapes, width, height)?,
                bits: 16,
            },
            AreaMethod::Zeno => AreaOutput::levels8(zeno::rasterize(shapes, width, height)?),
        })
    }

    /// The method's output on the `width` x `height` canvas whose top-left corner is at
    /// `(origin, origin)`, for `shapes` given in that canvas's own coordinates: what it
    /// computes with the placed coordinates. The methods that round them compute there
    /// (f32 accumulation by [`float::rasterize_at`], FreeType's by
    /// [`ftgrays::rasterize_at`]); `None` for the others, whose answer a whole-pixel move
    /// leaves unchanged (exact arithmetic, or samples decided exactly).
    ///
    /// # Errors
    /// As [`AreaMethod::draw`], FreeType's envelope at the placed coordinates included.
    pub fn draw_at(
        self,
        shapes: &[AreaShape],
        origin: i64,
        width: u32,
        height: u32,
        semantics: Semantics,
    ) -> Option<Result<AreaOutput, String>> {
        if !matches!(self, AreaMethod::Float | AreaMethod::FtGrays) {
            return None;
        }
        if !self.computes(semantics) {
            return Some(self.draw(shapes, width, height, semantics));
        }
        Some(match self {
            AreaMethod::Float => {
                let placed: Vec<AreaShape> = shapes.iter().map(|s| s.translated(origin, origin)).collect();
                Ok(AreaOutput::F32(float::rasterize_at(
                    &placed, origin, width, height, semantics,
                )))
            }
            _ => ftgrays::rasterize_at(shapes, origin, width, height).map(AreaOutput::levels8),
        })
    }
}

/// Each shape's covered share of `k x k` samples, counted and added over the shapes.
fn supersample_counts(shapes: &[AreaShape], width: u32, height: u32, k: u32) -> AreaOutput {
    let k = k.max(1);
    let mut counts = vec![0u32; width as usize * height as usize];
    for s in shapes {
        let one = supersample::counts(std::slice::from_ref(s), width, height, k, AnyTieRule::TopLeft);
        for (c, n) in counts.iter_mut().zip(one) {
            *c += n;
        }
    }
    AreaOutput::Counts { counts, of: k * k }
}

/// What an area method outputs, row-major where dense.
#[derive(Debug, Clone, PartialEq)]
pub enum AreaOutput {
    /// Exact values.
    Exact(AreaImage),
    /// f32 values, read exactly.
    F32(Vec<f32>),
    /// Levels of `bits` bits, `L` read as `L / (2^bits - 1)`.
    Levels {
        /// Per pixel.
        levels: Vec<u16>,
        /// 8 or 16.
        bits: u32,
    },
    /// Sample counts, `n` read as `n / of`.
    Counts {
        /// Per pixel.
        counts: Vec<u32>,
        /// Samples per pixel.
        of: u32,
    },
}

impl AreaOutput {
    /// 8-bit levels.
    pub fn levels8(levels: Vec<u8>) -> AreaOutput {
        AreaOutput::Levels {
            levels: levels.into_iter().map(u16::from).collect(),
            bits: 8,
        }
    }

    /// The value of the pixel at row-major index `k`, exactly; `dense` is the exact
    /// image's values, row-major (read for [`AreaOutput::Exact`] only).
    pub fn value(&self, k: usize, dense: &[BigRational]) -> BigRational {
        match self {
            AreaOutput::Exact(_) => dense[k].clone(),
            AreaOutput::F32(v) => BigRational::from_float(v[k]).unwrap_or_else(BigRational::zero),
            AreaOutput::Levels { levels, bits } => {
                BigRational::new(BigInt::from(levels[k]), (BigInt::from(1) << *bits) - 1)
            }
            AreaOutput::Counts { counts, of } => BigRational::new(BigInt::from(counts[k]), BigInt::from(*of)),
        }
    }

    /// The number of values it holds (the stored pixels of an exact image).
    pub fn len(&self) -> usize {
        match self {
            AreaOutput::Exact(i) => i.pixels.len(),
            AreaOutput::F32(v) => v.len(),
            AreaOutput::Levels { levels, .. } => levels.len(),
            AreaOutput::Counts { counts, .. } => counts.len(),
        }
    }

    /// It holds no value.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Its own levels, if it made them.
    pub fn own_levels(&self) -> Option<&[u16]> {
        match self {
            AreaOutput::Levels { levels, .. } => Some(levels),
            _ => None,
        }
    }

    /// Its values as an exact image on the `width` x `height` canvas under `semantics`
    /// (`None` for levels, which are already quantized, and for f32 values that are not
    /// finite).
    pub fn to_image(&self, width: u32, height: u32, semantics: Semantics) -> Option<AreaImage> {
        match self {
            AreaOutput::Exact(image) => Some(image.clone()),
            AreaOutput::F32(v) => AreaImage::from_f32(width, height, semantics, v).ok(),
            AreaOutput::Levels { .. } => None,
            AreaOutput::Counts { counts, of } => {
                let at = |x: u32, y: u32| counts[y as usize * width as usize + x as usize];
                let pixels = (0..height)
                    .flat_map(|y| (0..width).map(move |x| (x, y)))
                    .filter(|&(x, y)| at(x, y) != 0)
                    .map(|(x, y)| (x, y, BigRational::new(BigInt::from(at(x, y)), BigInt::from(*of))))
                    .collect();
                Some(AreaImage {
                    width,
                    height,
                    semantics,
                    pixels,
                })
            }
        }
    }

    /// Its levels under `q`: its own where it made them, else its values quantized
    /// (`None` for f32 values that are not finite).
    pub fn quantized(&self, width: u32, height: u32, semantics: Semantics, q: Quantization) -> Option<Vec<u16>> {
        match self {
            AreaOutput::Levels { levels, .. } => Some(levels.clone()),
            _ => self.to_image(width, height, semantics).map(|image| image.levels(q)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::{FillRule, Point, Polygon};

    fn square(x0: i64, y0: i64, x1: i64, y1: i64) -> AreaShape {
        let p = |x: i64, y: i64| Point::new(BigRational::from_integer(x.into()), BigRational::from_integer(y.into()));
        Polygon::new(vec![p(x0, y0), p(x1, y0), p(x1, y1), p(x0, y1)], FillRule::NonZero)
    }

    /// Every method in the list has its own name, and says what it is.
    #[test]
    fn every_method_is_named_once() {
        let names: std::collections::BTreeSet<&str> = AreaMethod::ALL.iter().map(|m| m.name()).collect();
        assert_eq!(names.len(), AreaMethod::ALL.len());
        assert!(AreaMethod::ALL
            .iter()
            .all(|m| !m.describe(m.native_semantics()).is_empty()));
    }

    /// A whole pixel is 1 for every method, under each semantics it computes: the exact
    /// value, 16/16 samples, 1.0 in f32, level 255 or 65535.
    #[test]
    fn a_whole_pixel_is_one_for_every_method() {
        let shapes = [square(0, 0, 1, 1)];
        let one = BigRational::from_integer(1.into());
        for m in AreaMethod::ALL {
            for s in Semantics::ALL.into_iter().filter(|&s| m.computes(s)) {
                let out = m.draw(&shapes, 1, 1, s).unwrap_or_else(|e| panic!("{}: {e}", m.name()));
                let dense = [one.clone()];
                assert_eq!(out.value(0, &dense), one, "{} under {}", m.name(), s.name());
            }
        }
    }

    /// Two squares over one pixel: the union is 1, the accumulation each alone added is 2
    /// (counted exactly; 8-bit levels saturate at 255).
    #[test]
    fn union_under_true_each_alone_added_under_accumulated() {
        let shapes = [square(0, 0, 1, 1), square(0, 0, 1, 1)];
        let union = AreaMethod::Supersample(4).draw(&shapes, 1, 1, Semantics::True).unwrap();
        let added = AreaMethod::Supersample(4)
            .draw(&shapes, 1, 1, Semantics::Accumulated)
            .unwrap();
        assert_eq!(
            union.value(0, &[BigRational::from_integer(1.into())]),
            BigRational::from_integer(1.into())
        );
        assert_eq!(
            added,
            AreaOutput::Counts {
                counts: vec![32],
                of: 16
            }
        );
        let skia = AreaMethod::TinySkia
            .draw(&shapes, 1, 1, Semantics::Accumulated)
            .unwrap();
        assert_eq!(skia.own_levels(), Some(&[255u16][..]));
    }

    /// A semantics the method does not compute is refused, named.
    #[test]
    fn a_semantics_not_computed_is_refused() {
        let shapes = [square(0, 0, 1, 1)];
        let err = AreaMethod::FtGrays.draw(&shapes, 1, 1, Semantics::True).unwrap_err();
        assert!(err.contains("ftgrays") && err.contains("true"), "{err}");
        assert!(AreaMethod::Cells.draw(&shapes, 1, 1, Semantics::True).is_err());
    }

    /// Only the methods that round placed coordinates draw anew far from the origin.
    #[test]
    fn only_rounding_methods_draw_at_a_distance() {
        let shapes = [square(0, 0, 1, 1)];
        for m in AreaMethod::ALL {
            let at = m.draw_at(&shapes, 1 << 10, 1, 1, Semantics::Accumulated);
            assert_eq!(
                at.is_some(),
                matches!(m, AreaMethod::Float | AreaMethod::FtGrays),
                "{}",
                m.name()
            );
        }
        let far = AreaMethod::Float.draw_at(&shapes, 1 << 10, 1, 1, Semantics::Accumulated);
        assert_eq!(far.unwrap().unwrap(), AreaOutput::F32(vec![1.0]));
    }
}
