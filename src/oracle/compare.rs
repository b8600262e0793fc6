//! Comparing another renderer's output with the oracle's, pixel by pixel, and explaining
//! every difference ([`compare`], [`Report`]).

use std::collections::BTreeMap;
use std::fmt::{self, Write as _};

use image::{Rgb, RgbImage};
use serde_json::{json, Value};

use super::evidence::{distance_f64, distance_text, exact_distance, polygon_at, triangle_at};
use super::reason::{primitive_name, Classifier, Reason, ReasonClass};
use super::theirs::{Format, TheirPixel, Theirs};
use crate::convention::{Convention, PixelCentre, Target};
use crate::coverage::picture::{upscale, Scale};
use crate::coverage::Coverage;
use crate::geom::Point;
use crate::model::{prepare, Model, ModelError, Primitives, Shape};
use crate::num::exact::{exact_text, pair_text};
use crate::raster::sample_exact;

/// The version of the JSON report's schema ([`Report::to_json`]).
pub const REPORT_VERSION: u32 = 1;

/// How a differing pixel differs, seen from the whole pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum PixelKind {
    /// The oracle covers it, they do not (or they name fewer owners).
    Missing,
    /// They cover it, the oracle does not.
    Extra,
    /// Both cover it, with different owners.
    WrongOwner,
    /// They cover it more often than the oracle (a second owner, or one twice).
    Double,
}

impl PixelKind {
    /// Every kind, in report order.
    pub const ALL: [PixelKind; 4] = [
        PixelKind::Missing,
        PixelKind::Extra,
        PixelKind::WrongOwner,
        PixelKind::Double,
    ];

    /// Its name in reports.
    pub fn name(self) -> &'static str {
        match self {
            PixelKind::Missing => "missing",
            PixelKind::Extra => "extra",
            PixelKind::WrongOwner => "wrong owner",
            PixelKind::Double => "double",
        }
    }

    /// Its colour in the difference picture.
    pub fn colour(self) -> [u8; 3] {
        match self {
            PixelKind::Missing => [230, 40, 40],
            PixelKind::Extra => [40, 200, 60],
            PixelKind::WrongOwner => [240, 220, 40],
            PixelKind::Double => [220, 60, 220],
        }
    }
}

/// The colour of a pixel both cover with the same owners, in the difference picture.
pub const MATCHED_COLOUR: [u8; 3] = [128, 128, 128];
/// The colour of a pixel neither covers.
pub const EMPTY_COLOUR: [u8; 3] = [0, 0, 0];

/// One primitive's part in a differing pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Relation {
    /// The primitive covers the pixel in the oracle, not in theirs.
    Missing,
    /// The primitive covers the pixel in theirs, not in the oracle.
    Extra,
}

impl Relation {
    /// `missing` or `extra`.
    pub fn name(self) -> &'static str {
        match self {
            Relation::Missing => "missing",
            Relation::Extra => "extra",
        }
    }
}

/// One primitive's difference at one pixel, explained.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Finding {
    /// The primitive (`None`: their output names an owner no primitive explains).
    pub id: Option<u32>,
    /// Its scene field and index (`triangles[3]`); `None` with `id`, or for an id their
    /// output names that is not in the scene.
    pub primitive: Option<String>,
    /// Missing or extra.
    pub relation: Relation,
    /// True when their output names no owner here (a mask, a double cover's second owner)
    /// and `id` is the primitive that explains the pixel best.
    pub guessed: bool,
    /// Why.
    pub reason: Reason,
    /// The oracle's exact evidence for this primitive at the sample (edge values and
    /// flags, winding numbers, the line test), one line.
    pub evidence: String,
}

/// A pixel where their output differs from the oracle's.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DiffPixel {
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// How it differs.
    pub kind: PixelKind,
    /// The oracle's owners, ascending.
    pub ours: Vec<u32>,
    /// Theirs.
    pub theirs: TheirPixel,
    /// Per primitive, why.
    pub findings: Vec<Finding>,
}

