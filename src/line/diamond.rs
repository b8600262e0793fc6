//! The diamond-exit rule (D3D11 §3.4.3, Vulkan's and GL's "diamond-exit" lines) in exact
//! integer arithmetic on snapped endpoints: a pixel is drawn when the segment, travelling
//! from start to end, leaves the pixel's diamond test area `|x - xc| + |y - yc| < 1/2`
//! (plus the boundary parts of [`super::exact::diamond_contains`]). Half-open: the last
//! pixel is not drawn when the end lies in its diamond; a zero-length line draws nothing.
//!
//! The test per pixel is the one of [`super::exact::diamond_exits`], in i128 homogeneous
//! coordinates: a point `a + (n/m) d` is tested as `(ua m + dx n, va m + dy n)` against
//! radius `r m`. Bounds (endpoints inside the 2^29-subpixel envelope, samples below
//! 2^30): `|ua| < 2^31`, `|d| <= 2^30`, clip parameters `n/m` with `|n| < 2^34`,
//! `0 < m < 2^32`; their midpoint has `|n| < 2^67`, `m < 2^65`, so every product stays
//! below 2^99, far inside i128. Only candidate pixels are tested: per step of the major
//! axis, the five pixels around the line.

use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::num::SubPixel;
use crate::raster::FixedGrid;

/// A segment snapped to the 2^-bits grid, inside the integer envelope.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FixedSegment {
    /// Start `[x, y]` in subpixels.
    pub a: [SubPixel; 2],
    /// End `[x, y]` in subpixels.
    pub b: [SubPixel; 2],
    /// The grid.
    pub bits: u32,
}

/// [`super::exact::diamond_contains`] on scaled integers.
fn contains(u: i128, v: i128, r: i128, x_major: bool) -> bool {
    let s = u.abs() + v.abs();
    if s != r {
        return s < r;
    }
    match v.signum() {
        1 => true,
        -1 => false,
        _ => u > 0 && !x_major,
    }
}

/// `n0/m0 < n1/m1` for positive denominators.
fn less(t0: (i128, i128), t1: (i128, i128)) -> bool {
    t0.0 * t1.1 < t1.0 * t0.1
}

/// What the per-pixel test needs of a segment, computed once per segment: the grid, the
/// endpoints and direction in i128, the diamond radius, the major axis.
struct Prepared {
    one: i128,
    c: i128,
    r: i128,
    a: [i128; 2],
    b: [i128; 2],
    d: [i128; 2],
    x_major: bool,
}

impl Prepared {
    /// # Panics
    /// When `seg` was snapped to another grid than `target`'s subpixel bits.
    fn new(seg: &FixedSegment, target: &Target) -> Prepared {
        let conv = &target.convention;
        assert_eq!(
            seg.bits, conv.subpixel_bits,
            "segment snapped to another grid than the target's"
        );
        let grid = FixedGrid::of(conv);
        let one = i128::from(grid.one);
        let a = seg.a.map(|v| i128::from(v.get()));
        let b = seg.b.map(|v| i128::from(v.get()));
        let d = [b[0] - a[0], b[1] - a[1]];
        Prepared {
            one,
            c: i128::from(grid.centre),
            r: one / 2,
            a,
            b,
            d,
            x_major: d[0].abs() >= d[1].abs(),
        }
    }

    /// Whether the segment draws pixel `(i, j)`.
    fn exits(&self, i: i64, j: i64) -> bool {
        let Prepared {
            one,
            c,
            r,
            a: [ax, ay],
            b: [bx, by],
            d: [dx, dy],
            x_major,
        } = *self;
        let (cx, cy) = (i128::from(i) * one + c, i128::from(j) * one + c);
        if contains(bx - cx, by - cy, r, x_major) {
            return false;
        }
        let (ua, va) = (ax - cx, ay - cy);
        let (mut t0, mut t1) = ((0i128, 1i128), (1i128, 1i128));
        for (su, sv) in [(1, 1), (1, -1), (-1, 1), (-1, -1)] {
            let g0 = su * ua + sv * va;
            let g1 = su * dx + sv * dy;
            if g1 == 0 {
                if g0 > r {
                    return false;
                }
            } else if g1 > 0 {
                let t = (r - g0, g1);
                if less(t, t1) {
                    t1 = t;
                }
            } else {
                let t = (g0 - r, -g1);
                if less(t0, t) {
                    t0 = t;
                }
            }
        }
        if less(t1, t0) {
            return false;
        }
        let mid = (t0.0 * t1.1 + t1.0 * t0.1, 2 * t0.1 * t1.1);
        [t0, t1, mid]
            .iter()
            .any(|&(n, m)| contains(ua * m + dx * n, va * m + dy * n, r * m, x_major))
    }
}

/// Whether the segment draws pixel `(i, j)`.
///
/// # Panics
/// When `seg` was snapped to another grid than `target`'s subpixel bits.
pub fn exits(seg: &FixedSegment, i: i64, j: i64, target: &Target) -> bool {
    Prepared::new(seg, target).exits(i, j)
}

/// Draws the segment: for each step of its major axis across the canvas, tests the five
/// pixels nearest the line.
///
/// # Panics
/// When `seg` was snapped to another grid than `target`'s subpixel bits.
pub fn draw<S: CoverageSink + ?Sized>(seg: &FixedSegment, id: u32, target: &Target, sink: &mut S) {
    let prepared = Prepared::new(seg, target);
    let conv = &target.convention;
    let FixedGrid { one, centre: c } = FixedGrid::of(conv);
    let [ax, ay] = seg.a.map(SubPixel::get);
    let [bx, by] = seg.b.map(SubPixel::get);
    let (dx, dy) = (bx - ax, by - ay);
    if dx == 0 && dy == 0 {
        return; // a point never leaves a diamond
    }
    let x_major = dx.abs() >= dy.abs();
    // (major, minor) views of the endpoints and the canvas
    let (a_maj, a_min, d_maj, d_min) = if x_major { (ax, ay, dx, dy) } else { (ay, ax, dy, dx) };
    let (side_maj, side_min) = if x_major {
        (target.width, target.height)
    } else {
        (target.height, target.width)
    };
    let b_maj = a_maj + d_maj;
    let first = (a_maj.min(b_maj) - c).div_euclid(one) - 1;
    let last = (a_maj.max(b_maj) - c).div_euclid(one) + 1;
    let first = first.max(0);
    let last = last.min(i64::from(side_maj) - 1);
    for k in first..=last {
        // the line's minor coordinate at this step's sample, as num / den (den > 0)
        let s = k * one + c;
        let (num, den) = (
            i128::from(a_min) * i128::from(d_maj) + i128::from(s - a_maj) * i128::from(d_min),
            i128::from(d_maj),
        );
        let (num, den) = if den < 0 { (-num, -den) } else { (num, den) };
        // row index nearest: floor((minor - c) / one)
        let near = (num - i128::from(c) * den).div_euclid(den * i128::from(one));
        let near = i64::try_from(near).expect("inside the envelope");
        for m in (near - 2).max(0)..=(near + 2).min(i64::from(side_min) - 1) {
            let (i, j) = if x_major { (k, m) } else { (m, k) };
            if prepared.exits(i, j) {
                let on_canvas = |v: i64| u32::try_from(v).expect("clamped to the canvas");
                sink.cover(on_canvas(i), on_canvas(j), id);
            }
        }
    }
}
