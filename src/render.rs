//! A whole scene through one model: triangles, lines, polygons and clip-space triangles
//! (ids in that order), each clipped against the scene's `clip` window before it is
//! rasterized.
//!
//! How each model family clips:
//! - `exact`, `exact-snapped`: Sutherland-Hodgman in exact arithmetic on the primitive (as
//!   written or snapped), then the polygon oracle. Clip-space triangles are clipped in
//!   clip space, divided and mapped exactly.
//! - `fixed`, `scanline`: the primitive is rasterized whole and masked with `raster(W)`
//!   (an exact scissor): clipped vertices are not on the subpixel grid, and
//!   `raster(clip(P, W)) == raster(P) ∩ raster(W)` holds exactly (tests/clip.rs), so this
//!   is the same coverage without re-snapping anything.
//! - float models: Sutherland-Hodgman in the model's float type, then the clipped polygon
//!   as a fan of float triangles; clip-space triangles clipped, divided and mapped in that
//!   float type. Their departures from the exact result are the measured trade.
//! - Lines, in every model: the whole line is drawn and its pixels kept when their sample
//!   lies in the closed window (seed 002's point clipping; a clipped Bresenham line would
//!   need its error term restarted, which changes no pixel this way).

use crate::clip::homogeneous::{self, clip_to_window_exact};
use crate::clip::mask::ClipMask;
use crate::clip::sutherland_hodgman::{self, clip_polygon};
use crate::clip::Window;
use crate::convention::Target;
use crate::coverage::{Coverage, CoverageSink};
use crate::fill::polygon::rasterize_exact;
use crate::geom::{FillRule, Polygon, Triangle};
use crate::model::{prepare, prepare_lines, prepare_polygons, Model, ModelError, PreparedLine};
use crate::scene::Scene;
use crate::tri::float::{rasterize_f32, rasterize_f64, FloatRule};

/// Ids are positions in one sequence.
fn id(k: usize) -> u32 {
    u32::try_from(k).expect("scene primitive counts fit u32")
}

/// The window-space polygon of each clip-space triangle, exactly (clipped in clip space,
/// divided, mapped through the viewport).
pub fn clip_space_polygons(scene: &Scene) -> Vec<Polygon> {
    let viewport = scene.viewport();
    scene
        .clip_space_triangles
        .iter()
        .map(|t| {
            let outline = clip_to_window_exact(t, &viewport)
                .into_iter()
                .map(|v| v.point)
                .collect();
            Polygon::new(outline, FillRule::NonZero)
        })
        .collect()
}

/// Renders every primitive of `scene` with `model`, clipped against `scene.clip`.
///
/// # Errors
/// The first primitive the model cannot take (envelope, float range, polygons for float
/// models, a polygon the `fixed` model cannot triangulate).
pub fn render_scene(model: Model, scene: &Scene, target: &Target) -> Result<Coverage, ModelError> {
    let conv = &target.convention;
    let triangles = scene.triangles();
    let lines = prepare_lines(model, &scene.lines, conv)?;
    let first_polygon = triangles.len() + lines.len();
    let first_clip_space = first_polygon + scene.polygons.len();
    let mut out = Coverage::new(target.width, target.height);

    // Lines: the whole line, scissored by the closed window.
    let point_mask = scene
        .clip
        .as_ref()
        .filter(|_| !lines.is_empty())
        .map(|w| ClipMask::for_points(w, target));
    draw_lines(&lines, triangles.len(), point_mask.as_ref(), target, &mut out);

    match model {
        Model::Exact | Model::ExactSnapped => {
            let snap_tri = |t: &Triangle| match model {
                Model::ExactSnapped => t.snapped(conv).to_exact(),
                _ => t.clone(),
            };
            let snap_poly = |p: &Polygon| match model {
                Model::ExactSnapped => p.snapped_exact(conv),
                _ => p.clone(),
            };
            for (k, t) in triangles.iter().enumerate() {
                let t = snap_tri(t);
                match &scene.clip {
                    None => crate::tri::exact::rasterize(&t, id(k), target, &mut out),
                    Some(w) => fill_clipped(
                        &Polygon::new(t.v.to_vec(), FillRule::NonZero),
                        w,
                        id(k),
                        target,
                        &mut out,
                    ),
                }
            }
            let polygons = scene
                .polygons
                .iter()
                .chain(clip_space_polygons(scene).iter())
                .map(snap_poly)
                .collect::<Vec<_>>();
            for (k, p) in polygons.iter().enumerate() {
                match &scene.clip {
                    None => rasterize_exact(p, id(first_polygon + k), target, &mut out),
                    Some(w) => fill_clipped(p, w, id(first_polygon + k), target, &mut out),
                }
            }
        }
        Model::Fixed | Model::Scanline => {
            let prepared = prepare(model, &triangles, conv)?;
            let mut polygons = prepare_polygons(model, &scene.polygons, conv)?;
            for (k, p) in clip_space_polygons(scene).iter().enumerate() {
                let one =
                    prepare_polygons(model, std::slice::from_ref(p), conv).map_err(|e| ModelError::ClipSpace {
                        triangle: k,
                        message: match e {
                            ModelError::PolygonEnvelope {
                                vertex, axis, error, ..
                            } => format!(
                                "window-space vertex {vertex} (after clipping and the viewport), {axis}: {error}"
                            ),
                            ModelError::Triangulate { error, .. } => format!("window-space polygon: {error}"),
                            other => other.to_string(),
                        },
                    })?;
                polygons.extend(one);
            }
            let fill_all = |sink: &mut dyn CoverageSink| {
                prepared.rasterize_into(target, sink);
                for (k, p) in polygons.iter().enumerate() {
                    p.fill(id(first_polygon + k), target, sink);
                }
            };
            match scene.clip.as_ref().map(|w| ClipMask::for_areas(w, target)) {
                Some(mask) => fill_all(&mut mask.scissor(&mut out)),
                None => fill_all(&mut out),
            }
        }
        Model::Float32 | Model::Float32Naive | Model::Float64 | Model::Float64Naive => {
            if !scene.polygons.is_empty() {
                return Err(ModelError::NoFloatPolygon { polygon: 0, model });
            }
            float_areas(model, scene, &triangles, first_clip_space, target, &mut out)?;
        }
    }
    Ok(out)
}

