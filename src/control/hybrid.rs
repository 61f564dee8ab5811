//! Hybrid force/position control (thesis Section 5.2, eq. 5.4):
//!
//! ```text
//! tau = J^T ( S J^-T tau_p  +  (I - S) f_f )
//! ```
//!
//! `tau_p` is the joint-space position loop's torque (the thesis uses PID with feedback
//! linearization), mapped to Cartesian space by `J^-T`; `f_f` is the Cartesian force loop's
//! wrench ([`ForcePi`]); `S` is the diagonal selection matrix, switched at a given time.
//!
//! `J` is the 6 x N geometric Jacobian reduced to the N task rows the robot can act in
//! (rows `vx vy vz wz` for the SCARA, whose rows `wx wy` are zero), so that it is square.
//! Singularities are handled explicitly, see [`reduced_transpose_solve`].

use super::force::ForcePi;
use super::{Controller, ControllerInput};
use crate::model::cholesky::Cholesky;
use crate::model::{JointMatrix, JointVector, RobotModel, Wrench};

/// The selection matrix over time: `S = diag(before)` for `t < switch_s`, then
/// `diag(after)`; entries in `[0, 1]`, 1 = position controlled, 0 = force controlled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SelectionSchedule {
    /// Diagonal of `S` before the switch.
    pub before: [f64; 6],
    /// Diagonal of `S` from the switch on.
    pub after: [f64; 6],
    /// Switch time, s.
    pub switch_s: f64,
}

impl SelectionSchedule {
    /// The thesis's: `S = I` for `t < 2 s`, then `diag(1, 1, 0, 1, 1, 1)` (eq. 5.5, 5.6).
    #[must_use]
    pub fn thesis() -> Self {
        Self {
            before: [1.0; 6],
            after: [1.0, 1.0, 0.0, 1.0, 1.0, 1.0],
            switch_s: 2.0,
        }
    }

    /// The diagonal of `S` at time `t`.
    #[must_use]
    pub fn at(&self, t: f64) -> [f64; 6] {
        if t < self.switch_s {
            self.before
        } else {
            self.after
        }
    }
}

/// How `J^-T` was obtained at the last step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JacobianSolve {
    /// `S` selected every task direction for position: `J^T S J^-T = I`, no inverse needed.
    NotNeeded,
    /// Regular LU solve.
    Exact,
    /// Near a singularity: damped least squares (see [`reduced_transpose_solve`]).
    Damped,
}

/// Below this normalised determinant of the reduced Jacobian (|det J| over the product of
/// its row norms, 1 for orthogonal rows, 0 at a singularity) the solve is damped.
pub const SINGULARITY_THRESHOLD: f64 = 1e-3;
/// Largest damping `lambda` (same units as the Jacobian entries, m or 1) at the singularity.
pub const MAX_DAMPING: f64 = 1e-2;

/// Solves `J_r^T f = tau` for the task wrench `f` (N x N reduced Jacobian).
///
/// Both regimes use `f = J_r (J_r^T J_r + lambda^2 I)^-1 tau` with a fixed-size Cholesky
/// factorisation (exact for `lambda = 0`). Away from singularities (normalised determinant
/// `m >= SINGULARITY_THRESHOLD`, with `|det J_r|` read off the factor's diagonal)
/// `lambda = 0`; closer, damped least squares with
/// `lambda = MAX_DAMPING (1 - m / SINGULARITY_THRESHOLD)`, growing smoothly from 0 at the
/// threshold, so the wrench stays bounded instead of the thesis's nudge of `q2` by 1e-4.
#[must_use]
pub fn reduced_transpose_solve<const N: usize>(
    jr: &JointMatrix<N>,
    tau: &JointVector<N>,
) -> (JointVector<N>, JacobianSolve) {
    let a = jr.transpose() * jr;
    let row_norms: f64 = (0..N).map(|i| jr.row(i).norm()).product();
    if let Ok(c) = Cholesky::new(&a) {
        let det: f64 = (0..N).map(|i| c.l()[(i, i)]).product();
        let m = if row_norms > 0.0 {
            det.abs() / row_norms
        } else {
            0.0
        };
        if m >= SINGULARITY_THRESHOLD {
            return (jr * c.solve(tau), JacobianSolve::Exact);
        }
        let lambda = MAX_DAMPING * (1.0 - m / SINGULARITY_THRESHOLD);
        return (damped(jr, &a, lambda, tau), JacobianSolve::Damped);
    }
    (damped(jr, &a, MAX_DAMPING, tau), JacobianSolve::Damped)
}

