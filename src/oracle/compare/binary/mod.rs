//! One sample per pixel: another renderer's mask, ids PNG or JSON compared with the
//! oracle's coverage, pixel by pixel, every difference explained ([`compare`],
//! [`CompareReport`]).
//!
//! This module holds the diffing: how a pixel differs ([`PixelKind`], [`Relation`]) and
//! [`compare`] itself. Its parts, each
//! re-exported here: the evidence at one differing pixel and the spatial index of the
//! shapes that may explain it (`pixel`), and the [`CompareReport`] with its text, JSON and
//! difference picture (`report`).

mod html;
mod pixel;
mod report;

use std::collections::BTreeMap;

pub use html::{escape as html_escape, html_page, view_block, HTML_EXPLAINED_AT_MOST};
pub(crate) use pixel::{evidence, evidence_at, pixel_box_holds};
pub use pixel::{DiffPixel, PixelFinding};
pub use report::{reason_text, CompareReport, COMPARE_REPORT_VERSION, EMPTY_COLOUR, MATCHED_COLOUR};

use super::{CompareError, SizeMismatch};
use crate::convention::Target;
use crate::coverage::Coverage;
use crate::model::{prepare_parallel, Model, Primitives};
use crate::oracle::candidate::{image, snapped, Candidate};
use crate::oracle::reason::{decide, Classifier, Snapping, Support};
use crate::oracle::theirs::{Format, TheirPixel, Theirs};
use pixel::{guessed, named, Candidates};
use report::Joint;

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

/// How many differing pixels [`compare`] classifies: a renderer that gets a whole image
/// wrong is judged in seconds, not hours (each classification runs exact searches). Its
/// differing pixels are all found and counted by kind; [`pick_classified`] says which are
/// classified.
pub const CLASSIFY_AT_MOST: usize = 2000;

/// Which of `total` differing pixels (in row order) a comparison that classifies at most
/// `at_most` classifies: all when they are that few; else the first half of `at_most` in
/// row order (the top of the picture, whole) and the other half spread evenly over the
/// rest (pixel `h + floor(j (total - h) / k)` for `j` in `0..k`, `h` and `k` the two
/// halves), so the sample reaches down the picture.
///
/// ```
/// use rasterproof::oracle::compare::pick_classified;
/// assert_eq!(pick_classified(3, 10), vec![true; 3]);
/// let picked = pick_classified(10, 4);
/// let at: Vec<usize> = (0..10).filter(|&i| picked[i]).collect();
/// assert_eq!(at, vec![0, 1, 2, 6]); // 2 first, then 2 + floor(j * 8 / 2) for j = 0, 1
/// ```
pub fn pick_classified(total: usize, at_most: usize) -> Vec<bool> {
    if total <= at_most {
        return vec![true; total];
    }
    let head = at_most / 2;
    let spread = at_most - head;
    let mut picked = vec![false; total];
    picked[..head].fill(true);
    for j in 0..spread {
        picked[head + j * (total - head) / spread] = true;
    }
    picked
}

/// How a one-sample comparison is made: the oracle model, how many differing pixels are
/// classified, and on how many threads the scene is drawn. `CompareOptions::from(model)`
/// (or `model.into()`) classifies at most [`CLASSIFY_AT_MOST`] on one thread.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CompareOptions {
    /// The exact model whose coverage is the answer.
    pub model: Model,
    /// How many differing pixels are classified (`None`: every one), picked by
    /// [`pick_classified`].
    pub classify_at_most: Option<usize>,
    /// Threads drawing the scene ([`crate::model::PreparedScene::coverage_parallel`]: the
    /// same coverage as one thread's); the classification runs on one.
    pub jobs: usize,
}

impl From<Model> for CompareOptions {
    fn from(model: Model) -> CompareOptions {
        CompareOptions {
            model,
            classify_at_most: Some(CLASSIFY_AT_MOST),
            jobs: 1,
        }
    }
}

