//! `rasterproof clip`: the scene's primitives clipped against its `clip` window (and its
//! clip-space triangles clipped against the view volume, divided and mapped), printed
//! with every coordinate as an exact string. An area primitive whose result encloses no
//! area (a point or a segment) prints as `[]`; a line's result may be a single point
//! (see [`rasterproof::clip::area_or_empty`]).

use std::path::PathBuf;
use std::process::ExitCode;

use rasterproof::clip::arithmetic::{Arithmetic, Clipper};
use rasterproof::geom::Point;
use rasterproof::num::exact::json_pair;
use rasterproof::scene::parse_scene_bytes;

use super::OutputFormat;

/// What `clip` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// The scene file (JSON).
    scene: PathBuf,
    /// exact (default), float32 or float64: the arithmetic of the clipping.
    #[arg(long, default_value = "exact")]
    model: String,
    /// Clip-space triangles: divide by w first, then clip in 2D (exact only; refuses
    /// vertices with w <= 0, which only clip-space clipping handles).
    #[arg(long)]
    divide_first: bool,
    /// Output format on stdout. Every primitive is listed in input order; `[]` is one that
    /// covers nothing: clipped away, or (triangles, polygon contours, clip-space
    /// triangles) left with no area — a point or a segment, as when it touches the window
    /// only at a corner or along an edge. A line touching the window in one point is that
    /// point twice (a segment of length zero).
    #[arg(long, default_value_t = OutputFormat::Json, value_parser = OutputFormat::parser(FORMATS))]
    format: OutputFormat,
}

/// `--format`'s values for `clip`, with their help.
const FORMATS: [(OutputFormat, &str); 2] = [
    (
        OutputFormat::Json,
        r#"`{"triangles":[...],"lines":[...],"polygons":[...],"clip_space_triangles":[...]}`"#,
    ),
    (OutputFormat::Text, "A one-line summary"),
];

/// A point as `["x","y"]`, exact text.
fn pt(p: &Point) -> String {
    json_pair(&p.x, &p.y)
}

fn list(points: &[Point]) -> String {
    format!("[{}]", points.iter().map(pt).collect::<Vec<_>>().join(","))
}

/// Clips the scene's primitives as `o` asks and prints them (or the summary); exit 0.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    let name = o.scene.display().to_string();
    let arith = Arithmetic::from_name(&o.model).ok_or_else(|| {
        format!(
            "--model: unknown model {:?} for clip (expected exact, float32 or float64)",
            o.model
        )
    })?;
    if o.divide_first && arith != Arithmetic::Exact {
        return Err("--divide-first: only with --model exact".into());
    }
    let bytes = std::fs::read(&o.scene).map_err(|e| format!("{name}: cannot read: {e}"))?;
    let scene = parse_scene_bytes(&bytes, &name).map_err(|e| e.to_string())?;
    let in_file = |e: String| format!("{name}: {e}");
    let clipper = Clipper::new(arith, scene.clip.as_ref()).map_err(in_file)?;

    let mut triangles = Vec::new();
    for (k, t) in scene.triangles.iter().enumerate() {
        triangles.push(list(
            &clipper
                .contour(&t.triangle.v, &format!("triangles[{k}]"))
                .map_err(in_file)?,
        ));
    }
    let mut lines = Vec::new();
    for (k, l) in scene.lines.iter().enumerate() {
        let kept = clipper
            .segment(&l.from, &l.to, &format!("lines[{k}]"))
            .map_err(in_file)?;
        lines.push(kept.map_or("[]".to_string(), |(a, b)| format!("[{},{}]", pt(&a), pt(&b))));
    }
    let mut polygons = Vec::new();
    for (k, p) in scene.polygons.iter().enumerate() {
        let what = format!("polygons[{k}]");
        let outline = clipper.contour(&p.outline, &what).map_err(in_file)?;
        if outline.is_empty() {
            polygons.push("[]".to_string());
            continue;
        }
        let mut contours = vec![list(&outline)];
        for h in &p.holes {
            contours.push(list(&clipper.contour(h, &what).map_err(in_file)?));
        }
        polygons.push(format!("[{}]", contours.join(",")));
    }
    let mut clip_space = Vec::new();
    let viewport = scene.viewport();
    for (k, t) in scene.clip_space_triangles.iter().enumerate() {
        let what = format!("clip_space_triangles[{k}]");
        clip_space.push(list(
            &clipper
                .clip_space(t, &viewport, o.divide_first, &what)
                .map_err(in_file)?,
        ));
    }
    match o.format {
        OutputFormat::Json => {
            let json = format!(
                "{{\"triangles\":[{}],\"lines\":[{}],\"polygons\":[{}],\"clip_space_triangles\":[{}]}}",
                triangles.join(","),
                lines.join(","),
                polygons.join(","),
                clip_space.join(",")
            );
            crate::cli::print_stdout(&json)?;
        }
        OutputFormat::Text => {
            let kept = |v: &[String]| v.iter().filter(|s| s.as_str() != "[]").count();
            crate::cli::print_stdout(&format!(
                "{name}: {} clipping: {}/{} triangles, {}/{} lines, {}/{} polygons, {}/{} clip-space triangles keep something",
                o.model,
                kept(&triangles),
                triangles.len(),
                kept(&lines),
                lines.len(),
                kept(&polygons),
                polygons.len(),
                kept(&clip_space),
                clip_space.len()
            ))?;
        }
    }
    Ok(ExitCode::SUCCESS)
}
