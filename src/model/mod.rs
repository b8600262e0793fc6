//! The closed set of models, and the ONE place that prepares a scene's primitives for a
//! model: triangles, lines, polygons, clip-space triangles and the clip window, with ids
//! assigned once.
//!
//! A scene is rendered in two steps: [`prepare`] converts every primitive into the model's
//! input form (snapping, the integer envelope, float conversion, triangulation, clipping:
//! this is where errors happen), and [`PreparedScene::render`] rasterizes (it cannot fail).
//! [`render`] does both; [`render_triangles`] is the same for a plain list of triangles.
//!
//! How each model family clips against the window (`raster(clip(P, W)) == raster(P) ∩
//! raster(W)` holds exactly, tests/clip.rs):
//! - exact models: Sutherland-Hodgman in exact arithmetic on the primitive (as written or
//!   snapped), then the polygon oracle; clip-space triangles are clipped in clip space,
//!   divided and mapped exactly.
//! - integer models: the primitive is rasterized whole and masked with `raster(W)` (an
//!   exact scissor): clipped vertices are not on the subpixel grid, and the scissor gives
//!   the same coverage without re-snapping anything.
//! - float models: Sutherland-Hodgman in the model's float type, then the clipped polygon
//!   as a fan of float triangles; clip-space triangles clipped, divided and mapped in that
//!   type (both by [`crate::clip::arithmetic::Clipper`]'s float forms). Their departures
//!   from the exact result are the measured trade.
//! - lines, in every model: the whole line is drawn and its pixels kept when their sample
//!   lies in the closed window (point clipping against the window's half-planes; a
//!   clipped Bresenham line would need its error term restarted, which changes no pixel
//!   this way).

mod area;
mod conservative;
mod error;
mod lines;
pub mod plan;
mod polygons;
mod prepared;
mod samples;
mod triangles;
mod values;

use std::fmt;

use glam::{DVec2, Vec2};

use crate::geom::Point;
use crate::num::exact::{exact_text_short, nearest_f32, nearest_f64};
use crate::tri::float::FloatRule;

pub use area::{area_shapes, render_area, render_area_rows, AreaError};
pub use conservative::{render_conservative, ConservativeCoverage, ConservativeError, ConservativeRule};
pub use error::ModelError;
pub use prepared::{prepare, prepare_parallel, render, render_triangles, PreparedScene, Primitives, Shape};
pub use samples::{render_samples, SampleFrames};
pub use values::{
    centroid, exact_pixel_values, exact_values, values_image, values_json, values_tiff, SampleValues, ValuesImageError,
};

/// A model: one arithmetic for every primitive of a scene (the CLI's `--model`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Model {
    /// Exact on the scene as written (no snapping): the planned engine.
    Exact,
    /// Exact on the snapped scene: the planned engine.
    ExactSnapped,
    /// The plain oracle on the scene as written: BigRational per sample.
    ExactPlain,
    /// The plain oracle on the snapped scene.
    ExactSnappedPlain,
    /// Incremental i64 edge functions with block traversal, on the snapped scene.
    Fixed,
    /// Edge walking: spans per scanline from an exact integer DDA, on the snapped scene.
    Scanline,
    /// Scratchapixel in f32 with the tie rule applied to float values.
    Float32,
    /// Scratchapixel in f64 with the tie rule applied to float values.
    Float64,
    /// Scratchapixel in f32 with the naive `w >= 0` test.
    Float32Naive,
    /// Scratchapixel in f64 with the naive `w >= 0` test.
    Float64Naive,
}

impl Model {
    /// Every model.
    pub const ALL: [Model; 10] = [
        Model::Exact,
        Model::ExactSnapped,
        Model::ExactPlain,
        Model::ExactSnappedPlain,
        Model::Fixed,
        Model::Scanline,
        Model::Float32,
        Model::Float64,
        Model::Float32Naive,
        Model::Float64Naive,
    ];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Model::Exact => "exact",
            Model::ExactSnapped => "exact-snapped",
            Model::ExactPlain => "exact-plain",
            Model::ExactSnappedPlain => "exact-snapped-plain",
            Model::Fixed => "fixed",
            Model::Scanline => "scanline",
            Model::Float32 => "float32",
            Model::Float64 => "float64",
            Model::Float32Naive => "float32-naive",
            Model::Float64Naive => "float64-naive",
        }
    }

    /// Parses a name written by [`Model::name`], or a line model's alias: `bresenham`
    /// (= `fixed`), `dda32` (= `float32`), `dda64` (= `float64`).
    pub fn from_name(name: &str) -> Option<Model> {
        match name {
            "bresenham" => Some(Model::Fixed),
            "dda32" => Some(Model::Float32),
            "dda64" => Some(Model::Float64),
            _ => Model::ALL.into_iter().find(|m| m.name() == name),
        }
    }

    /// The coordinate range over which the model is exact, in words.
    pub fn envelope(self) -> &'static str {
        match self {
            Model::Exact | Model::ExactSnapped => "unbounded: the planner picks i32 ... bigint per primitive",
            Model::ExactPlain | Model::ExactSnappedPlain => "unbounded (arbitrary precision)",
            Model::Fixed | Model::Scanline => "|snapped coordinate| <= 2^29 subpixels (2^21 px at 8 bits)",
            Model::Float32 | Model::Float32Naive => "none: inexact; refuses coordinates beyond f32",
            Model::Float64 | Model::Float64Naive => "none: inexact; refuses coordinates beyond f64",
        }
    }
}