/// Compares `theirs` with what the exact `options.model` renders of `primitives` on
/// `target`, and explains the differing pixels (see [`crate::oracle::reason`] for the
/// classes): every one of them is found and counted by kind, and at most
/// `options.classify_at_most` are classified ([`pick_classified`]).
///
/// What a pixel's owners are in each format, and so what can differ: a mask names none
/// (missing and extra only; an extra pixel is explained by the primitive that explains it
/// best, `guessed`); an ids PNG names the highest owner and marks several (a pixel the
/// oracle gives owners `O` should hold `max(O)`, marked when `|O| >= 2`); JSON names all.
///
/// ```
/// use rasterproof::model::{render, Model};
/// use rasterproof::oracle::{compare, Comparison, Format, Theirs};
/// use rasterproof::scene::parse_scene;
/// let scene = parse_scene(r#"{"width": 4, "height": 4, "triangles": [{"v": [[0, 0], [4, 0], [0, 4]]}]}"#, "s.json").unwrap();
/// let target = scene.target().unwrap();
/// let ours = render(&scene.primitives(), &target, Model::ExactSnapped).unwrap();
/// let theirs = Theirs::from_coverage(&ours, Format::Ids);
/// let report = compare(&scene.primitives(), &target, &theirs, &Model::ExactSnapped.into()).unwrap();
/// assert!(report.identical());
/// ```
///
/// # Errors
/// Their canvas differs from `target`'s, the model is not exact, or it refuses the scene.
pub fn compare(
    primitives: &Primitives,
    target: &Target,
    theirs: &Theirs,
    options: &CompareOptions,
) -> Result<CompareReport, CompareError> {
    let CompareOptions {
        model,
        classify_at_most: at_most,
        jobs,
    } = *options;
    SizeMismatch::check(theirs, target).map_err(CompareError::Size)?;
    if !model.is_exact() {
        return Err(CompareError::NotExact(model));
    }
    let prepared = prepare_parallel(primitives, target, model, jobs).map_err(CompareError::Model)?;
    let ours = prepared.coverage_parallel(target, jobs, &|| {});
    // The differing pixels, all of them; then which are classified.
    let differing: Vec<(u32, u32, TheirPixel, DiffOwners)> = covered_by_either(&ours, theirs)
        .filter_map(|(y, x)| {
            let t = theirs.pixel(x, y);
            differ(ours.owners(x, y), &t, theirs.format()).map(|d| (x, y, t, d))
        })
        .collect();
    // The index is built only when a pixel differs: an identical image costs its render,
    // its shapes and one pass over the covered pixels.
    let shapes = prepared.shapes().ok_or(CompareError::NotExact(model))?;
    let mut classifier = Classifier::new(primitives, target, model, &shapes);
    let index = if differing.is_empty() {
        Candidates::new(&[], target)
    } else {
        Candidates::new(&shapes, target)
    };
    let picked = pick_classified(differing.len(), at_most.unwrap_or(usize::MAX));
    // Pass one: every finding with what the searches found; pass two decides each with
    // the support of the whole comparison (`reason::decide`).
    let mut pixels = Vec::new();
    let mut found = Vec::new();
    let mut support = Support::default();
    for ((x, y, t, (kind, missing, extra, unnamed)), classified) in differing.into_iter().zip(picked) {
        let o = ours.owners(x, y);
        if !classified {
            pixels.push(DiffPixel {
                x,
                y,
                kind,
                ours: o.to_vec(),
                theirs: t,
                classified: false,
                findings: Vec::new(),
            });
            continue;
        }
        let mut findings = Vec::new();
        let mut push = |(finding, f)| {
            support.add(&f);
            found.push(f);
            findings.push(finding);
        };
        for id in missing {
            push(named(&mut classifier, primitives, id, Relation::Missing, x, y, target));
        }
        for id in extra {
            push(named(&mut classifier, primitives, id, Relation::Extra, x, y, target));
        }
        if unnamed {
            let candidates: Vec<usize> = index
                .near(x, y)
                .into_iter()
                .filter(|&k| !o.iter().any(|&id| usize::try_from(id).ok() == Some(k)))
                .collect();
            push(guessed(&mut classifier, primitives, &candidates, x, y, target));
        }
        pixels.push(DiffPixel {
            x,
            y,
            kind,
            ours: o.to_vec(),
            theirs: t,
            classified: true,
            findings,
        });
    }
    let mut found = found.into_iter();
    for f in pixels.iter_mut().flat_map(|p: &mut DiffPixel| p.findings.iter_mut()) {
        f.reason = decide(found.next().expect("one found per finding"), &support);
    }
    let joint = joint_checked(&pixels, primitives, target, theirs.format());
    Ok(CompareReport {
        model,
        convention: target.convention,
        format: theirs.format(),
        width: target.width,
        height: target.height,
        ours_covered: ours.covered_pixels(),
        theirs_covered: theirs.covered_pixels(),
        pixels,
        ours,
        joint,
    })
}

