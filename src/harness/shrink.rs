//! The one shrinker: a failing scene made minimal with the renderer under test in the
//! loop ([`shrink`]), by dropping primitives and the clip window, cropping the canvas and
//! simplifying coordinates. The hunt ([`crate::oracle::hunt`]) shrinks their renderer's
//! failures with it, and [`crate::harness::find_counterexample`] a rasterizer's
//! disagreement with the oracle (one subpixel its smallest step).

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::scene::Scene;

/// How many primitives a scene has.
pub fn primitive_count(s: &Scene) -> usize {
    s.triangles.len() + s.lines.len() + s.polygons.len() + s.clip_space_triangles.len()
}

/// The grids a coordinate is simplified to, coarsest first: 1, 1/2, ..., 1/256 px.
const GRID_BITS: std::ops::RangeInclusive<u32> = 0..=8;

/// `v` on the grid of `1/2^bits` px: rounded towards zero (`away` false) or away from zero.
fn on_grid(v: &BigRational, bits: u32, away: bool) -> BigRational {
    let k = BigRational::from_integer(BigInt::from(1u32 << bits));
    let scaled = v * &k;
    let t = scaled.trunc();
    let r = if away && t != scaled {
        t + BigRational::from_integer(if v.is_positive() { 1 } else { -1 }.into())
    } else {
        t
    };
    r / k
}

/// `v` on the grid of `1/2^bits` px, rounded to the nearest (ties away from zero).
fn nearest_on_grid(v: &BigRational, bits: u32) -> BigRational {
    let k = BigRational::from_integer(BigInt::from(1u32 << bits));
    (v * &k).round() / k
}

/// Simpler values for a coordinate, simplest first. Nearer zero: 0, the integer towards
/// zero and, with `away` (a value simplified away from zero when its denominator
/// shrinks), the integer away from zero; then the same on the grids 1/2 .. 1/256 px;
/// then one pixel nearer zero, the integer half of it (when `|v| >= 2`), and with a
/// `step`, one step nearer zero (when `|v| >= step`). Every value but the away ones is
/// nearer zero than `v`; every away one has a smaller denominator.
fn simpler(v: &BigRational, step: Option<&BigRational>, away: bool) -> Vec<BigRational> {
    let mut out = vec![BigRational::zero()];
    for bits in GRID_BITS {
        out.push(on_grid(v, bits, false));
        if away {
            let a = on_grid(v, bits, true);
            if a.denom() < v.denom() {
                out.push(a);
            }
        }
    }
    let one = BigRational::from_integer(1.into());
    if v.abs() >= one {
        out.push(v - BigRational::from_integer(if v.is_positive() { 1 } else { -1 }.into()));
    }
    if v.abs() >= BigRational::from_integer(2.into()) {
        out.push((v / BigRational::from_integer(2.into())).trunc());
    }
    if let Some(step) = step {
        if v.abs() >= *step {
            out.push(if v.is_positive() { v - step } else { v + step });
        }
    }
    let mut seen = Vec::new();
    out.retain(|c| {
        let fresh = c != v && !seen.contains(c);
        seen.push(c.clone());
        fresh
    });
    out
}

/// The scene with every coordinate off the grid of `1/2^bits` px rounded to its nearest
/// point of that grid (each such coordinate's denominator shrinks), or `None` when all
/// lie on it already.
fn rounded(s: &Scene, bits: u32) -> Option<Scene> {
    let mut out = s.clone();
    let limit = BigInt::from(1u32 << bits);
    let mut changed = false;
    out.map_coordinates(|_, c| {
        if *c.denom() > limit {
            changed = true;
            nearest_on_grid(c, bits)
        } else {
            c.clone()
        }
    });
    changed.then_some(out)
}

/// The scene moved by whole pixels (`-dx`, `-dy`) on a `width` x `height` canvas.
fn moved(s: &Scene, dx: i64, dy: i64, width: u32, height: u32) -> Scene {
    let mut out = s.clone();
    out.width = width;
    out.height = height;
    let (fx, fy) = (
        BigRational::from_integer(dx.into()),
        BigRational::from_integer(dy.into()),
    );
    out.map_coordinates(|k, c| c - if k % 2 == 0 { &fx } else { &fy });
    out
}

