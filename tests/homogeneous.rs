//! Homogeneous clipping (issue 4): clip-space Sutherland-Hodgman against the six planes,
//! divide and viewport, perspective-correct interpolation. Exact: hand goldens, outputs
//! inside the volume and on the triangle, before-the-divide == after-the-divide for
//! geometry in front of the eye, nothing behind the eye drawn, perspective-correct
//! interpolation exact. Float: departures counted by magnitude (`--nocapture`).

use crate::common;

use crate::mat4;
use crate::rng;

use common::{config, q};
use glam::{DMat4, DVec2, DVec4};
use mat4::{mat_exact_from_f64, mat_mul_exact, transform_exact};
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use proptest::prelude::*;
use rasterproof::clip::homogeneous::{
    clip_exact, clip_f32, clip_f64, clip_to_window_exact, divide_then_clip_exact, interpolate_exact, project_exact,
    project_f64, to_window_exact, transform_f64, ClipVertex, ClipVertexF32, ClipVertexF64, DepthRange, NdcY,
    ProjectError, Viewport, WindowVertex,
};
use rasterproof::convention::{Convention, Target};
use rasterproof::coverage::Coverage;
use rasterproof::fill::polygon::{area2_exact, rasterize_exact};
use rasterproof::geom::{FillRule, Point, Polygon, Triangle};
use rasterproof::interp::barycentric_exact;

fn int(n: i64) -> BigRational {
    q(n, 1)
}

fn viewport(size: i64, y_axis: NdcY, depth: DepthRange) -> Viewport {
    Viewport::new(int(0), int(0), int(size), int(size), y_axis, depth).unwrap()
}

fn vertex(pos: [BigRational; 4], attrs: Vec<BigRational>) -> ClipVertex {
    ClipVertex { pos, attrs }
}

fn points(poly: &[WindowVertex]) -> Vec<Point> {
    poly.iter().map(|v| v.point.clone()).collect()
}

/// The pixels the exact polygon oracle covers, on a `size` x `size` canvas.
fn raster(outline: Vec<Point>, size: u32) -> Coverage {
    let target = Target::new(size, size, Convention::default()).unwrap();
    let mut c = Coverage::new(size, size);
    rasterize_exact(&Polygon::new(outline, FillRule::NonZero), 0, &target, &mut c);
    c
}

/// The clip volume written out plane by plane (not through the crate's plane table).
fn in_volume(p: &[BigRational; 4], depth: DepthRange) -> bool {
    let [x, y, z, w] = p;
    let near = match depth {
        DepthRange::ZeroToOne => !z.is_negative(),
        DepthRange::MinusOneToOne => z >= &-w,
    };
    &-w <= x && x <= w && &-w <= y && y <= w && near && z <= w
}

/// One vertex beyond x = w. V0 = (0,0,1,2) a=0, V1 = (3,0,1,1) a=6, V2 = (0,1,1,2) a=2.
/// Only x <= w cuts (d = w - x: 2, -2, 2). Walking from V0 (previous V2, in): V0 kept;
/// V0 -> V1 in->out at t = 2/(2+2) = 1/2: P = (3/2, 0, 1, 3/2), a = 3; V1 -> V2 out->in at
/// t = -2/(-2-2) = 1/2 from V1: Q = (3/2, 1/2, 1, 3/2), a = 6 + (2-6)/2 = 4, then V2.
/// Window (8x8, NDC y = -1 at the top, x_win = 4 (x/w + 1)): V0 NDC (0,0,1/2) -> (4,4);
/// P NDC (1,0,2/3) -> (8,4); Q NDC (1,1/3,2/3) -> (8,16/3); V2 NDC (0,1/2,1/2) -> (4,6).
#[test]
fn golden_vertex_beyond_x_equals_w() {
    let v = |p: [i64; 4], a| ClipVertex::from_ints(p, &[a]);
    let tri = [v([0, 0, 1, 2], 0), v([3, 0, 1, 1], 6), v([0, 1, 1, 2], 2)];
    let p = vertex([q(3, 2), int(0), int(1), q(3, 2)], vec![int(3)]);
    let qv = vertex([q(3, 2), q(1, 2), int(1), q(3, 2)], vec![int(4)]);
    let out = clip_exact(&tri, DepthRange::ZeroToOne);
    assert_eq!(out, vec![tri[0].clone(), p, qv, tri[2].clone()]);

    let vp = viewport(8, NdcY::Down, DepthRange::ZeroToOne);
    let win = clip_to_window_exact(&tri, &vp);
    let expected = [(int(4), int(4)), (int(8), int(4)), (int(8), q(16, 3)), (int(4), int(6))];
    assert_eq!(points(&win), expected.map(|(x, y)| Point::new(x, y)).to_vec());
    assert_eq!(
        win.iter().map(|v| v.z.clone()).collect::<Vec<_>>(),
        vec![q(1, 2), q(2, 3), q(2, 3), q(1, 2)]
    );
    assert_eq!(win[1].inv_w, q(2, 3));
    assert_eq!(win[2].attrs, vec![int(4)]);
}

