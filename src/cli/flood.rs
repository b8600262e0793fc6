//! `rasterproof flood`: the region of one pixel's colour in a PNG, optionally recoloured.

use std::path::PathBuf;
use std::process::ExitCode;

use image::Rgba;
use rasterproof::fill::flood::{
    load_png, paint, region_summary, span_region, write_region_json, Connectivity, MAX_IMAGE_SIDE,
};

use super::OutputFormat;

/// What `flood` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// The image (PNG, any colour type, read as 8-bit RGBA; at most 16384 pixels per side).
    image: PathBuf,
    /// The seed pixel X,Y (0-based; x right, y down from the top-left corner).
    #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
    at: String,
    /// 4 (up, down, left, right) or 8 (also the diagonals).
    #[arg(long, value_name = "4|8", default_value = "4")]
    connectivity: String,
    /// The fill colour for --out: R,G,B (opaque) or R,G,B,A, each 0..=255. Default 255,0,0
    /// (opaque red).
    #[arg(
        long = "color",
        value_name = "R,G,B",
        default_value = "255,0,0",
        allow_hyphen_values = true
    )]
    color: String,
    /// Write the image with the region recoloured (PNG, 8-bit RGBA); nothing is written
    /// when the run fails.
    #[arg(short = 'o', long = "out")]
    out: Option<PathBuf>,
    /// Output format on stdout.
    #[arg(long, default_value_t = OutputFormat::Text, value_parser = OutputFormat::parser(FORMATS))]
    format: OutputFormat,
}

/// `--format`'s values for `flood`, with their help.
const FORMATS: [(OutputFormat, &str); 2] = [
    (
        OutputFormat::Text,
        "A one-line summary: pixel count, connectivity, seed, file",
    ),
    (
        OutputFormat::Json,
        "`{\"width\":W,\"height\":H,\"at\":[x,y],\"connectivity\":4,\"pixels\":[[x,y],...]}`, \
         the region's pixels row-major (by y, then x)",
    ),
];

/// Finds the seed pixel's region, writes `--out` recoloured and prints the region
/// (the summary, or the pixels as JSON with the summary on stderr); exit 0.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    let at = parse_at(&o.at)?;
    let connectivity = parse_connectivity(&o.connectivity)?;
    let colour = parse_colour(&o.color)?;
    let name = o.image.display().to_string();
    let mut image = load_png(&o.image).map_err(|e| e.to_string())?;
    let region = span_region(&image, at, connectivity).map_err(|e| {
        format!(
            "--at: {},{} is outside the image {name} ({}x{}: x must be in 0..{}, y in 0..{})",
            e.seed.0, e.seed.1, e.width, e.height, e.width, e.height
        )
    })?;

    if let Some(path) = &o.out {
        paint(&mut image, &region, colour);
        let mut outputs = crate::cli::Outputs::new();
        outputs.stage_png(path, &image)?;
        outputs.commit()?;
    }
    let recoloured = o.out.as_deref().map(|path| (colour, path));
    let summary = region_summary(&name, &region, at, connectivity, recoloured);
    match o.format {
        OutputFormat::Json => {
            crate::cli::write_stdout(|out| write_region_json(out, &region, at, connectivity))?;
            eprintln!("{summary}");
        }
        OutputFormat::Text => crate::cli::print_stdout(&summary)?,
    }
    Ok(ExitCode::SUCCESS)
}

/// `--at X,Y` ([`super::parse_pixel`]).
fn parse_at(text: &str) -> Result<(u32, u32), String> {
    super::parse_pixel(text).ok_or_else(|| {
        format!(
            "--at: {text:?} is not X,Y (two integers from 0 to {}, e.g. 3,4)",
            MAX_IMAGE_SIDE - 1
        )
    })
}

fn parse_connectivity(text: &str) -> Result<Connectivity, String> {
    text.trim()
        .parse::<u32>()
        .ok()
        .and_then(Connectivity::from_number)
        .ok_or_else(|| format!("--connectivity: {text:?} is not 4 or 8"))
}

/// `R,G,B` (alpha 255) or `R,G,B,A`, each 0..=255.
fn parse_colour(text: &str) -> Result<Rgba<u8>, String> {
    let bad = || format!("--color: {text:?} is not R,G,B or R,G,B,A (integers 0..=255, e.g. 255,0,0)");
    let parts = integers(text).ok_or_else(bad)?;
    let channel = |v: u64| u8::try_from(v).map_err(|_| bad());
    match parts[..] {
        [r, g, b] => Ok(Rgba([channel(r)?, channel(g)?, channel(b)?, 255])),
        [r, g, b, a] => Ok(Rgba([channel(r)?, channel(g)?, channel(b)?, channel(a)?])),
        _ => Err(bad()),
    }
}

/// Comma-separated non-negative integers (spaces around each allowed); `None` if any part
/// is not one.
fn integers(text: &str) -> Option<Vec<u64>> {
    text.split(',').map(|part| part.trim().parse::<u64>().ok()).collect()
}
