//! Exact values at pixel centres at float speed: a filtered evaluation that decides what
//! the plain definition ([`crate::interp::values`]) decides, falling back to it where the
//! filter cannot ([`PlannedValue`]).
//!
//! Every value of [`crate::interp::values`] at a window point `p = (p_x, p_y)` is a ratio of
//! two affine functions of `p`. With the homogeneous barycentrics `b_i = q . n_i / det`,
//! `q = (p_x, p_y, 1)` and `n_i` the cross products of the other two homogeneous vertices:
//!
//! - `smooth`: `f = sum b_i f_i / sum b_i = (sum f_i q . n_i) / (sum q . n_i)`;
//! - `noperspective`: `f = sum b_i w_i f_i = (sum w_i f_i q . n_i) / det`, a constant
//!   denominator;
//! - a segment: `f = f_a + t (f_b - f_a)` with `t = (p - a) . (b - a) / |b - a|^2`.
//!
//! At pixel `(x, y)` the point is `(x + c, y + c)` for the convention's centre `c` (or a
//! sample's `(x + o_x, y + o_y)`, [`PlannedValue::channels_at`]), so the value is `N(x, y) / D(x, y)` with `N = a x + b y + k` and `D = d x + e y + g`, six exact
//! rationals set up once per primitive and channel. Per pixel the plan evaluates both in
//! f64 from the coefficients rounded to f64: each result within `4 u (|a x| + |b y| + |k|)`
//! of the exact one (`u = 2^-53`: one rounding of each coefficient, two products, two
//! sums; the coordinates are exact, at most 2^24), so the quotient `v` is within
//! `e = (4 u S_N + |v| 4 u S_D) / (|D| - 4 u S_D) + u |v|` of the exact value. That is a
//! certified interval, and every question asked of the value is answered from it when the
//! interval decides it:
//!
//! - the nearest f32 ([`PlannedValue::nearest_f32`]): when no f32 midpoint (the rounding
//!   boundaries) lies within `e` of `v`, the exact value rounds as `v` does;
//! - whether it lies within a bound of an f32 ([`PlannedValue::within`]).
//!
//! Otherwise (an interval straddling a boundary, a denominator the interval cannot tell
//! from zero, a coordinate beyond 2^24) the exact rationals decide: the same ratio, in big
//! rationals. The two paths decide alike by construction; `tests/values_planned.rs`
//! compares them with the plain definition on random primitives, on values placed exactly
//! on f32 midpoints and far from the origin.

use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use crate::geom::Point;
use crate::interp::values::{Interpolation, NoValue, ProvokingVertex, ValueSetup};
use crate::num::exact::{nearest_f32, nearest_f64};

/// f64's unit roundoff.
const U: f64 = 1.0 / 9_007_199_254_740_992.0;

/// Coordinates up to this magnitude are exact in f64 products with margin.
const MAX_COORDINATE: f64 = 16_777_216.0;

/// An affine function `a x + b y + k` of the pixel's integer coordinates, exact and in f64.
#[derive(Debug, Clone, PartialEq)]
struct Affine {
    exact: [BigRational; 3],
    float: [f64; 3],
}

impl Affine {
    fn new(exact: [BigRational; 3]) -> Affine {
        let float = [0, 1, 2].map(|i| nearest_f64(&exact[i]).unwrap_or(f64::INFINITY));
        Affine { exact, float }
    }

    fn constant(k: BigRational) -> Affine {
        Affine::new([BigRational::zero(), BigRational::zero(), k])
    }

    /// The f64 value and the sum of the absolute terms (its error is within `4 u` of it).
    fn float_at(&self, x: f64, y: f64) -> (f64, f64) {
        let [a, b, k] = self.float;
        (a * x + b * y + k, (a * x).abs() + (b * y).abs() + k.abs())
    }

    fn exact_at(&self, x: u32, y: u32) -> BigRational {
        let [a, b, k] = &self.exact;
        a * BigRational::from_integer(x.into()) + b * BigRational::from_integer(y.into()) + k
    }
}

/// One channel of one primitive, set up for pixel centres (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct PlannedValue {
    /// The value everywhere (`flat`), or `N / D`.
    form: Form,
}

#[derive(Debug, Clone, PartialEq)]
enum Form {
    Constant(BigRational, Option<f32>),
    Ratio(Box<[Affine; 2]>),
    None(NoValue),
}

/// What the plan knows of a value at a pixel: a certified f64 interval, or nothing (the
/// exact value must decide).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Approx {
    /// The f64 estimate.
    pub value: f64,
    /// A bound on its distance from the exact value.
    pub error: f64,
}

impl PlannedValue {
    /// Channel `channel` of `setup` under `interpolation` at pixel centres offset by
    /// `centre` (the convention's: 1/2 or 0).
    pub fn new(
        setup: &ValueSetup,
        interpolation: Interpolation,
        provoking: ProvokingVertex,
        channel: usize,
        centre: &BigRational,
    ) -> PlannedValue {
        PlannedValue::channels(setup, interpolation, provoking, channel..channel + 1, centre)
            .pop()
            .expect("one channel")
    }

