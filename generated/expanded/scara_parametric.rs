// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `armdyn_derive::robot_model!("models/scara_parametric.json")` in the `generated` crate,
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
pub const OPERATION_COUNTS: [(&str, u32, u32); 6] = [
    ("mass_matrix", 91, 4),
    ("coriolis_matrix", 102, 4),
    ("coriolis", 73, 4),
    ("gravity", 3, 0),
    ("inverse_dynamics", 112, 4),
    ("forward_dynamics", 191, 4),
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
/// Operation count: 91 floating-point operations, 4 trig calls.
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
    let v0: f64 = params[39];
    let v1: f64 = 0.32_f64;
    let v2: f64 = params[30];
    let v3: f64 = v1 * v2;
    let v4: f64 = v0 + v3;
    let v5: f64 = params[29];
    let v6: f64 = v4 + v5;
    let v7: f64 = 0.8_f64;
    let v8: f64 = params[21];
    let v9: f64 = v7 * v8;
    let v10: f64 = v6 + v9;
    let v11: f64 = params[20];
    let v12: f64 = v1 * v11;
    let v13: f64 = v10 + v12;
    let v14: f64 = params[19];
    let v15: f64 = v13 + v14;
    let v16: f64 = params[11];
    let v17: f64 = v7 * v16;
    let v18: f64 = v15 + v17;
    let v19: f64 = params[10];
    let v20: f64 = v1 * v19;
    let v21: f64 = v18 + v20;
    let v22: f64 = params[9];
    let v23: f64 = v21 + v22;
    let v24: f64 = params[1];
    let v25: f64 = v7 * v24;
    let v26: f64 = v23 + v25;
    let v27: f64 = 0.16_f64;
    let v28: f64 = params[0];
    let v29: f64 = v27 * v28;
    let v30: f64 = v26 + v29;
    let v31: f64 = params[31];
    let v32: f64 = v7 * v31;
    let v33: f64 = q[3];
    let (v39, v34): (f64, f64) = ::armdyn_runtime::libm::sincos(v33);
    let v35: f64 = v32 * v34;
    let v36: f64 = v30 + v35;
    let v37: f64 = params[32];
    let v38: f64 = v7 * v37;
    let v40: f64 = v38 * v39;
    let v41: f64 = v36 - v40;
    let v42: f64 = params[22];
    let v43: f64 = v7 * v42;
    let v44: f64 = params[12];
    let v45: f64 = v7 * v44;
    let v46: f64 = v43 + v45;
    let v47: f64 = v38 * v34;
    let v48: f64 = v46 + v47;
    let v49: f64 = v32 * v39;
    let v50: f64 = v48 + v49;
    let v51: f64 = q[1];
    let (v52, v61): (f64, f64) = ::armdyn_runtime::libm::sincos(v51);
    let v53: f64 = v50 * v52;
    let v54: f64 = v41 + v53;
    let v55: f64 = v3 + v9;
    let v56: f64 = v55 + v12;
    let v57: f64 = v56 + v17;
    let v58: f64 = v57 + v20;
    let v59: f64 = v58 + v35;
    let v60: f64 = v59 - v40;
    let v62: f64 = v60 * v61;
    let v63: f64 = v54 + v62;
    let v64: f64 = v27 * v2;
    let v65: f64 = v0 + v64;
    let v66: f64 = v65 + v5;
    let v67: f64 = v66 + v9;
    let v68: f64 = v27 * v11;
    let v69: f64 = v67 + v68;
    let v70: f64 = v69 + v14;
    let v71: f64 = v70 + v17;
    let v72: f64 = v27 * v19;
    let v73: f64 = v71 + v72;
    let v74: f64 = v73 + v35;
    let v75: f64 = v74 - v40;
    let v76: f64 = 0.4_f64;
    let v77: f64 = v76 * v42;
    let v78: f64 = v76 * v44;
    let v79: f64 = v77 + v78;
    let v80: f64 = v76 * v37;
    let v81: f64 = v80 * v34;
    let v82: f64 = v79 + v81;
    let v83: f64 = v76 * v31;
    let v84: f64 = v83 * v39;
    let v85: f64 = v82 + v84;
    let v86: f64 = v85 * v52;
    let v87: f64 = v75 + v86;
    let v88: f64 = v76 * v8;
    let v89: f64 = v64 + v88;
    let v90: f64 = v89 + v68;
    let v91: f64 = v76 * v16;
    let v92: f64 = v90 + v91;
    let v93: f64 = v92 + v72;
    let v94: f64 = v83 * v34;
    let v95: f64 = v93 + v94;
    let v96: f64 = v80 * v39;
    let v97: f64 = v95 - v96;
    let v98: f64 = v97 * v61;
    let v99: f64 = v87 + v98;
    let v100: f64 = 0.0_f64;
    let v101: f64 = -0.4_f64;
    let v102: f64 = v76 * v61;
    let v103: f64 = v101 - v102;
    let v104: f64 = v103 * v31;
    let v105: f64 = v80 * v52;
    let v106: f64 = v104 - v105;
    let v107: f64 = v106 * v34;
    let v108: f64 = v107 - v0;
    let v109: f64 = v76 + v102;
    let v110: f64 = v109 * v37;
    let v111: f64 = v83 * v52;
    let v112: f64 = v110 - v111;
    let v113: f64 = v112 * v39;
    let v114: f64 = v108 + v113;
    let v115: f64 = v0 + v94;
    let v116: f64 = v96 - v115;
    let v117: f64 = v2 + v11;
    [
        [v63, v99, v100, v114],
        [v99, v75, v100, v116],
        [v100, v100, v117, v100],
        [v114, v116, v100, v0],
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
/// Operation count: 102 floating-point operations, 4 trig calls.
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
    let v29: f64 = v26 + v28;
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
    let v48: f64 = params[10];
    let v49: f64 = v36 * v48;
    let v50: f64 = v47 + v49;
    let v51: f64 = v2 * v14;
    let v52: f64 = v50 + v51;
    let v53: f64 = v35 - v52;
    let v54: f64 = v53 * v4;
    let v55: f64 = v34 + v54;
    let v56: f64 = qd[1];
    let v57: f64 = v55 * v56;
    let v58: f64 = v24 + v57;
    let v59: f64 = v33 * v56;
    let v60: f64 = v30 + v32;
    let v61: f64 = v60 * v23;
    let v62: f64 = v59 - v61;
    let v63: f64 = qd[0];
    let v64: f64 = v33 * v63;
    let v65: f64 = v62 + v64;
    let v66: f64 = v65 * v7;
    let v67: f64 = v66 - v61;
    let v68: f64 = v51 - v35;
    let v69: f64 = v68 * v23;
    let v70: f64 = v53 * v56;
    let v71: f64 = v69 + v70;
    let v72: f64 = v53 * v63;
    let v73: f64 = v71 + v72;
    let v74: f64 = v73 * v4;
    let v75: f64 = v67 + v74;
    let v76: f64 = 0.0_f64;
    let v77: f64 = v0 * v56;
    let v78: f64 = v0 * v23;
    let v79: f64 = v77 - v78;
    let v80: f64 = v0 * v63;
    let v81: f64 = v79 + v80;
    let v82: f64 = v81 * v1;
    let v83: f64 = v82 * v4;
    let v84: f64 = v78 - v77;
    let v85: f64 = v84 - v80;
    let v86: f64 = v85 * v7;
    let v87: f64 = v85 + v86;
    let v88: f64 = v87 * v10;
    let v89: f64 = v83 + v88;
    let v90: f64 = v89 * v14;
    let v91: f64 = v85 * v10;
    let v92: f64 = v91 * v4;
    let v93: f64 = v87 * v1;
    let v94: f64 = v92 + v93;
    let v95: f64 = v94 * v20;
    let v96: f64 = v90 + v95;
    let v97: f64 = v52 - v35;
    let v98: f64 = v97 * v4;
    let v99: f64 = v98 - v34;
    let v100: f64 = v99 * v63;
    let v101: f64 = v100 - v61;
    let v102: f64 = -v61;
    let v103: f64 = v91 * v14;
    let v104: f64 = v85 * v1;
    let v105: f64 = v104 * v20;
    let v106: f64 = v103 + v105;
    let v107: f64 = v60 * v56;
    let v108: f64 = v0 + v8;
    let v109: f64 = v108 * v10;
    let v110: f64 = v109 - v5;
    let v111: f64 = v110 * v14;
    let v112: f64 = v108 * v1;
    let v113: f64 = v18 + v112;
    let v114: f64 = v113 * v20;
    let v115: f64 = v111 + v114;
    let v116: f64 = v115 * v63;
    let v117: f64 = v107 + v116;
    let v118: f64 = v77 + v80;
    let v119: f64 = v118 * v10;
    let v120: f64 = v119 * v14;
    let v121: f64 = v118 * v1;
    let v122: f64 = v121 * v20;
    let v123: f64 = v120 + v122;
    [
        [v58, v75, v76, v96],
        [v101, v102, v76, v106],
        [v76, v76, v76, v76],
        [v117, v123, v76, v76],
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
/// Operation count: 73 floating-point operations, 4 trig calls.
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
    let v0: f64 = params[2];
    let v1: f64 = qd[0];
    let v2: f64 = 0.4_f64;
    let v3: f64 = v2 * v1;
    let v4: f64 = v1 * v3;
    let v5: f64 = v0 * v4;
    let v6: f64 = params[12];
    let v7: f64 = q[1];
    let (v17, v8): (f64, f64) = ::armdyn_runtime::libm::sincos(v7);
    let v9: f64 = v8 * v4;
    let v10: f64 = qd[1];
    let v11: f64 = v1 + v10;
    let v12: f64 = v2 * v11;
    let v13: f64 = v11 * v12;
    let v14: f64 = v9 + v13;
    let v15: f64 = v6 * v14;
    let v16: f64 = params[11];
    let v18: f64 = v17 * v4;
    let v19: f64 = v16 * v18;
    let v20: f64 = v15 - v19;
    let v21: f64 = params[22];
    let v22: f64 = v21 * v14;
    let v23: f64 = params[21];
    let v24: f64 = v23 * v18;
    let v25: f64 = v22 - v24;
    let v26: f64 = params[31];
    let v27: f64 = q[3];
    let (v28, v30): (f64, f64) = ::armdyn_runtime::libm::sincos(v27);
    let v29: f64 = v28 * v14;
    let v31: f64 = v30 * v18;
    let v32: f64 = v29 - v31;
    let v33: f64 = v26 * v32;
    let v34: f64 = params[32];
    let v35: f64 = v30 * v14;
    let v36: f64 = v28 * v18;
    let v37: f64 = v35 + v36;
    let v38: f64 = v34 * v37;
    let v39: f64 = v33 + v38;
    let v40: f64 = v25 + v39;
    let v41: f64 = v20 + v40;
    let v42: f64 = params[30];
    let v43: f64 = v42 * v32;
    let v44: f64 = qd[3];
    let v45: f64 = v44 - v11;
    let v46: f64 = v45 * v34;
    let v47: f64 = v45 * v46;
    let v48: f64 = v43 - v47;
    let v49: f64 = v30 * v48;
    let v50: f64 = v42 * v37;
    let v51: f64 = v45 * v26;
    let v52: f64 = v45 * v51;
    let v53: f64 = v50 + v52;
    let v54: f64 = v28 * v53;
    let v55: f64 = v49 - v54;
    let v56: f64 = params[20];
    let v57: f64 = v56 * v18;
    let v58: f64 = v11 * v21;
    let v59: f64 = v11 * v58;
    let v60: f64 = v57 + v59;
    let v61: f64 = v55 - v60;
    let v62: f64 = params[10];
    let v63: f64 = v62 * v18;
    let v64: f64 = v11 * v6;
    let v65: f64 = v11 * v64;
    let v66: f64 = v63 + v65;
    let v67: f64 = v61 - v66;
    let v68: f64 = v2 * v67;
    let v69: f64 = v41 + v68;
    let v70: f64 = v5 - v69;
    let v71: f64 = v1 * v0;
    let v72: f64 = v1 * v71;
    let v73: f64 = v62 * v14;
    let v74: f64 = v11 * v16;
    let v75: f64 = v11 * v74;
    let v76: f64 = v73 + v75;
    let v77: f64 = v56 * v14;
    let v78: f64 = v11 * v23;
    let v79: f64 = v11 * v78;
    let v80: f64 = v77 + v79;
    let v81: f64 = v30 * v53;
    let v82: f64 = v28 * v48;
    let v83: f64 = v81 + v82;
    let v84: f64 = v80 + v83;
    let v85: f64 = v76 + v84;
    let v86: f64 = v17 * v85;
    let v87: f64 = v8 * v67;
    let v88: f64 = v86 + v87;
    let v89: f64 = v72 + v88;
    let v90: f64 = v2 * v89;
    let v91: f64 = v70 - v90;
    let v92: f64 = -v69;
    let v93: f64 = 0.0_f64;
    [v91, v92, v93, v39]
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
/// Operation count: 112 floating-point operations, 4 trig calls.
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
    let v3: f64 = params[1];
    let v4: f64 = 0.4_f64;
    let v5: f64 = v4 * v1;
    let v6: f64 = v3 * v5;
    let v7: f64 = params[2];
    let v8: f64 = qd[0];
    let v9: f64 = v4 * v8;
    let v10: f64 = v8 * v9;
    let v11: f64 = v7 * v10;
    let v12: f64 = v6 + v11;
    let v13: f64 = v2 + v12;
    let v14: f64 = params[39];
    let v15: f64 = qdd[3];
    let v16: f64 = qdd[1];
    let v17: f64 = v1 + v16;
    let v18: f64 = v15 - v17;
    let v19: f64 = v14 * v18;
    let v20: f64 = params[31];
    let v21: f64 = q[3];
    let (v22, v35): (f64, f64) = ::armdyn_runtime::libm::sincos(v21);
    let v23: f64 = q[1];
    let (v24, v26): (f64, f64) = ::armdyn_runtime::libm::sincos(v23);
    let v25: f64 = v24 * v5;
    let v27: f64 = v26 * v10;
    let v28: f64 = v25 - v27;
    let v29: f64 = qd[1];
    let v30: f64 = v8 + v29;
    let v31: f64 = v4 * v30;
    let v32: f64 = v30 * v31;
    let v33: f64 = v28 - v32;
    let v34: f64 = v22 * v33;
    let v36: f64 = v24 * v10;
    let v37: f64 = v26 * v5;
    let v38: f64 = v36 + v37;
    let v39: f64 = v4 * v17;
    let v40: f64 = v38 + v39;
    let v41: f64 = v35 * v40;
    let v42: f64 = v34 + v41;
    let v43: f64 = v20 * v42;
    let v44: f64 = params[32];
    let v45: f64 = v35 * v33;
    let v46: f64 = v22 * v40;
    let v47: f64 = v45 - v46;
    let v48: f64 = v44 * v47;
    let v49: f64 = v43 + v48;
    let v50: f64 = v19 - v49;
    let v51: f64 = params[29];
    let v52: f64 = v51 * v17;
    let v53: f64 = params[21];
    let v54: f64 = v53 * v40;
    let v55: f64 = params[22];
    let v56: f64 = v55 * v33;
    let v57: f64 = v54 + v56;
    let v58: f64 = v52 + v57;
    let v59: f64 = v50 - v58;
    let v60: f64 = params[19];
    let v61: f64 = v60 * v17;
    let v62: f64 = params[11];
    let v63: f64 = v62 * v40;
    let v64: f64 = params[12];
    let v65: f64 = v64 * v33;
    let v66: f64 = v63 + v65;
    let v67: f64 = v61 + v66;
    let v68: f64 = v59 - v67;
    let v69: f64 = params[30];
    let v70: f64 = v69 * v47;
    let v71: f64 = v18 * v44;
    let v72: f64 = qd[3];
    let v73: f64 = v72 - v30;
    let v74: f64 = v73 * v20;
    let v75: f64 = v73 * v74;
    let v76: f64 = v71 + v75;
    let v77: f64 = v70 - v76;
    let v78: f64 = v22 * v77;
    let v79: f64 = v18 * v20;
    let v80: f64 = v73 * v44;
    let v81: f64 = v73 * v80;
    let v82: f64 = v79 - v81;
    let v83: f64 = v69 * v42;
    let v84: f64 = v82 - v83;
    let v85: f64 = v35 * v84;
    let v86: f64 = v78 + v85;
    let v87: f64 = params[20];
    let v88: f64 = v87 * v40;
    let v89: f64 = v17 * v53;
    let v90: f64 = v30 * v55;
    let v91: f64 = v30 * v90;
    let v92: f64 = v89 + v91;
    let v93: f64 = v88 + v92;
    let v94: f64 = v86 - v93;
    let v95: f64 = params[10];
    let v96: f64 = v95 * v40;
    let v97: f64 = v17 * v62;
    let v98: f64 = v30 * v64;
    let v99: f64 = v30 * v98;
    let v100: f64 = v97 + v99;
    let v101: f64 = v96 + v100;
    let v102: f64 = v94 - v101;
    let v103: f64 = v4 * v102;
    let v104: f64 = v68 + v103;
    let v105: f64 = v13 - v104;
    let v106: f64 = params[0];
    let v107: f64 = v106 * v5;
    let v108: f64 = v1 * v3;
    let v109: f64 = v8 * v7;
    let v110: f64 = v8 * v109;
    let v111: f64 = v108 - v110;
    let v112: f64 = v107 + v111;
    let v113: f64 = v95 * v33;
    let v114: f64 = v17 * v64;
    let v115: f64 = v30 * v62;
    let v116: f64 = v30 * v115;
    let v117: f64 = v114 - v116;
    let v118: f64 = v113 + v117;
    let v119: f64 = v87 * v33;
    let v120: f64 = v17 * v55;
    let v121: f64 = v30 * v53;
    let v122: f64 = v30 * v121;
    let v123: f64 = v120 - v122;
    let v124: f64 = v119 + v123;
    let v125: f64 = v35 * v77;
    let v126: f64 = v22 * v84;
    let v127: f64 = v125 - v126;
    let v128: f64 = v124 + v127;
    let v129: f64 = v118 + v128;
    let v130: f64 = v24 * v129;
    let v131: f64 = v26 * v102;
    let v132: f64 = v130 - v131;
    let v133: f64 = v112 + v132;
    let v134: f64 = v4 * v133;
    let v135: f64 = v105 + v134;
    let v136: f64 = -v104;
    let v137: f64 = -9.8_f64;
    let v138: f64 = qdd[2];
    let v139: f64 = v137 + v138;
    let v140: f64 = v87 * v139;
    let v141: f64 = v69 * v139;
    let v142: f64 = v140 + v141;
    [v135, v136, v142, v50]
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
/// Operation count: 191 floating-point operations, 4 trig calls.
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
    let (
        v1,
        v2,
        v4,
        v5,
        v6,
        v8,
        v11,
        v14,
        v17,
        v21,
        v27,
        v37,
        v39,
        v40,
        v41,
        v42,
        v48,
        v49,
        v55,
        v60,
        v61,
        v64,
        v65,
        v66,
        v67,
        v71,
        v72,
        v78,
        v80,
        v81,
        v86,
        v87,
        v89,
        v91,
        v93,
        v95,
        v103,
        v105,
        v108,
        v111,
        v112,
    ) = {
        let v0: f64 = tau[0];
        let v1: f64 = 0.8_f64;
        let v2: f64 = qd[0];
        let v3: f64 = v1 * v2;
        let v4: f64 = 0.4_f64;
        let v5: f64 = qd[3];
        let v6: f64 = v4 * v5;
        let v7: f64 = v3 - v6;
        let v8: f64 = params[31];
        let v9: f64 = v7 * v8;
        let v10: f64 = q[1];
        let (v11, v14): (f64, f64) = ::armdyn_runtime::libm::sincos(v10);
        let v12: f64 = v9 * v11;
        let v13: f64 = v6 - v3;
        let v15: f64 = v13 * v14;
        let v16: f64 = v13 + v15;
        let v17: f64 = params[32];
        let v18: f64 = v16 * v17;
        let v19: f64 = v12 + v18;
        let v20: f64 = q[3];
        let (v27, v21): (f64, f64) = ::armdyn_runtime::libm::sincos(v20);
        let v22: f64 = v19 * v21;
        let v23: f64 = v13 * v17;
        let v24: f64 = v23 * v11;
        let v25: f64 = v16 * v8;
        let v26: f64 = v24 + v25;
        let v28: f64 = v26 * v27;
        let v29: f64 = v22 + v28;
        let v30: f64 = v29 * v5;
        let v31: f64 = params[22];
        let v32: f64 = v4 * v31;
        let v33: f64 = params[12];
        let v34: f64 = v4 * v33;
        let v35: f64 = v32 + v34;
        let v36: f64 = v4 * v17;
        let v37: f64 = v36 * v21;
        let v38: f64 = v35 + v37;
        let v39: f64 = v4 * v8;
        let v40: f64 = v39 * v27;
        let v41: f64 = v38 + v40;
        let v42: f64 = qd[1];
        let v43: f64 = v41 * v42;
        let v44: f64 = v1 * v17;
        let v45: f64 = v44 * v21;
        let v46: f64 = v1 * v8;
        let v47: f64 = v46 * v27;
        let v48: f64 = v45 + v47;
        let v49: f64 = v48 * v5;
        let v50: f64 = v43 - v49;
        let v51: f64 = v1 * v31;
        let v52: f64 = v1 * v33;
        let v53: f64 = v51 + v52;
        let v54: f64 = v53 + v45;
        let v55: f64 = v54 + v47;
        let v56: f64 = v55 * v2;
        let v57: f64 = v50 + v56;
        let v58: f64 = v57 * v14;
        let v59: f64 = v58 - v49;
        let v60: f64 = v46 * v21;
        let v61: f64 = v44 * v27;
        let v62: f64 = v60 - v61;
        let v63: f64 = v62 * v5;
        let v64: f64 = v36 * v27;
        let v65: f64 = 0.16_f64;
        let v66: f64 = params[30];
        let v67: f64 = v65 * v66;
        let v68: f64 = params[21];
        let v69: f64 = v4 * v68;
        let v70: f64 = v67 + v69;
        let v71: f64 = params[20];
        let v72: f64 = v65 * v71;
        let v73: f64 = v70 + v72;
        let v74: f64 = params[11];
        let v75: f64 = v4 * v74;
        let v76: f64 = v73 + v75;
        let v77: f64 = params[10];
        let v78: f64 = v65 * v77;
        let v79: f64 = v76 + v78;
        let v80: f64 = v39 * v21;
        let v81: f64 = v79 + v80;
        let v82: f64 = v64 - v81;
        let v83: f64 = v82 * v42;
        let v84: f64 = v63 + v83;
        let v85: f64 = 0.32_f64;
        let v86: f64 = v85 * v66;
        let v87: f64 = v1 * v68;
        let v88: f64 = v86 + v87;
        let v89: f64 = v85 * v71;
        let v90: f64 = v88 + v89;
        let v91: f64 = v1 * v74;
        let v92: f64 = v90 + v91;
        let v93: f64 = v85 * v77;
        let v94: f64 = v92 + v93;
        let v95: f64 = v94 + v60;
        let v96: f64 = v61 - v95;
        let v97: f64 = v96 * v2;
        let v98: f64 = v84 + v97;
        let v99: f64 = v98 * v11;
        let v100: f64 = v59 + v99;
        let v101: f64 = v100 * v42;
        let v102: f64 = v30 + v101;
        let v103: f64 = v0 - v102;
        let v104: f64 = -0.4_f64;
        let v105: f64 = v4 * v14;
        let v106: f64 = v104 - v105;
        let v107: f64 = v106 * v8;
        let v108: f64 = v36 * v11;
        let v109: f64 = v107 - v108;
        let v110: f64 = v109 * v21;
        let v111: f64 = params[39];
        let v112: f64 = v110 - v111;
        (
            v1,
            v2,
            v4,
            v5,
            v6,
            v8,
            v11,
            v14,
            v17,
            v21,
            v27,
            v37,
            v39,
            v40,
            v41,
            v42,
            v48,
            v49,
            v55,
            v60,
            v61,
            v64,
            v65,
            v66,
            v67,
            v71,
            v72,
            v78,
            v80,
            v81,
            v86,
            v87,
            v89,
            v91,
            v93,
            v95,
            v103,
            v105,
            v108,
            v111,
            v112,
        )
    };
    let (v208, v211, v219, v224) = {
        let v113: f64 = v4 + v105;
        let v114: f64 = v113 * v17;
        let v115: f64 = v39 * v11;
        let v116: f64 = v114 - v115;
        let v117: f64 = v116 * v27;
        let v118: f64 = v112 + v117;
        let v119: f64 = v118 / v111;
        let v120: f64 = tau[3];
        let v121: f64 = v37 + v40;
        let v122: f64 = v121 * v42;
        let v123: f64 = v122 * v42;
        let v124: f64 = v48 * v42;
        let v125: f64 = v116 * v21;
        let v126: f64 = v113 * v8;
        let v127: f64 = v108 + v126;
        let v128: f64 = v127 * v27;
        let v129: f64 = v125 + v128;
        let v130: f64 = v129 * v2;
        let v131: f64 = v124 + v130;
        let v132: f64 = v131 * v2;
        let v133: f64 = v123 + v132;
        let v134: f64 = v120 - v133;
        let v135: f64 = v119 * v134;
        let v136: f64 = v103 - v135;
        let v137: f64 = v111 + v67;
        let v138: f64 = params[29];
        let v139: f64 = v137 + v138;
        let v140: f64 = v139 + v87;
        let v141: f64 = v140 + v72;
        let v142: f64 = params[19];
        let v143: f64 = v141 + v142;
        let v144: f64 = v143 + v91;
        let v145: f64 = v144 + v78;
        let v146: f64 = v145 + v60;
        let v147: f64 = v146 - v61;
        let v148: f64 = v41 * v11;
        let v149: f64 = v147 + v148;
        let v150: f64 = v81 - v64;
        let v151: f64 = v150 * v14;
        let v152: f64 = v149 + v151;
        let v153: f64 = v111 + v80;
        let v154: f64 = v64 - v153;
        let v155: f64 = v154 / v111;
        let v156: f64 = v118 * v155;
        let v157: f64 = v152 - v156;
        let v158: f64 = v154 * v155;
        let v159: f64 = v147 - v158;
        let v160: f64 = v157 / v159;
        let v161: f64 = tau[1];
        let v162: f64 = v1 * v42;
        let v163: f64 = v6 - v162;
        let v164: f64 = v163 * v17;
        let v165: f64 = v164 * v21;
        let v166: f64 = v163 * v8;
        let v167: f64 = v166 * v27;
        let v168: f64 = v165 + v167;
        let v169: f64 = v168 * v5;
        let v170: f64 = v150 * v11;
        let v171: f64 = v41 * v14;
        let v172: f64 = v170 - v171;
        let v173: f64 = v172 * v2;
        let v174: f64 = v173 - v49;
        let v175: f64 = v174 * v2;
        let v176: f64 = v169 + v175;
        let v177: f64 = v161 - v176;
        let v178: f64 = v155 * v134;
        let v179: f64 = v177 - v178;
        let v180: f64 = v160 * v179;
        let v181: f64 = v136 - v180;
        let v182: f64 = v111 + v86;
        let v183: f64 = v182 + v138;
        let v184: f64 = v183 + v87;
        let v185: f64 = v184 + v89;
        let v186: f64 = v185 + v142;
        let v187: f64 = v186 + v91;
        let v188: f64 = v187 + v93;
        let v189: f64 = params[9];
        let v190: f64 = v188 + v189;
        let v191: f64 = params[1];
        let v192: f64 = v1 * v191;
        let v193: f64 = v190 + v192;
        let v194: f64 = params[0];
        let v195: f64 = v65 * v194;
        let v196: f64 = v193 + v195;
        let v197: f64 = v196 + v60;
        let v198: f64 = v197 - v61;
        let v199: f64 = v55 * v11;
        let v200: f64 = v198 + v199;
        let v201: f64 = v95 - v61;
        let v202: f64 = v201 * v14;
        let v203: f64 = v200 + v202;
        let v204: f64 = v118 * v119;
        let v205: f64 = v203 - v204;
        let v206: f64 = v157 * v160;
        let v207: f64 = v205 - v206;
        let v208: f64 = v181 / v207;
        let v209: f64 = v179 / v159;
        let v210: f64 = v160 * v208;
        let v211: f64 = v209 - v210;
        let v212: f64 = tau[2];
        let v213: f64 = 9.8_f64;
        let v214: f64 = v213 * v66;
        let v215: f64 = v213 * v71;
        let v216: f64 = v214 + v215;
        let v217: f64 = v212 + v216;
        let v218: f64 = v66 + v71;
        let v219: f64 = v217 / v218;
        let v220: f64 = v134 / v111;
        let v221: f64 = v119 * v208;
        let v222: f64 = v220 - v221;
        let v223: f64 = v155 * v211;
        let v224: f64 = v222 - v223;
        (v208, v211, v219, v224)
    };
    [v208, v211, v219, v224]
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/scara_parametric.json")
);
