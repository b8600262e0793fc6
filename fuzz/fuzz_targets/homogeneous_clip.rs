//! Homogeneous clipping (`clip::homogeneous`) with w of either sign, crossing 0, and
//! vertices on the planes (coordinates `n / (1 + d % 8)`, |n| <= 16):
//!
//! 1. `clip_exact` of any polygon (3 to 6 vertices) with one-hot attributes: every output
//!    vertex satisfies the six planes (written out here, not through the crate's table),
//!    has w > 0 or is the eye, and lies on the input: its attributes are weights
//!    μ >= 0 with Σ μ = 1 and pos = Σ μ_i V_i exactly. A triangle inside the volume comes
//!    back unchanged; a polygon with w < 0 everywhere clips to nothing.
//! 2. `clip_to_window_exact` of a triangle: every vertex inside the closed viewport, depth
//!    in [0, 1], 1/w > 0. With w > 0 everywhere, `divide_then_clip_exact` gives the same
//!    vertices (or `EdgeOn` for a zero-area image); otherwise it refuses the first vertex
//!    with w <= 0, naming its w.
//! 3. Perspective-correct interpolation across the clipped triangle: a point
//!    P = Σ λ_i O_i of three clipped vertices, projected, interpolated from their
//!    projections, carries exactly P's attribute, depth and 1/w.
//! 4. The models: a clip-space triangle renders the same under `exact` and `exact-plain`,
//!    `exact-snapped` and `exact-snapped-plain`; `fixed` and `float32` never panic on it.
//! 5. The f32 / f64 forms on the same vertices and on arbitrary bit patterns (NaN and
//!    infinities included) never panic.
//!
//! `Debug` is the input struct (Rust).

#![no_main]

use arbitrary::Arbitrary;
use glam::{DVec4, Vec4};
use libfuzzer_sys::fuzz_target;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use rasterproof::clip::homogeneous::{
    clip_exact, clip_f32, clip_f64, clip_to_window_exact, clip_to_window_f32, clip_to_window_f64,
    divide_then_clip_exact, interpolate_exact, project_exact, to_window_exact, ClipVertex, ClipVertexF32,
    ClipVertexF64, DepthRange, NdcY, ProjectError, Viewport, WindowVertex,
};
use rasterproof::convention::{Convention, Target};
use rasterproof::fill::polygon::area2_exact;
use rasterproof::geom::Point;
use rasterproof::model::{render, Model, Primitives};
use rasterproof::num::exact::exact_text;

#[derive(Debug, Clone, Copy, Arbitrary)]
struct C(i8, u8);

impl C {
    fn value(self) -> BigRational {
        let n = i64::from(self.0) % 17;
        BigRational::new(BigInt::from(n), BigInt::from(1 + i64::from(self.1 % 8)))
    }
}

#[derive(Debug, Clone, Arbitrary)]
struct Input {
    /// The first 3 to 6 are the polygon; the first 3 the triangle.
    vertices: [[C; 4]; 6],
    count: u8,
    attrs: [i8; 3],
    gl_depth: bool,
    ndc_down: bool,
    /// Viewport x, y (halves) and width, height (`1 + n % 16`, halves).
    viewport: [i8; 4],
    /// Weights of the interpolated point, `1 + l % 9`, and which clipped vertices.
    lambda: [u8; 3],
    fan: u8,
    /// Arbitrary f32 bit patterns for the float forms.
    raw: [[u32; 4]; 3],
}

fn q(n: i64) -> BigRational {
    BigRational::from_integer(BigInt::from(n))
}

/// The clip volume written out plane by plane.
fn in_volume(p: &[BigRational; 4], depth: DepthRange) -> bool {
    let [x, y, z, w] = p;
    let near = match depth {
        DepthRange::ZeroToOne => !z.is_negative(),
        DepthRange::MinusOneToOne => z >= &-w,
    };
    &-w <= x && x <= w && &-w <= y && y <= w && near && z <= w
}

fn one_hot(k: usize, n: usize) -> Vec<BigRational> {
    (0..n).map(|i| q(i64::from(i == k))).collect()
}

