//! A conservative renderer's output judged against the exact pair of sets
//! ([`crate::model::render_conservative`]): right when every pixel it must cover is
//! covered, no pixel beyond those it may cover is, and each degenerate triangle that must
//! not vanish covers one of the pixels it touches. Pixels in the band between the two
//! sets are counted, never wrong.
//!
//! Their output is read as a mask (covered or not): conservative coverage is a per-pixel
//! answer of the whole scene, and an ids image's one id per pixel cannot say which of
//! several triangles reached a pixel.

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::{CompareError, SizeMismatch};
use crate::convention::Target;
use crate::model::{render_conservative, ConservativeRule, Primitives};
use crate::oracle::theirs::Theirs;

/// The judgement of one image.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ConservativeReport {
    /// The rule judged under, as text.
    pub rule: String,
    /// Pixels that must be covered and are not, with the triangles that require them.
    pub missing: Vec<(u32, u32, Vec<u32>)>,
    /// Pixels covered beyond every triangle's uncertainty region.
    pub beyond: Vec<(u32, u32)>,
    /// Band pixels (may, not must) they cover, with the triangles whose uncertainty
    /// region reaches them.
    pub band_covered: Vec<(u32, u32, Vec<u32>)>,
    /// Band pixels they leave uncovered (either answer is right there).
    pub band_uncovered: usize,
    /// Degenerate triangles that must not vanish of which they cover none of the pixels
    /// touched.
    pub vanished: Vec<u32>,
    /// The canvas width.
    pub width: u32,
    /// The canvas height.
    pub height: u32,
    /// What the rule says of each pixel, row by row: 2 must be covered, 1 may be (the
    /// band), 0 must not.
    pub oracle: Vec<u8>,
    /// Whether they cover each pixel, row by row.
    pub covered: Vec<bool>,
}

impl ConservativeReport {
    /// `must ⊆ theirs ⊆ may`, and no degenerate triangle vanished: their image is one the
    /// rule allows.
    pub fn identical(&self) -> bool {
        self.missing.is_empty() && self.beyond.is_empty() && self.vanished.is_empty()
    }

    /// The report as text, listing at most `limit` pixels of each kind.
    pub fn to_text(&self, scene: &str, theirs: &str, limit: usize) -> String {
        let mut s = format!("{theirs} against {scene}, conservative {}: ", self.rule);
        if self.identical() {
            s.push_str("right (every must-pixel covered, none beyond the may-pixels)\n");
        } else {
            let _ = writeln!(
                s,
                "{} missing, {} beyond the uncertainty region, {} degenerate triangles vanished",
                self.missing.len(),
                self.beyond.len(),
                self.vanished.len()
            );
        }
        let _ = writeln!(
            s,
            "band (may, not must): {} covered, {} not",
            self.band_covered.len(),
            self.band_uncovered
        );
        for (x, y, ids) in self.missing.iter().take(limit) {
            let _ = writeln!(s, "  ({x}, {y}) missing: triangles {ids:?} overlap the pixel's square");
        }
        for (x, y) in self.beyond.iter().take(limit) {
            let _ = writeln!(
                s,
                "  ({x}, {y}) beyond: no triangle's uncertainty region reaches the pixel"
            );
        }
        for (x, y, ids) in self.band_covered.iter().take(limit) {
            let _ = writeln!(
                s,
                "  ({x}, {y}) band, covered: within the uncertainty region of triangles {ids:?}, not overlapped"
            );
        }
        for id in &self.vanished {
            let _ = writeln!(
                s,
                "  triangles[{id}] vanished: degenerate, it must cover one of the pixels it touches"
            );
        }
        s
    }

    /// The report as JSON: `{"rule", "right", "missing": [[x, y, [ids]]], "beyond": [[x,
    /// y]], "band_covered": [[x, y, [ids]]], "band_uncovered" (a count), "vanished": [ids]}`.
    pub fn to_json(&self) -> Value {
        json!({
            "rule": self.rule,
            "right": self.identical(),
            "missing": self.missing.iter().map(|(x, y, ids)| json!([x, y, ids])).collect::<Vec<_>>(),
            "beyond": self.beyond.iter().map(|(x, y)| json!([x, y])).collect::<Vec<_>>(),
            "band_covered": self.band_covered.iter().map(|(x, y, ids)| json!([x, y, ids])).collect::<Vec<_>>(),
            "band_uncovered": self.band_uncovered,
            "vanished": self.vanished,
        })
    }
}

/// Judges `theirs` against the conservative coverage of `primitives` on `target` under
/// `rule` ([`render_conservative`]'s must and may sets).
///
/// # Errors
/// Their canvas is not the scene's; the scene cannot be rasterized conservatively.
pub fn compare_conservative(
    primitives: &Primitives,
    target: &Target,
    theirs: &Theirs,
    rule: &ConservativeRule,
) -> Result<ConservativeReport, CompareError> {
    let sets = render_conservative(primitives, target, rule).map_err(CompareError::Conservative)?;
    SizeMismatch::check(theirs, target).map_err(CompareError::Size)?;
    let (w, h) = (target.width, target.height);
    let mut report = ConservativeReport {
        rule: rule.to_string(),
        missing: Vec::new(),
        beyond: Vec::new(),
        band_covered: Vec::new(),
        band_uncovered: 0,
        vanished: Vec::new(),
        width: w,
        height: h,
        oracle: Vec::new(),
        covered: Vec::new(),
    };
    for y in 0..h {
        for x in 0..w {
            let covered = theirs.pixel(x, y).covered;
            let must = sets.must.owners(x, y);
            let may = sets.may.owners(x, y);
            report
                .oracle
                .push(if !must.is_empty() { 2 } else { u8::from(!may.is_empty()) });
            report.covered.push(covered);
            match (covered, !must.is_empty(), !may.is_empty()) {
                (false, true, _) => report.missing.push((x, y, must.to_vec())),
                (true, _, false) => report.beyond.push((x, y)),
                (true, false, true) => report.band_covered.push((x, y, may.to_vec())),
                (false, false, true) => report.band_uncovered += 1,
                _ => {}
            }
        }
    }
    for (id, pixels) in &sets.one_of {
        if !pixels.iter().any(|&(x, y)| theirs.pixel(x, y).covered) {
            report.vanished.push(*id);
        }
    }
    Ok(report)
}

impl super::Comparison for ConservativeReport {
    fn to_html(&self, page: &super::HtmlInputs<'_>) -> Option<String> {
        Some(ConservativeReport::to_html(self, page))
    }

    fn identical(&self) -> bool {
        ConservativeReport::identical(self)
    }

    /// Missing pixels, pixels beyond the uncertainty region, degenerate triangles vanished,
    /// and the band pixels covered (never wrong).
    fn counts(&self) -> Vec<(String, usize)> {
        vec![
            ("missing".to_string(), self.missing.len()),
            ("beyond".to_string(), self.beyond.len()),
            ("vanished".to_string(), self.vanished.len()),
            ("band covered".to_string(), self.band_covered.len()),
        ]
    }

    fn to_text(&self, scene: &str, theirs: &str, limit: usize) -> String {
        ConservativeReport::to_text(self, scene, theirs, limit)
    }

    fn to_json(&self, _scene: &str, _theirs: &str) -> Value {
        ConservativeReport::to_json(self)
    }
}
