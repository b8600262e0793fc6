//! The plain oracle of area coverage, written to be read.
//!
//! A pixel is cut into vertical slabs at every x where something changes inside it: a
//! vertex, two edges crossing, an edge crossing the pixel's top or bottom side. Inside a
//! slab no two edges cross and no edge leaves or enters the pixel's rows, so the edges that
//! span the slab lie one above the other in one order, each a straight segment, and between
//! two consecutive ones the winding number of every shape is constant. Each such
//! trapezoid, clamped to the pixel's rows, has an exact area (its width times the mean of
//! its two heights); its winding numbers come from counting the edges below it, each
//! edge counting +1 when it runs towards +x and -1 when it runs towards -x (the vertical
//! ray of Hain's and Sunday's winding-number test; vertical edges span no slab and count
//! nothing). The sums are exact:
//!
//! - true coverage: the area of the trapezoids inside any shape under its fill rule;
//! - accumulated coverage of a shape: the sum of area x winding number over the
//!   trapezoids, the integral of the winding number that FreeType's `ftgrays.c` accumulates
//!   cell by cell (Sutherland and Hodgman's clipping of each contour to the pixel, summed by
//!   the shoelace formula, gives the same number by another road: the tests check one
//!   against the other).

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::{fold, inside, path_winding, AreaImage, AreaShape, Semantics};
use crate::geom::{Point, Polygon};

/// One trapezoid of a pixel: its area and the winding number of every contour there.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Piece {
    /// Its area (within the pixel).
    pub area: BigRational,
    /// The winding number about each contour: the shapes in the order given, each its
    /// outline then its holes.
    pub windings: Vec<i64>,
}

/// An edge of a shape that is not vertical, from `a` to `b`.
struct Edge<'a> {
    a: &'a Point,
    b: &'a Point,
    /// The contour it belongs to (numbered as [`Piece::windings`]).
    contour: usize,
}

impl Edge<'_> {
    fn min_x(&self) -> &BigRational {
        std::cmp::min(&self.a.x, &self.b.x)
    }

    fn max_x(&self) -> &BigRational {
        std::cmp::max(&self.a.x, &self.b.x)
    }

    /// Its y at `x` (on its line).
    fn y_at(&self, x: &BigRational) -> BigRational {
        &self.a.y + (&self.b.y - &self.a.y) * (x - &self.a.x) / (&self.b.x - &self.a.x)
    }

    /// The x where it crosses the horizontal line at `y` (an end, when that end lies on
    /// the line and the other above it).
    fn x_at(&self, y: &BigRational) -> Option<BigRational> {
        let (da, db) = (&self.a.y - y, &self.b.y - y);
        (da.is_positive() != db.is_positive())
            .then(|| &self.a.x + (y - &self.a.y) * (&self.b.x - &self.a.x) / (&self.b.y - &self.a.y))
    }

    /// The x where its line meets `other`'s, when they are not parallel.
    fn crossing_x(&self, other: &Edge) -> Option<BigRational> {
        let slope = |e: &Edge| (&e.b.y - &e.a.y) / (&e.b.x - &e.a.x);
        let (m1, m2) = (slope(self), slope(other));
        (m1 != m2).then(|| {
            // a1.y + m1 (x - a1.x) = a2.y + m2 (x - a2.x)
            (&other.a.y - &self.a.y + &m1 * &self.a.x - &m2 * &other.a.x) / (m1 - m2)
        })
    }

    /// +1 towards +x, -1 towards -x.
    fn direction(&self) -> i64 {
        if self.b.x > self.a.x {
            1
        } else {
            -1
        }
    }
}

/// Every non-vertical edge of `shapes`.
fn edges(shapes: &[AreaShape]) -> Vec<Edge<'_>> {
    let mut out = Vec::new();
    for (k, contour) in shapes.iter().flat_map(Polygon::contours).enumerate() {
        for i in 0..contour.len() {
            let (a, b) = (&contour[i], &contour[(i + 1) % contour.len()]);
            if a.x != b.x {
                out.push(Edge { a, b, contour: k });
            }
        }
    }
    out
}

