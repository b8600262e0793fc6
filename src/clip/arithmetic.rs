//! Clipping in a chosen arithmetic, results read back exactly: the one place that picks,
//! for exact, f64 or f32, which clipper runs and how its inputs are converted (a
//! coordinate that does not fit the float type is an error naming it) and its float
//! results are turned back into exact points (every finite float is a rational). What
//! `rasterproof clip --model` computes, what the trade's clipping workloads measure, and
//! (in the float forms [`Clipper::contour_f64`], [`Clipper::clip_space_f32`], ...) what
//! the float models clip their converted vertices with.
//!
//! - a closed contour: Sutherland-Hodgman (Sutherland & Hodgman 1974) against the
//!   window's half-planes, then [`area_or_empty`];
//! - a segment: Cohen-Sutherland (Sproull & Sutherland 1968) against a rectangle,
//!   Cyrus-Beck against a convex window;
//! - a clip-space triangle: clipped against the view volume, divided and mapped
//!   (Blinn & Newell 1978), then clipped against the window as a contour.

use glam::{DVec2, Vec2};
use num_rational::BigRational;

use super::halfplane::{clip_segment_exact, HalfPlane, HalfPlaneF32, HalfPlaneF64};
use super::homogeneous::{
    self, clip_to_window_exact, divide_then_clip_exact, ClipVertex, ClipVertexF32, ClipVertexF64, ProjectError,
    Viewport, ViewportF32, ViewportF64,
};
use super::{area_or_empty, cohen_sutherland, sutherland_hodgman, Window};
use crate::geom::Point;
use crate::num::exact::json_pair;

/// The arithmetic a [`Clipper`] runs in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ClipArithmetic {
    /// BigRational: the exact result.
    Exact,
    /// f64 with glam.
    F64,
    /// f32 with glam.
    F32,
}

impl ClipArithmetic {
    /// The arithmetic named `exact`, `float64` or `float32` (the CLI's `--model`), `None`
    /// for any other name.
    pub fn from_name(name: &str) -> Option<ClipArithmetic> {
        match name {
            "exact" => Some(ClipArithmetic::Exact),
            "float64" => Some(ClipArithmetic::F64),
            "float32" => Some(ClipArithmetic::F32),
            _ => None,
        }
    }

    /// Its name: `exact`, `float64` or `float32` (what [`ClipArithmetic::from_name`] reads).
    pub fn name(self) -> &'static str {
        match self {
            ClipArithmetic::Exact => "exact",
            ClipArithmetic::F64 => "float64",
            ClipArithmetic::F32 => "float32",
        }
    }
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

/// Clipping against one window (or none) in one arithmetic. Every error is a sentence
/// that starts with the name of what was being clipped (`what`, e.g. `triangles[2]`).
///
/// ```
/// use rasterproof::clip::arithmetic::{ClipArithmetic, Clipper};
/// use rasterproof::clip::Window;
/// use rasterproof::geom::Point;
/// use rasterproof::num::parse_rational;
/// let n = |s| parse_rational(s).unwrap();
/// let window = Window::rect(n("0"), n("0"), n("2"), n("2")).unwrap();
/// let clipper = Clipper::new(ClipArithmetic::F32, Some(&window)).unwrap();
/// let kept = clipper.segment(&Point::from_ints(-2, 1), &Point::from_ints(4, 1), "lines[0]").unwrap();
/// assert_eq!(kept, Some((Point::from_ints(0, 1), Point::from_ints(2, 1))));
/// ```
pub struct Clipper {
    arithmetic: ClipArithmetic,
    window: Option<Window>,
    planes: Vec<HalfPlane>,
    planes64: Vec<HalfPlaneF64>,
    planes32: Vec<HalfPlaneF32>,
}

