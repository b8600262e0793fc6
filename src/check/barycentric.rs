//! The barycentric invariant: barycentrics sum to exactly 1 (exact); integer edge values sum to twice the
//! area (fixed); float sums are off by a measured number of ulps.

use num_traits::One;

use super::Violation;
use crate::convention::Target;
use crate::geom::{FixedTriangle, Point, Triangle};
use crate::interp::{barycentric_exact, barycentric_f32, barycentric_fixed};
use crate::num::exact::exact_text;

/// The exact barycentrics of `p` sum to exactly 1 (zero-area triangles have none: Ok).
pub fn check_barycentric_exact(t: &Triangle, p: &Point) -> Result<(), Violation> {
    let Some(l) = barycentric_exact(t, p) else {
        return Ok(());
    };
    let sum = &l[0] + &l[1] + &l[2];
    if sum.is_one() {
        Ok(())
    } else {
        Err(Violation::new(
            "barycentric sum",
            format!(
                "at {p}: {} + {} + {} = {}",
                exact_text(&l[0]),
                exact_text(&l[1]),
                exact_text(&l[2]),
                exact_text(&sum)
            ),
        ))
    }
}

/// The integer edge values at the sample of `(x, y)` sum to exactly twice the area.
pub fn check_barycentric_fixed(t: &FixedTriangle, x: u32, y: u32, target: &Target) -> Result<(), Violation> {
    let b = barycentric_fixed(t, x, y, target);
    let sum = b.w[0] + b.w[1] + b.w[2];
    if sum == b.area2 {
        Ok(())
    } else {
        Err(Violation::new(
            "integer edge sum",
            format!("pixel ({x}, {y}): w = {:?}, sum {sum} != 2*area {}", b.w, b.area2),
        ))
    }
}

/// How far the f32 barycentrics of `p` sum from 1, in ulps of 1 (f32::EPSILON); `None`
/// when the triangle does not fit f32 or its float area is 0.
pub fn float_sum_error_ulps(t: &Triangle, p: &Point) -> Option<f64> {
    let tf = t.to_f32()?;
    let pf = p.to_f32()?;
    let l = barycentric_f32(&tf, pf)?;
    let sum = f64::from(l[0]) + f64::from(l[1]) + f64::from(l[2]);
    Some((sum - 1.0).abs() / f64::from(f32::EPSILON))
}