/// The trapezoids of pixel `(px, py)` (the square `[px, px + 1] x [py, py + 1]`) under
/// `shapes`, those of non-zero area.
pub fn pieces(shapes: &[AreaShape], px: i64, py: i64) -> Vec<Piece> {
    let int = |v: i64| BigRational::from_integer(v.into());
    let (x0, x1, y0, y1) = (int(px), int(px + 1), int(py), int(py + 1));
    let all = edges(shapes);
    let contours = shapes.iter().map(|s| 1 + s.holes.len()).sum();
    // The edges over the pixel's column; those that also meet the pixel's rows cross its
    // sides and each other where it matters.
    let column: Vec<&Edge> = all.iter().filter(|e| *e.min_x() < x1 && *e.max_x() > x0).collect();
    let near: Vec<&Edge> = column
        .iter()
        .copied()
        .filter(|e| *std::cmp::min(&e.a.y, &e.b.y) <= y1 && *std::cmp::max(&e.a.y, &e.b.y) >= y0)
        .collect();
    let inside = |x: &BigRational| *x > x0 && *x < x1;
    let mut xs = vec![x0.clone(), x1.clone()];
    // Where an edge of the column starts or ends, the edges spanning a slab change (and
    // with them the winding numbers above, even from below the pixel).
    for e in &column {
        xs.extend([&e.a.x, &e.b.x].into_iter().filter(|x| inside(x)).cloned());
    }
    for e in &near {
        xs.extend([&y0, &y1].into_iter().filter_map(|y| e.x_at(y)).filter(|x| inside(x)));
    }
    for (i, e) in near.iter().enumerate() {
        for f in &near[i + 1..] {
            if let Some(x) = e.crossing_x(f) {
                let on_both = |g: &Edge| x >= *g.min_x() && x <= *g.max_x();
                if inside(&x) && on_both(e) && on_both(f) {
                    xs.push(x);
                }
            }
        }
    }
    xs.sort();
    xs.dedup();
    let clamp = |y: BigRational| y.max(y0.clone()).min(y1.clone());
    let half = BigRational::new(1.into(), 2.into());
    let mut out = Vec::new();
    for slab in xs.windows(2) {
        let (xa, xb) = (&slab[0], &slab[1]);
        let xm = (xa + xb) * &half;
        // The edges spanning the slab, bottom to top: (y at the middle, clamped y at each
        // side, direction, shape).
        let mut spanning: Vec<(BigRational, BigRational, BigRational, &Edge)> = column
            .iter()
            .filter(|e| e.min_x() <= xa && e.max_x() >= xb)
            .map(|e| (e.y_at(&xm), clamp(e.y_at(xa)), clamp(e.y_at(xb)), *e))
            .collect();
        spanning.sort_by(|p, q| p.0.cmp(&q.0));
        let mut windings = vec![0i64; contours];
        for pair in spanning.windows(2) {
            let (lower, upper) = (&pair[0], &pair[1]);
            windings[lower.3.contour] += lower.3.direction();
            let area = (xb - xa) * (&upper.1 - &lower.1 + &upper.2 - &lower.2) * &half;
            if !area.is_zero() {
                out.push(Piece {
                    area,
                    windings: windings.clone(),
                });
            }
        }
    }
    out
}

/// Pixel `(px, py)`'s true coverage under `shapes` (the area of the union of their
/// inside regions) and each shape's accumulated value (the signed integral of its path's
/// winding number over the pixel, [`super::path_winding`]).
pub fn pixel(shapes: &[AreaShape], px: i64, py: i64) -> (BigRational, Vec<BigRational>) {
    let mut union = BigRational::zero();
    let mut accumulated = vec![BigRational::zero(); shapes.len()];
    for piece in pieces(shapes, px, py) {
        // Each shape's windings: its outline's and its holes', in order.
        let mut rest = piece.windings.as_slice();
        let mut covered = false;
        for (shape, acc) in shapes.iter().zip(accumulated.iter_mut()) {
            let (own, after) = rest.split_at(1 + shape.holes.len());
            rest = after;
            covered |= inside(shape, own);
            *acc += &piece.area * BigRational::from_integer(path_winding(own).into());
        }
        if covered {
            union += &piece.area;
        }
    }
    (union, accumulated)
}

