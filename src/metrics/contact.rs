//! Contact metrics of any surface: the normal force along the real surface's normal at the
//! contact point, the tangential (friction) force, the path error in the tangent plane, and
//! when contact was first made and detected (thesis Chapter 6 and the scenario format).

use super::{Rms, Settling};
use crate::contact::Scene;
use crate::sim::Sample;
use nalgebra::Vector3;

/// The normal push (N, positive pressing), the reference push and the tangential force
/// magnitude of one sample against `scene` (zero away from every surface), with the unit
/// normal used.
#[must_use]
pub fn normal_components<const N: usize>(
    s: &Sample<N>,
    scene: &Scene,
) -> (f64, f64, f64, Vector3<f64>) {
    let f = Vector3::new(s.wrench[0], s.wrench[1], s.wrench[2]);
    let w = &s.setpoint.wrench;
    let f_ref = Vector3::new(w[0], w[1], w[2]);
    let v = Vector3::zeros();
    let n = scene
        .nearest(&s.position, &v)
        .map_or(Vector3::z(), |(_, c)| c.closest.normal);
    let push = -n.dot(&f);
    let tangential = (f + n * push).norm();
    (push, -n.dot(&f_ref), tangential, n)
}

/// Accumulates contact metrics sample by sample (no allocation).
///
/// `force_start_s` is when force control started (the switch), `value_n` the nominal force
/// (for percentages and the 5 % settling band), `end_s` the run's length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactMetrics {
    force_start_s: Option<f64>,
    value_n: f64,
    end_s: f64,
    first_touch_s: Option<f64>,
    touching: bool,
    losses: usize,
    peak_push_n: f64,
    max_tangential_n: f64,
    peak_excess_n: f64,
    settling: Settling,
    error_last_n: Rms,
    error_short_n: Rms,
    path_error_m: Rms,
    sum_steady: f64,
    n_steady: usize,
    ramp_s: f64,
    from_push_n: Option<f64>,
    settling_ramped: Settling,
}

/// Final values of [`ContactMetrics`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactSummary {
    /// When force control started, s (`None`: never).
    pub force_start_s: Option<f64>,
    /// First sample with a non-zero normal force, s.
    pub first_touch_s: Option<f64>,
    /// Times the tool left the surface after the first touch.
    pub contact_losses: usize,
    /// Largest normal push, N.
    pub peak_normal_force_n: f64,
    /// Largest tangential (friction) force, N.
    pub max_tangential_force_n: f64,
    /// Largest push beyond the reference after the switch, % of the nominal force.
    pub normal_force_overshoot_pct: f64,
    /// Time from the switch until the push stays within 5 % of the nominal force of its
    /// reference, s (`None`: not settled by the end, or never switched).
    pub normal_force_settling_time_s: Option<f64>,
    /// RMS of push minus reference over the last 5 s, N.
    pub normal_force_rms_error_last5s_n: f64,
    /// RMS of push minus reference over the last [`SHORT_WINDOW_S`] (3 s), N.
    pub normal_force_rms_error_last3s_n: f64,
    /// RMS tangential path error while force controlled and touching, mm.
    pub path_rms_error_contact_mm: f64,
    /// Mean of push minus reference over the last [`STEADY_WINDOW_S`], N (positive:
    /// pressing harder than asked).
    pub normal_force_steady_error_n: f64,
    /// As `normal_force_settling_time_s`, but against the reference as the controller ramps
    /// it from the push at the switch (see [`ContactMetrics::with_ramp`]); the same without
    /// a ramp.
    pub normal_force_tracking_settling_s: Option<f64>,
}

/// Length of the final window of the RMS force error, s.
pub const LAST_WINDOW_S: f64 = 5.0;
/// Length of the shorter final window of the RMS force error, s.
pub const SHORT_WINDOW_S: f64 = 3.0;
/// Length of the final window of the steady-state force error, s.
pub const STEADY_WINDOW_S: f64 = 1.0;
/// Settling band, share of the nominal force.
pub const SETTLING_BAND: f64 = 0.05;

