//! The trade's workloads, drawn from the crate's proptest strategies with a fixed seed
//! (each workload from its own stream, so that running fewer families changes none), and
//! their placement at a magnitude: every coordinate plus `(M, M)`, exactly.

use num_rational::BigRational;
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

use crate::clip::{Rect, Window};
use crate::geom::{Point, Polygon, Rgb, Triangle};
use crate::line::Line;
use crate::strategy::Mesh;

/// A runner seeded by the run's seed and the workload's name.
pub(crate) fn runner(seed: u64, workload: &str) -> TestRunner {
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&seed.to_le_bytes());
    // FNV-1a of the name: a stable stream per workload.
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in workload.bytes() {
        h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
    }
    bytes[8..16].copy_from_slice(&h.to_le_bytes());
    TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &bytes))
}

/// One value of `s`, not shrunk.
///
/// # Panics
/// When the strategy rejects every value it draws (the crate's strategies filter little).
pub(crate) fn draw<T: std::fmt::Debug>(runner: &mut TestRunner, s: &impl Strategy<Value = T>) -> T {
    s.new_tree(runner)
        .expect("the trade's strategies accept their draws")
        .current()
}

/// `n` values of `s`.
pub(crate) fn draw_n<T: std::fmt::Debug>(runner: &mut TestRunner, s: &impl Strategy<Value = T>, n: usize) -> Vec<T> {
    (0..n).map(|_| draw(runner, s)).collect()
}

/// Random vertex colours.
pub(crate) fn colours(runner: &mut TestRunner, n: usize) -> Vec<[Rgb; 3]> {
    let rgb = proptest::array::uniform3(proptest::array::uniform3(0u8..=255));
    draw_n(runner, &rgb, n)
}

/// `n` random points on the 2^-`bits` px grid in `[0, side)^2`, Delaunay-triangulated
/// (spade, exactly: [`crate::strategy::triangulate`]).
pub(crate) fn mesh(runner: &mut TestRunner, side: u32, bits: u32, n: usize) -> Mesh {
    let span = i64::from(side) << bits;
    let points = draw_n(runner, &(0..span, 0..span), n);
    let points: Vec<[i64; 2]> = points.into_iter().map(|(x, y)| [x, y]).collect();
    crate::strategy::triangulate(&points, bits).expect("random points span an area")
}

/// The exact offset `M` as a rational.
fn offset(m: i64) -> BigRational {
    BigRational::from_integer(m.into())
}

/// `p + (m, m)`.
pub(crate) fn place_point(p: &Point, m: i64) -> Point {
    let d = offset(m);
    Point::new(&p.x + &d, &p.y + &d)
}

/// Triangles placed at `m`.
pub(crate) fn place_triangles(ts: &[Triangle], m: i64) -> Vec<Triangle> {
    ts.iter().map(|t| t.translated(m, m)).collect()
}

/// Lines placed at `m`.
pub(crate) fn place_lines(ls: &[Line], m: i64) -> Vec<Line> {
    ls.iter()
        .map(|l| Line {
            from: place_point(&l.from, m),
            to: place_point(&l.to, m),
            rule: l.rule,
        })
        .collect()
}

/// Polygons placed at `m`.
pub(crate) fn place_polygons(ps: &[Polygon], m: i64) -> Vec<Polygon> {
    ps.iter().map(|p| p.translated(m, m)).collect()
}

/// A window placed at `m`.
pub(crate) fn place_window(w: &Window, m: i64) -> Window {
    match w {
        Window::Rect(r) => {
            let d = offset(m);
            Window::Rect(Box::new(Rect {
                xmin: &r.xmin + &d,
                ymin: &r.ymin + &d,
                xmax: &r.xmax + &d,
                ymax: &r.ymax + &d,
            }))
        }
        Window::Convex(points) => Window::Convex(points.iter().map(|p| place_point(p, m)).collect()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn streams_are_stable_and_separate() {
        let s = 0i64..1_000_000;
        let a = draw_n(&mut runner(1, "pixel triangles"), &s, 4);
        assert_eq!(a, draw_n(&mut runner(1, "pixel triangles"), &s, 4));
        assert_ne!(a, draw_n(&mut runner(1, "medium triangles"), &s, 4));
        assert_ne!(a, draw_n(&mut runner(2, "pixel triangles"), &s, 4));
    }

    #[test]
    fn placing_moves_every_coordinate_exactly() {
        let t = Triangle::new(
            Point::from_ints(0, 1),
            Point::from_fractions(1, 3, 2, 1),
            Point::from_ints(5, 5),
        );
        let placed = place_triangles(std::slice::from_ref(&t), 1 << 30);
        assert_eq!(placed[0].translated(-(1 << 30), -(1 << 30)), t);
        let w = Window::rect(offset(0), offset(0), offset(4), offset(4)).unwrap();
        let Window::Rect(r) = place_window(&w, 7) else {
            unreachable!()
        };
        assert_eq!((r.xmin.clone(), r.ymax.clone()), (offset(7), offset(11)));
    }
}
