//! Clipping (issue 4): half-planes, Cohen-Sutherland and Sutherland-Hodgman, exact and
//! float. Exact: outputs inside the window, the kept part of a segment is exactly the
//! part inside (an independent t-interval computation), and
//! raster(clip(P, W)) == raster(P) ∩ raster(W). Float: departures counted by magnitude.

use crate::common;

use crate::rng;

use common::config;
use glam::DVec2;
use num_rational::BigRational;
use proptest::prelude::*;
use rasterproof::check::{check_clip_raster, check_inside, check_segment_clip, inside_interval};
use rasterproof::clip::halfplane::HalfPlane;
use rasterproof::clip::sutherland_hodgman::{clip_exact, clip_polygon};
use rasterproof::clip::{cohen_sutherland, sutherland_hodgman, Window, WindowError};
use rasterproof::convention::{PixelCentre, Preset, Target};
use rasterproof::edge::exact::edge_function;
use rasterproof::geom::{FillRule, Point, Polygon};
use rasterproof::strategy::clip::{any_window, rect_window};
use rasterproof::strategy::polygon::any_polygon;
use rasterproof::strategy::tie_heavy_coordinate;

fn q(n: i64) -> BigRational {
    BigRational::from_integer(n.into())
}

fn rect(xmin: i64, ymin: i64, xmax: i64, ymax: i64) -> rasterproof::clip::Rect {
    match Window::rect(q(xmin), q(ymin), q(xmax), q(ymax)).unwrap() {
        Window::Rect(r) => *r,
        Window::Convex(_) => unreachable!(),
    }
}

#[test]
fn windows_are_validated() {
    assert_eq!(
        Window::rect(q(3), q(0), q(3), q(1)).unwrap_err().to_string(),
        "empty window: xmin 3 >= xmax 3"
    );
    assert!(matches!(
        Window::rect(q(0), q(2), q(1), q(1)),
        Err(WindowError::Empty { axis: 'y', .. })
    ));
    let p = |x, y| Point::from_ints(x, y);
    assert_eq!(
        Window::convex(vec![p(0, 0), p(1, 0)]),
        Err(WindowError::TooFewVertices(2))
    );
    // collinear vertex, a dent, a pentagram (every turn the same way, but it winds twice)
    assert!(Window::convex(vec![p(0, 0), p(2, 0), p(4, 0), p(2, 3)]).is_err());
    assert!(Window::convex(vec![p(0, 0), p(4, 0), p(2, 1), p(4, 4), p(0, 4)]).is_err());
    let star = vec![p(50, 0), p(79, 90), p(2, 35), p(98, 35), p(21, 90)];
    assert_eq!(Window::convex(star), Err(WindowError::WindsMoreThanOnce));
    // either orientation is a window
    assert!(Window::convex(vec![p(0, 0), p(4, 0), p(0, 4)]).is_ok());
    assert!(Window::convex(vec![p(0, 0), p(0, 4), p(4, 0)]).is_ok());
}

/// Seed 002's half-plane: kept when <p - p0, n> >= 0, the same as e . p >= 0 with
/// e = (n, -n . p0); the boundary is kept.
#[test]
fn half_plane_by_hand() {
    // Through (1, 2) with normal (1, 1): x + y >= 3.
    let h = HalfPlane::from_point_normal(&Point::from_ints(1, 2), [q(1), q(1)]).unwrap();
    assert_eq!(h, HalfPlane::from_line(q(1), q(1), q(-3)).unwrap());
    assert!(h.contains(&Point::from_ints(3, 0)));
    assert!(h.contains(&Point::from_fractions(3, 2, 3, 2)));
    assert!(!h.contains(&Point::from_fractions(3, 2, 1, 1)));
    // (0, 0) -> (4, 2) meets x + y = 3 at t = 1/2: (2, 1).
    assert_eq!(
        h.intersect(&Point::from_ints(0, 0), &Point::from_ints(4, 2)),
        Some(Point::from_ints(2, 1))
    );
    assert!(HalfPlane::from_line(q(0), q(0), q(1)).is_none());
}

