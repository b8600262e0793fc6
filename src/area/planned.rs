//! Accumulated coverage by signed-area cell accumulation in machine integers, exactly: the
//! planned engine. It computes what [`super::cells`] computes (and so what the plain
//! oracle, [`super::exact`], gives under the accumulated semantics), at integer speed where
//! a shape's numbers allow it, in big rationals where they do not.
//!
//! **Why integers can be exact.** Scale a shape by `S`, the least common multiple of its
//! coordinates' denominators: its vertices become integers. An edge with integer steps
//! `(dx, dy) = g (a, b)` (`a`, `b` coprime) crosses a column line at a `y` whose
//! denominator divides `|a|`, and a row line at an `x` whose denominator divides `|b|`. So
//! in *fine units* of `1 / F` pixel, `F = S |a| |b|` (`S |b|` for a vertical edge), every
//! point where the edge is cut is an integer. A piece of the edge inside one cell, from
//! `(x1, y1)` to `(x2, y2)` in fine units, adds `c = y2 - y1` to the cell's cover and
//! `c (2 F (col + 1) - x1 - x2) / (2 F^2)` to its area (the part of the cell right of the
//! piece), as in [`super::cells`]. Per pixel, each edge through it leaves one fraction over
//! its own `2 F^2`; every edge left of it in the row leaves its whole cover of the row,
//! which is an integer in units of `1 / S` (rows and vertices are whole in those units).
//! The pixel's value is that integer sum over `S` plus its few fractions.
//!
//! **The plan** ([`plan`]): a shape is computed in `i128` when `S` and its scaled
//! coordinates are below `2^62` in magnitude and every edge has `F <= 2^FINE_BITS`
//! ([`FINE_BITS`] = 62); otherwise in big rationals ([`super::cells`]). Within that
//! envelope, and on canvases below `2^31` a side (the scene reader's limits are far
//! smaller), every number the walk forms fits `i128`: `M <= F`, so fine coordinates are
//! below `2^124` and the walk's sums of them below `2^126`; a piece's cover is at most
//! `F`, the factor beside it in the area at most `2 F`, so a pixel's numerator is at most
//! `2 F^2 + 2 F^2 = 2^126` and its denominator `2 F^2 = 2^125`. The bound is tight: at
//! `F = 2^63` the denominator alone leaves `i128`. A pixel's fractions are added with
//! checked rational arithmetic (`num_rational::Ratio<i128>`'s `checked_add`, never its
//! unchecked operators), and a pixel whose sum leaves `i128` is summed in big rationals.
//!
//! Semantics: the accumulated ones come out of the walk. True coverage does not in
//! general (it needs each contour's winding, not the path's); [`rasterize`] computes it
//! with the plain oracle.

use std::ops::Range;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::{BigRational, Ratio};
use num_traits::{CheckedAdd, Signed, ToPrimitive, Zero};

use super::{cells, exact, AreaImage, AreaShape, Semantics};
use crate::geom::FillRule;

/// The largest fine unit, as a power of two: an edge is walked in `i128` when its
/// `F = S |a| |b|` is at most `2^FINE_BITS` (see the module documentation).
pub const FINE_BITS: u32 = 62;

/// The bound on a scaled coordinate and on the scale, as a power of two.
const SCALED_BITS: u32 = 62;

/// The arithmetic the plan chose for a shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AreaWidth {
    /// Every edge in `i128` (pixel sums that leave it are summed in big rationals).
    I128,
    /// Big rationals throughout ([`super::cells`]).
    Big,
}

/// The arithmetic [`accumulate`] uses for `shape` (see the module documentation for the
/// envelope).
///
/// ```
/// use num_rational::BigRational;
/// use rasterproof::area::planned::{plan, AreaWidth};
/// use rasterproof::geom::{FillRule, Point, Polygon};
/// let p = |x: i64, y: i64, d: i64| Point::new(BigRational::new(x.into(), d.into()), BigRational::new(y.into(), d.into()));
/// let glyph = Polygon::new(vec![p(0, 0, 64), p(300, 0, 64), p(0, 200, 64)], FillRule::NonZero);
/// assert_eq!(plan(&glyph), AreaWidth::I128);
/// // A sliver 2^62 / 3 px long, in thirds: its slanted edge's F is 3 x 2^62.
/// let far = Polygon::new(vec![p(0, 0, 3), p(1 << 62, 0, 3), p(0, 1, 3)], FillRule::NonZero);
/// assert_eq!(plan(&far), AreaWidth::Big);
/// ```
pub fn plan(shape: &AreaShape) -> AreaWidth {
    if fine_edges(shape).is_some() {
        AreaWidth::I128
    } else {
        AreaWidth::Big
    }
}

