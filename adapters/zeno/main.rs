//! zeno adapter: renders a rasterproof scene with `zeno` 0.3.3's mask rasterizer (a port of
//! FreeType's smooth rasterizer, `ftgrays.c`, to Rust: 24.8 cells, 8-bit levels) and
//! writes zeno's **8-bit alpha mask as a grey PNG**, so that `rasterproof compare
//! SCENE.json OUT.png --as grey` (and `hunt` through `--serve`) can judge it against the
//! exact area coverage.
//!
//! ```sh
//! cargo run --release --example zeno-adapter -- SCENE.json OUT.png
//! target/release/rasterproof compare SCENE.json OUT.png --as grey --semantics accumulated --quantization ftgrays
//! target/release/examples/zeno-adapter --serve
//! ```
//!
//! With `--serve` it stays alive and takes one scene per line on stdin (the stay-alive
//! protocol of `rasterproof::oracle::renderer::stay_alive`), through `rasterproof::oracle::renderer::adapter`.
//!
//! What it draws: **one path** of every shape, in id order: each triangle a `MoveTo`, two
//! `LineTo`s and a `Close`; each polygon its outline and each hole (as written: the
//! contours of one glyph) the same way. The path is filled by
//! `Mask::new(&path).size(width, height).style(fill).render()` under the scene's rule:
//! `Fill::NonZero` for triangles and nonzero polygons, `Fill::EvenOdd` for even-odd
//! polygons; a scene that mixes the two rules is **refused** (exit 2: one path has one
//! rule). zeno accumulates the path's signed area as FreeType does, so the winding numbers
//! of all the contours add: a hole is a hole where it runs against its outline (as glyph
//! counters do), overlapping shapes add before the rule folds them (nonzero: clamped to
//! 255; even-odd: reflected).
//!
//! Lines, clip windows (`clip`) and clip-space triangles are refused (exit 2); `viewport`
//! (which only places clip-space triangles) is ignored.
//!
//! How y maps: zeno's default `Origin::TopLeft` is y down with the origin at the top left,
//! as rasterproof's canvas is, so nothing is flipped. With an explicit `size` zeno does not
//! move the path to its bounds (no `offset`, no `render_offset`): the mask's `Placement`
//! is `left = 0, top = 0`, so pixel (x, y) of the mask is pixel (x, y) of the canvas (a
//! unit square at (2, 3)-(3, 4) lights pixel (2, 3) alone, at 255).
//!
//! Coordinates: zeno takes `f32`; every exact coordinate is rounded once to the nearest
//! `f32` (`Point::to_f32`; the adapter says on stderr how many were not f32-exact), and
//! zeno itself then truncates `256 v` towards zero to its 24.8 fixed point. Its
//! arithmetic is i32 (and that conversion undefined beyond the i32 range), so a
//! coordinate of magnitude 4096 px or more is refused: below it no product of its edge walk
//! (`dx x 256` and sums of four such terms) leaves i32.
//!
//! Quantization: zeno's own 8-bit alpha, as is: FreeType's levels (`coverage >> 9`, a
//! negative value complemented by `~`, 256 clamped to 255 for nonzero, `& 511` reflected
//! for even-odd), closest to the crate's `ftgrays` quantization.
//!
//! Exit status: 0 when the PNG was written, 2 with one line on stderr otherwise (bad
//! arguments, an unreadable or invalid scene, a refused primitive, an unwritable output);
//! under `--serve` each of these is an `"ok": false` answer instead.

#![warn(clippy::cast_possible_truncation, clippy::cast_possible_wrap)]

use std::process::ExitCode;

use num_rational::BigRational;
use rasterproof::geom::{FillRule, Point, Triangle};
use rasterproof::oracle::renderer::adapter::adapter_main;
use rasterproof::scene::Scene;
use zeno::{Command, Fill, Mask};

/// A contour's exact points and its name in messages (`polygons[2].holes[0]`).
type Contour<'a> = (Vec<&'a Point>, String);

/// The name every message starts with.
const NAME: &str = "zeno-adapter";

