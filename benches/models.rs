//! Speed of every triangle model, side by side, in one run: Mpix/s is criterion's
//! element throughput (elements = covered pixels of the workload).
//!
//! Workloads: (a) 10k medium triangles at 1024x1024, (b) 100k small triangles at
//! 1024x1024, (c) one triangle covering half of 4096x4096, all on the 1/256 grid; then
//! (a) and (b) again with 3-decimal coordinates (`exact`'s own workload: scale 1000), and
//! (a) at 2^40 px scale (every coordinate times 2^32, a canvas window there) for the
//! arbitrary-precision fallback. The plain oracles are measured on a prefix of (a) and
//! (b) and on a 512x512 version of (c) — per pixel their cost does not depend on the
//! workload size, and the full workloads would take minutes per sample.
//!
//! `cargo bench --features bench --bench models`

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use rasterproof::convention::{Preset, Target};
use rasterproof::coverage::CountBuffer;
use rasterproof::geom::{Point, Triangle};
use rasterproof::model::{prepare, Model, Primitives};

#[path = "../tests/common/rng.rs"]
mod rng;
#[path = "common/workloads.rs"]
mod workloads;
use workloads::{half_canvas, triangles};

fn covered(model: Model, tris: &[Triangle], target: &Target) -> u64 {
    let prepared = prepare(&Primitives::from_triangles(tris), target, model).unwrap();
    let mut sink = CountBuffer::new(target.width, target.height);
    prepared.render(target, &mut sink);
    sink.total()
}

fn bench_workload(
    c: &mut Criterion,
    name: &str,
    side: u32,
    full: &[Triangle],
    exact_subset: &[Triangle],
    exact_side: u32,
) {
    let mut group = c.benchmark_group(name);
    group.sample_size(10);
    for model in Model::ALL {
        let is_exact = matches!(model, Model::ExactPlain | Model::ExactSnappedPlain);
        let (tris, side) = if is_exact {
            (exact_subset, exact_side)
        } else {
            (full, side)
        };
        let target = Target::new(side, side, Preset::D3d11.convention()).unwrap();
        let pixels = covered(model, tris, &target);
        group.throughput(Throughput::Elements(pixels));
        let prepared = prepare(&Primitives::from_triangles(tris), &target, model).unwrap();
        let mut sink = CountBuffer::new(side, side);
        let label = if is_exact {
            format!("{model} ({} tris, {side}px)", tris.len())
        } else {
            model.to_string()
        };
        group.bench_function(BenchmarkId::from_parameter(label), |b| {
            b.iter(|| prepared.render(&target, &mut sink));
        });
    }
    group.finish();
}

/// The same triangles with every coordinate moved to the nearest 1/1000 (3 decimals, as a
/// scene file written with `%.3f` has them).
fn decimal(tris: &[Triangle]) -> Vec<Triangle> {
    use num_rational::BigRational;
    let to =
        |v: &BigRational| (v * BigRational::from_integer(1000.into())).round() / BigRational::from_integer(1000.into());
    tris.iter()
        .map(|t| {
            let p = |i: usize| Point::new(to(&t.v[i].x), to(&t.v[i].y));
            Triangle::new(p(0), p(1), p(2))
        })
        .collect()
}

/// The same triangles with every coordinate moved by `k / p`, p = 2^61 - 1 (a prime): the
/// scale is p times the grid's and the edge values pass 2^127, so the planner falls back
/// to arbitrary precision.
fn beyond_i128(tris: &[Triangle]) -> Vec<Triangle> {
    use num_rational::BigRational;
    let p = (1i64 << 61) - 1;
    let nudge = |v: &BigRational, k: i64| v + BigRational::new(k.into(), p.into());
    tris.iter()
        .map(|t| {
            let q = |i: usize| Point::new(nudge(&t.v[i].x, 1 + i as i64), nudge(&t.v[i].y, 7 + i as i64));
            Triangle::new(q(0), q(1), q(2))
        })
        .collect()
}

/// Planned `exact` against `fixed` (and the plain oracle on a prefix) on a workload the
/// exact model reads as written.
fn bench_as_written(c: &mut Criterion, name: &str, side: u32, full: &[Triangle], prefix: usize) {
    let mut group = c.benchmark_group(name);
    group.sample_size(10);
    let target = Target::new(side, side, Preset::D3d11.convention()).unwrap();
    for (model, tris) in [
        (Model::Fixed, full),
        (Model::Exact, full),
        (Model::ExactPlain, &full[..prefix]),
    ] {
        let pixels = covered(model, tris, &target);
        group.throughput(Throughput::Elements(pixels));
        let prepared = prepare(&Primitives::from_triangles(tris), &target, model).unwrap();
        let mut sink = CountBuffer::new(side, side);
        let label = format!("{model} ({} tris)", tris.len());
        group.bench_function(BenchmarkId::from_parameter(label), |b| {
            b.iter(|| prepared.render(&target, &mut sink));
        });
    }
    group.finish();
}

fn models(c: &mut Criterion) {
    let medium = triangles(10_000, 1024, 24, 1);
    bench_workload(c, "a_medium_10k_1024", 1024, &medium, &medium[..100], 1024);
    let small = triangles(100_000, 1024, 4, 2);
    bench_workload(c, "b_small_100k_1024", 1024, &small, &small[..2000], 1024);
    bench_workload(c, "c_half_4096", 4096, &half_canvas(4096), &half_canvas(512), 512);
    bench_as_written(c, "a_medium_10k_1024_3_decimals", 1024, &decimal(&medium), 100);
    bench_as_written(c, "b_small_100k_1024_3_decimals", 1024, &decimal(&small), 2000);
    bench_as_written(c, "a_medium_1024_beyond_i128", 1024, &beyond_i128(&medium[..1000]), 100);
}

criterion_group!(benches, models);
criterion_main!(benches);
