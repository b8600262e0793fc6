//! Which method made a grey image: every way a renderer may produce grey levels
//! ([`GreyMethod`]: the exact value, supersampling, f32 accumulation, conflation under each
//! quantization, and the integer methods of FreeType, tiny-skia, ab_glyph and zeno), each
//! drawn exactly and compared level by level with theirs ([`fit_grey`], what `compare --as
//! grey --fit` answers, [`GreyFitReport`]).

use serde_json::{json, Value};

use crate::area::{conflate, planned, supersample, AreaImage, AreaShape, Quantization, Semantics};
use crate::convention::Target;
use crate::model::Model;
use crate::oracle::compare::grey::SUPERSAMPLING;
use crate::oracle::compare::{CompareError, Comparison, SizeMismatch};
use crate::oracle::theirs::GreyImage;

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

/// What a grey fit found: every method tried with how many of their pixels it gets wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GreyFitReport {
    /// The exact model the scene's shapes came from.
    pub model: Model,
    /// Every method of [`GreyMethod::all`] that could draw the shapes, with the number of
    /// their pixels whose level it does not give, fewest first (ties in the order tried).
    pub methods: Vec<(GreyMethod, usize)>,
}

impl GreyFitReport {
    /// The methods that give every level of their image.
    pub fn exact(&self) -> Vec<GreyMethod> {
        self.methods.iter().filter(|(_, n)| *n == 0).map(|(m, _)| *m).collect()
    }
}

impl Comparison for GreyFitReport {
    /// Some method gives every level of their image.
    fn identical(&self) -> bool {
        self.methods.first().is_some_and(|(_, n)| *n == 0)
    }

    /// The methods tried, and those exact.
    fn counts(&self) -> Vec<(String, usize)> {
        vec![
            ("tried".to_string(), self.methods.len()),
            ("exact".to_string(), self.exact().len()),
        ]
    }

    /// The header, then the exact methods, or the closest five with their differing pixels.
    fn to_text(&self, scene: &str, theirs: &str, _limit: usize) -> String {
        let exact = self.exact().len();
        let mut s = format!(
            "compare --as grey --fit: {theirs} against {scene} (model {})\n{} methods tried, {exact} give their image exactly\n",
            self.model,
            self.methods.len()
        );
        let shown = if exact == 0 { 5 } else { exact };
        for (m, n) in self.methods.iter().take(shown) {
            s.push_str(&format!("  {}: {n} pixels differ\n", m.describe()));
        }
        s
    }

    /// `{"tried", "methods": [{"method", "differing"}]}`, fewest differing first.
    fn to_json(&self, _scene: &str, _theirs: &str) -> Value {
        json!({
            "tried": self.methods.len(),
            "methods": self.methods.iter().map(|(m, n)| json!({"method": m.describe(), "differing": n})).collect::<Vec<_>>(),
        })
    }
}

/// `compare --as grey --fit`: every method of [`GreyMethod::all`] drawing `shapes` on
/// `target`'s canvas, with how many of their pixels it gets wrong, fewest first (ties in
/// the order tried). `model` is the exact model the shapes came from, which the report
/// names.
///
/// # Errors
/// Their image's size does not fit the canvas.
pub fn fit_grey(
    shapes: &[AreaShape],
    target: &Target,
    theirs: &GreyImage,
    model: Model,
) -> Result<GreyFitReport, CompareError> {
    SizeMismatch::check_size((theirs.width, theirs.height), target).map_err(CompareError::GreySize)?;
    let (width, height) = (target.width, target.height);
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
    Ok(GreyFitReport { model, methods: out })
}
