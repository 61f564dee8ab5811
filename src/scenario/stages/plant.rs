//! Stage 2: the plant. Its rigid body (the description's, or `[plant]`'s parameters through
//! the generated parametric model), the run's timing and initial state, end stops, joint
//! friction and the real surfaces.

use super::super::error::ScenarioError;
use super::super::robot::ScenarioRobot;
use super::super::spec::Scenario;
use super::reference::ReferenceStage;
use crate::contact::Scene;
use crate::model::Parametric;
use crate::sim::{EndStops, SimConfig};

/// What the plant stage produced.
pub struct PlantStage<const N: usize, R: ScenarioRobot<N>> {
    /// Timing, initial state, limits, end stops and friction.
    pub config: SimConfig<N>,
    /// The plant's own rigid body (`None`: the description's, the generated functions).
    pub model: Option<Parametric<N, R>>,
    /// The real surfaces.
    pub scene: Scene,
}

/// Stage 2 (see the [module documentation](self)).
///
/// # Errors
///
/// [`ScenarioError`] on `surfaces` if there are more than the scene holds.
pub fn plant<const N: usize, R: ScenarioRobot<N>>(
    scenario: &Scenario,
    robot: &R,
    reference: &ReferenceStage<N>,
) -> Result<PlantStage<N, R>, ScenarioError> {
    let scene = Scene::new(&scenario.surfaces).map_err(|n| {
        scenario.error(
            "surfaces",
            format!("{n} surfaces; at most {}", crate::contact::MAX_SURFACES),
        )
    })?;
    let mut config = SimConfig::new(robot);
    config.duration = reference.duration;
    config.control_dt = scenario.control_dt_s;
    config.plant_dt = scenario.plant_dt_s;
    config.q0 = reference.q0;
    config.end_stops = scenario.end_stops.then(|| EndStops::from_model(robot));
    config.friction = scenario.plant.friction::<N>();
    Ok(PlantStage {
        config,
        model: scenario.plant.model(*robot),
        scene,
    })
}