/// The comparison of their output with the oracle's.
#[derive(Debug, Clone)]
pub struct Report {
    /// The oracle model.
    pub model: Model,
    /// The convention.
    pub convention: Convention,
    /// How their file was read.
    pub format: Format,
    /// Canvas width.
    pub width: u32,
    /// Canvas height.
    pub height: u32,
    /// Pixels the oracle covers.
    pub ours_covered: usize,
    /// Pixels they cover.
    pub theirs_covered: usize,
    /// Every differing pixel, row-major.
    pub pixels: Vec<DiffPixel>,
    ours: Coverage,
}

/// Their canvas is not the scene's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SizeMismatch {
    /// Their width and height.
    pub theirs: (u32, u32),
    /// The scene's.
    pub scene: (u32, u32),
}

impl SizeMismatch {
    /// `Err` when `theirs` is not `target`'s size.
    pub fn check(theirs: &Theirs, target: &Target) -> Result<(), SizeMismatch> {
        let m = SizeMismatch {
            theirs: (theirs.width(), theirs.height()),
            scene: (target.width, target.height),
        };
        if m.theirs == m.scene {
            Ok(())
        } else {
            Err(m)
        }
    }
}

impl fmt::Display for SizeMismatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "their image is {}x{} but the scene's canvas is {}x{}",
            self.theirs.0, self.theirs.1, self.scene.0, self.scene.1
        )
    }
}

/// Why a comparison could not be made.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CompareError {
    /// Their canvas is not the scene's.
    Size(SizeMismatch),
    /// The oracle must be an exact model.
    NotExact(Model),
    /// The oracle model refused the scene.
    Model(ModelError),
}

