//! tiny-skia adapter: renders a rasterproof scene with tiny-skia's non-anti-aliased path
//! fill and writes the ids PNG (`render --ids-out`'s layout), so that `rasterproof compare
//! SCENE.json OUT.png --as ids` and `hunt --cmd` can judge tiny-skia.
//!
//! ```sh
//! cargo run --release --example tiny-skia-adapter -- SCENE.json OUT.png
//! target/debug/rasterproof compare SCENE.json OUT.png --as ids
//! target/debug/rasterproof hunt --serve 'target/release/examples/tiny-skia-adapter --serve'
//! ```
//!
//! With `--serve` it stays alive and takes one scene per line on stdin (the stay-alive
//! protocol of `rasterproof::oracle::renderer::stay_alive`), through `rasterproof::oracle::renderer::adapter`.
//!
//! What it draws, in id order (triangles, lines, polygons): the last writer wins a pixel,
//! so it holds the highest id + 1 of the primitives that cover it, with alpha 254 where two
//! or more did (the ids PNG's "several owners" mark; the adapter draws every primitive a
//! second time into a count pixmap with `BlendMode::Plus` and alpha 1/255 to know):
//!
//! - **triangles**: a closed three-point path, `FillRule::Winding`;
//! - **polygons**: the scene judges every contour on its own, under the polygon's fill rule
//!   (`nonzero` = `Winding`, `even-odd` = `EvenOdd`): a sample is inside when the outline
//!   holds it and none of the holes does. So the adapter fills the outline and each hole
//!   into its own tiny-skia `Mask` (tiny-skia's raster of each contour), keeps the pixels
//!   the outline's mask covers and no hole's mask does (and the clip window's mask, if
//!   any), and fills the canvas through that mask. (One path of all the contours would add
//!   their winding numbers instead: a hole reaching outside the outline would be filled
//!   there, two overlapping holes would cancel under `even-odd`.)
//! - **lines**: a hairline (`Stroke { width: 0, .. }`, butt caps): a diamond-exit line from
//!   `from` to `to` as written, a Bresenham line (pixel addresses) from the centre of its
//!   first pixel to the centre of its last. tiny-skia's hairline is its own DDA (one pixel
//!   per major-axis column whose centre lies in `[round(start), round(end))`), so expect
//!   `line-rule` differences;
//! - **clip windows** (`clip`): the window's outline filled into a tiny-skia `Mask` (non
//!   anti-aliased, so tiny-skia's own raster of the window), passed to every fill and
//!   stroke;
//! - **clip-space triangles**: refused (exit 2): tiny-skia has no clip space.
//!
//! Each primitive is filled with `anti_alias = false`, `BlendMode::Source` and the colour
//! that encodes id + 1 (R the low byte, G, B the high byte, alpha 255; tiny-skia stores
//! premultiplied colour, which equals it at alpha 255), into a `Pixmap` of
//! the canvas (transparent black = uncovered), in window coordinates: tiny-skia is y down
//! with the origin at the top left, as rasterproof is, so nothing is flipped.
//!
//! Coordinates: tiny-skia takes `f32`, so every exact coordinate is rounded once to the
//! nearest `f32` (`Point::to_f32`). Scenes should use f32-exact coordinates (`hunt
//! --float32-exact` generates them); the adapter says on stderr how many were not, and
//! a coordinate outside the f32 range is refused (exit 2).
//!
//! With `--grey` first (`tiny-skia-adapter --grey SCENE.json OUT.png`, `--grey --serve`)
//! it draws anti-aliased area coverage instead, as an 8-bit grey PNG for `compare --as
//! grey` (see `render_grey`).
//!
//! Exit status: 0 when the PNG was written, 2 with one line on stderr otherwise (bad
//! arguments, an unreadable or invalid scene, a refused primitive, an unwritable output);
//! under `--serve` each of these is an `"ok": false` answer instead.

#![warn(clippy::cast_possible_truncation, clippy::cast_possible_wrap)]

use std::process::ExitCode;

use num_rational::BigRational;
use num_traits::Zero;
use rasterproof::geom::{FillRule, Point};
use rasterproof::line::LineRule;
use rasterproof::oracle::renderer::adapter::adapter_main;
use rasterproof::scene::Scene;
use tiny_skia::{BlendMode, Mask, Paint, Path, PathBuilder, Pixmap, Stroke, Transform};

/// The name every message starts with.
const NAME: &str = "tiny-skia-adapter";

/// The largest id + 1 the 24 bits of an ids PNG hold.
const MAX_ENCODED: u32 = (1 << 24) - 1;

