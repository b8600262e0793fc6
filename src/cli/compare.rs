//! `rasterproof compare`: another renderer's output against the oracle, every differing
//! pixel explained ([`rasterproof::oracle::compare`]).

use std::path::PathBuf;
use std::process::ExitCode;

use rasterproof::coverage::picture::{legend_path, Scale};
use rasterproof::oracle::compare::compare_classifying;
use rasterproof::oracle::{Background, Format, Theirs};

use super::{ConventionArgs, OutputFormat, Outputs};

/// What `compare` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// The scene file (JSON).
    scene: PathBuf,
    /// Their output: a PNG (`--as mask` or `ids`) or the JSON of `render --format json`.
    theirs: PathBuf,
    /// How to read THEIRS: mask (covered where a pixel differs from the background), ids
    /// (the ids PNG of `render --ids-out`: id + 1 in R (low byte), G, B; alpha 254 marks
    /// several owners), json, or grey (an anti-aliased 8- or 16-bit grey PNG, compared
    /// with the exact area coverage: see --semantics and --quantization). Default: json
    /// for a .json file, ids otherwise.
    #[arg(long = "as", value_name = "FORMAT")]
    theirs_as: Option<String>,
    /// The oracle model: exact-snapped (the default for ids, masks and JSON: the answer of
    /// a renderer that snaps vertices to the subpixel grid) or exact (vertices as written;
    /// the default for `--as grey`: anti-aliasing renderers do not snap), or their plain
    /// forms.
    #[arg(long)]
    model: Option<String>,
    #[command(flatten)]
    convention: ConventionArgs,
    /// The uncovered colour of a mask PNG, 8-bit channels (default: transparent black
    /// for images with alpha, black for images without).
    #[arg(long, value_name = "R,G,B[,A]")]
    background: Option<String>,
    /// Write the difference picture (PNG): grey where both cover a pixel alike, red
    /// missing, green extra, yellow wrong owner, magenta double, black neither; scaled up
    /// for small canvases, its legend beside it as DIFF.legend.txt.
    #[arg(long = "diff-out", value_name = "DIFF.png")]
    diff_out: Option<PathBuf>,
    /// Write the comparison as one self-contained HTML page: the three images side by
    /// side, zoom and pan, each pixel's explanation on click.
    #[arg(long, value_name = "REPORT.html")]
    html: Option<PathBuf>,
    /// Output format on stdout.
    #[arg(long = "format", default_value_t = OutputFormat::Text, value_parser = OutputFormat::parser(FORMATS))]
    format_out: OutputFormat,
    /// Text output: how many differing pixels to explain one by one (JSON lists all).
    #[arg(long, default_value_t = 20)]
    limit: usize,
    /// How many differing pixels to classify (each runs exact searches; a few ms): N, or
    /// `all`. Every differing pixel is found and counted by kind whatever N is; beyond N,
    /// the first N/2 in row order and N/2 spread evenly over the rest are classified.
    #[arg(long, value_name = "N|all", default_value = "2000", value_parser = parse_classify)]
    classify: Classify,
    /// Threads drawing the scene's exact coverage (default 1): bands of 64-row tiles, the
    /// same coverage as one thread's (the classification of differing pixels runs on one).
    #[arg(long, default_value_t = 1, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=256))]
    jobs: u32,
    /// Instead of comparing under one convention, search them all: tie rule (top-left,
    /// bottom-left, top-right, bottom-right, all-inclusive, all-exclusive), snapping (0..=16
    /// subpixel bits x 5 roundings, or none) and sample position (0.5 or 0); print every
    /// convention under which the oracle's image equals theirs, or the closest five. Exit 0
    /// when one does, 1 when none does.
    #[arg(long, conflicts_with_all = ["diff_out", "model", "html"])]
    fit: bool,
    /// The sample pattern of their output, replacing the scene's `samples`: N samples per
    /// pixel at the standard positions (1, 2, 4, 8 or 16). Under a pattern of several
    /// samples THEIRS is one ids (or mask) image per sample index, stacked (width W,
    /// height N x H, sample s in rows s H .. (s + 1) H; what `render --ids-out` writes),
    /// and each sample index is compared (or, with `--fit`, fitted, and the positions on the
    /// 1/16 px grid that give its image listed) on its own.
    #[arg(long, value_name = "N")]
    samples: Option<usize>,
    /// Judge THEIRS (read as a mask, or the pixels an ids image covers) as conservative
    /// rasterization under RULE (`d3d12-tier1`, `d3d12-tier2`, `d3d12-tier3`, `vulkan`;
    /// see `render --conservative`): right when every pixel it must cover is covered and
    /// none beyond those it may cover is. Exit 0 when right, 1 otherwise.
    #[arg(long, value_name = "RULE", conflicts_with_all = ["fit", "diff_out", "html", "samples"])]
    conservative: Option<String>,
    /// With `--as grey`: the exact area semantics their levels approximate (`true`,
    /// `accumulated` or `unclamped`; see `render --coverage area`).
    #[arg(long, default_value = "true", value_name = "true|accumulated|unclamped")]
    semantics: String,
    /// With `--as grey`: how their levels quantize a value (`round`, `truncate`,
    /// `ftgrays`: 8-bit; `round16`: 16-bit). A pixel whose level is another rounding of the
    /// exact value is classed `quantization`.
    #[arg(long, default_value = "round", value_name = "round|truncate|ftgrays|round16")]
    quantization: String,
}