fn polygon_identities(pos: &[[BigRational; 4]], depth: DepthRange) {
    let n = pos.len();
    let poly: Vec<ClipVertex> = pos
        .iter()
        .enumerate()
        .map(|(k, p)| ClipVertex {
            pos: p.clone(),
            attrs: one_hot(k, n),
        })
        .collect();
    let out = clip_exact(&poly, depth);
    for v in &out {
        assert!(in_volume(&v.pos, depth), "{v:?} outside the volume");
        assert!(
            v.pos[3].is_positive() || v.pos.iter().all(Zero::is_zero),
            "{v:?}: w <= 0 and not the eye"
        );
        let mu = &v.attrs;
        assert!(mu.iter().all(|m| !m.is_negative()), "{v:?}: a negative weight");
        assert_eq!(
            mu.iter().fold(q(0), |a, m| a + m),
            q(1),
            "{v:?}: weights do not sum to 1"
        );
        for (c, coordinate) in v.pos.iter().enumerate() {
            let sum = (0..n).fold(q(0), |a, k| a + &mu[k] * &pos[k][c]);
            assert_eq!(&sum, coordinate, "{v:?} is not on the input polygon");
        }
    }
    let distinct = (0..n).all(|k| pos[k] != pos[(k + 1) % n]);
    if n == 3 && distinct && pos.iter().all(|p| in_volume(p, depth)) {
        assert_eq!(out, poly, "a triangle inside the volume changed");
    }
    if pos.iter().all(|p| p[3].is_negative()) {
        assert!(out.is_empty(), "a polygon behind the eye left {out:?}");
    }
}

fn window_identities(tri: &[ClipVertex; 3], vp: &Viewport) {
    let window = clip_to_window_exact(tri, vp);
    let (x1, y1) = (&vp.x + &vp.width, &vp.y + &vp.height);
    for v in &window {
        let p = &v.point;
        assert!(
            vp.x <= p.x && p.x <= x1 && vp.y <= p.y && p.y <= y1,
            "{p} outside the viewport"
        );
        assert!(
            !v.z.is_negative() && v.z <= q(1),
            "depth {} outside [0, 1]",
            exact_text(&v.z)
        );
        assert!(v.inv_w.is_positive(), "1/w = {}", exact_text(&v.inv_w));
    }
    let behind = tri.iter().position(|v| !v.pos[3].is_positive());
    match (behind, divide_then_clip_exact(tri, vp)) {
        (None, Ok(after)) => assert_eq!(after, window, "before and after the divide differ"),
        (None, Err(ProjectError::EdgeOn)) => {
            let points: Vec<Point> = window.iter().map(|v| v.point.clone()).collect();
            assert!(area2_exact(&points).is_zero(), "edge-on after the divide, area before");
        }
        (Some(k), Err(ProjectError::NotInFront { vertex, w })) => {
            assert_eq!((vertex, w), (k, exact_text(&tri[k].pos[3])));
        }
        (k, r) => panic!("vertex behind the eye {k:?}, divide-then-clip {r:?}"),
    }
    for (k, v) in tri.iter().enumerate() {
        assert_eq!(to_window_exact(v, k, vp).is_ok(), v.pos[3].is_positive());
    }
}

fn interpolation(tri: &[ClipVertex; 3], input: &Input, vp: &Viewport) {
    let out: Vec<ClipVertex> = clip_exact(tri, vp.depth)
        .into_iter()
        .filter(|v| v.pos[3].is_positive())
        .collect();
    if out.len() < 3 {
        return;
    }
    let j = 1 + usize::from(input.fan) % (out.len() - 2);
    let corners = [out[0].clone(), out[j].clone(), out[j + 1].clone()];
    let weights = input.lambda.map(|l| 1 + i64::from(l % 9));
    let total: i64 = weights.iter().sum();
    let l = weights.map(|w| BigRational::new(w.into(), total.into()));
    let mix = |f: &dyn Fn(&ClipVertex) -> BigRational| (0..3).fold(q(0), |a, k| a + &l[k] * f(&corners[k]));
    let p = ClipVertex {
        pos: std::array::from_fn(|c| mix(&|v| v.pos[c].clone())),
        attrs: vec![mix(&|v| v.attrs[0].clone())],
    };
    let p = to_window_exact(&p, 0, vp).expect("a convex combination of w > 0 has w > 0");
    let projected: [WindowVertex; 3] = project_exact(&corners, vp).expect("w > 0").try_into().expect("three");
    if let Some(got) = interpolate_exact(&projected, &p.point) {
        assert_eq!(got.attrs, p.attrs, "perspective-correct attribute");
        assert_eq!(got.z, p.z, "depth");
        assert_eq!(got.inv_w, p.inv_w, "1/w");
    }
}

