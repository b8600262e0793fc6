//! A fixed-point Gouraud DDA: a varying set up once per triangle as a plane in Q32.32 fixed
//! point and stepped from pixel to pixel by integer additions ([`GouraudDda`]). It is the
//! incremental form of the seed notes: an attribute is a plane `A x + B y + C` over the
//! triangle, "one more incrementally tracked value" (Luebke, "Drawing triangles"), walked
//! as `f(x + 1, y) = f + A`, `f(x, y + 1) = f + B` (the ELTE notes' incremental
//! Gouraud), a span's first pixel reached from the row's start in one step of `L` pixels,
//! `f(x + L, y) = f + L A` (Pineda 1988's incremental edge function, read for an
//! attribute).
//!
//! - **Format**: a value is an i64 `n` meaning `n / 2^32` (Q32.32: 32 integer bits with
//!   the sign, 32 fractional bits; [`FRACTION_BITS`]).
//! - **Inputs**, from the exact scene: each vertex position snapped to 1/256 px (8 subpixel
//!   bits, nearest-even, as `num::fixed::snap`), each vertex's value rounded to the nearest
//!   Q32.32 (ties to even). A `smooth` value walks two planes, the value over `w` and `1 / w`
//!   (each vertex's exact quotient rounded once), a `noperspective` one the value itself, a
//!   `flat` one the provoking vertex's value (a plane without slope).
//! - **Setup**, exactly in i128 from those integers: the gradients per pixel `A = df/dx`
//!   and `B = df/dy` (Cramer's rule over the snapped vertices, `A = 256 (df_1 dy_2 - df_2
//!   dy_1) / (dx_1 dy_2 - dx_2 dy_1)` in subpixel units relative to vertex 0), each rounded
//!   to Q32.32; then the value at the sample of the walk's first pixel (the top-left pixel
//!   of the snapped vertices' bounding box), reached from vertex 0 by the rounded
//!   gradients, rounded to Q32.32.
//! - **Walk**: exact i64 additions ([`Span::step`]); the value at pixel `(x, y)` is
//!   `start + (x - left) A + (y - top) B` exactly, however the walk reaches it, so the
//!   DDA's error is the rounding of its inputs, of `A`, `B` and the start, times the
//!   distance walked: it does not grow with the triangle's distance from the origin.
//! - **Output**: `noperspective` and `flat`: the Q32.32 value rounded once to f32. `smooth`:
//!   perspective through the `1 / w` DDA, then the divide: the quotient of the two walked
//!   planes taken in f64 (`N as f64 / D as f64`, three roundings), then rounded to f32, as
//!   a fixed-point walker beside a floating-point divider computes it.
//!
//! **The range envelope** ([`DdaError`], checked at setup: outside it the DDA refuses,
//! never answers wrongly): a triangle (not a segment) with every `w` positive and at most
//! 2^14 (so that `1 / w >= 2^-14`, far above the walk's rounding: the walked `1 / w` stays
//! positive at every pixel whose sample lies inside the triangle); positions within 2^44 px
//! of the origin and a bounding box at most 2^16 px a side (every subpixel difference below
//! 2^25, every setup product below 2^97); every vertex input below 2^30 in magnitude (its
//! Q32.32 integer below 2^62); a snapped area that is not zero; and every value the walk
//! reaches in the bounding box below 2^62 in Q32.32 (`|start| + |A| W + |B| H`, which also
//! bounds the gradients), so that each step, one past the box included, is an exact i64
//! addition.

use std::fmt;
use std::ops::Range;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::interp::values::{Interpolation, ProvokingVertex, ValueSetup};
use crate::num::exact::exact_text_short;
use crate::num::fixed::{round_quotient, snap};
use crate::num::lane::Lane;
use crate::num::Rounding;

/// The fractional bits of a value: Q32.32.
pub const FRACTION_BITS: u32 = 32;

/// The subpixel bits positions are snapped to.
pub const SUBPIXEL_BITS: u32 = 8;

/// The channels a DDA walks at most (a vec4's).
pub const DDA_CHANNELS: usize = 4;

