//! What the solvers of [`ilqr`](super::ilqr) and [`terminal_cost`](super::terminal_cost)
//! share: the problem checked and set up, trajectories and multipliers.

use nalgebra::DVector;

use super::problem::{MoveProblem, PlanError};
use crate::model::{DynamicsDerivatives, JointVector};

/// The problem after checking, with the vectors the solver needs.
pub(super) struct Setup<'r, const N: usize, R> {
    pub(super) robot: &'r R,
    pub(super) steps: usize,
    pub(super) h: f64,
    pub(super) substeps: usize,
    pub(super) effort: JointVector<N>,
    pub(super) share: f64,
    pub(super) lower: JointVector<N>,
    pub(super) upper: JointVector<N>,
    pub(super) speed: JointVector<N>,
    pub(super) start: DVector<f64>,
    pub(super) goal: DVector<f64>,
}

/// Inequality rows per joint: position above, below; velocity above, below.
pub(super) const LIMIT_ROWS: usize = 4;

/// A speed limit that never binds.
pub(super) const NO_SPEED_LIMIT: f64 = 1e300;

/// Multipliers and penalty of the augmented Lagrangian.
pub(super) struct Multipliers {
    /// Goal, `2N`.
    pub(super) goal: DVector<f64>,
    /// Joint limits at knots 1..=K: `[upper; lower; speed up; speed down]`, `4N` each.
    pub(super) limits: Vec<DVector<f64>>,
    pub(super) penalty: f64,
}

/// A trajectory: states `x_0..=x_K`, controls `v_0..v_(K-1)` (torque shares).
#[derive(Clone)]
pub(super) struct Trajectory {
    pub(super) x: Vec<DVector<f64>>,
    pub(super) v: Vec<DVector<f64>>,
    /// Per knot step, the RK4 stages' accelerations of its roll-out (`4 substeps N`), so that
    /// the Jacobians need only the derivatives; empty where not recorded.
    pub(super) stages: Vec<Vec<f64>>,
}

pub(super) fn split<const N: usize>(x: &DVector<f64>) -> (JointVector<N>, JointVector<N>) {
    (
        JointVector::<N>::from_fn(|i, _| x[i]),
        JointVector::<N>::from_fn(|i, _| x[N + i]),
    )
}

pub(super) fn join<const N: usize>(q: &JointVector<N>, qd: &JointVector<N>) -> DVector<f64> {
    DVector::from_fn(2 * N, |i, _| if i < N { q[i] } else { qd[i - N] })
}

/// `problem` checked (each bad setting named) and set up for `robot`.
pub(super) fn setup<'r, const N: usize, R: DynamicsDerivatives<N>>(
    robot: &'r R,
    problem: &MoveProblem<N>,
) -> Result<Setup<'r, N, R>, PlanError> {
    let setting = |m: &str| Err(PlanError::Setting(m.into()));
    if !(problem.duration_s.is_finite() && problem.duration_s > 0.0) {
        return setting("the duration must be a positive number of seconds");
    }
    if !(problem.step_s.is_finite() && problem.step_s > 0.0 && problem.step_s <= problem.duration_s)
    {
        return setting("the knot step must be positive and at most the duration");
    }
    let steps_f = (problem.duration_s / problem.step_s).round();
    if steps_f > 1e6 {
        return setting("the duration holds more than a million knot steps: use a larger step");
    }
    if !(problem.max_effort_share > 0.0 && problem.max_effort_share <= 1.0) {
        return setting("the effort share must be in (0, 1]");
    }
    if !(problem.limit_margin.is_finite() && problem.limit_margin >= 0.0) {
        return setting("the joint-limit margin must be >= 0");
    }
    if let Some(v) = &problem.max_joint_speed {
        if let Some(i) = (0..N).find(|&i| v[i].is_nan() || v[i] <= 0.0) {
            return Err(PlanError::Setting(format!(
                "the speed limit of joint `{}` must be > 0 (got {})",
                R::JOINT_NAMES[i],
                v[i]
            )));
        }
    }
    let lower = robot.lower_limits().add_scalar(problem.limit_margin);
    let upper = robot.upper_limits().add_scalar(-problem.limit_margin);
    for (name, q) in [("start", &problem.from), ("goal", &problem.to)] {
        if let Some(i) =
            (0..N).find(|&i| !(q[i].is_finite() && q[i] >= lower[i] && q[i] <= upper[i]))
        {
            return Err(PlanError::Setting(format!(
                "the {name} configuration's joint `{}` = {} is outside its limits [{}, {}] (less the margin {})",
                R::JOINT_NAMES[i],
                q[i],
                lower[i] - problem.limit_margin,
                upper[i] + problem.limit_margin,
                problem.limit_margin
            )));
        }
    }
    if problem.substeps == 0 || problem.substeps > 1000 {
        return setting("the RK4 steps per knot step must be between 1 and 1000");
    }
    let steps = (steps_f as usize).max(1);
    Ok(Setup {
        robot,
        steps,
        h: problem.step_s,
        substeps: problem.substeps,
        effort: robot.effort_limits(),
        share: problem.max_effort_share,
        lower,
        upper,
        speed: problem
            .max_joint_speed
            .unwrap_or(JointVector::<N>::repeat(NO_SPEED_LIMIT)),
        start: join(&problem.from, &JointVector::<N>::zeros()),
        goal: join(&problem.to, &JointVector::<N>::zeros()),
    })
}
