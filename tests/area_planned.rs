//! The planned exact area engine (`area::planned`, machine integers) against the plain
//! oracle (`area::exact`) and exact cell accumulation (`area::cells`): on every polygon
//! family, on meshes, on shapes that leave the canvas on every side, on coordinates of
//! mixed denominators, and by hand at each bound of its envelope (a shape just inside is
//! walked in `i128` and one just outside in big rationals, and both agree with the
//! oracle).

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};
use proptest::prelude::*;

use crate::common::config;
use rasterproof::area::exact::{self, pixel};
use rasterproof::area::planned::{self, plan, AreaWidth, FINE_BITS};
use rasterproof::area::{cells, triangle_shape, AreaShape, Semantics};
use rasterproof::geom::{FillRule, Point, Polygon};
use rasterproof::strategy::polygon::any_polygon;
use rasterproof::strategy::{any_triangle, delaunay_mesh};

/// `n / d` as a rational.
fn q(n: i128, d: i128) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

/// `shape` moved by `(dx, dy)` and scaled about the origin by `k`.
fn affine(shape: &AreaShape, k: &BigRational, dx: &BigRational, dy: &BigRational) -> AreaShape {
    let f = |p: &Point| Point::new(&p.x * k + dx, &p.y * k + dy);
    Polygon {
        outline: shape.outline.iter().map(f).collect(),
        holes: shape.holes.iter().map(|c| c.iter().map(f).collect()).collect(),
        fill_rule: shape.fill_rule,
    }
}

/// Asserts that the planned engine gives the plain oracle's signed integral at every
/// pixel of a `side` x `side` canvas for each shape, and the same images under every
/// semantics for them all.
fn assert_planned_is_exact(shapes: &[AreaShape], side: u32) -> Result<(), TestCaseError> {
    for shape in shapes {
        let got = planned::accumulate(shape, side, side);
        prop_assert_eq!(&got, &cells::accumulate(shape, side, side));
        let one = std::slice::from_ref(shape);
        let mut k = 0;
        for y in 0..side {
            for x in 0..side {
                let (_, acc) = pixel(one, i64::from(x), i64::from(y));
                let mine = match got.get(k) {
                    Some((gx, gy, v)) if (*gx, *gy) == (x, y) => {
                        k += 1;
                        v.clone()
                    }
                    _ => BigRational::zero(),
                };
                prop_assert_eq!(&mine, &acc[0], "pixel ({}, {})", x, y);
            }
        }
        prop_assert_eq!(k, got.len(), "a zero or a pixel out of order among {:?}", got);
    }
    for s in Semantics::ALL {
        prop_assert_eq!(
            planned::rasterize(shapes, side, side, s),
            exact::rasterize(shapes, side, side, s)
        );
    }
    Ok(())
}

/// A scale: a whole number, a third, a power of two small or large.
fn scale() -> impl Strategy<Value = BigRational> {
    prop_oneof![
        Just(q(1, 1)),
        Just(q(1, 3)),
        Just(q(5, 7)),
        Just(q(1, 1 << 20)),
        Just(q(3, 2))
    ]
}

/// A move: by whole pixels, by a fraction, far off the canvas on either side.
fn shift() -> impl Strategy<Value = BigRational> {
    prop_oneof![
        (-6i128..6).prop_map(|n| q(n, 1)),
        (-40i128..40).prop_map(|n| q(n, 9)),
        Just(q(-(1 << 40), 1)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..config("proptest-regressions/area_planned.txt") })]

    /// Every polygon family (simple, tangled, stellated, holed; nonzero and even-odd) with
    /// a triangle of every scale, scaled and moved so that they leave the canvas, use
    /// thirds and sevenths, and sit at powers of two.
    #[test]
    fn planned_equals_the_plain_oracle(
        poly in any_polygon(5, 7),
        t in any_triangle(5),
        k in scale(),
        dx in shift(),
        dy in shift(),
    ) {
        let shapes = [affine(&poly, &k, &dx, &dy), triangle_shape(&t)];
        assert_planned_is_exact(&shapes, 6)?;
    }

    /// A triangulation's triangles, summed: the hull's accumulated coverage.
    #[test]
    fn planned_meshes_equal_the_plain_oracle(mesh in delaunay_mesh([0, 0], 4, 3, 8)) {
        let triangles: Vec<AreaShape> = mesh.triangles.iter().map(triangle_shape).collect();
        assert_planned_is_exact(&triangles, 5)?;
    }
}

