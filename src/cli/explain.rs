//! `rasterproof explain`: one pixel of a scene, exactly ([`rasterproof::oracle::explain_pixel`]);
//! its interpolated values with `--as values`
//! ([`rasterproof::oracle::explain::values::explain_values`]).

use std::path::PathBuf;
use std::process::ExitCode;

use rasterproof::oracle::explain::values::explain_values;
use rasterproof::oracle::{explain_pixel, Background, Format, Question};

use super::value_args::{read_theirs, their_format, ValueArgs};
use super::{ConventionArgs, OutputFormat};

/// What `explain` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// The scene file (JSON).
    scene: PathBuf,
    /// The pixel, as X,Y (column, row; 0,0 is the top-left pixel).
    #[arg(value_name = "X,Y")]
    pixel: String,
    /// Their values image (a float32 TIFF, or a UNORM PNG with `--as values`), as `compare
    /// --as values` reads it (stacked once per sample index under a pattern): each
    /// channel's value beside the exact one, its distance in f32 steps, and the class the
    /// comparison gives the pixel.
    #[arg(value_name = "THEIRS")]
    theirs: Option<PathBuf>,
    /// `values`: explain the pixel's interpolated values of a varying (see --varying)
    /// instead of its coverage: per sample, the primitive shown and why, the point the
    /// varying is taken at (centre, sample or centroid) exactly, the homogeneous
    /// barycentrics and weights there, the formula with its numbers, each channel's exact
    /// value and its nearest f32 (with the bits), theirs (with the bits) and the signed
    /// distance in f32 steps, the f32 envelope (near and far), a centroid varying's range
    /// and the class. The default when THEIRS is a .tif or .tiff file.
    #[arg(long = "as", value_name = "values")]
    theirs_as: Option<String>,
    #[command(flatten)]
    values: ValueArgs,
    #[command(flatten)]
    convention: ConventionArgs,
    /// Output format on stdout.
    #[arg(long, default_value_t = OutputFormat::Text, value_parser = OutputFormat::parser(FORMATS))]
    format: OutputFormat,
    /// Also draw the pixel's neighbourhood as an SVG picture: the 5x5 pixels around it,
    /// their samples, each nearby edge (solid where it owns the samples on it, dashed
    /// where not), a polygon's winding number, a line's diamond, as the oracle
    /// (exact-snapped) draws them.
    #[arg(long, value_name = "OUT.svg")]
    svg: Option<PathBuf>,
    /// `area`: explain the pixel's exact area coverage instead (as `render --coverage
    /// area` computes it, under `--model`): its value under each semantics, each shape's
    /// integral of its winding number, the edges that meet the pixel's square, and its
    /// pieces (the trapezoids between the edges) with their areas and winding numbers.
    #[arg(long, default_value = "sample", value_name = "sample|area")]
    coverage: String,
    /// The model whose shapes `--coverage area` measures (exact, the default, or
    /// exact-snapped; the plain forms give the same shapes), or whose coverage says which
    /// primitive each sample shows with `--as values` (exact-snapped, the default, or
    /// exact, as `compare --as values`).
    #[arg(long)]
    model: Option<String>,
    /// The sample pattern, replacing the scene's `samples`: the standard pattern of N (2,
    /// 4, 8, 16). Under a pattern of several samples explain lists every sample of the
    /// pixel (its position, each nearby primitive's exact evidence there) and what every
    /// model decides at each sample index; with `--as values`, each sample's value, THEIRS
    /// being one image per sample index, stacked.
    #[arg(long, value_name = "N")]
    samples: Option<usize>,
}

/// `--format`'s values for `explain`, with their help.
const FORMATS: [(OutputFormat, &str); 2] = [
    (
        OutputFormat::Text,
        "The sample, each nearby primitive's exact evidence (as written and snapped), and what every model decides; \
         with --as values, each sample's value derived, theirs and its class",
    ),
    (OutputFormat::Json, "The same as one JSON object"),
];

/// The pixel `X,Y` ([`super::parse_pixel`]).
fn parse_pixel(text: &str) -> Result<(u32, u32), String> {
    super::parse_pixel(text).ok_or_else(|| format!("pixel: {text:?} is not X,Y (two non-negative integers)"))
}