/// Every vertex input is below this in magnitude (2^30).
const MAX_INPUT_BITS: u32 = 30;
/// Every walked Q32.32 integer is below 2^62.
const MAX_WALK_BITS: u32 = 62;
/// The largest bounding box side, px (2^16).
const MAX_BOX_BITS: u32 = 16;
/// Positions within 2^44 px of the origin.
const MAX_POSITION_BITS: u32 = 44;
/// The largest `w` of a smooth value (2^14).
const MAX_W_BITS: u32 = 14;

/// Why the DDA refuses a triangle (module docs: the range envelope).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum DdaError {
    /// A line segment: the DDA walks triangles.
    NotATriangle,
    /// A smooth value with a vertex at `w <= 0` or above 2^14.
    W {
        /// The vertex.
        vertex: usize,
        /// Its `w`, exactly.
        w: String,
    },
    /// A vertex position beyond 2^44 px, or a bounding box wider or taller than 2^16 px.
    Position {
        /// What is too large.
        what: String,
    },
    /// A vertex input (a value, or for `smooth` the value over `w` or `1 / w`) of 2^30 or
    /// more in magnitude.
    Input {
        /// The vertex.
        vertex: usize,
        /// The channel (`None`: `1 / w`).
        channel: Option<usize>,
        /// The input, exactly.
        value: String,
    },
    /// The snapped vertices are collinear: no plane.
    Degenerate,
    /// A value the walk reaches in the bounding box is 2^62 or more in Q32.32.
    Walk {
        /// The channel (`None`: `1 / w`).
        channel: Option<usize>,
    },
}

impl fmt::Display for DdaError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let channel = |c: &Option<usize>| c.map_or_else(|| "1/w".to_string(), |c| format!("channel {c}"));
        match self {
            DdaError::NotATriangle => f.write_str("the fixed-point DDA walks triangles, not line segments"),
            DdaError::W { vertex, w } => write!(
                f,
                "vertex {vertex}: w = {w} is outside the DDA's envelope (0 < w <= 2^{MAX_W_BITS})"
            ),
            DdaError::Position { what } => write!(f, "{what}: outside the DDA's envelope"),
            DdaError::Input {
                vertex,
                channel: c,
                value,
            } => write!(
                f,
                "vertex {vertex}, {}: {value} is outside the DDA's Q32.32 envelope (|v| < 2^{MAX_INPUT_BITS})",
                channel(c)
            ),
            DdaError::Degenerate => f.write_str("the snapped triangle has no area"),
            DdaError::Walk { channel: c } => write!(
                f,
                "{}: the walk over the bounding box reaches 2^{MAX_WALK_BITS} in Q32.32, outside the DDA's envelope",
                channel(c)
            ),
        }
    }
}

impl std::error::Error for DdaError {}

/// One walked plane, in Q32.32: its value at the sample of the walk's first pixel and its
/// steps per pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FixedPlane {
    /// The value at the first pixel's sample.
    pub start: i64,
    /// The step to the next pixel right, `A`.
    pub dx: i64,
    /// The step to the next row down, `B`.
    pub dy: i64,
}

/// The snapped vertices' bounding box in pixels: the walk's first pixel (`left`, `top`)
/// and its last column and row.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct PixelBox {
    left: i64,
    top: i64,
    right: i64,
    bottom: i64,
}

/// A triangle's varying set up for the walk (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct GouraudDda {
    /// The walk's box.
    pixels: PixelBox,
    /// Per channel, the plane walked: the value (`noperspective`, `flat`) or the value over
    /// `w` (`smooth`).
    planes: [FixedPlane; DDA_CHANNELS],
    channels: usize,
    /// `smooth`: the plane of `1 / w`.
    w: Option<FixedPlane>,
}

/// A value rounded to Q32.32, or its refusal.
fn q32(v: &BigRational, vertex: usize, channel: Option<usize>) -> Result<i64, DdaError> {
    let n = snap(v, FRACTION_BITS, Rounding::NearestEven);
    n.to_i64()
        .filter(|n| n.unsigned_abs() < 1 << (MAX_INPUT_BITS + FRACTION_BITS))
        .ok_or_else(|| DdaError::Input {
            vertex,
            channel,
            value: exact_text_short(v),
        })
}

