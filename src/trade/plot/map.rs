//! Picture (c) of the trade: the predicate map, the float models' inside/outside
//! decisions near a sliver edge far from the origin against the exact ones.

use plotters::prelude::*;

use super::{err, Area, SANS};
use crate::trade::predicate_map::{Decision, MapPanel, PredicateMap};

/// The colour of a decision.
fn decision_colour(d: Decision) -> RGBColor {
    match d {
        Decision::Inside => RGBColor(190, 190, 190),
        Decision::Outside => RGBColor(255, 255, 255),
        Decision::WronglyInside => RGBColor(215, 25, 28),
        Decision::WronglyOutside => RGBColor(33, 113, 181),
    }
}

/// Picture (c): the title, the four models' panels, and the legend.
pub(super) fn predicate_map<DB: DrawingBackend>(root: &Area<DB>, map: &PredicateMap) -> Result<(), String> {
    root.fill(&WHITE).map_err(err)?;
    let (_, h) = root.dim_in_pixel();
    let (top, rest) = root.split_vertically(80);
    title(&top, map)?;
    let (grid, bottom) = rest.split_vertically(h - 80 - 110);
    let panels = grid.split_evenly((2, 2));
    let edge = exact_edge(map);
    for (area, panel) in panels.iter().zip(&map.panels) {
        draw_panel(area, map, panel, &edge)?;
    }
    legend(&bottom)
}

/// The picture's two title lines.
fn title<DB: DrawingBackend>(top: &Area<DB>, map: &PredicateMap) -> Result<(), String> {
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
    Ok(())
}

/// The exact edge in patch coordinates (px from the patch's first pixel's corner), as the
/// line across the patch.
fn exact_edge(map: &PredicateMap) -> Vec<(f64, f64)> {
    let side = f64::from(map.side);
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
    vec![(0.0, ay + (0.0 - ax) * slope), (side, ay + (side - ax) * slope)]
}

/// One model's panel: its decisions, a rectangle per run of equal decisions in a row,
/// under the exact edge.
fn draw_panel<DB: DrawingBackend>(
    area: &Area<DB>,
    map: &PredicateMap,
    p: &MapPanel,
    edge: &[(f64, f64)],
) -> Result<(), String> {
    let side = f64::from(map.side);
    let points = usize::try_from(map.side).map_err(err)?;
    let m = map.magnitude;
    let caption = format!(
        "{}: {} of {} pixels decided wrongly",
        p.model,
        p.wrong(),
        p.decisions.len()
    );
    let mut chart = ChartBuilder::on(area)
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
        .draw_series(LineSeries::new(edge.to_vec(), BLACK.stroke_width(1)))
        .map_err(err)?;
    Ok(())
}

/// The legend: the four decisions' colours, and how to read a pixel.
fn legend<DB: DrawingBackend>(bottom: &Area<DB>) -> Result<(), String> {
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
