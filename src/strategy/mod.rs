//! proptest strategies (feature `proptest`), shared by the property tests, the `check`
//! command, fuzz targets and users: random triangles at several scales, spade Delaunay
//! meshes with their convex outline, and tie-heavy inputs.
//!
//! Coordinates are exact rationals. Grid coordinates are multiples of 2^-8 px (the default
//! subpixel grid) unless a family says otherwise.

pub mod clip;
pub mod polygon;

use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;
use spade::{DelaunayTriangulation, Point2, Triangulation};

use crate::geom::{Point, Triangle};

/// Subpixel bits of the grid the strategies draw on (the presets' default).
pub const GRID_BITS: u32 = 8;
const GRID: i64 = 1 << GRID_BITS;

/// A point `(xs, ys) / 2^GRID_BITS`.
fn grid_point(xs: i64, ys: i64) -> Point {
    Point::from_fractions(xs, GRID, ys, GRID)
}

/// A triangle family.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TriangleScale {
    /// Vertices within 2 px of each other, on the grid.
    Pixel,
    /// Vertices anywhere on the canvas (and a little beyond), on the grid.
    Medium,
    /// Long and thin: two far-apart vertices, the third within a few subpixels of the
    /// line between them.
    Sliver,
    /// Vertices up to 2^21 px away (the fixed model's envelope edge at 8 bits), so only a
    /// corner crosses the canvas.
    Huge,
    /// Small triangles near the far corner of a 16384 x 16384 canvas, where f32 keeps only
    /// 10 bits of fraction.
    FarFromOrigin,
}

impl TriangleScale {
    /// Every family.
    pub const ALL: [TriangleScale; 5] = [
        TriangleScale::Pixel,
        TriangleScale::Medium,
        TriangleScale::Sliver,
        TriangleScale::Huge,
        TriangleScale::FarFromOrigin,
    ];

    /// The canvas side the family is drawn for (`canvas` unless the family needs its own).
    pub fn canvas_for(self, canvas: u32) -> u32 {
        match self {
            TriangleScale::FarFromOrigin => crate::convention::MAX_CANVAS,
            _ => canvas,
        }
    }
}

/// A random triangle of the family `scale` for a `canvas` x `canvas` target
/// (`FarFromOrigin` draws for 16384 whatever `canvas` says: see [`TriangleScale::canvas_for`]).
pub fn triangle(scale: TriangleScale, canvas: u32) -> BoxedStrategy<Triangle> {
    let c = i64::from(canvas) * GRID;
    match scale {
        TriangleScale::Pixel => ((-GRID..c), (-GRID..c), prop::array::uniform4(-2 * GRID..=2 * GRID))
            .prop_map(|(x, y, d)| {
                Triangle::new(
                    grid_point(x, y),
                    grid_point(x + d[0], y + d[1]),
                    grid_point(x + d[2], y + d[3]),
                )
            })
            .boxed(),
        TriangleScale::Medium => prop::array::uniform6(-c / 4..c + c / 4)
            .prop_map(|v| Triangle::new(grid_point(v[0], v[1]), grid_point(v[2], v[3]), grid_point(v[4], v[5])))
            .boxed(),
        TriangleScale::Sliver => (prop::array::uniform4(-c / 4..c + c / 4), 0i64..=GRID, -4i64..=4)
            .prop_map(|(v, t, off)| {
                // third vertex: at parameter t/GRID along a->b, nudged `off` subpixels in y
                let (ax, ay, bx, by) = (v[0], v[1], v[2], v[3]);
                let mx = BigRational::new((ax * (GRID - t) + bx * t).into(), (GRID * GRID).into());
                let my = BigRational::new((ay * (GRID - t) + by * t + off * GRID).into(), (GRID * GRID).into());
                Triangle::new(grid_point(ax, ay), grid_point(bx, by), Point::new(mx, my))
            })
            .boxed(),
        TriangleScale::Huge => {
            let far = 1i64 << (crate::num::FIXED_ENVELOPE_BITS);
            (prop::array::uniform4(-far..=far), 0..c, 0..c)
                .prop_map(|(v, x, y)| Triangle::new(grid_point(v[0], v[1]), grid_point(v[2], v[3]), grid_point(x, y)))
                .boxed()
        }
        TriangleScale::FarFromOrigin => {
            let side = i64::from(crate::convention::MAX_CANVAS) * GRID;
            let lo = side - 200 * GRID;
            (
                prop::array::uniform2(lo..side),
                prop::array::uniform4(-40 * GRID..=40 * GRID),
            )
                .prop_map(|(p, d)| {
                    Triangle::new(
                        grid_point(p[0], p[1]),
                        grid_point(p[0] + d[0], p[1] + d[1]),
                        grid_point(p[0] + d[2], p[1] + d[3]),
                    )
                })
                .boxed()
        }
    }
}

/// Any family (each equally likely), for a `canvas` x `canvas` target; `FarFromOrigin`
/// excluded since it needs its own canvas.
pub fn any_triangle(canvas: u32) -> BoxedStrategy<Triangle> {
    prop_oneof![
        triangle(TriangleScale::Pixel, canvas),
        triangle(TriangleScale::Medium, canvas),
        triangle(TriangleScale::Sliver, canvas),
        triangle(TriangleScale::Huge, canvas),
        tie_heavy_triangle(canvas),
    ]
    .boxed()
}

