//! The planned exact engine for polygons: the oracle's decisions
//! ([`rasterize_exact`](super::rasterize_exact)), computed row by row with an active edge
//! table (Foley, van Dam, Feiner and Hughes, "Computer Graphics: Principles and Practice",
//! 2nd ed., §3.6, scan-converting polygons) in the narrowest arithmetic that provably holds
//! every value it adds ([`crate::num::plan`]).
//!
//! **PolygonSetup**, once per polygon, in exact integers. The scale `L` is the least common
//! multiple of the denominators of every vertex and of the pixel centre; coordinates are
//! taken relative to the first sample of the outline's pixel range (columns `0..=w`, rows
//! `0..=h` locally), so local pixel `(i, j)` has its sample at `(i L, j L)`. Only the
//! outline's range is swept: a sample outside the outline's closed bounding box has
//! winding number 0 around it (no edge crosses its row, or every crossing lies on one side
//! of it), so the oracle covers nothing there.
//!
//! Each edge with `dy != 0`, oriented downwards (top `t`, `(dx, dy) = bottom - t`,
//! `dy > 0`), reduced by `g = gcd(dx, dy)` (`dx' = dx / g`, `dy' = dy / g`), crosses the
//! rows of the module's crossing rule (`crosses_moved_row`): `t.y <= j L < bottom.y` under
//! the top rules, `t.y < j L <= bottom.y` under the bottom rules, clamped to `0..=h`. On
//! row `j` the crossing is right of pixel `i`'s moved sample exactly when `E(i L, j L) < 0`
//! for the downward edge under the left rules (`E = 0` moves the sample right of the
//! crossing), so pixels `i >= θ_j = ceil(N_j / d)` are at or right of it, with
//!
//! `N_j = t.x dy' + (j L - t.y) dx'`, `d = L dy' > 0`, `N_{j+1} = N_j + L dx'`;
//!
//! under the right rules a sample on the crossing moves left of it, so `N_j` takes one
//! more (`θ_j = floor(N_j / d) + 1 = ceil((N_j + 1) / d)`) and nothing else changes.
//! All-inclusive and all-exclusive run the top-left table; the samples lying exactly on
//! an edge are then found edge by edge at setup (those where `N_j` is a multiple of `d`,
//! and those on horizontal edges along sample rows) and decided by the oracle's closure /
//! interior test ([`PlannedPolygon::with_rule`]).
//!
//! The sweep of a row (the module's `Sweep`, shared with the scanline filler) only asks
//! which crossings have `θ_j <= i` for pixels `i` of the range, so `θ_j` is clamped to
//! `0..=w+1` without changing a pixel: the rows where `N_j <= 0` (`θ_j <= 0`) and where
//! `N_j > w d` (`θ_j > w`) take the constant `0` or `w + 1`, found at setup by one
//! division each (`N_j` is linear in `j`, so they are a prefix and a suffix of the edge's
//! rows), and the rows between them, the **middle**, where `1 <= θ_j <= w`, run the exact
//! DDA of [`crate::num::dda::CeilDda`]: `θ` and `r = θ d - N` (`0 <= r < d`) advance by
//! `floor(L dx' / d)` and `L dx' mod d`, carrying one when `r` goes negative. No division
//! per row, no rationals per pixel.
//!
//! **The bound.** The quotient `θ` and its step are pixel indices of the range (in
//! `1..=w` on the middle rows; the step's magnitude is below `w` when there are two middle
//! rows) and stay in `i64`. The planned width holds only what the DDA adds and compares:
//! `d`, the step `L dx' mod d` in `[0, d)`, the remainder `r` in `[0, d)`, `r - step` in
//! `(-d, d)` and `r - step + d` in `[0, d)`. So the largest magnitude reached is the
//! largest `d = L dy'` over the edges with at least two middle rows (the others never
//! step and keep no lane value), and that is the [`Bound`]. It is attained: `d` itself is
//! held.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::Zero;

use super::contains_exact_with;
use super::{closed_edges, Crossing, Sweep};
use crate::convention::{AnyTieRule, MovedSample, Target, TieRule};
use crate::coverage::CoverageSink;
use crate::geom::{FillRule, Point, Polygon};
use crate::num::lane::{InWidth, Lane, LaneState, Planned};
use crate::num::plan::{ceil_div, floor_div, index, indices_above, scale_of, scaled, Bound, Plan, Width};
use crate::raster::{exact_sample_range, ExactGrid, PixelRange};