fn draw_lines(lines: &[PreparedLine], first: usize, mask: Option<&ClipMask>, target: &Target, out: &mut Coverage) {
    for (k, l) in lines.iter().enumerate() {
        match mask {
            None => l.draw(id(first + k), target, out),
            Some(m) => l.draw(id(first + k), target, &mut m.scissor(out)),
        }
    }
}

/// `p` clipped exactly against `w` (every contour), filled by the oracle.
fn fill_clipped<S: CoverageSink + ?Sized>(p: &Polygon, w: &Window, id: u32, target: &Target, sink: &mut S) {
    rasterize_exact(&clip_polygon(p, w), id, target, sink);
}

/// The float models' route in one float type: the window's half-planes, the triangles and
/// the clip-space triangles converted to it, clipped in it, filled as fans of float
/// triangles. Written once for f32 and f64 (the crate's float forms are concrete types).
macro_rules! float_areas_in {
    ($model:expr, $scene:expr, $triangles:expr, $first_clip_space:expr, $target:expr, $out:expr,
     to_float: $to_float:ident, clip: $clip:path, clip_to_window: $clip_to_window:path, rasterize: $rasterize:path) => {{
        let (model, scene, target): (Model, &Scene, &Target) = ($model, $scene, $target);
        let rule = match model {
            Model::Float32Naive | Model::Float64Naive => FloatRule::Naive,
            _ => FloatRule::TieRule,
        };
        let range = |what: String| ModelError::FloatScene { what, model };
        let planes = match &scene.clip {
            None => None,
            Some(w) => Some(
                w.half_planes()
                    .iter()
                    .map(|h| h.$to_float())
                    .collect::<Option<Vec<_>>>()
                    .ok_or_else(|| range("clip (a window edge's line coefficient)".into()))?,
            ),
        };
        let out: &mut Coverage = $out;
        let mut fill = |poly: Vec<_>, k: usize| {
            let poly = match &planes {
                Some(planes) => $clip(&poly, planes),
                None => poly,
            };
            for i in 1..poly.len().saturating_sub(1) {
                $rasterize(&[poly[0], poly[i], poly[i + 1]], id(k), target, rule, &mut *out);
            }
        };
        for (k, t) in $triangles.iter().enumerate() {
            let t = t.$to_float().ok_or(ModelError::FloatRange { triangle: k, model })?;
            fill(t.to_vec(), k);
        }
        let viewport = scene.viewport().$to_float().ok_or_else(|| range("viewport".into()))?;
        for (k, t) in scene.clip_space_triangles.iter().enumerate() {
            let vertices = t
                .iter()
                .map(|v| v.$to_float())
                .collect::<Option<Vec<_>>>()
                .ok_or_else(|| range(format!("clip_space_triangles[{k}]")))?;
            let window = $clip_to_window(&vertices, &viewport);
            fill(window.into_iter().map(|v| v.point).collect(), $first_clip_space + k);
        }
        Ok(())
    }};
}

/// The float models: triangles and clip-space triangles, clipped in the float type.
fn float_areas(
    model: Model,
    scene: &Scene,
    triangles: &[Triangle],
    first_clip_space: usize,
    target: &Target,
    out: &mut Coverage,
) -> Result<(), ModelError> {
    if matches!(model, Model::Float32 | Model::Float32Naive) {
        float_areas_in!(model, scene, triangles, first_clip_space, target, out,
            to_float: to_f32, clip: sutherland_hodgman::clip_f32,
            clip_to_window: homogeneous::clip_to_window_f32, rasterize: rasterize_f32)
    } else {
        float_areas_in!(model, scene, triangles, first_clip_space, target, out,
            to_float: to_f64, clip: sutherland_hodgman::clip_f64,
            clip_to_window: homogeneous::clip_to_window_f64, rasterize: rasterize_f64)
    }
}
