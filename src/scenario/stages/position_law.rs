//! Stage 3: the position law, built on the controller's model (the description's or an
//! identified one) with its gains.

use super::super::controllers::GainReport;
use super::super::error::ScenarioError;
use super::super::spec::Scenario;
use crate::control::Controller;
use crate::model::RobotModel;

/// Stage 3: the scenario's position law on `model`, and its gains.
///
/// # Errors
///
/// [`ScenarioError`] on `position.law` if the gain design fails or a setting does not fit
/// the robot.
pub fn position_law<const N: usize, M: RobotModel<N> + Copy + 'static>(
    scenario: &Scenario,
    model: M,
) -> Result<(Box<dyn Controller<N>>, GainReport), ScenarioError> {
    scenario
        .position
        .build_with(model, &scenario.position_settings)
        .map_err(|e| scenario.error("position.law", e))
}
