//! The trade's pictures, drawn with plotters as PNG and SVG: (a) speed against error per
//! workload with the Pareto front, (b) error against coordinate magnitude, one line per
//! contender, each for the binary models' workloads and again for the area family's (all
//! in `charts`), and for the values family against canvas offset and attribute scale
//! (`values`), (c) the predicate map (`map`). Text is drawn with DejaVu
//! Sans, compiled in from `assets/fonts/` (its licence beside it), so no system font
//! library is needed. [`TradeReport::pictures`] draws them all.

mod charts;
mod map;
mod values;

use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::report::{Axis, TradeReport, WorkloadReport};

/// DejaVu Sans 2.37 (Debian's fonts-dejavu-core; licence: assets/fonts/LICENSE-DejaVu.txt).
static FONT: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");

/// The family name the pictures use.
const SANS: &str = "sans-serif";

/// Registers the font once.
fn font() -> Result<(), String> {
    static DONE: OnceLock<bool> = OnceLock::new();
    let ok = *DONE.get_or_init(|| plotters::style::register_font(SANS, FontStyle::Normal, FONT).is_ok());
    ok.then_some(())
        .ok_or_else(|| "the compiled-in font cannot be read".into())
}

/// One picture file: its name in the output folder and its bytes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Picture {
    /// `speed-vs-error.png`, `error-vs-magnitude.svg`, ...
    pub name: String,
    /// The file's content.
    pub bytes: Vec<u8>,
}

type Area<DB> = DrawingArea<DB, Shift>;

fn err(e: impl std::fmt::Display) -> String {
    format!("drawing a picture: {e}")
}

/// Draws `f` into a PNG of `w` x `h`.
fn png(w: u32, h: u32, f: impl FnOnce(&Area<BitMapBackend<'_>>) -> Result<(), String>) -> Result<Vec<u8>, String> {
    let len = usize::try_from(u64::from(w) * u64::from(h) * 3).map_err(err)?;
    let mut buf = vec![0u8; len];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        f(&root)?;
        root.present().map_err(err)?;
    }
    use image::codecs::png::{CompressionType, FilterType, PngEncoder};
    use image::ImageEncoder as _;
    let mut out = Vec::new();
    PngEncoder::new_with_quality(&mut out, CompressionType::Best, FilterType::Adaptive)
        .write_image(&buf, w, h, image::ExtendedColorType::Rgb8)
        .map_err(err)?;
    Ok(out)
}

