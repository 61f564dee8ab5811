//! The singularity of the SCARA's reduced Jacobian (thesis Section 3.2.2) and the damped
//! inverse that replaces its exact inverse near it.
//!
//! The reduced Jacobian `Jr` (rows `vx, vy, vz, wz` of the geometric Jacobian; thesis eq.
//! 3.35 without its zero rows) has `det Jr = l1 l2 sin q2`: it is singular with the arm
//! stretched (`q2 = 0`, the outer boundary of the workspace) or folded (`q2 = pi`). Near it,
//! [`ScaraGeometry::joint_target`](super::ScaraGeometry::joint_target) replaces `Jr^-1` by a damped least-squares inverse that
//! damps only the direction of lost mobility (Chiaverini's singular-value filtering):
//!
//! ```text
//! Jr^# = Jr^T (Jr Jr^T + lambda^2 U)^-1,    U = [u u^T 0; 0 0]   (4 x 4)
//! lambda^2 = LAMBDA_MAX^2 (1 - (s / S0)^2)   for s = |sin q2| < S0,   0 otherwise
//! ```
//!
//! where `u` is the unit left singular vector of the smallest singular value of the planar
//! block `J12` (eq. 3.38; at the singularity, the direction along the arm, towards or away
//! from the base axis). The residual `b - Jr Jr^# b = lambda^2 U (...)` lies along `u`
//! only: the tangential velocity, the z velocity and the yaw rate are still met exactly, and
//! only the speed along the arm is given up near the singularity. [`SINGULARITY_THRESHOLD`]
//! `S0 = 0.05` (`|q2|` within about 2.9 degrees of 0 or pi) and [`MAX_DAMPING`] `LAMBDA_MAX =
//! 0.01 m`: the damping is zero, and the inverse exact, for `s >= S0`, grows continuously
//! as `s` falls below `S0`, and bounds the joint speed per unit Cartesian speed along `u` by
//! `1 / (2 LAMBDA_MAX) = 50 rad/m`. The result says when it acted
//! ([`Conditioning::Damped`]). This replaces the thesis's nudge of `q2` away from 0 by
//! 1e-4 rad (Section 5.2), whose inverse still divides by `sin(1e-4)`: factors of
//! `2.5 / sin q2 = 2.5e4` in eq. 5.7.

use nalgebra::{Matrix4, Vector4};

use crate::model::lu::Lu;
use crate::model::{JointVector, RobotModel, Scara};

/// `S0`: below this `|sin q2|` the inverse of the reduced Jacobian is damped.
pub const SINGULARITY_THRESHOLD: f64 = 0.05;

/// `LAMBDA_MAX`: the damping at the singularity itself (`sin q2 = 0`), m.
pub const MAX_DAMPING: f64 = 0.01;

/// Rows of the geometric Jacobian kept in the reduced 4 x 4 Jacobian: `vx, vy, vz, wz`.
const REDUCED_ROWS: [usize; 4] = super::TASK_ROWS;

/// Whether the reduced Jacobian was inverted exactly or with damping.
///
/// # Example
///
/// ```
/// use armdyn::robots::scara::Conditioning;
/// assert!(!Conditioning::Regular.is_singular());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Conditioning {
    /// `|sin q2| >= S0`: the exact inverse was used.
    Regular,
    /// `|sin q2| < S0`: near the stretched or folded arm; the damped least-squares inverse was
    /// used, so the joint velocity and acceleration meet the Cartesian ones only
    /// approximately in x and y.
    Damped {
        /// `sin q2` at the target.
        sin_q2: f64,
        /// The damping `lambda` used, m.
        lambda: f64,
    },
}

impl Conditioning {
    /// Whether the target was near a singularity (damped).
    ///
    /// ```
    /// use armdyn::robots::scara::Conditioning;
    /// assert!(Conditioning::Damped { sin_q2: 0.0, lambda: 0.01 }.is_singular());
    /// ```
    pub fn is_singular(&self) -> bool {
        matches!(self, Conditioning::Damped { .. })
    }
}