    /// The channels `channels` of `setup`, the primitive's part set up once.
    pub fn channels(
        setup: &ValueSetup,
        interpolation: Interpolation,
        provoking: ProvokingVertex,
        channels: std::ops::Range<usize>,
        centre: &BigRational,
    ) -> Vec<PlannedValue> {
        let offset = Point::new(centre.clone(), centre.clone());
        PlannedValue::channels_at(setup, interpolation, provoking, channels, &offset)
    }

    /// [`PlannedValue::channels`] at the point `(x + offset.x, y + offset.y)` of pixel
    /// `(x, y)`: a sample position of a pattern, the same in every pixel.
    ///
    /// ```
    /// use rasterproof::geom::Point;
    /// use rasterproof::interp::planned::PlannedValue;
    /// use rasterproof::interp::values::{Interpolation, ProvokingVertex, ValueSetup, ValueTriangle};
    /// let q = |n: i64, d: i64| num_rational::BigRational::new(n.into(), d.into());
    /// let (a, b, c) = (Point::from_ints(0, 0), Point::from_ints(8, 0), Point::from_ints(0, 8));
    /// // The value is x + 2y (0, 8 and 16 at the vertices, w = 1).
    /// let t = ValueSetup::Triangle(Box::new(ValueTriangle::window(
    ///     [&a, &b, &c],
    ///     [&q(1, 1), &q(1, 1), &q(1, 1)],
    ///     [vec![q(0, 1)], vec![q(8, 1)], vec![q(16, 1)]],
    /// )));
    /// // Vulkan's 4x sample 0 sits at (3/8, 1/8) in its pixel: in pixel (2, 1) at
    /// // (19/8, 9/8), where x + 2y = 37/8.
    /// let offset = Point::from_fractions(3, 8, 1, 8);
    /// let planned = PlannedValue::channels_at(&t, Interpolation::Smooth, ProvokingVertex::First, 0..1, &offset);
    /// assert_eq!(planned[0].exact(2, 1), Ok(q(37, 8)));
    /// ```
    pub fn channels_at(
        setup: &ValueSetup,
        interpolation: Interpolation,
        provoking: ProvokingVertex,
        channels: std::ops::Range<usize>,
        offset: &Point,
    ) -> Vec<PlannedValue> {
        let constant = |v: &BigRational| PlannedValue {
            form: Form::Constant(v.clone(), nearest_f32(v)),
        };
        let none = |e: NoValue| {
            channels
                .clone()
                .map(|_| PlannedValue {
                    form: Form::None(e.clone()),
                })
                .collect()
        };
        let ratio = |n: Affine, d: Affine| PlannedValue {
            form: Form::Ratio(Box::new([n, d])),
        };
        match setup {
            ValueSetup::Triangle(t) if interpolation == Interpolation::Flat => {
                channels.map(|k| constant(&t.values[provoking.vertex(3)][k])).collect()
            }
            ValueSetup::Segment(s) if interpolation == Interpolation::Flat => {
                channels.map(|k| constant(&s.values[provoking.vertex(2)][k])).collect()
            }
            ValueSetup::Triangle(t) => {
                let h = &t.h;
                let cross = |a: &[BigRational; 3], b: &[BigRational; 3]| {
                    [
                        &a[1] * &b[2] - &a[2] * &b[1],
                        &a[2] * &b[0] - &a[0] * &b[2],
                        &a[0] * &b[1] - &a[1] * &b[0],
                    ]
                };
                let normals = [cross(&h[1], &h[2]), cross(&h[2], &h[0]), cross(&h[0], &h[1])];
                let det = &h[0][0] * &normals[0][0] + &h[0][1] * &normals[0][1] + &h[0][2] * &normals[0][2];
                if det.is_zero() {
                    return none(NoValue::Degenerate);
                }
                // sum over i of weight_i (q . n_i), as a function of (x, y), with
                // q = (x + offset_x, y + offset_y, 1).
                let affine = |weight: &dyn Fn(usize) -> BigRational| {
                    let mut c = [BigRational::zero(), BigRational::zero(), BigRational::zero()];
                    for (i, n) in normals.iter().enumerate() {
                        let w = weight(i);
                        for k in 0..3 {
                            c[k] += &w * &n[k];
                        }
                    }
                    let k = &c[2] + &c[0] * &offset.x + &c[1] * &offset.y;
                    Affine::new([c[0].clone(), c[1].clone(), k])
                };
                if interpolation == Interpolation::Smooth {
                    let d = affine(&|_| BigRational::one());
                    channels
                        .map(|k| ratio(affine(&|i| t.values[i][k].clone()), d.clone()))
                        .collect()
                } else {
                    let d = Affine::constant(det.clone());
                    channels
                        .map(|k| ratio(affine(&|i| &t.values[i][k] * &h[i][2]), d.clone()))
                        .collect()
                }
            }
            ValueSetup::Segment(s) => {
                let [a, b] = &s.ends;
                let (dx, dy) = (&b.x - &a.x, &b.y - &a.y);
                let length2 = &dx * &dx + &dy * &dy;
                if length2.is_zero() {
                    return none(NoValue::Degenerate);
                }
                let d = Affine::constant(length2.clone());
                let from = (&offset.x - &a.x) * &dx + (&offset.y - &a.y) * &dy;
                channels
                    .map(|k| {
                        let (fa, fb) = (&s.values[0][k], &s.values[1][k]);
                        let df = fb - fa;
                        // fa L2 + ((x + c - a_x) dx + (y + c - a_y) dy) df.
                        let c = fa * &length2 + &from * &df;
                        ratio(Affine::new([&dx * &df, &dy * &df, c]), d.clone())
                    })
                    .collect()
            }
        }
    }

