//! Integer edge functions over i64 subpixels, inside the envelope of
//! [`crate::num::fixed`] (every value below 2^62 in magnitude, so no operation here can
//! overflow; the test profile keeps overflow checks on to prove it).

use crate::convention::TieRule;
use crate::geom::FixedTriangle;

/// `E(p)` for the edge `a -> b` in subpixel units; `[x, y]` pairs inside the envelope.
#[inline]
pub fn edge_function(a: [i64; 2], b: [i64; 2], p: [i64; 2]) -> i64 {
    (p[0] - a[0]) * (b[1] - a[1]) - (p[1] - a[1]) * (b[0] - a[0])
}

/// `E(p)` in i128, for points beyond the i64 envelope (a sample of any `u32` pixel, a
/// scaled contour): exact while every coordinate is below 2^62 in magnitude.
pub fn edge_function_wide(a: [i128; 2], b: [i128; 2], p: [i128; 2]) -> i128 {
    (p[0] - a[0]) * (b[1] - a[1]) - (p[1] - a[1]) * (b[0] - a[0])
}

/// One edge of an oriented fixed-point triangle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FixedEdge {
    /// The start vertex `[x, y]`.
    pub a: [i64; 2],
    /// `b.x - a.x`.
    pub dx: i64,
    /// `b.y - a.y`.
    pub dy: i64,
    /// 0 on an inclusive edge, 1 otherwise: a sample is inside when `E - bias >= 0`
    /// (for integers, `E > 0 || (E == 0 && inclusive)` is exactly that).
    pub bias: i64,
}

impl FixedEdge {
    /// The edge `a -> b` of a triangle whose interior is `E > 0`.
    #[inline]
    pub fn new(a: [i64; 2], b: [i64; 2], rule: TieRule) -> FixedEdge {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let inclusive = rule.is_inclusive(dx.cmp(&0), dy.cmp(&0));
        FixedEdge {
            a,
            dx,
            dy,
            bias: if inclusive { 0 } else { 1 },
        }
    }

    /// `E(p) - bias`: the sample is inside this edge when it is `>= 0`.
    pub fn biased_value(&self, p: [i64; 2]) -> i64 {
        (p[0] - self.a[0]) * self.dy - (p[1] - self.a[1]) * self.dx - self.bias
    }
}

/// Twice the signed area, `E_{v0 v1}(v2)`.
#[inline]
pub fn area2(t: &FixedTriangle) -> i64 {
    let v = t.coords();
    edge_function(v[0], v[1], v[2])
}

/// The three edges of the oriented triangle (v1, v2 swapped if needed so the interior is
/// `E > 0`); `None` for zero area.
#[inline]
pub fn triangle_edges(t: &FixedTriangle, rule: TieRule) -> Option<[FixedEdge; 3]> {
    let [a, mut b, mut c] = t.coords();
    match area2(t).cmp(&0) {
        std::cmp::Ordering::Equal => return None,
        std::cmp::Ordering::Less => std::mem::swap(&mut b, &mut c),
        std::cmp::Ordering::Greater => {}
    }
    Some([
        FixedEdge::new(a, b, rule),
        FixedEdge::new(b, c, rule),
        FixedEdge::new(c, a, rule),
    ])
}
