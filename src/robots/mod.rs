//! What is special about particular robots, reached through the generic interfaces: a
//! robot's own closed-form inverse kinematics, its workspace and planning, its presets and
//! its deployable step. Everything else of the crate works on any robot of the registry.
//!
//! - [`scara`]: the thesis's SCARA.

pub mod scara;

/// The scenario's defaults ([`crate::scenario::ScenarioRobot`],
/// [`crate::scenario::RobotVocabulary`]) for every robot of the registry without a module
/// here: this macro's first rules list the robots that have one.
#[cfg(feature = "std")]
macro_rules! default_scenario_robot {
    (scara, $ty:ident, $n:literal) => {};
    ($module:ident, $ty:ident, $n:literal) => {
        impl crate::scenario::ScenarioRobot<$n> for crate::model::$ty {}
        impl crate::scenario::RobotVocabulary<$n> for crate::model::$ty {}
    };
}

#[cfg(feature = "std")]
macro_rules! default_scenario_robots {
    ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        $(default_scenario_robot!($module, $ty, $n);)*
    };
}

#[cfg(feature = "std")]
armdyn_generated::for_each_robot!(default_scenario_robots);
