//! Why a model cannot take a primitive: each error names the primitive (`triangles[3]`,
//! `polygons[0].holes[1][2].x`), the value and the limit.

use std::fmt;

use crate::fill::triangulate::TriangulateError;
use crate::num::EnvelopeError;

use super::Model;

/// A triangle the chosen model cannot take.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ModelError {
    /// A snapped coordinate outside the integer envelope.
    Envelope {
        /// Triangle index.
        triangle: usize,
        /// Vertex index (0-2).
        vertex: usize,
        /// `'x'` or `'y'`.
        axis: char,
        /// The value and the limit.
        error: EnvelopeError,
    },
    /// A coordinate that does not fit the float model's type.
    FloatRange {
        /// Which coordinate: `triangles[0].v[2].x`, `lines[1].from.y`,
        /// `polygons[3].holes[0][5].x`.
        at: String,
        /// The value, as exact text (shortened when long).
        value: String,
        /// The model.
        model: Model,
    },
    /// A diamond-exit line endpoint outside the integer envelope.
    LineEnvelope {
        /// Line index (among the lines).
        line: usize,
        /// `"from"` or `"to"`.
        end: &'static str,
        /// `'x'` or `'y'`.
        axis: char,
        /// The value and the limit.
        error: EnvelopeError,
    },
    /// A Bresenham line whose endpoints are not integers within ±2^24.
    LineEndpoints {
        /// Line index (among the lines).
        line: usize,
    },
    /// A snapped polygon vertex outside the integer envelope.
    PolygonEnvelope {
        /// Polygon index (among the polygons).
        polygon: usize,
        /// 0 for the outline, `k` for hole `k - 1`.
        contour: usize,
        /// Vertex index within the contour.
        vertex: usize,
        /// `'x'` or `'y'`.
        axis: char,
        /// The value and the limit.
        error: EnvelopeError,
    },
    /// The `fixed` model triangulates polygons; this one cannot be triangulated.
    Triangulate {
        /// Polygon index (among the polygons).
        polygon: usize,
        /// Why.
        error: TriangulateError,
    },
    /// A clip-space triangle the model cannot take after clipping and projection.
    ClipSpace {
        /// Index among the clip-space triangles.
        triangle: usize,
        /// Why.
        message: String,
    },
    /// A scene value that does not fit the float model's type.
    FloatScene {
        /// Which value (`clip`, `viewport`, `triangles[3]`, ...).
        what: String,
        /// The model.
        model: Model,
    },
    /// Clip-space triangles given without a viewport to map them with.
    NoViewport,
    /// Lines under a pattern of several samples: a line's pixels are decided by its own
    /// rule (Bresenham, diamond exit), not per sample.
    LinesUnderPattern {
        /// How many lines the scene has.
        lines: usize,
        /// The pattern, named.
        pattern: String,
    },
    /// A sample a model that snaps to the subpixel grid cannot place: its offset from the
    /// convention's one sample is not a whole number of subpixels.
    SampleOffGrid {
        /// The sample index.
        sample: usize,
        /// Its position in the pixel, as exact text.
        position: String,
        /// The convention's subpixel bits.
        bits: u32,
        /// The model.
        model: Model,
    },
    /// The scene moved to bring one sample to the pixel's sample position is one the model
    /// cannot take (a coordinate pushed past the envelope).
    AtSample {
        /// The sample index.
        sample: usize,
        /// Its position in the pixel, as exact text.
        position: String,
        /// Why.
        error: Box<ModelError>,
    },
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ModelError::Envelope {
                triangle,
                vertex,
                axis,
                error,
            } => write!(f, "triangles[{triangle}].v[{vertex}].{axis}: {error}"),
            ModelError::FloatRange { at, value, model } => {
                let (ty, max) = match model.float_type() {
                    Some(super::FloatType::F32) => ("f32", f64::from(f32::MAX)),
                    _ => ("f64", f64::MAX),
                };
                write!(
                    f,
                    "{at}: {value} does not fit the {model} model's float type {ty} (|v| <= {max:e})"
                )
            }
            ModelError::LineEnvelope { line, end, axis, error } => write!(f, "lines[{line}].{end}.{axis}: {error}"),
            ModelError::LineEndpoints { line } => write!(
                f,
                "lines[{line}]: a Bresenham line needs integer pixel endpoints within +-2^24"
            ),
            ModelError::PolygonEnvelope {
                polygon,
                contour,
                vertex,
                axis,
                error,
            } => match contour {
                0 => write!(f, "polygons[{polygon}].v[{vertex}].{axis}: {error}"),
                k => write!(f, "polygons[{polygon}].holes[{}][{vertex}].{axis}: {error}", k - 1),
            },
            ModelError::Triangulate { polygon, error } => {
                write!(
                    f,
                    "polygons[{polygon}]: cannot triangulate for the fixed model: {error}"
                )
            }
            ModelError::ClipSpace { triangle, message } => write!(f, "clip_space_triangles[{triangle}]: {message}"),
            ModelError::FloatScene { what, model } => {
                write!(f, "{what}: a value does not fit the {model} model's float type")
            }
            ModelError::NoViewport => f.write_str("clip_space_triangles: no viewport to map them with"),
            ModelError::LinesUnderPattern { lines, pattern } => write!(
                f,
                "lines: {lines} line(s) under the {pattern} sample pattern; lines are drawn by their own rule, one answer per pixel, so a scene with samples has none"
            ),
            ModelError::SampleOffGrid {
                sample,
                position,
                bits,
                model,
            } => write!(
                f,
                "samples[{sample}]: {position} is not a whole number of subpixels (1/2^{bits}) from the pixel's sample position, so the {model} model, which snaps to that grid, cannot place it"
            ),
            ModelError::AtSample { sample, position, error } => {
                write!(f, "at sample {sample} {position} (the scene moved to it): {error}")
            }
        }
    }
}

impl std::error::Error for ModelError {}
