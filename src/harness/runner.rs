//! One way to run numbered cases on several threads: [`Runner`]. `threads` scoped std
//! threads claim the next index from one atomic counter, check a stop predicate before
//! each case, and send what the case returned to the calling thread, which hands the
//! results on in index order (a per-case callback, [`Runner::run`], or all of them
//! collected, [`Runner::collect`]). No thread pool outlives the call, and the result does
//! not depend on the number of threads.
//!
//! The suite's [`SuiteConfig`](super::suite::SuiteConfig) runs its cases this way (`check --jobs N`).
//! A caller with its own work queue moves to it in three steps, as `oracle::hunt` can:
//!
//! 1. its queue of case numbers becomes `count` (a shard's cases are its positions
//!    `0..count`, mapped to case numbers inside `case`, as the suite does with
//!    [`Shard::case_at`](super::suite::Shard::case_at));
//! 2. its deadline or cancel flag becomes `stop` (checked before each case, as the
//!    hunt's claim checks its deadline);
//! 3. its shared result list (a `Mutex<Vec<_>>` sorted afterwards) becomes the returned
//!    `Vec` of [`Runner::collect`], already in index order, or the callback of
//!    [`Runner::run`] when the results are folded as they come; an error of a case
//!    (a scene that cannot be generated) is returned by `case` and raised by the
//!    callback, which ends the run.
//!
//! The cases that are handed on are always the first ones: once `stop` holds for a case,
//! that case and every later one are dropped, even those another thread had already run,
//! so that a stopped run reports a prefix of its cases, the same on any number of
//! threads.

use std::collections::BTreeMap;
use std::io;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::mpsc;

/// Stack of each worker thread: the main thread's usual 8 MiB, for the deep recursions of
/// the exact arithmetic and the triangulation on big inputs.
pub const DEFAULT_STACK: usize = 8 << 20;

/// How to run cases: on how many threads, with what stack, under what name.
///
/// ```
/// use rasterproof::harness::runner::{Ran, Runner};
/// let runner = Runner { threads: 3, ..Runner::default() };
/// let (squares, ran) = runner.collect(10, &|| false, &|i| i * i).unwrap();
/// assert_eq!(squares, [0, 1, 4, 9, 16, 25, 36, 49, 64, 81]);
/// assert_eq!(ran, Ran { cases: 10, stopped: false });
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Runner<'a> {
    /// Worker threads (0 is taken as 1). The calling thread does not run cases: it hands
    /// the results on.
    pub threads: usize,
    /// Each worker's stack, bytes.
    pub stack: usize,
    /// The workers are named `NAME-0`, `NAME-1`, ...
    pub name: &'a str,
}

impl Default for Runner<'_> {
    /// One thread of [`DEFAULT_STACK`], named `rasterproof-N`.
    fn default() -> Self {
        Runner {
            threads: 1,
            stack: DEFAULT_STACK,
            name: "rasterproof",
        }
    }
}

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Ran {
    /// How many cases were handed on: the first `cases` of `0..count`.
    pub cases: u64,
    /// Whether the stop predicate ended the run before every case ran.
    pub stopped: bool,
}

/// Why a run failed.
#[derive(Debug)]
pub enum RunError<E> {
    /// A worker thread could not be started.
    Spawn(io::Error),
    /// The per-case callback failed: its error (the run ended there).
    Case(E),
}