/// Explains the pixel `o` names and prints it; exit 0.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    let (x, y) = parse_pixel(&o.pixel)?;
    let values = values_asked(o)?;
    o.values.only_for_values(values)?;
    let (name, scene, target) = super::load_scene_with(&o.scene, &o.convention, 1)?;
    if values {
        return run_values(o, (x, y), &name, &scene, &target);
    }
    match o.coverage.as_str() {
        "sample" => {}
        "area" => {
            if o.svg.is_some() {
                return Err("--svg draws the sample's neighbourhood: it is for --coverage sample".to_string());
            }
            if x >= target.width || y >= target.height {
                return Err(format!(
                    "pixel: ({x}, {y}) is off the {}x{} canvas of {name}",
                    target.width, target.height
                ));
            }
            let model = super::parse_model(o.model.as_deref().unwrap_or("exact"))?;
            let shapes = rasterproof::model::area_shapes(&scene.primitives(), &target, model)
                .map_err(|e| format!("{name}: {e} (model {model})"))?;
            let why = rasterproof::area::exact::explain(&shapes, i64::from(x), i64::from(y));
            super::write_stdout(|out| {
                writeln!(out, "{name}: model {model}, {}", target.convention)?;
                out.write_all(why.to_text().as_bytes())
            })?;
            return Ok(ExitCode::SUCCESS);
        }
        other => return Err(format!("--coverage: unknown kind {other:?} (expected sample or area)")),
    }
    if o.model.is_some() {
        return Err("--model is for --coverage area (explain shows every model's decision for a sample)".to_string());
    }
    let pattern = match o.samples {
        Some(n) => Some(super::parse_samples(n)?),
        None => scene.samples.clone(),
    };
    let off_canvas = || {
        format!(
            "pixel: ({x}, {y}) is off the {}x{} canvas of {name}",
            target.width, target.height
        )
    };
    let heading = format!("{name}: {}", target.convention);
    if let Some(pattern) = pattern.filter(|p| !p.is_single(&target.convention)) {
        if o.svg.is_some() {
            return Err(
                "--svg draws one sample per pixel; leave it out under a pattern of several samples".to_string(),
            );
        }
        if !scene.lines.is_empty() {
            return Err(format!(
                "{name}: lines: a line has no samples; explain it without a pattern"
            ));
        }
        let why = rasterproof::oracle::explain::explain_samples(&scene.primitives(), &target, &pattern, x, y)
            .ok_or_else(off_canvas)?;
        print(o.format, &heading, &why.to_text(), &why.to_json())?;
        return Ok(ExitCode::SUCCESS);
    }
    let why = explain_pixel(&scene.primitives(), &target, x, y).ok_or_else(off_canvas)?;
    if let Some(path) = &o.svg {
        let svg = rasterproof::oracle::svg::neighbourhood_svg(
            &scene.primitives(),
            &target,
            x,
            y,
            rasterproof::model::Model::ExactSnapped,
        )
        .map_err(|e| format!("{name}: {e}"))?
        .ok_or_else(|| format!("pixel: ({x}, {y}) is off the canvas of {name}"))?;
        let mut outputs = super::Outputs::new();
        outputs.stage_text(path, &svg)?;
        outputs.commit()?;
    }
    print(o.format, &heading, &why.to_text(), &why.to_json())?;
    Ok(ExitCode::SUCCESS)
}

/// Whether `o` asks for values (`--as values`, or THEIRS a TIFF), refusing what does not go
/// with them: their output read otherwise, `--coverage area`, `--svg`.
fn values_asked(o: &Options) -> Result<bool, String> {
    let format = match (&o.theirs, &o.theirs_as) {
        (Some(path), theirs_as) => Some(their_format(theirs_as.as_deref(), path)?),
        (None, Some(f)) => Some(Format::from_name(f).ok_or_else(|| {
            format!("--as: unknown format {f:?} (explain takes values; coverage is explained without --as)")
        })?),
        (None, None) => None,
    };
    match format {
        None => Ok(false),
        Some(Format::Values) if o.coverage != "sample" => {
            Err("--as values explains a varying's values; --coverage area is for coverage".to_string())
        }
        Some(Format::Values) if o.svg.is_some() => {
            Err("--svg draws the sample's neighbourhood: it is for coverage, not --as values".to_string())
        }
        Some(Format::Values) => Ok(true),
        Some(other) => Err(format!(
            "--as: explain reads THEIRS as values only (a float32 TIFF, or a UNORM PNG with --as values), not {}; compare takes coverage",
            other.name()
        )),
    }
}

/// `explain --as values`: the pixel's values of the varying, exactly, and theirs.
fn run_values(
    o: &Options,
    (x, y): (u32, u32),
    name: &str,
    scene: &rasterproof::scene::Scene,
    target: &rasterproof::convention::Target,
) -> Result<ExitCode, String> {
    if x >= target.width || y >= target.height {
        return Err(format!(
            "pixel: ({x}, {y}) is off the {}x{} canvas of {name}",
            target.width, target.height
        ));
    }
    let model = super::parse_model(o.model.as_deref().unwrap_or("exact-snapped"))?;
    let pattern = match o.samples {
        Some(n) => Some(super::parse_samples(n)?),
        None => scene.samples.clone(),
    };
    let options = o.values.options(scene, name, model, pattern, target)?;
    let theirs = match &o.theirs {
        Some(path) => Some(read_theirs(path, Format::Values, Background::default())?),
        None => None,
    };
    let theirs_name = theirs.as_ref().map_or("", |(n, _)| n.as_str());
    let why = explain_values(
        &scene.primitives(),
        target,
        theirs.as_ref().map(|(_, t)| t),
        &options,
        x,
        y,
    )
    .map_err(|e| Question::Values(Box::new(options.clone())).error_text(&e, name, theirs_name))?;
    let heading = format!("{name}: {}", target.convention);
    print(o.format, &heading, &why.to_text(), &why.to_json())?;
    Ok(ExitCode::SUCCESS)
}

/// An explanation on stdout: its text under the heading line, or its JSON.
fn print(format: OutputFormat, heading: &str, text: &str, json: &serde_json::Value) -> Result<(), String> {
    match format {
        OutputFormat::Text => super::write_stdout(|out| {
            writeln!(out, "{heading}")?;
            out.write_all(text.as_bytes())
        }),
        OutputFormat::Json => super::print_stdout(&json.to_string()),
    }
}
