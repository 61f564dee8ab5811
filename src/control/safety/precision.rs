//! The supervisor's numbers in another scalar: limits stated in `f64` rounded to the one a
//! microcontroller runs (`f32`), and its trips widened back to `f64` for a report (the
//! peaks: [`Peaks::cast`](super::Peaks::cast)).
//! Every value goes through `f64`: exact from `f32`, rounded to nearest into `f32`.

use nalgebra::RealField;

use super::limits::{ForceLimits, Reaction, SafetyLimits, SensorLimits};
use super::trip::{Trip, TripLog};

/// `x` as `U`, through `f64` (NaN if `T` has no `f64` value, which no float lacks).
#[must_use]
pub fn cast<T: RealField + Copy, U: RealField + Copy>(x: T) -> U {
    nalgebra::convert(nalgebra::try_convert::<T, f64>(x).unwrap_or(f64::NAN))
}

impl<T: RealField + Copy> Reaction<T> {
    /// The same reaction in the scalar `U`.
    #[must_use]
    pub fn cast<U: RealField + Copy>(&self) -> Reaction<U> {
        match *self {
            Self::Hold { omega_rad_s } => Reaction::Hold {
                omega_rad_s: cast(omega_rad_s),
            },
            Self::Retract {
                omega_rad_s,
                speed_m_s,
                distance_m,
            } => Reaction::Retract {
                omega_rad_s: cast(omega_rad_s),
                speed_m_s: cast(speed_m_s),
                distance_m: cast(distance_m),
            },
            Self::Compliant {
                stiffness_n_m,
                damping_rad_s,
            } => Reaction::Compliant {
                stiffness_n_m: cast(stiffness_n_m),
                damping_rad_s: cast(damping_rad_s),
            },
        }
    }
}

impl<T: RealField + Copy> ForceLimits<T> {
    /// The same limits in the scalar `U`.
    #[must_use]
    pub fn cast<U: RealField + Copy>(&self) -> ForceLimits<U> {
        ForceLimits {
            max_n: cast(self.max_n),
            max_rate_n_s: cast(self.max_rate_n_s),
            rate_window_s: cast(self.rate_window_s),
            oscillation_rms_n: self.oscillation_rms_n.map(cast),
            oscillation_hz: cast(self.oscillation_hz),
            oscillation_window_s: cast(self.oscillation_window_s),
            oscillation_arm_s: cast(self.oscillation_arm_s),
            oscillation_swing_window_s: cast(self.oscillation_swing_window_s),
            loss_fraction: self.loss_fraction.map(cast),
            loss_s: cast(self.loss_s),
        }
    }
}

impl<T: RealField + Copy> SensorLimits<T> {
    /// The same limits in the scalar `U`.
    #[must_use]
    pub fn cast<U: RealField + Copy>(&self) -> SensorLimits<U> {
        SensorLimits {
            range_n: cast(self.range_n),
            range_nm: cast(self.range_nm),
            frozen_s: self.frozen_s.map(cast),
            stale_s: cast(self.stale_s),
            spike_n: self.spike_n.map(cast),
        }
    }
}

impl<T: RealField + Copy, const N: usize> SafetyLimits<T, N> {
    /// The same limits in the scalar `U`: those of a host's design on a microcontroller.
    #[must_use]
    pub fn cast<U: RealField + Copy>(&self) -> SafetyLimits<U, N> {
        SafetyLimits {
            force: self.force.cast(),
            sensor: self.sensor.cast(),
            max_tool_speed_m_s: self.max_tool_speed_m_s.map(cast),
            workspace: self.workspace.map(|(lo, hi)| (lo.map(cast), hi.map(cast))),
            joint_lower: self.joint_lower.map(cast),
            joint_upper: self.joint_upper.map(cast),
            joint_margin: self.joint_margin.map(|v| v.map(cast)),
            max_joint_speed: self.max_joint_speed.map(|v| v.map(cast)),
            effort: self.effort.map(cast),
            max_torque_rate: self.max_torque_rate.map(|v| v.map(cast)),
            reaction: self.reaction.cast(),
        }
    }
}

impl<T: RealField + Copy> Trip<T> {
    /// The same trip in the scalar `U`.
    #[must_use]
    pub fn cast<U: RealField + Copy>(&self) -> Trip<U> {
        Trip {
            cause: self.cause,
            t: cast(self.t),
            value: cast(self.value),
            limit: cast(self.limit),
        }
    }
}

impl<T: RealField + Copy> TripLog<T> {
    /// The same log in the scalar `U`, in order.
    #[must_use]
    pub fn cast<U: RealField + Copy>(&self) -> TripLog<U> {
        let mut log = TripLog::default();
        for trip in self.iter() {
            log.record(trip.cast());
        }
        log
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::safety::TripCause;

    #[test]
    fn limits_round_to_f32_and_widen_back_within_its_precision() {
        let mut l = SafetyLimits::<f64, 4>::unit_joints(100.0, Some(200.0));
        assert_eq!(l.force.max_n, 600.0);
        l.force.max_n = 600.1;
        l.reaction = Reaction::retract();
        let single: SafetyLimits<f32, 4> = l.cast();
        assert_eq!(single.force.max_n, 600.1_f32);
        let back: SafetyLimits<f64, 4> = single.cast();
        assert!((back.force.max_n - 600.1).abs() < 1e-4);
        assert_eq!(back.reaction.name(), "retract");
        assert_eq!(l.cast::<f64>(), l);
    }

    #[test]
    fn a_trip_log_keeps_its_order_and_causes() {
        let mut log = TripLog::<f32>::default();
        log.record(Trip {
            cause: TripCause::SensorStale,
            t: 1.5,
            value: 0.03,
            limit: 0.02,
        });
        log.record(Trip {
            cause: TripCause::Force,
            t: 1.6,
            value: 700.0,
            limit: 600.0,
        });
        let wide: TripLog<f64> = log.cast();
        assert_eq!(wide.len(), 2);
        assert_eq!(wide.first().unwrap().cause, TripCause::SensorStale);
        assert_eq!(wide.first().unwrap().t, 1.5);
    }
}
