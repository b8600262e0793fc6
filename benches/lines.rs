//! Speed of every line model, side by side: Mpix/s is criterion's element throughput
//! (elements = pixels produced by the workload).
//!
//! Workload: 100k random lines of 1..=1000 px (Chebyshev length) on a 1024x1024 canvas,
//! starts on the canvas, ends anywhere (some run off it). Rows:
//!
//! - `bresenham walk`: ours, `bresenham::walk` counting pixels (every pixel of every line);
//! - `line_drawing Bresenham`: the `line_drawing` crate's iterator, counting pixels;
//! - `dda f32/f64 walk`: `dda::walk_f32/f64` counting pixels; `dda f32/f64 pixels (Vec)`:
//!   `dda::pixels_f32/f64`, each line's pixels into a fresh `Vec`;
//! - `bresenham draw`: ours into a `CountBuffer` (pixels on the canvas only);
//! - `diamond fixed`: `diamond::rasterize` of the same endpoints (pixel centres, 8 subpixel
//!   bits) into a `CountBuffer` (pixels drawn: on the canvas, last pixel excluded);
//! - `exact bresenham`: the exact reference `exact::resolve(&exact::ideal(..))` on the
//!   first 1000 lines only (its cost per pixel does not depend on the workload size).
//!
//! `cargo bench --features bench --bench lines`

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use rasterproof::convention::{Preset, Target};
use rasterproof::coverage::CountBuffer;
use rasterproof::line::dda::DdaFloat;
use rasterproof::line::diamond::FixedSegment;
use rasterproof::line::{bresenham, dda, diamond, exact, BresenhamTie};
use rasterproof::num::SubPixel;

const SIDE: u32 = 1024;
const LINES: usize = 100_000;
const EXACT_LINES: usize = 1000;

#[path = "../tests/common/rng.rs"]
mod rng;
#[path = "common/workloads.rs"]
mod workloads;

/// The segment between the centres of pixels `a` and `b`, on the 2^-8 grid.
fn segment(a: [i64; 2], b: [i64; 2]) -> FixedSegment {
    let sub = |p: [i64; 2]| p.map(|v| SubPixel::new(v * 256 + 128).expect("inside the envelope"));
    FixedSegment {
        a: sub(a),
        b: sub(b),
        bits: 8,
    }
}

fn walk_count(ls: &[([i64; 2], [i64; 2])]) -> u64 {
    let mut n = 0u64;
    for &(a, b) in ls {
        bresenham::walk(a, b, BresenhamTie::Stay, |p, _| {
            black_box(p);
            n += 1;
        });
    }
    n
}

fn line_drawing_count(ls: &[([i64; 2], [i64; 2])]) -> u64 {
    let mut n = 0u64;
    for &(a, b) in ls {
        for p in line_drawing::Bresenham::new((a[0], a[1]), (b[0], b[1])) {
            black_box(p);
            n += 1;
        }
    }
    n
}

/// The DDA through its visitor (no allocation), counting pixels.
fn dda_walk_count(ls: &[([i64; 2], [i64; 2])], float: DdaFloat) -> u64 {
    let mut n = 0u64;
    let mut visit = |p: [i64; 2]| {
        black_box(p);
        n += 1;
    };
    for &(a, b) in ls {
        match float {
            DdaFloat::F32 => dda::walk_f32(a, b, &mut visit),
            DdaFloat::F64 => dda::walk_f64(a, b, &mut visit),
        }
    }
    n
}

/// The DDA into a fresh `Vec` per line.
fn dda_vec_count(ls: &[([i64; 2], [i64; 2])], f: fn([i64; 2], [i64; 2]) -> Vec<[i64; 2]>) -> u64 {
    ls.iter().map(|&(a, b)| black_box(f(a, b)).len() as u64).sum()
}

