//! Barycentric coordinates and attribute interpolation (Pineda 1988; Scratchapixel; Luebke).
//!
//! - exact: `λ0 = E(v1,v2,p) / E(v0,v1,v2)` etc. over `BigRational`; they sum to exactly 1;
//! - integer: the three edge values `w0, w1, w2` at a sample, whose sum is exactly twice
//!   the signed area (an algebraic identity the i64 arithmetic keeps inside the envelope);
//! - float: the same ratios in f32 / f64 (the sum misses 1 by a few ulps);
//! - Gouraud colour `c = λ0 c0 + λ1 c1 + λ2 c2`, and the plane equation of Luebke's slides
//!   `c = A x + B y + C` from a 3x3 solve, equal to it in exact arithmetic;
//! - [`values`]: a scene's declared varyings, exactly, at any point of a triangle
//!   (`smooth`, `noperspective`, `flat`; window-space or clip-space vertices); [`planned`]
//!   the same at float speed, [`float`] the float interpolators renderers build,
//!   [`envelope`] their error bound, [`dda`] a fixed-point Gouraud DDA.

pub mod dda;
pub mod envelope;
pub mod float;
pub mod planned;
pub mod values;

use glam::{DVec2, Vec2};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

use crate::convention::Target;
use crate::edge::exact::{area2, edge_function};
use crate::edge::fixed;
use crate::edge::float::{edge_f32, edge_f64};
use crate::geom::{FixedTriangle, Point, Rgb, Triangle};
use crate::num::exact::round_to_integer;
use crate::num::Rounding;
use crate::raster::FixedGrid;

/// Exact barycentrics of `p` (inside or outside: outside they extrapolate);
/// `None` for a zero-area triangle.
///
/// ```
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::interp::barycentric_exact;
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(3, 0), Point::from_ints(0, 3));
/// let l = barycentric_exact(&t, &Point::from_ints(1, 1)).unwrap();
/// assert_eq!(l, [(1, 3), (1, 3), (1, 3)].map(|(n, d)| num_rational::BigRational::new(n.into(), d.into())));
/// ```
pub fn barycentric_exact(t: &Triangle, p: &Point) -> Option<[BigRational; 3]> {
    let area = area2(t);
    if area.is_zero() {
        return None;
    }
    let [v0, v1, v2] = &t.v;
    Some([
        edge_function(v1, v2, p) / &area,
        edge_function(v2, v0, p) / &area,
        edge_function(v0, v1, p) / &area,
    ])
}

/// Integer edge values at a pixel's sample, with twice the signed area.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FixedBarycentrics {
    /// `[E(v1,v2,p), E(v2,v0,p), E(v0,v1,p)]` in subpixel² units.
    pub w: [i128; 3],
    /// `E(v0,v1,v2)`: `w[0] + w[1] + w[2] == area2`, always.
    pub area2: i128,
}

/// The integer edge values at the sample of pixel `(x, y)`, in i128: for any `u32` pixel
/// (on the canvas or not) and a [`FixedTriangle`], |values| < 2^100, so nothing overflows.
/// (On the canvas they also fit the i64 the `fixed` model steps with.)
pub fn barycentric_fixed(t: &FixedTriangle, x: u32, y: u32, target: &Target) -> FixedBarycentrics {
    let p = FixedGrid::of(&target.convention).sample_point(x, y).map(i128::from);
    let [v0, v1, v2] = t.coords().map(|v| v.map(i128::from));
    let e = crate::edge::fixed::edge_function_wide;
    FixedBarycentrics {
        w: [e(v1, v2, p), e(v2, v0, p), e(v0, v1, p)],
        area2: i128::from(fixed::area2(t)),
    }
}

/// f32 barycentrics (Scratchapixel: each edge value divided by the area); `None` when the
/// float area is zero.
pub fn barycentric_f32(t: &[Vec2; 3], p: Vec2) -> Option<[f32; 3]> {
    let area = edge_f32(t[0], t[1], t[2]);
    (area != 0.0).then(|| {
        [
            edge_f32(t[1], t[2], p) / area,
            edge_f32(t[2], t[0], p) / area,
            edge_f32(t[0], t[1], p) / area,
        ]
    })
}

/// f64 barycentrics; `None` when the float area is zero.
pub fn barycentric_f64(t: &[DVec2; 3], p: DVec2) -> Option<[f64; 3]> {
    let area = edge_f64(t[0], t[1], t[2]);
    (area != 0.0).then(|| {
        [
            edge_f64(t[1], t[2], p) / area,
            edge_f64(t[2], t[0], p) / area,
            edge_f64(t[0], t[1], p) / area,
        ]
    })
}

/// Exact Gouraud colour at `p`: `Σ λi ci` per channel, unrounded.
pub fn gouraud_exact(t: &Triangle, colours: &[Rgb; 3], p: &Point) -> Option<[BigRational; 3]> {
    let l = barycentric_exact(t, p)?;
    Some(std::array::from_fn(|ch| {
        (0..3)
            .map(|k| &l[k] * BigRational::from_integer(BigInt::from(colours[k][ch])))
            .fold(BigRational::zero(), |acc, v| acc + v)
    }))
}

