//! Hybrid force/position control (thesis Section 5.2, eq. 5.4):
//!
//! ```text
//! tau = J^T ( S J^-T tau_p  +  (I - S) f_f )
//! ```
//!
//! `tau_p` is the joint-space position loop's torque (the thesis uses PID with feedback
//! linearization), mapped to Cartesian space by `J^-T`; `f_f` is the force loop's command
//! ([`ForcePi`]); `S` selects position control in the tangent directions of a task frame
//! and force control along its normal ([`TaskFrame`]), from a time or from detected contact
//! on ([`SelectionPolicy`]).
//!
//! `J` is the 6 x N geometric Jacobian reduced to the N task rows the robot can act in
//! (rows `vx vy vz wz` for the SCARA, whose rows `wx wy` are zero), so that it is square.
//! Singularities are handled explicitly, see [`reduced_transpose_solve`].

use super::force::ForcePi;
use super::selection::{Decision, SelectionPolicy, Supervisor};
use super::task_frame::TaskFrame;
use super::{Controller, ControllerInput};
use crate::contact::FRICTION_REGULARISATION_SPEED;
use crate::model::cholesky::Cholesky;
use crate::model::{Jacobian, JointMatrix, JointVector, RobotModel};
use nalgebra::Vector3;

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
/// Away from singularities (normalised determinant `m = |det J_r| / prod_i |row_i J_r|`
/// at or above [`SINGULARITY_THRESHOLD`]) `f = J_r^-T tau`, with `J_r^-1` from nalgebra's
/// fixed-size inverse (closed-form cofactors up to 4 x 4, LU beyond). Closer, damped least
/// squares `f = J_r (J_r^T J_r + lambda^2 I)^-1 tau` by a fixed-size Cholesky factorisation,
/// with `lambda = MAX_DAMPING (1 - m / SINGULARITY_THRESHOLD)`, growing smoothly from 0 at
/// the threshold, so the wrench stays bounded instead of the thesis's nudge of `q2` by 1e-4.
///
/// The test `m >= SINGULARITY_THRESHOLD` is first made without a determinant: by Hadamard's
/// inequality on the columns `c_i` of `J_r^-1`, `|det J_r| >= 1 / prod_i |c_i|`, so
/// `prod_i |row_i|^2 |c_i|^2 <= 1 / SINGULARITY_THRESHOLD^2` already proves it (squared:
/// no square root). Only where that bound is inconclusive is `m` computed, with
/// `|det J_r|` from the Cholesky factor of `J_r^T J_r`.
#[must_use]
pub fn reduced_transpose_solve<const N: usize>(
    jr: &JointMatrix<N>,
    tau: &JointVector<N>,
) -> (JointVector<N>, JacobianSolve) {
    let f = JacobianFactor::new(jr);
    (f.transpose_solve(tau), f.how())
}

/// The solve behind [`reduced_transpose_solve`] as one matrix `P` (N x N), kept to solve both
/// `J_r^T f = tau` (`f = P^T tau`) and `J_r dq = dx` (`dq = P dx`) at one state: `J_r^-1`,
/// or near a singularity the damped pseudo-inverse `(J_r^T J_r + lambda^2 I)^-1 J_r^T`, or
/// zero if even the damped system could not be factorised (a non-finite Jacobian).
///
/// Units: `P` maps task-space quantities (m, rad, N, N m) to joint-space ones (rad, m,
/// N m, N), the inverse of the Jacobian's.
#[derive(Clone, Copy, Debug)]
pub struct JacobianFactor<const N: usize> {
    p: JointMatrix<N>,
    how: JacobianSolve,
}

impl<const N: usize> JacobianFactor<N> {
    /// Factorises, damped near singularities as [`reduced_transpose_solve`] says.
    #[must_use]
    #[inline(always)]
    pub fn new(jr: &JointMatrix<N>) -> Self {
        // Product of the squared row norms of J_r (the denominator of m, squared).
        let rows_sq: f64 = (0..N).map(|i| jr.row(i).norm_squared()).product();
        if let Some(inverse) = jr.try_inverse() {
            let columns_sq: f64 = (0..N).map(|j| inverse.column(j).norm_squared()).product();
            let t2 = SINGULARITY_THRESHOLD * SINGULARITY_THRESHOLD;
            // Hadamard: m^2 >= 1 / (rows_sq columns_sq); NaN fails and goes on to `m`.
            if t2 * rows_sq * columns_sq <= 1.0 {
                return Self::exact(inverse);
            }
            let m = normalised_determinant(jr, rows_sq);
            if m >= SINGULARITY_THRESHOLD {
                return Self::exact(inverse);
            }
            return Self::damped(jr, MAX_DAMPING * (1.0 - m / SINGULARITY_THRESHOLD));
        }
        Self::damped(jr, MAX_DAMPING)
    }

