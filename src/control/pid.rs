//! Decentralized PID (thesis Section 4.1, eq. 4.1 and 4.15).

use super::gains::PidGains;
use super::{Controller, ControllerInput};
use crate::model::JointVector;

/// Independent PID loops per joint: `tau = Kp e + Ki int(e) dt + Kd de/dt` (eq. 4.1), with
/// `e = q_d - q` and `de/dt = qd_d - qd`. No model terms: gravity and coupling are left to
/// the integral action.
///
/// The integral is accumulated by the rectangle rule at the control period.
///
/// ```
/// use armdyn::control::{pid::Pid, gains::PidGains, Controller};
/// use nalgebra::Vector4;
/// let gains = PidGains::from_poles(&Vector4::new(5.57, 1.12, 4.94, 0.0025), [-8.0, -9.0, -10.0]);
/// let pid = Pid::new(gains);
/// assert_eq!(pid.name(), "pid");
/// ```
#[derive(Clone, Debug)]
pub struct Pid<const N: usize> {
    gains: PidGains<N>,
    integral: JointVector<N>,
}

impl<const N: usize> Pid<N> {
    /// A PID with the given gains and a zero integrator.
    #[must_use]
    pub fn new(gains: PidGains<N>) -> Self {
        Self {
            gains,
            integral: JointVector::zeros(),
        }
    }

    /// The gains.
    #[must_use]
    pub fn gains(&self) -> &PidGains<N> {
        &self.gains
    }

    /// The PID law alone, advancing the integrator by `dt`.
    pub fn law(&mut self, e: &JointVector<N>, e_dot: &JointVector<N>, dt: f64) -> JointVector<N> {
        self.integral += e * dt;
        self.gains.kp.component_mul(e)
            + self.gains.ki.component_mul(&self.integral)
            + self.gains.kd.component_mul(e_dot)
    }

    /// Clears the integrator.
    pub fn reset_integral(&mut self) {
        self.integral = JointVector::zeros();
    }
}

impl<const N: usize> Controller<N> for Pid<N> {
    fn name(&self) -> &'static str {
        "pid"
    }

    fn reset(&mut self) {
        self.reset_integral();
    }

    /// The integral of the joint error (rad s or m s per joint).
    fn state_len(&self) -> usize {
        N
    }

    fn write_state(&self, out: &mut [f64]) {
        out[..N].copy_from_slice(self.integral.as_slice());
    }

    fn read_state(&mut self, x: &[f64]) {
        self.integral = JointVector::from_column_slice(&x[..N]);
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let e = input.target.q - input.q;
        let e_dot = input.target.qd - input.qd;
        self.law(&e, &e_dot, dt)
    }
}
