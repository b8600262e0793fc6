//! The clipping workloads: segments against rectangles (Cohen-Sutherland) and polygon
//! outlines against convex windows (Sutherland-Hodgman), each exact, in f64 and in f32.
//! Every clipper runs on the placed inputs at every magnitude (clipping needs no canvas),
//! through [`Clipper`] (which converts the inputs and reads each output vertex back
//! exactly); each vertex is checked against the exact window
//! ([`crate::check::check_inside`]). The speed passes time the algorithms themselves on
//! inputs converted beforehand.

use glam::{DVec2, Vec2};
use num_rational::BigRational;
use proptest::prelude::{prop_oneof, BoxedStrategy, Strategy};

use crate::check::check_inside;
use crate::clip::arithmetic::{ClipArithmetic, Clipper};
use crate::clip::halfplane::{HalfPlane, HalfPlaneF32, HalfPlaneF64};
use crate::clip::{cohen_sutherland, sutherland_hodgman, Rect, Window};
use crate::geom::Point;
use crate::strategy::clip::{any_window, rect_window};
use crate::strategy::polygon::simple_polygon;
use crate::strategy::tie_heavy_coordinate;

use super::measure::CLIP_OUTSIDE;
use super::metric::Metric;
use super::report::{Axis, Cell, Outcome, Placement, SpeedEntry, WorkloadReport};
use super::speed::{entries, Contender, Job};
use super::workloads::{draw, place_point, place_window, runner};
use super::{Config, Family, Magnitude, Sizes};

/// The arithmetics of each workload's three contenders, in the order of their names.
const ARITHMETICS: [ClipArithmetic; 3] = [ClipArithmetic::Exact, ClipArithmetic::F64, ClipArithmetic::F32];

/// Measures the clipping workloads.
pub(crate) fn run(config: &Config, sizes: &Sizes, progress: &mut dyn FnMut(&str)) -> Vec<WorkloadReport> {
    progress("clipping: segments vs rectangles");
    let segments = segments(config, sizes);
    progress("clipping: polygons vs convex windows");
    vec![segments, polygons(config, sizes)]
}

/// The output vertices of one clip, read back exactly (`None`: not finite).
type Out = Vec<Option<Point>>;

/// Each case's output vertices in `arithmetic` through [`Clipper`] (one per case's
/// window), by `clip`; `None` when an input (a coordinate, a bound, a window line) does
/// not fit the float type.
fn clip_outputs<C>(
    cases: &[C],
    window: impl Fn(&C) -> &Window,
    arithmetic: ClipArithmetic,
    clip: impl Fn(&Clipper, &C) -> Result<Vec<Result<Point, String>>, String>,
) -> Option<Vec<Out>> {
    cases
        .iter()
        .map(|c| {
            let clipper = Clipper::new(arithmetic, Some(window(c))).ok()?;
            let out = clip(&clipper, c).ok()?;
            Some(out.into_iter().map(Result::ok).collect())
        })
        .collect()
}

/// Counts the outputs outside `window` (a non-finite one counts), and all outputs.
fn outside(outputs: &[Out], windows: &[Window]) -> (u64, u64) {
    let (mut out, mut all) = (0u64, 0u64);
    for (o, w) in outputs.iter().zip(windows) {
        for v in o {
            all += 1;
            let inside = v
                .as_ref()
                .is_some_and(|p| check_inside(std::slice::from_ref(p), w).is_ok());
            out += u64::from(!inside);
        }
    }
    (out, all)
}

