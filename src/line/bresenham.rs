//! Integer Bresenham / midpoint lines in all eight octants (Bresenham 1965, Pitteway 1967): the first-octant
//! algorithm with the axes reflected (major axis by `|dx| >= |dy|`, steps by the signs of
//! dx and dy), one integer add per pixel. The direction of travel is kept (no swapping of
//! ends), so `a -> b` and `b -> a` may differ, and only at exact ties.

use super::{Axes, BresenhamTie};
use crate::convention::Target;
use crate::coverage::CoverageSink;

/// Walks the line from pixel `from` to pixel `to` (both included, `max(|dx|, |dy|) + 1`
/// pixels), calling `visit(pixel, decision)` for each; `decision` is the value that
/// chooses the move after this pixel (`None` for the last). Endpoints within
/// ±[`super::MAX_BRESENHAM_COORD`].
///
/// ```
/// use rasterproof::line::{bresenham::walk, BresenhamTie};
/// // A worked example of the midpoint form: decisions 2, 0, 6, 4.
/// let mut seen = Vec::new();
/// walk([5, 8], [9, 11], BresenhamTie::Stay, |p, d| seen.push((p, d)));
/// assert_eq!(seen, vec![([5, 8], Some(2)), ([6, 9], Some(0)), ([7, 9], Some(6)), ([8, 10], Some(4)), ([9, 11], None)]);
/// ```
pub fn walk(from: [i64; 2], to: [i64; 2], tie: BresenhamTie, mut visit: impl FnMut([i64; 2], Option<i64>)) {
    let axes = Axes::of(from, to);
    let (mut major, mut minor) = axes.split(from);
    // d = 2 F(midpoint): 2 dy - dx at the start, + 2 dy after a major step, + 2 (dy - dx)
    // after a diagonal one (first-octant names; dy, dx are the minor and major lengths).
    let mut d = 2 * axes.minor_len - axes.major_len;
    for _ in 0..axes.major_len {
        visit(axes.join(major, minor), Some(d));
        let step_minor = match tie {
            BresenhamTie::Stay => d > 0,
            BresenhamTie::Step => d >= 0,
        };
        if step_minor {
            minor += axes.minor_sign;
            d += 2 * (axes.minor_len - axes.major_len);
        } else {
            d += 2 * axes.minor_len;
        }
        major += axes.major_sign;
    }
    visit(axes.join(major, minor), None);
}

/// The line's pixels, in order from `from` to `to`.
pub fn pixels(from: [i64; 2], to: [i64; 2], tie: BresenhamTie) -> Vec<[i64; 2]> {
    let mut out = Vec::new();
    walk(from, to, tie, |p, _| out.push(p));
    out
}

/// Draws the line into `sink` (pixels off the canvas are skipped): [`walk`]'s pixels,
/// with the walk clipped to the canvas first and then run without a test per pixel.
///
/// The clip is exact, from a closed form of the walk. In first-octant names (`dx` the
/// major length, `dy` the minor one, `t` the tie threshold: `Stay` steps the minor axis
/// when `d >= 1`, `Step` when `d >= 0`), the error `e_k = d_k - t` starts at
/// `2dy - dx - t` and stays in `[2dy - 2dx, 2dy)` (a step from below 0 adds `2dy`, one from
/// at least 0 adds `2dy - 2dx`; `0 <= dy <= dx` and `dx >= 1 >= t` keep it there), so
/// after `k` major steps the walk has made
///
/// `m_k = floor((2 k dy + dx - t) / (2 dx))`
///
/// minor steps, with `d_k = 2dy - dx + 2 k dy - 2 m_k dx`. Both coordinates move
/// monotonically with `k`, so the steps on the canvas are one range `k0..=k1`: the major
/// axis bounds it directly and the minor axis through the inverse of `m_k`. The walk
/// starts at `k0` from the closed form. Inside ±[`super::MAX_BRESENHAM_COORD`] every
/// product is below `2^53`.
#[inline]
pub fn rasterize<S: CoverageSink + ?Sized>(
    from: [i64; 2],
    to: [i64; 2],
    tie: BresenhamTie,
    id: u32,
    target: &Target,
    sink: &mut S,
) {
    let axes = Axes::of(from, to);
    let Some(Clipped {
        k0,
        k1,
        major,
        minor,
        d,
    }) = clip(&axes, from, tie, target)
    else {
        return;
    };
    let walk = Walk {
        k0,
        k1,
        major: on_canvas(major),
        minor: on_canvas(minor),
        d,
        major_step: unit(axes.major_sign),
        minor_step: unit(axes.minor_sign),
        threshold: threshold(tie),
        diagonal: 2 * (axes.minor_len - axes.major_len),
        straight: 2 * axes.minor_len,
    };
    if axes.x_major {
        walk.run::<S, true>(id, sink);
    } else {
        walk.run::<S, false>(id, sink);
    }
}

