//! The clip volume's six planes and exact clipping against them in clip space.

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::{rational, ClipVertex, DepthRange};
use crate::clip::sutherland_hodgman::merged;

/// The six clip planes as small integer 4-vectors `p`, inside where `p . (x, y, z, w) >= 0`,
/// in the order they are applied: `x >= -w`, `x <= w`, `y >= -w`, `y <= w`, near, far.
///
/// ```
/// use rasterproof::clip::homogeneous::{clip_planes, DepthRange};
/// // GL's near plane z >= -w is z + w >= 0; D3D's is z >= 0; both far planes are z <= w.
/// assert_eq!(clip_planes(DepthRange::MinusOneToOne)[4], [0, 0, 1, 1]);
/// assert_eq!(clip_planes(DepthRange::ZeroToOne)[4], [0, 0, 1, 0]);
/// assert_eq!(clip_planes(DepthRange::ZeroToOne)[5], [0, 0, -1, 1]);
/// ```
pub fn clip_planes(depth: DepthRange) -> [[i8; 4]; 6] {
    let near = match depth {
        DepthRange::ZeroToOne => [0, 0, 1, 0],
        DepthRange::MinusOneToOne => [0, 0, 1, 1],
    };
    [
        [1, 0, 0, 1],
        [-1, 0, 0, 1],
        [0, 1, 0, 1],
        [0, -1, 0, 1],
        near,
        [0, 0, -1, 1],
    ]
}

impl ClipVertex {
    /// `p . pos`: the vertex's signed distance (scaled) to plane `p`; inside when `>= 0`.
    pub fn plane_distance(&self, plane: &[i8; 4]) -> BigRational {
        plane
            .iter()
            .zip(&self.pos)
            .map(|(&c, x)| rational(i64::from(c)) * x)
            .fold(BigRational::zero(), |acc, v| acc + v)
    }

    /// Whether the vertex is inside the clip volume, boundary included.
    ///
    /// ```
    /// use rasterproof::clip::homogeneous::{ClipVertex, DepthRange};
    /// // z = -1, w = 2: inside GL's -w <= z, outside D3D's 0 <= z.
    /// let v = ClipVertex::from_ints([2, -2, -1, 2], &[]);
    /// assert!(v.inside(DepthRange::MinusOneToOne));
    /// assert!(!v.inside(DepthRange::ZeroToOne));
    /// ```
    pub fn inside(&self, depth: DepthRange) -> bool {
        clip_planes(depth).iter().all(|p| !self.plane_distance(p).is_negative())
    }

    /// `self + t (other - self)`, position and attributes.
    fn lerp(&self, other: &ClipVertex, t: &BigRational) -> ClipVertex {
        let mix = |a: &BigRational, b: &BigRational| a + t * (b - a);
        ClipVertex {
            pos: std::array::from_fn(|k| mix(&self.pos[k], &other.pos[k])),
            attrs: self.attrs.iter().zip(&other.attrs).map(|(a, b)| mix(a, b)).collect(),
        }
    }
}

/// `poly` (a triangle or any polygon, vertices in order) clipped against the clip volume,
/// exactly: Sutherland-Hodgman against the six [`clip_planes`] in turn, the four in/out
/// cases of [`sutherland_hodgman`](crate::clip::sutherland_hodgman), repeated consecutive vertices merged. Empty when
/// nothing is inside. Every output vertex is inside the volume, so it has `w > 0` or is
/// the eye `(0, 0, 0, 0)` (a primitive through the eye is seen edge-on).
///
/// ```
/// use rasterproof::clip::homogeneous::{clip_exact, ClipVertex, DepthRange};
/// // The triangle (0,0) (4,0) (0,4) at w = 2 (attribute = x) against x <= 2 and y <= 2:
/// // x + y <= 4 holds on all of [0,2]^2, so the square is left. x <= w cuts the edges at
/// // t = 1/2, giving (2,0) and (2,2); y <= w then cuts (0,4) -> (0,0) at (0,2), emitted
/// // first (out -> in at the first vertex), and (2,2) -> (0,4) at t = 0, merged with (2,2).
/// let v = |x, y| ClipVertex::from_ints([x, y, 0, 2], &[x]);
/// let out = clip_exact(&[v(0, 0), v(4, 0), v(0, 4)], DepthRange::ZeroToOne);
/// assert_eq!(out, vec![v(0, 2), v(0, 0), v(2, 0), v(2, 2)]);
/// ```
pub fn clip_exact(poly: &[ClipVertex], depth: DepthRange) -> Vec<ClipVertex> {
    let mut poly = poly.to_vec();
    for plane in clip_planes(depth) {
        let n = poly.len();
        let mut out = Vec::with_capacity(n + 2);
        for (k, e) in poly.iter().enumerate() {
            let s = &poly[(k + n - 1) % n];
            let (ds, de) = (s.plane_distance(&plane), e.plane_distance(&plane));
            let (s_in, e_in) = (!ds.is_negative(), !de.is_negative());
            if s_in != e_in {
                // one side >= 0, the other < 0: ds != de
                let t = &ds / (&ds - &de);
                out.push(s.lerp(e, &t));
            }
            if e_in {
                out.push(e.clone());
            }
        }
        poly = merged(out);
    }
    poly
}
