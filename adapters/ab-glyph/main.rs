//! ab_glyph_rasterizer adapter: renders a rasterproof scene with `ab_glyph_rasterizer`
//! 0.1.10 (the rasterizer of the `ab_glyph` font crate, forked from font-rs: f32 signed-area
//! accumulation) and writes a **16-bit grey PNG** of its coverage, so that `rasterproof
//! compare SCENE.json OUT.png --as grey --quantization round16` (and `hunt` through
//! `--serve`) can judge it against the exact area coverage.
//!
//! ```sh
//! cargo run --release --example ab-glyph-adapter -- SCENE.json OUT.png
//! target/release/rasterproof compare SCENE.json OUT.png --as grey --semantics accumulated --quantization round16
//! target/release/examples/ab-glyph-adapter --serve
//! ```
//!
//! With `--serve` it stays alive and takes one scene per line on stdin (the stay-alive
//! protocol of `rasterproof::oracle::renderer::stay_alive`), through `rasterproof::oracle::renderer::adapter`.
//!
//! What it draws: **one `Rasterizer` for the whole scene**, as a glyph is drawn: every
//! triangle (its three edges) and every polygon (its outline and each hole, as written:
//! the contours of one glyph) added with `Rasterizer::draw_line`, each contour closed by
//! its last edge back to its first point. ab_glyph_rasterizer only accumulates the signed
//! area of the edges and reports its absolute value (`for_each_pixel`): the winding
//! numbers of all the contours add, whatever shape they belong to, so
//!
//! - a hole counts as a hole when it runs against its outline (as glyphs' counters do,
//!   and as `glyph-scene` writes them); one running the outline's way winds 2 there;
//! - two shapes that overlap add (two triangles of the same orientation give 2 where
//!   they overlap, of opposite orientations 0): the value is `|sum of the signed areas|`,
//!   the integral of the winding number of the scene's contours as one path (the crate's
//!   unclamped accumulated semantics of that one path), not a sum over the shapes;
//! - **even-odd polygons are refused** (exit 2): ab_glyph_rasterizer has no fill rule, its
//!   value is the nonzero accumulation (with `abs`, and no clamp).
//!
//! Lines, clip windows (`clip`) and clip-space triangles are refused (exit 2);
//! `viewport` (which only places clip-space triangles) is ignored.
//!
//! How y maps: ab_glyph_rasterizer's grid is y down with the origin at the top left of
//! pixel (0, 0), as rasterproof's canvas is, so nothing is flipped: pixel (x, y) of the
//! rasterizer is pixel (x, y) of the canvas.
//!
//! Coordinates: ab_glyph_rasterizer takes `f32`; every exact coordinate is rounded once to
//! the nearest `f32` (`Point::to_f32`; the adapter says on stderr how many were not
//! f32-exact). Its accumulation buffer is one run of `width x height` cells read as one
//! sum, so an edge left of column 0 or right of the last column would land in the row
//! above or below: when a shape reaches left of the canvas or right of it, the rasterizer
//! is widened to hold every point (as ab_glyph sizes it to the glyph's pixel bounds), the
//! scene moved right by `L = -floor(min x)` whole pixels (exactly, before the one rounding
//! to f32), and the canvas's columns cut out of it again. Rows above and below the canvas
//! it skips itself. A widened rasterizer of more than 2^28 cells is refused.
//!
//! Quantization: ab_glyph's value `a` (an f32, `|accumulated area|`) becomes the 16-bit
//! level `round(min(a, 1) x 65535)`, ties to even, computed exactly (the product of an f32
//! and 65535 is exact in f64): the crate's `round16` quantization of `a`. The clamp to 1 is
//! the adapter's: ab_glyph's own value exceeds 1 where contours overlap with the same
//! orientation, and by f32 rounding at pixels fully inside (up to 1.0000002 at 17 pixels of
//! `adapters/scenes/dejavu.json`); a note on stderr counts those pixels and gives the
//! largest value.
//!
//! Exit status: 0 when the PNG was written, 2 with one line on stderr otherwise (bad
//! arguments, an unreadable or invalid scene, a refused primitive, an unwritable output);
//! under `--serve` each of these is an `"ok": false` answer instead.

#![warn(clippy::cast_possible_truncation, clippy::cast_possible_wrap)]

use std::process::ExitCode;

use ab_glyph_rasterizer::{point, Rasterizer};
use num_rational::BigRational;
use num_traits::ToPrimitive;
use rasterproof::geom::{FillRule, Point, Triangle};
use rasterproof::oracle::renderer::adapter::adapter_main;
use rasterproof::scene::Scene;

/// A contour's exact points and its name in messages (`polygons[2].holes[0]`).
type Contour<'a> = (Vec<&'a Point>, String);

/// The name every message starts with.
const NAME: &str = "ab-glyph-adapter";

/// The most cells a (widened) rasterizer may have: 2^28 f32s, 1 GiB.
const MAX_CELLS: u64 = 1 << 28;

fn main() -> ExitCode {
    adapter_main(NAME, std::env::args_os().skip(1).collect(), |scene| {
        let drawn = render(scene)?;
        if drawn.inexact > 0 {
            eprintln!(
                "{NAME}: note: {} coordinate(s) are not f32-exact; rounded to the nearest f32",
                drawn.inexact
            );
        }
        if drawn.above_one > 0 {
            eprintln!(
                "{NAME}: note: ab_glyph's coverage exceeds 1 at {} pixel(s) (up to {}: overlapping contours, \
                 or f32 rounding past 1); clamped to 1",
                drawn.above_one, drawn.largest
            );
        }
        image::ImageBuffer::<image::Luma<u16>, Vec<u16>>::from_raw(scene.width, scene.height, drawn.levels)
            .map(image::DynamicImage::ImageLuma16)
            .ok_or_else(|| "internal: the levels do not match the canvas".to_string())
    })
}

