//! The checks and set-up shared by the solvers of [`ilqr`](super::ilqr) and
//! [`terminal_cost`](super::terminal_cost), and the plan made of a solved trajectory.

use super::ilqr::{join, split, Setup, Trajectory, NO_SPEED_LIMIT};
use super::problem::{MoveProblem, OptimalMove, PlanError};
use crate::model::{DynamicsDerivatives, JointVector, ModelError};

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
        let (_, a) = s.step(&t.x[k], &t.v[k])?;
        qdd.push(a);
        tau.push(JointVector::<N>::from_fn(|i, _| s.effort[i] * t.v[k][i]));
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