/// Pixel `(px, py)`'s value under `semantics` (see [`super`]): the union's area, or the
/// sum of each shape's folded accumulated value.
pub fn value(shapes: &[AreaShape], px: i64, py: i64, semantics: Semantics) -> BigRational {
    let (union, accumulated) = pixel(shapes, px, py);
    under(shapes, union, &accumulated, semantics)
}

/// Pixel `(px, py)`'s value under each semantics, in [`Semantics::ALL`] order, and each
/// shape's signed integral of its path's winding number over it: [`value`] of every
/// semantics, the pixel's pieces found once.
pub fn values(shapes: &[AreaShape], px: i64, py: i64) -> (Vec<(Semantics, BigRational)>, Vec<BigRational>) {
    let (union, accumulated) = pixel(shapes, px, py);
    let values = Semantics::ALL
        .into_iter()
        .map(|s| (s, under(shapes, union.clone(), &accumulated, s)))
        .collect();
    (values, accumulated)
}

/// The value under `semantics` of a pixel whose union has area `union` and whose shapes'
/// integrals are `accumulated`.
fn under(shapes: &[AreaShape], union: BigRational, accumulated: &[BigRational], semantics: Semantics) -> BigRational {
    match semantics {
        Semantics::True => union,
        _ => shapes
            .iter()
            .zip(accumulated)
            .map(|(s, acc)| fold(s.fill_rule, acc, semantics))
            .sum(),
    }
}

/// The edges of `shapes` that meet pixel `(px, py)`'s closed square, in shape, contour
/// and edge order.
pub fn crossing_edges(shapes: &[AreaShape], px: i64, py: i64) -> Vec<CrossingEdge> {
    let int = |v: i64| BigRational::from_integer(v.into());
    let square = crate::clip::Rect {
        xmin: int(px),
        ymin: int(py),
        xmax: int(px + 1),
        ymax: int(py + 1),
    };
    let mut edges = Vec::new();
    for (s, shape) in shapes.iter().enumerate() {
        for (c, contour) in shape.contours().enumerate() {
            for e in 0..contour.len() {
                let (a, b) = (&contour[e], &contour[(e + 1) % contour.len()]);
                if crate::clip::cohen_sutherland::clip_exact(a, b, &square).is_some() {
                    edges.push(CrossingEdge {
                        shape: s,
                        contour: c,
                        edge: e,
                        from: a.clone(),
                        to: b.clone(),
                    });
                }
            }
        }
    }
    edges
}

/// The exact area coverage of `shapes` on a `width` x `height` canvas: every pixel that
/// the shapes' bounding box meets, by [`value`].
pub fn rasterize(shapes: &[AreaShape], width: u32, height: u32, semantics: Semantics) -> AreaImage {
    let points: Vec<&Point> = shapes.iter().flat_map(Polygon::contours).flatten().collect();
    let mut pixels = Vec::new();
    if let Some(first) = points.first() {
        let (mut lo_x, mut hi_x, mut lo_y, mut hi_y) = (&first.x, &first.x, &first.y, &first.y);
        for p in &points {
            lo_x = lo_x.min(&p.x);
            hi_x = hi_x.max(&p.x);
            lo_y = lo_y.min(&p.y);
            hi_y = hi_y.max(&p.y);
        }
        let range = |lo: &BigRational, hi: &BigRational, side: u32| {
            let first = lo.floor().to_integer().max(0.into());
            let last = hi.ceil().to_integer().min(side.into());
            let (first, last): (i64, i64) = (first.try_into().unwrap_or(i64::MAX), last.try_into().unwrap_or(0));
            first..last
        };
        for py in range(lo_y, hi_y, height) {
            for px in range(lo_x, hi_x, width) {
                let v = value(shapes, px, py, semantics);
                if !v.is_zero() {
                    let (x, y) = (u32::try_from(px), u32::try_from(py));
                    if let (Ok(x), Ok(y)) = (x, y) {
                        pixels.push((x, y, v));
                    }
                }
            }
        }
    }
    AreaImage {
        width,
        height,
        semantics,
        pixels,
    }
}

