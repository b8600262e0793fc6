//! The bench workloads shared by `models`, `peers` and `lines` (one generator each, so the
//! benches measure the same inputs). Include with `#[path = "common/workloads.rs"] mod
//! workloads;` next to `mod rng;` (tests/common/rng.rs).

#![allow(dead_code)] // each bench uses its share

use rasterproof::geom::{Point, Triangle};

use super::rng::Rng;

/// `n` triangles on the 1/256 grid of a `side` canvas, vertices within `spread` px of a
/// random centre.
pub fn triangles(n: usize, side: i64, spread: i64, seed: u64) -> Vec<Triangle> {
    let mut rng = Rng(seed);
    let g = 256;
    (0..n)
        .map(|_| {
            let (cx, cy) = (rng.below(side * g), rng.below(side * g));
            let mut vertex = || {
                let x = (cx + rng.below(2 * spread * g) - spread * g).clamp(0, side * g);
                let y = (cy + rng.below(2 * spread * g) - spread * g).clamp(0, side * g);
                Point::from_fractions(x, g, y, g)
            };
            Triangle::new(vertex(), vertex(), vertex())
        })
        .collect()
}

/// One triangle covering half of a `side` canvas.
pub fn half_canvas(side: i64) -> Vec<Triangle> {
    vec![Triangle::new(
        Point::from_ints(0, 0),
        Point::from_ints(side, 0),
        Point::from_ints(0, side),
    )]
}

/// A line between two pixel addresses.
pub type Segment = ([i64; 2], [i64; 2]);

/// `n` lines: start on a `side` canvas, major length 1..=1000, minor length 0..=major,
/// random signs and major axis; with `inside`, the far end is drawn again until it is on
/// the canvas too.
pub fn lines(n: usize, side: i64, inside: bool, seed: u64) -> Vec<Segment> {
    let mut rng = Rng(seed);
    (0..n)
        .map(|_| {
            let a = [rng.range(0, side - 1), rng.range(0, side - 1)];
            loop {
                let major = rng.range(1, 1000);
                let minor = rng.range(0, major);
                let mut sign = || if rng.next() & 1 == 0 { 1 } else { -1 };
                let (dmaj, dmin) = (sign() * major, sign() * minor);
                let (dx, dy) = if rng.next() & 1 == 0 {
                    (dmaj, dmin)
                } else {
                    (dmin, dmaj)
                };
                let b = [a[0] + dx, a[1] + dy];
                if !inside || b.iter().all(|v| (0..side).contains(v)) {
                    return (a, b);
                }
            }
        })
        .collect()
}
