//! Another renderer's interpolated values judged against the exact ones: every covered
//! pixel's value of one varying, read as float32 or as UNORM levels, classed as exact,
//! inside the f32 envelope, or off with a reason ([`compare_values`]).
//!
//! Which pixels are judged: those the oracle model covers (one sample per pixel), each
//! showing its highest-id owner, as [`crate::model::exact_values`] gives them. Their
//! coverage is `compare --as ids`'s question; here a pixel they left empty reads as their
//! background (usually 0) and is judged like any other value.
//!
//! The classes, in the order they are tried (the first that holds names the pixel):
//!
//! | class | off? | holds when every channel of theirs is |
//! |---|---|---|
//! | `exact` | no | the exact value rounded to the nearest f32 (float32), or a level the UNORM rule allows |
//! | `f32` | no | within the envelope of an interpolator anchored at a vertex ([`crate::interp::envelope`]) |
//! | `far-anchor` | no | within the envelope of a plane anchored at the framebuffer's origin |
//! | `affine` | yes | the `noperspective` value of a `smooth` varying (no perspective correction) |
//! | `perspective` | yes | the `smooth` value of a `noperspective` varying |
//! | `provoking-vertex` | yes | another vertex's value of a `flat` varying |
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
use crate::convention::Target;
use crate::geom::Point;
use crate::interp::envelope::{value_envelope, EnvelopeSetup};
use crate::interp::planned::PlannedValue;
use crate::interp::values::{Interpolation, NoValue, ProvokingVertex, Sampling, ValueSetup, Varying, Varyings};
use crate::model::{render, Model, Primitives};
use crate::num::exact::{exact_text, nearest_f32, nearest_f64};
use crate::num::unorm::{unorm_levels, UnormRule};
use crate::oracle::theirs::{Theirs, ValueImage, ValueSamples};
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
        })
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
    /// A smooth varying's noperspective value.
    Affine,
    /// A noperspective varying's smooth value.
    Perspective,
    /// A flat varying's value from another vertex.
    ProvokingVertex,
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
    pub const ALL: [ValueClass; 10] = [
        ValueClass::Exact,
        ValueClass::F32,
        ValueClass::FarAnchor,
        ValueClass::Affine,
        ValueClass::Perspective,
        ValueClass::ProvokingVertex,
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
            ValueClass::Affine => "affine",
            ValueClass::Perspective => "perspective",
            ValueClass::ProvokingVertex => "provoking-vertex",
            ValueClass::ChannelsSwapped => "channels-swapped",
            ValueClass::VerticesPermuted => "vertices-permuted",
            ValueClass::UnormRule => "unorm-rule",
            ValueClass::Gross => "gross",
        }
    }

    /// Whether the class is a difference the specifications do not allow (every class
    /// but `exact`, `f32` and `far-anchor`).
    pub fn is_off(self) -> bool {
        !matches!(self, ValueClass::Exact | ValueClass::F32 | ValueClass::FarAnchor)
    }

    /// One line on what the class means.
    pub fn meaning(self) -> &'static str {
        match self {
            ValueClass::Exact => "the exact value rounded to the nearest f32, or a level the UNORM rule allows",
            ValueClass::F32 => "within the f32 error of an interpolator anchored at a vertex",
            ValueClass::FarAnchor => {
                "within the f32 error of a plane anchored at the framebuffer's origin, beyond a vertex-anchored one's"
            }
            ValueClass::Affine => "the screen-linear value of a smooth varying: no perspective correction",
            ValueClass::Perspective => "the perspective-correct value of a noperspective varying",
            ValueClass::ProvokingVertex => "another vertex's value of a flat varying: the wrong provoking vertex",
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
    fn text(self) -> String {
        match self {
            TheirValue::F32(f) => format!("{f:e}"),
            TheirValue::Level(l) => format!("level {l}"),
        }
    }

    fn json(self) -> Value {
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
    /// The largest distance in f32 steps among the pixels inside the envelope.
    pub max_ulps_inside: u64,
}

/// Distance in f32 steps between two finite floats (by their order as integers).
pub(crate) fn f32_steps(a: f32, b: f32) -> u64 {
    let ord = |f: f32| {
        let bits = i64::from(f.to_bits() & 0x7fff_ffff);
        if f.is_sign_negative() {
            -bits
        } else {
            bits
        }
    };
    (ord(a) - ord(b)).unsigned_abs()
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
/// A canvas of another size; their image not read as values; fewer channels than the
/// varying has; a model that is not exact or refuses the scene.
pub fn compare_values(
    primitives: &Primitives,
    target: &Target,
    theirs: &Theirs,
    options: &ValueOptions,
) -> Result<ValueReport, CompareError> {
    let (image, varying, range) = their_values(target, theirs, options)?;
    let owners = covered_owners(primitives, target, options)?;
    let (bits, read_as) = match &image.samples {
        ValueSamples::F32(_) => (0, "float32".to_string()),
        ValueSamples::Unorm { bits, .. } => (*bits, format!("unorm{bits} ({} rule)", options.unorm.name())),
    };
    let mut report = ValueReport {
        varying: varying.name.clone(),
        interpolation: varying.interpolation,
        sampling: varying.sampling,
        read_as,
        judged: 0,
        without_value: 0,
        counts: Vec::new(),
        pixels: Vec::new(),
        max_ulps_inside: 0,
    };
    let mut counts = [0usize; ValueClass::ALL.len()];
    let mut plans = Plans::new(
        options,
        range.clone(),
        &target.convention.pixel_centre.offset(),
        target.height,
    );
    let mut listed_inside = 0;
    for &(x, y, id) in &owners {
        let Some(plan) = plans.of(id) else {
            report.without_value += 1;
            continue;
        };
        let theirs_here = their_channels(image, x, y, varying.channels);
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
        // With one sample per pixel a centroid is the sample, which is the centre.
        let class = class.unwrap_or_else(|| {
            let exact = exact.as_ref().expect("computed when undecided");
            classify(
                &theirs_here,
                exact,
                setup,
                &sample_exact(x, y, target),
                options,
                range.clone(),
                bits,
                target.height,
            )
        });
        counts[ValueClass::ALL.iter().position(|&c| c == class).expect("listed")] += 1;
        report.judged += 1;
        let ulps: Vec<Option<u64>> = theirs_here
            .iter()
            .zip(&nearest)
            .map(|(t, n)| match (t, n) {
                (TheirValue::F32(f), Some(n)) if f.is_finite() => Some(f32_steps(*f, *n)),
                _ => None,
            })
            .collect();
        if !class.is_off() {
            let most = ulps.iter().flatten().copied().max().unwrap_or(0);
            report.max_ulps_inside = report.max_ulps_inside.max(most);
        }
        if class != ValueClass::Exact && (class.is_off() || list) {
            listed_inside += usize::from(!class.is_off());
            report.pixels.push(ValuePixel {
                x,
                y,
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

/// Their values image, checked against the canvas and the varying judged, with the
/// varying and the range of its channels in a vertex's values.
pub(crate) fn their_values<'a>(
    target: &Target,
    theirs: &'a Theirs,
    options: &'a ValueOptions,
) -> Result<(&'a ValueImage, &'a Varying, std::ops::Range<usize>), CompareError> {
    let image = theirs.values().ok_or(CompareError::Format(theirs.format()))?;
    SizeMismatch::check(theirs, target).map_err(CompareError::Size)?;
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
/// highest id): what is judged.
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

/// How many pixels inside the envelope a report lists one by one (every pixel off is
/// listed; the counts are complete).
pub const LISTED_INSIDE: usize = 1000;

/// Each primitive's planned values and envelopes, set up on first use.
pub(crate) struct Plans<'a> {
    options: &'a ValueOptions,
    channels: std::ops::Range<usize>,
    centre: BigRational,
    centre_f64: f64,
    height: u32,
    plans: Vec<Option<Option<Plan>>>,
}

/// One primitive's channels: planned values and envelopes.
pub(crate) struct Plan {
    values: Vec<PlannedValue>,
    envelopes: Vec<EnvelopeSetup>,
    centre: f64,
}

impl<'a> Plans<'a> {
    pub(crate) fn new(
        options: &'a ValueOptions,
        channels: std::ops::Range<usize>,
        centre: &BigRational,
        height: u32,
    ) -> Plans<'a> {
        Plans {
            height,
            options,
            channels,
            centre: centre.clone(),
            centre_f64: nearest_f64(centre).unwrap_or(0.5),
            plans: (0..options.setups.len()).map(|_| None).collect(),
        }
    }

    /// Primitive `id`'s plan; `None` for a primitive that carries no values.
    pub(crate) fn of(&mut self, id: u32) -> Option<&Plan> {
        let (options, channels, centre, centre_f64, height) =
            (self.options, &self.channels, &self.centre, self.centre_f64, self.height);
        self.plans[id as usize]
            .get_or_insert_with(|| {
                let setup = options.setups[id as usize].as_ref()?;
                let interpolation = options.varyings.list[options.varying].interpolation;
                let provoking = options.varyings.provoking;
                Some(Plan {
                    values: PlannedValue::channels(setup, interpolation, provoking, channels.clone(), centre),
                    envelopes: EnvelopeSetup::channels(setup, interpolation, channels.clone(), height),
                    centre: centre_f64,
                })
            })
            .as_ref()
    }
}

impl Plan {
    /// The exact values at pixel `(x, y)`.
    pub(crate) fn exact(&self, x: u32, y: u32) -> Result<Vec<BigRational>, NoValue> {
        self.values.iter().map(|v| v.exact(x, y)).collect()
    }

    /// Each channel's exact value rounded to the nearest f32 at pixel `(x, y)`.
    pub(crate) fn nearest(&self, x: u32, y: u32) -> Result<Vec<Option<f32>>, NoValue> {
        self.values.iter().map(|v| v.nearest_f32(x, y)).collect()
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
            let envelope = self.envelopes[c].at_pixel(x, y, self.centre);
            let inside = |bound: Option<f64>| -> Result<bool, NoValue> {
                bound.map_or(Ok(false), |b| self.values[c].within(x, y, t, b))
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

/// The class of one pixel (module docs).
#[allow(clippy::too_many_arguments)]
fn classify(
    theirs: &[TheirValue],
    exact: &[BigRational],
    setup: &ValueSetup,
    at: &Point,
    options: &ValueOptions,
    range: std::ops::Range<usize>,
    bits: u32,
    height: u32,
) -> ValueClass {
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
    for alt in alternatives(exact, setup, at, options, range.clone()) {
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

/// The values a renderer with one of the known bugs would write (module docs), in class
/// order.
fn alternatives(
    exact: &[BigRational],
    setup: &ValueSetup,
    at: &Point,
    options: &ValueOptions,
    range: std::ops::Range<usize>,
) -> Vec<Alternative> {
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
}

impl Comparison for ValueReport {
    fn identical(&self) -> bool {
        self.off() == 0
    }

    fn counts(&self) -> Vec<(String, usize)> {
        self.counts.iter().map(|(c, n)| (c.name().to_string(), *n)).collect()
    }

    fn to_text(&self, scene: &str, theirs: &str, limit: usize) -> String {
        let mut s = format!(
            "{theirs} against {scene}, values of {:?} ({}, {}), read as {}: ",
            self.varying,
            self.interpolation.name(),
            self.sampling.name(),
            self.read_as
        );
        let off = self.off();
        if off == 0 {
            let _ = writeln!(
                s,
                "right: {} pixels judged, every value exact or inside the f32 envelope (at most {} f32 steps)",
                self.judged, self.max_ulps_inside
            );
        } else {
            let _ = writeln!(s, "{off} of {} judged pixels off", self.judged);
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
        let mut listed: Vec<&ValuePixel> = self.pixels.iter().filter(|p| p.class.is_off()).collect();
        listed.extend(self.pixels.iter().filter(|p| !p.class.is_off()));
        for p in listed.into_iter().take(limit) {
            let exact: Vec<String> = p.exact.iter().map(exact_text).collect();
            let theirs: Vec<String> = p.theirs.iter().map(|t| t.text()).collect();
            let _ = write!(
                s,
                "  ({}, {}) primitive {}: {}; exact [{}], theirs [{}]",
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
            s.push('\n');
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
