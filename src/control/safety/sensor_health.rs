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
