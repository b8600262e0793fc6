//! Another renderer's anti-aliased output (a grey image) against exact area coverage
//! (`compare --as grey`): per pixel their level against the exact value in units of their
//! quantum, and for each pixel that differs from the exact value's level under the named
//! quantization, the most plausible exact reason ([`GreyClass`]).

use std::collections::BTreeMap;

use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use serde_json::json;

use crate::area::{conflate, exact, planned, supersample, AreaImage, AreaShape, Quantization, Semantics};
use crate::num::exact::{exact_text, nearest_f64};

/// The supersampling counts tried (per axis).
pub const SUPERSAMPLING: [u32; 4] = [2, 4, 8, 16];

/// A grey image: one level per pixel, row-major, of `bits` bits (8 or 16).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GreyImage {
    /// Width.
    pub width: u32,
    /// Height.
    pub height: u32,
    /// Bits per level: 8 or 16.
    pub bits: u32,
    /// The levels, row-major.
    pub levels: Vec<u16>,
}

impl GreyImage {
    /// A grey PNG (8- or 16-bit grey, with or without alpha, whose alpha is ignored),
    /// named `name` in errors.
    ///
    /// # Errors
    /// Not a PNG, or another colour type: the error names the file and what it holds.
    pub fn read_png(bytes: &[u8], name: &str) -> Result<GreyImage, String> {
        // The crate's guarded decoder: a malformed palette or a hostile size is an error,
        // not a panic inside the decoder or an allocation of gigabytes.
        let image = crate::fill::flood::decode_png_as_decoded(bytes, name, crate::convention::MAX_CANVAS)
            .map_err(|e| format!("{name}: not a PNG this reader takes: {}", e.detail()))?;
        let (width, height) = (image.width(), image.height());
        match image {
            image::DynamicImage::ImageLuma8(_) | image::DynamicImage::ImageLumaA8(_) => Ok(GreyImage {
                width,
                height,
                bits: 8,
                levels: image.to_luma8().into_raw().into_iter().map(u16::from).collect(),
            }),
            image::DynamicImage::ImageLuma16(_) | image::DynamicImage::ImageLumaA16(_) => Ok(GreyImage {
                width,
                height,
                bits: 16,
                levels: image.to_luma16().into_raw(),
            }),
            other => Err(format!(
                "{name}: a {:?} PNG; --as grey reads 8- or 16-bit grey (with or without alpha)",
                other.color()
            )),
        }
    }
}

/// Why their level differs from the exact value's, the most plausible first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum GreyClass {
    /// Their level is a legal rounding of the exact value (within one quantum): another
    /// rounding than the one named; or, where several shapes share the pixel, the sum of
    /// a rounding of each shape's own value (each shape quantized on its own, the levels
    /// added).
    Quantization,
    /// Their level is a rounding (down or up) of another semantics' value, or of the
    /// accumulated value of the whole scene as one path (every shape's winding integral
    /// added in one buffer, where shapes of opposite orientations cancel), further from
    /// the stated one's than precision reaches (see [`GreyClass::Precision`]): they
    /// integrate the winding number where the stated semantics is true coverage, or the
    /// other way round, or accumulate the scene in one buffer.
    Accumulation,
    /// The pixel meets several shapes and their level is a rounding of the shapes blended
    /// one by one, source-over ([`crate::area::conflate`]: `1 - (1 - a)(1 - b)` where the
    /// exact union is `a + b`), each shape's own value exact or supersampled, further from
    /// the union than precision reaches and nearer to their level than the union is: they
    /// composite each shape on its own (a seam between abutting shapes).
    Conflation,
    /// Fixed- or floating-point error (and none of the above): within its reach of the
    /// exact value, the larger of two quanta and `1/256 + 2/256` of coverage per edge
    /// meeting the pixel (at 8 bits a level and two per edge; the reach of a cell rasterizer's rounded divisions: FreeType's `ftgrays.c`
    /// makes each crossing at most 1/256 px short, as the crate's tests of
    /// [`crate::area::ftgrays`] check).
    Precision,
    /// Beyond the precision bound, and a rounding of the share of `k x k` samples
    /// covered, samples on an edge decided by any of the tie rules
    /// ([`crate::convention::AnyTieRule`]): they supersample.
    Supersampling(u32),
    /// None of these.
    Gross,
}

