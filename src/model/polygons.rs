//! A scene's polygons in each model's form (the oracle's exact polygon, the scanline
//! filler's snapped polygon, the `fixed` model's triangulation, a float polygon for the
//! float winding test, a float fan for clipped convex pieces), and the
//! window-space polygon of each clip-space triangle.

use glam::{DVec2, Vec2};

use crate::clip::homogeneous::{clip_to_window_exact, ClipVertex, Viewport};
use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::fill;
use crate::fill::polygon::{PlannedPolygon, PolygonF32, PolygonF64};
use crate::fill::triangulate::triangulate;
use crate::geom::{FillRule, FixedPolygon, FixedTriangle, Point, Polygon};
use crate::tri::fixed;
use crate::tri::float::{rasterize_f32, rasterize_f64, FloatRule};

use super::{point_f32, point_f64, Arithmetic, FloatType, IntegerTraversal, Model, ModelError};

/// A polygon converted for one model.
#[derive(Debug, Clone)]
pub(crate) enum PreparedPolygon {
    /// The plain oracle's input: the polygon as written (`exact-plain`) or snapped
    /// (`exact-snapped-plain`).
    Exact(Polygon),
    /// The same exact polygon and its planned form (`None`: it covers nothing), for
    /// `exact` and `exact-snapped`.
    Planned(Polygon, Option<Box<PlannedPolygon>>),
    /// The scanline filler's input.
    Scanline(FixedPolygon),
    /// The `fixed` model's input: the snapped polygon's triangulation.
    Triangles(Vec<FixedTriangle>),
    /// A polygon in f32 for the float models' winding test.
    Float32(PolygonF32, FloatRule),
    /// A polygon in f64.
    Float64(PolygonF64, FloatRule),
    /// A convex f32 polygon (a clipped triangle or clip-space triangle), filled as a fan
    /// of float triangles.
    Fan32(Vec<Vec2>, FloatRule),
    /// A convex f64 polygon, filled as a fan.
    Fan64(Vec<DVec2>, FloatRule),
}

/// Converts polygon `k` for `model`.
pub(crate) fn prepare_polygon(
    model: Model,
    k: usize,
    p: &Polygon,
    target: &Target,
) -> Result<PreparedPolygon, ModelError> {
    let conv = &target.convention;
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
    Ok(match model.arithmetic() {
        Arithmetic::Exact { snapped, plain } => {
            let exact = if snapped { p.snapped_exact(conv) } else { p.clone() };
            PreparedPolygon::exact(exact, plain, target)
        }
        Arithmetic::Integer(IntegerTraversal::Scanline) => PreparedPolygon::Scanline(fixed()?),
        Arithmetic::Integer(IntegerTraversal::Blocks) => PreparedPolygon::Triangles(
            triangulate(&fixed()?).map_err(|error| ModelError::Triangulate { polygon: k, error })?,
        ),
        Arithmetic::Float(FloatType::F32, rule) => {
            let (outline, holes) = float_contours(p, |v, c, i| point_f32(v, || contour_vertex(k, c, i), model))?;
            let fill_rule = p.fill_rule;
            PreparedPolygon::Float32(
                PolygonF32 {
                    outline,
                    holes,
                    fill_rule,
                },
                rule,
            )
        }
        Arithmetic::Float(FloatType::F64, rule) => {
            let (outline, holes) = float_contours(p, |v, c, i| point_f64(v, || contour_vertex(k, c, i), model))?;
            let fill_rule = p.fill_rule;
            PreparedPolygon::Float64(
                PolygonF64 {
                    outline,
                    holes,
                    fill_rule,
                },
                rule,
            )
        }
    })
}

/// A polygon's outline and holes in a float type.
type FloatContours<V> = (Vec<V>, Vec<Vec<V>>);

/// The outline and holes of `p` converted vertex by vertex: `convert(vertex, contour, index)`
/// with contour 0 the outline and `h + 1` hole `h`; the first error stops it.
fn float_contours<V>(
    p: &Polygon,
    convert: impl Fn(&Point, usize, usize) -> Result<V, ModelError>,
) -> Result<FloatContours<V>, ModelError> {
    let contour = |c: usize, points: &[Point]| -> Result<Vec<V>, ModelError> {
        points.iter().enumerate().map(|(i, v)| convert(v, c, i)).collect()
    };
    let outline = contour(0, &p.outline)?;
    let holes = p
        .holes
        .iter()
        .enumerate()
        .map(|(h, points)| contour(h + 1, points))
        .collect::<Result<_, _>>()?;
    Ok((outline, holes))
}

