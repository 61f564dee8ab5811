//! What a scenario needs of its robot beyond the model, and the dispatch from a robot's name
//! to the generic code that runs it.
//!
//! [`ScenarioRobot`] has a default for everything: a Cartesian reference becomes joint
//! setpoints through the numerical inverse kinematics ([`super::ik_plan`]). A robot with
//! knowledge of its own implements it in its own module (the SCARA's closed form, elbow
//! planning, thesis references and deployable step: `crate::robots::scara::scenario`); every
//! other robot of the registry gets the defaults (`crate::robots` lists which robots have a
//! module). [`visit_robot`] calls a [`ScenarioVisitor`] with the robot of a name.

use super::error::ScenarioError;
use super::planned::{PlannedReference, SharedTrajectory};
use super::spec::Scenario;
use super::vocabulary::RobotVocabulary;

/// The controller a deployable step is asked in (`armdyn run scenario --precision`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Precision {
    /// Single precision, as on a microcontroller whose FPU has no `f64`.
    F32,
    /// Double precision.
    F64,
}

/// A robot as a scenario runs it (see the [module documentation](self)).
pub trait ScenarioRobot<const N: usize>:
    RobotVocabulary<N> + crate::model::DynamicsDerivatives<N>
{
    /// The joint setpoints of `scenario`'s run along `trajectory`: by default the numerical
    /// inverse kinematics at every sample, warm-started, checked over the whole reference
    /// first ([`super::ik_plan::plan`]).
    ///
    /// # Errors
    ///
    /// [`ScenarioError`] naming the key at fault (a reference that leaves the workspace).
    fn plan(
        &self,
        scenario: &Scenario,
        trajectory: SharedTrajectory,
    ) -> Result<Box<dyn PlannedReference<N>>, ScenarioError> {
        super::ik_plan::plan(*self, scenario, trajectory)
    }

    /// The robot's deployable hybrid step in `precision` for `scenario`, with the PI gains
    /// `(Kfp, Kfi, Kvd)` chosen by the preparation (`None` for a law without them); `Err`
    /// naming the first key it cannot follow, or saying the robot has none.
    ///
    /// # Errors
    ///
    /// [`ScenarioError`] on `robot` by default: no deployable step.
    fn deployed(
        scenario: &Scenario,
        _precision: Precision,
        _gains: Option<(f64, f64, f64)>,
        _safety: Option<&crate::control::safety::SafetyLimits<f64, N>>,
    ) -> Result<Box<dyn crate::control::Controller<N>>, ScenarioError> {
        Err(scenario.error(
            "robot",
            format!(
                "robot `{}` has no deployable step (a controller in f32 for a microcontroller); run it with --precision reference",
                Self::NAME
            ),
        ))
    }
}

/// Generic code to run with the robot of a scenario (see [`visit_robot`]).
pub trait ScenarioVisitor {
    /// What the visit returns.
    type Output;
    /// Called with the robot's zero-sized model.
    fn visit<const N: usize, R: ScenarioRobot<N>>(self, robot: &R) -> Self::Output;
}

/// Calls `visitor` with the robot called `name`; `None` if there is no such robot.
pub fn visit_robot<V: ScenarioVisitor>(name: &str, visitor: V) -> Option<V::Output> {
    crate::with_robot_named!(name, |robot: R, N, _module| visitor.visit::<N, R>(&robot))
}
