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
    for c in out.coordinates_mut() {
        if *c.denom() > limit {
            *c = nearest_on_grid(c, bits);
            changed = true;
        }
    }
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
    let mut cs = out.coordinates_mut();
    for (k, c) in cs.iter_mut().enumerate() {
        **c -= if k % 2 == 0 { &fx } else { &fy };
    }
    out
}

/// Shrinks `scene` while `keeps` holds: drops triangles, lines and polygons (never the
/// last primitive) and the clip window, crops the canvas (halves, then one pixel from a
/// side; a crop from the left or the top moves the scene by whole pixels), and simplifies
/// the coordinates ([`Scene::coordinates_mut`]), the simplest values first, so that the
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
///     let v = &s.triangles[0].triangle.v;
///     v.iter().all(|p| (&p.x * r(4, 1)).is_integer() && (&p.y * r(4, 1)).is_integer())
///         && v.iter().any(|p| p.x >= r(1, 1))
/// };
/// let (minimal, runs) = shrink(&scene, &mut keeps, 10_000, Some(&r(1, 4)));
/// assert!(runs < 10_000);
/// assert_eq!((minimal.width, minimal.height), (1, 1));
/// let xs: Vec<_> = minimal.triangles[0].triangle.v.iter().map(|p| p.x.clone()).collect();
/// assert_eq!(xs.iter().filter(|x| **x == r(1, 1)).count(), 1);
/// ```
pub fn shrink(
    scene: &Scene,
    keeps: &mut dyn FnMut(&Scene) -> bool,
    budget: usize,
    step: Option<&BigRational>,
) -> (Scene, usize) {
    let mut best = scene.clone();
    let mut runs = 0;
    let mut attempt = |candidate: &Scene, runs: &mut usize| -> bool {
        if *runs >= budget {
            return false;
        }
        *runs += 1;
        keeps(candidate)
    };
    // Whether this round may move values away from zero (the first, and each after a
    // drop or a crop).
    let mut away = true;
    loop {
        let mut changed = false;
        let mut structural = false;
        // Drop primitives, last first.
        for kind in 0..3 {
            let len = match kind {
                0 => best.triangles.len(),
                1 => best.lines.len(),
                _ => best.polygons.len(),
            };
            for i in (0..len).rev() {
                let mut c = best.clone();
                match kind {
                    0 => drop(c.triangles.remove(i)),
                    1 => drop(c.lines.remove(i)),
                    _ => drop(c.polygons.remove(i)),
                }
                if primitive_count(&c) > 0 && attempt(&c, &mut runs) {
                    best = c;
                    changed = true;
                    structural = true;
                }
            }
        }
        if best.clip.is_some() {
            let mut c = best.clone();
            c.clip = None;
            if attempt(&c, &mut runs) {
                best = c;
                changed = true;
                structural = true;
            }
        }
        // Crop: halves, then a pixel from each side (moving the scene for left and top).
        if best.clip.is_none() {
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
            for (dx, dy, cw, ch) in crops {
                if cw == 0 || ch == 0 || (cw, ch) == (best.width, best.height) {
                    continue;
                }
                let c = moved(&best, dx, dy, cw, ch);
                if attempt(&c, &mut runs) {
                    best = c;
                    changed = true;
                    structural = true;
                    break;
                }
            }
        }
        // All coordinates at once on the coarsest grid that keeps the failure.
        if away || structural {
            for bits in GRID_BITS {
                if let Some(c) = rounded(&best, bits) {
                    if attempt(&c, &mut runs) {
                        best = c;
                        changed = true;
                        break;
                    }
                }
            }
        }
        // Simpler coordinates, one at a time.
        // A move changes one coordinate only: the others' values, read once, stay true.
        let values: Vec<BigRational> = best.clone().coordinates_mut().into_iter().map(|c| c.clone()).collect();
        for (k, value) in values.iter().enumerate() {
            for v in simpler(value, step, away || structural) {
                let mut c = best.clone();
                *c.coordinates_mut()[k] = v;
                if attempt(&c, &mut runs) {
                    best = c;
                    changed = true;
                    break;
                }
            }
        }
        if !changed || runs >= budget {
            return (best, runs);
        }
        away = structural;
    }
}
