//! The closed set of models the CLI and the harness pick from at run time, and the one
//! place that turns a scene's exact triangles into each model's input form.

use std::fmt;

use glam::{DVec2, Vec2};
use image::RgbImage;
use num_rational::BigRational;

use crate::convention::{Convention, Target};
use crate::coverage::{primitive_colour, Coverage, CoverageSink};
use crate::fill;
use crate::fill::triangulate::{triangulate, TriangulateError};
use crate::geom::{FixedPolygon, FixedTriangle, Point, Polygon, Triangle};
use crate::interp::{barycentric_fixed, gouraud_exact, gouraud_f32, gouraud_f64, to_channel, Rgb};
use crate::line::diamond::FixedSegment;
use crate::line::{self, BresenhamTie, Line, LineRule};
use crate::num::exact::dyadic;
use crate::num::EnvelopeError;
use crate::num::SubPixel;
use crate::tri::float::FloatRule;
use crate::tri::{exact, fixed, float, scanline};

/// A triangle model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Model {
    /// The oracle on the scene as written (no snapping).
    Exact,
    /// The oracle on the snapped scene.
    ExactSnapped,
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
    pub const ALL: [Model; 8] = [
        Model::Exact,
        Model::ExactSnapped,
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
            Model::Exact | Model::ExactSnapped => "unbounded (arbitrary precision)",
            Model::Fixed | Model::Scanline => "|snapped coordinate| <= 2^29 subpixels (2^21 px at 8 bits)",
            Model::Float32 | Model::Float32Naive => "none: inexact; refuses coordinates beyond f32",
            Model::Float64 | Model::Float64Naive => "none: inexact; refuses coordinates beyond f64",
        }
    }
}

