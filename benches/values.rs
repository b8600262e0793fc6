//! Speed of exact interpolated values against float interpolators, side by side in one
//! run, on a 1920x1080 mesh of about 100k triangles (a grid of jittered quads, vertices on
//! the 1/256 grid, each vertex a w of 1/4 to 8 and three values in thirds, tenths and
//! 256ths; about 20 px a triangle). Mpix/s is criterion's element throughput (elements =
//! covered pixels, each one value of three channels).
//!
//! Every contender walks the same list of covered pixels, triangle by triangle (the
//! exact-snapped coverage, computed before timing: the rasterizer is not what is
//! measured), sets each triangle up from inputs already in its own number type (as a
//! renderer holds its vertices), and computes the three channels' f32 values at each pixel
//! centre:
//!
//! - `f32-origin-plane`: the plane equations of `1 / w` and `f / w` anchored at the
//!   framebuffer's origin in f32 (llvmpipe's setup and evaluation: `a0 + dadx x + dady y`,
//!   the quotient as a multiply by the reciprocal; unfused, since without the target's FMA
//!   a fused multiply-add is a library call);
//! - `f32-barycentric`: the three edge functions at the centre, `sum E_i f_i / w_i / sum E_i
//!   / w_i` in f32;
//! - `planned-exact`: the exact value rounded to the nearest f32, from
//!   `interp::planned`'s f64 filter (`FastPlan`): its uniform bound four pixels at a time
//!   (`nearest_f32_x4`), the bound at the pixel where that leaves a pixel, the exact
//!   inputs' sign at an f32 midpoint (`nearest_f32_exact`), and the exact ratio
//!   (`PlannedValue`, set up in rationals on first need) where none of those decides;
//! - `rasterize-exact-snapped`: for scale, what finding those pixels costs (the exact
//!   integer rasterizer, one thread), which a renderer adds to any interpolator;
//! - `plain-exact`: the readable definition (`ValueSetup::value`) in rationals, on the
//!   first 500 triangles only (per pixel its cost does not depend on the mesh size).
//!
//! `cargo bench --features bench --bench values`; `VALUES_BENCH_RAW=1` adds a quick
//! reading of the two contenders the issue compares (the least of 40 runs each) and stops.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use num_rational::BigRational;
use rasterproof::convention::{Preset, Target};
use rasterproof::geom::{Point, Triangle};
use rasterproof::interp::planned::{FastPlan, PlannedValue, TriangleF64};
use rasterproof::interp::values::{Interpolation, ProvokingVertex, ValueSetup, ValueTriangle};
use rasterproof::model::{render, Model, Primitives};
use rasterproof::num::exact::nearest_f32;

#[path = "../tests/common/rng.rs"]
mod rng;
use rng::Rng;

const WIDTH: u32 = 1920;
const HEIGHT: u32 = 1080;
/// 259 x 193 quads, two triangles each: 99,974 triangles.
const COLUMNS: i64 = 259;
const ROWS: i64 = 193;

/// One triangle: its exact setup, its f32 and f64 inputs, and the pixels it shows.
struct Item {
    setup: ValueSetup,
    f32_in: ([f32; 3], [f32; 3], [f32; 3], [[f32; 3]; 3]),
    f64_in: TriangleF64,
    pixels: Vec<(u32, u32)>,
}

/// The mesh's triangles and their canvas, for the rasterizer's share.
struct Geometry {
    primitives: Primitives,
    target: Target,
}