fn models(tri: &[ClipVertex; 3], vp: &Viewport) {
    let target = Target::new(8, 8, Convention::default()).expect("valid");
    let primitives = Primitives {
        clip_space_triangles: vec![tri.clone().map(|v| ClipVertex { attrs: vec![], ..v })],
        viewport: Some(vp.clone()),
        ..Primitives::default()
    };
    for (a, b) in [
        (Model::Exact, Model::ExactPlain),
        (Model::ExactSnapped, Model::ExactSnappedPlain),
    ] {
        let (ra, rb) = (render(&primitives, &target, a), render(&primitives, &target, b));
        assert_eq!(
            ra.expect("exact takes clip space"),
            rb.expect("exact takes clip space"),
            "{a} != {b}"
        );
    }
    for m in [Model::Fixed, Model::Float32] {
        let _ = render(&primitives, &target, m);
    }
}

fn floats(tri: &[ClipVertex; 3], input: &Input, vp: &Viewport) {
    let v64: Vec<ClipVertexF64> = tri.iter().map(|v| v.to_f64().expect("small")).collect();
    let v32: Vec<ClipVertexF32> = tri.iter().map(|v| v.to_f32().expect("small")).collect();
    let (vp64, vp32) = (vp.to_f64().expect("small"), vp.to_f32().expect("small"));
    let _ = clip_to_window_f64(&v64, &vp64);
    let _ = clip_to_window_f32(&v32, &vp32);
    let raw32: Vec<ClipVertexF32> = input
        .raw
        .iter()
        .map(|r| ClipVertexF32 {
            pos: Vec4::from_array(r.map(f32::from_bits)),
            attrs: vec![f32::from_bits(r[0].rotate_left(7))],
        })
        .collect();
    let raw64: Vec<ClipVertexF64> = raw32
        .iter()
        .map(|v| ClipVertexF64 {
            pos: DVec4::from_array(v.pos.to_array().map(f64::from)),
            attrs: v.attrs.iter().copied().map(f64::from).collect(),
        })
        .collect();
    let _ = clip_f32(&raw32, vp.depth);
    let _ = clip_f64(&raw64, vp.depth);
    let _ = clip_to_window_f32(&raw32, &vp32);
    let _ = clip_to_window_f64(&raw64, &vp64);
}

fuzz_target!(|input: Input| {
    let depth = if input.gl_depth {
        DepthRange::MinusOneToOne
    } else {
        DepthRange::ZeroToOne
    };
    let n = 3 + usize::from(input.count % 4);
    let pos: Vec<[BigRational; 4]> = input.vertices[..n].iter().map(|v| v.map(C::value)).collect();
    polygon_identities(&pos, depth);

    let half = |v: i8| BigRational::new(BigInt::from(v % 16), BigInt::from(2));
    let side = |v: i8| BigRational::new(BigInt::from(1 + v.unsigned_abs() % 16), BigInt::from(2));
    let [vx, vy, vw, vh] = input.viewport;
    let y_axis = if input.ndc_down { NdcY::Down } else { NdcY::Up };
    let vp = Viewport::new(half(vx), half(vy), side(vw), side(vh), y_axis, depth).expect("positive sides");
    let tri: [ClipVertex; 3] = std::array::from_fn(|k| ClipVertex {
        pos: pos[k].clone(),
        attrs: vec![q(i64::from(input.attrs[k]))],
    });
    window_identities(&tri, &vp);
    interpolation(&tri, &input, &vp);
    models(&tri, &vp);
    floats(&tri, &input, &vp);
});
