//! A scene's primitives prepared for one model, ids assigned once, and drawn.

use image::RgbImage;

use crate::clip::arithmetic::{ClipArithmetic, Clipper};
use crate::clip::homogeneous::{ClipVertex, Viewport};
use crate::clip::mask::ClipMask;
use crate::clip::sutherland_hodgman::clip_polygon;
use crate::clip::Window;
use crate::convention::Target;
use crate::coverage::{Coverage, CoverageSink, IdRun, RowBand, Spare, TILE};
use crate::geom::{CompactTriangle, FillRule, Polygon, Rgb, Triangle};
use crate::line::Line;

use super::lines::{prepare_lines, PreparedLine};
use super::plan::PrimitivePlan;
use super::polygons::{prepare_clip_space, prepare_polygon, PreparedPolygon};
use super::triangles::{prepare_triangles, Band, PreparedTriangles};
use super::{Arithmetic, FloatType, Model, ModelError};

/// What a scene draws, every coordinate exact. Ids follow one sequence: triangles `0..`,
/// then lines, then polygons, then clip-space triangles, each in list order.
/// [`crate::scene::Scene::primitives`] gives a scene file's.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Primitives {
    /// Window-space triangles, in compact form (each exact, 96 bytes when its
    /// coordinates are small).
    pub triangles: Vec<CompactTriangle>,
    /// Lines (Bresenham or diamond-exit).
    pub lines: Vec<Line>,
    /// Polygons with holes and a fill rule.
    pub polygons: Vec<Polygon>,
    /// Clip-space `(x, y, z, w)` triangles: clipped against the view volume, divided and
    /// mapped through `viewport`.
    pub clip_space_triangles: Vec<[ClipVertex; 3]>,
    /// The viewport of the clip-space triangles (needed when there are any).
    pub viewport: Option<Viewport>,
    /// The window every primitive is clipped against before rasterization.
    pub clip: Option<Window>,
}

impl Primitives {
    /// Just these triangles.
    pub fn from_triangles(triangles: &[Triangle]) -> Primitives {
        Primitives {
            triangles: triangles.iter().map(CompactTriangle::from).collect(),
            ..Primitives::default()
        }
    }

    /// The primitive kinds in id order, named as a scene file's fields, with their
    /// counts: what the coverage picture's legend names each id by.
    pub fn id_runs(&self) -> [IdRun<'static>; 4] {
        let run = |name, count| IdRun { name, count };
        [
            run("triangles", self.triangles.len()),
            run("lines", self.lines.len()),
            run("polygons", self.polygons.len()),
            run("clip_space_triangles", self.clip_space_triangles.len()),
        ]
    }

    /// The id of the first line, polygon and clip-space triangle.
    fn first_ids(&self) -> [usize; 3] {
        let line = self.triangles.len();
        let polygon = line + self.lines.len();
        [line, polygon, polygon + self.polygons.len()]
    }
}

/// A primitive's exact window-space geometry as an exact model rasterizes it (snapped for
/// `exact-snapped`, clipped against the scene's window where the model clips): what
/// [`crate::oracle`] explains a pixel with. [`PreparedScene::shapes`] gives them.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Shape {
    /// A triangle, drawn by the edge-function oracle.
    Triangle(Triangle),
    /// A polygon (a scene polygon, a triangle clipped against the window, or a clip-space
    /// triangle's window-space polygon), drawn by the winding-number oracle.
    Polygon(Polygon),
    /// A Bresenham line between two pixel addresses.
    Bresenham {
        /// The first pixel.
        from: [i64; 2],
        /// The last pixel.
        to: [i64; 2],
        /// Who wins a tie.
        tie: crate::line::BresenhamTie,
    },
    /// A diamond-exit line between two exact window-space points. With a clip window its
    /// pixels are kept where their sample lies in the closed window.
    Diamond {
        /// Start.
        from: crate::geom::Point,
        /// End.
        to: crate::geom::Point,
    },
}

