//! `rasterproof clip`: the scene's primitives clipped against its `clip` window (and its
//! clip-space triangles clipped against the view volume, divided and mapped), printed
//! with every coordinate as an exact string ([`rasterproof::scene::Scene::clipped`], laid
//! out by its `to_json` / `to_text`). An area primitive whose result encloses no
//! area (a point or a segment) prints as `[]`; a line's result may be a single point
//! (see [`rasterproof::clip::area_or_empty`]).

use std::path::PathBuf;
use std::process::ExitCode;

use rasterproof::clip::arithmetic::ClipArithmetic;
use rasterproof::scene::{parse_scene_with, ParseOptions};

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

/// Clips the scene's primitives as `o` asks and prints them (or the summary); exit 0.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    let name = o.scene.display().to_string();
    let arith = ClipArithmetic::from_name(&o.model).ok_or_else(|| {
        format!(
            "--model: unknown model {:?} for clip (expected exact, float32 or float64)",
            o.model
        )
    })?;
    if o.divide_first && arith != ClipArithmetic::Exact {
        return Err("--divide-first: only with --model exact".into());
    }
    let bytes = std::fs::read(&o.scene).map_err(|e| format!("{name}: cannot read: {e}"))?;
    let scene = parse_scene_with(&bytes, &name, &ParseOptions::default()).map_err(|e| e.to_string())?;
    let clipped = scene
        .clipped(arith, o.divide_first)
        .map_err(|e| format!("{name}: {e}"))?;
    match o.format {
        OutputFormat::Json => crate::cli::print_stdout(&clipped.to_json())?,
        OutputFormat::Text => crate::cli::print_stdout(&clipped.to_text(&name))?,
    }
    Ok(ExitCode::SUCCESS)
}
