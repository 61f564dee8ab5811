//! A robot with rotor inertia at its joints: the armature a drive adds to the joint-space
//! inertia, which a description of the links alone leaves out.
//!
//! ```text
//! M_a(q) = M(q) + diag(a)        tau = M_a(q) qdd + c(q, qd) + g(q)
//! ```
//!
//! `a_i` is the rotor's inertia reflected through its gear, kg m^2 (or kg for a prismatic
//! joint); the velocity terms do not change (the rotor spins about a fixed axis of its link).

use super::robot::RobotModel;
use super::types::{JointMatrix, JointVector};

/// `R` with armature `a` at its joints: `M_a(q) = M(q) + diag(a)` and
/// `tau = M_a(q) qdd + c(q, qd) + g(q)`; kinematics, `c` and `g` delegated, forward dynamics
/// by a Cholesky solve of `M_a`.
///
/// ```
/// use armdyn::model::{RobotModel, Ur5, WithArmature};
/// use nalgebra::SVector;
/// let q = SVector::from([0.1, -1.2, 1.0, -0.5, 1.4, 0.3]);
/// let a = SVector::repeat(0.1);
/// let m = WithArmature::new(Ur5, a).mass_matrix(&q);
/// assert!((m - Ur5.mass_matrix(&q) - nalgebra::SMatrix::<f64, 6, 6>::from_diagonal(&a)).amax() < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WithArmature<const N: usize, R> {
    robot: R,
    armature: JointVector<N>,
}

impl<const N: usize, R: RobotModel<N>> WithArmature<N, R> {
    /// `robot` with armature `armature` (kg m^2 or kg, each >= 0; not checked here).
    #[must_use]
    pub fn new(robot: R, armature: JointVector<N>) -> Self {
        Self { robot, armature }
    }

    /// The armature, kg m^2 or kg.
    #[must_use]
    pub fn armature(&self) -> &JointVector<N> {
        &self.armature
    }
}

impl<const N: usize, R: RobotModel<N>> RobotModel<N> for WithArmature<N, R> {
    kinematics_of_the_wrapped_robot!(R, robot, R::GRAVITY);

    fn mass_matrix(&self, q: &JointVector<N>) -> JointMatrix<N> {
        let mut m = self.robot.mass_matrix(q);
        for i in 0..N {
            m[(i, i)] += self.armature[i];
        }
        m
    }
    fn mass_matrix_and_bias(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
    ) -> (JointMatrix<N>, JointVector<N>) {
        let (mut m, bias) = self.robot.mass_matrix_and_bias(q, qd);
        for i in 0..N {
            m[(i, i)] += self.armature[i];
        }
        (m, bias)
    }
    fn coriolis_matrix(&self, q: &JointVector<N>, qd: &JointVector<N>) -> JointMatrix<N> {
        self.robot.coriolis_matrix(q, qd)
    }
    fn coriolis(&self, q: &JointVector<N>, qd: &JointVector<N>) -> JointVector<N> {
        self.robot.coriolis(q, qd)
    }
    fn gravity(&self, q: &JointVector<N>) -> JointVector<N> {
        self.robot.gravity(q)
    }
    fn inverse_dynamics(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        qdd: &JointVector<N>,
    ) -> JointVector<N> {
        self.robot.inverse_dynamics(q, qd, qdd) + self.armature.component_mul(qdd)
    }
    // Forward dynamics: the default, a Cholesky solve of `M_a`.
}
