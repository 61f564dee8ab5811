//! The robots of `robots/*.toml`, backed by the generated functions of `scara-generated`: one
//! type per entry of the generated registry (`scara_generated::for_each_robot!`), named after
//! the robot (`scara_mdh` -> `ScaraMdh`).
//!
//! Each type is zero-sized and converts between `nalgebra` types and the generated code's
//! fixed-size arrays; the conversions are copies of a few dozen `f64` that the optimiser
//! folds away.

use nalgebra::{Vector3, Vector6};
use scara_generated as generated;
use scara_generated::lanes::Batch;

use super::batch::BatchModel;
use super::derivatives::{
    DynamicsDerivatives, ForwardDynamicsDerivatives, InverseDynamicsDerivatives,
};
use super::error::ModelError;
use super::joint::JointKind;
use super::robot::RobotModel;
use super::types::{Jacobian, JointMatrix, JointVector, Pose};
use crate::target::Task;

/// `[bool; N]` (prismatic or not) to `[JointKind; N]`, at compile time.
const fn joint_kinds<const N: usize>(is_prismatic: [bool; N]) -> [JointKind; N] {
    let mut kinds = [JointKind::Revolute; N];
    let mut i = 0;
    while i < N {
        kinds[i] = JointKind::from_is_prismatic(is_prismatic[i]);
        i += 1;
    }
    kinds
}

#[inline(always)]
fn to_array<const N: usize>(v: &JointVector<N>) -> [f64; N] {
    (*v).into()
}

#[inline(always)]
fn from_rows<const R: usize, const C: usize>(m: &[[f64; C]; R]) -> nalgebra::SMatrix<f64, R, C> {
    nalgebra::SMatrix::<f64, R, C>::from_fn(|i, j| m[i][j])
}

