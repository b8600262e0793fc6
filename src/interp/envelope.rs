//! How far a correct f32 interpolator may land from the exact value: a bound derived by
//! forward error analysis, per channel, at one point of a primitive.
//!
//! An interpolator reads its inputs (window positions, `1 / w`, vertex values) as f32 and
//! computes a value with a few dozen f32 operations, in one of a handful of forms: a plane
//! `g(p) = g_j + dg/dx (p_x - x_j) + dg/dy (p_y - y_j)` anchored at a vertex `j`, the same
//! plane anchored at the framebuffer's origin (`a0 + dadx x + dady y`, with `a0` the plane
//! at `(0, 0)`), or barycentrics from edge functions, `sum E_i(p) g_i / sum E_i`. Its
//! result differs from the exact value by at most `gamma * S` to first order, where `S`
//! is the same computation run on the absolute values of its inputs with every
//! subtraction turned into an addition (Higham, *Accuracy and Stability of Numerical
//! Algorithms*, 2nd ed., section 3.1, the bound `|fl(x) - x| <= gamma_n |x|` with the
//! running error of each operation carried as a multiple of the absolute-value
//! computation). This module evaluates `S` for each form and takes the largest, so the
//! bound holds whichever form a renderer chose:
//!
//! - an input difference `a - b` counts as `|a - b|` when both inputs are f32 exactly (the
//!   subtraction rounds once, relative to its result), and as `|a| + |b|` otherwise (each
//!   input was rounded to f32 first, relative to itself);
//! - a gradient `N / A` (`A` twice the signed area) carries `(S_N + |N / A| S_A) / |A|`;
//! - `gamma = 16 u / (1 - 16 u)` with `u = 2^-24`: sixteen roundings along the longest
//!   chain of an interpolator (setup: two differences, two products, a difference, a
//!   reciprocal or a division; evaluation: a difference, two products, two sums; the
//!   perspective divide), with room for a reciprocal approximation refined by one
//!   Newton-Raphson step (about 2 u);
//! - a perspective-correct (`smooth`) value `N / D`, with `N` the plane of `f_i / w_i` and
//!   `D` the plane of `1 / w_i`, carries `(e_N + |f| e_D) / (|D| - e_D) + u |f|`; it has no
//!   bound where `|D| <= e_D` (the point is too near the horizon for f32 to say anything);
//! - a `flat` value is a copy: its only error is the input's rounding to f32.
//!
//! Two bounds come out: [`Envelope::near`], the largest over the forms anchored at a vertex
//! or at the point's own edge functions, and [`Envelope::far`], which adds the plane
//! anchored at the framebuffer's origin (its top left corner, or a GL renderer's bottom left
//! one). The origin-anchored plane's error grows with the
//! distance of the primitive from `(0, 0)` (its `a0` is extrapolated there and its
//! gradient multiplied by the pixel's coordinates), which is why a value within `far` but
//! not `near` is named for it. Both are computed in f64 from the exact inputs; f64's own
//! rounding (2^-53 relative) is far inside the constant's slack.

use num_rational::BigRational;

use crate::geom::Point;
use crate::interp::values::{Interpolation, ValueSetup};
use crate::num::exact::{is_f32, nearest_f64};

/// Unit roundoff of f32 (round to nearest).
const U: f64 = 1.0 / 16_777_216.0;

/// The roundings an f32 interpolator is allowed along its longest chain (module docs).
pub const ROUNDINGS: f64 = 16.0;

/// `gamma_n = n u / (1 - n u)` for `n = ROUNDINGS`.
fn gamma() -> f64 {
    ROUNDINGS * U / (1.0 - ROUNDINGS * U)
}

/// The bounds on `|theirs - exact|` of one channel at one point (module docs); `None`
/// where f32 arithmetic bounds nothing (a smooth value too near the horizon).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Envelope {
    /// Any interpolator anchored at a vertex or evaluating edge functions at the point.
    pub near: Option<f64>,
    /// Any of those or a plane anchored at the framebuffer's origin (at least `near`).
    pub far: Option<f64>,
}

