//! Invariant checkers. Each `check_*` returns `Result<(), Violation>`; the violation
//! explains the failure exactly (pixel, triangle, exact edge values). Public and always
//! compiled: they are what users run on their own rasterizers' output.

mod agreement;
mod area;
mod barycentric;
mod clip;
mod explain;
mod fill;
mod invariance;
mod line;
mod values;
mod watertight;

use std::fmt;

pub use agreement::{check_agreement, differing_pixels, PixelDiff};
pub use area::{check_area_additivity, check_area_bounds, check_area_conservation};
pub use barycentric::{check_barycentric_exact, check_barycentric_fixed, float_sum_error_ulps};
pub use clip::{check_clip_raster, check_inside, check_segment_clip, inside_interval};
pub use explain::{
    explain_sample, segment_distance2, triangle_at, triangle_covers, EdgeAt, Side, TriangleAt, DYADIC_BITS,
    DYADIC_LIMIT_BITS,
};
pub use fill::check_triangulation;
pub use invariance::{check_rotation_and_winding, check_translation};
pub use line::{
    check_diamond_agreement, check_line_pixels, check_line_reference, check_line_symmetry, line_departures,
    SymmetryReport,
};
pub use values::{
    check_values_flat, check_values_hull, check_values_rotation, check_values_shared_edge, check_values_translation,
};
pub use watertight::{check_no_double_cover, check_watertight, check_watertight_samples};

/// A broken invariant, with an exact explanation.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Violation {
    /// Which invariant (`"watertight"`, `"agreement"`, ...).
    pub invariant: &'static str,
    /// What exactly went wrong.
    pub message: String,
}

impl Violation {
    /// A violation of `invariant` (a short name such as `"watertight"`), explained by
    /// `message`.
    ///
    /// ```
    /// use rasterproof::check::Violation;
    /// let v = Violation::new("watertight", "pixel (3, 4) covered twice");
    /// assert_eq!(v.to_string(), "watertight violated: pixel (3, 4) covered twice");
    /// ```
    pub fn new(invariant: &'static str, message: impl Into<String>) -> Violation {
        Violation {
            invariant,
            message: message.into(),
        }
    }
}

impl fmt::Display for Violation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} violated: {}", self.invariant, self.message)
    }
}

impl std::error::Error for Violation {}