/// Cohen-Sutherland by hand on [0, 4] x [0, 4]: through a corner, along a side, a point.
#[test]
fn cohen_sutherland_by_hand() {
    let r = rect(0, 0, 4, 4);
    let p = |x, y| Point::from_ints(x, y);
    let clip = |a: Point, b: Point| cohen_sutherland::clip_exact(&a, &b, &r);
    // (-1,-1) -> (1,1) enters at the corner (0,0).
    assert_eq!(clip(p(-1, -1), p(1, 1)), Some((p(0, 0), p(1, 1))));
    // Along the top side y = 0, from x = -2 to 6: the side itself is kept.
    assert_eq!(clip(p(-2, 0), p(6, 0)), Some((p(0, 0), p(4, 0))));
    // Touching the corner (4, 0) only: one point.
    assert_eq!(clip(p(3, -1), p(5, 1)), Some((p(4, 0), p(4, 0))));
    // Both ends left: rejected by the outcodes alone.
    assert_eq!(clip(p(-3, 1), p(-1, 3)), None);
    // Different outcodes, yet outside: (-1, 3) -> (1, 6) passes left of (0, 4.5).
    assert_eq!(clip(p(-1, 3), p(1, 6)), None);
}

/// The seed's pseudo-code forgets the intersection in the out -> in case.
fn forgetful(subject: &[Point], planes: &[HalfPlane]) -> Vec<Point> {
    let mut poly = subject.to_vec();
    for h in planes {
        let mut out = Vec::new();
        for (k, e) in poly.iter().enumerate() {
            let s = &poly[(k + poly.len() - 1) % poly.len()];
            match (h.contains(s), h.contains(e)) {
                (true, true) | (false, true) => out.push(e.clone()),
                (true, false) => out.push(h.intersect(s, e).unwrap()),
                (false, false) => {}
            }
        }
        poly = out;
    }
    poly
}

/// The triangle (2,1) (6,1) (2,3) against [0,4] x [0,8]: its hypotenuse x + 2y = 8 leaves
/// through x = 4 at (4, 2). Right: (2,1) (4,1) (4,2) (2,3). The forgetful version drops
/// (4, 2), cutting off the triangle (4,1) (4,2) (2,3); its first sample is (3.5, 1.5)
/// (3.5 + 2 * 1.5 = 6.5 < 8, inside the true polygon; on the forgetful polygon's edge
/// x + y = 5, a right edge, so outside). The checker must say so.
#[test]
fn the_seeds_forgotten_intersection_is_caught() {
    let p = |x, y| Point::from_ints(x, y);
    let tri = vec![p(2, 1), p(6, 1), p(2, 3)];
    let w = Window::rect(q(0), q(0), q(4), q(8)).unwrap();
    let right = clip_exact(&tri, &w.half_planes());
    assert_eq!(right, vec![p(2, 1), p(4, 1), p(4, 2), p(2, 3)]);
    let target = Target::new(8, 8, Preset::D3d11.convention()).unwrap();
    let poly = Polygon::new(tri.clone(), FillRule::NonZero);
    let good = Polygon::new(right, FillRule::NonZero);
    assert!(check_clip_raster(&poly, &good, &w, &target).is_ok());
    let bad = Polygon::new(forgetful(&tri, &w.half_planes()), FillRule::NonZero);
    let err = check_clip_raster(&poly, &bad, &w, &target).unwrap_err();
    assert!(err.message.contains("first (3, 1)"), "{err}");
}

/// Samples on the window's boundary follow the tie rule: [1, 3] x [1, 3] with corner
/// samples (i, j) has samples on all four sides; top-left keeps its left and top sides:
/// x, y in {1, 2}. A polygon covering everything, clipped, covers exactly those 4.
#[test]
fn window_boundary_samples_follow_the_tie_rule() {
    let mut conv = Preset::D3d11.convention();
    conv.pixel_centre = PixelCentre::Corner;
    let target = Target::new(6, 6, conv).unwrap();
    let p = |x, y| Point::from_ints(x, y);
    let big = Polygon::new(vec![p(-1, -1), p(7, -1), p(7, 7), p(-1, 7)], FillRule::NonZero);
    let w = Window::rect(q(1), q(1), q(3), q(3)).unwrap();
    let cut = clip_polygon(&big, &w);
    let mut c = rasterproof::coverage::Coverage::new(6, 6);
    rasterproof::fill::polygon::rasterize_exact(&cut, 0, &target, &mut c);
    let got: Vec<(u32, u32)> = c.iter().map(|(x, y, _)| (x, y)).collect();
    assert_eq!(got, [(1, 1), (2, 1), (1, 2), (2, 2)]);
    assert!(check_clip_raster(&big, &cut, &w, &target).is_ok());
}

