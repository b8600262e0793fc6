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

/// Draws the line into `sink` (pixels off the canvas are skipped): [`walk`]'s pixels, in
/// one loop with the tie folded into a threshold (`Stay` steps the minor axis when
/// `d >= 1`, `Step` when `d >= 0`) and the canvas test on unsigned coordinates.
#[inline]
pub fn draw<S: CoverageSink + ?Sized>(
    from: [i64; 2],
    to: [i64; 2],
    tie: BresenhamTie,
    id: u32,
    target: &Target,
    sink: &mut S,
) {
    let axes = Axes::of(from, to);
    let (mut major, mut minor) = axes.split(from);
    let threshold = match tie {
        BresenhamTie::Stay => 1,
        BresenhamTie::Step => 0,
    };
    let (diagonal, straight) = (2 * (axes.minor_len - axes.major_len), 2 * axes.minor_len);
    let mut d = 2 * axes.minor_len - axes.major_len;
    let (width, height) = (u64::from(target.width), u64::from(target.height));
    for k in 0..=axes.major_len {
        let [x, y] = axes.join(major, minor);
        // a negative coordinate wraps to a huge u64: one comparison per axis
        #[allow(clippy::cast_sign_loss, clippy::cast_possible_truncation)]
        if (x as u64) < width && (y as u64) < height {
            sink.cover(x as u32, y as u32, id);
        }
        if k == axes.major_len {
            break;
        }
        if d >= threshold {
            minor += axes.minor_sign;
            d += diagonal;
        } else {
            d += straight;
        }
        major += axes.major_sign;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::Convention;
    use crate::coverage::Coverage;

    /// `draw` covers exactly `walk`'s pixels that lie on the canvas, for lines in every
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
                    draw(a, b, tie, 0, &target, &mut drawn);
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
}
