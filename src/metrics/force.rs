//! The thesis's force metrics of a hybrid trial (Chapter 5): the contact force along base z
//! against its reference (overshoot, settling, RMS over the last window) and the x-y position
//! error in contact. [`ContactMetrics`](super::ContactMetrics) measures the same along any
//! surface's normal.

use super::{Rms, Settling};
use crate::sim::Sample;

/// Contact-force and in-contact position metrics of a hybrid trial (z force, x-y position).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForceMetrics {
    switch_s: f64,
    last_window_s: f64,
    end_s: f64,
    nominal_n: f64,
    peak_excess_n: f64,
    settling: Settling,
    error_last_n: Rms,
    xy_error_m: Rms,
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
            peak_excess_n: 0.0,
            settling: Settling::new(band_fraction * nominal_n),
            error_last_n: Rms::default(),
            xy_error_m: Rms::default(),
            min_z: f64::INFINITY,
        }
    }

    /// Adds one sample.
    pub fn push<const N: usize>(&mut self, s: &Sample<N>) {
        self.min_z = self.min_z.min(s.position.z);
        if !super::reached(s.t, self.switch_s) {
            return;
        }
        let fz = s.wrench[2];
        let fz_ref = s.setpoint.wrench[2];
        let err = fz - fz_ref;
        self.peak_excess_n = self.peak_excess_n.max(-err);
        self.settling.push(s.t, err);
        if super::reached(s.t, self.end_s - self.last_window_s) {
            self.error_last_n.push(err);
        }
        let exy = s.setpoint.cartesian.position.xy() - s.position.xy();
        self.xy_error_m.push_squared(exy.norm_squared());
    }

    /// The metrics so far.
    #[must_use]
    pub fn summary(&self) -> ForceSummary {
        ForceSummary {
            force_overshoot_pct: self.peak_excess_n / self.nominal_n * 100.0,
            settling_time_s: self.settling.time_after(self.switch_s, self.end_s),
            force_rms_error_last_n: self.error_last_n.rms(),
            xy_rms_error_contact_mm: self.xy_error_m.rms() * 1000.0,
            min_z_m: self.min_z,
        }
    }
}
