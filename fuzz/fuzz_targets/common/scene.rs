//! A whole scene as a fuzz input: the bytes are a scene file when they parse as one
//! (so real scenes, tie-heavy ones included, are seeds and the fuzzer mutates them), and
//! otherwise drive a structured generator of every primitive kind with coordinates of
//! every kind (tie points, dyadic grids, thirds and sevenths, 3-decimal values, far off the
//! canvas, 2^-80 from a sample). Either way the scene is bounded (canvas, primitive and
//! vertex counts) so one run stays fast, and it is kept only if it survives
//! `to_json` and a parse unchanged: its `Debug` is that scene file, which pastes into a
//! test as `parse_scene(r#"..."#, "case.json")`.

use std::fmt;

use arbitrary::{Arbitrary, Result, Unstructured};
use num_bigint::BigInt;
use num_rational::BigRational;
use rasterproof::clip::homogeneous::{ClipVertex, DepthRange, NdcY, Viewport};
use rasterproof::clip::Window;
use rasterproof::convention::{PixelCentre, Preset, Rounding, TieRule};
use rasterproof::geom::{FillRule, Point, Polygon, Triangle};
use rasterproof::line::{BresenhamTie, Line, LineRule};
use rasterproof::scene::{parse_scene, parse_scene_with, Overrides, ParseOptions, Scene, SceneTriangle};

/// The largest canvas side a fuzzed scene keeps (a parsed scene's canvas is cut to it).
/// These bounds set the targets' speed: the plain oracles and `compare`'s reason search
/// cost in proportion to samples times primitives, in arbitrary precision; each
/// primitive is rasterized on its own, so a few of each kind find what many would.
pub const MAX_SIDE: u32 = 8;
/// The most triangles kept.
pub const MAX_TRIANGLES: usize = 2;
/// The most lines kept.
pub const MAX_LINES: usize = 1;
/// The most polygons kept.
pub const MAX_POLYGONS: usize = 1;
/// The most vertices per polygon contour kept (contours with fewer than 3 are dropped).
pub const MAX_CONTOUR: usize = 6;
/// The most clip-space triangles kept.
pub const MAX_CLIP_SPACE: usize = 1;

/// A scene to fuzz with; `Debug` prints it as a scene file.
#[derive(Clone)]
pub struct FuzzScene {
    /// The scene, bounded and round-trip checked.
    pub scene: Scene,
}

impl fmt::Debug for FuzzScene {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.scene.to_json())
    }
}

impl<'a> Arbitrary<'a> for FuzzScene {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        bounded(structured(u)?)
    }

    fn arbitrary_take_rest(mut u: Unstructured<'a>) -> Result<Self> {
        let bytes = u.peek_bytes(u.len()).unwrap_or_default();
        if let Ok(scene) = parse_scene_with(bytes, "<fuzz>", &ParseOptions::default()) {
            return bounded(scene);
        }
        bounded(structured(&mut u)?)
    }
}

/// The scene cut to the bounds above, kept when its scene file reads back as itself.
fn bounded(mut s: Scene) -> Result<FuzzScene> {
    s.width = s.width.min(MAX_SIDE);
    s.height = s.height.min(MAX_SIDE);
    s.triangles.truncate(MAX_TRIANGLES);
    s.lines.truncate(MAX_LINES);
    s.polygons.truncate(MAX_POLYGONS);
    s.clip_space_triangles.truncate(MAX_CLIP_SPACE);
    for p in &mut s.polygons {
        p.outline.truncate(MAX_CONTOUR);
        p.holes.truncate(1);
        for h in &mut p.holes {
            h.truncate(MAX_CONTOUR);
        }
    }
    s.polygons.retain(|p| p.outline.len() >= 3);
    for p in &mut s.polygons {
        p.holes.retain(|h| h.len() >= 3);
    }
    match parse_scene(&s.to_json(), "<fuzz>") {
        Ok(again) if again == s => Ok(FuzzScene { scene: s }),
        _ => Err(arbitrary::Error::IncorrectFormat),
    }
}

