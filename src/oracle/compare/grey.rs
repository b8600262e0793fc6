//! Another renderer's anti-aliased output (a grey image) against exact area coverage
//! (`compare --as grey`): per pixel their level against the exact value in units of their
//! quantum, and for each pixel that differs from the exact value's level under the named
//! quantization, the most plausible exact reason ([`GreyClass`]).

use std::collections::BTreeMap;

use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use serde_json::json;

use super::{CompareError, SizeMismatch};
use crate::area::method::SUPERSAMPLE_SIDES;
use crate::area::{conflate, exact, planned, supersample, AreaShape, Quantization, Semantics};
use crate::convention::Target;
use crate::model::{Model, Primitives};
use crate::num::exact::{exact_text, nearest_f64};
use crate::oracle::compare::fit::grey::GreyMethod;
use crate::oracle::theirs::{GreyImage, Theirs};

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
    /// other way round, or accumulate the scene in one buffer. Also, where no class below
    /// explains the level, their level within precision's reach of such a value (and
    /// beyond it from the stated one's): they accumulate, and their arithmetic rounds too.
    Accumulation,
    /// The pixel meets several shapes and their level is a rounding of the shapes blended
    /// one by one, source-over ([`crate::area::conflate`]: `1 - (1 - a)(1 - b)` where the
    /// exact union is `a + b`), each shape's own value exact or supersampled, further from
    /// the union than precision reaches and nearer to their level than the union is: they
    /// composite each shape on its own (a seam between abutting shapes). Also, where no
    /// class below explains the level, their level within precision's reach of the exact
    /// values blended (and beyond it from the exact value).
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
    /// The level of the method judged against ([`GreyOptions::method`]), when one is.
    pub method: Option<u16>,
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
    /// The exact model the shapes came from.
    pub model: Model,
    /// The canvas.
    pub width: u32,
    /// The canvas.
    pub height: u32,
    /// The semantics the exact values follow.
    pub semantics: Semantics,
    /// Their named quantization.
    pub quantization: Quantization,
    /// The method judged against ([`GreyOptions::method`]), when one is: then a pixel
    /// differs where their level is not its level.
    pub method: Option<GreyMethod>,
    /// The pixels that differ (from the exact value's level under the named quantization,
    /// or from the method's level when one is judged against), row by row.
    pub pixels: Vec<GreyPixel>,
    /// The methods of the area family that give every level of their image (found by
    /// [`crate::oracle::judge`] when pixels differ; empty otherwise, and when none does).
    pub explained_by: Vec<GreyMethod>,
    /// The largest `|their level - exact value|` over the canvas, in quanta (the exact value
    /// clamped to `[0, 1]`, as every quantization clamps it).
    pub max_error: BigRational,
    /// The mean of `|their level - exact value|` over the canvas, in quanta.
    pub mean_error: BigRational,
    /// How many pixels are off from the level they are judged against (the named
    /// quantization's, or the method's) by each number of levels (0 included).
    pub histogram: BTreeMap<u32, u64>,
    /// Every pixel's level judged against (the method's, or the exact value's under the
    /// named quantization), row by row: the oracle's image.
    pub judged_levels: Vec<u16>,
    /// Their levels, row by row.
    pub their_levels: Vec<u16>,
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
/// of all the shapes added (`accumulated`, each shape's, as [`exact::explain`] gives them),
/// then folded by the first shape's fill rule (a shape of the opposite orientation cancels
/// another there).
fn one_path(shapes: &[AreaShape], accumulated: &[BigRational]) -> BigRational {
    let Some(first) = shapes.first() else {
        return BigRational::zero();
    };
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

/// Whether a `k x k` supersampled value could round to `level`, judged from `exact`, the
/// exact value that supersampling approximates (within `[0, 1]`), and the `edges` that
/// meet the pixel: of the `k x k` cells whose centres are the samples, only one whose
/// interior an edge crosses can have a sample decision (0 or 1) other than its exact
/// share of area, and a segment inside the pixel crosses the interiors of at most
/// `2k - 1` cells (it crosses at most `k - 1` vertical and `k - 1` horizontal grid lines).
/// So the supersampled value lies within `edges (2k - 1) / k^2` of the exact one, and a
/// rounding of it within that many quanta, plus one, of `exact` in quanta. The cheap test
/// that spares a gross pixel `k^2` exact sample tests per shape and `k`.
fn sampling_reaches(level: u16, exact: &BigRational, edges: u32, k: u32, s: i64) -> bool {
    let (k, edges) = (i64::from(k), i64::from(edges));
    let scale = BigRational::from_integer(s.into());
    let bound = BigRational::new((edges * (2 * k - 1) * s).into(), (k * k).into()) + BigRational::one();
    (BigRational::from_integer(level.into()) - exact * scale).abs() <= bound
}

/// Whether `level` lies between the sums of the floors and of the ceilings of each shape's
/// own value times `s` (each clamped to `[0, top]`, the sum too): a renderer that
/// quantizes every shape on its own and adds the levels (a glyph at a time).
fn rounds_per_shape<'o>(
    shapes: &[AreaShape],
    own: &dyn Fn() -> &'o [BigRational],
    v: &BigRational,
    level: u16,
    s: i64,
    top: u16,
) -> bool {
    if shapes.len() < 2 {
        return false;
    }
    let values = own();
    // Only where the shapes' own values add up to the pixel's (no overlap under true
    // coverage): then the levels added are a rounding of each part of it.
    if values.len() < 2 || values.iter().sum::<BigRational>() != *v {
        return false;
    }
    let scale = BigRational::from_integer(s.into());
    let clamp = |b: num_bigint::BigInt| b.to_i64().unwrap_or(i64::MAX).clamp(0, i64::from(top));
    let (mut lo, mut hi) = (0i64, 0i64);
    for v in values {
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
///
/// The supersampled values are drawn only for a `k` whose blend can reach `level`: the
/// blend moves by at most the sum of its inputs' moves (each factor of `1 - (1 - a_1)...`
/// lies in `[0, 1]`), and each shape's `k x k` value lies within its edges' reach of its
/// exact true-coverage value ([`sampling_reaches`]), so the blend of the supersampled
/// values lies within `edges` samples' reach of the blend of the exact ones.
fn conflated<'o>(
    c: &Classifier<'_>,
    (x, y): (u32, u32),
    level: u16,
    (v, edges, own_exact): (&BigRational, u32, &dyn Fn() -> &'o [BigRational]),
    reach: &BigRational,
) -> bool {
    let (shapes, boxes, semantics, s, top) = (c.shapes, &c.boxes, c.semantics, c.s, c.top);
    if shapes.len() < 2 {
        return false;
    }
    let scale = BigRational::from_integer(s.into());
    let theirs = BigRational::from_integer(level.into());
    let off = |value: &BigRational| (&theirs - value * &scale).abs();
    let exact_blend = std::cell::OnceCell::new();
    std::iter::once(conflate::Own::Exact(semantics))
        .chain(SUPERSAMPLE_SIDES.into_iter().map(conflate::Own::Supersampled))
        .any(|own| {
            if let conflate::Own::Supersampled(k) = own {
                let exact = exact_blend.get_or_init(|| {
                    let own = conflate::own_values(shapes, boxes, x, y, conflate::Own::Exact(Semantics::True));
                    conflate::blend(&own)
                });
                if !sampling_reaches(level, exact, edges, k, s) {
                    return false;
                }
            }
            let drawn;
            let values: &[BigRational] = match own {
                conflate::Own::Exact(_) => own_exact(),
                conflate::Own::Supersampled(_) => {
                    drawn = conflate::own_values(shapes, boxes, x, y, own);
                    &drawn
                }
            };
            if values.len() < 2 {
                return false;
            }
            let blended = conflate::blend(values);
            if !rounds(level, &blended, s, top) {
                return false;
            }
            // What the same values give without blending: the exact value, or the `k x k`
            // share of the union (true coverage) or the shares summed (accumulated).
            let union = match own {
                conflate::Own::Exact(_) => v.clone(),
                conflate::Own::Supersampled(k) if semantics == Semantics::True => supersample::pixel(shapes, x, y, k),
                conflate::Own::Supersampled(_) => values.iter().sum(),
            };
            off(&blended) < off(&union) && beyond(&blended, &union, s, reach) && beyond(&blended, v, s, reach)
        })
}

/// How the differing pixels of one comparison are classed: the shapes and their pixel
/// boxes (found once: the per-shape classes ask at every differing pixel), the stated
/// semantics, and the quantization's levels per unit of coverage (`s`) and top level.
struct Classifier<'a> {
    shapes: &'a [AreaShape],
    boxes: conflate::Boxes,
    semantics: Semantics,
    s: i64,
    top: u16,
}

impl Classifier<'_> {
    /// The class of pixel `(x, y)`, whose level `level` is not the exact value `v`'s under
    /// the named quantization; `error` is their level less `v` clamped to `[0, 1]`, in
    /// quanta. The classes are tried in [`GreyClass`] order, the cheap ones first.
    fn class(&self, (x, y): (u32, u32), level: u16, v: &BigRational, error: &BigRational) -> GreyClass {
        let (shapes, s, top) = (self.shapes, self.s, self.top);
        // Each shape's own exact value under the stated semantics, found once for the
        // classes that ask for it (per-shape quantization, conflation, composed).
        let own_cell = std::cell::OnceCell::new();
        let own = || {
            own_cell
                .get_or_init(|| conflate::own_values(shapes, &self.boxes, x, y, conflate::Own::Exact(self.semantics)))
                .as_slice()
        };
        if rounds(level, v, s, top) || rounds_per_shape(shapes, &own, v, level, s, top) {
            return GreyClass::Quantization;
        }
        let (px, py) = (i64::from(x), i64::from(y));
        let edges = exact::crossing_edges(shapes, px, py).len();
        let edges = u32::try_from(edges).unwrap_or(u32::MAX / 4).min(u32::MAX / 4);
        // How far fixed-point arithmetic may stray here, in quanta: two, or 1/256 of
        // coverage and 2/256 per edge meeting the pixel (a level and two per edge at 8
        // bits). Another value explains their level only where it lies further than that
        // from the exact one.
        let cells = BigRational::new((1 + 2 * edges).into(), 256.into());
        let reach = (cells * BigRational::from_integer(s.into())).max(BigRational::from_integer(2.into()));
        if error.abs() + BigRational::one() <= reach {
            // Another value explains a level only as one of its roundings (within a
            // quantum) and only beyond the reach from the exact value, so a level within
            // the reach less a quantum is precision: the costly checks below could not
            // name it (the same answer, sooner).
            return GreyClass::Precision;
        }
        let (values, accumulated) = exact::values(shapes, px, py);
        // The values another semantics gives, and the scene's as one path.
        let others: Vec<BigRational> = values
            .iter()
            .filter(|(semantics, _)| *semantics != self.semantics)
            .map(|(_, other)| other.clone())
            .chain(std::iter::once(one_path(shapes, &accumulated)))
            .collect();
        if others
            .iter()
            .any(|o| rounds(level, o, s, top) && beyond(o, v, s, &reach))
        {
            return GreyClass::Accumulation;
        }
        if conflated(self, (x, y), level, (v, edges, &own), &reach) {
            return GreyClass::Conflation;
        }
        if error.abs() <= reach {
            return GreyClass::Precision;
        }
        // Supersampling approximates the union's area: the true-coverage value.
        let union = values
            .iter()
            .find(|(semantics, _)| *semantics == Semantics::True)
            .map_or_else(BigRational::zero, |(_, u)| u.clone());
        let union = union.max(BigRational::zero()).min(BigRational::one());
        let sampled = SUPERSAMPLE_SIDES.into_iter().find(|&k| {
            sampling_reaches(level, &union, edges, k, s)
                && supersample::pixel_under_each_rule(shapes, x, y, k)
                    .iter()
                    .any(|v| rounds(level, v, s, top))
        });
        if let Some(k) = sampled {
            return GreyClass::Supersampling(k);
        }
        // The classes composed with precision: their level within the reach of another
        // semantics' value (or of the blend of the shapes' own values), where it lies
        // beyond the reach of the exact value (known here: precision alone was ruled out
        // above): a renderer that accumulates (or blends) and whose arithmetic rounds too
        // (FreeType's divisions on a self-overlapping outline). The other value itself may
        // lie within the reach of the exact one: the two errors add up.
        let near = |value: &BigRational| {
            let shown = value.clone().max(BigRational::zero()).min(BigRational::one());
            (BigRational::from_integer(level.into()) - shown * BigRational::from_integer(s.into())).abs() <= reach
        };
        if others.iter().any(|o| o != v && near(o)) {
            return GreyClass::Accumulation;
        }
        let own = own();
        let blended = conflate::blend(own);
        if own.len() >= 2 && &blended != v && near(&blended) {
            return GreyClass::Conflation;
        }
        GreyClass::Gross
    }
}