/// A triangle's inputs as the DDA holds them: positions in subpixels, each vertex's
/// inputs in Q32.32 ([`DdaTriangle::of`] rounds the exact scene's).
///
/// # Guarantees
/// Every position below 2^52 subpixels (2^44 px) in magnitude, every input below 2^62
/// (2^30 in Q32.32), the sample offset in `0..256` subpixels: what [`GouraudDda::new`]'s
/// products are bounded by.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DdaTriangle {
    /// Each vertex's x and y, subpixels.
    x: [i64; 3],
    y: [i64; 3],
    /// Per channel, each vertex's input: its value, or for `smooth` its value over `w`.
    inputs: [[i64; 3]; DDA_CHANNELS],
    channels: usize,
    /// `smooth`: each vertex's `1 / w`.
    inverse_w: Option<[i64; 3]>,
    /// The sample's offset in its pixel, subpixels.
    sample: i64,
}

impl DdaTriangle {
    /// The channels `channels` (at most [`DDA_CHANNELS`]) of `setup` under
    /// `interpolation` (`provoking` for `flat`), for samples at `(x + centre, y +
    /// centre)` of pixel `(x, y)` (`0 <= centre < 1`), each input rounded (module docs).
    ///
    /// # Errors
    /// A segment, a `w` or an input outside the range envelope (module docs), the reason.
    ///
    /// # Panics
    /// When `channels` holds more than [`DDA_CHANNELS`] channels or channels a vertex does
    /// not have.
    pub fn of(
        setup: &ValueSetup,
        interpolation: Interpolation,
        provoking: ProvokingVertex,
        channels: Range<usize>,
        centre: &BigRational,
    ) -> Result<DdaTriangle, DdaError> {
        assert!(
            channels.len() <= DDA_CHANNELS,
            "a DDA walks at most {DDA_CHANNELS} channels"
        );
        let ValueSetup::Triangle(t) = setup else {
            return Err(DdaError::NotATriangle);
        };
        let smooth = interpolation == Interpolation::Smooth;
        let max_w = BigRational::from_integer(BigInt::one() << MAX_W_BITS);
        for (vertex, h) in t.h.iter().enumerate() {
            let w = &h[2];
            if w.is_zero() || (smooth && (w.is_negative() || *w > max_w)) {
                return Err(DdaError::W {
                    vertex,
                    w: exact_text_short(w),
                });
            }
        }
        let limit = BigInt::one() << (MAX_POSITION_BITS + SUBPIXEL_BITS);
        let subpixels = |v: &BigRational, what: String| -> Result<i64, DdaError> {
            let s = snap(v, SUBPIXEL_BITS, Rounding::NearestEven);
            if s.abs() >= limit {
                return Err(DdaError::Position {
                    what: format!("{what} = {}", exact_text_short(v)),
                });
            }
            Ok(s.to_i64().expect("below 2^52"))
        };
        let (mut x, mut y) = ([0; 3], [0; 3]);
        for i in 0..3 {
            x[i] = subpixels(&(&t.h[i][0] / &t.h[i][2]), format!("vertex {i}'s x"))?;
            y[i] = subpixels(&(&t.h[i][1] / &t.h[i][2]), format!("vertex {i}'s y"))?;
        }
        let sample = snap(centre, SUBPIXEL_BITS, Rounding::NearestEven)
            .to_i64()
            .filter(|c| (0..1 << SUBPIXEL_BITS).contains(c))
            .ok_or_else(|| DdaError::Position {
                what: format!("a sample {} px into its pixel", exact_text_short(centre)),
            })?;
        let vertex_inputs = |channel: Option<usize>| -> Result<[i64; 3], DdaError> {
            let mut out = [0; 3];
            for (vertex, o) in out.iter_mut().enumerate() {
                let w = &t.h[vertex][2];
                let v = match (channel, interpolation) {
                    (None, _) => w.recip(),
                    (Some(c), Interpolation::Smooth) => &t.values[vertex][c] / w,
                    (Some(c), Interpolation::NoPerspective) => t.values[vertex][c].clone(),
                    (Some(c), Interpolation::Flat) => t.values[provoking.vertex(3)][c].clone(),
                };
                *o = q32(&v, vertex, channel)?;
            }
            Ok(out)
        };
        let mut inputs = [[0; 3]; DDA_CHANNELS];
        for (input, c) in inputs.iter_mut().zip(channels.clone()) {
            *input = vertex_inputs(Some(c))?;
        }
        Ok(DdaTriangle {
            x,
            y,
            inputs,
            channels: channels.len(),
            inverse_w: if smooth { Some(vertex_inputs(None)?) } else { None },
            sample,
        })
    }
}

