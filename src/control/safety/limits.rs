//! What the supervisor checks and the limits it checks them against ([`SafetyLimits`]), and
//! what it does on a trip ([`Reaction`]).

use nalgebra::{RealField, SVector, Vector3};

/// The reaction latched on the first trip.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reaction<T> {
    /// Hold the joints where they were at the trip, with gravity compensation and the force
    /// loop off: `tau = M (w^2 (q_trip - q) - 2 w qd) + c + g` (critically damped, `w` rad/s).
    Hold {
        /// Natural frequency of the hold, rad/s (> 0).
        omega_rad_s: T,
    },
    /// Move the tool away from the surface along its outward normal at `speed_m_s` for
    /// `distance_m`, then hold there (the joint reference follows the Cartesian one through
    /// the damped pseudo-inverse of the translational Jacobian, tracked as in `Hold`).
    Retract {
        /// Natural frequency of the tracking, rad/s (> 0).
        omega_rad_s: T,
        /// Retraction speed, m/s (> 0).
        speed_m_s: T,
        /// Retraction distance, m (> 0).
        distance_m: T,
    },
    /// Zero force target and a low stiffness about the pose at the trip:
    /// `tau = J_p^T K (p_trip - p) - M 2 w qd + c + g`, `w` the joint damping's rate.
    Compliant {
        /// Translational stiffness, N/m (>= 0).
        stiffness_n_m: T,
        /// Rate of the joint-space damping, rad/s (> 0).
        damping_rad_s: T,
    },
}

impl<T: RealField + Copy> Reaction<T> {
    /// `hold` at 30 rad/s: stiff enough to stop a tool that lost its surface within a few
    /// millimetres (see the shipped `scenarios/faults/`).
    #[must_use]
    pub fn hold() -> Self {
        Self::Hold {
            omega_rad_s: nalgebra::convert(30.0),
        }
    }

    /// `retract` at 30 rad/s, 50 mm/s for 50 mm.
    #[must_use]
    pub fn retract() -> Self {
        Self::Retract {
            omega_rad_s: nalgebra::convert(30.0),
            speed_m_s: nalgebra::convert(0.05),
            distance_m: nalgebra::convert(0.05),
        }
    }

    /// `compliant` at 200 N/m with joint damping at 5 rad/s.
    #[must_use]
    pub fn compliant() -> Self {
        Self::Compliant {
            stiffness_n_m: nalgebra::convert(200.0),
            damping_rad_s: nalgebra::convert(5.0),
        }
    }

    /// Its name in scenario files and reports: `hold`, `retract` or `compliant`.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::Hold { .. } => "hold",
            Self::Retract { .. } => "retract",
            Self::Compliant { .. } => "compliant",
        }
    }
}

/// The sensor's health checks and its spike filter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorLimits<T> {
    /// Measuring range per force axis, N: a reading beyond it (or non-finite) trips.
    pub range_n: T,
    /// Measuring range per torque axis, N m.
    pub range_nm: T,
    /// How long fresh readings may repeat bitwise before the sensor counts as frozen, s
    /// (`None`: not checked; a noise-free simulated sensor repeats itself at rest).
    pub frozen_s: Option<T>,
    /// Longest age of the reading (no new sample) before it counts as stale, s.
    pub stale_s: T,
    /// Spike filter: a reading whose force differs from the last accepted one by more than
    /// this (N) is replaced by the last accepted one for one period; the next reading is
    /// accepted whatever it is, so a real step is taken one period late (`None`: off).
    pub spike_n: Option<T>,
}

/// Alternating excursions of the high-passed force error that make an oscillation.
pub const OSCILLATION_SWINGS: usize = 4;