/// A clipped walk, ready to run on the canvas.
struct Walk {
    k0: i64,
    k1: i64,
    major: u32,
    minor: u32,
    d: i64,
    /// +1 or -1 as a wrapping u32 step.
    major_step: u32,
    minor_step: u32,
    threshold: i64,
    diagonal: i64,
    straight: i64,
}

impl Walk {
    /// Covers the pixels of steps `k0..=k1`, every one on the canvas (no test per pixel).
    #[inline(always)]
    fn run<S: CoverageSink + ?Sized, const X_MAJOR: bool>(self, id: u32, sink: &mut S) {
        let (mut major, mut minor, mut d) = (self.major, self.minor, self.d);
        let cover = |sink: &mut S, major: u32, minor: u32| {
            if X_MAJOR {
                sink.cover(major, minor, id);
            } else {
                sink.cover(minor, major, id);
            }
        };
        for _ in self.k0..self.k1 {
            cover(sink, major, minor);
            if d >= self.threshold {
                minor = minor.wrapping_add(self.minor_step);
                d += self.diagonal;
            } else {
                d += self.straight;
            }
            major = major.wrapping_add(self.major_step);
        }
        cover(sink, major, minor);
    }
}

/// The tie as a threshold on the decision value: the minor axis steps when `d >= t`.
fn threshold(tie: BresenhamTie) -> i64 {
    match tie {
        BresenhamTie::Stay => 1,
        BresenhamTie::Step => 0,
    }
}

/// A coordinate the clip put on the canvas.
fn on_canvas(v: i64) -> u32 {
    u32::try_from(v).expect("clipped to the canvas")
}

/// A sign (-1, 0 or 1) as a wrapping u32 step.
fn unit(sign: i64) -> u32 {
    match sign {
        1 => 1,
        -1 => u32::MAX,
        _ => 0,
    }
}

/// The steps of a walk on the canvas and the walk's state at the first.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Clipped {
    /// First step on the canvas.
    k0: i64,
    /// Last step on the canvas.
    k1: i64,
    /// Major coordinate at `k0`.
    major: i64,
    /// Minor coordinate at `k0`.
    minor: i64,
    /// Decision value at `k0`.
    d: i64,
}

/// The range of `k` in `0..=n` for which `start + sign * f(k)` lies in `0..extent`, for a
/// nondecreasing `f` given through its inverse: `first(v)` is the smallest `k` with
/// `f(k) >= v` and `last(v)` the largest with `f(k) <= v` (both may leave `0..=n`).
fn range_on(
    start: i64,
    sign: i64,
    extent: i64,
    n: i64,
    first: impl Fn(i64) -> i64,
    last: impl Fn(i64) -> i64,
) -> Option<(i64, i64)> {
    // The values of f that land on the canvas: lo..=hi.
    let (lo, hi) = match sign {
        1 => (-start, extent - 1 - start),
        -1 => (start - (extent - 1), start),
        _ => {
            return (0..extent).contains(&start).then_some((0, n));
        }
    };
    let (k0, k1) = (first(lo).max(0), last(hi).min(n));
    (k0 <= k1).then_some((k0, k1))
}

/// Clips the walk of `axes` from `from` to the canvas: `None` when no pixel is on it.
fn clip(axes: &Axes, from: [i64; 2], tie: BresenhamTie, target: &Target) -> Option<Clipped> {
    let t = threshold(tie);
    let (major0, minor0) = axes.split(from);
    let (width, height) = (i64::from(target.width), i64::from(target.height));
    let (major_extent, minor_extent) = if axes.x_major { (width, height) } else { (height, width) };
    let (n, dx, dy) = (axes.major_len, axes.major_len, axes.minor_len);
    if n == 0 {
        // One pixel.
        let on = (0..major_extent).contains(&major0) && (0..minor_extent).contains(&minor0);
        return on.then_some(Clipped {
            k0: 0,
            k1: 0,
            major: major0,
            minor: minor0,
            d: 0,
        });
    }
    // Major: f(k) = k.
    let (a0, a1) = range_on(major0, axes.major_sign, major_extent, n, |v| v, |v| v)?;
    // Minor: f(k) = m_k. m_k >= v <=> 2 k dy >= 2 v dx - dx + t; m_k <= v <=> 2 k dy <= (2 v + 1) dx + t - 1.
    // With dy = 0, m_k = 0 for every k (and `range_on` takes the sign-0 branch).
    let (b0, b1) = range_on(
        minor0,
        axes.minor_sign,
        minor_extent,
        n,
        |v| ceil_div(2 * v * dx - dx + t, 2 * dy),
        |v| (2 * v * dx + dx + t - 1).div_euclid(2 * dy),
    )?;
    let (k0, k1) = (a0.max(b0), a1.min(b1));
    if k0 > k1 {
        return None;
    }
    let m = (2 * k0 * dy + dx - t).div_euclid(2 * dx);
    Some(Clipped {
        k0,
        k1,
        major: major0 + axes.major_sign * k0,
        minor: minor0 + axes.minor_sign * m,
        d: 2 * dy - dx + 2 * k0 * dy - 2 * m * dx,
    })
}

