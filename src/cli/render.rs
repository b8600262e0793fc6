//! `rasterproof render`.

use std::path::PathBuf;
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};
use rasterproof::area::{AreaImage, Quantization, Semantics};
use rasterproof::convention::Target;
use rasterproof::coverage::picture::{legend_path, upscale};
use rasterproof::coverage::Coverage;
use rasterproof::coverage::{Scale, ASCII_GRID_MAX_SIDE};
use rasterproof::model::plan;
use rasterproof::model::{
    exact_pixel_values, exact_values, prepare_parallel, render_area_rows, values_image, values_json, values_tiff,
    Model, PreparedScene,
};
use rasterproof::num::exact::{counted, exact_text, terminating_decimal};
use std::time::{Duration, Instant};

use super::{OutputFormat, Outputs};

/// What `render` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// The scene file (JSON).
    scene: PathBuf,
    /// The model (default exact-snapped; exact with `--coverage area`: anti-aliasing
    /// renderers do not snap); `--help` lists them and says what exact and exact-snapped
    /// mean.
    #[arg(long, long_help = crate::cli::model_help())]
    model: Option<String>,
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
    /// Write one varying's exact values (the scene's `varyings`; one sample per pixel)
    /// as a UNORM PNG: each channel the level nearest the exact value (ties to even,
    /// clamped to [0, 1]); 1 channel grey, 2 grey and alpha, 3 RGB, 4 RGBA. Or, for a
    /// file ending in .tif or .tiff, as a float32 TIFF: each channel the exact value
    /// rounded once to the nearest f32; 1 channel grey, 2 or 3 RGB, 4 RGBA. 0 where no
    /// value; never scaled. `--varying` names the varying (default the first), `--unorm`
    /// the bits a channel of a PNG (8, default, or 16).
    #[arg(long = "values-out", value_name = "VALUES.png|VALUES.tiff")]
    values_out: Option<PathBuf>,
    /// With `--values-out`: the varying drawn (default the scene's first).
    #[arg(long, value_name = "NAME")]
    varying: Option<String>,
    /// With `--values-out`: bits a channel, 8 or 16.
    #[arg(long, default_value_t = 8, value_name = "BITS")]
    unorm: u32,
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
    /// What a pixel's answer is: `sample` (one sample per pixel, covered or not) or `area`
    /// (anti-aliased coverage: the exact fraction of the pixel's square inside the shapes,
    /// a rational number; triangles and polygons only, exact models only). With `area`,
    /// `--format json` prints `{"width","height","coverage":"area","semantics","model",
    /// "pixels":[[x,y,"n/d"],...]}` (every pixel with a value, by row) and the text grid
    /// shows tenths (`.` none, `1`-`9` tenths, `#` whole).
    #[arg(long, default_value = "sample", value_name = "sample|area")]
    coverage: String,
    /// With `--coverage area`, which area: `true` (the part of the pixel inside under the
    /// fill rule; the union of the shapes), `accumulated` (the integral of the winding
    /// number, folded as FreeType's ftgrays.c folds it: nonzero min(1, |acc|), even-odd
    /// modulo 2; each shape's value summed, as an accumulation buffer does) or `unclamped`
    /// (|acc|, not folded: font-rs, ab_glyph).
    #[arg(long, default_value = "true", value_name = "true|accumulated|unclamped")]
    semantics: String,
    /// With `--coverage area`: write the grey image (PNG, 8-bit grey, 16-bit for
    /// `round16`; never scaled), each pixel its value quantized by `--quantization`.
    #[arg(long = "grey-out", value_name = "GREY.png")]
    grey_out: Option<PathBuf>,
    /// How `--grey-out` quantizes a value v (clamped to [0, 1]): `round` (v x 255, to the
    /// nearest, ties to even), `truncate` (v x 255 towards zero), `ftgrays` (FreeType's
    /// smooth rasterizer: v x 256 truncated, 256 clamped to 255), `round16` (v x 65535
    /// to the nearest, ties to even; 16-bit PNG).
    #[arg(long, default_value = "round", value_name = "round|truncate|ftgrays|round16")]
    quantization: String,
    /// The sample pattern, replacing the scene's `samples`: N samples per pixel at the
    /// standard positions of Vulkan and Direct3D (1, 2, 4, 8 or 16). Under a pattern of
    /// several samples a pixel's answer is its sample mask: `--ids-out` writes one ids
    /// image per sample index, stacked (width W, height N x H, sample s in rows s H ..
    /// (s + 1) H), `--count-out` the covered samples as a grey level, `--format json`
    /// `{"width","height","samples","pixels":[[x,y,mask,[ids of sample 0],...],...]}`, and
    /// the text grid the number of covered samples (`.` none, `1`-`9`, `a`-`f`, `#` all).
    #[arg(long, value_name = "N")]
    samples: Option<usize>,
    /// With a pattern: write the coverage count (PNG, 8-bit grey): round(255 k / N) for k
    /// of the N samples covered, what resolving a multisampled target holding the scene in
    /// opaque white on black gives.
    #[arg(long = "count-out", value_name = "COUNT.png")]
    count_out: Option<PathBuf>,
    /// Conservative rasterization instead of samples: the pixels a renderer must cover and
    /// those it may, exactly, under `d3d12-tier1` (uncertainty 1/2 px, post-snap
    /// degenerates may be culled), `d3d12-tier2` (1/256 px, degenerates kept),
    /// `d3d12-tier3` (as tier 2, with inner coverage) or `vulkan` (1/256 px of
    /// overestimation, touching pixels must be covered, with underestimation). Triangles
    /// only. The text grid shows `#` must, `+` may, `.` neither (then the inner coverage
    /// the same way); `--format json` gives `{"rule","must":[[x,y,[ids]]...],"may":...,
    /// "inner_must","inner_may","one_of":[[id,[[x,y]...]]]}`; `-o SETS.png` a grey PNG:
    /// 255 must, 128 may, 0 neither.
    #[arg(long, value_name = "RULE")]
    conservative: Option<String>,
    /// Threads drawing the scene (default 1): the canvas is cut into bands of 64-row
    /// tiles, each drawn by one thread, and the outputs are byte-identical to one
    /// thread's. The one-sample coverage only (`--as area`, `--samples` and
    /// `--conservative` draw on one thread).
    #[arg(long, default_value_t = 1, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=256))]
    jobs: u32,
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
        r#"`{"width":W,"height":H,"pixels":[[x,y,[ids...]],...]}`; a scene that declares varyings adds `"values":{"varyings":[...],"provoking_vertex","samples":[[x,y,sample,id,[value per varying]],...]}`, each value its channels as exact strings, or why there is none (`not-carried`, `horizon`), computed exactly at the scene's vertices for the samples the model covers"#,
    ),
];

