//! The edge-walking rasterizer (`scanline`, issue 5's first part) is proven equal to the
//! oracle on the snapped scene: every triangle family, every preset, other subpixel grids
//! and corner samples, far from the origin, at the envelope edge, and on meshes.

use crate::common;

use common::config;
use proptest::prelude::*;
use rasterproof::check::{check_agreement, check_watertight};
use rasterproof::convention::{PixelCentre, Preset, Target, MAX_CANVAS};
use rasterproof::geom::{Point, Triangle};
use rasterproof::model::{render_triangles, Model};
use rasterproof::strategy::{any_triangle, delaunay_mesh, tie_heavy_mesh, triangle, TriangleScale};

fn agree(tris: &[Triangle], target: &Target) -> Result<(), TestCaseError> {
    let exact = render_triangles(tris, target, Model::ExactSnappedPlain).unwrap();
    let scan = render_triangles(tris, target, Model::Scanline).map_err(|e| TestCaseError::fail(e.to_string()))?;
    check_agreement("exact-snapped-plain", &exact, "scanline", &scan, tris, target)
        .map_err(|v| TestCaseError::fail(v.to_string()))
}

proptest! {
    #![proptest_config(config("proptest-regressions/scanline.txt"))]

    #[test]
    fn scanline_equals_exact_snapped(t in any_triangle(32), p in prop::sample::select(Preset::ALL.to_vec())) {
        agree(&[t], &Target::new(32, 32, p.convention()).unwrap())?;
    }

    /// Other grids (1..=16 subpixel bits) and D3D9-style corner samples.
    #[test]
    fn scanline_equals_exact_snapped_on_any_grid(t in any_triangle(24), bits in 1u32..=16, corner in any::<bool>()) {
        let mut conv = Preset::D3d11.convention();
        conv.subpixel_bits = bits;
        if corner {
            conv.pixel_centre = PixelCentre::Corner;
        }
        // The Huge family is drawn for 8 bits; on a finer grid it may leave the envelope,
        // where the integer models rightly refuse it (tested in tests/properties.rs).
        prop_assume!(t.snapped(&conv).to_fixed().is_ok());
        agree(&[t], &Target::new(24, 24, conv).unwrap())?;
    }

    #[test]
    fn scanline_equals_exact_snapped_far_from_origin(t in triangle(TriangleScale::FarFromOrigin, MAX_CANVAS)) {
        agree(&[t], &Target::new(MAX_CANVAS, MAX_CANVAS, Preset::D3d11.convention()).unwrap())?;
    }

    #[test]
    fn scanline_meshes_are_watertight(mesh in delaunay_mesh([-4, -4], 40, 8, 24), tie_mesh in tie_heavy_mesh(32, 24)) {
        for m in [&mesh, &tie_mesh] {
            for p in [Preset::D3d11, Preset::Gl] {
                let target = Target::new(32, 32, p.convention()).unwrap();
                let cov = render_triangles(&m.triangles, &target, Model::Scanline).unwrap();
                check_watertight(&m.triangles, &m.outline, &cov, &target).map_err(|v| TestCaseError::fail(v.to_string()))?;
            }
        }
    }
}

/// At the envelope edge (±2^29 subpixels) the i128 walkers stay exact.
#[test]
fn scanline_at_the_envelope_edge() {
    let target = Target::new(32, 32, Preset::D3d11.convention()).unwrap();
    let e = 1i64 << 21;
    for t in [
        Triangle::new(
            Point::from_ints(-e, -e),
            Point::from_ints(e, -e),
            Point::from_ints(5, e),
        ),
        Triangle::new(
            Point::from_ints(-e, -e),
            Point::from_ints(e, e),
            Point::from_ints(-e, e),
        ),
        Triangle::new(Point::from_ints(e, e), Point::from_ints(-e, 3), Point::from_ints(7, -e)),
    ] {
        agree(std::slice::from_ref(&t), &target).unwrap();
    }
}