impl ContactMetrics {
    /// An empty accumulator.
    #[must_use]
    pub fn new(force_start_s: Option<f64>, value_n: f64, end_s: f64) -> Self {
        Self {
            force_start_s,
            value_n,
            end_s,
            first_touch_s: None,
            touching: false,
            losses: 0,
            peak_push_n: 0.0,
            max_tangential_n: 0.0,
            peak_excess_n: 0.0,
            settling: Settling::new(SETTLING_BAND * value_n),
            error_last_n: Rms::default(),
            error_short_n: Rms::default(),
            path_error_m: Rms::default(),
            sum_steady: 0.0,
            n_steady: 0,
            ramp_s: 0.0,
            from_push_n: None,
            settling_ramped: Settling::new(SETTLING_BAND * value_n),
        }
    }

    /// Also measures settling against the reference ramped over `ramp_s` (s) from the push
    /// at the switch to its value, as contact-switched controllers ramp it.
    #[must_use]
    pub fn with_ramp(mut self, ramp_s: f64) -> Self {
        self.ramp_s = ramp_s;
        self
    }

    /// Adds one sample, measured against the real surfaces of `scene`.
    pub fn push<const N: usize>(&mut self, s: &Sample<N>, scene: &Scene) {
        let (push, push_ref, tangential, n) = normal_components(s, scene);
        let touching = push > 0.0;
        if touching && self.first_touch_s.is_none() {
            self.first_touch_s = Some(s.t);
        }
        if self.touching && !touching {
            self.losses += 1;
        }
        self.touching = touching;
        self.peak_push_n = self.peak_push_n.max(push);
        self.max_tangential_n = self.max_tangential_n.max(tangential);
        let Some(start) = self.force_start_s else {
            return;
        };
        if !super::reached(s.t, start) {
            return;
        }
        let err = push - push_ref;
        let from = *self.from_push_n.get_or_insert(push);
        let share = if self.ramp_s > 0.0 {
            ((s.t - start) / self.ramp_s).clamp(0.0, 1.0)
        } else {
            1.0
        };
        self.settling_ramped
            .push(s.t, push - (from + (push_ref - from) * share));
        self.peak_excess_n = self.peak_excess_n.max(err);
        self.settling.push(s.t, err);
        if super::reached(s.t, self.end_s - LAST_WINDOW_S) {
            self.error_last_n.push(err);
        }
        if super::reached(s.t, self.end_s - SHORT_WINDOW_S) {
            self.error_short_n.push(err);
        }
        if super::reached(s.t, self.end_s - STEADY_WINDOW_S) {
            self.sum_steady += err;
            self.n_steady += 1;
        }
        if touching {
            let e = s.setpoint.cartesian.position - s.position;
            let et = e - n * n.dot(&e);
            self.path_error_m.push_squared(et.norm_squared());
        }
    }

    /// The metrics so far.
    #[must_use]
    pub fn summary(&self) -> ContactSummary {
        let settled = |settling: &Settling| {
            self.force_start_s
                .and_then(|start| settling.time_after(start, self.end_s))
        };
        ContactSummary {
            force_start_s: self.force_start_s,
            first_touch_s: self.first_touch_s,
            contact_losses: self.losses,
            peak_normal_force_n: self.peak_push_n,
            max_tangential_force_n: self.max_tangential_n,
            normal_force_overshoot_pct: self.peak_excess_n / self.value_n * 100.0,
            normal_force_settling_time_s: settled(&self.settling),
            normal_force_rms_error_last5s_n: self.error_last_n.rms(),
            normal_force_rms_error_last3s_n: self.error_short_n.rms(),
            path_rms_error_contact_mm: self.path_error_m.rms() * 1000.0,
            normal_force_steady_error_n: if self.n_steady == 0 {
                0.0
            } else {
                self.sum_steady / self.n_steady as f64
            },
            normal_force_tracking_settling_s: settled(&self.settling_ramped),
        }
    }
}
