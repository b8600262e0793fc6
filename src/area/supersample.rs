//! Coverage by supersampling, a contender: `k x k` point samples per pixel, at
//! `((i + 1/2) / k, (j + 1/2) / k)` from its top-left corner, each decided exactly by the
//! polygon oracle under the top-left rule, the count over `k^2` as the pixel's value. It is
//! what 2D renderers with `k` sub-scanlines approximate (tiny-skia supersamples 4, Skia's
//! supersampling path 16) and what a multisampling GPU resolves; its departures from the
//! exact area are at most a sample's share per crossing edge, and it adds up exactly
//! across a triangulation (each sample has one owner).
//!
//! Two roads to the same counts: the plain test ([`row_counts_with`]: each sample against
//! every edge, the reference) and the sweep ([`for_each_row_counts`]: each sample row's
//! edge crossings found once, exactly, and the row's samples counted between them), which
//! every drawing here uses; a property test holds them equal under every tie rule.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};

use super::{AreaImage, AreaShape, Semantics};
use crate::convention::{AnyTieRule, MovedSample};
use crate::fill::polygon::contains_exact_with;
use crate::geom::Point;

/// The shapes' supersampled coverage on a `width` x `height` canvas: for each pixel the
/// share of its `k x k` samples inside any shape (true coverage's counterpart), samples
/// on an edge decided by the top-left rule. `k` of 0 is read as 1. Drawn by the sweep
/// ([`for_each_row_counts`]), equal to [`pixel`] at every pixel.
pub fn rasterize(shapes: &[AreaShape], width: u32, height: u32, k: u32) -> AreaImage {
    let k = k.max(1);
    let of = BigInt::from(u64::from(k) * u64::from(k));
    let mut pixels = Vec::new();
    for_each_row_counts(shapes, width, height, k, AnyTieRule::TopLeft, |y, counts| {
        for (x, rows) in counts.chunks(k as usize).enumerate() {
            let n: u32 = rows.iter().sum();
            if n != 0 {
                let x = u32::try_from(x).unwrap_or(u32::MAX);
                pixels.push((x, y, BigRational::new(n.into(), of.clone())));
            }
        }
    });
    AreaImage {
        width,
        height,
        semantics: Semantics::True,
        pixels,
    }
}

/// Each pixel's count of samples inside any of `shapes`, out of `k x k` (row-major;
/// samples on an edge decided by `rule`; `k` of 0 read as 1), by the sweep.
pub fn counts(shapes: &[AreaShape], width: u32, height: u32, k: u32, rule: AnyTieRule) -> Vec<u32> {
    let k = k.max(1);
    let mut out = Vec::with_capacity(width as usize * height as usize);
    for_each_row_counts(shapes, width, height, k, rule, |_, counts| {
        out.extend(counts.chunks(k as usize).map(|rows| rows.iter().sum::<u32>()));
    });
    out
}

/// The sweep: for each pixel row `y`, top first, `emit(y, counts)` with, for each pixel
/// `x` of the row and each of its `k` sample rows `j` (top first), at `counts[x k + j]`,
/// how many of that sample row's `k` samples lie inside any of `shapes`, samples on an
/// edge decided by `rule`: what [`row_counts_with`] gives pixel by pixel (`k` of 0 read
/// as 1).
///
/// Each sample row is a horizontal line `y_s = (2r + 1) / 2k`. A directional rule tests
/// the sample moved by `(±ε, ±ε²)`, so an edge counts in the moved row's winding number
/// when its `y` range holds `y_s` half-open (closed at the top end for the rules that move
/// down, at the bottom end for those that move up), and its crossing `x_c` at `y_s`
/// (exact) is right of the moved sample when `x_c > x_s`, or `x_c = x_s` and the rule
/// moves left. So every crossing splits the row's sample columns once, and the winding
/// numbers of all the row's samples come from one pass over its crossings: a cost per
/// edge crossing, not per sample and edge. The two non-directional rules take a
/// directional rule's answer, and test again with [`contains_exact_with`] each sample
/// that lies on an edge (the only samples where the rules differ).
pub fn for_each_row_counts(
    shapes: &[AreaShape],
    width: u32,
    height: u32,
    k: u32,
    rule: AnyTieRule,
    emit: impl FnMut(u32, &[u32]),
) {
    sweep(shapes, (0, 0, width, height), k, rule, emit);
}

