//! A scenario's closed loop linearised at a time of its run ([`crate::sim::linearize`]).

use super::prepare::{prepare, PreparedRun};
use super::robot::ScenarioRobot;
use super::spec::Scenario;
use super::ScenarioError;
use crate::sim::linearize::{linearize_closed_loop, Linearization, LinearizeAt, LinearizeError};

/// Why a scenario could not be linearised.
#[derive(Debug, thiserror::Error)]
pub enum ScenarioLinearizeError {
    /// The scenario is invalid.
    #[error(transparent)]
    Scenario(#[from] ScenarioError),
    /// The loop could not be linearised.
    #[error(transparent)]
    Linearize(#[from] LinearizeError),
}

/// The scenario as it is linearised: the sensor without noise (noise is a disturbance, not
/// dynamics, and a step whose output is random has no Jacobian) and without injected faults
/// (the linearisation is of the nominal loop). Everything else is the file's.
#[must_use]
pub fn nominal(scenario: &Scenario) -> Scenario {
    let mut s = scenario.clone();
    s.sensor.noise_n = 0.0;
    s.faults.clear();
    s
}

/// Linearises `scenario`'s closed loop at the first control sample at or after `at_s`
/// (of the run of [`nominal`]`(scenario)`).
///
/// # Errors
///
/// [`ScenarioLinearizeError`]: the scenario is invalid, the time is outside the run, the
/// plant differs from the description (`[plant]` parameters: the generated derivatives are
/// the description's), or a controller stage hides state.
#[allow(clippy::result_large_err)] // see `crate::sim`
pub fn linearize(scenario: &Scenario, at_s: f64) -> Result<Linearization, ScenarioLinearizeError> {
    let prepared = prepare(&nominal(scenario))?;
    Ok(prepared.run.linearize(at_s, false)?)
}

/// Linearises `scenario`'s closed loop at its equilibrium nearest the state of the first
/// control sample at or after `at_s` (of the run of [`nominal`]`(scenario)`), the reference
/// held there ([`crate::sim::linearize::LinearizeAt::Equilibrium`]): the point the run would
/// come to rest at, which a run that oscillates or slides never samples.
///
/// # Errors
///
/// As [`linearize`], and when the reference moves at `at_s` or no equilibrium is found.
#[allow(clippy::result_large_err)] // see `crate::sim`
pub fn linearize_equilibrium(
    scenario: &Scenario,
    at_s: f64,
) -> Result<Linearization, ScenarioLinearizeError> {
    let prepared = prepare(&nominal(scenario))?;
    Ok(prepared.run.linearize(at_s, true)?)
}

impl<const N: usize, R: ScenarioRobot<N>> PreparedRun<N, R> {
    /// The closed loop linearised at `at_s` (see [`linearize`]), or at its equilibrium nearest
    /// the run's state there (see [`linearize_equilibrium`]).
    ///
    /// # Errors
    ///
    /// As [`linearize`] and [`linearize_equilibrium`].
    #[allow(clippy::result_large_err)] // see `crate::sim`
    pub fn linearize(
        mut self,
        at_s: f64,
        at_equilibrium: bool,
    ) -> Result<Linearization, LinearizeError> {
        if self.plant.is_some() {
            return Err(LinearizeError::Unsupported(
                "the plant's parameters differ from the description's ([plant]): the generated \
                 derivatives are the description's, so this loop cannot be linearised by them; \
                 remove the [plant] parameters to linearise the nominal loop"
                    .into(),
            ));
        }
        let mut reference = super::execute::RunReference {
            planned: self.reference.as_mut(),
            force: self.force.as_ref(),
        };
        linearize_closed_loop(
            &self.robot,
            self.controller.as_mut(),
            &mut reference,
            &self.environment,
            &self.config,
            at_s,
            if at_equilibrium {
                LinearizeAt::Equilibrium
            } else {
                LinearizeAt::Sample
            },
        )
    }
}
