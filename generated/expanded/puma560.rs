// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `scara_derive::robot_model!("models/puma560.json")` in the `generated` crate,
// formatted with prettyplease. Not compiled: for reading and review.

/// Name of the robot (`robot.name` in the model file).
pub const ROBOT_NAME: &str = "puma560";
/// Description of the robot, from the model file.
pub const DESCRIPTION: &str = "PUMA 560, 6R, standard DH with the published inertial parameters";
/// Degrees of freedom: the number of joints.
pub const DOF: usize = 6;
/// Name and version of the generator that wrote the model file.
pub const GENERATOR: &str = "scara-codegen 0.1.0";
/// Version of CasADi the generator used.
pub const CASADI_VERSION: &str = "3.7.2";
/// Robot description file the model was generated from.
pub const SOURCE: &str = "robots/puma560.toml";
/// SHA-256 of the robot description file (64 hex digits).
pub const SOURCE_SHA256: &str = "6e2f52b5e6a0b5c65a1cb8ce1147eb3e09d8436806f36e24ce6c24b5cec30c2f";
/// Joint names, base to tip.
pub const JOINT_NAMES: [&str; DOF] = ["q1", "q2", "q3", "q4", "q5", "q6"];
/// `true` for a prismatic joint (m, N), `false` for a revolute one (rad, N m).
pub const JOINT_IS_PRISMATIC: [bool; DOF] = [false, false, false, false, false, false];
/// Joint position limits `[lower, upper]`, rad or m.
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const JOINT_LIMITS: [[f64; 2]; DOF] = [
    [-2.792526803190927_f64, 2.792526803190927_f64],
    [-0.7853981633974483_f64, 3.9269908169872414_f64],
    [-3.9269908169872414_f64, 0.7853981633974483_f64],
    [-1.9198621771937625_f64, 2.9670597283903604_f64],
    [-1.7453292519943295_f64, 1.7453292519943295_f64],
    [-4.642575810304916_f64, 4.642575810304916_f64],
];
/// Actuator effort limits, N m (revolute) or N (prismatic).
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const EFFORT_LIMITS: [f64; DOF] = [
    97.6_f64,
    186.4_f64,
    89.4_f64,
    24.2_f64,
    20.1_f64,
    21.3_f64,
];
/// Gravity vector in the base frame, m/s^2.
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const GRAVITY: [f64; 3] = [0.0_f64, 0.0_f64, -9.81_f64];
/// `(function, flops, trig)` for every function, in file order: floating-point
/// operations (add, sub, mul, div, neg, sq, twice, inv, sqrt, fabs) and trig calls
/// (sin, cos, atan2) in its body.
pub const OPERATION_COUNTS: [(&str, u32, u32); 12] = [
    ("frame_poses", 115, 12),
    ("end_effector_pose", 102, 12),
    ("jacobian", 73, 10),
    ("jdot_qd", 208, 10),
    ("mass_matrix", 263, 8),
    ("coriolis_matrix", 1471, 8),
    ("coriolis", 483, 10),
    ("gravity", 39, 8),
    ("inverse_dynamics", 520, 10),
    ("forward_dynamics", 871, 10),
    ("regressor", 1221, 10),
    ("standard_parameters", 0, 0),
];
/// Poses of every DH frame, products of the DH transforms `A_1 ... A_i` (thesis eq. 3.2-3.7).
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `poses: [[[f64; 4]; 4]; 6]` (6 x 4 x 4, row-major): homogeneous transforms T_0i of the description's frames 1..n in the base frame (m)
///
/// Operation count: 115 floating-point operations, 12 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn frame_poses(q: &[f64; 6]) -> [[[f64; 4]; 4]; 6] {
    let v0: f64 = q[0];
    let v1: f64 = ::libm::cos(v0);
    let v2: f64 = 0.0_f64;
    let v3: f64 = ::libm::sin(v0);
    let v4: f64 = -v1;
    let v5: f64 = 1.0_f64;
    let v6: f64 = 0.6718_f64;
    let v7: f64 = q[1];
    let v8: f64 = ::libm::cos(v7);
    let v9: f64 = v1 * v8;
    let v10: f64 = ::libm::sin(v7);
    let v11: f64 = v1 * v10;
    let v12: f64 = -v11;
    let v13: f64 = 0.4318_f64;
    let v14: f64 = v13 * v8;
    let v15: f64 = v1 * v14;
    let v16: f64 = v3 * v8;
    let v17: f64 = v3 * v10;
    let v18: f64 = -v17;
    let v19: f64 = v3 * v14;
    let v20: f64 = v13 * v10;
    let v21: f64 = v6 + v20;
    let v22: f64 = q[2];
    let v23: f64 = ::libm::cos(v22);
    let v24: f64 = v9 * v23;
    let v25: f64 = ::libm::sin(v22);
    let v26: f64 = v11 * v25;
    let v27: f64 = v24 - v26;
    let v28: f64 = -v3;
    let v29: f64 = v9 * v25;
    let v30: f64 = v11 * v23;
    let v31: f64 = v29 + v30;
    let v32: f64 = -v31;
    let v33: f64 = 0.0203_f64;
    let v34: f64 = v33 * v23;
    let v35: f64 = v9 * v34;
    let v36: f64 = v33 * v25;
    let v37: f64 = v11 * v36;
    let v38: f64 = v35 - v37;
    let v39: f64 = 0.15005_f64;
    let v40: f64 = v39 * v3;
    let v41: f64 = v38 + v40;
    let v42: f64 = v15 + v41;
    let v43: f64 = v16 * v23;
    let v44: f64 = v17 * v25;
    let v45: f64 = v43 - v44;
    let v46: f64 = v16 * v25;
    let v47: f64 = v17 * v23;
    let v48: f64 = v46 + v47;
    let v49: f64 = -v48;
    let v50: f64 = v16 * v34;
    let v51: f64 = v17 * v36;
    let v52: f64 = v50 - v51;
    let v53: f64 = v39 * v1;
    let v54: f64 = v52 - v53;
    let v55: f64 = v19 + v54;
    let v56: f64 = v10 * v23;
    let v57: f64 = v8 * v25;
    let v58: f64 = v56 + v57;
    let v59: f64 = v8 * v23;
    let v60: f64 = v10 * v25;
    let v61: f64 = v59 - v60;
    let v62: f64 = v10 * v34;
    let v63: f64 = v8 * v36;
    let v64: f64 = v62 + v63;
    let v65: f64 = v21 + v64;
    let v66: f64 = q[3];
    let v67: f64 = ::libm::cos(v66);
    let v68: f64 = v27 * v67;
    let v69: f64 = ::libm::sin(v66);
    let v70: f64 = v3 * v69;
    let v71: f64 = v68 - v70;
    let v72: f64 = v27 * v69;
    let v73: f64 = v3 * v67;
    let v74: f64 = v72 + v73;
    let v75: f64 = v13 * v31;
    let v76: f64 = v42 - v75;
    let v77: f64 = v45 * v67;
    let v78: f64 = v1 * v69;
    let v79: f64 = v77 + v78;
    let v80: f64 = v45 * v69;
    let v81: f64 = v1 * v67;
    let v82: f64 = v80 - v81;
    let v83: f64 = v13 * v48;
    let v84: f64 = v55 - v83;
    let v85: f64 = v58 * v67;
    let v86: f64 = v58 * v69;
    let v87: f64 = v13 * v61;
    let v88: f64 = v65 + v87;
    let v89: f64 = q[4];
    let v90: f64 = ::libm::cos(v89);
    let v91: f64 = v71 * v90;
    let v92: f64 = ::libm::sin(v89);
    let v93: f64 = v31 * v92;
    let v94: f64 = v91 - v93;
    let v95: f64 = -v74;
    let v96: f64 = v71 * v92;
    let v97: f64 = v31 * v90;
    let v98: f64 = v96 + v97;
    let v99: f64 = -v98;
    let v100: f64 = v79 * v90;
    let v101: f64 = v48 * v92;
    let v102: f64 = v100 - v101;
    let v103: f64 = -v82;
    let v104: f64 = v79 * v92;
    let v105: f64 = v48 * v90;
    let v106: f64 = v104 + v105;
    let v107: f64 = -v106;
    let v108: f64 = v85 * v90;
    let v109: f64 = v61 * v92;
    let v110: f64 = v108 + v109;
    let v111: f64 = -v86;
    let v112: f64 = v61 * v90;
    let v113: f64 = v85 * v92;
    let v114: f64 = v112 - v113;
    let v115: f64 = q[5];
    let v116: f64 = ::libm::cos(v115);
    let v117: f64 = v94 * v116;
    let v118: f64 = ::libm::sin(v115);
    let v119: f64 = v74 * v118;
    let v120: f64 = v117 - v119;
    let v121: f64 = v94 * v118;
    let v122: f64 = v74 * v116;
    let v123: f64 = v121 + v122;
    let v124: f64 = -v123;
    let v125: f64 = v102 * v116;
    let v126: f64 = v82 * v118;
    let v127: f64 = v125 - v126;
    let v128: f64 = v102 * v118;
    let v129: f64 = v82 * v116;
    let v130: f64 = v128 + v129;
    let v131: f64 = -v130;
    let v132: f64 = v110 * v116;
    let v133: f64 = v86 * v118;
    let v134: f64 = v132 - v133;
    let v135: f64 = v110 * v118;
    let v136: f64 = v86 * v116;
    let v137: f64 = v135 + v136;
    let v138: f64 = -v137;
    [
        [[v1, v2, v3, v2], [v3, v2, v4, v2], [v2, v5, v2, v6], [v2, v2, v2, v5]],
        [[v9, v12, v3, v15], [v16, v18, v4, v19], [v10, v8, v2, v21], [v2, v2, v2, v5]],
        [
            [v27, v28, v32, v42],
            [v45, v1, v49, v55],
            [v58, v2, v61, v65],
            [v2, v2, v2, v5],
        ],
        [
            [v71, v32, v74, v76],
            [v79, v49, v82, v84],
            [v85, v61, v86, v88],
            [v2, v2, v2, v5],
        ],
        [
            [v94, v95, v99, v76],
            [v102, v103, v107, v84],
            [v110, v111, v114, v88],
            [v2, v2, v2, v5],
        ],
        [
            [v120, v124, v99, v76],
            [v127, v131, v107, v84],
            [v134, v138, v114, v88],
            [v2, v2, v2, v5],
        ],
    ]
}
/// End-effector pose, forward kinematics `T_0n` (thesis eq. 3.7).
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `pose: [[f64; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n) in the base frame (m)
///
/// Operation count: 102 floating-point operations, 12 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn end_effector_pose(q: &[f64; 6]) -> [[f64; 4]; 4] {
    let v0: f64 = q[2];
    let v1: f64 = ::libm::sin(v0);
    let v2: f64 = q[1];
    let v3: f64 = ::libm::sin(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = ::libm::cos(v0);
    let v6: f64 = ::libm::cos(v2);
    let v7: f64 = v5 * v6;
    let v8: f64 = v4 - v7;
    let v9: f64 = q[5];
    let v10: f64 = ::libm::sin(v9);
    let v11: f64 = v8 * v10;
    let v12: f64 = q[3];
    let v13: f64 = ::libm::sin(v12);
    let v14: f64 = v11 * v13;
    let v15: f64 = q[4];
    let v16: f64 = ::libm::cos(v15);
    let v17: f64 = ::libm::cos(v12);
    let v18: f64 = v16 * v17;
    let v19: f64 = v18 * v5;
    let v20: f64 = ::libm::sin(v15);
    let v21: f64 = v20 * v1;
    let v22: f64 = v19 - v21;
    let v23: f64 = v22 * v6;
    let v24: f64 = v20 * v5;
    let v25: f64 = v18 * v1;
    let v26: f64 = v24 + v25;
    let v27: f64 = v26 * v3;
    let v28: f64 = v23 - v27;
    let v29: f64 = ::libm::cos(v9);
    let v30: f64 = v28 * v29;
    let v31: f64 = v14 + v30;
    let v32: f64 = q[0];
    let v33: f64 = ::libm::cos(v32);
    let v34: f64 = v31 * v33;
    let v35: f64 = v10 * v17;
    let v36: f64 = v29 * v16;
    let v37: f64 = v36 * v13;
    let v38: f64 = v35 + v37;
    let v39: f64 = ::libm::sin(v32);
    let v40: f64 = v38 * v39;
    let v41: f64 = v34 - v40;
    let v42: f64 = v10 * v16;
    let v43: f64 = v42 * v13;
    let v44: f64 = v29 * v17;
    let v45: f64 = v43 - v44;
    let v46: f64 = v45 * v39;
    let v47: f64 = v8 * v29;
    let v48: f64 = v47 * v13;
    let v49: f64 = v21 - v19;
    let v50: f64 = v49 * v6;
    let v51: f64 = v50 + v27;
    let v52: f64 = v51 * v10;
    let v53: f64 = v48 + v52;
    let v54: f64 = v53 * v33;
    let v55: f64 = v46 + v54;
    let v56: f64 = v20 * v13;
    let v57: f64 = v56 * v39;
    let v58: f64 = v20 * v17;
    let v59: f64 = v58 * v1;
    let v60: f64 = v16 * v5;
    let v61: f64 = v59 - v60;
    let v62: f64 = v61 * v3;
    let v63: f64 = v58 * v5;
    let v64: f64 = v16 * v1;
    let v65: f64 = v63 + v64;
    let v66: f64 = v65 * v6;
    let v67: f64 = v62 - v66;
    let v68: f64 = v67 * v33;
    let v69: f64 = v57 + v68;
    let v70: f64 = 0.15005_f64;
    let v71: f64 = v70 * v39;
    let v72: f64 = 0.4318_f64;
    let v73: f64 = 0.0203_f64;
    let v74: f64 = v73 * v5;
    let v75: f64 = v72 + v74;
    let v76: f64 = v72 * v1;
    let v77: f64 = v75 - v76;
    let v78: f64 = v77 * v6;
    let v79: f64 = v72 * v5;
    let v80: f64 = v73 * v1;
    let v81: f64 = v79 + v80;
    let v82: f64 = v81 * v3;
    let v83: f64 = v78 - v82;
    let v84: f64 = v83 * v33;
    let v85: f64 = v71 + v84;
    let v86: f64 = v38 * v33;
    let v87: f64 = v31 * v39;
    let v88: f64 = v86 + v87;
    let v89: f64 = v44 - v43;
    let v90: f64 = v89 * v33;
    let v91: f64 = v53 * v39;
    let v92: f64 = v90 + v91;
    let v93: f64 = v67 * v39;
    let v94: f64 = v56 * v33;
    let v95: f64 = v93 - v94;
    let v96: f64 = v83 * v39;
    let v97: f64 = v70 * v33;
    let v98: f64 = v96 - v97;
    let v99: f64 = v26 * v6;
    let v100: f64 = v22 * v3;
    let v101: f64 = v99 + v100;
    let v102: f64 = v101 * v29;
    let v103: f64 = v1 * v6;
    let v104: f64 = v5 * v3;
    let v105: f64 = v103 + v104;
    let v106: f64 = v105 * v10;
    let v107: f64 = v106 * v13;
    let v108: f64 = v102 - v107;
    let v109: f64 = v49 * v3;
    let v110: f64 = v109 - v99;
    let v111: f64 = v110 * v10;
    let v112: f64 = v105 * v29;
    let v113: f64 = v112 * v13;
    let v114: f64 = v111 - v113;
    let v115: f64 = v60 - v59;
    let v116: f64 = v115 * v6;
    let v117: f64 = v65 * v3;
    let v118: f64 = v116 - v117;
    let v119: f64 = 0.6718_f64;
    let v120: f64 = v81 * v6;
    let v121: f64 = v119 + v120;
    let v122: f64 = v77 * v3;
    let v123: f64 = v121 + v122;
    let v124: f64 = 0.0_f64;
    let v125: f64 = 1.0_f64;
    [
        [v41, v55, v69, v85],
        [v88, v92, v95, v98],
        [v108, v114, v118, v123],
        [v124, v124, v124, v125],
    ]
}
/// Geometric Jacobian of the end-effector frame origin in the base frame (thesis eq. 3.29).
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `jacobian: [[f64; 6]; 6]` (6 x 6, row-major): rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame
///
/// Operation count: 73 floating-point operations, 10 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn jacobian(q: &[f64; 6]) -> [[f64; 6]; 6] {
    let v0: f64 = 0.15005_f64;
    let v1: f64 = q[0];
    let v2: f64 = ::libm::cos(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = 0.4318_f64;
    let v5: f64 = q[2];
    let v6: f64 = ::libm::cos(v5);
    let v7: f64 = v4 * v6;
    let v8: f64 = 0.0203_f64;
    let v9: f64 = ::libm::sin(v5);
    let v10: f64 = v8 * v9;
    let v11: f64 = v7 + v10;
    let v12: f64 = q[1];
    let v13: f64 = ::libm::sin(v12);
    let v14: f64 = v11 * v13;
    let v15: f64 = -0.4318_f64;
    let v16: f64 = v8 * v6;
    let v17: f64 = v15 - v16;
    let v18: f64 = v4 * v9;
    let v19: f64 = v17 + v18;
    let v20: f64 = ::libm::cos(v12);
    let v21: f64 = v19 * v20;
    let v22: f64 = v14 + v21;
    let v23: f64 = ::libm::sin(v1);
    let v24: f64 = v22 * v23;
    let v25: f64 = v3 + v24;
    let v26: f64 = v19 * v13;
    let v27: f64 = v11 * v20;
    let v28: f64 = v26 - v27;
    let v29: f64 = v28 * v2;
    let v30: f64 = v18 - v16;
    let v31: f64 = v30 * v13;
    let v32: f64 = v31 - v27;
    let v33: f64 = v32 * v2;
    let v34: f64 = 0.0_f64;
    let v35: f64 = v0 * v23;
    let v36: f64 = v4 + v16;
    let v37: f64 = v36 - v18;
    let v38: f64 = v37 * v20;
    let v39: f64 = v38 - v14;
    let v40: f64 = v39 * v2;
    let v41: f64 = v35 + v40;
    let v42: f64 = v28 * v23;
    let v43: f64 = v32 * v23;
    let v44: f64 = v16 - v18;
    let v45: f64 = v44 * v20;
    let v46: f64 = v45 - v14;
    let v47: f64 = v9 * v20;
    let v48: f64 = v6 * v13;
    let v49: f64 = v47 + v48;
    let v50: f64 = v49 * v2;
    let v51: f64 = -v50;
    let v52: f64 = q[3];
    let v53: f64 = ::libm::cos(v52);
    let v54: f64 = v53 * v23;
    let v55: f64 = v6 * v20;
    let v56: f64 = v9 * v13;
    let v57: f64 = v55 - v56;
    let v58: f64 = ::libm::sin(v52);
    let v59: f64 = v57 * v58;
    let v60: f64 = v59 * v2;
    let v61: f64 = v54 + v60;
    let v62: f64 = q[4];
    let v63: f64 = ::libm::sin(v62);
    let v64: f64 = v63 * v58;
    let v65: f64 = v64 * v23;
    let v66: f64 = v63 * v53;
    let v67: f64 = v66 * v9;
    let v68: f64 = ::libm::cos(v62);
    let v69: f64 = v68 * v6;
    let v70: f64 = v67 - v69;
    let v71: f64 = v70 * v13;
    let v72: f64 = v66 * v6;
    let v73: f64 = v68 * v9;
    let v74: f64 = v72 + v73;
    let v75: f64 = v74 * v20;
    let v76: f64 = v71 - v75;
    let v77: f64 = v76 * v2;
    let v78: f64 = v65 + v77;
    let v79: f64 = -v2;
    let v80: f64 = v49 * v23;
    let v81: f64 = -v80;
    let v82: f64 = v59 * v23;
    let v83: f64 = v53 * v2;
    let v84: f64 = v82 - v83;
    let v85: f64 = v76 * v23;
    let v86: f64 = v64 * v2;
    let v87: f64 = v85 - v86;
    let v88: f64 = 1.0_f64;
    let v89: f64 = v49 * v58;
    let v90: f64 = v69 - v67;
    let v91: f64 = v90 * v20;
    let v92: f64 = v74 * v13;
    let v93: f64 = v91 - v92;
    [
        [v25, v29, v33, v34, v34, v34],
        [v41, v42, v43, v34, v34, v34],
        [v34, v39, v46, v34, v34, v34],
        [v34, v23, v23, v51, v61, v78],
        [v34, v79, v79, v81, v84, v87],
        [v88, v34, v34, v57, v89, v93],
    ]
}
/// Acceleration term of the end-effector twist: `d/dt (J qd) = J qdd + Jdot qd`.
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 6]`: joint velocities qd (rad/s or m/s)
///
/// # Output
///
/// `jdot_qd: [f64; 6]`: Jdot(q, qd) qd: m/s^2 (rows 0-2) and rad/s^2 (rows 3-5), base frame
///
/// Operation count: 208 floating-point operations, 10 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn jdot_qd(q: &[f64; 6], qd: &[f64; 6]) -> [f64; 6] {
    let (
        v1,
        v3,
        v7,
        v13,
        v17,
        v20,
        v31,
        v36,
        v81,
        v83,
        v95,
        v111,
        v112,
        v113,
        v115,
        v116,
        v117,
    ) = {
        let v0: f64 = 0.8636_f64;
        let v1: f64 = qd[2];
        let v2: f64 = v0 * v1;
        let v3: f64 = qd[1];
        let v4: f64 = v0 * v3;
        let v5: f64 = v2 + v4;
        let v6: f64 = q[2];
        let v7: f64 = ::libm::cos(v6);
        let v8: f64 = v5 * v7;
        let v9: f64 = 0.0406_f64;
        let v10: f64 = v9 * v1;
        let v11: f64 = v9 * v3;
        let v12: f64 = v10 + v11;
        let v13: f64 = ::libm::sin(v6);
        let v14: f64 = v12 * v13;
        let v15: f64 = v8 + v14;
        let v16: f64 = q[1];
        let v17: f64 = ::libm::cos(v16);
        let v18: f64 = v15 * v17;
        let v19: f64 = 0.15005_f64;
        let v20: f64 = qd[0];
        let v21: f64 = v19 * v20;
        let v22: f64 = v18 - v21;
        let v23: f64 = v9 * v7;
        let v24: f64 = v0 * v13;
        let v25: f64 = v23 - v24;
        let v26: f64 = v25 * v1;
        let v27: f64 = v0 + v23;
        let v28: f64 = v27 - v24;
        let v29: f64 = v28 * v3;
        let v30: f64 = v26 + v29;
        let v31: f64 = ::libm::sin(v16);
        let v32: f64 = v30 * v31;
        let v33: f64 = v22 + v32;
        let v34: f64 = v33 * v20;
        let v35: f64 = q[0];
        let v36: f64 = ::libm::sin(v35);
        let v37: f64 = v34 * v36;
        let v38: f64 = 0.4318_f64;
        let v39: f64 = v38 * v1;
        let v40: f64 = v39 * v1;
        let v41: f64 = v38 * v20;
        let v42: f64 = v41 * v20;
        let v43: f64 = v40 + v42;
        let v44: f64 = v38 * v3;
        let v45: f64 = v2 + v44;
        let v46: f64 = v45 * v3;
        let v47: f64 = v43 + v46;
        let v48: f64 = v47 * v7;
        let v49: f64 = 0.0203_f64;
        let v50: f64 = v49 * v1;
        let v51: f64 = v50 * v1;
        let v52: f64 = v49 * v20;
        let v53: f64 = v52 * v20;
        let v54: f64 = v51 + v53;
        let v55: f64 = v49 * v3;
        let v56: f64 = v10 + v55;
        let v57: f64 = v56 * v3;
        let v58: f64 = v54 + v57;
        let v59: f64 = v58 * v13;
        let v60: f64 = v48 + v59;
        let v61: f64 = v60 * v31;
        let v62: f64 = v38 * v13;
        let v63: f64 = v49 * v7;
        let v64: f64 = v62 - v63;
        let v65: f64 = v64 * v1;
        let v66: f64 = v65 * v1;
        let v67: f64 = -0.4318_f64;
        let v68: f64 = v67 - v63;
        let v69: f64 = v68 + v62;
        let v70: f64 = v69 * v20;
        let v71: f64 = v70 * v20;
        let v72: f64 = v66 + v71;
        let v73: f64 = v24 - v23;
        let v74: f64 = v73 * v1;
        let v75: f64 = v69 * v3;
        let v76: f64 = v74 + v75;
        let v77: f64 = v76 * v3;
        let v78: f64 = v72 + v77;
        let v79: f64 = v78 * v17;
        let v80: f64 = v61 + v79;
        let v81: f64 = ::libm::cos(v35);
        let v82: f64 = v80 * v81;
        let v83: f64 = v37 + v82;
        let v84: f64 = v21 - v18;
        let v85: f64 = -0.8636_f64;
        let v86: f64 = v85 - v23;
        let v87: f64 = v86 + v24;
        let v88: f64 = v87 * v3;
        let v89: f64 = v74 + v88;
        let v90: f64 = v89 * v31;
        let v91: f64 = v84 + v90;
        let v92: f64 = v91 * v20;
        let v93: f64 = v92 * v81;
        let v94: f64 = v80 * v36;
        let v95: f64 = v93 + v94;
        let v96: f64 = v64 * v31;
        let v97: f64 = v38 * v7;
        let v98: f64 = v49 * v13;
        let v99: f64 = v97 + v98;
        let v100: f64 = v99 * v17;
        let v101: f64 = v96 - v100;
        let v102: f64 = v101 * v1;
        let v103: f64 = v102 * v1;
        let v104: f64 = v76 * v31;
        let v105: f64 = v45 * v7;
        let v106: f64 = v56 * v13;
        let v107: f64 = v105 + v106;
        let v108: f64 = v107 * v17;
        let v109: f64 = v104 - v108;
        let v110: f64 = v109 * v3;
        let v111: f64 = v103 + v110;
        let v112: f64 = qd[5];
        let v113: f64 = qd[3];
        let v114: f64 = v112 * v113;
        let v115: f64 = q[4];
        let v116: f64 = ::libm::sin(v115);
        let v117: f64 = v114 * v116;
        (
            v1,
            v3,
            v7,
            v13,
            v17,
            v20,
            v31,
            v36,
            v81,
            v83,
            v95,
            v111,
            v112,
            v113,
            v115,
            v116,
            v117,
        )
    };
    let (v196, v212, v235) = {
        let v118: f64 = q[3];
        let v119: f64 = ::libm::cos(v118);
        let v120: f64 = v117 * v119;
        let v121: f64 = ::libm::cos(v115);
        let v122: f64 = v112 * v121;
        let v123: f64 = v122 - v113;
        let v124: f64 = qd[4];
        let v125: f64 = v123 * v124;
        let v126: f64 = ::libm::sin(v118);
        let v127: f64 = v125 * v126;
        let v128: f64 = v120 + v127;
        let v129: f64 = v112 * v116;
        let v130: f64 = v129 * v119;
        let v131: f64 = v124 * v126;
        let v132: f64 = v130 - v131;
        let v133: f64 = v132 * v7;
        let v134: f64 = v113 + v122;
        let v135: f64 = v134 * v13;
        let v136: f64 = v133 + v135;
        let v137: f64 = v136 * v17;
        let v138: f64 = v134 * v7;
        let v139: f64 = v131 - v130;
        let v140: f64 = v139 * v13;
        let v141: f64 = v138 + v140;
        let v142: f64 = v141 * v31;
        let v143: f64 = v137 + v142;
        let v144: f64 = v143 * v20;
        let v145: f64 = v128 + v144;
        let v146: f64 = v145 * v36;
        let v147: f64 = v1 + v3;
        let v148: f64 = v147 * v20;
        let v149: f64 = v147 * v13;
        let v150: f64 = v149 * v31;
        let v151: f64 = v147 * v7;
        let v152: f64 = v151 * v17;
        let v153: f64 = v150 - v152;
        let v154: f64 = v153 * v113;
        let v155: f64 = v148 + v154;
        let v156: f64 = v7 * v17;
        let v157: f64 = v13 * v31;
        let v158: f64 = v156 - v157;
        let v159: f64 = v158 * v113;
        let v160: f64 = v20 + v159;
        let v161: f64 = v160 * v119;
        let v162: f64 = v149 * v17;
        let v163: f64 = v151 * v31;
        let v164: f64 = v162 + v163;
        let v165: f64 = v164 * v126;
        let v166: f64 = v161 - v165;
        let v167: f64 = v166 * v124;
        let v168: f64 = v155 + v167;
        let v169: f64 = v124 * v119;
        let v170: f64 = v147 + v169;
        let v171: f64 = v170 * v13;
        let v172: f64 = v171 * v31;
        let v173: f64 = v170 * v7;
        let v174: f64 = v173 * v17;
        let v175: f64 = v172 - v174;
        let v176: f64 = v175 * v121;
        let v177: f64 = v20 * v126;
        let v178: f64 = v113 * v126;
        let v179: f64 = v178 * v7;
        let v180: f64 = v147 * v119;
        let v181: f64 = v124 + v180;
        let v182: f64 = v181 * v13;
        let v183: f64 = v179 + v182;
        let v184: f64 = v183 * v17;
        let v185: f64 = v177 + v184;
        let v186: f64 = v181 * v7;
        let v187: f64 = v178 * v13;
        let v188: f64 = v186 - v187;
        let v189: f64 = v188 * v31;
        let v190: f64 = v185 + v189;
        let v191: f64 = v190 * v116;
        let v192: f64 = v176 + v191;
        let v193: f64 = v192 * v112;
        let v194: f64 = v168 + v193;
        let v195: f64 = v194 * v81;
        let v196: f64 = v146 + v195;
        let v197: f64 = v113 - v122;
        let v198: f64 = v197 * v124;
        let v199: f64 = v198 * v126;
        let v200: f64 = v199 - v120;
        let v201: f64 = v139 * v7;
        let v202: f64 = v201 - v135;
        let v203: f64 = v202 * v17;
        let v204: f64 = v132 * v13;
        let v205: f64 = v204 - v138;
        let v206: f64 = v205 * v31;
        let v207: f64 = v203 + v206;
        let v208: f64 = v207 * v20;
        let v209: f64 = v200 + v208;
        let v210: f64 = v209 * v81;
        let v211: f64 = v194 * v36;
        let v212: f64 = v210 + v211;
        let v213: f64 = v152 - v150;
        let v214: f64 = v213 * v124;
        let v215: f64 = v214 * v126;
        let v216: f64 = v169 - v147;
        let v217: f64 = v216 * v13;
        let v218: f64 = v217 * v17;
        let v219: f64 = v216 * v7;
        let v220: f64 = v219 * v31;
        let v221: f64 = v218 + v220;
        let v222: f64 = v221 * v113;
        let v223: f64 = v215 + v222;
        let v224: f64 = v187 - v186;
        let v225: f64 = v224 * v17;
        let v226: f64 = v183 * v31;
        let v227: f64 = v225 + v226;
        let v228: f64 = v227 * v116;
        let v229: f64 = v171 * v17;
        let v230: f64 = v173 * v31;
        let v231: f64 = v229 + v230;
        let v232: f64 = v231 * v121;
        let v233: f64 = v228 - v232;
        let v234: f64 = v233 * v112;
        let v235: f64 = v223 + v234;
        (v196, v212, v235)
    };
    [v83, v95, v111, v196, v212, v235]
}
/// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `mass_matrix: [[f64; 6]; 6]` (6 x 6, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
///
/// Operation count: 263 floating-point operations, 8 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn mass_matrix(q: &[f64; 6]) -> [[f64; 6]; 6] {
    let (
        v3,
        v4,
        v5,
        v9,
        v12,
        v15,
        v29,
        v32,
        v33,
        v34,
        v36,
        v43,
        v50,
        v53,
        v59,
        v63,
        v78,
        v135,
        v138,
        v139,
        v140,
        v141,
        v142,
        v144,
        v147,
        v149,
        v151,
        v152,
        v153,
        v154,
        v155,
        v159,
    ) = {
        let v0: f64 = 1.553523243625_f64;
        let v1: f64 = 0.00020216_f64;
        let v2: f64 = q[4];
        let v3: f64 = ::libm::cos(v2);
        let v4: f64 = v1 * v3;
        let v5: f64 = v4 * v3;
        let v6: f64 = v0 - v5;
        let v7: f64 = 0.000864288_f64;
        let v8: f64 = q[3];
        let v9: f64 = ::libm::sin(v8);
        let v10: f64 = v7 * v9;
        let v11: f64 = 0.000116928_f64;
        let v12: f64 = ::libm::cos(v8);
        let v13: f64 = v11 * v12;
        let v14: f64 = v10 - v13;
        let v15: f64 = ::libm::sin(v2);
        let v16: f64 = v14 * v15;
        let v17: f64 = v6 + v16;
        let v18: f64 = 0.022546398_f64;
        let v19: f64 = v11 * v3;
        let v20: f64 = v18 + v19;
        let v21: f64 = -0.002487168_f64;
        let v22: f64 = 0.00040432_f64;
        let v23: f64 = v22 * v3;
        let v24: f64 = v21 - v23;
        let v25: f64 = v24 * v15;
        let v26: f64 = v25 * v12;
        let v27: f64 = v20 + v26;
        let v28: f64 = q[2];
        let v29: f64 = ::libm::sin(v28);
        let v30: f64 = v27 * v29;
        let v31: f64 = 0.3239198455_f64;
        let v32: f64 = 0.002487168_f64;
        let v33: f64 = v32 + v4;
        let v34: f64 = v33 * v3;
        let v35: f64 = v31 + v34;
        let v36: f64 = v11 * v15;
        let v37: f64 = -0.00030216_f64;
        let v38: f64 = v37 + v5;
        let v39: f64 = v38 * v12;
        let v40: f64 = v36 + v39;
        let v41: f64 = v40 * v12;
        let v42: f64 = v35 + v41;
        let v43: f64 = ::libm::cos(v28);
        let v44: f64 = v42 * v43;
        let v45: f64 = v30 + v44;
        let v46: f64 = v45 * v43;
        let v47: f64 = v17 + v46;
        let v48: f64 = 0.008347998_f64;
        let v49: f64 = v48 + v19;
        let v50: f64 = 0.02191385_f64;
        let v51: f64 = v50 * v29;
        let v52: f64 = v49 - v51;
        let v53: f64 = v32 * v29;
        let v54: f64 = v24 + v53;
        let v55: f64 = v54 * v15;
        let v56: f64 = v55 * v12;
        let v57: f64 = v52 + v56;
        let v58: f64 = q[1];
        let v59: f64 = ::libm::sin(v58);
        let v60: f64 = v57 * v59;
        let v61: f64 = 1.9257810475_f64;
        let v62: f64 = 0.769752588_f64;
        let v63: f64 = v62 * v29;
        let v64: f64 = v61 - v63;
        let v65: f64 = 0.00030216_f64;
        let v66: f64 = v65 * v12;
        let v67: f64 = v36 - v66;
        let v68: f64 = v67 * v12;
        let v69: f64 = v64 + v68;
        let v70: f64 = v32 - v53;
        let v71: f64 = v1 * v12;
        let v72: f64 = v71 * v12;
        let v73: f64 = v1 + v72;
        let v74: f64 = v73 * v3;
        let v75: f64 = v70 + v74;
        let v76: f64 = v75 * v3;
        let v77: f64 = v69 + v76;
        let v78: f64 = ::libm::cos(v58);
        let v79: f64 = v77 * v78;
        let v80: f64 = v60 + v79;
        let v81: f64 = v32 * v15;
        let v82: f64 = v81 * v12;
        let v83: f64 = v50 - v82;
        let v84: f64 = -0.045092796_f64;
        let v85: f64 = 0.000233856_f64;
        let v86: f64 = v85 * v3;
        let v87: f64 = v84 - v86;
        let v88: f64 = 0.004974336_f64;
        let v89: f64 = 0.00080864_f64;
        let v90: f64 = v89 * v3;
        let v91: f64 = v88 + v90;
        let v92: f64 = v91 * v15;
        let v93: f64 = v92 * v12;
        let v94: f64 = v87 + v93;
        let v95: f64 = v94 * v29;
        let v96: f64 = v83 + v95;
        let v97: f64 = -0.647839691_f64;
        let v98: f64 = -0.004974336_f64;
        let v99: f64 = v98 - v23;
        let v100: f64 = v99 * v3;
        let v101: f64 = v97 + v100;
        let v102: f64 = 0.00060432_f64;
        let v103: f64 = v23 * v3;
        let v104: f64 = v102 - v103;
        let v105: f64 = v104 * v12;
        let v106: f64 = v85 * v15;
        let v107: f64 = v105 - v106;
        let v108: f64 = v107 * v12;
        let v109: f64 = v101 + v108;
        let v110: f64 = v109 * v43;
        let v111: f64 = v96 + v110;
        let v112: f64 = v111 * v78;
        let v113: f64 = -0.769752588_f64;
        let v114: f64 = v32 * v3;
        let v115: f64 = v113 - v114;
        let v116: f64 = v94 * v43;
        let v117: f64 = v115 + v116;
        let v118: f64 = 0.647839691_f64;
        let v119: f64 = v88 + v23;
        let v120: f64 = v119 * v3;
        let v121: f64 = v118 + v120;
        let v122: f64 = -0.00060432_f64;
        let v123: f64 = v122 + v103;
        let v124: f64 = v123 * v12;
        let v125: f64 = v106 + v124;
        let v126: f64 = v125 * v12;
        let v127: f64 = v121 + v126;
        let v128: f64 = v127 * v29;
        let v129: f64 = v117 + v128;
        let v130: f64 = v129 * v59;
        let v131: f64 = v112 + v130;
        let v132: f64 = v131 * v43;
        let v133: f64 = v80 + v132;
        let v134: f64 = v133 * v78;
        let v135: f64 = v47 + v134;
        let v136: f64 = -0.023751_f64;
        let v137: f64 = -0.1384816665_f64;
        let v138: f64 = 0.000432144_f64;
        let v139: f64 = v138 * v3;
        let v140: f64 = v137 - v139;
        let v141: f64 = -0.001243584_f64;
        let v142: f64 = v141 - v4;
        let v143: f64 = v142 * v15;
        let v144: f64 = v143 * v9;
        let v145: f64 = v140 + v144;
        let v146: f64 = v145 * v43;
        let v147: f64 = v136 + v146;
        let v148: f64 = -0.00380751875_f64;
        let v149: f64 = v138 * v15;
        let v150: f64 = v149 * v12;
        let v151: f64 = v148 + v150;
        let v152: f64 = v65 - v5;
        let v153: f64 = v152 * v12;
        let v154: f64 = 5.8464e-05_f64;
        let v155: f64 = v154 * v15;
        let v156: f64 = v153 - v155;
        let v157: f64 = v156 * v9;
        let v158: f64 = v151 + v157;
        let v159: f64 = v158 * v29;
        (
            v3,
            v4,
            v5,
            v9,
            v12,
            v15,
            v29,
            v32,
            v33,
            v34,
            v36,
            v43,
            v50,
            v53,
            v59,
            v63,
            v78,
            v135,
            v138,
            v139,
            v140,
            v141,
            v142,
            v144,
            v147,
            v149,
            v151,
            v152,
            v153,
            v154,
            v155,
            v159,
        )
    };
    let (
        v181,
        v205,
        v207,
        v229,
        v240,
        v256,
        v257,
        v258,
        v269,
        v283,
        v298,
        v301,
        v309,
        v310,
        v314,
        v318,
        v319,
    ) = {
        let v160: f64 = v147 + v159;
        let v161: f64 = v160 * v78;
        let v162: f64 = -0.6903913435_f64;
        let v163: f64 = v151 * v43;
        let v164: f64 = v162 + v163;
        let v165: f64 = 0.1384816665_f64;
        let v166: f64 = v165 + v139;
        let v167: f64 = v166 * v29;
        let v168: f64 = v164 + v167;
        let v169: f64 = v153 * v43;
        let v170: f64 = v154 * v43;
        let v171: f64 = v141 - v170;
        let v172: f64 = 0.001243584_f64;
        let v173: f64 = v172 + v4;
        let v174: f64 = v173 * v29;
        let v175: f64 = v171 + v174;
        let v176: f64 = v175 * v15;
        let v177: f64 = v169 + v176;
        let v178: f64 = v177 * v9;
        let v179: f64 = v168 + v178;
        let v180: f64 = v179 * v59;
        let v181: f64 = v161 + v180;
        let v182: f64 = v140 * v43;
        let v183: f64 = v151 * v29;
        let v184: f64 = v182 + v183;
        let v185: f64 = v184 * v78;
        let v186: f64 = v163 + v167;
        let v187: f64 = v186 * v59;
        let v188: f64 = v185 + v187;
        let v189: f64 = v152 * v29;
        let v190: f64 = v189 * v78;
        let v191: f64 = v152 * v43;
        let v192: f64 = v191 * v59;
        let v193: f64 = v190 + v192;
        let v194: f64 = v193 * v12;
        let v195: f64 = v142 * v43;
        let v196: f64 = v154 * v29;
        let v197: f64 = v195 - v196;
        let v198: f64 = v197 * v78;
        let v199: f64 = v174 - v170;
        let v200: f64 = v199 * v59;
        let v201: f64 = v198 + v200;
        let v202: f64 = v201 * v15;
        let v203: f64 = v194 + v202;
        let v204: f64 = v203 * v9;
        let v205: f64 = v188 + v204;
        let v206: f64 = 0.00184216_f64;
        let v207: f64 = v206 - v5;
        let v208: f64 = v207 * v43;
        let v209: f64 = v208 * v78;
        let v210: f64 = -0.00184216_f64;
        let v211: f64 = v210 + v5;
        let v212: f64 = v211 * v29;
        let v213: f64 = v212 * v59;
        let v214: f64 = v209 + v213;
        let v215: f64 = v138 * v43;
        let v216: f64 = v215 * v78;
        let v217: f64 = v138 * v29;
        let v218: f64 = v217 * v59;
        let v219: f64 = v216 - v218;
        let v220: f64 = v219 * v9;
        let v221: f64 = v173 * v43;
        let v222: f64 = v196 + v221;
        let v223: f64 = v222 * v59;
        let v224: f64 = v175 * v78;
        let v225: f64 = v223 + v224;
        let v226: f64 = v225 * v12;
        let v227: f64 = v220 + v226;
        let v228: f64 = v227 * v15;
        let v229: f64 = v214 + v228;
        let v230: f64 = v149 * v29;
        let v231: f64 = v139 * v12;
        let v232: f64 = v231 * v43;
        let v233: f64 = v230 - v232;
        let v234: f64 = v233 * v78;
        let v235: f64 = v149 * v43;
        let v236: f64 = v231 * v29;
        let v237: f64 = v235 + v236;
        let v238: f64 = v237 * v59;
        let v239: f64 = v234 + v238;
        let v240: f64 = 0.00064216_f64;
        let v241: f64 = v240 * v29;
        let v242: f64 = v241 * v78;
        let v243: f64 = v240 * v43;
        let v244: f64 = v243 * v59;
        let v245: f64 = v242 + v244;
        let v246: f64 = v172 * v43;
        let v247: f64 = v246 + v196;
        let v248: f64 = v247 * v59;
        let v249: f64 = v172 * v29;
        let v250: f64 = v171 + v249;
        let v251: f64 = v250 * v78;
        let v252: f64 = v248 + v251;
        let v253: f64 = v252 * v3;
        let v254: f64 = v245 + v253;
        let v255: f64 = v254 * v9;
        let v256: f64 = v239 + v255;
        let v257: f64 = 4e-05_f64;
        let v258: f64 = v257 * v3;
        let v259: f64 = v258 * v43;
        let v260: f64 = v257 * v15;
        let v261: f64 = v260 * v12;
        let v262: f64 = v261 * v29;
        let v263: f64 = v259 - v262;
        let v264: f64 = v263 * v78;
        let v265: f64 = v261 * v43;
        let v266: f64 = v258 * v29;
        let v267: f64 = v265 + v266;
        let v268: f64 = v267 * v59;
        let v269: f64 = v264 - v268;
        let v270: f64 = 2.1071040725_f64;
        let v271: f64 = v50 * v43;
        let v272: f64 = v270 + v271;
        let v273: f64 = v272 - v63;
        let v274: f64 = v33 - v53;
        let v275: f64 = v274 * v3;
        let v276: f64 = v273 + v275;
        let v277: f64 = -0.000116928_f64;
        let v278: f64 = v32 * v43;
        let v279: f64 = v277 - v278;
        let v280: f64 = v279 * v15;
        let v281: f64 = v280 + v153;
        let v282: f64 = v281 * v12;
        let v283: f64 = v276 + v282;
        let v284: f64 = 0.3589900705_f64;
        let v285: f64 = 0.010956925_f64;
        let v286: f64 = v285 * v43;
        let v287: f64 = v284 + v286;
        let v288: f64 = 0.384876294_f64;
        let v289: f64 = v288 * v29;
        let v290: f64 = v287 - v289;
        let v291: f64 = v33 - v249;
        let v292: f64 = v291 * v3;
        let v293: f64 = v290 + v292;
        let v294: f64 = v277 - v246;
        let v295: f64 = v294 * v15;
        let v296: f64 = v295 + v153;
        let v297: f64 = v296 * v12;
        let v298: f64 = v293 + v297;
        let v299: f64 = v142 + v249;
        let v300: f64 = v299 * v15;
        let v301: f64 = v300 * v9;
        let v302: f64 = -5.8464e-05_f64;
        let v303: f64 = v302 - v246;
        let v304: f64 = v303 * v15;
        let v305: f64 = v172 - v249;
        let v306: f64 = v305 * v3;
        let v307: f64 = v240 + v306;
        let v308: f64 = v307 * v12;
        let v309: f64 = v304 + v308;
        let v310: f64 = v260 * v9;
        let v311: f64 = v284 + v34;
        let v312: f64 = v153 - v36;
        let v313: f64 = v312 * v12;
        let v314: f64 = v311 + v313;
        let v315: f64 = v172 * v3;
        let v316: f64 = v240 + v315;
        let v317: f64 = v316 * v12;
        let v318: f64 = v317 - v155;
        let v319: f64 = 0.0_f64;
        (
            v181,
            v205,
            v207,
            v229,
            v240,
            v256,
            v257,
            v258,
            v269,
            v283,
            v298,
            v301,
            v309,
            v310,
            v314,
            v318,
            v319,
        )
    };
    [
        [v135, v181, v205, v229, v256, v269],
        [v181, v283, v298, v301, v309, v310],
        [v205, v298, v314, v144, v318, v310],
        [v229, v301, v144, v207, v319, v258],
        [v256, v309, v318, v319, v240, v319],
        [v269, v310, v310, v258, v319, v257],
    ]
}
/// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 6]`: joint velocities qd (rad/s or m/s)
///
/// # Output
///
/// `coriolis_matrix: [[f64; 6]; 6]` (6 x 6, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
///
/// Operation count: 1471 floating-point operations, 8 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn coriolis_matrix(q: &[f64; 6], qd: &[f64; 6]) -> [[f64; 6]; 6] {
    let (
        v0,
        v1,
        v3,
        v4,
        v6,
        v8,
        v9,
        v12,
        v14,
        v15,
        v16,
        v17,
        v18,
        v20,
        v22,
        v24,
        v27,
        v30,
        v32,
        v33,
        v35,
        v37,
        v38,
        v39,
        v40,
        v43,
        v44,
        v49,
        v52,
        v53,
        v54,
        v56,
        v60,
        v66,
        v67,
        v68,
        v72,
        v73,
        v74,
        v75,
        v76,
        v77,
        v80,
        v84,
        v87,
        v88,
        v96,
        v103,
        v108,
        v109,
        v110,
        v114,
        v115,
        v119,
        v120,
        v128,
        v129,
        v130,
        v131,
        v138,
        v139,
        v142,
        v146,
        v147,
        v149,
        v152,
        v153,
        v159,
        v162,
        v163,
        v171,
        v172,
        v173,
        v174,
        v178,
        v179,
        v181,
        v183,
        v191,
        v192,
        v193,
    ) = {
        let v0: f64 = -0.004173999_f64;
        let v1: f64 = 0.010956925_f64;
        let v2: f64 = q[2];
        let v3: f64 = ::libm::sin(v2);
        let v4: f64 = v1 * v3;
        let v5: f64 = v0 + v4;
        let v6: f64 = qd[1];
        let v7: f64 = v5 * v6;
        let v8: f64 = 0.011273199_f64;
        let v9: f64 = qd[2];
        let v10: f64 = v8 * v9;
        let v11: f64 = v7 - v10;
        let v12: f64 = 0.000432144_f64;
        let v13: f64 = q[3];
        let v14: f64 = ::libm::sin(v13);
        let v15: f64 = v12 * v14;
        let v16: f64 = 5.8464e-05_f64;
        let v17: f64 = ::libm::cos(v13);
        let v18: f64 = v16 * v17;
        let v19: f64 = v15 - v18;
        let v20: f64 = qd[4];
        let v21: f64 = v19 * v20;
        let v22: f64 = v16 * v9;
        let v23: f64 = v16 * v6;
        let v24: f64 = v22 + v23;
        let v25: f64 = v21 - v24;
        let v26: f64 = q[4];
        let v27: f64 = ::libm::cos(v26);
        let v28: f64 = v25 * v27;
        let v29: f64 = v11 + v28;
        let v30: f64 = 0.00020216_f64;
        let v31: f64 = v30 * v20;
        let v32: f64 = v31 * v27;
        let v33: f64 = qd[3];
        let v34: f64 = v16 * v33;
        let v35: f64 = v34 * v14;
        let v36: f64 = v32 + v35;
        let v37: f64 = v12 * v33;
        let v38: f64 = 0.001243584_f64;
        let v39: f64 = v30 * v27;
        let v40: f64 = v38 + v39;
        let v41: f64 = v40 * v9;
        let v42: f64 = v37 + v41;
        let v43: f64 = v38 * v3;
        let v44: f64 = v40 - v43;
        let v45: f64 = v44 * v6;
        let v46: f64 = v42 + v45;
        let v47: f64 = v46 * v17;
        let v48: f64 = v36 + v47;
        let v49: f64 = ::libm::sin(v26);
        let v50: f64 = v48 * v49;
        let v51: f64 = v29 + v50;
        let v52: f64 = 0.384876294_f64;
        let v53: f64 = v38 * v27;
        let v54: f64 = v52 + v53;
        let v55: f64 = v54 * v6;
        let v56: f64 = 0.022546398_f64;
        let v57: f64 = v56 * v9;
        let v58: f64 = v56 * v6;
        let v59: f64 = v57 + v58;
        let v60: f64 = 0.000116928_f64;
        let v61: f64 = v60 * v9;
        let v62: f64 = v60 * v6;
        let v63: f64 = v61 + v62;
        let v64: f64 = v63 * v27;
        let v65: f64 = v59 + v64;
        let v66: f64 = -0.001243584_f64;
        let v67: f64 = v66 - v39;
        let v68: f64 = v67 * v20;
        let v69: f64 = v68 - v35;
        let v70: f64 = v69 * v49;
        let v71: f64 = v65 + v70;
        let v72: f64 = v16 * v20;
        let v73: f64 = v72 * v27;
        let v74: f64 = 0.00030216_f64;
        let v75: f64 = v39 * v27;
        let v76: f64 = v74 - v75;
        let v77: f64 = v76 * v33;
        let v78: f64 = v77 * v14;
        let v79: f64 = v73 + v78;
        let v80: f64 = 0.002487168_f64;
        let v81: f64 = v80 * v9;
        let v82: f64 = v80 * v6;
        let v83: f64 = v81 + v82;
        let v84: f64 = 0.00040432_f64;
        let v85: f64 = v84 * v9;
        let v86: f64 = v84 * v6;
        let v87: f64 = v85 + v86;
        let v88: f64 = v31 * v17;
        let v89: f64 = v87 + v88;
        let v90: f64 = v89 * v27;
        let v91: f64 = v83 + v90;
        let v92: f64 = v91 * v49;
        let v93: f64 = v79 - v92;
        let v94: f64 = v93 * v17;
        let v95: f64 = v71 + v94;
        let v96: f64 = ::libm::cos(v2);
        let v97: f64 = v95 * v96;
        let v98: f64 = v55 + v97;
        let v99: f64 = v38 * v33;
        let v100: f64 = v99 * v14;
        let v101: f64 = v100 - v72;
        let v102: f64 = v101 * v49;
        let v103: f64 = 0.3239198455_f64;
        let v104: f64 = v103 * v9;
        let v105: f64 = v103 * v6;
        let v106: f64 = v104 + v105;
        let v107: f64 = v102 - v106;
        let v108: f64 = v30 * v33;
        let v109: f64 = v108 * v49;
        let v110: f64 = v109 * v14;
        let v111: f64 = v110 - v83;
        let v112: f64 = v30 * v9;
        let v113: f64 = v30 * v6;
        let v114: f64 = v112 + v113;
        let v115: f64 = v114 * v27;
        let v116: f64 = v111 - v115;
        let v117: f64 = v116 * v27;
        let v118: f64 = v107 + v117;
        let v119: f64 = v84 * v27;
        let v120: f64 = v66 - v119;
        let v121: f64 = v120 * v27;
        let v122: f64 = v30 + v121;
        let v123: f64 = v122 * v20;
        let v124: f64 = v63 * v49;
        let v125: f64 = v123 - v124;
        let v126: f64 = v74 * v9;
        let v127: f64 = v74 * v6;
        let v128: f64 = v126 + v127;
        let v129: f64 = v115 * v27;
        let v130: f64 = v128 - v129;
        let v131: f64 = v130 * v17;
        let v132: f64 = v125 + v131;
        let v133: f64 = v132 * v17;
        let v134: f64 = v118 + v133;
        let v135: f64 = v134 * v3;
        let v136: f64 = v98 + v135;
        let v137: f64 = v136 * v96;
        let v138: f64 = v51 + v137;
        let v139: f64 = 0.008347998_f64;
        let v140: f64 = v139 * v6;
        let v141: f64 = v57 + v140;
        let v142: f64 = v74 * v33;
        let v143: f64 = v142 * v17;
        let v144: f64 = v143 * v14;
        let v145: f64 = v141 + v144;
        let v146: f64 = v1 * v9;
        let v147: f64 = 0.02191385_f64;
        let v148: f64 = v147 * v6;
        let v149: f64 = v146 + v148;
        let v150: f64 = v149 * v3;
        let v151: f64 = v145 - v150;
        let v152: f64 = v108 * v27;
        let v153: f64 = v152 * v14;
        let v154: f64 = v72 - v153;
        let v155: f64 = v154 * v17;
        let v156: f64 = v63 + v155;
        let v157: f64 = v156 * v27;
        let v158: f64 = v151 + v157;
        let v159: f64 = v67 + v43;
        let v160: f64 = v159 * v20;
        let v161: f64 = v160 - v35;
        let v162: f64 = v38 * v9;
        let v163: f64 = v162 + v82;
        let v164: f64 = v163 * v3;
        let v165: f64 = v164 - v83;
        let v166: f64 = v165 - v90;
        let v167: f64 = v166 * v17;
        let v168: f64 = v161 + v167;
        let v169: f64 = v168 * v49;
        let v170: f64 = v158 + v169;
        let v171: f64 = q[1];
        let v172: f64 = ::libm::cos(v171);
        let v173: f64 = v170 * v172;
        let v174: f64 = 1.9257810475_f64;
        let v175: f64 = v174 * v6;
        let v176: f64 = v104 + v175;
        let v177: f64 = v102 - v176;
        let v178: f64 = v52 * v9;
        let v179: f64 = 0.769752588_f64;
        let v180: f64 = v179 * v6;
        let v181: f64 = v178 + v180;
        let v182: f64 = v99 * v49;
        let v183: f64 = v182 * v14;
        let v184: f64 = v181 - v183;
        let v185: f64 = v184 * v3;
        let v186: f64 = v177 + v185;
        let v187: f64 = v31 - v124;
        let v188: f64 = v128 * v17;
        let v189: f64 = v187 + v188;
        let v190: f64 = v189 * v17;
        let v191: f64 = v186 + v190;
        let v192: f64 = -0.002487168_f64;
        let v193: f64 = v192 - v39;
        (
            v0,
            v1,
            v3,
            v4,
            v6,
            v8,
            v9,
            v12,
            v14,
            v15,
            v16,
            v17,
            v18,
            v20,
            v22,
            v24,
            v27,
            v30,
            v32,
            v33,
            v35,
            v37,
            v38,
            v39,
            v40,
            v43,
            v44,
            v49,
            v52,
            v53,
            v54,
            v56,
            v60,
            v66,
            v67,
            v68,
            v72,
            v73,
            v74,
            v75,
            v76,
            v77,
            v80,
            v84,
            v87,
            v88,
            v96,
            v103,
            v108,
            v109,
            v110,
            v114,
            v115,
            v119,
            v120,
            v128,
            v129,
            v130,
            v131,
            v138,
            v139,
            v142,
            v146,
            v147,
            v149,
            v152,
            v153,
            v159,
            v162,
            v163,
            v171,
            v172,
            v173,
            v174,
            v178,
            v179,
            v181,
            v183,
            v191,
            v192,
            v193,
        )
    };
    let (
        v197,
        v201,
        v212,
        v215,
        v216,
        v218,
        v222,
        v228,
        v237,
        v247,
        v264,
        v265,
        v283,
        v284,
        v350,
        v351,
        v357,
        v360,
        v361,
        v362,
        v365,
        v367,
        v368,
        v370,
        v371,
        v372,
        v376,
        v377,
        v379,
        v383,
        v384,
        v385,
        v386,
        v387,
    ) = {
        let v194: f64 = v193 + v43;
        let v195: f64 = v194 * v9;
        let v196: f64 = v110 + v195;
        let v197: f64 = v80 * v3;
        let v198: f64 = v193 + v197;
        let v199: f64 = v198 * v6;
        let v200: f64 = v196 + v199;
        let v201: f64 = v66 + v43;
        let v202: f64 = v201 * v20;
        let v203: f64 = v84 * v20;
        let v204: f64 = v114 * v17;
        let v205: f64 = v203 + v204;
        let v206: f64 = v205 * v27;
        let v207: f64 = v202 - v206;
        let v208: f64 = v207 * v17;
        let v209: f64 = v200 + v208;
        let v210: f64 = v209 * v27;
        let v211: f64 = v191 + v210;
        let v212: f64 = ::libm::sin(v171);
        let v213: f64 = v211 * v212;
        let v214: f64 = v173 + v213;
        let v215: f64 = v38 * v20;
        let v216: f64 = v215 * v49;
        let v217: f64 = v216 - v149;
        let v218: f64 = 0.045092796_f64;
        let v219: f64 = v218 * v9;
        let v220: f64 = v218 * v6;
        let v221: f64 = v219 + v220;
        let v222: f64 = 0.000233856_f64;
        let v223: f64 = v222 * v9;
        let v224: f64 = v222 * v6;
        let v225: f64 = v223 + v224;
        let v226: f64 = v225 * v27;
        let v227: f64 = v221 + v226;
        let v228: f64 = v192 - v119;
        let v229: f64 = v228 * v20;
        let v230: f64 = v60 * v33;
        let v231: f64 = v230 * v14;
        let v232: f64 = v229 - v231;
        let v233: f64 = v232 * v49;
        let v234: f64 = v227 + v233;
        let v235: f64 = v234 * v3;
        let v236: f64 = v217 + v235;
        let v237: f64 = 0.647839691_f64;
        let v238: f64 = v237 * v9;
        let v239: f64 = v237 * v6;
        let v240: f64 = v238 + v239;
        let v241: f64 = v60 * v20;
        let v242: f64 = v80 * v33;
        let v243: f64 = v242 * v14;
        let v244: f64 = v241 - v243;
        let v245: f64 = v244 * v49;
        let v246: f64 = v240 + v245;
        let v247: f64 = 0.004974336_f64;
        let v248: f64 = v247 * v9;
        let v249: f64 = v247 * v6;
        let v250: f64 = v248 + v249;
        let v251: f64 = v84 * v33;
        let v252: f64 = v251 * v49;
        let v253: f64 = v252 * v14;
        let v254: f64 = v250 - v253;
        let v255: f64 = v87 * v27;
        let v256: f64 = v254 + v255;
        let v257: f64 = v256 * v27;
        let v258: f64 = v246 + v257;
        let v259: f64 = v258 * v96;
        let v260: f64 = v236 + v259;
        let v261: f64 = v163 * v49;
        let v262: f64 = v241 * v27;
        let v263: f64 = 0.00060432_f64;
        let v264: f64 = v119 * v27;
        let v265: f64 = v263 - v264;
        let v266: f64 = v265 * v33;
        let v267: f64 = v266 * v14;
        let v268: f64 = v262 + v267;
        let v269: f64 = 0.00080864_f64;
        let v270: f64 = v269 * v9;
        let v271: f64 = v269 * v6;
        let v272: f64 = v270 + v271;
        let v273: f64 = v203 * v17;
        let v274: f64 = v272 + v273;
        let v275: f64 = v274 * v27;
        let v276: f64 = v250 + v275;
        let v277: f64 = v276 * v49;
        let v278: f64 = v268 - v277;
        let v279: f64 = v278 * v3;
        let v280: f64 = v261 + v279;
        let v281: f64 = v225 * v49;
        let v282: f64 = -0.00040432_f64;
        let v283: f64 = v269 * v27;
        let v284: f64 = v80 + v283;
        let v285: f64 = v284 * v27;
        let v286: f64 = v282 + v285;
        let v287: f64 = v286 * v20;
        let v288: f64 = v281 + v287;
        let v289: f64 = v255 * v27;
        let v290: f64 = v263 * v9;
        let v291: f64 = v263 * v6;
        let v292: f64 = v290 + v291;
        let v293: f64 = v289 - v292;
        let v294: f64 = v293 * v17;
        let v295: f64 = v288 + v294;
        let v296: f64 = v295 * v96;
        let v297: f64 = v280 + v296;
        let v298: f64 = v297 * v17;
        let v299: f64 = v260 + v298;
        let v300: f64 = v299 * v212;
        let v301: f64 = v183 - v181;
        let v302: f64 = v80 * v20;
        let v303: f64 = v302 + v231;
        let v304: f64 = v250 * v17;
        let v305: f64 = v303 + v304;
        let v306: f64 = v305 * v49;
        let v307: f64 = v263 * v33;
        let v308: f64 = v307 * v17;
        let v309: f64 = v308 * v14;
        let v310: f64 = v221 + v309;
        let v311: f64 = v306 - v310;
        let v312: f64 = v311 * v96;
        let v313: f64 = v301 + v312;
        let v314: f64 = v281 - v203;
        let v315: f64 = v292 * v17;
        let v316: f64 = v314 - v315;
        let v317: f64 = v316 * v17;
        let v318: f64 = v246 + v317;
        let v319: f64 = v318 * v3;
        let v320: f64 = v313 + v319;
        let v321: f64 = v203 * v49;
        let v322: f64 = v321 - v225;
        let v323: f64 = v322 * v96;
        let v324: f64 = v323 - v163;
        let v325: f64 = v256 * v3;
        let v326: f64 = v324 + v325;
        let v327: f64 = v269 * v20;
        let v328: f64 = v87 * v17;
        let v329: f64 = v327 + v328;
        let v330: f64 = v329 * v27;
        let v331: f64 = v302 + v330;
        let v332: f64 = v331 * v3;
        let v333: f64 = v332 - v215;
        let v334: f64 = v251 * v27;
        let v335: f64 = v334 * v14;
        let v336: f64 = v335 - v241;
        let v337: f64 = v274 * v49;
        let v338: f64 = v336 + v337;
        let v339: f64 = v338 * v96;
        let v340: f64 = v333 + v339;
        let v341: f64 = v340 * v17;
        let v342: f64 = v326 + v341;
        let v343: f64 = v342 * v27;
        let v344: f64 = v320 + v343;
        let v345: f64 = v344 * v172;
        let v346: f64 = v300 + v345;
        let v347: f64 = v346 * v96;
        let v348: f64 = v214 + v347;
        let v349: f64 = v348 * v172;
        let v350: f64 = v138 + v349;
        let v351: f64 = v16 * v27;
        let v352: f64 = v0 - v351;
        let v353: f64 = v352 + v4;
        let v354: f64 = v44 * v49;
        let v355: f64 = v354 * v17;
        let v356: f64 = v353 + v355;
        let v357: f64 = v60 * v27;
        let v358: f64 = v56 + v357;
        let v359: f64 = v228 * v49;
        let v360: f64 = v359 * v17;
        let v361: f64 = v358 + v360;
        let v362: f64 = v361 * v96;
        let v363: f64 = v54 + v362;
        let v364: f64 = -0.3239198455_f64;
        let v365: f64 = v193 * v27;
        let v366: f64 = v364 + v365;
        let v367: f64 = v76 * v17;
        let v368: f64 = v60 * v49;
        let v369: f64 = v367 - v368;
        let v370: f64 = v369 * v17;
        let v371: f64 = v366 + v370;
        let v372: f64 = v371 * v3;
        let v373: f64 = v363 + v372;
        let v374: f64 = v373 * v96;
        let v375: f64 = v356 + v374;
        let v376: f64 = qd[0];
        let v377: f64 = v375 * v376;
        let v378: f64 = 0.023751_f64;
        let v379: f64 = v378 * v6;
        let v380: f64 = 0.00380751875_f64;
        let v381: f64 = v380 * v9;
        let v382: f64 = v380 * v6;
        let v383: f64 = v381 + v382;
        let v384: f64 = 2e-05_f64;
        let v385: f64 = qd[5];
        let v386: f64 = v384 * v385;
        let v387: f64 = v12 * v9;
        (
            v197,
            v201,
            v212,
            v215,
            v216,
            v218,
            v222,
            v228,
            v237,
            v247,
            v264,
            v265,
            v283,
            v284,
            v350,
            v351,
            v357,
            v360,
            v361,
            v362,
            v365,
            v367,
            v368,
            v370,
            v371,
            v372,
            v376,
            v377,
            v379,
            v383,
            v384,
            v385,
            v386,
            v387,
        )
    };
    let (
        v390,
        v392,
        v399,
        v400,
        v401,
        v402,
        v403,
        v413,
        v419,
        v425,
        v480,
        v482,
        v483,
        v486,
        v488,
        v496,
        v502,
        v504,
        v514,
        v517,
        v521,
        v533,
        v536,
        v545,
        v555,
        v568,
        v570,
        v575,
        v581,
    ) = {
        let v388: f64 = v386 - v387;
        let v389: f64 = v12 * v6;
        let v390: f64 = v388 - v389;
        let v391: f64 = v390 * v17;
        let v392: f64 = v12 * v20;
        let v393: f64 = v391 - v392;
        let v394: f64 = v393 * v49;
        let v395: f64 = v383 + v394;
        let v396: f64 = -0.00042216_f64;
        let v397: f64 = v396 + v75;
        let v398: f64 = v397 * v20;
        let v399: f64 = v24 * v49;
        let v400: f64 = v398 + v399;
        let v401: f64 = v129 - v128;
        let v402: f64 = v401 * v17;
        let v403: f64 = v400 + v402;
        let v404: f64 = v403 * v14;
        let v405: f64 = v395 + v404;
        let v406: f64 = v405 * v3;
        let v407: f64 = v379 + v406;
        let v408: f64 = 0.1384816665_f64;
        let v409: f64 = v408 * v9;
        let v410: f64 = v408 * v6;
        let v411: f64 = v409 + v410;
        let v412: f64 = -0.00107216_f64;
        let v413: f64 = v74 * v17;
        let v414: f64 = v413 * v17;
        let v415: f64 = v412 + v414;
        let v416: f64 = v415 * v33;
        let v417: f64 = v411 + v416;
        let v418: f64 = v162 - v37;
        let v419: f64 = v38 * v6;
        let v420: f64 = v418 + v419;
        let v421: f64 = v420 * v49;
        let v422: f64 = v421 * v14;
        let v423: f64 = v417 + v422;
        let v424: f64 = v387 - v386;
        let v425: f64 = v424 + v389;
        let v426: f64 = v425 + v152;
        let v427: f64 = v152 * v17;
        let v428: f64 = v392 - v427;
        let v429: f64 = v428 * v17;
        let v430: f64 = v426 + v429;
        let v431: f64 = v114 + v88;
        let v432: f64 = v431 * v49;
        let v433: f64 = v432 * v14;
        let v434: f64 = v430 + v433;
        let v435: f64 = v434 * v27;
        let v436: f64 = v423 + v435;
        let v437: f64 = v436 * v96;
        let v438: f64 = v407 + v437;
        let v439: f64 = v438 * v212;
        let v440: f64 = v377 + v439;
        let v441: f64 = -0.6903913435_f64;
        let v442: f64 = v38 * v49;
        let v443: f64 = v442 * v14;
        let v444: f64 = v441 - v443;
        let v445: f64 = v444 * v6;
        let v446: f64 = v139 + v357;
        let v447: f64 = v446 + v360;
        let v448: f64 = v447 * v172;
        let v449: f64 = -1.9257810475_f64;
        let v450: f64 = v449 + v365;
        let v451: f64 = v450 + v370;
        let v452: f64 = v451 * v212;
        let v453: f64 = v448 + v452;
        let v454: f64 = v453 * v376;
        let v455: f64 = v445 + v454;
        let v456: f64 = v179 * v212;
        let v457: f64 = v147 * v172;
        let v458: f64 = v456 - v457;
        let v459: f64 = v458 * v376;
        let v460: f64 = v417 + v459;
        let v461: f64 = v80 * v376;
        let v462: f64 = v461 * v17;
        let v463: f64 = v462 * v172;
        let v464: f64 = v420 * v14;
        let v465: f64 = v463 + v464;
        let v466: f64 = v465 * v49;
        let v467: f64 = v460 + v466;
        let v468: f64 = v461 * v212;
        let v469: f64 = v426 + v468;
        let v470: f64 = v469 + v429;
        let v471: f64 = v470 + v433;
        let v472: f64 = v471 * v27;
        let v473: f64 = v467 + v472;
        let v474: f64 = v473 * v3;
        let v475: f64 = v455 + v474;
        let v476: f64 = v425 * v17;
        let v477: f64 = v392 + v476;
        let v478: f64 = v477 * v49;
        let v479: f64 = v478 - v383;
        let v480: f64 = 0.00042216_f64;
        let v481: f64 = v480 - v75;
        let v482: f64 = v481 * v20;
        let v483: f64 = v482 - v399;
        let v484: f64 = v483 + v131;
        let v485: f64 = v484 * v14;
        let v486: f64 = v479 + v485;
        let v487: f64 = -0.769752588_f64;
        let v488: f64 = v80 * v27;
        let v489: f64 = v487 - v488;
        let v490: f64 = -0.045092796_f64;
        let v491: f64 = v222 * v27;
        let v492: f64 = v490 - v491;
        let v493: f64 = v247 + v283;
        let v494: f64 = v493 * v49;
        let v495: f64 = v494 * v17;
        let v496: f64 = v492 + v495;
        let v497: f64 = v496 * v96;
        let v498: f64 = v489 + v497;
        let v499: f64 = v247 + v119;
        let v500: f64 = v499 * v27;
        let v501: f64 = v237 + v500;
        let v502: f64 = v222 * v49;
        let v503: f64 = -0.00060432_f64;
        let v504: f64 = v503 + v264;
        let v505: f64 = v504 * v17;
        let v506: f64 = v502 + v505;
        let v507: f64 = v506 * v17;
        let v508: f64 = v501 + v507;
        let v509: f64 = v508 * v3;
        let v510: f64 = v498 + v509;
        let v511: f64 = v510 * v172;
        let v512: f64 = -0.02191385_f64;
        let v513: f64 = v80 * v49;
        let v514: f64 = v513 * v17;
        let v515: f64 = v512 + v514;
        let v516: f64 = v218 + v491;
        let v517: f64 = -0.004974336_f64;
        let v518: f64 = v517 - v283;
        let v519: f64 = v518 * v49;
        let v520: f64 = v519 * v17;
        let v521: f64 = v516 + v520;
        let v522: f64 = v521 * v3;
        let v523: f64 = v515 + v522;
        let v524: f64 = v508 * v96;
        let v525: f64 = v523 + v524;
        let v526: f64 = v525 * v212;
        let v527: f64 = v511 + v526;
        let v528: f64 = v527 * v376;
        let v529: f64 = v486 + v528;
        let v530: f64 = v529 * v96;
        let v531: f64 = v475 + v530;
        let v532: f64 = v531 * v172;
        let v533: f64 = v440 + v532;
        let v534: f64 = -0.011273199_f64;
        let v535: f64 = v534 - v351;
        let v536: f64 = v40 * v49;
        let v537: f64 = v536 * v17;
        let v538: f64 = v535 + v537;
        let v539: f64 = v362 + v372;
        let v540: f64 = v539 * v96;
        let v541: f64 = v538 + v540;
        let v542: f64 = v541 * v376;
        let v543: f64 = v406 + v437;
        let v544: f64 = v543 * v212;
        let v545: f64 = v542 + v544;
        let v546: f64 = v361 * v172;
        let v547: f64 = v371 * v212;
        let v548: f64 = v546 + v547;
        let v549: f64 = v548 * v376;
        let v550: f64 = v52 * v212;
        let v551: f64 = v1 * v172;
        let v552: f64 = v550 - v551;
        let v553: f64 = v552 * v376;
        let v554: f64 = v417 + v553;
        let v555: f64 = v38 * v376;
        let v556: f64 = v555 * v17;
        let v557: f64 = v556 * v172;
        let v558: f64 = v557 + v464;
        let v559: f64 = v558 * v49;
        let v560: f64 = v554 + v559;
        let v561: f64 = v555 * v212;
        let v562: f64 = v426 + v561;
        let v563: f64 = v562 + v429;
        let v564: f64 = v563 + v433;
        let v565: f64 = v564 * v27;
        let v566: f64 = v560 + v565;
        let v567: f64 = v566 * v3;
        let v568: f64 = v549 + v567;
        let v569: f64 = -0.384876294_f64;
        let v570: f64 = v569 - v53;
        let v571: f64 = v570 + v497;
        let v572: f64 = v571 + v509;
        let v573: f64 = v572 * v172;
        let v574: f64 = -0.010956925_f64;
        let v575: f64 = v442 * v17;
        let v576: f64 = v574 + v575;
        let v577: f64 = v576 + v522;
        let v578: f64 = v577 + v524;
        let v579: f64 = v578 * v212;
        let v580: f64 = v573 + v579;
        let v581: f64 = v580 * v376;
        (
            v390,
            v392,
            v399,
            v400,
            v401,
            v402,
            v403,
            v413,
            v419,
            v425,
            v480,
            v482,
            v483,
            v486,
            v488,
            v496,
            v502,
            v504,
            v514,
            v517,
            v521,
            v533,
            v536,
            v545,
            v555,
            v568,
            v570,
            v575,
            v581,
        )
    };
    let (
        v586,
        v587,
        v589,
        v591,
        v615,
        v620,
        v631,
        v656,
        v657,
        v662,
        v665,
        v668,
        v683,
        v684,
        v688,
        v689,
        v690,
        v692,
        v693,
        v694,
        v695,
        v705,
        v716,
        v720,
        v728,
        v729,
        v730,
        v738,
        v740,
        v744,
        v746,
        v754,
        v758,
        v765,
        v774,
        v775,
    ) = {
        let v582: f64 = v486 + v581;
        let v583: f64 = v582 * v96;
        let v584: f64 = v568 + v583;
        let v585: f64 = v584 * v172;
        let v586: f64 = v545 + v585;
        let v587: f64 = v12 * v49;
        let v588: f64 = v587 * v17;
        let v589: f64 = v16 * v49;
        let v590: f64 = v536 * v3;
        let v591: f64 = v367 - v589;
        let v592: f64 = v591 * v96;
        let v593: f64 = v590 + v592;
        let v594: f64 = v593 * v96;
        let v595: f64 = v589 + v594;
        let v596: f64 = v595 * v14;
        let v597: f64 = v588 + v596;
        let v598: f64 = v597 * v376;
        let v599: f64 = v18 - v15;
        let v600: f64 = v599 * v20;
        let v601: f64 = v600 * v27;
        let v602: f64 = v12 * v17;
        let v603: f64 = v16 * v14;
        let v604: f64 = v602 + v603;
        let v605: f64 = v604 * v33;
        let v606: f64 = v32 + v605;
        let v607: f64 = v606 * v49;
        let v608: f64 = v601 - v607;
        let v609: f64 = v608 * v3;
        let v610: f64 = 0.00107216_f64;
        let v611: f64 = v610 * v9;
        let v612: f64 = v610 * v6;
        let v613: f64 = v611 + v612;
        let v614: f64 = v129 - v613;
        let v615: f64 = v67 * v33;
        let v616: f64 = v390 + v615;
        let v617: f64 = v616 * v49;
        let v618: f64 = v617 * v14;
        let v619: f64 = v614 + v618;
        let v620: f64 = 0.00022_f64;
        let v621: f64 = v40 * v27;
        let v622: f64 = v620 + v621;
        let v623: f64 = v622 * v20;
        let v624: f64 = v623 + v131;
        let v625: f64 = v624 * v17;
        let v626: f64 = v619 + v625;
        let v627: f64 = v626 * v96;
        let v628: f64 = v609 + v627;
        let v629: f64 = v628 * v212;
        let v630: f64 = v598 + v629;
        let v631: f64 = v32 * v49;
        let v632: f64 = v37 * v49;
        let v633: f64 = v632 - v73;
        let v634: f64 = v633 * v17;
        let v635: f64 = v631 + v634;
        let v636: f64 = v635 * v96;
        let v637: f64 = v215 * v27;
        let v638: f64 = v637 * v17;
        let v639: f64 = v636 - v638;
        let v640: f64 = v614 + v625;
        let v641: f64 = v640 * v3;
        let v642: f64 = v639 + v641;
        let v643: f64 = v392 * v27;
        let v644: f64 = v643 * v96;
        let v645: f64 = v265 * v96;
        let v646: f64 = v645 * v3;
        let v647: f64 = v646 * v212;
        let v648: f64 = v504 * v96;
        let v649: f64 = v648 * v96;
        let v650: f64 = v76 + v649;
        let v651: f64 = v650 * v172;
        let v652: f64 = v647 + v651;
        let v653: f64 = v652 * v376;
        let v654: f64 = v653 * v17;
        let v655: f64 = v644 + v654;
        let v656: f64 = v16 * v96;
        let v657: f64 = v38 + v656;
        let v658: f64 = v657 * v33;
        let v659: f64 = v616 * v3;
        let v660: f64 = v658 + v659;
        let v661: f64 = v44 * v212;
        let v662: f64 = v16 * v172;
        let v663: f64 = v661 - v662;
        let v664: f64 = v228 * v96;
        let v665: f64 = v60 * v3;
        let v666: f64 = v664 - v665;
        let v667: f64 = v666 * v212;
        let v668: f64 = v60 * v96;
        let v669: f64 = v38 + v668;
        let v670: f64 = v228 * v3;
        let v671: f64 = v669 + v670;
        let v672: f64 = v671 * v172;
        let v673: f64 = v667 + v672;
        let v674: f64 = v673 * v96;
        let v675: f64 = v663 + v674;
        let v676: f64 = v675 * v376;
        let v677: f64 = v660 + v676;
        let v678: f64 = v677 * v49;
        let v679: f64 = v655 + v678;
        let v680: f64 = v679 * v14;
        let v681: f64 = v642 + v680;
        let v682: f64 = v681 * v172;
        let v683: f64 = v630 + v682;
        let v684: f64 = v30 * v49;
        let v685: f64 = v684 - v18;
        let v686: f64 = v685 + v15;
        let v687: f64 = v686 * v27;
        let v688: f64 = v67 * v96;
        let v689: f64 = v16 * v3;
        let v690: f64 = v688 - v689;
        let v691: f64 = v690 * v49;
        let v692: f64 = v30 * v3;
        let v693: f64 = v684 * v17;
        let v694: f64 = v16 - v693;
        let v695: f64 = v694 * v96;
        let v696: f64 = v120 * v3;
        let v697: f64 = v695 + v696;
        let v698: f64 = v697 * v27;
        let v699: f64 = v692 + v698;
        let v700: f64 = v699 * v17;
        let v701: f64 = v691 + v700;
        let v702: f64 = v701 * v96;
        let v703: f64 = v687 + v702;
        let v704: f64 = v703 * v376;
        let v705: f64 = v620 * v33;
        let v706: f64 = v705 * v17;
        let v707: f64 = v216 * v14;
        let v708: f64 = v706 - v707;
        let v709: f64 = v708 * v96;
        let v710: f64 = v604 * v20;
        let v711: f64 = v390 - v710;
        let v712: f64 = v711 * v49;
        let v713: f64 = v480 * v9;
        let v714: f64 = v480 * v6;
        let v715: f64 = v713 + v714;
        let v716: f64 = v715 * v14;
        let v717: f64 = v712 - v716;
        let v718: f64 = v717 * v3;
        let v719: f64 = v709 + v718;
        let v720: f64 = v18 - v684;
        let v721: f64 = v720 * v33;
        let v722: f64 = v115 - v37;
        let v723: f64 = v722 * v14;
        let v724: f64 = v721 + v723;
        let v725: f64 = v724 * v3;
        let v726: f64 = v40 * v33;
        let v727: f64 = v425 + v726;
        let v728: f64 = v114 * v49;
        let v729: f64 = v728 * v14;
        let v730: f64 = v727 + v729;
        let v731: f64 = v730 * v17;
        let v732: f64 = v392 + v731;
        let v733: f64 = v732 * v96;
        let v734: f64 = v725 + v733;
        let v735: f64 = v734 * v27;
        let v736: f64 = v719 + v735;
        let v737: f64 = v736 * v212;
        let v738: f64 = v704 + v737;
        let v739: f64 = v705 * v3;
        let v740: f64 = v30 * v376;
        let v741: f64 = v740 * v212;
        let v742: f64 = v739 + v741;
        let v743: f64 = v742 * v17;
        let v744: f64 = v84 * v3;
        let v745: f64 = v744 * v172;
        let v746: f64 = v84 * v96;
        let v747: f64 = v746 * v212;
        let v748: f64 = v745 + v747;
        let v749: f64 = v748 * v376;
        let v750: f64 = v749 * v17;
        let v751: f64 = v716 - v750;
        let v752: f64 = v751 * v96;
        let v753: f64 = v743 + v752;
        let v754: f64 = v38 - v43;
        let v755: f64 = v754 * v20;
        let v756: f64 = v755 * v14;
        let v757: f64 = v201 * v172;
        let v758: f64 = v16 * v212;
        let v759: f64 = v757 - v758;
        let v760: f64 = v759 * v376;
        let v761: f64 = v756 + v760;
        let v762: f64 = v425 + v710;
        let v763: f64 = v80 * v96;
        let v764: f64 = v763 + v665;
        let v765: f64 = v764 * v172;
        let v766: f64 = v669 - v197;
        let v767: f64 = v766 * v212;
        let v768: f64 = v765 + v767;
        let v769: f64 = v768 * v376;
        let v770: f64 = v762 + v769;
        let v771: f64 = v770 * v96;
        let v772: f64 = v761 + v771;
        let v773: f64 = v772 * v49;
        let v774: f64 = v753 + v773;
        let v775: f64 = v392 * v3;
        (
            v586,
            v587,
            v589,
            v591,
            v615,
            v620,
            v631,
            v656,
            v657,
            v662,
            v665,
            v668,
            v683,
            v684,
            v688,
            v689,
            v690,
            v692,
            v693,
            v694,
            v695,
            v705,
            v716,
            v720,
            v728,
            v729,
            v730,
            v738,
            v740,
            v744,
            v746,
            v754,
            v758,
            v765,
            v774,
            v775,
        )
    };
    let (
        v777,
        v779,
        v780,
        v801,
        v806,
        v822,
        v823,
        v826,
        v829,
        v830,
        v831,
        v849,
        v850,
        v851,
        v853,
        v856,
        v860,
        v875,
        v876,
        v877,
        v878,
        v879,
        v887,
        v890,
        v898,
        v906,
        v907,
        v911,
        v917,
        v922,
        v925,
        v938,
        v941,
        v942,
        v944,
        v949,
        v951,
        v961,
        v963,
        v965,
        v967,
        v969,
    ) = {
        let v776: f64 = v740 * v49;
        let v777: f64 = v776 * v172;
        let v778: f64 = v775 - v777;
        let v779: f64 = v746 * v172;
        let v780: f64 = v744 * v212;
        let v781: f64 = v779 - v780;
        let v782: f64 = v781 * v376;
        let v783: f64 = v108 + v782;
        let v784: f64 = v783 * v49;
        let v785: f64 = v37 - v115;
        let v786: f64 = v785 * v14;
        let v787: f64 = v784 + v786;
        let v788: f64 = v787 * v96;
        let v789: f64 = v778 + v788;
        let v790: f64 = v66 - v656;
        let v791: f64 = v790 * v33;
        let v792: f64 = v730 * v3;
        let v793: f64 = v791 + v792;
        let v794: f64 = v694 * v172;
        let v795: f64 = v120 + v43;
        let v796: f64 = v795 * v212;
        let v797: f64 = v794 + v796;
        let v798: f64 = v284 * v96;
        let v799: f64 = v84 * v49;
        let v800: f64 = v799 * v17;
        let v801: f64 = v60 - v800;
        let v802: f64 = v801 * v3;
        let v803: f64 = v798 + v802;
        let v804: f64 = v803 * v212;
        let v805: f64 = -0.000116928_f64;
        let v806: f64 = v805 + v800;
        let v807: f64 = v806 * v96;
        let v808: f64 = v66 + v807;
        let v809: f64 = v284 * v3;
        let v810: f64 = v808 + v809;
        let v811: f64 = v810 * v172;
        let v812: f64 = v804 + v811;
        let v813: f64 = v812 * v96;
        let v814: f64 = v797 + v813;
        let v815: f64 = v814 * v376;
        let v816: f64 = v793 + v815;
        let v817: f64 = v816 * v17;
        let v818: f64 = v789 + v817;
        let v819: f64 = v818 * v27;
        let v820: f64 = v774 + v819;
        let v821: f64 = v820 * v172;
        let v822: f64 = v738 + v821;
        let v823: f64 = v384 * v33;
        let v824: f64 = v823 * v14;
        let v825: f64 = v824 * v3;
        let v826: f64 = v384 * v20;
        let v827: f64 = v384 * v9;
        let v828: f64 = v384 * v6;
        let v829: f64 = v827 + v828;
        let v830: f64 = v829 * v17;
        let v831: f64 = v826 + v830;
        let v832: f64 = v831 * v96;
        let v833: f64 = v825 - v832;
        let v834: f64 = v833 * v172;
        let v835: f64 = v824 * v96;
        let v836: f64 = v831 * v3;
        let v837: f64 = v835 + v836;
        let v838: f64 = v837 * v212;
        let v839: f64 = v834 + v838;
        let v840: f64 = v839 * v49;
        let v841: f64 = v826 * v17;
        let v842: f64 = v829 + v841;
        let v843: f64 = v842 * v3;
        let v844: f64 = v843 * v172;
        let v845: f64 = v842 * v96;
        let v846: f64 = v845 * v212;
        let v847: f64 = v844 + v846;
        let v848: f64 = v847 * v27;
        let v849: f64 = v840 - v848;
        let v850: f64 = v386 + v615;
        let v851: f64 = v850 * v49;
        let v852: f64 = v851 * v17;
        let v853: f64 = -0.00022_f64;
        let v854: f64 = v67 * v27;
        let v855: f64 = v853 + v854;
        let v856: f64 = v855 * v20;
        let v857: f64 = v856 * v14;
        let v858: f64 = v852 + v857;
        let v859: f64 = v858 * v96;
        let v860: f64 = 0.00077_f64;
        let v861: f64 = v860 * v33;
        let v862: f64 = v72 * v14;
        let v863: f64 = v386 - v862;
        let v864: f64 = v863 * v27;
        let v865: f64 = v861 + v864;
        let v866: f64 = v631 * v14;
        let v867: f64 = v591 * v33;
        let v868: f64 = v866 + v867;
        let v869: f64 = v868 * v17;
        let v870: f64 = v865 + v869;
        let v871: f64 = v870 * v3;
        let v872: f64 = v859 + v871;
        let v873: f64 = v872 * v172;
        let v874: f64 = v386 * v27;
        let v875: f64 = v861 + v874;
        let v876: f64 = v875 * v96;
        let v877: f64 = v620 * v3;
        let v878: f64 = v40 * v3;
        let v879: f64 = v790 + v878;
        let v880: f64 = v879 * v27;
        let v881: f64 = v877 + v880;
        let v882: f64 = v881 * v20;
        let v883: f64 = v882 * v14;
        let v884: f64 = v876 + v883;
        let v885: f64 = v77 * v17;
        let v886: f64 = v885 * v96;
        let v887: f64 = v32 * v14;
        let v888: f64 = v887 * v96;
        let v889: f64 = v386 * v3;
        let v890: f64 = v888 - v889;
        let v891: f64 = v879 * v33;
        let v892: f64 = v890 + v891;
        let v893: f64 = v892 * v49;
        let v894: f64 = v886 + v893;
        let v895: f64 = v894 * v17;
        let v896: f64 = v884 + v895;
        let v897: f64 = v896 * v212;
        let v898: f64 = v873 + v897;
        let v899: f64 = 0.004173999_f64;
        let v900: f64 = v899 + v351;
        let v901: f64 = v900 - v4;
        let v902: f64 = v159 * v49;
        let v903: f64 = v902 * v17;
        let v904: f64 = v901 + v903;
        let v905: f64 = -0.022546398_f64;
        let v906: f64 = v905 - v357;
        let v907: f64 = v80 + v119;
        let v908: f64 = v907 * v49;
        let v909: f64 = v908 * v17;
        let v910: f64 = v906 + v909;
        let v911: f64 = v910 * v96;
        let v912: f64 = v570 + v911;
        let v913: f64 = v80 + v39;
        let v914: f64 = v913 * v27;
        let v915: f64 = v103 + v914;
        let v916: f64 = -0.00030216_f64;
        let v917: f64 = v916 + v75;
        let v918: f64 = v917 * v17;
        let v919: f64 = v368 + v918;
        let v920: f64 = v919 * v17;
        let v921: f64 = v915 + v920;
        let v922: f64 = v921 * v3;
        let v923: f64 = v912 + v922;
        let v924: f64 = v923 * v96;
        let v925: f64 = v904 + v924;
        let v926: f64 = -0.008347998_f64;
        let v927: f64 = v926 - v357;
        let v928: f64 = v147 * v3;
        let v929: f64 = v927 + v928;
        let v930: f64 = v907 - v197;
        let v931: f64 = v930 * v49;
        let v932: f64 = v931 * v17;
        let v933: f64 = v929 + v932;
        let v934: f64 = v933 * v172;
        let v935: f64 = v179 * v3;
        let v936: f64 = v174 - v935;
        let v937: f64 = v368 - v413;
        let v938: f64 = v937 * v17;
        let v939: f64 = v936 + v938;
        let v940: f64 = v80 - v197;
        let v941: f64 = v30 * v17;
        let v942: f64 = v941 * v17;
        let v943: f64 = v30 + v942;
        let v944: f64 = v943 * v27;
        let v945: f64 = v940 + v944;
        let v946: f64 = v945 * v27;
        let v947: f64 = v939 + v946;
        let v948: f64 = v947 * v212;
        let v949: f64 = v934 + v948;
        let v950: f64 = v179 + v488;
        let v951: f64 = v521 * v96;
        let v952: f64 = v950 + v951;
        let v953: f64 = -0.647839691_f64;
        let v954: f64 = v517 - v119;
        let v955: f64 = v954 * v27;
        let v956: f64 = v953 + v955;
        let v957: f64 = v265 * v17;
        let v958: f64 = v957 - v502;
        let v959: f64 = v958 * v17;
        let v960: f64 = v956 + v959;
        let v961: f64 = v960 * v3;
        let v962: f64 = v952 + v961;
        let v963: f64 = v962 * v172;
        let v964: f64 = v147 - v514;
        let v965: f64 = v496 * v3;
        let v966: f64 = v964 + v965;
        let v967: f64 = v960 * v96;
        let v968: f64 = v966 + v967;
        let v969: f64 = v968 * v212;
        (
            v777,
            v779,
            v780,
            v801,
            v806,
            v822,
            v823,
            v826,
            v829,
            v830,
            v831,
            v849,
            v850,
            v851,
            v853,
            v856,
            v860,
            v875,
            v876,
            v877,
            v878,
            v879,
            v887,
            v890,
            v898,
            v906,
            v907,
            v911,
            v917,
            v922,
            v925,
            v938,
            v941,
            v942,
            v944,
            v949,
            v951,
            v961,
            v963,
            v965,
            v967,
            v969,
        )
    };
    let (
        v976,
        v980,
        v981,
        v982,
        v986,
        v996,
        v1003,
        v1014,
        v1016,
        v1026,
        v1032,
        v1046,
        v1049,
        v1061,
        v1062,
        v1064,
        v1068,
        v1074,
        v1083,
        v1084,
        v1094,
        v1099,
        v1106,
        v1107,
        v1108,
        v1113,
        v1120,
        v1139,
        v1146,
        v1161,
        v1163,
    ) = {
        let v970: f64 = v963 + v969;
        let v971: f64 = v970 * v96;
        let v972: f64 = v949 + v971;
        let v973: f64 = v972 * v172;
        let v974: f64 = v925 + v973;
        let v975: f64 = v974 * v376;
        let v976: f64 = v898 + v975;
        let v977: f64 = v570 * v96;
        let v978: f64 = v977 - v4;
        let v979: f64 = v978 * v9;
        let v980: f64 = -5.8464e-05_f64;
        let v981: f64 = v38 * v96;
        let v982: f64 = v980 - v981;
        let v983: f64 = v982 * v20;
        let v984: f64 = v153 + v983;
        let v985: f64 = v984 * v27;
        let v986: f64 = v142 * v14;
        let v987: f64 = v985 - v986;
        let v988: f64 = v987 * v17;
        let v989: f64 = v979 + v988;
        let v990: f64 = v162 * v17;
        let v991: f64 = v990 * v3;
        let v992: f64 = v16 + v981;
        let v993: f64 = v992 * v33;
        let v994: f64 = v993 * v14;
        let v995: f64 = v991 + v994;
        let v996: f64 = -0.00020216_f64;
        let v997: f64 = v996 + v942;
        let v998: f64 = v997 * v27;
        let v999: f64 = v201 + v998;
        let v1000: f64 = v999 * v20;
        let v1001: f64 = v995 + v1000;
        let v1002: f64 = v1001 * v49;
        let v1003: f64 = v989 + v1002;
        let v1004: f64 = v917 * v33;
        let v1005: f64 = v1004 * v14;
        let v1006: f64 = v1005 - v73;
        let v1007: f64 = v1006 * v17;
        let v1008: f64 = v1 * v6;
        let v1009: f64 = v146 + v1008;
        let v1010: f64 = v1009 * v3;
        let v1011: f64 = v1007 - v1010;
        let v1012: f64 = v52 * v6;
        let v1013: f64 = v178 + v1012;
        let v1014: f64 = v162 + v419;
        let v1015: f64 = v215 * v17;
        let v1016: f64 = v1014 + v1015;
        let v1017: f64 = v1016 * v27;
        let v1018: f64 = v1013 + v1017;
        let v1019: f64 = v1018 * v96;
        let v1020: f64 = v1011 - v1019;
        let v1021: f64 = v1014 * v17;
        let v1022: f64 = v1021 * v3;
        let v1023: f64 = v994 + v1022;
        let v1024: f64 = v1023 + v1000;
        let v1025: f64 = v1024 * v49;
        let v1026: f64 = v1020 + v1025;
        let v1027: f64 = v860 * v3;
        let v1028: f64 = v1027 * v172;
        let v1029: f64 = v860 * v96;
        let v1030: f64 = v1029 * v212;
        let v1031: f64 = v1028 + v1030;
        let v1032: f64 = v1031 * v376;
        let v1033: f64 = v159 * v27;
        let v1034: f64 = v853 + v1033;
        let v1035: f64 = v1034 * v20;
        let v1036: f64 = v1014 * v96;
        let v1037: f64 = v24 + v1036;
        let v1038: f64 = v1037 * v49;
        let v1039: f64 = v1035 + v1038;
        let v1040: f64 = v1039 * v14;
        let v1041: f64 = v1032 + v1040;
        let v1042: f64 = v76 * v3;
        let v1043: f64 = v1042 * v172;
        let v1044: f64 = v76 * v96;
        let v1045: f64 = v1044 * v212;
        let v1046: f64 = v1043 + v1045;
        let v1047: f64 = v1046 * v376;
        let v1048: f64 = v1047 * v17;
        let v1049: f64 = v401 * v14;
        let v1050: f64 = v1048 + v1049;
        let v1051: f64 = v159 * v33;
        let v1052: f64 = v386 + v1051;
        let v1053: f64 = v690 * v172;
        let v1054: f64 = v879 * v212;
        let v1055: f64 = v1053 + v1054;
        let v1056: f64 = v1055 * v376;
        let v1057: f64 = v1052 + v1056;
        let v1058: f64 = v1057 * v49;
        let v1059: f64 = v1050 + v1058;
        let v1060: f64 = v1059 * v17;
        let v1061: f64 = v1041 + v1060;
        let v1062: f64 = v877 * v212;
        let v1063: f64 = v620 * v96;
        let v1064: f64 = v1063 * v172;
        let v1065: f64 = v1062 - v1064;
        let v1066: f64 = v1065 * v376;
        let v1067: f64 = v1066 - v705;
        let v1068: f64 = v1067 * v14;
        let v1069: f64 = v1016 * v3;
        let v1070: f64 = v1069 - v1016;
        let v1071: f64 = v1070 * v49;
        let v1072: f64 = v1068 + v1071;
        let v1073: f64 = v983 - v728;
        let v1074: f64 = v980 + v693;
        let v1075: f64 = v1074 - v981;
        let v1076: f64 = v1075 * v9;
        let v1077: f64 = v1075 * v6;
        let v1078: f64 = v1076 + v1077;
        let v1079: f64 = v1078 * v17;
        let v1080: f64 = v1073 + v1079;
        let v1081: f64 = v1074 * v3;
        let v1082: f64 = v688 + v1081;
        let v1083: f64 = v1082 * v172;
        let v1084: f64 = v1074 * v96;
        let v1085: f64 = v66 + v1084;
        let v1086: f64 = v1085 + v878;
        let v1087: f64 = v1086 * v212;
        let v1088: f64 = v1083 + v1087;
        let v1089: f64 = v1088 * v376;
        let v1090: f64 = v1052 + v1089;
        let v1091: f64 = v1090 * v14;
        let v1092: f64 = v1080 + v1091;
        let v1093: f64 = v1092 * v27;
        let v1094: f64 = v1072 + v1093;
        let v1095: f64 = v823 * v49;
        let v1096: f64 = v1095 * v17;
        let v1097: f64 = v826 * v27;
        let v1098: f64 = v1097 * v14;
        let v1099: f64 = v1096 + v1098;
        let v1100: f64 = v384 * v49;
        let v1101: f64 = v1100 * v17;
        let v1102: f64 = v1101 * v96;
        let v1103: f64 = v384 * v27;
        let v1104: f64 = v1103 * v3;
        let v1105: f64 = v1102 + v1104;
        let v1106: f64 = v1105 * v172;
        let v1107: f64 = v1103 * v96;
        let v1108: f64 = v1101 * v3;
        let v1109: f64 = v1107 - v1108;
        let v1110: f64 = v1109 * v212;
        let v1111: f64 = v1106 + v1110;
        let v1112: f64 = v1111 * v376;
        let v1113: f64 = v1099 + v1112;
        let v1114: f64 = v875 * v3;
        let v1115: f64 = v1114 * v172;
        let v1116: f64 = v876 * v212;
        let v1117: f64 = v1115 + v1116;
        let v1118: f64 = v878 - v656;
        let v1119: f64 = v1118 * v212;
        let v1120: f64 = v1053 + v1119;
        let v1121: f64 = v1120 * v27;
        let v1122: f64 = v1065 + v1121;
        let v1123: f64 = v1122 * v20;
        let v1124: f64 = v1123 * v14;
        let v1125: f64 = v1117 + v1124;
        let v1126: f64 = v1046 * v33;
        let v1127: f64 = v1126 * v17;
        let v1128: f64 = v386 * v96;
        let v1129: f64 = v887 * v3;
        let v1130: f64 = v1128 + v1129;
        let v1131: f64 = v1130 * v172;
        let v1132: f64 = v890 * v212;
        let v1133: f64 = v1131 + v1132;
        let v1134: f64 = v1120 * v33;
        let v1135: f64 = v1133 + v1134;
        let v1136: f64 = v1135 * v49;
        let v1137: f64 = v1127 + v1136;
        let v1138: f64 = v1137 * v17;
        let v1139: f64 = v1125 + v1138;
        let v1140: f64 = v8 + v351;
        let v1141: f64 = v67 * v49;
        let v1142: f64 = v1141 * v17;
        let v1143: f64 = v1140 + v1142;
        let v1144: f64 = v911 + v922;
        let v1145: f64 = v1144 * v96;
        let v1146: f64 = v1143 + v1145;
        let v1147: f64 = v906 + v4;
        let v1148: f64 = v907 - v43;
        let v1149: f64 = v1148 * v49;
        let v1150: f64 = v1149 * v17;
        let v1151: f64 = v1147 + v1150;
        let v1152: f64 = v1151 * v172;
        let v1153: f64 = v52 * v3;
        let v1154: f64 = v103 - v1153;
        let v1155: f64 = v1154 + v938;
        let v1156: f64 = v80 - v43;
        let v1157: f64 = v1156 + v944;
        let v1158: f64 = v1157 * v27;
        let v1159: f64 = v1155 + v1158;
        let v1160: f64 = v1159 * v212;
        let v1161: f64 = v1152 + v1160;
        let v1162: f64 = v54 + v951;
        let v1163: f64 = v1162 + v961;
        (
            v976,
            v980,
            v981,
            v982,
            v986,
            v996,
            v1003,
            v1014,
            v1016,
            v1026,
            v1032,
            v1046,
            v1049,
            v1061,
            v1062,
            v1064,
            v1068,
            v1074,
            v1083,
            v1084,
            v1094,
            v1099,
            v1106,
            v1107,
            v1108,
            v1113,
            v1120,
            v1139,
            v1146,
            v1161,
            v1163,
        )
    };
    let (
        v1175,
        v1190,
        v1193,
        v1204,
        v1207,
        v1220,
        v1222,
        v1223,
        v1227,
        v1236,
        v1246,
        v1248,
        v1250,
        v1270,
        v1300,
        v1308,
        v1316,
        v1327,
        v1337,
        v1345,
        v1346,
        v1349,
        v1354,
        v1355,
        v1357,
    ) = {
        let v1164: f64 = v1163 * v172;
        let v1165: f64 = v1 - v575;
        let v1166: f64 = v1165 + v965;
        let v1167: f64 = v1166 + v967;
        let v1168: f64 = v1167 * v212;
        let v1169: f64 = v1164 + v1168;
        let v1170: f64 = v1169 * v96;
        let v1171: f64 = v1161 + v1170;
        let v1172: f64 = v1171 * v172;
        let v1173: f64 = v1146 + v1172;
        let v1174: f64 = v1173 * v376;
        let v1175: f64 = v1139 + v1174;
        let v1176: f64 = v54 * v96;
        let v1177: f64 = v4 + v1176;
        let v1178: f64 = v1177 * v6;
        let v1179: f64 = v35 + v68;
        let v1180: f64 = v1179 * v49;
        let v1181: f64 = v1178 + v1180;
        let v1182: f64 = v1074 * v20;
        let v1183: f64 = v153 + v1182;
        let v1184: f64 = v1183 * v27;
        let v1185: f64 = v419 * v49;
        let v1186: f64 = v1185 * v3;
        let v1187: f64 = v986 + v1186;
        let v1188: f64 = v1184 - v1187;
        let v1189: f64 = v1188 * v17;
        let v1190: f64 = v1181 + v1189;
        let v1191: f64 = v1184 - v986;
        let v1192: f64 = v1191 * v17;
        let v1193: f64 = v1180 + v1192;
        let v1194: f64 = v399 + v856;
        let v1195: f64 = v1194 * v14;
        let v1196: f64 = v1032 + v1195;
        let v1197: f64 = v851 + v1049;
        let v1198: f64 = v1046 * v17;
        let v1199: f64 = v1120 * v49;
        let v1200: f64 = v1198 + v1199;
        let v1201: f64 = v1200 * v376;
        let v1202: f64 = v1197 + v1201;
        let v1203: f64 = v1202 * v17;
        let v1204: f64 = v1196 + v1203;
        let v1205: f64 = v1016 * v49;
        let v1206: f64 = v1068 - v1205;
        let v1207: f64 = v728 * v17;
        let v1208: f64 = v1207 - v24;
        let v1209: f64 = v1208 * v17;
        let v1210: f64 = v72 + v728;
        let v1211: f64 = v1209 - v1210;
        let v1212: f64 = v1084 + v878;
        let v1213: f64 = v1212 * v212;
        let v1214: f64 = v1083 + v1213;
        let v1215: f64 = v1214 * v376;
        let v1216: f64 = v850 + v1215;
        let v1217: f64 = v1216 * v14;
        let v1218: f64 = v1211 + v1217;
        let v1219: f64 = v1218 * v27;
        let v1220: f64 = v1206 + v1219;
        let v1221: f64 = v30 * v96;
        let v1222: f64 = v1221 * v172;
        let v1223: f64 = v692 * v212;
        let v1224: f64 = v1222 - v1223;
        let v1225: f64 = v1224 * v20;
        let v1226: f64 = v1225 * v27;
        let v1227: f64 = v67 * v3;
        let v1228: f64 = v656 + v1227;
        let v1229: f64 = v1228 * v96;
        let v1230: f64 = v980 + v1229;
        let v1231: f64 = v159 * v212;
        let v1232: f64 = v662 + v1231;
        let v1233: f64 = v907 * v96;
        let v1234: f64 = v665 + v1233;
        let v1235: f64 = v1234 * v212;
        let v1236: f64 = v66 - v668;
        let v1237: f64 = v907 * v3;
        let v1238: f64 = v1236 + v1237;
        let v1239: f64 = v1238 * v172;
        let v1240: f64 = v1235 + v1239;
        let v1241: f64 = v1240 * v96;
        let v1242: f64 = v1232 + v1241;
        let v1243: f64 = v1242 * v172;
        let v1244: f64 = v1230 + v1243;
        let v1245: f64 = v1244 * v376;
        let v1246: f64 = v384 * v3;
        let v1247: f64 = v1246 * v172;
        let v1248: f64 = v384 * v96;
        let v1249: f64 = v1248 * v212;
        let v1250: f64 = v1247 + v1249;
        let v1251: f64 = v1250 * v385;
        let v1252: f64 = v1245 - v1251;
        let v1253: f64 = v1252 * v14;
        let v1254: f64 = v1226 + v1253;
        let v1255: f64 = v1254 * v49;
        let v1256: f64 = v860 * v9;
        let v1257: f64 = v860 * v6;
        let v1258: f64 = v1256 + v1257;
        let v1259: f64 = v1258 * v3;
        let v1260: f64 = v1259 * v172;
        let v1261: f64 = v1258 * v96;
        let v1262: f64 = v1261 * v212;
        let v1263: f64 = v1260 + v1262;
        let v1264: f64 = v1255 - v1263;
        let v1265: f64 = v917 * v14;
        let v1266: f64 = v1265 * v96;
        let v1267: f64 = v1266 * v96;
        let v1268: f64 = v1267 - v587;
        let v1269: f64 = v1268 * v376;
        let v1270: f64 = v1014 + v115;
        let v1271: f64 = v1270 * v3;
        let v1272: f64 = v419 - v1271;
        let v1273: f64 = v1272 * v49;
        let v1274: f64 = v403 * v96;
        let v1275: f64 = v1273 + v1274;
        let v1276: f64 = v1275 * v212;
        let v1277: f64 = v1269 + v1276;
        let v1278: f64 = v917 * v376;
        let v1279: f64 = v1278 * v14;
        let v1280: f64 = v1279 * v172;
        let v1281: f64 = v265 * v376;
        let v1282: f64 = v1281 * v14;
        let v1283: f64 = v1282 * v96;
        let v1284: f64 = v1283 * v172;
        let v1285: f64 = v1270 * v49;
        let v1286: f64 = v1284 + v1285;
        let v1287: f64 = v1286 * v96;
        let v1288: f64 = v1280 + v1287;
        let v1289: f64 = v504 * v376;
        let v1290: f64 = v1289 * v14;
        let v1291: f64 = v1290 * v96;
        let v1292: f64 = v1291 * v212;
        let v1293: f64 = v400 + v1292;
        let v1294: f64 = v1293 + v402;
        let v1295: f64 = v1294 * v3;
        let v1296: f64 = v1288 + v1295;
        let v1297: f64 = v1296 * v172;
        let v1298: f64 = v1277 + v1297;
        let v1299: f64 = v1298 * v17;
        let v1300: f64 = v1264 + v1299;
        let v1301: f64 = v982 * v6;
        let v1302: f64 = v1301 - v22;
        let v1303: f64 = v1302 * v49;
        let v1304: f64 = v482 + v1303;
        let v1305: f64 = v1304 * v14;
        let v1306: f64 = v1305 - v1032;
        let v1307: f64 = v130 * v14;
        let v1308: f64 = v386 * v49;
        let v1309: f64 = v1307 - v1308;
        let v1310: f64 = v917 * v3;
        let v1311: f64 = v1310 * v172;
        let v1312: f64 = v917 * v96;
        let v1313: f64 = v1312 * v212;
        let v1314: f64 = v1311 + v1313;
        let v1315: f64 = v1314 * v17;
        let v1316: f64 = v40 * v96;
        let v1317: f64 = v689 + v1316;
        let v1318: f64 = v1317 * v172;
        let v1319: f64 = v657 + v1227;
        let v1320: f64 = v1319 * v212;
        let v1321: f64 = v1318 + v1320;
        let v1322: f64 = v1321 * v49;
        let v1323: f64 = v1315 + v1322;
        let v1324: f64 = v1323 * v376;
        let v1325: f64 = v1309 + v1324;
        let v1326: f64 = v1325 * v17;
        let v1327: f64 = v1306 + v1326;
        let v1328: f64 = v483 * v14;
        let v1329: f64 = v1328 - v1032;
        let v1330: f64 = v1228 * v212;
        let v1331: f64 = v1318 + v1330;
        let v1332: f64 = v1331 * v49;
        let v1333: f64 = v1315 + v1332;
        let v1334: f64 = v1333 * v376;
        let v1335: f64 = v1309 + v1334;
        let v1336: f64 = v1335 * v17;
        let v1337: f64 = v1329 + v1336;
        let v1338: f64 = v480 * v3;
        let v1339: f64 = v1338 * v172;
        let v1340: f64 = v480 * v96;
        let v1341: f64 = v1340 * v212;
        let v1342: f64 = v1339 + v1341;
        let v1343: f64 = v1342 * v376;
        let v1344: f64 = v1343 * v17;
        let v1345: f64 = v1308 + v1344;
        let v1346: f64 = v716 - v1345;
        let v1347: f64 = v1224 * v376;
        let v1348: f64 = v108 + v1347;
        let v1349: f64 = v1348 * v49;
        let v1350: f64 = v692 * v172;
        let v1351: f64 = v1221 * v212;
        let v1352: f64 = v1350 + v1351;
        let v1353: f64 = v1352 * v376;
        let v1354: f64 = v1353 * v17;
        let v1355: f64 = v114 * v14;
        let v1356: f64 = v1354 - v1355;
        let v1357: f64 = v1356 * v27;
        (
            v1175,
            v1190,
            v1193,
            v1204,
            v1207,
            v1220,
            v1222,
            v1223,
            v1227,
            v1236,
            v1246,
            v1248,
            v1250,
            v1270,
            v1300,
            v1308,
            v1316,
            v1327,
            v1337,
            v1345,
            v1346,
            v1349,
            v1354,
            v1355,
            v1357,
        )
    };
    let (v1360, v1365, v1470, v1496, v1509, v1519, v1520, v1531, v1536, v1539, v1546) = {
        let v1358: f64 = v1349 + v1357;
        let v1359: f64 = v1358 * v27;
        let v1360: f64 = v1346 + v1359;
        let v1361: f64 = v1250 * v376;
        let v1362: f64 = v1361 * v14;
        let v1363: f64 = v831 + v1362;
        let v1364: f64 = v1363 * v49;
        let v1365: f64 = -v1364;
        let v1366: f64 = v555 * v49;
        let v1367: f64 = v1366 * v96;
        let v1368: f64 = v480 * v33;
        let v1369: f64 = v1368 * v17;
        let v1370: f64 = v1369 * v212;
        let v1371: f64 = v1367 + v1370;
        let v1372: f64 = v1371 * v96;
        let v1373: f64 = v589 - v941;
        let v1374: f64 = v1373 * v376;
        let v1375: f64 = v1374 * v96;
        let v1376: f64 = v620 * v9;
        let v1377: f64 = v620 * v6;
        let v1378: f64 = v1376 + v1377;
        let v1379: f64 = v1378 * v14;
        let v1380: f64 = v1308 + v1379;
        let v1381: f64 = v1380 * v212;
        let v1382: f64 = v1375 - v1381;
        let v1383: f64 = v1382 * v3;
        let v1384: f64 = v1372 + v1383;
        let v1385: f64 = v1369 * v3;
        let v1386: f64 = v1380 * v96;
        let v1387: f64 = v1385 + v1386;
        let v1388: f64 = v746 * v3;
        let v1389: f64 = v1388 * v172;
        let v1390: f64 = v746 * v96;
        let v1391: f64 = v996 + v1390;
        let v1392: f64 = v1391 * v212;
        let v1393: f64 = v1389 + v1392;
        let v1394: f64 = v1393 * v17;
        let v1395: f64 = v754 * v172;
        let v1396: f64 = v758 + v1395;
        let v1397: f64 = v1236 + v197;
        let v1398: f64 = v1397 * v212;
        let v1399: f64 = v1398 - v765;
        let v1400: f64 = v1399 * v96;
        let v1401: f64 = v1396 + v1400;
        let v1402: f64 = v1401 * v49;
        let v1403: f64 = v1394 + v1402;
        let v1404: f64 = v1403 * v376;
        let v1405: f64 = v1387 + v1404;
        let v1406: f64 = v1405 * v172;
        let v1407: f64 = v1384 + v1406;
        let v1408: f64 = v720 - v15;
        let v1409: f64 = v684 * v96;
        let v1410: f64 = v38 + v119;
        let v1411: f64 = v1410 * v3;
        let v1412: f64 = v1084 + v1411;
        let v1413: f64 = v1412 * v17;
        let v1414: f64 = v1409 + v1413;
        let v1415: f64 = v1414 * v96;
        let v1416: f64 = v1408 + v1415;
        let v1417: f64 = v1416 * v376;
        let v1418: f64 = v109 * v3;
        let v1419: f64 = v386 - v152;
        let v1420: f64 = v1419 * v17;
        let v1421: f64 = v1420 * v96;
        let v1422: f64 = v1418 + v1421;
        let v1423: f64 = v695 + v1227;
        let v1424: f64 = v1423 * v9;
        let v1425: f64 = v38 + v695;
        let v1426: f64 = v1425 + v1227;
        let v1427: f64 = v1426 * v6;
        let v1428: f64 = v1424 + v1427;
        let v1429: f64 = v1428 * v14;
        let v1430: f64 = v1422 + v1429;
        let v1431: f64 = v1430 * v212;
        let v1432: f64 = v1417 + v1431;
        let v1433: f64 = v24 * v14;
        let v1434: f64 = v1433 * v3;
        let v1435: f64 = v777 + v1434;
        let v1436: f64 = v780 - v779;
        let v1437: f64 = v1436 * v376;
        let v1438: f64 = v1437 - v108;
        let v1439: f64 = v1438 * v49;
        let v1440: f64 = v1270 * v14;
        let v1441: f64 = v1439 + v1440;
        let v1442: f64 = v1441 * v96;
        let v1443: f64 = v1435 + v1442;
        let v1444: f64 = v1419 - v729;
        let v1445: f64 = v1444 * v3;
        let v1446: f64 = v1074 * v172;
        let v1447: f64 = v1410 - v43;
        let v1448: f64 = v1447 * v212;
        let v1449: f64 = v1446 + v1448;
        let v1450: f64 = v192 - v283;
        let v1451: f64 = v1450 * v96;
        let v1452: f64 = v806 * v3;
        let v1453: f64 = v1451 + v1452;
        let v1454: f64 = v1453 * v212;
        let v1455: f64 = v801 * v96;
        let v1456: f64 = v38 + v1455;
        let v1457: f64 = v1450 * v3;
        let v1458: f64 = v1456 + v1457;
        let v1459: f64 = v1458 * v172;
        let v1460: f64 = v1454 + v1459;
        let v1461: f64 = v1460 * v96;
        let v1462: f64 = v1449 + v1461;
        let v1463: f64 = v1462 * v376;
        let v1464: f64 = v1445 + v1463;
        let v1465: f64 = v1464 * v17;
        let v1466: f64 = v1443 + v1465;
        let v1467: f64 = v1466 * v172;
        let v1468: f64 = v1432 + v1467;
        let v1469: f64 = v1468 * v27;
        let v1470: f64 = v1407 + v1469;
        let v1471: f64 = v754 * v6;
        let v1472: f64 = v162 + v1471;
        let v1473: f64 = v1472 * v49;
        let v1474: f64 = v1064 - v1062;
        let v1475: f64 = v1474 * v376;
        let v1476: f64 = v1475 - v1368;
        let v1477: f64 = v1476 * v14;
        let v1478: f64 = v1473 + v1477;
        let v1479: f64 = v694 * v9;
        let v1480: f64 = v694 + v981;
        let v1481: f64 = v1480 * v6;
        let v1482: f64 = v1479 + v1481;
        let v1483: f64 = v1482 * v17;
        let v1484: f64 = v728 + v1483;
        let v1485: f64 = v152 - v386;
        let v1486: f64 = v694 * v3;
        let v1487: f64 = v1316 + v1486;
        let v1488: f64 = v1487 * v172;
        let v1489: f64 = v1426 * v212;
        let v1490: f64 = v1488 + v1489;
        let v1491: f64 = v1490 * v376;
        let v1492: f64 = v1485 + v1491;
        let v1493: f64 = v1492 * v14;
        let v1494: f64 = v1484 + v1493;
        let v1495: f64 = v1494 * v27;
        let v1496: f64 = v1478 + v1495;
        let v1497: f64 = v1014 * v49;
        let v1498: f64 = v1497 + v1477;
        let v1499: f64 = v24 - v1207;
        let v1500: f64 = v1499 * v17;
        let v1501: f64 = v728 + v1500;
        let v1502: f64 = v1423 * v212;
        let v1503: f64 = v1488 + v1502;
        let v1504: f64 = v1503 * v376;
        let v1505: f64 = v1485 + v1504;
        let v1506: f64 = v1505 * v14;
        let v1507: f64 = v1501 + v1506;
        let v1508: f64 = v1507 * v27;
        let v1509: f64 = v1498 + v1508;
        let v1510: f64 = v1345 - v716;
        let v1511: f64 = v1223 - v1222;
        let v1512: f64 = v1511 * v376;
        let v1513: f64 = v1512 - v108;
        let v1514: f64 = v1513 * v49;
        let v1515: f64 = v1355 - v1354;
        let v1516: f64 = v1515 * v27;
        let v1517: f64 = v1514 + v1516;
        let v1518: f64 = v1517 * v27;
        let v1519: f64 = v1510 + v1518;
        let v1520: f64 = 0.0_f64;
        let v1521: f64 = v1248 * v172;
        let v1522: f64 = v1246 * v212;
        let v1523: f64 = v1521 - v1522;
        let v1524: f64 = v1523 * v376;
        let v1525: f64 = v823 + v1524;
        let v1526: f64 = v1525 * v49;
        let v1527: f64 = v1361 * v17;
        let v1528: f64 = v829 * v14;
        let v1529: f64 = v1527 - v1528;
        let v1530: f64 = v1529 * v27;
        let v1531: f64 = v1526 + v1530;
        let v1532: f64 = v1108 - v1107;
        let v1533: f64 = v1532 * v212;
        let v1534: f64 = v1533 - v1106;
        let v1535: f64 = v1534 * v376;
        let v1536: f64 = v1099 + v1535;
        let v1537: f64 = v830 - v826;
        let v1538: f64 = v1537 + v1362;
        let v1539: f64 = v1538 * v49;
        let v1540: f64 = v1522 - v1521;
        let v1541: f64 = v1540 * v376;
        let v1542: f64 = v1541 - v823;
        let v1543: f64 = v1542 * v49;
        let v1544: f64 = v1528 - v1527;
        let v1545: f64 = v1544 * v27;
        let v1546: f64 = v1543 + v1545;
        (v1360, v1365, v1470, v1496, v1509, v1519, v1520, v1531, v1536, v1539, v1546)
    };
    [
        [v350, v533, v586, v683, v822, v849],
        [v976, v1003, v1026, v1061, v1094, v1113],
        [v1175, v1190, v1193, v1204, v1220, v1113],
        [v1300, v1327, v1337, v631, v1360, v1365],
        [v1470, v1496, v1509, v1519, v1520, v1531],
        [v849, v1536, v1536, v1539, v1546, v1520],
    ]
}
/// Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53).
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 6]`: joint velocities qd (rad/s or m/s)
///
/// # Output
///
/// `coriolis: [f64; 6]`: c(q, qd) = C(q, qd) qd (N m or N)
///
/// Operation count: 483 floating-point operations, 10 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn coriolis(q: &[f64; 6], qd: &[f64; 6]) -> [f64; 6] {
    let (
        v1,
        v3,
        v5,
        v7,
        v9,
        v11,
        v13,
        v15,
        v16,
        v21,
        v22,
        v23,
        v27,
        v28,
        v33,
        v36,
        v39,
        v42,
        v43,
        v46,
        v48,
        v51,
        v54,
        v56,
        v58,
        v61,
        v62,
        v67,
        v70,
        v73,
        v77,
        v81,
        v82,
        v85,
        v86,
        v88,
        v93,
        v94,
        v99,
        v102,
        v111,
        v116,
        v119,
        v129,
        v130,
        v133,
        v143,
        v148,
        v150,
        v158,
        v160,
        v162,
        v163,
        v166,
        v167,
        v173,
        v175,
        v178,
        v179,
    ) = {
        let v0: f64 = q[1];
        let v1: f64 = ::libm::sin(v0);
        let v2: f64 = q[2];
        let v3: f64 = ::libm::cos(v2);
        let v4: f64 = q[3];
        let v5: f64 = ::libm::cos(v4);
        let v6: f64 = q[4];
        let v7: f64 = ::libm::cos(v6);
        let v8: f64 = q[5];
        let v9: f64 = ::libm::cos(v8);
        let v10: f64 = 0.00024216_f64;
        let v11: f64 = ::libm::cos(v0);
        let v12: f64 = qd[0];
        let v13: f64 = qd[1];
        let v14: f64 = v12 * v13;
        let v15: f64 = v11 * v14;
        let v16: f64 = v11 * v12;
        let v17: f64 = qd[2];
        let v18: f64 = v16 * v17;
        let v19: f64 = v15 + v18;
        let v20: f64 = v3 * v19;
        let v21: f64 = ::libm::sin(v2);
        let v22: f64 = v1 * v14;
        let v23: f64 = v1 * v12;
        let v24: f64 = v23 * v17;
        let v25: f64 = v22 + v24;
        let v26: f64 = v21 * v25;
        let v27: f64 = v20 - v26;
        let v28: f64 = v13 + v17;
        let v29: f64 = qd[3];
        let v30: f64 = v28 * v29;
        let v31: f64 = v27 - v30;
        let v32: f64 = v5 * v31;
        let v33: f64 = ::libm::sin(v4);
        let v34: f64 = v3 * v23;
        let v35: f64 = v21 * v16;
        let v36: f64 = v34 + v35;
        let v37: f64 = v36 * v29;
        let v38: f64 = v33 * v37;
        let v39: f64 = v32 - v38;
        let v40: f64 = v3 * v16;
        let v41: f64 = v21 * v23;
        let v42: f64 = v40 - v41;
        let v43: f64 = v42 + v29;
        let v44: f64 = qd[4];
        let v45: f64 = v43 * v44;
        let v46: f64 = v39 + v45;
        let v47: f64 = v7 * v46;
        let v48: f64 = ::libm::sin(v6);
        let v49: f64 = v21 * v19;
        let v50: f64 = v3 * v25;
        let v51: f64 = v49 + v50;
        let v52: f64 = v5 * v36;
        let v53: f64 = v33 * v28;
        let v54: f64 = v52 - v53;
        let v55: f64 = v54 * v44;
        let v56: f64 = v51 + v55;
        let v57: f64 = v48 * v56;
        let v58: f64 = v47 - v57;
        let v59: f64 = v33 * v36;
        let v60: f64 = v5 * v28;
        let v61: f64 = v59 + v60;
        let v62: f64 = v61 + v44;
        let v63: f64 = qd[5];
        let v64: f64 = v62 * v63;
        let v65: f64 = v58 - v64;
        let v66: f64 = v9 * v65;
        let v67: f64 = ::libm::sin(v8);
        let v68: f64 = v33 * v31;
        let v69: f64 = v5 * v37;
        let v70: f64 = v68 + v69;
        let v71: f64 = v7 * v54;
        let v72: f64 = v48 * v43;
        let v73: f64 = v71 + v72;
        let v74: f64 = v73 * v63;
        let v75: f64 = v70 + v74;
        let v76: f64 = v67 * v75;
        let v77: f64 = v66 - v76;
        let v78: f64 = v10 * v77;
        let v79: f64 = v7 * v43;
        let v80: f64 = v48 * v54;
        let v81: f64 = v79 - v80;
        let v82: f64 = v81 + v63;
        let v83: f64 = v67 * v73;
        let v84: f64 = v9 * v62;
        let v85: f64 = v83 + v84;
        let v86: f64 = v10 * v85;
        let v87: f64 = v82 * v86;
        let v88: f64 = 4e-05_f64;
        let v89: f64 = v88 * v82;
        let v90: f64 = v85 * v89;
        let v91: f64 = v87 - v90;
        let v92: f64 = v78 + v91;
        let v93: f64 = 0.00288_f64;
        let v94: f64 = 0.4318_f64;
        let v95: f64 = v94 * v54;
        let v96: f64 = v43 * v95;
        let v97: f64 = v94 * v70;
        let v98: f64 = v96 - v97;
        let v99: f64 = -0.15005_f64;
        let v100: f64 = v99 * v51;
        let v101: f64 = v99 * v36;
        let v102: f64 = 0.0203_f64;
        let v103: f64 = v102 * v28;
        let v104: f64 = v101 + v103;
        let v105: f64 = v28 * v104;
        let v106: f64 = v102 * v42;
        let v107: f64 = v42 * v106;
        let v108: f64 = v105 + v107;
        let v109: f64 = v100 - v108;
        let v110: f64 = v94 * v16;
        let v111: f64 = v23 * v110;
        let v112: f64 = v21 * v111;
        let v113: f64 = v16 * v110;
        let v114: f64 = v94 * v13;
        let v115: f64 = v13 * v114;
        let v116: f64 = v113 + v115;
        let v117: f64 = v3 * v116;
        let v118: f64 = v112 - v117;
        let v119: f64 = v109 + v118;
        let v120: f64 = v5 * v119;
        let v121: f64 = v102 * v51;
        let v122: f64 = v99 * v42;
        let v123: f64 = v42 * v122;
        let v124: f64 = v36 * v104;
        let v125: f64 = v123 + v124;
        let v126: f64 = v121 + v125;
        let v127: f64 = v94 * v22;
        let v128: f64 = v23 * v114;
        let v129: f64 = v127 + v128;
        let v130: f64 = v126 + v129;
        let v131: f64 = v33 * v130;
        let v132: f64 = v120 - v131;
        let v133: f64 = v98 + v132;
        let v134: f64 = v7 * v133;
        let v135: f64 = v99 * v27;
        let v136: f64 = v36 * v106;
        let v137: f64 = v28 * v122;
        let v138: f64 = v136 - v137;
        let v139: f64 = v135 + v138;
        let v140: f64 = v21 * v116;
        let v141: f64 = v3 * v111;
        let v142: f64 = v140 + v141;
        let v143: f64 = v139 + v142;
        let v144: f64 = v94 * v61;
        let v145: f64 = v61 * v144;
        let v146: f64 = v54 * v95;
        let v147: f64 = v145 + v146;
        let v148: f64 = v143 - v147;
        let v149: f64 = v48 * v148;
        let v150: f64 = v134 + v149;
        let v151: f64 = v67 * v150;
        let v152: f64 = v94 * v39;
        let v153: f64 = v43 * v144;
        let v154: f64 = v152 + v153;
        let v155: f64 = v33 * v119;
        let v156: f64 = v5 * v130;
        let v157: f64 = v155 + v156;
        let v158: f64 = v154 + v157;
        let v159: f64 = v9 * v158;
        let v160: f64 = v151 + v159;
        let v161: f64 = v93 * v160;
        let v162: f64 = v92 + v161;
        let v163: f64 = v9 * v162;
        let v164: f64 = v9 * v73;
        let v165: f64 = v67 * v62;
        let v166: f64 = v164 - v165;
        let v167: f64 = v10 * v166;
        let v168: f64 = v82 * v167;
        let v169: f64 = v166 * v89;
        let v170: f64 = v168 - v169;
        let v171: f64 = v67 * v65;
        let v172: f64 = v9 * v75;
        let v173: f64 = v171 + v172;
        let v174: f64 = v10 * v173;
        let v175: f64 = v170 - v174;
        let v176: f64 = v9 * v150;
        let v177: f64 = v67 * v158;
        let v178: f64 = v176 - v177;
        let v179: f64 = v93 * v178;
        (
            v1,
            v3,
            v5,
            v7,
            v9,
            v11,
            v13,
            v15,
            v16,
            v21,
            v22,
            v23,
            v27,
            v28,
            v33,
            v36,
            v39,
            v42,
            v43,
            v46,
            v48,
            v51,
            v54,
            v56,
            v58,
            v61,
            v62,
            v67,
            v70,
            v73,
            v77,
            v81,
            v82,
            v85,
            v86,
            v88,
            v93,
            v94,
            v99,
            v102,
            v111,
            v116,
            v119,
            v129,
            v130,
            v133,
            v143,
            v148,
            v150,
            v158,
            v160,
            v162,
            v163,
            v166,
            v167,
            v173,
            v175,
            v178,
            v179,
        )
    };
    let (
        v201,
        v208,
        v213,
        v215,
        v250,
        v252,
        v256,
        v270,
        v296,
        v298,
        v301,
        v303,
        v307,
        v310,
        v312,
        v314,
        v320,
        v324,
        v326,
        v340,
        v343,
        v346,
        v350,
        v355,
        v357,
        v358,
        v359,
    ) = {
        let v180: f64 = v175 + v179;
        let v181: f64 = v67 * v180;
        let v182: f64 = v163 - v181;
        let v183: f64 = 0.0003_f64;
        let v184: f64 = v183 * v58;
        let v185: f64 = 0.0004_f64;
        let v186: f64 = v185 * v62;
        let v187: f64 = v81 * v186;
        let v188: f64 = v183 * v81;
        let v189: f64 = v62 * v188;
        let v190: f64 = v187 - v189;
        let v191: f64 = v184 + v190;
        let v192: f64 = v182 + v191;
        let v193: f64 = v7 * v192;
        let v194: f64 = v85 * v167;
        let v195: f64 = v166 * v86;
        let v196: f64 = v194 - v195;
        let v197: f64 = v48 * v46;
        let v198: f64 = v7 * v56;
        let v199: f64 = v197 + v198;
        let v200: f64 = v88 * v199;
        let v201: f64 = v196 - v200;
        let v202: f64 = v183 * v73;
        let v203: f64 = v62 * v202;
        let v204: f64 = v73 * v186;
        let v205: f64 = v203 - v204;
        let v206: f64 = v183 * v199;
        let v207: f64 = v205 - v206;
        let v208: f64 = v201 + v207;
        let v209: f64 = v48 * v208;
        let v210: f64 = v193 - v209;
        let v211: f64 = 0.00209602_f64;
        let v212: f64 = v211 * v39;
        let v213: f64 = v211 * v61;
        let v214: f64 = v43 * v213;
        let v215: f64 = 0.0013_f64;
        let v216: f64 = v215 * v43;
        let v217: f64 = v61 * v216;
        let v218: f64 = v214 - v217;
        let v219: f64 = v212 + v218;
        let v220: f64 = 0.01558_f64;
        let v221: f64 = v220 * v158;
        let v222: f64 = v219 + v221;
        let v223: f64 = v210 + v222;
        let v224: f64 = 0.82_f64;
        let v225: f64 = v224 * v158;
        let v226: f64 = v220 * v39;
        let v227: f64 = v220 * v61;
        let v228: f64 = v43 * v227;
        let v229: f64 = v226 + v228;
        let v230: f64 = v225 + v229;
        let v231: f64 = 0.09_f64;
        let v232: f64 = v231 * v178;
        let v233: f64 = v93 * v166;
        let v234: f64 = v82 * v233;
        let v235: f64 = v93 * v173;
        let v236: f64 = v234 - v235;
        let v237: f64 = v232 + v236;
        let v238: f64 = v67 * v237;
        let v239: f64 = v231 * v160;
        let v240: f64 = v93 * v77;
        let v241: f64 = v93 * v85;
        let v242: f64 = v82 * v241;
        let v243: f64 = v240 + v242;
        let v244: f64 = v239 + v243;
        let v245: f64 = v9 * v244;
        let v246: f64 = v238 - v245;
        let v247: f64 = 0.34_f64;
        let v248: f64 = v247 * v158;
        let v249: f64 = v246 - v248;
        let v250: f64 = v230 - v249;
        let v251: f64 = v94 * v250;
        let v252: f64 = v223 + v251;
        let v253: f64 = v5 * v252;
        let v254: f64 = v211 * v70;
        let v255: f64 = v54 * v216;
        let v256: f64 = v211 * v54;
        let v257: f64 = v43 * v256;
        let v258: f64 = v255 - v257;
        let v259: f64 = v254 + v258;
        let v260: f64 = v220 * v133;
        let v261: f64 = v259 - v260;
        let v262: f64 = v67 * v162;
        let v263: f64 = v9 * v180;
        let v264: f64 = v262 + v263;
        let v265: f64 = v81 * v202;
        let v266: f64 = v73 * v188;
        let v267: f64 = v265 - v266;
        let v268: f64 = v185 * v70;
        let v269: f64 = v267 - v268;
        let v270: f64 = v264 + v269;
        let v271: f64 = v261 - v270;
        let v272: f64 = v9 * v237;
        let v273: f64 = v67 * v244;
        let v274: f64 = v272 + v273;
        let v275: f64 = v247 * v150;
        let v276: f64 = v274 + v275;
        let v277: f64 = v7 * v276;
        let v278: f64 = v7 * v148;
        let v279: f64 = v48 * v133;
        let v280: f64 = v278 - v279;
        let v281: f64 = v231 * v280;
        let v282: f64 = v166 * v233;
        let v283: f64 = v85 * v241;
        let v284: f64 = v282 + v283;
        let v285: f64 = v281 - v284;
        let v286: f64 = v247 * v280;
        let v287: f64 = v285 + v286;
        let v288: f64 = v48 * v287;
        let v289: f64 = v277 - v288;
        let v290: f64 = v224 * v133;
        let v291: f64 = v220 * v54;
        let v292: f64 = v43 * v291;
        let v293: f64 = v220 * v70;
        let v294: f64 = v292 - v293;
        let v295: f64 = v290 + v294;
        let v296: f64 = v289 + v295;
        let v297: f64 = v94 * v296;
        let v298: f64 = v271 - v297;
        let v299: f64 = v33 * v298;
        let v300: f64 = v253 + v299;
        let v301: f64 = 0.090474288_f64;
        let v302: f64 = v301 * v27;
        let v303: f64 = 0.0068208_f64;
        let v304: f64 = v303 * v51;
        let v305: f64 = v302 - v304;
        let v306: f64 = v303 * v36;
        let v307: f64 = 0.0047376_f64;
        let v308: f64 = v307 * v28;
        let v309: f64 = v306 - v308;
        let v310: f64 = 0.01543232_f64;
        let v311: f64 = v310 * v42;
        let v312: f64 = v309 + v311;
        let v313: f64 = v28 * v312;
        let v314: f64 = -0.001373904_f64;
        let v315: f64 = v314 * v36;
        let v316: f64 = 0.111498032_f64;
        let v317: f64 = v316 * v28;
        let v318: f64 = v315 - v317;
        let v319: f64 = v307 * v42;
        let v320: f64 = v318 + v319;
        let v321: f64 = v42 * v320;
        let v322: f64 = v313 + v321;
        let v323: f64 = v305 - v322;
        let v324: f64 = -0.06768_f64;
        let v325: f64 = v324 * v143;
        let v326: f64 = 0.336_f64;
        let v327: f64 = v326 * v130;
        let v328: f64 = v325 + v327;
        let v329: f64 = v323 + v328;
        let v330: f64 = v300 + v329;
        let v331: f64 = v48 * v276;
        let v332: f64 = v7 * v287;
        let v333: f64 = v331 + v332;
        let v334: f64 = v224 * v148;
        let v335: f64 = v61 * v227;
        let v336: f64 = v54 * v291;
        let v337: f64 = v335 + v336;
        let v338: f64 = v334 - v337;
        let v339: f64 = v333 + v338;
        let v340: f64 = 4.8_f64;
        let v341: f64 = v340 * v143;
        let v342: f64 = v324 * v27;
        let v343: f64 = -0.09744_f64;
        let v344: f64 = v343 * v42;
        let v345: f64 = v326 * v36;
        let v346: f64 = v344 - v345;
        let v347: f64 = v36 * v346;
        let v348: f64 = v326 * v28;
        let v349: f64 = v324 * v42;
        let v350: f64 = v348 + v349;
        let v351: f64 = v28 * v350;
        let v352: f64 = v347 - v351;
        let v353: f64 = v342 + v352;
        let v354: f64 = v341 + v353;
        let v355: f64 = v339 + v354;
        let v356: f64 = v99 * v355;
        let v357: f64 = v330 + v356;
        let v358: f64 = v3 * v357;
        let v359: f64 = v48 * v192;
        (
            v201,
            v208,
            v213,
            v215,
            v250,
            v252,
            v256,
            v270,
            v296,
            v298,
            v301,
            v303,
            v307,
            v310,
            v312,
            v314,
            v320,
            v324,
            v326,
            v340,
            v343,
            v346,
            v350,
            v355,
            v357,
            v358,
            v359,
        )
    };
    let (v367, v490, v535, v536, v537) = {
        let v360: f64 = v7 * v208;
        let v361: f64 = v359 + v360;
        let v362: f64 = v61 * v256;
        let v363: f64 = v54 * v213;
        let v364: f64 = v362 - v363;
        let v365: f64 = v215 * v51;
        let v366: f64 = v364 - v365;
        let v367: f64 = v361 + v366;
        let v368: f64 = v303 * v27;
        let v369: f64 = v310 * v51;
        let v370: f64 = v368 - v369;
        let v371: f64 = v36 * v320;
        let v372: f64 = v301 * v36;
        let v373: f64 = v314 * v28;
        let v374: f64 = v372 - v373;
        let v375: f64 = v303 * v42;
        let v376: f64 = v374 + v375;
        let v377: f64 = v28 * v376;
        let v378: f64 = v371 + v377;
        let v379: f64 = v370 + v378;
        let v380: f64 = v343 * v130;
        let v381: f64 = v324 * v119;
        let v382: f64 = v380 + v381;
        let v383: f64 = v379 - v382;
        let v384: f64 = v367 + v383;
        let v385: f64 = v33 * v296;
        let v386: f64 = v5 * v250;
        let v387: f64 = v385 - v386;
        let v388: f64 = v340 * v130;
        let v389: f64 = v343 * v51;
        let v390: f64 = v326 * v27;
        let v391: f64 = v389 + v390;
        let v392: f64 = v42 * v350;
        let v393: f64 = v324 * v36;
        let v394: f64 = v343 * v28;
        let v395: f64 = v393 + v394;
        let v396: f64 = v36 * v395;
        let v397: f64 = v392 + v396;
        let v398: f64 = v391 + v397;
        let v399: f64 = v388 + v398;
        let v400: f64 = v387 - v399;
        let v401: f64 = v102 * v400;
        let v402: f64 = v5 * v296;
        let v403: f64 = v33 * v250;
        let v404: f64 = v402 + v403;
        let v405: f64 = v340 * v119;
        let v406: f64 = v324 * v51;
        let v407: f64 = v28 * v395;
        let v408: f64 = v42 * v346;
        let v409: f64 = v407 + v408;
        let v410: f64 = v406 - v409;
        let v411: f64 = v405 + v410;
        let v412: f64 = v404 + v411;
        let v413: f64 = v99 * v412;
        let v414: f64 = v401 - v413;
        let v415: f64 = v384 + v414;
        let v416: f64 = v21 * v415;
        let v417: f64 = v358 - v416;
        let v418: f64 = 1.03118515_f64;
        let v419: f64 = v418 * v15;
        let v420: f64 = 0.03798072_f64;
        let v421: f64 = v420 * v22;
        let v422: f64 = v419 - v421;
        let v423: f64 = 1.4401023_f64;
        let v424: f64 = v423 * v23;
        let v425: f64 = -0.023751_f64;
        let v426: f64 = v425 * v16;
        let v427: f64 = v424 + v426;
        let v428: f64 = 2.842524056_f64;
        let v429: f64 = v428 * v13;
        let v430: f64 = v427 + v429;
        let v431: f64 = v16 * v430;
        let v432: f64 = v420 * v23;
        let v433: f64 = 3.727456406_f64;
        let v434: f64 = v433 * v16;
        let v435: f64 = v432 + v434;
        let v436: f64 = v425 * v13;
        let v437: f64 = v435 + v436;
        let v438: f64 = v13 * v437;
        let v439: f64 = v431 - v438;
        let v440: f64 = v422 + v439;
        let v441: f64 = 0.1044_f64;
        let v442: f64 = v441 * v129;
        let v443: f64 = 3.9585_f64;
        let v444: f64 = v443 * v111;
        let v445: f64 = v442 - v444;
        let v446: f64 = v440 + v445;
        let v447: f64 = v417 + v446;
        let v448: f64 = v1 * v447;
        let v449: f64 = v21 * v357;
        let v450: f64 = v3 * v415;
        let v451: f64 = v449 + v450;
        let v452: f64 = v420 * v15;
        let v453: f64 = v433 * v22;
        let v454: f64 = v452 - v453;
        let v455: f64 = v418 * v23;
        let v456: f64 = v420 * v16;
        let v457: f64 = v455 + v456;
        let v458: f64 = v423 * v13;
        let v459: f64 = v457 + v458;
        let v460: f64 = v13 * v459;
        let v461: f64 = v23 * v430;
        let v462: f64 = v460 - v461;
        let v463: f64 = v454 + v462;
        let v464: f64 = v443 * v116;
        let v465: f64 = -6.33012_f64;
        let v466: f64 = v465 * v129;
        let v467: f64 = v464 + v466;
        let v468: f64 = v463 - v467;
        let v469: f64 = v451 + v468;
        let v470: f64 = 17.4_f64;
        let v471: f64 = v470 * v129;
        let v472: f64 = v441 * v15;
        let v473: f64 = v465 * v22;
        let v474: f64 = v472 + v473;
        let v475: f64 = v465 * v13;
        let v476: f64 = v443 * v23;
        let v477: f64 = v475 - v476;
        let v478: f64 = v23 * v477;
        let v479: f64 = v443 * v16;
        let v480: f64 = v441 * v13;
        let v481: f64 = v479 - v480;
        let v482: f64 = v16 * v481;
        let v483: f64 = v478 - v482;
        let v484: f64 = v474 + v483;
        let v485: f64 = v471 + v484;
        let v486: f64 = v485 - v400;
        let v487: f64 = v94 * v486;
        let v488: f64 = v469 - v487;
        let v489: f64 = v11 * v488;
        let v490: f64 = v448 + v489;
        let v491: f64 = v423 * v15;
        let v492: f64 = v425 * v22;
        let v493: f64 = v491 - v492;
        let v494: f64 = v23 * v437;
        let v495: f64 = v16 * v459;
        let v496: f64 = v494 - v495;
        let v497: f64 = v493 + v496;
        let v498: f64 = v465 * v111;
        let v499: f64 = v441 * v116;
        let v500: f64 = v498 + v499;
        let v501: f64 = v497 + v500;
        let v502: f64 = v33 * v252;
        let v503: f64 = v5 * v298;
        let v504: f64 = v502 - v503;
        let v505: f64 = v314 * v27;
        let v506: f64 = v307 * v51;
        let v507: f64 = v505 - v506;
        let v508: f64 = v42 * v376;
        let v509: f64 = v36 * v312;
        let v510: f64 = v508 - v509;
        let v511: f64 = v507 + v510;
        let v512: f64 = v326 * v119;
        let v513: f64 = v343 * v143;
        let v514: f64 = v512 - v513;
        let v515: f64 = v511 + v514;
        let v516: f64 = v504 + v515;
        let v517: f64 = v102 * v355;
        let v518: f64 = v516 - v517;
        let v519: f64 = v501 - v518;
        let v520: f64 = v21 * v412;
        let v521: f64 = v3 * v355;
        let v522: f64 = v520 + v521;
        let v523: f64 = v470 * v111;
        let v524: f64 = v13 * v481;
        let v525: f64 = v441 * v23;
        let v526: f64 = v465 * v16;
        let v527: f64 = v525 - v526;
        let v528: f64 = v23 * v527;
        let v529: f64 = v524 - v528;
        let v530: f64 = v443 * v15;
        let v531: f64 = v529 - v530;
        let v532: f64 = v523 + v531;
        let v533: f64 = v522 + v532;
        let v534: f64 = v94 * v533;
        let v535: f64 = v519 + v534;
        let v536: f64 = -v518;
        let v537: f64 = -v270;
        (v367, v490, v535, v536, v537)
    };
    [v490, v535, v536, v367, v537, v201]
}
/// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `gravity: [f64; 6]`: g(q), joint torques (N m) or forces (N) that hold the robot still
///
/// Operation count: 39 floating-point operations, 8 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn gravity(q: &[f64; 6]) -> [f64; 6] {
    let v0: f64 = 0.0_f64;
    let v1: f64 = 37.2347379_f64;
    let v2: f64 = 0.24892875_f64;
    let v3: f64 = 0.0282528_f64;
    let v4: f64 = q[4];
    let v5: f64 = ::libm::sin(v4);
    let v6: f64 = v3 * v5;
    let v7: f64 = q[3];
    let v8: f64 = ::libm::cos(v7);
    let v9: f64 = v6 * v8;
    let v10: f64 = v2 - v9;
    let v11: f64 = q[2];
    let v12: f64 = ::libm::cos(v11);
    let v13: f64 = v10 * v12;
    let v14: f64 = v1 + v13;
    let v15: f64 = -8.7439473_f64;
    let v16: f64 = ::libm::cos(v4);
    let v17: f64 = v3 * v16;
    let v18: f64 = v15 - v17;
    let v19: f64 = ::libm::sin(v11);
    let v20: f64 = v18 * v19;
    let v21: f64 = v14 + v20;
    let v22: f64 = q[1];
    let v23: f64 = ::libm::cos(v22);
    let v24: f64 = v21 * v23;
    let v25: f64 = -1.024164_f64;
    let v26: f64 = v18 * v12;
    let v27: f64 = v25 + v26;
    let v28: f64 = -0.24892875_f64;
    let v29: f64 = v28 + v9;
    let v30: f64 = v29 * v19;
    let v31: f64 = v27 + v30;
    let v32: f64 = ::libm::sin(v22);
    let v33: f64 = v31 * v32;
    let v34: f64 = v24 + v33;
    let v35: f64 = v13 + v20;
    let v36: f64 = v35 * v23;
    let v37: f64 = v26 + v30;
    let v38: f64 = v37 * v32;
    let v39: f64 = v36 + v38;
    let v40: f64 = v3 * v19;
    let v41: f64 = v40 * v23;
    let v42: f64 = v3 * v12;
    let v43: f64 = v42 * v32;
    let v44: f64 = v41 + v43;
    let v45: f64 = v44 * v5;
    let v46: f64 = ::libm::sin(v7);
    let v47: f64 = v45 * v46;
    let v48: f64 = v6 * v19;
    let v49: f64 = v17 * v8;
    let v50: f64 = v49 * v12;
    let v51: f64 = v48 - v50;
    let v52: f64 = v51 * v32;
    let v53: f64 = v6 * v12;
    let v54: f64 = v49 * v19;
    let v55: f64 = v53 + v54;
    let v56: f64 = v55 * v23;
    let v57: f64 = v52 - v56;
    [v0, v34, v39, v47, v57, v0]
}
/// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 6]`: joint velocities qd (rad/s or m/s)
/// - `qdd: &[f64; 6]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// # Output
///
/// `tau: [f64; 6]`: joint torques (N m) or forces (N), no external wrench
///
/// Operation count: 520 floating-point operations, 10 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn inverse_dynamics(q: &[f64; 6], qd: &[f64; 6], qdd: &[f64; 6]) -> [f64; 6] {
    let (
        v1,
        v3,
        v5,
        v7,
        v9,
        v10,
        v11,
        v13,
        v16,
        v18,
        v19,
        v24,
        v27,
        v28,
        v32,
        v33,
        v38,
        v39,
        v41,
        v44,
        v48,
        v51,
        v52,
        v55,
        v57,
        v60,
        v62,
        v65,
        v67,
        v69,
        v72,
        v73,
        v78,
        v81,
        v83,
        v86,
        v90,
        v94,
        v95,
        v98,
        v99,
        v101,
        v106,
        v107,
        v119,
        v125,
        v128,
        v131,
        v139,
        v149,
        v150,
        v153,
        v165,
        v170,
        v172,
        v180,
        v182,
        v184,
        v185,
        v188,
        v189,
        v192,
        v193,
        v194,
    ) = {
        let v0: f64 = q[1];
        let v1: f64 = ::libm::sin(v0);
        let v2: f64 = q[2];
        let v3: f64 = ::libm::cos(v2);
        let v4: f64 = q[3];
        let v5: f64 = ::libm::cos(v4);
        let v6: f64 = q[4];
        let v7: f64 = ::libm::cos(v6);
        let v8: f64 = q[5];
        let v9: f64 = ::libm::cos(v8);
        let v10: f64 = 0.00024216_f64;
        let v11: f64 = ::libm::cos(v0);
        let v12: f64 = qd[0];
        let v13: f64 = qd[1];
        let v14: f64 = v12 * v13;
        let v15: f64 = v11 * v14;
        let v16: f64 = qdd[0];
        let v17: f64 = v1 * v16;
        let v18: f64 = v15 + v17;
        let v19: f64 = v11 * v12;
        let v20: f64 = qd[2];
        let v21: f64 = v19 * v20;
        let v22: f64 = v18 + v21;
        let v23: f64 = v3 * v22;
        let v24: f64 = ::libm::sin(v2);
        let v25: f64 = v11 * v16;
        let v26: f64 = v1 * v14;
        let v27: f64 = v25 - v26;
        let v28: f64 = v1 * v12;
        let v29: f64 = v28 * v20;
        let v30: f64 = v27 - v29;
        let v31: f64 = v24 * v30;
        let v32: f64 = v23 + v31;
        let v33: f64 = v13 + v20;
        let v34: f64 = qd[3];
        let v35: f64 = v33 * v34;
        let v36: f64 = v32 - v35;
        let v37: f64 = v5 * v36;
        let v38: f64 = ::libm::sin(v4);
        let v39: f64 = qdd[1];
        let v40: f64 = qdd[2];
        let v41: f64 = v39 + v40;
        let v42: f64 = v3 * v28;
        let v43: f64 = v24 * v19;
        let v44: f64 = v42 + v43;
        let v45: f64 = v44 * v34;
        let v46: f64 = v41 + v45;
        let v47: f64 = v38 * v46;
        let v48: f64 = v37 - v47;
        let v49: f64 = v3 * v19;
        let v50: f64 = v24 * v28;
        let v51: f64 = v49 - v50;
        let v52: f64 = v51 + v34;
        let v53: f64 = qd[4];
        let v54: f64 = v52 * v53;
        let v55: f64 = v48 + v54;
        let v56: f64 = v7 * v55;
        let v57: f64 = ::libm::sin(v6);
        let v58: f64 = v3 * v30;
        let v59: f64 = v24 * v22;
        let v60: f64 = v58 - v59;
        let v61: f64 = qdd[3];
        let v62: f64 = v60 + v61;
        let v63: f64 = v5 * v44;
        let v64: f64 = v38 * v33;
        let v65: f64 = v63 - v64;
        let v66: f64 = v65 * v53;
        let v67: f64 = v62 - v66;
        let v68: f64 = v57 * v67;
        let v69: f64 = v56 + v68;
        let v70: f64 = v38 * v44;
        let v71: f64 = v5 * v33;
        let v72: f64 = v70 + v71;
        let v73: f64 = v72 + v53;
        let v74: f64 = qd[5];
        let v75: f64 = v73 * v74;
        let v76: f64 = v69 - v75;
        let v77: f64 = v9 * v76;
        let v78: f64 = ::libm::sin(v8);
        let v79: f64 = v38 * v36;
        let v80: f64 = v5 * v46;
        let v81: f64 = v79 + v80;
        let v82: f64 = qdd[4];
        let v83: f64 = v81 + v82;
        let v84: f64 = v7 * v65;
        let v85: f64 = v57 * v52;
        let v86: f64 = v84 + v85;
        let v87: f64 = v86 * v74;
        let v88: f64 = v83 + v87;
        let v89: f64 = v78 * v88;
        let v90: f64 = v77 - v89;
        let v91: f64 = v10 * v90;
        let v92: f64 = v7 * v52;
        let v93: f64 = v57 * v65;
        let v94: f64 = v92 - v93;
        let v95: f64 = v94 + v74;
        let v96: f64 = v78 * v86;
        let v97: f64 = v9 * v73;
        let v98: f64 = v96 + v97;
        let v99: f64 = v10 * v98;
        let v100: f64 = v95 * v99;
        let v101: f64 = 4e-05_f64;
        let v102: f64 = v101 * v95;
        let v103: f64 = v98 * v102;
        let v104: f64 = v100 - v103;
        let v105: f64 = v91 + v104;
        let v106: f64 = 0.00288_f64;
        let v107: f64 = 0.4318_f64;
        let v108: f64 = v107 * v65;
        let v109: f64 = v52 * v108;
        let v110: f64 = v107 * v81;
        let v111: f64 = v109 - v110;
        let v112: f64 = 9.81_f64;
        let v113: f64 = v112 * v1;
        let v114: f64 = v107 * v19;
        let v115: f64 = v19 * v114;
        let v116: f64 = v107 * v13;
        let v117: f64 = v13 * v116;
        let v118: f64 = v115 + v117;
        let v119: f64 = v113 - v118;
        let v120: f64 = v3 * v119;
        let v121: f64 = v107 * v39;
        let v122: f64 = v28 * v114;
        let v123: f64 = v121 + v122;
        let v124: f64 = v112 * v11;
        let v125: f64 = v123 + v124;
        let v126: f64 = v24 * v125;
        let v127: f64 = v120 + v126;
        let v128: f64 = -0.15005_f64;
        let v129: f64 = v128 * v60;
        let v130: f64 = v128 * v44;
        let v131: f64 = 0.0203_f64;
        let v132: f64 = v131 * v33;
        let v133: f64 = v130 + v132;
        let v134: f64 = v33 * v133;
        let v135: f64 = v131 * v51;
        let v136: f64 = v51 * v135;
        let v137: f64 = v134 + v136;
        let v138: f64 = v129 + v137;
        let v139: f64 = v127 - v138;
        let v140: f64 = v5 * v139;
        let v141: f64 = v131 * v60;
        let v142: f64 = v128 * v51;
        let v143: f64 = v51 * v142;
        let v144: f64 = v44 * v133;
        let v145: f64 = v143 + v144;
        let v146: f64 = v141 - v145;
        let v147: f64 = v28 * v116;
        let v148: f64 = v107 * v27;
        let v149: f64 = v147 - v148;
        let v150: f64 = v146 - v149;
        let v151: f64 = v38 * v150;
        let v152: f64 = v140 + v151;
        let v153: f64 = v111 + v152;
        let v154: f64 = v7 * v153;
        let v155: f64 = v128 * v32;
        let v156: f64 = v131 * v41;
        let v157: f64 = v155 + v156;
        let v158: f64 = v44 * v135;
        let v159: f64 = v33 * v142;
        let v160: f64 = v158 - v159;
        let v161: f64 = v157 + v160;
        let v162: f64 = v3 * v125;
        let v163: f64 = v24 * v119;
        let v164: f64 = v162 - v163;
        let v165: f64 = v161 + v164;
        let v166: f64 = v107 * v72;
        let v167: f64 = v72 * v166;
        let v168: f64 = v65 * v108;
        let v169: f64 = v167 + v168;
        let v170: f64 = v165 - v169;
        let v171: f64 = v57 * v170;
        let v172: f64 = v154 + v171;
        let v173: f64 = v78 * v172;
        let v174: f64 = v107 * v48;
        let v175: f64 = v52 * v166;
        let v176: f64 = v174 + v175;
        let v177: f64 = v38 * v139;
        let v178: f64 = v5 * v150;
        let v179: f64 = v177 - v178;
        let v180: f64 = v176 + v179;
        let v181: f64 = v9 * v180;
        let v182: f64 = v173 + v181;
        let v183: f64 = v106 * v182;
        let v184: f64 = v105 + v183;
        let v185: f64 = v9 * v184;
        let v186: f64 = v9 * v86;
        let v187: f64 = v78 * v73;
        let v188: f64 = v186 - v187;
        let v189: f64 = v10 * v188;
        let v190: f64 = v95 * v189;
        let v191: f64 = v188 * v102;
        let v192: f64 = v190 - v191;
        let v193: f64 = v78 * v76;
        let v194: f64 = v9 * v88;
        (
            v1,
            v3,
            v5,
            v7,
            v9,
            v10,
            v11,
            v13,
            v16,
            v18,
            v19,
            v24,
            v27,
            v28,
            v32,
            v33,
            v38,
            v39,
            v41,
            v44,
            v48,
            v51,
            v52,
            v55,
            v57,
            v60,
            v62,
            v65,
            v67,
            v69,
            v72,
            v73,
            v78,
            v81,
            v83,
            v86,
            v90,
            v94,
            v95,
            v98,
            v99,
            v101,
            v106,
            v107,
            v119,
            v125,
            v128,
            v131,
            v139,
            v149,
            v150,
            v153,
            v165,
            v170,
            v172,
            v180,
            v182,
            v184,
            v185,
            v188,
            v189,
            v192,
            v193,
            v194,
        )
    };
    let (
        v225,
        v237,
        v239,
        v274,
        v276,
        v280,
        v294,
        v320,
        v322,
        v325,
        v327,
        v330,
        v334,
        v337,
        v339,
        v342,
        v346,
        v350,
        v352,
        v366,
        v369,
        v374,
        v378,
        v383,
        v385,
        v386,
        v389,
    ) = {
        let v195: f64 = v193 + v194;
        let v196: f64 = v10 * v195;
        let v197: f64 = v192 - v196;
        let v198: f64 = v9 * v172;
        let v199: f64 = v78 * v180;
        let v200: f64 = v198 - v199;
        let v201: f64 = v106 * v200;
        let v202: f64 = v197 + v201;
        let v203: f64 = v78 * v202;
        let v204: f64 = v185 - v203;
        let v205: f64 = 0.0003_f64;
        let v206: f64 = v205 * v69;
        let v207: f64 = 0.0004_f64;
        let v208: f64 = v207 * v73;
        let v209: f64 = v94 * v208;
        let v210: f64 = v205 * v94;
        let v211: f64 = v73 * v210;
        let v212: f64 = v209 - v211;
        let v213: f64 = v206 + v212;
        let v214: f64 = v204 + v213;
        let v215: f64 = v7 * v214;
        let v216: f64 = v7 * v67;
        let v217: f64 = v57 * v55;
        let v218: f64 = v216 - v217;
        let v219: f64 = qdd[5];
        let v220: f64 = v218 + v219;
        let v221: f64 = v101 * v220;
        let v222: f64 = v98 * v189;
        let v223: f64 = v188 * v99;
        let v224: f64 = v222 - v223;
        let v225: f64 = v221 + v224;
        let v226: f64 = v205 * v218;
        let v227: f64 = v205 * v86;
        let v228: f64 = v73 * v227;
        let v229: f64 = v86 * v208;
        let v230: f64 = v228 - v229;
        let v231: f64 = v226 + v230;
        let v232: f64 = v225 + v231;
        let v233: f64 = v57 * v232;
        let v234: f64 = v215 - v233;
        let v235: f64 = 0.00209602_f64;
        let v236: f64 = v235 * v48;
        let v237: f64 = v235 * v72;
        let v238: f64 = v52 * v237;
        let v239: f64 = 0.0013_f64;
        let v240: f64 = v239 * v52;
        let v241: f64 = v72 * v240;
        let v242: f64 = v238 - v241;
        let v243: f64 = v236 + v242;
        let v244: f64 = 0.01558_f64;
        let v245: f64 = v244 * v180;
        let v246: f64 = v243 + v245;
        let v247: f64 = v234 + v246;
        let v248: f64 = 0.82_f64;
        let v249: f64 = v248 * v180;
        let v250: f64 = v244 * v48;
        let v251: f64 = v244 * v72;
        let v252: f64 = v52 * v251;
        let v253: f64 = v250 + v252;
        let v254: f64 = v249 + v253;
        let v255: f64 = 0.09_f64;
        let v256: f64 = v255 * v200;
        let v257: f64 = v106 * v188;
        let v258: f64 = v95 * v257;
        let v259: f64 = v106 * v195;
        let v260: f64 = v258 - v259;
        let v261: f64 = v256 + v260;
        let v262: f64 = v78 * v261;
        let v263: f64 = v255 * v182;
        let v264: f64 = v106 * v90;
        let v265: f64 = v106 * v98;
        let v266: f64 = v95 * v265;
        let v267: f64 = v264 + v266;
        let v268: f64 = v263 + v267;
        let v269: f64 = v9 * v268;
        let v270: f64 = v262 - v269;
        let v271: f64 = 0.34_f64;
        let v272: f64 = v271 * v180;
        let v273: f64 = v270 - v272;
        let v274: f64 = v254 - v273;
        let v275: f64 = v107 * v274;
        let v276: f64 = v247 + v275;
        let v277: f64 = v5 * v276;
        let v278: f64 = v235 * v81;
        let v279: f64 = v65 * v240;
        let v280: f64 = v235 * v65;
        let v281: f64 = v52 * v280;
        let v282: f64 = v279 - v281;
        let v283: f64 = v278 + v282;
        let v284: f64 = v244 * v153;
        let v285: f64 = v283 - v284;
        let v286: f64 = v78 * v184;
        let v287: f64 = v9 * v202;
        let v288: f64 = v286 + v287;
        let v289: f64 = v94 * v227;
        let v290: f64 = v86 * v210;
        let v291: f64 = v289 - v290;
        let v292: f64 = v207 * v83;
        let v293: f64 = v291 - v292;
        let v294: f64 = v288 + v293;
        let v295: f64 = v285 - v294;
        let v296: f64 = v9 * v261;
        let v297: f64 = v78 * v268;
        let v298: f64 = v296 + v297;
        let v299: f64 = v271 * v172;
        let v300: f64 = v298 + v299;
        let v301: f64 = v7 * v300;
        let v302: f64 = v7 * v170;
        let v303: f64 = v57 * v153;
        let v304: f64 = v302 - v303;
        let v305: f64 = v255 * v304;
        let v306: f64 = v188 * v257;
        let v307: f64 = v98 * v265;
        let v308: f64 = v306 + v307;
        let v309: f64 = v305 - v308;
        let v310: f64 = v271 * v304;
        let v311: f64 = v309 + v310;
        let v312: f64 = v57 * v311;
        let v313: f64 = v301 - v312;
        let v314: f64 = v248 * v153;
        let v315: f64 = v244 * v65;
        let v316: f64 = v52 * v315;
        let v317: f64 = v244 * v81;
        let v318: f64 = v316 - v317;
        let v319: f64 = v314 + v318;
        let v320: f64 = v313 + v319;
        let v321: f64 = v107 * v320;
        let v322: f64 = v295 - v321;
        let v323: f64 = v38 * v322;
        let v324: f64 = v277 + v323;
        let v325: f64 = 0.090474288_f64;
        let v326: f64 = v325 * v32;
        let v327: f64 = -0.001373904_f64;
        let v328: f64 = v327 * v41;
        let v329: f64 = v326 - v328;
        let v330: f64 = 0.0068208_f64;
        let v331: f64 = v330 * v60;
        let v332: f64 = v329 + v331;
        let v333: f64 = v330 * v44;
        let v334: f64 = 0.0047376_f64;
        let v335: f64 = v334 * v33;
        let v336: f64 = v333 - v335;
        let v337: f64 = 0.01543232_f64;
        let v338: f64 = v337 * v51;
        let v339: f64 = v336 + v338;
        let v340: f64 = v33 * v339;
        let v341: f64 = v327 * v44;
        let v342: f64 = 0.111498032_f64;
        let v343: f64 = v342 * v33;
        let v344: f64 = v341 - v343;
        let v345: f64 = v334 * v51;
        let v346: f64 = v344 + v345;
        let v347: f64 = v51 * v346;
        let v348: f64 = v340 + v347;
        let v349: f64 = v332 - v348;
        let v350: f64 = -0.06768_f64;
        let v351: f64 = v350 * v165;
        let v352: f64 = 0.336_f64;
        let v353: f64 = v352 * v150;
        let v354: f64 = v351 - v353;
        let v355: f64 = v349 + v354;
        let v356: f64 = v324 + v355;
        let v357: f64 = v57 * v300;
        let v358: f64 = v7 * v311;
        let v359: f64 = v357 + v358;
        let v360: f64 = v248 * v170;
        let v361: f64 = v72 * v251;
        let v362: f64 = v65 * v315;
        let v363: f64 = v361 + v362;
        let v364: f64 = v360 - v363;
        let v365: f64 = v359 + v364;
        let v366: f64 = 4.8_f64;
        let v367: f64 = v366 * v165;
        let v368: f64 = v350 * v32;
        let v369: f64 = -0.09744_f64;
        let v370: f64 = v369 * v41;
        let v371: f64 = v368 + v370;
        let v372: f64 = v369 * v51;
        let v373: f64 = v352 * v44;
        let v374: f64 = v372 - v373;
        let v375: f64 = v44 * v374;
        let v376: f64 = v352 * v33;
        let v377: f64 = v350 * v51;
        let v378: f64 = v376 + v377;
        let v379: f64 = v33 * v378;
        let v380: f64 = v375 - v379;
        let v381: f64 = v371 + v380;
        let v382: f64 = v367 + v381;
        let v383: f64 = v365 + v382;
        let v384: f64 = v128 * v383;
        let v385: f64 = v356 + v384;
        let v386: f64 = v3 * v385;
        let v387: f64 = v57 * v214;
        let v388: f64 = v7 * v232;
        let v389: f64 = v387 + v388;
        (
            v225,
            v237,
            v239,
            v274,
            v276,
            v280,
            v294,
            v320,
            v322,
            v325,
            v327,
            v330,
            v334,
            v337,
            v339,
            v342,
            v346,
            v350,
            v352,
            v366,
            v369,
            v374,
            v378,
            v383,
            v385,
            v386,
            v389,
        )
    };
    let (v395, v529, v580, v581, v582) = {
        let v390: f64 = v239 * v62;
        let v391: f64 = v72 * v280;
        let v392: f64 = v65 * v237;
        let v393: f64 = v391 - v392;
        let v394: f64 = v390 + v393;
        let v395: f64 = v389 + v394;
        let v396: f64 = v330 * v32;
        let v397: f64 = v334 * v41;
        let v398: f64 = v396 - v397;
        let v399: f64 = v337 * v60;
        let v400: f64 = v398 + v399;
        let v401: f64 = v44 * v346;
        let v402: f64 = v325 * v44;
        let v403: f64 = v327 * v33;
        let v404: f64 = v402 - v403;
        let v405: f64 = v330 * v51;
        let v406: f64 = v404 + v405;
        let v407: f64 = v33 * v406;
        let v408: f64 = v401 + v407;
        let v409: f64 = v400 + v408;
        let v410: f64 = v369 * v150;
        let v411: f64 = v350 * v139;
        let v412: f64 = v410 - v411;
        let v413: f64 = v409 + v412;
        let v414: f64 = v395 + v413;
        let v415: f64 = v38 * v320;
        let v416: f64 = v5 * v274;
        let v417: f64 = v415 - v416;
        let v418: f64 = v366 * v150;
        let v419: f64 = v369 * v60;
        let v420: f64 = v352 * v32;
        let v421: f64 = v419 - v420;
        let v422: f64 = v51 * v378;
        let v423: f64 = v350 * v44;
        let v424: f64 = v369 * v33;
        let v425: f64 = v423 + v424;
        let v426: f64 = v44 * v425;
        let v427: f64 = v422 + v426;
        let v428: f64 = v421 - v427;
        let v429: f64 = v418 + v428;
        let v430: f64 = v417 + v429;
        let v431: f64 = v131 * v430;
        let v432: f64 = v5 * v320;
        let v433: f64 = v38 * v274;
        let v434: f64 = v432 + v433;
        let v435: f64 = v366 * v139;
        let v436: f64 = v352 * v41;
        let v437: f64 = v350 * v60;
        let v438: f64 = v436 + v437;
        let v439: f64 = v33 * v425;
        let v440: f64 = v51 * v374;
        let v441: f64 = v439 + v440;
        let v442: f64 = v438 + v441;
        let v443: f64 = v435 - v442;
        let v444: f64 = v434 + v443;
        let v445: f64 = v128 * v444;
        let v446: f64 = v431 - v445;
        let v447: f64 = v414 + v446;
        let v448: f64 = v24 * v447;
        let v449: f64 = v386 - v448;
        let v450: f64 = 1.03118515_f64;
        let v451: f64 = v450 * v18;
        let v452: f64 = 0.03798072_f64;
        let v453: f64 = v452 * v27;
        let v454: f64 = v451 + v453;
        let v455: f64 = 1.4401023_f64;
        let v456: f64 = v455 * v39;
        let v457: f64 = v454 + v456;
        let v458: f64 = v455 * v28;
        let v459: f64 = -0.023751_f64;
        let v460: f64 = v459 * v19;
        let v461: f64 = v458 + v460;
        let v462: f64 = 2.842524056_f64;
        let v463: f64 = v462 * v13;
        let v464: f64 = v461 + v463;
        let v465: f64 = v19 * v464;
        let v466: f64 = v452 * v28;
        let v467: f64 = 3.727456406_f64;
        let v468: f64 = v467 * v19;
        let v469: f64 = v466 + v468;
        let v470: f64 = v459 * v13;
        let v471: f64 = v469 + v470;
        let v472: f64 = v13 * v471;
        let v473: f64 = v465 - v472;
        let v474: f64 = v457 + v473;
        let v475: f64 = 0.1044_f64;
        let v476: f64 = v475 * v149;
        let v477: f64 = 3.9585_f64;
        let v478: f64 = v477 * v125;
        let v479: f64 = v476 - v478;
        let v480: f64 = v474 + v479;
        let v481: f64 = v449 + v480;
        let v482: f64 = v1 * v481;
        let v483: f64 = v24 * v385;
        let v484: f64 = v3 * v447;
        let v485: f64 = v483 + v484;
        let v486: f64 = v452 * v18;
        let v487: f64 = v467 * v27;
        let v488: f64 = v486 + v487;
        let v489: f64 = v459 * v39;
        let v490: f64 = v488 + v489;
        let v491: f64 = v450 * v28;
        let v492: f64 = v452 * v19;
        let v493: f64 = v491 + v492;
        let v494: f64 = v455 * v13;
        let v495: f64 = v493 + v494;
        let v496: f64 = v13 * v495;
        let v497: f64 = v28 * v464;
        let v498: f64 = v496 - v497;
        let v499: f64 = v490 + v498;
        let v500: f64 = v477 * v119;
        let v501: f64 = -6.33012_f64;
        let v502: f64 = v501 * v149;
        let v503: f64 = v500 - v502;
        let v504: f64 = v499 + v503;
        let v505: f64 = v485 + v504;
        let v506: f64 = 17.4_f64;
        let v507: f64 = v506 * v149;
        let v508: f64 = v475 * v18;
        let v509: f64 = v501 * v27;
        let v510: f64 = v508 - v509;
        let v511: f64 = v501 * v13;
        let v512: f64 = v477 * v28;
        let v513: f64 = v511 - v512;
        let v514: f64 = v28 * v513;
        let v515: f64 = v477 * v19;
        let v516: f64 = v475 * v13;
        let v517: f64 = v515 - v516;
        let v518: f64 = v19 * v517;
        let v519: f64 = v514 - v518;
        let v520: f64 = v510 + v519;
        let v521: f64 = v507 + v520;
        let v522: f64 = v521 - v430;
        let v523: f64 = v107 * v522;
        let v524: f64 = v505 - v523;
        let v525: f64 = v11 * v524;
        let v526: f64 = v482 + v525;
        let v527: f64 = 0.35_f64;
        let v528: f64 = v527 * v16;
        let v529: f64 = v526 + v528;
        let v530: f64 = v455 * v18;
        let v531: f64 = v459 * v27;
        let v532: f64 = v530 + v531;
        let v533: f64 = v462 * v39;
        let v534: f64 = v532 + v533;
        let v535: f64 = v28 * v471;
        let v536: f64 = v19 * v495;
        let v537: f64 = v535 - v536;
        let v538: f64 = v534 + v537;
        let v539: f64 = v501 * v125;
        let v540: f64 = v475 * v119;
        let v541: f64 = v539 - v540;
        let v542: f64 = v538 + v541;
        let v543: f64 = v38 * v276;
        let v544: f64 = v5 * v322;
        let v545: f64 = v543 - v544;
        let v546: f64 = v327 * v32;
        let v547: f64 = v342 * v41;
        let v548: f64 = v546 - v547;
        let v549: f64 = v334 * v60;
        let v550: f64 = v548 + v549;
        let v551: f64 = v51 * v406;
        let v552: f64 = v44 * v339;
        let v553: f64 = v551 - v552;
        let v554: f64 = v550 + v553;
        let v555: f64 = v352 * v139;
        let v556: f64 = v369 * v165;
        let v557: f64 = v555 - v556;
        let v558: f64 = v554 + v557;
        let v559: f64 = v545 + v558;
        let v560: f64 = v131 * v383;
        let v561: f64 = v559 - v560;
        let v562: f64 = v542 - v561;
        let v563: f64 = v24 * v444;
        let v564: f64 = v3 * v383;
        let v565: f64 = v563 + v564;
        let v566: f64 = v506 * v125;
        let v567: f64 = v501 * v39;
        let v568: f64 = v477 * v18;
        let v569: f64 = v567 - v568;
        let v570: f64 = v13 * v517;
        let v571: f64 = v475 * v28;
        let v572: f64 = v501 * v19;
        let v573: f64 = v571 - v572;
        let v574: f64 = v28 * v573;
        let v575: f64 = v570 - v574;
        let v576: f64 = v569 + v575;
        let v577: f64 = v566 + v576;
        let v578: f64 = v565 + v577;
        let v579: f64 = v107 * v578;
        let v580: f64 = v562 + v579;
        let v581: f64 = -v561;
        let v582: f64 = -v294;
        (v395, v529, v580, v581, v582)
    };
    [v529, v580, v581, v395, v582, v225]
}
/// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g.
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 6]`: joint velocities qd (rad/s or m/s)
/// - `tau: &[f64; 6]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
///
/// # Output
///
/// `qdd: [f64; 6]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// Operation count: 871 floating-point operations, 10 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn forward_dynamics(q: &[f64; 6], qd: &[f64; 6], tau: &[f64; 6]) -> [f64; 6] {
    let (
        v0,
        v2,
        v4,
        v6,
        v8,
        v10,
        v12,
        v14,
        v16,
        v17,
        v22,
        v23,
        v24,
        v28,
        v29,
        v34,
        v37,
        v40,
        v43,
        v44,
        v47,
        v49,
        v52,
        v55,
        v57,
        v62,
        v63,
        v68,
        v71,
        v74,
        v78,
        v82,
        v83,
        v86,
        v87,
        v89,
        v94,
        v95,
        v100,
        v103,
        v118,
        v122,
        v125,
        v135,
        v136,
        v139,
        v149,
        v154,
        v156,
        v164,
        v166,
        v168,
        v172,
        v173,
        v179,
        v184,
        v186,
        v188,
        v189,
        v190,
        v191,
        v192,
        v193,
        v194,
        v195,
    ) = {
        let v0: f64 = tau[0];
        let v1: f64 = q[1];
        let v2: f64 = ::libm::sin(v1);
        let v3: f64 = q[2];
        let v4: f64 = ::libm::cos(v3);
        let v5: f64 = q[3];
        let v6: f64 = ::libm::cos(v5);
        let v7: f64 = q[4];
        let v8: f64 = ::libm::cos(v7);
        let v9: f64 = q[5];
        let v10: f64 = ::libm::cos(v9);
        let v11: f64 = 0.00024216_f64;
        let v12: f64 = ::libm::cos(v1);
        let v13: f64 = qd[0];
        let v14: f64 = qd[1];
        let v15: f64 = v13 * v14;
        let v16: f64 = v12 * v15;
        let v17: f64 = v12 * v13;
        let v18: f64 = qd[2];
        let v19: f64 = v17 * v18;
        let v20: f64 = v16 + v19;
        let v21: f64 = v4 * v20;
        let v22: f64 = ::libm::sin(v3);
        let v23: f64 = v2 * v15;
        let v24: f64 = v2 * v13;
        let v25: f64 = v24 * v18;
        let v26: f64 = v23 + v25;
        let v27: f64 = v22 * v26;
        let v28: f64 = v21 - v27;
        let v29: f64 = v14 + v18;
        let v30: f64 = qd[3];
        let v31: f64 = v29 * v30;
        let v32: f64 = v28 - v31;
        let v33: f64 = v6 * v32;
        let v34: f64 = ::libm::sin(v5);
        let v35: f64 = v4 * v24;
        let v36: f64 = v22 * v17;
        let v37: f64 = v35 + v36;
        let v38: f64 = v37 * v30;
        let v39: f64 = v34 * v38;
        let v40: f64 = v33 - v39;
        let v41: f64 = v4 * v17;
        let v42: f64 = v22 * v24;
        let v43: f64 = v41 - v42;
        let v44: f64 = v43 + v30;
        let v45: f64 = qd[4];
        let v46: f64 = v44 * v45;
        let v47: f64 = v40 + v46;
        let v48: f64 = v8 * v47;
        let v49: f64 = ::libm::sin(v7);
        let v50: f64 = v22 * v20;
        let v51: f64 = v4 * v26;
        let v52: f64 = v50 + v51;
        let v53: f64 = v6 * v37;
        let v54: f64 = v34 * v29;
        let v55: f64 = v53 - v54;
        let v56: f64 = v55 * v45;
        let v57: f64 = v52 + v56;
        let v58: f64 = v49 * v57;
        let v59: f64 = v48 - v58;
        let v60: f64 = v34 * v37;
        let v61: f64 = v6 * v29;
        let v62: f64 = v60 + v61;
        let v63: f64 = v62 + v45;
        let v64: f64 = qd[5];
        let v65: f64 = v63 * v64;
        let v66: f64 = v59 - v65;
        let v67: f64 = v10 * v66;
        let v68: f64 = ::libm::sin(v9);
        let v69: f64 = v34 * v32;
        let v70: f64 = v6 * v38;
        let v71: f64 = v69 + v70;
        let v72: f64 = v8 * v55;
        let v73: f64 = v49 * v44;
        let v74: f64 = v72 + v73;
        let v75: f64 = v74 * v64;
        let v76: f64 = v71 + v75;
        let v77: f64 = v68 * v76;
        let v78: f64 = v67 - v77;
        let v79: f64 = v11 * v78;
        let v80: f64 = v8 * v44;
        let v81: f64 = v49 * v55;
        let v82: f64 = v80 - v81;
        let v83: f64 = v82 + v64;
        let v84: f64 = v68 * v74;
        let v85: f64 = v10 * v63;
        let v86: f64 = v84 + v85;
        let v87: f64 = v11 * v86;
        let v88: f64 = v83 * v87;
        let v89: f64 = 4e-05_f64;
        let v90: f64 = v89 * v83;
        let v91: f64 = v86 * v90;
        let v92: f64 = v88 - v91;
        let v93: f64 = v79 + v92;
        let v94: f64 = 0.00288_f64;
        let v95: f64 = 0.4318_f64;
        let v96: f64 = v95 * v55;
        let v97: f64 = v44 * v96;
        let v98: f64 = v95 * v71;
        let v99: f64 = v97 - v98;
        let v100: f64 = -0.15005_f64;
        let v101: f64 = v100 * v52;
        let v102: f64 = v100 * v37;
        let v103: f64 = 0.0203_f64;
        let v104: f64 = v103 * v29;
        let v105: f64 = v102 + v104;
        let v106: f64 = v29 * v105;
        let v107: f64 = v103 * v43;
        let v108: f64 = v43 * v107;
        let v109: f64 = v106 + v108;
        let v110: f64 = v101 - v109;
        let v111: f64 = 9.81_f64;
        let v112: f64 = v111 * v2;
        let v113: f64 = v95 * v17;
        let v114: f64 = v17 * v113;
        let v115: f64 = v95 * v14;
        let v116: f64 = v14 * v115;
        let v117: f64 = v114 + v116;
        let v118: f64 = v112 - v117;
        let v119: f64 = v4 * v118;
        let v120: f64 = v24 * v113;
        let v121: f64 = v111 * v12;
        let v122: f64 = v120 + v121;
        let v123: f64 = v22 * v122;
        let v124: f64 = v119 + v123;
        let v125: f64 = v110 + v124;
        let v126: f64 = v6 * v125;
        let v127: f64 = v103 * v52;
        let v128: f64 = v100 * v43;
        let v129: f64 = v43 * v128;
        let v130: f64 = v37 * v105;
        let v131: f64 = v129 + v130;
        let v132: f64 = v127 + v131;
        let v133: f64 = v95 * v23;
        let v134: f64 = v24 * v115;
        let v135: f64 = v133 + v134;
        let v136: f64 = v132 + v135;
        let v137: f64 = v34 * v136;
        let v138: f64 = v126 - v137;
        let v139: f64 = v99 + v138;
        let v140: f64 = v8 * v139;
        let v141: f64 = v100 * v28;
        let v142: f64 = v37 * v107;
        let v143: f64 = v29 * v128;
        let v144: f64 = v142 - v143;
        let v145: f64 = v141 + v144;
        let v146: f64 = v4 * v122;
        let v147: f64 = v22 * v118;
        let v148: f64 = v146 - v147;
        let v149: f64 = v145 + v148;
        let v150: f64 = v95 * v62;
        let v151: f64 = v62 * v150;
        let v152: f64 = v55 * v96;
        let v153: f64 = v151 + v152;
        let v154: f64 = v149 - v153;
        let v155: f64 = v49 * v154;
        let v156: f64 = v140 + v155;
        let v157: f64 = v68 * v156;
        let v158: f64 = v95 * v40;
        let v159: f64 = v44 * v150;
        let v160: f64 = v158 + v159;
        let v161: f64 = v34 * v125;
        let v162: f64 = v6 * v136;
        let v163: f64 = v161 + v162;
        let v164: f64 = v160 + v163;
        let v165: f64 = v10 * v164;
        let v166: f64 = v157 + v165;
        let v167: f64 = v94 * v166;
        let v168: f64 = v93 + v167;
        let v169: f64 = v10 * v168;
        let v170: f64 = v10 * v74;
        let v171: f64 = v68 * v63;
        let v172: f64 = v170 - v171;
        let v173: f64 = v11 * v172;
        let v174: f64 = v83 * v173;
        let v175: f64 = v172 * v90;
        let v176: f64 = v174 - v175;
        let v177: f64 = v68 * v66;
        let v178: f64 = v10 * v76;
        let v179: f64 = v177 + v178;
        let v180: f64 = v11 * v179;
        let v181: f64 = v176 - v180;
        let v182: f64 = v10 * v156;
        let v183: f64 = v68 * v164;
        let v184: f64 = v182 - v183;
        let v185: f64 = v94 * v184;
        let v186: f64 = v181 + v185;
        let v187: f64 = v68 * v186;
        let v188: f64 = v169 - v187;
        let v189: f64 = 0.0003_f64;
        let v190: f64 = v189 * v59;
        let v191: f64 = 0.0004_f64;
        let v192: f64 = v191 * v63;
        let v193: f64 = v82 * v192;
        let v194: f64 = v189 * v82;
        let v195: f64 = v63 * v194;
        (
            v0,
            v2,
            v4,
            v6,
            v8,
            v10,
            v12,
            v14,
            v16,
            v17,
            v22,
            v23,
            v24,
            v28,
            v29,
            v34,
            v37,
            v40,
            v43,
            v44,
            v47,
            v49,
            v52,
            v55,
            v57,
            v62,
            v63,
            v68,
            v71,
            v74,
            v78,
            v82,
            v83,
            v86,
            v87,
            v89,
            v94,
            v95,
            v100,
            v103,
            v118,
            v122,
            v125,
            v135,
            v136,
            v139,
            v149,
            v154,
            v156,
            v164,
            v166,
            v168,
            v172,
            v173,
            v179,
            v184,
            v186,
            v188,
            v189,
            v190,
            v191,
            v192,
            v193,
            v194,
            v195,
        )
    };
    let (
        v207,
        v256,
        v258,
        v276,
        v302,
        v304,
        v313,
        v318,
        v320,
        v330,
        v332,
        v346,
        v349,
        v352,
        v356,
        v361,
        v363,
        v364,
        v373,
        v382,
        v390,
        v391,
    ) = {
        let v196: f64 = v193 - v195;
        let v197: f64 = v190 + v196;
        let v198: f64 = v188 + v197;
        let v199: f64 = v8 * v198;
        let v200: f64 = v86 * v173;
        let v201: f64 = v172 * v87;
        let v202: f64 = v200 - v201;
        let v203: f64 = v49 * v47;
        let v204: f64 = v8 * v57;
        let v205: f64 = v203 + v204;
        let v206: f64 = v89 * v205;
        let v207: f64 = v202 - v206;
        let v208: f64 = v189 * v74;
        let v209: f64 = v63 * v208;
        let v210: f64 = v74 * v192;
        let v211: f64 = v209 - v210;
        let v212: f64 = v189 * v205;
        let v213: f64 = v211 - v212;
        let v214: f64 = v207 + v213;
        let v215: f64 = v49 * v214;
        let v216: f64 = v199 - v215;
        let v217: f64 = 0.00209602_f64;
        let v218: f64 = v217 * v40;
        let v219: f64 = v217 * v62;
        let v220: f64 = v44 * v219;
        let v221: f64 = 0.0013_f64;
        let v222: f64 = v221 * v44;
        let v223: f64 = v62 * v222;
        let v224: f64 = v220 - v223;
        let v225: f64 = v218 + v224;
        let v226: f64 = 0.01558_f64;
        let v227: f64 = v226 * v164;
        let v228: f64 = v225 + v227;
        let v229: f64 = v216 + v228;
        let v230: f64 = 0.82_f64;
        let v231: f64 = v230 * v164;
        let v232: f64 = v226 * v40;
        let v233: f64 = v226 * v62;
        let v234: f64 = v44 * v233;
        let v235: f64 = v232 + v234;
        let v236: f64 = v231 + v235;
        let v237: f64 = 0.09_f64;
        let v238: f64 = v237 * v184;
        let v239: f64 = v94 * v172;
        let v240: f64 = v83 * v239;
        let v241: f64 = v94 * v179;
        let v242: f64 = v240 - v241;
        let v243: f64 = v238 + v242;
        let v244: f64 = v68 * v243;
        let v245: f64 = v237 * v166;
        let v246: f64 = v94 * v78;
        let v247: f64 = v94 * v86;
        let v248: f64 = v83 * v247;
        let v249: f64 = v246 + v248;
        let v250: f64 = v245 + v249;
        let v251: f64 = v10 * v250;
        let v252: f64 = v244 - v251;
        let v253: f64 = 0.34_f64;
        let v254: f64 = v253 * v164;
        let v255: f64 = v252 - v254;
        let v256: f64 = v236 - v255;
        let v257: f64 = v95 * v256;
        let v258: f64 = v229 + v257;
        let v259: f64 = v6 * v258;
        let v260: f64 = v217 * v71;
        let v261: f64 = v55 * v222;
        let v262: f64 = v217 * v55;
        let v263: f64 = v44 * v262;
        let v264: f64 = v261 - v263;
        let v265: f64 = v260 + v264;
        let v266: f64 = v226 * v139;
        let v267: f64 = v265 - v266;
        let v268: f64 = v68 * v168;
        let v269: f64 = v10 * v186;
        let v270: f64 = v268 + v269;
        let v271: f64 = v82 * v208;
        let v272: f64 = v74 * v194;
        let v273: f64 = v271 - v272;
        let v274: f64 = v191 * v71;
        let v275: f64 = v273 - v274;
        let v276: f64 = v270 + v275;
        let v277: f64 = v267 - v276;
        let v278: f64 = v10 * v243;
        let v279: f64 = v68 * v250;
        let v280: f64 = v278 + v279;
        let v281: f64 = v253 * v156;
        let v282: f64 = v280 + v281;
        let v283: f64 = v8 * v282;
        let v284: f64 = v8 * v154;
        let v285: f64 = v49 * v139;
        let v286: f64 = v284 - v285;
        let v287: f64 = v237 * v286;
        let v288: f64 = v172 * v239;
        let v289: f64 = v86 * v247;
        let v290: f64 = v288 + v289;
        let v291: f64 = v287 - v290;
        let v292: f64 = v253 * v286;
        let v293: f64 = v291 + v292;
        let v294: f64 = v49 * v293;
        let v295: f64 = v283 - v294;
        let v296: f64 = v230 * v139;
        let v297: f64 = v226 * v55;
        let v298: f64 = v44 * v297;
        let v299: f64 = v226 * v71;
        let v300: f64 = v298 - v299;
        let v301: f64 = v296 + v300;
        let v302: f64 = v295 + v301;
        let v303: f64 = v95 * v302;
        let v304: f64 = v277 - v303;
        let v305: f64 = v34 * v304;
        let v306: f64 = v259 + v305;
        let v307: f64 = 0.090474288_f64;
        let v308: f64 = v307 * v28;
        let v309: f64 = 0.0068208_f64;
        let v310: f64 = v309 * v52;
        let v311: f64 = v308 - v310;
        let v312: f64 = v309 * v37;
        let v313: f64 = 0.0047376_f64;
        let v314: f64 = v313 * v29;
        let v315: f64 = v312 - v314;
        let v316: f64 = 0.01543232_f64;
        let v317: f64 = v316 * v43;
        let v318: f64 = v315 + v317;
        let v319: f64 = v29 * v318;
        let v320: f64 = -0.001373904_f64;
        let v321: f64 = v320 * v37;
        let v322: f64 = 0.111498032_f64;
        let v323: f64 = v322 * v29;
        let v324: f64 = v321 - v323;
        let v325: f64 = v313 * v43;
        let v326: f64 = v324 + v325;
        let v327: f64 = v43 * v326;
        let v328: f64 = v319 + v327;
        let v329: f64 = v311 - v328;
        let v330: f64 = -0.06768_f64;
        let v331: f64 = v330 * v149;
        let v332: f64 = 0.336_f64;
        let v333: f64 = v332 * v136;
        let v334: f64 = v331 + v333;
        let v335: f64 = v329 + v334;
        let v336: f64 = v306 + v335;
        let v337: f64 = v49 * v282;
        let v338: f64 = v8 * v293;
        let v339: f64 = v337 + v338;
        let v340: f64 = v230 * v154;
        let v341: f64 = v62 * v233;
        let v342: f64 = v55 * v297;
        let v343: f64 = v341 + v342;
        let v344: f64 = v340 - v343;
        let v345: f64 = v339 + v344;
        let v346: f64 = 4.8_f64;
        let v347: f64 = v346 * v149;
        let v348: f64 = v330 * v28;
        let v349: f64 = -0.09744_f64;
        let v350: f64 = v349 * v43;
        let v351: f64 = v332 * v37;
        let v352: f64 = v350 - v351;
        let v353: f64 = v37 * v352;
        let v354: f64 = v332 * v29;
        let v355: f64 = v330 * v43;
        let v356: f64 = v354 + v355;
        let v357: f64 = v29 * v356;
        let v358: f64 = v353 - v357;
        let v359: f64 = v348 + v358;
        let v360: f64 = v347 + v359;
        let v361: f64 = v345 + v360;
        let v362: f64 = v100 * v361;
        let v363: f64 = v336 + v362;
        let v364: f64 = v4 * v363;
        let v365: f64 = v49 * v198;
        let v366: f64 = v8 * v214;
        let v367: f64 = v365 + v366;
        let v368: f64 = v62 * v262;
        let v369: f64 = v55 * v219;
        let v370: f64 = v368 - v369;
        let v371: f64 = v221 * v52;
        let v372: f64 = v370 - v371;
        let v373: f64 = v367 + v372;
        let v374: f64 = v309 * v28;
        let v375: f64 = v316 * v52;
        let v376: f64 = v374 - v375;
        let v377: f64 = v37 * v326;
        let v378: f64 = v307 * v37;
        let v379: f64 = v320 * v29;
        let v380: f64 = v378 - v379;
        let v381: f64 = v309 * v43;
        let v382: f64 = v380 + v381;
        let v383: f64 = v29 * v382;
        let v384: f64 = v377 + v383;
        let v385: f64 = v376 + v384;
        let v386: f64 = v349 * v136;
        let v387: f64 = v330 * v125;
        let v388: f64 = v386 + v387;
        let v389: f64 = v385 - v388;
        let v390: f64 = v373 + v389;
        let v391: f64 = v34 * v302;
        (
            v207,
            v256,
            v258,
            v276,
            v302,
            v304,
            v313,
            v318,
            v320,
            v330,
            v332,
            v346,
            v349,
            v352,
            v356,
            v361,
            v363,
            v364,
            v373,
            v382,
            v390,
            v391,
        )
    };
    let (
        v418,
        v429,
        v431,
        v443,
        v447,
        v449,
        v465,
        v471,
        v476,
        v487,
        v498,
        v499,
        v501,
        v510,
        v511,
        v513,
        v516,
        v518,
        v520,
        v530,
        v536,
        v537,
        v538,
        v539,
        v542,
        v543,
        v545,
        v552,
        v553,
        v555,
        v557,
        v559,
        v560,
        v561,
        v562,
        v580,
        v581,
        v587,
    ) = {
        let v392: f64 = v6 * v256;
        let v393: f64 = v391 - v392;
        let v394: f64 = v346 * v136;
        let v395: f64 = v349 * v52;
        let v396: f64 = v332 * v28;
        let v397: f64 = v395 + v396;
        let v398: f64 = v43 * v356;
        let v399: f64 = v330 * v37;
        let v400: f64 = v349 * v29;
        let v401: f64 = v399 + v400;
        let v402: f64 = v37 * v401;
        let v403: f64 = v398 + v402;
        let v404: f64 = v397 + v403;
        let v405: f64 = v394 + v404;
        let v406: f64 = v393 - v405;
        let v407: f64 = v103 * v406;
        let v408: f64 = v6 * v302;
        let v409: f64 = v34 * v256;
        let v410: f64 = v408 + v409;
        let v411: f64 = v346 * v125;
        let v412: f64 = v330 * v52;
        let v413: f64 = v29 * v401;
        let v414: f64 = v43 * v352;
        let v415: f64 = v413 + v414;
        let v416: f64 = v412 - v415;
        let v417: f64 = v411 + v416;
        let v418: f64 = v410 + v417;
        let v419: f64 = v100 * v418;
        let v420: f64 = v407 - v419;
        let v421: f64 = v390 + v420;
        let v422: f64 = v22 * v421;
        let v423: f64 = v364 - v422;
        let v424: f64 = 1.03118515_f64;
        let v425: f64 = v424 * v16;
        let v426: f64 = 0.03798072_f64;
        let v427: f64 = v426 * v23;
        let v428: f64 = v425 - v427;
        let v429: f64 = 1.4401023_f64;
        let v430: f64 = v429 * v24;
        let v431: f64 = -0.023751_f64;
        let v432: f64 = v431 * v17;
        let v433: f64 = v430 + v432;
        let v434: f64 = 2.842524056_f64;
        let v435: f64 = v434 * v14;
        let v436: f64 = v433 + v435;
        let v437: f64 = v17 * v436;
        let v438: f64 = v426 * v24;
        let v439: f64 = 3.727456406_f64;
        let v440: f64 = v439 * v17;
        let v441: f64 = v438 + v440;
        let v442: f64 = v431 * v14;
        let v443: f64 = v441 + v442;
        let v444: f64 = v14 * v443;
        let v445: f64 = v437 - v444;
        let v446: f64 = v428 + v445;
        let v447: f64 = 0.1044_f64;
        let v448: f64 = v447 * v135;
        let v449: f64 = 3.9585_f64;
        let v450: f64 = v449 * v122;
        let v451: f64 = v448 - v450;
        let v452: f64 = v446 + v451;
        let v453: f64 = v423 + v452;
        let v454: f64 = v2 * v453;
        let v455: f64 = v22 * v363;
        let v456: f64 = v4 * v421;
        let v457: f64 = v455 + v456;
        let v458: f64 = v426 * v16;
        let v459: f64 = v439 * v23;
        let v460: f64 = v458 - v459;
        let v461: f64 = v424 * v24;
        let v462: f64 = v426 * v17;
        let v463: f64 = v461 + v462;
        let v464: f64 = v429 * v14;
        let v465: f64 = v463 + v464;
        let v466: f64 = v14 * v465;
        let v467: f64 = v24 * v436;
        let v468: f64 = v466 - v467;
        let v469: f64 = v460 + v468;
        let v470: f64 = v449 * v118;
        let v471: f64 = -6.33012_f64;
        let v472: f64 = v471 * v135;
        let v473: f64 = v470 - v472;
        let v474: f64 = v469 + v473;
        let v475: f64 = v457 + v474;
        let v476: f64 = 17.4_f64;
        let v477: f64 = v476 * v135;
        let v478: f64 = v447 * v16;
        let v479: f64 = v471 * v23;
        let v480: f64 = v478 + v479;
        let v481: f64 = v471 * v14;
        let v482: f64 = v449 * v24;
        let v483: f64 = v481 - v482;
        let v484: f64 = v24 * v483;
        let v485: f64 = v449 * v17;
        let v486: f64 = v447 * v14;
        let v487: f64 = v485 - v486;
        let v488: f64 = v17 * v487;
        let v489: f64 = v484 - v488;
        let v490: f64 = v480 + v489;
        let v491: f64 = v477 + v490;
        let v492: f64 = v491 - v406;
        let v493: f64 = v95 * v492;
        let v494: f64 = v475 - v493;
        let v495: f64 = v12 * v494;
        let v496: f64 = v454 + v495;
        let v497: f64 = v0 - v496;
        let v498: f64 = 24999.999999999996_f64;
        let v499: f64 = v89 * v8;
        let v500: f64 = v499 * v4;
        let v501: f64 = v89 * v49;
        let v502: f64 = v501 * v6;
        let v503: f64 = v502 * v22;
        let v504: f64 = v500 - v503;
        let v505: f64 = v504 * v12;
        let v506: f64 = v502 * v4;
        let v507: f64 = v499 * v22;
        let v508: f64 = v506 + v507;
        let v509: f64 = v508 * v2;
        let v510: f64 = v505 - v509;
        let v511: f64 = v498 * v510;
        let v512: f64 = tau[5];
        let v513: f64 = v512 - v207;
        let v514: f64 = v511 * v513;
        let v515: f64 = v497 - v514;
        let v516: f64 = 1557.24430048586_f64;
        let v517: f64 = 0.000432144_f64;
        let v518: f64 = v517 * v49;
        let v519: f64 = v518 * v22;
        let v520: f64 = v517 * v8;
        let v521: f64 = v520 * v6;
        let v522: f64 = v521 * v4;
        let v523: f64 = v519 - v522;
        let v524: f64 = v523 * v12;
        let v525: f64 = v518 * v4;
        let v526: f64 = v521 * v22;
        let v527: f64 = v525 + v526;
        let v528: f64 = v527 * v2;
        let v529: f64 = v524 + v528;
        let v530: f64 = 0.00064216_f64;
        let v531: f64 = v530 * v22;
        let v532: f64 = v531 * v12;
        let v533: f64 = v530 * v4;
        let v534: f64 = v533 * v2;
        let v535: f64 = v532 + v534;
        let v536: f64 = 0.001243584_f64;
        let v537: f64 = v536 * v4;
        let v538: f64 = 5.8464e-05_f64;
        let v539: f64 = v538 * v22;
        let v540: f64 = v537 + v539;
        let v541: f64 = v540 * v2;
        let v542: f64 = -0.001243584_f64;
        let v543: f64 = v538 * v4;
        let v544: f64 = v542 - v543;
        let v545: f64 = v536 * v22;
        let v546: f64 = v544 + v545;
        let v547: f64 = v546 * v12;
        let v548: f64 = v541 + v547;
        let v549: f64 = v548 * v8;
        let v550: f64 = v535 + v549;
        let v551: f64 = v550 * v34;
        let v552: f64 = v529 + v551;
        let v553: f64 = v516 * v552;
        let v554: f64 = tau[4];
        let v555: f64 = v554 + v276;
        let v556: f64 = v553 * v555;
        let v557: f64 = v515 - v556;
        let v558: f64 = 0.00184216_f64;
        let v559: f64 = 0.00020216_f64;
        let v560: f64 = v559 * v8;
        let v561: f64 = v560 * v8;
        let v562: f64 = v558 - v561;
        let v563: f64 = v562 * v4;
        let v564: f64 = v563 * v12;
        let v565: f64 = -0.00184216_f64;
        let v566: f64 = v565 + v561;
        let v567: f64 = v566 * v22;
        let v568: f64 = v567 * v2;
        let v569: f64 = v564 + v568;
        let v570: f64 = v517 * v4;
        let v571: f64 = v570 * v12;
        let v572: f64 = v517 * v22;
        let v573: f64 = v572 * v2;
        let v574: f64 = v571 - v573;
        let v575: f64 = v574 * v34;
        let v576: f64 = v536 + v560;
        let v577: f64 = v576 * v4;
        let v578: f64 = v539 + v577;
        let v579: f64 = v578 * v2;
        let v580: f64 = v576 * v22;
        let v581: f64 = v544 + v580;
        let v582: f64 = v581 * v12;
        let v583: f64 = v579 + v582;
        let v584: f64 = v583 * v6;
        let v585: f64 = v575 + v584;
        let v586: f64 = v585 * v49;
        let v587: f64 = v569 + v586;
        (
            v418,
            v429,
            v431,
            v443,
            v447,
            v449,
            v465,
            v471,
            v476,
            v487,
            v498,
            v499,
            v501,
            v510,
            v511,
            v513,
            v516,
            v518,
            v520,
            v530,
            v536,
            v537,
            v538,
            v539,
            v542,
            v543,
            v545,
            v552,
            v553,
            v555,
            v557,
            v559,
            v560,
            v561,
            v562,
            v580,
            v581,
            v587,
        )
    };
    let (
        v588,
        v590,
        v592,
        v593,
        v597,
        v616,
        v636,
        v644,
        v651,
        v653,
        v655,
        v657,
        v660,
        v661,
        v670,
        v671,
        v689,
        v691,
        v696,
        v698,
        v727,
        v734,
        v757,
        v759,
        v761,
        v765,
        v767,
        v783,
    ) = {
        let v588: f64 = v498 * v499;
        let v589: f64 = v510 * v588;
        let v590: f64 = v587 - v589;
        let v591: f64 = v499 * v588;
        let v592: f64 = v562 - v591;
        let v593: f64 = v590 / v592;
        let v594: f64 = tau[3];
        let v595: f64 = v594 - v373;
        let v596: f64 = v588 * v513;
        let v597: f64 = v595 - v596;
        let v598: f64 = v593 * v597;
        let v599: f64 = v557 - v598;
        let v600: f64 = -0.1384816665_f64;
        let v601: f64 = v600 - v520;
        let v602: f64 = v601 * v4;
        let v603: f64 = -0.00380751875_f64;
        let v604: f64 = v518 * v6;
        let v605: f64 = v603 + v604;
        let v606: f64 = v605 * v22;
        let v607: f64 = v602 + v606;
        let v608: f64 = v607 * v12;
        let v609: f64 = v605 * v4;
        let v610: f64 = 0.1384816665_f64;
        let v611: f64 = v610 + v520;
        let v612: f64 = v611 * v22;
        let v613: f64 = v609 + v612;
        let v614: f64 = v613 * v2;
        let v615: f64 = v608 + v614;
        let v616: f64 = 0.00030216_f64;
        let v617: f64 = v616 - v561;
        let v618: f64 = v617 * v22;
        let v619: f64 = v618 * v12;
        let v620: f64 = v617 * v4;
        let v621: f64 = v620 * v2;
        let v622: f64 = v619 + v621;
        let v623: f64 = v622 * v6;
        let v624: f64 = v542 - v560;
        let v625: f64 = v624 * v4;
        let v626: f64 = v625 - v539;
        let v627: f64 = v626 * v12;
        let v628: f64 = v580 - v543;
        let v629: f64 = v628 * v2;
        let v630: f64 = v627 + v629;
        let v631: f64 = v630 * v49;
        let v632: f64 = v623 + v631;
        let v633: f64 = v632 * v34;
        let v634: f64 = v615 + v633;
        let v635: f64 = v501 * v34;
        let v636: f64 = v498 * v635;
        let v637: f64 = v510 * v636;
        let v638: f64 = v634 - v637;
        let v639: f64 = v536 * v8;
        let v640: f64 = v530 + v639;
        let v641: f64 = v640 * v6;
        let v642: f64 = v538 * v49;
        let v643: f64 = v641 - v642;
        let v644: f64 = v516 * v643;
        let v645: f64 = v552 * v644;
        let v646: f64 = v638 - v645;
        let v647: f64 = v624 * v49;
        let v648: f64 = v647 * v34;
        let v649: f64 = v635 * v588;
        let v650: f64 = v648 - v649;
        let v651: f64 = v650 / v592;
        let v652: f64 = v590 * v651;
        let v653: f64 = v646 - v652;
        let v654: f64 = 0.3589900705_f64;
        let v655: f64 = 0.002487168_f64;
        let v656: f64 = v655 + v560;
        let v657: f64 = v656 * v8;
        let v658: f64 = v654 + v657;
        let v659: f64 = v617 * v6;
        let v660: f64 = 0.000116928_f64;
        let v661: f64 = v660 * v49;
        let v662: f64 = v659 - v661;
        let v663: f64 = v662 * v6;
        let v664: f64 = v658 + v663;
        let v665: f64 = v635 * v636;
        let v666: f64 = v664 - v665;
        let v667: f64 = v643 * v644;
        let v668: f64 = v666 - v667;
        let v669: f64 = v650 * v651;
        let v670: f64 = v668 - v669;
        let v671: f64 = v653 / v670;
        let v672: f64 = tau[2];
        let v673: f64 = v34 * v258;
        let v674: f64 = v6 * v304;
        let v675: f64 = v673 - v674;
        let v676: f64 = v320 * v28;
        let v677: f64 = v313 * v52;
        let v678: f64 = v676 - v677;
        let v679: f64 = v43 * v382;
        let v680: f64 = v37 * v318;
        let v681: f64 = v679 - v680;
        let v682: f64 = v678 + v681;
        let v683: f64 = v332 * v125;
        let v684: f64 = v349 * v149;
        let v685: f64 = v683 - v684;
        let v686: f64 = v682 + v685;
        let v687: f64 = v675 + v686;
        let v688: f64 = v103 * v361;
        let v689: f64 = v687 - v688;
        let v690: f64 = v672 + v689;
        let v691: f64 = v636 * v513;
        let v692: f64 = v690 - v691;
        let v693: f64 = v644 * v555;
        let v694: f64 = v692 - v693;
        let v695: f64 = v651 * v597;
        let v696: f64 = v694 - v695;
        let v697: f64 = v671 * v696;
        let v698: f64 = v599 - v697;
        let v699: f64 = v601 + v648;
        let v700: f64 = v699 * v4;
        let v701: f64 = v431 + v700;
        let v702: f64 = v659 - v642;
        let v703: f64 = v702 * v34;
        let v704: f64 = v605 + v703;
        let v705: f64 = v704 * v22;
        let v706: f64 = v701 + v705;
        let v707: f64 = v706 * v12;
        let v708: f64 = -0.6903913435_f64;
        let v709: f64 = v708 + v609;
        let v710: f64 = v709 + v612;
        let v711: f64 = v659 * v4;
        let v712: f64 = v581 * v49;
        let v713: f64 = v711 + v712;
        let v714: f64 = v713 * v34;
        let v715: f64 = v710 + v714;
        let v716: f64 = v715 * v2;
        let v717: f64 = v707 + v716;
        let v718: f64 = v717 - v637;
        let v719: f64 = -5.8464e-05_f64;
        let v720: f64 = v719 - v537;
        let v721: f64 = v720 * v49;
        let v722: f64 = v536 - v545;
        let v723: f64 = v722 * v8;
        let v724: f64 = v530 + v723;
        let v725: f64 = v724 * v6;
        let v726: f64 = v721 + v725;
        let v727: f64 = v516 * v726;
        let v728: f64 = v552 * v727;
        let v729: f64 = v718 - v728;
        let v730: f64 = v624 + v545;
        let v731: f64 = v730 * v49;
        let v732: f64 = v731 * v34;
        let v733: f64 = v732 - v649;
        let v734: f64 = v733 / v592;
        let v735: f64 = v590 * v734;
        let v736: f64 = v729 - v735;
        let v737: f64 = 0.010956925_f64;
        let v738: f64 = v737 * v4;
        let v739: f64 = v654 + v738;
        let v740: f64 = 0.384876294_f64;
        let v741: f64 = v740 * v22;
        let v742: f64 = v739 - v741;
        let v743: f64 = v656 - v545;
        let v744: f64 = v743 * v8;
        let v745: f64 = v742 + v744;
        let v746: f64 = -0.000116928_f64;
        let v747: f64 = v746 - v537;
        let v748: f64 = v747 * v49;
        let v749: f64 = v748 + v659;
        let v750: f64 = v749 * v6;
        let v751: f64 = v745 + v750;
        let v752: f64 = v751 - v665;
        let v753: f64 = v726 * v644;
        let v754: f64 = v752 - v753;
        let v755: f64 = v733 * v651;
        let v756: f64 = v754 - v755;
        let v757: f64 = v756 / v670;
        let v758: f64 = v653 * v757;
        let v759: f64 = v736 - v758;
        let v760: f64 = 2.1071040725_f64;
        let v761: f64 = 0.02191385_f64;
        let v762: f64 = v761 * v4;
        let v763: f64 = v760 + v762;
        let v764: f64 = 0.769752588_f64;
        let v765: f64 = v764 * v22;
        let v766: f64 = v763 - v765;
        let v767: f64 = v655 * v22;
        let v768: f64 = v656 - v767;
        let v769: f64 = v768 * v8;
        let v770: f64 = v766 + v769;
        let v771: f64 = v655 * v4;
        let v772: f64 = v746 - v771;
        let v773: f64 = v772 * v49;
        let v774: f64 = v773 + v659;
        let v775: f64 = v774 * v6;
        let v776: f64 = v770 + v775;
        let v777: f64 = v776 - v665;
        let v778: f64 = v726 * v727;
        let v779: f64 = v777 - v778;
        let v780: f64 = v733 * v734;
        let v781: f64 = v779 - v780;
        let v782: f64 = v756 * v757;
        let v783: f64 = v781 - v782;
        (
            v588,
            v590,
            v592,
            v593,
            v597,
            v616,
            v636,
            v644,
            v651,
            v653,
            v655,
            v657,
            v660,
            v661,
            v670,
            v671,
            v689,
            v691,
            v696,
            v698,
            v727,
            v734,
            v757,
            v759,
            v761,
            v765,
            v767,
            v783,
        )
    };
    let (v945, v948, v953, v960, v967, v976) = {
        let v784: f64 = v759 / v783;
        let v785: f64 = tau[1];
        let v786: f64 = v429 * v16;
        let v787: f64 = v431 * v23;
        let v788: f64 = v786 - v787;
        let v789: f64 = v24 * v443;
        let v790: f64 = v17 * v465;
        let v791: f64 = v789 - v790;
        let v792: f64 = v788 + v791;
        let v793: f64 = v471 * v122;
        let v794: f64 = v447 * v118;
        let v795: f64 = v793 - v794;
        let v796: f64 = v792 + v795;
        let v797: f64 = v796 - v689;
        let v798: f64 = v22 * v418;
        let v799: f64 = v4 * v361;
        let v800: f64 = v798 + v799;
        let v801: f64 = v476 * v122;
        let v802: f64 = v14 * v487;
        let v803: f64 = v447 * v24;
        let v804: f64 = v471 * v17;
        let v805: f64 = v803 - v804;
        let v806: f64 = v24 * v805;
        let v807: f64 = v802 - v806;
        let v808: f64 = v449 * v16;
        let v809: f64 = v807 - v808;
        let v810: f64 = v801 + v809;
        let v811: f64 = v800 + v810;
        let v812: f64 = v95 * v811;
        let v813: f64 = v797 + v812;
        let v814: f64 = v785 - v813;
        let v815: f64 = v814 - v691;
        let v816: f64 = v727 * v555;
        let v817: f64 = v815 - v816;
        let v818: f64 = v734 * v597;
        let v819: f64 = v817 - v818;
        let v820: f64 = v757 * v696;
        let v821: f64 = v819 - v820;
        let v822: f64 = v784 * v821;
        let v823: f64 = v698 - v822;
        let v824: f64 = 1.553523243625_f64;
        let v825: f64 = v824 - v561;
        let v826: f64 = 0.000864288_f64;
        let v827: f64 = v826 * v34;
        let v828: f64 = v660 * v6;
        let v829: f64 = v827 - v828;
        let v830: f64 = v829 * v49;
        let v831: f64 = v825 + v830;
        let v832: f64 = 0.022546398_f64;
        let v833: f64 = v660 * v8;
        let v834: f64 = v832 + v833;
        let v835: f64 = -0.002487168_f64;
        let v836: f64 = 0.00040432_f64;
        let v837: f64 = v836 * v8;
        let v838: f64 = v835 - v837;
        let v839: f64 = v838 * v49;
        let v840: f64 = v839 * v6;
        let v841: f64 = v834 + v840;
        let v842: f64 = v841 * v22;
        let v843: f64 = 0.3239198455_f64;
        let v844: f64 = v843 + v657;
        let v845: f64 = -0.00030216_f64;
        let v846: f64 = v845 + v561;
        let v847: f64 = v846 * v6;
        let v848: f64 = v661 + v847;
        let v849: f64 = v848 * v6;
        let v850: f64 = v844 + v849;
        let v851: f64 = v850 * v4;
        let v852: f64 = v842 + v851;
        let v853: f64 = v852 * v4;
        let v854: f64 = v831 + v853;
        let v855: f64 = 0.008347998_f64;
        let v856: f64 = v855 + v833;
        let v857: f64 = v761 * v22;
        let v858: f64 = v856 - v857;
        let v859: f64 = v838 + v767;
        let v860: f64 = v859 * v49;
        let v861: f64 = v860 * v6;
        let v862: f64 = v858 + v861;
        let v863: f64 = v862 * v2;
        let v864: f64 = 1.9257810475_f64;
        let v865: f64 = v864 - v765;
        let v866: f64 = v616 * v6;
        let v867: f64 = v661 - v866;
        let v868: f64 = v867 * v6;
        let v869: f64 = v865 + v868;
        let v870: f64 = v655 - v767;
        let v871: f64 = v559 * v6;
        let v872: f64 = v871 * v6;
        let v873: f64 = v559 + v872;
        let v874: f64 = v873 * v8;
        let v875: f64 = v870 + v874;
        let v876: f64 = v875 * v8;
        let v877: f64 = v869 + v876;
        let v878: f64 = v877 * v12;
        let v879: f64 = v863 + v878;
        let v880: f64 = v655 * v49;
        let v881: f64 = v880 * v6;
        let v882: f64 = v761 - v881;
        let v883: f64 = -0.045092796_f64;
        let v884: f64 = 0.000233856_f64;
        let v885: f64 = v884 * v8;
        let v886: f64 = v883 - v885;
        let v887: f64 = 0.004974336_f64;
        let v888: f64 = 0.00080864_f64;
        let v889: f64 = v888 * v8;
        let v890: f64 = v887 + v889;
        let v891: f64 = v890 * v49;
        let v892: f64 = v891 * v6;
        let v893: f64 = v886 + v892;
        let v894: f64 = v893 * v22;
        let v895: f64 = v882 + v894;
        let v896: f64 = -0.647839691_f64;
        let v897: f64 = -0.004974336_f64;
        let v898: f64 = v897 - v837;
        let v899: f64 = v898 * v8;
        let v900: f64 = v896 + v899;
        let v901: f64 = 0.00060432_f64;
        let v902: f64 = v837 * v8;
        let v903: f64 = v901 - v902;
        let v904: f64 = v903 * v6;
        let v905: f64 = v884 * v49;
        let v906: f64 = v904 - v905;
        let v907: f64 = v906 * v6;
        let v908: f64 = v900 + v907;
        let v909: f64 = v908 * v4;
        let v910: f64 = v895 + v909;
        let v911: f64 = v910 * v12;
        let v912: f64 = -0.769752588_f64;
        let v913: f64 = v655 * v8;
        let v914: f64 = v912 - v913;
        let v915: f64 = v893 * v4;
        let v916: f64 = v914 + v915;
        let v917: f64 = 0.647839691_f64;
        let v918: f64 = v887 + v837;
        let v919: f64 = v918 * v8;
        let v920: f64 = v917 + v919;
        let v921: f64 = -0.00060432_f64;
        let v922: f64 = v921 + v902;
        let v923: f64 = v922 * v6;
        let v924: f64 = v905 + v923;
        let v925: f64 = v924 * v6;
        let v926: f64 = v920 + v925;
        let v927: f64 = v926 * v22;
        let v928: f64 = v916 + v927;
        let v929: f64 = v928 * v2;
        let v930: f64 = v911 + v929;
        let v931: f64 = v930 * v4;
        let v932: f64 = v879 + v931;
        let v933: f64 = v932 * v12;
        let v934: f64 = v854 + v933;
        let v935: f64 = v510 * v511;
        let v936: f64 = v934 - v935;
        let v937: f64 = v552 * v553;
        let v938: f64 = v936 - v937;
        let v939: f64 = v590 * v593;
        let v940: f64 = v938 - v939;
        let v941: f64 = v653 * v671;
        let v942: f64 = v940 - v941;
        let v943: f64 = v759 * v784;
        let v944: f64 = v942 - v943;
        let v945: f64 = v823 / v944;
        let v946: f64 = v821 / v783;
        let v947: f64 = v784 * v945;
        let v948: f64 = v946 - v947;
        let v949: f64 = v696 / v670;
        let v950: f64 = v671 * v945;
        let v951: f64 = v949 - v950;
        let v952: f64 = v757 * v948;
        let v953: f64 = v951 - v952;
        let v954: f64 = v597 / v592;
        let v955: f64 = v593 * v945;
        let v956: f64 = v954 - v955;
        let v957: f64 = v734 * v948;
        let v958: f64 = v956 - v957;
        let v959: f64 = v651 * v953;
        let v960: f64 = v958 - v959;
        let v961: f64 = v516 * v555;
        let v962: f64 = v553 * v945;
        let v963: f64 = v961 - v962;
        let v964: f64 = v727 * v948;
        let v965: f64 = v963 - v964;
        let v966: f64 = v644 * v953;
        let v967: f64 = v965 - v966;
        let v968: f64 = v498 * v513;
        let v969: f64 = v511 * v945;
        let v970: f64 = v968 - v969;
        let v971: f64 = v636 * v948;
        let v972: f64 = v970 - v971;
        let v973: f64 = v636 * v953;
        let v974: f64 = v972 - v973;
        let v975: f64 = v588 * v960;
        let v976: f64 = v974 - v975;
        (v945, v948, v953, v960, v967, v976)
    };
    [v945, v948, v953, v960, v967, v976]
}
/// Dynamic regressor: `inverse_dynamics(q, qd, qdd) = Y(q, qd, qdd) * standard_parameters()`.
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 6]`: joint velocities qd (rad/s or m/s)
/// - `qdd: &[f64; 6]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// # Output
///
/// `regressor: [[f64; 60]; 6]` (6 x 60, row-major): Y(q, qd, qdd), columns in the order of `standard_parameters`
///
/// Operation count: 1221 floating-point operations, 10 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn regressor(q: &[f64; 6], qd: &[f64; 6], qdd: &[f64; 6]) -> [[f64; 60]; 6] {
    let (
        v0,
        v4,
        v5,
        v6,
        v7,
        v13,
        v18,
        v24,
        v26,
        v31,
        v34,
        v42,
        v44,
        v47,
        v48,
        v52,
        v54,
        v58,
        v66,
        v74,
        v77,
        v82,
        v83,
        v84,
        v86,
        v91,
        v95,
        v99,
        v105,
        v107,
        v113,
        v116,
        v118,
        v129,
        v130,
        v135,
        v138,
        v139,
        v148,
        v151,
        v152,
        v154,
        v165,
        v169,
        v177,
        v179,
    ) = {
        let v0: f64 = qdd[0];
        let v1: f64 = q[1];
        let v2: f64 = ::libm::sin(v1);
        let v3: f64 = qd[0];
        let v4: f64 = v2 * v3;
        let v5: f64 = 0.4318_f64;
        let v6: f64 = qd[1];
        let v7: f64 = v5 * v6;
        let v8: f64 = v4 * v7;
        let v9: f64 = ::libm::cos(v1);
        let v10: f64 = v9 * v0;
        let v11: f64 = v3 * v6;
        let v12: f64 = v2 * v11;
        let v13: f64 = v10 - v12;
        let v14: f64 = v5 * v13;
        let v15: f64 = v8 - v14;
        let v16: f64 = v5 * v9;
        let v17: f64 = v15 * v16;
        let v18: f64 = -v17;
        let v19: f64 = v13 * v16;
        let v20: f64 = v4 * v16;
        let v21: f64 = v6 * v20;
        let v22: f64 = v19 - v21;
        let v23: f64 = v15 * v9;
        let v24: f64 = v22 - v23;
        let v25: f64 = v15 * v2;
        let v26: f64 = v9 * v3;
        let v27: f64 = v26 * v16;
        let v28: f64 = v6 * v27;
        let v29: f64 = v9 * v11;
        let v30: f64 = v2 * v0;
        let v31: f64 = v29 + v30;
        let v32: f64 = v31 * v16;
        let v33: f64 = v28 + v32;
        let v34: f64 = v25 - v33;
        let v35: f64 = v26 * v27;
        let v36: f64 = v4 * v20;
        let v37: f64 = v35 + v36;
        let v38: f64 = 9.81_f64;
        let v39: f64 = v38 * v2;
        let v40: f64 = v5 * v26;
        let v41: f64 = v26 * v40;
        let v42: f64 = v6 * v7;
        let v43: f64 = v41 + v42;
        let v44: f64 = v39 - v43;
        let v45: f64 = v44 * v9;
        let v46: f64 = v37 + v45;
        let v47: f64 = qdd[1];
        let v48: f64 = v5 * v47;
        let v49: f64 = v4 * v40;
        let v50: f64 = v48 + v49;
        let v51: f64 = v38 * v9;
        let v52: f64 = v50 + v51;
        let v53: f64 = v52 * v2;
        let v54: f64 = v46 - v53;
        let v55: f64 = v6 * v9;
        let v56: f64 = v4 * v55;
        let v57: f64 = v31 * v2;
        let v58: f64 = v56 + v57;
        let v59: f64 = v26 * v55;
        let v60: f64 = v31 * v9;
        let v61: f64 = v59 + v60;
        let v62: f64 = v6 * v2;
        let v63: f64 = v4 * v62;
        let v64: f64 = v61 - v63;
        let v65: f64 = v13 * v2;
        let v66: f64 = v64 + v65;
        let v67: f64 = v6 * v55;
        let v68: f64 = v26 * v2;
        let v69: f64 = v4 * v9;
        let v70: f64 = v68 - v69;
        let v71: f64 = v4 * v70;
        let v72: f64 = v67 + v71;
        let v73: f64 = v47 * v2;
        let v74: f64 = v72 + v73;
        let v75: f64 = v13 * v9;
        let v76: f64 = v26 * v62;
        let v77: f64 = v75 - v76;
        let v78: f64 = v47 * v9;
        let v79: f64 = v6 * v62;
        let v80: f64 = v78 - v79;
        let v81: f64 = v26 * v70;
        let v82: f64 = v80 + v81;
        let v83: f64 = v6 * v70;
        let v84: f64 = 0.0203_f64;
        let v85: f64 = q[2];
        let v86: f64 = ::libm::cos(v85);
        let v87: f64 = qd[2];
        let v88: f64 = v4 * v87;
        let v89: f64 = v13 - v88;
        let v90: f64 = v86 * v89;
        let v91: f64 = ::libm::sin(v85);
        let v92: f64 = v26 * v87;
        let v93: f64 = v31 + v92;
        let v94: f64 = v91 * v93;
        let v95: f64 = v90 - v94;
        let v96: f64 = v84 * v95;
        let v97: f64 = v86 * v26;
        let v98: f64 = v91 * v4;
        let v99: f64 = v97 - v98;
        let v100: f64 = -0.15005_f64;
        let v101: f64 = v100 * v99;
        let v102: f64 = v99 * v101;
        let v103: f64 = v86 * v4;
        let v104: f64 = v91 * v26;
        let v105: f64 = v103 + v104;
        let v106: f64 = v100 * v105;
        let v107: f64 = v6 + v87;
        let v108: f64 = v84 * v107;
        let v109: f64 = v106 + v108;
        let v110: f64 = v105 * v109;
        let v111: f64 = v102 + v110;
        let v112: f64 = v96 - v111;
        let v113: f64 = v112 - v15;
        let v114: f64 = v86 * v9;
        let v115: f64 = v91 * v2;
        let v116: f64 = v114 - v115;
        let v117: f64 = v84 * v116;
        let v118: f64 = v16 + v117;
        let v119: f64 = v113 * v118;
        let v120: f64 = v86 * v44;
        let v121: f64 = v91 * v52;
        let v122: f64 = v120 + v121;
        let v123: f64 = v100 * v95;
        let v124: f64 = v107 * v109;
        let v125: f64 = v84 * v99;
        let v126: f64 = v99 * v125;
        let v127: f64 = v124 + v126;
        let v128: f64 = v123 + v127;
        let v129: f64 = v122 - v128;
        let v130: f64 = v100 * v116;
        let v131: f64 = v129 * v130;
        let v132: f64 = v119 - v131;
        let v133: f64 = v86 * v93;
        let v134: f64 = v91 * v89;
        let v135: f64 = v133 + v134;
        let v136: f64 = v100 * v135;
        let v137: f64 = qdd[2];
        let v138: f64 = v47 + v137;
        let v139: f64 = v84 * v138;
        let v140: f64 = v136 + v139;
        let v141: f64 = v105 * v125;
        let v142: f64 = v107 * v101;
        let v143: f64 = v141 - v142;
        let v144: f64 = v140 + v143;
        let v145: f64 = v86 * v52;
        let v146: f64 = v91 * v44;
        let v147: f64 = v145 - v146;
        let v148: f64 = v144 + v147;
        let v149: f64 = v91 * v9;
        let v150: f64 = v86 * v2;
        let v151: f64 = v149 + v150;
        let v152: f64 = v100 * v151;
        let v153: f64 = v148 * v152;
        let v154: f64 = v132 + v153;
        let v155: f64 = v107 * v130;
        let v156: f64 = v105 * v118;
        let v157: f64 = v155 - v156;
        let v158: f64 = v107 * v157;
        let v159: f64 = v95 * v118;
        let v160: f64 = v158 + v159;
        let v161: f64 = v113 * v116;
        let v162: f64 = v160 + v161;
        let v163: f64 = v99 * v130;
        let v164: f64 = v105 * v152;
        let v165: f64 = v163 + v164;
        let v166: f64 = v99 * v165;
        let v167: f64 = v162 + v166;
        let v168: f64 = v138 * v152;
        let v169: f64 = v167 + v168;
        let v170: f64 = v95 * v130;
        let v171: f64 = v105 * v157;
        let v172: f64 = v170 + v171;
        let v173: f64 = v129 * v116;
        let v174: f64 = v172 - v173;
        let v175: f64 = v99 * v118;
        let v176: f64 = v107 * v152;
        let v177: f64 = v175 + v176;
        let v178: f64 = v99 * v177;
        let v179: f64 = v174 - v178;
        (
            v0,
            v4,
            v5,
            v6,
            v7,
            v13,
            v18,
            v24,
            v26,
            v31,
            v34,
            v42,
            v44,
            v47,
            v48,
            v52,
            v54,
            v58,
            v66,
            v74,
            v77,
            v82,
            v83,
            v84,
            v86,
            v91,
            v95,
            v99,
            v105,
            v107,
            v113,
            v116,
            v118,
            v129,
            v130,
            v135,
            v138,
            v139,
            v148,
            v151,
            v152,
            v154,
            v165,
            v169,
            v177,
            v179,
        )
    };
    let (
        v183,
        v192,
        v196,
        v204,
        v212,
        v214,
        v219,
        v222,
        v224,
        v226,
        v228,
        v233,
        v237,
        v240,
        v248,
        v254,
        v258,
        v260,
        v265,
        v272,
        v273,
        v278,
        v279,
        v280,
        v297,
        v299,
        v313,
        v324,
        v330,
        v340,
        v346,
        v350,
        v353,
        v358,
        v359,
    ) = {
        let v180: f64 = v135 * v152;
        let v181: f64 = v179 + v180;
        let v182: f64 = v148 * v151;
        let v183: f64 = v181 + v182;
        let v184: f64 = v138 * v130;
        let v185: f64 = v135 * v118;
        let v186: f64 = v184 - v185;
        let v187: f64 = v107 * v177;
        let v188: f64 = v186 - v187;
        let v189: f64 = v105 * v165;
        let v190: f64 = v188 - v189;
        let v191: f64 = v113 * v151;
        let v192: f64 = v190 - v191;
        let v193: f64 = v107 * v116;
        let v194: f64 = v105 * v193;
        let v195: f64 = v135 * v151;
        let v196: f64 = v194 + v195;
        let v197: f64 = v105 * v116;
        let v198: f64 = v99 * v151;
        let v199: f64 = v197 - v198;
        let v200: f64 = v105 * v199;
        let v201: f64 = v107 * v193;
        let v202: f64 = v200 - v201;
        let v203: f64 = v138 * v151;
        let v204: f64 = v202 - v203;
        let v205: f64 = v99 * v193;
        let v206: f64 = v135 * v116;
        let v207: f64 = v205 + v206;
        let v208: f64 = v107 * v151;
        let v209: f64 = v105 * v208;
        let v210: f64 = v207 - v209;
        let v211: f64 = v95 * v151;
        let v212: f64 = v210 + v211;
        let v213: f64 = v107 * v199;
        let v214: f64 = -v213;
        let v215: f64 = v99 * v199;
        let v216: f64 = v138 * v116;
        let v217: f64 = v215 - v216;
        let v218: f64 = v107 * v208;
        let v219: f64 = v217 + v218;
        let v220: f64 = v95 * v116;
        let v221: f64 = v99 * v208;
        let v222: f64 = v220 - v221;
        let v223: f64 = q[3];
        let v224: f64 = ::libm::sin(v223);
        let v225: f64 = v224 * v105;
        let v226: f64 = ::libm::cos(v223);
        let v227: f64 = v226 * v107;
        let v228: f64 = v225 + v227;
        let v229: f64 = v5 * v228;
        let v230: f64 = v228 * v229;
        let v231: f64 = v226 * v105;
        let v232: f64 = v224 * v107;
        let v233: f64 = v231 - v232;
        let v234: f64 = v5 * v233;
        let v235: f64 = v233 * v234;
        let v236: f64 = v230 + v235;
        let v237: f64 = v148 - v236;
        let v238: f64 = v237 * v152;
        let v239: f64 = qd[3];
        let v240: f64 = v99 + v239;
        let v241: f64 = v240 * v234;
        let v242: f64 = v107 * v239;
        let v243: f64 = v135 - v242;
        let v244: f64 = v224 * v243;
        let v245: f64 = v105 * v239;
        let v246: f64 = v138 + v245;
        let v247: f64 = v226 * v246;
        let v248: f64 = v244 + v247;
        let v249: f64 = v5 * v248;
        let v250: f64 = v241 - v249;
        let v251: f64 = v226 * v129;
        let v252: f64 = v224 * v113;
        let v253: f64 = v251 + v252;
        let v254: f64 = v250 + v253;
        let v255: f64 = v224 * v118;
        let v256: f64 = v226 * v130;
        let v257: f64 = v255 - v256;
        let v258: f64 = v224 * v151;
        let v259: f64 = v5 * v258;
        let v260: f64 = v257 - v259;
        let v261: f64 = v254 * v260;
        let v262: f64 = v238 + v261;
        let v263: f64 = v226 * v243;
        let v264: f64 = v224 * v246;
        let v265: f64 = v263 - v264;
        let v266: f64 = v5 * v265;
        let v267: f64 = v240 * v229;
        let v268: f64 = v266 + v267;
        let v269: f64 = v224 * v129;
        let v270: f64 = v226 * v113;
        let v271: f64 = v269 - v270;
        let v272: f64 = v268 + v271;
        let v273: f64 = v226 * v151;
        let v274: f64 = v5 * v273;
        let v275: f64 = v224 * v130;
        let v276: f64 = v226 * v118;
        let v277: f64 = v275 + v276;
        let v278: f64 = v274 - v277;
        let v279: f64 = v272 * v278;
        let v280: f64 = v262 + v279;
        let v281: f64 = v248 * v152;
        let v282: f64 = v272 * v116;
        let v283: f64 = v281 - v282;
        let v284: f64 = v240 * v260;
        let v285: f64 = v233 * v152;
        let v286: f64 = v284 - v285;
        let v287: f64 = v240 * v286;
        let v288: f64 = v283 - v287;
        let v289: f64 = v237 * v258;
        let v290: f64 = v288 + v289;
        let v291: f64 = v233 * v278;
        let v292: f64 = v228 * v260;
        let v293: f64 = v291 - v292;
        let v294: f64 = v228 * v293;
        let v295: f64 = v290 + v294;
        let v296: f64 = qdd[3];
        let v297: f64 = v95 + v296;
        let v298: f64 = v297 * v278;
        let v299: f64 = v295 - v298;
        let v300: f64 = v233 * v286;
        let v301: f64 = v248 * v260;
        let v302: f64 = v300 - v301;
        let v303: f64 = v254 * v258;
        let v304: f64 = v302 - v303;
        let v305: f64 = v228 * v152;
        let v306: f64 = v240 * v278;
        let v307: f64 = v305 - v306;
        let v308: f64 = v228 * v307;
        let v309: f64 = v304 - v308;
        let v310: f64 = v265 * v278;
        let v311: f64 = v309 + v310;
        let v312: f64 = v272 * v273;
        let v313: f64 = v311 + v312;
        let v314: f64 = v254 * v116;
        let v315: f64 = v265 * v152;
        let v316: f64 = v314 - v315;
        let v317: f64 = v297 * v260;
        let v318: f64 = v316 + v317;
        let v319: f64 = v240 * v307;
        let v320: f64 = v318 + v319;
        let v321: f64 = v233 * v293;
        let v322: f64 = v320 - v321;
        let v323: f64 = v237 * v273;
        let v324: f64 = v322 - v323;
        let v325: f64 = v228 * v116;
        let v326: f64 = v240 * v258;
        let v327: f64 = v325 - v326;
        let v328: f64 = v233 * v327;
        let v329: f64 = v265 * v273;
        let v330: f64 = v328 + v329;
        let v331: f64 = v265 * v116;
        let v332: f64 = v240 * v327;
        let v333: f64 = v331 + v332;
        let v334: f64 = v233 * v258;
        let v335: f64 = v228 * v273;
        let v336: f64 = v334 - v335;
        let v337: f64 = v233 * v336;
        let v338: f64 = v333 + v337;
        let v339: f64 = v297 * v273;
        let v340: f64 = v338 + v339;
        let v341: f64 = v228 * v327;
        let v342: f64 = v265 * v258;
        let v343: f64 = v341 + v342;
        let v344: f64 = v240 * v273;
        let v345: f64 = v233 * v116;
        let v346: f64 = v344 - v345;
        let v347: f64 = v233 * v346;
        let v348: f64 = v343 + v347;
        let v349: f64 = v248 * v273;
        let v350: f64 = v348 + v349;
        let v351: f64 = v297 * v116;
        let v352: f64 = v240 * v336;
        let v353: f64 = v351 + v352;
        let v354: f64 = v248 * v116;
        let v355: f64 = v297 * v258;
        let v356: f64 = v354 + v355;
        let v357: f64 = v228 * v336;
        let v358: f64 = v356 + v357;
        let v359: f64 = v240 * v346;
        (
            v183,
            v192,
            v196,
            v204,
            v212,
            v214,
            v219,
            v222,
            v224,
            v226,
            v228,
            v233,
            v237,
            v240,
            v248,
            v254,
            v258,
            v260,
            v265,
            v272,
            v273,
            v278,
            v279,
            v280,
            v297,
            v299,
            v313,
            v324,
            v330,
            v340,
            v346,
            v350,
            v353,
            v358,
            v359,
        )
    };
    let (
        v360,
        v363,
        v365,
        v367,
        v369,
        v372,
        v376,
        v382,
        v384,
        v388,
        v391,
        v400,
        v412,
        v417,
        v419,
        v422,
        v437,
        v439,
        v450,
        v456,
        v466,
        v476,
        v479,
        v486,
        v489,
        v491,
        v493,
        v495,
        v498,
        v503,
        v506,
        v508,
        v511,
        v514,
        v516,
        v519,
        v522,
        v525,
        v528,
        v533,
        v536,
        v538,
        v539,
    ) = {
        let v360: f64 = v358 + v359;
        let v361: f64 = v248 * v258;
        let v362: f64 = v228 * v346;
        let v363: f64 = v361 + v362;
        let v364: f64 = q[4];
        let v365: f64 = ::libm::cos(v364);
        let v366: f64 = v365 * v237;
        let v367: f64 = ::libm::sin(v364);
        let v368: f64 = v367 * v254;
        let v369: f64 = v366 - v368;
        let v370: f64 = v365 * v152;
        let v371: f64 = v367 * v260;
        let v372: f64 = v370 - v371;
        let v373: f64 = v369 * v372;
        let v374: f64 = v365 * v254;
        let v375: f64 = v367 * v237;
        let v376: f64 = v374 + v375;
        let v377: f64 = v367 * v152;
        let v378: f64 = v365 * v260;
        let v379: f64 = v377 + v378;
        let v380: f64 = v376 * v379;
        let v381: f64 = v373 + v380;
        let v382: f64 = v381 + v279;
        let v383: f64 = qdd[4];
        let v384: f64 = v248 + v383;
        let v385: f64 = v384 * v372;
        let v386: f64 = v365 * v240;
        let v387: f64 = v367 * v233;
        let v388: f64 = v386 - v387;
        let v389: f64 = v365 * v233;
        let v390: f64 = v367 * v240;
        let v391: f64 = v389 + v390;
        let v392: f64 = v391 * v372;
        let v393: f64 = v388 * v379;
        let v394: f64 = v392 - v393;
        let v395: f64 = v388 * v394;
        let v396: f64 = v385 + v395;
        let v397: f64 = v369 * v258;
        let v398: f64 = v396 + v397;
        let v399: f64 = qd[4];
        let v400: f64 = v228 + v399;
        let v401: f64 = v391 * v278;
        let v402: f64 = v400 * v379;
        let v403: f64 = v401 - v402;
        let v404: f64 = v400 * v403;
        let v405: f64 = v398 + v404;
        let v406: f64 = v233 * v399;
        let v407: f64 = v297 - v406;
        let v408: f64 = v365 * v407;
        let v409: f64 = v240 * v399;
        let v410: f64 = v265 + v409;
        let v411: f64 = v367 * v410;
        let v412: f64 = v408 - v411;
        let v413: f64 = v412 * v278;
        let v414: f64 = v405 - v413;
        let v415: f64 = v365 * v116;
        let v416: f64 = v367 * v273;
        let v417: f64 = v415 - v416;
        let v418: f64 = v272 * v417;
        let v419: f64 = v414 - v418;
        let v420: f64 = v365 * v410;
        let v421: f64 = v367 * v407;
        let v422: f64 = v420 + v421;
        let v423: f64 = v422 * v372;
        let v424: f64 = v412 * v379;
        let v425: f64 = v423 - v424;
        let v426: f64 = v391 * v403;
        let v427: f64 = v425 + v426;
        let v428: f64 = v388 * v278;
        let v429: f64 = v400 * v372;
        let v430: f64 = v428 - v429;
        let v431: f64 = v388 * v430;
        let v432: f64 = v427 + v431;
        let v433: f64 = v376 * v417;
        let v434: f64 = v432 - v433;
        let v435: f64 = v367 * v116;
        let v436: f64 = v365 * v273;
        let v437: f64 = v435 + v436;
        let v438: f64 = v369 * v437;
        let v439: f64 = v434 + v438;
        let v440: f64 = v400 * v430;
        let v441: f64 = v391 * v394;
        let v442: f64 = v384 * v379;
        let v443: f64 = v441 + v442;
        let v444: f64 = v376 * v258;
        let v445: f64 = v443 + v444;
        let v446: f64 = v440 - v445;
        let v447: f64 = v422 * v278;
        let v448: f64 = v446 + v447;
        let v449: f64 = v272 * v437;
        let v450: f64 = v448 + v449;
        let v451: f64 = v400 * v417;
        let v452: f64 = v388 * v258;
        let v453: f64 = v451 - v452;
        let v454: f64 = v391 * v453;
        let v455: f64 = v422 * v437;
        let v456: f64 = v454 + v455;
        let v457: f64 = v391 * v417;
        let v458: f64 = v388 * v437;
        let v459: f64 = v457 - v458;
        let v460: f64 = v391 * v459;
        let v461: f64 = v422 * v258;
        let v462: f64 = v400 * v453;
        let v463: f64 = v461 + v462;
        let v464: f64 = v460 - v463;
        let v465: f64 = v384 * v437;
        let v466: f64 = v464 - v465;
        let v467: f64 = v388 * v453;
        let v468: f64 = v422 * v417;
        let v469: f64 = v467 + v468;
        let v470: f64 = v391 * v258;
        let v471: f64 = v400 * v437;
        let v472: f64 = v470 - v471;
        let v473: f64 = v391 * v472;
        let v474: f64 = v469 + v473;
        let v475: f64 = v412 * v437;
        let v476: f64 = v474 + v475;
        let v477: f64 = v384 * v258;
        let v478: f64 = v400 * v459;
        let v479: f64 = v477 - v478;
        let v480: f64 = v388 * v459;
        let v481: f64 = v412 * v258;
        let v482: f64 = v384 * v417;
        let v483: f64 = v481 + v482;
        let v484: f64 = v480 - v483;
        let v485: f64 = v400 * v472;
        let v486: f64 = v484 - v485;
        let v487: f64 = v412 * v417;
        let v488: f64 = v388 * v472;
        let v489: f64 = v487 + v488;
        let v490: f64 = q[5];
        let v491: f64 = ::libm::sin(v490);
        let v492: f64 = v491 * v376;
        let v493: f64 = ::libm::cos(v490);
        let v494: f64 = v493 * v272;
        let v495: f64 = v492 + v494;
        let v496: f64 = v491 * v379;
        let v497: f64 = v493 * v278;
        let v498: f64 = v496 + v497;
        let v499: f64 = v495 * v498;
        let v500: f64 = v373 + v499;
        let v501: f64 = v493 * v376;
        let v502: f64 = v491 * v272;
        let v503: f64 = v501 - v502;
        let v504: f64 = v493 * v379;
        let v505: f64 = v491 * v278;
        let v506: f64 = v504 - v505;
        let v507: f64 = v503 * v506;
        let v508: f64 = v500 + v507;
        let v509: f64 = qd[5];
        let v510: f64 = v400 * v509;
        let v511: f64 = v422 - v510;
        let v512: f64 = v491 * v511;
        let v513: f64 = v391 * v509;
        let v514: f64 = v384 + v513;
        let v515: f64 = v493 * v514;
        let v516: f64 = v512 + v515;
        let v517: f64 = v516 * v372;
        let v518: f64 = qdd[5];
        let v519: f64 = v412 + v518;
        let v520: f64 = v519 * v498;
        let v521: f64 = v517 - v520;
        let v522: f64 = v388 + v509;
        let v523: f64 = v493 * v391;
        let v524: f64 = v491 * v400;
        let v525: f64 = v523 - v524;
        let v526: f64 = v525 * v372;
        let v527: f64 = v522 * v506;
        let v528: f64 = v526 - v527;
        let v529: f64 = v522 * v528;
        let v530: f64 = v521 + v529;
        let v531: f64 = v491 * v391;
        let v532: f64 = v493 * v400;
        let v533: f64 = v531 + v532;
        let v534: f64 = v525 * v498;
        let v535: f64 = v533 * v506;
        let v536: f64 = v534 - v535;
        let v537: f64 = v533 * v536;
        let v538: f64 = v530 + v537;
        let v539: f64 = v495 * v417;
        (
            v360,
            v363,
            v365,
            v367,
            v369,
            v372,
            v376,
            v382,
            v384,
            v388,
            v391,
            v400,
            v412,
            v417,
            v419,
            v422,
            v437,
            v439,
            v450,
            v456,
            v466,
            v476,
            v479,
            v486,
            v489,
            v491,
            v493,
            v495,
            v498,
            v503,
            v506,
            v508,
            v511,
            v514,
            v516,
            v519,
            v522,
            v525,
            v528,
            v533,
            v536,
            v538,
            v539,
        )
    };
    let (
        v545,
        v548,
        v565,
        v576,
        v582,
        v592,
        v602,
        v605,
        v612,
        v615,
        v616,
        v621,
        v624,
        v627,
        v629,
        v632,
        v634,
        v635,
        v637,
        v641,
        v643,
        v653,
        v661,
        v668,
        v670,
        v672,
        v675,
        v678,
        v679,
        v682,
        v683,
        v687,
        v688,
        v689,
        v690,
        v697,
        v701,
        v705,
        v709,
        v713,
        v718,
        v719,
    ) = {
        let v540: f64 = v538 - v539;
        let v541: f64 = v493 * v258;
        let v542: f64 = v491 * v437;
        let v543: f64 = v541 + v542;
        let v544: f64 = v369 * v543;
        let v545: f64 = v540 + v544;
        let v546: f64 = v493 * v511;
        let v547: f64 = v491 * v514;
        let v548: f64 = v546 - v547;
        let v549: f64 = v548 * v372;
        let v550: f64 = v522 * v498;
        let v551: f64 = v533 * v372;
        let v552: f64 = v550 - v551;
        let v553: f64 = v522 * v552;
        let v554: f64 = v549 + v553;
        let v555: f64 = v525 * v536;
        let v556: f64 = v554 + v555;
        let v557: f64 = v519 * v506;
        let v558: f64 = v556 - v557;
        let v559: f64 = v503 * v417;
        let v560: f64 = v558 - v559;
        let v561: f64 = v493 * v437;
        let v562: f64 = v491 * v258;
        let v563: f64 = v561 - v562;
        let v564: f64 = v369 * v563;
        let v565: f64 = v560 + v564;
        let v566: f64 = v533 * v552;
        let v567: f64 = v548 * v498;
        let v568: f64 = v566 + v567;
        let v569: f64 = v525 * v528;
        let v570: f64 = v568 - v569;
        let v571: f64 = v516 * v506;
        let v572: f64 = v570 - v571;
        let v573: f64 = v503 * v543;
        let v574: f64 = v572 - v573;
        let v575: f64 = v495 * v563;
        let v576: f64 = v574 + v575;
        let v577: f64 = v533 * v417;
        let v578: f64 = v522 * v543;
        let v579: f64 = v577 - v578;
        let v580: f64 = v525 * v579;
        let v581: f64 = v548 * v563;
        let v582: f64 = v580 + v581;
        let v583: f64 = v525 * v417;
        let v584: f64 = v522 * v563;
        let v585: f64 = v583 - v584;
        let v586: f64 = v525 * v585;
        let v587: f64 = v533 * v579;
        let v588: f64 = v548 * v543;
        let v589: f64 = v587 + v588;
        let v590: f64 = v586 - v589;
        let v591: f64 = v516 * v563;
        let v592: f64 = v590 - v591;
        let v593: f64 = v548 * v417;
        let v594: f64 = v522 * v579;
        let v595: f64 = v593 + v594;
        let v596: f64 = v525 * v543;
        let v597: f64 = v533 * v563;
        let v598: f64 = v596 - v597;
        let v599: f64 = v525 * v598;
        let v600: f64 = v595 + v599;
        let v601: f64 = v519 * v563;
        let v602: f64 = v600 + v601;
        let v603: f64 = v516 * v543;
        let v604: f64 = v533 * v585;
        let v605: f64 = v603 - v604;
        let v606: f64 = v522 * v585;
        let v607: f64 = v516 * v417;
        let v608: f64 = v519 * v543;
        let v609: f64 = v607 + v608;
        let v610: f64 = v606 - v609;
        let v611: f64 = v533 * v598;
        let v612: f64 = v610 - v611;
        let v613: f64 = v519 * v417;
        let v614: f64 = v522 * v598;
        let v615: f64 = v613 + v614;
        let v616: f64 = v5 * v52;
        let v617: f64 = -0.4318_f64;
        let v618: f64 = v617 * v4;
        let v619: f64 = v26 * v618;
        let v620: f64 = v48 - v619;
        let v621: f64 = v620 + v52;
        let v622: f64 = v4 * v618;
        let v623: f64 = v622 - v44;
        let v624: f64 = v623 - v42;
        let v625: f64 = v617 * v31;
        let v626: f64 = v26 * v7;
        let v627: f64 = v625 + v626;
        let v628: f64 = v4 * v26;
        let v629: f64 = -v628;
        let v630: f64 = v4 * v4;
        let v631: f64 = v26 * v26;
        let v632: f64 = v630 - v631;
        let v633: f64 = v6 * v26;
        let v634: f64 = v31 - v633;
        let v635: f64 = v26 * v4;
        let v636: f64 = v6 * v4;
        let v637: f64 = v13 + v636;
        let v638: f64 = v5 * v91;
        let v639: f64 = v129 * v638;
        let v640: f64 = v5 * v86;
        let v641: f64 = v640 + v84;
        let v642: f64 = v148 * v641;
        let v643: f64 = v639 + v642;
        let v644: f64 = v107 * v638;
        let v645: f64 = v107 * v644;
        let v646: f64 = v148 - v645;
        let v647: f64 = v105 * v641;
        let v648: f64 = v99 * v638;
        let v649: f64 = v647 - v648;
        let v650: f64 = v99 * v649;
        let v651: f64 = v646 + v650;
        let v652: f64 = v138 * v641;
        let v653: f64 = v651 + v652;
        let v654: f64 = v135 * v641;
        let v655: f64 = v95 * v638;
        let v656: f64 = v105 * v644;
        let v657: f64 = v655 + v656;
        let v658: f64 = v107 * v641;
        let v659: f64 = v99 * v658;
        let v660: f64 = v657 + v659;
        let v661: f64 = v654 - v660;
        let v662: f64 = v138 * v638;
        let v663: f64 = v129 + v662;
        let v664: f64 = v107 * v658;
        let v665: f64 = v663 + v664;
        let v666: f64 = v105 * v649;
        let v667: f64 = v665 + v666;
        let v668: f64 = -v667;
        let v669: f64 = v105 * v99;
        let v670: f64 = -v669;
        let v671: f64 = v107 * v99;
        let v672: f64 = v671 - v135;
        let v673: f64 = v105 * v105;
        let v674: f64 = v99 * v99;
        let v675: f64 = v673 - v674;
        let v676: f64 = v107 * v105;
        let v677: f64 = v95 + v676;
        let v678: f64 = -v677;
        let v679: f64 = v99 * v105;
        let v680: f64 = v237 * v641;
        let v681: f64 = v226 * v638;
        let v682: f64 = v5 * v226;
        let v683: f64 = v681 - v682;
        let v684: f64 = v254 * v683;
        let v685: f64 = v680 + v684;
        let v686: f64 = v224 * v638;
        let v687: f64 = v5 * v224;
        let v688: f64 = v686 - v687;
        let v689: f64 = v272 * v688;
        let v690: f64 = v685 + v689;
        let v691: f64 = v248 * v641;
        let v692: f64 = v240 * v683;
        let v693: f64 = v233 * v641;
        let v694: f64 = v692 - v693;
        let v695: f64 = v240 * v694;
        let v696: f64 = v691 - v695;
        let v697: f64 = v237 * v226;
        let v698: f64 = v696 + v697;
        let v699: f64 = v233 * v688;
        let v700: f64 = v228 * v683;
        let v701: f64 = v699 - v700;
        let v702: f64 = v228 * v701;
        let v703: f64 = v698 + v702;
        let v704: f64 = v297 * v688;
        let v705: f64 = v703 - v704;
        let v706: f64 = v233 * v694;
        let v707: f64 = v248 * v683;
        let v708: f64 = v706 - v707;
        let v709: f64 = v254 * v226;
        let v710: f64 = v708 - v709;
        let v711: f64 = v228 * v641;
        let v712: f64 = v240 * v688;
        let v713: f64 = v711 - v712;
        let v714: f64 = v228 * v713;
        let v715: f64 = v710 - v714;
        let v716: f64 = v265 * v688;
        let v717: f64 = v715 + v716;
        let v718: f64 = v272 * v224;
        let v719: f64 = v717 - v718;
        (
            v545,
            v548,
            v565,
            v576,
            v582,
            v592,
            v602,
            v605,
            v612,
            v615,
            v616,
            v621,
            v624,
            v627,
            v629,
            v632,
            v634,
            v635,
            v637,
            v641,
            v643,
            v653,
            v661,
            v668,
            v670,
            v672,
            v675,
            v678,
            v679,
            v682,
            v683,
            v687,
            v688,
            v689,
            v690,
            v697,
            v701,
            v705,
            v709,
            v713,
            v718,
            v719,
        )
    };
    let (
        v727,
        v728,
        v733,
        v741,
        v749,
        v750,
        v755,
        v758,
        v768,
        v775,
        v784,
        v785,
        v786,
        v797,
        v800,
        v801,
        v806,
        v811,
        v812,
        v818,
        v828,
        v838,
        v841,
        v848,
        v851,
        v854,
        v859,
        v861,
        v867,
        v875,
        v879,
        v880,
        v881,
        v892,
        v896,
        v897,
        v898,
        v899,
    ) = {
        let v720: f64 = v297 * v683;
        let v721: f64 = v265 * v641;
        let v722: f64 = v720 - v721;
        let v723: f64 = v240 * v713;
        let v724: f64 = v722 + v723;
        let v725: f64 = v233 * v701;
        let v726: f64 = v724 - v725;
        let v727: f64 = v237 * v224;
        let v728: f64 = v726 + v727;
        let v729: f64 = v240 * v226;
        let v730: f64 = v233 * v729;
        let v731: f64 = v265 * v224;
        let v732: f64 = v730 + v731;
        let v733: f64 = -v732;
        let v734: f64 = v233 * v226;
        let v735: f64 = v228 * v224;
        let v736: f64 = v734 + v735;
        let v737: f64 = v233 * v736;
        let v738: f64 = v240 * v729;
        let v739: f64 = v737 - v738;
        let v740: f64 = v297 * v224;
        let v741: f64 = v739 - v740;
        let v742: f64 = v265 * v226;
        let v743: f64 = v228 * v729;
        let v744: f64 = v742 - v743;
        let v745: f64 = v240 * v224;
        let v746: f64 = v233 * v745;
        let v747: f64 = v744 - v746;
        let v748: f64 = v248 * v224;
        let v749: f64 = v747 - v748;
        let v750: f64 = v240 * v736;
        let v751: f64 = v297 * v226;
        let v752: f64 = v228 * v736;
        let v753: f64 = v751 + v752;
        let v754: f64 = v240 * v745;
        let v755: f64 = v753 - v754;
        let v756: f64 = v248 * v226;
        let v757: f64 = v228 * v745;
        let v758: f64 = v756 - v757;
        let v759: f64 = v365 * v641;
        let v760: f64 = v367 * v683;
        let v761: f64 = v759 - v760;
        let v762: f64 = v369 * v761;
        let v763: f64 = v367 * v641;
        let v764: f64 = v365 * v683;
        let v765: f64 = v763 + v764;
        let v766: f64 = v376 * v765;
        let v767: f64 = v762 + v766;
        let v768: f64 = v767 + v689;
        let v769: f64 = v384 * v761;
        let v770: f64 = v391 * v761;
        let v771: f64 = v388 * v765;
        let v772: f64 = v770 - v771;
        let v773: f64 = v388 * v772;
        let v774: f64 = v769 + v773;
        let v775: f64 = v369 * v226;
        let v776: f64 = v774 + v775;
        let v777: f64 = v391 * v688;
        let v778: f64 = v400 * v765;
        let v779: f64 = v777 - v778;
        let v780: f64 = v400 * v779;
        let v781: f64 = v776 + v780;
        let v782: f64 = v412 * v688;
        let v783: f64 = v781 - v782;
        let v784: f64 = v367 * v224;
        let v785: f64 = v272 * v784;
        let v786: f64 = v783 - v785;
        let v787: f64 = v422 * v761;
        let v788: f64 = v412 * v765;
        let v789: f64 = v787 - v788;
        let v790: f64 = v391 * v779;
        let v791: f64 = v789 + v790;
        let v792: f64 = v388 * v688;
        let v793: f64 = v400 * v761;
        let v794: f64 = v792 - v793;
        let v795: f64 = v388 * v794;
        let v796: f64 = v791 + v795;
        let v797: f64 = v376 * v784;
        let v798: f64 = v796 - v797;
        let v799: f64 = v365 * v224;
        let v800: f64 = v369 * v799;
        let v801: f64 = v798 - v800;
        let v802: f64 = v400 * v794;
        let v803: f64 = v391 * v772;
        let v804: f64 = v384 * v765;
        let v805: f64 = v803 + v804;
        let v806: f64 = v376 * v226;
        let v807: f64 = v805 + v806;
        let v808: f64 = v802 - v807;
        let v809: f64 = v422 * v688;
        let v810: f64 = v808 + v809;
        let v811: f64 = v272 * v799;
        let v812: f64 = v810 - v811;
        let v813: f64 = v400 * v784;
        let v814: f64 = v388 * v226;
        let v815: f64 = v813 - v814;
        let v816: f64 = v391 * v815;
        let v817: f64 = v422 * v799;
        let v818: f64 = v816 - v817;
        let v819: f64 = v391 * v784;
        let v820: f64 = v388 * v799;
        let v821: f64 = v819 + v820;
        let v822: f64 = v391 * v821;
        let v823: f64 = v422 * v226;
        let v824: f64 = v400 * v815;
        let v825: f64 = v823 + v824;
        let v826: f64 = v822 - v825;
        let v827: f64 = v384 * v799;
        let v828: f64 = v826 + v827;
        let v829: f64 = v388 * v815;
        let v830: f64 = v422 * v784;
        let v831: f64 = v829 + v830;
        let v832: f64 = v391 * v226;
        let v833: f64 = v400 * v799;
        let v834: f64 = v832 + v833;
        let v835: f64 = v391 * v834;
        let v836: f64 = v831 + v835;
        let v837: f64 = v412 * v799;
        let v838: f64 = v836 - v837;
        let v839: f64 = v384 * v226;
        let v840: f64 = v400 * v821;
        let v841: f64 = v839 - v840;
        let v842: f64 = v388 * v821;
        let v843: f64 = v412 * v226;
        let v844: f64 = v384 * v784;
        let v845: f64 = v843 + v844;
        let v846: f64 = v842 - v845;
        let v847: f64 = v400 * v834;
        let v848: f64 = v846 - v847;
        let v849: f64 = v412 * v784;
        let v850: f64 = v388 * v834;
        let v851: f64 = v849 + v850;
        let v852: f64 = v491 * v765;
        let v853: f64 = v493 * v688;
        let v854: f64 = v852 + v853;
        let v855: f64 = v495 * v854;
        let v856: f64 = v762 + v855;
        let v857: f64 = v493 * v765;
        let v858: f64 = v491 * v688;
        let v859: f64 = v857 - v858;
        let v860: f64 = v503 * v859;
        let v861: f64 = v856 + v860;
        let v862: f64 = v516 * v761;
        let v863: f64 = v519 * v854;
        let v864: f64 = v862 - v863;
        let v865: f64 = v525 * v761;
        let v866: f64 = v522 * v859;
        let v867: f64 = v865 - v866;
        let v868: f64 = v522 * v867;
        let v869: f64 = v864 + v868;
        let v870: f64 = v525 * v854;
        let v871: f64 = v533 * v859;
        let v872: f64 = v870 - v871;
        let v873: f64 = v533 * v872;
        let v874: f64 = v869 + v873;
        let v875: f64 = v495 * v784;
        let v876: f64 = v874 - v875;
        let v877: f64 = v491 * v799;
        let v878: f64 = v493 * v226;
        let v879: f64 = v877 - v878;
        let v880: f64 = v369 * v879;
        let v881: f64 = v876 - v880;
        let v882: f64 = v548 * v761;
        let v883: f64 = v522 * v854;
        let v884: f64 = v533 * v761;
        let v885: f64 = v883 - v884;
        let v886: f64 = v522 * v885;
        let v887: f64 = v882 + v886;
        let v888: f64 = v525 * v872;
        let v889: f64 = v887 + v888;
        let v890: f64 = v519 * v859;
        let v891: f64 = v889 - v890;
        let v892: f64 = v503 * v784;
        let v893: f64 = v891 - v892;
        let v894: f64 = v491 * v226;
        let v895: f64 = v493 * v799;
        let v896: f64 = v894 + v895;
        let v897: f64 = v369 * v896;
        let v898: f64 = v893 - v897;
        let v899: f64 = v533 * v885;
        (
            v727,
            v728,
            v733,
            v741,
            v749,
            v750,
            v755,
            v758,
            v768,
            v775,
            v784,
            v785,
            v786,
            v797,
            v800,
            v801,
            v806,
            v811,
            v812,
            v818,
            v828,
            v838,
            v841,
            v848,
            v851,
            v854,
            v859,
            v861,
            v867,
            v875,
            v879,
            v880,
            v881,
            v892,
            v896,
            v897,
            v898,
            v899,
        )
    };
    let (
        v906,
        v908,
        v909,
        v915,
        v925,
        v935,
        v939,
        v946,
        v949,
        v950,
        v954,
        v959,
        v963,
        v968,
        v982,
        v994,
        v1002,
        v1012,
        v1027,
        v1039,
        v1049,
        v1052,
        v1057,
        v1059,
        v1065,
        v1070,
        v1074,
        v1075,
        v1078,
        v1079,
    ) = {
        let v900: f64 = v548 * v854;
        let v901: f64 = v899 + v900;
        let v902: f64 = v525 * v867;
        let v903: f64 = v901 - v902;
        let v904: f64 = v516 * v859;
        let v905: f64 = v903 - v904;
        let v906: f64 = v503 * v879;
        let v907: f64 = v905 + v906;
        let v908: f64 = v495 * v896;
        let v909: f64 = v907 - v908;
        let v910: f64 = v533 * v784;
        let v911: f64 = v522 * v879;
        let v912: f64 = v910 + v911;
        let v913: f64 = v525 * v912;
        let v914: f64 = v548 * v896;
        let v915: f64 = v913 - v914;
        let v916: f64 = v548 * v879;
        let v917: f64 = v533 * v912;
        let v918: f64 = v916 - v917;
        let v919: f64 = v525 * v784;
        let v920: f64 = v522 * v896;
        let v921: f64 = v919 + v920;
        let v922: f64 = v525 * v921;
        let v923: f64 = v918 + v922;
        let v924: f64 = v516 * v896;
        let v925: f64 = v923 + v924;
        let v926: f64 = v548 * v784;
        let v927: f64 = v522 * v912;
        let v928: f64 = v926 + v927;
        let v929: f64 = v533 * v896;
        let v930: f64 = v525 * v879;
        let v931: f64 = v929 - v930;
        let v932: f64 = v525 * v931;
        let v933: f64 = v928 + v932;
        let v934: f64 = v519 * v896;
        let v935: f64 = v933 - v934;
        let v936: f64 = v516 * v879;
        let v937: f64 = v533 * v921;
        let v938: f64 = v936 + v937;
        let v939: f64 = -v938;
        let v940: f64 = v519 * v879;
        let v941: f64 = v516 * v784;
        let v942: f64 = v940 - v941;
        let v943: f64 = v522 * v921;
        let v944: f64 = v942 + v943;
        let v945: f64 = v533 * v931;
        let v946: f64 = v944 - v945;
        let v947: f64 = v519 * v784;
        let v948: f64 = v522 * v931;
        let v949: f64 = v947 + v948;
        let v950: f64 = v84 * v148;
        let v951: f64 = v84 * v105;
        let v952: f64 = v99 * v951;
        let v953: f64 = v148 + v952;
        let v954: f64 = v953 + v139;
        let v955: f64 = -0.0203_f64;
        let v956: f64 = v955 * v107;
        let v957: f64 = v99 * v956;
        let v958: f64 = v84 * v135;
        let v959: f64 = v957 + v958;
        let v960: f64 = v107 * v956;
        let v961: f64 = v960 - v129;
        let v962: f64 = v105 * v951;
        let v963: f64 = v961 - v962;
        let v964: f64 = v84 * v237;
        let v965: f64 = v254 * v682;
        let v966: f64 = v964 - v965;
        let v967: f64 = v272 * v687;
        let v968: f64 = v966 - v967;
        let v969: f64 = v84 * v248;
        let v970: f64 = v955 * v233;
        let v971: f64 = v240 * v682;
        let v972: f64 = v970 - v971;
        let v973: f64 = v240 * v972;
        let v974: f64 = v969 - v973;
        let v975: f64 = v974 + v697;
        let v976: f64 = v228 * v682;
        let v977: f64 = v233 * v687;
        let v978: f64 = v976 - v977;
        let v979: f64 = v228 * v978;
        let v980: f64 = v975 + v979;
        let v981: f64 = v297 * v687;
        let v982: f64 = v980 + v981;
        let v983: f64 = v233 * v972;
        let v984: f64 = v248 * v682;
        let v985: f64 = v983 + v984;
        let v986: f64 = v985 - v709;
        let v987: f64 = v84 * v228;
        let v988: f64 = v240 * v687;
        let v989: f64 = v987 + v988;
        let v990: f64 = v228 * v989;
        let v991: f64 = v986 - v990;
        let v992: f64 = v265 * v687;
        let v993: f64 = v991 - v992;
        let v994: f64 = v993 - v718;
        let v995: f64 = v955 * v265;
        let v996: f64 = v297 * v682;
        let v997: f64 = v995 - v996;
        let v998: f64 = v240 * v989;
        let v999: f64 = v997 + v998;
        let v1000: f64 = v233 * v978;
        let v1001: f64 = v999 - v1000;
        let v1002: f64 = v1001 + v727;
        let v1003: f64 = v84 * v365;
        let v1004: f64 = v367 * v682;
        let v1005: f64 = v1003 + v1004;
        let v1006: f64 = v369 * v1005;
        let v1007: f64 = v84 * v367;
        let v1008: f64 = v365 * v682;
        let v1009: f64 = v1007 - v1008;
        let v1010: f64 = v376 * v1009;
        let v1011: f64 = v1006 + v1010;
        let v1012: f64 = v1011 - v967;
        let v1013: f64 = v384 * v1005;
        let v1014: f64 = v391 * v1005;
        let v1015: f64 = v388 * v1009;
        let v1016: f64 = v1014 - v1015;
        let v1017: f64 = v388 * v1016;
        let v1018: f64 = v1013 + v1017;
        let v1019: f64 = v1018 + v775;
        let v1020: f64 = v400 * v1009;
        let v1021: f64 = v391 * v687;
        let v1022: f64 = v1020 + v1021;
        let v1023: f64 = v400 * v1022;
        let v1024: f64 = v1019 - v1023;
        let v1025: f64 = v412 * v687;
        let v1026: f64 = v1024 + v1025;
        let v1027: f64 = v1026 - v785;
        let v1028: f64 = v422 * v1005;
        let v1029: f64 = v412 * v1009;
        let v1030: f64 = v1028 - v1029;
        let v1031: f64 = v391 * v1022;
        let v1032: f64 = v1030 - v1031;
        let v1033: f64 = v400 * v1005;
        let v1034: f64 = v388 * v687;
        let v1035: f64 = v1033 + v1034;
        let v1036: f64 = v388 * v1035;
        let v1037: f64 = v1032 - v1036;
        let v1038: f64 = v1037 - v797;
        let v1039: f64 = v1038 - v800;
        let v1040: f64 = v391 * v1016;
        let v1041: f64 = v384 * v1009;
        let v1042: f64 = v1040 + v1041;
        let v1043: f64 = v1042 + v806;
        let v1044: f64 = v400 * v1035;
        let v1045: f64 = v1043 + v1044;
        let v1046: f64 = v422 * v687;
        let v1047: f64 = v1045 + v1046;
        let v1048: f64 = v1047 + v811;
        let v1049: f64 = -v1048;
        let v1050: f64 = v493 * v687;
        let v1051: f64 = v491 * v1009;
        let v1052: f64 = v1050 - v1051;
        let v1053: f64 = v495 * v1052;
        let v1054: f64 = v1006 - v1053;
        let v1055: f64 = v493 * v1009;
        let v1056: f64 = v491 * v687;
        let v1057: f64 = v1055 + v1056;
        let v1058: f64 = v503 * v1057;
        let v1059: f64 = v1054 + v1058;
        let v1060: f64 = v516 * v1005;
        let v1061: f64 = v519 * v1052;
        let v1062: f64 = v1060 + v1061;
        let v1063: f64 = v525 * v1005;
        let v1064: f64 = v522 * v1057;
        let v1065: f64 = v1063 - v1064;
        let v1066: f64 = v522 * v1065;
        let v1067: f64 = v1062 + v1066;
        let v1068: f64 = v525 * v1052;
        let v1069: f64 = v533 * v1057;
        let v1070: f64 = v1068 + v1069;
        let v1071: f64 = v533 * v1070;
        let v1072: f64 = v1067 - v1071;
        let v1073: f64 = v1072 - v875;
        let v1074: f64 = v1073 - v880;
        let v1075: f64 = v548 * v1005;
        let v1076: f64 = v533 * v1005;
        let v1077: f64 = v522 * v1052;
        let v1078: f64 = v1076 + v1077;
        let v1079: f64 = v522 * v1078;
        (
            v906,
            v908,
            v909,
            v915,
            v925,
            v935,
            v939,
            v946,
            v949,
            v950,
            v954,
            v959,
            v963,
            v968,
            v982,
            v994,
            v1002,
            v1012,
            v1027,
            v1039,
            v1049,
            v1052,
            v1057,
            v1059,
            v1065,
            v1070,
            v1074,
            v1075,
            v1078,
            v1079,
        )
    };
    let (
        v1086,
        v1095,
        v1096,
        v1097,
        v1099,
        v1102,
        v1104,
        v1106,
        v1108,
        v1111,
        v1112,
        v1116,
        v1124,
        v1132,
        v1134,
        v1139,
        v1142,
        v1146,
        v1150,
        v1153,
        v1159,
        v1169,
        v1179,
        v1182,
        v1189,
        v1192,
        v1193,
        v1195,
        v1197,
        v1200,
        v1203,
        v1204,
        v1205,
        v1207,
        v1211,
        v1216,
        v1224,
        v1232,
        v1235,
        v1240,
        v1241,
        v1242,
        v1243,
        v1244,
        v1247,
        v1249,
        v1251,
        v1253,
        v1254,
    ) = {
        let v1080: f64 = v1075 - v1079;
        let v1081: f64 = v525 * v1070;
        let v1082: f64 = v1080 - v1081;
        let v1083: f64 = v519 * v1057;
        let v1084: f64 = v1082 - v1083;
        let v1085: f64 = v1084 - v892;
        let v1086: f64 = v1085 - v897;
        let v1087: f64 = v533 * v1078;
        let v1088: f64 = v548 * v1052;
        let v1089: f64 = v1087 + v1088;
        let v1090: f64 = v525 * v1065;
        let v1091: f64 = v1089 + v1090;
        let v1092: f64 = v516 * v1057;
        let v1093: f64 = v1091 + v1092;
        let v1094: f64 = v906 - v1093;
        let v1095: f64 = v1094 - v908;
        let v1096: f64 = -v272;
        let v1097: f64 = v233 * v228;
        let v1098: f64 = v240 * v228;
        let v1099: f64 = v265 + v1098;
        let v1100: f64 = v228 * v228;
        let v1101: f64 = v233 * v233;
        let v1102: f64 = v1100 - v1101;
        let v1103: f64 = v240 * v233;
        let v1104: f64 = v248 - v1103;
        let v1105: f64 = v228 * v233;
        let v1106: f64 = -v1105;
        let v1107: f64 = v272 * v365;
        let v1108: f64 = -v1107;
        let v1109: f64 = v369 * v367;
        let v1110: f64 = v376 * v365;
        let v1111: f64 = v1109 - v1110;
        let v1112: f64 = v272 * v367;
        let v1113: f64 = v400 * v365;
        let v1114: f64 = v391 * v1113;
        let v1115: f64 = v422 * v367;
        let v1116: f64 = v1114 + v1115;
        let v1117: f64 = v391 * v365;
        let v1118: f64 = v388 * v367;
        let v1119: f64 = v1117 - v1118;
        let v1120: f64 = v391 * v1119;
        let v1121: f64 = v400 * v1113;
        let v1122: f64 = v1120 - v1121;
        let v1123: f64 = v384 * v367;
        let v1124: f64 = v1122 - v1123;
        let v1125: f64 = v388 * v1113;
        let v1126: f64 = v422 * v365;
        let v1127: f64 = v1125 + v1126;
        let v1128: f64 = v400 * v367;
        let v1129: f64 = v391 * v1128;
        let v1130: f64 = v1127 - v1129;
        let v1131: f64 = v412 * v367;
        let v1132: f64 = v1130 + v1131;
        let v1133: f64 = v400 * v1119;
        let v1134: f64 = -v1133;
        let v1135: f64 = v388 * v1119;
        let v1136: f64 = v384 * v365;
        let v1137: f64 = v1135 - v1136;
        let v1138: f64 = v400 * v1128;
        let v1139: f64 = v1137 + v1138;
        let v1140: f64 = v412 * v365;
        let v1141: f64 = v388 * v1128;
        let v1142: f64 = v1140 - v1141;
        let v1143: f64 = v491 * v367;
        let v1144: f64 = v369 * v1143;
        let v1145: f64 = v495 * v365;
        let v1146: f64 = v1144 - v1145;
        let v1147: f64 = v493 * v367;
        let v1148: f64 = v369 * v1147;
        let v1149: f64 = v503 * v365;
        let v1150: f64 = v1148 - v1149;
        let v1151: f64 = v495 * v1147;
        let v1152: f64 = v503 * v1143;
        let v1153: f64 = v1151 - v1152;
        let v1154: f64 = v533 * v365;
        let v1155: f64 = v522 * v1143;
        let v1156: f64 = v1154 - v1155;
        let v1157: f64 = v525 * v1156;
        let v1158: f64 = v548 * v1147;
        let v1159: f64 = v1157 + v1158;
        let v1160: f64 = v525 * v365;
        let v1161: f64 = v522 * v1147;
        let v1162: f64 = v1160 - v1161;
        let v1163: f64 = v525 * v1162;
        let v1164: f64 = v533 * v1156;
        let v1165: f64 = v548 * v1143;
        let v1166: f64 = v1164 + v1165;
        let v1167: f64 = v1163 - v1166;
        let v1168: f64 = v516 * v1147;
        let v1169: f64 = v1167 - v1168;
        let v1170: f64 = v548 * v365;
        let v1171: f64 = v522 * v1156;
        let v1172: f64 = v1170 + v1171;
        let v1173: f64 = v525 * v1143;
        let v1174: f64 = v533 * v1147;
        let v1175: f64 = v1173 - v1174;
        let v1176: f64 = v525 * v1175;
        let v1177: f64 = v1172 + v1176;
        let v1178: f64 = v519 * v1147;
        let v1179: f64 = v1177 + v1178;
        let v1180: f64 = v516 * v1143;
        let v1181: f64 = v533 * v1162;
        let v1182: f64 = v1180 - v1181;
        let v1183: f64 = v522 * v1162;
        let v1184: f64 = v516 * v365;
        let v1185: f64 = v519 * v1143;
        let v1186: f64 = v1184 + v1185;
        let v1187: f64 = v1183 - v1186;
        let v1188: f64 = v533 * v1175;
        let v1189: f64 = v1187 - v1188;
        let v1190: f64 = v519 * v365;
        let v1191: f64 = v522 * v1175;
        let v1192: f64 = v1190 + v1191;
        let v1193: f64 = -v376;
        let v1194: f64 = v391 * v388;
        let v1195: f64 = -v1194;
        let v1196: f64 = v400 * v388;
        let v1197: f64 = v1196 - v422;
        let v1198: f64 = v391 * v391;
        let v1199: f64 = v388 * v388;
        let v1200: f64 = v1198 - v1199;
        let v1201: f64 = v400 * v391;
        let v1202: f64 = v412 + v1201;
        let v1203: f64 = -v1202;
        let v1204: f64 = v388 * v391;
        let v1205: f64 = v369 * v493;
        let v1206: f64 = v369 * v491;
        let v1207: f64 = -v1206;
        let v1208: f64 = v503 * v493;
        let v1209: f64 = v495 * v491;
        let v1210: f64 = v1208 + v1209;
        let v1211: f64 = -v1210;
        let v1212: f64 = v522 * v493;
        let v1213: f64 = v525 * v1212;
        let v1214: f64 = v548 * v491;
        let v1215: f64 = v1213 + v1214;
        let v1216: f64 = -v1215;
        let v1217: f64 = v533 * v1212;
        let v1218: f64 = v548 * v493;
        let v1219: f64 = v1217 - v1218;
        let v1220: f64 = v522 * v491;
        let v1221: f64 = v525 * v1220;
        let v1222: f64 = v1219 + v1221;
        let v1223: f64 = v516 * v491;
        let v1224: f64 = v1222 + v1223;
        let v1225: f64 = v525 * v493;
        let v1226: f64 = v533 * v491;
        let v1227: f64 = v1225 + v1226;
        let v1228: f64 = v525 * v1227;
        let v1229: f64 = v522 * v1212;
        let v1230: f64 = v1228 - v1229;
        let v1231: f64 = v519 * v491;
        let v1232: f64 = v1230 - v1231;
        let v1233: f64 = v516 * v493;
        let v1234: f64 = v533 * v1220;
        let v1235: f64 = v1233 - v1234;
        let v1236: f64 = v522 * v1220;
        let v1237: f64 = v519 * v493;
        let v1238: f64 = v1236 - v1237;
        let v1239: f64 = v533 * v1227;
        let v1240: f64 = v1238 - v1239;
        let v1241: f64 = v522 * v1227;
        let v1242: f64 = -v495;
        let v1243: f64 = -v503;
        let v1244: f64 = v525 * v533;
        let v1245: f64 = v525 * v525;
        let v1246: f64 = v533 * v533;
        let v1247: f64 = v1245 - v1246;
        let v1248: f64 = v522 * v533;
        let v1249: f64 = v548 + v1248;
        let v1250: f64 = v533 * v525;
        let v1251: f64 = -v1250;
        let v1252: f64 = v522 * v525;
        let v1253: f64 = v1252 - v516;
        let v1254: f64 = 0.0_f64;
        (
            v1086,
            v1095,
            v1096,
            v1097,
            v1099,
            v1102,
            v1104,
            v1106,
            v1108,
            v1111,
            v1112,
            v1116,
            v1124,
            v1132,
            v1134,
            v1139,
            v1142,
            v1146,
            v1150,
            v1153,
            v1159,
            v1169,
            v1179,
            v1182,
            v1189,
            v1192,
            v1193,
            v1195,
            v1197,
            v1200,
            v1203,
            v1204,
            v1205,
            v1207,
            v1211,
            v1216,
            v1224,
            v1232,
            v1235,
            v1240,
            v1241,
            v1242,
            v1243,
            v1244,
            v1247,
            v1249,
            v1251,
            v1253,
            v1254,
        )
    };
    [
        [
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v0,
            v1254,
            v1254,
            v18,
            v24,
            v34,
            v54,
            v58,
            v66,
            v74,
            v77,
            v82,
            v83,
            v154,
            v169,
            v183,
            v192,
            v196,
            v204,
            v212,
            v214,
            v219,
            v222,
            v280,
            v299,
            v313,
            v324,
            v330,
            v340,
            v350,
            v353,
            v360,
            v363,
            v382,
            v419,
            v439,
            v450,
            v456,
            v466,
            v476,
            v479,
            v486,
            v489,
            v508,
            v545,
            v565,
            v576,
            v582,
            v592,
            v602,
            v605,
            v612,
            v615,
        ],
        [
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v616,
            v621,
            v624,
            v627,
            v629,
            v632,
            v634,
            v635,
            v637,
            v47,
            v643,
            v653,
            v661,
            v668,
            v670,
            v672,
            v675,
            v138,
            v678,
            v679,
            v690,
            v705,
            v719,
            v728,
            v733,
            v741,
            v749,
            v750,
            v755,
            v758,
            v768,
            v786,
            v801,
            v812,
            v818,
            v828,
            v838,
            v841,
            v848,
            v851,
            v861,
            v881,
            v898,
            v909,
            v915,
            v925,
            v935,
            v939,
            v946,
            v949,
        ],
        [
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v950,
            v954,
            v959,
            v963,
            v670,
            v672,
            v675,
            v138,
            v678,
            v679,
            v968,
            v982,
            v994,
            v1002,
            v733,
            v741,
            v749,
            v750,
            v755,
            v758,
            v1012,
            v1027,
            v1039,
            v1049,
            v818,
            v828,
            v838,
            v841,
            v848,
            v851,
            v1059,
            v1074,
            v1086,
            v1095,
            v915,
            v925,
            v935,
            v939,
            v946,
            v949,
        ],
        [
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1096,
            v1254,
            v254,
            v1097,
            v1099,
            v1102,
            v297,
            v1104,
            v1106,
            v1254,
            v1108,
            v1111,
            v1112,
            v1116,
            v1124,
            v1132,
            v1134,
            v1139,
            v1142,
            v1254,
            v1146,
            v1150,
            v1153,
            v1159,
            v1169,
            v1179,
            v1182,
            v1189,
            v1192,
        ],
        [
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v369,
            v1254,
            v1193,
            v1195,
            v1197,
            v1200,
            v384,
            v1203,
            v1204,
            v1254,
            v1205,
            v1207,
            v1211,
            v1216,
            v1224,
            v1232,
            v1235,
            v1240,
            v1241,
        ],
        [
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1254,
            v1242,
            v1243,
            v1254,
            v1244,
            v1247,
            v1249,
            v1251,
            v1253,
            v519,
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
/// `params: [f64; 60]`: per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2, inertia about the link frame origin)
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
pub fn standard_parameters() -> [f64; 60] {
    let v0: f64 = 0.0_f64;
    let v1: f64 = 0.35_f64;
    let v2: f64 = 17.4_f64;
    let v3: f64 = -6.33012_f64;
    let v4: f64 = 0.1044_f64;
    let v5: f64 = 3.9585_f64;
    let v6: f64 = 1.03118515_f64;
    let v7: f64 = 0.03798072_f64;
    let v8: f64 = 1.4401023_f64;
    let v9: f64 = 3.727456406_f64;
    let v10: f64 = -0.023751_f64;
    let v11: f64 = 2.842524056_f64;
    let v12: f64 = 4.8_f64;
    let v13: f64 = -0.09744_f64;
    let v14: f64 = -0.06768_f64;
    let v15: f64 = 0.336_f64;
    let v16: f64 = 0.090474288_f64;
    let v17: f64 = -0.001373904_f64;
    let v18: f64 = 0.0068208_f64;
    let v19: f64 = 0.111498032_f64;
    let v20: f64 = 0.0047376_f64;
    let v21: f64 = 0.01543232_f64;
    let v22: f64 = 0.82_f64;
    let v23: f64 = 0.01558_f64;
    let v24: f64 = 0.00209602_f64;
    let v25: f64 = 0.0013_f64;
    let v26: f64 = 0.34_f64;
    let v27: f64 = 0.0003_f64;
    let v28: f64 = 0.0004_f64;
    let v29: f64 = 0.09_f64;
    let v30: f64 = 0.00288_f64;
    let v31: f64 = 0.00024216_f64;
    let v32: f64 = 4e-05_f64;
    [
        v0,
        v0,
        v0,
        v0,
        v0,
        v0,
        v0,
        v1,
        v0,
        v0,
        v2,
        v3,
        v4,
        v5,
        v6,
        v7,
        v8,
        v9,
        v10,
        v11,
        v12,
        v13,
        v14,
        v15,
        v16,
        v17,
        v18,
        v19,
        v20,
        v21,
        v22,
        v0,
        v23,
        v0,
        v24,
        v0,
        v0,
        v25,
        v0,
        v24,
        v26,
        v0,
        v0,
        v0,
        v27,
        v0,
        v0,
        v28,
        v0,
        v27,
        v29,
        v0,
        v0,
        v30,
        v31,
        v0,
        v0,
        v31,
        v0,
        v32,
    ]
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/puma560.json")
);
