//! Another renderer's interpolated values judged against the exact ones: every covered
//! pixel's value of one varying, read as float32 or as UNORM levels, classed as exact,
//! inside the f32 envelope, or off with a reason ([`compare_values`]).
//!
//! Which pixels are judged: those the oracle model covers (one sample per pixel), each
//! showing its highest-id owner, as [`crate::model::exact_values`] gives them. Their
//! coverage is `compare --as ids`'s question; here a pixel they left empty reads as their
//! background (usually 0) and is judged like any other value.
//!
//! Under a pattern of several samples ([`ValueOptions::with_pattern`]) their image is one
//! values image per sample index, stacked (sample `s` in rows `[s H, (s + 1) H)`), and every
//! covered sample is judged: the value of its highest-id owner, taken at the centre
//! (`centre`), at the sample (`sample`), or at Direct3D's centroid (`centroid`: the centre
//! when the primitive covers every sample of the pixel, else its first covered sample).
//! Vulkan's `Centroid` decoration and GLSL's `centroid` qualifier allow any point inside
//! both the pixel and the primitive; such a value is `centroid-range`, not off.
//!
//! The classes, in the order they are tried (the first that holds names the pixel):
//!
//! | class | off? | holds when every channel of theirs is |
//! |---|---|---|
//! | `exact` | no | the exact value rounded to the nearest f32 (float32), or a level the UNORM rule allows |
//! | `f32` | no | within the envelope of an interpolator anchored at a vertex ([`crate::interp::envelope`]) |
//! | `far-anchor` | no | within the envelope of a plane anchored at the framebuffer's origin |
//! | `unbounded` | no | where f32 bounds nothing (the 1/w plane's error exceeds 1/w): within the envelope elsewhere |
//! | `centroid-range` | no | a `centroid` varying's value somewhere in the pixel inside the primitive |
//! | `affine` | yes | the `noperspective` value of a `smooth` varying (no perspective correction) |
//! | `perspective` | yes | the `smooth` value of a `noperspective` varying |
//! | `provoking-vertex` | yes | another vertex's value of a `flat` varying |
//! | `at-centre` | yes | the value at the pixel's centre where the varying asks for its centroid or sample |
//! | `w-at-centre` | yes | a smooth value with `f / w` at the sample or centroid and `1 / w` at the centre |
//! | `at-sample` | yes | the value at another of the primitive's covered samples in the pixel |
//! | `channels-swapped` | yes | the exact channels in another order |
//! | `vertices-permuted` | yes | the value of the primitive with its vertices' values in another order |
//! | `unorm-rule` | yes | a level another UNORM rule (nearest, Vulkan, Direct3D) allows |
//! | `gross` | yes | none of these |
//!
//! Each alternative is judged with its own envelope, so a renderer with an affine bug and
//! f32 arithmetic is still named `affine`.

use std::fmt::Write as _;

use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use serde_json::{json, Value};

use super::{CompareError, Comparison, SizeMismatch};
use crate::clip::halfplane::HalfPlane;
use crate::clip::sutherland_hodgman::clip_exact;
use crate::convention::{Convention, Target};
use crate::geom::Point;
use crate::interp::envelope::{value_envelope, Envelope, EnvelopeSetup};
use crate::interp::planned::{FastPlan, PlannedValue, TriangleF64};
use crate::interp::values::{
    Interpolation, NoValue, ProvokingVertex, Sampling, ValueSetup, ValueTriangle, Varying, Varyings,
};
use crate::model::{render, render_samples, Model, Primitives};
use crate::num::exact::{exact_text, nearest_f32, nearest_f64};
use crate::num::unorm::{unorm_levels, UnormRule};
use crate::oracle::theirs::{Theirs, ValueImage, ValueSamples};
use crate::pattern::SamplePattern;
use crate::raster::sample_exact;
use crate::scene::Scene;

/// What [`compare_values`] judges and how.
#[derive(Debug, Clone)]
pub struct ValueOptions {
    /// The exact model whose coverage says which pixels are judged.
    pub model: Model,
    /// Each primitive's interpolation setup (`Scene::value_setups`), by id.
    pub setups: Vec<Option<ValueSetup>>,
    /// The scene's varyings.
    pub varyings: Varyings,
    /// The varying their image holds (an index of `varyings.list`).
    pub varying: usize,
    /// How a UNORM image's levels are judged.
    pub unorm: UnormRule,
    /// The sample pattern of their image, when it has several samples per pixel: one
    /// values image per sample index, stacked (`None`: one sample per pixel).
    pub pattern: Option<SamplePattern>,
    /// Keep every judged sample's class and first channel in the report
    /// ([`ValueReport::picture`]: what its HTML page draws, `compare --html`).
    pub picture: bool,
}

impl ValueOptions {
    /// The options of `compare --as values` for `scene` (named `name` in errors): the
    /// varying `varying` names (default the first), the UNORM rule named `unorm`
    /// (`nearest`, `vulkan` or `d3d`).
    ///
    /// # Errors
    /// A scene without varyings, a varying it does not declare, an unknown rule: one line
    /// naming the option.
    pub fn for_scene(
        scene: &Scene,
        name: &str,
        model: Model,
        varying: Option<&str>,
        unorm: &str,
    ) -> Result<ValueOptions, String> {
        let varyings = &scene.varyings;
        let names: Vec<&str> = varyings.list.iter().map(|v| v.name.as_str()).collect();
        let varying = match varying {
            None if names.is_empty() => return Err(format!("--as values: {name} declares no varyings")),
            None => 0,
            Some(v) => names
                .iter()
                .position(|n| *n == v)
                .ok_or_else(|| format!("--varying: {name} declares no varying {v:?} (it declares {names:?})"))?,
        };
        let unorm = UnormRule::parse(unorm)
            .ok_or_else(|| format!("--unorm-rule: unknown rule {unorm:?} (expected nearest, vulkan or d3d)"))?;
        Ok(ValueOptions {
            model,
            setups: scene.value_setups(),
            varyings: varyings.clone(),
            varying,
            unorm,
            pattern: None,
            picture: false,
        })
    }

    /// These options keeping (or not) every judged sample in the report
    /// ([`ValueReport::picture`]).
    pub fn with_picture(mut self, picture: bool) -> ValueOptions {
        self.picture = picture;
        self
    }

    /// These options for their image under `pattern` (`None`, or a pattern of one sample
    /// at the convention's centre: one sample per pixel).
    pub fn with_pattern(mut self, pattern: Option<SamplePattern>, convention: &Convention) -> ValueOptions {
        self.pattern = pattern.filter(|p| !p.is_single(convention));
        self
    }

    /// Samples per pixel of their image.
    pub fn samples(&self) -> usize {
        self.pattern.as_ref().map_or(1, SamplePattern::len)
    }
}

