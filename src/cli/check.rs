//! `rasterproof check` and `rasterproof check-merge`: the invariant suite
//! ([`rasterproof::harness::suite`]) on seeded random cases — on several threads, one
//! shard of the run, within a time budget — with a progress bar, the failing cases written
//! to `--out` (the exact and integer models' failures; the float models' too with
//! `--out-float`), the table with its findings and legend, and the report as JSON
//! (`--report`) and JUnit XML (`--junit`); `check-merge` merges shard reports into the
//! whole run's.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, Ordering};

use rasterproof::check::Violation;
use rasterproof::harness::suite::{Hooks, SceneFiles, SuiteConfig, SuiteReport};
use rasterproof::harness::CaseRun;
use rasterproof::scene::Scene;

use super::run_args::{ReportArgs, RunArgs};
use super::{print_stdout, Outputs};

/// What `check` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// Number of random cases of the whole run (0..N), whatever the shard.
    #[arg(long, default_value_t = 256)]
    cases: u64,
    /// Seed of the case generator (same seed, same cases).
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Write each case an exact or integer model failed as a scene file (and a .txt
    /// explanation) into this folder.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// With --out: also write the float models' violations (the measured trade; many
    /// files).
    #[arg(long, requires = "out")]
    out_float: bool,
    /// Threads, shard, time budget, progress bar, reports.
    #[command(flatten)]
    run: RunArgs,
}

/// What `check-merge` was asked to do.
#[derive(clap::Args)]
pub struct MergeOptions {
    /// The reports of the shards (`check --shard K/N --report FILE.json`) of one run.
    #[arg(required = true, value_name = "REPORT.json")]
    reports: Vec<PathBuf>,
    /// The merged report's outputs.
    #[command(flatten)]
    outputs: ReportArgs,
}

/// Runs the suite as `o` asks, writes the failures `--out` asks for, prints the report
/// and writes `--report` and `--junit`; exit 1 when an exact or integer model failed.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    o.run.outputs.check_writable()?;
    if let Some(dir) = &o.out {
        std::fs::create_dir_all(dir).map_err(|e| format!("--out {}: cannot create: {e}", dir.display()))?;
    }
    let plan = SuiteConfig {
        seed: o.seed,
        cases: o.cases,
        shard: o.run.shard(),
        jobs: o.run.jobs,
        budget: o.run.time,
        scene_files: o.out.as_ref().map(|dir| SceneFiles {
            dir: dir.clone(),
            float: o.out_float,
        }),
    };
    let bar = o.run.progress_bar(plan.case_count(), "cases");
    let tick = || bar.inc(1);
    let files = plan.scene_files.as_ref();
    let mut on_case = |k: u64, run: &CaseRun| -> Result<(), String> {
        for outcome in &run.outcomes {
            let Some((scene, v)) = outcome.repro() else { continue };
            if outcome.is_fatal() {
                bar.suspend(|| eprintln!("case {k}: {} ({}): {v}", outcome.invariant, outcome.label));
            }
            if let Some(path) = files.and_then(|f| f.path_for(k, outcome)) {
                write_case(&path, scene, v)?;
            }
        }
        Ok(())
    };
    let report = plan.run_with(Hooks {
        stop: Some(interrupt_flag()),
        tick: Some(&tick),
        on_case: Some(&mut on_case),
    })?;
    bar.finish_and_clear();
    finish(&report, &o.run.outputs)
}

/// Set by Ctrl-C (SIGINT): the run starts no further case, and `check` writes and prints
/// the report of the cases done (it says "stopped: interrupted"). A second Ctrl-C, or one
/// when the handler could not be installed, ends the process as usual.
static INTERRUPTED: AtomicBool = AtomicBool::new(false);

/// [`INTERRUPTED`], its Ctrl-C handler installed.
fn interrupt_flag() -> &'static AtomicBool {
    let _ = ctrlc::set_handler(|| {
        if INTERRUPTED.swap(true, Ordering::SeqCst) {
            std::process::exit(130);
        }
    });
    &INTERRUPTED
}

/// Reads the shard reports, merges them, prints the merged report and writes `--report`
/// and `--junit`; exit 1 when an exact or integer model failed.
pub fn merge(o: &MergeOptions) -> Result<ExitCode, String> {
    o.outputs.check_writable()?;
    let mut reports = Vec::new();
    for path in &o.reports {
        let name = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| format!("{name}: cannot read: {e}"))?;
        let text = String::from_utf8(bytes).map_err(|_| format!("{name}: not a check report: not UTF-8 text"))?;
        reports.push((name.clone(), SuiteReport::from_json(&text, &name)?));
    }
    let merged = SuiteReport::merge(reports)?;
    finish(&merged, &o.outputs)
}

/// Writes the report's files (all or none), prints it, and gives the exit code.
fn finish(report: &SuiteReport, outputs_asked: &ReportArgs) -> Result<ExitCode, String> {
    let mut outputs = Outputs::new();
    if let Some(path) = &outputs_asked.report {
        outputs.stage_text(path, &report.to_json())?;
    }
    if let Some(path) = &outputs_asked.junit {
        outputs.stage_text(path, &report.junit())?;
    }
    outputs.commit()?;
    for line in report.lines() {
        print_stdout(&line)?;
    }
    Ok(if report.passed() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// Writes a failing outcome's scene at `path` (a `.json`) and its violation as the `.txt`
/// beside it.
fn write_case(path: &Path, scene: &Scene, v: &Violation) -> Result<(), String> {
    std::fs::write(path, scene.to_json()).map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
    let txt = path.with_extension("txt");
    std::fs::write(&txt, format!("{v}\n")).map_err(|e| format!("{}: cannot write: {e}", txt.display()))
}
