//! From a checked [`Scenario`] to a run ready to go: the stages of [`super::stages`] in
//! order, for the scenario's robot.
//!
//! [`prepare_for`] is the typed entry, for code that knows its robot; [`prepare`] finds the
//! scenario's robot by name ([`with_robot_named!`](crate::with_robot_named)) and gives a
//! [`Prepared`] of any robot.

use super::controllers::GainReport;
use super::desired_force::DesiredForce;
use super::error::ScenarioError;
use super::outcome::Outcome;
use super::planned::PlannedReference;
use super::plant::ControllerModel;
use super::robot::{Precision, ScenarioRobot};
use super::spec::Scenario;
use super::stages::{faults, force_law, plant, position_law, reference, safety, sensor};
use crate::contact::Scene;
use crate::control::Controller;
use crate::model::{Parametric, ParametricModel, WithArmature};
use crate::sim::faults::FaultyEnvironment;
use crate::sim::SimConfig;
use crate::sim::SimError;

/// A run of robot `R` ready to go.
pub struct PreparedRun<const N: usize, R: ScenarioRobot<N>> {
    /// The robot.
    pub robot: R,
    /// The controller (with its sensor, if any).
    pub controller: Box<dyn Controller<N>>,
    /// Its gains.
    pub gains: GainReport,
    /// The planned reference (the run's joint setpoints).
    pub reference: Box<dyn PlannedReference<N>>,
    /// The desired force.
    pub force: Option<DesiredForce>,
    /// The real surfaces.
    pub scene: Scene,
    /// The real surfaces with the scenario's faults of the environment (an edge, a stiffness
    /// step, a payload): what the run touches.
    pub environment: FaultyEnvironment,
    /// The plant's timing, initial state, limits, end stops and friction.
    pub config: SimConfig<N>,
    /// The plant's own rigid body (`None`: the description's).
    pub plant: Option<Parametric<N, R>>,
}

/// What the controller stages give: the controller, its gains, the desired force.
type ControllerStages<const N: usize> = (Box<dyn Controller<N>>, GainReport, Option<DesiredForce>);

/// The controller stages (position law, force law) on the controller's model `model`.
fn controller_on<
    const N: usize,
    R: ScenarioRobot<N>,
    M: crate::model::RobotModel<N> + Copy + 'static,
>(
    scenario: &Scenario,
    robot: &R,
    model: M,
    reference: &reference::ReferenceStage<N>,
) -> Result<ControllerStages<N>, ScenarioError> {
    let (position, mut gains) = position_law::position_law(scenario, model)?;
    let (controller, force) =
        force_law::force_law(scenario, robot, model, reference, position, &mut gains)?;
    Ok((controller, gains, force))
}

/// Builds everything a run of `scenario` on `robot` needs, stage by stage, and checks what
/// needs it (the reference against the workspace, the force surface against the
/// reference). `robot` is the one the scenario names (its `robot` key).
///
/// # Errors
///
/// [`ScenarioError`] naming the key at fault (`robot` if the scenario is of another robot).
pub fn prepare_for<const N: usize, R: ScenarioRobot<N>>(
    scenario: &Scenario,
    robot: R,
) -> Result<PreparedRun<N, R>, ScenarioError> {
    prepare_stages(scenario, robot, None)
}