impl GreyClass {
    /// In words: `quantization`, `supersampling (4x4)`, ...
    pub fn name(self) -> String {
        match self {
            GreyClass::Quantization => "quantization".into(),
            GreyClass::Accumulation => "accumulation".into(),
            GreyClass::Conflation => "conflation".into(),
            GreyClass::Supersampling(k) => format!("supersampling ({k}x{k})"),
            GreyClass::Precision => "precision".into(),
            GreyClass::Gross => "gross".into(),
        }
    }
}

/// A pixel whose level is not the exact value's under the named quantization.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GreyPixel {
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// Their level.
    pub theirs: u16,
    /// The exact value's level under the named quantization.
    pub ours: u16,
    /// The exact value.
    pub exact: BigRational,
    /// Their level less the exact value clamped to `[0, 1]`, in quanta (exact).
    pub error: BigRational,
    /// Why.
    pub class: GreyClass,
}

/// A grey comparison.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GreyReport {
    /// The canvas.
    pub width: u32,
    /// The canvas.
    pub height: u32,
    /// The semantics the exact values follow.
    pub semantics: Semantics,
    /// Their named quantization.
    pub quantization: Quantization,
    /// The pixels that differ, row by row.
    pub pixels: Vec<GreyPixel>,
    /// The largest `|their level - exact value|` over the canvas, in quanta (the exact value
    /// clamped to `[0, 1]`, as every quantization clamps it).
    pub max_error: BigRational,
    /// The mean of `|their level - exact value|` over the canvas, in quanta.
    pub mean_error: BigRational,
    /// How many pixels are off from the named quantization's level by each number of
    /// levels (0 included).
    pub histogram: BTreeMap<u32, u64>,
}

/// Levels per unit of coverage: 256 for FreeType's quantization, else the largest level.
fn scale(q: Quantization) -> i64 {
    match q {
        Quantization::FtGrays => 256,
        Quantization::Round16 => 65535,
        _ => 255,
    }
}

/// Whether `level` is a rounding (down or up) of `v x scale`, clamped to `[0, top]`.
fn rounds(level: u16, v: &BigRational, s: i64, top: u16) -> bool {
    let scaled = v.clone().max(BigRational::zero()) * BigRational::from_integer(s.into());
    let clamp = |b: num_bigint::BigInt| b.to_i64().unwrap_or(i64::MAX).clamp(0, i64::from(top));
    let (lo, hi) = (clamp(scaled.floor().to_integer()), clamp(scaled.ceil().to_integer()));
    (lo..=hi).contains(&i64::from(level))
}

/// Pixel `(x, y)`'s accumulated value with every shape in one path (one accumulation
/// buffer, as ab_glyph_rasterizer and zeno are fed a whole scene): the signed integrals
/// of all the shapes added, then folded by the first shape's fill rule (a shape of the
/// opposite orientation cancels another there).
fn one_path(shapes: &[AreaShape], x: u32, y: u32) -> BigRational {
    let Some(first) = shapes.first() else {
        return BigRational::zero();
    };
    let (_, accumulated) = exact::pixel(shapes, i64::from(x), i64::from(y));
    let sum: BigRational = accumulated.iter().sum();
    crate::area::fold(first.fill_rule, &sum, Semantics::Accumulated)
}

/// Whether two values (clamped to `[0, 1]`) differ by more than `reach` quanta: an
/// explanation by another value (another semantics, the shapes blended) is claimed only
/// where precision could not also explain the level.
fn beyond(a: &BigRational, b: &BigRational, s: i64, reach: &BigRational) -> bool {
    let clamp = |v: &BigRational| v.clone().max(BigRational::zero()).min(BigRational::one());
    (clamp(a) - clamp(b)).abs() * BigRational::from_integer(s.into()) > *reach
}

