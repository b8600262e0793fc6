//! One pixel's interpolated values explained ([`explain_values`]): for each sample of the
//! pixel, the primitive it shows and why, the point its varying is taken at, the exact
//! derivation (the homogeneous barycentrics there, the weights, the formula with its
//! numbers), each channel's exact value and its nearest f32 with the f32's bits, their
//! value with its bits and its signed distance in f32 steps, the f32 envelope there (near
//! and far), a `centroid` varying's range, and the class `compare --as values` gives it.
//!
//! The definitions are [`crate::interp::values`]'s: Olano and Greer's 2D homogeneous
//! barycentrics, `smooth` as equation (14.9) and `noperspective` as (14.10) of the OpenGL
//! 4.6 core specification (section 14.6.1), `flat` the provoking vertex's value (section
//! 13.4). The class is judged by [`crate::oracle::compare::values::compare_values`]'s own
//! code, restricted to the pixel, so that it is the class the whole comparison gives there.

mod text;

use std::ops::Range;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::convention::Target;
use crate::coverage::samples::SampleCoverage;
use crate::geom::Point;
use crate::interp::envelope::{value_envelope, Envelope};
use crate::interp::values::{Interpolation, NoValue, ProvokingVertex, Sampling, ValueSetup, Varying};
use crate::model::{centroid, render, render_samples, Model, Primitives};
use crate::num::exact::{decimal_pair_text, exact_text, nearest_f32, pair_text};
use crate::num::unorm::unorm_levels;
use crate::oracle::compare::values::{
    centroid_range, compare_values_where, f32_signed_steps, read_as, their_channels, their_values, TheirValue,
    ValueClass, ValueOptions,
};
use crate::oracle::compare::CompareError;
use crate::oracle::reason::primitive_name;
use crate::oracle::theirs::Theirs;
use crate::pattern::SamplePattern;
use crate::raster::sample_exact;

/// One pixel's values of one varying, explained (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct ValueExplanation {
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// The varying explained.
    pub varying: Varying,
    /// The provoking vertex of the scene's `flat` varyings.
    pub provoking: ProvokingVertex,
    /// The exact model whose coverage says which primitive each sample shows.
    pub model: Model,
    /// The sample pattern, named, under several samples per pixel.
    pub pattern: Option<String>,
    /// How their image was read (`float32`, `unorm8 (nearest rule)`), when it was given.
    pub read_as: Option<String>,
    /// Each sample of the pixel, in index order (one with one sample per pixel).
    pub samples: Vec<SampleValue>,
}

/// One sample of the pixel.
#[derive(Debug, Clone, PartialEq)]
pub struct SampleValue {
    /// Its index in the pattern (0 with one sample per pixel).
    pub index: usize,
    /// Its position in the pixel, exact text, under a pattern of several samples.
    pub position: Option<String>,
    /// The primitives covering it, ascending.
    pub owners: Vec<u32>,
    /// The primitive it shows and the value there; `None` when nothing covers it.
    pub shown: Option<Shown>,
    /// Their channels at the sample (their image's row `index * H + y`), when their image
    /// was given.
    pub theirs: Option<Vec<TheirValue>>,
    /// The class `compare --as values` gives the sample; `None` when it is not judged
    /// (not covered, no exact value, or no image of theirs).
    pub class: Option<ValueClass>,
}

/// The primitive a sample shows and its value there.
#[derive(Debug, Clone, PartialEq)]
pub struct Shown {
    /// Its id: the highest of the sample's owners.
    pub id: u32,
    /// Its scene field and index (`triangles[0]`).
    pub primitive: String,
    /// Which point of the pixel the varying is taken at, and why, in words.
    pub at: String,
    /// That point, exactly.
    pub point: Point,
    /// How the value is built from the primitive's vertices; `None` for a primitive that
    /// carries no values.
    pub derivation: Option<Derivation>,
    /// Each channel's value, or why there is none.
    pub channels: Result<Vec<ChannelValue>, NoValue>,
}

/// How a value is built from a primitive's vertices at a point.
#[derive(Debug, Clone, PartialEq)]
pub enum Derivation {
    /// A triangle's.
    Triangle(Box<TriangleAt>),
    /// A line segment's.
    Segment(Box<SegmentAt>),
}

