//! Polygon strategies: star-shaped simple polygons (optionally with a hole), tangled
//! (self-intersecting) ones, stellated ones like the pentagram, and tie-heavy versions on
//! the half-pixel grid. Integer arithmetic only (no trigonometry), so a persisted case
//! replays identically everywhere.
//!
//! A star-shaped polygon is built around a centre: vertex `k` of `n` lies in the `k`-th
//! of `n` equal sectors of a square's perimeter, at a random distance. For `n >= 5`
//! consecutive vertices are less than 136° apart seen from the centre, so the polygon is
//! simple and keeps a disc of radius `0.37 r_min` around the centre free of its edges;
//! the hole is drawn inside `0.2 r_min * sqrt(2)`. Rounding to the grid can still make a
//! tiny polygon degenerate: tests that need a simple polygon check it with
//! [`crate::fill::triangulate::validate`] and reject the rare case.

use proptest::prelude::*;

use super::{grid_point, GRID};
use crate::fill::polygon::{locate_exact, Location};
use crate::geom::{FillRule, Point, Polygon};

/// Resolution of the direction square (half-side, in its own units).
const HALF: i64 = 1 << 20;

/// The point at perimeter parameter `t` in `[0, 8 HALF)` of the square of half-side
/// `HALF`: monotone in angle around the centre.
fn square_perimeter(t: i64) -> [i64; 2] {
    let s = 2 * HALF;
    match t / s {
        0 => [HALF, -HALF + t],
        1 => [HALF - (t - s), HALF],
        2 => [-HALF, HALF - (t - 2 * s)],
        _ => [-HALF + (t - 3 * s), -HALF],
    }
}

/// Rounds `v` to a multiple of `quantum` (subpixels).
fn quantised(v: i64, quantum: i64) -> i64 {
    (v + quantum / 2).div_euclid(quantum) * quantum
}

/// Star-shaped contour around `centre` (subpixels): one vertex per sector `(u, f)` with
/// `u` in 0..1024 (position in the sector) and `f` in 1..=1024 (radius `f/1024 * radius`).
fn star_contour(centre: [i64; 2], radius: i64, sectors: &[(i64, i64)], quantum: i64) -> Vec<Point> {
    let n = i64::try_from(sectors.len()).expect("few vertices");
    sectors
        .iter()
        .zip(0..)
        .map(|(&(u, f), k)| {
            let t = (k * 1024 + u) * 8 * HALF / (n * 1024);
            let d = square_perimeter(t);
            let r = radius * f / 1024;
            let v = [0, 1].map(|a| quantised(centre[a] + d[a] * r / HALF, quantum));
            grid_point(v[0], v[1])
        })
        .collect()
}

fn fill_rule() -> BoxedStrategy<FillRule> {
    prop_oneof![Just(FillRule::NonZero), Just(FillRule::EvenOdd)].boxed()
}

/// Sector parameters for `n` vertices, radii between a quarter and the whole radius.
fn sectors(n: std::ops::RangeInclusive<usize>) -> BoxedStrategy<Vec<(i64, i64)>> {
    prop::collection::vec((0i64..1024, 256i64..=1024), n).boxed()
}

/// A star-shaped simple polygon on a `canvas` x `canvas` target (its centre on the canvas,
/// its radius up to the canvas side, so it often leaves the canvas), 3..=`max_vertices`
/// vertices, on the grid of `quantum` subpixels (`GRID`ths of a pixel); with
/// `with_hole`, polygons of 5 or more vertices get a star-shaped hole around the centre.
pub fn star_polygon(canvas: u32, max_vertices: usize, with_hole: bool, quantum: i64) -> BoxedStrategy<Polygon> {
    let c = i64::from(canvas) * GRID;
    (
        prop::array::uniform2(0..c),
        GRID..=c,
        sectors(3..=max_vertices.max(3)),
        sectors(3..=6),
        fill_rule(),
    )
        .prop_map(move |(centre, radius, outer, inner, rule)| {
            let mut poly = Polygon::new(star_contour(centre, radius, &outer, quantum), rule);
            if with_hole && outer.len() >= 5 {
                let r_min = outer
                    .iter()
                    .map(|&(_, f)| radius * f / 1024)
                    .min()
                    .expect("3+ vertices");
                poly.holes.push(star_contour(centre, r_min / 5, &inner, quantum));
            }
            poly
        })
        .boxed()
}

