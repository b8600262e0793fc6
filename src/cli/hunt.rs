//! `rasterproof hunt`: differential testing of an external renderer
//! ([`rasterproof::oracle::hunt`]), every distinct failure shrunk to a minimal scene; one
//! shard of the cases, within a time budget, with the report as JSON (`--report`) and
//! JUnit XML (`--junit`).

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};
use rasterproof::convention::Preset;
use rasterproof::harness::suite::Shard;
use rasterproof::oracle::hunt::{fit_convention, hunt, rust_test, HuntConfig, HuntVerdict, SceneFamily};
use rasterproof::oracle::program::Program;
use rasterproof::oracle::{Background, Format};

use rasterproof::model::Model;

use super::{parse_duration, parse_shard, writable_outputs, ConventionArgs, Outputs, ProgressArgs};

/// What `hunt` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// The renderer: `PROGRAM ARGS {scene} {out}`, split as a POSIX shell splits words and
    /// run without a shell; {scene} is replaced by a scene file's path, {out} by the path
    /// it must write (a PNG, or JSON with --as json).
    #[arg(long, value_name = "COMMAND")]
    cmd: String,
    /// How to read its output: ids (default), mask or json.
    #[arg(long = "as", value_name = "FORMAT", default_value = "ids")]
    theirs_as: String,
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
    /// hunt under it (its oracle model too).
    #[arg(long, conflicts_with_all = ["preset", "tie_rule", "subpixel_bits", "rounding", "pixel_centre", "model"])]
    fit_first: bool,
    /// Canvas side of every scene, pixels.
    #[arg(long, default_value_t = 16)]
    canvas: u32,
    /// Write each distinct failure here: the minimal scene (finding-NN.json), its
    /// explanation (finding-NN.txt) and a Rust test (finding-NN.rs).
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Kill the renderer after this many seconds (a timeout is a finding).
    #[arg(long, default_value_t = 10.0)]
    timeout: f64,
    /// Run this many renderers at once.
    #[arg(long, default_value_t = 1)]
    jobs: usize,
    /// Only coordinates that f32 holds exactly (for programs that read floats).
    #[arg(long)]
    float32_exact: bool,
    /// Runs of the renderer allowed per shrink.
    #[arg(long, default_value_t = 400)]
    shrink_runs: usize,
    #[command(flatten)]
    progress: ProgressArgs,
    /// Run shard K of N only: the cases k of 0..cases with k mod N = K - 1 (1 <= K <= N);
    /// the N shards together run exactly the unsharded hunt's cases.
    #[arg(long, value_name = "K/N", value_parser = parse_shard)]
    shard: Option<Shard>,
    /// Start no case after this much time (90s, 5m, 1h, 1h30m; units ms, s, m, h): the
    /// running ones finish, what was found is shrunk, and the cases that ran are the first
    /// of the shard's, in order.
    #[arg(long, value_name = "DURATION", value_parser = parse_duration)]
    time: Option<Duration>,
    /// Write the report as JSON: seed, shard, cases requested and run, the convention, the
    /// counts and every finding with its minimal scene (schema: docs/oracle.md, `hunt`).
    #[arg(long, value_name = "FILE.json")]
    report: Option<PathBuf>,
    /// Write the result as JUnit XML: one failed test case per finding, one passing
    /// "identical to the oracle" with the counts.
    #[arg(long, value_name = "FILE.xml")]
    junit: Option<PathBuf>,
}