/// A scene converted for one model: every conversion done, nothing left that can fail.
/// Built by [`prepare`]; [`PreparedScene::render`] rasterizes it into any sink.
#[derive(Debug, Clone)]
pub struct PreparedScene {
    model: Model,
    /// The triangles in the model's form, unclipped (drawn when `clipped_triangles` is
    /// `None`, and shaded for the colour picture).
    triangles: PreparedTriangles,
    /// Exact and float models with a window: each triangle clipped to a polygon (id = index).
    clipped_triangles: Option<Vec<PreparedPolygon>>,
    lines: Vec<PreparedLine>,
    /// The scene's polygons, then the clip-space triangles' window-space polygons
    /// (clipped already where the model clips geometry).
    polygons: Vec<PreparedPolygon>,
    /// Integer models with a window: `raster(W)`, applied to every area.
    area_mask: Option<ClipMask>,
    /// Lines with a window: the closed window's pixels.
    point_mask: Option<ClipMask>,
    first_line: usize,
    first_polygon: usize,
    /// How many of `polygons` are the scene's own (the rest are clip-space triangles).
    scene_polygons: usize,
}

/// The bands of a parallel render of a canvas `height` rows high on `jobs` threads: rows
/// `y0..y1`, whole 64-row tiles (the last may end at the height), up to four per thread
/// so that a thread that finishes early takes another.
fn bands(height: u32, jobs: usize) -> Vec<(u32, u32)> {
    if jobs <= 1 {
        return vec![(0, height)];
    }
    bands_of(height, jobs.saturating_mul(4))
}

/// The most pixels in one band of [`PreparedScene::visit_bands`]: 2^23, 32 MiB of
/// coverage slots. Each thread's first band is memory the system maps and zeroes; the
/// next ones reuse it.
const BAND_PIXELS: u64 = 1 << 23;

/// The bands of [`PreparedScene::visit_bands`] on `target`: as [`bands`], and more where
/// a band would hold over [`BAND_PIXELS`] pixels (on one thread too).
fn visited_bands(target: &Target, jobs: usize) -> Vec<(u32, u32)> {
    let pixels = u64::from(target.width) * u64::from(target.height);
    let by_memory = usize::try_from(pixels.div_ceil(BAND_PIXELS)).unwrap_or(usize::MAX);
    let by_jobs = if jobs <= 1 { 1 } else { jobs.saturating_mul(4) };
    bands_of(target.height, by_memory.max(by_jobs))
}

/// Rows `0..height` cut into up to `count` bands of whole 64-row tiles (as even as the
/// tiles allow; fewer when there are fewer tile rows).
fn bands_of(height: u32, count: usize) -> Vec<(u32, u32)> {
    let tile_rows = height.div_ceil(TILE);
    let count = u32::try_from(count).unwrap_or(u32::MAX).clamp(1, tile_rows.max(1));
    (0..count)
        .map(|b| {
            let first = tile_rows * b / count * TILE;
            let end = (tile_rows * (b + 1) / count * TILE).min(height);
            (first, end)
        })
        .filter(|(a, b)| a < b)
        .collect()
}

/// Ids are positions in one sequence.
fn id(k: usize) -> u32 {
    u32::try_from(k).expect("scene primitive counts fit u32")
}

/// Converts every primitive of `primitives` for `model` on `target`.
///
/// # Errors
/// The first primitive the model cannot take: a coordinate outside the integer envelope
/// or the float type, a polygon the `fixed` model cannot triangulate, clip-space
/// triangles without a viewport. Lines are checked first, then the areas.
pub fn prepare(primitives: &Primitives, target: &Target, model: Model) -> Result<PreparedScene, ModelError> {
    prepare_parallel(primitives, target, model, 1)
}