/// The sweep of [`for_each_row_counts`] over the window of `width x height` pixels whose
/// top-left pixel is `(x0, y0)`: `emit(y, counts)` for its rows `y` (canvas rows), the
/// counts of its pixels from `x0`.
fn sweep(
    shapes: &[AreaShape],
    (x0, y0, width, height): (u32, u32, u32, u32),
    k: u32,
    rule: AnyTieRule,
    mut emit: impl FnMut(u32, &[u32]),
) {
    let k = k.max(1);
    let columns = width as usize * k as usize;
    let window = Window {
        x: i64::from(x0)..i64::from(x0) + i64::from(width),
        y: i64::from(y0)..i64::from(y0) + i64::from(height),
    };
    let base = window.x.start * i64::from(k);
    let swept: Vec<SweptShape> = shapes.iter().map(|s| SweptShape::new(s, &window, k)).collect();
    let moved = rule.moved_sample().unwrap_or(MovedSample {
        right: true,
        down: true,
    });
    let mut counts = vec![0u32; columns];
    let mut mask = vec![false; columns * k as usize];
    for y in y0..y0.saturating_add(height) {
        counts.iter_mut().for_each(|c| *c = 0);
        mask.iter_mut().for_each(|m| *m = false);
        let first_row = i64::from(y) * i64::from(k);
        for (shape, sw) in shapes.iter().zip(&swept) {
            if !sw.rows.contains(&i64::from(y)) {
                continue;
            }
            for j in 0..k {
                let r = first_row + i64::from(j);
                let mut inside = sw.inside_row(shape, r, k, moved);
                if rule.moved_sample().is_none() {
                    sw.retest_on_edges(shape, r, k, rule, &mut inside);
                }
                let j = j as usize;
                let row = &mut mask[j * columns..(j + 1) * columns];
                let (c0, c1) = (sw.columns.start - base, sw.columns.end - base);
                for (slot, is) in row[index(c0)..index(c1)].iter_mut().zip(inside) {
                    *slot |= is;
                }
            }
        }
        for (j, row) in mask.chunks(columns).enumerate() {
            for (c, _) in row.iter().enumerate().filter(|(_, m)| **m) {
                counts[(c / k as usize) * k as usize + j] += 1;
            }
        }
        emit(y, &counts);
    }
}

/// A column or length the sweep has made non-negative, as an index.
fn index(v: i64) -> usize {
    usize::try_from(v).unwrap_or(0)
}

/// A big integer clamped into `i64`.
fn clamped(v: &BigInt) -> i64 {
    v.to_i64().unwrap_or(if v.is_negative() { i64::MIN } else { i64::MAX })
}

/// `2k v - 1` (exact): a coordinate in half sample steps, less the half step of the first
/// sample; the sample of index `i` is at `2i` of it.
fn half_steps(v: &BigRational, k: u32) -> BigRational {
    v * BigRational::from_integer(BigInt::from(2 * u64::from(k))) - BigRational::from_integer(1.into())
}

/// The pixels a sweep covers: columns `x`, rows `y`.
struct Window {
    x: std::ops::Range<i64>,
    y: std::ops::Range<i64>,
}

/// One shape as the sweep reads it: its contours' edges with the exact slopes, and the
/// pixel rows and sample columns its outline's box spans (the window's part of it).
struct SweptShape {
    /// Pixel rows `y` its outline meets.
    rows: std::ops::Range<i64>,
    /// Sample columns its outline meets (sample `c` at `x = (2c + 1) / 2k`).
    columns: std::ops::Range<i64>,
    /// Per contour (outline first), per edge `a -> b` with `dy != 0` that meets the
    /// window's rows: `dx / dy`.
    slopes: Vec<Vec<Option<BigRational>>>,
}

