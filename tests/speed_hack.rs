//! A known-bad implementation, kept to show what the harness catches: seed 004's "speed
//! hacks" inner loop (Luebke, "Drawing triangles", slide 29), copied faithfully:
//!
//! ```c
//! for (int x = xMin; x <= xMax; x++) {
//!     if (e0|e1|e2 > 0) { setPixel(x,y); xflag++; }
//!     else if (xflag != 0) break;
//!     e0 += a0; e1 += a1; e2 += a2;
//! }
//! ```
//!
//! C binds `>` tighter than `|`, so the test is `e0 | e1 | (e2 > 0)`: true whenever `e0`
//! or `e1` has any bit set. The seed's note says what was meant: all three values
//! non-negative, which an OR of the values tests through the sign bit as
//! `(e0|e1|e2) >= 0` — still `>= 0`, with no tie rule. The harness must find both, and
//! report each with a minimal scene.

use rasterproof::convention::{Preset, Target};
use rasterproof::coverage::{Coverage, CoverageSink};
use rasterproof::geom::FixedTriangle;
use rasterproof::harness::{find_counterexample, Counterexample, HarnessConfig};
use rasterproof::scene::parse_scene;

/// Which inside test the loop uses.
#[derive(Clone, Copy)]
enum Test {
    /// `e0|e1|e2 > 0` as C parses it.
    AsWritten,
    /// `(e0|e1|e2) >= 0`: the sign bits, as intended.
    SignBits,
}

/// The slide's loop on the snapped triangle: edge equations `A x + B y + C` from two
/// vertices (seed 004: `A = y0 - y1`, `B = x1 - x0`, `C = x0 y1 - x1 y0`), flipped so the
/// third vertex is on the positive side ("consistent edge order, test the sign and flip"),
/// a bounding box of whole pixels, samples at the target's pixel centres, incremental
/// update along the row and the early exit.
fn speed_hack(test: Test) -> impl Fn(&FixedTriangle, u32, &Target, &mut dyn CoverageSink) {
    move |t, id, target, sink| {
        let v = t.coords();
        let one = 1i64 << t.bits;
        let c = target.convention.pixel_centre.offset_subpixels(t.bits);
        let edge = |p: [i64; 2], q: [i64; 2], r: [i64; 2]| {
            let (a, b, cc) = (p[1] - q[1], q[0] - p[0], p[0] * q[1] - q[0] * p[1]);
            if a * r[0] + b * r[1] + cc < 0 {
                (-a, -b, -cc)
            } else {
                (a, b, cc)
            }
        };
        let edges = [edge(v[0], v[1], v[2]), edge(v[1], v[2], v[0]), edge(v[2], v[0], v[1])];
        let min = |k: usize| v.iter().map(|p| p[k]).min().unwrap().div_euclid(one);
        let max = |k: usize| -(-v.iter().map(|p| p[k]).max().unwrap()).div_euclid(one);
        let (w, h) = (i64::from(target.width), i64::from(target.height));
        for y in min(1).max(0)..=max(1).min(h - 1) {
            let (x_min, x_max) = (min(0).max(0), max(0).min(w - 1));
            let (sx, sy) = (x_min * one + c, y * one + c);
            let mut e = edges.map(|(a, b, cc)| a * sx + b * sy + cc);
            let step = edges.map(|(a, _, _)| a * one);
            let mut xflag = 0;
            for x in x_min..=x_max {
                let inside = match test {
                    Test::AsWritten => (e[0] | e[1] | i64::from(e[2] > 0)) != 0,
                    Test::SignBits => (e[0] | e[1] | e[2]) >= 0,
                };
                if inside {
                    sink.cover(u32::try_from(x).unwrap(), u32::try_from(y).unwrap(), id);
                    xflag += 1;
                } else if xflag != 0 {
                    break;
                }
                for k in 0..3 {
                    e[k] += step[k];
                }
            }
        }
    }
}

fn config() -> HarnessConfig {
    HarnessConfig {
        cases: 256,
        canvas: 16,
        preset: Preset::D3d11,
        seed: 4,
    }
}

/// The reported scene is a real counterexample: read back from its JSON text, the oracle
/// and the speed hack disagree on it.
fn assert_genuine(found: &Counterexample, test: Test) {
    // Shown with `cargo test --test it speed_hack:: -- --nocapture`: what a user sees.
    eprintln!("{}{}\n", found.scene.to_json(), found.violation);
    let scene = parse_scene(&found.scene.to_json(), "counterexample.json").unwrap();
    let target = scene.target().unwrap();
    let t = scene.triangles[0]
        .triangle
        .snapped(&target.convention)
        .to_fixed()
        .unwrap();
    assert_eq!(t, found.triangle);
    let (mut oracle, mut hack) = (
        Coverage::new(target.width, target.height),
        Coverage::new(target.width, target.height),
    );
    rasterproof::tri::exact::rasterize(&scene.triangles[0].triangle.to_triangle(), 0, &target, &mut oracle);
    speed_hack(test)(&t, 0, &target, &mut hack);
    assert_ne!(oracle, hack);
}

