//! The force sensor's health: non-finite, out-of-range, stale and frozen readings, and a
//! spike filter.

// `!(x <= limit)` on purpose: a NaN fails the check and trips.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::limits::SensorLimits;
use super::trip::{Trip, TripCause};
use nalgebra::{RealField, Vector6};

/// The checks of each reading, in order: non-finite (any axis NaN or infinite), stale (its
/// age beyond the stale time), out of range (any axis beyond the range), frozen (fresh
/// readings bitwise equal to the previous fresh one for the frozen time); then the spike
/// filter. No allocation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorHealth<T> {
    accepted: Option<Vector6<T>>,
    last_fresh: Option<Vector6<T>>,
    frozen_for_s: T,
    held: bool,
    spikes: u32,
}

impl<T: RealField + Copy> Default for SensorHealth<T> {
    fn default() -> Self {
        Self {
            accepted: None,
            last_fresh: None,
            frozen_for_s: T::zero(),
            held: false,
            spikes: 0,
        }
    }
}

impl<T: RealField + Copy> SensorHealth<T> {
    /// The last accepted reading (zero before the first).
    #[must_use]
    pub fn accepted(&self) -> Vector6<T> {
        self.accepted.unwrap_or_else(Vector6::zeros)
    }

    /// Readings the spike filter held back.
    #[must_use]
    pub fn spikes(&self) -> u32 {
        self.spikes
    }

    /// Checks `reading`, `age_s` seconds old, at time `t` (s) one period `dt` (s) after the
    /// previous one: the trip of the first check that fails, if any; the reading the
    /// controller may use is then [`accepted`](Self::accepted) (the spike filter may hold one
    /// back).
    #[inline(always)]
    pub fn judge(
        &mut self,
        limits: &SensorLimits<T>,
        t: T,
        reading: &Vector6<T>,
        age_s: T,
        dt: T,
    ) -> Option<Trip<T>> {
        let trip = |cause, value, limit| Trip {
            cause,
            t,
            value,
            limit,
        };
        // One pass for the common case, without early exits (a NaN fails the comparison too).
        let mut in_range = true;
        for i in 0..3 {
            in_range &=
                (reading[i].abs() <= limits.range_n) & (reading[i + 3].abs() <= limits.range_nm);
        }
        if !in_range {
            if let Some(x) = reading.iter().find(|x| !x.is_finite()) {
                return Some(trip(TripCause::SensorNonFinite, *x, limits.range_n));
            }
        }
        // Within a part in 10^6 of a period: an age is a sum of periods.
        if !(age_s <= limits.stale_s + dt * nalgebra::convert(1e-6)) {
            return Some(trip(TripCause::SensorStale, age_s, limits.stale_s));
        }
        if !in_range {
            let force = reading.fixed_rows::<3>(0).amax();
            if force > limits.range_n {
                return Some(trip(TripCause::SensorRange, force, limits.range_n));
            }
            let torque = reading.fixed_rows::<3>(3).amax();
            return Some(trip(TripCause::SensorRange, torque, limits.range_nm));
        }
        if age_s <= T::zero() {
            let repeated = self
                .last_fresh
                .is_some_and(|last| (0..6).fold(true, |same, i| same & (last[i] == reading[i])));
            if repeated {
                self.frozen_for_s += dt;
            } else {
                self.frozen_for_s = T::zero();
            }
            self.last_fresh = Some(*reading);
            if let Some(frozen_s) = limits.frozen_s {
                // Within a part in 10^6 of a period: a sum of periods is not exact.
                if self.frozen_for_s >= frozen_s - dt * nalgebra::convert(1e-6) {
                    return Some(trip(TripCause::SensorFrozen, self.frozen_for_s, frozen_s));
                }
            }
        }
        if let (Some(spike_n), Some(prev), false) = (limits.spike_n, self.accepted, self.held) {
            let jump = (reading.fixed_rows::<3>(0) - prev.fixed_rows::<3>(0)).norm_squared();
            if jump > spike_n * spike_n {
                self.held = true;
                self.spikes += 1;
                return None;
            }
        }
        self.held = false;
        self.accepted = Some(*reading);
        None
    }
}

