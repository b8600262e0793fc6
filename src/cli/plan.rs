//! `rasterproof plan`: per primitive, the arithmetic the planned exact engine runs it in
//! and the bound that forced it; a summary by width; which fixed-width models are exact
//! for the scene.

use std::path::PathBuf;
use std::process::ExitCode;

use rasterproof::model::plan::plan_scene;

use super::OutputFormat;

/// What `plan` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// The scene file (JSON).
    scene: PathBuf,
    /// The planned model: exact-snapped (the default) or exact.
    #[arg(long, default_value = "exact-snapped")]
    model: String,
    /// Override the scene's preset: d3d11, vulkan, gl, cts.
    #[arg(long)]
    preset: Option<String>,
    /// Output format on stdout.
    #[arg(long, default_value_t = OutputFormat::Text, value_parser = OutputFormat::parser(FORMATS))]
    format: OutputFormat,
}

/// `--format`'s values for `plan`, with their help.
const FORMATS: [(OutputFormat, &str); 2] = [
    (
        OutputFormat::Text,
        "One line per primitive, the summary, the fixed-width models' verdicts",
    ),
    (
        OutputFormat::Json,
        "The same as one JSON object (schema in docs/cli.md, `plan`)",
    ),
];

/// Plans the scene with the model `o` names and prints the plan; exit 0.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    let model = super::parse_model(&o.model)?;
    if !model.plans() {
        return Err(format!(
            "--model: {model} has no plan (only exact and exact-snapped run the planned engine)"
        ));
    }
    let (name, scene, target) = super::load_scene(&o.scene, o.preset.as_deref(), 1)?;
    let plan = plan_scene(&scene.primitives(), &target, model).map_err(|e| format!("{name}: {e} (model {model})"))?;
    match o.format {
        OutputFormat::Text => super::print_stdout(&plan.to_text(&name, &target.convention.to_string()))?,
        OutputFormat::Json => super::print_stdout(&plan.to_json(&name, &target.convention.to_string()))?,
    }
    Ok(ExitCode::SUCCESS)
}
