//! Polygon fill in f32 and f64: the float side of the trade. Every sample of the bounding
//! box is tested by its winding number around each contour, counted edge by edge in the
//! float type, as a float renderer would:
//!
//! - [`FloatRule::WithTieRule`]: the oracle's rule (see the [module docs](super)) read in
//!   floats: an edge crosses the moved sample's row when `min <= y < max` (top-left) or
//!   `min < y <= max` (bottom-left), and the crossing is right of the sample when the
//!   float `E(p)` and `dy` have different signs (`E == 0`: the sign of `dy` decides).
//!   Exact when every product is exact in the type (small dyadic coordinates); rounding
//!   in `E` moves samples across edges elsewhere.
//! - [`FloatRule::Naive`]: the crossing test most code copies (W. R. Franklin's PNPOLY):
//!   an edge counts when `(a.y > y) != (b.y > y)` and `x < a.x + (y - a.y)(b.x - a.x) /
//!   (b.y - a.y)`, the intersection computed with a division; ties fall where that
//!   division rounds them.
//!
//! The winding number decides with the polygon's fill rule, outline minus holes, as the
//! oracle does. Each row tests only the edges that reach it (a sweep of the edges sorted
//! by their top), so a fill costs `O(n log n + samples x edges per row)` for `n` edges,
//! not `samples x n`.

use glam::{DVec2, Vec2};

use super::closed_edges;
use crate::convention::{Target, TieRule};
use crate::coverage::CoverageSink;
use crate::geom::FillRule;
use crate::raster::{float_sample_range, sample_f64};
use crate::tri::float::FloatRule;

macro_rules! float_polygon {
    ($polygon:ident, $winding:ident, $crossing:ident, $rasterize:ident, $vec:ty, $float:ty, $name:literal) => {
        #[doc = concat!("A polygon in ", $name, ": an outline, holes and a fill rule.")]
        #[derive(Debug, Clone, PartialEq)]
        pub struct $polygon {
            /// The outline's vertices, in order (either orientation).
            pub outline: Vec<$vec>,
            /// The holes' vertices.
            pub holes: Vec<Vec<$vec>>,
            /// Nonzero or even-odd.
            pub fill_rule: FillRule,
        }

        impl $polygon {
            /// The outline, then the holes.
            pub fn contours(&self) -> impl Iterator<Item = &[$vec]> + Clone {
                std::iter::once(self.outline.as_slice()).chain(self.holes.iter().map(Vec::as_slice))
            }
        }

        #[doc = concat!("The winding number of the sample `p` around `contour`, in ", $name)]
        /// under `rule` (see the module docs for what each rule counts).
        pub fn $winding(p: $vec, contour: &[$vec], tie: TieRule, rule: FloatRule) -> i64 {
            closed_edges(contour)
                .map(|(a, b)| $crossing(p, *a, *b, tie, rule))
                .sum()
        }

        /// What the edge `a -> b` adds to the winding number of the sample `p`.
        fn $crossing(p: $vec, a: $vec, b: $vec, tie: TieRule, rule: FloatRule) -> i64 {
            let dy = b.y - a.y;
            match rule {
                FloatRule::WithTieRule => {
                    let (lo, hi) = if a.y <= b.y { (a.y, b.y) } else { (b.y, a.y) };
                    let crosses = match tie {
                        TieRule::TopLeft => lo <= p.y && p.y < hi,
                        TieRule::BottomLeft => lo < p.y && p.y <= hi,
                    };
                    if !crosses {
                        return 0;
                    }
                    let e = (p.x - a.x) * dy - (p.y - a.y) * (b.x - a.x);
                    let right = e != 0.0 && (e > 0.0) != (dy > 0.0);
                    if right {
                        return if dy > 0.0 { -1 } else { 1 };
                    }
                    0
                }
                FloatRule::Naive => {
                    if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / dy {
                        return if dy > 0.0 { -1 } else { 1 };
                    }
                    0
                }
            }
        }

        #[doc = concat!("Fills `poly` in ", $name, ": every sample of its bounding box tested")]
        /// by its winding numbers (outline minus holes, the fill rule on each).
        pub fn $rasterize<S: CoverageSink + ?Sized>(
            poly: &$polygon,
            id: u32,
            target: &Target,
            rule: FloatRule,
            sink: &mut S,
        ) {
            let points = poly.contours().flatten();
            let (Some(min), Some(max)) = (
                points.clone().copied().reduce(<$vec>::min),
                points.copied().reduce(<$vec>::max),
            ) else {
                return;
            };
            let wide = |v: $vec| [f64::from(v.x), f64::from(v.y)];
            let Some(range) = float_sample_range(wide(min), wide(max), target) else {
                return;
            };
            let tie = target.convention.tie_rule;
            // Only an edge with `lo <= y <= hi` can count for a sample at height `y`
            // (every rule's crossing test implies it), so each row tests the edges active
            // on it, found by a sweep down the rows: the same decisions as testing every
            // edge, in O(edges log edges + samples x active edges).
            let mut edges: Vec<(usize, $vec, $vec)> = poly
                .contours()
                .enumerate()
                .flat_map(|(k, c)| closed_edges(c).map(move |(a, b)| (k, *a, *b)))
                .collect();
            let lo = |e: &(usize, $vec, $vec)| e.1.y.min(e.2.y);
            edges.sort_by(|x, y| lo(x).total_cmp(&lo(y)));
            let mut next = 0;
            let mut active: Vec<(usize, $vec, $vec)> = Vec::new();
            #[allow(clippy::cast_possible_truncation)] // canvas samples are exact in f32
            for j in range.y0..=range.y1 {
                let y = sample_f64(range.x0, j, target).y as $float;
                while next < edges.len() && lo(&edges[next]) <= y {
                    active.push(edges[next]);
                    next += 1;
                }
                active.retain(|e| e.1.y.max(e.2.y) >= y);
                active.sort_by_key(|e| e.0);
                // The outline's edges first (contour 0), then each hole's.
                let contours: Vec<&[(usize, $vec, $vec)]> = active.chunk_by(|a, b| a.0 == b.0).collect();
                if !contours.first().is_some_and(|c| c[0].0 == 0) {
                    continue; // no outline edge on this row: winding number 0 everywhere
                }
                let winding = |p: $vec, c: &[(usize, $vec, $vec)]| -> i64 {
                    c.iter().map(|e| $crossing(p, e.1, e.2, tie, rule)).sum()
                };
                for i in range.x0..=range.x1 {
                    let s = sample_f64(i, j, target);
                    let p = <$vec>::new(s.x as $float, s.y as $float);
                    if poly.fill_rule.inside(winding(p, contours[0]))
                        && !contours[1..].iter().any(|h| poly.fill_rule.inside(winding(p, h)))
                    {
                        sink.cover(i, j, id);
                    }
                }
            }
        }
    };
}

