//! Accumulated coverage by signed-area cell accumulation, exactly: the method of the
//! scanline anti-aliasing renderers (libart; FreeType's `ftgrays.c`, after Raph Levien's
//! libart; font-rs; ab_glyph_rasterizer), here in exact rationals.
//!
//! Each edge of a shape's path is cut where it crosses a pixel row or column, so that each
//! piece lies in one cell (pixel). A piece going down by `dy` (y grows downwards on the
//! canvas) at mean local x `xm` (0 at the cell's left side, 1 at its right) adds `dy` to
//! the *cover* of the cell, and `dy (1 - xm)` to its *area*: the part of the cell right of
//! the piece. Walking a row left to right, a pixel's integral of the winding number is the
//! cover of every cell left of it plus its own area, negated (a shape whose shoelace sum
//! is positive winds +1 by the convention of [`super::exact`]).
//!
//! Only the accumulated semantics come out of it (the fold decides the rest); where the
//! path winds at most once it is true coverage too. The plain oracle ([`super::exact`])
//! gives the same numbers by a different road: the tests check one against the other.

use std::collections::BTreeMap;

use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use super::{fold, AreaImage, AreaShape, Semantics};
use crate::geom::Point;

/// The cells of one shape: `(row, column) -> (cover, area)`.
type Cells = BTreeMap<(i64, i64), (BigRational, BigRational)>;

/// The directed edges of `shape`'s path: every contour's, as given.
fn path_edges(shape: &AreaShape) -> Vec<(Point, Point)> {
    let mut out = Vec::new();
    for contour in shape.contours() {
        let n = contour.len();
        for i in 0..n {
            out.push((contour[i].clone(), contour[(i + 1) % n].clone()));
        }
    }
    out
}

/// Adds the edge `a -> b` to `cells`, cut at the column lines `0..=width` and the row lines
/// `0..=height` only: a piece left of the canvas gives all columns its cover wherever it
/// lies, and pieces above, below or right of it give the canvas nothing.
fn add_edge(cells: &mut Cells, a: &Point, b: &Point, width: u32, height: u32) {
    if a.y == b.y {
        return; // no cover, no area
    }
    // The parameters where the edge crosses a whole x or y, in order, with its ends.
    let mut ts = vec![BigRational::zero(), BigRational::one()];
    for (from, to, side) in [(&a.x, &b.x, width), (&a.y, &b.y, height)] {
        if from == to {
            continue;
        }
        let (lo, hi) = (from.min(to), from.max(to));
        let last = BigRational::from_integer(side.into()).min(hi.clone());
        let mut k = lo.ceil().max(BigRational::zero());
        while k <= last {
            ts.push((&k - from) / (to - from));
            k += BigRational::one();
        }
    }
    ts.sort();
    ts.dedup();
    let at = |t: &BigRational| Point::new(&a.x + (&b.x - &a.x) * t, &a.y + (&b.y - &a.y) * t);
    let half = BigRational::new(1.into(), 2.into());
    for pair in ts.windows(2) {
        let (p, q) = (at(&pair[0]), at(&pair[1]));
        let dy = &q.y - &p.y;
        if dy.is_zero() {
            continue;
        }
        let mid_x = (&p.x + &q.x) * &half;
        let mid_y = (&p.y + &q.y) * &half;
        let (column, row) = (mid_x.floor(), mid_y.floor());
        let xm = &mid_x - &column;
        let key = (integer(&row), integer(&column));
        let cell = cells
            .entry(key)
            .or_insert_with(|| (BigRational::zero(), BigRational::zero()));
        cell.1 += &dy * (BigRational::one() - xm);
        cell.0 += dy;
    }
}

/// `v`, a whole number, as an i64 (saturating: a cell that far lies off every canvas).
fn integer(v: &BigRational) -> i64 {
    i64::try_from(v.to_integer()).unwrap_or(if v.is_negative() { i64::MIN } else { i64::MAX })
}

/// The integral of `shape`'s path winding number over every pixel of a `width` x `height`
/// canvas with a non-zero value: `(x, y, acc)` by row, then column.
pub fn accumulate(shape: &AreaShape, width: u32, height: u32) -> Vec<(u32, u32, BigRational)> {
    let mut cells = Cells::new();
    for (a, b) in path_edges(shape) {
        add_edge(&mut cells, &a, &b, width, height);
    }
    let mut out = Vec::new();
    let mut row_cells = cells.into_iter().peekable();
    for y in 0..i64::from(height) {
        // This row's cells by column; the cover of those left of the canvas is carried in.
        let mut carry = BigRational::zero();
        let mut row: BTreeMap<i64, (BigRational, BigRational)> = BTreeMap::new();
        while let Some(((r, column), cell)) = row_cells.next_if(|((r, _), _)| *r <= y) {
            if r < y {
                continue; // above the canvas
            }
            if column < 0 {
                carry += cell.0;
            } else {
                row.insert(column, cell);
            }
        }
        let zero = (BigRational::zero(), BigRational::zero());
        for x in 0..i64::from(width) {
            let (cover, area) = row.get(&x).unwrap_or(&zero);
            let acc = -(&carry + area);
            carry += cover;
            if !acc.is_zero() {
                if let (Ok(px), Ok(py)) = (u32::try_from(x), u32::try_from(y)) {
                    out.push((px, py, acc));
                }
            }
        }
    }
    out
}

/// The scene's accumulated coverage under `semantics` (`Accumulated` or
/// `AccumulatedUnclamped`; `True` is refused with `None`, as cells carry no inside test):
/// each shape's value folded, summed, as [`super::exact::rasterize`] gives it.
pub fn rasterize(shapes: &[AreaShape], width: u32, height: u32, semantics: Semantics) -> Option<AreaImage> {
    if semantics == Semantics::True {
        return None;
    }
    let mut sum: BTreeMap<(u32, u32), BigRational> = BTreeMap::new();
    for shape in shapes {
        for (x, y, acc) in accumulate(shape, width, height) {
            *sum.entry((y, x)).or_insert_with(BigRational::zero) += fold(shape.fill_rule, &acc, semantics);
        }
    }
    Some(AreaImage {
        width,
        height,
        semantics,
        pixels: sum
            .into_iter()
            .filter(|(_, v)| !v.is_zero())
            .map(|((y, x), v)| (x, y, v))
            .collect(),
    })
}