    /// The exact value at pixel `(x, y)`: what [`ValueSetup::value`] gives at its centre.
    ///
    /// # Errors
    /// As the plain definition: degenerate, or on the horizon.
    pub fn exact(&self, x: u32, y: u32) -> Result<BigRational, NoValue> {
        match &self.form {
            Form::Constant(v, _) => Ok(v.clone()),
            Form::None(e) => Err(e.clone()),
            Form::Ratio(ratio) => {
                let [n, d] = ratio.as_ref();
                let den = d.exact_at(x, y);
                if den.is_zero() {
                    return Err(NoValue::Horizon);
                }
                Ok(n.exact_at(x, y) / den)
            }
        }
    }

    /// The certified f64 interval of the value at pixel `(x, y)`, when the filter gives
    /// one.
    pub fn approx(&self, x: u32, y: u32) -> Option<Approx> {
        match &self.form {
            Form::Constant(v, _) => nearest_f64(v).map(|value| Approx {
                value,
                error: U * value.abs(),
            }),
            Form::None(_) => None,
            Form::Ratio(ratio) => {
                let [n, d] = ratio.as_ref();
                let (xf, yf) = (f64::from(x), f64::from(y));
                if xf > MAX_COORDINATE || yf > MAX_COORDINATE {
                    return None;
                }
                let (nv, ns) = n.float_at(xf, yf);
                let (dv, ds) = d.float_at(xf, yf);
                let (en, ed) = (4.0 * U * ns, 4.0 * U * ds);
                let room = dv.abs() - ed;
                if room.is_nan() || room <= 0.0 || !nv.is_finite() || !dv.is_finite() {
                    return None;
                }
                let value = nv / dv;
                let error = (en + value.abs() * ed) / room + U * value.abs();
                (value.is_finite() && error.is_finite()).then_some(Approx {
                    value,
                    error: error * (1.0 + 8.0 * U),
                })
            }
        }
    }

    /// The exact value at pixel `(x, y)` rounded to the nearest f32 (ties to even):
    /// `nearest_f32` of [`PlannedValue::exact`], decided in f64 where the interval allows.
    /// `Ok(None)` for a value beyond f32's range.
    ///
    /// # Errors
    /// As [`PlannedValue::exact`].
    pub fn nearest_f32(&self, x: u32, y: u32) -> Result<Option<f32>, NoValue> {
        if let Form::Constant(_, f) = &self.form {
            return Ok(*f);
        }
        if let Some(a) = self.approx(x, y) {
            #[allow(clippy::cast_possible_truncation)] // rounding to f32 is the point
            let f = a.value as f32;
            if f.is_finite() && f != 0.0 {
                // The rounding boundaries around f: the midpoints with its neighbours.
                let below = f64::from(f32::from_bits(f.to_bits() - 1));
                let above = f64::from(f32::from_bits(f.to_bits() + 1));
                let (lo, hi) = ((below + f64::from(f)) / 2.0, (above + f64::from(f)) / 2.0);
                let (lo, hi) = if lo < hi { (lo, hi) } else { (hi, lo) };
                if a.value - a.error > lo && a.value + a.error < hi {
                    return Ok(Some(f));
                }
            }
        }
        self.exact(x, y).map(|v| nearest_f32(&v))
    }

    /// Whether the exact value at pixel `(x, y)` lies within `bound` of `t`: decided in
    /// f64 where the interval allows, exactly otherwise.
    ///
    /// # Errors
    /// As [`PlannedValue::exact`].
    pub fn within(&self, x: u32, y: u32, t: f32, bound: f64) -> Result<bool, NoValue> {
        if let Some(a) = self.approx(x, y) {
            let d = (f64::from(t) - a.value).abs();
            // |t - v| within d +- (error + the rounding of d itself).
            let slack = a.error + 2.0 * U * d;
            if d + slack <= bound {
                return Ok(true);
            }
            if d - slack > bound {
                return Ok(false);
            }
        }
        let v = self.exact(x, y)?;
        let t = BigRational::from_float(f64::from(t)).expect("a finite f32");
        Ok(BigRational::from_float(bound).is_some_and(|b| (t - v).abs() <= b))
    }
}

/// A window-space triangle's inputs in f64, each the nearest f64 to the exact input:
/// what [`FastPlan`] sets up from (converted once per primitive, as a renderer holds its
/// vertices in floats).
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleF64 {
    /// The vertices' window x.
    pub x: [f64; 3],
    /// The vertices' window y.
    pub y: [f64; 3],
    /// The vertices' clip-space w (1 without perspective).
    pub w: [f64; 3],
    /// `1 / w` of each vertex, rounded (set up once, as a renderer keeps it).
    pub r: [f64; 3],
    /// Per vertex, the channels set up (the first of them at index 0; at most four, the
    /// rest 0).
    pub values: [[f64; FAST_CHANNELS]; 3],
    /// How many channels `values` holds.
    pub channels: usize,
}

