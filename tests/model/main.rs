//! Tests of the generated models through `armdyn::model`: kinematics against numeric differentiation and an independent URDF reading, dynamics against energy and the Lagrangian, forward dynamics, single precision, and the generated extras.
//!
//! One test crate per area of `src/`, its files as modules (one link of the library per
//! area).

#[macro_use]
#[path = "../common/mod.rs"]
mod common;
mod cholesky;
mod derivatives;
mod dynamics;
mod energy;
mod forward_kinematics;
mod generated_extras;
mod generated_f32;
mod generated_lanes;
mod lu;