/// The two-part explanation of the classified differences ([`report::joint_parts`]),
/// checked: the scene snapped to its grid with its first rounding, drawn under its first
/// tie rule with the oracle's sample position, must give their answer at every classified
/// differing pixel. Unchecked (`checked: None`) when that image cannot be drawn: clip-space
/// triangles, or a rule other than top-left and bottom-left under a clip window.
fn joint_checked(pixels: &[DiffPixel], primitives: &Primitives, target: &Target, format: Format) -> Option<Joint> {
    let mut joint = report::joint_parts(pixels)?;
    let candidate = Candidate {
        tie_rule: joint.rules[0],
        snapping: Snapping {
            bits: Some(joint.bits),
            rounding: joint.roundings[0],
        },
        pixel_centre: target.convention.pixel_centre,
    };
    if primitives.clip_space_triangles.is_empty() {
        if let Ok(Some(both)) = image(&snapped(primitives, candidate.snapping), target, &candidate) {
            joint.checked = Some(
                pixels
                    .iter()
                    .filter(|p| p.classified)
                    .all(|p| differ(both.owners(p.x, p.y), &p.theirs, format).is_none()),
            );
        }
    }
    Some(joint)
}

/// Differing pixels of `ours` against `theirs`, by kind, as [`compare`] counts them (without
/// explaining them); with `stop`, counting ends once that many are found.
pub fn count_differences(ours: &Coverage, theirs: &Theirs, stop: Option<usize>) -> BTreeMap<PixelKind, usize> {
    let mut out = BTreeMap::new();
    let mut total = 0;
    for (y, x) in covered_by_either(ours, theirs) {
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

/// The pixels either side covers, `(y, x)` in row order, each once: the two row-ordered
/// lists merged (no sort: a fit counts the differences of a thousand images).
fn covered_by_either<'a>(ours: &'a Coverage, theirs: &Theirs) -> impl Iterator<Item = (u32, u32)> + 'a + use<'a> {
    let mut a = ours.iter().map(|(x, y, _)| (y, x)).peekable();
    let mut b = theirs.covered().into_iter().map(|(x, y)| (y, x)).peekable();
    std::iter::from_fn(move || match (a.peek().copied(), b.peek().copied()) {
        (Some(p), Some(q)) => {
            if p <= q {
                a.next();
            }
            if q <= p {
                b.next();
            }
            Some(p.min(q))
        }
        (Some(_), None) => a.next(),
        (None, _) => b.next(),
    })
}

/// How a pixel differs ([`differ`]): its kind, the ids missing in theirs, the ids extra in
/// theirs, and whether an owner they do not name is extra.
type DiffOwners = (PixelKind, Vec<u32>, Vec<u32>, bool);

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
fn differ(o: &[u32], t: &TheirPixel, format: Format) -> Option<DiffOwners> {
    match format {
        Format::Mask | Format::Grey | Format::Values => match (o.is_empty(), t.covered) {
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

impl super::Comparison for CompareReport {
    fn identical(&self) -> bool {
        CompareReport::identical(self)
    }

    /// The findings by reason class (a pixel with two primitives' findings counts twice),
    /// then the differing pixels left unclassified.
    fn counts(&self) -> Vec<(String, usize)> {
        let mut by_class: BTreeMap<crate::oracle::reason::ReasonClass, usize> = BTreeMap::new();
        for ((_, class), n) in self.summary() {
            *by_class.entry(class).or_insert(0) += n;
        }
        let mut out: Vec<(String, usize)> = by_class.into_iter().map(|(c, n)| (c.name().to_string(), n)).collect();
        let unclassified = self.pixels.len() - self.classified();
        if unclassified > 0 {
            out.push(("unclassified".to_string(), unclassified));
        }
        out
    }

    fn to_text(&self, scene: &str, theirs: &str, limit: usize) -> String {
        CompareReport::to_text(self, scene, theirs, limit)
    }

    fn to_json(&self, scene: &str, theirs: &str) -> serde_json::Value {
        CompareReport::to_json(self, scene, theirs)
    }

    fn to_html(&self, page: &super::HtmlInputs<'_>) -> Option<String> {
        Some(CompareReport::to_html(
            self,
            page.scene,
            page.theirs,
            page.scene_json,
            page.command,
        ))
    }
}
