//! `rasterproof render`.

use std::path::PathBuf;
use std::process::ExitCode;

use rasterproof::convention::Preset;
use rasterproof::model::{prepare, Model};
use rasterproof::scene::parse_scene_bytes;

/// What `render` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// The scene file (JSON).
    scene: PathBuf,
    /// The model (default exact-snapped); `--help` lists them.
    #[arg(long, default_value = "exact-snapped", long_help = crate::cli::model_help())]
    model: String,
    /// Override the scene's preset: d3d11, vulkan, gl, cts (the scene's explicit
    /// overrides still apply on top).
    #[arg(long)]
    preset: Option<String>,
    /// Write the coverage picture (one colour per triangle, magenta where covered twice).
    #[arg(short = 'o', long = "out")]
    out: Option<PathBuf>,
    /// Write the interpolated-colour (Gouraud) picture.
    #[arg(long = "colors-out")]
    colors_out: Option<PathBuf>,
    /// Output format on stdout.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

/// How `render` reports on stdout.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// A one-line summary naming the model and preset.
    Text,
    /// `{"width":W,"height":H,"pixels":[[x,y,[ids...]],...]}`.
    Json,
}

pub fn run(o: &Options) -> Result<ExitCode, String> {
    let name = o.scene.display().to_string();
    let model = Model::from_name(&o.model).ok_or_else(|| {
        let all: Vec<&str> = Model::ALL.iter().map(|m| m.name()).collect();
        format!(
            "--model: unknown model {:?} (expected one of {})",
            o.model,
            all.join(", ")
        )
    })?;
    let bytes = std::fs::read(&o.scene).map_err(|e| format!("{name}: cannot read: {e}"))?;
    let mut scene = parse_scene_bytes(&bytes, &name).map_err(|e| e.to_string())?;
    if let Some(p) = &o.preset {
        scene.preset = Preset::from_name(p)
            .ok_or_else(|| format!("--preset: unknown preset {p:?} (expected one of d3d11, vulkan, gl, cts)"))?;
    }
    let target = scene
        .target()
        .ok_or_else(|| format!("{name}: invalid canvas or convention"))?;
    let fail = |e: rasterproof::model::ModelError| format!("{name}: {e} (model {model})");
    let prepared = prepare(model, &scene.primitives(), &target).map_err(fail)?;
    let coverage = prepared.coverage(&target);

    if let Some(path) = &o.out {
        coverage
            .save_png(path)
            .map_err(|e| format!("{}: cannot write PNG: {e}", path.display()))?;
    }
    if let Some(path) = &o.colors_out {
        prepared
            .colour_image(&coverage, &scene.colours(), &target)
            .save_with_format(path, image::ImageFormat::Png)
            .map_err(|e| format!("{}: cannot write PNG: {e}", path.display()))?;
    }
    let summary = format!(
        "{name}: model {model}, {}: {} pixels covered, {} covered more than once",
        target.convention,
        coverage.covered_pixels(),
        coverage.double_covered().count()
    );
    match o.format {
        Format::Json => {
            crate::cli::print_stdout(&coverage.to_json())?;
            eprintln!("{summary}");
        }
        Format::Text => crate::cli::print_stdout(&summary)?,
    }
    Ok(ExitCode::SUCCESS)
}
