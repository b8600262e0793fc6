//! The fill invariants: a triangulation of a polygon covers exactly the polygon's fill,
//! each pixel once.

use super::Violation;
use crate::convention::Target;
use crate::coverage::Coverage;
use crate::fill::polygon::{contour_winding_exact, rasterize_exact};
use crate::geom::{Polygon, Triangle};
use crate::raster::sample_exact;

/// `triangles` (any triangulator's output for `polygon`) cover, by the exact oracle,
/// exactly the samples of the polygon's fill, and no sample twice. The violation names
/// the first bad pixel, the triangles that cover it and the moved sample's winding number.
///
/// ```
/// use rasterproof::check::check_triangulation;
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::geom::{FillRule, Point, Polygon, Triangle};
/// let p = |x, y| Point::from_ints(x, y);
/// let square = Polygon::new(vec![p(0, 0), p(4, 0), p(4, 4), p(0, 4)], FillRule::NonZero);
/// let target = Target::new(4, 4, Convention::default()).unwrap();
/// let good = [Triangle::new(p(0, 0), p(4, 0), p(4, 4)), Triangle::new(p(0, 0), p(4, 4), p(0, 4))];
/// assert!(check_triangulation(&square, &good, &target).is_ok());
/// // Overlapping triangles: the pixels of the overlap are covered twice.
/// let bad = [Triangle::new(p(0, 0), p(4, 0), p(4, 4)), Triangle::new(p(0, 0), p(4, 0), p(0, 4))];
/// assert!(check_triangulation(&square, &bad, &target).is_err());
/// ```
pub fn check_triangulation(polygon: &Polygon, triangles: &[Triangle], target: &Target) -> Result<(), Violation> {
    let mut fill = Coverage::new(target.width, target.height);
    rasterize_exact(polygon, 0, target, &mut fill);
    let mut tiles = Coverage::new(target.width, target.height);
    for (k, t) in triangles.iter().enumerate() {
        let id = u32::try_from(k).map_err(|_| Violation::new("triangulation", "too many triangles"))?;
        crate::tri::exact::rasterize(t, id, target, &mut tiles);
    }
    let mut bad = Vec::new();
    for y in 0..target.height {
        for x in 0..target.width {
            let (inside, owners) = (!fill.owners(x, y).is_empty(), tiles.owners(x, y));
            if owners.len() != usize::from(inside) {
                bad.push((x, y, owners.to_vec(), inside));
            }
        }
    }
    let Some((x, y, owners, inside)) = bad.first() else {
        return Ok(());
    };
    let sample = sample_exact(*x, *y, target);
    let w: Vec<i64> = polygon
        .contours()
        .map(|c| contour_winding_exact(&sample, c, target.convention.tie_rule))
        .collect();
    Err(Violation::new(
        "triangulation",
        format!(
            "{} bad pixels; first ({x}, {y}): covered by triangles {owners:?}, but the polygon's fill ({}, winding numbers {w:?} around the outline and holes at the moved sample) {} it",
            bad.len(),
            polygon.fill_rule.name(),
            if *inside { "contains" } else { "does not contain" }
        ),
    ))
}
