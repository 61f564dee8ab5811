//! What a reference gives the controller at one control sample.

use super::{CartesianTarget, JointTarget};
use nalgebra::Vector6;

/// `[fx fy fz tx ty tz]`.
type Wrench = Vector6<f64>;

/// Desired values at one control sample: the joint-space reference, the task-space one it
/// came from (or that it gives, for a joint-space reference), and the desired wrench of the
/// tool on the environment (base frame, `[fx fy fz tx ty tz]`, N and N m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setpoint<const N: usize> {
    /// Joint-space reference.
    pub joint: JointTarget<N>,
    /// Cartesian reference.
    pub cartesian: CartesianTarget,
    /// Desired wrench of the tool on the environment.
    pub wrench: Wrench,
}
