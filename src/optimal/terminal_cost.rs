//! The move with a terminal cost in place of the goal constraint: the problem as Crocoddyl
//! poses it (a shooting problem whose terminal model penalises the state's distance to the
//! goal), solved by the same control-limited iLQR as [`optimise_move`](super::optimise_move),
//! so that the two solvers can be run side by side on one problem (`benches/crocoddyl/`).
//!
//! ```text
//! minimise   sum_k h |v_k|^2  +  (w / 2) |x_K - [q_goal; 0]|^2       v_k = tau_k / e
//! subject to |v_k,i| <= s                     (torque limits: a box in each backward-pass QP)
//!            x_(k+1) = f(x_k, v_k)             (substeps RK4 steps of FD, torque held over h)
//! ```
//!
//! Unlike [`optimise_move`](super::optimise_move) there are no joint or speed limits (the
//! free forward dynamics of Crocoddyl has none), no multiplier updates (one iLQR run on a
//! fixed cost), and the first trajectory is the roll-out of torques the caller gives.

use nalgebra::DVector;

use super::ilqr::{finish, inner_solve};
use super::problem::{MoveProblem, OptimalMove, PlanError};
use super::setup::{setup, Multipliers, Trajectory, LIMIT_ROWS, NO_SPEED_LIMIT};
use crate::model::{DynamicsDerivatives, JointVector};

/// A solved terminal-cost move.
#[derive(Clone, Debug, PartialEq)]
pub struct TerminalCostMove<const N: usize> {
    /// The plan (its `violation` is the largest goal error left, rad or m and rad/s or m/s).
    pub plan: OptimalMove<N>,
    /// The cost at the solution, effort plus terminal cost, s.
    pub cost: f64,
    /// Its terminal part, `(w / 2) |x_K - x_goal|^2`.
    pub terminal_cost: f64,
    /// The cost of the first trajectory (the roll-out of the given torques).
    pub initial_cost: f64,
}

/// The minimum of effort plus `weight / 2` times the squared distance of the last state to
/// the goal at rest (see the [module documentation](self)), from the roll-out of
/// `initial_torques` (one per knot step, N m or N, clamped to the effort share), in at most
/// `max_iterations` iLQR iterations. `problem`'s joint-limit margin and speed limits are not
/// used; its start and goal must lie inside the joint limits.
///
/// # Errors
///
/// [`PlanError::Setting`] for a bad setting or initial torques of the wrong count or not
/// finite (named), [`PlanError::Model`] if the model fails.
pub fn optimise_with_terminal_cost<const N: usize, R: DynamicsDerivatives<N>>(
    robot: &R,
    problem: &MoveProblem<N>,
    weight: f64,
    initial_torques: &[JointVector<N>],
    max_iterations: usize,
) -> Result<TerminalCostMove<N>, PlanError> {
    if !(weight.is_finite() && weight > 0.0) {
        return Err(PlanError::Setting(format!(
            "the terminal weight must be a positive number (got {weight})"
        )));
    }
    if max_iterations == 0 {
        return Err(PlanError::Setting(
            "the iterations must be at least 1".into(),
        ));
    }
    let mut s = setup(robot, problem)?;
    if initial_torques.len() != s.steps {
        return Err(PlanError::Setting(format!(
            "{} initial torques for {} knot steps ({} s in steps of {} s): give one per step",
            initial_torques.len(),
            s.steps,
            problem.duration_s,
            problem.step_s
        )));
    }
    if let Some(k) = initial_torques
        .iter()
        .position(|t| !t.iter().all(|x| x.is_finite()))
    {
        return Err(PlanError::Setting(format!(
            "initial torque {k} is not finite"
        )));
    }
    // No joint or speed limits: bounds that never bind.
    s.lower = JointVector::<N>::repeat(-NO_SPEED_LIMIT);
    s.upper = JointVector::<N>::repeat(NO_SPEED_LIMIT);
    s.speed = JointVector::<N>::repeat(NO_SPEED_LIMIT);
    let mut t = Trajectory {
        x: Vec::with_capacity(s.steps + 1),
        v: Vec::with_capacity(s.steps),
        stages: Vec::new(),
    };
    t.x.push(s.start.clone());
    for (k, tau) in initial_torques.iter().enumerate() {
        let v = DVector::from_fn(N, |i, _| (tau[i] / s.effort[i]).clamp(-s.share, s.share));
        let next = s.step(&t.x[k], &v)?;
        t.x.push(next);
        t.v.push(v);
    }
    // Fixed multipliers of zero: the merit is the cost, effort + (w / 2) |x_K - x_goal|^2.
    let m = Multipliers {
        goal: DVector::zeros(2 * N),
        limits: vec![DVector::zeros(LIMIT_ROWS * N); s.steps],
        penalty: weight,
    };
    let initial_cost = s.merit(&t, &m);
    let iterations = inner_solve(&s, &mut t, &m, max_iterations)?;
    let cost = s.merit(&t, &m);
    let effort = s.effort_of(&t);
    let violation = (&t.x[s.steps] - &s.goal).amax();
    Ok(TerminalCostMove {
        plan: finish(&s, &t, iterations, violation)?,
        cost,
        terminal_cost: cost - effort,
        initial_cost,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{RobotModel, Ur5};

    fn problem() -> MoveProblem<6> {
        MoveProblem {
            from: JointVector::<6>::from([0.0, -1.2, 1.0, -0.5, 0.3, 0.0]),
            to: JointVector::<6>::from([0.8, -0.9, 0.6, -0.2, 0.5, 0.4]),
            duration_s: 1.0,
            step_s: 0.02,
            substeps: 1,
            max_effort_share: 0.5,
            limit_margin: 0.0,
            max_joint_speed: None,
        }
    }

    /// From gravity compensation at the start, the solver brings the arm near the goal at
    /// rest, within the torque box, at a cost far below the first trajectory's.
    #[test]
    fn reaches_the_goal_within_the_box_from_gravity_compensation() {
        let p = problem();
        let hold = vec![Ur5.gravity(&p.from); 50];
        let m = optimise_with_terminal_cost(&Ur5, &p, 1e4, &hold, 200).unwrap();
        assert!(
            m.cost < 0.05 * m.initial_cost,
            "{} {}",
            m.cost,
            m.initial_cost
        );
        assert!(m.plan.violation < 0.05, "goal error {}", m.plan.violation);
        assert!(m.plan.peak_effort_share <= 0.5 + 1e-12);
        assert!((m.cost - m.plan.effort - m.terminal_cost).abs() < 1e-12);
        // A larger weight buys a smaller goal error with more effort.
        let stiff = optimise_with_terminal_cost(&Ur5, &p, 1e6, &hold, 200).unwrap();
        assert!(stiff.plan.violation < m.plan.violation);
        assert!(stiff.plan.effort > m.plan.effort);
    }

    #[test]
    fn bad_settings_are_named() {
        let p = problem();
        let hold = vec![JointVector::<6>::zeros(); 50];
        let e = |w: f64, t: &[JointVector<6>]| {
            optimise_with_terminal_cost(&Ur5, &p, w, t, 10)
                .unwrap_err()
                .to_string()
        };
        assert!(e(0.0, &hold).contains("terminal weight"));
        assert!(e(1.0, &hold[..3]).contains("3 initial torques for 50 knot steps"));
        let mut bad = hold.clone();
        bad[7][2] = f64::NAN;
        assert_eq!(e(1.0, &bad), "initial torque 7 is not finite");
    }
}