/// Renders the scene with the model `o` names, writes the pictures asked for (all or
/// none) and prints the coverage and summary; exit 0.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    match o.coverage.as_str() {
        "sample" => {}
        "area" => return run_area(o),
        other => return Err(format!("--coverage: unknown kind {other:?} (expected sample or area)")),
    }
    if o.values_out.is_none() && (o.varying.is_some() || o.unorm != 8) {
        return Err("--varying and --unorm need --values-out".to_string());
    }
    if o.grey_out.is_some() || o.semantics != "true" || o.quantization != "round" {
        return Err("--grey-out, --semantics and --quantization need --coverage area".to_string());
    }
    let model = super::parse_model(o.model.as_deref().unwrap_or("exact-snapped"))?;
    let scale_asked = o.scale.as_deref().map(parse_scale).transpose()?;
    let (name, scene, target) = super::load_scene_with(&o.scene, &o.convention, o.jobs as usize)?;
    if let Some(rule) = &o.conservative {
        return run_conservative(o, rule, &name, &scene, &target);
    }
    let pattern = match o.samples {
        Some(n) => Some(super::parse_samples(n)?),
        None => scene.samples.clone(),
    };
    if let Some(pattern) = pattern.filter(|p| !p.is_single(&target.convention)) {
        return run_samples(o, model, &name, &scene, &target, &pattern);
    }
    if o.count_out.is_some() {
        return Err(format!(
            "--count-out needs a pattern of several samples (--samples N, or the scene's samples); {name} has one sample per pixel"
        ));
    }
    let scale = match scale_asked {
        Some(k) => Scale::new(k, target.width, target.height).map_err(|e| format!("--scale: {e} (scene {name})"))?,
        None => Scale::default_for(target.width, target.height),
    };
    let fail = |e: rasterproof::model::ModelError| format!("{name}: {e} (model {model})");
    let primitives = scene.primitives_parallel(o.jobs as usize);
    let prepared = prepare_parallel(&primitives, &target, model, o.jobs as usize).map_err(fail)?;
    let small = target.width <= ASCII_GRID_MAX_SIDE && target.height <= ASCII_GRID_MAX_SIDE;
    let whole = o.out.is_some() || o.colors_out.is_some() || o.ids_out.is_some() || o.values_out.is_some() || small;
    if !whole && matches!(o.format, OutputFormat::Text) && prepared.bands_skip_all() {
        // Only the summary, of triangles only: the frame is counted band by band, in the
        // memory of a few bands instead of the whole canvas.
        let (covered, double) = count_with_progress(&prepared, &target, o.jobs as usize);
        let summary = summary(&name, model, &target, covered, double, &prepared);
        crate::cli::print_stdout(&summary)?;
        std::mem::forget((scene, primitives, prepared));
        return Ok(ExitCode::SUCCESS);
    }
    let coverage = draw_with_progress(&prepared, &target, o.jobs as usize);

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
    if let Some(path) = &o.values_out {
        let tiff = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("tif") || e.eq_ignore_ascii_case("tiff"));
        match values_out(o, &name, &scene, &coverage, &target, tiff)? {
            Ok(image) => outputs.stage(path, "PNG", |out| image.write_to(out, image::ImageFormat::Png))?,
            Err(bytes) => outputs.stage(path, "TIFF", |out| std::io::Write::write_all(out, &bytes))?,
        }
        wrote.push(format!("{} (values, unscaled)", path.display()));
    }
    if let Some(path) = &o.ids_out {
        let ids = coverage
            .to_ids_image()
            .map_err(|e| format!("--ids-out {}: {e} (scene {name})", path.display()))?;
        outputs.stage_png(path, &ids)?;
        wrote.push(format!("{} (ids, unscaled)", path.display()));
    }
    outputs.commit()?;

    let double = coverage.double_covered().count();
    let mut summary = summary(&name, model, &target, coverage.covered_pixels(), double, &prepared);
    if !wrote.is_empty() {
        let k = scale.get();
        summary.push_str(&format!("; wrote {} (scale {k})", wrote.join(", ")));
    }
    match o.format {
        OutputFormat::Json if !scene.varyings.list.is_empty() => {
            let values = exact_pixel_values(&coverage, &scene.value_setups(), &scene.varyings, &target);
            crate::cli::print_stdout(&values_json(coverage.to_json(), &scene.varyings, &values))?;
            eprintln!("{summary}");
        }
        OutputFormat::Json => {
            crate::cli::write_stdout(|out| {
                coverage.write_json(out)?;
                writeln!(out)
            })?;
            eprintln!("{summary}");
        }
        OutputFormat::Text => {
            let grid = if small { coverage.to_ascii() } else { String::new() };
            crate::cli::print_stdout(&format!("{grid}{summary}"))?;
        }
    }
    // The process ends next: the system takes the memory back at once, where dropping a
    // frame's scene, triangles and coverage would walk a million triangles and 65,536
    // tiles first (some 40 ms of a 16384² frame of 1M triangles, on one thread).
    std::mem::forget((scene, primitives, prepared, coverage));
    Ok(ExitCode::SUCCESS)
}

