//! Property tests: every invariant for `exact-snapped` and `fixed`, 256 cases each by
//! default (PROPTEST_CASES raises it). Regressions land in proptest-regressions/.

use crate::common;

use common::{config, coverage_map, Conv, Rule};
use num_rational::BigRational;
use proptest::prelude::*;
use rasterproof::check::{
    check_agreement, check_barycentric_exact, check_barycentric_fixed, check_no_double_cover,
    check_rotation_and_winding, check_translation, check_watertight,
};
use rasterproof::convention::{Preset, Target, MAX_CANVAS};
use rasterproof::geom::{Point, Triangle};
use rasterproof::interp::{gouraud_exact, Plane};
use rasterproof::model::{render_triangles, Model};
use rasterproof::strategy::{any_triangle, delaunay_mesh, tie_heavy_mesh, tie_heavy_triangle, triangle, TriangleScale};

const CANVAS: u32 = 32;

fn preset() -> impl Strategy<Value = Preset> {
    prop::sample::select(Preset::ALL.to_vec())
}

fn target(side: u32, preset: Preset) -> Target {
    Target::new(side, side, preset.convention()).unwrap()
}

fn agree(tris: &[Triangle], target: &Target) -> Result<(), TestCaseError> {
    let exact = render_triangles(tris, target, Model::ExactSnappedPlain).unwrap();
    let fixed = render_triangles(tris, target, Model::Fixed).map_err(|e| TestCaseError::fail(e.to_string()))?;
    check_agreement("exact-snapped-plain", &exact, "fixed", &fixed, tris, target)
        .map_err(|v| TestCaseError::fail(v.to_string()))
}

fn ok(r: Result<(), rasterproof::check::Violation>) -> Result<(), TestCaseError> {
    r.map_err(|v| TestCaseError::fail(v.to_string()))
}