/// The snapped vertices relative to vertex 0, and the walk's box.
struct Frame {
    /// Vertices 1 and 2 relative to vertex 0, subpixels.
    d: [(i128, i128); 2],
    /// Twice the signed area, subpixels squared, made positive (`sign` kept for the
    /// gradients).
    area2: i128,
    sign: i128,
    /// The first pixel's sample relative to vertex 0, subpixels.
    sample: (i128, i128),
    /// The bounding box in pixels.
    pixels: PixelBox,
}

impl Frame {
    fn new(t: &DdaTriangle) -> Result<Frame, DdaError> {
        let (xs, ys) = (t.x.map(i128::from), t.y.map(i128::from));
        let one = 1i128 << SUBPIXEL_BITS;
        let pixel = |v: i128| i64::try_from(v.div_euclid(one)).expect("below 2^44");
        let (left, right) = (pixel(xs[0].min(xs[1]).min(xs[2])), pixel(xs[0].max(xs[1]).max(xs[2])));
        let (top, bottom) = (pixel(ys[0].min(ys[1]).min(ys[2])), pixel(ys[0].max(ys[1]).max(ys[2])));
        if right - left > 1 << MAX_BOX_BITS || bottom - top > 1 << MAX_BOX_BITS {
            return Err(DdaError::Position {
                what: format!("a bounding box of {} x {} px", right - left + 1, bottom - top + 1),
            });
        }
        let d = [(xs[1] - xs[0], ys[1] - ys[0]), (xs[2] - xs[0], ys[2] - ys[0])];
        let area2 = d[0].0 * d[1].1 - d[1].0 * d[0].1;
        if area2 == 0 {
            return Err(DdaError::Degenerate);
        }
        let c = i128::from(t.sample);
        Ok(Frame {
            d,
            area2: area2.abs(),
            sign: area2.signum(),
            sample: (i128::from(left) * one + c - xs[0], i128::from(top) * one + c - ys[0]),
            pixels: PixelBox {
                left,
                top,
                right,
                bottom,
            },
        })
    }

    /// The plane through the vertex inputs `v` (Q32.32), walked from the first pixel.
    fn plane(&self, v: [i64; 3], channel: Option<usize>) -> Result<FixedPlane, DdaError> {
        let [v0, v1, v2] = v.map(i128::from);
        let (df1, df2) = (v1 - v0, v2 - v0);
        let [(dx1, dy1), (dx2, dy2)] = self.d;
        let per_pixel = 1i128 << SUBPIXEL_BITS;
        // Every product below 2^63 * 2^25 * 2 * 2^8 = 2^97.
        let a = round_quotient(
            self.sign * (df1 * dy2 - df2 * dy1) * per_pixel,
            self.area2,
            Rounding::NearestEven,
        );
        let b = round_quotient(
            self.sign * (dx1 * df2 - dx2 * df1) * per_pixel,
            self.area2,
            Rounding::NearestEven,
        );
        let walk = Err(DdaError::Walk { channel });
        let bound = 1i128 << MAX_WALK_BITS;
        if a.abs() >= bound || b.abs() >= bound {
            return walk;
        }
        let (sx, sy) = self.sample;
        let start = v0 + round_quotient(a * sx + b * sy, per_pixel, Rounding::NearestEven);
        let p = &self.pixels;
        let (w, h) = (i128::from(p.right - p.left), i128::from(p.bottom - p.top));
        if start.abs() + a.abs() * w + b.abs() * h >= bound {
            return walk;
        }
        let narrow = |v: i128| i64::try_from(v).expect("below 2^62");
        Ok(FixedPlane {
            start: narrow(start),
            dx: narrow(a),
            dy: narrow(b),
        })
    }
}