impl SweptShape {
    fn new(shape: &AreaShape, window: &Window, k: u32) -> SweptShape {
        let outline = &shape.outline;
        let bound = |f: &dyn Fn(&Point) -> &BigRational, lo: bool| {
            outline
                .iter()
                .map(f)
                .reduce(|a, b| if (b < a) == lo { b } else { a })
                .map_or(0, |v| clamped(&if lo { v.floor() } else { v.ceil() }.to_integer()))
        };
        let (x0, x1) = (bound(&|p| &p.x, true), bound(&|p| &p.x, false));
        let (y0, y1) = (bound(&|p| &p.y, true), bound(&|p| &p.y, false));
        let clamp = |v: i64, range: &std::ops::Range<i64>| v.clamp(range.start, range.end);
        let k = i64::from(k);
        let column = |v: i64| clamp(v, &window.x) * k;
        let contours = std::iter::once(outline).chain(&shape.holes);
        let (rows, columns) = (clamp(y0, &window.y)..clamp(y1, &window.y), column(x0)..column(x1));
        // A shape outside the window needs no slopes (the costly part: a division per edge).
        let outside = rows.is_empty() || columns.is_empty();
        let (top, bottom) = (
            BigRational::from_integer(window.y.start.into()),
            BigRational::from_integer(window.y.end.into()),
        );
        SweptShape {
            rows,
            columns,
            slopes: contours
                .filter(|_| !outside)
                .map(|c| {
                    edges(c)
                        .map(|(a, b)| {
                            // An edge that meets no sample row of the window needs no slope.
                            let (lo, hi) = if a.y <= b.y { (&a.y, &b.y) } else { (&b.y, &a.y) };
                            let away = *hi < top || *lo > bottom;
                            let dy = &b.y - &a.y;
                            (!dy.is_zero() && !away).then(|| (&b.x - &a.x) / dy)
                        })
                        .collect()
                })
                .collect(),
        }
    }

    /// For each sample column of its box (from `columns.start`), whether the sample of row
    /// `r` there, moved as `moved` says, lies inside `shape` (its outline's winding number
    /// inside by the fill rule, no hole's).
    fn inside_row(&self, shape: &AreaShape, r: i64, k: u32, moved: MovedSample) -> Vec<bool> {
        let (c0, c1) = (self.columns.start, self.columns.end);
        if c0 >= c1 {
            return Vec::new();
        }
        let n = index(c1 - c0);
        let y_s = BigRational::new((2 * r + 1).into(), BigInt::from(2 * u64::from(k)));
        let mut inside = vec![true; n];
        let contours = std::iter::once(&shape.outline).chain(&shape.holes);
        for (nth, (contour, slopes)) in contours.zip(&self.slopes).enumerate() {
            // winding(c) = the sum of the crossings right of sample c: each crossing adds its
            // count to the columns before its boundary (a difference array).
            let mut diff = vec![0i64; n + 1];
            for ((a, b), slope) in edges(contour).zip(slopes) {
                let Some(slope) = slope else { continue };
                let (lo, hi) = if a.y <= b.y { (&a.y, &b.y) } else { (&b.y, &a.y) };
                let crosses = if moved.down {
                    *lo <= y_s && y_s < *hi
                } else {
                    *lo < y_s && y_s <= *hi
                };
                if !crosses {
                    continue;
                }
                let x_c = &a.x + (&y_s - &a.y) * slope;
                let u = half_steps(&x_c, k) / BigRational::from_integer(2.into());
                // The first sample column right of the crossing.
                let first_right = if moved.right {
                    u.ceil().to_integer()
                } else {
                    u.floor().to_integer() + 1
                };
                let boundary = index(clamped(&first_right).clamp(c0, c1) - c0);
                let w = if b.y > a.y { -1 } else { 1 };
                diff[0] += w;
                diff[boundary] -= w;
            }
            let mut winding = 0i64;
            for (c, slot) in inside.iter_mut().enumerate() {
                winding += diff[c];
                let filled = shape.fill_rule.inside(winding);
                *slot &= if nth == 0 { filled } else { !filled };
            }
        }
        inside
    }