/// The class of one judged pixel (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ValueClass {
    /// The correctly rounded value, or an allowed level.
    Exact,
    /// Within the envelope of an interpolator anchored near the primitive.
    F32,
    /// Within the envelope of a plane anchored at the framebuffer's origin only.
    FarAnchor,
    /// Where f32 arithmetic bounds nothing: any value is a correct interpolator's.
    Unbounded,
    /// A centroid varying's value at another point of the pixel inside the primitive.
    CentroidRange,
    /// A smooth varying's noperspective value.
    Affine,
    /// A noperspective varying's smooth value.
    Perspective,
    /// A flat varying's value from another vertex.
    ProvokingVertex,
    /// The value at the pixel's centre where the varying asks for a centroid or a sample.
    AtCentre,
    /// A smooth value with `f / w` taken at the sample or centroid and `1 / w` at the
    /// pixel's centre.
    WAtCentre,
    /// The value at another covered sample of the pixel than the point asked for.
    AtSample,
    /// The channels in another order.
    ChannelsSwapped,
    /// The vertices' values in another order.
    VerticesPermuted,
    /// A level of another UNORM rule.
    UnormRule,
    /// None of the above.
    Gross,
}

impl ValueClass {
    /// Every class, in the order they are tried.
    pub const ALL: [ValueClass; 15] = [
        ValueClass::Exact,
        ValueClass::F32,
        ValueClass::FarAnchor,
        ValueClass::Unbounded,
        ValueClass::CentroidRange,
        ValueClass::Affine,
        ValueClass::Perspective,
        ValueClass::ProvokingVertex,
        ValueClass::AtCentre,
        ValueClass::WAtCentre,
        ValueClass::AtSample,
        ValueClass::ChannelsSwapped,
        ValueClass::VerticesPermuted,
        ValueClass::UnormRule,
        ValueClass::Gross,
    ];

    /// The class's name in reports.
    pub fn name(self) -> &'static str {
        match self {
            ValueClass::Exact => "exact",
            ValueClass::F32 => "f32",
            ValueClass::FarAnchor => "far-anchor",
            ValueClass::Unbounded => "unbounded",
            ValueClass::CentroidRange => "centroid-range",
            ValueClass::Affine => "affine",
            ValueClass::Perspective => "perspective",
            ValueClass::ProvokingVertex => "provoking-vertex",
            ValueClass::AtCentre => "at-centre",
            ValueClass::WAtCentre => "w-at-centre",
            ValueClass::AtSample => "at-sample",
            ValueClass::ChannelsSwapped => "channels-swapped",
            ValueClass::VerticesPermuted => "vertices-permuted",
            ValueClass::UnormRule => "unorm-rule",
            ValueClass::Gross => "gross",
        }
    }

    /// Whether the class is a difference the specifications do not allow (every class
    /// but `exact`, `f32`, `far-anchor`, `unbounded` and `centroid-range`).
    pub fn is_off(self) -> bool {
        !matches!(
            self,
            ValueClass::Exact
                | ValueClass::F32
                | ValueClass::FarAnchor
                | ValueClass::Unbounded
                | ValueClass::CentroidRange
        )
    }

    /// One line on what the class means.
    pub fn meaning(self) -> &'static str {
        match self {
            ValueClass::Exact => "the exact value rounded to the nearest f32, or a level the UNORM rule allows",
            ValueClass::F32 => "within the f32 error of an interpolator anchored at a vertex",
            ValueClass::FarAnchor => {
                "within the f32 error of a plane anchored at the framebuffer's origin, beyond a vertex-anchored one's"
            }
            ValueClass::Unbounded => {
                "no f32 bound here: the error of a 1/w plane (anchored far away, or near the horizon) can exceed 1/w itself, so any value is a correct interpolator's"
            }
            ValueClass::CentroidRange => {
                "a centroid varying's value at a point inside both the pixel and the primitive other than Direct3D's centroid (Vulkan and GL allow any)"
            }
            ValueClass::Affine => "the screen-linear value of a smooth varying: no perspective correction",
            ValueClass::Perspective => "the perspective-correct value of a noperspective varying",
            ValueClass::ProvokingVertex => "another vertex's value of a flat varying: the wrong provoking vertex",
            ValueClass::AtCentre => "the value at the pixel's centre where the varying asks for its centroid or its sample",
            ValueClass::WAtCentre => {
                "a smooth value divided at the wrong point: f/w at the sample or centroid, 1/w at the pixel's centre"
            }
            ValueClass::AtSample => "the value at another covered sample of the pixel than the point the varying asks for",
            ValueClass::ChannelsSwapped => "the exact channels in another order",
            ValueClass::VerticesPermuted => "the value of the primitive with its vertices' values in another order",
            ValueClass::UnormRule => "a level another UNORM conversion rule allows",
            ValueClass::Gross => "none of the classes: a wrong value",
        }
    }
}

/// Their number in one channel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TheirValue {
    /// A float32 sample.
    F32(f32),
    /// A UNORM level.
    Level(u32),
}

impl TheirValue {
    /// For people: the float in scientific notation, or `level L`.
    pub(crate) fn text(self) -> String {
        match self {
            TheirValue::F32(f) => format!("{f:e}"),
            TheirValue::Level(l) => format!("level {l}"),
        }
    }

    /// For programs: the float (a string when not finite) or the level.
    pub(crate) fn json(self) -> Value {
        match self {
            TheirValue::F32(f) if f.is_finite() => json!(f),
            TheirValue::F32(f) => json!(f.to_string()),
            TheirValue::Level(l) => json!(l),
        }
    }
}

/// One pixel whose value is not `exact`.
#[derive(Debug, Clone, PartialEq)]
pub struct ValuePixel {
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// The sample index (0 with one sample per pixel).
    pub sample: usize,
    /// The primitive shown.
    pub id: u32,
    /// Its class.
    pub class: ValueClass,
    /// The exact value, per channel.
    pub exact: Vec<BigRational>,
    /// Theirs, per channel.
    pub theirs: Vec<TheirValue>,
    /// Per channel, the distance in f32 steps from the correctly rounded exact value (a
    /// float32 image only).
    pub ulps: Vec<Option<u64>>,
}

