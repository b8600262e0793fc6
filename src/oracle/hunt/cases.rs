//! The steps every hunt shares: its cases run on threads until done, out of time or
//! interrupted; their outcomes counted; and a finding's scene shrunk asking the renderer
//! once per distinct scene.

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, MutexGuard, PoisonError};
use std::time::Instant;

use super::{generate_scene, HuntConfig};
use crate::harness::runner::{RunError, Runner};
use crate::scene::Scene;

/// Runs the cases of `config.shard` among `0..config.cases` on `jobs` threads (named
/// `name`): each case's scene generated and handed, with the case's number, to `case`;
/// `tick` called after each. Returns the number of cases requested and the results of the
/// cases that ran: the first of the shard's, in order (the runner hands on an unbroken
/// prefix), whatever the number of threads. No case starts once `config.budget` has
/// passed or `interrupted` is set.
///
/// # Errors
/// A scene could not be generated, or the threads could not be started.
pub(super) fn run_cases<T: Send>(
    config: &HuntConfig,
    jobs: usize,
    name: &'static str,
    tick: &(dyn Fn() + Sync),
    interrupted: &AtomicBool,
    case: &(dyn Fn(u64, Scene) -> T + Sync),
) -> Result<(u64, Vec<T>), String> {
    let requested = config.shard.case_count(config.cases);
    let deadline = config.budget.and_then(|b| Instant::now().checked_add(b));
    let stop = || deadline.is_some_and(|d| Instant::now() >= d) || interrupted.load(Ordering::SeqCst);
    let one = |i: u64| -> Result<T, String> {
        let k = config
            .shard
            .case_at(i)
            .ok_or_else(|| format!("the shard has no case at position {i}"))?;
        let result = case(k, generate_scene(config, k)?);
        tick();
        Ok(result)
    };
    let runner = Runner {
        threads: jobs.max(1),
        name,
        ..Runner::default()
    };
    let mut results: Vec<T> = Vec::new();
    runner
        .run(requested, &stop, &one, &mut |_, r| r.map(|r| results.push(r)))
        .map_err(|e| match e {
            RunError::Spawn(e) => format!("cannot start {jobs} threads: {e}"),
            RunError::Case(e) => e,
        })?;
    Ok((requested, results))
}

/// The cases of a hunt counted by how they ended.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(super) struct CaseCounts {
    /// Identical to the oracle.
    pub(super) same: u64,
    /// Different.
    pub(super) differing: u64,
    /// Their renderer failed.
    pub(super) failed: u64,
    /// The oracle refused the scene.
    pub(super) refused: u64,
}

/// The shrink budget of a finding: `runs`, or none once the hunt was interrupted (its
/// findings are then reported as first seen).
pub(super) fn shrink_budget(runs: usize, interrupted: &AtomicBool) -> usize {
    if interrupted.load(Ordering::SeqCst) {
        0
    } else {
        runs
    }
}

/// A shrinker's test of candidate scenes, `keeps` (does the scene still show the
/// finding?), asking it once per distinct scene: the shrinker may reach one scene by two
/// steps, and each answer costs a renderer run.
pub(super) struct AskOnce<F> {
    keeps: F,
    seen: Mutex<HashMap<String, bool>>,
}

impl<F: Fn(&Scene) -> bool + Sync> AskOnce<F> {
    /// `keeps`, remembered.
    pub(super) fn new(keeps: F) -> AskOnce<F> {
        AskOnce {
            keeps,
            seen: Mutex::new(HashMap::new()),
        }
    }

    /// Whether `scene` keeps the finding.
    pub(super) fn keeps(&self, scene: &Scene) -> bool {
        let key = scene.to_json();
        if let Some(&kept) = lock(&self.seen).get(&key) {
            return kept;
        }
        let kept = (self.keeps)(scene);
        lock(&self.seen).insert(key, kept);
        kept
    }

    /// The first of `batch` that keeps the finding, the batch asked side by side.
    pub(super) fn first_kept(&self, batch: &[Scene]) -> Option<usize> {
        if batch.len() == 1 {
            return self.keeps(&batch[0]).then_some(0);
        }
        let kept = crate::chunks::map_each(batch.iter().collect(), batch.len(), |s| self.keeps(s));
        kept.iter().position(|&k| k)
    }

    /// The distinct scenes asked so far.
    pub(super) fn asked(&self) -> usize {
        lock(&self.seen).len()
    }
}

/// `m` locked, whether or not a thread panicked holding it (the data is a cache: every
/// state it can be left in is valid).
fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(PoisonError::into_inner)
}