macro_rules! generated_robot {
    ($(#[$attr:meta])* $ty:ident, $module:ident, $n:literal) => {
        $(#[$attr])*
        #[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
        pub struct $ty;

        impl RobotModel<$n> for $ty {
            const NAME: &'static str = generated::$module::ROBOT_NAME;
            const JOINT_NAMES: [&'static str; $n] = generated::$module::JOINT_NAMES;
            const JOINT_KINDS: [JointKind; $n] =
                joint_kinds(generated::$module::JOINT_IS_PRISMATIC);
            const JOINT_LIMITS: [[f64; 2]; $n] = generated::$module::JOINT_LIMITS;
            const EFFORT_LIMITS: [f64; $n] = generated::$module::EFFORT_LIMITS;
            const GRAVITY: [f64; 3] = generated::$module::GRAVITY;
            const TASK: Task = match Task::from_rows(&generated::$module::TASK_ROWS) {
                Some(task) => task,
                None => panic!("the generator writes only valid tasks"),
            };
            const SOURCE_SHA256: &'static str = generated::$module::SOURCE_SHA256;
            const OPERATION_COUNTS: &'static [(&'static str, u32, u32)] =
                &generated::$module::OPERATION_COUNTS;

            #[inline]
            fn frame_poses(&self, q: &JointVector<$n>) -> [Pose; $n] {
                generated::$module::frame_poses(&to_array(q)).map(|t| from_rows(&t))
            }

            #[inline]
            fn end_effector_pose(&self, q: &JointVector<$n>) -> Pose {
                from_rows(&generated::$module::end_effector_pose(&to_array(q)))
            }

            #[inline]
            fn jacobian(&self, q: &JointVector<$n>) -> Jacobian<$n> {
                from_rows(&generated::$module::jacobian(&to_array(q)))
            }

            #[inline]
            fn jacobian_and_position(
                &self,
                q: &JointVector<$n>,
            ) -> (Jacobian<$n>, Vector3<f64>) {
                let rows = generated::$module::jacobian_and_position(&to_array(q));
                (
                    Jacobian::<$n>::from_fn(|i, j| rows[i][j]),
                    Vector3::new(rows[0][$n], rows[1][$n], rows[2][$n]),
                )
            }

            #[inline]
            fn jdot_qd(&self, q: &JointVector<$n>, qd: &JointVector<$n>) -> Vector6<f64> {
                generated::$module::jdot_qd(&to_array(q), &to_array(qd)).into()
            }

            #[inline]
            fn inverse_dynamics(
                &self,
                q: &JointVector<$n>,
                qd: &JointVector<$n>,
                qdd: &JointVector<$n>,
            ) -> JointVector<$n> {
                generated::$module::inverse_dynamics(&to_array(q), &to_array(qd), &to_array(qdd))
                    .into()
            }

            #[inline]
            fn forward_dynamics(
                &self,
                q: &JointVector<$n>,
                qd: &JointVector<$n>,
                tau: &JointVector<$n>,
            ) -> Result<JointVector<$n>, ModelError> {
                let qdd: JointVector<$n> = generated::$module::forward_dynamics(
                    &to_array(q),
                    &to_array(qd),
                    &to_array(tau),
                )
                .into();
                match qdd.iter().position(|x| !x.is_finite()) {
                    Some(index) => Err(ModelError::NonFinite {
                        what: "qdd",
                        index,
                        value: qdd[index],
                    }),
                    None => Ok(qdd),
                }
            }

            #[inline]
            fn mass_matrix(&self, q: &JointVector<$n>) -> JointMatrix<$n> {
                from_rows(&generated::$module::mass_matrix(&to_array(q)))
            }

            #[inline]
            fn mass_matrix_and_bias(
                &self,
                q: &JointVector<$n>,
                qd: &JointVector<$n>,
            ) -> (JointMatrix<$n>, JointVector<$n>) {
                let rows = generated::$module::mass_matrix_and_bias(&to_array(q), &to_array(qd));
                (
                    JointMatrix::<$n>::from_fn(|i, j| rows[i][j]),
                    JointVector::<$n>::from_fn(|i, _| rows[i][$n]),
                )
            }

            #[inline]
            fn coriolis_matrix(
                &self,
                q: &JointVector<$n>,
                qd: &JointVector<$n>,
            ) -> JointMatrix<$n> {
                from_rows(&generated::$module::coriolis_matrix(
                    &to_array(q),
                    &to_array(qd),
                ))
            }

            #[inline]
            fn coriolis(&self, q: &JointVector<$n>, qd: &JointVector<$n>) -> JointVector<$n> {
                generated::$module::coriolis(&to_array(q), &to_array(qd)).into()
            }

            #[inline]
            fn gravity(&self, q: &JointVector<$n>) -> JointVector<$n> {
                generated::$module::gravity(&to_array(q)).into()
            }
        }

        impl DynamicsDerivatives<$n> for $ty {
            #[inline]
            fn inverse_dynamics_derivatives(
                &self,
                q: &JointVector<$n>,
                qd: &JointVector<$n>,
                qdd: &JointVector<$n>,
            ) -> InverseDynamicsDerivatives<$n> {
                let rows = generated::$module::inverse_dynamics_derivatives(
                    &to_array(q),
                    &to_array(qd),
                    &to_array(qdd),
                );
                InverseDynamicsDerivatives {
                    dtau_dq: JointMatrix::<$n>::from_fn(|i, j| rows[i][j]),
                    dtau_dqd: JointMatrix::<$n>::from_fn(|i, j| rows[i][$n + j]),
                    mass_matrix: JointMatrix::<$n>::from_fn(|i, j| rows[i][2 * $n + j]),
                }
            }

            #[inline]
            fn forward_dynamics_derivatives(
                &self,
                q: &JointVector<$n>,
                qd: &JointVector<$n>,
                tau: &JointVector<$n>,
            ) -> Result<ForwardDynamicsDerivatives<$n>, ModelError> {
                let rows = generated::$module::forward_dynamics_derivatives(
                    &to_array(q),
                    &to_array(qd),
                    &to_array(tau),
                );
                for row in &rows {
                    if let Some(index) = row.iter().position(|x| !x.is_finite()) {
                        return Err(ModelError::NonFinite {
                            what: "forward_dynamics_derivatives",
                            index,
                            value: row[index],
                        });
                    }
                }
                Ok(ForwardDynamicsDerivatives {
                    dqdd_dq: JointMatrix::<$n>::from_fn(|i, j| rows[i][j]),
                    dqdd_dqd: JointMatrix::<$n>::from_fn(|i, j| rows[i][$n + j]),
                    mass_matrix_inverse: JointMatrix::<$n>::from_fn(|i, j| rows[i][2 * $n + j]),
                })
            }

            #[inline]
            fn jacobian_derivatives(&self, q: &JointVector<$n>) -> [Jacobian<$n>; $n] {
                generated::$module::jacobian_derivatives(&to_array(q)).map(|d| from_rows(&d))
            }
        }

        impl BatchModel<$n> for $ty {
            #[inline]
            fn mass_matrix_and_bias_lanes(
                &self,
                q: &[Batch; $n],
                qd: &[Batch; $n],
            ) -> ([[Batch; $n]; $n], [Batch; $n]) {
                let rows = generated::$module::lanes::mass_matrix_and_bias(q, qd);
                (
                    core::array::from_fn(|i| core::array::from_fn(|j| rows[i][j])),
                    core::array::from_fn(|i| rows[i][$n]),
                )
            }

            #[inline]
            fn forward_dynamics_lanes(
                &self,
                q: &[Batch; $n],
                qd: &[Batch; $n],
                tau: &[Batch; $n],
            ) -> [Batch; $n] {
                generated::$module::lanes::forward_dynamics(q, qd, tau)
            }

            #[inline]
            fn inverse_dynamics_lanes(
                &self,
                q: &[Batch; $n],
                qd: &[Batch; $n],
                qdd: &[Batch; $n],
            ) -> [Batch; $n] {
                generated::$module::lanes::inverse_dynamics(q, qd, qdd)
            }
        }
    };
}

/// Defines the model type of every robot of the registry (`scara_generated::for_each_robot!`).
macro_rules! generated_robots {
    ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        $(
            generated_robot!(
                #[doc = $doc]
                ///
                /// Zero-sized, backed by the generated functions of
                #[doc = concat!("`scara_generated::", stringify!($module), "`.")]
                $ty,
                $module,
                $n
            );
        )*
    };
}

scara_generated::for_each_robot!(generated_robots);
