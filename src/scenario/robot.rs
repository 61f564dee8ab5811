//! What a scenario needs of its robot beyond the model.
//!
//! [`ScenarioRobot`] has a default for everything: a Cartesian reference becomes joint
//! setpoints through the numerical inverse kinematics ([`super::ik_plan`]). A robot with
//! knowledge of its own implements it in its own module (the SCARA's closed form, elbow
//! planning, thesis references and deployable step: `crate::robots::scara::scenario`); every
//! other robot of the registry gets the defaults (`crate::robots` lists which robots have a
//! module). A scenario's robot is found by its name with
//! [`with_robot_named!`](crate::with_robot_named).

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