/// Limits of the contact force and its oscillation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForceLimits<T> {
    /// Largest measured force (norm of the force part of the accepted reading), N.
    pub max_n: T,
    /// Largest rate of that norm, N/s, over the window `rate_window_s`.
    pub max_rate_n_s: T,
    /// Window of the rate, s: `(|f|(t) - |f|(t - w)) / w`.
    pub rate_window_s: T,
    /// Oscillation: largest RMS of the force error `|f| - |f_d|` above `oscillation_hz`
    /// (second-order high-pass, RMS over `oscillation_window_s`), N (`None`: off).
    pub oscillation_rms_n: Option<T>,
    /// Corner of the oscillation detector's high-pass, Hz: above the force loop's bandwidth,
    /// below the contact mode.
    pub oscillation_hz: T,
    /// Time constant of the RMS, s.
    pub oscillation_window_s: T,
    /// How long after the switch to force control the detector starts, s: the switch's
    /// transient is the force loop's step response, not an oscillation (a contact that
    /// oscillates from its first touch meets the force and rate limits first).
    pub oscillation_arm_s: T,
    /// Window of the swings, s: an oscillation is at least [`OSCILLATION_SWINGS`] alternating
    /// excursions of the high-passed error beyond `+-oscillation_rms_n` within it, with the
    /// RMS above its limit (a step or a drift of the force gives one excursion, not four).
    pub oscillation_swing_window_s: T,
    /// Contact lost: under force control, once the force has reached half its reference, a
    /// force below `loss_fraction` of the reference for `loss_s` seconds trips (`None`: off).
    pub loss_fraction: Option<T>,
    /// How long the force may stay below `loss_fraction` of its reference, s.
    pub loss_s: T,
}

/// Everything the supervisor checks, for a robot of `N` joints.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SafetyLimits<T, const N: usize> {
    /// The contact force.
    pub force: ForceLimits<T>,
    /// The sensor.
    pub sensor: SensorLimits<T>,
    /// Largest tool speed, m/s (`None`: not checked).
    pub max_tool_speed_m_s: Option<T>,
    /// The box the tool must stay in, base frame, m (`None`: not checked).
    pub workspace: Option<(Vector3<T>, Vector3<T>)>,
    /// Lower and upper joint limits, rad or m.
    pub joint_lower: SVector<T, N>,
    /// Upper joint limits.
    pub joint_upper: SVector<T, N>,
    /// Closest approach to a joint limit before a trip, rad or m (0: at the limit; `None`:
    /// not checked).
    pub joint_margin: Option<SVector<T, N>>,
    /// Largest joint speed, rad/s or m/s (`None`: not checked).
    pub max_joint_speed: Option<SVector<T, N>>,
    /// The actuators' limits, N m or N: the torque rate is that of the torque they can
    /// apply (the command clamped to them).
    pub effort: SVector<T, N>,
    /// Largest torque rate, N m/s or N/s per joint: a step of the applied torque larger than
    /// this per period is slewed to it (not a trip) and counted (`None`: not limited).
    pub max_torque_rate: Option<SVector<T, N>>,
    /// What to do on a trip.
    pub reaction: Reaction<T>,
}

impl<T: RealField + Copy, const N: usize> SafetyLimits<T, N> {
    /// The stated defaults ([`defaults`]) for a robot with joint limits `lower` and `upper`
    /// and actuator limits `effort`, pressing with `force_n` (N; `None`: no force control)
    /// through a sensor whose noise is `noise_n` (N, one sigma per axis): the force limit
    /// `max(3 f, f + 150)` N (300 N without force control), the oscillation limit
    /// `max(0.2 f, 5) + 3 sigma` N (off without force control), the frozen check only for a
    /// noisy sensor, a joint margin of `-JOINT_LIMIT_GIVE` (a trip 1 mm or 1 mrad past the
    /// limit, into an end stop), no workspace box, tool and
    /// joint speeds and the torque rate unchecked, and `hold`.
    #[must_use]
    pub fn defaults(
        lower: SVector<T, N>,
        upper: SVector<T, N>,
        effort: SVector<T, N>,
        force_n: Option<T>,
        noise_n: T,
    ) -> Self {
        let c = |x: f64| -> T { nalgebra::convert(x) };
        let force = force_n.map(|f| f.abs());
        Self {
            force: ForceLimits {
                max_n: force.map_or(c(defaults::MAX_FORCE_WITHOUT_FORCE_CONTROL_N), |f| {
                    (c(3.0) * f).max(f + c(150.0))
                }),
                max_rate_n_s: c(defaults::MAX_FORCE_RATE_N_S),
                rate_window_s: c(defaults::RATE_WINDOW_S),
                oscillation_rms_n: force.map(|f| (c(0.2) * f).max(c(5.0)) + c(3.0) * noise_n),
                oscillation_hz: c(defaults::OSCILLATION_HZ),
                oscillation_window_s: c(defaults::OSCILLATION_WINDOW_S),
                oscillation_arm_s: c(defaults::OSCILLATION_ARM_S),
                oscillation_swing_window_s: c(defaults::OSCILLATION_SWING_WINDOW_S),
                loss_fraction: Some(c(defaults::LOSS_FRACTION)),
                loss_s: c(defaults::LOSS_S),
            },
            sensor: SensorLimits {
                range_n: c(defaults::SENSOR_RANGE_N),
                range_nm: c(defaults::SENSOR_RANGE_NM),
                frozen_s: (noise_n > T::zero()).then(|| c(defaults::FROZEN_S)),
                stale_s: c(defaults::STALE_S),
                spike_n: Some(c(defaults::SPIKE_N)),
            },
            max_tool_speed_m_s: None,
            workspace: None,
            joint_lower: lower,
            joint_upper: upper,
            joint_margin: Some(SVector::repeat(-c(defaults::JOINT_LIMIT_GIVE))),
            max_joint_speed: None,
            effort,
            max_torque_rate: None,
            reaction: Reaction::hold(),
        }
    }
}

