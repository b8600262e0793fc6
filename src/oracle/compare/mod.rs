//! Every comparison of another renderer's output with the oracle, in one shape.
//!
//! Each kind of answer a renderer gives has its comparison here, one file each, and each
//! takes the same four things, `(primitives, target, theirs, options)`, and returns a
//! report with the same surface, the [`Comparison`] trait: [`Comparison::identical`], its
//! counts by class, text, JSON and the HTML page (every comparison has one; the fits
//! print text and JSON). Every failure to
//! compare is a [`CompareError`].
//!
//! | answer | function | options | report |
//! |---|---|---|---|
//! | one sample per pixel (mask, ids, JSON) | [`compare()`] | [`CompareOptions`] | [`CompareReport`] |
//! | one image per sample index of a pattern | [`samples::compare_samples`] | [`samples::SampleOptions`] | [`samples::SampleCompareReport`] |
//! | anti-aliased grey levels | [`grey::compare_grey`] | [`grey::GreyOptions`] | [`grey::GreyReport`] |
//! | a conservative coverage | [`conservative::compare_conservative`] | [`crate::model::ConservativeRule`] | [`conservative::ConservativeReport`] |
//! | one varying's values (float32 or UNORM) | [`values::compare_values`] | [`values::ValueOptions`] | [`values::ValueReport`] |
//! | the convention of a one-sample image | [`fit::fit`] | none | [`fit::FitReport`] |
//! | the convention and sample positions under a pattern | [`fit::samples::fit_samples`] | [`fit::samples::SampleFitOptions`] | [`fit::samples::SampleFitReport`] |
//! | the method of a grey image | [`fit::grey::fit_grey`] | none | [`fit::grey::GreyFitReport`] |
//! | the float interpolator of their values | [`fit::values::fit_values`] | [`values::ValueOptions`] | [`fit::values::ValueFitReport`] |
//!
//! [`judge`] is the one entry point over all of them: a [`Question`] in, a [`Judgement`]
//! (any of the reports, itself a [`Comparison`]) out; what the CLI's `compare` calls.
//!
//! A new kind of answer adds one file here (its options, its report implementing
//! [`Comparison`], its function), a variant of [`Question`] and of [`Judgement`], and the
//! error variants it needs in [`CompareError`].

pub mod binary;
pub mod conservative;
pub mod fit;
pub mod grey;
mod pages;
pub mod samples;
pub mod values;

use std::fmt;

use serde_json::Value;

pub use binary::{
    compare, count_differences, html_escape, html_page, pick_classified, reason_text, view_block, CompareOptions,
    CompareReport, DiffPixel, PixelFinding, PixelKind, Relation, CLASSIFY_AT_MOST, COMPARE_REPORT_VERSION,
    EMPTY_COLOUR, HTML_EXPLAINED_AT_MOST, MATCHED_COLOUR,
};
pub(crate) use binary::{evidence, evidence_at, pixel_box_holds};

use crate::area::{AreaShape, Quantization};
use crate::convention::Target;
use crate::model::{AreaError, ConservativeError, ConservativeRule, Model, ModelError, Primitives};
use crate::oracle::theirs::{Format, Theirs};

/// What every comparison's report answers: whether their output is right, how many
/// differences of each class it has, and the report for people (text, HTML) and programs
/// (JSON).
pub trait Comparison {
    /// Their output is exactly what the oracle allows: nothing differs (one sample, every
    /// sample index, grey levels), every must-pixel is covered and none beyond the
    /// may-pixels (conservative), or some convention or method gives it exactly (a fit).
    /// What `compare` exits 0 on.
    fn identical(&self) -> bool;

    /// The differences counted by class, in report order: reason classes of the
    /// classified differing pixels (one sample, every sample index), grey classes, the
    /// conservative kinds, or the exact fits found.
    fn counts(&self) -> Vec<(String, usize)>;

    /// For people: the headline, the counts and at most `limit` differences one by one.
    /// `scene` and `theirs` are the names the text quotes (file names, as given).
    fn to_text(&self, scene: &str, theirs: &str, limit: usize) -> String;

