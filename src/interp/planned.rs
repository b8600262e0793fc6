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
//! At pixel `(x, y)` the point is `(x + c, y + c)` for the convention's centre `c`, so the
//! value is `N(x, y) / D(x, y)` with `N = a x + b y + k` and `D = d x + e y + g`, six exact
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
                // q = (x + centre, y + centre, 1).
                let affine = |weight: &dyn Fn(usize) -> BigRational| {
                    let mut c = [BigRational::zero(), BigRational::zero(), BigRational::zero()];
                    for (i, n) in normals.iter().enumerate() {
                        let w = weight(i);
                        for k in 0..3 {
                            c[k] += &w * &n[k];
                        }
                    }
                    let k = &c[2] + (&c[0] + &c[1]) * centre;
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
                let from = (centre - &a.x) * &dx + (centre - &a.y) * &dy;
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
