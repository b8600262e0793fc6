//! Clipping, exactly: any polygon clipped by Sutherland-Hodgman against any window stays
//! inside it and rasterizes to raster(P) ∩ raster(W); Cohen-Sutherland keeps exactly the
//! part of a segment inside a rectangle; window validation and the float forms never
//! panic or hang on any input.

#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;

mod common;
use common::{convention, PresetChoice};
use rasterproof::check::{check_clip_raster, check_inside, check_segment_clip};
use rasterproof::clip::sutherland_hodgman::clip_polygon;
use rasterproof::clip::{cohen_sutherland, sutherland_hodgman, Window};
use rasterproof::convention::Target;
use rasterproof::geom::{FillRule, Point, Polygon};

#[derive(Debug, Clone, Arbitrary)]
struct Input {
    subject: Vec<(i16, i16)>,
    /// A rectangle from the first two points, or a convex window from all of them.
    window: Vec<(i16, i16)>,
    convex: bool,
    /// Coordinates are `v / (1 + den % 8)` px after folding onto [-8, 24).
    den: u8,
    even_odd: bool,
    preset: PresetChoice,
    corner: bool,
}

fuzz_target!(|input: Input| {
    let den = 1 + i64::from(input.den % 8);
    let point = |&(x, y): &(i16, i16)| {
        let fold = |v: i16| i64::from(v).rem_euclid(32 * den) - 8 * den;
        Point::from_fractions(fold(x), den, fold(y), den)
    };
    let subject: Vec<Point> = input.subject.iter().take(10).map(point).collect();
    let corners: Vec<Point> = input.window.iter().take(8).map(point).collect();
    let window = if input.convex {
        Window::convex(corners)
    } else if corners.len() >= 2 {
        let (a, b) = (&corners[0], &corners[1]);
        Window::rect(
            a.x.clone().min(b.x.clone()),
            a.y.clone().min(b.y.clone()),
            a.x.clone().max(b.x.clone()),
            a.y.clone().max(b.y.clone()),
        )
    } else {
        return;
    };
    let Ok(window) = window else {
        return; // refused with an error: fine, as long as it did not panic
    };
    if subject.len() < 3 {
        return;
    }
    let rule = if input.even_odd {
        FillRule::EvenOdd
    } else {
        FillRule::NonZero
    };
    let poly = Polygon::new(subject.clone(), rule);
    let cut = clip_polygon(&poly, &window);
    if let Err(v) = check_inside(&cut.outline, &window) {
        panic!("{v}\n{poly:?}\n{window:?}");
    }
    let mut conv = convention(input.preset, None, input.corner);
    conv.subpixel_bits = 8;
    let target = Target::new(16, 16, conv).expect("valid");
    if let Err(v) = check_clip_raster(&poly, &cut, &window, &target) {
        panic!("{v}\n{poly:?}\n{window:?}");
    }
    let f = |p: &Point| p.to_f64().expect("small coordinates fit f64");
    let planes: Vec<_> = window.half_planes().iter().map(|h| h.to_f64().unwrap()).collect();
    let _ = sutherland_hodgman::clip_f64(&subject.iter().map(f).collect::<Vec<_>>(), &planes);
    if let Window::Rect(r) = &window {
        let (a, b) = (&subject[0], &subject[1]);
        let kept = cohen_sutherland::clip_exact(a, b, r);
        if let Err(v) = check_segment_clip(a, b, r, kept.as_ref()) {
            panic!("{v}");
        }
        let _ = cohen_sutherland::clip_f64(f(a), f(b), &r.to_f64().unwrap());
        let _ = cohen_sutherland::clip_f32(
            a.to_f32().expect("fits f32"),
            b.to_f32().expect("fits f32"),
            &r.to_f32().unwrap(),
        );
    }
});