/// `shape`'s scale and its non-horizontal edges in fine units (a horizontal edge adds no
/// cover and no area), or `None` when the shape is outside the `i128` envelope.
fn fine_edges(shape: &AreaShape) -> Option<(i128, Vec<Fine>)> {
    let s = scaled(shape)?;
    let edges = s
        .edges()
        .filter(|(p, q)| p.1 != q.1)
        .map(|(p, q)| fine_units(s.scale, p, q))
        .collect::<Option<Vec<Fine>>>()?;
    Some((s.scale, edges))
}

/// A shape scaled to integers: `scale` and each contour's vertices times `scale`.
struct Scaled {
    scale: i128,
    contours: Vec<Vec<(i128, i128)>>,
}

impl Scaled {
    /// The directed edges of the path: every contour's, as given.
    fn edges(&self) -> impl Iterator<Item = ((i128, i128), (i128, i128))> + '_ {
        self.contours
            .iter()
            .flat_map(|c| (0..c.len()).map(move |i| (c[i], c[(i + 1) % c.len()])))
    }
}

/// `shape` scaled by the least common multiple of its coordinates' denominators, when the
/// scale and every scaled coordinate are below `2^SCALED_BITS`.
fn scaled(shape: &AreaShape) -> Option<Scaled> {
    let mut lcm = BigInt::from(1);
    for p in shape.contours().flatten() {
        lcm = lcm.lcm(p.x.denom()).lcm(p.y.denom());
    }
    let limit = 1i128 << SCALED_BITS;
    let scale = lcm.to_i128().filter(|s| *s <= limit)?;
    let whole = |v: &BigRational| -> Option<i128> {
        let n = (v.numer() * (&lcm / v.denom())).to_i128()?;
        (n.abs() < limit).then_some(n)
    };
    let contours = shape
        .contours()
        .map(|c| c.iter().map(|p| Some((whole(&p.x)?, whole(&p.y)?))).collect())
        .collect::<Option<_>>()?;
    Some(Scaled { scale, contours })
}

/// An edge in fine units: its vertices, its reduced steps `(a, b)`, `M = |a| |b|` (with
/// `|a|` taken as 1 for a vertical edge) and `F = S M`.
struct Fine {
    x0: i128,
    y0: i128,
    y1: i128,
    a: i128,
    b: i128,
    m: i128,
    f: i128,
}

/// The edge `p -> q` (scaled by `scale`) in fine units, or `None` outside the envelope.
/// A horizontal edge (no cover, no area) has no fine form either: callers skip it first.
fn fine_units(scale: i128, p: (i128, i128), q: (i128, i128)) -> Option<Fine> {
    let (dx, dy) = (q.0 - p.0, q.1 - p.1);
    debug_assert_ne!(dy, 0, "a horizontal edge has no fine form");
    let g = dx.abs().gcd(&dy.abs());
    let (a, b) = (dx / g, dy / g);
    let m = a.abs().max(1).checked_mul(b.abs())?;
    let f = scale.checked_mul(m).filter(|f| *f <= 1i128 << FINE_BITS)?;
    Some(Fine {
        x0: p.0 * m,
        y0: p.1 * m,
        y1: q.1 * m,
        a,
        b,
        m,
        f,
    })
}

impl Fine {
    /// The x where the edge's line meets the row line (or vertex) at fine `y`: exact,
    /// since `y - y0` is a multiple of `M`, so of `|b|`.
    fn x_at(&self, y: i128) -> i128 {
        self.x0 + (y - self.y0) / self.b * self.a
    }

    /// The y where the edge's line meets the column line at fine `x` (`a != 0`).
    fn y_at(&self, x: i128) -> i128 {
        self.y0 + (x - self.x0) / self.a * self.b
    }
}

/// What one shape's edges leave in a canvas row.
#[derive(Default)]
struct Events {
    /// `(row, column, amount)`: from `column` rightwards, `amount / S` is added to every
    /// pixel of the row (an edge's whole cover of the row, negated).
    tails: Vec<(u32, u32, i128)>,
    /// `(row, column, numerator, denominator)`: a fraction added to one pixel (an edge
    /// through it: the cover of its pieces left of the pixel and its area, negated).
    fractions: Vec<(u32, u32, i128, i128)>,
}

