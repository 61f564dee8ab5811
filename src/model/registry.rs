//! The registry of generated robots: look a robot up by name and call generic code with it.
//!
//! The list is the generator's (`armdyn_generated::ROBOTS`, `armdyn_generated::for_each_robot!`):
//! adding `robots/<name>.toml` and regenerating adds the robot here, to the command line, to
//! the tests and to the benchmarks.

use super::robot::RobotModel;

/// The name of every generated robot, in name order.
pub const ROBOTS: &[&str] = &armdyn_generated::ROBOTS;

/// Generic code to run with one robot chosen at run time (see [`visit_robot`]).
pub trait RobotVisitor {
    /// What the visit returns.
    type Output;
    /// Called with the robot's zero-sized model (`Copy`, so controllers can own one).
    fn visit<const N: usize, R: RobotModel<N> + Copy + 'static>(self, robot: &R) -> Self::Output;
}

macro_rules! visit_by_name {
    ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        /// Calls `visitor` with the robot called `name`; `None` if there is no such robot.
        ///
        /// ```
        /// use armdyn::model::{visit_robot, RobotModel, RobotVisitor};
        /// struct Dof;
        /// impl RobotVisitor for Dof {
        ///     type Output = usize;
        ///     fn visit<const N: usize, R: RobotModel<N> + Copy + 'static>(self, _robot: &R) -> usize {
        ///         N
        ///     }
        /// }
        /// assert_eq!(visit_robot("puma560", Dof), Some(6));
        /// assert_eq!(visit_robot("kuka", Dof), None);
        /// ```
        pub fn visit_robot<V: RobotVisitor>(name: &str, visitor: V) -> Option<V::Output> {
            match name {
                $(stringify!($module) => Some(visitor.visit::<$n, _>(&super::robots::$ty)),)*
                _ => None,
            }
        }
    };
}

armdyn_generated::for_each_robot!(visit_by_name);
