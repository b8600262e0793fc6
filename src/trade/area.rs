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
//! - **Contenders** ([`AreaModel`]): the planned exact engine (`area::planned`, the
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
//!   second on glyph outlines of hundreds of edges) run on a 12 x 12 px window (4 x 4 with
//!   `--quick`) centred on the middle partly covered pixel, with the shapes that have a non-zero
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
//!   [`float::rasterize_at`], `area::float`'s walk with its canvas origin at `(M, M)`;
//!   `ftgrays` by [`ftgrays::rasterize_at`], its 26.6 rounding and 24.8 envelope at the placed
//!   coordinates, the rest by the model. Beyond the envelope `ftgrays` refuses, with its
//!   own message.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};

use crate::area::{cells, exact, float, ftgrays, planned, supersample, AreaImage, AreaShape, Quantization, Semantics};
use crate::convention::{Preset, Target};
use crate::geom::{Point, Polygon};
use crate::model::{render_samples, Model, Primitives};
use crate::pattern::SamplePattern;
use crate::strategy::{triangle, TriangleScale};

use super::metric::Metric;
use super::report::{Cell, Outcome, Placement, PlanSummary, WorkloadReport};
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

/// The samples per side of the sample-counting contenders.
const SAMPLES: u32 = 4;

/// An area contender.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AreaModel {
    /// `area::exact`, the plain oracle (subset).
    Plain,
    /// `area::cells`, exact accumulation in big rationals (subset).
    Cells,
    /// `area::planned`, the planned exact engine: the reference.
    Planned,
    /// `area::float`, f32 accumulation.
    Float,
    /// `area::ftgrays`, FreeType's 24.8 integer cells, 8-bit levels.
    FtGrays,
    /// `area::supersample` with 4 x 4 samples, counted exactly (subset).
    Supersample,
    /// `area::supersample::tiny_skia_levels`, tiny-skia's 4 sub-scanlines (subset).
    TinySkia,
    /// Multisampling at the standard 4x positions: the `scanline` model per sample
    /// (`model::render_samples`), vertices snapped to 8 subpixel bits as a GPU snaps them,
    /// each shape's covered samples counted.
    Msaa4,
    /// The same at the standard 8x positions.
    Msaa8,
    /// The same at the standard 16x positions.
    Msaa16,
}

impl AreaModel {
    /// Every contender, in report order.
    pub const ALL: [AreaModel; 10] = [
        AreaModel::Plain,
        AreaModel::Cells,
        AreaModel::Planned,
        AreaModel::Float,
        AreaModel::FtGrays,
        AreaModel::Supersample,
        AreaModel::TinySkia,
        AreaModel::Msaa4,
        AreaModel::Msaa8,
        AreaModel::Msaa16,
    ];