/// Shrinks `scene` while `keeps` holds: drops triangles, lines and polygons (never the
/// last primitive) and the clip window, crops the canvas (halves, then one pixel from a
/// side; a crop from the left or the top moves the scene by whole pixels), and simplifies
/// the coordinates ([`Scene::coordinates`]), the simplest values first, so that the
/// minimal scene reads like one a person would write:
///
/// - in the first round, and in every round that dropped or cropped something or follows
///   one that did,
///   all coordinates at once rounded to the nearest integer, else to the nearest half,
///   ..., 1/256 px (the coarsest grid that keeps the failure; one run per grid), and each
///   coordinate also tried at the integer (then half, ...) away from zero;
/// - in every round, each coordinate moved nearer zero: 0, the integer towards zero, the
///   value rounded towards zero to the grids of 1/2 .. 1/256 px, one pixel nearer zero,
///   the integer half of it and, with `step`, one `step` nearer zero when its magnitude is
///   at least `step`.
///
/// It repeats until no step keeps the failure or `budget` runs of `keeps` are spent.
/// Returns the smallest scene and the runs used.
///
/// When fewer than `budget` runs were used, the scene is minimal in this sense: no single
/// step of the last round keeps the failure (in particular, with `step`, no coordinate can
/// move one `step` towards zero). It ends, even with `usize::MAX` runs, when `keeps`
/// accepts only scenes whose coordinates lie on one fixed grid: the rounds that may move
/// a value away from zero come only after a drop or a crop (which lower the number of
/// primitives, or remove the clip window, or shrink the canvas), and a move away from
/// zero lowers its coordinate's denominator; every other accepted step lowers one
/// coordinate's magnitude, leaving the rest as they were.
///
/// ```
/// use num_rational::BigRational;
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::harness::shrink::shrink;
/// use rasterproof::scene::Scene;
/// let r = |n: i64, d: i64| BigRational::new(n.into(), d.into());
/// let p = |x, y| Point::new(r(x, 4), r(y, 4));
/// let scene = Scene::new(8, 8, vec![Triangle { v: [p(9, 5), p(22, 7), p(13, 19)] }]);
/// // Fails while some vertex lies at x >= 1 px, on the quarter-pixel grid.
/// let mut keeps = |s: &Scene| {
///     let v = &s.triangles[0].triangle.to_triangle().v;
///     v.iter().all(|p| (&p.x * r(4, 1)).is_integer() && (&p.y * r(4, 1)).is_integer())
///         && v.iter().any(|p| p.x >= r(1, 1))
/// };
/// let (minimal, runs) = shrink(&scene, &mut keeps, 10_000, Some(&r(1, 4)));
/// assert!(runs < 10_000);
/// assert_eq!((minimal.width, minimal.height), (1, 1));
/// let xs: Vec<_> = minimal.triangles[0].triangle.to_triangle().v.iter().map(|p| p.x.clone()).collect();
/// assert_eq!(xs.iter().filter(|x| **x == r(1, 1)).count(), 1);
/// ```
pub fn shrink(
    scene: &Scene,
    keeps: &mut dyn FnMut(&Scene) -> bool,
    budget: usize,
    step: Option<&BigRational>,
) -> (Scene, usize) {
    let mut first_kept = |batch: &[Scene]| batch.iter().position(&mut *keeps);
    shrink_batched(scene, &mut first_kept, 1, budget, step)
}

