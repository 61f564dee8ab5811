//! What a scenario needs of its robot beyond the model, and the dispatch from a robot's name
//! to the generic code that runs it.
//!
//! [`ScenarioRobot`] has a default for everything: a Cartesian reference becomes joint
//! setpoints through the numerical inverse kinematics ([`super::ik_plan`]). A robot with
//! knowledge of its own implements it in its own module (the SCARA's closed form, elbow
//! planning, thesis references and deployable step: `crate::robots::scara::scenario`); every
//! other robot of the registry gets the defaults here. [`visit_robot`] calls a
//! [`ScenarioVisitor`] with the robot of a name.

use crate::model::{JointVector, ParametricModel};
use crate::sim::{ReferenceSource, Sample};
use crate::trajectory::CartesianTrajectory;

use super::error::ScenarioError;
use super::spec::Scenario;

/// A Cartesian reference that can be shared by the stages of a run.
pub type SharedTrajectory = std::sync::Arc<dyn CartesianTrajectory + Send + Sync>;

/// The controller a deployable step is asked in (`scara run scenario --precision`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Precision {
    /// Single precision, as on a microcontroller whose FPU has no `f64`.
    F32,
    /// Double precision.
    F64,
}

/// What a planned reference reports after the run, for `metrics.json` and the console.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ReferenceReport {
    /// Samples at which the reference's joint rates were damped near a singularity.
    pub singular_samples: usize,
    /// Samples at which the inverse kinematics failed and the previous target was held.
    pub failed_samples: usize,
    /// Further keys of `metrics.json` (the robot's own: a SCARA's elbow plan and flips).
    pub metrics: serde_json::Map<String, serde_json::Value>,
    /// Lines for the console.
    pub notes: Vec<String>,
}

/// A reference planned for a robot: the joint setpoints of the run (a
/// [`ReferenceSource`]), the Cartesian reference as it runs, where it starts, and what it
/// reports.
pub trait PlannedReference<const N: usize>: ReferenceSource<N> {
    /// The Cartesian reference as the run follows it (a planned manoeuvre may have paused
    /// it), for the checks and metrics that need the path.
    fn trajectory(&self) -> &dyn CartesianTrajectory;
    /// The joints at rest on the reference's first point (`start_on_reference`).
    fn start(&self) -> JointVector<N>;
    /// The joints that put the tool at `position` (m) with the reference's orientation at `t`
    /// (the contact pose of a force design), or why not.
    ///
    /// # Errors
    ///
    /// A message if the pose is out of reach.
    fn joints_at(
        &self,
        t: f64,
        position: &nalgebra::Vector3<f64>,
    ) -> Result<JointVector<N>, String>;
    /// The report after a run of `samples`.
    fn report(&self, samples: &[Sample<N>], effort_limits: &JointVector<N>) -> ReferenceReport;
}

/// A robot as a scenario runs it (see the [module documentation](self)).
pub trait ScenarioRobot<const N: usize>: ParametricModel<N> + Send + Sync {
    /// The named references (`[reference] kind = "thesis"`) of this robot.
    fn named_references() -> &'static [&'static str] {
        &[]
    }

    /// The named reference `name`, with `surface_z_m` (m) where it takes one; `None` if there
    /// is no such reference for this robot.
    fn named_reference(_name: &str, _surface_z_m: Option<f64>) -> Option<SharedTrajectory> {
        None
    }

    /// Whether the robot plans elbow switches (`[reference] elbow_switch` and its keys).
    fn has_elbows() -> bool {
        false
    }

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

macro_rules! scenario_robots {
    ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        /// Calls `visitor` with the robot called `name`; `None` if there is no such robot.
        pub fn visit_robot<V: ScenarioVisitor>(name: &str, visitor: V) -> Option<V::Output> {
            match name {
                $(stringify!($module) => Some(visitor.visit::<$n, _>(&crate::model::$ty)),)*
                _ => None,
            }
        }
        $(default_scenario_robot!($module, $ty, $n);)*
    };
}

/// The defaults for every robot without a module of its own in `crate::robots`: the list of
/// robots that have one is this macro's first rules.
macro_rules! default_scenario_robot {
    (scara, $ty:ident, $n:literal) => {};
    ($module:ident, $ty:ident, $n:literal) => {
        impl ScenarioRobot<$n> for crate::model::$ty {}
    };
}

scara_generated::for_each_robot!(scenario_robots);
