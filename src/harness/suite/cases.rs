//! The suite's cases: seeded draws from the proptest strategies of [`crate::strategy`].

use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

use crate::clip::Window;
use crate::convention::{Preset, MAX_CANVAS};
use crate::geom::{Point, Polygon, Triangle};
use crate::line::Line;
use crate::strategy::clip::{any_window, rect_window};
use crate::strategy::polygon::{any_polygon, simple_polygon};
use crate::strategy::{
    any_triangle, delaunay_mesh, diamond_line, long_pixel_line, pixel_line, tie_heavy_coordinate, tie_heavy_mesh, Mesh,
};

/// Canvas side of the ordinary cases, pixels (the far-from-origin meshes use
/// [`MAX_CANVAS`]).
pub const CANVAS: u32 = 32;

/// One generated case: the inputs every checker of the suite reads.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Case {
    /// A mesh of the family [`Case::mesh_family`], on a [`Case::mesh_canvas`] canvas.
    pub mesh: Mesh,
    /// A far-from-origin mesh on a fine 2^-16 px grid, for the float models only (snapping
    /// it to 8 bits could fold thin triangles, so it is no input for the snapped models).
    pub fine_mesh: Mesh,
    /// A Bresenham line on and around the canvas, integer endpoints.
    pub line: ([i64; 2], [i64; 2]),
    /// A diamond-exit line with tie-heavy endpoints.
    pub diamond: Line,
    /// A line up to 1000 px long, around 0, 2^16, 2^20 or 2^23, for the DDA.
    pub long_line: ([i64; 2], [i64; 2]),
    /// Canvas side of [`Case::mesh`]: [`CANVAS`], or [`MAX_CANVAS`] far from the origin.
    pub mesh_canvas: u32,
    /// `"random mesh"`, `"tie-heavy mesh"` or `"far-from-origin mesh"` (case `k` has
    /// family `k % 3`).
    pub mesh_family: &'static str,
    /// A random triangle of any family.
    pub triangle: Triangle,
    /// A whole-pixel translation for the invariance check, each in `-5..=5`.
    pub shift: (i64, i64),
    /// The convention, `d3d11` or `gl`.
    pub preset: Preset,
    /// Any polygon: simple, with a hole, tangled, stellated, tie-heavy.
    pub polygon: Polygon,
    /// A simple polygon (star-shaped, maybe with a hole), for the triangulation.
    pub simple: Polygon,
    /// A clip window, a rectangle or convex.
    pub window: Window,
    /// A rectangular window for the segment clip.
    pub rect: Window,
    /// A segment with tie-heavy endpoints.
    pub segment: (Point, Point),
}

/// A test runner whose RNG is seeded by the run's `seed` and the case number.
fn runner_for(seed: u64, case: u64) -> TestRunner {
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&seed.to_le_bytes());
    bytes[8..16].copy_from_slice(&case.to_le_bytes());
    TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &bytes))
}

/// One value of `s`, not shrunk.
fn draw<T: std::fmt::Debug>(runner: &mut TestRunner, s: impl Strategy<Value = T>) -> Result<T, String> {
    Ok(s.new_tree(runner)
        .map_err(|e| format!("case generation failed: {e}"))?
        .current())
}

/// Case `k` of the run seeded `seed`: the same `seed` and `k` always give the same case.
/// Fails (with the message `rasterproof check` prints) only when a strategy rejects every
/// value it draws.
pub fn generate(seed: u64, k: u64) -> Result<Case, String> {
    let mut runner = runner_for(seed, k);
    let far = i64::from(MAX_CANVAS) - 48;
    let (mesh, mesh_canvas, mesh_family) = match k % 3 {
        0 => (
            draw(&mut runner, delaunay_mesh([0, 0], i64::from(CANVAS), 8, 16))?,
            CANVAS,
            "random mesh",
        ),
        1 => (draw(&mut runner, tie_heavy_mesh(CANVAS, 16))?, CANVAS, "tie-heavy mesh"),
        _ => (
            draw(&mut runner, delaunay_mesh([far, far], 48, 8, 16))?,
            MAX_CANVAS,
            "far-from-origin mesh",
        ),
    };
    let fine_mesh = draw(&mut runner, delaunay_mesh([far, far], 48, 16, 24))?;
    let triangle = draw(&mut runner, any_triangle(CANVAS))?;
    let line = draw(&mut runner, pixel_line(i64::from(CANVAS), 8))?;
    let diamond = draw(&mut runner, diamond_line(CANVAS))?;
    let origin = draw(
        &mut runner,
        proptest::sample::select(vec![0i64, 1 << 16, 1 << 20, 1 << 23]),
    )?;
    let long_line = draw(&mut runner, long_pixel_line(origin, 500))?;
    let shift = draw(&mut runner, (-5i64..=5, -5i64..=5))?;
    let preset = draw(&mut runner, proptest::sample::select(vec![Preset::D3d11, Preset::Gl]))?;
    let polygon = draw(&mut runner, any_polygon(CANVAS, 12))?;
    let simple = draw(&mut runner, simple_polygon(CANVAS, 12))?;
    let window = draw(&mut runner, any_window(CANVAS))?;
    let rect = draw(&mut runner, rect_window(CANVAS))?;
    let ends = draw(&mut runner, proptest::array::uniform4(tie_heavy_coordinate(CANVAS)))?;
    let [ax, ay, bx, by] = ends;
    Ok(Case {
        mesh,
        fine_mesh,
        line,
        diamond,
        long_line,
        mesh_canvas,
        mesh_family,
        triangle,
        shift,
        preset,
        polygon,
        simple,
        window,
        rect,
        segment: (Point::new(ax, ay), Point::new(bx, by)),
    })
}