impl Envelope {
    /// No error allowed beyond the input's own rounding: a copied value.
    fn copy(f: f64) -> Envelope {
        let e = Some(U * f.abs());
        Envelope { near: e, far: e }
    }

    /// Nothing bounded.
    const NONE: Envelope = Envelope { near: None, far: None };
}

/// A rational as f64, and whether it is an f32 exactly (so that a difference of two such
/// rounds once, relative to its result).
#[derive(Debug, Clone, Copy)]
struct Input {
    v: f64,
    exact: bool,
}

impl Input {
    fn of(q: &BigRational) -> Input {
        let v = nearest_f64(q).unwrap_or(f64::INFINITY);
        let exact = is_f32(q);
        Input { v, exact }
    }
}

/// `a - b` and the absolute-value computation of it.
fn diff(a: Input, b: Input) -> (f64, f64) {
    let d = a.v - b.v;
    (
        d,
        if a.exact && b.exact {
            d.abs()
        } else {
            a.v.abs() + b.v.abs()
        },
    )
}

/// A window-space triangle as the bound sees it: positions and, per vertex, the function
/// interpolated (a value, `f / w` or `1 / w`), each with its absolute-value companion; and
/// what of `S` does not depend on the point, worked out once ([`Plane::new`]).
#[derive(Debug, Clone)]
struct Plane {
    x: [Input; 3],
    y: [Input; 3],
    g: [f64; 3],
    /// The canvas's height: a GL renderer's framebuffer origin is its lower left corner,
    /// `(0, H)` in the scene's window coordinates.
    height: f64,
    /// `None` where f32 bounds nothing at any point (a degenerate area).
    gradient: Option<Gradient>,
}

/// A plane's gradient and the absolute-value sums of its computation.
#[derive(Debug, Clone, Copy)]
struct Gradient {
    /// Twice the signed area.
    area: f64,
    gx: f64,
    gy: f64,
    /// The gradient's absolute-value sums, the denominator's error included.
    sx: f64,
    sy: f64,
}

impl Plane {
    /// The plane of `g` over the triangle `(x, y)`. A renderer sets the gradient up from
    /// the differences to any one vertex (llvmpipe from vertex 0 after its reordering,
    /// which may make it the scene's vertex 1 or 2), and their absolute-value sums differ
    /// with the choice (a sliver with two close vertices cancels far more from the third
    /// one), so the sums are the largest over the three.
    fn new(x: [Input; 3], y: [Input; 3], g: [f64; 3], height: f64) -> Plane {
        let gradient = (|| {
            let from = |b: usize| {
                let (j, k) = ((b + 1) % 3, (b + 2) % 3);
                let (dx1, ax1) = diff(x[j], x[b]);
                let (dx2, ax2) = diff(x[k], x[b]);
                let (dy1, ay1) = diff(y[j], y[b]);
                let (dy2, ay2) = diff(y[k], y[b]);
                let area = dx1 * dy2 - dx2 * dy1;
                let area_abs = ax1 * ay2 + ax2 * ay1;
                let (dg1, ag1) = (g[j] - g[b], g[j].abs() + g[b].abs());
                let (dg2, ag2) = (g[k] - g[b], g[k].abs() + g[b].abs());
                let nx = dg1 * dy2 - dg2 * dy1;
                let ny = dx1 * dg2 - dx2 * dg1;
                (area, area_abs, nx, ny, (ag1 * ay2 + ag2 * ay1), (ax1 * ag2 + ax2 * ag1))
            };
            // The gradient itself from vertex 0 (the same plane from any vertex).
            let (area, _, nx, ny, _, _) = from(0);
            if area == 0.0 || !area.is_finite() {
                return None;
            }
            let (gx, gy) = (nx / area, ny / area);
            let (mut sx, mut sy) = (0.0f64, 0.0f64);
            for b in 0..3 {
                let (_, area_abs, _, _, nx_abs, ny_abs) = from(b);
                // An area f32 cannot tell from zero: a plane's gradient may be infinite.
                if gamma() * area_abs >= area.abs() {
                    return None;
                }
                // The gradient's absolute-value sums, the denominator's error included.
                sx = sx.max((nx_abs + gx.abs() * area_abs) / area.abs());
                sy = sy.max((ny_abs + gy.abs() * area_abs) / area.abs());
            }
            Some(Gradient { area, gx, gy, sx, sy })
        })();
        Plane {
            x,
            y,
            g,
            height,
            gradient,
        }
    }

