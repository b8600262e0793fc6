//! Fitting the convention: which tie rule, snapping and sample position make the oracle
//! produce another renderer's image exactly ([`fit`]). The experiment a driver engineer
//! runs by hand, as one search.
//!
//! The search space: the six tie rules of [`AnyTieRule`]; snapping to 0..=16 subpixel bits
//! with each [`Rounding`], or no snapping; the sample at the pixel centre or its corner —
//! 6 x (17 x 5 + 1) x 2 = 1032 conventions. Each is rendered exactly: the scene's vertices
//! snapped by the candidate (exactly, [`crate::num::fixed::snap`]), then the planned exact
//! engine; triangles and polygons take any of the six rules
//! ([`crate::tri::planned::PlannedTriangle::with_rule`],
//! [`crate::fill::polygon::PlannedPolygon::with_rule`]); a scene with a clip window only
//! over the two rules the models render (top-left, bottom-left), which its clipped pieces
//! follow.
//! Scenes with clip-space triangles are refused (their window-space vertices exist only
//! after clipping; compare them under a stated convention).
//!
//! Conventions that must draw the same image are not drawn twice: when the all-inclusive
//! and all-exclusive images are equal no sample lies on an edge and every tie rule draws
//! that image; every snapping to a grid the scene already lies on leaves the scene as it
//! is (counted once, with the unsnapped scene); and roundings at the same bits whose
//! snapped scenes are equal (compared exactly) share their counts.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use num_bigint::BigInt;
use num_traits::One;
use serde_json::{json, Value};

pub mod grey;
pub mod samples;
pub mod values;

use super::binary::{count_differences, PixelKind};
use super::{CompareError, SizeMismatch};
use crate::convention::{AnyTieRule, PixelCentre, Target};
use crate::coverage::Coverage;
use crate::geom::{CompactTriangle, Point, Triangle};
use crate::line::LineRule;
use crate::model::Primitives;
use crate::num::plan::scale_of;
use crate::num::Rounding;
use crate::oracle::candidate::{image, snapped, snappings};
use crate::oracle::reason::Snapping;
use crate::oracle::theirs::{Format, Theirs};

pub use crate::oracle::candidate::{Candidate, MAX_FIT_BITS};

/// How many distinct counts of differing pixels the closest conventions of a fit span
/// when none is exact (every convention at each of those counts is kept).
pub const CLOSEST: usize = 5;

/// A convention and how far its image is from theirs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Fit {
    /// The convention.
    pub candidate: Candidate,
    /// Differing pixels by kind (empty: it explains their image exactly).
    pub differing: BTreeMap<PixelKind, usize>,
    /// At its snapping and pixel centre no sample lies on an edge, so all six tie rules
    /// draw the same image: the image cannot tell them apart.
    pub rules_alike: bool,
}

impl Fit {
    /// How many pixels differ.
    pub fn total(&self) -> usize {
        self.differing.values().sum()
    }
}

/// What a fit found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FitReport {
    /// How their image was read (a mask, an ids PNG, JSON).
    pub format: Format,
    /// Every convention whose image equals theirs, in search order.
    pub exact: Vec<Candidate>,
    /// When none does: the closest, fewest differing pixels first: every convention
    /// whose count is among the [`CLOSEST`] smallest counts found (so conventions that tie
    /// are all kept, in search order).
    pub closest: Vec<Fit>,
    /// How many conventions were rendered.
    pub searched: usize,
    /// Why some were not (a scene with a clip window: the four rules other than top-left
    /// and bottom-left), with how many.
    pub not_searched: Option<(usize, String)>,
}

