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
//!
//! One more form is not a plane but 2D homogeneous rasterization (Olano and Greer 1997),
//! as the pure-Rust software renderer euc 0.5.3 builds it (`src/rasterizer/triangles.rs`,
//! with vek 0.14's products) and adapters/euc feeds it: [`Form::Homogeneous`]`(k)`, named
//! `homogeneous-S` for a square target of side `S = 2^k`. Each vertex is sent at clip
//! position `(ndc_x w, ndc_y w, 0, w)` with `ndc_x = x (2/S) - 1` and `ndc_y = 1 - y (2/S)`
//! (y up; `w` taken back as `1 / (1 / w)` from the model's input, the scene's w where it is
//! a power of two, and 1 for a `noperspective` value); with `c = (x_c, y_c, w_c)`
//! the last vertex's `(x, y, w)`, `ca = a - c`, `cb = b - c`, `n = ca x cb` and `r = 1 / (n .
//! c)` (`((n_x c_x + n_y c_y) + n_z c_z)`; 1 when `n` is zero), the matrix with rows `cb x
//! c`, `c x ca`, `n`, each entry times `r`, times the NDC matrix `[[2/S, 0, -1], [0, -2/S,
//! 1], [0, 0, 1]]` (each entry `(m_0 t_0j + m_1 t_1j) + m_2 t_2j`) gives `F`, and at the
//! pixel's centre `p`, `h_i = (F_i0 p_x + F_i1 p_y) + F_i2`; the weights are `w_a = h_0 /
//! h_2`, `w_b = h_1 / h_2`, `w_c = (1 - w_a) - w_b` (perspective-correct, since the
//! positions carry w) and the value `w_a a + (w_b b + w_c c)`, fused as
//! `fma(a, w_a, fma(b, w_b, c w_c))` under `fma` (euc's `Interpolate::lerp3`). Every other
//! operation is one rounding (vek's `mul_add` on f32 is a product and a sum, unfused). [`VertexOrder::Reversed`] is euc's reordering: a triangle
//! whose NDC cross product `(b - a) x (c - a)` is negative (clockwise with y up) is set up as
//! `(c, b, a)`. The matrix is ill-conditioned when the triangle is small against its
//! distance from the target's centre (every NDC coordinate and every `n` entry loses the
//! bits of that ratio), so these models are not bounded by [`crate::interp::envelope`]'s
//! error bound ([`FloatInterpolator::enveloped`]).

use std::ops::{Add, Div, Mul, Range, Sub};

use crate::interp::values::{Interpolation, ProvokingVertex, ValueSetup};
use crate::num::exact::nearest_f32;

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
    /// euc's 2D homogeneous weights on a square target of side `2^k` (module docs).
    Homogeneous(u8),
}

/// The largest `k` of [`Form::Homogeneous`] that [`FloatInterpolator::all`] lists: a target
/// of side 2^14, the largest canvas.
pub const HOMOGENEOUS_MAX_LOG2: u8 = 14;

/// The vertex order the setup sees (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum VertexOrder {
    /// As given.
    AsGiven,
    /// A clockwise triangle reordered counter-clockwise, keeping the provoking vertex.
    CounterClockwise,
    /// euc's: a triangle clockwise in y-up NDC (for the planes: a negative area in the
    /// model's window coordinates) set up as `(v2, v1, v0)`.
    Reversed,
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

impl FloatTriangle {
    /// `setup`'s triangle as a renderer holds it: each position, `w` and value rounded to
    /// the nearest f32, and `1 / w` the f32 reciprocal of the rounded `w`; `None` when an
    /// input is not a finite f32, or for a segment.
    pub fn of(setup: &ValueSetup) -> Option<FloatTriangle> {
        let ValueSetup::Triangle(t) = setup else {
            return None;
        };
        let w: Vec<f32> = t.h.iter().map(|h| nearest_f32(&h[2])).collect::<Option<_>>()?;
        let coord = |i: usize, c: usize| nearest_f32(&(&t.h[i][c] / &t.h[i][2]));
        let x = [coord(0, 0)?, coord(1, 0)?, coord(2, 0)?];
        let y = [coord(0, 1)?, coord(1, 1)?, coord(2, 1)?];
        let values = [0, 1, 2].map(|i| t.values[i].iter().map(nearest_f32).collect::<Option<Vec<f32>>>());
        let [Some(a), Some(b), Some(c)] = values else {
            return None;
        };
        Some(FloatTriangle {
            x,
            y,
            inv_w: [1.0 / w[0], 1.0 / w[1], 1.0 / w[2]],
            values: [a, b, c],
        })
    }
}