/// The path of vertex `i` of contour `c` (0 the outline, `h + 1` hole `h`) of polygon `k`.
fn contour_vertex(k: usize, c: usize, i: usize) -> String {
    match c {
        0 => format!("polygons[{k}].v[{i}]"),
        h => format!("polygons[{k}].holes[{}][{i}]", h - 1),
    }
}

/// The window-space polygon of a clip-space triangle, exactly (clipped in clip space,
/// divided, mapped through the viewport).
pub(crate) fn clip_space_polygon(t: &[ClipVertex; 3], viewport: &Viewport) -> Polygon {
    let outline = clip_to_window_exact(t, viewport).into_iter().map(|v| v.point).collect();
    Polygon::new(outline, FillRule::NonZero)
}

/// Clip-space triangle `k` for an exact or integer `model`: its exact window-space polygon,
/// prepared as a polygon; errors name the clip-space triangle.
pub(crate) fn prepare_clip_space(
    model: Model,
    k: usize,
    t: &[ClipVertex; 3],
    viewport: &Viewport,
    target: &Target,
) -> Result<PreparedPolygon, ModelError> {
    prepare_polygon(model, k, &clip_space_polygon(t, viewport), target).map_err(|e| ModelError::ClipSpace {
        triangle: k,
        message: match e {
            ModelError::PolygonEnvelope {
                vertex, axis, error, ..
            } => format!("window-space vertex {vertex} (after clipping and the viewport), {axis}: {error}"),
            ModelError::Triangulate { error, .. } => format!("window-space polygon: {error}"),
            other => other.to_string(),
        },
    })
}

impl PreparedPolygon {
    /// An exact model's form of the exact polygon `p`: the plain oracle's or the planned
    /// engine's.
    pub(crate) fn exact(p: Polygon, plain: bool, target: &Target) -> PreparedPolygon {
        if plain {
            PreparedPolygon::Exact(p)
        } else {
            let planned = PlannedPolygon::new(&p, target).map(Box::new);
            PreparedPolygon::Planned(p, planned)
        }
    }

    /// The exact polygon of an exact model's form.
    pub(crate) fn exact_polygon(&self) -> Option<&Polygon> {
        match self {
            PreparedPolygon::Exact(p) | PreparedPolygon::Planned(p, _) => Some(p),
            _ => None,
        }
    }

    /// The planned engine's plan; `None` for every other form.
    pub(crate) fn plan(&self) -> Option<&crate::num::plan::Plan> {
        match self {
            PreparedPolygon::Planned(_, Some(p)) => Some(p.plan()),
            _ => None,
        }
    }

    /// Fills the polygon with id `id`.
    pub(crate) fn fill<S: CoverageSink + ?Sized>(&self, id: u32, target: &Target, sink: &mut S) {
        match self {
            PreparedPolygon::Exact(p) => fill::polygon::rasterize_exact(p, id, target, sink),
            PreparedPolygon::Planned(_, p) => {
                if let Some(p) = p {
                    p.rasterize(id, sink);
                }
            }
            PreparedPolygon::Scanline(p) => fill::polygon::rasterize(p, id, target, sink),
            PreparedPolygon::Triangles(ts) => ts.iter().for_each(|t| fixed::rasterize(t, id, target, sink)),
            PreparedPolygon::Float32(p, rule) => fill::polygon::rasterize_f32(p, id, target, *rule, sink),
            PreparedPolygon::Float64(p, rule) => fill::polygon::rasterize_f64(p, id, target, *rule, sink),
            PreparedPolygon::Fan32(poly, rule) => {
                for i in 1..poly.len().saturating_sub(1) {
                    rasterize_f32(&[poly[0], poly[i], poly[i + 1]], id, target, *rule, sink);
                }
            }
            PreparedPolygon::Fan64(poly, rule) => {
                for i in 1..poly.len().saturating_sub(1) {
                    rasterize_f64(&[poly[0], poly[i], poly[i + 1]], id, target, *rule, sink);
                }
            }
        }
    }
}