/// Crossing w = 0. A = (0,0,1,2) a=0, B = (2,0,1,2) a=6, C = (0,2,-1,-2) a=12 (behind the
/// eye); the plane of all three is z = w/2. Planes in order:
/// - x >= -w (d = x + w: 2, 4, -2): C -> A out->in at t = 1/2: D = (0,1,0,0) a=6 (w = 0!),
///   then A, B; B -> C in->out at t = 4/6: E = (2/3,4/3,-1/3,-2/3) a=10. [D, A, B, E]
/// - x <= w (d = w - x: 0, 2, 0, -4/3): E -> D cut at t = 1 (D), D, A, B, B -> E cut at
///   t = 0 (B); merged: [D, A, B]
/// - y >= -w: all in. y <= w (d = w - y: -1, 2, 2): B -> D in->out at t = 2/3:
///   F = (2/3,2/3,1/3,2/3) a=6; D -> A out->in at t = 1/3: G = (0,2/3,1/3,2/3) a=4; A; B.
/// - z >= 0 and z <= w (z = w/2 > 0 on F, G, A, B): all in. Result [F, G, A, B].
///
/// In NDC that is the square [0,1]^2 at depth 1/2: F (1,1), G (0,1), A (0,0), B (1,0).
/// Check by geometry: for w > 0 the edge A -> C is the ray x = 0 upwards from (0,0) in
/// NDC, B -> C the ray y = x - 1 from (1,0), A -> B is y = 0; inside the NDC square that
/// region is exactly [0,1]^2. Window (8x8, y = -1 at the top): [4,8] x [4,8], 16 pixels.
/// Naive dividing sends C to NDC (0,-1), window (4,0): the triangle (4,4) (8,4) (4,0)
/// lies in the other half of the screen.
#[test]
fn golden_crossing_w_zero() {
    let v = |p: [i64; 4], a| ClipVertex::from_ints(p, &[a]);
    let tri = [v([0, 0, 1, 2], 0), v([2, 0, 1, 2], 6), v([0, 2, -1, -2], 12)];
    let f = vertex([q(2, 3), q(2, 3), q(1, 3), q(2, 3)], vec![int(6)]);
    let g = vertex([int(0), q(2, 3), q(1, 3), q(2, 3)], vec![int(4)]);
    for depth in [DepthRange::ZeroToOne, DepthRange::MinusOneToOne] {
        assert_eq!(
            clip_exact(&tri, depth),
            vec![f.clone(), g.clone(), tri[0].clone(), tri[1].clone()]
        );
    }
    let vp = viewport(8, NdcY::Down, DepthRange::ZeroToOne);
    let win = clip_to_window_exact(&tri, &vp);
    let square = [(8, 8), (4, 8), (4, 4), (8, 4)].map(|(x, y)| Point::from_ints(x, y));
    assert_eq!(points(&win), square.to_vec());
    assert!(win.iter().all(|v| v.z == q(1, 2)));

    // Nothing behind the eye is drawn: the clipped polygon covers the 4x4 square, the
    // naively divided triangle covers pixels the clipped one does not, e.g. (4, 1).
    let clipped = raster(points(&win), 8);
    assert_eq!(clipped.covered_pixels(), 16);
    assert!(clipped.owners(4, 1).is_empty());
    let naive = raster(
        vec![Point::from_ints(4, 4), Point::from_ints(8, 4), Point::from_ints(4, 0)],
        8,
    );
    assert_eq!(naive.owners(4, 1), &[0]);
    // and the after-divide path refuses it
    assert_eq!(
        divide_then_clip_exact(&tri, &vp),
        Err(ProjectError::NotInFront {
            vertex: 2,
            w: "-2".into()
        })
    );
}

