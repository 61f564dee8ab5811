//! Optimal control on the generated derivatives (feature `std`): minimum-effort and
//! shortest joint moves between two configurations of any robot, with torque and joint
//! limits.
//!
//! * [`ilqr`]: control-limited iLQR with an augmented Lagrangian for the goal and the joint
//!   limits ([`optimise_move`]);
//! * [`joint_move`]: the shortest move within an effort share ([`shortest_move`]) and the
//!   move as a joint reference ([`OptimalMove::at`]);
//! * [`quintic`](mod@quintic): the rest-to-rest quintic the moves are compared with and start from;
//! * [`problem`]: the move to optimise ([`MoveProblem`]), its result ([`OptimalMove`]) and
//!   its errors;
//! * [`terminal_cost`]: the move with a terminal cost instead of the goal constraint, as
//!   Crocoddyl poses it ([`optimise_with_terminal_cost`]);
//! * [`free_space_step`]: a knot step of the plans' dynamics and its Jacobians;
//! * [`box_qp`]: the bounded QP of each backward-pass step.

mod backward_pass;
pub mod box_qp;
pub mod free_space_step;
pub mod ilqr;
pub mod joint_move;
pub mod problem;
pub mod quintic;
mod setup;
pub mod terminal_cost;

pub use ilqr::{optimise_move, optimise_move_from, IlqrOptions};
pub use joint_move::shortest_move;
pub use problem::{MoveProblem, OptimalMove, PlanError};
pub use quintic::{
    quintic, quintic_effort, quintic_peak_effort_share, shortest_fitting, shortest_quintic,
};
pub use terminal_cost::{optimise_with_terminal_cost, TerminalCostMove};