fn tie_point() -> impl Strategy<Value = Point> {
    (tie_heavy_coordinate(16), tie_heavy_coordinate(16)).prop_map(|(x, y)| Point::new(x, y))
}

/// Strict convexity by its definition: for every edge, every other vertex strictly on
/// one side of its line, the same side for all edges. Quadratic; the crate's check is
/// linear.
fn strictly_convex_by_definition(points: &[Point]) -> bool {
    let n = points.len();
    let mut side = None;
    for i in 0..n {
        for (k, p) in points.iter().enumerate() {
            if k == i || k == (i + 1) % n {
                continue;
            }
            let e = edge_function(&points[i], &points[(i + 1) % n], p);
            let positive = e > BigRational::from_integer(0.into());
            if e == BigRational::from_integer(0.into()) || side.is_some_and(|s| s != positive) {
                return false;
            }
            side = Some(positive);
        }
    }
    n >= 3
}

proptest! {
    #![proptest_config(config("proptest-regressions/clip.txt"))]

    /// The linear convexity check agrees with the definition on small-grid point lists
    /// (many collinear, repeated, reflex and twice-winding cases).
    #[test]
    fn convexity_check_matches_the_definition(raw in prop::collection::vec((0i64..5, 0i64..5), 0..8)) {
        let points: Vec<Point> = raw.iter().map(|&(x, y)| Point::from_ints(x, y)).collect();
        prop_assert_eq!(Window::convex(points.clone()).is_ok(), strictly_convex_by_definition(&points));
    }

    /// Cohen-Sutherland keeps exactly the part inside: the same endpoints as the
    /// independent t-interval, on tie-heavy segments and windows (through corners, along
    /// sides, touching).
    #[test]
    fn cohen_sutherland_keeps_exactly_the_inside(a in tie_point(), b in tie_point(), w in rect_window(16)) {
        let Window::Rect(r) = &w else { unreachable!() };
        let kept = cohen_sutherland::clip_exact(&a, &b, r);
        check_segment_clip(&a, &b, r, kept.as_ref()).map_err(|v| TestCaseError::fail(v.to_string()))?;
        if let Some((p, e)) = &kept {
            check_inside(&[p.clone(), e.clone()], &w).map_err(|v| TestCaseError::fail(v.to_string()))?;
            prop_assert!(edge_function(&a, &b, p) == BigRational::from_integer(0.into()));
        }
    }

    /// Sutherland-Hodgman's output stays inside the window, every contour of every
    /// polygon family, rectangles and convex windows of either orientation.
    #[test]
    fn sutherland_hodgman_output_is_inside(poly in any_polygon(16, 10), w in any_window(16)) {
        let cut = clip_polygon(&poly, &w);
        for c in std::iter::once(&cut.outline).chain(&cut.holes) {
            check_inside(c, &w).map_err(|v| TestCaseError::fail(v.to_string()))?;
        }
    }

    /// raster(clip(P, W)) == raster(P) ∩ raster(W), pixel for pixel, for concave,
    /// holed and self-intersecting subjects, both fill rules, every preset, centre and
    /// corner samples.
    #[test]
    fn clipped_raster_is_the_restricted_raster(
        poly in any_polygon(16, 10),
        w in any_window(16),
        preset in prop::sample::select(Preset::ALL.to_vec()),
        corner in any::<bool>(),
    ) {
        let mut conv = preset.convention();
        if corner {
            conv.pixel_centre = PixelCentre::Corner;
        }
        let target = Target::new(16, 16, conv).unwrap();
        let cut = clip_polygon(&poly, &w);
        check_clip_raster(&poly, &cut, &w, &target).map_err(|v| TestCaseError::fail(format!("{v}\n{poly:?}\n{w:?}")))?;
    }
}

