//! The SCARA with inertial parameters given at run time: the generated parametric model
//! (`scara_generated::scara::parametric`) behind [`RobotModel`], for a plant whose
//! parameters differ from the description's or a controller that uses identified ones.

use nalgebra::{Vector3, Vector6};
use scara_generated::scara as generated;

use super::robot::RobotModel;
use super::types::{Jacobian, JointMatrix, JointVector, Pose};
use super::{JointKind, ModelError, Scara};

/// Standard inertial parameters of the SCARA: per link `[m, m cx, m cy, m cz, Ixx, Ixy,
/// Ixz, Iyy, Iyz, Izz]` (kg, kg m, kg m^2; inertia about the link frame's origin, link frame
/// axes), links 1 to 4.
pub type ScaraParameters = [f64; 40];

/// The thesis SCARA's kinematics with dynamics from a parameter vector.
///
/// With the description's parameters ([`Self::nominal`]) it equals [`Scara`] to rounding
/// (the parametric functions evaluate the same model in another order of operations).
///
/// ```
/// use scara::model::{ParametricScara, RobotModel, Scara};
/// use nalgebra::Vector4;
/// let q = Vector4::new(0.2, -0.4, 0.15, 0.3);
/// let m = ParametricScara::nominal().mass_matrix(&q);
/// assert!((m - Scara.mass_matrix(&q)).norm() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParametricScara {
    params: ScaraParameters,
}

impl ParametricScara {
    /// A model with parameters `params`.
    #[must_use]
    pub fn new(params: ScaraParameters) -> Self {
        Self { params }
    }

    /// The description's parameters.
    #[must_use]
    pub fn nominal() -> Self {
        Self::new(generated::standard_parameters())
    }

    /// The parameters.
    #[must_use]
    pub fn parameters(&self) -> &ScaraParameters {
        &self.params
    }
}

#[inline(always)]
fn arr(v: &JointVector<4>) -> [f64; 4] {
    (*v).into()
}

#[inline(always)]
fn rows<const R: usize, const C: usize>(m: &[[f64; C]; R]) -> nalgebra::SMatrix<f64, R, C> {
    nalgebra::SMatrix::<f64, R, C>::from_fn(|i, j| m[i][j])
}

impl RobotModel<4> for ParametricScara {
    const NAME: &'static str = <Scara as RobotModel<4>>::NAME;
    const JOINT_NAMES: [&'static str; 4] = <Scara as RobotModel<4>>::JOINT_NAMES;
    const JOINT_KINDS: [JointKind; 4] = <Scara as RobotModel<4>>::JOINT_KINDS;
    const JOINT_LIMITS: [[f64; 2]; 4] = <Scara as RobotModel<4>>::JOINT_LIMITS;
    const EFFORT_LIMITS: [f64; 4] = <Scara as RobotModel<4>>::EFFORT_LIMITS;
    const GRAVITY: [f64; 3] = <Scara as RobotModel<4>>::GRAVITY;
    const SOURCE_SHA256: &'static str = <Scara as RobotModel<4>>::SOURCE_SHA256;
    const OPERATION_COUNTS: &'static [(&'static str, u32, u32)] =
        &generated::parametric::OPERATION_COUNTS;

    fn frame_poses(&self, q: &JointVector<4>) -> [Pose; 4] {
        Scara.frame_poses(q)
    }
    fn end_effector_pose(&self, q: &JointVector<4>) -> Pose {
        Scara.end_effector_pose(q)
    }
    fn jacobian(&self, q: &JointVector<4>) -> Jacobian<4> {
        Scara.jacobian(q)
    }
    fn jacobian_and_position(&self, q: &JointVector<4>) -> (Jacobian<4>, Vector3<f64>) {
        Scara.jacobian_and_position(q)
    }
    fn jdot_qd(&self, q: &JointVector<4>, qd: &JointVector<4>) -> Vector6<f64> {
        Scara.jdot_qd(q, qd)
    }
    #[inline]
    fn mass_matrix(&self, q: &JointVector<4>) -> JointMatrix<4> {
        rows(&generated::parametric::mass_matrix(&arr(q), &self.params))
    }
    #[inline]
    fn coriolis_matrix(&self, q: &JointVector<4>, qd: &JointVector<4>) -> JointMatrix<4> {
        rows(&generated::parametric::coriolis_matrix(
            &arr(q),
            &arr(qd),
            &self.params,
        ))
    }
    #[inline]
    fn coriolis(&self, q: &JointVector<4>, qd: &JointVector<4>) -> JointVector<4> {
        generated::parametric::coriolis(&arr(q), &arr(qd), &self.params).into()
    }
    #[inline]
    fn gravity(&self, q: &JointVector<4>) -> JointVector<4> {
        generated::parametric::gravity(&arr(q), &self.params).into()
    }
    #[inline]
    fn inverse_dynamics(
        &self,
        q: &JointVector<4>,
        qd: &JointVector<4>,
        qdd: &JointVector<4>,
    ) -> JointVector<4> {
        generated::parametric::inverse_dynamics(&arr(q), &arr(qd), &arr(qdd), &self.params).into()
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
        q: &JointVector<4>,
        qd: &JointVector<4>,
        tau: &JointVector<4>,
    ) -> Result<JointVector<4>, ModelError> {
        let qdd: JointVector<4> =
            generated::parametric::forward_dynamics(&arr(q), &arr(qd), &arr(tau), &self.params)
                .into();
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