proptest! {
    #![proptest_config(config("proptest-regressions/properties.txt"))]

    /// Model agreement: fixed == exact-snapped on every triangle family and every preset.
    #[test]
    fn fixed_equals_exact_snapped(t in any_triangle(CANVAS), p in preset()) {
        agree(&[t], &target(CANVAS, p))?;
    }

    /// Model agreement under every snapping rounding (the directed ones too: floor, ceiling,
    /// towards zero) and every subpixel precision: fixed and scanline == exact-snapped.
    #[test]
    fn integer_models_equal_exact_snapped_under_every_rounding(
        ts in prop::collection::vec(any_triangle(CANVAS), 1..4),
        rounding in prop::sample::select(rasterproof::convention::Rounding::ALL.to_vec()),
        bits in 1u32..=16,
    ) {
        let mut conv = Preset::D3d11.convention();
        conv.rounding = rounding;
        conv.subpixel_bits = bits;
        let target = Target::new(CANVAS, CANVAS, conv).unwrap();
        let exact = render_triangles(&ts, &target, Model::ExactSnappedPlain).unwrap();
        for model in [Model::Fixed, Model::Scanline, Model::ExactSnapped] {
            if let Ok(c) = render_triangles(&ts, &target, model) {
                ok(check_agreement("exact-snapped-plain", &exact, model.name(), &c, &ts, &target))?;
            }
        }
    }

    /// Model agreement far from the origin, on the largest canvas.
    #[test]
    fn fixed_equals_exact_snapped_far_from_origin(t in triangle(TriangleScale::FarFromOrigin, MAX_CANVAS), p in preset()) {
        agree(&[t], &target(MAX_CANVAS, p))?;
    }

    /// Both models equal an independent oracle (hand-written snapping, i128 edge values, the
    /// ε-move tie rule as a lexicographic comparison) on tie-heavy triangles.
    #[test]
    fn models_equal_the_independent_oracle(ts in prop::collection::vec(tie_heavy_triangle(12), 1..4), p in preset()) {
        let target = target(12, p);
        let c = target.convention;
        let conv = Conv {
            rule: if c.tie_rule == rasterproof::convention::TieRule::TopLeft { Rule::TopLeft } else { Rule::BottomLeft },
            bits: c.subpixel_bits,
            half_away: c.rounding == rasterproof::convention::Rounding::HalfAwayFromZero,
        };
        let raw: Vec<[[BigRational; 2]; 3]> = ts.iter().map(|t| t.v.clone().map(|p| [p.x, p.y])).collect();
        let expected = common::render(&raw, 12, 12, conv);
        for model in [Model::ExactSnapped, Model::Fixed] {
            let got = coverage_map(&render_triangles(&ts, &target, model).unwrap());
            prop_assert_eq!(&got, &expected, "{}", model);
        }
    }

    /// Watertightness on random Delaunay meshes: every sample inside the hull owned exactly
    /// once, none outside, no double cover.
    #[test]
    fn meshes_are_watertight(mesh in delaunay_mesh([-4, -4], 40, 8, 24), p in preset()) {
        let target = target(CANVAS, p);
        for model in [Model::ExactSnapped, Model::Fixed] {
            let cov = render_triangles(&mesh.triangles, &target, model).unwrap();
            ok(check_no_double_cover(&cov))?;
            ok(check_watertight(&mesh.triangles, &mesh.outline, &cov, &target))?;
        }
    }

    /// Watertightness on tie-heavy meshes (vertices on the half-pixel grid: samples on shared
    /// edges and on vertices everywhere).
    #[test]
    fn tie_heavy_meshes_are_watertight(mesh in tie_heavy_mesh(CANVAS, 24), p in preset()) {
        let target = target(CANVAS, p);
        for model in [Model::ExactSnapped, Model::Fixed] {
            let cov = render_triangles(&mesh.triangles, &target, model).unwrap();
            ok(check_watertight(&mesh.triangles, &mesh.outline, &cov, &target))?;
        }
        agree(&mesh.triangles, &target)?;
    }

    /// The barycentric invariant: exact barycentrics sum to 1 anywhere (inside or extrapolated); integer
    /// edge values sum to twice the area at every sample of the canvas corners and centre.
    #[test]
    fn barycentrics_sum_exactly(t in any_triangle(CANVAS), x in 0u32..CANVAS, y in 0u32..CANVAS, p in preset()) {
        let target = target(CANVAS, p);
        let sample = Point::from_fractions(2 * i64::from(x) + 1, 2, 2 * i64::from(y) + 1, 2);
        ok(check_barycentric_exact(&t, &sample))?;
        if let Ok(f) = t.snapped(&target.convention).to_fixed() {
            for (sx, sy) in [(x, y), (0, 0), (CANVAS - 1, CANVAS - 1)] {
                ok(check_barycentric_fixed(&f, sx, sy, &target))?;
            }
        }
    }

    /// Invariance: rotation and winding reversal change nothing.
    #[test]
    fn rotation_and_winding_change_nothing(t in any_triangle(CANVAS), p in preset()) {
        let target = target(CANVAS, p);
        for model in [Model::ExactSnapped, Model::Fixed] {
            ok(check_rotation_and_winding(&t, &target, model))?;
        }
    }

    /// Invariance: translation by whole pixels moves the coverage (nearest-even presets;
    /// see `check_translation` for why half-away-from-zero is excluded).
    #[test]
    fn translation_moves_coverage(t in any_triangle(CANVAS), dx in -6i64..=6, dy in -6i64..=6,
                                  p in prop::sample::select(vec![Preset::D3d11, Preset::Gl, Preset::Vulkan])) {
        let target = target(CANVAS, p);
        for model in [Model::Exact, Model::ExactSnapped, Model::Fixed] {
            ok(check_translation(&t, &target, dx, dy, model))?;
        }
    }

    /// Seed 004's plane equation equals the barycentric Gouraud colour, exactly, anywhere.
    #[test]
    fn plane_equation_equals_barycentric_interpolation(
        t in any_triangle(CANVAS),
        colours in prop::array::uniform3(prop::array::uniform3(any::<u8>())),
        px in -64i64..64, py in -64i64..64,
    ) {
        let p = Point::from_fractions(px, 2, py, 2);
        let Some(bary) = gouraud_exact(&t, &colours, &p) else { return Ok(()) };
        for ch in 0..3 {
            let values = colours.map(|c| BigRational::from_integer(c[ch].into()));
            let plane = Plane::setup(&t, &values).expect("non-degenerate: gouraud_exact succeeded");
            prop_assert_eq!(plane.eval(&p), bary[ch].clone());
        }
    }
}

/// The fixed model right at its envelope: coordinates of exactly ±2^29 subpixels agree
/// with the oracle; one subpixel beyond is an error naming the vertex, not a wrong answer.
#[test]
fn fixed_at_the_envelope_edge() {
    let target = target(CANVAS, Preset::D3d11);
    let edge = 1i64 << 21; // px; 2^29 subpixels at 8 bits
    let cases = [
        Triangle::new(
            Point::from_ints(-edge, -edge),
            Point::from_ints(edge, -edge),
            Point::from_ints(5, edge),
        ),
        Triangle::new(
            Point::from_ints(edge, edge),
            Point::from_ints(-edge, 3),
            Point::from_ints(7, -edge),
        ),
        // the diagonal y = x from corner to corner of the envelope: every sample (k+1/2, k+1/2)
        // on the canvas is a tie, decided with edge values near 2^61
        Triangle::new(
            Point::from_ints(-edge, -edge),
            Point::from_ints(edge, edge),
            Point::from_ints(-edge, edge),
        ),
    ];
    for t in &cases {
        agree(std::slice::from_ref(t), &target).unwrap();
        let cov = render_triangles(std::slice::from_ref(t), &target, Model::Fixed).unwrap();
        assert!(cov.covered_pixels() > 0, "the envelope triangles cross the canvas");
    }
    let beyond = Triangle::new(
        Point::from_ints(0, 0),
        Point::from_ints(3, 0),
        Point::from_fractions(edge * 256 + 1, 256, 5, 1),
    );
    let err = render_triangles(&[beyond], &target, Model::Fixed)
        .unwrap_err()
        .to_string();
    assert!(err.starts_with("triangles[0].v[2].x: "), "{err}");
    assert!(err.contains("536870913 subpixels"), "{err}");
}
