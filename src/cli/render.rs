//! `rasterproof render`.

use std::path::PathBuf;
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rasterproof::convention::Target;
use rasterproof::coverage::picture::{legend_path, upscale};
use rasterproof::coverage::Coverage;
use rasterproof::coverage::{Scale, ASCII_GRID_MAX_SIDE};
use rasterproof::model::plan;
use rasterproof::model::{prepare, PreparedScene};
use std::time::{Duration, Instant};

use super::{OutputFormat, Outputs};

/// What `render` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// The scene file (JSON).
    scene: PathBuf,
    /// The model (default exact-snapped); `--help` lists them and says what exact and
    /// exact-snapped mean.
    #[arg(long, default_value = "exact-snapped", long_help = crate::cli::model_help())]
    model: String,
    #[command(flatten)]
    convention: super::ConventionArgs,
    /// Write the coverage picture (PNG): black where uncovered, one colour per primitive,
    /// white where several primitives cover a pixel; its legend (id, colour, primitive,
    /// pixels) goes beside it as OUT.legend.txt. A failing run writes no file at all.
    #[arg(short = 'o', long = "out", value_name = "OUT.png")]
    out: Option<PathBuf>,
    /// Write the interpolated-colour (Gouraud) picture (PNG), at the same scale.
    #[arg(long = "colors-out", value_name = "COLOURS.png")]
    colors_out: Option<PathBuf>,
    /// Write the ids PNG, for programs: 8-bit RGBA, each pixel id + 1 as a 24-bit number
    /// (R low byte, G, B high byte), alpha 255; 0 = uncovered; several owners: the highest
    /// id with alpha 254. Never scaled. Ids above 2^24 - 2 are refused.
    #[arg(long = "ids-out", value_name = "IDS.png")]
    ids_out: Option<PathBuf>,
    /// Enlarge the pictures (not the ids PNG): each pixel becomes a KxK block. Default: the smallest K that
    /// makes the picture at least 256 px wide, lowered to keep each side at most 4096 px.
    #[arg(long, value_name = "K", allow_hyphen_values = true)]
    scale: Option<String>,
    /// Output format on stdout.
    #[arg(long, default_value_t = OutputFormat::Text, value_parser = OutputFormat::parser(FORMATS))]
    format: OutputFormat,
}

/// `--format`'s values for `render`, with their help.
const FORMATS: [(OutputFormat, &str); 2] = [
    (
        OutputFormat::Text,
        "Up to 64x64 pixels, the coverage as a grid (`.` uncovered, the owner id's \
         last digit, `#` several owners; row 0 first), then a one-line summary naming \
         the model and preset",
    ),
    (
        OutputFormat::Json,
        r#"`{"width":W,"height":H,"pixels":[[x,y,[ids...]],...]}`"#,
    ),
];

/// Renders the scene with the model `o` names, writes the pictures asked for (all or
/// none) and prints the coverage and summary; exit 0.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    let model = super::parse_model(&o.model)?;
    let scale_asked = o.scale.as_deref().map(parse_scale).transpose()?;
    let (name, scene, target) = super::load_scene_with(&o.scene, &o.convention)?;
    let scale = match scale_asked {
        Some(k) => Scale::new(k, target.width, target.height).map_err(|e| format!("--scale: {e} (scene {name})"))?,
        None => Scale::default_for(target.width, target.height),
    };
    let fail = |e: rasterproof::model::ModelError| format!("{name}: {e} (model {model})");
    let primitives = scene.primitives();
    let prepared = prepare(&primitives, &target, model).map_err(fail)?;
    let coverage = draw_with_progress(&prepared, &target);

    let mut outputs = Outputs::new();
    let mut wrote = Vec::new();
    if let Some(path) = &o.out {
        outputs.stage_png(path, &coverage.picture(scale))?;
        let legend = legend_path(path);
        outputs.stage_text(&legend, &coverage.legend(&primitives.id_runs(), scale))?;
        wrote.extend([path.display().to_string(), legend.display().to_string()]);
    }
    if let Some(path) = &o.colors_out {
        let colours = prepared.colour_image(&coverage, &scene.colours(), &target);
        outputs.stage_png(path, &upscale(&colours, scale))?;
        wrote.push(path.display().to_string());
    }
    if let Some(path) = &o.ids_out {
        let ids = coverage
            .to_ids_image()
            .map_err(|e| format!("--ids-out {}: {e} (scene {name})", path.display()))?;
        outputs.stage_png(path, &ids)?;
        wrote.push(format!("{} (ids, unscaled)", path.display()));
    }
    outputs.commit()?;

    let mut summary = format!(
        "{name}: model {model}, {}: {} pixels covered, {} covered more than once",
        target.convention,
        coverage.covered_pixels(),
        coverage.double_covered().count()
    );
    if model.plans() {
        summary.push_str(&format!("; plan: {}", plan::summary(&prepared.plans())));
    }
    if !wrote.is_empty() {
        let k = scale.get();
        summary.push_str(&format!("; wrote {} (scale {k})", wrote.join(", ")));
    }
    match o.format {
        OutputFormat::Json => {
            crate::cli::write_stdout(|out| {
                coverage.write_json(out)?;
                writeln!(out)
            })?;
            eprintln!("{summary}");
        }
        OutputFormat::Text => {
            let small = target.width <= ASCII_GRID_MAX_SIDE && target.height <= ASCII_GRID_MAX_SIDE;
            let grid = if small { coverage.to_ascii() } else { String::new() };
            crate::cli::print_stdout(&format!("{grid}{summary}"))?;
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// Draws the scene; once drawing has gone on for a second (an arbitrary-precision plan, a
/// plain oracle on a big frame), a progress bar on stderr counts the primitives drawn
/// (indicatif hides it when stderr is not a terminal).
fn draw_with_progress(prepared: &PreparedScene, target: &Target) -> Coverage {
    let start = Instant::now();
    let bar = ProgressBar::with_draw_target(Some(prepared.primitive_count() as u64), ProgressDrawTarget::hidden());
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} primitives, {elapsed} ({eta} left)")
            .expect("static template"),
    );
    let mut shown = false;
    let mut coverage = Coverage::new(target.width, target.height);
    prepared.render_observed(target, &mut coverage, &mut || {
        bar.inc(1);
        if !shown && start.elapsed() > Duration::from_secs(1) {
            bar.set_draw_target(ProgressDrawTarget::stderr());
            shown = true;
        }
    });
    bar.finish_and_clear();
    coverage
}

/// `--scale K`: a whole number (its range is checked against the canvas later).
fn parse_scale(text: &str) -> Result<u32, String> {
    text.trim()
        .parse::<u32>()
        .map_err(|_| format!("--scale: {text:?} is not a whole number K >= 1 (each pixel becomes a KxK block)"))
}