impl fmt::Display for Model {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

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
    /// A coordinate that does not fit the float type.
    FloatRange {
        /// Triangle index.
        triangle: usize,
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
    /// A float model asked for a diamond-exit line (it has only the DDA).
    NoFloatDiamond {
        /// Line index (among the lines).
        line: usize,
        /// The model.
        model: Model,
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
    /// A float model asked for a polygon (polygons are filled by exact and integer models).
    NoFloatPolygon {
        /// Polygon index (among the polygons).
        polygon: usize,
        /// The model.
        model: Model,
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
            ModelError::FloatRange { triangle, model } => write!(
                f,
                "triangles[{triangle}]: a coordinate does not fit the {model} model's float type"
            ),
            ModelError::LineEnvelope {
                line,
                end,
                axis,
                error,
            } => write!(f, "lines[{line}].{end}.{axis}: {error}"),
            ModelError::LineEndpoints { line } => write!(
                f,
                "lines[{line}]: a Bresenham line needs integer pixel endpoints within +-2^24"
            ),
            ModelError::NoFloatDiamond { line, model } => write!(
                f,
                "lines[{line}]: the {model} model draws lines with the DDA only; use exact, exact-snapped or fixed for \"rule\": \"diamond\""
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
                write!(f, "polygons[{polygon}]: cannot triangulate for the fixed model: {error}")
            }
            ModelError::ClipSpace { triangle, message } => write!(f, "clip_space_triangles[{triangle}]: {message}"),
            ModelError::FloatScene { what, model } => {
                write!(f, "{what}: a value does not fit the {model} model's float type")
            }
            ModelError::NoFloatPolygon { polygon, model } => write!(
                f,
                "polygons[{polygon}]: the {model} model has no polygon fill; use exact, exact-snapped, scanline or fixed"
            ),
        }
    }
}

impl std::error::Error for ModelError {}

/// A scene's triangles converted for one model (the conversion is where errors happen;
/// rasterizing a prepared scene cannot fail).
#[derive(Debug, Clone)]
pub enum Prepared {
    /// Exact triangles (as written, or snapped and converted back).
    Exact(Vec<Triangle>),
    /// Fixed-point triangles inside the envelope.
    Fixed(Vec<FixedTriangle>),
    /// Fixed-point triangles for the scanline (edge-walking) model.
    Scanline(Vec<FixedTriangle>),
    /// f32 triangles and the float rule.
    F32(Vec<[Vec2; 3]>, FloatRule),
    /// f64 triangles and the float rule.
    F64(Vec<[DVec2; 3]>, FloatRule),
}

/// Converts `triangles` for `model`; the first triangle it cannot take is the error.
pub fn prepare(model: Model, triangles: &[Triangle], conv: &Convention) -> Result<Prepared, ModelError> {
    Ok(match model {
        Model::Exact => Prepared::Exact(triangles.to_vec()),
        Model::ExactSnapped => Prepared::Exact(triangles.iter().map(|t| t.snapped(conv).to_exact()).collect()),
        Model::Fixed => Prepared::Fixed(fixed_triangles(triangles, conv)?),
        Model::Scanline => Prepared::Scanline(fixed_triangles(triangles, conv)?),
        Model::Float32 | Model::Float32Naive => Prepared::F32(
            triangles
                .iter()
                .enumerate()
                .map(|(k, t)| t.to_f32().ok_or(ModelError::FloatRange { triangle: k, model }))
                .collect::<Result<_, _>>()?,
            float_rule(model),
        ),
        Model::Float64 | Model::Float64Naive => Prepared::F64(
            triangles
                .iter()
                .enumerate()
                .map(|(k, t)| t.to_f64().ok_or(ModelError::FloatRange { triangle: k, model }))
                .collect::<Result<_, _>>()?,
            float_rule(model),
        ),
    })
}

/// Snaps every triangle and checks it against the integer envelope.
fn fixed_triangles(triangles: &[Triangle], conv: &Convention) -> Result<Vec<FixedTriangle>, ModelError> {
    triangles
        .iter()
        .enumerate()
        .map(|(k, t)| {
            t.snapped(conv)
                .to_fixed()
                .map_err(|(vertex, axis, error)| ModelError::Envelope {
                    triangle: k,
                    vertex,
                    axis,
                    error,
                })
        })
        .collect()
}

fn float_rule(model: Model) -> FloatRule {
    match model {
        Model::Float32Naive | Model::Float64Naive => FloatRule::Naive,
        _ => FloatRule::TieRule,
    }
}

/// Triangle ids are their indices.
fn id_of(k: usize) -> u32 {
    u32::try_from(k).expect("scene triangle counts fit u32")
}

impl Prepared {
    /// Rasterizes every triangle into `sink`, triangle k with id k.
    pub fn rasterize_into<S: CoverageSink + ?Sized>(&self, target: &Target, sink: &mut S) {
        match self {
            Prepared::Exact(ts) => ts
                .iter()
                .enumerate()
                .for_each(|(k, t)| exact::rasterize(t, id_of(k), target, sink)),
            Prepared::Fixed(ts) => ts
                .iter()
                .enumerate()
                .for_each(|(k, t)| fixed::rasterize(t, id_of(k), target, sink)),
            Prepared::Scanline(ts) => ts
                .iter()
                .enumerate()
                .for_each(|(k, t)| scanline::rasterize(t, id_of(k), target, sink)),
            Prepared::F32(ts, rule) => ts
                .iter()
                .enumerate()
                .for_each(|(k, t)| float::rasterize_f32(t, id_of(k), target, *rule, sink)),
            Prepared::F64(ts, rule) => ts
                .iter()
                .enumerate()
                .for_each(|(k, t)| float::rasterize_f64(t, id_of(k), target, *rule, sink)),
        }
    }

    /// The Gouraud colour of triangle `k` at the sample of pixel `(x, y)`, computed in the
    /// model's own arithmetic (exact rationals; exact integer edge values over twice the
    /// area for `fixed`; f32 / f64 barycentrics for the float models).
    pub fn shade(&self, k: usize, colours: &[Rgb; 3], x: u32, y: u32, target: &Target) -> Rgb {
        let centre = target.convention.pixel_centre.offset_f64();
        match self {
            Prepared::Exact(ts) => {
                let c = target.convention.pixel_centre.offset();
                let p = crate::tri::sample_point(x, y, &c);
                gouraud_exact(&ts[k], colours, &p).map_or([0; 3], |c| c.each_ref().map(to_channel))
            }
            Prepared::Fixed(ts) | Prepared::Scanline(ts) => {
                let b = barycentric_fixed(&ts[k], x, y, target);
                if b.area2 == 0 {
                    return [0; 3];
                }
                std::array::from_fn(|ch| {
                    let sum: i128 = (0..3).map(|i| b.w[i] * i128::from(colours[i][ch])).sum();
                    to_channel(&BigRational::new(sum.into(), b.area2.into()))
                })
            }
            #[allow(clippy::cast_possible_truncation)] // pixel centres < 2^15: exact in f32
            Prepared::F32(ts, _) => {
                let p = Vec2::new((f64::from(x) + centre) as f32, (f64::from(y) + centre) as f32);
                gouraud_f32(&ts[k], colours, p).unwrap_or([0; 3])
            }
            Prepared::F64(ts, _) => {
                let p = DVec2::new(f64::from(x) + centre, f64::from(y) + centre);
                gouraud_f64(&ts[k], colours, p).unwrap_or([0; 3])
            }
        }
    }

