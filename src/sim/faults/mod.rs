//! Faults injected into a simulated run, each from a start time for a duration:
//!
//! - in the force sensor's readings ([`FaultySensor`]): dropout, frozen, NaN, infinite and
//!   out-of-range readings, a spike, a bias jump, a noise burst;
//! - in the environment ([`FaultyEnvironment`]): a surface that ends (an edge across the
//!   patch), a stiffness step, a payload held by the tool and dropped;
//! - in the plant ([`PlantFaults`], part of [`SimConfig`](super::SimConfig)): an actuator
//!   delivering a share of its torque, a control period delayed by a number of plant
//!   steps, and jitter of the sampling instants.

mod environment;
mod sensor;

pub use environment::{FaultyEnvironment, SurfaceEdge};
pub use sensor::{FaultySensor, SensorFault, SensorFaultKind, MAX_SENSOR_FAULTS};

/// A time window `[start_s, start_s + duration_s)`, s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    /// Start, s.
    pub start_s: f64,
    /// Length, s (`f64::INFINITY`: to the end of the run).
    pub duration_s: f64,
}

impl Window {
    /// Whether `t` (s) is inside.
    #[must_use]
    pub fn contains(&self, t: f64) -> bool {
        t >= self.start_s && t - self.start_s < self.duration_s
    }
}

/// Actuators delivering `scale` of the commanded torque (after saturation) on the joints of
/// `joints` (bit `i`: joint `i`) during `window`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ActuatorFault {
    /// When.
    pub window: Window,
    /// Share delivered, in `[0, 1]`.
    pub scale: f64,
    /// The joints (bit mask).
    pub joints: u32,
}

/// During `window`, each torque reaches the plant `plant_steps` plant steps after it was
/// computed (the previous one is held meanwhile).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DelayFault {
    /// When (by the time the torque was computed).
    pub window: Window,
    /// Delay, plant steps (at most [`MAX_DELAY_STEPS`]).
    pub plant_steps: usize,
}

/// Most plant steps a torque can be delayed by.
pub const MAX_DELAY_STEPS: usize = 64;

/// The sampling instants off their grid by a uniform draw in `[-max_s, max_s]` each,
/// rounded to the plant step (a seeded xoshiro256++: reproducible); the controller still
/// assumes its nominal period.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JitterFault {
    /// Largest offset, s (less than half the control period).
    pub max_s: f64,
    /// Seed.
    pub seed: u64,
}

/// The plant's faults (none by default).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PlantFaults {
    /// A weak actuator.
    pub actuator: Option<ActuatorFault>,
    /// A delayed control period.
    pub delay: Option<DelayFault>,
    /// Sampling jitter.
    pub jitter: Option<JitterFault>,
}

impl PlantFaults {
    /// The share of joint `i`'s torque delivered at `t`.
    #[must_use]
    pub fn actuator_scale(&self, t: f64, i: usize) -> f64 {
        match self.actuator {
            Some(a) if a.window.contains(t) && a.joints & (1 << i) != 0 => a.scale,
            _ => 1.0,
        }
    }

    /// The delay of a torque computed at `t`, plant steps.
    #[must_use]
    pub fn delay_steps(&self, t: f64) -> usize {
        match self.delay {
            Some(d) if d.window.contains(t) => d.plant_steps.min(MAX_DELAY_STEPS),
            _ => 0,
        }
    }
}
