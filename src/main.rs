//! The `rasterproof` command: render a scene exactly, run the invariant suite.
//!
//! Exit codes: 0 success; 1 an invariant of the exact or fixed model was violated;
//! 2 bad input (with a one-line error naming the file, field and value).

#![forbid(unsafe_code)]

mod cli;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Exact reference rasterizer and verification harness for 2D rasterization.
#[derive(Parser)]
#[command(name = "rasterproof", version, about)]
struct Args {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene file with one model.
    Render(cli::render::Options),
    /// Clip a scene's primitives against its clip window; print them exactly.
    Clip(cli::clip::Options),
    /// Flood fill: the 4- or 8-connected region of one pixel's colour in a PNG.
    Flood(cli::flood::Options),
    /// Run the invariant suite on random cases.
    Check {
        /// Number of random cases.
        #[arg(long, default_value_t = 256)]
        cases: u64,
        /// Seed of the case generator (same seed, same cases).
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// Write each failing case as a scene file into this folder.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Hide the progress bar.
        #[arg(long)]
        quiet: bool,
    },
}

fn main() -> ExitCode {
    let args = Args::parse();
    let result = match args.command {
        Command::Render(options) => cli::render::run(&options),
        Command::Clip(options) => cli::clip::run(&options),
        Command::Flood(options) => cli::flood::run(&options),
        Command::Check {
            cases,
            seed,
            out,
            quiet,
        } => cli::check::run(cases, seed, out.as_deref(), quiet),
    };
    match result {
        Ok(code) => code,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::from(2)
        }
    }
}
