//! The area-coverage invariants, on values a renderer produced (exactly, or in f32 read
//! exactly by [`AreaImage::from_f32`]): values in `[0, 1]`, the values of a shape adding up
//! to its area, and the pieces of a triangulation adding up to the whole, pixel by pixel.

use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use super::Violation;
use crate::area::{AreaImage, Semantics};
use crate::num::exact::{exact_text_short, nearest_f64};

/// `v` as an exact fraction and, beside it, as a decimal.
fn shown(v: &BigRational) -> String {
    match nearest_f64(v) {
        Some(f) => format!("{} (~{f:.9})", exact_text_short(v)),
        None => exact_text_short(v),
    }
}

/// Every value lies in `[0, 1]` (not asked of `unclamped` images, whose overlaps exceed
/// 1). The violation names the first pixel outside and its value.
///
/// ```
/// use num_rational::BigRational;
/// use rasterproof::area::{AreaImage, Semantics};
/// use rasterproof::check::check_area_bounds;
/// let image = |v: BigRational| AreaImage { width: 1, height: 1, semantics: Semantics::True, pixels: vec![(0, 0, v)] };
/// assert!(check_area_bounds(&image(BigRational::new(1.into(), 2.into()))).is_ok());
/// assert!(check_area_bounds(&image(BigRational::new(5.into(), 4.into()))).is_err());
/// ```
pub fn check_area_bounds(image: &AreaImage) -> Result<(), Violation> {
    if image.semantics == Semantics::AccumulatedUnclamped {
        return Ok(());
    }
    match image
        .pixels
        .iter()
        .find(|(_, _, v)| v.is_negative() || *v > BigRational::one())
    {
        None => Ok(()),
        Some((x, y, v)) => Err(Violation::new(
            "area bounds",
            format!("pixel ({x}, {y}) has coverage {}, outside [0, 1]", shown(v)),
        )),
    }
}

/// The values add up to `area`, the exact area of what was drawn (for a shape inside the
/// canvas whose path winds at most once, [`crate::area::path_signed_area`]'s magnitude).
/// The violation gives both sums and their exact difference.
///
/// ```
/// use num_rational::BigRational;
/// use rasterproof::area::{exact, triangle_shape, Semantics};
/// use rasterproof::check::check_area_conservation;
/// use rasterproof::geom::{Point, Triangle};
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(3, 0), Point::from_ints(0, 1));
/// let image = exact::rasterize(&[triangle_shape(&t)], 4, 4, Semantics::True);
/// assert!(check_area_conservation(&image, &BigRational::new(3.into(), 2.into())).is_ok());
/// assert!(check_area_conservation(&image, &BigRational::from_integer(2.into())).is_err());
/// ```
pub fn check_area_conservation(image: &AreaImage, area: &BigRational) -> Result<(), Violation> {
    let total = image.total();
    if total == *area {
        return Ok(());
    }
    Err(Violation::new(
        "area conservation",
        format!(
            "the pixels add up to {}, the area drawn is {}: off by {}",
            shown(&total),
            shown(area),
            shown(&(&total - area))
        ),
    ))
}

/// At every pixel the pieces' values add up to the whole's: a triangulation's triangles
/// drawn one by one against the polygon (or hull) they tile, with no seam and no overlap.
/// The violation names the first pixel that differs, both values, and how many differ.
///
/// # Errors
/// Also when the images' sizes differ.
pub fn check_area_additivity(pieces: &[AreaImage], whole: &AreaImage) -> Result<(), Violation> {
    // The pieces' sum, by (row, column).
    let mut sum: std::collections::BTreeMap<(u32, u32), BigRational> = std::collections::BTreeMap::new();
    for p in pieces {
        if (p.width, p.height) != (whole.width, whole.height) {
            return Err(Violation::new(
                "area additivity",
                format!(
                    "a piece is {}x{}, the whole {}x{}",
                    p.width, p.height, whole.width, whole.height
                ),
            ));
        }
        for (x, y, v) in &p.pixels {
            *sum.entry((*y, *x)).or_insert_with(BigRational::zero) += v;
        }
    }
    let mut first = None;
    let mut count = 0usize;
    for y in 0..whole.height {
        for x in 0..whole.width {
            let s = sum.get(&(y, x)).cloned().unwrap_or_else(BigRational::zero);
            let w = whole.value(x, y);
            if s != w {
                count += 1;
                first.get_or_insert((x, y, s, w));
            }
        }
    }
    match first {
        None => Ok(()),
        Some((x, y, s, w)) => Err(Violation::new(
            "area additivity",
            format!(
                "{count} pixel(s) differ; the first, ({x}, {y}): the pieces add up to {}, the whole is {} ({} {})",
                shown(&s),
                shown(&w),
                if s > w { "overlap" } else { "seam" },
                shown(&(&s - &w).abs())
            ),
        )),
    }
}
