//! Exact attribute values at a point of a triangle: the readable definition of what an
//! interpolator must write (`smooth`, `noperspective`, `flat`).
//!
//! A triangle's vertex `i` has its window position `(x_i, y_i)` and its clip-space `w_i`
//! (`1` for a window-space triangle given without `w`). In 2D homogeneous coordinates
//! (Olano and Greer, "Triangle Scan Conversion using 2D Homogeneous Coordinates", 1997) it
//! is `h_i = (x_i w_i, y_i w_i, w_i)`; for a clip-space vertex `(X, Y, Z, W)` that is the
//! viewport's window map applied without the divide, so a vertex behind the eye (`W <= 0`)
//! is no special case and nothing is clipped first. At a window point `p` the homogeneous
//! barycentrics `b` solve `b_0 h_0 + b_1 h_1 + b_2 h_2 = (p_x, p_y, 1)`, by Cramer's rule:
//! `b_i = q . (h_{i+1} x h_{i+2}) / h_0 . (h_1 x h_2)` with `q = (p_x, p_y, 1)`. Then
//!
//! - `mu_i = b_i w_i` are `p`'s window-space barycentrics over the projected vertices
//!   (`mu_0 + mu_1 + mu_2 = 1` is the third row of the system);
//! - `b_0 + b_1 + b_2 = 1 / w` at `p`;
//! - **smooth** (perspective-correct): `f = (b_0 f_0 + b_1 f_1 + b_2 f_2) / (b_0 + b_1 + b_2)`,
//!   which is `sum mu_i f_i / w_i / sum mu_i / w_i`, equation (14.9) of the OpenGL 4.6 core
//!   specification (section 14.6.1) and the Vulkan specification's perspective-correct
//!   polygon interpolation (section "Basic Polygon Rasterization"). It is undefined where
//!   `1 / w = 0` (the triangle's horizon, which only an extrapolated point can reach);
//! - **noperspective**: `f = sum mu_i f_i`, linear in window space (equation (14.10)). With
//!   a vertex behind the eye this is the window-linear function that clipping with the
//!   specification's adjusted `t` (OpenGL 4.6 section 13.7) gives the clipped polygon;
//! - **flat**: the provoking vertex's value, the first or the last vertex of a triangle of
//!   a list (OpenGL 4.6 section 13.4, table 13.2; Vulkan "Provoking Vertex"; Direct3D 10
//!   and later always take the first).
//!
//! Every value is exact: a ratio of polynomials in the scene's rational coordinates. A
//! point outside the triangle extrapolates (the plane goes on), as a pixel centre outside a
//! primitive does under multisampling.

use std::fmt;
use std::ops::Range;

use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::geom::Point;

/// How a varying's value varies over a primitive.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Interpolation {
    /// Perspective-correct (GLSL `smooth`, WGSL `perspective`, HLSL `linear`).
    Smooth,
    /// Linear in window space (GLSL `noperspective`, WGSL `linear`, HLSL `noperspective`).
    NoPerspective,
    /// The provoking vertex's value everywhere (GLSL `flat`, WGSL `flat`, HLSL
    /// `nointerpolation`).
    Flat,
}

impl Interpolation {
    /// Every interpolation, in the order their names are listed.
    pub const ALL: [Interpolation; 3] = [Interpolation::Smooth, Interpolation::NoPerspective, Interpolation::Flat];

    /// The scene file's name: `smooth`, `noperspective` or `flat`.
    pub fn name(self) -> &'static str {
        match self {
            Interpolation::Smooth => "smooth",
            Interpolation::NoPerspective => "noperspective",
            Interpolation::Flat => "flat",
        }
    }

    /// The interpolation named `name`.
    pub fn parse(name: &str) -> Option<Interpolation> {
        Interpolation::ALL.into_iter().find(|i| i.name() == name)
    }
}

impl fmt::Display for Interpolation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Where in a pixel a varying is evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Sampling {
    /// The pixel's centre (the convention's sample point), covered or not.
    Centre,
    /// Direct3D's centroid rule: the centre when every sample of the pixel is covered,
    /// otherwise the first covered sample in index order (with one sample per pixel: the
    /// sample).
    Centroid,
    /// Each covered sample's own position (per-sample shading).
    Sample,
}

impl Sampling {
    /// Every sampling point, in the order their names are listed.
    pub const ALL: [Sampling; 3] = [Sampling::Centre, Sampling::Centroid, Sampling::Sample];

