//! The float triangle models over a canvas-sized window at magnitude `M`, which no
//! canvas reaches (a target ends at 16384 px): [`crate::tri::float`]'s loop, line for
//! line, with the window's origin added to each sample. As the model does on its canvas,
//! the sample `M + i + c` is computed exactly in f64 (exact for `M <= 2^40`) and rounded
//! once to the model's type; the vertices are the scene's exact coordinates rounded to
//! the type; the pixel range is the samples inside the float bounding box, read in f64.
//! Window pixel `i` is pixel `M + i` of the plane. Equal to the model's own output where a
//! canvas reaches (tested at `M = 0` and `M = 2^13`).

use glam::{DVec2, Vec2};

use crate::convention::Convention;
use crate::coverage::CoverageSink;
use crate::edge::float::{edge_f32, edge_f64, is_inclusive};
use crate::tri::float::FloatRule;

/// A canvas-sized window at `origin` px on both axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct FarWindow {
    /// Its first pixel's index on each axis, at most 2^40.
    pub(crate) origin: i64,
    /// Its side, px.
    pub(crate) side: u32,
}

impl FarWindow {
    /// The f64 sample of window pixel `i` on one axis: `origin + i + c`, exact.
    #[allow(clippy::cast_precision_loss)] // origin + i < 2^41: exact in f64
    pub(crate) fn sample(&self, i: u32, conv: &Convention) -> f64 {
        (self.origin + i64::from(i)) as f64 + conv.pixel_centre.offset_f64()
    }

    /// The window pixels whose sample lies in `[lo, hi]` on one axis (read in f64, as
    /// [`crate::raster::float_sample_range`] does), or `None`.
    fn range(&self, lo: f64, hi: f64, conv: &Convention) -> Option<(u32, u32)> {
        if lo.is_nan() || hi.is_nan() {
            return None;
        }
        let c = conv.pixel_centre.offset_f64();
        let first = index(((lo - c).ceil()).clamp(-1e18, 1e18)).saturating_sub(self.origin);
        let last = index(((hi - c).floor()).clamp(-1e18, 1e18)).saturating_sub(self.origin);
        let first = first.max(0);
        let last = last.min(i64::from(self.side) - 1);
        (first <= last).then(|| {
            let f = u32::try_from(first).expect("within the window");
            let l = u32::try_from(last).expect("within the window");
            (f, l)
        })
    }
}

/// A float already clamped to ±1e18 as an integer.
#[allow(clippy::cast_possible_truncation)] // clamped to ±1e18 and integral
fn index(v: f64) -> i64 {
    v as i64
}

macro_rules! far_rasterizer {
    ($name:ident, $vec:ty, $float:ty, $edge:ident) => {
        /// [`crate::tri::float`]'s rasterizer over the window `w`.
        pub(crate) fn $name<S: CoverageSink + ?Sized>(
            tri: &[$vec; 3],
            id: u32,
            w: &FarWindow,
            conv: &Convention,
            rule: FloatRule,
            sink: &mut S,
        ) {
            let [v0, mut v1, mut v2] = *tri;
            let area = $edge(v0, v1, v2);
            if area == 0.0 || !area.is_finite() {
                return;
            }
            if area < 0.0 {
                std::mem::swap(&mut v1, &mut v2);
            }
            let inclusive = |a: $vec, b: $vec| match rule {
                FloatRule::Naive => true,
                FloatRule::WithTieRule => is_inclusive(
                    [f64::from(a.x), f64::from(a.y)],
                    [f64::from(b.x), f64::from(b.y)],
                    conv.tie_rule,
                ),
            };
            let incl = [inclusive(v1, v2), inclusive(v2, v0), inclusive(v0, v1)];
            let min = v0.min(v1).min(v2);
            let max = v0.max(v1).max(v2);
            let Some((x0, x1)) = w.range(f64::from(min.x), f64::from(max.x), conv) else {
                return;
            };
            let Some((y0, y1)) = w.range(f64::from(min.y), f64::from(max.y), conv) else {
                return;
            };
            let passes = |e: $float, inclusive: bool| e > 0.0 || (e == 0.0 && inclusive);
            #[allow(clippy::cast_possible_truncation)] // rounding the sample to the type is the model's
            for j in y0..=y1 {
                let sy = w.sample(j, conv) as $float;
                for i in x0..=x1 {
                    let p = <$vec>::new(w.sample(i, conv) as $float, sy);
                    let e0 = $edge(v1, v2, p);
                    let e1 = $edge(v2, v0, p);
                    let e2 = $edge(v0, v1, p);
                    if passes(e0, incl[0]) && passes(e1, incl[1]) && passes(e2, incl[2]) {
                        sink.cover(i, j, id);
                    }
                }
            }
        }
    };
}

far_rasterizer!(rasterize_f32, Vec2, f32, edge_f32);
far_rasterizer!(rasterize_f64, DVec2, f64, edge_f64);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::{Preset, Target};
    use crate::coverage::Coverage;
    use crate::geom::{Point, Triangle};
    use crate::model::{render_triangles, Model};
    use crate::trade::workloads::{draw_n, place_triangles, runner};

    /// The far rasterizer over the window at `m` equals the model on a canvas that reaches
    /// the window, restricted to it.
    fn agrees_at(m: i64, triangles: &[Triangle]) {
        let side = 48u32;
        let conv = Preset::D3d11.convention();
        let placed = place_triangles(triangles, m);
        let big = u32::try_from(m).unwrap() + side;
        let target = Target::new(big, big, conv).unwrap();
        let window = FarWindow { origin: m, side };
        for model in [Model::Float32, Model::Float64, Model::Float32Naive, Model::Float64Naive] {
            let theirs = render_triangles(model, &placed, &target).unwrap();
            let mu = u32::try_from(m).unwrap();
            let expected = theirs.restricted(mu, mu, big, big).translated(-m, -m);
            let mut ours = Coverage::new(big, big);
            let (f32, rule) = crate::trade::arith::float_of(model).unwrap();
            for (k, t) in placed.iter().enumerate() {
                let id = u32::try_from(k).unwrap();
                if f32 {
                    rasterize_f32(&t.to_f32().unwrap(), id, &window, &conv, rule, &mut ours);
                } else {
                    rasterize_f64(&t.to_f64().unwrap(), id, &window, &conv, rule, &mut ours);
                }
            }
            assert_eq!(ours, expected, "{model} at {m}");
        }
    }

    #[test]
    fn equals_the_float_models_where_a_canvas_reaches() {
        let mut r = runner(3, "far test");
        // Triangles on a 2^-16 grid (so that f32 rounds them at 2^13) around the window.
        let c = -(8i64 << 16)..(56i64 << 16);
        let pts = draw_n(&mut r, &proptest::array::uniform6(c), 40);
        let q = |v: i64| num_rational::BigRational::new(v.into(), (1i64 << 16).into());
        let tris: Vec<Triangle> = pts
            .iter()
            .map(|v| {
                Triangle::new(
                    Point::new(q(v[0]), q(v[1])),
                    Point::new(q(v[2]), q(v[3])),
                    Point::new(q(v[4]), q(v[5])),
                )
            })
            .collect();
        agrees_at(0, &tris);
        agrees_at(1 << 13, &tris);
    }
}
