//! Running a sweep's trials in parallel (rayon) in a pool of a chosen size; results in trial
//! order whatever ran them.

use std::time::Instant;

use rayon::prelude::*;

use super::draw::{apply, draw_all, Draw};
use super::spec::SweepSpec;
use super::trial::{run_trial, TrialResult};
use crate::scenario::Scenario;

/// A finished sweep.
#[derive(Clone, Debug)]
pub struct SweepRun {
    /// Each trial's draws.
    pub draws: Vec<Draw>,
    /// Each trial's result, in the same order.
    pub results: Vec<TrialResult>,
    /// Wall-clock time of the trials, s.
    pub elapsed_s: f64,
    /// Threads used.
    pub threads: usize,
}

impl SweepRun {
    /// Trials per second of wall-clock time.
    #[must_use]
    pub fn trials_per_s(&self) -> f64 {
        self.results.len() as f64 / self.elapsed_s
    }
}

/// Runs the trials of `draws` (any part of a sweep's draws: a trial's result depends on its
/// draw alone) in parallel on the current rayon pool, in their order; `done` is called after
/// each trial.
pub fn run_trials(
    base: &Scenario,
    spec: &SweepSpec,
    draws: &[Draw],
    done: &(dyn Fn() + Sync),
) -> Vec<TrialResult> {
    draws
        .par_iter()
        .map(|d| {
            let r = match apply(base, spec, d) {
                Ok(s) => run_trial(&s, spec.max_position_error_mm),
                Err(e) => super::trial::setup_failure(e),
            };
            done();
            r
        })
        .collect()
}

/// Runs `samples` trials of `base` with draws from `spec` seeded by `seed` on `threads`
/// threads (0: rayon's default, one per core); `done` is called after each trial.
///
/// # Errors
///
/// If the thread pool cannot be built.
pub fn run_sweep(
    base: &Scenario,
    spec: &SweepSpec,
    samples: usize,
    seed: u64,
    threads: usize,
    done: &(dyn Fn() + Sync),
) -> Result<SweepRun, rayon::ThreadPoolBuildError> {
    let draws = draw_all(spec, samples, seed);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()?;
    let start = Instant::now();
    let results = pool.install(|| run_trials(base, spec, &draws, done));
    Ok(SweepRun {
        draws,
        results,
        elapsed_s: start.elapsed().as_secs_f64(),
        threads: pool.current_num_threads(),
    })
}
