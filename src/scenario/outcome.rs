//! The run (the last stage) and what it gives: every sample, the run's counts, and the
//! metrics of joint tracking, pose tracking, force and contact, for any robot.

use super::controllers::GainReport;
use super::planned::ReferenceReport;
use crate::contact::Scene;
use crate::metrics::{AlignmentSummary, PoseSummary, PostureSummary};
use crate::metrics::{ContactSummary, ForceSummary};
use crate::model::JointKind;
use crate::sim::{RunStats, Sample};
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

/// What a run gives with every one of its samples: [`PreparedRun::execute`]'s result, for a
/// robot of `N` joints. The erased [`execute`] keeps the [`Outcome`] only.
///
/// [`PreparedRun::execute`]: super::PreparedRun::execute
/// [`execute`]: super::execute
#[derive(Clone, Debug)]
pub struct Recorded<const N: usize> {
    /// The run's metrics and counts.
    pub outcome: Outcome,
    /// One entry per control sample.
    pub samples: Vec<Sample<N>>,
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

/// What a run gives: its counts and metrics (the samples are in [`Recorded`]).
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The run's counts.
    pub stats: RunCounts,
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
    /// The tool axis against the inward normal in contact (a controller that holds one).
    pub alignment: Option<AlignmentSummary>,
    /// A redundant arm's posture error (from the scenario's `[metrics] after_s`).
    pub posture: Option<PostureSummary>,
    /// The sensor's bias as the controller tared it, against the true one (a tared sensor).
    pub sensor_bias: Option<BiasReport>,
    /// The largest step of a joint's commanded torque between consecutive samples over the
    /// first 10 samples of force control (`SWITCH_WINDOW_SAMPLES`, the switch's included), N m
    /// or N: how smoothly force control starts.
    pub switch_torque_step: Option<f64>,
    /// The largest such step from 1 s (`SETTLED_AFTER_SWITCH_S`) after the switch on: what
    /// the sensor's noise alone moves the torques by in steady contact, N m or N.
    pub settled_torque_step: Option<f64>,
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
    /// What the safety supervisor saw, with the run's faults.
    pub safety: super::safety_outcome::SafetySummary,
    /// What the planned reference reports (damped samples, the robot's own keys).
    pub reference: ReferenceReport,
}

/// How many samples from the switch `Outcome::switch_torque_step` looks at.
pub const SWITCH_WINDOW_SAMPLES: usize = 10;
/// When, after the switch, `Outcome::settled_torque_step` starts looking, s.
pub const SETTLED_AFTER_SWITCH_S: f64 = 1.0;

/// The tared bias of the force sensor (sensor frame) and the true one, N.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BiasReport {
    /// The controller's estimate, force axes, N.
    pub estimate_n: [f64; 3],
    /// The sensor's bias, N.
    pub true_n: [f64; 3],
    /// `|estimate - true|`, N.
    pub error_n: f64,
}