/// [`shrink`], trying each step's candidates up to `width` at a time: `first_kept` is
/// handed a batch of candidates (in the order [`shrink`] would try them, all made from the
/// same scene) and returns the index of the first that keeps the failure, or `None`. A
/// caller with several renderers runs a batch at once (the hunt does, when it has more
/// jobs than findings).
///
/// The minimal scene and the runs are [`shrink`]'s, whatever the width: the runs count
/// the candidates up to and including the kept one, as one at a time would; the
/// candidates after it in its batch were made from a scene the shrinker no longer holds
/// and are dropped (work done ahead for nothing: at most `width - 1` per kept step).
/// Every batch holds at most the runs left in `budget`.
///
/// ```
/// use num_rational::BigRational;
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::harness::shrink::{shrink, shrink_batched};
/// use rasterproof::scene::Scene;
/// let r = |n: i64| BigRational::from_integer(n.into());
/// let p = |x, y| Point::new(r(x), r(y));
/// let scene = Scene::new(8, 8, vec![Triangle { v: [p(7, 1), p(7, 2), p(3, 6)] }]);
/// // Fails while the first vertex lies at x >= 5: moving it to 0 is tried and refused
/// // before 6 is kept, so a batch of 4 holds both (one batch, two runs).
/// let keeps = |s: &Scene| s.triangles[0].triangle.to_triangle().v[0].x >= r(5);
/// let one = shrink(&scene, &mut |s: &Scene| keeps(s), 100, None);
/// let mut batches = 0;
/// let mut first_kept = |batch: &[Scene]| {
///     batches += 1;
///     batch.iter().position(|s| keeps(s))
/// };
/// assert_eq!(shrink_batched(&scene, &mut first_kept, 4, 100, None), one);
/// assert!(batches < one.1);
/// ```
pub fn shrink_batched(
    scene: &Scene,
    first_kept: &mut dyn FnMut(&[Scene]) -> Option<usize>,
    width: usize,
    budget: usize,
    step: Option<&BigRational>,
) -> (Scene, usize) {
    let mut best = scene.clone();
    let mut tries = Tries {
        first_kept,
        width: width.max(1),
        budget,
        runs: 0,
    };
    // Whether this round may move values away from zero (the first, and each after a
    // drop or a crop).
    let mut away = true;
    loop {
        // Drops and crops change the scene's structure; then the coordinates.
        let structural = drop_primitives(&mut best, &mut tries)
            | drop_polygon_parts(&mut best, &mut tries)
            | drop_clip(&mut best, &mut tries)
            | crop(&mut best, &mut tries);
        let mut changed = structural;
        if away || structural {
            changed |= coarsen(&mut best, &mut tries);
        }
        changed |= simplify_coordinates(&mut best, &mut tries, step, away || structural);
        let runs = tries.runs;
        if !changed || runs >= budget {
            return (best, runs);
        }
        away = structural;
    }
}

/// Drops primitives, last first; after a drop, on with the one before it. Whether any
/// was dropped.
fn drop_primitives(best: &mut Scene, tries: &mut Tries) -> bool {
    let mut changed = false;
    for kind in 0..3 {
        let mut below = match kind {
            0 => best.triangles.len(),
            1 => best.lines.len(),
            _ => best.polygons.len(),
        };
        while let Some((m, c)) = tries.first(below, |m| {
            let i = below - 1 - m;
            let mut c = best.clone();
            match kind {
                0 => drop(c.triangles.remove(i)),
                1 => drop(c.lines.remove(i)),
                _ => drop(c.polygons.remove(i)),
            }
            (primitive_count(&c) > 0).then_some(c)
        }) {
            *best = c;
            changed = true;
            below -= m + 1;
        }
    }
    changed
}

/// A part of a polygon the shrinker may drop: a hole, or a vertex of a contour (the
/// outline, contour 0, or hole `h`, contour `h + 1`).
#[derive(Debug, Clone, Copy)]
enum Part {
    Hole {
        polygon: usize,
        hole: usize,
    },
    Vertex {
        polygon: usize,
        contour: usize,
        vertex: usize,
    },
}

/// The parts of `scene`'s polygons in the order they are tried: last polygon first; in
/// each, its holes last first, each hole whole and then its vertices last first; then the
/// outline's vertices last first. Dropping one leaves the parts after it where they were.
fn parts(scene: &Scene) -> Vec<Part> {
    let mut out = Vec::new();
    for (polygon, p) in scene.polygons.iter().enumerate().rev() {
        for (hole, points) in p.holes.iter().enumerate().rev() {
            out.push(Part::Hole { polygon, hole });
            out.extend((0..points.len()).rev().map(|vertex| Part::Vertex {
                polygon,
                contour: hole + 1,
                vertex,
            }));
        }
        out.extend((0..p.outline.len()).rev().map(|vertex| Part::Vertex {
            polygon,
            contour: 0,
            vertex,
        }));
    }
    out
}

/// `scene` without `part`; `None` where that would leave a contour of fewer than three
/// vertices (a hole that small is dropped whole).
fn without(scene: &Scene, part: Part) -> Option<Scene> {
    let mut c = scene.clone();
    match part {
        Part::Hole { polygon, hole } => drop(c.polygons[polygon].holes.remove(hole)),
        Part::Vertex {
            polygon,
            contour,
            vertex,
        } => {
            let p = &mut c.polygons[polygon];
            let points = if contour == 0 {
                &mut p.outline
            } else {
                &mut p.holes[contour - 1]
            };
            if points.len() <= 3 {
                return None;
            }
            drop(points.remove(vertex));
        }
    }
    Some(c)
}

