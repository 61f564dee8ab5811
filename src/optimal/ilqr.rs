//! Control-limited iLQR with an augmented Lagrangian: the minimum-effort joint move between
//! two configurations of any robot in a given time.
//!
//! ```text
//! x_k = [q_k; qd_k],  v_k = tau_k / e   (torque as a share of each effort limit e_i)
//! x_(k+1) = f(x_k, v_k):   RK4 of qdd = FD(q, qd, e v) over h, torque held (substeps RK4 steps)
//! minimise   sum_k h |v_k|^2                                   (effort: integral of sum (tau_i/e_i)^2)
//! subject to |v_k,i| <= s                 (torque limits: a box in each backward-pass QP)
//!            lo_i <= q_k,i <= hi_i         (joint limits: augmented Lagrangian)
//!            |qd_k,i| <= vmax_i            (speed limits, if any: augmented Lagrangian)
//!            x_K = [q_goal; 0]             (rest at the goal: augmented Lagrangian)
//! ```
//!
//! The dynamics hold the torque over each knot step `h` and integrate it as a simulated
//! plant does (`substeps` RK4 steps): the plan is the plant's own sampled trajectory, so a
//! computed-torque controller sampled at the knots reproduces its torques. The Jacobians
//! `A = df/dx`, `B = df/dv` are the chain rule through the RK4 stages of the generated
//! derivatives `d qdd/d q`, `d qdd/d qd`, `M^-1` ([`DynamicsDerivatives`], via
//! [`knot_step_with`]).
//!
//! Each iteration is a Gauss–Newton backward pass (second derivatives of `f` dropped, as in
//! iLQR) whose control step is a box QP ([`box_qp`](super::box_qp): the torque limits hold
//! exactly, and feedback acts only on the controls not at a limit: Tassa, Mansard and
//! Todorov, "Control-limited differential dynamic programming", 2014), then a forward pass
//! with a backtracking line search on the merit (cost plus the augmented-Lagrangian terms),
//! and Levenberg–Marquardt regularisation of `Q_uu` when a pass fails. Around it the
//! augmented Lagrangian updates the multipliers of the goal and the joint limits and raises
//! the penalty while the violation does not shrink (as in ALTRO, Howell, Jackson and
//! Manchester 2019), until the violation is below [`IlqrOptions::tolerance`].

use nalgebra::DVector;

use super::backward_pass::{Blocks, KnotGains, KnotJacobian};
use super::free_space_step::knot_step_with;
use super::problem::{MoveProblem, OptimalMove, PlanError};
use super::quintic::quintic;
use super::setup::{join, setup, split, Multipliers, Setup, Trajectory, LIMIT_ROWS};
use crate::model::{DynamicsDerivatives, JointMatrix, JointVector, ModelError};
use crate::sim::rk4::rk4_step;

/// Settings of the solver.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IlqrOptions {
    /// Iterations per augmented-Lagrangian round (default 200).
    pub max_iterations: usize,
    /// Augmented-Lagrangian rounds (default 30).
    pub max_rounds: usize,
    /// Largest violation accepted: goal error (rad or m, and rad/s or m/s) and joint-limit
    /// excess (default 1e-6).
    pub tolerance: f64,
    /// First penalty weight (default 10).
    pub initial_penalty: f64,
    /// Factor the penalty grows by when a round does not cut the violation by 4 (default 10).
    pub penalty_growth: f64,
    /// Largest penalty weight (default 1e10).
    pub max_penalty: f64,
}

impl Default for IlqrOptions {
    fn default() -> Self {
        Self {
            max_iterations: 200,
            max_rounds: 30,
            tolerance: 1e-6,
            initial_penalty: 10.0,
            penalty_growth: 10.0,
            max_penalty: 1e10,
        }
    }
}

/// An augmented-Lagrangian round's iLQR stops when an accepted step improves the merit by
/// less than this share (the multipliers change after it anyway; the last round's
/// violation is what [`IlqrOptions::tolerance`] checks).
const INNER_TOLERANCE: f64 = 1e-7;