/// How grey levels are judged: the exact model the scene's shapes come from (what the
/// report names), the area semantics their levels approximate, and how they quantize.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GreyOptions {
    /// The exact model whose snapped or unsnapped shapes are compared (`exact`: as
    /// written, what anti-aliasing renderers draw).
    pub model: Model,
    /// The exact semantics their levels approximate.
    pub semantics: Semantics,
    /// How their levels quantize a value.
    pub quantization: Quantization,
    /// A method to judge against: a pixel differs where their level is not this
    /// method's (each such pixel still classed against the exact value). `None`: against
    /// the exact value's level under `quantization`.
    pub method: Option<GreyMethod>,
}

/// [`compare_grey`] of a scene: their output (read as grey levels) against the area
/// shapes of `primitives` under the exact `options.model`.
///
/// # Errors
/// Their output is not grey levels, or as [`compare_grey`]; the scene has no area
/// coverage under the model ([`CompareError::Area`]).
pub fn compare_grey_scene(
    primitives: &Primitives,
    target: &Target,
    theirs: &Theirs,
    options: &GreyOptions,
) -> Result<GreyReport, CompareError> {
    let grey = super::grey_of(theirs)?;
    let shapes = super::area_shapes(primitives, target, options.model)?;
    compare_grey(&shapes, target, grey, options)
}

