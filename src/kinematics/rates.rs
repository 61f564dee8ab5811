//! Joint velocities and accelerations for a task-space velocity and acceleration.
//!
//! With `J_t` the task's rows of the geometric Jacobian (the other rows zero) and `J^#` its
//! damped right pseudo-inverse `J_t^T (J_t J_t^T + lambda^2 I)^-1`:
//!
//! ```text
//! qd  = J^# v_t
//! qdd = J^# (a_t - (Jdot qd)_t)          (from d/dt (J qd) = J qdd + Jdot qd)
//! ```
//!
//! `lambda` is zero away from singularities and grows as the task rows lose rank: with `m`
//! the normalised determinant `sqrt(det(J_t J_t^T)) / prod_i |row_i|` (1 for orthogonal rows,
//! 0 at a singularity), `lambda = MAX_DAMPING (1 - m / SINGULARITY_THRESHOLD)` below the
//! threshold ([`crate::control::jacobian_factor`]'s constants). For a redundant arm this is
//! the minimum-norm joint motion; the reference's posture is kept by the inverse kinematics
//! that gives `q`.

use nalgebra::{SMatrix, Vector6};

use crate::model::{JointVector, RobotModel};
use crate::target::CartesianTarget;

/// Below this normalised determinant of the task rows the pseudo-inverse is damped.
pub const SINGULARITY_THRESHOLD: f64 = 1e-3;
/// The damping at a singularity (units of the Jacobian's entries, m or 1).
pub const MAX_DAMPING: f64 = 1e-2;

/// Joint rates and whether the inverse was damped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointRates<const N: usize> {
    /// Joint velocities, rad/s or m/s.
    pub qd: JointVector<N>,
    /// Joint accelerations, rad/s^2 or m/s^2.
    pub qdd: JointVector<N>,
    /// The damping used, 0 away from singularities (units of the Jacobian's entries).
    pub damping: f64,
}

/// The part of joint motion `v` (rad/s or m/s, or any joint-space vector) that leaves the
/// tool still in `robot`'s task directions: `(I - J_t^+ J_t) v`, with the pseudo-inverse of
/// the task rows (damped as in [`joint_rates`] near singularities). Zero for a robot with as
/// many joints as task directions, away from singularities.
///
/// ```
/// use armdyn::kinematics::null_space_part;
/// use armdyn::model::{Panda, RobotModel};
/// use nalgebra::SVector;
/// let q = SVector::from([0.1, -0.6, 0.2, -2.0, 0.1, 1.6, 0.7]);
/// let v = SVector::from([0.3, -0.1, 0.2, 0.1, 0.0, -0.2, 0.1]);
/// let n = null_space_part(&Panda, &q, &v);
/// assert!((Panda.jacobian(&q) * n).norm() < 1e-12 && n.norm() > 1e-3);
/// ```
#[must_use]
pub fn null_space_part<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &JointVector<N>,
    v: &JointVector<N>,
) -> JointVector<N> {
    let (jt, a) = task_rows_and_normal(robot, q);
    match a.cholesky() {
        Some(c) => v - jt.transpose() * c.solve(&(jt * v)),
        None => JointVector::zeros(),
    }
}

/// The joint motion within the task's null space that comes nearest `delta` (rad or m) in
/// the metric `sum_i w_i dq_i^2`: `P (P W P)^+ P W delta`, `P = I - J_t^+ J_t`, `W = diag(w)`.
/// With equal weights it is `P delta`; a joint with a large weight gets its share of
/// `delta` first. Zero for a robot with as many joints as task directions.
///
/// ```
/// use armdyn::kinematics::null_space_step;
/// use armdyn::model::{Panda, RobotModel};
/// use nalgebra::SVector;
/// let q = SVector::from([0.1, -0.6, 0.2, -2.0, 0.1, 1.6, 0.7]);
/// let delta = SVector::from([0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0]);
/// let w = SVector::from([1e-4, 1e-4, 1e-4, 1.0, 1e-4, 1e-4, 1e-4]);
/// let step = null_space_step(&Panda, &q, &delta, &w);
/// assert!((Panda.jacobian(&q) * step).norm() < 1e-9); // the tool stays
/// // Of the self-motions, the one that takes the elbow furthest towards its target per
/// // weighted length: its share of 0.1 rad, in the asked direction.
/// assert!(step[3] > 0.0 && step[3] <= 0.1 + 1e-12);
/// let plain = armdyn::kinematics::null_space_part(&Panda, &q, &delta);
/// assert!(step[3] >= plain[3]);
/// ```
#[must_use]
pub fn null_space_step<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &JointVector<N>,
    delta: &JointVector<N>,
    weights: &JointVector<N>,
) -> JointVector<N> {
    let (jt, a) = task_rows_and_normal(robot, q);
    let Some(c) = a.cholesky() else {
        return JointVector::zeros();
    };
    // P as a matrix: I - J^T (J J^T)^-1 J.
    let p = nalgebra::SMatrix::<f64, N, N>::identity() - jt.transpose() * c.solve(&jt);
    let w = nalgebra::SMatrix::<f64, N, N>::from_diagonal(weights);
    let mut pwp = p * w * p;
    let eps = 1e-10 * pwp.trace().max(1e-300);
    for i in 0..N {
        pwp[(i, i)] += eps;
    }
    match pwp.cholesky() {
        Some(m) => p * m.solve(&(p * weights.component_mul(delta))),
        None => JointVector::zeros(),
    }
}