/// How many shape edges meet pixel `(x, y)`'s square.
fn edges_meeting(shapes: &[AreaShape], x: u32, y: u32) -> u32 {
    let edges = exact::explain(shapes, i64::from(x), i64::from(y)).edges.len();
    u32::try_from(edges).unwrap_or(u32::MAX / 4).min(u32::MAX / 4)
}

/// Whether `level` lies between the sums of the floors and of the ceilings of each shape's
/// own value times `s` (each clamped to `[0, top]`, the sum too): a renderer that
/// quantizes every shape on its own and adds the levels (a glyph at a time).
fn rounds_per_shape(
    (shapes, boxes): (&[AreaShape], &conflate::Boxes),
    (x, y): (u32, u32),
    (semantics, v): (Semantics, &BigRational),
    level: u16,
    s: i64,
    top: u16,
) -> bool {
    if shapes.len() < 2 {
        return false;
    }
    let values = conflate::own_values(shapes, boxes, x, y, conflate::Own::Exact(semantics));
    // Only where the shapes' own values add up to the pixel's (no overlap under true
    // coverage): then the levels added are a rounding of each part of it.
    if values.len() < 2 || values.iter().sum::<BigRational>() != *v {
        return false;
    }
    let scale = BigRational::from_integer(s.into());
    let clamp = |b: num_bigint::BigInt| b.to_i64().unwrap_or(i64::MAX).clamp(0, i64::from(top));
    let (mut lo, mut hi) = (0i64, 0i64);
    for v in &values {
        let scaled = v * &scale;
        lo += clamp(scaled.floor().to_integer());
        hi += clamp(scaled.ceil().to_integer());
    }
    let top = i64::from(top);
    (lo.min(top)..=hi.min(top)).contains(&i64::from(level))
}

/// Whether `level` is explained by conflation at pixel `(x, y)` (see
/// [`GreyClass::Conflation`]): two or more shapes have a share of the pixel, and their own
/// values (exact under `semantics`, or supersampled `k x k`) blended one by one round to
/// `level` (down or up), further than `reach` quanta from the exact value `v` and from
/// what the same values give unblended
/// (the exact value `v`; the `k x k` share of the union under true coverage, the shares
/// summed under the accumulated semantics), which lies further from `level`.
fn conflated(
    (shapes, boxes): (&[AreaShape], &conflate::Boxes),
    (x, y): (u32, u32),
    semantics: Semantics,
    (level, top): (u16, u16),
    v: &BigRational,
    (s, reach): (i64, &BigRational),
) -> bool {
    if shapes.len() < 2 {
        return false;
    }
    let scale = BigRational::from_integer(s.into());
    let theirs = BigRational::from_integer(level.into());
    let off = |value: &BigRational| (&theirs - value * &scale).abs();
    std::iter::once(conflate::Own::Exact(semantics))
        .chain(SUPERSAMPLING.into_iter().map(conflate::Own::Supersampled))
        .any(|own| {
            let values = conflate::own_values(shapes, boxes, x, y, own);
            if values.len() < 2 {
                return false;
            }
            // What the same values give without blending: the exact value, or the `k x k`
            // share of the union (true coverage) or the shares summed (accumulated).
            let union = match own {
                conflate::Own::Exact(_) => v.clone(),
                conflate::Own::Supersampled(k) if semantics == Semantics::True => supersample::pixel(shapes, x, y, k),
                conflate::Own::Supersampled(_) => values.iter().sum(),
            };
            let blended = conflate::blend(&values);
            rounds(level, &blended, s, top)
                && off(&blended) < off(&union)
                && beyond(&blended, &union, s, reach)
                && beyond(&blended, v, s, reach)
        })
}

