//! A robot with gravity switched off, for energy checks and gravity-free studies.

use super::robot::RobotModel;
use super::types::{JointMatrix, JointVector};

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
    kinematics_of_the_wrapped_robot!(R, 0, [0.0; 3]);

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
    // Inverse dynamics: the default, `M qdd + c` (its `g` is zero).
}
