//! Stage 1: the reference. The scenario's Cartesian reference (a robot's named one,
//! waypoints, a CSV of poses) planned by the robot into joint setpoints, or a joint
//! reference followed as it is; the run's length and initial joints.

use std::sync::Arc;

use super::super::error::ScenarioError;
use super::super::joint_plan::JointPlan;
use super::super::planned::{PlannedReference, SharedTrajectory};
use super::super::robot::ScenarioRobot;
use super::super::spec::{ReferenceSpec, Scenario};
use crate::model::JointVector;
use crate::trajectory::{CartesianTrajectory, JointReference};

/// What the reference stage produced.
pub struct ReferenceStage<const N: usize> {
    /// The planned reference: the run's joint setpoints.
    pub planned: Box<dyn PlannedReference<N>>,
    /// Length of the run, s (`duration_s`, else the planned reference's).
    pub duration: f64,
    /// Initial joints (`q0`, or at rest on the reference's first point).
    pub q0: JointVector<N>,
}

/// The scenario's Cartesian reference for robot `R` (`None` for a joint reference).
///
/// # Errors
///
/// [`ScenarioError`] on `reference.name` for a named reference the robot does not have.
pub fn cartesian<const N: usize, R: ScenarioRobot<N>>(
    scenario: &Scenario,
) -> Result<Option<SharedTrajectory>, ScenarioError> {
    Ok(match &scenario.reference {
        ReferenceSpec::Named { name, surface_z_m } => {
            Some(R::named_reference(name, *surface_z_m).ok_or_else(|| {
                scenario.error(
                    "reference.name",
                    format!("robot `{}` has no reference `{name}`", R::NAME),
                )
            })?)
        }
        ReferenceSpec::Waypoints(w) => Some(Arc::new(w.clone())),
        ReferenceSpec::Csv(_, t) => Some(Arc::new(t.clone())),
        ReferenceSpec::Joints(..) => None,
    })
}

/// The scenario's joint reference, if it is one.
fn joints<const N: usize, R: ScenarioRobot<N>>(
    scenario: &Scenario,
) -> Result<Option<JointReference<N>>, ScenarioError> {
    match &scenario.reference {
        ReferenceSpec::Joints(path, text) => {
            JointReference::<N>::from_csv_reader_named(text.as_bytes(), &R::JOINT_NAMES)
                .map(Some)
                .map_err(|e| scenario.error("reference.file", format!("{}: {e}", path.display())))
        }
        _ => Ok(None),
    }
}

/// The length of the scenario's reference before any planning, s.
pub(crate) fn reference_duration<const N: usize, R: ScenarioRobot<N>>(
    scenario: &Scenario,
) -> Result<f64, ScenarioError> {
    if let Some(t) = cartesian::<N, R>(scenario)? {
        return Ok(t.duration());
    }
    Ok(joints::<N, R>(scenario)?.map_or(0.0, |j| j.duration()))
}

/// Stage 1 (see the [module documentation](self)).
///
/// # Errors
///
/// [`ScenarioError`] naming the key at fault: a reference the robot cannot follow (out of
/// its workspace or limits).
pub fn reference<const N: usize, R: ScenarioRobot<N>>(
    scenario: &Scenario,
    robot: &R,
) -> Result<ReferenceStage<N>, ScenarioError> {
    let planned: Box<dyn PlannedReference<N>> = match cartesian::<N, R>(scenario)? {
        Some(trajectory) => robot.plan(scenario, trajectory)?,
        None => {
            let j = joints::<N, R>(scenario)?
                .ok_or_else(|| scenario.error("reference", "no reference"))?;
            Box::new(JointPlan::new(*robot, j))
        }
    };
    let duration = scenario
        .duration_s
        .unwrap_or_else(|| planned.trajectory().duration());
    let q0 = if scenario.start_on_reference {
        planned.start()
    } else {
        let q0 = scenario.q0_or_zero();
        JointVector::<N>::from_fn(|i, _| q0[i])
    };
    Ok(ReferenceStage {
        planned,
        duration,
        q0,
    })
}