/// [`compare_grey_shows`] of a scene, as [`compare_grey_scene`] reads it.
///
/// # Errors
/// As [`compare_grey_scene`].
pub fn compare_grey_scene_shows(
    primitives: &Primitives,
    target: &Target,
    theirs: &Theirs,
    options: &GreyOptions,
    wanted: (GreyClass, bool),
) -> Result<bool, CompareError> {
    let grey = super::grey_of(theirs)?;
    let shapes = super::area_shapes(primitives, target, options.model)?;
    compare_grey_shows(&shapes, target, grey, options, wanted)
}

/// Compares `theirs` with the exact area coverage of `shapes` on `target`'s canvas under
/// `options.semantics`, their levels read under `options.quantization`.
///
/// # Errors
/// Their image's size or bit depth does not fit the canvas or the quantization.
pub fn compare_grey(
    shapes: &[AreaShape],
    target: &Target,
    theirs: &GreyImage,
    options: &GreyOptions,
) -> Result<GreyReport, CompareError> {
    compare_grey_until(shapes, target, theirs, options, None)
}

/// Whether [`compare_grey`] would class at least one pixel `class`, their level above
/// the exact value (`over`) or not: the question a hunt's shrinker asks of each candidate
/// scene. The same classes, sooner: a pixel whose error has the other sign is not classed,
/// and the first pixel of the class ends the search.
///
/// # Errors
/// As [`compare_grey`].
pub fn compare_grey_shows(
    shapes: &[AreaShape],
    target: &Target,
    theirs: &GreyImage,
    options: &GreyOptions,
    (class, over): (GreyClass, bool),
) -> Result<bool, CompareError> {
    let report = compare_grey_until(shapes, target, theirs, options, Some((class, over)))?;
    Ok(report.pixels.iter().any(|p| p.class == class))
}

