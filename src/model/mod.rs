//! Robot models: the generated kinematics and dynamics behind one trait.
//!
//! - [`RobotModel`]: what a controller or simulator may ask of a robot (pose, Jacobian,
//!   `M`, `C`, `c`, `g`, limits), in `nalgebra` fixed-size types.
//! - [`Scara`], [`ScaraMdh`], [`Puma560`], [`Planar2`], [`Ur5`], [`Panda`], ...: one
//!   zero-sized type per generated robot, from the generated registry;
//!   [`with_robot_named!`](crate::with_robot_named) and [`ROBOTS`] reach them by name.
//! - [`forward_dynamics`], [`inverse_dynamics`]: the equation of motion both ways.
//! - [`DynamicsDerivatives`]: `d tau/d (q, qd)` of inverse and `d qdd/d (q, qd, tau)` of
//!   forward dynamics, and `d J/d q`, generated; the tool wrench's terms composed from them.
//! - [`cholesky`]: the fixed-size factorisation behind [`forward_dynamics_cholesky`] (the
//!   reference path) and the hybrid controller's Jacobian solve.
//! - [`lu`]: fixed-size LU with partial pivoting, bit for bit nalgebra's, for the SCARA's
//!   joint reference.
//! - [`batch`]: forward and inverse dynamics and `M`, `c + g` over slices of states, four per
//!   call of the generated `f64x4` functions ([`batch::BatchModel`]).
//! - [`robot_type!`](crate::robot_type): the model type of a generated module, a user's own
//!   arm's as the registry's ([`robot_type`]).
//! - [`Parametric`]: any robot with inertial parameters given at run time (the generated
//!   parametric model, [`ParametricModel`]), and [`LinkInertia`] to perturb them.
//!
//! Nothing here allocates; everything works in `no_std`.

/// The constants and the kinematics of a model type that wraps the robot `$r` in its field
/// `$field` and changes only its dynamics ([`WithArmature`], [`Parametric`],
/// [`WithoutGravity`]): everything is the wrapped robot's but the gravity vector, `$gravity`.
macro_rules! kinematics_of_the_wrapped_robot {
    ($r:ident, $field:tt, $gravity:expr) => {
        const NAME: &'static str = $r::NAME;
        const JOINT_NAMES: [&'static str; N] = $r::JOINT_NAMES;
        const JOINT_KINDS: [$crate::model::JointKind; N] = $r::JOINT_KINDS;
        const JOINT_LIMITS: [[f64; 2]; N] = $r::JOINT_LIMITS;
        const EFFORT_LIMITS: [f64; N] = $r::EFFORT_LIMITS;
        const GRAVITY: [f64; 3] = $gravity;
        const TASK: $crate::target::Task = $r::TASK;
        const SOURCE_SHA256: &'static str = $r::SOURCE_SHA256;
        const OPERATION_COUNTS: &'static [(&'static str, u32, u32)] = $r::OPERATION_COUNTS;

        fn frame_poses(&self, q: &$crate::model::JointVector<N>) -> [$crate::model::Pose; N] {
            self.$field.frame_poses(q)
        }
        fn end_effector_pose(&self, q: &$crate::model::JointVector<N>) -> $crate::model::Pose {
            self.$field.end_effector_pose(q)
        }
        fn jacobian(&self, q: &$crate::model::JointVector<N>) -> $crate::model::Jacobian<N> {
            self.$field.jacobian(q)
        }
        fn jacobian_and_position(
            &self,
            q: &$crate::model::JointVector<N>,
        ) -> ($crate::model::Jacobian<N>, nalgebra::Vector3<f64>) {
            self.$field.jacobian_and_position(q)
        }
        fn jdot_qd(
            &self,
            q: &$crate::model::JointVector<N>,
            qd: &$crate::model::JointVector<N>,
        ) -> nalgebra::Vector6<f64> {
            self.$field.jdot_qd(q, qd)
        }
    };
}

mod armature;
pub mod batch;
pub mod cholesky;
mod derivatives;
mod dynamics;
mod error;
mod joint;
mod link_inertia;
pub mod lu;
mod parametric;
mod registry;
mod robot;
pub mod robot_type;
mod robots;
pub mod sensor_mount;
mod types;
mod without_gravity;

pub use derivatives::{
    forward_dynamics_derivatives_with_wrench, inverse_dynamics_derivatives_with_wrench,
    wrench_torque_derivative, DynamicsDerivatives, ForwardDynamicsDerivatives,
    InverseDynamicsDerivatives,
};
pub use dynamics::{
    external_joint_torque, forward_dynamics, forward_dynamics_cholesky, inverse_dynamics,
};
pub use error::ModelError;
pub use joint::JointKind;
pub use link_inertia::LinkInertia;
pub use parametric::{Parametric, ParametricModel, PARAMETERS_PER_LINK};
pub use registry::ROBOTS;
pub use robot::RobotModel;
pub use robots::*;
pub use sensor_mount::{rotate_wrench, tool_rotation, SensorMount};
pub use types::{Jacobian, JointMatrix, JointVector, Pose, Wrench};

pub use armature::WithArmature;
pub use without_gravity::WithoutGravity;