impl fmt::Display for CompareError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CompareError::Size(m) => write!(f, "{m}"),
            CompareError::NotExact(m) => write!(
                f,
                "--model {}: the oracle must be an exact model (exact, exact-snapped, exact-plain, exact-snapped-plain)",
                m.name()
            ),
            CompareError::Model(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for CompareError {}

/// Compares `theirs` with what the exact `model` renders of `primitives` on `target`, and
/// explains every differing pixel (see [`super::reason`] for the classes).
///
/// What a pixel's owners are in each format, and so what can differ: a mask names none
/// (missing and extra only; an extra pixel is explained by the primitive that explains it
/// best, `guessed`); an ids PNG names the highest owner and marks several (a pixel the
/// oracle gives owners `O` should hold `max(O)`, marked when `|O| >= 2`); JSON names all.
///
/// ```
/// use rasterproof::model::{render, Model};
/// use rasterproof::oracle::{compare, Format, Theirs};
/// use rasterproof::scene::parse_scene;
/// let scene = parse_scene(r#"{"width": 4, "height": 4, "triangles": [{"v": [[0, 0], [4, 0], [0, 4]]}]}"#, "s.json").unwrap();
/// let target = scene.target().unwrap();
/// let ours = render(Model::ExactSnapped, &scene.primitives(), &target).unwrap();
/// let theirs = Theirs::from_coverage(&ours, Format::Ids);
/// let report = compare(&scene.primitives(), &target, Model::ExactSnapped, &theirs).unwrap();
/// assert!(report.pixels.is_empty());
/// ```
///
/// # Errors
/// Their canvas differs from `target`'s, `model` is not exact, or it refuses the scene.
pub fn compare(
    primitives: &Primitives,
    target: &Target,
    model: Model,
    theirs: &Theirs,
) -> Result<Report, CompareError> {
    SizeMismatch::check(theirs, target).map_err(CompareError::Size)?;
    if !model.is_exact() {
        return Err(CompareError::NotExact(model));
    }
    let prepared = prepare(model, primitives, target).map_err(CompareError::Model)?;
    let ours = prepared.coverage(target);
    let shapes = prepared.shapes().ok_or(CompareError::NotExact(model))?;
    let mut classifier = Classifier::new(primitives, target, model, &shapes);
    let index = Candidates::new(&shapes, target);
    let mut keys: Vec<(u32, u32)> = ours.iter().map(|(x, y, _)| (y, x)).collect();
    keys.extend(theirs.covered().into_iter().map(|(x, y)| (y, x)));
    keys.sort_unstable();
    keys.dedup();
    let mut pixels = Vec::new();
    for (y, x) in keys {
        {
            let o = ours.owners(x, y);
            let t = theirs.pixel(x, y);
            let Some((kind, missing, extra, unnamed)) = differ(o, &t, theirs.format()) else {
                continue;
            };
            let mut findings = Vec::new();
            for id in missing {
                findings.push(named(&mut classifier, primitives, id, Relation::Missing, x, y, target));
            }
            for id in extra {
                findings.push(named(&mut classifier, primitives, id, Relation::Extra, x, y, target));
            }
            if unnamed {
                let candidates: Vec<usize> = index
                    .near(x, y)
                    .into_iter()
                    .filter(|&k| !o.iter().any(|&id| usize::try_from(id).ok() == Some(k)))
                    .collect();
                findings.push(guessed(&mut classifier, primitives, &candidates, x, y, target));
            }
            pixels.push(DiffPixel {
                x,
                y,
                kind,
                ours: o.to_vec(),
                theirs: t,
                findings,
            });
        }
    }
    Ok(Report {
        model,
        convention: target.convention,
        format: theirs.format(),
        width: target.width,
        height: target.height,
        ours_covered: ours.covered_pixels(),
        theirs_covered: theirs.covered_pixels(),
        pixels,
        ours,
    })
}

/// Differing pixels of `ours` against `theirs`, by kind, as [`compare`] counts them (without
/// explaining them); with `stop`, counting ends once that many are found.
pub fn count_differences(ours: &Coverage, theirs: &Theirs, stop: Option<usize>) -> BTreeMap<PixelKind, usize> {
    let mut keys: Vec<(u32, u32)> = ours.iter().map(|(x, y, _)| (y, x)).collect();
    keys.extend(theirs.covered().into_iter().map(|(x, y)| (y, x)));
    keys.sort_unstable();
    keys.dedup();
    let mut out = BTreeMap::new();
    let mut total = 0;
    for (y, x) in keys {
        if let Some((kind, ..)) = differ(ours.owners(x, y), &theirs.pixel(x, y), theirs.format()) {
            *out.entry(kind).or_insert(0) += 1;
            total += 1;
            if stop.is_some_and(|s| total >= s) {
                break;
            }
        }
    }
    out
}

/// The multiset difference `a - b` of two ascending lists.
fn minus(a: &[u32], b: &[u32]) -> Vec<u32> {
    let mut rest = b.to_vec();
    let mut out = Vec::new();
    for &v in a {
        if let Some(k) = rest.iter().position(|&w| w == v) {
            rest.remove(k);
        } else {
            out.push(v);
        }
    }
    out
}

/// How ours (`o`) and theirs (`t`) differ at a pixel: the kind, the ids missing in theirs,
/// the ids extra in theirs, and whether an owner they do not name is extra; `None` when
/// they agree (as far as the format tells).
fn differ(o: &[u32], t: &TheirPixel, format: Format) -> Option<(PixelKind, Vec<u32>, Vec<u32>, bool)> {
    match format {
        Format::Mask => match (o.is_empty(), t.covered) {
            (false, false) => Some((PixelKind::Missing, o.to_vec(), Vec::new(), false)),
            (true, true) => Some((PixelKind::Extra, Vec::new(), Vec::new(), true)),
            _ => None,
        },
        Format::Ids => {
            let (Some(&h), Some(&top)) = (t.ids.first(), o.last()) else {
                return match (o.is_empty(), t.covered) {
                    (false, false) => Some((PixelKind::Missing, o.to_vec(), Vec::new(), false)),
                    (true, true) => Some((PixelKind::Extra, Vec::new(), t.ids.clone(), t.several)),
                    _ => None,
                };
            };
            let several = o.len() > 1;
            if h == top && t.several == several {
                None
            } else if h == top && t.several {
                Some((PixelKind::Double, Vec::new(), Vec::new(), true))
            } else if h == top {
                Some((PixelKind::Missing, o[..o.len() - 1].to_vec(), Vec::new(), false))
            } else {
                // One owner named: every other owner of ours is missing. Several marked: the
                // highest is named, so only ours above it are known to be missing.
                let missing: Vec<u32> = o
                    .iter()
                    .copied()
                    .filter(|&id| if t.several { id > h } else { id != h })
                    .collect();
                let extra = if o.contains(&h) { Vec::new() } else { vec![h] };
                Some((PixelKind::WrongOwner, missing, extra, false))
            }
        }
        Format::Json => {
            if o == t.ids.as_slice() {
                return None;
            }
            let (missing, extra) = (minus(o, &t.ids), minus(&t.ids, o));
            let kind = if t.ids.is_empty() || extra.is_empty() {
                PixelKind::Missing
            } else if o.is_empty() {
                PixelKind::Extra
            } else if missing.is_empty() {
                PixelKind::Double
            } else {
                PixelKind::WrongOwner
            };
            Some((kind, missing, extra, false))
        }
    }
}

/// The finding for a primitive their output (or the oracle) names.
fn named(
    classifier: &mut Classifier<'_>,
    primitives: &Primitives,
    id: u32,
    relation: Relation,
    x: u32,
    y: u32,
    target: &Target,
) -> Finding {
    let k = usize::try_from(id).ok().filter(|&k| k < classifier.shapes().len());
    let Some(k) = k else {
        return Finding {
            id: Some(id),
            primitive: None,
            relation,
            guessed: false,
            reason: Reason::Gross { distance2: None },
            evidence: format!("id {id} is not a primitive of the scene"),
        };
    };
    let reason = classifier.reason(k, x, y, relation == Relation::Extra);
    Finding {
        id: Some(id),
        primitive: primitive_name(primitives, id),
        relation,
        guessed: false,
        reason,
        evidence: evidence(&classifier.shapes()[k], x, y, target),
    }
}

/// The finding for an extra owner their output does not name: the candidate primitive
/// that explains it best, or none (gross) when none does.
fn guessed(
    classifier: &mut Classifier<'_>,
    primitives: &Primitives,
    candidates: &[usize],
    x: u32,
    y: u32,
    target: &Target,
) -> Finding {
    match classifier.best_extra(candidates, x, y) {
        Some((k, reason)) if reason.class() != ReasonClass::Gross => {
            let id = u32::try_from(k).expect("ids fit u32");
            Finding {
                id: Some(id),
                primitive: primitive_name(primitives, id),
                relation: Relation::Extra,
                guessed: true,
                reason,
                evidence: evidence(&classifier.shapes()[k], x, y, target),
            }
        }
        best => Finding {
            id: None,
            primitive: None,
            relation: Relation::Extra,
            guessed: true,
            reason: Reason::Gross {
                distance2: best.and_then(|(_, r)| match r {
                    Reason::Gross { distance2 } => distance2,
                    _ => None,
                }),
            },
            evidence: format!(
                "no primitive has an edge within 1 px of the sample {}",
                point_text(&sample_exact(x, y, target))
            ),
        },
    }
}

fn point_text(p: &Point) -> String {
    pair_text(&p.x, &p.y)
}

/// The oracle's evidence for `shape` at pixel `(x, y)`, one line.
pub(crate) fn evidence(shape: &Shape, x: u32, y: u32, target: &Target) -> String {
    let p = sample_exact(x, y, target);
    let rule = target.convention.tie_rule;
    let s = format!("sample {}: ", point_text(&p));
    match shape {
        Shape::Triangle(t) => match triangle_at(t, &p, rule.into()) {
            Some(at) => s + &at.to_string(),
            None => s + "zero-area triangle -> outside",
        },
        Shape::Polygon(poly) => {
            let at = polygon_at(poly, &p, rule);
            format!("{s}{} ({}) {at}", "polygon", poly.fill_rule.name())
        }
        Shape::Diamond { from, to } => {
            let exits = crate::line::exact::diamond_exits(from, to, i64::from(x), i64::from(y), target);
            format!(
                "{s}diamond-exit line {} -> {}: {}",
                point_text(from),
                point_text(to),
                if exits {
                    "exits the pixel's diamond -> covered"
                } else {
                    "does not exit the pixel's diamond -> not covered"
                }
            )
        }
        Shape::Bresenham { from, to, tie } => format!(
            "Bresenham line ({}, {}) -> ({}, {}), ties {}; pixel ({x}, {y})",
            from[0],
            from[1],
            to[0],
            to[1],
            tie.name()
        ),
    }
}

/// A coarse index of the shapes' bounding boxes (grown by 1 px), for the extra pixels
/// whose owner their output does not name.
struct Candidates {
    cell: u32,
    columns: u32,
    cells: Vec<Vec<usize>>,
}

impl Candidates {
    const CELL: u32 = 32;

    fn new(shapes: &[Shape], target: &Target) -> Candidates {
        let cell = Candidates::CELL;
        let columns = target.width.div_ceil(cell);
        let rows = target.height.div_ceil(cell);
        let mut cells = vec![Vec::new(); usize::try_from(columns * rows).expect("fits")];
        let c = target.convention.pixel_centre;
        for (k, s) in shapes.iter().enumerate() {
            let Some([x0, y0, x1, y1]) = pixel_box(s, c, target) else {
                continue;
            };
            for cy in y0 / cell..=y1 / cell {
                for cx in x0 / cell..=x1 / cell {
                    cells[usize::try_from(cy * columns + cx).expect("fits")].push(k);
                }
            }
        }
        Candidates { cell, columns, cells }
    }

    fn near(&self, x: u32, y: u32) -> Vec<usize> {
        self.cells[usize::try_from((y / self.cell) * self.columns + x / self.cell).expect("fits")].clone()
    }
}

/// Whether pixel `(x, y)` lies in `shape`'s pixel box ([`pixel_box`]).
pub(crate) fn pixel_box_holds(shape: &Shape, x: u32, y: u32, target: &Target) -> bool {
    pixel_box(shape, target.convention.pixel_centre, target)
        .is_some_and(|[x0, y0, x1, y1]| (x0..=x1).contains(&x) && (y0..=y1).contains(&y))
}

/// The pixels whose samples lie within 2 px of `shape`'s bounding box, clamped to the
/// canvas; `None` when off it.
fn pixel_box(shape: &Shape, centre: PixelCentre, target: &Target) -> Option<[u32; 4]> {
    use num_traits::ToPrimitive;
    let points: Vec<[f64; 2]> = match shape {
        Shape::Triangle(t) => t.v.iter().map(|p| [f(&p.x), f(&p.y)]).collect(),
        Shape::Polygon(poly) => poly.contours().flatten().map(|p| [f(&p.x), f(&p.y)]).collect(),
        Shape::Diamond { from, to } => [from, to].iter().map(|p| [f(&p.x), f(&p.y)]).collect(),
        Shape::Bresenham { from, to, .. } => [from, to]
            .iter()
            .map(|a| [a[0].to_f64().unwrap_or(0.0), a[1].to_f64().unwrap_or(0.0)])
            .collect(),
    };
    let off = centre.offset_f64();
    let lo = |axis: usize| points.iter().map(|p| p[axis]).fold(f64::INFINITY, f64::min) - off - 2.0;
    let hi = |axis: usize| points.iter().map(|p| p[axis]).fold(f64::NEG_INFINITY, f64::max) - off + 2.0;
    let clamp = |v: f64, side: u32| -> u32 { v.floor().clamp(0.0, f64::from(side - 1)).to_u32().unwrap_or(0) };
    let (x0, x1, y0, y1) = (lo(0), hi(0), lo(1), hi(1));
    if x1 < 0.0 || y1 < 0.0 || x0 > f64::from(target.width) || y0 > f64::from(target.height) {
        return None;
    }
    Some([
        clamp(x0, target.width),
        clamp(y0, target.height),
        clamp(x1, target.width),
        clamp(y1, target.height),
    ])
}

/// A coordinate as the nearest f64 (for the coarse index only; ±inf when out of range).
fn f(v: &num_rational::BigRational) -> f64 {
    use num_traits::Signed;
    crate::num::exact::nearest_f64(v).unwrap_or(if v.is_negative() {
        f64::NEG_INFINITY
    } else {
        f64::INFINITY
    })
}

impl Report {
    /// True when their output equals the oracle's (as far as the format tells).
    pub fn identical(&self) -> bool {
        self.pixels.is_empty()
    }

    /// Findings counted by pixel kind and reason class (a pixel with two primitives'
    /// findings counts twice).
    pub fn summary(&self) -> BTreeMap<(PixelKind, ReasonClass), usize> {
        let mut out = BTreeMap::new();
        for p in &self.pixels {
            for f in &p.findings {
                *out.entry((p.kind, f.reason.class())).or_insert(0) += 1;
            }
        }
        out
    }

    /// Differing pixels by kind.
    pub fn pixels_by_kind(&self) -> BTreeMap<PixelKind, usize> {
        let mut out = BTreeMap::new();
        for p in &self.pixels {
            *out.entry(p.kind).or_insert(0) += 1;
        }
        out
    }

    /// The text report: a header, the summary table (findings by pixel kind and reason
    /// class), then the first `limit` differing pixels, each with every finding's reason
    /// and the oracle's exact evidence.
    pub fn to_text(&self, scene: &str, theirs: &str, limit: usize) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "compare: {theirs} (as {}) against {scene}: model {}, {}",
            self.format.name(),
            self.model.name(),
            self.convention
        );
        let _ = writeln!(
            s,
            "canvas {}x{}: the oracle covers {} pixels, theirs {}; {} differ",
            self.width,
            self.height,
            self.ours_covered,
            self.theirs_covered,
            self.pixels.len()
        );
        if self.pixels.is_empty() {
            s.push_str("identical\n");
            return s;
        }
        let summary = self.summary();
        let classes: Vec<ReasonClass> = ReasonClass::ALL
            .into_iter()
            .filter(|c| summary.keys().any(|(_, k)| k == c))
            .collect();
        let by_kind = self.pixels_by_kind();
        let _ = write!(s, "\n{:<12} {:>7}", "", "pixels");
        for c in &classes {
            let _ = write!(s, " {:>10}", c.name());
        }
        s.push('\n');
        for kind in PixelKind::ALL {
            let Some(n) = by_kind.get(&kind) else { continue };
            let _ = write!(s, "{:<12} {n:>7}", kind.name());
            for c in &classes {
                let _ = write!(s, " {:>10}", summary.get(&(kind, *c)).copied().unwrap_or(0));
            }
            s.push('\n');
        }
        s.push_str(
            "(pixels: differing pixels of each kind; the class columns count findings, one per pixel and primitive)\n",
        );
        let shown = self.pixels.len().min(limit);
        if shown > 0 {
            let _ = writeln!(s, "\nthe first {shown} of {} differing pixels:", self.pixels.len());
        }
        for p in self.pixels.iter().take(limit) {
            let _ = writeln!(
                s,
                "({}, {}) {}: oracle {}, theirs {}",
                p.x,
                p.y,
                p.kind.name(),
                owners_text(&p.ours),
                their_text(&p.theirs, self.format)
            );
            for f in &p.findings {
                let who = match (&f.primitive, f.id) {
                    (Some(name), Some(id)) => format!("{name} (id {id})"),
                    (None, Some(id)) => format!("id {id}"),
                    _ => "no primitive".to_string(),
                };
                let guess = if f.guessed {
                    " (their output names no owner; the best explanation)"
                } else {
                    ""
                };
                let _ = writeln!(
                    s,
                    "  {who} {}{guess}: {}: {}",
                    f.relation.name(),
                    f.reason.class().name(),
                    reason_text(&f.reason)
                );
                let _ = writeln!(s, "    {}", f.evidence);
            }
        }
        s
    }

    /// The JSON report (schema version [`REPORT_VERSION`]), complete:
    /// `{"version", "scene", "theirs", "format", "model", "convention": {preset, tie_rule,
    /// pixel_centre, subpixel_bits, rounding}, "width", "height", "ours_covered",
    /// "theirs_covered", "differing", "pixels_by_kind": {kind: n}, "summary": [{kind, class,
    /// count}], "pixels": [{x, y, kind, ours: [ids], theirs: {covered, ids, several},
    /// findings: [{id, primitive, relation, guessed, class, reason: {...}, evidence}]}]}`.
    /// A reason holds, by class: `tie` `{edges: [{index, from, to, side, value,
    /// inclusive}], rules}`; `clip` `{unclipped_covers}`; `line-rule` `{rules}`;
    /// `fill-rule` `{winding, fill_rule}`; `snapping` `{subpixel_bits (null: unsnapped),
    /// roundings}`; `near-edge` and `gross` `{distance: {squared, exact, approx} or null}`.
    /// Exact numbers are strings (`"7/2"`).
    pub fn to_json(&self, scene: &str, theirs: &str) -> Value {
        let c = &self.convention;
        let summary: Vec<Value> = self
            .summary()
            .iter()
            .map(|((k, class), n)| json!({"kind": k.name(), "class": class.name(), "count": n}))
            .collect();
        let by_kind: serde_json::Map<String, Value> = self
            .pixels_by_kind()
            .iter()
            .map(|(k, n)| (k.name().to_string(), json!(n)))
            .collect();
        let pixels: Vec<Value> = self
            .pixels
            .iter()
            .map(|p| {
                let findings: Vec<Value> = p
                    .findings
                    .iter()
                    .map(|f| {
                        json!({
                            "id": f.id,
                            "primitive": f.primitive,
                            "relation": f.relation.name(),
                            "guessed": f.guessed,
                            "class": f.reason.class().name(),
                            "reason": reason_json(&f.reason),
                            "evidence": f.evidence,
                        })
                    })
                    .collect();
                json!({
                    "x": p.x, "y": p.y, "kind": p.kind.name(), "ours": p.ours,
                    "theirs": {"covered": p.theirs.covered, "ids": p.theirs.ids, "several": p.theirs.several},
                    "findings": findings,
                })
            })
            .collect();
        json!({
            "version": REPORT_VERSION,
            "scene": scene,
            "theirs": theirs,
            "format": self.format.name(),
            "model": self.model.name(),
            "convention": {
                "preset": c.preset.name(),
                "tie_rule": c.tie_rule.name(),
                "pixel_centre": c.pixel_centre.name(),
                "subpixel_bits": c.subpixel_bits,
                "rounding": c.rounding.name(),
            },
            "width": self.width,
            "height": self.height,
            "ours_covered": self.ours_covered,
            "theirs_covered": self.theirs_covered,
            "differing": self.pixels.len(),
            "pixels_by_kind": by_kind,
            "summary": summary,
            "pixels": pixels,
        })
    }

    /// The difference picture at scale 1: [`EMPTY_COLOUR`] where neither covers,
    /// [`MATCHED_COLOUR`] where both agree, each differing pixel its kind's
    /// [`PixelKind::colour`]. Scale it with [`crate::coverage::picture::upscale`].
    pub fn diff_image(&self) -> RgbImage {
        let mut img = RgbImage::from_pixel(self.width, self.height, Rgb(EMPTY_COLOUR));
        for (x, y, _) in self.ours.iter() {
            img.put_pixel(x, y, Rgb(MATCHED_COLOUR));
        }
        for p in &self.pixels {
            img.put_pixel(p.x, p.y, Rgb(p.kind.colour()));
        }
        img
    }

    /// [`Report::diff_image`] scaled by `scale`.
    pub fn diff_picture(&self, scale: Scale) -> RgbImage {
        upscale(&self.diff_image(), scale)
    }

    /// The legend of the difference picture: each colour, what it means and how many
    /// pixels have it.
    pub fn diff_legend(&self, scale: Scale) -> String {
        let by_kind = self.pixels_by_kind();
        let hex = |c: [u8; 3]| format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]);
        let matched = self.ours_covered - self.pixels.iter().filter(|p| !p.ours.is_empty()).count();
        let mut s = format!(
            "difference picture: {}x{} canvas, each pixel {k}x{k} picture pixels\n",
            self.width,
            self.height,
            k = scale.get()
        );
        let _ = writeln!(
            s,
            "{}  matched (both cover it, same owners)  {matched}",
            hex(MATCHED_COLOUR)
        );
        for kind in PixelKind::ALL {
            let _ = writeln!(
                s,
                "{}  {:<36}  {}",
                hex(kind.colour()),
                kind.name(),
                by_kind.get(&kind).copied().unwrap_or(0)
            );
        }
        let _ = writeln!(s, "{}  neither covers it", hex(EMPTY_COLOUR));
        s
    }
}

