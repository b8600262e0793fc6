//! Running the suite at scale: a [`SuiteConfig`] (seed, cases, shard, threads, time budget) run
//! by the harness's [`Runner`] into a [`SuiteReport`]. The shard's cases run on `jobs`
//! threads; their results come back in case order and are folded into the report one by
//! one as they come, so the report does not depend on the number of threads.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use super::{generate, run_case, CaseRun, CheckOutcome, Shard, SuiteReport};
use crate::harness::runner::{RunError, Runner, DEFAULT_STACK};

/// At most this many threads.
pub const MAX_JOBS: usize = 1024;

/// Where `check --out` writes failing cases' scenes: which outcomes and under which name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SceneFiles {
    /// The folder.
    pub dir: PathBuf,
    /// Also the float models' violations, not only the fatal ones (`--out-float`).
    pub float: bool,
}

impl SceneFiles {
    /// The scene file of the failing outcome `o` of case `k`, when it is one to write:
    /// `DIR/case-K-INVARIANT-MODEL.json` (the invariant's non-alphanumeric characters and
    /// the label's `/` written `-`); its explanation goes beside it as the `.txt`.
    ///
    /// ```
    /// use rasterproof::harness::suite::SceneFiles;
    /// use rasterproof::harness::{generate, run_case};
    /// let files = SceneFiles { dir: "out".into(), float: true };
    /// let run = run_case(&generate(0, 0).unwrap());
    /// let o = run.outcomes.iter().find(|o| o.result.is_err()).unwrap();
    /// let path = files.path_for(0, o).unwrap();
    /// assert!(path.starts_with("out") && path.to_str().unwrap().ends_with(".json"));
    /// assert!(files.path_for(0, &run.outcomes[0]).is_none() || run.outcomes[0].result.is_err());
    /// ```
    pub fn path_for(&self, k: u64, o: &CheckOutcome) -> Option<PathBuf> {
        if o.result.is_ok() || !(o.is_fatal() || self.float) {
            return None;
        }
        Some(scene_path(&self.dir, k, o))
    }
}

/// `dir/case-K-INVARIANT-MODEL.json` for outcome `o` of case `k`.
fn scene_path(dir: &Path, k: u64, o: &CheckOutcome) -> PathBuf {
    let slug: String = o
        .invariant
        .chars()
        .map(|ch| if ch.is_ascii_alphanumeric() { ch } else { '-' })
        .collect();
    let label: String = o.label.chars().map(|ch| if ch == '/' { '-' } else { ch }).collect();
    dir.join(format!("case-{k}-{slug}-{label}.json"))
}

/// What to run: the suite's cases `0..cases` of the run seeded `seed`, those of `shard`,
/// on `jobs` threads, stopping when `budget` has passed.
///
/// ```
/// use rasterproof::harness::suite::{SuiteConfig, Shard};
/// let report = SuiteConfig { shard: Shard::new(2, 3).unwrap(), jobs: 2, ..SuiteConfig::new(7, 6) }.run().unwrap();
/// assert_eq!(report.cases_run(), 2); // cases 1 and 4
/// assert!(report.is_complete() && report.passed());
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SuiteConfig {
    /// The seed of the case generator.
    pub seed: u64,
    /// The whole run's cases, `0..cases`, whatever the shard.
    pub cases: u64,
    /// The shard to run.
    pub shard: Shard,
    /// Threads, `1..=MAX_JOBS`.
    pub jobs: usize,
    /// No case starts once this much time has passed since the start; `None`: no limit.
    pub budget: Option<Duration>,
    /// Where the report says failing scenes were written (the caller writes them: see
    /// [`Hooks::on_case`]); `None`: nowhere.
    pub scene_files: Option<SceneFiles>,
}

/// What [`Hooks::on_case`] is called with: a case's index and outcomes.
pub type OnCase<'a> = &'a mut dyn FnMut(u64, &CaseRun) -> Result<(), String>;

/// What the caller sees while a [`SuiteConfig`] runs.
#[derive(Default)]
pub struct Hooks<'a> {
    /// When set, no further case starts; the report says the run was interrupted.
    pub stop: Option<&'a AtomicBool>,
    /// Called on a worker thread each time a case has run (for a progress bar).
    pub tick: Option<&'a (dyn Fn() + Sync)>,
    /// Called with each case that ran and its outcomes, in index order, before it is
    /// added to the report (to print and write its failures); an error ends the run.
    pub on_case: Option<OnCase<'a>>,
}

impl SuiteConfig {
    /// Every case of `0..cases` seeded `seed`, one thread, no budget, no files.
    pub fn new(seed: u64, cases: u64) -> SuiteConfig {
        SuiteConfig {
            seed,
            cases,
            shard: Shard::WHOLE,
            jobs: 1,
            budget: None,
            scene_files: None,
        }
    }

    /// How many cases the plan's shard holds.
    pub fn case_count(&self) -> u64 {
        self.shard.case_count(self.cases)
    }

    /// Runs the plan with no hooks (see [`SuiteConfig::run_with`]).
    ///
    /// # Errors
    /// As [`SuiteConfig::run_with`].
    pub fn run(&self) -> Result<SuiteReport, String> {
        self.run_with(Hooks::default())
    }

