//! Joint moves between two configurations at rest: the optimised move as a joint reference,
//! the shortest optimised move within an effort share, and the quintic it is compared with.
//!
//! ```text
//! quintic:  q(t) = from + (to - from) S(t / T),   S(u) = 10 u^3 - 15 u^4 + 6 u^5
//! shortest: min T such that the minimum-effort move of duration T keeps |tau_i| <= s e_i
//! ```
//!
//! The shortest optimised move is found by bisection on `T` between a lower bound and the
//! quintic's shortest duration within the same share (where a feasible move is known to
//! exist), each trial solved by [`optimise_move`]; a trial is feasible when the solver meets
//! the goal and the joint limits (the torque box holds by construction).

use super::ilqr::{optimise_move, optimise_move_from, IlqrOptions};
use super::problem::{MoveProblem, OptimalMove, PlanError};
use crate::model::{DynamicsDerivatives, JointVector, RobotModel};
use crate::target::JointTarget;

/// Points at which a quintic's inverse dynamics is checked for its peak effort share.
pub const QUINTIC_SAMPLES: usize = 400;
/// Longest move searched, s.
pub const MAX_DURATION_S: f64 = 60.0;
/// Share of a step within which a time is taken as the knot ([`OptimalMove::at`]).
pub const KNOT_SNAP: f64 = 1e-3;
/// Relative precision of the shortest durations (bisection stops below it).
pub const DURATION_PRECISION: f64 = 2e-3;

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

/// The rest-to-rest quintic `from -> to` of duration `T` at the share `u` in `[0, 1]` of it:
/// `q = from + (to - from) S(u)`, `S(u) = 10 u^3 - 15 u^4 + 6 u^5`, and its rates.
#[must_use]
pub fn quintic<const N: usize>(
    from: &JointVector<N>,
    to: &JointVector<N>,
    duration_s: f64,
    u: f64,
) -> JointTarget<N> {
    let d = to - from;
    let t = duration_s;
    let (u2, u3) = (u * u, u * u * u);
    let s = u3 * (10.0 - 15.0 * u + 6.0 * u2);
    let ds = 30.0 * u2 * (1.0 - u) * (1.0 - u) / t;
    let dds = 60.0 * u * (1.0 - 3.0 * u + 2.0 * u2) / (t * t);
    JointTarget {
        q: from + d * s,
        qd: d * ds,
        qdd: d * dds,
    }
}

/// The largest `|tau_i| / e_i` of the rest-to-rest quintic `from -> to` of duration `T`
/// (inverse dynamics at [`QUINTIC_SAMPLES`] + 1 points).
#[must_use]
pub fn quintic_peak_effort_share<const N: usize, R: RobotModel<N>>(
    robot: &R,
    from: &JointVector<N>,
    to: &JointVector<N>,
    duration_s: f64,
) -> f64 {
    let limits = robot.effort_limits();
    (0..=QUINTIC_SAMPLES)
        .map(|k| {
            let j = quintic(from, to, duration_s, k as f64 / QUINTIC_SAMPLES as f64);
            let tau = robot.inverse_dynamics(&j.q, &j.qd, &j.qdd);
            (0..N)
                .map(|i| (tau[i] / limits[i]).abs())
                .fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

/// The effort `integral of sum_i (tau_i / e_i)^2 dt` of the rest-to-rest quintic
/// `from -> to` of duration `T`, s (midpoint rule over [`QUINTIC_SAMPLES`] intervals).
#[must_use]
pub fn quintic_effort<const N: usize, R: RobotModel<N>>(
    robot: &R,
    from: &JointVector<N>,
    to: &JointVector<N>,
    duration_s: f64,
) -> f64 {
    let limits = robot.effort_limits();
    let n = QUINTIC_SAMPLES as f64;
    (0..QUINTIC_SAMPLES)
        .map(|k| {
            let j = quintic(from, to, duration_s, (k as f64 + 0.5) / n);
            let tau = robot.inverse_dynamics(&j.q, &j.qd, &j.qdd);
            (0..N).map(|i| (tau[i] / limits[i]).powi(2)).sum::<f64>() * duration_s / n
        })
        .sum()
}

/// The shortest quintic `from -> to` whose peak effort share is at most `share` (to
/// [`DURATION_PRECISION`]); 0 if the two are equal.
///
/// # Errors
///
/// [`PlanError::Setting`] if even [`MAX_DURATION_S`] exceeds the share (gravity alone is
/// too much for it).
pub fn shortest_quintic<const N: usize, R: RobotModel<N>>(
    robot: &R,
    from: &JointVector<N>,
    to: &JointVector<N>,
    share: f64,
) -> Result<f64, PlanError> {
    if (to - from).amax() == 0.0 {
        return Ok(0.0);
    }
    let fits = |t: f64| quintic_peak_effort_share(robot, from, to, t) <= share;
    if !fits(MAX_DURATION_S) {
        return Err(PlanError::Setting(format!(
            "no quintic of up to {MAX_DURATION_S} s stays within an effort share of {share}: \
             holding the configurations takes more"
        )));
    }
    let (mut lo, mut hi) = (1e-3, MAX_DURATION_S);
    while hi - lo > DURATION_PRECISION * hi {
        let mid = 0.5 * (lo + hi);
        if fits(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Ok(hi)
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
