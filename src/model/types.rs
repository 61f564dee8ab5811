//! Fixed-size `nalgebra` aliases used throughout the model API.

use nalgebra::{Matrix4, SMatrix, SVector, Vector6};

/// A joint-space vector of `N` entries: positions (rad or m), velocities (rad/s or m/s),
/// accelerations (rad/s^2 or m/s^2) or generalised forces (N m or N), joint by joint.
pub type JointVector<const N: usize> = SVector<f64, N>;

/// A joint-space `N x N` matrix, such as the mass matrix `M(q)` or the Coriolis matrix
/// `C(q, qd)`.
pub type JointMatrix<const N: usize> = SMatrix<f64, N, N>;

/// The geometric Jacobian, `6 x N`, in the base frame: rows `vx vy vz wx wy wz`
/// (m/s and rad/s per unit joint velocity), taken at the origin of the last DH frame.
pub type Jacobian<const N: usize> = SMatrix<f64, 6, N>;

/// A homogeneous transform, 4 x 4: rotation in the upper-left 3 x 3, translation (m) in the
/// last column, `[0 0 0 1]` as the last row.
pub type Pose = Matrix4<f64>;

/// A wrench in the base frame, ordered `[fx fy fz tx ty tz]` (N and N m).
pub type Wrench = Vector6<f64>;