/// `--values-out`'s image: the varying `--varying` names (default the first), a PNG at
/// `--unorm` bits (`Ok`) or a float32 TIFF's bytes (`Err`).
fn values_out(
    o: &Options,
    name: &str,
    scene: &rasterproof::scene::Scene,
    coverage: &Coverage,
    target: &Target,
    tiff: bool,
) -> Result<Result<image::DynamicImage, Vec<u8>>, String> {
    let varyings = &scene.varyings;
    let k = varying_index(o, name, scene)?;
    let values = exact_pixel_values(coverage, &scene.value_setups(), varyings, target);
    if tiff {
        return values_tiff(&values, varyings, k, target.width, target.height, 1)
            .map(Err)
            .map_err(|e| format!("--values-out: {e} (scene {name})"));
    }
    values_image(&values, varyings, k, target.width, target.height, o.unorm)
        .map(Ok)
        .map_err(|e| format!("--values-out: {e} (scene {name}, --unorm {})", o.unorm))
}

/// The varying `--values-out` writes: the one `--varying` names, default the first.
fn varying_index(o: &Options, name: &str, scene: &rasterproof::scene::Scene) -> Result<usize, String> {
    let varyings = &scene.varyings;
    if varyings.list.is_empty() {
        return Err(format!("--values-out: {name} declares no varyings"));
    }
    match &o.varying {
        None => Ok(0),
        Some(v) => varyings.list.iter().position(|d| &d.name == v).ok_or_else(|| {
            let names: Vec<&str> = varyings.list.iter().map(|d| d.name.as_str()).collect();
            format!(
                "--varying: {name} declares no varying {v:?} (it declares {})",
                names.join(", ")
            )
        }),
    }
}