    /// For programs: everything, as one JSON object (schemas in docs/oracle.md).
    fn to_json(&self, scene: &str, theirs: &str) -> Value;

    /// As one self-contained HTML page, where this kind of answer has one.
    fn to_html(&self, _page: &HtmlInputs<'_>) -> Option<String> {
        None
    }
}

/// What an HTML report quotes besides the comparison: the two names, the scene's text and
/// the command that made it.
#[derive(Debug, Clone, Copy)]
pub struct HtmlInputs<'a> {
    /// The scene's name.
    pub scene: &'a str,
    /// Their output's name.
    pub theirs: &'a str,
    /// The scene file's text.
    pub scene_json: &'a str,
    /// The command line, as the page shows it.
    pub command: &'a str,
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
    /// `Err` when their `(width, height)` is not `target`'s size.
    pub fn check_size(theirs: (u32, u32), target: &Target) -> Result<(), SizeMismatch> {
        let m = SizeMismatch {
            theirs,
            scene: (target.width, target.height),
        };
        if m.theirs == m.scene {
            Ok(())
        } else {
            Err(m)
        }
    }

    /// `Err` when `theirs` is not `target`'s size.
    pub fn check(theirs: &Theirs, target: &Target) -> Result<(), SizeMismatch> {
        SizeMismatch::check_size((theirs.width(), theirs.height()), target)
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

/// Why a comparison (or a fit) could not be made.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CompareError {
    /// Their canvas is not the scene's.
    Size(SizeMismatch),
    /// Their grey image's canvas is not the scene's.
    GreySize(SizeMismatch),
    /// The oracle must be an exact model.
    NotExact(Model),
    /// The oracle model refused the scene.
    Model(ModelError),
    /// Their multisampled image is not the pattern's images stacked.
    Samples(String),
    /// The scene's exact area coverage cannot be computed (a grey comparison).
    Area(AreaError),
    /// The scene's conservative coverage cannot be computed.
    Conservative(ConservativeError),
    /// Their grey image's levels are not of the quantization's bit depth.
    Levels {
        /// Bits per level of their image.
        bits: u32,
        /// The quantization asked for.
        quantization: Quantization,
    },
    /// The question needs another kind of output than theirs (grey levels, or one-sample
    /// coverage) and their file was read as this format.
    Format(Format),
    /// A fit does not search scenes with clip-space triangles.
    ClipSpace,
    /// The grey method judged against cannot draw the scene, or makes levels of another
    /// depth than theirs.
    Method(String),
    /// A values comparison cannot be made: the varying, or their channels.
    Values(String),
}

impl CompareError {
    /// Whether their output is at fault (its size, stacking, depth or format), rather than
    /// the scene or the options: the CLI names their file first then.
    pub fn is_theirs(&self) -> bool {
        matches!(
            self,
            CompareError::Size(_)
                | CompareError::GreySize(_)
                | CompareError::Samples(_)
                | CompareError::Levels { .. }
                | CompareError::Format(_)
        )
    }

    /// The one-line message naming the file at fault: `THEIRS: why (SCENE)` when their
    /// output is at fault, `SCENE: why` otherwise.
    pub fn to_text(&self, scene: &str, theirs: &str) -> String {
        if self.is_theirs() {
            format!("{theirs}: {self} ({scene})")
        } else {
            format!("{scene}: {self}")
        }
    }
}

