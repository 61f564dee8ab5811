//! Controllers for deployment on a microcontroller: allocation-free, `no_std`, and generic
//! over the scalar, so that they run in `f32` on an FPU that has no `f64` (Cortex-M4F) as well
//! as in `f64`.
//!
//! - [`ScaraScalar`]: `f32` or `f64`, each with the SCARA's generated functions in its own
//!   precision (`armdyn_generated::scara::f32` and `armdyn_generated::scara`).
//! - [`ScaraHybrid`]: the thesis's hybrid force/position step on the SCARA (PID with feedback
//!   linearization, PI + feedforward + velocity damping along a fixed normal, switch at a
//!   time) over either; its gains come from the `f64` design code of [`crate::control`].
//! - [`SupervisedHybrid`]: it inside the safety supervisor
//!   ([`SafetyMonitor`](crate::control::safety::SafetyMonitor)) in the same scalar, limits
//!   rounded from their `f64` statement: the step the firmware runs;
//! - [`Deployed`]: either as a [`Controller<4>`](crate::control::Controller), casting the inputs
//!   to its scalar and the torques back, for trials against the `f64` plant.
//!
//! The `f64` instantiation runs the same operations, in the same order, as
//! [`HybridForcePosition`](crate::control::hybrid::HybridForcePosition) in that configuration
//! (`tests/scara/deploy_hybrid.rs` requires them equal to the last bit over many states and steps).

mod controller;
mod error;
mod hybrid;
mod scalar;
mod supervised;

pub use controller::Deployed;
pub use error::DeployError;
pub use hybrid::{HybridInput, ScaraHybrid};
pub use scalar::ScaraScalar;
pub use supervised::SupervisedHybrid;