/// One edge of the table, independent of the width: its rows, the constant thresholds
/// outside its middle rows, and the DDA's start and integer step.
#[derive(Debug, Clone)]
struct TableEdge {
    /// First and last local row it crosses (`0 <= first <= last <= h`).
    first: i64,
    last: i64,
    /// The middle rows `m0..=m1` (empty when `m0 > m1`), where the threshold is in `1..=w`.
    middle: [i64; 2],
    /// The clamped threshold (`0` or `w + 1`) on the rows before the middle.
    lead: i64,
    /// The clamped threshold on the rows after the middle.
    trail: i64,
    /// The threshold on row `m0`.
    q0: i64,
    /// `floor(L dx' / d)` (used only when the middle has two rows or more).
    step_q: i64,
    /// Which contour (0 the outline).
    contour: usize,
    /// `-1` for an edge going down the screen, `+1` going up.
    winding: i64,
    /// Its remainders in the lanes, when the middle has two rows or more.
    dda: Option<usize>,
}

/// What the DDA of one edge holds in the planned width: the remainder on row `m0`, the
/// divisor and the remainder's step.
#[derive(Debug, Clone)]
struct Remainders<T> {
    r0: T,
    d: T,
    step_r: T,
}

impl<T: Lane> Remainders<T> {
    fn from_big(v: &Remainders<BigInt>) -> Remainders<T> {
        Remainders {
            r0: T::from_big(&v.r0),
            d: T::from_big(&v.d),
            step_r: T::from_big(&v.step_r),
        }
    }
}

/// A polygon's state in each width: the remainders of its edges that step.
#[derive(Debug, Clone)]
struct PolygonLanes;

impl LaneState for PolygonLanes {
    type In<T: Lane> = Vec<Remainders<T>>;
    fn convert<T: Lane>(exact: &Vec<Remainders<BigInt>>) -> Vec<Remainders<T>> {
        exact.iter().map(Remainders::from_big).collect()
    }
}

/// The active edge table of one polygon, run in the planned width.
struct Sweeping<'a, S: ?Sized> {
    polygon: &'a PlannedPolygon,
    id: u32,
    sink: &'a mut S,
}

impl<S: CoverageSink + ?Sized> InWidth<PolygonLanes> for Sweeping<'_, S> {
    type Output = ();
    #[inline]
    fn run<T: Lane>(self, remainders: &Vec<Remainders<T>>) {
        self.polygon.traverse(remainders, self.id, self.sink);
    }
}

/// A polygon set up for the planned engine: its pixel range, edge table, plan and the
/// DDA remainders in the planned width.
#[derive(Debug, Clone)]
pub struct PlannedPolygon {
    target: Target,
    range: PixelRange,
    contours: usize,
    fill_rule: FillRule,
    edges: Vec<TableEdge>,
    /// Under all-inclusive and all-exclusive: the samples on an edge, `(row, column,
    /// covered)`, sorted; they override the top-left table's answer.
    on_edges: Vec<(u32, u32, bool)>,
    planned: Planned<PolygonLanes>,
}

/// The exact setup.
struct PolygonSetup {
    range: PixelRange,
    on_edges: Vec<(u32, u32, bool)>,
    scale: BigInt,
    edges: Vec<TableEdge>,
    remainders: Vec<Remainders<BigInt>>,
    bound: Bound,
}

/// The geometry shared by every edge of one polygon's setup.
struct Frame {
    scale: BigInt,
    origin: [BigInt; 2],
    /// The range's last local column and row.
    w: i64,
    h: i64,
    moved: MovedSample,
}

impl Frame {
    fn local(&self, p: &Point) -> [BigInt; 2] {
        [
            scaled(&p.x, &self.scale) - &self.origin[0],
            scaled(&p.y, &self.scale) - &self.origin[1],
        ]
    }
}

