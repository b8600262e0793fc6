//! The values family (`--family values`): interpolated attribute values at covered pixel
//! centres, every interpolator side by side: its speed on the origin's workload and, per
//! canvas offset and per attribute scale, its error against the exact value.
//!
//! - **Workloads**: seeded random triangles (vertex 0 on the 1/256 px grid anywhere on the
//!   canvas, the other two within 24 px of it) and a mesh (a grid of 8 px quads, its inner
//!   vertices jittered by up to a third of a cell on the 1/256 px grid, two triangles a
//!   quad), each vertex with a `w` of `k/4` (`k` in 1..=32, so 1/4 to 8) and three channels
//!   in (0, 1]: thirds `n/3`, tenths `n/10` (decimals no binary float holds) and 256ths
//!   (dyadic), `n` from 1. The triangles are interpolated `smooth` (perspective-correct) and
//!   `noperspective`, the mesh `smooth`. The covered pixels are the exact model's, under
//!   Vulkan's convention (centres at `+1/2`, top-left). No vertex value is 0, so no exact
//!   value is (each is a weighted mean of the vertices' with positive weights): where the
//!   exact value is 0 a float's rounding noise of 10^-9 is a billion f32 steps away (seen
//!   with zeros: 8.6 x 10^8 at the origin, from every plane model), which would hide every
//!   other error in the largest.
//! - **Canvas offset** ([`OFFSETS`]: 0, 2^4, ..., 2^24 px): every coordinate moved by
//!   `(M, M)` exactly, each pixel `(x, y)` becoming `(x + M, y + M)`, and every contender
//!   computing with the placed coordinates.
//! - **Attribute scale** ([`SCALES`]: 2^0, 2^4, ..., 2^32, the window at the origin): the two
//!   triangle workloads again, every value multiplied by the scale exactly.
//! - **Contenders** ([`ValueContender::ALL`]): `exact-plain`, the readable definition
//!   ([`ValueSetup::value`] in big rationals, rounded by [`nearest_f32`]; on a subset, the
//!   first triangles until the run's plain-oracle pixel count); `planned`, what `compare
//!   --as values` judges with ([`FastPlan`]'s f64 bound, [`PlannedValue`] where it cannot
//!   decide); four float models of [`crate::interp::float`], each unfused, vertices as
//!   given, the smooth quotient a multiply by the reciprocal, y down, from the renderer's
//!   f32 inputs ([`FloatTriangle::of`]): `f32-origin-plane` (planes of `f / w` and `1 / w`
//!   anchored at the framebuffer's origin, llvmpipe's form), `f32-vertex-plane` (anchored at
//!   vertex 0), `f32-barycentric` (edge functions at the centre) and `f64-origin-plane` (the
//!   origin plane in f64 arithmetic, rounded to f32 once); and `dda-q32.32`, the
//!   fixed-point Gouraud DDA of [`crate::interp::dda`] (Q32.32 in i64, perspective through
//!   a DDA of `1 / w` and an f64 divide), which refuses what its envelope does not hold.
//! - **Error**, per channel value at a covered pixel centre, against the exact value
//!   rounded to the nearest f32 (ties to even): decided by [`PlannedValue`]'s certified f64
//!   interval where it can, by the exact ratio in big rationals where it cannot. `ulps`:
//!   the count of f32 values between that and the contender's f32 (0: the correctly rounded
//!   value; a NaN counts [`NAN_STEPS`]), its 99th percentile and largest. `wrong UNORM8
//!   levels`, per million values: the contender's value divided by the attribute scale,
//!   clamped to [0, 1], times 255, rounded to nearest with ties to even (NaN to 0), against
//!   the exact value's nearest f32 under the same rule: the level an interpolator that
//!   rounds correctly writes. (The exact rational's own level differs from that only for a
//!   value within half an f32 step of a half level: 3/10 is 76.5/255, which rounds to the
//!   even 76, while its nearest f32 is above 3/10 and converts to 77; no f32 output can
//!   give 76 there, so those are not counted against a contender.)
//! - **Speed**: every contender over the origin's covered pixels, triangle by triangle,
//!   set up from inputs already in its own number type (as a renderer holds them: f32,
//!   f64, Q32.32, exact rationals), three channels a pixel, round-robin; Mpix/s counts
//!   covered (pixel, triangle) pairs, the ratio is to `f32-origin-plane`. The attribute
//!   sweep's workloads are the offset workloads' triangles at the origin: their speed is
//!   theirs.
//!
//! The workloads are in `workloads`, the error metrics in `metrics`.
//!
//! Scaling every value by a power of two commutes with every f32 and f64 rounding (short
//! of overflow and underflow), so the float models' errors in ulps are the same at every
//! attribute scale, figure for figure; the DDA's precision is absolute (2^-32), so its
//! error in ulps falls as the values grow, until its envelope ends.

