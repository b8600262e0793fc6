//! `rasterproof hunt`: differential testing of an external renderer
//! ([`rasterproof::oracle::hunt`]), every distinct failure shrunk to a minimal scene; one
//! shard of the cases, within a time budget, with the report as JSON (`--report`) and
//! JUnit XML (`--junit`).

use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use num_rational::BigRational;
use rasterproof::area::{Quantization, Semantics};
use rasterproof::convention::Preset;
use rasterproof::num::exact::{counted, exact_text};
use rasterproof::oracle::compare::fit::grey::GreyMethod;
use rasterproof::oracle::hunt::{
    fit_convention, fit_grey_method, fit_sample_convention, grey_rust_test, hunt_grey, hunt_interruptible, hunt_values,
    rust_test, FitFirst, GreyFitFirst, GreyHuntConfig, HuntConfig, HuntReport, SceneFamily, ValueHuntConfig,
    AREA_FAMILIES, FIT_PROBES, VALUE_FAMILIES,
};
use rasterproof::oracle::renderer::{Program, Renderer, StayAlive};
use rasterproof::oracle::GreyImage;
use rasterproof::oracle::{Background, Format};
use rasterproof::pattern::SamplePattern;

use super::run_args::RunArgs;
use super::{ConventionArgs, Outputs};

