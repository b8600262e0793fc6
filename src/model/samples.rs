//! A scene at every sample of a pattern (multisampling): [`render_samples`].
//!
//! The plain oracles (`exact-plain`, `exact-snapped-plain`) test each sample where it is:
//! sample `s` of pixel `(i, j)` is the exact point `(i + x_s, j + y_s)`, inside a triangle
//! or polygon under the tie rule exactly as a pixel's one sample is
//! ([`crate::tri::exact::rasterize_samples`], [`crate::fill::polygon::rasterize_exact_samples`]).
//!
//! Every other model renders the scene once per sample, moved so that the sample comes to
//! where the model puts a pixel's one sample: by `(c - x_s, c - y_s)`, `c` the
//! convention's pixel centre (1/2 or 0). A translation keeps every edge's direction, so
//! the tie rule, the planner's bounds (up to the moved coordinates) and each model's
//! traversal decide the moved sample as they decide a centre. A model that snaps
//! (`exact-snapped`, `fixed`, `scanline`) is handed the scene snapped first, exactly, then
//! moved by a whole number of subpixels: snapping the moved points again changes nothing,
//! so it decides each sample of the snapped scene (moving first and snapping after would
//! not be the same: nearest-even and half-away rounding are not translation invariant at
//! a tie). Such a model refuses a sample whose offset is off its subpixel grid
//! ([`ModelError::SampleOffGrid`]); the standard patterns sit on the 1/16 grid, so every
//! convention with 4 subpixel bits or more places them. Clip-space triangles are mapped
//! to their exact window-space polygons first for the snapping models (as `prepare` does)
//! and moved by the viewport's origin for the others. A clip window moves with the scene:
//! a sample is clipped where it lies, not where its pixel's centre lies.
//!
//! Lines have no samples (a Bresenham or diamond-exit line decides a pixel by its own
//! rule): a scene with lines under a pattern of several samples is refused
//! ([`ModelError::LinesUnderPattern`]). The one-sample pattern at the convention's sample
//! position is the scene rendered as without a pattern, lines and all.

use num_rational::BigRational;

use super::polygons::clip_space_polygon;
use super::{prepare, render, Model, ModelError, Primitives, Shape};
use crate::clip::{Rect, Window};
use crate::convention::Target;
use crate::coverage::samples::SampleCoverage;
use crate::fill::polygon::rasterize_exact_samples;
use crate::geom::{Point, Polygon, Triangle};
use crate::pattern::SamplePattern;

/// The scene's coverage at every sample of `pattern` under `model` (see the module docs).
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::model::{render_samples, Model, Primitives};
/// use rasterproof::pattern::SamplePattern;
/// // The triangle (0,0) (1,0) (0,1) on a 1x1 canvas: of the standard 4x samples
/// // (3/8, 1/8) (7/8, 3/8) (1/8, 5/8) (5/8, 7/8), x + y < 1 holds for samples 0 and 2
/// // (1/2 and 3/4); sample 1 has x + y = 5/4 and sample 3 has 3/2.
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(1, 0), Point::from_ints(0, 1));
/// let target = Target::new(1, 1, Convention::default()).unwrap();
/// let four = SamplePattern::standard(4).unwrap();
/// for model in [Model::ExactSnappedPlain, Model::Fixed, Model::Float32] {
///     let c = render_samples(&Primitives::from_triangles(&[t.clone()]), &target, &four, model).unwrap();
///     assert_eq!(c.mask(0, 0), 0b0101, "{model}");
/// }
/// ```
///
/// # Errors
/// Whatever [`prepare`] refuses for the scene as given; lines under a pattern of several
/// samples; for a model that snaps, a sample off its subpixel grid; a moved scene the model
/// cannot take ([`ModelError::AtSample`]).
pub fn render_samples(
    primitives: &Primitives,
    target: &Target,
    pattern: &SamplePattern,
    model: Model,
) -> Result<SampleCoverage, ModelError> {
    let convention = &target.convention;
    if pattern.is_single(convention) {
        return Ok(SampleCoverage::from_samples(vec![render(primitives, target, model)?]));
    }
    if !primitives.lines.is_empty() {
        return Err(ModelError::LinesUnderPattern {
            lines: primitives.lines.len(),
            pattern: pattern.name(),
        });
    }
    let prepared = prepare(primitives, target, model)?;
    if let (Some(shapes), true) = (prepared.shapes(), model.is_plain()) {
        return Ok(plain(&shapes, target, pattern));
    }
    let frames = SampleFrames::new(primitives, target, pattern, model)?;
    let mut samples = Vec::with_capacity(pattern.len());
    for s in 0..pattern.len() {
        let moved = frames.at(s)?;
        let coverage = render(&moved, target, model).map_err(|error| ModelError::AtSample {
            sample: s,
            position: pattern.position_text(s),
            error: Box::new(error),
        })?;
        samples.push(coverage);
    }
    Ok(SampleCoverage::from_samples(samples))
}

