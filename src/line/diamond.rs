//! The diamond-exit rule (D3D11 §3.4.3, Vulkan's and GL's "diamond-exit" lines) in exact
//! integer arithmetic on snapped endpoints: a pixel is drawn when the segment, travelling
//! from start to end, leaves the pixel's diamond test area `|x - xc| + |y - yc| < 1/2`
//! (plus the boundary parts of [`super::exact::diamond_contains`]). Half-open: the last
//! pixel is not drawn when the end lies in its diamond; a zero-length line draws nothing.
//!
//! The test per pixel is the one of [`super::exact::diamond_exits`], in homogeneous integer
//! coordinates: a point `a + (n/m) d` is tested as `(ua m + dx n, va m + dy n)` against
//! radius `r m`. Bounds (endpoints inside the 2^29-subpixel envelope, samples below
//! 2^30): `|ua| < 2^31`, `|d| <= 2^30`, clip parameters `n/m` with `|n| < 2^34`,
//! `0 < m < 2^32`; their midpoint has `|n| < 2^67`, `m < 2^65`, so every product stays
//! below 2^99, far inside i128. Only candidate pixels are tested: per step of the major
//! axis, the two pixels whose centres bracket the line (see [`rasterize`] for why no other
//! can be drawn).
//!
//! The width is planned per segment ([`rasterize`]): in terms of `D = max(|dx|, |dy|, 1)` and
//! `U`, the largest `|ua|`, `|va|` (or of `b`) over the candidate pixels, every value of the
//! test is at most `32 U D^2 + 8 r D^2` (derived at `fits_i64`). When that is below
//! `2^63` the test runs in i64 (lines up to about 2500 px at 8 subpixel bits), else in
//! i128. [`exits`], which may be asked about any pixel, always runs in i128.

use num_traits::{PrimInt, Signed};

use crate::convention::Target;
use crate::coverage::CoverageSink;
use crate::num::dda::CeilDda64;
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

/// The integer widths the per-pixel test runs in (i64 and i128).
trait Wide: PrimInt + Signed {
    /// `v`, exactly.
    fn of(v: i64) -> Self;
}

impl Wide for i64 {
    #[inline(always)]
    fn of(v: i64) -> Self {
        v
    }
}

impl Wide for i128 {
    #[inline(always)]
    fn of(v: i64) -> Self {
        i128::from(v)
    }
}

/// [`super::exact::diamond_contains`] on scaled integers.
#[inline]
fn contains<T: Wide>(u: T, v: T, r: T, x_major: bool) -> bool {
    let s = u.abs() + v.abs();
    if s != r {
        return s < r;
    }
    if v.is_positive() {
        true
    } else if v.is_negative() {
        false
    } else {
        u.is_positive() && !x_major
    }
}

/// `n0/m0 < n1/m1` for positive denominators.
#[inline]
fn less<T: Wide>(t0: (T, T), t1: (T, T)) -> bool {
    t0.0 * t1.1 < t1.0 * t0.1
}

/// What the per-pixel test needs of a segment, computed once per segment: the grid, the
/// endpoints and direction, the diamond radius, the major axis.
struct Prepared<T> {
    one: T,
    c: T,
    r: T,
    a: [T; 2],
    b: [T; 2],
    d: [T; 2],
    x_major: bool,
}

impl<T: Wide> Prepared<T> {
    /// # Panics
    /// When `seg` was snapped to another grid than `target`'s subpixel bits.
    fn new(seg: &FixedSegment, target: &Target) -> Prepared<T> {
        let conv = &target.convention;
        assert_eq!(
            seg.bits, conv.subpixel_bits,
            "segment snapped to another grid than the target's"
        );
        let grid = FixedGrid::of(conv);
        let one = T::of(grid.one);
        let a = seg.a.map(|v| T::of(v.get()));
        let b = seg.b.map(|v| T::of(v.get()));
        let d = [b[0] - a[0], b[1] - a[1]];
        Prepared {
            one,
            c: T::of(grid.centre),
            r: one / T::of(2),
            a,
            b,
            d,
            x_major: d[0].abs() >= d[1].abs(),
        }
    }