use num_rational::BigRational;

use crate::geom::Point;
use crate::interp::dda::{DdaError, DdaTriangle, GouraudDda, Span};
use crate::interp::float::{Divide, FloatInterpolator, FloatTriangle, Form, VertexOrder};
use crate::interp::planned::{FastPlan, PlannedValue, TriangleF64};
use crate::interp::values::{Interpolation, ProvokingVertex, ValueSetup};
use crate::num::exact::nearest_f32;

use super::report::{Axis, Cell, Outcome, Placement, PlanSummary, SpeedEntry, WorkloadReport};
use super::speed::{entries, Contender, Job};
use super::{Config, Family, Magnitude, Sizes};

mod metrics;
mod workloads;

use metrics::metrics;
pub use metrics::{ulp_steps, NAN_STEPS, ULPS, WRONG_UNORM};
pub use workloads::{workloads, ValueTri, ValueWorkload};

/// The canvas offsets, px: 0, 2^4, 2^8, ..., 2^24.
pub const OFFSETS: [u64; 7] = [0, 1 << 4, 1 << 8, 1 << 12, 1 << 16, 1 << 20, 1 << 24];

/// The attribute scales of the sweep: 2^0, 2^4, ..., 2^32.
pub const SCALES: [u64; 9] = [1, 1 << 4, 1 << 8, 1 << 12, 1 << 16, 1 << 20, 1 << 24, 1 << 28, 1 << 32];

/// The values tables' legend, printed once above them.
pub const TABLES_NOTE: &str = "Values (family `values`): each error is per channel value at a covered pixel \
centre, against the exact value's nearest f32 (ties to even). `ulps` (p99/max) counts the f32 values between \
it and the contender's (0: correctly rounded; a NaN counts 2^32); `wrong UNORM8 levels` (per million values) \
compares the 8-bit UNORM levels of the two: the value divided by the attribute scale, clamped to [0, 1], times \
255, rounded to nearest with ties to even (NaN to 0). Offsets move every coordinate by (M, M) exactly; \
attribute scales multiply every value, the window at the origin.";

/// `f32-origin-plane`: llvmpipe's planes in f32, unfused.
const ORIGIN_F32: FloatInterpolator = float_model(Form::OriginPlane, false);
/// `f32-vertex-plane`.
const VERTEX_F32: FloatInterpolator = float_model(Form::VertexPlane, false);
/// `f32-barycentric`.
const BARYCENTRIC_F32: FloatInterpolator = float_model(Form::Barycentric, false);
/// `f64-origin-plane`.
const ORIGIN_F64: FloatInterpolator = float_model(Form::OriginPlane, true);

/// A float model as the trade runs it: unfused (a fused multiply-add without the target's
/// FMA is a library call, not the instruction a renderer built for its CPU uses), vertices
/// as given, the reciprocal, y down.
const fn float_model(form: Form, f64: bool) -> FloatInterpolator {
    FloatInterpolator {
        form,
        fma: false,
        order: VertexOrder::AsGiven,
        divide: Divide::Reciprocal,
        f64,
        y_up: false,
    }
}

/// One interpolator of the values family (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ValueContender {
    /// The readable definition in big rationals, rounded to the nearest f32.
    Plain,
    /// `FastPlan`, and `PlannedValue` where its bound cannot decide.
    Planned,
    /// A float model of [`crate::interp::float`].
    Float(FloatInterpolator),
    /// The fixed-point Gouraud DDA of [`crate::interp::dda`].
    Dda,
}

impl ValueContender {
    /// Every contender, in report order.
    pub const ALL: [ValueContender; 7] = [
        ValueContender::Plain,
        ValueContender::Planned,
        ValueContender::Float(ORIGIN_F32),
        ValueContender::Float(VERTEX_F32),
        ValueContender::Float(BARYCENTRIC_F32),
        ValueContender::Float(ORIGIN_F64),
        ValueContender::Dda,
    ];

