//! One knot step of the plans' dynamics and its Jacobians, in free space: `substeps` RK4 steps
//! of `qdd = FD(q, qd, tau)` with the torque held, and `d [q; qd]_(k+1) / d [q_k; qd_k; tau]`
//! by the chain rule through every stage, on fixed-size `N x N` blocks (no allocation).
//!
//! ```text
//! stage i:  a_i = FD(q_i, v_i, tau)
//!           d a_i = FD_q P_i^q + FD_qd P_i^v + [0, 0, M^-1]        (P_i: d (q_i, v_i) / d (q, qd, tau))
//! step:     q' = q + h/6 (v_1 + 2 v_2 + 2 v_3 + v_4),  qd' = qd + h/6 (a_1 + 2 a_2 + 2 a_3 + a_4)
//! ```
//!
//! The same map as [`plant_period`](crate::sim::linearize::plant::plant_period) without a
//! contact, end stops or friction (tested equal), which also differentiates the contact model
//! and the Jacobian at every stage: the plans need neither.

use crate::model::{DynamicsDerivatives, JointMatrix, JointVector, ModelError};

/// Derivatives of `N` quantities with respect to the step's start `q`, `qd` and the torque.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sensitivity<const N: usize> {
    /// With respect to `q` at the step's start.
    pub q: JointMatrix<N>,
    /// With respect to `qd` at the step's start.
    pub qd: JointMatrix<N>,
    /// With respect to the torque held over the step.
    pub tau: JointMatrix<N>,
}

impl<const N: usize> Sensitivity<N> {
    fn zeros() -> Self {
        Self {
            q: JointMatrix::<N>::zeros(),
            qd: JointMatrix::<N>::zeros(),
            tau: JointMatrix::<N>::zeros(),
        }
    }

    /// `self + other * s`.
    fn plus(&self, other: &Self, s: f64) -> Self {
        Self {
            q: self.q + other.q * s,
            qd: self.qd + other.qd * s,
            tau: self.tau + other.tau * s,
        }
    }

    /// `m * self` (a left product of every block).
    fn left(m: &JointMatrix<N>, s: &Self) -> Self {
        Self {
            q: m * s.q,
            qd: m * s.qd,
            tau: m * s.tau,
        }
    }
}

/// The end of a knot step and its Jacobians.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KnotStep<const N: usize> {
    /// Joint positions at the step's end.
    pub q: JointVector<N>,
    /// Joint velocities at the step's end.
    pub qd: JointVector<N>,
    /// `d q_end / d (q, qd, tau)`.
    pub dq: Sensitivity<N>,
    /// `d qd_end / d (q, qd, tau)`.
    pub dqd: Sensitivity<N>,
}

/// `substeps` RK4 steps of `h` each from `(q, qd)` with `tau` held, and the Jacobians of the
/// end state (see the [module documentation](self)).
///
/// # Errors
///
/// [`ModelError`] if forward dynamics or its derivatives fail at a stage.
pub fn knot_step<const N: usize, R: DynamicsDerivatives<N>>(
    robot: &R,
    q: &JointVector<N>,
    qd: &JointVector<N>,
    tau: &JointVector<N>,
    substeps: usize,
    h: f64,
) -> Result<KnotStep<N>, ModelError> {
    knot_step_with(robot, q, qd, tau, substeps, h, None)
}

/// [`knot_step`], with the stages' accelerations `a_1..a_4` of every substep already known
/// (`4 substeps N` numbers, stage after stage, from a roll-out of the same step by
/// [`rk4_step`](crate::sim::rk4::rk4_step), whose stage states are these bit for bit): only
/// the derivatives are evaluated. `None`: as [`knot_step`].
///
/// # Errors
///
/// As [`knot_step`]; a `known` of the wrong length is not used.
pub fn knot_step_with<const N: usize, R: DynamicsDerivatives<N>>(
    robot: &R,
    q: &JointVector<N>,
    qd: &JointVector<N>,
    tau: &JointVector<N>,
    substeps: usize,
    h: f64,
    known: Option<&[f64]>,
) -> Result<KnotStep<N>, ModelError> {
    let known = known.filter(|k| k.len() == 4 * substeps * N);
    let identity = JointMatrix::<N>::identity();
    // d (q, qd) / d (q0, qd0, tau) so far.
    let mut total_q = Sensitivity {
        q: identity,
        ..Sensitivity::zeros()
    };
    let mut total_v = Sensitivity {
        qd: identity,
        ..Sensitivity::zeros()
    };
    let (mut q, mut qd) = (*q, *qd);
    // A stage at (qs, vs) whose sensitivities are (pq, pv): its acceleration and d a.
    let stage = |index: usize,
                 qs: &JointVector<N>,
                 vs: &JointVector<N>,
                 pq: &Sensitivity<N>,
                 pv: &Sensitivity<N>|
     -> Result<(JointVector<N>, Sensitivity<N>), ModelError> {
        let a = match known {
            Some(k) => JointVector::<N>::from_column_slice(&k[index * N..(index + 1) * N]),
            None => robot.forward_dynamics(qs, vs, tau)?,
        };
        let d = robot.forward_dynamics_derivatives(qs, vs, tau)?;
        let mut da =
            Sensitivity::left(&d.dqdd_dq, pq).plus(&Sensitivity::left(&d.dqdd_dqd, pv), 1.0);
        da.tau += d.mass_matrix_inverse;
        Ok((a, da))
    };
    for sub in 0..substeps {
        let (p1q, p1v) = (total_q, total_v);
        let (a1, d1) = stage(4 * sub, &q, &qd, &p1q, &p1v)?;
        let (q2, v2) = (q + qd * (h / 2.0), qd + a1 * (h / 2.0));
        let (p2q, p2v) = (p1q.plus(&p1v, h / 2.0), p1v.plus(&d1, h / 2.0));
        let (a2, d2) = stage(4 * sub + 1, &q2, &v2, &p2q, &p2v)?;
        let (q3, v3) = (q + v2 * (h / 2.0), qd + a2 * (h / 2.0));
        let (p3q, p3v) = (p1q.plus(&p2v, h / 2.0), p1v.plus(&d2, h / 2.0));
        let (a3, d3) = stage(4 * sub + 2, &q3, &v3, &p3q, &p3v)?;
        let (q4, v4) = (q + v3 * h, qd + a3 * h);
        let (p4q, p4v) = (p1q.plus(&p3v, h), p1v.plus(&d3, h));
        let (a4, d4) = stage(4 * sub + 3, &q4, &v4, &p4q, &p4v)?;
        q += (qd + v2 * 2.0 + v3 * 2.0 + v4) * (h / 6.0);
        qd += (a1 + a2 * 2.0 + a3 * 2.0 + a4) * (h / 6.0);
        let sixth = h / 6.0;
        total_q = p1q
            .plus(&p1v, sixth)
            .plus(&p2v, 2.0 * sixth)
            .plus(&p3v, 2.0 * sixth)
            .plus(&p4v, sixth);
        total_v = p1v
            .plus(&d1, sixth)
            .plus(&d2, 2.0 * sixth)
            .plus(&d3, 2.0 * sixth)
            .plus(&d4, sixth);
    }
    Ok(KnotStep {
        q,
        qd,
        dq: total_q,
        dqd: total_v,
    })
}
