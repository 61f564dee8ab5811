//! The shared vocabulary of references, at the bottom of the house: what a reference asks of
//! the robot at one instant, in joint space ([`JointTarget`]) and in task space
//! ([`CartesianTarget`]: a full pose with its first two derivatives), what the simulator
//! hands a controller ([`Setpoint`]), and the angle and orientation helpers they need
//! ([`angle`], [`orientation`]).
//!
//! `control`, `kinematics`, `trajectory` and `sim` all import this module and none of them
//! imports another for these types, so the flow between them stays one-way.
//!
//! Orientations are unit quaternions (`nalgebra::UnitQuaternion`), angular velocities and
//! accelerations are vectors in the base frame (rad/s, rad/s^2), and the orientation error
//! is the SO(3) logarithm [`orientation::error`]: the rotation vector (axis times angle,
//! angle in `[0, pi]`) that turns the actual orientation into the desired one, base frame.
//! Roll, pitch and yaw are fixed axes x-y-z (REP-103): `R = Rz(yaw) Ry(pitch) Rx(roll)`.
//!
//! A robot's [`Task`] (which of the six directions its end effector is controlled in) and the
//! pose error in those directions are here too.
//!
//! Nothing here allocates; everything works in `no_std`. This module imports nothing else of
//! the crate.

pub mod angle;
mod joint;
pub mod orientation;
mod pose;
mod setpoint;
mod task;

pub use angle::wrap_angle;
pub use joint::JointTarget;
pub use pose::{CartesianTarget, PoseSample};
pub use setpoint::Setpoint;
pub use task::{Rotations, Task, DIRECTION_NAMES};
