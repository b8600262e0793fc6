//! The [`CompareReport`] of a comparison: its summary, text, JSON and difference picture, and a
//! reason in words ([`reason_text`]).

use std::collections::BTreeMap;
use std::fmt::Write as _;

use image::{Rgb, RgbImage};
use serde_json::{json, Value};

use super::pixel::point_text;
use super::{DiffPixel, PixelKind};
use crate::convention::{AnyTieRule, Convention, Rounding};
use crate::coverage::picture::{upscale, Scale};
use crate::coverage::Coverage;
use crate::model::Model;
use crate::num::exact::exact_text;
use crate::oracle::evidence::{distance_decimal_text, distance_f64, distance_text, exact_distance};
use crate::oracle::reason::{offset_text, Reason, ReasonClass};
use crate::oracle::theirs::{Format, TheirPixel};

/// The version of the JSON report's schema ([`CompareReport::to_json`]).
pub const COMPARE_REPORT_VERSION: u32 = 1;

/// The colour of a pixel both cover with the same owners, in the difference picture.
pub const MATCHED_COLOUR: [u8; 3] = [128, 128, 128];
/// The colour of a pixel neither covers.
pub const EMPTY_COLOUR: [u8; 3] = [0, 0, 0];

/// The comparison of their output with the oracle's.
#[derive(Debug, Clone)]
pub struct CompareReport {
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
    pub(super) ours: Coverage,
    /// The tie rule and snapping that together explain the classified differences, when
    /// each is explained by one of the two ([`CompareReport::headline`]), with whether
    /// the scene drawn under both at once was checked to give their answer at each.
    pub(super) joint: Option<Joint>,
}

/// A two-part convention: a tie rule and a grid, each explaining some of the classified
/// differences and together all of them.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Joint {
    /// The tie rules every tie finding names.
    pub rules: Vec<AnyTieRule>,
    /// The subpixel bits every snapping finding names.
    pub bits: u32,
    /// The roundings every snapping finding names at those bits.
    pub roundings: Vec<Rounding>,
    /// Findings of each part: ties, snappings.
    pub counts: [usize; 2],
    /// The scene drawn with the first rule and rounding at once gives their answer at every
    /// classified differing pixel (`None`: it could not be drawn, say under a clip window).
    pub checked: Option<bool>,
}

impl CompareReport {
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

    /// The one convention that explains every classified difference, when there is one:
    /// every finding is of one class and the alternatives it names share a value (a tie
    /// rule, a sample position, a grid and rounding, a line rule), named so that a reader
    /// sees it before the table: `every classified difference is explained by one
    /// convention: the sample at (i, j)`. Or two parts: every finding a tie or a snapping,
    /// the ties sharing a rule and the snappings a grid and rounding (a fixed-point
    /// renderer's truncation beside its own tie rule); then the scene is drawn under both
    /// at once and the headline says whether that gives their answer at every classified
    /// pixel. `None` when the findings name nothing in common (say near-edge float error
    /// beside ties), or nothing differs.
    ///
    /// Before all these: when their image covers no pixel where the oracle covers some,
    /// the headline says that their renderer drew nothing (the per-pixel reasons, read
    /// one pixel at a time, would call the scene's edge pixels ties).
    pub fn headline(&self) -> Option<String> {
        if self.theirs_covered == 0 && self.ours_covered > 0 {
            return Some(format!(
                "their image covers no pixel: their renderer drew nothing here (the oracle covers {} {})",
                self.ours_covered,
                if self.ours_covered == 1 { "pixel" } else { "pixels" }
            ));
        }
        if let Some(one) = self.one_class_headline() {
            return Some(one);
        }
        let j = self.joint.as_ref()?;
        let or = |names: Vec<&str>| names.join(" or ");
        let rules = or(j.rules.iter().map(|r| r.name()).collect());
        let roundings = or(j.roundings.iter().map(|r| r.name()).collect());
        let parts = format!(
            "snapping to {} subpixel bits, rounding {roundings} ({} findings), with the tie rule {rules} ({} findings)",
            j.bits, j.counts[1], j.counts[0]
        );
        Some(match j.checked {
            Some(true) => format!(
                "every classified difference is explained by one convention: {parts}; drawn under both at once, \
                 the scene gives their answer at every classified pixel"
            ),
            Some(false) => format!(
                "each classified difference is explained by one of two changes: {parts}; drawn under both at once, \
                 the scene does not give their answer at every classified pixel"
            ),
            None => format!("each classified difference is explained by one of two changes: {parts}"),
        })
    }