impl<const N: usize, R: DynamicsDerivatives<N>> Setup<'_, N, R> {
    /// `f(x, v)`: the knot step `h` as `substeps` RK4 steps with the torque held.
    pub(super) fn step(
        &self,
        x: &DVector<f64>,
        v: &DVector<f64>,
    ) -> Result<DVector<f64>, ModelError> {
        self.step_recording(x, v, &mut Vec::new())
    }

    /// [`Self::step`], appending the stages' accelerations to `stages` (for
    /// [`knot_step_with`]).
    pub(super) fn step_recording(
        &self,
        x: &DVector<f64>,
        v: &DVector<f64>,
        stages: &mut Vec<f64>,
    ) -> Result<DVector<f64>, ModelError> {
        let (mut q, mut qd) = split::<N>(x);
        let tau = self.torque(v);
        let h = self.h / self.substeps as f64;
        for _ in 0..self.substeps {
            (q, qd) = rk4_step(&q, &qd, h, |q, qd| {
                let a = self.robot.forward_dynamics(q, qd, &tau)?;
                stages.extend(a.iter());
                Ok::<_, ModelError>(a)
            })?;
        }
        Ok(join(&q, &qd))
    }

    /// The torque of the control `v`: `tau_i = e_i v_i` (N m or N).
    fn torque(&self, v: &DVector<f64>) -> JointVector<N> {
        JointVector::<N>::from_fn(|i, _| self.effort[i] * v[i])
    }

    /// `A = df/dx`, `B = df/dv` at `(x, v)`: the chain rule through the RK4 stages
    /// ([`knot_step_with`], in free space without end stops or friction); `stages`: the
    /// roll-out's stage accelerations of this step, if recorded.
    fn jacobians(
        &self,
        x: &DVector<f64>,
        v: &DVector<f64>,
        stages: Option<&Vec<f64>>,
    ) -> Result<KnotJacobian<N>, ModelError> {
        let (q, qd) = split::<N>(x);
        let tau = self.torque(v);
        let h = self.h / self.substeps as f64;
        let known = stages.map(Vec::as_slice);
        let s = knot_step_with(self.robot, &q, &qd, &tau, self.substeps, h, known)?;
        let effort = JointMatrix::<N>::from_diagonal(&self.effort);
        Ok(KnotJacobian {
            a: Blocks {
                qq: s.dq.q,
                qv: s.dq.qd,
                vq: s.dqd.q,
                vv: s.dqd.qd,
            },
            b: [s.dq.tau * effort, s.dqd.tau * effort],
        })
    }

    /// Joint-limit excesses at `x`: `[q - upper; lower - q; qd - vmax; -vmax - qd]`
    /// (positive: violated).
    pub(super) fn limit_excess(&self, x: &DVector<f64>) -> DVector<f64> {
        DVector::from_fn(LIMIT_ROWS * N, |i, _| {
            let j = i % N;
            match i / N {
                0 => x[j] - self.upper[j],
                1 => self.lower[j] - x[j],
                2 => x[N + j] - self.speed[j],
                _ => -self.speed[j] - x[N + j],
            }
        })
    }

    /// The largest violation of a trajectory: goal error and joint-limit excess.
    fn violation(&self, t: &Trajectory) -> f64 {
        let goal = (&t.x[self.steps] - &self.goal).amax();
        let limits = t.x[1..]
            .iter()
            .map(|x| self.limit_excess(x).max().max(0.0))
            .fold(0.0, f64::max);
        goal.max(limits)
    }

    /// The effort `sum h |v|^2`.
    pub(super) fn effort_of(&self, t: &Trajectory) -> f64 {
        t.v.iter().map(|v| self.h * v.norm_squared()).sum()
    }

    /// The merit: effort plus the augmented-Lagrangian terms.
    pub(super) fn merit(&self, t: &Trajectory, m: &Multipliers) -> f64 {
        let rho = m.penalty;
        let mut total = self.effort_of(t);
        for (k, x) in t.x[1..].iter().enumerate() {
            let g = self.limit_excess(x);
            for i in 0..LIMIT_ROWS * N {
                let lam = m.limits[k][i];
                let a = (lam + rho * g[i]).max(0.0);
                total += (a * a - lam * lam) / (2.0 * rho);
            }
        }
        let c = &t.x[self.steps] - &self.goal;
        total + m.goal.dot(&c) + 0.5 * rho * c.norm_squared()
    }

    /// Rolls the plan forward from the start with feedback: `v = clamp(v + alpha k + K dx)`.
    fn forward(
        &self,
        nominal: &Trajectory,
        gains: &[KnotGains<N>],
        alpha: f64,
    ) -> Option<Trajectory> {
        let mut x = Vec::with_capacity(self.steps + 1);
        let mut v = Vec::with_capacity(self.steps);
        let mut stages = Vec::with_capacity(self.steps);
        x.push(self.start.clone());
        for k in 0..self.steps {
            let (dq, dqd) = split::<N>(&(&x[k] - &nominal.x[k]));
            let change = gains[k].control(alpha, &dq, &dqd);
            let vk = DVector::from_fn(N, |i, _| {
                (nominal.v[k][i] + change[i]).clamp(-self.share, self.share)
            });
            let mut recorded = Vec::with_capacity(4 * self.substeps * N);
            let next = self.step_recording(&x[k], &vk, &mut recorded).ok()?;
            if !next.iter().all(|s| s.is_finite()) {
                return None;
            }
            x.push(next);
            v.push(vk);
            stages.push(recorded);
        }
        Some(Trajectory { x, v, stages })
    }
}