/// Searches the conventions (see the module docs) for those under which the exact image of
/// `primitives` on `target`'s canvas equals `theirs`.
///
/// ```
/// use rasterproof::model::{render, Model};
/// use rasterproof::oracle::{fit, Format, Theirs};
/// use rasterproof::scene::parse_scene;
/// // A renderer with the GL rule: the bottom edge at y = 1/2 owns its samples.
/// let scene = parse_scene(r#"{"width": 4, "height": 2, "triangles": [{"v": [[0, "0.5"], [4, "0.5"], [0, "-3.5"]]}]}"#, "s.json").unwrap();
/// let mut gl = scene.clone();
/// gl.preset = rasterproof::convention::Preset::Gl;
/// let theirs = render(&gl.primitives(), &gl.target().unwrap(), Model::ExactSnapped).unwrap();
/// let found = fit(&scene.primitives(), &scene.target().unwrap(), &Theirs::from_coverage(&theirs, Format::Ids)).unwrap();
/// use rasterproof::convention::{AnyTieRule, PixelCentre};
/// // At 8 bits with centred samples the tie rule alone decides row 0: a bottom rule.
/// let at_8_bits: Vec<AnyTieRule> = found
///     .exact
///     .iter()
///     .filter(|c| c.snapping.bits == Some(8) && c.pixel_centre == PixelCentre::Half)
///     .map(|c| c.tie_rule)
///     .collect();
/// assert!(at_8_bits.contains(&AnyTieRule::BottomLeft));
/// assert!(!at_8_bits.contains(&AnyTieRule::TopLeft));
/// ```
///
/// # Errors
/// Their canvas differs, the scene has clip-space triangles, or a snapped coordinate is
/// beyond what the exact engine accepts.
pub fn fit(primitives: &Primitives, target: &Target, theirs: &Theirs) -> Result<FitReport, CompareError> {
    SizeMismatch::check(theirs, target).map_err(CompareError::Size)?;
    if !primitives.clip_space_triangles.is_empty() {
        return Err(CompareError::ClipSpace);
    }
    let mut exact = Vec::new();
    let mut closest: Vec<Fit> = Vec::new();
    let (mut searched, mut skipped) = (0, 0);
    // Snappings that give the same scene give the same images, which are counted once:
    // every snapping to a grid the scene is already on is the scene itself, and two
    // roundings at the same bits often agree (compared exactly, scene by scene).
    let on_grid = grid_bits(primitives);
    let mut unsnapped: Option<[Counts; 2]> = None;
    let mut same_bits: Vec<(Primitives, [Counts; 2])> = Vec::new();
    let mut bits_of_same = None;
    for s in snappings() {
        let is_unsnapped = match (s.bits, on_grid) {
            (None, _) => true,
            (Some(b), Some(k)) => b >= k,
            (Some(_), None) => false,
        };
        if bits_of_same != Some(s.bits) {
            same_bits.clear();
            bits_of_same = Some(s.bits);
        }
        let counts = match &unsnapped {
            Some(counts) if is_unsnapped => counts.clone(),
            _ => {
                let scene = snapped(primitives, s);
                match same_bits.iter().find(|(earlier, _)| *earlier == scene) {
                    Some((_, counts)) => counts.clone(),
                    None => {
                        // Stop counting once the count cannot matter: at 1 when exact fits
                        // exist, just past the worst of a full list of the closest otherwise.
                        // (A count cut short is above every kept one, so whichever
                        // snapping reuses it keeps it out as well: the bound only tightens.)
                        let stop = if !exact.is_empty() {
                            Some(1)
                        } else if distinct_totals(&closest) == CLOSEST {
                            closest.last().map(|f| f.total() + 1)
                        } else {
                            None
                        };
                        let half = counts_of(&scene, target, PixelCentre::Half, theirs, stop)?;
                        let corner = counts_of(&scene, target, PixelCentre::Corner, theirs, stop)?;
                        let counts = [half, corner];
                        if is_unsnapped {
                            unsnapped = Some(counts.clone());
                        }
                        same_bits.push((scene, counts.clone()));
                        counts
                    }
                }
            }
        };
        for (pixel_centre, (by_rule, rules_alike)) in [PixelCentre::Half, PixelCentre::Corner].into_iter().zip(counts) {
            for (tie_rule, differing) in by_rule {
                let Some(differing) = differing else {
                    skipped += 1;
                    continue;
                };
                searched += 1;
                let candidate = Candidate {
                    tie_rule,
                    snapping: s,
                    pixel_centre,
                };
                let fit = Fit {
                    candidate,
                    differing,
                    rules_alike,
                };
                if fit.total() == 0 {
                    exact.push(candidate);
                } else if exact.is_empty() {
                    closest.push(fit);
                    // Stable: conventions that tie stay in search order.
                    closest.sort_by_key(Fit::total);
                    while distinct_totals(&closest) > CLOSEST {
                        let worst = closest.last().map(Fit::total);
                        closest.retain(|f| Some(f.total()) != worst);
                    }
                }
            }
        }
    }
    if !exact.is_empty() {
        closest.clear();
    }
    Ok(FitReport {
        format: theirs.format(),
        exact,
        closest,
        searched,
        not_searched: (skipped > 0).then(|| {
            (
                skipped,
                "top-right, bottom-right, all-inclusive and all-exclusive are not searched with a clip \
                 window (which edges of the clipped pieces own their samples is the window's own question)"
                    .to_string(),
            )
        }),
    })
}