    #[inline]
    fn exact(inverse: JointMatrix<N>) -> Self {
        Self {
            p: inverse,
            how: JacobianSolve::Exact,
        }
    }

    /// `P = (J_r^T J_r + lambda^2 I)^-1 J_r^T`, zero if the Cholesky factorisation fails.
    #[cold]
    fn damped(jr: &JointMatrix<N>, lambda: f64) -> Self {
        let a = jr.transpose() * jr
            + JointMatrix::<N>::identity() * (lambda * lambda).max(f64::MIN_POSITIVE);
        let p = match Cholesky::new(&a) {
            Ok(c) => {
                let mut p = JointMatrix::<N>::zeros();
                for j in 0..N {
                    p.set_column(j, &c.solve(&jr.row(j).transpose()));
                }
                p
            }
            Err(_) => JointMatrix::<N>::zeros(),
        };
        Self {
            p,
            how: JacobianSolve::Damped,
        }
    }

    /// How the factor was obtained.
    #[must_use]
    pub fn how(&self) -> JacobianSolve {
        self.how
    }

    /// The task wrench `f` with `J_r^T f = tau`: `P^T tau` (zero if even the damped system
    /// failed).
    #[must_use]
    #[inline]
    pub fn transpose_solve(&self, tau: &JointVector<N>) -> JointVector<N> {
        self.p.tr_mul(tau)
    }

    /// `J_r^T f` for the wrench `f = P^T tau` that [`Self::transpose_solve`] returns: `tau`
    /// itself when exact (`J_r^T J_r^-T = I`), `J_r^T J_r (J_r^T J_r + lambda^2 I)^-1 tau`
    /// when damped.
    #[must_use]
    #[inline]
    pub fn wrench_torque(&self, jr: &JointMatrix<N>, tau: &JointVector<N>) -> JointVector<N> {
        match self.how {
            JacobianSolve::Damped => jr.tr_mul(&self.p.tr_mul(tau)),
            _ => *tau,
        }
    }

    /// The joint displacement `dq` with `J_r dq = dx` (least squares, damped alike): `P dx`.
    #[must_use]
    #[inline]
    pub fn solve(&self, dx: &JointVector<N>) -> JointVector<N> {
        self.p * dx
    }
}

/// `m = |det J_r| / sqrt(rows_sq)`, with `|det J_r| = sqrt(det(J_r^T J_r))` read off the
/// diagonal of the Cholesky factor of `J_r^T J_r`; 0 where that factorisation fails (a
/// singular or non-finite `J_r`) or a row is zero.
#[cold]
fn normalised_determinant<const N: usize>(jr: &JointMatrix<N>, rows_sq: f64) -> f64 {
    match Cholesky::new(&jr.tr_mul(jr)) {
        Ok(c) if rows_sq > 0.0 => {
            let det: f64 = (0..N).map(|i| c.l()[(i, i)]).product();
            det / crate::math::sqrt(rows_sq)
        }
        _ => 0.0,
    }
}

/// The rows `rows` of the 6 x N Jacobian `j`, as an N x N matrix.
///
/// Each entry is picked by comparing its row index with 0..6 (selects on values held in
/// registers) rather than by indexing `j` in memory: the indexed gather writes the matrix
/// entry by entry and the inverse then reads it back 16 bytes at a time, a store-forwarding
/// stall in the SCARA's hybrid step (about 14 ns with the rows fixed at compile time; this
/// form removed about 9 ns of it in one measurement). Same values, bit for bit.
#[inline(always)]
fn reduced_rows<const N: usize>(j: &Jacobian<N>, rows: &[usize; N]) -> JointMatrix<N> {
    JointMatrix::<N>::from_fn(|r, c| {
        let k = rows[r];
        let mut x = j[(0, c)];
        for i in 1..6 {
            if k == i {
                x = j[(i, c)];
            }
        }
        x
    })
}