/// A workload's speed entries from one round-robin run of `jobs` (one per arithmetic, in
/// [`ARITHMETICS`] order, `None` where refused).
fn speed_entries(names: [&'static str; 3], jobs: Vec<Option<Job<'_>>>, count: u64, sizes: &Sizes) -> Vec<SpeedEntry> {
    let contenders = names
        .iter()
        .zip(ARITHMETICS)
        .zip(jobs)
        .map(|((&name, a), job)| Contender {
            name: name.into(),
            exact: a == ClipArithmetic::Exact,
            reference: "the exact check",
            elements: count,
            subset: false,
            jobs: job
                .map(|j| (j, None))
                .ok_or_else(|| "the inputs do not fit the float type".to_string()),
        })
        .collect();
    entries(contenders, sizes.repetitions, sizes.min_pass_seconds)
}

fn cell(mag: Magnitude, name: &str, outcome: Outcome) -> Cell {
    Cell {
        magnitude: mag,
        contender: name.into(),
        outcome,
    }
}

fn placement(mag: Magnitude) -> Placement {
    if mag.px() == 0 {
        Placement::OnCanvas
    } else {
        Placement::AtMagnitude
    }
}

fn measured(mag: Magnitude, (count, of): (u64, u64)) -> Outcome {
    Outcome::Measured {
        placement: placement(mag),
        metrics: vec![Metric::Rate {
            name: CLIP_OUTSIDE,
            count,
            of,
        }],
    }
}

fn rect_of(w: &Window) -> &Rect {
    match w {
        Window::Rect(r) => r,
        Window::Convex(_) => unreachable!("rect_window draws rectangles"),
    }
}

/// A rectangle whose bounds are decimals with one digit (`12.3`), as a scene file writes
/// them: not dyadic, so a float type holds them only rounded (either way).
fn decimal_rect(canvas: u32) -> BoxedStrategy<Window> {
    let n = i64::from(canvas);
    let coordinate = (-1..=n, 0i64..10).prop_map(|(i, d)| BigRational::new((10 * i + d).into(), 10.into()));
    proptest::array::uniform4(coordinate)
        .prop_filter_map("empty rectangle", |[a, b, c, d]| {
            let (xmin, xmax) = if a <= c { (a, c) } else { (c, a) };
            let (ymin, ymax) = if b <= d { (b, d) } else { (d, b) };
            Window::rect(xmin, ymin, xmax, ymax).ok()
        })
        .boxed()
}

fn segments(config: &Config, sizes: &Sizes) -> WorkloadReport {
    let name = "segments vs rectangles";
    let count = 500 * sizes.count;
    let mut r = runner(config.seed, name);
    let ends = proptest::array::uniform4(tie_heavy_coordinate(sizes.canvas));
    let rect = prop_oneof![rect_window(sizes.canvas), decimal_rect(sizes.canvas)];
    let cases: Vec<(Point, Point, Window)> = (0..count)
        .map(|_| {
            let [ax, ay, bx, by] = draw(&mut r, &ends);
            (Point::new(ax, ay), Point::new(bx, by), draw(&mut r, &rect))
        })
        .collect();
    let names = ["cohen-sutherland", "cs-f64", "cs-f32"];

    // Speed at the origin, inputs converted once: the jobs call each arithmetic's
    // Cohen-Sutherland directly, since going through `Clipper` would time its conversions
    // and read-back too.
    let c64: Option<Vec<(DVec2, DVec2, cohen_sutherland::RectF64)>> = cases
        .iter()
        .map(|(a, b, w)| Some((a.to_f64()?, b.to_f64()?, rect_of(w).to_f64()?)))
        .collect();
    let c32: Option<Vec<(Vec2, Vec2, cohen_sutherland::RectF32)>> = cases
        .iter()
        .map(|(a, b, w)| Some((a.to_f32()?, b.to_f32()?, rect_of(w).to_f32()?)))
        .collect();
    let jobs: Vec<Option<Job<'_>>> = vec![
        Some(Box::new(|| {
            let kept = cases
                .iter()
                .filter_map(|(a, b, w)| cohen_sutherland::clip_exact(a, b, rect_of(w)));
            kept.count() as u64
        })),
        c64.as_ref().map(|c| -> Job<'_> {
            Box::new(move || {
                c.iter()
                    .filter_map(|(a, b, r)| cohen_sutherland::clip_f64(*a, *b, r))
                    .count() as u64
            })
        }),
        c32.as_ref().map(|c| -> Job<'_> {
            Box::new(move || {
                c.iter()
                    .filter_map(|(a, b, r)| cohen_sutherland::clip_f32(*a, *b, r))
                    .count() as u64
            })
        }),
    ];
    let speed = speed_entries(names, jobs, count as u64, sizes);

    let mut cells = Vec::new();
    for &mag in &config.magnitudes {
        let m = mag.px_i64();
        let placed: Vec<(Point, Point, Window)> = cases
            .iter()
            .map(|(a, b, w)| (place_point(a, m), place_point(b, m), place_window(w, m)))
            .collect();
        let windows: Vec<Window> = placed.iter().map(|(_, _, w)| w.clone()).collect();
        for (name, arithmetic) in names.iter().zip(ARITHMETICS) {
            let outputs = clip_outputs(
                &placed,
                |(_, _, w)| w,
                arithmetic,
                |clipper, (a, b, _)| {
                    let ends = clipper.segment_ends(a, b, "a segment")?;
                    Ok(ends.map(Vec::from).unwrap_or_default())
                },
            );
            let outcome = match outputs {
                None => Outcome::Refused("a coordinate does not fit the float type".into()),
                Some(o) => measured(mag, outside(&o, &windows)),
            };
            cells.push(cell(mag, name, outcome));
        }
    }
    WorkloadReport {
        name: name.into(),
        family: Family::Clipping,
        description: format!(
            "{count} segments with tie-heavy endpoints (pixel centres, corners, k/512 px) against rectangles with \
             tie-heavy bounds (strategy::clip::rect_window) or one-digit decimal bounds (12.3 px); errors: output \
             endpoints outside the window."
        ),
        primitives: count,
        unit: "Mprim/s",
        baseline: "cohen-sutherland",
        on_grid: false,
        plans: Vec::new(),
        speed,
        cells,
        axis: Axis::Offset,
    }
}