impl<'a> Runner<'a> {
    /// Runs `case(i)` for `i` in `0..count` on the runner's threads and calls `each(i,
    /// result)` on the calling thread in index order, as the results come in. Before each
    /// case a worker asks `stop()`: once it holds, no further case starts, and the run
    /// ends after the last case of the unbroken prefix that ran (later results, which
    /// other threads may have computed, are dropped). An error of `each` ends the run the
    /// same way.
    ///
    /// ```
    /// use rasterproof::harness::runner::{Ran, Runner};
    /// use std::sync::atomic::{AtomicU64, Ordering};
    /// let started = AtomicU64::new(0);
    /// let stop = || started.fetch_add(1, Ordering::Relaxed) >= 4; // 4 cases start
    /// let mut seen = Vec::new();
    /// let runner = Runner { threads: 2, ..Runner::default() };
    /// let ran = runner
    ///     .run(100, &stop, &|i| i + 1, &mut |i, v| {
    ///         seen.push((i, v));
    ///         Ok::<(), String>(())
    ///     })
    ///     .unwrap();
    /// assert_eq!(ran, Ran { cases: 4, stopped: true });
    /// assert_eq!(seen, [(0, 1), (1, 2), (2, 3), (3, 4)]);
    /// ```
    ///
    /// # Errors
    /// A thread cannot start ([`RunError::Spawn`]), or `each` fails ([`RunError::Case`]).
    ///
    /// # Panics
    /// A case panics: the panic is raised here once every thread has ended.
    pub fn run<T: Send, E>(
        &self,
        count: u64,
        stop: &(dyn Fn() -> bool + Sync),
        case: &(dyn Fn(u64) -> T + Sync),
        each: &mut dyn FnMut(u64, T) -> Result<(), E>,
    ) -> Result<Ran, RunError<E>> {
        let next = AtomicU64::new(0);
        let ended = AtomicBool::new(false);
        std::thread::scope(|s| {
            let (tx, rx) = mpsc::channel::<(u64, Option<T>)>();
            for t in 0..self.threads.max(1) {
                let tx = tx.clone();
                let (next, ended) = (&next, &ended);
                let worker = move || loop {
                    if ended.load(Ordering::Relaxed) {
                        break;
                    }
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    if i >= count {
                        break;
                    }
                    if stop() {
                        ended.store(true, Ordering::Relaxed);
                        let _ = tx.send((i, None));
                        break;
                    }
                    if tx.send((i, Some(case(i)))).is_err() {
                        break;
                    }
                };
                let spawned = std::thread::Builder::new()
                    .name(format!("{}-{t}", self.name))
                    .stack_size(self.stack)
                    .spawn_scoped(s, worker);
                if let Err(e) = spawned {
                    ended.store(true, Ordering::Relaxed);
                    return Err(RunError::Spawn(e));
                }
            }
            drop(tx);
            // Results that came in before an earlier one, by index.
            let mut early: BTreeMap<u64, Option<T>> = BTreeMap::new();
            let mut cases = 0;
            for (i, result) in rx {
                early.insert(i, result);
                while let Some(result) = early.remove(&cases) {
                    let Some(result) = result else {
                        ended.store(true, Ordering::Relaxed);
                        return Ok(Ran { cases, stopped: true });
                    };
                    if let Err(e) = each(cases, result) {
                        ended.store(true, Ordering::Relaxed);
                        return Err(RunError::Case(e));
                    }
                    cases += 1;
                }
            }
            Ok(Ran { cases, stopped: false })
        })
    }

    /// Runs `case(i)` for `i` in `0..count` as [`Runner::run`] does and returns the
    /// results of the cases that ran, in index order, with how the run ended.
    ///
    /// # Errors
    /// A thread cannot start.
    ///
    /// # Panics
    /// A case panics: the panic is raised here once every thread has ended.
    pub fn collect<T: Send>(
        &self,
        count: u64,
        stop: &(dyn Fn() -> bool + Sync),
        case: &(dyn Fn(u64) -> T + Sync),
    ) -> io::Result<(Vec<T>, Ran)> {
        let mut out = Vec::new();
        let ran = self.run(count, stop, case, &mut |_, t| {
            out.push(t);
            Ok::<(), std::convert::Infallible>(())
        });
        match ran {
            Ok(ran) => Ok((out, ran)),
            Err(RunError::Spawn(e)) => Err(e),
            Err(RunError::Case(never)) => match never {},
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every thread count gives the same results in index order; the workers carry the
    /// runner's name.
    #[test]
    fn results_come_in_index_order_on_any_number_of_threads() {
        let case = |i: u64| {
            // Later cases finish first.
            std::thread::sleep(std::time::Duration::from_micros(50 * (20 - i % 20)));
            (i, std::thread::current().name().unwrap_or("").to_string())
        };
        for threads in [0, 1, 2, 7] {
            let runner = Runner {
                threads,
                name: "test-runner",
                ..Runner::default()
            };
            let (out, ran) = runner.collect(60, &|| false, &case).unwrap();
            assert_eq!(
                ran,
                Ran {
                    cases: 60,
                    stopped: false
                }
            );
            assert_eq!(out.iter().map(|r| r.0).collect::<Vec<_>>(), (0..60).collect::<Vec<_>>());
            assert!(out.iter().all(|r| r.1.starts_with("test-runner-")), "{out:?}");
        }
        let (none, ran) = Runner::default().collect(0, &|| true, &|i| i).unwrap();
        assert!(none.is_empty());
        assert_eq!(
            ran,
            Ran {
                cases: 0,
                stopped: false
            }
        );
    }

    /// A stop before the start runs nothing; a callback error ends the run with it, after
    /// the cases before it were handed on.
    #[test]
    fn stop_and_errors_end_the_run() {
        let runner = Runner {
            threads: 3,
            ..Runner::default()
        };
        let (out, ran) = runner.collect(50, &|| true, &|i| i).unwrap();
        assert!(out.is_empty());
        assert_eq!(
            ran,
            Ran {
                cases: 0,
                stopped: true
            }
        );

        let mut seen = Vec::new();
        let e = runner.run(50, &|| false, &|i| i, &mut |i, _| {
            if i == 5 {
                return Err(format!("case {i}"));
            }
            seen.push(i);
            Ok(())
        });
        assert!(matches!(e, Err(RunError::Case(ref m)) if m == "case 5"), "{e:?}");
        assert_eq!(seen, [0, 1, 2, 3, 4]);
    }
}
