//! `rasterproof trade`: every model's speed and error side by side, by coordinate
//! magnitude ([`rasterproof::trade::run`]); the tables on stdout, and with `--out DIR`
//! trade.json, trade.md and the pictures, written all or nothing.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use rasterproof::trade::{run as run_trade, Config, Family, Magnitude, TradeReport};

use super::OutputFormat;

/// What `trade` was asked to do.
#[derive(clap::Args)]
pub struct Options {
    /// Small workloads (128 px canvas) and 3 repetitions: well under a minute; what CI runs.
    #[arg(long)]
    quick: bool,
    /// Only these families: triangles, lines, polygons, clipping, area, values (repeat the
    /// option or separate with commas; default: all).
    #[arg(long = "family", value_name = "F", value_delimiter = ',', num_args = 1..)]
    families: Vec<String>,
    /// The window's distance from the origin, px, comma-separated: 0, 2^k (k <= 40) or a
    /// number of pixels (the values family has its own: 0, 2^4, ..., 2^24, and attribute
    /// scales 2^0 to 2^32).
    #[arg(long, value_name = "LIST", default_value = "0,2^10,2^16,2^20,2^23,2^24,2^30")]
    magnitudes: String,
    /// The workloads' seed.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Write trade.json, trade.md and the pictures (speed-vs-error, error-vs-magnitude,
    /// predicate-map, area-speed-vs-error, area-error-vs-magnitude, values-error-vs-offset,
    /// values-error-vs-scale, values-speed-vs-error; PNG and SVG) into DIR, created if
    /// missing. All or nothing: a failing run leaves none of them behind.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Output format on stdout.
    #[arg(long, default_value_t = OutputFormat::Text, value_parser = OutputFormat::parser(FORMATS))]
    format: OutputFormat,
    /// No progress lines on stderr.
    #[arg(long)]
    quiet: bool,
}

/// `--format`'s values for `trade`, with their help.
const FORMATS: [(OutputFormat, &str); 2] = [
    (OutputFormat::Text, "The tables (trade.md's Markdown)"),
    (
        OutputFormat::Json,
        "trade.json's object (schema in README.md, \"The trade\")",
    ),
];

/// `--family` values, or every family.
fn families(names: &[String]) -> Result<Vec<Family>, String> {
    if names.is_empty() {
        return Ok(Family::ALL.to_vec());
    }
    let mut out = Vec::new();
    for n in names {
        let f = Family::from_name(n.trim()).ok_or_else(|| {
            let all: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
            format!("--family: unknown family {n:?} (expected one of {})", all.join(", "))
        })?;
        if !out.contains(&f) {
            out.push(f);
        }
    }
    out.sort_unstable();
    Ok(out)
}

/// `--out DIR` must be a folder or not exist yet.
fn check_out(dir: &Path) -> Result<(), String> {
    if dir.exists() && !dir.is_dir() {
        return Err(format!("{}: --out names a file, not a folder", dir.display()));
    }
    Ok(())
}

/// Writes the report's files into `dir`, all or nothing (a folder this call created is
/// removed again when writing fails).
fn write_files(dir: &Path, report: &TradeReport, json: &str, markdown: &str) -> Result<(), String> {
    let pictures = report.pictures()?;
    let created = !dir.exists();
    if created {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: cannot create the folder: {e}", dir.display()))?;
    }
    let staged = (|| {
        let mut out = super::Outputs::new();
        out.stage_text(&dir.join("trade.json"), json)?;
        out.stage_text(&dir.join("trade.md"), markdown)?;
        for p in &pictures {
            out.stage(&dir.join(&p.name), "picture", |w| {
                std::io::Write::write_all(w, &p.bytes)
            })?;
        }
        out.commit()
    })();
    if staged.is_err() && created {
        let _ = std::fs::remove_dir(dir);
    }
    staged
}

/// Runs the trade as `o` asks, writes `--out` (all or nothing) and prints the tables;
/// exit 1 when an exact or integer model shows an error.
pub fn run(o: &Options) -> Result<ExitCode, String> {
    let config = Config {
        quick: o.quick,
        seed: o.seed,
        families: families(&o.families)?,
        magnitudes: Magnitude::parse_list(&o.magnitudes).map_err(|e| format!("--magnitudes: {e}"))?,
    };
    if let Some(dir) = &o.out {
        check_out(dir)?;
    }
    let quiet = o.quiet;
    let start = std::time::Instant::now();
    let report = run_trade(&config, &mut |line| {
        if !quiet {
            eprintln!("trade: {line} ({:.1} s)", start.elapsed().as_secs_f64());
        }
    });
    let json = format!("{:#}\n", report.to_json());
    let markdown = report.to_markdown();
    if let Some(dir) = &o.out {
        write_files(dir, &report, &json, &markdown)?;
    }
    match o.format {
        OutputFormat::Text => super::write_stdout(|w| w.write_all(markdown.as_bytes()))?,
        OutputFormat::Json => super::write_stdout(|w| w.write_all(json.as_bytes()))?,
    }
    if !quiet {
        eprintln!("trade: done in {:.1} s", start.elapsed().as_secs_f64());
    }
    let broken = report.exact_errors();
    if broken.is_empty() {
        Ok(ExitCode::SUCCESS)
    } else {
        for b in &broken {
            eprintln!("trade: an exact model is wrong: {b}");
        }
        Ok(ExitCode::from(1))
    }
}
