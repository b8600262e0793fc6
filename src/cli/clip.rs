//! `rasterproof clip`: the scene's primitives clipped against its `clip` window (and its
//! clip-space triangles clipped against the view volume, divided and mapped), printed
//! with every coordinate as an exact string. An area primitive whose result encloses no
//! area (a point or a segment) prints as `[]`; a line's result may be a single point
//! (see [`rasterproof::clip::area_or_empty`]).

use std::path::PathBuf;
use std::process::ExitCode;

use glam::{DVec2, Vec2};
use num_rational::BigRational;
use rasterproof::clip::halfplane::{clip_segment_exact, HalfPlane, HalfPlaneF32, HalfPlaneF64};
use rasterproof::clip::homogeneous::{self, clip_to_window_exact, divide_then_clip_exact, ClipVertex, ProjectError};
use rasterproof::clip::{area_or_empty, cohen_sutherland, sutherland_hodgman, Window};
use rasterproof::geom::Point;
use rasterproof::num::exact::json_pair;
use rasterproof::scene::{parse_scene_bytes, Scene};

/// What `clip` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// The scene file (JSON).
    scene: PathBuf,
    /// exact (default), float32 or float64: the arithmetic of the clipping.
    #[arg(long, default_value = "exact")]
    model: String,
    /// Clip-space triangles: divide by w first, then clip in 2D (exact only; refuses
    /// vertices with w <= 0, which only clip-space clipping handles).
    #[arg(long)]
    divide_first: bool,
    /// Output format on stdout. Every primitive is listed in input order; `[]` is one that
    /// covers nothing: clipped away, or (triangles, polygon contours, clip-space
    /// triangles) left with no area — a point or a segment, as when it touches the window
    /// only at a corner or along an edge. A line touching the window in one point is that
    /// point twice (a segment of length zero).
    #[arg(long, value_enum, default_value_t = Format::Json)]
    format: Format,
}

/// How `clip` reports on stdout.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// `{"triangles":[...],"lines":[...],"polygons":[...],"clip_space_triangles":[...]}`.
    Json,
    /// A one-line summary.
    Text,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Arith {
    Exact,
    F32,
    F64,
}

/// A point as `["x","y"]`, exact text.
fn pt(p: &Point) -> String {
    json_pair(&p.x, &p.y)
}

fn list(points: &[Point]) -> String {
    format!("[{}]", points.iter().map(pt).collect::<Vec<_>>().join(","))
}

/// A float's exact value.
fn from_f64(v: f64) -> Result<BigRational, String> {
    BigRational::from_float(v).ok_or_else(|| format!("a float result is not finite: {v}"))
}

fn point64(p: DVec2) -> Result<Point, String> {
    Ok(Point::new(from_f64(p.x)?, from_f64(p.y)?))
}

fn point32(p: Vec2) -> Result<Point, String> {
    point64(p.as_dvec2())
}

/// The clipping of one scene in one arithmetic.
struct Clipper<'a> {
    scene: &'a Scene,
    arith: Arith,
    planes: Vec<HalfPlane>,
    planes64: Vec<HalfPlaneF64>,
    planes32: Vec<HalfPlaneF32>,
}