    /// The interpolated-colour picture: each covered pixel takes the colour of its
    /// highest-numbered (last drawn) triangle; a triangle without colours shows its
    /// coverage colour.
    pub fn colour_image(&self, coverage: &Coverage, colours: &[Option<[Rgb; 3]>], target: &Target) -> RgbImage {
        let mut img = RgbImage::new(target.width, target.height);
        for (x, y, ids) in coverage.iter() {
            let Some(&top) = ids.last() else { continue };
            let k = top as usize;
            let rgb = match colours.get(k).copied().flatten() {
                Some(c) => self.shade(k, &c, x, y, target),
                None => primitive_colour(top),
            };
            img.put_pixel(x, y, image::Rgb(rgb));
        }
        img
    }
}

/// Renders `triangles` with `model` into a fresh [`Coverage`].
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::model::{render, Model};
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(8, 0), Point::from_ints(0, 8));
/// let target = Target::new(8, 8, Convention::default()).unwrap();
/// let exact = render(Model::ExactSnapped, &[t.clone()], &target).unwrap();
/// assert_eq!(render(Model::Fixed, &[t], &target).unwrap(), exact);
/// ```
pub fn render(model: Model, triangles: &[Triangle], target: &Target) -> Result<Coverage, ModelError> {
    let prepared = prepare(model, triangles, &target.convention)?;
    let mut coverage = Coverage::new(target.width, target.height);
    prepared.rasterize_into(target, &mut coverage);
    Ok(coverage)
}

/// A line converted for one model.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PreparedLine {
    /// Bresenham, drawn by the exact ideal-line reference.
    IdealBresenham([i64; 2], [i64; 2], BresenhamTie),
    /// Bresenham, integer.
    Bresenham([i64; 2], [i64; 2], BresenhamTie),
    /// The f32 DDA.
    Dda32([i64; 2], [i64; 2]),
    /// The f64 DDA.
    Dda64([i64; 2], [i64; 2]),
    /// Diamond-exit, the plain exact reading (endpoints as written or snapped).
    DiamondExact(Box<(Point, Point)>),
    /// Diamond-exit, integer.
    DiamondFixed(FixedSegment),
}

/// Converts `lines` for `model`; the first line it cannot take is the error.
pub fn prepare_lines(model: Model, lines: &[Line], conv: &Convention) -> Result<Vec<PreparedLine>, ModelError> {
    lines
        .iter()
        .enumerate()
        .map(|(k, l)| match l.rule {
            LineRule::Bresenham(tie) => {
                let (a, b) = l.pixel_endpoints().ok_or(ModelError::LineEndpoints { line: k })?;
                Ok(match model {
                    Model::Exact | Model::ExactSnapped => PreparedLine::IdealBresenham(a, b, tie),
                    Model::Fixed | Model::Scanline => PreparedLine::Bresenham(a, b, tie),
                    Model::Float32 | Model::Float32Naive => PreparedLine::Dda32(a, b),
                    Model::Float64 | Model::Float64Naive => PreparedLine::Dda64(a, b),
                })
            }
            LineRule::Diamond => {
                let snap = |p: &Point| {
                    let s = |v| crate::num::fixed::snap(v, conv.subpixel_bits, conv.rounding);
                    [s(&p.x), s(&p.y)]
                };
                match model {
                    Model::Exact => Ok(PreparedLine::DiamondExact(Box::new((l.from.clone(), l.to.clone())))),
                    Model::ExactSnapped => {
                        let back = |[x, y]: [num_bigint::BigInt; 2]| {
                            Point::new(dyadic(&x, conv.subpixel_bits), dyadic(&y, conv.subpixel_bits))
                        };
                        Ok(PreparedLine::DiamondExact(Box::new((
                            back(snap(&l.from)),
                            back(snap(&l.to)),
                        ))))
                    }
                    Model::Fixed | Model::Scanline => {
                        let fixed = |p: &Point, end: &'static str| -> Result<[SubPixel; 2], ModelError> {
                            let [x, y] = snap(p);
                            let f = |v: &num_bigint::BigInt, axis| {
                                SubPixel::try_from_bigint(v, conv.subpixel_bits).map_err(|error| {
                                    ModelError::LineEnvelope {
                                        line: k,
                                        end,
                                        axis,
                                        error,
                                    }
                                })
                            };
                            Ok([f(&x, 'x')?, f(&y, 'y')?])
                        };
                        Ok(PreparedLine::DiamondFixed(FixedSegment {
                            a: fixed(&l.from, "from")?,
                            b: fixed(&l.to, "to")?,
                            bits: conv.subpixel_bits,
                        }))
                    }
                    _ => Err(ModelError::NoFloatDiamond { line: k, model }),
                }
            }
        })
        .collect()
}