    /// The scene file's name: `centre`, `centroid` or `sample`.
    pub fn name(self) -> &'static str {
        match self {
            Sampling::Centre => "centre",
            Sampling::Centroid => "centroid",
            Sampling::Sample => "sample",
        }
    }

    /// The sampling point named `name`.
    pub fn parse(name: &str) -> Option<Sampling> {
        Sampling::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// Which vertex of a triangle of a list a `flat` varying takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum ProvokingVertex {
    /// Vertex 0: Vulkan's default, Direct3D's only rule, OpenGL's
    /// `GL_FIRST_VERTEX_CONVENTION`.
    #[default]
    First,
    /// Vertex 2: OpenGL's default (`GL_LAST_VERTEX_CONVENTION`), Vulkan's
    /// `VK_PROVOKING_VERTEX_MODE_LAST_VERTEX_EXT`.
    Last,
}

impl ProvokingVertex {
    /// The scene file's name: `first` or `last`.
    pub fn name(self) -> &'static str {
        match self {
            ProvokingVertex::First => "first",
            ProvokingVertex::Last => "last",
        }
    }

    /// The rule named `name`.
    pub fn parse(name: &str) -> Option<ProvokingVertex> {
        [ProvokingVertex::First, ProvokingVertex::Last]
            .into_iter()
            .find(|p| p.name() == name)
    }

    /// The provoking vertex's index in a primitive of `count` vertices of a list (a
    /// triangle's 0 or 2, a line's 0 or 1).
    pub fn vertex(self, count: usize) -> usize {
        match self {
            ProvokingVertex::First => 0,
            ProvokingVertex::Last => count - 1,
        }
    }
}

/// One declared varying: a name, its number of channels, how it is interpolated and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Varying {
    /// The name primitives give its values under.
    pub name: String,
    /// Channels per vertex, at least 1.
    pub channels: usize,
    /// How it varies.
    pub interpolation: Interpolation,
    /// Where it is evaluated.
    pub sampling: Sampling,
}

/// A scene's varyings, in declaration order, and the provoking-vertex rule of its `flat`
/// ones. Each vertex of a primitive carries every varying's channels, concatenated in this
/// order.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Varyings {
    /// The varyings.
    pub list: Vec<Varying>,
    /// The provoking vertex of `flat` varyings.
    pub provoking: ProvokingVertex,
}

impl Varyings {
    /// The channels of all varyings together: a vertex's value count.
    pub fn channels(&self) -> usize {
        self.list.iter().map(|v| v.channels).sum()
    }

    /// Each varying with the range of its channels in a vertex's values.
    ///
    /// ```
    /// use rasterproof::interp::values::{Interpolation, Sampling, Varying, Varyings};
    /// let v = |name: &str, channels| Varying {
    ///     name: name.into(),
    ///     channels,
    ///     interpolation: Interpolation::Smooth,
    ///     sampling: Sampling::Centre,
    /// };
    /// let all = Varyings { list: vec![v("uv", 2), v("colour", 3)], ..Varyings::default() };
    /// let ranges: Vec<_> = all.ranges().map(|(v, r)| (v.name.as_str(), r)).collect();
    /// assert_eq!(ranges, [("uv", 0..2), ("colour", 2..5)]);
    /// ```
    pub fn ranges(&self) -> impl Iterator<Item = (&Varying, Range<usize>)> {
        self.list.iter().scan(0, |start, v| {
            let range = *start..*start + v.channels;
            *start = range.end;
            Some((v, range))
        })
    }
}

/// A triangle as an interpolator sees it: each vertex in 2D homogeneous window
/// coordinates `(x w, y w, w)` with its values (every varying's channels).
#[derive(Debug, Clone, PartialEq)]
pub struct ValueTriangle {
    /// Per vertex, `[x w, y w, w]`.
    pub h: [[BigRational; 3]; 3],
    /// Per vertex, the values of every channel.
    pub values: [Vec<BigRational>; 3],
}

/// Why a triangle has no value at a point.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum NoValue {
    /// The homogeneous vertices are linearly dependent: the triangle has no area in window
    /// space (it covers no sample) or is seen edge-on.
    Degenerate,
    /// `1 / w = 0` at the point: it lies on the triangle's horizon, where a perspective-
    /// correct value is infinite. Only an extrapolated point (outside the triangle) can.
    Horizon,
    /// The primitive carries no values (polygons do not).
    NotCarried,
}

impl NoValue {
    /// The reason's name in JSON: `degenerate`, `horizon` or `not-carried`.
    pub fn name(&self) -> &'static str {
        match self {
            NoValue::Degenerate => "degenerate",
            NoValue::Horizon => "horizon",
            NoValue::NotCarried => "not-carried",
        }
    }
}