impl Clipper {
    /// A clipper for `window` (`None`: nothing is clipped) in `arithmetic`.
    ///
    /// # Errors
    /// A line of the window has a coefficient beyond the float type (the message names
    /// the window edge).
    pub fn new(arithmetic: ClipArithmetic, window: Option<&Window>) -> Result<Clipper, String> {
        let planes = window.map(Window::half_planes).unwrap_or_default();
        let beyond = |k: usize, ty: &str| {
            format!("clip: the line of window edge {k} has a coefficient (a, b or c in a x + b y + c >= 0) beyond {ty}")
        };
        let planes64 = match arithmetic {
            ClipArithmetic::F64 => planes
                .iter()
                .enumerate()
                .map(|(k, h)| h.to_f64().ok_or_else(|| beyond(k, "f64")))
                .collect::<Result<Vec<_>, _>>()?,
            _ => Vec::new(),
        };
        let planes32 = match arithmetic {
            ClipArithmetic::F32 => planes
                .iter()
                .enumerate()
                .map(|(k, h)| h.to_f32().ok_or_else(|| beyond(k, "f32")))
                .collect::<Result<Vec<_>, _>>()?,
            _ => Vec::new(),
        };
        Ok(Clipper {
            arithmetic,
            window: window.cloned(),
            planes,
            planes64,
            planes32,
        })
    }

    fn to64(p: &Point, what: &str) -> Result<DVec2, String> {
        p.to_f64()
            .ok_or_else(|| format!("{what}: a coordinate does not fit f64"))
    }

    fn to32(p: &Point, what: &str) -> Result<Vec2, String> {
        p.to_f32()
            .ok_or_else(|| format!("{what}: a coordinate does not fit f32"))
    }

    /// A closed contour clipped by Sutherland-Hodgman (unchanged without a window), empty
    /// when what is left encloses no area ([`area_or_empty`]).
    ///
    /// # Errors
    /// A coordinate does not fit the float type, or a float result is not finite.
    pub fn contour(&self, c: &[Point], what: &str) -> Result<Vec<Point>, String> {
        self.sutherland_hodgman(c, what).map(area_or_empty)
    }

    fn sutherland_hodgman(&self, c: &[Point], what: &str) -> Result<Vec<Point>, String> {
        self.contour_vertices(c, what)?.into_iter().collect()
    }

    /// A closed contour clipped by Sutherland-Hodgman as it comes out (unchanged without a
    /// window; no [`area_or_empty`]), each vertex read back exactly on its own: `Err` in a
    /// vertex is a float result that is not finite (the message names `what` and the
    /// value). What the trade counts outside the window, vertex by vertex.
    ///
    /// # Errors
    /// A coordinate does not fit the float type.
    pub fn contour_vertices(&self, c: &[Point], what: &str) -> Result<Vec<Result<Point, String>>, String> {
        if self.window.is_none() {
            return Ok(c.iter().cloned().map(Ok).collect());
        }
        let back = |r: Result<Point, String>| r.map_err(|e| format!("{what}: {e}"));
        match self.arithmetic {
            ClipArithmetic::Exact => Ok(sutherland_hodgman::clip_exact(c, &self.planes)
                .into_iter()
                .map(Ok)
                .collect()),
            ClipArithmetic::F64 => {
                let v = c.iter().map(|p| Self::to64(p, what)).collect::<Result<Vec<_>, _>>()?;
                Ok(self.contour_f64(&v).into_iter().map(|p| back(point64(p))).collect())
            }
            ClipArithmetic::F32 => {
                let v = c.iter().map(|p| Self::to32(p, what)).collect::<Result<Vec<_>, _>>()?;
                Ok(self.contour_f32(&v).into_iter().map(|p| back(point32(p))).collect())
            }
        }
    }

    /// A closed contour of f64 vertices clipped by Sutherland-Hodgman in f64 against the
    /// window's half-planes (unchanged without a window; no [`area_or_empty`]): what the
    /// float64 models clip their converted vertices with.
    ///
    /// # Panics
    /// With a window, when the clipper's arithmetic is not [`ClipArithmetic::F64`].
    pub fn contour_f64(&self, c: &[DVec2]) -> Vec<DVec2> {
        if self.window.is_none() {
            return c.to_vec();
        }
        assert_eq!(
            self.arithmetic,
            ClipArithmetic::F64,
            "contour_f64 on a clipper in another arithmetic"
        );
        sutherland_hodgman::clip_f64(c, &self.planes64)
    }

