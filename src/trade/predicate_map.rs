//! Picture (c): a predicate map in the manner of the robust crate's `predicate-map`
//! example. A long sliver edge far from the origin, through pixel centres every 3 px,
//! and a zoomed patch of the window around its middle: each pixel is the float models'
//! decision for that pixel's sample (inside the edge, or not) compared with the exact
//! one. The float decision is computed as the models compute it: the edge's exact
//! vertices and the sample rounded to the type, [`crate::edge::float`]'s edge function,
//! the tie rule on the float value (or the naive `E >= 0`).

use glam::DVec2;
use num_rational::BigRational;
use num_traits::Zero;
use serde_json::{json, Value};

use crate::convention::{Preset, TieRule};
use crate::edge::exact::ExactEdge;
use crate::edge::float::{edge_f32, edge_f64, is_inclusive};
use crate::geom::Point;
use crate::num::exact::exact_text;

use super::Magnitude;

/// The magnitude of the map: 2^24 px, where f32 can no longer hold a pixel centre.
pub(crate) const MAP_MAGNITUDE: Magnitude = Magnitude::DEFAULT[5];

/// The patch side, px.
const SIDE: u32 = 64;

/// The edge's length scale: it runs `(3K, -K)` px.
const K: i64 = 2048;

/// A pixel's float decision against the exact one.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Decision {
    /// Both inside.
    Inside,
    /// Both outside.
    Outside,
    /// The float model says inside; exactly, the sample is outside.
    WronglyInside,
    /// The float model says outside; exactly, the sample is inside.
    WronglyOutside,
}

impl Decision {
    fn of(float: bool, exact: bool) -> Decision {
        match (float, exact) {
            (true, true) => Decision::Inside,
            (false, false) => Decision::Outside,
            (true, false) => Decision::WronglyInside,
            (false, true) => Decision::WronglyOutside,
        }
    }

    /// Whether the float model got it wrong.
    pub fn is_wrong(self) -> bool {
        matches!(self, Decision::WronglyInside | Decision::WronglyOutside)
    }
}

/// One model's decisions over the patch.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MapPanel {
    /// The model (`float32`, `float32-naive`, `float64`, `float64-naive`).
    pub model: &'static str,
    /// Row-major, [`PredicateMap::side`] a row.
    pub decisions: Vec<Decision>,
}

impl MapPanel {
    /// How many pixels it decides wrongly.
    pub fn wrong(&self) -> usize {
        self.decisions.iter().filter(|d| d.is_wrong()).count()
    }
}

/// The map: the edge, the patch and each float model's decisions.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PredicateMap {
    /// The magnitude: the edge runs from `(M + 1/2, M + 1/2 + 2048)` to `(M + 1/2 + 6144,
    /// M + 1/2)`.
    pub magnitude: Magnitude,
    /// The edge's start.
    pub a: Point,
    /// The edge's end.
    pub b: Point,
    /// The patch's first pixel (both axes are offsets from it: pixel `(x0 + i, y0 + j)`).
    pub origin: [i64; 2],
    /// The patch side, px.
    pub side: u32,
    /// The decisions of float32, float32-naive, float64, float64-naive.
    pub panels: Vec<MapPanel>,
}