impl PreparedLine {
    /// Draws the line with id `id`.
    pub fn draw<S: CoverageSink + ?Sized>(&self, id: u32, target: &Target, sink: &mut S) {
        match self {
            PreparedLine::IdealBresenham(a, b, tie) => line::exact::draw_bresenham(*a, *b, *tie, id, target, sink),
            PreparedLine::Bresenham(a, b, tie) => line::bresenham::draw(*a, *b, *tie, id, target, sink),
            PreparedLine::Dda32(a, b) => line::dda::draw(*a, *b, line::dda::DdaFloat::F32, id, target, sink),
            PreparedLine::Dda64(a, b) => line::dda::draw(*a, *b, line::dda::DdaFloat::F64, id, target, sink),
            PreparedLine::DiamondExact(ends) => line::exact::draw_diamond(&ends.0, &ends.1, id, target, sink),
            PreparedLine::DiamondFixed(seg) => line::diamond::draw(seg, id, target, sink),
        }
    }
}

/// A polygon converted for one model.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PreparedPolygon {
    /// The oracle's input: the polygon as written (`exact`) or snapped (`exact-snapped`).
    Exact(Polygon),
    /// The scanline filler's input.
    Scanline(FixedPolygon),
    /// The `fixed` model's input: the snapped polygon's triangulation.
    Triangles(Vec<FixedTriangle>),
}

/// Converts `polygons` for `model`; the first polygon it cannot take is the error.
pub fn prepare_polygons(
    model: Model,
    polygons: &[Polygon],
    conv: &Convention,
) -> Result<Vec<PreparedPolygon>, ModelError> {
    polygons
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let fixed = || {
                p.to_fixed(conv)
                    .map_err(|(contour, vertex, axis, error)| ModelError::PolygonEnvelope {
                        polygon: k,
                        contour,
                        vertex,
                        axis,
                        error,
                    })
            };
            Ok(match model {
                Model::Exact => PreparedPolygon::Exact(p.clone()),
                Model::ExactSnapped => PreparedPolygon::Exact(p.snapped_exact(conv)),
                Model::Scanline => PreparedPolygon::Scanline(fixed()?),
                Model::Fixed => PreparedPolygon::Triangles(
                    triangulate(&fixed()?).map_err(|error| ModelError::Triangulate { polygon: k, error })?,
                ),
                _ => return Err(ModelError::NoFloatPolygon { polygon: k, model }),
            })
        })
        .collect()
}

impl PreparedPolygon {
    /// Fills the polygon with id `id`.
    pub fn fill<S: CoverageSink + ?Sized>(&self, id: u32, target: &Target, sink: &mut S) {
        match self {
            PreparedPolygon::Exact(p) => fill::polygon::rasterize_exact(p, id, target, sink),
            PreparedPolygon::Scanline(p) => fill::polygon::rasterize(p, id, target, sink),
            PreparedPolygon::Triangles(ts) => ts.iter().for_each(|t| fixed::rasterize(t, id, target, sink)),
        }
    }
}

/// Renders triangles (ids `0..`), then lines, then polygons (ids after the triangles and
/// lines, in that order) with `model`.
pub fn render_primitives(
    model: Model,
    triangles: &[Triangle],
    lines: &[Line],
    polygons: &[Polygon],
    target: &Target,
) -> Result<Coverage, ModelError> {
    let prepared = prepare(model, triangles, &target.convention)?;
    let lines = prepare_lines(model, lines, &target.convention)?;
    let polygons = prepare_polygons(model, polygons, &target.convention)?;
    let mut coverage = Coverage::new(target.width, target.height);
    prepared.rasterize_into(target, &mut coverage);
    for (k, l) in lines.iter().enumerate() {
        l.draw(id_of(triangles.len() + k), target, &mut coverage);
    }
    for (k, p) in polygons.iter().enumerate() {
        p.fill(id_of(triangles.len() + lines.len() + k), target, &mut coverage);
    }
    Ok(coverage)
}