    /// `S` of the function at `p` (module docs), the largest over the forms, without and
    /// with the origin-anchored plane; and the exact function's value there (f64).
    fn abs_sum(&self, p: (Input, Input)) -> Option<(f64, f64, f64)> {
        let (x, y, g) = (&self.x, &self.y, &self.g);
        let Gradient {
            area, gx, gy, sx, sy, ..
        } = self.gradient?;
        let value = g[0] + gx * (p.0.v - x[0].v) + gy * (p.1.v - y[0].v);
        // A plane anchored at vertex j: g_j + g_x (p_x - x_j) + g_y (p_y - y_j).
        let anchored = |j: usize| {
            let (_, adx) = diff(p.0, x[j]);
            let (_, ady) = diff(p.1, y[j]);
            g[j].abs() + (sx + gx.abs()) * adx + (sy + gy.abs()) * ady
        };
        // Barycentrics: E_i(p) = (x_j - p_x)(y_k - p_y) - (x_k - p_x)(y_j - p_y).
        let edge_abs = |i: usize| {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            let (_, axj) = diff(x[j], p.0);
            let (_, ayk) = diff(y[k], p.1);
            let (_, axk) = diff(x[k], p.0);
            let (_, ayj) = diff(y[j], p.1);
            axj * ayk + axk * ayj
        };
        // Its denominator is the sum of the three edge functions at p, which cancel down to
        // the area: their own absolute-value sums bound its error, not the area's.
        let edges = [0, 1, 2].map(edge_abs);
        if gamma() * edges.iter().sum::<f64>() >= area.abs() {
            return None;
        }
        let barycentric = (0..3).map(|i| g[i].abs() * edges[i]).sum::<f64>() / area.abs()
            + value.abs() * edges.iter().sum::<f64>() / area.abs();
        let near = (0..3).map(anchored).fold(barycentric, f64::max);
        // The origin-anchored plane: a0 = g_j - (g_x x_j + g_y y_j), then a0 + g_x p_x + g_y p_y,
        // with the origin at the top left corner or (y flipped, H - y rounded first) the
        // bottom left one.
        let h = self.height.abs();
        let origin = |j: usize| {
            let along_y = y[j].v.abs() + p.1.v.abs() + 2.0 * h;
            g[j].abs() + (sx + gx.abs()) * (x[j].v.abs() + p.0.v.abs()) + (sy + gy.abs()) * along_y
        };
        let far = (0..3).map(origin).fold(near, f64::max);
        Some((near, far, value))
    }
}

