//! `rasterproof compare`: another renderer's output against the oracle, every differing
//! pixel explained ([`rasterproof::oracle::compare`]).

use std::path::PathBuf;
use std::process::ExitCode;

use rasterproof::area::Quantization;
use rasterproof::coverage::picture::{legend_path, Scale};
use rasterproof::oracle::compare::fit::samples::{SampleFitOptions, POSITION_GRID};
use rasterproof::oracle::compare::grey::GreyOptions;
use rasterproof::oracle::compare::samples::SampleOptions;
use rasterproof::oracle::compare::HtmlInputs;
use rasterproof::oracle::{judge, Background, CompareOptions, Comparison, Format, Question};

use super::value_args::{read_theirs, their_format, ValueArgs};
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
    /// with the exact area coverage: see --semantics and --quantization), or values (one
    /// varying's interpolated values: a float32 TIFF or a UNORM PNG, judged at every
    /// pixel the oracle covers; see --varying). Default: json for a .json file, values
    /// for a .tif or .tiff file, ids otherwise.
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
    /// side, zoom and pan, each pixel's explanation on click (grey levels by class, each
    /// sample index of a pattern, a conservative set's must-pixels and band, and values:
    /// the exact values and theirs in grey, each judged pixel coloured by class, alike).
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
    #[arg(long, value_name = "RULE", conflicts_with_all = ["fit", "diff_out", "samples"])]
    conservative: Option<String>,
    /// With `--as grey`: the exact area semantics their levels approximate (`true`,
    /// `accumulated` or `unclamped`; see `render --coverage area`).
    #[arg(long, default_value = "true", value_name = "true|accumulated|unclamped")]
    semantics: String,
    /// With `--as grey`: how their levels quantize a value (`round`: to the nearest level
    /// at their image's depth, 8 or 16 bits; `truncate`, `ftgrays`: 8-bit; `round16`:
    /// 16-bit). A pixel whose level is another rounding of the exact value is classed
    /// `quantization`.
    #[arg(long, default_value = "round", value_name = "round|truncate|ftgrays|round16")]
    quantization: String,
    /// With `--as grey`: judge against this method of the area family (a name `--fit`
    /// prints, e.g. `supersample-4x4-round`, `exact-accumulated-truncate` or `ftgrays`)
    /// instead of the exact value's levels: the pixels listed are those where their level
    /// is not the method's, each still classed against the exact value. The method names
    /// its semantics and quantization (leave out --semantics and --quantization). Exit 0
    /// when it gives every level.
    #[arg(long, value_name = "NAME", conflicts_with_all = ["fit", "semantics", "quantization"])]
    method: Option<String>,
    #[command(flatten)]
    values: ValueArgs,
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

