//! The legend of the suite's table: one line for each column, invariant and model label
//! `rasterproof check` prints, so that the table can be read without the source.

use crate::model::Model;

/// The table's columns and the summary's terms, in the order the legend lists them.
pub const TERMS: [(&str, &str); 5] = [
    ("cases", "cases on which the check ran for that model"),
    (
        "violations",
        "cases on which it failed: fatal for the exact and integer models; float: the trade",
    ),
    (
        "skipped",
        "cases on which it could not run (reasons above); cases + skipped = the run's cases",
    ),
    (
        "by family",
        "watertight + agreement (mesh) violations by the case's mesh: random, tie-heavy, far-from-origin",
    ),
    (
        "ulps of 1",
        "|l0 + l1 + l2 - 1| of f32 barycentrics, in f32::EPSILON = 2^-23 (f32's step at 1)",
    ),
];

/// Every invariant of the table.
pub const INVARIANTS: [(&str, &str); 21] = [
    (
        "agreement (fine mesh)",
        "agreement (mesh) on the fine mesh, against exact-plain (float models only)",
    ),
    (
        "agreement (mesh)",
        "the mesh's pixels = the plain oracle's (snapping models: exact-snapped-plain; others: exact-plain)",
    ),
    (
        "agreement (triangle)",
        "the same on the case's random triangle (any family), against the plain oracle",
    ),
    ("barycentric sum", "exact barycentrics at 3 samples sum to exactly 1"),
    (
        "clip agreement",
        "the clipped polygon (rational vertices) drawn by the planned engine = the plain oracle's",
    ),
    (
        "clip inside",
        "every vertex of the clipped polygon lies in the closed window (checked exactly)",
    ),
    (
        "clip raster",
        "raster(clip(P, W)) = raster(P) ∩ raster(W) pixel for pixel (exact oracle)",
    ),
    (
        "diamond agreement",
        "the diamond-exit line = the plain exact reading (of the snapped line, for the snapping models)",
    ),
    (
        "integer edge sum",
        "the i64 edge values at 3 samples sum to exactly twice the snapped triangle's area",
    ),
    (
        "line pixels",
        "max(|dx|,|dy|)+1 pixels end to end, 8-connected, each within 1/2 px of the ideal line",
    ),
    (
        "line pixels (long)",
        "line pixels on a line up to 1000 px long near 0, 2^16, 2^20 or 2^23",
    ),
    (
        "line reference",
        "the pixels = the exact reference: the candidate within 1/2 px, at exact ties the tie convention",
    ),
    (
        "line symmetry",
        "drawn b -> a, the pixels of a -> b, except at exact ties of the ideal line",
    ),
    (
        "polygon agreement",
        "a random polygon's fill (holes, self-intersecting, ties) = the plain oracle's",
    ),
    (
        "rotation/winding",
        "the same pixels with the vertices rotated (v1 v2 v0, v2 v0 v1) and reversed (v0 v2 v1)",
    ),
    (
        "segment clip",
        "the clipped segment is exactly its part inside the rectangle, ends on the segment",
    ),
    (
        "translation",
        "a whole-pixel move (-5..=5 on each axis) moves the coverage by as much",
    ),
    (
        "triangulation",
        "the snapped simple polygon's triangles cover its fill, each pixel once, nothing else",
    ),
    (
        "watertight",
        "a mesh covers each sample inside its outline exactly once, none outside (no gap, overlap)",
    ),
    (
        "watertight (4x)",
        "watertight at each of the standard 4x sample positions (the mesh drawn per sample)",
    ),
    (
        "watertight (fine mesh)",
        "watertight on the fine mesh: near (16336, 16336), a 2^-16 px grid (float models only)",
    ),
];

/// The labels of the table that are not a [`Model::name`] (the algorithm, where several
/// share a model); a model's own name is explained by [`Model::describe`].
pub const LABELS: [(&str, &str); 9] = [
    (
        "bresenham/step",
        "integer Bresenham; a tie steps the minor axis (error term, e >= 0)",
    ),
    (
        "bresenham/stay",
        "integer Bresenham; a tie keeps the minor coordinate (midpoint, d <= 0)",
    ),
    (
        "cohen-sutherland",
        "Cohen-Sutherland segment clipping against a rectangle, exact",
    ),
    ("dda32", "float32's lines: a DDA stepping in f32"),
    ("dda64", "float64's lines: a DDA stepping in f64"),
    ("diamond", "fixed's diamond-exit lines, integer arithmetic"),
    (
        "sh-f32",
        "Sutherland-Hodgman in f32, intersections rounded (a vertex outside: the trade)",
    ),
    (
        "sh-f64",
        "Sutherland-Hodgman in f64, intersections rounded (a vertex outside: the trade)",
    ),
    ("sutherland-hodgman", "Sutherland-Hodgman polygon clipping, exact"),
];

/// The one-line explanation of a term, invariant or label of the table; `None` for a
/// name the legend does not know (a test keeps every name the suite prints known).
///
/// ```
/// use rasterproof::harness::suite::legend::describe;
/// assert_eq!(describe("sh-f32").unwrap(), "Sutherland-Hodgman in f32, intersections rounded (a vertex outside: the trade)");
/// assert!(describe("fixed").unwrap().starts_with("i64 edge functions"));
/// assert_eq!(describe("no such row"), None);
/// ```
pub fn describe(name: &str) -> Option<&'static str> {
    TERMS
        .iter()
        .chain(&INVARIANTS)
        .chain(&LABELS)
        .find(|(n, _)| *n == name)
        .map(|&(_, text)| text)
        .or_else(|| Model::ALL.iter().find(|m| m.name() == name).map(|m| m.describe()))
}