fn owners_text(ids: &[u32]) -> String {
    if ids.is_empty() {
        "none".to_string()
    } else {
        let v: Vec<String> = ids.iter().map(u32::to_string).collect();
        format!("[{}]", v.join(", "))
    }
}

fn their_text(t: &TheirPixel, format: Format) -> String {
    match (format, t.covered) {
        (_, false) => "none".to_string(),
        (Format::Mask, true) => "covered".to_string(),
        (Format::Ids, true) if t.several => format!("{} and others (several owners)", owners_text(&t.ids)),
        _ => owners_text(&t.ids),
    }
}

/// A reason in words.
pub fn reason_text(r: &Reason) -> String {
    match r {
        Reason::Tie { edges, rules } => {
            let names: Vec<&str> = rules.iter().map(|r| r.name()).collect();
            let on = if edges.is_empty() {
                "the sample lies on the polygon's outline".to_string()
            } else {
                let e: Vec<String> = edges
                    .iter()
                    .map(|e| {
                        format!(
                            "edge {} {} -> {} (a {} edge, {} here)",
                            e.index,
                            point_text(&e.from),
                            point_text(&e.to),
                            e.side.name(),
                            if e.inclusive { "inclusive" } else { "exclusive" }
                        )
                    })
                    .collect();
                format!("the sample lies on {}", e.join(" and "))
            };
            format!("{on}; their answer is the tie rule {}", names.join(" or "))
        }
        Reason::Clip { unclipped_covers } => format!(
            "the primitive without the clip window {} the pixel: they did not clip (or clipped elsewhere)",
            if *unclipped_covers { "covers" } else { "does not cover" }
        ),
        Reason::LineRule { rules } => format!("their answer is the line rule {}", rules.join(" or ")),
        Reason::FillRule { winding, fill_rule } => {
            format!(
                "winding number {winding}; their answer is the fill rule {}",
                fill_rule.name()
            )
        }
        Reason::Snapping {
            bits: Some(b),
            roundings,
        } => {
            let names: Vec<&str> = roundings.iter().map(|r| r.name()).collect();
            format!(
                "their answer is snapping to {b} subpixel bits, rounding {}",
                names.join(" or ")
            )
        }
        Reason::Snapping { bits: None, .. } => {
            "their answer is the unsnapped primitive (no subpixel snapping of 1..=16 bits gives it)".to_string()
        }
        Reason::NearEdge { distance2 } => format!("the sample is {} from an edge", distance_text(distance2)),
        Reason::Gross { distance2: Some(d) } => format!("the sample is {} from the nearest edge", distance_text(d)),
        Reason::Gross { distance2: None } => "no edge within 1 px".to_string(),
    }
}