/// Entirely behind the eye (w = -2): NDC (-1/2,-1/2,1/2) (1/2,-1/2,1/2) (0,1/2,1/2), well
/// inside the NDC cube, so naive dividing draws the window triangle (2,2) (6,2) (4,6);
/// clip-space clipping draws nothing (x >= -w and x <= w cannot both hold when w < 0).
#[test]
fn entirely_behind_the_eye_draws_nothing() {
    let tri = [[1, 1, -1, -2], [-1, 1, -1, -2], [0, -1, -1, -2]].map(|p| ClipVertex::from_ints(p, &[]));
    let vp = viewport(8, NdcY::Down, DepthRange::ZeroToOne);
    assert!(clip_exact(&tri, DepthRange::ZeroToOne).is_empty());
    assert!(clip_exact(&tri, DepthRange::MinusOneToOne).is_empty());
    assert!(clip_to_window_exact(&tri, &vp).is_empty());
    assert!(matches!(
        divide_then_clip_exact(&tri, &vp),
        Err(ProjectError::NotInFront { vertex: 0, .. })
    ));
    let naive = raster(
        vec![Point::from_ints(2, 2), Point::from_ints(6, 2), Point::from_ints(4, 6)],
        8,
    );
    assert!(naive.covered_pixels() > 0);
    assert_eq!(naive.owners(4, 3), &[0]);
}

/// The viewport's y convention: NDC y = 1/2 is 3/4 of the way down with Vulkan's
/// (y = -1 at the top), 1/4 with GL's (y = +1 at the top); depth 0 is window depth 0 for
/// D3D, 1/2 for GL.
#[test]
fn viewport_conventions() {
    let v = ClipVertex::from_ints([0, 1, 0, 2], &[]);
    let down = to_window_exact(&v, 0, &viewport(8, NdcY::Down, DepthRange::ZeroToOne)).unwrap();
    let up = to_window_exact(&v, 0, &viewport(8, NdcY::Up, DepthRange::MinusOneToOne)).unwrap();
    assert_eq!(down.point, Point::from_ints(4, 6));
    assert_eq!(up.point, Point::from_ints(4, 2));
    assert_eq!((down.z, up.z), (int(0), q(1, 2)));
}

/// Bad input: w = 0 or w < 0 handed to the divide is an error naming the vertex, never a
/// panic; in f64 NaN too. An edge-on triangle cannot be clipped after the divide.
#[test]
fn bad_input_is_an_error() {
    let vp = viewport(8, NdcY::Down, DepthRange::ZeroToOne);
    let tri = [[0, 0, 0, 1], [1, 0, 0, 0], [0, 1, 0, 1]].map(|p| ClipVertex::from_ints(p, &[]));
    let err = divide_then_clip_exact(&tri, &vp).unwrap_err();
    assert_eq!(
        err,
        ProjectError::NotInFront {
            vertex: 1,
            w: "0".into()
        }
    );
    assert!(err.to_string().starts_with("vertex 1 has w = 0 <= 0"), "{err}");
    assert!(matches!(
        project_exact(&tri, &vp),
        Err(ProjectError::NotInFront { vertex: 1, .. })
    ));
    let vp64 = vp.to_f64().unwrap();
    for w in [0.0, -1.0, f64::NAN] {
        let poly = [DVec4::new(0.0, 0.0, 0.0, 1.0), DVec4::new(0.0, 0.0, 0.0, w)]
            .map(|pos| ClipVertexF64 { pos, attrs: vec![] });
        assert!(matches!(
            project_f64(&poly, &vp64),
            Err(ProjectError::NotInFront { vertex: 1, .. })
        ));
    }
    // edge-on: all three on the NDC line y = 0
    let flat = [[0, 0, 0, 1], [1, 0, 0, 2], [-1, 0, 0, 3]].map(|p| ClipVertex::from_ints(p, &[]));
    assert_eq!(divide_then_clip_exact(&flat, &vp), Err(ProjectError::EdgeOn));
}

