//! Coverage composited shape by shape, a contender: each shape's coverage computed on its
//! own and blended *source-over* onto what the shapes before it left, as a 2D renderer
//! does when it fills one path at a time with an opaque colour and anti-aliasing (Porter
//! and Duff, "Compositing Digital Images", SIGGRAPH 1984: `over` with opaque sources of
//! alpha `a` and `b` gives `1 - (1 - a)(1 - b)`).
//!
//! Two shapes that abut along an edge through a pixel cover `a + b` of it together (the
//! exact union, or the sum of the folded accumulated values), but blending gives
//! `a + b - ab`: the background shows through the seam, by exactly `ab`. This is the
//! *conflation artefact* of 2D renderers (Kilgard and Bolz, "GPU-accelerated path
//! rendering", 2012, §5; Skia's and Vello's seams between abutting paths). Each shape's
//! own value is exact (the plain oracle, [`super::exact::value`]) or, for a renderer that
//! supersamples, its `k x k` share ([`super::supersample::pixel`]): [`pixel`] composes
//! whichever it is given.

use num_rational::BigRational;
use num_traits::{One, Zero};

use super::{exact, supersample, AreaImage, AreaShape, Semantics};
use crate::geom::Polygon;

/// How each shape's own value is computed before the shapes are blended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Own {
    /// The exact area under a semantics.
    Exact(Semantics),
    /// The share of `k x k` samples covered.
    Supersampled(u32),
}

/// Each shape's pixel box (the pixels its bounding box meets; a pixel outside has a value
/// of zero), computed once per scene for [`own_values`], which asks at every pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Boxes(Vec<Option<(i64, i64, i64, i64)>>);

impl Boxes {
    /// The boxes of `shapes`, in order.
    pub fn of(shapes: &[AreaShape]) -> Boxes {
        Boxes(shapes.iter().map(pixel_box).collect())
    }

    /// Whether shape `k`'s box holds pixel `(x, y)`.
    fn meets(&self, k: usize, x: u32, y: u32) -> bool {
        self.0.get(k).copied().flatten().is_some_and(|b| meets(b, x, y))
    }
}

/// The pixels `(x0, y0, x1, y1)` (half-open) that the shape's bounding box meets, or
/// `None` for a shape with no vertex. A pixel outside it has a value of zero.
fn pixel_box(shape: &AreaShape) -> Option<(i64, i64, i64, i64)> {
    let mut points = shape.contours().flatten();
    let first = points.next()?;
    let (mut lo_x, mut hi_x, mut lo_y, mut hi_y) = (&first.x, &first.x, &first.y, &first.y);
    for p in points {
        lo_x = lo_x.min(&p.x);
        hi_x = hi_x.max(&p.x);
        lo_y = lo_y.min(&p.y);
        hi_y = hi_y.max(&p.y);
    }
    let whole = |v: &BigRational, up: bool| {
        let w = if up { v.ceil() } else { v.floor() };
        num_traits::ToPrimitive::to_i64(&w.to_integer()).unwrap_or(if up { i64::MAX } else { i64::MIN })
    };
    Some((
        whole(lo_x, false),
        whole(lo_y, false),
        whole(hi_x, true),
        whole(hi_y, true),
    ))
}

/// Whether pixel `(x, y)` lies in the box.
fn meets(b: (i64, i64, i64, i64), x: u32, y: u32) -> bool {
    let (x, y) = (i64::from(x), i64::from(y));
    b.0 <= x && x < b.2 && b.1 <= y && y < b.3
}

/// Pixel `(x, y)`'s value with the shapes blended one by one, each shape's own value
/// computed as `own` says: `1 - (1 - a_1)(1 - a_2)...`, each `a_i` clamped to `[0, 1]`
/// first (an opaque source's alpha).
///
/// ```
/// use num_rational::BigRational;
/// use rasterproof::area::conflate::{pixel, Own};
/// use rasterproof::area::Semantics;
/// use rasterproof::geom::{FillRule, Point, Polygon};
/// let square = |x0: i64, x1: i64| {
///     let p = |x: i64, y: i64| Point::new(BigRational::new(x.into(), 2.into()), BigRational::from_integer(y.into()));
///     Polygon::new(vec![p(x0, 0), p(x1, 0), p(x1, 2), p(x0, 2)], FillRule::NonZero)
/// };
/// // Two halves of pixel (0, 0), side by side: 1/2 + 1/2 exactly, 3/4 blended.
/// let halves = [square(0, 1), square(1, 2)];
/// let v = pixel(&halves, 0, 0, Own::Exact(Semantics::True));
/// assert_eq!(v, BigRational::new(3.into(), 4.into()));
/// ```
pub fn pixel(shapes: &[AreaShape], x: u32, y: u32, own: Own) -> BigRational {
    blend(&own_values(shapes, &Boxes::of(shapes), x, y, own))
}

/// The shapes' own values at pixel `(x, y)` that are not zero, in shape order, each
/// clamped to `[0, 1]` (what [`pixel`] blends; two or more is where conflation can show).
/// `boxes` are the shapes' ([`Boxes::of`]), computed once for every pixel asked.
pub fn own_values(shapes: &[AreaShape], boxes: &Boxes, x: u32, y: u32, own: Own) -> Vec<BigRational> {
    shapes
        .iter()
        .enumerate()
        .filter(|(k, _)| boxes.meets(*k, x, y))
        .map(|(_, shape)| value(shape, x, y, own).max(BigRational::zero()).min(BigRational::one()))
        .filter(|a| !a.is_zero())
        .collect()
}

/// `1 - (1 - a_1)(1 - a_2)...`: opaque sources of alphas `a_i` blended over each other.
pub fn blend(alphas: &[BigRational]) -> BigRational {
    let through: BigRational = alphas.iter().map(|a| BigRational::one() - a).product();
    BigRational::one() - through
}

/// One shape's own value at pixel `(x, y)`.
fn value(shape: &Polygon, x: u32, y: u32, own: Own) -> BigRational {
    let one = std::slice::from_ref(shape);
    match own {
        Own::Exact(semantics) => exact::value(one, i64::from(x), i64::from(y), semantics),
        Own::Supersampled(k) => supersample::pixel(one, x, y, k),
    }
}

/// The shapes blended one by one on a `width` x `height` canvas, each shape's own value
/// exact under `semantics` (every pixel some shape's bounding box meets, by [`pixel`]).
pub fn rasterize(shapes: &[AreaShape], width: u32, height: u32, semantics: Semantics) -> AreaImage {
    let boxes = Boxes::of(shapes);
    let mut pixels = Vec::new();
    for y in 0..height {
        for x in 0..width {
            if !(0..shapes.len()).any(|k| boxes.meets(k, x, y)) {
                continue;
            }
            let v = blend(&own_values(shapes, &boxes, x, y, Own::Exact(semantics)));
            if !v.is_zero() {
                pixels.push((x, y, v));
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
