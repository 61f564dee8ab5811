//! Environments the end effector can touch (thesis Section 5.1), and what a force sensor
//! reports of them.
//!
//! An [`Environment`] gives the wrench the tool exerts on it, base frame
//! `[fx fy fz tx ty tz]` (the thesis's `f_ext`), from the tool's position and velocity. The
//! plant feels `tau_ext = J^T f_ext` (`docs/thesis.md`, erratum 3). A [`ForceSensor`] adds bias,
//! noise and filtering to what a controller measures of it (the wrappers
//! [`Sensed`](crate::control::sensed::Sensed) and
//! [`SensedBehindTool`](crate::control::sensed_behind_tool::SensedBehindTool) of `control`).

use crate::model::Wrench;
use nalgebra::Vector3;

mod scene;
mod sensor;
mod surface;

pub use crate::surface::{
    plane_axes, Cylinder, Plane, Sphere, SurfaceGeometry, SurfacePoint,
    FRICTION_REGULARISATION_SPEED,
};
pub use scene::{ContactState, ContactSurface, Scene, MAX_SURFACES};
pub use sensor::{ForceSensor, SensorError};
pub use surface::{ReactionSurface, SurfaceError};

/// Something the end effector can push on.
pub trait Environment {
    /// The wrench the tool exerts on the environment at `position` (m) moving at
    /// `velocity` (m/s), base frame, N and N m. Exactly zero when not in contact.
    fn wrench(&self, position: &Vector3<f64>, velocity: &Vector3<f64>) -> Wrench;

    /// The wrench at time `t` (s): [`Self::wrench`] for an environment that does not change
    /// (the simulator calls this one; faults that act from a time on override it).
    fn wrench_at(&self, t: f64, position: &Vector3<f64>, velocity: &Vector3<f64>) -> Wrench {
        let _ = t;
        self.wrench(position, velocity)
    }
}

/// No contact anywhere: the free-space trials of Chapter 4.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FreeSpace;

impl Environment for FreeSpace {
    fn wrench(&self, _position: &Vector3<f64>, _velocity: &Vector3<f64>) -> Wrench {
        Wrench::zeros()
    }
}
