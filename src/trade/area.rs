//! The area-coverage workloads (family `area`) and the area models on them, side by side:
//! speed at the origin and, per coordinate magnitude, the error of each pixel's coverage
//! against the exact value.
//!
//! - **Workloads**: DejaVu Sans's "g@&B%" (the committed scene
//!   `adapters/scenes/dejavu.json`, 7 polygons on 102 x 32 px at 24 px per em) scaled exactly by
//!   `px / 24` to 9, 24, 64 and 200 px per em, each glyph polygon one shape; an abutting
//!   mesh (a spade Delaunay triangulation, each triangle its own shape, so that a pixel's
//!   value is accumulated across shapes); slivers (long thin triangles, each its own shape).
//!   Every value is under [`Semantics::Accumulated`]: each shape's value folded, summed
//!   over the shapes (what a renderer adding shapes into one accumulation buffer
//!   computes; for the glyphs, whose contours do not overlap, it is their true coverage).
//! - **Contenders** ([`AreaContender`]: methods of [`AreaMethod::ALL`], and multisampling): the planned exact engine (`area::planned`, the
//!   reference and a speed contender), exact cell accumulation in big rationals
//!   (`area::cells`) and the plain oracle (`area::exact`), both on the subset below; f32
//!   accumulation (`area::float`, font-rs and ab_glyph's method); FreeType's 24.8 integer
//!   cells with 8-bit output (`area::ftgrays`); 4 x 4 exact point samples
//!   (`area::supersample`) and tiny-skia's levels from them, both on the subset;
//!   multisampling at the standard 4x, 8x and 16x positions (`msaa-4x` ... : the
//!   `scanline` model per sample, snapped to 8 subpixel bits, on every pixel; whole-pixel
//!   moves leave it unchanged, so its cells beyond 0 are the origin's). The
//!   sample-counting models are run on one shape at a time and their results added (the
//!   counts exactly, the 8-bit levels saturating, as `ftgrays` adds its passes), so that
//!   every contender answers the same accumulated question.
//! - **The subset**: the models that are slow by design (the exact ones in big rationals
//!   and the sample counters, which decide every sample exactly: 10 to 1000 pixels a
//!   second on glyph outlines of hundreds of edges) run on a 12 x 12 px window (`--quick`
//!   too: its glyph workloads are the full run's, figure for figure) centred on the middle
//!   partly covered pixel, with the shapes that have a non-zero
//!   exact value in it, against the planned engine's answer there (as the binary trade runs its
//!   plain oracles on a corner).
//! - **Speed**: each model's own function from the shapes to its output (exact values,
//!   f32 values, 8-bit levels), round-robin as elsewhere in the trade; Mpix/s counts the
//!   pixels whose exact value is not zero.
//! - **Error** of a pixel: `|model - exact|`, where the model's value is its f32 read
//!   exactly, its 8-bit level `L` read as `L / 255`, its sample count `n` as `n / 16`. Over
//!   the pixels where either is not zero: the pixels off by more than half a quantum
//!   (`|error| > 1/510`: where an 8-bit image of the model differs from the correctly
//!   rounded one), per million (the headline); the largest and the mean error in quanta of
//!   1/255 ([`Metric::Quanta`]); for `ftgrays` also the levels that differ from its own
//!   quantization of the exact value (`floor(256 v)` clamped to 255), which separates its
//!   arithmetic from its choice of rounding.
//! - **Magnitude `M`**: the exact models (planned, cells, plain, the exact sample counts)
//!   are translation-invariant under a whole-pixel shift (exact arithmetic; the property
//!   `rotation_reversal_translation` of `tests/area.rs`), so their cells at `M > 0` are
//!   the origin's, marked `translated`. The two models with rounding compute with the
//!   placed coordinates (shapes moved by `(M, M)` exactly, the window `[M, M + side)^2`),
//!   as `trade::far` does for the float triangle models: `f32-accum` by
//!   [`crate::area::float::rasterize_at`], `area::float`'s walk with its canvas origin at `(M, M)`;
//!   `ftgrays` by [`crate::area::ftgrays::rasterize_at`], its 26.6 rounding and 24.8 envelope at the placed
//!   coordinates, the rest by the model. Beyond the envelope `ftgrays` refuses, with its
//!   own message.

use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};