/// The differing pixels of each tie rule's image at one snapping and pixel centre, by
/// kind (`None`: the rule is not searched for this scene), and whether the six rules draw
/// one image there (no sample on an edge).
type Counts = (Vec<(AnyTieRule, Option<BTreeMap<PixelKind, usize>>)>, bool);

/// How many distinct counts of differing pixels `fits` (sorted by count) hold.
fn distinct_totals(fits: &[Fit]) -> usize {
    let mut n = 0;
    let mut last = None;
    for f in fits {
        if last != Some(f.total()) {
            n += 1;
            last = Some(f.total());
        }
    }
    n
}

/// The images of `scene` (snapped already) under the six tie rules with the sample at
/// `pixel_centre`, counted against theirs (up to `stop` differing pixels each).
fn counts_of(
    scene: &Primitives,
    target: &Target,
    pixel_centre: PixelCentre,
    theirs: &Theirs,
    stop: Option<usize>,
) -> Result<Counts, CompareError> {
    let candidate = |tie_rule| Candidate {
        tie_rule,
        snapping: Snapping {
            bits: None,
            rounding: Rounding::NearestEven,
        },
        pixel_centre,
    };
    let render = |tie_rule| image(scene, target, &candidate(tie_rule)).map_err(CompareError::Model);
    // Every rule covers at least what all-exclusive covers and at most what all-inclusive
    // covers, primitive by primitive: when those two images are equal, no sample lies on
    // an edge and every rule draws that same image, which is then counted once.
    let inclusive = render(AnyTieRule::AllInclusive)?;
    let exclusive = match inclusive {
        Some(_) => render(AnyTieRule::AllExclusive)?,
        None => None,
    };
    let count = |image: &Coverage| count_differences(image, theirs, stop);
    let (inclusive, exclusive) = match (&inclusive, &exclusive) {
        (Some(i), Some(e)) if i == e => {
            let same = count(i);
            return Ok((
                AnyTieRule::ALL.into_iter().map(|r| (r, Some(same.clone()))).collect(),
                true,
            ));
        }
        (i, e) => (i.as_ref().map(count), e.as_ref().map(count)),
    };
    let mut out = Vec::new();
    for tie_rule in AnyTieRule::ALL {
        let differing = match tie_rule {
            AnyTieRule::AllInclusive => inclusive.clone(),
            AnyTieRule::AllExclusive => exclusive.clone(),
            _ => render(tie_rule)?.map(|image| count(&image)),
        };
        out.push((tie_rule, differing));
    }
    Ok((out, false))
}