    /// The speed baseline.
    pub const BASELINE: ValueContender = ValueContender::Float(ORIGIN_F32);

    /// Its name in the report.
    pub fn name(self) -> &'static str {
        match self {
            ValueContender::Plain => "exact-plain",
            ValueContender::Planned => "planned",
            ValueContender::Float(m) => match (m.form, m.f64) {
                (Form::OriginPlane, false) => "f32-origin-plane",
                (Form::VertexPlane, false) => "f32-vertex-plane",
                (Form::Barycentric, false) => "f32-barycentric",
                (Form::OriginPlane, true) => "f64-origin-plane",
                _ => "float",
            },
            ValueContender::Dda => "dda-q32.32",
        }
    }

    /// Computes the exact value's nearest f32 (its error must be zero).
    pub fn is_exact(self) -> bool {
        matches!(self, ValueContender::Plain | ValueContender::Planned)
    }

    /// Runs on the subset (the plain definition, slow by design).
    fn on_subset(self) -> bool {
        self == ValueContender::Plain
    }
}

/// A workload's triangles in every contender's number type, at one offset and scale.
struct Inputs {
    /// The exact setup.
    setup: ValueSetup,
    /// f32 inputs (`None`: one is not a finite f32).
    float: Option<FloatTriangle>,
    /// f64 inputs (`None`: the fast plan cannot take them; the exact path decides).
    f64: Option<TriangleF64>,
    /// Q32.32 inputs, or the DDA's refusal.
    dda: Result<DdaTriangle, DdaError>,
}

/// The pixel centres' offset in their pixels.
fn half() -> BigRational {
    BigRational::new(1.into(), 2.into())
}

fn inputs(w: &ValueWorkload, offset: u64, scale: u64) -> Vec<Inputs> {
    let centre = half();
    w.triangles
        .iter()
        .map(|t| {
            let setup = t.setup(offset, scale);
            Inputs {
                float: FloatTriangle::of(&setup),
                f64: TriangleF64::of(&setup, 0..3),
                dda: DdaTriangle::of(&setup, w.interpolation, ProvokingVertex::First, 0..3, &centre),
                setup,
            }
        })
        .collect()
}

/// Runs `c` over `inputs` (each triangle's covered pixels moved by `shift`), handing every
/// channel value to `sink` in order (triangle, pixel, channel); NaN where it has none. The
/// setup of each triangle is part of the work, from inputs already in the contender's
/// number type.
///
/// # Errors
/// The contender refuses the workload: the DDA outside its envelope, a float model whose
/// inputs f32 does not hold.
fn evaluate(
    c: ValueContender,
    interpolation: Interpolation,
    inputs: &[Inputs],
    pixels: &[Vec<(u32, u32)>],
    shift: u32,
    sink: &mut impl FnMut(f32),
) -> Result<(), String> {
    let first = ProvokingVertex::First;
    let mut out = [0f32; 3];
    for (k, (input, pixels)) in inputs.iter().zip(pixels).enumerate() {
        let at = |&(x, y): &(u32, u32)| (x + shift, y + shift);
        match c {
            ValueContender::Plain => {
                for p in pixels.iter().map(at) {
                    let centre = |v: u32| BigRational::from_integer(v.into()) + half();
                    let values = input
                        .setup
                        .value(interpolation, first, 0..3, &Point::new(centre(p.0), centre(p.1)));
                    for c in 0..3 {
                        sink(
                            values
                                .as_ref()
                                .ok()
                                .and_then(|v| nearest_f32(&v[c]))
                                .unwrap_or(f32::NAN),
                        );
                    }
                }
            }
            ValueContender::Planned => {
                let fast = input
                    .f64
                    .as_ref()
                    .map(|t| FastPlan::new(t, interpolation, first, (0.5, 0.5)));
                let mut slow: Option<Vec<PlannedValue>> = None;
                let mut decided = [None; 3];
                for p in pixels.iter().map(at) {
                    match &fast {
                        Some(f) => f.nearest_f32(p.0, p.1, &mut decided),
                        None => decided = [None; 3],
                    }
                    for (c, d) in decided.iter().enumerate() {
                        sink(d.unwrap_or_else(|| {
                            let plans = slow.get_or_insert_with(|| {
                                PlannedValue::channels(&input.setup, interpolation, first, 0..3, &half())
                            });
                            plans[c].nearest_f32(p.0, p.1).ok().flatten().unwrap_or(f32::NAN)
                        }));
                    }
                }
            }
            ValueContender::Float(model) => {
                let t = input
                    .float
                    .as_ref()
                    .ok_or_else(|| format!("triangle {k}: an input is not a finite f32"))?;
                // Y down: the canvas height is not read.
                let setup = model.setup(t, interpolation, first, 0..3, u32::MAX, 0.5);
                for p in pixels.iter().map(at) {
                    setup.values(p, &mut out);
                    out.iter().for_each(|&v| sink(v));
                }
            }
            ValueContender::Dda => {
                let t = input.dda.as_ref().map_err(|e| format!("triangle {k}: {e}"))?;
                let dda = GouraudDda::new(t).map_err(|e| format!("triangle {k}: {e}"))?;
                walk(&dda, pixels.iter().map(at), &mut |v| {
                    v.iter().for_each(|&v| sink(v));
                });
            }
        }
    }
    Ok(())
}