impl TriangleF64 {
    /// The channels `channels` of `setup`'s triangle; `None` for a segment, more than four
    /// channels, an input beyond f64's range, a window position f64 does not hold exactly
    /// (the fast plan's bound counts no rounding of the positions, whose error would be
    /// relative to their distance from the origin, not to the triangle's size), or a
    /// vertex at `w <= 0` (the bound needs `1 / w` finite). `w` and the values may be
    /// rounded: their errors are relative.
    pub fn of(setup: &ValueSetup, channels: std::ops::Range<usize>) -> Option<TriangleF64> {
        let ValueSetup::Triangle(t) = setup else {
            return None;
        };
        let w = [0, 1, 2].map(|i| nearest_f64(&t.h[i][2]));
        let w = [w[0]?, w[1]?, w[2]?];
        if w.iter().any(|&w| w <= 0.0 || !w.is_finite()) {
            return None;
        }
        let coordinate = |i: usize, c: usize| {
            let exact = &t.h[i][c] / &t.h[i][2];
            nearest_f64(&exact).filter(|v| BigRational::from_float(*v).as_ref() == Some(&exact))
        };
        let x = [coordinate(0, 0)?, coordinate(1, 0)?, coordinate(2, 0)?];
        let y = [coordinate(0, 1)?, coordinate(1, 1)?, coordinate(2, 1)?];
        if channels.len() > FAST_CHANNELS {
            return None;
        }
        let mut values = [[0.0; FAST_CHANNELS]; 3];
        for (vertex, out) in values.iter_mut().enumerate() {
            for (o, v) in out.iter_mut().zip(&t.values[vertex][channels.clone()]) {
                *o = nearest_f64(v).filter(|v| v.is_finite())?;
            }
        }
        Some(TriangleF64 {
            x,
            y,
            w,
            r: w.map(|w| 1.0 / w),
            values,
            channels: channels.len(),
        })
    }
}

/// `γ_n = n u / (1 - n u)`: the bound on `n` relative roundings (Higham, *Accuracy and
/// Stability of Numerical Algorithms*, lemma 3.1).
fn gamma(n: f64) -> f64 {
    n * U / (1.0 - n * U)
}

/// The roundings on any path of the fast plan's evaluation, the inputs' own included
/// (counted in [`FastPlan`]'s docs): 15, with one to spare.
const FAST_ROUNDINGS: f64 = 16.0;

/// A triangle's values at the points `(x + o_x, y + o_y)` of pixels `(x, y)` set up in f64
/// arithmetic from the nearest-f64 inputs ([`TriangleF64`]), with error bounds that
/// decide the nearest f32 of the exact value at almost every pixel for the cost of a few
/// float operations, and say when they cannot ([`FastPlan::nearest_f32`] gives `None`:
/// [`FastPlan::nearest_f32_exact`] decides nearly all of those from the exact inputs by one
/// sign, and the exact [`PlannedValue`] the rest).
///
/// The value is `N / D` with `N = sum g_i E_i(p)` and `D = sum r_i E_i(p)`, `E_i` the
/// edge function opposite vertex `i` (cyclically, `E_0(p) = (x_1 - p_x)(y_2 - p_y) -
/// (x_2 - p_x)(y_1 - p_y)`), and `r_i = 1 / w_i`, `g_i = f_i / w_i` (`smooth`) or `r_i =
/// 1`, `g_i = f_i` (`noperspective`), every `r_i` and `g_i` negated when the triangle is
/// clockwise (`N / D` is unchanged, and `D > 0` inside the triangle). The plane is
/// anchored at the integer point `(a_x, a_y)` at or below vertex 0 (its coordinates
/// rounded down): the positions are taken relative to it, exactly (a position f64 cannot
/// hold exactly, or one whose difference from the anchor it cannot, leaves every value to
/// the exact path), so that the terms stay the size of the triangle wherever it lies on
/// the canvas. Each `E_i` is written as `A_i x + B_i y + K_i` at pixel `(a_x + x, a_y +
/// y)`, with `A_i = y_j - y_k`, `B_i = x_k - x_j` and `K_i = x_j y_k - x_k y_j + A_i o_x +
/// B_i o_y` in relative coordinates.
///
/// **The bound at a pixel.** Every computed number is the exact one's polynomial (or
/// reciprocal) in the inputs, each monomial perturbed by at most `m` factors `(1 + δ)`,
/// `|δ| <= u = 2^-53`: an input 1, `r_i` 2, `g_i` 4, `A_i` and `B_i` 2, `K_i` 6, the
/// coefficients `sum g_i K_i` 13, and the value of `N` at a pixel (`x` and `y` exact
/// integers) 15. So `|N' - N| <= γ_16 S_N`, `S_N` the same computation on absolute values
/// (lemma 3.3 and section 3.1 of Higham's book), here bounded in closed form: with `X >=
/// |x_i|, |x|` and `Y >= |y_i|, |y|` (vertices and pixel, relative to the anchor), `|o| <=
/// 1`, every `|A_i| |x| + |B_i| |y| + |K_i|` term is at most `T = 6 X Y + 2 X + 2 Y`, so
/// `S_N <= T sum |g_i|` (`e_N`, a constant of the triangle) and `S_D <= T sum |r_i|`
/// (`e_D`). Then, at a pixel where `|D'| > 1024 e_D`: `|N' / D' - N / D| <= (e_N + |N / D|
/// e_D) / |D'|`, and the computed quotient `N' * fl(1 / D')` adds two roundings; solved for
/// the error `E`, `E <= (e_N + |v'| e_D) Q + 8 u |v'|` with `Q = |fl(1 / D')| (1024 /
/// 1023)(1 + 2u)`, widened by `(1 + 8 u)` for its own arithmetic. Round-to-nearest is
/// monotone, so when `v' - E` and `v' + E` round to the same f32 the exact value does too.
///
/// **The uniform bound**, tried first at every pixel. The bound above is largest where
/// `|D'|` is smallest and `|v'|` largest, so over the pixels where `D' >= F` (a floor set
/// up per triangle, at least `1024 e_D`) and `|v'| <= V_c` (per channel) it is at most
/// `U_c = ((e_N + V_c e_D)(1 / F)(1 + u)(1024 / 1023)(1 + 2u) + 8 u V_c)(1 + 8u)`, widened
/// by `(1 + 16 u)` for the roundings of its own set-up (`fl(1 / D') <= (1 / F)(1 + u)`
/// when `D' >= F`). A pixel meeting both tests is decided when `v' - U_c` and `v' + U_c`
/// round alike: two conversions and three comparisons a channel, no bound computed per
/// pixel. The floor is half the smallest of `D`'s values at the vertices (`r_i` times
/// twice the area: `D` is affine and its minimum over the triangle is at a vertex), and
/// `V_c` twice the largest `|f_i|` of the channel (inside the triangle the value is in
/// the vertices' hull), so the pixels a triangle covers pass both tests; any other pixel
/// falls back to the bound at the pixel, which holds wherever `|D'| > 1024 e_D`.
#[derive(Debug, Clone, PartialEq)]
pub struct FastPlan {
    form: FastForm,
    /// The anchor `(a_x, a_y)`, integers.
    anchor: (f64, f64),
    /// The pixels the bound holds for: `|x - a_x| <= limit.0`, `|y - a_y| <= limit.1`.
    limit: (f64, f64),
}