/// One coordinate, of one of the kinds that stress a rasterizer.
#[derive(Debug, Clone, Copy, Arbitrary)]
enum Coord {
    /// A pixel corner or centre on the canvas (or one pixel beyond): `n / 2`, folded.
    Tie(i8),
    /// `n / 2^(k % 17)`: the subpixel grids and finer, folded onto the canvas and a margin.
    Grid(i32, u8),
    /// `n / (1 + d)`: thirds, sevenths, ... (never on a binary grid), folded.
    Fraction(i16, u8),
    /// A 3-decimal value `n / 1000`, folded.
    Milli(i32),
    /// Far off the canvas: `n * 2^(e % 140)`, beyond i64 and i128 (what forces the
    /// planner's wide and arbitrary-precision widths).
    Far(i16, u8),
    /// Just off a sample: `t / 2 ± 2^-(20 + e % 80)`.
    Near(i8, u8, bool),
}

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

fn fold(n: i64, den: i64, side: u32) -> BigRational {
    let margin = 4 * den;
    let span = (i64::from(side) * den) + 2 * margin;
    q(n.rem_euclid(span) - margin, den)
}

impl Coord {
    fn value(self, side: u32) -> BigRational {
        match self {
            Coord::Tie(n) => fold(i64::from(n), 2, side),
            Coord::Grid(n, k) => fold(i64::from(n), 1 << (k % 17), side),
            Coord::Fraction(n, d) => fold(i64::from(n), 1 + i64::from(d), side),
            Coord::Milli(n) => fold(i64::from(n), 1000, side),
            Coord::Far(n, e) => BigRational::from_integer(BigInt::from(n) << (e % 140)),
            Coord::Near(t, e, up) => {
                let eps = BigRational::new(BigInt::from(1), BigInt::from(1) << (20 + e % 80));
                let base = fold(i64::from(t), 2, side);
                if up {
                    base + eps
                } else {
                    base - eps
                }
            }
        }
    }
}

#[derive(Debug, Clone, Copy, Arbitrary)]
struct Vertex(Coord, Coord);

impl Vertex {
    fn point(self, w: u32, h: u32) -> Point {
        Point::new(self.0.value(w), self.1.value(h))
    }
}

#[derive(Debug, Clone, Copy, Arbitrary)]
enum PresetChoice {
    D3d11,
    Vulkan,
    Gl,
    Cts,
}

#[derive(Debug, Clone, Copy, Arbitrary)]
enum RoundingChoice {
    NearestEven,
    HalfAway,
    Floor,
    Ceiling,
    TowardsZero,
}

#[derive(Debug, Clone, Arbitrary)]
enum LineChoice {
    /// Integer endpoints (pixel addresses) within ±(side + 4).
    Bresenham([i8; 4], bool),
    /// Any endpoints.
    Diamond(Vertex, Vertex),
}

#[derive(Debug, Clone, Arbitrary)]
enum ClipChoice {
    /// A rectangle from two corners (refused when empty).
    Rect(Vertex, Vertex),
    /// A convex window (refused unless strictly convex).
    Convex(Vec<Vertex>),
}

/// A clip-space coordinate: `n / 4`, so w crosses 0 and vertices sit on the planes.
#[derive(Debug, Clone, Copy, Arbitrary)]
struct ClipPos([i8; 4]);

#[derive(Debug, Clone, Arbitrary)]
struct Structured {
    width: u8,
    height: u8,
    preset: PresetChoice,
    bits: Option<u8>,
    rounding: Option<RoundingChoice>,
    tie_rule: Option<bool>,
    corner: Option<bool>,
    triangles: Vec<[Vertex; 3]>,
    lines: Vec<LineChoice>,
    polygons: Vec<(Vec<Vertex>, Option<Vec<Vertex>>, bool)>,
    clip_space: Vec<[ClipPos; 3]>,
    viewport: Option<([i8; 4], bool, bool)>,
    clip: Option<ClipChoice>,
}