/// The table entry of the edge `a -> b` (local coordinates) and its remainders when it
/// steps; `None` when it is horizontal or crosses no row of the range.
fn table_edge(
    a: [BigInt; 2],
    b: [BigInt; 2],
    contour: usize,
    f: &Frame,
) -> Option<(TableEdge, Option<Remainders<BigInt>>)> {
    let (top, bottom, winding) = match a[1].cmp(&b[1]) {
        Ordering::Equal => return None,
        Ordering::Less => (a, b, -1),
        Ordering::Greater => (b, a, 1),
    };
    let l = &f.scale;
    let (first, last) = if f.moved.down {
        (ceil_div(&top[1], l), ceil_div(&bottom[1], l) - 1)
    } else {
        (floor_div(&top[1], l) + 1, floor_div(&bottom[1], l))
    };
    let first = first.max(BigInt::zero());
    let last = last.min(BigInt::from(f.h));
    if first > last {
        return None;
    }
    let (first, last) = (index(&first), index(&last));
    let (dx, dy) = (&bottom[0] - &top[0], &bottom[1] - &top[1]);
    let g = dx.gcd(&dy); // > 0: dy > 0
    let (dx, dy) = (dx / &g, dy / &g);
    let d = l * &dy;
    let inc = l * &dx;
    // A sample moved left (the right rules) is at or right of the crossing only when
    // strictly right of it: `θ = floor(N / d) + 1 = ceil((N + 1) / d)`.
    let moved_left = BigInt::from(i64::from(!f.moved.right));
    let n_at = |j: i64| &top[0] * &dy + (BigInt::from(j) * l - &top[1]) * &dx + &moved_left;
    let n_first = n_at(first);
    let (w, zero) = (f.w, BigInt::zero());
    let wd = BigInt::from(w) * &d;
    // m0: the first row past the lead rows; m1: the last row before the trail rows.
    let (m0, m1, lead, trail) = match inc.sign() {
        num_bigint::Sign::Plus => {
            // N grows: N <= 0 (threshold 0), then the middle, then N > w d (w + 1).
            let (s0, _) = indices_above(&n_first, &inc, first, last, &zero);
            let (sw, _) = indices_above(&n_first, &inc, first, last, &wd);
            (s0, sw - 1, 0, w + 1)
        }
        num_bigint::Sign::Minus => {
            // N falls: N > w d (w + 1), then the middle, then N <= 0 (threshold 0).
            let (_, ew) = indices_above(&n_first, &inc, first, last, &wd);
            let (_, e0) = indices_above(&n_first, &inc, first, last, &zero);
            (ew + 1, e0, w + 1, 0)
        }
        num_bigint::Sign::NoSign => {
            let constant = if n_first <= zero {
                Some(0)
            } else if n_first > wd {
                Some(w + 1)
            } else {
                None
            };
            match constant {
                Some(t) => (last + 1, last, t, t),
                None => (first, last, 0, 0),
            }
        }
    };
    let mut edge = TableEdge {
        first,
        last,
        middle: [m0, m1],
        lead,
        trail,
        q0: 0,
        step_q: 0,
        contour,
        winding,
        dda: None,
    };
    if m0 > m1 {
        return Some((edge, None));
    }
    let n0 = n_at(m0);
    let q0 = ceil_div(&n0, &d);
    edge.q0 = index(&q0);
    if m0 == m1 {
        return Some((edge, None));
    }
    let step_q = floor_div(&inc, &d);
    edge.step_q = index(&step_q);
    let remainders = Remainders {
        r0: &q0 * &d - &n0,
        step_r: &inc - &step_q * &d,
        d,
    };
    Some((edge, Some(remainders)))
}