/// The judgement of one varying's values.
#[derive(Debug, Clone, PartialEq)]
pub struct ValueReport {
    /// The varying judged.
    pub varying: String,
    /// Its interpolation.
    pub interpolation: Interpolation,
    /// Its sampling.
    pub sampling: Sampling,
    /// Samples per pixel of their image (1, or the pattern's count: one image per sample
    /// index, stacked).
    pub samples: usize,
    /// `float32`, or `unorm8`/`unorm16` with the rule.
    pub read_as: String,
    /// Pixels judged (covered, with an exact value).
    pub judged: usize,
    /// Covered pixels without an exact value (a polygon's, a horizon's).
    pub without_value: usize,
    /// Pixels per class, in [`ValueClass::ALL`]'s order (classes with none left out).
    pub counts: Vec<(ValueClass, usize)>,
    /// Every pixel not `exact`, row by row.
    pub pixels: Vec<ValuePixel>,
    /// The largest distance in f32 steps among the pixels inside the envelope (`f32`,
    /// `far-anchor`; not `centroid-range`, another point's value).
    pub max_ulps_inside: u64,
    /// Every judged sample, when the options asked for it ([`ValueOptions::picture`]).
    pub picture: Option<ValuePicture>,
}

/// Every judged sample of a [`ValueReport`]: what its HTML page draws.
#[derive(Debug, Clone, PartialEq)]
pub struct ValuePicture {
    /// The canvas's width.
    pub width: u32,
    /// The canvas's height (their image is `samples` times as tall).
    pub height: u32,
    /// The judged samples, row by row, then by sample index.
    pub judged: Vec<JudgedValue>,
}

/// One judged sample: where, its class, and the first channel of both answers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JudgedValue {
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// The sample index (0 with one sample per pixel).
    pub sample: usize,
    /// Its class.
    pub class: ValueClass,
    /// The exact value of the first channel rounded to the nearest f32 (`None` beyond
    /// f32's range).
    pub exact: Option<f32>,
    /// Their first channel.
    pub theirs: Option<TheirValue>,
}

/// Distance in f32 steps between two finite floats (by their order as integers).
pub(crate) fn f32_steps(a: f32, b: f32) -> u64 {
    f32_signed_steps(a, b).unsigned_abs()
}

/// The signed distance in f32 steps from `b` to `a` (positive when `a` is above), both
/// finite: their order as integers, `-0` and `0` the same.
pub(crate) fn f32_signed_steps(a: f32, b: f32) -> i64 {
    let ord = |f: f32| {
        let bits = i64::from(f.to_bits() & 0x7fff_ffff);
        if f.is_sign_negative() {
            -bits
        } else {
            bits
        }
    };
    ord(a) - ord(b)
}

/// Whether their channel `t` is `v` up to `bound` (f32: correctly rounded or within the
/// bound; UNORM: a level `rule` allows for some value within the bound).
fn within(t: TheirValue, v: &BigRational, bound: Option<f64>, bits: u32, rule: UnormRule) -> bool {
    match t {
        TheirValue::F32(f) => {
            if nearest_f32(v) == Some(f) {
                return true;
            }
            let (Some(b), Some(exact)) = (bound, BigRational::from_float(f64::from(f))) else {
                return false;
            };
            (exact - v).abs().to_f64().is_some_and(|d| d <= b)
        }
        TheirValue::Level(l) => {
            if unorm_levels(v, bits, rule).contains(&l) {
                return true;
            }
            let Some(b) = bound.and_then(BigRational::from_float) else {
                return false;
            };
            let (lo, hi) = (unorm_levels(&(v - &b), bits, rule), unorm_levels(&(v + &b), bits, rule));
            (*lo.start()..=*hi.end()).contains(&l)
        }
    }
}

/// One candidate value of a pixel: the channels and the interpolation whose envelope
/// judges them, at a point.
struct Alternative {
    class: ValueClass,
    values: Vec<BigRational>,
    interpolation: Interpolation,
    setup: ValueSetup,
    at: Point,
}

/// Judges their values of the varying `options.varying` of the scene drawn from
/// `primitives` on `target` (module docs).
///
/// # Errors
/// A canvas of another size (under a pattern of several samples, not the canvas stacked
/// once per sample); their image not read as values; fewer channels than the varying has;
/// a model that is not exact or refuses the scene.
pub fn compare_values(
    primitives: &Primitives,
    target: &Target,
    theirs: &Theirs,
    options: &ValueOptions,
) -> Result<ValueReport, CompareError> {
    compare_values_where(primitives, target, theirs, options, |_, _| true)
}

/// [`compare_values`] judging only the pixels `(x, y)` for which `keep(x, y)` holds (the
/// counts count those): one pixel for `explain`.
pub(crate) fn compare_values_where(
    primitives: &Primitives,
    target: &Target,
    theirs: &Theirs,
    options: &ValueOptions,
    keep: impl Fn(u32, u32) -> bool,
) -> Result<ValueReport, CompareError> {
    let (image, varying, range) = their_values(target, theirs, options)?;
    let mut judged = judged_samples(primitives, target, options, varying.sampling)?;
    judged.retain(|j| keep(j.x, j.y));
    let (bits, read_as) = read_as(image, options.unorm);
    let mut report = ValueReport {
        varying: varying.name.clone(),
        interpolation: varying.interpolation,
        sampling: varying.sampling,
        samples: options.samples(),
        read_as,
        judged: 0,
        without_value: 0,
        counts: Vec::new(),
        pixels: Vec::new(),
        max_ulps_inside: 0,
        picture: options.picture.then(|| ValuePicture {
            width: target.width,
            height: target.height,
            judged: Vec::new(),
        }),
    };
    let mut counts = [0usize; ValueClass::ALL.len()];
    let mut plans = Plans::new(options, range.clone(), target);
    let mut listed_inside = 0;
    for j in &judged {
        let (x, y, id) = (j.x, j.y, j.id);
        let Some(plan) = plans.of_at(id, j.point) else {
            report.without_value += 1;
            continue;
        };
        // The stacked row: checked to fit (their image is that tall).
        let row = u32::try_from(j.sample).expect("at most 64 samples") * target.height + y;
        let theirs_here = their_channels(image, x, row, varying.channels);
        let Ok((class, nearest)) = plan.judge(&theirs_here, x, y) else {
            report.without_value += 1;
            continue;
        };
        let setup = options.setups[id as usize].as_ref().expect("a plan has a setup");
        // The exact values, where the fast judgement did not settle the class or the
        // pixel is listed.
        let list = class.is_some_and(|c| c != ValueClass::Exact) && listed_inside < LISTED_INSIDE;
        let exact = if class.is_none() || list || class.is_some_and(ValueClass::is_off) {
            match plan.exact(x, y) {
                Ok(v) => Some(v),
                Err(_) => {
                    report.without_value += 1;
                    continue;
                }
            }
        } else {
            None
        };
        let class = class.unwrap_or_else(|| {
            let exact = exact.as_ref().expect("computed when undecided");
            let at = plans.point(x, y, j.point);
            let others = j.others().map(|p| plans.point(x, y, p)).collect();
            let context = Context {
                setup,
                at,
                others,
                centre: sample_exact(x, y, target),
            };
            classify(
                &theirs_here,
                exact,
                &context,
                options,
                range.clone(),
                bits,
                target.height,
            )
        });
        counts[ValueClass::ALL.iter().position(|&c| c == class).expect("listed")] += 1;
        report.judged += 1;
        if let Some(picture) = &mut report.picture {
            picture.judged.push(JudgedValue {
                x,
                y,
                sample: j.sample,
                class,
                exact: nearest.first().copied().flatten(),
                theirs: theirs_here.first().copied(),
            });
        }
        let ulps: Vec<Option<u64>> = theirs_here
            .iter()
            .zip(&nearest)
            .map(|(t, n)| match (t, n) {
                (TheirValue::F32(f), Some(n)) if f.is_finite() => Some(f32_steps(*f, *n)),
                _ => None,
            })
            .collect();
        if matches!(class, ValueClass::Exact | ValueClass::F32 | ValueClass::FarAnchor) {
            let most = ulps.iter().flatten().copied().max().unwrap_or(0);
            report.max_ulps_inside = report.max_ulps_inside.max(most);
        }
        if class != ValueClass::Exact && (class.is_off() || list) {
            listed_inside += usize::from(!class.is_off());
            report.pixels.push(ValuePixel {
                x,
                y,
                sample: j.sample,
                id,
                class,
                exact: exact.expect("computed for a listed pixel"),
                theirs: theirs_here,
                ulps,
            });
        }
    }
    report.counts = ValueClass::ALL
        .iter()
        .zip(counts)
        .filter(|&(_, n)| n > 0)
        .map(|(&c, n)| (c, n))
        .collect();
    Ok(report)
}

