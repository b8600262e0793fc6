//! Another renderer's multisampled output judged sample by sample:
//! [`compare_samples`].
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

use super::compare::{compare_classifying, count_differences, CompareError, CompareReport};
use super::theirs::Theirs;
use crate::convention::Target;
use crate::model::{render_samples, Model, Primitives, SampleFrames};
use crate::num::exact::exact_text;
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

/// Compares their stacked per-sample output with the scene at every sample of `pattern`,
/// classifying at most `at_most` differing pixels per sample index (`None`: all).
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::model::{render_samples, Model, Primitives};
/// use rasterproof::oracle::samples::compare_samples;
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
/// let report = compare_samples(&scene, &target, &four, &theirs, Model::ExactSnapped, None).unwrap();
/// assert!(report.identical());
/// ```
///
/// # Errors
/// Their image is not `pattern.len()` images of the canvas stacked; the model refuses the
/// scene or a sample ([`CompareError::Model`]); the model is not exact.
pub fn compare_samples(
    primitives: &Primitives,
    target: &Target,
    pattern: &SamplePattern,
    theirs: &Theirs,
    model: Model,
    at_most: Option<usize>,
) -> Result<SampleCompareReport, CompareError> {
    let per_sample = theirs
        .unstack(pattern.len(), target.height)
        .map_err(CompareError::Samples)?;
    let frames = SampleFrames::new(primitives, target, pattern, model).map_err(CompareError::Model)?;
    let mut samples = Vec::with_capacity(pattern.len());
    let mut moved_by = Vec::with_capacity(pattern.len());
    for (s, theirs) in per_sample.iter().enumerate() {
        let moved = frames.at(s).map_err(CompareError::Model)?;
        samples.push(compare_classifying(&moved, target, theirs, model, at_most, 1)?);
        let [dx, dy] = pattern.offset(s, &target.convention);
        moved_by.push([exact_text(&-dx), exact_text(&-dy)]);
    }
    Ok(SampleCompareReport {
        pattern: pattern.clone(),
        samples,
        moved_by,
    })
}

/// Where their samples sit, as far as their images tell: for each sample index of their
/// stacked image, every position on the `1/grid` pixel grid whose one-sample image of the
/// scene (under `model` and the target's convention) equals theirs exactly, and whether
/// `pattern`'s own position for that index is among them. What `compare --fit` prints
/// under a pattern, so that a renderer whose positions are not the standard ones is named
/// with the positions its images allow.
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::model::{render_samples, Model, Primitives};
/// use rasterproof::oracle::samples::fit_positions;
/// use rasterproof::oracle::{Format, Theirs};
/// use rasterproof::pattern::SamplePattern;
/// // Two triangles splitting a 1x1 canvas on its diagonal x = y; their "renderer" has
/// // the 2x pattern's samples swapped: (1/4, 1/4) first, then (3/4, 3/4). Both lie on the
/// // diagonal, and a position on the 1/4 grid explains sample 0 exactly when it falls
/// // on the same side or tie as (1/4, 1/4).
/// let t = |a: [i64; 2], b: [i64; 2], c: [i64; 2]| Triangle::new(Point::from_ints(a[0], a[1]), Point::from_ints(b[0], b[1]), Point::from_ints(c[0], c[1]));
/// let scene = Primitives::from_triangles(&[t([0, 0], [1, 0], [1, 1]), t([0, 0], [1, 1], [0, 1])]);
/// let target = Target::new(1, 1, Convention::default()).unwrap();
/// let two = SamplePattern::standard(2).unwrap();
/// let swapped = SamplePattern::custom(vec![two.positions()[1].clone(), two.positions()[0].clone()]).unwrap();
/// let theirs = render_samples(&scene, &target, &swapped, Model::ExactSnapped).unwrap();
/// let theirs: Vec<Theirs> = theirs.samples().iter().map(|c| Theirs::from_coverage(c, Format::Ids)).collect();
/// let found = fit_positions(&scene, &target, &two, &theirs, Model::ExactSnapped, 4).unwrap();
/// assert_eq!(found.len(), 2);
/// assert!(found.iter().all(|f| !f.fits.is_empty()));
/// ```
///
/// # Errors
/// `theirs` is not one image per sample index of `pattern`; the model refuses the scene.
pub fn fit_positions(
    primitives: &Primitives,
    target: &Target,
    pattern: &SamplePattern,
    theirs: &[Theirs],
    model: Model,
    grid: u32,
) -> Result<Vec<PositionFit>, CompareError> {
    if theirs.len() != pattern.len() {
        return Err(CompareError::Samples(format!(
            "{} sample images for the {} positions of the {pattern} pattern",
            theirs.len(),
            pattern.len()
        )));
    }
    let grid = grid.max(1);
    let q = |n: u32| num_rational::BigRational::new(n.into(), grid.into());
    let candidates: Vec<[num_rational::BigRational; 2]> = (0..grid)
        .flat_map(|j| (0..grid).map(move |i| (i, j)))
        .map(|(i, j)| [q(i), q(j)])
        .collect();
    // Every candidate rendered once, as a pattern of all of them (each is one sample).
    let chunks: Vec<_> = candidates.chunks(crate::pattern::MAX_SAMPLES).collect();
    let mut images = Vec::with_capacity(candidates.len());
    for chunk in chunks {
        let all = SamplePattern::custom(chunk.to_vec()).map_err(|e| CompareError::Samples(e.to_string()))?;
        let c = render_samples(primitives, target, &all, model).map_err(CompareError::Model)?;
        images.extend(c.samples().iter().cloned());
    }
    let mut out = Vec::with_capacity(pattern.len());
    for (s, their) in theirs.iter().enumerate() {
        let fits: Vec<[num_rational::BigRational; 2]> = candidates
            .iter()
            .zip(&images)
            .filter(|(_, ours)| count_differences(ours, their, Some(1)).is_empty())
            .map(|(p, _)| p.clone())
            .collect();
        let own = &pattern.positions()[s];
        out.push(PositionFit {
            index: s,
            standard_fits: fits.contains(own),
            fits,
        });
    }
    Ok(out)
}

/// The positions that explain one sample index of their image ([`fit_positions`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PositionFit {
    /// The sample index.
    pub index: usize,
    /// Whether the pattern's own position for this index explains it.
    pub standard_fits: bool,
    /// Every grid position that explains it exactly.
    pub fits: Vec<[num_rational::BigRational; 2]>,
}
