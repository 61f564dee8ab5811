//! Computed torque (inverse dynamics control), the textbook reference for Chapter 4.

use super::{Controller, ControllerInput};
use crate::model::{JointVector, RobotModel};

/// `tau = M(q) (qdd_d + Kp e + Kd de/dt) + c(q, qd) + g(q)`: with a correct model every joint
/// error obeys `e'' + Kd e' + Kp e = 0`.
///
/// Default gains: a critically damped pair at `omega` rad/s per joint, `Kp = omega^2`,
/// `Kd = 2 omega` (1/s^2 and 1/s: they multiply accelerations, not torques).
#[derive(Clone, Debug)]
pub struct ComputedTorque<const N: usize, R> {
    robot: R,
    kp: JointVector<N>,
    kd: JointVector<N>,
}

impl<const N: usize, R: RobotModel<N>> ComputedTorque<N, R> {
    /// Critically damped error dynamics with natural frequency `omega` (rad/s) on every joint.
    #[must_use]
    pub fn critically_damped(robot: R, omega: f64) -> Self {
        Self::new(
            robot,
            JointVector::repeat(omega * omega),
            JointVector::repeat(2.0 * omega),
        )
    }

    /// Explicit gains, 1/s^2 and 1/s.
    #[must_use]
    pub fn new(robot: R, kp: JointVector<N>, kd: JointVector<N>) -> Self {
        Self { robot, kp, kd }
    }

    /// Position gains, 1/s^2.
    #[must_use]
    pub fn kp(&self) -> &JointVector<N> {
        &self.kp
    }

    /// Velocity gains, 1/s.
    #[must_use]
    pub fn kd(&self) -> &JointVector<N> {
        &self.kd
    }
}

impl<const N: usize, R: RobotModel<N>> Controller<N> for ComputedTorque<N, R> {
    fn name(&self) -> &'static str {
        "computed-torque"
    }

    fn reset(&mut self) {}

    fn step(&mut self, input: &ControllerInput<'_, N>, _dt: f64) -> JointVector<N> {
        let e = input.target.q - input.q;
        let e_dot = input.target.qd - input.qd;
        let v = input.target.qdd + self.kp.component_mul(&e) + self.kd.component_mul(&e_dot);
        self.robot.inverse_dynamics(input.q, input.qd, &v)
    }
}