/// The samples of the range that lie exactly on an edge of some contour, `(x, y)` on the
/// canvas, sorted by row then column, each once. A non-horizontal edge meets the sample
/// row `j` at `x = N_j / dy'` (the table's `N_j`, unmoved), which is a sample's when `N_j`
/// is a multiple of `d = L dy'`; a horizontal edge on a sample row holds the samples
/// between its ends.
fn on_edge_samples(poly: &Polygon, frame: &Frame, range: PixelRange) -> Vec<(u32, u32)> {
    let l = &frame.scale;
    let zero = BigInt::zero();
    let clamped = |lo: BigInt, hi: BigInt, last: i64| {
        let (lo, hi) = (lo.max(zero.clone()), hi.min(BigInt::from(last)));
        (lo <= hi).then(|| index(&lo)..=index(&hi))
    };
    let mut local: Vec<(i64, i64)> = Vec::new();
    for (a, b) in poly.contours().flat_map(closed_edges) {
        let (a, b) = (frame.local(a), frame.local(b));
        if a[1] == b[1] {
            let (j, rem) = a[1].div_mod_floor(l);
            let Some(rows) = clamped(j.clone(), j, frame.h) else {
                continue;
            };
            let (lo, hi) = if a[0] <= b[0] { (&a[0], &b[0]) } else { (&b[0], &a[0]) };
            if let (true, Some(columns)) = (rem.is_zero(), clamped(ceil_div(lo, l), floor_div(hi, l), frame.w)) {
                local.extend(columns.map(|i| (*rows.start(), i)));
            }
            continue;
        }
        let (top, bottom) = if a[1] < b[1] { (a, b) } else { (b, a) };
        let (dx, dy) = (&bottom[0] - &top[0], &bottom[1] - &top[1]);
        let g = dx.gcd(&dy);
        let (dx, dy) = (dx / &g, dy / &g);
        let d = l * &dy;
        let Some(rows) = clamped(ceil_div(&top[1], l), floor_div(&bottom[1], l), frame.h) else {
            continue;
        };
        for j in rows {
            let n = &top[0] * &dy + (BigInt::from(j) * l - &top[1]) * &dx;
            let (i, rem) = n.div_mod_floor(&d);
            if rem.is_zero() && i >= zero && i <= BigInt::from(frame.w) {
                local.push((j, index(&i)));
            }
        }
    }
    local.sort_unstable();
    local.dedup();
    let (x0, y0) = (i64::from(range.x0), i64::from(range.y0));
    let canvas = |v: i64| u32::try_from(v).expect("inside the range, on the canvas");
    local
        .into_iter()
        .map(|(j, i)| (canvas(x0 + i), canvas(y0 + j)))
        .collect()
}

fn setup(poly: &Polygon, target: &Target, rule: AnyTieRule) -> Option<PolygonSetup> {
    let range = exact_sample_range(poly.outline.iter(), target)?;
    let centre = target.convention.pixel_centre.offset();
    let scale = scale_of(poly.contours().flatten().flat_map(|p| [&p.x, &p.y]).chain([&centre]));
    let c = scaled(&centre, &scale);
    let frame = Frame {
        origin: [
            BigInt::from(range.x0) * &scale + &c,
            BigInt::from(range.y0) * &scale + &c,
        ],
        scale,
        w: i64::from(range.x1 - range.x0),
        h: i64::from(range.y1 - range.y0),
        moved: rule.moved_sample().unwrap_or(TieRule::TopLeft.moved_sample()),
    };
    let mut edges = Vec::new();
    let mut remainders = Vec::new();
    let mut bound = Bound {
        value: BigInt::zero(),
        what: "no edge steps (every threshold is found at setup)".into(),
    };
    for (k, contour) in poly.contours().enumerate() {
        for (e, (a, b)) in closed_edges(contour).enumerate() {
            let Some((mut edge, steps)) = table_edge(frame.local(a), frame.local(b), k, &frame) else {
                continue;
            };
            if let Some(rem) = steps {
                if rem.d > bound.value {
                    bound = Bound {
                        value: rem.d.clone(),
                        what: format!(
                            "the step divisor of contour {k}'s edge {e}, rows {}..={}: its height in units, over the gcd of its width and height",
                            i64::from(range.y0) + edge.middle[0],
                            i64::from(range.y0) + edge.middle[1]
                        ),
                    };
                }
                edge.dda = Some(remainders.len());
                remainders.push(rem);
            }
            edges.push(edge);
        }
    }
    edges.sort_by_key(|e| e.first);
    let grid = ExactGrid::of(target);
    let on_edges = match rule.moved_sample() {
        Some(_) => Vec::new(),
        None => on_edge_samples(poly, &frame, range)
            .into_iter()
            .map(|(x, y)| {
                let sample = grid.sample(x, y);
                (y, x, contains_exact_with(&sample, poly, rule))
            })
            .collect(),
    };
    Some(PolygonSetup {
        range,
        on_edges,
        scale: frame.scale,
        edges,
        remainders,
        bound,
    })
}

