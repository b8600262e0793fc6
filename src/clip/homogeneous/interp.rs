//! Perspective-correct interpolation over a window-space triangle, exactly.

use num_rational::BigRational;
use num_traits::Zero;

use super::WindowVertex;
use crate::geom::{Point, Triangle};
use crate::interp::barycentric_exact;

/// The vertex at window point `p` of the window-space triangle `tri`, perspective-correct:
/// with window-space barycentrics `b_i`, depth `Σ b_i z_i` and `1/w = Σ b_i / w_i` (both
/// affine in window space), attribute `a = Σ b_i a_i / w_i / Σ b_i / w_i`. `None` when
/// the triangle has zero area, or at a `p` outside it where `Σ b_i / w_i = 0` (the horizon).
///
/// ```
/// use rasterproof::clip::homogeneous::{interpolate_exact, WindowVertex};
/// use rasterproof::geom::Point;
/// let q = |n: i64, d: i64| num_rational::BigRational::new(n.into(), d.into());
/// let v = |x, y, w, a| WindowVertex { point: Point::from_ints(x, y), z: q(0, 1), inv_w: q(1, w), attrs: vec![q(a, 1)] };
/// // Attribute 0 at w = 1, 1 at w = 3. At the screen midpoint b = (1/2, 1/2, 0):
/// // (1/2 * 1/3) / (1/2 + 1/2 * 1/3) = 1/4, not the affine 1/2.
/// let tri = [v(0, 0, 1, 0), v(4, 0, 3, 1), v(0, 4, 1, 0)];
/// let mid = interpolate_exact(&tri, &Point::from_ints(2, 0)).unwrap();
/// assert_eq!(mid.attrs, vec![q(1, 4)]);
/// assert_eq!(mid.inv_w, q(2, 3));
/// ```
pub fn interpolate_exact(tri: &[WindowVertex; 3], p: &Point) -> Option<WindowVertex> {
    let screen = Triangle::new(tri[0].point.clone(), tri[1].point.clone(), tri[2].point.clone());
    let b = barycentric_exact(&screen, p)?;
    let affine = |value: &dyn Fn(&WindowVertex) -> BigRational| -> BigRational {
        (0..3).fold(BigRational::zero(), |acc, i| acc + &b[i] * value(&tri[i]))
    };
    let inv_w = affine(&|v| v.inv_w.clone());
    if inv_w.is_zero() {
        return None;
    }
    let count = tri.iter().map(|v| v.attrs.len()).min().unwrap_or(0);
    let attrs = (0..count)
        .map(|k| affine(&|v| &v.attrs[k] * &v.inv_w) / &inv_w)
        .collect();
    Some(WindowVertex {
        point: p.clone(),
        z: affine(&|v| v.z.clone()),
        inv_w,
        attrs,
    })
}