/// The first trajectory: a reference tracked by computed torque (natural frequency
/// 30 rad/s) on the discrete dynamics, torques clamped to the box. The reference is the
/// rest-to-rest quintic from start to goal, or `warm` (an earlier plan between the same
/// configurations) scaled in time to this duration.
fn initial<const N: usize, R: DynamicsDerivatives<N>>(
    s: &Setup<'_, N, R>,
    p: &MoveProblem<N>,
    warm: Option<&OptimalMove<N>>,
) -> Result<Trajectory, ModelError> {
    let total = s.h * s.steps as f64;
    let (kp, kd) = (900.0, 60.0);
    let mut x = vec![s.start.clone()];
    let mut v = Vec::with_capacity(s.steps);
    for k in 0..s.steps {
        let t = k as f64 * s.h;
        let (qr, qdr, qddr) = match warm {
            Some(w) => {
                let r = w.duration_s() / total;
                let j = w.at(t * r);
                (j.q, j.qd * r, j.qdd * (r * r))
            }
            None => {
                let j = quintic(&p.from, &p.to, total, (t / total).clamp(0.0, 1.0));
                (j.q, j.qd, j.qdd)
            }
        };
        let (q, qd) = split::<N>(&x[k]);
        let a = qddr + (qr - q) * kp + (qdr - qd) * kd;
        let tau = s.robot.inverse_dynamics(&q, &qd, &a);
        let vk = DVector::from_fn(N, |i, _| (tau[i] / s.effort[i]).clamp(-s.share, s.share));
        let next = s.step(&x[k], &vk)?;
        x.push(next);
        v.push(vk);
    }
    Ok(Trajectory {
        x,
        v,
        stages: Vec::new(),
    })
}

/// The minimum-effort move of `problem` (see the [module documentation](self)).
///
/// # Errors
///
/// [`PlanError::Setting`] for a bad setting (named), [`PlanError::Model`] if the model fails,
/// [`PlanError::Infeasible`] if the goal or the limits cannot be met within the effort share.
pub fn optimise_move<const N: usize, R: DynamicsDerivatives<N>>(
    robot: &R,
    problem: &MoveProblem<N>,
    options: &IlqrOptions,
) -> Result<OptimalMove<N>, PlanError> {
    optimise_move_from(robot, problem, options, None)
}