    /// Runs the shard's cases in index order, `jobs` at a time, until they are done, the
    /// budget has passed or `hooks.stop` is set; the cases that ran are the first of the
    /// shard's, and the report says why the others did not.
    ///
    /// # Errors
    /// `jobs` outside `1..=MAX_JOBS`, the threads cannot start, a case cannot be
    /// generated, or `hooks.on_case` fails: its message.
    pub fn run_with(&self, mut hooks: Hooks<'_>) -> Result<SuiteReport, String> {
        if !(1..=MAX_JOBS).contains(&self.jobs) {
            return Err(format!("jobs {}: expected 1..={MAX_JOBS} threads", self.jobs));
        }
        let runner = Runner {
            threads: self.jobs,
            stack: DEFAULT_STACK,
            name: "rasterproof-check",
        };
        let start = Instant::now();
        let deadline = self.budget.and_then(|b| start.checked_add(b));
        let never = AtomicBool::new(false);
        let stop = hooks.stop.unwrap_or(&never);
        let halted = || stop.load(Ordering::Relaxed) || deadline.is_some_and(|d| Instant::now() >= d);
        let tick = hooks.tick;
        let case_of = |j: u64| self.shard.case_at(j).expect("a position of the shard's cases");
        let case = |j: u64| {
            let run = generate(self.seed, case_of(j)).map(|case| run_case(&case));
            if let Some(tick) = tick {
                tick();
            }
            run
        };
        let files = self.scene_files.as_ref();
        let path_of =
            |k: u64| move |o: &CheckOutcome| files.and_then(|f| f.path_for(k, o)).map(|p| p.display().to_string());
        let mut report = SuiteReport::new(self.seed, self.cases, self.shard);
        let mut fold = |j: u64, run: Result<CaseRun, String>| -> Result<(), String> {
            let k = case_of(j);
            let run = run?;
            if let Some(on_case) = hooks.on_case.as_mut() {
                on_case(k, &run)?;
            }
            report.add(k, &run, &path_of(k));
            Ok(())
        };
        let ran = runner
            .run(self.case_count(), &halted, &case, &mut fold)
            .map_err(|e| match e {
                RunError::Spawn(e) => format!("cannot start {} threads: {e}", self.jobs),
                RunError::Case(e) => e,
            })?;
        if ran.stopped {
            report.stop(self.stopped_why(&report, stop.load(Ordering::Relaxed)));
        }
        Ok(report)
    }

    /// Why the run ended after `report`'s cases: interrupted, or the budget.
    fn stopped_why(&self, report: &SuiteReport, interrupted: bool) -> String {
        let shard = if self.shard == Shard::WHOLE {
            String::new()
        } else {
            format!("shard {}: ", self.shard)
        };
        let why = match self.budget {
            Some(b) if !interrupted => format!("the time budget ({b:?}) ran out"),
            _ => "interrupted".to_string(),
        };
        format!(
            "{shard}{why} after {} of {} cases",
            report.cases_run(),
            self.case_count()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two threads give the report of one; a stop set before the start runs nothing and
    /// says so; a zero budget stops at once too; jobs 0 is refused.
    #[test]
    fn threads_budget_and_stop() {
        let one = SuiteConfig::new(3, 3).run().unwrap();
        let two = SuiteConfig {
            jobs: 2,
            ..SuiteConfig::new(3, 3)
        }
        .run()
        .unwrap();
        assert_eq!(one, two);
        assert_eq!(one.to_json(), two.to_json());

        let stop = AtomicBool::new(true);
        let stopped = SuiteConfig::new(3, 6)
            .run_with(Hooks {
                stop: Some(&stop),
                ..Hooks::default()
            })
            .unwrap();
        assert_eq!(stopped.cases_run(), 0);
        assert!(!stopped.is_complete());
        assert_eq!(stopped.stopped(), ["interrupted after 0 of 6 cases"]);

        let none = SuiteConfig {
            budget: Some(Duration::ZERO),
            shard: Shard::new(1, 2).unwrap(),
            ..SuiteConfig::new(3, 6)
        }
        .run()
        .unwrap();
        assert_eq!(
            none.stopped(),
            ["shard 1/2: the time budget (0ns) ran out after 0 of 3 cases"]
        );

        let e = SuiteConfig {
            jobs: 0,
            ..SuiteConfig::new(3, 6)
        }
        .run()
        .unwrap_err();
        assert!(e.contains("jobs 0"), "{e}");
    }

    /// on_case sees every case in index order, even with several threads.
    #[test]
    fn on_case_sees_cases_in_order() {
        let mut seen = Vec::new();
        let mut on_case = |k: u64, _: &CaseRun| {
            seen.push(k);
            Ok(())
        };
        SuiteConfig {
            jobs: 2,
            shard: Shard::new(2, 2).unwrap(),
            ..SuiteConfig::new(1, 7)
        }
        .run_with(Hooks {
            on_case: Some(&mut on_case),
            ..Hooks::default()
        })
        .unwrap();
        assert_eq!(seen, [1, 3, 5]);
    }
}