/// One tie-heavy coordinate: a pixel centre `i + 1/2`, a pixel corner `i`, or `i + k/512`
/// (a snapping tie at 8 bits when k is odd).
pub fn tie_heavy_coordinate(canvas: u32) -> BoxedStrategy<BigRational> {
    let n = i64::from(canvas);
    prop_oneof![
        (-1..=n).prop_map(|i| BigRational::new((2 * i + 1).into(), 2.into())),
        (-1..=n).prop_map(|i| BigRational::from_integer(i.into())),
        ((-1..=n), (0i64..512)).prop_map(|(i, k)| BigRational::new((512 * i + k).into(), 512.into())),
    ]
    .boxed()
}

/// A triangle whose vertices are all tie-heavy coordinates.
pub fn tie_heavy_triangle(canvas: u32) -> BoxedStrategy<Triangle> {
    prop::array::uniform6(tie_heavy_coordinate(canvas))
        .prop_map(|[a, b, c, d, e, f]| Triangle::new(Point::new(a, b), Point::new(c, d), Point::new(e, f)))
        .boxed()
}

/// A triangulated convex region: its triangles and its outline (the convex hull, in order).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Mesh {
    /// The triangles, in spade's face order.
    pub triangles: Vec<Triangle>,
    /// The convex hull, in order.
    pub outline: Vec<Point>,
}

/// Delaunay-triangulates points given in units of 2^-bits px. Returns `None` when the
/// points span no area. The points are integer-valued f64 (exact, far inside spade's
/// limits), so the triangulation is exact and the faces are mapped back exactly.
pub fn triangulate(points: &[[i64; 2]], bits: u32) -> Option<Mesh> {
    let mut dt: DelaunayTriangulation<Point2<f64>> = DelaunayTriangulation::new();
    for &[x, y] in points {
        let p = Point2::new(exact_f64(x), exact_f64(y));
        spade::validate_vertex(&p).ok()?;
        dt.insert(p).ok()?;
    }
    let denom = BigInt::from(1) << bits;
    let back = |p: Point2<f64>| Point::new(from_f64(p.x, &denom), from_f64(p.y, &denom));
    let triangles: Vec<Triangle> = dt
        .inner_faces()
        .map(|f| {
            let [a, b, c] = f.vertices().map(|v| back(v.position()));
            Triangle::new(a, b, c)
        })
        .collect();
    if triangles.is_empty() {
        return None;
    }
    let outline = dt.convex_hull().map(|e| back(e.from().position())).collect();
    Some(Mesh { triangles, outline })
}

/// `v` as f64; the strategies only produce |v| < 2^40, exact in f64.
#[allow(clippy::cast_precision_loss)]
fn exact_f64(v: i64) -> f64 {
    debug_assert!(v.unsigned_abs() < 1 << 52);
    v as f64
}

#[allow(clippy::cast_possible_truncation)]
fn from_f64(v: f64, denom: &BigInt) -> BigRational {
    // v came from exact_f64 of an integer, so the cast back is exact.
    BigRational::new(BigInt::from(v as i64), denom.clone())
}

/// A spade Delaunay mesh of 3..=`max_points` random points on the 2^-`bits` px grid, inside
/// `[origin, origin + extent)` px on each axis.
pub fn delaunay_mesh(origin: [i64; 2], extent: i64, bits: u32, max_points: usize) -> BoxedStrategy<Mesh> {
    let unit = 1i64 << bits;
    let (ox, oy, span) = (origin[0] * unit, origin[1] * unit, extent * unit);
    prop::collection::vec((0..span, 0..span), 3..=max_points)
        .prop_filter_map("points span no area", move |pts| {
            let pts: Vec<[i64; 2]> = pts.into_iter().map(|(x, y)| [ox + x, oy + y]).collect();
            triangulate(&pts, bits)
        })
        .boxed()
}

/// A tie-heavy mesh: points on the half-pixel grid, so many samples lie exactly on shared
/// edges and on vertices.
pub fn tie_heavy_mesh(canvas: u32, max_points: usize) -> BoxedStrategy<Mesh> {
    delaunay_mesh([0, 0], i64::from(canvas), 1, max_points)
}

/// Integer pixel endpoints `(from, to)` with coordinates in `-margin..side + margin`, all
/// octants, zero-length lines included.
pub fn pixel_line(side: i64, margin: i64) -> BoxedStrategy<([i64; 2], [i64; 2])> {
    let c = -margin..side + margin;
    ((c.clone(), c.clone()), (c.clone(), c))
        .prop_map(|((a, b), (x, y))| ([a, b], [x, y]))
        .boxed()
}

/// Integer pixel endpoints around `origin` with a major length of up to `max_len`: the
/// family for measuring the DDA's departures by length and magnitude.
pub fn long_pixel_line(origin: i64, max_len: i64) -> BoxedStrategy<([i64; 2], [i64; 2])> {
    (
        prop::array::uniform2(-max_len..=max_len),
        prop::array::uniform2(-max_len..=max_len),
    )
        .prop_map(move |(a, b)| ([origin + a[0], origin + a[1]], [origin + b[0], origin + b[1]]))
        .boxed()
}

/// A diamond-exit line on a `side` canvas with tie-heavy endpoints (pixel centres,
/// corners, diamond corners at half pixels, k/512).
pub fn diamond_line(side: u32) -> BoxedStrategy<crate::line::Line> {
    (prop::array::uniform4(tie_heavy_coordinate(side)),)
        .prop_map(|([a, b, c, d],)| crate::line::Line {
            from: Point::new(a, b),
            to: Point::new(c, d),
            rule: crate::line::LineRule::Diamond,
        })
        .boxed()
}