/// Perspective-correct against affine by hand. V0 = (0,0,0,1) a=0, V1 = (3,0,0,3) a=1,
/// V2 = (0,1,0,1) a=0 on an 8x8 viewport (x_win = 4 (x/w + 1)). The clip-space midpoint of
/// V0 V1 is (3/2,0,0,2) with a = 1/2; it projects to x_win = 4 (3/4 + 1) = 7, while V0
/// and V1 project to x_win 4 and 8: screen barycentrics (1/4, 3/4, 0). Affine gives
/// 3/4; perspective (3/4 * 1/3) / (1/4 * 1 + 3/4 * 1/3) = (1/4) / (1/2) = 1/2.
#[test]
fn perspective_correct_differs_from_affine_by_hand() {
    let v = |p: [i64; 4], a| ClipVertex::from_ints(p, &[a]);
    let vp = viewport(8, NdcY::Down, DepthRange::ZeroToOne);
    let tri: [WindowVertex; 3] = project_exact(&[v([0, 0, 0, 1], 0), v([3, 0, 0, 3], 1), v([0, 1, 0, 1], 0)], &vp)
        .unwrap()
        .try_into()
        .unwrap();
    let p = Point::from_ints(7, 4);
    assert_eq!(interpolate_exact(&tri, &p).unwrap().attrs, vec![q(1, 2)]);
    let screen = Triangle::new(tri[0].point.clone(), tri[1].point.clone(), tri[2].point.clone());
    let b = barycentric_exact(&screen, &p).unwrap();
    let affine = &b[1] * &tri[1].attrs[0];
    assert_eq!(affine, q(3, 4));
}

/// The exact transform agrees with glam's where f64 is exact (small dyadic entries), and
/// the exact product applies its right factor first.
#[test]
fn exact_transform_matches_glam_on_dyadics() {
    let a = DMat4::from_cols_array(&[
        1.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.5, 0.25, -1.5, -1.0, 0.0, 0.0, -2.0, 0.0,
    ]);
    let b = DMat4::from_cols_array(&[
        0.5, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 3.0, -1.0, -4.0, 1.0,
    ]);
    let obj = glam::DVec3::new(1.5, -2.0, 0.75);
    let exact = |v: f64| BigRational::from_float(v).unwrap();
    let v = [exact(obj.x), exact(obj.y), exact(obj.z), int(1)];
    let (ea, eb) = (mat_exact_from_f64(&a).unwrap(), mat_exact_from_f64(&b).unwrap());
    let via_glam = transform_f64(&(a * b), obj).to_array().map(exact);
    assert_eq!(transform_exact(&mat_mul_exact(&ea, &eb), &v), via_glam);
    assert_eq!(transform_exact(&ea, &transform_exact(&eb, &v)), via_glam);
}

fn coordinate() -> impl Strategy<Value = BigRational> {
    (-12i64..=12, 1i64..=4).prop_map(|(n, d)| q(n, d))
}

fn positive_w() -> impl Strategy<Value = BigRational> {
    (1i64..=12, 1i64..=4).prop_map(|(n, d)| q(n, d))
}

fn position(w: impl Strategy<Value = BigRational>) -> impl Strategy<Value = [BigRational; 4]> {
    (coordinate(), coordinate(), coordinate(), w).prop_map(|(x, y, z, w)| [x, y, z, w])
}

fn depth_range() -> impl Strategy<Value = DepthRange> {
    prop_oneof![Just(DepthRange::ZeroToOne), Just(DepthRange::MinusOneToOne)]
}