#[derive(Debug, Clone, PartialEq)]
#[allow(clippy::large_enum_variant)] // boxing the ratio costs an allocation per triangle
enum FastForm {
    /// Nothing decided: the exact values decide every channel.
    Undecided(usize),
    /// Per channel the decided f32 (`None`: the exact value decides).
    Constant([Option<f32>; FAST_CHANNELS], usize),
    Ratio(FastRatio),
}

/// `N / D`'s coefficients and bounds (see [`FastPlan`]).
#[derive(Debug, Clone, PartialEq)]
struct FastRatio {
    /// `D`'s coefficients `[a, b, k]` at integer pixel coordinates.
    d: [f64; 3],
    /// `D`'s error bound.
    e_d: f64,
    /// Per channel, `N`'s coefficients.
    n: [[f64; 3]; FAST_CHANNELS],
    /// Per channel, `N`'s error bound.
    e_n: [f64; FAST_CHANNELS],
    channels: usize,
    /// The uniform bound's floor `F` on `D'`.
    floor: f64,
    /// Per channel the uniform bound `U_c`, and the largest `|v'|` it holds for, `V_c`.
    uniform: [f64; FAST_CHANNELS],
    most: [f64; FAST_CHANNELS],
    /// What the exact sign needs: the offset in the pixel, the vertices relative to the
    /// anchor (exact), and whether `r_i = 1 / w_i`.
    offset: (f64, f64),
    x: [f64; 3],
    y: [f64; 3],
    smooth: bool,
}

/// The channels a fast plan decides (a vec4's); more leave every value to the exact path.
const FAST_CHANNELS: usize = 4;

/// The f32 every real of `[lo, hi]` rounds to, when they all round to one finite f32.
#[inline]
fn decided(lo: f64, hi: f64) -> Option<f32> {
    #[allow(clippy::cast_possible_truncation)] // rounding to f32 is the point
    let (a, b) = (lo as f32, hi as f32);
    // NaN (from an infinite or NaN bound) converts to NaN: not finite.
    (a.to_bits() == b.to_bits() && a.is_finite()).then_some(a)
}

/// `a - b` when f64 holds it exactly (Knuth's TwoSum leaves no error term).
fn exact_difference(a: f64, b: f64) -> Option<f64> {
    let s = a - b;
    let bv = s - a;
    let av = s - bv;
    let e = (a - av) + (-b - bv);
    (e == 0.0 && s.is_finite()).then_some(s)
}

/// The largest integer at most `v` (`f64::floor` without the library call where a
/// conversion does it: below 2^62 in magnitude).
#[inline]
fn floor(v: f64) -> f64 {
    if v.abs() < 4_611_686_018_427_387_904.0 {
        #[allow(clippy::cast_possible_truncation, clippy::cast_precision_loss)] // |v| < 2^62: exact
        let t = v as i64 as f64;
        if t > v {
            t - 1.0
        } else {
            t
        }
    } else {
        v.floor()
    }
}

