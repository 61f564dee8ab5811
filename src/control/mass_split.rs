//! The split `M(q) = M_linear + M_nonlinear(q)` of feedback linearization (thesis eq. 4.17–4.19,
//! 4.38–4.39).

use crate::model::{JointMatrix, JointVector, RobotModel};

/// Which terms of `M` the linear part keeps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplitKind {
    /// The whole configuration-independent part of `M` (eq. 4.18): decentralized PID with
    /// feedback linearization, full-state feedback.
    ConstantPart,
    /// Only the diagonal of the constant part (eq. 4.38): centralized PID with feedback
    /// linearization; every coupling term goes to `M_nonlinear`.
    ConstantDiagonal,
}

/// The constant part of `M(q)`: the mean of `M` over `q2 in {0, pi/2, pi, 3 pi/2}` with the
/// other joints at 0. Exact for a SCARA, whose `M` is affine in `cos q2` (eq. 3.67); for other
/// robots it is the average over those four elbow angles.
#[must_use]
pub fn constant_part<const N: usize, R: RobotModel<N>>(robot: &R) -> JointMatrix<N> {
    let mut sum = JointMatrix::<N>::zeros();
    for k in 0..4 {
        let mut q = JointVector::<N>::zeros();
        if N > 1 {
            q[1] = f64::from(k) * core::f64::consts::FRAC_PI_2;
        }
        sum += robot.mass_matrix(&q);
    }
    let mean = sum / 4.0;
    // Symmetrise and clear the rounding residue of cos(pi/2) = 6e-17.
    (mean + mean.transpose()) / 2.0
}

/// `M_linear` for a split kind, from the model's constant part.
#[must_use]
pub fn linear_part<const N: usize, R: RobotModel<N>>(robot: &R, kind: SplitKind) -> JointMatrix<N> {
    let c = constant_part(robot);
    match kind {
        SplitKind::ConstantPart => c,
        SplitKind::ConstantDiagonal => JointMatrix::from_diagonal(&c.diagonal()),
    }
}