impl Clipper<'_> {
    fn to64(&self, p: &Point, what: &str) -> Result<DVec2, String> {
        p.to_f64()
            .ok_or_else(|| format!("{what}: a coordinate does not fit f64"))
    }

    fn to32(&self, p: &Point, what: &str) -> Result<Vec2, String> {
        p.to_f32()
            .ok_or_else(|| format!("{what}: a coordinate does not fit f32"))
    }

    /// A closed contour clipped by Sutherland-Hodgman (unchanged without a window), empty
    /// when what is left encloses no area ([`area_or_empty`]).
    fn contour(&self, c: &[Point], what: &str) -> Result<Vec<Point>, String> {
        self.sutherland_hodgman(c, what).map(area_or_empty)
    }

    fn sutherland_hodgman(&self, c: &[Point], what: &str) -> Result<Vec<Point>, String> {
        if self.scene.clip.is_none() {
            return Ok(c.to_vec());
        }
        match self.arith {
            Arith::Exact => Ok(sutherland_hodgman::clip_exact(c, &self.planes)),
            Arith::F64 => {
                let v = c.iter().map(|p| self.to64(p, what)).collect::<Result<Vec<_>, _>>()?;
                sutherland_hodgman::clip_f64(&v, &self.planes64)
                    .into_iter()
                    .map(|p| point64(p).map_err(|e| format!("{what}: {e}")))
                    .collect()
            }
            Arith::F32 => {
                let v = c.iter().map(|p| self.to32(p, what)).collect::<Result<Vec<_>, _>>()?;
                sutherland_hodgman::clip_f32(&v, &self.planes32)
                    .into_iter()
                    .map(|p| point32(p).map_err(|e| format!("{what}: {e}")))
                    .collect()
            }
        }
    }

    /// A segment: Cohen-Sutherland for a rectangle, Cyrus-Beck for a convex window.
    fn segment(&self, a: &Point, b: &Point, what: &str) -> Result<Option<(Point, Point)>, String> {
        let Some(window) = &self.scene.clip else {
            return Ok(Some((a.clone(), b.clone())));
        };
        let (fa, fb) = match self.arith {
            Arith::Exact => (DVec2::ZERO, DVec2::ZERO),
            Arith::F64 => (self.to64(a, what)?, self.to64(b, what)?),
            // f32 values, held in f64 (exactly) until the f32 clipper takes them back
            Arith::F32 => (self.to32(a, what)?.as_dvec2(), self.to32(b, what)?.as_dvec2()),
        };
        let both = |r: Option<(DVec2, DVec2)>| -> Result<Option<(Point, Point)>, String> {
            r.map(|(p, q)| Ok((point64(p)?, point64(q)?)))
                .transpose()
                .map_err(|e: String| format!("{what}: {e}"))
        };
        match (window, self.arith) {
            (Window::Rect(r), Arith::Exact) => Ok(cohen_sutherland::clip_exact(a, b, r)),
            (Window::Convex(_), Arith::Exact) => Ok(clip_segment_exact(a, b, &self.planes)),
            (Window::Rect(r), Arith::F64) => {
                let r = r.to_f64().ok_or("clip: a bound does not fit f64")?;
                both(cohen_sutherland::clip_f64(fa, fb, &r))
            }
            (Window::Rect(r), Arith::F32) => {
                let r = r.to_f32().ok_or("clip: a bound does not fit f32")?;
                both(
                    cohen_sutherland::clip_f32(fa.as_vec2(), fb.as_vec2(), &r)
                        .map(|(p, q)| (p.as_dvec2(), q.as_dvec2())),
                )
            }
            (Window::Convex(_), Arith::F64) => both(HalfPlaneF64::clip_segment(fa, fb, &self.planes64)),
            (Window::Convex(_), Arith::F32) => both(
                HalfPlaneF32::clip_segment(fa.as_vec2(), fb.as_vec2(), &self.planes32)
                    .map(|(p, q)| (p.as_dvec2(), q.as_dvec2())),
            ),
        }
    }

    /// A clip-space triangle: clipped against the view volume, divided, mapped, then
    /// clipped against the window.
    fn clip_space(&self, k: usize, divide_first: bool) -> Result<Vec<Point>, String> {
        let t = &self.scene.clip_space_triangles[k];
        let what = format!("clip_space_triangles[{k}]");
        let viewport = self.scene.viewport();
        let window_space: Vec<Point> = match self.arith {
            Arith::Exact if divide_first => match divide_then_clip_exact(t, &viewport) {
                // seen edge-on: it covers no sample, as on the clip-space path
                Err(ProjectError::EdgeOn) => Vec::new(),
                Err(e) => return Err(format!("{what}: {e} (--divide-first)")),
                Ok(vertices) => vertices.into_iter().map(|v| v.point).collect(),
            },
            Arith::Exact => clip_to_window_exact(t, &viewport)
                .into_iter()
                .map(|v| v.point)
                .collect(),
            Arith::F64 => {
                let vp = viewport.to_f64().ok_or("viewport: a number does not fit f64")?;
                let v = t
                    .iter()
                    .map(ClipVertex::to_f64)
                    .collect::<Option<Vec<_>>>()
                    .ok_or_else(|| format!("{what}: a coordinate does not fit f64"))?;
                homogeneous::clip_to_window_f64(&v, &vp)
                    .into_iter()
                    .map(|v| point64(v.point).map_err(|e| format!("{what}: {e}")))
                    .collect::<Result<_, _>>()?
            }
            Arith::F32 => {
                let vp = viewport.to_f32().ok_or("viewport: a number does not fit f32")?;
                let v = t
                    .iter()
                    .map(ClipVertex::to_f32)
                    .collect::<Option<Vec<_>>>()
                    .ok_or_else(|| format!("{what}: a coordinate does not fit f32"))?;
                homogeneous::clip_to_window_f32(&v, &vp)
                    .into_iter()
                    .map(|v| point32(v.point).map_err(|e| format!("{what}: {e}")))
                    .collect::<Result<_, _>>()?
            }
        };
        if window_space.is_empty() {
            return Ok(window_space);
        }
        self.contour(&window_space, &what)
    }
}