/// The least `k <= MAX_FIT_BITS` such that every vertex the fit snaps is on the `2^-k`
/// grid (then every snapping to `k` bits or more leaves the scene as it is); `None` when
/// some vertex is on no such grid.
fn grid_bits(primitives: &Primitives) -> Option<u32> {
    let triangles: Vec<Triangle> = primitives.triangles.iter().map(CompactTriangle::to_triangle).collect();
    let mut points: Vec<&Point> = Vec::new();
    for t in &triangles {
        points.extend(t.v.iter());
    }
    for l in primitives.lines.iter().filter(|l| l.rule == LineRule::Diamond) {
        points.extend([&l.from, &l.to]);
    }
    for p in &primitives.polygons {
        points.extend(p.contours().flatten());
    }
    // The common denominator is 2^k exactly when every coordinate is on the 2^-k grid.
    let scale = scale_of(points.iter().flat_map(|p| [&p.x, &p.y]));
    let k = scale.trailing_zeros().unwrap_or(0);
    (scale == BigInt::one() << k && k <= u64::from(MAX_FIT_BITS))
        .then(|| u32::try_from(k).expect("at most MAX_FIT_BITS"))
}

impl FitReport {
    /// The exact fits grouped by tie rule and pixel centre, each with its snappings in
    /// words (`any snapping`, `unsnapped`, `8..=16 bits: nearest-even, half-away`, ...).
    pub fn grouped(&self) -> Vec<(AnyTieRule, PixelCentre, String)> {
        let mut groups: Vec<(AnyTieRule, PixelCentre, Vec<Snapping>)> = Vec::new();
        for c in &self.exact {
            match groups
                .iter_mut()
                .find(|(t, p, _)| *t == c.tie_rule && *p == c.pixel_centre)
            {
                Some(g) => g.2.push(c.snapping),
                None => groups.push((c.tie_rule, c.pixel_centre, vec![c.snapping])),
            }
        }
        let all = snappings();
        groups
            .into_iter()
            .map(|(t, p, s)| (t, p, snappings_text(&s, &all)))
            .collect()
    }

    /// What the image tells of each part of the convention, one line each: the tie rules,
    /// pixel centres and snappings among the exact fits, or, when every one of the
    /// searched values fits, that the image cannot tell them apart (no sample of it lies
    /// where they differ). Empty without an exact fit.
    ///
    /// ```
    /// use rasterproof::model::{render, Model};
    /// use rasterproof::oracle::{fit, Format, Theirs};
    /// use rasterproof::scene::parse_scene;
    /// // A triangle whose edges pass through no sample: every tie rule draws it alike.
    /// let scene = parse_scene(r#"{"width": 8, "height": 8, "triangles": [{"v": [[0.1, 0.2], [7.3, 0.4], [0.3, 6.9]]}]}"#, "s.json").unwrap();
    /// let target = scene.target().unwrap();
    /// let theirs = Theirs::from_coverage(&render(&scene.primitives(), &target, Model::ExactSnapped).unwrap(), Format::Json);
    /// let lines = fit(&scene.primitives(), &target, &theirs).unwrap().observable();
    /// assert!(lines[0].starts_with("tie rule: not observable here"), "{lines:?}");
    /// ```
    pub fn observable(&self) -> Vec<String> {
        if self.exact.is_empty() {
            return Vec::new();
        }
        let mut rules: Vec<AnyTieRule> = Vec::new();
        let mut centres: Vec<PixelCentre> = Vec::new();
        let mut snaps: Vec<Snapping> = Vec::new();
        for c in &self.exact {
            if !rules.contains(&c.tie_rule) {
                rules.push(c.tie_rule);
            }
            if !centres.contains(&c.pixel_centre) {
                centres.push(c.pixel_centre);
            }
            if !snaps.contains(&c.snapping) {
                snaps.push(c.snapping);
            }
        }
        let names = |v: Vec<&str>| v.join(", ");
        let tie = if rules.len() == AnyTieRule::ALL.len() {
            "tie rule: not observable here (all six fit: no sample lies on an edge where the rules differ; \
             hunt --fit-first draws tie-heavy probe scenes that tell them apart)"
                .to_string()
        } else {
            format!("tie rule: {}", names(rules.iter().map(|r| r.name()).collect()))
        };
        let centre = if centres.len() == 2 {
            "pixel centre: not observable here (0.5 and 0 both fit)".to_string()
        } else {
            format!("pixel centre: {}", names(centres.iter().map(|c| c.name()).collect()))
        };
        let all = snappings();
        let snapping = if snaps.len() == all.len() {
            "snapping: not observable here (every grid and rounding fits)".to_string()
        } else {
            format!("snapping: {}", snappings_text(&snaps, &all))
        };
        vec![tie, centre, snapping]
    }