impl PlannedPolygon {
    /// Sets up `poly` (exact vertices: as written, snapped, or out of exact clipping) for
    /// `target`, in the cheapest width its bound allows; `None` when it covers nothing
    /// because no sample of the canvas lies in its outline's bounding box.
    pub fn new(poly: &Polygon, target: &Target) -> Option<PlannedPolygon> {
        Self::with_rule(poly, target, target.convention.tie_rule.into())
    }

    /// As [`PlannedPolygon::new`] under any of the six tie rules, the target's own aside:
    /// the four directional rules in the edge table itself (the rows each edge crosses,
    /// and `N + 1` for the right rules: see the module docs); all-inclusive and
    /// all-exclusive as the top-left table with the samples that lie exactly on an edge
    /// decided at setup by the oracle's closure / interior test
    /// ([`contains_exact_with`]), those samples found
    /// exactly, edge by edge.
    ///
    /// ```
    /// use rasterproof::convention::{AnyTieRule, Convention, PixelCentre, Target};
    /// use rasterproof::coverage::Coverage;
    /// use rasterproof::fill::polygon::{rasterize_exact_with, PlannedPolygon};
    /// use rasterproof::geom::{FillRule, Point, Polygon};
    /// let tri = Polygon::new([(0, 0), (4, 0), (0, 4)].iter().map(|&(x, y)| Point::from_ints(x, y)).collect(), FillRule::NonZero);
    /// let target = Target::new(5, 5, Convention { pixel_centre: PixelCentre::Corner, ..Convention::default() }).unwrap();
    /// for rule in AnyTieRule::ALL {
    ///     let (mut a, mut b) = (Coverage::new(5, 5), Coverage::new(5, 5));
    ///     PlannedPolygon::with_rule(&tri, &target, rule).unwrap().rasterize(0, &mut a);
    ///     rasterize_exact_with(&tri, 0, &target, rule, &mut b);
    ///     assert_eq!(a, b, "{rule:?}");
    /// }
    /// ```
    pub fn with_rule(poly: &Polygon, target: &Target, rule: AnyTieRule) -> Option<PlannedPolygon> {
        let mut s = setup(poly, target, rule)?;
        let planned = Planned::new(s.scale.clone(), s.bound.clone(), std::mem::take(&mut s.remainders));
        Some(Self::of(poly, target, s, planned))
    }

    /// As [`PlannedPolygon::new`] but in `width`: `Ok(None)` when it covers nothing,
    /// `Err(plan)` (the plan it would have) when `width` cannot hold its bound. For tests
    /// and benches that run every width.
    pub fn forced(poly: &Polygon, target: &Target, width: Width) -> Result<Option<PlannedPolygon>, Plan> {
        Self::forced_with_rule(poly, target, target.convention.tie_rule.into(), width)
    }

    /// [`PlannedPolygon::forced`] under any of the six tie rules.
    pub fn forced_with_rule(
        poly: &Polygon,
        target: &Target,
        rule: AnyTieRule,
        width: Width,
    ) -> Result<Option<PlannedPolygon>, Plan> {
        let Some(mut s) = setup(poly, target, rule) else {
            return Ok(None);
        };
        let planned = Planned::forced(
            s.scale.clone(),
            s.bound.clone(),
            std::mem::take(&mut s.remainders),
            width,
        )?;
        Ok(Some(Self::of(poly, target, s, planned)))
    }

    fn of(poly: &Polygon, target: &Target, s: PolygonSetup, planned: Planned<PolygonLanes>) -> PlannedPolygon {
        PlannedPolygon {
            target: *target,
            range: s.range,
            contours: poly.contours().count(),
            fill_rule: poly.fill_rule,
            edges: s.edges,
            on_edges: s.on_edges,
            planned,
        }
    }

    /// The plan: scale, bound and width.
    pub fn plan(&self) -> &Plan {
        self.planned.plan()
    }

