//! Every thread the library starts to map a known set of items, the results in input
//! order (the answer is the one a single thread gives, error included: the error of the
//! lowest index is the one returned). Two mechanisms, each for what it is good at:
//!
//! - **rayon's pool** ([`map`], [`try_map`], [`defaults`]): a slice cut into at most
//!   `jobs` runs of consecutive items, each run written in place into one output vector;
//!   for many cheap items of even cost (reading and preparing a scene's triangles), where
//!   collecting each thread's part and copying it would cost what the threads save.
//! - **threads of its own** ([`map_each`], [`map_each_with`]): items handed out in turn to
//!   up to `jobs` scoped threads, each taking the next as soon as it is done; for a few
//!   items of uneven cost, items that block (a renderer's process), or threads that carry
//!   state from one item to the next (a band's spare tiles). No pool thread is held
//!   blocked, and no item waits behind a run cut in advance.
//!
//! The other threads of the crate: `harness::runner` (feature `proptest`), the one case
//! runner of the suite and the hunt, a stream of cases up to `2^64` with a stop condition,
//! each result consumed in case order as it arrives, on named threads with a stack of
//! their own; and the one reader thread per renderer process kept alive
//! (`oracle::renderer::stay_alive`), which waits on the process's output.

use std::sync::{Mutex, PoisonError};

use rayon::prelude::*;

/// `f(k, &items[k])` for every `k`, on up to `jobs` threads (rayon's pool, the items cut
/// into at most `jobs` runs of consecutive ones), written in place into one vector in
/// input order. `jobs` of 0 or 1, or fewer than two items, runs on the calling thread and
/// stops at the first error; on several threads every item is tried, and the error of the
/// lowest index wins (refused items hold `U::default()` meanwhile, never returned).
///
/// # Errors
/// The error of the first item (in input order) that `f` refuses.
///
/// ```
/// use rasterproof::chunks::try_map;
/// let halves = try_map(&[2, 4, 6, 8], 2, |_, &n| if n % 2 == 0 { Ok(n / 2) } else { Err(n) });
/// assert_eq!(halves, Ok(vec![1, 2, 3, 4]));
/// let first = try_map(&[2, 3, 4, 5], 2, |k, &n| if n % 2 == 0 { Ok(n) } else { Err(k) });
/// assert_eq!(first, Err(1));
/// ```
pub fn try_map<T, U, E, F>(items: &[T], jobs: usize, f: F) -> Result<Vec<U>, E>
where
    T: Sync,
    U: Send + Default,
    E: Send,
    F: Fn(usize, &T) -> Result<U, E> + Sync,
{
    if jobs <= 1 || items.len() < 2 {
        return items.iter().enumerate().map(|(k, item)| f(k, item)).collect();
    }
    let first_error: Mutex<Option<(usize, E)>> = Mutex::new(None);
    let out = in_order(items, jobs, |k, item| match f(k, item) {
        Ok(u) => u,
        Err(e) => {
            let mut first = first_error.lock().unwrap_or_else(PoisonError::into_inner);
            if first.as_ref().is_none_or(|&(j, _)| j >= k) {
                *first = Some((k, e));
            }
            U::default()
        }
    });
    match first_error.into_inner().unwrap_or_else(PoisonError::into_inner) {
        Some((_, e)) => Err(e),
        None => Ok(out),
    }
}

/// [`try_map`] for an `f` that cannot fail.
///
/// ```
/// use rasterproof::chunks::map;
/// assert_eq!(map(&[1, 2, 3], 4, |k, &n| n * 10 + k), vec![10, 21, 32]);
/// ```
pub fn map<T, U, F>(items: &[T], jobs: usize, f: F) -> Vec<U>
where
    T: Sync,
    U: Send,
    F: Fn(usize, &T) -> U + Sync,
{
    if jobs <= 1 || items.len() < 2 {
        return items.iter().enumerate().map(|(k, item)| f(k, item)).collect();
    }
    in_order(items, jobs, f)
}