    /// [`Clipper::contour_f64`] in f32: what the float32 models clip with.
    ///
    /// # Panics
    /// With a window, when the clipper's arithmetic is not [`ClipArithmetic::F32`].
    pub fn contour_f32(&self, c: &[Vec2]) -> Vec<Vec2> {
        if self.window.is_none() {
            return c.to_vec();
        }
        assert_eq!(
            self.arithmetic,
            ClipArithmetic::F32,
            "contour_f32 on a clipper in another arithmetic"
        );
        sutherland_hodgman::clip_f32(c, &self.planes32)
    }

    /// A clip-space triangle already in f64: clipped against the view volume, divided and
    /// mapped by `viewport` in f64, then clipped against the window by
    /// [`Clipper::contour_f64`]. What the float64 models draw as a fan.
    ///
    /// # Panics
    /// With a window, when the clipper's arithmetic is not [`ClipArithmetic::F64`].
    pub fn clip_space_f64(&self, t: &[ClipVertexF64], viewport: &ViewportF64) -> Vec<DVec2> {
        let points: Vec<DVec2> = homogeneous::clip_to_window_f64(t, viewport)
            .into_iter()
            .map(|v| v.point)
            .collect();
        self.contour_f64(&points)
    }

    /// [`Clipper::clip_space_f64`] in f32: what the float32 models draw as a fan.
    ///
    /// # Panics
    /// With a window, when the clipper's arithmetic is not [`ClipArithmetic::F32`].
    pub fn clip_space_f32(&self, t: &[ClipVertexF32], viewport: &ViewportF32) -> Vec<Vec2> {
        let points: Vec<Vec2> = homogeneous::clip_to_window_f32(t, viewport)
            .into_iter()
            .map(|v| v.point)
            .collect();
        self.contour_f32(&points)
    }

    /// A segment: Cohen-Sutherland for a rectangle, Cyrus-Beck for a convex window;
    /// `None` when nothing of it is inside.
    ///
    /// # Errors
    /// A coordinate or a bound does not fit the float type, or a float result is not
    /// finite.
    pub fn segment(&self, a: &Point, b: &Point, what: &str) -> Result<Option<(Point, Point)>, String> {
        self.segment_ends(a, b, what)?.map(|[p, q]| Ok((p?, q?))).transpose()
    }

    /// [`Clipper::segment`] with each end read back exactly on its own: `Err` in an end is
    /// a float result that is not finite (the message names `what` and the value). What
    /// the trade counts outside the window, end by end.
    ///
    /// # Errors
    /// A coordinate or a bound does not fit the float type.
    pub fn segment_ends(&self, a: &Point, b: &Point, what: &str) -> Result<Option<[Result<Point, String>; 2]>, String> {
        let Some(window) = &self.window else {
            return Ok(Some([Ok(a.clone()), Ok(b.clone())]));
        };
        let (fa, fb) = match self.arithmetic {
            ClipArithmetic::Exact => (DVec2::ZERO, DVec2::ZERO),
            ClipArithmetic::F64 => (Self::to64(a, what)?, Self::to64(b, what)?),
            // f32 values, held in f64 (exactly) until the f32 clipper takes them back
            ClipArithmetic::F32 => (Self::to32(a, what)?.as_dvec2(), Self::to32(b, what)?.as_dvec2()),
        };
        let exact = |r: Option<(Point, Point)>| r.map(|(p, q)| [Ok(p), Ok(q)]);
        let both =
            |r: Option<(DVec2, DVec2)>| r.map(|(p, q)| [p, q].map(|v| point64(v).map_err(|e| format!("{what}: {e}"))));
        Ok(match (window, self.arithmetic) {
            (Window::Rect(r), ClipArithmetic::Exact) => exact(cohen_sutherland::clip_exact(a, b, r)),
            (Window::Convex(_), ClipArithmetic::Exact) => exact(clip_segment_exact(a, b, &self.planes)),
            (Window::Rect(r), ClipArithmetic::F64) => {
                let r = r.to_f64().ok_or("clip: a bound does not fit f64")?;
                both(cohen_sutherland::clip_f64(fa, fb, &r))
            }
            (Window::Rect(r), ClipArithmetic::F32) => {
                let r = r.to_f32().ok_or("clip: a bound does not fit f32")?;
                both(
                    cohen_sutherland::clip_f32(fa.as_vec2(), fb.as_vec2(), &r)
                        .map(|(p, q)| (p.as_dvec2(), q.as_dvec2())),
                )
            }
            (Window::Convex(_), ClipArithmetic::F64) => both(HalfPlaneF64::clip_segment(fa, fb, &self.planes64)),
            (Window::Convex(_), ClipArithmetic::F32) => both(
                HalfPlaneF32::clip_segment(fa.as_vec2(), fb.as_vec2(), &self.planes32)
                    .map(|(p, q)| (p.as_dvec2(), q.as_dvec2())),
            ),
        })
    }

