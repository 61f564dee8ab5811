//! Full-state feedback with feedback linearization (thesis Section 4.3, eq. 4.25–4.37), with
//! the tracking law corrected (`docs/thesis.md`, erratum 7).
//!
//! The feedback-linearized plant is `M_linear qdd = u` (eq. 4.21), in state space
//! `x = [q; qd]`, `A = [0 I; 0 0]`, `B = [0; M_linear^-1]` (eq. 4.26–4.28). The thesis's
//! law `u = -K x + q_d` (eq. 4.29) adds a joint position to a torque and never feeds the
//! reference velocity back; the tracking law used here is
//!
//! ```text
//! u = M_linear qdd_d + K1 (q_d - q) + K2 (qd_d - qd),      K = [K1 K2]
//! ```
//!
//! so that the tracking error `e = x_d - x` obeys `e' = (A - B K) e` exactly when the model
//! is right: the closed-loop poles are the eigenvalues of `A - B K`. The torque is then
//! `tau = u + M_nonlinear(q) M_linear^-1 u + c + g = M(q) M_linear^-1 u + c + g`.

use super::mass_split::{linear_part, SplitKind};
use super::{Controller, ControllerInput};
use crate::model::{JointMatrix, JointVector, RobotModel};

/// The thesis's pole pattern for `n` joints: `2 n` poles `-8.0, -8.1, -8.2, ...` rad/s, each
/// `-(80 + k) / 10` (an exact quotient: for the SCARA's four joints the thesis's poles,
/// `robots::scara::thesis_setup::THESIS_FSF_POLES`, to the bit).
///
/// ```
/// use armdyn::control::fsf::fsf_poles;
/// assert_eq!(fsf_poles(4), vec![-8.0, -8.1, -8.2, -8.3, -8.4, -8.5, -8.6, -8.7]);
/// assert_eq!(fsf_poles(6).len(), 12);
/// ```
#[cfg(feature = "std")]
#[must_use]
pub fn fsf_poles(n: usize) -> std::vec::Vec<f64> {
    (0..2 * n).map(|k| -(80.0 + k as f64) / 10.0).collect()
}

/// How the gain matrix was designed (for reports).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FsfDesign {
    /// Pole placement.
    Place,
    /// Linear-quadratic regulator.
    Lqr,
}

/// Full-state feedback on the feedback-linearized plant, `K = [K1 K2]` in torque units
/// (N m/rad and N m s/rad, or N/m and N s/m).
#[derive(Clone, Debug)]
pub struct FullStateFeedback<const N: usize, R> {
    robot: R,
    m_linear: JointMatrix<N>,
    m_linear_inv: JointMatrix<N>,
    k1: JointMatrix<N>,
    k2: JointMatrix<N>,
    design: FsfDesign,
}

/// Errors of the gain design.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum FsfError {
    /// The pole list does not have `2 N` entries.
    #[error("pole placement needs {expected} poles, got {got}")]
    PoleCount {
        /// `2 N`.
        expected: usize,
        /// Given.
        got: usize,
    },
    /// A requested pole is not real, finite and negative.
    #[error(
        "pole {index} must be finite and negative (stable), got a non-negative or non-finite value"
    )]
    UnstablePole {
        /// Index in the list.
        index: usize,
    },
    /// `M_linear` is singular.
    #[error("M_linear is singular")]
    SingularMass,
}