/// Walks `e` row by row over the `rows` of a `width`-wide canvas into `events`.
fn walk(e: &Fine, width: u32, rows: &Range<u32>, events: &mut Events) {
    let f = e.f;
    let sign = (e.y1 - e.y0).signum();
    let (top, bottom) = (
        e.y0.min(e.y1).max(i128::from(rows.start) * f),
        e.y0.max(e.y1).min(i128::from(rows.end) * f),
    );
    if top >= bottom {
        return;
    }
    let (w, twice_f, den) = (i128::from(width), 2 * f, 2 * f * f);
    for row in top / f..=(bottom - 1) / f {
        let (ya, yb) = (top.max(row * f), bottom.min((row + 1) * f));
        let (xa, xb) = (e.x_at(ya), e.x_at(yb));
        // The row's piece, left to right.
        let (mut xl, mut yl, xr, yr) = if xa <= xb { (xa, ya, xb, yb) } else { (xb, yb, xa, ya) };
        let r = u32::try_from(row).expect("a row of the canvas");
        let mut carry = 0; // the cover of the pieces left of the current column
        let mut last = -1; // the last column with a piece
        let mut push = |col: i128, carry: i128, area: i128| {
            let c = u32::try_from(col).expect("a column of the canvas");
            events.fractions.push((r, c, -(carry * twice_f + area), den));
        };
        if xl == xr {
            // Vertical within the row: one piece, at the column right of a column line.
            if xl >= 0 {
                last = xl / f;
                if last < w {
                    push(last, 0, sign * (yr - yl).abs() * (twice_f * (last + 1) - 2 * xl));
                }
            }
        } else {
            if xl < 0 {
                // Left of the canvas: only its cover matters.
                let x_end = xr.min(0);
                let y_end = if x_end == xr { yr } else { e.y_at(0) };
                carry += sign * (y_end - yl).abs();
                (xl, yl) = (x_end, y_end);
            }
            while xl < xr {
                let col = xl / f;
                if col >= w {
                    last = w;
                    break;
                }
                let x_next = xr.min((col + 1) * f);
                let y_next = if x_next == xr { yr } else { e.y_at(x_next) };
                let c = sign * (y_next - yl).abs();
                push(col, carry, c * (twice_f * (col + 1) - xl - x_next));
                carry += c;
                last = col;
                (xl, yl) = (x_next, y_next);
            }
        }
        if last + 1 < w {
            let cover = sign * (yb - ya);
            let c = u32::try_from(last + 1).expect("a column of the canvas");
            events.tails.push((r, c, -(cover / e.m)));
        }
    }
}

/// A pixel's exact value: in `i128` while it fits, in big rationals beyond.
#[derive(Debug, Clone)]
enum Value {
    Small(Ratio<i128>),
    Big(BigRational),
}

impl Value {
    fn big(&self) -> BigRational {
        match self {
            Value::Small(r) => BigRational::new_raw(BigInt::from(*r.numer()), BigInt::from(*r.denom())),
            Value::Big(b) => b.clone(),
        }
    }

    fn add(self, other: &Value) -> Value {
        if let (Value::Small(a), Value::Small(b)) = (&self, other) {
            if let Some(sum) = a.checked_add(b) {
                return Value::Small(sum);
            }
        }
        Value::Big(self.big() + other.big())
    }

    fn is_zero(&self) -> bool {
        match self {
            Value::Small(r) => r.is_zero(),
            Value::Big(b) => b.is_zero(),
        }
    }

    /// [`super::fold`], in `i128` when it stays there.
    fn fold(self, fill_rule: FillRule, semantics: Semantics) -> Value {
        let Value::Small(r) = &self else {
            return Value::Big(super::fold(fill_rule, &self.big(), semantics));
        };
        let (n, d) = (r.numer().abs(), *r.denom());
        let folded = match (semantics, fill_rule) {
            (Semantics::AccumulatedUnclamped | Semantics::True, _) => Some(n),
            (Semantics::Accumulated, FillRule::NonZero) => Some(n.min(d)),
            // n mod 2d, reflected above d; both keep n/d's lowest terms.
            (Semantics::Accumulated, FillRule::EvenOdd) => d.checked_mul(2).map(|two_d| {
                let m = n % two_d;
                if m > d {
                    two_d - m
                } else {
                    m
                }
            }),
        };
        match folded {
            Some(v) if v == d => Value::Small(Ratio::from_integer(1)),
            Some(v) => Value::Small(Ratio::new_raw(v, d)),
            None => Value::Big(super::fold(fill_rule, &self.big(), semantics)),
        }
    }
}