/// Compares `theirs` with the exact area coverage of `shapes` under `semantics`, their
/// levels read under `quantization`.
///
/// # Errors
/// Their image's size or bit depth does not fit the canvas or the quantization.
pub fn compare_grey(
    shapes: &[AreaShape],
    theirs: &GreyImage,
    width: u32,
    height: u32,
    semantics: Semantics,
    quantization: Quantization,
) -> Result<GreyReport, String> {
    if (theirs.width, theirs.height) != (width, height) {
        return Err(format!(
            "their image is {}x{}, the scene's canvas {width}x{height}",
            theirs.width, theirs.height
        ));
    }
    if theirs.bits != quantization.bits() {
        return Err(format!(
            "their image has {}-bit levels; the quantization {} makes {}-bit ones",
            theirs.bits,
            quantization.name(),
            quantization.bits()
        ));
    }
    let s = scale(quantization);
    let top = u16::try_from((1u32 << theirs.bits) - 1).unwrap_or(u16::MAX);
    let others: Vec<Semantics> = Semantics::ALL.into_iter().filter(|o| *o != semantics).collect();
    let mut pixels = Vec::new();
    let (mut max_error, mut total_error) = (BigRational::zero(), BigRational::zero());
    let mut histogram = BTreeMap::new();
    // Every pixel's exact value at once (the planned engine, equal to the plain oracle).
    let values = planned::rasterize(shapes, width, height, semantics);
    // The shapes' pixel boxes, once: the per-shape classes ask at every differing pixel.
    let boxes = conflate::Boxes::of(shapes);
    for y in 0..height {
        for x in 0..width {
            let level = theirs.levels[(y * width + x) as usize];
            let v = values.value(x, y);
            let ours = quantization.level(&v);
            // Against the value a level can show: clamped to [0, 1] (the accumulated
            // semantics' sum over overlapping shapes exceeds 1; every quantization clamps).
            let shown = v.clone().max(BigRational::zero()).min(BigRational::one());
            let error = BigRational::from_integer(level.into()) - shown * BigRational::from_integer(s.into());
            max_error = max_error.max(error.abs());
            total_error += error.abs();
            *histogram.entry(u32::from(level.abs_diff(ours))).or_insert(0) += 1;
            if level == ours {
                continue;
            }
            // How far fixed-point arithmetic may stray here, in quanta: two, or 1/256 of
            // coverage and 2/256 per edge meeting the pixel (a level and two per edge at 8
            // bits). Another value explains their level only where it lies further than
            // that from the exact one.
            let cells = BigRational::new((1 + 2 * edges_meeting(shapes, x, y)).into(), 256.into());
            let reach = (cells * BigRational::from_integer(s.into())).max(BigRational::from_integer(2.into()));
            let class = if rounds(level, &v, s, top)
                || rounds_per_shape((shapes, &boxes), (x, y), (semantics, &v), level, s, top)
            {
                GreyClass::Quantization
            } else if error.abs() + BigRational::one() <= reach {
                // Another value explains a level only as one of its roundings (within a
                // quantum) and only beyond the reach from the exact value, so a level
                // within the reach less a quantum is precision: the costly checks below
                // could not name it (the same answer, sooner).
                GreyClass::Precision
            } else if others
                .iter()
                .map(|o| exact::value(shapes, i64::from(x), i64::from(y), *o))
                .chain(std::iter::once(one_path(shapes, x, y)))
                .any(|other| rounds(level, &other, s, top) && beyond(&other, &v, s, &reach))
            {
                GreyClass::Accumulation
            } else if conflated((shapes, &boxes), (x, y), semantics, (level, top), &v, (s, &reach)) {
                GreyClass::Conflation
            } else if error.abs() <= reach {
                GreyClass::Precision
            } else if let Some(k) = SUPERSAMPLING.into_iter().find(|&k| {
                supersample::pixel_under_each_rule(shapes, x, y, k)
                    .iter()
                    .any(|v| rounds(level, v, s, top))
            }) {
                GreyClass::Supersampling(k)
            } else {
                GreyClass::Gross
            };
            pixels.push(GreyPixel {
                x,
                y,
                theirs: level,
                ours,
                exact: v,
                error,
                class,
            });
        }
    }
    let count = u64::from(width) * u64::from(height);
    Ok(GreyReport {
        width,
        height,
        semantics,
        quantization,
        pixels,
        max_error,
        mean_error: total_error / BigRational::from_integer(count.max(1).into()),
        histogram,
    })
}