/// Defaults of [`SafetyLimits`] that are the same for every robot (the scenario layer derives
/// the rest from the scenario: the force limit from its force reference, the box from its
/// reference): sensor range 2500 N and 250 N m (a large six-axis sensor's), stale after
/// 20 ms, frozen after 20 ms (for a sensor with noise), spike filter at 200 N; force rate
/// 100 kN/s over 10 ms; oscillation above 5 Hz, RMS over 50 ms and four swings within 0.25 s,
/// from 0.2 s after the switch
/// to force control; contact lost below 20 % of the reference for 2 ms.
pub mod defaults {
    /// Force range of the sensor per axis, N.
    pub const SENSOR_RANGE_N: f64 = 2500.0;
    /// Torque range of the sensor per axis, N m.
    pub const SENSOR_RANGE_NM: f64 = 250.0;
    /// Stale after, s.
    pub const STALE_S: f64 = 0.02;
    /// Frozen after, s.
    pub const FROZEN_S: f64 = 0.02;
    /// Spike filter threshold, N.
    pub const SPIKE_N: f64 = 200.0;
    /// Largest force rate, N/s.
    pub const MAX_FORCE_RATE_N_S: f64 = 100_000.0;
    /// Window of the force rate, s.
    pub const RATE_WINDOW_S: f64 = 0.01;
    /// Corner of the oscillation detector's high-pass, Hz.
    pub const OSCILLATION_HZ: f64 = 5.0;
    /// Time constant of the oscillation RMS, s.
    pub const OSCILLATION_WINDOW_S: f64 = 0.05;
    /// The oscillation detector starts this long after the switch, s.
    pub const OSCILLATION_ARM_S: f64 = 0.2;
    /// Window of the oscillation's swings, s (two cycles of 8 Hz).
    pub const OSCILLATION_SWING_WINDOW_S: f64 = 0.25;
    /// Contact lost below this share of the reference.
    pub const LOSS_FRACTION: f64 = 0.2;
    /// Contact lost after, s.
    pub const LOSS_S: f64 = 0.002;
    /// Largest force without force control, N.
    pub const MAX_FORCE_WITHOUT_FORCE_CONTROL_N: f64 = 300.0;
    /// How far past a joint limit a joint may go before the default check trips, rad or m:
    /// into an end stop's give. A joint resting on its stop (the SCARA's d3 at its top,
    /// where several trials start) presses micrometres in; 1 mm into the SCARA's d3 stop
    /// takes about 490 N.
    pub const JOINT_LIMIT_GIVE: f64 = 1e-3;
}

#[cfg(test)]
impl<const N: usize> SafetyLimits<f64, N> {
    /// The [`defaults`](Self::defaults) of the unit tests: joints in `[-1, 1]`, every effort
    /// limit `effort`, force reference `force_n`, a noiseless sensor.
    pub(crate) fn unit_joints(effort: f64, force_n: Option<f64>) -> Self {
        Self::defaults(
            SVector::repeat(-1.0),
            SVector::repeat(1.0),
            SVector::repeat(effort),
            force_n,
            0.0,
        )
    }
}
