//! The shrinker: a failing scene made minimal with their renderer in the loop
//! ([`shrink`]), by dropping primitives, cropping the canvas and simplifying coordinates.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::families::coordinates;
use crate::scene::Scene;

/// How many primitives a scene has.
pub fn primitive_count(s: &Scene) -> usize {
    s.triangles.len() + s.lines.len() + s.polygons.len() + s.clip_space_triangles.len()
}

/// Simpler values for a coordinate, simplest first: 0, the integer towards zero, the
/// value rounded towards zero to coarser grids (1/2 .. 1/256 px), one pixel nearer zero,
/// half of it.
fn simpler(v: &BigRational) -> Vec<BigRational> {
    let mut out = vec![BigRational::zero(), v.trunc()];
    for bits in 1..=8u32 {
        let k = BigRational::from_integer(BigInt::from(1u32 << bits));
        out.push((v * &k).trunc() / &k);
    }
    if v.abs() >= BigRational::from_integer(1.into()) {
        out.push(v - BigRational::from_integer(if v.is_positive() { 1 } else { -1 }.into()));
    }
    out.push(v / BigRational::from_integer(2.into()));
    let mut seen = Vec::new();
    out.retain(|c| {
        let fresh = c != v && !seen.contains(c);
        seen.push(c.clone());
        fresh
    });
    out
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
    let mut cs = coordinates(&mut out);
    for (k, c) in cs.iter_mut().enumerate() {
        **c -= if k % 2 == 0 { &fx } else { &fy };
    }
    out
}

/// Shrinks `scene` while `keeps` holds: drops primitives (and the clip window), crops the
/// canvas (to the differing pixels' box when `keeps` accepts it, then halves, then one
/// pixel at a time from each side), and moves each coordinate to simpler values; repeats
/// until no step keeps the failure or `budget` runs are spent. Returns the smallest scene
/// and the runs used.
pub fn shrink(scene: &Scene, keeps: &mut dyn FnMut(&Scene) -> bool, budget: usize) -> (Scene, usize) {
    let mut best = scene.clone();
    let mut runs = 0;
    let mut attempt = |candidate: &Scene, runs: &mut usize| -> bool {
        if *runs >= budget {
            return false;
        }
        *runs += 1;
        keeps(candidate)
    };
    loop {
        let mut changed = false;
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
                }
            }
        }
        if best.clip.is_some() {
            let mut c = best.clone();
            c.clip = None;
            if attempt(&c, &mut runs) {
                best = c;
                changed = true;
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
                    break;
                }
            }
        }
        // Simpler coordinates.
        let n = coordinates(&mut best.clone()).len();
        for k in 0..n {
            let value = coordinates(&mut best.clone())[k].clone();
            for v in simpler(&value) {
                let mut c = best.clone();
                *coordinates(&mut c)[k] = v;
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
    }
}
