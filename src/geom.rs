//! Geometry: exact points and triangles, their snapped forms, and the fixed-point
//! triangle that the integer models take (inside the envelope by construction).

use num_bigint::BigInt;
use num_rational::BigRational;

use crate::convention::Convention;
use crate::num::compact::Compact;
use crate::num::exact::{dyadic, nearest_f32, nearest_f64, pair_text};
use crate::num::fixed::snap;
use crate::num::{EnvelopeError, SubPixel};

/// A point with exact rational coordinates, in pixels.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Point {
    /// x, to the right.
    pub x: BigRational,
    /// y, downwards.
    pub y: BigRational,
}

/// `(3, -7/2)`: the exact text of both coordinates ([`pair_text`]).
impl std::fmt::Display for Point {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&pair_text(&self.x, &self.y))
    }
}

impl Point {
    /// A point from two rationals.
    pub fn new(x: BigRational, y: BigRational) -> Point {
        Point { x, y }
    }

    /// A point from integers.
    pub fn from_ints(x: i64, y: i64) -> Point {
        Point::new(BigRational::from_integer(x.into()), BigRational::from_integer(y.into()))
    }

    /// The point rounded to the nearest f32 on each axis (once: [`nearest_f32`]); `None`
    /// when a coordinate does not fit f32.
    pub fn to_f32(&self) -> Option<glam::Vec2> {
        Some(glam::Vec2::new(nearest_f32(&self.x)?, nearest_f32(&self.y)?))
    }

    /// The point rounded to the nearest f64 on each axis; `None` when a coordinate does not
    /// fit f64.
    pub fn to_f64(&self) -> Option<glam::DVec2> {
        Some(glam::DVec2::new(nearest_f64(&self.x)?, nearest_f64(&self.y)?))
    }

    /// A point from fractions `xn/xd, yn/yd` (denominators non-zero).
    pub fn from_fractions(xn: i64, xd: i64, yn: i64, yd: i64) -> Point {
        Point::new(
            BigRational::new(xn.into(), xd.into()),
            BigRational::new(yn.into(), yd.into()),
        )
    }
}

/// An 8-bit RGB colour, 0-255 per channel: a vertex colour of a scene triangle.
pub type Rgb = [u8; 3];

/// A triangle with exact vertices, in the order given (either winding).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Triangle {
    /// The three vertices.
    pub v: [Point; 3],
}

impl Triangle {
    /// A triangle from three points.
    pub fn new(a: Point, b: Point, c: Point) -> Triangle {
        Triangle { v: [a, b, c] }
    }

    /// The same triangle with vertices rotated: (v1, v2, v0).
    pub fn rotated(&self) -> Triangle {
        let [a, b, c] = self.v.clone();
        Triangle::new(b, c, a)
    }

    /// The same triangle with the opposite winding: (v0, v2, v1).
    pub fn reversed(&self) -> Triangle {
        let [a, b, c] = self.v.clone();
        Triangle::new(a, c, b)
    }

    /// The triangle moved by whole pixels.
    pub fn translated(&self, dx: i64, dy: i64) -> Triangle {
        let (dx, dy) = (
            BigRational::from_integer(dx.into()),
            BigRational::from_integer(dy.into()),
        );
        Triangle {
            v: self.v.clone().map(|p| Point::new(p.x + &dx, p.y + &dy)),
        }
    }

    /// The vertices snapped to the convention's grid.
    pub fn snapped(&self, convention: &Convention) -> SnappedTriangle {
        let s = |x: &BigRational| snap(x, convention.subpixel_bits, convention.rounding);
        SnappedTriangle {
            v: self.v.clone().map(|p| [s(&p.x), s(&p.y)]),
            bits: convention.subpixel_bits,
        }
    }

    /// The vertices rounded to the nearest f32 (once: [`nearest_f32`]), as glam vectors.
    /// `None` when a coordinate does not fit f32.
    pub fn to_f32(&self) -> Option<[glam::Vec2; 3]> {
        let [a, b, c] = &self.v;
        Some([a.to_f32()?, b.to_f32()?, c.to_f32()?])
    }