fn distance_json(d2: &num_rational::BigRational) -> Value {
    json!({"squared": exact_text(d2), "exact": exact_distance(d2), "approx": distance_f64(d2)})
}

fn reason_json(r: &Reason) -> Value {
    match r {
        Reason::Tie { edges, rules } => {
            let edges: Vec<Value> = edges
                .iter()
                .map(|e| {
                    json!({
                        "index": e.index,
                        "from": [exact_text(&e.from.x), exact_text(&e.from.y)],
                        "to": [exact_text(&e.to.x), exact_text(&e.to.y)],
                        "side": e.side.name(),
                        "value": exact_text(&e.value),
                        "inclusive": e.inclusive,
                    })
                })
                .collect();
            let rules: Vec<&str> = rules.iter().map(|r| r.name()).collect();
            json!({"edges": edges, "rules": rules})
        }
        Reason::Clip { unclipped_covers } => json!({"unclipped_covers": unclipped_covers}),
        Reason::LineRule { rules } => json!({ "rules": rules }),
        Reason::FillRule { winding, fill_rule } => json!({"winding": winding, "fill_rule": fill_rule.name()}),
        Reason::Snapping { bits, roundings } => {
            let names: Vec<&str> = roundings.iter().map(|r| r.name()).collect();
            json!({"subpixel_bits": bits, "roundings": names})
        }
        Reason::NearEdge { distance2 } => json!({ "distance": distance_json(distance2) }),
        Reason::Gross { distance2 } => json!({ "distance": distance2.as_ref().map(distance_json) }),
    }
}