/// The summary line of a one-sample render: the pixels covered, once and more than once,
/// and the plan of a planned model.
fn summary(
    name: &str,
    model: Model,
    target: &Target,
    covered: usize,
    double: usize,
    prepared: &PreparedScene,
) -> String {
    let mut summary = format!(
        "{name}: model {model}, {}: {} covered, {double} covered more than once",
        target.convention,
        counted(covered as u64, "pixel"),
    );
    if model.plans() {
        summary.push_str(&format!("; plan: {}", plan::summary(&prepared.plans())));
    }
    summary
}

/// `render` under a pattern of several samples: every sample's coverage, the stacked ids
/// PNG, the count PNG, the masks as JSON or the count grid; exit 0.
fn run_samples(
    o: &Options,
    model: rasterproof::model::Model,
    name: &str,
    scene: &rasterproof::scene::Scene,
    target: &Target,
    pattern: &rasterproof::pattern::SamplePattern,
) -> Result<ExitCode, String> {
    let tiff = |p: &std::path::Path| {
        p.extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("tif") || e.eq_ignore_ascii_case("tiff"))
    };
    if o.out.is_some()
        || o.colors_out.is_some()
        || o.values_out.as_deref().is_some_and(|p| !tiff(p))
        || o.scale.is_some()
    {
        return Err(format!(
            "{name}: under the {pattern} sample pattern render writes --ids-out (one ids image per sample, stacked), --values-out STACKED.tiff (one float32 values image per sample, stacked) and --count-out (and each sample's values with --format json); -o, --colors-out, a PNG --values-out and --scale are for one sample per pixel"
        ));
    }
    let primitives = scene.primitives();
    let coverage = rasterproof::model::render_samples(&primitives, target, pattern, model)
        .map_err(|e| format!("{name}: {e} (model {model}, {pattern} samples)"))?;
    let mut outputs = Outputs::new();
    let mut wrote = Vec::new();
    if let Some(path) = &o.ids_out {
        let ids = coverage
            .to_stacked_ids_image()
            .map_err(|e| format!("--ids-out {}: {e} (scene {name})", path.display()))?;
        outputs.stage_png(path, &ids)?;
        wrote.push(format!("{} (ids, {} samples stacked)", path.display(), pattern.len()));
    }
    if let Some(path) = &o.values_out {
        let k = varying_index(o, name, scene)?;
        let values = exact_values(&coverage, pattern, &scene.value_setups(), &scene.varyings, target);
        let bytes = values_tiff(&values, &scene.varyings, k, target.width, target.height, pattern.len())
            .map_err(|e| format!("--values-out: {e} (scene {name})"))?;
        outputs.stage(path, "TIFF", |out| std::io::Write::write_all(out, &bytes))?;
        wrote.push(format!(
            "{} (values, {} samples stacked)",
            path.display(),
            pattern.len()
        ));
    }
    if let Some(path) = &o.count_out {
        outputs.stage_png(path, &coverage.to_count_image())?;
        wrote.push(format!("{} (covered samples, grey)", path.display()));
    }
    outputs.commit()?;
    let n = u32::try_from(pattern.len()).expect("at most 64 samples");
    let counts: Vec<(u32, u32, u32)> = coverage
        .covered_pixels()
        .into_iter()
        .map(|(x, y)| (x, y, coverage.covered_count(x, y)))
        .collect();
    let samples: u64 = counts.iter().map(|c| u64::from(c.2)).sum();
    let full = counts.iter().filter(|c| c.2 == n).count();
    let mut summary = format!(
        "{name}: model {model}, {}, {pattern} samples: {} covered, {} with some, {full} with all",
        target.convention,
        counted(samples, "sample"),
        counted(counts.len() as u64, "pixel"),
    );
    if !wrote.is_empty() {
        summary.push_str(&format!("; wrote {}", wrote.join(", ")));
    }
    match o.format {
        OutputFormat::Json => {
            let json = if scene.varyings.list.is_empty() {
                coverage.to_json()
            } else {
                let values = exact_values(&coverage, pattern, &scene.value_setups(), &scene.varyings, target);
                values_json(coverage.to_json(), &scene.varyings, &values)
            };
            crate::cli::print_stdout(&json)?;
            eprintln!("{summary}");
        }
        OutputFormat::Text => {
            let (w, h) = (target.width, target.height);
            let mut grid = String::new();
            if w <= ASCII_GRID_MAX_SIDE && h <= ASCII_GRID_MAX_SIDE {
                let mut cells = vec![b'.'; w as usize * h as usize];
                for &(x, y, k) in &counts {
                    let digit = char::from_digit(k.min(15), 16).expect("a hex digit");
                    cells[(y * w + x) as usize] = if k == n { b'#' } else { digit as u8 };
                }
                for row in cells.chunks(w as usize) {
                    grid.push_str(std::str::from_utf8(row).expect("ASCII"));
                    grid.push('\n');
                }
            }
            crate::cli::print_stdout(&format!("{grid}{summary}"))?;
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// `render --conservative RULE`: the must and may sets, as text, JSON or a grey PNG.
fn run_conservative(
    o: &Options,
    rule: &str,
    name: &str,
    scene: &rasterproof::scene::Scene,
    target: &Target,
) -> Result<ExitCode, String> {
    let rule = super::parse_conservative(rule)?;
    if o.colors_out.is_some()
        || o.values_out.is_some()
        || o.ids_out.is_some()
        || o.count_out.is_some()
        || o.samples.is_some()
        || o.model.is_some()
    {
        return Err(format!(
            "--conservative writes -o SETS.png and the sets on stdout; --colors-out, --values-out, --ids-out, --count-out, --samples and --model are for sample coverage ({name})"
        ));
    }
    let sets = rasterproof::model::render_conservative(&scene.primitives(), target, &rule)
        .map_err(|e| format!("{name}: {e}"))?;
    let (w, h) = (target.width, target.height);
    let level = |must: &Coverage, may: &Coverage, x: u32, y: u32| {
        if !must.owners(x, y).is_empty() {
            2
        } else {
            u8::from(!may.owners(x, y).is_empty())
        }
    };
    let mut outputs = Outputs::new();
    if let Some(path) = &o.out {
        let image = image::GrayImage::from_fn(w, h, |x, y| {
            image::Luma([[0, 128, 255][usize::from(level(&sets.must, &sets.may, x, y))]])
        });
        outputs.stage_png(path, &image)?;
    }
    outputs.commit()?;
    let summary = format!(
        "{name}: conservative {rule}, {}: {} must be covered, {} may{}",
        target.convention,
        counted(sets.must.covered_pixels() as u64, "pixel"),
        sets.may.covered_pixels(),
        match &sets.inner {
            Some((must, may)) => format!(
                "; inner coverage: {} must, {} may",
                must.covered_pixels(),
                may.covered_pixels()
            ),
            None => String::new(),
        }
    );
    match o.format {
        OutputFormat::Json => {
            crate::cli::print_stdout(&sets.to_json(&rule).to_string())?;
            eprintln!("{summary}");
        }
        OutputFormat::Text => {
            let mut grid = String::new();
            if w <= ASCII_GRID_MAX_SIDE && h <= ASCII_GRID_MAX_SIDE {
                let draw = |grid: &mut String, must: &Coverage, may: &Coverage| {
                    for y in 0..h {
                        for x in 0..w {
                            grid.push(['.', '+', '#'][usize::from(level(must, may, x, y))]);
                        }
                        grid.push('\n');
                    }
                };
                draw(&mut grid, &sets.must, &sets.may);
                if let Some((must, may)) = &sets.inner {
                    grid.push_str("inner coverage:\n");
                    draw(&mut grid, must, may);
                }
            }
            crate::cli::print_stdout(&format!("{grid}{summary}"))?;
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// `render --coverage area`: the exact area of every pixel, its grey image and its text
/// or JSON; exit 0.
fn run_area(o: &Options) -> Result<ExitCode, String> {
    if o.out.is_some() || o.colors_out.is_some() || o.values_out.is_some() || o.ids_out.is_some() || o.scale.is_some() {
        return Err(
            "--coverage area writes --grey-out GREY.png (and the values on stdout); -o, --colors-out, --values-out, --ids-out and --scale are for --coverage sample".to_string(),
        );
    }
    let model = super::parse_model(o.model.as_deref().unwrap_or("exact"))?;
    let semantics = super::parse_semantics(&o.semantics)?;
    let quantization = super::parse_quantization(&o.quantization)?;
    let (name, scene, target) = super::load_scene_with(&o.scene, &o.convention, o.jobs as usize)?;
    let primitives = scene.primitives();
    let fail = |e: rasterproof::model::AreaError| format!("{name}: {e} (model {model})");
    // Refusals first, before anything is written.
    rasterproof::model::area_shapes(&primitives, &target, model).map_err(fail)?;
    let (width, height) = (target.width, target.height);
    let small = width <= ASCII_GRID_MAX_SIDE && height <= ASCII_GRID_MAX_SIDE;
    let json = matches!(o.format, OutputFormat::Json);
    // The rows are streamed: to stdout as JSON, into the grey levels, into the counts; only
    // a canvas small enough for the text grid is kept whole.
    let mut tally = AreaTally {
        count: 0,
        whole: 0,
        total: BigRational::zero(),
        width,
        levels: o
            .grey_out
            .as_ref()
            .map(|_| vec![0u16; width as usize * height as usize]),
        quantization,
        kept: (small && !json).then(|| AreaImage {
            width,
            height,
            semantics,
            pixels: Vec::new(),
        }),
    };
    let stream = |tally: &mut AreaTally, out: Option<&mut dyn std::io::Write>| {
        stream_area(&primitives, &target, model, semantics, tally, out)
    };
    if json {
        crate::cli::write_stdout(|out| stream(&mut tally, Some(out)))?;
    } else {
        stream(&mut tally, None).map_err(|e| format!("{name}: {e}"))?;
    }
    let mut outputs = Outputs::new();
    let mut wrote = String::new();
    if let (Some(path), Some(levels)) = (&o.grey_out, tally.levels.take()) {
        stage_grey(&mut outputs, path, levels, (width, height), quantization)?;
        wrote = format!(
            "; wrote {} ({}-bit grey, {})",
            path.display(),
            quantization.bits(),
            quantization.name()
        );
    }
    outputs.commit()?;
    let AreaTally {
        count, whole, total, ..
    } = &tally;
    let summary = format!(
        "{name}: area coverage ({} semantics), model {model}, {}: {} with area, {whole} of them whole; total {}{}{wrote}",
        semantics.name(),
        target.convention,
        counted(*count as u64, "pixel"),
        exact_text(total),
        terminating_decimal(total).map_or(String::new(), |d| format!(" = {d}")),
    );
    if json {
        eprintln!("{summary}");
    } else {
        let grid = tally.kept.as_ref().map_or(String::new(), tenths_grid);
        crate::cli::print_stdout(&format!("{grid}{summary}"))?;
    }
    Ok(ExitCode::SUCCESS)
}

/// Streams the area of every covered pixel, row by row, into `tally`, and as JSON to
/// `out` when given.
fn stream_area(
    primitives: &rasterproof::model::Primitives,
    target: &Target,
    model: Model,
    semantics: Semantics,
    tally: &mut AreaTally,
    mut out: Option<&mut dyn std::io::Write>,
) -> std::io::Result<()> {
    let (width, height) = (target.width, target.height);
    if let Some(out) = out.as_mut() {
        write!(
            out,
            "{{\"width\":{width},\"height\":{height},\"coverage\":\"area\",\"semantics\":\"{}\",\"model\":\"{model}\",\"pixels\":[",
            semantics.name()
        )?;
    }
    let mut written: std::io::Result<()> = Ok(());
    render_area_rows(primitives, target, model, semantics, |y, row| {
        for (x, v) in row {
            if let (Some(out), Ok(())) = (out.as_mut(), &written) {
                let comma = if tally.count == 0 { "" } else { "," };
                written = write!(out, "{comma}[{x},{y},\"{}\"]", exact_text(&v));
            }
            tally.take(x, y, v);
        }
    })
    .map_err(|e| std::io::Error::other(e.to_string()))?;
    written?;
    if let Some(out) = out {
        writeln!(out, "]}}")?;
    }
    Ok(())
}

/// Stages the grey image of `levels` at `path`: 16-bit or 8-bit as `quantization` makes
/// them.
fn stage_grey(
    outputs: &mut Outputs,
    path: &std::path::Path,
    levels: Vec<u16>,
    (width, height): (u32, u32),
    quantization: Quantization,
) -> Result<(), String> {
    if quantization.bits() == 16 {
        let grey: image::ImageBuffer<image::Luma<u16>, Vec<u16>> =
            image::ImageBuffer::from_raw(width, height, levels).ok_or("the grey image's size")?;
        outputs.stage(path, "PNG", |out| grey.write_to(out, image::ImageFormat::Png))?;
    } else {
        let bytes = levels.iter().map(|&l| u8::try_from(l).unwrap_or(u8::MAX)).collect();
        let grey: image::GrayImage =
            image::ImageBuffer::from_raw(width, height, bytes).ok_or("the grey image's size")?;
        outputs.stage_png(path, &grey)?;
    }
    Ok(())
}

/// What `render --coverage area` gathers from the streamed rows.
struct AreaTally {
    /// Pixels with area.
    count: usize,
    /// Pixels wholly covered.
    whole: usize,
    /// The total area.
    total: BigRational,
    /// The canvas's width.
    width: u32,
    /// The grey levels, row by row, when a grey image is written.
    levels: Option<Vec<u16>>,
    /// How a value becomes a level.
    quantization: Quantization,
    /// The whole image, for the text grid of a small canvas.
    kept: Option<AreaImage>,
}

impl AreaTally {
    /// Takes the area `v` of pixel (`x`, `y`).
    fn take(&mut self, x: u32, y: u32, v: BigRational) {
        self.count += 1;
        self.whole += usize::from(v.is_one());
        self.total += &v;
        if let Some(levels) = self.levels.as_mut() {
            levels[y as usize * self.width as usize + x as usize] = self.quantization.level(&v);
        }
        if let Some(kept) = self.kept.as_mut() {
            kept.pixels.push((x, y, v));
        }
    }
}

/// The area image as text, row 0 first: `.` no area, `1`-`9` the tenths (rounded down,
/// at least 1), `#` a whole pixel.
fn tenths_grid(image: &AreaImage) -> String {
    let mut s = String::new();
    for y in 0..image.height {
        for x in 0..image.width {
            let v = image.value(x, y);
            s.push(if v.is_zero() {
                '.'
            } else if v >= BigRational::one() {
                '#'
            } else {
                let tenths = (v * BigRational::from_integer(10.into())).floor().to_integer();
                char::from_digit(tenths.to_u32().unwrap_or(0).clamp(1, 9), 10).unwrap_or('?')
            });
        }
        s.push('\n');
    }
    s
}

/// Draws the scene on `jobs` threads; once drawing has gone on for a second (an
/// arbitrary-precision plan, a plain oracle on a big frame), a progress bar on stderr
/// counts the primitives drawn, or the bands on several threads (indicatif hides it when
/// stderr is not a terminal).
fn draw_with_progress(prepared: &PreparedScene, target: &Target, jobs: usize) -> Coverage {
    let bands = PreparedScene::band_count(target, jobs);
    if bands > 1 {
        let bar = LateBar::new(bands, "bands");
        let coverage = prepared.coverage_parallel(target, jobs, &|| bar.inc(1));
        bar.bar.finish_and_clear();
        return coverage;
    }
    let bar = LateBar::new(prepared.primitive_count(), "primitives");
    let mut ticks = Ticks::new();
    let mut coverage = Coverage::new(target.width, target.height);
    prepared.render_observed(target, &mut coverage, &mut || {
        if let Some(done) = ticks.tick() {
            bar.inc(done);
        }
    });
    bar.bar.finish_and_clear();
    coverage
}

/// The pixels covered and covered more than once, counted band by band
/// ([`PreparedScene::visit_bands`]) with the bar of [`draw_with_progress`] over the bands.
fn count_with_progress(prepared: &PreparedScene, target: &Target, jobs: usize) -> (usize, usize) {
    let bar = LateBar::new(PreparedScene::visited_band_count(target, jobs), "bands");
    let counts = prepared.visit_bands(
        target,
        jobs,
        |_, _, band| (band.covered_pixels(), band.double_covered().count()),
        &|| bar.inc(1),
    );
    bar.bar.finish_and_clear();
    counts.into_iter().fold((0, 0), |(c, d), (bc, bd)| (c + bc, d + bd))
}

/// A progress bar of `count` `unit`s, hidden until the work has gone on for a second,
/// then drawn on stderr; told from any thread.
struct LateBar {
    bar: ProgressBar,
    start: Instant,
    shown: std::sync::atomic::AtomicBool,
}

impl LateBar {
    fn new(count: usize, unit: &str) -> LateBar {
        let bar = ProgressBar::with_draw_target(Some(count as u64), ProgressDrawTarget::hidden());
        bar.set_style(
            ProgressStyle::with_template(&format!(
                "{{bar:40}} {{pos}}/{{len}} {unit}, {{elapsed}} ({{eta}} left)"
            ))
            .expect("a valid template"),
        );
        LateBar {
            bar,
            start: Instant::now(),
            shown: std::sync::atomic::AtomicBool::new(false),
        }
    }

    /// `done` more units done.
    fn inc(&self, done: u64) {
        self.bar.inc(done);
        if self.start.elapsed() > Duration::from_secs(1) && !self.shown.swap(true, std::sync::atomic::Ordering::Relaxed)
        {
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
        }
    }
}

/// The progress of one thread drawing primitive after primitive, told to the bar in
/// batches: the bar and the clock cost some 20 ns a call, 2% of drawing a million small
/// triangles when asked after each. A batch doubles while it takes under 10 ms and halves
/// when it takes over 100 ms, so the bar moves about ten times a second whether a
/// primitive takes nanoseconds or seconds.
struct Ticks {
    /// When the last batch was told.
    last: Instant,
    /// Primitives drawn since, and the batch size.
    pending: u64,
    batch: u64,
}

impl Ticks {
    fn new() -> Ticks {
        Ticks {
            last: Instant::now(),
            pending: 0,
            batch: 1,
        }
    }

    /// One more primitive drawn; the primitives to add to the bar when a batch is full.
    fn tick(&mut self) -> Option<u64> {
        self.pending += 1;
        if self.pending < self.batch {
            return None;
        }
        let now = Instant::now();
        let took = now - self.last;
        self.last = now;
        if took < Duration::from_millis(10) {
            self.batch = (self.batch * 2).min(1 << 16);
        } else if took > Duration::from_millis(100) {
            self.batch = (self.batch / 2).max(1);
        }
        Some(std::mem::take(&mut self.pending))
    }
}

/// `--scale K`: a whole number (its range is checked against the canvas later).
fn parse_scale(text: &str) -> Result<u32, String> {
    text.trim()
        .parse::<u32>()
        .map_err(|_| format!("--scale: {text:?} is not a whole number K >= 1 (each pixel becomes a KxK block)"))
}