/// The f32 envelope of each of the channels `channels` of `setup` at window point `p`
/// under `interpolation` (module docs). A triangle with a vertex at `w <= 0` (behind the
/// eye: a renderer clips it into other triangles first) and a degenerate primitive bound
/// nothing.
///
/// ```
/// use rasterproof::geom::Point;
/// use rasterproof::interp::envelope::value_envelope;
/// use rasterproof::interp::values::{Interpolation, ValueSetup, ValueTriangle};
/// let q = |n: i64| num_rational::BigRational::from_integer(n.into());
/// let (a, b, c) = (Point::from_ints(0, 0), Point::from_ints(8, 0), Point::from_ints(0, 8));
/// let t = ValueSetup::Triangle(Box::new(ValueTriangle::window(
///     [&a, &b, &c],
///     [&q(1), &q(1), &q(1)],
///     [vec![q(0)], vec![q(8)], vec![q(0)]],
/// )));
/// let e = value_envelope(&t, Interpolation::NoPerspective, 0..1, &Point::from_ints(1, 1), 8);
/// // The value is 1; a few dozen f32 roundings of numbers near 8 stay below 2^-15.
/// let near = e[0].near.unwrap();
/// assert!(near > 0.0 && near < 1.0 / 32768.0);
/// ```
pub fn value_envelope(
    setup: &ValueSetup,
    interpolation: Interpolation,
    channels: std::ops::Range<usize>,
    p: &Point,
    height: u32,
) -> Vec<Envelope> {
    EnvelopeSetup::channels(setup, interpolation, channels, height)
        .iter()
        .map(|e| e.at(p))
        .collect()
}

/// One channel's envelope, its primitive's part set up once: what [`value_envelope`]
/// evaluates, for many points.
#[derive(Debug, Clone)]
pub struct EnvelopeSetup {
    kind: Kind,
}

#[derive(Debug, Clone)]
enum Kind {
    Fixed(Envelope),
    Linear(Plane),
    Smooth {
        n: Plane,
        d: Plane,
    },
    Segment {
        ends: [(Input, Input); 2],
        fa: f64,
        fb: f64,
    },
}

impl EnvelopeSetup {
    /// Channel `channel` of `setup` under `interpolation` on a canvas `height` px high.
    pub fn new(setup: &ValueSetup, interpolation: Interpolation, channel: usize, height: u32) -> EnvelopeSetup {
        EnvelopeSetup::channels(setup, interpolation, channel..channel + 1, height)
            .pop()
            .expect("one channel")
    }

    /// The channels `channels` of `setup`, the primitive's positions read once.
    pub fn channels(
        setup: &ValueSetup,
        interpolation: Interpolation,
        channels: std::ops::Range<usize>,
        height: u32,
    ) -> Vec<EnvelopeSetup> {
        let each = |kind: &dyn Fn(usize) -> Kind| channels.clone().map(|k| EnvelopeSetup { kind: kind(k) }).collect();
        match setup {
            ValueSetup::Triangle(t) => {
                let value = |i: usize, k: usize| Input::of(&t.values[i][k]).v;
                if interpolation == Interpolation::Flat {
                    // The provoking vertex is the caller's; every vertex's value is a copy.
                    return each(&|k| {
                        Kind::Fixed(Envelope::copy((0..3).map(|i| value(i, k).abs()).fold(0.0, f64::max)))
                    });
                }
                let w: Vec<f64> = t.h.iter().map(|h| nearest_f64(&h[2]).unwrap_or(0.0)).collect();
                if w.iter().any(|&w| w <= 0.0 || !w.is_finite()) {
                    return each(&|_| Kind::Fixed(Envelope::NONE));
                }
                let pos = |i: usize, c: usize| Input::of(&(&t.h[i][c] / &t.h[i][2]));
                let (x, y) = ([0, 1, 2].map(|i| pos(i, 0)), [0, 1, 2].map(|i| pos(i, 1)));
                let plane = |g: [f64; 3]| Plane::new(x, y, g, f64::from(height));
                if interpolation == Interpolation::NoPerspective {
                    each(&|k| Kind::Linear(plane([0, 1, 2].map(|i| value(i, k)))))
                } else {
                    let d = plane([0, 1, 2].map(|i| 1.0 / w[i]));
                    each(&|k| Kind::Smooth {
                        n: plane([0, 1, 2].map(|i| value(i, k) / w[i])),
                        d: d.clone(),
                    })
                }
            }
            ValueSetup::Segment(s) => {
                let ends = [&s.ends[0], &s.ends[1]].map(|e| (Input::of(&e.x), Input::of(&e.y)));
                each(&|k| {
                    let fa = Input::of(&s.values[0][k]).v;
                    let fb = Input::of(&s.values[1][k]).v;
                    if interpolation == Interpolation::Flat {
                        Kind::Fixed(Envelope::copy(fa.abs().max(fb.abs())))
                    } else {
                        Kind::Segment { ends, fa, fb }
                    }
                })
            }
        }
    }

