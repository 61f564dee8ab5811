//! What is special about particular robots, reached through the generic interfaces: a
//! robot's own closed-form inverse kinematics, its workspace and planning, its presets and
//! its deployable step. Everything else of the crate works on any robot of the registry.
//!
//! - [`scara`]: the thesis's SCARA.

pub mod scara;
