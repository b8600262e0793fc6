//! Area coverage speed, side by side in one run: the plain oracle (`area::exact`), exact
//! cell accumulation (`area::cells`), the planned exact engine (`area::planned`), f32 accumulation (`area::float`), FreeType's integer
//! method (`area::ftgrays`) and 4x4 supersampling (`area::supersample`), on a glyph-like
//! polygon (a 16-vertex star outline with a star hole, 1/64 px coordinates, 48 px across)
//! on a 64x64 canvas. Mpix/s is criterion's element throughput (elements = the canvas's
//! pixels).
//!
//! A second group draws real glyphs: DejaVu Sans's "g@&B%" at 24 px per em
//! (`adapters/scenes/dejavu.json`, made by the `glyph-scene` example: 14 polygons, curves
//! flattened at dyadic parameters) on its 123x32 canvas.
//!
//! `cargo bench --features bench --bench area`

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use num_rational::BigRational;
use rasterproof::area::{cells, exact, float, ftgrays, planned, supersample, Semantics};
use rasterproof::geom::{FillRule, Point, Polygon};

const SIDE: u32 = 64;

/// A star of `n` points around (32, 32), radii `outer` and `inner` px, rounded to 1/64 px.
fn star(n: usize, outer: f64, inner: f64, turn: f64) -> Vec<Point> {
    (0..2 * n)
        .map(|k| {
            #[allow(clippy::cast_precision_loss)]
            let a = turn + std::f64::consts::PI * k as f64 / n as f64;
            let r = if k % 2 == 0 { outer } else { inner };
            #[allow(clippy::cast_possible_truncation)]
            let q = |v: f64| BigRational::new(((v * 64.0).round() as i64).into(), 64.into());
            Point::new(q(32.0 + r * a.cos()), q(32.0 + r * a.sin()))
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let glyph = Polygon {
        outline: star(8, 24.0, 15.0, 0.1),
        holes: vec![star(5, 8.0, 4.0, 0.3)],
        fill_rule: FillRule::NonZero,
    };
    let shapes = [glyph];
    let mut g = c.benchmark_group("area");
    g.throughput(Throughput::Elements(u64::from(SIDE * SIDE)));
    g.sample_size(10);
    g.bench_function("exact (plain oracle)", |b| {
        b.iter(|| exact::rasterize(&shapes, SIDE, SIDE, Semantics::True));
    });
    g.bench_function("cells (exact accumulation)", |b| {
        b.iter(|| cells::rasterize(&shapes, SIDE, SIDE, Semantics::Accumulated));
    });
    g.bench_function("planned (exact accumulation, i128)", |b| {
        b.iter(|| planned::rasterize(&shapes, SIDE, SIDE, Semantics::Accumulated));
    });
    g.bench_function("float (f32 accumulation)", |b| {
        b.iter(|| float::rasterize(&shapes, SIDE, SIDE, Semantics::Accumulated));
    });
    g.bench_function("ftgrays (24.8 integers)", |b| {
        b.iter(|| ftgrays::rasterize(&shapes, SIDE, SIDE).unwrap());
    });
    g.bench_function("supersample 4x4 (exact samples)", |b| {
        b.iter(|| supersample::rasterize(&shapes, SIDE, SIDE, 4));
    });
    g.finish();

    let text = include_str!("../adapters/scenes/dejavu.json");
    let scene = rasterproof::scene::parse_scene(text, "dejavu.json").expect("the committed glyph scene");
    let target = scene.target().expect("its canvas");
    let glyphs = rasterproof::model::area_shapes(&scene.primitives(), &target, rasterproof::model::Model::Exact)
        .expect("glyph shapes");
    let (w, h) = (target.width, target.height);
    let mut g = c.benchmark_group("area-glyphs");
    g.throughput(Throughput::Elements(u64::from(w * h)));
    g.sample_size(10);
    g.bench_function("exact (plain oracle)", |b| {
        b.iter(|| exact::rasterize(&glyphs, w, h, Semantics::Accumulated));
    });
    g.bench_function("cells (exact accumulation)", |b| {
        b.iter(|| cells::rasterize(&glyphs, w, h, Semantics::Accumulated));
    });
    g.bench_function("planned (exact accumulation, i128)", |b| {
        b.iter(|| planned::rasterize(&glyphs, w, h, Semantics::Accumulated));
    });
    g.bench_function("float (f32 accumulation)", |b| {
        b.iter(|| float::rasterize(&glyphs, w, h, Semantics::Accumulated));
    });
    g.bench_function("ftgrays (24.8 integers)", |b| {
        b.iter(|| ftgrays::rasterize(&glyphs, w, h).unwrap());
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