    /// The vertices rounded to the nearest f64, as glam vectors. `None` when a coordinate
    /// does not fit f64.
    pub fn to_f64(&self) -> Option<[glam::DVec2; 3]> {
        let [a, b, c] = &self.v;
        Some([a.to_f64()?, b.to_f64()?, c.to_f64()?])
    }
}

/// A triangle's exact vertices in compact form: each coordinate a [`Compact`], 16 bytes
/// when it is small, so a triangle of a scene file's decimals costs 96 bytes and no heap.
/// How a scene holds its triangles ([`crate::model::Primitives`]); the integer models snap
/// it without a big rational, the exact models read it as a [`Triangle`].
///
/// ```
/// use rasterproof::geom::{CompactTriangle, Point, Triangle};
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_fractions(9, 2, 0, 1), Point::from_ints(0, 4));
/// let c = CompactTriangle::from(&t);
/// assert_eq!(c.to_triangle(), t);
/// assert_eq!(std::mem::size_of::<CompactTriangle>(), 96);
/// ```
/// The default is the triangle with every vertex at the origin.
#[derive(Debug, Clone, Default, PartialEq, Eq, Hash)]
pub struct CompactTriangle {
    /// `[x, y]` of each vertex, in pixels.
    pub v: [[Compact; 2]; 3],
}

impl CompactTriangle {
    /// The exact triangle.
    pub fn to_triangle(&self) -> Triangle {
        Triangle {
            v: self.v.clone().map(|[x, y]| Point::new(x.to_big(), y.to_big())),
        }
    }

    /// The vertices snapped to the convention's grid: [`Triangle::snapped`] of
    /// [`CompactTriangle::to_triangle`].
    pub fn snapped(&self, convention: &Convention) -> SnappedTriangle {
        let s = |x: &Compact| x.snap(convention.subpixel_bits, convention.rounding);
        SnappedTriangle {
            v: self.v.each_ref().map(|[x, y]| [s(x), s(y)]),
            bits: convention.subpixel_bits,
        }
    }

    /// The vertices snapped to the convention's grid, as exact pixel coordinates again
    /// (`snapped(convention).to_exact()`, for the `exact-snapped` model), compact.
    pub fn snapped_exact(&self, convention: &Convention) -> CompactTriangle {
        let (bits, rounding) = (convention.subpixel_bits, convention.rounding);
        let snap_one = |x: &Compact| match x.snap_i64(bits, rounding) {
            Some(s) => Compact::dyadic(s, bits),
            None => Compact::from_big(dyadic(&x.snap(bits, rounding), bits)),
        };
        CompactTriangle {
            v: self.v.each_ref().map(|[x, y]| [snap_one(x), snap_one(y)]),
        }
    }

    /// The triangle in the integer models' form when snapping leaves it as it is: every
    /// coordinate on the convention's subpixel grid ([`Compact::on_grid`]) inside the
    /// envelope; `None` otherwise. The planned engine draws such a triangle with the
    /// integer engine.
    pub fn on_grid(&self, convention: &Convention) -> Option<FixedTriangle> {
        let bits = convention.subpixel_bits;
        let exact = |x: &Compact| x.on_grid(bits).and_then(SubPixel::new);
        let mut v = [[SubPixel::new(0).expect("0 is inside the envelope"); 2]; 3];
        for (k, [x, y]) in self.v.iter().enumerate() {
            v[k] = [exact(x)?, exact(y)?];
        }
        Some(FixedTriangle { v, bits })
    }

    /// The snapped triangle in the integer models' form (`snapped(convention).to_fixed()`),
    /// in machine integers when every coordinate is small.
    ///
    /// # Errors
    /// The first vertex coordinate outside the envelope, as `(vertex, axis, error)`.
    pub fn to_fixed(&self, convention: &Convention) -> Result<FixedTriangle, (usize, char, EnvelopeError)> {
        let (bits, rounding) = (convention.subpixel_bits, convention.rounding);
        let fast = |x: &Compact| x.snap_i64(bits, rounding).and_then(SubPixel::new);
        let mut v = [[SubPixel::new(0).expect("0 is inside the envelope"); 2]; 3];
        for (k, [x, y]) in self.v.iter().enumerate() {
            match (fast(x), fast(y)) {
                (Some(x), Some(y)) => v[k] = [x, y],
                _ => return self.snapped(convention).to_fixed(),
            }
        }
        Ok(FixedTriangle { v, bits })
    }
}