/// The bits of their image's levels (0 for float32) and how it was read: `float32`, or
/// `unorm8`/`unorm16` with the `rule` its levels are judged under.
pub(crate) fn read_as(image: &ValueImage, rule: UnormRule) -> (u32, String) {
    match &image.samples {
        ValueSamples::F32(_) => (0, "float32".to_string()),
        ValueSamples::Unorm { bits, .. } => (*bits, format!("unorm{bits} ({} rule)", rule.name())),
    }
}

/// Their values image, checked against the canvas (stacked once per sample under a
/// pattern of several) and the varying judged, with the varying and the range of its
/// channels in a vertex's values.
pub(crate) fn their_values<'a>(
    target: &Target,
    theirs: &'a Theirs,
    options: &'a ValueOptions,
) -> Result<(&'a ValueImage, &'a Varying, std::ops::Range<usize>), CompareError> {
    let image = theirs.values().ok_or(CompareError::Format(theirs.format()))?;
    match &options.pattern {
        None => SizeMismatch::check(theirs, target).map_err(CompareError::Size)?,
        Some(pattern) => {
            let stacked = u64::from(target.height) * pattern.len() as u64;
            if (image.width, u64::from(image.height)) != (target.width, stacked) {
                return Err(CompareError::Values(format!(
                    "their image is {}x{}; under the {pattern} sample pattern it must be the {}x{} canvas stacked once per sample index ({}x{}, sample s in rows s*{} to (s+1)*{} - 1)",
                    image.width, image.height, target.width, target.height, target.width, stacked, target.height, target.height
                )));
            }
        }
    }
    let (varying, range) = options
        .varyings
        .ranges()
        .nth(options.varying)
        .ok_or_else(|| CompareError::Values("the scene declares no such varying".to_string()))?;
    if image.channels < varying.channels {
        return Err(CompareError::Values(format!(
            "their image has {} channels a pixel; the varying {:?} has {}",
            image.channels, varying.name, varying.channels
        )));
    }
    Ok((image, varying, range))
}

/// The pixels the oracle model covers, row by row, each with the primitive it shows (the
/// highest id): what is judged with one sample per pixel.
pub(crate) fn covered_owners(
    primitives: &Primitives,
    target: &Target,
    options: &ValueOptions,
) -> Result<Vec<(u32, u32, u32)>, CompareError> {
    if !options.model.is_exact() {
        return Err(CompareError::NotExact(options.model));
    }
    let coverage = render(primitives, target, options.model).map_err(CompareError::Model)?;
    let mut owners: Vec<(u32, u32, u32)> = coverage
        .iter()
        .filter_map(|(x, y, ids)| ids.last().map(|&id| (x, y, id)))
        .collect();
    owners.sort_unstable_by_key(|&(x, y, _)| (y, x));
    Ok(owners)
}

/// One judged sample: where, which primitive it shows, and the point its value is taken
/// at (a [`Plans`] point: 0 the pixel's centre, `1 + s` sample `s`).
#[derive(Debug, Clone, PartialEq)]
struct Judged {
    x: u32,
    y: u32,
    sample: usize,
    id: u32,
    point: usize,
    /// The primitive's covered samples in the pixel (bit `k`: sample `k`; 0 with one
    /// sample per pixel): the other points a renderer might have taken (`at-sample`).
    mask: u64,
}

impl Judged {
    /// The points (as [`Plans`] numbers them) of the primitive's other covered samples.
    fn others(&self) -> impl Iterator<Item = usize> + '_ {
        (0..64usize)
            .filter(move |&k| self.mask >> k & 1 == 1 && 1 + k != self.point)
            .map(|k| 1 + k)
    }
}

/// Every covered sample, row by row, then by sample index, with the point its value is
/// taken at under `sampling`: the centre (`centre`, or `centroid` when the primitive
/// covers every sample of the pixel), the sample (`sample`), or the primitive's first
/// covered sample (`centroid`, Direct3D's rule). With one sample per pixel, every covered
/// pixel at its centre.
fn judged_samples(
    primitives: &Primitives,
    target: &Target,
    options: &ValueOptions,
    sampling: Sampling,
) -> Result<Vec<Judged>, CompareError> {
    let Some(pattern) = &options.pattern else {
        let owners = covered_owners(primitives, target, options)?;
        return Ok(owners
            .into_iter()
            .map(|(x, y, id)| Judged {
                x,
                y,
                sample: 0,
                id,
                point: 0,
                mask: 0,
            })
            .collect());
    };
    if !options.model.is_exact() {
        return Err(CompareError::NotExact(options.model));
    }
    let coverage = render_samples(primitives, target, pattern, options.model).map_err(CompareError::Model)?;
    let count = pattern.len();
    let all = if count >= 64 { u64::MAX } else { (1u64 << count) - 1 };
    let mut out = Vec::new();
    for (x, y) in coverage.covered_pixels() {
        for s in 0..count {
            let Some(&id) = coverage.owners(x, y, s).last() else {
                continue;
            };
            let mask = coverage.mask_of(x, y, id);
            let point = match sampling {
                Sampling::Centre => 0,
                Sampling::Sample => 1 + s,
                Sampling::Centroid if mask & all == all => 0,
                Sampling::Centroid => 1 + mask.trailing_zeros() as usize,
            };
            out.push(Judged {
                x,
                y,
                sample: s,
                id,
                point,
                mask,
            });
        }
    }
    out.sort_by_key(|j| (j.y, j.x, j.sample));
    Ok(out)
}