/// [`prepare`] with the triangles converted on up to `jobs` threads (consecutive
/// triangles on each, [`crate::chunks`]): the same prepared scene, and the same first
/// error, as one thread's.
///
/// # Errors
/// As [`prepare`].
pub fn prepare_parallel(
    primitives: &Primitives,
    target: &Target,
    model: Model,
    jobs: usize,
) -> Result<PreparedScene, ModelError> {
    let lines = prepare_lines(model, &primitives.lines, target)?;
    let viewport = || primitives.viewport.as_ref().ok_or(ModelError::NoViewport);
    let [first_line, first_polygon, _] = primitives.first_ids();
    let point_mask = primitives
        .clip
        .as_ref()
        .filter(|_| !lines.is_empty())
        .map(|w| ClipMask::for_points(w, target));
    let mut scene = PreparedScene {
        model,
        triangles: PreparedTriangles::Exact(Vec::new()),
        clipped_triangles: None,
        lines,
        polygons: Vec::new(),
        area_mask: None,
        point_mask,
        first_line,
        first_polygon,
        scene_polygons: primitives.polygons.len(),
    };
    match model.arithmetic() {
        Arithmetic::Exact { .. } | Arithmetic::Integer(_) => {
            scene.triangles = prepare_triangles(model, &primitives.triangles, target, jobs)?;
            for (k, p) in primitives.polygons.iter().enumerate() {
                scene.polygons.push(prepare_polygon(model, k, p, target)?);
            }
            if !primitives.clip_space_triangles.is_empty() {
                let viewport = viewport()?;
                for (k, t) in primitives.clip_space_triangles.iter().enumerate() {
                    scene.polygons.push(prepare_clip_space(model, k, t, viewport, target)?);
                }
            }
            if let Some(w) = &primitives.clip {
                if let (Some(ts), Arithmetic::Exact { plain, .. }) =
                    (scene.triangles.exact_triangles(), model.arithmetic())
                {
                    let whole = |t: &Triangle| Polygon::new(t.v.to_vec(), FillRule::NonZero);
                    let clip = |p: &Polygon| PreparedPolygon::exact(clip_polygon(p, w), plain, target);
                    scene.clipped_triangles = Some(ts.iter().map(|t| clip(&whole(t))).collect());
                    for p in &mut scene.polygons {
                        if let Some(poly) = p.exact_polygon() {
                            *p = clip(poly);
                        }
                    }
                } else {
                    scene.area_mask = Some(ClipMask::for_areas(w, target));
                }
            }
        }
        Arithmetic::Float(float, rule) => match float {
            FloatType::F32 => prepare_float_f32(&mut scene, primitives, rule, target, viewport, jobs)?,
            FloatType::F64 => prepare_float_f64(&mut scene, primitives, rule, target, viewport, jobs)?,
        },
    }
    Ok(scene)
}

/// The float models' areas in one float type: the window's [`Clipper`] in that type, the
/// triangles, polygons and clip-space triangles converted to it and clipped in it
/// (Sutherland-Hodgman on every contour, [`Clipper::contour_f32`] / `_f64`), triangles and
/// clip-space pieces kept as fans. Written once for f32 and f64 (the crate's float forms
/// are concrete types).
macro_rules! prepare_float_in {
    ($name:ident, $arithmetic:expr, $to_float:ident, $contour:ident, $clip_space:ident, $triangles:ident, $fan:ident, $polygon:ident) => {
        fn $name<'a>(
            scene: &mut PreparedScene,
            primitives: &'a Primitives,
            rule: crate::tri::float::FloatRule,
            target: &Target,
            viewport: impl Fn() -> Result<&'a Viewport, ModelError>,
            jobs: usize,
        ) -> Result<(), ModelError> {
            let model = scene.model;
            let range = |what: String| ModelError::FloatScene { what, model };
            let clipper = Clipper::new($arithmetic, primitives.clip.as_ref())
                .map_err(|_| range("clip (a window edge's line coefficient)".into()))?;
            let window = primitives.clip.is_some();
            scene.triangles = prepare_triangles(model, &primitives.triangles, target, jobs)?;
            if let (true, PreparedTriangles::$triangles(ts, _)) = (window, &scene.triangles) {
                let fans = ts
                    .iter()
                    .map(|t| PreparedPolygon::$fan(clipper.$contour(t), rule));
                scene.clipped_triangles = Some(fans.collect());
            }
            for (k, p) in primitives.polygons.iter().enumerate() {
                let mut prepared = prepare_polygon(model, k, p, target)?;
                if let (true, PreparedPolygon::$polygon(poly, _)) = (window, &mut prepared) {
                    poly.outline = clipper.$contour(&poly.outline);
                    for hole in &mut poly.holes {
                        *hole = clipper.$contour(hole);
                    }
                }
                scene.polygons.push(prepared);
            }
            if !primitives.clip_space_triangles.is_empty() {
                let viewport = viewport()?.$to_float().ok_or_else(|| range("viewport".into()))?;
                for (k, t) in primitives.clip_space_triangles.iter().enumerate() {
                    let vertices = t
                        .iter()
                        .map(|v| v.$to_float())
                        .collect::<Option<Vec<_>>>()
                        .ok_or_else(|| range(format!("clip_space_triangles[{k}]")))?;
                    let window_space = clipper.$clip_space(&vertices, &viewport);
                    scene.polygons.push(PreparedPolygon::$fan(window_space, rule));
                }
            }
            Ok(())
        }
    };
}