/// Float clipping's departures by coordinate magnitude: segments and triangles around
/// (m, m), a 64 px window there. Counted: outputs with a point outside the window
/// (exactly: the float value read back as a rational), and the largest distance of a
/// Cohen-Sutherland endpoint from the original segment's line, in pixels (a rounded
/// intersection is almost never exactly on it). Printed with `--nocapture`; asserted:
/// at 2^24 f32 lands more than half a pixel off the line (its spacing there is 2 px)
/// while f64 stays within 1e-6 px, and near 0 f64 stays within 1e-9 px.
#[test]
fn float_clipping_departures_by_magnitude() {
    use num_traits::ToPrimitive;
    let mut rng = rng::Rng(17);
    let exact = |v: f64| BigRational::from_float(v).expect("finite");
    let ep = |p: DVec2| Point::new(exact(p.x), exact(p.y));
    println!("| magnitude | CS outside f32 / f64 | CS max off-line px f32 / f64 | SH outside f32 / f64 | of |");
    for shift in [0u32, 10, 16, 20, 24] {
        let m = if shift == 0 { 0.0 } else { f64::from(1u32 << shift) };
        let w = Window::rect(exact(m), exact(m), exact(m + 64.0), exact(m + 64.0)).unwrap();
        let Window::Rect(r) = &w else { unreachable!() };
        let planes = w.half_planes();
        let (r64, r32) = (r.to_f64().unwrap(), r.to_f32().unwrap());
        let (p64, p32): (Vec<_>, Vec<_>) = planes
            .iter()
            .map(|h| (h.to_f64().unwrap(), h.to_f32().unwrap()))
            .unzip();
        let (mut outside, mut off_line, mut sh_outside) = ([0u32; 2], [0f64; 2], [0u32; 2]);
        let n = 500;
        for _ in 0..n {
            // endpoints on the 1/8 grid from 16 px before the window to 16 px after it
            let mut coord = || m - 16.0 + f64::from(u32::try_from(rng.below(96 * 8)).unwrap()) / 8.0;
            let (a, b, c) = (
                DVec2::new(coord(), coord()),
                DVec2::new(coord(), coord()),
                DVec2::new(coord(), coord()),
            );
            let (ea, eb) = (ep(a), ep(b));
            let length = (b - a).length();
            let distance = |p: &Point| (edge_function(&ea, &eb, p).to_f64().unwrap() / length).abs();
            let kept = [
                cohen_sutherland::clip_f32(a.as_vec2(), b.as_vec2(), &r32).map(|(s, e)| (s.as_dvec2(), e.as_dvec2())),
                cohen_sutherland::clip_f64(a, b, &r64),
            ];
            for (k, seg) in kept.iter().enumerate() {
                if let Some((s, e)) = seg {
                    let (s, e) = (ep(*s), ep(*e));
                    outside[k] += u32::from(!w.contains(&s) || !w.contains(&e));
                    if length > 0.0 {
                        off_line[k] = off_line[k].max(distance(&s)).max(distance(&e));
                    }
                }
            }
            let any_outside = |pts: Vec<DVec2>| u32::from(pts.into_iter().any(|p| !w.contains(&ep(p))));
            sh_outside[0] += any_outside(
                sutherland_hodgman::clip_f32(&[a.as_vec2(), b.as_vec2(), c.as_vec2()], &p32)
                    .into_iter()
                    .map(|p| p.as_dvec2())
                    .collect(),
            );
            sh_outside[1] += any_outside(sutherland_hodgman::clip_f64(&[a, b, c], &p64));
        }
        println!(
            "| 2^{shift} | {} / {} | {:.2e} / {:.2e} | {} / {} | {n} |",
            outside[0], outside[1], off_line[0], off_line[1], sh_outside[0], sh_outside[1]
        );
        if shift == 24 {
            assert!(off_line[0] > 0.5 && off_line[1] < 1e-6, "at 2^24: {off_line:?}");
        }
        if shift == 0 {
            assert!(
                off_line[1] < 1e-9,
                "f64 endpoints {} px off the line near 0",
                off_line[1]
            );
        }
    }
    // The exact interval for reference: a sanity check of the independent computation.
    let r = rect(0, 0, 4, 4);
    assert_eq!(
        inside_interval(&Point::from_ints(-4, 2), &Point::from_ints(4, 2), &r),
        Some((
            BigRational::new(1.into(), 2.into()),
            BigRational::from_integer(1.into())
        ))
    );
}