/// The task rows of the Jacobian (other rows zero) and `J_t J_t^T + lambda^2 I` (with an
/// identity on the rows outside the task), damped as the module says; and the damping.
fn task_rows_and_normal<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &JointVector<N>,
) -> (SMatrix<f64, 6, N>, nalgebra::Matrix6<f64>) {
    let (jt, a, _) = damped_normal(robot, q);
    (jt, a)
}

fn damped_normal<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &JointVector<N>,
) -> (SMatrix<f64, 6, N>, nalgebra::Matrix6<f64>, f64) {
    let mask = R::TASK.mask();
    let j = robot.jacobian(q);
    let jt = SMatrix::<f64, 6, N>::from_fn(|r, c| j[(r, c)] * mask[r]);
    let mut a = jt * jt.transpose();
    let mut rows = 1.0;
    for k in 0..6 {
        if mask[k] == 1.0 {
            rows *= a[(k, k)];
        } else {
            a[(k, k)] = 1.0;
        }
    }
    let det = a.determinant();
    let m = if rows > 0.0 && det > 0.0 {
        libm::sqrt(det / rows)
    } else {
        0.0
    };
    let damping = if m >= SINGULARITY_THRESHOLD {
        0.0
    } else {
        MAX_DAMPING * (1.0 - m / SINGULARITY_THRESHOLD)
    };
    for k in 0..6 {
        if mask[k] == 1.0 {
            a[(k, k)] += damping * damping;
        }
    }
    (jt, a, damping)
}

/// The joint rates at `q` that give `target`'s velocity and acceleration in `robot`'s task
/// directions (see the [module documentation](self)).
///
/// ```
/// use armdyn::kinematics::joint_rates;
/// use armdyn::model::{RobotModel, Ur5};
/// use armdyn::target::{orientation, CartesianTarget};
/// use nalgebra::{SVector, Vector3};
///
/// let q = SVector::from([0.3, -1.2, 1.4, -1.8, -1.5, 0.2]);
/// let mut t = CartesianTarget::at_rest(Vector3::zeros(), orientation::from_yaw(0.0));
/// t.velocity = Vector3::new(0.1, -0.05, 0.02);
/// t.angular_velocity = Vector3::new(0.0, 0.2, -0.1);
/// let r = joint_rates(&Ur5, &q, &t);
/// let twist = Ur5.jacobian(&q) * r.qd;
/// assert!((twist - t.twist()).norm() < 1e-12 && r.damping == 0.0);
/// ```
#[must_use]
pub fn joint_rates<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &JointVector<N>,
    target: &CartesianTarget,
) -> JointRates<N> {
    let mask = R::TASK.mask();
    let (jt, a, damping) = damped_normal(robot, q);
    let solve = |b: &Vector6<f64>| -> JointVector<N> {
        let b = b.component_mul(&mask);
        match a.cholesky() {
            Some(c) => jt.transpose() * c.solve(&b),
            None => JointVector::repeat(f64::NAN),
        }
    };
    let qd = solve(&target.twist());
    let bias = robot.jdot_qd(q, &qd);
    let qdd = solve(&(target.acceleration_twist() - bias));
    JointRates { qd, qdd, damping }
}