/// The DDA's walk over `pixels` (row by row): a new span where a row starts or skips a
/// pixel, one step to the next pixel otherwise.
fn walk(dda: &GouraudDda, pixels: impl Iterator<Item = (u32, u32)>, sink: &mut impl FnMut(&[f32])) {
    let mut out = [0f32; 3];
    let mut span: Option<(Span<'_>, (u32, u32))> = None;
    for p in pixels {
        let next = matches!(&span, Some((_, last)) if last.1 == p.1 && last.0 + 1 == p.0);
        match &mut span {
            Some((s, last)) if next => {
                s.step();
                *last = p;
            }
            _ => span = dda.span(p.0, p.1).map(|s| (s, p)),
        }
        match &span {
            Some((s, _)) => s.values(&mut out),
            None => out = [f32::NAN; 3],
        }
        sink(&out);
    }
}

/// The exact reference at every (triangle, pixel, channel) of `inputs`, in
/// [`evaluate`]'s order: the exact value's nearest f32 (`None`: no value, or none f32
/// holds).
fn references(
    interpolation: Interpolation,
    inputs: &[Inputs],
    pixels: &[Vec<(u32, u32)>],
    shift: u32,
) -> Vec<Option<f32>> {
    let mut out = Vec::new();
    for (input, pixels) in inputs.iter().zip(pixels) {
        let plans = PlannedValue::channels(&input.setup, interpolation, ProvokingVertex::First, 0..3, &half());
        for &(x, y) in pixels {
            let (x, y) = (x + shift, y + shift);
            out.extend(plans.iter().map(|p| p.nearest_f32(x, y).ok().flatten()));
        }
    }
    out
}

/// The first triangles that cover at least `pixels` pixels (at least one triangle).
fn subset_len(w: &ValueWorkload, pixels: u64) -> usize {
    let mut total = 0;
    for (k, p) in w.pixels.iter().enumerate() {
        if total >= pixels {
            return k.max(1);
        }
        total += p.len() as u64;
    }
    w.pixels.len()
}

/// Every contender's errors at magnitude `m` of `w`'s axis.
fn errors_at(w: &ValueWorkload, m: Magnitude, subset: usize) -> Vec<Cell> {
    let (offset, scale) = w.at(m);
    let inputs = inputs(w, offset, scale);
    let shift = u32::try_from(offset).expect("offsets are at most 2^24");
    let refs = references(w.interpolation, &inputs, &w.pixels, shift);
    let placement = if offset == 0 {
        Placement::OnCanvas
    } else {
        Placement::AtMagnitude
    };
    ValueContender::ALL
        .iter()
        .map(|&c| {
            let n = if c.on_subset() { subset } else { inputs.len() };
            let mut values = Vec::with_capacity(refs.len());
            let outcome = match evaluate(c, w.interpolation, &inputs[..n], &w.pixels[..n], shift, &mut |v| {
                values.push(v);
            }) {
                Ok(()) => Outcome::Measured {
                    placement,
                    metrics: metrics(&refs, &values, scale),
                },
                Err(reason) => Outcome::Refused(reason),
            };
            Cell {
                magnitude: m,
                contender: c.name().into(),
                outcome,
            }
        })
        .collect()
}

/// Every contender's speed on `w` at the origin, round-robin.
fn speed(w: &ValueWorkload, sizes: &Sizes, subset: usize) -> Vec<SpeedEntry> {
    let inputs = inputs(w, 0, 1);
    let inputs = &inputs;
    let contenders: Vec<Contender<'_>> = ValueContender::ALL
        .iter()
        .map(|&c| {
            let n = if c.on_subset() { subset } else { inputs.len() };
            let (ins, pixels) = (&inputs[..n], &w.pixels[..n]);
            let interpolation = w.interpolation;
            let jobs = evaluate(c, interpolation, ins, pixels, 0, &mut |_| {}).map(|()| {
                let job: Job<'_> = Box::new(move || {
                    let mut sum = 0u64;
                    let _ = evaluate(c, interpolation, ins, pixels, 0, &mut |v| {
                        sum = sum.wrapping_add(u64::from(v.to_bits()));
                    });
                    sum
                });
                (job, None)
            });
            Contender {
                name: c.name().into(),
                exact: c.is_exact(),
                reference: "exact",
                elements: pixels.iter().map(|p| p.len() as u64).sum(),
                subset: c.on_subset(),
                jobs,
            }
        })
        .collect();
    entries(contenders, sizes.repetitions, sizes.min_pass_seconds)
}