/// Drops polygons' holes and vertices (a repeated point, an empty hole, a vertex on a
/// straight run), in [`parts`]' order; after a drop, on with the part after it. Whether
/// any was dropped.
fn drop_polygon_parts(best: &mut Scene, tries: &mut Tries) -> bool {
    let mut changed = false;
    let mut at = 0;
    loop {
        let all = parts(best);
        let rest = all.get(at..).unwrap_or_default();
        let Some((m, c)) = tries.first(rest.len(), |k| without(best, rest[k])) else {
            return changed;
        };
        *best = c;
        changed = true;
        at += m;
    }
}

/// Drops the clip window. Whether it was dropped.
fn drop_clip(best: &mut Scene, tries: &mut Tries) -> bool {
    if best.clip.is_none() {
        return false;
    }
    let mut c = best.clone();
    c.clip = None;
    let Some((_, c)) = tries.first(1, |_| Some(c.clone())) else {
        return false;
    };
    *best = c;
    true
}

/// Crops an unclipped scene: halves, then a pixel from each side (moving the scene for
/// left and top). Whether it was cropped.
fn crop(best: &mut Scene, tries: &mut Tries) -> bool {
    if best.clip.is_some() {
        return false;
    }
    let (w, h) = (best.width, best.height);
    let crops = [
        (0, 0, w.div_ceil(2), h),
        (i64::from(w / 2), 0, w - w / 2, h),
        (0, 0, w, h.div_ceil(2)),
        (0, i64::from(h / 2), w, h - h / 2),
        (0, 0, w - 1, h),
        (1, 0, w - 1, h),
        (0, 0, w, h - 1),
        (0, 1, w, h - 1),
    ];
    let candidate = |m: usize| {
        let (dx, dy, cw, ch) = crops[m];
        (cw != 0 && ch != 0 && (cw, ch) != (w, h)).then(|| moved(best, dx, dy, cw, ch))
    };
    let Some((_, c)) = tries.first(crops.len(), candidate) else {
        return false;
    };
    *best = c;
    true
}

/// All coordinates at once on the coarsest grid that keeps the failure. Whether they
/// moved.
fn coarsen(best: &mut Scene, tries: &mut Tries) -> bool {
    let grids: Vec<u32> = GRID_BITS.collect();
    let Some((_, c)) = tries.first(grids.len(), |m| rounded(best, grids[m])) else {
        return false;
    };
    *best = c;
    true
}

/// Simpler coordinates, one at a time (moving away from zero only when `away`). Whether
/// any moved.
fn simplify_coordinates(best: &mut Scene, tries: &mut Tries, step: Option<&BigRational>, away: bool) -> bool {
    let mut changed = false;
    // A move changes one coordinate only: the others' values, read once, stay true.
    let values: Vec<BigRational> = best.coordinates();
    for (k, value) in values.iter().enumerate() {
        let vs = simpler(value, step, away);
        let moved_to = |m: usize| {
            let mut c = best.clone();
            c.map_coordinates(|j, x| if j == k { vs[m].clone() } else { x.clone() });
            Some(c)
        };
        if let Some((_, c)) = tries.first(vs.len(), moved_to) {
            *best = c;
            changed = true;
        }
    }
    changed
}

/// The shrinker's runs of the failure test: candidates tried up to `width` at a time,
/// counted as one at a time would count them.
struct Tries<'k> {
    /// The index of the first candidate of a batch that keeps the failure.
    first_kept: &'k mut dyn FnMut(&[Scene]) -> Option<usize>,
    /// Candidates per batch, at least 1.
    width: usize,
    /// Runs allowed.
    budget: usize,
    /// Runs counted so far.
    runs: usize,
}

impl Tries<'_> {
    /// The first of the candidates `make(0)`, ..., `make(n - 1)` (skipping those that are
    /// `None`, which cost no run) that keeps the failure, with its index; `None` when none
    /// does or the budget ends first.
    fn first(&mut self, n: usize, make: impl Fn(usize) -> Option<Scene>) -> Option<(usize, Scene)> {
        let mut next = 0;
        while next < n && self.runs < self.budget {
            let room = (self.budget - self.runs).min(self.width);
            let (mut batch, mut at) = (Vec::with_capacity(room), Vec::with_capacity(room));
            while next < n && batch.len() < room {
                if let Some(c) = make(next) {
                    batch.push(c);
                    at.push(next);
                }
                next += 1;
            }
            if batch.is_empty() {
                return None;
            }
            match (self.first_kept)(&batch) {
                Some(p) if p < batch.len() => {
                    self.runs += p + 1;
                    return Some((at[p], batch.swap_remove(p)));
                }
                _ => self.runs += batch.len(),
            }
        }
        None
    }
}