/// An edge of a shape that meets a pixel's square.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CrossingEdge {
    /// The shape (its index among the shapes: its id in the scene).
    pub shape: usize,
    /// The contour: 0 the outline, 1.. the holes.
    pub contour: usize,
    /// The edge's index in its contour (from vertex `edge` to the next).
    pub edge: usize,
    /// Its start.
    pub from: Point,
    /// Its end.
    pub to: Point,
}

/// What makes up one pixel's area ([`explain`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AreaExplanation {
    /// The pixel's column.
    pub x: i64,
    /// The pixel's row.
    pub y: i64,
    /// Its value under each semantics, in [`Semantics::ALL`] order.
    pub values: Vec<(Semantics, BigRational)>,
    /// Each shape's signed integral of its path's winding number over the pixel.
    pub accumulated: Vec<BigRational>,
    /// The edges that meet the pixel's closed square.
    pub edges: Vec<CrossingEdge>,
    /// The pixel's trapezoids ([`pieces`]).
    pub pieces: Vec<Piece>,
}

/// Pixel `(px, py)` explained: its exact values, each shape's integral, the edges that meet
/// its square and its pieces with their winding numbers.
pub fn explain(shapes: &[AreaShape], px: i64, py: i64) -> AreaExplanation {
    let (values, accumulated) = values(shapes, px, py);
    AreaExplanation {
        x: px,
        y: py,
        values,
        accumulated,
        edges: crossing_edges(shapes, px, py),
        pieces: pieces(shapes, px, py),
    }
}