/// How many pixels inside the envelope a report lists one by one (every pixel off is
/// listed; the counts are complete).
pub const LISTED_INSIDE: usize = 1000;

/// Each primitive's planned values and envelopes, set up on first use, at each point of
/// a pixel a value is taken at: point 0 the convention's centre, point `1 + s` sample `s`
/// of the pattern.
pub(crate) struct Plans<'a> {
    options: &'a ValueOptions,
    channels: std::ops::Range<usize>,
    height: u32,
    /// Per point, its exact offset from the pixel's corner and how the envelope reads it.
    points: Vec<(Point, Offset)>,
    plans: Vec<Option<Option<Plan<'a>>>>,
}

/// How a plan's envelope takes its point from the pixel's coordinates.
#[derive(Debug, Clone, Copy)]
enum Offset {
    /// The centre `(x + c, y + c)`, `c` 1/2 or 0.
    Centre(f64),
    /// `(x + o_x, y + o_y)`, each offset exact in f64.
    Dyadic(f64, f64),
    /// An offset f64 cannot hold: the envelope takes the exact point.
    Exact,
}

/// One primitive's channels at one point of the pixel: planned values and envelopes.
pub(crate) struct Plan<'a> {
    /// The f64 filter that decides most nearest f32s in a few operations.
    fast: Option<FastPlan>,
    /// The exact planned values, set up where the filter first leaves a question open.
    values: std::cell::OnceCell<Vec<PlannedValue>>,
    setup: &'a ValueSetup,
    interpolation: Interpolation,
    provoking: ProvokingVertex,
    channels: std::ops::Range<usize>,
    envelopes: Vec<EnvelopeSetup>,
    offset: Offset,
    exact_offset: Point,
}

impl<'a> Plans<'a> {
    pub(crate) fn new(options: &'a ValueOptions, channels: std::ops::Range<usize>, target: &Target) -> Plans<'a> {
        let centre = target.convention.pixel_centre.offset();
        let mut points = vec![(
            Point::new(centre.clone(), centre.clone()),
            Offset::Centre(target.convention.pixel_centre.offset_f64()),
        )];
        for [ox, oy] in options.pattern.iter().flat_map(|p| p.positions()) {
            let exact = |v: &BigRational| nearest_f64(v).filter(|f| BigRational::from_float(*f).as_ref() == Some(v));
            let offset = match (exact(ox), exact(oy)) {
                (Some(fx), Some(fy)) => Offset::Dyadic(fx, fy),
                _ => Offset::Exact,
            };
            points.push((Point::new(ox.clone(), oy.clone()), offset));
        }
        let slots = options.setups.len() * points.len();
        Plans {
            height: target.height,
            options,
            channels,
            points,
            plans: (0..slots).map(|_| None).collect(),
        }
    }

    /// Primitive `id`'s plan at pixel centres; `None` for a primitive that carries no
    /// values.
    pub(crate) fn of(&mut self, id: u32) -> Option<&Plan<'a>> {
        self.of_at(id, 0)
    }

    /// Primitive `id`'s plan at point `point`.
    fn of_at(&mut self, id: u32, point: usize) -> Option<&Plan<'a>> {
        let (options, channels, height) = (self.options, &self.channels, self.height);
        let (offset, kind) = &self.points[point];
        let slot = id as usize * self.points.len() + point;
        self.plans[slot]
            .get_or_insert_with(|| {
                let setup = options.setups[id as usize].as_ref()?;
                let interpolation = options.varyings.list[options.varying].interpolation;
                let provoking = options.varyings.provoking;
                let fast = match kind {
                    Offset::Centre(c) => Some((*c, *c)),
                    Offset::Dyadic(ox, oy) => Some((*ox, *oy)),
                    Offset::Exact => None,
                }
                .and_then(|o| {
                    let t = TriangleF64::of(setup, channels.clone())?;
                    Some(FastPlan::new(&t, interpolation, provoking, o))
                });
                Some(Plan {
                    fast,
                    values: std::cell::OnceCell::new(),
                    setup,
                    interpolation,
                    provoking,
                    channels: channels.clone(),
                    envelopes: EnvelopeSetup::channels(setup, interpolation, channels.clone(), height),
                    offset: *kind,
                    exact_offset: offset.clone(),
                })
            })
            .as_ref()
    }

    /// Point `point` of pixel `(x, y)`, exactly.
    fn point(&self, x: u32, y: u32, point: usize) -> Point {
        let offset = &self.points[point].0;
        Point::new(
            BigRational::from_integer(x.into()) + &offset.x,
            BigRational::from_integer(y.into()) + &offset.y,
        )
    }
}