/// The arithmetic a model runs in.
trait Real:
    Copy + std::fmt::Debug + PartialEq + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self>
{
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
    /// f32, y up; the 96 plane and barycentric models, then euc's homogeneous ones for each
    /// target side 2^0 to 2^14, fused or not, reversed or as given (quotient, f32, y down).
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
        for k in 0..=HOMOGENEOUS_MAX_LOG2 {
            for fma in [true, false] {
                for order in [VertexOrder::Reversed, VertexOrder::AsGiven] {
                    out.push(FloatInterpolator {
                        form: Form::Homogeneous(k),
                        fma,
                        order,
                        divide: Divide::Quotient,
                        f64: false,
                        y_up: false,
                    });
                }
            }
        }
        out
    }

    /// Whether the model's error is bounded by [`crate::interp::envelope`]'s: every plane
    /// and barycentric model; not the homogeneous ones (module docs).
    pub fn enveloped(&self) -> bool {
        !matches!(self.form, Form::Homogeneous(_))
    }

    /// The model's name: its choices joined by spaces, e.g. `origin-plane fma ccw rcp f32
    /// y-up`, or euc's on a 64-pixel target, `homogeneous-64 fma rev div f32 y-down`.
    pub fn name(&self) -> String {
        format!(
            "{} {} {} {} {} {}",
            match self.form {
                Form::OriginPlane => "origin-plane".to_string(),
                Form::VertexPlane => "vertex-plane".to_string(),
                Form::Barycentric => "barycentric".to_string(),
                Form::Homogeneous(k) => format!("homogeneous-{}", 1u32 << k),
            },
            if self.fma { "fma" } else { "no-fma" },
            match self.order {
                VertexOrder::AsGiven => "as-given",
                VertexOrder::CounterClockwise => "ccw",
                VertexOrder::Reversed => "rev",
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
    /// // The value x over (0, 0), (8, 0), (0, 8): every plane and barycentric model gives
    /// // 1.5 at pixel (1, 3), and so does euc's homogeneous setup on an 8-pixel target.
    /// let t = FloatTriangle {
    ///     x: [0.0, 8.0, 0.0],
    ///     y: [0.0, 0.0, 8.0],
    ///     inv_w: [1.0; 3],
    ///     values: [vec![0.0], vec![8.0], vec![0.0]],
    /// };
    /// for m in FloatInterpolator::all().into_iter().filter(|m| m.enveloped() || m.name().starts_with("homogeneous-8 ")) {
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
        if let Form::Homogeneous(k) = self.form {
            return self.homogeneous_value(t, interpolation, channel, (px, py), k, centre);
        }
        let mut out = [0.0];
        self.setup(t, interpolation, provoking, channel..channel + 1, height, centre)
            .values((px, py), &mut out);
        out[0]
    }

    /// The model set up once for triangle `t`'s channels `channels` (at most
    /// [`SETUP_CHANNELS`]) under `interpolation`, on a canvas of height `height` with pixel
    /// centres at `+ centre`: the vertex order, the gradients and the plane's anchor
    /// computed once, as a renderer computes them per primitive, so that
    /// [`FloatSetup::values`] runs only the per-pixel operations.
    /// [`FloatInterpolator::value`] is this setup's value at one pixel, bit for bit (the
    /// same code; euc's homogeneous forms set up per pixel, as euc does).
    ///
    /// ```
    /// use rasterproof::interp::float::{FloatInterpolator, FloatTriangle};
    /// use rasterproof::interp::values::{Interpolation, ProvokingVertex};
    /// let t = FloatTriangle {
    ///     x: [0.0, 8.0, 0.0],
    ///     y: [0.0, 0.0, 8.0],
    ///     inv_w: [1.0, 0.5, 0.25],
    ///     values: [vec![0.0, 1.0], vec![8.0, 3.0], vec![0.0, 5.0]],
    /// };
    /// let m = FloatInterpolator::all()[0];
    /// let setup = m.setup(&t, Interpolation::Smooth, ProvokingVertex::First, 0..2, 8, 0.5);
    /// let mut out = [0.0; 2];
    /// setup.values((1, 3), &mut out);
    /// for c in 0..2 {
    ///     let one = m.value(&t, Interpolation::Smooth, ProvokingVertex::First, c, (1, 3), 8, 0.5);
    ///     assert_eq!(out[c].to_bits(), one.to_bits());
    /// }
    /// ```
    ///
    /// # Panics
    /// When `channels` holds more than [`SETUP_CHANNELS`] channels, or channels a vertex
    /// does not have.
    pub fn setup(
        &self,
        t: &FloatTriangle,
        interpolation: Interpolation,
        provoking: ProvokingVertex,
        channels: Range<usize>,
        height: u32,
        centre: f32,
    ) -> FloatSetup {
        assert!(
            channels.len() <= SETUP_CHANNELS,
            "a float setup holds at most {SETUP_CHANNELS} channels, not {}",
            channels.len()
        );
        let kind = if interpolation == Interpolation::Flat {
            let mut each = [0.0; SETUP_CHANNELS];
            for (e, c) in each.iter_mut().zip(channels.clone()) {
                *e = t.values[provoking.vertex(3)][c];
            }
            Kind::Flat(each, channels.len())
        } else if let Form::Homogeneous(k) = self.form {
            Kind::Homogeneous {
                model: *self,
                triangle: t.clone(),
                interpolation,
                channels,
                k,
                centre,
            }
        } else if self.f64 {
            Kind::F64(Planes::new(self, t, interpolation, provoking, channels, height, centre))
        } else {
            Kind::F32(Planes::new(self, t, interpolation, provoking, channels, height, centre))
        };
        FloatSetup { kind }
    }

    /// euc's value, in the model's arithmetic.
    fn homogeneous_value(
        &self,
        t: &FloatTriangle,
        interpolation: Interpolation,
        channel: usize,
        pixel: (u32, u32),
        k: u8,
        centre: f32,
    ) -> f32 {
        if self.f64 {
            self.homogeneous::<f64>(t, interpolation, channel, pixel, k, centre)
        } else {
            self.homogeneous::<f32>(t, interpolation, channel, pixel, k, centre)
        }
    }

    /// euc's value on a target of side `2^k` (module docs), every step as euc and vek take it.
    #[allow(clippy::cast_precision_loss, clippy::many_single_char_names)]
    fn homogeneous<R: Real>(
        &self,
        t: &FloatTriangle,
        interpolation: Interpolation,
        channel: usize,
        (px, py): (u32, u32),
        k: u8,
        centre: f32,
    ) -> f32 {
        let (zero, one) = (R::of(0.0), R::of(1.0));
        let side = R::of((1u32 << k) as f32);
        let scale = R::of(2.0) / side;
        let cross = |a: [R; 3], b: [R; 3]| {
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        };
        let dot = |a: [R; 3], b: [R; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        // The vertex shader: clip-space (x, y, w), and the NDC point after the divide.
        let hom = [0, 1, 2].map(|i| {
            let w = if interpolation == Interpolation::Smooth {
                one / R::of(t.inv_w[i])
            } else {
                one
            };
            let ndc_x = R::of(t.x[i]) * scale - one;
            let ndc_y = one - R::of(t.y[i]) * scale;
            [ndc_x * w, ndc_y * w, w]
        });
        let ndc = hom.map(|h| [h[0] / h[2], h[1] / h[2]]);
        let mut order = [0, 1, 2];
        if self.order == VertexOrder::Reversed {
            let (ab, ac) = (
                [ndc[1][0] - ndc[0][0], ndc[1][1] - ndc[0][1]],
                [ndc[2][0] - ndc[0][0], ndc[2][1] - ndc[0][1]],
            );
            if (ab[0] * ac[1] - ab[1] * ac[0]).out() < 0.0 {
                order = [2, 1, 0];
            }
        }
        let [a, b, c] = order.map(|i| hom[i]);
        let ca = [a[0] - c[0], a[1] - c[1], a[2] - c[2]];
        let cb = [b[0] - c[0], b[1] - c[1], b[2] - c[2]];
        let n = cross(ca, cb);
        let r = if dot(n, n).out() > 0.0 { one / dot(n, c) } else { one };
        let m = [cross(cb, c), cross(c, ca), n].map(|row| row.map(|e| e * r));
        let ndc_matrix = [
            [scale, zero, R::of(-1.0)],
            [zero, R::of(-2.0) / side, one],
            [zero, zero, one],
        ];
        let f = m.map(|row| {
            [0, 1, 2].map(|j| row[0] * ndc_matrix[0][j] + row[1] * ndc_matrix[1][j] + row[2] * ndc_matrix[2][j])
        });
        let p = (R::of(px as f32) + R::of(centre), R::of(py as f32) + R::of(centre));
        let h = f.map(|row| row[0] * p.0 + row[1] * p.1 + row[2]);
        let (wa, wb) = match self.divide {
            Divide::Quotient => (h[0] / h[2], h[1] / h[2]),
            Divide::Reciprocal => {
                let rcp = one / h[2];
                (h[0] * rcp, h[1] * rcp)
            }
        };
        let wc = one - wa - wb;
        let [va, vb, vc] = order.map(|i| R::of(t.values[i][channel]));
        if self.fma {
            va.fused(wa, vb.fused(wb, vc * wc)).out()
        } else {
            (va * wa + (vb * wb + vc * wc)).out()
        }
    }
}

/// The channels a [`FloatSetup`] holds at most (a vec4's).
pub const SETUP_CHANNELS: usize = 4;

/// A model set up for one triangle ([`FloatInterpolator::setup`]): its values at pixels.
#[derive(Debug, Clone, PartialEq)]
pub struct FloatSetup {
    kind: Kind,
}

#[derive(Debug, Clone, PartialEq)]
enum Kind {
    /// The provoking vertex's values.
    Flat([f32; SETUP_CHANNELS], usize),
    F32(Planes<f32>),
    F64(Planes<f64>),
    /// euc's forms, set up per pixel.
    Homogeneous {
        model: FloatInterpolator,
        triangle: FloatTriangle,
        interpolation: Interpolation,
        channels: Range<usize>,
        k: u8,
        centre: f32,
    },
}

impl FloatSetup {
    /// How many channels it evaluates.
    pub fn channels(&self) -> usize {
        match &self.kind {
            Kind::Flat(_, n) => *n,
            Kind::F32(p) => p.channels,
            Kind::F64(p) => p.channels,
            Kind::Homogeneous { channels, .. } => channels.len(),
        }
    }

    /// Every channel's value at pixel `(px, py)`, into `out` (one per channel).
    ///
    /// # Panics
    /// When `out` is shorter than [`FloatSetup::channels`].
    #[inline]
    pub fn values(&self, pixel: (u32, u32), out: &mut [f32]) {
        match &self.kind {
            Kind::Flat(each, n) => out[..*n].copy_from_slice(&each[..*n]),
            Kind::F32(p) => p.values(pixel, out),
            Kind::F64(p) => p.values(pixel, out),
            Kind::Homogeneous {
                model,
                triangle,
                interpolation,
                channels,
                k,
                centre,
            } => {
                let out = &mut out[..channels.len()];
                for (o, c) in out.iter_mut().zip(channels.clone()) {
                    *o = model.homogeneous_value(triangle, *interpolation, c, pixel, *k, *centre);
                }
            }
        }
    }
}

/// What a plane or barycentric model evaluates per pixel: `base + dadx e_x + dady e_y`, or
/// the vertices' own values weighted by the edge functions.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Weights<R> {
    /// `[base, dadx, dady]`.
    Plane([R; 3]),
    /// The vertices' values (premultiplied by `1 / w` for a smooth value).
    Vertices([R; 3]),
}

/// A plane or barycentric model set up for one triangle (the module docs' choices).
#[derive(Debug, Clone, PartialEq)]
struct Planes<R> {
    form: Form,
    fma: bool,
    divide: Divide,
    y_up: bool,
    height: u32,
    centre: R,
    /// The vertices in the setup's order (y flipped for a y-up setup).
    x: [R; 3],
    y: [R; 3],
    /// `1 / w`'s weights, for a smooth value.
    w: Option<Weights<R>>,
    values: [Weights<R>; SETUP_CHANNELS],
    channels: usize,
}

impl<R: Real> Planes<R> {
    #[allow(clippy::cast_precision_loss)] // the model's own conversion of the canvas height
    fn new(
        m: &FloatInterpolator,
        t: &FloatTriangle,
        interpolation: Interpolation,
        provoking: ProvokingVertex,
        channels: Range<usize>,
        height: u32,
        centre: f32,
    ) -> Planes<R> {
        let flip = |y: f32| if m.y_up { height as f32 - y } else { y };
        let (x, y) = (t.x.map(R::of), t.y.map(|v| R::of(flip(v))));
        let mut order = [0, 1, 2];
        if m.order == VertexOrder::CounterClockwise {
            let area = (x[0] - x[1]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[0] - y[1]);
            if area.out() < 0.0 {
                order = match provoking {
                    ProvokingVertex::First => [0, 2, 1],
                    ProvokingVertex::Last => [1, 0, 2],
                };
            }
        } else if m.order == VertexOrder::Reversed {
            let area = (x[0] - x[1]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[0] - y[1]);
            if area.out() < 0.0 {
                order = [2, 1, 0];
            }
        }
        let x = order.map(|i| x[i]);
        let y = order.map(|i| y[i]);
        let perspective = interpolation == Interpolation::Smooth;
        let c = R::of(centre);
        let weights = |g: [R; 3]| -> Weights<R> {
            if m.form == Form::Barycentric {
                return Weights::Vertices(g);
            }
            let (dx01, dy01) = (x[0] - x[1], y[0] - y[1]);
            let (dx20, dy20) = (x[2] - x[0], y[2] - y[0]);
            let ooa = R::of(1.0) / (dx01 * dy20 - dy01 * dx20);
            let (dx20o, dy20o, dx01o, dy01o) = (dx20 * ooa, dy20 * ooa, dx01 * ooa, dy01 * ooa);
            let (da01, da20) = (g[0] - g[1], g[2] - g[0]);
            let dadx = da01 * dy20o - da20 * dy01o;
            let dady = da20 * dx01o - da01 * dx20o;
            let base = if m.form == Form::OriginPlane {
                g[0] - (dadx * (x[0] - c) + dady * (y[0] - c))
            } else {
                g[0]
            };
            Weights::Plane([base, dadx, dady])
        };
        let mut values = [Weights::Vertices([R::of(0.0); 3]); SETUP_CHANNELS];
        for (out, channel) in values.iter_mut().zip(channels.clone()) {
            let a = order.map(|i| {
                let v = R::of(t.values[i][channel]);
                if perspective {
                    v * R::of(t.inv_w[i])
                } else {
                    v
                }
            });
            *out = weights(a);
        }
        Planes {
            form: m.form,
            fma: m.fma,
            divide: m.divide,
            y_up: m.y_up,
            height,
            centre: c,
            x,
            y,
            w: perspective.then(|| weights(order.map(|i| R::of(t.inv_w[i])))),
            values,
            channels: channels.len(),
        }
    }

    /// Every channel at pixel `(px, py)`: the plane at the pixel (the origin plane at its
    /// integer coordinates, the vertex plane at its centre's offset from vertex 0), or the
    /// edge functions at its centre, then the smooth quotient.
    #[allow(clippy::cast_precision_loss)] // the model's own conversion of the pixel's coordinates
    #[inline]
    fn values(&self, (px, py): (u32, u32), out: &mut [f32]) {
        let row = if self.y_up { self.height - 1 - py } else { py };
        let pixel = (R::of(px as f32), R::of(row as f32));
        let at = (pixel.0 + self.centre, pixel.1 + self.centre);
        let (x, y) = (&self.x, &self.y);
        let (ex, ey) = if self.form == Form::OriginPlane {
            pixel
        } else {
            (at.0 - x[0], at.1 - y[0])
        };
        let edges = if self.form == Form::Barycentric {
            let e = |j: usize, k: usize| (x[j] - at.0) * (y[k] - at.1) - (x[k] - at.0) * (y[j] - at.1);
            [e(1, 2), e(2, 0), e(0, 1)]
        } else {
            [R::of(0.0); 3]
        };
        let eval = |g: &Weights<R>| -> R {
            match *g {
                Weights::Plane([base, dadx, dady]) => {
                    if self.fma {
                        dady.fused(ey, dadx.fused(ex, base))
                    } else {
                        base + dadx * ex + dady * ey
                    }
                }
                Weights::Vertices(g) => {
                    let [e0, e1, e2] = edges;
                    (e0 * g[0] + e1 * g[1] + e2 * g[2]) / (e0 + e1 + e2)
                }
            }
        };
        let w = self.w.as_ref().map(eval);
        let reciprocal = match (w, self.divide) {
            (Some(w), Divide::Reciprocal) => Some(R::of(1.0) / w),
            _ => None,
        };
        for (o, g) in out[..self.channels].iter_mut().zip(&self.values) {
            let value = eval(g);
            *o = match (w, reciprocal) {
                (_, Some(r)) => (value * r).out(),
                (Some(w), None) => (value / w).out(),
                (None, None) => value.out(),
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// euc's setup of (0, 0), (8, 0), (0, 8) with w = 1, 1, 2 on an 8-pixel target, by hand:
    /// scale 1/4, clip positions a = (-1, 1, 1), b = (1, 1, 1), c = (-2, -2, 2); the NDC
    /// cross product is -4, so the setup is reversed: a = (-2, -2, 2), c = (-1, 1, 1).
    /// `ca = (-1, -3, 1)`, `cb = (2, 0, 0)`, `n = (0, 2, 6)`, `n . c = 8`, `r = 1/8`; the
    /// rows `cb x c = (0, -2, 2)`, `c x ca = (4, 0, 4)`, `n` times `r`, times the NDC
    /// matrix, give F = [[0, 1/16, 0], [1/8, 0, 0], [0, -1/16, 1]] (every step exact), so at
    /// pixel (1, 3), centre (1.5, 3.5): h = (7/32, 3/16, 25/32), the perspective-correct
    /// weights 7/25, 6/25, 12/25 of the vertices (0, 8), (8, 0), (0, 0). The weights are
    /// the two f32 quotients and `(1 - w_a) - w_b`; the value is euc's fused lerp of the
    /// values 7, 5, 3 in that order.
    #[test]
    fn homogeneous_matches_the_hand_derived_setup() {
        let t = FloatTriangle {
            x: [0.0, 8.0, 0.0],
            y: [0.0, 0.0, 8.0],
            inv_w: [1.0, 1.0, 0.5],
            values: [vec![3.0], vec![5.0], vec![7.0]],
        };
        let (h0, h1, h2) = (7.0f32 / 32.0, 3.0f32 / 16.0, 25.0f32 / 32.0);
        let (wa, wb) = (h0 / h2, h1 / h2);
        let wc = 1.0 - wa - wb;
        let euc = FloatInterpolator {
            form: Form::Homogeneous(3),
            fma: true,
            order: VertexOrder::Reversed,
            divide: Divide::Quotient,
            f64: false,
            y_up: false,
        };
        assert_eq!(euc.name(), "homogeneous-8 fma rev div f32 y-down");
        let v = euc.value(&t, Interpolation::Smooth, ProvokingVertex::First, 0, (1, 3), 8, 0.5);
        assert_eq!(v.to_bits(), 7.0f32.mul_add(wa, 5.0f32.mul_add(wb, 3.0 * wc)).to_bits());
        // Unfused: the products rounded, then summed as euc's order would.
        let unfused = FloatInterpolator { fma: false, ..euc };
        let v = unfused.value(&t, Interpolation::Smooth, ProvokingVertex::First, 0, (1, 3), 8, 0.5);
        assert_eq!(v.to_bits(), (7.0 * wa + (5.0 * wb + 3.0 * wc)).to_bits());
        // The exact value is (7 * 7 + 5 * 6 + 3 * 12) / 25 = 4.6; euc is within a step.
        assert!((v - 4.6).abs() <= 2.0 * f32::EPSILON * 4.6, "{v}");
    }

    /// One setup of three channels gives, channel by channel, each one-channel value of
    /// every model (the `1 / w` plane and the edge functions computed once per pixel for
    /// all of them), bit for bit, for every interpolation and provoking vertex.
    #[test]
    fn a_setup_of_several_channels_gives_each_channels_value() {
        let t = FloatTriangle {
            x: [3.25, 97.5, 11.0],
            y: [5.5, 17.75, 80.125],
            inv_w: [1.0, 0.3, 0.7],
            values: [vec![0.1, 5.0, -2.0], vec![0.7, 1.0, 3.5], vec![0.3, 9.0, 0.25]],
        };
        for m in FloatInterpolator::all() {
            for interpolation in Interpolation::ALL {
                for provoking in [ProvokingVertex::First, ProvokingVertex::Last] {
                    let setup = m.setup(&t, interpolation, provoking, 0..3, 100, 0.5);
                    assert_eq!(setup.channels(), 3);
                    for pixel in [(10, 20), (40, 30), (0, 99)] {
                        let mut out = [0.0; 3];
                        setup.values(pixel, &mut out);
                        for (c, v) in out.iter().enumerate() {
                            let one = m.value(&t, interpolation, provoking, c, pixel, 100, 0.5);
                            assert_eq!(v.to_bits(), one.to_bits(), "{} {interpolation} {pixel:?} {c}", m.name());
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn every_model_has_its_own_name() {
        let all = FloatInterpolator::all();
        let names: std::collections::HashSet<String> = all.iter().map(FloatInterpolator::name).collect();
        assert_eq!(names.len(), all.len());
        assert_eq!(all.len(), 96 + 4 * (usize::from(HOMOGENEOUS_MAX_LOG2) + 1));
        assert_eq!(all.iter().filter(|m| m.enveloped()).count(), 96);
    }
}
