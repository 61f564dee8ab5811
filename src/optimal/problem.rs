//! A joint move to optimise, the result, and why there may be none (solved by
//! [`ilqr`](super::ilqr)).

use crate::model::{JointVector, ModelError};

/// A rest-to-rest joint move to optimise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoveProblem<const N: usize> {
    /// Start configuration (at rest).
    pub from: JointVector<N>,
    /// Goal configuration (at rest).
    pub to: JointVector<N>,
    /// Duration, s.
    pub duration_s: f64,
    /// Knot spacing `h`, s: the move takes `round(T / h)` steps of exactly `h` (the duration is
    /// rounded to a whole number of steps, so that a controller of period `h` samples the knots).
    pub step_s: f64,
    /// RK4 steps per knot step (>= 1): the plan is the trajectory of a plant integrated
    /// so, with the torque held over each knot step (a simulated plant's control period and
    /// integration steps make it exactly that plant's).
    pub substeps: usize,
    /// Largest share of each effort limit any torque may use, in (0, 1].
    pub max_effort_share: f64,
    /// How far inside each joint limit the move stays, rad or m (>= 0).
    pub limit_margin: f64,
    /// Largest joint speed, rad/s or m/s, per joint (`None`: unlimited).
    pub max_joint_speed: Option<JointVector<N>>,
}

/// Why a move could not be optimised.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PlanError {
    /// A setting is out of range (the message names it).
    #[error("{0}")]
    Setting(String),
    /// The model failed at a state of the plan.
    #[error("the model failed during the optimisation: {0}")]
    Model(#[from] ModelError),
    /// The constraints could not be met (too short a time for the effort share).
    #[error(
        "no move within the limits found in {duration_s} s: after {iterations} iterations the \
         goal is missed by {violation:.3e} (rad, rad/s or m, m/s); allow more time or a larger \
         effort share"
    )]
    Infeasible {
        /// Duration tried, s.
        duration_s: f64,
        /// Iterations spent.
        iterations: usize,
        /// The violation left.
        violation: f64,
    },
}

/// An optimised move: knots every `step_s`, the torque held over each step.
#[derive(Clone, Debug, PartialEq)]
pub struct OptimalMove<const N: usize> {
    /// Knot spacing, s.
    pub step_s: f64,
    /// Joint positions at the knots (`steps + 1`).
    pub q: Vec<JointVector<N>>,
    /// Joint velocities at the knots (`steps + 1`).
    pub qd: Vec<JointVector<N>>,
    /// Acceleration at the start of each step, `FD(q_k, qd_k, tau_k)` (`steps`).
    pub qdd: Vec<JointVector<N>>,
    /// Torque over each step (`steps`), N m or N.
    pub tau: Vec<JointVector<N>>,
    /// The effort, `integral of sum_i (tau_i / e_i)^2 dt`, s.
    pub effort: f64,
    /// Largest `|tau_i| / e_i` over the move.
    pub peak_effort_share: f64,
    /// iLQR iterations over all rounds.
    pub iterations: usize,
    /// Violation left (goal error, joint-limit excess).
    pub violation: f64,
}

impl<const N: usize> OptimalMove<N> {
    /// Duration, s.
    #[must_use]
    pub fn duration_s(&self) -> f64 {
        self.step_s * self.qdd.len() as f64
    }
}