prepare_float_in!(
    prepare_float_f32,
    ClipArithmetic::F32,
    to_f32,
    contour_f32,
    clip_space_f32,
    F32,
    Fan32,
    Float32
);
prepare_float_in!(
    prepare_float_f64,
    ClipArithmetic::F64,
    to_f64,
    contour_f64,
    clip_space_f64,
    F64,
    Fan64,
    Float64
);

impl PreparedScene {
    /// The model it was prepared for.
    pub fn model(&self) -> Model {
        self.model
    }

    /// Rasterizes every primitive into `sink` with its id.
    pub fn render<S: CoverageSink + ?Sized>(&self, target: &Target, sink: &mut S) {
        self.render_observed(target, sink, || {});
    }

    /// How many primitives [`PreparedScene::render_observed`] draws (the clipped triangles
    /// count as their triangles).
    pub fn primitive_count(&self) -> usize {
        let triangles = self.clipped_triangles.as_ref().map_or(self.triangles.len(), Vec::len);
        self.lines.len() + triangles + self.polygons.len()
    }

    /// Whether a band of [`PreparedScene::coverage_parallel`] or
    /// [`PreparedScene::visit_bands`] draws only the primitives that meet its rows: every
    /// primitive is a triangle drawn unclipped (the integer models, or no clip window).
    /// Lines, polygons and triangles clipped to polygons are drawn whole by every band,
    /// which keeps its own rows of them, so many bands cost them many times.
    pub fn bands_skip_all(&self) -> bool {
        self.lines.is_empty() && self.polygons.is_empty() && self.clipped_triangles.is_none()
    }

    /// [`PreparedScene::render`], calling `after` once each primitive is drawn (a progress
    /// bar's tick: `render` shows one when a run goes on for more than a second).
    pub fn render_observed<S: CoverageSink + ?Sized, F: FnMut()>(&self, target: &Target, sink: &mut S, after: F) {
        self.render_band(target, sink, None, after);
    }

    /// Draws into `sink` what a sink of rows `band` (`y0..y1`, [`RowBand`]) keeps: every
    /// primitive, except the triangles whose rows miss the band (`None`: no band).
    fn render_band<S: CoverageSink + ?Sized, F: FnMut()>(
        &self,
        target: &Target,
        sink: &mut S,
        band: Option<Band<'_>>,
        mut after: F,
    ) {
        for (k, l) in self.lines.iter().enumerate() {
            let k = id(self.first_line + k);
            match &self.point_mask {
                None => l.rasterize(k, target, sink),
                Some(m) => l.rasterize(k, target, &mut m.scissor(sink)),
            }
            after();
        }
        match &self.area_mask {
            None => self.render_areas(target, sink, band, &mut after),
            Some(m) => self.render_areas(target, &mut m.scissor(sink), band, &mut after),
        }
    }

    fn render_areas<S: CoverageSink + ?Sized, F: FnMut()>(
        &self,
        target: &Target,
        sink: &mut S,
        band: Option<Band<'_>>,
        after: &mut F,
    ) {
        match &self.clipped_triangles {
            None => self.triangles.rasterize_each(target, sink, band, &mut *after),
            Some(polygons) => {
                for (k, p) in polygons.iter().enumerate() {
                    p.fill(id(k), target, sink);
                    after();
                }
            }
        }
        for (k, p) in self.polygons.iter().enumerate() {
            p.fill(id(self.first_polygon + k), target, sink);
            after();
        }
    }