impl PredicateMap {
    /// The map at magnitude `m` (the trade draws it at 2^24 px).
    pub fn compute(m: Magnitude) -> PredicateMap {
        let m = m.px_i64();
        let half = BigRational::new(1.into(), 2.into());
        let at = |x: i64, y: i64| {
            let p = Point::from_ints(m + x, m + y);
            Point::new(&p.x + &half, &p.y + &half)
        };
        // dy < 0: under top-left the edge is not inclusive, so a sample exactly on it is
        // outside, which the naive `E >= 0` gets wrong.
        let (a, b) = (at(0, K), at(3 * K, 0));
        let rule = Preset::D3d11.convention().tie_rule;
        let edge = ExactEdge::new(&a, &b, rule);
        let origin = [m + 3 * K / 2 - i64::from(SIDE / 2), m + K / 2 - i64::from(SIDE / 2)];
        let samples: Vec<Point> = (0..SIDE)
            .flat_map(|j| (0..SIDE).map(move |i| (i, j)))
            .map(|(i, j)| {
                let p = Point::from_ints(origin[0] + i64::from(i), origin[1] + i64::from(j));
                Point::new(&p.x + &half, &p.y + &half)
            })
            .collect();
        let exact: Vec<bool> = samples.iter().map(|p| edge.contains(p)).collect();
        let a32 = a.to_f32().expect("2^40 fits f32");
        let b32 = b.to_f32().expect("2^40 fits f32");
        let a64 = a.to_f64().expect("fits f64");
        let b64 = b.to_f64().expect("fits f64");
        let incl32 = float_inclusive(a32.as_dvec2(), b32.as_dvec2(), rule);
        let incl64 = float_inclusive(a64, b64, rule);
        let panel = |model: &'static str, decide: &dyn Fn(&Point) -> bool| MapPanel {
            model,
            decisions: samples
                .iter()
                .zip(&exact)
                .map(|(p, &e)| Decision::of(decide(p), e))
                .collect(),
        };
        let e32 = |p: &Point| edge_f32(a32, b32, p.to_f32().expect("fits f32"));
        let e64 = |p: &Point| edge_f64(a64, b64, p.to_f64().expect("fits f64"));
        let panels = vec![
            panel("float32", &|p| passes(f64::from(e32(p)), incl32)),
            panel("float32-naive", &|p| e32(p) >= 0.0),
            panel("float64", &|p| passes(e64(p), incl64)),
            panel("float64-naive", &|p| e64(p) >= 0.0),
        ];
        PredicateMap {
            magnitude: Magnitude::new(u64::try_from(m).expect("non-negative")).expect("at most 2^40"),
            a,
            b,
            origin,
            side: SIDE,
            panels,
        }
    }

    /// The exact decisions' count of samples exactly on the edge (ties).
    pub fn ties(&self) -> usize {
        let edge = ExactEdge::new(&self.a, &self.b, TieRule::TopLeft);
        (0..self.side)
            .flat_map(|j| (0..self.side).map(move |i| (i, j)))
            .filter(|&(i, j)| {
                let half = BigRational::new(1.into(), 2.into());
                let p = Point::from_ints(self.origin[0] + i64::from(i), self.origin[1] + i64::from(j));
                edge.value(&Point::new(&p.x + &half, &p.y + &half)).is_zero()
            })
            .count()
    }

    /// The map's summary in the report's JSON.
    pub(crate) fn to_json(&self) -> Value {
        let point = |p: &Point| json!([exact_text(&p.x), exact_text(&p.y)]);
        json!({
            "magnitude": self.magnitude.label(),
            "edge": [point(&self.a), point(&self.b)],
            "origin": self.origin,
            "side": self.side,
            "panels": self.panels.iter().map(|p| json!({
                "model": p.model, "wrong": p.wrong(), "points": p.decisions.len(),
            })).collect::<Vec<_>>(),
        })
    }
}

/// The inclusive flag from the float edge vector, as the float models derive it.
fn float_inclusive(a: DVec2, b: DVec2, rule: TieRule) -> bool {
    is_inclusive([a.x, a.y], [b.x, b.y], rule)
}

/// The float models' test: `E > 0`, or `E == 0` on an inclusive edge.
fn passes(e: f64, inclusive: bool) -> bool {
    e > 0.0 || (e == 0.0 && inclusive)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::Signed;

    #[test]
    fn f32_fails_far_out_and_naive_fails_at_ties() {
        let map = PredicateMap::compute(MAP_MAGNITUDE);
        let wrong: Vec<usize> = map.panels.iter().map(MapPanel::wrong).collect();
        assert!(wrong[0] > 0, "f32 at 2^24 cannot hold the pixel centres");
        assert_eq!(wrong[2], 0, "every f64 value here is exact");
        assert_eq!(wrong[3], map.ties(), "naive f64 is wrong exactly at the ties");
        assert!(
            map.ties() >= 15,
            "the edge passes a pixel centre every 3 px: {}",
            map.ties()
        );
        // Near the origin f32 is exact too.
        let near = PredicateMap::compute(Magnitude::new(0).unwrap());
        assert_eq!(near.panels[0].wrong(), 0);
        // The sign test is the exact edge's.
        assert!(ExactEdge::new(&map.a, &map.b, TieRule::TopLeft).dy.is_negative());
    }
}
