//! Another renderer's multisampled output judged sample by sample:
//! [`compare_samples`] (where their samples sit: [`super::fit::samples`]).
//!
//! Their output is one ids (or mask) image per sample index, stacked (what `render
//! --ids-out` writes under a pattern, and what a GPU adapter reads back from a
//! multisampled target). Sample index `s` is compared as a one-sample image of the scene
//! moved so that sample `s` comes to the pixel's sample position ([`SampleFrames`]: snapped
//! first for a snapping model, then moved by whole subpixels), so the difference is exact
//! and every reason class of [`super::compare()`] applies to it: a tie at that sample, snapping,
//! near-edge, gross. A pixel's explanation is written in that moved frame: its sample is
//! the pixel's centre, and the coordinates it quotes are the scene's moved by
//! `(c - x_s, c - y_s)` (the report says by how much).

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::binary::{compare, CompareOptions, CompareReport};
use super::CompareError;
use crate::convention::Target;
use crate::model::{Model, Primitives, SampleFrames};
use crate::num::exact::exact_text;
use crate::oracle::theirs::Theirs;
use crate::pattern::SamplePattern;

/// The comparison of every sample index.
#[derive(Debug, Clone)]
pub struct SampleCompareReport {
    /// The pattern compared.
    pub pattern: SamplePattern,
    /// Per sample index, its comparison (in the frame moved to that sample).
    pub samples: Vec<CompareReport>,
    /// Per sample index, the offset `(dx, dy)` the scene was moved by, as exact text.
    pub moved_by: Vec<[String; 2]>,
}

impl SampleCompareReport {
    /// No sample of any pixel differs.
    pub fn identical(&self) -> bool {
        self.samples.iter().all(CompareReport::identical)
    }

    /// How many samples differ, over all pixels and sample indices.
    pub fn differing_samples(&self) -> usize {
        self.samples.iter().map(|r| r.pixels.len()).sum()
    }

    /// The report as text: one line for the whole, then each sample index that differs
    /// with its own comparison (at most `limit` pixels listed per sample).
    pub fn to_text(&self, scene: &str, theirs: &str, limit: usize) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "{scene} against {theirs}, {} samples: {}",
            self.pattern,
            if self.identical() {
                "identical at every sample".to_string()
            } else {
                format!("{} samples differ", self.differing_samples())
            }
        );
        for (k, r) in self.samples.iter().enumerate() {
            let [dx, dy] = &self.moved_by[k];
            let _ = write!(
                s,
                "sample {k} at {}: {}",
                self.pattern.position_text(k),
                if r.identical() {
                    "identical\n".to_string()
                } else {
                    format!("{} pixels differ; explained with the scene moved by ({dx}, {dy}), this sample at the pixel centre\n", r.pixels.len())
                }
            );
            if !r.identical() {
                for line in r.to_text(scene, theirs, limit).lines() {
                    let _ = writeln!(s, "  {line}");
                }
            }
        }
        s
    }

    /// The report as JSON: `{"pattern", "identical", "differing_samples", "samples": [{
    /// "index", "position", "moved_by", "report"}]}`, each `report` [`CompareReport::to_json`]'s.
    pub fn to_json(&self, scene: &str, theirs: &str) -> Value {
        let samples: Vec<Value> = self
            .samples
            .iter()
            .enumerate()
            .map(|(k, r)| {
                let [x, y] = &self.pattern.positions()[k];
                json!({
                    "index": k,
                    "position": [exact_text(x), exact_text(y)],
                    "moved_by": self.moved_by[k],
                    "report": r.to_json(scene, theirs),
                })
            })
            .collect();
        json!({
            "pattern": self.pattern.to_json(),
            "identical": self.identical(),
            "differing_samples": self.differing_samples(),
            "samples": samples,
        })
    }
}