/// [`compare_grey`], or with `wanted = Some((class, over))` only the pixels whose error
/// is of that sign, stopping at the first of that class (the report then holds the pixels
/// classed so far; its error figures are partial).
fn compare_grey_until(
    shapes: &[AreaShape],
    target: &Target,
    theirs: &GreyImage,
    options: &GreyOptions,
    wanted: Option<(GreyClass, bool)>,
) -> Result<GreyReport, CompareError> {
    let GreyOptions {
        model,
        semantics,
        quantization,
        method,
    } = *options;
    let (width, height) = (target.width, target.height);
    SizeMismatch::check_size((theirs.width, theirs.height), target).map_err(CompareError::GreySize)?;
    if theirs.bits != quantization.bits() {
        return Err(CompareError::Levels {
            bits: theirs.bits,
            quantization,
        });
    }
    let judged = match method {
        Some(m) if m.bits() != theirs.bits => {
            return Err(CompareError::Method(format!(
                "the method {} makes {}-bit levels; their image has {}-bit ones",
                m.name(),
                m.bits(),
                theirs.bits
            )))
        }
        Some(m) => Some(m.levels(shapes, width, height).ok_or_else(|| {
            let why = m
                .area
                .draw(shapes, width, height, m.semantics)
                .err()
                .unwrap_or_else(|| "a value that is not finite".to_string());
            CompareError::Method(format!("the method {} cannot draw the scene: {why}", m.name()))
        })?),
        None => None,
    };
    let s = scale(quantization);
    let classifier = Classifier {
        shapes,
        boxes: conflate::Boxes::of(shapes),
        semantics,
        s,
        top: u16::try_from((1u32 << theirs.bits) - 1).unwrap_or(u16::MAX),
    };
    let mut pixels = Vec::new();
    let (mut max_error, mut total_error) = (BigRational::zero(), BigRational::zero());
    let mut histogram = BTreeMap::new();
    // Every pixel's exact value at once (the planned engine, equal to the plain oracle).
    let values = planned::rasterize(shapes, width, height, semantics);
    let mut judged_levels = Vec::with_capacity(theirs.levels.len());
    'rows: for y in 0..height {
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
            let judged_level = judged.as_ref().map_or(ours, |j| j[(y * width + x) as usize]);
            judged_levels.push(judged_level);
            *histogram.entry(u32::from(level.abs_diff(judged_level))).or_insert(0) += 1;
            if level == judged_level || wanted.is_some_and(|(_, over)| error.is_positive() != over) {
                continue;
            }
            let class = classifier.class((x, y), level, &v, &error);
            let found = wanted.is_some_and(|(c, _)| c == class);
            pixels.push(GreyPixel {
                x,
                y,
                theirs: level,
                ours,
                method: judged.as_ref().map(|_| judged_level),
                exact: v,
                error,
                class,
            });
            if found {
                break 'rows;
            }
        }
    }
    let count = u64::from(width) * u64::from(height);
    Ok(GreyReport {
        model,
        width,
        height,
        semantics,
        quantization,
        method,
        pixels,
        explained_by: Vec::new(),
        max_error,
        mean_error: total_error / BigRational::from_integer(count.max(1).into()),
        histogram,
        judged_levels,
        their_levels: theirs.levels.clone(),
    })
}