impl fmt::Display for NoValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NoValue::Degenerate => f.write_str("the triangle is degenerate in window space"),
            NoValue::Horizon => f.write_str("the point lies on the triangle's horizon (1/w = 0)"),
            NoValue::NotCarried => f.write_str("the primitive carries no values"),
        }
    }
}

fn cross(a: &[BigRational; 3], b: &[BigRational; 3]) -> [BigRational; 3] {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn dot(a: &[BigRational; 3], b: &[BigRational; 3]) -> BigRational {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

impl ValueTriangle {
    /// A window-space triangle: vertex `i` at `points[i]` with clip-space `w[i]` (all `1`
    /// for no perspective) and `values[i]`.
    pub fn window(points: [&Point; 3], w: [&BigRational; 3], values: [Vec<BigRational>; 3]) -> ValueTriangle {
        let h = [0, 1, 2].map(|i| [&points[i].x * w[i], &points[i].y * w[i], w[i].clone()]);
        ValueTriangle { h, values }
    }

    /// The homogeneous barycentrics `b` of window point `p` (see the module docs); their
    /// sum is `1 / w` at `p`.
    ///
    /// ```
    /// use rasterproof::geom::Point;
    /// use rasterproof::interp::values::ValueTriangle;
    /// let q = |n: i64, d: i64| num_rational::BigRational::new(n.into(), d.into());
    /// let (a, b, c) = (Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
    /// // w = 1, 3, 1: at the midpoint of the first edge the window barycentrics are
    /// // (1/2, 1/2, 0), and b_i = mu_i / w_i = (1/2, 1/6, 0).
    /// let t = ValueTriangle::window([&a, &b, &c], [&q(1, 1), &q(3, 1), &q(1, 1)], [vec![], vec![], vec![]]);
    /// assert_eq!(t.barycentrics(&Point::from_ints(2, 0)).unwrap(), [q(1, 2), q(1, 6), q(0, 1)]);
    /// ```
    ///
    /// # Errors
    /// [`NoValue::Degenerate`] when the homogeneous vertices are linearly dependent.
    pub fn barycentrics(&self, p: &Point) -> Result<[BigRational; 3], NoValue> {
        let [h0, h1, h2] = &self.h;
        let normals = [cross(h1, h2), cross(h2, h0), cross(h0, h1)];
        let det = dot(h0, &normals[0]);
        if det.is_zero() {
            return Err(NoValue::Degenerate);
        }
        let q = [p.x.clone(), p.y.clone(), BigRational::one()];
        Ok(normals.map(|n| dot(&q, &n) / &det))
    }

    /// The exact value of the channels `channels` at window point `p` under
    /// `interpolation` (`provoking` for [`Interpolation::Flat`]).
    ///
    /// ```
    /// use rasterproof::geom::Point;
    /// use rasterproof::interp::values::{Interpolation, ProvokingVertex, ValueTriangle};
    /// let q = |n: i64, d: i64| num_rational::BigRational::new(n.into(), d.into());
    /// let (a, b, c) = (Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
    /// // The value 0 at w = 1, 1 at w = 3, 0 at w = 1. At the first edge's midpoint:
    /// // smooth (1/2 * 1/3) / (1/2 + 1/2 * 1/3) = 1/4, noperspective 1/2, flat (last) 0.
    /// let t = ValueTriangle::window(
    ///     [&a, &b, &c],
    ///     [&q(1, 1), &q(3, 1), &q(1, 1)],
    ///     [vec![q(0, 1)], vec![q(1, 1)], vec![q(0, 1)]],
    /// );
    /// let mid = Point::from_ints(2, 0);
    /// let at = |i| t.value(i, ProvokingVertex::Last, 0..1, &mid).unwrap();
    /// assert_eq!(at(Interpolation::Smooth), [q(1, 4)]);
    /// assert_eq!(at(Interpolation::NoPerspective), [q(1, 2)]);
    /// assert_eq!(at(Interpolation::Flat), [q(0, 1)]);
    /// ```
    ///
    /// # Errors
    /// [`NoValue::Degenerate`] for a degenerate triangle (smooth and noperspective);
    /// [`NoValue::Horizon`] for a smooth value where `1 / w = 0`.
    ///
    /// # Panics
    /// When a vertex has fewer values than `channels` asks for.
    pub fn value(
        &self,
        interpolation: Interpolation,
        provoking: ProvokingVertex,
        channels: Range<usize>,
        p: &Point,
    ) -> Result<Vec<BigRational>, NoValue> {
        interpolate(&self.values, interpolation, provoking, channels, || {
            let b = self.barycentrics(p)?;
            if interpolation == Interpolation::NoPerspective {
                return Ok([0, 1, 2].map(|i| &b[i] * &self.h[i][2]));
            }
            let inv_w = &b[0] + &b[1] + &b[2];
            if inv_w.is_zero() {
                return Err(NoValue::Horizon);
            }
            Ok(b.map(|bi| bi / &inv_w))
        })
    }
}

/// The channels `channels` of a primitive whose vertices hold `values`: the provoking
/// vertex's for [`Interpolation::Flat`], otherwise the vertices' values weighted by
/// `weights` (which sum to 1).
fn interpolate<const N: usize>(
    values: &[Vec<BigRational>; N],
    interpolation: Interpolation,
    provoking: ProvokingVertex,
    channels: Range<usize>,
    weights: impl FnOnce() -> Result<[BigRational; N], NoValue>,
) -> Result<Vec<BigRational>, NoValue> {
    if interpolation == Interpolation::Flat {
        return Ok(values[provoking.vertex(N)][channels].to_vec());
    }
    let weights = weights()?;
    Ok(channels
        .map(|k| (0..N).fold(BigRational::zero(), |acc, i| acc + &weights[i] * &values[i][k]))
        .collect())
}

/// A line segment as an interpolator sees it: its two ends (window space, `w = 1`) with
/// their values.
///
/// At a window point `p` the segment's parameter is `t = (p - a) . (b - a) / |b - a|^2`,
/// the projection of `p` onto the segment's line (the Vulkan specification's "Basic Line
/// Segment Rasterization" and OpenGL 4.6 section 14.5.1 give it for the fragment's
/// centre); a `smooth` or `noperspective` value is `(1 - t) f_a + t f_b` (both ends at
/// `w = 1`, so the two agree), extrapolated where `t` leaves `[0, 1]` (a fragment past an
/// end). A `flat` value is the provoking end's: the first (`from`) or the last (`to`),
/// OpenGL's table 13.2 for independent lines.
#[derive(Debug, Clone, PartialEq)]
pub struct ValueSegment {
    /// `from` and `to`.
    pub ends: [Point; 2],
    /// Each end's values of every channel.
    pub values: [Vec<BigRational>; 2],
}

impl ValueSegment {
    /// The parameter `t` of window point `p` along the segment; `None` for a segment of
    /// zero length.
    ///
    /// ```
    /// use rasterproof::geom::Point;
    /// use rasterproof::interp::values::ValueSegment;
    /// let q = |n: i64, d: i64| num_rational::BigRational::new(n.into(), d.into());
    /// let s = ValueSegment { ends: [Point::from_ints(0, 0), Point::from_ints(4, 2)], values: [vec![], vec![]] };
    /// // (1, 3) . (4, 2) / 20 = 10 / 20.
    /// assert_eq!(s.parameter(&Point::from_ints(1, 3)), Some(q(1, 2)));
    /// ```
    pub fn parameter(&self, p: &Point) -> Option<BigRational> {
        let [a, b] = &self.ends;
        let (dx, dy) = (&b.x - &a.x, &b.y - &a.y);
        let length2 = &dx * &dx + &dy * &dy;
        if length2.is_zero() {
            return None;
        }
        Some(((&p.x - &a.x) * &dx + (&p.y - &a.y) * &dy) / length2)
    }

    /// The exact value of the channels `channels` at window point `p` (see the type's
    /// docs).
    ///
    /// # Errors
    /// [`NoValue::Degenerate`] for a zero-length segment (smooth and noperspective).
    ///
    /// # Panics
    /// When an end has fewer values than `channels` asks for.
    pub fn value(
        &self,
        interpolation: Interpolation,
        provoking: ProvokingVertex,
        channels: Range<usize>,
        p: &Point,
    ) -> Result<Vec<BigRational>, NoValue> {
        interpolate(&self.values, interpolation, provoking, channels, || {
            let t = self.parameter(p).ok_or(NoValue::Degenerate)?;
            Ok([BigRational::one() - &t, t])
        })
    }
}

/// A primitive's interpolation setup: a triangle's or a line segment's.
#[derive(Debug, Clone, PartialEq)]
pub enum ValueSetup {
    /// A triangle, window-space or clip-space (boxed: nine rationals and three lists).
    Triangle(Box<ValueTriangle>),
    /// A line segment (boxed, as the triangle is).
    Segment(Box<ValueSegment>),
}

impl ValueSetup {
    /// The exact value of the channels `channels` at window point `p`
    /// ([`ValueTriangle::value`], [`ValueSegment::value`]).
    ///
    /// # Errors
    /// As theirs.
    pub fn value(
        &self,
        interpolation: Interpolation,
        provoking: ProvokingVertex,
        channels: Range<usize>,
        p: &Point,
    ) -> Result<Vec<BigRational>, NoValue> {
        match self {
            ValueSetup::Triangle(t) => t.value(interpolation, provoking, channels, p),
            ValueSetup::Segment(s) => s.value(interpolation, provoking, channels, p),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    /// The window points (0, 0) and (4, 0) at w = 1 and (2, 2) at w = -1, with the values
    /// 0, 8 and 16.
    fn behind_the_eye() -> ValueTriangle {
        ValueTriangle {
            h: [
                [q(0, 1), q(0, 1), q(1, 1)],
                [q(4, 1), q(0, 1), q(1, 1)],
                [q(-2, 1), q(-2, 1), q(-1, 1)],
            ],
            values: [vec![q(0, 1)], vec![q(8, 1)], vec![q(16, 1)]],
        }
    }

    /// A triangle with one vertex behind the eye (w = -1): the value at a point is still
    /// the clip-space linear function seen through the point, computed by hand. Vertices
    /// in homogeneous form h = (x w, y w, w): (0,0,1), (4,0,1) and (-2,-2,-1) (window
    /// point (2, 2) at w = -1). At p = (1, 1/2): b solves b0 (0,0,1) + b1 (4,0,1) +
    /// b2 (-2,-2,-1) = (1, 1/2, 1): b2 = -1/4, 4 b1 = 1 + 2 b2 = 1/2, b1 = 1/8,
    /// b0 = 1 - b1 + b2 = 5/8. Sum 1/2 = 1/w. Smooth with values 0, 8, 16: (0 + 1 - 4) / (1/2)
    /// = -6; noperspective mu = (5/8, 1/8, 1/4): 1 + 4 = 5.
    #[test]
    fn a_vertex_behind_the_eye_by_hand() {
        let t = behind_the_eye();
        let p = Point::new(q(1, 1), q(1, 2));
        assert_eq!(t.barycentrics(&p).unwrap(), [q(5, 8), q(1, 8), q(-1, 4)]);
        let at = |i| t.value(i, ProvokingVertex::First, 0..1, &p).unwrap();
        assert_eq!(at(Interpolation::Smooth), [q(-6, 1)]);
        assert_eq!(at(Interpolation::NoPerspective), [q(5, 1)]);
        assert_eq!(at(Interpolation::Flat), [q(0, 1)]);
    }

    /// On the horizon (1/w = 0) a smooth value does not exist; the flat one does. The
    /// triangle above at p = (0, 1): the y row -2 b2 = 1 gives b2 = -1/2, the x row
    /// 4 b1 - 2 b2 = 0 gives b1 = -1/4, the w row b0 + b1 - b2 = 1 gives b0 = 3/4; the
    /// sum is 0. Collinear window points are degenerate.
    #[test]
    fn the_horizon_has_no_smooth_value() {
        let t = behind_the_eye();
        let p = Point::new(q(0, 1), q(1, 1));
        let b = t.barycentrics(&p).unwrap();
        assert_eq!(&b[0] + &b[1] + &b[2], q(0, 1));
        assert_eq!(
            t.value(Interpolation::Smooth, ProvokingVertex::First, 0..1, &p),
            Err(NoValue::Horizon)
        );
        assert_eq!(
            t.value(Interpolation::Flat, ProvokingVertex::Last, 0..1, &p),
            Ok(vec![q(16, 1)])
        );
        let flat = ValueTriangle {
            h: [
                [q(0, 1), q(0, 1), q(1, 1)],
                [q(2, 1), q(2, 1), q(1, 1)],
                [q(4, 1), q(4, 1), q(1, 1)],
            ],
            values: [vec![q(0, 1)], vec![q(1, 1)], vec![q(2, 1)]],
        };
        assert_eq!(flat.barycentrics(&p), Err(NoValue::Degenerate));
    }

    #[test]
    fn names_read_back() {
        for i in Interpolation::ALL {
            assert_eq!(Interpolation::parse(i.name()), Some(i));
        }
        for s in Sampling::ALL {
            assert_eq!(Sampling::parse(s.name()), Some(s));
        }
        for p in [ProvokingVertex::First, ProvokingVertex::Last] {
            assert_eq!(ProvokingVertex::parse(p.name()), Some(p));
        }
        assert_eq!(Interpolation::parse("linear"), None);
        assert_eq!(ProvokingVertex::Last.vertex(3), 2);
        assert_eq!(ProvokingVertex::Last.vertex(2), 1);
        assert_eq!(ProvokingVertex::First.vertex(3), 0);
    }
}