    /// Its name in the report.
    pub fn name(self) -> &'static str {
        match self {
            AreaModel::Plain => "area-plain",
            AreaModel::Cells => "area-cells",
            AreaModel::Planned => "area-planned",
            AreaModel::Float => "f32-accum",
            AreaModel::FtGrays => "ftgrays",
            AreaModel::Supersample => "supersample-4x4",
            AreaModel::TinySkia => "tiny-skia-4x4",
            AreaModel::Msaa4 => "msaa-4x",
            AreaModel::Msaa8 => "msaa-8x",
            AreaModel::Msaa16 => "msaa-16x",
        }
    }

    /// Computes the exact value (its error must be zero).
    pub fn is_exact(self) -> bool {
        matches!(self, AreaModel::Plain | AreaModel::Cells | AreaModel::Planned)
    }

    /// Runs on the subset (slow by design).
    fn on_subset(self) -> bool {
        matches!(
            self,
            AreaModel::Plain | AreaModel::Cells | AreaModel::Supersample | AreaModel::TinySkia
        )
    }

    /// The model's own output for `shapes` on a `width` x `height` canvas at the origin.
    ///
    /// # Errors
    /// `ftgrays`'s refusal (a coordinate outside its 24.8 envelope).
    pub fn draw(self, shapes: &[AreaShape], width: u32, height: u32) -> Result<AreaOutput, String> {
        Ok(match self {
            AreaModel::Plain => AreaOutput::Exact(exact::rasterize(shapes, width, height, SEMANTICS)),
            AreaModel::Cells => AreaOutput::Exact(
                cells::rasterize(shapes, width, height, SEMANTICS).expect("cells take the accumulated semantics"),
            ),
            AreaModel::Planned => AreaOutput::Exact(planned::rasterize(shapes, width, height, SEMANTICS)),
            AreaModel::Float => AreaOutput::F32(float::rasterize(shapes, width, height, SEMANTICS)),
            AreaModel::FtGrays => AreaOutput::Levels(ftgrays::rasterize(shapes, width, height)?),
            AreaModel::Supersample => {
                let mut counts = vec![0u32; width as usize * height as usize];
                let k2 = BigRational::from_integer(BigInt::from(SAMPLES * SAMPLES));
                for s in shapes {
                    let image = supersample::rasterize(std::slice::from_ref(s), width, height, SAMPLES);
                    for (x, y, v) in image.pixels {
                        let n = (v * &k2).to_integer().to_u32().unwrap_or(0);
                        counts[y as usize * width as usize + x as usize] += n;
                    }
                }
                AreaOutput::Counts {
                    counts,
                    of: SAMPLES * SAMPLES,
                }
            }
            AreaModel::TinySkia => {
                let mut levels = vec![0u8; width as usize * height as usize];
                for s in shapes {
                    let one = supersample::tiny_skia_levels(std::slice::from_ref(s), width, height);
                    for (l, v) in levels.iter_mut().zip(one) {
                        *l = l.saturating_add(v);
                    }
                }
                AreaOutput::Levels(levels)
            }
            AreaModel::Msaa4 => msaa(shapes, width, height, 4)?,
            AreaModel::Msaa8 => msaa(shapes, width, height, 8)?,
            AreaModel::Msaa16 => msaa(shapes, width, height, 16)?,
        })
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

/// What an area model outputs, row-major where dense.
#[derive(Debug, Clone, PartialEq)]
pub enum AreaOutput {
    /// Exact values.
    Exact(AreaImage),
    /// f32 values, read exactly.
    F32(Vec<f32>),
    /// 8-bit levels, `L` read as `L / 255`.
    Levels(Vec<u8>),
    /// Sample counts, `n` read as `n / of`.
    Counts {
        /// Per pixel.
        counts: Vec<u32>,
        /// Samples per pixel.
        of: u32,
    },
}

impl AreaOutput {
    /// The value of the pixel at row-major index `k`, exactly.
    fn value(&self, k: usize, dense: &[BigRational]) -> BigRational {
        match self {
            AreaOutput::Exact(_) => dense[k].clone(),
            AreaOutput::F32(v) => BigRational::from_float(v[k]).unwrap_or_else(BigRational::zero),
            AreaOutput::Levels(l) => BigRational::new(BigInt::from(l[k]), BigInt::from(255)),
            AreaOutput::Counts { counts, of } => BigRational::new(BigInt::from(counts[k]), BigInt::from(*of)),
        }
    }

    /// A number the optimiser must not drop.
    fn len(&self) -> u64 {
        match self {
            AreaOutput::Exact(i) => i.pixels.len() as u64,
            AreaOutput::F32(v) => v.len() as u64,
            AreaOutput::Levels(v) => v.len() as u64,
            AreaOutput::Counts { counts, .. } => counts.len() as u64,
        }
    }
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
        if let (Some(q), AreaOutput::Levels(l)) = (own, output) {
            levels_off += u64::from(q.level(e) != u16::from(l[k]));
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

fn measure(w: &Workload, config: &Config, sizes: &Sizes) -> WorkloadReport {
    let reference = planned::rasterize(&w.shapes, w.width, w.height, SEMANTICS);
    let (sub, sw, sh) = subset(w, &reference, sizes.area_subset);
    let sub_reference = planned::rasterize(&sub, sw, sh, SEMANTICS);
    let pick = |m: AreaModel| {
        if m.on_subset() {
            (&sub[..], sw, sh, &sub_reference)
        } else {
            (&w.shapes[..], w.width, w.height, &reference)
        }
    };

    // Speed at the origin, round-robin.
    let contenders: Vec<Contender<'_>> = AreaModel::ALL
        .iter()
        .map(|&m| {
            let (shapes, width, height, r) = pick(m);
            let jobs = m.draw(shapes, width, height).map(|_| {
                let job: Job<'_> = Box::new(move || m.draw(shapes, width, height).map_or(0, |o| o.len()));
                (job, None)
            });
            Contender {
                name: m.name().into(),
                exact: m.is_exact(),
                reference: AreaModel::Planned.name(),
                elements: r.pixels.len() as u64,
                subset: m.on_subset(),
                jobs,
            }
        })
        .collect();
    let speed = entries(contenders, sizes.repetitions, sizes.min_pass_seconds);

    // Errors at the origin, by each model's own code.
    let own = |m: AreaModel| (m == AreaModel::FtGrays).then_some(Quantization::FtGrays);
    let origin: Vec<(AreaModel, Outcome)> = AreaModel::ALL
        .iter()
        .map(|&m| {
            let (shapes, width, height, r) = pick(m);
            let outcome = match m.draw(shapes, width, height) {
                Ok(out) => Outcome::Measured {
                    placement: Placement::OnCanvas,
                    metrics: area_metrics(r, &out, own(m)),
                },
                Err(e) => Outcome::Refused(e),
            };
            (m, outcome)
        })
        .collect();
    let mut cells = Vec::new();
    for &mag in &config.magnitudes {
        let at = mag.px_i64();
        let placed: Vec<AreaShape> = if at == 0 {
            Vec::new()
        } else {
            w.shapes.iter().map(|s| s.translated(at, at)).collect()
        };
        for (m, at_origin) in &origin {
            let outcome = match (at, m) {
                (0, _) => at_origin.clone(),
                (_, AreaModel::Float) => {
                    let out = AreaOutput::F32(float::rasterize_at(&placed, at, w.width, w.height, SEMANTICS));
                    Outcome::Measured {
                        placement: Placement::AtMagnitude,
                        metrics: area_metrics(&reference, &out, None),
                    }
                }
                (_, AreaModel::FtGrays) => match ftgrays::rasterize_at(&w.shapes, at, w.width, w.height) {
                    Ok(levels) => Outcome::Measured {
                        placement: Placement::AtMagnitude,
                        metrics: area_metrics(&reference, &AreaOutput::Levels(levels), own(*m)),
                    },
                    Err(e) => Outcome::Refused(e),
                },
                _ => match at_origin {
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
    WorkloadReport {
        name: w.name.clone(),
        family: Family::Area,
        description: w.description.clone(),
        primitives: w.shapes.len(),
        unit: "Mpix/s",
        baseline: AreaModel::Planned.name(),
        on_grid: true,
        plans: vec![plan(w, &config.magnitudes)],
        speed,
        cells,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