impl GreyReport {
    /// Every pixel has the exact value's level under the named quantization.
    pub fn identical(&self) -> bool {
        self.pixels.is_empty()
    }

    /// How many differing pixels each class explains.
    pub fn classes(&self) -> BTreeMap<GreyClass, usize> {
        let mut out = BTreeMap::new();
        for p in &self.pixels {
            *out.entry(p.class).or_insert(0) += 1;
        }
        out
    }

    /// As text without the header naming the files: the summary, the classes, then up to
    /// `limit` pixels.
    pub fn levels_text(&self, limit: usize) -> String {
        let approx = |v: &BigRational| nearest_f64(v).map_or_else(|| exact_text(v), |f| format!("{f:.4}"));
        let exact = format!(
            "the exact {} coverage quantized by {}",
            self.semantics.name(),
            self.quantization.name()
        );
        let judged = match self.method {
            Some(m) => format!(
                "{} (--method {}); error against the exact {} coverage",
                m.describe(),
                m.name(),
                self.semantics.name()
            ),
            None => format!("{exact}; error"),
        };
        let mut s = format!(
            "{} of {} pixels differ from {judged} in quanta: max {}, mean {}\n",
            self.pixels.len(),
            u64::from(self.width) * u64::from(self.height),
            approx(&self.max_error),
            approx(&self.mean_error),
        );
        match self.explained_by.as_slice() {
            [] => {}
            [one] => s.push_str(&format!(
                "  one method gives every level of their image: {} (--method {})\n",
                one.describe(),
                one.name()
            )),
            many => {
                s.push_str(&format!(
                    "  {} methods give every level of their image (the image cannot tell them apart):\n",
                    many.len()
                ));
                for m in many {
                    s.push_str(&format!("    {} (--method {})\n", m.describe(), m.name()));
                }
            }
        }
        for (class, n) in self.classes() {
            s.push_str(&format!(
                "  {}: {}\n",
                class.name(),
                crate::num::exact::counted(n as u64, "pixel")
            ));
        }
        let histogram: Vec<String> = self.histogram.iter().map(|(d, n)| format!("{d}: {n}")).collect();
        s.push_str(&format!("  levels off (levels: pixels): {}\n", histogram.join(", ")));
        for p in self.pixels.iter().take(limit) {
            let method = p.method.map(|m| format!(" the method's {m},")).unwrap_or_default();
            s.push_str(&format!(
                "  ({}, {}): theirs {},{method} exact {} (level {}), off by {} quanta: {}\n",
                p.x,
                p.y,
                p.theirs,
                exact_text(&p.exact),
                p.ours,
                approx(&p.error),
                p.class.name()
            ));
        }
        // `--limit 0` asks for the counts alone: no pixel, and no "more" of them.
        if limit > 0 && self.pixels.len() > limit {
            s.push_str(&format!("  ... and {} more\n", self.pixels.len() - limit));
        }
        s
    }