/// The reduced 4 x 4 Jacobian of the generated SCARA model at `q`: rows `vx, vy, vz, wz` of
/// the geometric Jacobian (thesis eq. 3.35 without its two zero rows), so that
/// `[v; yaw_rate] = Jr qd` (m/s, m/s, m/s, rad/s). `det Jr = l1 l2 sin q2`.
///
/// ```
/// use armdyn::robots::scara::reduced_jacobian;
/// use nalgebra::Vector4;
/// let jr = reduced_jacobian(&Vector4::new(0.3, 1.0, 0.2, 0.0));
/// assert!((jr.determinant() - 0.16 * 1.0_f64.sin()).abs() < 1e-12);
/// assert_eq!(jr.row(3).clone_owned(), nalgebra::RowVector4::new(1.0, 1.0, 0.0, -1.0));
/// ```
pub fn reduced_jacobian(q: &JointVector<4>) -> Matrix4<f64> {
    let j = Scara.jacobian(q);
    Matrix4::from_fn(|r, c| j[(REDUCED_ROWS[r], c)])
}

/// The damping `lambda` (m) used at `|sin q2| = s`: `LAMBDA_MAX sqrt(1 - (s / S0)^2)` below
/// [`SINGULARITY_THRESHOLD`], 0 at or above it.
///
/// ```
/// use armdyn::robots::scara::{damping, MAX_DAMPING};
/// assert_eq!(damping(0.0), MAX_DAMPING);
/// assert_eq!(damping(0.5), 0.0);
/// ```
pub fn damping(sin_q2: f64) -> f64 {
    let s = libm::fabs(sin_q2) / SINGULARITY_THRESHOLD;
    if s < 1.0 {
        MAX_DAMPING * crate::math::sqrt(1.0 - s * s)
    } else {
        0.0
    }
}

/// Solves `Jr x = b` for the reduced Jacobian `jr` at a configuration with the given
/// `sin q2`: exactly (LU) when `|sin q2| >=` [`SINGULARITY_THRESHOLD`], otherwise by damped
/// least squares `x = Jr^T (Jr Jr^T + lambda^2 U)^-1 b` with `lambda =` [`damping`]`(sin
/// q2)` and `U` the projector on the weakest direction of the planar block (see the [module
/// documentation](self)). Returns the solution and whether damping acted. Never panics; a
/// non-finite input gives a non-finite output.
///
/// ```
/// use armdyn::robots::scara::{damped_solve, reduced_jacobian};
/// use nalgebra::Vector4;
///
/// let q = Vector4::new(0.0, 0.0, 0.2, 0.0); // arm stretched along x: Jr is singular
/// let b = Vector4::new(-0.1, 0.05, 0.0, 0.0); // in x (along the arm) and y (across it)
/// let (x, conditioning) = damped_solve(&reduced_jacobian(&q), 0.0, &b);
/// assert!(conditioning.is_singular());
/// let v = reduced_jacobian(&q) * x;
/// assert!(v[0].abs() < 1e-15);            // the motion along the arm is given up...
/// assert!((v[1] - 0.05).abs() < 1e-15);   // ...the one across it is kept
/// ```
pub fn damped_solve(
    jr: &Matrix4<f64>,
    sin_q2: f64,
    b: &Vector4<f64>,
) -> (Vector4<f64>, Conditioning) {
    let solver = DampedSolver::new(jr, sin_q2);
    (solver.solve(b), solver.conditioning())
}

/// [`damped_solve`] factorised once for several right-hand sides `b` (the joint velocity,
/// then the acceleration, of one target), each solve the same numbers as [`damped_solve`]'s.
#[derive(Clone, Debug)]
pub struct DampedSolver {
    how: Factored,
    conditioning: Conditioning,
}

