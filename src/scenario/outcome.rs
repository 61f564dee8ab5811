//! The run (the last stage) and what it gives: every sample, the run's counts, and the
//! metrics of joint tracking, pose tracking, force and contact, for any robot.

use std::any::Any;

use super::controllers::GainReport;
use super::desired_force::DesiredForce;
use super::prepare::{Prepared, PreparedRun};
use super::robot::{PlannedReference, ReferenceReport, ScenarioRobot};
use super::runner::{run, RunOutput};
use super::spec::Scenario;
use crate::contact::Scene;
use crate::control::selection::SelectionPolicy;
use crate::metrics::{ContactMetrics, ContactSummary, ForceMetrics, ForceSummary};
use crate::metrics::{PoseMetrics, PoseSummary, TrackingMetrics};
use crate::model::{JointKind, Wrench};
use crate::sim::{ReferenceSource, RunStats, Sample, Setpoint, SimError};
use crate::target::Task;

/// Start of the "after the transient" window of the joint tracking metrics, s (the
/// thesis's).
pub const TRACKING_AFTER_S: f64 = 2.0;

/// The run's counts, per joint.
#[derive(Clone, Debug, PartialEq)]
pub struct RunCounts {
    /// Control samples taken.
    pub samples: usize,
    /// Per joint, the first sample time at which the position was outside its limits.
    pub first_limit_violation: Vec<Option<f64>>,
    /// Per joint, how many samples had the torque clamped by saturation.
    pub saturated_samples: Vec<usize>,
    /// Per joint, how many samples found it past an end stop.
    pub end_stop_samples: Vec<usize>,
}

impl<const N: usize> From<&RunStats<N>> for RunCounts {
    fn from(s: &RunStats<N>) -> Self {
        Self {
            samples: s.samples,
            first_limit_violation: s.first_limit_violation.to_vec(),
            saturated_samples: s.saturated_samples.to_vec(),
            end_stop_samples: s.end_stop_samples.to_vec(),
        }
    }
}

/// Every sample of a run (of the robot's joint count) and its counts.
pub struct RunRecord {
    samples: Box<dyn Any + Send + Sync>,
    /// The run's counts.
    pub stats: RunCounts,
}

impl RunRecord {
    /// The samples, if the robot has `N` joints.
    #[must_use]
    pub fn samples<const N: usize>(&self) -> Option<&[Sample<N>]> {
        self.samples
            .downcast_ref::<Vec<Sample<N>>>()
            .map(Vec::as_slice)
    }
}

/// Joint tracking metrics, per joint (rad or m; torques N m or N).
#[derive(Clone, Debug, PartialEq)]
pub struct JointTracking {
    /// RMS joint error over the whole run.
    pub rms_joint_error: Vec<f64>,
    /// RMS joint error from [`TRACKING_AFTER_S`] on.
    pub rms_joint_error_after: Vec<f64>,
    /// Largest absolute joint error from [`TRACKING_AFTER_S`] on.
    pub max_joint_error_after: Vec<f64>,
    /// Largest absolute applied torque.
    pub max_abs_tau: Vec<f64>,
}

/// What a run gives.
pub struct Outcome {
    /// Every sample and the run's counts.
    pub run: RunRecord,
    /// The robot's name.
    pub robot: &'static str,
    /// Its joint names.
    pub joint_names: Vec<&'static str>,
    /// Its joint kinds.
    pub joint_kinds: Vec<JointKind>,
    /// Its task.
    pub task: Task,
    /// Joint tracking metrics (the "after" window from [`TRACKING_AFTER_S`], the thesis's).
    pub tracking: JointTracking,
    /// Joint tracking metrics with the "after" window from the scenario's `[metrics]
    /// after_s`.
    pub tracking_after: JointTracking,
    /// Pose tracking metrics (from the scenario's `[metrics] after_s`).
    pub pose: PoseSummary,
    /// The thesis's z-force metrics (force-controlled scenarios).
    pub force: Option<ForceSummary>,
    /// Contact metrics along the real normal (scenarios with surfaces).
    pub contact: Option<ContactSummary>,
    /// The controller's name.
    pub controller_name: &'static str,
    /// Its gains.
    pub gains: GainReport,
    /// The real surfaces.
    pub scene: Scene,
    /// Force control mode: `"time"`, `"contact"` or `None`.
    pub selection: Option<&'static str>,
    /// Samples with any joint outside its limits.
    pub joint_limit_violation_samples: usize,
    /// What the planned reference reports (damped samples, the robot's own keys).
    pub reference: ReferenceReport,
}

impl Outcome {
    /// The robot's joint count.
    #[must_use]
    pub fn dof(&self) -> usize {
        self.joint_names.len()
    }
}

/// A prepared run of any robot, run by [`execute`].
#[allow(clippy::result_large_err)] // see `crate::sim`
pub(super) trait ErasedRun {
    fn execute(
        self: Box<Self>,
        scenario: &Scenario,
        progress: &mut dyn FnMut(f64),
    ) -> Result<Outcome, SimError>;
    fn into_any(self: Box<Self>) -> Box<dyn Any>;
    fn controller_name(&self) -> &'static str;
}

impl<const N: usize, R: ScenarioRobot<N>> ErasedRun for PreparedRun<N, R> {
    fn execute(
        self: Box<Self>,
        scenario: &Scenario,
        progress: &mut dyn FnMut(f64),
    ) -> Result<Outcome, SimError> {
        (*self).execute(scenario, progress)
    }

    fn into_any(self: Box<Self>) -> Box<dyn Any> {
        self
    }

    fn controller_name(&self) -> &'static str {
        self.controller.name()
    }
}

