//! A task-space reference: the tool's full pose and its first two time derivatives.

use nalgebra::{UnitQuaternion, Vector3, Vector6};

use super::orientation;

/// The end-effector reference at one instant, base frame: position (m) and orientation,
/// linear velocity (m/s) and angular velocity (rad/s), linear acceleration (m/s^2) and
/// angular acceleration (rad/s^2), all in the base frame.
///
/// A robot that controls fewer than six task directions reads only its own: the SCARA
/// (`x, y, z, yaw`) reads the position, [`Self::yaw`] and the z components of the angular
/// terms.
///
/// # Example
///
/// ```
/// use armdyn::target::CartesianTarget;
/// use armdyn::target::orientation::from_rpy;
/// use nalgebra::Vector3;
///
/// let down = from_rpy(std::f64::consts::PI, 0.0, 0.0); // tool z along base -z
/// let target = CartesianTarget::at_rest(Vector3::new(0.4, 0.1, 0.3), down);
/// assert_eq!(target.angular_velocity, Vector3::zeros());
/// assert!((target.orientation * Vector3::z() + Vector3::z()).norm() < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CartesianTarget {
    /// Position of the end-effector frame origin, m.
    pub position: Vector3<f64>,
    /// Orientation of the end-effector frame.
    pub orientation: UnitQuaternion<f64>,
    /// Time derivative of `position`, m/s.
    pub velocity: Vector3<f64>,
    /// Angular velocity, base frame, rad/s: `d/dt R = [w]x R`.
    pub angular_velocity: Vector3<f64>,
    /// Second time derivative of `position`, m/s^2.
    pub acceleration: Vector3<f64>,
    /// Time derivative of `angular_velocity`, rad/s^2.
    pub angular_acceleration: Vector3<f64>,
}

impl CartesianTarget {
    /// A target at rest: the given position (m) and orientation, zero velocity and
    /// acceleration.
    #[must_use]
    pub fn at_rest(position: Vector3<f64>, orientation: UnitQuaternion<f64>) -> Self {
        Self {
            position,
            orientation,
            velocity: Vector3::zeros(),
            angular_velocity: Vector3::zeros(),
            acceleration: Vector3::zeros(),
            angular_acceleration: Vector3::zeros(),
        }
    }

    /// A target whose orientation is a rotation `yaw` (rad) about base z, turning at
    /// `yaw_rate` (rad/s) with `yaw_acceleration` (rad/s^2): the pose of a SCARA-like tool.
    ///
    /// ```
    /// use armdyn::target::CartesianTarget;
    /// use nalgebra::Vector3;
    /// let z = Vector3::zeros();
    /// let t = CartesianTarget::planar(Vector3::new(0.5, 0.1, 0.2), 0.3, z, 0.5, z, 0.0);
    /// assert!((t.yaw() - 0.3).abs() < 1e-15);
    /// assert_eq!(t.angular_velocity, Vector3::new(0.0, 0.0, 0.5));
    /// ```
    #[must_use]
    pub fn planar(
        position: Vector3<f64>,
        yaw: f64,
        velocity: Vector3<f64>,
        yaw_rate: f64,
        acceleration: Vector3<f64>,
        yaw_acceleration: f64,
    ) -> Self {
        Self {
            position,
            orientation: orientation::from_yaw(yaw),
            velocity,
            angular_velocity: Vector3::new(0.0, 0.0, yaw_rate),
            acceleration,
            angular_acceleration: Vector3::new(0.0, 0.0, yaw_acceleration),
        }
    }

    /// The yaw of the orientation, rad in `(-pi, pi]` ([`orientation::yaw`]).
    #[must_use]
    pub fn yaw(&self) -> f64 {
        orientation::yaw(&self.orientation)
    }

    /// The twist `[v; w]` (m/s, rad/s), ordered as the rows of the geometric Jacobian.
    #[must_use]
    pub fn twist(&self) -> Vector6<f64> {
        let (v, w) = (self.velocity, self.angular_velocity);
        Vector6::new(v.x, v.y, v.z, w.x, w.y, w.z)
    }

    /// The acceleration `[a; alpha]` (m/s^2, rad/s^2), ordered as the rows of the Jacobian.
    #[must_use]
    pub fn acceleration_twist(&self) -> Vector6<f64> {
        let (a, b) = (self.acceleration, self.angular_acceleration);
        Vector6::new(a.x, a.y, a.z, b.x, b.y, b.z)
    }
}

/// The pose part of a reference at one time: `t` (s), position (m) and orientation.
///
/// The unit of the sampled references and of the planners that read a reference at
/// discrete times.
///
/// ```
/// use armdyn::target::PoseSample;
/// use nalgebra::Vector3;
/// let s = PoseSample::with_yaw(0.5, Vector3::new(0.4, 0.0, 0.2), 0.25);
/// assert_eq!(s.t, 0.5);
/// assert!((s.yaw() - 0.25).abs() < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoseSample {
    /// Time, s.
    pub t: f64,
    /// End-effector position in the base frame, m.
    pub position: Vector3<f64>,
    /// End-effector orientation.
    pub orientation: UnitQuaternion<f64>,
}

impl PoseSample {
    /// A sample at time `t` (s) of position `position` (m) and orientation `orientation`.
    #[must_use]
    pub fn new(t: f64, position: Vector3<f64>, orientation: UnitQuaternion<f64>) -> Self {
        PoseSample {
            t,
            position,
            orientation,
        }
    }

    /// A sample whose orientation is `yaw` (rad) about base z.
    #[must_use]
    pub fn with_yaw(t: f64, position: Vector3<f64>, yaw: f64) -> Self {
        Self::new(t, position, orientation::from_yaw(yaw))
    }

    /// The pose part of `target`, stamped with time `t` (s).
    #[must_use]
    pub fn from_target(t: f64, target: &CartesianTarget) -> Self {
        Self::new(t, target.position, target.orientation)
    }

    /// The yaw of the orientation, rad in `(-pi, pi]`.
    #[must_use]
    pub fn yaw(&self) -> f64 {
        orientation::yaw(&self.orientation)
    }
}