fn y_axis() -> impl Strategy<Value = NdcY> {
    prop_oneof![Just(NdcY::Down), Just(NdcY::Up)]
}

fn one_hot(k: usize) -> Vec<BigRational> {
    (0..3).map(|i| int(i64::from(i == k))).collect()
}

proptest! {
    #![proptest_config(config("proptest-regressions/homogeneous.txt"))]

    /// Any triangle, w of either sign: every output vertex satisfies the six planes
    /// exactly, has w > 0 or is the eye, and lies on the triangle — with one-hot
    /// attributes the carried attributes are the vertex's weights μ, so μ_i >= 0,
    /// Σ μ_i = 1 and pos = Σ μ_i V_i exactly. A triangle inside the volume is unchanged;
    /// one entirely behind the eye (w < 0 everywhere) clips to nothing.
    #[test]
    fn clip_output_is_inside_and_on_the_triangle(
        pos in proptest::array::uniform3(position(coordinate())),
        depth in depth_range(),
    ) {
        let tri: Vec<ClipVertex> = pos.iter().enumerate().map(|(k, p)| vertex(p.clone(), one_hot(k))).collect();
        let out = clip_exact(&tri, depth);
        for v in &out {
            prop_assert!(in_volume(&v.pos, depth), "{v:?} outside");
            prop_assert!(v.pos[3].is_positive() || v.pos.iter().all(Zero::is_zero), "{v:?}");
            let mu = &v.attrs;
            prop_assert!(mu.iter().all(|m| !m.is_negative()));
            prop_assert_eq!(mu.iter().fold(int(0), |a, m| a + m), int(1));
            for (c, coordinate) in v.pos.iter().enumerate() {
                let sum = (0..3).fold(int(0), |a, k| a + &mu[k] * &pos[k][c]);
                prop_assert_eq!(&sum, coordinate);
            }
        }
        if tri.iter().all(|v| in_volume(&v.pos, depth)) && pos[0] != pos[1] && pos[1] != pos[2] && pos[2] != pos[0] {
            prop_assert_eq!(&out, &tri);
        }
        let behind: Vec<ClipVertex> = tri.iter().map(|v| {
            let mut v = v.clone();
            v.pos[3] = -v.pos[3].abs() - int(1);
            v
        }).collect();
        prop_assert!(clip_exact(&behind, depth).is_empty());
    }

    /// In front of the eye (w > 0 everywhere) clipping before the divide and after it give
    /// the same window polygon, exactly, vertex for vertex in the same order (positions,
    /// depth, 1/w, attributes). Same order, not just the same cyclic sequence: both apply
    /// the corresponding planes in the same order (x_win >= left is x >= -w, ... depth >= 0
    /// is the near plane), the in/out decisions agree (for w > 0, x + w >= 0 iff
    /// x/w >= -1), and the divide maps each edge onto its image segment keeping order, so
    /// every intersection is the same point emitted at the same step. An edge-on triangle
    /// is refused after the divide; before it, it projects to zero area.
    #[test]
    fn before_and_after_the_divide_agree(
        pos in proptest::array::uniform3(position(positive_w())),
        attrs in proptest::array::uniform3(proptest::collection::vec(-20i64..=20, 2)),
        (x0, y0, size) in (-4i64..=4, -4i64..=4, 1i64..=16),
        y_axis in y_axis(),
        depth in depth_range(),
    ) {
        let tri: [ClipVertex; 3] = std::array::from_fn(|k| {
            vertex(pos[k].clone(), attrs[k].iter().map(|&a| int(a)).collect())
        });
        let vp = Viewport::new(int(x0), int(y0), int(size), q(size, 2), y_axis, depth).unwrap();
        let before = clip_to_window_exact(&tri, &vp);
        match divide_then_clip_exact(&tri, &vp) {
            Ok(after) => prop_assert_eq!(before, after),
            Err(ProjectError::EdgeOn) => prop_assert!(area2_exact(&points(&before)).is_zero()),
            Err(e) => prop_assert!(false, "{e}"),
        }
    }

    /// Perspective-correct interpolation is exact: P = Σ λ_i V_i in clip space (λ_i > 0,
    /// Σ λ_i = 1) carries Σ λ_i a_i; projecting P and interpolating at its window point
    /// from the projected triangle gives exactly that, and P's depth and 1/w.
    #[test]
    fn perspective_correct_interpolation_is_exact(
        pos in proptest::array::uniform3(position(positive_w())),
        attrs in proptest::array::uniform3(-20i64..=20),
        lambda in proptest::array::uniform3(1i64..=9),
        y_axis in y_axis(),
        depth in depth_range(),
    ) {
        let total: i64 = lambda.iter().sum();
        let l = lambda.map(|n| q(n, total));
        let vp = Viewport::new(int(0), int(0), int(16), int(16), y_axis, depth).unwrap();
        let tri: [ClipVertex; 3] = std::array::from_fn(|k| vertex(pos[k].clone(), vec![int(attrs[k])]));
        let p_pos: [BigRational; 4] = std::array::from_fn(|c| (0..3).fold(int(0), |a, k| a + &l[k] * &pos[k][c]));
        let p_attr = (0..3).fold(int(0), |a, k| a + &l[k] * int(attrs[k]));
        let p = to_window_exact(&vertex(p_pos, vec![p_attr.clone()]), 0, &vp).unwrap();
        let projected: [WindowVertex; 3] = project_exact(&tri, &vp).unwrap().try_into().unwrap();
        let interpolated = interpolate_exact(&projected, &p.point);
        prop_assume!(interpolated.is_some()); // edge-on: no screen barycentrics
        let got = interpolated.unwrap();
        prop_assert_eq!(&got.attrs, &vec![p_attr]);
        prop_assert_eq!(&got.z, &p.z);
        prop_assert_eq!(&got.inv_w, &p.inv_w);
    }
}