    /// [`CompareReport::headline`] when every finding is of one class.
    fn one_class_headline(&self) -> Option<String> {
        let findings: Vec<&Reason> = self
            .pixels
            .iter()
            .flat_map(|p| &p.findings)
            .map(|f| &f.reason)
            .collect();
        let or = |names: Vec<String>| names.join(" or ");
        let what = match findings.first()? {
            Reason::Tie { .. } => {
                let rules = shared_by_all(&findings, |r| match r {
                    Reason::Tie { rules, .. } => Some(rules.as_slice()),
                    _ => None,
                })?;
                format!(
                    "the tie rule {}",
                    or(rules.iter().map(|r| r.name().to_string()).collect())
                )
            }
            Reason::SamplePosition { .. } => {
                let offsets = shared_by_all(&findings, |r| match r {
                    Reason::SamplePosition { offsets } => Some(offsets.as_slice()),
                    _ => None,
                })?;
                format!(
                    "the sample at {}",
                    or(offsets.iter().map(|o| offset_text(*o)).collect())
                )
            }
            Reason::Snapping { bits: None, .. } => {
                let unsnapped = |r: &&Reason| matches!(r, Reason::Snapping { bits: None, .. });
                findings
                    .iter()
                    .all(unsnapped)
                    .then(|| "no snapping (vertices as written)".to_string())?
            }
            Reason::Snapping { bits: Some(b), .. } => {
                let roundings = shared_by_all(&findings, |r| match r {
                    Reason::Snapping { bits, roundings } if *bits == Some(*b) => Some(roundings.as_slice()),
                    _ => None,
                })?;
                let names = or(roundings.iter().map(|r| r.name().to_string()).collect());
                format!("snapping to {b} subpixel bits, rounding {names}")
            }
            Reason::LineRule { .. } => {
                let rules = shared_by_all(&findings, |r| match r {
                    Reason::LineRule { rules } => Some(rules.as_slice()),
                    _ => None,
                })?;
                format!("the line rule {}", or(rules.iter().map(ToString::to_string).collect()))
            }
            _ => return None,
        };
        Some(format!(
            "every classified difference is explained by one convention: {what}"
        ))
    }

    /// How many differing pixels were classified (all but those [`super::pick_classified`]
    /// left out of a large comparison).
    pub fn classified(&self) -> usize {
        self.pixels.iter().filter(|p| p.classified).count()
    }

    /// Differing pixels left unclassified, by kind.
    pub fn unclassified_by_kind(&self) -> BTreeMap<PixelKind, usize> {
        let mut out = BTreeMap::new();
        for p in self.pixels.iter().filter(|p| !p.classified) {
            *out.entry(p.kind).or_insert(0) += 1;
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
            "canvas {}x{}: the oracle covers {}, theirs {}; {} differ",
            self.width,
            self.height,
            crate::num::exact::counted(self.ours_covered as u64, "pixel"),
            self.theirs_covered,
            self.pixels.len()
        );
        if self.pixels.is_empty() {
            s.push_str("identical\n");
            return s;
        }
        if let Some(h) = self.headline() {
            let _ = writeln!(s, "{h}");
        }
        let summary = self.summary();
        let classes: Vec<ReasonClass> = ReasonClass::ALL
            .into_iter()
            .filter(|c| summary.keys().any(|(_, k)| k == c))
            .collect();
        let by_kind = self.pixels_by_kind();
        let unclassified = self.unclassified_by_kind();
        let classified = self.classified();
        if classified < self.pixels.len() {
            let _ = writeln!(
                s,
                "classified: {classified} of the {} differing pixels (the first {} in row order, the rest spread \
                 evenly over the others); every pixel is counted by kind (compare --classify all classifies each)",
                self.pixels.len(),
                classified / 2
            );
        }
        let _ = write!(s, "\n{:<12} {:>7}", "", "pixels");
        for c in &classes {
            let _ = write!(s, " {:>10}", c.name());
        }
        if !unclassified.is_empty() {
            let _ = write!(s, " {:>12}", "unclassified");
        }
        s.push('\n');
        for kind in PixelKind::ALL {
            let Some(n) = by_kind.get(&kind) else { continue };
            let _ = write!(s, "{:<12} {n:>7}", kind.name());
            for c in &classes {
                let _ = write!(s, " {:>10}", summary.get(&(kind, *c)).copied().unwrap_or(0));
            }
            if !unclassified.is_empty() {
                let _ = write!(s, " {:>12}", unclassified.get(&kind).copied().unwrap_or(0));
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
            s.push_str(&self.pixel_text(p));
        }
        s
    }

    /// One differing pixel in words, as the text report prints it: the pixel, its kind and
    /// both answers, then each finding with its reason, the exact evidence and the distance
    /// to the nearest edge.
    pub fn pixel_text(&self, p: &DiffPixel) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "({}, {}) {}: oracle {}, theirs {}",
            p.x,
            p.y,
            p.kind.name(),
            owners_text(&p.ours),
            their_text(&p.theirs, self.format)
        );
        if !p.classified {
            s.push_str("  (not classified)\n");
        }
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
            if let Some(d2) = &f.distance2 {
                let _ = writeln!(s, "    nearest edge: {}", distance_decimal_text(d2));
            }
        }
        s
    }

    /// The JSON report (schema version [`COMPARE_REPORT_VERSION`]), complete:
    /// `{"version", "scene", "theirs", "format", "model", "convention": {preset, tie_rule,
    /// pixel_centre, subpixel_bits, rounding}, "width", "height", "ours_covered",
    /// "theirs_covered", "differing", "classified", "headline" ([`Self::headline`], or
    /// null), "pixels_by_kind": {kind: n},
    /// "unclassified_by_kind": {kind: n}, "summary": [{kind, class, count}] (of the
    /// classified pixels' findings), "pixels": [{x, y, kind, ours: [ids], theirs: {covered,
    /// ids, several}, classified, findings (empty when not classified): [{id, primitive,
    /// relation, guessed, class, reason: {...}, distance,
    /// evidence}]}]}`; `distance` is the sample's distance to the primitive's nearest edge,
    /// `{squared, exact, approx}` (null when no primitive is named or guessed).
    /// A reason holds, by class: `tie` `{edges: [{index, from, to, side, value,
    /// inclusive}], rules}`; `clip` `{unclipped_covers}`; `line-rule` `{rules}`;
    /// `fill-rule` `{winding, fill_rule}`; `sample-position` `{offsets: [[x, y]]}` (half
    /// pixels from the pixel's corner); `snapping` `{subpixel_bits (null: unsnapped),
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
        let unclassified: serde_json::Map<String, Value> = self
            .unclassified_by_kind()
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
                            "distance": f.distance2.as_ref().map(distance_json),
                            "evidence": f.evidence,
                        })
                    })
                    .collect();
                json!({
                    "x": p.x, "y": p.y, "kind": p.kind.name(), "ours": p.ours,
                    "theirs": {"covered": p.theirs.covered, "ids": p.theirs.ids, "several": p.theirs.several},
                    "classified": p.classified,
                    "findings": findings,
                })
            })
            .collect();
        json!({
            "version": COMPARE_REPORT_VERSION,
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
            "classified": self.classified(),
            "headline": self.headline(),
            "pixels_by_kind": by_kind,
            "unclassified_by_kind": unclassified,
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

    /// [`CompareReport::diff_image`] scaled by `scale`.
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
        (Format::Mask | Format::Grey, true) => "covered".to_string(),
        (Format::Ids, true) if t.several => format!("{} and others (several owners)", owners_text(&t.ids)),
        _ => owners_text(&t.ids),
    }
}