/// A triangle at a point: its vertices and its homogeneous barycentrics there.
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleAt {
    /// Per vertex, its window point (`None` at `w = 0`: a point at infinity) and its
    /// clip-space `w`.
    pub vertices: [(Option<Point>, BigRational); 3],
    /// The homogeneous barycentrics `b` at the point ([`crate::interp::values`]): `None`
    /// for a `flat` varying (which needs none) or a degenerate triangle.
    pub b: Option<[BigRational; 3]>,
}

impl TriangleAt {
    /// `1 / w` at the point: `b_0 + b_1 + b_2`.
    pub fn inverse_w(&self) -> Option<BigRational> {
        self.b.as_ref().map(|b| &b[0] + &b[1] + &b[2])
    }

    /// The window-space barycentrics `mu_i = b_i w_i`: the `noperspective` weights.
    pub fn window_barycentrics(&self) -> Option<[BigRational; 3]> {
        let b = self.b.as_ref()?;
        Some([0, 1, 2].map(|i| &b[i] * &self.vertices[i].1))
    }

    /// The perspective-correct weights `b_i / (b_0 + b_1 + b_2)`: the `smooth` ones;
    /// `None` on the horizon (`1 / w = 0`).
    pub fn weights(&self) -> Option<[BigRational; 3]> {
        let b = self.b.as_ref()?;
        let inv_w = self.inverse_w().filter(|s| !s.is_zero())?;
        Some([0, 1, 2].map(|i| &b[i] / &inv_w))
    }
}

/// A line segment at a point: its ends and the point's parameter along it.
#[derive(Debug, Clone, PartialEq)]
pub struct SegmentAt {
    /// `from` and `to`.
    pub ends: [Point; 2],
    /// The point's projection onto the segment, `t` (0 at `from`, 1 at `to`); `None` for
    /// a segment of zero length.
    pub t: Option<BigRational>,
}

/// One channel's value at a sample, and theirs.
#[derive(Debug, Clone, PartialEq)]
pub struct ChannelValue {
    /// The channel's index in the varying.
    pub channel: usize,
    /// The vertices' values of the channel.
    pub vertex_values: Vec<BigRational>,
    /// The formula with its numbers, ending in the exact value.
    pub formula: String,
    /// The exact value.
    pub exact: BigRational,
    /// It rounded once to the nearest f32 (ties to even); `None` beyond f32's range.
    pub nearest: Option<f32>,
    /// How far a correct f32 interpolator may land from it ([`crate::interp::envelope`]).
    pub envelope: Envelope,
    /// A `centroid` varying of a triangle: the least and greatest value over the pixel's
    /// square clipped to the triangle, and the envelope (far) at that region's corners.
    pub centroid_range: Option<(BigRational, BigRational, Option<f64>)>,
    /// Their value, when their image was given.
    pub theirs: Option<TheirValue>,
    /// Their float's signed distance from the nearest f32 in f32 steps (positive: theirs
    /// is above); `None` for a level, a float that is not finite, or a value beyond f32.
    pub steps: Option<i64>,
    /// Their image's UNORM levels: the levels the rule allows for the exact value.
    pub levels: Option<(u32, u32)>,
}

