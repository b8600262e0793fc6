//! The `rasterproof` command: render a scene exactly, run the invariant suite.
//!
//! Exit codes ([`cli::EXIT_CODES`], at the end of every command's `--help`): 0 success;
//! 1 an invariant of an exact or integer model was violated (`check`); 2 bad input (with a
//! one-line error naming the file, field and value; `render` and `flood` then write no
//! output file).

#![forbid(unsafe_code)]

mod cli;

use std::path::PathBuf;
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
    /// Clip a scene's primitives against its clip window; print them exactly.
    #[command(after_help = cli::EXIT_CODES)]
    Clip(cli::clip::Options),
    /// Flood fill: the 4- or 8-connected region of one pixel's colour in a PNG.
    #[command(after_help = cli::EXIT_CODES)]
    Flood(cli::flood::Options),
    /// Run the invariant suite on random cases; print the table, a legend of its terms,
    /// and the verdict.
    #[command(after_help = cli::EXIT_CODES)]
    Check {
        /// Number of random cases.
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
        /// Hide the progress bar.
        #[arg(long)]
        quiet: bool,
    },
}

fn main() -> ExitCode {
    let args = Args::parse();
    let result = match args.command {
        Command::Render(options) => cli::render::run(&options),
        Command::Plan(options) => cli::plan::run(&options),
        Command::Clip(options) => cli::clip::run(&options),
        Command::Flood(options) => cli::flood::run(&options),
        Command::Check {
            cases,
            seed,
            out,
            out_float,
            quiet,
        } => cli::check::run(
            cases,
            seed,
            cli::check::Written {
                dir: out.as_deref(),
                float: out_float,
            },
            quiet,
        ),
    };
    match result {
        Ok(code) => code,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::from(2)
        }
    }
}
