//! Preparing a run as one-way stages, each a function of what the stages before it
//! produced, one file each:
//!
//! ```text
//! reference -> plant -> position law -> force law -> [safety, sensor faults] -> sensor -> (run: super::execute)
//! ```
//!
//! - [`reference`](mod@reference): the Cartesian (or joint) reference, planned by the robot
//!   ([`ScenarioRobot::plan`](super::robot::ScenarioRobot::plan)), the run's length and
//!   initial joints;
//! - [`plant`]: the plant's model (the description's, or `[plant]`'s parameters), timing,
//!   end stops, friction and surfaces;
//! - [`position_law`]: the position controller on the controller's model;
//! - [`force_law`]: the force loop around it, its task frame and desired force, and the
//!   reach check; its gains designed at the contact pose by [`force_design`] (which plans
//!   the reference to find that pose);
//! - [`full_frame_laws`]: the force laws in the full task frame, for an arm that controls
//!   all three rotations;
//! - [`sensor`]: the force sensor in front of the controller (at the tool point, or before a
//!   tool, with the tare and the weight's compensation);
//! - [`safety`](mod@safety): the safety supervisor around the controller, inside the sensor,
//!   and the sensor's faults between them.

pub mod faults;
pub mod force_design;
pub mod force_law;
pub mod full_frame_laws;
pub mod plant;
pub mod position_law;
pub mod reference;
pub mod safety;
pub mod sensor;

use crate::contact::SurfaceGeometry;

/// Surface `geometry` shifted by `shift` m along its outward normal (the controller's belief
/// of a surface; a sweep's offset of the real one).
#[must_use]
pub fn shifted(geometry: &SurfaceGeometry, shift: f64) -> SurfaceGeometry {
    match *geometry {
        SurfaceGeometry::Plane {
            point,
            normal,
            axes,
            half_extent,
        } => SurfaceGeometry::Plane {
            point: point + normal * shift,
            normal,
            axes,
            half_extent,
        },
        SurfaceGeometry::Sphere { centre, radius } => SurfaceGeometry::Sphere {
            centre,
            radius: radius + shift,
        },
        SurfaceGeometry::Cylinder {
            point,
            axis,
            radius,
        } => SurfaceGeometry::Cylinder {
            point,
            axis,
            radius: radius + shift,
        },
    }
}