/// Explains pixel `(x, y)`'s values of the varying `options` names, under its pattern, with
/// `theirs` (their values image, as `compare --as values` reads it) or without.
///
/// ```
/// use rasterproof::model::Model;
/// use rasterproof::oracle::compare::values::ValueOptions;
/// use rasterproof::oracle::explain::values::explain_values;
/// use rasterproof::scene::parse_scene;
/// // The value x at vertices (0, 0), (4, 0), (0, 4) with w = 1, 1, 2.
/// let scene = parse_scene(
///     r#"{"width": 4, "height": 4, "varyings": [{"name": "u", "channels": 1}],
///         "triangles": [{"v": [[0, 0], [4, 0], [0, 4]], "w": [1, 1, 2], "varyings": {"u": [[0], [4], [0]]}}]}"#,
///     "s.json",
/// )
/// .unwrap();
/// let target = scene.target().unwrap();
/// let options = ValueOptions::for_scene(&scene, "s.json", Model::Exact, None, "nearest").unwrap();
/// let why = explain_values(&scene.primitives(), &target, None, &options, 1, 1).unwrap();
/// // At (3/2, 3/2): mu = (1/4, 3/8, 3/8), b = mu / w = (1/4, 3/8, 3/16), 1/w = 13/16,
/// // f = (3/8 x 4) / (13/16) = 24/13.
/// let shown = why.samples[0].shown.as_ref().unwrap();
/// let channel = &shown.channels.as_ref().unwrap()[0];
/// assert_eq!(channel.exact.to_string(), "24/13");
/// assert!(why.to_text().contains("= 24/13"));
/// ```
///
/// # Errors
/// The pixel off the canvas ([`CompareError::Values`]); a model that is not exact or
/// refuses the scene; their image of another size, or with fewer channels than the
/// varying (as [`crate::oracle::compare::values::compare_values`]).
pub fn explain_values(
    primitives: &Primitives,
    target: &Target,
    theirs: Option<&Theirs>,
    options: &ValueOptions,
    x: u32,
    y: u32,
) -> Result<ValueExplanation, CompareError> {
    if x >= target.width || y >= target.height {
        return Err(CompareError::Values(format!(
            "pixel ({x}, {y}) is off the {}x{} canvas",
            target.width, target.height
        )));
    }
    if !options.model.is_exact() {
        return Err(CompareError::NotExact(options.model));
    }
    let (varying, range) = options
        .varyings
        .ranges()
        .nth(options.varying)
        .map(|(v, r)| (v.clone(), r))
        .ok_or_else(|| CompareError::Values("the scene declares no such varying".to_string()))?;
    let single = SamplePattern::single(&target.convention);
    let pattern = options.pattern.as_ref().unwrap_or(&single);
    let coverage = match &options.pattern {
        Some(p) => render_samples(primitives, target, p, options.model),
        None => render(primitives, target, options.model).map(|c| SampleCoverage::from_samples(vec![c])),
    }
    .map_err(CompareError::Model)?;
    // Their image: checked as the comparison checks it, and the pixel judged by it.
    let judged = match theirs {
        Some(theirs) => {
            let (image, ..) = their_values(target, theirs, options)?;
            let picture = options.clone().with_picture(true);
            let report = compare_values_where(primitives, target, theirs, &picture, |i, j| (i, j) == (x, y))?;
            let judged = report.picture.map(|p| p.judged).unwrap_or_default();
            Some((image, read_as(image, options.unorm), judged))
        }
        None => None,
    };
    let context = Context {
        primitives,
        options,
        varying: &varying,
        range,
        target,
        centre: sample_exact(x, y, target),
    };
    let mut samples = Vec::new();
    for s in 0..pattern.len() {
        let owners = coverage.owners(x, y, s).to_vec();
        let shown = owners.last().map(|&id| {
            let point = match varying.sampling {
                Sampling::Centre => context.centre.clone(),
                Sampling::Sample => pattern.sample(x, y, s),
                Sampling::Centroid => centroid(&coverage, pattern, x, y, id, &context.centre),
            };
            let at = point_words(&varying, options.pattern.as_ref(), &coverage, (x, y, s, id), &point);
            context.shown(id, at, point)
        });
        let theirs = judged.as_ref().map(|(image, ..)| {
            let row = u64::from(target.height) * s as u64 + u64::from(y);
            // Their image is checked to be the canvas stacked once per sample.
            their_channels(image, x, u32::try_from(row).unwrap_or(u32::MAX), varying.channels)
        });
        let class = judged
            .as_ref()
            .and_then(|(.., all)| all.iter().find(|j| j.sample == s).map(|j| j.class));
        let mut sample = SampleValue {
            index: s,
            position: options.pattern.as_ref().map(|p| p.position_text(s)),
            owners,
            shown,
            theirs,
            class,
        };
        sample.compare_channels();
        samples.push(sample);
    }
    let (bits, read_as) = judged.map_or((0, None), |(_, (bits, read_as), _)| (bits, Some(read_as)));
    let mut explanation = ValueExplanation {
        x,
        y,
        varying,
        provoking: options.varyings.provoking,
        model: options.model,
        pattern: options.pattern.as_ref().map(ToString::to_string),
        read_as,
        samples,
    };
    if bits > 0 {
        explanation.allowed_levels(bits, options.unorm);
    }
    Ok(explanation)
}

