//! The convention a hunt states in its scenes when it follows a fit of their renderer's
//! output ([`hunt_convention`], [`preferred`]).

use crate::convention::{AnyTieRule, PixelCentre, TieRule};
use crate::model::Model;
use crate::oracle::fit::Candidate;
use crate::scene::Overrides;

/// The convention a fit names, as scene overrides and the oracle model, when hunt can
/// state it in a scene file: a top-left or bottom-left rule and 1..=16 bits (the oracle
/// `exact-snapped`) or no snapping (`exact`).
pub fn hunt_convention(c: &Candidate) -> Option<(Overrides, Model)> {
    let tie_rule = match c.tie_rule {
        AnyTieRule::TopLeft => TieRule::TopLeft,
        AnyTieRule::BottomLeft => TieRule::BottomLeft,
        _ => return None,
    };
    let mut o = Overrides {
        tie_rule: Some(tie_rule),
        pixel_centre: Some(c.pixel_centre),
        ..Overrides::default()
    };
    match c.snapping.bits {
        None => Some((o, Model::Exact)),
        Some(0) => None,
        Some(b) => {
            o.subpixel_bits = Some(b);
            o.rounding = Some(c.snapping.rounding);
            Some((o, Model::ExactSnapped))
        }
    }
}

/// The fit hunt prefers among exact ones: one it can state ([`hunt_convention`]), at the
/// usual 8 bits or else the most bits, nearest-even, pixel centre 0.5, top-left.
pub fn preferred(exact: &[Candidate]) -> Option<Candidate> {
    exact
        .iter()
        .copied()
        .filter(|c| hunt_convention(c).is_some())
        .min_by_key(|c| {
            let bits = c
                .snapping
                .bits
                .map_or(17, |b| if b == 8 { 0 } else { 17 - i64::from(b) });
            (
                bits,
                c.snapping.rounding != crate::num::Rounding::NearestEven,
                c.pixel_centre != PixelCentre::Half,
                c.tie_rule != AnyTieRule::TopLeft,
            )
        })
}
