// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `armdyn_derive::robot_model!("models/planar2_parametric.json")` in the `generated` crate,
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
pub const OPERATION_COUNTS: [(&str, u32, u32); 6] = [
    ("mass_matrix", 24, 2),
    ("coriolis_matrix", 21, 2),
    ("coriolis", 22, 2),
    ("gravity", 26, 4),
    ("inverse_dynamics", 57, 4),
    ("forward_dynamics", 77, 4),
];
/// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `params: &[f64; 20]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `mass_matrix: [[f64; 2]; 2]` (2 x 2, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
///
/// Operation count: 24 floating-point operations, 2 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn mass_matrix(q: &[f64; 2], params: &[f64; 20]) -> [[f64; 2]; 2] {
    let v0: f64 = params[19];
    let v1: f64 = 0.8_f64;
    let v2: f64 = params[11];
    let v3: f64 = v1 * v2;
    let v4: f64 = v0 + v3;
    let v5: f64 = 0.41_f64;
    let v6: f64 = params[10];
    let v7: f64 = v5 * v6;
    let v8: f64 = v4 + v7;
    let v9: f64 = params[9];
    let v10: f64 = v8 + v9;
    let v11: f64 = params[1];
    let v12: f64 = v10 + v11;
    let v13: f64 = 0.25_f64;
    let v14: f64 = params[0];
    let v15: f64 = v13 * v14;
    let v16: f64 = v12 + v15;
    let v17: f64 = params[12];
    let v18: f64 = q[1];
    let (v19, v25): (f64, f64) = ::armdyn_runtime::libm::sincos(v18);
    let v20: f64 = v17 * v19;
    let v21: f64 = v16 - v20;
    let v22: f64 = 0.4_f64;
    let v23: f64 = v22 * v6;
    let v24: f64 = v2 + v23;
    let v26: f64 = v24 * v25;
    let v27: f64 = v21 + v26;
    let v28: f64 = 0.16_f64;
    let v29: f64 = v28 * v6;
    let v30: f64 = v4 + v29;
    let v31: f64 = 0.5_f64;
    let v32: f64 = v31 * v17;
    let v33: f64 = v32 * v19;
    let v34: f64 = v30 - v33;
    let v35: f64 = v31 * v2;
    let v36: f64 = 0.2_f64;
    let v37: f64 = v36 * v6;
    let v38: f64 = v35 + v37;
    let v39: f64 = v38 * v25;
    let v40: f64 = v34 + v39;
    [[v27, v40], [v40, v30]]
}
/// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
/// - `params: &[f64; 20]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `coriolis_matrix: [[f64; 2]; 2]` (2 x 2, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
///
/// Operation count: 21 floating-point operations, 2 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn coriolis_matrix(
    q: &[f64; 2],
    qd: &[f64; 2],
    params: &[f64; 20],
) -> [[f64; 2]; 2] {
    let v0: f64 = 0.5_f64;
    let v1: f64 = params[12];
    let v2: f64 = v0 * v1;
    let v3: f64 = q[1];
    let (v12, v4): (f64, f64) = ::armdyn_runtime::libm::sincos(v3);
    let v5: f64 = v2 * v4;
    let v6: f64 = params[11];
    let v7: f64 = v0 * v6;
    let v8: f64 = 0.2_f64;
    let v9: f64 = params[10];
    let v10: f64 = v8 * v9;
    let v11: f64 = v7 + v10;
    let v13: f64 = v11 * v12;
    let v14: f64 = v5 + v13;
    let v15: f64 = qd[1];
    let v16: f64 = v14 * v15;
    let v17: f64 = -v16;
    let v18: f64 = v0 * v15;
    let v19: f64 = qd[0];
    let v20: f64 = v0 * v19;
    let v21: f64 = v18 + v20;
    let v22: f64 = v21 * v1;
    let v23: f64 = v22 * v4;
    let v24: f64 = v11 * v15;
    let v25: f64 = v11 * v19;
    let v26: f64 = v24 + v25;
    let v27: f64 = v26 * v12;
    let v28: f64 = v23 + v27;
    let v29: f64 = -v28;
    let v30: f64 = v14 * v19;
    let v31: f64 = 0.0_f64;
    [[v17, v29], [v30, v31]]
}
/// Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53).
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
/// - `params: &[f64; 20]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `coriolis: [f64; 2]`: c(q, qd) = C(q, qd) qd (N m or N)
///
/// Operation count: 22 floating-point operations, 2 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn coriolis(q: &[f64; 2], qd: &[f64; 2], params: &[f64; 20]) -> [f64; 2] {
    let v0: f64 = 0.5_f64;
    let v1: f64 = qd[1];
    let v2: f64 = v0 * v1;
    let v3: f64 = qd[0];
    let v4: f64 = v2 + v3;
    let v5: f64 = params[12];
    let v6: f64 = v4 * v5;
    let v7: f64 = q[1];
    let (v22, v8): (f64, f64) = ::armdyn_runtime::libm::sincos(v7);
    let v9: f64 = v6 * v8;
    let v10: f64 = params[11];
    let v11: f64 = v0 * v10;
    let v12: f64 = 0.2_f64;
    let v13: f64 = params[10];
    let v14: f64 = v12 * v13;
    let v15: f64 = v11 + v14;
    let v16: f64 = v15 * v1;
    let v17: f64 = 0.4_f64;
    let v18: f64 = v17 * v13;
    let v19: f64 = v10 + v18;
    let v20: f64 = v19 * v3;
    let v21: f64 = v16 + v20;
    let v23: f64 = v21 * v22;
    let v24: f64 = v9 + v23;
    let v25: f64 = v24 * v1;
    let v26: f64 = -v25;
    let v27: f64 = v0 * v5;
    let v28: f64 = v27 * v8;
    let v29: f64 = v15 * v22;
    let v30: f64 = v28 + v29;
    let v31: f64 = v30 * v3;
    let v32: f64 = v31 * v3;
    [v26, v32]
}
/// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `params: &[f64; 20]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `gravity: [f64; 2]`: g(q), joint torques (N m) or forces (N) that hold the robot still
///
/// Operation count: 26 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn gravity(q: &[f64; 2], params: &[f64; 20]) -> [f64; 2] {
    let v0: f64 = 4.905_f64;
    let v1: f64 = params[10];
    let v2: f64 = v0 * v1;
    let v3: f64 = 9.81_f64;
    let v4: f64 = params[1];
    let v5: f64 = v3 * v4;
    let v6: f64 = v2 + v5;
    let v7: f64 = params[0];
    let v8: f64 = v0 * v7;
    let v9: f64 = v6 + v8;
    let v10: f64 = params[12];
    let v11: f64 = v3 * v10;
    let v12: f64 = q[1];
    let (v13, v21): (f64, f64) = ::armdyn_runtime::libm::sincos(v12);
    let v14: f64 = v11 * v13;
    let v15: f64 = v9 - v14;
    let v16: f64 = params[11];
    let v17: f64 = v3 * v16;
    let v18: f64 = 3.924_f64;
    let v19: f64 = v18 * v1;
    let v20: f64 = v17 + v19;
    let v22: f64 = v20 * v21;
    let v23: f64 = v15 + v22;
    let v24: f64 = q[0];
    let (v33, v25): (f64, f64) = ::armdyn_runtime::libm::sincos(v24);
    let v26: f64 = v23 * v25;
    let v27: f64 = params[2];
    let v28: f64 = v3 * v27;
    let v29: f64 = v11 * v21;
    let v30: f64 = v28 + v29;
    let v31: f64 = v20 * v13;
    let v32: f64 = v30 + v31;
    let v34: f64 = v32 * v33;
    let v35: f64 = v26 - v34;
    let v36: f64 = v22 - v14;
    let v37: f64 = v36 * v25;
    let v38: f64 = v29 + v31;
    let v39: f64 = v38 * v33;
    let v40: f64 = v37 - v39;
    [v35, v40]
}
/// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
/// - `qdd: &[f64; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
/// - `params: &[f64; 20]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `tau: [f64; 2]`: joint torques (N m) or forces (N), no external wrench
///
/// Operation count: 57 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn inverse_dynamics(
    q: &[f64; 2],
    qd: &[f64; 2],
    qdd: &[f64; 2],
    params: &[f64; 20],
) -> [f64; 2] {
    let v0: f64 = params[9];
    let v1: f64 = qdd[0];
    let v2: f64 = v0 * v1;
    let v3: f64 = params[1];
    let v4: f64 = 9.81_f64;
    let v5: f64 = q[0];
    let (v13, v6): (f64, f64) = ::armdyn_runtime::libm::sincos(v5);
    let v7: f64 = v4 * v6;
    let v8: f64 = 0.5_f64;
    let v9: f64 = v8 * v1;
    let v10: f64 = v7 + v9;
    let v11: f64 = v3 * v10;
    let v12: f64 = params[2];
    let v14: f64 = v4 * v13;
    let v15: f64 = qd[0];
    let v16: f64 = v8 * v15;
    let v17: f64 = v15 * v16;
    let v18: f64 = v14 - v17;
    let v19: f64 = v12 * v18;
    let v20: f64 = v11 - v19;
    let v21: f64 = v2 + v20;
    let v22: f64 = params[19];
    let v23: f64 = qdd[1];
    let v24: f64 = v1 + v23;
    let v25: f64 = v22 * v24;
    let v26: f64 = params[11];
    let v27: f64 = q[1];
    let (v30, v28): (f64, f64) = ::armdyn_runtime::libm::sincos(v27);
    let v29: f64 = v28 * v10;
    let v31: f64 = v30 * v18;
    let v32: f64 = v29 - v31;
    let v33: f64 = 0.4_f64;
    let v34: f64 = v33 * v24;
    let v35: f64 = v32 + v34;
    let v36: f64 = v26 * v35;
    let v37: f64 = params[12];
    let v38: f64 = v28 * v18;
    let v39: f64 = v30 * v10;
    let v40: f64 = v38 + v39;
    let v41: f64 = qd[1];
    let v42: f64 = v15 + v41;
    let v43: f64 = v33 * v42;
    let v44: f64 = v42 * v43;
    let v45: f64 = v40 - v44;
    let v46: f64 = v37 * v45;
    let v47: f64 = v36 - v46;
    let v48: f64 = v25 + v47;
    let v49: f64 = params[10];
    let v50: f64 = v49 * v35;
    let v51: f64 = v24 * v26;
    let v52: f64 = v42 * v37;
    let v53: f64 = v42 * v52;
    let v54: f64 = v51 - v53;
    let v55: f64 = v50 + v54;
    let v56: f64 = v33 * v55;
    let v57: f64 = v48 + v56;
    let v58: f64 = v21 + v57;
    let v59: f64 = params[0];
    let v60: f64 = v59 * v10;
    let v61: f64 = v1 * v3;
    let v62: f64 = v15 * v12;
    let v63: f64 = v15 * v62;
    let v64: f64 = v61 - v63;
    let v65: f64 = v60 + v64;
    let v66: f64 = v49 * v45;
    let v67: f64 = v24 * v37;
    let v68: f64 = v42 * v26;
    let v69: f64 = v42 * v68;
    let v70: f64 = v67 + v69;
    let v71: f64 = v66 - v70;
    let v72: f64 = v30 * v71;
    let v73: f64 = v28 * v55;
    let v74: f64 = v72 + v73;
    let v75: f64 = v65 + v74;
    let v76: f64 = v8 * v75;
    let v77: f64 = v58 + v76;
    [v77, v57]
}
/// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g. The pivots `D_k` of the factorisation depend on `params`, which must therefore give a positive definite mass matrix (any physical parameter set does: positive masses, inertias that satisfy the triangle inequalities); nothing is checked, and parameters that make a pivot zero give a non-finite result.
///
/// # Inputs
///
/// - `q: &[f64; 2]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 2]`: joint velocities qd (rad/s or m/s)
/// - `tau: &[f64; 2]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
/// - `params: &[f64; 20]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `qdd: [f64; 2]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// Operation count: 77 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn forward_dynamics(
    q: &[f64; 2],
    qd: &[f64; 2],
    tau: &[f64; 2],
    params: &[f64; 20],
) -> [f64; 2] {
    let v0: f64 = tau[0];
    let v1: f64 = params[1];
    let v2: f64 = 9.81_f64;
    let v3: f64 = q[0];
    let (v8, v4): (f64, f64) = ::armdyn_runtime::libm::sincos(v3);
    let v5: f64 = v2 * v4;
    let v6: f64 = v1 * v5;
    let v7: f64 = params[2];
    let v9: f64 = v2 * v8;
    let v10: f64 = qd[0];
    let v11: f64 = 0.5_f64;
    let v12: f64 = v11 * v10;
    let v13: f64 = v10 * v12;
    let v14: f64 = v9 - v13;
    let v15: f64 = v7 * v14;
    let v16: f64 = v6 - v15;
    let v17: f64 = params[11];
    let v18: f64 = q[1];
    let (v21, v19): (f64, f64) = ::armdyn_runtime::libm::sincos(v18);
    let v20: f64 = v19 * v5;
    let v22: f64 = v21 * v14;
    let v23: f64 = v20 - v22;
    let v24: f64 = v17 * v23;
    let v25: f64 = params[12];
    let v26: f64 = v19 * v14;
    let v27: f64 = v21 * v5;
    let v28: f64 = v26 + v27;
    let v29: f64 = qd[1];
    let v30: f64 = v10 + v29;
    let v31: f64 = 0.4_f64;
    let v32: f64 = v31 * v30;
    let v33: f64 = v30 * v32;
    let v34: f64 = v28 - v33;
    let v35: f64 = v25 * v34;
    let v36: f64 = v24 - v35;
    let v37: f64 = params[10];
    let v38: f64 = v37 * v23;
    let v39: f64 = v30 * v25;
    let v40: f64 = v30 * v39;
    let v41: f64 = v38 - v40;
    let v42: f64 = v31 * v41;
    let v43: f64 = v36 + v42;
    let v44: f64 = v16 + v43;
    let v45: f64 = params[0];
    let v46: f64 = v45 * v5;
    let v47: f64 = v10 * v7;
    let v48: f64 = v10 * v47;
    let v49: f64 = v46 - v48;
    let v50: f64 = v37 * v34;
    let v51: f64 = v30 * v17;
    let v52: f64 = v30 * v51;
    let v53: f64 = v50 - v52;
    let v54: f64 = v21 * v53;
    let v55: f64 = v19 * v41;
    let v56: f64 = v54 + v55;
    let v57: f64 = v49 + v56;
    let v58: f64 = v11 * v57;
    let v59: f64 = v44 + v58;
    let v60: f64 = v0 - v59;
    let v61: f64 = params[19];
    let v62: f64 = 0.8_f64;
    let v63: f64 = v62 * v17;
    let v64: f64 = v61 + v63;
    let v65: f64 = 0.16_f64;
    let v66: f64 = v65 * v37;
    let v67: f64 = v64 + v66;
    let v68: f64 = v11 * v25;
    let v69: f64 = v68 * v21;
    let v70: f64 = v67 - v69;
    let v71: f64 = v11 * v17;
    let v72: f64 = 0.2_f64;
    let v73: f64 = v72 * v37;
    let v74: f64 = v71 + v73;
    let v75: f64 = v74 * v19;
    let v76: f64 = v70 + v75;
    let v77: f64 = v76 / v67;
    let v78: f64 = tau[1];
    let v79: f64 = v78 - v43;
    let v80: f64 = v77 * v79;
    let v81: f64 = v60 - v80;
    let v82: f64 = 0.41_f64;
    let v83: f64 = v82 * v37;
    let v84: f64 = v64 + v83;
    let v85: f64 = params[9];
    let v86: f64 = v84 + v85;
    let v87: f64 = v86 + v1;
    let v88: f64 = 0.25_f64;
    let v89: f64 = v88 * v45;
    let v90: f64 = v87 + v89;
    let v91: f64 = v25 * v21;
    let v92: f64 = v90 - v91;
    let v93: f64 = v31 * v37;
    let v94: f64 = v17 + v93;
    let v95: f64 = v94 * v19;
    let v96: f64 = v92 + v95;
    let v97: f64 = v76 * v77;
    let v98: f64 = v96 - v97;
    let v99: f64 = v81 / v98;
    let v100: f64 = v79 / v67;
    let v101: f64 = v77 * v99;
    let v102: f64 = v100 - v101;
    [v99, v102]
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/planar2_parametric.json")
);