/// A scene ready to be moved to each sample of a pattern for one model: snapped exactly
/// once, up front, when the model snaps (see the module docs). [`SampleFrames::at`] gives
/// the scene the model renders to decide one sample index; [`render_samples`] renders
/// each, and a per-sample comparison judges each.
#[derive(Debug, Clone)]
pub struct SampleFrames {
    base: Primitives,
    target: Target,
    pattern: SamplePattern,
    model: Model,
}

impl SampleFrames {
    /// `primitives` for `model` on `target`, at the samples of `pattern`.
    ///
    /// # Errors
    /// Lines ([`ModelError::LinesUnderPattern`]: a line has no samples).
    pub fn new(
        primitives: &Primitives,
        target: &Target,
        pattern: &SamplePattern,
        model: Model,
    ) -> Result<SampleFrames, ModelError> {
        if !primitives.lines.is_empty() {
            return Err(ModelError::LinesUnderPattern {
                lines: primitives.lines.len(),
                pattern: pattern.name(),
            });
        }
        let base = if model.snaps() {
            snapped(primitives, target)
        } else {
            primitives.clone()
        };
        Ok(SampleFrames {
            base,
            target: *target,
            pattern: pattern.clone(),
            model,
        })
    }

    /// The scene moved so that sample `s` of the pattern sits at the convention's one
    /// sample position.
    ///
    /// # Errors
    /// A model that snaps and a sample off its subpixel grid ([`ModelError::SampleOffGrid`]).
    pub fn at(&self, s: usize) -> Result<Primitives, ModelError> {
        let (convention, pattern) = (&self.target.convention, &self.pattern);
        if self.model.snaps() && pattern.offset_subpixels(s, convention).is_none() {
            return Err(ModelError::SampleOffGrid {
                sample: s,
                position: pattern.position_text(s),
                bits: convention.subpixel_bits,
                model: self.model,
            });
        }
        Ok(moved(&self.base, &pattern.offset(s, convention)))
    }
}

/// The plain per-sample oracle over a plain model's exact shapes (no lines: refused
/// before).
fn plain(shapes: &[Shape], target: &Target, pattern: &SamplePattern) -> SampleCoverage {
    let mut out = SampleCoverage::new(target.width, target.height, pattern.len());
    for (id, shape) in (0u32..).zip(shapes) {
        match shape {
            Shape::Triangle(t) => crate::tri::exact::rasterize_samples(t, id, target, pattern, &mut out),
            Shape::Polygon(p) => rasterize_exact_samples(p, id, target, pattern, &mut out),
            Shape::Bresenham { .. } | Shape::Diamond { .. } => unreachable!("lines are refused under a pattern"),
        }
    }
    out
}

/// The areas snapped exactly to the convention's grid, clip-space triangles as their exact
/// window-space polygons (snapped), in id order; the window as given.
fn snapped(primitives: &Primitives, target: &Target) -> Primitives {
    let convention = &target.convention;
    let mut polygons: Vec<Polygon> = primitives
        .polygons
        .iter()
        .map(|p| p.snapped_exact(convention))
        .collect();
    if let Some(viewport) = &primitives.viewport {
        let window_space = primitives
            .clip_space_triangles
            .iter()
            .map(|t| clip_space_polygon(t, viewport));
        polygons.extend(window_space.map(|p| p.snapped_exact(convention)));
    }
    Primitives {
        triangles: primitives
            .triangles
            .iter()
            .map(|t| t.snapped(convention).to_exact().into())
            .collect(),
        lines: Vec::new(),
        polygons,
        clip_space_triangles: Vec::new(),
        viewport: None,
        clip: primitives.clip.clone(),
    }
}

/// `primitives` moved by `-offset`: triangles, polygons, the clip window, and the
/// viewport's origin (which moves the clip-space triangles' window-space images).
fn moved(primitives: &Primitives, offset: &[BigRational; 2]) -> Primitives {
    let [dx, dy] = offset;
    let point = |p: &Point| Point::new(&p.x - dx, &p.y - dy);
    let contour = |c: &Vec<Point>| c.iter().map(point).collect::<Vec<_>>();
    let mut viewport = primitives.viewport.clone();
    if let Some(v) = &mut viewport {
        v.x = &v.x - dx;
        v.y = &v.y - dy;
    }
    Primitives {
        triangles: primitives
            .triangles
            .iter()
            .map(|t| {
                let t = t.to_triangle();
                Triangle::new(point(&t.v[0]), point(&t.v[1]), point(&t.v[2])).into()
            })
            .collect(),
        lines: Vec::new(),
        polygons: primitives
            .polygons
            .iter()
            .map(|p| Polygon {
                outline: contour(&p.outline),
                holes: p.holes.iter().map(contour).collect(),
                fill_rule: p.fill_rule,
            })
            .collect(),
        clip_space_triangles: primitives.clip_space_triangles.clone(),
        viewport,
        clip: primitives.clip.as_ref().map(|w| match w {
            Window::Rect(r) => Window::Rect(Box::new(Rect {
                xmin: &r.xmin - dx,
                ymin: &r.ymin - dy,
                xmax: &r.xmax - dx,
                ymax: &r.ymax - dy,
            })),
            Window::Convex(pts) => Window::Convex(pts.iter().map(point).collect()),
        }),
    }
}
