//! [`robot_type!`](crate::robot_type): the model type of a generated robot module, for the
//! registry's robots and for a user's own arm alike.
//!
//! A module expanded by `armdyn_runtime::robot_model!` (with `lanes`), holding a submodule
//! `parametric` expanded from the robot's `<robot>_parametric.json`, becomes a zero-sized type
//! with [`RobotModel`](super::RobotModel), [`DynamicsDerivatives`](super::DynamicsDerivatives),
//! [`BatchModel`](super::batch::BatchModel) and [`ParametricModel`](super::ParametricModel):
//! everything the controllers, the simulator, identification and the scenarios ask of a robot.
//! The registry's types ([`Scara`](super::Scara), [`Panda`](super::Panda), ...) are made by
//! this same macro.
//!
//! The helpers below are what the expansion calls; they are public only for it.

use super::joint::JointKind;
use super::types::JointVector;

/// `[bool; N]` (prismatic or not) to `[JointKind; N]`, at compile time.
#[doc(hidden)]
#[must_use]
pub const fn joint_kinds<const N: usize>(is_prismatic: [bool; N]) -> [JointKind; N] {
    let mut kinds = [JointKind::Revolute; N];
    let mut i = 0;
    while i < N {
        kinds[i] = JointKind::from_is_prismatic(is_prismatic[i]);
        i += 1;
    }
    kinds
}

/// A joint vector as the generated code's array.
#[doc(hidden)]
#[inline(always)]
#[must_use]
pub fn to_array<const N: usize>(v: &JointVector<N>) -> [f64; N] {
    (*v).into()
}

/// A generated row-major array as an `nalgebra` matrix.
#[doc(hidden)]
#[inline(always)]
#[must_use]
pub fn from_rows<const R: usize, const C: usize>(
    m: &[[f64; C]; R],
) -> nalgebra::SMatrix<f64, R, C> {
    nalgebra::SMatrix::<f64, R, C>::from_fn(|i, j| m[i][j])
}

/// The first non-finite element of `rows` as a [`ModelError`](super::ModelError) naming
/// `what`.
#[doc(hidden)]
#[inline]
pub fn check_finite<const R: usize, const C: usize>(
    what: &'static str,
    rows: &[[f64; C]; R],
) -> Result<(), super::ModelError> {
    for row in rows {
        if let Some(index) = row.iter().position(|x| !x.is_finite()) {
            return Err(super::ModelError::NonFinite {
                what,
                index,
                value: row[index],
            });
        }
    }
    Ok(())
}

