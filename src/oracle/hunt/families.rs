//! The scenes a hunt draws: the scene [`SceneFamily`]s, the scene of one case
//! ([`generate_scene`]), and a scene's coordinates rounded to f32 ([`float32_exact`]).

use num_rational::BigRational;
use proptest::strategy::{BoxedStrategy, Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

use super::HuntConfig;
use crate::geom::{Point, Polygon, Triangle};
use crate::line::{BresenhamTie, Line, LineRule};
use crate::scene::Scene;
use crate::strategy::polygon::any_polygon;
use crate::strategy::{delaunay_mesh, diamond_line, pixel_line, tie_heavy_mesh, triangle, TriangleScale};

/// A family of generated scenes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum SceneFamily {
    /// A tie-heavy mesh: vertices on pixel centres, corners and snapping ties.
    Mesh,
    /// A Delaunay mesh of random points on the 1/256 px grid.
    Delaunay,
    /// Random triangles of every size (pixel, medium, sliver, huge, tie-heavy).
    Triangles,
    /// Slivers: a third vertex a few subpixels off the line through the other two.
    Slivers,
    /// Triangles with vertices far off the canvas (up to the integer envelope).
    Huge,
    /// A Delaunay mesh on a fine 2^-16 px grid.
    Fine,
    /// Bresenham and diamond-exit lines.
    Lines,
    /// Polygons: simple, with holes, tangled, stellated, tie-heavy.
    Polygons,
}

impl SceneFamily {
    /// Every family.
    pub const ALL: [SceneFamily; 8] = [
        SceneFamily::Mesh,
        SceneFamily::Delaunay,
        SceneFamily::Triangles,
        SceneFamily::Slivers,
        SceneFamily::Huge,
        SceneFamily::Fine,
        SceneFamily::Lines,
        SceneFamily::Polygons,
    ];

    /// The families whose scenes are triangles only (every family but `lines`, which
    /// draws lines, and `polygons`, which draws polygons): what a renderer that draws
    /// nothing but triangles is hunted with.
    pub const TRIANGLES_ONLY: [SceneFamily; 6] = [
        SceneFamily::Mesh,
        SceneFamily::Delaunay,
        SceneFamily::Triangles,
        SceneFamily::Slivers,
        SceneFamily::Huge,
        SceneFamily::Fine,
    ];

    /// The name of the shorthand for [`SceneFamily::TRIANGLES_ONLY`] on the command line.
    /// (`triangles` alone is the family of random triangles of every size.)
    pub const TRIANGLES_ONLY_NAME: &'static str = "all-triangles";

    /// Its name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            SceneFamily::Mesh => "mesh",
            SceneFamily::Delaunay => "delaunay",
            SceneFamily::Triangles => "triangles",
            SceneFamily::Slivers => "slivers",
            SceneFamily::Huge => "huge",
            SceneFamily::Fine => "fine",
            SceneFamily::Lines => "lines",
            SceneFamily::Polygons => "polygons",
        }
    }

    /// Parses a name written by [`SceneFamily::name`].
    pub fn from_name(name: &str) -> Option<SceneFamily> {
        SceneFamily::ALL.into_iter().find(|f| f.name() == name)
    }

    /// The families a command-line name stands for: one family by its name, or every
    /// triangle-only family for [`SceneFamily::TRIANGLES_ONLY_NAME`] (`all-triangles`).
    ///
    /// ```
    /// use rasterproof::oracle::hunt::SceneFamily;
    /// assert_eq!(SceneFamily::expand("lines"), Some(vec![SceneFamily::Lines]));
    /// assert_eq!(SceneFamily::expand("all-triangles").unwrap().len(), 6);
    /// assert_eq!(SceneFamily::expand("cubes"), None);
    /// ```
    pub fn expand(name: &str) -> Option<Vec<SceneFamily>> {
        if name == SceneFamily::TRIANGLES_ONLY_NAME {
            return Some(SceneFamily::TRIANGLES_ONLY.to_vec());
        }
        SceneFamily::from_name(name).map(|f| vec![f])
    }

    /// Triangles, lines and polygons of this family on a `canvas` x `canvas` target.
    fn strategy(self, canvas: u32) -> BoxedStrategy<(Vec<Triangle>, Vec<Line>, Vec<Polygon>)> {
        let side = i64::from(canvas);
        let tris = |s: BoxedStrategy<Triangle>| {
            proptest::collection::vec(s, 1..4)
                .prop_map(|t| (t, Vec::new(), Vec::new()))
                .boxed()
        };
        let mesh =
            |s: BoxedStrategy<crate::strategy::Mesh>| s.prop_map(|m| (m.triangles, Vec::new(), Vec::new())).boxed();
        match self {
            SceneFamily::Mesh => mesh(tie_heavy_mesh(canvas, 12)),
            SceneFamily::Delaunay => mesh(delaunay_mesh([0, 0], side, 8, 12)),
            SceneFamily::Triangles => tris(crate::strategy::any_triangle(canvas)),
            SceneFamily::Slivers => tris(triangle(TriangleScale::Sliver, canvas)),
            SceneFamily::Huge => tris(triangle(TriangleScale::Huge, canvas)),
            SceneFamily::Fine => mesh(delaunay_mesh([0, 0], side, 16, 12)),
            SceneFamily::Lines => (
                proptest::collection::vec(pixel_line(side, 2), 0..3),
                proptest::collection::vec(diamond_line(canvas), 0..3),
            )
                .prop_map(|(b, d)| {
                    let bresenham = b.into_iter().map(|(a, b)| Line {
                        from: Point::from_ints(a[0], a[1]),
                        to: Point::from_ints(b[0], b[1]),
                        rule: LineRule::Bresenham(BresenhamTie::Stay),
                    });
                    (Vec::new(), bresenham.chain(d).collect(), Vec::new())
                })
                .boxed(),
            SceneFamily::Polygons => proptest::collection::vec(any_polygon(canvas, 8), 1..3)
                .prop_map(|p| (Vec::new(), Vec::new(), p))
                .boxed(),
        }
    }
}

/// The scene of case `k`: the same config and `k` always give the same scene.
///
/// # Errors
/// A strategy rejected every value it drew (the message names the family).
pub fn generate_scene(config: &HuntConfig, k: u64) -> Result<Scene, String> {
    let family = config.families[usize::try_from(k % config.families.len() as u64).expect("small")];
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&config.seed.to_le_bytes());
    bytes[8..16].copy_from_slice(&k.to_le_bytes());
    bytes[16] = 0x48; // 'H': not the suite's streams
    let mut runner = TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &bytes));
    let (triangles, lines, polygons) = family
        .strategy(config.canvas)
        .new_tree(&mut runner)
        .map_err(|e| format!("hunt: family {}: {e}", family.name()))?
        .current();
    let mut scene = Scene::new(config.canvas, config.canvas, triangles);
    scene.lines = lines;
    scene.polygons = polygons;
    scene.preset = config.preset;
    scene.overrides = config.overrides;
    scene.samples = config.samples.clone();
    if config.float32_exact {
        float32_exact(&mut scene);
    }
    Ok(scene)
}

/// Rounds every coordinate to the nearest f32, exactly (so a program reading f32 sees the
/// scene the oracle sees).
pub fn float32_exact(scene: &mut Scene) {
    scene.map_coordinates(|_, v| {
        crate::num::exact::nearest_f32(v)
            .and_then(BigRational::from_float)
            .unwrap_or_else(|| v.clone())
    });
}
