//! What a scenario file can say about a robot beyond its model: the references it knows by
//! name (`[reference] kind = "thesis"`) and whether it plans elbow switches. Reading a file
//! needs only this ([`RobotVocabulary`], found by name with
//! [`with_robot_named!`](crate::with_robot_named): the
//! reader does not depend on the runner, whose default planning reads scenarios); running it
//! needs the rest of [`ScenarioRobot`](super::ScenarioRobot). A robot without a module of
//! its own in `crate::robots` gets the defaults (`crate::robots` says which).

use crate::model::ParametricModel;

use super::planned::SharedTrajectory;

/// What a scenario file can name of a robot (see the [module documentation](self)).
pub trait RobotVocabulary<const N: usize>: ParametricModel<N> + Send + Sync {
    /// The named references (`[reference] kind = "thesis"`) of this robot.
    fn named_references() -> &'static [&'static str] {
        &[]
    }

    /// The named reference `name`, with `surface_z_m` (m) where it takes one; `None` if there
    /// is no such reference for this robot.
    fn named_reference(_name: &str, _surface_z_m: Option<f64>) -> Option<SharedTrajectory> {
        None
    }

    /// Whether the robot plans elbow switches (`[reference] elbow_switch` and its keys).
    fn has_elbows() -> bool {
        false
    }
}