float_polygon!(
    PolygonF32,
    contour_winding_f32,
    crossing_f32,
    rasterize_f32,
    Vec2,
    f32,
    "f32"
);
float_polygon!(
    PolygonF64,
    contour_winding_f64,
    crossing_f64,
    rasterize_f64,
    DVec2,
    f64,
    "f64"
);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::{Convention, Preset};
    use crate::coverage::Coverage;

    fn square(a: f64, b: f64) -> Vec<DVec2> {
        vec![DVec2::new(a, a), DVec2::new(b, a), DVec2::new(b, b), DVec2::new(a, b)]
    }

    #[test]
    fn a_square_with_a_hole_by_hand() {
        // 8x8 square with the 4x4 hole (2..6)^2, samples at centres: 64 - 16 = 48 pixels.
        let target = Target::new(8, 8, Convention::default()).unwrap();
        for rule in [FloatRule::WithTieRule, FloatRule::Naive] {
            let poly = PolygonF64 {
                outline: square(0.0, 8.0),
                holes: vec![square(2.0, 6.0)],
                fill_rule: FillRule::NonZero,
            };
            let mut c = Coverage::new(8, 8);
            rasterize_f64(&poly, 0, &target, rule, &mut c);
            assert_eq!(c.covered_pixels(), 48, "{rule:?}");
            assert!(c.owners(3, 3).is_empty());
        }
    }

    #[test]
    fn samples_on_edges_follow_the_tie_rule() {
        // The square [0.5, 2.5]^2 has samples on all four edges. Top-left owns the left
        // and top ones: samples x, y in {0.5, 1.5} -> pixels 0 and 1 of rows 0 and 1.
        let sq = square(0.5, 2.5);
        let tl = Target::new(4, 4, Preset::D3d11.convention()).unwrap();
        let w = |p: DVec2, tie| contour_winding_f64(p, &sq, tie, FloatRule::WithTieRule).abs();
        assert_eq!(w(DVec2::new(0.5, 0.5), TieRule::TopLeft), 1);
        assert_eq!(w(DVec2::new(2.5, 1.5), TieRule::TopLeft), 0); // right edge
        assert_eq!(w(DVec2::new(1.5, 2.5), TieRule::TopLeft), 0); // bottom edge
        assert_eq!(w(DVec2::new(1.5, 2.5), TieRule::BottomLeft), 1); // bottom edge under GL
        assert_eq!(w(DVec2::new(1.5, 0.5), TieRule::BottomLeft), 0); // top edge under GL
        let poly = PolygonF32 {
            outline: sq.iter().map(|v| v.as_vec2()).collect(),
            holes: vec![],
            fill_rule: FillRule::EvenOdd,
        };
        let mut c = Coverage::new(4, 4);
        rasterize_f32(&poly, 7, &tl, FloatRule::WithTieRule, &mut c);
        let got: Vec<(u32, u32)> = c.iter().map(|(x, y, _)| (x, y)).collect();
        assert_eq!(got, vec![(0, 0), (1, 0), (0, 1), (1, 1)]);
    }
}