/// The stages of [`prepare_for`] in order, with the laws' controller replaced by the robot's
/// deployable step in `deployed` precision (see [`super::prepare_deployed`]) where given.
pub(super) fn prepare_stages<const N: usize, R: ScenarioRobot<N>>(
    scenario: &Scenario,
    robot: R,
    deployed: Option<Precision>,
) -> Result<PreparedRun<N, R>, ScenarioError> {
    if scenario.robot != R::NAME {
        return Err(scenario.error(
            "robot",
            format!(
                "the scenario is of robot `{}`; it was given `{}`",
                scenario.robot,
                R::NAME
            ),
        ));
    }
    let reference = reference::reference(scenario, &robot)?;
    let plant = plant::plant(scenario, &robot, &reference)?;
    let armature = scenario
        .controller_armature
        .as_ref()
        .map(|a| crate::model::JointVector::<N>::from_fn(|i, _| a[i]));
    let (controller, mut gains, force) = match &scenario.controller_model {
        ControllerModel::Nominal => match armature {
            None => controller_on(scenario, &robot, robot, &reference)?,
            Some(a) => {
                let (c, mut g, f) =
                    controller_on(scenario, &robot, WithArmature::new(robot, a), &reference)?;
                g.note = format!("{}; controller model: armature {:?}", g.note, a.as_slice());
                (c, g, f)
            }
        },
        ControllerModel::Identified { parameters, .. } => {
            let p = <R as ParametricModel<N>>::parameters_from(parameters).ok_or_else(|| {
                scenario.error(
                    "controller_model",
                    format!(
                        "has {} parameters; robot `{}` has {}",
                        parameters.len(),
                        R::NAME,
                        10 * N
                    ),
                )
            })?;
            let model = Parametric::new(robot, p);
            let (c, mut g, f) = match armature {
                None => controller_on(scenario, &robot, model, &reference)?,
                Some(a) => {
                    controller_on(scenario, &robot, WithArmature::new(model, a), &reference)?
                }
            };
            g.note = format!(
                "{}; controller model: {}",
                g.note,
                scenario.controller_model.describe()
            );
            (c, g, f)
        }
    };
    let limits = safety::limits(
        scenario,
        &robot,
        reference.planned.as_ref(),
        reference.duration,
        &plant.config.q0,
        &plant.config.effort_limits,
    );
    // A deployed run: the step takes the laws' place (their gains, given or designed, are its
    // own) and runs inside its own supervisor, in its own precision.
    let controller = match deployed {
        None => controller,
        Some(precision) => {
            let safety = scenario.safety.enabled.then_some(&limits);
            R::deployed(scenario, precision, gains.force, safety)?
        }
    };
    let controller = sensor::tool_compensation(
        scenario,
        robot,
        reference.planned.as_ref(),
        reference.duration,
        controller,
    )?;
    let controller = match deployed {
        None => safety::supervise(scenario, robot, limits, controller)?,
        Some(_) => safety::with_sensor_faults(scenario, controller)?,
    };
    let controller = sensor::sensor(scenario, robot, controller, &mut gains)?;
    if let Some(precision) = deployed {
        gains.note = format!(
            "{}; run by the robot's deployable step in f{}",
            gains.note,
            match precision {
                Precision::F32 => 32,
                Precision::F64 => 64,
            }
        );
    }
    let mut config = plant.config;
    config.faults = faults::plant_faults(scenario);
    let environment = faults::environment(
        scenario,
        &plant.scene,
        reference.planned.as_ref(),
        R::GRAVITY,
    )?;
    Ok(PreparedRun {
        robot,
        controller,
        gains,
        reference: reference.planned,
        force,
        scene: plant.scene,
        environment,
        config,
        plant: plant.model,
    })
}

/// A prepared run of any robot, run by [`execute`](super::execute::execute).
#[allow(clippy::result_large_err)] // see `crate::sim`
pub(super) trait ErasedRun {
    fn execute(
        self: Box<Self>,
        scenario: &Scenario,
        progress: &mut dyn FnMut(f64),
    ) -> Result<Outcome, SimError>;
    fn controller_name(&self) -> &'static str;
    fn linearize(
        self: Box<Self>,
        at_s: f64,
        at_equilibrium: bool,
    ) -> Result<crate::sim::linearize::Linearization, crate::sim::linearize::LinearizeError>;
}

/// A run of any robot ready to go ([`prepare`]).
pub struct Prepared {
    pub(super) run: Box<dyn ErasedRun>,
    /// Its gains.
    pub gains: GainReport,
    /// The real surfaces.
    pub scene: Scene,
    /// Length of the run, s.
    pub duration: f64,
}

impl Prepared {
    /// The controller's name.
    #[must_use]
    pub fn controller_name(&self) -> &'static str {
        self.run.controller_name()
    }
}

impl<const N: usize, R: ScenarioRobot<N>> From<PreparedRun<N, R>> for Prepared {
    fn from(p: PreparedRun<N, R>) -> Self {
        Self {
            gains: p.gains.clone(),
            scene: p.scene,
            duration: p.config.duration,
            run: Box::new(p),
        }
    }
}

/// Builds everything a run of `scenario` needs, for its robot (see [`prepare_for`]).
///
/// # Errors
///
/// [`ScenarioError`] naming the key at fault.
pub fn prepare(scenario: &Scenario) -> Result<Prepared, ScenarioError> {
    crate::with_robot_named!(scenario.robot.as_str(), |robot: R, N, _module| {
        prepare_for(scenario, robot).map(Prepared::from)
    })
    .unwrap_or_else(|| Err(scenario.error("robot", format!("unknown robot `{}`", scenario.robot))))
}

/// Length of a scenario's run, s, known without planning the reference: its `duration_s`,
/// or else its reference's. A planned manoeuvre (a SCARA's elbow flip) lengthens a run
/// without `duration_s` by its pauses; [`prepare`]'s `duration` is the exact length.
#[must_use]
pub fn run_duration(scenario: &Scenario) -> f64 {
    scenario.duration_s.unwrap_or_else(|| {
        crate::with_robot_named!(scenario.robot.as_str(), |_robot: R, N, _module| {
            reference::reference_duration::<N, R>(scenario).unwrap_or(0.0)
        })
        .unwrap_or(0.0)
    })
}
