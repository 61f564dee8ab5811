//! Any robot with its inertial parameters given at run time: the generated parametric model
//! (`armdyn_generated::<robot>::parametric`) behind [`RobotModel`], for a plant whose
//! parameters differ from the description's or a controller that uses identified ones.
//!
//! The standard parameters are 10 per link, `[m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz,
//! Izz]` (kg, kg m, kg m^2; inertia about the link frame's origin, link-frame axes), links 1
//! to N in order. The kinematics do not depend on them and come from the robot itself.

use super::error::ModelError;
use super::robot::RobotModel;
use super::types::{JointMatrix, JointVector};

/// Standard inertial parameters per link.
pub const PARAMETERS_PER_LINK: usize = 10;

/// A robot whose generated model also exists with its inertial parameters as an input: every
/// robot of the registry and every type of [`robot_type!`](crate::robot_type).
pub trait ParametricModel<const N: usize>: RobotModel<N> + Copy + Default + 'static {
    /// The `10 N` standard parameters, `[f64; 10 * N]`.
    type Parameters: Copy
        + core::fmt::Debug
        + PartialEq
        + Send
        + Sync
        + AsRef<[f64]>
        + AsMut<[f64]>
        + 'static;

    /// The description's standard parameters.
    fn standard_parameters() -> Self::Parameters;

    /// `params` (exactly `10 N` numbers) as the parameter array; `None` for another length.
    fn parameters_from(params: &[f64]) -> Option<Self::Parameters>;

    /// `M(q)` for parameters `p`.
    fn mass_matrix_with(q: &JointVector<N>, p: &Self::Parameters) -> JointMatrix<N>;
    /// `C(q, qd)` for parameters `p`.
    fn coriolis_matrix_with(
        q: &JointVector<N>,
        qd: &JointVector<N>,
        p: &Self::Parameters,
    ) -> JointMatrix<N>;
    /// `c(q, qd)` for parameters `p`.
    fn coriolis_with(
        q: &JointVector<N>,
        qd: &JointVector<N>,
        p: &Self::Parameters,
    ) -> JointVector<N>;
    /// `g(q)` for parameters `p`.
    fn gravity_with(q: &JointVector<N>, p: &Self::Parameters) -> JointVector<N>;
    /// Inverse dynamics for parameters `p`.
    fn inverse_dynamics_with(
        q: &JointVector<N>,
        qd: &JointVector<N>,
        qdd: &JointVector<N>,
        p: &Self::Parameters,
    ) -> JointVector<N>;
    /// Forward dynamics for parameters `p` (the generated unrolled solve; not checked).
    fn forward_dynamics_with(
        q: &JointVector<N>,
        qd: &JointVector<N>,
        tau: &JointVector<N>,
        p: &Self::Parameters,
    ) -> JointVector<N>;
}

/// Robot `R`'s kinematics with dynamics from a parameter vector.
///
/// With the description's parameters ([`Self::nominal`]) it equals `R` to rounding (the
/// parametric functions evaluate the same model in another order of operations).
///
/// ```
/// use armdyn::model::{Parametric, RobotModel, Ur5};
/// use nalgebra::SVector;
/// let q = SVector::from([0.2, -0.4, 0.15, 0.3, -0.2, 0.1]);
/// let m = Parametric::nominal(Ur5).mass_matrix(&q);
/// assert!((m - Ur5.mass_matrix(&q)).norm() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parametric<const N: usize, R: ParametricModel<N>> {
    robot: R,
    params: R::Parameters,
}

impl<const N: usize, R: ParametricModel<N>> Parametric<N, R> {
    /// `robot` with parameters `params`.
    #[must_use]
    pub fn new(robot: R, params: R::Parameters) -> Self {
        Self { robot, params }
    }

    /// `robot` with the description's parameters.
    #[must_use]
    pub fn nominal(robot: R) -> Self {
        Self::new(robot, R::standard_parameters())
    }

    /// The parameters.
    #[must_use]
    pub fn parameters(&self) -> &R::Parameters {
        &self.params
    }

    /// The robot whose kinematics it has.
    #[must_use]
    pub fn robot(&self) -> &R {
        &self.robot
    }
}

impl<const N: usize, R: ParametricModel<N>> RobotModel<N> for Parametric<N, R> {
    kinematics_of_the_wrapped_robot!(R, robot, R::GRAVITY);

    #[inline]
    fn mass_matrix(&self, q: &JointVector<N>) -> JointMatrix<N> {
        R::mass_matrix_with(q, &self.params)
    }
    #[inline]
    fn coriolis_matrix(&self, q: &JointVector<N>, qd: &JointVector<N>) -> JointMatrix<N> {
        R::coriolis_matrix_with(q, qd, &self.params)
    }
    #[inline]
    fn coriolis(&self, q: &JointVector<N>, qd: &JointVector<N>) -> JointVector<N> {
        R::coriolis_with(q, qd, &self.params)
    }
    #[inline]
    fn gravity(&self, q: &JointVector<N>) -> JointVector<N> {
        R::gravity_with(q, &self.params)
    }
    #[inline]
    fn inverse_dynamics(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        qdd: &JointVector<N>,
    ) -> JointVector<N> {
        R::inverse_dynamics_with(q, qd, qdd, &self.params)
    }
    /// The generated parametric forward dynamics (an unrolled sparse `L^T D L` solve, its
    /// pivots functions of the parameters), not the default Cholesky solve: the parameters
    /// must give a positive definite `M(q)`, as any physical set does.
    ///
    /// # Errors
    ///
    /// [`ModelError::NonFinite`] naming `"qdd"` if the result is not finite (for instance,
    /// parameters that make `M(q)` singular).
    #[inline]
    fn forward_dynamics(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        tau: &JointVector<N>,
    ) -> Result<JointVector<N>, ModelError> {
        let qdd = R::forward_dynamics_with(q, qd, tau, &self.params);
        match qdd.iter().position(|x| !x.is_finite()) {
            Some(index) => Err(ModelError::NonFinite {
                what: "qdd",
                index,
                value: qdd[index],
            }),
            None => Ok(qdd),
        }
    }
}