/// How a model computes: the one place the per-model choice is made. Every preparation
/// matches on this, never on [`Model`] itself, so a new model is one more arm here.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Arithmetic {
    /// Exact: the planned engines, or the plain oracles, on the scene as written or
    /// snapped.
    Exact {
        /// Snap vertices to the subpixel grid first (`exact-snapped`).
        snapped: bool,
        /// The plain per-sample BigRational oracle instead of the planned engine.
        plain: bool,
    },
    /// Integers on the snapped scene, inside the envelope.
    Integer(IntegerTraversal),
    /// Floats on the scene as written.
    Float(FloatType, FloatRule),
}

/// How an integer model visits a triangle's pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum IntegerTraversal {
    /// Incremental edge functions in blocks (`fixed`); polygons triangulated.
    Blocks,
    /// Edge walking, spans per row (`scanline`); polygons by the active edge table.
    Scanline,
}

/// A float model's type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum FloatType {
    /// f32.
    F32,
    /// f64.
    F64,
}

impl Model {
    /// The model's arithmetic.
    pub(crate) fn arithmetic(self) -> Arithmetic {
        match self {
            Model::Exact => Arithmetic::Exact {
                snapped: false,
                plain: false,
            },
            Model::ExactSnapped => Arithmetic::Exact {
                snapped: true,
                plain: false,
            },
            Model::ExactPlain => Arithmetic::Exact {
                snapped: false,
                plain: true,
            },
            Model::ExactSnappedPlain => Arithmetic::Exact {
                snapped: true,
                plain: true,
            },
            Model::Fixed => Arithmetic::Integer(IntegerTraversal::Blocks),
            Model::Scanline => Arithmetic::Integer(IntegerTraversal::Scanline),
            Model::Float32 => Arithmetic::Float(FloatType::F32, FloatRule::WithTieRule),
            Model::Float64 => Arithmetic::Float(FloatType::F64, FloatRule::WithTieRule),
            Model::Float32Naive => Arithmetic::Float(FloatType::F32, FloatRule::Naive),
            Model::Float64Naive => Arithmetic::Float(FloatType::F64, FloatRule::Naive),
        }
    }

    /// The plain oracle a model is compared with: `exact-snapped-plain` for the models
    /// that snap, `exact-plain` for the others.
    pub fn reference(self) -> Model {
        if self.snaps() {
            Model::ExactSnappedPlain
        } else {
            Model::ExactPlain
        }
    }

    /// Whether the model runs the planned exact engine (`exact`, `exact-snapped`): the
    /// models with a plan per primitive.
    pub fn plans(self) -> bool {
        matches!(self.arithmetic(), Arithmetic::Exact { plain: false, .. })
    }

    /// The float type of a float model.
    pub(crate) fn float_type(self) -> Option<FloatType> {
        match self.arithmetic() {
            Arithmetic::Float(t, _) => Some(t),
            _ => None,
        }
    }

    /// Whether the model is exact: the exact and integer models, whose every invariant
    /// must hold (a float model's violations are the measured trade).
    pub fn is_exact(self) -> bool {
        !matches!(self.arithmetic(), Arithmetic::Float(..))
    }

    /// Whether the model is a plain oracle (`exact-plain`, `exact-snapped-plain`): a
    /// bounding-box loop of exact predicates, written to be read.
    pub fn is_plain(self) -> bool {
        matches!(self.arithmetic(), Arithmetic::Exact { plain: true, .. })
    }

    /// Whether the model computes in exact arithmetic with no envelope (the four exact
    /// models): it refuses no finite coordinate.
    pub fn is_unbounded(self) -> bool {
        matches!(self.arithmetic(), Arithmetic::Exact { .. })
    }