impl Plan<'_> {
    /// The exact planned values, set up on first use.
    fn values(&self) -> &[PlannedValue] {
        self.values.get_or_init(|| {
            PlannedValue::channels_at(
                self.setup,
                self.interpolation,
                self.provoking,
                self.channels.clone(),
                &self.exact_offset,
            )
        })
    }

    /// The exact values at pixel `(x, y)`.
    pub(crate) fn exact(&self, x: u32, y: u32) -> Result<Vec<BigRational>, NoValue> {
        self.values().iter().map(|v| v.exact(x, y)).collect()
    }

    /// Each channel's exact value rounded to the nearest f32 at pixel `(x, y)`: the f64
    /// filter's, the exact inputs' sign where it leaves a question, the exact planned
    /// value's where that does too.
    pub(crate) fn nearest(&self, x: u32, y: u32) -> Result<Vec<Option<f32>>, NoValue> {
        let channels = self.channels.len();
        // A fast plan exists for at most four channels: its answers fit on the stack.
        let mut fast = [None; 4];
        if let (Some(plan), Some(out)) = (&self.fast, fast.get_mut(..channels)) {
            plan.nearest_f32(x, y, out);
        }
        (0..channels)
            .map(|c| {
                let decided = fast.get(c).copied().flatten().or_else(|| {
                    let plan = self.fast.as_ref()?;
                    plan.nearest_f32_exact(self.setup, self.channels.start, x, y, c)
                });
                match decided {
                    Some(f) => Ok(Some(f)),
                    None => self.values()[c].nearest_f32(x, y),
                }
            })
            .collect()
    }

    /// Channel `c`'s envelope at pixel `(x, y)`'s point.
    fn envelope(&self, c: usize, x: u32, y: u32) -> Envelope {
        let e = &self.envelopes[c];
        match self.offset {
            Offset::Centre(centre) => e.at_pixel(x, y, centre),
            Offset::Dyadic(ox, oy) => e.at_offset(x, y, (ox, oy)),
            Offset::Exact => e.at(&Point::new(
                BigRational::from_integer(x.into()) + &self.exact_offset.x,
                BigRational::from_integer(y.into()) + &self.exact_offset.y,
            )),
        }
    }

    /// The class of their float32 channels at pixel `(x, y)` when the planned values
    /// settle it (`exact`, `f32`, `far-anchor`), `None` when only the exact search can
    /// (a pixel off, or UNORM levels); and the correctly rounded values.
    fn judge(&self, theirs: &[TheirValue], x: u32, y: u32) -> Result<(Option<ValueClass>, Vec<Option<f32>>), NoValue> {
        let nearest = self.nearest(x, y)?;
        let mut class = ValueClass::Exact;
        for (c, (t, n)) in theirs.iter().zip(&nearest).enumerate() {
            let TheirValue::F32(t) = *t else {
                return Ok((None, nearest));
            };
            if n.is_some_and(|n| n == t && n.is_sign_negative() == t.is_sign_negative())
                || (*n == Some(0.0) && t == 0.0)
            {
                continue;
            }
            if !t.is_finite() {
                return Ok((None, nearest));
            }
            let envelope = self.envelope(c, x, y);
            let inside = |bound: Option<f64>| -> Result<bool, NoValue> {
                let Some(b) = bound else {
                    return Ok(false);
                };
                match self.fast.as_ref().and_then(|f| f.within(x, y, c, t, b)) {
                    Some(answer) => Ok(answer),
                    None => self.values()[c].within(x, y, t, b),
                }
            };
            let here = if inside(envelope.near)? {
                ValueClass::F32
            } else if inside(envelope.far)? {
                ValueClass::FarAnchor
            } else {
                return Ok((None, nearest));
            };
            class = class.max(here);
        }
        Ok((Some(class), nearest))
    }
}

/// Their first `channels` channels at `(x, y)`.
pub(crate) fn their_channels(image: &ValueImage, x: u32, y: u32, channels: usize) -> Vec<TheirValue> {
    let at = (y as usize * image.width as usize + x as usize) * image.channels;
    match &image.samples {
        ValueSamples::F32(s) => s[at..at + channels].iter().map(|&f| TheirValue::F32(f)).collect(),
        ValueSamples::Unorm { levels, .. } => levels[at..at + channels]
            .iter()
            .map(|&l| TheirValue::Level(u32::from(l)))
            .collect(),
    }
}

/// Where one judged value was taken, for [`classify`].
struct Context<'a> {
    setup: &'a ValueSetup,
    /// The point its value is taken at.
    at: Point,
    /// The primitive's other covered samples of the pixel.
    others: Vec<Point>,
    /// The pixel's centre.
    centre: Point,
}

/// The class of one pixel (module docs).
fn classify(
    theirs: &[TheirValue],
    exact: &[BigRational],
    context: &Context,
    options: &ValueOptions,
    range: std::ops::Range<usize>,
    bits: u32,
    height: u32,
) -> ValueClass {
    let (setup, at) = (context.setup, &context.at);
    let varying = &options.varyings.list[options.varying];
    let rule = options.unorm;
    let all_within = |values: &[BigRational], bounds: &[Option<f64>]| {
        theirs
            .iter()
            .zip(values)
            .zip(bounds)
            .all(|((t, v), b)| within(*t, v, *b, bits, rule))
    };
    let none = vec![None; exact.len()];
    if all_within(exact, &none) {
        return ValueClass::Exact;
    }
    let envelope = value_envelope(setup, varying.interpolation, range.clone(), at, height);
    let near: Vec<Option<f64>> = envelope.iter().map(|e| e.near).collect();
    let far: Vec<Option<f64>> = envelope.iter().map(|e| e.far).collect();
    if all_within(exact, &near) {
        return ValueClass::F32;
    }
    if all_within(exact, &far) {
        return ValueClass::FarAnchor;
    }
    let unbounded = far.iter().any(Option::is_none)
        && theirs
            .iter()
            .zip(exact)
            .zip(&far)
            .all(|((t, v), b)| b.is_none() || within(*t, v, *b, bits, rule));
    if unbounded {
        return ValueClass::Unbounded;
    }
    if varying.sampling == Sampling::Centroid {
        if let Some(extremes) = centroid_range(setup, varying.interpolation, &context.centre, range.clone(), height) {
            let inside = theirs
                .iter()
                .zip(&extremes)
                .all(|(t, (lo, hi, bound))| within_range(*t, lo, hi, *bound, bits, rule));
            if inside {
                return ValueClass::CentroidRange;
            }
        }
    }
    for alt in alternatives(exact, context, options, range.clone()) {
        let bounds: Vec<Option<f64>> = value_envelope(&alt.setup, alt.interpolation, range.clone(), &alt.at, height)
            .iter()
            .map(|e| e.far)
            .collect();
        if alt.values.len() == exact.len() && all_within(&alt.values, &bounds) {
            return alt.class;
        }
    }
    if let TheirValue::Level(_) = theirs[0] {
        let other_rule = [UnormRule::Nearest, UnormRule::Vulkan, UnormRule::D3d]
            .into_iter()
            .any(|r| {
                theirs
                    .iter()
                    .zip(exact)
                    .all(|(t, v)| matches!(t, TheirValue::Level(l) if unorm_levels(v, bits, r).contains(l)))
            });
        if other_rule {
            return ValueClass::UnormRule;
        }
    }
    ValueClass::Gross
}

