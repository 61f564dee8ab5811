//! References: Cartesian paths of the end effector and force profiles (thesis Appendix B).
//!
//! - [`CartesianTarget`]: position, yaw and their first two time derivatives at one instant.
//! - [`CartesianTrajectory`]: a reference defined for `t` in `[0, duration]`.
//! - `thesis`: the position test (eq. 4.16), contact test (B.3) and three-zone trials.
//! - `sampled`: a user reference given as samples (CSV), interpolated.
//! - `force`: desired contact-force profiles (B.3).

use nalgebra::Vector3;

/// The end-effector reference at one instant, base frame.
///
/// `position` in m, `yaw` (rotation about the base z axis, the SCARA's `phi = q1 + q2 - q4`)
/// in rad, with their velocities (m/s, rad/s) and accelerations (m/s^2, rad/s^2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CartesianTarget {
    /// Position of the end-effector frame origin, m.
    pub position: Vector3<f64>,
    /// Yaw about the base z axis, rad.
    pub yaw: f64,
    /// Time derivative of `position`, m/s.
    pub velocity: Vector3<f64>,
    /// Time derivative of `yaw`, rad/s.
    pub yaw_rate: f64,
    /// Second time derivative of `position`, m/s^2.
    pub acceleration: Vector3<f64>,
    /// Second time derivative of `yaw`, rad/s^2.
    pub yaw_acceleration: f64,
}

/// A Cartesian end-effector reference over `[0, duration]` seconds.
pub trait CartesianTrajectory {
    /// Length of the reference, s.
    fn duration(&self) -> f64;
    /// The reference at time `t` (s); `t` outside `[0, duration]` is clamped.
    fn at(&self, t: f64) -> CartesianTarget;
}