/// The model type of a generated robot module: a zero-sized type with
/// [`RobotModel`](crate::model::RobotModel),
/// [`DynamicsDerivatives`](crate::model::DynamicsDerivatives),
/// [`BatchModel`](crate::model::batch::BatchModel),
/// [`ParametricModel`](crate::model::ParametricModel) and, with the feature `std`,
/// identification's `Identifiable`, so that the controllers, the simulator,
/// identification and scenario runs take it as they take the registry's robots.
///
/// The module is the layout the registry's robots have (`armdyn-generated`), from the two
/// graphs `armdyn-codegen DESCRIPTION.toml --out DIR` writes:
///
/// ```ignore
/// pub mod my_arm {
///     armdyn_runtime::robot_model!("models/my_arm.json", f32, lanes);
///     pub mod parametric {
///         armdyn_runtime::robot_model!("models/my_arm_parametric.json");
///     }
/// }
/// armdyn::robot_type! {
///     /// My five-joint arm.
///     pub struct MyArm = my_arm;
/// }
/// ```
///
/// The joint count is the module's `DOF` (or given after a comma: `= my_arm, 5`). The
/// module must have `TASK_ROWS`, which the generator writes into every graph.
///
/// ```
/// armdyn::robot_type! {
///     /// The UR5 of the registry, as a user's crate would name its own arm.
///     pub struct MyUr5 = armdyn_generated::ur5;
/// }
/// use armdyn::model::{RobotModel, Ur5};
/// use nalgebra::SVector;
/// let q = SVector::from([0.1, -1.2, 1.0, -0.5, 1.4, 0.3]);
/// assert_eq!(MyUr5.mass_matrix(&q), Ur5.mass_matrix(&q));
/// assert_eq!(<MyUr5 as RobotModel<6>>::NAME, "ur5");
/// ```
#[macro_export]
macro_rules! robot_type {
    ($(#[$attr:meta])* $vis:vis struct $ty:ident = $($module:ident)::+ $(;)?) => {
        $crate::robot_type!($(#[$attr])* $vis struct $ty = $($module)::+, { $($module)::+::DOF });
    };
    ($(#[$attr:meta])* $vis:vis struct $ty:ident = $($module:ident)::+, $n:tt $(;)?) => {
        $(#[$attr])*
        #[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
        $vis struct $ty;

        impl $crate::model::RobotModel<$n> for $ty {
            const NAME: &'static str = $($module)::+::ROBOT_NAME;
            const JOINT_NAMES: [&'static str; $n] = $($module)::+::JOINT_NAMES;
            const JOINT_KINDS: [$crate::model::JointKind; $n] =
                $crate::model::robot_type::joint_kinds($($module)::+::JOINT_IS_PRISMATIC);
            const JOINT_LIMITS: [[f64; 2]; $n] = $($module)::+::JOINT_LIMITS;
            const EFFORT_LIMITS: [f64; $n] = $($module)::+::EFFORT_LIMITS;
            const GRAVITY: [f64; 3] = $($module)::+::GRAVITY;
            const TASK: $crate::target::Task =
                match $crate::target::Task::from_rows(&$($module)::+::TASK_ROWS) {
                    Some(task) => task,
                    None => panic!("the generator writes only valid tasks"),
                };
            const SOURCE_SHA256: &'static str = $($module)::+::SOURCE_SHA256;
            const OPERATION_COUNTS: &'static [(&'static str, u32, u32)] =
                &$($module)::+::OPERATION_COUNTS;

            #[inline]
            fn frame_poses(
                &self,
                q: &$crate::model::JointVector<$n>,
            ) -> [$crate::model::Pose; $n] {
                use $crate::model::robot_type::{from_rows, to_array};
                $($module)::+::frame_poses(&to_array(q)).map(|t| from_rows(&t))
            }

            #[inline]
            fn end_effector_pose(&self, q: &$crate::model::JointVector<$n>) -> $crate::model::Pose {
                use $crate::model::robot_type::{from_rows, to_array};
                from_rows(&$($module)::+::end_effector_pose(&to_array(q)))
            }

            #[inline]
            fn jacobian(&self, q: &$crate::model::JointVector<$n>) -> $crate::model::Jacobian<$n> {
                use $crate::model::robot_type::{from_rows, to_array};
                from_rows(&$($module)::+::jacobian(&to_array(q)))
            }

            #[inline]
            fn jacobian_and_position(
                &self,
                q: &$crate::model::JointVector<$n>,
            ) -> ($crate::model::Jacobian<$n>, $crate::nalgebra::Vector3<f64>) {
                use $crate::model::robot_type::to_array;
                let rows = $($module)::+::jacobian_and_position(&to_array(q));
                (
                    $crate::model::Jacobian::<$n>::from_fn(|i, j| rows[i][j]),
                    $crate::nalgebra::Vector3::new(rows[0][$n], rows[1][$n], rows[2][$n]),
                )
            }

            #[inline]
            fn jdot_qd(
                &self,
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
            ) -> $crate::nalgebra::Vector6<f64> {
                use $crate::model::robot_type::to_array;
                $($module)::+::jdot_qd(&to_array(q), &to_array(qd)).into()
            }

            #[inline]
            fn inverse_dynamics(
                &self,
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
                qdd: &$crate::model::JointVector<$n>,
            ) -> $crate::model::JointVector<$n> {
                use $crate::model::robot_type::to_array;
                $($module)::+::inverse_dynamics(&to_array(q), &to_array(qd), &to_array(qdd)).into()
            }

            #[inline]
            fn forward_dynamics(
                &self,
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
                tau: &$crate::model::JointVector<$n>,
            ) -> Result<$crate::model::JointVector<$n>, $crate::model::ModelError> {
                use $crate::model::robot_type::{check_finite, to_array};
                let qdd = $($module)::+::forward_dynamics(&to_array(q), &to_array(qd), &to_array(tau));
                check_finite("qdd", &[qdd])?;
                Ok(qdd.into())
            }

            #[inline]
            fn mass_matrix(&self, q: &$crate::model::JointVector<$n>) -> $crate::model::JointMatrix<$n> {
                use $crate::model::robot_type::{from_rows, to_array};
                from_rows(&$($module)::+::mass_matrix(&to_array(q)))
            }

            #[inline]
            fn mass_matrix_and_bias(
                &self,
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
            ) -> ($crate::model::JointMatrix<$n>, $crate::model::JointVector<$n>) {
                use $crate::model::robot_type::to_array;
                let rows = $($module)::+::mass_matrix_and_bias(&to_array(q), &to_array(qd));
                (
                    $crate::model::JointMatrix::<$n>::from_fn(|i, j| rows[i][j]),
                    $crate::model::JointVector::<$n>::from_fn(|i, _| rows[i][$n]),
                )
            }

            #[inline]
            fn coriolis_matrix(
                &self,
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
            ) -> $crate::model::JointMatrix<$n> {
                use $crate::model::robot_type::{from_rows, to_array};
                from_rows(&$($module)::+::coriolis_matrix(&to_array(q), &to_array(qd)))
            }

            #[inline]
            fn coriolis(
                &self,
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
            ) -> $crate::model::JointVector<$n> {
                use $crate::model::robot_type::to_array;
                $($module)::+::coriolis(&to_array(q), &to_array(qd)).into()
            }

            #[inline]
            fn gravity(&self, q: &$crate::model::JointVector<$n>) -> $crate::model::JointVector<$n> {
                use $crate::model::robot_type::to_array;
                $($module)::+::gravity(&to_array(q)).into()
            }
        }

        impl $crate::model::DynamicsDerivatives<$n> for $ty {
            #[inline]
            fn inverse_dynamics_derivatives(
                &self,
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
                qdd: &$crate::model::JointVector<$n>,
            ) -> $crate::model::InverseDynamicsDerivatives<$n> {
                use $crate::model::robot_type::to_array;
                let rows = $($module)::+::inverse_dynamics_derivatives(
                    &to_array(q),
                    &to_array(qd),
                    &to_array(qdd),
                );
                $crate::model::InverseDynamicsDerivatives {
                    dtau_dq: $crate::model::JointMatrix::<$n>::from_fn(|i, j| rows[i][j]),
                    dtau_dqd: $crate::model::JointMatrix::<$n>::from_fn(|i, j| rows[i][$n + j]),
                    mass_matrix: $crate::model::JointMatrix::<$n>::from_fn(|i, j| rows[i][2 * $n + j]),
                }
            }

            #[inline]
            fn forward_dynamics_derivatives(
                &self,
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
                tau: &$crate::model::JointVector<$n>,
            ) -> Result<$crate::model::ForwardDynamicsDerivatives<$n>, $crate::model::ModelError> {
                use $crate::model::robot_type::{check_finite, to_array};
                let rows = $($module)::+::forward_dynamics_derivatives(
                    &to_array(q),
                    &to_array(qd),
                    &to_array(tau),
                );
                check_finite("forward_dynamics_derivatives", &rows)?;
                Ok($crate::model::ForwardDynamicsDerivatives {
                    dqdd_dq: $crate::model::JointMatrix::<$n>::from_fn(|i, j| rows[i][j]),
                    dqdd_dqd: $crate::model::JointMatrix::<$n>::from_fn(|i, j| rows[i][$n + j]),
                    mass_matrix_inverse: $crate::model::JointMatrix::<$n>::from_fn(|i, j| rows[i][2 * $n + j]),
                })
            }

            #[inline]
            fn jacobian_derivatives(
                &self,
                q: &$crate::model::JointVector<$n>,
            ) -> [$crate::model::Jacobian<$n>; $n] {
                use $crate::model::robot_type::{from_rows, to_array};
                $($module)::+::jacobian_derivatives(&to_array(q)).map(|d| from_rows(&d))
            }
        }

        impl $crate::model::batch::BatchModel<$n> for $ty {
            #[inline]
            fn mass_matrix_and_bias_lanes(
                &self,
                q: &$crate::model::batch::Lanes<$n>,
                qd: &$crate::model::batch::Lanes<$n>,
            ) -> ($crate::model::batch::LaneMatrix<$n>, $crate::model::batch::Lanes<$n>) {
                let rows = $($module)::+::lanes::mass_matrix_and_bias(q, qd);
                (
                    core::array::from_fn(|i| core::array::from_fn(|j| rows[i][j])),
                    core::array::from_fn(|i| rows[i][$n]),
                )
            }

            #[inline]
            fn forward_dynamics_lanes(
                &self,
                q: &$crate::model::batch::Lanes<$n>,
                qd: &$crate::model::batch::Lanes<$n>,
                tau: &$crate::model::batch::Lanes<$n>,
            ) -> $crate::model::batch::Lanes<$n> {
                $($module)::+::lanes::forward_dynamics(q, qd, tau)
            }

            #[inline]
            fn inverse_dynamics_lanes(
                &self,
                q: &$crate::model::batch::Lanes<$n>,
                qd: &$crate::model::batch::Lanes<$n>,
                qdd: &$crate::model::batch::Lanes<$n>,
            ) -> $crate::model::batch::Lanes<$n> {
                $($module)::+::lanes::inverse_dynamics(q, qd, qdd)
            }

            #[inline]
            fn inverse_dynamics_derivatives_lanes(
                &self,
                q: &$crate::model::batch::Lanes<$n>,
                qd: &$crate::model::batch::Lanes<$n>,
                qdd: &$crate::model::batch::Lanes<$n>,
            ) -> [$crate::model::batch::LaneMatrix<$n>; 3] {
                let rows = $($module)::+::lanes::inverse_dynamics_derivatives(q, qd, qdd);
                core::array::from_fn(|b| core::array::from_fn(|i| core::array::from_fn(|j| rows[i][b * $n + j])))
            }

            #[inline]
            fn forward_dynamics_derivatives_lanes(
                &self,
                q: &$crate::model::batch::Lanes<$n>,
                qd: &$crate::model::batch::Lanes<$n>,
                tau: &$crate::model::batch::Lanes<$n>,
            ) -> [$crate::model::batch::LaneMatrix<$n>; 3] {
                let rows = $($module)::+::lanes::forward_dynamics_derivatives(q, qd, tau);
                core::array::from_fn(|b| core::array::from_fn(|i| core::array::from_fn(|j| rows[i][b * $n + j])))
            }
        }

        impl $crate::model::ParametricModel<$n> for $ty {
            type Parameters = [f64; $crate::model::PARAMETERS_PER_LINK * $n];

            fn standard_parameters() -> Self::Parameters {
                $($module)::+::standard_parameters()
            }

            fn parameters_from(params: &[f64]) -> Option<Self::Parameters> {
                params.try_into().ok()
            }

            #[inline]
            fn mass_matrix_with(
                q: &$crate::model::JointVector<$n>,
                p: &Self::Parameters,
            ) -> $crate::model::JointMatrix<$n> {
                use $crate::model::robot_type::{from_rows, to_array};
                from_rows(&$($module)::+::parametric::mass_matrix(&to_array(q), p))
            }

            #[inline]
            fn coriolis_matrix_with(
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
                p: &Self::Parameters,
            ) -> $crate::model::JointMatrix<$n> {
                use $crate::model::robot_type::{from_rows, to_array};
                from_rows(&$($module)::+::parametric::coriolis_matrix(&to_array(q), &to_array(qd), p))
            }

            #[inline]
            fn coriolis_with(
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
                p: &Self::Parameters,
            ) -> $crate::model::JointVector<$n> {
                use $crate::model::robot_type::to_array;
                $($module)::+::parametric::coriolis(&to_array(q), &to_array(qd), p).into()
            }

            #[inline]
            fn gravity_with(
                q: &$crate::model::JointVector<$n>,
                p: &Self::Parameters,
            ) -> $crate::model::JointVector<$n> {
                use $crate::model::robot_type::to_array;
                $($module)::+::parametric::gravity(&to_array(q), p).into()
            }

            #[inline]
            fn inverse_dynamics_with(
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
                qdd: &$crate::model::JointVector<$n>,
                p: &Self::Parameters,
            ) -> $crate::model::JointVector<$n> {
                use $crate::model::robot_type::to_array;
                $($module)::+::parametric::inverse_dynamics(&to_array(q), &to_array(qd), &to_array(qdd), p)
                    .into()
            }

            #[inline]
            fn forward_dynamics_with(
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
                tau: &$crate::model::JointVector<$n>,
                p: &Self::Parameters,
            ) -> $crate::model::JointVector<$n> {
                use $crate::model::robot_type::to_array;
                $($module)::+::parametric::forward_dynamics(&to_array(q), &to_array(qd), &to_array(tau), p)
                    .into()
            }
        }

        $crate::__identifiable!($ty = $($module)::+, $n);
    };
}