    /// Every primitive's plan, in id order (see [`crate::model::plan`]): the triangles
    /// (clipped ones as their clipped polygons), then the lines, the polygons and the
    /// clip-space triangles.
    pub fn plans(&self) -> Vec<PrimitivePlan> {
        let mut out = Vec::new();
        match &self.clipped_triangles {
            None => {
                for k in 0..self.triangles.len() {
                    out.push(PrimitivePlan {
                        kind: "triangle",
                        index: k,
                        id: id(k),
                        plan: self.triangles.plan(k),
                        unplanned: None,
                    });
                }
            }
            Some(polygons) => {
                for (k, p) in polygons.iter().enumerate() {
                    out.push(PrimitivePlan {
                        kind: "clipped triangle",
                        index: k,
                        id: id(k),
                        plan: p.plan().cloned(),
                        unplanned: None,
                    });
                }
            }
        }
        for (k, l) in self.lines.iter().enumerate() {
            out.push(PrimitivePlan {
                kind: "line",
                index: k,
                id: id(self.first_line + k),
                plan: l.plan().cloned(),
                unplanned: l.is_bresenham().then_some(super::plan::BRESENHAM),
            });
        }
        for (k, p) in self.polygons.iter().enumerate() {
            let (kind, index) = if k < self.scene_polygons {
                ("polygon", k)
            } else {
                ("clip-space triangle", k - self.scene_polygons)
            };
            out.push(PrimitivePlan {
                kind,
                index,
                id: id(self.first_polygon + k),
                plan: p.plan().cloned(),
                unplanned: None,
            });
        }
        for p in out.iter_mut().filter(|p| p.plan.is_none()) {
            p.unplanned = p.unplanned.or(Some(super::plan::COVERS_NO_PIXEL));
        }
        out
    }

    /// Every primitive's exact geometry, in id order (index = id), read from the very
    /// form the model draws; `None` unless the model is exact ([`Model::is_exact`]).
    /// Bresenham lines keep their pixel endpoints; a window clips the areas (the
    /// triangles become polygons) and keeps the lines' pixels whose samples lie in it.
    pub fn shapes(&self) -> Option<Vec<Shape>> {
        let mut out = Vec::with_capacity(self.primitive_count());
        match &self.clipped_triangles {
            None => out.extend(self.triangles.exact_triangles()?.into_iter().map(Shape::Triangle)),
            Some(polygons) => {
                for p in polygons {
                    out.push(Shape::Polygon(p.exact_polygon()?.clone()));
                }
            }
        }
        for l in &self.lines {
            out.push(l.exact_shape()?);
        }
        for p in &self.polygons {
            out.push(Shape::Polygon(p.exact_polygon()?.clone()));
        }
        Some(out)
    }

    /// A fresh [`Coverage`] of `target` with everything drawn.
    pub fn coverage(&self, target: &Target) -> Coverage {
        let mut coverage = Coverage::new(target.width, target.height);
        self.render(target, &mut coverage);
        coverage
    }

    /// [`PreparedScene::coverage`] drawn by `jobs` threads, bit for bit the same: the canvas
    /// is cut into bands of whole 64-row tiles (up to four per thread, taken in turn), each
    /// band drawn by one thread into a coverage of its own through a [`RowBand`] sink (every
    /// primitive in id order, but the triangles whose rows miss the band), then the bands'
    /// tiles are moved into one coverage. A pixel's owners are added by the same primitives
    /// in the same order in its band as on one thread. `after` is called once each band is
    /// drawn (`band_count` of them).
    pub fn coverage_parallel(&self, target: &Target, jobs: usize, after: &(dyn Fn() + Sync)) -> Coverage {
        let bands = bands(target.height, jobs);
        if bands.len() <= 1 {
            let coverage = self.coverage(target);
            after();
            return coverage;
        }
        let drawn = self.draw_bands(target, jobs, &bands, after, |_, coverage, _| coverage);
        let mut coverage = Coverage::new(target.width, target.height);
        for (band, &(y0, y1)) in drawn.into_iter().zip(&bands) {
            coverage.absorb_rows(band, y0, y1);
        }
        coverage
    }

