//! Flood fill speed on 4096x4096 images, the span fill beside the BFS oracle in one run:
//! Mpix/s is criterion's element throughput (elements = pixels in the region filled).
//!
//! Workloads: (a) one colour everywhere (the region is all 16.8M pixels); (b) a random
//! depth-first maze, 2047x2047 cells (the region is its 8.4M passage pixels, one run per
//! corridor piece); (c) noise with 70% of the pixels one colour, above the 4-connected
//! site-percolation threshold (0.593), so the seed's region spans the image with holes
//! everywhere. Each is filled 4- and 8-connected. `flood_fill` (region and recolouring)
//! is measured on (a) too, on a fresh copy of the image each time (the copy is not timed).
//!
//! `cargo bench --features bench --bench flood -- --warm-up-time 1 --measurement-time 4`

use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion, Throughput};
use image::{Rgba, RgbaImage};
use rasterproof::fill::flood::{bfs_region, flood_fill, span_region, Connectivity};

#[path = "../tests/common/raster.rs"]
mod raster;
#[path = "../tests/common/rng.rs"]
mod rng;

const SIDE: u32 = 4096;
const A: Rgba<u8> = Rgba([20, 40, 60, 255]);
const B: Rgba<u8> = Rgba([200, 100, 0, 255]);

fn bench_image(c: &mut Criterion, name: &str, img: &RgbaImage, seed: (u32, u32), with_flood_fill: bool) {
    let mut group = c.benchmark_group(name);
    group.sample_size(10);
    for conn in Connectivity::ALL {
        let region = span_region(img, seed, conn).unwrap();
        assert_eq!(region, bfs_region(img, seed, conn).unwrap(), "{name} {conn}");
        group.throughput(Throughput::Elements(region.len() as u64));
        let n = conn.number();
        group.bench_function(BenchmarkId::new("span", n), |b| {
            b.iter(|| span_region(img, seed, conn).unwrap());
        });
        group.bench_function(BenchmarkId::new("bfs", n), |b| {
            b.iter(|| bfs_region(img, seed, conn).unwrap());
        });
        if with_flood_fill {
            group.bench_function(BenchmarkId::new("flood_fill", n), |b| {
                b.iter_batched_ref(
                    || img.clone(),
                    |copy| flood_fill(copy, seed, conn, B).unwrap(),
                    BatchSize::PerIteration,
                );
            });
        }
    }
    group.finish();
}

fn flood(c: &mut Criterion) {
    let one = RgbaImage::from_pixel(SIDE, SIDE, A);
    bench_image(c, "a_one_region_4096", &one, (SIDE / 2, SIDE / 2), true);
    drop(one);
    let maze = raster::maze(SIDE, SIDE, 0, 42);
    bench_image(c, "b_maze_4096", &maze, (1, 1), false);
    drop(maze);
    let noise = raster::noise(SIDE, SIDE, &[A, B], &[7, 3], 9);
    let seed = noise
        .enumerate_pixels()
        .find(|p| *p.2 == A)
        .map(|p| (p.0, p.1))
        .unwrap();
    bench_image(c, "c_noise70_4096", &noise, seed, false);
}

criterion_group!(benches, flood);
criterion_main!(benches);