impl<const N: usize, R: RobotModel<N>> FullStateFeedback<N, R> {
    /// Pole placement: joint `i` of the decoupled error dynamics gets the poles
    /// `poles[2 i]` and `poles[2 i + 1]`, i.e. `K = M_linear [diag(p p'), diag(-(p + p'))]`,
    /// which makes `A - B K = [0 I; -diag(p p') diag(p + p')]`, whose eigenvalues are exactly
    /// the requested poles. (The multi-input placement has many solutions; this one keeps the
    /// joints decoupled, which the thesis found `place()` did not, eq. 4.34–4.35.)
    ///
    /// # Errors
    ///
    /// [`FsfError`] for a wrong pole count, an unstable pole or a singular `M_linear`.
    pub fn place(robot: R, poles: &[f64]) -> Result<Self, FsfError> {
        if poles.len() != 2 * N {
            return Err(FsfError::PoleCount {
                expected: 2 * N,
                got: poles.len(),
            });
        }
        if let Some(index) = poles.iter().position(|p| !(p.is_finite() && *p < 0.0)) {
            return Err(FsfError::UnstablePole { index });
        }
        let m_linear = linear_part(&robot, SplitKind::ConstantPart);
        let a = JointVector::<N>::from_fn(|i, _| poles[2 * i] * poles[2 * i + 1]);
        let b = JointVector::<N>::from_fn(|i, _| -(poles[2 * i] + poles[2 * i + 1]));
        let k1 = m_linear * JointMatrix::from_diagonal(&a);
        let k2 = m_linear * JointMatrix::from_diagonal(&b);
        Self::with_gains(robot, m_linear, k1, k2, FsfDesign::Place)
    }

    /// Explicit gains `K = [k1 k2]` (torque units) for a given `M_linear`.
    ///
    /// # Errors
    ///
    /// [`FsfError::SingularMass`] if `m_linear` is singular.
    pub fn with_gains(
        robot: R,
        m_linear: JointMatrix<N>,
        k1: JointMatrix<N>,
        k2: JointMatrix<N>,
        design: FsfDesign,
    ) -> Result<Self, FsfError> {
        let m_linear_inv = m_linear.try_inverse().ok_or(FsfError::SingularMass)?;
        Ok(Self {
            robot,
            m_linear,
            m_linear_inv,
            k1,
            k2,
            design,
        })
    }

    /// Position block `K1` of the gain matrix.
    #[must_use]
    pub fn k1(&self) -> &JointMatrix<N> {
        &self.k1
    }

    /// Velocity block `K2` of the gain matrix.
    #[must_use]
    pub fn k2(&self) -> &JointMatrix<N> {
        &self.k2
    }

    /// `M_linear` (eq. 4.18).
    #[must_use]
    pub fn m_linear(&self) -> &JointMatrix<N> {
        &self.m_linear
    }

    /// How `K` was designed.
    #[must_use]
    pub fn design(&self) -> FsfDesign {
        self.design
    }
}

impl<const N: usize, R: RobotModel<N>> Controller<N> for FullStateFeedback<N, R> {
    fn name(&self) -> &'static str {
        match self.design {
            FsfDesign::Place => "fsf-place",
            FsfDesign::Lqr => "fsf-lqr",
        }
    }

    fn reset(&mut self) {}

    fn step(&mut self, input: &ControllerInput<'_, N>, _dt: f64) -> JointVector<N> {
        let e = input.target.q - input.q;
        let e_dot = input.target.qd - input.qd;
        let u = self.m_linear * input.target.qdd + self.k1 * e + self.k2 * e_dot;
        self.robot.mass_matrix(input.q) * (self.m_linear_inv * u)
            + self.robot.coriolis(input.q, input.qd)
            + self.robot.gravity(input.q)
    }
}

/// Weights of the LQR design of [`FullStateFeedback::lqr`]: cost
/// `int e^T Q e + u^T R u dt` with `e = [q_d - q; qd_d - qd]` (2N) and `u` in torque units.
#[cfg(feature = "std")]
#[derive(Clone, Debug)]
pub struct LqrWeights {
    /// State weight, 2N x 2N.
    pub q: nalgebra::DMatrix<f64>,
    /// Input weight, N x N.
    pub r: nalgebra::DMatrix<f64>,
}

#[cfg(feature = "std")]
impl LqrWeights {
    /// `Q = I`, `R = I` for `n` joints: the weights that reproduce the thesis's LQR gain on
    /// the SCARA (eq. 4.36), which is far too soft to track (about 0.5 rad/s of bandwidth on
    /// joint 1).
    #[must_use]
    pub fn identity(n: usize) -> Self {
        Self {
            q: nalgebra::DMatrix::identity(2 * n, 2 * n),
            r: nalgebra::DMatrix::identity(n, n),
        }
    }