    /// For people: the exact fits (what the image tells of each part of the convention,
    /// then the fits grouped), or the closest conventions with their differing pixels by
    /// kind.
    pub fn fit_text(&self) -> String {
        let mut s = format!("fit: {} conventions searched", self.searched);
        if let Some((n, why)) = &self.not_searched {
            let _ = write!(s, " ({n} not: {why})");
        }
        s.push('\n');
        if self.exact.is_empty() {
            s.push_str(
                "no convention explains their image exactly; the closest, the conventions that differ by the same \
                 counts together:\n",
            );
            for group in self.closest_groups() {
                let f = group[0];
                let kinds: Vec<String> = f.differing.iter().map(|(k, n)| format!("{n} {}", k.name())).collect();
                let noun = if f.total() == 1 {
                    "differing pixel"
                } else {
                    "differing pixels"
                };
                if let [one] = group.as_slice() {
                    let _ = writeln!(s, "  {}: {} {noun} ({})", one.candidate, f.total(), kinds.join(", "));
                    continue;
                }
                let _ = writeln!(
                    s,
                    "  {} {noun} ({}), {} conventions, of these parts:",
                    f.total(),
                    kinds.join(", "),
                    group.len()
                );
                for line in group_lines(&group) {
                    let _ = writeln!(s, "    {line}");
                }
            }
            return s;
        }
        let _ = writeln!(s, "{} conventions explain their image exactly.", self.exact.len());
        s.push_str("what their image tells, part by part:\n");
        for line in self.observable() {
            let _ = writeln!(s, "  {line}");
        }
        s.push_str("the exact fits:\n");
        for (t, p, snaps) in self.grouped() {
            let _ = writeln!(s, "  tie rule {}, pixel centre {}: {snaps}", t.name(), p.name());
        }
        s
    }

    /// The closest conventions grouped by their counts of differing pixels by kind and
    /// whether all six tie rules draw one image there ([`Fit::rules_alike`]), in order
    /// (fewest first; a group in search order).
    pub fn closest_groups(&self) -> Vec<Vec<&Fit>> {
        let mut groups: Vec<Vec<&Fit>> = Vec::new();
        for f in &self.closest {
            match groups
                .iter_mut()
                .find(|g| g[0].differing == f.differing && g[0].rules_alike == f.rules_alike)
            {
                Some(g) => g.push(f),
                None => groups.push(vec![f]),
            }
        }
        groups
    }

    /// For programs: `{"searched", "not_searched": {count, why} or null, "exact":
    /// [{tie_rule, subpixel_bits (null: unsnapped), rounding, pixel_centre}], "closest":
    /// [{convention, differing, by_kind}]}`.
    pub fn fit_json(&self) -> Value {
        let conv = |c: &Candidate| {
            json!({
                "tie_rule": c.tie_rule.name(),
                "subpixel_bits": c.snapping.bits,
                "rounding": c.snapping.bits.map(|_| c.snapping.rounding.name()),
                "pixel_centre": c.pixel_centre.name(),
            })
        };
        let closest: Vec<Value> = self
            .closest
            .iter()
            .map(|f| {
                let by_kind: serde_json::Map<String, Value> = f
                    .differing
                    .iter()
                    .map(|(k, n)| (k.name().to_string(), json!(n)))
                    .collect();
                json!({"convention": conv(&f.candidate), "differing": f.total(), "by_kind": by_kind})
            })
            .collect();
        json!({
            "searched": self.searched,
            "not_searched": self.not_searched.as_ref().map(|(n, why)| json!({"count": n, "why": why})),
            "exact": self.exact.iter().map(conv).collect::<Vec<_>>(),
            "closest": closest,
        })
    }
}

