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
use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};
use rasterproof::check::Violation;
use rasterproof::harness::suite::{Hooks, SceneFiles, Shard, SuiteConfig, SuiteReport, MAX_JOBS};
use rasterproof::harness::CaseRun;
use rasterproof::scene::Scene;

use super::{parse_duration, parse_shard, print_stdout, writable_outputs, Outputs, ProgressArgs};

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
    #[command(flatten)]
    progress: ProgressArgs,
    /// Run the cases on N threads (1..=1024); the results do not depend on N.
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = parse_jobs)]
    jobs: usize,
    /// Run shard K of N only: the cases k with k mod N = K - 1 (1 <= K <= N). The N
    /// shards' reports merge (check-merge) into the report of the whole run.
    #[arg(long, value_name = "K/N", value_parser = parse_shard)]
    shard: Option<Shard>,
    /// Start no case after this much time (90s, 5m, 1h, 1h30m; units ms, s, m, h) and
    /// report the cases that ran (the first of the shard's, in order).
    #[arg(long, value_name = "DURATION", value_parser = parse_duration)]
    time: Option<Duration>,
    /// Write the report as JSON: seed, shard, cases, every row, the findings and every
    /// failing case with its scene and explanation (schema: README, `check` section).
    /// Ctrl-C stops the run at the next case and still writes the report of those done.
    #[arg(long, value_name = "FILE.json")]
    report: Option<PathBuf>,
    /// Write the result as JUnit XML: one test case per invariant and model, failed when an
    /// exact or integer model violated it.
    #[arg(long, value_name = "FILE.xml")]
    junit: Option<PathBuf>,
}

/// What `check-merge` was asked to do.
#[derive(clap::Args)]
pub struct MergeOptions {
    /// The reports of the shards (`check --shard K/N --report FILE.json`) of one run.
    #[arg(required = true, value_name = "REPORT.json")]
    reports: Vec<PathBuf>,
    /// Write the merged report as JSON.
    #[arg(long, value_name = "FILE.json")]
    report: Option<PathBuf>,
    /// Write the merged result as JUnit XML.
    #[arg(long, value_name = "FILE.xml")]
    junit: Option<PathBuf>,
}

/// `--jobs N`: 1..=[`MAX_JOBS`].
fn parse_jobs(s: &str) -> Result<usize, String> {
    match s.parse::<usize>() {
        Ok(n) if (1..=MAX_JOBS).contains(&n) => Ok(n),
        _ => Err(format!("expected a number of threads in 1..={MAX_JOBS}")),
    }
}

/// Runs the suite as `o` asks, writes the failures `--out` asks for, prints the report
/// and writes `--report` and `--junit`; exit 1 when an exact or integer model failed.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    writable_outputs(o.report.as_deref(), o.junit.as_deref())?;
    if let Some(dir) = &o.out {
        std::fs::create_dir_all(dir).map_err(|e| format!("--out {}: cannot create: {e}", dir.display()))?;
    }
    let plan = SuiteConfig {
        seed: o.seed,
        cases: o.cases,
        shard: o.shard.unwrap_or(Shard::WHOLE),
        jobs: o.jobs,
        budget: o.time,
        scene_files: o.out.as_ref().map(|dir| SceneFiles {
            dir: dir.clone(),
            float: o.out_float,
        }),
    };
    let bar = if o.progress.quiet {
        ProgressBar::hidden()
    } else {
        ProgressBar::new(plan.case_count())
    };
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} cases, {elapsed} ({eta} left)").expect("static template"),
    );
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
    finish(&report, o.report.as_deref(), o.junit.as_deref())
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
    writable_outputs(o.report.as_deref(), o.junit.as_deref())?;
    let mut reports = Vec::new();
    for path in &o.reports {
        let name = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| format!("{name}: cannot read: {e}"))?;
        let text = String::from_utf8(bytes).map_err(|_| format!("{name}: not a check report: not UTF-8 text"))?;
        reports.push((name.clone(), SuiteReport::from_json(&text, &name)?));
    }
    let merged = SuiteReport::merge(reports)?;
    finish(&merged, o.report.as_deref(), o.junit.as_deref())
}

/// Writes the report's files (all or none), prints it, and gives the exit code.
fn finish(report: &SuiteReport, json: Option<&Path>, junit: Option<&Path>) -> Result<ExitCode, String> {
    let mut outputs = Outputs::new();
    if let Some(path) = json {
        outputs.stage_text(path, &report.to_json())?;
    }
    if let Some(path) = junit {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_parse_with_units_and_refuse_the_rest() {
        assert_eq!(parse_duration("90s"), Ok(Duration::from_secs(90)));
        assert_eq!(parse_duration("5m"), Ok(Duration::from_secs(300)));
        assert_eq!(parse_duration("1h30m"), Ok(Duration::from_secs(5400)));
        assert_eq!(parse_duration("250ms"), Ok(Duration::from_millis(250)));
        for bad in ["", "90", "s", "1x", "1.5s", "-1s", "1 s"] {
            assert!(parse_duration(bad).is_err(), "{bad}");
        }
        assert!(parse_duration("99999999999999999999h").is_err());
        assert_eq!(parse_jobs("2"), Ok(2));
        assert!(parse_jobs("0").is_err() && parse_jobs("x").is_err() && parse_jobs("1025").is_err());
    }
}
