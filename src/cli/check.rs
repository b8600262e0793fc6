//! `rasterproof check`: the invariant suite ([`rasterproof::harness::suite`]) on seeded
//! random cases, with a progress bar, the failing cases written to `--out` (the exact and
//! integer models' failures; the float models' too with `--out-float`), and the table with
//! its legend.

use std::path::Path;
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressStyle};
use rasterproof::check::Violation;
use rasterproof::harness::{generate, run_case, Outcome, Tally};
use rasterproof::scene::Scene;

use super::print_stdout;

/// Which failing cases `--out` writes.
#[derive(Debug, Clone, Copy)]
pub struct Written<'a> {
    /// `--out`: the folder; `None` writes nothing.
    pub dir: Option<&'a Path>,
    /// `--out-float`: the float models' violations too, not only the fatal ones.
    pub float: bool,
}

impl Written<'_> {
    /// Whether the failing outcome `o` is written.
    fn wants(&self, o: &Outcome) -> bool {
        o.is_fatal() || self.float
    }
}

/// Runs `cases` cases of the suite seeded `seed`, writes the failures `out` asks for and
/// prints the report; exit 1 when an exact or integer model failed.
pub fn run(cases: u64, seed: u64, out: Written<'_>, quiet: bool) -> Result<ExitCode, String> {
    if let Some(dir) = out.dir {
        std::fs::create_dir_all(dir).map_err(|e| format!("--out {}: cannot create: {e}", dir.display()))?;
    }
    let bar = if quiet {
        ProgressBar::hidden()
    } else {
        ProgressBar::new(cases)
    };
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} cases, {elapsed} ({eta} left)").expect("static template"),
    );
    let mut tally = Tally::new(seed);
    for k in 0..cases {
        let case = generate(seed, k)?;
        let run = run_case(&case);
        for o in &run.outcomes {
            let Some((scene, v)) = o.repro() else { continue };
            if o.is_fatal() {
                bar.suspend(|| eprintln!("case {k}: {} ({}): {v}", o.invariant, o.label));
            }
            if let Some(dir) = out.dir.filter(|_| out.wants(o)) {
                write_case(dir, k, o, scene, v)?;
            }
        }
        tally.add(&run);
        bar.inc(1);
    }
    bar.finish_and_clear();
    for line in tally.lines() {
        print_stdout(&line)?;
    }
    Ok(if tally.passed() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// Writes the failing outcome `o` of case `k` into `dir`: its scene as
/// `case-K-INVARIANT-MODEL.json` and its violation as the `.txt` next to it.
fn write_case(dir: &Path, k: u64, o: &Outcome, scene: &Scene, v: &Violation) -> Result<(), String> {
    let slug: String = o
        .invariant
        .chars()
        .map(|ch| if ch.is_ascii_alphanumeric() { ch } else { '-' })
        .collect();
    let label: String = o.label.chars().map(|ch| if ch == '/' { '-' } else { ch }).collect();
    let stem = dir.join(format!("case-{k}-{slug}-{label}"));
    let json = stem.with_extension("json");
    std::fs::write(&json, scene.to_json()).map_err(|e| format!("{}: cannot write: {e}", json.display()))?;
    let txt = stem.with_extension("txt");
    std::fs::write(&txt, format!("{v}\n")).map_err(|e| format!("{}: cannot write: {e}", txt.display()))
}