/// `f(item)` for every item of `items`, taken by value, on up to `jobs` threads of its
/// own, each thread taking the next item as soon as it is done with its last: for a few
/// items of uneven cost, or threads of uneven speed (a busy core, a noisy neighbour),
/// where runs cut in advance would leave one thread waiting for the other. The results
/// in input order; `jobs` of 0 or 1, or fewer than two items, runs on the calling thread.
/// A panic in `f` is raised again on the calling thread.
///
/// ```
/// use rasterproof::chunks::map_each;
/// let lengths = map_each(vec!["a", "bb", "ccc"], 2, str::len);
/// assert_eq!(lengths, [1, 2, 3]);
/// ```
pub fn map_each<T: Send, U: Send>(items: Vec<T>, jobs: usize, f: impl Fn(T) -> U + Sync) -> Vec<U> {
    map_each_with(items, jobs, || (), |(), item| f(item))
}

/// [`map_each`] with a state of each thread's own, made by `state` when the thread starts
/// and handed to `f` with each item it takes: what a thread carries from one item to the
/// next (the tiles of its last band, to draw the next into).
///
/// ```
/// use rasterproof::chunks::map_each_with;
/// // Each thread counts the items it has taken; every item is counted by one thread.
/// let counts = map_each_with(vec![10, 20, 30], 2, || 0, |seen: &mut u32, n| { *seen += 1; (n, *seen) });
/// assert_eq!(counts.iter().map(|&(n, _)| n).collect::<Vec<_>>(), [10, 20, 30]);
/// assert!(counts.iter().all(|&(_, seen)| (1..=3).contains(&seen)));
/// ```
pub fn map_each_with<T: Send, U: Send, S>(
    items: Vec<T>,
    jobs: usize,
    state: impl Fn() -> S + Sync,
    f: impl Fn(&mut S, T) -> U + Sync,
) -> Vec<U> {
    if jobs <= 1 || items.len() < 2 {
        let mut mine = state();
        return items.into_iter().map(|item| f(&mut mine, item)).collect();
    }
    let threads = jobs.min(items.len());
    let next = Mutex::new(items.into_iter().enumerate());
    let mut done: Vec<(usize, U)> = std::thread::scope(|s| {
        let workers: Vec<_> = (0..threads)
            .map(|_| {
                s.spawn(|| {
                    let mut own = state();
                    let mut mine = Vec::new();
                    loop {
                        let item = next.lock().unwrap_or_else(PoisonError::into_inner).next();
                        let Some((k, item)) = item else {
                            return mine;
                        };
                        mine.push((k, f(&mut own, item)));
                    }
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic)))
            .collect()
    });
    done.sort_unstable_by_key(|&(k, _)| k);
    done.into_iter().map(|(_, u)| u).collect()
}

/// `count` default values, made on up to `jobs` threads of rayon's pool in runs written in
/// place (the fresh memory a big vector touches is most of its cost): the places a reader
/// on several threads then fills.
///
/// ```
/// let zeros: Vec<u64> = rasterproof::chunks::defaults(5, 2);
/// assert_eq!(zeros, [0; 5]);
/// ```
pub fn defaults<U: Send + Default>(count: usize, jobs: usize) -> Vec<U> {
    let mut out = Vec::with_capacity(count);
    (0..count)
        .into_par_iter()
        .with_min_len(count.div_ceil(jobs.max(1)).max(1))
        .map(|_| U::default())
        .collect_into_vec(&mut out);
    out
}

/// `f` over `items` on rayon's pool in at most `jobs` runs, each writing its part of the
/// one output vector (no part is copied afterwards: for a big scene the copy, and the
/// fresh memory it touches, would cost what the threads save).
fn in_order<T: Sync, U: Send>(items: &[T], jobs: usize, f: impl Fn(usize, &T) -> U + Sync) -> Vec<U> {
    let run = items.len().div_ceil(jobs.max(1));
    let mut out = Vec::with_capacity(items.len());
    items
        .par_iter()
        .enumerate()
        .with_min_len(run)
        .map(|(k, item)| f(k, item))
        .collect_into_vec(&mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every length around every thread count: the same as one thread, and the first error
    /// in input order whichever chunk it falls in.
    #[test]
    fn chunks_give_one_threads_answer() {
        for len in 0..40usize {
            let items: Vec<usize> = (0..len).map(|k| k * 7 % 11).collect();
            let plain: Vec<usize> = items.iter().enumerate().map(|(k, n)| k * 100 + n).collect();
            for jobs in 0..9 {
                assert_eq!(map(&items, jobs, |k, &n| k * 100 + n), plain, "len {len}, jobs {jobs}");
                // Items equal to `bad` fail (at a place that moves with the length, in the
                // first chunk, a later one or none); the first such index is the error.
                let bad = len % 13;
                let first = items.iter().position(|&n| n == bad);
                let got = try_map(&items, jobs, |k, &n| if n == bad { Err(k) } else { Ok(n) });
                match first {
                    Some(k) => assert_eq!(got, Err(k), "len {len}, jobs {jobs}"),
                    None => assert_eq!(got, Ok(items.clone()), "len {len}, jobs {jobs}"),
                }
            }
        }
    }

    #[test]
    fn items_taken_in_turn_come_back_in_order() {
        for len in 0..40usize {
            let items: Vec<usize> = (0..len).map(|k| k * 7 % 11).collect();
            let plain: Vec<usize> = items.iter().map(|n| n * 3 + 1).collect();
            for jobs in 0..9 {
                // Uneven costs, so the threads finish out of order.
                let got = map_each(items.clone(), jobs, |n| {
                    std::thread::sleep(std::time::Duration::from_micros((n as u64 % 3) * 50));
                    n * 3 + 1
                });
                assert_eq!(got, plain, "len {len}, jobs {jobs}");
            }
        }
    }

    #[test]
    fn items_taken_in_turn_use_at_most_jobs_threads() {
        let here = std::thread::current().id();
        let ids = map_each(vec![(); 64], 1, |()| std::thread::current().id());
        assert!(ids.iter().all(|&i| i == here));
        for jobs in [2, 3] {
            let ids = map_each(vec![(); 64], jobs, |()| {
                std::thread::sleep(std::time::Duration::from_micros(200));
                std::thread::current().id()
            });
            let mut distinct = ids.clone();
            distinct.sort_by_key(|i| format!("{i:?}"));
            distinct.dedup();
            assert!(
                distinct.len() <= jobs && !distinct.contains(&here),
                "{jobs} jobs: {distinct:?}"
            );
        }
    }

    #[test]
    fn one_item_runs_here_and_two_on_the_threads() {
        let here = std::thread::current().id();
        assert_eq!(map_each(vec![()], 2, |()| std::thread::current().id()), [here]);
        let ids = map_each(vec![(), ()], 2, |()| std::thread::current().id());
        assert!(ids.iter().all(|&i| i != here), "{ids:?}");
    }

    #[test]
    #[should_panic(expected = "item 5")]
    fn a_panic_in_an_item_reaches_the_caller() {
        map_each((0..10).collect(), 2, |k| assert!(k != 5, "item {k}"));
    }

    /// One job runs on the calling thread; two cut the items into two runs of consecutive
    /// items, no more.
    #[test]
    fn jobs_bound_the_runs() {
        let here = std::thread::current().id();
        assert!(map(&[0u8; 64], 1, |_, _| std::thread::current().id())
            .iter()
            .all(|&i| i == here));
        let ids = map(&[0u8; 64], 2, |_, _| std::thread::current().id());
        assert!(ids[..32].iter().all(|&i| i == ids[0]));
        assert!(ids[32..].iter().all(|&i| i == ids[32]));
    }
}