/// `--classify`: a bound, or none.
#[derive(Clone, Copy, Debug)]
struct Classify(Option<usize>);

/// `--classify N|all`.
fn parse_classify(s: &str) -> Result<Classify, String> {
    if s == "all" {
        return Ok(Classify(None));
    }
    s.parse::<usize>()
        .map(|n| Classify(Some(n)))
        .map_err(|_| "expected a number of pixels or `all`".to_string())
}

/// `--format`'s values for `compare`, with their help.
const FORMATS: [(OutputFormat, &str); 2] = [
    (
        OutputFormat::Text,
        "The summary table (findings by pixel kind and reason class), then the first \
         `--limit` pixels, each with its exact explanation",
    ),
    (
        OutputFormat::Json,
        "Everything, as one JSON object (schema in docs/oracle.md, `compare`)",
    ),
];

/// `--background R,G,B[,A]`.
fn parse_background(text: &str) -> Result<Background, String> {
    let parts: Result<Vec<u8>, _> = text.split(',').map(|p| p.trim().parse::<u8>()).collect();
    let bad = || format!("--background: {text:?} is not R,G,B or R,G,B,A with channels 0..=255");
    match parts.map_err(|_| bad())?.as_slice() {
        [r, g, b] => Ok(Background {
            rgb: [*r, *g, *b],
            alpha: None,
        }),
        [r, g, b, a] => Ok(Background {
            rgb: [*r, *g, *b],
            alpha: Some(*a),
        }),
        _ => Err(bad()),
    }
}