    /// Covers every pixel whose moved sample is inside the polygon under its fill rule:
    /// equal, pixel for pixel, to [`rasterize_exact`](super::rasterize_exact) on the same
    /// polygon and target (the property tests of `tests/planned_polygons_lines.rs` are the
    /// proof).
    ///
    /// ```
    /// use rasterproof::convention::{Convention, Target};
    /// use rasterproof::coverage::Coverage;
    /// use rasterproof::fill::polygon::{rasterize_exact, PlannedPolygon};
    /// use rasterproof::geom::{FillRule, Point, Polygon};
    /// use rasterproof::num::plan::Width;
    /// // An L shape with a vertex at a third of a pixel.
    /// let pts = [(0, 1, 0, 1), (6, 1, 0, 1), (6, 1, 2, 1), (7, 3, 2, 1), (2, 1, 6, 1), (0, 1, 6, 1)];
    /// let outline = pts.iter().map(|&(a, b, c, d)| Point::from_fractions(a, b, c, d)).collect();
    /// let poly = Polygon::new(outline, FillRule::NonZero);
    /// let target = Target::new(8, 8, Convention::default()).unwrap();
    /// let planned = PlannedPolygon::new(&poly, &target).unwrap();
    /// assert_eq!(planned.plan().scale, 6.into()); // lcm(3, 2)
    /// assert_eq!(planned.plan().width, Width::I32);
    /// let (mut a, mut b) = (Coverage::new(8, 8), Coverage::new(8, 8));
    /// planned.rasterize(0, &mut a);
    /// rasterize_exact(&poly, 0, &target, &mut b);
    /// assert_eq!(a, b);
    /// ```
    pub fn rasterize<S: CoverageSink + ?Sized>(&self, id: u32, sink: &mut S) {
        if self.on_edges.is_empty() {
            self.planned.run(Sweeping {
                polygon: self,
                id,
                sink,
            });
            return;
        }
        let mut overriding = Overriding {
            sink: &mut *sink,
            on_edges: &self.on_edges,
        };
        self.planned.run(Sweeping {
            polygon: self,
            id,
            sink: &mut overriding,
        });
        for &(y, x, covered) in &self.on_edges {
            if covered {
                sink.cover(x, y, id);
            }
        }
    }

    /// The active edge table over the rows of the range, generic over the planned width
    /// (see the module docs).
    fn traverse<T: Lane, S: CoverageSink + ?Sized>(&self, lanes: &[Remainders<T>], id: u32, sink: &mut S) {
        /// An edge on the active list: its threshold and remainder on the middle rows.
        struct Active<T> {
            edge: usize,
            q: i64,
            r: Option<T>,
        }
        let (x0, y0) = (i64::from(self.range.x0), i64::from(self.range.y0));
        let h = i64::from(self.range.y1 - self.range.y0);
        let edges = &self.edges;
        let mut next = 0;
        let mut active: Vec<Active<T>> = Vec::new();
        let mut crossings: Vec<Crossing> = Vec::new();
        let mut sweep = Sweep::new(self.contours, self.fill_rule);
        for j in 0..=h {
            while next < edges.len() && edges[next].first == j {
                let e = &edges[next];
                active.push(Active {
                    edge: next,
                    q: e.q0,
                    r: e.dda.map(|k| lanes[k].r0.clone()),
                });
                next += 1;
            }
            active.retain(|a| edges[a.edge].last >= j);
            crossings.clear();
            crossings.extend(active.iter().map(|a| {
                let e = &edges[a.edge];
                let local = if j < e.middle[0] {
                    e.lead
                } else if j <= e.middle[1] {
                    a.q
                } else {
                    e.trail
                };
                Crossing {
                    threshold: i128::from(x0 + local),
                    contour: e.contour,
                    winding: e.winding,
                }
            }));
            sweep.emit_spans(y0 + j, &mut crossings, id, &self.target, sink);
            for a in &mut active {
                let e = &edges[a.edge];
                if e.middle[0] <= j && j < e.middle[1] {
                    let k = e.dda.expect("an edge with two middle rows has remainders");
                    let (s, r) = (&lanes[k], a.r.as_mut().expect("set with the edge"));
                    a.q += e.step_q;
                    *r = r.minus(&s.step_r);
                    if !r.non_negative() {
                        r.add_to(&s.d);
                        a.q += 1;
                    }
                }
            }
        }
    }
}

/// A sink that passes on every pixel but the samples on an edge (decided apart, under
/// all-inclusive and all-exclusive).
struct Overriding<'a, S: ?Sized> {
    sink: &'a mut S,
    /// `(row, column, covered)`, sorted.
    on_edges: &'a [(u32, u32, bool)],
}