    /// How many bands [`PreparedScene::coverage_parallel`] cuts `target` into for `jobs`.
    pub fn band_count(target: &Target, jobs: usize) -> usize {
        bands(target.height, jobs).len()
    }

    /// Draws the frame a band of rows at a time on `jobs` threads and hands each band to
    /// `visit` as rows `y0..y1` and a [`Coverage`] of the whole canvas that covers nothing
    /// outside them, what [`PreparedScene::coverage`] covers in those rows (the owners in
    /// the same order); returns what `visit` returns, in band order. For what needs no
    /// whole coverage at once (counts, checks, rows written out in turn): a thread draws
    /// its next band into the memory of the last, so a frame holds about `jobs` bands of
    /// coverage at a time instead of its whole canvas.
    ///
    /// The bands are whole 64-row tiles, at most 2^23 pixels each (32 MiB of coverage)
    /// and, on several threads, at least four per thread; `after` is called once each band
    /// is visited ([`PreparedScene::visited_band_count`] of them).
    ///
    /// ```
    /// use rasterproof::model::{prepare, Model};
    /// use rasterproof::scene::parse_scene;
    /// let scene = parse_scene(
    ///     r#"{"width": 256, "height": 256, "triangles": [
    ///         {"v": [[0, 0], [256, 0], [0, 256]]}, {"v": [[0, 0], [128, 0], [0, 128]]}]}"#,
    ///     "two.json",
    /// )
    /// .unwrap();
    /// let target = scene.target().unwrap();
    /// let prepared = prepare(&scene.primitives(), &target, Model::Fixed).unwrap();
    /// let counts = prepared.visit_bands(&target, 2, |_, _, band| (band.covered_pixels(), band.double_covered().count()), &|| {});
    /// assert_eq!(counts.len(), 4);
    /// // The big triangle covers the pixels whose centres (x + 1/2, y + 1/2) lie inside
    /// // its diagonal x + y = 256 (a centre on it is on the bottom-right edge, which the
    /// // top-left rule leaves out): x + y <= 254, 255 * 256 / 2 of them...
    /// let covered: usize = counts.iter().map(|c| c.0).sum();
    /// assert_eq!(covered, 255 * 256 / 2);
    /// // ...of which the small one covers those with x + y <= 126 again.
    /// let double: usize = counts.iter().map(|c| c.1).sum();
    /// assert_eq!(double, 127 * 128 / 2);
    /// ```
    pub fn visit_bands<R: Send>(
        &self,
        target: &Target,
        jobs: usize,
        visit: impl Fn(u32, u32, &Coverage) -> R + Sync,
        after: &(dyn Fn() + Sync),
    ) -> Vec<R> {
        let bands = visited_bands(target, jobs);
        if bands.len() <= 1 {
            let r = visit(0, target.height, &self.coverage(target));
            after();
            return vec![r];
        }
        self.draw_bands(target, jobs, &bands, after, |b, coverage, spare| {
            let (y0, y1) = bands[b];
            let r = visit(y0, y1, &coverage);
            *spare = coverage.into_spare();
            r
        })
    }

    /// How many bands [`PreparedScene::visit_bands`] cuts `target` into for `jobs`.
    pub fn visited_band_count(target: &Target, jobs: usize) -> usize {
        visited_bands(target, jobs).len()
    }

