//! A scene's triangles in each model's input form, and their Gouraud shading in the
//! model's own arithmetic.

use glam::{DVec2, Vec2};
use image::RgbImage;
use num_rational::BigRational;

use crate::chunks;
use crate::convention::{Convention, Target};
use crate::coverage::{primitive_colour, Coverage, CoverageSink};
use crate::geom::{CompactTriangle, FixedTriangle, Rgb, Triangle};
use crate::interp::{barycentric_fixed, gouraud_exact, gouraud_f32, gouraud_f64, to_channel};
use crate::raster::{exact_sample_range, fixed_sample_range, float_sample_range, sample_exact, sample_f32, sample_f64};
use crate::tri::float::FloatRule;
use crate::tri::planned::PlannedTriangle;
use crate::tri::{exact, fixed, float, scanline};

use super::{point_f32, point_f64, Arithmetic, FloatType, IntegerTraversal, Model, ModelError};

/// A scene's triangles converted for one model (the conversion is where errors happen;
/// rasterizing prepared triangles cannot fail).
#[derive(Debug, Clone)]
pub(crate) enum PreparedTriangles {
    /// Exact triangles (as written, or snapped and converted back) for the plain oracle.
    Exact(Vec<Triangle>),
    /// The same exact triangles in compact form, each in its planned form, and the target
    /// they were planned for.
    Planned(Vec<CompactTriangle>, Vec<PlannedForm>, Target),
    /// Fixed-point triangles inside the envelope, for the block-traversal model.
    Fixed(Vec<FixedTriangle>),
    /// Fixed-point triangles for the scanline (edge-walking) model.
    Scanline(Vec<FixedTriangle>),
    /// f32 triangles and the float rule.
    F32(Vec<[Vec2; 3]>, FloatRule),
    /// f64 triangles and the float rule.
    F64(Vec<[DVec2; 3]>, FloatRule),
}

/// How the planned engine (`exact`, `exact-snapped`) draws one triangle: in the cheapest
/// exact form it has.
#[derive(Debug, Clone)]
pub(crate) enum PlannedForm {
    /// It covers nothing.
    Empty,
    /// Its vertices lie on the subpixel grid, inside the integer envelope: the integer
    /// engine draws it ([`fixed::rasterize`]). Snapping leaves such a triangle as it is, and the
    /// integer engines cover exactly the oracle's pixels of the snapped triangle, so
    /// exactly the oracle's pixels of this one; 56 bytes instead of a plan and its lanes.
    Grid(FixedTriangle),
    /// Set up in its planned width.
    Planned(Box<PlannedTriangle>),
}

impl PlannedForm {
    /// `tri`'s form for `target`.
    fn of(tri: &CompactTriangle, target: &Target) -> PlannedForm {
        if let Some(fixed) = tri.on_grid(&target.convention) {
            return PlannedForm::Grid(fixed);
        }
        match PlannedTriangle::from_compact(tri, target) {
            Some(p) => PlannedForm::Planned(Box::new(p)),
            None => PlannedForm::Empty,
        }
    }
}

/// Converts `triangles` for `model` on up to `jobs` threads; the first triangle it cannot
/// take is the error.
pub(crate) fn prepare_triangles(
    model: Model,
    triangles: &[CompactTriangle],
    target: &Target,
    jobs: usize,
) -> Result<PreparedTriangles, ModelError> {
    let conv = &target.convention;
    let at = |k: usize, i: usize| move || format!("triangles[{k}].v[{i}]");
    Ok(match model.arithmetic() {
        Arithmetic::Exact { snapped, plain } => {
            let exact: Vec<CompactTriangle> = if snapped {
                chunks::map(triangles, jobs, |_, t| t.snapped_exact(conv))
            } else {
                triangles.to_vec()
            };
            if plain {
                PreparedTriangles::Exact(chunks::map(&exact, jobs, |_, t| t.to_triangle()))
            } else {
                let planned = chunks::map(&exact, jobs, |_, t| PlannedForm::of(t, target));
                PreparedTriangles::Planned(exact, planned, *target)
            }
        }
        Arithmetic::Integer(IntegerTraversal::Blocks) => {
            PreparedTriangles::Fixed(fixed_triangles(triangles, conv, jobs)?)
        }
        Arithmetic::Integer(IntegerTraversal::Scanline) => {
            PreparedTriangles::Scanline(fixed_triangles(triangles, conv, jobs)?)
        }
        Arithmetic::Float(FloatType::F32, rule) => PreparedTriangles::F32(
            float_triangles(triangles, jobs, |v, k, i| point_f32(v, at(k, i), model))?,
            rule,
        ),
        Arithmetic::Float(FloatType::F64, rule) => PreparedTriangles::F64(
            float_triangles(triangles, jobs, |v, k, i| point_f64(v, at(k, i), model))?,
            rule,
        ),
    })
}

