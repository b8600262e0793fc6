//! The planner's order of widths, measured: the planned triangle traversal forced into
//! each width on the same workload, side by side, round-robin in one process (median of
//! 21 repetitions, Mpix/s and the ratio to i32). The workload has every value below 2^24 so that
//! all six widths can run it: 10k medium triangles with integer vertices (scale 2) at
//! 1024x1024.
//!
//! `cargo bench --features bench --bench widths`; the figures are in `rasterproof::num::plan::CHEAPEST_FIRST`.

use std::time::Instant;

use rasterproof::convention::{Preset, Target};
use rasterproof::coverage::CountBuffer;
use rasterproof::geom::{Point, Triangle};
use rasterproof::num::plan::Width;
use rasterproof::tri::planned::PlannedTriangle;

#[path = "../tests/common/rng.rs"]
mod rng;
use rng::Rng;

fn triangles(n: usize, side: i64, spread: i64, seed: u64) -> Vec<Triangle> {
    let mut rng = Rng(seed);
    (0..n)
        .map(|_| {
            let (cx, cy) = (rng.below(side), rng.below(side));
            let mut vertex = || {
                let x = (cx + rng.below(2 * spread) - spread).clamp(0, side);
                let y = (cy + rng.below(2 * spread) - spread).clamp(0, side);
                Point::from_ints(x, y)
            };
            Triangle::new(vertex(), vertex(), vertex())
        })
        .collect()
}

fn main() {
    let side = 1024;
    let target = Target::new(side, side, Preset::D3d11.convention()).unwrap();
    let tris = triangles(10_000, i64::from(side), 24, 1);
    let planned: Vec<(Width, Vec<PlannedTriangle>)> = Width::ALL
        .into_iter()
        .map(|width| {
            let ts = tris
                .iter()
                .filter_map(|t| PlannedTriangle::forced(t, &target, width).expect("every value below 2^24"))
                .collect();
            (width, ts)
        })
        .collect();
    let mut sink = CountBuffer::new(side, side);
    planned[0].1.iter().for_each(|p| p.rasterize(0, &mut sink));
    let pixels = sink.total();
    // Round-robin: every repetition times each width once, so drift hits all alike.
    let reps = 21;
    let mut times: Vec<Vec<f64>> = vec![Vec::new(); planned.len()];
    for _ in 0..reps {
        for (k, (_, ts)) in planned.iter().enumerate() {
            let mut sink = CountBuffer::new(side, side);
            let start = Instant::now();
            ts.iter().for_each(|p| p.rasterize(0, &mut sink));
            times[k].push(start.elapsed().as_secs_f64());
            assert_eq!(sink.total(), pixels, "every width covers the same pixels");
        }
    }
    println!(
        "planned traversal, 10k medium triangles at 1024x1024 ({pixels} pixels), median of {reps} round-robin reps"
    );
    println!("{:<8} {:>10} {:>10} {:>8}", "width", "ms", "Mpix/s", "vs i32");
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let medians: Vec<f64> = times.iter_mut().map(median).collect();
    let i32_time = medians[1];
    for ((width, _), t) in planned.iter().zip(&medians) {
        println!(
            "{:<8} {:>10.2} {:>10.1} {:>8.2}",
            width.name(),
            t * 1e3,
            pixels as f64 / t / 1e6,
            i32_time / t
        );
    }
}
