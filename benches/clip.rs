//! The cost of exactness in clipping, side by side in one run: Cohen-Sutherland on random
//! segments and Sutherland-Hodgman on random triangles against a 256x256 window, exact
//! (BigRational) against f64 and f32. Throughput elements are primitives (criterion's
//! Melem/s = million primitives per second). The exact forms run on the first 10k of the
//! 100k primitives: their cost per primitive does not depend on how many there are.
//!
//! `cargo bench --features bench --bench clip`

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use glam::DVec2;
use num_rational::BigRational;
use rasterproof::clip::{cohen_sutherland, sutherland_hodgman, Window};
use rasterproof::geom::Point;

#[path = "../tests/common/rng.rs"]
mod rng;
use rng::Rng;

const N: usize = 100_000;
const EXACT_N: usize = 10_000;

/// `n` points on the 1/256 grid of [-128, 384)^2 (the window is [0, 256]^2).
fn points(n: usize, seed: u64) -> Vec<DVec2> {
    let mut rng = Rng(seed);
    #[allow(clippy::cast_precision_loss)] // below 2^17: exact
    let mut c = || (rng.below(512 * 256) - 128 * 256) as f64 / 256.0;
    (0..n).map(|_| DVec2::new(c(), c())).collect()
}

fn exact(p: DVec2) -> Point {
    Point::new(
        BigRational::from_float(p.x).expect("finite"),
        BigRational::from_float(p.y).expect("finite"),
    )
}

fn bench(c: &mut Criterion) {
    let q = |n: i64| BigRational::from_integer(n.into());
    let window = Window::rect(q(0), q(0), q(256), q(256)).unwrap();
    let Window::Rect(rect) = &window else { unreachable!() };
    let (r64, r32) = (rect.to_f64().unwrap(), rect.to_f32().unwrap());
    let planes = window.half_planes();
    let p64: Vec<_> = planes.iter().map(|h| h.to_f64().unwrap()).collect();
    let p32: Vec<_> = planes.iter().map(|h| h.to_f32().unwrap()).collect();

    let pts = points(3 * N, 9);
    let exact_pts: Vec<Point> = pts[..3 * EXACT_N].iter().map(|&p| exact(p)).collect(); // 10k triangles, 10k of its 15k segments

    // f32 inputs converted once, outside the timed loops (exact: they are on the 1/256 grid)
    let pts32: Vec<glam::Vec2> = pts.iter().map(|p| p.as_vec2()).collect();

    let mut g = c.benchmark_group("cohen_sutherland_100k");
    g.sample_size(10);
    g.throughput(Throughput::Elements(EXACT_N as u64));
    g.bench_function(BenchmarkId::from_parameter("exact (10k)"), |b| {
        b.iter(|| {
            exact_pts
                .chunks(2)
                .take(EXACT_N)
                .filter_map(|s| cohen_sutherland::clip_exact(&s[0], &s[1], rect))
                .count()
        });
    });
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function(BenchmarkId::from_parameter("f64"), |b| {
        b.iter(|| {
            pts.chunks(2)
                .take(N)
                .filter_map(|s| cohen_sutherland::clip_f64(s[0], s[1], &r64))
                .count()
        });
    });
    g.bench_function(BenchmarkId::from_parameter("f32"), |b| {
        b.iter(|| {
            pts32
                .chunks(2)
                .take(N)
                .filter_map(|s| cohen_sutherland::clip_f32(s[0], s[1], &r32))
                .count()
        });
    });
    g.finish();

    let mut g = c.benchmark_group("sutherland_hodgman_100k");
    g.sample_size(10);
    g.throughput(Throughput::Elements(EXACT_N as u64));
    g.bench_function(BenchmarkId::from_parameter("exact (10k)"), |b| {
        b.iter(|| {
            exact_pts
                .chunks(3)
                .map(|t| sutherland_hodgman::clip_exact(t, &planes).len())
                .sum::<usize>()
        });
    });
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function(BenchmarkId::from_parameter("f64"), |b| {
        b.iter(|| {
            pts.chunks(3)
                .map(|t| sutherland_hodgman::clip_f64(t, &p64).len())
                .sum::<usize>()
        });
    });
    g.bench_function(BenchmarkId::from_parameter("f32"), |b| {
        b.iter(|| {
            pts32
                .chunks(3)
                .map(|t| sutherland_hodgman::clip_f32(t, &p32).len())
                .sum::<usize>()
        });
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
