//! The torques of a latched reaction ([`Reaction`]), from the model at the current state.

use super::limits::Reaction;
use nalgebra::{Matrix3, RealField, SMatrix, SVector, Vector3};

/// The robot at the current state, as a reaction needs it.
#[derive(Clone, Copy, Debug)]
pub struct ModelAt<'a, T: RealField + Copy, const N: usize> {
    /// Mass matrix `M(q)`.
    pub mass: &'a SMatrix<T, N, N>,
    /// Bias `c(q, qd) + g(q)`, N m or N.
    pub bias: &'a SVector<T, N>,
    /// Translational rows of the geometric Jacobian at the tool point.
    pub jp: &'a SMatrix<T, 3, N>,
    /// Tool position, m, base frame.
    pub position: &'a Vector3<T>,
}

/// Where a reaction started and where its reference is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReactionState<T: RealField + Copy, const N: usize> {
    /// Time of the trip, s.
    pub t0: T,
    /// Joints at the trip.
    pub q0: SVector<T, N>,
    /// Tool position at the trip, m.
    pub p0: Vector3<T>,
    /// Direction of a retraction (the surface's outward unit normal), base frame.
    pub away: Vector3<T>,
    /// The retraction's joint reference.
    q_ref: SVector<T, N>,
}

/// A retraction stops where its joint reference comes within this share of a joint's range
/// of a limit (the tracking overshoots a little).
pub const RETRACT_LIMIT_SHARE: f64 = 0.02;

/// Damping of the pseudo-inverse of the translational Jacobian, m: `J^T (J J^T + l^2 I)^-1`.
pub const RETRACT_DAMPING_M: f64 = 1e-3;

impl<T: RealField + Copy, const N: usize> ReactionState<T, N> {
    /// A reaction starting at time `t0` (s), joints `q0`, tool at `p0` (m), retreating along
    /// `away` (normalised here; the base `z` if it is zero or not finite).
    #[must_use]
    pub fn new(t0: T, q0: SVector<T, N>, p0: Vector3<T>, away: Vector3<T>) -> Self {
        let norm = away.norm();
        let away = if norm.is_finite() && norm > T::zero() {
            away / norm
        } else {
            Vector3::z()
        };
        Self {
            t0,
            q0,
            p0,
            away,
            q_ref: q0,
        }
    }

    /// The reaction's torque at time `t` (s), one period `dt` after the last, at `(q, qd)`;
    /// a retraction stops where its joint reference would come within
    /// [`RETRACT_LIMIT_SHARE`] of the range of `[lower, upper]`.
    #[allow(clippy::too_many_arguments)]
    pub fn torque(
        &mut self,
        reaction: &Reaction<T>,
        t: T,
        dt: T,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        model: &ModelAt<'_, T, N>,
        (lower, upper): (&SVector<T, N>, &SVector<T, N>),
    ) -> SVector<T, N> {
        let two: T = nalgebra::convert(2.0);
        match *reaction {
            Reaction::Hold { omega_rad_s: w } => {
                model.mass * ((self.q0 - q) * (w * w) - qd * (two * w)) + model.bias
            }
            Reaction::Retract {
                omega_rad_s: w,
                speed_m_s,
                distance_m,
            } => {
                let moving = (t - self.t0) * speed_m_s < distance_m;
                let qd_ref = if moving {
                    let jp = model.jp;
                    let l2: T = nalgebra::convert(RETRACT_DAMPING_M * RETRACT_DAMPING_M);
                    let jjt = jp * jp.transpose() + Matrix3::identity() * l2;
                    jjt.cholesky().map_or_else(SVector::zeros, |c| {
                        jp.transpose() * c.solve(&(self.away * speed_m_s))
                    })
                } else {
                    SVector::zeros()
                };
                let next = self.q_ref + qd_ref * dt;
                let keep: T = nalgebra::convert(RETRACT_LIMIT_SHARE);
                let inside = (0..N).all(|i| {
                    let m = (upper[i] - lower[i]) * keep;
                    lower[i] + m <= next[i] && next[i] <= upper[i] - m
                });
                let qd_ref = if inside { qd_ref } else { SVector::zeros() };
                self.q_ref += qd_ref * dt;
                model.mass * ((self.q_ref - q) * (w * w) + (qd_ref - qd) * (two * w)) + model.bias
            }
            Reaction::Compliant {
                stiffness_n_m,
                damping_rad_s,
            } => {
                let f = (self.p0 - model.position) * stiffness_n_m;
                model.jp.transpose() * f - model.mass * (qd * (two * damping_rad_s)) + model.bias
            }
        }
    }
}