/// Per channel, the least and the greatest value a window-space triangle takes in the
/// closed pixel square around `centre` (side 1) clipped to the closed triangle, with the
/// largest f32 envelope (anchored at the origin) at the clipped region's vertices: the
/// values Vulkan's and GL's centroid allows ("a location inside both the pixel and the
/// primitive"). A smooth or noperspective value is a ratio of two affine functions whose
/// denominator keeps its sign inside the triangle (`1 / w > 0`), so its extremes over the
/// convex region lie at the region's vertices. `None` for a flat varying, a segment, a
/// triangle with a vertex at `w <= 0`, a degenerate one, or an empty region.
#[allow(clippy::type_complexity)]
pub(crate) fn centroid_range(
    setup: &ValueSetup,
    interpolation: Interpolation,
    centre: &Point,
    range: std::ops::Range<usize>,
    height: u32,
) -> Option<Vec<(BigRational, BigRational, Option<f64>)>> {
    let ValueSetup::Triangle(t) = setup else {
        return None;
    };
    if interpolation == Interpolation::Flat || t.h.iter().any(|h| !h[2].is_positive()) {
        return None;
    }
    let p: Vec<Point> = t.h.iter().map(|h| Point::new(&h[0] / &h[2], &h[1] / &h[2])).collect();
    let area = (&p[1].x - &p[0].x) * (&p[2].y - &p[0].y) - (&p[1].y - &p[0].y) * (&p[2].x - &p[0].x);
    if area.is_zero() {
        return None;
    }
    // Walk the edges so that the third vertex, and with it the inside, is where each
    // edge function is >= 0 (`HalfPlane::inside_of_edge`): E_01(p_2) = -area.
    let order = if area.is_negative() { [0, 1, 2] } else { [0, 2, 1] };
    let planes: Vec<HalfPlane> = (0..3)
        .map(|k| HalfPlane::inside_of_edge(&p[order[k]], &p[order[(k + 1) % 3]]))
        .collect::<Option<_>>()?;
    let half = BigRational::new(1.into(), 2.into());
    let (x0, x1) = (&centre.x - &half, &centre.x + &half);
    let (y0, y1) = (&centre.y - &half, &centre.y + &half);
    let square = [
        Point::new(x0.clone(), y0.clone()),
        Point::new(x1.clone(), y0),
        Point::new(x1, y1.clone()),
        Point::new(x0, y1),
    ];
    let region = clip_exact(&square, &planes);
    let mut out: Option<Vec<(BigRational, BigRational, Option<f64>)>> = None;
    for vertex in &region {
        let values = setup
            .value(interpolation, ProvokingVertex::First, range.clone(), vertex)
            .ok()?;
        let envelopes = value_envelope(setup, interpolation, range.clone(), vertex, height);
        let next = values.into_iter().zip(envelopes).map(|(v, e)| (v.clone(), v, e.far));
        out = Some(match out {
            None => next.collect(),
            Some(so_far) => so_far
                .into_iter()
                .zip(next)
                .map(|((lo, hi, b), (v, _, e))| {
                    let bound = b.zip(e).map(|(b, e)| b.max(e));
                    (lo.min(v.clone()), hi.max(v), bound)
                })
                .collect(),
        });
    }
    out
}

/// Whether their channel `t` lies in `[lo, hi]` widened by `bound` (UNORM: a level the
/// rule allows for some value there).
fn within_range(
    t: TheirValue,
    lo: &BigRational,
    hi: &BigRational,
    bound: Option<f64>,
    bits: u32,
    rule: UnormRule,
) -> bool {
    let b = bound
        .and_then(BigRational::from_float)
        .unwrap_or_else(BigRational::zero);
    let (lo, hi) = (lo - &b, hi + &b);
    match t {
        TheirValue::F32(f) => {
            BigRational::from_float(f64::from(f)).is_some_and(|v| lo <= v && v <= hi)
                || [nearest_f32(&lo), nearest_f32(&hi)].contains(&Some(f))
        }
        TheirValue::Level(l) => {
            (*unorm_levels(&lo, bits, rule).start()..=*unorm_levels(&hi, bits, rule).end()).contains(&l)
        }
    }
}

/// The values a renderer with one of the known bugs would write (module docs), in class
/// order.
fn alternatives(
    exact: &[BigRational],
    context: &Context,
    options: &ValueOptions,
    range: std::ops::Range<usize>,
) -> Vec<Alternative> {
    let (setup, at) = (context.setup, &context.at);
    let varying = &options.varyings.list[options.varying];
    let provoking = options.varyings.provoking;
    let mut out = Vec::new();
    let mut push = |class, interpolation, setup: &ValueSetup, at: &Point, provoking: ProvokingVertex| {
        if let Ok(values) = setup.value(interpolation, provoking, range.clone(), at) {
            out.push(Alternative {
                class,
                values,
                interpolation,
                setup: setup.clone(),
                at: at.clone(),
            });
        }
    };
    match varying.interpolation {
        Interpolation::Smooth => push(ValueClass::Affine, Interpolation::NoPerspective, setup, at, provoking),
        Interpolation::NoPerspective => push(ValueClass::Perspective, Interpolation::Smooth, setup, at, provoking),
        Interpolation::Flat => {
            let other = match provoking {
                ProvokingVertex::First => ProvokingVertex::Last,
                ProvokingVertex::Last => ProvokingVertex::First,
            };
            push(ValueClass::ProvokingVertex, Interpolation::Flat, setup, at, other);
            // A triangle's middle vertex: neither first nor last.
            if let ValueSetup::Triangle(t) = setup {
                let mut middle = t.as_ref().clone();
                middle.values.swap(0, 1);
                push(
                    ValueClass::ProvokingVertex,
                    Interpolation::Flat,
                    &ValueSetup::Triangle(Box::new(middle)),
                    at,
                    ProvokingVertex::First,
                );
            }
        }
    }
    if varying.interpolation != Interpolation::Flat {
        let divided = match (varying.interpolation, setup) {
            (Interpolation::Smooth, ValueSetup::Triangle(t)) if context.centre != *at => {
                divided_at_centre(t, at, &context.centre, range.clone())
            }
            _ => None,
        };
        if context.centre != *at {
            push(
                ValueClass::AtCentre,
                varying.interpolation,
                setup,
                &context.centre,
                provoking,
            );
        }
        for other in &context.others {
            push(ValueClass::AtSample, varying.interpolation, setup, other, provoking);
        }
        if let Some(values) = divided {
            out.push(Alternative {
                class: ValueClass::WAtCentre,
                values,
                interpolation: Interpolation::Smooth,
                setup: setup.clone(),
                at: at.clone(),
            });
        }
    }
    if exact.len() > 1 {
        for perm in permutations(exact.len()).into_iter().skip(1) {
            out.push(Alternative {
                class: ValueClass::ChannelsSwapped,
                values: perm.iter().map(|&c| exact[c].clone()).collect(),
                interpolation: varying.interpolation,
                setup: setup.clone(),
                at: at.clone(),
            });
        }
    }
    if let ValueSetup::Triangle(t) = setup {
        for perm in permutations(3).into_iter().skip(1) {
            let mut permuted = t.as_ref().clone();
            permuted.values = [0, 1, 2].map(|i| t.values[perm[i]].clone());
            let permuted = ValueSetup::Triangle(Box::new(permuted));
            if let Ok(values) = permuted.value(varying.interpolation, provoking, range.clone(), at) {
                if values.iter().zip(exact).any(|(a, b)| a != b) || values.iter().all(Zero::is_zero) {
                    out.push(Alternative {
                        class: ValueClass::VerticesPermuted,
                        values,
                        interpolation: varying.interpolation,
                        setup: permuted,
                        at: at.clone(),
                    });
                }
            }
        }
    }
    out
}

