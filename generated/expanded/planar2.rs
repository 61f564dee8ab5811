// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `scara_derive::robot_model!("models/planar2.json")` in the `generated` crate,
// formatted with prettyplease. Not compiled: for reading and review.

/// Name of the robot (`robot.name` in the model file).
pub const ROBOT_NAME: &str = "planar2";
/// Description of the robot, from the model file.
pub const DESCRIPTION: &str = "Planar 2R arm in a vertical plane (uniform rods), gravity along -y";
/// Degrees of freedom: the number of joints.
pub const DOF: usize = 2;
/// Name and version of the generator that wrote the model file.
pub const GENERATOR: &str = "scara-codegen 0.1.0";
/// Version of CasADi the generator used.
pub const CASADI_VERSION: &str = "3.7.2";
/// Robot description file the model was generated from.
pub const SOURCE: &str = "robots/planar2.toml";
/// SHA-256 of the robot description file (64 hex digits).
pub const SOURCE_SHA256: &str = "a8e749828718c1e2ab05aaf26a6a0853d304e950003bf0c30e770c00e6284dcd";
/// Joint names, base to tip.
pub const JOINT_NAMES: [&str; DOF] = ["q1", "q2"];
/// `true` for a prismatic joint (m, N), `false` for a revolute one (rad, N m).
pub const JOINT_IS_PRISMATIC: [bool; DOF] = [false, false];
/// Joint position limits `[lower, upper]`, rad or m.
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const JOINT_LIMITS: [[f64; 2]; DOF] = [
    [-3.141592653589793_f64, 3.141592653589793_f64],
    [-2.356194490192345_f64, 2.356194490192345_f64],
];
/// Actuator effort limits, N m (revolute) or N (prismatic).
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const EFFORT_LIMITS: [f64; DOF] = [50.0_f64, 30.0_f64];
/// Gravity vector in the base frame, m/s^2.
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const GRAVITY: [f64; 3] = [0.0_f64, -9.81_f64, 0.0_f64];
/// `(function, flops, trig)` for every function, in file order: floating-point
/// operations (add, sub, mul, div, neg, sq, twice, inv, sqrt, fabs) and trig calls
/// (sin, cos, atan2) in its body.
pub const OPERATION_COUNTS: [(&str, u32, u32); 7] = [
    ("frame_poses", 19, 4),
    ("end_effector_pose", 16, 4),
    ("jacobian", 14, 4),
    ("mass_matrix", 4, 1),
    ("coriolis_matrix", 8, 1),
    ("coriolis", 9, 1),
    ("gravity", 8, 4),
];
/// Poses of every DH frame, `A_1 A_2 ... A_i` with `A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)` (thesis eq. 3.2-3.7).
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `poses: [[[f64; 4]; 4]; 2]` (2 x 4 x 4, row-major): homogeneous transforms T_0i of DH frames 1..n in the base frame (m)
///
/// Operation count: 19 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn frame_poses(q: &[f64; 2]) -> [[[f64; 4]; 4]; 2] {
    let v0: f64 = q[0];
    let v1: f64 = ::libm::cos(v0);
    let v2: f64 = ::libm::sin(v0);
    let v3: f64 = -v2;
    let v4: f64 = 0.0_f64;
    let v5: f64 = 0.5_f64;
    let v6: f64 = v5 * v1;
    let v7: f64 = v5 * v2;
    let v8: f64 = 1.0_f64;
    let v9: f64 = q[1];
    let v10: f64 = ::libm::cos(v9);
    let v11: f64 = v10 * v1;
    let v12: f64 = ::libm::sin(v9);
    let v13: f64 = v12 * v2;
    let v14: f64 = v11 - v13;
    let v15: f64 = v12 * v1;
    let v16: f64 = v10 * v2;
    let v17: f64 = v15 + v16;
    let v18: f64 = -v17;
    let v19: f64 = 0.4_f64;
    let v20: f64 = v19 * v10;
    let v21: f64 = v5 + v20;
    let v22: f64 = v21 * v1;
    let v23: f64 = v19 * v12;
    let v24: f64 = v23 * v2;
    let v25: f64 = v22 - v24;
    let v26: f64 = v23 * v1;
    let v27: f64 = v21 * v2;
    let v28: f64 = v26 + v27;
    [
        [[v1, v3, v4, v6], [v2, v1, v4, v7], [v4, v4, v8, v4], [v4, v4, v4, v8]],
        [[v14, v18, v4, v25], [v17, v14, v4, v28], [v4, v4, v8, v4], [v4, v4, v4, v8]],
    ]
}
/// End-effector pose, forward kinematics `T_0n` (thesis eq. 3.7).
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `pose: [[f64; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n) in the base frame (m)
///
/// Operation count: 16 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn end_effector_pose(q: &[f64; 2]) -> [[f64; 4]; 4] {
    let v0: f64 = q[1];
    let v1: f64 = ::libm::cos(v0);
    let v2: f64 = q[0];
    let v3: f64 = ::libm::cos(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = ::libm::sin(v0);
    let v6: f64 = ::libm::sin(v2);
    let v7: f64 = v5 * v6;
    let v8: f64 = v4 - v7;
    let v9: f64 = v5 * v3;
    let v10: f64 = v1 * v6;
    let v11: f64 = v9 + v10;
    let v12: f64 = -v11;
    let v13: f64 = 0.0_f64;
    let v14: f64 = 0.5_f64;
    let v15: f64 = 0.4_f64;
    let v16: f64 = v15 * v1;
    let v17: f64 = v14 + v16;
    let v18: f64 = v17 * v3;
    let v19: f64 = v15 * v5;
    let v20: f64 = v19 * v6;
    let v21: f64 = v18 - v20;
    let v22: f64 = v19 * v3;
    let v23: f64 = v17 * v6;
    let v24: f64 = v22 + v23;
    let v25: f64 = 1.0_f64;
    [
        [v8, v12, v13, v21],
        [v11, v8, v13, v24],
        [v13, v13, v25, v13],
        [v13, v13, v13, v25],
    ]
}
/// Geometric Jacobian of the end-effector frame origin in the base frame (thesis eq. 3.29).
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `jacobian: [[f64; 2]; 6]` (6 x 2, row-major): rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame
///
/// Operation count: 14 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn jacobian(q: &[f64; 2]) -> [[f64; 2]; 6] {
    let v0: f64 = 0.5_f64;
    let v1: f64 = q[0];
    let v2: f64 = ::libm::sin(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = 0.4_f64;
    let v5: f64 = q[1];
    let v6: f64 = ::libm::cos(v5);
    let v7: f64 = v4 * v6;
    let v8: f64 = v2 * v7;
    let v9: f64 = ::libm::cos(v1);
    let v10: f64 = ::libm::sin(v5);
    let v11: f64 = v4 * v10;
    let v12: f64 = v9 * v11;
    let v13: f64 = v8 + v12;
    let v14: f64 = v3 + v13;
    let v15: f64 = -v14;
    let v16: f64 = -v13;
    let v17: f64 = v0 * v9;
    let v18: f64 = v9 * v7;
    let v19: f64 = v2 * v11;
    let v20: f64 = v18 - v19;
    let v21: f64 = v17 + v20;
    let v22: f64 = 0.0_f64;
    let v23: f64 = 1.0_f64;
    [[v15, v16], [v21, v20], [v22, v22], [v22, v22], [v22, v22], [v23, v23]]
}
/// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `mass_matrix: [[f64; 2]; 2]` (2 x 2, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
///
/// Operation count: 4 floating-point operations, 1 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn mass_matrix(q: &[f64; 2]) -> [[f64; 2]; 2] {
    let v0: f64 = 0.6220166666666667_f64;
    let v1: f64 = 0.3_f64;
    let v2: f64 = q[1];
    let v3: f64 = ::libm::cos(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = v0 + v4;
    let v6: f64 = 0.08015_f64;
    let v7: f64 = 0.15_f64;
    let v8: f64 = v7 * v3;
    let v9: f64 = v6 + v8;
    [[v5, v9], [v9, v6]]
}
/// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
///
/// # Output
///
/// `coriolis_matrix: [[f64; 2]; 2]` (2 x 2, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
///
/// Operation count: 8 floating-point operations, 1 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn coriolis_matrix(q: &[f64; 2], qd: &[f64; 2]) -> [[f64; 2]; 2] {
    let v0: f64 = 0.15_f64;
    let v1: f64 = qd[1];
    let v2: f64 = v0 * v1;
    let v3: f64 = q[1];
    let v4: f64 = ::libm::sin(v3);
    let v5: f64 = v2 * v4;
    let v6: f64 = -v5;
    let v7: f64 = qd[0];
    let v8: f64 = v0 * v7;
    let v9: f64 = v2 + v8;
    let v10: f64 = v9 * v4;
    let v11: f64 = -v10;
    let v12: f64 = v8 * v4;
    let v13: f64 = 0.0_f64;
    [[v6, v11], [v12, v13]]
}
/// Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53).
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
///
/// # Output
///
/// `coriolis: [f64; 2]`: c(q, qd) = C(q, qd) qd (N m or N)
///
/// Operation count: 9 floating-point operations, 1 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn coriolis(q: &[f64; 2], qd: &[f64; 2]) -> [f64; 2] {
    let v0: f64 = 0.15_f64;
    let v1: f64 = qd[1];
    let v2: f64 = v0 * v1;
    let v3: f64 = 0.3_f64;
    let v4: f64 = qd[0];
    let v5: f64 = v3 * v4;
    let v6: f64 = v2 + v5;
    let v7: f64 = v6 * v1;
    let v8: f64 = q[1];
    let v9: f64 = ::libm::sin(v8);
    let v10: f64 = v7 * v9;
    let v11: f64 = -v10;
    let v12: f64 = v0 * v4;
    let v13: f64 = v12 * v4;
    let v14: f64 = v13 * v9;
    [v11, v14]
}
/// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `gravity: [f64; 2]`: g(q), joint torques (N m) or forces (N) that hold the robot still
///
/// Operation count: 8 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn gravity(q: &[f64; 2]) -> [f64; 2] {
    let v0: f64 = 12.2625_f64;
    let v1: f64 = 2.943_f64;
    let v2: f64 = q[1];
    let v3: f64 = ::libm::cos(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = v0 + v4;
    let v6: f64 = q[0];
    let v7: f64 = ::libm::cos(v6);
    let v8: f64 = v5 * v7;
    let v9: f64 = ::libm::sin(v2);
    let v10: f64 = v1 * v9;
    let v11: f64 = ::libm::sin(v6);
    let v12: f64 = v10 * v11;
    let v13: f64 = v8 - v12;
    let v14: f64 = v4 * v7;
    let v15: f64 = v14 - v12;
    [v13, v15]
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/planar2.json")
);