/// Every triangle converted vertex by vertex, `convert(vertex, triangle, index)`, on up to
/// `jobs` threads; the first error stops it.
fn float_triangles<V: Send + Default>(
    triangles: &[CompactTriangle],
    jobs: usize,
    convert: impl Fn(&crate::geom::Point, usize, usize) -> Result<V, ModelError> + Sync,
) -> Result<Vec<[V; 3]>, ModelError> {
    chunks::try_map(triangles, jobs, |k, t| {
        let t = t.to_triangle();
        Ok([
            convert(&t.v[0], k, 0)?,
            convert(&t.v[1], k, 1)?,
            convert(&t.v[2], k, 2)?,
        ])
    })
}

/// Snaps every triangle and checks it against the integer envelope, on up to `jobs`
/// threads.
fn fixed_triangles(
    triangles: &[CompactTriangle],
    conv: &Convention,
    jobs: usize,
) -> Result<Vec<FixedTriangle>, ModelError> {
    chunks::try_map(triangles, jobs, |k, t| {
        t.to_fixed(conv).map_err(|(vertex, axis, error)| ModelError::Envelope {
            triangle: k,
            vertex,
            axis,
            error,
        })
    })
}

/// Which triangles a band's thread draws ([`PreparedTriangles::meeting_each`]): their
/// indices, ascending, those whose rows meet the band's.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Band<'a> {
    /// The triangles' indices, ascending.
    pub(crate) triangles: &'a [u32],
}

/// The rows a prepared triangle's engine visits, `first..=last` (`None`: it covers
/// nothing): the sample range of its vertices, found by the function its engine finds its
/// own range with, so a triangle skipped by a band has no pixel in it.
trait Rows {
    fn rows(&self, target: &Target) -> Option<(u32, u32)>;
}

impl Rows for Triangle {
    fn rows(&self, target: &Target) -> Option<(u32, u32)> {
        exact_sample_range(self.v.iter(), target).map(|r| (r.y0, r.y1))
    }
}

impl Rows for PlannedForm {
    fn rows(&self, target: &Target) -> Option<(u32, u32)> {
        match self {
            PlannedForm::Empty => None,
            PlannedForm::Grid(t) => t.rows(target),
            PlannedForm::Planned(p) => Some(p.rows()),
        }
    }
}

impl Rows for FixedTriangle {
    fn rows(&self, target: &Target) -> Option<(u32, u32)> {
        fixed_sample_range(self.coords().into_iter(), target).map(|r| (r.y0, r.y1))
    }
}

impl Rows for [Vec2; 3] {
    fn rows(&self, target: &Target) -> Option<(u32, u32)> {
        let (min, max) = (self[0].min(self[1]).min(self[2]), self[0].max(self[1]).max(self[2]));
        let wide = |v: Vec2| [f64::from(v.x), f64::from(v.y)];
        float_sample_range(wide(min), wide(max), target).map(|r| (r.y0, r.y1))
    }
}

impl Rows for [DVec2; 3] {
    fn rows(&self, target: &Target) -> Option<(u32, u32)> {
        let (min, max) = (self[0].min(self[1]).min(self[2]), self[0].max(self[1]).max(self[2]));
        float_sample_range(min.to_array(), max.to_array(), target).map(|r| (r.y0, r.y1))
    }
}

/// The exact Gouraud colour of `t` at pixel `(x, y)`'s sample, as 8-bit channels (black
/// for a degenerate triangle).
fn shade_exact(t: &Triangle, colours: &[Rgb; 3], x: u32, y: u32, target: &Target) -> Rgb {
    gouraud_exact(t, colours, &sample_exact(x, y, target)).map_or([0; 3], |c| c.each_ref().map(to_channel))
}

/// Triangle ids are their indices.
#[inline]
fn id_of(k: usize) -> u32 {
    u32::try_from(k).expect("scene triangle counts fit u32")
}

impl PreparedTriangles {
    /// The exact triangles of the exact models (plain or planned), for exact clipping.
    pub(crate) fn exact_triangles(&self) -> Option<Vec<Triangle>> {
        match self {
            PreparedTriangles::Exact(ts) => Some(ts.clone()),
            PreparedTriangles::Planned(ts, _, _) => Some(ts.iter().map(CompactTriangle::to_triangle).collect()),
            _ => None,
        }
    }

