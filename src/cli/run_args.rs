//! The run arguments `check` and `hunt` share — threads, one shard of the cases, a time
//! budget, the progress bar — and the report arguments they share with `check-merge`,
//! each declared once and flattened into each command's options.

use std::path::{Path, PathBuf};
use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};
use rasterproof::harness::suite::{Shard, MAX_JOBS};

/// How a run of cases runs (`check`, `hunt`): on how many threads, which shard of the
/// cases, for how long, with or without a progress bar, and which reports it writes.
#[derive(clap::Args, Debug, Clone)]
pub struct RunArgs {
    /// Run the cases on N threads (1..=1024); the results do not depend on N.
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = parse_jobs)]
    pub jobs: usize,
    /// Run shard K of N only: the cases k of 0..cases with k mod N = K - 1 (1 <= K <= N);
    /// the N shards together run exactly the unsharded run's cases, and their reports
    /// merge into its report (check-merge).
    #[arg(long, value_name = "K/N", value_parser = parse_shard)]
    shard: Option<Shard>,
    /// Start no case after this much time (90s, 5m, 1h, 1h30m; units ms, s, m, h): the
    /// running cases finish, and the cases that ran are the first of the shard's, in order.
    /// (check: Ctrl-C stops the same way, and the report covers the cases done.)
    #[arg(long, value_name = "DURATION", value_parser = parse_duration)]
    pub time: Option<Duration>,
    /// Hide the progress bar.
    #[arg(long)]
    quiet: bool,
    /// The reports.
    #[command(flatten)]
    pub outputs: ReportArgs,
}

impl RunArgs {
    /// The shard asked for; the whole run without `--shard`.
    pub fn shard(&self) -> Shard {
        self.shard.unwrap_or(Shard::WHOLE)
    }

    /// A progress bar over `len` cases that names them `what` ("cases", "scenes");
    /// hidden with `--quiet`.
    pub fn progress_bar(&self, len: u64, what: &str) -> ProgressBar {
        let bar = if self.quiet {
            ProgressBar::hidden()
        } else {
            ProgressBar::new(len)
        };
        bar.set_style(
            ProgressStyle::with_template(&format!(
                "{{bar:40}} {{pos}}/{{len}} {what}, {{elapsed}} ({{eta}} left)"
            ))
            .expect("a fixed template"),
        );
        bar
    }
}

/// The reports a run writes (`check`, `check-merge`, `hunt`).
#[derive(clap::Args, Debug, Clone)]
pub struct ReportArgs {
    /// Write the report as JSON: the run (seed, shard, cases asked for and run), its
    /// counts and every failure with its scene (schemas: docs/cli.md, `check`;
    /// docs/oracle.md, `hunt`).
    #[arg(long, value_name = "FILE.json")]
    pub report: Option<PathBuf>,
    /// Write the result as JUnit XML (check: one test case per invariant and model, failed
    /// when an exact or integer model violated it; hunt: one failed test case per finding,
    /// one passing with the counts).
    #[arg(long, value_name = "FILE.xml")]
    pub junit: Option<PathBuf>,
}

impl ReportArgs {
    /// Fails early, before a long run, when an output cannot be written: `--report` and
    /// `--junit` name one file, or one is a folder or in a folder that does not exist.
    /// [`super::Outputs`] still checks everything when it writes.
    pub fn check_writable(&self) -> Result<(), String> {
        let (json, junit) = (self.report.as_deref(), self.junit.as_deref());
        if let (Some(a), Some(b)) = (json, junit) {
            if a == b {
                return Err(format!("--report and --junit: both name {}", a.display()));
            }
        }
        json.into_iter().chain(junit).try_for_each(writable)
    }
}

/// `--jobs N`: 1..=[`MAX_JOBS`].
fn parse_jobs(s: &str) -> Result<usize, String> {
    match s.parse::<usize>() {
        Ok(n) if (1..=MAX_JOBS).contains(&n) => Ok(n),
        _ => Err(format!("expected a number of threads in 1..={MAX_JOBS}")),
    }
}

/// `--shard K/N` (`check`, `hunt`): shard K of N, `1 <= K <= N`.
fn parse_shard(s: &str) -> Result<Shard, String> {
    s.parse()
}

/// `--time DURATION` (`check`, `hunt`): one or more `<integer><unit>`, unit `ms`, `s`, `m` or `h`.
fn parse_duration(s: &str) -> Result<Duration, String> {
    let bad = || "expected a duration such as 90s, 5m, 1h or 1h30m (units ms, s, m, h)".to_string();
    let mut total = Duration::ZERO;
    let mut rest = s.trim();
    if rest.is_empty() {
        return Err(bad());
    }
    while !rest.is_empty() {
        let digits = rest.find(|c: char| !c.is_ascii_digit()).ok_or_else(bad)?;
        let n: u64 = rest[..digits].parse().map_err(|_| bad())?;
        rest = &rest[digits..];
        let unit_len = rest.find(|c: char| c.is_ascii_digit()).unwrap_or(rest.len());
        let part = match &rest[..unit_len] {
            "ms" => Some(Duration::from_millis(n)),
            "s" => Some(Duration::from_secs(n)),
            "m" => n.checked_mul(60).map(Duration::from_secs),
            "h" => n.checked_mul(3600).map(Duration::from_secs),
            _ => return Err(bad()),
        };
        total = part
            .and_then(|p| total.checked_add(p))
            .ok_or_else(|| "too long a duration".to_string())?;
        rest = &rest[unit_len..];
    }
    Ok(total)
}

/// Whether `path` can be written: see [`ReportArgs::check_writable`].
fn writable(path: &Path) -> Result<(), String> {
    if path.is_dir() {
        return Err(format!("{}: cannot write: it is a folder", path.display()));
    }
    match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() && !dir.is_dir() => {
            Err(format!("{}: cannot write: no folder {}", path.display(), dir.display()))
        }
        _ => Ok(()),
    }
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
