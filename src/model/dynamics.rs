//! The equation of motion, both ways (thesis Section 3.3, eq. 3.67–3.71).
//!
//! ```text
//! tau = M(q) qdd + c(q, qd) + g(q) + tau_ext,        tau_ext = J(q)^T f_ext
//! ```
//!
//! `f_ext` is the wrench the end effector exerts on the environment (base frame,
//! `[fx fy fz tx ty tz]`), so pushing on a surface costs torque. The thesis's eq. 3.70/3.71
//! print the opposite sign for `J^T f_ext`; this is the corrected form (`docs/thesis.md`,
//! erratum 3).

use super::error::ModelError;
use super::robot::RobotModel;
use super::types::{JointVector, Wrench};

fn check_finite<const N: usize>(what: &'static str, v: &JointVector<N>) -> Result<(), ModelError> {
    match v.iter().position(|x| !x.is_finite()) {
        Some(index) => Err(ModelError::NonFinite {
            what,
            index,
            value: v[index],
        }),
        None => Ok(()),
    }
}

/// Forward dynamics: the joint accelerations for given torques,
/// `qdd = M(q)^-1 (tau - c(q, qd) - g(q) - tau_ext)` (thesis eq. 3.70/3.71 with the sign of
/// the contact term corrected).
///
/// - `q`, `qd`: joint positions (rad or m) and velocities (rad/s or m/s).
/// - `tau`: actuator torques/forces (N m or N).
/// - `tau_ext`: the joint-space effect of the external wrench, `J(q)^T f_ext` (N m or N);
///   see [`external_joint_torque`]. Zero in free motion.
///
/// Returns `qdd` in rad/s^2 or m/s^2, computed by [`RobotModel::forward_dynamics`] of
/// `tau - tau_ext`: the generated function for the generated robots (an unrolled sparse
/// `L^T D L` factorisation of `M`), a fixed-size Cholesky solve otherwise. Nothing
/// allocates.
///
/// # Errors
///
/// [`ModelError::NonFinite`] if an input holds NaN or an infinity, or the result does;
/// [`ModelError::NotPositiveDefinite`] if `M(q)` is not positive definite (not for a
/// physical robot at finite `q`; reported by the Cholesky path).
///
/// # Example
///
/// ```
/// use armdyn::model::{forward_dynamics, inverse_dynamics, Planar2};
/// use nalgebra::Vector2;
///
/// let (q, qd, tau) = (Vector2::new(0.3, -0.2), Vector2::new(1.0, 0.5), Vector2::new(2.0, -1.0));
/// let qdd = forward_dynamics(&Planar2, &q, &qd, &tau, &Vector2::zeros()).unwrap();
/// let back = inverse_dynamics(&Planar2, &q, &qd, &qdd, &Vector2::zeros());
/// assert!((back - tau).norm() < 1e-12);
/// ```
#[inline]
pub fn forward_dynamics<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &JointVector<N>,
    qd: &JointVector<N>,
    tau: &JointVector<N>,
    tau_ext: &JointVector<N>,
) -> Result<JointVector<N>, ModelError> {
    robot.forward_dynamics(q, qd, &net_torque(q, qd, tau, tau_ext)?)
}

/// `tau - tau_ext`, once every input is checked finite (the checks of [`forward_dynamics`]).
fn net_torque<const N: usize>(
    q: &JointVector<N>,
    qd: &JointVector<N>,
    tau: &JointVector<N>,
    tau_ext: &JointVector<N>,
) -> Result<JointVector<N>, ModelError> {
    check_finite("q", q)?;
    check_finite("qd", qd)?;
    check_finite("tau", tau)?;
    check_finite("tau_ext", tau_ext)?;
    Ok(tau - tau_ext)
}

/// Forward dynamics as [`forward_dynamics`], always by assembling `M`, `c` and `g` and
/// solving with a fixed-size Cholesky factorisation: the reference path that the generated
/// forward dynamics is tested against.
///
/// # Errors
///
/// As [`forward_dynamics`].
///
/// # Example
///
/// ```
/// use armdyn::model::{forward_dynamics, forward_dynamics_cholesky, Scara};
/// use nalgebra::Vector4;
///
/// let (q, qd) = (Vector4::new(0.3, 0.8, 0.2, 0.1), Vector4::new(0.2, -0.1, 0.05, 0.3));
/// let (tau, z) = (Vector4::new(5.0, -2.0, -40.0, 0.1), Vector4::zeros());
/// let a = forward_dynamics(&Scara, &q, &qd, &tau, &z).unwrap();
/// let b = forward_dynamics_cholesky(&Scara, &q, &qd, &tau, &z).unwrap();
/// assert!((a - b).norm() <= 1e-12 * b.norm());
/// ```
pub fn forward_dynamics_cholesky<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &JointVector<N>,
    qd: &JointVector<N>,
    tau: &JointVector<N>,
    tau_ext: &JointVector<N>,
) -> Result<JointVector<N>, ModelError> {
    robot.forward_dynamics_by_cholesky(q, qd, &net_torque(q, qd, tau, tau_ext)?)
}

/// Inverse dynamics: the torques that produce given accelerations,
/// `tau = M(q) qdd + c(q, qd) + g(q) + tau_ext` (thesis eq. 3.67/3.68 with the contact term
/// of Section 3.3).
///
/// Units as in [`forward_dynamics`]; `qdd` in rad/s^2 or m/s^2, result in N m or N.
/// Uses [`RobotModel::inverse_dynamics`] (recursive Newton–Euler for the generated robots).
/// Inputs are not checked: NaN in gives NaN out.
///
/// # Example
///
/// ```
/// use armdyn::model::{inverse_dynamics, RobotModel, Scara};
/// use nalgebra::SVector;
///
/// let q = SVector::<f64, 4>::new(0.0, 0.5, 0.2, 0.0);
/// let z = SVector::<f64, 4>::zeros();
/// // At rest, the torque is the gravity term alone: 9.8 (m3 + m4) on the prismatic joint.
/// let tau = inverse_dynamics(&Scara, &q, &z, &z, &z);
/// assert!((tau[2] + 9.8 * (4.03 + 0.91)).abs() < 1e-9);
/// ```
pub fn inverse_dynamics<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &JointVector<N>,
    qd: &JointVector<N>,
    qdd: &JointVector<N>,
    tau_ext: &JointVector<N>,
) -> JointVector<N> {
    robot.inverse_dynamics(q, qd, qdd) + tau_ext
}

/// The joint torques `J(q)^T f_ext` (N m or N) that balance a wrench `f_ext` the end
/// effector exerts on the environment (base frame, `[fx fy fz tx ty tz]`, N and N m, at
/// the origin of the last DH frame).
///
/// # Example
///
/// ```
/// use armdyn::model::{external_joint_torque, Scara, Wrench};
/// use nalgebra::SVector;
///
/// // Pushing down (-z) with 200 N loads the prismatic joint (whose axis points down).
/// let q = SVector::<f64, 4>::new(0.0, 0.5, 0.2, 0.0);
/// let tau_ext = external_joint_torque(&Scara, &q, &Wrench::new(0.0, 0.0, -200.0, 0.0, 0.0, 0.0));
/// assert!((tau_ext[2] - 200.0).abs() < 1e-9);
/// ```
pub fn external_joint_torque<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &JointVector<N>,
    f_ext: &Wrench,
) -> JointVector<N> {
    robot.jacobian(q).transpose() * f_ext
}
