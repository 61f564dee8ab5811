// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `armdyn_derive::robot_model!("models/scara_mdh_parametric.json")` in the `generated` crate,
// formatted with prettyplease. Not compiled: for reading and review.

/// Name of the robot (`robot.name` in the model file).
pub const ROBOT_NAME: &str = "scara_mdh";
/// Description of the robot, from the model file.
pub const DESCRIPTION: &str = "The thesis SCARA of scara.toml, in modified (Craig) DH";
/// Degrees of freedom: the number of joints.
pub const DOF: usize = 4;
/// Name and version of the generator that wrote the model file.
pub const GENERATOR: &str = "armdyn-codegen 0.1.0";
/// Version of CasADi the generator used.
pub const CASADI_VERSION: &str = "3.7.2";
/// Robot description file the model was generated from.
pub const SOURCE: &str = "robots/scara_mdh.toml";
/// SHA-256 of the robot description file (64 hex digits).
pub const SOURCE_SHA256: &str = "1de6a7bea59197b216f0be482f8d2ec85f489f80bfc909499f882a796fe0a970";
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
pub const OPERATION_COUNTS: [(&str, u32, u32); 6] = [
    ("mass_matrix", 61, 4),
    ("coriolis_matrix", 104, 4),
    ("coriolis", 67, 4),
    ("gravity", 3, 0),
    ("inverse_dynamics", 100, 4),
    ("forward_dynamics", 160, 4),
];
/// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `params: &[f64; 40]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `mass_matrix: [[f64; 4]; 4]` (4 x 4, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
///
/// Operation count: 61 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn mass_matrix(q: &[f64; 4], params: &[f64; 40]) -> [[f64; 4]; 4] {
    let v0: f64 = params[9];
    let v1: f64 = params[19];
    let v2: f64 = params[29];
    let v3: f64 = params[39];
    let v4: f64 = 0.0225_f64;
    let v5: f64 = params[30];
    let v6: f64 = v4 * v5;
    let v7: f64 = 2.0_f64;
    let v8: f64 = 0.15_f64;
    let v9: f64 = params[33];
    let v10: f64 = v8 * v9;
    let v11: f64 = v7 * v10;
    let v12: f64 = v6 + v11;
    let v13: f64 = v3 + v12;
    let v14: f64 = v13 - v6;
    let v15: f64 = v14 - v10;
    let v16: f64 = v15 - v10;
    let v17: f64 = v2 + v16;
    let v18: f64 = params[20];
    let v19: f64 = v18 + v5;
    let v20: f64 = 0.16000000000000003_f64;
    let v21: f64 = q[2];
    let v22: f64 = v21 * v21;
    let v23: f64 = v20 + v22;
    let v24: f64 = v19 * v23;
    let v25: f64 = 0.4_f64;
    let v26: f64 = params[21];
    let v27: f64 = q[3];
    let (v31, v28): (f64, f64) = ::armdyn_runtime::libm::sincos(v27);
    let v29: f64 = params[31];
    let v30: f64 = v28 * v29;
    let v32: f64 = params[32];
    let v33: f64 = v31 * v32;
    let v34: f64 = v30 - v33;
    let v35: f64 = v26 + v34;
    let v36: f64 = v25 * v35;
    let v37: f64 = params[23];
    let v38: f64 = v8 * v5;
    let v39: f64 = v9 + v38;
    let v40: f64 = v37 + v39;
    let v41: f64 = v40 * v21;
    let v42: f64 = v36 + v41;
    let v43: f64 = v7 * v42;
    let v44: f64 = v24 + v43;
    let v45: f64 = v17 + v44;
    let v46: f64 = v19 * v22;
    let v47: f64 = v45 - v46;
    let v48: f64 = v47 - v41;
    let v49: f64 = v21 * v40;
    let v50: f64 = v48 - v49;
    let v51: f64 = v1 + v50;
    let v52: f64 = params[10];
    let v53: f64 = v52 + v19;
    let v54: f64 = v20 * v53;
    let v55: f64 = q[1];
    let (v62, v56): (f64, f64) = ::armdyn_runtime::libm::sincos(v55);
    let v57: f64 = params[11];
    let v58: f64 = v25 * v19;
    let v59: f64 = v35 + v58;
    let v60: f64 = v57 + v59;
    let v61: f64 = v56 * v60;
    let v63: f64 = params[12];
    let v64: f64 = params[22];
    let v65: f64 = v31 * v29;
    let v66: f64 = v28 * v32;
    let v67: f64 = v65 + v66;
    let v68: f64 = v64 + v67;
    let v69: f64 = v63 - v68;
    let v70: f64 = v62 * v69;
    let v71: f64 = v61 - v70;
    let v72: f64 = v25 * v71;
    let v73: f64 = v7 * v72;
    let v74: f64 = v54 + v73;
    let v75: f64 = v51 + v74;
    let v76: f64 = v0 + v75;
    let v77: f64 = v51 + v72;
    let v78: f64 = 0.0_f64;
    let v79: f64 = v25 * v34;
    let v80: f64 = v3 + v79;
    let v81: f64 = v66 + v65;
    let v82: f64 = v62 * v81;
    let v83: f64 = v56 * v34;
    let v84: f64 = v82 + v83;
    let v85: f64 = v25 * v84;
    let v86: f64 = v80 + v85;
    let v87: f64 = -v86;
    let v88: f64 = -v80;
    [
        [v76, v77, v78, v87],
        [v77, v51, v78, v88],
        [v78, v78, v19, v78],
        [v87, v88, v78, v3],
    ]
}
/// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
/// - `params: &[f64; 40]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `coriolis_matrix: [[f64; 4]; 4]` (4 x 4, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
///
/// Operation count: 104 floating-point operations, 4 trig calls.
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
    q: &[f64; 4],
    qd: &[f64; 4],
    params: &[f64; 40],
) -> [[f64; 4]; 4] {
    let v0: f64 = 0.4_f64;
    let v1: f64 = params[31];
    let v2: f64 = v0 * v1;
    let v3: f64 = q[1];
    let (v4, v7): (f64, f64) = ::armdyn_runtime::libm::sincos(v3);
    let v5: f64 = v2 * v4;
    let v6: f64 = -0.4_f64;
    let v8: f64 = v0 * v7;
    let v9: f64 = v6 - v8;
    let v10: f64 = params[32];
    let v11: f64 = v9 * v10;
    let v12: f64 = v5 + v11;
    let v13: f64 = q[3];
    let (v20, v14): (f64, f64) = ::armdyn_runtime::libm::sincos(v13);
    let v15: f64 = v12 * v14;
    let v16: f64 = v9 * v1;
    let v17: f64 = v0 * v10;
    let v18: f64 = v17 * v4;
    let v19: f64 = v16 - v18;
    let v21: f64 = v19 * v20;
    let v22: f64 = v15 + v21;
    let v23: f64 = qd[3];
    let v24: f64 = v22 * v23;
    let v25: f64 = params[22];
    let v26: f64 = v0 * v25;
    let v27: f64 = params[12];
    let v28: f64 = v0 * v27;
    let v29: f64 = v26 - v28;
    let v30: f64 = v17 * v14;
    let v31: f64 = v29 + v30;
    let v32: f64 = v2 * v20;
    let v33: f64 = v31 + v32;
    let v34: f64 = v33 * v7;
    let v35: f64 = v17 * v20;
    let v36: f64 = 0.16_f64;
    let v37: f64 = params[30];
    let v38: f64 = v36 * v37;
    let v39: f64 = params[21];
    let v40: f64 = v0 * v39;
    let v41: f64 = v38 + v40;
    let v42: f64 = params[20];
    let v43: f64 = v36 * v42;
    let v44: f64 = v41 + v43;
    let v45: f64 = params[11];
    let v46: f64 = v0 * v45;
    let v47: f64 = v44 + v46;
    let v48: f64 = v2 * v14;
    let v49: f64 = v47 + v48;
    let v50: f64 = v35 - v49;
    let v51: f64 = v50 * v4;
    let v52: f64 = v34 + v51;
    let v53: f64 = qd[1];
    let v54: f64 = v52 * v53;
    let v55: f64 = v24 + v54;
    let v56: f64 = v33 * v53;
    let v57: f64 = v30 + v32;
    let v58: f64 = v57 * v23;
    let v59: f64 = v56 - v58;
    let v60: f64 = qd[0];
    let v61: f64 = v33 * v60;
    let v62: f64 = v59 + v61;
    let v63: f64 = v62 * v7;
    let v64: f64 = v63 - v58;
    let v65: f64 = v48 - v35;
    let v66: f64 = v65 * v23;
    let v67: f64 = v50 * v53;
    let v68: f64 = v66 + v67;
    let v69: f64 = v50 * v60;
    let v70: f64 = v68 + v69;
    let v71: f64 = v70 * v4;
    let v72: f64 = v64 + v71;
    let v73: f64 = 0.0_f64;
    let v74: f64 = v0 * v53;
    let v75: f64 = v0 * v23;
    let v76: f64 = v74 - v75;
    let v77: f64 = v0 * v60;
    let v78: f64 = v76 + v77;
    let v79: f64 = v78 * v1;
    let v80: f64 = v79 * v4;
    let v81: f64 = v75 - v74;
    let v82: f64 = v81 - v77;
    let v83: f64 = v82 * v7;
    let v84: f64 = v82 + v83;
    let v85: f64 = v84 * v10;
    let v86: f64 = v80 + v85;
    let v87: f64 = v86 * v14;
    let v88: f64 = v82 * v10;
    let v89: f64 = v88 * v4;
    let v90: f64 = v84 * v1;
    let v91: f64 = v89 + v90;
    let v92: f64 = v91 * v20;
    let v93: f64 = v87 + v92;
    let v94: f64 = v28 - v26;
    let v95: f64 = v94 - v30;
    let v96: f64 = v95 - v32;
    let v97: f64 = v96 * v7;
    let v98: f64 = v49 - v35;
    let v99: f64 = v98 * v4;
    let v100: f64 = v97 + v99;
    let v101: f64 = v100 * v60;
    let v102: f64 = v101 - v58;
    let v103: f64 = -v58;
    let v104: f64 = v88 * v14;
    let v105: f64 = v82 * v1;
    let v106: f64 = v105 * v20;
    let v107: f64 = v104 + v106;
    let v108: f64 = v57 * v53;
    let v109: f64 = v0 + v8;
    let v110: f64 = v109 * v10;
    let v111: f64 = v110 - v5;
    let v112: f64 = v111 * v14;
    let v113: f64 = v109 * v1;
    let v114: f64 = v18 + v113;
    let v115: f64 = v114 * v20;
    let v116: f64 = v112 + v115;
    let v117: f64 = v116 * v60;
    let v118: f64 = v108 + v117;
    let v119: f64 = v74 + v77;
    let v120: f64 = v119 * v10;
    let v121: f64 = v120 * v14;
    let v122: f64 = v119 * v1;
    let v123: f64 = v122 * v20;
    let v124: f64 = v121 + v123;
    [
        [v55, v72, v73, v93],
        [v102, v103, v73, v107],
        [v73, v73, v73, v73],
        [v118, v124, v73, v73],
    ]
}
/// Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53).
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
/// - `params: &[f64; 40]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `coriolis: [f64; 4]`: c(q, qd) = C(q, qd) qd (N m or N)
///
/// Operation count: 67 floating-point operations, 4 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn coriolis(q: &[f64; 4], qd: &[f64; 4], params: &[f64; 40]) -> [f64; 4] {
    let v0: f64 = params[11];
    let v1: f64 = q[1];
    let (v2, v10): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
    let v3: f64 = qd[0];
    let v4: f64 = 0.4_f64;
    let v5: f64 = v4 * v3;
    let v6: f64 = v3 * v5;
    let v7: f64 = v2 * v6;
    let v8: f64 = v0 * v7;
    let v9: f64 = params[12];
    let v11: f64 = v10 * v6;
    let v12: f64 = v9 * v11;
    let v13: f64 = v8 + v12;
    let v14: f64 = params[22];
    let v15: f64 = qd[1];
    let v16: f64 = v3 + v15;
    let v17: f64 = v4 * v16;
    let v18: f64 = v16 * v17;
    let v19: f64 = v11 + v18;
    let v20: f64 = v14 * v19;
    let v21: f64 = params[21];
    let v22: f64 = v21 * v7;
    let v23: f64 = v20 - v22;
    let v24: f64 = params[31];
    let v25: f64 = q[3];
    let (v26, v28): (f64, f64) = ::armdyn_runtime::libm::sincos(v25);
    let v27: f64 = v26 * v19;
    let v29: f64 = v28 * v7;
    let v30: f64 = v27 - v29;
    let v31: f64 = v24 * v30;
    let v32: f64 = params[32];
    let v33: f64 = v28 * v19;
    let v34: f64 = v26 * v7;
    let v35: f64 = v33 + v34;
    let v36: f64 = v32 * v35;
    let v37: f64 = v31 + v36;
    let v38: f64 = v23 + v37;
    let v39: f64 = v13 - v38;
    let v40: f64 = params[30];
    let v41: f64 = v40 * v30;
    let v42: f64 = qd[3];
    let v43: f64 = v42 - v16;
    let v44: f64 = v43 * v32;
    let v45: f64 = v43 * v44;
    let v46: f64 = v41 - v45;
    let v47: f64 = v28 * v46;
    let v48: f64 = v40 * v35;
    let v49: f64 = v43 * v24;
    let v50: f64 = v43 * v49;
    let v51: f64 = v48 + v50;
    let v52: f64 = v26 * v51;
    let v53: f64 = v47 - v52;
    let v54: f64 = params[20];
    let v55: f64 = v54 * v7;
    let v56: f64 = v16 * v14;
    let v57: f64 = v16 * v56;
    let v58: f64 = v55 + v57;
    let v59: f64 = v53 - v58;
    let v60: f64 = v4 * v59;
    let v61: f64 = v39 - v60;
    let v62: f64 = params[10];
    let v63: f64 = v62 * v7;
    let v64: f64 = v16 * v9;
    let v65: f64 = v16 * v64;
    let v66: f64 = v63 - v65;
    let v67: f64 = v66 - v59;
    let v68: f64 = v10 * v67;
    let v69: f64 = v62 * v11;
    let v70: f64 = v16 * v0;
    let v71: f64 = v16 * v70;
    let v72: f64 = v69 + v71;
    let v73: f64 = v54 * v19;
    let v74: f64 = v16 * v21;
    let v75: f64 = v16 * v74;
    let v76: f64 = v73 + v75;
    let v77: f64 = v28 * v51;
    let v78: f64 = v26 * v46;
    let v79: f64 = v77 + v78;
    let v80: f64 = v76 + v79;
    let v81: f64 = v72 + v80;
    let v82: f64 = v2 * v81;
    let v83: f64 = v68 - v82;
    let v84: f64 = v4 * v83;
    let v85: f64 = v61 + v84;
    let v86: f64 = 0.0_f64;
    [v85, v61, v86, v37]
}
/// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `params: &[f64; 40]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `gravity: [f64; 4]`: g(q), joint torques (N m) or forces (N) that hold the robot still
///
/// Operation count: 3 floating-point operations, 0 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn gravity(q: &[f64; 4], params: &[f64; 40]) -> [f64; 4] {
    let v0: f64 = 0.0_f64;
    let v1: f64 = -9.8_f64;
    let v2: f64 = params[20];
    let v3: f64 = v1 * v2;
    let v4: f64 = params[30];
    let v5: f64 = v1 * v4;
    let v6: f64 = v3 + v5;
    [v0, v0, v6, v0]
}
/// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
/// - `qdd: &[f64; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
/// - `params: &[f64; 40]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `tau: [f64; 4]`: joint torques (N m) or forces (N), no external wrench
///
/// Operation count: 100 floating-point operations, 4 trig calls.
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
    q: &[f64; 4],
    qd: &[f64; 4],
    qdd: &[f64; 4],
    params: &[f64; 40],
) -> [f64; 4] {
    let v0: f64 = params[9];
    let v1: f64 = qdd[0];
    let v2: f64 = v0 * v1;
    let v3: f64 = params[19];
    let v4: f64 = qdd[1];
    let v5: f64 = v1 + v4;
    let v6: f64 = v3 * v5;
    let v7: f64 = params[11];
    let v8: f64 = q[1];
    let (v9, v15): (f64, f64) = ::armdyn_runtime::libm::sincos(v8);
    let v10: f64 = qd[0];
    let v11: f64 = 0.4_f64;
    let v12: f64 = v11 * v10;
    let v13: f64 = v10 * v12;
    let v14: f64 = v9 * v13;
    let v16: f64 = v11 * v1;
    let v17: f64 = v15 * v16;
    let v18: f64 = v14 + v17;
    let v19: f64 = v7 * v18;
    let v20: f64 = params[12];
    let v21: f64 = v9 * v16;
    let v22: f64 = v15 * v13;
    let v23: f64 = v21 - v22;
    let v24: f64 = v20 * v23;
    let v25: f64 = v19 - v24;
    let v26: f64 = v6 + v25;
    let v27: f64 = params[39];
    let v28: f64 = qdd[3];
    let v29: f64 = v28 - v5;
    let v30: f64 = v27 * v29;
    let v31: f64 = params[31];
    let v32: f64 = q[3];
    let (v33, v40): (f64, f64) = ::armdyn_runtime::libm::sincos(v32);
    let v34: f64 = qd[1];
    let v35: f64 = v10 + v34;
    let v36: f64 = v11 * v35;
    let v37: f64 = v35 * v36;
    let v38: f64 = v23 - v37;
    let v39: f64 = v33 * v38;
    let v41: f64 = v11 * v5;
    let v42: f64 = v18 + v41;
    let v43: f64 = v40 * v42;
    let v44: f64 = v39 + v43;
    let v45: f64 = v31 * v44;
    let v46: f64 = params[32];
    let v47: f64 = v40 * v38;
    let v48: f64 = v33 * v42;
    let v49: f64 = v47 - v48;
    let v50: f64 = v46 * v49;
    let v51: f64 = v45 + v50;
    let v52: f64 = v30 - v51;
    let v53: f64 = params[29];
    let v54: f64 = v53 * v5;
    let v55: f64 = params[21];
    let v56: f64 = v55 * v42;
    let v57: f64 = params[22];
    let v58: f64 = v57 * v38;
    let v59: f64 = v56 + v58;
    let v60: f64 = v54 + v59;
    let v61: f64 = v52 - v60;
    let v62: f64 = v26 - v61;
    let v63: f64 = params[30];
    let v64: f64 = v63 * v49;
    let v65: f64 = v29 * v46;
    let v66: f64 = qd[3];
    let v67: f64 = v66 - v35;
    let v68: f64 = v67 * v31;
    let v69: f64 = v67 * v68;
    let v70: f64 = v65 + v69;
    let v71: f64 = v64 - v70;
    let v72: f64 = v33 * v71;
    let v73: f64 = v29 * v31;
    let v74: f64 = v67 * v46;
    let v75: f64 = v67 * v74;
    let v76: f64 = v73 - v75;
    let v77: f64 = v63 * v44;
    let v78: f64 = v76 - v77;
    let v79: f64 = v40 * v78;
    let v80: f64 = v72 + v79;
    let v81: f64 = params[20];
    let v82: f64 = v81 * v42;
    let v83: f64 = v5 * v55;
    let v84: f64 = v35 * v57;
    let v85: f64 = v35 * v84;
    let v86: f64 = v83 + v85;
    let v87: f64 = v82 + v86;
    let v88: f64 = v80 - v87;
    let v89: f64 = v11 * v88;
    let v90: f64 = v62 - v89;
    let v91: f64 = v2 + v90;
    let v92: f64 = params[10];
    let v93: f64 = v92 * v23;
    let v94: f64 = v5 * v20;
    let v95: f64 = v35 * v7;
    let v96: f64 = v35 * v95;
    let v97: f64 = v94 + v96;
    let v98: f64 = v93 - v97;
    let v99: f64 = v81 * v38;
    let v100: f64 = v5 * v57;
    let v101: f64 = v35 * v55;
    let v102: f64 = v35 * v101;
    let v103: f64 = v100 - v102;
    let v104: f64 = v99 + v103;
    let v105: f64 = v40 * v71;
    let v106: f64 = v33 * v78;
    let v107: f64 = v105 - v106;
    let v108: f64 = v104 + v107;
    let v109: f64 = v98 + v108;
    let v110: f64 = v9 * v109;
    let v111: f64 = v92 * v18;
    let v112: f64 = v5 * v7;
    let v113: f64 = v35 * v20;
    let v114: f64 = v35 * v113;
    let v115: f64 = v112 - v114;
    let v116: f64 = v111 + v115;
    let v117: f64 = v116 - v88;
    let v118: f64 = v15 * v117;
    let v119: f64 = v110 + v118;
    let v120: f64 = v11 * v119;
    let v121: f64 = v91 + v120;
    let v122: f64 = -9.8_f64;
    let v123: f64 = qdd[2];
    let v124: f64 = v122 + v123;
    let v125: f64 = v81 * v124;
    let v126: f64 = v63 * v124;
    let v127: f64 = v125 + v126;
    [v121, v90, v127, v52]
}
/// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g. The pivots `D_k` of the factorisation depend on `params`, which must therefore give a positive definite mass matrix (any physical parameter set does: positive masses, inertias that satisfy the triangle inequalities); nothing is checked, and parameters that make a pivot zero give a non-finite result.
///
/// # Inputs
///
/// - `q: &[f64; 4]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 4]`: joint velocities qd (rad/s or m/s)
/// - `tau: &[f64; 4]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
/// - `params: &[f64; 40]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `qdd: [f64; 4]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// Operation count: 160 floating-point operations, 4 trig calls.
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
    q: &[f64; 4],
    qd: &[f64; 4],
    tau: &[f64; 4],
    params: &[f64; 40],
) -> [f64; 4] {
    let v0: f64 = tau[0];
    let v1: f64 = params[11];
    let v2: f64 = q[1];
    let (v3, v11): (f64, f64) = ::armdyn_runtime::libm::sincos(v2);
    let v4: f64 = qd[0];
    let v5: f64 = 0.4_f64;
    let v6: f64 = v5 * v4;
    let v7: f64 = v4 * v6;
    let v8: f64 = v3 * v7;
    let v9: f64 = v1 * v8;
    let v10: f64 = params[12];
    let v12: f64 = v11 * v7;
    let v13: f64 = v10 * v12;
    let v14: f64 = v9 + v13;
    let v15: f64 = params[22];
    let v16: f64 = qd[1];
    let v17: f64 = v4 + v16;
    let v18: f64 = v5 * v17;
    let v19: f64 = v17 * v18;
    let v20: f64 = v12 + v19;
    let v21: f64 = v15 * v20;
    let v22: f64 = params[21];
    let v23: f64 = v22 * v8;
    let v24: f64 = v21 - v23;
    let v25: f64 = params[31];
    let v26: f64 = q[3];
    let (v27, v29): (f64, f64) = ::armdyn_runtime::libm::sincos(v26);
    let v28: f64 = v27 * v20;
    let v30: f64 = v29 * v8;
    let v31: f64 = v28 - v30;
    let v32: f64 = v25 * v31;
    let v33: f64 = params[32];
    let v34: f64 = v29 * v20;
    let v35: f64 = v27 * v8;
    let v36: f64 = v34 + v35;
    let v37: f64 = v33 * v36;
    let v38: f64 = v32 + v37;
    let v39: f64 = v24 + v38;
    let v40: f64 = v14 - v39;
    let v41: f64 = params[30];
    let v42: f64 = v41 * v31;
    let v43: f64 = qd[3];
    let v44: f64 = v43 - v17;
    let v45: f64 = v44 * v33;
    let v46: f64 = v44 * v45;
    let v47: f64 = v42 - v46;
    let v48: f64 = v29 * v47;
    let v49: f64 = v41 * v36;
    let v50: f64 = v44 * v25;
    let v51: f64 = v44 * v50;
    let v52: f64 = v49 + v51;
    let v53: f64 = v27 * v52;
    let v54: f64 = v48 - v53;
    let v55: f64 = params[20];
    let v56: f64 = v55 * v8;
    let v57: f64 = v17 * v15;
    let v58: f64 = v17 * v57;
    let v59: f64 = v56 + v58;
    let v60: f64 = v54 - v59;
    let v61: f64 = v5 * v60;
    let v62: f64 = v40 - v61;
    let v63: f64 = params[10];
    let v64: f64 = v63 * v8;
    let v65: f64 = v17 * v10;
    let v66: f64 = v17 * v65;
    let v67: f64 = v64 - v66;
    let v68: f64 = v67 - v60;
    let v69: f64 = v11 * v68;
    let v70: f64 = v63 * v12;
    let v71: f64 = v17 * v1;
    let v72: f64 = v17 * v71;
    let v73: f64 = v70 + v72;
    let v74: f64 = v55 * v20;
    let v75: f64 = v17 * v22;
    let v76: f64 = v17 * v75;
    let v77: f64 = v74 + v76;
    let v78: f64 = v29 * v52;
    let v79: f64 = v27 * v47;
    let v80: f64 = v78 + v79;
    let v81: f64 = v77 + v80;
    let v82: f64 = v73 + v81;
    let v83: f64 = v3 * v82;
    let v84: f64 = v69 - v83;
    let v85: f64 = v5 * v84;
    let v86: f64 = v62 + v85;
    let v87: f64 = v0 - v86;
    let v88: f64 = params[39];
    let v89: f64 = v29 * v25;
    let v90: f64 = v27 * v33;
    let v91: f64 = v89 - v90;
    let v92: f64 = v5 * v91;
    let v93: f64 = v88 + v92;
    let v94: f64 = v29 * v33;
    let v95: f64 = v27 * v25;
    let v96: f64 = v94 + v95;
    let v97: f64 = v3 * v96;
    let v98: f64 = v11 * v91;
    let v99: f64 = v97 + v98;
    let v100: f64 = v5 * v99;
    let v101: f64 = v93 + v100;
    let v102: f64 = v101 / v88;
    let v103: f64 = tau[3];
    let v104: f64 = v103 - v38;
    let v105: f64 = v102 * v104;
    let v106: f64 = v87 + v105;
    let v107: f64 = params[19];
    let v108: f64 = params[29];
    let v109: f64 = 0.0225_f64;
    let v110: f64 = v109 * v41;
    let v111: f64 = 2.0_f64;
    let v112: f64 = 0.15_f64;
    let v113: f64 = params[33];
    let v114: f64 = v112 * v113;
    let v115: f64 = v111 * v114;
    let v116: f64 = v110 + v115;
    let v117: f64 = v88 + v116;
    let v118: f64 = v117 - v110;
    let v119: f64 = v118 - v114;
    let v120: f64 = v119 - v114;
    let v121: f64 = v108 + v120;
    let v122: f64 = v55 + v41;
    let v123: f64 = 0.16000000000000003_f64;
    let v124: f64 = q[2];
    let v125: f64 = v124 * v124;
    let v126: f64 = v123 + v125;
    let v127: f64 = v122 * v126;
    let v128: f64 = v22 + v91;
    let v129: f64 = v5 * v128;
    let v130: f64 = params[23];
    let v131: f64 = v112 * v41;
    let v132: f64 = v113 + v131;
    let v133: f64 = v130 + v132;
    let v134: f64 = v133 * v124;
    let v135: f64 = v129 + v134;
    let v136: f64 = v111 * v135;
    let v137: f64 = v127 + v136;
    let v138: f64 = v121 + v137;
    let v139: f64 = v122 * v125;
    let v140: f64 = v138 - v139;
    let v141: f64 = v140 - v134;
    let v142: f64 = v124 * v133;
    let v143: f64 = v141 - v142;
    let v144: f64 = v107 + v143;
    let v145: f64 = v5 * v122;
    let v146: f64 = v128 + v145;
    let v147: f64 = v1 + v146;
    let v148: f64 = v11 * v147;
    let v149: f64 = v95 + v94;
    let v150: f64 = v15 + v149;
    let v151: f64 = v10 - v150;
    let v152: f64 = v3 * v151;
    let v153: f64 = v148 - v152;
    let v154: f64 = v5 * v153;
    let v155: f64 = v144 + v154;
    let v156: f64 = v93 / v88;
    let v157: f64 = v101 * v156;
    let v158: f64 = v155 - v157;
    let v159: f64 = v93 * v156;
    let v160: f64 = v144 - v159;
    let v161: f64 = v158 / v160;
    let v162: f64 = tau[1];
    let v163: f64 = v162 - v62;
    let v164: f64 = v156 * v104;
    let v165: f64 = v163 + v164;
    let v166: f64 = v161 * v165;
    let v167: f64 = v106 - v166;
    let v168: f64 = params[9];
    let v169: f64 = v63 + v122;
    let v170: f64 = v123 * v169;
    let v171: f64 = v111 * v154;
    let v172: f64 = v170 + v171;
    let v173: f64 = v144 + v172;
    let v174: f64 = v168 + v173;
    let v175: f64 = v101 * v102;
    let v176: f64 = v174 - v175;
    let v177: f64 = v158 * v161;
    let v178: f64 = v176 - v177;
    let v179: f64 = v167 / v178;
    let v180: f64 = v165 / v160;
    let v181: f64 = v161 * v179;
    let v182: f64 = v180 - v181;
    let v183: f64 = tau[2];
    let v184: f64 = -9.8_f64;
    let v185: f64 = v184 * v55;
    let v186: f64 = v184 * v41;
    let v187: f64 = v185 + v186;
    let v188: f64 = v183 - v187;
    let v189: f64 = v188 / v122;
    let v190: f64 = v104 / v88;
    let v191: f64 = v102 * v179;
    let v192: f64 = v190 + v191;
    let v193: f64 = v156 * v182;
    let v194: f64 = v192 + v193;
    [v179, v182, v189, v194]
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/scara_mdh_parametric.json")
);