    /// Draws `bands` (two or more) on up to `jobs` threads, each band through a
    /// [`RowBand`] into a coverage of its own that takes the tiles its thread's last band
    /// left in the spare; `finish` turns band `b`'s coverage into what is kept, and may
    /// leave tiles in the spare. What is kept, in band order.
    fn draw_bands<R: Send>(
        &self,
        target: &Target,
        jobs: usize,
        bands: &[(u32, u32)],
        after: &(dyn Fn() + Sync),
        finish: impl Fn(usize, Coverage, &mut Spare) -> R + Sync,
    ) -> Vec<R> {
        let meeting = self.triangles.meeting_each(target, jobs, bands);
        let each: Vec<(usize, &(u32, u32))> = bands.iter().enumerate().collect();
        crate::chunks::map_each_with(each, jobs, Spare::default, |spare, (b, &(y0, y1))| {
            let mut coverage = Coverage::with_spare(target.width, target.height, std::mem::take(spare));
            let band = Band { triangles: &meeting[b] };
            self.render_band(target, &mut RowBand::new(&mut coverage, y0, y1), Some(band), || {});
            let kept = finish(b, coverage, spare);
            after();
            kept
        })
    }

    /// The Gouraud colour of triangle `k` at the sample of pixel `(x, y)`, computed in the
    /// model's own arithmetic (exact rationals; exact integer edge values over twice the
    /// area for the integer models; f32 / f64 barycentrics for the float models).
    ///
    /// # Panics
    /// When `k` is not a triangle of the scene.
    pub fn shade(&self, k: usize, colours: &[Rgb; 3], x: u32, y: u32, target: &Target) -> Rgb {
        self.triangles.shade(k, colours, x, y, target)
    }

    /// The interpolated-colour picture: each covered pixel takes the colour of its
    /// highest-numbered (last drawn) primitive, a triangle with vertex `colours` shaded by
    /// [`PreparedScene::shade`]; any other primitive shows its coverage colour.
    pub fn colour_image(&self, coverage: &Coverage, colours: &[Option<[Rgb; 3]>], target: &Target) -> RgbImage {
        self.triangles.colour_image(coverage, colours, target)
    }
}

/// Renders `primitives` with `model` on `target`: [`prepare`], then [`PreparedScene::render`]
/// into a fresh [`Coverage`]. The entry point for a whole scene.
///
/// ```
/// use rasterproof::model::{render, Model};
/// use rasterproof::scene::parse_scene;
/// let scene = parse_scene(
///     r#"{"width": 8, "height": 8,
///         "triangles": [{"v": [[0, 0], [8, 0], [0, 8]]}],
///         "lines": [{"from": [0, 7], "to": [7, 7]}],
///         "clip": {"rect": [0, 0, 4, 8]}}"#,
///     "example.json",
/// )
/// .unwrap();
/// let target = scene.target().unwrap();
/// let coverage = render(&scene.primitives(), &target, Model::Fixed).unwrap();
/// // The line (id 1) keeps its pixels with samples inside the window: x = 0..=3.
/// assert_eq!(coverage.owners(3, 7), &[1]);
/// assert!(coverage.owners(4, 7).is_empty());
/// assert_eq!(coverage, render(&scene.primitives(), &target, Model::ExactSnapped).unwrap());
/// ```
///
/// # Errors
/// As [`prepare`].
pub fn render(primitives: &Primitives, target: &Target, model: Model) -> Result<Coverage, ModelError> {
    Ok(prepare(primitives, target, model)?.coverage(target))
}

/// Renders `triangles` (ids `0..`) with `model` into a fresh [`Coverage`].
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::model::{render_triangles, Model};
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(8, 0), Point::from_ints(0, 8));
/// let target = Target::new(8, 8, Convention::default()).unwrap();
/// let exact = render_triangles(&[t.clone()], &target, Model::ExactSnapped).unwrap();
/// assert_eq!(render_triangles(&[t], &target, Model::Fixed).unwrap(), exact);
/// ```
///
/// # Errors
/// The first triangle the model cannot take (envelope, float range).
pub fn render_triangles(triangles: &[Triangle], target: &Target, model: Model) -> Result<Coverage, ModelError> {
    let compact: Vec<CompactTriangle> = triangles.iter().map(CompactTriangle::from).collect();
    let prepared = prepare_triangles(model, &compact, target, 1)?;
    let mut coverage = Coverage::new(target.width, target.height);
    prepared.rasterize_into(target, &mut coverage);
    Ok(coverage)
}