impl GouraudDda {
    /// The walk of `t`: its planes set up in integers (module docs).
    ///
    /// ```
    /// use num_rational::BigRational;
    /// use rasterproof::geom::Point;
    /// use rasterproof::interp::dda::{DdaTriangle, GouraudDda};
    /// use rasterproof::interp::values::{Interpolation, ProvokingVertex, ValueSetup, ValueTriangle};
    /// let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
    /// // The value x / 4 over (0, 0), (4, 0), (0, 4): A = 1/4, B = 0, exact in Q32.32.
    /// let (a, b, c) = (Point::from_ints(0, 0), Point::from_ints(4, 0), Point::from_ints(0, 4));
    /// let one = q(1, 1);
    /// let t = ValueSetup::Triangle(Box::new(ValueTriangle::window(
    ///     [&a, &b, &c],
    ///     [&one, &one, &one],
    ///     [vec![q(0, 1)], vec![q(1, 1)], vec![q(0, 1)]],
    /// )));
    /// let inputs = DdaTriangle::of(&t, Interpolation::NoPerspective, ProvokingVertex::First, 0..1, &q(1, 2)).unwrap();
    /// let dda = GouraudDda::new(&inputs).unwrap();
    /// let mut span = dda.span(0, 1).unwrap();
    /// let mut out = [0.0];
    /// span.step();
    /// span.step();
    /// span.values(&mut out);
    /// assert_eq!(out[0], 0.625); // pixel (2, 1), sample (2.5, 1.5): 2.5 / 4
    /// ```
    ///
    /// # Errors
    /// Outside the range envelope (module docs: a bounding box above 2^16 px, no area, a
    /// walk reaching 2^62), the reason.
    pub fn new(t: &DdaTriangle) -> Result<GouraudDda, DdaError> {
        let frame = Frame::new(t)?;
        let mut planes = [FixedPlane::default(); DDA_CHANNELS];
        for (c, (plane, v)) in planes.iter_mut().zip(&t.inputs[..t.channels]).enumerate() {
            *plane = frame.plane(*v, Some(c))?;
        }
        let w = match t.inverse_w {
            Some(v) => Some(frame.plane(v, None)?),
            None => None,
        };
        Ok(GouraudDda {
            pixels: frame.pixels,
            planes,
            channels: t.channels,
            w,
        })
    }

    /// The walked planes, one per channel (the value over `w` for `smooth`).
    pub fn planes(&self) -> &[FixedPlane] {
        &self.planes[..self.channels]
    }

    /// `smooth`'s plane of `1 / w`.
    pub fn inverse_w(&self) -> Option<&FixedPlane> {
        self.w.as_ref()
    }

    /// The walk's first pixel (the snapped bounding box's top-left).
    pub fn first_pixel(&self) -> (i64, i64) {
        (self.pixels.left, self.pixels.top)
    }

    /// The walk at pixel `(x, y)`: the first pixel's values stepped down `y - top` rows and
    /// right `x - left` pixels, each by one exact multiple of its step (module docs);
    /// `None` outside the bounding box.
    pub fn span(&self, x: u32, y: u32) -> Option<Span<'_>> {
        let (x, y) = (i64::from(x), i64::from(y));
        let b = &self.pixels;
        if !(b.left..=b.right).contains(&x) || !(b.top..=b.bottom).contains(&y) {
            return None;
        }
        // Inside the envelope: every value the walk reaches in the box is below 2^62.
        let at = |p: &FixedPlane| p.start + (x - b.left) * p.dx + (y - b.top) * p.dy;
        let mut n = [0; DDA_CHANNELS];
        for (n, p) in n.iter_mut().zip(self.planes()) {
            *n = at(p);
        }
        Some(Span {
            dda: self,
            n,
            d: self.w.as_ref().map(at),
        })
    }
}

/// The walk at one pixel of a row: the walked values there, stepped to the right.
#[derive(Debug, Clone)]
pub struct Span<'a> {
    dda: &'a GouraudDda,
    /// Per channel, the walked value (Q32.32).
    n: [i64; DDA_CHANNELS],
    /// `smooth`: the walked `1 / w`.
    d: Option<i64>,
}