fn main() -> ExitCode {
    let mut args: Vec<std::ffi::OsString> = std::env::args_os().skip(1).collect();
    let grey = args.first().is_some_and(|a| a == "--grey");
    if grey {
        args.remove(0);
    }
    adapter_main(NAME, args, |scene| {
        let mut converter = Converter::default();
        let image: image::DynamicImage = if grey {
            let levels = render_grey(scene, &mut converter)?;
            image::GrayImage::from_raw(scene.width, scene.height, levels)
                .ok_or_else(|| "internal: the pixmap's size does not match its data".to_string())?
                .into()
        } else {
            let rgba = render(scene, &mut converter)?;
            image::RgbaImage::from_raw(scene.width, scene.height, rgba)
                .ok_or_else(|| "internal: the pixmap's size does not match its data".to_string())?
                .into()
        };
        if converter.inexact > 0 {
            eprintln!(
                "{NAME}: note: {} coordinate(s) are not f32-exact; rounded to the nearest f32",
                converter.inexact
            );
        }
        Ok(image)
    })
}

/// `--grey`: every triangle and polygon filled anti-aliased (`anti_alias = true`), opaque
/// white, `BlendMode::SourceOver`, in id order, onto a transparent pixmap; the grey level
/// is the pixmap's alpha. A polygon is one path of its outline and holes under its fill
/// rule (as a vector renderer draws a glyph). Lines, clip windows and clip-space
/// triangles are refused.
fn render_grey(scene: &Scene, converter: &mut Converter) -> Result<Vec<u8>, String> {
    if !scene.lines.is_empty() || scene.clip.is_some() || !scene.clip_space_triangles.is_empty() {
        return Err("--grey draws triangles and polygons only (no lines, clip window or clip-space triangles)".into());
    }
    let mut pixmap = Pixmap::new(scene.width, scene.height)
        .ok_or_else(|| format!("tiny-skia cannot allocate a {}x{} pixmap", scene.width, scene.height))?;
    let mut paint = Paint::default();
    paint.set_color_rgba8(255, 255, 255, 255);
    paint.anti_alias = true;
    paint.blend_mode = BlendMode::SourceOver;
    let mut paths = Vec::new();
    for (k, t) in scene.triangles().iter().enumerate() {
        let path = converter.closed_path([(t.v.iter().collect(), format!("triangles[{k}].v"))])?;
        paths.push(path.map(|p| (p, tiny_skia::FillRule::Winding)));
    }
    for (k, polygon) in scene.polygons.iter().enumerate() {
        let rule = match polygon.fill_rule {
            FillRule::NonZero => tiny_skia::FillRule::Winding,
            FillRule::EvenOdd => tiny_skia::FillRule::EvenOdd,
        };
        let contours = std::iter::once((polygon.outline.iter().collect(), format!("polygons[{k}].v"))).chain(
            polygon
                .holes
                .iter()
                .enumerate()
                .map(|(h, hole)| (hole.iter().collect(), format!("polygons[{k}].holes[{h}]"))),
        );
        paths.push(converter.closed_path(contours)?.map(|p| (p, rule)));
    }
    for (path, rule) in paths.iter().flatten() {
        pixmap.fill_path(path, &paint, *rule, Transform::identity(), None);
    }
    Ok(pixmap.data().chunks_exact(4).map(|p| p[3]).collect())
}

/// Exact coordinates to tiny-skia's f32, counting those that did not fit exactly.
#[derive(Default)]
struct Converter {
    /// Coordinates that were rounded.
    inexact: usize,
}

impl Converter {
    /// `p` moved by `(offset, offset)`, rounded once to the nearest f32 per axis.
    fn point(&mut self, p: &Point, offset: &BigRational, what: &str) -> Result<(f32, f32), String> {
        let moved = Point::new(&p.x + offset, &p.y + offset);
        let v = moved
            .to_f32()
            .ok_or_else(|| format!("{what}: {moved} does not fit f32 (tiny-skia's coordinate type)"))?;
        for (exact, rounded) in [(&moved.x, v.x), (&moved.y, v.y)] {
            if BigRational::from_float(rounded).as_ref() != Some(exact) {
                self.inexact += 1;
            }
        }
        Ok((v.x, v.y))
    }

    /// A path of closed contours (each at least three points).
    fn closed_path<'a>(
        &mut self,
        contours: impl IntoIterator<Item = (Vec<&'a Point>, String)>,
    ) -> Result<Option<Path>, String> {
        let zero = BigRational::zero();
        let mut builder = PathBuilder::new();
        for (contour, what) in contours {
            for (k, p) in contour.iter().enumerate() {
                let (x, y) = self.point(p, &zero, &format!("{what}[{k}]"))?;
                if k == 0 {
                    builder.move_to(x, y);
                } else {
                    builder.line_to(x, y);
                }
            }
            builder.close();
        }
        Ok(builder.finish())
    }
}

