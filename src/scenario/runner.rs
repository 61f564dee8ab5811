//! Runs a closed loop and keeps every sample.

use crate::contact::Environment;
use crate::control::Controller;
use crate::model::RobotModel;
use crate::sim::{simulate, ReferenceSource, RunStats, Sample, SimConfig, SimError};

/// Every control sample of a run and its summary.
#[derive(Clone, Debug)]
pub struct RunOutput<const N: usize> {
    /// One entry per control sample.
    pub samples: Vec<Sample<N>>,
    /// Saturation and joint-limit counts.
    pub stats: RunStats<N>,
}

#[allow(clippy::result_large_err)] // see `crate::sim`
/// Simulates `controller` on `robot` following `reference` in `environment`; `progress` is
/// called with the simulated time about every 0.5 s.
///
/// # Errors
///
/// [`SimError`] from the simulator (bad settings, non-finite state).
pub fn run<const N: usize, R: RobotModel<N>>(
    robot: &R,
    controller: &mut dyn Controller<N>,
    reference: &mut dyn ReferenceSource<N>,
    environment: &dyn Environment,
    config: &SimConfig<N>,
    mut progress: impl FnMut(f64),
) -> Result<RunOutput<N>, SimError> {
    let expected = ((config.duration / config.control_dt).round() as usize).saturating_add(1);
    let mut samples = Vec::new();
    // Every sample is kept (hundreds of bytes each): refuse a run that cannot fit in memory
    // instead of aborting on a failed allocation.
    samples.try_reserve_exact(expected).map_err(|_| {
        SimError::Config("not enough memory to keep every control sample of this run")
    })?;
    let mut next_report = 0.5;
    let stats = simulate(robot, controller, reference, environment, config, |s| {
        if s.t >= next_report {
            progress(s.t);
            next_report += 0.5;
        }
        samples.push(*s);
    })?;
    Ok(RunOutput { samples, stats })
}
