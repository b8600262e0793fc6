//! The line workloads: Bresenham lines with integer endpoints (the exact ideal line,
//! integer Bresenham with both ties, the f32 and f64 DDAs) and diamond-exit lines with
//! tie-heavy endpoints (the plain and planned exact readings, the integer test). Bresenham
//! pixels are walked at every magnitude with the placed endpoints (a pixel list needs no
//! canvas); diamond-exit lines are exact contenders (see [`super::exact_only`]).

use crate::check::line_departures;
use crate::convention::{Preset, Target};
use crate::geom::Point;
use crate::line::exact::{ideal, resolve};
use crate::line::{bresenham, dda, BresenhamTie, Line, LineRule};
use crate::model::{prepare, Model, Primitives};
use crate::num::fixed::snap;
use crate::strategy::{diamond_line, pixel_line};

use super::exact_only::{self, Spec};
use super::measure::{LINE_HALF_PIXEL, LINE_REFERENCE};
use super::metric::Metric;
use super::report::{Axis, Cell, Outcome, Placement, WorkloadReport};
use super::speed::{entries, model_jobs, Contender};
use super::workloads::{draw_n, place_lines, runner};
use super::{Config, Family, Sizes};

/// A Bresenham-line contender.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Walk {
    /// The exact ideal line (the reference), ties as `stay`.
    Exact,
    /// Integer Bresenham.
    Bresenham(BresenhamTie),
    /// The f32 DDA.
    Dda32,
    /// The f64 DDA.
    Dda64,
}

impl Walk {
    const ALL: [Walk; 5] = [
        Walk::Exact,
        Walk::Bresenham(BresenhamTie::Stay),
        Walk::Bresenham(BresenhamTie::Step),
        Walk::Dda32,
        Walk::Dda64,
    ];

    fn name(self) -> &'static str {
        match self {
            Walk::Exact => "exact",
            Walk::Bresenham(BresenhamTie::Stay) => "bresenham/stay",
            Walk::Bresenham(BresenhamTie::Step) => "bresenham/step",
            Walk::Dda32 => "dda32",
            Walk::Dda64 => "dda64",
        }
    }

    /// The model that draws it, and the tie its lines carry.
    fn model(self) -> (Model, BresenhamTie) {
        match self {
            Walk::Exact => (Model::Exact, BresenhamTie::Stay),
            Walk::Bresenham(tie) => (Model::Fixed, tie),
            Walk::Dda32 => (Model::Float32, BresenhamTie::Stay),
            Walk::Dda64 => (Model::Float64, BresenhamTie::Stay),
        }
    }

    /// The tie of the exact reference it is compared with.
    fn tie(self) -> BresenhamTie {
        self.model().1
    }

    fn pixels(self, a: [i64; 2], b: [i64; 2]) -> Vec<[i64; 2]> {
        match self {
            Walk::Exact => resolve(&ideal(a, b), BresenhamTie::Stay),
            Walk::Bresenham(tie) => bresenham::pixels(a, b, tie),
            Walk::Dda32 => dda::pixels_f32(a, b),
            Walk::Dda64 => dda::pixels_f64(a, b),
        }
    }
}

/// Measures the line workloads.
pub(crate) fn run(config: &Config, sizes: &Sizes, progress: &mut dyn FnMut(&str)) -> Vec<WorkloadReport> {
    progress("lines: bresenham lines");
    let bresenham = bresenham_lines(config, sizes);
    progress("lines: diamond-exit lines");
    vec![bresenham, diamond_lines(config, sizes)]
}

fn as_line((a, b): ([i64; 2], [i64; 2]), tie: BresenhamTie) -> Line {
    Line {
        from: Point::from_ints(a[0], a[1]),
        to: Point::from_ints(b[0], b[1]),
        rule: LineRule::Bresenham(tie),
    }
}