/// Draws `f` into an SVG of `w` x `h`.
fn svg(w: u32, h: u32, f: impl FnOnce(&Area<SVGBackend<'_>>) -> Result<(), String>) -> Result<Vec<u8>, String> {
    let mut s = String::new();
    {
        let root = SVGBackend::with_string(&mut s, (w, h)).into_drawing_area();
        f(&root)?;
        root.present().map_err(err)?;
    }
    Ok(s.into_bytes())
}

/// The colour of a contender, the same in every picture: blues for the exact models,
/// oranges and browns for the integer ones, red for f32, purple for f64 (lighter:
/// naive); the area contenders alike (`ftgrays` orange, supersampling purple, tiny-skia
/// pink); the values contenders alike (the vertex plane teal, barycentrics pink, the
/// fixed-point DDA brown).
fn colour(name: &str) -> RGBColor {
    match name {
        "exact-plain" => RGBColor(8, 48, 107),
        "exact" | "cohen-sutherland" | "sutherland-hodgman" => RGBColor(33, 113, 181),
        "exact-snapped-plain" => RGBColor(0, 109, 44),
        "exact-snapped" => RGBColor(65, 171, 93),
        "fixed" | "bresenham/stay" => RGBColor(230, 120, 0),
        "scanline" | "bresenham/step" => RGBColor(140, 81, 10),
        "float32" | "dda32" | "cs-f32" | "sh-f32" => RGBColor(215, 25, 28),
        "float64" | "dda64" | "cs-f64" | "sh-f64" => RGBColor(117, 50, 160),
        "float32-naive" => RGBColor(247, 129, 191),
        "float64-naive" => RGBColor(150, 150, 150),
        "area-plain" => RGBColor(8, 48, 107),
        "area-cells" => RGBColor(0, 109, 44),
        "area-planned" => RGBColor(33, 113, 181),
        "f32-accum" => RGBColor(215, 25, 28),
        "ftgrays" => RGBColor(230, 120, 0),
        "supersample-4x4" => RGBColor(117, 50, 160),
        "tiny-skia-4x4" => RGBColor(247, 129, 191),
        "msaa-4x" => RGBColor(161, 217, 155),
        "msaa-8x" => RGBColor(65, 171, 93),
        "msaa-16x" => RGBColor(0, 90, 50),
        "planned" => RGBColor(33, 113, 181),
        "f32-origin-plane" => RGBColor(215, 25, 28),
        "f32-vertex-plane" => RGBColor(0, 139, 139),
        "f32-barycentric" => RGBColor(247, 129, 191),
        "f64-origin-plane" => RGBColor(117, 50, 160),
        "dda-q32.32" => RGBColor(140, 81, 10),
        _ => RGBColor(0, 0, 0),
    }
}

/// Every contender of `workloads`, in first-seen order, with whether it is exact.
fn contenders(workloads: &[&WorkloadReport]) -> Vec<(String, bool)> {
    let mut out: Vec<(String, bool)> = Vec::new();
    for w in workloads {
        for s in &w.speed {
            if !out.iter().any(|(n, _)| *n == s.contender) {
                out.push((s.contender.clone(), s.exact));
            }
        }
    }
    out
}

/// A picture's frame, filled white: `title` (at `size` points) across the top, a grid of
/// `rows` x `cols` panels, and the bottom 150 px, for the legend.
fn frame<DB: DrawingBackend>(
    root: &Area<DB>,
    title: &str,
    size: u32,
    (rows, cols): (usize, usize),
) -> Result<(Vec<Area<DB>>, Area<DB>), String> {
    root.fill(&WHITE).map_err(err)?;
    let (_, h) = root.dim_in_pixel();
    let (top, rest) = root.split_vertically(56);
    top.titled(title, (SANS, size)).map_err(err)?;
    let (grid, bottom) = rest.split_vertically(h - 56 - 150);
    Ok((grid.split_evenly((rows, cols)), bottom))
}

/// Draws a legend: one marker and name per entry, in rows of `per_row`.
fn legend<DB: DrawingBackend>(
    area: &Area<DB>,
    entries: &[(String, RGBColor, bool)],
    per_row: usize,
    note: &str,
) -> Result<(), String> {
    let (w, _) = area.dim_in_pixel();
    let col = i32::try_from(w).map_err(err)? / i32::try_from(per_row.max(1)).map_err(err)?;
    let text = (SANS, 17).into_font();
    for (k, (name, c, exact)) in entries.iter().enumerate() {
        let (row, column) = (k / per_row, k % per_row);
        let x = 20 + i32::try_from(column).map_err(err)? * col;
        let y = 16 + i32::try_from(row).map_err(err)? * 26;
        if *exact {
            area.draw(&Circle::new((x, y), 7, c.filled())).map_err(err)?;
        } else {
            area.draw(&TriangleMarker::new((x, y), 9, c.filled())).map_err(err)?;
        }
        area.draw(&Text::new(name.clone(), (x + 14, y - 9), text.clone()))
            .map_err(err)?;
    }
    let rows = i32::try_from(entries.len().div_ceil(per_row.max(1))).map_err(err)?;
    for (k, line) in note.lines().enumerate() {
        let y = 10 + rows * 26 + i32::try_from(k).map_err(err)? * 22;
        area.draw(&Text::new(line.to_string(), (20, y), (SANS, 16).into_font()))
            .map_err(err)?;
    }
    Ok(())
}

fn legend_entries(workloads: &[&WorkloadReport]) -> Vec<(String, RGBColor, bool)> {
    contenders(workloads)
        .into_iter()
        .map(|(n, e)| (n.clone(), colour(&n), e))
        .collect()
}

impl TradeReport {
    /// The pictures, PNG and SVG: `speed-vs-error`, `error-vs-magnitude` (the binary
    /// models' workloads), `area-speed-vs-error`, `area-error-vs-magnitude` (the area
    /// family's), `values-error-vs-offset`, `values-error-vs-scale`,
    /// `values-speed-vs-error` (the values family's), `predicate-map` (see the module docs
    /// of [`crate::trade`]).
    ///
    /// # Errors
    /// Drawing fails (the compiled-in font unreadable, an encoder error).
    pub fn pictures(&self) -> Result<Vec<Picture>, String> {
        font()?;
        let (w, h) = (1800, 1400);
        let mut out = Vec::new();
        let mut push = |name: &str, bytes| {
            out.push(Picture {
                name: name.into(),
                bytes,
            });
        };
        push(
            "speed-vs-error.png",
            png(w, h, |a| charts::speed_error(a, self, false))?,
        );
        push(
            "speed-vs-error.svg",
            svg(w, h, |a| charts::speed_error(a, self, false))?,
        );
        push(
            "error-vs-magnitude.png",
            png(w, h, |a| charts::error_magnitude(a, self))?,
        );
        push(
            "error-vs-magnitude.svg",
            svg(w, h, |a| charts::error_magnitude(a, self))?,
        );
        push(
            "area-speed-vs-error.png",
            png(w, 1100, |a| charts::speed_error(a, self, true))?,
        );
        push(
            "area-speed-vs-error.svg",
            svg(w, 1100, |a| charts::speed_error(a, self, true))?,
        );
        let (aw, ah) = (2400, 1200);
        push(
            "area-error-vs-magnitude.png",
            png(aw, ah, |a| charts::area_error_magnitude(a, self))?,
        );
        push(
            "area-error-vs-magnitude.svg",
            svg(aw, ah, |a| charts::area_error_magnitude(a, self))?,
        );
        let (vw, vh) = (2400, 1700);
        push(
            "values-error-vs-offset.png",
            png(vw, vh, |a| values::error_by(a, self, Axis::Offset))?,
        );
        push(
            "values-error-vs-offset.svg",
            svg(vw, vh, |a| values::error_by(a, self, Axis::Offset))?,
        );
        push(
            "values-error-vs-scale.png",
            png(1800, vh, |a| values::error_by(a, self, Axis::AttributeScale))?,
        );
        push(
            "values-error-vs-scale.svg",
            svg(1800, vh, |a| values::error_by(a, self, Axis::AttributeScale))?,
        );
        push(
            "values-speed-vs-error.png",
            png(vw, 1300, |a| values::speed_error(a, self))?,
        );
        push(
            "values-speed-vs-error.svg",
            svg(vw, 1300, |a| values::speed_error(a, self))?,
        );
        let (mw, mh) = (1300, 1360);
        push(
            "predicate-map.png",
            png(mw, mh, |a| map::predicate_map(a, &self.predicate_map))?,
        );
        push(
            "predicate-map.svg",
            svg(mw, mh, |a| map::predicate_map(a, &self.predicate_map))?,
        );
        Ok(out)
    }
}