use crate::area::{planned, AreaImage, AreaMethod, AreaOutput, AreaShape, Quantization, Semantics};
use crate::convention::{Preset, Target};
use crate::geom::{Point, Polygon};
use crate::model::{render_samples, Model, Primitives};
use crate::pattern::SamplePattern;
use crate::strategy::{triangle, TriangleScale};

use super::metric::Metric;
use super::report::{Axis, Cell, Outcome, Placement, PlanSummary, SpeedEntry, WorkloadReport};
use super::speed::{entries, Contender, Job};
use super::workloads::{draw_n, mesh, runner};
use super::{Config, Family, Magnitude, Sizes};

/// Every value is under this semantics (see the module documentation).
const SEMANTICS: Semantics = Semantics::Accumulated;

/// The glyph sizes, px per em.
pub(crate) const GLYPH_SIZES: [u32; 4] = [9, 24, 64, 200];

/// The committed glyph scene: DejaVu Sans's "g@&B%" at 24 px per em.
static DEJAVU: &str = include_str!("../../adapters/scenes/dejavu.json");

/// The headline metric: pixels whose error exceeds half a quantum (1/510).
pub const OFF_HALF_QUANTUM: &str = "pixels off by > 1/2 quantum";
/// The distribution of the absolute error, in quanta of 1/255.
pub const COVERAGE_ERROR: &str = "coverage error";
/// `ftgrays`: its levels against its own quantization of the exact value.
pub const LEVELS_OFF: &str = "levels off its quantization of the exact value";

/// An area contender: a method of the area family's one list, or multisampling.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AreaContender {
    /// A method of [`AreaMethod::ALL`], drawing under [`Semantics::Accumulated`].
    Method(AreaMethod),
    /// Multisampling at the standard positions of this count: the `scanline` model per
    /// sample (`model::render_samples`), vertices snapped to 8 subpixel bits as a GPU
    /// snaps them, each shape's covered samples counted.
    Msaa(u32),
}

impl AreaContender {
    /// Every contender, in report order.
    pub const ALL: [AreaContender; 10] = [
        AreaContender::Method(AreaMethod::Plain),
        AreaContender::Method(AreaMethod::Cells),
        AreaContender::Method(AreaMethod::Planned),
        AreaContender::Method(AreaMethod::Float),
        AreaContender::Method(AreaMethod::FtGrays),
        AreaContender::Method(AreaMethod::Supersample(4)),
        AreaContender::Method(AreaMethod::TinySkia),
        AreaContender::Msaa(4),
        AreaContender::Msaa(8),
        AreaContender::Msaa(16),
    ];

    /// Its name in the report.
    pub fn name(self) -> &'static str {
        match self {
            AreaContender::Method(m) => m.name(),
            AreaContender::Msaa(4) => "msaa-4x",
            AreaContender::Msaa(8) => "msaa-8x",
            AreaContender::Msaa(16) => "msaa-16x",
            AreaContender::Msaa(_) => "msaa",
        }
    }

    /// Computes the exact value (its error must be zero).
    pub fn is_exact(self) -> bool {
        matches!(self, AreaContender::Method(m) if m.is_exact())
    }

    /// Runs on the subset (slow by design: exact in big rationals, or every sample
    /// decided exactly).
    fn on_subset(self) -> bool {
        match self {
            AreaContender::Method(m) => {
                m != AreaMethod::REFERENCE
                    && (m.is_exact() || matches!(m, AreaMethod::Supersample(_) | AreaMethod::TinySkia))
            }
            AreaContender::Msaa(_) => false,
        }
    }

    /// The quantization it applies itself, for [`LEVELS_OFF`] (`ftgrays`'s).
    fn own_quantization(self) -> Option<Quantization> {
        (self == AreaContender::Method(AreaMethod::FtGrays)).then_some(Quantization::FtGrays)
    }

    /// The contender's own output for `shapes` on a `width` x `height` canvas at the
    /// origin, under [`Semantics::Accumulated`].
    ///
    /// # Errors
    /// The method's refusal (`ftgrays`: a coordinate outside its 24.8 envelope).
    pub fn draw(self, shapes: &[AreaShape], width: u32, height: u32) -> Result<AreaOutput, String> {
        match self {
            AreaContender::Method(m) => m.draw(shapes, width, height, SEMANTICS),
            AreaContender::Msaa(n) => msaa(shapes, width, height, n as usize),
        }
    }
}