fn bresenham_lines(config: &Config, sizes: &Sizes) -> WorkloadReport {
    let name = "bresenham lines";
    let side = i64::from(sizes.canvas);
    let count = 100 * sizes.count;
    let ends = draw_n(&mut runner(config.seed, name), &pixel_line(side, 0), count);
    let target = Target::new(sizes.canvas, sizes.canvas, Preset::D3d11.convention()).expect("a valid canvas");
    let lines_with = |tie| Primitives {
        lines: ends.iter().map(|&e| as_line(e, tie)).collect(),
        ..Primitives::default()
    };
    // Every line has max(|dx|, |dy|) + 1 pixels, all on the canvas.
    let pixels: u64 = ends
        .iter()
        .map(|(a, b)| (a[0] - b[0]).unsigned_abs().max((a[1] - b[1]).unsigned_abs()) + 1)
        .sum();

    let prims: Vec<Primitives> = Walk::ALL.iter().map(|w| lines_with(w.model().1)).collect();
    let contenders = Walk::ALL
        .iter()
        .zip(&prims)
        .map(|(&walk, p)| Contender {
            name: walk.name().into(),
            exact: walk.model().0.is_exact(),
            reference: "exact",
            elements: pixels,
            subset: false,
            jobs: model_jobs(walk.model().0, p, &target),
        })
        .collect();
    let speed = entries(contenders, sizes.repetitions, sizes.min_pass_seconds);

    let mut cells = Vec::new();
    for &mag in &config.magnitudes {
        let m = mag.px_i64();
        let placed: Vec<([i64; 2], [i64; 2])> = ends
            .iter()
            .map(|(a, b)| ([a[0] + m, a[1] + m], [b[0] + m, b[1] + m]))
            .collect();
        // The exact references of both ties, once per magnitude (when some walk runs).
        let mut references: Option<References> = None;
        for walk in Walk::ALL {
            let (model, tie) = walk.model();
            let prims = Primitives {
                lines: placed.iter().map(|&e| as_line(e, tie)).collect(),
                ..Primitives::default()
            };
            let outcome = match prepare(&prims, &target, model) {
                Err(e) => Outcome::Refused(e.to_string()),
                Ok(_) => Outcome::Measured {
                    placement: if m == 0 {
                        Placement::OnCanvas
                    } else {
                        Placement::AtMagnitude
                    },
                    metrics: walk_metrics(
                        walk,
                        &placed,
                        references.get_or_insert_with(|| References::of(&placed)),
                        pixels,
                    ),
                },
            };
            cells.push(Cell {
                magnitude: mag,
                contender: walk.name().into(),
                outcome,
            });
        }
    }
    WorkloadReport {
        name: name.into(),
        family: Family::Lines,
        description: format!(
            "{count} lines between random pixels of the canvas (strategy::pixel_line), every octant; Bresenham \
             endpoints are pixel addresses."
        ),
        primitives: count,
        unit: "Mpix/s",
        baseline: "bresenham/stay",
        on_grid: true,
        plans: Vec::new(),
        speed,
        cells,
        axis: Axis::Offset,
    }
}

/// The exact reference pixels of every line, for each tie.
struct References {
    stay: Vec<Vec<[i64; 2]>>,
    step: Vec<Vec<[i64; 2]>>,
}

impl References {
    fn of(lines: &[([i64; 2], [i64; 2])]) -> References {
        let (mut stay, mut step) = (Vec::new(), Vec::new());
        for &(a, b) in lines {
            let line = ideal(a, b);
            stay.push(resolve(&line, BresenhamTie::Stay));
            step.push(resolve(&line, BresenhamTie::Step));
        }
        References { stay, step }
    }
}

/// Half-pixel departures and differences from the exact reference (same tie) of one
/// walk over every placed line.
fn walk_metrics(walk: Walk, lines: &[([i64; 2], [i64; 2])], refs: &References, pixels: u64) -> Vec<Metric> {
    let (mut departed, mut off) = (0u64, 0u64);
    let by_tie = match walk.tie() {
        BresenhamTie::Stay => &refs.stay,
        BresenhamTie::Step => &refs.step,
    };
    for (&(a, b), reference) in lines.iter().zip(by_tie) {
        let drawn = match walk {
            Walk::Exact => reference.clone(),
            _ => walk.pixels(a, b),
        };
        departed += line_departures(a, b, &drawn) as u64;
        off += reference.iter().zip(&drawn).filter(|(r, d)| r != d).count() as u64
            + reference.len().abs_diff(drawn.len()) as u64;
    }
    vec![
        Metric::Rate {
            name: LINE_HALF_PIXEL,
            count: departed,
            of: pixels,
        },
        Metric::Rate {
            name: LINE_REFERENCE,
            count: off,
            of: pixels,
        },
    ]
}

fn diamond_lines(config: &Config, sizes: &Sizes) -> WorkloadReport {
    let name = "diamond-exit lines";
    let count = 100 * sizes.count;
    let lines = draw_n(&mut runner(config.seed, name), &diamond_line(sizes.canvas), count);
    let conv = Preset::D3d11.convention();
    let select = |ids: &[usize]| Primitives {
        lines: ids.iter().map(|&k| lines[k].clone()).collect(),
        ..Primitives::default()
    };
    let place = |m: i64| Primitives {
        lines: place_lines(&lines, m),
        ..Primitives::default()
    };
    let on_grid = lines.iter().all(|l| {
        [&l.from, &l.to].iter().all(|p| {
            [&p.x, &p.y].iter().all(|v| {
                crate::num::exact::dyadic(&snap(v, conv.subpixel_bits, conv.rounding), conv.subpixel_bits) == **v
            })
        })
    });
    exact_only::measure(
        &Spec {
            name,
            family: Family::Lines,
            description: format!(
                "{count} diamond-exit lines (D3D11 3.4.3) with tie-heavy endpoints: pixel centres, corners, \
                 k/512 px (strategy::diamond_line)."
            ),
            count,
            select: &select,
            place: &place,
            models: &[
                ("exact-plain", Model::ExactPlain),
                ("exact", Model::Exact),
                ("exact-snapped-plain", Model::ExactSnappedPlain),
                ("exact-snapped", Model::ExactSnapped),
                ("fixed", Model::Fixed),
            ],
            baseline: "fixed",
            on_grid,
        },
        config,
        sizes,
    )
}