fn structured(u: &mut Unstructured<'_>) -> Result<Scene> {
    let s = Structured::arbitrary(u)?;
    let (w, h) = (1 + u32::from(s.width) % MAX_SIDE, 1 + u32::from(s.height) % MAX_SIDE);
    let preset = match s.preset {
        PresetChoice::D3d11 => Preset::D3d11,
        PresetChoice::Vulkan => Preset::Vulkan,
        PresetChoice::Gl => Preset::Gl,
        PresetChoice::Cts => Preset::Cts,
    };
    let overrides = Overrides {
        subpixel_bits: s.bits.map(|b| 1 + u32::from(b % 16)),
        rounding: s.rounding.map(|r| match r {
            RoundingChoice::NearestEven => Rounding::NearestEven,
            RoundingChoice::HalfAway => Rounding::HalfAwayFromZero,
            RoundingChoice::Floor => Rounding::Floor,
            RoundingChoice::Ceiling => Rounding::Ceiling,
            RoundingChoice::TowardsZero => Rounding::TowardsZero,
        }),
        tie_rule: s
            .tie_rule
            .map(|b| if b { TieRule::TopLeft } else { TieRule::BottomLeft }),
        pixel_centre: s
            .corner
            .map(|c| if c { PixelCentre::Corner } else { PixelCentre::Half }),
    };
    let mut scene = Scene::new(w, h, Vec::new());
    scene.preset = preset;
    scene.overrides = overrides;
    scene.triangles = s
        .triangles
        .iter()
        .take(MAX_TRIANGLES)
        .map(|t| SceneTriangle {
            triangle: Triangle::new(t[0].point(w, h), t[1].point(w, h), t[2].point(w, h)).into(),
            colours: None,
            values: None,
        })
        .collect();
    scene.lines = s
        .lines
        .iter()
        .take(MAX_LINES)
        .map(|l| match l {
            LineChoice::Bresenham(e, step) => {
                let c = |v: i8, side: u32| i64::from(v).rem_euclid(i64::from(side) + 8) - 4;
                Line {
                    from: Point::from_ints(c(e[0], w), c(e[1], h)),
                    to: Point::from_ints(c(e[2], w), c(e[3], h)),
                    rule: LineRule::Bresenham(if *step { BresenhamTie::Step } else { BresenhamTie::Stay }),
                }
            }
            LineChoice::Diamond(a, b) => Line {
                from: a.point(w, h),
                to: b.point(w, h),
                rule: LineRule::Diamond,
            },
        })
        .collect();
    let contour = |c: &[Vertex]| -> Vec<Point> { c.iter().take(MAX_CONTOUR).map(|v| v.point(w, h)).collect() };
    scene.polygons = s
        .polygons
        .iter()
        .take(MAX_POLYGONS)
        .map(|(outline, hole, even_odd)| Polygon {
            outline: contour(outline),
            holes: hole.iter().map(|h| contour(h)).collect(),
            fill_rule: if *even_odd {
                FillRule::EvenOdd
            } else {
                FillRule::NonZero
            },
        })
        .collect();
    scene.clip_space_triangles = s
        .clip_space
        .iter()
        .take(MAX_CLIP_SPACE)
        .map(|t| {
            t.map(|ClipPos(p)| ClipVertex {
                pos: p.map(|c| q(i64::from(c), 4)),
                attrs: Vec::new(),
            })
        })
        .collect();
    if let Some((v, down, zero_to_one)) = s.viewport {
        let side = |n: i8| q(1 + i64::from(n.unsigned_abs() % 32), 2);
        scene.viewport = Viewport::new(
            q(i64::from(v[0] % 8), 2),
            q(i64::from(v[1] % 8), 2),
            side(v[2]),
            side(v[3]),
            if down { NdcY::Down } else { NdcY::Up },
            if zero_to_one {
                DepthRange::ZeroToOne
            } else {
                DepthRange::MinusOneToOne
            },
        );
    }
    scene.clip = match &s.clip {
        None => None,
        Some(ClipChoice::Rect(a, b)) => {
            let (a, b) = (a.point(w, h), b.point(w, h));
            let (x0, x1) = if a.x <= b.x { (a.x, b.x) } else { (b.x, a.x) };
            let (y0, y1) = if a.y <= b.y { (a.y, b.y) } else { (b.y, a.y) };
            Window::rect(x0, y0, x1, y1).ok()
        }
        Some(ClipChoice::Convex(points)) => Window::convex(contour(points)).ok(),
    };
    Ok(scene)
}
