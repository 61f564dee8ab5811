//! Partial derivatives of the equation of motion, from the generated functions.
//!
//! ```text
//! tau = ID(q, qd, qdd) + J(q)^T f_ext          inverse dynamics
//! qdd = FD(q, qd, tau - J(q)^T f_ext)          forward dynamics
//! ```
//!
//! [`DynamicsDerivatives`] gives the derivatives without a wrench, generated exactly by the
//! generator (`d tau/d q`, `d tau/d qd`, `d tau/d qdd = M`; `d qdd/d q`, `d qdd/d qd`,
//! `d qdd/d tau = M^-1`; `d J/d q_k`), the same quantities as Pinocchio's
//! `computeRNEADerivatives` and `computeABADerivatives`. The wrench terms compose from them:
//!
//! ```text
//! d tau/d q  += W(q, f),   d tau/d f  = J^T,          W[:, k] = (d J/d q_k)^T f
//! d qdd/d q  = FD_q(q, qd, tau - J^T f) - M^-1 W,      d qdd/d f = -M^-1 J^T
//! ```
//!
//! ([`inverse_dynamics_derivatives_with_wrench`], [`forward_dynamics_derivatives_with_wrench`]).
//! Nothing allocates; everything works in `no_std`.

use nalgebra::SMatrix;

use super::error::ModelError;
use super::robot::RobotModel;
use super::types::{Jacobian, JointMatrix, JointVector, Wrench};

/// `d tau / d (q, qd, qdd)` of inverse dynamics at one state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InverseDynamicsDerivatives<const N: usize> {
    /// `d tau / d q` (N m/rad; N/m, N m/m, N/rad for prismatic rows or columns).
    pub dtau_dq: JointMatrix<N>,
    /// `d tau / d qd` (N m s/rad, N s/m).
    pub dtau_dqd: JointMatrix<N>,
    /// `d tau / d qdd = M(q)` (kg m^2, kg m, kg).
    pub mass_matrix: JointMatrix<N>,
}

/// `d qdd / d (q, qd, tau)` of forward dynamics at one state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForwardDynamicsDerivatives<const N: usize> {
    /// `d qdd / d q` (1/s^2).
    pub dqdd_dq: JointMatrix<N>,
    /// `d qdd / d qd` (1/s).
    pub dqdd_dqd: JointMatrix<N>,
    /// `d qdd / d tau = M(q)^-1` (1/(kg m^2), 1/kg).
    pub mass_matrix_inverse: JointMatrix<N>,
}

/// The derivatives of a robot's dynamics (implemented by every generated robot).
pub trait DynamicsDerivatives<const N: usize>: RobotModel<N> {
    /// `d tau / d q`, `d tau / d qd` and `M` of [`RobotModel::inverse_dynamics`] at
    /// `(q, qd, qdd)`.
    fn inverse_dynamics_derivatives(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        qdd: &JointVector<N>,
    ) -> InverseDynamicsDerivatives<N>;

    /// `d qdd / d q`, `d qdd / d qd` and `M^-1` of [`RobotModel::forward_dynamics`] at
    /// `(q, qd, tau)`: `d qdd/d x = -M^-1 d ID/d x` at `qdd = FD(q, qd, tau)`.
    ///
    /// # Errors
    ///
    /// [`ModelError::NonFinite`] if a result is not finite (an input was not, or `M` is
    /// singular).
    fn forward_dynamics_derivatives(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        tau: &JointVector<N>,
    ) -> Result<ForwardDynamicsDerivatives<N>, ModelError>;

    /// `d J / d q_k` for each joint k (entry k), of [`RobotModel::jacobian`]: m/rad in the
    /// linear rows, 1/rad in the angular ones (per m for a prismatic joint k).
    fn jacobian_derivatives(&self, q: &JointVector<N>) -> [Jacobian<N>; N];
}

/// `W(q, f)`: column k is `(d J/d q_k)^T f`, the derivative of `J(q)^T f` with respect to q
/// at a fixed wrench `f` (base frame, `[fx fy fz tx ty tz]`, N and N m).
pub fn wrench_torque_derivative<const N: usize, R: DynamicsDerivatives<N>>(
    robot: &R,
    q: &JointVector<N>,
    f_ext: &Wrench,
) -> JointMatrix<N> {
    let dj = robot.jacobian_derivatives(q);
    JointMatrix::<N>::from_fn(|i, k| (0..6).map(|r| dj[k][(r, i)] * f_ext[r]).sum())
}

/// The derivatives of `tau = ID(q, qd, qdd) + J(q)^T f_ext`, with `d tau / d f_ext = J^T`.
pub fn inverse_dynamics_derivatives_with_wrench<const N: usize, R: DynamicsDerivatives<N>>(
    robot: &R,
    q: &JointVector<N>,
    qd: &JointVector<N>,
    qdd: &JointVector<N>,
    f_ext: &Wrench,
) -> (InverseDynamicsDerivatives<N>, SMatrix<f64, N, 6>) {
    let mut d = robot.inverse_dynamics_derivatives(q, qd, qdd);
    d.dtau_dq += wrench_torque_derivative(robot, q, f_ext);
    (d, robot.jacobian(q).transpose())
}

/// The derivatives of `qdd = FD(q, qd, tau - J(q)^T f_ext)`, with
/// `d qdd / d f_ext = -M^-1 J^T` (N x 6, second value).
///
/// # Errors
///
/// As [`DynamicsDerivatives::forward_dynamics_derivatives`].
pub fn forward_dynamics_derivatives_with_wrench<const N: usize, R: DynamicsDerivatives<N>>(
    robot: &R,
    q: &JointVector<N>,
    qd: &JointVector<N>,
    tau: &JointVector<N>,
    f_ext: &Wrench,
) -> Result<(ForwardDynamicsDerivatives<N>, SMatrix<f64, N, 6>), ModelError> {
    let jt = robot.jacobian(q).transpose();
    let mut d = robot.forward_dynamics_derivatives(q, qd, &(tau - jt * f_ext))?;
    d.dqdd_dq -= d.mass_matrix_inverse * wrench_torque_derivative(robot, q, f_ext);
    let dqdd_df = -(d.mass_matrix_inverse * jt);
    Ok((d, dqdd_df))
}
