//! Clip windows: rectangles with tie-heavy bounds (pixel centres, corners, k/512), and
//! strictly convex polygons (convex hulls of random grid points, kept when strictly
//! convex).

use proptest::prelude::*;

use super::{tie_heavy_coordinate, triangulate};
use crate::clip::Window;

/// A rectangle window with tie-heavy bounds in and around a `canvas` x `canvas` target.
pub fn rect_window(canvas: u32) -> BoxedStrategy<Window> {
    prop::array::uniform4(tie_heavy_coordinate(canvas))
        .prop_filter_map("empty rectangle", |[a, b, c, d]| {
            let (xmin, xmax) = if a <= c { (a, c) } else { (c, a) };
            let (ymin, ymax) = if b <= d { (b, d) } else { (d, b) };
            Window::rect(xmin, ymin, xmax, ymax).ok()
        })
        .boxed()
}

/// A strictly convex window: the convex hull of 3..=12 points on the half-pixel grid
/// (tie-heavy) or the 1/256 grid, in and around a `canvas` x `canvas` target.
pub fn convex_window(canvas: u32) -> BoxedStrategy<Window> {
    let side = i64::from(canvas);
    (
        prop::sample::select(vec![1u32, 8]),
        prop::collection::vec(prop::array::uniform2(0i64..1 << 20), 3..=12),
    )
        .prop_filter_map("hull not strictly convex", move |(bits, raw)| {
            let unit = 1i64 << bits;
            let span = (side + 8) * unit;
            let pts: Vec<[i64; 2]> = raw.iter().map(|p| p.map(|v| v % span - 4 * unit)).collect();
            let mesh = triangulate(&pts, bits)?;
            Window::convex(mesh.outline).ok()
        })
        .boxed()
}

/// Either kind.
pub fn any_window(canvas: u32) -> BoxedStrategy<Window> {
    prop_oneof![rect_window(canvas), convex_window(canvas)].boxed()
}
