//! Judging grey (anti-aliased) images, side by side in one run: `compare_grey` of a
//! glyph-like outline (`adapters/scenes/glyph.json`, 32x32) against a correct 4x4
//! supersampler's levels (its differing pixels are supersampling), and against a renderer
//! with a gross bug, the same supersampler drawing the glyphs 3/8 px to the right (most
//! of its edge pixels are gross: no class explains them). A gross pixel is ruled out of
//! the sample classes by a bound before any sample is drawn, so the two should cost about
//! the same. Then `fit_grey` of the correct image (every method of the area family drawn
//! on the whole canvas), timed once: it takes seconds, criterion's ten runs would take
//! minutes. Last, a grey hunt (`hunt_grey`, 24 scenes of the area families on 8 px
//! canvases, each finding shrunk), timed once against each of the two renderers: the
//! correct 4x4 supersampler, and the same 3/8 px to the right.
//!
//! `cargo bench --features bench --bench grey`

use criterion::{criterion_group, criterion_main, Criterion};
use num_rational::BigRational;
use rasterproof::area::{supersample, Quantization, Semantics};
use rasterproof::geom::Point;
use rasterproof::model::Model;
use rasterproof::oracle::compare::fit::grey::fit_grey;
use rasterproof::oracle::compare::grey::{compare_grey, GreyClass, GreyOptions};
use rasterproof::oracle::GreyImage;

fn bench(c: &mut Criterion) {
    let text = include_str!("../adapters/scenes/glyph.json");
    let scene = rasterproof::scene::parse_scene(text, "glyph.json").expect("the committed glyph scene");
    let target = scene.target().expect("its canvas");
    let glyphs = rasterproof::model::area_shapes(&scene.primitives(), &target, Model::Exact).expect("glyph shapes");
    let (w, h) = (target.width, target.height);
    let image = |shapes: &[rasterproof::area::AreaShape]| GreyImage {
        width: w,
        height: h,
        bits: 8,
        levels: supersample::rasterize(shapes, w, h, 4).levels(Quantization::Round8),
    };
    let correct = image(&glyphs);
    let shift = BigRational::new(3.into(), 8.into());
    let moved: Vec<_> = glyphs
        .iter()
        .map(|g| {
            let mut g = g.clone();
            for p in g.outline.iter_mut().chain(g.holes.iter_mut().flatten()) {
                *p = Point::new(&p.x + &shift, p.y.clone());
            }
            g
        })
        .collect();
    let gross = image(&moved);
    let options = GreyOptions {
        model: Model::Exact,
        semantics: Semantics::True,
        quantization: Quantization::Round8,
        method: None,
    };
    for (name, theirs) in [("correct", &correct), ("gross", &gross)] {
        let start = std::time::Instant::now();
        let report = compare_grey(&glyphs, &target, theirs, &options).expect("a comparison");
        let classes = report.classes();
        println!(
            "{name}: {} pixels differ, {} of them gross; one compare_grey: {:.2} s",
            report.pixels.len(),
            classes.get(&GreyClass::Gross).copied().unwrap_or(0),
            start.elapsed().as_secs_f64()
        );
    }
    let mut g = c.benchmark_group("grey-judge");
    g.sample_size(10);
    g.bench_function("compare_grey, a correct 4x4 supersampler", |b| {
        b.iter(|| compare_grey(&glyphs, &target, &correct, &options).expect("a comparison"));
    });
    g.bench_function("compare_grey, the same 3/8 px off (gross)", |b| {
        b.iter(|| compare_grey(&glyphs, &target, &gross, &options).expect("a comparison"));
    });
    g.finish();
    // The fit takes seconds to minutes: one timed run, not criterion's ten.
    let start = std::time::Instant::now();
    let fit = fit_grey(&glyphs, &target, &correct, Model::Exact).expect("a fit");
    println!(
        "fit_grey, a correct 4x4 supersampler: {:.1} s (one run); first: {}",
        start.elapsed().as_secs_f64(),
        fit.methods.first().map_or("none".to_string(), |(m, n)| format!(
            "{} ({n} pixels differ)",
            m.describe()
        ))
    );
}

/// A 4x4 supersampler as a renderer closure (round to 8 bits, top-left ties), its
/// shapes first moved right by `shift` px (0: a correct one).
fn supersampler(
    shift: BigRational,
) -> impl Fn(
    &rasterproof::scene::Scene,
) -> Result<rasterproof::oracle::Theirs, rasterproof::oracle::renderer::program::RenderFailure>
       + Sync {
    move |scene| {
        let target = scene.target().expect("a hunt's scene has a canvas");
        let shapes = rasterproof::model::area_shapes(&scene.primitives(), &target, Model::Exact).unwrap_or_default();
        let moved: Vec<_> = shapes
            .into_iter()
            .map(|mut g| {
                for p in g.outline.iter_mut().chain(g.holes.iter_mut().flatten()) {
                    *p = Point::new(&p.x + &shift, p.y.clone());
                }
                g
            })
            .collect();
        Ok(rasterproof::oracle::Theirs::from_grey(GreyImage {
            width: target.width,
            height: target.height,
            bits: 8,
            levels: supersample::rasterize(&moved, target.width, target.height, 4).levels(Quantization::Round8),
        }))
    }
}

/// One grey hunt against each supersampler, timed once each (seconds to a minute).
fn hunts() {
    use rasterproof::oracle::hunt::{hunt_grey, GreyHuntConfig, HuntConfig, AREA_FAMILIES};
    let config = GreyHuntConfig {
        hunt: HuntConfig {
            cases: 24,
            canvas: 8,
            families: AREA_FAMILIES.to_vec(),
            shrink_runs: 40,
            ..HuntConfig::default()
        },
        semantics: Semantics::True,
        quantization: Quantization::Round8,
        grid: None,
        method: None,
    };
    let never = std::sync::atomic::AtomicBool::new(false);
    let mut seconds = Vec::new();
    for (name, shift) in [("correct", 0), ("3/8 px off (gross)", 3)] {
        let renderer = supersampler(BigRational::new(shift.into(), 8.into()));
        let start = std::time::Instant::now();
        let report = hunt_grey(&renderer, &config, 1, &|| {}, &never).expect("a hunt");
        let took = start.elapsed().as_secs_f64();
        seconds.push(took);
        println!(
            "hunt_grey, a 4x4 supersampler {name}: {:.1} s (one run, 24 scenes, {} findings shrunk)",
            took,
            report.findings.len()
        );
    }
    println!(
        "hunt_grey: the gross renderer's hunt takes {:.2}x the correct one's",
        seconds[1] / seconds[0]
    );
}

/// The criterion groups, then the hunts.
fn all(c: &mut Criterion) {
    bench(c);
    hunts();
}

criterion_group!(benches, all);
criterion_main!(benches);