fn mesh() -> (Vec<Item>, u64, Geometry) {
    let mut rng = Rng(0x5eed_1080);
    let g = 256;
    // Grid vertices, interior ones jittered by up to a third of a cell; each with a w and
    // three values.
    let w_of = [1i64, 2, 4, 8, 16, 32];
    let mut vertices = Vec::new();
    for j in 0..=ROWS {
        for i in 0..=COLUMNS {
            let (cx, cy) = (i * i64::from(WIDTH) * g / COLUMNS, j * i64::from(HEIGHT) * g / ROWS);
            let jitter = |rng: &mut Rng, edge: bool, cell: i64| if edge { 0 } else { rng.range(-cell / 3, cell / 3) };
            let x = cx + jitter(&mut rng, i == 0 || i == COLUMNS, i64::from(WIDTH) * g / COLUMNS);
            let y = cy + jitter(&mut rng, j == 0 || j == ROWS, i64::from(HEIGHT) * g / ROWS);
            let w = BigRational::new(w_of[rng.below(6) as usize].into(), 4.into());
            let values: Vec<BigRational> = (0..3)
                .map(|_| {
                    BigRational::new(
                        (rng.below(2001) - 1000).into(),
                        [1i64, 3, 10, 256][rng.below(4) as usize].into(),
                    )
                })
                .collect();
            vertices.push((Point::from_fractions(x, g, y, g), w, values));
        }
    }
    let at = |i: i64, j: i64| (j * (COLUMNS + 1) + i) as usize;
    let mut triangles = Vec::new();
    for j in 0..ROWS {
        for i in 0..COLUMNS {
            triangles.push([at(i, j), at(i + 1, j), at(i, j + 1)]);
            triangles.push([at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    let target = Target::new(WIDTH, HEIGHT, Preset::Vulkan.convention()).unwrap();
    let geometry: Vec<Triangle> = triangles
        .iter()
        .map(|t| {
            Triangle::new(
                vertices[t[0]].0.clone(),
                vertices[t[1]].0.clone(),
                vertices[t[2]].0.clone(),
            )
        })
        .collect();
    let coverage = render(&Primitives::from_triangles(&geometry), &target, Model::ExactSnapped).unwrap();
    let mut pixels = vec![Vec::new(); triangles.len()];
    let mut total = 0;
    for (x, y, ids) in coverage.iter() {
        if let Some(&id) = ids.last() {
            pixels[id as usize].push((x, y));
            total += 1;
        }
    }
    let items = triangles
        .iter()
        .zip(pixels)
        .map(|(t, pixels)| {
            let v = t.map(|k| &vertices[k]);
            let setup = ValueSetup::Triangle(Box::new(ValueTriangle::window(
                [&v[0].0, &v[1].0, &v[2].0],
                [&v[0].1, &v[1].1, &v[2].1],
                [v[0].2.clone(), v[1].2.clone(), v[2].2.clone()],
            )));
            let f = |q: &BigRational| nearest_f32(q).unwrap();
            let f32_in = (
                v.map(|v| f(&v.0.x)),
                v.map(|v| f(&v.0.y)),
                v.map(|v| 1.0 / f(&v.1)),
                v.map(|v| [f(&v.2[0]), f(&v.2[1]), f(&v.2[2])]),
            );
            let f64_in = TriangleF64::of(&setup, 0..3).unwrap();
            Item {
                setup,
                f32_in,
                f64_in,
                pixels,
            }
        })
        .collect();
    let geometry = Geometry {
        primitives: Primitives::from_triangles(&geometry),
        target,
    };
    (items, total, geometry)
}

/// llvmpipe's plane setup in f32 (see `interp::float`'s module docs): each attribute
/// `a_i` (here `1 / w_i` and `f_i / w_i`) as `a0 + dadx x + dady y` at integer pixel
/// coordinates, the centre folded into `a0`.
fn plane(x: &[f32; 3], y: &[f32; 3], a: [f32; 3]) -> [f32; 3] {
    let (dx01, dy01) = (x[0] - x[1], y[0] - y[1]);
    let (dx20, dy20) = (x[2] - x[0], y[2] - y[0]);
    let ooa = 1.0 / (dx01 * dy20 - dy01 * dx20);
    let (da01, da20) = (a[0] - a[1], a[2] - a[0]);
    let dadx = da01 * (dy20 * ooa) - da20 * (dy01 * ooa);
    let dady = da20 * (dx01 * ooa) - da01 * (dx20 * ooa);
    let a0 = a[0] - (dadx * (x[0] - 0.5) + dady * (y[0] - 0.5));
    [a0, dadx, dady]
}

fn f32_origin_plane(items: &[Item]) -> u64 {
    let mut sum = 0u64;
    for item in items {
        let (x, y, r, v) = &item.f32_in;
        let w = plane(x, y, *r);
        let c = [0, 1, 2].map(|c| plane(x, y, [v[0][c] * r[0], v[1][c] * r[1], v[2][c] * r[2]]));
        for &(px, py) in &item.pixels {
            let (fx, fy) = (px as f32, py as f32);
            // Unfused: `mul_add` without the target's FMA is a library call, not the
            // instruction a renderer built for its CPU uses.
            let rw = 1.0 / (w[0] + w[1] * fx + w[2] * fy);
            for p in &c {
                sum = sum.wrapping_add(u64::from(((p[0] + p[1] * fx + p[2] * fy) * rw).to_bits()));
            }
        }
    }
    sum
}

fn f32_barycentric(items: &[Item]) -> u64 {
    let mut sum = 0u64;
    for item in items {
        let (x, y, r, v) = &item.f32_in;
        let g = [0, 1, 2].map(|c| [v[0][c] * r[0], v[1][c] * r[1], v[2][c] * r[2]]);
        for &(px, py) in &item.pixels {
            let (cx, cy) = (px as f32 + 0.5, py as f32 + 0.5);
            let e = [0, 1, 2].map(|i| {
                let (j, k) = ((i + 1) % 3, (i + 2) % 3);
                (x[j] - cx) * (y[k] - cy) - (x[k] - cx) * (y[j] - cy)
            });
            let d = e[0] * r[0] + e[1] * r[1] + e[2] * r[2];
            for gc in &g {
                let n = e[0] * gc[0] + e[1] * gc[1] + e[2] * gc[2];
                sum = sum.wrapping_add(u64::from((n / d).to_bits()));
            }
        }
    }
    sum
}

/// How many channel values each tier of the planned path decided.
#[derive(Debug, Default, Clone, Copy, PartialEq)]
struct Tiers {
    /// The uniform bound, four pixels at a time.
    uniform: u64,
    /// The bound at the pixel.
    pixel: u64,
    /// The sign of the exact inputs at an f32 midpoint.
    sign: u64,
    /// The exact ratio.
    ratio: u64,
}

/// The planned path as a renderer would run it: each triangle's pixels four at a time
/// under the uniform bound, a pixel it leaves under the bound at the pixel, a value that
/// leaves at an f32 midpoint by the exact inputs' sign, and what that leaves by the exact
/// ratio.
fn planned_exact(items: &[Item]) -> (u64, Tiers) {
    let mut sum = 0u64;
    let mut tiers = Tiers::default();
    let half = BigRational::new(1.into(), 2.into());
    let mut four = [[0.0f32; 4]; 4];
    let mut out = [None; 3];
    for item in items {
        let fast = FastPlan::new(&item.f64_in, Interpolation::Smooth, ProvokingVertex::First, (0.5, 0.5));
        let mut slow: Option<Vec<PlannedValue>> = None;
        for chunk in item.pixels.chunks(4) {
            // A short last chunk repeats its last pixel.
            let at = |i: usize| chunk[i.min(chunk.len() - 1)];
            let (xs, ys) = ([0, 1, 2, 3].map(|i| at(i).0), [0, 1, 2, 3].map(|i| at(i).1));
            let undecided = fast.nearest_f32_x4(xs, ys, &mut four);
            for (i, &(px, py)) in chunk.iter().enumerate() {
                if undecided & (1 << i) == 0 {
                    tiers.uniform += 3;
                    for channel in &four[..3] {
                        sum = sum.wrapping_add(u64::from(channel[i].to_bits()));
                    }
                    continue;
                }
                fast.nearest_f32(px, py, &mut out);
                for (c, o) in out.iter().enumerate() {
                    let f = if let Some(f) = o {
                        tiers.pixel += 1;
                        *f
                    } else if let Some(f) = fast.nearest_f32_exact(&item.setup, 0, px, py, c) {
                        tiers.sign += 1;
                        f
                    } else {
                        tiers.ratio += 1;
                        let plans = slow.get_or_insert_with(|| {
                            PlannedValue::channels(
                                &item.setup,
                                Interpolation::Smooth,
                                ProvokingVertex::First,
                                0..3,
                                &half,
                            )
                        });
                        plans[c].nearest_f32(px, py).unwrap().unwrap()
                    };
                    sum = sum.wrapping_add(u64::from(f.to_bits()));
                }
            }
        }
    }
    (sum, tiers)
}

/// Each pixel's values from the exact ratio alone (`PlannedValue`, which the tests prove
/// equal to the plain definition): what the planned path must equal on the whole mesh.
fn ratio_exact(items: &[Item]) -> u64 {
    let mut sum = 0u64;
    let half = BigRational::new(1.into(), 2.into());
    for item in items {
        let fast = FastPlan::new(&item.f64_in, Interpolation::Smooth, ProvokingVertex::First, (0.5, 0.5));
        let mut slow: Option<Vec<PlannedValue>> = None;
        let mut out = [None; 3];
        for &(px, py) in &item.pixels {
            fast.nearest_f32(px, py, &mut out);
            for (c, o) in out.iter().enumerate() {
                // The bound at the pixel where it decides (proven with the ratio in the
                // tests), the ratio itself everywhere else.
                let f = o.unwrap_or_else(|| {
                    let plans = slow.get_or_insert_with(|| {
                        PlannedValue::channels(&item.setup, Interpolation::Smooth, ProvokingVertex::First, 0..3, &half)
                    });
                    plans[c].nearest_f32(px, py).unwrap().unwrap()
                });
                sum = sum.wrapping_add(u64::from(f.to_bits()));
            }
        }
    }
    sum
}

fn plain_exact(items: &[Item]) -> u64 {
    let mut sum = 0u64;
    let half = BigRational::new(1.into(), 2.into());
    for item in items {
        for &(px, py) in &item.pixels {
            let p = Point::new(
                BigRational::from_integer(px.into()) + &half,
                BigRational::from_integer(py.into()) + &half,
            );
            let v = item
                .setup
                .value(Interpolation::Smooth, ProvokingVertex::First, 0..3, &p)
                .unwrap();
            for c in &v {
                sum = sum.wrapping_add(u64::from(nearest_f32(c).unwrap().to_bits()));
            }
        }
    }
    sum
}

fn bench(c: &mut Criterion) {
    let (items, pixels, geometry) = mesh();
    let subset = &items[..500];
    let subset_pixels: u64 = subset.iter().map(|i| i.pixels.len() as u64).sum();
    // The planned values are the plain ones (checked here once, outside the timing): on
    // a 500-triangle prefix against the definition, on the whole mesh against the exact
    // ratio; and how often each tier decided.
    let (planned_sum, _) = planned_exact(subset);
    assert_eq!(planned_sum, plain_exact(subset), "planned and plain values differ");
    let (planned_all, tiers) = planned_exact(&items);
    assert_eq!(
        planned_all,
        ratio_exact(&items),
        "planned values and the exact ratio's differ"
    );
    eprintln!(
        "mesh: {} triangles, {pixels} covered pixels ({:.1} a triangle), {} channel values decided by: the uniform bound {}, the bound at the pixel {}, the exact inputs' sign {}, the exact ratio {}",
        items.len(),
        pixels as f64 / items.len() as f64,
        3 * pixels,
        tiers.uniform,
        tiers.pixel,
        tiers.sign,
        tiers.ratio,
    );
    if std::env::var_os("VALUES_BENCH_RAW").is_some() {
        // A quick reading without criterion: the least of 40 runs of each, alternating.
        let least = |f: &dyn Fn() -> u64| {
            (0..40)
                .map(|_| {
                    let t = std::time::Instant::now();
                    std::hint::black_box(f());
                    t.elapsed().as_secs_f64() * 1e3
                })
                .fold(f64::INFINITY, f64::min)
        };
        let (a, b) = (least(&|| f32_origin_plane(&items)), least(&|| planned_exact(&items).0));
        eprintln!(
            "least of 40: f32-origin-plane {a:.2} ms, planned-exact {b:.2} ms, planned at {:.2}x its speed",
            a / b
        );
        return;
    }
    let mut group = c.benchmark_group("values-1080p-100k");
    group.sample_size(10);
    group.throughput(Throughput::Elements(pixels));
    group.bench_function("f32-origin-plane", |b| b.iter(|| f32_origin_plane(&items)));
    group.bench_function("f32-barycentric", |b| b.iter(|| f32_barycentric(&items)));
    group.bench_function("planned-exact", |b| b.iter(|| planned_exact(&items)));
    // What a renderer adds to any of them: finding the covered pixels (the exact-snapped
    // integer rasterizer, one thread).
    group.bench_function("rasterize-exact-snapped", |b| {
        b.iter(|| render(&geometry.primitives, &geometry.target, Model::ExactSnapped).unwrap())
    });
    group.throughput(Throughput::Elements(subset_pixels));
    group.bench_function("plain-exact (500 triangles)", |b| b.iter(|| plain_exact(subset)));
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
