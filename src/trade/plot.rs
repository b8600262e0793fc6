//! The trade's pictures, drawn with plotters as PNG and SVG: (a) speed against error per
//! workload with the Pareto front, (b) error against coordinate magnitude, one line per
//! contender, (c) the predicate map. Text is drawn with DejaVu Sans, compiled in from
//! `assets/fonts/` (its licence beside it), so no system font library is needed.

use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::predicate_map::{Decision, PredicateMap};
use super::report::{Outcome, Report, SpeedOutcome, WorkloadReport};
use super::Magnitude;

/// DejaVu Sans 2.37 (Debian's fonts-dejavu-core; licence: assets/fonts/LICENSE-DejaVu.txt).
static FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

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
/// naive).
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
        _ => RGBColor(0, 0, 0),
    }
}

/// Every contender of the report, in first-seen order, with whether it is exact.
fn contenders(r: &Report) -> Vec<(String, bool)> {
    let mut out: Vec<(String, bool)> = Vec::new();
    for w in &r.workloads {
        for s in &w.speed {
            if !out.iter().any(|(n, _)| *n == s.contender) {
                out.push((s.contender.clone(), s.exact));
            }
        }
    }
    out
}

/// A rate of 0 is drawn here, on the tick labelled `0`.
const ZERO: f64 = 0.1;
/// Non-zero rates below it are drawn at it, so that none sits on the `0` line.
const SMALLEST: f64 = 0.2;
/// The log axes' ends (per million).
const BOTTOM: f64 = 0.06;
const TOP: f64 = 4e6;

fn rate_label(v: f64) -> String {
    if (v - ZERO).abs() < 1e-9 {
        "0".into()
    } else if v < ZERO {
        String::new()
    } else if v >= 1.0 {
        format!("{v:.0}")
    } else {
        format!("{v}")
    }
}

fn speed_label(v: f64) -> String {
    if v >= 1.0 {
        format!("{v:.0}")
    } else {
        format!("{v:.1e}")
    }
}

/// A workload's headline rate per million at `m` for `contender` (`None`: refused or
/// not run).
fn headline(w: &WorkloadReport, contender: &str, m: Magnitude) -> Option<f64> {
    let c = w.cell(contender, m)?;
    match &c.outcome {
        Outcome::Refused(_) => None,
        Outcome::Measured { metrics, .. } => {
            let h = metrics.first()?;
            Some(if h.is_zero() {
                ZERO
            } else {
                h.per_million().unwrap_or(0.0).max(SMALLEST)
            })
        }
    }
}

/// The magnitude picture (a) shows: the largest run at or below 2^20 px (fixed's
/// envelope), else the smallest run.
pub(crate) fn speed_error_magnitude(r: &Report) -> Magnitude {
    let limit = 1u64 << 20;
    r.config
        .magnitudes
        .iter()
        .rev()
        .find(|m| m.px() <= limit)
        .or(r.config.magnitudes.first())
        .copied()
        .unwrap_or(Magnitude::DEFAULT[0])
}