pub fn run(o: &Options) -> Result<ExitCode, String> {
    let name = o.scene.display().to_string();
    let arith = match o.model.as_str() {
        "exact" => Arith::Exact,
        "float32" => Arith::F32,
        "float64" => Arith::F64,
        other => {
            return Err(format!(
                "--model: unknown model {other:?} for clip (expected exact, float32 or float64)"
            ))
        }
    };
    if o.divide_first && arith != Arith::Exact {
        return Err("--divide-first: only with --model exact".into());
    }
    let bytes = std::fs::read(&o.scene).map_err(|e| format!("{name}: cannot read: {e}"))?;
    let scene = parse_scene_bytes(&bytes, &name).map_err(|e| e.to_string())?;
    let planes = scene.clip.as_ref().map(Window::half_planes).unwrap_or_default();
    let in_file = |e: String| format!("{name}: {e}");
    let beyond = |k: usize, ty: &str| {
        in_file(format!(
            "clip: the line of window edge {k} has a coefficient (a, b or c in a x + b y + c >= 0) beyond {ty}"
        ))
    };
    let planes64 = match arith {
        Arith::F64 => planes
            .iter()
            .enumerate()
            .map(|(k, h)| h.to_f64().ok_or_else(|| beyond(k, "f64")))
            .collect::<Result<Vec<_>, _>>()?,
        _ => Vec::new(),
    };
    let planes32 = match arith {
        Arith::F32 => planes
            .iter()
            .enumerate()
            .map(|(k, h)| h.to_f32().ok_or_else(|| beyond(k, "f32")))
            .collect::<Result<Vec<_>, _>>()?,
        _ => Vec::new(),
    };
    let clipper = Clipper {
        scene: &scene,
        arith,
        planes,
        planes64,
        planes32,
    };

    let mut triangles = Vec::new();
    for (k, t) in scene.triangles.iter().enumerate() {
        triangles.push(list(
            &clipper
                .contour(&t.triangle.v, &format!("triangles[{k}]"))
                .map_err(in_file)?,
        ));
    }
    let mut lines = Vec::new();
    for (k, l) in scene.lines.iter().enumerate() {
        let kept = clipper
            .segment(&l.from, &l.to, &format!("lines[{k}]"))
            .map_err(in_file)?;
        lines.push(kept.map_or("[]".to_string(), |(a, b)| format!("[{},{}]", pt(&a), pt(&b))));
    }
    let mut polygons = Vec::new();
    for (k, p) in scene.polygons.iter().enumerate() {
        let what = format!("polygons[{k}]");
        let outline = clipper.contour(&p.outline, &what).map_err(in_file)?;
        if outline.is_empty() {
            polygons.push("[]".to_string());
            continue;
        }
        let mut contours = vec![list(&outline)];
        for h in &p.holes {
            contours.push(list(&clipper.contour(h, &what).map_err(in_file)?));
        }
        polygons.push(format!("[{}]", contours.join(",")));
    }
    let mut clip_space = Vec::new();
    for k in 0..scene.clip_space_triangles.len() {
        clip_space.push(list(&clipper.clip_space(k, o.divide_first).map_err(in_file)?));
    }
    match o.format {
        Format::Json => {
            let json = format!(
                "{{\"triangles\":[{}],\"lines\":[{}],\"polygons\":[{}],\"clip_space_triangles\":[{}]}}",
                triangles.join(","),
                lines.join(","),
                polygons.join(","),
                clip_space.join(",")
            );
            crate::cli::print_stdout(&json)?;
        }
        Format::Text => {
            let kept = |v: &[String]| v.iter().filter(|s| s.as_str() != "[]").count();
            crate::cli::print_stdout(&format!(
                "{name}: {} clipping: {}/{} triangles, {}/{} lines, {}/{} polygons, {}/{} clip-space triangles keep something",
                o.model,
                kept(&triangles),
                triangles.len(),
                kept(&lines),
                lines.len(),
                kept(&polygons),
                polygons.len(),
                kept(&clip_space),
                clip_space.len()
            ))?;
        }
    }
    Ok(ExitCode::SUCCESS)
}