/// The shapes' covered samples at the standard pattern of `n`, each shape's added: the
/// `scanline` model per sample under D3D11's convention (8 subpixel bits, nearest-even,
/// top-left), what a multisampling GPU resolves.
fn msaa(shapes: &[AreaShape], width: u32, height: u32, n: usize) -> Result<AreaOutput, String> {
    let pattern = SamplePattern::standard(n).ok_or_else(|| format!("no standard {n}x pattern"))?;
    let target = Target::new(width, height, Preset::D3d11.convention()).ok_or("canvas outside the limits")?;
    let primitives = Primitives {
        polygons: shapes.to_vec(),
        ..Primitives::default()
    };
    let coverage = render_samples(&primitives, &target, &pattern, Model::Scanline).map_err(|e| e.to_string())?;
    let mut counts = vec![0u32; width as usize * height as usize];
    for c in coverage.samples() {
        for (x, y, ids) in c.iter() {
            counts[y as usize * width as usize + x as usize] += u32::try_from(ids.len()).unwrap_or(u32::MAX);
        }
    }
    Ok(AreaOutput::Counts {
        counts,
        of: u32::try_from(n).expect("at most 16"),
    })
}

/// `image` as a dense row-major vector.
fn dense(image: &AreaImage) -> Vec<BigRational> {
    let mut out = vec![BigRational::zero(); image.width as usize * image.height as usize];
    for (x, y, v) in &image.pixels {
        out[*y as usize * image.width as usize + *x as usize] = v.clone();
    }
    out
}

/// The error metrics of `output` against the exact `reference` (see the module
/// documentation); `own` is the quantization an 8-bit model applies, for
/// [`LEVELS_OFF`].
pub fn area_metrics(reference: &AreaImage, output: &AreaOutput, own: Option<Quantization>) -> Vec<Metric> {
    let exact = dense(reference);
    let theirs = match output {
        AreaOutput::Exact(image) => dense(image),
        _ => Vec::new(),
    };
    let half = BigRational::new(1.into(), 510.into());
    let quantum = BigRational::from_integer(255.into());
    let (mut pixels, mut off, mut levels_off) = (0u64, 0u64, 0u64);
    let mut max = BigRational::zero();
    let mut sum = 0f64;
    for (k, e) in exact.iter().enumerate() {
        let v = output.value(k, &theirs);
        if v.is_zero() && e.is_zero() {
            continue;
        }
        pixels += 1;
        if let (Some(q), Some(l)) = (own, output.own_levels()) {
            levels_off += u64::from(q.level(e) != l[k]);
        }
        if v == *e {
            continue;
        }
        let d = (&v - e).abs();
        if d > half {
            off += 1;
        }
        sum += (&d * &quantum).to_f64().unwrap_or(f64::INFINITY);
        if d > max {
            max = d;
        }
    }
    let max = if max.is_zero() {
        0.0
    } else {
        // Never 0 for a non-zero error.
        (&max * &quantum)
            .to_f64()
            .unwrap_or(f64::INFINITY)
            .max(f64::MIN_POSITIVE)
    };
    #[allow(clippy::cast_precision_loss)] // pixel counts far below 2^53
    let mean = if pixels == 0 { 0.0 } else { sum / pixels as f64 };
    let mut out = vec![
        Metric::Rate {
            name: OFF_HALF_QUANTUM,
            count: off,
            of: pixels,
        },
        Metric::Quanta {
            name: COVERAGE_ERROR,
            max,
            mean,
            pixels,
        },
    ];
    if own.is_some() {
        out.push(Metric::Rate {
            name: LEVELS_OFF,
            count: levels_off,
            of: pixels,
        });
    }
    out
}

/// One area workload.
struct Workload {
    name: String,
    description: String,
    shapes: Vec<AreaShape>,
    width: u32,
    height: u32,
}

/// The committed glyph scene's polygons and canvas, scaled by `px / 24` exactly.
pub fn glyphs(px: u32) -> (Vec<AreaShape>, u32, u32) {
    let scene = crate::scene::parse_scene(DEJAVU, "adapters/scenes/dejavu.json").expect("the committed glyph scene");
    let target = scene.target().expect("its canvas");
    let s = BigRational::new(px.into(), 24.into());
    let scale = |c: &[Point]| -> Vec<Point> { c.iter().map(|p| Point::new(&p.x * &s, &p.y * &s)).collect() };
    let shapes = scene
        .primitives()
        .polygons
        .iter()
        .map(|p| Polygon {
            outline: scale(&p.outline),
            holes: p.holes.iter().map(|h| scale(h)).collect(),
            fill_rule: p.fill_rule,
        })
        .collect();
    let side = |v: u32| (u64::from(v) * u64::from(px)).div_ceil(24);
    let (w, h) = (side(target.width), side(target.height));
    (
        shapes,
        u32::try_from(w).expect("a small canvas"),
        u32::try_from(h).expect("a small canvas"),
    )
}

