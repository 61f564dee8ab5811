//! A scenario run with its hybrid controller as the robot's deployable step (the SCARA's
//! `ScaraHybrid`) in `f32` or `f64`: the controller a microcontroller would run, rounding
//! included, against the usual `f64` plant, to see before deployment what single precision
//! changes. The supervisor, unless `[safety] enabled = false`, is the step's own
//! ([`SupervisedHybrid`](crate::robots::scara::deploy::SupervisedHybrid) for the SCARA), in
//! the same precision.

use super::error::ScenarioError;
use super::prepare::{prepare_stages, Prepared, PreparedRun};
use super::robot::{Precision, ScenarioRobot};
use super::spec::Scenario;

/// [`super::prepare`], with the controller replaced by the robot's deployable step in
/// `precision` (behind the scenario's force sensor, if any), its gains those the
/// preparation chose (given or designed).
///
/// # Errors
///
/// [`ScenarioError`] naming the first key the deployable step cannot follow, a robot
/// without one, or any error of [`super::prepare`].
pub fn prepare_deployed(
    scenario: &Scenario,
    precision: Precision,
) -> Result<Prepared, ScenarioError> {
    crate::with_robot_named!(scenario.robot.as_str(), |robot: R, N, _module| {
        prepare_deployed_for(scenario, robot, precision).map(Prepared::from)
    })
    .unwrap_or_else(|| Err(scenario.error("robot", "unknown robot")))
}

/// [`prepare_deployed`] on `robot` (the one the scenario names), typed: its
/// [`PreparedRun::execute`] keeps the samples.
///
/// # Errors
///
/// As [`prepare_deployed`].
pub fn prepare_deployed_for<const N: usize, R: ScenarioRobot<N>>(
    scenario: &Scenario,
    robot: R,
    precision: Precision,
) -> Result<PreparedRun<N, R>, ScenarioError> {
    prepare_stages(scenario, robot, Some(precision))
}