impl FastPlan {
    /// The plan of `t`'s channels under `interpolation` (`provoking` for `flat`) at
    /// offset `offset` in each pixel (each coordinate of magnitude at most 1, exact in
    /// f64), for pixels within 2 px of the triangle's bounding box (others: `None` from
    /// [`FastPlan::nearest_f32`]).
    pub fn new(
        t: &TriangleF64,
        interpolation: Interpolation,
        provoking: ProvokingVertex,
        offset: (f64, f64),
    ) -> FastPlan {
        let channels = t.channels;
        let anchor = (floor(t.x[0]), floor(t.y[0]));
        let relative = |c: &[f64; 3], a: f64| -> Option<[f64; 3]> {
            Some([
                exact_difference(c[0], a)?,
                exact_difference(c[1], a)?,
                exact_difference(c[2], a)?,
            ])
        };
        let undecided = FastPlan {
            form: FastForm::Undecided(channels),
            anchor,
            limit: (0.0, 0.0),
        };
        let (Some(x), Some(y), true) = (
            relative(&t.x, anchor.0),
            relative(&t.y, anchor.1),
            channels <= FAST_CHANNELS,
        ) else {
            return undecided;
        };
        let most_of = |c: &[f64; 3]| c[0].abs().max(c[1].abs()).max(c[2].abs()) + 2.0;
        let limit = (most_of(&x), most_of(&y));
        if interpolation == Interpolation::Flat {
            let v = &t.values[provoking.vertex(3)];
            let mut each = [None; FAST_CHANNELS];
            for (e, &f) in each.iter_mut().zip(&v[..channels]) {
                *e = decided(f - f.abs() * 2.0 * U, f + f.abs() * 2.0 * U);
            }
            return FastPlan {
                form: FastForm::Constant(each, channels),
                anchor,
                limit: (f64::INFINITY, f64::INFINITY),
            };
        }
        // A triangle without area has no value (the plain definition's `Degenerate`), though
        // N / D may be finite off its line: leave every value to the exact path unless the
        // area's sign is certain (exact positions: three roundings).
        let (p, q) = ((x[1] - x[0]) * (y[2] - y[0]), (x[2] - x[0]) * (y[1] - y[0]));
        let area2 = p - q;
        let certain = area2.abs() > gamma(4.0) * (p.abs() + q.abs()) * 2.0;
        if !certain {
            return undecided;
        }
        let sign = if area2 < 0.0 { -1.0 } else { 1.0 };
        let (ox, oy) = offset;
        let mut a = [0.0; 3];
        let mut b = [0.0; 3];
        let mut k = [0.0; 3];
        for i in 0..3 {
            let (j, l) = ((i + 1) % 3, (i + 2) % 3);
            a[i] = y[j] - y[l];
            b[i] = x[l] - x[j];
            k[i] = (x[j] * y[l] - x[l] * y[j]) + (a[i] * ox + b[i] * oy);
        }
        let smooth = interpolation == Interpolation::Smooth;
        let r = if smooth {
            [sign * t.r[0], sign * t.r[1], sign * t.r[2]]
        } else {
            [sign; 3]
        };
        let combine = |weight: &[f64; 3]| -> [f64; 3] {
            let c = |coefficient: &[f64; 3]| {
                (weight[0] * coefficient[0] + weight[1] * coefficient[1]) + weight[2] * coefficient[2]
            };
            [c(&a), c(&b), c(&k)]
        };
        let (xl, yl) = limit;
        let terms = 6.0 * xl * yl + 2.0 * xl + 2.0 * yl;
        // The bound on sums computed in f64 themselves: widened by 2^-40.
        let scale = gamma(FAST_ROUNDINGS) * terms * (1.0 + 1.0 / 1_099_511_627_776.0);
        let d = combine(&r);
        let e_d = scale * (r[0].abs() + r[1].abs() + r[2].abs());
        // The uniform bound's floor: half D's least value at a vertex, `r_i |2 A|`.
        let least = r[0].abs().min(r[1].abs()).min(r[2].abs());
        let floor_d = (0.5 * area2.abs() * least).max(1024.0 * e_d);
        let q_most = (1.0 / floor_d) * (1.0 + U) * (1024.0 / 1023.0) * (1.0 + 2.0 * U);
        let mut ratio = FastRatio {
            d,
            e_d,
            n: [[0.0; 3]; FAST_CHANNELS],
            e_n: [0.0; FAST_CHANNELS],
            channels,
            floor: floor_d,
            uniform: [0.0; FAST_CHANNELS],
            most: [0.0; FAST_CHANNELS],
            offset,
            x,
            y,
            smooth,
        };
        // Every lane, the unused ones' values 0 (a fixed count the compiler can unroll).
        for c in 0..FAST_CHANNELS {
            let f = [t.values[0][c], t.values[1][c], t.values[2][c]];
            let g = [f[0] * r[0], f[1] * r[1], f[2] * r[2]];
            ratio.n[c] = combine(&g);
            let e_n = scale * (g[0].abs() + g[1].abs() + g[2].abs());
            ratio.e_n[c] = e_n;
            let most = 2.0 * f[0].abs().max(f[1].abs()).max(f[2].abs());
            // Beyond f32's range the uniform bound decides nothing (the bound at the pixel
            // still may).
            let most = if most <= f64::from(f32::MAX) / 2.0 { most } else { 0.0 };
            ratio.most[c] = most;
            ratio.uniform[c] = ((e_n + most * e_d) * q_most + 8.0 * U * most) * (1.0 + 8.0 * U) * (1.0 + 16.0 * U);
        }
        FastPlan {
            form: FastForm::Ratio(ratio),
            anchor,
            limit,
        }
    }

