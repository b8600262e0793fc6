//! An independent oracle for the tests, sharing no code with the crate's models: integer
//! snapping written out by hand, i128 edge values on the subpixel grid, and the tie rule
//! taken literally from its ε reading — the sample is moved right by ε and down
//! (top-left) or up (bottom-left) by ε², and E at the moved sample is compared with 0 as
//! a polynomial in ε (lexicographically: E, then dE/dε, then the ε² coefficient).

#![allow(dead_code)]

use std::collections::BTreeMap;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::ToPrimitive;
use proptest::test_runner::{Config, FileFailurePersistence};

/// proptest config: PROPTEST_CASES (default 256) cases, regressions in proptest-regressions/.
pub fn config(file: &'static str) -> Config {
    Config {
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(file))),
        ..Config::default()
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    TopLeft,
    BottomLeft,
}

#[derive(Clone, Copy, Debug)]
pub struct Conv {
    pub rule: Rule,
    pub bits: u32,
    pub half_away: bool,
}

/// Rounds num/den * 2^bits to an integer: nearest, ties to even or away from zero.
pub fn snap(x: &BigRational, bits: u32, half_away: bool) -> i128 {
    let scaled = x.numer() * (BigInt::from(1) << bits);
    let den = x.denom(); // positive
    let (q, r) = scaled.div_mod_floor(den); // x*2^bits = q + r/den, 0 <= r < den
    let twice = &r * 2;
    let q = if twice < *den {
        q
    } else if twice > *den {
        q + 1
    } else if half_away {
        if scaled.sign() == num_bigint::Sign::Minus {
            q
        } else {
            q + 1
        }
    } else if q.is_even() {
        q
    } else {
        q + 1
    };
    q.to_i128().expect("test coordinates are small")
}

/// Pixel -> sorted owner ids, for triangles given as exact vertices, samples at centres.
pub fn render(tris: &[[[BigRational; 2]; 3]], w: u32, h: u32, conv: Conv) -> BTreeMap<(u32, u32), Vec<u32>> {
    let half = 1i128 << (conv.bits - 1);
    render_at(tris, w, h, conv, [half, half])
}

/// [`render`] with each pixel's sample at `at` subpixels from its top-left corner.
pub fn render_at(
    tris: &[[[BigRational; 2]; 3]],
    w: u32,
    h: u32,
    conv: Conv,
    at: [i128; 2],
) -> BTreeMap<(u32, u32), Vec<u32>> {
    let mut out: BTreeMap<(u32, u32), Vec<u32>> = BTreeMap::new();
    for (id, t) in tris.iter().enumerate() {
        let v: Vec<[i128; 2]> = t
            .iter()
            .map(|p| {
                [
                    snap(&p[0], conv.bits, conv.half_away),
                    snap(&p[1], conv.bits, conv.half_away),
                ]
            })
            .collect();
        let area = (v[2][0] - v[0][0]) * (v[1][1] - v[0][1]) - (v[2][1] - v[0][1]) * (v[1][0] - v[0][0]);
        if area == 0 {
            continue;
        }
        let order = if area > 0 { [0, 1, 2] } else { [0, 2, 1] };
        for j in 0..h {
            for i in 0..w {
                let one = 1i128 << conv.bits;
                let p = [i128::from(i) * one + at[0], i128::from(j) * one + at[1]];
                let inside = (0..3).all(|k| {
                    let a = v[order[k]];
                    let b = v[order[(k + 1) % 3]];
                    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                    let e = (p[0] - a[0]) * dy - (p[1] - a[1]) * dx;
                    // E(p + (ε, ±ε²)) = e + ε dy ∓ ε² dx
                    let eps2 = match conv.rule {
                        Rule::TopLeft => -dx,
                        Rule::BottomLeft => dx,
                    };
                    (e, dy, eps2) > (0, 0, 0)
                });
                if inside {
                    out.entry((j, i)).or_default().push(u32::try_from(id).unwrap());
                }
            }
        }
    }
    out
}

/// Parses the CLI's JSON coverage into the same shape as [`render`].
pub fn parse_coverage_json(text: &str) -> (u32, u32, BTreeMap<(u32, u32), Vec<u32>>) {
    let v: serde_json::Value = serde_json::from_str(text).expect("valid JSON");
    let w = u32::try_from(v["width"].as_u64().unwrap()).unwrap();
    let h = u32::try_from(v["height"].as_u64().unwrap()).unwrap();
    let mut out = BTreeMap::new();
    for px in v["pixels"].as_array().unwrap() {
        let x = u32::try_from(px[0].as_u64().unwrap()).unwrap();
        let y = u32::try_from(px[1].as_u64().unwrap()).unwrap();
        let ids = px[2]
            .as_array()
            .unwrap()
            .iter()
            .map(|i| u32::try_from(i.as_u64().unwrap()).unwrap())
            .collect();
        out.insert((y, x), ids);
    }
    (w, h, out)
}

/// The crate's coverage in the same shape.
pub fn coverage_map(c: &rasterproof::coverage::Coverage) -> BTreeMap<(u32, u32), Vec<u32>> {
    c.iter().map(|(x, y, ids)| ((y, x), ids.to_vec())).collect()
}

pub fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// A canvas of `width x height` pixels under the default convention (what a grey
/// comparison of area shapes is drawn on).
pub fn canvas(width: u32, height: u32) -> rasterproof::convention::Target {
    rasterproof::convention::Target::new(width, height, rasterproof::convention::Convention::default())
        .expect("a valid canvas")
}

/// Grey levels judged under `semantics` and `quantization`, against the exact model's
/// (unsnapped) shapes.
pub fn grey_options(
    semantics: rasterproof::area::Semantics,
    quantization: rasterproof::area::Quantization,
) -> rasterproof::oracle::compare::grey::GreyOptions {
    rasterproof::oracle::compare::grey::GreyOptions {
        model: rasterproof::model::Model::Exact,
        semantics,
        quantization,
        method: None,
    }
}
