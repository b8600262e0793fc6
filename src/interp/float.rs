//! Float models of how interpolators are really built: a triangle's per-vertex values
//! turned into a value at a pixel by a stated sequence of f32 (or f64) operations, so that
//! a renderer's output can be reproduced bit for bit ([`FloatInterpolator`]).
//!
//! Every model sets up from the renderer's own inputs ([`FloatTriangle`]: window positions,
//! `1 / w` and the values, each an f32) and differs from the others in the choices
//! implementations make:
//!
//! - [`Form`]: a plane `a0 + dadx x + dady y` whose `a0` is the plane extrapolated to the
//!   framebuffer's origin with the pixel centre folded in (Mesa llvmpipe's
//!   `lp_state_setup.c` sets up `a0 = a_0 - (dadx (x_0 - 1/2) + dady (y_0 - 1/2))` and
//!   `lp_bld_interp.c` evaluates it at integer pixel coordinates); the same plane anchored
//!   at vertex 0 (`a_0 + dadx (p_x - x_0) + dady (p_y - y_0)`); or barycentrics from the
//!   three edge functions at the pixel's centre (`sum E_i a_i / sum E_i`, Pineda 1988);
//! - the gradient, the same for both planes: `ooa = 1 / (dx01 dy20 - dy01 dx20)`, then
//!   `dadx = da01 (dy20 ooa) - da20 (dy01 ooa)` and `dady = da20 (dx01 ooa) - da01 (dx20
//!   ooa)` with `dx01 = x_0 - x_1`, `dx20 = x_2 - x_0`, `da01 = a_0 - a_1`, `da20 = a_2 -
//!   a_0` (llvmpipe's order of operations);
//! - whether the evaluation fuses each multiply-add (`fma`: one rounding, as LLVM's
//!   `llvm.fmuladd` on a CPU with FMA) or rounds the product and the sum;
//! - [`VertexOrder`]: vertices as given, or a clockwise triangle (negative area in the
//!   model's window coordinates) reordered counter-clockwise the way llvmpipe's
//!   `lp_setup_tri.c` does, `(v0, v2, v1)` when the provoking vertex is the first and
//!   `(v1, v0, v2)` when it is the last: the anchor moves, the provoking vertex does not;
//! - a `smooth` value: each vertex value premultiplied by its `1 / w`, the plane of `1 / w`
//!   interpolated beside it, then the quotient, as `a * (1 / W)` ([`Divide::Reciprocal`],
//!   llvmpipe's `lp_build_rcp` then a multiply) or `a / W`;
//! - f32 throughout, or f64 rounded to f32 once at the end;
//! - the window's y axis: the scene's (down) or GL's (up, `y' = H - y`, the pixel row
//!   counted from the bottom), since a GL renderer sets up in its own window coordinates.
//!
//! A `flat` value is the provoking vertex's value in every model.

use std::ops::{Add, Div, Mul, Sub};

use crate::interp::values::{Interpolation, ProvokingVertex};

/// How the value at a pixel is formed (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Form {
    /// `a0 + dadx x + dady y` at integer pixel coordinates, `a0` at the framebuffer's
    /// origin with the pixel centre folded in.
    OriginPlane,
    /// `a_0 + dadx (p_x - x_0) + dady (p_y - y_0)` at the pixel's centre.
    VertexPlane,
    /// `sum E_i(p) a_i / sum E_i(p)` at the pixel's centre.
    Barycentric,
}

/// The vertex order the setup sees (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum VertexOrder {
    /// As given.
    AsGiven,
    /// A clockwise triangle reordered counter-clockwise, keeping the provoking vertex.
    CounterClockwise,
}

/// How a `smooth` value's quotient is taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Divide {
    /// `a * (1 / W)`.
    Reciprocal,
    /// `a / W`.
    Quotient,
}

/// One model of an interpolator (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct FloatInterpolator {
    /// How the value is formed.
    pub form: Form,
    /// Whether each multiply-add of the evaluation is fused.
    pub fma: bool,
    /// The vertex order of the setup.
    pub order: VertexOrder,
    /// The smooth quotient.
    pub divide: Divide,
    /// f64 arithmetic rounded to f32 at the end, instead of f32 throughout.
    pub f64: bool,
    /// The setup in GL's window coordinates, y up.
    pub y_up: bool,
}