#[derive(Clone, Debug)]
enum Factored {
    /// `x = Jr^-1 b`.
    Exact(Lu<f64, 4>),
    /// `x = Jr^T (Jr Jr^T + lambda^2 u u^T)^-1 b` (`None`: that matrix is singular).
    Damped(Option<Lu<f64, 4>>, Matrix4<f64>),
}

impl DampedSolver {
    /// The solver of `jr` at `sin q2 = sin_q2`.
    #[must_use]
    pub fn new(jr: &Matrix4<f64>, sin_q2: f64) -> Self {
        let lambda = damping(sin_q2);
        if lambda == 0.0 {
            // Invertible exactly when every solve by it succeeds.
            let lu = Lu::new(jr);
            if lu.is_invertible() {
                return Self {
                    how: Factored::Exact(lu),
                    conditioning: Conditioning::Regular,
                };
            }
        }
        // Damped (or the exact solve failed, which needs a Jacobian that is singular away
        // from sin q2 = 0: not this robot; fall back to the largest damping).
        let lambda = if lambda == 0.0 { MAX_DAMPING } else { lambda };
        let u = weakest_direction(jr);
        let mut normal = jr * jr.transpose();
        for r in 0..2 {
            for c in 0..2 {
                normal[(r, c)] += lambda * lambda * u[r] * u[c];
            }
        }
        let lu = Lu::new(&normal);
        Self {
            how: Factored::Damped(lu.is_invertible().then_some(lu), jr.transpose()),
            conditioning: Conditioning::Damped { sin_q2, lambda },
        }
    }

    /// `x` for the right-hand side `b` (NaN if the damped matrix is singular).
    #[must_use]
    pub fn solve(&self, b: &Vector4<f64>) -> Vector4<f64> {
        match &self.how {
            Factored::Exact(lu) => lu.solve(b).unwrap_or_else(|| Vector4::repeat(f64::NAN)),
            Factored::Damped(Some(lu), jrt) => lu
                .solve(b)
                .map_or_else(|| Vector4::repeat(f64::NAN), |y| jrt * y),
            Factored::Damped(None, _) => Vector4::repeat(f64::NAN),
        }
    }

    /// How the inverse was taken.
    #[must_use]
    pub fn conditioning(&self) -> Conditioning {
        self.conditioning
    }
}

/// Unit eigenvector of the smallest eigenvalue of `J12 J12^T` (`J12` the top-left 2 x 2 block
/// of `jr`): the left singular vector of the smallest singular value of `J12`.
fn weakest_direction(jr: &Matrix4<f64>) -> [f64; 2] {
    let (j11, j12, j21, j22) = (jr[(0, 0)], jr[(0, 1)], jr[(1, 0)], jr[(1, 1)]);
    let a = j11 * j11 + j12 * j12;
    let b = j11 * j21 + j12 * j22;
    let d = j21 * j21 + j22 * j22;
    let half_gap = crate::math::hypot(0.5 * (a - d), b);
    let smallest = 0.5 * (a + d) - half_gap;
    // Two expressions of the same eigenvector; the longer one is the better conditioned.
    let (v1, v2) = ([b, smallest - a], [smallest - d, b]);
    let (n1, n2) = (
        crate::math::hypot(v1[0], v1[1]),
        crate::math::hypot(v2[0], v2[1]),
    );
    if n1 >= n2 && n1 > 0.0 {
        [v1[0] / n1, v1[1] / n1]
    } else if n2 > 0.0 {
        [v2[0] / n2, v2[1] / n2]
    } else {
        [1.0, 0.0] // isotropic (or zero) block: every direction is as weak
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn damping_is_continuous_and_acts_only_near_the_singularity() {
        assert_eq!(damping(SINGULARITY_THRESHOLD), 0.0);
        assert!(damping(SINGULARITY_THRESHOLD * (1.0 - 1e-12)) < 1e-7);
        assert_eq!(damping(-0.0), MAX_DAMPING);
        assert_eq!(damping(0.2), 0.0);
    }
}