/// Hybrid force/position controller for an N-joint robot acting in N task directions, three
/// of them the linear velocity (rows 0, 1, 2 of the Jacobian).
///
/// Eq. 5.4 in a task frame whose first axis is the contact normal `n` ([`TaskFrame`]):
///
/// ```text
/// f_cmd = (I - n n^T) J^-T tau_p  +  n (f_f + g_n)  +  f_friction     (linear rows)
/// f_cmd = J^-T tau_p                                            (other task rows, e.g. wz)
/// tau   = J^T f_cmd
/// ```
///
/// with `f_f` the force law along `n` ([`ForcePi`]), `g_n = n . J^-T g(q)` the model's
/// gravity along the normal (optional, off in the thesis's law) and `f_friction = mu_nom |f_n| t_d`
/// the optional friction feedforward along the reference's tangential direction `t_d`. While
/// force is controlled the position loop's target is moved along `n` onto the tool (to first
/// order, through `J^-1`), so the joint-space position loop only sees tangential errors. When
/// force is controlled comes from the [`SelectionPolicy`]: at a fixed time (the thesis's
/// `S = diag(1, 1, 0, 1, 1, 1)` from 2 s is `TaskFrame::Fixed(z)` with
/// `SelectionPolicy::Time { switch_s: 2 }`, and equals it up to rounding), or on
/// detected contact with an approach, a ramp and bumpless transfer ([`Supervisor`]): at the
/// switch the normal command equals the position loop's last one, and the difference to the
/// force law's fades out linearly over the force reference's ramp.
///
/// One solve per step serves all of it: `a = J^-1 n` (the joint motion per metre along `n`)
/// moves the target, gives the position loop's force along the normal as
/// `n . J^-T tau_p = a . tau_p` and `g_n = a . g`, and
/// `tau = J^T J^-T tau_p + J^T (n (f_f + g_n - a . tau_p) + f_friction)`, where
/// `J^T J^-T tau_p = tau_p` unless the solve is damped ([`JacobianFactor::wrench_torque`]).
#[derive(Clone, Debug)]
pub struct HybridForcePosition<const N: usize, R, P> {
    robot: R,
    position: P,
    force: ForcePi,
    frame: TaskFrame,
    supervisor: Supervisor,
    rows: [usize; N],
    linear: [usize; 3],
    friction_feedforward: f64,
    normal_gravity: bool,
    anti_windup: bool,
    last_solve: JacobianSolve,
    last_normal_command: f64,
    transfer_offset: f64,
    force_active: bool,
}

impl<const N: usize, R: RobotModel<N>, P: Controller<N>> HybridForcePosition<N, R, P> {
    /// `rows`: the task rows of the 6 x N Jacobian kept (each in 0..6, distinct, including
    /// 0, 1 and 2), e.g. `[0, 1, 2, 5]` for a SCARA.
    ///
    /// Returns `None` if `rows` repeats a row, names one outside 0..6 or lacks a linear row.
    #[must_use]
    pub fn new(
        robot: R,
        position: P,
        force: ForcePi,
        frame: TaskFrame,
        selection: SelectionPolicy,
        rows: [usize; N],
    ) -> Option<Self> {
        for (i, r) in rows.iter().enumerate() {
            if *r >= 6 || rows[..i].contains(r) {
                return None;
            }
        }
        let find = |row: usize| rows.iter().position(|r| *r == row);
        let linear = [find(0)?, find(1)?, find(2)?];
        Some(Self {
            robot,
            position,
            force,
            frame,
            supervisor: Supervisor::new(selection),
            rows,
            linear,
            friction_feedforward: 0.0,
            normal_gravity: false,
            anti_windup: false,
            last_solve: JacobianSolve::NotNeeded,
            last_normal_command: 0.0,
            transfer_offset: 0.0,
            force_active: false,
        })
    }

    /// Adds the friction feedforward with nominal Coulomb coefficient `mu` (0: none).
    #[must_use]
    pub fn with_friction_feedforward(mut self, mu: f64) -> Self {
        self.friction_feedforward = mu;
        self
    }

    /// Keeps the model's gravity along the normal in the force command (`g_n` below): the
    /// thesis's law drops it with the position loop's normal row, and the force integral has
    /// to take it up slowly (the 48 N of d3's weight decaying with `(1 + Kfp) / Kfi = 4.2 s`).
    #[must_use]
    pub fn with_normal_gravity_compensation(mut self, on: bool) -> Self {
        self.normal_gravity = on;
        self
    }