/// A triangle as a renderer holds it: window positions, `1 / w` and the values of every
/// channel, each an f32 (the scene's exact numbers rounded to nearest).
#[derive(Debug, Clone, PartialEq)]
pub struct FloatTriangle {
    /// Window x of each vertex.
    pub x: [f32; 3],
    /// Window y of each vertex (the scene's, y down).
    pub y: [f32; 3],
    /// `1 / w` of each vertex.
    pub inv_w: [f32; 3],
    /// Each vertex's values.
    pub values: [Vec<f32>; 3],
}

/// The arithmetic a model runs in.
trait Real: Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self> {
    fn of(v: f32) -> Self;
    fn fused(self, b: Self, c: Self) -> Self;
    fn out(self) -> f32;
}

impl Real for f32 {
    fn of(v: f32) -> f32 {
        v
    }
    fn fused(self, b: f32, c: f32) -> f32 {
        self.mul_add(b, c)
    }
    fn out(self) -> f32 {
        self
    }
}

impl Real for f64 {
    fn of(v: f32) -> f64 {
        f64::from(v)
    }
    fn fused(self, b: f64, c: f64) -> f64 {
        self.mul_add(b, c)
    }
    #[allow(clippy::cast_possible_truncation)] // rounding to f32 is the model's last step
    fn out(self) -> f32 {
        self as f32
    }
}

impl FloatInterpolator {
    /// Every model, llvmpipe's first: origin plane, fused, counter-clockwise, reciprocal,
    /// f32, y up.
    pub fn all() -> Vec<FloatInterpolator> {
        let mut out = Vec::new();
        for y_up in [true, false] {
            for form in [Form::OriginPlane, Form::VertexPlane, Form::Barycentric] {
                for fma in [true, false] {
                    for order in [VertexOrder::CounterClockwise, VertexOrder::AsGiven] {
                        for divide in [Divide::Reciprocal, Divide::Quotient] {
                            for f64 in [false, true] {
                                out.push(FloatInterpolator {
                                    form,
                                    fma,
                                    order,
                                    divide,
                                    f64,
                                    y_up,
                                });
                            }
                        }
                    }
                }
            }
        }
        out
    }

    /// The model's name: its choices joined by spaces, e.g. `origin-plane fma ccw rcp f32
    /// y-up`.
    pub fn name(&self) -> String {
        format!(
            "{} {} {} {} {} {}",
            match self.form {
                Form::OriginPlane => "origin-plane",
                Form::VertexPlane => "vertex-plane",
                Form::Barycentric => "barycentric",
            },
            if self.fma { "fma" } else { "no-fma" },
            match self.order {
                VertexOrder::AsGiven => "as-given",
                VertexOrder::CounterClockwise => "ccw",
            },
            match self.divide {
                Divide::Reciprocal => "rcp",
                Divide::Quotient => "div",
            },
            if self.f64 { "f64" } else { "f32" },
            if self.y_up { "y-up" } else { "y-down" },
        )
    }

    /// The value of channel `channel` at pixel `(px, py)` (a canvas of height `height`,
    /// pixel centres at `+ centre`) under `interpolation`.
    ///
    /// ```
    /// use rasterproof::interp::float::{FloatInterpolator, FloatTriangle};
    /// use rasterproof::interp::values::{Interpolation, ProvokingVertex};
    /// // The value x over (0, 0), (8, 0), (0, 8): every model gives 1.5 at pixel (1, 3).
    /// let t = FloatTriangle {
    ///     x: [0.0, 8.0, 0.0],
    ///     y: [0.0, 0.0, 8.0],
    ///     inv_w: [1.0; 3],
    ///     values: [vec![0.0], vec![8.0], vec![0.0]],
    /// };
    /// for m in FloatInterpolator::all() {
    ///     let v = m.value(&t, Interpolation::Smooth, ProvokingVertex::First, 0, (1, 3), 8, 0.5);
    ///     assert_eq!(v, 1.5, "{}", m.name());
    /// }
    /// ```
    #[allow(clippy::too_many_arguments)]
    pub fn value(
        &self,
        t: &FloatTriangle,
        interpolation: Interpolation,
        provoking: ProvokingVertex,
        channel: usize,
        (px, py): (u32, u32),
        height: u32,
        centre: f32,
    ) -> f32 {
        if interpolation == Interpolation::Flat {
            return t.values[provoking.vertex(3)][channel];
        }
        if self.f64 {
            self.eval::<f64>(t, interpolation, provoking, channel, (px, py), height, centre)
        } else {
            self.eval::<f32>(t, interpolation, provoking, channel, (px, py), height, centre)
        }
    }