/// The quad (0, 0) (w, e) (w, 3) (0, 3) with a slanted top edge: its `F` is that edge's
/// `S |a| |b|`; the other edges are vertical (`F = S`) or horizontal.
fn slanted_quad(w: BigRational, e: BigRational) -> AreaShape {
    let p = |x: BigRational, y: BigRational| Point::new(x, y);
    Polygon::new(
        vec![p(q(0, 1), q(0, 1)), p(w.clone(), e), p(w, q(3, 1)), p(q(0, 1), q(3, 1))],
        FillRule::NonZero,
    )
}

/// At the fine-unit bound: `S = 2^31`, the top edge 1 px across and 2^-31 px down, so
/// `|a| = 2^31`, `|b| = 1` and `F = 2^62` (in `i128`); one step further, 1 + 2^-31 px
/// across, `F = 2^62 + 2^31` (big rationals); and `F = 2^63`, where the fraction's
/// denominator `2 F^2` would leave `i128` (a bound raised past it is caught here).
#[test]
fn the_fine_unit_bound_by_hand() {
    assert_eq!(FINE_BITS, 62);
    let s = 1i128 << 31;
    let at = slanted_quad(q(1, 1), q(1, s));
    let past = slanted_quad(q(s + 1, s), q(1, s));
    let far_past = slanted_quad(q(1, 2), q(1, 2 * s));
    assert_eq!(plan(&at), AreaWidth::I128);
    assert_eq!(plan(&past), AreaWidth::Big);
    assert_eq!(plan(&far_past), AreaWidth::Big);
    for shape in [at, past, far_past] {
        assert_planned_is_exact(std::slice::from_ref(&shape), 4).unwrap();
        // Pixel (0, 0) by hand: the unit square less the sliver above the edge.
        let (w, e) = (&shape.outline[1].x, &shape.outline[1].y);
        let sliver = if w >= &BigRational::one() {
            e / (w * q(2, 1))
        } else {
            e * q(1, 2) / w
        };
        let expected = if w >= &BigRational::one() {
            BigRational::one() - sliver
        } else {
            // Half a pixel wide: the left half less its sliver.
            q(1, 2) - e * q(1, 4)
        };
        let image = planned::rasterize(std::slice::from_ref(&shape), 4, 4, Semantics::Accumulated);
        assert_eq!(image.value(0, 0), expected, "{shape:?}");
    }
}

/// At the scaled-coordinate bound: a strip one third of a pixel high from `-x / 3` to 2
/// px, its left side `x` units of 1/3 px left of the canvas; `x = 2^62 - 1` is taken in
/// `i128`, `x = 2^62` is not. Its edges are horizontal or vertical (`F = S = 3`), so only
/// the coordinate bound decides; on the canvas it covers a third of pixels 0 and 1.
#[test]
fn the_coordinate_bound_by_hand() {
    let limit = 1i128 << 62;
    for (x, width) in [(limit - 1, AreaWidth::I128), (limit, AreaWidth::Big)] {
        let p = |x: BigRational, y: BigRational| Point::new(x, y);
        let strip = Polygon::new(
            vec![
                p(q(-x, 3), q(0, 1)),
                p(q(2, 1), q(0, 1)),
                p(q(2, 1), q(1, 3)),
                p(q(-x, 3), q(1, 3)),
            ],
            FillRule::NonZero,
        );
        assert_eq!(plan(&strip), width, "x = {x}");
        assert_planned_is_exact(std::slice::from_ref(&strip), 3).unwrap();
        let image = planned::rasterize(&[strip], 3, 3, Semantics::Accumulated);
        assert_eq!(image.pixels, vec![(0, 0, q(1, 3)), (1, 0, q(1, 3))], "x = {x}");
    }
}

/// Edges on the canvas's border: a square [1, 3] x [0, 2] on a 3x3 canvas (its right side
/// on the canvas's right border, its top on the top border), and the same square moved
/// one pixel right (its right side one pixel past the border): whole pixels inside the
/// canvas, nothing at column 3, under both fill rules and both ways round.
#[test]
fn edges_on_the_canvas_border_by_hand() {
    let p = |x: i128, y: i128| Point::new(q(x, 1), q(y, 1));
    let one = BigRational::one;
    for (dx, expected) in [
        (0, vec![(1, 0, one()), (2, 0, one()), (1, 1, one()), (2, 1, one())]),
        (1, vec![(2, 0, one()), (2, 1, one())]),
    ] {
        for rule in [FillRule::NonZero, FillRule::EvenOdd] {
            let mut square = Polygon::new(vec![p(1 + dx, 0), p(3 + dx, 0), p(3 + dx, 2), p(1 + dx, 2)], rule);
            for _ in 0..2 {
                assert_planned_is_exact(std::slice::from_ref(&square), 3).unwrap();
                let image = planned::rasterize(std::slice::from_ref(&square), 3, 3, Semantics::Accumulated);
                assert_eq!(image.pixels, expected, "{square:?}");
                square.outline.reverse();
            }
        }
    }
}