/// Float clipping's departures by magnitude. Triangles near the corner x = y = w of the
/// volume at distance M: vertices (M, M, M/2, M) + offsets on the 1/8 grid in [-8, 8]
/// (at M = 0, w crosses 0). The exact model clips the f64 inputs read exactly; f32 also
/// rounds its inputs (at 2^24 its spacing is 2, the offsets collapse). Counted per
/// triangle: an output vertex outside the volume (read back exactly), a different vertex
/// count than exact, and the largest window-space distance (1024 px viewport, max norm)
/// from the exact vertices when the counts agree. Printed with `--nocapture`.
///
/// What it shows: the divide makes the window error scale-free — scaling a whole triangle
/// by a power of 2 changes no float rounding, and a triangle of fixed size at distance M
/// shrinks on screen like 1/M, so the pixel errors do not grow with M. What does grow is
/// input rounding: at 2^24 f32 cannot hold the 1/8 offsets (spacing 2), the triangle
/// collapses and the vertex count departs from the exact one. Outside-the-volume outputs
/// are common near w = 0 (M = 0), where every intersection is rounded onto a plane.
/// Asserted (robust facts): f64 stays within 1e-6 px at every magnitude and always keeps
/// the exact vertex count; f32 departs more than f64 at every magnitude; at 2^24 and
/// 2^32 f32 changes the vertex count of some triangles.
#[test]
fn float_clipping_departures_by_magnitude() {
    let mut rng = rng::Rng(41);
    let exact = |v: f64| BigRational::from_float(v).expect("finite");
    let vp = viewport(1024, NdcY::Down, DepthRange::ZeroToOne);
    let (vp64, vp32) = (vp.to_f64().unwrap(), vp.to_f32().unwrap());
    let depth = DepthRange::ZeroToOne;
    let distance = |a: DVec2, b: &Point| {
        (a.x - b.x.to_f64().unwrap())
            .abs()
            .max((a.y - b.y.to_f64().unwrap()).abs())
    };
    println!(
        "| M | outside f32 / f64 | count differs f32 / f64 | max error px f32 / f64 | > 1/256 px f32 / f64 | of |"
    );
    let n = 200;
    for shift in [None, Some(8u32), Some(16), Some(24), Some(32)] {
        let m = shift.map_or(0.0, |s| f64::from(2u32).powi(i32::try_from(s).unwrap()));
        let (mut outside, mut count, mut max_err, mut over) = ([0u32; 2], [0u32; 2], [0f64; 2], [0u32; 2]);
        for _ in 0..n {
            let mut off = || f64::from(i32::try_from(rng.range(-64, 64)).unwrap()) / 8.0;
            let tri: Vec<(DVec4, f64)> = (0..3)
                .map(|_| (DVec4::new(m + off(), m + off(), m / 2.0 + off(), m + off()), off()))
                .collect();
            let ex: Vec<ClipVertex> = tri
                .iter()
                .map(|(p, a)| vertex(p.to_array().map(exact), vec![exact(*a)]))
                .collect();
            let t64: Vec<ClipVertexF64> = tri
                .iter()
                .map(|&(pos, a)| ClipVertexF64 { pos, attrs: vec![a] })
                .collect();
            #[allow(clippy::cast_possible_truncation)] // rounding to f32 is the point
            let t32: Vec<ClipVertexF32> = tri
                .iter()
                .map(|&(pos, a)| ClipVertexF32 {
                    pos: pos.as_vec4(),
                    attrs: vec![a as f32],
                })
                .collect();
            let exact_out = clip_exact(&ex, depth);
            let exact_win: Vec<Option<Point>> = exact_out
                .iter()
                .map(|v| to_window_exact(v, 0, &vp).ok().map(|w| w.point))
                .collect();
            let outs: [Vec<DVec4>; 2] = [
                clip_f32(&t32, depth).iter().map(|v| v.pos.as_dvec4()).collect(),
                clip_f64(&t64, depth).iter().map(|v| v.pos).collect(),
            ];
            for (k, out) in outs.iter().enumerate() {
                outside[k] += u32::from(out.iter().any(|p| !in_volume(&p.to_array().map(exact), depth)));
                if out.len() != exact_out.len() {
                    count[k] += 1;
                    continue;
                }
                let float_win = if k == 0 {
                    let f32s: Vec<ClipVertexF32> = out
                        .iter()
                        .map(|p| ClipVertexF32 {
                            pos: p.as_vec4(),
                            attrs: vec![],
                        })
                        .collect();
                    rasterproof::clip::homogeneous::project_f32(&f32s, &vp32)
                        .map(|w| w.iter().map(|v| v.point.as_dvec2()).collect::<Vec<_>>())
                } else {
                    let f64s: Vec<ClipVertexF64> =
                        out.iter().map(|&pos| ClipVertexF64 { pos, attrs: vec![] }).collect();
                    project_f64(&f64s, &vp64).map(|w| w.iter().map(|v| v.point).collect())
                };
                let Ok(float_win) = float_win else {
                    count[k] += 1; // a float vertex at w <= 0 (the exact one is the eye)
                    continue;
                };
                let err = float_win
                    .iter()
                    .zip(&exact_win)
                    .filter_map(|(f, e)| e.as_ref().map(|e| distance(*f, e)))
                    .fold(0.0, f64::max);
                max_err[k] = max_err[k].max(err);
                over[k] += u32::from(err > 1.0 / 256.0);
            }
        }
        let label = shift.map_or_else(|| "0".to_string(), |s| format!("2^{s}"));
        println!(
            "| {label} | {} / {} | {} / {} | {:.2e} / {:.2e} | {} / {} | {n} |",
            outside[0], outside[1], count[0], count[1], max_err[0], max_err[1], over[0], over[1]
        );
        assert!(max_err[1] < 1e-6, "f64 off by {} px at {label}", max_err[1]);
        assert_eq!(count[1], 0, "f64 vertex count differs at {label}");
        assert!(max_err[0] > max_err[1], "at {label}: {max_err:?}");
        if shift >= Some(24) {
            assert!(count[0] > 0, "f32 kept every vertex count at {label}");
        }
    }
}