fn workloads(config: &Config, sizes: &Sizes) -> Vec<Workload> {
    let mut out: Vec<Workload> = GLYPH_SIZES
        .iter()
        .map(|&px| {
            let (shapes, width, height) = glyphs(px);
            Workload {
                name: format!("glyphs at {px} px/em"),
                description: format!(
                    "DejaVu Sans \"g@&B%\" (adapters/scenes/dejavu.json, curves flattened at dyadic parameters) \
                     scaled exactly by {px}/24, each glyph polygon one shape, on its {width}x{height} canvas."
                ),
                shapes,
                width,
                height,
            }
        })
        .collect();
    let side = sizes.canvas;
    let points = 100 * sizes.count;
    let m = mesh(&mut runner(config.seed, "area mesh"), side, 8, points);
    out.push(Workload {
        name: "abutting mesh".into(),
        description: format!(
            "A spade Delaunay triangulation of {points} random points on the 1/256 px grid, each triangle its own \
             shape ({} triangles): a pixel's value accumulated across the triangles meeting it.",
            m.triangles.len()
        ),
        shapes: m.triangles.iter().map(crate::area::triangle_shape).collect(),
        width: side,
        height: side,
    });
    let count = 100 * sizes.count;
    let slivers = draw_n(
        &mut runner(config.seed, "area slivers"),
        &triangle(TriangleScale::Sliver, side),
        count,
    );
    out.push(Workload {
        name: "area slivers".into(),
        description: format!(
            "{count} random slivers (strategy::TriangleScale::Sliver: long and thin, the third vertex within 4/256 px of the \
             line), each its own shape."
        ),
        shapes: slivers.iter().map(crate::area::triangle_shape).collect(),
        width: side,
        height: side,
    });
    out
}

/// Measures every area workload.
pub(crate) fn run(config: &Config, sizes: &Sizes, progress: &mut dyn FnMut(&str)) -> Vec<WorkloadReport> {
    workloads(config, sizes)
        .iter()
        .map(|w| {
            progress(&format!("area: {}", w.name));
            measure(w, config, sizes)
        })
        .collect()
}

/// The subset: the `side` x `side` px window (at most the canvas) centred on the middle
/// partly covered pixel of the exact answer `reference` (so that it holds edges), the shapes with a
/// non-zero exact value in it, moved by whole pixels so that the window is the canvas at the
/// origin (every model here is exact under that move, or measured at the origin anyway).
fn subset(w: &Workload, reference: &AreaImage, side: u32) -> (Vec<AreaShape>, u32, u32) {
    let (sw, sh) = (w.width.min(side), w.height.min(side));
    let partial: Vec<&(u32, u32, BigRational)> = reference.pixels.iter().filter(|p| !p.2.is_integer()).collect();
    let (cx, cy) = partial.get(partial.len() / 2).map_or((0, 0), |p| (p.0, p.1));
    let x0 = cx.saturating_sub(sw / 2).min(w.width - sw);
    let y0 = cy.saturating_sub(sh / 2).min(w.height - sh);
    let int = |v: u32| BigRational::from_integer(v.into());
    let (left, right, top, bottom) = (int(x0), int(x0 + sw), int(y0), int(y0 + sh));
    let meets = |s: &AreaShape| {
        let pts: Vec<&Point> = s.contours().flatten().collect();
        let min = |f: fn(&Point) -> &BigRational| pts.iter().map(|p| f(p)).min().cloned();
        let max = |f: fn(&Point) -> &BigRational| pts.iter().map(|p| f(p)).max().cloned();
        match (min(|p| &p.x), max(|p| &p.x), min(|p| &p.y), max(|p| &p.y)) {
            (Some(a), Some(b), Some(c), Some(d)) => a < right && b > left && c < bottom && d > top,
            _ => false,
        }
    };
    // Of those, the ones with a non-zero exact value in the window (a long sliver's
    // bounding box meets many windows that it does not touch).
    let shapes = w
        .shapes
        .iter()
        .filter(|s| meets(s))
        .map(|s| s.translated(-i64::from(x0), -i64::from(y0)))
        .filter(|s| !planned::accumulate(s, sw, sh).is_empty())
        .collect();
    (shapes, sw, sh)
}