/// The colour of id + 1: R the low byte, G the middle, B the high byte, alpha 255.
fn id_paint(id: u32) -> Result<Paint<'static>, String> {
    let encoded = id
        .checked_add(1)
        .filter(|&e| e <= MAX_ENCODED)
        .ok_or_else(|| format!("primitive id {id} does not fit the 24 bits of an ids PNG"))?;
    let [r, g, b, _] = encoded.to_le_bytes();
    let mut paint = Paint::default();
    paint.set_color_rgba8(r, g, b, 255);
    paint.anti_alias = false;
    paint.blend_mode = BlendMode::Source;
    Ok(paint)
}

/// What one primitive is to tiny-skia.
enum Shape {
    /// A filled path.
    Fill(Path, tiny_skia::FillRule),
    /// A hairline stroke.
    Hairline(Path),
    /// A polygon with holes: inside the outline and in none of the holes, each contour
    /// filled on its own with the rule.
    Region {
        /// The outline.
        outline: Path,
        /// The holes.
        holes: Vec<Path>,
        /// The polygon's fill rule, for every contour.
        rule: tiny_skia::FillRule,
    },
}

/// The two pixmaps a scene is drawn into: the ids (last writer wins) and the number of
/// primitives that covered each pixel (in the alpha channel, added by `BlendMode::Plus`).
struct Canvas<'m> {
    /// id + 1 per pixel, alpha 255 where covered.
    ids: Pixmap,
    /// The cover count per pixel, in alpha (saturating at 255).
    counts: Pixmap,
    /// The clip window's mask.
    mask: Option<&'m Mask>,
}

impl Canvas<'_> {
    /// Draws `shape` as primitive `id` into both pixmaps.
    fn draw(&mut self, shape: &Shape, id: u32) -> Result<(), String> {
        let paint = id_paint(id)?;
        let mut count = Paint::default();
        count.set_color_rgba8(0, 0, 0, 1);
        count.anti_alias = false;
        count.blend_mode = BlendMode::Plus;
        let identity = Transform::identity();
        let hairline = Stroke {
            width: 0.0,
            ..Stroke::default()
        };
        let region = match shape {
            Shape::Region { outline, holes, rule } => Some(self.region(outline, holes, *rule)?),
            _ => None,
        };
        let (width, height) = (self.ids.width(), self.ids.height());
        for (pixmap, paint) in [(&mut self.ids, &paint), (&mut self.counts, &count)] {
            match shape {
                Shape::Fill(path, rule) => pixmap.fill_path(path, paint, *rule, identity, self.mask),
                Shape::Hairline(path) => pixmap.stroke_path(path, paint, &hairline, identity, self.mask),
                Shape::Region { .. } => {
                    let all = tiny_skia::IntRect::from_xywh(0, 0, width, height)
                        .ok_or("internal: an empty canvas")?
                        .to_rect();
                    // tiny-skia 0.11's fill_rect with `BlendMode::Source` and a mask
                    // clears the pixels the mask leaves out (seen on a 2x1 canvas);
                    // the id paint is opaque, so `SourceOver` through a 0/255 mask
                    // writes exactly the masked pixels. The count paint adds already.
                    let mut paint = paint.clone();
                    if paint.blend_mode == BlendMode::Source {
                        paint.blend_mode = BlendMode::SourceOver;
                    }
                    pixmap.fill_rect(all, &paint, identity, region.as_ref());
                }
            }
        }
        Ok(())
    }

    /// The mask of a polygon with holes: 255 where tiny-skia's fill of the outline covers
    /// the pixel, its fill of no hole does, and the clip window's mask (if any) does; else 0.
    fn region(&self, outline: &Path, holes: &[Path], rule: tiny_skia::FillRule) -> Result<Mask, String> {
        let (width, height) = (self.ids.width(), self.ids.height());
        let filled = |path: &Path| -> Result<Mask, String> {
            let mut mask =
                Mask::new(width, height).ok_or_else(|| format!("tiny-skia cannot allocate a {width}x{height} mask"))?;
            mask.fill_path(path, rule, false, Transform::identity());
            Ok(mask)
        };
        let mut region = filled(outline)?;
        for hole in holes {
            let hole = filled(hole)?;
            for (r, h) in region.data_mut().iter_mut().zip(hole.data()) {
                if *h != 0 {
                    *r = 0;
                }
            }
        }
        if let Some(clip) = self.mask {
            for (r, c) in region.data_mut().iter_mut().zip(clip.data()) {
                if *c == 0 {
                    *r = 0;
                }
            }
        }
        for r in region.data_mut() {
            if *r != 0 {
                *r = 255;
            }
        }
        Ok(region)
    }

    /// The ids PNG's bytes: alpha 254 where two or more primitives covered the pixel.
    fn into_ids_rgba(self) -> Vec<u8> {
        let mut ids = self.ids.take();
        for (pixel, count) in ids.chunks_exact_mut(4).zip(self.counts.data().chunks_exact(4)) {
            if count[3] >= 2 {
                pixel[3] = 254;
            }
        }
        ids
    }
}

