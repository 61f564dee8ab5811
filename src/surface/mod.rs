//! Surface models shared by the plant and the controllers: the shapes a tool can touch
//! ([`Shape`]: a plane patch, a sphere, a cylinder, a torus, each one file; signed distance and
//! outward normal, settings, drawing) and the regularised Coulomb friction law. The plant's
//! contact forces ([`crate::contact`]) and a controller's task frame and friction
//! feedforward ([`crate::control`]) both use them, so neither imports the other.

mod cylinder;
mod friction;
mod geometry;
mod plane;
mod shape;
mod sphere;
mod torus;

pub use cylinder::Cylinder;
pub use friction::{sliding_friction, FRICTION_REGULARISATION_SPEED};
pub use geometry::SurfaceGeometry;
pub use plane::{plane_axes, Plane};
#[cfg(feature = "std")]
pub use shape::{circle, Drawing};
pub use shape::{Setting, SettingsReader, Shape, SurfacePoint, MAX_LENGTH_M};
pub use sphere::Sphere;
pub use torus::Torus;