impl fmt::Display for CompareError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CompareError::Size(m) => write!(f, "{m}"),
            CompareError::GreySize(m) => write!(
                f,
                "their image is {}x{}, the scene's canvas {}x{}",
                m.theirs.0, m.theirs.1, m.scene.0, m.scene.1
            ),
            CompareError::NotExact(m) => write!(
                f,
                "--model {}: the oracle must be an exact model (exact, exact-snapped, exact-plain, exact-snapped-plain)",
                m.name()
            ),
            CompareError::Model(e) => write!(f, "{e}"),
            CompareError::Samples(e) => write!(f, "{e}"),
            CompareError::Area(e) => write!(f, "{e}"),
            CompareError::Conservative(e) => write!(f, "{e}"),
            CompareError::Levels { bits, quantization } => {
                write!(
                    f,
                    "their image has {bits}-bit levels; the quantization {} makes {}-bit ones",
                    quantization.name(),
                    quantization.bits()
                )?;
                let fitting: Vec<&str> = Quantization::ALL
                    .into_iter()
                    .filter(|q| q.bits() == *bits)
                    .map(Quantization::name)
                    .collect();
                match fitting.as_slice() {
                    [] => Ok(()),
                    [one] => write!(f, " (the quantization of {bits}-bit levels is {one})"),
                    many => write!(f, " (the quantizations of {bits}-bit levels: {})", many.join(", ")),
                }
            }
            CompareError::Format(format) => write!(
                f,
                "their output was read as {}, which this comparison does not take (grey levels are compared with \
                 --as grey, coverage with --as mask, ids or json)",
                format.name()
            ),
            CompareError::Method(e) | CompareError::Values(e) => write!(f, "{e}"),
            CompareError::ClipSpace => f.write_str(
                "--fit does not search scenes with clip_space_triangles (their window-space vertices exist only \
                 after clipping); compare them under a stated convention",
            ),
        }
    }
}

impl std::error::Error for CompareError {}

/// One question about their output: which comparison (or fit) [`judge`] makes.
#[derive(Debug, Clone)]
pub enum Question {
    /// One sample per pixel against the exact model ([`compare()`]).
    Binary(CompareOptions),
    /// Every sample index of a pattern ([`samples::compare_samples`]).
    Samples(samples::SampleOptions),
    /// Grey levels against the exact area coverage ([`grey::compare_grey`]).
    Grey(grey::GreyOptions),
    /// A conservative coverage under a rule ([`conservative::compare_conservative`]).
    Conservative(ConservativeRule),
    /// The conventions that give their one-sample image ([`fit::fit`]).
    Fit,
    /// The conventions and sample positions that give each sample index
    /// ([`fit::samples::fit_samples`]).
    FitSamples(fit::samples::SampleFitOptions),
    /// The grey methods that give their levels, the scene's area shapes under this exact
    /// model ([`fit::grey::fit_grey`]).
    FitGrey(Model),
    /// Their values of one varying ([`values::compare_values`]).
    Values(Box<values::ValueOptions>),
    /// The float models that reproduce their values ([`fit::values::fit_values`]).
    FitValues(Box<values::ValueOptions>),
}

impl Question {
    /// The one-line message of `error`, met answering this question: the file at fault
    /// first ([`CompareError::to_text`]), and for a fault of the scene, the model (and
    /// pattern) it was drawn under.
    pub fn error_text(&self, error: &CompareError, scene: &str, theirs: &str) -> String {
        let text = error.to_text(scene, theirs);
        if error.is_theirs() {
            return text;
        }
        match self {
            Question::Binary(o) => format!("{text} (model {})", o.model),
            Question::Samples(o) => format!("{text} (model {}, {} samples)", o.model, o.pattern),
            Question::Grey(o) => format!("{text} (model {})", o.model),
            Question::FitGrey(model) => format!("{text} (model {model})"),
            Question::Values(o) | Question::FitValues(o) => format!("{text} (model {})", o.model),
            Question::Conservative(_) | Question::Fit | Question::FitSamples(_) => text,
        }
    }
}

/// The answer to a [`Question`]: one of the reports, itself a [`Comparison`].
#[derive(Debug, Clone)]
pub enum Judgement {
    /// [`Question::Binary`]'s.
    Binary(Box<CompareReport>),
    /// [`Question::Samples`]'s.
    Samples(samples::SampleCompareReport),
    /// [`Question::Grey`]'s.
    Grey(grey::GreyReport),
    /// [`Question::Conservative`]'s.
    Conservative(conservative::ConservativeReport),
    /// [`Question::Fit`]'s.
    Fit(fit::FitReport),
    /// [`Question::FitSamples`]'s.
    FitSamples(fit::samples::SampleFitReport),
    /// [`Question::FitGrey`]'s.
    FitGrey(fit::grey::GreyFitReport),
    /// [`Question::Values`]'s.
    Values(values::ValueReport),
    /// [`Question::FitValues`]'s.
    FitValues(fit::values::ValueFitReport),
}

