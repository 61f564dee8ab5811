//! References: Cartesian paths of the end effector and force profiles (thesis Appendix B).
//!
//! - [`CartesianTarget`]: position, yaw and their first two time derivatives at one instant.
//! - [`CartesianTrajectory`]: a reference defined for `t` in `[0, duration]`.
//! - [`thesis`]: the position test (eq. 4.16), contact test (B.3) and three-zone trials, with
//!   analytic derivatives.
//! - [`force`]: desired contact-force profiles (B.3).
//! - `sampled` (feature `std`): a user reference given as samples (CSV), interpolated.
//! - [`PoseSample`] and `sample` (feature `std`): a reference read at discrete times, as
//!   the workspace planner ([`crate::kinematics::ScaraGeometry::plan_elbows`]) wants it.

use nalgebra::Vector3;

pub mod force;
#[cfg(feature = "std")]
pub mod force_csv;
#[cfg(feature = "std")]
pub mod joint_csv;
#[cfg(feature = "std")]
pub mod pause;
#[cfg(feature = "std")]
pub mod sampled;
pub mod thesis;
#[cfg(feature = "std")]
pub mod waypoints;

pub use force::ForceProfile;
#[cfg(feature = "std")]
pub use joint_csv::{JointCsvError, JointReference};
#[cfg(feature = "std")]
pub use sampled::{CsvError, SampledError, SampledTrajectory};
pub use thesis::{ContactTest, PositionTest, ThreeZone};

/// The end-effector reference at one instant, base frame.
///
/// `position` in m, `yaw` (rotation about the base z axis, the SCARA's `phi = q1 + q2 - q4`)
/// in rad, with their velocities (m/s, rad/s) and accelerations (m/s^2, rad/s^2).
///
/// # Example
///
/// ```
/// use scara::trajectory::{CartesianTarget, CartesianTrajectory, PositionTest};
///
/// let target: CartesianTarget = PositionTest::new().at(0.0);
/// // Eq. 4.16 starts with the arm stretched along x, 0.25 m above the base plane.
/// assert!((target.position.x - 0.8).abs() < 1e-15);
/// assert_eq!(target.yaw, 0.0);
/// ```
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

impl CartesianTarget {
    /// A target at rest: the given position (m) and yaw (rad), zero velocity and acceleration.
    ///
    /// ```
    /// use scara::trajectory::CartesianTarget;
    /// use nalgebra::Vector3;
    ///
    /// let target = CartesianTarget::at_rest(Vector3::new(0.5, 0.1, 0.2), 0.3);
    /// assert_eq!(target.velocity, Vector3::zeros());
    /// assert_eq!(target.yaw_acceleration, 0.0);
    /// ```
    pub fn at_rest(position: Vector3<f64>, yaw: f64) -> Self {
        CartesianTarget {
            position,
            yaw,
            velocity: Vector3::zeros(),
            yaw_rate: 0.0,
            acceleration: Vector3::zeros(),
            yaw_acceleration: 0.0,
        }
    }
}

/// A Cartesian end-effector reference over `[0, duration]` seconds.
///
/// # Example
///
/// ```
/// use scara::trajectory::{CartesianTrajectory, ThreeZone};
///
/// let reference = ThreeZone::new();
/// assert_eq!(reference.duration(), 10.0);
/// // Times past the end are clamped: the reference holds its final value.
/// assert_eq!(reference.at(12.0), reference.at(10.0));
/// ```
pub trait CartesianTrajectory {
    /// Length of the reference, s.
    fn duration(&self) -> f64;
    /// The reference at time `t` (s); `t` outside `[0, duration]` is clamped.
    fn at(&self, t: f64) -> CartesianTarget;
}

#[cfg(feature = "std")]
impl<T: CartesianTrajectory + ?Sized> CartesianTrajectory for std::boxed::Box<T> {
    fn duration(&self) -> f64 {
        (**self).duration()
    }

    fn at(&self, t: f64) -> CartesianTarget {
        (**self).at(t)
    }
}

/// The pose part of a reference at one time: `t` (s), position (m) and yaw (rad).
///
/// The unit of the sampled reference ([`SampledTrajectory`]) and of the workspace planner
/// ([`crate::kinematics::ScaraGeometry::plan_elbows`]).
///
/// # Example
///
/// ```
/// use scara::trajectory::{CartesianTrajectory, PoseSample, ContactTest};
///
/// let reference = ContactTest::thesis();
/// let sample = PoseSample::from_target(2.0, &reference.at(2.0));
/// // At j = 0.2 the contact test reaches the surface, z = z_rs = 0.13 m.
/// assert!((sample.position.z - 0.13).abs() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoseSample {
    /// Time, s.
    pub t: f64,
    /// End-effector position in the base frame, m.
    pub position: Vector3<f64>,
    /// Yaw about the base z axis, rad.
    pub yaw: f64,
}

impl PoseSample {
    /// A sample at time `t` (s) of position `position` (m) and yaw `yaw` (rad).
    ///
    /// ```
    /// use scara::trajectory::PoseSample;
    /// use nalgebra::Vector3;
    /// let s = PoseSample::new(0.5, Vector3::new(0.4, 0.0, 0.2), 0.0);
    /// assert_eq!(s.t, 0.5);
    /// ```
    pub fn new(t: f64, position: Vector3<f64>, yaw: f64) -> Self {
        PoseSample { t, position, yaw }
    }

    /// The pose part of `target`, stamped with time `t` (s).
    ///
    /// ```
    /// use scara::trajectory::{CartesianTarget, PoseSample};
    /// use nalgebra::Vector3;
    /// let target = CartesianTarget::at_rest(Vector3::new(0.4, 0.1, 0.2), 0.25);
    /// let s = PoseSample::from_target(1.0, &target);
    /// assert_eq!((s.position, s.yaw), (target.position, 0.25));
    /// ```
    pub fn from_target(t: f64, target: &CartesianTarget) -> Self {
        PoseSample {
            t,
            position: target.position,
            yaw: target.yaw,
        }
    }
}

/// Reads `reference` every `dt` seconds from 0 to its duration, both ends included.
///
/// The times are `k dt` for `k = 0, 1, ...` while `k dt` is below the duration (with a
/// relative slack of 1e-9 so that `10 / 0.005` gives exactly 2001 samples), then the
/// duration itself. A non-positive or non-finite `dt`, or a non-finite duration, gives the
/// single sample at `t = 0`.
///
/// # Example
///
/// ```
/// use scara::trajectory::{sample, PositionTest};
///
/// let samples = sample(&PositionTest::new(), 0.005);
/// assert_eq!(samples.len(), 2001); // the thesis's 0.005 s grid over T = 10 s, plus t = T
/// assert_eq!(samples[2000].t, 10.0);
/// ```
#[cfg(feature = "std")]
pub fn sample<R: CartesianTrajectory + ?Sized>(reference: &R, dt: f64) -> Vec<PoseSample> {
    let duration = reference.duration();
    let mut out = Vec::new();
    out.push(PoseSample::from_target(0.0, &reference.at(0.0)));
    if !(dt > 0.0 && dt.is_finite() && duration.is_finite() && duration > 0.0) {
        return out;
    }
    let mut k: u64 = 1;
    loop {
        let t = k as f64 * dt;
        if t >= duration * (1.0 - 1e-9) {
            break;
        }
        out.push(PoseSample::from_target(t, &reference.at(t)));
        k += 1;
    }
    out.push(PoseSample::from_target(duration, &reference.at(duration)));
    out
}