impl GreyReport {
    /// How many differing pixels each class explains.
    pub fn classes(&self) -> BTreeMap<GreyClass, usize> {
        let mut out = BTreeMap::new();
        for p in &self.pixels {
            *out.entry(p.class).or_insert(0) += 1;
        }
        out
    }

    /// As text: the summary, the classes, then up to `limit` pixels.
    pub fn to_text(&self, limit: usize) -> String {
        let approx = |v: &BigRational| nearest_f64(v).map_or_else(|| exact_text(v), |f| format!("{f:.4}"));
        let mut s = format!(
            "{} of {} pixels differ from the exact {} coverage quantized by {}; error in quanta: max {}, mean {}\n",
            self.pixels.len(),
            u64::from(self.width) * u64::from(self.height),
            self.semantics.name(),
            self.quantization.name(),
            approx(&self.max_error),
            approx(&self.mean_error),
        );
        for (class, n) in self.classes() {
            s.push_str(&format!("  {}: {n} pixels\n", class.name()));
        }
        let histogram: Vec<String> = self.histogram.iter().map(|(d, n)| format!("{d}: {n}")).collect();
        s.push_str(&format!("  levels off (levels: pixels): {}\n", histogram.join(", ")));
        for p in self.pixels.iter().take(limit) {
            s.push_str(&format!(
                "  ({}, {}): theirs {}, exact {} (level {}), off by {} quanta: {}\n",
                p.x,
                p.y,
                p.theirs,
                exact_text(&p.exact),
                p.ours,
                approx(&p.error),
                p.class.name()
            ));
        }
        if self.pixels.len() > limit {
            s.push_str(&format!("  ... and {} more\n", self.pixels.len() - limit));
        }
        s
    }

    /// As JSON: `{"width","height","semantics","quantization","differing","classes",
    /// "max_error","mean_error","histogram","pixels":[{"x","y","theirs","ours","exact",
    /// "error","class"}]}` (exact values as fraction strings).
    pub fn to_json(&self) -> serde_json::Value {
        json!({
            "width": self.width,
            "height": self.height,
            "semantics": self.semantics.name(),
            "quantization": self.quantization.name(),
            "differing": self.pixels.len(),
            "classes": self.classes().into_iter().map(|(c, n)| (c.name(), n)).collect::<BTreeMap<_, _>>(),
            "max_error": exact_text(&self.max_error),
            "mean_error": exact_text(&self.mean_error),
            "histogram": self.histogram.iter().map(|(d, n)| (d.to_string(), *n)).collect::<BTreeMap<_, _>>(),
            "pixels": self.pixels.iter().map(|p| json!({
                "x": p.x,
                "y": p.y,
                "theirs": p.theirs,
                "ours": p.ours,
                "exact": exact_text(&p.exact),
                "error": exact_text(&p.error),
                "class": p.class.name(),
            })).collect::<Vec<_>>(),
        })
    }
}