/// Compares their output with the oracle (or, with `--fit`, searches the conventions),
/// writes `--diff-out` and prints the report; exit 1 when the images differ (or no
/// convention fits).
pub fn run(o: &Options) -> Result<ExitCode, String> {
    if o.theirs_as.as_deref() == Some("grey") {
        return run_grey(o);
    }
    if o.semantics != "true" || o.quantization != "round" {
        return Err("--semantics and --quantization are for --as grey".to_string());
    }
    let model = super::parse_model(o.model.as_deref().unwrap_or("exact-snapped"))?;
    let format = match &o.theirs_as {
        Some(f) => Format::from_name(f)
            .ok_or_else(|| format!("--as: unknown format {f:?} (expected mask, ids, json or grey)"))?,
        None if o.theirs.extension().is_some_and(|e| e.eq_ignore_ascii_case("json")) => Format::Json,
        None => Format::Ids,
    };
    let background = o
        .background
        .as_deref()
        .map(parse_background)
        .transpose()?
        .unwrap_or_default();
    if o.background.is_some() && format != Format::Mask {
        return Err("--background: only a mask (--as mask) has a background".to_string());
    }
    let (name, scene, target) = super::load_scene_with(&o.scene, &o.convention, o.jobs as usize)?;
    let theirs_name = o.theirs.display().to_string();
    let bytes = std::fs::read(&o.theirs).map_err(|e| format!("{theirs_name}: cannot read: {e}"))?;
    let theirs = Theirs::read(&bytes, &theirs_name, format, background).map_err(|e| e.to_string())?;
    if let Some(rule) = &o.conservative {
        let rule = super::parse_conservative(rule)?;
        let sets = rasterproof::model::render_conservative(&scene.primitives(), &target, &rule)
            .map_err(|e| format!("{name}: {e}"))?;
        let report = rasterproof::oracle::conservative::judge_conservative(&sets, &rule, &theirs)
            .map_err(|e| format!("{theirs_name}: {e} ({name})"))?;
        match o.format_out {
            OutputFormat::Text => {
                super::write_stdout(|out| out.write_all(report.to_text(&name, &theirs_name, o.limit).as_bytes()))?
            }
            OutputFormat::Json => super::print_stdout(&report.to_json().to_string())?,
        }
        return Ok(if report.right() {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(1)
        });
    }
    let pattern = match o.samples {
        Some(n) => Some(super::parse_samples(n)?),
        None => scene.samples.clone(),
    };
    if let Some(pattern) = pattern.filter(|p| !p.is_single(&target.convention)) {
        if o.diff_out.is_some() || o.html.is_some() {
            return Err(format!(
                "{name}: under the {pattern} sample pattern compare prints its comparison per sample (text or JSON); --diff-out and --html are for one sample per pixel"
            ));
        }
        let per_sample = Samples {
            name: &name,
            theirs_name: &theirs_name,
            primitives: scene.primitives(),
            target,
            pattern,
        };
        return if o.fit {
            per_sample.fit(o, &theirs)
        } else {
            per_sample.compare(o, model, &theirs)
        };
    }
    if o.fit {
        let found = rasterproof::oracle::fit(&scene.primitives(), &target, &theirs).map_err(|e| match e {
            rasterproof::oracle::FitError::Size(_) => format!("{theirs_name}: {e} ({name})"),
            other => format!("{name}: {other}"),
        })?;
        match o.format_out {
            OutputFormat::Text => super::write_stdout(|out| {
                writeln!(
                    out,
                    "compare --fit: {theirs_name} (as {}) against {name}",
                    format.name()
                )?;
                out.write_all(found.to_text().as_bytes())
            })?,
            OutputFormat::Json => super::print_stdout(&found.to_json().to_string())?,
        }
        return Ok(if found.exact.is_empty() {
            ExitCode::from(1)
        } else {
            ExitCode::SUCCESS
        });
    }
    let report = compare_classifying(
        &scene.primitives_parallel(o.jobs as usize),
        &target,
        &theirs,
        model,
        o.classify.0,
        o.jobs as usize,
    )
    .map_err(|e| match e {
        rasterproof::oracle::CompareError::Size(_) => format!("{theirs_name}: {e} ({name})"),
        other => format!("{name}: {other} (model {model})"),
    })?;
    let mut outputs = Outputs::new();
    if let Some(path) = &o.diff_out {
        let scale = Scale::default_for(target.width, target.height);
        outputs.stage_png(path, &report.diff_picture(scale))?;
        outputs.stage_text(&legend_path(path), &report.diff_legend(scale))?;
    }
    if let Some(path) = &o.html {
        let scene_text = std::fs::read_to_string(&o.scene).unwrap_or_else(|_| scene.to_json());
        let command = shell_words::join(std::env::args());
        outputs.stage_text(path, &report.to_html(&name, &theirs_name, &scene_text, &command))?;
    }
    outputs.commit()?;
    match o.format_out {
        OutputFormat::Text => {
            super::write_stdout(|out| out.write_all(report.to_text(&name, &theirs_name, o.limit).as_bytes()))?
        }
        OutputFormat::Json => super::print_stdout(&report.to_json(&name, &theirs_name).to_string())?,
    }
    Ok(if report.identical() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// `--fit` under a pattern tries every sample position on this grid (1/16 px: the grid of
/// the standard patterns and of D3D's and Vulkan's programmable sample positions).
const POSITION_GRID: u32 = 16;

/// A comparison under a pattern of several samples.
struct Samples<'a> {
    name: &'a str,
    theirs_name: &'a str,
    primitives: rasterproof::model::Primitives,
    target: rasterproof::convention::Target,
    pattern: rasterproof::pattern::SamplePattern,
}

impl Samples<'_> {
    /// Every sample index compared; exit 0 when all are identical, 1 otherwise.
    fn compare(&self, o: &Options, model: rasterproof::model::Model, theirs: &Theirs) -> Result<ExitCode, String> {
        let report = rasterproof::oracle::samples::compare_samples(
            &self.primitives,
            &self.target,
            &self.pattern,
            theirs,
            model,
            o.classify.0,
        )
        .map_err(|e| match e {
            rasterproof::oracle::CompareError::Samples(_) => format!("{}: {e} ({})", self.theirs_name, self.name),
            other => format!("{}: {other} (model {model}, {} samples)", self.name, self.pattern),
        })?;
        match o.format_out {
            OutputFormat::Text => super::write_stdout(|out| {
                out.write_all(report.to_text(self.name, self.theirs_name, o.limit).as_bytes())
            })?,
            OutputFormat::Json => super::print_stdout(&report.to_json(self.name, self.theirs_name).to_string())?,
        }
        Ok(if report.identical() {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(1)
        })
    }

    /// `--fit` per sample index: each sample's image against every convention, the scene
    /// moved exactly to that sample (unsnapped: each candidate snaps the moved scene, which
    /// is the snapped scene moved except at a coordinate exactly halfway between two
    /// subpixels); then the conventions that give every sample. Exit 0 when one does.
    fn fit(&self, o: &Options, theirs: &Theirs) -> Result<ExitCode, String> {
        use rasterproof::model::{Model, SampleFrames};
        let per_sample = theirs
            .unstack(self.pattern.len(), self.target.height)
            .map_err(|e| format!("{}: {e} ({})", self.theirs_name, self.name))?;
        let frames = SampleFrames::new(&self.primitives, &self.target, &self.pattern, Model::Exact)
            .map_err(|e| format!("{}: {e}", self.name))?;
        let mut fits = Vec::new();
        for (s, theirs) in per_sample.iter().enumerate() {
            let moved = frames.at(s).map_err(|e| format!("{}: {e}", self.name))?;
            let found = rasterproof::oracle::fit(&moved, &self.target, theirs)
                .map_err(|e| format!("{}: sample {s}: {e}", self.name))?;
            fits.push(found);
        }
        let common: Vec<_> = fits[0]
            .exact
            .iter()
            .filter(|c| fits.iter().all(|f| f.exact.contains(c)))
            .collect();
        // Where their samples sit: every 1/16 px position that gives each sample index's
        // image under the scene's own convention.
        let positions = rasterproof::oracle::samples::fit_positions(
            &self.primitives,
            &self.target,
            &self.pattern,
            &per_sample,
            Model::ExactSnapped,
            POSITION_GRID,
        )
        .map_err(|e| format!("{}: {e}", self.name))?;
        let exact_text = |p: &[num_rational::BigRational; 2]| {
            format!(
                "({}, {})",
                rasterproof::num::exact::exact_text(&p[0]),
                rasterproof::num::exact::exact_text(&p[1])
            )
        };
        match o.format_out {
            OutputFormat::Text => super::write_stdout(|out| {
                writeln!(
                    out,
                    "compare --fit: {} against {}, {} samples, each sample index on its own",
                    self.theirs_name, self.name, self.pattern
                )?;
                for (s, f) in fits.iter().enumerate() {
                    writeln!(out, "sample {s} at {}:", self.pattern.position_text(s))?;
                    for line in f.to_text().lines() {
                        writeln!(out, "  {line}")?;
                    }
                }
                writeln!(
                    out,
                    "sample positions on the 1/{POSITION_GRID} px grid that give each sample's image under {}:",
                    self.target.convention
                )?;
                for p in &positions {
                    let listed: Vec<String> = p.fits.iter().take(8).map(exact_text).collect();
                    let more = p.fits.len().saturating_sub(8);
                    writeln!(
                        out,
                        "  sample {}: the pattern's {} {}; {} of {} positions fit{}{}",
                        p.index,
                        self.pattern.position_text(p.index),
                        if p.standard_fits { "fits" } else { "does NOT fit" },
                        p.fits.len(),
                        POSITION_GRID * POSITION_GRID,
                        if listed.is_empty() {
                            String::new()
                        } else {
                            format!(": {}", listed.join(" "))
                        },
                        if more > 0 {
                            format!(" and {more} more")
                        } else {
                            String::new()
                        }
                    )?;
                }
                if common.is_empty() {
                    writeln!(out, "no convention gives every sample's image exactly (if each sample has fits of its own, their sample positions are not the {}'s)", self.pattern)
                } else {
                    writeln!(
                        out,
                        "{} conventions give every sample's image exactly, at the {} positions:",
                        common.len(),
                        self.pattern
                    )?;
                    for c in &common {
                        writeln!(out, "  {c}")?;
                    }
                    Ok(())
                }
            })?,
            OutputFormat::Json => super::print_stdout(
                &serde_json::json!({
                    "pattern": self.pattern.to_json(),
                    "every_sample": common.iter().map(ToString::to_string).collect::<Vec<_>>(),
                    "samples": fits.iter().map(|f| f.to_json()).collect::<Vec<_>>(),
                    "positions": positions.iter().map(|p| serde_json::json!({
                        "index": p.index,
                        "pattern_fits": p.standard_fits,
                        "fits": p.fits.iter().map(exact_text).collect::<Vec<_>>(),
                    })).collect::<Vec<_>>(),
                })
                .to_string(),
            )?,
        }
        Ok(if common.is_empty() {
            ExitCode::from(1)
        } else {
            ExitCode::SUCCESS
        })
    }
}