/// `ceil(a / b)` for `b > 0`.
fn ceil_div(a: i64, b: i64) -> i64 {
    -(-a).div_euclid(b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::Convention;
    use crate::coverage::Coverage;

    /// `rasterize` covers exactly `walk`'s pixels that lie on the canvas, for lines in every
    /// octant, partly or wholly off a 12x9 canvas, both ties.
    #[test]
    fn draw_is_walk_on_the_canvas() {
        let target = Target::new(12, 9, Convention::default()).unwrap();
        let ends: Vec<[i64; 2]> = (-3..15)
            .step_by(2)
            .flat_map(|x| (-4..13).step_by(3).map(move |y| [x, y]))
            .collect();
        for &a in &ends {
            for &b in &ends {
                for tie in [BresenhamTie::Stay, BresenhamTie::Step] {
                    let mut drawn = Coverage::new(12, 9);
                    rasterize(a, b, tie, 0, &target, &mut drawn);
                    let mut walked = Coverage::new(12, 9);
                    for [x, y] in pixels(a, b, tie) {
                        if (0..12).contains(&x) && (0..9).contains(&y) {
                            walked.cover(u32::try_from(x).unwrap(), u32::try_from(y).unwrap(), 0);
                        }
                    }
                    assert_eq!(drawn, walked, "{a:?} -> {b:?} {tie:?}");
                }
            }
        }
    }

    /// `walk`'s pixels on the canvas, drawn with `cover_if_on_canvas` (a test per pixel).
    fn walked(a: [i64; 2], b: [i64; 2], tie: BresenhamTie, target: &Target) -> Coverage {
        let mut walked = Coverage::new(target.width, target.height);
        walk(a, b, tie, |p, _| {
            super::super::cover_if_on_canvas(p, 0, target, &mut walked)
        });
        walked
    }

    /// The clip, exhaustively: every pair of endpoints within three pixels of a 5x4 canvas
    /// (every octant, every entry and exit edge and corner, lines that miss, points), both ties.
    #[test]
    fn the_clip_is_exact_around_a_small_canvas() {
        let target = Target::new(5, 4, Convention::default()).unwrap();
        let ends: Vec<[i64; 2]> = (-3..8).flat_map(|x| (-3..7).map(move |y| [x, y])).collect();
        for &a in &ends {
            for &b in &ends {
                for tie in [BresenhamTie::Stay, BresenhamTie::Step] {
                    let mut drawn = Coverage::new(5, 4);
                    rasterize(a, b, tie, 0, &target, &mut drawn);
                    assert_eq!(drawn, walked(a, b, tie, &target), "{a:?} -> {b:?} {tie:?}");
                }
            }
        }
    }

    /// The clip at the envelope: lines from corner to corner of the +-2^24 square and
    /// steep and shallow ones through a 64x48 canvas, whose start is 2^24 steps away.
    #[test]
    fn the_clip_is_exact_at_the_envelope() {
        let m = super::super::MAX_BRESENHAM_COORD;
        let target = Target::new(64, 48, Convention::default()).unwrap();
        let lines = [
            ([-m, -m], [m, m]),
            ([m, m], [-m, -m]),
            ([-m, m], [m, -m]),
            ([-m, -m + 7], [m, m - 3]),
            ([-m, 20], [m, 29]),
            ([m, 45], [-m, 2]),
            ([30, -m], [33, m]),
            ([-m, -m / 3], [m, m / 3 + 11]),
        ];
        for (a, b) in lines {
            for tie in [BresenhamTie::Stay, BresenhamTie::Step] {
                let mut drawn = Coverage::new(64, 48);
                rasterize(a, b, tie, 0, &target, &mut drawn);
                let walked = walked(a, b, tie, &target);
                assert!(walked.covered_pixels() > 0, "{a:?} -> {b:?} crosses the canvas");
                assert_eq!(drawn, walked, "{a:?} -> {b:?} {tie:?}");
            }
        }
    }
}
