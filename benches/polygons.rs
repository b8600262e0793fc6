//! Polygon fill speed, side by side in one run: the scanline filler (active edge table)
//! against triangulate-then-`fixed`, on 1000 random simple polygons (star-shaped, 3 to 24
//! vertices, about half with a hole, up to 96 px across) scattered over 1024x1024; the
//! exact oracle on the first 5. Mpix/s is criterion's element throughput (elements =
//! covered pixels).
//!
//! `cargo bench --features bench --bench polygons`

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use rasterproof::convention::{Preset, Target};
use rasterproof::coverage::CountBuffer;
use rasterproof::fill::triangulate::validate;
use rasterproof::geom::Polygon;
use rasterproof::model::{prepare, Model, PreparedScene, Primitives};
use rasterproof::strategy::polygon::simple_polygon;

#[path = "../tests/common/rng.rs"]
mod rng;
use rng::Rng;

const SIDE: u32 = 1024;

/// `n` simple polygons (validated after snapping), each moved to a random place.
fn polygons(n: usize, target: &Target) -> Vec<Polygon> {
    let mut runner = TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &[5; 32]));
    let strategy = simple_polygon(96, 24);
    let mut rng = Rng(11);
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let p = strategy.new_tree(&mut runner).unwrap().current();
        let p = p.translated(rng.below(i64::from(SIDE) - 96), rng.below(i64::from(SIDE) - 96));
        if validate(&p.to_fixed(&target.convention).unwrap()).is_ok() {
            out.push(p);
        }
    }
    out
}

fn prepare_polygons(model: Model, polygons: &[Polygon], target: &Target) -> PreparedScene {
    let primitives = Primitives {
        polygons: polygons.to_vec(),
        ..Primitives::default()
    };
    prepare(&primitives, target, model).unwrap()
}

fn fill_all(prepared: &PreparedScene, target: &Target, sink: &mut CountBuffer) {
    prepared.render(target, sink);
}

fn covered(prepared: &PreparedScene, target: &Target) -> u64 {
    let mut sink = CountBuffer::new(SIDE, SIDE);
    fill_all(prepared, target, &mut sink);
    sink.total()
}

fn bench(c: &mut Criterion) {
    let target = Target::new(SIDE, SIDE, Preset::D3d11.convention()).unwrap();
    let polys = polygons(1000, &target);
    let mut group = c.benchmark_group("polygons_1k_1024");
    group.sample_size(10);
    let mut sink = CountBuffer::new(SIDE, SIDE);
    for (model, label, subset) in [
        (Model::Scanline, "scanline (active edge table)", &polys[..]),
        (Model::Fixed, "fixed (pre-triangulated)", &polys[..]),
        (Model::ExactSnapped, "exact-snapped (first 5)", &polys[..5]),
    ] {
        let prepared = prepare_polygons(model, subset, &target);
        group.throughput(Throughput::Elements(covered(&prepared, &target)));
        group.bench_function(BenchmarkId::from_parameter(label), |b| {
            b.iter(|| fill_all(&prepared, &target, &mut sink));
        });
    }
    // Triangulation included: the whole route of the fixed model per frame.
    let prepared = prepare_polygons(Model::Fixed, &polys, &target);
    group.throughput(Throughput::Elements(covered(&prepared, &target)));
    group.bench_function(BenchmarkId::from_parameter("triangulate + fixed"), |b| {
        b.iter(|| {
            let prepared = prepare_polygons(Model::Fixed, &polys, &target);
            fill_all(&prepared, &target, &mut sink);
        });
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
