//! The checkers have teeth: on named input families they FIND the float models' gaps,
//! double cover and wrong pixels. Each test draws a fixed, seeded sample of cases, counts
//! the violations (printed for the notes) and asserts at least one was found.

use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use rasterproof::check::{check_agreement, check_watertight};
use rasterproof::convention::{Preset, Target, MAX_CANVAS};
use rasterproof::model::{render_triangles, Model};
use rasterproof::strategy::{delaunay_mesh, tie_heavy_mesh, Mesh};

fn meshes(strategy: impl Strategy<Value = Mesh>, n: usize, seed: u8) -> Vec<Mesh> {
    let mut runner = TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]));
    (0..n)
        .map(|_| strategy.new_tree(&mut runner).unwrap().current())
        .collect()
}

/// Counts meshes where `model` breaks watertightness or disagrees with `reference`.
fn count_violations(meshes: &[Mesh], side: u32, model: Model, reference: Model) -> (usize, usize) {
    let target = Target::new(side, side, Preset::D3d11.convention()).unwrap();
    let (mut watertight, mut agreement) = (0, 0);
    for m in meshes {
        let cov = render_triangles(&m.triangles, &target, model).unwrap();
        if check_watertight(&m.triangles, &m.outline, &cov, &target).is_err() {
            watertight += 1;
        }
        let r = render_triangles(&m.triangles, &target, reference).unwrap();
        if check_agreement(reference.name(), &r, model.name(), &cov, &m.triangles, &target).is_err() {
            agreement += 1;
        }
    }
    println!(
        "{model} on {} meshes ({side}x{side}): {watertight} not watertight, {agreement} disagree with {reference}",
        meshes.len()
    );
    (watertight, agreement)
}

/// Seed 003's naive `w >= 0` test gives a sample on a shared edge to both triangles: on
/// tie-heavy meshes the checker must report double cover.
#[test]
fn naive_float32_double_covers_tie_heavy_meshes() {
    let ms = meshes(tie_heavy_mesh(32, 16), 32, 1);
    let (watertight, agreement) = count_violations(&ms, 32, Model::Float32Naive, Model::ExactPlain);
    assert!(
        watertight > 0,
        "no watertightness violation found in {} meshes",
        ms.len()
    );
    assert!(agreement > 0);
}

/// Meshes near the far corner of the 16384 canvas with vertices on a fine 2^-16 px grid.
fn far_fine_meshes() -> Vec<Mesh> {
    let far = i64::from(MAX_CANVAS) - 48;
    meshes(delaunay_mesh([far, far], 48, 16, 32), 48, 2)
}

/// The float32 model with the tie rule applied to float values, on far-from-origin meshes
/// with fine vertices: f32 keeps only 10 fraction bits near 16384, so converting a vertex
/// moves it by up to 2^-11 px and samples that close to an edge change side. The checker
/// must find pixels where float32 differs from the exact model.
#[test]
fn float32_breaks_far_from_origin_meshes() {
    let (watertight, agreement) = count_violations(&far_fine_meshes(), MAX_CANVAS, Model::Float32, Model::ExactPlain);
    assert!(watertight + agreement > 0, "no violation found in far meshes");
}

/// The same family in f64, which holds it exactly: 2^-16 px vertices near 16384 need 30
/// bits (f64 has 53), edge differences need 22 bits and their products 44: no rounding
/// anywhere, so float64 must agree with the exact model on every mesh.
#[test]
fn float64_is_exact_on_the_same_family() {
    let (w, a) = count_violations(&far_fine_meshes(), MAX_CANVAS, Model::Float64, Model::ExactPlain);
    assert_eq!((w, a), (0, 0));
}