fn damped<const N: usize>(
    jr: &JointMatrix<N>,
    a: &JointMatrix<N>,
    lambda: f64,
    tau: &JointVector<N>,
) -> JointVector<N> {
    let damped = a + JointMatrix::<N>::identity() * (lambda * lambda).max(f64::MIN_POSITIVE);
    match Cholesky::new(&damped) {
        Ok(c) => jr * c.solve(tau),
        Err(_) => JointVector::zeros(),
    }
}

/// Hybrid force/position controller for an N-joint robot acting in N task directions.
#[derive(Clone, Debug)]
pub struct HybridForcePosition<const N: usize, R, P> {
    robot: R,
    position: P,
    force: ForcePi,
    selection: SelectionSchedule,
    rows: [usize; N],
    last_solve: JacobianSolve,
}

impl<const N: usize, R: RobotModel<N>, P: Controller<N>> HybridForcePosition<N, R, P> {
    /// `rows`: the task rows of the 6 x N Jacobian kept (each in 0..6, distinct), e.g.
    /// `[0, 1, 2, 5]` for a SCARA.
    ///
    /// Returns `None` if `rows` repeats a row or names one outside 0..6.
    #[must_use]
    pub fn new(
        robot: R,
        position: P,
        force: ForcePi,
        selection: SelectionSchedule,
        rows: [usize; N],
    ) -> Option<Self> {
        for (i, r) in rows.iter().enumerate() {
            if *r >= 6 || rows[..i].contains(r) {
                return None;
            }
        }
        Some(Self {
            robot,
            position,
            force,
            selection,
            rows,
            last_solve: JacobianSolve::NotNeeded,
        })
    }

    /// How `J^-T` was obtained at the last step.
    #[must_use]
    pub fn last_solve(&self) -> JacobianSolve {
        self.last_solve
    }

    /// The force law.
    #[must_use]
    pub fn force_law(&self) -> &ForcePi {
        &self.force
    }

    /// The position controller.
    #[must_use]
    pub fn position_controller(&self) -> &P {
        &self.position
    }
}

impl<const N: usize, R: RobotModel<N>, P: Controller<N>> Controller<N>
    for HybridForcePosition<N, R, P>
{
    fn name(&self) -> &'static str {
        if self.force.kvd() == 0.0 {
            "hybrid-pi-ff"
        } else {
            "hybrid-pi-ff-vd"
        }
    }

    fn reset(&mut self) {
        self.position.reset();
        self.force.reset();
        self.last_solve = JacobianSolve::NotNeeded;
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let tau_p = self.position.step(input, dt);
        let s = self.selection.at(input.t);
        let j = self.robot.jacobian(input.q);
        let jr = JointMatrix::<N>::from_fn(|r, c| j[(self.rows[r], c)]);
        let twist: Wrench = j * input.qd;
        let mut force_weight = Wrench::zeros();
        for r in self.rows {
            force_weight[r] = 1.0 - s[r];
        }
        let f_f = self
            .force
            .step(input.wrench_ref, input.wrench, &twist, &force_weight, dt);
        if self.rows.iter().all(|&r| s[r] == 1.0) {
            self.last_solve = JacobianSolve::NotNeeded;
            return tau_p;
        }
        let (f_p, how) = reduced_transpose_solve(&jr, &tau_p);
        self.last_solve = how;
        let f_cmd = JointVector::<N>::from_fn(|i, _| {
            let r = self.rows[i];
            s[r] * f_p[i] + (1.0 - s[r]) * f_f[r]
        });
        jr.transpose() * f_cmd
    }
}