/// The point a varying is taken at, in words: which point and why.
fn point_words(
    varying: &Varying,
    pattern: Option<&SamplePattern>,
    coverage: &SampleCoverage,
    (x, y, s, id): (u32, u32, usize, u32),
    point: &Point,
) -> String {
    let place = format!(
        "{}{}",
        pair_text(&point.x, &point.y),
        decimal_pair_text(&point.x, &point.y)
    );
    let Some(pattern) = pattern else {
        return format!("the pixel's sample point {place} (one sample per pixel)");
    };
    match varying.sampling {
        Sampling::Centre => format!("the pixel's centre {place} (sampling centre)"),
        Sampling::Sample => format!("sample {s}'s own position {place} (sampling sample)"),
        Sampling::Centroid => {
            let mask = coverage.mask_of(x, y, id);
            let covered = mask.count_ones();
            if usize::try_from(covered).is_ok_and(|c| c >= pattern.len()) {
                format!("the pixel's centre {place}: the primitive covers every sample (Direct3D's centroid)")
            } else {
                format!(
                    "sample {}, the primitive's first covered sample (it covers {covered} of {}), at {place} (Direct3D's centroid)",
                    mask.trailing_zeros(),
                    pattern.len()
                )
            }
        }
    }
}

/// What every sample's value at one pixel is computed from.
struct Context<'a> {
    primitives: &'a Primitives,
    options: &'a ValueOptions,
    varying: &'a Varying,
    /// The varying's channels in a vertex's values.
    range: Range<usize>,
    target: &'a Target,
    /// The pixel's centre (its sample point under the convention).
    centre: Point,
}

impl Context<'_> {
    /// The value of primitive `id` at `point` (`at`: the point in words).
    fn shown(&self, id: u32, at: String, point: Point) -> Shown {
        let (options, varying, range, target) = (self.options, self.varying, &self.range, self.target);
        let setup = options.setups.get(id as usize).and_then(Option::as_ref);
        let primitive = primitive_name(self.primitives, id).unwrap_or_default();
        let Some(setup) = setup else {
            return Shown {
                id,
                primitive,
                at,
                point,
                derivation: None,
                channels: Err(NoValue::NotCarried),
            };
        };
        let interpolation = varying.interpolation;
        let provoking = options.varyings.provoking;
        let derivation = match setup {
            ValueSetup::Triangle(t) => Derivation::Triangle(Box::new(TriangleAt {
                vertices: t.h.clone().map(|h| {
                    let window = (!h[2].is_zero()).then(|| Point::new(&h[0] / &h[2], &h[1] / &h[2]));
                    (window, h[2].clone())
                }),
                b: (interpolation != Interpolation::Flat)
                    .then(|| t.barycentrics(&point).ok())
                    .flatten(),
            })),
            ValueSetup::Segment(s) => Derivation::Segment(Box::new(SegmentAt {
                ends: s.ends.clone(),
                t: s.parameter(&point),
            })),
        };
        let channels = setup
            .value(interpolation, provoking, range.clone(), &point)
            .map(|values| {
                let envelopes = value_envelope(setup, interpolation, range.clone(), &point, target.height);
                let ranges = match varying.sampling {
                    Sampling::Centroid => {
                        centroid_range(setup, interpolation, &self.centre, range.clone(), target.height)
                    }
                    _ => None,
                };
                values
                    .into_iter()
                    .zip(envelopes)
                    .zip(range.clone())
                    .enumerate()
                    .map(|(c, ((exact, envelope), k))| {
                        let vertex_values: Vec<BigRational> = match setup {
                            ValueSetup::Triangle(t) => t.values.iter().map(|v| v[k].clone()).collect(),
                            ValueSetup::Segment(s) => s.values.iter().map(|v| v[k].clone()).collect(),
                        };
                        ChannelValue {
                            channel: c,
                            formula: formula(&derivation, interpolation, provoking, &vertex_values, &exact),
                            vertex_values,
                            nearest: nearest_f32(&exact),
                            exact,
                            envelope,
                            centroid_range: ranges.as_ref().and_then(|r| r.get(c).cloned()),
                            theirs: None,
                            steps: None,
                            levels: None,
                        }
                    })
                    .collect()
            });
        Shown {
            id,
            primitive,
            at,
            point,
            derivation: Some(derivation),
            channels,
        }
    }
}