#[cfg(test)]
mod tests {
    use super::super::limits::defaults;
    use super::*;

    fn limits() -> SensorLimits<f64> {
        SensorLimits {
            range_n: defaults::SENSOR_RANGE_N,
            range_nm: defaults::SENSOR_RANGE_NM,
            frozen_s: Some(0.005),
            stale_s: 0.003,
            spike_n: Some(defaults::SPIKE_N),
        }
    }

    /// [`SensorHealth::judge`] with [`limits`] at a 1 ms period, as a result: the reading to
    /// use, or the trip.
    fn check(
        h: &mut SensorHealth<f64>,
        t: f64,
        r: &Vector6<f64>,
        age_s: f64,
    ) -> Result<Vector6<f64>, Trip<f64>> {
        match h.judge(&limits(), t, r, age_s, 1e-3) {
            Some(trip) => Err(trip),
            None => Ok(h.accepted()),
        }
    }

    fn fz(f: f64) -> Vector6<f64> {
        Vector6::new(0.0, 0.0, f, 0.0, 0.0, 0.0)
    }

    #[test]
    fn each_bad_reading_trips_with_its_cause() {
        let mut h = SensorHealth::default();
        let cause = |h: &mut SensorHealth<f64>, r: Vector6<f64>, age| {
            check(h, 1.0, &r, age).err().map(|t| t.cause)
        };
        assert_eq!(cause(&mut h, fz(-50.0), 0.0), None);
        assert_eq!(
            cause(&mut h, fz(f64::NAN), 0.0),
            Some(TripCause::SensorNonFinite)
        );
        assert_eq!(
            cause(&mut h, fz(f64::NEG_INFINITY), 0.0),
            Some(TripCause::SensorNonFinite)
        );
        assert_eq!(
            cause(&mut h, fz(-3000.0), 0.0),
            Some(TripCause::SensorRange)
        );
        assert_eq!(cause(&mut h, fz(-50.0), 0.002), None);
        assert_eq!(
            cause(&mut h, fz(-50.0), 0.004),
            Some(TripCause::SensorStale)
        );
    }

    #[test]
    fn a_repeating_reading_is_frozen_after_the_frozen_time() {
        let mut h = SensorHealth::default();
        let r = fz(-50.0);
        // The first reading and four repeats (4 ms) pass; the fifth repeat is 5 ms frozen.
        for k in 0..5 {
            assert!(check(&mut h, k as f64 * 1e-3, &r, 0.0).is_ok(), "{k}");
        }
        let trip = check(&mut h, 5e-3, &r, 0.0).unwrap_err();
        assert_eq!(trip.cause, TripCause::SensorFrozen);
        // A held (not fresh) reading is not a frozen one.
        let mut h = SensorHealth::default();
        for k in 0..10 {
            let _ = check(&mut h, k as f64 * 1e-3, &fz(k as f64), 0.0);
        }
        assert!(check(&mut h, 0.01, &fz(9.0), 0.001).is_ok());
    }

    #[test]
    fn the_spike_filter_holds_one_reading_and_takes_a_real_step_one_period_late() {
        let mut h = SensorHealth::default();
        assert_eq!(check(&mut h, 0.0, &fz(-50.0), 0.0), Ok(fz(-50.0)));
        assert_eq!(check(&mut h, 1e-3, &fz(-2050.0), 0.0), Ok(fz(-50.0)));
        assert_eq!(check(&mut h, 2e-3, &fz(-51.0), 0.0), Ok(fz(-51.0)));
        assert_eq!(h.spikes(), 1);
        // A step that stays: held once, then accepted.
        assert_eq!(check(&mut h, 3e-3, &fz(-600.0), 0.0), Ok(fz(-51.0)));
        assert_eq!(check(&mut h, 4e-3, &fz(-600.0), 0.0), Ok(fz(-600.0)));
    }
}