fn grid_shape(n: usize) -> (usize, usize) {
    let cols = if n <= 4 { n.max(1) } else { 4 };
    (n.div_ceil(cols).max(1), cols)
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

fn legend_entries(r: &Report) -> Vec<(String, RGBColor, bool)> {
    contenders(r)
        .into_iter()
        .map(|(n, e)| (n.clone(), colour(&n), e))
        .collect()
}

/// Picture (a).
fn speed_error<DB: DrawingBackend>(root: &Area<DB>, r: &Report) -> Result<(), String> {
    root.fill(&WHITE).map_err(err)?;
    let m = speed_error_magnitude(r);
    let (_, h) = root.dim_in_pixel();
    let (top, rest) = root.split_vertically(56);
    top.titled(
        &format!(
            "Speed against error at {m} px from the origin, per workload: each contender a point; ringed and joined \
             in black: the Pareto front"
        ),
        (SANS, 26),
    )
    .map_err(err)?;
    let (grid, bottom) = rest.split_vertically(h - 56 - 150);
    let n = r.workloads.len();
    let (rows, cols) = grid_shape(n);
    let panels = grid.split_evenly((rows, cols));
    for (panel, w) in panels.iter().zip(&r.workloads) {
        let points: Vec<(String, f64, f64, bool)> = w
            .speed
            .iter()
            .filter_map(|s| match s.outcome {
                SpeedOutcome::Measured { median, .. } if median > 0.0 => {
                    Some((s.contender.clone(), median, headline(w, &s.contender, m)?, s.exact))
                }
                _ => None,
            })
            .collect();
        let refused: Vec<&str> = w
            .speed
            .iter()
            .filter(|s| headline(w, &s.contender, m).is_none())
            .map(|s| s.contender.as_str())
            .collect();
        let lo = points.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        let hi = points.iter().map(|p| p.1).fold(0.0, f64::max);
        let (lo, hi) = if lo.is_finite() && hi > 0.0 {
            (lo / 3.0, hi * 3.0)
        } else {
            (1e-3, 1e3)
        };
        let caption = if refused.is_empty() {
            w.name.clone()
        } else {
            format!("{} (refused: {})", w.name, refused.join(", "))
        };
        let mut chart = ChartBuilder::on(panel)
            .caption(caption, (SANS, 16))
            .margin(10)
            .x_label_area_size(44)
            .y_label_area_size(64)
            .build_cartesian_2d((lo..hi).log_scale(), (BOTTOM..TOP).log_scale())
            .map_err(err)?;
        let x_desc = format!("speed, {} (log)", w.unit);
        let first = w
            .cells
            .iter()
            .find_map(|c| c.outcome.headline().map(|h| h.name()))
            .unwrap_or("errors");
        let y_desc = format!("{first} per million");
        chart
            .configure_mesh()
            .x_desc(x_desc)
            .y_desc(y_desc)
            .x_labels(5)
            .y_labels(8)
            .x_label_formatter(&|v| speed_label(*v))
            .y_label_formatter(&|v| rate_label(*v))
            .axis_desc_style((SANS, 14))
            .label_style((SANS, 12))
            .draw()
            .map_err(err)?;
        // The Pareto front: fastest first, keeping each point with less error than every
        // faster one.
        let mut sorted = points.clone();
        sorted.sort_by(|a, b| b.1.total_cmp(&a.1));
        let mut front: Vec<(f64, f64)> = Vec::new();
        for p in &sorted {
            let better = match front.last() {
                None => true,
                Some(&(_, e)) => p.2 < e,
            };
            if better {
                front.push((p.1, p.2));
            }
        }
        let mut steps = Vec::new();
        for (k, &(s, e)) in front.iter().enumerate() {
            if k > 0 {
                steps.push((s, front[k - 1].1));
            }
            steps.push((s, e));
        }
        chart
            .draw_series(LineSeries::new(steps, BLACK.stroke_width(2)))
            .map_err(err)?;
        for &(s, e) in &front {
            chart
                .draw_series(std::iter::once(Circle::new((s, e), 11, BLACK.stroke_width(2))))
                .map_err(err)?;
        }
        for (name, s, e, exact) in &points {
            let c = colour(name);
            if *exact {
                chart.draw_series(std::iter::once(Circle::new((*s, *e), 6, c.filled())))
            } else {
                chart.draw_series(std::iter::once(TriangleMarker::new((*s, *e), 8, c.filled())))
            }
            .map_err(err)?;
        }
    }
    legend(
        &bottom,
        &legend_entries(r),
        6,
        "Circles: exact and integer models; triangles: float models. Speed: drawing the prepared workload at the \
         origin, median of the round-robin repetitions.\nError: per million pixels the exact answer covers (lines: \
         line pixels; clipping: output vertices); 0 is exactly zero. A refused contender is not drawn.",
    )
}

/// Picture (b).
fn error_magnitude<DB: DrawingBackend>(root: &Area<DB>, r: &Report) -> Result<(), String> {
    root.fill(&WHITE).map_err(err)?;
    let (_, h) = root.dim_in_pixel();
    let (top, rest) = root.split_vertically(56);
    top.titled(
        "Error against coordinate magnitude (the window at M px from the origin), one line per contender",
        (SANS, 26),
    )
    .map_err(err)?;
    let (grid, bottom) = rest.split_vertically(h - 56 - 150);
    let mags = r.config.magnitudes.clone();
    let labels: Vec<String> = mags.iter().map(|m| m.label()).collect();
    let n = mags.len();
    let (rows, cols) = grid_shape(r.workloads.len());
    let panels = grid.split_evenly((rows, cols));
    let last = u32::try_from(n.saturating_sub(1)).map_err(err)?;
    for (panel, w) in panels.iter().zip(&r.workloads) {
        let first = w
            .cells
            .iter()
            .find_map(|c| c.outcome.headline().map(|h| h.name()))
            .unwrap_or("errors");
        let mut chart = ChartBuilder::on(panel)
            .caption(w.name.clone(), (SANS, 16))
            .margin(10)
            .x_label_area_size(44)
            .y_label_area_size(64)
            .build_cartesian_2d((0u32..last).into_segmented(), (BOTTOM..TOP).log_scale())
            .map_err(err)?;
        let label_of = |v: &SegmentValue<u32>| match v {
            SegmentValue::CenterOf(i) | SegmentValue::Exact(i) => labels
                .get(usize::try_from(*i).unwrap_or(usize::MAX))
                .cloned()
                .unwrap_or_default(),
            SegmentValue::Last => String::new(),
        };
        chart
            .configure_mesh()
            .x_desc("magnitude M, px (2^k)")
            .y_desc(format!("{first} per million"))
            .x_labels(n)
            .y_labels(8)
            .x_label_formatter(&label_of)
            .y_label_formatter(&|v| rate_label(*v))
            .axis_desc_style((SANS, 14))
            .label_style((SANS, 12))
            .draw()
            .map_err(err)?;
        let mut refusing = 0;
        for s in &w.speed {
            let c = colour(&s.contender);
            let mut run: Vec<(SegmentValue<u32>, f64)> = Vec::new();
            let any_refused = w
                .cells
                .iter()
                .any(|c| c.contender == s.contender && matches!(c.outcome, Outcome::Refused(_)));
            // Each refusing contender's crosses a little lower than the last one's.
            let cross_y = 1.5e6 / 2f64.powi(refusing);
            if any_refused {
                refusing += 1;
            }
            let mut runs = Vec::new();
            for (k, &m) in mags.iter().enumerate() {
                let x = SegmentValue::CenterOf(u32::try_from(k).map_err(err)?);
                match w.cell(&s.contender, m).map(|c| &c.outcome) {
                    Some(Outcome::Measured { .. }) => {
                        run.push((x, headline(w, &s.contender, m).unwrap_or(ZERO)));
                    }
                    Some(Outcome::Refused(_)) => {
                        runs.push(std::mem::take(&mut run));
                        chart
                            .draw_series(std::iter::once(Cross::new((x, cross_y), 7, c.stroke_width(3))))
                            .map_err(err)?;
                    }
                    None => runs.push(std::mem::take(&mut run)),
                }
            }
            runs.push(run);
            for line in runs.into_iter().filter(|l| !l.is_empty()) {
                let width = if s.exact { 2 } else { 3 };
                chart
                    .draw_series(LineSeries::new(line.clone(), c.stroke_width(width)))
                    .map_err(err)?;
                for p in line {
                    if s.exact {
                        chart.draw_series(std::iter::once(Circle::new(p, 4, c.filled())))
                    } else {
                        chart.draw_series(std::iter::once(TriangleMarker::new(p, 6, c.filled())))
                    }
                    .map_err(err)?;
                }
            }
        }
    }
    legend(
        &bottom,
        &legend_entries(r),
        6,
        "A cross near the top: the model refuses the workload there (integer envelope, Bresenham endpoints beyond \
         2^24, float range). Error per million as in the tables; 0 is exactly zero.",
    )
}

/// The colour of a decision.
fn decision_colour(d: Decision) -> RGBColor {
    match d {
        Decision::Inside => RGBColor(190, 190, 190),
        Decision::Outside => RGBColor(255, 255, 255),
        Decision::WronglyInside => RGBColor(215, 25, 28),
        Decision::WronglyOutside => RGBColor(33, 113, 181),
    }
}

/// Picture (c).
fn predicate_map<DB: DrawingBackend>(root: &Area<DB>, map: &PredicateMap) -> Result<(), String> {
    root.fill(&WHITE).map_err(err)?;
    let (_, h) = root.dim_in_pixel();
    let (top, rest) = root.split_vertically(80);
    let m = map.magnitude;
    top.draw(&Text::new(
        format!("Predicate map at M = {m} px from the origin: which pixels the float models decide wrongly"),
        (20, 12),
        (SANS, 24).into_font(),
    ))
    .map_err(err)?;
    top.draw(&Text::new(
        format!(
            "The sliver edge (M + 1/2, M + 2048 + 1/2) -> (M + 6144 + 1/2, M + 1/2); a {s} x {s} px patch of the window \
             around its middle, zoomed",
            s = map.side
        ),
        (20, 46),
        (SANS, 17).into_font(),
    ))
    .map_err(err)?;
    let (grid, bottom) = rest.split_vertically(h - 80 - 110);
    let panels = grid.split_evenly((2, 2));
    let side = f64::from(map.side);
    let points = usize::try_from(map.side).map_err(err)?;
    // The exact edge in patch coordinates (px from the patch's first pixel's corner).
    let to_patch = |p: &crate::geom::Point, axis: usize| {
        use num_traits::ToPrimitive;
        let v = if axis == 0 { &p.x } else { &p.y };
        let o = num_rational::BigRational::from_integer(map.origin[axis].into());
        (v - o).to_f64().unwrap_or(0.0)
    };
    let (ax, ay, bx, by) = (
        to_patch(&map.a, 0),
        to_patch(&map.a, 1),
        to_patch(&map.b, 0),
        to_patch(&map.b, 1),
    );
    let slope = (by - ay) / (bx - ax);
    let edge_line = vec![(0.0, ay + (0.0 - ax) * slope), (side, ay + (side - ax) * slope)];
    for (panel, p) in panels.iter().zip(&map.panels) {
        let caption = format!(
            "{}: {} of {} pixels decided wrongly",
            p.model,
            p.wrong(),
            p.decisions.len()
        );
        let mut chart = ChartBuilder::on(panel)
            .caption(caption, (SANS, 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(56)
            .build_cartesian_2d(0.0..side, side..0.0)
            .map_err(err)?;
        let ox = map.origin[0] - m.px_i64();
        let oy = map.origin[1] - m.px_i64();
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(format!("x - M - {ox}, px"))
            .y_desc(format!("y - M - {oy}, px"))
            .x_label_formatter(&|v| format!("{v:.0}"))
            .y_label_formatter(&|v| format!("{v:.0}"))
            .axis_desc_style((SANS, 14))
            .label_style((SANS, 12))
            .draw()
            .map_err(err)?;
        // One rectangle per run of equal decisions in a row.
        for (j, row) in p.decisions.chunks(points).enumerate() {
            let mut i = 0;
            while i < row.len() {
                let d = row[i];
                let len = row[i..].iter().take_while(|&&e| e == d).count();
                let (x0, x1) = (to_f64(i), to_f64(i + len));
                let (y0, y1) = (to_f64(j), to_f64(j + 1));
                chart
                    .draw_series(std::iter::once(Rectangle::new(
                        [(x0, y0), (x1, y1)],
                        decision_colour(d).filled(),
                    )))
                    .map_err(err)?;
                i += len;
            }
        }
        chart
            .draw_series(LineSeries::new(edge_line.clone(), BLACK.stroke_width(1)))
            .map_err(err)?;
    }
    let text = (SANS, 17).into_font();
    let entries = [
        (Decision::Inside, "inside, as exactly"),
        (Decision::Outside, "outside, as exactly"),
        (Decision::WronglyInside, "inside, exactly outside (wrong)"),
        (Decision::WronglyOutside, "outside, exactly inside (wrong)"),
    ];
    for (k, (d, name)) in entries.iter().enumerate() {
        let x = 20 + i32::try_from(k).map_err(err)? * 300;
        bottom
            .draw(&Rectangle::new([(x, 8), (x + 22, 30)], decision_colour(*d).filled()))
            .map_err(err)?;
        bottom
            .draw(&Rectangle::new([(x, 8), (x + 22, 30)], BLACK.stroke_width(1)))
            .map_err(err)?;
        bottom
            .draw(&Text::new(*name, (x + 30, 10), text.clone()))
            .map_err(err)?;
    }
    bottom
        .draw(&Text::new(
            "Each pixel: the float model's decision at its centre against the exact one, under top-left (this edge \
             is not inclusive:"
                .to_string(),
            (20, 48),
            (SANS, 15).into_font(),
        ))
        .map_err(err)?;
    bottom
        .draw(&Text::new(
            "a sample on it is outside). Black line: the exact edge. The float models round the vertices and the \
             sample to the type; naive: E >= 0."
                .to_string(),
            (20, 72),
            (SANS, 15).into_font(),
        ))
        .map_err(err)?;
    Ok(())
}

#[allow(clippy::cast_precision_loss)] // indices below 2^14
fn to_f64(i: usize) -> f64 {
    i as f64
}

/// Every picture of the report, PNG and SVG.
///
/// # Errors
/// Drawing fails (the compiled-in font unreadable, an encoder error).
pub(crate) fn pictures(r: &Report) -> Result<Vec<Picture>, String> {
    font()?;
    let (w, h) = (1800, 1400);
    let mut out = Vec::new();
    let mut push = |name: &str, bytes| {
        out.push(Picture {
            name: name.into(),
            bytes,
        });
    };
    push("speed-vs-error.png", png(w, h, |a| speed_error(a, r))?);
    push("speed-vs-error.svg", svg(w, h, |a| speed_error(a, r))?);
    push("error-vs-magnitude.png", png(w, h, |a| error_magnitude(a, r))?);
    push("error-vs-magnitude.svg", svg(w, h, |a| error_magnitude(a, r))?);
    let (mw, mh) = (1300, 1360);
    push(
        "predicate-map.png",
        png(mw, mh, |a| predicate_map(a, &r.predicate_map))?,
    );
    push(
        "predicate-map.svg",
        svg(mw, mh, |a| predicate_map(a, &r.predicate_map))?,
    );
    Ok(out)
}
