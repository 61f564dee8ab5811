//! Task-space tracking metrics: the tool's position and orientation errors against the
//! Cartesian reference, in the robot's task directions ([`Task::pose_error`]).

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
    n: usize,
    sum_sq_position: f64,
    sum_sq_orientation: f64,
    max_position: f64,
    max_orientation: f64,
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
            n: 0,
            sum_sq_position: 0.0,
            sum_sq_orientation: 0.0,
            max_position: 0.0,
            max_orientation: 0.0,
        }
    }

    /// Adds one sample.
    pub fn push<const N: usize>(&mut self, s: &Sample<N>) {
        if s.t < self.after_s - 1e-12 || s.force_controlled {
            return;
        }
        let c = &s.setpoint.cartesian;
        let e = self
            .task
            .pose_error(&c.position, &c.orientation, &s.position, &s.orientation);
        let (ep, eo) = (e.fixed_rows::<3>(0).norm(), e.fixed_rows::<3>(3).norm());
        self.n += 1;
        self.sum_sq_position += ep * ep;
        self.sum_sq_orientation += eo * eo;
        self.max_position = self.max_position.max(ep);
        self.max_orientation = self.max_orientation.max(eo);
    }

    /// The metrics so far (zeros for an empty window).
    #[must_use]
    pub fn summary(&self) -> PoseSummary {
        let rms = |sum: f64| {
            if self.n == 0 {
                0.0
            } else {
                crate::math::sqrt(sum / self.n as f64)
            }
        };
        PoseSummary {
            position_rms_m: rms(self.sum_sq_position),
            position_max_m: self.max_position,
            orientation_rms_rad: rms(self.sum_sq_orientation),
            orientation_max_rad: self.max_orientation,
            after_s: self.after_s,
            samples: self.n,
        }
    }
}