/// How a multisampled output is compared: the pattern of their samples, the oracle model,
/// and how many differing pixels of each sample index are classified.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SampleOptions {
    /// The pattern their stacked image follows, one image per sample index.
    pub pattern: SamplePattern,
    /// The exact model whose coverage at each sample is the answer.
    pub model: Model,
    /// How many differing pixels of each sample index are classified (`None`: every one).
    pub classify_at_most: Option<usize>,
}

/// Compares their stacked per-sample output with the scene at every sample of
/// `options.pattern`, each sample index as a one-sample comparison ([`super::compare()`])
/// of the scene moved to that sample.
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::model::{render_samples, Model, Primitives};
/// use rasterproof::oracle::compare::samples::{compare_samples, SampleOptions};
/// use rasterproof::oracle::{Format, Theirs};
/// use rasterproof::pattern::SamplePattern;
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
/// let scene = Primitives::from_triangles(&[t]);
/// let target = Target::new(4, 4, Convention::default()).unwrap();
/// let four = SamplePattern::standard(4).unwrap();
/// // Their output: our own sample 0 in every sample slot.
/// let ours = render_samples(&scene, &target, &four, Model::ExactSnapped).unwrap();
/// let stacked = image::DynamicImage::ImageRgba8(ours.to_stacked_ids_image().unwrap());
/// let mut png = Vec::new();
/// stacked.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png).unwrap();
/// let theirs = Theirs::read(&png, "theirs.png", Format::Ids, Default::default()).unwrap();
/// let options = SampleOptions { pattern: four, model: Model::ExactSnapped, classify_at_most: None };
/// let report = compare_samples(&scene, &target, &theirs, &options).unwrap();
/// assert!(report.identical());
/// ```
///
/// # Errors
/// Their image is not `pattern.len()` images of the canvas stacked; the model refuses the
/// scene or a sample ([`CompareError::Model`]); the model is not exact.
pub fn compare_samples(
    primitives: &Primitives,
    target: &Target,
    theirs: &Theirs,
    options: &SampleOptions,
) -> Result<SampleCompareReport, CompareError> {
    let SampleOptions {
        pattern,
        model,
        classify_at_most,
    } = options;
    let one = CompareOptions {
        model: *model,
        classify_at_most: *classify_at_most,
        jobs: 1,
    };
    let per_sample = theirs
        .unstack(pattern.len(), target.height)
        .map_err(CompareError::Samples)?;
    let frames = SampleFrames::new(primitives, target, pattern, *model).map_err(CompareError::Model)?;
    let mut samples = Vec::with_capacity(pattern.len());
    let mut moved_by = Vec::with_capacity(pattern.len());
    for (s, theirs) in per_sample.iter().enumerate() {
        let moved = frames.at(s).map_err(CompareError::Model)?;
        samples.push(compare(&moved, target, theirs, &one)?);
        let [dx, dy] = pattern.offset(s, &target.convention);
        moved_by.push([exact_text(&-dx), exact_text(&-dy)]);
    }
    Ok(SampleCompareReport {
        pattern: pattern.clone(),
        samples,
        moved_by,
    })
}

impl super::Comparison for SampleCompareReport {
    fn to_html(&self, page: &super::HtmlInputs<'_>) -> Option<String> {
        Some(SampleCompareReport::to_html(self, page))
    }

    fn identical(&self) -> bool {
        SampleCompareReport::identical(self)
    }

    /// Every sample index's counts, added class by class.
    fn counts(&self) -> Vec<(String, usize)> {
        let mut out: Vec<(String, usize)> = Vec::new();
        for (class, n) in self.samples.iter().flat_map(super::Comparison::counts) {
            match out.iter_mut().find(|(c, _)| *c == class) {
                Some((_, m)) => *m += n,
                None => out.push((class, n)),
            }
        }
        out
    }

    fn to_text(&self, scene: &str, theirs: &str, limit: usize) -> String {
        SampleCompareReport::to_text(self, scene, theirs, limit)
    }

    fn to_json(&self, scene: &str, theirs: &str) -> Value {
        SampleCompareReport::to_json(self, scene, theirs)
    }
}
