//! Float edge functions with glam, Scratchapixel style: the fast, inexact end
//! of the trade. Each product and difference rounds; the harness measures what that costs.

use std::cmp::Ordering;

use glam::{DVec2, Vec2};

use crate::convention::TieRule;

/// `E(p)` for the edge `a -> b` in f32, evaluated as written (no fused multiply-add).
pub fn edge_f32(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    (p.x - a.x) * (b.y - a.y) - (p.y - a.y) * (b.x - a.x)
}

/// `E(p)` for the edge `a -> b` in f64, evaluated as written.
pub fn edge_f64(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    (p.x - a.x) * (b.y - a.y) - (p.y - a.y) * (b.x - a.x)
}

fn sign(v: f64) -> Ordering {
    v.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
}

/// The inclusive flag of the edge `a -> b` from the float edge vector (f32 values widen
/// to f64 exactly).
pub fn is_inclusive(a: [f64; 2], b: [f64; 2], rule: TieRule) -> bool {
    rule.is_inclusive(sign(b[0] - a[0]), sign(b[1] - a[1]))
}