/// The planned engine's arithmetic per magnitude: shapes in i128 and in big rationals.
fn plan(w: &Workload, mags: &[Magnitude]) -> PlanSummary {
    let count = |m: i64| {
        let i128s = w
            .shapes
            .iter()
            .filter(|s| planned::plan(&s.translated(m, m)) == planned::AreaWidth::I128)
            .count();
        (i128s, w.shapes.len() - i128s)
    };
    let (i, b) = count(0);
    let at: Vec<String> = mags
        .iter()
        .map(|m| {
            let (i, b) = count(m.px_i64());
            format!("{m} px: {i} i128, {b} big")
        })
        .collect();
    PlanSummary {
        model: "area-planned",
        by_width: vec![("i128", i), ("big", b)],
        summary: format!("shapes by arithmetic at the placed coordinates: {}", at.join("; ")),
    }
}

/// A workload with the exact answers its contenders are measured against: the whole
/// canvas's, and the subset's (for the contenders slow by design).
struct Stage<'a> {
    w: &'a Workload,
    reference: AreaImage,
    sub: Vec<AreaShape>,
    sub_size: (u32, u32),
    sub_reference: AreaImage,
}

impl<'a> Stage<'a> {
    /// The planned engine's answers on the workload and on its subset.
    fn new(w: &'a Workload, sizes: &Sizes) -> Stage<'a> {
        let reference = planned::rasterize(&w.shapes, w.width, w.height, SEMANTICS);
        let (sub, sw, sh) = subset(w, &reference, sizes.area_subset);
        let sub_reference = planned::rasterize(&sub, sw, sh, SEMANTICS);
        Stage {
            w,
            reference,
            sub,
            sub_size: (sw, sh),
            sub_reference,
        }
    }

    /// What `c` runs on: its shapes, canvas and exact answer.
    fn pick(&self, c: AreaContender) -> (&[AreaShape], u32, u32, &AreaImage) {
        if c.on_subset() {
            (&self.sub, self.sub_size.0, self.sub_size.1, &self.sub_reference)
        } else {
            (&self.w.shapes, self.w.width, self.w.height, &self.reference)
        }
    }
}

fn measure(w: &Workload, config: &Config, sizes: &Sizes) -> WorkloadReport {
    let stage = Stage::new(w, sizes);
    let speed = speed_at_origin(&stage, sizes);
    let origin = errors_at_origin(&stage);
    let cells = errors_by_magnitude(&stage, &origin, &config.magnitudes);
    WorkloadReport {
        name: w.name.clone(),
        family: Family::Area,
        description: w.description.clone(),
        primitives: w.shapes.len(),
        unit: "Mpix/s",
        baseline: AreaMethod::REFERENCE.name(),
        on_grid: true,
        plans: vec![plan(w, &config.magnitudes)],
        speed,
        cells,
        axis: Axis::Offset,
    }
}

/// Every contender's speed at the origin, round-robin.
fn speed_at_origin(stage: &Stage<'_>, sizes: &Sizes) -> Vec<SpeedEntry> {
    let contenders: Vec<Contender<'_>> = AreaContender::ALL
        .iter()
        .map(|&m| {
            let (shapes, width, height, r) = stage.pick(m);
            let jobs = m.draw(shapes, width, height).map(|_| {
                let job: Job<'_> = Box::new(move || m.draw(shapes, width, height).map_or(0, |o| o.len() as u64));
                (job, None)
            });
            Contender {
                name: m.name().into(),
                exact: m.is_exact(),
                reference: AreaMethod::REFERENCE.name(),
                elements: r.pixels.len() as u64,
                subset: m.on_subset(),
                jobs,
            }
        })
        .collect();
    entries(contenders, sizes.repetitions, sizes.min_pass_seconds)
}

/// Every contender's errors at the origin, by its own code, or its refusal.
fn errors_at_origin(stage: &Stage<'_>) -> Vec<(AreaContender, Outcome)> {
    AreaContender::ALL
        .iter()
        .map(|&m| {
            let (shapes, width, height, r) = stage.pick(m);
            let outcome = match m.draw(shapes, width, height) {
                Ok(out) => Outcome::Measured {
                    placement: Placement::OnCanvas,
                    metrics: area_metrics(r, &out, m.own_quantization()),
                },
                Err(e) => Outcome::Refused(e),
            };
            (m, outcome)
        })
        .collect()
}

/// Every contender's errors at each magnitude: computed anew with the placed coordinates
/// by the methods that round them ([`AreaMethod::draw_at`]), the origin's for the others
/// (a whole-pixel move leaves them unchanged).
fn errors_by_magnitude(stage: &Stage<'_>, origin: &[(AreaContender, Outcome)], magnitudes: &[Magnitude]) -> Vec<Cell> {
    let w = stage.w;
    let mut cells = Vec::new();
    for &mag in magnitudes {
        let at = mag.px_i64();
        for (m, at_origin) in origin {
            let placed = match m {
                AreaContender::Method(method) if at != 0 => method.draw_at(&w.shapes, at, w.width, w.height, SEMANTICS),
                _ => None,
            };
            let outcome = match placed {
                Some(Ok(out)) => Outcome::Measured {
                    placement: Placement::AtMagnitude,
                    metrics: area_metrics(&stage.reference, &out, m.own_quantization()),
                },
                Some(Err(e)) => Outcome::Refused(e),
                None if at == 0 => at_origin.clone(),
                None => match at_origin {
                    Outcome::Measured { metrics, .. } => Outcome::Measured {
                        placement: Placement::Translated,
                        metrics: metrics.clone(),
                    },
                    refused => refused.clone(),
                },
            };
            cells.push(Cell {
                magnitude: mag,
                contender: m.name().into(),
                outcome,
            });
        }
    }
    cells
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::area::{float, ftgrays};

    /// The far f32 walk at origin 0 is the model itself; at 2^10, the model on a canvas
    /// that reaches the window, restricted to it.
    #[test]
    fn far_f32_equals_the_model_where_a_canvas_reaches() {
        let (shapes, w, h) = glyphs(9);
        assert_eq!(
            float::rasterize_at(&shapes, 0, w, h, SEMANTICS),
            float::rasterize(&shapes, w, h, SEMANTICS)
        );
        let m = 1i64 << 10;
        let mu = u32::try_from(m).unwrap();
        let placed: Vec<AreaShape> = shapes.iter().map(|s| s.translated(m, m)).collect();
        let big = float::rasterize(&placed, mu + w, mu + h, SEMANTICS);
        let window: Vec<f32> = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| big[((mu + y) * (mu + w) + mu + x) as usize])
            .collect();
        let far = float::rasterize_at(&placed, m, w, h, SEMANTICS);
        assert_eq!(far, window);
        // And f32 rounds there: the far answer is not the origin's.
        assert_ne!(far, float::rasterize(&shapes, w, h, SEMANTICS));
    }