/// What `hunt` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// The renderer, run once per scene: `PROGRAM ARGS {scene} {out}`, split as a POSIX
    /// shell splits words and run without a shell; {scene} is replaced by a scene file's
    /// path, {out} by the path it must write (a PNG, or JSON with --as json).
    #[arg(
        long,
        value_name = "COMMAND",
        required_unless_present = "serve",
        conflicts_with = "serve"
    )]
    cmd: Option<String>,
    /// The renderer, started once per job and kept alive: `PROGRAM ARGS`, which reads one
    /// JSON request per line on stdin and answers one JSON line per scene on stdout (the
    /// stay-alive protocol, docs/oracle.md). Far faster than --cmd for a renderer with a
    /// costly start (Python, a GPU context).
    #[arg(long, value_name = "COMMAND")]
    serve: Option<String>,
    /// How to read its output: ids (default), mask or json; or grey: an 8- or 16-bit grey
    /// PNG of anti-aliased coverage, judged against exact area coverage (see --semantics and
    /// --quantization; the families default to those with area); or values: each scene
    /// gets a varying `c` of 3 channels with a w and values at every vertex, and their
    /// values image (a float32 TIFF or a UNORM PNG) is judged by `compare --as values`
    /// (see --interpolation and --provoking; the families default to triangles only).
    #[arg(long = "as", value_name = "FORMAT", default_value = "ids")]
    theirs_as: String,
    /// With --as grey: the exact area semantics their levels approximate (true,
    /// accumulated or unclamped).
    #[arg(long, default_value = "true")]
    semantics: String,
    /// With --as grey: how their levels quantize coverage (round, truncate, ftgrays,
    /// round16); it fixes the bit depth.
    #[arg(long, default_value = "round")]
    quantization: String,
    /// With --as grey: every coordinate rounded to the nearest multiple of 2^-BITS px
    /// (0..=16), for a renderer whose input is fixed point (FreeType's 26.6: 6).
    #[arg(long, value_name = "BITS")]
    grid: Option<u32>,
    /// With --as grey: judge against this method of the area family (a name `compare --as
    /// grey --fit` prints, e.g. supersample-4x4-round or ftgrays) instead of the exact
    /// value's levels: a pixel differs where their level is not the method's. The method
    /// names its semantics and quantization (leave out --semantics and --quantization).
    #[arg(long, value_name = "NAME", conflicts_with_all = ["semantics", "quantization"])]
    method: Option<String>,
    /// With --as values: the varying's interpolation in every scene (smooth,
    /// noperspective or flat).
    #[arg(long, default_value = "smooth")]
    interpolation: String,
    /// With --as values: the scenes' provoking vertex (first or last).
    #[arg(long, default_value = "first")]
    provoking: String,
    /// With --as values: where the varying is sampled (centre, centroid or sample; the
    /// last two differ from the centre under --samples N, where their answer is a
    /// float32 TIFF of N values images stacked, W x N·H).
    #[arg(long, default_value = "centre")]
    sampling: String,
    /// How many scenes.
    #[arg(long, default_value_t = 200)]
    cases: u64,
    /// Seed of the scene generator (same seed, same scenes).
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// The families to draw from (repeat, or comma-separate): mesh, delaunay, triangles,
    /// slivers, huge, fine (triangles only), lines (needs lines), polygons (needs
    /// polygons); all-triangles: the six triangle-only families. Default: all.
    #[arg(long = "family", value_name = "F", value_delimiter = ',')]
    families: Vec<String>,
    /// The convention every scene states: `--preset` (default d3d11) and the overrides.
    #[command(flatten)]
    convention: ConventionArgs,
    /// The oracle model: exact-snapped (default: for a renderer that snaps vertices to the
    /// subpixel grid) or exact (vertices as written: for one that does not snap).
    #[arg(long, default_value = "exact-snapped")]
    model: String,
    /// Fit the renderer's convention first (compare --fit on tie-heavy probe scenes) and
    /// hunt under it (its oracle model too). When no convention explains the probes, or
    /// only ones a scene file cannot state (say top-right ties), it says so and exits 1.
    /// With --as grey: fit its method (compare --as grey --fit on probe scenes of the
    /// hunt's families) and hunt against it, as --method does. With --samples N: fit each
    /// sample index too, and hunt under the pattern with any sample that sits elsewhere
    /// moved to where its images put it.
    #[arg(long, conflicts_with_all = ["preset", "tie_rule", "subpixel_bits", "rounding", "pixel_centre", "model", "method"])]
    fit_first: bool,
    /// Canvas side of every scene, pixels.
    #[arg(long, default_value_t = 16)]
    canvas: u32,
    /// Write each distinct failure here: the minimal scene (finding-NN.json), its
    /// explanation (finding-NN.txt) and a Rust test (finding-NN.rs); and index.html, every
    /// finding in one self-contained page to explore.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Kill the renderer after this many seconds (a timeout is a finding).
    #[arg(long, default_value_t = 10.0)]
    timeout: f64,
    /// Only coordinates that f32 holds exactly (for programs that read floats).
    #[arg(long)]
    float32_exact: bool,
    /// Runs of the renderer allowed per shrink.
    #[arg(long, default_value_t = 400)]
    shrink_runs: usize,
    /// Every scene states the standard pattern of N samples (`samples`: 2, 4, 8 or 16):
    /// the renderer answers with one ids image per sample index, stacked (width W, height
    /// N x H), and each sample index is judged on its own (`compare --samples`). The
    /// families default to the triangle-only ones; lines have no samples.
    #[arg(long, value_name = "N")]
    samples: Option<usize>,
    /// Renderers run at once (--jobs), shard, time budget, progress bar, reports.
    #[command(flatten)]
    run: RunArgs,
}

/// Runs the hunt as `o` asks, writes `--out`, `--report` and `--junit` (all or none) and
/// prints the summary; exit 1 when something was found.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    o.run.outputs.check_writable()?;
    let (format, grey, samples) = mode(o)?;
    let families = families(o, grey.is_some(), samples.is_some())?;
    let (cmd, program) = renderer(o, format)?;
    stop_cleanly_when_interrupted(program.as_ref());
    let mut config = hunt_config(o, families, samples)?;
    if let Some((semantics, quantization, method)) = grey {
        let mut config = GreyHuntConfig {
            hunt: config,
            semantics,
            quantization,
            grid: o.grid,
            method,
        };
        if o.fit_first {
            if let Some(exit) = fit_grey_first(program.as_ref(), &mut config)? {
                return Ok(exit);
            }
        }
        return run_grey(o, &config, program.as_ref(), cmd);
    }
    if format == Format::Values {
        config.model = super::parse_model(&o.model)?;
        let config = ValueHuntConfig::named(config, &o.interpolation, &o.provoking, &o.sampling)?;
        return run_values(o, &config, program.as_ref(), cmd);
    }
    config.model = match super::parse_model(&o.model)? {
        m if m.plans() => m,
        m => {
            return Err(format!(
                "--model: {m} is not an oracle (expected exact-snapped or exact)"
            ))
        }
    };
    let render_with = program.as_ref();
    if o.fit_first {
        if let Some(exit) = fit_first(render_with, &mut config)? {
            return Ok(exit);
        }
    }
    let bar = o.run.progress_bar(config.shard.case_count(config.cases), "scenes");
    let report = hunt_interruptible(render_with, &config, o.run.jobs, &|| bar.inc(1), &INTERRUPTED)?;
    bar.finish_and_clear();
    write_outputs(o, &report, cmd, &config)?;
    super::write_stdout(|out| out.write_all(report.to_text(o.out.as_deref()).as_bytes()))?;
    Ok(exit_code(report.interrupted, report.findings.is_empty()))
}