/// `compare --as grey`: their grey levels against the exact area coverage; exit 0 when
/// every pixel has the exact value's level, 1 when some differ.
fn run_grey(o: &Options) -> Result<ExitCode, String> {
    if o.diff_out.is_some() || o.html.is_some() || o.background.is_some() {
        return Err("--as grey prints its comparison (text or JSON); --diff-out, --html and --background are for the one-sample formats".to_string());
    }
    let model = super::parse_model(o.model.as_deref().unwrap_or("exact"))?;
    let semantics = super::parse_semantics(&o.semantics)?;
    let quantization = super::parse_quantization(&o.quantization)?;
    let (name, scene, target) = super::load_scene_with(&o.scene, &o.convention, o.jobs as usize)?;
    let theirs_name = o.theirs.display().to_string();
    let bytes = std::fs::read(&o.theirs).map_err(|e| format!("{theirs_name}: cannot read: {e}"))?;
    let theirs = rasterproof::oracle::grey::GreyImage::read_png(&bytes, &theirs_name)?;
    let shapes = rasterproof::model::area_shapes(&scene.primitives(), &target, model)
        .map_err(|e| format!("{name}: {e} (model {model})"))?;
    if o.fit {
        let found = rasterproof::oracle::grey::fit_grey(&shapes, &theirs, target.width, target.height)
            .map_err(|e| format!("{theirs_name}: {e} ({name})"))?;
        let exact: Vec<_> = found.iter().filter(|(_, n)| *n == 0).collect();
        match o.format_out {
            OutputFormat::Text => super::write_stdout(|out| {
                writeln!(out, "compare --as grey --fit: {theirs_name} against {name} (model {model})")?;
                writeln!(out, "{} methods tried, {} give their image exactly", found.len(), exact.len())?;
                let closest: Vec<_> = found.iter().take(5).collect();
                for (m, n) in if exact.is_empty() { closest } else { exact.clone() } {
                    writeln!(out, "  {}: {n} pixels differ", m.describe())?;
                }
                Ok(())
            })?,
            OutputFormat::Json => super::print_stdout(
                &serde_json::json!({
                    "tried": found.len(),
                    "methods": found.iter().map(|(m, n)| serde_json::json!({"method": m.describe(), "differing": n})).collect::<Vec<_>>(),
                })
                .to_string(),
            )?,
        }
        return Ok(if exact.is_empty() {
            ExitCode::from(1)
        } else {
            ExitCode::SUCCESS
        });
    }
    let report =
        rasterproof::oracle::grey::compare_grey(&shapes, &theirs, target.width, target.height, semantics, quantization)
            .map_err(|e| format!("{theirs_name}: {e} ({name})"))?;
    match o.format_out {
        OutputFormat::Text => super::write_stdout(|out| {
            writeln!(out, "compare --as grey: {theirs_name} against {name} (model {model})")?;
            out.write_all(report.to_text(o.limit).as_bytes())
        })?,
        OutputFormat::Json => super::print_stdout(&report.to_json().to_string())?,
    }
    Ok(if report.pixels.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