impl Judgement {
    /// The one-sample report, when the question was [`Question::Binary`]: what has a
    /// difference picture.
    pub fn binary(&self) -> Option<&CompareReport> {
        match self {
            Judgement::Binary(r) => Some(r),
            _ => None,
        }
    }

    /// The report behind it, as its common surface.
    pub fn report(&self) -> &dyn Comparison {
        match self {
            Judgement::Binary(r) => r.as_ref(),
            Judgement::Samples(r) => r,
            Judgement::Grey(r) => r,
            Judgement::Conservative(r) => r,
            Judgement::Fit(r) => r,
            Judgement::FitSamples(r) => r,
            Judgement::FitGrey(r) => r,
            Judgement::Values(r) => r,
            Judgement::FitValues(r) => r,
        }
    }
}

impl Comparison for Judgement {
    fn identical(&self) -> bool {
        self.report().identical()
    }

    fn counts(&self) -> Vec<(String, usize)> {
        self.report().counts()
    }

    fn to_text(&self, scene: &str, theirs: &str, limit: usize) -> String {
        self.report().to_text(scene, theirs, limit)
    }

    fn to_json(&self, scene: &str, theirs: &str) -> Value {
        self.report().to_json(scene, theirs)
    }

    fn to_html(&self, page: &HtmlInputs<'_>) -> Option<String> {
        self.report().to_html(page)
    }
}

/// Answers `question` about `theirs`, their output of `primitives` on `target`: the one
/// entry point over every comparison and fit of this module.
///
/// # Errors
/// As the comparison asked for: see [`CompareError`].
pub fn judge(
    primitives: &Primitives,
    target: &Target,
    theirs: &Theirs,
    question: &Question,
) -> Result<Judgement, CompareError> {
    Ok(match question {
        Question::Binary(o) => Judgement::Binary(Box::new(compare(primitives, target, theirs, o)?)),
        Question::Samples(o) => Judgement::Samples(samples::compare_samples(primitives, target, theirs, o)?),
        Question::Grey(o) => {
            let mut report = grey::compare_grey_scene(primitives, target, theirs, o)?;
            // Pixels differ from the exact value's levels: the headline names the methods
            // that give every level, when some do (a correct supersampler, FreeType).
            if !report.identical() && o.method.is_none() {
                let shapes = area_shapes(primitives, target, o.model)?;
                report.explained_by = fit::grey::fit_grey(&shapes, target, grey_of(theirs)?, o.model)?.exact();
            }
            Judgement::Grey(report)
        }
        Question::Conservative(rule) => {
            Judgement::Conservative(conservative::compare_conservative(primitives, target, theirs, rule)?)
        }
        Question::Fit => Judgement::Fit(fit::fit(primitives, target, theirs)?),
        Question::Values(o) => Judgement::Values(values::compare_values(primitives, target, theirs, o)?),
        Question::FitValues(o) => Judgement::FitValues(fit::values::fit_values(primitives, target, theirs, o)?),
        Question::FitSamples(o) => Judgement::FitSamples(fit::samples::fit_samples(primitives, target, theirs, o)?),
        Question::FitGrey(model) => {
            let grey = grey_of(theirs)?;
            let shapes = area_shapes(primitives, target, *model)?;
            Judgement::FitGrey(fit::grey::fit_grey(&shapes, target, grey, *model)?)
        }
    })
}

/// The scene's area shapes under an exact `model`.
pub(crate) fn area_shapes(
    primitives: &Primitives,
    target: &Target,
    model: Model,
) -> Result<Vec<AreaShape>, CompareError> {
    crate::model::area_shapes(primitives, target, model).map_err(CompareError::Area)
}

/// Their grey levels, or the error that they were read otherwise.
pub(crate) fn grey_of(theirs: &Theirs) -> Result<&crate::oracle::theirs::GreyImage, CompareError> {
    theirs.grey().ok_or(CompareError::Format(theirs.format()))
}
