//! The safety supervisor: checks around any controller, a latched reaction on a trip, and an
//! output stage that never lets a non-finite or too steep torque through.
//!
//! ```text
//! reading -> sensor health + spike filter -> controller -> state checks -> reaction? -> guard + slew -> tau
//! ```
//!
//! - [`SafetyLimits`]: what is checked ([`limits`]), and the [`Reaction`] latched on a trip;
//! - [`SafetyMonitor`]: the checks and the output stage over any scalar (`f64`, `f32`), for
//!   any controller loop, the host's or a microcontroller's;
//! - [`Supervised`]: a [`Controller`](super::Controller) inside the monitor, on a robot model;
//! - [`SafetyReport`]: what a run's supervisor saw (trips, counts, peaks).

pub mod force_watch;
pub mod limits;
pub mod monitor;
pub mod period_bounds;
pub mod precision;
pub mod reaction;
pub mod sensor_health;
mod supervised;
pub mod trip;

pub use limits::{ForceLimits, Reaction, SafetyLimits, SensorLimits};
pub use monitor::{Observation, Peaks, SafetyMonitor, SafetyReport};
pub use supervised::Supervised;
pub use trip::{Trip, TripCause, TripLog};
