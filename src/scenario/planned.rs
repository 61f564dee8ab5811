//! What the reference stage gives: a reference planned for a robot (its joint setpoints, the
//! Cartesian path as it runs, where it starts) and what it reports after the run.

use crate::model::JointVector;
use crate::sim::{ReferenceSource, Sample};
use crate::trajectory::CartesianTrajectory;

/// A Cartesian reference that can be shared by the stages of a run.
pub type SharedTrajectory = std::sync::Arc<dyn CartesianTrajectory + Send + Sync>;

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