impl From<&Triangle> for CompactTriangle {
    fn from(t: &Triangle) -> CompactTriangle {
        CompactTriangle {
            v: t.v.each_ref().map(|p| [Compact::from(&p.x), Compact::from(&p.y)]),
        }
    }
}

impl From<Triangle> for CompactTriangle {
    fn from(t: Triangle) -> CompactTriangle {
        CompactTriangle {
            v: t.v.map(|p| [Compact::from_big(p.x), Compact::from_big(p.y)]),
        }
    }
}

/// A triangle snapped to a 2^-bits grid: integer subpixels of any size.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SnappedTriangle {
    /// `[x, y]` of each vertex in subpixels.
    pub v: [[BigInt; 2]; 3],
    /// The grid: 2^-bits pixel.
    pub bits: u32,
}

impl SnappedTriangle {
    /// The snapped triangle as exact rationals (for the `exact-snapped` model).
    pub fn to_exact(&self) -> Triangle {
        Triangle {
            v: self
                .v
                .clone()
                .map(|[x, y]| Point::new(dyadic(&x, self.bits), dyadic(&y, self.bits))),
        }
    }

    /// The snapped triangle in the integer models' form; an error names the first vertex
    /// coordinate outside the envelope as `(vertex, axis, error)`.
    pub fn to_fixed(&self) -> Result<FixedTriangle, (usize, char, EnvelopeError)> {
        let mut v = [[SubPixel::new(0).expect("0 is inside the envelope"); 2]; 3];
        for (k, [x, y]) in self.v.iter().enumerate() {
            v[k][0] = SubPixel::try_from_bigint(x, self.bits).map_err(|e| (k, 'x', e))?;
            v[k][1] = SubPixel::try_from_bigint(y, self.bits).map_err(|e| (k, 'y', e))?;
        }
        Ok(FixedTriangle { v, bits: self.bits })
    }
}

/// A triangle in subpixels, inside the integer models' envelope by construction. The
/// default is every vertex at the origin, on the grid of whole pixels.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct FixedTriangle {
    /// `[x, y]` of each vertex.
    pub v: [[SubPixel; 2]; 3],
    /// The grid: 2^-bits pixel.
    pub bits: u32,
}

impl FixedTriangle {
    /// The vertices as plain i64 pairs.
    #[inline]
    pub fn coords(&self) -> [[i64; 2]; 3] {
        self.v.map(|[x, y]| [x.get(), y.get()])
    }

    /// The triangle as exact rationals (for the oracle).
    pub fn to_exact(&self) -> Triangle {
        Triangle {
            v: self
                .coords()
                .map(|[x, y]| Point::new(dyadic(&x.into(), self.bits), dyadic(&y.into(), self.bits))),
        }
    }
}

/// How a polygon's winding number decides which samples are inside.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FillRule {
    /// Inside where the winding number is not zero (SVG's and Canvas 2D's default).
    NonZero,
    /// Inside where the winding number is odd.
    EvenOdd,
}

impl FillRule {
    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            FillRule::NonZero => "nonzero",
            FillRule::EvenOdd => "even-odd",
        }
    }

    /// Parses a name written by [`FillRule::name`].
    pub fn from_name(name: &str) -> Option<FillRule> {
        [FillRule::NonZero, FillRule::EvenOdd]
            .into_iter()
            .find(|r| r.name() == name)
    }

    /// Whether a sample with winding number `w` is inside.
    pub fn inside(self, w: i64) -> bool {
        match self {
            FillRule::NonZero => w != 0,
            FillRule::EvenOdd => w.rem_euclid(2) == 1,
        }
    }
}