    /// Triangle `k`'s plan, for the planned engine (`None` otherwise, or when it covers
    /// nothing): the planner's verdict on it, also for a triangle the integer engine draws
    /// (set up again here).
    pub(crate) fn plan(&self, k: usize) -> Option<crate::num::plan::Plan> {
        match self {
            PreparedTriangles::Planned(ts, forms, target) => match &forms[k] {
                PlannedForm::Empty => None,
                PlannedForm::Grid(_) => PlannedTriangle::from_compact(&ts[k], target).map(|p| p.plan().clone()),
                PlannedForm::Planned(p) => Some(p.plan().clone()),
            },
            _ => None,
        }
    }

    /// How many triangles.
    pub(crate) fn len(&self) -> usize {
        match self {
            PreparedTriangles::Exact(ts) => ts.len(),
            PreparedTriangles::Planned(ts, _, _) => ts.len(),
            PreparedTriangles::Fixed(ts) | PreparedTriangles::Scanline(ts) => ts.len(),
            PreparedTriangles::F32(ts, _) => ts.len(),
            PreparedTriangles::F64(ts, _) => ts.len(),
        }
    }

    /// Rasterizes every triangle whole into `sink`, triangle k with id k.
    pub(crate) fn rasterize_into<S: CoverageSink + ?Sized>(&self, target: &Target, sink: &mut S) {
        self.rasterize_each(target, sink, None, || {});
    }

    /// Rasterizes every triangle whole into `sink`, triangle k with id k, calling `after`
    /// once each is drawn. With `band` only the band's triangles are drawn (and `after` is
    /// not called): the sink of a band keeps only the band's rows, so a triangle whose rows
    /// ([`Rows`]) miss them would add nothing. The model is matched once, outside the
    /// loop, and `after` is inlined: with a match and an indirect call per triangle,
    /// `fixed` on the peer bench's 100k small triangles took 5.23-5.44 ms against
    /// 4.75-4.83 ms (three runs).
    pub(crate) fn rasterize_each<S: CoverageSink + ?Sized, F: FnMut()>(
        &self,
        target: &Target,
        sink: &mut S,
        band: Option<Band<'_>>,
        mut after: F,
    ) {
        // One loop per model, each calling `draw(triangle, id)` then `after`.
        fn each<T, F: FnMut()>(ts: &[T], band: Option<Band<'_>>, mut draw: impl FnMut(&T, u32), after: &mut F) {
            match band {
                None => {
                    for (k, t) in ts.iter().enumerate() {
                        draw(t, id_of(k));
                        after();
                    }
                }
                Some(band) => {
                    for &k in band.triangles {
                        draw(&ts[k as usize], k);
                    }
                }
            }
        }
        match self {
            PreparedTriangles::Exact(ts) => each(ts, band, |t, id| exact::rasterize(t, id, target, sink), &mut after),
            PreparedTriangles::Planned(_, ts, _) => each(
                ts,
                band,
                |t, id| match t {
                    PlannedForm::Empty => {}
                    PlannedForm::Grid(t) => fixed::rasterize(t, id, target, sink),
                    PlannedForm::Planned(t) => t.rasterize(id, sink),
                },
                &mut after,
            ),
            PreparedTriangles::Fixed(ts) => each(ts, band, |t, id| fixed::rasterize(t, id, target, sink), &mut after),
            PreparedTriangles::Scanline(ts) => {
                each(ts, band, |t, id| scanline::rasterize(t, id, target, sink), &mut after);
            }
            PreparedTriangles::F32(ts, rule) => {
                each(
                    ts,
                    band,
                    |t, id| float::rasterize_f32(t, id, target, *rule, sink),
                    &mut after,
                );
            }
            PreparedTriangles::F64(ts, rule) => {
                each(
                    ts,
                    band,
                    |t, id| float::rasterize_f64(t, id, target, *rule, sink),
                    &mut after,
                );
            }
        }
    }