/// Bands: on a 150x150 canvas (three bands of `BAND` = 64 rows), a triangle and a holed
/// star crossing the band lines, with coordinates in thirds, give the cells' values, and
/// `for_each_row` hands out every row once, top first, each row's pixels by column.
#[test]
fn bands_change_nothing() {
    assert_eq!(planned::BAND, 64);
    let p = |x: i128, y: i128| Point::new(q(x, 3), q(y, 3));
    let triangle = Polygon::new(vec![p(10, 5), p(440, 190), p(30, 449)], FillRule::NonZero);
    let star = |r: i128, turn: bool| -> Vec<Point> {
        let pts = [(0, -3), (1, -1), (3, 0), (1, 1), (0, 3), (-1, 1), (-3, 0), (-1, -1)];
        let mut v: Vec<Point> = pts.iter().map(|&(x, y)| p(225 + r * x, 200 + r * y)).collect();
        if turn {
            v.reverse();
        }
        v
    };
    let holed = Polygon {
        outline: star(40, false),
        holes: vec![star(10, true)],
        fill_rule: FillRule::EvenOdd,
    };
    let shapes = [triangle, holed];
    for s in [Semantics::Accumulated, Semantics::AccumulatedUnclamped] {
        assert_eq!(
            Some(planned::rasterize(&shapes, 150, 150, s)),
            cells::rasterize(&shapes, 150, 150, s)
        );
    }
    let mut rows = Vec::new();
    planned::for_each_row(&shapes, 150, 150, Semantics::Accumulated, |y, pixels| {
        assert!(pixels.windows(2).all(|w| w[0].0 < w[1].0), "row {y}");
        rows.push(y);
    });
    assert_eq!(rows, (0..150).collect::<Vec<u32>>());
}

/// Rows the canvas's borders cut: an L whose inner vertical edge lies on the right border
/// (x = 3 on a 3-wide canvas) with the shape going on past it, and a strip wider than the
/// canvas (no edge on it at all: the row's value comes from the edges left of it alone).
/// Only the canvas's pixels have values, each whole.
#[test]
fn shapes_past_the_canvas_by_hand() {
    let p = |x: i128, y: i128| Point::new(q(x, 1), q(y, 1));
    let one = BigRational::one;
    let ell = Polygon::new(
        vec![p(1, 0), p(5, 0), p(5, 2), p(3, 2), p(3, 1), p(1, 1)],
        FillRule::NonZero,
    );
    let strip = Polygon::new(vec![p(-1, 1), p(4, 1), p(4, 2), p(-1, 2)], FillRule::NonZero);
    let cases = [
        (ell, vec![(1, 0, one()), (2, 0, one())]),
        (strip, vec![(0, 1, one()), (1, 1, one()), (2, 1, one())]),
    ];
    for (shape, expected) in cases {
        assert_planned_is_exact(std::slice::from_ref(&shape), 3).unwrap();
        let image = planned::rasterize(std::slice::from_ref(&shape), 3, 3, Semantics::Accumulated);
        assert_eq!(image.pixels, expected, "{shape:?}");
    }
}

/// A pixel wound twice over part of it: the square [0, 2]^2 with a "hole" [1/2, 3/2]^2
/// running the same way (the path winds 2 there). Pixel (0, 0) integrates 1 + 1/4 = 5/4:
/// unclamped 5/4, nonzero accumulated 1 (written "1", in lowest terms), even-odd
/// accumulated 2 - 5/4 = 3/4.
#[test]
fn a_doubly_wound_pixel_by_hand() {
    let p = |x: i128, y: i128| Point::new(q(x, 2), q(y, 2));
    let outline = vec![p(0, 0), p(4, 0), p(4, 4), p(0, 4)];
    let inner = vec![p(1, 1), p(3, 1), p(3, 3), p(1, 3)];
    for (rule, accumulated) in [(FillRule::NonZero, q(1, 1)), (FillRule::EvenOdd, q(3, 4))] {
        let shape = Polygon {
            outline: outline.clone(),
            holes: vec![inner.clone()],
            fill_rule: rule,
        };
        assert_planned_is_exact(std::slice::from_ref(&shape), 2).unwrap();
        let one = std::slice::from_ref(&shape);
        assert_eq!(
            planned::rasterize(one, 2, 2, Semantics::AccumulatedUnclamped).value(0, 0),
            q(5, 4)
        );
        let v = planned::rasterize(one, 2, 2, Semantics::Accumulated).value(0, 0);
        assert_eq!(v, accumulated);
        assert!(
            v.numer().gcd(v.denom()).is_one() && v.denom().sign() == num_bigint::Sign::Plus,
            "{v:?}"
        );
    }
}
