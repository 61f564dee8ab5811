//! PID with feedback linearization, decentralized (thesis Section 4.2, eq. 4.17–4.24) and
//! centralized (Section 4.3, eq. 4.38–4.39).

use super::gains::{MassRounding, PidGains};
use super::mass_split::{linear_part, SplitKind};
use super::pid::Pid;
use super::{Controller, ControllerInput};
use crate::model::{JointMatrix, JointVector, RobotModel};

/// `tau = u + M_nonlinear(q) qdd_cmd + c(q, qd) + g(q)` with `u` a PID on the joint error
/// (eq. 4.24), so that the closed loop is `M_linear qdd = u` (eq. 4.21).
///
/// The thesis's law uses the measured `qdd`, which makes an algebraic loop (the torque
/// depends on the acceleration it causes). Here `qdd_cmd = M_linear^-1 u`, the acceleration
/// the linearized plant is commanded to have: it needs no acceleration measurement and gives
/// exactly `M_linear qdd = u` when the model is right, since then
/// `tau = M(q) M_linear^-1 u + c + g`.
///
/// Gains: [`PidGains::from_poles`] on the diagonal of `M_linear` (eq. 4.22).
///
/// With acceleration feedforward ([`Self::with_acceleration_feedforward`], off in the thesis)
/// the commanded acceleration is `qdd_cmd = qdd_d + M_linear^-1 u`, so
/// `tau = M(q) (qdd_d + M_linear^-1 u) + c + g`: with a correct model the joint error obeys
/// `M_linear e'' = -u` whatever the reference's acceleration, so fast planned moves are
/// followed too.
#[derive(Clone, Debug)]
pub struct PidFeedbackLinearization<const N: usize, R> {
    robot: R,
    pid: Pid<N>,
    m_linear: JointMatrix<N>,
    m_linear_inv: JointMatrix<N>,
    kind: SplitKind,
    acceleration_feedforward: bool,
}

impl<const N: usize, R: RobotModel<N>> PidFeedbackLinearization<N, R> {
    /// The thesis's design method: `M_linear` from the model's constant part (`kind`), gains
    /// placing each joint's three poles at `poles` (rad/s) on its diagonal with the given
    /// rounding ([`PidGains::from_poles`]). `None` if `M_linear` is singular (not for a
    /// physical robot).
    #[must_use]
    pub fn with_poles(
        robot: R,
        kind: SplitKind,
        rounding: MassRounding,
        poles: [f64; 3],
    ) -> Option<Self> {
        let m_linear = linear_part(&robot, kind);
        let masses = rounding.apply(&m_linear.diagonal());
        Self::new(robot, m_linear, PidGains::from_poles(&masses, poles), kind)
    }

    /// Explicit `M_linear` and gains. `None` if `M_linear` is singular.
    #[must_use]
    pub fn new(
        robot: R,
        m_linear: JointMatrix<N>,
        gains: PidGains<N>,
        kind: SplitKind,
    ) -> Option<Self> {
        let m_linear_inv = m_linear.try_inverse()?;
        Some(Self {
            robot,
            pid: Pid::new(gains),
            m_linear,
            m_linear_inv,
            kind,
            acceleration_feedforward: false,
        })
    }

    /// Feeds the reference's joint acceleration forward (see the type's documentation).
    #[must_use]
    pub fn with_acceleration_feedforward(mut self, on: bool) -> Self {
        self.acceleration_feedforward = on;
        self
    }

    /// Whether the reference's acceleration is fed forward.
    #[must_use]
    pub fn acceleration_feedforward(&self) -> bool {
        self.acceleration_feedforward
    }

    /// The PID gains.
    #[must_use]
    pub fn gains(&self) -> &PidGains<N> {
        self.pid.gains()
    }

    /// `M_linear` (kg m^2, kg m, kg).
    #[must_use]
    pub fn m_linear(&self) -> &JointMatrix<N> {
        &self.m_linear
    }

    /// `M_nonlinear(q) = M(q) - M_linear` (eq. 4.19 / 4.39).
    #[must_use]
    pub fn m_nonlinear(&self, q: &JointVector<N>) -> JointMatrix<N> {
        self.robot.mass_matrix(q) - self.m_linear
    }
}

impl<const N: usize, R: RobotModel<N>> Controller<N> for PidFeedbackLinearization<N, R> {
    fn name(&self) -> &'static str {
        match self.kind {
            SplitKind::ConstantPart => "pid-fl",
            SplitKind::ConstantDiagonal => "pid-fl-central",
        }
    }

    fn reset(&mut self) {
        self.pid.reset_integral();
    }

    crate::control::pass_on_state!(pid);

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let e = input.target.q - input.q;
        let e_dot = input.target.qd - input.qd;
        let u = self.pid.law(&e, &e_dot, dt);
        let qdd_cmd = self.m_linear_inv * u;
        // M, c and g in one call: the generated robots share their sin/cos.
        let (m, bias) = self.robot.mass_matrix_and_bias(input.q, input.qd);
        if self.acceleration_feedforward {
            return m * (input.target.qdd + qdd_cmd) + bias;
        }
        u + (m - self.m_linear) * qdd_cmd + bias
    }
}
