//! Explaining one pixel: the exact edge values of a triangle at its sample.

use std::fmt::Write as _;

use num_traits::{Signed, Zero};

use crate::convention::Target;
use crate::edge::exact::triangle_edges;
use crate::geom::Triangle;
use crate::num::exact::exact_text;
use crate::raster::sample_exact;

/// Why the exact model puts pixel `(x, y)` inside or outside `tri`: the sample, each
/// edge's exact value and inclusive flag, and the verdict.
///
/// ```
/// use rasterproof::check::explain_sample;
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::geom::{Point, Triangle};
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
/// let target = Target::new(4, 4, Convention::default()).unwrap();
/// let why = explain_sample(&t, 1, 2, &target);
/// assert!(why.contains("E=0 (exclusive)"), "{why}");
/// assert!(why.ends_with("-> outside"), "{why}");
/// ```
pub fn explain_sample(tri: &Triangle, x: u32, y: u32, target: &Target) -> String {
    let p = sample_exact(x, y, target);
    let mut s = format!("sample {p}");
    let Some(edges) = triangle_edges(tri, target.convention.tie_rule) else {
        s.push_str(": zero-area triangle -> outside");
        return s;
    };
    let mut inside = true;
    for (k, e) in edges.iter().enumerate() {
        let v = e.value(&p);
        let flag = if e.inclusive { "inclusive" } else { "exclusive" };
        let ok = v.is_positive() || (v.is_zero() && e.inclusive);
        inside &= ok;
        let _ = write!(s, "; edge {k}: E={} ({flag})", exact_text(&v));
    }
    s.push_str(if inside { " -> inside" } else { " -> outside" });
    s
}
