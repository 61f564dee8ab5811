//! How a force law controls the motion directions: the loop that tracks the reference in
//! every task direction, told at each sample what to do along the contact normal
//! ([`NormalTarget`]), and whose command the force law then completes along the normal. Two
//! loops: [`JointLoop`](super::joint_loop::JointLoop), a joint-space position controller
//! acting through the robot's square task rows (the thesis's law, the SCARA's `x y z yaw`),
//! and [`TaskFrameLoop`](super::task_frame_loop::TaskFrameLoop), task-space inverse dynamics
//! in the full task frame with the tool held to the normal and a null-space posture.
//!
//! With `F_m` the loop's wrench and `df` what the force law adds along the linear rows:
//!
//! ```text
//! tau = J^T (F_m + df)        (+ the loop's own terms: c + g, the posture in the null space)
//! ```

use nalgebra::{SMatrix, Vector3};

use super::normal_reading::NormalReading;
use super::{ControllerInput, ToolState};
use crate::model::{JointVector, RobotModel};

/// What a motion loop tracks along the contact normal at one sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NormalTarget {
    /// The reference as it is (position control before a time switch): nothing to compute
    /// along the normal.
    Reference,
    /// The reference moved `offset_m` (m) along the outward normal at `rate_m_s` (m/s):
    /// negative into the surface (an approach), or an admittance's height. With
    /// `drop_normal_acceleration` the reference's own acceleration along the normal is
    /// taken out of the target.
    Moved {
        /// m.
        offset_m: f64,
        /// m/s.
        rate_m_s: f64,
        /// Whether the reference's normal acceleration is dropped.
        drop_normal_acceleration: bool,
    },
    /// The tool itself: the normal direction is the force law's, the loop sees only the
    /// errors across it.
    Free,
}

/// What a motion loop computed at one sample.
#[derive(Clone, Copy, Debug)]
pub enum Motion<C, const N: usize> {
    /// The torque, final (a loop that needs nothing along the normal, or one that cannot form
    /// its wrench at this state and falls back to holding the arm's own dynamics).
    Torque(JointVector<N>),
    /// A command for [`MotionLoop::torque`], whose wrench along the normal is `normal_n`, N.
    Command {
        /// The loop's command.
        command: C,
        /// `n . F_m`, N.
        normal_n: f64,
    },
}

/// A motion loop (see the [module documentation](self)). No allocation, no failure.
pub trait MotionLoop<const N: usize> {
    /// What the loop computes from the joint state once per sample and reuses.
    type Sample;
    /// A command before it becomes torque.
    type Command;
    /// Whether the loop acts in the full task frame (the laws' names say so).
    const FULL_FRAME: bool;

    /// The tool's position and velocity at `input`'s state, and the sample.
    fn sample<R: RobotModel<N>>(
        &self,
        robot: &R,
        input: &ControllerInput<'_, N>,
    ) -> (ToolState, Self::Sample);

    /// The command tracking `target` along the normal of `reading` (and the reference in
    /// every other direction), after `dt` s.
    #[allow(clippy::too_many_arguments)]
    fn command<R: RobotModel<N>>(
        &mut self,
        robot: &R,
        input: &ControllerInput<'_, N>,
        sample: &Self::Sample,
        tool: &ToolState,
        reading: &NormalReading,
        target: NormalTarget,
        dt: f64,
    ) -> Motion<Self::Command, N>;

    /// The torque of `command` with `df` (N, base frame) added to its linear rows.
    fn torque<R: RobotModel<N>>(
        &self,
        robot: &R,
        input: &ControllerInput<'_, N>,
        sample: &Self::Sample,
        command: Self::Command,
        df: Option<&Vector3<f64>>,
    ) -> JointVector<N>;

    /// The model's gravity along the normal in the loop's wrench, N (0 for a loop that
    /// compensates gravity in joint space).
    fn gravity_along_normal<R: RobotModel<N>>(
        &self,
        robot: &R,
        input: &ControllerInput<'_, N>,
        command: &Self::Command,
    ) -> f64;

    /// The linear rows of the Jacobian at the sample (m/s per unit joint velocity).
    fn linear_jacobian(&self, sample: &Self::Sample) -> SMatrix<f64, 3, N>;

    /// Clears the loop's state for a new run.
    fn reset(&mut self);
    /// How many numbers of state the loop carries ([`Controller::state_len`](super::Controller::state_len)).
    fn state_len(&self) -> usize;
    /// Writes the state into `out[..self.state_len()]`.
    fn write_state(&self, out: &mut [f64]);
    /// Sets the state from `x[..self.state_len()]`.
    fn read_state(&mut self, x: &[f64]);
}