    /// The envelope at window point `p`.
    pub fn at(&self, p: &Point) -> Envelope {
        self.at_input((Input::of(&p.x), Input::of(&p.y)))
    }

    /// The envelope at the point `(x + centre, y + centre)` of pixel `(x, y)`, `centre`
    /// 1/2 or 0 (exact in f32 below 2^22).
    pub fn at_pixel(&self, x: u32, y: u32, centre: f64) -> Envelope {
        let input = |c: u32| Input {
            v: f64::from(c) + centre,
            exact: c < 1 << 22,
        };
        self.at_input((input(x), input(y)))
    }

    /// The envelope at the point `(x + offset.0, y + offset.1)` of pixel `(x, y)`: a
    /// sample position of a pattern, each offset an f64 that is exactly the position's
    /// (the caller's to ensure; [`EnvelopeSetup::at`] takes any exact point).
    pub fn at_offset(&self, x: u32, y: u32, offset: (f64, f64)) -> Envelope {
        let input = |c: u32, o: f64| {
            // Exact in f64 for the short dyadic offsets of sample patterns (below 2^24 px).
            let v = f64::from(c) + o;
            #[allow(clippy::cast_possible_truncation)] // the question is whether it is exact
            let exact = f64::from(v as f32) == v && v - f64::from(c) == o;
            Input { v, exact }
        };
        self.at_input((input(x, offset.0), input(y, offset.1)))
    }

    fn at_input(&self, at: (Input, Input)) -> Envelope {
        match &self.kind {
            Kind::Fixed(e) => *e,
            Kind::Linear(plane) => bounds(plane.abs_sum(at)),
            Kind::Smooth { n, d } => match (n.abs_sum(at), d.abs_sum(at)) {
                (Some(n), Some(d)) => {
                    let f = n.2 / d.2;
                    let quotient = |sn: f64, sd: f64| {
                        let (en, ed) = (gamma() * sn, gamma() * sd);
                        let room = d.2.abs() - ed;
                        (room > 0.0).then(|| (en + f.abs() * ed) / room + U * f.abs())
                    };
                    Envelope {
                        near: quotient(n.0, d.0),
                        far: quotient(n.1, d.1),
                    }
                }
                _ => Envelope::NONE,
            },
            Kind::Segment { ends, fa, fb } => {
                let (dx, adx) = diff(ends[1].0, ends[0].0);
                let (dy, ady) = diff(ends[1].1, ends[0].1);
                let length2 = dx * dx + dy * dy;
                if length2 == 0.0 {
                    return Envelope::NONE;
                }
                let (px, apx) = diff(at.0, ends[0].0);
                let (py, apy) = diff(at.1, ends[0].1);
                let t = (px * dx + py * dy) / length2;
                let t_abs = (apx * adx + apy * ady) / length2 + t.abs() * (adx * adx + ady * ady) / length2;
                let df_abs = fa.abs() + fb.abs();
                let e = Some(gamma() * (fa.abs() + (t_abs + t.abs()) * df_abs));
                Envelope { near: e, far: e }
            }
        }
    }
}

/// A plane's `S` as the two bounds.
fn bounds(s: Option<(f64, f64, f64)>) -> Envelope {
    match s {
        Some((near, far, _)) => Envelope {
            near: Some(gamma() * near),
            far: Some(gamma() * far),
        },
        None => Envelope::NONE,
    }
}
