// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `scara_derive::robot_model!("models/scara.json")` in the `generated` crate,
// formatted with prettyplease. Not compiled: for reading and review.

/// Name of the robot (`robot.name` in the model file).
pub const ROBOT_NAME: &str = "scara";
/// Description of the robot, from the model file.
pub const DESCRIPTION: &str = "4-DOF SCARA (RRPR) of the hybrid force/position thesis, Table 3.1";
/// Degrees of freedom: the number of joints.
pub const DOF: usize = 4;
/// Name and version of the generator that wrote the model file.
pub const GENERATOR: &str = "scara-codegen 0.1.0";
/// Version of CasADi the generator used.
pub const CASADI_VERSION: &str = "3.7.2";
/// Robot description file the model was generated from.
pub const SOURCE: &str = "robots/scara.toml";
/// SHA-256 of the robot description file (64 hex digits).
pub const SOURCE_SHA256: &str = "fc1e74336735d1d18c912982a97d98b6ed8071707a81d71f850d321caa779198";
/// Joint names, base to tip.
pub const JOINT_NAMES: [&str; DOF] = ["q1", "q2", "d3", "q4"];
/// `true` for a prismatic joint (m, N), `false` for a revolute one (rad, N m).
pub const JOINT_IS_PRISMATIC: [bool; DOF] = [false, false, true, false];
/// Joint position limits `[lower, upper]`, rad or m.
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const JOINT_LIMITS: [[f64; 2]; DOF] = [
    [-1.5707963267948966_f64, 1.5707963267948966_f64],
    [-2.748893571891069_f64, 2.748893571891069_f64],
    [0.1_f64, 0.35_f64],
    [-3.141592653589793_f64, 3.141592653589793_f64],
];
/// Actuator effort limits, N m (revolute) or N (prismatic).
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const EFFORT_LIMITS: [f64; DOF] = [1000.0_f64, 1000.0_f64, 1000.0_f64, 1000.0_f64];
/// Gravity vector in the base frame, m/s^2.
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const GRAVITY: [f64; 3] = [0.0_f64, 0.0_f64, -9.8_f64];
/// `(function, flops, trig)` for every function, in file order: floating-point
/// operations (add, sub, mul, div, neg, sq, twice, inv, sqrt, fabs) and trig calls
/// (sin, cos, atan2) in its body.
pub const OPERATION_COUNTS: [(&str, u32, u32); 7] = [
    ("frame_poses", 35, 6),
    ("end_effector_pose", 25, 6),
    ("jacobian", 14, 4),
    ("mass_matrix", 4, 1),
    ("coriolis_matrix", 8, 1),
    ("coriolis", 9, 1),
    ("gravity", 0, 0),
];
/// Poses of every DH frame, `A_1 A_2 ... A_i` with `A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)` (thesis eq. 3.2-3.7).
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `poses: [[[f64; 4]; 4]; 4]` (4 x 4 x 4, row-major): homogeneous transforms T_0i of DH frames 1..n in the base frame (m)
///
/// Operation count: 35 floating-point operations, 6 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn frame_poses(q: &[f64; 4]) -> [[[f64; 4]; 4]; 4] {
    let v0: f64 = q[0];
    let v1: f64 = ::libm::cos(v0);
    let v2: f64 = ::libm::sin(v0);
    let v3: f64 = -v2;
    let v4: f64 = 0.0_f64;
    let v5: f64 = 0.4_f64;
    let v6: f64 = v5 * v1;
    let v7: f64 = v5 * v2;
    let v8: f64 = 1.0_f64;
    let v9: f64 = 0.5_f64;
    let v10: f64 = q[1];
    let v11: f64 = ::libm::cos(v10);
    let v12: f64 = v1 * v11;
    let v13: f64 = ::libm::sin(v10);
    let v14: f64 = v2 * v13;
    let v15: f64 = v12 - v14;
    let v16: f64 = v1 * v13;
    let v17: f64 = v2 * v11;
    let v18: f64 = v16 + v17;
    let v19: f64 = v5 * v11;
    let v20: f64 = v1 * v19;
    let v21: f64 = v5 * v13;
    let v22: f64 = v2 * v21;
    let v23: f64 = v20 - v22;
    let v24: f64 = v6 + v23;
    let v25: f64 = v17 + v16;
    let v26: f64 = v14 - v12;
    let v27: f64 = v2 * v19;
    let v28: f64 = v1 * v21;
    let v29: f64 = v27 + v28;
    let v30: f64 = v7 + v29;
    let v31: f64 = -1.0_f64;
    let v32: f64 = q[2];
    let v33: f64 = v9 - v32;
    let v34: f64 = q[3];
    let v35: f64 = ::libm::cos(v34);
    let v36: f64 = v15 * v35;
    let v37: f64 = ::libm::sin(v34);
    let v38: f64 = v18 * v37;
    let v39: f64 = v36 + v38;
    let v40: f64 = v18 * v35;
    let v41: f64 = v15 * v37;
    let v42: f64 = v40 - v41;
    let v43: f64 = v25 * v35;
    let v44: f64 = v26 * v37;
    let v45: f64 = v43 + v44;
    let v46: f64 = v26 * v35;
    let v47: f64 = v25 * v37;
    let v48: f64 = v46 - v47;
    let v49: f64 = -0.15_f64;
    let v50: f64 = v33 + v49;
    [
        [[v1, v3, v4, v6], [v2, v1, v4, v7], [v4, v4, v8, v9], [v4, v4, v4, v8]],
        [[v15, v18, v4, v24], [v25, v26, v4, v30], [v4, v4, v31, v9], [v4, v4, v4, v8]],
        [[v15, v18, v4, v24], [v25, v26, v4, v30], [v4, v4, v31, v33], [v4, v4, v4, v8]],
        [[v39, v42, v4, v24], [v45, v48, v4, v30], [v4, v4, v31, v50], [v4, v4, v4, v8]],
    ]
}
/// End-effector pose, forward kinematics `T_0n` (thesis eq. 3.7).
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `pose: [[f64; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n) in the base frame (m)
///
/// Operation count: 25 floating-point operations, 6 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn end_effector_pose(q: &[f64; 4]) -> [[f64; 4]; 4] {
    let v0: f64 = q[3];
    let v1: f64 = ::libm::cos(v0);
    let v2: f64 = q[1];
    let v3: f64 = ::libm::cos(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = ::libm::sin(v0);
    let v6: f64 = ::libm::sin(v2);
    let v7: f64 = v5 * v6;
    let v8: f64 = v4 + v7;
    let v9: f64 = q[0];
    let v10: f64 = ::libm::cos(v9);
    let v11: f64 = v8 * v10;
    let v12: f64 = v5 * v3;
    let v13: f64 = v1 * v6;
    let v14: f64 = v12 - v13;
    let v15: f64 = ::libm::sin(v9);
    let v16: f64 = v14 * v15;
    let v17: f64 = v11 + v16;
    let v18: f64 = v13 - v12;
    let v19: f64 = v18 * v10;
    let v20: f64 = v8 * v15;
    let v21: f64 = v19 + v20;
    let v22: f64 = 0.0_f64;
    let v23: f64 = 0.4_f64;
    let v24: f64 = v23 * v3;
    let v25: f64 = v23 + v24;
    let v26: f64 = v25 * v10;
    let v27: f64 = v23 * v6;
    let v28: f64 = v27 * v15;
    let v29: f64 = v26 - v28;
    let v30: f64 = v18 * v15;
    let v31: f64 = v30 - v11;
    let v32: f64 = v27 * v10;
    let v33: f64 = v25 * v15;
    let v34: f64 = v32 + v33;
    let v35: f64 = -1.0_f64;
    let v36: f64 = 0.35_f64;
    let v37: f64 = q[2];
    let v38: f64 = v36 - v37;
    let v39: f64 = 1.0_f64;
    [
        [v17, v21, v22, v29],
        [v21, v31, v22, v34],
        [v22, v22, v35, v38],
        [v22, v22, v22, v39],
    ]
}
/// Geometric Jacobian of the end-effector frame origin in the base frame (thesis eq. 3.29).
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `jacobian: [[f64; 4]; 6]` (6 x 4, row-major): rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame
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
pub fn jacobian(q: &[f64; 4]) -> [[f64; 4]; 6] {
    let v0: f64 = 0.4_f64;
    let v1: f64 = q[0];
    let v2: f64 = ::libm::sin(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = q[1];
    let v5: f64 = ::libm::cos(v4);
    let v6: f64 = v0 * v5;
    let v7: f64 = v2 * v6;
    let v8: f64 = ::libm::cos(v1);
    let v9: f64 = ::libm::sin(v4);
    let v10: f64 = v0 * v9;
    let v11: f64 = v8 * v10;
    let v12: f64 = v7 + v11;
    let v13: f64 = v3 + v12;
    let v14: f64 = -v13;
    let v15: f64 = -v12;
    let v16: f64 = 0.0_f64;
    let v17: f64 = v0 * v8;
    let v18: f64 = v8 * v6;
    let v19: f64 = v2 * v10;
    let v20: f64 = v18 - v19;
    let v21: f64 = v17 + v20;
    let v22: f64 = -1.0_f64;
    let v23: f64 = 1.0_f64;
    [
        [v14, v15, v16, v16],
        [v21, v20, v16, v16],
        [v16, v16, v22, v16],
        [v16, v16, v16, v16],
        [v16, v16, v16, v16],
        [v23, v23, v16, v22],
    ]
}
/// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `mass_matrix: [[f64; 4]; 4]` (4 x 4, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
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
pub fn mass_matrix(q: &[f64; 4]) -> [[f64; 4]; 4] {
    let v0: f64 = 3.22955337_f64;
    let v1: f64 = 2.336896_f64;
    let v2: f64 = q[1];
    let v3: f64 = ::libm::cos(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = v0 + v4;
    let v6: f64 = 1.12144112_f64;
    let v7: f64 = 1.168448_f64;
    let v8: f64 = v7 * v3;
    let v9: f64 = v6 + v8;
    let v10: f64 = 0.0_f64;
    let v11: f64 = -0.0025_f64;
    let v12: f64 = 4.94_f64;
    let v13: f64 = 0.0025_f64;
    [[v5, v9, v10, v11], [v9, v6, v10, v11], [v10, v10, v12, v10], [v11, v11, v10, v13]]
}
/// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
///
/// # Output
///
/// `coriolis_matrix: [[f64; 4]; 4]` (4 x 4, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
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
pub fn coriolis_matrix(q: &[f64; 4], qd: &[f64; 4]) -> [[f64; 4]; 4] {
    let v0: f64 = 1.168448_f64;
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
    let v12: f64 = 0.0_f64;
    let v13: f64 = v8 * v4;
    [
        [v6, v11, v12, v12],
        [v13, v12, v12, v12],
        [v12, v12, v12, v12],
        [v12, v12, v12, v12],
    ]
}
/// Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53).
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
///
/// # Output
///
/// `coriolis: [f64; 4]`: c(q, qd) = C(q, qd) qd (N m or N)
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
pub fn coriolis(q: &[f64; 4], qd: &[f64; 4]) -> [f64; 4] {
    let v0: f64 = 1.168448_f64;
    let v1: f64 = qd[1];
    let v2: f64 = v0 * v1;
    let v3: f64 = 2.336896_f64;
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
    let v15: f64 = 0.0_f64;
    [v11, v14, v15, v15]
}
/// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `gravity: [f64; 4]`: g(q), joint torques (N m) or forces (N) that hold the robot still
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
pub fn gravity(q: &[f64; 4]) -> [f64; 4] {
    let v0: f64 = 0.0_f64;
    let v1: f64 = -48.412_f64;
    [v0, v0, v1, v0]
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/scara.json")
);