/// The smooth value with its numerator `sum b_i f_i` taken at `at` and its denominator
/// `sum b_i` (`1 / w`) at `centre`, `b` the homogeneous barycentrics: what an interpolator
/// computes when it moves `f / w` to the sample or centroid and leaves `1 / w` at the centre.
fn divided_at_centre(
    t: &ValueTriangle,
    at: &Point,
    centre: &Point,
    channels: std::ops::Range<usize>,
) -> Option<Vec<BigRational>> {
    let (b, c) = (t.barycentrics(at).ok()?, t.barycentrics(centre).ok()?);
    let d = &c[0] + &c[1] + &c[2];
    if d.is_zero() {
        return None;
    }
    Some(
        channels
            .map(|k| (&b[0] * &t.values[0][k] + &b[1] * &t.values[1][k] + &b[2] * &t.values[2][k]) / &d)
            .collect(),
    )
}

/// Every permutation of `0..n` (n at most 4), the identity first.
fn permutations(n: usize) -> Vec<Vec<usize>> {
    fn go(prefix: &mut Vec<usize>, n: usize, out: &mut Vec<Vec<usize>>) {
        if prefix.len() == n {
            out.push(prefix.clone());
            return;
        }
        for k in 0..n {
            if !prefix.contains(&k) {
                prefix.push(k);
                go(prefix, n, out);
                prefix.pop();
            }
        }
    }
    let mut out = Vec::new();
    go(&mut Vec::new(), n, &mut out);
    out
}

impl ValueReport {
    /// How many judged pixels are off (a class the specifications do not allow).
    pub fn off(&self) -> usize {
        self.counts.iter().filter(|(c, _)| c.is_off()).map(|(_, n)| n).sum()
    }

    /// The listed pixels in the text report's order: every one off, then those inside.
    pub fn listed(&self) -> Vec<&ValuePixel> {
        let mut listed: Vec<&ValuePixel> = self.pixels.iter().filter(|p| p.class.is_off()).collect();
        listed.extend(self.pixels.iter().filter(|p| !p.class.is_off()));
        listed
    }

    /// A listed pixel's line of the text report: `(X, Y) [sample S] primitive ID: CLASS;
    /// exact [...], theirs [...] (N f32 steps)`.
    pub fn pixel_text(&self, p: &ValuePixel) -> String {
        let exact: Vec<String> = p.exact.iter().map(exact_text).collect();
        let theirs: Vec<String> = p.theirs.iter().map(|t| t.text()).collect();
        let sample = if self.samples > 1 {
            format!(" sample {}", p.sample)
        } else {
            String::new()
        };
        let mut s = format!(
            "({}, {}){sample} primitive {}: {}; exact [{}], theirs [{}]",
            p.x,
            p.y,
            p.id,
            p.class.name(),
            exact.join(", "),
            theirs.join(", ")
        );
        if p.ulps.iter().any(Option::is_some) {
            let ulps: Vec<String> = p
                .ulps
                .iter()
                .map(|u| u.map_or("-".to_string(), |u| u.to_string()))
                .collect();
            let _ = write!(s, " ({} f32 steps)", ulps.join(", "));
        }
        s
    }
}

impl Comparison for ValueReport {
    fn identical(&self) -> bool {
        self.off() == 0
    }

    fn to_html(&self, page: &super::HtmlInputs<'_>) -> Option<String> {
        Some(ValueReport::to_html(self, page))
    }

    fn counts(&self) -> Vec<(String, usize)> {
        self.counts.iter().map(|(c, n)| (c.name().to_string(), *n)).collect()
    }

    fn to_text(&self, scene: &str, theirs: &str, limit: usize) -> String {
        let samples = if self.samples > 1 {
            format!(", {} samples a pixel", self.samples)
        } else {
            String::new()
        };
        let mut s = format!(
            "{theirs} against {scene}, values of {:?} ({}, {}{samples}), read as {}: ",
            self.varying,
            self.interpolation.name(),
            self.sampling.name(),
            self.read_as
        );
        let off = self.off();
        let unit = if self.samples > 1 { "samples" } else { "pixels" };
        if off == 0 {
            let range = if self.counts.iter().any(|(c, _)| *c == ValueClass::CentroidRange) {
                ", or inside the centroid's range"
            } else {
                ""
            };
            let _ = writeln!(
                s,
                "right: {} {unit} judged, every value exact or inside the f32 envelope (at most {} f32 steps){range}",
                self.judged, self.max_ulps_inside
            );
        } else {
            let _ = writeln!(s, "{off} of {} judged {unit} off", self.judged);
        }
        if self.without_value > 0 {
            let _ = writeln!(
                s,
                "{} covered pixels have no exact value (not carried, horizon)",
                self.without_value
            );
        }
        for (class, n) in &self.counts {
            let _ = writeln!(s, "  {:>8}  {:<18} {}", n, class.name(), class.meaning());
        }
        for p in self.listed().into_iter().take(limit) {
            let _ = writeln!(s, "  {}", self.pixel_text(p));
        }
        s
    }

    fn to_json(&self, scene: &str, theirs: &str) -> Value {
        let counts: serde_json::Map<String, Value> = self
            .counts
            .iter()
            .map(|(c, n)| (c.name().to_string(), json!(n)))
            .collect();
        let pixels: Vec<Value> = self
            .pixels
            .iter()
            .map(|p| {
                json!({
                    "x": p.x,
                    "y": p.y,
                    "sample": p.sample,
                    "id": p.id,
                    "class": p.class.name(),
                    "exact": p.exact.iter().map(exact_text).collect::<Vec<_>>(),
                    "theirs": p.theirs.iter().map(|t| t.json()).collect::<Vec<_>>(),
                    "f32_steps": p.ulps,
                })
            })
            .collect();
        json!({
            "scene": scene,
            "theirs": theirs,
            "as": "values",
            "varying": self.varying,
            "interpolation": self.interpolation.name(),
            "sampling": self.sampling.name(),
            "samples": self.samples,
            "read_as": self.read_as,
            "identical": self.identical(),
            "judged": self.judged,
            "without_value": self.without_value,
            "off": self.off(),
            "counts": counts,
            "max_f32_steps_inside": self.max_ulps_inside,
            "pixels": pixels,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_count_floats_between() {
        assert_eq!(f32_steps(1.0, 1.0), 0);
        assert_eq!(f32_steps(1.0, 1.0 + f32::EPSILON), 1);
        assert_eq!(f32_steps(-0.0, 0.0), 0);
        assert_eq!(f32_steps(f32::from_bits(1), -f32::from_bits(1)), 2);
        assert_eq!(permutations(3).len(), 6);
        assert_eq!(permutations(3)[0], [0, 1, 2]);
    }
}