/// One way a renderer may produce grey levels, as `compare --as grey --fit` tries it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GreyMethod {
    /// The exact value under a semantics, quantized.
    Exact(Semantics, Quantization),
    /// The share of `k x k` samples covered, quantized.
    Supersampling(u32, Quantization),
    /// f32 signed-area accumulation (font-rs, ab_glyph's method), folded as FreeType
    /// folds, quantized.
    Float(Quantization),
    /// Each shape's exact accumulated coverage, blended one by one source-over
    /// ([`crate::area::conflate`]), quantized.
    Conflated(Quantization),
    /// FreeType's smooth rasterizer's integer method ([`crate::area::ftgrays`]).
    FtGrays,
    /// tiny-skia's anti-aliasing: 4 x 4 samples and its levels
    /// ([`crate::area::supersample::tiny_skia_levels`]).
    TinySkia,
    /// ab_glyph_rasterizer's f32 accumulation of every shape in one buffer, 16-bit levels
    /// rounded from its value clamped to 1 ([`crate::area::abglyph`]).
    AbGlyph,
    /// zeno's rasterizer, FreeType's method with a 32-bit reciprocal and f32 input
    /// ([`crate::area::zeno`]).
    Zeno,
}

impl GreyMethod {
    /// In words.
    pub fn describe(self) -> String {
        match self {
            GreyMethod::Exact(s, q) => format!("exact {} coverage, quantized by {}", s.name(), q.name()),
            GreyMethod::Supersampling(k, q) => format!("{k}x{k} supersampling, quantized by {}", q.name()),
            GreyMethod::Float(q) => format!("f32 accumulation, quantized by {}", q.name()),
            GreyMethod::Conflated(q) => format!(
                "each shape's exact accumulated coverage blended source-over (conflation), quantized by {}",
                q.name()
            ),
            GreyMethod::FtGrays => "FreeType's smooth rasterizer (ftgrays.c's integer method)".to_string(),
            GreyMethod::TinySkia => "tiny-skia's anti-aliasing (4x4 supersampling, its 8-bit levels)".to_string(),
            GreyMethod::AbGlyph => {
                "ab_glyph_rasterizer's f32 accumulation (one buffer, round16 of its value clamped to 1)".to_string()
            }
            GreyMethod::Zeno => "zeno's rasterizer (FreeType's method, 32-bit reciprocal, f32 input)".to_string(),
        }
    }

    /// The levels this method gives `shapes` on the canvas, or `None` when it cannot draw
    /// them (FreeType's, ab_glyph's or zeno's envelope or refusals).
    pub fn levels(self, shapes: &[AreaShape], width: u32, height: u32) -> Option<Vec<u16>> {
        match self {
            GreyMethod::FtGrays => crate::area::ftgrays::rasterize(shapes, width, height)
                .ok()
                .map(|l| l.into_iter().map(u16::from).collect()),
            GreyMethod::TinySkia => Some(
                supersample::tiny_skia_levels(shapes, width, height)
                    .into_iter()
                    .map(u16::from)
                    .collect(),
            ),
            GreyMethod::AbGlyph => crate::area::abglyph::levels(shapes, width, height).ok(),
            GreyMethod::Zeno => crate::area::zeno::rasterize(shapes, width, height)
                .ok()
                .map(|l| l.into_iter().map(u16::from).collect()),
            _ => self.values(shapes, width, height).map(|(image, q)| image.levels(q)),
        }
    }

    /// The exact values the method quantizes, and how (`None` for the renderers' own
    /// methods, which make their levels themselves, and for f32 values that are not finite).
    fn values(self, shapes: &[AreaShape], width: u32, height: u32) -> Option<(AreaImage, Quantization)> {
        match self {
            GreyMethod::Exact(s, q) => Some((planned::rasterize(shapes, width, height, s), q)),
            GreyMethod::Supersampling(k, q) => Some((supersample::rasterize(shapes, width, height, k), q)),
            GreyMethod::Float(q) => {
                let values = crate::area::float::rasterize(shapes, width, height, Semantics::Accumulated);
                Some((
                    AreaImage::from_f32(width, height, Semantics::Accumulated, &values).ok()?,
                    q,
                ))
            }
            GreyMethod::Conflated(q) => Some((conflate::rasterize(shapes, width, height, Semantics::Accumulated), q)),
            GreyMethod::FtGrays | GreyMethod::TinySkia | GreyMethod::AbGlyph | GreyMethod::Zeno => None,
        }
    }