/// The planned reference with the desired force: the setpoints of the run.
struct RunReference<'a, const N: usize> {
    planned: &'a mut dyn PlannedReference<N>,
    force: Option<&'a DesiredForce>,
}

impl<const N: usize> ReferenceSource<N> for RunReference<'_, N> {
    fn at(&mut self, t: f64) -> Setpoint<N> {
        let mut s = self.planned.at(t);
        s.wrench = self
            .force
            .map_or_else(Wrench::zeros, |f| f.wrench(t, &s.cartesian.position));
        s
    }
}

impl<const N: usize, R: ScenarioRobot<N>> PreparedRun<N, R> {
    /// Runs it; `progress` gets the simulated time about every 0.5 s.
    ///
    /// # Errors
    ///
    /// [`SimError`] if the simulation breaks down.
    #[allow(clippy::result_large_err)]
    pub fn execute(
        mut self,
        scenario: &Scenario,
        progress: impl FnMut(f64),
    ) -> Result<Outcome, SimError> {
        let out = self.run(progress)?;
        Ok(self.outcome(scenario, out))
    }

    /// Runs it and keeps the typed samples.
    ///
    /// # Errors
    ///
    /// [`SimError`] if the simulation breaks down.
    #[allow(clippy::result_large_err)]
    pub fn run(&mut self, progress: impl FnMut(f64)) -> Result<RunOutput<N>, SimError> {
        let mut reference = RunReference {
            planned: self.reference.as_mut(),
            force: self.force.as_ref(),
        };
        match &self.plant {
            None => run(
                &self.robot,
                self.controller.as_mut(),
                &mut reference,
                &self.scene,
                &self.config,
                progress,
            ),
            Some(plant) => run(
                plant,
                self.controller.as_mut(),
                &mut reference,
                &self.scene,
                &self.config,
                progress,
            ),
        }
    }

    /// The metrics of a run `out` of this preparation.
    fn outcome(self, scenario: &Scenario, out: RunOutput<N>) -> Outcome {
        let mut tracking = TrackingMetrics::new(TRACKING_AFTER_S);
        out.samples.iter().for_each(|s| tracking.push(s));
        let tracking = tracking.summary();
        let mut after = TrackingMetrics::new(scenario.pose_metrics_after_s);
        out.samples.iter().for_each(|s| after.push(s));
        let after = after.summary();
        let mut pose = PoseMetrics::new(R::TASK, scenario.pose_metrics_after_s);
        out.samples.iter().for_each(|s| pose.push(s));
        let duration = self.config.duration;
        let switch_s = out.samples.iter().find(|s| s.force_controlled).map(|s| s.t);
        let force = scenario.force.as_ref().map(|f| {
            let mut m =
                ForceMetrics::new(switch_s.unwrap_or(duration), duration, 5.0, f.value_n, 0.05);
            out.samples.iter().for_each(|s| m.push(s));
            m.summary()
        });
        let contact = (!scenario.surfaces.is_empty()).then(|| {
            let value = scenario.force.as_ref().map_or(1.0, |f| f.value_n);
            let ramp_s = match scenario.selection {
                Some(SelectionPolicy::Contact(c)) => c.ramp_s,
                _ => 0.0,
            };
            let mut m = ContactMetrics::new(switch_s, value, duration).with_ramp(ramp_s);
            out.samples.iter().for_each(|s| m.push(s, &self.scene));
            m.summary()
        });
        let (lower, upper) = (self.robot.lower_limits(), self.robot.upper_limits());
        let joint_limit_violation_samples = out
            .samples
            .iter()
            .filter(|s| (0..N).any(|i| !(lower[i] <= s.q[i] && s.q[i] <= upper[i])))
            .count();
        let reference = self
            .reference
            .report(&out.samples, &self.config.effort_limits);
        let v = |x: &crate::model::JointVector<N>| x.iter().copied().collect::<Vec<f64>>();
        Outcome {
            robot: R::NAME,
            joint_names: R::JOINT_NAMES.to_vec(),
            joint_kinds: R::JOINT_KINDS.to_vec(),
            task: R::TASK,
            tracking: JointTracking {
                rms_joint_error: v(&tracking.rms_joint_error),
                rms_joint_error_after: v(&tracking.rms_joint_error_after),
                max_joint_error_after: v(&tracking.max_joint_error_after),
                max_abs_tau: v(&tracking.max_abs_tau),
            },
            tracking_after: JointTracking {
                rms_joint_error: v(&after.rms_joint_error),
                rms_joint_error_after: v(&after.rms_joint_error_after),
                max_joint_error_after: v(&after.max_joint_error_after),
                max_abs_tau: v(&after.max_abs_tau),
            },
            pose: pose.summary(),
            force,
            contact,
            controller_name: self.controller.name(),
            gains: self.gains,
            scene: self.scene,
            selection: scenario.selection.map(|s| match s {
                SelectionPolicy::Time { .. } => "time",
                SelectionPolicy::Contact(_) => "contact",
            }),
            joint_limit_violation_samples,
            reference,
            run: RunRecord {
                stats: RunCounts::from(&out.stats),
                samples: Box::new(out.samples),
            },
        }
    }
}

/// Runs a prepared scenario; `progress` gets the simulated time about every 0.5 s.
///
/// # Errors
///
/// [`SimError`] if the simulation breaks down.
#[allow(clippy::result_large_err)]
pub fn execute(
    scenario: &Scenario,
    p: Prepared,
    mut progress: impl FnMut(f64),
) -> Result<Outcome, SimError> {
    p.run.execute(scenario, &mut progress)
}