    /// Every channel's exact value at pixel `(x, y)` rounded to the nearest f32, into
    /// `out` (one per channel), where a bound decides it; `None` where none does (the
    /// exact inputs must decide: [`FastPlan::nearest_f32_exact`], then
    /// [`PlannedValue::nearest_f32`]).
    ///
    /// # Panics
    /// When `out` is shorter than the plan's channels.
    #[inline]
    pub fn nearest_f32(&self, x: u32, y: u32, out: &mut [Option<f32>]) {
        // Exact: integers below 2^53.
        let (xf, yf) = (f64::from(x) - self.anchor.0, f64::from(y) - self.anchor.1);
        match &self.form {
            FastForm::Undecided(channels) => out[..*channels].fill(None),
            FastForm::Constant(each, channels) => out[..*channels].copy_from_slice(&each[..*channels]),
            FastForm::Ratio(r) => {
                let out = &mut out[..r.channels];
                if xf.abs() > self.limit.0 || yf.abs() > self.limit.1 {
                    out.fill(None);
                    return;
                }
                let dv = r.d[0] * xf + r.d[1] * yf + r.d[2];
                if dv >= r.floor {
                    // The uniform bound (type docs).
                    let inv = 1.0 / dv;
                    let mut all = true;
                    for (c, o) in out.iter_mut().enumerate() {
                        let n = &r.n[c];
                        let v = (n[0] * xf + n[1] * yf + n[2]) * inv;
                        let here = decided(v - r.uniform[c], v + r.uniform[c]).filter(|_| v.abs() <= r.most[c]);
                        all &= here.is_some();
                        *o = here;
                    }
                    if all {
                        return;
                    }
                }
                for (c, o) in out.iter_mut().enumerate() {
                    *o = r.interval(xf, yf, c).and_then(|(lo, hi)| decided(lo, hi));
                }
            }
        }
    }

    /// [`FastPlan::nearest_f32`] at four pixels at once under the uniform bound alone
    /// (its arithmetic in four lanes, which the compiler can run as vectors): channel `c`
    /// of pixel `(x[i], y[i])` into `out[c][i]`, and a mask with bit `i` set where that
    /// bound does not decide every channel of pixel `i` (ask [`FastPlan::nearest_f32`]
    /// there).
    #[inline]
    pub fn nearest_f32_x4(&self, x: [u32; 4], y: [u32; 4], out: &mut [[f32; 4]; FAST_CHANNELS]) -> u8 {
        let r = match &self.form {
            FastForm::Ratio(r) => r,
            FastForm::Undecided(_) => return 0xf,
            FastForm::Constant(each, channels) => {
                let mut all = true;
                for (c, e) in each[..*channels].iter().enumerate() {
                    out[c] = [e.unwrap_or(0.0); 4];
                    all &= e.is_some();
                }
                return if all { 0 } else { 0xf };
            }
        };

        let mut xf = [0.0; 4];
        let mut yf = [0.0; 4];
        for i in 0..4 {
            xf[i] = f64::from(x[i]) - self.anchor.0;
            yf[i] = f64::from(y[i]) - self.anchor.1;
        }
        let mut ok = [false; 4];
        let mut inv = [0.0; 4];
        for i in 0..4 {
            let dv = r.d[0] * xf[i] + r.d[1] * yf[i] + r.d[2];
            ok[i] = (dv >= r.floor) & (xf[i].abs() <= self.limit.0) & (yf[i].abs() <= self.limit.1);
            inv[i] = 1.0 / dv;
        }
        let lanes = out.iter_mut().zip(&r.n).zip(r.uniform.iter().zip(&r.most));
        for ((out_c, n), (&u, &most)) in lanes.take(r.channels) {
            for i in 0..4 {
                let v = (n[0] * xf[i] + n[1] * yf[i] + n[2]) * inv[i];
                #[allow(clippy::cast_possible_truncation)] // rounding to f32 is the point
                let (lo, hi) = ((v - u) as f32, (v + u) as f32);
                // |v| <= most <= f32::MAX: both ends finite (most is 0 for a value f32
                // cannot hold), and a NaN fails the comparison.
                ok[i] &= (lo.to_bits() == hi.to_bits()) & (v.abs() <= most);
                out_c[i] = lo;
            }
        }
        u8::from(!ok[0]) | u8::from(!ok[1]) << 1 | u8::from(!ok[2]) << 2 | u8::from(!ok[3]) << 3
    }

