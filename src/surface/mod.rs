//! Surface models shared by the plant and the controllers: the shapes a tool can touch
//! (plane patch, sphere, cylinder: signed distance and outward normal) and the regularised
//! Coulomb friction law. The plant's contact forces ([`crate::contact`]) and a controller's
//! task frame and friction feedforward ([`crate::control`]) both use them, so neither imports
//! the other.

mod friction;
mod geometry;

pub use friction::{sliding_friction, FRICTION_REGULARISATION_SPEED};
pub use geometry::{plane_axes, SurfaceGeometry, SurfacePoint};