impl AreaExplanation {
    /// As text: the values, each shape's integral, the edges, the pieces.
    pub fn to_text(&self) -> String {
        use crate::num::exact::{exact_text, terminating_decimal};
        let shown = |v: &BigRational| match terminating_decimal(v) {
            Some(d) if d != exact_text(v) => format!("{} (= {d})", exact_text(v)),
            _ => exact_text(v),
        };
        let mut s = format!("pixel ({}, {}): area coverage\n", self.x, self.y);
        for (sem, v) in &self.values {
            s.push_str(&format!("  {:<12} {}\n", sem.name(), shown(v)));
        }
        for (k, acc) in self.accumulated.iter().enumerate() {
            if !acc.is_zero() {
                s.push_str(&format!(
                    "  shape {k}: integral of its path's winding number {}\n",
                    shown(acc)
                ));
            }
        }
        if self.edges.is_empty() {
            s.push_str("  no edge meets the pixel\n");
        }
        for e in &self.edges {
            let contour = if e.contour == 0 {
                "outline".to_string()
            } else {
                format!("hole {}", e.contour - 1)
            };
            s.push_str(&format!(
                "  edge: shape {} {contour} edge {}: {} -> {}\n",
                e.shape,
                e.edge,
                crate::num::exact::pair_text(&e.from.x, &e.from.y),
                crate::num::exact::pair_text(&e.to.x, &e.to.y)
            ));
        }
        for p in &self.pieces {
            s.push_str(&format!(
                "  piece: area {}, winding numbers {:?}\n",
                shown(&p.area),
                p.windings
            ));
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::FillRule;

    fn r(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    fn p(x: BigRational, y: BigRational) -> Point {
        Point::new(x, y)
    }

    fn square(x0: BigRational, y0: BigRational, side: BigRational) -> Vec<Point> {
        let (x1, y1) = (&x0 + &side, &y0 + &side);
        vec![
            p(x0.clone(), y0.clone()),
            p(x1.clone(), y0),
            p(x1, y1.clone()),
            p(x0, y1),
        ]
    }

    #[test]
    fn right_triangle_by_hand() {
        // (0,0) (2,0) (0,2): pixel (0,0) whole, (1,0) and (0,1) half, (1,1) nothing.
        let t = Polygon::new(
            vec![p(r(0, 1), r(0, 1)), p(r(2, 1), r(0, 1)), p(r(0, 1), r(2, 1))],
            FillRule::NonZero,
        );
        let shapes = [t];
        let v = |x, y| value(&shapes, x, y, Semantics::True);
        assert_eq!(
            [v(0, 0), v(1, 0), v(0, 1), v(1, 1)],
            [r(1, 1), r(1, 2), r(1, 2), r(0, 1)]
        );
        // Accumulated: the same, whatever the orientation.
        let (_, acc) = pixel(&shapes, 1, 0);
        assert_eq!(acc[0].abs(), r(1, 2));
    }

    #[test]
    fn overlapping_squares_by_hand() {
        // Squares [0, 3/2]^2 and [1/2, 2]^2, both the same way round, in one contour
        // (joined by the segment (0,0)-(1/2,1/2), walked there and back). In pixel (0, 0):
        // the first covers it all, the second [1/2, 1]^2 (1/4), the overlap is 1/4.
        // Nonzero: 1; even-odd: 1 - 1/4. Accumulated: 1 + 1/4, folded to 1 (nonzero) and
        // 2 - 5/4 (even-odd); unclamped 5/4.
        let mut outline = square(r(0, 1), r(0, 1), r(3, 2));
        outline.push(p(r(0, 1), r(0, 1)));
        outline.extend(square(r(1, 2), r(1, 2), r(3, 2)));
        outline.push(p(r(1, 2), r(1, 2)));
        let shape = |fill_rule| Polygon::new(outline.clone(), fill_rule);
        let nz = [shape(FillRule::NonZero)];
        let eo = [shape(FillRule::EvenOdd)];
        assert_eq!(value(&nz, 0, 0, Semantics::True), r(1, 1));
        assert_eq!(value(&eo, 0, 0, Semantics::True), r(3, 4));
        assert_eq!(value(&nz, 0, 0, Semantics::Accumulated), r(1, 1));
        assert_eq!(value(&eo, 0, 0, Semantics::Accumulated), r(3, 4));
        assert_eq!(value(&nz, 0, 0, Semantics::AccumulatedUnclamped), r(5, 4));
        // Pixel (1, 1): the first [1, 3/2]^2 (1/4), the second [1, 2]^2 (1), overlap 1/4.
        assert_eq!(value(&eo, 1, 1, Semantics::True), r(3, 4));
        assert_eq!(value(&nz, 1, 1, Semantics::AccumulatedUnclamped), r(5, 4));
    }

    #[test]
    fn a_hole_by_hand() {
        // A 3x3 square with the middle pixel as a hole: the hole is empty in true coverage
        // either way round; accumulated, a hole running against the outline winds 0 (empty),
        // one running its way winds 2 (nonzero folds it to 1; unclamped 2).
        for (against, accumulated, unclamped) in [(false, 1, 2), (true, 0, 0)] {
            let mut hole = square(r(1, 1), r(1, 1), r(1, 1));
            if against {
                hole.reverse();
            }
            let shapes = [Polygon {
                outline: square(r(0, 1), r(0, 1), r(3, 1)),
                holes: vec![hole],
                fill_rule: FillRule::NonZero,
            }];
            let image = rasterize(&shapes, 3, 3, Semantics::True);
            assert_eq!(image.pixels.len(), 8);
            assert_eq!(image.value(1, 1), r(0, 1));
            assert_eq!(image.total(), r(8, 1));
            assert_eq!(value(&shapes, 1, 1, Semantics::Accumulated), r(accumulated, 1));
            assert_eq!(value(&shapes, 1, 1, Semantics::AccumulatedUnclamped), r(unclamped, 1));
            assert_eq!(value(&shapes, 0, 0, Semantics::Accumulated), r(1, 1));
        }
    }

    #[test]
    fn two_shapes_union_by_hand() {
        // Two triangles splitting the unit square along its diagonal: the union is the
        // whole pixel, each half of it; a third triangle over one of them adds nothing.
        let t = |a: (i64, i64), b: (i64, i64), c: (i64, i64)| {
            let q = |v: (i64, i64)| p(r(v.0, 1), r(v.1, 1));
            Polygon::new(vec![q(a), q(b), q(c)], FillRule::NonZero)
        };
        let shapes = [
            t((0, 0), (1, 0), (1, 1)),
            t((0, 0), (1, 1), (0, 1)),
            t((1, 1), (0, 1), (0, 0)),
        ];
        assert_eq!(value(&shapes[..2], 0, 0, Semantics::True), r(1, 1));
        assert_eq!(value(&shapes, 0, 0, Semantics::True), r(1, 1));
        // Accumulated sums each shape's value: 3/2 with the third.
        assert_eq!(value(&shapes, 0, 0, Semantics::Accumulated), r(3, 2));
    }
}