fn polygons(config: &Config, sizes: &Sizes) -> WorkloadReport {
    let name = "polygons vs convex windows";
    let count = 100 * sizes.count;
    let mut r = runner(config.seed, name);
    let subject = simple_polygon(sizes.canvas, 12);
    let window = any_window(sizes.canvas);
    let cases: Vec<(Vec<Point>, Window)> = (0..count)
        .map(|_| (draw(&mut r, &subject).outline, draw(&mut r, &window)))
        .collect();
    let names = ["sutherland-hodgman", "sh-f64", "sh-f32"];

    // Speed at the origin, inputs converted once: the jobs call each arithmetic's
    // Sutherland-Hodgman directly, since going through `Clipper` would time its conversions
    // and read-back too.
    type F64Case = (Vec<DVec2>, Vec<HalfPlaneF64>);
    type F32Case = (Vec<Vec2>, Vec<HalfPlaneF32>);
    let planes: Vec<Vec<HalfPlane>> = cases.iter().map(|(_, w)| w.half_planes()).collect();
    let c64: Option<Vec<F64Case>> = cases
        .iter()
        .zip(&planes)
        .map(|((s, _), p)| {
            Some((
                s.iter().map(Point::to_f64).collect::<Option<_>>()?,
                p.iter().map(HalfPlane::to_f64).collect::<Option<_>>()?,
            ))
        })
        .collect();
    let c32: Option<Vec<F32Case>> = cases
        .iter()
        .zip(&planes)
        .map(|((s, _), p)| {
            Some((
                s.iter().map(Point::to_f32).collect::<Option<_>>()?,
                p.iter().map(HalfPlane::to_f32).collect::<Option<_>>()?,
            ))
        })
        .collect();
    let jobs: Vec<Option<Job<'_>>> = vec![
        Some(Box::new(|| {
            let sizes = cases
                .iter()
                .zip(&planes)
                .map(|((s, _), p)| sutherland_hodgman::clip_exact(s, p).len());
            sizes.sum::<usize>() as u64
        })),
        c64.as_ref().map(|c| -> Job<'_> {
            Box::new(move || {
                c.iter()
                    .map(|(s, p)| sutherland_hodgman::clip_f64(s, p).len())
                    .sum::<usize>() as u64
            })
        }),
        c32.as_ref().map(|c| -> Job<'_> {
            Box::new(move || {
                c.iter()
                    .map(|(s, p)| sutherland_hodgman::clip_f32(s, p).len())
                    .sum::<usize>() as u64
            })
        }),
    ];
    let speed = speed_entries(names, jobs, count as u64, sizes);

    let mut cells = Vec::new();
    for &mag in &config.magnitudes {
        let m = mag.px_i64();
        let placed: Vec<(Vec<Point>, Window)> = cases
            .iter()
            .map(|(s, w)| (s.iter().map(|p| place_point(p, m)).collect(), place_window(w, m)))
            .collect();
        let windows: Vec<Window> = placed.iter().map(|(_, w)| w.clone()).collect();
        for (name, arithmetic) in names.iter().zip(ARITHMETICS) {
            let outputs = clip_outputs(
                &placed,
                |(_, w)| w,
                arithmetic,
                |clipper, (subject, _)| clipper.contour_vertices(subject, "a polygon"),
            );
            let outcome = match outputs {
                None => Outcome::Refused("a coordinate or window line does not fit the float type".into()),
                Some(o) => measured(mag, outside(&o, &windows)),
            };
            cells.push(cell(mag, name, outcome));
        }
    }
    WorkloadReport {
        name: name.into(),
        family: Family::Clipping,
        description: format!(
            "{count} simple polygon outlines (strategy::polygon::simple_polygon) against rectangles and strictly \
             convex windows (strategy::clip::any_window); errors: output vertices outside the window."
        ),
        primitives: count,
        unit: "Mprim/s",
        baseline: "sutherland-hodgman",
        on_grid: false,
        plans: Vec::new(),
        speed,
        cells,
        axis: Axis::Offset,
    }
}