    /// Whether the segment draws pixel `(i, j)`.
    #[inline]
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
        let (zero, unit) = (T::zero(), T::one());
        let (cx, cy) = (T::of(i) * one + c, T::of(j) * one + c);
        if contains(bx - cx, by - cy, r, x_major) {
            return false;
        }
        let (ua, va) = (ax - cx, ay - cy);
        let (mut t0, mut t1) = ((zero, unit), (unit, unit));
        for (su, sv) in [(true, true), (true, false), (false, true), (false, false)] {
            let signed = |v: T, plus: bool| if plus { v } else { -v };
            let g0 = signed(ua, su) + signed(va, sv);
            let g1 = signed(dx, su) + signed(dy, sv);
            if g1 == zero {
                if g0 > r {
                    return false;
                }
            } else if g1 > zero {
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
        let mid = (t0.0 * t1.1 + t1.0 * t0.1, T::of(2) * t0.1 * t1.1);
        [t0, t1, mid]
            .iter()
            .any(|&(n, m)| contains(ua * m + dx * n, va * m + dy * n, r * m, x_major))
    }
}

/// Whether [`rasterize`]'s per-pixel test of `seg` fits i64.
///
/// The bound, with `D = max(|dx|, |dy|, 1)`, `U` at least every `|ua|`, `|va|`, `|ub|`,
/// `|vb|` (a candidate pixel's centre to an endpoint, per axis) and `r` the radius:
/// `|g0| <= 2U`, `|g1| <= 2D`, so a clip parameter has `|n| <= 2U + r`, `0 < m <= 2D`
/// (or is 0/1, 1/1); a product in `less` is at most `(2U + r) 2D`; the midpoint has
/// `|n| <= 4D (2U + r)`, `m <= 8 D^2`; then `|ua m + dx n| <= 8 U D^2 + 4 D^2 (2U + r)
/// = 16 U D^2 + 4 r D^2`, and the sum of two such in `contains` at most
/// `32 U D^2 + 8 r D^2`, which bounds every value (`r m <= 8 r D^2` too).
///
/// `U`: [`rasterize`] tests major steps from one before the first endpoint's to one after the
/// last's (samples within `|d| + 2` pixels of `a` on the major axis) and, on the minor
/// axis, the pixels within two of the line's (at most two pixels past the endpoints,
/// the slope being at most 1), centres within `|d| + 5` pixels of `a`; likewise for `b`.
/// `U = D + 8` pixels covers both with room.
fn fits_i64(seg: &FixedSegment, target: &Target) -> bool {
    let grid = FixedGrid::of(&target.convention);
    let [ax, ay] = seg.a.map(|v| i128::from(v.get()));
    let [bx, by] = seg.b.map(|v| i128::from(v.get()));
    let d = (bx - ax).abs().max((by - ay).abs()).max(1);
    let u = d + 8 * i128::from(grid.one);
    let r = i128::from(grid.one) / 2;
    // In the envelope d, u < 2^32: every product here is below 2^102.
    32 * u * d * d + 8 * r * d * d <= i128::from(i64::MAX)
}

/// Whether the segment draws pixel `(i, j)`.
///
/// # Panics
/// When `seg` was snapped to another grid than `target`'s subpixel bits.
pub fn exits(seg: &FixedSegment, i: i64, j: i64, target: &Target) -> bool {
    Prepared::<i128>::new(seg, target).exits(i, j)
}

/// Draws the segment: for each step of its major axis across the canvas, tests the two
/// pixels whose centres bracket the line on the minor axis, in i64 when `fits_i64` shows
/// the test's values fit, else in i128.
///
/// Why two suffice (x-major names; `|slope| <= 1`): a pixel is drawn only if the segment
/// meets its closed test area, some `(x, y)` on it with `|x - xc| + |y - yc| <= 1/2`. The
/// line through the segment is at `y(xc)` at the pixel's sample column, and
/// `|y(xc) - yc| <= |y(x) - yc| + |slope| |x - xc| <= 1/2`. With `near` the row whose
/// centre is the last at or before `y(xc)`, the centres within 1/2 of `y(xc)` are those of
/// `near` and `near + 1` only (the next ones are a whole pixel further).
///
/// # Panics
/// When `seg` was snapped to another grid than `target`'s subpixel bits.
pub fn rasterize<S: CoverageSink + ?Sized>(seg: &FixedSegment, id: u32, target: &Target, sink: &mut S) {
    if fits_i64(seg, target) {
        draw_in::<i64, S>(seg, id, target, sink);
    } else {
        draw_in::<i128, S>(seg, id, target, sink);
    }
}

/// [`rasterize`] with the per-pixel test in `T`.
fn draw_in<T: Wide, S: CoverageSink + ?Sized>(seg: &FixedSegment, id: u32, target: &Target, sink: &mut S) {
    let prepared = Prepared::<T>::new(seg, target);
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
    if first > last {
        return;
    }
    // The row nearest the line at each step's sample: floor((minor - c) / one), with the
    // line's minor coordinate num / den (den = |d_maj| > 0) and num growing by
    // sign * one * d_min per step, walked as a DDA (a floor is the ceil of v - (D - 1)).
    // In i64: num - c den is an edge value at a canvas sample (one step past the last
    // included), below 3.1 * 2^60 inside the envelope (see `crate::num::fixed`), and
    // D = den * one <= 2^46: within CeilDda64's 2^62.
    let (sign, den) = (d_maj.signum(), d_maj.abs());
    let value = |k: i64| sign * (a_min * d_maj + (k * one + c - a_maj) * d_min) - c * den;
    let big_d = den * one;
    let mut nearest = CeilDda64::new(value(first) - (big_d - 1), sign * one * d_min, big_d);
    for k in first..=last {
        let near = nearest.get();
        debug_assert_eq!(near, value(k).div_euclid(big_d), "the DDA is the division");
        nearest.step();
        for m in near.max(0)..=(near + 1).min(i64::from(side_min) - 1) {
            let (i, j) = if x_major { (k, m) } else { (m, k) };
            if prepared.exits(i, j) {
                let on_canvas = |v: i64| u32::try_from(v).expect("clamped to the canvas");
                sink.cover(on_canvas(i), on_canvas(j), id);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::Preset;
    use crate::coverage::Coverage;
    use crate::geom::Point;

    fn segment(a: [i64; 2], b: [i64; 2]) -> FixedSegment {
        let sub = |v: i64| SubPixel::new(v).expect("inside the envelope");
        FixedSegment {
            a: a.map(sub),
            b: b.map(sub),
            bits: 8,
        }
    }

    fn drawn_in<T: Wide>(seg: &FixedSegment, target: &Target) -> Coverage {
        let mut c = Coverage::new(target.width, target.height);
        draw_in::<T, _>(seg, 0, target, &mut c);
        c
    }

    /// The plain exact reading ([`super::super::exact::diamond_exits`]) over the pixels
    /// the candidate walk may visit: rows and columns within three of the segment's box.
    fn exact_reading(seg: &FixedSegment, target: &Target) -> Coverage {
        let point = |p: [SubPixel; 2]| Point::from_fractions(p[0].get(), 256, p[1].get(), 256);
        let (a, b) = (point(seg.a), point(seg.b));
        let mut c = Coverage::new(target.width, target.height);
        let px = |v: SubPixel| v.get().div_euclid(256);
        let (x0, x1) = (px(seg.a[0]).min(px(seg.b[0])) - 3, px(seg.a[0]).max(px(seg.b[0])) + 3);
        let (y0, y1) = (px(seg.a[1]).min(px(seg.b[1])) - 3, px(seg.a[1]).max(px(seg.b[1])) + 3);
        let w = i64::from(target.width) - 1;
        let h = i64::from(target.height) - 1;
        for j in y0.max(0)..=y1.min(h) {
            for i in x0.max(0)..=x1.min(w) {
                if super::super::exact::diamond_exits(&a, &b, i, j, target) {
                    c.cover(u32::try_from(i).unwrap(), u32::try_from(j).unwrap(), 0);
                }
            }
        }
        c
    }

    /// The plan's edge, by hand: at 8 subpixel bits (`one = 256`, `r = 128`, so
    /// `U = D + 2048`) the bound `32 (D + 2048) D^2 + 1024 D^2` is
    /// 9_223_335_120_456_382_464 at D = 659_868, below `2^63 - 1` =
    /// 9_223_372_036_854_775_807, and 9_223_377_009_236_057_248 at D = 659_869, above it.
    /// At 659_868 the segment draws in i64, at 659_869 in i128, and both draw what the
    /// exact reading draws, in either width.
    #[test]
    fn both_sides_of_the_i64_plan_equal_the_exact_reading() {
        let target = Target::new(48, 40, Preset::D3d11.convention()).unwrap();
        // A shallow line starting on the canvas and ending far off it: the canvas part is
        // small, the length sets the plan.
        let seg_of = |d: i64| segment([300, 2000], [300 + d, 2000 + d / 5]);
        let fits = |d: i64| fits_i64(&seg_of(d), &target);
        let lo = crate::num::last_where(1 << 10, 1 << 22, fits);
        let hi = lo + 1;
        assert_eq!(lo, 659_868, "the edge");
        for d in [lo, hi] {
            let seg = seg_of(d);
            let exact = exact_reading(&seg, &target);
            assert!(exact.covered_pixels() > 10, "the line crosses the canvas");
            assert_eq!(drawn_in::<i128>(&seg, &target), exact, "i128 at {d}");
            assert_eq!(drawn_in::<i64>(&seg, &target), exact, "i64 at {d}");
            let mut planned = Coverage::new(48, 40);
            rasterize(&seg, 0, &target, &mut planned);
            assert_eq!(planned, exact, "planned at {d}");
        }
    }

    /// Both widths against the exact reading on short segments of every direction whose
    /// ends sit on and around the diamonds' corners and edges (the ties the i64 path must
    /// decide as the i128 one does).
    #[test]
    fn the_i64_test_equals_the_exact_reading_on_ties() {
        let target = Target::new(6, 6, Preset::D3d11.convention()).unwrap();
        let ends: Vec<[i64; 2]> = (0..7)
            .flat_map(|x| (0..7).map(move |y| [256 + 128 * x, 256 + 128 * y]))
            .collect();
        for &a in &ends {
            for &b in ends.iter().step_by(3) {
                let seg = segment(a, b);
                assert!(fits_i64(&seg, &target));
                let exact = exact_reading(&seg, &target);
                assert_eq!(drawn_in::<i64>(&seg, &target), exact, "{a:?} -> {b:?}");
            }
        }
    }
}