impl<S: CoverageSink + ?Sized> CoverageSink for Overriding<'_, S> {
    fn cover(&mut self, x: u32, y: u32, id: u32) {
        if self
            .on_edges
            .binary_search_by_key(&(y, x), |&(r, c, _)| (r, c))
            .is_err()
        {
            self.sink.cover(x, y, id);
        }
    }

    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, id: u32) {
        let first = self.on_edges.partition_point(|&(r, c, _)| (r, c) < (y, x0));
        let mut start = x0;
        for &(_, c, _) in self.on_edges[first..]
            .iter()
            .take_while(|&&(r, c, _)| r == y && c <= x1)
        {
            if start < c {
                self.sink.cover_span(y, start, c - 1, id);
            }
            start = c + 1;
        }
        if start <= x1 {
            self.sink.cover_span(y, start, x1, id);
        }
    }
}

/// Plans and rasterizes `poly` in one call (see [`PlannedPolygon`]).
pub fn rasterize<S: CoverageSink + ?Sized>(poly: &Polygon, id: u32, target: &Target, sink: &mut S) {
    if let Some(p) = PlannedPolygon::new(poly, target) {
        p.rasterize(id, sink);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::{Convention, PixelCentre, Preset};
    use crate::coverage::Coverage;

    fn pts(v: &[(i64, i64)]) -> Vec<Point> {
        v.iter().map(|&(x, y)| Point::from_ints(x, y)).collect()
    }

    fn oracle(poly: &Polygon, target: &Target) -> Coverage {
        let mut c = Coverage::new(target.width, target.height);
        super::super::rasterize_exact(poly, 0, target, &mut c);
        c
    }

    fn planned(poly: &Polygon, target: &Target, width: Option<Width>) -> Coverage {
        let mut c = Coverage::new(target.width, target.height);
        let p = match width {
            None => PlannedPolygon::new(poly, target),
            Some(w) => PlannedPolygon::forced(poly, target, w).expect("width holds the bound"),
        };
        if let Some(p) = p {
            p.rasterize(0, &mut c);
        }
        c
    }

    /// `rows_above` against counting the rows one by one.
    #[test]
    fn rows_above_by_brute_force() {
        for n_first in -9..=9i64 {
            for inc in [-7i64, -3, -1, 1, 2, 5] {
                for v in -12..=12i64 {
                    for (first, last) in [(0i64, 0i64), (0, 5), (3, 9)] {
                        let rows: Vec<i64> = (first..=last).filter(|j| n_first + (j - first) * inc > v).collect();
                        let (lo, hi) = indices_above(&n_first.into(), &inc.into(), first, last, &v.into());
                        let got: Vec<i64> = (lo..=hi).collect();
                        assert_eq!(got, rows, "n_first {n_first} inc {inc} v {v} rows {first}..={last}");
                        assert!((first..=last + 1).contains(&lo) && (first - 1..=last).contains(&hi));
                    }
                }
            }
        }
    }

    /// A hand-derived plan: the triangle (0,0) (5,3) (1,6) on an 8x8 canvas, samples at
    /// pixel centres, so `L = 2`; the outline's box holds the samples of columns 0..=4 and
    /// rows 0..=5 (`w = 4`, `h = 5`), the first sample (1/2, 1/2) is (1, 1) in `L` units, and
    /// the vertices are, locally, A = (-1,-1), B = (9,5), C = (1,11).
    /// - A -> B: top A, (dx, dy) = (10, 6), g = 2, (dx', dy') = (5, 3), d = L dy' = 6.
    ///   Top-left rows: ceil(-1/2) = 0 ..= ceil(5/2) - 1 = 2. N_j = -1 * 3 + (2j + 1) * 5 =
    ///   10j + 2: 2, 12, 22 for rows 0..=2, all in (0, w d] = (0, 24], so the middle is
    ///   rows 0..=2 and the DDA runs with d = 6 (thresholds ceil(2/6) = 1, 2, 4).
    /// - B -> C: top B, (dx, dy) = (-8, 6), g = 2, (-4, 3), d = 6; rows ceil(5/2) = 3 ..=
    ///   ceil(11/2) - 1 = 5 (clamped to h = 5). N_j = 9 * 3 + (2j - 5)(-4) = 47 - 8j: 23,
    ///   15, 7 for rows 3..=5, in (0, 24]: the middle is rows 3..=5 (thresholds 4, 3, 2),
    ///   d = 6.
    /// - C -> A: going up, top A, (dx, dy) = (2, 12), g = 2, (1, 6), d = 12; rows 0..=5.
    ///   N_j = -1 * 6 + (2j + 1) * 1 = 2j - 5: -5, -3, -1 (threshold 0, the lead rows 0..=2),
    ///   then 1, 3, 5 (thresholds 1: the middle rows 3..=5), d = 12.
    ///
    /// So the bound is 12, the divisor of contour 0's edge 2, over rows 3..=5.
    #[test]
    fn bound_by_hand() {
        let poly = Polygon::new(pts(&[(0, 0), (5, 3), (1, 6)]), FillRule::NonZero);
        let target = Target::new(8, 8, Convention::default()).unwrap();
        let p = PlannedPolygon::new(&poly, &target).unwrap();
        assert_eq!(p.plan().scale, BigInt::from(2));
        assert_eq!(p.plan().bound.value, BigInt::from(12));
        assert_eq!(
            p.plan().bound.what,
            "the step divisor of contour 0's edge 2, rows 3..=5: its height in units, over the gcd of its width and height"
        );
        assert_eq!(p.plan().width, Width::I32);
        let e = &p.edges;
        assert_eq!(e.len(), 3);
        let by_contour_edge: Vec<([i64; 2], i64, i64)> = e.iter().map(|e| (e.middle, e.lead, e.q0)).collect();
        // sorted by first row: A->B (0), C->A (0), B->C (3, its lead would be w + 1)
        assert_eq!(by_contour_edge, vec![([0, 2], 0, 1), ([3, 5], 0, 1), ([3, 5], 5, 4)]);
        assert_eq!(planned(&poly, &target, None), oracle(&poly, &target));
    }

    /// Every width runs a small polygon with a hole and a rational vertex, under every
    /// preset and both centres, and equals the oracle.
    #[test]
    fn every_width_equals_the_oracle() {
        let mut poly = Polygon::new(
            vec![
                Point::from_fractions(1, 3, 1, 7),
                Point::from_ints(11, 1),
                Point::from_fractions(23, 2, 21, 2),
                Point::from_ints(0, 9),
            ],
            FillRule::EvenOdd,
        );
        poly.holes.push(pts(&[(3, 3), (7, 4), (5, 7)]));
        for preset in Preset::ALL {
            for centre in [PixelCentre::Half, PixelCentre::Corner] {
                let mut conv = preset.convention();
                conv.pixel_centre = centre;
                let target = Target::new(12, 12, conv).unwrap();
                let want = oracle(&poly, &target);
                assert!(want.covered_pixels() > 40);
                for w in Width::ALL {
                    assert_eq!(planned(&poly, &target, Some(w)), want, "{preset:?} {centre:?} {w}");
                }
            }
        }
    }

    /// An edge far off the canvas on both sides of the range: its thresholds are the
    /// constants 0 and w + 1, its huge x never reaches the lanes, and the plan stays i32.
    #[test]
    fn far_edges_stay_out_of_the_lanes() {
        let big = BigInt::from(10).pow(30);
        let q = |v: BigInt| num_rational::BigRational::from_integer(v);
        let outline = vec![
            Point::new(q(-big.clone()), q(0.into())),
            Point::new(q(big.clone()), q(2.into())),
            Point::new(q(4.into()), q(8.into())),
        ];
        let poly = Polygon::new(outline, FillRule::NonZero);
        let target = Target::new(16, 16, Convention::default()).unwrap();
        let p = PlannedPolygon::new(&poly, &target).unwrap();
        assert_eq!(p.plan().width, Width::I32);
        assert_eq!(planned(&poly, &target, None), oracle(&poly, &target));
    }

    #[test]
    fn nothing_on_the_canvas_plans_nothing() {
        let poly = Polygon::new(pts(&[(20, 20), (30, 20), (25, 30)]), FillRule::NonZero);
        let target = Target::new(16, 16, Convention::default()).unwrap();
        assert!(PlannedPolygon::new(&poly, &target).is_none());
        assert!(matches!(PlannedPolygon::forced(&poly, &target, Width::F32), Ok(None)));
        let empty = Polygon::new(Vec::new(), FillRule::NonZero);
        assert!(PlannedPolygon::new(&empty, &target).is_none());
    }
}