/// A number in a formula: its exact text, in parentheses when negative.
fn term(q: &BigRational) -> String {
    if q.is_negative() {
        format!("({})", exact_text(q))
    } else {
        exact_text(q)
    }
}

/// A number divided or dividing: its exact text, in parentheses unless a non-negative
/// integer.
fn operand(q: &BigRational) -> String {
    if q.is_integer() && !q.is_negative() {
        exact_text(q)
    } else {
        format!("({})", exact_text(q))
    }
}

/// `w0 × f0 + w1 × f1 + ...`.
fn weighted(weights: &[BigRational], values: &[BigRational]) -> String {
    let terms: Vec<String> = weights
        .iter()
        .zip(values)
        .map(|(w, f)| format!("{} × {}", term(w), term(f)))
        .collect();
    terms.join(" + ")
}

/// The formula of one channel with its numbers, ending in `= exact`.
fn formula(
    derivation: &Derivation,
    interpolation: Interpolation,
    provoking: ProvokingVertex,
    values: &[BigRational],
    exact: &BigRational,
) -> String {
    let value = exact_text(exact);
    if interpolation == Interpolation::Flat {
        let k = provoking.vertex(values.len());
        let which = if values.len() == 2 { "end" } else { "vertex" };
        return format!("f = f{k} (the provoking {which}: the {}) = {value}", provoking.name());
    }
    match derivation {
        Derivation::Triangle(t) => match (interpolation, &t.b, t.window_barycentrics()) {
            (Interpolation::NoPerspective, _, Some(mu)) => {
                format!("f = mu0 f0 + mu1 f1 + mu2 f2 = {} = {value}", weighted(&mu, values))
            }
            (_, Some(b), _) => {
                let numerator: BigRational = b.iter().zip(values).map(|(b, f)| b * f).sum();
                let inv_w = t.inverse_w().unwrap_or_default();
                format!(
                    "f = (b0 f0 + b1 f1 + b2 f2) / (b0 + b1 + b2) = ({}) / {} = {} / {} = {value}",
                    weighted(b, values),
                    operand(&inv_w),
                    operand(&numerator),
                    operand(&inv_w)
                )
            }
            _ => format!("f = {value}"),
        },
        Derivation::Segment(s) => match &s.t {
            Some(t) => {
                let one_minus = BigRational::from_integer(1.into()) - t;
                format!(
                    "f = (1 - t) f0 + t f1 = {} = {value}",
                    weighted(&[one_minus, t.clone()], values)
                )
            }
            None => format!("f = {value}"),
        },
    }
}

impl SampleValue {
    /// Fills each channel's theirs, its distance in f32 steps, and (UNORM) the levels the
    /// rule allows, from [`SampleValue::theirs`].
    fn compare_channels(&mut self) {
        let (
            Some(theirs),
            Some(Shown {
                channels: Ok(channels), ..
            }),
        ) = (&self.theirs, &mut self.shown)
        else {
            return;
        };
        for (channel, t) in channels.iter_mut().zip(theirs) {
            channel.theirs = Some(*t);
            match t {
                TheirValue::F32(f) => {
                    channel.steps = channel
                        .nearest
                        .filter(|_| f.is_finite())
                        .map(|n| f32_signed_steps(*f, n));
                }
                TheirValue::Level(_) => {}
            }
        }
    }
}

impl ValueExplanation {
    /// Fills the UNORM levels each channel's rule allows (`bits` a level, `rule`).
    fn allowed_levels(&mut self, bits: u32, rule: crate::num::unorm::UnormRule) {
        for sample in &mut self.samples {
            if let Some(Shown {
                channels: Ok(channels), ..
            }) = &mut sample.shown
            {
                for c in channels
                    .iter_mut()
                    .filter(|c| matches!(c.theirs, Some(TheirValue::Level(_))))
                {
                    let levels = unorm_levels(&c.exact, bits, rule);
                    c.levels = Some((*levels.start(), *levels.end()));
                }
            }
        }
    }
}
