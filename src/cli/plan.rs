//! `rasterproof plan`: per primitive, the arithmetic the planned exact engine runs it in
//! and the bound that forced it; a summary by width; which fixed-width models are exact
//! for the scene.

use std::path::PathBuf;
use std::process::ExitCode;

use rasterproof::model::plan::{plan_scene, ScenePlan};
use serde_json::{json, Value};

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
    let (name, scene, target) = super::load_scene(&o.scene, o.preset.as_deref())?;
    let plan = plan_scene(model, &scene.primitives(), &target).map_err(|e| format!("{name}: {e} (model {model})"))?;
    match o.format {
        OutputFormat::Text => super::print_stdout(&text(&name, &target.convention.to_string(), &plan))?,
        OutputFormat::Json => super::print_stdout(&json(&name, &target.convention.to_string(), &plan).to_string())?,
    }
    Ok(ExitCode::SUCCESS)
}

fn text(name: &str, convention: &str, plan: &ScenePlan) -> String {
    let mut s = format!("{name}: model {}, {convention}\n", plan.model);
    for p in &plan.primitives {
        let what = match &p.plan {
            Some(plan) => plan.to_string(),
            None => "not planned (covers nothing, or a Bresenham line)".into(),
        };
        s.push_str(&format!("{} {} (id {}): {what}\n", p.kind, p.index, p.id));
    }
    s.push_str(&format!("summary: {}\n", plan.summary()));
    s.push_str("fixed-width models:\n");
    for v in &plan.fixed_width {
        let verdict = match &v.broken_by {
            None => "exact for this scene".to_string(),
            Some(why) => format!("not exact (or not proven): {why}"),
        };
        s.push_str(&format!("  {:<9} {verdict}\n", v.model.name()));
    }
    s.pop();
    s
}

fn json(name: &str, convention: &str, plan: &ScenePlan) -> Value {
    let primitives: Vec<Value> = plan
        .primitives
        .iter()
        .map(|p| match &p.plan {
            Some(q) => json!({
                "kind": p.kind,
                "index": p.index,
                "id": p.id,
                "width": q.width.name(),
                "bound": q.bound.value.to_string(),
                "bound_bits": q.bound.bits(),
                "bound_at": q.bound.what,
                "scale": q.scale.to_string(),
            }),
            None => json!({"kind": p.kind, "index": p.index, "id": p.id, "width": null}),
        })
        .collect();
    let by_width: serde_json::Map<String, Value> = plan
        .by_width()
        .into_iter()
        .map(|(w, n)| (w.name().to_string(), json!(n)))
        .collect();
    let fixed: Vec<Value> = plan
        .fixed_width
        .iter()
        .map(|v| json!({"model": v.model.name(), "exact": v.exact, "broken_by": v.broken_by}))
        .collect();
    json!({
        "scene": name,
        "model": plan.model.name(),
        "convention": convention,
        "primitives": primitives,
        "by_width": by_width,
        "fixed_width": fixed,
    })
}
