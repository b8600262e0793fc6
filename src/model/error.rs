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
        }
    }
}

impl std::error::Error for ModelError {}