/// `base / scale` plus each fraction.
fn pixel_value(base: i128, scale: i128, fractions: &[(u32, u32, i128, i128)]) -> Value {
    let mut v = Value::Small(if base % scale == 0 {
        Ratio::from_integer(base / scale)
    } else {
        Ratio::new(base, scale)
    });
    for &(_, _, n, d) in fractions {
        v = v.add(&Value::Small(Ratio::new(n, d)));
    }
    v
}

/// A shape ready to walk: in `i128` (its scale and its non-horizontal edges in fine units),
/// or, outside the envelope, its values from the big-rational cells.
enum Prepared {
    Small { scale: i128, edges: Vec<Fine> },
    Big(Vec<(u32, u32, BigRational)>),
}

impl Prepared {
    /// `shape` on a `width` x `height` canvas, by the plan's width.
    fn new(shape: &AreaShape, width: u32, height: u32) -> Prepared {
        match fine_edges(shape) {
            Some((scale, edges)) => Prepared::Small { scale, edges },
            None => Prepared::Big(cells::accumulate(shape, width, height)),
        }
    }

    /// The integral of the path's winding number over every pixel of `rows` with a
    /// non-zero value, by row, then column.
    fn band(&self, width: u32, rows: &Range<u32>) -> Vec<(u32, u32, Value)> {
        match self {
            Prepared::Small { scale, edges } => band_i128(*scale, edges, width, rows),
            Prepared::Big(pixels) => {
                let first = pixels.partition_point(|p| p.1 < rows.start);
                let last = pixels.partition_point(|p| p.1 < rows.end);
                pixels[first..last]
                    .iter()
                    .map(|(x, y, v)| (*x, *y, Value::Big(v.clone())))
                    .collect()
            }
        }
    }
}

/// [`Prepared::band`] in `i128`.
fn band_i128(scale: i128, edges: &[Fine], width: u32, rows: &Range<u32>) -> Vec<(u32, u32, Value)> {
    let mut events = Events::default();
    for e in edges {
        walk(e, width, rows, &mut events);
    }
    events.tails.sort_unstable_by_key(|e| (e.0, e.1));
    events.fractions.sort_unstable_by_key(|e| (e.0, e.1));
    let mut out = Vec::new();
    let (mut t, mut k) = (0, 0);
    let (tails, fractions) = (&events.tails, &events.fractions);
    let run = |row: u32, from: u32, to: u32, base: i128, out: &mut Vec<(u32, u32, Value)>| {
        if base != 0 && from < to {
            let v = pixel_value(base, scale, &[]);
            out.extend((from..to).map(|x| (x, row, v.clone())));
        }
    };
    while t < tails.len() || k < fractions.len() {
        let row = match (tails.get(t), fractions.get(k)) {
            (Some(a), Some(b)) => a.0.min(b.0),
            (Some(a), None) => a.0,
            (None, Some(b)) => b.0,
            (None, None) => unreachable!(),
        };
        let (mut base, mut cursor) = (0i128, 0u32);
        loop {
            let next_tail = tails.get(t).filter(|e| e.0 == row).map(|e| e.1);
            let next_fraction = fractions.get(k).filter(|e| e.0 == row).map(|e| e.1);
            let col = match (next_tail, next_fraction) {
                (Some(a), Some(b)) => a.min(b),
                (Some(a), None) => a,
                (None, Some(b)) => b,
                (None, None) => break,
            };
            run(row, cursor, col, base, &mut out);
            while tails.get(t).is_some_and(|e| (e.0, e.1) == (row, col)) {
                base += tails[t].2;
                t += 1;
            }
            let first = k;
            while fractions.get(k).is_some_and(|e| (e.0, e.1) == (row, col)) {
                k += 1;
            }
            let v = pixel_value(base, scale, &fractions[first..k]);
            if !v.is_zero() {
                out.push((col, row, v));
            }
            cursor = col + 1;
        }
        run(row, cursor, width, base, &mut out);
    }
    out
}

/// The integral of `shape`'s path winding number over every pixel of a `width` x `height`
/// canvas with a non-zero value: `(x, y, acc)` by row, then column; what
/// [`super::cells::accumulate`] gives, by the plan's arithmetic.
pub fn accumulate(shape: &AreaShape, width: u32, height: u32) -> Vec<(u32, u32, BigRational)> {
    Prepared::new(shape, width, height)
        .band(width, &(0..height))
        .into_iter()
        .map(|(x, y, v)| (x, y, v.big()))
        .collect()
}