/// Runs the hunt as `o` asks, writes `--out`, `--report` and `--junit` (all or none) and
/// prints the summary; exit 1 when something was found.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    writable_outputs(o.report.as_deref(), o.junit.as_deref())?;
    let format = Format::from_name(&o.theirs_as)
        .ok_or_else(|| format!("--as: unknown format {:?} (expected ids, mask or json)", o.theirs_as))?;
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
    if o.jobs == 0 {
        return Err("--jobs: 0 (at least 1)".to_string());
    }
    let families = if o.families.is_empty() {
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
    };
    let program = Program::new(
        &o.cmd,
        format,
        Background::default(),
        Duration::from_secs_f64(o.timeout),
    )?;
    // Interrupted (Ctrl-C, SIGTERM): no stray temporary files and no renderer left
    // running. The renderer runs in a process group of its own (it does not get the
    // terminal's Ctrl-C): every running renderer's whole group is killed here; its files
    // go with the folder.
    let temp = program.temp_dir().to_path_buf();
    let groups = program.process_groups();
    let _ = ctrlc::set_handler(move || {
        groups.kill_all();
        let _ = std::fs::remove_dir_all(&temp);
        eprintln!("hunt: interrupted; nothing written");
        std::process::exit(130);
    });
    let mut config = HuntConfig {
        cases: o.cases,
        seed: o.seed,
        families,
        canvas: o.canvas,
        float32_exact: o.float32_exact,
        shrink_runs: o.shrink_runs,
        shard: o.shard.unwrap_or(Shard::WHOLE),
        budget: o.time,
        ..HuntConfig::default()
    };
    if let Some(p) = &o.convention.preset {
        config.preset = Preset::from_name(p)
            .ok_or_else(|| format!("--preset: unknown preset {p:?} (expected one of d3d11, vulkan, gl, cts)"))?;
    }
    o.convention.apply(&mut config.overrides)?;
    config.model = match super::parse_model(&o.model)? {
        m @ (Model::Exact | Model::ExactSnapped) => m,
        m => {
            return Err(format!(
                "--model: {m} is not an oracle (expected exact-snapped or exact)"
            ))
        }
    };
    let render_with = |s: &rasterproof::scene::Scene| program.render(s);
    if o.fit_first {
        let (best, overrides, model) = fit_convention(&config, &render_with)?;
        eprintln!("fit: hunting under {best} (oracle {})", model.name());
        config.overrides = overrides;
        config.model = model;
    }
    let bar = if o.progress.quiet {
        ProgressBar::hidden()
    } else {
        ProgressBar::new(config.shard.case_count(config.cases))
    };
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} scenes, {elapsed} ({eta} left)").expect("static template"),
    );
    let report = hunt(&render_with, &config, o.jobs, &|| bar.inc(1))?;
    bar.finish_and_clear();

    let mut outputs = Outputs::new();
    if let Some(dir) = &o.out {
        std::fs::create_dir_all(dir).map_err(|e| format!("--out {}: cannot create: {e}", dir.display()))?;
        for (n, f) in report.findings.iter().enumerate() {
            let n = n + 1;
            let path = |ext: &str| dir.join(format!("finding-{n:02}.{ext}"));
            outputs.stage_text(&path("json"), &f.minimal.to_json())?;
            outputs.stage_text(&path("txt"), &explanation(f, n))?;
            outputs.stage_text(&path("rs"), &rust_test(f, n, config.model))?;
        }
    }
    if let Some(path) = &o.report {
        outputs.stage_text(path, &report.to_json(&o.cmd))?;
    }
    if let Some(path) = &o.junit {
        outputs.stage_text(path, &report.junit(&o.cmd))?;
    }
    outputs.commit()?;
    let convention = config.overrides.apply(config.preset);
    let shard = if config.shard == Shard::WHOLE {
        String::new()
    } else {
        format!("shard {} of {} cases, ", config.shard, config.cases)
    };
    let mut lines = vec![format!(
        "hunt: {} scenes ({shard}{} px canvas, {}, oracle {}): {} identical, {} differ, {} failed, {} refused by the oracle",
        report.cases,
        o.canvas,
        convention,
        config.model.name(),
        report.same,
        report.differing,
        report.failed,
        report.refused
    )];
    if report.stopped_by_time {
        lines.push(format!(
            "stopped: the time budget ({:?}) ran out after {} of {} cases",
            config.budget.unwrap_or_default(),
            report.cases,
            report.requested
        ));
    }
    if !report.findings.is_empty() {
        lines.push(format!(
            "{:<4} {:<44} {:>6} {:>6} {:>10} {:>7}",
            "", "finding", "cases", "first", "primitives", "canvas"
        ));
    }
    for (n, f) in report.findings.iter().enumerate() {
        lines.push(format!(
            "{:<4} {:<44} {:>6} {:>6} {:>10} {:>7}",
            format!("{:02}", n + 1),
            f.signature.describe(),
            f.cases,
            f.case,
            rasterproof::oracle::hunt::primitive_count(&f.minimal),
            format!("{}x{}", f.minimal.width, f.minimal.height)
        ));
    }
    if let (Some(dir), false) = (&o.out, report.findings.is_empty()) {
        lines.push(format!(
            "wrote finding-NN.json / .txt / .rs for each into {}",
            dir.display()
        ));
    }
    for line in lines {
        super::print_stdout(&line)?;
    }
    Ok(if report.findings.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// The `.txt` of a finding: what it is, its minimal scene's comparison (or failure), and
/// the first scene that showed it.
fn explanation(f: &rasterproof::oracle::hunt::HuntFinding, n: usize) -> String {
    let mut s = format!(
        "finding {n:02}: {} (first in case {}, {} cases; shrunk with {} renderer runs)\n\n",
        f.signature.describe(),
        f.case,
        f.cases,
        f.runs
    );
    match &f.verdict {
        HuntVerdict::Differs(r) => s.push_str(&r.to_text(&format!("finding-{n:02}.json"), "their output", 50)),
        HuntVerdict::Failed(failure) => s.push_str(&format!("their renderer: {failure}\n")),
        HuntVerdict::Same => s.push_str("(the minimal scene no longer fails: the renderer is not deterministic)\n"),
        HuntVerdict::Refused(e) => s.push_str(&format!("the oracle refused the minimal scene: {e}\n")),
    }
    s.push_str("\nthe original scene:\n");
    s.push_str(&f.original.to_json());
    s
}