/// How `planned` decides at the origin: channel values by `FastPlan`'s f64 bound and by
/// the exact ratio.
fn plan(w: &ValueWorkload) -> PlanSummary {
    let (mut fast, mut exact) = (0usize, 0usize);
    let mut decided = [None; 3];
    for (t, pixels) in w.triangles.iter().zip(&w.pixels) {
        let plan = TriangleF64::of(&t.setup(0, 1), 0..3)
            .map(|f| FastPlan::new(&f, w.interpolation, ProvokingVertex::First, (0.5, 0.5)));
        for &(x, y) in pixels {
            match &plan {
                Some(p) => p.nearest_f32(x, y, &mut decided),
                None => decided = [None; 3],
            }
            let n = decided.iter().filter(|d| d.is_some()).count();
            fast += n;
            exact += 3 - n;
        }
    }
    PlanSummary {
        model: "planned",
        by_width: vec![("f64", fast), ("exact", exact)],
        summary: format!(
            "channel values at the origin decided by FastPlan's f64 bound: {fast}; by the exact ratio in big \
             rationals: {exact}"
        ),
    }
}

/// `w` as a report: its speed (or `speed`, its twin's on the same triangles), its plan and
/// its errors at every magnitude of its axis.
fn report(w: &ValueWorkload, speed: Vec<SpeedEntry>, subset: usize) -> WorkloadReport {
    let cells = w
        .magnitudes()
        .into_iter()
        .flat_map(|m| errors_at(w, m, subset))
        .collect();
    WorkloadReport {
        name: w.name.clone(),
        family: Family::Values,
        description: w.description.clone(),
        primitives: w.triangles.len(),
        unit: "Mpix/s",
        baseline: ValueContender::BASELINE.name(),
        on_grid: true,
        plans: vec![plan(w)],
        speed,
        cells,
        axis: w.axis,
    }
}

/// Measures every values workload, then the attribute sweep of the two triangle workloads.
pub(crate) fn run(config: &Config, sizes: &Sizes, progress: &mut dyn FnMut(&str)) -> Vec<WorkloadReport> {
    let mut out = Vec::new();
    let mut sweeps = Vec::new();
    for w in workloads(config) {
        progress(&format!("values: {}", w.name));
        let subset = subset_len(&w, sizes.plain_pixels);
        let speed = speed(&w, sizes, subset);
        out.push(report(&w, speed.clone(), subset));
        if w.name.ends_with("triangles") {
            let sweep = ValueWorkload {
                name: format!("{} by attribute scale", w.name),
                description: format!(
                    "The {} {} above at the origin, every value multiplied by the scale (exactly: a power of two); \
                     speed: theirs.",
                    w.triangles.len(),
                    w.name
                ),
                axis: Axis::AttributeScale,
                ..w
            };
            sweeps.push((sweep, speed, subset));
        }
    }
    for (w, speed, subset) in sweeps {
        progress(&format!("values: {}", w.name));
        out.push(report(&w, speed, subset));
    }
    out
}