    /// As JSON: `{"width","height","semantics","quantization","method","explained_by",
    /// "differing","classes","max_error","mean_error","histogram","pixels":[{"x","y",
    /// "theirs","ours","method","exact","error","class"}]}` (exact values as fraction
    /// strings; `method` the name of the method judged against and a pixel's level under
    /// it, or null; `explained_by` the names of the methods that give every level).
    pub fn levels_json(&self) -> serde_json::Value {
        json!({
            "width": self.width,
            "height": self.height,
            "semantics": self.semantics.name(),
            "quantization": self.quantization.name(),
            "method": self.method.map(GreyMethod::name),
            "explained_by": self.explained_by.iter().map(|m| m.name()).collect::<Vec<_>>(),
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
                "method": p.method,
                "exact": exact_text(&p.exact),
                "error": exact_text(&p.error),
                "class": p.class.name(),
            })).collect::<Vec<_>>(),
        })
    }
}

impl super::Comparison for GreyReport {
    fn to_html(&self, page: &super::HtmlInputs<'_>) -> Option<String> {
        Some(GreyReport::to_html(self, page))
    }

    fn identical(&self) -> bool {
        GreyReport::identical(self)
    }

    /// The differing pixels by grey class.
    fn counts(&self) -> Vec<(String, usize)> {
        self.classes().into_iter().map(|(c, n)| (c.name(), n)).collect()
    }

    /// A header naming both files and the model, then [`GreyReport::levels_text`].
    fn to_text(&self, scene: &str, theirs: &str, limit: usize) -> String {
        format!(
            "compare --as grey: {theirs} against {scene} (model {})\n{}",
            self.model,
            self.levels_text(limit)
        )
    }

    /// [`GreyReport::levels_json`].
    fn to_json(&self, _scene: &str, _theirs: &str) -> serde_json::Value {
        self.levels_json()
    }
}
