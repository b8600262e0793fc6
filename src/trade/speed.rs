//! Round-robin timing in one process: every contender of a workload runs once per
//! repetition, in turn, so that a slow moment of the machine hits all of them alike. A
//! pass repeats the contender's work until it lasts a minimum time (calibrated once, on
//! a warm-up pass), and its speed is the work per second.

use std::time::Instant;

use crate::convention::Target;
use crate::coverage::CountBuffer;
use crate::model::{prepare, Model, Primitives};

use super::report::{SpeedEntry, SpeedOutcome};

/// One contender's job: does the work once and returns something the optimiser must
/// not drop (a covered-pixel total).
pub(crate) type Job<'a> = Box<dyn FnMut() -> u64 + 'a>;

/// The seconds of one run of each job, `repetitions` times, round-robin: the result's
/// `[k][r]` is job `k`'s time per run in repetition `r`.
pub(crate) fn round_robin(jobs: &mut [Job<'_>], repetitions: usize, min_pass_seconds: f64) -> Vec<Vec<f64>> {
    // Warm-up and calibration: one run each.
    let runs: Vec<u32> = jobs
        .iter_mut()
        .map(|job| {
            let t = timed(job, 1);
            runs_for(t, min_pass_seconds)
        })
        .collect();
    let mut out = vec![Vec::with_capacity(repetitions); jobs.len()];
    for _ in 0..repetitions {
        for (k, job) in jobs.iter_mut().enumerate() {
            out[k].push(timed(job, runs[k]) / f64::from(runs[k]));
        }
    }
    out
}

/// How many runs make a pass of at least `min` seconds when one run takes `one`.
fn runs_for(one: f64, min: f64) -> u32 {
    if one <= 0.0 {
        return 1000;
    }
    let n = (min / one).ceil().clamp(1.0, 1e6);
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)] // clamped to 1..=1e6
    let n = n as u32;
    n
}

/// Seconds for `n` runs of `job`.
fn timed(job: &mut Job<'_>, n: u32) -> f64 {
    let start = Instant::now();
    let mut sink = 0u64;
    for _ in 0..n {
        sink = sink.wrapping_add(job());
    }
    std::hint::black_box(sink);
    start.elapsed().as_secs_f64()
}

/// One contender to time: its draw (the headline speed) and, where it has one, its
/// prepare-and-draw from the exact scene; or why it cannot run.
pub(crate) struct Contender<'a> {
    /// Its name.
    pub(crate) name: String,
    /// Exact or integer.
    pub(crate) exact: bool,
    /// What its errors are counted against.
    pub(crate) reference: &'static str,
    /// The work of one run.
    pub(crate) elements: u64,
    /// Timed on the plain-oracle subset.
    pub(crate) subset: bool,
    /// `(draw, prepare and draw)`, or the model's refusal.
    pub(crate) jobs: Result<(Job<'a>, Option<Job<'a>>), String>,
}

/// A model's two jobs on `prims`: draw the prepared scene, and prepare and draw it, both
/// into a [`CountBuffer`] kept between runs; or the model's refusal.
pub(crate) fn model_jobs<'a>(
    model: Model,
    prims: &'a Primitives,
    target: &'a Target,
) -> Result<(Job<'a>, Option<Job<'a>>), String> {
    let prepared = prepare(prims, target, model).map_err(|e| e.to_string())?;
    let mut sink = CountBuffer::new(target.width, target.height);
    let mut sink2 = CountBuffer::new(target.width, target.height);
    let draw: Job<'a> = Box::new(move || {
        prepared.render(target, &mut sink);
        std::hint::black_box(&sink);
        0
    });
    let full: Job<'a> = Box::new(move || {
        let p = prepare(prims, target, model).expect("prepared once already");
        p.render(target, &mut sink2);
        std::hint::black_box(&sink2);
        0
    });
    Ok((draw, Some(full)))
}

/// Whether `model` takes `prims` (placed at a magnitude): its own preparation's verdict,
/// or nothing to check for the exact models, whose envelope is unbounded.
pub(crate) fn refusal(model: Model, prims: &Primitives, target: &Target) -> Result<(), String> {
    if model.is_unbounded() {
        return Ok(());
    }
    prepare(prims, target, model).map(|_| ()).map_err(|e| e.to_string())
}

/// Times every contender round-robin and reports its speeds.
pub(crate) fn entries(contenders: Vec<Contender<'_>>, repetitions: usize, min_pass_seconds: f64) -> Vec<SpeedEntry> {
    let mut jobs: Vec<Job<'_>> = Vec::new();
    // Per contender: the indices of its jobs in `jobs`.
    let mut at: Vec<Option<(usize, Option<usize>)>> = Vec::new();
    let mut rest = Vec::new();
    for c in contenders {
        match c.jobs {
            Err(reason) => {
                at.push(None);
                rest.push((c.name, c.exact, c.reference, c.elements, c.subset, Some(reason)));
            }
            Ok((draw, full)) => {
                let d = jobs.len();
                jobs.push(draw);
                let f = full.map(|f| {
                    jobs.push(f);
                    d + 1
                });
                at.push(Some((d, f)));
                rest.push((c.name, c.exact, c.reference, c.elements, c.subset, None));
            }
        }
    }
    let seconds = round_robin(&mut jobs, repetitions, min_pass_seconds);
    drop(jobs);
    rest.into_iter()
        .zip(at)
        .map(|((name, exact, reference, elements, subset, refused), at)| {
            let outcome = match (at, refused) {
                (Some((d, f)), _) => {
                    let (median, min, max) = speeds(elements, &seconds[d]);
                    SpeedOutcome::Measured {
                        median,
                        min,
                        max,
                        with_prepare: f.map(|f| speeds(elements, &seconds[f]).0),
                        elements,
                        subset,
                    }
                }
                (None, reason) => SpeedOutcome::Refused(reason.unwrap_or_default()),
            };
            SpeedEntry {
                contender: name,
                exact,
                reference,
                outcome,
            }
        })
        .collect()
}

/// Median, slowest and fastest speed in millions of `elements` per second, from the
/// seconds per run of each repetition.
pub(crate) fn speeds(elements: u64, seconds: &[f64]) -> (f64, f64, f64) {
    #[allow(clippy::cast_precision_loss)] // work counts far below 2^53
    let work = elements as f64 / 1e6;
    let mut v: Vec<f64> = seconds.iter().map(|&t| if t > 0.0 { work / t } else { 0.0 }).collect();
    let (median, max) = super::measure::median_max(&mut v);
    let min = v.first().copied().unwrap_or(0.0);
    (median, min, max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_job_runs_every_repetition() {
        let (mut a, mut b) = (0u64, 0u64);
        {
            let mut jobs: Vec<Job<'_>> = vec![
                Box::new(|| {
                    a += 1;
                    a
                }),
                Box::new(|| {
                    b += 1;
                    b
                }),
            ];
            let t = round_robin(&mut jobs, 3, 0.0);
            assert_eq!(t.len(), 2);
            assert!(t.iter().all(|r| r.len() == 3));
        }
        assert_eq!((a, b), (4, 4), "a warm-up run, then one run per repetition");
        let (median, min, max) = speeds(2_000_000, &[1.0, 2.0, 0.5]);
        assert_eq!((median, min, max), (2.0, 1.0, 4.0));
    }
}