/// Compares their output with the oracle (or, with `--fit`, searches the conventions):
/// parses the options into one [`Question`], reads both files, asks
/// [`rasterproof::oracle::judge`], writes `--diff-out` and `--html`, and prints the report;
/// exit 1 when the images differ (or no convention fits).
pub fn run(o: &Options) -> Result<ExitCode, String> {
    let format = their_format(o.theirs_as.as_deref(), &o.theirs)?;
    let background = background(o, format)?;
    let grey = format == Format::Grey;
    if grey && o.diff_out.is_some() {
        return Err(GREY_PRINTS.to_string());
    }
    if !grey && (o.semantics != "true" || o.quantization != "round" || o.method.is_some()) {
        return Err("--semantics, --quantization and --method are for --as grey".to_string());
    }
    let values = format == Format::Values;
    o.values.only_for_values(values)?;
    if values && (o.diff_out.is_some() || o.conservative.is_some()) {
        return Err(
            "--as values prints its comparison (text, JSON or --html); --diff-out and --conservative are for coverage"
                .to_string(),
        );
    }
    let model = super::parse_model(
        o.model
            .as_deref()
            .unwrap_or(if grey { "exact" } else { "exact-snapped" }),
    )?;
    let semantics = super::parse_semantics(&o.semantics)?;
    let quantization = super::parse_quantization(&o.quantization)?;
    let (name, scene, target) = super::load_scene_with(&o.scene, &o.convention, o.jobs as usize)?;
    let (theirs_name, theirs) = read_theirs(&o.theirs, format, background)?;
    // Rounding is read at their image's depth (8 or 16 bits); the other quantizations
    // name theirs.
    let quantization = match theirs.grey() {
        Some(g) if quantization == Quantization::Round8 => quantization.at_depth(g.bits).unwrap_or(quantization),
        _ => quantization,
    };
    let method = match (&o.method, theirs.grey()) {
        (Some(name), Some(g)) => Some(super::parse_grey_method(name, Some(g.bits))?),
        _ => None,
    };
    let (semantics, quantization) = match (method, theirs.grey()) {
        (Some(m), Some(g)) => m.judged_as(g.bits),
        _ => (semantics, quantization),
    };
    let grey_options = grey.then_some(GreyOptions {
        model,
        semantics,
        quantization,
        method,
    });
    let pattern = match o.samples {
        Some(n) => Some(super::parse_samples(n)?),
        None => scene.samples.clone(),
    }
    .filter(|p| !p.is_single(&target.convention));
    let question = match (grey_options, &o.conservative, pattern.clone()) {
        _ if values => {
            let options = o
                .values
                .options(&scene, &name, model, pattern, &target)?
                .with_picture(o.html.is_some());
            if o.fit {
                Question::FitValues(Box::new(options))
            } else {
                Question::Values(Box::new(options))
            }
        }
        (Some(g), ..) if o.fit => Question::FitGrey(g.model),
        (Some(g), ..) => Question::Grey(g),
        (None, Some(rule), _) => Question::Conservative(super::parse_conservative(rule)?),
        (None, None, Some(pattern)) if o.diff_out.is_some() => {
            return Err(format!(
                "{name}: under the {pattern} sample pattern compare prints its comparison per sample (text, JSON or --html); --diff-out is for one sample per pixel"
            ))
        }
        (None, None, Some(pattern)) if o.fit => Question::FitSamples(SampleFitOptions {
            pattern,
            grid: POSITION_GRID,
        }),
        (None, None, Some(pattern)) => Question::Samples(SampleOptions {
            pattern,
            model,
            classify_at_most: o.classify.0,
        }),
        (None, None, None) if o.fit => Question::Fit,
        (None, None, None) => Question::Binary(CompareOptions {
            model,
            classify_at_most: o.classify.0,
            jobs: o.jobs as usize,
        }),
    };
    let judgement = judge(&scene.primitives_parallel(o.jobs as usize), &target, &theirs, &question)
        .map_err(|e| question.error_text(&e, &name, &theirs_name))?;
    let mut outputs = Outputs::new();
    if let (Some(path), Some(report)) = (&o.diff_out, judgement.binary()) {
        let scale = Scale::default_for(target.width, target.height);
        outputs.stage_png(path, &report.diff_picture(scale))?;
        outputs.stage_text(&legend_path(path), &report.diff_legend(scale))?;
    }
    if let Some(path) = &o.html {
        let scene_json = std::fs::read_to_string(&o.scene).unwrap_or_else(|_| scene.to_json());
        let command = shell_words::join(std::env::args());
        let page = HtmlInputs {
            scene: &name,
            theirs: &theirs_name,
            scene_json: &scene_json,
            command: &command,
        };
        if let Some(html) = judgement.to_html(&page) {
            outputs.stage_text(path, &html)?;
        }
    }
    outputs.commit()?;
    match o.format_out {
        OutputFormat::Text => {
            super::write_stdout(|out| out.write_all(judgement.to_text(&name, &theirs_name, o.limit).as_bytes()))?
        }
        OutputFormat::Json => super::print_stdout(&judgement.to_json(&name, &theirs_name).to_string())?,
    }
    Ok(if judgement.identical() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// Why `--as grey` refuses the picture and page options.
const GREY_PRINTS: &str =
    "--as grey prints its comparison (text, JSON or --html); --diff-out and --background are for the one-sample formats";

/// `--background`, which only a mask has.
fn background(o: &Options, format: Format) -> Result<Background, String> {
    if o.background.is_some() && format == Format::Grey {
        return Err(GREY_PRINTS.to_string());
    }
    let background = o.background.as_deref().map(parse_background).transpose()?;
    if background.is_some() && format != Format::Mask {
        return Err("--background: only a mask (--as mask) has a background".to_string());
    }
    Ok(background.unwrap_or_default())
}