/// A polygon with exact vertices: an outline and holes, each a closed contour (the last
/// vertex joins the first), in either orientation.
///
/// Its region: the samples whose moved sample (the tie rule's ε reading,
/// [`crate::convention::TieRule`]) satisfies the fill rule for its winding number around
/// the outline, and for none of the holes' — the outline's region minus the holes'
/// regions. Both fill rules ignore orientation, so a hole is a hole however it is wound;
/// even-odd and nonzero agree on simple contours and differ where a self-intersecting
/// contour winds twice. Clipping a contour against a convex window keeps its winding
/// number at every point inside the window, so clipping commutes with this rule.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Polygon {
    /// The outer contour.
    pub outline: Vec<Point>,
    /// The holes.
    pub holes: Vec<Vec<Point>>,
    /// Even-odd or nonzero.
    pub fill_rule: FillRule,
}

impl Polygon {
    /// A polygon without holes.
    pub fn new(outline: Vec<Point>, fill_rule: FillRule) -> Polygon {
        Polygon {
            outline,
            holes: Vec::new(),
            fill_rule,
        }
    }

    /// The outline, then the holes.
    pub fn contours(&self) -> impl Iterator<Item = &[Point]> + '_ {
        std::iter::once(self.outline.as_slice()).chain(self.holes.iter().map(Vec::as_slice))
    }

    /// The polygon moved by whole pixels.
    pub fn translated(&self, dx: i64, dy: i64) -> Polygon {
        let (dx, dy) = (
            BigRational::from_integer(dx.into()),
            BigRational::from_integer(dy.into()),
        );
        let mv = |c: &Vec<Point>| -> Vec<Point> { c.iter().map(|p| Point::new(&p.x + &dx, &p.y + &dy)).collect() };
        Polygon {
            outline: mv(&self.outline),
            holes: self.holes.iter().map(mv).collect(),
            fill_rule: self.fill_rule,
        }
    }

    /// The polygon with every vertex snapped to the convention's grid, as exact rationals
    /// again (the `exact-snapped` model's input).
    pub fn snapped_exact(&self, convention: &Convention) -> Polygon {
        let bits = convention.subpixel_bits;
        let s = |x: &BigRational| dyadic(&snap(x, bits, convention.rounding), bits);
        let mv = |c: &Vec<Point>| -> Vec<Point> { c.iter().map(|p| Point::new(s(&p.x), s(&p.y))).collect() };
        Polygon {
            outline: mv(&self.outline),
            holes: self.holes.iter().map(mv).collect(),
            fill_rule: self.fill_rule,
        }
    }

    /// The snapped polygon in the integer models' form; an error names the first vertex
    /// coordinate outside the envelope as `(contour, vertex, axis, error)`, contour 0
    /// being the outline and `k` the hole `k - 1`.
    pub fn to_fixed(&self, convention: &Convention) -> Result<FixedPolygon, (usize, usize, char, EnvelopeError)> {
        let bits = convention.subpixel_bits;
        let mut contours = Vec::with_capacity(1 + self.holes.len());
        for (k, contour) in self.contours().enumerate() {
            let mut out = Vec::with_capacity(contour.len());
            for (i, p) in contour.iter().enumerate() {
                let f = |x: &BigRational, axis| {
                    SubPixel::try_from_bigint(&snap(x, bits, convention.rounding), bits)
                        .map(SubPixel::get)
                        .map_err(|e| (k, i, axis, e))
                };
                out.push([f(&p.x, 'x')?, f(&p.y, 'y')?]);
            }
            contours.push(out);
        }
        Ok(FixedPolygon {
            contours,
            fill_rule: self.fill_rule,
            bits,
        })
    }
}

/// A polygon in subpixels, every coordinate inside the integer models' envelope
/// (`|v| <= 2^29`) by construction.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct FixedPolygon {
    contours: Vec<Vec<[i64; 2]>>,
    /// Even-odd or nonzero.
    pub fill_rule: FillRule,
    /// The grid: 2^-bits pixel.
    pub bits: u32,
}

impl FixedPolygon {
    /// A polygon from contours in subpixels (the first is the outline, the rest holes);
    /// `None` when a coordinate is outside the envelope or there is no outline.
    pub fn new(contours: Vec<Vec<[i64; 2]>>, fill_rule: FillRule, bits: u32) -> Option<FixedPolygon> {
        let inside = contours.iter().flatten().flatten().all(|&v| SubPixel::new(v).is_some());
        (inside && !contours.is_empty()).then_some(FixedPolygon {
            contours,
            fill_rule,
            bits,
        })
    }