    /// Conditional integration of the force law's integral (anti-windup): a period whose
    /// integral increment would drive an actuator further past its limit
    /// (`RobotModel::EFFORT_LIMITS`) is not integrated, and its increment is taken out of
    /// that period's command. Off in the thesis's law.
    #[must_use]
    pub fn with_anti_windup(mut self, on: bool) -> Self {
        self.anti_windup = on;
        self
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

    /// The switching state machine.
    #[must_use]
    pub fn supervisor(&self) -> &Supervisor {
        &self.supervisor
    }

    /// A task-space vector (reduced rows) whose linear rows are `v` and the others zero.
    fn lift(&self, v: &Vector3<f64>) -> JointVector<N> {
        let mut x = JointVector::<N>::zeros();
        for k in 0..3 {
            x[self.linear[k]] = v[k];
        }
        x
    }

    /// Conditional integration (see [`Self::with_anti_windup`]): `tau` without this period's
    /// integral increment if that increment pushes a saturated actuator further out.
    fn without_windup(
        &mut self,
        jr: &JointMatrix<N>,
        n: &Vector3<f64>,
        tau: JointVector<N>,
        integral_before: f64,
    ) -> JointVector<N> {
        let increment = self.force.kfi() * (self.force.integral() - integral_before);
        let dtau = jr.transpose() * self.lift(&(n * increment));
        let winds_up = (0..N).any(|i| tau[i].abs() > R::EFFORT_LIMITS[i] && dtau[i] * tau[i] > 0.0);
        if winds_up {
            self.force.set_integral(integral_before);
            tau - dtau
        } else {
            tau
        }
    }

    fn linear_part(&self, x: &JointVector<N>) -> Vector3<f64> {
        Vector3::new(x[self.linear[0]], x[self.linear[1]], x[self.linear[2]])
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
        self.supervisor.reset();
        self.last_solve = JacobianSolve::NotNeeded;
        self.last_normal_command = 0.0;
        self.transfer_offset = 0.0;
        self.force_active = false;
    }

    fn force_controlled(&self) -> bool {
        self.force_active
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        // J and the tool position p (m) in one call: the generated robots share sin/cos.
        let (j, p) = self.robot.jacobian_and_position(input.q);
        // The tool's linear velocity (rows vx vy vz of J qd), m/s.
        let v: Vector3<f64> = j.fixed_rows::<3>(0) * input.qd;
        let n = self.frame.normal_at(&p);
        let f_n = n.dot(&Vector3::new(
            input.wrench[0],
            input.wrench[1],
            input.wrench[2],
        ));
        let v_n = n.dot(&v);
        let contact_mode = matches!(self.supervisor.policy(), SelectionPolicy::Contact(_));
        let (ref_gap, tool_gap) = if contact_mode {
            (
                self.frame.signed_distance(&input.cartesian.position),
                self.frame.signed_distance(&p),
            )
        } else {
            (None, None)
        };
        let decision = self
            .supervisor
            .step(input.t, dt, -f_n, f_n, ref_gap, tool_gap);
        if let Decision::Position { .. } = decision {
            self.force_active = false;
            self.force.reset();
            self.last_solve = JacobianSolve::NotNeeded;
            if !contact_mode {
                return self.position.step(input, dt);
            }
        }
        let jr = reduced_rows(&j, &self.rows);
        let factor = JacobianFactor::new(&jr);
        // The joint motion per metre along the normal (one solve serves q and qd).
        let along_n = factor.solve(&self.lift(&n));
        match decision {
            Decision::Position {
                offset_m,
                offset_rate_m_s,
            } => {
                // The approach: the target moved `offset_m` into the surface along -n.
                let mut target = *input.target;
                target.q -= along_n * offset_m;
                target.qd -= along_n * offset_rate_m_s;
                let tau_p = self.position.step(
                    &ControllerInput {
                        target: &target,
                        ..*input
                    },
                    dt,
                );
                self.last_normal_command =
                    n.dot(&self.linear_part(&factor.transpose_solve(&tau_p)));
                tau_p
            }
            Decision::Force {
                just_switched,
                ramp,
                from_n,
            } => {
                self.force_active = true;
                // The position loop sees only tangential errors: its target is moved along
                // n onto the tool.
                let c = input.cartesian;
                let mut target = *input.target;
                target.q += along_n * n.dot(&(p - c.position));
                target.qd += along_n * n.dot(&(v - c.velocity));
                let tau_p = self.position.step(
                    &ControllerInput {
                        target: &target,
                        ..*input
                    },
                    dt,
                );
                self.last_solve = factor.how();
                // The position loop's force along n, n . J^-T tau_p, as (J^-1 n) . tau_p.
                let f_p_n = along_n.dot(&tau_p);
                let w = input.wrench_ref;
                let target_n = n.dot(&Vector3::new(w[0], w[1], w[2]));
                let f_d = if ramp >= 1.0 {
                    target_n
                } else {
                    from_n + (target_n - from_n) * ramp
                };
                let g_n = if self.normal_gravity {
                    // n . J^-T g, likewise.
                    along_n.dot(&self.robot.gravity(input.q))
                } else {
                    0.0
                };
                let integral_before = self.force.integral();
                let mut f_f = self.force.step(f_d, f_n, v_n, dt);
                if just_switched {
                    // Bumpless: the normal command starts where the position loop left off;
                    // the difference fades out over the force ramp.
                    self.transfer_offset = self.last_normal_command - g_n - f_f;
                }
                if ramp < 1.0 {
                    f_f += self.transfer_offset * (1.0 - ramp);
                }
                // f_cmd = f_p + df: the position loop's wrench with its normal component
                // replaced by the force command (and the friction feedforward added).
                let mut df = if self.normal_gravity {
                    n * (f_f + g_n - f_p_n)
                } else {
                    n * (f_f - f_p_n)
                };
                if self.friction_feedforward > 0.0 {
                    let vt = c.velocity - n * n.dot(&c.velocity);
                    let speed = crate::math::sqrt(vt.dot(&vt)).max(FRICTION_REGULARISATION_SPEED);
                    df += vt * (self.friction_feedforward * (-f_n).max(0.0) / speed);
                }
                // tau = J^T f_cmd = J^T f_p + J^T df, with J^T f_p = tau_p unless damped.
                let mut tau = factor.wrench_torque(&jr, &tau_p);
                for k in 0..3 {
                    tau += jr.row(self.linear[k]).transpose() * df[k];
                }
                if self.anti_windup {
                    return self.without_windup(&jr, &n, tau, integral_before);
                }
                tau
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Scara;

    /// The reduced SCARA Jacobian (rows vx vy vz wz) at `q`.
    fn jr(q: [f64; 4]) -> JointMatrix<4> {
        let j = Scara.jacobian(&JointVector::<4>::from(q));
        JointMatrix::<4>::from_fn(|r, c| j[([0, 1, 2, 5][r], c)])
    }

    /// `m` by its definition, with nalgebra's determinant.
    fn measure(jr: &JointMatrix<4>) -> f64 {
        let rows: f64 = (0..4).map(|i| jr.row(i).norm()).product();
        jr.determinant().abs() / rows
    }

    #[test]
    fn away_from_singularities_the_solves_are_exact() {
        let tau = JointVector::<4>::new(3.0, -2.0, 48.0, 0.5);
        // q2 = 0.8: the Hadamard bound settles it; q2 = 0.02: it does not, m = 0.008 does.
        for q2 in [0.8, -2.0, 0.02] {
            let jr = jr([0.3, q2, 0.2, 0.1]);
            let f = JacobianFactor::new(&jr);
            assert_eq!(f.how(), JacobianSolve::Exact, "q2 = {q2}");
            let w = f.transpose_solve(&tau);
            assert!((jr.transpose() * w - tau).norm() < 1e-12 * tau.norm());
            assert_eq!(f.wrench_torque(&jr, &tau), tau);
            let dq = f.solve(&tau);
            assert!((jr * dq - tau).norm() < 1e-12 * tau.norm() * dq.norm().max(1.0));
        }
    }

    #[test]
    fn near_a_singularity_the_solve_is_damped_by_the_documented_law() {
        let tau = JointVector::<4>::new(3.0, -2.0, 48.0, 0.5);
        let jr = jr([0.3, 1e-4, 0.2, 0.1]);
        let m = measure(&jr);
        assert!(m < SINGULARITY_THRESHOLD);
        let f = JacobianFactor::new(&jr);
        assert_eq!(f.how(), JacobianSolve::Damped);
        let lambda = MAX_DAMPING * (1.0 - m / SINGULARITY_THRESHOLD);
        let a = jr.transpose() * jr + JointMatrix::<4>::identity() * (lambda * lambda);
        let a_inv = a.try_inverse().unwrap();
        let expected = jr * a_inv * tau;
        let w = f.transpose_solve(&tau);
        assert!((w - expected).norm() < 1e-9 * expected.norm());
        let expected_dq = a_inv * jr.transpose() * tau;
        assert!((f.solve(&tau) - expected_dq).norm() < 1e-9 * expected_dq.norm());
        let expected_torque = jr.transpose() * expected;
        assert!((f.wrench_torque(&jr, &tau) - expected_torque).norm() < 1e-9 * tau.norm());
        // At the singularity itself, full damping; a NaN gives zero, damped.
        assert_eq!(
            JacobianFactor::new(&self::jr([0.3, 0.0, 0.2, 0.1])).how(),
            JacobianSolve::Damped
        );
        let mut bad = jr;
        bad[(1, 1)] = f64::NAN;
        let f = JacobianFactor::new(&bad);
        assert_eq!(f.how(), JacobianSolve::Damped);
        assert_eq!(f.transpose_solve(&tau), JointVector::<4>::zeros());
    }
}
