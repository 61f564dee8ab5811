//! Identification works on every generated robot: each has a regressor and its standard
//! parameters. [`robot_type!`](crate::robot_type) implements [`Identifiable`] for the
//! registry's robots and a user's own.

use nalgebra::{DMatrix, DVector};

#[cfg(test)]
use crate::model::Scara;
use crate::model::{JointVector, RobotModel};

/// Standard inertial parameters per link, in the generated order.
pub const PER_LINK: usize = 10;

/// Names of the ten standard parameters of link `j` (from 1), in the generated order:
/// mass (kg), first moments (kg m) and the inertia about the link frame's origin (kg m^2).
#[must_use]
pub fn standard_names(j: usize) -> [String; PER_LINK] {
    [
        format!("m{j}"),
        format!("m{j} cx{j}"),
        format!("m{j} cy{j}"),
        format!("m{j} cz{j}"),
        format!("Ixx{j}"),
        format!("Ixy{j}"),
        format!("Ixz{j}"),
        format!("Iyy{j}"),
        format!("Iyz{j}"),
        format!("Izz{j}"),
    ]
}

/// A robot with a generated regressor `Y(q, qd, qdd)` (`tau = Y pi`, `10 N` standard
/// parameters `pi`) and a parametric inverse dynamics.
pub trait Identifiable<const N: usize>: RobotModel<N> + Copy + Send + Sync + 'static {
    /// The `N x 10 N` regressor at one state (rad, rad/s, rad/s^2 or m, m/s, m/s^2).
    fn regressor(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        qdd: &JointVector<N>,
    ) -> DMatrix<f64>;

    /// The robot's standard parameters, as in its description.
    fn standard_parameters(&self) -> DVector<f64>;

    /// Names of every standard parameter (`m1`, `m1 cx1`, ..., `Izz N`).
    fn parameter_names(&self) -> Vec<String> {
        (1..=N).flat_map(standard_names).collect()
    }
}

/// The part of [`robot_type!`](crate::robot_type) that needs `std`: [`Identifiable`] (a
/// regressor as a `DMatrix`). Without the feature `std` the macro of that name in
/// `identification/mod.rs` is empty, so `robot_type!` works in `no_std` crates.
#[doc(hidden)]
#[macro_export]
macro_rules! __identifiable {
    ($ty:ident = $($module:ident)::+, $n:tt) => {
        impl $crate::identification::Identifiable<$n> for $ty {
            fn regressor(
                &self,
                q: &$crate::model::JointVector<$n>,
                qd: &$crate::model::JointVector<$n>,
                qdd: &$crate::model::JointVector<$n>,
            ) -> $crate::nalgebra::DMatrix<f64> {
                use $crate::model::robot_type::to_array;
                let y = $($module)::+::regressor(&to_array(q), &to_array(qd), &to_array(qdd));
                $crate::nalgebra::DMatrix::from_fn($n, $crate::model::PARAMETERS_PER_LINK * $n, |i, j| y[i][j])
            }

            fn standard_parameters(&self) -> $crate::nalgebra::DVector<f64> {
                $crate::nalgebra::DVector::from_column_slice(&$($module)::+::standard_parameters())
            }
        }
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regressor_times_standard_parameters_is_inverse_dynamics() {
        let q = nalgebra::Vector4::new(0.3, -0.7, 0.2, 1.1);
        let qd = nalgebra::Vector4::new(0.5, -0.2, 0.1, 0.9);
        let qdd = nalgebra::Vector4::new(-1.0, 2.0, 0.3, -0.4);
        let tau = Scara.regressor(&q, &qd, &qdd) * Scara.standard_parameters();
        let id = Scara.inverse_dynamics(&q, &qd, &qdd);
        for i in 0..4 {
            approx::assert_relative_eq!(tau[i], id[i], epsilon = 1e-9, max_relative = 1e-12);
        }
        assert_eq!(Scara.parameter_names()[11], "m2 cx2");
    }
}