/// The largest coordinate magnitude zeno's i32 edge walk is given (exclusive), in px.
const LIMIT: f32 = 4096.0;

fn main() -> ExitCode {
    adapter_main(NAME, std::env::args_os().skip(1).collect(), |scene| {
        let (levels, inexact) = render(scene)?;
        if inexact > 0 {
            eprintln!("{NAME}: note: {inexact} coordinate(s) are not f32-exact; rounded to the nearest f32");
        }
        image::GrayImage::from_raw(scene.width, scene.height, levels)
            .ok_or_else(|| "internal: zeno's mask does not match the canvas".to_string())
    })
}

/// The scene's contours, each a list of exact points named for messages, and the one
/// fill rule they are filled under; `triangles` are the scene's, read exactly.
fn contours<'a>(scene: &'a Scene, triangles: &'a [Triangle]) -> Result<(Vec<Contour<'a>>, Fill), String> {
    if !scene.lines.is_empty() {
        return Err(format!(
            "lines: {} line(s): refused, this adapter draws area coverage of triangles and polygons only",
            scene.lines.len()
        ));
    }
    if scene.clip.is_some() {
        return Err("clip: refused, this adapter draws no clip window".into());
    }
    if !scene.clip_space_triangles.is_empty() {
        return Err(format!(
            "clip_space_triangles: {} clip-space triangle(s): refused, zeno has no clip space",
            scene.clip_space_triangles.len()
        ));
    }
    let mut rules = scene.polygons.iter().map(|p| p.fill_rule).collect::<Vec<_>>();
    if !scene.triangles.is_empty() {
        rules.push(FillRule::NonZero);
    }
    let fill = match (rules.contains(&FillRule::NonZero), rules.contains(&FillRule::EvenOdd)) {
        (true, true) => {
            return Err(
                "the scene mixes nonzero shapes (triangles or polygons) and even-odd polygons: refused, \
                 this adapter fills one zeno path under one rule"
                    .into(),
            )
        }
        (false, true) => Fill::EvenOdd,
        _ => Fill::NonZero,
    };
    let mut out = Vec::new();
    for (k, t) in triangles.iter().enumerate() {
        out.push((t.v.iter().collect(), format!("triangles[{k}].v")));
    }
    for (k, polygon) in scene.polygons.iter().enumerate() {
        out.push((polygon.outline.iter().collect(), format!("polygons[{k}].v")));
        for (h, hole) in polygon.holes.iter().enumerate() {
            out.push((hole.iter().collect(), format!("polygons[{k}].holes[{h}]")));
        }
    }
    Ok((out, fill))
}

/// zeno's mask of the scene, row by row, and how many coordinates were not f32-exact.
fn render(scene: &Scene) -> Result<(Vec<u8>, usize), String> {
    let triangles = scene.triangles();
    let (contours, fill) = contours(scene, &triangles)?;
    let mut path = Vec::new();
    let mut inexact = 0;
    for (contour, what) in &contours {
        for (k, p) in contour.iter().enumerate() {
            let v = p
                .to_f32()
                .filter(|v| v.x.abs() < LIMIT && v.y.abs() < LIMIT)
                .ok_or_else(|| {
                    format!("{what}[{k}]: {p}: refused, zeno's i32 edge walk takes coordinates within ±{LIMIT} px")
                })?;
            for (exact, rounded) in [(&p.x, v.x), (&p.y, v.y)] {
                if BigRational::from_float(rounded).as_ref() != Some(exact) {
                    inexact += 1;
                }
            }
            let to = zeno::Point::new(v.x, v.y);
            path.push(if k == 0 {
                Command::MoveTo(to)
            } else {
                Command::LineTo(to)
            });
        }
        path.push(Command::Close);
    }
    let (mask, placement) = Mask::new(&path).size(scene.width, scene.height).style(fill).render();
    if (placement.left, placement.top, placement.width, placement.height) != (0, 0, scene.width, scene.height) {
        return Err(format!(
            "internal: zeno placed the mask at ({}, {}) with size {}x{}, not on the canvas",
            placement.left, placement.top, placement.width, placement.height
        ));
    }
    Ok((mask, inexact))
}