    #[allow(clippy::too_many_arguments, clippy::cast_precision_loss)]
    fn eval<R: Real>(
        &self,
        t: &FloatTriangle,
        interpolation: Interpolation,
        provoking: ProvokingVertex,
        channel: usize,
        (px, py): (u32, u32),
        height: u32,
        centre: f32,
    ) -> f32 {
        let flip = |y: f32| if self.y_up { height as f32 - y } else { y };
        let row = if self.y_up { height - 1 - py } else { py };
        let (x, y) = (t.x.map(R::of), t.y.map(|v| R::of(flip(v))));
        let mut order = [0, 1, 2];
        if self.order == VertexOrder::CounterClockwise {
            let area = (x[0] - x[1]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[0] - y[1]);
            if area.out() < 0.0 {
                order = match provoking {
                    ProvokingVertex::First => [0, 2, 1],
                    ProvokingVertex::Last => [1, 0, 2],
                };
            }
        }
        let x = order.map(|i| x[i]);
        let y = order.map(|i| y[i]);
        let perspective = interpolation == Interpolation::Smooth;
        let inv_w = order.map(|i| R::of(t.inv_w[i]));
        let a = order.map(|i| {
            let v = R::of(t.values[i][channel]);
            if perspective {
                v * R::of(t.inv_w[i])
            } else {
                v
            }
        });
        let pixel = (R::of(px as f32), R::of(row as f32));
        let c = R::of(centre);
        let at = (pixel.0 + c, pixel.1 + c);
        let plane = |g: [R; 3]| -> R {
            match self.form {
                Form::Barycentric => {
                    let e = |j: usize, k: usize| (x[j] - at.0) * (y[k] - at.1) - (x[k] - at.0) * (y[j] - at.1);
                    let (e0, e1, e2) = (e(1, 2), e(2, 0), e(0, 1));
                    (e0 * g[0] + e1 * g[1] + e2 * g[2]) / (e0 + e1 + e2)
                }
                Form::OriginPlane | Form::VertexPlane => {
                    let (dx01, dy01) = (x[0] - x[1], y[0] - y[1]);
                    let (dx20, dy20) = (x[2] - x[0], y[2] - y[0]);
                    let ooa = R::of(1.0) / (dx01 * dy20 - dy01 * dx20);
                    let (dx20o, dy20o, dx01o, dy01o) = (dx20 * ooa, dy20 * ooa, dx01 * ooa, dy01 * ooa);
                    let (da01, da20) = (g[0] - g[1], g[2] - g[0]);
                    let dadx = da01 * dy20o - da20 * dy01o;
                    let dady = da20 * dx01o - da01 * dx20o;
                    let (base, ex, ey) = if self.form == Form::OriginPlane {
                        let a0 = g[0] - (dadx * (x[0] - c) + dady * (y[0] - c));
                        (a0, pixel.0, pixel.1)
                    } else {
                        (g[0], at.0 - x[0], at.1 - y[0])
                    };
                    if self.fma {
                        dady.fused(ey, dadx.fused(ex, base))
                    } else {
                        base + dadx * ex + dady * ey
                    }
                }
            }
        };
        let value = plane(a);
        if !perspective {
            return value.out();
        }
        let w = plane(inv_w);
        match self.divide {
            Divide::Reciprocal => (value * (R::of(1.0) / w)).out(),
            Divide::Quotient => (value / w).out(),
        }
    }
}
