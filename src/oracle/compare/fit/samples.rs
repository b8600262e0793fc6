//! Where a multisampled renderer's samples sit and which convention it follows: each
//! sample index of their stacked image fitted on its own ([`super::fit`] on the scene moved
//! to that sample), the conventions common to every index, and every position on a grid
//! that gives each index's image ([`fit_positions`]). What `compare --fit` answers under a
//! pattern ([`fit_samples`], [`SampleFitReport`]).

use std::fmt::Write as _;

use num_rational::BigRational;
use serde_json::{json, Value};

use super::{fit, Candidate, FitReport};
use crate::convention::{Convention, Target};
use crate::model::{render_samples, Model, Primitives, SampleFrames};
use crate::num::exact::exact_text;
use crate::oracle::compare::{count_differences, CompareError};
use crate::oracle::theirs::Theirs;
use crate::pattern::SamplePattern;

/// The grid a fit under a pattern tries every sample position on by default: 1/16 px, the
/// grid of the standard patterns and of D3D's and Vulkan's programmable sample positions.
pub const POSITION_GRID: u32 = 16;

/// How a multisampled output is fitted.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SampleFitOptions {
    /// The pattern their stacked image follows.
    pub pattern: SamplePattern,
    /// The positions tried are the `grid x grid` points `(i / grid, j / grid)`.
    pub grid: u32,
}

/// What a fit under a pattern found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SampleFitReport {
    /// The pattern fitted.
    pub pattern: SamplePattern,
    /// The scene's convention, under which the positions were fitted.
    pub convention: Convention,
    /// The grid of positions tried.
    pub grid: u32,
    /// Per sample index, the convention fit of its image (the scene moved to that sample).
    pub samples: Vec<FitReport>,
    /// The conventions that give every sample index's image exactly.
    pub every_sample: Vec<Candidate>,
    /// Per sample index, the grid positions that give its image under the scene's own
    /// convention.
    pub positions: Vec<PositionFit>,
}

/// Fits their stacked per-sample output: each sample index's image against every
/// convention, the scene moved exactly to that sample (unsnapped: each candidate snaps the
/// moved scene, which is the snapped scene moved except at a coordinate exactly halfway
/// between two subpixels); the conventions that give every sample; and the positions on
/// the `options.grid` grid that give each sample's image under the scene's convention
/// (snapped, as a renderer snaps).
///
/// # Errors
/// Their image is not the pattern's images stacked; a fit fails ([`fit`]'s errors).
pub fn fit_samples(
    primitives: &Primitives,
    target: &Target,
    theirs: &Theirs,
    options: &SampleFitOptions,
) -> Result<SampleFitReport, CompareError> {
    let pattern = &options.pattern;
    let per_sample = theirs
        .unstack(pattern.len(), target.height)
        .map_err(CompareError::Samples)?;
    let frames = SampleFrames::new(primitives, target, pattern, Model::Exact).map_err(CompareError::Model)?;
    let mut samples = Vec::with_capacity(per_sample.len());
    for (s, theirs) in per_sample.iter().enumerate() {
        let moved = frames.at(s).map_err(CompareError::Model)?;
        samples.push(fit(&moved, target, theirs)?);
    }
    let every_sample: Vec<Candidate> = samples[0]
        .exact
        .iter()
        .filter(|c| samples.iter().all(|f| f.exact.contains(c)))
        .cloned()
        .collect();
    let positions = fit_positions(
        primitives,
        target,
        pattern,
        &per_sample,
        Model::ExactSnapped,
        options.grid,
    )?;
    Ok(SampleFitReport {
        pattern: pattern.clone(),
        convention: target.convention,
        grid: options.grid.max(1),
        samples,
        every_sample,
        positions,
    })
}

/// A position as `(x, y)` in exact text.
fn position_text(p: &[BigRational; 2]) -> String {
    format!("({}, {})", exact_text(&p[0]), exact_text(&p[1]))
}

impl super::super::Comparison for SampleFitReport {
    /// Some convention gives every sample index's image exactly.
    fn identical(&self) -> bool {
        !self.every_sample.is_empty()
    }

    /// The conventions that give every sample's image, then the sample indices whose
    /// pattern position does not fit.
    fn counts(&self) -> Vec<(String, usize)> {
        vec![
            ("every sample".to_string(), self.every_sample.len()),
            (
                "positions not fitting".to_string(),
                self.positions.iter().filter(|p| !p.standard_fits).count(),
            ),
        ]
    }

    fn to_text(&self, scene: &str, theirs: &str, _limit: usize) -> String {
        let mut out = format!(
            "compare --fit: {theirs} against {scene}, {} samples, each sample index on its own\n",
            self.pattern
        );
        for (s, f) in self.samples.iter().enumerate() {
            let _ = writeln!(out, "sample {s} at {}:", self.pattern.position_text(s));
            for line in f.fit_text().lines() {
                let _ = writeln!(out, "  {line}");
            }
        }
        let _ = writeln!(
            out,
            "sample positions on the 1/{} px grid that give each sample's image under {}:",
            self.grid, self.convention
        );
        for p in &self.positions {
            let listed: Vec<String> = p.fits.iter().take(8).map(position_text).collect();
            let more = p.fits.len().saturating_sub(8);
            let _ = writeln!(
                out,
                "  sample {}: the pattern's {} {}; {} of {} positions fit{}{}",
                p.index,
                self.pattern.position_text(p.index),
                if p.standard_fits { "fits" } else { "does NOT fit" },
                p.fits.len(),
                self.grid * self.grid,
                if listed.is_empty() {
                    String::new()
                } else {
                    format!(": {}", listed.join(" "))
                },
                if more > 0 {
                    format!(" and {more} more")
                } else {
                    String::new()
                }
            );
        }
        if self.every_sample.is_empty() {
            let _ = writeln!(
                out,
                "no convention gives every sample's image exactly (if each sample has fits of its own, their \
                 sample positions are not the {}'s)",
                self.pattern
            );
        } else {
            let _ = writeln!(
                out,
                "{} conventions give every sample's image exactly, at the {} positions:",
                self.every_sample.len(),
                self.pattern
            );
            for c in &self.every_sample {
                let _ = writeln!(out, "  {c}");
            }
        }
        out
    }

    /// `{"pattern", "every_sample": [convention], "samples": [FitReport's JSON],
    /// "positions": [{"index", "pattern_fits", "fits": ["(x, y)"]}]}`.
    fn to_json(&self, _scene: &str, _theirs: &str) -> Value {
        json!({
            "pattern": self.pattern.to_json(),
            "every_sample": self.every_sample.iter().map(ToString::to_string).collect::<Vec<_>>(),
            "samples": self.samples.iter().map(FitReport::fit_json).collect::<Vec<_>>(),
            "positions": self.positions.iter().map(|p| json!({
                "index": p.index,
                "pattern_fits": p.standard_fits,
                "fits": p.fits.iter().map(position_text).collect::<Vec<_>>(),
            })).collect::<Vec<_>>(),
        })
    }
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
/// use rasterproof::oracle::compare::fit::samples::fit_positions;
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
    let q = |n: u32| BigRational::new(n.into(), grid.into());
    let candidates: Vec<[BigRational; 2]> = (0..grid)
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
        let fits: Vec<[BigRational; 2]> = candidates
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
    pub fits: Vec<[BigRational; 2]>,
}