    /// For each of `bands` (rows `y0..y1`, consecutive from row 0, in order), the indices
    /// of the triangles whose rows ([`Rows`]) meet it, ascending: each triangle's rows
    /// found once, on up to `jobs` threads, for every band of a parallel render.
    pub(crate) fn meeting_each(&self, target: &Target, jobs: usize, bands: &[(u32, u32)]) -> Vec<Vec<u32>> {
        fn all<T: Rows + Sync>(ts: &[T], target: &Target, jobs: usize, bands: &[(u32, u32)]) -> Vec<Vec<u32>> {
            // Runs of triangles, each giving its lists per band; a band's list is its
            // lists of the runs in turn.
            let runs: Vec<(usize, usize)> = {
                let count = jobs.max(1).saturating_mul(4).min(ts.len().max(1));
                (0..count)
                    .map(|r| (ts.len() * r / count, ts.len() * (r + 1) / count))
                    .collect()
            };
            let band_of = |row: u32| bands.partition_point(|&(_, y1)| y1 <= row).min(bands.len() - 1);
            let lists = chunks::map(&runs, jobs, |_, &(from, to)| {
                let mut lists = vec![Vec::new(); bands.len()];
                for (k, t) in (from..).zip(&ts[from..to]) {
                    if let Some((first, last)) = t.rows(target).filter(|(first, last)| first <= last) {
                        for list in &mut lists[band_of(first)..=band_of(last)] {
                            list.push(id_of(k));
                        }
                    }
                }
                lists
            });
            (0..bands.len())
                .map(|b| lists.iter().flat_map(|run| run[b].iter().copied()).collect())
                .collect()
        }
        if bands.is_empty() {
            return Vec::new();
        }
        match self {
            PreparedTriangles::Exact(ts) => all(ts, target, jobs, bands),
            PreparedTriangles::Planned(_, ts, _) => all(ts, target, jobs, bands),
            PreparedTriangles::Fixed(ts) | PreparedTriangles::Scanline(ts) => all(ts, target, jobs, bands),
            PreparedTriangles::F32(ts, _) => all(ts, target, jobs, bands),
            PreparedTriangles::F64(ts, _) => all(ts, target, jobs, bands),
        }
    }

    /// The Gouraud colour of triangle `k` at the sample of pixel `(x, y)`, computed in the
    /// model's own arithmetic (exact rationals; exact integer edge values over twice the
    /// area for the integer models; f32 / f64 barycentrics for the float models).
    pub(crate) fn shade(&self, k: usize, colours: &[Rgb; 3], x: u32, y: u32, target: &Target) -> Rgb {
        match self {
            PreparedTriangles::Exact(ts) => shade_exact(&ts[k], colours, x, y, target),
            PreparedTriangles::Planned(ts, _, _) => shade_exact(&ts[k].to_triangle(), colours, x, y, target),
            PreparedTriangles::Fixed(ts) | PreparedTriangles::Scanline(ts) => {
                let b = barycentric_fixed(&ts[k], x, y, target);
                if b.area2 == 0 {
                    return [0; 3];
                }
                std::array::from_fn(|ch| {
                    let sum: i128 = (0..3).map(|i| b.w[i] * i128::from(colours[i][ch])).sum();
                    to_channel(&BigRational::new(sum.into(), b.area2.into()))
                })
            }
            PreparedTriangles::F32(ts, _) => gouraud_f32(&ts[k], colours, sample_f32(x, y, target)).unwrap_or([0; 3]),
            PreparedTriangles::F64(ts, _) => gouraud_f64(&ts[k], colours, sample_f64(x, y, target)).unwrap_or([0; 3]),
        }
    }

    /// The interpolated-colour picture: each covered pixel takes the colour of its
    /// highest-numbered (last drawn) primitive; a triangle without colours, or any other
    /// primitive, shows its coverage colour.
    pub(crate) fn colour_image(&self, coverage: &Coverage, colours: &[Option<[Rgb; 3]>], target: &Target) -> RgbImage {
        let mut img = RgbImage::new(target.width, target.height);
        // The planned engine keeps its triangles compact: the exact triangle of the last
        // one shaded is kept, not rebuilt at every pixel (a row's pixels mostly share one).
        let mut exact: Option<(usize, Triangle)> = None;
        for (x, y, ids) in coverage.iter() {
            let Some(&top) = ids.last() else { continue };
            let k = top as usize;
            let rgb = match (colours.get(k).copied().flatten(), self) {
                (Some(c), PreparedTriangles::Planned(ts, _, _)) if k < ts.len() => {
                    let t = match exact.take() {
                        Some((j, t)) if j == k => t,
                        _ => ts[k].to_triangle(),
                    };
                    let rgb = shade_exact(&t, &c, x, y, target);
                    exact = Some((k, t));
                    rgb
                }
                (Some(c), _) if k < self.len() => self.shade(k, &c, x, y, target),
                _ => primitive_colour(top),
            };
            img.put_pixel(x, y, image::Rgb(rgb));
        }
        img
    }
}
