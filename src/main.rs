//! The `rasterproof` command: render a scene exactly, run the invariant suite.
//!
//! Exit codes ([`cli::EXIT_CODES`], at the end of every command's `--help`): 0 success;
//! 1 an invariant of an exact or integer model was violated (`check`, `check-merge`), an
//! exact or integer model shows an error (`trade`), the images differ (`compare`), no
//! convention fits (`compare --fit`), `hunt` found something; 2 bad input (with a
//! one-line error naming the file, field and value; `render` and `flood` then write no
//! output file).

#![forbid(unsafe_code)]

mod cli;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Exact reference rasterizer and verification harness for 2D rasterization.
#[derive(Parser)]
#[command(name = "rasterproof", version, about, after_help = cli::EXIT_CODES)]
struct Args {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene file with one model.
    #[command(after_help = cli::EXIT_CODES)]
    Render(cli::render::Options),
    /// The planned exact engine's arithmetic per primitive, the bound that forced it, and
    /// which fixed-width models are exact for the scene.
    #[command(after_help = cli::EXIT_CODES)]
    Plan(cli::plan::Options),
    /// Compare another renderer's output (PNG or render's JSON) with the oracle; classify
    /// and explain every differing pixel exactly.
    #[command(after_help = cli::EXIT_CODES)]
    Compare(cli::compare::Options),
    /// Explain one pixel: its exact sample, each nearby primitive's edge values and
    /// flags, and what every model decides; with `--as values`, a varying's exact value
    /// there, derived, against theirs.
    #[command(after_help = cli::EXIT_CODES)]
    Explain(cli::explain::Options),
    /// Differential testing of another renderer (a program): random scenes rendered by it
    /// and compared with the oracle; each distinct failure shrunk to a minimal scene.
    #[command(after_help = cli::EXIT_CODES)]
    Hunt(cli::hunt::Options),
    /// Clip a scene's primitives against its clip window; print them exactly.
    #[command(after_help = cli::EXIT_CODES)]
    Clip(cli::clip::Options),
    /// Flood fill: the 4- or 8-connected region of one pixel's colour in a PNG.
    #[command(after_help = cli::EXIT_CODES)]
    Flood(cli::flood::Options),
    /// Run the invariant suite on random cases (on N threads, one shard, within a time
    /// budget); print the table, its findings, a legend of its terms, and the verdict.
    #[command(after_help = cli::EXIT_CODES)]
    Check(cli::check::Options),
    /// Merge the reports of a run's shards (check --shard K/N --report) into the whole
    /// run's; print it as check does.
    #[command(after_help = cli::EXIT_CODES)]
    CheckMerge(cli::check::MergeOptions),
    /// Merge the reports of a hunt's shards (hunt --shard K/N --report) into the whole
    /// hunt's report; print its counts and findings.
    #[command(after_help = cli::EXIT_CODES)]
    HuntMerge(cli::hunt::MergeOptions),
    /// Turn geometry you hold into a scene file, exactly as its floats read: RenderDoc's
    /// mesh-viewer CSV export of post-transform positions, or raw little-endian f32
    /// position buffers (with an optional index buffer).
    #[command(after_help = cli::EXIT_CODES)]
    Import(cli::import::Options),
    /// Every model's speed and error side by side, on seeded workloads at coordinate
    /// magnitudes 0 to 2^30 px: the tables, and with --out trade.json, trade.md and the
    /// pictures. Exit 1 when an exact or integer model shows an error.
    #[command(after_help = cli::EXIT_CODES)]
    Trade(cli::trade::Options),
}

fn main() -> ExitCode {
    let args = Args::parse();
    let result = match args.command {
        Command::Render(options) => cli::render::run(&options),
        Command::Plan(options) => cli::plan::run(&options),
        Command::Compare(options) => cli::compare::run(&options),
        Command::Explain(options) => cli::explain::run(&options),
        Command::Hunt(options) => cli::hunt::run(&options),
        Command::Clip(options) => cli::clip::run(&options),
        Command::Flood(options) => cli::flood::run(&options),
        Command::Check(options) => cli::check::run(&options),
        Command::CheckMerge(options) => cli::check::merge(&options),
        Command::HuntMerge(options) => cli::hunt::merge(&options),
        Command::Import(options) => cli::import::run(&options),
        Command::Trade(options) => cli::trade::run(&options),
    };
    match result {
        Ok(code) => code,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::from(2)
        }
    }
}