/// The shapes of `scene`, in id order (triangles, lines, polygons); `None` for a primitive
/// tiny-skia gets no path for (fewer than two distinct points).
fn shapes(scene: &Scene, converter: &mut Converter) -> Result<Vec<Option<Shape>>, String> {
    if !scene.clip_space_triangles.is_empty() {
        return Err(format!(
            "clip_space_triangles: {} clip-space triangle(s): refused, tiny-skia has no clip space \
             (draw their window-space triangles instead)",
            scene.clip_space_triangles.len()
        ));
    }
    let mut shapes = Vec::new();
    for (k, t) in scene.triangles().iter().enumerate() {
        let contour = t.v.iter().collect();
        let path = converter.closed_path([(contour, format!("triangles[{k}].v"))])?;
        shapes.push(path.map(|p| Shape::Fill(p, tiny_skia::FillRule::Winding)));
    }

    let half = BigRational::new(1.into(), 2.into());
    let zero = BigRational::zero();
    for (k, line) in scene.lines.iter().enumerate() {
        // A Bresenham endpoint is a pixel address: its line runs between pixel centres.
        let offset = match line.rule {
            LineRule::Bresenham(_) => &half,
            LineRule::Diamond => &zero,
        };
        let (x0, y0) = converter.point(&line.from, offset, &format!("lines[{k}].from"))?;
        let (x1, y1) = converter.point(&line.to, offset, &format!("lines[{k}].to"))?;
        let mut builder = PathBuilder::new();
        builder.move_to(x0, y0);
        builder.line_to(x1, y1);
        shapes.push(builder.finish().map(Shape::Hairline));
    }

    for (k, polygon) in scene.polygons.iter().enumerate() {
        let rule = match polygon.fill_rule {
            FillRule::NonZero => tiny_skia::FillRule::Winding,
            FillRule::EvenOdd => tiny_skia::FillRule::EvenOdd,
        };
        let outline = converter.closed_path([(polygon.outline.iter().collect(), format!("polygons[{k}].v"))])?;
        let Some(outline) = outline else {
            shapes.push(None);
            continue;
        };
        let mut holes = Vec::new();
        for (h, hole) in polygon.holes.iter().enumerate() {
            if let Some(path) = converter.closed_path([(hole.iter().collect(), format!("polygons[{k}].holes[{h}]"))])? {
                holes.push(path);
            }
        }
        shapes.push(Some(if holes.is_empty() {
            Shape::Fill(outline, rule)
        } else {
            Shape::Region { outline, holes, rule }
        }));
    }
    Ok(shapes)
}

/// Renders every primitive of `scene` in id order; returns the ids PNG's RGBA bytes.
fn render(scene: &Scene, converter: &mut Converter) -> Result<Vec<u8>, String> {
    let shapes = shapes(scene, converter)?;
    let pixmap = || {
        Pixmap::new(scene.width, scene.height)
            .ok_or_else(|| format!("tiny-skia cannot allocate a {}x{} pixmap", scene.width, scene.height))
    };
    let mask = clip_mask(scene, converter)?;
    let mut canvas = Canvas {
        ids: pixmap()?,
        counts: pixmap()?,
        mask: mask.as_ref(),
    };
    for (id, shape) in shapes.iter().enumerate() {
        let id = u32::try_from(id).map_err(|_| "more primitives than u32 ids".to_string())?;
        if let Some(shape) = shape {
            canvas.draw(shape, id)?;
        }
    }
    Ok(canvas.into_ids_rgba())
}

/// The scene's clip window as a tiny-skia mask (its outline filled without anti-aliasing),
/// or `None` without a window.
fn clip_mask(scene: &Scene, converter: &mut Converter) -> Result<Option<Mask>, String> {
    let Some(window) = &scene.clip else {
        return Ok(None);
    };
    let mut mask = Mask::new(scene.width, scene.height)
        .ok_or_else(|| format!("tiny-skia cannot allocate a {}x{} mask", scene.width, scene.height))?;
    let outline = window.outline();
    if let Some(path) = converter.closed_path([(outline.iter().collect(), "clip".to_string())])? {
        mask.fill_path(&path, tiny_skia::FillRule::Winding, false, Transform::identity());
    }
    Ok(Some(mask))
}