    /// The outline, then the holes: `[x, y]` subpixels.
    pub fn contours(&self) -> &[Vec<[i64; 2]>] {
        &self.contours
    }

    /// The polygon as exact rationals (for the oracle).
    pub fn to_exact(&self) -> Polygon {
        let pt = |&[x, y]: &[i64; 2]| Point::new(dyadic(&x.into(), self.bits), dyadic(&y.into(), self.bits));
        Polygon {
            outline: self.contours[0].iter().map(pt).collect(),
            holes: self.contours[1..].iter().map(|c| c.iter().map(pt).collect()).collect(),
            fill_rule: self.fill_rule,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::Preset;

    #[test]
    fn snapping_a_triangle_and_back() {
        let t = Triangle::new(
            Point::from_fractions(1, 3, 0, 1),
            Point::from_fractions(10, 1, 1, 512),
            Point::from_fractions(-3, 2, 5, 1),
        );
        let s = t.snapped(&Preset::D3d11.convention());
        assert_eq!(s.v[0], [BigInt::from(85), BigInt::from(0)]);
        assert_eq!(s.v[1], [BigInt::from(2560), BigInt::from(0)]); // 1/512 -> 0.5 -> even 0
        assert_eq!(s.v[2], [BigInt::from(-384), BigInt::from(1280)]);
        let cts = t.snapped(&Preset::Cts.convention());
        assert_eq!(cts.v[1][1], BigInt::from(1)); // half away from zero
        assert_eq!(s.to_exact().v[0].x, BigRational::new(85.into(), 256.into()));
    }

    #[test]
    fn envelope_is_checked_per_vertex() {
        let far = 1i64 << 21; // 2^21 px = 2^29 subpixels: inside, exactly at the edge
        let t = Triangle::new(
            Point::from_ints(far, 0),
            Point::from_ints(0, -far),
            Point::from_ints(0, 0),
        );
        assert!(t.snapped(&Convention::default()).to_fixed().is_ok());
        let t = Triangle::new(
            Point::from_ints(0, 0),
            Point::from_fractions(far * 256 + 1, 256, 0, 1),
            Point::from_ints(0, 1),
        );
        let (vertex, axis, _) = t.snapped(&Convention::default()).to_fixed().unwrap_err();
        assert_eq!((vertex, axis), (1, 'x'));
    }

    /// A triangle is on the grid when snapping leaves every coordinate as it is: at 8
    /// bits, 3/4 px is 192 subpixels, -5/2 px is -640, 1/256 px is 1; 1/512 px and 1/3 px
    /// are not on it, nor is 2^21 px + 1/256 (one subpixel beyond the envelope's 2^29), and
    /// a triangle on it is the snapped triangle.
    #[test]
    fn a_triangle_on_the_grid_is_its_snapped_self() {
        let conv = Preset::Cts.convention();
        let tri = |x: (i64, i64), y: (i64, i64)| {
            CompactTriangle::from(Triangle::new(
                Point::from_fractions(x.0, x.1, y.0, y.1),
                Point::from_ints(0, 0),
                Point::from_ints(1, 0),
            ))
        };
        let at = |t: CompactTriangle| t.on_grid(&conv).map(|f| f.coords()[0]);
        assert_eq!(at(tri((3, 4), (-5, 2))), Some([192, -640]));
        assert_eq!(at(tri((1, 256), (0, 1))), Some([1, 0]));
        assert_eq!(at(tri((1, 512), (0, 1))), None);
        assert_eq!(at(tri((0, 1), (1, 3))), None);
        let far = (1i64 << 21) * 256;
        assert_eq!(at(tri((far, 256), (0, 1))), Some([1 << 29, 0]));
        assert_eq!(at(tri((far + 1, 256), (0, 1))), None);
        let t = tri((-7, 8), (33, 16));
        assert_eq!(t.on_grid(&conv), t.to_fixed(&conv).ok());
    }
}