fn exact_count(ls: &[([i64; 2], [i64; 2])]) -> u64 {
    ls.iter()
        .map(|&(a, b)| black_box(exact::resolve(&exact::ideal(a, b), BresenhamTie::Stay)).len() as u64)
        .sum()
}

fn bresenham_draw(ls: &[([i64; 2], [i64; 2])], target: &Target, sink: &mut CountBuffer) {
    for (k, &(a, b)) in ls.iter().enumerate() {
        bresenham::rasterize(a, b, BresenhamTie::Stay, k as u32, target, sink);
    }
}

fn diamond_draw(segs: &[FixedSegment], target: &Target, sink: &mut CountBuffer) {
    for (k, s) in segs.iter().enumerate() {
        diamond::rasterize(s, k as u32, target, sink);
    }
}

/// Pixels a drawing routine puts on the canvas.
fn drawn(draw: impl Fn(&mut CountBuffer)) -> u64 {
    let mut sink = CountBuffer::new(SIDE, SIDE);
    draw(&mut sink);
    sink.total()
}

fn bench_lines(c: &mut Criterion) {
    let ls = workloads::lines(LINES, i64::from(SIDE), false, 1);
    let segs: Vec<FixedSegment> = ls.iter().map(|&(a, b)| segment(a, b)).collect();
    let target = Target::new(SIDE, SIDE, Preset::D3d11.convention()).unwrap();
    let all_pixels = walk_count(&ls);
    let mut group = c.benchmark_group("lines_100k_1024");
    group.sample_size(10);

    group.throughput(Throughput::Elements(all_pixels));
    group.bench_function(BenchmarkId::from_parameter("bresenham walk"), |b| {
        b.iter(|| walk_count(&ls))
    });
    assert_eq!(line_drawing_count(&ls), all_pixels);
    group.bench_function(BenchmarkId::from_parameter("line_drawing Bresenham"), |b| {
        b.iter(|| line_drawing_count(&ls))
    });
    group.bench_function(BenchmarkId::from_parameter("dda f32 walk"), |b| {
        b.iter(|| dda_walk_count(&ls, DdaFloat::F32))
    });
    group.bench_function(BenchmarkId::from_parameter("dda f64 walk"), |b| {
        b.iter(|| dda_walk_count(&ls, DdaFloat::F64))
    });
    group.bench_function(BenchmarkId::from_parameter("dda f32 pixels (Vec)"), |b| {
        b.iter(|| dda_vec_count(&ls, dda::pixels_f32))
    });
    group.bench_function(BenchmarkId::from_parameter("dda f64 pixels (Vec)"), |b| {
        b.iter(|| dda_vec_count(&ls, dda::pixels_f64))
    });

    let mut sink = CountBuffer::new(SIDE, SIDE);
    let (on_canvas, diamond_pixels) = (
        drawn(|s| bresenham_draw(&ls, &target, s)),
        drawn(|s| diamond_draw(&segs, &target, s)),
    );
    eprintln!(
        "workload: {LINES} lines, {all_pixels} Bresenham pixels ({on_canvas} on the canvas), {diamond_pixels} diamond-exit pixels"
    );
    group.throughput(Throughput::Elements(on_canvas));
    group.bench_function(BenchmarkId::from_parameter("bresenham draw (CountBuffer)"), |b| {
        b.iter(|| bresenham_draw(&ls, &target, &mut sink))
    });
    group.throughput(Throughput::Elements(diamond_pixels));
    group.bench_function(BenchmarkId::from_parameter("diamond fixed (CountBuffer)"), |b| {
        b.iter(|| diamond_draw(&segs, &target, &mut sink))
    });

    let few = &ls[..EXACT_LINES];
    group.throughput(Throughput::Elements(walk_count(few)));
    group.bench_function(
        BenchmarkId::from_parameter(format!("exact bresenham ({EXACT_LINES} lines)")),
        |b| b.iter(|| exact_count(few)),
    );
    group.finish();
}

criterion_group!(benches, bench_lines);
criterion_main!(benches);