/// A hunt's exit: 130 when interrupted, 0 when it found nothing, 1 otherwise.
fn exit_code(interrupted: bool, nothing_found: bool) -> ExitCode {
    if interrupted {
        ExitCode::from(130)
    } else if nothing_found {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

/// The kind of hunt the options ask for, checked: how their output is read, the grey
/// options of a grey hunt, the pattern of a multisample hunt.
#[allow(clippy::type_complexity)]
fn mode(o: &Options) -> Result<(Format, Option<GreyJudged>, Option<SamplePattern>), String> {
    let format = Format::from_name(&o.theirs_as).ok_or_else(|| {
        format!(
            "--as: unknown format {:?} (expected ids, mask, json, grey or values)",
            o.theirs_as
        )
    })?;
    let grey = if format == Format::Grey {
        if o.model != "exact-snapped" {
            return Err(
                "--model is for the binary hunt; --as grey is judged against exact area coverage (--semantics, \
                        --quantization) or a method (--method)"
                    .to_string(),
            );
        }
        if o.run.outputs.junit.is_some() {
            return Err("--junit: the grey hunt writes --report (JSON) and --out".to_string());
        }
        Some(grey_options(o)?)
    } else {
        if o.semantics != "true" || o.quantization != "round" || o.grid.is_some() || o.method.is_some() {
            return Err("--semantics, --quantization, --grid and --method are for --as grey".to_string());
        }
        None
    };
    if !(o.timeout > 0.0 && o.timeout.is_finite()) {
        return Err(format!("--timeout: {} is not a positive number of seconds", o.timeout));
    }
    if !(1..=rasterproof::convention::MAX_CANVAS).contains(&o.canvas) {
        return Err(format!(
            "--canvas: {} is outside 1..={}",
            o.canvas,
            rasterproof::convention::MAX_CANVAS
        ));
    }
    let samples = o.samples.map(super::parse_samples).transpose()?.filter(|p| p.len() > 1);
    let values = format == Format::Values;
    if !values && (o.interpolation != "smooth" || o.provoking != "first" || o.sampling != "centre") {
        return Err("--interpolation, --provoking and --sampling are for --as values".to_string());
    }
    if values && (o.fit_first || o.run.outputs.junit.is_some()) {
        return Err("--as values writes --report (JSON) and --out; leave out --fit-first and --junit".to_string());
    }
    if samples.is_some() && grey.is_some() {
        return Err("--samples: a multisample hunt judges ids or masks per sample; leave out --as grey".to_string());
    }
    Ok((format, grey, samples))
}

/// `--family`, or the default families of the kind of hunt (area shapes for a grey hunt,
/// triangles for a multisample one, every family otherwise).
fn families(o: &Options, grey: bool, samples: bool) -> Result<Vec<SceneFamily>, String> {
    Ok(if o.families.is_empty() && grey {
        AREA_FAMILIES.to_vec()
    } else if o.families.is_empty() && o.theirs_as == "values" {
        VALUE_FAMILIES.to_vec()
    } else if o.families.is_empty() && samples {
        SceneFamily::TRIANGLES_ONLY.to_vec()
    } else if o.families.is_empty() {
        SceneFamily::ALL.to_vec()
    } else {
        let mut families = Vec::new();
        for f in &o.families {
            let expanded = SceneFamily::expand(f.trim()).ok_or_else(|| {
                let all: Vec<&str> = SceneFamily::ALL.iter().map(|f| f.name()).collect();
                format!(
                    "--family: unknown family {f:?} (expected {} or {})",
                    all.join(", "),
                    SceneFamily::TRIANGLES_ONLY_NAME
                )
            })?;
            families.extend(expanded);
        }
        families
    })
}

/// The renderer (`--serve` or `--cmd`) and its command line.
fn renderer(o: &Options, format: Format) -> Result<(&str, Box<dyn Renderer>), String> {
    let timeout = Duration::from_secs_f64(o.timeout);
    Ok(match (&o.cmd, &o.serve) {
        (_, Some(serve)) => (
            serve,
            Box::new(StayAlive::new(serve, format, Background::default(), timeout)?),
        ),
        (Some(cmd), None) => (
            cmd,
            Box::new(Program::new(cmd, format, Background::default(), timeout)?),
        ),
        (None, None) => return Err("give the renderer with --cmd or --serve".to_string()),
    })
}

/// Sets what Ctrl-C (or SIGTERM) does during the hunt (see inside).
fn stop_cleanly_when_interrupted(program: &dyn Renderer) {
    // Interrupted (Ctrl-C, SIGTERM): the first time, no case starts any more, the running
    // ones finish and the report of the cases done is written (findings not shrunk). The
    // second time at once: no stray temporary files and no renderer left running. The
    // renderer runs in a process group of its own (it does not get the terminal's
    // Ctrl-C): every running renderer's whole group is killed here; its files go with the
    // folder.
    let (temp, groups) = program.files_and_groups().expect("a program has both");
    let temp = temp.to_path_buf();
    let _ = ctrlc::set_handler(move || {
        if !INTERRUPTED.swap(true, Ordering::SeqCst) {
            eprintln!(
                "hunt: interrupted: finishing the running scenes, then writing the report of the cases done \
                 (Ctrl-C again to stop at once, writing nothing)"
            );
            return;
        }
        groups.kill_all();
        let _ = std::fs::remove_dir_all(&temp);
        eprintln!("hunt: interrupted twice; nothing written");
        std::process::exit(130);
    });
}

/// The hunt's configuration from the options: cases, families, canvas, shard, budget,
/// pattern, preset and convention overrides.
fn hunt_config(o: &Options, families: Vec<SceneFamily>, samples: Option<SamplePattern>) -> Result<HuntConfig, String> {
    let mut config = HuntConfig {
        cases: o.cases,
        seed: o.seed,
        families,
        canvas: o.canvas,
        float32_exact: o.float32_exact,
        shrink_runs: o.shrink_runs,
        shard: o.run.shard(),
        budget: o.run.time,
        samples,
        ..HuntConfig::default()
    };
    if config.samples.is_some() && config.families.contains(&SceneFamily::Lines) {
        return Err("--family lines: lines have no samples (a line decides a pixel by its own rule); leave it out with --samples".to_string());
    }
    if let Some(p) = &o.convention.preset {
        config.preset = Preset::from_name(p)
            .ok_or_else(|| format!("--preset: unknown preset {p:?} (expected one of d3d11, vulkan, gl, cts)"))?;
    }
    o.convention.apply(&mut config.overrides)?;
    Ok(config)
}

/// `--fit-first`: the convention the renderer follows, stated in `config` (under a
/// pattern of several samples, with the sample positions that explain its images); or,
/// when no scene file can state it or none explains its images, the exit after saying so.
fn fit_first(render_with: &dyn Renderer, config: &mut HuntConfig) -> Result<Option<ExitCode>, String> {
    let (found, moved) = match config.samples.as_ref().filter(|p| p.len() > 1) {
        None => (fit_convention(render_with, config)?, String::new()),
        Some(_) => {
            let found = fit_sample_convention(render_with, config)?;
            let moved: Vec<String> = found
                .moved
                .iter()
                .map(|m| {
                    let point = |p: &[BigRational; 2]| format!("({}, {})", exact_text(&p[0]), exact_text(&p[1]));
                    format!(
                        ", sample {} at {}, not the pattern's {} (the nearest of {} on the 1/16 px grid that {} its \
                         image on every probe)",
                        m.index,
                        point(&m.to),
                        point(&m.from),
                        counted(m.fitting as u64, "position"),
                        if m.fitting == 1 { "gives" } else { "give" }
                    )
                })
                .collect();
            config.samples = Some(found.pattern);
            (found.convention, moved.concat())
        }
    };
    match found {
        FitFirst::Statable { fit, overrides, model } => {
            eprintln!("fit: hunting under {fit} (oracle {}){moved}", model.name());
            config.overrides = overrides;
            config.model = model;
        }
        // What the renderer follows is the finding: exit 1, as `compare --fit` does.
        FitFirst::Unstatable(fits) => {
            let names: Vec<String> = fits.iter().map(ToString::to_string).collect();
            super::print_stdout(&format!(
                "fit: the renderer's images of the {FIT_PROBES} probe scenes are explained exactly by {} \
                     convention(s), none of which a scene file can state (scene files state the tie rules top-left \
                     and bottom-left, and a grid of 1 to 16 subpixel bits or none), so hunt cannot hunt under it; \
                     nothing else was run or written. The convention(s):\n  {}",
                fits.len(),
                names.join("\n  ")
            ))?;
            return Ok(Some(ExitCode::from(1)));
        }
        FitFirst::NoneExplains(last) => {
            super::print_stdout(&format!(
                "fit: no convention explains the renderer's images of the {FIT_PROBES} probe scenes; nothing \
                     else was run or written. The last probe's fit:\n{last}"
            ))?;
            return Ok(Some(ExitCode::from(1)));
        }
    }
    Ok(None)
}

/// `--out` (each finding's scene, text and Rust test, and the HTML page), `--report` and
/// `--junit`: all or none.
fn write_outputs(o: &Options, report: &HuntReport, cmd: &str, config: &HuntConfig) -> Result<(), String> {
    let mut outputs = Outputs::new();
    if let Some(dir) = &o.out {
        std::fs::create_dir_all(dir).map_err(|e| format!("--out {}: cannot create: {e}", dir.display()))?;
        for (n, f) in report.findings.iter().enumerate() {
            let n = n + 1;
            let path = |ext: &str| dir.join(format!("finding-{n:02}.{ext}"));
            outputs.stage_text(&path("json"), &f.minimal.to_json())?;
            outputs.stage_text(&path("txt"), &f.to_text(n))?;
            outputs.stage_text(&path("rs"), &rust_test(f, n, config.model))?;
        }
        outputs.stage_text(&dir.join("index.html"), &report.to_html(cmd))?;
    }
    if let Some(path) = &o.run.outputs.report {
        outputs.stage_text(path, &report.to_json(cmd))?;
    }
    if let Some(path) = &o.run.outputs.junit {
        outputs.stage_text(path, &report.junit(cmd))?;
    }
    outputs.commit()
}

/// What a grey hunt judges against: the semantics and quantization, and the method when
/// one is named.
type GreyJudged = (Semantics, Quantization, Option<GreyMethod>);

/// `--semantics` and `--quantization` of a grey hunt, or those of its `--method`.
fn grey_options(o: &Options) -> Result<GreyJudged, String> {
    if let Some(bits) = o.grid.filter(|b| *b > 16) {
        return Err(format!("--grid: {bits} bits is outside 0..=16"));
    }
    if let Some(name) = &o.method {
        let method = super::parse_grey_method(name, None)?;
        let (semantics, quantization) = method.judged_as(method.bits());
        return Ok((semantics, quantization, Some(method)));
    }
    let semantics = super::parse_semantics(&o.semantics)?;
    let quantization = super::parse_quantization(&o.quantization)?;
    Ok((semantics, quantization, None))
}

/// `--as grey --fit-first`: the method the renderer follows, judged against in `config`;
/// or, when none explains its images of the probes, the exit after saying so.
fn fit_grey_first(renderer: &dyn Renderer, config: &mut GreyHuntConfig) -> Result<Option<ExitCode>, String> {
    match fit_grey_method(renderer, config)? {
        GreyFitFirst::Found(methods) => {
            let method = methods[0];
            let others: Vec<String> = methods[1..].iter().map(|m| m.name()).collect();
            let also = if others.is_empty() {
                String::new()
            } else {
                format!(" (these give the same levels too: {})", others.join(", "))
            };
            eprintln!(
                "fit: hunting against {} (--method {}){also}",
                method.describe(),
                method.name()
            );
            let (semantics, quantization) = method.judged_as(method.bits());
            config.semantics = semantics;
            config.quantization = quantization;
            config.method = Some(method);
            Ok(None)
        }
        GreyFitFirst::NoneExplains(last) => {
            super::print_stdout(&format!(
                "fit: no method of the area family gives every level of the renderer's images of the {FIT_PROBES} \
                 probe scenes; nothing else was run or written. The last probe's fit:\n{last}"
            ))?;
            Ok(Some(ExitCode::from(1)))
        }
    }
}

/// The grey hunt (`--as grey`): runs it, writes `--out` (each finding's minimal scene,
/// their grey PNG of it and the comparison's text) and `--report`, prints the summary;
/// exit 1 when something was found.
fn run_grey(o: &Options, config: &GreyHuntConfig, renderer: &dyn Renderer, cmd: &str) -> Result<ExitCode, String> {
    let bar = o
        .run
        .progress_bar(config.hunt.shard.case_count(config.hunt.cases), "scenes");
    let report = hunt_grey(renderer, config, o.run.jobs, &|| bar.inc(1), &INTERRUPTED)?;
    bar.finish_and_clear();
    let text = report.to_text(8);
    let mut outputs = Outputs::new();
    if let Some(dir) = &o.out {
        std::fs::create_dir_all(dir).map_err(|e| format!("--out {}: cannot create: {e}", dir.display()))?;
        for (n, f) in report.findings.iter().enumerate() {
            let n = n + 1;
            let path = |ext: &str| dir.join(format!("finding-{n:02}.{ext}"));
            outputs.stage_text(&path("json"), &f.minimal.to_json())?;
            outputs.stage_text(&path("txt"), &f.to_text(n))?;
            outputs.stage_text(&path("rs"), &grey_rust_test(f, n, &report))?;
            if let Some(theirs) = &f.theirs {
                let image = grey_png(theirs)?;
                outputs.stage(&path("png"), "PNG", |w| {
                    image.write_to(w, image::ImageFormat::Png).map_err(|e| e.to_string())
                })?;
            }
        }
        outputs.stage_text(&dir.join("index.html"), &report.to_html(cmd))?;
    }
    if let Some(path) = &o.run.outputs.report {
        outputs.stage_text(path, &report.to_json(cmd).to_string())?;
    }
    outputs.commit()?;
    super::print_stdout(text.trim_end())?;
    Ok(exit_code(report.interrupted, report.findings.is_empty()))
}

/// Runs a values hunt and writes `--out` (each finding's minimal scene and its text) and
/// `--report`.
fn run_values(o: &Options, config: &ValueHuntConfig, renderer: &dyn Renderer, cmd: &str) -> Result<ExitCode, String> {
    let bar = o
        .run
        .progress_bar(config.hunt.shard.case_count(config.hunt.cases), "scenes");
    let report = hunt_values(renderer, config, o.run.jobs, &|| bar.inc(1), &INTERRUPTED)?;
    bar.finish_and_clear();
    let mut outputs = Outputs::new();
    if let Some(dir) = &o.out {
        std::fs::create_dir_all(dir).map_err(|e| format!("--out {}: cannot create: {e}", dir.display()))?;
        for (n, f) in report.findings.iter().enumerate() {
            let path = |ext: &str| dir.join(format!("finding-{:02}.{ext}", n + 1));
            outputs.stage_text(&path("json"), &f.minimal.to_json())?;
            outputs.stage_text(&path("txt"), &f.to_text(n + 1))?;
        }
    }
    if let Some(path) = &o.run.outputs.report {
        outputs.stage_text(path, &report.to_json(cmd).to_string())?;
    }
    outputs.commit()?;
    super::print_stdout(report.to_text().trim_end())?;
    Ok(exit_code(report.interrupted, report.findings.is_empty()))
}

/// Their grey levels as an 8- or 16-bit grey PNG image.
fn grey_png(g: &GreyImage) -> Result<image::DynamicImage, String> {
    let bad = || format!("a {}x{} grey image of {} levels", g.width, g.height, g.levels.len());
    if g.bits == 16 {
        image::ImageBuffer::from_raw(g.width, g.height, g.levels.clone())
            .map(image::DynamicImage::ImageLuma16)
            .ok_or_else(bad)
    } else {
        let bytes = g.levels.iter().map(|&v| u8::try_from(v).unwrap_or(u8::MAX)).collect();
        image::GrayImage::from_raw(g.width, g.height, bytes)
            .map(image::DynamicImage::ImageLuma8)
            .ok_or_else(bad)
    }
}

/// Set by the first Ctrl-C (or SIGTERM) of a hunt.
static INTERRUPTED: AtomicBool = AtomicBool::new(false);

/// What `hunt-merge` was asked to do.
#[derive(clap::Args)]
pub struct MergeOptions {
    /// The reports of the shards (`hunt --shard K/N --report FILE.json`) of one hunt.
    #[arg(required = true, value_name = "REPORT.json")]
    reports: Vec<PathBuf>,
    /// Write the merged report (JSON, the hunt report's schema).
    #[arg(long, value_name = "FILE.json")]
    report: Option<PathBuf>,
}

/// Reads the shard reports, merges them, writes `--report` and prints the merged counts
/// and findings; exit 1 when something was found.
pub fn merge(o: &MergeOptions) -> Result<ExitCode, String> {
    let mut reports = Vec::new();
    for path in &o.reports {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| format!("{name}: cannot read: {e}"))?;
        let value: serde_json::Value =
            serde_json::from_str(&text).map_err(|e| format!("{name}: not a hunt report: not JSON ({e})"))?;
        reports.push((name, value));
    }
    let merged = rasterproof::oracle::hunt::merge_reports(&reports)?;
    if let Some(path) = &o.report {
        let mut outputs = Outputs::new();
        let text = serde_json::to_string_pretty(&merged).map_err(|e| format!("internal: {e}"))?;
        outputs.stage_text(path, &format!("{text}\n"))?;
        outputs.commit()?;
    }
    let counts = &merged["counts"];
    let findings = merged["findings"].as_array().cloned().unwrap_or_default();
    let shard = &merged["shard"];
    let shards = match shard.get("merged") {
        Some(list) => format!("shards {list} of {}", shard["n"]),
        None => "every shard".to_string(),
    };
    let mut text = format!(
        "hunt-merge: {} reports ({shards}): {} scenes: {} identical, {} differ, {} failed, {} refused by the oracle\n",
        reports.len(),
        merged["cases_run"],
        counts["same"],
        counts["differ"],
        counts["failed"],
        counts["refused"]
    );
    let per_sample = rasterproof::oracle::hunt::per_sample_summaries(&merged)?;
    if per_sample.iter().any(|p| p.cases > 0) {
        text.push_str("by sample index:\n");
        for p in &per_sample {
            text.push_str(&format!("  {}\n", p.to_text()));
        }
    }
    for (k, f) in findings.iter().enumerate() {
        text.push_str(&format!(
            "{:02}   {:<44} {:>6} {:>6}\n",
            k + 1,
            f["signature"].as_str().unwrap_or("?"),
            f["cases"],
            f["first_case"]
        ));
    }
    super::print_stdout(text.trim_end())?;
    Ok(if findings.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