    /// Whether channel `channel`'s exact value at pixel `(x, y)` lies within `bound` of
    /// `t`, where the bound at the pixel decides it (as [`PlannedValue::within`]); `None`
    /// where it does not.
    pub fn within(&self, x: u32, y: u32, channel: usize, t: f32, bound: f64) -> Option<bool> {
        let (xf, yf) = (f64::from(x) - self.anchor.0, f64::from(y) - self.anchor.1);
        let (lo, hi) = match &self.form {
            FastForm::Ratio(r) if channel < r.channels && xf.abs() <= self.limit.0 && yf.abs() <= self.limit.1 => {
                r.interval(xf, yf, channel)?
            }
            _ => return None,
        };
        // The exact value lies in [lo, hi]: |t - v| is at most the farther end's distance
        // and at least the nearer's (0 inside), each difference rounded once.
        let t = f64::from(t);
        let (to_lo, to_hi) = ((t - lo).abs(), (t - hi).abs());
        let farthest = to_lo.max(to_hi) * (1.0 + 2.0 * U);
        let nearest = if lo <= t && t <= hi {
            0.0
        } else {
            to_lo.min(to_hi) * (1.0 - 2.0 * U)
        };
        if !farthest.is_finite() {
            None
        } else if farthest <= bound {
            Some(true)
        } else if nearest > bound {
            Some(false)
        } else {
            None
        }
    }

    /// Channel `channel`'s exact value at pixel `(x, y)` rounded to the nearest f32, where
    /// the bound at the pixel leaves exactly two neighbouring f32s of one sign, `a < b`:
    /// then the exact value `v` rounds to `a` below their midpoint `m`, to `b` above it,
    /// and to the even one at it, and the sign of `v - m = (N - m D) / D` decides, `N - m D
    /// = sum (f_i - m) r_i E_i(p)` and `D`, computed exactly from `setup`'s rationals (the
    /// window positions, which f64 holds exactly, and `p`, dyadic). `None` in any other
    /// case (the caller asks [`PlannedValue::nearest_f32`]). `setup` must be the triangle
    /// the plan was set up from, with `channel` counted from the plan's first channel at
    /// `first` of `setup`'s.
    pub fn nearest_f32_exact(&self, setup: &ValueSetup, first: usize, x: u32, y: u32, channel: usize) -> Option<f32> {
        let (FastForm::Ratio(r), ValueSetup::Triangle(t)) = (&self.form, setup) else {
            return None;
        };
        let (xf, yf) = (f64::from(x) - self.anchor.0, f64::from(y) - self.anchor.1);
        if xf.abs() > self.limit.0 || yf.abs() > self.limit.1 || channel >= r.channels {
            return None;
        }
        let (lo, hi) = r.interval(xf, yf, channel)?;
        #[allow(clippy::cast_possible_truncation)] // rounding to f32 is the point
        let (a, b) = (lo as f32, hi as f32);
        let neighbours = a.is_finite()
            && b.is_finite()
            && a != 0.0
            && b != 0.0
            && (a > 0.0) == (b > 0.0)
            && f32::from_bits(if a > 0.0 { a.to_bits() + 1 } else { a.to_bits() - 1 }) == b;
        if !neighbours {
            return None;
        }
        let m = BigRational::from_float((f64::from(a) + f64::from(b)) / 2.0)?;
        let exact = BigRational::from_float;
        let (px, py) = (exact(xf)? + exact(r.offset.0)?, exact(yf)? + exact(r.offset.1)?);
        let each = |c: &[f64; 3]| Some([exact(c[0])?, exact(c[1])?, exact(c[2])?]);
        let (vx, vy) = (each(&r.x)?, each(&r.y)?);
        let (mut n, mut d) = (BigRational::zero(), BigRational::zero());
        for i in 0..3 {
            let (j, l) = ((i + 1) % 3, (i + 2) % 3);
            let e = (&vx[j] - &px) * (&vy[l] - &py) - (&vx[l] - &px) * (&vy[j] - &py);
            let re = if r.smooth { e / &t.h[i][2] } else { e };
            n += (&t.values[i][first + channel] - &m) * &re;
            d += re;
        }
        Some(match (n.signum() * d.signum()).cmp(&BigRational::zero()) {
            std::cmp::Ordering::Less => a,
            std::cmp::Ordering::Greater => b,
            std::cmp::Ordering::Equal if d.is_zero() => return None,
            std::cmp::Ordering::Equal => {
                if a.to_bits() % 2 == 0 {
                    a
                } else {
                    b
                }
            }
        })
    }
}

impl FastRatio {
    /// Channel `c`'s certified interval at the relative pixel `(xf, yf)` under the bound
    /// at the pixel ([`FastPlan`]), when `|D'|` is large enough for it.
    #[inline]
    fn interval(&self, xf: f64, yf: f64, c: usize) -> Option<(f64, f64)> {
        let dv = self.d[0] * xf + self.d[1] * yf + self.d[2];
        // A NaN denominator fails the test too.
        let far_enough = dv.abs() > 1024.0 * self.e_d;
        if !far_enough {
            return None;
        }
        let inv = 1.0 / dv;
        let q = inv.abs() * (1024.0 / 1023.0) * (1.0 + 2.0 * U);
        let p = self.e_d * q + 8.0 * U;
        let n = &self.n[c];
        let v = (n[0] * xf + n[1] * yf + n[2]) * inv;
        let e = (v.abs() * p + self.e_n[c] * q) * (1.0 + 8.0 * U);
        Some((v - e, v + e))
    }
}
