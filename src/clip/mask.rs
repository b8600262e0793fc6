//! A clip window as a per-row pixel mask, and a sink that applies it (a scissor). For
//! areas (triangles, polygons) the mask is `raster(W)`: the window filled as a polygon,
//! samples on its boundary decided by the tie rule, so that masking a model's coverage
//! equals clipping the primitive exactly and then rasterizing it
//! (`raster(clip(P, W)) == raster(P) ∩ raster(W)`, see [`crate::clip`]). For line pixels
//! the mask is the closed window: a pixel is kept when its sample lies in the window or
//! on its boundary (point clipping against the window's half-planes).

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::Window;
use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::fill::polygon::rasterize_rows_exact;
use crate::geom::{FillRule, Polygon};
use crate::raster::ExactGrid;

/// For each row, the inclusive pixel span inside the window (a convex window meets a row
/// in one interval), or `None`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ClipMask {
    rows: Vec<Option<(u32, u32)>>,
}

/// Collects the spans of one primitive, one per row.
struct Spans<'a>(&'a mut Vec<Option<(u32, u32)>>);

impl CoverageSink for Spans<'_> {
    fn cover(&mut self, x: u32, y: u32, id: u32) {
        self.cover_span(y, x, x, id);
    }

    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, _id: u32) {
        let row = &mut self.0[y as usize];
        *row = Some(match *row {
            None => (x0, x1),
            Some((a, b)) => (a.min(x0), b.max(x1)),
        });
    }
}

impl ClipMask {
    /// `raster(W)`: the pixels whose moved sample lies inside the window (the tie rule's
    /// reading of its boundary), computed exactly row by row.
    pub fn for_areas(window: &Window, target: &Target) -> ClipMask {
        let mut rows = vec![None; target.height as usize];
        let poly = Polygon::new(window.outline(), FillRule::NonZero);
        rasterize_rows_exact(&poly, 0, target, &mut Spans(&mut rows));
        ClipMask { rows }
    }

    /// The pixels whose sample lies in the closed window, computed exactly row by row:
    /// each half-plane `a x + b y + c >= 0` bounds the row's x from one side.
    pub fn for_points(window: &Window, target: &Target) -> ClipMask {
        let planes = window.half_planes();
        let grid = ExactGrid::of(target);
        let rows = (0..target.height)
            .map(|j| {
                let y = grid.coordinate(j);
                let (mut lo, mut hi): (Option<BigRational>, Option<BigRational>) = (None, None);
                for h in &planes {
                    let rest = &h.b * &y + &h.c; // a x + rest >= 0
                    if h.a.is_zero() {
                        if rest.is_negative() {
                            return None;
                        }
                        continue;
                    }
                    let bound = -rest / &h.a;
                    if h.a.is_positive() {
                        lo = Some(lo.map_or(bound.clone(), |l| l.max(bound)));
                    } else {
                        hi = Some(hi.map_or(bound.clone(), |u| u.min(bound)));
                    }
                }
                // pixel i: lo <= i + c <= hi
                let first = lo.map_or(0, |l| grid.first_at_or_after(&l).max(0));
                let last = hi.map_or(i64::from(target.width) - 1, |u| {
                    grid.last_at_or_before(&u).min(i64::from(target.width) - 1)
                });
                (first <= last).then(|| {
                    (
                        u32::try_from(first).expect("clamped to the canvas"),
                        u32::try_from(last).expect("clamped to the canvas"),
                    )
                })
            })
            .collect();
        ClipMask { rows }
    }

    /// Whether pixel `(x, y)` is inside.
    pub fn contains(&self, x: u32, y: u32) -> bool {
        self.rows
            .get(y as usize)
            .copied()
            .flatten()
            .is_some_and(|(a, b)| a <= x && x <= b)
    }

    /// Wraps `sink` so that only pixels inside the mask reach it.
    pub fn scissor<'a, S: CoverageSink + ?Sized>(&'a self, sink: &'a mut S) -> Scissored<'a, S> {
        Scissored { mask: self, sink }
    }
}

/// A sink that forwards only the pixels inside a [`ClipMask`].
pub struct Scissored<'a, S: CoverageSink + ?Sized> {
    mask: &'a ClipMask,
    sink: &'a mut S,
}

impl<S: CoverageSink + ?Sized> CoverageSink for Scissored<'_, S> {
    fn cover(&mut self, x: u32, y: u32, id: u32) {
        if self.mask.contains(x, y) {
            self.sink.cover(x, y, id);
        }
    }

    fn cover_span(&mut self, y: u32, x0: u32, x1: u32, id: u32) {
        if let Some(Some((a, b))) = self.mask.rows.get(y as usize) {
            let (lo, hi) = (x0.max(*a), x1.min(*b));
            if lo <= hi {
                self.sink.cover_span(y, lo, hi, id);
            }
        }
    }
}