/// What a group of closest conventions (the same counts of differing pixels) holds, part
/// by part: the tie rules (all six where the image cannot tell them apart: no sample on an
/// edge), the pixel centres and the snappings.
fn group_lines(group: &[&Fit]) -> Vec<String> {
    let mut rules: Vec<AnyTieRule> = Vec::new();
    let mut centres: Vec<PixelCentre> = Vec::new();
    let mut snaps: Vec<Snapping> = Vec::new();
    for f in group {
        let c = f.candidate;
        if !rules.contains(&c.tie_rule) {
            rules.push(c.tie_rule);
        }
        if !centres.contains(&c.pixel_centre) {
            centres.push(c.pixel_centre);
        }
        if !snaps.contains(&c.snapping) {
            snaps.push(c.snapping);
        }
    }
    let tie = if rules.len() == AnyTieRule::ALL.len() && group.iter().all(|f| f.rules_alike) {
        "tie rule: not observable here (no sample lies on an edge: the six rules draw one image)".to_string()
    } else if rules.len() == AnyTieRule::ALL.len() {
        "tie rule: any of the six (each differs by these counts)".to_string()
    } else {
        format!(
            "tie rule: {}",
            rules.iter().map(|r| r.name()).collect::<Vec<_>>().join(", ")
        )
    };
    let centre = match centres.as_slice() {
        [one] => format!("pixel centre: {}", one.name()),
        _ => "pixel centre: 0.5 or 0".to_string(),
    };
    let all = snappings();
    vec![tie, centre, format!("snapping: {}", snappings_text(&snaps, &all))]
}

/// A set of snappings in words: `any snapping`, or per rounding set the bits it holds.
fn snappings_text(found: &[Snapping], all: &[Snapping]) -> String {
    if found.len() == all.len() {
        return "any snapping".to_string();
    }
    let mut parts = Vec::new();
    let mut by_bits: BTreeMap<u32, Vec<Rounding>> = BTreeMap::new();
    for s in found {
        match s.bits {
            Some(b) => by_bits.entry(b).or_default().push(s.rounding),
            None => parts.push("unsnapped".to_string()),
        }
    }
    // Runs of consecutive bits with the same roundings.
    let mut runs: Vec<(u32, u32, Vec<Rounding>)> = Vec::new();
    for (b, r) in by_bits {
        match runs.last_mut() {
            Some((_, hi, rs)) if *hi + 1 == b && *rs == r => *hi = b,
            _ => runs.push((b, b, r)),
        }
    }
    let mut text: Vec<String> = runs
        .into_iter()
        .map(|(lo, hi, r)| {
            let bits = if lo == hi {
                format!("{lo} bits")
            } else {
                format!("{lo}..={hi} bits")
            };
            let r: Vec<&str> = if r.len() == Rounding::ALL.len() {
                vec!["any rounding"]
            } else {
                r.iter().map(|r| r.name()).collect()
            };
            format!("{bits} ({})", r.join(", "))
        })
        .collect();
    text.extend(parts);
    text.join("; ")
}

impl super::Comparison for FitReport {
    /// Some convention gives their image exactly.
    fn identical(&self) -> bool {
        !self.exact.is_empty()
    }

    /// The conventions that give their image exactly, then the closest kept.
    fn counts(&self) -> Vec<(String, usize)> {
        vec![
            ("exact".to_string(), self.exact.len()),
            ("closest".to_string(), self.closest.len()),
        ]
    }

    /// The header naming both files, then [`FitReport::fit_text`].
    fn to_text(&self, scene: &str, theirs: &str, _limit: usize) -> String {
        format!(
            "compare --fit: {theirs} (as {}) against {scene}\n{}",
            self.format.name(),
            self.fit_text()
        )
    }

