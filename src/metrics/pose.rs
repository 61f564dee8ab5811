//! Task-space tracking metrics: the tool's position and orientation errors against the
//! Cartesian reference, in the robot's task directions ([`Task::pose_error`]).

use super::RmsMax;
use crate::sim::Sample;
use crate::target::Task;

/// Position and orientation tracking of the tool from `after_s` on, while it is position
/// controlled (samples in force control, where the reference lies inside the surface on
/// purpose, are left to the contact metrics), accumulated sample by sample without
/// allocation.
///
/// The position error is the distance `|p_d - p|` in the task's translations (m); the
/// orientation error the angle of `log(R_d R^T)` for a full task, the yaw difference for a
/// yaw task (rad), zero for a positioning task.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoseMetrics {
    task: Task,
    after_s: f64,
    position_m: RmsMax,
    orientation_rad: RmsMax,
}

/// Final values of [`PoseMetrics`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoseSummary {
    /// RMS position error for `t >= after_s`, m.
    pub position_rms_m: f64,
    /// Largest position error for `t >= after_s`, m.
    pub position_max_m: f64,
    /// RMS orientation error for `t >= after_s`, rad.
    pub orientation_rms_rad: f64,
    /// Largest orientation error for `t >= after_s`, rad.
    pub orientation_max_rad: f64,
    /// The window's start, s.
    pub after_s: f64,
    /// Samples in the window (position controlled).
    pub samples: usize,
}

impl PoseMetrics {
    /// Empty accumulator for a robot of task `task`, window from `after_s` (s).
    #[must_use]
    pub fn new(task: Task, after_s: f64) -> Self {
        Self {
            task,
            after_s,
            position_m: RmsMax::default(),
            orientation_rad: RmsMax::default(),
        }
    }

    /// Adds one sample.
    pub fn push<const N: usize>(&mut self, s: &Sample<N>) {
        if !super::reached(s.t, self.after_s) || s.force_controlled {
            return;
        }
        let c = &s.setpoint.cartesian;
        let e = self
            .task
            .pose_error(&c.position, &c.orientation, &s.position, &s.orientation);
        self.position_m.push(e.fixed_rows::<3>(0).norm());
        self.orientation_rad.push(e.fixed_rows::<3>(3).norm());
    }

    /// The metrics so far (zeros for an empty window).
    #[must_use]
    pub fn summary(&self) -> PoseSummary {
        PoseSummary {
            position_rms_m: self.position_m.rms(),
            position_max_m: self.position_m.max(),
            orientation_rms_rad: self.orientation_rad.rms(),
            orientation_max_rad: self.orientation_rad.max(),
            after_s: self.after_s,
            samples: self.position_m.count(),
        }
    }
}