    /// Whether the model computes in integers on the snapped scene, inside its envelope
    /// (`fixed`, `scanline`).
    pub fn is_integer(self) -> bool {
        matches!(self.arithmetic(), Arithmetic::Integer(_))
    }

    /// Whether an integer model fills a polygon by triangulating it (`fixed`; `scanline`
    /// walks an active edge table), so that it takes simple polygons only.
    pub fn triangulates_polygons(self) -> bool {
        matches!(self.arithmetic(), Arithmetic::Integer(IntegerTraversal::Blocks))
    }

    /// A float model's rule (`None` for the exact and integer models).
    pub fn float_rule(self) -> Option<FloatRule> {
        match self.arithmetic() {
            Arithmetic::Float(_, rule) => Some(rule),
            _ => None,
        }
    }

    /// Whether the model computes in f32.
    pub fn is_f32(self) -> bool {
        self.float_type() == Some(FloatType::F32)
    }

    /// Whether two models compute in the same kind of arithmetic (exact, integer or
    /// float), whatever their variant of it.
    pub fn same_arithmetic(self, other: Model) -> bool {
        std::mem::discriminant(&self.arithmetic()) == std::mem::discriminant(&other.arithmetic())
    }

    /// The variant's name in Rust (`ExactSnapped`), as generated code writes
    /// `rasterproof::model::Model::ExactSnapped`.
    pub fn rust_name(self) -> &'static str {
        match self {
            Model::Exact => "Exact",
            Model::ExactSnapped => "ExactSnapped",
            Model::ExactPlain => "ExactPlain",
            Model::ExactSnappedPlain => "ExactSnappedPlain",
            Model::Fixed => "Fixed",
            Model::Scanline => "Scanline",
            Model::Float32 => "Float32",
            Model::Float64 => "Float64",
            Model::Float32Naive => "Float32Naive",
            Model::Float64Naive => "Float64Naive",
        }
    }

    /// Whether the model rasterizes the snapped scene (so `exact-snapped-plain` is its
    /// reference; `exact-plain` is the reference of the others).
    pub fn snaps(self) -> bool {
        matches!(
            self.arithmetic(),
            Arithmetic::Exact { snapped: true, .. } | Arithmetic::Integer(_)
        )
    }

    /// One line for `--help`: what the model computes and how it fills each primitive.
    pub fn describe(self) -> &'static str {
        match self {
            Model::Exact => "exact on the scene as written (no snapping), in the planned width per primitive",
            Model::ExactSnapped => "exact on the snapped scene, in the planned width per primitive (the default)",
            Model::ExactPlain => "the plain oracle on the scene as written: BigRational per sample",
            Model::ExactSnappedPlain => "the plain oracle on the snapped scene: what every other model must equal",
            Model::Fixed => "i64 edge functions in blocks (alias bresenham); polygons triangulated (simple only)",
            Model::Scanline => "edge walking with exact integer DDAs; polygons by an active edge table",
            Model::Float32 => "f32, the tie rule on float values (alias dda32); polygons by float winding",
            Model::Float64 => "f64, the tie rule on float values (alias dda64); polygons by float winding",
            Model::Float32Naive => "f32 with the naive w >= 0 test; polygons by the PNPOLY crossing test",
            Model::Float64Naive => "f64 with the naive w >= 0 test; polygons by the PNPOLY crossing test",
        }
    }
}

impl fmt::Display for Model {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// `p` rounded to the nearest f32 on each axis, or the error naming `{at}.x` / `{at}.y`,
/// the value and the model.
pub(crate) fn point_f32(p: &Point, at: impl Fn() -> String, model: Model) -> Result<Vec2, ModelError> {
    let f = |v, axis| nearest_f32(v).ok_or_else(|| float_range(v, format!("{}.{axis}", at()), model));
    Ok(Vec2::new(f(&p.x, 'x')?, f(&p.y, 'y')?))
}

/// `p` rounded to the nearest f64 on each axis, or the error naming the coordinate.
pub(crate) fn point_f64(p: &Point, at: impl Fn() -> String, model: Model) -> Result<DVec2, ModelError> {
    let f = |v, axis| nearest_f64(v).ok_or_else(|| float_range(v, format!("{}.{axis}", at()), model));
    Ok(DVec2::new(f(&p.x, 'x')?, f(&p.y, 'y')?))
}

fn float_range(v: &num_rational::BigRational, at: String, model: Model) -> ModelError {
    ModelError::FloatRange {
        at,
        value: exact_text_short(v),
        model,
    }
}