    /// Weights on the commanded acceleration `M_linear^-1 u` instead of the torque:
    /// `Q = diag(omega^4 I, 2 omega^2 I)`, `R = M_linear^-T M_linear^-1`. Each joint's error then
    /// gets a critically damped pair of poles at `-omega` whatever its inertia (default
    /// `omega = 8.35` rad/s, the mean of the thesis's placement poles). `None` if `M_linear`
    /// is singular.
    #[must_use]
    pub fn acceleration_penalty<const N: usize>(
        m_linear: &JointMatrix<N>,
        omega: f64,
    ) -> Option<Self> {
        let mut q = nalgebra::DMatrix::zeros(2 * N, 2 * N);
        for i in 0..N {
            q[(i, i)] = omega.powi(4);
            q[(N + i, N + i)] = 2.0 * omega * omega;
        }
        let inv = m_linear.try_inverse()?;
        let r = inv.transpose() * inv;
        Some(Self {
            q,
            r: nalgebra::DMatrix::from_fn(N, N, |i, j| r[(i, j)]),
        })
    }
}

#[cfg(feature = "std")]
impl<const N: usize, R: RobotModel<N>> FullStateFeedback<N, R> {
    /// LQR on `A = [0 I; 0 0]`, `B = [0; M_linear^-1]` (eq. 4.26–4.28) with the given weights;
    /// returns the controller and the Riccati solution (for its residual).
    ///
    /// # Errors
    ///
    /// [`super::lqr::LqrError`] from the Riccati solve, or a singular `M_linear`.
    pub fn lqr(
        robot: R,
        weights: &LqrWeights,
    ) -> Result<(Self, super::lqr::LqrSolution), super::lqr::LqrError> {
        let m_linear = linear_part(&robot, SplitKind::ConstantPart);
        let (a, b) =
            linearized_plant(&m_linear).ok_or(super::lqr::LqrError::Singular("M_linear"))?;
        let sol = super::lqr::lqr(&a, &b, &weights.q, &weights.r)?;
        let k1 = JointMatrix::<N>::from_fn(|i, j| sol.k[(i, j)]);
        let k2 = JointMatrix::<N>::from_fn(|i, j| sol.k[(i, N + j)]);
        let ctrl = Self::with_gains(robot, m_linear, k1, k2, FsfDesign::Lqr)
            .map_err(|_| super::lqr::LqrError::Singular("M_linear"))?;
        Ok((ctrl, sol))
    }

    /// The closed-loop matrix `A - B K` of the linearized error dynamics (2N x 2N).
    #[must_use]
    pub fn closed_loop_matrix(&self) -> nalgebra::DMatrix<f64> {
        let (a, b) = linearized_plant(&self.m_linear).unwrap_or_else(|| {
            (
                nalgebra::DMatrix::zeros(2 * N, 2 * N),
                nalgebra::DMatrix::zeros(2 * N, N),
            )
        });
        let k = nalgebra::DMatrix::from_fn(N, 2 * N, |i, j| {
            if j < N {
                self.k1[(i, j)]
            } else {
                self.k2[(i, j - N)]
            }
        });
        a - b * k
    }
}

/// `A = [0 I; 0 0]`, `B = [0; M_linear^-1]` (eq. 4.26–4.28); `None` if `M_linear` is singular.
#[cfg(feature = "std")]
#[must_use]
pub fn linearized_plant<const N: usize>(
    m_linear: &JointMatrix<N>,
) -> Option<(nalgebra::DMatrix<f64>, nalgebra::DMatrix<f64>)> {
    let inv = m_linear.try_inverse()?;
    let mut a = nalgebra::DMatrix::zeros(2 * N, 2 * N);
    let mut b = nalgebra::DMatrix::zeros(2 * N, N);
    for i in 0..N {
        a[(i, N + i)] = 1.0;
        for j in 0..N {
            b[(N + i, j)] = inv[(i, j)];
        }
    }
    Some((a, b))
}