/// The rows [`for_each_row`] computes at once.
pub const BAND: u32 = 64;

/// The scene's coverage under `semantics`, row by row: `emit(y, pixels)` for every row of
/// the canvas, top first, with the row's non-zero `(x, value)` by column. Under the
/// accumulated semantics the rows are computed [`BAND`] at a time (each shape's edges
/// walked over the band only), so the memory is the shapes' and one band's, whatever the
/// canvas (a shape outside the `i128` envelope holds its big-rational cells, whole); true
/// coverage is computed by the plain oracle, whole, then handed out by row.
pub fn for_each_row(
    shapes: &[AreaShape],
    width: u32,
    height: u32,
    semantics: Semantics,
    mut emit: impl FnMut(u32, Vec<(u32, BigRational)>),
) {
    if semantics == Semantics::True {
        exact::rasterize(shapes, width, height, semantics).for_each_row(emit);
        return;
    }
    let prepared: Vec<(Prepared, FillRule)> = shapes
        .iter()
        .map(|s| (Prepared::new(s, width, height), s.fill_rule))
        .collect();
    let mut start = 0;
    while start < height {
        let rows = start..height.min(start.saturating_add(BAND));
        let mut all: Vec<(u32, u32, Value)> = Vec::new();
        for (p, rule) in &prepared {
            all.extend(
                p.band(width, &rows)
                    .into_iter()
                    .map(|(x, y, v)| (x, y, v.fold(*rule, semantics))),
            );
        }
        if prepared.len() > 1 {
            all.sort_by_key(|p| (p.1, p.0));
        }
        let mut summed = sum_places(all).into_iter().peekable();
        for y in rows.clone() {
            let mut row = Vec::new();
            while let Some((x, _, v)) = summed.next_if(|p| p.1 == y) {
                row.push((x, v));
            }
            emit(y, row);
        }
        start = rows.end;
    }
}

/// Values by place (sorted by row, then column), those at one place summed, zeros left
/// out, as big rationals.
fn sum_places(all: Vec<(u32, u32, Value)>) -> Vec<(u32, u32, BigRational)> {
    let mut pixels: Vec<(u32, u32, BigRational)> = Vec::with_capacity(all.len());
    let mut sum: Option<(u32, u32, Value)> = None;
    for (x, y, v) in all {
        sum = match sum {
            Some((sx, sy, acc)) if (sx, sy) == (x, y) => Some((x, y, acc.add(&v))),
            previous => {
                if let Some((sx, sy, acc)) = previous.filter(|(_, _, a)| !a.is_zero()) {
                    pixels.push((sx, sy, acc.big()));
                }
                Some((x, y, v))
            }
        };
    }
    if let Some((sx, sy, acc)) = sum.filter(|(_, _, a)| !a.is_zero()) {
        pixels.push((sx, sy, acc.big()));
    }
    pixels
}

/// The scene's coverage under `semantics`: the accumulated semantics by the planned walk
/// (each shape's value folded, summed over the shapes, as [`super::exact::rasterize`]
/// gives it), true coverage by the plain oracle.
///
/// ```
/// use num_rational::BigRational;
/// use rasterproof::area::{planned, Semantics};
/// use rasterproof::geom::{FillRule, Point, Polygon};
/// let p = |x: i64, y: i64| Point::new(BigRational::from_integer(x.into()), BigRational::from_integer(y.into()));
/// // The triangle (0,0) (2,0) (0,2): a whole pixel and two halves.
/// let t = Polygon::new(vec![p(0, 0), p(2, 0), p(0, 2)], FillRule::NonZero);
/// let image = planned::rasterize(&[t], 2, 2, Semantics::Accumulated);
/// let half = BigRational::new(1.into(), 2.into());
/// assert_eq!(image.pixels, vec![(0, 0, BigRational::from_integer(1.into())), (1, 0, half.clone()), (0, 1, half)]);
/// ```
pub fn rasterize(shapes: &[AreaShape], width: u32, height: u32, semantics: Semantics) -> AreaImage {
    if semantics == Semantics::True {
        return exact::rasterize(shapes, width, height, semantics);
    }
    let mut pixels = Vec::new();
    for_each_row(shapes, width, height, semantics, |y, row| {
        pixels.extend(row.into_iter().map(|(x, v)| (x, y, v)));
    });
    AreaImage {
        width,
        height,
        semantics,
        pixels,
    }
}