/// A tangled polygon: 3..=`max_vertices` random grid points in random order (it usually
/// crosses itself), around and beyond a `canvas` x `canvas` target.
pub fn tangled_polygon(canvas: u32, max_vertices: usize, quantum: i64) -> BoxedStrategy<Polygon> {
    let c = i64::from(canvas) * GRID;
    (
        prop::collection::vec(prop::array::uniform2(-c / 4..c + c / 4), 3..=max_vertices.max(3)),
        fill_rule(),
    )
        .prop_map(move |(pts, rule)| {
            let outline = pts
                .iter()
                .map(|p| grid_point(quantised(p[0], quantum), quantised(p[1], quantum)))
                .collect();
            Polygon::new(outline, rule)
        })
        .boxed()
}

/// A stellated polygon like the pentagram: a star-shaped contour of an odd number (5..=9)
/// of vertices visited every second vertex, so its centre winds twice.
pub fn stellated_polygon(canvas: u32, quantum: i64) -> BoxedStrategy<Polygon> {
    star_polygon(canvas, 9, false, quantum)
        .prop_filter_map("needs an odd vertex count", |star| {
            let n = star.outline.len();
            (n >= 5 && n % 2 == 1).then(|| {
                let outline = (0..n).map(|k| star.outline[(2 * k) % n].clone()).collect();
                Polygon::new(outline, star.fill_rule)
            })
        })
        .boxed()
}

/// A tangled outline with a tangled hole: both contours random points in random order
/// (the hole smaller, around the same area), so they cross themselves and each other.
/// The hole starts at one of its vertices that is not outside the outline (as scene files
/// require), or is left out when it has none.
pub fn tangled_with_hole(canvas: u32, max_vertices: usize, quantum: i64) -> BoxedStrategy<Polygon> {
    (
        tangled_polygon(canvas, max_vertices, quantum),
        tangled_polygon(canvas / 2, 6, quantum),
    )
        .prop_map(move |(mut outline, hole)| {
            let shift = i64::from(canvas / 4);
            let mut hole = hole.translated(shift, shift).outline;
            // Scene files refuse a hole whose first vertex lies outside the outline: start
            // the hole at a vertex inside it, or leave the hole out.
            let inside = |p: &Point| locate_exact(p, &outline.outline) != Location::Outside;
            if let Some(k) = hole.iter().position(inside) {
                hole.rotate_left(k);
                outline.holes.push(hole);
            }
            outline
        })
        .boxed()
}

/// Simple polygons (star-shaped, with and without a hole, on the grid and on the
/// tie-heavy half-pixel grid), up to `max_vertices` vertices.
pub fn simple_polygon(canvas: u32, max_vertices: usize) -> BoxedStrategy<Polygon> {
    prop_oneof![
        star_polygon(canvas, max_vertices, false, 1),
        star_polygon(canvas, max_vertices, true, 1),
        star_polygon(canvas, max_vertices, true, GRID / 2),
    ]
    .boxed()
}

/// Any polygon: the simple families, tangled and stellated ones, tangled ones with a
/// tangled hole, tie-heavy versions.
pub fn any_polygon(canvas: u32, max_vertices: usize) -> BoxedStrategy<Polygon> {
    prop_oneof![
        simple_polygon(canvas, max_vertices),
        tangled_polygon(canvas, max_vertices, 1),
        tangled_polygon(canvas, max_vertices, GRID / 2),
        stellated_polygon(canvas, 1),
        stellated_polygon(canvas, GRID / 2),
        tangled_with_hole(canvas, max_vertices, 1),
        tangled_with_hole(canvas, max_vertices, GRID / 2),
    ]
    .boxed()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The direction square is walked monotonically: consecutive parameters turn the same
    /// way around the centre (cross product of the directions never negative).
    #[test]
    fn square_perimeter_is_monotone_in_angle() {
        let step = HALF / 16;
        let mut prev = square_perimeter(0);
        let mut t = step;
        while t < 8 * HALF {
            let p = square_perimeter(t);
            let cross = i128::from(prev[0]) * i128::from(p[1]) - i128::from(prev[1]) * i128::from(p[0]);
            assert!(cross > 0, "t {t}: {prev:?} -> {p:?}");
            prev = p;
            t += step;
        }
    }
}
