// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `armdyn_derive::robot_model!("models/scara.json", f32, lanes)` in the `generated` crate,
// formatted with prettyplease. Not compiled: for reading and review.

/// Name of the robot (`robot.name` in the model file).
pub const ROBOT_NAME: &str = "scara";
/// Description of the robot, from the model file.
pub const DESCRIPTION: &str = "4-DOF SCARA (RRPR) of the hybrid force/position thesis, Table 3.1";
/// Degrees of freedom: the number of joints.
pub const DOF: usize = 4;
/// Name and version of the generator that wrote the model file.
pub const GENERATOR: &str = "armdyn-codegen 0.1.0";
/// Version of CasADi the generator used.
pub const CASADI_VERSION: &str = "3.7.2";
/// Robot description file the model was generated from.
pub const SOURCE: &str = "robots/scara.toml";
/// SHA-256 of the robot description file (64 hex digits).
pub const SOURCE_SHA256: &str = "79ae59464cf07c74de94db66a5081057af6eadadd868872a64e8623e0f9fbaef";
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
/// The task: the rows of the geometric Jacobian (`vx vy vz wx wy wz`) its end
/// effector is controlled in (the description's `task`).
pub const TASK_ROWS: [usize; 4] = [0, 1, 2, 5];
/// `(function, flops, trig)` for every function, in file order: floating-point
/// operations (add, sub, mul, div, neg, sq, twice, inv, sqrt, fabs) and trig calls
/// (sin, cos, atan2) in its body.
pub const OPERATION_COUNTS: [(&str, u32, u32); 17] = [
    ("frame_poses", 35, 6),
    ("end_effector_pose", 25, 6),
    ("jacobian", 14, 4),
    ("jacobian_and_position", 22, 4),
    ("jdot_qd", 29, 4),
    ("jacobian_derivatives", 14, 4),
    ("mass_matrix", 4, 1),
    ("coriolis_matrix", 8, 1),
    ("coriolis", 9, 1),
    ("gravity", 0, 0),
    ("inverse_dynamics", 30, 2),
    ("forward_dynamics", 32, 2),
    ("mass_matrix_and_bias", 13, 2),
    ("inverse_dynamics_derivatives", 29, 2),
    ("forward_dynamics_derivatives", 76, 2),
    ("regressor", 85, 4),
    ("standard_parameters", 0, 0),
];
/// Poses of every link frame (the description's DH frames, or its URDF links), products of the joint transforms `A_1 ... A_i` (thesis eq. 3.2-3.7).
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `poses: [[[f64; 4]; 4]; 4]` (4 x 4 x 4, row-major): homogeneous transforms T_0i of the description's frames 1..n in the base frame (m)
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
    let (v2, v1): (f64, f64) = ::armdyn_runtime::libm::sincos(v0);
    let v3: f64 = -v2;
    let v4: f64 = 0.0_f64;
    let v5: f64 = 0.4_f64;
    let v6: f64 = v5 * v1;
    let v7: f64 = v5 * v2;
    let v8: f64 = 1.0_f64;
    let v9: f64 = 0.5_f64;
    let v10: f64 = q[1];
    let (v13, v11): (f64, f64) = ::armdyn_runtime::libm::sincos(v10);
    let v12: f64 = v1 * v11;
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
    let (v37, v35): (f64, f64) = ::armdyn_runtime::libm::sincos(v34);
    let v36: f64 = v15 * v35;
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
/// `pose: [[f64; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the base frame (m)
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
    let (v5, v1): (f64, f64) = ::armdyn_runtime::libm::sincos(v0);
    let v2: f64 = q[1];
    let (v6, v3): (f64, f64) = ::armdyn_runtime::libm::sincos(v2);
    let v4: f64 = v1 * v3;
    let v7: f64 = v5 * v6;
    let v8: f64 = v4 + v7;
    let v9: f64 = q[0];
    let (v15, v10): (f64, f64) = ::armdyn_runtime::libm::sincos(v9);
    let v11: f64 = v8 * v10;
    let v12: f64 = v5 * v3;
    let v13: f64 = v1 * v6;
    let v14: f64 = v12 - v13;
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
    let (v2, v8): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = q[1];
    let (v9, v5): (f64, f64) = ::armdyn_runtime::libm::sincos(v4);
    let v6: f64 = v0 * v5;
    let v7: f64 = v2 * v6;
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
/// Jacobian and tool position in one pass: `[J | p; 0]`, row r is `[J_r0, ..., J_r(n-1), p_r]` with `J` the geometric Jacobian of `jacobian` and `p` the end-effector origin of `end_effector_pose` (rows 0-2; the last column of rows 3-5 is 0), the same operations as those two functions (bit-identical results), with common subexpressions, sin/cos included, computed once for both and the pose's rotation not computed.
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `jacobian_and_position: [[f64; 5]; 6]` (6 x 5, row-major): rows `[J(q) | p(q); 0]`: the geometric Jacobian of `jacobian` (rows vx vy vz per unit joint velocity, then wx wy wz, base frame), then the end-effector origin (m, base frame) in rows 0-2 of the last column, 0 in rows 3-5
///
/// Operation count: 22 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn jacobian_and_position(q: &[f64; 4]) -> [[f64; 5]; 6] {
    let v0: f64 = 0.4_f64;
    let v1: f64 = q[0];
    let (v2, v8): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = q[1];
    let (v9, v5): (f64, f64) = ::armdyn_runtime::libm::sincos(v4);
    let v6: f64 = v0 * v5;
    let v7: f64 = v2 * v6;
    let v10: f64 = v0 * v9;
    let v11: f64 = v8 * v10;
    let v12: f64 = v7 + v11;
    let v13: f64 = v3 + v12;
    let v14: f64 = -v13;
    let v15: f64 = -v12;
    let v16: f64 = 0.0_f64;
    let v17: f64 = v0 + v6;
    let v18: f64 = v17 * v8;
    let v19: f64 = v10 * v2;
    let v20: f64 = v18 - v19;
    let v21: f64 = v0 * v8;
    let v22: f64 = v8 * v6;
    let v23: f64 = v2 * v10;
    let v24: f64 = v22 - v23;
    let v25: f64 = v21 + v24;
    let v26: f64 = v10 * v8;
    let v27: f64 = v17 * v2;
    let v28: f64 = v26 + v27;
    let v29: f64 = -1.0_f64;
    let v30: f64 = 0.35_f64;
    let v31: f64 = q[2];
    let v32: f64 = v30 - v31;
    let v33: f64 = 1.0_f64;
    [
        [v14, v15, v16, v16, v20],
        [v25, v24, v16, v16, v28],
        [v16, v16, v29, v16, v32],
        [v16, v16, v16, v16, v16],
        [v16, v16, v16, v16, v16],
        [v33, v33, v16, v29, v16],
    ]
}
/// Acceleration term of the end-effector twist: `d/dt (J qd) = J qdd + Jdot qd`.
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
///
/// # Output
///
/// `jdot_qd: [f64; 6]`: Jdot(q, qd) qd: m/s^2 (rows 0-2) and rad/s^2 (rows 3-5), base frame
///
/// Operation count: 29 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn jdot_qd(q: &[f64; 4], qd: &[f64; 4]) -> [f64; 6] {
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
    let v22: f64 = v19 * v7;
    let v23: f64 = v18 + v22;
    let v24: f64 = v23 * v9;
    let v25: f64 = v21 - v24;
    let v26: f64 = v25 * v17;
    let v27: f64 = v14 + v26;
    let v28: f64 = v3 * v9;
    let v29: f64 = v8 * v5;
    let v30: f64 = v28 + v29;
    let v31: f64 = v30 * v12;
    let v32: f64 = v31 * v12;
    let v33: f64 = v20 * v9;
    let v34: f64 = v23 * v5;
    let v35: f64 = v33 + v34;
    let v36: f64 = v35 * v17;
    let v37: f64 = v32 + v36;
    let v38: f64 = -v37;
    let v39: f64 = 0.0_f64;
    [v27, v38, v39, v39, v39, v39]
}
/// Partial derivatives of the geometric Jacobian, `d J / d q_k` for each joint k: `Jdot = sum_k d J/d q_k qd_k`, and `d (J^T f)/d q_k = (d J/d q_k)^T f` for a tool wrench f.
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `jacobian_derivatives: [[[f64; 4]; 6]; 4]` (4 x 6 x 4, row-major): `[k][r][c] = d J_rc / d q_k`, the partial derivatives of `jacobian` (m/rad or 1/rad per row kind; per m for prismatic joints)
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
pub fn jacobian_derivatives(q: &[f64; 4]) -> [[[f64; 4]; 6]; 4] {
    let v0: f64 = 0.4_f64;
    let v1: f64 = q[1];
    let (v2, v8): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = q[0];
    let (v5, v11): (f64, f64) = ::armdyn_runtime::libm::sincos(v4);
    let v6: f64 = v3 * v5;
    let v7: f64 = -0.4_f64;
    let v9: f64 = v0 * v8;
    let v10: f64 = v7 - v9;
    let v12: f64 = v10 * v11;
    let v13: f64 = v6 + v12;
    let v14: f64 = v9 * v11;
    let v15: f64 = v6 - v14;
    let v16: f64 = 0.0_f64;
    let v17: f64 = v10 * v5;
    let v18: f64 = v3 * v11;
    let v19: f64 = v17 - v18;
    let v20: f64 = v9 * v5;
    let v21: f64 = v18 + v20;
    let v22: f64 = -v21;
    [
        [
            [v13, v15, v16, v16],
            [v19, v22, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
        ],
        [
            [v15, v15, v16, v16],
            [v22, v22, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
        ],
        [
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
        ],
        [
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
        ],
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
    let v3: f64 = ::armdyn_runtime::libm::cos(v2);
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
    let v4: f64 = ::armdyn_runtime::libm::sin(v3);
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
    let v9: f64 = ::armdyn_runtime::libm::sin(v8);
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
/// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
/// - `qdd: &[f64; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// # Output
///
/// `tau: [f64; 4]`: joint torques (N m) or forces (N), no external wrench
///
/// Operation count: 30 floating-point operations, 2 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn inverse_dynamics(q: &[f64; 4], qd: &[f64; 4], qdd: &[f64; 4]) -> [f64; 4] {
    let v0: f64 = 1.12144112_f64;
    let v1: f64 = qdd[1];
    let v2: f64 = v0 * v1;
    let v3: f64 = 0.0025_f64;
    let v4: f64 = qdd[3];
    let v5: f64 = v3 * v4;
    let v6: f64 = v2 - v5;
    let v7: f64 = 3.22955337_f64;
    let v8: f64 = qdd[0];
    let v9: f64 = v7 * v8;
    let v10: f64 = v6 + v9;
    let v11: f64 = 1.168448_f64;
    let v12: f64 = v11 * v1;
    let v13: f64 = 2.336896_f64;
    let v14: f64 = v13 * v8;
    let v15: f64 = v12 + v14;
    let v16: f64 = q[1];
    let (v26, v17): (f64, f64) = ::armdyn_runtime::libm::sincos(v16);
    let v18: f64 = v15 * v17;
    let v19: f64 = v10 + v18;
    let v20: f64 = qd[1];
    let v21: f64 = v11 * v20;
    let v22: f64 = qd[0];
    let v23: f64 = v13 * v22;
    let v24: f64 = v21 + v23;
    let v25: f64 = v24 * v20;
    let v27: f64 = v25 * v26;
    let v28: f64 = v19 - v27;
    let v29: f64 = v11 * v22;
    let v30: f64 = v29 * v22;
    let v31: f64 = v30 * v26;
    let v32: f64 = v6 + v31;
    let v33: f64 = v11 * v17;
    let v34: f64 = v0 + v33;
    let v35: f64 = v34 * v8;
    let v36: f64 = v32 + v35;
    let v37: f64 = -48.412_f64;
    let v38: f64 = 4.94_f64;
    let v39: f64 = qdd[2];
    let v40: f64 = v38 * v39;
    let v41: f64 = v37 + v40;
    let v42: f64 = v3 * v1;
    let v43: f64 = v5 - v42;
    let v44: f64 = v3 * v8;
    let v45: f64 = v43 - v44;
    [v28, v36, v41, v45]
}
/// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g.
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
/// - `tau: &[f64; 4]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
///
/// # Output
///
/// `qdd: [f64; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// Operation count: 32 floating-point operations, 2 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn forward_dynamics(q: &[f64; 4], qd: &[f64; 4], tau: &[f64; 4]) -> [f64; 4] {
    let v0: f64 = tau[0];
    let v1: f64 = 1.168448_f64;
    let v2: f64 = qd[1];
    let v3: f64 = v1 * v2;
    let v4: f64 = 2.336896_f64;
    let v5: f64 = qd[0];
    let v6: f64 = v4 * v5;
    let v7: f64 = v3 + v6;
    let v8: f64 = v7 * v2;
    let v9: f64 = q[1];
    let (v10, v17): (f64, f64) = ::armdyn_runtime::libm::sincos(v9);
    let v11: f64 = v8 * v10;
    let v12: f64 = v0 + v11;
    let v13: f64 = tau[3];
    let v14: f64 = v12 + v13;
    let v15: f64 = 0.8937020743325618_f64;
    let v16: f64 = 1.12144112_f64;
    let v18: f64 = v1 * v17;
    let v19: f64 = v16 + v18;
    let v20: f64 = 0.0025_f64;
    let v21: f64 = v19 - v20;
    let v22: f64 = v15 * v21;
    let v23: f64 = tau[1];
    let v24: f64 = v1 * v5;
    let v25: f64 = v24 * v5;
    let v26: f64 = v25 * v10;
    let v27: f64 = v23 - v26;
    let v28: f64 = v27 + v13;
    let v29: f64 = v22 * v28;
    let v30: f64 = v14 - v29;
    let v31: f64 = 3.22955337_f64;
    let v32: f64 = v4 * v17;
    let v33: f64 = v31 + v32;
    let v34: f64 = v33 - v20;
    let v35: f64 = v21 * v22;
    let v36: f64 = v34 - v35;
    let v37: f64 = v30 / v36;
    let v38: f64 = v15 * v28;
    let v39: f64 = v22 * v37;
    let v40: f64 = v38 - v39;
    let v41: f64 = 0.20242914979757085_f64;
    let v42: f64 = tau[2];
    let v43: f64 = -48.412_f64;
    let v44: f64 = v42 - v43;
    let v45: f64 = v41 * v44;
    let v46: f64 = 400.0_f64;
    let v47: f64 = v46 * v13;
    let v48: f64 = v47 + v37;
    let v49: f64 = v48 + v40;
    [v37, v40, v45, v49]
}
/// Mass matrix and bias in one pass: row i is `[M_i0, ..., M_i(n-1), c_i + g_i]`, the `M(q)` of `mass_matrix` with the bias `c(q, qd) + g(q)` of `coriolis` and `gravity` as a last column (what Pinocchio's `crba` and `nonLinearEffects` compute together). Common subexpressions, sin/cos included, are computed once for both.
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
///
/// # Output
///
/// `mass_matrix_and_bias: [[f64; 5]; 4]` (4 x 5, row-major): rows `[M(q) | c(q, qd) + g(q)]`: the symmetric positive definite M (kg m^2, kg m, kg), then the bias (N m or N)
///
/// Operation count: 13 floating-point operations, 2 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn mass_matrix_and_bias(q: &[f64; 4], qd: &[f64; 4]) -> [[f64; 5]; 4] {
    let v0: f64 = 3.22955337_f64;
    let v1: f64 = 2.336896_f64;
    let v2: f64 = q[1];
    let (v18, v3): (f64, f64) = ::armdyn_runtime::libm::sincos(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = v0 + v4;
    let v6: f64 = 1.12144112_f64;
    let v7: f64 = 1.168448_f64;
    let v8: f64 = v7 * v3;
    let v9: f64 = v6 + v8;
    let v10: f64 = 0.0_f64;
    let v11: f64 = -0.0025_f64;
    let v12: f64 = qd[1];
    let v13: f64 = v7 * v12;
    let v14: f64 = qd[0];
    let v15: f64 = v1 * v14;
    let v16: f64 = v13 + v15;
    let v17: f64 = v16 * v12;
    let v19: f64 = v17 * v18;
    let v20: f64 = -v19;
    let v21: f64 = v7 * v14;
    let v22: f64 = v21 * v14;
    let v23: f64 = v22 * v18;
    let v24: f64 = 4.94_f64;
    let v25: f64 = -48.412_f64;
    let v26: f64 = 0.0025_f64;
    [
        [v5, v9, v10, v11, v20],
        [v9, v6, v10, v11, v23],
        [v10, v10, v24, v10, v25],
        [v11, v11, v10, v26, v10],
    ]
}
/// Derivatives of inverse dynamics: row i is `[d tau_i/d q | d tau_i/d qd | d tau_i/d qdd]` (3n entries; the last block is the mass matrix `M(q)`), the partial derivatives of `inverse_dynamics` (what Pinocchio's `computeRNEADerivatives` computes), generated by algorithmic differentiation of its graph and folded like every other function.
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
/// - `qdd: &[f64; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// # Output
///
/// `inverse_dynamics_derivatives: [[f64; 12]; 4]` (4 x 12, row-major): rows `[d tau/d q | d tau/d qd | M(q)]`: N m/rad, N m s/rad, kg m^2 (N/m, N s/m, kg for prismatic joints)
///
/// Operation count: 29 floating-point operations, 2 trig calls.
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
    q: &[f64; 4],
    qd: &[f64; 4],
    qdd: &[f64; 4],
) -> [[f64; 12]; 4] {
    let v0: f64 = 0.0_f64;
    let v1: f64 = 1.168448_f64;
    let v2: f64 = qdd[1];
    let v3: f64 = v1 * v2;
    let v4: f64 = 2.336896_f64;
    let v5: f64 = qdd[0];
    let v6: f64 = v4 * v5;
    let v7: f64 = v3 + v6;
    let v8: f64 = q[1];
    let (v9, v17): (f64, f64) = ::armdyn_runtime::libm::sincos(v8);
    let v10: f64 = v7 * v9;
    let v11: f64 = qd[1];
    let v12: f64 = v1 * v11;
    let v13: f64 = qd[0];
    let v14: f64 = v4 * v13;
    let v15: f64 = v12 + v14;
    let v16: f64 = v15 * v11;
    let v18: f64 = v16 * v17;
    let v19: f64 = v10 + v18;
    let v20: f64 = -v19;
    let v21: f64 = v4 * v11;
    let v22: f64 = v9 * v21;
    let v23: f64 = -v22;
    let v24: f64 = v12 + v15;
    let v25: f64 = v9 * v24;
    let v26: f64 = -v25;
    let v27: f64 = 3.22955337_f64;
    let v28: f64 = v4 * v17;
    let v29: f64 = v27 + v28;
    let v30: f64 = 1.12144112_f64;
    let v31: f64 = v1 * v17;
    let v32: f64 = v30 + v31;
    let v33: f64 = -0.0025_f64;
    let v34: f64 = v1 * v13;
    let v35: f64 = v34 * v13;
    let v36: f64 = v35 * v17;
    let v37: f64 = v1 * v9;
    let v38: f64 = v5 * v37;
    let v39: f64 = v36 - v38;
    let v40: f64 = v34 + v34;
    let v41: f64 = v9 * v40;
    let v42: f64 = 4.94_f64;
    let v43: f64 = 0.0025_f64;
    [
        [v0, v20, v0, v0, v23, v26, v0, v0, v29, v32, v0, v33],
        [v0, v39, v0, v0, v41, v0, v0, v0, v32, v30, v0, v33],
        [v0, v0, v0, v0, v0, v0, v0, v0, v0, v0, v42, v0],
        [v0, v0, v0, v0, v0, v0, v0, v0, v33, v33, v0, v43],
    ]
}
/// Derivatives of forward dynamics: row i is `[d qdd_i/d q | d qdd_i/d qd | d qdd_i/d tau]` (3n entries; the last block is `M(q)^-1`), the partial derivatives of `forward_dynamics` (what Pinocchio's `computeABADerivatives` computes): `d qdd/d x = -M^-1 d ID/d x` at `qdd = forward_dynamics(q, qd, tau)` (implicit function theorem on `inverse_dynamics(q, qd, forward_dynamics(q, qd, tau)) = tau`), all 3n right-hand sides solved by one unrolled sparse `L^T D L` factorisation of M. For a tool wrench `f` (`tau - J^T f` into forward dynamics) add `-M^-1 d(J^T f)/d q` to the first block, from `jacobian_derivatives`.
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
/// - `tau: &[f64; 4]`: joint torques (N m) or forces (N)
///
/// # Output
///
/// `forward_dynamics_derivatives: [[f64; 12]; 4]` (4 x 12, row-major): rows `[d qdd/d q | d qdd/d qd | M(q)^-1]`: 1/s^2, 1/s, 1/(kg m^2) (per m, per kg for prismatic joints)
///
/// Operation count: 76 floating-point operations, 2 trig calls.
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
    q: &[f64; 4],
    qd: &[f64; 4],
    tau: &[f64; 4],
) -> [[f64; 12]; 4] {
    let v0: f64 = 0.0_f64;
    let v1: f64 = 1.168448_f64;
    let v2: f64 = 0.8937020743325618_f64;
    let v3: f64 = tau[1];
    let v4: f64 = qd[0];
    let v5: f64 = v1 * v4;
    let v6: f64 = v5 * v4;
    let v7: f64 = q[1];
    let (v8, v15): (f64, f64) = ::armdyn_runtime::libm::sincos(v7);
    let v9: f64 = v6 * v8;
    let v10: f64 = v3 - v9;
    let v11: f64 = tau[3];
    let v12: f64 = v10 + v11;
    let v13: f64 = v2 * v12;
    let v14: f64 = 1.12144112_f64;
    let v16: f64 = v1 * v15;
    let v17: f64 = v14 + v16;
    let v18: f64 = 0.0025_f64;
    let v19: f64 = v17 - v18;
    let v20: f64 = v2 * v19;
    let v21: f64 = tau[0];
    let v22: f64 = qd[1];
    let v23: f64 = v1 * v22;
    let v24: f64 = 2.336896_f64;
    let v25: f64 = v24 * v4;
    let v26: f64 = v23 + v25;
    let v27: f64 = v26 * v22;
    let v28: f64 = v27 * v8;
    let v29: f64 = v21 + v28;
    let v30: f64 = v29 + v11;
    let v31: f64 = v20 * v12;
    let v32: f64 = v30 - v31;
    let v33: f64 = 3.22955337_f64;
    let v34: f64 = v24 * v15;
    let v35: f64 = v33 + v34;
    let v36: f64 = v35 - v18;
    let v37: f64 = v19 * v20;
    let v38: f64 = v36 - v37;
    let v39: f64 = v32 / v38;
    let v40: f64 = v20 * v39;
    let v41: f64 = v13 - v40;
    let v42: f64 = v1 * v41;
    let v43: f64 = v24 * v39;
    let v44: f64 = v42 + v43;
    let v45: f64 = v44 * v8;
    let v46: f64 = v27 * v15;
    let v47: f64 = v45 + v46;
    let v48: f64 = v6 * v15;
    let v49: f64 = v1 * v8;
    let v50: f64 = v39 * v49;
    let v51: f64 = v48 - v50;
    let v52: f64 = v20 * v51;
    let v53: f64 = v47 + v52;
    let v54: f64 = v53 / v38;
    let v55: f64 = v24 * v22;
    let v56: f64 = v8 * v55;
    let v57: f64 = v5 + v5;
    let v58: f64 = v8 * v57;
    let v59: f64 = v20 * v58;
    let v60: f64 = v56 + v59;
    let v61: f64 = v60 / v38;
    let v62: f64 = v23 + v26;
    let v63: f64 = v8 * v62;
    let v64: f64 = v63 / v38;
    let v65: f64 = 1.0_f64 / v38;
    let v66: f64 = v20 / v38;
    let v67: f64 = -v66;
    let v68: f64 = 1.0_f64;
    let v69: f64 = v68 - v20;
    let v70: f64 = v69 / v38;
    let v71: f64 = v2 * v51;
    let v72: f64 = v20 * v54;
    let v73: f64 = v71 + v72;
    let v74: f64 = -v73;
    let v75: f64 = v2 * v58;
    let v76: f64 = v20 * v61;
    let v77: f64 = v75 + v76;
    let v78: f64 = -v77;
    let v79: f64 = v20 * v64;
    let v80: f64 = -v79;
    let v81: f64 = v20 * v66;
    let v82: f64 = v2 + v81;
    let v83: f64 = v20 * v70;
    let v84: f64 = v2 - v83;
    let v85: f64 = 0.20242914979757085_f64;
    let v86: f64 = v54 - v73;
    let v87: f64 = v61 - v77;
    let v88: f64 = v64 - v79;
    let v89: f64 = v65 - v66;
    let v90: f64 = v82 - v66;
    let v91: f64 = 400.0_f64;
    let v92: f64 = v91 + v70;
    let v93: f64 = v92 + v84;
    [
        [v0, v54, v0, v0, v61, v64, v0, v0, v65, v67, v0, v70],
        [v0, v74, v0, v0, v78, v80, v0, v0, v67, v82, v0, v84],
        [v0, v0, v0, v0, v0, v0, v0, v0, v0, v0, v85, v0],
        [v0, v86, v0, v0, v87, v88, v0, v0, v89, v90, v0, v93],
    ]
}
/// Dynamic regressor: `inverse_dynamics(q, qd, qdd) = Y(q, qd, qdd) * standard_parameters()`.
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
/// - `qdd: &[f64; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// # Output
///
/// `regressor: [[f64; 40]; 4]` (4 x 40, row-major): Y(q, qd, qdd), columns in the order of `standard_parameters`
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
pub fn regressor(q: &[f64; 4], qd: &[f64; 4], qdd: &[f64; 4]) -> [[f64; 40]; 4] {
    let v0: f64 = 0.4_f64;
    let v1: f64 = qdd[0];
    let v2: f64 = v0 * v1;
    let v3: f64 = v0 * v2;
    let v4: f64 = v2 + v2;
    let v5: f64 = qd[0];
    let v6: f64 = -0.4_f64;
    let v7: f64 = v6 * v5;
    let v8: f64 = v5 * v7;
    let v9: f64 = v0 * v5;
    let v10: f64 = v5 * v9;
    let v11: f64 = v8 + v10;
    let v12: f64 = q[1];
    let (v13, v15): (f64, f64) = ::armdyn_runtime::libm::sincos(v12);
    let v14: f64 = v13 * v2;
    let v16: f64 = v15 * v10;
    let v17: f64 = v14 - v16;
    let v18: f64 = qd[1];
    let v19: f64 = v5 + v18;
    let v20: f64 = v0 * v19;
    let v21: f64 = v19 * v20;
    let v22: f64 = v17 - v21;
    let v23: f64 = v0 * v13;
    let v24: f64 = v22 * v23;
    let v25: f64 = v13 * v10;
    let v26: f64 = v15 * v2;
    let v27: f64 = v25 + v26;
    let v28: f64 = qdd[1];
    let v29: f64 = v1 + v28;
    let v30: f64 = v0 * v29;
    let v31: f64 = v27 + v30;
    let v32: f64 = v6 * v15;
    let v33: f64 = v32 + v6;
    let v34: f64 = v31 * v33;
    let v35: f64 = v24 - v34;
    let v36: f64 = v19 * v23;
    let v37: f64 = v19 * v36;
    let v38: f64 = v29 * v33;
    let v39: f64 = v37 + v38;
    let v40: f64 = v31 - v39;
    let v41: f64 = v29 * v23;
    let v42: f64 = v19 * v33;
    let v43: f64 = v19 * v42;
    let v44: f64 = v41 - v43;
    let v45: f64 = v44 + v22;
    let v46: f64 = q[3];
    let (v49, v47): (f64, f64) = ::armdyn_runtime::libm::sincos(v46);
    let v48: f64 = v47 * v22;
    let v50: f64 = v49 * v31;
    let v51: f64 = v48 - v50;
    let v52: f64 = v47 * v23;
    let v53: f64 = v49 * v33;
    let v54: f64 = v52 + v53;
    let v55: f64 = v51 * v54;
    let v56: f64 = v49 * v22;
    let v57: f64 = v47 * v31;
    let v58: f64 = v56 + v57;
    let v59: f64 = v47 * v33;
    let v60: f64 = v49 * v23;
    let v61: f64 = v59 - v60;
    let v62: f64 = v58 * v61;
    let v63: f64 = v55 - v62;
    let v64: f64 = qdd[3];
    let v65: f64 = v64 - v29;
    let v66: f64 = v65 * v61;
    let v67: f64 = qd[3];
    let v68: f64 = v67 - v19;
    let v69: f64 = v68 * v54;
    let v70: f64 = v68 * v69;
    let v71: f64 = v66 - v70;
    let v72: f64 = v71 + v58;
    let v73: f64 = v68 * v61;
    let v74: f64 = v68 * v73;
    let v75: f64 = v65 * v54;
    let v76: f64 = v74 + v75;
    let v77: f64 = v51 - v76;
    let v78: f64 = -v65;
    let v79: f64 = v0 * v31;
    let v80: f64 = v30 + v31;
    let v81: f64 = v6 * v49;
    let v82: f64 = v51 * v81;
    let v83: f64 = v6 * v47;
    let v84: f64 = v58 * v83;
    let v85: f64 = v82 - v84;
    let v86: f64 = v65 * v83;
    let v87: f64 = v68 * v81;
    let v88: f64 = v68 * v87;
    let v89: f64 = v86 - v88;
    let v90: f64 = v89 + v58;
    let v91: f64 = v68 * v83;
    let v92: f64 = v68 * v91;
    let v93: f64 = v65 * v81;
    let v94: f64 = v92 + v93;
    let v95: f64 = v51 - v94;
    let v96: f64 = -9.8_f64;
    let v97: f64 = qdd[2];
    let v98: f64 = v96 + v97;
    let v99: f64 = -v58;
    let v100: f64 = -v51;
    let v101: f64 = 0.0_f64;
    [
        [
            v3,
            v4,
            v11,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v1,
            v35,
            v40,
            v45,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v29,
            v35,
            v40,
            v45,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v29,
            v63,
            v72,
            v77,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v78,
        ],
        [
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v79,
            v80,
            v17,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v29,
            v79,
            v80,
            v17,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v29,
            v85,
            v90,
            v95,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v78,
        ],
        [
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v98,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v98,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
        ],
        [
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v99,
            v100,
            v101,
            v101,
            v101,
            v101,
            v101,
            v101,
            v65,
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
/// `params: [f64; 40]`: per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2, inertia about the link frame origin)
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
pub fn standard_parameters() -> [f64; 40] {
    let v0: f64 = 6.01_f64;
    let v1: f64 = -1.11185_f64;
    let v2: f64 = 0.0_f64;
    let v3: f64 = 0.0132_f64;
    let v4: f64 = 0.38669225_f64;
    let v5: f64 = 0.38639225_f64;
    let v6: f64 = 5.37_f64;
    let v7: f64 = -1.20288_f64;
    let v8: f64 = 0.0234_f64;
    let v9: f64 = 0.39554512_f64;
    let v10: f64 = 0.42524512_f64;
    let v11: f64 = 4.03_f64;
    let v12: f64 = -0.81003_f64;
    let v13: f64 = 0.24301603_f64;
    let v14: f64 = 0.0064_f64;
    let v15: f64 = 0.91_f64;
    let v16: f64 = -0.11102_f64;
    let v17: f64 = 0.01514444_f64;
    let v18: f64 = 0.0025_f64;
    [
        v0,
        v1,
        v2,
        v2,
        v3,
        v2,
        v2,
        v4,
        v2,
        v5,
        v6,
        v7,
        v2,
        v2,
        v8,
        v2,
        v2,
        v9,
        v2,
        v10,
        v11,
        v2,
        v2,
        v12,
        v13,
        v2,
        v2,
        v13,
        v2,
        v14,
        v15,
        v2,
        v2,
        v16,
        v17,
        v2,
        v2,
        v17,
        v2,
        v18,
    ]
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
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `poses: [[[f32; 4]; 4]; 4]` (4 x 4 x 4, row-major): homogeneous transforms T_0i of the description's frames 1..n in the base frame (m)
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
    pub fn frame_poses(q: &[f32; 4]) -> [[[f32; 4]; 4]; 4] {
        let v0: f32 = q[0];
        let (v2, v1): (f32, f32) = ::armdyn_runtime::libm::sincosf(v0);
        let v3: f32 = -v2;
        let v4: f32 = 0.0_f32;
        let v5: f32 = 0.4_f32;
        let v6: f32 = v5 * v1;
        let v7: f32 = v5 * v2;
        let v8: f32 = 1.0_f32;
        let v9: f32 = 0.5_f32;
        let v10: f32 = q[1];
        let (v13, v11): (f32, f32) = ::armdyn_runtime::libm::sincosf(v10);
        let v12: f32 = v1 * v11;
        let v14: f32 = v2 * v13;
        let v15: f32 = v12 - v14;
        let v16: f32 = v1 * v13;
        let v17: f32 = v2 * v11;
        let v18: f32 = v16 + v17;
        let v19: f32 = v5 * v11;
        let v20: f32 = v1 * v19;
        let v21: f32 = v5 * v13;
        let v22: f32 = v2 * v21;
        let v23: f32 = v20 - v22;
        let v24: f32 = v6 + v23;
        let v25: f32 = v17 + v16;
        let v26: f32 = v14 - v12;
        let v27: f32 = v2 * v19;
        let v28: f32 = v1 * v21;
        let v29: f32 = v27 + v28;
        let v30: f32 = v7 + v29;
        let v31: f32 = -1.0_f32;
        let v32: f32 = q[2];
        let v33: f32 = v9 - v32;
        let v34: f32 = q[3];
        let (v37, v35): (f32, f32) = ::armdyn_runtime::libm::sincosf(v34);
        let v36: f32 = v15 * v35;
        let v38: f32 = v18 * v37;
        let v39: f32 = v36 + v38;
        let v40: f32 = v18 * v35;
        let v41: f32 = v15 * v37;
        let v42: f32 = v40 - v41;
        let v43: f32 = v25 * v35;
        let v44: f32 = v26 * v37;
        let v45: f32 = v43 + v44;
        let v46: f32 = v26 * v35;
        let v47: f32 = v25 * v37;
        let v48: f32 = v46 - v47;
        let v49: f32 = -0.15_f32;
        let v50: f32 = v33 + v49;
        [
            [[v1, v3, v4, v6], [v2, v1, v4, v7], [v4, v4, v8, v9], [v4, v4, v4, v8]],
            [
                [v15, v18, v4, v24],
                [v25, v26, v4, v30],
                [v4, v4, v31, v9],
                [v4, v4, v4, v8],
            ],
            [
                [v15, v18, v4, v24],
                [v25, v26, v4, v30],
                [v4, v4, v31, v33],
                [v4, v4, v4, v8],
            ],
            [
                [v39, v42, v4, v24],
                [v45, v48, v4, v30],
                [v4, v4, v31, v50],
                [v4, v4, v4, v8],
            ],
        ]
    }
    /// End-effector pose, forward kinematics `T_0n` (thesis eq. 3.7).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `pose: [[f32; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the base frame (m)
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
    pub fn end_effector_pose(q: &[f32; 4]) -> [[f32; 4]; 4] {
        let v0: f32 = q[3];
        let (v5, v1): (f32, f32) = ::armdyn_runtime::libm::sincosf(v0);
        let v2: f32 = q[1];
        let (v6, v3): (f32, f32) = ::armdyn_runtime::libm::sincosf(v2);
        let v4: f32 = v1 * v3;
        let v7: f32 = v5 * v6;
        let v8: f32 = v4 + v7;
        let v9: f32 = q[0];
        let (v15, v10): (f32, f32) = ::armdyn_runtime::libm::sincosf(v9);
        let v11: f32 = v8 * v10;
        let v12: f32 = v5 * v3;
        let v13: f32 = v1 * v6;
        let v14: f32 = v12 - v13;
        let v16: f32 = v14 * v15;
        let v17: f32 = v11 + v16;
        let v18: f32 = v13 - v12;
        let v19: f32 = v18 * v10;
        let v20: f32 = v8 * v15;
        let v21: f32 = v19 + v20;
        let v22: f32 = 0.0_f32;
        let v23: f32 = 0.4_f32;
        let v24: f32 = v23 * v3;
        let v25: f32 = v23 + v24;
        let v26: f32 = v25 * v10;
        let v27: f32 = v23 * v6;
        let v28: f32 = v27 * v15;
        let v29: f32 = v26 - v28;
        let v30: f32 = v18 * v15;
        let v31: f32 = v30 - v11;
        let v32: f32 = v27 * v10;
        let v33: f32 = v25 * v15;
        let v34: f32 = v32 + v33;
        let v35: f32 = -1.0_f32;
        let v36: f32 = 0.35_f32;
        let v37: f32 = q[2];
        let v38: f32 = v36 - v37;
        let v39: f32 = 1.0_f32;
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
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian: [[f32; 4]; 6]` (6 x 4, row-major): rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame
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
    pub fn jacobian(q: &[f32; 4]) -> [[f32; 4]; 6] {
        let v0: f32 = 0.4_f32;
        let v1: f32 = q[0];
        let (v2, v8): (f32, f32) = ::armdyn_runtime::libm::sincosf(v1);
        let v3: f32 = v0 * v2;
        let v4: f32 = q[1];
        let (v9, v5): (f32, f32) = ::armdyn_runtime::libm::sincosf(v4);
        let v6: f32 = v0 * v5;
        let v7: f32 = v2 * v6;
        let v10: f32 = v0 * v9;
        let v11: f32 = v8 * v10;
        let v12: f32 = v7 + v11;
        let v13: f32 = v3 + v12;
        let v14: f32 = -v13;
        let v15: f32 = -v12;
        let v16: f32 = 0.0_f32;
        let v17: f32 = v0 * v8;
        let v18: f32 = v8 * v6;
        let v19: f32 = v2 * v10;
        let v20: f32 = v18 - v19;
        let v21: f32 = v17 + v20;
        let v22: f32 = -1.0_f32;
        let v23: f32 = 1.0_f32;
        [
            [v14, v15, v16, v16],
            [v21, v20, v16, v16],
            [v16, v16, v22, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v23, v23, v16, v22],
        ]
    }
    /// Jacobian and tool position in one pass: `[J | p; 0]`, row r is `[J_r0, ..., J_r(n-1), p_r]` with `J` the geometric Jacobian of `jacobian` and `p` the end-effector origin of `end_effector_pose` (rows 0-2; the last column of rows 3-5 is 0), the same operations as those two functions (bit-identical results), with common subexpressions, sin/cos included, computed once for both and the pose's rotation not computed.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian_and_position: [[f32; 5]; 6]` (6 x 5, row-major): rows `[J(q) | p(q); 0]`: the geometric Jacobian of `jacobian` (rows vx vy vz per unit joint velocity, then wx wy wz, base frame), then the end-effector origin (m, base frame) in rows 0-2 of the last column, 0 in rows 3-5
    ///
    /// Operation count: 22 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jacobian_and_position(q: &[f32; 4]) -> [[f32; 5]; 6] {
        let v0: f32 = 0.4_f32;
        let v1: f32 = q[0];
        let (v2, v8): (f32, f32) = ::armdyn_runtime::libm::sincosf(v1);
        let v3: f32 = v0 * v2;
        let v4: f32 = q[1];
        let (v9, v5): (f32, f32) = ::armdyn_runtime::libm::sincosf(v4);
        let v6: f32 = v0 * v5;
        let v7: f32 = v2 * v6;
        let v10: f32 = v0 * v9;
        let v11: f32 = v8 * v10;
        let v12: f32 = v7 + v11;
        let v13: f32 = v3 + v12;
        let v14: f32 = -v13;
        let v15: f32 = -v12;
        let v16: f32 = 0.0_f32;
        let v17: f32 = v0 + v6;
        let v18: f32 = v17 * v8;
        let v19: f32 = v10 * v2;
        let v20: f32 = v18 - v19;
        let v21: f32 = v0 * v8;
        let v22: f32 = v8 * v6;
        let v23: f32 = v2 * v10;
        let v24: f32 = v22 - v23;
        let v25: f32 = v21 + v24;
        let v26: f32 = v10 * v8;
        let v27: f32 = v17 * v2;
        let v28: f32 = v26 + v27;
        let v29: f32 = -1.0_f32;
        let v30: f32 = 0.35_f32;
        let v31: f32 = q[2];
        let v32: f32 = v30 - v31;
        let v33: f32 = 1.0_f32;
        [
            [v14, v15, v16, v16, v20],
            [v25, v24, v16, v16, v28],
            [v16, v16, v29, v16, v32],
            [v16, v16, v16, v16, v16],
            [v16, v16, v16, v16, v16],
            [v33, v33, v16, v29, v16],
        ]
    }
    /// Acceleration term of the end-effector twist: `d/dt (J qd) = J qdd + Jdot qd`.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 4]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `jdot_qd: [f32; 6]`: Jdot(q, qd) qd: m/s^2 (rows 0-2) and rad/s^2 (rows 3-5), base frame
    ///
    /// Operation count: 29 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jdot_qd(q: &[f32; 4], qd: &[f32; 4]) -> [f32; 6] {
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
        let v22: f32 = v19 * v7;
        let v23: f32 = v18 + v22;
        let v24: f32 = v23 * v9;
        let v25: f32 = v21 - v24;
        let v26: f32 = v25 * v17;
        let v27: f32 = v14 + v26;
        let v28: f32 = v3 * v9;
        let v29: f32 = v8 * v5;
        let v30: f32 = v28 + v29;
        let v31: f32 = v30 * v12;
        let v32: f32 = v31 * v12;
        let v33: f32 = v20 * v9;
        let v34: f32 = v23 * v5;
        let v35: f32 = v33 + v34;
        let v36: f32 = v35 * v17;
        let v37: f32 = v32 + v36;
        let v38: f32 = -v37;
        let v39: f32 = 0.0_f32;
        [v27, v38, v39, v39, v39, v39]
    }
    /// Partial derivatives of the geometric Jacobian, `d J / d q_k` for each joint k: `Jdot = sum_k d J/d q_k qd_k`, and `d (J^T f)/d q_k = (d J/d q_k)^T f` for a tool wrench f.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian_derivatives: [[[f32; 4]; 6]; 4]` (4 x 6 x 4, row-major): `[k][r][c] = d J_rc / d q_k`, the partial derivatives of `jacobian` (m/rad or 1/rad per row kind; per m for prismatic joints)
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
    pub fn jacobian_derivatives(q: &[f32; 4]) -> [[[f32; 4]; 6]; 4] {
        let v0: f32 = 0.4_f32;
        let v1: f32 = q[1];
        let (v2, v8): (f32, f32) = ::armdyn_runtime::libm::sincosf(v1);
        let v3: f32 = v0 * v2;
        let v4: f32 = q[0];
        let (v5, v11): (f32, f32) = ::armdyn_runtime::libm::sincosf(v4);
        let v6: f32 = v3 * v5;
        let v7: f32 = -0.4_f32;
        let v9: f32 = v0 * v8;
        let v10: f32 = v7 - v9;
        let v12: f32 = v10 * v11;
        let v13: f32 = v6 + v12;
        let v14: f32 = v9 * v11;
        let v15: f32 = v6 - v14;
        let v16: f32 = 0.0_f32;
        let v17: f32 = v10 * v5;
        let v18: f32 = v3 * v11;
        let v19: f32 = v17 - v18;
        let v20: f32 = v9 * v5;
        let v21: f32 = v18 + v20;
        let v22: f32 = -v21;
        [
            [
                [v13, v15, v16, v16],
                [v19, v22, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
            ],
            [
                [v15, v15, v16, v16],
                [v22, v22, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
            ],
            [
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
            ],
            [
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
            ],
        ]
    }
    /// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `mass_matrix: [[f32; 4]; 4]` (4 x 4, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
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
    pub fn mass_matrix(q: &[f32; 4]) -> [[f32; 4]; 4] {
        let v0: f32 = 3.2295535_f32;
        let v1: f32 = 2.336896_f32;
        let v2: f32 = q[1];
        let v3: f32 = ::armdyn_runtime::libm::cosf(v2);
        let v4: f32 = v1 * v3;
        let v5: f32 = v0 + v4;
        let v6: f32 = 1.1214411_f32;
        let v7: f32 = 1.168448_f32;
        let v8: f32 = v7 * v3;
        let v9: f32 = v6 + v8;
        let v10: f32 = 0.0_f32;
        let v11: f32 = -0.0025_f32;
        let v12: f32 = 4.94_f32;
        let v13: f32 = 0.0025_f32;
        [
            [v5, v9, v10, v11],
            [v9, v6, v10, v11],
            [v10, v10, v12, v10],
            [v11, v11, v10, v13],
        ]
    }
    /// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 4]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis_matrix: [[f32; 4]; 4]` (4 x 4, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
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
    pub fn coriolis_matrix(q: &[f32; 4], qd: &[f32; 4]) -> [[f32; 4]; 4] {
        let v0: f32 = 1.168448_f32;
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
        let v12: f32 = 0.0_f32;
        let v13: f32 = v8 * v4;
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
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 4]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis: [f32; 4]`: c(q, qd) = C(q, qd) qd (N m or N)
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
    pub fn coriolis(q: &[f32; 4], qd: &[f32; 4]) -> [f32; 4] {
        let v0: f32 = 1.168448_f32;
        let v1: f32 = qd[1];
        let v2: f32 = v0 * v1;
        let v3: f32 = 2.336896_f32;
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
        let v15: f32 = 0.0_f32;
        [v11, v14, v15, v15]
    }
    /// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `gravity: [f32; 4]`: g(q), joint torques (N m) or forces (N) that hold the robot still
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
    pub fn gravity(q: &[f32; 4]) -> [f32; 4] {
        let v0: f32 = 0.0_f32;
        let v1: f32 = -48.412_f32;
        [v0, v0, v1, v0]
    }
    /// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 4]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[f32; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `tau: [f32; 4]`: joint torques (N m) or forces (N), no external wrench
    ///
    /// Operation count: 30 floating-point operations, 2 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn inverse_dynamics(q: &[f32; 4], qd: &[f32; 4], qdd: &[f32; 4]) -> [f32; 4] {
        let v0: f32 = 1.1214411_f32;
        let v1: f32 = qdd[1];
        let v2: f32 = v0 * v1;
        let v3: f32 = 0.0025_f32;
        let v4: f32 = qdd[3];
        let v5: f32 = v3 * v4;
        let v6: f32 = v2 - v5;
        let v7: f32 = 3.2295535_f32;
        let v8: f32 = qdd[0];
        let v9: f32 = v7 * v8;
        let v10: f32 = v6 + v9;
        let v11: f32 = 1.168448_f32;
        let v12: f32 = v11 * v1;
        let v13: f32 = 2.336896_f32;
        let v14: f32 = v13 * v8;
        let v15: f32 = v12 + v14;
        let v16: f32 = q[1];
        let (v26, v17): (f32, f32) = ::armdyn_runtime::libm::sincosf(v16);
        let v18: f32 = v15 * v17;
        let v19: f32 = v10 + v18;
        let v20: f32 = qd[1];
        let v21: f32 = v11 * v20;
        let v22: f32 = qd[0];
        let v23: f32 = v13 * v22;
        let v24: f32 = v21 + v23;
        let v25: f32 = v24 * v20;
        let v27: f32 = v25 * v26;
        let v28: f32 = v19 - v27;
        let v29: f32 = v11 * v22;
        let v30: f32 = v29 * v22;
        let v31: f32 = v30 * v26;
        let v32: f32 = v6 + v31;
        let v33: f32 = v11 * v17;
        let v34: f32 = v0 + v33;
        let v35: f32 = v34 * v8;
        let v36: f32 = v32 + v35;
        let v37: f32 = -48.412_f32;
        let v38: f32 = 4.94_f32;
        let v39: f32 = qdd[2];
        let v40: f32 = v38 * v39;
        let v41: f32 = v37 + v40;
        let v42: f32 = v3 * v1;
        let v43: f32 = v5 - v42;
        let v44: f32 = v3 * v8;
        let v45: f32 = v43 - v44;
        [v28, v36, v41, v45]
    }
    /// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 4]`: joint velocities qd (rad/s or m/s)
    /// - `tau: &[f32; 4]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
    ///
    /// # Output
    ///
    /// `qdd: [f32; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// Operation count: 32 floating-point operations, 2 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn forward_dynamics(q: &[f32; 4], qd: &[f32; 4], tau: &[f32; 4]) -> [f32; 4] {
        let v0: f32 = tau[0];
        let v1: f32 = 1.168448_f32;
        let v2: f32 = qd[1];
        let v3: f32 = v1 * v2;
        let v4: f32 = 2.336896_f32;
        let v5: f32 = qd[0];
        let v6: f32 = v4 * v5;
        let v7: f32 = v3 + v6;
        let v8: f32 = v7 * v2;
        let v9: f32 = q[1];
        let (v10, v17): (f32, f32) = ::armdyn_runtime::libm::sincosf(v9);
        let v11: f32 = v8 * v10;
        let v12: f32 = v0 + v11;
        let v13: f32 = tau[3];
        let v14: f32 = v12 + v13;
        let v15: f32 = 0.8937021_f32;
        let v16: f32 = 1.1214411_f32;
        let v18: f32 = v1 * v17;
        let v19: f32 = v16 + v18;
        let v20: f32 = 0.0025_f32;
        let v21: f32 = v19 - v20;
        let v22: f32 = v15 * v21;
        let v23: f32 = tau[1];
        let v24: f32 = v1 * v5;
        let v25: f32 = v24 * v5;
        let v26: f32 = v25 * v10;
        let v27: f32 = v23 - v26;
        let v28: f32 = v27 + v13;
        let v29: f32 = v22 * v28;
        let v30: f32 = v14 - v29;
        let v31: f32 = 3.2295535_f32;
        let v32: f32 = v4 * v17;
        let v33: f32 = v31 + v32;
        let v34: f32 = v33 - v20;
        let v35: f32 = v21 * v22;
        let v36: f32 = v34 - v35;
        let v37: f32 = v30 / v36;
        let v38: f32 = v15 * v28;
        let v39: f32 = v22 * v37;
        let v40: f32 = v38 - v39;
        let v41: f32 = 0.20242915_f32;
        let v42: f32 = tau[2];
        let v43: f32 = -48.412_f32;
        let v44: f32 = v42 - v43;
        let v45: f32 = v41 * v44;
        let v46: f32 = 400.0_f32;
        let v47: f32 = v46 * v13;
        let v48: f32 = v47 + v37;
        let v49: f32 = v48 + v40;
        [v37, v40, v45, v49]
    }
    /// Mass matrix and bias in one pass: row i is `[M_i0, ..., M_i(n-1), c_i + g_i]`, the `M(q)` of `mass_matrix` with the bias `c(q, qd) + g(q)` of `coriolis` and `gravity` as a last column (what Pinocchio's `crba` and `nonLinearEffects` compute together). Common subexpressions, sin/cos included, are computed once for both.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 4]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `mass_matrix_and_bias: [[f32; 5]; 4]` (4 x 5, row-major): rows `[M(q) | c(q, qd) + g(q)]`: the symmetric positive definite M (kg m^2, kg m, kg), then the bias (N m or N)
    ///
    /// Operation count: 13 floating-point operations, 2 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn mass_matrix_and_bias(q: &[f32; 4], qd: &[f32; 4]) -> [[f32; 5]; 4] {
        let v0: f32 = 3.2295535_f32;
        let v1: f32 = 2.336896_f32;
        let v2: f32 = q[1];
        let (v18, v3): (f32, f32) = ::armdyn_runtime::libm::sincosf(v2);
        let v4: f32 = v1 * v3;
        let v5: f32 = v0 + v4;
        let v6: f32 = 1.1214411_f32;
        let v7: f32 = 1.168448_f32;
        let v8: f32 = v7 * v3;
        let v9: f32 = v6 + v8;
        let v10: f32 = 0.0_f32;
        let v11: f32 = -0.0025_f32;
        let v12: f32 = qd[1];
        let v13: f32 = v7 * v12;
        let v14: f32 = qd[0];
        let v15: f32 = v1 * v14;
        let v16: f32 = v13 + v15;
        let v17: f32 = v16 * v12;
        let v19: f32 = v17 * v18;
        let v20: f32 = -v19;
        let v21: f32 = v7 * v14;
        let v22: f32 = v21 * v14;
        let v23: f32 = v22 * v18;
        let v24: f32 = 4.94_f32;
        let v25: f32 = -48.412_f32;
        let v26: f32 = 0.0025_f32;
        [
            [v5, v9, v10, v11, v20],
            [v9, v6, v10, v11, v23],
            [v10, v10, v24, v10, v25],
            [v11, v11, v10, v26, v10],
        ]
    }
    /// Derivatives of inverse dynamics: row i is `[d tau_i/d q | d tau_i/d qd | d tau_i/d qdd]` (3n entries; the last block is the mass matrix `M(q)`), the partial derivatives of `inverse_dynamics` (what Pinocchio's `computeRNEADerivatives` computes), generated by algorithmic differentiation of its graph and folded like every other function.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 4]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[f32; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `inverse_dynamics_derivatives: [[f32; 12]; 4]` (4 x 12, row-major): rows `[d tau/d q | d tau/d qd | M(q)]`: N m/rad, N m s/rad, kg m^2 (N/m, N s/m, kg for prismatic joints)
    ///
    /// Operation count: 29 floating-point operations, 2 trig calls.
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
        q: &[f32; 4],
        qd: &[f32; 4],
        qdd: &[f32; 4],
    ) -> [[f32; 12]; 4] {
        let v0: f32 = 0.0_f32;
        let v1: f32 = 1.168448_f32;
        let v2: f32 = qdd[1];
        let v3: f32 = v1 * v2;
        let v4: f32 = 2.336896_f32;
        let v5: f32 = qdd[0];
        let v6: f32 = v4 * v5;
        let v7: f32 = v3 + v6;
        let v8: f32 = q[1];
        let (v9, v17): (f32, f32) = ::armdyn_runtime::libm::sincosf(v8);
        let v10: f32 = v7 * v9;
        let v11: f32 = qd[1];
        let v12: f32 = v1 * v11;
        let v13: f32 = qd[0];
        let v14: f32 = v4 * v13;
        let v15: f32 = v12 + v14;
        let v16: f32 = v15 * v11;
        let v18: f32 = v16 * v17;
        let v19: f32 = v10 + v18;
        let v20: f32 = -v19;
        let v21: f32 = v4 * v11;
        let v22: f32 = v9 * v21;
        let v23: f32 = -v22;
        let v24: f32 = v12 + v15;
        let v25: f32 = v9 * v24;
        let v26: f32 = -v25;
        let v27: f32 = 3.2295535_f32;
        let v28: f32 = v4 * v17;
        let v29: f32 = v27 + v28;
        let v30: f32 = 1.1214411_f32;
        let v31: f32 = v1 * v17;
        let v32: f32 = v30 + v31;
        let v33: f32 = -0.0025_f32;
        let v34: f32 = v1 * v13;
        let v35: f32 = v34 * v13;
        let v36: f32 = v35 * v17;
        let v37: f32 = v1 * v9;
        let v38: f32 = v5 * v37;
        let v39: f32 = v36 - v38;
        let v40: f32 = v34 + v34;
        let v41: f32 = v9 * v40;
        let v42: f32 = 4.94_f32;
        let v43: f32 = 0.0025_f32;
        [
            [v0, v20, v0, v0, v23, v26, v0, v0, v29, v32, v0, v33],
            [v0, v39, v0, v0, v41, v0, v0, v0, v32, v30, v0, v33],
            [v0, v0, v0, v0, v0, v0, v0, v0, v0, v0, v42, v0],
            [v0, v0, v0, v0, v0, v0, v0, v0, v33, v33, v0, v43],
        ]
    }
    /// Derivatives of forward dynamics: row i is `[d qdd_i/d q | d qdd_i/d qd | d qdd_i/d tau]` (3n entries; the last block is `M(q)^-1`), the partial derivatives of `forward_dynamics` (what Pinocchio's `computeABADerivatives` computes): `d qdd/d x = -M^-1 d ID/d x` at `qdd = forward_dynamics(q, qd, tau)` (implicit function theorem on `inverse_dynamics(q, qd, forward_dynamics(q, qd, tau)) = tau`), all 3n right-hand sides solved by one unrolled sparse `L^T D L` factorisation of M. For a tool wrench `f` (`tau - J^T f` into forward dynamics) add `-M^-1 d(J^T f)/d q` to the first block, from `jacobian_derivatives`.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 4]`: joint velocities qd (rad/s or m/s)
    /// - `tau: &[f32; 4]`: joint torques (N m) or forces (N)
    ///
    /// # Output
    ///
    /// `forward_dynamics_derivatives: [[f32; 12]; 4]` (4 x 12, row-major): rows `[d qdd/d q | d qdd/d qd | M(q)^-1]`: 1/s^2, 1/s, 1/(kg m^2) (per m, per kg for prismatic joints)
    ///
    /// Operation count: 76 floating-point operations, 2 trig calls.
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
        q: &[f32; 4],
        qd: &[f32; 4],
        tau: &[f32; 4],
    ) -> [[f32; 12]; 4] {
        let v0: f32 = 0.0_f32;
        let v1: f32 = 1.168448_f32;
        let v2: f32 = 0.8937021_f32;
        let v3: f32 = tau[1];
        let v4: f32 = qd[0];
        let v5: f32 = v1 * v4;
        let v6: f32 = v5 * v4;
        let v7: f32 = q[1];
        let (v8, v15): (f32, f32) = ::armdyn_runtime::libm::sincosf(v7);
        let v9: f32 = v6 * v8;
        let v10: f32 = v3 - v9;
        let v11: f32 = tau[3];
        let v12: f32 = v10 + v11;
        let v13: f32 = v2 * v12;
        let v14: f32 = 1.1214411_f32;
        let v16: f32 = v1 * v15;
        let v17: f32 = v14 + v16;
        let v18: f32 = 0.0025_f32;
        let v19: f32 = v17 - v18;
        let v20: f32 = v2 * v19;
        let v21: f32 = tau[0];
        let v22: f32 = qd[1];
        let v23: f32 = v1 * v22;
        let v24: f32 = 2.336896_f32;
        let v25: f32 = v24 * v4;
        let v26: f32 = v23 + v25;
        let v27: f32 = v26 * v22;
        let v28: f32 = v27 * v8;
        let v29: f32 = v21 + v28;
        let v30: f32 = v29 + v11;
        let v31: f32 = v20 * v12;
        let v32: f32 = v30 - v31;
        let v33: f32 = 3.2295535_f32;
        let v34: f32 = v24 * v15;
        let v35: f32 = v33 + v34;
        let v36: f32 = v35 - v18;
        let v37: f32 = v19 * v20;
        let v38: f32 = v36 - v37;
        let v39: f32 = v32 / v38;
        let v40: f32 = v20 * v39;
        let v41: f32 = v13 - v40;
        let v42: f32 = v1 * v41;
        let v43: f32 = v24 * v39;
        let v44: f32 = v42 + v43;
        let v45: f32 = v44 * v8;
        let v46: f32 = v27 * v15;
        let v47: f32 = v45 + v46;
        let v48: f32 = v6 * v15;
        let v49: f32 = v1 * v8;
        let v50: f32 = v39 * v49;
        let v51: f32 = v48 - v50;
        let v52: f32 = v20 * v51;
        let v53: f32 = v47 + v52;
        let v54: f32 = v53 / v38;
        let v55: f32 = v24 * v22;
        let v56: f32 = v8 * v55;
        let v57: f32 = v5 + v5;
        let v58: f32 = v8 * v57;
        let v59: f32 = v20 * v58;
        let v60: f32 = v56 + v59;
        let v61: f32 = v60 / v38;
        let v62: f32 = v23 + v26;
        let v63: f32 = v8 * v62;
        let v64: f32 = v63 / v38;
        let v65: f32 = 1.0_f32 / v38;
        let v66: f32 = v20 / v38;
        let v67: f32 = -v66;
        let v68: f32 = 1.0_f32;
        let v69: f32 = v68 - v20;
        let v70: f32 = v69 / v38;
        let v71: f32 = v2 * v51;
        let v72: f32 = v20 * v54;
        let v73: f32 = v71 + v72;
        let v74: f32 = -v73;
        let v75: f32 = v2 * v58;
        let v76: f32 = v20 * v61;
        let v77: f32 = v75 + v76;
        let v78: f32 = -v77;
        let v79: f32 = v20 * v64;
        let v80: f32 = -v79;
        let v81: f32 = v20 * v66;
        let v82: f32 = v2 + v81;
        let v83: f32 = v20 * v70;
        let v84: f32 = v2 - v83;
        let v85: f32 = 0.20242915_f32;
        let v86: f32 = v54 - v73;
        let v87: f32 = v61 - v77;
        let v88: f32 = v64 - v79;
        let v89: f32 = v65 - v66;
        let v90: f32 = v82 - v66;
        let v91: f32 = 400.0_f32;
        let v92: f32 = v91 + v70;
        let v93: f32 = v92 + v84;
        [
            [v0, v54, v0, v0, v61, v64, v0, v0, v65, v67, v0, v70],
            [v0, v74, v0, v0, v78, v80, v0, v0, v67, v82, v0, v84],
            [v0, v0, v0, v0, v0, v0, v0, v0, v0, v0, v85, v0],
            [v0, v86, v0, v0, v87, v88, v0, v0, v89, v90, v0, v93],
        ]
    }
    /// Dynamic regressor: `inverse_dynamics(q, qd, qdd) = Y(q, qd, qdd) * standard_parameters()`.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 4]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[f32; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `regressor: [[f32; 40]; 4]` (4 x 40, row-major): Y(q, qd, qdd), columns in the order of `standard_parameters`
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
    pub fn regressor(q: &[f32; 4], qd: &[f32; 4], qdd: &[f32; 4]) -> [[f32; 40]; 4] {
        let v0: f32 = 0.4_f32;
        let v1: f32 = qdd[0];
        let v2: f32 = v0 * v1;
        let v3: f32 = v0 * v2;
        let v4: f32 = v2 + v2;
        let v5: f32 = qd[0];
        let v6: f32 = -0.4_f32;
        let v7: f32 = v6 * v5;
        let v8: f32 = v5 * v7;
        let v9: f32 = v0 * v5;
        let v10: f32 = v5 * v9;
        let v11: f32 = v8 + v10;
        let v12: f32 = q[1];
        let (v13, v15): (f32, f32) = ::armdyn_runtime::libm::sincosf(v12);
        let v14: f32 = v13 * v2;
        let v16: f32 = v15 * v10;
        let v17: f32 = v14 - v16;
        let v18: f32 = qd[1];
        let v19: f32 = v5 + v18;
        let v20: f32 = v0 * v19;
        let v21: f32 = v19 * v20;
        let v22: f32 = v17 - v21;
        let v23: f32 = v0 * v13;
        let v24: f32 = v22 * v23;
        let v25: f32 = v13 * v10;
        let v26: f32 = v15 * v2;
        let v27: f32 = v25 + v26;
        let v28: f32 = qdd[1];
        let v29: f32 = v1 + v28;
        let v30: f32 = v0 * v29;
        let v31: f32 = v27 + v30;
        let v32: f32 = v6 * v15;
        let v33: f32 = v32 + v6;
        let v34: f32 = v31 * v33;
        let v35: f32 = v24 - v34;
        let v36: f32 = v19 * v23;
        let v37: f32 = v19 * v36;
        let v38: f32 = v29 * v33;
        let v39: f32 = v37 + v38;
        let v40: f32 = v31 - v39;
        let v41: f32 = v29 * v23;
        let v42: f32 = v19 * v33;
        let v43: f32 = v19 * v42;
        let v44: f32 = v41 - v43;
        let v45: f32 = v44 + v22;
        let v46: f32 = q[3];
        let (v49, v47): (f32, f32) = ::armdyn_runtime::libm::sincosf(v46);
        let v48: f32 = v47 * v22;
        let v50: f32 = v49 * v31;
        let v51: f32 = v48 - v50;
        let v52: f32 = v47 * v23;
        let v53: f32 = v49 * v33;
        let v54: f32 = v52 + v53;
        let v55: f32 = v51 * v54;
        let v56: f32 = v49 * v22;
        let v57: f32 = v47 * v31;
        let v58: f32 = v56 + v57;
        let v59: f32 = v47 * v33;
        let v60: f32 = v49 * v23;
        let v61: f32 = v59 - v60;
        let v62: f32 = v58 * v61;
        let v63: f32 = v55 - v62;
        let v64: f32 = qdd[3];
        let v65: f32 = v64 - v29;
        let v66: f32 = v65 * v61;
        let v67: f32 = qd[3];
        let v68: f32 = v67 - v19;
        let v69: f32 = v68 * v54;
        let v70: f32 = v68 * v69;
        let v71: f32 = v66 - v70;
        let v72: f32 = v71 + v58;
        let v73: f32 = v68 * v61;
        let v74: f32 = v68 * v73;
        let v75: f32 = v65 * v54;
        let v76: f32 = v74 + v75;
        let v77: f32 = v51 - v76;
        let v78: f32 = -v65;
        let v79: f32 = v0 * v31;
        let v80: f32 = v30 + v31;
        let v81: f32 = v6 * v49;
        let v82: f32 = v51 * v81;
        let v83: f32 = v6 * v47;
        let v84: f32 = v58 * v83;
        let v85: f32 = v82 - v84;
        let v86: f32 = v65 * v83;
        let v87: f32 = v68 * v81;
        let v88: f32 = v68 * v87;
        let v89: f32 = v86 - v88;
        let v90: f32 = v89 + v58;
        let v91: f32 = v68 * v83;
        let v92: f32 = v68 * v91;
        let v93: f32 = v65 * v81;
        let v94: f32 = v92 + v93;
        let v95: f32 = v51 - v94;
        let v96: f32 = -9.8_f32;
        let v97: f32 = qdd[2];
        let v98: f32 = v96 + v97;
        let v99: f32 = -v58;
        let v100: f32 = -v51;
        let v101: f32 = 0.0_f32;
        [
            [
                v3,
                v4,
                v11,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v1,
                v35,
                v40,
                v45,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v29,
                v35,
                v40,
                v45,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v29,
                v63,
                v72,
                v77,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v78,
            ],
            [
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v79,
                v80,
                v17,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v29,
                v79,
                v80,
                v17,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v29,
                v85,
                v90,
                v95,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v78,
            ],
            [
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v98,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v98,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
            ],
            [
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v99,
                v100,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v65,
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
    /// `params: [f32; 40]`: per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2, inertia about the link frame origin)
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
    pub fn standard_parameters() -> [f32; 40] {
        let v0: f32 = 6.01_f32;
        let v1: f32 = -1.11185_f32;
        let v2: f32 = 0.0_f32;
        let v3: f32 = 0.0132_f32;
        let v4: f32 = 0.38669226_f32;
        let v5: f32 = 0.38639224_f32;
        let v6: f32 = 5.37_f32;
        let v7: f32 = -1.20288_f32;
        let v8: f32 = 0.0234_f32;
        let v9: f32 = 0.39554513_f32;
        let v10: f32 = 0.4252451_f32;
        let v11: f32 = 4.03_f32;
        let v12: f32 = -0.81003_f32;
        let v13: f32 = 0.24301603_f32;
        let v14: f32 = 0.0064_f32;
        let v15: f32 = 0.91_f32;
        let v16: f32 = -0.11102_f32;
        let v17: f32 = 0.01514444_f32;
        let v18: f32 = 0.0025_f32;
        [
            v0,
            v1,
            v2,
            v2,
            v3,
            v2,
            v2,
            v4,
            v2,
            v5,
            v6,
            v7,
            v2,
            v2,
            v8,
            v2,
            v2,
            v9,
            v2,
            v10,
            v11,
            v2,
            v2,
            v12,
            v13,
            v2,
            v2,
            v13,
            v2,
            v14,
            v15,
            v2,
            v2,
            v16,
            v17,
            v2,
            v2,
            v17,
            v2,
            v18,
        ]
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
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `poses: [[[L; 4]; 4]; 4]` (4 x 4 x 4, row-major): homogeneous transforms T_0i of the description's frames 1..n in the base frame (m)
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
    pub fn frame_poses<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 4],
    ) -> [[[L; 4]; 4]; 4] {
        let v0: L = q[0];
        let (v2, v1): (L, L) = L::sincos(v0);
        let v3: L = -v2;
        let v4: L = L::splat(0.0_f64);
        let v5: L = L::splat(0.4_f64);
        let v6: L = v5 * v1;
        let v7: L = v5 * v2;
        let v8: L = L::splat(1.0_f64);
        let v9: L = L::splat(0.5_f64);
        let v10: L = q[1];
        let (v13, v11): (L, L) = L::sincos(v10);
        let v12: L = v1 * v11;
        let v14: L = v2 * v13;
        let v15: L = v12 - v14;
        let v16: L = v1 * v13;
        let v17: L = v2 * v11;
        let v18: L = v16 + v17;
        let v19: L = v5 * v11;
        let v20: L = v1 * v19;
        let v21: L = v5 * v13;
        let v22: L = v2 * v21;
        let v23: L = v20 - v22;
        let v24: L = v6 + v23;
        let v25: L = v17 + v16;
        let v26: L = v14 - v12;
        let v27: L = v2 * v19;
        let v28: L = v1 * v21;
        let v29: L = v27 + v28;
        let v30: L = v7 + v29;
        let v31: L = -L::splat(1.0_f64);
        let v32: L = q[2];
        let v33: L = v9 - v32;
        let v34: L = q[3];
        let (v37, v35): (L, L) = L::sincos(v34);
        let v36: L = v15 * v35;
        let v38: L = v18 * v37;
        let v39: L = v36 + v38;
        let v40: L = v18 * v35;
        let v41: L = v15 * v37;
        let v42: L = v40 - v41;
        let v43: L = v25 * v35;
        let v44: L = v26 * v37;
        let v45: L = v43 + v44;
        let v46: L = v26 * v35;
        let v47: L = v25 * v37;
        let v48: L = v46 - v47;
        let v49: L = -L::splat(0.15_f64);
        let v50: L = v33 + v49;
        [
            [[v1, v3, v4, v6], [v2, v1, v4, v7], [v4, v4, v8, v9], [v4, v4, v4, v8]],
            [
                [v15, v18, v4, v24],
                [v25, v26, v4, v30],
                [v4, v4, v31, v9],
                [v4, v4, v4, v8],
            ],
            [
                [v15, v18, v4, v24],
                [v25, v26, v4, v30],
                [v4, v4, v31, v33],
                [v4, v4, v4, v8],
            ],
            [
                [v39, v42, v4, v24],
                [v45, v48, v4, v30],
                [v4, v4, v31, v50],
                [v4, v4, v4, v8],
            ],
        ]
    }
    /// End-effector pose, forward kinematics `T_0n` (thesis eq. 3.7).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `pose: [[L; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the base frame (m)
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
    pub fn end_effector_pose<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 4],
    ) -> [[L; 4]; 4] {
        let v0: L = q[3];
        let (v5, v1): (L, L) = L::sincos(v0);
        let v2: L = q[1];
        let (v6, v3): (L, L) = L::sincos(v2);
        let v4: L = v1 * v3;
        let v7: L = v5 * v6;
        let v8: L = v4 + v7;
        let v9: L = q[0];
        let (v15, v10): (L, L) = L::sincos(v9);
        let v11: L = v8 * v10;
        let v12: L = v5 * v3;
        let v13: L = v1 * v6;
        let v14: L = v12 - v13;
        let v16: L = v14 * v15;
        let v17: L = v11 + v16;
        let v18: L = v13 - v12;
        let v19: L = v18 * v10;
        let v20: L = v8 * v15;
        let v21: L = v19 + v20;
        let v22: L = L::splat(0.0_f64);
        let v23: L = L::splat(0.4_f64);
        let v24: L = v23 * v3;
        let v25: L = v23 + v24;
        let v26: L = v25 * v10;
        let v27: L = v23 * v6;
        let v28: L = v27 * v15;
        let v29: L = v26 - v28;
        let v30: L = v18 * v15;
        let v31: L = v30 - v11;
        let v32: L = v27 * v10;
        let v33: L = v25 * v15;
        let v34: L = v32 + v33;
        let v35: L = -L::splat(1.0_f64);
        let v36: L = L::splat(0.35_f64);
        let v37: L = q[2];
        let v38: L = v36 - v37;
        let v39: L = L::splat(1.0_f64);
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
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian: [[L; 4]; 6]` (6 x 4, row-major): rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame
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
    pub fn jacobian<L: ::armdyn_runtime::lanes::Lane>(q: &[L; 4]) -> [[L; 4]; 6] {
        let v0: L = L::splat(0.4_f64);
        let v1: L = q[0];
        let (v2, v8): (L, L) = L::sincos(v1);
        let v3: L = v0 * v2;
        let v4: L = q[1];
        let (v9, v5): (L, L) = L::sincos(v4);
        let v6: L = v0 * v5;
        let v7: L = v2 * v6;
        let v10: L = v0 * v9;
        let v11: L = v8 * v10;
        let v12: L = v7 + v11;
        let v13: L = v3 + v12;
        let v14: L = -v13;
        let v15: L = -v12;
        let v16: L = L::splat(0.0_f64);
        let v17: L = v0 * v8;
        let v18: L = v8 * v6;
        let v19: L = v2 * v10;
        let v20: L = v18 - v19;
        let v21: L = v17 + v20;
        let v22: L = -L::splat(1.0_f64);
        let v23: L = L::splat(1.0_f64);
        [
            [v14, v15, v16, v16],
            [v21, v20, v16, v16],
            [v16, v16, v22, v16],
            [v16, v16, v16, v16],
            [v16, v16, v16, v16],
            [v23, v23, v16, v22],
        ]
    }
    /// Jacobian and tool position in one pass: `[J | p; 0]`, row r is `[J_r0, ..., J_r(n-1), p_r]` with `J` the geometric Jacobian of `jacobian` and `p` the end-effector origin of `end_effector_pose` (rows 0-2; the last column of rows 3-5 is 0), the same operations as those two functions (bit-identical results), with common subexpressions, sin/cos included, computed once for both and the pose's rotation not computed.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian_and_position: [[L; 5]; 6]` (6 x 5, row-major): rows `[J(q) | p(q); 0]`: the geometric Jacobian of `jacobian` (rows vx vy vz per unit joint velocity, then wx wy wz, base frame), then the end-effector origin (m, base frame) in rows 0-2 of the last column, 0 in rows 3-5
    ///
    /// Operation count: 22 floating-point operations, 4 trig calls.
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
        q: &[L; 4],
    ) -> [[L; 5]; 6] {
        let v0: L = L::splat(0.4_f64);
        let v1: L = q[0];
        let (v2, v8): (L, L) = L::sincos(v1);
        let v3: L = v0 * v2;
        let v4: L = q[1];
        let (v9, v5): (L, L) = L::sincos(v4);
        let v6: L = v0 * v5;
        let v7: L = v2 * v6;
        let v10: L = v0 * v9;
        let v11: L = v8 * v10;
        let v12: L = v7 + v11;
        let v13: L = v3 + v12;
        let v14: L = -v13;
        let v15: L = -v12;
        let v16: L = L::splat(0.0_f64);
        let v17: L = v0 + v6;
        let v18: L = v17 * v8;
        let v19: L = v10 * v2;
        let v20: L = v18 - v19;
        let v21: L = v0 * v8;
        let v22: L = v8 * v6;
        let v23: L = v2 * v10;
        let v24: L = v22 - v23;
        let v25: L = v21 + v24;
        let v26: L = v10 * v8;
        let v27: L = v17 * v2;
        let v28: L = v26 + v27;
        let v29: L = -L::splat(1.0_f64);
        let v30: L = L::splat(0.35_f64);
        let v31: L = q[2];
        let v32: L = v30 - v31;
        let v33: L = L::splat(1.0_f64);
        [
            [v14, v15, v16, v16, v20],
            [v25, v24, v16, v16, v28],
            [v16, v16, v29, v16, v32],
            [v16, v16, v16, v16, v16],
            [v16, v16, v16, v16, v16],
            [v33, v33, v16, v29, v16],
        ]
    }
    /// Acceleration term of the end-effector twist: `d/dt (J qd) = J qdd + Jdot qd`.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 4]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `jdot_qd: [L; 6]`: Jdot(q, qd) qd: m/s^2 (rows 0-2) and rad/s^2 (rows 3-5), base frame
    ///
    /// Operation count: 29 floating-point operations, 4 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jdot_qd<L: ::armdyn_runtime::lanes::Lane>(q: &[L; 4], qd: &[L; 4]) -> [L; 6] {
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
        let v22: L = v19 * v7;
        let v23: L = v18 + v22;
        let v24: L = v23 * v9;
        let v25: L = v21 - v24;
        let v26: L = v25 * v17;
        let v27: L = v14 + v26;
        let v28: L = v3 * v9;
        let v29: L = v8 * v5;
        let v30: L = v28 + v29;
        let v31: L = v30 * v12;
        let v32: L = v31 * v12;
        let v33: L = v20 * v9;
        let v34: L = v23 * v5;
        let v35: L = v33 + v34;
        let v36: L = v35 * v17;
        let v37: L = v32 + v36;
        let v38: L = -v37;
        let v39: L = L::splat(0.0_f64);
        [v27, v38, v39, v39, v39, v39]
    }
    /// Partial derivatives of the geometric Jacobian, `d J / d q_k` for each joint k: `Jdot = sum_k d J/d q_k qd_k`, and `d (J^T f)/d q_k = (d J/d q_k)^T f` for a tool wrench f.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian_derivatives: [[[L; 4]; 6]; 4]` (4 x 6 x 4, row-major): `[k][r][c] = d J_rc / d q_k`, the partial derivatives of `jacobian` (m/rad or 1/rad per row kind; per m for prismatic joints)
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
        q: &[L; 4],
    ) -> [[[L; 4]; 6]; 4] {
        let v0: L = L::splat(0.4_f64);
        let v1: L = q[1];
        let (v2, v8): (L, L) = L::sincos(v1);
        let v3: L = v0 * v2;
        let v4: L = q[0];
        let (v5, v11): (L, L) = L::sincos(v4);
        let v6: L = v3 * v5;
        let v7: L = -L::splat(0.4_f64);
        let v9: L = v0 * v8;
        let v10: L = v7 - v9;
        let v12: L = v10 * v11;
        let v13: L = v6 + v12;
        let v14: L = v9 * v11;
        let v15: L = v6 - v14;
        let v16: L = L::splat(0.0_f64);
        let v17: L = v10 * v5;
        let v18: L = v3 * v11;
        let v19: L = v17 - v18;
        let v20: L = v9 * v5;
        let v21: L = v18 + v20;
        let v22: L = -v21;
        [
            [
                [v13, v15, v16, v16],
                [v19, v22, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
            ],
            [
                [v15, v15, v16, v16],
                [v22, v22, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
            ],
            [
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
            ],
            [
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
                [v16, v16, v16, v16],
            ],
        ]
    }
    /// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `mass_matrix: [[L; 4]; 4]` (4 x 4, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
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
    pub fn mass_matrix<L: ::armdyn_runtime::lanes::Lane>(q: &[L; 4]) -> [[L; 4]; 4] {
        let v0: L = L::splat(3.22955337_f64);
        let v1: L = L::splat(2.336896_f64);
        let v2: L = q[1];
        let v3: L = L::cos(v2);
        let v4: L = v1 * v3;
        let v5: L = v0 + v4;
        let v6: L = L::splat(1.12144112_f64);
        let v7: L = L::splat(1.168448_f64);
        let v8: L = v7 * v3;
        let v9: L = v6 + v8;
        let v10: L = L::splat(0.0_f64);
        let v11: L = -L::splat(0.0025_f64);
        let v12: L = L::splat(4.94_f64);
        let v13: L = L::splat(0.0025_f64);
        [
            [v5, v9, v10, v11],
            [v9, v6, v10, v11],
            [v10, v10, v12, v10],
            [v11, v11, v10, v13],
        ]
    }
    /// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 4]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis_matrix: [[L; 4]; 4]` (4 x 4, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
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
        q: &[L; 4],
        qd: &[L; 4],
    ) -> [[L; 4]; 4] {
        let v0: L = L::splat(1.168448_f64);
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
        let v12: L = L::splat(0.0_f64);
        let v13: L = v8 * v4;
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
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 4]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis: [L; 4]`: c(q, qd) = C(q, qd) qd (N m or N)
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
        q: &[L; 4],
        qd: &[L; 4],
    ) -> [L; 4] {
        let v0: L = L::splat(1.168448_f64);
        let v1: L = qd[1];
        let v2: L = v0 * v1;
        let v3: L = L::splat(2.336896_f64);
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
        let v15: L = L::splat(0.0_f64);
        [v11, v14, v15, v15]
    }
    /// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `gravity: [L; 4]`: g(q), joint torques (N m) or forces (N) that hold the robot still
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
    pub fn gravity<L: ::armdyn_runtime::lanes::Lane>(q: &[L; 4]) -> [L; 4] {
        let v0: L = L::splat(0.0_f64);
        let v1: L = -L::splat(48.412_f64);
        [v0, v0, v1, v0]
    }
    /// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 4]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[L; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `tau: [L; 4]`: joint torques (N m) or forces (N), no external wrench
    ///
    /// Operation count: 30 floating-point operations, 2 trig calls.
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
        q: &[L; 4],
        qd: &[L; 4],
        qdd: &[L; 4],
    ) -> [L; 4] {
        let v0: L = L::splat(1.12144112_f64);
        let v1: L = qdd[1];
        let v2: L = v0 * v1;
        let v3: L = L::splat(0.0025_f64);
        let v4: L = qdd[3];
        let v5: L = v3 * v4;
        let v6: L = v2 - v5;
        let v7: L = L::splat(3.22955337_f64);
        let v8: L = qdd[0];
        let v9: L = v7 * v8;
        let v10: L = v6 + v9;
        let v11: L = L::splat(1.168448_f64);
        let v12: L = v11 * v1;
        let v13: L = L::splat(2.336896_f64);
        let v14: L = v13 * v8;
        let v15: L = v12 + v14;
        let v16: L = q[1];
        let (v26, v17): (L, L) = L::sincos(v16);
        let v18: L = v15 * v17;
        let v19: L = v10 + v18;
        let v20: L = qd[1];
        let v21: L = v11 * v20;
        let v22: L = qd[0];
        let v23: L = v13 * v22;
        let v24: L = v21 + v23;
        let v25: L = v24 * v20;
        let v27: L = v25 * v26;
        let v28: L = v19 - v27;
        let v29: L = v11 * v22;
        let v30: L = v29 * v22;
        let v31: L = v30 * v26;
        let v32: L = v6 + v31;
        let v33: L = v11 * v17;
        let v34: L = v0 + v33;
        let v35: L = v34 * v8;
        let v36: L = v32 + v35;
        let v37: L = -L::splat(48.412_f64);
        let v38: L = L::splat(4.94_f64);
        let v39: L = qdd[2];
        let v40: L = v38 * v39;
        let v41: L = v37 + v40;
        let v42: L = v3 * v1;
        let v43: L = v5 - v42;
        let v44: L = v3 * v8;
        let v45: L = v43 - v44;
        [v28, v36, v41, v45]
    }
    /// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 4]`: joint velocities qd (rad/s or m/s)
    /// - `tau: &[L; 4]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
    ///
    /// # Output
    ///
    /// `qdd: [L; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// Operation count: 32 floating-point operations, 2 trig calls.
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
        q: &[L; 4],
        qd: &[L; 4],
        tau: &[L; 4],
    ) -> [L; 4] {
        let v0: L = tau[0];
        let v1: L = L::splat(1.168448_f64);
        let v2: L = qd[1];
        let v3: L = v1 * v2;
        let v4: L = L::splat(2.336896_f64);
        let v5: L = qd[0];
        let v6: L = v4 * v5;
        let v7: L = v3 + v6;
        let v8: L = v7 * v2;
        let v9: L = q[1];
        let (v10, v17): (L, L) = L::sincos(v9);
        let v11: L = v8 * v10;
        let v12: L = v0 + v11;
        let v13: L = tau[3];
        let v14: L = v12 + v13;
        let v15: L = L::splat(0.8937020743325618_f64);
        let v16: L = L::splat(1.12144112_f64);
        let v18: L = v1 * v17;
        let v19: L = v16 + v18;
        let v20: L = L::splat(0.0025_f64);
        let v21: L = v19 - v20;
        let v22: L = v15 * v21;
        let v23: L = tau[1];
        let v24: L = v1 * v5;
        let v25: L = v24 * v5;
        let v26: L = v25 * v10;
        let v27: L = v23 - v26;
        let v28: L = v27 + v13;
        let v29: L = v22 * v28;
        let v30: L = v14 - v29;
        let v31: L = L::splat(3.22955337_f64);
        let v32: L = v4 * v17;
        let v33: L = v31 + v32;
        let v34: L = v33 - v20;
        let v35: L = v21 * v22;
        let v36: L = v34 - v35;
        let v37: L = v30 / v36;
        let v38: L = v15 * v28;
        let v39: L = v22 * v37;
        let v40: L = v38 - v39;
        let v41: L = L::splat(0.20242914979757085_f64);
        let v42: L = tau[2];
        let v43: L = -L::splat(48.412_f64);
        let v44: L = v42 - v43;
        let v45: L = v41 * v44;
        let v46: L = L::splat(400.0_f64);
        let v47: L = v46 * v13;
        let v48: L = v47 + v37;
        let v49: L = v48 + v40;
        [v37, v40, v45, v49]
    }
    /// Mass matrix and bias in one pass: row i is `[M_i0, ..., M_i(n-1), c_i + g_i]`, the `M(q)` of `mass_matrix` with the bias `c(q, qd) + g(q)` of `coriolis` and `gravity` as a last column (what Pinocchio's `crba` and `nonLinearEffects` compute together). Common subexpressions, sin/cos included, are computed once for both.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 4]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `mass_matrix_and_bias: [[L; 5]; 4]` (4 x 5, row-major): rows `[M(q) | c(q, qd) + g(q)]`: the symmetric positive definite M (kg m^2, kg m, kg), then the bias (N m or N)
    ///
    /// Operation count: 13 floating-point operations, 2 trig calls.
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
        q: &[L; 4],
        qd: &[L; 4],
    ) -> [[L; 5]; 4] {
        let v0: L = L::splat(3.22955337_f64);
        let v1: L = L::splat(2.336896_f64);
        let v2: L = q[1];
        let (v18, v3): (L, L) = L::sincos(v2);
        let v4: L = v1 * v3;
        let v5: L = v0 + v4;
        let v6: L = L::splat(1.12144112_f64);
        let v7: L = L::splat(1.168448_f64);
        let v8: L = v7 * v3;
        let v9: L = v6 + v8;
        let v10: L = L::splat(0.0_f64);
        let v11: L = -L::splat(0.0025_f64);
        let v12: L = qd[1];
        let v13: L = v7 * v12;
        let v14: L = qd[0];
        let v15: L = v1 * v14;
        let v16: L = v13 + v15;
        let v17: L = v16 * v12;
        let v19: L = v17 * v18;
        let v20: L = -v19;
        let v21: L = v7 * v14;
        let v22: L = v21 * v14;
        let v23: L = v22 * v18;
        let v24: L = L::splat(4.94_f64);
        let v25: L = -L::splat(48.412_f64);
        let v26: L = L::splat(0.0025_f64);
        [
            [v5, v9, v10, v11, v20],
            [v9, v6, v10, v11, v23],
            [v10, v10, v24, v10, v25],
            [v11, v11, v10, v26, v10],
        ]
    }
    /// Derivatives of inverse dynamics: row i is `[d tau_i/d q | d tau_i/d qd | d tau_i/d qdd]` (3n entries; the last block is the mass matrix `M(q)`), the partial derivatives of `inverse_dynamics` (what Pinocchio's `computeRNEADerivatives` computes), generated by algorithmic differentiation of its graph and folded like every other function.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 4]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[L; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `inverse_dynamics_derivatives: [[L; 12]; 4]` (4 x 12, row-major): rows `[d tau/d q | d tau/d qd | M(q)]`: N m/rad, N m s/rad, kg m^2 (N/m, N s/m, kg for prismatic joints)
    ///
    /// Operation count: 29 floating-point operations, 2 trig calls.
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
        q: &[L; 4],
        qd: &[L; 4],
        qdd: &[L; 4],
    ) -> [[L; 12]; 4] {
        let v0: L = L::splat(0.0_f64);
        let v1: L = L::splat(1.168448_f64);
        let v2: L = qdd[1];
        let v3: L = v1 * v2;
        let v4: L = L::splat(2.336896_f64);
        let v5: L = qdd[0];
        let v6: L = v4 * v5;
        let v7: L = v3 + v6;
        let v8: L = q[1];
        let (v9, v17): (L, L) = L::sincos(v8);
        let v10: L = v7 * v9;
        let v11: L = qd[1];
        let v12: L = v1 * v11;
        let v13: L = qd[0];
        let v14: L = v4 * v13;
        let v15: L = v12 + v14;
        let v16: L = v15 * v11;
        let v18: L = v16 * v17;
        let v19: L = v10 + v18;
        let v20: L = -v19;
        let v21: L = v4 * v11;
        let v22: L = v9 * v21;
        let v23: L = -v22;
        let v24: L = v12 + v15;
        let v25: L = v9 * v24;
        let v26: L = -v25;
        let v27: L = L::splat(3.22955337_f64);
        let v28: L = v4 * v17;
        let v29: L = v27 + v28;
        let v30: L = L::splat(1.12144112_f64);
        let v31: L = v1 * v17;
        let v32: L = v30 + v31;
        let v33: L = -L::splat(0.0025_f64);
        let v34: L = v1 * v13;
        let v35: L = v34 * v13;
        let v36: L = v35 * v17;
        let v37: L = v1 * v9;
        let v38: L = v5 * v37;
        let v39: L = v36 - v38;
        let v40: L = v34 + v34;
        let v41: L = v9 * v40;
        let v42: L = L::splat(4.94_f64);
        let v43: L = L::splat(0.0025_f64);
        [
            [v0, v20, v0, v0, v23, v26, v0, v0, v29, v32, v0, v33],
            [v0, v39, v0, v0, v41, v0, v0, v0, v32, v30, v0, v33],
            [v0, v0, v0, v0, v0, v0, v0, v0, v0, v0, v42, v0],
            [v0, v0, v0, v0, v0, v0, v0, v0, v33, v33, v0, v43],
        ]
    }
    /// Derivatives of forward dynamics: row i is `[d qdd_i/d q | d qdd_i/d qd | d qdd_i/d tau]` (3n entries; the last block is `M(q)^-1`), the partial derivatives of `forward_dynamics` (what Pinocchio's `computeABADerivatives` computes): `d qdd/d x = -M^-1 d ID/d x` at `qdd = forward_dynamics(q, qd, tau)` (implicit function theorem on `inverse_dynamics(q, qd, forward_dynamics(q, qd, tau)) = tau`), all 3n right-hand sides solved by one unrolled sparse `L^T D L` factorisation of M. For a tool wrench `f` (`tau - J^T f` into forward dynamics) add `-M^-1 d(J^T f)/d q` to the first block, from `jacobian_derivatives`.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 4]`: joint velocities qd (rad/s or m/s)
    /// - `tau: &[L; 4]`: joint torques (N m) or forces (N)
    ///
    /// # Output
    ///
    /// `forward_dynamics_derivatives: [[L; 12]; 4]` (4 x 12, row-major): rows `[d qdd/d q | d qdd/d qd | M(q)^-1]`: 1/s^2, 1/s, 1/(kg m^2) (per m, per kg for prismatic joints)
    ///
    /// Operation count: 76 floating-point operations, 2 trig calls.
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
        q: &[L; 4],
        qd: &[L; 4],
        tau: &[L; 4],
    ) -> [[L; 12]; 4] {
        let v0: L = L::splat(0.0_f64);
        let v1: L = L::splat(1.168448_f64);
        let v2: L = L::splat(0.8937020743325618_f64);
        let v3: L = tau[1];
        let v4: L = qd[0];
        let v5: L = v1 * v4;
        let v6: L = v5 * v4;
        let v7: L = q[1];
        let (v8, v15): (L, L) = L::sincos(v7);
        let v9: L = v6 * v8;
        let v10: L = v3 - v9;
        let v11: L = tau[3];
        let v12: L = v10 + v11;
        let v13: L = v2 * v12;
        let v14: L = L::splat(1.12144112_f64);
        let v16: L = v1 * v15;
        let v17: L = v14 + v16;
        let v18: L = L::splat(0.0025_f64);
        let v19: L = v17 - v18;
        let v20: L = v2 * v19;
        let v21: L = tau[0];
        let v22: L = qd[1];
        let v23: L = v1 * v22;
        let v24: L = L::splat(2.336896_f64);
        let v25: L = v24 * v4;
        let v26: L = v23 + v25;
        let v27: L = v26 * v22;
        let v28: L = v27 * v8;
        let v29: L = v21 + v28;
        let v30: L = v29 + v11;
        let v31: L = v20 * v12;
        let v32: L = v30 - v31;
        let v33: L = L::splat(3.22955337_f64);
        let v34: L = v24 * v15;
        let v35: L = v33 + v34;
        let v36: L = v35 - v18;
        let v37: L = v19 * v20;
        let v38: L = v36 - v37;
        let v39: L = v32 / v38;
        let v40: L = v20 * v39;
        let v41: L = v13 - v40;
        let v42: L = v1 * v41;
        let v43: L = v24 * v39;
        let v44: L = v42 + v43;
        let v45: L = v44 * v8;
        let v46: L = v27 * v15;
        let v47: L = v45 + v46;
        let v48: L = v6 * v15;
        let v49: L = v1 * v8;
        let v50: L = v39 * v49;
        let v51: L = v48 - v50;
        let v52: L = v20 * v51;
        let v53: L = v47 + v52;
        let v54: L = v53 / v38;
        let v55: L = v24 * v22;
        let v56: L = v8 * v55;
        let v57: L = v5 + v5;
        let v58: L = v8 * v57;
        let v59: L = v20 * v58;
        let v60: L = v56 + v59;
        let v61: L = v60 / v38;
        let v62: L = v23 + v26;
        let v63: L = v8 * v62;
        let v64: L = v63 / v38;
        let v65: L = L::splat(1.0_f64) / v38;
        let v66: L = v20 / v38;
        let v67: L = -v66;
        let v68: L = L::splat(1.0_f64);
        let v69: L = v68 - v20;
        let v70: L = v69 / v38;
        let v71: L = v2 * v51;
        let v72: L = v20 * v54;
        let v73: L = v71 + v72;
        let v74: L = -v73;
        let v75: L = v2 * v58;
        let v76: L = v20 * v61;
        let v77: L = v75 + v76;
        let v78: L = -v77;
        let v79: L = v20 * v64;
        let v80: L = -v79;
        let v81: L = v20 * v66;
        let v82: L = v2 + v81;
        let v83: L = v20 * v70;
        let v84: L = v2 - v83;
        let v85: L = L::splat(0.20242914979757085_f64);
        let v86: L = v54 - v73;
        let v87: L = v61 - v77;
        let v88: L = v64 - v79;
        let v89: L = v65 - v66;
        let v90: L = v82 - v66;
        let v91: L = L::splat(400.0_f64);
        let v92: L = v91 + v70;
        let v93: L = v92 + v84;
        [
            [v0, v54, v0, v0, v61, v64, v0, v0, v65, v67, v0, v70],
            [v0, v74, v0, v0, v78, v80, v0, v0, v67, v82, v0, v84],
            [v0, v0, v0, v0, v0, v0, v0, v0, v0, v0, v85, v0],
            [v0, v86, v0, v0, v87, v88, v0, v0, v89, v90, v0, v93],
        ]
    }
    /// Dynamic regressor: `inverse_dynamics(q, qd, qdd) = Y(q, qd, qdd) * standard_parameters()`.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 4]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[L; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `regressor: [[L; 40]; 4]` (4 x 40, row-major): Y(q, qd, qdd), columns in the order of `standard_parameters`
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
    pub fn regressor<L: ::armdyn_runtime::lanes::Lane>(
        q: &[L; 4],
        qd: &[L; 4],
        qdd: &[L; 4],
    ) -> [[L; 40]; 4] {
        let v0: L = L::splat(0.4_f64);
        let v1: L = qdd[0];
        let v2: L = v0 * v1;
        let v3: L = v0 * v2;
        let v4: L = v2 + v2;
        let v5: L = qd[0];
        let v6: L = -L::splat(0.4_f64);
        let v7: L = v6 * v5;
        let v8: L = v5 * v7;
        let v9: L = v0 * v5;
        let v10: L = v5 * v9;
        let v11: L = v8 + v10;
        let v12: L = q[1];
        let (v13, v15): (L, L) = L::sincos(v12);
        let v14: L = v13 * v2;
        let v16: L = v15 * v10;
        let v17: L = v14 - v16;
        let v18: L = qd[1];
        let v19: L = v5 + v18;
        let v20: L = v0 * v19;
        let v21: L = v19 * v20;
        let v22: L = v17 - v21;
        let v23: L = v0 * v13;
        let v24: L = v22 * v23;
        let v25: L = v13 * v10;
        let v26: L = v15 * v2;
        let v27: L = v25 + v26;
        let v28: L = qdd[1];
        let v29: L = v1 + v28;
        let v30: L = v0 * v29;
        let v31: L = v27 + v30;
        let v32: L = v6 * v15;
        let v33: L = v32 + v6;
        let v34: L = v31 * v33;
        let v35: L = v24 - v34;
        let v36: L = v19 * v23;
        let v37: L = v19 * v36;
        let v38: L = v29 * v33;
        let v39: L = v37 + v38;
        let v40: L = v31 - v39;
        let v41: L = v29 * v23;
        let v42: L = v19 * v33;
        let v43: L = v19 * v42;
        let v44: L = v41 - v43;
        let v45: L = v44 + v22;
        let v46: L = q[3];
        let (v49, v47): (L, L) = L::sincos(v46);
        let v48: L = v47 * v22;
        let v50: L = v49 * v31;
        let v51: L = v48 - v50;
        let v52: L = v47 * v23;
        let v53: L = v49 * v33;
        let v54: L = v52 + v53;
        let v55: L = v51 * v54;
        let v56: L = v49 * v22;
        let v57: L = v47 * v31;
        let v58: L = v56 + v57;
        let v59: L = v47 * v33;
        let v60: L = v49 * v23;
        let v61: L = v59 - v60;
        let v62: L = v58 * v61;
        let v63: L = v55 - v62;
        let v64: L = qdd[3];
        let v65: L = v64 - v29;
        let v66: L = v65 * v61;
        let v67: L = qd[3];
        let v68: L = v67 - v19;
        let v69: L = v68 * v54;
        let v70: L = v68 * v69;
        let v71: L = v66 - v70;
        let v72: L = v71 + v58;
        let v73: L = v68 * v61;
        let v74: L = v68 * v73;
        let v75: L = v65 * v54;
        let v76: L = v74 + v75;
        let v77: L = v51 - v76;
        let v78: L = -v65;
        let v79: L = v0 * v31;
        let v80: L = v30 + v31;
        let v81: L = v6 * v49;
        let v82: L = v51 * v81;
        let v83: L = v6 * v47;
        let v84: L = v58 * v83;
        let v85: L = v82 - v84;
        let v86: L = v65 * v83;
        let v87: L = v68 * v81;
        let v88: L = v68 * v87;
        let v89: L = v86 - v88;
        let v90: L = v89 + v58;
        let v91: L = v68 * v83;
        let v92: L = v68 * v91;
        let v93: L = v65 * v81;
        let v94: L = v92 + v93;
        let v95: L = v51 - v94;
        let v96: L = -L::splat(9.8_f64);
        let v97: L = qdd[2];
        let v98: L = v96 + v97;
        let v99: L = -v58;
        let v100: L = -v51;
        let v101: L = L::splat(0.0_f64);
        [
            [
                v3,
                v4,
                v11,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v1,
                v35,
                v40,
                v45,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v29,
                v35,
                v40,
                v45,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v29,
                v63,
                v72,
                v77,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v78,
            ],
            [
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v79,
                v80,
                v17,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v29,
                v79,
                v80,
                v17,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v29,
                v85,
                v90,
                v95,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v78,
            ],
            [
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v98,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v98,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
            ],
            [
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v99,
                v100,
                v101,
                v101,
                v101,
                v101,
                v101,
                v101,
                v65,
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
    /// `params: [L; 40]`: per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2, inertia about the link frame origin)
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
    pub fn standard_parameters<L: ::armdyn_runtime::lanes::Lane>() -> [L; 40] {
        let v0: L = L::splat(6.01_f64);
        let v1: L = -L::splat(1.11185_f64);
        let v2: L = L::splat(0.0_f64);
        let v3: L = L::splat(0.0132_f64);
        let v4: L = L::splat(0.38669225_f64);
        let v5: L = L::splat(0.38639225_f64);
        let v6: L = L::splat(5.37_f64);
        let v7: L = -L::splat(1.20288_f64);
        let v8: L = L::splat(0.0234_f64);
        let v9: L = L::splat(0.39554512_f64);
        let v10: L = L::splat(0.42524512_f64);
        let v11: L = L::splat(4.03_f64);
        let v12: L = -L::splat(0.81003_f64);
        let v13: L = L::splat(0.24301603_f64);
        let v14: L = L::splat(0.0064_f64);
        let v15: L = L::splat(0.91_f64);
        let v16: L = -L::splat(0.11102_f64);
        let v17: L = L::splat(0.01514444_f64);
        let v18: L = L::splat(0.0025_f64);
        [
            v0,
            v1,
            v2,
            v2,
            v3,
            v2,
            v2,
            v4,
            v2,
            v5,
            v6,
            v7,
            v2,
            v2,
            v8,
            v2,
            v2,
            v9,
            v2,
            v10,
            v11,
            v2,
            v2,
            v12,
            v13,
            v2,
            v2,
            v13,
            v2,
            v14,
            v15,
            v2,
            v2,
            v16,
            v17,
            v2,
            v2,
            v17,
            v2,
            v18,
        ]
    }
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/scara.json")
);
