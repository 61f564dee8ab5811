//! Run metrics, accumulated sample by sample without allocation: joint tracking errors,
//! torques (Chapter 4), the tool's pose tracking, and contact-force quality (Chapter 5).

use crate::model::JointVector;
use crate::sim::Sample;

pub mod alignment;
pub mod contact;
pub mod pose;
mod rms_max;

pub use alignment::{AlignmentMetrics, AlignmentSummary, PostureMetrics, PostureSummary};
pub use contact::{ContactMetrics, ContactSummary};
pub use pose::{PoseMetrics, PoseSummary};

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
        if s.t >= self.after_s - 1e-12 {
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

/// Contact-force and in-contact position metrics of a hybrid trial (z force, x-y position).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForceMetrics {
    switch_s: f64,
    last_window_s: f64,
    end_s: f64,
    nominal_n: f64,
    band_n: f64,
    peak_excess_n: f64,
    last_outside_s: Option<f64>,
    sum_sq_last: f64,
    n_last: usize,
    sum_sq_xy: f64,
    n_xy: usize,
    min_z: f64,
}

/// Final values of [`ForceMetrics`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForceSummary {
    /// Largest push beyond the reference after the switch, percent of the nominal force:
    /// `max(0, max_t (fz_ref - fz)) / nominal * 100` (fz negative = pushing down).
    pub force_overshoot_pct: f64,
    /// Time after the switch until the force stays within the band of its reference, s
    /// (`None` if it is still outside at the end).
    pub settling_time_s: Option<f64>,
    /// RMS of `fz - fz_ref` over the last window, N.
    pub force_rms_error_last_n: f64,
    /// RMS x-y position error for `t >= switch`, mm.
    pub xy_rms_error_contact_mm: f64,
    /// Lowest end-effector z of the run, m.
    pub min_z_m: f64,
}

impl ForceMetrics {
    /// `switch_s`: when force control starts (2 s); `end_s`: run length (10 s);
    /// `last_window_s`: length of the final RMS window (5 s); `nominal_n`: reference magnitude
    /// (200 N); `band_fraction`: settling band as a fraction of it (0.05).
    #[must_use]
    pub fn new(
        switch_s: f64,
        end_s: f64,
        last_window_s: f64,
        nominal_n: f64,
        band_fraction: f64,
    ) -> Self {
        Self {
            switch_s,
            last_window_s,
            end_s,
            nominal_n,
            band_n: band_fraction * nominal_n,
            peak_excess_n: 0.0,
            last_outside_s: None,
            sum_sq_last: 0.0,
            n_last: 0,
            sum_sq_xy: 0.0,
            n_xy: 0,
            min_z: f64::INFINITY,
        }
    }

    /// Adds one sample.
    pub fn push<const N: usize>(&mut self, s: &Sample<N>) {
        self.min_z = self.min_z.min(s.position.z);
        if s.t < self.switch_s - 1e-12 {
            return;
        }
        let fz = s.wrench[2];
        let fz_ref = s.setpoint.wrench[2];
        let err = fz - fz_ref;
        self.peak_excess_n = self.peak_excess_n.max(-err);
        if err.abs() > self.band_n {
            self.last_outside_s = Some(s.t);
        }
        if s.t >= self.end_s - self.last_window_s - 1e-12 {
            self.sum_sq_last += err * err;
            self.n_last += 1;
        }
        let exy = s.setpoint.cartesian.position.xy() - s.position.xy();
        self.sum_sq_xy += exy.norm_squared();
        self.n_xy += 1;
    }

    /// The metrics so far.
    #[must_use]
    pub fn summary(&self) -> ForceSummary {
        let settling_time_s = match self.last_outside_s {
            None => Some(0.0),
            Some(t) if t >= self.end_s - 1e-9 => None,
            Some(t) => Some(t - self.switch_s),
        };
        let rms = |sum: f64, n: usize| {
            if n == 0 {
                0.0
            } else {
                crate::math::sqrt(sum / n as f64)
            }
        };
        ForceSummary {
            force_overshoot_pct: self.peak_excess_n / self.nominal_n * 100.0,
            settling_time_s,
            force_rms_error_last_n: rms(self.sum_sq_last, self.n_last),
            xy_rms_error_contact_mm: rms(self.sum_sq_xy, self.n_xy) * 1000.0,
            min_z_m: self.min_z,
        }
    }
}