impl Span<'_> {
    /// The walked Q32.32 integers here: per channel, and `1 / w` for `smooth`.
    pub fn fixed(&self) -> (&[i64], Option<i64>) {
        (&self.n[..self.dda.channels], self.d)
    }

    /// To the next pixel right: one addition per plane (exact: module docs, the walk stays
    /// below 2^62 within the bounding box, one step past it below 2^63).
    #[inline]
    pub fn step(&mut self) {
        for (n, p) in self.n.iter_mut().zip(self.dda.planes()) {
            n.add_to(&p.dx);
        }
        if let (Some(d), Some(p)) = (&mut self.d, &self.dda.w) {
            d.add_to(&p.dx);
        }
    }

    /// Every channel's value here as f32, into `out` (module docs: the output).
    ///
    /// # Panics
    /// When `out` is shorter than the DDA's channels.
    #[inline]
    pub fn values(&self, out: &mut [f32]) {
        let n = &self.n[..self.dda.channels];
        // Rounding to f32 (or the quotient's operands to f64) is the model's own last step.
        #[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation)]
        match self.d {
            None => {
                let scale = 1.0 / (1u64 << FRACTION_BITS) as f32;
                for (o, &n) in out.iter_mut().zip(n) {
                    *o = n as f32 * scale;
                }
            }
            Some(d) => {
                let d = d as f64;
                for (o, &n) in out.iter_mut().zip(n) {
                    *o = (n as f64 / d) as f32;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Point;
    use crate::interp::values::ValueTriangle;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    fn triangle(points: [(i64, i64); 3], w: [BigRational; 3], values: [i64; 3], den: i64) -> ValueSetup {
        let p = points.map(|(x, y)| Point::from_ints(x, y));
        ValueSetup::Triangle(Box::new(ValueTriangle::window(
            [&p[0], &p[1], &p[2]],
            [&w[0], &w[1], &w[2]],
            values.map(|v| vec![q(v, den)]),
        )))
    }

    fn dda(t: &ValueSetup, interpolation: Interpolation) -> Result<GouraudDda, DdaError> {
        GouraudDda::new(&DdaTriangle::of(
            t,
            interpolation,
            ProvokingVertex::First,
            0..1,
            &q(1, 2),
        )?)
    }

    fn ones() -> [BigRational; 3] {
        [q(1, 1), q(1, 1), q(1, 1)]
    }

    /// By hand: the value x / 3 over (0, 0), (3, 0), (0, 3) (values 0, 1, 0), samples at
    /// pixel centres. In subpixels vertex 1 is (768, 0) and vertex 2 (0, 768), twice the
    /// area 768^2; `A = 256 (2^32 * 768) / 768^2 = 2^32 / 3 = 1431655765.33...`, rounded
    /// to 1431655765, `B = 0`. The first pixel is (0, 0), its sample (128, 128)
    /// subpixels from vertex 0: `start = round(1431655765 * 128 / 256) = round(715827882.5)`,
    /// a tie, to the even 715827882. At pixel (2, 2): `715827882 + 2 * 1431655765 =
    /// 3579139412`, which is 0.833333333022892475 (the exact value 5/6 less 3.1e-10); as f32
    /// (24 bits: multiples of 256 at this size) 3579139328 / 2^32 = 0.833333313465118408,
    /// which is also 5/6's nearest f32.
    #[test]
    fn noperspective_by_hand() {
        let t = triangle([(0, 0), (3, 0), (0, 3)], ones(), [0, 1, 0], 1);
        let dda = dda(&t, Interpolation::NoPerspective).unwrap();
        assert_eq!(dda.first_pixel(), (0, 0));
        assert_eq!(
            dda.planes(),
            [FixedPlane {
                start: 715_827_882,
                dx: 1_431_655_765,
                dy: 0
            }]
        );
        assert_eq!(dda.inverse_w(), None);
        // Down two rows and right two pixels, by steps and by the L-step alike.
        let mut walked = dda.span(0, 2).unwrap();
        walked.step();
        walked.step();
        let direct = dda.span(2, 2).unwrap();
        assert_eq!(walked.fixed(), (&[3_579_139_412i64][..], None));
        assert_eq!(direct.fixed(), walked.fixed());
        let mut out = [0.0];
        direct.values(&mut out);
        assert_eq!(out[0].to_bits(), 0.833_333_3_f32.to_bits());
        assert_eq!(f64::from(out[0]), 3_579_139_328.0 / 4_294_967_296.0);
        assert!(dda.span(3, 0).is_some() && dda.span(4, 0).is_none());
    }

    /// By hand, smooth: (0, 0), (4, 0), (0, 4) with w = 1, 2, 1 and values 0, 1, 0. The
    /// value over w is 0, 1/2, 0 (the plane x / 8: `A = 2^29`), 1 / w is 1, 1/2, 1 (the
    /// plane 1 - x / 8: `A = -2^29`); at the first sample (1/2, 1/2) they are 1/16 = 2^28
    /// and 15/16 = 15 * 2^28. At pixel (1, 0), sample (3/2, 1/2): N = 3 * 2^28, D = 13 * 2^28,
    /// the value 3/13, here the f64 quotient 3/13 rounded to f32.
    #[test]
    fn smooth_by_hand() {
        let t = triangle([(0, 0), (4, 0), (0, 4)], [q(1, 1), q(2, 1), q(1, 1)], [0, 1, 0], 1);
        let dda = dda(&t, Interpolation::Smooth).unwrap();
        let p = 1i64 << 28;
        assert_eq!(
            dda.planes(),
            [FixedPlane {
                start: p,
                dx: 2 * p,
                dy: 0
            }]
        );
        assert_eq!(
            dda.inverse_w(),
            Some(&FixedPlane {
                start: 15 * p,
                dx: -2 * p,
                dy: 0
            })
        );
        let mut span = dda.span(0, 0).unwrap();
        span.step();
        assert_eq!(span.fixed(), (&[3 * p][..], Some(13 * p)));
        let mut out = [0.0];
        span.values(&mut out);
        #[allow(clippy::cast_possible_truncation)]
        let expected = (3.0f64 / 13.0) as f32;
        assert_eq!(out[0].to_bits(), expected.to_bits());
    }

    /// The envelope one unit either side: a constant value just below 2^30 is walked, 2^30 is
    /// refused with its value; w = 2^14 is taken, 2^14 + 1 refused; a segment and a
    /// collinear triangle are refused.
    #[test]
    fn the_envelope_is_refused_with_its_reason() {
        let limit = 1i64 << 30;
        // A constant value, so that the walk reaches nothing beyond the inputs.
        let at = |v: i64, den: i64| {
            let t = triangle([(0, 0), (4, 0), (0, 4)], ones(), [v, v, v], den);
            dda(&t, Interpolation::NoPerspective)
        };
        // 2^30 - 2^-32 rounds to 2^62 - 1 in Q32.32.
        assert!(at((limit << 32) - 1, 1 << 32).is_ok());
        let err = at(limit, 1).unwrap_err();
        assert_eq!(
            err,
            DdaError::Input {
                vertex: 0,
                channel: Some(0),
                value: "1073741824".into()
            }
        );
        assert!(err.to_string().contains("2^30"), "{err}");
        let with_w = |w: i64| {
            let t = triangle([(0, 0), (4, 0), (0, 4)], [q(1, 1), q(w, 1), q(1, 1)], [0, 1, 0], 1);
            dda(&t, Interpolation::Smooth)
        };
        assert!(with_w(1 << 14).is_ok());
        assert!(matches!(with_w((1 << 14) + 1), Err(DdaError::W { vertex: 1, .. })));
        assert!(matches!(with_w(-1), Err(DdaError::W { vertex: 1, .. })));
        let flat = triangle([(0, 0), (2, 2), (4, 4)], ones(), [0, 1, 0], 1);
        assert_eq!(dda(&flat, Interpolation::NoPerspective), Err(DdaError::Degenerate));
    }

    /// The walk does not move with the triangle: the same triangle 2^24 px from the origin
    /// walks the same integers (its inputs and differences are the same).
    #[test]
    fn the_walk_is_translation_invariant() {
        let near = triangle([(1, 2), (40, 7), (9, 30)], ones(), [1, 2, 7], 10);
        let m = 1i64 << 24;
        let far = triangle(
            [(1 + m, 2 + m), (40 + m, 7 + m), (9 + m, 30 + m)],
            ones(),
            [1, 2, 7],
            10,
        );
        let (a, b) = (
            dda(&near, Interpolation::NoPerspective).unwrap(),
            dda(&far, Interpolation::NoPerspective).unwrap(),
        );
        assert_eq!(a.planes(), b.planes());
        let mu = u32::try_from(m).unwrap();
        assert_eq!(
            a.span(10, 10).unwrap().fixed(),
            b.span(10 + mu, 10 + mu).unwrap().fixed()
        );
    }
}
