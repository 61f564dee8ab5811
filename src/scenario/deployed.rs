//! A scenario run with its hybrid controller as the robot's deployable step (the SCARA's
//! `ScaraHybrid`) in `f32` or `f64`: the controller a microcontroller would run, rounding
//! included, against the usual `f64` plant, to see before deployment what single precision
//! changes. The supervisor, unless `[safety] enabled = false`, is the step's own
//! ([`SupervisedHybrid`](crate::robots::scara::deploy::SupervisedHybrid) for the SCARA), in
//! the same precision.

use super::error::ScenarioError;
use super::prepare::{prepare_stages, Prepared};
use super::robot::{visit_robot, Precision, ScenarioRobot, ScenarioVisitor};
use super::spec::Scenario;

struct Deploy<'a>(&'a Scenario, Precision);

impl ScenarioVisitor for Deploy<'_> {
    type Output = Result<Prepared, ScenarioError>;
    fn visit<const N: usize, R: ScenarioRobot<N>>(self, robot: &R) -> Self::Output {
        let Deploy(scenario, precision) = self;
        let p = prepare_stages(scenario, *robot, Some(precision))?;
        Ok(Prepared {
            gains: p.gains.clone(),
            scene: p.scene,
            duration: p.config.duration,
            run: Box::new(p),
        })
    }
}

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
    visit_robot(&scenario.robot, Deploy(scenario, precision))
        .unwrap_or_else(|| Err(scenario.error("robot", "unknown robot")))
}