    /// Under a rule that moves no sample (all-inclusive, all-exclusive): tests again, with
    /// [`contains_exact_with`], each sample of row `r` that lies on an edge of `shape`
    /// (the others have every rule's answer): `inside` as [`SweptShape::inside_row`] gives
    /// it, corrected there.
    fn retest_on_edges(&self, shape: &AreaShape, r: i64, k: u32, rule: AnyTieRule, inside: &mut [bool]) {
        let c0 = self.columns.start;
        let k2 = BigInt::from(2 * u64::from(k));
        let y_s = BigRational::new((2 * r + 1).into(), k2.clone());
        for c in self.on_edges(shape, r, k) {
            let p = Point::new(BigRational::new((2 * c + 1).into(), k2.clone()), y_s.clone());
            inside[index(c - c0)] = contains_exact_with(&p, shape, rule);
        }
    }

    /// The sample columns of its box whose sample of row `r` lies on an edge of `shape`
    /// (endpoints included), in order, each once: the samples whose answer depends on the
    /// tie rule.
    fn on_edges(&self, shape: &AreaShape, r: i64, k: u32) -> Vec<i64> {
        let (c0, c1) = (self.columns.start, self.columns.end);
        if c0 >= c1 || !self.rows.contains(&r.div_euclid(i64::from(k))) {
            return Vec::new();
        }
        let y_s = BigRational::new((2 * r + 1).into(), BigInt::from(2 * u64::from(k)));
        let two = BigRational::from_integer(2.into());
        let mut on_edge: Vec<i64> = Vec::new();
        let contours = std::iter::once(&shape.outline).chain(&shape.holes);
        for (contour, slopes) in contours.zip(&self.slopes) {
            for ((a, b), slope) in edges(contour).zip(slopes) {
                let (lo, hi) = if a.y <= b.y { (&a.y, &b.y) } else { (&b.y, &a.y) };
                if y_s < *lo || y_s > *hi {
                    continue;
                }
                match slope {
                    Some(slope) => {
                        let u = half_steps(&(&a.x + (&y_s - &a.y) * slope), k) / &two;
                        if u.is_integer() {
                            on_edge.push(clamped(&u.to_integer()));
                        }
                    }
                    None => {
                        let (left, right) = if a.x <= b.x { (&a.x, &b.x) } else { (&b.x, &a.x) };
                        let first = clamped(&(half_steps(left, k) / &two).ceil().to_integer()).max(c0);
                        let last = clamped(&(half_steps(right, k) / &two).floor().to_integer()).min(c1 - 1);
                        on_edge.extend(first..=last);
                    }
                }
            }
        }
        on_edge.sort_unstable();
        on_edge.dedup();
        on_edge.retain(|c| (c0..c1).contains(c));
        on_edge
    }
}

/// A contour's closed edges `(a, b)`, the last back to the first.
fn edges(contour: &[Point]) -> impl Iterator<Item = (&Point, &Point)> {
    contour.iter().zip(contour.iter().cycle().skip(1))
}

/// Pixel `(x, y)`'s supersampled value: the share of its `k x k` samples inside any shape
/// (`k` of 0 read as 1), samples on an edge decided by the top-left rule; by the sweep
/// over the one pixel ([`pixel_row_counts`]).
pub fn pixel(shapes: &[AreaShape], x: u32, y: u32, k: u32) -> BigRational {
    let k = k.max(1);
    let count: u32 = pixel_row_counts(shapes, x, y, k, AnyTieRule::TopLeft).iter().sum();
    BigRational::new(count.into(), (u64::from(k) * u64::from(k)).into())
}

/// [`row_counts_with`], by the sweep of [`for_each_row_counts`] over the one pixel: the
/// cost of the edges that cross its sample rows, not of every sample against every edge.
pub fn pixel_row_counts(shapes: &[AreaShape], x: u32, y: u32, k: u32, rule: AnyTieRule) -> Vec<u32> {
    let mut out = Vec::new();
    sweep(shapes, (x, y, 1, 1), k, rule, |_, counts| out = counts.to_vec());
    out
}

