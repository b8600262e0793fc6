//! Invariance: coverage does not change under vertex rotation or winding reversal, and
//! moves with a translation by whole pixels.

use super::Violation;
use crate::convention::Target;
use crate::geom::Triangle;
use crate::model::{render_triangles, Model, ModelError};

fn rendered(model: Model, t: &Triangle, target: &Target) -> Result<crate::coverage::Coverage, Violation> {
    render_triangles(std::slice::from_ref(t), target, model)
        .map_err(|e: ModelError| Violation::new("invariance", format!("{model} refused the triangle: {e}")))
}

/// `model` covers the same pixels for (v0,v1,v2), (v1,v2,v0), (v2,v0,v1) and (v0,v2,v1).
pub fn check_rotation_and_winding(t: &Triangle, target: &Target, model: Model) -> Result<(), Violation> {
    let base = rendered(model, t, target)?;
    let variants = [
        ("rotated once", t.rotated()),
        ("rotated twice", t.rotated().rotated()),
        ("winding reversed", t.reversed()),
    ];
    for (what, v) in variants {
        let other = rendered(model, &v, target)?;
        let d = super::differing_pixels(&base, &other);
        if let Some(first) = d.first() {
            return Err(Violation::new(
                "invariance",
                format!(
                    "{model}: {what} changes {} pixels; first ({}, {}): {:?} vs {:?}",
                    d.len(),
                    first.x,
                    first.y,
                    first.reference,
                    first.candidate
                ),
            ));
        }
    }
    Ok(())
}

/// Translating `t` by `(dx, dy)` whole pixels translates its coverage, compared where both
/// the pixel and its pre-image are on the canvas.
///
/// Holds exactly for the exact models and for the snapped ones under nearest-even
/// rounding. A translated triangle the model refuses (moved out of its envelope) is no
/// violation: there is nothing to compare, and the result is Ok. Under half-away-from-zero (`cts`) a snapping tie that changes sign is rounded
/// the other way, so a translation across the origin can legitimately move an edge.
pub fn check_translation(t: &Triangle, target: &Target, dx: i64, dy: i64, model: Model) -> Result<(), Violation> {
    let base = rendered(model, t, target)?;
    let Ok(moved) = render_triangles(std::slice::from_ref(&t.translated(dx, dy)), target, model) else {
        return Ok(());
    };
    let (w, h) = (i64::from(target.width), i64::from(target.height));
    let clamp = |v: i64, side: i64| u32::try_from(v.clamp(0, side)).expect("clamped to the canvas");
    let (x0, x1) = (clamp(dx, w), clamp(w + dx, w));
    let (y0, y1) = (clamp(dy, h), clamp(h + dy, h));
    let expected = base.translated(dx, dy).restricted(x0, y0, x1, y1);
    let got = moved.restricted(x0, y0, x1, y1);
    let d = super::differing_pixels(&expected, &got);
    match d.first() {
        None => Ok(()),
        Some(first) => Err(Violation::new(
            "invariance",
            format!(
                "{model}: translation by ({dx}, {dy}) changes {} pixels; first ({}, {}): expected {:?}, got {:?}",
                d.len(),
                first.x,
                first.y,
                first.reference,
                first.candidate
            ),
        )),
    }
}
