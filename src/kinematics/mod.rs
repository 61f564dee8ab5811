//! Inverse kinematics for any arm, behind one interface.
//!
//! - [`InverseKinematics`]: joints for a task-space pose, from a seed configuration; a
//!   failure says how far from the target the best configuration found is, never a silent
//!   wrong answer.
//! - [`NumericalIk`]: damped least squares (Levenberg–Marquardt) on the generated Jacobian,
//!   joint limits respected, a stated tolerance and iteration cap, restarts when the seed
//!   leads nowhere, and for a redundant arm the solution nearest a stated posture.
//! - [`joint_rates`]: the joint velocity and acceleration that give a task-space velocity
//!   and acceleration at a configuration (damped near singularities).
//!
//! A robot's own closed form (the SCARA's, [`crate::robots::scara::ClosedFormIk`]) is that
//! robot's solver behind the same interface.
//!
//! Nothing here allocates; everything works in `no_std`.

pub mod numerical;
pub mod rates;

pub use numerical::{IkOptions, NumericalIk};
pub use rates::{
    joint_rates, null_space_part, null_space_step, JointRates, MAX_DAMPING, SINGULARITY_THRESHOLD,
};

use crate::model::JointVector;
use crate::target::CartesianTarget;

/// A solution of inverse kinematics.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IkSolution<const N: usize> {
    /// The joints, within their limits, rad or m.
    pub q: JointVector<N>,
    /// Distance of the tool from the target position, m.
    pub position_error_m: f64,
    /// Angle between the tool's orientation and the target's in the task's rotations, rad.
    pub orientation_error_rad: f64,
    /// Iterations used (0 for a closed form).
    pub iterations: usize,
}

/// Why inverse kinematics found no solution.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum IkError {
    /// A target or seed value is NaN or infinite.
    #[error("the target or the seed is not finite")]
    NonFinite,
    /// No configuration within the limits reached the tolerance: the closest one found is
    /// `position_error_m` and `orientation_error_rad` away (the target is out of reach, or
    /// only reachable past a joint limit).
    #[error("no solution within the joint limits: the closest configuration found is {:.3e} mm and {:.3e} degrees from the target after {iterations} iterations", position_error_m * 1e3, orientation_error_rad.to_degrees())]
    NotReached {
        /// Remaining position error, m.
        position_error_m: f64,
        /// Remaining orientation error, rad.
        orientation_error_rad: f64,
        /// Iterations used over every start.
        iterations: usize,
    },
    /// The target is reached only with a joint outside its limits (a closed form, which
    /// knows its solutions).
    #[error("every solution puts joint {} at {value}, outside its limits [{lower}, {upper}]", joint + 1)]
    OutsideLimits {
        /// The joint, from 0.
        joint: usize,
        /// Its value there, rad or m.
        value: f64,
        /// Lower limit.
        lower: f64,
        /// Upper limit.
        upper: f64,
    },
}

/// Inverse kinematics of one robot: the joints that put its end effector at a pose, in the
/// robot's task directions ([`crate::model::RobotModel::TASK`]).
pub trait InverseKinematics<const N: usize> {
    /// Joints that put the tool at `target`'s position and orientation (its velocity and
    /// acceleration are not used), starting from or near `seed`.
    ///
    /// # Errors
    ///
    /// [`IkError`]: no solution within the limits (with the remaining error), or a
    /// non-finite input.
    fn solve(
        &self,
        target: &CartesianTarget,
        seed: &JointVector<N>,
    ) -> Result<IkSolution<N>, IkError>;
}
