// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `armdyn_derive::robot_model!("models/planar2.json", f32, lanes)` in the `generated` crate,
// formatted with prettyplease. Not compiled: for reading and review.

/// Name of the robot (`robot.name` in the model file).
pub const ROBOT_NAME: &str = "planar2";
/// Description of the robot, from the model file.
pub const DESCRIPTION: &str = "Planar 2R arm in a vertical plane (uniform rods), gravity along -y";
/// Degrees of freedom: the number of joints.
pub const DOF: usize = 2;
/// Name and version of the generator that wrote the model file.
pub const GENERATOR: &str = "armdyn-codegen 0.1.0";
/// Version of CasADi the generator used.
pub const CASADI_VERSION: &str = "3.7.2";
/// Robot description file the model was generated from.
pub const SOURCE: &str = "robots/planar2.toml";
/// SHA-256 of the robot description file (64 hex digits).
pub const SOURCE_SHA256: &str = "85680afb19fd3b353bad25308b5183d591867308bfdc1ac9036cf1a776a87d11";
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
/// The task: the rows of the geometric Jacobian (`vx vy vz wx wy wz`) its end
/// effector is controlled in (the description's `task`).
pub const TASK_ROWS: [usize; 2] = [0, 1];
/// `(function, flops, trig)` for every function, in file order: floating-point
/// operations (add, sub, mul, div, neg, sq, twice, inv, sqrt, fabs) and trig calls
/// (sin, cos, atan2) in its body.
pub const OPERATION_COUNTS: [(&str, u32, u32); 17] = [
    ("frame_poses", 19, 4),
    ("end_effector_pose", 16, 4),
    ("jacobian", 14, 4),
    ("jacobian_and_position", 21, 4),
    ("jdot_qd", 30, 4),
    ("jacobian_derivatives", 14, 4),
    ("mass_matrix", 4, 1),
    ("coriolis_matrix", 8, 1),
    ("coriolis", 9, 1),
    ("gravity", 8, 4),
    ("inverse_dynamics", 31, 4),
    ("forward_dynamics", 32, 4),
    ("mass_matrix_and_bias", 21, 4),
    ("inverse_dynamics_derivatives", 43, 4),
    ("forward_dynamics_derivatives", 85, 4),
    ("regressor", 47, 4),
    ("standard_parameters", 0, 0),
];
/// Poses of every link frame (the description's DH frames, or its URDF links), products of the joint transforms `A_1 ... A_i` (thesis eq. 3.2-3.7).
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `poses: [[[f64; 4]; 4]; 2]` (2 x 4 x 4, row-major): homogeneous transforms T_0i of the description's frames 1..n in the base frame (m)
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
    let (v2, v1): (f64, f64) = ::armdyn_runtime::libm::sincos(v0);
    let v3: f64 = -v2;
    let v4: f64 = 0.0_f64;
    let v5: f64 = 0.5_f64;
    let v6: f64 = v5 * v1;
    let v7: f64 = v5 * v2;
    let v8: f64 = 1.0_f64;
    let v9: f64 = q[1];
    let (v12, v10): (f64, f64) = ::armdyn_runtime::libm::sincos(v9);
    let v11: f64 = v10 * v1;
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
/// `pose: [[f64; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the base frame (m)
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
    let (v5, v1): (f64, f64) = ::armdyn_runtime::libm::sincos(v0);
    let v2: f64 = q[0];
    let (v6, v3): (f64, f64) = ::armdyn_runtime::libm::sincos(v2);
    let v4: f64 = v1 * v3;
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
    let (v2, v9): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = 0.4_f64;
    let v5: f64 = q[1];
    let (v10, v6): (f64, f64) = ::armdyn_runtime::libm::sincos(v5);
    let v7: f64 = v4 * v6;
    let v8: f64 = v2 * v7;
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
/// Jacobian and tool position in one pass: `[J | p; 0]`, row r is `[J_r0, ..., J_r(n-1), p_r]` with `J` the geometric Jacobian of `jacobian` and `p` the end-effector origin of `end_effector_pose` (rows 0-2; the last column of rows 3-5 is 0), the same operations as those two functions (bit-identical results), with common subexpressions, sin/cos included, computed once for both and the pose's rotation not computed.
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `jacobian_and_position: [[f64; 3]; 6]` (6 x 3, row-major): rows `[J(q) | p(q); 0]`: the geometric Jacobian of `jacobian` (rows vx vy vz per unit joint velocity, then wx wy wz, base frame), then the end-effector origin (m, base frame) in rows 0-2 of the last column, 0 in rows 3-5
///
/// Operation count: 21 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn jacobian_and_position(q: &[f64; 2]) -> [[f64; 3]; 6] {
    let v0: f64 = 0.5_f64;
    let v1: f64 = q[0];
    let (v2, v9): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = 0.4_f64;
    let v5: f64 = q[1];
    let (v10, v6): (f64, f64) = ::armdyn_runtime::libm::sincos(v5);
    let v7: f64 = v4 * v6;
    let v8: f64 = v2 * v7;
    let v11: f64 = v4 * v10;
    let v12: f64 = v9 * v11;
    let v13: f64 = v8 + v12;
    let v14: f64 = v3 + v13;
    let v15: f64 = -v14;
    let v16: f64 = -v13;
    let v17: f64 = v0 + v7;
    let v18: f64 = v17 * v9;
    let v19: f64 = v11 * v2;
    let v20: f64 = v18 - v19;
    let v21: f64 = v0 * v9;
    let v22: f64 = v9 * v7;
    let v23: f64 = v2 * v11;
    let v24: f64 = v22 - v23;
    let v25: f64 = v21 + v24;
    let v26: f64 = v11 * v9;
    let v27: f64 = v17 * v2;
    let v28: f64 = v26 + v27;
    let v29: f64 = 0.0_f64;
    let v30: f64 = 1.0_f64;
    [
        [v15, v16, v20],
        [v25, v24, v28],
        [v29, v29, v29],
        [v29, v29, v29],
        [v29, v29, v29],
        [v30, v30, v29],
    ]
}
/// Acceleration term of the end-effector twist: `d/dt (J qd) = J qdd + Jdot qd`.
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
///
/// # Output
///
/// `jdot_qd: [f64; 6]`: Jdot(q, qd) qd: m/s^2 (rows 0-2) and rad/s^2 (rows 3-5), base frame
///
/// Operation count: 30 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn jdot_qd(q: &[f64; 2], qd: &[f64; 2]) -> [f64; 6] {
    let v0: f64 = 0.4_f64;
    let v1: f64 = q[1];
    let (v2, v7): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = q[0];
    let (v5, v9): (f64, f64) = ::armdyn_runtime::libm::sincos(v4);
    let v6: f64 = v3 * v5;
    let v8: f64 = v0 * v7;
    let v10: f64 = v8 * v9;
    let v11: f64 = v6 - v10;
    let v12: f64 = qd[1];
    let v13: f64 = v11 * v12;
    let v14: f64 = v13 * v12;
    let v15: f64 = 0.8_f64;
    let v16: f64 = v15 * v12;
    let v17: f64 = qd[0];
    let v18: f64 = v0 * v17;
    let v19: f64 = v16 + v18;
    let v20: f64 = v19 * v2;
    let v21: f64 = v20 * v5;
    let v22: f64 = 0.5_f64;
    let v23: f64 = v22 * v17;
    let v24: f64 = v19 * v7;
    let v25: f64 = v23 + v24;
    let v26: f64 = v25 * v9;
    let v27: f64 = v21 - v26;
    let v28: f64 = v27 * v17;
    let v29: f64 = v14 + v28;
    let v30: f64 = v3 * v9;
    let v31: f64 = v8 * v5;
    let v32: f64 = v30 + v31;
    let v33: f64 = v32 * v12;
    let v34: f64 = v33 * v12;
    let v35: f64 = v20 * v9;
    let v36: f64 = v25 * v5;
    let v37: f64 = v35 + v36;
    let v38: f64 = v37 * v17;
    let v39: f64 = v34 + v38;
    let v40: f64 = -v39;
    let v41: f64 = 0.0_f64;
    [v29, v40, v41, v41, v41, v41]
}
/// Partial derivatives of the geometric Jacobian, `d J / d q_k` for each joint k: `Jdot = sum_k d J/d q_k qd_k`, and `d (J^T f)/d q_k = (d J/d q_k)^T f` for a tool wrench f.
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `jacobian_derivatives: [[[f64; 2]; 6]; 2]` (2 x 6 x 2, row-major): `[k][r][c] = d J_rc / d q_k`, the partial derivatives of `jacobian` (m/rad or 1/rad per row kind; per m for prismatic joints)
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
pub fn jacobian_derivatives(q: &[f64; 2]) -> [[[f64; 2]; 6]; 2] {
    let v0: f64 = 0.4_f64;
    let v1: f64 = q[1];
    let (v2, v8): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = q[0];
    let (v5, v11): (f64, f64) = ::armdyn_runtime::libm::sincos(v4);
    let v6: f64 = v3 * v5;
    let v7: f64 = -0.5_f64;
    let v9: f64 = v0 * v8;
    let v10: f64 = v7 - v9;
    let v12: f64 = v10 * v11;
    let v13: f64 = v6 + v12;
    let v14: f64 = v9 * v11;
    let v15: f64 = v6 - v14;
    let v16: f64 = v10 * v5;
    let v17: f64 = v3 * v11;
    let v18: f64 = v16 - v17;
    let v19: f64 = v9 * v5;
    let v20: f64 = v17 + v19;
    let v21: f64 = -v20;
    let v22: f64 = 0.0_f64;
    [
        [[v13, v15], [v18, v21], [v22, v22], [v22, v22], [v22, v22], [v22, v22]],
        [[v15, v15], [v21, v21], [v22, v22], [v22, v22], [v22, v22], [v22, v22]],
    ]
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
    let v3: f64 = ::armdyn_runtime::libm::cos(v2);
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
    let v4: f64 = ::armdyn_runtime::libm::sin(v3);
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
    let v9: f64 = ::armdyn_runtime::libm::sin(v8);
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
    let (v9, v3): (f64, f64) = ::armdyn_runtime::libm::sincos(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = v0 + v4;
    let v6: f64 = q[0];
    let (v11, v7): (f64, f64) = ::armdyn_runtime::libm::sincos(v6);
    let v8: f64 = v5 * v7;
    let v10: f64 = v1 * v9;
    let v12: f64 = v10 * v11;
    let v13: f64 = v8 - v12;
    let v14: f64 = v4 * v7;
    let v15: f64 = v14 - v12;
    [v13, v15]
}
/// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
/// - `qdd: &[f64; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// # Output
///
/// `tau: [f64; 2]`: joint torques (N m) or forces (N), no external wrench
///
/// Operation count: 31 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn inverse_dynamics(q: &[f64; 2], qd: &[f64; 2], qdd: &[f64; 2]) -> [f64; 2] {
    let v0: f64 = 0.08015_f64;
    let v1: f64 = qdd[1];
    let v2: f64 = v0 * v1;
    let v3: f64 = 0.6220166666666667_f64;
    let v4: f64 = qdd[0];
    let v5: f64 = v3 * v4;
    let v6: f64 = v2 + v5;
    let v7: f64 = 12.2625_f64;
    let v8: f64 = q[0];
    let (v24, v9): (f64, f64) = ::armdyn_runtime::libm::sincos(v8);
    let v10: f64 = v7 * v9;
    let v11: f64 = v6 + v10;
    let v12: f64 = 0.15_f64;
    let v13: f64 = v12 * v1;
    let v14: f64 = 0.3_f64;
    let v15: f64 = v14 * v4;
    let v16: f64 = v13 + v15;
    let v17: f64 = 2.943_f64;
    let v18: f64 = v17 * v9;
    let v19: f64 = v16 + v18;
    let v20: f64 = q[1];
    let (v33, v21): (f64, f64) = ::armdyn_runtime::libm::sincos(v20);
    let v22: f64 = v19 * v21;
    let v23: f64 = v11 + v22;
    let v25: f64 = v17 * v24;
    let v26: f64 = qd[1];
    let v27: f64 = v12 * v26;
    let v28: f64 = qd[0];
    let v29: f64 = v14 * v28;
    let v30: f64 = v27 + v29;
    let v31: f64 = v30 * v26;
    let v32: f64 = v25 + v31;
    let v34: f64 = v32 * v33;
    let v35: f64 = v23 - v34;
    let v36: f64 = v0 * v4;
    let v37: f64 = v2 + v36;
    let v38: f64 = v12 * v4;
    let v39: f64 = v38 + v18;
    let v40: f64 = v39 * v21;
    let v41: f64 = v37 + v40;
    let v42: f64 = v12 * v28;
    let v43: f64 = v42 * v28;
    let v44: f64 = v43 - v25;
    let v45: f64 = v44 * v33;
    let v46: f64 = v41 + v45;
    [v35, v46]
}
/// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g.
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
/// - `tau: &[f64; 2]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
///
/// # Output
///
/// `qdd: [f64; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// Operation count: 32 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn forward_dynamics(q: &[f64; 2], qd: &[f64; 2], tau: &[f64; 2]) -> [f64; 2] {
    let v0: f64 = tau[0];
    let v1: f64 = 12.2625_f64;
    let v2: f64 = 2.943_f64;
    let v3: f64 = q[1];
    let (v21, v4): (f64, f64) = ::armdyn_runtime::libm::sincos(v3);
    let v5: f64 = v2 * v4;
    let v6: f64 = v1 + v5;
    let v7: f64 = q[0];
    let (v10, v8): (f64, f64) = ::armdyn_runtime::libm::sincos(v7);
    let v9: f64 = v6 * v8;
    let v11: f64 = v2 * v10;
    let v12: f64 = 0.15_f64;
    let v13: f64 = qd[1];
    let v14: f64 = v12 * v13;
    let v15: f64 = 0.3_f64;
    let v16: f64 = qd[0];
    let v17: f64 = v15 * v16;
    let v18: f64 = v14 + v17;
    let v19: f64 = v18 * v13;
    let v20: f64 = v11 + v19;
    let v22: f64 = v20 * v21;
    let v23: f64 = v9 - v22;
    let v24: f64 = v0 - v23;
    let v25: f64 = 12.476606363069246_f64;
    let v26: f64 = 0.08015_f64;
    let v27: f64 = v12 * v4;
    let v28: f64 = v26 + v27;
    let v29: f64 = v25 * v28;
    let v30: f64 = tau[1];
    let v31: f64 = v5 * v8;
    let v32: f64 = v12 * v16;
    let v33: f64 = v32 * v16;
    let v34: f64 = v33 - v11;
    let v35: f64 = v34 * v21;
    let v36: f64 = v31 + v35;
    let v37: f64 = v30 - v36;
    let v38: f64 = v29 * v37;
    let v39: f64 = v24 - v38;
    let v40: f64 = 0.6220166666666667_f64;
    let v41: f64 = v15 * v4;
    let v42: f64 = v40 + v41;
    let v43: f64 = v28 * v29;
    let v44: f64 = v42 - v43;
    let v45: f64 = v39 / v44;
    let v46: f64 = v25 * v37;
    let v47: f64 = v29 * v45;
    let v48: f64 = v46 - v47;
    [v45, v48]
}
/// Mass matrix and bias in one pass: row i is `[M_i0, ..., M_i(n-1), c_i + g_i]`, the `M(q)` of `mass_matrix` with the bias `c(q, qd) + g(q)` of `coriolis` and `gravity` as a last column (what Pinocchio's `crba` and `nonLinearEffects` compute together). Common subexpressions, sin/cos included, are computed once for both.
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
///
/// # Output
///
/// `mass_matrix_and_bias: [[f64; 3]; 2]` (2 x 3, row-major): rows `[M(q) | c(q, qd) + g(q)]`: the symmetric positive definite M (kg m^2, kg m, kg), then the bias (N m or N)
///
/// Operation count: 21 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn mass_matrix_and_bias(q: &[f64; 2], qd: &[f64; 2]) -> [[f64; 3]; 2] {
    let v0: f64 = 0.6220166666666667_f64;
    let v1: f64 = 0.3_f64;
    let v2: f64 = q[1];
    let (v26, v3): (f64, f64) = ::armdyn_runtime::libm::sincos(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = v0 + v4;
    let v6: f64 = 0.08015_f64;
    let v7: f64 = 0.15_f64;
    let v8: f64 = v7 * v3;
    let v9: f64 = v6 + v8;
    let v10: f64 = 12.2625_f64;
    let v11: f64 = 2.943_f64;
    let v12: f64 = v11 * v3;
    let v13: f64 = v10 + v12;
    let v14: f64 = q[0];
    let (v17, v15): (f64, f64) = ::armdyn_runtime::libm::sincos(v14);
    let v16: f64 = v13 * v15;
    let v18: f64 = v11 * v17;
    let v19: f64 = qd[1];
    let v20: f64 = v7 * v19;
    let v21: f64 = qd[0];
    let v22: f64 = v1 * v21;
    let v23: f64 = v20 + v22;
    let v24: f64 = v23 * v19;
    let v25: f64 = v18 + v24;
    let v27: f64 = v25 * v26;
    let v28: f64 = v16 - v27;
    let v29: f64 = v12 * v15;
    let v30: f64 = v7 * v21;
    let v31: f64 = v30 * v21;
    let v32: f64 = v31 - v18;
    let v33: f64 = v32 * v26;
    let v34: f64 = v29 + v33;
    [[v5, v9, v28], [v9, v6, v34]]
}
/// Derivatives of inverse dynamics: row i is `[d tau_i/d q | d tau_i/d qd | d tau_i/d qdd]` (3n entries; the last block is the mass matrix `M(q)`), the partial derivatives of `inverse_dynamics` (what Pinocchio's `computeRNEADerivatives` computes), generated by algorithmic differentiation of its graph and folded like every other function.
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
/// - `qdd: &[f64; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// # Output
///
/// `inverse_dynamics_derivatives: [[f64; 6]; 2]` (2 x 6, row-major): rows `[d tau/d q | d tau/d qd | M(q)]`: N m/rad, N m s/rad, kg m^2 (N/m, N s/m, kg for prismatic joints)
///
/// Operation count: 43 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn inverse_dynamics_derivatives(
    q: &[f64; 2],
    qd: &[f64; 2],
    qdd: &[f64; 2],
) -> [[f64; 6]; 2] {
    let v0: f64 = 12.2625_f64;
    let v1: f64 = q[0];
    let (v2, v11): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = q[1];
    let (v10, v5): (f64, f64) = ::armdyn_runtime::libm::sincos(v4);
    let v6: f64 = 2.943_f64;
    let v7: f64 = v6 * v2;
    let v8: f64 = v5 * v7;
    let v9: f64 = v3 + v8;
    let v12: f64 = v6 * v11;
    let v13: f64 = v10 * v12;
    let v14: f64 = v9 + v13;
    let v15: f64 = -v14;
    let v16: f64 = 0.15_f64;
    let v17: f64 = qdd[1];
    let v18: f64 = v16 * v17;
    let v19: f64 = 0.3_f64;
    let v20: f64 = qdd[0];
    let v21: f64 = v19 * v20;
    let v22: f64 = v18 + v21;
    let v23: f64 = v22 + v12;
    let v24: f64 = v23 * v10;
    let v25: f64 = qd[1];
    let v26: f64 = v16 * v25;
    let v27: f64 = qd[0];
    let v28: f64 = v19 * v27;
    let v29: f64 = v26 + v28;
    let v30: f64 = v29 * v25;
    let v31: f64 = v7 + v30;
    let v32: f64 = v31 * v5;
    let v33: f64 = v24 + v32;
    let v34: f64 = -v33;
    let v35: f64 = v19 * v25;
    let v36: f64 = v10 * v35;
    let v37: f64 = -v36;
    let v38: f64 = v26 + v29;
    let v39: f64 = v10 * v38;
    let v40: f64 = -v39;
    let v41: f64 = 0.6220166666666667_f64;
    let v42: f64 = v19 * v5;
    let v43: f64 = v41 + v42;
    let v44: f64 = 0.08015_f64;
    let v45: f64 = v16 * v5;
    let v46: f64 = v44 + v45;
    let v47: f64 = v8 + v13;
    let v48: f64 = -v47;
    let v49: f64 = v16 * v27;
    let v50: f64 = v49 * v27;
    let v51: f64 = v50 - v7;
    let v52: f64 = v51 * v5;
    let v53: f64 = v16 * v20;
    let v54: f64 = v53 + v12;
    let v55: f64 = v54 * v10;
    let v56: f64 = v52 - v55;
    let v57: f64 = v49 + v49;
    let v58: f64 = v10 * v57;
    let v59: f64 = 0.0_f64;
    [[v15, v34, v37, v40, v43, v46], [v48, v56, v58, v59, v46, v44]]
}
/// Derivatives of forward dynamics: row i is `[d qdd_i/d q | d qdd_i/d qd | d qdd_i/d tau]` (3n entries; the last block is `M(q)^-1`), the partial derivatives of `forward_dynamics` (what Pinocchio's `computeABADerivatives` computes): `d qdd/d x = -M^-1 d ID/d x` at `qdd = forward_dynamics(q, qd, tau)` (implicit function theorem on `inverse_dynamics(q, qd, forward_dynamics(q, qd, tau)) = tau`), all 3n right-hand sides solved by one unrolled sparse `L^T D L` factorisation of M. For a tool wrench `f` (`tau - J^T f` into forward dynamics) add `-M^-1 d(J^T f)/d q` to the first block, from `jacobian_derivatives`.
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
/// - `tau: &[f64; 2]`: joint torques (N m) or forces (N)
///
/// # Output
///
/// `forward_dynamics_derivatives: [[f64; 6]; 2]` (2 x 6, row-major): rows `[d qdd/d q | d qdd/d qd | M(q)^-1]`: 1/s^2, 1/s, 1/(kg m^2) (per m, per kg for prismatic joints)
///
/// Operation count: 85 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn forward_dynamics_derivatives(
    q: &[f64; 2],
    qd: &[f64; 2],
    tau: &[f64; 2],
) -> [[f64; 6]; 2] {
    let v0: f64 = 12.2625_f64;
    let v1: f64 = q[0];
    let (v2, v11): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = q[1];
    let (v10, v5): (f64, f64) = ::armdyn_runtime::libm::sincos(v4);
    let v6: f64 = 2.943_f64;
    let v7: f64 = v6 * v2;
    let v8: f64 = v5 * v7;
    let v9: f64 = v3 + v8;
    let v12: f64 = v6 * v11;
    let v13: f64 = v10 * v12;
    let v14: f64 = v9 + v13;
    let v15: f64 = 12.476606363069246_f64;
    let v16: f64 = 0.08015_f64;
    let v17: f64 = 0.15_f64;
    let v18: f64 = v17 * v5;
    let v19: f64 = v16 + v18;
    let v20: f64 = v15 * v19;
    let v21: f64 = v8 + v13;
    let v22: f64 = v20 * v21;
    let v23: f64 = v14 - v22;
    let v24: f64 = 0.6220166666666667_f64;
    let v25: f64 = 0.3_f64;
    let v26: f64 = v25 * v5;
    let v27: f64 = v24 + v26;
    let v28: f64 = v19 * v20;
    let v29: f64 = v27 - v28;
    let v30: f64 = v23 / v29;
    let v31: f64 = tau[1];
    let v32: f64 = v6 * v5;
    let v33: f64 = v32 * v11;
    let v34: f64 = qd[0];
    let v35: f64 = v17 * v34;
    let v36: f64 = v35 * v34;
    let v37: f64 = v36 - v7;
    let v38: f64 = v37 * v10;
    let v39: f64 = v33 + v38;
    let v40: f64 = v31 - v39;
    let v41: f64 = v15 * v40;
    let v42: f64 = tau[0];
    let v43: f64 = v0 + v32;
    let v44: f64 = v43 * v11;
    let v45: f64 = qd[1];
    let v46: f64 = v17 * v45;
    let v47: f64 = v25 * v34;
    let v48: f64 = v46 + v47;
    let v49: f64 = v48 * v45;
    let v50: f64 = v7 + v49;
    let v51: f64 = v50 * v10;
    let v52: f64 = v44 - v51;
    let v53: f64 = v42 - v52;
    let v54: f64 = v20 * v40;
    let v55: f64 = v53 - v54;
    let v56: f64 = v55 / v29;
    let v57: f64 = v20 * v56;
    let v58: f64 = v41 - v57;
    let v59: f64 = v17 * v58;
    let v60: f64 = v25 * v56;
    let v61: f64 = v59 + v60;
    let v62: f64 = v61 + v12;
    let v63: f64 = v62 * v10;
    let v64: f64 = v50 * v5;
    let v65: f64 = v63 + v64;
    let v66: f64 = v37 * v5;
    let v67: f64 = v17 * v56;
    let v68: f64 = v67 + v12;
    let v69: f64 = v68 * v10;
    let v70: f64 = v66 - v69;
    let v71: f64 = v20 * v70;
    let v72: f64 = v65 + v71;
    let v73: f64 = v72 / v29;
    let v74: f64 = v25 * v45;
    let v75: f64 = v10 * v74;
    let v76: f64 = v35 + v35;
    let v77: f64 = v10 * v76;
    let v78: f64 = v20 * v77;
    let v79: f64 = v75 + v78;
    let v80: f64 = v79 / v29;
    let v81: f64 = v46 + v48;
    let v82: f64 = v10 * v81;
    let v83: f64 = v82 / v29;
    let v84: f64 = 1.0_f64 / v29;
    let v85: f64 = v20 / v29;
    let v86: f64 = -v85;
    let v87: f64 = v15 * v21;
    let v88: f64 = v20 * v30;
    let v89: f64 = v87 - v88;
    let v90: f64 = v15 * v70;
    let v91: f64 = v20 * v73;
    let v92: f64 = v90 + v91;
    let v93: f64 = -v92;
    let v94: f64 = v15 * v77;
    let v95: f64 = v20 * v80;
    let v96: f64 = v94 + v95;
    let v97: f64 = -v96;
    let v98: f64 = v20 * v83;
    let v99: f64 = -v98;
    let v100: f64 = v20 * v85;
    let v101: f64 = v15 + v100;
    [[v30, v73, v80, v83, v84, v86], [v89, v93, v97, v99, v86, v101]]
}
/// Dynamic regressor: `inverse_dynamics(q, qd, qdd) = Y(q, qd, qdd) * standard_parameters()`.
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
/// - `qdd: &[f64; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// # Output
///
/// `regressor: [[f64; 20]; 2]` (2 x 20, row-major): Y(q, qd, qdd), columns in the order of `standard_parameters`
///
/// Operation count: 47 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn regressor(q: &[f64; 2], qd: &[f64; 2], qdd: &[f64; 2]) -> [[f64; 20]; 2] {
    let v0: f64 = 0.5_f64;
    let v1: f64 = 9.81_f64;
    let v2: f64 = q[0];
    let (v14, v3): (f64, f64) = ::armdyn_runtime::libm::sincos(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = qdd[0];
    let v6: f64 = v0 * v5;
    let v7: f64 = v4 + v6;
    let v8: f64 = v0 * v7;
    let v9: f64 = v6 + v7;
    let v10: f64 = qd[0];
    let v11: f64 = -0.5_f64;
    let v12: f64 = v11 * v10;
    let v13: f64 = v10 * v12;
    let v15: f64 = v1 * v14;
    let v16: f64 = v0 * v10;
    let v17: f64 = v10 * v16;
    let v18: f64 = v15 - v17;
    let v19: f64 = v13 - v18;
    let v20: f64 = q[1];
    let (v23, v21): (f64, f64) = ::armdyn_runtime::libm::sincos(v20);
    let v22: f64 = v21 * v18;
    let v24: f64 = v23 * v7;
    let v25: f64 = v22 + v24;
    let v26: f64 = qd[1];
    let v27: f64 = v10 + v26;
    let v28: f64 = 0.4_f64;
    let v29: f64 = v28 * v27;
    let v30: f64 = v27 * v29;
    let v31: f64 = v25 - v30;
    let v32: f64 = v0 * v23;
    let v33: f64 = v31 * v32;
    let v34: f64 = v21 * v7;
    let v35: f64 = v23 * v18;
    let v36: f64 = v34 - v35;
    let v37: f64 = qdd[1];
    let v38: f64 = v5 + v37;
    let v39: f64 = v28 * v38;
    let v40: f64 = v36 + v39;
    let v41: f64 = v0 * v21;
    let v42: f64 = v41 + v28;
    let v43: f64 = v40 * v42;
    let v44: f64 = v33 + v43;
    let v45: f64 = v38 * v42;
    let v46: f64 = v27 * v32;
    let v47: f64 = v27 * v46;
    let v48: f64 = v45 - v47;
    let v49: f64 = v48 + v40;
    let v50: f64 = v38 * v32;
    let v51: f64 = v27 * v42;
    let v52: f64 = v27 * v51;
    let v53: f64 = v50 + v52;
    let v54: f64 = v53 + v31;
    let v55: f64 = -v54;
    let v56: f64 = v28 * v40;
    let v57: f64 = v39 + v40;
    let v58: f64 = -0.4_f64;
    let v59: f64 = v58 * v27;
    let v60: f64 = v27 * v59;
    let v61: f64 = v60 - v31;
    let v62: f64 = 0.0_f64;
    [
        [
            v8,
            v9,
            v19,
            v62,
            v62,
            v62,
            v62,
            v62,
            v62,
            v5,
            v44,
            v49,
            v55,
            v62,
            v62,
            v62,
            v62,
            v62,
            v62,
            v38,
        ],
        [
            v62,
            v62,
            v62,
            v62,
            v62,
            v62,
            v62,
            v62,
            v62,
            v62,
            v56,
            v57,
            v61,
            v62,
            v62,
            v62,
            v62,
            v62,
            v62,
            v38,
        ],
    ]
}
/// The robot's own standard inertial parameters, the `params` of the parametric model.
///
/// # Inputs
///
/// None.
///
/// # Output
///
/// `params: [f64; 20]`: per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2, inertia about the link frame origin)
///
/// Operation count: 0 floating-point operations, 0 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn standard_parameters() -> [f64; 20] {
    let v0: f64 = 2.0_f64;
    let v1: f64 = -0.5_f64;
    let v2: f64 = 0.0_f64;
    let v3: f64 = 0.0004_f64;
    let v4: f64 = 0.16686666666666666_f64;
    let v5: f64 = 1.5_f64;
    let v6: f64 = -0.3_f64;
    let v7: f64 = 0.0003_f64;
    let v8: f64 = 0.08015_f64;
    [v0, v1, v2, v2, v3, v2, v2, v4, v2, v4, v5, v6, v2, v2, v7, v2, v2, v8, v2, v8]
}
/// The same functions in single precision (`f32`), for processors whose FPU has no
/// `f64` (Cortex-M4F): every constant is the `f64` one rounded to the nearest
/// `f32`, and `libm`'s `sinf`, `cosf`, `sqrtf`, `fabsf`, `atan2f` replace the
/// `f64` calls. Same inputs, outputs and units as the parent module's.
pub mod f32 {
    /// Poses of every link frame (the description's DH frames, or its URDF links), products of the joint transforms `A_1 ... A_i` (thesis eq. 3.2-3.7).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `poses: [[[f32; 4]; 4]; 2]` (2 x 4 x 4, row-major): homogeneous transforms T_0i of the description's frames 1..n in the base frame (m)
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
    pub fn frame_poses(q: &[f32; 2]) -> [[[f32; 4]; 4]; 2] {
        let v0: f32 = q[0];
        let (v2, v1): (f32, f32) = ::armdyn_runtime::libm::sincosf(v0);
        let v3: f32 = -v2;
        let v4: f32 = 0.0_f32;
        let v5: f32 = 0.5_f32;
        let v6: f32 = v5 * v1;
        let v7: f32 = v5 * v2;
        let v8: f32 = 1.0_f32;
        let v9: f32 = q[1];
        let (v12, v10): (f32, f32) = ::armdyn_runtime::libm::sincosf(v9);
        let v11: f32 = v10 * v1;
        let v13: f32 = v12 * v2;
        let v14: f32 = v11 - v13;
        let v15: f32 = v12 * v1;
        let v16: f32 = v10 * v2;
        let v17: f32 = v15 + v16;
        let v18: f32 = -v17;
        let v19: f32 = 0.4_f32;
        let v20: f32 = v19 * v10;
        let v21: f32 = v5 + v20;
        let v22: f32 = v21 * v1;
        let v23: f32 = v19 * v12;
        let v24: f32 = v23 * v2;
        let v25: f32 = v22 - v24;
        let v26: f32 = v23 * v1;
        let v27: f32 = v21 * v2;
        let v28: f32 = v26 + v27;
        [
            [[v1, v3, v4, v6], [v2, v1, v4, v7], [v4, v4, v8, v4], [v4, v4, v4, v8]],
            [
                [v14, v18, v4, v25],
                [v17, v14, v4, v28],
                [v4, v4, v8, v4],
                [v4, v4, v4, v8],
            ],
        ]
    }
    /// End-effector pose, forward kinematics `T_0n` (thesis eq. 3.7).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `pose: [[f32; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the base frame (m)
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
    pub fn end_effector_pose(q: &[f32; 2]) -> [[f32; 4]; 4] {
        let v0: f32 = q[1];
        let (v5, v1): (f32, f32) = ::armdyn_runtime::libm::sincosf(v0);
        let v2: f32 = q[0];
        let (v6, v3): (f32, f32) = ::armdyn_runtime::libm::sincosf(v2);
        let v4: f32 = v1 * v3;
        let v7: f32 = v5 * v6;
        let v8: f32 = v4 - v7;
        let v9: f32 = v5 * v3;
        let v10: f32 = v1 * v6;
        let v11: f32 = v9 + v10;
        let v12: f32 = -v11;
        let v13: f32 = 0.0_f32;
        let v14: f32 = 0.5_f32;
        let v15: f32 = 0.4_f32;
        let v16: f32 = v15 * v1;
        let v17: f32 = v14 + v16;
        let v18: f32 = v17 * v3;
        let v19: f32 = v15 * v5;
        let v20: f32 = v19 * v6;
        let v21: f32 = v18 - v20;
        let v22: f32 = v19 * v3;
        let v23: f32 = v17 * v6;
        let v24: f32 = v22 + v23;
        let v25: f32 = 1.0_f32;
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
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian: [[f32; 2]; 6]` (6 x 2, row-major): rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame
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
    pub fn jacobian(q: &[f32; 2]) -> [[f32; 2]; 6] {
        let v0: f32 = 0.5_f32;
        let v1: f32 = q[0];
        let (v2, v9): (f32, f32) = ::armdyn_runtime::libm::sincosf(v1);
        let v3: f32 = v0 * v2;
        let v4: f32 = 0.4_f32;
        let v5: f32 = q[1];
        let (v10, v6): (f32, f32) = ::armdyn_runtime::libm::sincosf(v5);
        let v7: f32 = v4 * v6;
        let v8: f32 = v2 * v7;
        let v11: f32 = v4 * v10;
        let v12: f32 = v9 * v11;
        let v13: f32 = v8 + v12;
        let v14: f32 = v3 + v13;
        let v15: f32 = -v14;
        let v16: f32 = -v13;
        let v17: f32 = v0 * v9;
        let v18: f32 = v9 * v7;
        let v19: f32 = v2 * v11;
        let v20: f32 = v18 - v19;
        let v21: f32 = v17 + v20;
        let v22: f32 = 0.0_f32;
        let v23: f32 = 1.0_f32;
        [[v15, v16], [v21, v20], [v22, v22], [v22, v22], [v22, v22], [v23, v23]]
    }
    /// Jacobian and tool position in one pass: `[J | p; 0]`, row r is `[J_r0, ..., J_r(n-1), p_r]` with `J` the geometric Jacobian of `jacobian` and `p` the end-effector origin of `end_effector_pose` (rows 0-2; the last column of rows 3-5 is 0), the same operations as those two functions (bit-identical results), with common subexpressions, sin/cos included, computed once for both and the pose's rotation not computed.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian_and_position: [[f32; 3]; 6]` (6 x 3, row-major): rows `[J(q) | p(q); 0]`: the geometric Jacobian of `jacobian` (rows vx vy vz per unit joint velocity, then wx wy wz, base frame), then the end-effector origin (m, base frame) in rows 0-2 of the last column, 0 in rows 3-5
    ///
    /// Operation count: 21 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jacobian_and_position(q: &[f32; 2]) -> [[f32; 3]; 6] {
        let v0: f32 = 0.5_f32;
        let v1: f32 = q[0];
        let (v2, v9): (f32, f32) = ::armdyn_runtime::libm::sincosf(v1);
        let v3: f32 = v0 * v2;
        let v4: f32 = 0.4_f32;
        let v5: f32 = q[1];
        let (v10, v6): (f32, f32) = ::armdyn_runtime::libm::sincosf(v5);
        let v7: f32 = v4 * v6;
        let v8: f32 = v2 * v7;
        let v11: f32 = v4 * v10;
        let v12: f32 = v9 * v11;
        let v13: f32 = v8 + v12;
        let v14: f32 = v3 + v13;
        let v15: f32 = -v14;
        let v16: f32 = -v13;
        let v17: f32 = v0 + v7;
        let v18: f32 = v17 * v9;
        let v19: f32 = v11 * v2;
        let v20: f32 = v18 - v19;
        let v21: f32 = v0 * v9;
        let v22: f32 = v9 * v7;
        let v23: f32 = v2 * v11;
        let v24: f32 = v22 - v23;
        let v25: f32 = v21 + v24;
        let v26: f32 = v11 * v9;
        let v27: f32 = v17 * v2;
        let v28: f32 = v26 + v27;
        let v29: f32 = 0.0_f32;
        let v30: f32 = 1.0_f32;
        [
            [v15, v16, v20],
            [v25, v24, v28],
            [v29, v29, v29],
            [v29, v29, v29],
            [v29, v29, v29],
            [v30, v30, v29],
        ]
    }
    /// Acceleration term of the end-effector twist: `d/dt (J qd) = J qdd + Jdot qd`.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 2]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `jdot_qd: [f32; 6]`: Jdot(q, qd) qd: m/s^2 (rows 0-2) and rad/s^2 (rows 3-5), base frame
    ///
    /// Operation count: 30 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jdot_qd(q: &[f32; 2], qd: &[f32; 2]) -> [f32; 6] {
        let v0: f32 = 0.4_f32;
        let v1: f32 = q[1];
        let (v2, v7): (f32, f32) = ::armdyn_runtime::libm::sincosf(v1);
        let v3: f32 = v0 * v2;
        let v4: f32 = q[0];
        let (v5, v9): (f32, f32) = ::armdyn_runtime::libm::sincosf(v4);
        let v6: f32 = v3 * v5;
        let v8: f32 = v0 * v7;
        let v10: f32 = v8 * v9;
        let v11: f32 = v6 - v10;
        let v12: f32 = qd[1];
        let v13: f32 = v11 * v12;
        let v14: f32 = v13 * v12;
        let v15: f32 = 0.8_f32;
        let v16: f32 = v15 * v12;
        let v17: f32 = qd[0];
        let v18: f32 = v0 * v17;
        let v19: f32 = v16 + v18;
        let v20: f32 = v19 * v2;
        let v21: f32 = v20 * v5;
        let v22: f32 = 0.5_f32;
        let v23: f32 = v22 * v17;
        let v24: f32 = v19 * v7;
        let v25: f32 = v23 + v24;
        let v26: f32 = v25 * v9;
        let v27: f32 = v21 - v26;
        let v28: f32 = v27 * v17;
        let v29: f32 = v14 + v28;
        let v30: f32 = v3 * v9;
        let v31: f32 = v8 * v5;
        let v32: f32 = v30 + v31;
        let v33: f32 = v32 * v12;
        let v34: f32 = v33 * v12;
        let v35: f32 = v20 * v9;
        let v36: f32 = v25 * v5;
        let v37: f32 = v35 + v36;
        let v38: f32 = v37 * v17;
        let v39: f32 = v34 + v38;
        let v40: f32 = -v39;
        let v41: f32 = 0.0_f32;
        [v29, v40, v41, v41, v41, v41]
    }
    /// Partial derivatives of the geometric Jacobian, `d J / d q_k` for each joint k: `Jdot = sum_k d J/d q_k qd_k`, and `d (J^T f)/d q_k = (d J/d q_k)^T f` for a tool wrench f.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian_derivatives: [[[f32; 2]; 6]; 2]` (2 x 6 x 2, row-major): `[k][r][c] = d J_rc / d q_k`, the partial derivatives of `jacobian` (m/rad or 1/rad per row kind; per m for prismatic joints)
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
    pub fn jacobian_derivatives(q: &[f32; 2]) -> [[[f32; 2]; 6]; 2] {
        let v0: f32 = 0.4_f32;
        let v1: f32 = q[1];
        let (v2, v8): (f32, f32) = ::armdyn_runtime::libm::sincosf(v1);
        let v3: f32 = v0 * v2;
        let v4: f32 = q[0];
        let (v5, v11): (f32, f32) = ::armdyn_runtime::libm::sincosf(v4);
        let v6: f32 = v3 * v5;
        let v7: f32 = -0.5_f32;
        let v9: f32 = v0 * v8;
        let v10: f32 = v7 - v9;
        let v12: f32 = v10 * v11;
        let v13: f32 = v6 + v12;
        let v14: f32 = v9 * v11;
        let v15: f32 = v6 - v14;
        let v16: f32 = v10 * v5;
        let v17: f32 = v3 * v11;
        let v18: f32 = v16 - v17;
        let v19: f32 = v9 * v5;
        let v20: f32 = v17 + v19;
        let v21: f32 = -v20;
        let v22: f32 = 0.0_f32;
        [
            [[v13, v15], [v18, v21], [v22, v22], [v22, v22], [v22, v22], [v22, v22]],
            [[v15, v15], [v21, v21], [v22, v22], [v22, v22], [v22, v22], [v22, v22]],
        ]
    }
    /// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `mass_matrix: [[f32; 2]; 2]` (2 x 2, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
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
    pub fn mass_matrix(q: &[f32; 2]) -> [[f32; 2]; 2] {
        let v0: f32 = 0.62201667_f32;
        let v1: f32 = 0.3_f32;
        let v2: f32 = q[1];
        let v3: f32 = ::armdyn_runtime::libm::cosf(v2);
        let v4: f32 = v1 * v3;
        let v5: f32 = v0 + v4;
        let v6: f32 = 0.08015_f32;
        let v7: f32 = 0.15_f32;
        let v8: f32 = v7 * v3;
        let v9: f32 = v6 + v8;
        [[v5, v9], [v9, v6]]
    }
    /// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 2]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis_matrix: [[f32; 2]; 2]` (2 x 2, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
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
    pub fn coriolis_matrix(q: &[f32; 2], qd: &[f32; 2]) -> [[f32; 2]; 2] {
        let v0: f32 = 0.15_f32;
        let v1: f32 = qd[1];
        let v2: f32 = v0 * v1;
        let v3: f32 = q[1];
        let v4: f32 = ::armdyn_runtime::libm::sinf(v3);
        let v5: f32 = v2 * v4;
        let v6: f32 = -v5;
        let v7: f32 = qd[0];
        let v8: f32 = v0 * v7;
        let v9: f32 = v2 + v8;
        let v10: f32 = v9 * v4;
        let v11: f32 = -v10;
        let v12: f32 = v8 * v4;
        let v13: f32 = 0.0_f32;
        [[v6, v11], [v12, v13]]
    }
    /// Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 2]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis: [f32; 2]`: c(q, qd) = C(q, qd) qd (N m or N)
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
    pub fn coriolis(q: &[f32; 2], qd: &[f32; 2]) -> [f32; 2] {
        let v0: f32 = 0.15_f32;
        let v1: f32 = qd[1];
        let v2: f32 = v0 * v1;
        let v3: f32 = 0.3_f32;
        let v4: f32 = qd[0];
        let v5: f32 = v3 * v4;
        let v6: f32 = v2 + v5;
        let v7: f32 = v6 * v1;
        let v8: f32 = q[1];
        let v9: f32 = ::armdyn_runtime::libm::sinf(v8);
        let v10: f32 = v7 * v9;
        let v11: f32 = -v10;
        let v12: f32 = v0 * v4;
        let v13: f32 = v12 * v4;
        let v14: f32 = v13 * v9;
        [v11, v14]
    }
    /// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `gravity: [f32; 2]`: g(q), joint torques (N m) or forces (N) that hold the robot still
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
    pub fn gravity(q: &[f32; 2]) -> [f32; 2] {
        let v0: f32 = 12.2625_f32;
        let v1: f32 = 2.943_f32;
        let v2: f32 = q[1];
        let (v9, v3): (f32, f32) = ::armdyn_runtime::libm::sincosf(v2);
        let v4: f32 = v1 * v3;
        let v5: f32 = v0 + v4;
        let v6: f32 = q[0];
        let (v11, v7): (f32, f32) = ::armdyn_runtime::libm::sincosf(v6);
        let v8: f32 = v5 * v7;
        let v10: f32 = v1 * v9;
        let v12: f32 = v10 * v11;
        let v13: f32 = v8 - v12;
        let v14: f32 = v4 * v7;
        let v15: f32 = v14 - v12;
        [v13, v15]
    }
    /// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 2]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[f32; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `tau: [f32; 2]`: joint torques (N m) or forces (N), no external wrench
    ///
    /// Operation count: 31 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn inverse_dynamics(q: &[f32; 2], qd: &[f32; 2], qdd: &[f32; 2]) -> [f32; 2] {
        let v0: f32 = 0.08015_f32;
        let v1: f32 = qdd[1];
        let v2: f32 = v0 * v1;
        let v3: f32 = 0.62201667_f32;
        let v4: f32 = qdd[0];
        let v5: f32 = v3 * v4;
        let v6: f32 = v2 + v5;
        let v7: f32 = 12.2625_f32;
        let v8: f32 = q[0];
        let (v24, v9): (f32, f32) = ::armdyn_runtime::libm::sincosf(v8);
        let v10: f32 = v7 * v9;
        let v11: f32 = v6 + v10;
        let v12: f32 = 0.15_f32;
        let v13: f32 = v12 * v1;
        let v14: f32 = 0.3_f32;
        let v15: f32 = v14 * v4;
        let v16: f32 = v13 + v15;
        let v17: f32 = 2.943_f32;
        let v18: f32 = v17 * v9;
        let v19: f32 = v16 + v18;
        let v20: f32 = q[1];
        let (v33, v21): (f32, f32) = ::armdyn_runtime::libm::sincosf(v20);
        let v22: f32 = v19 * v21;
        let v23: f32 = v11 + v22;
        let v25: f32 = v17 * v24;
        let v26: f32 = qd[1];
        let v27: f32 = v12 * v26;
        let v28: f32 = qd[0];
        let v29: f32 = v14 * v28;
        let v30: f32 = v27 + v29;
        let v31: f32 = v30 * v26;
        let v32: f32 = v25 + v31;
        let v34: f32 = v32 * v33;
        let v35: f32 = v23 - v34;
        let v36: f32 = v0 * v4;
        let v37: f32 = v2 + v36;
        let v38: f32 = v12 * v4;
        let v39: f32 = v38 + v18;
        let v40: f32 = v39 * v21;
        let v41: f32 = v37 + v40;
        let v42: f32 = v12 * v28;
        let v43: f32 = v42 * v28;
        let v44: f32 = v43 - v25;
        let v45: f32 = v44 * v33;
        let v46: f32 = v41 + v45;
        [v35, v46]
    }
    /// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 2]`: joint velocities qd (rad/s or m/s)
    /// - `tau: &[f32; 2]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
    ///
    /// # Output
    ///
    /// `qdd: [f32; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// Operation count: 32 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn forward_dynamics(q: &[f32; 2], qd: &[f32; 2], tau: &[f32; 2]) -> [f32; 2] {
        let v0: f32 = tau[0];
        let v1: f32 = 12.2625_f32;
        let v2: f32 = 2.943_f32;
        let v3: f32 = q[1];
        let (v21, v4): (f32, f32) = ::armdyn_runtime::libm::sincosf(v3);
        let v5: f32 = v2 * v4;
        let v6: f32 = v1 + v5;
        let v7: f32 = q[0];
        let (v10, v8): (f32, f32) = ::armdyn_runtime::libm::sincosf(v7);
        let v9: f32 = v6 * v8;
        let v11: f32 = v2 * v10;
        let v12: f32 = 0.15_f32;
        let v13: f32 = qd[1];
        let v14: f32 = v12 * v13;
        let v15: f32 = 0.3_f32;
        let v16: f32 = qd[0];
        let v17: f32 = v15 * v16;
        let v18: f32 = v14 + v17;
        let v19: f32 = v18 * v13;
        let v20: f32 = v11 + v19;
        let v22: f32 = v20 * v21;
        let v23: f32 = v9 - v22;
        let v24: f32 = v0 - v23;
        let v25: f32 = 12.476606_f32;
        let v26: f32 = 0.08015_f32;
        let v27: f32 = v12 * v4;
        let v28: f32 = v26 + v27;
        let v29: f32 = v25 * v28;
        let v30: f32 = tau[1];
        let v31: f32 = v5 * v8;
        let v32: f32 = v12 * v16;
        let v33: f32 = v32 * v16;
        let v34: f32 = v33 - v11;
        let v35: f32 = v34 * v21;
        let v36: f32 = v31 + v35;
        let v37: f32 = v30 - v36;
        let v38: f32 = v29 * v37;
        let v39: f32 = v24 - v38;
        let v40: f32 = 0.62201667_f32;
        let v41: f32 = v15 * v4;
        let v42: f32 = v40 + v41;
        let v43: f32 = v28 * v29;
        let v44: f32 = v42 - v43;
        let v45: f32 = v39 / v44;
        let v46: f32 = v25 * v37;
        let v47: f32 = v29 * v45;
        let v48: f32 = v46 - v47;
        [v45, v48]
    }
    /// Mass matrix and bias in one pass: row i is `[M_i0, ..., M_i(n-1), c_i + g_i]`, the `M(q)` of `mass_matrix` with the bias `c(q, qd) + g(q)` of `coriolis` and `gravity` as a last column (what Pinocchio's `crba` and `nonLinearEffects` compute together). Common subexpressions, sin/cos included, are computed once for both.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 2]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `mass_matrix_and_bias: [[f32; 3]; 2]` (2 x 3, row-major): rows `[M(q) | c(q, qd) + g(q)]`: the symmetric positive definite M (kg m^2, kg m, kg), then the bias (N m or N)
    ///
    /// Operation count: 21 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn mass_matrix_and_bias(q: &[f32; 2], qd: &[f32; 2]) -> [[f32; 3]; 2] {
        let v0: f32 = 0.62201667_f32;
        let v1: f32 = 0.3_f32;
        let v2: f32 = q[1];
        let (v26, v3): (f32, f32) = ::armdyn_runtime::libm::sincosf(v2);
        let v4: f32 = v1 * v3;
        let v5: f32 = v0 + v4;
        let v6: f32 = 0.08015_f32;
        let v7: f32 = 0.15_f32;
        let v8: f32 = v7 * v3;
        let v9: f32 = v6 + v8;
        let v10: f32 = 12.2625_f32;
        let v11: f32 = 2.943_f32;
        let v12: f32 = v11 * v3;
        let v13: f32 = v10 + v12;
        let v14: f32 = q[0];
        let (v17, v15): (f32, f32) = ::armdyn_runtime::libm::sincosf(v14);
        let v16: f32 = v13 * v15;
        let v18: f32 = v11 * v17;
        let v19: f32 = qd[1];
        let v20: f32 = v7 * v19;
        let v21: f32 = qd[0];
        let v22: f32 = v1 * v21;
        let v23: f32 = v20 + v22;
        let v24: f32 = v23 * v19;
        let v25: f32 = v18 + v24;
        let v27: f32 = v25 * v26;
        let v28: f32 = v16 - v27;
        let v29: f32 = v12 * v15;
        let v30: f32 = v7 * v21;
        let v31: f32 = v30 * v21;
        let v32: f32 = v31 - v18;
        let v33: f32 = v32 * v26;
        let v34: f32 = v29 + v33;
        [[v5, v9, v28], [v9, v6, v34]]
    }
    /// Derivatives of inverse dynamics: row i is `[d tau_i/d q | d tau_i/d qd | d tau_i/d qdd]` (3n entries; the last block is the mass matrix `M(q)`), the partial derivatives of `inverse_dynamics` (what Pinocchio's `computeRNEADerivatives` computes), generated by algorithmic differentiation of its graph and folded like every other function.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 2]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[f32; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `inverse_dynamics_derivatives: [[f32; 6]; 2]` (2 x 6, row-major): rows `[d tau/d q | d tau/d qd | M(q)]`: N m/rad, N m s/rad, kg m^2 (N/m, N s/m, kg for prismatic joints)
    ///
    /// Operation count: 43 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn inverse_dynamics_derivatives(
        q: &[f32; 2],
        qd: &[f32; 2],
        qdd: &[f32; 2],
    ) -> [[f32; 6]; 2] {
        let v0: f32 = 12.2625_f32;
        let v1: f32 = q[0];
        let (v2, v11): (f32, f32) = ::armdyn_runtime::libm::sincosf(v1);
        let v3: f32 = v0 * v2;
        let v4: f32 = q[1];
        let (v10, v5): (f32, f32) = ::armdyn_runtime::libm::sincosf(v4);
        let v6: f32 = 2.943_f32;
        let v7: f32 = v6 * v2;
        let v8: f32 = v5 * v7;
        let v9: f32 = v3 + v8;
        let v12: f32 = v6 * v11;
        let v13: f32 = v10 * v12;
        let v14: f32 = v9 + v13;
        let v15: f32 = -v14;
        let v16: f32 = 0.15_f32;
        let v17: f32 = qdd[1];
        let v18: f32 = v16 * v17;
        let v19: f32 = 0.3_f32;
        let v20: f32 = qdd[0];
        let v21: f32 = v19 * v20;
        let v22: f32 = v18 + v21;
        let v23: f32 = v22 + v12;
        let v24: f32 = v23 * v10;
        let v25: f32 = qd[1];
        let v26: f32 = v16 * v25;
        let v27: f32 = qd[0];
        let v28: f32 = v19 * v27;
        let v29: f32 = v26 + v28;
        let v30: f32 = v29 * v25;
        let v31: f32 = v7 + v30;
        let v32: f32 = v31 * v5;
        let v33: f32 = v24 + v32;
        let v34: f32 = -v33;
        let v35: f32 = v19 * v25;
        let v36: f32 = v10 * v35;
        let v37: f32 = -v36;
        let v38: f32 = v26 + v29;
        let v39: f32 = v10 * v38;
        let v40: f32 = -v39;
        let v41: f32 = 0.62201667_f32;
        let v42: f32 = v19 * v5;
        let v43: f32 = v41 + v42;
        let v44: f32 = 0.08015_f32;
        let v45: f32 = v16 * v5;
        let v46: f32 = v44 + v45;
        let v47: f32 = v8 + v13;
        let v48: f32 = -v47;
        let v49: f32 = v16 * v27;
        let v50: f32 = v49 * v27;
        let v51: f32 = v50 - v7;
        let v52: f32 = v51 * v5;
        let v53: f32 = v16 * v20;
        let v54: f32 = v53 + v12;
        let v55: f32 = v54 * v10;
        let v56: f32 = v52 - v55;
        let v57: f32 = v49 + v49;
        let v58: f32 = v10 * v57;
        let v59: f32 = 0.0_f32;
        [[v15, v34, v37, v40, v43, v46], [v48, v56, v58, v59, v46, v44]]
    }
    /// Derivatives of forward dynamics: row i is `[d qdd_i/d q | d qdd_i/d qd | d qdd_i/d tau]` (3n entries; the last block is `M(q)^-1`), the partial derivatives of `forward_dynamics` (what Pinocchio's `computeABADerivatives` computes): `d qdd/d x = -M^-1 d ID/d x` at `qdd = forward_dynamics(q, qd, tau)` (implicit function theorem on `inverse_dynamics(q, qd, forward_dynamics(q, qd, tau)) = tau`), all 3n right-hand sides solved by one unrolled sparse `L^T D L` factorisation of M. For a tool wrench `f` (`tau - J^T f` into forward dynamics) add `-M^-1 d(J^T f)/d q` to the first block, from `jacobian_derivatives`.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 2]`: joint velocities qd (rad/s or m/s)
    /// - `tau: &[f32; 2]`: joint torques (N m) or forces (N)
    ///
    /// # Output
    ///
    /// `forward_dynamics_derivatives: [[f32; 6]; 2]` (2 x 6, row-major): rows `[d qdd/d q | d qdd/d qd | M(q)^-1]`: 1/s^2, 1/s, 1/(kg m^2) (per m, per kg for prismatic joints)
    ///
    /// Operation count: 85 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn forward_dynamics_derivatives(
        q: &[f32; 2],
        qd: &[f32; 2],
        tau: &[f32; 2],
    ) -> [[f32; 6]; 2] {
        let v0: f32 = 12.2625_f32;
        let v1: f32 = q[0];
        let (v2, v11): (f32, f32) = ::armdyn_runtime::libm::sincosf(v1);
        let v3: f32 = v0 * v2;
        let v4: f32 = q[1];
        let (v10, v5): (f32, f32) = ::armdyn_runtime::libm::sincosf(v4);
        let v6: f32 = 2.943_f32;
        let v7: f32 = v6 * v2;
        let v8: f32 = v5 * v7;
        let v9: f32 = v3 + v8;
        let v12: f32 = v6 * v11;
        let v13: f32 = v10 * v12;
        let v14: f32 = v9 + v13;
        let v15: f32 = 12.476606_f32;
        let v16: f32 = 0.08015_f32;
        let v17: f32 = 0.15_f32;
        let v18: f32 = v17 * v5;
        let v19: f32 = v16 + v18;
        let v20: f32 = v15 * v19;
        let v21: f32 = v8 + v13;
        let v22: f32 = v20 * v21;
        let v23: f32 = v14 - v22;
        let v24: f32 = 0.62201667_f32;
        let v25: f32 = 0.3_f32;
        let v26: f32 = v25 * v5;
        let v27: f32 = v24 + v26;
        let v28: f32 = v19 * v20;
        let v29: f32 = v27 - v28;
        let v30: f32 = v23 / v29;
        let v31: f32 = tau[1];
        let v32: f32 = v6 * v5;
        let v33: f32 = v32 * v11;
        let v34: f32 = qd[0];
        let v35: f32 = v17 * v34;
        let v36: f32 = v35 * v34;
        let v37: f32 = v36 - v7;
        let v38: f32 = v37 * v10;
        let v39: f32 = v33 + v38;
        let v40: f32 = v31 - v39;
        let v41: f32 = v15 * v40;
        let v42: f32 = tau[0];
        let v43: f32 = v0 + v32;
        let v44: f32 = v43 * v11;
        let v45: f32 = qd[1];
        let v46: f32 = v17 * v45;
        let v47: f32 = v25 * v34;
        let v48: f32 = v46 + v47;
        let v49: f32 = v48 * v45;
        let v50: f32 = v7 + v49;
        let v51: f32 = v50 * v10;
        let v52: f32 = v44 - v51;
        let v53: f32 = v42 - v52;
        let v54: f32 = v20 * v40;
        let v55: f32 = v53 - v54;
        let v56: f32 = v55 / v29;
        let v57: f32 = v20 * v56;
        let v58: f32 = v41 - v57;
        let v59: f32 = v17 * v58;
        let v60: f32 = v25 * v56;
        let v61: f32 = v59 + v60;
        let v62: f32 = v61 + v12;
        let v63: f32 = v62 * v10;
        let v64: f32 = v50 * v5;
        let v65: f32 = v63 + v64;
        let v66: f32 = v37 * v5;
        let v67: f32 = v17 * v56;
        let v68: f32 = v67 + v12;
        let v69: f32 = v68 * v10;
        let v70: f32 = v66 - v69;
        let v71: f32 = v20 * v70;
        let v72: f32 = v65 + v71;
        let v73: f32 = v72 / v29;
        let v74: f32 = v25 * v45;
        let v75: f32 = v10 * v74;
        let v76: f32 = v35 + v35;
        let v77: f32 = v10 * v76;
        let v78: f32 = v20 * v77;
        let v79: f32 = v75 + v78;
        let v80: f32 = v79 / v29;
        let v81: f32 = v46 + v48;
        let v82: f32 = v10 * v81;
        let v83: f32 = v82 / v29;
        let v84: f32 = 1.0_f32 / v29;
        let v85: f32 = v20 / v29;
        let v86: f32 = -v85;
        let v87: f32 = v15 * v21;
        let v88: f32 = v20 * v30;
        let v89: f32 = v87 - v88;
        let v90: f32 = v15 * v70;
        let v91: f32 = v20 * v73;
        let v92: f32 = v90 + v91;
        let v93: f32 = -v92;
        let v94: f32 = v15 * v77;
        let v95: f32 = v20 * v80;
        let v96: f32 = v94 + v95;
        let v97: f32 = -v96;
        let v98: f32 = v20 * v83;
        let v99: f32 = -v98;
        let v100: f32 = v20 * v85;
        let v101: f32 = v15 + v100;
        [[v30, v73, v80, v83, v84, v86], [v89, v93, v97, v99, v86, v101]]
    }
    /// Dynamic regressor: `inverse_dynamics(q, qd, qdd) = Y(q, qd, qdd) * standard_parameters()`.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 2]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[f32; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `regressor: [[f32; 20]; 2]` (2 x 20, row-major): Y(q, qd, qdd), columns in the order of `standard_parameters`
    ///
    /// Operation count: 47 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn regressor(q: &[f32; 2], qd: &[f32; 2], qdd: &[f32; 2]) -> [[f32; 20]; 2] {
        let v0: f32 = 0.5_f32;
        let v1: f32 = 9.81_f32;
        let v2: f32 = q[0];
        let (v14, v3): (f32, f32) = ::armdyn_runtime::libm::sincosf(v2);
        let v4: f32 = v1 * v3;
        let v5: f32 = qdd[0];
        let v6: f32 = v0 * v5;
        let v7: f32 = v4 + v6;
        let v8: f32 = v0 * v7;
        let v9: f32 = v6 + v7;
        let v10: f32 = qd[0];
        let v11: f32 = -0.5_f32;
        let v12: f32 = v11 * v10;
        let v13: f32 = v10 * v12;
        let v15: f32 = v1 * v14;
        let v16: f32 = v0 * v10;
        let v17: f32 = v10 * v16;
        let v18: f32 = v15 - v17;
        let v19: f32 = v13 - v18;
        let v20: f32 = q[1];
        let (v23, v21): (f32, f32) = ::armdyn_runtime::libm::sincosf(v20);
        let v22: f32 = v21 * v18;
        let v24: f32 = v23 * v7;
        let v25: f32 = v22 + v24;
        let v26: f32 = qd[1];
        let v27: f32 = v10 + v26;
        let v28: f32 = 0.4_f32;
        let v29: f32 = v28 * v27;
        let v30: f32 = v27 * v29;
        let v31: f32 = v25 - v30;
        let v32: f32 = v0 * v23;
        let v33: f32 = v31 * v32;
        let v34: f32 = v21 * v7;
        let v35: f32 = v23 * v18;
        let v36: f32 = v34 - v35;
        let v37: f32 = qdd[1];
        let v38: f32 = v5 + v37;
        let v39: f32 = v28 * v38;
        let v40: f32 = v36 + v39;
        let v41: f32 = v0 * v21;
        let v42: f32 = v41 + v28;
        let v43: f32 = v40 * v42;
        let v44: f32 = v33 + v43;
        let v45: f32 = v38 * v42;
        let v46: f32 = v27 * v32;
        let v47: f32 = v27 * v46;
        let v48: f32 = v45 - v47;
        let v49: f32 = v48 + v40;
        let v50: f32 = v38 * v32;
        let v51: f32 = v27 * v42;
        let v52: f32 = v27 * v51;
        let v53: f32 = v50 + v52;
        let v54: f32 = v53 + v31;
        let v55: f32 = -v54;
        let v56: f32 = v28 * v40;
        let v57: f32 = v39 + v40;
        let v58: f32 = -0.4_f32;
        let v59: f32 = v58 * v27;
        let v60: f32 = v27 * v59;
        let v61: f32 = v60 - v31;
        let v62: f32 = 0.0_f32;
        [
            [
                v8,
                v9,
                v19,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v5,
                v44,
                v49,
                v55,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v38,
            ],
            [
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v56,
                v57,
                v61,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v38,
            ],
        ]
    }
    /// The robot's own standard inertial parameters, the `params` of the parametric model.
    ///
    /// # Inputs
    ///
    /// None.
    ///
    /// # Output
    ///
    /// `params: [f32; 20]`: per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2, inertia about the link frame origin)
    ///
    /// Operation count: 0 floating-point operations, 0 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn standard_parameters() -> [f32; 20] {
        let v0: f32 = 2.0_f32;
        let v1: f32 = -0.5_f32;
        let v2: f32 = 0.0_f32;
        let v3: f32 = 0.0004_f32;
        let v4: f32 = 0.16686666_f32;
        let v5: f32 = 1.5_f32;
        let v6: f32 = -0.3_f32;
        let v7: f32 = 0.0003_f32;
        let v8: f32 = 0.08015_f32;
        [v0, v1, v2, v2, v3, v2, v2, v4, v2, v4, v5, v6, v2, v2, v7, v2, v2, v8, v2, v8]
    }
}
/// The same functions over several states at once, generic over the lane type
/// `L: ::armdyn_runtime::lanes::Lane` (`wide::f64x2`, `wide::f64x4`, or `f64`): input `i`
/// of state `k` is lane `k` of `input[i]`, and so is each output element. The
/// same instructions in the same order as the `f64` functions, each constant in
/// every lane (`L::splat`); the arithmetic is IEEE `f64` lane by lane, the trig
/// the trait's (`libm`'s for `f64`: bit for bit the scalar functions; `wide`'s
/// vectorised `sin_cos` and `atan2` for the SIMD types, a few ulp from `libm`'s).
/// For sweeps, planners and batches: several states per call keep the SIMD units
/// busy. Same units as the parent module's.
pub mod lanes {
    /// Poses of every link frame (the description's DH frames, or its URDF links), products of the joint transforms `A_1 ... A_i` (thesis eq. 3.2-3.7).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `poses: [[[L; 4]; 4]; 2]` (2 x 4 x 4, row-major): homogeneous transforms T_0i of the description's frames 1..n in the base frame (m)
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
    pub fn frame_poses<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 2],
    ) -> [[[L; 4]; 4]; 2] {
        let v0: L = q[0];
        let (v2, v1): (L, L) = L::sincos(v0);
        let v3: L = -v2;
        let v4: L = L::splat(0.0_f64);
        let v5: L = L::splat(0.5_f64);
        let v6: L = v5 * v1;
        let v7: L = v5 * v2;
        let v8: L = L::splat(1.0_f64);
        let v9: L = q[1];
        let (v12, v10): (L, L) = L::sincos(v9);
        let v11: L = v10 * v1;
        let v13: L = v12 * v2;
        let v14: L = v11 - v13;
        let v15: L = v12 * v1;
        let v16: L = v10 * v2;
        let v17: L = v15 + v16;
        let v18: L = -v17;
        let v19: L = L::splat(0.4_f64);
        let v20: L = v19 * v10;
        let v21: L = v5 + v20;
        let v22: L = v21 * v1;
        let v23: L = v19 * v12;
        let v24: L = v23 * v2;
        let v25: L = v22 - v24;
        let v26: L = v23 * v1;
        let v27: L = v21 * v2;
        let v28: L = v26 + v27;
        [
            [[v1, v3, v4, v6], [v2, v1, v4, v7], [v4, v4, v8, v4], [v4, v4, v4, v8]],
            [
                [v14, v18, v4, v25],
                [v17, v14, v4, v28],
                [v4, v4, v8, v4],
                [v4, v4, v4, v8],
            ],
        ]
    }
    /// End-effector pose, forward kinematics `T_0n` (thesis eq. 3.7).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `pose: [[L; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the base frame (m)
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
    pub fn end_effector_pose<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 2],
    ) -> [[L; 4]; 4] {
        let v0: L = q[1];
        let (v5, v1): (L, L) = L::sincos(v0);
        let v2: L = q[0];
        let (v6, v3): (L, L) = L::sincos(v2);
        let v4: L = v1 * v3;
        let v7: L = v5 * v6;
        let v8: L = v4 - v7;
        let v9: L = v5 * v3;
        let v10: L = v1 * v6;
        let v11: L = v9 + v10;
        let v12: L = -v11;
        let v13: L = L::splat(0.0_f64);
        let v14: L = L::splat(0.5_f64);
        let v15: L = L::splat(0.4_f64);
        let v16: L = v15 * v1;
        let v17: L = v14 + v16;
        let v18: L = v17 * v3;
        let v19: L = v15 * v5;
        let v20: L = v19 * v6;
        let v21: L = v18 - v20;
        let v22: L = v19 * v3;
        let v23: L = v17 * v6;
        let v24: L = v22 + v23;
        let v25: L = L::splat(1.0_f64);
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
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian: [[L; 2]; 6]` (6 x 2, row-major): rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame
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
    pub fn jacobian<L: ::armdyn_runtime::lanes::Lane>(q: &[L; 2]) -> [[L; 2]; 6] {
        let v0: L = L::splat(0.5_f64);
        let v1: L = q[0];
        let (v2, v9): (L, L) = L::sincos(v1);
        let v3: L = v0 * v2;
        let v4: L = L::splat(0.4_f64);
        let v5: L = q[1];
        let (v10, v6): (L, L) = L::sincos(v5);
        let v7: L = v4 * v6;
        let v8: L = v2 * v7;
        let v11: L = v4 * v10;
        let v12: L = v9 * v11;
        let v13: L = v8 + v12;
        let v14: L = v3 + v13;
        let v15: L = -v14;
        let v16: L = -v13;
        let v17: L = v0 * v9;
        let v18: L = v9 * v7;
        let v19: L = v2 * v11;
        let v20: L = v18 - v19;
        let v21: L = v17 + v20;
        let v22: L = L::splat(0.0_f64);
        let v23: L = L::splat(1.0_f64);
        [[v15, v16], [v21, v20], [v22, v22], [v22, v22], [v22, v22], [v23, v23]]
    }
    /// Jacobian and tool position in one pass: `[J | p; 0]`, row r is `[J_r0, ..., J_r(n-1), p_r]` with `J` the geometric Jacobian of `jacobian` and `p` the end-effector origin of `end_effector_pose` (rows 0-2; the last column of rows 3-5 is 0), the same operations as those two functions (bit-identical results), with common subexpressions, sin/cos included, computed once for both and the pose's rotation not computed.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian_and_position: [[L; 3]; 6]` (6 x 3, row-major): rows `[J(q) | p(q); 0]`: the geometric Jacobian of `jacobian` (rows vx vy vz per unit joint velocity, then wx wy wz, base frame), then the end-effector origin (m, base frame) in rows 0-2 of the last column, 0 in rows 3-5
    ///
    /// Operation count: 21 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jacobian_and_position<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 2],
    ) -> [[L; 3]; 6] {
        let v0: L = L::splat(0.5_f64);
        let v1: L = q[0];
        let (v2, v9): (L, L) = L::sincos(v1);
        let v3: L = v0 * v2;
        let v4: L = L::splat(0.4_f64);
        let v5: L = q[1];
        let (v10, v6): (L, L) = L::sincos(v5);
        let v7: L = v4 * v6;
        let v8: L = v2 * v7;
        let v11: L = v4 * v10;
        let v12: L = v9 * v11;
        let v13: L = v8 + v12;
        let v14: L = v3 + v13;
        let v15: L = -v14;
        let v16: L = -v13;
        let v17: L = v0 + v7;
        let v18: L = v17 * v9;
        let v19: L = v11 * v2;
        let v20: L = v18 - v19;
        let v21: L = v0 * v9;
        let v22: L = v9 * v7;
        let v23: L = v2 * v11;
        let v24: L = v22 - v23;
        let v25: L = v21 + v24;
        let v26: L = v11 * v9;
        let v27: L = v17 * v2;
        let v28: L = v26 + v27;
        let v29: L = L::splat(0.0_f64);
        let v30: L = L::splat(1.0_f64);
        [
            [v15, v16, v20],
            [v25, v24, v28],
            [v29, v29, v29],
            [v29, v29, v29],
            [v29, v29, v29],
            [v30, v30, v29],
        ]
    }
    /// Acceleration term of the end-effector twist: `d/dt (J qd) = J qdd + Jdot qd`.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 2]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `jdot_qd: [L; 6]`: Jdot(q, qd) qd: m/s^2 (rows 0-2) and rad/s^2 (rows 3-5), base frame
    ///
    /// Operation count: 30 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jdot_qd<L: ::armdyn_runtime::lanes::Lane>(q: &[L; 2], qd: &[L; 2]) -> [L; 6] {
        let v0: L = L::splat(0.4_f64);
        let v1: L = q[1];
        let (v2, v7): (L, L) = L::sincos(v1);
        let v3: L = v0 * v2;
        let v4: L = q[0];
        let (v5, v9): (L, L) = L::sincos(v4);
        let v6: L = v3 * v5;
        let v8: L = v0 * v7;
        let v10: L = v8 * v9;
        let v11: L = v6 - v10;
        let v12: L = qd[1];
        let v13: L = v11 * v12;
        let v14: L = v13 * v12;
        let v15: L = L::splat(0.8_f64);
        let v16: L = v15 * v12;
        let v17: L = qd[0];
        let v18: L = v0 * v17;
        let v19: L = v16 + v18;
        let v20: L = v19 * v2;
        let v21: L = v20 * v5;
        let v22: L = L::splat(0.5_f64);
        let v23: L = v22 * v17;
        let v24: L = v19 * v7;
        let v25: L = v23 + v24;
        let v26: L = v25 * v9;
        let v27: L = v21 - v26;
        let v28: L = v27 * v17;
        let v29: L = v14 + v28;
        let v30: L = v3 * v9;
        let v31: L = v8 * v5;
        let v32: L = v30 + v31;
        let v33: L = v32 * v12;
        let v34: L = v33 * v12;
        let v35: L = v20 * v9;
        let v36: L = v25 * v5;
        let v37: L = v35 + v36;
        let v38: L = v37 * v17;
        let v39: L = v34 + v38;
        let v40: L = -v39;
        let v41: L = L::splat(0.0_f64);
        [v29, v40, v41, v41, v41, v41]
    }
    /// Partial derivatives of the geometric Jacobian, `d J / d q_k` for each joint k: `Jdot = sum_k d J/d q_k qd_k`, and `d (J^T f)/d q_k = (d J/d q_k)^T f` for a tool wrench f.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian_derivatives: [[[L; 2]; 6]; 2]` (2 x 6 x 2, row-major): `[k][r][c] = d J_rc / d q_k`, the partial derivatives of `jacobian` (m/rad or 1/rad per row kind; per m for prismatic joints)
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
    pub fn jacobian_derivatives<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 2],
    ) -> [[[L; 2]; 6]; 2] {
        let v0: L = L::splat(0.4_f64);
        let v1: L = q[1];
        let (v2, v8): (L, L) = L::sincos(v1);
        let v3: L = v0 * v2;
        let v4: L = q[0];
        let (v5, v11): (L, L) = L::sincos(v4);
        let v6: L = v3 * v5;
        let v7: L = -L::splat(0.5_f64);
        let v9: L = v0 * v8;
        let v10: L = v7 - v9;
        let v12: L = v10 * v11;
        let v13: L = v6 + v12;
        let v14: L = v9 * v11;
        let v15: L = v6 - v14;
        let v16: L = v10 * v5;
        let v17: L = v3 * v11;
        let v18: L = v16 - v17;
        let v19: L = v9 * v5;
        let v20: L = v17 + v19;
        let v21: L = -v20;
        let v22: L = L::splat(0.0_f64);
        [
            [[v13, v15], [v18, v21], [v22, v22], [v22, v22], [v22, v22], [v22, v22]],
            [[v15, v15], [v21, v21], [v22, v22], [v22, v22], [v22, v22], [v22, v22]],
        ]
    }
    /// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `mass_matrix: [[L; 2]; 2]` (2 x 2, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
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
    pub fn mass_matrix<L: ::armdyn_runtime::lanes::Lane>(q: &[L; 2]) -> [[L; 2]; 2] {
        let v0: L = L::splat(0.6220166666666667_f64);
        let v1: L = L::splat(0.3_f64);
        let v2: L = q[1];
        let v3: L = L::cos(v2);
        let v4: L = v1 * v3;
        let v5: L = v0 + v4;
        let v6: L = L::splat(0.08015_f64);
        let v7: L = L::splat(0.15_f64);
        let v8: L = v7 * v3;
        let v9: L = v6 + v8;
        [[v5, v9], [v9, v6]]
    }
    /// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 2]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis_matrix: [[L; 2]; 2]` (2 x 2, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
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
    pub fn coriolis_matrix<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 2],
        qd: &[L; 2],
    ) -> [[L; 2]; 2] {
        let v0: L = L::splat(0.15_f64);
        let v1: L = qd[1];
        let v2: L = v0 * v1;
        let v3: L = q[1];
        let v4: L = L::sin(v3);
        let v5: L = v2 * v4;
        let v6: L = -v5;
        let v7: L = qd[0];
        let v8: L = v0 * v7;
        let v9: L = v2 + v8;
        let v10: L = v9 * v4;
        let v11: L = -v10;
        let v12: L = v8 * v4;
        let v13: L = L::splat(0.0_f64);
        [[v6, v11], [v12, v13]]
    }
    /// Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 2]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis: [L; 2]`: c(q, qd) = C(q, qd) qd (N m or N)
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
    pub fn coriolis<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 2],
        qd: &[L; 2],
    ) -> [L; 2] {
        let v0: L = L::splat(0.15_f64);
        let v1: L = qd[1];
        let v2: L = v0 * v1;
        let v3: L = L::splat(0.3_f64);
        let v4: L = qd[0];
        let v5: L = v3 * v4;
        let v6: L = v2 + v5;
        let v7: L = v6 * v1;
        let v8: L = q[1];
        let v9: L = L::sin(v8);
        let v10: L = v7 * v9;
        let v11: L = -v10;
        let v12: L = v0 * v4;
        let v13: L = v12 * v4;
        let v14: L = v13 * v9;
        [v11, v14]
    }
    /// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `gravity: [L; 2]`: g(q), joint torques (N m) or forces (N) that hold the robot still
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
    pub fn gravity<L: ::armdyn_runtime::lanes::Lane>(q: &[L; 2]) -> [L; 2] {
        let v0: L = L::splat(12.2625_f64);
        let v1: L = L::splat(2.943_f64);
        let v2: L = q[1];
        let (v9, v3): (L, L) = L::sincos(v2);
        let v4: L = v1 * v3;
        let v5: L = v0 + v4;
        let v6: L = q[0];
        let (v11, v7): (L, L) = L::sincos(v6);
        let v8: L = v5 * v7;
        let v10: L = v1 * v9;
        let v12: L = v10 * v11;
        let v13: L = v8 - v12;
        let v14: L = v4 * v7;
        let v15: L = v14 - v12;
        [v13, v15]
    }
    /// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 2]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[L; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `tau: [L; 2]`: joint torques (N m) or forces (N), no external wrench
    ///
    /// Operation count: 31 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn inverse_dynamics<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 2],
        qd: &[L; 2],
        qdd: &[L; 2],
    ) -> [L; 2] {
        let v0: L = L::splat(0.08015_f64);
        let v1: L = qdd[1];
        let v2: L = v0 * v1;
        let v3: L = L::splat(0.6220166666666667_f64);
        let v4: L = qdd[0];
        let v5: L = v3 * v4;
        let v6: L = v2 + v5;
        let v7: L = L::splat(12.2625_f64);
        let v8: L = q[0];
        let (v24, v9): (L, L) = L::sincos(v8);
        let v10: L = v7 * v9;
        let v11: L = v6 + v10;
        let v12: L = L::splat(0.15_f64);
        let v13: L = v12 * v1;
        let v14: L = L::splat(0.3_f64);
        let v15: L = v14 * v4;
        let v16: L = v13 + v15;
        let v17: L = L::splat(2.943_f64);
        let v18: L = v17 * v9;
        let v19: L = v16 + v18;
        let v20: L = q[1];
        let (v33, v21): (L, L) = L::sincos(v20);
        let v22: L = v19 * v21;
        let v23: L = v11 + v22;
        let v25: L = v17 * v24;
        let v26: L = qd[1];
        let v27: L = v12 * v26;
        let v28: L = qd[0];
        let v29: L = v14 * v28;
        let v30: L = v27 + v29;
        let v31: L = v30 * v26;
        let v32: L = v25 + v31;
        let v34: L = v32 * v33;
        let v35: L = v23 - v34;
        let v36: L = v0 * v4;
        let v37: L = v2 + v36;
        let v38: L = v12 * v4;
        let v39: L = v38 + v18;
        let v40: L = v39 * v21;
        let v41: L = v37 + v40;
        let v42: L = v12 * v28;
        let v43: L = v42 * v28;
        let v44: L = v43 - v25;
        let v45: L = v44 * v33;
        let v46: L = v41 + v45;
        [v35, v46]
    }
    /// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 2]`: joint velocities qd (rad/s or m/s)
    /// - `tau: &[L; 2]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
    ///
    /// # Output
    ///
    /// `qdd: [L; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// Operation count: 32 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn forward_dynamics<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 2],
        qd: &[L; 2],
        tau: &[L; 2],
    ) -> [L; 2] {
        let v0: L = tau[0];
        let v1: L = L::splat(12.2625_f64);
        let v2: L = L::splat(2.943_f64);
        let v3: L = q[1];
        let (v21, v4): (L, L) = L::sincos(v3);
        let v5: L = v2 * v4;
        let v6: L = v1 + v5;
        let v7: L = q[0];
        let (v10, v8): (L, L) = L::sincos(v7);
        let v9: L = v6 * v8;
        let v11: L = v2 * v10;
        let v12: L = L::splat(0.15_f64);
        let v13: L = qd[1];
        let v14: L = v12 * v13;
        let v15: L = L::splat(0.3_f64);
        let v16: L = qd[0];
        let v17: L = v15 * v16;
        let v18: L = v14 + v17;
        let v19: L = v18 * v13;
        let v20: L = v11 + v19;
        let v22: L = v20 * v21;
        let v23: L = v9 - v22;
        let v24: L = v0 - v23;
        let v25: L = L::splat(12.476606363069246_f64);
        let v26: L = L::splat(0.08015_f64);
        let v27: L = v12 * v4;
        let v28: L = v26 + v27;
        let v29: L = v25 * v28;
        let v30: L = tau[1];
        let v31: L = v5 * v8;
        let v32: L = v12 * v16;
        let v33: L = v32 * v16;
        let v34: L = v33 - v11;
        let v35: L = v34 * v21;
        let v36: L = v31 + v35;
        let v37: L = v30 - v36;
        let v38: L = v29 * v37;
        let v39: L = v24 - v38;
        let v40: L = L::splat(0.6220166666666667_f64);
        let v41: L = v15 * v4;
        let v42: L = v40 + v41;
        let v43: L = v28 * v29;
        let v44: L = v42 - v43;
        let v45: L = v39 / v44;
        let v46: L = v25 * v37;
        let v47: L = v29 * v45;
        let v48: L = v46 - v47;
        [v45, v48]
    }
    /// Mass matrix and bias in one pass: row i is `[M_i0, ..., M_i(n-1), c_i + g_i]`, the `M(q)` of `mass_matrix` with the bias `c(q, qd) + g(q)` of `coriolis` and `gravity` as a last column (what Pinocchio's `crba` and `nonLinearEffects` compute together). Common subexpressions, sin/cos included, are computed once for both.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 2]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `mass_matrix_and_bias: [[L; 3]; 2]` (2 x 3, row-major): rows `[M(q) | c(q, qd) + g(q)]`: the symmetric positive definite M (kg m^2, kg m, kg), then the bias (N m or N)
    ///
    /// Operation count: 21 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn mass_matrix_and_bias<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 2],
        qd: &[L; 2],
    ) -> [[L; 3]; 2] {
        let v0: L = L::splat(0.6220166666666667_f64);
        let v1: L = L::splat(0.3_f64);
        let v2: L = q[1];
        let (v26, v3): (L, L) = L::sincos(v2);
        let v4: L = v1 * v3;
        let v5: L = v0 + v4;
        let v6: L = L::splat(0.08015_f64);
        let v7: L = L::splat(0.15_f64);
        let v8: L = v7 * v3;
        let v9: L = v6 + v8;
        let v10: L = L::splat(12.2625_f64);
        let v11: L = L::splat(2.943_f64);
        let v12: L = v11 * v3;
        let v13: L = v10 + v12;
        let v14: L = q[0];
        let (v17, v15): (L, L) = L::sincos(v14);
        let v16: L = v13 * v15;
        let v18: L = v11 * v17;
        let v19: L = qd[1];
        let v20: L = v7 * v19;
        let v21: L = qd[0];
        let v22: L = v1 * v21;
        let v23: L = v20 + v22;
        let v24: L = v23 * v19;
        let v25: L = v18 + v24;
        let v27: L = v25 * v26;
        let v28: L = v16 - v27;
        let v29: L = v12 * v15;
        let v30: L = v7 * v21;
        let v31: L = v30 * v21;
        let v32: L = v31 - v18;
        let v33: L = v32 * v26;
        let v34: L = v29 + v33;
        [[v5, v9, v28], [v9, v6, v34]]
    }
    /// Derivatives of inverse dynamics: row i is `[d tau_i/d q | d tau_i/d qd | d tau_i/d qdd]` (3n entries; the last block is the mass matrix `M(q)`), the partial derivatives of `inverse_dynamics` (what Pinocchio's `computeRNEADerivatives` computes), generated by algorithmic differentiation of its graph and folded like every other function.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 2]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[L; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `inverse_dynamics_derivatives: [[L; 6]; 2]` (2 x 6, row-major): rows `[d tau/d q | d tau/d qd | M(q)]`: N m/rad, N m s/rad, kg m^2 (N/m, N s/m, kg for prismatic joints)
    ///
    /// Operation count: 43 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn inverse_dynamics_derivatives<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 2],
        qd: &[L; 2],
        qdd: &[L; 2],
    ) -> [[L; 6]; 2] {
        let v0: L = L::splat(12.2625_f64);
        let v1: L = q[0];
        let (v2, v11): (L, L) = L::sincos(v1);
        let v3: L = v0 * v2;
        let v4: L = q[1];
        let (v10, v5): (L, L) = L::sincos(v4);
        let v6: L = L::splat(2.943_f64);
        let v7: L = v6 * v2;
        let v8: L = v5 * v7;
        let v9: L = v3 + v8;
        let v12: L = v6 * v11;
        let v13: L = v10 * v12;
        let v14: L = v9 + v13;
        let v15: L = -v14;
        let v16: L = L::splat(0.15_f64);
        let v17: L = qdd[1];
        let v18: L = v16 * v17;
        let v19: L = L::splat(0.3_f64);
        let v20: L = qdd[0];
        let v21: L = v19 * v20;
        let v22: L = v18 + v21;
        let v23: L = v22 + v12;
        let v24: L = v23 * v10;
        let v25: L = qd[1];
        let v26: L = v16 * v25;
        let v27: L = qd[0];
        let v28: L = v19 * v27;
        let v29: L = v26 + v28;
        let v30: L = v29 * v25;
        let v31: L = v7 + v30;
        let v32: L = v31 * v5;
        let v33: L = v24 + v32;
        let v34: L = -v33;
        let v35: L = v19 * v25;
        let v36: L = v10 * v35;
        let v37: L = -v36;
        let v38: L = v26 + v29;
        let v39: L = v10 * v38;
        let v40: L = -v39;
        let v41: L = L::splat(0.6220166666666667_f64);
        let v42: L = v19 * v5;
        let v43: L = v41 + v42;
        let v44: L = L::splat(0.08015_f64);
        let v45: L = v16 * v5;
        let v46: L = v44 + v45;
        let v47: L = v8 + v13;
        let v48: L = -v47;
        let v49: L = v16 * v27;
        let v50: L = v49 * v27;
        let v51: L = v50 - v7;
        let v52: L = v51 * v5;
        let v53: L = v16 * v20;
        let v54: L = v53 + v12;
        let v55: L = v54 * v10;
        let v56: L = v52 - v55;
        let v57: L = v49 + v49;
        let v58: L = v10 * v57;
        let v59: L = L::splat(0.0_f64);
        [[v15, v34, v37, v40, v43, v46], [v48, v56, v58, v59, v46, v44]]
    }
    /// Derivatives of forward dynamics: row i is `[d qdd_i/d q | d qdd_i/d qd | d qdd_i/d tau]` (3n entries; the last block is `M(q)^-1`), the partial derivatives of `forward_dynamics` (what Pinocchio's `computeABADerivatives` computes): `d qdd/d x = -M^-1 d ID/d x` at `qdd = forward_dynamics(q, qd, tau)` (implicit function theorem on `inverse_dynamics(q, qd, forward_dynamics(q, qd, tau)) = tau`), all 3n right-hand sides solved by one unrolled sparse `L^T D L` factorisation of M. For a tool wrench `f` (`tau - J^T f` into forward dynamics) add `-M^-1 d(J^T f)/d q` to the first block, from `jacobian_derivatives`.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 2]`: joint velocities qd (rad/s or m/s)
    /// - `tau: &[L; 2]`: joint torques (N m) or forces (N)
    ///
    /// # Output
    ///
    /// `forward_dynamics_derivatives: [[L; 6]; 2]` (2 x 6, row-major): rows `[d qdd/d q | d qdd/d qd | M(q)^-1]`: 1/s^2, 1/s, 1/(kg m^2) (per m, per kg for prismatic joints)
    ///
    /// Operation count: 85 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn forward_dynamics_derivatives<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 2],
        qd: &[L; 2],
        tau: &[L; 2],
    ) -> [[L; 6]; 2] {
        let v0: L = L::splat(12.2625_f64);
        let v1: L = q[0];
        let (v2, v11): (L, L) = L::sincos(v1);
        let v3: L = v0 * v2;
        let v4: L = q[1];
        let (v10, v5): (L, L) = L::sincos(v4);
        let v6: L = L::splat(2.943_f64);
        let v7: L = v6 * v2;
        let v8: L = v5 * v7;
        let v9: L = v3 + v8;
        let v12: L = v6 * v11;
        let v13: L = v10 * v12;
        let v14: L = v9 + v13;
        let v15: L = L::splat(12.476606363069246_f64);
        let v16: L = L::splat(0.08015_f64);
        let v17: L = L::splat(0.15_f64);
        let v18: L = v17 * v5;
        let v19: L = v16 + v18;
        let v20: L = v15 * v19;
        let v21: L = v8 + v13;
        let v22: L = v20 * v21;
        let v23: L = v14 - v22;
        let v24: L = L::splat(0.6220166666666667_f64);
        let v25: L = L::splat(0.3_f64);
        let v26: L = v25 * v5;
        let v27: L = v24 + v26;
        let v28: L = v19 * v20;
        let v29: L = v27 - v28;
        let v30: L = v23 / v29;
        let v31: L = tau[1];
        let v32: L = v6 * v5;
        let v33: L = v32 * v11;
        let v34: L = qd[0];
        let v35: L = v17 * v34;
        let v36: L = v35 * v34;
        let v37: L = v36 - v7;
        let v38: L = v37 * v10;
        let v39: L = v33 + v38;
        let v40: L = v31 - v39;
        let v41: L = v15 * v40;
        let v42: L = tau[0];
        let v43: L = v0 + v32;
        let v44: L = v43 * v11;
        let v45: L = qd[1];
        let v46: L = v17 * v45;
        let v47: L = v25 * v34;
        let v48: L = v46 + v47;
        let v49: L = v48 * v45;
        let v50: L = v7 + v49;
        let v51: L = v50 * v10;
        let v52: L = v44 - v51;
        let v53: L = v42 - v52;
        let v54: L = v20 * v40;
        let v55: L = v53 - v54;
        let v56: L = v55 / v29;
        let v57: L = v20 * v56;
        let v58: L = v41 - v57;
        let v59: L = v17 * v58;
        let v60: L = v25 * v56;
        let v61: L = v59 + v60;
        let v62: L = v61 + v12;
        let v63: L = v62 * v10;
        let v64: L = v50 * v5;
        let v65: L = v63 + v64;
        let v66: L = v37 * v5;
        let v67: L = v17 * v56;
        let v68: L = v67 + v12;
        let v69: L = v68 * v10;
        let v70: L = v66 - v69;
        let v71: L = v20 * v70;
        let v72: L = v65 + v71;
        let v73: L = v72 / v29;
        let v74: L = v25 * v45;
        let v75: L = v10 * v74;
        let v76: L = v35 + v35;
        let v77: L = v10 * v76;
        let v78: L = v20 * v77;
        let v79: L = v75 + v78;
        let v80: L = v79 / v29;
        let v81: L = v46 + v48;
        let v82: L = v10 * v81;
        let v83: L = v82 / v29;
        let v84: L = L::splat(1.0_f64) / v29;
        let v85: L = v20 / v29;
        let v86: L = -v85;
        let v87: L = v15 * v21;
        let v88: L = v20 * v30;
        let v89: L = v87 - v88;
        let v90: L = v15 * v70;
        let v91: L = v20 * v73;
        let v92: L = v90 + v91;
        let v93: L = -v92;
        let v94: L = v15 * v77;
        let v95: L = v20 * v80;
        let v96: L = v94 + v95;
        let v97: L = -v96;
        let v98: L = v20 * v83;
        let v99: L = -v98;
        let v100: L = v20 * v85;
        let v101: L = v15 + v100;
        [[v30, v73, v80, v83, v84, v86], [v89, v93, v97, v99, v86, v101]]
    }
    /// Dynamic regressor: `inverse_dynamics(q, qd, qdd) = Y(q, qd, qdd) * standard_parameters()`.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 2]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[L; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `regressor: [[L; 20]; 2]` (2 x 20, row-major): Y(q, qd, qdd), columns in the order of `standard_parameters`
    ///
    /// Operation count: 47 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn regressor<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 2],
        qd: &[L; 2],
        qdd: &[L; 2],
    ) -> [[L; 20]; 2] {
        let v0: L = L::splat(0.5_f64);
        let v1: L = L::splat(9.81_f64);
        let v2: L = q[0];
        let (v14, v3): (L, L) = L::sincos(v2);
        let v4: L = v1 * v3;
        let v5: L = qdd[0];
        let v6: L = v0 * v5;
        let v7: L = v4 + v6;
        let v8: L = v0 * v7;
        let v9: L = v6 + v7;
        let v10: L = qd[0];
        let v11: L = -L::splat(0.5_f64);
        let v12: L = v11 * v10;
        let v13: L = v10 * v12;
        let v15: L = v1 * v14;
        let v16: L = v0 * v10;
        let v17: L = v10 * v16;
        let v18: L = v15 - v17;
        let v19: L = v13 - v18;
        let v20: L = q[1];
        let (v23, v21): (L, L) = L::sincos(v20);
        let v22: L = v21 * v18;
        let v24: L = v23 * v7;
        let v25: L = v22 + v24;
        let v26: L = qd[1];
        let v27: L = v10 + v26;
        let v28: L = L::splat(0.4_f64);
        let v29: L = v28 * v27;
        let v30: L = v27 * v29;
        let v31: L = v25 - v30;
        let v32: L = v0 * v23;
        let v33: L = v31 * v32;
        let v34: L = v21 * v7;
        let v35: L = v23 * v18;
        let v36: L = v34 - v35;
        let v37: L = qdd[1];
        let v38: L = v5 + v37;
        let v39: L = v28 * v38;
        let v40: L = v36 + v39;
        let v41: L = v0 * v21;
        let v42: L = v41 + v28;
        let v43: L = v40 * v42;
        let v44: L = v33 + v43;
        let v45: L = v38 * v42;
        let v46: L = v27 * v32;
        let v47: L = v27 * v46;
        let v48: L = v45 - v47;
        let v49: L = v48 + v40;
        let v50: L = v38 * v32;
        let v51: L = v27 * v42;
        let v52: L = v27 * v51;
        let v53: L = v50 + v52;
        let v54: L = v53 + v31;
        let v55: L = -v54;
        let v56: L = v28 * v40;
        let v57: L = v39 + v40;
        let v58: L = -L::splat(0.4_f64);
        let v59: L = v58 * v27;
        let v60: L = v27 * v59;
        let v61: L = v60 - v31;
        let v62: L = L::splat(0.0_f64);
        [
            [
                v8,
                v9,
                v19,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v5,
                v44,
                v49,
                v55,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v38,
            ],
            [
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v56,
                v57,
                v61,
                v62,
                v62,
                v62,
                v62,
                v62,
                v62,
                v38,
            ],
        ]
    }
    /// The robot's own standard inertial parameters, the `params` of the parametric model.
    ///
    /// # Inputs
    ///
    /// None.
    ///
    /// # Output
    ///
    /// `params: [L; 20]`: per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2, inertia about the link frame origin)
    ///
    /// Operation count: 0 floating-point operations, 0 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn standard_parameters<L: ::armdyn_runtime::lanes::Lane>() -> [L; 20] {
        let v0: L = L::splat(2.0_f64);
        let v1: L = -L::splat(0.5_f64);
        let v2: L = L::splat(0.0_f64);
        let v3: L = L::splat(0.0004_f64);
        let v4: L = L::splat(0.16686666666666666_f64);
        let v5: L = L::splat(1.5_f64);
        let v6: L = -L::splat(0.3_f64);
        let v7: L = L::splat(0.0003_f64);
        let v8: L = L::splat(0.08015_f64);
        [v0, v1, v2, v2, v3, v2, v2, v4, v2, v4, v5, v6, v2, v2, v7, v2, v2, v8, v2, v8]
    }
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/planar2.json")
);
