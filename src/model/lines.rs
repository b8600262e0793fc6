//! A scene's lines in each model's form: Bresenham (the exact ideal-line reference, the
//! integer walk, or the float DDA) and diamond-exit (exact, integer, or read in floats).

use glam::{DVec2, Vec2};
use num_bigint::BigInt;

use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::geom::Point;
use crate::line::diamond::FixedSegment;
use crate::line::planned::PlannedSegment;
use crate::line::{self, BresenhamTie, Line, LineRule};
use crate::num::exact::dyadic;
use crate::num::fixed::snap;
use crate::num::SubPixel;

use super::{point_f32, point_f64, Arithmetic, FloatType, Model, ModelError, Shape};

/// A line converted for one model.
#[derive(Debug, Clone)]
pub(crate) enum PreparedLine {
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
    /// Diamond-exit, the planned engine: the exact endpoints (as written or snapped) and
    /// their plan (`None`: it draws nothing).
    DiamondPlanned(Box<(Point, Point)>, Option<Box<PlannedSegment>>),
    /// Diamond-exit, integer.
    DiamondFixed(FixedSegment),
    /// Diamond-exit read in f32.
    DiamondF32(Vec2, Vec2),
    /// Diamond-exit read in f64.
    DiamondF64(DVec2, DVec2),
}

/// Converts `lines` for `model`; the first line it cannot take is the error.
pub(crate) fn prepare_lines(model: Model, lines: &[Line], target: &Target) -> Result<Vec<PreparedLine>, ModelError> {
    lines
        .iter()
        .enumerate()
        .map(|(k, l)| match l.rule {
            LineRule::Bresenham(tie) => {
                let (a, b) = l.pixel_endpoints().ok_or(ModelError::LineEndpoints { line: k })?;
                Ok(match model.arithmetic() {
                    Arithmetic::Exact { .. } => PreparedLine::IdealBresenham(a, b, tie),
                    Arithmetic::Integer(_) => PreparedLine::Bresenham(a, b, tie),
                    Arithmetic::Float(FloatType::F32, _) => PreparedLine::Dda32(a, b),
                    Arithmetic::Float(FloatType::F64, _) => PreparedLine::Dda64(a, b),
                })
            }
            LineRule::Diamond => prepare_diamond(model, k, l, target),
        })
        .collect()
}

/// A diamond-exit line for `model` (line `k`, for the error).
fn prepare_diamond(model: Model, k: usize, l: &Line, target: &Target) -> Result<PreparedLine, ModelError> {
    let conv = &target.convention;
    let snapped = |p: &Point| {
        let s = |v| snap(v, conv.subpixel_bits, conv.rounding);
        [s(&p.x), s(&p.y)]
    };
    match model.arithmetic() {
        Arithmetic::Exact {
            snapped: is_snapped,
            plain,
        } => {
            let back = |[x, y]: [BigInt; 2]| Point::new(dyadic(&x, conv.subpixel_bits), dyadic(&y, conv.subpixel_bits));
            let (a, b) = if is_snapped {
                (back(snapped(&l.from)), back(snapped(&l.to)))
            } else {
                (l.from.clone(), l.to.clone())
            };
            Ok(if plain {
                PreparedLine::DiamondExact(Box::new((a, b)))
            } else {
                let planned = PlannedSegment::new(&a, &b, target).map(Box::new);
                PreparedLine::DiamondPlanned(Box::new((a, b)), planned)
            })
        }
        Arithmetic::Integer(_) => {
            let fixed = |p: &Point, end: &'static str| -> Result<[SubPixel; 2], ModelError> {
                let [x, y] = snapped(p);
                let f = |v: &BigInt, axis| {
                    SubPixel::try_from_bigint(v, conv.subpixel_bits).map_err(|error| ModelError::LineEnvelope {
                        line: k,
                        end,
                        axis,
                        error,
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
        Arithmetic::Float(FloatType::F32, _) => {
            let end = |p: &Point, end: &str| point_f32(p, || format!("lines[{k}].{end}"), model);
            Ok(PreparedLine::DiamondF32(end(&l.from, "from")?, end(&l.to, "to")?))
        }
        Arithmetic::Float(FloatType::F64, _) => {
            let end = |p: &Point, end: &str| point_f64(p, || format!("lines[{k}].{end}"), model);
            Ok(PreparedLine::DiamondF64(end(&l.from, "from")?, end(&l.to, "to")?))
        }
    }
}

impl PreparedLine {
    /// The planned engine's plan; `None` for every other form.
    pub(crate) fn plan(&self) -> Option<&crate::num::plan::Plan> {
        match self {
            PreparedLine::DiamondPlanned(_, Some(seg)) => Some(seg.plan()),
            _ => None,
        }
    }

    /// Whether it is a Bresenham line (drawn from pixel endpoints; nothing to plan).
    pub(crate) fn is_bresenham(&self) -> bool {
        matches!(self, PreparedLine::IdealBresenham(..) | PreparedLine::Bresenham(..))
    }

    /// The exact line an exact model draws; `None` for the other models' forms.
    pub(crate) fn exact_shape(&self) -> Option<Shape> {
        match self {
            PreparedLine::IdealBresenham(from, to, tie) => Some(Shape::Bresenham {
                from: *from,
                to: *to,
                tie: *tie,
            }),
            PreparedLine::DiamondExact(ends) | PreparedLine::DiamondPlanned(ends, _) => Some(Shape::Diamond {
                from: ends.0.clone(),
                to: ends.1.clone(),
            }),
            _ => None,
        }
    }

    /// Draws the line with id `id`.
    pub(crate) fn rasterize<S: CoverageSink + ?Sized>(&self, id: u32, target: &Target, sink: &mut S) {
        match self {
            PreparedLine::IdealBresenham(a, b, tie) => line::exact::rasterize_bresenham(*a, *b, *tie, id, target, sink),
            PreparedLine::Bresenham(a, b, tie) => line::bresenham::rasterize(*a, *b, *tie, id, target, sink),
            PreparedLine::Dda32(a, b) => line::dda::rasterize(*a, *b, line::dda::DdaFloat::F32, id, target, sink),
            PreparedLine::Dda64(a, b) => line::dda::rasterize(*a, *b, line::dda::DdaFloat::F64, id, target, sink),
            PreparedLine::DiamondExact(ends) => line::exact::rasterize_diamond(&ends.0, &ends.1, id, target, sink),
            PreparedLine::DiamondPlanned(_, seg) => {
                if let Some(seg) = seg {
                    seg.rasterize(id, sink);
                }
            }
            PreparedLine::DiamondFixed(seg) => line::diamond::rasterize(seg, id, target, sink),
            PreparedLine::DiamondF32(a, b) => line::float::rasterize_diamond_f32(*a, *b, id, target, sink),
            PreparedLine::DiamondF64(a, b) => line::float::rasterize_diamond_f64(*a, *b, id, target, sink),
        }
    }
}