/// An exact channel value rounded to 0-255 (nearest, ties to even; clamped for samples
/// that extrapolate outside the triangle).
pub fn to_channel(c: &BigRational) -> u8 {
    let r = round_to_integer(c, Rounding::NearestEven);
    u8::try_from(r.clamp(BigInt::zero(), BigInt::from(255))).expect("clamped to 0..=255")
}

/// f32 Gouraud colour at `p`, rounded to nearest and clamped.
pub fn gouraud_f32(t: &[Vec2; 3], colours: &[Rgb; 3], p: Vec2) -> Option<Rgb> {
    let l = barycentric_f32(t, p)?;
    Some(std::array::from_fn(|ch| {
        let v: f32 = (0..3).map(|k| l[k] * f32::from(colours[k][ch])).sum();
        float_channel(f64::from(v))
    }))
}

/// f64 Gouraud colour at `p`, rounded to nearest and clamped.
pub fn gouraud_f64(t: &[DVec2; 3], colours: &[Rgb; 3], p: DVec2) -> Option<Rgb> {
    let l = barycentric_f64(t, p)?;
    Some(std::array::from_fn(|ch| {
        let v: f64 = (0..3).map(|k| l[k] * f64::from(colours[k][ch])).sum();
        float_channel(v)
    }))
}

#[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)] // clamped to 0..=255 first
fn float_channel(v: f64) -> u8 {
    if v.is_nan() {
        0
    } else {
        v.round().clamp(0.0, 255.0) as u8
    }
}

/// An attribute as a plane over the triangle: `c(x, y) = a x + b y + c` (Luebke, "Drawing triangles").
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Plane {
    /// Coefficient of x.
    pub a: BigRational,
    /// Coefficient of y.
    pub b: BigRational,
    /// Constant term.
    pub c: BigRational,
}

impl Plane {
    /// Luebke's plane-equation setup: solve `[xi yi 1] . [a b c] = vi` for the three vertices by
    /// Cramer's rule; `None` when the triangle has zero area (the matrix is singular).
    pub fn setup(t: &Triangle, values: &[BigRational; 3]) -> Option<Plane> {
        let one = BigRational::from_integer(BigInt::from(1));
        let rows: [[BigRational; 3]; 3] = std::array::from_fn(|k| [t.v[k].x.clone(), t.v[k].y.clone(), one.clone()]);
        let det = det3(&rows);
        if det.is_zero() {
            return None;
        }
        let replaced = |col: usize| -> BigRational {
            let mut m = rows.clone();
            for (k, row) in m.iter_mut().enumerate() {
                row[col] = values[k].clone();
            }
            det3(&m) / &det
        };
        Some(Plane {
            a: replaced(0),
            b: replaced(1),
            c: replaced(2),
        })
    }

    /// The attribute at `p`.
    pub fn eval(&self, p: &Point) -> BigRational {
        &self.a * &p.x + &self.b * &p.y + &self.c
    }
}

fn det3(m: &[[BigRational; 3]; 3]) -> BigRational {
    &m[0][0] * (&m[1][1] * &m[2][2] - &m[1][2] * &m[2][1]) - &m[0][1] * (&m[1][0] * &m[2][2] - &m[1][2] * &m[2][0])
        + &m[0][2] * (&m[1][0] * &m[2][1] - &m[1][1] * &m[2][0])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    /// Hand derivation: for v0=(0,0) v1=(4,0) v2=(0,4), λ1 = x/4 and λ2 = y/4.
    #[test]
    fn barycentrics_by_hand() {
        let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
        let l = barycentric_exact(&t, &Point::from_fractions(1, 2, 3, 2)).unwrap();
        assert_eq!(l, [q(1, 2), q(1, 8), q(3, 8)]);
    }

    /// A plane through c0=0 at (0,0), c1=255 at (4,0), c2=0 at (0,4) is c = 255 x / 4.
    #[test]
    fn plane_by_hand() {
        let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
        let p = Plane::setup(&t, &[q(0, 1), q(255, 1), q(0, 1)]).unwrap();
        assert_eq!(
            p,
            Plane {
                a: q(255, 4),
                b: q(0, 1),
                c: q(0, 1)
            }
        );
        let degenerate = Triangle::new(Point::from_ints(0, 0), Point::from_ints(1, 1), Point::from_ints(2, 2));
        assert!(Plane::setup(&degenerate, &[q(0, 1), q(1, 1), q(2, 1)]).is_none());
    }

    #[test]
    fn channel_rounding() {
        assert_eq!(to_channel(&q(255, 2)), 128); // 127.5 -> even 128
        assert_eq!(to_channel(&q(253, 2)), 126); // 126.5 -> even 126
        assert_eq!(to_channel(&q(-3, 1)), 0);
        assert_eq!(to_channel(&q(999, 1)), 255);
    }
}
