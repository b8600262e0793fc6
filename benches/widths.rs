//! The planner's order of widths, measured: the planned triangle traversal forced into
//! each width on the same workload, side by side (criterion's element throughput is
//! Mpix/s, elements = covered pixels). The workload has every value below 2^24 so that
//! all six widths can run it: 10k medium triangles with integer vertices (scale 2) at
//! 1024x1024.
//!
//! `cargo bench --bench widths`; the figures are in `rasterproof::num::plan::CHEAPEST_FIRST`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
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

fn widths(c: &mut Criterion) {
    let side = 1024;
    let target = Target::new(side, side, Preset::D3d11.convention()).unwrap();
    let tris = triangles(10_000, i64::from(side), 24, 1);
    let mut group = c.benchmark_group("widths_a_medium_10k_1024");
    group.sample_size(10);
    for width in Width::ALL {
        let planned: Vec<PlannedTriangle> = tris
            .iter()
            .filter_map(|t| PlannedTriangle::forced(t, &target, width).expect("every value below 2^24"))
            .collect();
        let mut sink = CountBuffer::new(side, side);
        planned.iter().for_each(|p| p.rasterize(0, &mut sink));
        group.throughput(Throughput::Elements(sink.total()));
        group.bench_function(BenchmarkId::from_parameter(width.name()), |b| {
            b.iter(|| planned.iter().for_each(|p| p.rasterize(0, &mut sink)));
        });
    }
    group.finish();
}

criterion_group!(benches, widths);
criterion_main!(benches);