    /// A clip-space triangle: clipped against the view volume, divided and mapped by
    /// `viewport` (or, with `divide_first`, exact only, divided first and clipped in 2D),
    /// then clipped against the window as a [`contour`](Clipper::contour).
    ///
    /// # Errors
    /// `divide_first` outside exact arithmetic, a vertex with `w <= 0` under
    /// `divide_first`, a number that does not fit the float type, or a float result that
    /// is not finite.
    pub fn clip_space(
        &self,
        t: &[ClipVertex; 3],
        viewport: &Viewport,
        divide_first: bool,
        what: &str,
    ) -> Result<Vec<Point>, String> {
        let window_space: Vec<Point> = match self.arithmetic {
            ClipArithmetic::Exact if divide_first => match divide_then_clip_exact(t, viewport) {
                // seen edge-on: it covers no sample, as on the clip-space path
                Err(ProjectError::EdgeOn) => Vec::new(),
                Err(e) => return Err(format!("{what}: {e} (--divide-first)")),
                Ok(vertices) => vertices.into_iter().map(|v| v.point).collect(),
            },
            _ if divide_first => return Err("--divide-first: only with --model exact".into()),
            ClipArithmetic::Exact => clip_to_window_exact(t, viewport).into_iter().map(|v| v.point).collect(),
            ClipArithmetic::F64 => {
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
            ClipArithmetic::F32 => {
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
        self.contour(&window_space, what)
    }
}

/// Every primitive of a scene clipped by one [`Clipper`], in input order: what
/// `rasterproof clip` prints ([`Clipped::to_json`], [`Clipped::to_text`]).
/// [`crate::scene::Scene::clipped`] builds it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Clipped {
    /// The arithmetic it was clipped in.
    pub arithmetic: ClipArithmetic,
    /// Each triangle's contour ([`Clipper::contour`]; empty: no area left).
    pub triangles: Vec<Vec<Point>>,
    /// Each line's kept segment ([`Clipper::segment`]; `None`: nothing inside).
    pub lines: Vec<Option<(Point, Point)>>,
    /// Each polygon's outline, then its holes, each a [`Clipper::contour`]; no contour at
    /// all when the outline keeps no area (its holes are not clipped then).
    pub polygons: Vec<Vec<Vec<Point>>>,
    /// Each clip-space triangle's window-space contour ([`Clipper::clip_space`]).
    pub clip_space_triangles: Vec<Vec<Point>>,
}

/// A point as `["x","y"]`, exact text.
fn json_point(p: &Point) -> String {
    json_pair(&p.x, &p.y)
}

/// A contour as `[["x","y"],...]`.
fn json_contour(points: &[Point]) -> String {
    format!("[{}]", points.iter().map(json_point).collect::<Vec<_>>().join(","))
}

impl Clipped {
    /// One line of JSON (no newline):
    /// `{"triangles":[...],"lines":[...],"polygons":[...],"clip_space_triangles":[...]}`,
    /// every coordinate an exact string: a triangle and a clip-space triangle as a list of
    /// points `["x","y"]`, a line as its two ends, a polygon as its contours (outline
    /// first); `[]` for one that covers nothing.
    pub fn to_json(&self) -> String {
        let lines = self.lines.iter().map(|l| {
            l.as_ref().map_or("[]".to_string(), |(a, b)| {
                format!("[{},{}]", json_point(a), json_point(b))
            })
        });
        let polygons = self.polygons.iter().map(|contours| {
            if contours.is_empty() {
                return "[]".to_string();
            }
            format!(
                "[{}]",
                contours.iter().map(|c| json_contour(c)).collect::<Vec<_>>().join(",")
            )
        });
        let triangles: Vec<String> = self.triangles.iter().map(|t| json_contour(t)).collect();
        let clip_space: Vec<String> = self.clip_space_triangles.iter().map(|t| json_contour(t)).collect();
        format!(
            "{{\"triangles\":[{}],\"lines\":[{}],\"polygons\":[{}],\"clip_space_triangles\":[{}]}}",
            triangles.join(","),
            lines.collect::<Vec<_>>().join(","),
            polygons.collect::<Vec<_>>().join(","),
            clip_space.join(",")
        )
    }

    /// The one-line summary (no newline): per kind, how many keep something, for the
    /// scene named `name`.
    pub fn to_text(&self, name: &str) -> String {
        let kept = |v: &[Vec<Point>]| v.iter().filter(|c| !c.is_empty()).count();
        format!(
            "{name}: {} clipping: {}/{} triangles, {}/{} lines, {}/{} polygons, {}/{} clip-space triangles keep something",
            self.arithmetic.name(),
            kept(&self.triangles),
            self.triangles.len(),
            self.lines.iter().filter(|l| l.is_some()).count(),
            self.lines.len(),
            self.polygons.iter().filter(|p| !p.is_empty()).count(),
            self.polygons.len(),
            kept(&self.clip_space_triangles),
            self.clip_space_triangles.len()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::parse_rational;

    fn window() -> Window {
        let n = |s| parse_rational(s).unwrap();
        Window::rect(n("0"), n("0"), n("8"), n("8")).unwrap()
    }

    #[test]
    fn float_forms_are_the_float_clippers_and_nothing_without_a_window() {
        let w = window();
        let c = [Vec2::new(-2.0, 1.0), Vec2::new(9.5, 2.0), Vec2::new(3.0, 10.0)];
        let planes: Vec<HalfPlaneF32> = w.half_planes().iter().map(|h| h.to_f32().unwrap()).collect();
        let clipper = Clipper::new(ClipArithmetic::F32, Some(&w)).unwrap();
        assert_eq!(clipper.contour_f32(&c), sutherland_hodgman::clip_f32(&c, &planes));
        assert_eq!(
            Clipper::new(ClipArithmetic::F32, None).unwrap().contour_f32(&c),
            c.to_vec()
        );
        // Without a window any arithmetic leaves a float contour as it is.
        assert_eq!(
            Clipper::new(ClipArithmetic::Exact, None).unwrap().contour_f32(&c),
            c.to_vec()
        );
    }

    #[test]
    fn a_result_that_is_not_finite_is_an_error_of_its_own_vertex() {
        // 8 x 3e38 overflows f32: the intersections with x = 0 and x = 8 are NaN.
        let w = window();
        let c = [Point::from_ints(0, 4), Point::from_ints(4, 0), Point::from_ints(0, 0)];
        let far = |x: f64| Point::new(BigRational::from_float(x).unwrap(), BigRational::from_integer(4.into()));
        let c = [far(-3e38), far(3e38), c[0].clone(), c[1].clone(), c[2].clone()];
        let clipper = Clipper::new(ClipArithmetic::F32, Some(&w)).unwrap();
        let each = clipper.contour_vertices(&c, "t").unwrap();
        let first = each
            .iter()
            .find_map(|v| v.clone().err())
            .expect("a vertex that is not finite");
        assert!(first.starts_with("t: a float result is not finite"), "{first}");
        assert!(each.iter().any(Result::is_ok));
        assert_eq!(clipper.contour(&c, "t"), Err(first));
        let exact = Clipper::new(ClipArithmetic::Exact, Some(&w)).unwrap();
        assert!(exact.contour_vertices(&c, "t").unwrap().iter().all(Result::is_ok));
        // A segment's ends, each on its own.
        let ends = clipper.segment_ends(&far(-3e38), &far(3e38), "s").unwrap();
        let segment = clipper.segment(&far(-3e38), &far(3e38), "s");
        match ends {
            Some([Ok(a), Ok(b)]) => assert_eq!(segment, Ok(Some((a, b)))),
            Some([a, b]) => assert_eq!(segment, Err(a.err().or(b.err()).unwrap())),
            None => assert_eq!(segment, Ok(None)),
        }
        // An input beyond f32 is the call's error.
        assert!(clipper.contour_vertices(&[far(1e39)], "t").is_err());
    }
}