/// The two parts of [`Joint`] (unchecked) when every finding is a tie or a snapping to a
/// number of bits, some of each, the ties sharing a rule and the snappings a rounding.
pub(super) fn joint_parts(pixels: &[DiffPixel]) -> Option<Joint> {
    let reasons: Vec<&Reason> = pixels.iter().flat_map(|p| &p.findings).map(|f| &f.reason).collect();
    let (ties, snaps): (Vec<&Reason>, Vec<&Reason>) = reasons.iter().partition(|r| matches!(r, Reason::Tie { .. }));
    let Some(Reason::Snapping { bits: Some(bits), .. }) = snaps.first() else {
        return None;
    };
    if ties.is_empty() {
        return None;
    }
    let rules = shared_by_all(&ties, |r| match r {
        Reason::Tie { rules, .. } => Some(rules.as_slice()),
        _ => None,
    })?;
    let roundings = shared_by_all(&snaps, |r| match r {
        Reason::Snapping { bits: b, roundings } if *b == Some(*bits) => Some(roundings.as_slice()),
        _ => None,
    })?;
    Some(Joint {
        rules,
        bits: *bits,
        roundings,
        counts: [ties.len(), snaps.len()],
        checked: None,
    })
}

/// The values that every reason's list holds (`list` picks it: a tie's rules, a sample
/// position's offsets, ...), in the first's order; `None` when some reason has no such list
/// (it is of another class) or nothing is shared.
fn shared_by_all<'r, T: PartialEq + Copy + 'r>(
    reasons: &[&'r Reason],
    list: impl Fn(&'r Reason) -> Option<&'r [T]>,
) -> Option<Vec<T>> {
    let lists: Vec<&[T]> = reasons.iter().map(|r| list(r)).collect::<Option<_>>()?;
    let first = lists.first()?;
    let shared: Vec<T> = first
        .iter()
        .copied()
        .filter(|v| lists.iter().all(|l| l.contains(v)))
        .collect();
    (!shared.is_empty()).then_some(shared)
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
        Reason::SamplePosition { offsets } => {
            let names: Vec<String> = offsets.iter().map(|o| offset_text(*o)).collect();
            format!(
                "their answer is the exact answer at the sample {} (another pixel centre)",
                names.join(" or ")
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
        Reason::SamplePosition { offsets } => json!({ "offsets": offsets }),
        Reason::Snapping { bits, roundings } => {
            let names: Vec<&str> = roundings.iter().map(|r| r.name()).collect();
            json!({"subpixel_bits": bits, "roundings": names})
        }
        Reason::NearEdge { distance2 } => json!({ "distance": distance_json(distance2) }),
        Reason::Gross { distance2 } => json!({ "distance": distance2.as_ref().map(distance_json) }),
    }
}
