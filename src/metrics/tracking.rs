//! Joint-space tracking of a position trial (thesis Chapter 4): the RMS and largest joint
//! errors `q_d - q`, over the run and after the transient, and the largest torques.

use crate::model::JointVector;
use crate::sim::Sample;

/// Joint-space tracking metrics of a position trial.
///
/// Errors are `q_d - q` per joint (rad or m); "after" means samples with `t >= after_s`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrackingMetrics<const N: usize> {
    after_s: f64,
    n: usize,
    n_after: usize,
    sum_sq: JointVector<N>,
    sum_sq_after: JointVector<N>,
    max_after: JointVector<N>,
    max_tau: JointVector<N>,
}

/// Final values of [`TrackingMetrics`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrackingSummary<const N: usize> {
    /// RMS joint error over the whole run, rad or m.
    pub rms_joint_error: JointVector<N>,
    /// RMS joint error for `t >= after_s`.
    pub rms_joint_error_after: JointVector<N>,
    /// Largest absolute joint error for `t >= after_s`.
    pub max_joint_error_after: JointVector<N>,
    /// Largest absolute applied torque, N m or N.
    pub max_abs_tau: JointVector<N>,
    /// The `after_s` used, s.
    pub after_s: f64,
}

impl<const N: usize> TrackingMetrics<N> {
    /// Empty accumulator; `after_s` is the start of the "after transient" window (2 s in the
    /// thesis's figures).
    #[must_use]
    pub fn new(after_s: f64) -> Self {
        let z = JointVector::zeros();
        Self {
            after_s,
            n: 0,
            n_after: 0,
            sum_sq: z,
            sum_sq_after: z,
            max_after: z,
            max_tau: z,
        }
    }

    /// Adds one sample.
    pub fn push(&mut self, s: &Sample<N>) {
        let e = s.setpoint.joint.q - s.q;
        let sq = e.component_mul(&e);
        self.n += 1;
        self.sum_sq += sq;
        if super::reached(s.t, self.after_s) {
            self.n_after += 1;
            self.sum_sq_after += sq;
            self.max_after = self.max_after.zip_map(&e, |m, x| m.max(x.abs()));
        }
        self.max_tau = self.max_tau.zip_map(&s.tau, |m, x| m.max(x.abs()));
    }

    /// The metrics so far (zeros for an empty window).
    #[must_use]
    pub fn summary(&self) -> TrackingSummary<N> {
        let rms = |sum: &JointVector<N>, n: usize| {
            if n == 0 {
                JointVector::zeros()
            } else {
                sum.map(|x| crate::math::sqrt(x / n as f64))
            }
        };
        TrackingSummary {
            rms_joint_error: rms(&self.sum_sq, self.n),
            rms_joint_error_after: rms(&self.sum_sq_after, self.n_after),
            max_joint_error_after: self.max_after,
            max_abs_tau: self.max_tau,
            after_s: self.after_s,
        }
    }
}
