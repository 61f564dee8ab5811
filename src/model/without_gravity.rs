//! A robot with gravity switched off, for energy checks and gravity-free studies.

use super::robot::RobotModel;
use super::types::{Jacobian, JointMatrix, JointVector, Pose};
use nalgebra::{Vector3, Vector6};

/// `R` with `g(q) = 0` and a zero gravity vector; everything else delegated.
///
/// ```
/// use armdyn::model::{RobotModel, Scara, WithoutGravity};
/// use nalgebra::Vector4;
/// assert_eq!(WithoutGravity(Scara).gravity(&Vector4::zeros()), Vector4::zeros());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WithoutGravity<R>(pub R);

impl<const N: usize, R: RobotModel<N>> RobotModel<N> for WithoutGravity<R> {
    const NAME: &'static str = R::NAME;
    const JOINT_NAMES: [&'static str; N] = R::JOINT_NAMES;
    const JOINT_KINDS: [super::JointKind; N] = R::JOINT_KINDS;
    const JOINT_LIMITS: [[f64; 2]; N] = R::JOINT_LIMITS;
    const EFFORT_LIMITS: [f64; N] = R::EFFORT_LIMITS;
    const GRAVITY: [f64; 3] = [0.0; 3];
    const TASK: crate::target::Task = R::TASK;
    const SOURCE_SHA256: &'static str = R::SOURCE_SHA256;
    const OPERATION_COUNTS: &'static [(&'static str, u32, u32)] = R::OPERATION_COUNTS;

    fn frame_poses(&self, q: &JointVector<N>) -> [Pose; N] {
        self.0.frame_poses(q)
    }
    fn end_effector_pose(&self, q: &JointVector<N>) -> Pose {
        self.0.end_effector_pose(q)
    }
    fn jacobian(&self, q: &JointVector<N>) -> Jacobian<N> {
        self.0.jacobian(q)
    }
    fn jacobian_and_position(&self, q: &JointVector<N>) -> (Jacobian<N>, Vector3<f64>) {
        self.0.jacobian_and_position(q)
    }
    fn jdot_qd(&self, q: &JointVector<N>, qd: &JointVector<N>) -> Vector6<f64> {
        self.0.jdot_qd(q, qd)
    }
    fn mass_matrix(&self, q: &JointVector<N>) -> JointMatrix<N> {
        self.0.mass_matrix(q)
    }
    fn coriolis_matrix(&self, q: &JointVector<N>, qd: &JointVector<N>) -> JointMatrix<N> {
        self.0.coriolis_matrix(q, qd)
    }
    fn coriolis(&self, q: &JointVector<N>, qd: &JointVector<N>) -> JointVector<N> {
        self.0.coriolis(q, qd)
    }
    fn gravity(&self, _q: &JointVector<N>) -> JointVector<N> {
        JointVector::zeros()
    }
    fn forward_dynamics(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        tau: &JointVector<N>,
    ) -> Result<JointVector<N>, super::ModelError> {
        // M^-1 (tau + g - c - g) = M^-1 (tau - c): the wrapped robot's own (fast) path.
        self.0.forward_dynamics(q, qd, &(tau + self.0.gravity(q)))
    }
    fn inverse_dynamics(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        qdd: &JointVector<N>,
    ) -> JointVector<N> {
        self.0.mass_matrix(q) * qdd + self.0.coriolis(q, qd)
    }
}
