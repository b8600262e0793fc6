//! Which method made a grey image: every way a renderer may produce grey levels
//! ([`GreyMethod`]: each method of the area family's list, [`AreaMethod::ALL`], under each
//! quantization, or with the levels it makes itself), each
//! drawn exactly and compared level by level with theirs ([`fit_grey`], what `compare --as
//! grey --fit` answers, [`GreyFitReport`]).

use serde_json::{json, Value};

use crate::area::{AreaMethod, AreaOutput, AreaShape, Quantization, Semantics};
use crate::convention::Target;
use crate::model::Model;
use crate::oracle::compare::{CompareError, Comparison, SizeMismatch};
use crate::oracle::theirs::GreyImage;

/// One way a renderer may produce grey levels, as `compare --as grey --fit` tries it: a
/// method of the area family's list under a semantics, quantized (or its own levels).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GreyMethod {
    /// The area method.
    pub area: AreaMethod,
    /// The semantics it computes.
    pub semantics: Semantics,
    /// How its values become levels (`None` for a method that makes its own).
    pub quantization: Option<Quantization>,
}

impl GreyMethod {
    /// `area`'s values under `semantics`, quantized by `q`.
    pub fn quantized(area: AreaMethod, semantics: Semantics, q: Quantization) -> GreyMethod {
        GreyMethod {
            area,
            semantics,
            quantization: Some(q),
        }
    }

    /// `area`'s own levels (FreeType's, tiny-skia's, ab_glyph's, zeno's).
    pub fn own(area: AreaMethod) -> GreyMethod {
        GreyMethod {
            area,
            semantics: area.native_semantics(),
            quantization: None,
        }
    }

    /// Its name, as `--method` takes it: the area method's name (`exact-SEMANTICS` for the
    /// exact value), then the quantization's, e.g. `supersample-4x4-round`,
    /// `exact-accumulated-truncate`, `f32-accum-round16`; a method that makes its own
    /// levels is its area method's name alone (`ftgrays`, `tiny-skia-4x4`).
    pub fn name(self) -> String {
        let area = if self.area.is_exact() {
            format!("exact-{}", self.semantics.name())
        } else {
            self.area.name().to_string()
        };
        match self.quantization {
            Some(q) => format!("{area}-{}", q.name()),
            None => area,
        }
    }

    /// The method of [`GreyMethod::all`]`(bits)` named `name` (see [`GreyMethod::name`]).
    ///
    /// # Errors
    /// No method of `bits`-bit levels has that name: the message lists those that do.
    pub fn from_name(name: &str, bits: u32) -> Result<GreyMethod, String> {
        let all = GreyMethod::all(bits);
        all.iter().copied().find(|m| m.name() == name).ok_or_else(|| {
            let names: Vec<String> = all.iter().map(|m| m.name()).collect();
            format!(
                "no grey method named {name:?} for {bits}-bit levels (expected one of: {})",
                names.join(", ")
            )
        })
    }

    /// The semantics and quantization its levels are judged under against the exact value
    /// at `bits` bits: its own, or for a method that makes its own levels its native
    /// semantics and the quantization nearest its levels (FreeType's for `ftgrays`, else
    /// rounding at `bits` bits).
    pub fn judged_as(self, bits: u32) -> (Semantics, Quantization) {
        let q = self.quantization.unwrap_or(match self.area {
            AreaMethod::FtGrays => Quantization::FtGrays,
            _ => Quantization::Round8.at_depth(bits).unwrap_or(Quantization::Round8),
        });
        (self.semantics, q)
    }

    /// Its levels for `shapes` on a `width` x `height` canvas (`None` where it cannot
    /// draw them, or an f32 value is not finite).
    pub fn levels(self, shapes: &[AreaShape], width: u32, height: u32) -> Option<Vec<u16>> {
        let out = self.area.draw(shapes, width, height, self.semantics).ok()?;
        out.quantized(
            width,
            height,
            self.semantics,
            self.quantization.unwrap_or(Quantization::Round8),
        )
    }

    /// The bits of its levels.
    pub fn bits(self) -> u32 {
        self.area
            .own_bits()
            .unwrap_or_else(|| self.quantization.map_or(8, Quantization::bits))
    }

    /// In words.
    pub fn describe(self) -> String {
        let what = self.area.describe(self.semantics);
        match self.quantization {
            Some(q) => format!("{what}, quantized by {}", q.name()),
            None => what,
        }
    }

    /// Every method whose levels have `bits` bits, in the order of [`AreaMethod::ALL`]:
    /// the exact value (asked of [`AreaMethod::REFERENCE`], under each semantics), each
    /// method that departs from it under its own semantics, each under every
    /// quantization of `bits` bits; then the methods that make their own levels.
    pub fn all(bits: u32) -> Vec<GreyMethod> {
        let qs: Vec<Quantization> = Quantization::ALL.into_iter().filter(|q| q.bits() == bits).collect();
        let mut out = Vec::new();
        for area in AreaMethod::ALL {
            match area.own_bits() {
                Some(own) if own == bits => out.push(GreyMethod::own(area)),
                Some(_) => {}
                None if area.is_exact() && area != AreaMethod::REFERENCE => {}
                None if area.is_exact() => {
                    for s in Semantics::ALL {
                        out.extend(qs.iter().map(|&q| GreyMethod::quantized(area, s, q)));
                    }
                }
                None => out.extend(
                    qs.iter()
                        .map(|&q| GreyMethod::quantized(area, area.native_semantics(), q)),
                ),
            }
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
            s.push_str(&format!(
                "  {} (--method {}): {}\n",
                m.describe(),
                m.name(),
                if *n == 1 {
                    "1 pixel differs".to_string()
                } else {
                    format!("{n} pixels differ")
                }
            ));
        }
        s
    }

    /// `{"tried", "methods": [{"method", "name", "differing"}]}`, fewest differing first
    /// (`name` as `--method` takes it).
    fn to_json(&self, _scene: &str, _theirs: &str) -> Value {
        json!({
            "tried": self.methods.len(),
            "methods": self.methods.iter().map(|(m, n)| json!({"method": m.describe(), "name": m.name(), "differing": n})).collect::<Vec<_>>(),
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
    // Each method's output is drawn once (the exact ones are the costly part) and
    // quantized as each of its grey methods asks.
    let mut drawn: Vec<((AreaMethod, Semantics), Option<AreaOutput>)> = Vec::new();
    let mut out = Vec::new();
    for m in GreyMethod::all(theirs.bits) {
        let key = (m.area, m.semantics);
        if !drawn.iter().any(|(k, _)| *k == key) {
            drawn.push((key, m.area.draw(shapes, width, height, m.semantics).ok()));
        }
        let levels = drawn
            .iter()
            .find(|(k, _)| *k == key)
            .and_then(|(_, o)| o.as_ref())
            .and_then(|o| {
                o.quantized(
                    width,
                    height,
                    m.semantics,
                    m.quantization.unwrap_or(Quantization::Round8),
                )
            });
        if let Some(levels) = levels {
            out.push((m, levels.iter().zip(&theirs.levels).filter(|(a, b)| a != b).count()));
        }
    }
    out.sort_by_key(|(_, n)| *n);
    Ok(GreyFitReport { model, methods: out })
}
