//! The full regressor of an identification: the generated standard-parameter columns plus,
//! with friction, a viscous and a Coulomb column per joint.

use nalgebra::DMatrix;

use super::robots::Identifiable;
use crate::model::JointVector;
use crate::sim::JointFriction;

/// Names of the friction parameters appended to the standard ones: `fv1 .. fvN` (N m s/rad
/// or N s/m), then `fc1 .. fcN` (N m or N).
#[must_use]
pub fn friction_names(n: usize) -> Vec<String> {
    (1..=n)
        .map(|j| format!("fv{j}"))
        .chain((1..=n).map(|j| format!("fc{j}")))
        .collect()
}

/// `[Y(q, qd, qdd) | diag(qd) | diag(tanh(qd / v))]` (`N x 12 N`) with friction smoothing
/// `v`, or `Y` alone (`N x 10 N`) without friction.
#[must_use]
pub fn full_regressor<const N: usize, R: Identifiable<N>>(
    robot: &R,
    q: &JointVector<N>,
    qd: &JointVector<N>,
    qdd: &JointVector<N>,
    friction_smoothing: Option<f64>,
) -> DMatrix<f64> {
    let y = robot.regressor(q, qd, qdd);
    let Some(v) = friction_smoothing else {
        return y;
    };
    let p = y.ncols();
    let mut full = y.resize_horizontally(p + 2 * N, 0.0);
    for i in 0..N {
        full[(i, p + i)] = qd[i];
        full[(i, p + N + i)] = JointFriction::<N>::shape(qd[i], v);
    }
    full
}
