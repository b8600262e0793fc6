//! The float triangle models over a canvas-sized window at magnitude `M`, which no
//! canvas reaches (a target ends at 16384 px): [`crate::tri::float`]'s own rasterizer
//! with its sample origin at `(M, M)`. As the model does on its canvas, the sample
//! `M + i + c` is computed exactly in f64 (exact for `M <= 2^40`) and rounded once to the
//! model's type; the vertices are the scene's exact coordinates rounded to the type; the
//! pixel range is the samples inside the float bounding box, read in f64. Window pixel `i`
//! is pixel `M + i` of the plane. Equal to the model's own output where a canvas reaches
//! (tested at `M = 0` and `M = 2^13`).

use crate::convention::Convention;
use crate::tri::float::{self, MAX_SAMPLE_ORIGIN};

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
    pub(crate) fn sample(&self, i: u32, conv: &Convention) -> f64 {
        float::sample_at(self.origin, i, conv)
    }

    /// The sample origin of [`float::rasterize_f32_at`] / [`float::rasterize_f64_at`] for
    /// this window (checked against their envelope in debug builds).
    pub(crate) fn origin(&self) -> [i64; 2] {
        debug_assert!(self.origin.abs() <= MAX_SAMPLE_ORIGIN, "{}", self.origin);
        [self.origin, self.origin]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::convention::{Preset, Target};
    use crate::coverage::Coverage;
    use crate::geom::{Point, Triangle};
    use crate::model::{render_triangles, Model};
    use crate::trade::workloads::{draw_n, place_triangles, runner};
    use crate::tri::float;

    /// The far rasterizer over the window at `m` equals the model on a canvas that reaches
    /// the window, restricted to it.
    fn agrees_at(m: i64, triangles: &[Triangle]) {
        let side = 48u32;
        let conv = Preset::D3d11.convention();
        let placed = place_triangles(triangles, m);
        let big = u32::try_from(m).unwrap() + side;
        let target = Target::new(big, big, conv).unwrap();
        let window = FarWindow { origin: m, side };
        let window_target = Target::new(side, side, conv).unwrap();
        for model in [Model::Float32, Model::Float64, Model::Float32Naive, Model::Float64Naive] {
            let theirs = render_triangles(&placed, &target, model).unwrap();
            let mu = u32::try_from(m).unwrap();
            let expected = theirs.restricted(mu, mu, big, big).translated(-m, -m);
            let mut ours = Coverage::new(big, big);
            let (f32, rule) = (model.is_f32(), model.float_rule().unwrap());
            for (k, t) in placed.iter().enumerate() {
                let id = u32::try_from(k).unwrap();
                let o = window.origin();
                if f32 {
                    float::rasterize_f32_at(&t.to_f32().unwrap(), id, o, &window_target, rule, &mut ours);
                } else {
                    float::rasterize_f64_at(&t.to_f64().unwrap(), id, o, &window_target, rule, &mut ours);
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