/// As written, nearly every pixel of the bounding box passes. The smallest counterexample
/// there can be, derived by hand: two vertices at the origin and the third one subpixel
/// away. Its area is zero, so the oracle covers nothing; but the edge from the origin to
/// the third vertex has a non-zero coefficient, its value at the sample (1/2, 1/2) is not
/// zero, and `e0 | e1 | ...` is true: the hack paints pixel (0, 0). The harness must
/// arrive at exactly that: coordinate magnitudes summing to 1 subpixel, on a 1x1 canvas.
#[test]
fn harness_catches_the_speed_hack_as_written() {
    let found = find_counterexample(speed_hack(Test::AsWritten), &config()).expect("the hack is caught");
    assert_eq!(found.violation.invariant, "agreement");
    let magnitude: i64 = found.triangle.coords().iter().flatten().map(|c| c.abs()).sum();
    assert_eq!(magnitude, 1, "{:?}", found.triangle);
    assert_eq!((found.scene.width, found.scene.height), (1, 1));
    assert!(
        found.violation.message.contains("(0, 0): oracle [], candidate [0]"),
        "{}",
        found.violation
    );
    assert_genuine(&found, Test::AsWritten);
}

/// The intended sign-bit test is right everywhere except at ties: it takes every sample
/// on an edge (`>= 0` on all three edges). The harness's minimal case is a zero-area
/// triangle whose line passes through the sample: all three values are 0 there, so the
/// hack covers the pixel, and the oracle covers nothing. Checked here independently: at
/// the first differing pixel some edge's exact value is zero (the test's own i128 edge
/// functions), the hack covers a pixel the oracle does not, and no coordinate can move
/// one subpixel towards zero with the failure staying.
#[test]
fn harness_catches_the_sign_bit_test_at_ties() {
    let found = find_counterexample(speed_hack(Test::SignBits), &config()).expect("ties are caught");
    assert_genuine(&found, Test::SignBits);
    let target = found.scene.target().unwrap();
    let (mut oracle, mut hack) = (
        Coverage::new(target.width, target.height),
        Coverage::new(target.width, target.height),
    );
    rasterproof::tri::exact::rasterize(
        &found.scene.triangles[0].triangle.to_triangle(),
        0,
        &target,
        &mut oracle,
    );
    speed_hack(Test::SignBits)(&found.triangle, 0, &target, &mut hack);
    let first = rasterproof::check::differing_pixels(&oracle, &hack).remove(0);
    assert!(first.reference.is_empty() && first.candidate == [0], "{first:?}");
    let v = found.triangle.coords().map(|p| p.map(i128::from));
    let one = 1i128 << found.triangle.bits;
    let s = [i128::from(first.x) * one + one / 2, i128::from(first.y) * one + one / 2];
    let on_an_edge = (0..3).any(|k| {
        let (a, b) = (v[k], v[(k + 1) % 3]);
        (s[0] - a[0]) * (b[1] - a[1]) - (s[1] - a[1]) * (b[0] - a[0]) == 0
    });
    assert!(on_an_edge, "{found:?}");
    // 1-minimal: no coordinate can move one subpixel towards zero and keep the failure.
    for k in 0..6 {
        let mut t = found.triangle;
        let c = t.v[k / 2][k % 2].get();
        if c == 0 {
            continue;
        }
        t.v[k / 2][k % 2] = rasterproof::num::SubPixel::new(c - c.signum()).unwrap();
        let (mut o, mut h) = (
            Coverage::new(target.width, target.height),
            Coverage::new(target.width, target.height),
        );
        rasterproof::tri::exact::rasterize(&t.to_exact(), 0, &target, &mut o);
        speed_hack(Test::SignBits)(&t, 0, &target, &mut h);
        assert_eq!(o, h, "coordinate {k} could still shrink: {t:?}");
    }
}

/// The tie the sign-bit test gets wrong on real triangles, by hand: the 4x4 square split
/// along its diagonal (0,0)-(4,4). The diagonal passes through the samples (0.5,0.5),
/// (1.5,1.5), (2.5,2.5), (3.5,3.5); both triangles have `E = 0` there, so the sign-bit
/// test gives those 4 pixels to both (the top-left rule gives each to one).
#[test]
fn sign_bit_test_double_covers_a_shared_diagonal() {
    let target = Target::new(4, 4, Preset::D3d11.convention()).unwrap();
    let tri = |v: [[i64; 2]; 3]| FixedTriangle {
        v: v.map(|p| p.map(|c| rasterproof::num::SubPixel::new(c * 256).unwrap())),
        bits: 8,
    };
    let (upper, lower) = (tri([[0, 0], [4, 0], [4, 4]]), tri([[0, 0], [4, 4], [0, 4]]));
    let mut hack = Coverage::new(4, 4);
    speed_hack(Test::SignBits)(&upper, 0, &target, &mut hack);
    speed_hack(Test::SignBits)(&lower, 1, &target, &mut hack);
    let doubled: Vec<(u32, u32)> = hack.double_covered().map(|(x, y, _)| (x, y)).collect();
    assert_eq!(doubled, [(0, 0), (1, 1), (2, 2), (3, 3)]);
    assert!(rasterproof::check::check_no_double_cover(&hack).is_err());
}

/// No false alarm: the crate's own integer models pass the same search.
#[test]
fn harness_passes_the_crates_models() {
    let config = HarnessConfig { cases: 128, ..config() };
    assert!(find_counterexample(
        |t, id, target, sink| rasterproof::tri::fixed::rasterize(t, id, target, sink),
        &config
    )
    .is_none());
    assert!(find_counterexample(
        |t, id, target, sink| rasterproof::tri::scanline::rasterize(t, id, target, sink),
        &config
    )
    .is_none());
}
