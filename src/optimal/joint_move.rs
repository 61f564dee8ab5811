//! Joint moves between two configurations at rest: the optimised move as a joint reference
//! and the shortest optimised move within an effort share.
//!
//! ```text
//! shortest: min T such that the minimum-effort move of duration T keeps |tau_i| <= s e_i
//! ```
//!
//! The shortest optimised move is found by bisection on `T` between a lower bound and the
//! quintic's shortest duration within the same share (where a feasible move is known to
//! exist), each trial solved by [`optimise_move`]; a trial is feasible when the solver meets
//! the goal and the joint limits (the torque box holds by construction).

use super::ilqr::{optimise_move, optimise_move_from, IlqrOptions};
use super::problem::{MoveProblem, OptimalMove, PlanError};
use super::quintic::{shortest_quintic, DURATION_PRECISION, MAX_DURATION_S};
use crate::model::{DynamicsDerivatives, JointVector};
use crate::target::JointTarget;

/// Share of a step within which a time is taken as the knot ([`OptimalMove::at`]).
pub const KNOT_SNAP: f64 = 1e-3;

impl<const N: usize> OptimalMove<N> {
    /// The move as a joint reference at `t` s after its start: within step `k`, the cubic
    /// Hermite of `(q_k, qd_k)` and `(q_(k+1), qd_(k+1))` and its derivative, with
    /// `qdd = qdd_k` held (as the torque is); exact at the knots; held at the last knot
    /// after the end and at the first before the start.
    #[must_use]
    pub fn at(&self, t: f64) -> JointTarget<N> {
        let steps = self.qdd.len();
        let rest = |q: JointVector<N>| JointTarget {
            q,
            qd: JointVector::<N>::zeros(),
            qdd: JointVector::<N>::zeros(),
        };
        // A time within KNOT_SNAP of a step of a knot is that knot: a sampled caller's clock
        // is a sum of periods, and a move's start a sum of durations, not exact multiples.
        let h = self.step_s;
        let x = t / h;
        let x = if (x - x.round()).abs() < KNOT_SNAP {
            x.round()
        } else {
            x
        };
        if steps == 0 || x < 0.0 || !x.is_finite() {
            return rest(self.q[0]);
        }
        if x >= steps as f64 {
            return rest(self.q[steps]);
        }
        let k = (x.floor() as usize).min(steps - 1);
        let u = (x - k as f64).clamp(0.0, 1.0);
        let (u2, u3) = (u * u, u * u * u);
        let (h00, h10, h01, h11) = (
            2.0 * u3 - 3.0 * u2 + 1.0,
            u3 - 2.0 * u2 + u,
            -2.0 * u3 + 3.0 * u2,
            u3 - u2,
        );
        let (d00, d10, d01, d11) = (
            (6.0 * u2 - 6.0 * u) / h,
            3.0 * u2 - 4.0 * u + 1.0,
            (-6.0 * u2 + 6.0 * u) / h,
            3.0 * u2 - 2.0 * u,
        );
        let (q0, q1, v0, v1) = (self.q[k], self.q[k + 1], self.qd[k], self.qd[k + 1]);
        JointTarget {
            q: q0 * h00 + v0 * (h * h10) + q1 * h01 + v1 * (h * h11),
            qd: q0 * d00 + v0 * d10 + q1 * d01 + v1 * d11,
            qdd: self.qdd[k],
        }
    }
}

/// The shortest optimised move (see the [module documentation](self)): `problem`'s
/// duration is ignored; the result is the minimum-effort move at the shortest feasible
/// duration found (to [`DURATION_PRECISION`] or one knot step, whichever is longer).
///
/// # Errors
///
/// As [`optimise_move`] and [`shortest_quintic`].
pub fn shortest_move<const N: usize, R: DynamicsDerivatives<N>>(
    robot: &R,
    problem: &MoveProblem<N>,
    options: &IlqrOptions,
) -> Result<OptimalMove<N>, PlanError> {
    let quintic = shortest_quintic(robot, &problem.from, &problem.to, problem.max_effort_share)?;
    if quintic == 0.0 {
        return optimise_move(
            robot,
            &MoveProblem {
                duration_s: problem.step_s,
                ..*problem
            },
            options,
        );
    }
    // Each trial starts from the best plan so far, scaled in time.
    let attempt = |t: f64, warm: Option<&OptimalMove<N>>| {
        optimise_move_from(
            robot,
            &MoveProblem {
                duration_s: t.max(problem.step_s),
                ..*problem
            },
            options,
            warm,
        )
    };
    // The quintic's duration is feasible in continuous time; the discrete plan may need a
    // little more.
    let mut hi = quintic;
    let mut best = loop {
        match attempt(hi, None) {
            Ok(m) => break m,
            Err(PlanError::Infeasible { .. }) if hi < MAX_DURATION_S => hi *= 1.1,
            Err(e) => return Err(e),
        }
    };
    // A lower bound: halve from half the quintic's duration until a trial is infeasible.
    // (For a double integrator the bang-bang move at the quintic's peak acceleration,
    // 10 / sqrt(3) d / T^2, takes sqrt(4 sqrt(3) / 10) = 0.83 of the quintic's time; with
    // gravity and a configuration-dependent inertia the ratio can be smaller.)
    let mut lo = 0.5 * quintic;
    loop {
        if lo < 2.0 * problem.step_s {
            return Err(PlanError::Setting(format!(
                "the shortest move is under two knot steps ({} s): use a smaller step",
                problem.step_s
            )));
        }
        match attempt(lo, Some(&best)) {
            Ok(m) => {
                hi = lo;
                best = m;
                lo *= 0.5;
            }
            Err(PlanError::Infeasible { .. }) => break,
            Err(e) => return Err(e),
        }
    }
    // Bisection on whole numbers of steps (every duration is one: see MoveProblem::step_s).
    let h = problem.step_s;
    while hi - lo > (DURATION_PRECISION * hi).max(1.5 * h) {
        let mid = (0.5 * (lo + hi) / h).round() * h;
        if mid <= lo || mid >= hi {
            break;
        }
        match attempt(mid, Some(&best)) {
            Ok(m) => {
                hi = mid;
                best = m;
            }
            Err(PlanError::Infeasible { .. }) => lo = mid,
            Err(e) => return Err(e),
        }
    }
    Ok(best)
}