    /// [`FitReport::fit_json`].
    fn to_json(&self, _scene: &str, _theirs: &str) -> Value {
        self.fit_json()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::oracle::Format;
    use crate::scene::parse_scene;

    fn primitives(json: &str) -> Primitives {
        parse_scene(json, "s.json").unwrap().primitives()
    }

    /// By hand: the grid of 1/2 and 3/4 is 2 bits; of integers 0; a third or 2^-17 is on
    /// no grid the fit searches; a Bresenham line's pixel addresses are not snapped.
    #[test]
    fn grid_bits_by_hand() {
        let tri = |a: &str, b: &str| {
            format!(r#"{{"width": 4, "height": 4, "triangles": [{{"v": [[0, 0], ["{a}", 1], [0, "{b}"]]}}]}}"#)
        };
        assert_eq!(grid_bits(&primitives(&tri("1/2", "3/4"))), Some(2));
        assert_eq!(grid_bits(&primitives(&tri("1", "3"))), Some(0));
        assert_eq!(grid_bits(&primitives(&tri("1/3", "1"))), None);
        assert_eq!(grid_bits(&primitives(&tri("1/131072", "1"))), None);
        assert_eq!(grid_bits(&primitives(&tri("1/65536", "1"))), Some(16));
        let polygon = r#"{"width": 4, "height": 4, "polygons": [{"v": [[0, 0], ["1/8", 1], [0, 2]]}]}"#;
        assert_eq!(grid_bits(&primitives(polygon)), Some(3));
    }

    /// The fit's verdicts, counts reused across snappings included, are the plain
    /// definition's: a convention fits exactly when the scene snapped its way and drawn
    /// under its rule and sample position is their image, pixel for pixel. Checked for
    /// every convention on scenes on the 1/4 grid (every snapping from 2 bits on is the
    /// scene itself), on the 1/2 grid with a polygon, and off every grid (thirds).
    #[test]
    fn every_verdict_is_the_plain_definition() {
        let scenes = [
            r#"{"width": 3, "height": 3, "triangles": [{"v": [["1/4", "-1/2"], ["3/4", "5/2"], [-2, "3/2"]]}, {"v": [["1/2", "1/2"], ["5/2", "1/2"], ["5/2", "5/2"]]}]}"#,
            r#"{"width": 4, "height": 4, "polygons": [{"v": [["1/2", "1/2"], ["7/2", "1/2"], ["7/2", "7/2"], ["3/2", "5/2"]]}]}"#,
            r#"{"width": 3, "height": 3, "triangles": [{"v": [["1/3", "1/3"], ["8/3", "2/3"], ["4/3", "7/3"]]}]}"#,
        ];
        for json in scenes {
            let p = primitives(json);
            let target = parse_scene(json, "s.json").unwrap().target().unwrap();
            // Theirs: 2 bits, floor, top-right, centre 1/2 (a convention that need not fit).
            let theirs_candidate = Candidate {
                tie_rule: AnyTieRule::TopRight,
                snapping: Snapping {
                    bits: Some(2),
                    rounding: Rounding::Floor,
                },
                pixel_centre: PixelCentre::Half,
            };
            let drawn = image(&snapped(&p, theirs_candidate.snapping), &target, &theirs_candidate)
                .unwrap()
                .unwrap();
            let theirs = Theirs::from_coverage(&drawn, Format::Json);
            let found = fit(&p, &target, &theirs).unwrap();
            assert!(found.exact.contains(&theirs_candidate), "{json}");
            for s in snappings() {
                for pixel_centre in [PixelCentre::Half, PixelCentre::Corner] {
                    for tie_rule in AnyTieRule::ALL {
                        let c = Candidate {
                            tie_rule,
                            snapping: s,
                            pixel_centre,
                        };
                        let ours = image(&snapped(&p, s), &target, &c).unwrap().unwrap();
                        assert_eq!(found.exact.contains(&c), ours == drawn, "{c} on {json}");
                    }
                }
            }
        }
    }
}