/// How many of pixel `(x, y)`'s samples inside any shape lie in each of its `k` sample
/// rows, top to bottom (`k` of 0 read as 1), samples on an edge decided by the top-left
/// rule: the plain test, each sample against every edge ([`contains_exact_with`]), the
/// reference the sweep is tested against.
pub fn row_counts(shapes: &[AreaShape], x: u32, y: u32, k: u32) -> Vec<u32> {
    row_counts_with(shapes, x, y, k, AnyTieRule::TopLeft)
}

/// [`row_counts`] with samples on an edge decided by `rule` (the plain test).
pub fn row_counts_with(shapes: &[AreaShape], x: u32, y: u32, k: u32, rule: AnyTieRule) -> Vec<u32> {
    let k = k.max(1);
    let step = |i: u32| BigRational::new((2 * i64::from(i) + 1).into(), (2 * i64::from(k)).into());
    (0..k)
        .map(|j| {
            let inside = (0..k).filter(|&i| {
                let p = Point::new(
                    BigRational::from_integer(x.into()) + step(i),
                    BigRational::from_integer(y.into()) + step(j),
                );
                shapes.iter().any(|s| contains_exact_with(&p, s, rule))
            });
            u32::try_from(inside.count()).unwrap_or(u32::MAX)
        })
        .collect()
}

/// Pixel `(x, y)`'s supersampled value under each tie rule of [`AnyTieRule::ALL`] (the
/// share of its `k x k` samples inside any shape, samples on an edge decided by that rule),
/// each value once.
pub fn pixel_under_each_rule(shapes: &[AreaShape], x: u32, y: u32, k: u32) -> Vec<BigRational> {
    let k = k.max(1);
    let window = Window {
        x: i64::from(x)..i64::from(x) + 1,
        y: i64::from(y)..i64::from(y) + 1,
    };
    // A sample on no edge has every rule's answer: with none, one sweep gives the value.
    let first_row = i64::from(y) * i64::from(k);
    let ties = shapes.iter().any(|s| {
        let swept = SweptShape::new(s, &window, k);
        (first_row..first_row + i64::from(k)).any(|r| !swept.on_edges(s, r, k).is_empty())
    });
    let rules: &[AnyTieRule] = if ties { &AnyTieRule::ALL } else { &[AnyTieRule::TopLeft] };
    let mut out: Vec<BigRational> = Vec::new();
    for &rule in rules {
        let count: u32 = pixel_row_counts(shapes, x, y, k, rule).iter().sum();
        let v = BigRational::new(count.into(), (u64::from(k) * u64::from(k)).into());
        if !out.contains(&v) {
            out.push(v);
        }
    }
    out
}

/// The 8-bit levels of tiny-skia's anti-aliased fill (after Skia's supersampling
/// scan converter, `SkScan_AntiPath.cpp`; tiny-skia's `scan/path_aa.rs`), from exact 4 x 4
/// samples, row by row: four sub-scanlines per pixel, each adding 16 per sample inside,
/// except that a sub-scanline whose four samples are all inside adds the full-run value
/// `64 - 1` on the pixel's last (bottom) sub-scanline, so that a whole pixel is 255, not
/// 256. A pixel is `16 n`, less 1 when its bottom sample row is full. A sample on an edge
/// goes by the bottom-right rule: its edges' rows start and its spans' ends are rounded
/// half up (`SkFDot6Round`), so a bottom or right edge takes the samples on it, a top or
/// left edge does not (tiny-skia 0.11.4 draws 64 for the top eighth of a pixel, 0 for the
/// bottom eighth). Shapes are taken as one union of samples (tiny-skia composites separate
/// paths source-over: [`super::conflate`]), and tiny-skia's own fixed-point edges can move
/// a sample that lies within about 1/256 px of an edge.
pub fn tiny_skia_levels(shapes: &[AreaShape], width: u32, height: u32) -> Vec<u8> {
    let mut out = Vec::with_capacity(width as usize * height as usize);
    for_each_row_counts(shapes, width, height, 4, AnyTieRule::BottomRight, |_, counts| {
        out.extend(counts.chunks(4).map(|rows| {
            let n: u32 = rows.iter().sum();
            let level = 16 * n - u32::from(rows[3] == 4);
            u8::try_from(level.min(255)).unwrap_or(u8::MAX)
        }));
    });
    out
}