/// What one scene gave.
struct Drawn {
    /// The 16-bit levels, row by row.
    levels: Vec<u16>,
    /// Coordinates that were not f32-exact.
    inexact: usize,
    /// Pixels whose value exceeded 1 before the clamp.
    above_one: usize,
    /// The largest value ab_glyph gave a pixel of the canvas.
    largest: f32,
}

/// The scene's contours, each a list of exact points, named for messages; `triangles` are
/// the scene's, read exactly.
fn contours<'a>(scene: &'a Scene, triangles: &'a [Triangle]) -> Result<Vec<Contour<'a>>, String> {
    if !scene.lines.is_empty() {
        return Err(format!(
            "lines: {} line(s): refused, this adapter draws area coverage of triangles and polygons only",
            scene.lines.len()
        ));
    }
    if scene.clip.is_some() {
        return Err("clip: refused, ab_glyph_rasterizer has no clip window".into());
    }
    if !scene.clip_space_triangles.is_empty() {
        return Err(format!(
            "clip_space_triangles: {} clip-space triangle(s): refused, ab_glyph_rasterizer has no clip space",
            scene.clip_space_triangles.len()
        ));
    }
    let mut out = Vec::new();
    for (k, t) in triangles.iter().enumerate() {
        out.push((t.v.iter().collect(), format!("triangles[{k}].v")));
    }
    for (k, polygon) in scene.polygons.iter().enumerate() {
        if polygon.fill_rule == FillRule::EvenOdd {
            return Err(format!(
                "polygons[{k}]: an even-odd polygon: refused, ab_glyph_rasterizer has no fill rule \
                 (it accumulates signed area: nonzero, as |sum|, unclamped)"
            ));
        }
        out.push((polygon.outline.iter().collect(), format!("polygons[{k}].v")));
        for (h, hole) in polygon.holes.iter().enumerate() {
            out.push((hole.iter().collect(), format!("polygons[{k}].holes[{h}]")));
        }
    }
    Ok(out)
}

/// The scene drawn into one ab_glyph `Rasterizer` and quantized.
fn render(scene: &Scene) -> Result<Drawn, String> {
    let triangles = scene.triangles();
    let contours = contours(scene, &triangles)?;
    // The columns the rasterizer must hold: the canvas's and every point's.
    let (mut lo, mut hi) = (0i64, i64::from(scene.width));
    for p in contours.iter().flat_map(|(c, _)| c.iter()) {
        let floor = p.x.floor().to_integer().to_i64();
        let ceil = p.x.ceil().to_integer().to_i64();
        match (floor, ceil) {
            (Some(f), Some(c)) => (lo, hi) = (lo.min(f), hi.max(c)),
            _ => return Err(format!("a point at x = {}: beyond any f32 rasterizer", p.x)),
        }
    }
    let width = hi - lo;
    let cells = u64::try_from(width)
        .unwrap_or(u64::MAX)
        .saturating_mul(u64::from(scene.height));
    if cells > MAX_CELLS {
        return Err(format!(
            "the shapes span columns {lo}..{hi}: a rasterizer of {width} x {} cells (more than 2^28) is refused",
            scene.height
        ));
    }
    let shift = BigRational::from_integer((-lo).into());
    let (w, h) = (
        usize::try_from(width).map_err(|_| "internal: a negative width")?,
        scene.height as usize,
    );
    let mut rasterizer = Rasterizer::new(w, h);
    let mut inexact = 0;
    for (contour, what) in &contours {
        let mut points = Vec::with_capacity(contour.len());
        for (k, p) in contour.iter().enumerate() {
            let moved = Point::new(&p.x + &shift, p.y.clone());
            let v = moved
                .to_f32()
                .ok_or_else(|| format!("{what}[{k}]: {moved} does not fit f32 (ab_glyph's coordinate type)"))?;
            for (exact, rounded) in [(&moved.x, v.x), (&moved.y, v.y)] {
                if BigRational::from_float(rounded).as_ref() != Some(exact) {
                    inexact += 1;
                }
            }
            points.push(point(v.x, v.y));
        }
        for (k, &a) in points.iter().enumerate() {
            rasterizer.draw_line(a, points[(k + 1) % points.len()]);
        }
    }
    let x0 = usize::try_from(-lo).map_err(|_| "internal: a positive left column")?;
    let canvas_width = scene.width as usize;
    let mut levels = vec![0u16; canvas_width * h];
    let (mut above_one, mut largest) = (0, 0f32);
    rasterizer.for_each_pixel(|index, a| {
        let (x, y) = (index % w, index / w);
        if x < x0 || x - x0 >= canvas_width {
            return;
        }
        if a > 1.0 {
            above_one += 1;
        }
        largest = largest.max(a);
        levels[y * canvas_width + x - x0] = level(a);
    });
    Ok(Drawn {
        levels,
        inexact,
        above_one,
        largest,
    })
}

/// `round(min(a, 1) x 65535)`, ties to even: exact, since an f32 times 65535 needs at
/// most 24 + 16 bits of an f64's 53.
#[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
fn level(a: f32) -> u16 {
    let clamped = f64::from(a.clamp(0.0, 1.0));
    (clamped * 65535.0).round_ties_even() as u16
}
