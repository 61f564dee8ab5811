//! Preparing a run as one-way stages, each a function of what the stages before it
//! produced, one file each:
//!
//! ```text
//! reference -> plant -> position law -> [contact pose] -> force law -> tool compensation
//!   -> [safety, sensor faults] -> sensor -> (run: super::execute)
//! ```
//!
//! - [`reference`](mod@reference): the Cartesian (or joint) reference, planned by the robot
//!   ([`ScenarioRobot::plan`](super::robot::ScenarioRobot::plan)), the run's length and
//!   initial joints;
//! - [`plant`]: the plant's model (the description's, or `[plant]`'s parameters), timing,
//!   end stops, friction and surfaces;
//! - [`position_law`]: the position controller on the controller's model;
//! - [`force_law`]: the force loop around it, its task frame and desired force, and the
//!   reach check; the contact pose found once, before any law, where the law needs it
//!   ([`force_design`]: designed gains, the impedance's damping, the tool axis);
//! - [`full_frame_laws`]: the force laws in the full task frame, for an arm that controls
//!   all three rotations;
//! - [`sensor`]: the tool's weight compensated and the bias tared by the controller (a sensor
//!   before a tool), and the force sensor in front of it all (at the tool point, or before a
//!   tool); a deployed run's step takes the laws' place and runs the same stages after them;
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
