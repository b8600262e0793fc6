//! The oracle: a plain loop over the pixels of the bounding box, three exact rational
//! edge functions per sample, and the tie rule's inclusive flag per edge. Written to be
//! read, not to be fast; every other model is proven equal to it.

use crate::convention::Target;
use crate::coverage::samples::SampleCoverage;
use crate::coverage::CoverageSink;
use crate::edge::exact::triangle_edges;
use crate::geom::Triangle;
use crate::pattern::SamplePattern;
use crate::raster::{exact_pixel_range, exact_sample_range, ExactGrid};

/// Covers every pixel whose sample is inside `tri` under `target`'s convention.
///
/// Run it on a scene's triangles as written (model `exact`) or on their snapped form
/// (model `exact-snapped`, `triangle.snapped(..).to_exact()`).
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::coverage::Coverage;
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::tri::exact::rasterize;
/// // (0,0) (4,0) (0,4) on a 4x4 canvas, samples at pixel centres:
/// //   ####      The hypotenuse x + y = 4 passes through the samples (0.5,3.5),
/// //   ###.      (1.5,2.5), (2.5,1.5), (3.5,0.5); it is a right edge, so they are out.
/// //   ##..
/// //   #...
/// let t = Triangle::new(Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
/// let target = Target::new(4, 4, Convention::default()).unwrap();
/// let mut c = Coverage::new(4, 4);
/// rasterize(&t, 0, &target, &mut c);
/// assert_eq!(c.covered_pixels(), 4 + 3 + 2 + 1 - 4);
/// assert_eq!(c.owners(0, 0), &[0]);
/// assert!(c.owners(3, 0).is_empty());
/// ```
pub fn rasterize<S: CoverageSink + ?Sized>(tri: &Triangle, id: u32, target: &Target, sink: &mut S) {
    let Some(edges) = triangle_edges(tri, target.convention.tie_rule) else {
        return; // zero area: covers nothing
    };
    let Some(range) = exact_sample_range(tri.v.iter(), target) else {
        return;
    };
    let grid = ExactGrid::of(target);
    for j in range.y0..=range.y1 {
        for i in range.x0..=range.x1 {
            let sample = grid.sample(i, j);
            if edges.iter().all(|e| e.contains(&sample)) {
                sink.cover(i, j, id);
            }
        }
    }
}

/// Covers every sample of `pattern` inside `tri` under `target`'s tie rule: sample `s` of
/// pixel `(i, j)` is the exact point `(i + x_s, j + y_s)` ([`SamplePattern::sample`]),
/// tested as [`rasterize`] tests a pixel's one sample. The plain per-sample oracle.
///
/// ```
/// use rasterproof::convention::{Convention, Target};
/// use rasterproof::coverage::samples::SampleCoverage;
/// use rasterproof::geom::{Point, Triangle};
/// use rasterproof::pattern::SamplePattern;
/// use rasterproof::tri::exact::rasterize_samples;
/// // The half plane left of x = 1/2 (a large triangle): of the standard 4x samples
/// // (3/8, 1/8) (7/8, 3/8) (1/8, 5/8) (5/8, 7/8) of pixel (0, 0), samples 0 and 2.
/// let t = Triangle::new(Point::from_ints(-8, -8), Point::from_fractions(1, 2, -8, 1), Point::from_fractions(1, 2, 8, 1));
/// let target = Target::new(1, 1, Convention::default()).unwrap();
/// let four = SamplePattern::standard(4).unwrap();
/// let mut c = SampleCoverage::new(1, 1, 4);
/// rasterize_samples(&t, 0, &target, &four, &mut c);
/// assert_eq!(c.mask(0, 0), 0b0101);
/// ```
pub fn rasterize_samples(tri: &Triangle, id: u32, target: &Target, pattern: &SamplePattern, sink: &mut SampleCoverage) {
    let Some(edges) = triangle_edges(tri, target.convention.tie_rule) else {
        return; // zero area: covers nothing
    };
    let Some(range) = exact_pixel_range(tri.v.iter(), target) else {
        return;
    };
    for j in range.y0..=range.y1 {
        for i in range.x0..=range.x1 {
            for s in 0..pattern.len() {
                let sample = pattern.sample(i, j, s);
                if edges.iter().all(|e| e.contains(&sample)) {
                    sink.cover(i, j, s, id);
                }
            }
        }
    }
}