/// As [`optimise_move`], starting from `warm` (an earlier plan between the same two
/// configurations, of any duration) scaled in time instead of the quintic.
///
/// # Errors
///
/// As [`optimise_move`].
pub fn optimise_move_from<const N: usize, R: DynamicsDerivatives<N>>(
    robot: &R,
    problem: &MoveProblem<N>,
    options: &IlqrOptions,
    warm: Option<&OptimalMove<N>>,
) -> Result<OptimalMove<N>, PlanError> {
    let s = setup(robot, problem)?;
    let steps = s.steps;
    let mut m = Multipliers {
        goal: DVector::zeros(2 * N),
        limits: vec![DVector::zeros(LIMIT_ROWS * N); steps],
        penalty: options.initial_penalty,
    };
    let mut t = initial(&s, problem, warm)?;
    let mut iterations = 0;
    let mut violation = s.violation(&t);
    let mut stalled = 0;
    for _round in 0..options.max_rounds {
        iterations += inner_solve(&s, &mut t, &m, options.max_iterations)?;
        let new_violation = s.violation(&t);
        if new_violation <= options.tolerance {
            violation = new_violation;
            break;
        }
        // Multiplier updates: lambda <- lambda + rho c (goal), max(0, lambda + rho g) (limits).
        let rho = m.penalty;
        let c = &t.x[steps] - &s.goal;
        m.goal += &c * rho;
        for (k, x) in t.x[1..].iter().enumerate() {
            let g = s.limit_excess(x);
            for i in 0..LIMIT_ROWS * N {
                m.limits[k][i] = (m.limits[k][i] + rho * g[i]).max(0.0);
            }
        }
        // At the largest penalty, a violation that no longer halves per round will not
        // reach the tolerance: the move is infeasible (two such rounds in a row).
        if m.penalty >= options.max_penalty && new_violation > 0.5 * violation {
            stalled += 1;
            if stalled >= 2 {
                violation = new_violation;
                break;
            }
        } else {
            stalled = 0;
        }
        if new_violation > 0.25 * violation {
            m.penalty = (m.penalty * options.penalty_growth).min(options.max_penalty);
        }
        violation = new_violation;
    }
    if violation > options.tolerance {
        return Err(PlanError::Infeasible {
            duration_s: problem.duration_s,
            iterations,
            violation,
        });
    }
    finish(&s, &t, iterations, violation).map_err(PlanError::from)
}

/// The plan of trajectory `t`: knots, accelerations, torques and its figures.
pub(super) fn finish<const N: usize, R: DynamicsDerivatives<N>>(
    s: &Setup<'_, N, R>,
    t: &Trajectory,
    iterations: usize,
    violation: f64,
) -> Result<OptimalMove<N>, ModelError> {
    let steps = s.steps;
    let mut qdd = Vec::with_capacity(steps);
    let mut tau = Vec::with_capacity(steps);
    for k in 0..steps {
        let (q, qd) = split::<N>(&t.x[k]);
        let torque = s.torque(&t.v[k]);
        qdd.push(s.robot.forward_dynamics(&q, &qd, &torque)?);
        tau.push(torque);
    }
    let peak = t.v.iter().map(|v| v.amax()).fold(0.0, f64::max);
    Ok(OptimalMove {
        step_s: s.h,
        effort: s.effort_of(t),
        q: t.x.iter().map(|x| split::<N>(x).0).collect(),
        qd: t.x.iter().map(|x| split::<N>(x).1).collect(),
        qdd,
        tau,
        peak_effort_share: peak,
        iterations,
        violation,
    })
}

/// iLQR on the merit with fixed multipliers: returns the iterations spent.
pub(super) fn inner_solve<const N: usize, R: DynamicsDerivatives<N>>(
    s: &Setup<'_, N, R>,
    t: &mut Trajectory,
    m: &Multipliers,
    max_iterations: usize,
) -> Result<usize, ModelError> {
    let mut mu = 0.0_f64;
    let mut merit = s.merit(t, m);
    for it in 0..max_iterations {
        let jac = (0..s.steps)
            .map(|k| s.jacobians(&t.x[k], &t.v[k], t.stages.get(k)))
            .collect::<Result<Vec<_>, _>>()?;
        let mut improved = false;
        let mut converged = false;
        while mu <= 1e10 {
            let Some((gains, dv1, dv2)) = s.backward(t, &jac, m, mu) else {
                mu = (mu * 10.0).max(1e-6);
                continue;
            };
            if -dv1 <= INNER_TOLERANCE * 1e-2 * (1.0 + merit.abs()) {
                converged = true;
                break;
            }
            let mut alpha = 1.0;
            while alpha > 1e-4 {
                if let Some(candidate) = s.forward(t, &gains, alpha) {
                    let value = s.merit(&candidate, m);
                    let expected = -(alpha * dv1 + alpha * alpha * dv2);
                    if value.is_finite()
                        && merit - value > 1e-4 * expected.max(0.0)
                        && value < merit
                    {
                        let relative = (merit - value) / (1.0 + merit.abs());
                        *t = candidate;
                        merit = value;
                        improved = true;
                        converged = relative < INNER_TOLERANCE;
                        break;
                    }
                }
                alpha *= 0.5;
            }
            if improved {
                mu = if mu <= 1e-6 { 0.0 } else { mu / 10.0 };
                break;
            }
            mu = (mu * 10.0).max(1e-6);
        }
        if converged || !improved {
            return Ok(it + 1);
        }
    }
    Ok(max_iterations)
}