    /// Its quantization (`None` for the methods of FreeType, tiny-skia, ab_glyph and zeno,
    /// which make their own levels).
    fn quantization(self) -> Option<Quantization> {
        match self {
            GreyMethod::Exact(_, q)
            | GreyMethod::Supersampling(_, q)
            | GreyMethod::Float(q)
            | GreyMethod::Conflated(q) => Some(q),
            GreyMethod::FtGrays | GreyMethod::TinySkia | GreyMethod::AbGlyph | GreyMethod::Zeno => None,
        }
    }

    /// The same method under another quantization (the renderers' own methods keep theirs).
    fn quantized(self, q: Quantization) -> GreyMethod {
        match self {
            GreyMethod::Exact(s, _) => GreyMethod::Exact(s, q),
            GreyMethod::Supersampling(k, _) => GreyMethod::Supersampling(k, q),
            GreyMethod::Float(_) => GreyMethod::Float(q),
            GreyMethod::Conflated(_) => GreyMethod::Conflated(q),
            GreyMethod::FtGrays => GreyMethod::FtGrays,
            m @ (GreyMethod::TinySkia | GreyMethod::AbGlyph | GreyMethod::Zeno) => m,
        }
    }

    /// Every method whose levels have `bits` bits, the exact ones first.
    pub fn all(bits: u32) -> Vec<GreyMethod> {
        let qs: Vec<Quantization> = Quantization::ALL.into_iter().filter(|q| q.bits() == bits).collect();
        let mut out = Vec::new();
        for s in Semantics::ALL {
            out.extend(qs.iter().map(|&q| GreyMethod::Exact(s, q)));
        }
        for k in SUPERSAMPLING {
            out.extend(qs.iter().map(|&q| GreyMethod::Supersampling(k, q)));
        }
        out.extend(qs.iter().map(|&q| GreyMethod::Float(q)));
        out.extend(qs.iter().map(|&q| GreyMethod::Conflated(q)));
        if bits == 8 {
            out.push(GreyMethod::FtGrays);
            out.push(GreyMethod::TinySkia);
            out.push(GreyMethod::Zeno);
        } else {
            out.push(GreyMethod::AbGlyph);
        }
        out
    }
}

/// `compare --as grey --fit`: every method of [`GreyMethod::all`] with how many of their
/// pixels it gets wrong, fewest first (ties in the order tried).
///
/// # Errors
/// Their image's size does not fit the canvas.
pub fn fit_grey(
    shapes: &[AreaShape],
    theirs: &GreyImage,
    width: u32,
    height: u32,
) -> Result<Vec<(GreyMethod, usize)>, String> {
    if (theirs.width, theirs.height) != (width, height) {
        return Err(format!(
            "their image is {}x{}, the scene's canvas {width}x{height}",
            theirs.width, theirs.height
        ));
    }
    // Each method's values are computed once (the exact ones are the costly part) and
    // quantized as each of its methods asks.
    let mut values: Vec<(GreyMethod, Option<(AreaImage, Quantization)>)> = Vec::new();
    let mut out = Vec::new();
    for m in GreyMethod::all(theirs.bits) {
        let levels = if m.quantization().is_none() {
            m.levels(shapes, width, height)
        } else {
            // Keyed by the method under a fixed quantization.
            let key = m.quantized(Quantization::Round8);
            if !values.iter().any(|(k, _)| *k == key) {
                values.push((key, m.values(shapes, width, height)));
            }
            let q = m.quantization().unwrap_or(Quantization::Round8);
            values
                .iter()
                .find(|(k, _)| *k == key)
                .and_then(|(_, v)| v.as_ref())
                .map(|(image, _)| image.levels(q))
        };
        if let Some(levels) = levels {
            out.push((m, levels.iter().zip(&theirs.levels).filter(|(a, b)| a != b).count()));
        }
    }
    out.sort_by_key(|(_, n)| *n);
    Ok(out)
}