    /// `ftgrays::rasterize_at` is the model on a canvas that reaches the window, restricted to it.
    #[test]
    fn ftgrays_at_equals_the_model_where_a_canvas_reaches() {
        let (shapes, w, h) = glyphs(9);
        assert_eq!(
            ftgrays::rasterize_at(&shapes, 0, w, h).unwrap(),
            ftgrays::rasterize(&shapes, w, h).unwrap()
        );
        let m = 1i64 << 10;
        let mu = u32::try_from(m).unwrap();
        let placed: Vec<AreaShape> = shapes.iter().map(|s| s.translated(m, m)).collect();
        let big = ftgrays::rasterize(&placed, mu + w, mu + h).unwrap();
        let window: Vec<u8> = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| big[((mu + y) * (mu + w) + mu + x) as usize])
            .collect();
        assert_eq!(ftgrays::rasterize_at(&shapes, m, w, h).unwrap(), window);
    }

    /// The glyph scene scales exactly: 7 polygons, 102x32 at 24 px/em, 850x267 at 200.
    #[test]
    fn the_glyphs_scale_exactly() {
        let (at24, w, h) = glyphs(24);
        assert_eq!((at24.len(), w, h), (7, 102, 32));
        let (at200, w, h) = glyphs(200);
        assert_eq!((w, h), (850, 267));
        let k = BigRational::new(200.into(), 24.into());
        assert_eq!(at200[0].outline[0].x, &at24[0].outline[0].x * &k);
    }
}
