// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `scara_derive::robot_model!("models/ur5.json", f32, lanes)` in the `generated` crate,
// formatted with prettyplease. Not compiled: for reading and review.

/// Name of the robot (`robot.name` in the model file).
pub const ROBOT_NAME: &str = "ur5";
/// Description of the robot, from the model file.
pub const DESCRIPTION: &str = "Universal Robots UR5, 6R, from the URDF of example-robot-data";
/// Degrees of freedom: the number of joints.
pub const DOF: usize = 6;
/// Name and version of the generator that wrote the model file.
pub const GENERATOR: &str = "scara-codegen 0.1.0";
/// Version of CasADi the generator used.
pub const CASADI_VERSION: &str = "3.7.2";
/// Robot description file the model was generated from.
pub const SOURCE: &str = "robots/ur5.toml";
/// SHA-256 of the robot description file (64 hex digits).
pub const SOURCE_SHA256: &str = "30c3e81da68d081f18ae14a77074db86d3b14a924158d2c0b43ef7ec42270ba8";
/// Joint names, base to tip.
pub const JOINT_NAMES: [&str; DOF] = [
    "shoulder_pan_joint",
    "shoulder_lift_joint",
    "elbow_joint",
    "wrist_1_joint",
    "wrist_2_joint",
    "wrist_3_joint",
];
/// `true` for a prismatic joint (m, N), `false` for a revolute one (rad, N m).
pub const JOINT_IS_PRISMATIC: [bool; DOF] = [false, false, false, false, false, false];
/// Joint position limits `[lower, upper]`, rad or m.
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const JOINT_LIMITS: [[f64; 2]; DOF] = [
    [-6.28318530718_f64, 6.28318530718_f64],
    [-6.28318530718_f64, 6.28318530718_f64],
    [-3.14159265359_f64, 3.14159265359_f64],
    [-6.28318530718_f64, 6.28318530718_f64],
    [-6.28318530718_f64, 6.28318530718_f64],
    [-6.28318530718_f64, 6.28318530718_f64],
];
/// Actuator effort limits, N m (revolute) or N (prismatic).
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const EFFORT_LIMITS: [f64; DOF] = [
    150.0_f64,
    150.0_f64,
    150.0_f64,
    28.0_f64,
    28.0_f64,
    28.0_f64,
];
/// Gravity vector in the base frame, m/s^2.
#[allow(clippy::all, clippy::pedantic, clippy::nursery)]
pub const GRAVITY: [f64; 3] = [0.0_f64, 0.0_f64, -9.81_f64];
/// `(function, flops, trig)` for every function, in file order: floating-point
/// operations (add, sub, mul, div, neg, sq, twice, inv, sqrt, fabs) and trig calls
/// (sin, cos, atan2) in its body.
pub const OPERATION_COUNTS: [(&str, u32, u32); 14] = [
    ("frame_poses", 113, 12),
    ("end_effector_pose", 111, 12),
    ("jacobian", 113, 10),
    ("jacobian_and_position", 194, 10),
    ("jdot_qd", 263, 10),
    ("mass_matrix", 238, 10),
    ("coriolis_matrix", 1641, 10),
    ("coriolis", 393, 10),
    ("gravity", 24, 6),
    ("inverse_dynamics", 425, 10),
    ("forward_dynamics", 751, 10),
    ("mass_matrix_and_bias", 635, 10),
    ("regressor", 1123, 10),
    ("standard_parameters", 0, 0),
];
/// Poses of every link frame (the description's DH frames, or its URDF links), products of the joint transforms `A_1 ... A_i` (thesis eq. 3.2-3.7).
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `poses: [[[f64; 4]; 4]; 6]` (6 x 4 x 4, row-major): homogeneous transforms T_0i of the description's frames 1..n in the base frame (m)
///
/// Operation count: 113 floating-point operations, 12 trig calls.
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
    let (v2, v1): (f64, f64) = ::libm::sincos(v0);
    let v3: f64 = -v2;
    let v4: f64 = 0.0_f64;
    let v5: f64 = 1.0_f64;
    let v6: f64 = 0.089159_f64;
    let v7: f64 = q[1];
    let (v8, v11): (f64, f64) = ::libm::sincos(v7);
    let v9: f64 = v1 * v8;
    let v10: f64 = -v9;
    let v12: f64 = v1 * v11;
    let v13: f64 = 0.13585_f64;
    let v14: f64 = v13 * v2;
    let v15: f64 = -v14;
    let v16: f64 = v2 * v8;
    let v17: f64 = -v16;
    let v18: f64 = v2 * v11;
    let v19: f64 = v13 * v1;
    let v20: f64 = -v11;
    let v21: f64 = -v8;
    let v22: f64 = q[2];
    let (v25, v23): (f64, f64) = ::libm::sincos(v22);
    let v24: f64 = v9 * v23;
    let v26: f64 = v12 * v25;
    let v27: f64 = v24 + v26;
    let v28: f64 = -v27;
    let v29: f64 = v12 * v23;
    let v30: f64 = v9 * v25;
    let v31: f64 = v29 - v30;
    let v32: f64 = 0.425_f64;
    let v33: f64 = v32 * v12;
    let v34: f64 = -0.1197_f64;
    let v35: f64 = v34 * v2;
    let v36: f64 = v33 - v35;
    let v37: f64 = v36 - v14;
    let v38: f64 = v16 * v23;
    let v39: f64 = v18 * v25;
    let v40: f64 = v38 + v39;
    let v41: f64 = -v40;
    let v42: f64 = v18 * v23;
    let v43: f64 = v16 * v25;
    let v44: f64 = v42 - v43;
    let v45: f64 = v34 * v1;
    let v46: f64 = v32 * v18;
    let v47: f64 = v45 + v46;
    let v48: f64 = v19 + v47;
    let v49: f64 = v8 * v25;
    let v50: f64 = v11 * v23;
    let v51: f64 = v49 - v50;
    let v52: f64 = v11 * v25;
    let v53: f64 = v8 * v23;
    let v54: f64 = v52 + v53;
    let v55: f64 = -v54;
    let v56: f64 = v32 * v8;
    let v57: f64 = v6 - v56;
    let v58: f64 = q[3];
    let (v59, v61): (f64, f64) = ::libm::sincos(v58);
    let v60: f64 = v27 * v59;
    let v62: f64 = v31 * v61;
    let v63: f64 = v60 - v62;
    let v64: f64 = v27 * v61;
    let v65: f64 = v31 * v59;
    let v66: f64 = v64 + v65;
    let v67: f64 = -v66;
    let v68: f64 = 0.39225_f64;
    let v69: f64 = v68 * v31;
    let v70: f64 = v37 + v69;
    let v71: f64 = v40 * v59;
    let v72: f64 = v44 * v61;
    let v73: f64 = v71 - v72;
    let v74: f64 = v40 * v61;
    let v75: f64 = v44 * v59;
    let v76: f64 = v74 + v75;
    let v77: f64 = -v76;
    let v78: f64 = v68 * v44;
    let v79: f64 = v48 + v78;
    let v80: f64 = v54 * v61;
    let v81: f64 = v51 * v59;
    let v82: f64 = v80 - v81;
    let v83: f64 = v51 * v61;
    let v84: f64 = v54 * v59;
    let v85: f64 = v83 + v84;
    let v86: f64 = v68 * v54;
    let v87: f64 = v57 - v86;
    let v88: f64 = q[4];
    let (v91, v89): (f64, f64) = ::libm::sincos(v88);
    let v90: f64 = v63 * v89;
    let v92: f64 = v2 * v91;
    let v93: f64 = v90 - v92;
    let v94: f64 = v63 * v91;
    let v95: f64 = v2 * v89;
    let v96: f64 = v94 + v95;
    let v97: f64 = -v96;
    let v98: f64 = 0.093_f64;
    let v99: f64 = v98 * v2;
    let v100: f64 = v70 - v99;
    let v101: f64 = v73 * v89;
    let v102: f64 = v1 * v91;
    let v103: f64 = v101 + v102;
    let v104: f64 = v1 * v89;
    let v105: f64 = v73 * v91;
    let v106: f64 = v104 - v105;
    let v107: f64 = v98 * v1;
    let v108: f64 = v79 + v107;
    let v109: f64 = v82 * v89;
    let v110: f64 = v82 * v91;
    let v111: f64 = -v110;
    let v112: f64 = q[5];
    let (v115, v113): (f64, f64) = ::libm::sincos(v112);
    let v114: f64 = v93 * v113;
    let v116: f64 = v66 * v115;
    let v117: f64 = v114 + v116;
    let v118: f64 = v93 * v115;
    let v119: f64 = v66 * v113;
    let v120: f64 = v118 - v119;
    let v121: f64 = 0.09465_f64;
    let v122: f64 = v121 * v66;
    let v123: f64 = v100 - v122;
    let v124: f64 = v103 * v113;
    let v125: f64 = v76 * v115;
    let v126: f64 = v124 + v125;
    let v127: f64 = v103 * v115;
    let v128: f64 = v76 * v113;
    let v129: f64 = v127 - v128;
    let v130: f64 = v121 * v76;
    let v131: f64 = v108 - v130;
    let v132: f64 = v109 * v113;
    let v133: f64 = v85 * v115;
    let v134: f64 = v132 - v133;
    let v135: f64 = v109 * v115;
    let v136: f64 = v85 * v113;
    let v137: f64 = v135 + v136;
    let v138: f64 = v121 * v85;
    let v139: f64 = v87 + v138;
    [
        [[v1, v3, v4, v4], [v2, v1, v4, v4], [v4, v4, v5, v6], [v4, v4, v4, v5]],
        [[v10, v3, v12, v15], [v17, v1, v18, v19], [v20, v4, v21, v6], [v4, v4, v4, v5]],
        [
            [v28, v3, v31, v37],
            [v41, v1, v44, v48],
            [v51, v4, v55, v57],
            [v4, v4, v4, v5],
        ],
        [
            [v63, v3, v67, v70],
            [v73, v1, v77, v79],
            [v82, v4, v85, v87],
            [v4, v4, v4, v5],
        ],
        [
            [v93, v97, v67, v100],
            [v103, v106, v77, v108],
            [v109, v111, v85, v87],
            [v4, v4, v4, v5],
        ],
        [
            [v117, v97, v120, v123],
            [v126, v106, v129, v131],
            [v134, v111, v137, v139],
            [v4, v4, v4, v5],
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
/// `pose: [[f64; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the base frame (m)
///
/// Operation count: 111 floating-point operations, 12 trig calls.
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
    let v0: f64 = q[0];
    let (v25, v1): (f64, f64) = ::libm::sincos(v0);
    let v2: f64 = q[1];
    let (v3, v8): (f64, f64) = ::libm::sincos(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = q[2];
    let (v10, v6): (f64, f64) = ::libm::sincos(v5);
    let v7: f64 = v4 * v6;
    let v9: f64 = v1 * v8;
    let v11: f64 = v9 * v10;
    let v12: f64 = v7 + v11;
    let v13: f64 = q[3];
    let (v14, v19): (f64, f64) = ::libm::sincos(v13);
    let v15: f64 = v12 * v14;
    let v16: f64 = v9 * v6;
    let v17: f64 = v4 * v10;
    let v18: f64 = v16 - v17;
    let v20: f64 = v18 * v19;
    let v21: f64 = v15 - v20;
    let v22: f64 = q[4];
    let (v23, v26): (f64, f64) = ::libm::sincos(v22);
    let v24: f64 = v21 * v23;
    let v27: f64 = v25 * v26;
    let v28: f64 = v24 + v27;
    let v29: f64 = -v28;
    let v30: f64 = v21 * v26;
    let v31: f64 = v25 * v23;
    let v32: f64 = v30 - v31;
    let v33: f64 = q[5];
    let (v39, v34): (f64, f64) = ::libm::sincos(v33);
    let v35: f64 = v32 * v34;
    let v36: f64 = v12 * v19;
    let v37: f64 = v18 * v14;
    let v38: f64 = v36 + v37;
    let v40: f64 = v38 * v39;
    let v41: f64 = v35 + v40;
    let v42: f64 = -v41;
    let v43: f64 = v32 * v39;
    let v44: f64 = v38 * v34;
    let v45: f64 = v43 - v44;
    let v46: f64 = 0.425_f64;
    let v47: f64 = v46 * v9;
    let v48: f64 = -0.1197_f64;
    let v49: f64 = v48 * v25;
    let v50: f64 = v47 - v49;
    let v51: f64 = 0.13585_f64;
    let v52: f64 = v51 * v25;
    let v53: f64 = v50 - v52;
    let v54: f64 = 0.39225_f64;
    let v55: f64 = v54 * v18;
    let v56: f64 = v53 + v55;
    let v57: f64 = 0.093_f64;
    let v58: f64 = v57 * v25;
    let v59: f64 = v56 - v58;
    let v60: f64 = 0.09465_f64;
    let v61: f64 = v60 * v38;
    let v62: f64 = v59 - v61;
    let v63: f64 = 0.0823_f64;
    let v64: f64 = v63 * v28;
    let v65: f64 = v62 - v64;
    let v66: f64 = v1 * v26;
    let v67: f64 = v25 * v3;
    let v68: f64 = v67 * v6;
    let v69: f64 = v25 * v8;
    let v70: f64 = v69 * v10;
    let v71: f64 = v68 + v70;
    let v72: f64 = v71 * v14;
    let v73: f64 = v69 * v6;
    let v74: f64 = v67 * v10;
    let v75: f64 = v73 - v74;
    let v76: f64 = v75 * v19;
    let v77: f64 = v72 - v76;
    let v78: f64 = v77 * v23;
    let v79: f64 = v66 - v78;
    let v80: f64 = v77 * v26;
    let v81: f64 = v1 * v23;
    let v82: f64 = v80 + v81;
    let v83: f64 = v82 * v34;
    let v84: f64 = v71 * v19;
    let v85: f64 = v75 * v14;
    let v86: f64 = v84 + v85;
    let v87: f64 = v86 * v39;
    let v88: f64 = v83 + v87;
    let v89: f64 = -v88;
    let v90: f64 = v82 * v39;
    let v91: f64 = v86 * v34;
    let v92: f64 = v90 - v91;
    let v93: f64 = v51 * v1;
    let v94: f64 = v48 * v1;
    let v95: f64 = v46 * v69;
    let v96: f64 = v94 + v95;
    let v97: f64 = v93 + v96;
    let v98: f64 = v54 * v75;
    let v99: f64 = v97 + v98;
    let v100: f64 = v57 * v1;
    let v101: f64 = v99 + v100;
    let v102: f64 = v60 * v86;
    let v103: f64 = v101 - v102;
    let v104: f64 = v63 * v79;
    let v105: f64 = v103 + v104;
    let v106: f64 = v8 * v10;
    let v107: f64 = v3 * v6;
    let v108: f64 = v106 + v107;
    let v109: f64 = v108 * v19;
    let v110: f64 = v3 * v10;
    let v111: f64 = v8 * v6;
    let v112: f64 = v110 - v111;
    let v113: f64 = v112 * v14;
    let v114: f64 = v109 - v113;
    let v115: f64 = v114 * v23;
    let v116: f64 = -v115;
    let v117: f64 = v114 * v26;
    let v118: f64 = v117 * v34;
    let v119: f64 = v112 * v19;
    let v120: f64 = v108 * v14;
    let v121: f64 = v119 + v120;
    let v122: f64 = v121 * v39;
    let v123: f64 = v118 - v122;
    let v124: f64 = -v123;
    let v125: f64 = v117 * v39;
    let v126: f64 = v121 * v34;
    let v127: f64 = v125 + v126;
    let v128: f64 = 0.089159_f64;
    let v129: f64 = v46 * v3;
    let v130: f64 = v128 - v129;
    let v131: f64 = v54 * v108;
    let v132: f64 = v130 - v131;
    let v133: f64 = v60 * v121;
    let v134: f64 = v132 + v133;
    let v135: f64 = v63 * v115;
    let v136: f64 = v134 - v135;
    let v137: f64 = 0.0_f64;
    let v138: f64 = 1.0_f64;
    [
        [v29, v42, v45, v65],
        [v79, v89, v92, v105],
        [v116, v124, v127, v136],
        [v137, v137, v137, v138],
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
/// Operation count: 113 floating-point operations, 10 trig calls.
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
    let v0: f64 = -0.10915_f64;
    let v1: f64 = 0.0823_f64;
    let v2: f64 = q[4];
    let (v13, v3): (f64, f64) = ::libm::sincos(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = v0 - v4;
    let v6: f64 = q[0];
    let (v43, v7): (f64, f64) = ::libm::sincos(v6);
    let v8: f64 = v5 * v7;
    let v9: f64 = 0.09465_f64;
    let v10: f64 = q[3];
    let (v15, v11): (f64, f64) = ::libm::sincos(v10);
    let v12: f64 = v9 * v11;
    let v14: f64 = v1 * v13;
    let v16: f64 = v14 * v15;
    let v17: f64 = v12 + v16;
    let v18: f64 = q[2];
    let (v26, v19): (f64, f64) = ::libm::sincos(v18);
    let v20: f64 = v17 * v19;
    let v21: f64 = 0.39225_f64;
    let v22: f64 = v14 * v11;
    let v23: f64 = v21 + v22;
    let v24: f64 = v9 * v15;
    let v25: f64 = v23 - v24;
    let v27: f64 = v25 * v26;
    let v28: f64 = v20 + v27;
    let v29: f64 = q[1];
    let (v30, v40): (f64, f64) = ::libm::sincos(v29);
    let v31: f64 = v28 * v30;
    let v32: f64 = -0.425_f64;
    let v33: f64 = v17 * v26;
    let v34: f64 = v32 + v33;
    let v35: f64 = -0.39225_f64;
    let v36: f64 = v35 - v22;
    let v37: f64 = v36 + v24;
    let v38: f64 = v37 * v19;
    let v39: f64 = v34 + v38;
    let v41: f64 = v39 * v40;
    let v42: f64 = v31 + v41;
    let v44: f64 = v42 * v43;
    let v45: f64 = v8 + v44;
    let v46: f64 = v37 * v26;
    let v47: f64 = v46 - v20;
    let v48: f64 = v47 * v40;
    let v49: f64 = v39 * v30;
    let v50: f64 = v48 + v49;
    let v51: f64 = v50 * v7;
    let v52: f64 = v33 + v38;
    let v53: f64 = v52 * v30;
    let v54: f64 = v48 + v53;
    let v55: f64 = v54 * v7;
    let v56: f64 = v24 - v22;
    let v57: f64 = v56 * v26;
    let v58: f64 = v57 - v20;
    let v59: f64 = v58 * v40;
    let v60: f64 = v56 * v19;
    let v61: f64 = v60 + v33;
    let v62: f64 = v61 * v30;
    let v63: f64 = v59 + v62;
    let v64: f64 = v63 * v7;
    let v65: f64 = v14 * v43;
    let v66: f64 = v1 * v11;
    let v67: f64 = v66 * v19;
    let v68: f64 = v1 * v15;
    let v69: f64 = v68 * v26;
    let v70: f64 = v67 - v69;
    let v71: f64 = v70 * v40;
    let v72: f64 = v68 * v19;
    let v73: f64 = v66 * v26;
    let v74: f64 = v72 + v73;
    let v75: f64 = v74 * v30;
    let v76: f64 = v71 - v75;
    let v77: f64 = v76 * v3;
    let v78: f64 = v77 * v7;
    let v79: f64 = v65 + v78;
    let v80: f64 = 0.0_f64;
    let v81: f64 = v5 * v43;
    let v82: f64 = v47 * v30;
    let v83: f64 = 0.425_f64;
    let v84: f64 = v83 - v33;
    let v85: f64 = v25 * v19;
    let v86: f64 = v84 + v85;
    let v87: f64 = v86 * v40;
    let v88: f64 = v82 + v87;
    let v89: f64 = v88 * v7;
    let v90: f64 = v81 + v89;
    let v91: f64 = v50 * v43;
    let v92: f64 = v54 * v43;
    let v93: f64 = v63 * v43;
    let v94: f64 = v77 * v43;
    let v95: f64 = v14 * v7;
    let v96: f64 = v94 - v95;
    let v97: f64 = v52 * v40;
    let v98: f64 = v97 + v31;
    let v99: f64 = v61 * v40;
    let v100: f64 = v22 - v24;
    let v101: f64 = v100 * v26;
    let v102: f64 = v20 + v101;
    let v103: f64 = v102 * v30;
    let v104: f64 = v99 + v103;
    let v105: f64 = v69 - v67;
    let v106: f64 = v105 * v30;
    let v107: f64 = v74 * v40;
    let v108: f64 = v106 - v107;
    let v109: f64 = v108 * v3;
    let v110: f64 = -v43;
    let v111: f64 = v15 * v26;
    let v112: f64 = v11 * v19;
    let v113: f64 = v111 - v112;
    let v114: f64 = v113 * v30;
    let v115: f64 = v15 * v19;
    let v116: f64 = v11 * v26;
    let v117: f64 = v115 + v116;
    let v118: f64 = v117 * v40;
    let v119: f64 = v114 - v118;
    let v120: f64 = v119 * v7;
    let v121: f64 = v112 - v111;
    let v122: f64 = v121 * v40;
    let v123: f64 = v117 * v30;
    let v124: f64 = v122 - v123;
    let v125: f64 = v124 * v13;
    let v126: f64 = v125 * v7;
    let v127: f64 = v3 * v43;
    let v128: f64 = v126 - v127;
    let v129: f64 = v119 * v43;
    let v130: f64 = v3 * v7;
    let v131: f64 = v125 * v43;
    let v132: f64 = v130 + v131;
    let v133: f64 = 1.0_f64;
    let v134: f64 = v113 * v40;
    let v135: f64 = v134 + v123;
    let v136: f64 = v119 * v13;
    [
        [v45, v51, v55, v64, v79, v80],
        [v90, v91, v92, v93, v96, v80],
        [v80, v42, v98, v104, v109, v80],
        [v80, v110, v110, v110, v120, v128],
        [v80, v7, v7, v7, v129, v132],
        [v133, v80, v80, v80, v135, v136],
    ]
}
/// Jacobian and tool position in one pass: `[J | p; 0]`, row r is `[J_r0, ..., J_r(n-1), p_r]` with `J` the geometric Jacobian of `jacobian` and `p` the end-effector origin of `end_effector_pose` (rows 0-2; the last column of rows 3-5 is 0), the same operations as those two functions (bit-identical results), with common subexpressions, sin/cos included, computed once for both and the pose's rotation not computed.
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
///
/// # Output
///
/// `jacobian_and_position: [[f64; 7]; 6]` (6 x 7, row-major): rows `[J(q) | p(q); 0]`: the geometric Jacobian of `jacobian` (rows vx vy vz per unit joint velocity, then wx wy wz, base frame), then the end-effector origin (m, base frame) in rows 0-2 of the last column, 0 in rows 3-5
///
/// Operation count: 194 floating-point operations, 10 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn jacobian_and_position(q: &[f64; 6]) -> [[f64; 7]; 6] {
    let (
        v1,
        v3,
        v5,
        v7,
        v9,
        v11,
        v13,
        v14,
        v15,
        v19,
        v20,
        v21,
        v22,
        v24,
        v25,
        v26,
        v30,
        v31,
        v33,
        v40,
        v42,
        v43,
        v45,
        v47,
        v50,
        v51,
        v52,
        v54,
        v55,
        v61,
        v63,
        v64,
        v67,
        v69,
        v74,
        v77,
        v79,
        v80,
        v81,
        v84,
        v87,
        v96,
        v106,
        v110,
    ) = {
        let v0: f64 = -0.10915_f64;
        let v1: f64 = 0.0823_f64;
        let v2: f64 = q[4];
        let (v13, v3): (f64, f64) = ::libm::sincos(v2);
        let v4: f64 = v1 * v3;
        let v5: f64 = v0 - v4;
        let v6: f64 = q[0];
        let (v43, v7): (f64, f64) = ::libm::sincos(v6);
        let v8: f64 = v5 * v7;
        let v9: f64 = 0.09465_f64;
        let v10: f64 = q[3];
        let (v15, v11): (f64, f64) = ::libm::sincos(v10);
        let v12: f64 = v9 * v11;
        let v14: f64 = v1 * v13;
        let v16: f64 = v14 * v15;
        let v17: f64 = v12 + v16;
        let v18: f64 = q[2];
        let (v26, v19): (f64, f64) = ::libm::sincos(v18);
        let v20: f64 = v17 * v19;
        let v21: f64 = 0.39225_f64;
        let v22: f64 = v14 * v11;
        let v23: f64 = v21 + v22;
        let v24: f64 = v9 * v15;
        let v25: f64 = v23 - v24;
        let v27: f64 = v25 * v26;
        let v28: f64 = v20 + v27;
        let v29: f64 = q[1];
        let (v30, v40): (f64, f64) = ::libm::sincos(v29);
        let v31: f64 = v28 * v30;
        let v32: f64 = -0.425_f64;
        let v33: f64 = v17 * v26;
        let v34: f64 = v32 + v33;
        let v35: f64 = -0.39225_f64;
        let v36: f64 = v35 - v22;
        let v37: f64 = v36 + v24;
        let v38: f64 = v37 * v19;
        let v39: f64 = v34 + v38;
        let v41: f64 = v39 * v40;
        let v42: f64 = v31 + v41;
        let v44: f64 = v42 * v43;
        let v45: f64 = v8 + v44;
        let v46: f64 = v37 * v26;
        let v47: f64 = v46 - v20;
        let v48: f64 = v47 * v40;
        let v49: f64 = v39 * v30;
        let v50: f64 = v48 + v49;
        let v51: f64 = v50 * v7;
        let v52: f64 = v33 + v38;
        let v53: f64 = v52 * v30;
        let v54: f64 = v48 + v53;
        let v55: f64 = v54 * v7;
        let v56: f64 = v24 - v22;
        let v57: f64 = v56 * v26;
        let v58: f64 = v57 - v20;
        let v59: f64 = v58 * v40;
        let v60: f64 = v56 * v19;
        let v61: f64 = v60 + v33;
        let v62: f64 = v61 * v30;
        let v63: f64 = v59 + v62;
        let v64: f64 = v63 * v7;
        let v65: f64 = v14 * v43;
        let v66: f64 = v1 * v11;
        let v67: f64 = v66 * v19;
        let v68: f64 = v1 * v15;
        let v69: f64 = v68 * v26;
        let v70: f64 = v67 - v69;
        let v71: f64 = v70 * v40;
        let v72: f64 = v68 * v19;
        let v73: f64 = v66 * v26;
        let v74: f64 = v72 + v73;
        let v75: f64 = v74 * v30;
        let v76: f64 = v71 - v75;
        let v77: f64 = v76 * v3;
        let v78: f64 = v77 * v7;
        let v79: f64 = v65 + v78;
        let v80: f64 = 0.0_f64;
        let v81: f64 = 0.425_f64;
        let v82: f64 = v7 * v40;
        let v83: f64 = v81 * v82;
        let v84: f64 = -0.1197_f64;
        let v85: f64 = v84 * v43;
        let v86: f64 = v83 - v85;
        let v87: f64 = 0.13585_f64;
        let v88: f64 = v87 * v43;
        let v89: f64 = v86 - v88;
        let v90: f64 = v82 * v19;
        let v91: f64 = v7 * v30;
        let v92: f64 = v91 * v26;
        let v93: f64 = v90 - v92;
        let v94: f64 = v21 * v93;
        let v95: f64 = v89 + v94;
        let v96: f64 = 0.093_f64;
        let v97: f64 = v96 * v43;
        let v98: f64 = v95 - v97;
        let v99: f64 = v91 * v19;
        let v100: f64 = v82 * v26;
        let v101: f64 = v99 + v100;
        let v102: f64 = v101 * v11;
        let v103: f64 = v93 * v15;
        let v104: f64 = v102 + v103;
        let v105: f64 = v9 * v104;
        let v106: f64 = v98 - v105;
        let v107: f64 = v101 * v15;
        let v108: f64 = v93 * v11;
        let v109: f64 = v107 - v108;
        let v110: f64 = v109 * v13;
        (
            v1,
            v3,
            v5,
            v7,
            v9,
            v11,
            v13,
            v14,
            v15,
            v19,
            v20,
            v21,
            v22,
            v24,
            v25,
            v26,
            v30,
            v31,
            v33,
            v40,
            v42,
            v43,
            v45,
            v47,
            v50,
            v51,
            v52,
            v54,
            v55,
            v61,
            v63,
            v64,
            v67,
            v69,
            v74,
            v77,
            v79,
            v80,
            v81,
            v84,
            v87,
            v96,
            v106,
            v110,
        )
    };
    let (
        v114,
        v123,
        v124,
        v125,
        v126,
        v129,
        v159,
        v161,
        v167,
        v172,
        v194,
        v195,
        v205,
        v213,
        v214,
        v217,
        v218,
        v220,
        v221,
    ) = {
        let v111: f64 = v43 * v3;
        let v112: f64 = v110 + v111;
        let v113: f64 = v1 * v112;
        let v114: f64 = v106 - v113;
        let v115: f64 = v5 * v43;
        let v116: f64 = v47 * v30;
        let v117: f64 = v81 - v33;
        let v118: f64 = v25 * v19;
        let v119: f64 = v117 + v118;
        let v120: f64 = v119 * v40;
        let v121: f64 = v116 + v120;
        let v122: f64 = v121 * v7;
        let v123: f64 = v115 + v122;
        let v124: f64 = v50 * v43;
        let v125: f64 = v54 * v43;
        let v126: f64 = v63 * v43;
        let v127: f64 = v77 * v43;
        let v128: f64 = v14 * v7;
        let v129: f64 = v127 - v128;
        let v130: f64 = v87 * v7;
        let v131: f64 = v84 * v7;
        let v132: f64 = v43 * v40;
        let v133: f64 = v81 * v132;
        let v134: f64 = v131 + v133;
        let v135: f64 = v130 + v134;
        let v136: f64 = v132 * v19;
        let v137: f64 = v43 * v30;
        let v138: f64 = v137 * v26;
        let v139: f64 = v136 - v138;
        let v140: f64 = v21 * v139;
        let v141: f64 = v135 + v140;
        let v142: f64 = v96 * v7;
        let v143: f64 = v141 + v142;
        let v144: f64 = v137 * v19;
        let v145: f64 = v132 * v26;
        let v146: f64 = v144 + v145;
        let v147: f64 = v146 * v11;
        let v148: f64 = v139 * v15;
        let v149: f64 = v147 + v148;
        let v150: f64 = v9 * v149;
        let v151: f64 = v143 - v150;
        let v152: f64 = v7 * v3;
        let v153: f64 = v146 * v15;
        let v154: f64 = v139 * v11;
        let v155: f64 = v153 - v154;
        let v156: f64 = v155 * v13;
        let v157: f64 = v152 - v156;
        let v158: f64 = v1 * v157;
        let v159: f64 = v151 + v158;
        let v160: f64 = v52 * v40;
        let v161: f64 = v160 + v31;
        let v162: f64 = v61 * v40;
        let v163: f64 = v22 - v24;
        let v164: f64 = v163 * v26;
        let v165: f64 = v20 + v164;
        let v166: f64 = v165 * v30;
        let v167: f64 = v162 + v166;
        let v168: f64 = v69 - v67;
        let v169: f64 = v168 * v30;
        let v170: f64 = v74 * v40;
        let v171: f64 = v169 - v170;
        let v172: f64 = v171 * v3;
        let v173: f64 = 0.089159_f64;
        let v174: f64 = v81 * v30;
        let v175: f64 = v173 - v174;
        let v176: f64 = v40 * v26;
        let v177: f64 = v30 * v19;
        let v178: f64 = v176 + v177;
        let v179: f64 = v21 * v178;
        let v180: f64 = v175 - v179;
        let v181: f64 = v30 * v26;
        let v182: f64 = v40 * v19;
        let v183: f64 = v181 - v182;
        let v184: f64 = v183 * v11;
        let v185: f64 = v178 * v15;
        let v186: f64 = v184 + v185;
        let v187: f64 = v9 * v186;
        let v188: f64 = v180 + v187;
        let v189: f64 = v178 * v11;
        let v190: f64 = v183 * v15;
        let v191: f64 = v189 - v190;
        let v192: f64 = v191 * v13;
        let v193: f64 = v1 * v192;
        let v194: f64 = v188 - v193;
        let v195: f64 = -v43;
        let v196: f64 = v15 * v26;
        let v197: f64 = v11 * v19;
        let v198: f64 = v196 - v197;
        let v199: f64 = v198 * v30;
        let v200: f64 = v15 * v19;
        let v201: f64 = v11 * v26;
        let v202: f64 = v200 + v201;
        let v203: f64 = v202 * v40;
        let v204: f64 = v199 - v203;
        let v205: f64 = v204 * v7;
        let v206: f64 = v197 - v196;
        let v207: f64 = v206 * v40;
        let v208: f64 = v202 * v30;
        let v209: f64 = v207 - v208;
        let v210: f64 = v209 * v13;
        let v211: f64 = v210 * v7;
        let v212: f64 = v3 * v43;
        let v213: f64 = v211 - v212;
        let v214: f64 = v204 * v43;
        let v215: f64 = v3 * v7;
        let v216: f64 = v210 * v43;
        let v217: f64 = v215 + v216;
        let v218: f64 = 1.0_f64;
        let v219: f64 = v198 * v40;
        let v220: f64 = v219 + v208;
        let v221: f64 = v204 * v13;
        (
            v114,
            v123,
            v124,
            v125,
            v126,
            v129,
            v159,
            v161,
            v167,
            v172,
            v194,
            v195,
            v205,
            v213,
            v214,
            v217,
            v218,
            v220,
            v221,
        )
    };
    [
        [v45, v51, v55, v64, v79, v80, v114],
        [v123, v124, v125, v126, v129, v80, v159],
        [v80, v42, v161, v167, v172, v80, v194],
        [v80, v195, v195, v195, v205, v213, v80],
        [v80, v7, v7, v7, v214, v217, v80],
        [v218, v80, v80, v80, v220, v221, v80],
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
/// Operation count: 263 floating-point operations, 10 trig calls.
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
        v5,
        v6,
        v8,
        v10,
        v13,
        v15,
        v18,
        v21,
        v24,
        v34,
        v35,
        v37,
        v39,
        v46,
        v50,
        v54,
        v58,
        v60,
        v65,
        v71,
        v72,
        v77,
        v83,
        v87,
        v96,
        v101,
        v106,
        v113,
        v119,
        v122,
        v124,
        v127,
        v130,
        v137,
        v141,
        v145,
        v146,
        v152,
    ) = {
        let v0: f64 = 0.0823_f64;
        let v1: f64 = qd[4];
        let v2: f64 = v0 * v1;
        let v3: f64 = v2 * v1;
        let v4: f64 = q[4];
        let (v21, v5): (f64, f64) = ::libm::sincos(v4);
        let v6: f64 = v3 * v5;
        let v7: f64 = 0.10915_f64;
        let v8: f64 = v0 * v5;
        let v9: f64 = v7 + v8;
        let v10: f64 = qd[0];
        let v11: f64 = v9 * v10;
        let v12: f64 = 0.1646_f64;
        let v13: f64 = qd[3];
        let v14: f64 = v12 * v13;
        let v15: f64 = qd[2];
        let v16: f64 = v12 * v15;
        let v17: f64 = v14 + v16;
        let v18: f64 = qd[1];
        let v19: f64 = v12 * v18;
        let v20: f64 = v17 + v19;
        let v22: f64 = v20 * v21;
        let v23: f64 = q[3];
        let (v24, v35): (f64, f64) = ::libm::sincos(v23);
        let v25: f64 = v22 * v24;
        let v26: f64 = 0.1893_f64;
        let v27: f64 = v26 * v13;
        let v28: f64 = v26 * v15;
        let v29: f64 = v27 + v28;
        let v30: f64 = v26 * v18;
        let v31: f64 = v29 + v30;
        let v32: f64 = v12 * v1;
        let v33: f64 = v32 * v5;
        let v34: f64 = v31 - v33;
        let v36: f64 = v34 * v35;
        let v37: f64 = v25 + v36;
        let v38: f64 = q[2];
        let (v50, v39): (f64, f64) = ::libm::sincos(v38);
        let v40: f64 = v37 * v39;
        let v41: f64 = 0.7845_f64;
        let v42: f64 = v41 * v15;
        let v43: f64 = v41 * v18;
        let v44: f64 = v42 + v43;
        let v45: f64 = v22 * v35;
        let v46: f64 = v44 + v45;
        let v47: f64 = v33 - v31;
        let v48: f64 = v47 * v24;
        let v49: f64 = v46 + v48;
        let v51: f64 = v49 * v50;
        let v52: f64 = v40 + v51;
        let v53: f64 = q[1];
        let (v65, v54): (f64, f64) = ::libm::sincos(v53);
        let v55: f64 = v52 * v54;
        let v56: f64 = v11 + v55;
        let v57: f64 = 0.85_f64;
        let v58: f64 = v57 * v18;
        let v59: f64 = v47 * v35;
        let v60: f64 = v59 - v25;
        let v61: f64 = v60 * v50;
        let v62: f64 = v58 + v61;
        let v63: f64 = v49 * v39;
        let v64: f64 = v62 + v63;
        let v66: f64 = v64 * v65;
        let v67: f64 = v56 + v66;
        let v68: f64 = v67 * v10;
        let v69: f64 = v6 + v68;
        let v70: f64 = q[0];
        let (v71, v152): (f64, f64) = ::libm::sincos(v70);
        let v72: f64 = v69 * v71;
        let v73: f64 = v32 * v10;
        let v74: f64 = v73 * v21;
        let v75: f64 = v0 * v13;
        let v76: f64 = v75 * v13;
        let v77: f64 = v3 + v76;
        let v78: f64 = v0 * v10;
        let v79: f64 = v78 * v10;
        let v80: f64 = v77 + v79;
        let v81: f64 = v0 * v15;
        let v82: f64 = v14 + v81;
        let v83: f64 = v82 * v15;
        let v84: f64 = v80 + v83;
        let v85: f64 = v0 * v18;
        let v86: f64 = v17 + v85;
        let v87: f64 = v86 * v18;
        let v88: f64 = v84 + v87;
        let v89: f64 = v88 * v21;
        let v90: f64 = v89 * v24;
        let v91: f64 = 0.09465_f64;
        let v92: f64 = v91 * v10;
        let v93: f64 = v92 * v10;
        let v94: f64 = v91 * v13;
        let v95: f64 = v94 - v33;
        let v96: f64 = v95 * v13;
        let v97: f64 = v93 + v96;
        let v98: f64 = v91 * v15;
        let v99: f64 = v27 + v98;
        let v100: f64 = v99 - v33;
        let v101: f64 = v100 * v15;
        let v102: f64 = v97 + v101;
        let v103: f64 = v91 * v18;
        let v104: f64 = v29 + v103;
        let v105: f64 = v104 - v33;
        let v106: f64 = v105 * v18;
        let v107: f64 = v102 + v106;
        let v108: f64 = v107 * v35;
        let v109: f64 = v90 + v108;
        let v110: f64 = v109 * v39;
        let v111: f64 = 0.39225_f64;
        let v112: f64 = v111 * v15;
        let v113: f64 = v112 * v15;
        let v114: f64 = v111 * v10;
        let v115: f64 = v114 * v10;
        let v116: f64 = v113 + v115;
        let v117: f64 = v111 * v18;
        let v118: f64 = v42 + v117;
        let v119: f64 = v118 * v18;
        let v120: f64 = v116 + v119;
        let v121: f64 = v89 * v35;
        let v122: f64 = v120 + v121;
        let v123: f64 = v33 - v94;
        let v124: f64 = v123 * v13;
        let v125: f64 = v124 - v93;
        let v126: f64 = v33 - v99;
        let v127: f64 = v126 * v15;
        let v128: f64 = v125 + v127;
        let v129: f64 = v33 - v104;
        let v130: f64 = v129 * v18;
        let v131: f64 = v128 + v130;
        let v132: f64 = v131 * v24;
        let v133: f64 = v122 + v132;
        let v134: f64 = v133 * v50;
        let v135: f64 = v110 + v134;
        let v136: f64 = v135 * v65;
        let v137: f64 = v74 + v136;
        let v138: f64 = v109 * v50;
        let v139: f64 = 0.425_f64;
        let v140: f64 = v139 * v18;
        let v141: f64 = v140 * v18;
        let v142: f64 = v139 * v10;
        let v143: f64 = v142 * v10;
        let v144: f64 = v141 + v143;
        let v145: f64 = v138 - v144;
        let v146: f64 = v107 * v24;
        (
            v1,
            v5,
            v6,
            v8,
            v10,
            v13,
            v15,
            v18,
            v21,
            v24,
            v34,
            v35,
            v37,
            v39,
            v46,
            v50,
            v54,
            v58,
            v60,
            v65,
            v71,
            v72,
            v77,
            v83,
            v87,
            v96,
            v101,
            v106,
            v113,
            v119,
            v122,
            v124,
            v127,
            v130,
            v137,
            v141,
            v145,
            v146,
            v152,
        )
    };
    let (v154, v175, v202, v262, v274, v293) = {
        let v147: f64 = v146 - v122;
        let v148: f64 = v147 * v39;
        let v149: f64 = v145 + v148;
        let v150: f64 = v149 * v54;
        let v151: f64 = v137 + v150;
        let v153: f64 = v151 * v152;
        let v154: f64 = v72 + v153;
        let v155: f64 = -0.10915_f64;
        let v156: f64 = v155 - v8;
        let v157: f64 = v156 * v10;
        let v158: f64 = v60 * v39;
        let v159: f64 = v34 * v24;
        let v160: f64 = v159 - v46;
        let v161: f64 = v160 * v50;
        let v162: f64 = v158 + v161;
        let v163: f64 = v162 * v54;
        let v164: f64 = v157 + v163;
        let v165: f64 = v37 * v50;
        let v166: f64 = v165 - v58;
        let v167: f64 = v160 * v39;
        let v168: f64 = v166 + v167;
        let v169: f64 = v168 * v65;
        let v170: f64 = v164 + v169;
        let v171: f64 = v170 * v10;
        let v172: f64 = v171 - v6;
        let v173: f64 = v172 * v152;
        let v174: f64 = v151 * v71;
        let v175: f64 = v173 + v174;
        let v176: f64 = v77 + v83;
        let v177: f64 = v176 + v87;
        let v178: f64 = v177 * v21;
        let v179: f64 = v178 * v24;
        let v180: f64 = v96 + v101;
        let v181: f64 = v180 + v106;
        let v182: f64 = v181 * v35;
        let v183: f64 = v179 + v182;
        let v184: f64 = v183 * v39;
        let v185: f64 = v113 + v119;
        let v186: f64 = v178 * v35;
        let v187: f64 = v185 + v186;
        let v188: f64 = v124 + v127;
        let v189: f64 = v188 + v130;
        let v190: f64 = v189 * v24;
        let v191: f64 = v187 + v190;
        let v192: f64 = v191 * v50;
        let v193: f64 = v184 + v192;
        let v194: f64 = v193 * v54;
        let v195: f64 = v189 * v35;
        let v196: f64 = v195 - v179;
        let v197: f64 = v196 * v50;
        let v198: f64 = v141 + v197;
        let v199: f64 = v191 * v39;
        let v200: f64 = v198 + v199;
        let v201: f64 = v200 * v65;
        let v202: f64 = v194 + v201;
        let v203: f64 = qd[5];
        let v204: f64 = v203 * v1;
        let v205: f64 = v204 * v21;
        let v206: f64 = v1 * v24;
        let v207: f64 = v203 * v21;
        let v208: f64 = v207 * v35;
        let v209: f64 = v206 - v208;
        let v210: f64 = v209 * v39;
        let v211: f64 = v1 * v35;
        let v212: f64 = v207 * v24;
        let v213: f64 = v211 + v212;
        let v214: f64 = v213 * v50;
        let v215: f64 = v210 + v214;
        let v216: f64 = v215 * v54;
        let v217: f64 = v213 * v39;
        let v218: f64 = v208 - v206;
        let v219: f64 = v218 * v50;
        let v220: f64 = v217 + v219;
        let v221: f64 = v220 * v65;
        let v222: f64 = v216 + v221;
        let v223: f64 = v222 * v10;
        let v224: f64 = v205 + v223;
        let v225: f64 = v224 * v71;
        let v226: f64 = v13 + v15;
        let v227: f64 = v226 + v18;
        let v228: f64 = v227 * v24;
        let v229: f64 = v228 * v50;
        let v230: f64 = v227 * v35;
        let v231: f64 = v230 * v39;
        let v232: f64 = v229 - v231;
        let v233: f64 = v232 * v54;
        let v234: f64 = v228 * v39;
        let v235: f64 = v230 * v50;
        let v236: f64 = v234 + v235;
        let v237: f64 = v236 * v65;
        let v238: f64 = v233 + v237;
        let v239: f64 = v238 * v1;
        let v240: f64 = v227 * v10;
        let v241: f64 = v239 - v240;
        let v242: f64 = v35 * v39;
        let v243: f64 = v24 * v50;
        let v244: f64 = v242 - v243;
        let v245: f64 = v244 * v54;
        let v246: f64 = v24 * v39;
        let v247: f64 = v35 * v50;
        let v248: f64 = v246 + v247;
        let v249: f64 = v248 * v65;
        let v250: f64 = v245 - v249;
        let v251: f64 = v250 * v1;
        let v252: f64 = v251 - v10;
        let v253: f64 = v252 * v5;
        let v254: f64 = v232 * v65;
        let v255: f64 = v236 * v54;
        let v256: f64 = v254 - v255;
        let v257: f64 = v256 * v21;
        let v258: f64 = v253 + v257;
        let v259: f64 = v258 * v203;
        let v260: f64 = v241 + v259;
        let v261: f64 = v260 * v152;
        let v262: f64 = v225 + v261;
        let v263: f64 = v218 * v39;
        let v264: f64 = v263 - v214;
        let v265: f64 = v264 * v54;
        let v266: f64 = v209 * v50;
        let v267: f64 = v266 - v217;
        let v268: f64 = v267 * v65;
        let v269: f64 = v265 + v268;
        let v270: f64 = v269 * v10;
        let v271: f64 = v270 - v205;
        let v272: f64 = v271 * v152;
        let v273: f64 = v260 * v71;
        let v274: f64 = v272 + v273;
        let v275: f64 = v238 * v203;
        let v276: f64 = v275 * v21;
        let v277: f64 = v203 * v5;
        let v278: f64 = v227 - v277;
        let v279: f64 = v278 * v24;
        let v280: f64 = v279 * v39;
        let v281: f64 = v278 * v35;
        let v282: f64 = v281 * v50;
        let v283: f64 = v280 + v282;
        let v284: f64 = v283 * v54;
        let v285: f64 = v281 * v39;
        let v286: f64 = v277 - v227;
        let v287: f64 = v286 * v24;
        let v288: f64 = v287 * v50;
        let v289: f64 = v285 + v288;
        let v290: f64 = v289 * v65;
        let v291: f64 = v284 + v290;
        let v292: f64 = v291 * v1;
        let v293: f64 = v276 + v292;
        (v154, v175, v202, v262, v274, v293)
    };
    [v154, v175, v202, v262, v274, v293]
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
/// Operation count: 238 floating-point operations, 10 trig calls.
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
        v0,
        v2,
        v3,
        v5,
        v6,
        v8,
        v10,
        v20,
        v25,
        v27,
        v32,
        v34,
        v39,
        v42,
        v48,
        v49,
        v51,
        v52,
        v53,
        v66,
        v67,
        v69,
        v73,
        v78,
        v87,
        v108,
        v109,
        v115,
        v116,
        v117,
        v120,
        v124,
        v127,
        v131,
        v134,
        v135,
        v136,
        v137,
        v141,
        v142,
    ) = {
        let v0: f64 = 0.00666_f64;
        let v1: f64 = q[1];
        let (v124, v2): (f64, f64) = ::libm::sincos(v1);
        let v3: f64 = 0.88490187591_f64;
        let v4: f64 = q[2];
        let (v73, v5): (f64, f64) = ::libm::sincos(v4);
        let v6: f64 = 0.191630813556_f64;
        let v7: f64 = q[3];
        let (v25, v8): (f64, f64) = ::libm::sincos(v7);
        let v9: f64 = 0.21942_f64;
        let v10: f64 = 0.0171364731454_f64;
        let v11: f64 = q[5];
        let (v12, v16): (f64, f64) = ::libm::sincos(v11);
        let v13: f64 = v10 * v12;
        let v14: f64 = v13 * v12;
        let v15: f64 = 0.033822_f64;
        let v17: f64 = v15 * v16;
        let v18: f64 = v17 * v16;
        let v19: f64 = v14 + v18;
        let v20: f64 = v9 + v19;
        let v21: f64 = 0.0121682781_f64;
        let v22: f64 = v20 + v21;
        let v23: f64 = v9 + v22;
        let v24: f64 = v8 * v23;
        let v26: f64 = q[4];
        let (v52, v27): (f64, f64) = ::libm::sincos(v26);
        let v28: f64 = v15 * v12;
        let v29: f64 = v28 * v16;
        let v30: f64 = v10 * v16;
        let v31: f64 = v30 * v12;
        let v32: f64 = v29 - v31;
        let v33: f64 = v27 * v32;
        let v34: f64 = v25 * v33;
        let v35: f64 = v24 - v34;
        let v36: f64 = v35 * v8;
        let v37: f64 = v17 * v12;
        let v38: f64 = v13 * v16;
        let v39: f64 = v37 - v38;
        let v40: f64 = v39 * v27;
        let v41: f64 = v8 * v40;
        let v42: f64 = 0.111172755531_f64;
        let v43: f64 = v30 * v16;
        let v44: f64 = v28 * v12;
        let v45: f64 = v43 + v44;
        let v46: f64 = 0.00168332516775_f64;
        let v47: f64 = v45 + v46;
        let v48: f64 = v42 + v47;
        let v49: f64 = v27 * v48;
        let v50: f64 = v49 * v27;
        let v51: f64 = 0.12999255384415_f64;
        let v53: f64 = v51 * v52;
        let v54: f64 = v53 * v52;
        let v55: f64 = v50 + v54;
        let v56: f64 = v55 + v21;
        let v57: f64 = v42 + v56;
        let v58: f64 = v25 * v57;
        let v59: f64 = v41 - v58;
        let v60: f64 = v59 * v25;
        let v61: f64 = v36 - v60;
        let v62: f64 = 0.40402113811874996_f64;
        let v63: f64 = 2.0_f64;
        let v64: f64 = 0.39225_f64;
        let v65: f64 = 0.017784735_f64;
        let v66: f64 = v65 * v25;
        let v67: f64 = v64 * v66;
        let v68: f64 = v63 * v67;
        let v69: f64 = v62 - v68;
        let v70: f64 = v61 + v69;
        let v71: f64 = v6 + v70;
        let v72: f64 = v5 * v71;
        let v74: f64 = v8 * v57;
        let v75: f64 = v25 * v40;
        let v76: f64 = v74 + v75;
        let v77: f64 = v76 * v25;
        let v78: f64 = v8 * v33;
        let v79: f64 = v25 * v23;
        let v80: f64 = v78 + v79;
        let v81: f64 = v80 * v8;
        let v82: f64 = v77 - v81;
        let v83: f64 = v65 * v8;
        let v84: f64 = v64 * v83;
        let v85: f64 = v82 - v84;
        let v86: f64 = v73 * v85;
        let v87: f64 = v72 + v86;
        let v88: f64 = v87 * v5;
        let v89: f64 = 0.004095_f64;
        let v90: f64 = v76 * v8;
        let v91: f64 = v80 * v25;
        let v92: f64 = v90 + v91;
        let v93: f64 = v92 + v69;
        let v94: f64 = v93 - v62;
        let v95: f64 = v94 + v67;
        let v96: f64 = v95 + v67;
        let v97: f64 = v89 + v96;
        let v98: f64 = v73 * v97;
        let v99: f64 = v59 * v8;
        let v100: f64 = v35 * v25;
        let v101: f64 = v99 + v100;
        let v102: f64 = v101 + v84;
        let v103: f64 = v5 * v102;
        let v104: f64 = v98 - v103;
        let v105: f64 = v104 * v73;
        let v106: f64 = v88 + v105;
        let v107: f64 = 0.9554455987809999_f64;
        let v108: f64 = -0.01566175149_f64;
        let v109: f64 = 0.425_f64;
        let v110: f64 = 0.56875_f64;
        let v111: f64 = 1.030009275_f64;
        let v112: f64 = v111 - v66;
        let v113: f64 = v110 + v112;
        let v114: f64 = v5 * v113;
        let v115: f64 = v73 * v83;
        let v116: f64 = v114 - v115;
        let v117: f64 = v109 * v116;
        let v118: f64 = v108 + v117;
        let v119: f64 = v63 * v118;
        let v120: f64 = v107 + v119;
        let v121: f64 = v106 + v120;
        let v122: f64 = v3 + v121;
        let v123: f64 = v2 * v122;
        let v125: f64 = v5 * v85;
        let v126: f64 = v73 * v71;
        let v127: f64 = v125 - v126;
        let v128: f64 = v127 * v5;
        let v129: f64 = v73 * v102;
        let v130: f64 = v5 * v97;
        let v131: f64 = v129 + v130;
        let v132: f64 = v131 * v73;
        let v133: f64 = v128 + v132;
        let v134: f64 = v5 * v83;
        let v135: f64 = v73 * v113;
        let v136: f64 = v134 + v135;
        let v137: f64 = v109 * v136;
        let v138: f64 = v133 - v137;
        let v139: f64 = v124 * v138;
        let v140: f64 = v123 + v139;
        let v141: f64 = v140 * v2;
        let v142: f64 = v104 * v5;
        (
            v0,
            v2,
            v3,
            v5,
            v6,
            v8,
            v10,
            v20,
            v25,
            v27,
            v32,
            v34,
            v39,
            v42,
            v48,
            v49,
            v51,
            v52,
            v53,
            v66,
            v67,
            v69,
            v73,
            v78,
            v87,
            v108,
            v109,
            v115,
            v116,
            v117,
            v120,
            v124,
            v127,
            v131,
            v134,
            v135,
            v136,
            v137,
            v141,
            v142,
        )
    };
    let (
        v163,
        v205,
        v217,
        v238,
        v251,
        v264,
        v270,
        v272,
        v278,
        v279,
        v280,
        v282,
        v283,
        v284,
        v285,
    ) = {
        let v143: f64 = v87 * v73;
        let v144: f64 = v142 - v143;
        let v145: f64 = v144 - v137;
        let v146: f64 = v2 * v145;
        let v147: f64 = 0.0151074_f64;
        let v148: f64 = v131 * v5;
        let v149: f64 = v127 * v73;
        let v150: f64 = v148 - v149;
        let v151: f64 = v150 + v120;
        let v152: f64 = 0.8852250624999999_f64;
        let v153: f64 = v151 - v152;
        let v154: f64 = v153 - v117;
        let v155: f64 = v154 - v117;
        let v156: f64 = v147 + v155;
        let v157: f64 = v124 * v156;
        let v158: f64 = v146 + v157;
        let v159: f64 = v158 * v124;
        let v160: f64 = v141 + v159;
        let v161: f64 = 0.12150210104175002_f64;
        let v162: f64 = v160 + v161;
        let v163: f64 = v0 + v162;
        let v164: f64 = v39 * v52;
        let v165: f64 = 0.0016539803549999999_f64;
        let v166: f64 = v164 - v165;
        let v167: f64 = v8 * v166;
        let v168: f64 = v49 * v52;
        let v169: f64 = v53 * v27;
        let v170: f64 = v168 - v169;
        let v171: f64 = v25 * v170;
        let v172: f64 = v167 - v171;
        let v173: f64 = v73 * v172;
        let v174: f64 = v8 * v170;
        let v175: f64 = v25 * v166;
        let v176: f64 = v174 + v175;
        let v177: f64 = 0.051322656825_f64;
        let v178: f64 = v176 + v177;
        let v179: f64 = v5 * v178;
        let v180: f64 = v173 + v179;
        let v181: f64 = -0.24932103525000002_f64;
        let v182: f64 = v180 + v181;
        let v183: f64 = -0.1197_f64;
        let v184: f64 = v183 * v116;
        let v185: f64 = v182 + v184;
        let v186: f64 = 0.0556077225_f64;
        let v187: f64 = v185 + v186;
        let v188: f64 = v124 * v187;
        let v189: f64 = v5 * v172;
        let v190: f64 = v73 * v178;
        let v191: f64 = v189 - v190;
        let v192: f64 = v183 * v136;
        let v193: f64 = v191 - v192;
        let v194: f64 = v2 * v193;
        let v195: f64 = v188 - v194;
        let v196: f64 = 0.13585_f64;
        let v197: f64 = 2.35004_f64;
        let v198: f64 = 2.0828824999999997_f64;
        let v199: f64 = v116 + v198;
        let v200: f64 = v197 + v199;
        let v201: f64 = v124 * v200;
        let v202: f64 = v2 * v136;
        let v203: f64 = v201 + v202;
        let v204: f64 = v196 * v203;
        let v205: f64 = v195 + v204;
        let v206: f64 = v180 + v184;
        let v207: f64 = v124 * v206;
        let v208: f64 = v135 + v134;
        let v209: f64 = v183 * v208;
        let v210: f64 = v191 - v209;
        let v211: f64 = v2 * v210;
        let v212: f64 = v207 - v211;
        let v213: f64 = v124 * v116;
        let v214: f64 = v2 * v208;
        let v215: f64 = v213 + v214;
        let v216: f64 = v196 * v215;
        let v217: f64 = v212 + v216;
        let v218: f64 = v73 * v176;
        let v219: f64 = v189 - v218;
        let v220: f64 = v73 * v66;
        let v221: f64 = v220 - v134;
        let v222: f64 = v183 * v221;
        let v223: f64 = v219 + v222;
        let v224: f64 = v2 * v223;
        let v225: f64 = v5 * v66;
        let v226: f64 = v225 + v115;
        let v227: f64 = v183 * v226;
        let v228: f64 = v5 * v176;
        let v229: f64 = v173 + v228;
        let v230: f64 = v227 - v229;
        let v231: f64 = v124 * v230;
        let v232: f64 = v224 + v231;
        let v233: f64 = v124 * v226;
        let v234: f64 = v2 * v221;
        let v235: f64 = v233 + v234;
        let v236: f64 = v196 * v235;
        let v237: f64 = v232 + v236;
        let v238: f64 = -v237;
        let v239: f64 = v8 * v20;
        let v240: f64 = v239 - v34;
        let v241: f64 = v73 * v240;
        let v242: f64 = v25 * v20;
        let v243: f64 = v78 + v242;
        let v244: f64 = v5 * v243;
        let v245: f64 = v241 + v244;
        let v246: f64 = v124 * v245;
        let v247: f64 = v5 * v240;
        let v248: f64 = v73 * v243;
        let v249: f64 = v247 - v248;
        let v250: f64 = v2 * v249;
        let v251: f64 = v246 - v250;
        let v252: f64 = v10 * v52;
        let v253: f64 = v25 * v252;
        let v254: f64 = v5 * v253;
        let v255: f64 = v8 * v252;
        let v256: f64 = v73 * v255;
        let v257: f64 = v254 + v256;
        let v258: f64 = v2 * v257;
        let v259: f64 = v5 * v255;
        let v260: f64 = v73 * v253;
        let v261: f64 = v259 - v260;
        let v262: f64 = v124 * v261;
        let v263: f64 = v258 + v262;
        let v264: f64 = -v263;
        let v265: f64 = v52 * v48;
        let v266: f64 = v265 * v52;
        let v267: f64 = v51 * v27;
        let v268: f64 = v267 * v27;
        let v269: f64 = v266 + v268;
        let v270: f64 = v42 + v269;
        let v271: f64 = v270 + v69;
        let v272: f64 = v6 + v271;
        let v273: f64 = v272 + v120;
        let v274: f64 = 0.070220536281_f64;
        let v275: f64 = v273 - v274;
        let v276: f64 = v275 - v108;
        let v277: f64 = v276 - v108;
        let v278: f64 = v3 + v277;
        let v279: f64 = v272 + v117;
        let v280: f64 = v270 - v67;
        let v281: f64 = v109 * v226;
        let v282: f64 = v280 - v281;
        let v283: f64 = v52 * v32;
        let v284: f64 = v10 * v27;
        let v285: f64 = 0.0_f64;
        (
            v163,
            v205,
            v217,
            v238,
            v251,
            v264,
            v270,
            v272,
            v278,
            v279,
            v280,
            v282,
            v283,
            v284,
            v285,
        )
    };
    [
        [v163, v205, v217, v238, v251, v264],
        [v205, v278, v279, v282, v283, v284],
        [v217, v279, v272, v280, v283, v284],
        [v238, v282, v280, v270, v283, v284],
        [v251, v283, v283, v283, v20, v285],
        [v264, v284, v284, v284, v285, v10],
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
/// Operation count: 1641 floating-point operations, 10 trig calls.
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
        v5,
        v6,
        v9,
        v11,
        v12,
        v13,
        v15,
        v18,
        v20,
        v22,
        v26,
        v27,
        v28,
        v29,
        v31,
        v32,
        v33,
        v40,
        v45,
        v51,
        v53,
        v55,
        v57,
        v58,
        v59,
        v61,
        v62,
        v64,
        v66,
        v68,
        v69,
        v76,
        v77,
        v80,
        v82,
        v84,
        v90,
        v92,
        v94,
        v97,
        v102,
        v108,
        v109,
        v110,
        v115,
        v116,
        v120,
        v122,
        v125,
        v126,
        v133,
        v136,
        v139,
        v143,
        v146,
        v148,
        v153,
        v158,
        v160,
        v161,
        v163,
        v167,
        v168,
        v169,
        v171,
        v172,
        v185,
        v188,
        v189,
    ) = {
        let v0: f64 = 0.679472691875_f64;
        let v1: f64 = 0.007558512375_f64;
        let v2: f64 = q[3];
        let (v3, v55): (f64, f64) = ::libm::sincos(v2);
        let v4: f64 = v1 * v3;
        let v5: f64 = v0 - v4;
        let v6: f64 = qd[1];
        let v7: f64 = v5 * v6;
        let v8: f64 = q[2];
        let (v9, v90): (f64, f64) = ::libm::sincos(v8);
        let v10: f64 = v7 * v9;
        let v11: f64 = 0.0166855268546_f64;
        let v12: f64 = qd[4];
        let v13: f64 = v11 * v12;
        let v14: f64 = q[5];
        let (v32, v15): (f64, f64) = ::libm::sincos(v14);
        let v16: f64 = v13 * v15;
        let v17: f64 = q[4];
        let (v18, v29): (f64, f64) = ::libm::sincos(v17);
        let v19: f64 = v16 * v18;
        let v20: f64 = qd[3];
        let v21: f64 = v11 * v20;
        let v22: f64 = qd[2];
        let v23: f64 = v11 * v22;
        let v24: f64 = v21 + v23;
        let v25: f64 = v11 * v6;
        let v26: f64 = v24 + v25;
        let v27: f64 = qd[5];
        let v28: f64 = v11 * v27;
        let v30: f64 = v28 * v29;
        let v31: f64 = v26 + v30;
        let v33: f64 = v31 * v32;
        let v34: f64 = v19 + v33;
        let v35: f64 = v34 * v15;
        let v36: f64 = v13 * v18;
        let v37: f64 = v35 - v36;
        let v38: f64 = v37 * v29;
        let v39: f64 = v10 + v38;
        let v40: f64 = 0.0333710537092_f64;
        let v41: f64 = v40 * v20;
        let v42: f64 = v40 * v22;
        let v43: f64 = v41 + v42;
        let v44: f64 = v40 * v6;
        let v45: f64 = v43 + v44;
        let v46: f64 = v45 + v30;
        let v47: f64 = v46 * v32;
        let v48: f64 = v19 + v47;
        let v49: f64 = v48 * v15;
        let v50: f64 = v36 - v49;
        let v51: f64 = v50 * v29;
        let v52: f64 = v28 * v15;
        let v53: f64 = v52 * v32;
        let v54: f64 = v51 - v53;
        let v56: f64 = v54 * v55;
        let v57: f64 = 0.00697606230375_f64;
        let v58: f64 = v57 * v20;
        let v59: f64 = v57 * v22;
        let v60: f64 = v58 + v59;
        let v61: f64 = v57 * v6;
        let v62: f64 = v60 + v61;
        let v63: f64 = v56 - v62;
        let v64: f64 = v13 * v32;
        let v65: f64 = v64 * v18;
        let v66: f64 = v26 * v15;
        let v67: f64 = v65 - v66;
        let v68: f64 = v67 * v15;
        let v69: f64 = 0.21481116377025_f64;
        let v70: f64 = v69 * v20;
        let v71: f64 = v69 * v22;
        let v72: f64 = v70 + v71;
        let v73: f64 = v69 * v6;
        let v74: f64 = v72 + v73;
        let v75: f64 = v68 - v74;
        let v76: f64 = v40 * v15;
        let v77: f64 = v76 * v15;
        let v78: f64 = v11 - v77;
        let v79: f64 = v78 * v27;
        let v80: f64 = v66 * v15;
        let v81: f64 = v26 - v80;
        let v82: f64 = v81 * v29;
        let v83: f64 = v79 + v82;
        let v84: f64 = v83 * v29;
        let v85: f64 = v75 + v84;
        let v86: f64 = v85 * v3;
        let v87: f64 = v63 + v86;
        let v88: f64 = v87 * v55;
        let v89: f64 = v39 + v88;
        let v91: f64 = v54 * v90;
        let v92: f64 = 0.3767457879045_f64;
        let v93: f64 = v92 * v22;
        let v94: f64 = v93 - v70;
        let v95: f64 = v92 * v6;
        let v96: f64 = v94 + v95;
        let v97: f64 = 0.0139521246075_f64;
        let v98: f64 = v97 * v22;
        let v99: f64 = v58 + v98;
        let v100: f64 = v97 * v6;
        let v101: f64 = v99 + v100;
        let v102: f64 = v101 * v3;
        let v103: f64 = v96 - v102;
        let v104: f64 = v103 + v68;
        let v105: f64 = v104 + v84;
        let v106: f64 = v105 * v9;
        let v107: f64 = v91 + v106;
        let v108: f64 = v1 * v6;
        let v109: f64 = 0.4296223275405_f64;
        let v110: f64 = v109 * v20;
        let v111: f64 = v109 * v22;
        let v112: f64 = v110 + v111;
        let v113: f64 = v109 * v6;
        let v114: f64 = v112 + v113;
        let v115: f64 = v45 * v15;
        let v116: f64 = v40 * v12;
        let v117: f64 = v116 * v32;
        let v118: f64 = v117 * v18;
        let v119: f64 = v115 - v118;
        let v120: f64 = v119 * v15;
        let v121: f64 = v114 + v120;
        let v122: f64 = v121 * v55;
        let v123: f64 = v40 * v27;
        let v124: f64 = v123 * v15;
        let v125: f64 = v124 * v32;
        let v126: f64 = v125 * v3;
        let v127: f64 = v122 - v126;
        let v128: f64 = v127 * v9;
        let v129: f64 = v108 + v128;
        let v130: f64 = v125 * v55;
        let v131: f64 = v101 + v130;
        let v132: f64 = v121 * v3;
        let v133: f64 = v131 + v132;
        let v134: f64 = v133 * v90;
        let v135: f64 = v129 + v134;
        let v136: f64 = v116 * v18;
        let v137: f64 = v136 * v3;
        let v138: f64 = v123 * v55;
        let v139: f64 = v137 - v138;
        let v140: f64 = v139 * v9;
        let v141: f64 = v136 * v55;
        let v142: f64 = v123 * v3;
        let v143: f64 = v141 + v142;
        let v144: f64 = v143 * v90;
        let v145: f64 = v140 - v144;
        let v146: f64 = v45 * v3;
        let v147: f64 = v146 * v90;
        let v148: f64 = v45 * v55;
        let v149: f64 = v148 * v9;
        let v150: f64 = v147 + v149;
        let v151: f64 = v150 * v29;
        let v152: f64 = v145 - v151;
        let v153: f64 = 0.0667421074184_f64;
        let v154: f64 = v153 * v20;
        let v155: f64 = v153 * v22;
        let v156: f64 = v154 + v155;
        let v157: f64 = v153 * v6;
        let v158: f64 = v156 + v157;
        let v159: f64 = v123 * v29;
        let v160: f64 = v158 + v159;
        let v161: f64 = v160 * v55;
        let v162: f64 = v161 * v90;
        let v163: f64 = v160 * v3;
        let v164: f64 = v163 * v9;
        let v165: f64 = v162 - v164;
        let v166: f64 = v165 * v32;
        let v167: f64 = v153 * v27;
        let v168: f64 = v167 * v3;
        let v169: f64 = v141 + v168;
        let v170: f64 = v169 * v90;
        let v171: f64 = v167 * v55;
        let v172: f64 = v171 - v137;
        let v173: f64 = v172 * v9;
        let v174: f64 = v170 + v173;
        let v175: f64 = v174 + v151;
        let v176: f64 = v175 * v15;
        let v177: f64 = v166 + v176;
        let v178: f64 = v177 * v15;
        let v179: f64 = v152 + v178;
        let v180: f64 = v179 * v29;
        let v181: f64 = v135 + v180;
        let v182: f64 = v181 * v55;
        let v183: f64 = v107 + v182;
        let v184: f64 = v183 * v90;
        let v185: f64 = v89 + v184;
        let v186: f64 = v1 * v20;
        let v187: f64 = v1 * v22;
        let v188: f64 = v186 + v187;
        let v189: f64 = 0.01511702475_f64;
        (
            v0,
            v1,
            v3,
            v4,
            v5,
            v6,
            v9,
            v11,
            v12,
            v13,
            v15,
            v18,
            v20,
            v22,
            v26,
            v27,
            v28,
            v29,
            v31,
            v32,
            v33,
            v40,
            v45,
            v51,
            v53,
            v55,
            v57,
            v58,
            v59,
            v61,
            v62,
            v64,
            v66,
            v68,
            v69,
            v76,
            v77,
            v80,
            v82,
            v84,
            v90,
            v92,
            v94,
            v97,
            v102,
            v108,
            v109,
            v110,
            v115,
            v116,
            v120,
            v122,
            v125,
            v126,
            v133,
            v136,
            v139,
            v143,
            v146,
            v148,
            v153,
            v158,
            v160,
            v161,
            v163,
            v167,
            v168,
            v169,
            v171,
            v172,
            v185,
            v188,
            v189,
        )
    };
    let (
        v193,
        v194,
        v202,
        v204,
        v210,
        v242,
        v252,
        v258,
        v266,
        v267,
        v268,
        v288,
        v298,
        v325,
        v345,
        v346,
        v347,
        v352,
        v353,
        v372,
        v375,
        v376,
        v378,
        v379,
    ) = {
        let v190: f64 = v189 * v6;
        let v191: f64 = v188 + v190;
        let v192: f64 = v191 * v3;
        let v193: f64 = v0 * v22;
        let v194: f64 = 1.35894538375_f64;
        let v195: f64 = v194 * v6;
        let v196: f64 = v193 + v195;
        let v197: f64 = v192 - v196;
        let v198: f64 = v197 * v9;
        let v199: f64 = v198 - v53;
        let v200: f64 = v199 + v51;
        let v201: f64 = q[1];
        let (v210, v202): (f64, f64) = ::libm::sincos(v201);
        let v203: f64 = v200 * v202;
        let v204: f64 = 1.3782737505055_f64;
        let v205: f64 = v204 * v6;
        let v206: f64 = v94 - v205;
        let v207: f64 = v206 - v102;
        let v208: f64 = v207 + v68;
        let v209: f64 = v208 + v84;
        let v211: f64 = v209 * v210;
        let v212: f64 = v203 + v211;
        let v213: f64 = v133 * v202;
        let v214: f64 = v191 * v9;
        let v215: f64 = v214 - v126;
        let v216: f64 = v215 + v122;
        let v217: f64 = v216 * v210;
        let v218: f64 = v213 + v217;
        let v219: f64 = v139 * v210;
        let v220: f64 = v143 * v202;
        let v221: f64 = v219 - v220;
        let v222: f64 = v146 * v202;
        let v223: f64 = v148 * v210;
        let v224: f64 = v222 + v223;
        let v225: f64 = v224 * v29;
        let v226: f64 = v221 - v225;
        let v227: f64 = v161 * v202;
        let v228: f64 = v163 * v210;
        let v229: f64 = v227 - v228;
        let v230: f64 = v229 * v32;
        let v231: f64 = v169 * v202;
        let v232: f64 = v172 * v210;
        let v233: f64 = v231 + v232;
        let v234: f64 = v233 + v225;
        let v235: f64 = v234 * v15;
        let v236: f64 = v230 + v235;
        let v237: f64 = v236 * v15;
        let v238: f64 = v226 + v237;
        let v239: f64 = v238 * v29;
        let v240: f64 = v218 + v239;
        let v241: f64 = v240 * v55;
        let v242: f64 = v212 + v241;
        let v243: f64 = v116 * v15;
        let v244: f64 = v243 * v18;
        let v245: f64 = v160 * v32;
        let v246: f64 = v244 + v245;
        let v247: f64 = v246 * v15;
        let v248: f64 = v247 - v136;
        let v249: f64 = v248 * v29;
        let v250: f64 = v125 + v249;
        let v251: f64 = v250 * v90;
        let v252: f64 = 0.753491575809_f64;
        let v253: f64 = v252 * v22;
        let v254: f64 = v110 - v253;
        let v255: f64 = v252 * v6;
        let v256: f64 = v254 - v255;
        let v257: f64 = v97 * v20;
        let v258: f64 = 0.027904249215_f64;
        let v259: f64 = v258 * v22;
        let v260: f64 = v257 + v259;
        let v261: f64 = v258 * v6;
        let v262: f64 = v260 + v261;
        let v263: f64 = v262 * v3;
        let v264: f64 = v256 + v263;
        let v265: f64 = v264 + v120;
        let v266: f64 = -0.0333710537092_f64;
        let v267: f64 = v153 * v15;
        let v268: f64 = v267 * v15;
        let v269: f64 = v266 + v268;
        let v270: f64 = v269 * v27;
        let v271: f64 = v115 * v15;
        let v272: f64 = v271 - v45;
        let v273: f64 = v272 * v29;
        let v274: f64 = v270 + v273;
        let v275: f64 = v274 * v29;
        let v276: f64 = v265 + v275;
        let v277: f64 = v276 * v9;
        let v278: f64 = v251 + v277;
        let v279: f64 = v278 * v202;
        let v280: f64 = v136 - v247;
        let v281: f64 = v280 * v29;
        let v282: f64 = v281 - v125;
        let v283: f64 = v282 * v9;
        let v284: f64 = v197 + v283;
        let v285: f64 = v276 * v90;
        let v286: f64 = v284 + v285;
        let v287: f64 = v286 * v210;
        let v288: f64 = v279 + v287;
        let v289: f64 = v167 * v15;
        let v290: f64 = v289 * v32;
        let v291: f64 = v290 * v3;
        let v292: f64 = v153 * v12;
        let v293: f64 = v292 * v32;
        let v294: f64 = v293 * v18;
        let v295: f64 = v158 * v15;
        let v296: f64 = v294 - v295;
        let v297: f64 = v296 * v15;
        let v298: f64 = 0.859244655081_f64;
        let v299: f64 = v298 * v20;
        let v300: f64 = v298 * v22;
        let v301: f64 = v299 + v300;
        let v302: f64 = v298 * v6;
        let v303: f64 = v301 + v302;
        let v304: f64 = v297 - v303;
        let v305: f64 = v304 * v55;
        let v306: f64 = v291 + v305;
        let v307: f64 = v306 * v90;
        let v308: f64 = v290 * v55;
        let v309: f64 = v262 + v308;
        let v310: f64 = v295 - v294;
        let v311: f64 = v310 * v15;
        let v312: f64 = v303 + v311;
        let v313: f64 = v312 * v3;
        let v314: f64 = v309 + v313;
        let v315: f64 = v314 * v9;
        let v316: f64 = v307 + v315;
        let v317: f64 = v316 * v210;
        let v318: f64 = v306 * v9;
        let v319: f64 = v318 - v191;
        let v320: f64 = v304 * v3;
        let v321: f64 = v320 - v309;
        let v322: f64 = v321 * v90;
        let v323: f64 = v319 + v322;
        let v324: f64 = v323 * v202;
        let v325: f64 = v317 + v324;
        let v326: f64 = v292 * v18;
        let v327: f64 = v326 * v55;
        let v328: f64 = v327 + v168;
        let v329: f64 = v328 * v90;
        let v330: f64 = v326 * v3;
        let v331: f64 = v171 - v330;
        let v332: f64 = v331 * v9;
        let v333: f64 = v329 + v332;
        let v334: f64 = v333 * v202;
        let v335: f64 = v331 * v90;
        let v336: f64 = v328 * v9;
        let v337: f64 = v335 - v336;
        let v338: f64 = v337 * v210;
        let v339: f64 = v334 + v338;
        let v340: f64 = v158 * v3;
        let v341: f64 = v340 * v90;
        let v342: f64 = v158 * v55;
        let v343: f64 = v342 * v9;
        let v344: f64 = v341 + v343;
        let v345: f64 = v344 * v202;
        let v346: f64 = v342 * v90;
        let v347: f64 = v340 * v9;
        let v348: f64 = v346 - v347;
        let v349: f64 = v348 * v210;
        let v350: f64 = v345 + v349;
        let v351: f64 = v350 * v29;
        let v352: f64 = v339 + v351;
        let v353: f64 = 0.1334842148368_f64;
        let v354: f64 = v353 * v20;
        let v355: f64 = v353 * v22;
        let v356: f64 = v354 + v355;
        let v357: f64 = v353 * v6;
        let v358: f64 = v356 + v357;
        let v359: f64 = v167 * v29;
        let v360: f64 = v358 + v359;
        let v361: f64 = v360 * v3;
        let v362: f64 = v361 * v9;
        let v363: f64 = v360 * v55;
        let v364: f64 = v363 * v90;
        let v365: f64 = v362 - v364;
        let v366: f64 = v365 * v202;
        let v367: f64 = v361 * v90;
        let v368: f64 = v363 * v9;
        let v369: f64 = v367 + v368;
        let v370: f64 = v369 * v210;
        let v371: f64 = v366 + v370;
        let v372: f64 = v371 * v32;
        let v373: f64 = v353 * v27;
        let v374: f64 = v373 * v55;
        let v375: f64 = v330 - v374;
        let v376: f64 = v375 * v9;
        let v377: f64 = v373 * v3;
        let v378: f64 = v327 + v377;
        let v379: f64 = v378 * v90;
        (
            v193,
            v194,
            v202,
            v204,
            v210,
            v242,
            v252,
            v258,
            v266,
            v267,
            v268,
            v288,
            v298,
            v325,
            v345,
            v346,
            v347,
            v352,
            v353,
            v372,
            v375,
            v376,
            v378,
            v379,
        )
    };
    let (
        v403,
        v404,
        v406,
        v407,
        v409,
        v411,
        v412,
        v415,
        v416,
        v417,
        v419,
        v420,
        v423,
        v426,
        v428,
        v430,
        v431,
        v432,
        v435,
        v439,
        v440,
        v442,
        v444,
        v446,
        v448,
        v454,
        v456,
        v458,
        v465,
        v471,
        v472,
        v474,
        v475,
        v486,
        v487,
        v489,
        v491,
        v493,
        v495,
        v497,
        v501,
        v502,
        v514,
        v516,
        v517,
        v525,
        v532,
        v533,
        v536,
        v544,
        v547,
        v551,
        v553,
        v560,
        v565,
        v566,
        v567,
        v569,
    ) = {
        let v380: f64 = v376 - v379;
        let v381: f64 = v380 * v202;
        let v382: f64 = v375 * v90;
        let v383: f64 = v378 * v9;
        let v384: f64 = v382 + v383;
        let v385: f64 = v384 * v210;
        let v386: f64 = v381 + v385;
        let v387: f64 = v347 - v346;
        let v388: f64 = v387 * v210;
        let v389: f64 = v388 - v345;
        let v390: f64 = v389 * v29;
        let v391: f64 = v386 + v390;
        let v392: f64 = v391 * v15;
        let v393: f64 = v372 + v392;
        let v394: f64 = v393 * v15;
        let v395: f64 = v352 + v394;
        let v396: f64 = v395 * v29;
        let v397: f64 = v325 + v396;
        let v398: f64 = v397 * v55;
        let v399: f64 = v288 + v398;
        let v400: f64 = v399 * v90;
        let v401: f64 = v242 + v400;
        let v402: f64 = v401 * v202;
        let v403: f64 = v185 + v402;
        let v404: f64 = v11 * v15;
        let v405: f64 = v404 * v32;
        let v406: f64 = v405 * v29;
        let v407: f64 = v5 * v9;
        let v408: f64 = v406 + v407;
        let v409: f64 = -0.00697606230375_f64;
        let v410: f64 = v76 * v32;
        let v411: f64 = v410 * v29;
        let v412: f64 = v411 * v55;
        let v413: f64 = v409 - v412;
        let v414: f64 = -0.21481116377025_f64;
        let v415: f64 = v404 * v15;
        let v416: f64 = v414 - v415;
        let v417: f64 = v11 - v415;
        let v418: f64 = v417 * v29;
        let v419: f64 = v418 * v29;
        let v420: f64 = v416 + v419;
        let v421: f64 = v420 * v3;
        let v422: f64 = v413 + v421;
        let v423: f64 = v422 * v55;
        let v424: f64 = v408 + v423;
        let v425: f64 = v92 - v415;
        let v426: f64 = v97 * v3;
        let v427: f64 = v425 - v426;
        let v428: f64 = v427 + v419;
        let v429: f64 = v428 * v9;
        let v430: f64 = v411 * v90;
        let v431: f64 = v429 - v430;
        let v432: f64 = v109 + v77;
        let v433: f64 = v266 + v77;
        let v434: f64 = v433 * v29;
        let v435: f64 = v434 * v29;
        let v436: f64 = v432 + v435;
        let v437: f64 = v436 * v55;
        let v438: f64 = v267 * v32;
        let v439: f64 = v438 * v29;
        let v440: f64 = v439 * v3;
        let v441: f64 = v437 - v440;
        let v442: f64 = v441 * v9;
        let v443: f64 = v1 + v442;
        let v444: f64 = v439 * v55;
        let v445: f64 = v97 + v444;
        let v446: f64 = v436 * v3;
        let v447: f64 = v445 + v446;
        let v448: f64 = v447 * v90;
        let v449: f64 = v443 + v448;
        let v450: f64 = v449 * v55;
        let v451: f64 = v431 + v450;
        let v452: f64 = v451 * v90;
        let v453: f64 = v424 + v452;
        let v454: f64 = qd[0];
        let v455: f64 = v453 * v454;
        let v456: f64 = 0.1099354731454_f64;
        let v457: f64 = v456 + v415;
        let v458: f64 = v457 + v419;
        let v459: f64 = v458 * v12;
        let v460: f64 = 0.00194120382525_f64;
        let v461: f64 = v460 * v20;
        let v462: f64 = v460 * v22;
        let v463: f64 = v461 + v462;
        let v464: f64 = v460 * v6;
        let v465: f64 = v463 + v464;
        let v466: f64 = v459 - v465;
        let v467: f64 = v466 * v55;
        let v468: f64 = v467 * v90;
        let v469: f64 = -0.1099354731454_f64;
        let v470: f64 = v469 - v415;
        let v471: f64 = -0.0166855268546_f64;
        let v472: f64 = v471 + v415;
        let v473: f64 = v472 * v29;
        let v474: f64 = v473 * v29;
        let v475: f64 = v470 + v474;
        let v476: f64 = v475 * v12;
        let v477: f64 = v465 + v476;
        let v478: f64 = v477 * v3;
        let v479: f64 = 0.07714261911625_f64;
        let v480: f64 = v479 * v22;
        let v481: f64 = v479 * v6;
        let v482: f64 = v480 + v481;
        let v483: f64 = v478 - v482;
        let v484: f64 = v483 * v9;
        let v485: f64 = v468 + v484;
        let v486: f64 = 0.0002254731454_f64;
        let v487: f64 = v486 * v3;
        let v488: f64 = v487 * v90;
        let v489: f64 = v486 * v55;
        let v490: f64 = v489 * v9;
        let v491: f64 = v488 + v490;
        let v492: f64 = v491 * v27;
        let v493: f64 = v26 * v3;
        let v494: f64 = v493 * v90;
        let v495: f64 = v26 * v55;
        let v496: f64 = v495 * v9;
        let v497: f64 = v494 + v496;
        let v498: f64 = v497 * v29;
        let v499: f64 = v492 - v498;
        let v500: f64 = v33 * v55;
        let v501: f64 = v26 * v29;
        let v502: f64 = v28 + v501;
        let v503: f64 = v502 * v15;
        let v504: f64 = v503 * v3;
        let v505: f64 = v500 + v504;
        let v506: f64 = v505 * v90;
        let v507: f64 = v503 * v55;
        let v508: f64 = v33 * v3;
        let v509: f64 = v507 - v508;
        let v510: f64 = v509 * v9;
        let v511: f64 = v506 + v510;
        let v512: f64 = v511 * v15;
        let v513: f64 = v499 + v512;
        let v514: f64 = v513 * v18;
        let v515: f64 = v485 + v514;
        let v516: f64 = v515 * v210;
        let v517: f64 = v455 + v516;
        let v518: f64 = 0.408499208875_f64;
        let v519: f64 = v518 * v6;
        let v520: f64 = -1.3782737505055_f64;
        let v521: f64 = v520 - v415;
        let v522: f64 = v521 - v426;
        let v523: f64 = v522 + v419;
        let v524: f64 = v523 * v210;
        let v525: f64 = v411 * v202;
        let v526: f64 = v524 - v525;
        let v527: f64 = v526 * v454;
        let v528: f64 = v519 + v527;
        let v529: f64 = v189 * v454;
        let v530: f64 = v529 * v202;
        let v531: f64 = v486 + v415;
        let v532: f64 = v531 * v27;
        let v533: f64 = v80 - v26;
        let v534: f64 = v533 * v29;
        let v535: f64 = v532 + v534;
        let v536: f64 = v535 * v18;
        let v537: f64 = v530 + v536;
        let v538: f64 = v537 * v3;
        let v539: f64 = v194 * v454;
        let v540: f64 = v539 * v202;
        let v541: f64 = v538 - v540;
        let v542: f64 = v541 * v9;
        let v543: f64 = v528 + v542;
        let v544: f64 = v441 * v210;
        let v545: f64 = v447 * v202;
        let v546: f64 = v544 + v545;
        let v547: f64 = v546 * v454;
        let v548: f64 = v529 * v210;
        let v549: f64 = v548 - v465;
        let v550: f64 = v11 * v29;
        let v551: f64 = v550 * v29;
        let v552: f64 = v456 + v551;
        let v553: f64 = v552 * v12;
        let v554: f64 = v549 + v553;
        let v555: f64 = v11 - v551;
        let v556: f64 = v555 * v12;
        let v557: f64 = v556 * v15;
        let v558: f64 = v33 * v18;
        let v559: f64 = v557 + v558;
        let v560: f64 = v559 * v15;
        let v561: f64 = v554 + v560;
        let v562: f64 = v561 * v9;
        let v563: f64 = v547 + v562;
        let v564: f64 = v563 * v55;
        let v565: f64 = v543 + v564;
        let v566: f64 = v466 * v3;
        let v567: f64 = v482 + v566;
        let v568: f64 = v31 * v15;
        let v569: f64 = v568 * v32;
        (
            v403,
            v404,
            v406,
            v407,
            v409,
            v411,
            v412,
            v415,
            v416,
            v417,
            v419,
            v420,
            v423,
            v426,
            v428,
            v430,
            v431,
            v432,
            v435,
            v439,
            v440,
            v442,
            v444,
            v446,
            v448,
            v454,
            v456,
            v458,
            v465,
            v471,
            v472,
            v474,
            v475,
            v486,
            v487,
            v489,
            v491,
            v493,
            v495,
            v497,
            v501,
            v502,
            v514,
            v516,
            v517,
            v525,
            v532,
            v533,
            v536,
            v544,
            v547,
            v551,
            v553,
            v560,
            v565,
            v566,
            v567,
            v569,
        )
    };
    let (
        v579,
        v582,
        v589,
        v591,
        v597,
        v600,
        v617,
        v619,
        v629,
        v641,
        v671,
        v676,
        v688,
        v689,
        v717,
        v732,
        v745,
        v749,
        v751,
        v759,
    ) = {
        let v570: f64 = v569 * v3;
        let v571: f64 = -0.0002254731454_f64;
        let v572: f64 = v571 - v415;
        let v573: f64 = v572 * v27;
        let v574: f64 = v573 + v82;
        let v575: f64 = v574 * v55;
        let v576: f64 = v570 + v575;
        let v577: f64 = v576 * v18;
        let v578: f64 = v567 + v577;
        let v579: f64 = v439 * v90;
        let v580: f64 = -0.753491575809_f64;
        let v581: f64 = v580 + v77;
        let v582: f64 = v258 * v3;
        let v583: f64 = v581 + v582;
        let v584: f64 = v583 + v435;
        let v585: f64 = v584 * v9;
        let v586: f64 = v579 + v585;
        let v587: f64 = v586 * v202;
        let v588: f64 = -1.35894538375_f64;
        let v589: f64 = v189 * v3;
        let v590: f64 = v588 + v589;
        let v591: f64 = v439 * v9;
        let v592: f64 = v590 - v591;
        let v593: f64 = v584 * v90;
        let v594: f64 = v592 + v593;
        let v595: f64 = v594 * v210;
        let v596: f64 = v587 + v595;
        let v597: f64 = v353 * v15;
        let v598: f64 = v597 * v32;
        let v599: f64 = v598 * v29;
        let v600: f64 = v599 * v3;
        let v601: f64 = -0.859244655081_f64;
        let v602: f64 = v601 - v268;
        let v603: f64 = v153 - v268;
        let v604: f64 = v603 * v29;
        let v605: f64 = v604 * v29;
        let v606: f64 = v602 + v605;
        let v607: f64 = v606 * v55;
        let v608: f64 = v600 + v607;
        let v609: f64 = v608 * v90;
        let v610: f64 = v599 * v55;
        let v611: f64 = v258 + v610;
        let v612: f64 = v298 + v268;
        let v613: f64 = -0.0667421074184_f64;
        let v614: f64 = v613 + v268;
        let v615: f64 = v614 * v29;
        let v616: f64 = v615 * v29;
        let v617: f64 = v612 + v616;
        let v618: f64 = v617 * v3;
        let v619: f64 = v611 + v618;
        let v620: f64 = v619 * v9;
        let v621: f64 = v609 + v620;
        let v622: f64 = v621 * v210;
        let v623: f64 = -0.01511702475_f64;
        let v624: f64 = v608 * v9;
        let v625: f64 = v623 + v624;
        let v626: f64 = -0.027904249215_f64;
        let v627: f64 = v626 - v610;
        let v628: f64 = v606 * v3;
        let v629: f64 = v627 + v628;
        let v630: f64 = v629 * v90;
        let v631: f64 = v625 + v630;
        let v632: f64 = v631 * v202;
        let v633: f64 = v622 + v632;
        let v634: f64 = v633 * v55;
        let v635: f64 = v596 + v634;
        let v636: f64 = v635 * v454;
        let v637: f64 = v578 + v636;
        let v638: f64 = v637 * v90;
        let v639: f64 = v565 + v638;
        let v640: f64 = v639 * v202;
        let v641: f64 = v517 + v640;
        let v642: f64 = v406 + v423;
        let v643: f64 = v442 + v448;
        let v644: f64 = v643 * v55;
        let v645: f64 = v431 + v644;
        let v646: f64 = v645 * v90;
        let v647: f64 = v642 + v646;
        let v648: f64 = v647 * v454;
        let v649: f64 = v648 + v516;
        let v650: f64 = v428 * v210;
        let v651: f64 = v650 - v525;
        let v652: f64 = v651 * v454;
        let v653: f64 = v1 * v454;
        let v654: f64 = v653 * v202;
        let v655: f64 = v654 + v536;
        let v656: f64 = v655 * v3;
        let v657: f64 = v0 * v454;
        let v658: f64 = v657 * v202;
        let v659: f64 = v656 - v658;
        let v660: f64 = v659 * v9;
        let v661: f64 = v652 + v660;
        let v662: f64 = v653 * v210;
        let v663: f64 = v662 - v465;
        let v664: f64 = v663 + v553;
        let v665: f64 = v664 + v560;
        let v666: f64 = v665 * v9;
        let v667: f64 = v547 + v666;
        let v668: f64 = v667 * v55;
        let v669: f64 = v661 + v668;
        let v670: f64 = -0.679472691875_f64;
        let v671: f64 = v670 + v4;
        let v672: f64 = v671 - v591;
        let v673: f64 = v672 + v593;
        let v674: f64 = v673 * v210;
        let v675: f64 = v587 + v674;
        let v676: f64 = -0.007558512375_f64;
        let v677: f64 = v676 + v624;
        let v678: f64 = v677 + v630;
        let v679: f64 = v678 * v202;
        let v680: f64 = v622 + v679;
        let v681: f64 = v680 * v55;
        let v682: f64 = v675 + v681;
        let v683: f64 = v682 * v454;
        let v684: f64 = v578 + v683;
        let v685: f64 = v684 * v90;
        let v686: f64 = v669 + v685;
        let v687: f64 = v686 * v202;
        let v688: f64 = v649 + v687;
        let v689: f64 = v57 * v3;
        let v690: f64 = v416 - v689;
        let v691: f64 = v690 + v419;
        let v692: f64 = v691 * v9;
        let v693: f64 = v692 - v430;
        let v694: f64 = v57 + v444;
        let v695: f64 = v694 + v446;
        let v696: f64 = v695 * v90;
        let v697: f64 = v442 + v696;
        let v698: f64 = v697 * v55;
        let v699: f64 = v693 + v698;
        let v700: f64 = v699 * v90;
        let v701: f64 = v642 + v700;
        let v702: f64 = v701 * v454;
        let v703: f64 = v465 * v3;
        let v704: f64 = v703 * v9;
        let v705: f64 = v465 * v55;
        let v706: f64 = v705 * v90;
        let v707: f64 = v704 - v706;
        let v708: f64 = v458 * v55;
        let v709: f64 = v708 * v90;
        let v710: f64 = v475 * v3;
        let v711: f64 = v710 * v9;
        let v712: f64 = v709 + v711;
        let v713: f64 = v712 * v12;
        let v714: f64 = v707 + v713;
        let v715: f64 = v714 + v514;
        let v716: f64 = v715 * v210;
        let v717: f64 = v702 + v716;
        let v718: f64 = v420 * v210;
        let v719: f64 = v718 - v525;
        let v720: f64 = v719 * v454;
        let v721: f64 = v655 * v9;
        let v722: f64 = v57 * v454;
        let v723: f64 = v722 * v210;
        let v724: f64 = v721 - v723;
        let v725: f64 = v724 * v3;
        let v726: f64 = v720 + v725;
        let v727: f64 = v695 * v202;
        let v728: f64 = v544 + v727;
        let v729: f64 = v728 * v454;
        let v730: f64 = v729 + v666;
        let v731: f64 = v730 * v55;
        let v732: f64 = v726 + v731;
        let v733: f64 = v566 + v577;
        let v734: f64 = v432 + v426;
        let v735: f64 = v734 + v435;
        let v736: f64 = v735 * v9;
        let v737: f64 = v579 + v736;
        let v738: f64 = v737 * v202;
        let v739: f64 = v4 - v591;
        let v740: f64 = v735 * v90;
        let v741: f64 = v739 + v740;
        let v742: f64 = v741 * v210;
        let v743: f64 = v738 + v742;
        let v744: f64 = v97 + v610;
        let v745: f64 = v744 + v618;
        let v746: f64 = v745 * v9;
        let v747: f64 = v609 + v746;
        let v748: f64 = v747 * v210;
        let v749: f64 = -0.0139521246075_f64;
        let v750: f64 = v749 - v610;
        let v751: f64 = v750 + v628;
        let v752: f64 = v751 * v90;
        let v753: f64 = v677 + v752;
        let v754: f64 = v753 * v202;
        let v755: f64 = v748 + v754;
        let v756: f64 = v755 * v55;
        let v757: f64 = v743 + v756;
        let v758: f64 = v757 * v454;
        let v759: f64 = v733 + v758;
        (
            v579,
            v582,
            v589,
            v591,
            v597,
            v600,
            v617,
            v619,
            v629,
            v641,
            v671,
            v676,
            v688,
            v689,
            v717,
            v732,
            v745,
            v749,
            v751,
            v759,
        )
    };
    let (
        v763,
        v783,
        v793,
        v794,
        v795,
        v796,
        v797,
        v798,
        v799,
        v803,
        v804,
        v810,
        v811,
        v814,
        v816,
        v833,
        v841,
        v855,
        v860,
        v861,
        v863,
        v865,
        v866,
        v867,
        v868,
        v870,
        v875,
        v880,
        v881,
        v882,
        v883,
        v884,
        v888,
        v890,
        v892,
        v895,
        v907,
        v913,
        v914,
        v916,
        v920,
        v922,
        v934,
        v948,
        v949,
    ) = {
        let v760: f64 = v759 * v90;
        let v761: f64 = v732 + v760;
        let v762: f64 = v761 * v202;
        let v763: f64 = v717 + v762;
        let v764: f64 = v456 * v20;
        let v765: f64 = v456 * v22;
        let v766: f64 = v764 + v765;
        let v767: f64 = v456 * v6;
        let v768: f64 = v766 + v767;
        let v769: f64 = v768 * v3;
        let v770: f64 = v769 * v90;
        let v771: f64 = v768 * v55;
        let v772: f64 = v771 * v9;
        let v773: f64 = v770 + v772;
        let v774: f64 = v773 * v202;
        let v775: f64 = v771 * v90;
        let v776: f64 = v769 * v9;
        let v777: f64 = v775 - v776;
        let v778: f64 = v777 * v210;
        let v779: f64 = v774 + v778;
        let v780: f64 = v11 * v55;
        let v781: f64 = v780 * v55;
        let v782: f64 = v471 + v781;
        let v783: f64 = v40 * v55;
        let v784: f64 = v783 * v3;
        let v785: f64 = v784 * v9;
        let v786: f64 = v783 * v55;
        let v787: f64 = v11 - v786;
        let v788: f64 = v787 * v90;
        let v789: f64 = v785 + v788;
        let v790: f64 = v789 * v90;
        let v791: f64 = v782 + v790;
        let v792: f64 = v791 * v454;
        let v793: f64 = v792 * v18;
        let v794: f64 = 0.016911_f64;
        let v795: f64 = v794 * v3;
        let v796: f64 = v795 * v9;
        let v797: f64 = v794 * v55;
        let v798: f64 = v797 * v90;
        let v799: f64 = v796 - v798;
        let v800: f64 = v799 * v27;
        let v801: f64 = v495 * v90;
        let v802: f64 = v493 * v9;
        let v803: f64 = v801 - v802;
        let v804: f64 = v803 * v29;
        let v805: f64 = v800 + v804;
        let v806: f64 = v805 * v210;
        let v807: f64 = v793 + v806;
        let v808: f64 = v11 * v454;
        let v809: f64 = v808 * v18;
        let v810: f64 = v809 * v202;
        let v811: f64 = v40 * v3;
        let v812: f64 = v811 * v210;
        let v813: f64 = v783 * v202;
        let v814: f64 = v812 - v813;
        let v815: f64 = v814 * v454;
        let v816: f64 = v815 * v18;
        let v817: f64 = v794 * v27;
        let v818: f64 = v501 - v817;
        let v819: f64 = v818 * v9;
        let v820: f64 = v816 + v819;
        let v821: f64 = v820 * v55;
        let v822: f64 = v810 + v821;
        let v823: f64 = v153 * v55;
        let v824: f64 = v823 * v55;
        let v825: f64 = v266 + v824;
        let v826: f64 = v825 * v90;
        let v827: f64 = v826 * v202;
        let v828: f64 = v40 - v824;
        let v829: f64 = v828 * v9;
        let v830: f64 = v829 * v210;
        let v831: f64 = v827 + v830;
        let v832: f64 = v831 * v454;
        let v833: f64 = v832 * v18;
        let v834: f64 = v153 * v9;
        let v835: f64 = v834 * v202;
        let v836: f64 = v153 * v90;
        let v837: f64 = v836 * v210;
        let v838: f64 = v835 + v837;
        let v839: f64 = v838 * v454;
        let v840: f64 = v839 * v18;
        let v841: f64 = v840 * v55;
        let v842: f64 = v817 + v841;
        let v843: f64 = v501 - v842;
        let v844: f64 = v843 * v3;
        let v845: f64 = v833 + v844;
        let v846: f64 = v845 * v90;
        let v847: f64 = v822 + v846;
        let v848: f64 = v847 * v202;
        let v849: f64 = v807 + v848;
        let v850: f64 = v849 * v29;
        let v851: f64 = v779 + v850;
        let v852: f64 = v780 * v90;
        let v853: f64 = v11 * v3;
        let v854: f64 = v853 * v9;
        let v855: f64 = v852 - v854;
        let v856: f64 = v855 * v202;
        let v857: f64 = v853 * v90;
        let v858: f64 = v780 * v9;
        let v859: f64 = v857 + v858;
        let v860: f64 = v859 * v210;
        let v861: f64 = v856 - v860;
        let v862: f64 = v861 * v27;
        let v863: f64 = v854 - v852;
        let v864: f64 = v863 * v210;
        let v865: f64 = v859 * v202;
        let v866: f64 = v864 - v865;
        let v867: f64 = v866 * v12;
        let v868: f64 = v780 * v3;
        let v869: f64 = v787 * v9;
        let v870: f64 = v784 * v90;
        let v871: f64 = v869 - v870;
        let v872: f64 = v871 * v90;
        let v873: f64 = v868 + v872;
        let v874: f64 = v787 * v210;
        let v875: f64 = v784 * v202;
        let v876: f64 = v874 - v875;
        let v877: f64 = v153 * v3;
        let v878: f64 = v877 * v90;
        let v879: f64 = v823 * v9;
        let v880: f64 = v878 + v879;
        let v881: f64 = v880 * v202;
        let v882: f64 = v823 * v90;
        let v883: f64 = v877 * v9;
        let v884: f64 = v882 - v883;
        let v885: f64 = v884 * v210;
        let v886: f64 = v881 + v885;
        let v887: f64 = v886 * v55;
        let v888: f64 = v40 * v9;
        let v889: f64 = v888 * v202;
        let v890: f64 = v40 * v90;
        let v891: f64 = v890 * v210;
        let v892: f64 = v889 + v891;
        let v893: f64 = v887 - v892;
        let v894: f64 = v893 * v90;
        let v895: f64 = v876 + v894;
        let v896: f64 = v895 * v202;
        let v897: f64 = v873 + v896;
        let v898: f64 = v897 * v454;
        let v899: f64 = v867 + v898;
        let v900: f64 = v899 * v18;
        let v901: f64 = v862 + v900;
        let v902: f64 = v901 * v32;
        let v903: f64 = v497 * v202;
        let v904: f64 = v803 * v210;
        let v905: f64 = v903 + v904;
        let v906: f64 = v11 - v781;
        let v907: f64 = v471 + v786;
        let v908: f64 = v907 * v90;
        let v909: f64 = v908 - v785;
        let v910: f64 = v909 * v90;
        let v911: f64 = v906 + v910;
        let v912: f64 = v911 * v454;
        let v913: f64 = v912 * v18;
        let v914: f64 = v855 * v27;
        let v915: f64 = v802 - v801;
        let v916: f64 = v915 * v29;
        let v917: f64 = v914 + v916;
        let v918: f64 = v917 * v210;
        let v919: f64 = v913 + v918;
        let v920: f64 = v813 - v812;
        let v921: f64 = v920 * v454;
        let v922: f64 = v921 * v18;
        let v923: f64 = v28 - v501;
        let v924: f64 = v923 * v9;
        let v925: f64 = v922 + v924;
        let v926: f64 = v925 * v55;
        let v927: f64 = v926 - v810;
        let v928: f64 = v828 * v90;
        let v929: f64 = v928 * v202;
        let v930: f64 = v825 * v9;
        let v931: f64 = v930 * v210;
        let v932: f64 = v929 + v931;
        let v933: f64 = v932 * v454;
        let v934: f64 = v933 * v18;
        let v935: f64 = v28 + v841;
        let v936: f64 = v935 - v501;
        let v937: f64 = v936 * v3;
        let v938: f64 = v934 + v937;
        let v939: f64 = v938 * v90;
        let v940: f64 = v927 + v939;
        let v941: f64 = v940 * v202;
        let v942: f64 = v919 + v941;
        let v943: f64 = v942 * v29;
        let v944: f64 = v905 + v943;
        let v945: f64 = v944 * v15;
        let v946: f64 = v902 + v945;
        let v947: f64 = v946 * v15;
        let v948: f64 = v851 + v947;
        let v949: f64 = v873 * v454;
        (
            v763,
            v783,
            v793,
            v794,
            v795,
            v796,
            v797,
            v798,
            v799,
            v803,
            v804,
            v810,
            v811,
            v814,
            v816,
            v833,
            v841,
            v855,
            v860,
            v861,
            v863,
            v865,
            v866,
            v867,
            v868,
            v870,
            v875,
            v880,
            v881,
            v882,
            v883,
            v884,
            v888,
            v890,
            v892,
            v895,
            v907,
            v913,
            v914,
            v916,
            v920,
            v922,
            v934,
            v948,
            v949,
        )
    };
    let (
        v957,
        v974,
        v983,
        v988,
        v997,
        v1002,
        v1003,
        v1009,
        v1012,
        v1013,
        v1017,
        v1018,
        v1025,
        v1027,
        v1028,
        v1038,
        v1039,
        v1040,
        v1041,
        v1043,
        v1045,
        v1050,
        v1055,
        v1063,
        v1064,
        v1065,
        v1073,
        v1074,
        v1080,
        v1081,
        v1082,
        v1088,
        v1090,
        v1095,
        v1096,
        v1102,
        v1106,
        v1121,
        v1122,
        v1124,
        v1126,
        v1132,
        v1133,
        v1134,
        v1137,
        v1139,
    ) = {
        let v950: f64 = v949 * v29;
        let v951: f64 = v799 * v12;
        let v952: f64 = v951 * v29;
        let v953: f64 = v486 * v20;
        let v954: f64 = v486 * v22;
        let v955: f64 = v953 + v954;
        let v956: f64 = v486 * v6;
        let v957: f64 = v955 + v956;
        let v958: f64 = v957 * v3;
        let v959: f64 = v958 * v90;
        let v960: f64 = v957 * v55;
        let v961: f64 = v960 * v9;
        let v962: f64 = v959 + v961;
        let v963: f64 = v962 * v18;
        let v964: f64 = v952 + v963;
        let v965: f64 = v964 * v210;
        let v966: f64 = v950 + v965;
        let v967: f64 = v958 * v9;
        let v968: f64 = v960 * v90;
        let v969: f64 = v967 - v968;
        let v970: f64 = v969 * v18;
        let v971: f64 = v895 * v454;
        let v972: f64 = v795 * v90;
        let v973: f64 = v797 * v9;
        let v974: f64 = v972 + v973;
        let v975: f64 = v974 * v12;
        let v976: f64 = v971 - v975;
        let v977: f64 = v976 * v29;
        let v978: f64 = v970 + v977;
        let v979: f64 = v978 * v202;
        let v980: f64 = v966 + v979;
        let v981: f64 = v11 * v32;
        let v982: f64 = v981 * v29;
        let v983: f64 = v982 * v29;
        let v984: f64 = v471 - v551;
        let v985: f64 = v984 * v32;
        let v986: f64 = v985 * v55;
        let v987: f64 = v76 * v29;
        let v988: f64 = v987 * v3;
        let v989: f64 = v986 - v988;
        let v990: f64 = v989 * v55;
        let v991: f64 = v983 + v990;
        let v992: f64 = v991 * v454;
        let v993: f64 = v66 * v55;
        let v994: f64 = v26 * v32;
        let v995: f64 = v994 * v29;
        let v996: f64 = v995 * v3;
        let v997: f64 = v993 - v996;
        let v998: f64 = v997 * v18;
        let v999: f64 = v981 * v55;
        let v1000: f64 = v404 * v29;
        let v1001: f64 = v1000 * v3;
        let v1002: f64 = v999 + v1001;
        let v1003: f64 = v1002 * v12;
        let v1004: f64 = v998 - v1003;
        let v1005: f64 = v1004 * v9;
        let v1006: f64 = v1005 * v210;
        let v1007: f64 = v992 + v1006;
        let v1008: f64 = v985 * v90;
        let v1009: f64 = v987 * v9;
        let v1010: f64 = v1008 - v1009;
        let v1011: f64 = v1010 * v454;
        let v1012: f64 = v66 * v18;
        let v1013: f64 = v1012 - v64;
        let v1014: f64 = v1013 * v3;
        let v1015: f64 = v1014 * v210;
        let v1016: f64 = v1011 + v1015;
        let v1017: f64 = v783 * v90;
        let v1018: f64 = v811 * v9;
        let v1019: f64 = v1017 - v1018;
        let v1020: f64 = v1019 * v454;
        let v1021: f64 = v1020 * v32;
        let v1022: f64 = v13 * v210;
        let v1023: f64 = v880 * v454;
        let v1024: f64 = v1022 + v1023;
        let v1025: f64 = v1024 * v15;
        let v1026: f64 = v1020 * v29;
        let v1027: f64 = v26 * v18;
        let v1028: f64 = v1027 * v210;
        let v1029: f64 = v1026 + v1028;
        let v1030: f64 = v1029 * v32;
        let v1031: f64 = v1025 + v1030;
        let v1032: f64 = v1031 * v29;
        let v1033: f64 = v1021 + v1032;
        let v1034: f64 = v1033 * v55;
        let v1035: f64 = v1016 + v1034;
        let v1036: f64 = v1035 * v90;
        let v1037: f64 = v1007 + v1036;
        let v1038: f64 = v1002 * v90;
        let v1039: f64 = v1000 * v55;
        let v1040: f64 = v981 * v3;
        let v1041: f64 = v1039 - v1040;
        let v1042: f64 = v1041 * v9;
        let v1043: f64 = v1038 + v1042;
        let v1044: f64 = v1043 * v12;
        let v1045: f64 = v996 - v993;
        let v1046: f64 = v1045 * v90;
        let v1047: f64 = v995 * v55;
        let v1048: f64 = v66 * v3;
        let v1049: f64 = v1047 + v1048;
        let v1050: f64 = v1049 * v9;
        let v1051: f64 = v1046 + v1050;
        let v1052: f64 = v1051 * v18;
        let v1053: f64 = v1044 + v1052;
        let v1054: f64 = v985 * v202;
        let v1055: f64 = v987 * v210;
        let v1056: f64 = v1054 - v1055;
        let v1057: f64 = v920 * v32;
        let v1058: f64 = v40 * v32;
        let v1059: f64 = v1058 * v29;
        let v1060: f64 = v1059 * v55;
        let v1061: f64 = v267 * v3;
        let v1062: f64 = v1060 + v1061;
        let v1063: f64 = v1062 * v202;
        let v1064: f64 = v267 * v55;
        let v1065: f64 = v1059 * v3;
        let v1066: f64 = v1064 - v1065;
        let v1067: f64 = v1066 * v210;
        let v1068: f64 = v1063 + v1067;
        let v1069: f64 = v1068 * v29;
        let v1070: f64 = v1057 + v1069;
        let v1071: f64 = v1070 * v55;
        let v1072: f64 = v1056 + v1071;
        let v1073: f64 = v890 * v202;
        let v1074: f64 = v888 * v210;
        let v1075: f64 = v1073 - v1074;
        let v1076: f64 = v1075 * v32;
        let v1077: f64 = v1059 * v90;
        let v1078: f64 = v267 * v9;
        let v1079: f64 = v1077 + v1078;
        let v1080: f64 = v1079 * v202;
        let v1081: f64 = v267 * v90;
        let v1082: f64 = v1059 * v9;
        let v1083: f64 = v1081 - v1082;
        let v1084: f64 = v1083 * v210;
        let v1085: f64 = v1080 + v1084;
        let v1086: f64 = v1085 * v29;
        let v1087: f64 = v1076 + v1086;
        let v1088: f64 = v883 - v882;
        let v1089: f64 = v1088 * v202;
        let v1090: f64 = v880 * v210;
        let v1091: f64 = v1089 + v1090;
        let v1092: f64 = v1091 * v32;
        let v1093: f64 = v153 * v32;
        let v1094: f64 = v1093 * v29;
        let v1095: f64 = v1094 * v3;
        let v1096: f64 = v597 * v55;
        let v1097: f64 = v1095 - v1096;
        let v1098: f64 = v1097 * v9;
        let v1099: f64 = v1094 * v55;
        let v1100: f64 = v597 * v3;
        let v1101: f64 = v1099 + v1100;
        let v1102: f64 = v1101 * v90;
        let v1103: f64 = v1098 - v1102;
        let v1104: f64 = v1103 * v202;
        let v1105: f64 = v1097 * v90;
        let v1106: f64 = v1101 * v9;
        let v1107: f64 = v1105 + v1106;
        let v1108: f64 = v1107 * v210;
        let v1109: f64 = v1104 + v1108;
        let v1110: f64 = v1109 * v29;
        let v1111: f64 = v1092 + v1110;
        let v1112: f64 = v1111 * v55;
        let v1113: f64 = v1087 + v1112;
        let v1114: f64 = v1113 * v90;
        let v1115: f64 = v1072 + v1114;
        let v1116: f64 = v1115 * v454;
        let v1117: f64 = v1053 + v1116;
        let v1118: f64 = v1117 * v202;
        let v1119: f64 = v1037 + v1118;
        let v1120: f64 = v1119 * v15;
        let v1121: f64 = v980 + v1120;
        let v1122: f64 = 0.126621_f64;
        let v1123: f64 = v1122 * v3;
        let v1124: f64 = v1123 * v9;
        let v1125: f64 = v1122 * v55;
        let v1126: f64 = v1125 * v90;
        let v1127: f64 = v1124 - v1126;
        let v1128: f64 = v1127 * v210;
        let v1129: f64 = v1123 * v90;
        let v1130: f64 = v1125 * v9;
        let v1131: f64 = v1129 + v1130;
        let v1132: f64 = v1131 * v202;
        let v1133: f64 = v1128 - v1132;
        let v1134: f64 = v1133 * v12;
        let v1135: f64 = v794 - v415;
        let v1136: f64 = v1135 * v55;
        let v1137: f64 = v1136 * v90;
        let v1138: f64 = -0.016911_f64;
        let v1139: f64 = v1138 + v415;
        (
            v957,
            v974,
            v983,
            v988,
            v997,
            v1002,
            v1003,
            v1009,
            v1012,
            v1013,
            v1017,
            v1018,
            v1025,
            v1027,
            v1028,
            v1038,
            v1039,
            v1040,
            v1041,
            v1043,
            v1045,
            v1050,
            v1055,
            v1063,
            v1064,
            v1065,
            v1073,
            v1074,
            v1080,
            v1081,
            v1082,
            v1088,
            v1090,
            v1095,
            v1096,
            v1102,
            v1106,
            v1121,
            v1122,
            v1124,
            v1126,
            v1132,
            v1133,
            v1134,
            v1137,
            v1139,
        )
    };
    let (
        v1181,
        v1185,
        v1189,
        v1194,
        v1196,
        v1198,
        v1201,
        v1203,
        v1205,
        v1208,
        v1210,
        v1225,
        v1238,
        v1240,
        v1246,
        v1249,
        v1250,
        v1252,
        v1263,
        v1268,
        v1269,
        v1277,
        v1288,
        v1293,
        v1298,
        v1301,
        v1304,
        v1307,
        v1313,
        v1316,
        v1319,
        v1324,
        v1329,
    ) = {
        let v1140: f64 = v1139 * v3;
        let v1141: f64 = v1140 * v9;
        let v1142: f64 = v1137 + v1141;
        let v1143: f64 = v1142 * v202;
        let v1144: f64 = v1140 * v90;
        let v1145: f64 = v1139 * v55;
        let v1146: f64 = v1145 * v9;
        let v1147: f64 = v1144 + v1146;
        let v1148: f64 = v1147 * v210;
        let v1149: f64 = v1143 + v1148;
        let v1150: f64 = v1149 * v27;
        let v1151: f64 = v1150 * v18;
        let v1152: f64 = v1134 + v1151;
        let v1153: f64 = v855 * v210;
        let v1154: f64 = v865 + v1153;
        let v1155: f64 = v1154 * v12;
        let v1156: f64 = v1155 * v29;
        let v1157: f64 = v867 * v15;
        let v1158: f64 = v1157 * v29;
        let v1159: f64 = v28 * v18;
        let v1160: f64 = v1159 * v3;
        let v1161: f64 = v13 * v55;
        let v1162: f64 = v1160 - v1161;
        let v1163: f64 = v1162 * v90;
        let v1164: f64 = v1159 * v55;
        let v1165: f64 = v13 * v3;
        let v1166: f64 = v1164 + v1165;
        let v1167: f64 = v1166 * v9;
        let v1168: f64 = v1163 + v1167;
        let v1169: f64 = v1168 * v202;
        let v1170: f64 = v1166 * v90;
        let v1171: f64 = v1161 - v1160;
        let v1172: f64 = v1171 * v9;
        let v1173: f64 = v1170 + v1172;
        let v1174: f64 = v1173 * v210;
        let v1175: f64 = v1169 + v1174;
        let v1176: f64 = v1175 * v32;
        let v1177: f64 = v1158 + v1176;
        let v1178: f64 = v1177 * v15;
        let v1179: f64 = v1156 + v1178;
        let v1180: f64 = v1179 * v29;
        let v1181: f64 = v1152 + v1180;
        let v1182: f64 = v671 * v9;
        let v1183: f64 = v1182 - v406;
        let v1184: f64 = v57 + v412;
        let v1185: f64 = v69 + v415;
        let v1186: f64 = v1185 + v474;
        let v1187: f64 = v1186 * v3;
        let v1188: f64 = v1184 + v1187;
        let v1189: f64 = v1188 * v55;
        let v1190: f64 = v1183 + v1189;
        let v1191: f64 = -0.3767457879045_f64;
        let v1192: f64 = v1191 + v415;
        let v1193: f64 = v1192 + v426;
        let v1194: f64 = v1193 + v474;
        let v1195: f64 = v1194 * v9;
        let v1196: f64 = v430 + v1195;
        let v1197: f64 = -0.4296223275405_f64;
        let v1198: f64 = v1197 - v77;
        let v1199: f64 = v40 - v77;
        let v1200: f64 = v1199 * v29;
        let v1201: f64 = v1200 * v29;
        let v1202: f64 = v1198 + v1201;
        let v1203: f64 = v1202 * v55;
        let v1204: f64 = v440 + v1203;
        let v1205: f64 = v1204 * v9;
        let v1206: f64 = v676 + v1205;
        let v1207: f64 = v749 - v444;
        let v1208: f64 = v1202 * v3;
        let v1209: f64 = v1207 + v1208;
        let v1210: f64 = v1209 * v90;
        let v1211: f64 = v1206 + v1210;
        let v1212: f64 = v1211 * v55;
        let v1213: f64 = v1196 + v1212;
        let v1214: f64 = v1213 * v90;
        let v1215: f64 = v1190 + v1214;
        let v1216: f64 = v194 - v589;
        let v1217: f64 = v1216 * v9;
        let v1218: f64 = v411 + v1217;
        let v1219: f64 = v1218 * v202;
        let v1220: f64 = v204 + v415;
        let v1221: f64 = v1220 + v426;
        let v1222: f64 = v1221 + v474;
        let v1223: f64 = v1222 * v210;
        let v1224: f64 = v1219 + v1223;
        let v1225: f64 = v1209 * v202;
        let v1226: f64 = v189 * v9;
        let v1227: f64 = v440 - v1226;
        let v1228: f64 = v1227 + v1203;
        let v1229: f64 = v1228 * v210;
        let v1230: f64 = v1225 + v1229;
        let v1231: f64 = v1230 * v55;
        let v1232: f64 = v1224 + v1231;
        let v1233: f64 = v252 - v77;
        let v1234: f64 = v1233 - v582;
        let v1235: f64 = v1234 + v1201;
        let v1236: f64 = v1235 * v9;
        let v1237: f64 = v1236 - v579;
        let v1238: f64 = v1237 * v202;
        let v1239: f64 = v1216 + v591;
        let v1240: f64 = v1235 * v90;
        let v1241: f64 = v1239 + v1240;
        let v1242: f64 = v1241 * v210;
        let v1243: f64 = v1238 + v1242;
        let v1244: f64 = v617 * v55;
        let v1245: f64 = v1244 - v600;
        let v1246: f64 = v1245 * v90;
        let v1247: f64 = v629 * v9;
        let v1248: f64 = v1246 + v1247;
        let v1249: f64 = v1248 * v210;
        let v1250: f64 = v1245 * v9;
        let v1251: f64 = v189 + v1250;
        let v1252: f64 = v619 * v90;
        let v1253: f64 = v1251 + v1252;
        let v1254: f64 = v1253 * v202;
        let v1255: f64 = v1249 + v1254;
        let v1256: f64 = v1255 * v55;
        let v1257: f64 = v1243 + v1256;
        let v1258: f64 = v1257 * v90;
        let v1259: f64 = v1232 + v1258;
        let v1260: f64 = v1259 * v202;
        let v1261: f64 = v1215 + v1260;
        let v1262: f64 = v1261 * v454;
        let v1263: f64 = v1181 + v1262;
        let v1264: f64 = v417 * v12;
        let v1265: f64 = v1264 * v18;
        let v1266: f64 = v53 * v29;
        let v1267: f64 = v1265 - v1266;
        let v1268: f64 = v1267 * v29;
        let v1269: f64 = v53 + v1268;
        let v1270: f64 = v188 * v90;
        let v1271: f64 = v58 + v1270;
        let v1272: f64 = v1271 * v55;
        let v1273: f64 = v1269 - v1272;
        let v1274: f64 = v188 * v3;
        let v1275: f64 = v1274 - v193;
        let v1276: f64 = v1275 * v9;
        let v1277: f64 = v1273 + v1276;
        let v1278: f64 = v188 + v108;
        let v1279: f64 = v1278 * v90;
        let v1280: f64 = v58 + v1279;
        let v1281: f64 = v1280 * v55;
        let v1282: f64 = v1269 - v1281;
        let v1283: f64 = v1278 * v3;
        let v1284: f64 = v0 * v6;
        let v1285: f64 = v193 + v1284;
        let v1286: f64 = v1283 - v1285;
        let v1287: f64 = v1286 * v9;
        let v1288: f64 = v1282 + v1287;
        let v1289: f64 = v1283 * v9;
        let v1290: f64 = v1269 + v1289;
        let v1291: f64 = v62 + v1279;
        let v1292: f64 = v1291 * v55;
        let v1293: f64 = v1290 - v1292;
        let v1294: f64 = v1139 * v27;
        let v1295: f64 = v1294 * v18;
        let v1296: f64 = v1133 * v454;
        let v1297: f64 = v1295 + v1296;
        let v1298: f64 = v1154 * v454;
        let v1299: f64 = v1298 * v29;
        let v1300: f64 = v1027 + v1299;
        let v1301: f64 = v64 - v1012;
        let v1302: f64 = v1040 - v1039;
        let v1303: f64 = v1302 * v9;
        let v1304: f64 = v1303 - v1038;
        let v1305: f64 = v1304 * v202;
        let v1306: f64 = v1302 * v90;
        let v1307: f64 = v1002 * v9;
        let v1308: f64 = v1306 + v1307;
        let v1309: f64 = v1308 * v210;
        let v1310: f64 = v1305 + v1309;
        let v1311: f64 = v1310 * v454;
        let v1312: f64 = v1301 + v1311;
        let v1313: f64 = v1312 * v15;
        let v1314: f64 = v1300 + v1313;
        let v1315: f64 = v1314 * v29;
        let v1316: f64 = v1297 + v1315;
        let v1317: f64 = v798 - v796;
        let v1318: f64 = v1317 * v202;
        let v1319: f64 = v974 * v210;
        let v1320: f64 = v1318 - v1319;
        let v1321: f64 = v1320 * v454;
        let v1322: f64 = v794 * v12;
        let v1323: f64 = v1321 - v1322;
        let v1324: f64 = v1323 * v18;
        let v1325: f64 = v863 * v202;
        let v1326: f64 = v1325 + v860;
        let v1327: f64 = v1326 * v454;
        let v1328: f64 = v13 + v1327;
        let v1329: f64 = v1328 * v15;
        (
            v1181,
            v1185,
            v1189,
            v1194,
            v1196,
            v1198,
            v1201,
            v1203,
            v1205,
            v1208,
            v1210,
            v1225,
            v1238,
            v1240,
            v1246,
            v1249,
            v1250,
            v1252,
            v1263,
            v1268,
            v1269,
            v1277,
            v1288,
            v1293,
            v1298,
            v1301,
            v1304,
            v1307,
            v1313,
            v1316,
            v1319,
            v1324,
            v1329,
        )
    };
    let (
        v1338,
        v1371,
        v1379,
        v1380,
        v1382,
        v1428,
        v1438,
        v1442,
        v1447,
        v1478,
        v1485,
        v1486,
        v1487,
        v1488,
        v1506,
        v1510,
        v1513,
        v1517,
        v1519,
    ) = {
        let v1330: f64 = v1329 * v18;
        let v1331: f64 = v1298 * v18;
        let v1332: f64 = v1331 - v501;
        let v1333: f64 = v1332 * v29;
        let v1334: f64 = v26 + v1333;
        let v1335: f64 = v1334 * v32;
        let v1336: f64 = v1330 + v1335;
        let v1337: f64 = v1336 * v15;
        let v1338: f64 = v1324 + v1337;
        let v1339: f64 = v1189 - v406;
        let v1340: f64 = v1205 + v1210;
        let v1341: f64 = v1340 * v55;
        let v1342: f64 = v1196 + v1341;
        let v1343: f64 = v1342 * v90;
        let v1344: f64 = v1339 + v1343;
        let v1345: f64 = v411 + v407;
        let v1346: f64 = v1345 * v202;
        let v1347: f64 = v1194 * v210;
        let v1348: f64 = v1346 + v1347;
        let v1349: f64 = v1 * v9;
        let v1350: f64 = v440 - v1349;
        let v1351: f64 = v1350 + v1203;
        let v1352: f64 = v1351 * v210;
        let v1353: f64 = v1225 + v1352;
        let v1354: f64 = v1353 * v55;
        let v1355: f64 = v1348 + v1354;
        let v1356: f64 = v5 + v591;
        let v1357: f64 = v1356 + v1240;
        let v1358: f64 = v1357 * v210;
        let v1359: f64 = v1238 + v1358;
        let v1360: f64 = v1 + v1250;
        let v1361: f64 = v1360 + v1252;
        let v1362: f64 = v1361 * v202;
        let v1363: f64 = v1249 + v1362;
        let v1364: f64 = v1363 * v55;
        let v1365: f64 = v1359 + v1364;
        let v1366: f64 = v1365 * v90;
        let v1367: f64 = v1355 + v1366;
        let v1368: f64 = v1367 * v202;
        let v1369: f64 = v1344 + v1368;
        let v1370: f64 = v1369 * v454;
        let v1371: f64 = v1181 + v1370;
        let v1372: f64 = v58 * v55;
        let v1373: f64 = v53 - v1372;
        let v1374: f64 = v1 * v55;
        let v1375: f64 = v1374 * v90;
        let v1376: f64 = v1375 + v407;
        let v1377: f64 = v1376 * v6;
        let v1378: f64 = v1373 + v1377;
        let v1379: f64 = v1378 + v1268;
        let v1380: f64 = v1373 + v1268;
        let v1381: f64 = v62 * v55;
        let v1382: f64 = v1269 - v1381;
        let v1383: f64 = v1185 + v689;
        let v1384: f64 = v1383 + v474;
        let v1385: f64 = v1384 * v9;
        let v1386: f64 = v430 + v1385;
        let v1387: f64 = v409 - v444;
        let v1388: f64 = v1387 + v1208;
        let v1389: f64 = v1388 * v90;
        let v1390: f64 = v1205 + v1389;
        let v1391: f64 = v1390 * v55;
        let v1392: f64 = v1386 + v1391;
        let v1393: f64 = v1392 * v90;
        let v1394: f64 = v1339 + v1393;
        let v1395: f64 = v4 * v9;
        let v1396: f64 = v411 - v1395;
        let v1397: f64 = v1396 * v202;
        let v1398: f64 = v1384 * v210;
        let v1399: f64 = v1397 + v1398;
        let v1400: f64 = v1388 * v202;
        let v1401: f64 = v1400 + v1352;
        let v1402: f64 = v1401 * v55;
        let v1403: f64 = v1399 + v1402;
        let v1404: f64 = v1198 - v426;
        let v1405: f64 = v1404 + v1201;
        let v1406: f64 = v1405 * v9;
        let v1407: f64 = v1406 - v579;
        let v1408: f64 = v1407 * v202;
        let v1409: f64 = v591 - v4;
        let v1410: f64 = v1405 * v90;
        let v1411: f64 = v1409 + v1410;
        let v1412: f64 = v1411 * v210;
        let v1413: f64 = v1408 + v1412;
        let v1414: f64 = v751 * v9;
        let v1415: f64 = v1246 + v1414;
        let v1416: f64 = v1415 * v210;
        let v1417: f64 = v745 * v90;
        let v1418: f64 = v1360 + v1417;
        let v1419: f64 = v1418 * v202;
        let v1420: f64 = v1416 + v1419;
        let v1421: f64 = v1420 * v55;
        let v1422: f64 = v1413 + v1421;
        let v1423: f64 = v1422 * v90;
        let v1424: f64 = v1403 + v1423;
        let v1425: f64 = v1424 * v202;
        let v1426: f64 = v1394 + v1425;
        let v1427: f64 = v1426 * v454;
        let v1428: f64 = v1181 + v1427;
        let v1429: f64 = v108 * v3;
        let v1430: f64 = v1429 * v9;
        let v1431: f64 = v53 - v1430;
        let v1432: f64 = v1431 + v1268;
        let v1433: f64 = v1 * v90;
        let v1434: f64 = v57 + v1433;
        let v1435: f64 = v1434 * v6;
        let v1436: f64 = v59 + v1435;
        let v1437: f64 = v1436 * v55;
        let v1438: f64 = v1432 + v1437;
        let v1439: f64 = v59 + v61;
        let v1440: f64 = v1439 * v55;
        let v1441: f64 = v53 + v1440;
        let v1442: f64 = v1441 + v1268;
        let v1443: f64 = v907 * v9;
        let v1444: f64 = v870 + v1443;
        let v1445: f64 = v1444 * v90;
        let v1446: f64 = v1445 - v868;
        let v1447: f64 = v1446 * v454;
        let v1448: f64 = v1447 * v15;
        let v1449: f64 = v1448 * v32;
        let v1450: f64 = v1449 * v18;
        let v1451: f64 = v1122 * v20;
        let v1452: f64 = v1122 * v22;
        let v1453: f64 = v1451 + v1452;
        let v1454: f64 = v1122 * v6;
        let v1455: f64 = v1453 + v1454;
        let v1456: f64 = v1455 * v55;
        let v1457: f64 = v53 * v3;
        let v1458: f64 = v1456 - v1457;
        let v1459: f64 = v1458 * v90;
        let v1460: f64 = v53 * v55;
        let v1461: f64 = v1455 * v3;
        let v1462: f64 = v1460 + v1461;
        let v1463: f64 = v1462 * v9;
        let v1464: f64 = v1459 - v1463;
        let v1465: f64 = v1464 * v210;
        let v1466: f64 = v1450 + v1465;
        let v1467: f64 = v1461 * v90;
        let v1468: f64 = v1456 * v9;
        let v1469: f64 = v1467 + v1468;
        let v1470: f64 = v907 * v210;
        let v1471: f64 = v875 + v1470;
        let v1472: f64 = v1088 * v210;
        let v1473: f64 = v1472 - v881;
        let v1474: f64 = v1473 * v55;
        let v1475: f64 = v892 + v1474;
        let v1476: f64 = v1475 * v90;
        let v1477: f64 = v1471 + v1476;
        let v1478: f64 = v1477 * v454;
        let v1479: f64 = v1478 * v18;
        let v1480: f64 = v914 + v1479;
        let v1481: f64 = v1480 * v15;
        let v1482: f64 = v1481 * v32;
        let v1483: f64 = v1469 + v1482;
        let v1484: f64 = v1483 * v202;
        let v1485: f64 = v1466 + v1484;
        let v1486: f64 = v489 * v90;
        let v1487: f64 = v487 * v9;
        let v1488: f64 = v1486 - v1487;
        let v1489: f64 = v1488 * v27;
        let v1490: f64 = v1489 + v916;
        let v1491: f64 = v1490 * v210;
        let v1492: f64 = v913 + v1491;
        let v1493: f64 = v486 * v27;
        let v1494: f64 = v1493 - v501;
        let v1495: f64 = v1494 * v9;
        let v1496: f64 = v922 + v1495;
        let v1497: f64 = v1496 * v55;
        let v1498: f64 = v1497 - v810;
        let v1499: f64 = v1493 + v841;
        let v1500: f64 = v1499 - v501;
        let v1501: f64 = v1500 * v3;
        let v1502: f64 = v934 + v1501;
        let v1503: f64 = v1502 * v90;
        let v1504: f64 = v1498 + v1503;
        let v1505: f64 = v1504 * v202;
        let v1506: f64 = v1492 + v1505;
        let v1507: f64 = v803 * v202;
        let v1508: f64 = v497 * v210;
        let v1509: f64 = v1507 - v1508;
        let v1510: f64 = v1509 * v32;
        let v1511: f64 = v914 + v804;
        let v1512: f64 = v1511 * v210;
        let v1513: f64 = v793 + v1512;
        let v1514: f64 = v502 * v9;
        let v1515: f64 = v816 + v1514;
        let v1516: f64 = v1515 * v55;
        let v1517: f64 = v810 + v1516;
        let v1518: f64 = v28 - v841;
        let v1519: f64 = v1518 + v501;
        (
            v1338,
            v1371,
            v1379,
            v1380,
            v1382,
            v1428,
            v1438,
            v1442,
            v1447,
            v1478,
            v1485,
            v1486,
            v1487,
            v1488,
            v1506,
            v1510,
            v1513,
            v1517,
            v1519,
        )
    };
    let (v1531, v1558, v1559, v1575, v1679, v1698, v1704, v1705) = {
        let v1520: f64 = v1519 * v3;
        let v1521: f64 = v833 + v1520;
        let v1522: f64 = v1521 * v90;
        let v1523: f64 = v1517 + v1522;
        let v1524: f64 = v1523 * v202;
        let v1525: f64 = v1513 + v1524;
        let v1526: f64 = v1525 * v15;
        let v1527: f64 = v1510 + v1526;
        let v1528: f64 = v1527 * v15;
        let v1529: f64 = v1506 + v1528;
        let v1530: f64 = v1529 * v29;
        let v1531: f64 = v1485 + v1530;
        let v1532: f64 = v532 * v18;
        let v1533: f64 = v1126 - v1124;
        let v1534: f64 = v1533 * v210;
        let v1535: f64 = v1132 + v1534;
        let v1536: f64 = v1535 * v454;
        let v1537: f64 = v1532 + v1536;
        let v1538: f64 = v533 * v18;
        let v1539: f64 = v861 * v15;
        let v1540: f64 = v1539 * v32;
        let v1541: f64 = v472 * v3;
        let v1542: f64 = v1541 * v90;
        let v1543: f64 = v472 * v55;
        let v1544: f64 = v1543 * v9;
        let v1545: f64 = v1542 + v1544;
        let v1546: f64 = v1545 * v202;
        let v1547: f64 = v1543 * v90;
        let v1548: f64 = v417 * v3;
        let v1549: f64 = v1548 * v9;
        let v1550: f64 = v1547 + v1549;
        let v1551: f64 = v1550 * v210;
        let v1552: f64 = v1546 + v1551;
        let v1553: f64 = v1552 * v29;
        let v1554: f64 = v1540 + v1553;
        let v1555: f64 = v1554 * v454;
        let v1556: f64 = v1538 + v1555;
        let v1557: f64 = v1556 * v29;
        let v1558: f64 = v1537 + v1557;
        let v1559: f64 = -v53;
        let v1560: f64 = v957 * v18;
        let v1561: f64 = v491 * v202;
        let v1562: f64 = v1488 * v210;
        let v1563: f64 = v1561 + v1562;
        let v1564: f64 = v1563 * v454;
        let v1565: f64 = v1564 * v29;
        let v1566: f64 = v1560 + v1565;
        let v1567: f64 = v1043 * v202;
        let v1568: f64 = v1041 * v90;
        let v1569: f64 = v1568 - v1307;
        let v1570: f64 = v1569 * v210;
        let v1571: f64 = v1567 + v1570;
        let v1572: f64 = v1571 * v454;
        let v1573: f64 = v1013 + v1572;
        let v1574: f64 = v1573 * v15;
        let v1575: f64 = v1566 + v1574;
        let v1576: f64 = v1447 * v29;
        let v1577: f64 = v1487 - v1486;
        let v1578: f64 = v1577 * v12;
        let v1579: f64 = v1578 * v29;
        let v1580: f64 = v794 * v20;
        let v1581: f64 = v794 * v22;
        let v1582: f64 = v1580 + v1581;
        let v1583: f64 = v794 * v6;
        let v1584: f64 = v1582 + v1583;
        let v1585: f64 = v1584 * v3;
        let v1586: f64 = v1585 * v90;
        let v1587: f64 = v1584 * v55;
        let v1588: f64 = v1587 * v9;
        let v1589: f64 = v1586 + v1588;
        let v1590: f64 = v1589 * v18;
        let v1591: f64 = v1579 + v1590;
        let v1592: f64 = v1591 * v210;
        let v1593: f64 = v1576 + v1592;
        let v1594: f64 = v1585 * v9;
        let v1595: f64 = v1587 * v90;
        let v1596: f64 = v1594 - v1595;
        let v1597: f64 = v1596 * v18;
        let v1598: f64 = v491 * v12;
        let v1599: f64 = v1478 - v1598;
        let v1600: f64 = v1599 * v29;
        let v1601: f64 = v1597 + v1600;
        let v1602: f64 = v1601 * v202;
        let v1603: f64 = v1593 + v1602;
        let v1604: f64 = v11 + v551;
        let v1605: f64 = v1604 * v32;
        let v1606: f64 = v1605 * v55;
        let v1607: f64 = v988 + v1606;
        let v1608: f64 = v1607 * v55;
        let v1609: f64 = v1608 - v983;
        let v1610: f64 = v1609 * v454;
        let v1611: f64 = v1045 * v18;
        let v1612: f64 = v1003 + v1611;
        let v1613: f64 = v1612 * v9;
        let v1614: f64 = v1613 * v210;
        let v1615: f64 = v1610 + v1614;
        let v1616: f64 = v1605 * v90;
        let v1617: f64 = v1009 + v1616;
        let v1618: f64 = v1617 * v454;
        let v1619: f64 = v1301 * v3;
        let v1620: f64 = v1619 * v210;
        let v1621: f64 = v1618 + v1620;
        let v1622: f64 = v1018 - v1017;
        let v1623: f64 = v1622 * v454;
        let v1624: f64 = v1623 * v32;
        let v1625: f64 = v1623 * v29;
        let v1626: f64 = v1625 - v1028;
        let v1627: f64 = v1626 * v32;
        let v1628: f64 = v1627 - v1025;
        let v1629: f64 = v1628 * v29;
        let v1630: f64 = v1624 + v1629;
        let v1631: f64 = v1630 * v55;
        let v1632: f64 = v1621 + v1631;
        let v1633: f64 = v1632 * v90;
        let v1634: f64 = v1615 + v1633;
        let v1635: f64 = v1304 * v12;
        let v1636: f64 = v997 * v90;
        let v1637: f64 = v1636 - v1050;
        let v1638: f64 = v1637 * v18;
        let v1639: f64 = v1635 + v1638;
        let v1640: f64 = v1605 * v202;
        let v1641: f64 = v1055 + v1640;
        let v1642: f64 = v814 * v32;
        let v1643: f64 = v1065 - v1064;
        let v1644: f64 = v1643 * v210;
        let v1645: f64 = v1644 - v1063;
        let v1646: f64 = v1645 * v29;
        let v1647: f64 = v1642 + v1646;
        let v1648: f64 = v1647 * v55;
        let v1649: f64 = v1641 + v1648;
        let v1650: f64 = v1074 - v1073;
        let v1651: f64 = v1650 * v32;
        let v1652: f64 = v1082 - v1081;
        let v1653: f64 = v1652 * v210;
        let v1654: f64 = v1653 - v1080;
        let v1655: f64 = v1654 * v29;
        let v1656: f64 = v1651 + v1655;
        let v1657: f64 = v884 * v202;
        let v1658: f64 = v1657 - v1090;
        let v1659: f64 = v1658 * v32;
        let v1660: f64 = v1096 - v1095;
        let v1661: f64 = v1660 * v9;
        let v1662: f64 = v1102 + v1661;
        let v1663: f64 = v1662 * v202;
        let v1664: f64 = v1660 * v90;
        let v1665: f64 = v1664 - v1106;
        let v1666: f64 = v1665 * v210;
        let v1667: f64 = v1663 + v1666;
        let v1668: f64 = v1667 * v29;
        let v1669: f64 = v1659 + v1668;
        let v1670: f64 = v1669 * v55;
        let v1671: f64 = v1656 + v1670;
        let v1672: f64 = v1671 * v90;
        let v1673: f64 = v1649 + v1672;
        let v1674: f64 = v1673 * v454;
        let v1675: f64 = v1639 + v1674;
        let v1676: f64 = v1675 * v202;
        let v1677: f64 = v1634 + v1676;
        let v1678: f64 = v1677 * v15;
        let v1679: f64 = v1603 + v1678;
        let v1680: f64 = v799 * v202;
        let v1681: f64 = v1680 + v1319;
        let v1682: f64 = v1681 * v454;
        let v1683: f64 = v486 * v12;
        let v1684: f64 = v1682 - v1683;
        let v1685: f64 = v1684 * v18;
        let v1686: f64 = v861 * v454;
        let v1687: f64 = v1686 - v13;
        let v1688: f64 = v1687 * v15;
        let v1689: f64 = v1688 * v18;
        let v1690: f64 = v866 * v454;
        let v1691: f64 = v1690 * v18;
        let v1692: f64 = v501 + v1691;
        let v1693: f64 = v1692 * v29;
        let v1694: f64 = v1693 - v26;
        let v1695: f64 = v1694 * v32;
        let v1696: f64 = v1689 + v1695;
        let v1697: f64 = v1696 * v15;
        let v1698: f64 = v1685 + v1697;
        let v1699: f64 = v1577 * v210;
        let v1700: f64 = v1699 - v1561;
        let v1701: f64 = v1700 * v454;
        let v1702: f64 = v1701 * v29;
        let v1703: f64 = v1702 - v1560;
        let v1704: f64 = v1703 + v1313;
        let v1705: f64 = 0.0_f64;
        (v1531, v1558, v1559, v1575, v1679, v1698, v1704, v1705)
    };
    [
        [v403, v641, v688, v763, v948, v1121],
        [v1263, v1277, v1288, v1293, v1316, v1338],
        [v1371, v1379, v1380, v1382, v1316, v1338],
        [v1428, v1438, v1442, v1269, v1316, v1338],
        [v1531, v1558, v1558, v1558, v1559, v1575],
        [v1679, v1698, v1698, v1698, v1704, v1705],
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
/// Operation count: 393 floating-point operations, 10 trig calls.
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
        v2,
        v3,
        v5,
        v6,
        v7,
        v9,
        v11,
        v12,
        v16,
        v17,
        v18,
        v20,
        v21,
        v25,
        v27,
        v28,
        v30,
        v31,
        v36,
        v39,
        v41,
        v42,
        v44,
        v45,
        v49,
        v50,
        v52,
        v56,
        v57,
        v61,
        v62,
        v65,
        v67,
        v69,
        v70,
        v72,
        v77,
        v82,
        v85,
        v87,
        v88,
        v89,
        v91,
        v94,
        v96,
        v98,
        v100,
        v103,
        v104,
        v106,
        v109,
        v111,
        v112,
        v113,
        v114,
        v121,
        v123,
        v125,
        v130,
        v132,
        v133,
        v137,
        v138,
        v139,
        v141,
        v144,
    ) = {
        let v0: f64 = q[1];
        let (v3, v1): (f64, f64) = ::libm::sincos(v0);
        let v2: f64 = 0.88490187591_f64;
        let v4: f64 = qd[0];
        let v5: f64 = v3 * v4;
        let v6: f64 = qd[1];
        let v7: f64 = v5 * v6;
        let v8: f64 = v2 * v7;
        let v9: f64 = v2 * v6;
        let v10: f64 = v5 * v9;
        let v11: f64 = 0.0151074_f64;
        let v12: f64 = v11 * v5;
        let v13: f64 = v6 * v12;
        let v14: f64 = v10 - v13;
        let v15: f64 = v8 + v14;
        let v16: f64 = 2.35004_f64;
        let v17: f64 = 0.13585_f64;
        let v18: f64 = v17 * v5;
        let v19: f64 = v5 * v18;
        let v20: f64 = v1 * v4;
        let v21: f64 = v17 * v20;
        let v22: f64 = v20 * v21;
        let v23: f64 = v19 + v22;
        let v24: f64 = v16 * v23;
        let v25: f64 = v15 + v24;
        let v26: f64 = q[2];
        let (v30, v27): (f64, f64) = ::libm::sincos(v26);
        let v28: f64 = 0.191630813556_f64;
        let v29: f64 = v27 * v7;
        let v31: f64 = v20 * v6;
        let v32: f64 = v30 * v31;
        let v33: f64 = v29 + v32;
        let v34: f64 = v30 * v20;
        let v35: f64 = v27 * v5;
        let v36: f64 = v34 + v35;
        let v37: f64 = qd[2];
        let v38: f64 = v36 * v37;
        let v39: f64 = v33 + v38;
        let v40: f64 = v28 * v39;
        let v41: f64 = v6 + v37;
        let v42: f64 = v28 * v41;
        let v43: f64 = v36 * v42;
        let v44: f64 = 0.004095_f64;
        let v45: f64 = v44 * v36;
        let v46: f64 = v41 * v45;
        let v47: f64 = v43 - v46;
        let v48: f64 = v40 + v47;
        let v49: f64 = 0.56875_f64;
        let v50: f64 = 0.425_f64;
        let v51: f64 = v50 * v7;
        let v52: f64 = v50 * v6;
        let v53: f64 = v5 * v52;
        let v54: f64 = v51 + v53;
        let v55: f64 = v23 + v54;
        let v56: f64 = -0.1197_f64;
        let v57: f64 = v56 * v36;
        let v58: f64 = v36 * v57;
        let v59: f64 = v30 * v5;
        let v60: f64 = v27 * v20;
        let v61: f64 = v59 - v60;
        let v62: f64 = v56 * v61;
        let v63: f64 = v61 * v62;
        let v64: f64 = v58 + v63;
        let v65: f64 = v55 + v64;
        let v66: f64 = v49 * v65;
        let v67: f64 = v48 + v66;
        let v68: f64 = q[3];
        let (v72, v69): (f64, f64) = ::libm::sincos(v68);
        let v70: f64 = 0.21942_f64;
        let v71: f64 = v69 * v39;
        let v73: f64 = v30 * v7;
        let v74: f64 = v27 * v31;
        let v75: f64 = v73 - v74;
        let v76: f64 = v61 * v37;
        let v77: f64 = v75 + v76;
        let v78: f64 = v72 * v77;
        let v79: f64 = v71 - v78;
        let v80: f64 = v69 * v36;
        let v81: f64 = v72 * v61;
        let v82: f64 = v80 - v81;
        let v83: f64 = qd[3];
        let v84: f64 = v82 * v83;
        let v85: f64 = v79 + v84;
        let v86: f64 = v70 * v85;
        let v87: f64 = 0.111172755531_f64;
        let v88: f64 = v41 + v83;
        let v89: f64 = v87 * v88;
        let v90: f64 = v82 * v89;
        let v91: f64 = v87 * v82;
        let v92: f64 = v88 * v91;
        let v93: f64 = v90 - v92;
        let v94: f64 = v86 + v93;
        let v95: f64 = q[4];
        let (v98, v96): (f64, f64) = ::libm::sincos(v95);
        let v97: f64 = v96 * v82;
        let v99: f64 = v98 * v88;
        let v100: f64 = v97 + v99;
        let v101: f64 = v96 * v88;
        let v102: f64 = v98 * v82;
        let v103: f64 = v101 - v102;
        let v104: f64 = v87 * v103;
        let v105: f64 = v100 * v104;
        let v106: f64 = v87 * v100;
        let v107: f64 = v103 * v106;
        let v108: f64 = v105 - v107;
        let v109: f64 = v86 + v108;
        let v110: f64 = q[5];
        let (v113, v111): (f64, f64) = ::libm::sincos(v110);
        let v112: f64 = 0.033822_f64;
        let v114: f64 = qd[4];
        let v115: f64 = v103 * v114;
        let v116: f64 = v72 * v39;
        let v117: f64 = v69 * v77;
        let v118: f64 = v116 + v117;
        let v119: f64 = v69 * v61;
        let v120: f64 = v72 * v36;
        let v121: f64 = v119 + v120;
        let v122: f64 = v121 * v83;
        let v123: f64 = v118 + v122;
        let v124: f64 = v96 * v123;
        let v125: f64 = v115 - v124;
        let v126: f64 = v113 * v125;
        let v127: f64 = v111 * v85;
        let v128: f64 = v126 + v127;
        let v129: f64 = v111 * v100;
        let v130: f64 = v121 + v114;
        let v131: f64 = v113 * v130;
        let v132: f64 = v129 - v131;
        let v133: f64 = qd[5];
        let v134: f64 = v132 * v133;
        let v135: f64 = v128 + v134;
        let v136: f64 = v112 * v135;
        let v137: f64 = 0.0171364731454_f64;
        let v138: f64 = v103 + v133;
        let v139: f64 = v137 * v138;
        let v140: f64 = v132 * v139;
        let v141: f64 = v137 * v132;
        let v142: f64 = v138 * v141;
        let v143: f64 = v140 - v142;
        let v144: f64 = v136 + v143;
        (
            v1,
            v2,
            v3,
            v5,
            v6,
            v7,
            v9,
            v11,
            v12,
            v16,
            v17,
            v18,
            v20,
            v21,
            v25,
            v27,
            v28,
            v30,
            v31,
            v36,
            v39,
            v41,
            v42,
            v44,
            v45,
            v49,
            v50,
            v52,
            v56,
            v57,
            v61,
            v62,
            v65,
            v67,
            v69,
            v70,
            v72,
            v77,
            v82,
            v85,
            v87,
            v88,
            v89,
            v91,
            v94,
            v96,
            v98,
            v100,
            v103,
            v104,
            v106,
            v109,
            v111,
            v112,
            v113,
            v114,
            v121,
            v123,
            v125,
            v130,
            v132,
            v133,
            v137,
            v138,
            v139,
            v141,
            v144,
        )
    };
    let (
        v151,
        v155,
        v162,
        v164,
        v165,
        v172,
        v179,
        v189,
        v190,
        v201,
        v208,
        v214,
        v224,
        v227,
        v236,
        v240,
        v248,
        v253,
        v255,
        v256,
        v267,
        v269,
        v271,
        v272,
        v273,
        v278,
        v280,
        v288,
        v289,
    ) = {
        let v145: f64 = v111 * v144;
        let v146: f64 = v111 * v125;
        let v147: f64 = v113 * v85;
        let v148: f64 = v146 - v147;
        let v149: f64 = v113 * v100;
        let v150: f64 = v111 * v130;
        let v151: f64 = v149 + v150;
        let v152: f64 = v151 * v133;
        let v153: f64 = v148 - v152;
        let v154: f64 = v137 * v153;
        let v155: f64 = v112 * v151;
        let v156: f64 = v138 * v155;
        let v157: f64 = v151 * v139;
        let v158: f64 = v156 - v157;
        let v159: f64 = v154 + v158;
        let v160: f64 = v113 * v159;
        let v161: f64 = v145 - v160;
        let v162: f64 = v109 + v161;
        let v163: f64 = v94 + v162;
        let v164: f64 = 0.093_f64;
        let v165: f64 = 1.219_f64;
        let v166: f64 = v164 * v82;
        let v167: f64 = v88 * v166;
        let v168: f64 = v164 * v85;
        let v169: f64 = v167 - v168;
        let v170: f64 = v17 * v31;
        let v171: f64 = v6 * v21;
        let v172: f64 = v170 - v171;
        let v173: f64 = v50 * v20;
        let v174: f64 = v5 * v173;
        let v175: f64 = v172 + v174;
        let v176: f64 = v27 * v175;
        let v177: f64 = v17 * v7;
        let v178: f64 = v6 * v18;
        let v179: f64 = v177 - v178;
        let v180: f64 = v20 * v173;
        let v181: f64 = v6 * v52;
        let v182: f64 = v180 + v181;
        let v183: f64 = v179 - v182;
        let v184: f64 = v30 * v183;
        let v185: f64 = v176 - v184;
        let v186: f64 = v41 * v62;
        let v187: f64 = v56 * v77;
        let v188: f64 = v186 - v187;
        let v189: f64 = v185 + v188;
        let v190: f64 = 0.39225_f64;
        let v191: f64 = v190 * v61;
        let v192: f64 = v36 * v191;
        let v193: f64 = v189 - v192;
        let v194: f64 = v72 * v193;
        let v195: f64 = v30 * v175;
        let v196: f64 = v27 * v183;
        let v197: f64 = v195 + v196;
        let v198: f64 = v56 * v39;
        let v199: f64 = v41 * v57;
        let v200: f64 = v198 - v199;
        let v201: f64 = v197 + v200;
        let v202: f64 = v61 * v191;
        let v203: f64 = v190 * v41;
        let v204: f64 = v41 * v203;
        let v205: f64 = v202 + v204;
        let v206: f64 = v201 - v205;
        let v207: f64 = v69 * v206;
        let v208: f64 = v194 + v207;
        let v209: f64 = v169 - v208;
        let v210: f64 = v96 * v209;
        let v211: f64 = v190 * v39;
        let v212: f64 = v36 * v203;
        let v213: f64 = v211 + v212;
        let v214: f64 = v65 + v213;
        let v215: f64 = v164 * v121;
        let v216: f64 = v121 * v215;
        let v217: f64 = v82 * v166;
        let v218: f64 = v216 + v217;
        let v219: f64 = v214 + v218;
        let v220: f64 = v98 * v219;
        let v221: f64 = v210 - v220;
        let v222: f64 = v165 * v221;
        let v223: f64 = 0.1879_f64;
        let v224: f64 = 0.09465_f64;
        let v225: f64 = v98 * v123;
        let v226: f64 = v100 * v114;
        let v227: f64 = v225 - v226;
        let v228: f64 = v224 * v227;
        let v229: f64 = v224 * v100;
        let v230: f64 = v130 * v229;
        let v231: f64 = v228 + v230;
        let v232: f64 = v221 + v231;
        let v233: f64 = v111 * v232;
        let v234: f64 = v69 * v193;
        let v235: f64 = v72 * v206;
        let v236: f64 = v234 - v235;
        let v237: f64 = v88 * v215;
        let v238: f64 = v164 * v123;
        let v239: f64 = v237 - v238;
        let v240: f64 = v236 + v239;
        let v241: f64 = v100 * v229;
        let v242: f64 = v224 * v103;
        let v243: f64 = v103 * v242;
        let v244: f64 = v241 + v243;
        let v245: f64 = v240 - v244;
        let v246: f64 = v113 * v245;
        let v247: f64 = v233 - v246;
        let v248: f64 = v223 * v247;
        let v249: f64 = v111 * v248;
        let v250: f64 = v113 * v232;
        let v251: f64 = v111 * v245;
        let v252: f64 = v250 + v251;
        let v253: f64 = v223 * v252;
        let v254: f64 = v113 * v253;
        let v255: f64 = v249 + v254;
        let v256: f64 = v222 + v255;
        let v257: f64 = v96 * v256;
        let v258: f64 = v130 * v242;
        let v259: f64 = v224 * v125;
        let v260: f64 = v258 - v259;
        let v261: f64 = v98 * v209;
        let v262: f64 = v96 * v219;
        let v263: f64 = v261 + v262;
        let v264: f64 = v260 - v263;
        let v265: f64 = v223 * v264;
        let v266: f64 = v165 * v263;
        let v267: f64 = v265 - v266;
        let v268: f64 = v98 * v267;
        let v269: f64 = v257 - v268;
        let v270: f64 = v164 * v269;
        let v271: f64 = v163 - v270;
        let v272: f64 = v69 * v271;
        let v273: f64 = v70 * v121;
        let v274: f64 = v88 * v273;
        let v275: f64 = v121 * v89;
        let v276: f64 = v274 - v275;
        let v277: f64 = v87 * v123;
        let v278: f64 = v276 - v277;
        let v279: f64 = v87 * v125;
        let v280: f64 = v70 * v130;
        let v281: f64 = v103 * v280;
        let v282: f64 = v130 * v104;
        let v283: f64 = v281 - v282;
        let v284: f64 = v279 + v283;
        let v285: f64 = v111 * v159;
        let v286: f64 = v113 * v144;
        let v287: f64 = v285 + v286;
        let v288: f64 = v284 + v287;
        let v289: f64 = v224 * v265;
        (
            v151,
            v155,
            v162,
            v164,
            v165,
            v172,
            v179,
            v189,
            v190,
            v201,
            v208,
            v214,
            v224,
            v227,
            v236,
            v240,
            v248,
            v253,
            v255,
            v256,
            v267,
            v269,
            v271,
            v272,
            v273,
            v278,
            v280,
            v288,
            v289,
        )
    };
    let (v301, v410, v427, v430, v433) = {
        let v290: f64 = v288 - v289;
        let v291: f64 = v96 * v290;
        let v292: f64 = v87 * v227;
        let v293: f64 = v130 * v106;
        let v294: f64 = v100 * v280;
        let v295: f64 = v293 - v294;
        let v296: f64 = v292 + v295;
        let v297: f64 = v137 * v227;
        let v298: f64 = v151 * v141;
        let v299: f64 = v132 * v155;
        let v300: f64 = v298 - v299;
        let v301: f64 = v297 + v300;
        let v302: f64 = v296 + v301;
        let v303: f64 = v224 * v255;
        let v304: f64 = v302 + v303;
        let v305: f64 = v98 * v304;
        let v306: f64 = v291 - v305;
        let v307: f64 = v278 + v306;
        let v308: f64 = v165 * v240;
        let v309: f64 = v111 * v253;
        let v310: f64 = v113 * v248;
        let v311: f64 = v309 - v310;
        let v312: f64 = v308 + v311;
        let v313: f64 = v164 * v312;
        let v314: f64 = v307 + v313;
        let v315: f64 = v72 * v314;
        let v316: f64 = v272 - v315;
        let v317: f64 = v67 + v316;
        let v318: f64 = v98 * v256;
        let v319: f64 = v96 * v267;
        let v320: f64 = v318 + v319;
        let v321: f64 = v165 * v214;
        let v322: f64 = v320 - v321;
        let v323: f64 = v190 * v322;
        let v324: f64 = v317 - v323;
        let v325: f64 = 2.275_f64;
        let v326: f64 = v325 * v201;
        let v327: f64 = v49 * v61;
        let v328: f64 = v61 * v327;
        let v329: f64 = v49 * v41;
        let v330: f64 = v41 * v329;
        let v331: f64 = v328 + v330;
        let v332: f64 = v326 - v331;
        let v333: f64 = v165 * v208;
        let v334: f64 = v269 - v333;
        let v335: f64 = v69 * v334;
        let v336: f64 = v165 * v236;
        let v337: f64 = v336 + v312;
        let v338: f64 = v72 * v337;
        let v339: f64 = v335 + v338;
        let v340: f64 = v332 - v339;
        let v341: f64 = v56 * v340;
        let v342: f64 = v324 + v341;
        let v343: f64 = v27 * v342;
        let v344: f64 = v44 * v77;
        let v345: f64 = v61 * v42;
        let v346: f64 = v28 * v61;
        let v347: f64 = v41 * v346;
        let v348: f64 = v345 - v347;
        let v349: f64 = v344 + v348;
        let v350: f64 = v69 * v314;
        let v351: f64 = v72 * v271;
        let v352: f64 = v350 + v351;
        let v353: f64 = v349 - v352;
        let v354: f64 = v325 * v189;
        let v355: f64 = v36 * v327;
        let v356: f64 = v354 - v355;
        let v357: f64 = v69 * v337;
        let v358: f64 = v72 * v334;
        let v359: f64 = v357 - v358;
        let v360: f64 = v356 + v359;
        let v361: f64 = v56 * v360;
        let v362: f64 = v353 - v361;
        let v363: f64 = v30 * v362;
        let v364: f64 = v343 + v363;
        let v365: f64 = v25 + v364;
        let v366: f64 = v325 * v65;
        let v367: f64 = v49 * v39;
        let v368: f64 = v36 * v329;
        let v369: f64 = v367 + v368;
        let v370: f64 = v366 + v369;
        let v371: f64 = v322 - v370;
        let v372: f64 = v50 * v371;
        let v373: f64 = v365 - v372;
        let v374: f64 = 8.393_f64;
        let v375: f64 = v374 * v179;
        let v376: f64 = v16 * v20;
        let v377: f64 = v20 * v376;
        let v378: f64 = v16 * v6;
        let v379: f64 = v6 * v378;
        let v380: f64 = v377 + v379;
        let v381: f64 = v375 - v380;
        let v382: f64 = v27 * v340;
        let v383: f64 = v30 * v360;
        let v384: f64 = v382 - v383;
        let v385: f64 = v381 + v384;
        let v386: f64 = v17 * v385;
        let v387: f64 = v373 + v386;
        let v388: f64 = v1 * v387;
        let v389: f64 = v2 * v20;
        let v390: f64 = v6 * v389;
        let v391: f64 = v20 * v9;
        let v392: f64 = v390 - v391;
        let v393: f64 = v11 * v31;
        let v394: f64 = v392 - v393;
        let v395: f64 = v27 * v362;
        let v396: f64 = v30 * v342;
        let v397: f64 = v395 - v396;
        let v398: f64 = v394 + v397;
        let v399: f64 = v374 * v172;
        let v400: f64 = v5 * v376;
        let v401: f64 = v399 + v400;
        let v402: f64 = v27 * v360;
        let v403: f64 = v30 * v340;
        let v404: f64 = v402 + v403;
        let v405: f64 = v401 + v404;
        let v406: f64 = v17 * v405;
        let v407: f64 = v398 - v406;
        let v408: f64 = v3 * v407;
        let v409: f64 = v388 + v408;
        let v410: f64 = -v409;
        let v411: f64 = v5 * v389;
        let v412: f64 = v20 * v12;
        let v413: f64 = v411 - v412;
        let v414: f64 = v16 * v172;
        let v415: f64 = v413 + v414;
        let v416: f64 = v61 * v45;
        let v417: f64 = v36 * v346;
        let v418: f64 = v416 - v417;
        let v419: f64 = v49 * v189;
        let v420: f64 = v418 + v419;
        let v421: f64 = v121 * v91;
        let v422: f64 = v82 * v273;
        let v423: f64 = v421 - v422;
        let v424: f64 = v98 * v290;
        let v425: f64 = v96 * v304;
        let v426: f64 = v424 + v425;
        let v427: f64 = v423 + v426;
        let v428: f64 = v420 + v427;
        let v429: f64 = v190 * v359;
        let v430: f64 = v428 + v429;
        let v431: f64 = v415 + v430;
        let v432: f64 = v50 * v404;
        let v433: f64 = v431 + v432;
        (v301, v410, v427, v430, v433)
    };
    [v410, v433, v430, v427, v162, v301]
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
/// Operation count: 24 floating-point operations, 6 trig calls.
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
    let v1: f64 = 0.17446825035_f64;
    let v2: f64 = q[3];
    let (v9, v3): (f64, f64) = ::libm::sincos(v2);
    let v4: f64 = v1 * v3;
    let v5: f64 = q[2];
    let (v12, v6): (f64, f64) = ::libm::sincos(v5);
    let v7: f64 = v4 * v6;
    let v8: f64 = 15.68382848775_f64;
    let v10: f64 = v1 * v9;
    let v11: f64 = v8 - v10;
    let v13: f64 = v11 * v12;
    let v14: f64 = v7 + v13;
    let v15: f64 = q[1];
    let (v16, v25): (f64, f64) = ::libm::sincos(v15);
    let v17: f64 = v14 * v16;
    let v18: f64 = -43.486969725_f64;
    let v19: f64 = v4 * v12;
    let v20: f64 = v18 + v19;
    let v21: f64 = -15.68382848775_f64;
    let v22: f64 = v21 + v10;
    let v23: f64 = v22 * v6;
    let v24: f64 = v20 + v23;
    let v26: f64 = v24 * v25;
    let v27: f64 = v17 + v26;
    let v28: f64 = v19 + v23;
    let v29: f64 = v28 * v25;
    let v30: f64 = v29 + v17;
    let v31: f64 = v10 * v6;
    let v32: f64 = v31 + v19;
    let v33: f64 = v32 * v25;
    let v34: f64 = v10 * v12;
    let v35: f64 = v7 - v34;
    let v36: f64 = v35 * v16;
    let v37: f64 = v33 + v36;
    [v0, v27, v30, v37, v0, v0]
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
/// Operation count: 425 floating-point operations, 10 trig calls.
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
        v2,
        v4,
        v5,
        v6,
        v8,
        v9,
        v12,
        v14,
        v16,
        v17,
        v21,
        v22,
        v23,
        v25,
        v26,
        v30,
        v32,
        v33,
        v35,
        v38,
        v43,
        v46,
        v48,
        v49,
        v51,
        v52,
        v56,
        v57,
        v59,
        v63,
        v64,
        v68,
        v69,
        v72,
        v74,
        v76,
        v77,
        v79,
        v84,
        v89,
        v92,
        v94,
        v95,
        v96,
        v98,
        v101,
        v103,
        v106,
        v108,
        v110,
        v113,
        v114,
        v116,
        v119,
        v121,
        v122,
        v123,
        v124,
        v126,
        v128,
        v135,
        v137,
        v140,
        v142,
        v147,
        v149,
        v150,
        v153,
        v154,
        v155,
        v156,
        v157,
    ) = {
        let v0: f64 = 0.00666_f64;
        let v1: f64 = qdd[0];
        let v2: f64 = v0 * v1;
        let v3: f64 = q[1];
        let (v6, v4): (f64, f64) = ::libm::sincos(v3);
        let v5: f64 = 0.88490187591_f64;
        let v7: f64 = qd[0];
        let v8: f64 = v6 * v7;
        let v9: f64 = qd[1];
        let v10: f64 = v8 * v9;
        let v11: f64 = v4 * v1;
        let v12: f64 = v10 - v11;
        let v13: f64 = v5 * v12;
        let v14: f64 = v5 * v9;
        let v15: f64 = v8 * v14;
        let v16: f64 = 0.0151074_f64;
        let v17: f64 = v16 * v8;
        let v18: f64 = v9 * v17;
        let v19: f64 = v15 - v18;
        let v20: f64 = v13 + v19;
        let v21: f64 = 2.35004_f64;
        let v22: f64 = 0.13585_f64;
        let v23: f64 = v22 * v8;
        let v24: f64 = v8 * v23;
        let v25: f64 = v4 * v7;
        let v26: f64 = v22 * v25;
        let v27: f64 = v25 * v26;
        let v28: f64 = v24 + v27;
        let v29: f64 = v21 * v28;
        let v30: f64 = v20 + v29;
        let v31: f64 = q[2];
        let (v35, v32): (f64, f64) = ::libm::sincos(v31);
        let v33: f64 = 0.191630813556_f64;
        let v34: f64 = v32 * v12;
        let v36: f64 = v6 * v1;
        let v37: f64 = v25 * v9;
        let v38: f64 = v36 + v37;
        let v39: f64 = v35 * v38;
        let v40: f64 = v34 + v39;
        let v41: f64 = v35 * v25;
        let v42: f64 = v32 * v8;
        let v43: f64 = v41 + v42;
        let v44: f64 = qd[2];
        let v45: f64 = v43 * v44;
        let v46: f64 = v40 + v45;
        let v47: f64 = v33 * v46;
        let v48: f64 = v9 + v44;
        let v49: f64 = v33 * v48;
        let v50: f64 = v43 * v49;
        let v51: f64 = 0.004095_f64;
        let v52: f64 = v51 * v43;
        let v53: f64 = v48 * v52;
        let v54: f64 = v50 - v53;
        let v55: f64 = v47 + v54;
        let v56: f64 = 0.56875_f64;
        let v57: f64 = 0.425_f64;
        let v58: f64 = v57 * v12;
        let v59: f64 = v57 * v9;
        let v60: f64 = v8 * v59;
        let v61: f64 = v58 + v60;
        let v62: f64 = v28 + v61;
        let v63: f64 = -0.1197_f64;
        let v64: f64 = v63 * v43;
        let v65: f64 = v43 * v64;
        let v66: f64 = v35 * v8;
        let v67: f64 = v32 * v25;
        let v68: f64 = v66 - v67;
        let v69: f64 = v63 * v68;
        let v70: f64 = v68 * v69;
        let v71: f64 = v65 + v70;
        let v72: f64 = v62 + v71;
        let v73: f64 = v56 * v72;
        let v74: f64 = v55 + v73;
        let v75: f64 = q[3];
        let (v79, v76): (f64, f64) = ::libm::sincos(v75);
        let v77: f64 = 0.21942_f64;
        let v78: f64 = v76 * v46;
        let v80: f64 = v35 * v12;
        let v81: f64 = v32 * v38;
        let v82: f64 = v80 - v81;
        let v83: f64 = v68 * v44;
        let v84: f64 = v82 + v83;
        let v85: f64 = v79 * v84;
        let v86: f64 = v78 - v85;
        let v87: f64 = v76 * v43;
        let v88: f64 = v79 * v68;
        let v89: f64 = v87 - v88;
        let v90: f64 = qd[3];
        let v91: f64 = v89 * v90;
        let v92: f64 = v86 + v91;
        let v93: f64 = v77 * v92;
        let v94: f64 = 0.111172755531_f64;
        let v95: f64 = v48 + v90;
        let v96: f64 = v94 * v95;
        let v97: f64 = v89 * v96;
        let v98: f64 = v94 * v89;
        let v99: f64 = v95 * v98;
        let v100: f64 = v97 - v99;
        let v101: f64 = v93 + v100;
        let v102: f64 = qdd[4];
        let v103: f64 = v92 + v102;
        let v104: f64 = v77 * v103;
        let v105: f64 = q[4];
        let (v108, v106): (f64, f64) = ::libm::sincos(v105);
        let v107: f64 = v106 * v89;
        let v109: f64 = v108 * v95;
        let v110: f64 = v107 + v109;
        let v111: f64 = v106 * v95;
        let v112: f64 = v108 * v89;
        let v113: f64 = v111 - v112;
        let v114: f64 = v94 * v113;
        let v115: f64 = v110 * v114;
        let v116: f64 = v94 * v110;
        let v117: f64 = v113 * v116;
        let v118: f64 = v115 - v117;
        let v119: f64 = v104 + v118;
        let v120: f64 = q[5];
        let (v123, v121): (f64, f64) = ::libm::sincos(v120);
        let v122: f64 = 0.033822_f64;
        let v124: f64 = qdd[1];
        let v125: f64 = qdd[2];
        let v126: f64 = v124 + v125;
        let v127: f64 = qdd[3];
        let v128: f64 = v126 + v127;
        let v129: f64 = v108 * v128;
        let v130: f64 = v79 * v46;
        let v131: f64 = v76 * v84;
        let v132: f64 = v130 + v131;
        let v133: f64 = v76 * v68;
        let v134: f64 = v79 * v43;
        let v135: f64 = v133 + v134;
        let v136: f64 = v135 * v90;
        let v137: f64 = v132 + v136;
        let v138: f64 = v106 * v137;
        let v139: f64 = v129 - v138;
        let v140: f64 = qd[4];
        let v141: f64 = v113 * v140;
        let v142: f64 = v139 + v141;
        let v143: f64 = v123 * v142;
        let v144: f64 = v121 * v103;
        let v145: f64 = v143 + v144;
        let v146: f64 = v121 * v110;
        let v147: f64 = v135 + v140;
        let v148: f64 = v123 * v147;
        let v149: f64 = v146 - v148;
        let v150: f64 = qd[5];
        let v151: f64 = v149 * v150;
        let v152: f64 = v145 + v151;
        let v153: f64 = v122 * v152;
        let v154: f64 = 0.0171364731454_f64;
        let v155: f64 = v113 + v150;
        let v156: f64 = v154 * v155;
        let v157: f64 = v149 * v156;
        (
            v2,
            v4,
            v5,
            v6,
            v8,
            v9,
            v12,
            v14,
            v16,
            v17,
            v21,
            v22,
            v23,
            v25,
            v26,
            v30,
            v32,
            v33,
            v35,
            v38,
            v43,
            v46,
            v48,
            v49,
            v51,
            v52,
            v56,
            v57,
            v59,
            v63,
            v64,
            v68,
            v69,
            v72,
            v74,
            v76,
            v77,
            v79,
            v84,
            v89,
            v92,
            v94,
            v95,
            v96,
            v98,
            v101,
            v103,
            v106,
            v108,
            v110,
            v113,
            v114,
            v116,
            v119,
            v121,
            v122,
            v123,
            v124,
            v126,
            v128,
            v135,
            v137,
            v140,
            v142,
            v147,
            v149,
            v150,
            v153,
            v154,
            v155,
            v156,
            v157,
        )
    };
    let (
        v158,
        v168,
        v172,
        v179,
        v181,
        v182,
        v192,
        v203,
        v213,
        v214,
        v227,
        v234,
        v240,
        v250,
        v255,
        v264,
        v268,
        v276,
        v281,
        v283,
        v284,
        v293,
        v295,
        v297,
        v299,
        v300,
        v301,
        v306,
        v308,
        v312,
        v315,
    ) = {
        let v158: f64 = v154 * v149;
        let v159: f64 = v155 * v158;
        let v160: f64 = v157 - v159;
        let v161: f64 = v153 + v160;
        let v162: f64 = v121 * v161;
        let v163: f64 = v121 * v142;
        let v164: f64 = v123 * v103;
        let v165: f64 = v163 - v164;
        let v166: f64 = v123 * v110;
        let v167: f64 = v121 * v147;
        let v168: f64 = v166 + v167;
        let v169: f64 = v168 * v150;
        let v170: f64 = v165 - v169;
        let v171: f64 = v154 * v170;
        let v172: f64 = v122 * v168;
        let v173: f64 = v155 * v172;
        let v174: f64 = v168 * v156;
        let v175: f64 = v173 - v174;
        let v176: f64 = v171 + v175;
        let v177: f64 = v123 * v176;
        let v178: f64 = v162 - v177;
        let v179: f64 = v119 + v178;
        let v180: f64 = v101 + v179;
        let v181: f64 = 0.093_f64;
        let v182: f64 = 1.219_f64;
        let v183: f64 = v181 * v89;
        let v184: f64 = v95 * v183;
        let v185: f64 = v181 * v92;
        let v186: f64 = v184 - v185;
        let v187: f64 = v22 * v38;
        let v188: f64 = v9 * v26;
        let v189: f64 = v187 - v188;
        let v190: f64 = 9.81_f64;
        let v191: f64 = v190 * v4;
        let v192: f64 = v189 - v191;
        let v193: f64 = v57 * v124;
        let v194: f64 = v57 * v25;
        let v195: f64 = v8 * v194;
        let v196: f64 = v193 + v195;
        let v197: f64 = v192 + v196;
        let v198: f64 = v32 * v197;
        let v199: f64 = v22 * v12;
        let v200: f64 = v9 * v23;
        let v201: f64 = v199 - v200;
        let v202: f64 = v190 * v6;
        let v203: f64 = v201 - v202;
        let v204: f64 = v25 * v194;
        let v205: f64 = v9 * v59;
        let v206: f64 = v204 + v205;
        let v207: f64 = v203 - v206;
        let v208: f64 = v35 * v207;
        let v209: f64 = v198 - v208;
        let v210: f64 = v48 * v69;
        let v211: f64 = v63 * v84;
        let v212: f64 = v210 - v211;
        let v213: f64 = v209 + v212;
        let v214: f64 = 0.39225_f64;
        let v215: f64 = v214 * v126;
        let v216: f64 = v214 * v68;
        let v217: f64 = v43 * v216;
        let v218: f64 = v215 - v217;
        let v219: f64 = v213 + v218;
        let v220: f64 = v79 * v219;
        let v221: f64 = v35 * v197;
        let v222: f64 = v32 * v207;
        let v223: f64 = v221 + v222;
        let v224: f64 = v63 * v46;
        let v225: f64 = v48 * v64;
        let v226: f64 = v224 - v225;
        let v227: f64 = v223 + v226;
        let v228: f64 = v68 * v216;
        let v229: f64 = v214 * v48;
        let v230: f64 = v48 * v229;
        let v231: f64 = v228 + v230;
        let v232: f64 = v227 - v231;
        let v233: f64 = v76 * v232;
        let v234: f64 = v220 + v233;
        let v235: f64 = v186 - v234;
        let v236: f64 = v106 * v235;
        let v237: f64 = v214 * v46;
        let v238: f64 = v43 * v229;
        let v239: f64 = v237 + v238;
        let v240: f64 = v72 + v239;
        let v241: f64 = v181 * v135;
        let v242: f64 = v135 * v241;
        let v243: f64 = v89 * v183;
        let v244: f64 = v242 + v243;
        let v245: f64 = v240 + v244;
        let v246: f64 = v108 * v245;
        let v247: f64 = v236 - v246;
        let v248: f64 = v182 * v247;
        let v249: f64 = 0.1879_f64;
        let v250: f64 = 0.09465_f64;
        let v251: f64 = v108 * v137;
        let v252: f64 = v106 * v128;
        let v253: f64 = v251 + v252;
        let v254: f64 = v110 * v140;
        let v255: f64 = v253 - v254;
        let v256: f64 = v250 * v255;
        let v257: f64 = v250 * v110;
        let v258: f64 = v147 * v257;
        let v259: f64 = v256 + v258;
        let v260: f64 = v247 + v259;
        let v261: f64 = v121 * v260;
        let v262: f64 = v76 * v219;
        let v263: f64 = v79 * v232;
        let v264: f64 = v262 - v263;
        let v265: f64 = v95 * v241;
        let v266: f64 = v181 * v137;
        let v267: f64 = v265 - v266;
        let v268: f64 = v264 + v267;
        let v269: f64 = v110 * v257;
        let v270: f64 = v250 * v113;
        let v271: f64 = v113 * v270;
        let v272: f64 = v269 + v271;
        let v273: f64 = v268 - v272;
        let v274: f64 = v123 * v273;
        let v275: f64 = v261 - v274;
        let v276: f64 = v249 * v275;
        let v277: f64 = v121 * v276;
        let v278: f64 = v123 * v260;
        let v279: f64 = v121 * v273;
        let v280: f64 = v278 + v279;
        let v281: f64 = v249 * v280;
        let v282: f64 = v123 * v281;
        let v283: f64 = v277 + v282;
        let v284: f64 = v248 + v283;
        let v285: f64 = v106 * v284;
        let v286: f64 = v147 * v270;
        let v287: f64 = v250 * v142;
        let v288: f64 = v286 - v287;
        let v289: f64 = v108 * v235;
        let v290: f64 = v106 * v245;
        let v291: f64 = v289 + v290;
        let v292: f64 = v288 - v291;
        let v293: f64 = v249 * v292;
        let v294: f64 = v182 * v291;
        let v295: f64 = v293 - v294;
        let v296: f64 = v108 * v295;
        let v297: f64 = v285 - v296;
        let v298: f64 = v181 * v297;
        let v299: f64 = v180 - v298;
        let v300: f64 = v76 * v299;
        let v301: f64 = v77 * v135;
        let v302: f64 = v95 * v301;
        let v303: f64 = v135 * v96;
        let v304: f64 = v302 - v303;
        let v305: f64 = v94 * v137;
        let v306: f64 = v304 - v305;
        let v307: f64 = v94 * v142;
        let v308: f64 = v77 * v147;
        let v309: f64 = v113 * v308;
        let v310: f64 = v147 * v114;
        let v311: f64 = v309 - v310;
        let v312: f64 = v307 + v311;
        let v313: f64 = v121 * v176;
        let v314: f64 = v123 * v161;
        let v315: f64 = v313 + v314;
        (
            v158,
            v168,
            v172,
            v179,
            v181,
            v182,
            v192,
            v203,
            v213,
            v214,
            v227,
            v234,
            v240,
            v250,
            v255,
            v264,
            v268,
            v276,
            v281,
            v283,
            v284,
            v293,
            v295,
            v297,
            v299,
            v300,
            v301,
            v306,
            v308,
            v312,
            v315,
        )
    };
    let (v331, v444, v467, v470, v473) = {
        let v316: f64 = v312 + v315;
        let v317: f64 = v250 * v293;
        let v318: f64 = v316 - v317;
        let v319: f64 = v106 * v318;
        let v320: f64 = v94 * v255;
        let v321: f64 = v147 * v116;
        let v322: f64 = v110 * v308;
        let v323: f64 = v321 - v322;
        let v324: f64 = v320 + v323;
        let v325: f64 = qdd[5];
        let v326: f64 = v255 + v325;
        let v327: f64 = v154 * v326;
        let v328: f64 = v168 * v158;
        let v329: f64 = v149 * v172;
        let v330: f64 = v328 - v329;
        let v331: f64 = v327 + v330;
        let v332: f64 = v324 + v331;
        let v333: f64 = v250 * v283;
        let v334: f64 = v332 + v333;
        let v335: f64 = v108 * v334;
        let v336: f64 = v319 - v335;
        let v337: f64 = v306 + v336;
        let v338: f64 = v182 * v268;
        let v339: f64 = v121 * v281;
        let v340: f64 = v123 * v276;
        let v341: f64 = v339 - v340;
        let v342: f64 = v338 + v341;
        let v343: f64 = v181 * v342;
        let v344: f64 = v337 + v343;
        let v345: f64 = v79 * v344;
        let v346: f64 = v300 - v345;
        let v347: f64 = v74 + v346;
        let v348: f64 = v108 * v284;
        let v349: f64 = v106 * v295;
        let v350: f64 = v348 + v349;
        let v351: f64 = v182 * v240;
        let v352: f64 = v350 - v351;
        let v353: f64 = v214 * v352;
        let v354: f64 = v347 - v353;
        let v355: f64 = 2.275_f64;
        let v356: f64 = v355 * v227;
        let v357: f64 = v56 * v68;
        let v358: f64 = v68 * v357;
        let v359: f64 = v56 * v48;
        let v360: f64 = v48 * v359;
        let v361: f64 = v358 + v360;
        let v362: f64 = v356 - v361;
        let v363: f64 = v182 * v234;
        let v364: f64 = v297 - v363;
        let v365: f64 = v76 * v364;
        let v366: f64 = v182 * v264;
        let v367: f64 = v366 + v342;
        let v368: f64 = v79 * v367;
        let v369: f64 = v365 + v368;
        let v370: f64 = v362 - v369;
        let v371: f64 = v63 * v370;
        let v372: f64 = v354 + v371;
        let v373: f64 = v32 * v372;
        let v374: f64 = v51 * v84;
        let v375: f64 = v68 * v49;
        let v376: f64 = v33 * v68;
        let v377: f64 = v48 * v376;
        let v378: f64 = v375 - v377;
        let v379: f64 = v374 + v378;
        let v380: f64 = v76 * v344;
        let v381: f64 = v79 * v299;
        let v382: f64 = v380 + v381;
        let v383: f64 = v379 - v382;
        let v384: f64 = v355 * v213;
        let v385: f64 = v56 * v126;
        let v386: f64 = v43 * v357;
        let v387: f64 = v385 - v386;
        let v388: f64 = v384 + v387;
        let v389: f64 = v76 * v367;
        let v390: f64 = v79 * v364;
        let v391: f64 = v389 - v390;
        let v392: f64 = v388 + v391;
        let v393: f64 = v63 * v392;
        let v394: f64 = v383 - v393;
        let v395: f64 = v35 * v394;
        let v396: f64 = v373 + v395;
        let v397: f64 = v30 + v396;
        let v398: f64 = v355 * v72;
        let v399: f64 = v56 * v46;
        let v400: f64 = v43 * v359;
        let v401: f64 = v399 + v400;
        let v402: f64 = v398 + v401;
        let v403: f64 = v352 - v402;
        let v404: f64 = v57 * v403;
        let v405: f64 = v397 - v404;
        let v406: f64 = 8.393_f64;
        let v407: f64 = v406 * v203;
        let v408: f64 = v21 * v25;
        let v409: f64 = v25 * v408;
        let v410: f64 = v21 * v9;
        let v411: f64 = v9 * v410;
        let v412: f64 = v409 + v411;
        let v413: f64 = v407 - v412;
        let v414: f64 = v32 * v370;
        let v415: f64 = v35 * v392;
        let v416: f64 = v414 - v415;
        let v417: f64 = v413 + v416;
        let v418: f64 = v22 * v417;
        let v419: f64 = v405 + v418;
        let v420: f64 = v4 * v419;
        let v421: f64 = v5 * v25;
        let v422: f64 = v9 * v421;
        let v423: f64 = v25 * v14;
        let v424: f64 = v422 - v423;
        let v425: f64 = v16 * v38;
        let v426: f64 = v424 - v425;
        let v427: f64 = v32 * v394;
        let v428: f64 = v35 * v372;
        let v429: f64 = v427 - v428;
        let v430: f64 = v426 + v429;
        let v431: f64 = v406 * v192;
        let v432: f64 = v21 * v124;
        let v433: f64 = v8 * v408;
        let v434: f64 = v432 + v433;
        let v435: f64 = v431 + v434;
        let v436: f64 = v32 * v392;
        let v437: f64 = v35 * v370;
        let v438: f64 = v436 + v437;
        let v439: f64 = v435 + v438;
        let v440: f64 = v22 * v439;
        let v441: f64 = v430 - v440;
        let v442: f64 = v6 * v441;
        let v443: f64 = v420 + v442;
        let v444: f64 = v2 - v443;
        let v445: f64 = v5 * v124;
        let v446: f64 = v8 * v421;
        let v447: f64 = v25 * v17;
        let v448: f64 = v446 - v447;
        let v449: f64 = v445 + v448;
        let v450: f64 = v21 * v192;
        let v451: f64 = v449 + v450;
        let v452: f64 = v33 * v126;
        let v453: f64 = v68 * v52;
        let v454: f64 = v43 * v376;
        let v455: f64 = v453 - v454;
        let v456: f64 = v452 + v455;
        let v457: f64 = v56 * v213;
        let v458: f64 = v456 + v457;
        let v459: f64 = v94 * v128;
        let v460: f64 = v135 * v98;
        let v461: f64 = v89 * v301;
        let v462: f64 = v460 - v461;
        let v463: f64 = v459 + v462;
        let v464: f64 = v108 * v318;
        let v465: f64 = v106 * v334;
        let v466: f64 = v464 + v465;
        let v467: f64 = v463 + v466;
        let v468: f64 = v458 + v467;
        let v469: f64 = v214 * v391;
        let v470: f64 = v468 + v469;
        let v471: f64 = v451 + v470;
        let v472: f64 = v57 * v438;
        let v473: f64 = v471 + v472;
        (v331, v444, v467, v470, v473)
    };
    [v444, v473, v470, v467, v179, v331]
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
/// Operation count: 751 floating-point operations, 10 trig calls.
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
        v3,
        v4,
        v6,
        v7,
        v8,
        v10,
        v12,
        v13,
        v17,
        v18,
        v19,
        v21,
        v22,
        v26,
        v28,
        v29,
        v31,
        v32,
        v37,
        v40,
        v42,
        v43,
        v45,
        v46,
        v50,
        v51,
        v53,
        v57,
        v58,
        v62,
        v63,
        v66,
        v68,
        v70,
        v71,
        v73,
        v78,
        v83,
        v86,
        v88,
        v89,
        v90,
        v92,
        v95,
        v97,
        v99,
        v101,
        v104,
        v105,
        v107,
        v112,
        v113,
        v114,
        v115,
        v122,
        v124,
        v126,
        v131,
        v133,
        v138,
        v142,
        v145,
        v152,
        v156,
        v160,
        v163,
    ) = {
        let v0: f64 = tau[0];
        let v1: f64 = q[1];
        let (v4, v2): (f64, f64) = ::libm::sincos(v1);
        let v3: f64 = 0.88490187591_f64;
        let v5: f64 = qd[0];
        let v6: f64 = v4 * v5;
        let v7: f64 = qd[1];
        let v8: f64 = v6 * v7;
        let v9: f64 = v3 * v8;
        let v10: f64 = v3 * v7;
        let v11: f64 = v6 * v10;
        let v12: f64 = 0.0151074_f64;
        let v13: f64 = v12 * v6;
        let v14: f64 = v7 * v13;
        let v15: f64 = v11 - v14;
        let v16: f64 = v9 + v15;
        let v17: f64 = 2.35004_f64;
        let v18: f64 = 0.13585_f64;
        let v19: f64 = v18 * v6;
        let v20: f64 = v6 * v19;
        let v21: f64 = v2 * v5;
        let v22: f64 = v18 * v21;
        let v23: f64 = v21 * v22;
        let v24: f64 = v20 + v23;
        let v25: f64 = v17 * v24;
        let v26: f64 = v16 + v25;
        let v27: f64 = q[2];
        let (v31, v28): (f64, f64) = ::libm::sincos(v27);
        let v29: f64 = 0.191630813556_f64;
        let v30: f64 = v28 * v8;
        let v32: f64 = v21 * v7;
        let v33: f64 = v31 * v32;
        let v34: f64 = v30 + v33;
        let v35: f64 = v31 * v21;
        let v36: f64 = v28 * v6;
        let v37: f64 = v35 + v36;
        let v38: f64 = qd[2];
        let v39: f64 = v37 * v38;
        let v40: f64 = v34 + v39;
        let v41: f64 = v29 * v40;
        let v42: f64 = v7 + v38;
        let v43: f64 = v29 * v42;
        let v44: f64 = v37 * v43;
        let v45: f64 = 0.004095_f64;
        let v46: f64 = v45 * v37;
        let v47: f64 = v42 * v46;
        let v48: f64 = v44 - v47;
        let v49: f64 = v41 + v48;
        let v50: f64 = 0.56875_f64;
        let v51: f64 = 0.425_f64;
        let v52: f64 = v51 * v8;
        let v53: f64 = v51 * v7;
        let v54: f64 = v6 * v53;
        let v55: f64 = v52 + v54;
        let v56: f64 = v24 + v55;
        let v57: f64 = -0.1197_f64;
        let v58: f64 = v57 * v37;
        let v59: f64 = v37 * v58;
        let v60: f64 = v31 * v6;
        let v61: f64 = v28 * v21;
        let v62: f64 = v60 - v61;
        let v63: f64 = v57 * v62;
        let v64: f64 = v62 * v63;
        let v65: f64 = v59 + v64;
        let v66: f64 = v56 + v65;
        let v67: f64 = v50 * v66;
        let v68: f64 = v49 + v67;
        let v69: f64 = q[3];
        let (v73, v70): (f64, f64) = ::libm::sincos(v69);
        let v71: f64 = 0.21942_f64;
        let v72: f64 = v70 * v40;
        let v74: f64 = v31 * v8;
        let v75: f64 = v28 * v32;
        let v76: f64 = v74 - v75;
        let v77: f64 = v62 * v38;
        let v78: f64 = v76 + v77;
        let v79: f64 = v73 * v78;
        let v80: f64 = v72 - v79;
        let v81: f64 = v70 * v37;
        let v82: f64 = v73 * v62;
        let v83: f64 = v81 - v82;
        let v84: f64 = qd[3];
        let v85: f64 = v83 * v84;
        let v86: f64 = v80 + v85;
        let v87: f64 = v71 * v86;
        let v88: f64 = 0.111172755531_f64;
        let v89: f64 = v42 + v84;
        let v90: f64 = v88 * v89;
        let v91: f64 = v83 * v90;
        let v92: f64 = v88 * v83;
        let v93: f64 = v89 * v92;
        let v94: f64 = v91 - v93;
        let v95: f64 = v87 + v94;
        let v96: f64 = q[4];
        let (v99, v97): (f64, f64) = ::libm::sincos(v96);
        let v98: f64 = v97 * v83;
        let v100: f64 = v99 * v89;
        let v101: f64 = v98 + v100;
        let v102: f64 = v97 * v89;
        let v103: f64 = v99 * v83;
        let v104: f64 = v102 - v103;
        let v105: f64 = v88 * v104;
        let v106: f64 = v101 * v105;
        let v107: f64 = v88 * v101;
        let v108: f64 = v104 * v107;
        let v109: f64 = v106 - v108;
        let v110: f64 = v87 + v109;
        let v111: f64 = q[5];
        let (v114, v112): (f64, f64) = ::libm::sincos(v111);
        let v113: f64 = 0.033822_f64;
        let v115: f64 = qd[4];
        let v116: f64 = v104 * v115;
        let v117: f64 = v73 * v40;
        let v118: f64 = v70 * v78;
        let v119: f64 = v117 + v118;
        let v120: f64 = v70 * v62;
        let v121: f64 = v73 * v37;
        let v122: f64 = v120 + v121;
        let v123: f64 = v122 * v84;
        let v124: f64 = v119 + v123;
        let v125: f64 = v97 * v124;
        let v126: f64 = v116 - v125;
        let v127: f64 = v114 * v126;
        let v128: f64 = v112 * v86;
        let v129: f64 = v127 + v128;
        let v130: f64 = v112 * v101;
        let v131: f64 = v122 + v115;
        let v132: f64 = v114 * v131;
        let v133: f64 = v130 - v132;
        let v134: f64 = qd[5];
        let v135: f64 = v133 * v134;
        let v136: f64 = v129 + v135;
        let v137: f64 = v113 * v136;
        let v138: f64 = 0.0171364731454_f64;
        let v139: f64 = v104 + v134;
        let v140: f64 = v138 * v139;
        let v141: f64 = v133 * v140;
        let v142: f64 = v138 * v133;
        let v143: f64 = v139 * v142;
        let v144: f64 = v141 - v143;
        let v145: f64 = v137 + v144;
        let v146: f64 = v112 * v145;
        let v147: f64 = v112 * v126;
        let v148: f64 = v114 * v86;
        let v149: f64 = v147 - v148;
        let v150: f64 = v114 * v101;
        let v151: f64 = v112 * v131;
        let v152: f64 = v150 + v151;
        let v153: f64 = v152 * v134;
        let v154: f64 = v149 - v153;
        let v155: f64 = v138 * v154;
        let v156: f64 = v113 * v152;
        let v157: f64 = v139 * v156;
        let v158: f64 = v152 * v140;
        let v159: f64 = v157 - v158;
        let v160: f64 = v155 + v159;
        let v161: f64 = v114 * v160;
        let v162: f64 = v146 - v161;
        let v163: f64 = v110 + v162;
        (
            v0,
            v2,
            v3,
            v4,
            v6,
            v7,
            v8,
            v10,
            v12,
            v13,
            v17,
            v18,
            v19,
            v21,
            v22,
            v26,
            v28,
            v29,
            v31,
            v32,
            v37,
            v40,
            v42,
            v43,
            v45,
            v46,
            v50,
            v51,
            v53,
            v57,
            v58,
            v62,
            v63,
            v66,
            v68,
            v70,
            v71,
            v73,
            v78,
            v83,
            v86,
            v88,
            v89,
            v90,
            v92,
            v95,
            v97,
            v99,
            v101,
            v104,
            v105,
            v107,
            v112,
            v113,
            v114,
            v115,
            v122,
            v124,
            v126,
            v131,
            v133,
            v138,
            v142,
            v145,
            v152,
            v156,
            v160,
            v163,
        )
    };
    let (
        v166,
        v176,
        v185,
        v195,
        v196,
        v207,
        v214,
        v242,
        v275,
        v277,
        v279,
        v296,
        v307,
        v310,
        v318,
        v320,
        v323,
        v326,
        v327,
    ) = {
        let v164: f64 = v95 + v163;
        let v165: f64 = 0.093_f64;
        let v166: f64 = 1.219_f64;
        let v167: f64 = v165 * v83;
        let v168: f64 = v89 * v167;
        let v169: f64 = v165 * v86;
        let v170: f64 = v168 - v169;
        let v171: f64 = v18 * v32;
        let v172: f64 = v7 * v22;
        let v173: f64 = v171 - v172;
        let v174: f64 = 9.81_f64;
        let v175: f64 = v174 * v2;
        let v176: f64 = v173 - v175;
        let v177: f64 = v51 * v21;
        let v178: f64 = v6 * v177;
        let v179: f64 = v176 + v178;
        let v180: f64 = v28 * v179;
        let v181: f64 = v18 * v8;
        let v182: f64 = v7 * v19;
        let v183: f64 = v181 - v182;
        let v184: f64 = v174 * v4;
        let v185: f64 = v183 - v184;
        let v186: f64 = v21 * v177;
        let v187: f64 = v7 * v53;
        let v188: f64 = v186 + v187;
        let v189: f64 = v185 - v188;
        let v190: f64 = v31 * v189;
        let v191: f64 = v180 - v190;
        let v192: f64 = v42 * v63;
        let v193: f64 = v57 * v78;
        let v194: f64 = v192 - v193;
        let v195: f64 = v191 + v194;
        let v196: f64 = 0.39225_f64;
        let v197: f64 = v196 * v62;
        let v198: f64 = v37 * v197;
        let v199: f64 = v195 - v198;
        let v200: f64 = v73 * v199;
        let v201: f64 = v31 * v179;
        let v202: f64 = v28 * v189;
        let v203: f64 = v201 + v202;
        let v204: f64 = v57 * v40;
        let v205: f64 = v42 * v58;
        let v206: f64 = v204 - v205;
        let v207: f64 = v203 + v206;
        let v208: f64 = v62 * v197;
        let v209: f64 = v196 * v42;
        let v210: f64 = v42 * v209;
        let v211: f64 = v208 + v210;
        let v212: f64 = v207 - v211;
        let v213: f64 = v70 * v212;
        let v214: f64 = v200 + v213;
        let v215: f64 = v170 - v214;
        let v216: f64 = v97 * v215;
        let v217: f64 = v196 * v40;
        let v218: f64 = v37 * v209;
        let v219: f64 = v217 + v218;
        let v220: f64 = v66 + v219;
        let v221: f64 = v165 * v122;
        let v222: f64 = v122 * v221;
        let v223: f64 = v83 * v167;
        let v224: f64 = v222 + v223;
        let v225: f64 = v220 + v224;
        let v226: f64 = v99 * v225;
        let v227: f64 = v216 - v226;
        let v228: f64 = v166 * v227;
        let v229: f64 = 0.1879_f64;
        let v230: f64 = 0.09465_f64;
        let v231: f64 = v99 * v124;
        let v232: f64 = v101 * v115;
        let v233: f64 = v231 - v232;
        let v234: f64 = v230 * v233;
        let v235: f64 = v230 * v101;
        let v236: f64 = v131 * v235;
        let v237: f64 = v234 + v236;
        let v238: f64 = v227 + v237;
        let v239: f64 = v112 * v238;
        let v240: f64 = v70 * v199;
        let v241: f64 = v73 * v212;
        let v242: f64 = v240 - v241;
        let v243: f64 = v89 * v221;
        let v244: f64 = v165 * v124;
        let v245: f64 = v243 - v244;
        let v246: f64 = v242 + v245;
        let v247: f64 = v101 * v235;
        let v248: f64 = v230 * v104;
        let v249: f64 = v104 * v248;
        let v250: f64 = v247 + v249;
        let v251: f64 = v246 - v250;
        let v252: f64 = v114 * v251;
        let v253: f64 = v239 - v252;
        let v254: f64 = v229 * v253;
        let v255: f64 = v112 * v254;
        let v256: f64 = v114 * v238;
        let v257: f64 = v112 * v251;
        let v258: f64 = v256 + v257;
        let v259: f64 = v229 * v258;
        let v260: f64 = v114 * v259;
        let v261: f64 = v255 + v260;
        let v262: f64 = v228 + v261;
        let v263: f64 = v97 * v262;
        let v264: f64 = v131 * v248;
        let v265: f64 = v230 * v126;
        let v266: f64 = v264 - v265;
        let v267: f64 = v99 * v215;
        let v268: f64 = v97 * v225;
        let v269: f64 = v267 + v268;
        let v270: f64 = v266 - v269;
        let v271: f64 = v229 * v270;
        let v272: f64 = v166 * v269;
        let v273: f64 = v271 - v272;
        let v274: f64 = v99 * v273;
        let v275: f64 = v263 - v274;
        let v276: f64 = v165 * v275;
        let v277: f64 = v164 - v276;
        let v278: f64 = v70 * v277;
        let v279: f64 = v71 * v122;
        let v280: f64 = v89 * v279;
        let v281: f64 = v122 * v90;
        let v282: f64 = v280 - v281;
        let v283: f64 = v88 * v124;
        let v284: f64 = v282 - v283;
        let v285: f64 = v88 * v126;
        let v286: f64 = v71 * v131;
        let v287: f64 = v104 * v286;
        let v288: f64 = v131 * v105;
        let v289: f64 = v287 - v288;
        let v290: f64 = v285 + v289;
        let v291: f64 = v112 * v160;
        let v292: f64 = v114 * v145;
        let v293: f64 = v291 + v292;
        let v294: f64 = v290 + v293;
        let v295: f64 = v230 * v271;
        let v296: f64 = v294 - v295;
        let v297: f64 = v97 * v296;
        let v298: f64 = v88 * v233;
        let v299: f64 = v131 * v107;
        let v300: f64 = v101 * v286;
        let v301: f64 = v299 - v300;
        let v302: f64 = v298 + v301;
        let v303: f64 = v138 * v233;
        let v304: f64 = v152 * v142;
        let v305: f64 = v133 * v156;
        let v306: f64 = v304 - v305;
        let v307: f64 = v303 + v306;
        let v308: f64 = v302 + v307;
        let v309: f64 = v230 * v261;
        let v310: f64 = v308 + v309;
        let v311: f64 = v99 * v310;
        let v312: f64 = v297 - v311;
        let v313: f64 = v284 + v312;
        let v314: f64 = v166 * v246;
        let v315: f64 = v112 * v259;
        let v316: f64 = v114 * v254;
        let v317: f64 = v315 - v316;
        let v318: f64 = v314 + v317;
        let v319: f64 = v165 * v318;
        let v320: f64 = v313 + v319;
        let v321: f64 = v73 * v320;
        let v322: f64 = v278 - v321;
        let v323: f64 = v68 + v322;
        let v324: f64 = v99 * v262;
        let v325: f64 = v97 * v273;
        let v326: f64 = v324 + v325;
        let v327: f64 = v166 * v220;
        (
            v166,
            v176,
            v185,
            v195,
            v196,
            v207,
            v214,
            v242,
            v275,
            v277,
            v279,
            v296,
            v307,
            v310,
            v318,
            v320,
            v323,
            v326,
            v327,
        )
    };
    let (
        v352,
        v365,
        v395,
        v410,
        v417,
        v429,
        v430,
        v432,
        v440,
        v446,
        v448,
        v451,
        v461,
        v462,
        v464,
        v466,
        v467,
        v470,
        v480,
        v481,
        v483,
        v484,
        v488,
        v489,
        v490,
        v491,
    ) = {
        let v328: f64 = v326 - v327;
        let v329: f64 = v196 * v328;
        let v330: f64 = v323 - v329;
        let v331: f64 = 2.275_f64;
        let v332: f64 = v331 * v207;
        let v333: f64 = v50 * v62;
        let v334: f64 = v62 * v333;
        let v335: f64 = v50 * v42;
        let v336: f64 = v42 * v335;
        let v337: f64 = v334 + v336;
        let v338: f64 = v332 - v337;
        let v339: f64 = v166 * v214;
        let v340: f64 = v275 - v339;
        let v341: f64 = v70 * v340;
        let v342: f64 = v166 * v242;
        let v343: f64 = v342 + v318;
        let v344: f64 = v73 * v343;
        let v345: f64 = v341 + v344;
        let v346: f64 = v338 - v345;
        let v347: f64 = v57 * v346;
        let v348: f64 = v330 + v347;
        let v349: f64 = v28 * v348;
        let v350: f64 = v45 * v78;
        let v351: f64 = v62 * v43;
        let v352: f64 = v29 * v62;
        let v353: f64 = v42 * v352;
        let v354: f64 = v351 - v353;
        let v355: f64 = v350 + v354;
        let v356: f64 = v70 * v320;
        let v357: f64 = v73 * v277;
        let v358: f64 = v356 + v357;
        let v359: f64 = v355 - v358;
        let v360: f64 = v331 * v195;
        let v361: f64 = v37 * v333;
        let v362: f64 = v360 - v361;
        let v363: f64 = v70 * v343;
        let v364: f64 = v73 * v340;
        let v365: f64 = v363 - v364;
        let v366: f64 = v362 + v365;
        let v367: f64 = v57 * v366;
        let v368: f64 = v359 - v367;
        let v369: f64 = v31 * v368;
        let v370: f64 = v349 + v369;
        let v371: f64 = v26 + v370;
        let v372: f64 = v331 * v66;
        let v373: f64 = v50 * v40;
        let v374: f64 = v37 * v335;
        let v375: f64 = v373 + v374;
        let v376: f64 = v372 + v375;
        let v377: f64 = v328 - v376;
        let v378: f64 = v51 * v377;
        let v379: f64 = v371 - v378;
        let v380: f64 = 8.393_f64;
        let v381: f64 = v380 * v185;
        let v382: f64 = v17 * v21;
        let v383: f64 = v21 * v382;
        let v384: f64 = v17 * v7;
        let v385: f64 = v7 * v384;
        let v386: f64 = v383 + v385;
        let v387: f64 = v381 - v386;
        let v388: f64 = v28 * v346;
        let v389: f64 = v31 * v366;
        let v390: f64 = v388 - v389;
        let v391: f64 = v387 + v390;
        let v392: f64 = v18 * v391;
        let v393: f64 = v379 + v392;
        let v394: f64 = v2 * v393;
        let v395: f64 = v3 * v21;
        let v396: f64 = v7 * v395;
        let v397: f64 = v21 * v10;
        let v398: f64 = v396 - v397;
        let v399: f64 = v12 * v32;
        let v400: f64 = v398 - v399;
        let v401: f64 = v28 * v368;
        let v402: f64 = v31 * v348;
        let v403: f64 = v401 - v402;
        let v404: f64 = v400 + v403;
        let v405: f64 = v380 * v176;
        let v406: f64 = v6 * v382;
        let v407: f64 = v405 + v406;
        let v408: f64 = v28 * v366;
        let v409: f64 = v31 * v346;
        let v410: f64 = v408 + v409;
        let v411: f64 = v407 + v410;
        let v412: f64 = v18 * v411;
        let v413: f64 = v404 - v412;
        let v414: f64 = v4 * v413;
        let v415: f64 = v394 + v414;
        let v416: f64 = v0 + v415;
        let v417: f64 = 58.355064750790525_f64;
        let v418: f64 = v138 * v99;
        let v419: f64 = v73 * v418;
        let v420: f64 = v28 * v419;
        let v421: f64 = v70 * v418;
        let v422: f64 = v31 * v421;
        let v423: f64 = v420 + v422;
        let v424: f64 = v2 * v423;
        let v425: f64 = v28 * v421;
        let v426: f64 = v31 * v419;
        let v427: f64 = v425 - v426;
        let v428: f64 = v4 * v427;
        let v429: f64 = v424 + v428;
        let v430: f64 = v417 * v429;
        let v431: f64 = tau[5];
        let v432: f64 = v431 - v307;
        let v433: f64 = v430 * v432;
        let v434: f64 = v416 + v433;
        let v435: f64 = v138 * v114;
        let v436: f64 = v435 * v114;
        let v437: f64 = v113 * v112;
        let v438: f64 = v437 * v112;
        let v439: f64 = v436 + v438;
        let v440: f64 = v71 + v439;
        let v441: f64 = v70 * v440;
        let v442: f64 = v113 * v114;
        let v443: f64 = v442 * v112;
        let v444: f64 = v138 * v112;
        let v445: f64 = v444 * v114;
        let v446: f64 = v443 - v445;
        let v447: f64 = v97 * v446;
        let v448: f64 = v73 * v447;
        let v449: f64 = v441 - v448;
        let v450: f64 = v31 * v449;
        let v451: f64 = v70 * v447;
        let v452: f64 = v73 * v440;
        let v453: f64 = v451 + v452;
        let v454: f64 = v28 * v453;
        let v455: f64 = v450 + v454;
        let v456: f64 = v4 * v455;
        let v457: f64 = v28 * v449;
        let v458: f64 = v31 * v453;
        let v459: f64 = v457 - v458;
        let v460: f64 = v2 * v459;
        let v461: f64 = v456 - v460;
        let v462: f64 = v461 / v440;
        let v463: f64 = tau[4];
        let v464: f64 = v463 - v163;
        let v465: f64 = v462 * v464;
        let v466: f64 = v434 - v465;
        let v467: f64 = v429 * v97;
        let v468: f64 = v437 * v114;
        let v469: f64 = v435 * v112;
        let v470: f64 = v468 - v469;
        let v471: f64 = v470 * v99;
        let v472: f64 = 0.0016539803549999999_f64;
        let v473: f64 = v471 - v472;
        let v474: f64 = v70 * v473;
        let v475: f64 = v444 * v112;
        let v476: f64 = v442 * v114;
        let v477: f64 = v475 + v476;
        let v478: f64 = 0.00168332516775_f64;
        let v479: f64 = v477 + v478;
        let v480: f64 = v88 + v479;
        let v481: f64 = v97 * v480;
        let v482: f64 = v481 * v99;
        let v483: f64 = 0.12999255384415_f64;
        let v484: f64 = v483 * v99;
        let v485: f64 = v484 * v97;
        let v486: f64 = v482 - v485;
        let v487: f64 = v73 * v486;
        let v488: f64 = v474 - v487;
        let v489: f64 = v28 * v488;
        let v490: f64 = v70 * v486;
        let v491: f64 = v73 * v473;
        (
            v352,
            v365,
            v395,
            v410,
            v417,
            v429,
            v430,
            v432,
            v440,
            v446,
            v448,
            v451,
            v461,
            v462,
            v464,
            v466,
            v467,
            v470,
            v480,
            v481,
            v483,
            v484,
            v488,
            v489,
            v490,
            v491,
        )
    };
    let (
        v498,
        v521,
        v523,
        v531,
        v533,
        v534,
        v535,
        v545,
        v547,
        v548,
        v578,
        v582,
        v584,
        v585,
        v588,
        v594,
        v595,
        v604,
        v609,
        v611,
        v618,
        v636,
        v637,
        v640,
        v645,
        v646,
        v648,
        v650,
        v653,
        v654,
        v655,
    ) = {
        let v492: f64 = v490 + v491;
        let v493: f64 = v31 * v492;
        let v494: f64 = v489 - v493;
        let v495: f64 = 0.017784735_f64;
        let v496: f64 = v495 * v73;
        let v497: f64 = v31 * v496;
        let v498: f64 = v495 * v70;
        let v499: f64 = v28 * v498;
        let v500: f64 = v497 - v499;
        let v501: f64 = v57 * v500;
        let v502: f64 = v494 + v501;
        let v503: f64 = v2 * v502;
        let v504: f64 = v28 * v496;
        let v505: f64 = v31 * v498;
        let v506: f64 = v504 + v505;
        let v507: f64 = v57 * v506;
        let v508: f64 = v31 * v488;
        let v509: f64 = v28 * v492;
        let v510: f64 = v508 + v509;
        let v511: f64 = v507 - v510;
        let v512: f64 = v4 * v511;
        let v513: f64 = v503 + v512;
        let v514: f64 = v4 * v506;
        let v515: f64 = v2 * v500;
        let v516: f64 = v514 + v515;
        let v517: f64 = v18 * v516;
        let v518: f64 = v513 + v517;
        let v519: f64 = v467 - v518;
        let v520: f64 = v99 * v446;
        let v521: f64 = v520 / v440;
        let v522: f64 = v461 * v521;
        let v523: f64 = v519 - v522;
        let v524: f64 = v99 * v480;
        let v525: f64 = v524 * v99;
        let v526: f64 = v483 * v97;
        let v527: f64 = v526 * v97;
        let v528: f64 = v525 + v527;
        let v529: f64 = v88 + v528;
        let v530: f64 = v138 * v97;
        let v531: f64 = v530 * v97;
        let v532: f64 = v529 - v531;
        let v533: f64 = v520 * v521;
        let v534: f64 = v532 - v533;
        let v535: f64 = v523 / v534;
        let v536: f64 = tau[3];
        let v537: f64 = v122 * v92;
        let v538: f64 = v83 * v279;
        let v539: f64 = v537 - v538;
        let v540: f64 = v99 * v296;
        let v541: f64 = v97 * v310;
        let v542: f64 = v540 + v541;
        let v543: f64 = v539 + v542;
        let v544: f64 = v536 - v543;
        let v545: f64 = v97 * v432;
        let v546: f64 = v544 - v545;
        let v547: f64 = v521 * v464;
        let v548: f64 = v546 - v547;
        let v549: f64 = v535 * v548;
        let v550: f64 = v466 - v549;
        let v551: f64 = 0.051322656825_f64;
        let v552: f64 = v492 + v551;
        let v553: f64 = v28 * v552;
        let v554: f64 = v508 + v553;
        let v555: f64 = 1.030009275_f64;
        let v556: f64 = v555 - v496;
        let v557: f64 = v50 + v556;
        let v558: f64 = v28 * v557;
        let v559: f64 = v558 - v505;
        let v560: f64 = v57 * v559;
        let v561: f64 = v554 + v560;
        let v562: f64 = v4 * v561;
        let v563: f64 = v31 * v552;
        let v564: f64 = v489 - v563;
        let v565: f64 = v31 * v557;
        let v566: f64 = v565 + v499;
        let v567: f64 = v57 * v566;
        let v568: f64 = v564 - v567;
        let v569: f64 = v2 * v568;
        let v570: f64 = v562 - v569;
        let v571: f64 = v4 * v559;
        let v572: f64 = v2 * v566;
        let v573: f64 = v571 + v572;
        let v574: f64 = v18 * v573;
        let v575: f64 = v570 + v574;
        let v576: f64 = v575 + v467;
        let v577: f64 = v576 - v522;
        let v578: f64 = v196 * v496;
        let v579: f64 = v529 - v578;
        let v580: f64 = v579 - v531;
        let v581: f64 = v580 - v533;
        let v582: f64 = v581 / v534;
        let v583: f64 = v523 * v582;
        let v584: f64 = v577 - v583;
        let v585: f64 = 0.40402113811874996_f64;
        let v586: f64 = 2.0_f64;
        let v587: f64 = v586 * v578;
        let v588: f64 = v585 - v587;
        let v589: f64 = v529 + v588;
        let v590: f64 = v29 + v589;
        let v591: f64 = v590 - v531;
        let v592: f64 = v591 - v533;
        let v593: f64 = v581 * v582;
        let v594: f64 = v592 - v593;
        let v595: f64 = v584 / v594;
        let v596: f64 = tau[2];
        let v597: f64 = v62 * v46;
        let v598: f64 = v37 * v352;
        let v599: f64 = v597 - v598;
        let v600: f64 = v50 * v195;
        let v601: f64 = v599 + v600;
        let v602: f64 = v601 + v543;
        let v603: f64 = v196 * v365;
        let v604: f64 = v602 + v603;
        let v605: f64 = v596 - v604;
        let v606: f64 = v605 - v545;
        let v607: f64 = v606 - v547;
        let v608: f64 = v582 * v548;
        let v609: f64 = v607 - v608;
        let v610: f64 = v595 * v609;
        let v611: f64 = v550 - v610;
        let v612: f64 = -0.24932103525000002_f64;
        let v613: f64 = v554 + v612;
        let v614: f64 = v613 + v560;
        let v615: f64 = 0.0556077225_f64;
        let v616: f64 = v614 + v615;
        let v617: f64 = v4 * v616;
        let v618: f64 = v499 + v565;
        let v619: f64 = v57 * v618;
        let v620: f64 = v564 - v619;
        let v621: f64 = v2 * v620;
        let v622: f64 = v617 - v621;
        let v623: f64 = 2.0828824999999997_f64;
        let v624: f64 = v559 + v623;
        let v625: f64 = v17 + v624;
        let v626: f64 = v4 * v625;
        let v627: f64 = v2 * v618;
        let v628: f64 = v626 + v627;
        let v629: f64 = v18 * v628;
        let v630: f64 = v622 + v629;
        let v631: f64 = v630 + v467;
        let v632: f64 = v631 - v522;
        let v633: f64 = v51 * v506;
        let v634: f64 = v579 - v633;
        let v635: f64 = v634 - v531;
        let v636: f64 = v635 - v533;
        let v637: f64 = v636 / v534;
        let v638: f64 = v523 * v637;
        let v639: f64 = v632 - v638;
        let v640: f64 = v51 * v559;
        let v641: f64 = v590 + v640;
        let v642: f64 = v641 - v531;
        let v643: f64 = v642 - v533;
        let v644: f64 = v636 * v582;
        let v645: f64 = v643 - v644;
        let v646: f64 = v645 / v594;
        let v647: f64 = v584 * v646;
        let v648: f64 = v639 - v647;
        let v649: f64 = 0.9554455987809999_f64;
        let v650: f64 = -0.01566175149_f64;
        let v651: f64 = v650 + v640;
        let v652: f64 = v586 * v651;
        let v653: f64 = v649 + v652;
        let v654: f64 = v590 + v653;
        let v655: f64 = 0.070220536281_f64;
        (
            v498,
            v521,
            v523,
            v531,
            v533,
            v534,
            v535,
            v545,
            v547,
            v548,
            v578,
            v582,
            v584,
            v585,
            v588,
            v594,
            v595,
            v604,
            v609,
            v611,
            v618,
            v636,
            v637,
            v640,
            v645,
            v646,
            v648,
            v650,
            v653,
            v654,
            v655,
        )
    };
    let (v784, v787, v792, v799, v808, v817) = {
        let v656: f64 = v654 - v655;
        let v657: f64 = v656 - v650;
        let v658: f64 = v657 - v650;
        let v659: f64 = v3 + v658;
        let v660: f64 = v659 - v531;
        let v661: f64 = v660 - v533;
        let v662: f64 = v636 * v637;
        let v663: f64 = v661 - v662;
        let v664: f64 = v645 * v646;
        let v665: f64 = v663 - v664;
        let v666: f64 = v648 / v665;
        let v667: f64 = tau[1];
        let v668: f64 = v6 * v395;
        let v669: f64 = v21 * v13;
        let v670: f64 = v668 - v669;
        let v671: f64 = v17 * v176;
        let v672: f64 = v670 + v671;
        let v673: f64 = v672 + v604;
        let v674: f64 = v51 * v410;
        let v675: f64 = v673 + v674;
        let v676: f64 = v667 - v675;
        let v677: f64 = v676 - v545;
        let v678: f64 = v677 - v547;
        let v679: f64 = v637 * v548;
        let v680: f64 = v678 - v679;
        let v681: f64 = v646 * v609;
        let v682: f64 = v680 - v681;
        let v683: f64 = v666 * v682;
        let v684: f64 = v611 - v683;
        let v685: f64 = 0.00666_f64;
        let v686: f64 = 0.0121682781_f64;
        let v687: f64 = v440 + v686;
        let v688: f64 = v71 + v687;
        let v689: f64 = v70 * v688;
        let v690: f64 = v689 - v448;
        let v691: f64 = v690 * v70;
        let v692: f64 = v470 * v97;
        let v693: f64 = v70 * v692;
        let v694: f64 = v481 * v97;
        let v695: f64 = v484 * v99;
        let v696: f64 = v694 + v695;
        let v697: f64 = v696 + v686;
        let v698: f64 = v88 + v697;
        let v699: f64 = v73 * v698;
        let v700: f64 = v693 - v699;
        let v701: f64 = v700 * v73;
        let v702: f64 = v691 - v701;
        let v703: f64 = v702 + v588;
        let v704: f64 = v29 + v703;
        let v705: f64 = v28 * v704;
        let v706: f64 = v70 * v698;
        let v707: f64 = v73 * v692;
        let v708: f64 = v706 + v707;
        let v709: f64 = v708 * v73;
        let v710: f64 = v73 * v688;
        let v711: f64 = v451 + v710;
        let v712: f64 = v711 * v70;
        let v713: f64 = v709 - v712;
        let v714: f64 = v196 * v498;
        let v715: f64 = v713 - v714;
        let v716: f64 = v31 * v715;
        let v717: f64 = v705 + v716;
        let v718: f64 = v717 * v28;
        let v719: f64 = v708 * v70;
        let v720: f64 = v711 * v73;
        let v721: f64 = v719 + v720;
        let v722: f64 = v721 + v588;
        let v723: f64 = v722 - v585;
        let v724: f64 = v723 + v578;
        let v725: f64 = v724 + v578;
        let v726: f64 = v45 + v725;
        let v727: f64 = v31 * v726;
        let v728: f64 = v700 * v70;
        let v729: f64 = v690 * v73;
        let v730: f64 = v728 + v729;
        let v731: f64 = v730 + v714;
        let v732: f64 = v28 * v731;
        let v733: f64 = v727 - v732;
        let v734: f64 = v733 * v31;
        let v735: f64 = v718 + v734;
        let v736: f64 = v735 + v653;
        let v737: f64 = v3 + v736;
        let v738: f64 = v2 * v737;
        let v739: f64 = v28 * v715;
        let v740: f64 = v31 * v704;
        let v741: f64 = v739 - v740;
        let v742: f64 = v741 * v28;
        let v743: f64 = v31 * v731;
        let v744: f64 = v28 * v726;
        let v745: f64 = v743 + v744;
        let v746: f64 = v745 * v31;
        let v747: f64 = v742 + v746;
        let v748: f64 = v51 * v618;
        let v749: f64 = v747 - v748;
        let v750: f64 = v4 * v749;
        let v751: f64 = v738 + v750;
        let v752: f64 = v751 * v2;
        let v753: f64 = v733 * v28;
        let v754: f64 = v717 * v31;
        let v755: f64 = v753 - v754;
        let v756: f64 = v755 - v748;
        let v757: f64 = v2 * v756;
        let v758: f64 = v745 * v28;
        let v759: f64 = v741 * v31;
        let v760: f64 = v758 - v759;
        let v761: f64 = v760 + v653;
        let v762: f64 = 0.8852250624999999_f64;
        let v763: f64 = v761 - v762;
        let v764: f64 = v763 - v640;
        let v765: f64 = v764 - v640;
        let v766: f64 = v12 + v765;
        let v767: f64 = v4 * v766;
        let v768: f64 = v757 + v767;
        let v769: f64 = v768 * v4;
        let v770: f64 = v752 + v769;
        let v771: f64 = 0.12150210104175002_f64;
        let v772: f64 = v770 + v771;
        let v773: f64 = v685 + v772;
        let v774: f64 = v429 * v430;
        let v775: f64 = v773 - v774;
        let v776: f64 = v461 * v462;
        let v777: f64 = v775 - v776;
        let v778: f64 = v523 * v535;
        let v779: f64 = v777 - v778;
        let v780: f64 = v584 * v595;
        let v781: f64 = v779 - v780;
        let v782: f64 = v648 * v666;
        let v783: f64 = v781 - v782;
        let v784: f64 = v684 / v783;
        let v785: f64 = v682 / v665;
        let v786: f64 = v666 * v784;
        let v787: f64 = v785 - v786;
        let v788: f64 = v609 / v594;
        let v789: f64 = v595 * v784;
        let v790: f64 = v788 - v789;
        let v791: f64 = v646 * v787;
        let v792: f64 = v790 - v791;
        let v793: f64 = v548 / v534;
        let v794: f64 = v535 * v784;
        let v795: f64 = v793 - v794;
        let v796: f64 = v637 * v787;
        let v797: f64 = v795 - v796;
        let v798: f64 = v582 * v792;
        let v799: f64 = v797 - v798;
        let v800: f64 = v464 / v440;
        let v801: f64 = v462 * v784;
        let v802: f64 = v800 - v801;
        let v803: f64 = v521 * v787;
        let v804: f64 = v802 - v803;
        let v805: f64 = v521 * v792;
        let v806: f64 = v804 - v805;
        let v807: f64 = v521 * v799;
        let v808: f64 = v806 - v807;
        let v809: f64 = v417 * v432;
        let v810: f64 = v430 * v784;
        let v811: f64 = v809 + v810;
        let v812: f64 = v97 * v787;
        let v813: f64 = v811 - v812;
        let v814: f64 = v97 * v792;
        let v815: f64 = v813 - v814;
        let v816: f64 = v97 * v799;
        let v817: f64 = v815 - v816;
        (v784, v787, v792, v799, v808, v817)
    };
    [v784, v787, v792, v799, v808, v817]
}
/// Mass matrix and bias in one pass: row i is `[M_i0, ..., M_i(n-1), c_i + g_i]`, the `M(q)` of `mass_matrix` with the bias `c(q, qd) + g(q)` of `coriolis` and `gravity` as a last column (what Pinocchio's `crba` and `nonLinearEffects` compute together). Common subexpressions, sin/cos included, are computed once for both.
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 6]`: joint velocities qd (rad/s or m/s)
///
/// # Output
///
/// `mass_matrix_and_bias: [[f64; 7]; 6]` (6 x 7, row-major): rows `[M(q) | c(q, qd) + g(q)]`: the symmetric positive definite M (kg m^2, kg m, kg), then the bias (N m or N)
///
/// Operation count: 635 floating-point operations, 10 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn mass_matrix_and_bias(q: &[f64; 6], qd: &[f64; 6]) -> [[f64; 7]; 6] {
    let (
        v2,
        v3,
        v5,
        v6,
        v8,
        v9,
        v10,
        v12,
        v15,
        v16,
        v20,
        v25,
        v27,
        v32,
        v34,
        v42,
        v48,
        v51,
        v52,
        v64,
        v66,
        v67,
        v69,
        v73,
        v78,
        v89,
        v108,
        v109,
        v110,
        v115,
        v116,
        v117,
        v120,
        v124,
        v134,
        v135,
        v136,
        v147,
        v163,
        v166,
        v170,
        v172,
        v173,
    ) = {
        let v0: f64 = 0.00666_f64;
        let v1: f64 = q[1];
        let (v124, v2): (f64, f64) = ::libm::sincos(v1);
        let v3: f64 = 0.88490187591_f64;
        let v4: f64 = q[2];
        let (v73, v5): (f64, f64) = ::libm::sincos(v4);
        let v6: f64 = 0.191630813556_f64;
        let v7: f64 = q[3];
        let (v25, v8): (f64, f64) = ::libm::sincos(v7);
        let v9: f64 = 0.21942_f64;
        let v10: f64 = 0.0171364731454_f64;
        let v11: f64 = q[5];
        let (v12, v16): (f64, f64) = ::libm::sincos(v11);
        let v13: f64 = v10 * v12;
        let v14: f64 = v13 * v12;
        let v15: f64 = 0.033822_f64;
        let v17: f64 = v15 * v16;
        let v18: f64 = v17 * v16;
        let v19: f64 = v14 + v18;
        let v20: f64 = v9 + v19;
        let v21: f64 = 0.0121682781_f64;
        let v22: f64 = v20 + v21;
        let v23: f64 = v9 + v22;
        let v24: f64 = v8 * v23;
        let v26: f64 = q[4];
        let (v52, v27): (f64, f64) = ::libm::sincos(v26);
        let v28: f64 = v15 * v12;
        let v29: f64 = v28 * v16;
        let v30: f64 = v10 * v16;
        let v31: f64 = v30 * v12;
        let v32: f64 = v29 - v31;
        let v33: f64 = v27 * v32;
        let v34: f64 = v25 * v33;
        let v35: f64 = v24 - v34;
        let v36: f64 = v35 * v8;
        let v37: f64 = v17 * v12;
        let v38: f64 = v13 * v16;
        let v39: f64 = v37 - v38;
        let v40: f64 = v39 * v27;
        let v41: f64 = v8 * v40;
        let v42: f64 = 0.111172755531_f64;
        let v43: f64 = v30 * v16;
        let v44: f64 = v28 * v12;
        let v45: f64 = v43 + v44;
        let v46: f64 = 0.00168332516775_f64;
        let v47: f64 = v45 + v46;
        let v48: f64 = v42 + v47;
        let v49: f64 = v27 * v48;
        let v50: f64 = v49 * v27;
        let v51: f64 = 0.12999255384415_f64;
        let v53: f64 = v51 * v52;
        let v54: f64 = v53 * v52;
        let v55: f64 = v50 + v54;
        let v56: f64 = v55 + v21;
        let v57: f64 = v42 + v56;
        let v58: f64 = v25 * v57;
        let v59: f64 = v41 - v58;
        let v60: f64 = v59 * v25;
        let v61: f64 = v36 - v60;
        let v62: f64 = 0.40402113811874996_f64;
        let v63: f64 = 2.0_f64;
        let v64: f64 = 0.39225_f64;
        let v65: f64 = 0.017784735_f64;
        let v66: f64 = v65 * v25;
        let v67: f64 = v64 * v66;
        let v68: f64 = v63 * v67;
        let v69: f64 = v62 - v68;
        let v70: f64 = v61 + v69;
        let v71: f64 = v6 + v70;
        let v72: f64 = v5 * v71;
        let v74: f64 = v8 * v57;
        let v75: f64 = v25 * v40;
        let v76: f64 = v74 + v75;
        let v77: f64 = v76 * v25;
        let v78: f64 = v8 * v33;
        let v79: f64 = v25 * v23;
        let v80: f64 = v78 + v79;
        let v81: f64 = v80 * v8;
        let v82: f64 = v77 - v81;
        let v83: f64 = v65 * v8;
        let v84: f64 = v64 * v83;
        let v85: f64 = v82 - v84;
        let v86: f64 = v73 * v85;
        let v87: f64 = v72 + v86;
        let v88: f64 = v87 * v5;
        let v89: f64 = 0.004095_f64;
        let v90: f64 = v76 * v8;
        let v91: f64 = v80 * v25;
        let v92: f64 = v90 + v91;
        let v93: f64 = v92 + v69;
        let v94: f64 = v93 - v62;
        let v95: f64 = v94 + v67;
        let v96: f64 = v95 + v67;
        let v97: f64 = v89 + v96;
        let v98: f64 = v73 * v97;
        let v99: f64 = v59 * v8;
        let v100: f64 = v35 * v25;
        let v101: f64 = v99 + v100;
        let v102: f64 = v101 + v84;
        let v103: f64 = v5 * v102;
        let v104: f64 = v98 - v103;
        let v105: f64 = v104 * v73;
        let v106: f64 = v88 + v105;
        let v107: f64 = 0.9554455987809999_f64;
        let v108: f64 = -0.01566175149_f64;
        let v109: f64 = 0.425_f64;
        let v110: f64 = 0.56875_f64;
        let v111: f64 = 1.030009275_f64;
        let v112: f64 = v111 - v66;
        let v113: f64 = v110 + v112;
        let v114: f64 = v5 * v113;
        let v115: f64 = v73 * v83;
        let v116: f64 = v114 - v115;
        let v117: f64 = v109 * v116;
        let v118: f64 = v108 + v117;
        let v119: f64 = v63 * v118;
        let v120: f64 = v107 + v119;
        let v121: f64 = v106 + v120;
        let v122: f64 = v3 + v121;
        let v123: f64 = v2 * v122;
        let v125: f64 = v5 * v85;
        let v126: f64 = v73 * v71;
        let v127: f64 = v125 - v126;
        let v128: f64 = v127 * v5;
        let v129: f64 = v73 * v102;
        let v130: f64 = v5 * v97;
        let v131: f64 = v129 + v130;
        let v132: f64 = v131 * v73;
        let v133: f64 = v128 + v132;
        let v134: f64 = v5 * v83;
        let v135: f64 = v73 * v113;
        let v136: f64 = v134 + v135;
        let v137: f64 = v109 * v136;
        let v138: f64 = v133 - v137;
        let v139: f64 = v124 * v138;
        let v140: f64 = v123 + v139;
        let v141: f64 = v140 * v2;
        let v142: f64 = v104 * v5;
        let v143: f64 = v87 * v73;
        let v144: f64 = v142 - v143;
        let v145: f64 = v144 - v137;
        let v146: f64 = v2 * v145;
        let v147: f64 = 0.0151074_f64;
        let v148: f64 = v131 * v5;
        let v149: f64 = v127 * v73;
        let v150: f64 = v148 - v149;
        let v151: f64 = v150 + v120;
        let v152: f64 = 0.8852250624999999_f64;
        let v153: f64 = v151 - v152;
        let v154: f64 = v153 - v117;
        let v155: f64 = v154 - v117;
        let v156: f64 = v147 + v155;
        let v157: f64 = v124 * v156;
        let v158: f64 = v146 + v157;
        let v159: f64 = v158 * v124;
        let v160: f64 = v141 + v159;
        let v161: f64 = 0.12150210104175002_f64;
        let v162: f64 = v160 + v161;
        let v163: f64 = v0 + v162;
        let v164: f64 = v39 * v52;
        let v165: f64 = 0.0016539803549999999_f64;
        let v166: f64 = v164 - v165;
        let v167: f64 = v8 * v166;
        let v168: f64 = v49 * v52;
        let v169: f64 = v53 * v27;
        let v170: f64 = v168 - v169;
        let v171: f64 = v25 * v170;
        let v172: f64 = v167 - v171;
        let v173: f64 = v73 * v172;
        (
            v2,
            v3,
            v5,
            v6,
            v8,
            v9,
            v10,
            v12,
            v15,
            v16,
            v20,
            v25,
            v27,
            v32,
            v34,
            v42,
            v48,
            v51,
            v52,
            v64,
            v66,
            v67,
            v69,
            v73,
            v78,
            v89,
            v108,
            v109,
            v110,
            v115,
            v116,
            v117,
            v120,
            v124,
            v134,
            v135,
            v136,
            v147,
            v163,
            v166,
            v170,
            v172,
            v173,
        )
    };
    let (
        v183,
        v196,
        v197,
        v205,
        v217,
        v226,
        v238,
        v251,
        v264,
        v266,
        v267,
        v268,
        v270,
        v272,
        v276,
        v278,
        v279,
        v283,
        v285,
        v290,
        v293,
        v295,
        v296,
        v298,
        v303,
        v307,
        v311,
        v312,
        v315,
        v317,
        v323,
        v328,
        v329,
        v331,
        v332,
        v333,
        v334,
        v336,
        v339,
        v342,
        v345,
        v346,
        v347,
    ) = {
        let v174: f64 = v8 * v170;
        let v175: f64 = v25 * v166;
        let v176: f64 = v174 + v175;
        let v177: f64 = 0.051322656825_f64;
        let v178: f64 = v176 + v177;
        let v179: f64 = v5 * v178;
        let v180: f64 = v173 + v179;
        let v181: f64 = -0.24932103525000002_f64;
        let v182: f64 = v180 + v181;
        let v183: f64 = -0.1197_f64;
        let v184: f64 = v183 * v116;
        let v185: f64 = v182 + v184;
        let v186: f64 = 0.0556077225_f64;
        let v187: f64 = v185 + v186;
        let v188: f64 = v124 * v187;
        let v189: f64 = v5 * v172;
        let v190: f64 = v73 * v178;
        let v191: f64 = v189 - v190;
        let v192: f64 = v183 * v136;
        let v193: f64 = v191 - v192;
        let v194: f64 = v2 * v193;
        let v195: f64 = v188 - v194;
        let v196: f64 = 0.13585_f64;
        let v197: f64 = 2.35004_f64;
        let v198: f64 = 2.0828824999999997_f64;
        let v199: f64 = v116 + v198;
        let v200: f64 = v197 + v199;
        let v201: f64 = v124 * v200;
        let v202: f64 = v2 * v136;
        let v203: f64 = v201 + v202;
        let v204: f64 = v196 * v203;
        let v205: f64 = v195 + v204;
        let v206: f64 = v180 + v184;
        let v207: f64 = v124 * v206;
        let v208: f64 = v135 + v134;
        let v209: f64 = v183 * v208;
        let v210: f64 = v191 - v209;
        let v211: f64 = v2 * v210;
        let v212: f64 = v207 - v211;
        let v213: f64 = v124 * v116;
        let v214: f64 = v2 * v208;
        let v215: f64 = v213 + v214;
        let v216: f64 = v196 * v215;
        let v217: f64 = v212 + v216;
        let v218: f64 = v73 * v176;
        let v219: f64 = v189 - v218;
        let v220: f64 = v73 * v66;
        let v221: f64 = v220 - v134;
        let v222: f64 = v183 * v221;
        let v223: f64 = v219 + v222;
        let v224: f64 = v2 * v223;
        let v225: f64 = v5 * v66;
        let v226: f64 = v225 + v115;
        let v227: f64 = v183 * v226;
        let v228: f64 = v5 * v176;
        let v229: f64 = v173 + v228;
        let v230: f64 = v227 - v229;
        let v231: f64 = v124 * v230;
        let v232: f64 = v224 + v231;
        let v233: f64 = v124 * v226;
        let v234: f64 = v2 * v221;
        let v235: f64 = v233 + v234;
        let v236: f64 = v196 * v235;
        let v237: f64 = v232 + v236;
        let v238: f64 = -v237;
        let v239: f64 = v8 * v20;
        let v240: f64 = v239 - v34;
        let v241: f64 = v73 * v240;
        let v242: f64 = v25 * v20;
        let v243: f64 = v78 + v242;
        let v244: f64 = v5 * v243;
        let v245: f64 = v241 + v244;
        let v246: f64 = v124 * v245;
        let v247: f64 = v5 * v240;
        let v248: f64 = v73 * v243;
        let v249: f64 = v247 - v248;
        let v250: f64 = v2 * v249;
        let v251: f64 = v246 - v250;
        let v252: f64 = v10 * v52;
        let v253: f64 = v25 * v252;
        let v254: f64 = v5 * v253;
        let v255: f64 = v8 * v252;
        let v256: f64 = v73 * v255;
        let v257: f64 = v254 + v256;
        let v258: f64 = v2 * v257;
        let v259: f64 = v5 * v255;
        let v260: f64 = v73 * v253;
        let v261: f64 = v259 - v260;
        let v262: f64 = v124 * v261;
        let v263: f64 = v258 + v262;
        let v264: f64 = -v263;
        let v265: f64 = qd[0];
        let v266: f64 = v124 * v265;
        let v267: f64 = qd[1];
        let v268: f64 = v266 * v267;
        let v269: f64 = v3 * v268;
        let v270: f64 = v3 * v267;
        let v271: f64 = v266 * v270;
        let v272: f64 = v147 * v266;
        let v273: f64 = v267 * v272;
        let v274: f64 = v271 - v273;
        let v275: f64 = v269 + v274;
        let v276: f64 = v196 * v266;
        let v277: f64 = v266 * v276;
        let v278: f64 = v2 * v265;
        let v279: f64 = v196 * v278;
        let v280: f64 = v278 * v279;
        let v281: f64 = v277 + v280;
        let v282: f64 = v197 * v281;
        let v283: f64 = v275 + v282;
        let v284: f64 = v5 * v268;
        let v285: f64 = v278 * v267;
        let v286: f64 = v73 * v285;
        let v287: f64 = v284 + v286;
        let v288: f64 = v73 * v278;
        let v289: f64 = v5 * v266;
        let v290: f64 = v288 + v289;
        let v291: f64 = qd[2];
        let v292: f64 = v290 * v291;
        let v293: f64 = v287 + v292;
        let v294: f64 = v6 * v293;
        let v295: f64 = v267 + v291;
        let v296: f64 = v6 * v295;
        let v297: f64 = v290 * v296;
        let v298: f64 = v89 * v290;
        let v299: f64 = v295 * v298;
        let v300: f64 = v297 - v299;
        let v301: f64 = v294 + v300;
        let v302: f64 = v109 * v268;
        let v303: f64 = v109 * v267;
        let v304: f64 = v266 * v303;
        let v305: f64 = v302 + v304;
        let v306: f64 = v281 + v305;
        let v307: f64 = v183 * v290;
        let v308: f64 = v290 * v307;
        let v309: f64 = v73 * v266;
        let v310: f64 = v5 * v278;
        let v311: f64 = v309 - v310;
        let v312: f64 = v183 * v311;
        let v313: f64 = v311 * v312;
        let v314: f64 = v308 + v313;
        let v315: f64 = v306 + v314;
        let v316: f64 = v110 * v315;
        let v317: f64 = v301 + v316;
        let v318: f64 = v8 * v293;
        let v319: f64 = v73 * v268;
        let v320: f64 = v5 * v285;
        let v321: f64 = v319 - v320;
        let v322: f64 = v311 * v291;
        let v323: f64 = v321 + v322;
        let v324: f64 = v25 * v323;
        let v325: f64 = v318 - v324;
        let v326: f64 = v8 * v290;
        let v327: f64 = v25 * v311;
        let v328: f64 = v326 - v327;
        let v329: f64 = qd[3];
        let v330: f64 = v328 * v329;
        let v331: f64 = v325 + v330;
        let v332: f64 = v9 * v331;
        let v333: f64 = v295 + v329;
        let v334: f64 = v42 * v333;
        let v335: f64 = v328 * v334;
        let v336: f64 = v42 * v328;
        let v337: f64 = v333 * v336;
        let v338: f64 = v335 - v337;
        let v339: f64 = v332 + v338;
        let v340: f64 = v27 * v328;
        let v341: f64 = v52 * v333;
        let v342: f64 = v340 + v341;
        let v343: f64 = v27 * v333;
        let v344: f64 = v52 * v328;
        let v345: f64 = v343 - v344;
        let v346: f64 = v42 * v345;
        let v347: f64 = v342 * v346;
        (
            v183,
            v196,
            v197,
            v205,
            v217,
            v226,
            v238,
            v251,
            v264,
            v266,
            v267,
            v268,
            v270,
            v272,
            v276,
            v278,
            v279,
            v283,
            v285,
            v290,
            v293,
            v295,
            v296,
            v298,
            v303,
            v307,
            v311,
            v312,
            v315,
            v317,
            v323,
            v328,
            v329,
            v331,
            v332,
            v333,
            v334,
            v336,
            v339,
            v342,
            v345,
            v346,
            v347,
        )
    };
    let (
        v348,
        v359,
        v368,
        v370,
        v378,
        v381,
        v388,
        v392,
        v396,
        v399,
        v401,
        v402,
        v412,
        v421,
        v431,
        v442,
        v449,
        v455,
        v465,
        v468,
        v477,
        v481,
        v489,
        v494,
        v496,
        v497,
        v506,
        v508,
        v510,
        v512,
        v513,
        v514,
        v519,
        v520,
        v521,
    ) = {
        let v348: f64 = v42 * v342;
        let v349: f64 = v345 * v348;
        let v350: f64 = v347 - v349;
        let v351: f64 = v332 + v350;
        let v352: f64 = qd[4];
        let v353: f64 = v345 * v352;
        let v354: f64 = v25 * v293;
        let v355: f64 = v8 * v323;
        let v356: f64 = v354 + v355;
        let v357: f64 = v8 * v311;
        let v358: f64 = v25 * v290;
        let v359: f64 = v357 + v358;
        let v360: f64 = v359 * v329;
        let v361: f64 = v356 + v360;
        let v362: f64 = v27 * v361;
        let v363: f64 = v353 - v362;
        let v364: f64 = v12 * v363;
        let v365: f64 = v16 * v331;
        let v366: f64 = v364 + v365;
        let v367: f64 = v16 * v342;
        let v368: f64 = v359 + v352;
        let v369: f64 = v12 * v368;
        let v370: f64 = v367 - v369;
        let v371: f64 = qd[5];
        let v372: f64 = v370 * v371;
        let v373: f64 = v366 + v372;
        let v374: f64 = v15 * v373;
        let v375: f64 = v345 + v371;
        let v376: f64 = v10 * v375;
        let v377: f64 = v370 * v376;
        let v378: f64 = v10 * v370;
        let v379: f64 = v375 * v378;
        let v380: f64 = v377 - v379;
        let v381: f64 = v374 + v380;
        let v382: f64 = v16 * v381;
        let v383: f64 = v16 * v363;
        let v384: f64 = v12 * v331;
        let v385: f64 = v383 - v384;
        let v386: f64 = v12 * v342;
        let v387: f64 = v16 * v368;
        let v388: f64 = v386 + v387;
        let v389: f64 = v388 * v371;
        let v390: f64 = v385 - v389;
        let v391: f64 = v10 * v390;
        let v392: f64 = v15 * v388;
        let v393: f64 = v375 * v392;
        let v394: f64 = v388 * v376;
        let v395: f64 = v393 - v394;
        let v396: f64 = v391 + v395;
        let v397: f64 = v12 * v396;
        let v398: f64 = v382 - v397;
        let v399: f64 = v351 + v398;
        let v400: f64 = v339 + v399;
        let v401: f64 = 0.093_f64;
        let v402: f64 = 1.219_f64;
        let v403: f64 = v401 * v328;
        let v404: f64 = v333 * v403;
        let v405: f64 = v401 * v331;
        let v406: f64 = v404 - v405;
        let v407: f64 = v196 * v285;
        let v408: f64 = v267 * v279;
        let v409: f64 = v407 - v408;
        let v410: f64 = 9.81_f64;
        let v411: f64 = v410 * v2;
        let v412: f64 = v409 - v411;
        let v413: f64 = v109 * v278;
        let v414: f64 = v266 * v413;
        let v415: f64 = v412 + v414;
        let v416: f64 = v5 * v415;
        let v417: f64 = v196 * v268;
        let v418: f64 = v267 * v276;
        let v419: f64 = v417 - v418;
        let v420: f64 = v410 * v124;
        let v421: f64 = v419 - v420;
        let v422: f64 = v278 * v413;
        let v423: f64 = v267 * v303;
        let v424: f64 = v422 + v423;
        let v425: f64 = v421 - v424;
        let v426: f64 = v73 * v425;
        let v427: f64 = v416 - v426;
        let v428: f64 = v295 * v312;
        let v429: f64 = v183 * v323;
        let v430: f64 = v428 - v429;
        let v431: f64 = v427 + v430;
        let v432: f64 = v64 * v311;
        let v433: f64 = v290 * v432;
        let v434: f64 = v431 - v433;
        let v435: f64 = v25 * v434;
        let v436: f64 = v73 * v415;
        let v437: f64 = v5 * v425;
        let v438: f64 = v436 + v437;
        let v439: f64 = v183 * v293;
        let v440: f64 = v295 * v307;
        let v441: f64 = v439 - v440;
        let v442: f64 = v438 + v441;
        let v443: f64 = v311 * v432;
        let v444: f64 = v64 * v295;
        let v445: f64 = v295 * v444;
        let v446: f64 = v443 + v445;
        let v447: f64 = v442 - v446;
        let v448: f64 = v8 * v447;
        let v449: f64 = v435 + v448;
        let v450: f64 = v406 - v449;
        let v451: f64 = v27 * v450;
        let v452: f64 = v64 * v293;
        let v453: f64 = v290 * v444;
        let v454: f64 = v452 + v453;
        let v455: f64 = v315 + v454;
        let v456: f64 = v401 * v359;
        let v457: f64 = v359 * v456;
        let v458: f64 = v328 * v403;
        let v459: f64 = v457 + v458;
        let v460: f64 = v455 + v459;
        let v461: f64 = v52 * v460;
        let v462: f64 = v451 - v461;
        let v463: f64 = v402 * v462;
        let v464: f64 = 0.1879_f64;
        let v465: f64 = 0.09465_f64;
        let v466: f64 = v52 * v361;
        let v467: f64 = v342 * v352;
        let v468: f64 = v466 - v467;
        let v469: f64 = v465 * v468;
        let v470: f64 = v465 * v342;
        let v471: f64 = v368 * v470;
        let v472: f64 = v469 + v471;
        let v473: f64 = v462 + v472;
        let v474: f64 = v16 * v473;
        let v475: f64 = v8 * v434;
        let v476: f64 = v25 * v447;
        let v477: f64 = v475 - v476;
        let v478: f64 = v333 * v456;
        let v479: f64 = v401 * v361;
        let v480: f64 = v478 - v479;
        let v481: f64 = v477 + v480;
        let v482: f64 = v342 * v470;
        let v483: f64 = v465 * v345;
        let v484: f64 = v345 * v483;
        let v485: f64 = v482 + v484;
        let v486: f64 = v481 - v485;
        let v487: f64 = v12 * v486;
        let v488: f64 = v474 - v487;
        let v489: f64 = v464 * v488;
        let v490: f64 = v16 * v489;
        let v491: f64 = v12 * v473;
        let v492: f64 = v16 * v486;
        let v493: f64 = v491 + v492;
        let v494: f64 = v464 * v493;
        let v495: f64 = v12 * v494;
        let v496: f64 = v490 + v495;
        let v497: f64 = v463 + v496;
        let v498: f64 = v27 * v497;
        let v499: f64 = v368 * v483;
        let v500: f64 = v465 * v363;
        let v501: f64 = v499 - v500;
        let v502: f64 = v52 * v450;
        let v503: f64 = v27 * v460;
        let v504: f64 = v502 + v503;
        let v505: f64 = v501 - v504;
        let v506: f64 = v464 * v505;
        let v507: f64 = v402 * v504;
        let v508: f64 = v506 - v507;
        let v509: f64 = v52 * v508;
        let v510: f64 = v498 - v509;
        let v511: f64 = v401 * v510;
        let v512: f64 = v400 - v511;
        let v513: f64 = v8 * v512;
        let v514: f64 = v9 * v359;
        let v515: f64 = v333 * v514;
        let v516: f64 = v359 * v334;
        let v517: f64 = v515 - v516;
        let v518: f64 = v42 * v361;
        let v519: f64 = v517 - v518;
        let v520: f64 = v42 * v363;
        let v521: f64 = v9 * v368;
        (
            v348,
            v359,
            v368,
            v370,
            v378,
            v381,
            v388,
            v392,
            v396,
            v399,
            v401,
            v402,
            v412,
            v421,
            v431,
            v442,
            v449,
            v455,
            v465,
            v468,
            v477,
            v481,
            v489,
            v494,
            v496,
            v497,
            v506,
            v508,
            v510,
            v512,
            v513,
            v514,
            v519,
            v520,
            v521,
        )
    };
    let (
        v542,
        v651,
        v657,
        v659,
        v665,
        v666,
        v667,
        v669,
        v670,
        v671,
        v688,
        v691,
        v694,
        v695,
    ) = {
        let v522: f64 = v345 * v521;
        let v523: f64 = v368 * v346;
        let v524: f64 = v522 - v523;
        let v525: f64 = v520 + v524;
        let v526: f64 = v16 * v396;
        let v527: f64 = v12 * v381;
        let v528: f64 = v526 + v527;
        let v529: f64 = v525 + v528;
        let v530: f64 = v465 * v506;
        let v531: f64 = v529 - v530;
        let v532: f64 = v27 * v531;
        let v533: f64 = v42 * v468;
        let v534: f64 = v368 * v348;
        let v535: f64 = v342 * v521;
        let v536: f64 = v534 - v535;
        let v537: f64 = v533 + v536;
        let v538: f64 = v10 * v468;
        let v539: f64 = v388 * v378;
        let v540: f64 = v370 * v392;
        let v541: f64 = v539 - v540;
        let v542: f64 = v538 + v541;
        let v543: f64 = v537 + v542;
        let v544: f64 = v465 * v496;
        let v545: f64 = v543 + v544;
        let v546: f64 = v52 * v545;
        let v547: f64 = v532 - v546;
        let v548: f64 = v519 + v547;
        let v549: f64 = v402 * v481;
        let v550: f64 = v16 * v494;
        let v551: f64 = v12 * v489;
        let v552: f64 = v550 - v551;
        let v553: f64 = v549 + v552;
        let v554: f64 = v401 * v553;
        let v555: f64 = v548 + v554;
        let v556: f64 = v25 * v555;
        let v557: f64 = v513 - v556;
        let v558: f64 = v317 + v557;
        let v559: f64 = v52 * v497;
        let v560: f64 = v27 * v508;
        let v561: f64 = v559 + v560;
        let v562: f64 = v402 * v455;
        let v563: f64 = v561 - v562;
        let v564: f64 = v64 * v563;
        let v565: f64 = v558 - v564;
        let v566: f64 = 2.275_f64;
        let v567: f64 = v566 * v442;
        let v568: f64 = v110 * v311;
        let v569: f64 = v311 * v568;
        let v570: f64 = v110 * v295;
        let v571: f64 = v295 * v570;
        let v572: f64 = v569 + v571;
        let v573: f64 = v567 - v572;
        let v574: f64 = v402 * v449;
        let v575: f64 = v510 - v574;
        let v576: f64 = v8 * v575;
        let v577: f64 = v402 * v477;
        let v578: f64 = v577 + v553;
        let v579: f64 = v25 * v578;
        let v580: f64 = v576 + v579;
        let v581: f64 = v573 - v580;
        let v582: f64 = v183 * v581;
        let v583: f64 = v565 + v582;
        let v584: f64 = v5 * v583;
        let v585: f64 = v89 * v323;
        let v586: f64 = v311 * v296;
        let v587: f64 = v6 * v311;
        let v588: f64 = v295 * v587;
        let v589: f64 = v586 - v588;
        let v590: f64 = v585 + v589;
        let v591: f64 = v8 * v555;
        let v592: f64 = v25 * v512;
        let v593: f64 = v591 + v592;
        let v594: f64 = v590 - v593;
        let v595: f64 = v566 * v431;
        let v596: f64 = v290 * v568;
        let v597: f64 = v595 - v596;
        let v598: f64 = v8 * v578;
        let v599: f64 = v25 * v575;
        let v600: f64 = v598 - v599;
        let v601: f64 = v597 + v600;
        let v602: f64 = v183 * v601;
        let v603: f64 = v594 - v602;
        let v604: f64 = v73 * v603;
        let v605: f64 = v584 + v604;
        let v606: f64 = v283 + v605;
        let v607: f64 = v566 * v315;
        let v608: f64 = v110 * v293;
        let v609: f64 = v290 * v570;
        let v610: f64 = v608 + v609;
        let v611: f64 = v607 + v610;
        let v612: f64 = v563 - v611;
        let v613: f64 = v109 * v612;
        let v614: f64 = v606 - v613;
        let v615: f64 = 8.393_f64;
        let v616: f64 = v615 * v421;
        let v617: f64 = v197 * v278;
        let v618: f64 = v278 * v617;
        let v619: f64 = v197 * v267;
        let v620: f64 = v267 * v619;
        let v621: f64 = v618 + v620;
        let v622: f64 = v616 - v621;
        let v623: f64 = v5 * v581;
        let v624: f64 = v73 * v601;
        let v625: f64 = v623 - v624;
        let v626: f64 = v622 + v625;
        let v627: f64 = v196 * v626;
        let v628: f64 = v614 + v627;
        let v629: f64 = v2 * v628;
        let v630: f64 = v3 * v278;
        let v631: f64 = v267 * v630;
        let v632: f64 = v278 * v270;
        let v633: f64 = v631 - v632;
        let v634: f64 = v147 * v285;
        let v635: f64 = v633 - v634;
        let v636: f64 = v5 * v603;
        let v637: f64 = v73 * v583;
        let v638: f64 = v636 - v637;
        let v639: f64 = v635 + v638;
        let v640: f64 = v615 * v412;
        let v641: f64 = v266 * v617;
        let v642: f64 = v640 + v641;
        let v643: f64 = v5 * v601;
        let v644: f64 = v73 * v581;
        let v645: f64 = v643 + v644;
        let v646: f64 = v642 + v645;
        let v647: f64 = v196 * v646;
        let v648: f64 = v639 - v647;
        let v649: f64 = v124 * v648;
        let v650: f64 = v629 + v649;
        let v651: f64 = -v650;
        let v652: f64 = v52 * v48;
        let v653: f64 = v652 * v52;
        let v654: f64 = v51 * v27;
        let v655: f64 = v654 * v27;
        let v656: f64 = v653 + v655;
        let v657: f64 = v42 + v656;
        let v658: f64 = v657 + v69;
        let v659: f64 = v6 + v658;
        let v660: f64 = v659 + v120;
        let v661: f64 = 0.070220536281_f64;
        let v662: f64 = v660 - v661;
        let v663: f64 = v662 - v108;
        let v664: f64 = v663 - v108;
        let v665: f64 = v3 + v664;
        let v666: f64 = v659 + v117;
        let v667: f64 = v657 - v67;
        let v668: f64 = v109 * v226;
        let v669: f64 = v667 - v668;
        let v670: f64 = v52 * v32;
        let v671: f64 = v10 * v27;
        let v672: f64 = v266 * v630;
        let v673: f64 = v278 * v272;
        let v674: f64 = v672 - v673;
        let v675: f64 = v197 * v412;
        let v676: f64 = v674 + v675;
        let v677: f64 = v311 * v298;
        let v678: f64 = v290 * v587;
        let v679: f64 = v677 - v678;
        let v680: f64 = v110 * v431;
        let v681: f64 = v679 + v680;
        let v682: f64 = v359 * v336;
        let v683: f64 = v328 * v514;
        let v684: f64 = v682 - v683;
        let v685: f64 = v52 * v531;
        let v686: f64 = v27 * v545;
        let v687: f64 = v685 + v686;
        let v688: f64 = v684 + v687;
        let v689: f64 = v681 + v688;
        let v690: f64 = v64 * v600;
        let v691: f64 = v689 + v690;
        let v692: f64 = v676 + v691;
        let v693: f64 = v109 * v645;
        let v694: f64 = v692 + v693;
        let v695: f64 = 0.0_f64;
        (
            v542,
            v651,
            v657,
            v659,
            v665,
            v666,
            v667,
            v669,
            v670,
            v671,
            v688,
            v691,
            v694,
            v695,
        )
    };
    [
        [v163, v205, v217, v238, v251, v264, v651],
        [v205, v665, v666, v669, v670, v671, v694],
        [v217, v666, v659, v667, v670, v671, v691],
        [v238, v669, v667, v657, v670, v671, v688],
        [v251, v670, v670, v670, v20, v695, v399],
        [v264, v671, v671, v671, v695, v10, v542],
    ]
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
/// Operation count: 1123 floating-point operations, 10 trig calls.
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
        v7,
        v8,
        v17,
        v20,
        v23,
        v29,
        v32,
        v45,
        v47,
        v59,
        v66,
        v71,
        v79,
        v87,
        v88,
        v94,
        v97,
        v99,
        v100,
        v107,
        v116,
        v120,
        v127,
        v130,
        v136,
        v138,
        v146,
        v151,
        v152,
        v162,
        v166,
        v172,
        v174,
        v176,
        v180,
        v187,
        v191,
        v193,
    ) = {
        let v0: f64 = qdd[0];
        let v1: f64 = 0.13585_f64;
        let v2: f64 = q[1];
        let (v3, v5): (f64, f64) = ::libm::sincos(v2);
        let v4: f64 = v3 * v0;
        let v6: f64 = qd[0];
        let v7: f64 = v5 * v6;
        let v8: f64 = qd[1];
        let v9: f64 = v7 * v8;
        let v10: f64 = v4 + v9;
        let v11: f64 = v1 * v10;
        let v12: f64 = v1 * v7;
        let v13: f64 = v8 * v12;
        let v14: f64 = v11 - v13;
        let v15: f64 = 9.81_f64;
        let v16: f64 = v15 * v5;
        let v17: f64 = v14 - v16;
        let v18: f64 = v1 * v3;
        let v19: f64 = v17 * v18;
        let v20: f64 = v3 * v6;
        let v21: f64 = v20 * v8;
        let v22: f64 = v5 * v0;
        let v23: f64 = v21 - v22;
        let v24: f64 = v1 * v23;
        let v25: f64 = v1 * v20;
        let v26: f64 = v8 * v25;
        let v27: f64 = v24 - v26;
        let v28: f64 = v15 * v3;
        let v29: f64 = v27 - v28;
        let v30: f64 = v1 * v5;
        let v31: f64 = v29 * v30;
        let v32: f64 = v19 - v31;
        let v33: f64 = v20 * v25;
        let v34: f64 = v7 * v12;
        let v35: f64 = v33 + v34;
        let v36: f64 = v35 * v3;
        let v37: f64 = v8 * v18;
        let v38: f64 = v8 * v37;
        let v39: f64 = v36 - v38;
        let v40: f64 = v20 * v18;
        let v41: f64 = v7 * v30;
        let v42: f64 = v40 + v41;
        let v43: f64 = v20 * v42;
        let v44: f64 = v39 - v43;
        let v45: f64 = qdd[1];
        let v46: f64 = v45 * v30;
        let v47: f64 = v44 + v46;
        let v48: f64 = v10 * v18;
        let v49: f64 = v7 * v37;
        let v50: f64 = v48 - v49;
        let v51: f64 = v17 * v3;
        let v52: f64 = v50 + v51;
        let v53: f64 = v8 * v30;
        let v54: f64 = v20 * v53;
        let v55: f64 = v52 + v54;
        let v56: f64 = v23 * v30;
        let v57: f64 = v55 - v56;
        let v58: f64 = v29 * v5;
        let v59: f64 = v57 - v58;
        let v60: f64 = v45 * v18;
        let v61: f64 = v8 * v53;
        let v62: f64 = v60 + v61;
        let v63: f64 = v7 * v42;
        let v64: f64 = v62 + v63;
        let v65: f64 = v35 * v5;
        let v66: f64 = v64 - v65;
        let v67: f64 = v8 * v3;
        let v68: f64 = v7 * v67;
        let v69: f64 = v23 * v5;
        let v70: f64 = v68 + v69;
        let v71: f64 = -v70;
        let v72: f64 = v8 * v67;
        let v73: f64 = v7 * v3;
        let v74: f64 = v20 * v5;
        let v75: f64 = v73 - v74;
        let v76: f64 = v7 * v75;
        let v77: f64 = v72 - v76;
        let v78: f64 = v45 * v5;
        let v79: f64 = v77 - v78;
        let v80: f64 = v8 * v5;
        let v81: f64 = v7 * v80;
        let v82: f64 = v20 * v67;
        let v83: f64 = v23 * v3;
        let v84: f64 = v82 + v83;
        let v85: f64 = v81 - v84;
        let v86: f64 = v10 * v5;
        let v87: f64 = v85 + v86;
        let v88: f64 = v8 * v75;
        let v89: f64 = v45 * v3;
        let v90: f64 = v20 * v75;
        let v91: f64 = v89 + v90;
        let v92: f64 = v8 * v80;
        let v93: f64 = v91 + v92;
        let v94: f64 = -v93;
        let v95: f64 = v10 * v3;
        let v96: f64 = v20 * v80;
        let v97: f64 = v95 + v96;
        let v98: f64 = q[2];
        let (v107, v99): (f64, f64) = ::libm::sincos(v98);
        let v100: f64 = 0.425_f64;
        let v101: f64 = v100 * v45;
        let v102: f64 = v100 * v7;
        let v103: f64 = v20 * v102;
        let v104: f64 = v101 + v103;
        let v105: f64 = v17 + v104;
        let v106: f64 = v99 * v105;
        let v108: f64 = v7 * v102;
        let v109: f64 = v100 * v8;
        let v110: f64 = v8 * v109;
        let v111: f64 = v108 + v110;
        let v112: f64 = v29 - v111;
        let v113: f64 = v107 * v112;
        let v114: f64 = v106 - v113;
        let v115: f64 = qd[2];
        let v116: f64 = v8 + v115;
        let v117: f64 = -0.1197_f64;
        let v118: f64 = v107 * v20;
        let v119: f64 = v99 * v7;
        let v120: f64 = v118 - v119;
        let v121: f64 = v117 * v120;
        let v122: f64 = v116 * v121;
        let v123: f64 = v107 * v23;
        let v124: f64 = v99 * v10;
        let v125: f64 = v123 - v124;
        let v126: f64 = v120 * v115;
        let v127: f64 = v125 + v126;
        let v128: f64 = v117 * v127;
        let v129: f64 = v122 - v128;
        let v130: f64 = v114 + v129;
        let v131: f64 = v99 * v18;
        let v132: f64 = v107 * v30;
        let v133: f64 = v131 + v132;
        let v134: f64 = v99 * v3;
        let v135: f64 = v107 * v5;
        let v136: f64 = v134 + v135;
        let v137: f64 = v117 * v136;
        let v138: f64 = v133 + v137;
        let v139: f64 = v130 * v138;
        let v140: f64 = v100 * v23;
        let v141: f64 = v20 * v109;
        let v142: f64 = v140 + v141;
        let v143: f64 = v35 + v142;
        let v144: f64 = v107 * v7;
        let v145: f64 = v99 * v20;
        let v146: f64 = v144 + v145;
        let v147: f64 = v117 * v146;
        let v148: f64 = v146 * v147;
        let v149: f64 = v120 * v121;
        let v150: f64 = v148 + v149;
        let v151: f64 = v143 + v150;
        let v152: f64 = v100 * v5;
        let v153: f64 = v151 * v152;
        let v154: f64 = v139 - v153;
        let v155: f64 = v107 * v105;
        let v156: f64 = v99 * v112;
        let v157: f64 = v155 + v156;
        let v158: f64 = v99 * v23;
        let v159: f64 = v107 * v10;
        let v160: f64 = v158 + v159;
        let v161: f64 = v146 * v115;
        let v162: f64 = v160 + v161;
        let v163: f64 = v117 * v162;
        let v164: f64 = v116 * v147;
        let v165: f64 = v163 - v164;
        let v166: f64 = v157 + v165;
        let v167: f64 = v107 * v18;
        let v168: f64 = v99 * v30;
        let v169: f64 = v167 - v168;
        let v170: f64 = v107 * v3;
        let v171: f64 = v99 * v5;
        let v172: f64 = v170 - v171;
        let v173: f64 = v117 * v172;
        let v174: f64 = v169 + v173;
        let v175: f64 = v166 * v174;
        let v176: f64 = v154 + v175;
        let v177: f64 = v127 * v152;
        let v178: f64 = v116 * v138;
        let v179: f64 = v120 * v152;
        let v180: f64 = v178 - v179;
        let v181: f64 = v116 * v180;
        let v182: f64 = v177 - v181;
        let v183: f64 = v151 * v136;
        let v184: f64 = v182 + v183;
        let v185: f64 = v146 * v138;
        let v186: f64 = v120 * v174;
        let v187: f64 = v185 + v186;
        let v188: f64 = v146 * v187;
        let v189: f64 = v184 - v188;
        let v190: f64 = qdd[2];
        let v191: f64 = v45 + v190;
        let v192: f64 = v191 * v174;
        let v193: f64 = v189 - v192;
        (
            v0,
            v4,
            v7,
            v8,
            v17,
            v20,
            v23,
            v29,
            v32,
            v45,
            v47,
            v59,
            v66,
            v71,
            v79,
            v87,
            v88,
            v94,
            v97,
            v99,
            v100,
            v107,
            v116,
            v120,
            v127,
            v130,
            v136,
            v138,
            v146,
            v151,
            v152,
            v162,
            v166,
            v172,
            v174,
            v176,
            v180,
            v187,
            v191,
            v193,
        )
    };
    let (
        v207,
        v216,
        v220,
        v228,
        v236,
        v237,
        v242,
        v246,
        v248,
        v249,
        v256,
        v263,
        v270,
        v273,
        v279,
        v281,
        v283,
        v286,
        v289,
        v295,
        v299,
        v309,
        v314,
        v316,
        v322,
        v334,
        v338,
        v347,
        v352,
        v360,
        v368,
        v369,
        v374,
        v377,
        v378,
        v379,
        v383,
        v385,
        v386,
        v387,
    ) = {
        let v194: f64 = v120 * v180;
        let v195: f64 = v127 * v138;
        let v196: f64 = v194 - v195;
        let v197: f64 = v130 * v136;
        let v198: f64 = v196 + v197;
        let v199: f64 = v146 * v152;
        let v200: f64 = v116 * v174;
        let v201: f64 = v199 + v200;
        let v202: f64 = v146 * v201;
        let v203: f64 = v198 - v202;
        let v204: f64 = v162 * v174;
        let v205: f64 = v203 + v204;
        let v206: f64 = v166 * v172;
        let v207: f64 = v205 + v206;
        let v208: f64 = v191 * v138;
        let v209: f64 = v162 * v152;
        let v210: f64 = v208 - v209;
        let v211: f64 = v116 * v201;
        let v212: f64 = v210 - v211;
        let v213: f64 = v120 * v187;
        let v214: f64 = v212 - v213;
        let v215: f64 = v151 * v172;
        let v216: f64 = v214 + v215;
        let v217: f64 = v116 * v136;
        let v218: f64 = v120 * v217;
        let v219: f64 = v162 * v172;
        let v220: f64 = v218 + v219;
        let v221: f64 = v116 * v217;
        let v222: f64 = v146 * v172;
        let v223: f64 = v120 * v136;
        let v224: f64 = v222 - v223;
        let v225: f64 = v120 * v224;
        let v226: f64 = v221 + v225;
        let v227: f64 = v191 * v172;
        let v228: f64 = v226 + v227;
        let v229: f64 = v116 * v172;
        let v230: f64 = v120 * v229;
        let v231: f64 = v146 * v217;
        let v232: f64 = v162 * v136;
        let v233: f64 = v231 + v232;
        let v234: f64 = v230 - v233;
        let v235: f64 = v127 * v172;
        let v236: f64 = v234 + v235;
        let v237: f64 = v116 * v224;
        let v238: f64 = v116 * v229;
        let v239: f64 = v191 * v136;
        let v240: f64 = v146 * v224;
        let v241: f64 = v239 + v240;
        let v242: f64 = v238 - v241;
        let v243: f64 = v127 * v136;
        let v244: f64 = v146 * v229;
        let v245: f64 = v243 + v244;
        let v246: f64 = -v245;
        let v247: f64 = q[3];
        let (v256, v248): (f64, f64) = ::libm::sincos(v247);
        let v249: f64 = 0.39225_f64;
        let v250: f64 = v249 * v191;
        let v251: f64 = v249 * v120;
        let v252: f64 = v146 * v251;
        let v253: f64 = v250 - v252;
        let v254: f64 = v130 + v253;
        let v255: f64 = v248 * v254;
        let v257: f64 = v120 * v251;
        let v258: f64 = v249 * v116;
        let v259: f64 = v116 * v258;
        let v260: f64 = v257 + v259;
        let v261: f64 = v166 - v260;
        let v262: f64 = v256 * v261;
        let v263: f64 = v255 - v262;
        let v264: f64 = v248 * v138;
        let v265: f64 = v256 * v174;
        let v266: f64 = v264 - v265;
        let v267: f64 = v263 * v266;
        let v268: f64 = v256 * v254;
        let v269: f64 = v248 * v261;
        let v270: f64 = v268 + v269;
        let v271: f64 = v256 * v138;
        let v272: f64 = v248 * v174;
        let v273: f64 = v271 + v272;
        let v274: f64 = v270 * v273;
        let v275: f64 = v267 + v274;
        let v276: f64 = v249 * v162;
        let v277: f64 = v146 * v258;
        let v278: f64 = v276 + v277;
        let v279: f64 = v151 + v278;
        let v280: f64 = v249 * v172;
        let v281: f64 = v152 - v280;
        let v282: f64 = v279 * v281;
        let v283: f64 = v275 - v282;
        let v284: f64 = v248 * v120;
        let v285: f64 = v256 * v146;
        let v286: f64 = v284 + v285;
        let v287: f64 = v248 * v146;
        let v288: f64 = v256 * v120;
        let v289: f64 = v287 - v288;
        let v290: f64 = v289 * v266;
        let v291: f64 = v286 * v273;
        let v292: f64 = v290 + v291;
        let v293: f64 = v286 * v292;
        let v294: f64 = qdd[3];
        let v295: f64 = v191 + v294;
        let v296: f64 = v295 * v266;
        let v297: f64 = v293 - v296;
        let v298: f64 = qd[3];
        let v299: f64 = v116 + v298;
        let v300: f64 = v299 * v273;
        let v301: f64 = v289 * v281;
        let v302: f64 = v300 + v301;
        let v303: f64 = v299 * v302;
        let v304: f64 = v297 + v303;
        let v305: f64 = v248 * v162;
        let v306: f64 = v256 * v127;
        let v307: f64 = v305 - v306;
        let v308: f64 = v289 * v298;
        let v309: f64 = v307 + v308;
        let v310: f64 = v309 * v281;
        let v311: f64 = v304 + v310;
        let v312: f64 = v256 * v136;
        let v313: f64 = v248 * v172;
        let v314: f64 = v312 + v313;
        let v315: f64 = v279 * v314;
        let v316: f64 = v311 - v315;
        let v317: f64 = v309 * v273;
        let v318: f64 = v256 * v162;
        let v319: f64 = v248 * v127;
        let v320: f64 = v318 + v319;
        let v321: f64 = v286 * v298;
        let v322: f64 = v320 + v321;
        let v323: f64 = v322 * v266;
        let v324: f64 = v317 - v323;
        let v325: f64 = v289 * v302;
        let v326: f64 = v324 - v325;
        let v327: f64 = v286 * v281;
        let v328: f64 = v299 * v266;
        let v329: f64 = v327 - v328;
        let v330: f64 = v286 * v329;
        let v331: f64 = v326 - v330;
        let v332: f64 = v248 * v136;
        let v333: f64 = v256 * v172;
        let v334: f64 = v332 - v333;
        let v335: f64 = v263 * v334;
        let v336: f64 = v331 + v335;
        let v337: f64 = v270 * v314;
        let v338: f64 = v336 + v337;
        let v339: f64 = v299 * v329;
        let v340: f64 = v289 * v292;
        let v341: f64 = v295 * v273;
        let v342: f64 = v340 + v341;
        let v343: f64 = v339 - v342;
        let v344: f64 = v322 * v281;
        let v345: f64 = v343 + v344;
        let v346: f64 = v279 * v334;
        let v347: f64 = v345 + v346;
        let v348: f64 = v322 * v334;
        let v349: f64 = v299 * v314;
        let v350: f64 = v289 * v349;
        let v351: f64 = v348 + v350;
        let v352: f64 = -v351;
        let v353: f64 = v295 * v334;
        let v354: f64 = v299 * v349;
        let v355: f64 = v353 - v354;
        let v356: f64 = v289 * v314;
        let v357: f64 = v286 * v334;
        let v358: f64 = v356 - v357;
        let v359: f64 = v289 * v358;
        let v360: f64 = v355 + v359;
        let v361: f64 = v299 * v334;
        let v362: f64 = v289 * v361;
        let v363: f64 = v309 * v334;
        let v364: f64 = v362 + v363;
        let v365: f64 = v286 * v349;
        let v366: f64 = v364 - v365;
        let v367: f64 = v322 * v314;
        let v368: f64 = v366 - v367;
        let v369: f64 = v299 * v358;
        let v370: f64 = v299 * v361;
        let v371: f64 = v286 * v358;
        let v372: f64 = v370 + v371;
        let v373: f64 = v295 * v314;
        let v374: f64 = v372 + v373;
        let v375: f64 = v286 * v361;
        let v376: f64 = v309 * v314;
        let v377: f64 = v375 + v376;
        let v378: f64 = 0.093_f64;
        let v379: f64 = v378 * v286;
        let v380: f64 = v299 * v379;
        let v381: f64 = v378 * v322;
        let v382: f64 = v380 - v381;
        let v383: f64 = v263 + v382;
        let v384: f64 = v378 * v334;
        let v385: f64 = v266 + v384;
        let v386: f64 = v383 * v385;
        let v387: f64 = q[4];
        (
            v207,
            v216,
            v220,
            v228,
            v236,
            v237,
            v242,
            v246,
            v248,
            v249,
            v256,
            v263,
            v270,
            v273,
            v279,
            v281,
            v283,
            v286,
            v289,
            v295,
            v299,
            v309,
            v314,
            v316,
            v322,
            v334,
            v338,
            v347,
            v352,
            v360,
            v368,
            v369,
            v374,
            v377,
            v378,
            v379,
            v383,
            v385,
            v386,
            v387,
        )
    };
    let (
        v388,
        v395,
        v401,
        v411,
        v416,
        v417,
        v424,
        v427,
        v431,
        v434,
        v442,
        v449,
        v454,
        v456,
        v469,
        v480,
        v486,
        v496,
        v506,
        v509,
        v516,
        v519,
        v520,
        v525,
        v527,
        v530,
        v537,
        v543,
        v548,
        v553,
        v556,
        v558,
        v565,
        v566,
        v568,
        v572,
        v574,
        v577,
        v580,
        v581,
    ) = {
        let (v388, v395): (f64, f64) = ::libm::sincos(v387);
        let v389: f64 = v378 * v289;
        let v390: f64 = v299 * v389;
        let v391: f64 = v378 * v309;
        let v392: f64 = v390 - v391;
        let v393: f64 = v392 - v270;
        let v394: f64 = v388 * v393;
        let v396: f64 = v286 * v379;
        let v397: f64 = v289 * v389;
        let v398: f64 = v396 + v397;
        let v399: f64 = v279 + v398;
        let v400: f64 = v395 * v399;
        let v401: f64 = v394 + v400;
        let v402: f64 = v395 * v281;
        let v403: f64 = v378 * v314;
        let v404: f64 = v273 + v403;
        let v405: f64 = v388 * v404;
        let v406: f64 = v402 + v405;
        let v407: f64 = v401 * v406;
        let v408: f64 = v386 - v407;
        let v409: f64 = v395 * v393;
        let v410: f64 = v388 * v399;
        let v411: f64 = v409 - v410;
        let v412: f64 = v388 * v281;
        let v413: f64 = v395 * v404;
        let v414: f64 = v412 - v413;
        let v415: f64 = v411 * v414;
        let v416: f64 = v408 + v415;
        let v417: f64 = v388 * v334;
        let v418: f64 = v383 * v417;
        let v419: f64 = v388 * v322;
        let v420: f64 = v395 * v295;
        let v421: f64 = v419 + v420;
        let v422: f64 = v395 * v289;
        let v423: f64 = v388 * v299;
        let v424: f64 = v422 + v423;
        let v425: f64 = qd[4];
        let v426: f64 = v424 * v425;
        let v427: f64 = v421 - v426;
        let v428: f64 = v427 * v385;
        let v429: f64 = v418 - v428;
        let v430: f64 = qdd[4];
        let v431: f64 = v309 + v430;
        let v432: f64 = v431 * v406;
        let v433: f64 = v429 + v432;
        let v434: f64 = v286 + v425;
        let v435: f64 = v424 * v385;
        let v436: f64 = v434 * v414;
        let v437: f64 = v435 - v436;
        let v438: f64 = v434 * v437;
        let v439: f64 = v433 + v438;
        let v440: f64 = v395 * v299;
        let v441: f64 = v388 * v289;
        let v442: f64 = v440 - v441;
        let v443: f64 = v442 * v414;
        let v444: f64 = v424 * v406;
        let v445: f64 = v443 - v444;
        let v446: f64 = v442 * v445;
        let v447: f64 = v439 - v446;
        let v448: f64 = v401 * v314;
        let v449: f64 = v447 - v448;
        let v450: f64 = v388 * v295;
        let v451: f64 = v395 * v322;
        let v452: f64 = v450 - v451;
        let v453: f64 = v442 * v425;
        let v454: f64 = v452 + v453;
        let v455: f64 = v454 * v385;
        let v456: f64 = v395 * v334;
        let v457: f64 = v383 * v456;
        let v458: f64 = v455 + v457;
        let v459: f64 = v434 * v406;
        let v460: f64 = v442 * v385;
        let v461: f64 = v459 - v460;
        let v462: f64 = v434 * v461;
        let v463: f64 = v458 - v462;
        let v464: f64 = v424 * v445;
        let v465: f64 = v463 + v464;
        let v466: f64 = v431 * v414;
        let v467: f64 = v465 - v466;
        let v468: f64 = v411 * v314;
        let v469: f64 = v467 - v468;
        let v470: f64 = v401 * v456;
        let v471: f64 = v411 * v417;
        let v472: f64 = v470 - v471;
        let v473: f64 = v442 * v461;
        let v474: f64 = v472 + v473;
        let v475: f64 = v454 * v406;
        let v476: f64 = v474 - v475;
        let v477: f64 = v424 * v437;
        let v478: f64 = v476 - v477;
        let v479: f64 = v427 * v414;
        let v480: f64 = v478 + v479;
        let v481: f64 = v454 * v456;
        let v482: f64 = v434 * v417;
        let v483: f64 = v442 * v314;
        let v484: f64 = v482 + v483;
        let v485: f64 = v424 * v484;
        let v486: f64 = v481 - v485;
        let v487: f64 = v427 * v456;
        let v488: f64 = v454 * v417;
        let v489: f64 = v487 - v488;
        let v490: f64 = v442 * v484;
        let v491: f64 = v489 - v490;
        let v492: f64 = v424 * v314;
        let v493: f64 = v434 * v456;
        let v494: f64 = v492 - v493;
        let v495: f64 = v424 * v494;
        let v496: f64 = v491 + v495;
        let v497: f64 = v424 * v417;
        let v498: f64 = v442 * v456;
        let v499: f64 = v497 + v498;
        let v500: f64 = v424 * v499;
        let v501: f64 = v431 * v456;
        let v502: f64 = v500 + v501;
        let v503: f64 = v434 * v484;
        let v504: f64 = v502 - v503;
        let v505: f64 = v454 * v314;
        let v506: f64 = v504 + v505;
        let v507: f64 = v442 * v494;
        let v508: f64 = v427 * v417;
        let v509: f64 = v507 - v508;
        let v510: f64 = v442 * v499;
        let v511: f64 = v431 * v417;
        let v512: f64 = v510 - v511;
        let v513: f64 = v434 * v494;
        let v514: f64 = v512 + v513;
        let v515: f64 = v427 * v314;
        let v516: f64 = v514 + v515;
        let v517: f64 = v434 * v499;
        let v518: f64 = v431 * v314;
        let v519: f64 = v517 + v518;
        let v520: f64 = 0.09465_f64;
        let v521: f64 = v520 * v442;
        let v522: f64 = v434 * v521;
        let v523: f64 = v520 * v454;
        let v524: f64 = v522 - v523;
        let v525: f64 = v524 - v401;
        let v526: f64 = v520 * v456;
        let v527: f64 = v406 - v526;
        let v528: f64 = v525 * v527;
        let v529: f64 = q[5];
        let (v530, v537): (f64, f64) = ::libm::sincos(v529);
        let v531: f64 = v520 * v427;
        let v532: f64 = v520 * v424;
        let v533: f64 = v434 * v532;
        let v534: f64 = v531 + v533;
        let v535: f64 = v411 + v534;
        let v536: f64 = v530 * v535;
        let v538: f64 = v424 * v532;
        let v539: f64 = v442 * v521;
        let v540: f64 = v538 + v539;
        let v541: f64 = v383 - v540;
        let v542: f64 = v537 * v541;
        let v543: f64 = v536 + v542;
        let v544: f64 = v537 * v385;
        let v545: f64 = v520 * v417;
        let v546: f64 = v414 - v545;
        let v547: f64 = v530 * v546;
        let v548: f64 = v544 + v547;
        let v549: f64 = v543 * v548;
        let v550: f64 = v528 + v549;
        let v551: f64 = v537 * v535;
        let v552: f64 = v530 * v541;
        let v553: f64 = v551 - v552;
        let v554: f64 = v537 * v546;
        let v555: f64 = v530 * v385;
        let v556: f64 = v554 - v555;
        let v557: f64 = v553 * v556;
        let v558: f64 = v550 + v557;
        let v559: f64 = v543 * v417;
        let v560: f64 = v530 * v454;
        let v561: f64 = v537 * v431;
        let v562: f64 = v560 + v561;
        let v563: f64 = v537 * v424;
        let v564: f64 = v530 * v434;
        let v565: f64 = v563 - v564;
        let v566: f64 = qd[5];
        let v567: f64 = v565 * v566;
        let v568: f64 = v562 + v567;
        let v569: f64 = v568 * v527;
        let v570: f64 = v559 + v569;
        let v571: f64 = qdd[5];
        let v572: f64 = v427 + v571;
        let v573: f64 = v572 * v548;
        let v574: f64 = v570 - v573;
        let v575: f64 = v530 * v424;
        let v576: f64 = v537 * v434;
        let v577: f64 = v575 + v576;
        let v578: f64 = v565 * v548;
        let v579: f64 = v577 * v556;
        let v580: f64 = v578 - v579;
        let v581: f64 = v577 * v580;
        (
            v388,
            v395,
            v401,
            v411,
            v416,
            v417,
            v424,
            v427,
            v431,
            v434,
            v442,
            v449,
            v454,
            v456,
            v469,
            v480,
            v486,
            v496,
            v506,
            v509,
            v516,
            v519,
            v520,
            v525,
            v527,
            v530,
            v537,
            v543,
            v548,
            v553,
            v556,
            v558,
            v565,
            v566,
            v568,
            v572,
            v574,
            v577,
            v580,
            v581,
        )
    };
    let (
        v583,
        v593,
        v598,
        v615,
        v626,
        v632,
        v642,
        v652,
        v655,
        v662,
        v665,
        v666,
        v667,
        v669,
        v672,
        v673,
        v675,
        v680,
        v691,
        v699,
        v705,
        v707,
        v709,
        v712,
        v714,
        v715,
        v719,
        v725,
        v735,
        v743,
        v750,
        v751,
        v753,
        v756,
        v758,
        v760,
        v762,
        v765,
        v767,
        v770,
        v772,
        v775,
    ) = {
        let v582: f64 = v574 + v581;
        let v583: f64 = v442 + v566;
        let v584: f64 = v583 * v556;
        let v585: f64 = v565 * v527;
        let v586: f64 = v584 - v585;
        let v587: f64 = v583 * v586;
        let v588: f64 = v582 - v587;
        let v589: f64 = v530 * v456;
        let v590: f64 = v537 * v314;
        let v591: f64 = v589 + v590;
        let v592: f64 = v525 * v591;
        let v593: f64 = v588 + v592;
        let v594: f64 = v537 * v454;
        let v595: f64 = v530 * v431;
        let v596: f64 = v594 - v595;
        let v597: f64 = v577 * v566;
        let v598: f64 = v596 - v597;
        let v599: f64 = v598 * v548;
        let v600: f64 = v577 * v527;
        let v601: f64 = v583 * v548;
        let v602: f64 = v600 - v601;
        let v603: f64 = v577 * v602;
        let v604: f64 = v599 - v603;
        let v605: f64 = v565 * v586;
        let v606: f64 = v604 + v605;
        let v607: f64 = v568 * v556;
        let v608: f64 = v606 - v607;
        let v609: f64 = v537 * v456;
        let v610: f64 = v530 * v314;
        let v611: f64 = v609 - v610;
        let v612: f64 = v543 * v611;
        let v613: f64 = v608 + v612;
        let v614: f64 = v553 * v591;
        let v615: f64 = v613 - v614;
        let v616: f64 = v583 * v602;
        let v617: f64 = v553 * v417;
        let v618: f64 = v598 * v527;
        let v619: f64 = v617 + v618;
        let v620: f64 = v616 - v619;
        let v621: f64 = v565 * v580;
        let v622: f64 = v620 - v621;
        let v623: f64 = v572 * v556;
        let v624: f64 = v622 + v623;
        let v625: f64 = v525 * v611;
        let v626: f64 = v624 - v625;
        let v627: f64 = v598 * v611;
        let v628: f64 = v577 * v417;
        let v629: f64 = v583 * v591;
        let v630: f64 = v628 + v629;
        let v631: f64 = v565 * v630;
        let v632: f64 = v627 - v631;
        let v633: f64 = v572 * v611;
        let v634: f64 = v598 * v417;
        let v635: f64 = v633 - v634;
        let v636: f64 = v583 * v630;
        let v637: f64 = v635 - v636;
        let v638: f64 = v565 * v591;
        let v639: f64 = v577 * v611;
        let v640: f64 = v638 - v639;
        let v641: f64 = v565 * v640;
        let v642: f64 = v637 + v641;
        let v643: f64 = v565 * v417;
        let v644: f64 = v583 * v611;
        let v645: f64 = v643 + v644;
        let v646: f64 = v565 * v645;
        let v647: f64 = v568 * v611;
        let v648: f64 = v646 + v647;
        let v649: f64 = v577 * v630;
        let v650: f64 = v648 - v649;
        let v651: f64 = v598 * v591;
        let v652: f64 = v650 + v651;
        let v653: f64 = v583 * v640;
        let v654: f64 = v572 * v417;
        let v655: f64 = v653 - v654;
        let v656: f64 = v583 * v645;
        let v657: f64 = v568 * v417;
        let v658: f64 = v656 - v657;
        let v659: f64 = v577 * v640;
        let v660: f64 = v658 + v659;
        let v661: f64 = v572 * v591;
        let v662: f64 = v660 + v661;
        let v663: f64 = v577 * v645;
        let v664: f64 = v568 * v591;
        let v665: f64 = v663 + v664;
        let v666: f64 = -v29;
        let v667: f64 = v7 * v20;
        let v668: f64 = v8 * v20;
        let v669: f64 = v23 - v668;
        let v670: f64 = v20 * v20;
        let v671: f64 = v7 * v7;
        let v672: f64 = v670 - v671;
        let v673: f64 = -v4;
        let v674: f64 = v20 * v7;
        let v675: f64 = -v674;
        let v676: f64 = v100 * v99;
        let v677: f64 = v130 * v676;
        let v678: f64 = v100 * v107;
        let v679: f64 = v166 * v678;
        let v680: f64 = v677 + v679;
        let v681: f64 = v116 * v676;
        let v682: f64 = v116 * v681;
        let v683: f64 = v166 + v682;
        let v684: f64 = v146 * v676;
        let v685: f64 = v120 * v678;
        let v686: f64 = v684 + v685;
        let v687: f64 = v146 * v686;
        let v688: f64 = v683 + v687;
        let v689: f64 = v191 * v678;
        let v690: f64 = v688 + v689;
        let v691: f64 = -v690;
        let v692: f64 = v120 * v681;
        let v693: f64 = v127 * v676;
        let v694: f64 = v692 - v693;
        let v695: f64 = v116 * v678;
        let v696: f64 = v146 * v695;
        let v697: f64 = v694 - v696;
        let v698: f64 = v162 * v678;
        let v699: f64 = v697 + v698;
        let v700: f64 = v191 * v676;
        let v701: f64 = v130 + v700;
        let v702: f64 = v116 * v695;
        let v703: f64 = v701 - v702;
        let v704: f64 = v120 * v686;
        let v705: f64 = v703 - v704;
        let v706: f64 = v120 * v146;
        let v707: f64 = -v706;
        let v708: f64 = v116 * v146;
        let v709: f64 = v162 - v708;
        let v710: f64 = v146 * v146;
        let v711: f64 = v120 * v120;
        let v712: f64 = v710 - v711;
        let v713: f64 = v116 * v120;
        let v714: f64 = v127 - v713;
        let v715: f64 = v146 * v120;
        let v716: f64 = v249 + v676;
        let v717: f64 = v248 * v716;
        let v718: f64 = v256 * v678;
        let v719: f64 = v717 - v718;
        let v720: f64 = v263 * v719;
        let v721: f64 = v256 * v716;
        let v722: f64 = v248 * v678;
        let v723: f64 = v721 + v722;
        let v724: f64 = v270 * v723;
        let v725: f64 = v720 + v724;
        let v726: f64 = v289 * v719;
        let v727: f64 = v286 * v723;
        let v728: f64 = v726 + v727;
        let v729: f64 = v286 * v728;
        let v730: f64 = v295 * v719;
        let v731: f64 = v263 + v730;
        let v732: f64 = v729 - v731;
        let v733: f64 = v299 * v723;
        let v734: f64 = v299 * v733;
        let v735: f64 = v732 + v734;
        let v736: f64 = v309 * v723;
        let v737: f64 = v322 * v719;
        let v738: f64 = v736 - v737;
        let v739: f64 = v289 * v733;
        let v740: f64 = v738 - v739;
        let v741: f64 = v299 * v719;
        let v742: f64 = v286 * v741;
        let v743: f64 = v740 + v742;
        let v744: f64 = v289 * v728;
        let v745: f64 = v270 + v744;
        let v746: f64 = v295 * v723;
        let v747: f64 = v745 + v746;
        let v748: f64 = v299 * v741;
        let v749: f64 = v747 + v748;
        let v750: f64 = -v749;
        let v751: f64 = v289 * v286;
        let v752: f64 = v299 * v286;
        let v753: f64 = v752 - v322;
        let v754: f64 = v286 * v286;
        let v755: f64 = v289 * v289;
        let v756: f64 = v754 - v755;
        let v757: f64 = v299 * v289;
        let v758: f64 = v309 - v757;
        let v759: f64 = v286 * v289;
        let v760: f64 = -v759;
        let v761: f64 = v383 * v719;
        let v762: f64 = v388 * v723;
        let v763: f64 = v401 * v762;
        let v764: f64 = v761 - v763;
        let v765: f64 = v395 * v723;
        let v766: f64 = v411 * v765;
        let v767: f64 = v764 - v766;
        let v768: f64 = v431 * v762;
        let v769: f64 = v427 * v719;
        let v770: f64 = v383 * v395;
        let v771: f64 = v769 + v770;
        let v772: f64 = v768 - v771;
        let v773: f64 = v424 * v719;
        let v774: f64 = v434 * v765;
        let v775: f64 = v773 + v774;
        (
            v583,
            v593,
            v598,
            v615,
            v626,
            v632,
            v642,
            v652,
            v655,
            v662,
            v665,
            v666,
            v667,
            v669,
            v672,
            v673,
            v675,
            v680,
            v691,
            v699,
            v705,
            v707,
            v709,
            v712,
            v714,
            v715,
            v719,
            v725,
            v735,
            v743,
            v750,
            v751,
            v753,
            v756,
            v758,
            v760,
            v762,
            v765,
            v767,
            v770,
            v772,
            v775,
        )
    };
    let (
        v782,
        v784,
        v794,
        v797,
        v805,
        v809,
        v817,
        v825,
        v828,
        v833,
        v834,
        v835,
        v839,
        v849,
        v851,
        v866,
        v867,
        v879,
        v881,
        v882,
        v883,
        v892,
        v893,
        v899,
        v909,
        v919,
        v922,
        v929,
        v932,
        v933,
        v934,
        v939,
        v949,
        v957,
        v963,
        v965,
        v967,
        v968,
        v969,
    ) = {
        let v776: f64 = v434 * v775;
        let v777: f64 = v772 + v776;
        let v778: f64 = v424 * v762;
        let v779: f64 = v442 * v765;
        let v780: f64 = v778 + v779;
        let v781: f64 = v442 * v780;
        let v782: f64 = v777 + v781;
        let v783: f64 = v454 * v719;
        let v784: f64 = v383 * v388;
        let v785: f64 = v783 + v784;
        let v786: f64 = v434 * v762;
        let v787: f64 = v442 * v719;
        let v788: f64 = v786 - v787;
        let v789: f64 = v434 * v788;
        let v790: f64 = v785 - v789;
        let v791: f64 = v424 * v780;
        let v792: f64 = v790 - v791;
        let v793: f64 = v431 * v765;
        let v794: f64 = v792 + v793;
        let v795: f64 = v411 * v395;
        let v796: f64 = v401 * v388;
        let v797: f64 = v795 + v796;
        let v798: f64 = v442 * v788;
        let v799: f64 = v797 + v798;
        let v800: f64 = v454 * v762;
        let v801: f64 = v799 - v800;
        let v802: f64 = v424 * v775;
        let v803: f64 = v801 - v802;
        let v804: f64 = v427 * v765;
        let v805: f64 = v803 - v804;
        let v806: f64 = v454 * v388;
        let v807: f64 = v434 * v395;
        let v808: f64 = v424 * v807;
        let v809: f64 = v806 + v808;
        let v810: f64 = v454 * v395;
        let v811: f64 = v427 * v388;
        let v812: f64 = v810 + v811;
        let v813: f64 = v442 * v807;
        let v814: f64 = v812 + v813;
        let v815: f64 = v434 * v388;
        let v816: f64 = v424 * v815;
        let v817: f64 = v814 - v816;
        let v818: f64 = v442 * v388;
        let v819: f64 = v424 * v395;
        let v820: f64 = v818 - v819;
        let v821: f64 = v424 * v820;
        let v822: f64 = v431 * v388;
        let v823: f64 = v821 + v822;
        let v824: f64 = v434 * v807;
        let v825: f64 = v823 + v824;
        let v826: f64 = v427 * v395;
        let v827: f64 = v442 * v815;
        let v828: f64 = v826 - v827;
        let v829: f64 = v431 * v395;
        let v830: f64 = v442 * v820;
        let v831: f64 = v829 + v830;
        let v832: f64 = v434 * v815;
        let v833: f64 = v831 - v832;
        let v834: f64 = v434 * v820;
        let v835: f64 = v520 * v388;
        let v836: f64 = v762 - v835;
        let v837: f64 = v525 * v836;
        let v838: f64 = v537 * v719;
        let v839: f64 = v520 * v395;
        let v840: f64 = v839 - v765;
        let v841: f64 = v530 * v840;
        let v842: f64 = v838 + v841;
        let v843: f64 = v543 * v842;
        let v844: f64 = v837 + v843;
        let v845: f64 = v537 * v840;
        let v846: f64 = v530 * v719;
        let v847: f64 = v845 - v846;
        let v848: f64 = v553 * v847;
        let v849: f64 = v844 + v848;
        let v850: f64 = v568 * v836;
        let v851: f64 = v543 * v395;
        let v852: f64 = v850 - v851;
        let v853: f64 = v572 * v842;
        let v854: f64 = v852 - v853;
        let v855: f64 = v565 * v842;
        let v856: f64 = v577 * v847;
        let v857: f64 = v855 - v856;
        let v858: f64 = v577 * v857;
        let v859: f64 = v854 + v858;
        let v860: f64 = v583 * v847;
        let v861: f64 = v565 * v836;
        let v862: f64 = v860 - v861;
        let v863: f64 = v583 * v862;
        let v864: f64 = v859 - v863;
        let v865: f64 = v530 * v388;
        let v866: f64 = v525 * v865;
        let v867: f64 = v864 + v866;
        let v868: f64 = v598 * v842;
        let v869: f64 = v577 * v836;
        let v870: f64 = v583 * v842;
        let v871: f64 = v869 - v870;
        let v872: f64 = v577 * v871;
        let v873: f64 = v868 - v872;
        let v874: f64 = v565 * v862;
        let v875: f64 = v873 + v874;
        let v876: f64 = v568 * v847;
        let v877: f64 = v875 - v876;
        let v878: f64 = v537 * v388;
        let v879: f64 = v543 * v878;
        let v880: f64 = v877 + v879;
        let v881: f64 = v553 * v865;
        let v882: f64 = v880 - v881;
        let v883: f64 = v553 * v395;
        let v884: f64 = v598 * v836;
        let v885: f64 = v883 - v884;
        let v886: f64 = v583 * v871;
        let v887: f64 = v885 + v886;
        let v888: f64 = v565 * v857;
        let v889: f64 = v887 - v888;
        let v890: f64 = v572 * v847;
        let v891: f64 = v889 + v890;
        let v892: f64 = v525 * v878;
        let v893: f64 = v891 - v892;
        let v894: f64 = v598 * v878;
        let v895: f64 = v577 * v395;
        let v896: f64 = v583 * v865;
        let v897: f64 = v895 - v896;
        let v898: f64 = v565 * v897;
        let v899: f64 = v894 + v898;
        let v900: f64 = v598 * v395;
        let v901: f64 = v572 * v878;
        let v902: f64 = v900 + v901;
        let v903: f64 = v583 * v897;
        let v904: f64 = v902 + v903;
        let v905: f64 = v565 * v865;
        let v906: f64 = v577 * v878;
        let v907: f64 = v905 - v906;
        let v908: f64 = v565 * v907;
        let v909: f64 = v904 + v908;
        let v910: f64 = v583 * v878;
        let v911: f64 = v565 * v395;
        let v912: f64 = v910 - v911;
        let v913: f64 = v565 * v912;
        let v914: f64 = v568 * v878;
        let v915: f64 = v913 + v914;
        let v916: f64 = v577 * v897;
        let v917: f64 = v915 + v916;
        let v918: f64 = v598 * v865;
        let v919: f64 = v917 + v918;
        let v920: f64 = v572 * v395;
        let v921: f64 = v583 * v907;
        let v922: f64 = v920 + v921;
        let v923: f64 = v568 * v395;
        let v924: f64 = v583 * v912;
        let v925: f64 = v923 + v924;
        let v926: f64 = v577 * v907;
        let v927: f64 = v925 + v926;
        let v928: f64 = v572 * v865;
        let v929: f64 = v927 + v928;
        let v930: f64 = v577 * v912;
        let v931: f64 = v568 * v865;
        let v932: f64 = v930 + v931;
        let v933: f64 = -v166;
        let v934: f64 = v249 * v248;
        let v935: f64 = v263 * v934;
        let v936: f64 = -0.39225_f64;
        let v937: f64 = v936 * v256;
        let v938: f64 = v270 * v937;
        let v939: f64 = v935 - v938;
        let v940: f64 = v289 * v934;
        let v941: f64 = v286 * v937;
        let v942: f64 = v940 - v941;
        let v943: f64 = v286 * v942;
        let v944: f64 = v295 * v934;
        let v945: f64 = v263 + v944;
        let v946: f64 = v943 - v945;
        let v947: f64 = v299 * v937;
        let v948: f64 = v299 * v947;
        let v949: f64 = v946 - v948;
        let v950: f64 = v289 * v947;
        let v951: f64 = v322 * v934;
        let v952: f64 = v309 * v937;
        let v953: f64 = v951 + v952;
        let v954: f64 = v950 - v953;
        let v955: f64 = v299 * v934;
        let v956: f64 = v286 * v955;
        let v957: f64 = v954 + v956;
        let v958: f64 = v295 * v937;
        let v959: f64 = v289 * v942;
        let v960: f64 = v270 + v959;
        let v961: f64 = v958 - v960;
        let v962: f64 = v299 * v955;
        let v963: f64 = v961 - v962;
        let v964: f64 = v383 * v934;
        let v965: f64 = v388 * v937;
        let v966: f64 = v401 * v965;
        let v967: f64 = v964 + v966;
        let v968: f64 = v395 * v937;
        let v969: f64 = v411 * v968;
        (
            v782,
            v784,
            v794,
            v797,
            v805,
            v809,
            v817,
            v825,
            v828,
            v833,
            v834,
            v835,
            v839,
            v849,
            v851,
            v866,
            v867,
            v879,
            v881,
            v882,
            v883,
            v892,
            v893,
            v899,
            v909,
            v919,
            v922,
            v929,
            v932,
            v933,
            v934,
            v939,
            v949,
            v957,
            v963,
            v965,
            v967,
            v968,
            v969,
        )
    };
    let (
        v970,
        v984,
        v995,
        v1003,
        v1016,
        v1031,
        v1043,
        v1052,
        v1053,
        v1054,
        v1055,
        v1062,
        v1077,
        v1089,
        v1098,
        v1099,
        v1100,
        v1102,
        v1105,
        v1107,
        v1108,
        v1110,
        v1111,
        v1115,
        v1116,
        v1121,
        v1129,
        v1137,
        v1138,
        v1143,
        v1146,
        v1147,
        v1148,
        v1150,
        v1153,
        v1155,
        v1157,
        v1158,
    ) = {
        let v970: f64 = v967 + v969;
        let v971: f64 = v424 * v934;
        let v972: f64 = v434 * v968;
        let v973: f64 = v971 - v972;
        let v974: f64 = v434 * v973;
        let v975: f64 = v427 * v934;
        let v976: f64 = v975 + v770;
        let v977: f64 = v431 * v965;
        let v978: f64 = v976 + v977;
        let v979: f64 = v974 - v978;
        let v980: f64 = v424 * v965;
        let v981: f64 = v442 * v968;
        let v982: f64 = v980 + v981;
        let v983: f64 = v442 * v982;
        let v984: f64 = v979 - v983;
        let v985: f64 = v454 * v934;
        let v986: f64 = v985 + v784;
        let v987: f64 = v442 * v934;
        let v988: f64 = v434 * v965;
        let v989: f64 = v987 + v988;
        let v990: f64 = v434 * v989;
        let v991: f64 = v986 + v990;
        let v992: f64 = v424 * v982;
        let v993: f64 = v991 + v992;
        let v994: f64 = v431 * v968;
        let v995: f64 = v993 - v994;
        let v996: f64 = v442 * v989;
        let v997: f64 = v797 - v996;
        let v998: f64 = v454 * v965;
        let v999: f64 = v997 + v998;
        let v1000: f64 = v424 * v973;
        let v1001: f64 = v999 - v1000;
        let v1002: f64 = v427 * v968;
        let v1003: f64 = v1001 + v1002;
        let v1004: f64 = v537 * v934;
        let v1005: f64 = v839 + v968;
        let v1006: f64 = v530 * v1005;
        let v1007: f64 = v1004 + v1006;
        let v1008: f64 = v543 * v1007;
        let v1009: f64 = v835 + v965;
        let v1010: f64 = v525 * v1009;
        let v1011: f64 = v1008 - v1010;
        let v1012: f64 = v537 * v1005;
        let v1013: f64 = v530 * v934;
        let v1014: f64 = v1012 - v1013;
        let v1015: f64 = v553 * v1014;
        let v1016: f64 = v1011 + v1015;
        let v1017: f64 = v565 * v1007;
        let v1018: f64 = v577 * v1014;
        let v1019: f64 = v1017 - v1018;
        let v1020: f64 = v577 * v1019;
        let v1021: f64 = v568 * v1009;
        let v1022: f64 = v851 + v1021;
        let v1023: f64 = v572 * v1007;
        let v1024: f64 = v1022 + v1023;
        let v1025: f64 = v1020 - v1024;
        let v1026: f64 = v565 * v1009;
        let v1027: f64 = v583 * v1014;
        let v1028: f64 = v1026 + v1027;
        let v1029: f64 = v583 * v1028;
        let v1030: f64 = v1025 - v1029;
        let v1031: f64 = v1030 + v866;
        let v1032: f64 = v577 * v1009;
        let v1033: f64 = v583 * v1007;
        let v1034: f64 = v1032 + v1033;
        let v1035: f64 = v577 * v1034;
        let v1036: f64 = v598 * v1007;
        let v1037: f64 = v1035 + v1036;
        let v1038: f64 = v565 * v1028;
        let v1039: f64 = v1037 + v1038;
        let v1040: f64 = v568 * v1014;
        let v1041: f64 = v1039 - v1040;
        let v1042: f64 = v1041 + v879;
        let v1043: f64 = v1042 - v881;
        let v1044: f64 = v598 * v1009;
        let v1045: f64 = v883 + v1044;
        let v1046: f64 = v583 * v1034;
        let v1047: f64 = v1045 - v1046;
        let v1048: f64 = v565 * v1019;
        let v1049: f64 = v1047 - v1048;
        let v1050: f64 = v572 * v1014;
        let v1051: f64 = v1049 + v1050;
        let v1052: f64 = v1051 - v892;
        let v1053: f64 = -v263;
        let v1054: f64 = -v270;
        let v1055: f64 = -v770;
        let v1056: f64 = v530 * v839;
        let v1057: f64 = v543 * v1056;
        let v1058: f64 = v525 * v835;
        let v1059: f64 = v1057 - v1058;
        let v1060: f64 = v537 * v839;
        let v1061: f64 = v553 * v1060;
        let v1062: f64 = v1059 + v1061;
        let v1063: f64 = v565 * v1056;
        let v1064: f64 = v577 * v1060;
        let v1065: f64 = v1063 - v1064;
        let v1066: f64 = v577 * v1065;
        let v1067: f64 = v568 * v835;
        let v1068: f64 = v851 + v1067;
        let v1069: f64 = v572 * v1056;
        let v1070: f64 = v1068 + v1069;
        let v1071: f64 = v1066 - v1070;
        let v1072: f64 = v565 * v835;
        let v1073: f64 = v583 * v1060;
        let v1074: f64 = v1072 + v1073;
        let v1075: f64 = v583 * v1074;
        let v1076: f64 = v1071 - v1075;
        let v1077: f64 = v1076 + v866;
        let v1078: f64 = v577 * v835;
        let v1079: f64 = v583 * v1056;
        let v1080: f64 = v1078 + v1079;
        let v1081: f64 = v577 * v1080;
        let v1082: f64 = v598 * v1056;
        let v1083: f64 = v1081 + v1082;
        let v1084: f64 = v565 * v1074;
        let v1085: f64 = v1083 + v1084;
        let v1086: f64 = v568 * v1060;
        let v1087: f64 = v1085 - v1086;
        let v1088: f64 = v1087 + v879;
        let v1089: f64 = v1088 - v881;
        let v1090: f64 = v598 * v835;
        let v1091: f64 = v883 + v1090;
        let v1092: f64 = v583 * v1080;
        let v1093: f64 = v1091 - v1092;
        let v1094: f64 = v565 * v1065;
        let v1095: f64 = v1093 - v1094;
        let v1096: f64 = v572 * v1060;
        let v1097: f64 = v1095 + v1096;
        let v1098: f64 = v1097 - v892;
        let v1099: f64 = -v401;
        let v1100: f64 = -v411;
        let v1101: f64 = v424 * v442;
        let v1102: f64 = -v1101;
        let v1103: f64 = v424 * v424;
        let v1104: f64 = v442 * v442;
        let v1105: f64 = v1103 - v1104;
        let v1106: f64 = v434 * v442;
        let v1107: f64 = v454 - v1106;
        let v1108: f64 = v442 * v424;
        let v1109: f64 = v434 * v424;
        let v1110: f64 = v1109 + v427;
        let v1111: f64 = v525 * v537;
        let v1112: f64 = v543 * v530;
        let v1113: f64 = v553 * v537;
        let v1114: f64 = v1112 + v1113;
        let v1115: f64 = -v1114;
        let v1116: f64 = v525 * v530;
        let v1117: f64 = v598 * v530;
        let v1118: f64 = v583 * v537;
        let v1119: f64 = v565 * v1118;
        let v1120: f64 = v1117 + v1119;
        let v1121: f64 = -v1120;
        let v1122: f64 = v577 * v530;
        let v1123: f64 = v565 * v537;
        let v1124: f64 = v1122 + v1123;
        let v1125: f64 = v565 * v1124;
        let v1126: f64 = v572 * v530;
        let v1127: f64 = v583 * v1118;
        let v1128: f64 = v1126 + v1127;
        let v1129: f64 = v1125 - v1128;
        let v1130: f64 = v598 * v537;
        let v1131: f64 = v583 * v530;
        let v1132: f64 = v565 * v1131;
        let v1133: f64 = v568 * v530;
        let v1134: f64 = v1132 + v1133;
        let v1135: f64 = v577 * v1118;
        let v1136: f64 = v1134 + v1135;
        let v1137: f64 = v1130 - v1136;
        let v1138: f64 = v583 * v1124;
        let v1139: f64 = v577 * v1124;
        let v1140: f64 = v583 * v1131;
        let v1141: f64 = v1139 - v1140;
        let v1142: f64 = v572 * v537;
        let v1143: f64 = v1141 + v1142;
        let v1144: f64 = v568 * v537;
        let v1145: f64 = v577 * v1131;
        let v1146: f64 = v1144 - v1145;
        let v1147: f64 = -v543;
        let v1148: f64 = v565 * v577;
        let v1149: f64 = v583 * v577;
        let v1150: f64 = v598 + v1149;
        let v1151: f64 = v577 * v577;
        let v1152: f64 = v565 * v565;
        let v1153: f64 = v1151 - v1152;
        let v1154: f64 = v583 * v565;
        let v1155: f64 = v568 - v1154;
        let v1156: f64 = v577 * v565;
        let v1157: f64 = -v1156;
        let v1158: f64 = 0.0_f64;
        (
            v970,
            v984,
            v995,
            v1003,
            v1016,
            v1031,
            v1043,
            v1052,
            v1053,
            v1054,
            v1055,
            v1062,
            v1077,
            v1089,
            v1098,
            v1099,
            v1100,
            v1102,
            v1105,
            v1107,
            v1108,
            v1110,
            v1111,
            v1115,
            v1116,
            v1121,
            v1129,
            v1137,
            v1138,
            v1143,
            v1146,
            v1147,
            v1148,
            v1150,
            v1153,
            v1155,
            v1157,
            v1158,
        )
    };
    [
        [
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v0,
            v32,
            v47,
            v59,
            v66,
            v71,
            v79,
            v87,
            v88,
            v94,
            v97,
            v176,
            v193,
            v207,
            v216,
            v220,
            v228,
            v236,
            v237,
            v242,
            v246,
            v283,
            v316,
            v338,
            v347,
            v352,
            v360,
            v368,
            v369,
            v374,
            v377,
            v416,
            v449,
            v469,
            v480,
            v486,
            v496,
            v506,
            v509,
            v516,
            v519,
            v558,
            v593,
            v615,
            v626,
            v632,
            v642,
            v652,
            v655,
            v662,
            v665,
        ],
        [
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v666,
            v1158,
            v17,
            v667,
            v669,
            v672,
            v45,
            v673,
            v675,
            v680,
            v691,
            v699,
            v705,
            v707,
            v709,
            v712,
            v191,
            v714,
            v715,
            v725,
            v735,
            v743,
            v750,
            v751,
            v753,
            v756,
            v295,
            v758,
            v760,
            v767,
            v782,
            v794,
            v805,
            v809,
            v817,
            v825,
            v828,
            v833,
            v834,
            v849,
            v867,
            v882,
            v893,
            v899,
            v909,
            v919,
            v922,
            v929,
            v932,
        ],
        [
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v933,
            v1158,
            v130,
            v707,
            v709,
            v712,
            v191,
            v714,
            v715,
            v939,
            v949,
            v957,
            v963,
            v751,
            v753,
            v756,
            v295,
            v758,
            v760,
            v970,
            v984,
            v995,
            v1003,
            v809,
            v817,
            v825,
            v828,
            v833,
            v834,
            v1016,
            v1031,
            v1043,
            v1052,
            v899,
            v909,
            v919,
            v922,
            v929,
            v932,
        ],
        [
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1053,
            v1158,
            v1054,
            v751,
            v753,
            v756,
            v295,
            v758,
            v760,
            v1158,
            v1055,
            v784,
            v797,
            v809,
            v817,
            v825,
            v828,
            v833,
            v834,
            v1062,
            v1077,
            v1089,
            v1098,
            v899,
            v909,
            v919,
            v922,
            v929,
            v932,
        ],
        [
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1099,
            v1100,
            v1158,
            v1102,
            v1105,
            v1107,
            v1108,
            v1110,
            v431,
            v1158,
            v1111,
            v1115,
            v1116,
            v1121,
            v1129,
            v1137,
            v1138,
            v1143,
            v1146,
        ],
        [
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1158,
            v1147,
            v1158,
            v553,
            v1148,
            v1150,
            v1153,
            v572,
            v1155,
            v1157,
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
    let v0: f64 = 3.7_f64;
    let v1: f64 = 0.0_f64;
    let v2: f64 = 0.010267495893_f64;
    let v3: f64 = 0.00666_f64;
    let v4: f64 = 8.393_f64;
    let v5: f64 = 2.35004_f64;
    let v6: f64 = 0.88490187591_f64;
    let v7: f64 = 0.0151074_f64;
    let v8: f64 = 2.275_f64;
    let v9: f64 = 0.56875_f64;
    let v10: f64 = 0.191630813556_f64;
    let v11: f64 = 0.004095_f64;
    let v12: f64 = 1.219_f64;
    let v13: f64 = 0.111172755531_f64;
    let v14: f64 = 0.21942_f64;
    let v15: f64 = 0.1879_f64;
    let v16: f64 = 0.0171364731454_f64;
    let v17: f64 = 0.033822_f64;
    [
        v0,
        v1,
        v1,
        v1,
        v2,
        v1,
        v1,
        v2,
        v1,
        v3,
        v4,
        v1,
        v1,
        v5,
        v6,
        v1,
        v1,
        v6,
        v1,
        v7,
        v8,
        v1,
        v1,
        v9,
        v10,
        v1,
        v1,
        v10,
        v1,
        v11,
        v12,
        v1,
        v1,
        v1,
        v13,
        v1,
        v1,
        v13,
        v1,
        v14,
        v12,
        v1,
        v1,
        v1,
        v13,
        v1,
        v1,
        v13,
        v1,
        v14,
        v15,
        v1,
        v1,
        v1,
        v16,
        v1,
        v1,
        v16,
        v1,
        v17,
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
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `poses: [[[f32; 4]; 4]; 6]` (6 x 4 x 4, row-major): homogeneous transforms T_0i of the description's frames 1..n in the base frame (m)
    ///
    /// Operation count: 113 floating-point operations, 12 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn frame_poses(q: &[f32; 6]) -> [[[f32; 4]; 4]; 6] {
        let v0: f32 = q[0];
        let (v2, v1): (f32, f32) = ::libm::sincosf(v0);
        let v3: f32 = -v2;
        let v4: f32 = 0.0_f32;
        let v5: f32 = 1.0_f32;
        let v6: f32 = 0.089159_f32;
        let v7: f32 = q[1];
        let (v8, v11): (f32, f32) = ::libm::sincosf(v7);
        let v9: f32 = v1 * v8;
        let v10: f32 = -v9;
        let v12: f32 = v1 * v11;
        let v13: f32 = 0.13585_f32;
        let v14: f32 = v13 * v2;
        let v15: f32 = -v14;
        let v16: f32 = v2 * v8;
        let v17: f32 = -v16;
        let v18: f32 = v2 * v11;
        let v19: f32 = v13 * v1;
        let v20: f32 = -v11;
        let v21: f32 = -v8;
        let v22: f32 = q[2];
        let (v25, v23): (f32, f32) = ::libm::sincosf(v22);
        let v24: f32 = v9 * v23;
        let v26: f32 = v12 * v25;
        let v27: f32 = v24 + v26;
        let v28: f32 = -v27;
        let v29: f32 = v12 * v23;
        let v30: f32 = v9 * v25;
        let v31: f32 = v29 - v30;
        let v32: f32 = 0.425_f32;
        let v33: f32 = v32 * v12;
        let v34: f32 = -0.1197_f32;
        let v35: f32 = v34 * v2;
        let v36: f32 = v33 - v35;
        let v37: f32 = v36 - v14;
        let v38: f32 = v16 * v23;
        let v39: f32 = v18 * v25;
        let v40: f32 = v38 + v39;
        let v41: f32 = -v40;
        let v42: f32 = v18 * v23;
        let v43: f32 = v16 * v25;
        let v44: f32 = v42 - v43;
        let v45: f32 = v34 * v1;
        let v46: f32 = v32 * v18;
        let v47: f32 = v45 + v46;
        let v48: f32 = v19 + v47;
        let v49: f32 = v8 * v25;
        let v50: f32 = v11 * v23;
        let v51: f32 = v49 - v50;
        let v52: f32 = v11 * v25;
        let v53: f32 = v8 * v23;
        let v54: f32 = v52 + v53;
        let v55: f32 = -v54;
        let v56: f32 = v32 * v8;
        let v57: f32 = v6 - v56;
        let v58: f32 = q[3];
        let (v59, v61): (f32, f32) = ::libm::sincosf(v58);
        let v60: f32 = v27 * v59;
        let v62: f32 = v31 * v61;
        let v63: f32 = v60 - v62;
        let v64: f32 = v27 * v61;
        let v65: f32 = v31 * v59;
        let v66: f32 = v64 + v65;
        let v67: f32 = -v66;
        let v68: f32 = 0.39225_f32;
        let v69: f32 = v68 * v31;
        let v70: f32 = v37 + v69;
        let v71: f32 = v40 * v59;
        let v72: f32 = v44 * v61;
        let v73: f32 = v71 - v72;
        let v74: f32 = v40 * v61;
        let v75: f32 = v44 * v59;
        let v76: f32 = v74 + v75;
        let v77: f32 = -v76;
        let v78: f32 = v68 * v44;
        let v79: f32 = v48 + v78;
        let v80: f32 = v54 * v61;
        let v81: f32 = v51 * v59;
        let v82: f32 = v80 - v81;
        let v83: f32 = v51 * v61;
        let v84: f32 = v54 * v59;
        let v85: f32 = v83 + v84;
        let v86: f32 = v68 * v54;
        let v87: f32 = v57 - v86;
        let v88: f32 = q[4];
        let (v91, v89): (f32, f32) = ::libm::sincosf(v88);
        let v90: f32 = v63 * v89;
        let v92: f32 = v2 * v91;
        let v93: f32 = v90 - v92;
        let v94: f32 = v63 * v91;
        let v95: f32 = v2 * v89;
        let v96: f32 = v94 + v95;
        let v97: f32 = -v96;
        let v98: f32 = 0.093_f32;
        let v99: f32 = v98 * v2;
        let v100: f32 = v70 - v99;
        let v101: f32 = v73 * v89;
        let v102: f32 = v1 * v91;
        let v103: f32 = v101 + v102;
        let v104: f32 = v1 * v89;
        let v105: f32 = v73 * v91;
        let v106: f32 = v104 - v105;
        let v107: f32 = v98 * v1;
        let v108: f32 = v79 + v107;
        let v109: f32 = v82 * v89;
        let v110: f32 = v82 * v91;
        let v111: f32 = -v110;
        let v112: f32 = q[5];
        let (v115, v113): (f32, f32) = ::libm::sincosf(v112);
        let v114: f32 = v93 * v113;
        let v116: f32 = v66 * v115;
        let v117: f32 = v114 + v116;
        let v118: f32 = v93 * v115;
        let v119: f32 = v66 * v113;
        let v120: f32 = v118 - v119;
        let v121: f32 = 0.09465_f32;
        let v122: f32 = v121 * v66;
        let v123: f32 = v100 - v122;
        let v124: f32 = v103 * v113;
        let v125: f32 = v76 * v115;
        let v126: f32 = v124 + v125;
        let v127: f32 = v103 * v115;
        let v128: f32 = v76 * v113;
        let v129: f32 = v127 - v128;
        let v130: f32 = v121 * v76;
        let v131: f32 = v108 - v130;
        let v132: f32 = v109 * v113;
        let v133: f32 = v85 * v115;
        let v134: f32 = v132 - v133;
        let v135: f32 = v109 * v115;
        let v136: f32 = v85 * v113;
        let v137: f32 = v135 + v136;
        let v138: f32 = v121 * v85;
        let v139: f32 = v87 + v138;
        [
            [[v1, v3, v4, v4], [v2, v1, v4, v4], [v4, v4, v5, v6], [v4, v4, v4, v5]],
            [
                [v10, v3, v12, v15],
                [v17, v1, v18, v19],
                [v20, v4, v21, v6],
                [v4, v4, v4, v5],
            ],
            [
                [v28, v3, v31, v37],
                [v41, v1, v44, v48],
                [v51, v4, v55, v57],
                [v4, v4, v4, v5],
            ],
            [
                [v63, v3, v67, v70],
                [v73, v1, v77, v79],
                [v82, v4, v85, v87],
                [v4, v4, v4, v5],
            ],
            [
                [v93, v97, v67, v100],
                [v103, v106, v77, v108],
                [v109, v111, v85, v87],
                [v4, v4, v4, v5],
            ],
            [
                [v117, v97, v120, v123],
                [v126, v106, v129, v131],
                [v134, v111, v137, v139],
                [v4, v4, v4, v5],
            ],
        ]
    }
    /// End-effector pose, forward kinematics `T_0n` (thesis eq. 3.7).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `pose: [[f32; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the base frame (m)
    ///
    /// Operation count: 111 floating-point operations, 12 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn end_effector_pose(q: &[f32; 6]) -> [[f32; 4]; 4] {
        let v0: f32 = q[0];
        let (v25, v1): (f32, f32) = ::libm::sincosf(v0);
        let v2: f32 = q[1];
        let (v3, v8): (f32, f32) = ::libm::sincosf(v2);
        let v4: f32 = v1 * v3;
        let v5: f32 = q[2];
        let (v10, v6): (f32, f32) = ::libm::sincosf(v5);
        let v7: f32 = v4 * v6;
        let v9: f32 = v1 * v8;
        let v11: f32 = v9 * v10;
        let v12: f32 = v7 + v11;
        let v13: f32 = q[3];
        let (v14, v19): (f32, f32) = ::libm::sincosf(v13);
        let v15: f32 = v12 * v14;
        let v16: f32 = v9 * v6;
        let v17: f32 = v4 * v10;
        let v18: f32 = v16 - v17;
        let v20: f32 = v18 * v19;
        let v21: f32 = v15 - v20;
        let v22: f32 = q[4];
        let (v23, v26): (f32, f32) = ::libm::sincosf(v22);
        let v24: f32 = v21 * v23;
        let v27: f32 = v25 * v26;
        let v28: f32 = v24 + v27;
        let v29: f32 = -v28;
        let v30: f32 = v21 * v26;
        let v31: f32 = v25 * v23;
        let v32: f32 = v30 - v31;
        let v33: f32 = q[5];
        let (v39, v34): (f32, f32) = ::libm::sincosf(v33);
        let v35: f32 = v32 * v34;
        let v36: f32 = v12 * v19;
        let v37: f32 = v18 * v14;
        let v38: f32 = v36 + v37;
        let v40: f32 = v38 * v39;
        let v41: f32 = v35 + v40;
        let v42: f32 = -v41;
        let v43: f32 = v32 * v39;
        let v44: f32 = v38 * v34;
        let v45: f32 = v43 - v44;
        let v46: f32 = 0.425_f32;
        let v47: f32 = v46 * v9;
        let v48: f32 = -0.1197_f32;
        let v49: f32 = v48 * v25;
        let v50: f32 = v47 - v49;
        let v51: f32 = 0.13585_f32;
        let v52: f32 = v51 * v25;
        let v53: f32 = v50 - v52;
        let v54: f32 = 0.39225_f32;
        let v55: f32 = v54 * v18;
        let v56: f32 = v53 + v55;
        let v57: f32 = 0.093_f32;
        let v58: f32 = v57 * v25;
        let v59: f32 = v56 - v58;
        let v60: f32 = 0.09465_f32;
        let v61: f32 = v60 * v38;
        let v62: f32 = v59 - v61;
        let v63: f32 = 0.0823_f32;
        let v64: f32 = v63 * v28;
        let v65: f32 = v62 - v64;
        let v66: f32 = v1 * v26;
        let v67: f32 = v25 * v3;
        let v68: f32 = v67 * v6;
        let v69: f32 = v25 * v8;
        let v70: f32 = v69 * v10;
        let v71: f32 = v68 + v70;
        let v72: f32 = v71 * v14;
        let v73: f32 = v69 * v6;
        let v74: f32 = v67 * v10;
        let v75: f32 = v73 - v74;
        let v76: f32 = v75 * v19;
        let v77: f32 = v72 - v76;
        let v78: f32 = v77 * v23;
        let v79: f32 = v66 - v78;
        let v80: f32 = v77 * v26;
        let v81: f32 = v1 * v23;
        let v82: f32 = v80 + v81;
        let v83: f32 = v82 * v34;
        let v84: f32 = v71 * v19;
        let v85: f32 = v75 * v14;
        let v86: f32 = v84 + v85;
        let v87: f32 = v86 * v39;
        let v88: f32 = v83 + v87;
        let v89: f32 = -v88;
        let v90: f32 = v82 * v39;
        let v91: f32 = v86 * v34;
        let v92: f32 = v90 - v91;
        let v93: f32 = v51 * v1;
        let v94: f32 = v48 * v1;
        let v95: f32 = v46 * v69;
        let v96: f32 = v94 + v95;
        let v97: f32 = v93 + v96;
        let v98: f32 = v54 * v75;
        let v99: f32 = v97 + v98;
        let v100: f32 = v57 * v1;
        let v101: f32 = v99 + v100;
        let v102: f32 = v60 * v86;
        let v103: f32 = v101 - v102;
        let v104: f32 = v63 * v79;
        let v105: f32 = v103 + v104;
        let v106: f32 = v8 * v10;
        let v107: f32 = v3 * v6;
        let v108: f32 = v106 + v107;
        let v109: f32 = v108 * v19;
        let v110: f32 = v3 * v10;
        let v111: f32 = v8 * v6;
        let v112: f32 = v110 - v111;
        let v113: f32 = v112 * v14;
        let v114: f32 = v109 - v113;
        let v115: f32 = v114 * v23;
        let v116: f32 = -v115;
        let v117: f32 = v114 * v26;
        let v118: f32 = v117 * v34;
        let v119: f32 = v112 * v19;
        let v120: f32 = v108 * v14;
        let v121: f32 = v119 + v120;
        let v122: f32 = v121 * v39;
        let v123: f32 = v118 - v122;
        let v124: f32 = -v123;
        let v125: f32 = v117 * v39;
        let v126: f32 = v121 * v34;
        let v127: f32 = v125 + v126;
        let v128: f32 = 0.089159_f32;
        let v129: f32 = v46 * v3;
        let v130: f32 = v128 - v129;
        let v131: f32 = v54 * v108;
        let v132: f32 = v130 - v131;
        let v133: f32 = v60 * v121;
        let v134: f32 = v132 + v133;
        let v135: f32 = v63 * v115;
        let v136: f32 = v134 - v135;
        let v137: f32 = 0.0_f32;
        let v138: f32 = 1.0_f32;
        [
            [v29, v42, v45, v65],
            [v79, v89, v92, v105],
            [v116, v124, v127, v136],
            [v137, v137, v137, v138],
        ]
    }
    /// Geometric Jacobian of the end-effector frame origin in the base frame (thesis eq. 3.29).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian: [[f32; 6]; 6]` (6 x 6, row-major): rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame
    ///
    /// Operation count: 113 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jacobian(q: &[f32; 6]) -> [[f32; 6]; 6] {
        let v0: f32 = -0.10915_f32;
        let v1: f32 = 0.0823_f32;
        let v2: f32 = q[4];
        let (v13, v3): (f32, f32) = ::libm::sincosf(v2);
        let v4: f32 = v1 * v3;
        let v5: f32 = v0 - v4;
        let v6: f32 = q[0];
        let (v43, v7): (f32, f32) = ::libm::sincosf(v6);
        let v8: f32 = v5 * v7;
        let v9: f32 = 0.09465_f32;
        let v10: f32 = q[3];
        let (v15, v11): (f32, f32) = ::libm::sincosf(v10);
        let v12: f32 = v9 * v11;
        let v14: f32 = v1 * v13;
        let v16: f32 = v14 * v15;
        let v17: f32 = v12 + v16;
        let v18: f32 = q[2];
        let (v26, v19): (f32, f32) = ::libm::sincosf(v18);
        let v20: f32 = v17 * v19;
        let v21: f32 = 0.39225_f32;
        let v22: f32 = v14 * v11;
        let v23: f32 = v21 + v22;
        let v24: f32 = v9 * v15;
        let v25: f32 = v23 - v24;
        let v27: f32 = v25 * v26;
        let v28: f32 = v20 + v27;
        let v29: f32 = q[1];
        let (v30, v40): (f32, f32) = ::libm::sincosf(v29);
        let v31: f32 = v28 * v30;
        let v32: f32 = -0.425_f32;
        let v33: f32 = v17 * v26;
        let v34: f32 = v32 + v33;
        let v35: f32 = -0.39225_f32;
        let v36: f32 = v35 - v22;
        let v37: f32 = v36 + v24;
        let v38: f32 = v37 * v19;
        let v39: f32 = v34 + v38;
        let v41: f32 = v39 * v40;
        let v42: f32 = v31 + v41;
        let v44: f32 = v42 * v43;
        let v45: f32 = v8 + v44;
        let v46: f32 = v37 * v26;
        let v47: f32 = v46 - v20;
        let v48: f32 = v47 * v40;
        let v49: f32 = v39 * v30;
        let v50: f32 = v48 + v49;
        let v51: f32 = v50 * v7;
        let v52: f32 = v33 + v38;
        let v53: f32 = v52 * v30;
        let v54: f32 = v48 + v53;
        let v55: f32 = v54 * v7;
        let v56: f32 = v24 - v22;
        let v57: f32 = v56 * v26;
        let v58: f32 = v57 - v20;
        let v59: f32 = v58 * v40;
        let v60: f32 = v56 * v19;
        let v61: f32 = v60 + v33;
        let v62: f32 = v61 * v30;
        let v63: f32 = v59 + v62;
        let v64: f32 = v63 * v7;
        let v65: f32 = v14 * v43;
        let v66: f32 = v1 * v11;
        let v67: f32 = v66 * v19;
        let v68: f32 = v1 * v15;
        let v69: f32 = v68 * v26;
        let v70: f32 = v67 - v69;
        let v71: f32 = v70 * v40;
        let v72: f32 = v68 * v19;
        let v73: f32 = v66 * v26;
        let v74: f32 = v72 + v73;
        let v75: f32 = v74 * v30;
        let v76: f32 = v71 - v75;
        let v77: f32 = v76 * v3;
        let v78: f32 = v77 * v7;
        let v79: f32 = v65 + v78;
        let v80: f32 = 0.0_f32;
        let v81: f32 = v5 * v43;
        let v82: f32 = v47 * v30;
        let v83: f32 = 0.425_f32;
        let v84: f32 = v83 - v33;
        let v85: f32 = v25 * v19;
        let v86: f32 = v84 + v85;
        let v87: f32 = v86 * v40;
        let v88: f32 = v82 + v87;
        let v89: f32 = v88 * v7;
        let v90: f32 = v81 + v89;
        let v91: f32 = v50 * v43;
        let v92: f32 = v54 * v43;
        let v93: f32 = v63 * v43;
        let v94: f32 = v77 * v43;
        let v95: f32 = v14 * v7;
        let v96: f32 = v94 - v95;
        let v97: f32 = v52 * v40;
        let v98: f32 = v97 + v31;
        let v99: f32 = v61 * v40;
        let v100: f32 = v22 - v24;
        let v101: f32 = v100 * v26;
        let v102: f32 = v20 + v101;
        let v103: f32 = v102 * v30;
        let v104: f32 = v99 + v103;
        let v105: f32 = v69 - v67;
        let v106: f32 = v105 * v30;
        let v107: f32 = v74 * v40;
        let v108: f32 = v106 - v107;
        let v109: f32 = v108 * v3;
        let v110: f32 = -v43;
        let v111: f32 = v15 * v26;
        let v112: f32 = v11 * v19;
        let v113: f32 = v111 - v112;
        let v114: f32 = v113 * v30;
        let v115: f32 = v15 * v19;
        let v116: f32 = v11 * v26;
        let v117: f32 = v115 + v116;
        let v118: f32 = v117 * v40;
        let v119: f32 = v114 - v118;
        let v120: f32 = v119 * v7;
        let v121: f32 = v112 - v111;
        let v122: f32 = v121 * v40;
        let v123: f32 = v117 * v30;
        let v124: f32 = v122 - v123;
        let v125: f32 = v124 * v13;
        let v126: f32 = v125 * v7;
        let v127: f32 = v3 * v43;
        let v128: f32 = v126 - v127;
        let v129: f32 = v119 * v43;
        let v130: f32 = v3 * v7;
        let v131: f32 = v125 * v43;
        let v132: f32 = v130 + v131;
        let v133: f32 = 1.0_f32;
        let v134: f32 = v113 * v40;
        let v135: f32 = v134 + v123;
        let v136: f32 = v119 * v13;
        [
            [v45, v51, v55, v64, v79, v80],
            [v90, v91, v92, v93, v96, v80],
            [v80, v42, v98, v104, v109, v80],
            [v80, v110, v110, v110, v120, v128],
            [v80, v7, v7, v7, v129, v132],
            [v133, v80, v80, v80, v135, v136],
        ]
    }
    /// Jacobian and tool position in one pass: `[J | p; 0]`, row r is `[J_r0, ..., J_r(n-1), p_r]` with `J` the geometric Jacobian of `jacobian` and `p` the end-effector origin of `end_effector_pose` (rows 0-2; the last column of rows 3-5 is 0), the same operations as those two functions (bit-identical results), with common subexpressions, sin/cos included, computed once for both and the pose's rotation not computed.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian_and_position: [[f32; 7]; 6]` (6 x 7, row-major): rows `[J(q) | p(q); 0]`: the geometric Jacobian of `jacobian` (rows vx vy vz per unit joint velocity, then wx wy wz, base frame), then the end-effector origin (m, base frame) in rows 0-2 of the last column, 0 in rows 3-5
    ///
    /// Operation count: 194 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jacobian_and_position(q: &[f32; 6]) -> [[f32; 7]; 6] {
        let (
            v1,
            v3,
            v5,
            v7,
            v9,
            v11,
            v13,
            v14,
            v15,
            v19,
            v20,
            v21,
            v22,
            v24,
            v25,
            v26,
            v30,
            v31,
            v33,
            v40,
            v42,
            v43,
            v45,
            v47,
            v50,
            v51,
            v52,
            v54,
            v55,
            v61,
            v63,
            v64,
            v67,
            v69,
            v74,
            v77,
            v79,
            v80,
            v81,
            v84,
            v87,
            v96,
            v106,
            v110,
        ) = {
            let v0: f32 = -0.10915_f32;
            let v1: f32 = 0.0823_f32;
            let v2: f32 = q[4];
            let (v13, v3): (f32, f32) = ::libm::sincosf(v2);
            let v4: f32 = v1 * v3;
            let v5: f32 = v0 - v4;
            let v6: f32 = q[0];
            let (v43, v7): (f32, f32) = ::libm::sincosf(v6);
            let v8: f32 = v5 * v7;
            let v9: f32 = 0.09465_f32;
            let v10: f32 = q[3];
            let (v15, v11): (f32, f32) = ::libm::sincosf(v10);
            let v12: f32 = v9 * v11;
            let v14: f32 = v1 * v13;
            let v16: f32 = v14 * v15;
            let v17: f32 = v12 + v16;
            let v18: f32 = q[2];
            let (v26, v19): (f32, f32) = ::libm::sincosf(v18);
            let v20: f32 = v17 * v19;
            let v21: f32 = 0.39225_f32;
            let v22: f32 = v14 * v11;
            let v23: f32 = v21 + v22;
            let v24: f32 = v9 * v15;
            let v25: f32 = v23 - v24;
            let v27: f32 = v25 * v26;
            let v28: f32 = v20 + v27;
            let v29: f32 = q[1];
            let (v30, v40): (f32, f32) = ::libm::sincosf(v29);
            let v31: f32 = v28 * v30;
            let v32: f32 = -0.425_f32;
            let v33: f32 = v17 * v26;
            let v34: f32 = v32 + v33;
            let v35: f32 = -0.39225_f32;
            let v36: f32 = v35 - v22;
            let v37: f32 = v36 + v24;
            let v38: f32 = v37 * v19;
            let v39: f32 = v34 + v38;
            let v41: f32 = v39 * v40;
            let v42: f32 = v31 + v41;
            let v44: f32 = v42 * v43;
            let v45: f32 = v8 + v44;
            let v46: f32 = v37 * v26;
            let v47: f32 = v46 - v20;
            let v48: f32 = v47 * v40;
            let v49: f32 = v39 * v30;
            let v50: f32 = v48 + v49;
            let v51: f32 = v50 * v7;
            let v52: f32 = v33 + v38;
            let v53: f32 = v52 * v30;
            let v54: f32 = v48 + v53;
            let v55: f32 = v54 * v7;
            let v56: f32 = v24 - v22;
            let v57: f32 = v56 * v26;
            let v58: f32 = v57 - v20;
            let v59: f32 = v58 * v40;
            let v60: f32 = v56 * v19;
            let v61: f32 = v60 + v33;
            let v62: f32 = v61 * v30;
            let v63: f32 = v59 + v62;
            let v64: f32 = v63 * v7;
            let v65: f32 = v14 * v43;
            let v66: f32 = v1 * v11;
            let v67: f32 = v66 * v19;
            let v68: f32 = v1 * v15;
            let v69: f32 = v68 * v26;
            let v70: f32 = v67 - v69;
            let v71: f32 = v70 * v40;
            let v72: f32 = v68 * v19;
            let v73: f32 = v66 * v26;
            let v74: f32 = v72 + v73;
            let v75: f32 = v74 * v30;
            let v76: f32 = v71 - v75;
            let v77: f32 = v76 * v3;
            let v78: f32 = v77 * v7;
            let v79: f32 = v65 + v78;
            let v80: f32 = 0.0_f32;
            let v81: f32 = 0.425_f32;
            let v82: f32 = v7 * v40;
            let v83: f32 = v81 * v82;
            let v84: f32 = -0.1197_f32;
            let v85: f32 = v84 * v43;
            let v86: f32 = v83 - v85;
            let v87: f32 = 0.13585_f32;
            let v88: f32 = v87 * v43;
            let v89: f32 = v86 - v88;
            let v90: f32 = v82 * v19;
            let v91: f32 = v7 * v30;
            let v92: f32 = v91 * v26;
            let v93: f32 = v90 - v92;
            let v94: f32 = v21 * v93;
            let v95: f32 = v89 + v94;
            let v96: f32 = 0.093_f32;
            let v97: f32 = v96 * v43;
            let v98: f32 = v95 - v97;
            let v99: f32 = v91 * v19;
            let v100: f32 = v82 * v26;
            let v101: f32 = v99 + v100;
            let v102: f32 = v101 * v11;
            let v103: f32 = v93 * v15;
            let v104: f32 = v102 + v103;
            let v105: f32 = v9 * v104;
            let v106: f32 = v98 - v105;
            let v107: f32 = v101 * v15;
            let v108: f32 = v93 * v11;
            let v109: f32 = v107 - v108;
            let v110: f32 = v109 * v13;
            (
                v1,
                v3,
                v5,
                v7,
                v9,
                v11,
                v13,
                v14,
                v15,
                v19,
                v20,
                v21,
                v22,
                v24,
                v25,
                v26,
                v30,
                v31,
                v33,
                v40,
                v42,
                v43,
                v45,
                v47,
                v50,
                v51,
                v52,
                v54,
                v55,
                v61,
                v63,
                v64,
                v67,
                v69,
                v74,
                v77,
                v79,
                v80,
                v81,
                v84,
                v87,
                v96,
                v106,
                v110,
            )
        };
        let (
            v114,
            v123,
            v124,
            v125,
            v126,
            v129,
            v159,
            v161,
            v167,
            v172,
            v194,
            v195,
            v205,
            v213,
            v214,
            v217,
            v218,
            v220,
            v221,
        ) = {
            let v111: f32 = v43 * v3;
            let v112: f32 = v110 + v111;
            let v113: f32 = v1 * v112;
            let v114: f32 = v106 - v113;
            let v115: f32 = v5 * v43;
            let v116: f32 = v47 * v30;
            let v117: f32 = v81 - v33;
            let v118: f32 = v25 * v19;
            let v119: f32 = v117 + v118;
            let v120: f32 = v119 * v40;
            let v121: f32 = v116 + v120;
            let v122: f32 = v121 * v7;
            let v123: f32 = v115 + v122;
            let v124: f32 = v50 * v43;
            let v125: f32 = v54 * v43;
            let v126: f32 = v63 * v43;
            let v127: f32 = v77 * v43;
            let v128: f32 = v14 * v7;
            let v129: f32 = v127 - v128;
            let v130: f32 = v87 * v7;
            let v131: f32 = v84 * v7;
            let v132: f32 = v43 * v40;
            let v133: f32 = v81 * v132;
            let v134: f32 = v131 + v133;
            let v135: f32 = v130 + v134;
            let v136: f32 = v132 * v19;
            let v137: f32 = v43 * v30;
            let v138: f32 = v137 * v26;
            let v139: f32 = v136 - v138;
            let v140: f32 = v21 * v139;
            let v141: f32 = v135 + v140;
            let v142: f32 = v96 * v7;
            let v143: f32 = v141 + v142;
            let v144: f32 = v137 * v19;
            let v145: f32 = v132 * v26;
            let v146: f32 = v144 + v145;
            let v147: f32 = v146 * v11;
            let v148: f32 = v139 * v15;
            let v149: f32 = v147 + v148;
            let v150: f32 = v9 * v149;
            let v151: f32 = v143 - v150;
            let v152: f32 = v7 * v3;
            let v153: f32 = v146 * v15;
            let v154: f32 = v139 * v11;
            let v155: f32 = v153 - v154;
            let v156: f32 = v155 * v13;
            let v157: f32 = v152 - v156;
            let v158: f32 = v1 * v157;
            let v159: f32 = v151 + v158;
            let v160: f32 = v52 * v40;
            let v161: f32 = v160 + v31;
            let v162: f32 = v61 * v40;
            let v163: f32 = v22 - v24;
            let v164: f32 = v163 * v26;
            let v165: f32 = v20 + v164;
            let v166: f32 = v165 * v30;
            let v167: f32 = v162 + v166;
            let v168: f32 = v69 - v67;
            let v169: f32 = v168 * v30;
            let v170: f32 = v74 * v40;
            let v171: f32 = v169 - v170;
            let v172: f32 = v171 * v3;
            let v173: f32 = 0.089159_f32;
            let v174: f32 = v81 * v30;
            let v175: f32 = v173 - v174;
            let v176: f32 = v40 * v26;
            let v177: f32 = v30 * v19;
            let v178: f32 = v176 + v177;
            let v179: f32 = v21 * v178;
            let v180: f32 = v175 - v179;
            let v181: f32 = v30 * v26;
            let v182: f32 = v40 * v19;
            let v183: f32 = v181 - v182;
            let v184: f32 = v183 * v11;
            let v185: f32 = v178 * v15;
            let v186: f32 = v184 + v185;
            let v187: f32 = v9 * v186;
            let v188: f32 = v180 + v187;
            let v189: f32 = v178 * v11;
            let v190: f32 = v183 * v15;
            let v191: f32 = v189 - v190;
            let v192: f32 = v191 * v13;
            let v193: f32 = v1 * v192;
            let v194: f32 = v188 - v193;
            let v195: f32 = -v43;
            let v196: f32 = v15 * v26;
            let v197: f32 = v11 * v19;
            let v198: f32 = v196 - v197;
            let v199: f32 = v198 * v30;
            let v200: f32 = v15 * v19;
            let v201: f32 = v11 * v26;
            let v202: f32 = v200 + v201;
            let v203: f32 = v202 * v40;
            let v204: f32 = v199 - v203;
            let v205: f32 = v204 * v7;
            let v206: f32 = v197 - v196;
            let v207: f32 = v206 * v40;
            let v208: f32 = v202 * v30;
            let v209: f32 = v207 - v208;
            let v210: f32 = v209 * v13;
            let v211: f32 = v210 * v7;
            let v212: f32 = v3 * v43;
            let v213: f32 = v211 - v212;
            let v214: f32 = v204 * v43;
            let v215: f32 = v3 * v7;
            let v216: f32 = v210 * v43;
            let v217: f32 = v215 + v216;
            let v218: f32 = 1.0_f32;
            let v219: f32 = v198 * v40;
            let v220: f32 = v219 + v208;
            let v221: f32 = v204 * v13;
            (
                v114,
                v123,
                v124,
                v125,
                v126,
                v129,
                v159,
                v161,
                v167,
                v172,
                v194,
                v195,
                v205,
                v213,
                v214,
                v217,
                v218,
                v220,
                v221,
            )
        };
        [
            [v45, v51, v55, v64, v79, v80, v114],
            [v123, v124, v125, v126, v129, v80, v159],
            [v80, v42, v161, v167, v172, v80, v194],
            [v80, v195, v195, v195, v205, v213, v80],
            [v80, v7, v7, v7, v214, v217, v80],
            [v218, v80, v80, v80, v220, v221, v80],
        ]
    }
    /// Acceleration term of the end-effector twist: `d/dt (J qd) = J qdd + Jdot qd`.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 6]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `jdot_qd: [f32; 6]`: Jdot(q, qd) qd: m/s^2 (rows 0-2) and rad/s^2 (rows 3-5), base frame
    ///
    /// Operation count: 263 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jdot_qd(q: &[f32; 6], qd: &[f32; 6]) -> [f32; 6] {
        let (
            v1,
            v5,
            v6,
            v8,
            v10,
            v13,
            v15,
            v18,
            v21,
            v24,
            v34,
            v35,
            v37,
            v39,
            v46,
            v50,
            v54,
            v58,
            v60,
            v65,
            v71,
            v72,
            v77,
            v83,
            v87,
            v96,
            v101,
            v106,
            v113,
            v119,
            v122,
            v124,
            v127,
            v130,
            v137,
            v141,
            v145,
            v146,
            v152,
        ) = {
            let v0: f32 = 0.0823_f32;
            let v1: f32 = qd[4];
            let v2: f32 = v0 * v1;
            let v3: f32 = v2 * v1;
            let v4: f32 = q[4];
            let (v21, v5): (f32, f32) = ::libm::sincosf(v4);
            let v6: f32 = v3 * v5;
            let v7: f32 = 0.10915_f32;
            let v8: f32 = v0 * v5;
            let v9: f32 = v7 + v8;
            let v10: f32 = qd[0];
            let v11: f32 = v9 * v10;
            let v12: f32 = 0.1646_f32;
            let v13: f32 = qd[3];
            let v14: f32 = v12 * v13;
            let v15: f32 = qd[2];
            let v16: f32 = v12 * v15;
            let v17: f32 = v14 + v16;
            let v18: f32 = qd[1];
            let v19: f32 = v12 * v18;
            let v20: f32 = v17 + v19;
            let v22: f32 = v20 * v21;
            let v23: f32 = q[3];
            let (v24, v35): (f32, f32) = ::libm::sincosf(v23);
            let v25: f32 = v22 * v24;
            let v26: f32 = 0.1893_f32;
            let v27: f32 = v26 * v13;
            let v28: f32 = v26 * v15;
            let v29: f32 = v27 + v28;
            let v30: f32 = v26 * v18;
            let v31: f32 = v29 + v30;
            let v32: f32 = v12 * v1;
            let v33: f32 = v32 * v5;
            let v34: f32 = v31 - v33;
            let v36: f32 = v34 * v35;
            let v37: f32 = v25 + v36;
            let v38: f32 = q[2];
            let (v50, v39): (f32, f32) = ::libm::sincosf(v38);
            let v40: f32 = v37 * v39;
            let v41: f32 = 0.7845_f32;
            let v42: f32 = v41 * v15;
            let v43: f32 = v41 * v18;
            let v44: f32 = v42 + v43;
            let v45: f32 = v22 * v35;
            let v46: f32 = v44 + v45;
            let v47: f32 = v33 - v31;
            let v48: f32 = v47 * v24;
            let v49: f32 = v46 + v48;
            let v51: f32 = v49 * v50;
            let v52: f32 = v40 + v51;
            let v53: f32 = q[1];
            let (v65, v54): (f32, f32) = ::libm::sincosf(v53);
            let v55: f32 = v52 * v54;
            let v56: f32 = v11 + v55;
            let v57: f32 = 0.85_f32;
            let v58: f32 = v57 * v18;
            let v59: f32 = v47 * v35;
            let v60: f32 = v59 - v25;
            let v61: f32 = v60 * v50;
            let v62: f32 = v58 + v61;
            let v63: f32 = v49 * v39;
            let v64: f32 = v62 + v63;
            let v66: f32 = v64 * v65;
            let v67: f32 = v56 + v66;
            let v68: f32 = v67 * v10;
            let v69: f32 = v6 + v68;
            let v70: f32 = q[0];
            let (v71, v152): (f32, f32) = ::libm::sincosf(v70);
            let v72: f32 = v69 * v71;
            let v73: f32 = v32 * v10;
            let v74: f32 = v73 * v21;
            let v75: f32 = v0 * v13;
            let v76: f32 = v75 * v13;
            let v77: f32 = v3 + v76;
            let v78: f32 = v0 * v10;
            let v79: f32 = v78 * v10;
            let v80: f32 = v77 + v79;
            let v81: f32 = v0 * v15;
            let v82: f32 = v14 + v81;
            let v83: f32 = v82 * v15;
            let v84: f32 = v80 + v83;
            let v85: f32 = v0 * v18;
            let v86: f32 = v17 + v85;
            let v87: f32 = v86 * v18;
            let v88: f32 = v84 + v87;
            let v89: f32 = v88 * v21;
            let v90: f32 = v89 * v24;
            let v91: f32 = 0.09465_f32;
            let v92: f32 = v91 * v10;
            let v93: f32 = v92 * v10;
            let v94: f32 = v91 * v13;
            let v95: f32 = v94 - v33;
            let v96: f32 = v95 * v13;
            let v97: f32 = v93 + v96;
            let v98: f32 = v91 * v15;
            let v99: f32 = v27 + v98;
            let v100: f32 = v99 - v33;
            let v101: f32 = v100 * v15;
            let v102: f32 = v97 + v101;
            let v103: f32 = v91 * v18;
            let v104: f32 = v29 + v103;
            let v105: f32 = v104 - v33;
            let v106: f32 = v105 * v18;
            let v107: f32 = v102 + v106;
            let v108: f32 = v107 * v35;
            let v109: f32 = v90 + v108;
            let v110: f32 = v109 * v39;
            let v111: f32 = 0.39225_f32;
            let v112: f32 = v111 * v15;
            let v113: f32 = v112 * v15;
            let v114: f32 = v111 * v10;
            let v115: f32 = v114 * v10;
            let v116: f32 = v113 + v115;
            let v117: f32 = v111 * v18;
            let v118: f32 = v42 + v117;
            let v119: f32 = v118 * v18;
            let v120: f32 = v116 + v119;
            let v121: f32 = v89 * v35;
            let v122: f32 = v120 + v121;
            let v123: f32 = v33 - v94;
            let v124: f32 = v123 * v13;
            let v125: f32 = v124 - v93;
            let v126: f32 = v33 - v99;
            let v127: f32 = v126 * v15;
            let v128: f32 = v125 + v127;
            let v129: f32 = v33 - v104;
            let v130: f32 = v129 * v18;
            let v131: f32 = v128 + v130;
            let v132: f32 = v131 * v24;
            let v133: f32 = v122 + v132;
            let v134: f32 = v133 * v50;
            let v135: f32 = v110 + v134;
            let v136: f32 = v135 * v65;
            let v137: f32 = v74 + v136;
            let v138: f32 = v109 * v50;
            let v139: f32 = 0.425_f32;
            let v140: f32 = v139 * v18;
            let v141: f32 = v140 * v18;
            let v142: f32 = v139 * v10;
            let v143: f32 = v142 * v10;
            let v144: f32 = v141 + v143;
            let v145: f32 = v138 - v144;
            let v146: f32 = v107 * v24;
            (
                v1,
                v5,
                v6,
                v8,
                v10,
                v13,
                v15,
                v18,
                v21,
                v24,
                v34,
                v35,
                v37,
                v39,
                v46,
                v50,
                v54,
                v58,
                v60,
                v65,
                v71,
                v72,
                v77,
                v83,
                v87,
                v96,
                v101,
                v106,
                v113,
                v119,
                v122,
                v124,
                v127,
                v130,
                v137,
                v141,
                v145,
                v146,
                v152,
            )
        };
        let (v154, v175, v202, v262, v274, v293) = {
            let v147: f32 = v146 - v122;
            let v148: f32 = v147 * v39;
            let v149: f32 = v145 + v148;
            let v150: f32 = v149 * v54;
            let v151: f32 = v137 + v150;
            let v153: f32 = v151 * v152;
            let v154: f32 = v72 + v153;
            let v155: f32 = -0.10915_f32;
            let v156: f32 = v155 - v8;
            let v157: f32 = v156 * v10;
            let v158: f32 = v60 * v39;
            let v159: f32 = v34 * v24;
            let v160: f32 = v159 - v46;
            let v161: f32 = v160 * v50;
            let v162: f32 = v158 + v161;
            let v163: f32 = v162 * v54;
            let v164: f32 = v157 + v163;
            let v165: f32 = v37 * v50;
            let v166: f32 = v165 - v58;
            let v167: f32 = v160 * v39;
            let v168: f32 = v166 + v167;
            let v169: f32 = v168 * v65;
            let v170: f32 = v164 + v169;
            let v171: f32 = v170 * v10;
            let v172: f32 = v171 - v6;
            let v173: f32 = v172 * v152;
            let v174: f32 = v151 * v71;
            let v175: f32 = v173 + v174;
            let v176: f32 = v77 + v83;
            let v177: f32 = v176 + v87;
            let v178: f32 = v177 * v21;
            let v179: f32 = v178 * v24;
            let v180: f32 = v96 + v101;
            let v181: f32 = v180 + v106;
            let v182: f32 = v181 * v35;
            let v183: f32 = v179 + v182;
            let v184: f32 = v183 * v39;
            let v185: f32 = v113 + v119;
            let v186: f32 = v178 * v35;
            let v187: f32 = v185 + v186;
            let v188: f32 = v124 + v127;
            let v189: f32 = v188 + v130;
            let v190: f32 = v189 * v24;
            let v191: f32 = v187 + v190;
            let v192: f32 = v191 * v50;
            let v193: f32 = v184 + v192;
            let v194: f32 = v193 * v54;
            let v195: f32 = v189 * v35;
            let v196: f32 = v195 - v179;
            let v197: f32 = v196 * v50;
            let v198: f32 = v141 + v197;
            let v199: f32 = v191 * v39;
            let v200: f32 = v198 + v199;
            let v201: f32 = v200 * v65;
            let v202: f32 = v194 + v201;
            let v203: f32 = qd[5];
            let v204: f32 = v203 * v1;
            let v205: f32 = v204 * v21;
            let v206: f32 = v1 * v24;
            let v207: f32 = v203 * v21;
            let v208: f32 = v207 * v35;
            let v209: f32 = v206 - v208;
            let v210: f32 = v209 * v39;
            let v211: f32 = v1 * v35;
            let v212: f32 = v207 * v24;
            let v213: f32 = v211 + v212;
            let v214: f32 = v213 * v50;
            let v215: f32 = v210 + v214;
            let v216: f32 = v215 * v54;
            let v217: f32 = v213 * v39;
            let v218: f32 = v208 - v206;
            let v219: f32 = v218 * v50;
            let v220: f32 = v217 + v219;
            let v221: f32 = v220 * v65;
            let v222: f32 = v216 + v221;
            let v223: f32 = v222 * v10;
            let v224: f32 = v205 + v223;
            let v225: f32 = v224 * v71;
            let v226: f32 = v13 + v15;
            let v227: f32 = v226 + v18;
            let v228: f32 = v227 * v24;
            let v229: f32 = v228 * v50;
            let v230: f32 = v227 * v35;
            let v231: f32 = v230 * v39;
            let v232: f32 = v229 - v231;
            let v233: f32 = v232 * v54;
            let v234: f32 = v228 * v39;
            let v235: f32 = v230 * v50;
            let v236: f32 = v234 + v235;
            let v237: f32 = v236 * v65;
            let v238: f32 = v233 + v237;
            let v239: f32 = v238 * v1;
            let v240: f32 = v227 * v10;
            let v241: f32 = v239 - v240;
            let v242: f32 = v35 * v39;
            let v243: f32 = v24 * v50;
            let v244: f32 = v242 - v243;
            let v245: f32 = v244 * v54;
            let v246: f32 = v24 * v39;
            let v247: f32 = v35 * v50;
            let v248: f32 = v246 + v247;
            let v249: f32 = v248 * v65;
            let v250: f32 = v245 - v249;
            let v251: f32 = v250 * v1;
            let v252: f32 = v251 - v10;
            let v253: f32 = v252 * v5;
            let v254: f32 = v232 * v65;
            let v255: f32 = v236 * v54;
            let v256: f32 = v254 - v255;
            let v257: f32 = v256 * v21;
            let v258: f32 = v253 + v257;
            let v259: f32 = v258 * v203;
            let v260: f32 = v241 + v259;
            let v261: f32 = v260 * v152;
            let v262: f32 = v225 + v261;
            let v263: f32 = v218 * v39;
            let v264: f32 = v263 - v214;
            let v265: f32 = v264 * v54;
            let v266: f32 = v209 * v50;
            let v267: f32 = v266 - v217;
            let v268: f32 = v267 * v65;
            let v269: f32 = v265 + v268;
            let v270: f32 = v269 * v10;
            let v271: f32 = v270 - v205;
            let v272: f32 = v271 * v152;
            let v273: f32 = v260 * v71;
            let v274: f32 = v272 + v273;
            let v275: f32 = v238 * v203;
            let v276: f32 = v275 * v21;
            let v277: f32 = v203 * v5;
            let v278: f32 = v227 - v277;
            let v279: f32 = v278 * v24;
            let v280: f32 = v279 * v39;
            let v281: f32 = v278 * v35;
            let v282: f32 = v281 * v50;
            let v283: f32 = v280 + v282;
            let v284: f32 = v283 * v54;
            let v285: f32 = v281 * v39;
            let v286: f32 = v277 - v227;
            let v287: f32 = v286 * v24;
            let v288: f32 = v287 * v50;
            let v289: f32 = v285 + v288;
            let v290: f32 = v289 * v65;
            let v291: f32 = v284 + v290;
            let v292: f32 = v291 * v1;
            let v293: f32 = v276 + v292;
            (v154, v175, v202, v262, v274, v293)
        };
        [v154, v175, v202, v262, v274, v293]
    }
    /// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `mass_matrix: [[f32; 6]; 6]` (6 x 6, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
    ///
    /// Operation count: 238 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn mass_matrix(q: &[f32; 6]) -> [[f32; 6]; 6] {
        let (
            v0,
            v2,
            v3,
            v5,
            v6,
            v8,
            v10,
            v20,
            v25,
            v27,
            v32,
            v34,
            v39,
            v42,
            v48,
            v49,
            v51,
            v52,
            v53,
            v66,
            v67,
            v69,
            v73,
            v78,
            v87,
            v108,
            v109,
            v115,
            v116,
            v117,
            v120,
            v124,
            v127,
            v131,
            v134,
            v135,
            v136,
            v137,
            v141,
            v142,
        ) = {
            let v0: f32 = 0.00666_f32;
            let v1: f32 = q[1];
            let (v124, v2): (f32, f32) = ::libm::sincosf(v1);
            let v3: f32 = 0.8849019_f32;
            let v4: f32 = q[2];
            let (v73, v5): (f32, f32) = ::libm::sincosf(v4);
            let v6: f32 = 0.19163081_f32;
            let v7: f32 = q[3];
            let (v25, v8): (f32, f32) = ::libm::sincosf(v7);
            let v9: f32 = 0.21942_f32;
            let v10: f32 = 0.017136473_f32;
            let v11: f32 = q[5];
            let (v12, v16): (f32, f32) = ::libm::sincosf(v11);
            let v13: f32 = v10 * v12;
            let v14: f32 = v13 * v12;
            let v15: f32 = 0.033822_f32;
            let v17: f32 = v15 * v16;
            let v18: f32 = v17 * v16;
            let v19: f32 = v14 + v18;
            let v20: f32 = v9 + v19;
            let v21: f32 = 0.012168278_f32;
            let v22: f32 = v20 + v21;
            let v23: f32 = v9 + v22;
            let v24: f32 = v8 * v23;
            let v26: f32 = q[4];
            let (v52, v27): (f32, f32) = ::libm::sincosf(v26);
            let v28: f32 = v15 * v12;
            let v29: f32 = v28 * v16;
            let v30: f32 = v10 * v16;
            let v31: f32 = v30 * v12;
            let v32: f32 = v29 - v31;
            let v33: f32 = v27 * v32;
            let v34: f32 = v25 * v33;
            let v35: f32 = v24 - v34;
            let v36: f32 = v35 * v8;
            let v37: f32 = v17 * v12;
            let v38: f32 = v13 * v16;
            let v39: f32 = v37 - v38;
            let v40: f32 = v39 * v27;
            let v41: f32 = v8 * v40;
            let v42: f32 = 0.11117276_f32;
            let v43: f32 = v30 * v16;
            let v44: f32 = v28 * v12;
            let v45: f32 = v43 + v44;
            let v46: f32 = 0.0016833252_f32;
            let v47: f32 = v45 + v46;
            let v48: f32 = v42 + v47;
            let v49: f32 = v27 * v48;
            let v50: f32 = v49 * v27;
            let v51: f32 = 0.12999256_f32;
            let v53: f32 = v51 * v52;
            let v54: f32 = v53 * v52;
            let v55: f32 = v50 + v54;
            let v56: f32 = v55 + v21;
            let v57: f32 = v42 + v56;
            let v58: f32 = v25 * v57;
            let v59: f32 = v41 - v58;
            let v60: f32 = v59 * v25;
            let v61: f32 = v36 - v60;
            let v62: f32 = 0.40402114_f32;
            let v63: f32 = 2.0_f32;
            let v64: f32 = 0.39225_f32;
            let v65: f32 = 0.017784735_f32;
            let v66: f32 = v65 * v25;
            let v67: f32 = v64 * v66;
            let v68: f32 = v63 * v67;
            let v69: f32 = v62 - v68;
            let v70: f32 = v61 + v69;
            let v71: f32 = v6 + v70;
            let v72: f32 = v5 * v71;
            let v74: f32 = v8 * v57;
            let v75: f32 = v25 * v40;
            let v76: f32 = v74 + v75;
            let v77: f32 = v76 * v25;
            let v78: f32 = v8 * v33;
            let v79: f32 = v25 * v23;
            let v80: f32 = v78 + v79;
            let v81: f32 = v80 * v8;
            let v82: f32 = v77 - v81;
            let v83: f32 = v65 * v8;
            let v84: f32 = v64 * v83;
            let v85: f32 = v82 - v84;
            let v86: f32 = v73 * v85;
            let v87: f32 = v72 + v86;
            let v88: f32 = v87 * v5;
            let v89: f32 = 0.004095_f32;
            let v90: f32 = v76 * v8;
            let v91: f32 = v80 * v25;
            let v92: f32 = v90 + v91;
            let v93: f32 = v92 + v69;
            let v94: f32 = v93 - v62;
            let v95: f32 = v94 + v67;
            let v96: f32 = v95 + v67;
            let v97: f32 = v89 + v96;
            let v98: f32 = v73 * v97;
            let v99: f32 = v59 * v8;
            let v100: f32 = v35 * v25;
            let v101: f32 = v99 + v100;
            let v102: f32 = v101 + v84;
            let v103: f32 = v5 * v102;
            let v104: f32 = v98 - v103;
            let v105: f32 = v104 * v73;
            let v106: f32 = v88 + v105;
            let v107: f32 = 0.9554456_f32;
            let v108: f32 = -0.015661752_f32;
            let v109: f32 = 0.425_f32;
            let v110: f32 = 0.56875_f32;
            let v111: f32 = 1.0300093_f32;
            let v112: f32 = v111 - v66;
            let v113: f32 = v110 + v112;
            let v114: f32 = v5 * v113;
            let v115: f32 = v73 * v83;
            let v116: f32 = v114 - v115;
            let v117: f32 = v109 * v116;
            let v118: f32 = v108 + v117;
            let v119: f32 = v63 * v118;
            let v120: f32 = v107 + v119;
            let v121: f32 = v106 + v120;
            let v122: f32 = v3 + v121;
            let v123: f32 = v2 * v122;
            let v125: f32 = v5 * v85;
            let v126: f32 = v73 * v71;
            let v127: f32 = v125 - v126;
            let v128: f32 = v127 * v5;
            let v129: f32 = v73 * v102;
            let v130: f32 = v5 * v97;
            let v131: f32 = v129 + v130;
            let v132: f32 = v131 * v73;
            let v133: f32 = v128 + v132;
            let v134: f32 = v5 * v83;
            let v135: f32 = v73 * v113;
            let v136: f32 = v134 + v135;
            let v137: f32 = v109 * v136;
            let v138: f32 = v133 - v137;
            let v139: f32 = v124 * v138;
            let v140: f32 = v123 + v139;
            let v141: f32 = v140 * v2;
            let v142: f32 = v104 * v5;
            (
                v0,
                v2,
                v3,
                v5,
                v6,
                v8,
                v10,
                v20,
                v25,
                v27,
                v32,
                v34,
                v39,
                v42,
                v48,
                v49,
                v51,
                v52,
                v53,
                v66,
                v67,
                v69,
                v73,
                v78,
                v87,
                v108,
                v109,
                v115,
                v116,
                v117,
                v120,
                v124,
                v127,
                v131,
                v134,
                v135,
                v136,
                v137,
                v141,
                v142,
            )
        };
        let (
            v163,
            v205,
            v217,
            v238,
            v251,
            v264,
            v270,
            v272,
            v278,
            v279,
            v280,
            v282,
            v283,
            v284,
            v285,
        ) = {
            let v143: f32 = v87 * v73;
            let v144: f32 = v142 - v143;
            let v145: f32 = v144 - v137;
            let v146: f32 = v2 * v145;
            let v147: f32 = 0.0151074_f32;
            let v148: f32 = v131 * v5;
            let v149: f32 = v127 * v73;
            let v150: f32 = v148 - v149;
            let v151: f32 = v150 + v120;
            let v152: f32 = 0.88522506_f32;
            let v153: f32 = v151 - v152;
            let v154: f32 = v153 - v117;
            let v155: f32 = v154 - v117;
            let v156: f32 = v147 + v155;
            let v157: f32 = v124 * v156;
            let v158: f32 = v146 + v157;
            let v159: f32 = v158 * v124;
            let v160: f32 = v141 + v159;
            let v161: f32 = 0.1215021_f32;
            let v162: f32 = v160 + v161;
            let v163: f32 = v0 + v162;
            let v164: f32 = v39 * v52;
            let v165: f32 = 0.0016539803_f32;
            let v166: f32 = v164 - v165;
            let v167: f32 = v8 * v166;
            let v168: f32 = v49 * v52;
            let v169: f32 = v53 * v27;
            let v170: f32 = v168 - v169;
            let v171: f32 = v25 * v170;
            let v172: f32 = v167 - v171;
            let v173: f32 = v73 * v172;
            let v174: f32 = v8 * v170;
            let v175: f32 = v25 * v166;
            let v176: f32 = v174 + v175;
            let v177: f32 = 0.051322658_f32;
            let v178: f32 = v176 + v177;
            let v179: f32 = v5 * v178;
            let v180: f32 = v173 + v179;
            let v181: f32 = -0.24932103_f32;
            let v182: f32 = v180 + v181;
            let v183: f32 = -0.1197_f32;
            let v184: f32 = v183 * v116;
            let v185: f32 = v182 + v184;
            let v186: f32 = 0.05560772_f32;
            let v187: f32 = v185 + v186;
            let v188: f32 = v124 * v187;
            let v189: f32 = v5 * v172;
            let v190: f32 = v73 * v178;
            let v191: f32 = v189 - v190;
            let v192: f32 = v183 * v136;
            let v193: f32 = v191 - v192;
            let v194: f32 = v2 * v193;
            let v195: f32 = v188 - v194;
            let v196: f32 = 0.13585_f32;
            let v197: f32 = 2.35004_f32;
            let v198: f32 = 2.0828824_f32;
            let v199: f32 = v116 + v198;
            let v200: f32 = v197 + v199;
            let v201: f32 = v124 * v200;
            let v202: f32 = v2 * v136;
            let v203: f32 = v201 + v202;
            let v204: f32 = v196 * v203;
            let v205: f32 = v195 + v204;
            let v206: f32 = v180 + v184;
            let v207: f32 = v124 * v206;
            let v208: f32 = v135 + v134;
            let v209: f32 = v183 * v208;
            let v210: f32 = v191 - v209;
            let v211: f32 = v2 * v210;
            let v212: f32 = v207 - v211;
            let v213: f32 = v124 * v116;
            let v214: f32 = v2 * v208;
            let v215: f32 = v213 + v214;
            let v216: f32 = v196 * v215;
            let v217: f32 = v212 + v216;
            let v218: f32 = v73 * v176;
            let v219: f32 = v189 - v218;
            let v220: f32 = v73 * v66;
            let v221: f32 = v220 - v134;
            let v222: f32 = v183 * v221;
            let v223: f32 = v219 + v222;
            let v224: f32 = v2 * v223;
            let v225: f32 = v5 * v66;
            let v226: f32 = v225 + v115;
            let v227: f32 = v183 * v226;
            let v228: f32 = v5 * v176;
            let v229: f32 = v173 + v228;
            let v230: f32 = v227 - v229;
            let v231: f32 = v124 * v230;
            let v232: f32 = v224 + v231;
            let v233: f32 = v124 * v226;
            let v234: f32 = v2 * v221;
            let v235: f32 = v233 + v234;
            let v236: f32 = v196 * v235;
            let v237: f32 = v232 + v236;
            let v238: f32 = -v237;
            let v239: f32 = v8 * v20;
            let v240: f32 = v239 - v34;
            let v241: f32 = v73 * v240;
            let v242: f32 = v25 * v20;
            let v243: f32 = v78 + v242;
            let v244: f32 = v5 * v243;
            let v245: f32 = v241 + v244;
            let v246: f32 = v124 * v245;
            let v247: f32 = v5 * v240;
            let v248: f32 = v73 * v243;
            let v249: f32 = v247 - v248;
            let v250: f32 = v2 * v249;
            let v251: f32 = v246 - v250;
            let v252: f32 = v10 * v52;
            let v253: f32 = v25 * v252;
            let v254: f32 = v5 * v253;
            let v255: f32 = v8 * v252;
            let v256: f32 = v73 * v255;
            let v257: f32 = v254 + v256;
            let v258: f32 = v2 * v257;
            let v259: f32 = v5 * v255;
            let v260: f32 = v73 * v253;
            let v261: f32 = v259 - v260;
            let v262: f32 = v124 * v261;
            let v263: f32 = v258 + v262;
            let v264: f32 = -v263;
            let v265: f32 = v52 * v48;
            let v266: f32 = v265 * v52;
            let v267: f32 = v51 * v27;
            let v268: f32 = v267 * v27;
            let v269: f32 = v266 + v268;
            let v270: f32 = v42 + v269;
            let v271: f32 = v270 + v69;
            let v272: f32 = v6 + v271;
            let v273: f32 = v272 + v120;
            let v274: f32 = 0.07022054_f32;
            let v275: f32 = v273 - v274;
            let v276: f32 = v275 - v108;
            let v277: f32 = v276 - v108;
            let v278: f32 = v3 + v277;
            let v279: f32 = v272 + v117;
            let v280: f32 = v270 - v67;
            let v281: f32 = v109 * v226;
            let v282: f32 = v280 - v281;
            let v283: f32 = v52 * v32;
            let v284: f32 = v10 * v27;
            let v285: f32 = 0.0_f32;
            (
                v163,
                v205,
                v217,
                v238,
                v251,
                v264,
                v270,
                v272,
                v278,
                v279,
                v280,
                v282,
                v283,
                v284,
                v285,
            )
        };
        [
            [v163, v205, v217, v238, v251, v264],
            [v205, v278, v279, v282, v283, v284],
            [v217, v279, v272, v280, v283, v284],
            [v238, v282, v280, v270, v283, v284],
            [v251, v283, v283, v283, v20, v285],
            [v264, v284, v284, v284, v285, v10],
        ]
    }
    /// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 6]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis_matrix: [[f32; 6]; 6]` (6 x 6, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
    ///
    /// Operation count: 1641 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn coriolis_matrix(q: &[f32; 6], qd: &[f32; 6]) -> [[f32; 6]; 6] {
        let (
            v0,
            v1,
            v3,
            v4,
            v5,
            v6,
            v9,
            v11,
            v12,
            v13,
            v15,
            v18,
            v20,
            v22,
            v26,
            v27,
            v28,
            v29,
            v31,
            v32,
            v33,
            v40,
            v45,
            v51,
            v53,
            v55,
            v57,
            v58,
            v59,
            v61,
            v62,
            v64,
            v66,
            v68,
            v69,
            v76,
            v77,
            v80,
            v82,
            v84,
            v90,
            v92,
            v94,
            v97,
            v102,
            v108,
            v109,
            v110,
            v115,
            v116,
            v120,
            v122,
            v125,
            v126,
            v133,
            v136,
            v139,
            v143,
            v146,
            v148,
            v153,
            v158,
            v160,
            v161,
            v163,
            v167,
            v168,
            v169,
            v171,
            v172,
            v185,
            v188,
            v189,
        ) = {
            let v0: f32 = 0.6794727_f32;
            let v1: f32 = 0.0075585125_f32;
            let v2: f32 = q[3];
            let (v3, v55): (f32, f32) = ::libm::sincosf(v2);
            let v4: f32 = v1 * v3;
            let v5: f32 = v0 - v4;
            let v6: f32 = qd[1];
            let v7: f32 = v5 * v6;
            let v8: f32 = q[2];
            let (v9, v90): (f32, f32) = ::libm::sincosf(v8);
            let v10: f32 = v7 * v9;
            let v11: f32 = 0.016685527_f32;
            let v12: f32 = qd[4];
            let v13: f32 = v11 * v12;
            let v14: f32 = q[5];
            let (v32, v15): (f32, f32) = ::libm::sincosf(v14);
            let v16: f32 = v13 * v15;
            let v17: f32 = q[4];
            let (v18, v29): (f32, f32) = ::libm::sincosf(v17);
            let v19: f32 = v16 * v18;
            let v20: f32 = qd[3];
            let v21: f32 = v11 * v20;
            let v22: f32 = qd[2];
            let v23: f32 = v11 * v22;
            let v24: f32 = v21 + v23;
            let v25: f32 = v11 * v6;
            let v26: f32 = v24 + v25;
            let v27: f32 = qd[5];
            let v28: f32 = v11 * v27;
            let v30: f32 = v28 * v29;
            let v31: f32 = v26 + v30;
            let v33: f32 = v31 * v32;
            let v34: f32 = v19 + v33;
            let v35: f32 = v34 * v15;
            let v36: f32 = v13 * v18;
            let v37: f32 = v35 - v36;
            let v38: f32 = v37 * v29;
            let v39: f32 = v10 + v38;
            let v40: f32 = 0.033371054_f32;
            let v41: f32 = v40 * v20;
            let v42: f32 = v40 * v22;
            let v43: f32 = v41 + v42;
            let v44: f32 = v40 * v6;
            let v45: f32 = v43 + v44;
            let v46: f32 = v45 + v30;
            let v47: f32 = v46 * v32;
            let v48: f32 = v19 + v47;
            let v49: f32 = v48 * v15;
            let v50: f32 = v36 - v49;
            let v51: f32 = v50 * v29;
            let v52: f32 = v28 * v15;
            let v53: f32 = v52 * v32;
            let v54: f32 = v51 - v53;
            let v56: f32 = v54 * v55;
            let v57: f32 = 0.0069760624_f32;
            let v58: f32 = v57 * v20;
            let v59: f32 = v57 * v22;
            let v60: f32 = v58 + v59;
            let v61: f32 = v57 * v6;
            let v62: f32 = v60 + v61;
            let v63: f32 = v56 - v62;
            let v64: f32 = v13 * v32;
            let v65: f32 = v64 * v18;
            let v66: f32 = v26 * v15;
            let v67: f32 = v65 - v66;
            let v68: f32 = v67 * v15;
            let v69: f32 = 0.21481116_f32;
            let v70: f32 = v69 * v20;
            let v71: f32 = v69 * v22;
            let v72: f32 = v70 + v71;
            let v73: f32 = v69 * v6;
            let v74: f32 = v72 + v73;
            let v75: f32 = v68 - v74;
            let v76: f32 = v40 * v15;
            let v77: f32 = v76 * v15;
            let v78: f32 = v11 - v77;
            let v79: f32 = v78 * v27;
            let v80: f32 = v66 * v15;
            let v81: f32 = v26 - v80;
            let v82: f32 = v81 * v29;
            let v83: f32 = v79 + v82;
            let v84: f32 = v83 * v29;
            let v85: f32 = v75 + v84;
            let v86: f32 = v85 * v3;
            let v87: f32 = v63 + v86;
            let v88: f32 = v87 * v55;
            let v89: f32 = v39 + v88;
            let v91: f32 = v54 * v90;
            let v92: f32 = 0.3767458_f32;
            let v93: f32 = v92 * v22;
            let v94: f32 = v93 - v70;
            let v95: f32 = v92 * v6;
            let v96: f32 = v94 + v95;
            let v97: f32 = 0.013952125_f32;
            let v98: f32 = v97 * v22;
            let v99: f32 = v58 + v98;
            let v100: f32 = v97 * v6;
            let v101: f32 = v99 + v100;
            let v102: f32 = v101 * v3;
            let v103: f32 = v96 - v102;
            let v104: f32 = v103 + v68;
            let v105: f32 = v104 + v84;
            let v106: f32 = v105 * v9;
            let v107: f32 = v91 + v106;
            let v108: f32 = v1 * v6;
            let v109: f32 = 0.42962232_f32;
            let v110: f32 = v109 * v20;
            let v111: f32 = v109 * v22;
            let v112: f32 = v110 + v111;
            let v113: f32 = v109 * v6;
            let v114: f32 = v112 + v113;
            let v115: f32 = v45 * v15;
            let v116: f32 = v40 * v12;
            let v117: f32 = v116 * v32;
            let v118: f32 = v117 * v18;
            let v119: f32 = v115 - v118;
            let v120: f32 = v119 * v15;
            let v121: f32 = v114 + v120;
            let v122: f32 = v121 * v55;
            let v123: f32 = v40 * v27;
            let v124: f32 = v123 * v15;
            let v125: f32 = v124 * v32;
            let v126: f32 = v125 * v3;
            let v127: f32 = v122 - v126;
            let v128: f32 = v127 * v9;
            let v129: f32 = v108 + v128;
            let v130: f32 = v125 * v55;
            let v131: f32 = v101 + v130;
            let v132: f32 = v121 * v3;
            let v133: f32 = v131 + v132;
            let v134: f32 = v133 * v90;
            let v135: f32 = v129 + v134;
            let v136: f32 = v116 * v18;
            let v137: f32 = v136 * v3;
            let v138: f32 = v123 * v55;
            let v139: f32 = v137 - v138;
            let v140: f32 = v139 * v9;
            let v141: f32 = v136 * v55;
            let v142: f32 = v123 * v3;
            let v143: f32 = v141 + v142;
            let v144: f32 = v143 * v90;
            let v145: f32 = v140 - v144;
            let v146: f32 = v45 * v3;
            let v147: f32 = v146 * v90;
            let v148: f32 = v45 * v55;
            let v149: f32 = v148 * v9;
            let v150: f32 = v147 + v149;
            let v151: f32 = v150 * v29;
            let v152: f32 = v145 - v151;
            let v153: f32 = 0.06674211_f32;
            let v154: f32 = v153 * v20;
            let v155: f32 = v153 * v22;
            let v156: f32 = v154 + v155;
            let v157: f32 = v153 * v6;
            let v158: f32 = v156 + v157;
            let v159: f32 = v123 * v29;
            let v160: f32 = v158 + v159;
            let v161: f32 = v160 * v55;
            let v162: f32 = v161 * v90;
            let v163: f32 = v160 * v3;
            let v164: f32 = v163 * v9;
            let v165: f32 = v162 - v164;
            let v166: f32 = v165 * v32;
            let v167: f32 = v153 * v27;
            let v168: f32 = v167 * v3;
            let v169: f32 = v141 + v168;
            let v170: f32 = v169 * v90;
            let v171: f32 = v167 * v55;
            let v172: f32 = v171 - v137;
            let v173: f32 = v172 * v9;
            let v174: f32 = v170 + v173;
            let v175: f32 = v174 + v151;
            let v176: f32 = v175 * v15;
            let v177: f32 = v166 + v176;
            let v178: f32 = v177 * v15;
            let v179: f32 = v152 + v178;
            let v180: f32 = v179 * v29;
            let v181: f32 = v135 + v180;
            let v182: f32 = v181 * v55;
            let v183: f32 = v107 + v182;
            let v184: f32 = v183 * v90;
            let v185: f32 = v89 + v184;
            let v186: f32 = v1 * v20;
            let v187: f32 = v1 * v22;
            let v188: f32 = v186 + v187;
            let v189: f32 = 0.015117025_f32;
            (
                v0,
                v1,
                v3,
                v4,
                v5,
                v6,
                v9,
                v11,
                v12,
                v13,
                v15,
                v18,
                v20,
                v22,
                v26,
                v27,
                v28,
                v29,
                v31,
                v32,
                v33,
                v40,
                v45,
                v51,
                v53,
                v55,
                v57,
                v58,
                v59,
                v61,
                v62,
                v64,
                v66,
                v68,
                v69,
                v76,
                v77,
                v80,
                v82,
                v84,
                v90,
                v92,
                v94,
                v97,
                v102,
                v108,
                v109,
                v110,
                v115,
                v116,
                v120,
                v122,
                v125,
                v126,
                v133,
                v136,
                v139,
                v143,
                v146,
                v148,
                v153,
                v158,
                v160,
                v161,
                v163,
                v167,
                v168,
                v169,
                v171,
                v172,
                v185,
                v188,
                v189,
            )
        };
        let (
            v193,
            v194,
            v202,
            v204,
            v210,
            v242,
            v252,
            v258,
            v266,
            v267,
            v268,
            v288,
            v298,
            v325,
            v345,
            v346,
            v347,
            v352,
            v353,
            v372,
            v375,
            v376,
            v378,
            v379,
        ) = {
            let v190: f32 = v189 * v6;
            let v191: f32 = v188 + v190;
            let v192: f32 = v191 * v3;
            let v193: f32 = v0 * v22;
            let v194: f32 = 1.3589454_f32;
            let v195: f32 = v194 * v6;
            let v196: f32 = v193 + v195;
            let v197: f32 = v192 - v196;
            let v198: f32 = v197 * v9;
            let v199: f32 = v198 - v53;
            let v200: f32 = v199 + v51;
            let v201: f32 = q[1];
            let (v210, v202): (f32, f32) = ::libm::sincosf(v201);
            let v203: f32 = v200 * v202;
            let v204: f32 = 1.3782737_f32;
            let v205: f32 = v204 * v6;
            let v206: f32 = v94 - v205;
            let v207: f32 = v206 - v102;
            let v208: f32 = v207 + v68;
            let v209: f32 = v208 + v84;
            let v211: f32 = v209 * v210;
            let v212: f32 = v203 + v211;
            let v213: f32 = v133 * v202;
            let v214: f32 = v191 * v9;
            let v215: f32 = v214 - v126;
            let v216: f32 = v215 + v122;
            let v217: f32 = v216 * v210;
            let v218: f32 = v213 + v217;
            let v219: f32 = v139 * v210;
            let v220: f32 = v143 * v202;
            let v221: f32 = v219 - v220;
            let v222: f32 = v146 * v202;
            let v223: f32 = v148 * v210;
            let v224: f32 = v222 + v223;
            let v225: f32 = v224 * v29;
            let v226: f32 = v221 - v225;
            let v227: f32 = v161 * v202;
            let v228: f32 = v163 * v210;
            let v229: f32 = v227 - v228;
            let v230: f32 = v229 * v32;
            let v231: f32 = v169 * v202;
            let v232: f32 = v172 * v210;
            let v233: f32 = v231 + v232;
            let v234: f32 = v233 + v225;
            let v235: f32 = v234 * v15;
            let v236: f32 = v230 + v235;
            let v237: f32 = v236 * v15;
            let v238: f32 = v226 + v237;
            let v239: f32 = v238 * v29;
            let v240: f32 = v218 + v239;
            let v241: f32 = v240 * v55;
            let v242: f32 = v212 + v241;
            let v243: f32 = v116 * v15;
            let v244: f32 = v243 * v18;
            let v245: f32 = v160 * v32;
            let v246: f32 = v244 + v245;
            let v247: f32 = v246 * v15;
            let v248: f32 = v247 - v136;
            let v249: f32 = v248 * v29;
            let v250: f32 = v125 + v249;
            let v251: f32 = v250 * v90;
            let v252: f32 = 0.7534916_f32;
            let v253: f32 = v252 * v22;
            let v254: f32 = v110 - v253;
            let v255: f32 = v252 * v6;
            let v256: f32 = v254 - v255;
            let v257: f32 = v97 * v20;
            let v258: f32 = 0.02790425_f32;
            let v259: f32 = v258 * v22;
            let v260: f32 = v257 + v259;
            let v261: f32 = v258 * v6;
            let v262: f32 = v260 + v261;
            let v263: f32 = v262 * v3;
            let v264: f32 = v256 + v263;
            let v265: f32 = v264 + v120;
            let v266: f32 = -0.033371054_f32;
            let v267: f32 = v153 * v15;
            let v268: f32 = v267 * v15;
            let v269: f32 = v266 + v268;
            let v270: f32 = v269 * v27;
            let v271: f32 = v115 * v15;
            let v272: f32 = v271 - v45;
            let v273: f32 = v272 * v29;
            let v274: f32 = v270 + v273;
            let v275: f32 = v274 * v29;
            let v276: f32 = v265 + v275;
            let v277: f32 = v276 * v9;
            let v278: f32 = v251 + v277;
            let v279: f32 = v278 * v202;
            let v280: f32 = v136 - v247;
            let v281: f32 = v280 * v29;
            let v282: f32 = v281 - v125;
            let v283: f32 = v282 * v9;
            let v284: f32 = v197 + v283;
            let v285: f32 = v276 * v90;
            let v286: f32 = v284 + v285;
            let v287: f32 = v286 * v210;
            let v288: f32 = v279 + v287;
            let v289: f32 = v167 * v15;
            let v290: f32 = v289 * v32;
            let v291: f32 = v290 * v3;
            let v292: f32 = v153 * v12;
            let v293: f32 = v292 * v32;
            let v294: f32 = v293 * v18;
            let v295: f32 = v158 * v15;
            let v296: f32 = v294 - v295;
            let v297: f32 = v296 * v15;
            let v298: f32 = 0.85924464_f32;
            let v299: f32 = v298 * v20;
            let v300: f32 = v298 * v22;
            let v301: f32 = v299 + v300;
            let v302: f32 = v298 * v6;
            let v303: f32 = v301 + v302;
            let v304: f32 = v297 - v303;
            let v305: f32 = v304 * v55;
            let v306: f32 = v291 + v305;
            let v307: f32 = v306 * v90;
            let v308: f32 = v290 * v55;
            let v309: f32 = v262 + v308;
            let v310: f32 = v295 - v294;
            let v311: f32 = v310 * v15;
            let v312: f32 = v303 + v311;
            let v313: f32 = v312 * v3;
            let v314: f32 = v309 + v313;
            let v315: f32 = v314 * v9;
            let v316: f32 = v307 + v315;
            let v317: f32 = v316 * v210;
            let v318: f32 = v306 * v9;
            let v319: f32 = v318 - v191;
            let v320: f32 = v304 * v3;
            let v321: f32 = v320 - v309;
            let v322: f32 = v321 * v90;
            let v323: f32 = v319 + v322;
            let v324: f32 = v323 * v202;
            let v325: f32 = v317 + v324;
            let v326: f32 = v292 * v18;
            let v327: f32 = v326 * v55;
            let v328: f32 = v327 + v168;
            let v329: f32 = v328 * v90;
            let v330: f32 = v326 * v3;
            let v331: f32 = v171 - v330;
            let v332: f32 = v331 * v9;
            let v333: f32 = v329 + v332;
            let v334: f32 = v333 * v202;
            let v335: f32 = v331 * v90;
            let v336: f32 = v328 * v9;
            let v337: f32 = v335 - v336;
            let v338: f32 = v337 * v210;
            let v339: f32 = v334 + v338;
            let v340: f32 = v158 * v3;
            let v341: f32 = v340 * v90;
            let v342: f32 = v158 * v55;
            let v343: f32 = v342 * v9;
            let v344: f32 = v341 + v343;
            let v345: f32 = v344 * v202;
            let v346: f32 = v342 * v90;
            let v347: f32 = v340 * v9;
            let v348: f32 = v346 - v347;
            let v349: f32 = v348 * v210;
            let v350: f32 = v345 + v349;
            let v351: f32 = v350 * v29;
            let v352: f32 = v339 + v351;
            let v353: f32 = 0.13348421_f32;
            let v354: f32 = v353 * v20;
            let v355: f32 = v353 * v22;
            let v356: f32 = v354 + v355;
            let v357: f32 = v353 * v6;
            let v358: f32 = v356 + v357;
            let v359: f32 = v167 * v29;
            let v360: f32 = v358 + v359;
            let v361: f32 = v360 * v3;
            let v362: f32 = v361 * v9;
            let v363: f32 = v360 * v55;
            let v364: f32 = v363 * v90;
            let v365: f32 = v362 - v364;
            let v366: f32 = v365 * v202;
            let v367: f32 = v361 * v90;
            let v368: f32 = v363 * v9;
            let v369: f32 = v367 + v368;
            let v370: f32 = v369 * v210;
            let v371: f32 = v366 + v370;
            let v372: f32 = v371 * v32;
            let v373: f32 = v353 * v27;
            let v374: f32 = v373 * v55;
            let v375: f32 = v330 - v374;
            let v376: f32 = v375 * v9;
            let v377: f32 = v373 * v3;
            let v378: f32 = v327 + v377;
            let v379: f32 = v378 * v90;
            (
                v193,
                v194,
                v202,
                v204,
                v210,
                v242,
                v252,
                v258,
                v266,
                v267,
                v268,
                v288,
                v298,
                v325,
                v345,
                v346,
                v347,
                v352,
                v353,
                v372,
                v375,
                v376,
                v378,
                v379,
            )
        };
        let (
            v403,
            v404,
            v406,
            v407,
            v409,
            v411,
            v412,
            v415,
            v416,
            v417,
            v419,
            v420,
            v423,
            v426,
            v428,
            v430,
            v431,
            v432,
            v435,
            v439,
            v440,
            v442,
            v444,
            v446,
            v448,
            v454,
            v456,
            v458,
            v465,
            v471,
            v472,
            v474,
            v475,
            v486,
            v487,
            v489,
            v491,
            v493,
            v495,
            v497,
            v501,
            v502,
            v514,
            v516,
            v517,
            v525,
            v532,
            v533,
            v536,
            v544,
            v547,
            v551,
            v553,
            v560,
            v565,
            v566,
            v567,
            v569,
        ) = {
            let v380: f32 = v376 - v379;
            let v381: f32 = v380 * v202;
            let v382: f32 = v375 * v90;
            let v383: f32 = v378 * v9;
            let v384: f32 = v382 + v383;
            let v385: f32 = v384 * v210;
            let v386: f32 = v381 + v385;
            let v387: f32 = v347 - v346;
            let v388: f32 = v387 * v210;
            let v389: f32 = v388 - v345;
            let v390: f32 = v389 * v29;
            let v391: f32 = v386 + v390;
            let v392: f32 = v391 * v15;
            let v393: f32 = v372 + v392;
            let v394: f32 = v393 * v15;
            let v395: f32 = v352 + v394;
            let v396: f32 = v395 * v29;
            let v397: f32 = v325 + v396;
            let v398: f32 = v397 * v55;
            let v399: f32 = v288 + v398;
            let v400: f32 = v399 * v90;
            let v401: f32 = v242 + v400;
            let v402: f32 = v401 * v202;
            let v403: f32 = v185 + v402;
            let v404: f32 = v11 * v15;
            let v405: f32 = v404 * v32;
            let v406: f32 = v405 * v29;
            let v407: f32 = v5 * v9;
            let v408: f32 = v406 + v407;
            let v409: f32 = -0.0069760624_f32;
            let v410: f32 = v76 * v32;
            let v411: f32 = v410 * v29;
            let v412: f32 = v411 * v55;
            let v413: f32 = v409 - v412;
            let v414: f32 = -0.21481116_f32;
            let v415: f32 = v404 * v15;
            let v416: f32 = v414 - v415;
            let v417: f32 = v11 - v415;
            let v418: f32 = v417 * v29;
            let v419: f32 = v418 * v29;
            let v420: f32 = v416 + v419;
            let v421: f32 = v420 * v3;
            let v422: f32 = v413 + v421;
            let v423: f32 = v422 * v55;
            let v424: f32 = v408 + v423;
            let v425: f32 = v92 - v415;
            let v426: f32 = v97 * v3;
            let v427: f32 = v425 - v426;
            let v428: f32 = v427 + v419;
            let v429: f32 = v428 * v9;
            let v430: f32 = v411 * v90;
            let v431: f32 = v429 - v430;
            let v432: f32 = v109 + v77;
            let v433: f32 = v266 + v77;
            let v434: f32 = v433 * v29;
            let v435: f32 = v434 * v29;
            let v436: f32 = v432 + v435;
            let v437: f32 = v436 * v55;
            let v438: f32 = v267 * v32;
            let v439: f32 = v438 * v29;
            let v440: f32 = v439 * v3;
            let v441: f32 = v437 - v440;
            let v442: f32 = v441 * v9;
            let v443: f32 = v1 + v442;
            let v444: f32 = v439 * v55;
            let v445: f32 = v97 + v444;
            let v446: f32 = v436 * v3;
            let v447: f32 = v445 + v446;
            let v448: f32 = v447 * v90;
            let v449: f32 = v443 + v448;
            let v450: f32 = v449 * v55;
            let v451: f32 = v431 + v450;
            let v452: f32 = v451 * v90;
            let v453: f32 = v424 + v452;
            let v454: f32 = qd[0];
            let v455: f32 = v453 * v454;
            let v456: f32 = 0.10993547_f32;
            let v457: f32 = v456 + v415;
            let v458: f32 = v457 + v419;
            let v459: f32 = v458 * v12;
            let v460: f32 = 0.0019412038_f32;
            let v461: f32 = v460 * v20;
            let v462: f32 = v460 * v22;
            let v463: f32 = v461 + v462;
            let v464: f32 = v460 * v6;
            let v465: f32 = v463 + v464;
            let v466: f32 = v459 - v465;
            let v467: f32 = v466 * v55;
            let v468: f32 = v467 * v90;
            let v469: f32 = -0.10993547_f32;
            let v470: f32 = v469 - v415;
            let v471: f32 = -0.016685527_f32;
            let v472: f32 = v471 + v415;
            let v473: f32 = v472 * v29;
            let v474: f32 = v473 * v29;
            let v475: f32 = v470 + v474;
            let v476: f32 = v475 * v12;
            let v477: f32 = v465 + v476;
            let v478: f32 = v477 * v3;
            let v479: f32 = 0.07714262_f32;
            let v480: f32 = v479 * v22;
            let v481: f32 = v479 * v6;
            let v482: f32 = v480 + v481;
            let v483: f32 = v478 - v482;
            let v484: f32 = v483 * v9;
            let v485: f32 = v468 + v484;
            let v486: f32 = 0.00022547315_f32;
            let v487: f32 = v486 * v3;
            let v488: f32 = v487 * v90;
            let v489: f32 = v486 * v55;
            let v490: f32 = v489 * v9;
            let v491: f32 = v488 + v490;
            let v492: f32 = v491 * v27;
            let v493: f32 = v26 * v3;
            let v494: f32 = v493 * v90;
            let v495: f32 = v26 * v55;
            let v496: f32 = v495 * v9;
            let v497: f32 = v494 + v496;
            let v498: f32 = v497 * v29;
            let v499: f32 = v492 - v498;
            let v500: f32 = v33 * v55;
            let v501: f32 = v26 * v29;
            let v502: f32 = v28 + v501;
            let v503: f32 = v502 * v15;
            let v504: f32 = v503 * v3;
            let v505: f32 = v500 + v504;
            let v506: f32 = v505 * v90;
            let v507: f32 = v503 * v55;
            let v508: f32 = v33 * v3;
            let v509: f32 = v507 - v508;
            let v510: f32 = v509 * v9;
            let v511: f32 = v506 + v510;
            let v512: f32 = v511 * v15;
            let v513: f32 = v499 + v512;
            let v514: f32 = v513 * v18;
            let v515: f32 = v485 + v514;
            let v516: f32 = v515 * v210;
            let v517: f32 = v455 + v516;
            let v518: f32 = 0.4084992_f32;
            let v519: f32 = v518 * v6;
            let v520: f32 = -1.3782737_f32;
            let v521: f32 = v520 - v415;
            let v522: f32 = v521 - v426;
            let v523: f32 = v522 + v419;
            let v524: f32 = v523 * v210;
            let v525: f32 = v411 * v202;
            let v526: f32 = v524 - v525;
            let v527: f32 = v526 * v454;
            let v528: f32 = v519 + v527;
            let v529: f32 = v189 * v454;
            let v530: f32 = v529 * v202;
            let v531: f32 = v486 + v415;
            let v532: f32 = v531 * v27;
            let v533: f32 = v80 - v26;
            let v534: f32 = v533 * v29;
            let v535: f32 = v532 + v534;
            let v536: f32 = v535 * v18;
            let v537: f32 = v530 + v536;
            let v538: f32 = v537 * v3;
            let v539: f32 = v194 * v454;
            let v540: f32 = v539 * v202;
            let v541: f32 = v538 - v540;
            let v542: f32 = v541 * v9;
            let v543: f32 = v528 + v542;
            let v544: f32 = v441 * v210;
            let v545: f32 = v447 * v202;
            let v546: f32 = v544 + v545;
            let v547: f32 = v546 * v454;
            let v548: f32 = v529 * v210;
            let v549: f32 = v548 - v465;
            let v550: f32 = v11 * v29;
            let v551: f32 = v550 * v29;
            let v552: f32 = v456 + v551;
            let v553: f32 = v552 * v12;
            let v554: f32 = v549 + v553;
            let v555: f32 = v11 - v551;
            let v556: f32 = v555 * v12;
            let v557: f32 = v556 * v15;
            let v558: f32 = v33 * v18;
            let v559: f32 = v557 + v558;
            let v560: f32 = v559 * v15;
            let v561: f32 = v554 + v560;
            let v562: f32 = v561 * v9;
            let v563: f32 = v547 + v562;
            let v564: f32 = v563 * v55;
            let v565: f32 = v543 + v564;
            let v566: f32 = v466 * v3;
            let v567: f32 = v482 + v566;
            let v568: f32 = v31 * v15;
            let v569: f32 = v568 * v32;
            (
                v403,
                v404,
                v406,
                v407,
                v409,
                v411,
                v412,
                v415,
                v416,
                v417,
                v419,
                v420,
                v423,
                v426,
                v428,
                v430,
                v431,
                v432,
                v435,
                v439,
                v440,
                v442,
                v444,
                v446,
                v448,
                v454,
                v456,
                v458,
                v465,
                v471,
                v472,
                v474,
                v475,
                v486,
                v487,
                v489,
                v491,
                v493,
                v495,
                v497,
                v501,
                v502,
                v514,
                v516,
                v517,
                v525,
                v532,
                v533,
                v536,
                v544,
                v547,
                v551,
                v553,
                v560,
                v565,
                v566,
                v567,
                v569,
            )
        };
        let (
            v579,
            v582,
            v589,
            v591,
            v597,
            v600,
            v617,
            v619,
            v629,
            v641,
            v671,
            v676,
            v688,
            v689,
            v717,
            v732,
            v745,
            v749,
            v751,
            v759,
        ) = {
            let v570: f32 = v569 * v3;
            let v571: f32 = -0.00022547315_f32;
            let v572: f32 = v571 - v415;
            let v573: f32 = v572 * v27;
            let v574: f32 = v573 + v82;
            let v575: f32 = v574 * v55;
            let v576: f32 = v570 + v575;
            let v577: f32 = v576 * v18;
            let v578: f32 = v567 + v577;
            let v579: f32 = v439 * v90;
            let v580: f32 = -0.7534916_f32;
            let v581: f32 = v580 + v77;
            let v582: f32 = v258 * v3;
            let v583: f32 = v581 + v582;
            let v584: f32 = v583 + v435;
            let v585: f32 = v584 * v9;
            let v586: f32 = v579 + v585;
            let v587: f32 = v586 * v202;
            let v588: f32 = -1.3589454_f32;
            let v589: f32 = v189 * v3;
            let v590: f32 = v588 + v589;
            let v591: f32 = v439 * v9;
            let v592: f32 = v590 - v591;
            let v593: f32 = v584 * v90;
            let v594: f32 = v592 + v593;
            let v595: f32 = v594 * v210;
            let v596: f32 = v587 + v595;
            let v597: f32 = v353 * v15;
            let v598: f32 = v597 * v32;
            let v599: f32 = v598 * v29;
            let v600: f32 = v599 * v3;
            let v601: f32 = -0.85924464_f32;
            let v602: f32 = v601 - v268;
            let v603: f32 = v153 - v268;
            let v604: f32 = v603 * v29;
            let v605: f32 = v604 * v29;
            let v606: f32 = v602 + v605;
            let v607: f32 = v606 * v55;
            let v608: f32 = v600 + v607;
            let v609: f32 = v608 * v90;
            let v610: f32 = v599 * v55;
            let v611: f32 = v258 + v610;
            let v612: f32 = v298 + v268;
            let v613: f32 = -0.06674211_f32;
            let v614: f32 = v613 + v268;
            let v615: f32 = v614 * v29;
            let v616: f32 = v615 * v29;
            let v617: f32 = v612 + v616;
            let v618: f32 = v617 * v3;
            let v619: f32 = v611 + v618;
            let v620: f32 = v619 * v9;
            let v621: f32 = v609 + v620;
            let v622: f32 = v621 * v210;
            let v623: f32 = -0.015117025_f32;
            let v624: f32 = v608 * v9;
            let v625: f32 = v623 + v624;
            let v626: f32 = -0.02790425_f32;
            let v627: f32 = v626 - v610;
            let v628: f32 = v606 * v3;
            let v629: f32 = v627 + v628;
            let v630: f32 = v629 * v90;
            let v631: f32 = v625 + v630;
            let v632: f32 = v631 * v202;
            let v633: f32 = v622 + v632;
            let v634: f32 = v633 * v55;
            let v635: f32 = v596 + v634;
            let v636: f32 = v635 * v454;
            let v637: f32 = v578 + v636;
            let v638: f32 = v637 * v90;
            let v639: f32 = v565 + v638;
            let v640: f32 = v639 * v202;
            let v641: f32 = v517 + v640;
            let v642: f32 = v406 + v423;
            let v643: f32 = v442 + v448;
            let v644: f32 = v643 * v55;
            let v645: f32 = v431 + v644;
            let v646: f32 = v645 * v90;
            let v647: f32 = v642 + v646;
            let v648: f32 = v647 * v454;
            let v649: f32 = v648 + v516;
            let v650: f32 = v428 * v210;
            let v651: f32 = v650 - v525;
            let v652: f32 = v651 * v454;
            let v653: f32 = v1 * v454;
            let v654: f32 = v653 * v202;
            let v655: f32 = v654 + v536;
            let v656: f32 = v655 * v3;
            let v657: f32 = v0 * v454;
            let v658: f32 = v657 * v202;
            let v659: f32 = v656 - v658;
            let v660: f32 = v659 * v9;
            let v661: f32 = v652 + v660;
            let v662: f32 = v653 * v210;
            let v663: f32 = v662 - v465;
            let v664: f32 = v663 + v553;
            let v665: f32 = v664 + v560;
            let v666: f32 = v665 * v9;
            let v667: f32 = v547 + v666;
            let v668: f32 = v667 * v55;
            let v669: f32 = v661 + v668;
            let v670: f32 = -0.6794727_f32;
            let v671: f32 = v670 + v4;
            let v672: f32 = v671 - v591;
            let v673: f32 = v672 + v593;
            let v674: f32 = v673 * v210;
            let v675: f32 = v587 + v674;
            let v676: f32 = -0.0075585125_f32;
            let v677: f32 = v676 + v624;
            let v678: f32 = v677 + v630;
            let v679: f32 = v678 * v202;
            let v680: f32 = v622 + v679;
            let v681: f32 = v680 * v55;
            let v682: f32 = v675 + v681;
            let v683: f32 = v682 * v454;
            let v684: f32 = v578 + v683;
            let v685: f32 = v684 * v90;
            let v686: f32 = v669 + v685;
            let v687: f32 = v686 * v202;
            let v688: f32 = v649 + v687;
            let v689: f32 = v57 * v3;
            let v690: f32 = v416 - v689;
            let v691: f32 = v690 + v419;
            let v692: f32 = v691 * v9;
            let v693: f32 = v692 - v430;
            let v694: f32 = v57 + v444;
            let v695: f32 = v694 + v446;
            let v696: f32 = v695 * v90;
            let v697: f32 = v442 + v696;
            let v698: f32 = v697 * v55;
            let v699: f32 = v693 + v698;
            let v700: f32 = v699 * v90;
            let v701: f32 = v642 + v700;
            let v702: f32 = v701 * v454;
            let v703: f32 = v465 * v3;
            let v704: f32 = v703 * v9;
            let v705: f32 = v465 * v55;
            let v706: f32 = v705 * v90;
            let v707: f32 = v704 - v706;
            let v708: f32 = v458 * v55;
            let v709: f32 = v708 * v90;
            let v710: f32 = v475 * v3;
            let v711: f32 = v710 * v9;
            let v712: f32 = v709 + v711;
            let v713: f32 = v712 * v12;
            let v714: f32 = v707 + v713;
            let v715: f32 = v714 + v514;
            let v716: f32 = v715 * v210;
            let v717: f32 = v702 + v716;
            let v718: f32 = v420 * v210;
            let v719: f32 = v718 - v525;
            let v720: f32 = v719 * v454;
            let v721: f32 = v655 * v9;
            let v722: f32 = v57 * v454;
            let v723: f32 = v722 * v210;
            let v724: f32 = v721 - v723;
            let v725: f32 = v724 * v3;
            let v726: f32 = v720 + v725;
            let v727: f32 = v695 * v202;
            let v728: f32 = v544 + v727;
            let v729: f32 = v728 * v454;
            let v730: f32 = v729 + v666;
            let v731: f32 = v730 * v55;
            let v732: f32 = v726 + v731;
            let v733: f32 = v566 + v577;
            let v734: f32 = v432 + v426;
            let v735: f32 = v734 + v435;
            let v736: f32 = v735 * v9;
            let v737: f32 = v579 + v736;
            let v738: f32 = v737 * v202;
            let v739: f32 = v4 - v591;
            let v740: f32 = v735 * v90;
            let v741: f32 = v739 + v740;
            let v742: f32 = v741 * v210;
            let v743: f32 = v738 + v742;
            let v744: f32 = v97 + v610;
            let v745: f32 = v744 + v618;
            let v746: f32 = v745 * v9;
            let v747: f32 = v609 + v746;
            let v748: f32 = v747 * v210;
            let v749: f32 = -0.013952125_f32;
            let v750: f32 = v749 - v610;
            let v751: f32 = v750 + v628;
            let v752: f32 = v751 * v90;
            let v753: f32 = v677 + v752;
            let v754: f32 = v753 * v202;
            let v755: f32 = v748 + v754;
            let v756: f32 = v755 * v55;
            let v757: f32 = v743 + v756;
            let v758: f32 = v757 * v454;
            let v759: f32 = v733 + v758;
            (
                v579,
                v582,
                v589,
                v591,
                v597,
                v600,
                v617,
                v619,
                v629,
                v641,
                v671,
                v676,
                v688,
                v689,
                v717,
                v732,
                v745,
                v749,
                v751,
                v759,
            )
        };
        let (
            v763,
            v783,
            v793,
            v794,
            v795,
            v796,
            v797,
            v798,
            v799,
            v803,
            v804,
            v810,
            v811,
            v814,
            v816,
            v833,
            v841,
            v855,
            v860,
            v861,
            v863,
            v865,
            v866,
            v867,
            v868,
            v870,
            v875,
            v880,
            v881,
            v882,
            v883,
            v884,
            v888,
            v890,
            v892,
            v895,
            v907,
            v913,
            v914,
            v916,
            v920,
            v922,
            v934,
            v948,
            v949,
        ) = {
            let v760: f32 = v759 * v90;
            let v761: f32 = v732 + v760;
            let v762: f32 = v761 * v202;
            let v763: f32 = v717 + v762;
            let v764: f32 = v456 * v20;
            let v765: f32 = v456 * v22;
            let v766: f32 = v764 + v765;
            let v767: f32 = v456 * v6;
            let v768: f32 = v766 + v767;
            let v769: f32 = v768 * v3;
            let v770: f32 = v769 * v90;
            let v771: f32 = v768 * v55;
            let v772: f32 = v771 * v9;
            let v773: f32 = v770 + v772;
            let v774: f32 = v773 * v202;
            let v775: f32 = v771 * v90;
            let v776: f32 = v769 * v9;
            let v777: f32 = v775 - v776;
            let v778: f32 = v777 * v210;
            let v779: f32 = v774 + v778;
            let v780: f32 = v11 * v55;
            let v781: f32 = v780 * v55;
            let v782: f32 = v471 + v781;
            let v783: f32 = v40 * v55;
            let v784: f32 = v783 * v3;
            let v785: f32 = v784 * v9;
            let v786: f32 = v783 * v55;
            let v787: f32 = v11 - v786;
            let v788: f32 = v787 * v90;
            let v789: f32 = v785 + v788;
            let v790: f32 = v789 * v90;
            let v791: f32 = v782 + v790;
            let v792: f32 = v791 * v454;
            let v793: f32 = v792 * v18;
            let v794: f32 = 0.016911_f32;
            let v795: f32 = v794 * v3;
            let v796: f32 = v795 * v9;
            let v797: f32 = v794 * v55;
            let v798: f32 = v797 * v90;
            let v799: f32 = v796 - v798;
            let v800: f32 = v799 * v27;
            let v801: f32 = v495 * v90;
            let v802: f32 = v493 * v9;
            let v803: f32 = v801 - v802;
            let v804: f32 = v803 * v29;
            let v805: f32 = v800 + v804;
            let v806: f32 = v805 * v210;
            let v807: f32 = v793 + v806;
            let v808: f32 = v11 * v454;
            let v809: f32 = v808 * v18;
            let v810: f32 = v809 * v202;
            let v811: f32 = v40 * v3;
            let v812: f32 = v811 * v210;
            let v813: f32 = v783 * v202;
            let v814: f32 = v812 - v813;
            let v815: f32 = v814 * v454;
            let v816: f32 = v815 * v18;
            let v817: f32 = v794 * v27;
            let v818: f32 = v501 - v817;
            let v819: f32 = v818 * v9;
            let v820: f32 = v816 + v819;
            let v821: f32 = v820 * v55;
            let v822: f32 = v810 + v821;
            let v823: f32 = v153 * v55;
            let v824: f32 = v823 * v55;
            let v825: f32 = v266 + v824;
            let v826: f32 = v825 * v90;
            let v827: f32 = v826 * v202;
            let v828: f32 = v40 - v824;
            let v829: f32 = v828 * v9;
            let v830: f32 = v829 * v210;
            let v831: f32 = v827 + v830;
            let v832: f32 = v831 * v454;
            let v833: f32 = v832 * v18;
            let v834: f32 = v153 * v9;
            let v835: f32 = v834 * v202;
            let v836: f32 = v153 * v90;
            let v837: f32 = v836 * v210;
            let v838: f32 = v835 + v837;
            let v839: f32 = v838 * v454;
            let v840: f32 = v839 * v18;
            let v841: f32 = v840 * v55;
            let v842: f32 = v817 + v841;
            let v843: f32 = v501 - v842;
            let v844: f32 = v843 * v3;
            let v845: f32 = v833 + v844;
            let v846: f32 = v845 * v90;
            let v847: f32 = v822 + v846;
            let v848: f32 = v847 * v202;
            let v849: f32 = v807 + v848;
            let v850: f32 = v849 * v29;
            let v851: f32 = v779 + v850;
            let v852: f32 = v780 * v90;
            let v853: f32 = v11 * v3;
            let v854: f32 = v853 * v9;
            let v855: f32 = v852 - v854;
            let v856: f32 = v855 * v202;
            let v857: f32 = v853 * v90;
            let v858: f32 = v780 * v9;
            let v859: f32 = v857 + v858;
            let v860: f32 = v859 * v210;
            let v861: f32 = v856 - v860;
            let v862: f32 = v861 * v27;
            let v863: f32 = v854 - v852;
            let v864: f32 = v863 * v210;
            let v865: f32 = v859 * v202;
            let v866: f32 = v864 - v865;
            let v867: f32 = v866 * v12;
            let v868: f32 = v780 * v3;
            let v869: f32 = v787 * v9;
            let v870: f32 = v784 * v90;
            let v871: f32 = v869 - v870;
            let v872: f32 = v871 * v90;
            let v873: f32 = v868 + v872;
            let v874: f32 = v787 * v210;
            let v875: f32 = v784 * v202;
            let v876: f32 = v874 - v875;
            let v877: f32 = v153 * v3;
            let v878: f32 = v877 * v90;
            let v879: f32 = v823 * v9;
            let v880: f32 = v878 + v879;
            let v881: f32 = v880 * v202;
            let v882: f32 = v823 * v90;
            let v883: f32 = v877 * v9;
            let v884: f32 = v882 - v883;
            let v885: f32 = v884 * v210;
            let v886: f32 = v881 + v885;
            let v887: f32 = v886 * v55;
            let v888: f32 = v40 * v9;
            let v889: f32 = v888 * v202;
            let v890: f32 = v40 * v90;
            let v891: f32 = v890 * v210;
            let v892: f32 = v889 + v891;
            let v893: f32 = v887 - v892;
            let v894: f32 = v893 * v90;
            let v895: f32 = v876 + v894;
            let v896: f32 = v895 * v202;
            let v897: f32 = v873 + v896;
            let v898: f32 = v897 * v454;
            let v899: f32 = v867 + v898;
            let v900: f32 = v899 * v18;
            let v901: f32 = v862 + v900;
            let v902: f32 = v901 * v32;
            let v903: f32 = v497 * v202;
            let v904: f32 = v803 * v210;
            let v905: f32 = v903 + v904;
            let v906: f32 = v11 - v781;
            let v907: f32 = v471 + v786;
            let v908: f32 = v907 * v90;
            let v909: f32 = v908 - v785;
            let v910: f32 = v909 * v90;
            let v911: f32 = v906 + v910;
            let v912: f32 = v911 * v454;
            let v913: f32 = v912 * v18;
            let v914: f32 = v855 * v27;
            let v915: f32 = v802 - v801;
            let v916: f32 = v915 * v29;
            let v917: f32 = v914 + v916;
            let v918: f32 = v917 * v210;
            let v919: f32 = v913 + v918;
            let v920: f32 = v813 - v812;
            let v921: f32 = v920 * v454;
            let v922: f32 = v921 * v18;
            let v923: f32 = v28 - v501;
            let v924: f32 = v923 * v9;
            let v925: f32 = v922 + v924;
            let v926: f32 = v925 * v55;
            let v927: f32 = v926 - v810;
            let v928: f32 = v828 * v90;
            let v929: f32 = v928 * v202;
            let v930: f32 = v825 * v9;
            let v931: f32 = v930 * v210;
            let v932: f32 = v929 + v931;
            let v933: f32 = v932 * v454;
            let v934: f32 = v933 * v18;
            let v935: f32 = v28 + v841;
            let v936: f32 = v935 - v501;
            let v937: f32 = v936 * v3;
            let v938: f32 = v934 + v937;
            let v939: f32 = v938 * v90;
            let v940: f32 = v927 + v939;
            let v941: f32 = v940 * v202;
            let v942: f32 = v919 + v941;
            let v943: f32 = v942 * v29;
            let v944: f32 = v905 + v943;
            let v945: f32 = v944 * v15;
            let v946: f32 = v902 + v945;
            let v947: f32 = v946 * v15;
            let v948: f32 = v851 + v947;
            let v949: f32 = v873 * v454;
            (
                v763,
                v783,
                v793,
                v794,
                v795,
                v796,
                v797,
                v798,
                v799,
                v803,
                v804,
                v810,
                v811,
                v814,
                v816,
                v833,
                v841,
                v855,
                v860,
                v861,
                v863,
                v865,
                v866,
                v867,
                v868,
                v870,
                v875,
                v880,
                v881,
                v882,
                v883,
                v884,
                v888,
                v890,
                v892,
                v895,
                v907,
                v913,
                v914,
                v916,
                v920,
                v922,
                v934,
                v948,
                v949,
            )
        };
        let (
            v957,
            v974,
            v983,
            v988,
            v997,
            v1002,
            v1003,
            v1009,
            v1012,
            v1013,
            v1017,
            v1018,
            v1025,
            v1027,
            v1028,
            v1038,
            v1039,
            v1040,
            v1041,
            v1043,
            v1045,
            v1050,
            v1055,
            v1063,
            v1064,
            v1065,
            v1073,
            v1074,
            v1080,
            v1081,
            v1082,
            v1088,
            v1090,
            v1095,
            v1096,
            v1102,
            v1106,
            v1121,
            v1122,
            v1124,
            v1126,
            v1132,
            v1133,
            v1134,
            v1137,
            v1139,
        ) = {
            let v950: f32 = v949 * v29;
            let v951: f32 = v799 * v12;
            let v952: f32 = v951 * v29;
            let v953: f32 = v486 * v20;
            let v954: f32 = v486 * v22;
            let v955: f32 = v953 + v954;
            let v956: f32 = v486 * v6;
            let v957: f32 = v955 + v956;
            let v958: f32 = v957 * v3;
            let v959: f32 = v958 * v90;
            let v960: f32 = v957 * v55;
            let v961: f32 = v960 * v9;
            let v962: f32 = v959 + v961;
            let v963: f32 = v962 * v18;
            let v964: f32 = v952 + v963;
            let v965: f32 = v964 * v210;
            let v966: f32 = v950 + v965;
            let v967: f32 = v958 * v9;
            let v968: f32 = v960 * v90;
            let v969: f32 = v967 - v968;
            let v970: f32 = v969 * v18;
            let v971: f32 = v895 * v454;
            let v972: f32 = v795 * v90;
            let v973: f32 = v797 * v9;
            let v974: f32 = v972 + v973;
            let v975: f32 = v974 * v12;
            let v976: f32 = v971 - v975;
            let v977: f32 = v976 * v29;
            let v978: f32 = v970 + v977;
            let v979: f32 = v978 * v202;
            let v980: f32 = v966 + v979;
            let v981: f32 = v11 * v32;
            let v982: f32 = v981 * v29;
            let v983: f32 = v982 * v29;
            let v984: f32 = v471 - v551;
            let v985: f32 = v984 * v32;
            let v986: f32 = v985 * v55;
            let v987: f32 = v76 * v29;
            let v988: f32 = v987 * v3;
            let v989: f32 = v986 - v988;
            let v990: f32 = v989 * v55;
            let v991: f32 = v983 + v990;
            let v992: f32 = v991 * v454;
            let v993: f32 = v66 * v55;
            let v994: f32 = v26 * v32;
            let v995: f32 = v994 * v29;
            let v996: f32 = v995 * v3;
            let v997: f32 = v993 - v996;
            let v998: f32 = v997 * v18;
            let v999: f32 = v981 * v55;
            let v1000: f32 = v404 * v29;
            let v1001: f32 = v1000 * v3;
            let v1002: f32 = v999 + v1001;
            let v1003: f32 = v1002 * v12;
            let v1004: f32 = v998 - v1003;
            let v1005: f32 = v1004 * v9;
            let v1006: f32 = v1005 * v210;
            let v1007: f32 = v992 + v1006;
            let v1008: f32 = v985 * v90;
            let v1009: f32 = v987 * v9;
            let v1010: f32 = v1008 - v1009;
            let v1011: f32 = v1010 * v454;
            let v1012: f32 = v66 * v18;
            let v1013: f32 = v1012 - v64;
            let v1014: f32 = v1013 * v3;
            let v1015: f32 = v1014 * v210;
            let v1016: f32 = v1011 + v1015;
            let v1017: f32 = v783 * v90;
            let v1018: f32 = v811 * v9;
            let v1019: f32 = v1017 - v1018;
            let v1020: f32 = v1019 * v454;
            let v1021: f32 = v1020 * v32;
            let v1022: f32 = v13 * v210;
            let v1023: f32 = v880 * v454;
            let v1024: f32 = v1022 + v1023;
            let v1025: f32 = v1024 * v15;
            let v1026: f32 = v1020 * v29;
            let v1027: f32 = v26 * v18;
            let v1028: f32 = v1027 * v210;
            let v1029: f32 = v1026 + v1028;
            let v1030: f32 = v1029 * v32;
            let v1031: f32 = v1025 + v1030;
            let v1032: f32 = v1031 * v29;
            let v1033: f32 = v1021 + v1032;
            let v1034: f32 = v1033 * v55;
            let v1035: f32 = v1016 + v1034;
            let v1036: f32 = v1035 * v90;
            let v1037: f32 = v1007 + v1036;
            let v1038: f32 = v1002 * v90;
            let v1039: f32 = v1000 * v55;
            let v1040: f32 = v981 * v3;
            let v1041: f32 = v1039 - v1040;
            let v1042: f32 = v1041 * v9;
            let v1043: f32 = v1038 + v1042;
            let v1044: f32 = v1043 * v12;
            let v1045: f32 = v996 - v993;
            let v1046: f32 = v1045 * v90;
            let v1047: f32 = v995 * v55;
            let v1048: f32 = v66 * v3;
            let v1049: f32 = v1047 + v1048;
            let v1050: f32 = v1049 * v9;
            let v1051: f32 = v1046 + v1050;
            let v1052: f32 = v1051 * v18;
            let v1053: f32 = v1044 + v1052;
            let v1054: f32 = v985 * v202;
            let v1055: f32 = v987 * v210;
            let v1056: f32 = v1054 - v1055;
            let v1057: f32 = v920 * v32;
            let v1058: f32 = v40 * v32;
            let v1059: f32 = v1058 * v29;
            let v1060: f32 = v1059 * v55;
            let v1061: f32 = v267 * v3;
            let v1062: f32 = v1060 + v1061;
            let v1063: f32 = v1062 * v202;
            let v1064: f32 = v267 * v55;
            let v1065: f32 = v1059 * v3;
            let v1066: f32 = v1064 - v1065;
            let v1067: f32 = v1066 * v210;
            let v1068: f32 = v1063 + v1067;
            let v1069: f32 = v1068 * v29;
            let v1070: f32 = v1057 + v1069;
            let v1071: f32 = v1070 * v55;
            let v1072: f32 = v1056 + v1071;
            let v1073: f32 = v890 * v202;
            let v1074: f32 = v888 * v210;
            let v1075: f32 = v1073 - v1074;
            let v1076: f32 = v1075 * v32;
            let v1077: f32 = v1059 * v90;
            let v1078: f32 = v267 * v9;
            let v1079: f32 = v1077 + v1078;
            let v1080: f32 = v1079 * v202;
            let v1081: f32 = v267 * v90;
            let v1082: f32 = v1059 * v9;
            let v1083: f32 = v1081 - v1082;
            let v1084: f32 = v1083 * v210;
            let v1085: f32 = v1080 + v1084;
            let v1086: f32 = v1085 * v29;
            let v1087: f32 = v1076 + v1086;
            let v1088: f32 = v883 - v882;
            let v1089: f32 = v1088 * v202;
            let v1090: f32 = v880 * v210;
            let v1091: f32 = v1089 + v1090;
            let v1092: f32 = v1091 * v32;
            let v1093: f32 = v153 * v32;
            let v1094: f32 = v1093 * v29;
            let v1095: f32 = v1094 * v3;
            let v1096: f32 = v597 * v55;
            let v1097: f32 = v1095 - v1096;
            let v1098: f32 = v1097 * v9;
            let v1099: f32 = v1094 * v55;
            let v1100: f32 = v597 * v3;
            let v1101: f32 = v1099 + v1100;
            let v1102: f32 = v1101 * v90;
            let v1103: f32 = v1098 - v1102;
            let v1104: f32 = v1103 * v202;
            let v1105: f32 = v1097 * v90;
            let v1106: f32 = v1101 * v9;
            let v1107: f32 = v1105 + v1106;
            let v1108: f32 = v1107 * v210;
            let v1109: f32 = v1104 + v1108;
            let v1110: f32 = v1109 * v29;
            let v1111: f32 = v1092 + v1110;
            let v1112: f32 = v1111 * v55;
            let v1113: f32 = v1087 + v1112;
            let v1114: f32 = v1113 * v90;
            let v1115: f32 = v1072 + v1114;
            let v1116: f32 = v1115 * v454;
            let v1117: f32 = v1053 + v1116;
            let v1118: f32 = v1117 * v202;
            let v1119: f32 = v1037 + v1118;
            let v1120: f32 = v1119 * v15;
            let v1121: f32 = v980 + v1120;
            let v1122: f32 = 0.126621_f32;
            let v1123: f32 = v1122 * v3;
            let v1124: f32 = v1123 * v9;
            let v1125: f32 = v1122 * v55;
            let v1126: f32 = v1125 * v90;
            let v1127: f32 = v1124 - v1126;
            let v1128: f32 = v1127 * v210;
            let v1129: f32 = v1123 * v90;
            let v1130: f32 = v1125 * v9;
            let v1131: f32 = v1129 + v1130;
            let v1132: f32 = v1131 * v202;
            let v1133: f32 = v1128 - v1132;
            let v1134: f32 = v1133 * v12;
            let v1135: f32 = v794 - v415;
            let v1136: f32 = v1135 * v55;
            let v1137: f32 = v1136 * v90;
            let v1138: f32 = -0.016911_f32;
            let v1139: f32 = v1138 + v415;
            (
                v957,
                v974,
                v983,
                v988,
                v997,
                v1002,
                v1003,
                v1009,
                v1012,
                v1013,
                v1017,
                v1018,
                v1025,
                v1027,
                v1028,
                v1038,
                v1039,
                v1040,
                v1041,
                v1043,
                v1045,
                v1050,
                v1055,
                v1063,
                v1064,
                v1065,
                v1073,
                v1074,
                v1080,
                v1081,
                v1082,
                v1088,
                v1090,
                v1095,
                v1096,
                v1102,
                v1106,
                v1121,
                v1122,
                v1124,
                v1126,
                v1132,
                v1133,
                v1134,
                v1137,
                v1139,
            )
        };
        let (
            v1181,
            v1185,
            v1189,
            v1194,
            v1196,
            v1198,
            v1201,
            v1203,
            v1205,
            v1208,
            v1210,
            v1225,
            v1238,
            v1240,
            v1246,
            v1249,
            v1250,
            v1252,
            v1263,
            v1268,
            v1269,
            v1277,
            v1288,
            v1293,
            v1298,
            v1301,
            v1304,
            v1307,
            v1313,
            v1316,
            v1319,
            v1324,
            v1329,
        ) = {
            let v1140: f32 = v1139 * v3;
            let v1141: f32 = v1140 * v9;
            let v1142: f32 = v1137 + v1141;
            let v1143: f32 = v1142 * v202;
            let v1144: f32 = v1140 * v90;
            let v1145: f32 = v1139 * v55;
            let v1146: f32 = v1145 * v9;
            let v1147: f32 = v1144 + v1146;
            let v1148: f32 = v1147 * v210;
            let v1149: f32 = v1143 + v1148;
            let v1150: f32 = v1149 * v27;
            let v1151: f32 = v1150 * v18;
            let v1152: f32 = v1134 + v1151;
            let v1153: f32 = v855 * v210;
            let v1154: f32 = v865 + v1153;
            let v1155: f32 = v1154 * v12;
            let v1156: f32 = v1155 * v29;
            let v1157: f32 = v867 * v15;
            let v1158: f32 = v1157 * v29;
            let v1159: f32 = v28 * v18;
            let v1160: f32 = v1159 * v3;
            let v1161: f32 = v13 * v55;
            let v1162: f32 = v1160 - v1161;
            let v1163: f32 = v1162 * v90;
            let v1164: f32 = v1159 * v55;
            let v1165: f32 = v13 * v3;
            let v1166: f32 = v1164 + v1165;
            let v1167: f32 = v1166 * v9;
            let v1168: f32 = v1163 + v1167;
            let v1169: f32 = v1168 * v202;
            let v1170: f32 = v1166 * v90;
            let v1171: f32 = v1161 - v1160;
            let v1172: f32 = v1171 * v9;
            let v1173: f32 = v1170 + v1172;
            let v1174: f32 = v1173 * v210;
            let v1175: f32 = v1169 + v1174;
            let v1176: f32 = v1175 * v32;
            let v1177: f32 = v1158 + v1176;
            let v1178: f32 = v1177 * v15;
            let v1179: f32 = v1156 + v1178;
            let v1180: f32 = v1179 * v29;
            let v1181: f32 = v1152 + v1180;
            let v1182: f32 = v671 * v9;
            let v1183: f32 = v1182 - v406;
            let v1184: f32 = v57 + v412;
            let v1185: f32 = v69 + v415;
            let v1186: f32 = v1185 + v474;
            let v1187: f32 = v1186 * v3;
            let v1188: f32 = v1184 + v1187;
            let v1189: f32 = v1188 * v55;
            let v1190: f32 = v1183 + v1189;
            let v1191: f32 = -0.3767458_f32;
            let v1192: f32 = v1191 + v415;
            let v1193: f32 = v1192 + v426;
            let v1194: f32 = v1193 + v474;
            let v1195: f32 = v1194 * v9;
            let v1196: f32 = v430 + v1195;
            let v1197: f32 = -0.42962232_f32;
            let v1198: f32 = v1197 - v77;
            let v1199: f32 = v40 - v77;
            let v1200: f32 = v1199 * v29;
            let v1201: f32 = v1200 * v29;
            let v1202: f32 = v1198 + v1201;
            let v1203: f32 = v1202 * v55;
            let v1204: f32 = v440 + v1203;
            let v1205: f32 = v1204 * v9;
            let v1206: f32 = v676 + v1205;
            let v1207: f32 = v749 - v444;
            let v1208: f32 = v1202 * v3;
            let v1209: f32 = v1207 + v1208;
            let v1210: f32 = v1209 * v90;
            let v1211: f32 = v1206 + v1210;
            let v1212: f32 = v1211 * v55;
            let v1213: f32 = v1196 + v1212;
            let v1214: f32 = v1213 * v90;
            let v1215: f32 = v1190 + v1214;
            let v1216: f32 = v194 - v589;
            let v1217: f32 = v1216 * v9;
            let v1218: f32 = v411 + v1217;
            let v1219: f32 = v1218 * v202;
            let v1220: f32 = v204 + v415;
            let v1221: f32 = v1220 + v426;
            let v1222: f32 = v1221 + v474;
            let v1223: f32 = v1222 * v210;
            let v1224: f32 = v1219 + v1223;
            let v1225: f32 = v1209 * v202;
            let v1226: f32 = v189 * v9;
            let v1227: f32 = v440 - v1226;
            let v1228: f32 = v1227 + v1203;
            let v1229: f32 = v1228 * v210;
            let v1230: f32 = v1225 + v1229;
            let v1231: f32 = v1230 * v55;
            let v1232: f32 = v1224 + v1231;
            let v1233: f32 = v252 - v77;
            let v1234: f32 = v1233 - v582;
            let v1235: f32 = v1234 + v1201;
            let v1236: f32 = v1235 * v9;
            let v1237: f32 = v1236 - v579;
            let v1238: f32 = v1237 * v202;
            let v1239: f32 = v1216 + v591;
            let v1240: f32 = v1235 * v90;
            let v1241: f32 = v1239 + v1240;
            let v1242: f32 = v1241 * v210;
            let v1243: f32 = v1238 + v1242;
            let v1244: f32 = v617 * v55;
            let v1245: f32 = v1244 - v600;
            let v1246: f32 = v1245 * v90;
            let v1247: f32 = v629 * v9;
            let v1248: f32 = v1246 + v1247;
            let v1249: f32 = v1248 * v210;
            let v1250: f32 = v1245 * v9;
            let v1251: f32 = v189 + v1250;
            let v1252: f32 = v619 * v90;
            let v1253: f32 = v1251 + v1252;
            let v1254: f32 = v1253 * v202;
            let v1255: f32 = v1249 + v1254;
            let v1256: f32 = v1255 * v55;
            let v1257: f32 = v1243 + v1256;
            let v1258: f32 = v1257 * v90;
            let v1259: f32 = v1232 + v1258;
            let v1260: f32 = v1259 * v202;
            let v1261: f32 = v1215 + v1260;
            let v1262: f32 = v1261 * v454;
            let v1263: f32 = v1181 + v1262;
            let v1264: f32 = v417 * v12;
            let v1265: f32 = v1264 * v18;
            let v1266: f32 = v53 * v29;
            let v1267: f32 = v1265 - v1266;
            let v1268: f32 = v1267 * v29;
            let v1269: f32 = v53 + v1268;
            let v1270: f32 = v188 * v90;
            let v1271: f32 = v58 + v1270;
            let v1272: f32 = v1271 * v55;
            let v1273: f32 = v1269 - v1272;
            let v1274: f32 = v188 * v3;
            let v1275: f32 = v1274 - v193;
            let v1276: f32 = v1275 * v9;
            let v1277: f32 = v1273 + v1276;
            let v1278: f32 = v188 + v108;
            let v1279: f32 = v1278 * v90;
            let v1280: f32 = v58 + v1279;
            let v1281: f32 = v1280 * v55;
            let v1282: f32 = v1269 - v1281;
            let v1283: f32 = v1278 * v3;
            let v1284: f32 = v0 * v6;
            let v1285: f32 = v193 + v1284;
            let v1286: f32 = v1283 - v1285;
            let v1287: f32 = v1286 * v9;
            let v1288: f32 = v1282 + v1287;
            let v1289: f32 = v1283 * v9;
            let v1290: f32 = v1269 + v1289;
            let v1291: f32 = v62 + v1279;
            let v1292: f32 = v1291 * v55;
            let v1293: f32 = v1290 - v1292;
            let v1294: f32 = v1139 * v27;
            let v1295: f32 = v1294 * v18;
            let v1296: f32 = v1133 * v454;
            let v1297: f32 = v1295 + v1296;
            let v1298: f32 = v1154 * v454;
            let v1299: f32 = v1298 * v29;
            let v1300: f32 = v1027 + v1299;
            let v1301: f32 = v64 - v1012;
            let v1302: f32 = v1040 - v1039;
            let v1303: f32 = v1302 * v9;
            let v1304: f32 = v1303 - v1038;
            let v1305: f32 = v1304 * v202;
            let v1306: f32 = v1302 * v90;
            let v1307: f32 = v1002 * v9;
            let v1308: f32 = v1306 + v1307;
            let v1309: f32 = v1308 * v210;
            let v1310: f32 = v1305 + v1309;
            let v1311: f32 = v1310 * v454;
            let v1312: f32 = v1301 + v1311;
            let v1313: f32 = v1312 * v15;
            let v1314: f32 = v1300 + v1313;
            let v1315: f32 = v1314 * v29;
            let v1316: f32 = v1297 + v1315;
            let v1317: f32 = v798 - v796;
            let v1318: f32 = v1317 * v202;
            let v1319: f32 = v974 * v210;
            let v1320: f32 = v1318 - v1319;
            let v1321: f32 = v1320 * v454;
            let v1322: f32 = v794 * v12;
            let v1323: f32 = v1321 - v1322;
            let v1324: f32 = v1323 * v18;
            let v1325: f32 = v863 * v202;
            let v1326: f32 = v1325 + v860;
            let v1327: f32 = v1326 * v454;
            let v1328: f32 = v13 + v1327;
            let v1329: f32 = v1328 * v15;
            (
                v1181,
                v1185,
                v1189,
                v1194,
                v1196,
                v1198,
                v1201,
                v1203,
                v1205,
                v1208,
                v1210,
                v1225,
                v1238,
                v1240,
                v1246,
                v1249,
                v1250,
                v1252,
                v1263,
                v1268,
                v1269,
                v1277,
                v1288,
                v1293,
                v1298,
                v1301,
                v1304,
                v1307,
                v1313,
                v1316,
                v1319,
                v1324,
                v1329,
            )
        };
        let (
            v1338,
            v1371,
            v1379,
            v1380,
            v1382,
            v1428,
            v1438,
            v1442,
            v1447,
            v1478,
            v1485,
            v1486,
            v1487,
            v1488,
            v1506,
            v1510,
            v1513,
            v1517,
            v1519,
        ) = {
            let v1330: f32 = v1329 * v18;
            let v1331: f32 = v1298 * v18;
            let v1332: f32 = v1331 - v501;
            let v1333: f32 = v1332 * v29;
            let v1334: f32 = v26 + v1333;
            let v1335: f32 = v1334 * v32;
            let v1336: f32 = v1330 + v1335;
            let v1337: f32 = v1336 * v15;
            let v1338: f32 = v1324 + v1337;
            let v1339: f32 = v1189 - v406;
            let v1340: f32 = v1205 + v1210;
            let v1341: f32 = v1340 * v55;
            let v1342: f32 = v1196 + v1341;
            let v1343: f32 = v1342 * v90;
            let v1344: f32 = v1339 + v1343;
            let v1345: f32 = v411 + v407;
            let v1346: f32 = v1345 * v202;
            let v1347: f32 = v1194 * v210;
            let v1348: f32 = v1346 + v1347;
            let v1349: f32 = v1 * v9;
            let v1350: f32 = v440 - v1349;
            let v1351: f32 = v1350 + v1203;
            let v1352: f32 = v1351 * v210;
            let v1353: f32 = v1225 + v1352;
            let v1354: f32 = v1353 * v55;
            let v1355: f32 = v1348 + v1354;
            let v1356: f32 = v5 + v591;
            let v1357: f32 = v1356 + v1240;
            let v1358: f32 = v1357 * v210;
            let v1359: f32 = v1238 + v1358;
            let v1360: f32 = v1 + v1250;
            let v1361: f32 = v1360 + v1252;
            let v1362: f32 = v1361 * v202;
            let v1363: f32 = v1249 + v1362;
            let v1364: f32 = v1363 * v55;
            let v1365: f32 = v1359 + v1364;
            let v1366: f32 = v1365 * v90;
            let v1367: f32 = v1355 + v1366;
            let v1368: f32 = v1367 * v202;
            let v1369: f32 = v1344 + v1368;
            let v1370: f32 = v1369 * v454;
            let v1371: f32 = v1181 + v1370;
            let v1372: f32 = v58 * v55;
            let v1373: f32 = v53 - v1372;
            let v1374: f32 = v1 * v55;
            let v1375: f32 = v1374 * v90;
            let v1376: f32 = v1375 + v407;
            let v1377: f32 = v1376 * v6;
            let v1378: f32 = v1373 + v1377;
            let v1379: f32 = v1378 + v1268;
            let v1380: f32 = v1373 + v1268;
            let v1381: f32 = v62 * v55;
            let v1382: f32 = v1269 - v1381;
            let v1383: f32 = v1185 + v689;
            let v1384: f32 = v1383 + v474;
            let v1385: f32 = v1384 * v9;
            let v1386: f32 = v430 + v1385;
            let v1387: f32 = v409 - v444;
            let v1388: f32 = v1387 + v1208;
            let v1389: f32 = v1388 * v90;
            let v1390: f32 = v1205 + v1389;
            let v1391: f32 = v1390 * v55;
            let v1392: f32 = v1386 + v1391;
            let v1393: f32 = v1392 * v90;
            let v1394: f32 = v1339 + v1393;
            let v1395: f32 = v4 * v9;
            let v1396: f32 = v411 - v1395;
            let v1397: f32 = v1396 * v202;
            let v1398: f32 = v1384 * v210;
            let v1399: f32 = v1397 + v1398;
            let v1400: f32 = v1388 * v202;
            let v1401: f32 = v1400 + v1352;
            let v1402: f32 = v1401 * v55;
            let v1403: f32 = v1399 + v1402;
            let v1404: f32 = v1198 - v426;
            let v1405: f32 = v1404 + v1201;
            let v1406: f32 = v1405 * v9;
            let v1407: f32 = v1406 - v579;
            let v1408: f32 = v1407 * v202;
            let v1409: f32 = v591 - v4;
            let v1410: f32 = v1405 * v90;
            let v1411: f32 = v1409 + v1410;
            let v1412: f32 = v1411 * v210;
            let v1413: f32 = v1408 + v1412;
            let v1414: f32 = v751 * v9;
            let v1415: f32 = v1246 + v1414;
            let v1416: f32 = v1415 * v210;
            let v1417: f32 = v745 * v90;
            let v1418: f32 = v1360 + v1417;
            let v1419: f32 = v1418 * v202;
            let v1420: f32 = v1416 + v1419;
            let v1421: f32 = v1420 * v55;
            let v1422: f32 = v1413 + v1421;
            let v1423: f32 = v1422 * v90;
            let v1424: f32 = v1403 + v1423;
            let v1425: f32 = v1424 * v202;
            let v1426: f32 = v1394 + v1425;
            let v1427: f32 = v1426 * v454;
            let v1428: f32 = v1181 + v1427;
            let v1429: f32 = v108 * v3;
            let v1430: f32 = v1429 * v9;
            let v1431: f32 = v53 - v1430;
            let v1432: f32 = v1431 + v1268;
            let v1433: f32 = v1 * v90;
            let v1434: f32 = v57 + v1433;
            let v1435: f32 = v1434 * v6;
            let v1436: f32 = v59 + v1435;
            let v1437: f32 = v1436 * v55;
            let v1438: f32 = v1432 + v1437;
            let v1439: f32 = v59 + v61;
            let v1440: f32 = v1439 * v55;
            let v1441: f32 = v53 + v1440;
            let v1442: f32 = v1441 + v1268;
            let v1443: f32 = v907 * v9;
            let v1444: f32 = v870 + v1443;
            let v1445: f32 = v1444 * v90;
            let v1446: f32 = v1445 - v868;
            let v1447: f32 = v1446 * v454;
            let v1448: f32 = v1447 * v15;
            let v1449: f32 = v1448 * v32;
            let v1450: f32 = v1449 * v18;
            let v1451: f32 = v1122 * v20;
            let v1452: f32 = v1122 * v22;
            let v1453: f32 = v1451 + v1452;
            let v1454: f32 = v1122 * v6;
            let v1455: f32 = v1453 + v1454;
            let v1456: f32 = v1455 * v55;
            let v1457: f32 = v53 * v3;
            let v1458: f32 = v1456 - v1457;
            let v1459: f32 = v1458 * v90;
            let v1460: f32 = v53 * v55;
            let v1461: f32 = v1455 * v3;
            let v1462: f32 = v1460 + v1461;
            let v1463: f32 = v1462 * v9;
            let v1464: f32 = v1459 - v1463;
            let v1465: f32 = v1464 * v210;
            let v1466: f32 = v1450 + v1465;
            let v1467: f32 = v1461 * v90;
            let v1468: f32 = v1456 * v9;
            let v1469: f32 = v1467 + v1468;
            let v1470: f32 = v907 * v210;
            let v1471: f32 = v875 + v1470;
            let v1472: f32 = v1088 * v210;
            let v1473: f32 = v1472 - v881;
            let v1474: f32 = v1473 * v55;
            let v1475: f32 = v892 + v1474;
            let v1476: f32 = v1475 * v90;
            let v1477: f32 = v1471 + v1476;
            let v1478: f32 = v1477 * v454;
            let v1479: f32 = v1478 * v18;
            let v1480: f32 = v914 + v1479;
            let v1481: f32 = v1480 * v15;
            let v1482: f32 = v1481 * v32;
            let v1483: f32 = v1469 + v1482;
            let v1484: f32 = v1483 * v202;
            let v1485: f32 = v1466 + v1484;
            let v1486: f32 = v489 * v90;
            let v1487: f32 = v487 * v9;
            let v1488: f32 = v1486 - v1487;
            let v1489: f32 = v1488 * v27;
            let v1490: f32 = v1489 + v916;
            let v1491: f32 = v1490 * v210;
            let v1492: f32 = v913 + v1491;
            let v1493: f32 = v486 * v27;
            let v1494: f32 = v1493 - v501;
            let v1495: f32 = v1494 * v9;
            let v1496: f32 = v922 + v1495;
            let v1497: f32 = v1496 * v55;
            let v1498: f32 = v1497 - v810;
            let v1499: f32 = v1493 + v841;
            let v1500: f32 = v1499 - v501;
            let v1501: f32 = v1500 * v3;
            let v1502: f32 = v934 + v1501;
            let v1503: f32 = v1502 * v90;
            let v1504: f32 = v1498 + v1503;
            let v1505: f32 = v1504 * v202;
            let v1506: f32 = v1492 + v1505;
            let v1507: f32 = v803 * v202;
            let v1508: f32 = v497 * v210;
            let v1509: f32 = v1507 - v1508;
            let v1510: f32 = v1509 * v32;
            let v1511: f32 = v914 + v804;
            let v1512: f32 = v1511 * v210;
            let v1513: f32 = v793 + v1512;
            let v1514: f32 = v502 * v9;
            let v1515: f32 = v816 + v1514;
            let v1516: f32 = v1515 * v55;
            let v1517: f32 = v810 + v1516;
            let v1518: f32 = v28 - v841;
            let v1519: f32 = v1518 + v501;
            (
                v1338,
                v1371,
                v1379,
                v1380,
                v1382,
                v1428,
                v1438,
                v1442,
                v1447,
                v1478,
                v1485,
                v1486,
                v1487,
                v1488,
                v1506,
                v1510,
                v1513,
                v1517,
                v1519,
            )
        };
        let (v1531, v1558, v1559, v1575, v1679, v1698, v1704, v1705) = {
            let v1520: f32 = v1519 * v3;
            let v1521: f32 = v833 + v1520;
            let v1522: f32 = v1521 * v90;
            let v1523: f32 = v1517 + v1522;
            let v1524: f32 = v1523 * v202;
            let v1525: f32 = v1513 + v1524;
            let v1526: f32 = v1525 * v15;
            let v1527: f32 = v1510 + v1526;
            let v1528: f32 = v1527 * v15;
            let v1529: f32 = v1506 + v1528;
            let v1530: f32 = v1529 * v29;
            let v1531: f32 = v1485 + v1530;
            let v1532: f32 = v532 * v18;
            let v1533: f32 = v1126 - v1124;
            let v1534: f32 = v1533 * v210;
            let v1535: f32 = v1132 + v1534;
            let v1536: f32 = v1535 * v454;
            let v1537: f32 = v1532 + v1536;
            let v1538: f32 = v533 * v18;
            let v1539: f32 = v861 * v15;
            let v1540: f32 = v1539 * v32;
            let v1541: f32 = v472 * v3;
            let v1542: f32 = v1541 * v90;
            let v1543: f32 = v472 * v55;
            let v1544: f32 = v1543 * v9;
            let v1545: f32 = v1542 + v1544;
            let v1546: f32 = v1545 * v202;
            let v1547: f32 = v1543 * v90;
            let v1548: f32 = v417 * v3;
            let v1549: f32 = v1548 * v9;
            let v1550: f32 = v1547 + v1549;
            let v1551: f32 = v1550 * v210;
            let v1552: f32 = v1546 + v1551;
            let v1553: f32 = v1552 * v29;
            let v1554: f32 = v1540 + v1553;
            let v1555: f32 = v1554 * v454;
            let v1556: f32 = v1538 + v1555;
            let v1557: f32 = v1556 * v29;
            let v1558: f32 = v1537 + v1557;
            let v1559: f32 = -v53;
            let v1560: f32 = v957 * v18;
            let v1561: f32 = v491 * v202;
            let v1562: f32 = v1488 * v210;
            let v1563: f32 = v1561 + v1562;
            let v1564: f32 = v1563 * v454;
            let v1565: f32 = v1564 * v29;
            let v1566: f32 = v1560 + v1565;
            let v1567: f32 = v1043 * v202;
            let v1568: f32 = v1041 * v90;
            let v1569: f32 = v1568 - v1307;
            let v1570: f32 = v1569 * v210;
            let v1571: f32 = v1567 + v1570;
            let v1572: f32 = v1571 * v454;
            let v1573: f32 = v1013 + v1572;
            let v1574: f32 = v1573 * v15;
            let v1575: f32 = v1566 + v1574;
            let v1576: f32 = v1447 * v29;
            let v1577: f32 = v1487 - v1486;
            let v1578: f32 = v1577 * v12;
            let v1579: f32 = v1578 * v29;
            let v1580: f32 = v794 * v20;
            let v1581: f32 = v794 * v22;
            let v1582: f32 = v1580 + v1581;
            let v1583: f32 = v794 * v6;
            let v1584: f32 = v1582 + v1583;
            let v1585: f32 = v1584 * v3;
            let v1586: f32 = v1585 * v90;
            let v1587: f32 = v1584 * v55;
            let v1588: f32 = v1587 * v9;
            let v1589: f32 = v1586 + v1588;
            let v1590: f32 = v1589 * v18;
            let v1591: f32 = v1579 + v1590;
            let v1592: f32 = v1591 * v210;
            let v1593: f32 = v1576 + v1592;
            let v1594: f32 = v1585 * v9;
            let v1595: f32 = v1587 * v90;
            let v1596: f32 = v1594 - v1595;
            let v1597: f32 = v1596 * v18;
            let v1598: f32 = v491 * v12;
            let v1599: f32 = v1478 - v1598;
            let v1600: f32 = v1599 * v29;
            let v1601: f32 = v1597 + v1600;
            let v1602: f32 = v1601 * v202;
            let v1603: f32 = v1593 + v1602;
            let v1604: f32 = v11 + v551;
            let v1605: f32 = v1604 * v32;
            let v1606: f32 = v1605 * v55;
            let v1607: f32 = v988 + v1606;
            let v1608: f32 = v1607 * v55;
            let v1609: f32 = v1608 - v983;
            let v1610: f32 = v1609 * v454;
            let v1611: f32 = v1045 * v18;
            let v1612: f32 = v1003 + v1611;
            let v1613: f32 = v1612 * v9;
            let v1614: f32 = v1613 * v210;
            let v1615: f32 = v1610 + v1614;
            let v1616: f32 = v1605 * v90;
            let v1617: f32 = v1009 + v1616;
            let v1618: f32 = v1617 * v454;
            let v1619: f32 = v1301 * v3;
            let v1620: f32 = v1619 * v210;
            let v1621: f32 = v1618 + v1620;
            let v1622: f32 = v1018 - v1017;
            let v1623: f32 = v1622 * v454;
            let v1624: f32 = v1623 * v32;
            let v1625: f32 = v1623 * v29;
            let v1626: f32 = v1625 - v1028;
            let v1627: f32 = v1626 * v32;
            let v1628: f32 = v1627 - v1025;
            let v1629: f32 = v1628 * v29;
            let v1630: f32 = v1624 + v1629;
            let v1631: f32 = v1630 * v55;
            let v1632: f32 = v1621 + v1631;
            let v1633: f32 = v1632 * v90;
            let v1634: f32 = v1615 + v1633;
            let v1635: f32 = v1304 * v12;
            let v1636: f32 = v997 * v90;
            let v1637: f32 = v1636 - v1050;
            let v1638: f32 = v1637 * v18;
            let v1639: f32 = v1635 + v1638;
            let v1640: f32 = v1605 * v202;
            let v1641: f32 = v1055 + v1640;
            let v1642: f32 = v814 * v32;
            let v1643: f32 = v1065 - v1064;
            let v1644: f32 = v1643 * v210;
            let v1645: f32 = v1644 - v1063;
            let v1646: f32 = v1645 * v29;
            let v1647: f32 = v1642 + v1646;
            let v1648: f32 = v1647 * v55;
            let v1649: f32 = v1641 + v1648;
            let v1650: f32 = v1074 - v1073;
            let v1651: f32 = v1650 * v32;
            let v1652: f32 = v1082 - v1081;
            let v1653: f32 = v1652 * v210;
            let v1654: f32 = v1653 - v1080;
            let v1655: f32 = v1654 * v29;
            let v1656: f32 = v1651 + v1655;
            let v1657: f32 = v884 * v202;
            let v1658: f32 = v1657 - v1090;
            let v1659: f32 = v1658 * v32;
            let v1660: f32 = v1096 - v1095;
            let v1661: f32 = v1660 * v9;
            let v1662: f32 = v1102 + v1661;
            let v1663: f32 = v1662 * v202;
            let v1664: f32 = v1660 * v90;
            let v1665: f32 = v1664 - v1106;
            let v1666: f32 = v1665 * v210;
            let v1667: f32 = v1663 + v1666;
            let v1668: f32 = v1667 * v29;
            let v1669: f32 = v1659 + v1668;
            let v1670: f32 = v1669 * v55;
            let v1671: f32 = v1656 + v1670;
            let v1672: f32 = v1671 * v90;
            let v1673: f32 = v1649 + v1672;
            let v1674: f32 = v1673 * v454;
            let v1675: f32 = v1639 + v1674;
            let v1676: f32 = v1675 * v202;
            let v1677: f32 = v1634 + v1676;
            let v1678: f32 = v1677 * v15;
            let v1679: f32 = v1603 + v1678;
            let v1680: f32 = v799 * v202;
            let v1681: f32 = v1680 + v1319;
            let v1682: f32 = v1681 * v454;
            let v1683: f32 = v486 * v12;
            let v1684: f32 = v1682 - v1683;
            let v1685: f32 = v1684 * v18;
            let v1686: f32 = v861 * v454;
            let v1687: f32 = v1686 - v13;
            let v1688: f32 = v1687 * v15;
            let v1689: f32 = v1688 * v18;
            let v1690: f32 = v866 * v454;
            let v1691: f32 = v1690 * v18;
            let v1692: f32 = v501 + v1691;
            let v1693: f32 = v1692 * v29;
            let v1694: f32 = v1693 - v26;
            let v1695: f32 = v1694 * v32;
            let v1696: f32 = v1689 + v1695;
            let v1697: f32 = v1696 * v15;
            let v1698: f32 = v1685 + v1697;
            let v1699: f32 = v1577 * v210;
            let v1700: f32 = v1699 - v1561;
            let v1701: f32 = v1700 * v454;
            let v1702: f32 = v1701 * v29;
            let v1703: f32 = v1702 - v1560;
            let v1704: f32 = v1703 + v1313;
            let v1705: f32 = 0.0_f32;
            (v1531, v1558, v1559, v1575, v1679, v1698, v1704, v1705)
        };
        [
            [v403, v641, v688, v763, v948, v1121],
            [v1263, v1277, v1288, v1293, v1316, v1338],
            [v1371, v1379, v1380, v1382, v1316, v1338],
            [v1428, v1438, v1442, v1269, v1316, v1338],
            [v1531, v1558, v1558, v1558, v1559, v1575],
            [v1679, v1698, v1698, v1698, v1704, v1705],
        ]
    }
    /// Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 6]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis: [f32; 6]`: c(q, qd) = C(q, qd) qd (N m or N)
    ///
    /// Operation count: 393 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn coriolis(q: &[f32; 6], qd: &[f32; 6]) -> [f32; 6] {
        let (
            v1,
            v2,
            v3,
            v5,
            v6,
            v7,
            v9,
            v11,
            v12,
            v16,
            v17,
            v18,
            v20,
            v21,
            v25,
            v27,
            v28,
            v30,
            v31,
            v36,
            v39,
            v41,
            v42,
            v44,
            v45,
            v49,
            v50,
            v52,
            v56,
            v57,
            v61,
            v62,
            v65,
            v67,
            v69,
            v70,
            v72,
            v77,
            v82,
            v85,
            v87,
            v88,
            v89,
            v91,
            v94,
            v96,
            v98,
            v100,
            v103,
            v104,
            v106,
            v109,
            v111,
            v112,
            v113,
            v114,
            v121,
            v123,
            v125,
            v130,
            v132,
            v133,
            v137,
            v138,
            v139,
            v141,
            v144,
        ) = {
            let v0: f32 = q[1];
            let (v3, v1): (f32, f32) = ::libm::sincosf(v0);
            let v2: f32 = 0.8849019_f32;
            let v4: f32 = qd[0];
            let v5: f32 = v3 * v4;
            let v6: f32 = qd[1];
            let v7: f32 = v5 * v6;
            let v8: f32 = v2 * v7;
            let v9: f32 = v2 * v6;
            let v10: f32 = v5 * v9;
            let v11: f32 = 0.0151074_f32;
            let v12: f32 = v11 * v5;
            let v13: f32 = v6 * v12;
            let v14: f32 = v10 - v13;
            let v15: f32 = v8 + v14;
            let v16: f32 = 2.35004_f32;
            let v17: f32 = 0.13585_f32;
            let v18: f32 = v17 * v5;
            let v19: f32 = v5 * v18;
            let v20: f32 = v1 * v4;
            let v21: f32 = v17 * v20;
            let v22: f32 = v20 * v21;
            let v23: f32 = v19 + v22;
            let v24: f32 = v16 * v23;
            let v25: f32 = v15 + v24;
            let v26: f32 = q[2];
            let (v30, v27): (f32, f32) = ::libm::sincosf(v26);
            let v28: f32 = 0.19163081_f32;
            let v29: f32 = v27 * v7;
            let v31: f32 = v20 * v6;
            let v32: f32 = v30 * v31;
            let v33: f32 = v29 + v32;
            let v34: f32 = v30 * v20;
            let v35: f32 = v27 * v5;
            let v36: f32 = v34 + v35;
            let v37: f32 = qd[2];
            let v38: f32 = v36 * v37;
            let v39: f32 = v33 + v38;
            let v40: f32 = v28 * v39;
            let v41: f32 = v6 + v37;
            let v42: f32 = v28 * v41;
            let v43: f32 = v36 * v42;
            let v44: f32 = 0.004095_f32;
            let v45: f32 = v44 * v36;
            let v46: f32 = v41 * v45;
            let v47: f32 = v43 - v46;
            let v48: f32 = v40 + v47;
            let v49: f32 = 0.56875_f32;
            let v50: f32 = 0.425_f32;
            let v51: f32 = v50 * v7;
            let v52: f32 = v50 * v6;
            let v53: f32 = v5 * v52;
            let v54: f32 = v51 + v53;
            let v55: f32 = v23 + v54;
            let v56: f32 = -0.1197_f32;
            let v57: f32 = v56 * v36;
            let v58: f32 = v36 * v57;
            let v59: f32 = v30 * v5;
            let v60: f32 = v27 * v20;
            let v61: f32 = v59 - v60;
            let v62: f32 = v56 * v61;
            let v63: f32 = v61 * v62;
            let v64: f32 = v58 + v63;
            let v65: f32 = v55 + v64;
            let v66: f32 = v49 * v65;
            let v67: f32 = v48 + v66;
            let v68: f32 = q[3];
            let (v72, v69): (f32, f32) = ::libm::sincosf(v68);
            let v70: f32 = 0.21942_f32;
            let v71: f32 = v69 * v39;
            let v73: f32 = v30 * v7;
            let v74: f32 = v27 * v31;
            let v75: f32 = v73 - v74;
            let v76: f32 = v61 * v37;
            let v77: f32 = v75 + v76;
            let v78: f32 = v72 * v77;
            let v79: f32 = v71 - v78;
            let v80: f32 = v69 * v36;
            let v81: f32 = v72 * v61;
            let v82: f32 = v80 - v81;
            let v83: f32 = qd[3];
            let v84: f32 = v82 * v83;
            let v85: f32 = v79 + v84;
            let v86: f32 = v70 * v85;
            let v87: f32 = 0.11117276_f32;
            let v88: f32 = v41 + v83;
            let v89: f32 = v87 * v88;
            let v90: f32 = v82 * v89;
            let v91: f32 = v87 * v82;
            let v92: f32 = v88 * v91;
            let v93: f32 = v90 - v92;
            let v94: f32 = v86 + v93;
            let v95: f32 = q[4];
            let (v98, v96): (f32, f32) = ::libm::sincosf(v95);
            let v97: f32 = v96 * v82;
            let v99: f32 = v98 * v88;
            let v100: f32 = v97 + v99;
            let v101: f32 = v96 * v88;
            let v102: f32 = v98 * v82;
            let v103: f32 = v101 - v102;
            let v104: f32 = v87 * v103;
            let v105: f32 = v100 * v104;
            let v106: f32 = v87 * v100;
            let v107: f32 = v103 * v106;
            let v108: f32 = v105 - v107;
            let v109: f32 = v86 + v108;
            let v110: f32 = q[5];
            let (v113, v111): (f32, f32) = ::libm::sincosf(v110);
            let v112: f32 = 0.033822_f32;
            let v114: f32 = qd[4];
            let v115: f32 = v103 * v114;
            let v116: f32 = v72 * v39;
            let v117: f32 = v69 * v77;
            let v118: f32 = v116 + v117;
            let v119: f32 = v69 * v61;
            let v120: f32 = v72 * v36;
            let v121: f32 = v119 + v120;
            let v122: f32 = v121 * v83;
            let v123: f32 = v118 + v122;
            let v124: f32 = v96 * v123;
            let v125: f32 = v115 - v124;
            let v126: f32 = v113 * v125;
            let v127: f32 = v111 * v85;
            let v128: f32 = v126 + v127;
            let v129: f32 = v111 * v100;
            let v130: f32 = v121 + v114;
            let v131: f32 = v113 * v130;
            let v132: f32 = v129 - v131;
            let v133: f32 = qd[5];
            let v134: f32 = v132 * v133;
            let v135: f32 = v128 + v134;
            let v136: f32 = v112 * v135;
            let v137: f32 = 0.017136473_f32;
            let v138: f32 = v103 + v133;
            let v139: f32 = v137 * v138;
            let v140: f32 = v132 * v139;
            let v141: f32 = v137 * v132;
            let v142: f32 = v138 * v141;
            let v143: f32 = v140 - v142;
            let v144: f32 = v136 + v143;
            (
                v1,
                v2,
                v3,
                v5,
                v6,
                v7,
                v9,
                v11,
                v12,
                v16,
                v17,
                v18,
                v20,
                v21,
                v25,
                v27,
                v28,
                v30,
                v31,
                v36,
                v39,
                v41,
                v42,
                v44,
                v45,
                v49,
                v50,
                v52,
                v56,
                v57,
                v61,
                v62,
                v65,
                v67,
                v69,
                v70,
                v72,
                v77,
                v82,
                v85,
                v87,
                v88,
                v89,
                v91,
                v94,
                v96,
                v98,
                v100,
                v103,
                v104,
                v106,
                v109,
                v111,
                v112,
                v113,
                v114,
                v121,
                v123,
                v125,
                v130,
                v132,
                v133,
                v137,
                v138,
                v139,
                v141,
                v144,
            )
        };
        let (
            v151,
            v155,
            v162,
            v164,
            v165,
            v172,
            v179,
            v189,
            v190,
            v201,
            v208,
            v214,
            v224,
            v227,
            v236,
            v240,
            v248,
            v253,
            v255,
            v256,
            v267,
            v269,
            v271,
            v272,
            v273,
            v278,
            v280,
            v288,
            v289,
        ) = {
            let v145: f32 = v111 * v144;
            let v146: f32 = v111 * v125;
            let v147: f32 = v113 * v85;
            let v148: f32 = v146 - v147;
            let v149: f32 = v113 * v100;
            let v150: f32 = v111 * v130;
            let v151: f32 = v149 + v150;
            let v152: f32 = v151 * v133;
            let v153: f32 = v148 - v152;
            let v154: f32 = v137 * v153;
            let v155: f32 = v112 * v151;
            let v156: f32 = v138 * v155;
            let v157: f32 = v151 * v139;
            let v158: f32 = v156 - v157;
            let v159: f32 = v154 + v158;
            let v160: f32 = v113 * v159;
            let v161: f32 = v145 - v160;
            let v162: f32 = v109 + v161;
            let v163: f32 = v94 + v162;
            let v164: f32 = 0.093_f32;
            let v165: f32 = 1.219_f32;
            let v166: f32 = v164 * v82;
            let v167: f32 = v88 * v166;
            let v168: f32 = v164 * v85;
            let v169: f32 = v167 - v168;
            let v170: f32 = v17 * v31;
            let v171: f32 = v6 * v21;
            let v172: f32 = v170 - v171;
            let v173: f32 = v50 * v20;
            let v174: f32 = v5 * v173;
            let v175: f32 = v172 + v174;
            let v176: f32 = v27 * v175;
            let v177: f32 = v17 * v7;
            let v178: f32 = v6 * v18;
            let v179: f32 = v177 - v178;
            let v180: f32 = v20 * v173;
            let v181: f32 = v6 * v52;
            let v182: f32 = v180 + v181;
            let v183: f32 = v179 - v182;
            let v184: f32 = v30 * v183;
            let v185: f32 = v176 - v184;
            let v186: f32 = v41 * v62;
            let v187: f32 = v56 * v77;
            let v188: f32 = v186 - v187;
            let v189: f32 = v185 + v188;
            let v190: f32 = 0.39225_f32;
            let v191: f32 = v190 * v61;
            let v192: f32 = v36 * v191;
            let v193: f32 = v189 - v192;
            let v194: f32 = v72 * v193;
            let v195: f32 = v30 * v175;
            let v196: f32 = v27 * v183;
            let v197: f32 = v195 + v196;
            let v198: f32 = v56 * v39;
            let v199: f32 = v41 * v57;
            let v200: f32 = v198 - v199;
            let v201: f32 = v197 + v200;
            let v202: f32 = v61 * v191;
            let v203: f32 = v190 * v41;
            let v204: f32 = v41 * v203;
            let v205: f32 = v202 + v204;
            let v206: f32 = v201 - v205;
            let v207: f32 = v69 * v206;
            let v208: f32 = v194 + v207;
            let v209: f32 = v169 - v208;
            let v210: f32 = v96 * v209;
            let v211: f32 = v190 * v39;
            let v212: f32 = v36 * v203;
            let v213: f32 = v211 + v212;
            let v214: f32 = v65 + v213;
            let v215: f32 = v164 * v121;
            let v216: f32 = v121 * v215;
            let v217: f32 = v82 * v166;
            let v218: f32 = v216 + v217;
            let v219: f32 = v214 + v218;
            let v220: f32 = v98 * v219;
            let v221: f32 = v210 - v220;
            let v222: f32 = v165 * v221;
            let v223: f32 = 0.1879_f32;
            let v224: f32 = 0.09465_f32;
            let v225: f32 = v98 * v123;
            let v226: f32 = v100 * v114;
            let v227: f32 = v225 - v226;
            let v228: f32 = v224 * v227;
            let v229: f32 = v224 * v100;
            let v230: f32 = v130 * v229;
            let v231: f32 = v228 + v230;
            let v232: f32 = v221 + v231;
            let v233: f32 = v111 * v232;
            let v234: f32 = v69 * v193;
            let v235: f32 = v72 * v206;
            let v236: f32 = v234 - v235;
            let v237: f32 = v88 * v215;
            let v238: f32 = v164 * v123;
            let v239: f32 = v237 - v238;
            let v240: f32 = v236 + v239;
            let v241: f32 = v100 * v229;
            let v242: f32 = v224 * v103;
            let v243: f32 = v103 * v242;
            let v244: f32 = v241 + v243;
            let v245: f32 = v240 - v244;
            let v246: f32 = v113 * v245;
            let v247: f32 = v233 - v246;
            let v248: f32 = v223 * v247;
            let v249: f32 = v111 * v248;
            let v250: f32 = v113 * v232;
            let v251: f32 = v111 * v245;
            let v252: f32 = v250 + v251;
            let v253: f32 = v223 * v252;
            let v254: f32 = v113 * v253;
            let v255: f32 = v249 + v254;
            let v256: f32 = v222 + v255;
            let v257: f32 = v96 * v256;
            let v258: f32 = v130 * v242;
            let v259: f32 = v224 * v125;
            let v260: f32 = v258 - v259;
            let v261: f32 = v98 * v209;
            let v262: f32 = v96 * v219;
            let v263: f32 = v261 + v262;
            let v264: f32 = v260 - v263;
            let v265: f32 = v223 * v264;
            let v266: f32 = v165 * v263;
            let v267: f32 = v265 - v266;
            let v268: f32 = v98 * v267;
            let v269: f32 = v257 - v268;
            let v270: f32 = v164 * v269;
            let v271: f32 = v163 - v270;
            let v272: f32 = v69 * v271;
            let v273: f32 = v70 * v121;
            let v274: f32 = v88 * v273;
            let v275: f32 = v121 * v89;
            let v276: f32 = v274 - v275;
            let v277: f32 = v87 * v123;
            let v278: f32 = v276 - v277;
            let v279: f32 = v87 * v125;
            let v280: f32 = v70 * v130;
            let v281: f32 = v103 * v280;
            let v282: f32 = v130 * v104;
            let v283: f32 = v281 - v282;
            let v284: f32 = v279 + v283;
            let v285: f32 = v111 * v159;
            let v286: f32 = v113 * v144;
            let v287: f32 = v285 + v286;
            let v288: f32 = v284 + v287;
            let v289: f32 = v224 * v265;
            (
                v151,
                v155,
                v162,
                v164,
                v165,
                v172,
                v179,
                v189,
                v190,
                v201,
                v208,
                v214,
                v224,
                v227,
                v236,
                v240,
                v248,
                v253,
                v255,
                v256,
                v267,
                v269,
                v271,
                v272,
                v273,
                v278,
                v280,
                v288,
                v289,
            )
        };
        let (v301, v410, v427, v430, v433) = {
            let v290: f32 = v288 - v289;
            let v291: f32 = v96 * v290;
            let v292: f32 = v87 * v227;
            let v293: f32 = v130 * v106;
            let v294: f32 = v100 * v280;
            let v295: f32 = v293 - v294;
            let v296: f32 = v292 + v295;
            let v297: f32 = v137 * v227;
            let v298: f32 = v151 * v141;
            let v299: f32 = v132 * v155;
            let v300: f32 = v298 - v299;
            let v301: f32 = v297 + v300;
            let v302: f32 = v296 + v301;
            let v303: f32 = v224 * v255;
            let v304: f32 = v302 + v303;
            let v305: f32 = v98 * v304;
            let v306: f32 = v291 - v305;
            let v307: f32 = v278 + v306;
            let v308: f32 = v165 * v240;
            let v309: f32 = v111 * v253;
            let v310: f32 = v113 * v248;
            let v311: f32 = v309 - v310;
            let v312: f32 = v308 + v311;
            let v313: f32 = v164 * v312;
            let v314: f32 = v307 + v313;
            let v315: f32 = v72 * v314;
            let v316: f32 = v272 - v315;
            let v317: f32 = v67 + v316;
            let v318: f32 = v98 * v256;
            let v319: f32 = v96 * v267;
            let v320: f32 = v318 + v319;
            let v321: f32 = v165 * v214;
            let v322: f32 = v320 - v321;
            let v323: f32 = v190 * v322;
            let v324: f32 = v317 - v323;
            let v325: f32 = 2.275_f32;
            let v326: f32 = v325 * v201;
            let v327: f32 = v49 * v61;
            let v328: f32 = v61 * v327;
            let v329: f32 = v49 * v41;
            let v330: f32 = v41 * v329;
            let v331: f32 = v328 + v330;
            let v332: f32 = v326 - v331;
            let v333: f32 = v165 * v208;
            let v334: f32 = v269 - v333;
            let v335: f32 = v69 * v334;
            let v336: f32 = v165 * v236;
            let v337: f32 = v336 + v312;
            let v338: f32 = v72 * v337;
            let v339: f32 = v335 + v338;
            let v340: f32 = v332 - v339;
            let v341: f32 = v56 * v340;
            let v342: f32 = v324 + v341;
            let v343: f32 = v27 * v342;
            let v344: f32 = v44 * v77;
            let v345: f32 = v61 * v42;
            let v346: f32 = v28 * v61;
            let v347: f32 = v41 * v346;
            let v348: f32 = v345 - v347;
            let v349: f32 = v344 + v348;
            let v350: f32 = v69 * v314;
            let v351: f32 = v72 * v271;
            let v352: f32 = v350 + v351;
            let v353: f32 = v349 - v352;
            let v354: f32 = v325 * v189;
            let v355: f32 = v36 * v327;
            let v356: f32 = v354 - v355;
            let v357: f32 = v69 * v337;
            let v358: f32 = v72 * v334;
            let v359: f32 = v357 - v358;
            let v360: f32 = v356 + v359;
            let v361: f32 = v56 * v360;
            let v362: f32 = v353 - v361;
            let v363: f32 = v30 * v362;
            let v364: f32 = v343 + v363;
            let v365: f32 = v25 + v364;
            let v366: f32 = v325 * v65;
            let v367: f32 = v49 * v39;
            let v368: f32 = v36 * v329;
            let v369: f32 = v367 + v368;
            let v370: f32 = v366 + v369;
            let v371: f32 = v322 - v370;
            let v372: f32 = v50 * v371;
            let v373: f32 = v365 - v372;
            let v374: f32 = 8.393_f32;
            let v375: f32 = v374 * v179;
            let v376: f32 = v16 * v20;
            let v377: f32 = v20 * v376;
            let v378: f32 = v16 * v6;
            let v379: f32 = v6 * v378;
            let v380: f32 = v377 + v379;
            let v381: f32 = v375 - v380;
            let v382: f32 = v27 * v340;
            let v383: f32 = v30 * v360;
            let v384: f32 = v382 - v383;
            let v385: f32 = v381 + v384;
            let v386: f32 = v17 * v385;
            let v387: f32 = v373 + v386;
            let v388: f32 = v1 * v387;
            let v389: f32 = v2 * v20;
            let v390: f32 = v6 * v389;
            let v391: f32 = v20 * v9;
            let v392: f32 = v390 - v391;
            let v393: f32 = v11 * v31;
            let v394: f32 = v392 - v393;
            let v395: f32 = v27 * v362;
            let v396: f32 = v30 * v342;
            let v397: f32 = v395 - v396;
            let v398: f32 = v394 + v397;
            let v399: f32 = v374 * v172;
            let v400: f32 = v5 * v376;
            let v401: f32 = v399 + v400;
            let v402: f32 = v27 * v360;
            let v403: f32 = v30 * v340;
            let v404: f32 = v402 + v403;
            let v405: f32 = v401 + v404;
            let v406: f32 = v17 * v405;
            let v407: f32 = v398 - v406;
            let v408: f32 = v3 * v407;
            let v409: f32 = v388 + v408;
            let v410: f32 = -v409;
            let v411: f32 = v5 * v389;
            let v412: f32 = v20 * v12;
            let v413: f32 = v411 - v412;
            let v414: f32 = v16 * v172;
            let v415: f32 = v413 + v414;
            let v416: f32 = v61 * v45;
            let v417: f32 = v36 * v346;
            let v418: f32 = v416 - v417;
            let v419: f32 = v49 * v189;
            let v420: f32 = v418 + v419;
            let v421: f32 = v121 * v91;
            let v422: f32 = v82 * v273;
            let v423: f32 = v421 - v422;
            let v424: f32 = v98 * v290;
            let v425: f32 = v96 * v304;
            let v426: f32 = v424 + v425;
            let v427: f32 = v423 + v426;
            let v428: f32 = v420 + v427;
            let v429: f32 = v190 * v359;
            let v430: f32 = v428 + v429;
            let v431: f32 = v415 + v430;
            let v432: f32 = v50 * v404;
            let v433: f32 = v431 + v432;
            (v301, v410, v427, v430, v433)
        };
        [v410, v433, v430, v427, v162, v301]
    }
    /// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `gravity: [f32; 6]`: g(q), joint torques (N m) or forces (N) that hold the robot still
    ///
    /// Operation count: 24 floating-point operations, 6 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn gravity(q: &[f32; 6]) -> [f32; 6] {
        let v0: f32 = 0.0_f32;
        let v1: f32 = 0.17446825_f32;
        let v2: f32 = q[3];
        let (v9, v3): (f32, f32) = ::libm::sincosf(v2);
        let v4: f32 = v1 * v3;
        let v5: f32 = q[2];
        let (v12, v6): (f32, f32) = ::libm::sincosf(v5);
        let v7: f32 = v4 * v6;
        let v8: f32 = 15.683828_f32;
        let v10: f32 = v1 * v9;
        let v11: f32 = v8 - v10;
        let v13: f32 = v11 * v12;
        let v14: f32 = v7 + v13;
        let v15: f32 = q[1];
        let (v16, v25): (f32, f32) = ::libm::sincosf(v15);
        let v17: f32 = v14 * v16;
        let v18: f32 = -43.48697_f32;
        let v19: f32 = v4 * v12;
        let v20: f32 = v18 + v19;
        let v21: f32 = -15.683828_f32;
        let v22: f32 = v21 + v10;
        let v23: f32 = v22 * v6;
        let v24: f32 = v20 + v23;
        let v26: f32 = v24 * v25;
        let v27: f32 = v17 + v26;
        let v28: f32 = v19 + v23;
        let v29: f32 = v28 * v25;
        let v30: f32 = v29 + v17;
        let v31: f32 = v10 * v6;
        let v32: f32 = v31 + v19;
        let v33: f32 = v32 * v25;
        let v34: f32 = v10 * v12;
        let v35: f32 = v7 - v34;
        let v36: f32 = v35 * v16;
        let v37: f32 = v33 + v36;
        [v0, v27, v30, v37, v0, v0]
    }
    /// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 6]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[f32; 6]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `tau: [f32; 6]`: joint torques (N m) or forces (N), no external wrench
    ///
    /// Operation count: 425 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn inverse_dynamics(q: &[f32; 6], qd: &[f32; 6], qdd: &[f32; 6]) -> [f32; 6] {
        let (
            v2,
            v4,
            v5,
            v6,
            v8,
            v9,
            v12,
            v14,
            v16,
            v17,
            v21,
            v22,
            v23,
            v25,
            v26,
            v30,
            v32,
            v33,
            v35,
            v38,
            v43,
            v46,
            v48,
            v49,
            v51,
            v52,
            v56,
            v57,
            v59,
            v63,
            v64,
            v68,
            v69,
            v72,
            v74,
            v76,
            v77,
            v79,
            v84,
            v89,
            v92,
            v94,
            v95,
            v96,
            v98,
            v101,
            v103,
            v106,
            v108,
            v110,
            v113,
            v114,
            v116,
            v119,
            v121,
            v122,
            v123,
            v124,
            v126,
            v128,
            v135,
            v137,
            v140,
            v142,
            v147,
            v149,
            v150,
            v153,
            v154,
            v155,
            v156,
            v157,
        ) = {
            let v0: f32 = 0.00666_f32;
            let v1: f32 = qdd[0];
            let v2: f32 = v0 * v1;
            let v3: f32 = q[1];
            let (v6, v4): (f32, f32) = ::libm::sincosf(v3);
            let v5: f32 = 0.8849019_f32;
            let v7: f32 = qd[0];
            let v8: f32 = v6 * v7;
            let v9: f32 = qd[1];
            let v10: f32 = v8 * v9;
            let v11: f32 = v4 * v1;
            let v12: f32 = v10 - v11;
            let v13: f32 = v5 * v12;
            let v14: f32 = v5 * v9;
            let v15: f32 = v8 * v14;
            let v16: f32 = 0.0151074_f32;
            let v17: f32 = v16 * v8;
            let v18: f32 = v9 * v17;
            let v19: f32 = v15 - v18;
            let v20: f32 = v13 + v19;
            let v21: f32 = 2.35004_f32;
            let v22: f32 = 0.13585_f32;
            let v23: f32 = v22 * v8;
            let v24: f32 = v8 * v23;
            let v25: f32 = v4 * v7;
            let v26: f32 = v22 * v25;
            let v27: f32 = v25 * v26;
            let v28: f32 = v24 + v27;
            let v29: f32 = v21 * v28;
            let v30: f32 = v20 + v29;
            let v31: f32 = q[2];
            let (v35, v32): (f32, f32) = ::libm::sincosf(v31);
            let v33: f32 = 0.19163081_f32;
            let v34: f32 = v32 * v12;
            let v36: f32 = v6 * v1;
            let v37: f32 = v25 * v9;
            let v38: f32 = v36 + v37;
            let v39: f32 = v35 * v38;
            let v40: f32 = v34 + v39;
            let v41: f32 = v35 * v25;
            let v42: f32 = v32 * v8;
            let v43: f32 = v41 + v42;
            let v44: f32 = qd[2];
            let v45: f32 = v43 * v44;
            let v46: f32 = v40 + v45;
            let v47: f32 = v33 * v46;
            let v48: f32 = v9 + v44;
            let v49: f32 = v33 * v48;
            let v50: f32 = v43 * v49;
            let v51: f32 = 0.004095_f32;
            let v52: f32 = v51 * v43;
            let v53: f32 = v48 * v52;
            let v54: f32 = v50 - v53;
            let v55: f32 = v47 + v54;
            let v56: f32 = 0.56875_f32;
            let v57: f32 = 0.425_f32;
            let v58: f32 = v57 * v12;
            let v59: f32 = v57 * v9;
            let v60: f32 = v8 * v59;
            let v61: f32 = v58 + v60;
            let v62: f32 = v28 + v61;
            let v63: f32 = -0.1197_f32;
            let v64: f32 = v63 * v43;
            let v65: f32 = v43 * v64;
            let v66: f32 = v35 * v8;
            let v67: f32 = v32 * v25;
            let v68: f32 = v66 - v67;
            let v69: f32 = v63 * v68;
            let v70: f32 = v68 * v69;
            let v71: f32 = v65 + v70;
            let v72: f32 = v62 + v71;
            let v73: f32 = v56 * v72;
            let v74: f32 = v55 + v73;
            let v75: f32 = q[3];
            let (v79, v76): (f32, f32) = ::libm::sincosf(v75);
            let v77: f32 = 0.21942_f32;
            let v78: f32 = v76 * v46;
            let v80: f32 = v35 * v12;
            let v81: f32 = v32 * v38;
            let v82: f32 = v80 - v81;
            let v83: f32 = v68 * v44;
            let v84: f32 = v82 + v83;
            let v85: f32 = v79 * v84;
            let v86: f32 = v78 - v85;
            let v87: f32 = v76 * v43;
            let v88: f32 = v79 * v68;
            let v89: f32 = v87 - v88;
            let v90: f32 = qd[3];
            let v91: f32 = v89 * v90;
            let v92: f32 = v86 + v91;
            let v93: f32 = v77 * v92;
            let v94: f32 = 0.11117276_f32;
            let v95: f32 = v48 + v90;
            let v96: f32 = v94 * v95;
            let v97: f32 = v89 * v96;
            let v98: f32 = v94 * v89;
            let v99: f32 = v95 * v98;
            let v100: f32 = v97 - v99;
            let v101: f32 = v93 + v100;
            let v102: f32 = qdd[4];
            let v103: f32 = v92 + v102;
            let v104: f32 = v77 * v103;
            let v105: f32 = q[4];
            let (v108, v106): (f32, f32) = ::libm::sincosf(v105);
            let v107: f32 = v106 * v89;
            let v109: f32 = v108 * v95;
            let v110: f32 = v107 + v109;
            let v111: f32 = v106 * v95;
            let v112: f32 = v108 * v89;
            let v113: f32 = v111 - v112;
            let v114: f32 = v94 * v113;
            let v115: f32 = v110 * v114;
            let v116: f32 = v94 * v110;
            let v117: f32 = v113 * v116;
            let v118: f32 = v115 - v117;
            let v119: f32 = v104 + v118;
            let v120: f32 = q[5];
            let (v123, v121): (f32, f32) = ::libm::sincosf(v120);
            let v122: f32 = 0.033822_f32;
            let v124: f32 = qdd[1];
            let v125: f32 = qdd[2];
            let v126: f32 = v124 + v125;
            let v127: f32 = qdd[3];
            let v128: f32 = v126 + v127;
            let v129: f32 = v108 * v128;
            let v130: f32 = v79 * v46;
            let v131: f32 = v76 * v84;
            let v132: f32 = v130 + v131;
            let v133: f32 = v76 * v68;
            let v134: f32 = v79 * v43;
            let v135: f32 = v133 + v134;
            let v136: f32 = v135 * v90;
            let v137: f32 = v132 + v136;
            let v138: f32 = v106 * v137;
            let v139: f32 = v129 - v138;
            let v140: f32 = qd[4];
            let v141: f32 = v113 * v140;
            let v142: f32 = v139 + v141;
            let v143: f32 = v123 * v142;
            let v144: f32 = v121 * v103;
            let v145: f32 = v143 + v144;
            let v146: f32 = v121 * v110;
            let v147: f32 = v135 + v140;
            let v148: f32 = v123 * v147;
            let v149: f32 = v146 - v148;
            let v150: f32 = qd[5];
            let v151: f32 = v149 * v150;
            let v152: f32 = v145 + v151;
            let v153: f32 = v122 * v152;
            let v154: f32 = 0.017136473_f32;
            let v155: f32 = v113 + v150;
            let v156: f32 = v154 * v155;
            let v157: f32 = v149 * v156;
            (
                v2,
                v4,
                v5,
                v6,
                v8,
                v9,
                v12,
                v14,
                v16,
                v17,
                v21,
                v22,
                v23,
                v25,
                v26,
                v30,
                v32,
                v33,
                v35,
                v38,
                v43,
                v46,
                v48,
                v49,
                v51,
                v52,
                v56,
                v57,
                v59,
                v63,
                v64,
                v68,
                v69,
                v72,
                v74,
                v76,
                v77,
                v79,
                v84,
                v89,
                v92,
                v94,
                v95,
                v96,
                v98,
                v101,
                v103,
                v106,
                v108,
                v110,
                v113,
                v114,
                v116,
                v119,
                v121,
                v122,
                v123,
                v124,
                v126,
                v128,
                v135,
                v137,
                v140,
                v142,
                v147,
                v149,
                v150,
                v153,
                v154,
                v155,
                v156,
                v157,
            )
        };
        let (
            v158,
            v168,
            v172,
            v179,
            v181,
            v182,
            v192,
            v203,
            v213,
            v214,
            v227,
            v234,
            v240,
            v250,
            v255,
            v264,
            v268,
            v276,
            v281,
            v283,
            v284,
            v293,
            v295,
            v297,
            v299,
            v300,
            v301,
            v306,
            v308,
            v312,
            v315,
        ) = {
            let v158: f32 = v154 * v149;
            let v159: f32 = v155 * v158;
            let v160: f32 = v157 - v159;
            let v161: f32 = v153 + v160;
            let v162: f32 = v121 * v161;
            let v163: f32 = v121 * v142;
            let v164: f32 = v123 * v103;
            let v165: f32 = v163 - v164;
            let v166: f32 = v123 * v110;
            let v167: f32 = v121 * v147;
            let v168: f32 = v166 + v167;
            let v169: f32 = v168 * v150;
            let v170: f32 = v165 - v169;
            let v171: f32 = v154 * v170;
            let v172: f32 = v122 * v168;
            let v173: f32 = v155 * v172;
            let v174: f32 = v168 * v156;
            let v175: f32 = v173 - v174;
            let v176: f32 = v171 + v175;
            let v177: f32 = v123 * v176;
            let v178: f32 = v162 - v177;
            let v179: f32 = v119 + v178;
            let v180: f32 = v101 + v179;
            let v181: f32 = 0.093_f32;
            let v182: f32 = 1.219_f32;
            let v183: f32 = v181 * v89;
            let v184: f32 = v95 * v183;
            let v185: f32 = v181 * v92;
            let v186: f32 = v184 - v185;
            let v187: f32 = v22 * v38;
            let v188: f32 = v9 * v26;
            let v189: f32 = v187 - v188;
            let v190: f32 = 9.81_f32;
            let v191: f32 = v190 * v4;
            let v192: f32 = v189 - v191;
            let v193: f32 = v57 * v124;
            let v194: f32 = v57 * v25;
            let v195: f32 = v8 * v194;
            let v196: f32 = v193 + v195;
            let v197: f32 = v192 + v196;
            let v198: f32 = v32 * v197;
            let v199: f32 = v22 * v12;
            let v200: f32 = v9 * v23;
            let v201: f32 = v199 - v200;
            let v202: f32 = v190 * v6;
            let v203: f32 = v201 - v202;
            let v204: f32 = v25 * v194;
            let v205: f32 = v9 * v59;
            let v206: f32 = v204 + v205;
            let v207: f32 = v203 - v206;
            let v208: f32 = v35 * v207;
            let v209: f32 = v198 - v208;
            let v210: f32 = v48 * v69;
            let v211: f32 = v63 * v84;
            let v212: f32 = v210 - v211;
            let v213: f32 = v209 + v212;
            let v214: f32 = 0.39225_f32;
            let v215: f32 = v214 * v126;
            let v216: f32 = v214 * v68;
            let v217: f32 = v43 * v216;
            let v218: f32 = v215 - v217;
            let v219: f32 = v213 + v218;
            let v220: f32 = v79 * v219;
            let v221: f32 = v35 * v197;
            let v222: f32 = v32 * v207;
            let v223: f32 = v221 + v222;
            let v224: f32 = v63 * v46;
            let v225: f32 = v48 * v64;
            let v226: f32 = v224 - v225;
            let v227: f32 = v223 + v226;
            let v228: f32 = v68 * v216;
            let v229: f32 = v214 * v48;
            let v230: f32 = v48 * v229;
            let v231: f32 = v228 + v230;
            let v232: f32 = v227 - v231;
            let v233: f32 = v76 * v232;
            let v234: f32 = v220 + v233;
            let v235: f32 = v186 - v234;
            let v236: f32 = v106 * v235;
            let v237: f32 = v214 * v46;
            let v238: f32 = v43 * v229;
            let v239: f32 = v237 + v238;
            let v240: f32 = v72 + v239;
            let v241: f32 = v181 * v135;
            let v242: f32 = v135 * v241;
            let v243: f32 = v89 * v183;
            let v244: f32 = v242 + v243;
            let v245: f32 = v240 + v244;
            let v246: f32 = v108 * v245;
            let v247: f32 = v236 - v246;
            let v248: f32 = v182 * v247;
            let v249: f32 = 0.1879_f32;
            let v250: f32 = 0.09465_f32;
            let v251: f32 = v108 * v137;
            let v252: f32 = v106 * v128;
            let v253: f32 = v251 + v252;
            let v254: f32 = v110 * v140;
            let v255: f32 = v253 - v254;
            let v256: f32 = v250 * v255;
            let v257: f32 = v250 * v110;
            let v258: f32 = v147 * v257;
            let v259: f32 = v256 + v258;
            let v260: f32 = v247 + v259;
            let v261: f32 = v121 * v260;
            let v262: f32 = v76 * v219;
            let v263: f32 = v79 * v232;
            let v264: f32 = v262 - v263;
            let v265: f32 = v95 * v241;
            let v266: f32 = v181 * v137;
            let v267: f32 = v265 - v266;
            let v268: f32 = v264 + v267;
            let v269: f32 = v110 * v257;
            let v270: f32 = v250 * v113;
            let v271: f32 = v113 * v270;
            let v272: f32 = v269 + v271;
            let v273: f32 = v268 - v272;
            let v274: f32 = v123 * v273;
            let v275: f32 = v261 - v274;
            let v276: f32 = v249 * v275;
            let v277: f32 = v121 * v276;
            let v278: f32 = v123 * v260;
            let v279: f32 = v121 * v273;
            let v280: f32 = v278 + v279;
            let v281: f32 = v249 * v280;
            let v282: f32 = v123 * v281;
            let v283: f32 = v277 + v282;
            let v284: f32 = v248 + v283;
            let v285: f32 = v106 * v284;
            let v286: f32 = v147 * v270;
            let v287: f32 = v250 * v142;
            let v288: f32 = v286 - v287;
            let v289: f32 = v108 * v235;
            let v290: f32 = v106 * v245;
            let v291: f32 = v289 + v290;
            let v292: f32 = v288 - v291;
            let v293: f32 = v249 * v292;
            let v294: f32 = v182 * v291;
            let v295: f32 = v293 - v294;
            let v296: f32 = v108 * v295;
            let v297: f32 = v285 - v296;
            let v298: f32 = v181 * v297;
            let v299: f32 = v180 - v298;
            let v300: f32 = v76 * v299;
            let v301: f32 = v77 * v135;
            let v302: f32 = v95 * v301;
            let v303: f32 = v135 * v96;
            let v304: f32 = v302 - v303;
            let v305: f32 = v94 * v137;
            let v306: f32 = v304 - v305;
            let v307: f32 = v94 * v142;
            let v308: f32 = v77 * v147;
            let v309: f32 = v113 * v308;
            let v310: f32 = v147 * v114;
            let v311: f32 = v309 - v310;
            let v312: f32 = v307 + v311;
            let v313: f32 = v121 * v176;
            let v314: f32 = v123 * v161;
            let v315: f32 = v313 + v314;
            (
                v158,
                v168,
                v172,
                v179,
                v181,
                v182,
                v192,
                v203,
                v213,
                v214,
                v227,
                v234,
                v240,
                v250,
                v255,
                v264,
                v268,
                v276,
                v281,
                v283,
                v284,
                v293,
                v295,
                v297,
                v299,
                v300,
                v301,
                v306,
                v308,
                v312,
                v315,
            )
        };
        let (v331, v444, v467, v470, v473) = {
            let v316: f32 = v312 + v315;
            let v317: f32 = v250 * v293;
            let v318: f32 = v316 - v317;
            let v319: f32 = v106 * v318;
            let v320: f32 = v94 * v255;
            let v321: f32 = v147 * v116;
            let v322: f32 = v110 * v308;
            let v323: f32 = v321 - v322;
            let v324: f32 = v320 + v323;
            let v325: f32 = qdd[5];
            let v326: f32 = v255 + v325;
            let v327: f32 = v154 * v326;
            let v328: f32 = v168 * v158;
            let v329: f32 = v149 * v172;
            let v330: f32 = v328 - v329;
            let v331: f32 = v327 + v330;
            let v332: f32 = v324 + v331;
            let v333: f32 = v250 * v283;
            let v334: f32 = v332 + v333;
            let v335: f32 = v108 * v334;
            let v336: f32 = v319 - v335;
            let v337: f32 = v306 + v336;
            let v338: f32 = v182 * v268;
            let v339: f32 = v121 * v281;
            let v340: f32 = v123 * v276;
            let v341: f32 = v339 - v340;
            let v342: f32 = v338 + v341;
            let v343: f32 = v181 * v342;
            let v344: f32 = v337 + v343;
            let v345: f32 = v79 * v344;
            let v346: f32 = v300 - v345;
            let v347: f32 = v74 + v346;
            let v348: f32 = v108 * v284;
            let v349: f32 = v106 * v295;
            let v350: f32 = v348 + v349;
            let v351: f32 = v182 * v240;
            let v352: f32 = v350 - v351;
            let v353: f32 = v214 * v352;
            let v354: f32 = v347 - v353;
            let v355: f32 = 2.275_f32;
            let v356: f32 = v355 * v227;
            let v357: f32 = v56 * v68;
            let v358: f32 = v68 * v357;
            let v359: f32 = v56 * v48;
            let v360: f32 = v48 * v359;
            let v361: f32 = v358 + v360;
            let v362: f32 = v356 - v361;
            let v363: f32 = v182 * v234;
            let v364: f32 = v297 - v363;
            let v365: f32 = v76 * v364;
            let v366: f32 = v182 * v264;
            let v367: f32 = v366 + v342;
            let v368: f32 = v79 * v367;
            let v369: f32 = v365 + v368;
            let v370: f32 = v362 - v369;
            let v371: f32 = v63 * v370;
            let v372: f32 = v354 + v371;
            let v373: f32 = v32 * v372;
            let v374: f32 = v51 * v84;
            let v375: f32 = v68 * v49;
            let v376: f32 = v33 * v68;
            let v377: f32 = v48 * v376;
            let v378: f32 = v375 - v377;
            let v379: f32 = v374 + v378;
            let v380: f32 = v76 * v344;
            let v381: f32 = v79 * v299;
            let v382: f32 = v380 + v381;
            let v383: f32 = v379 - v382;
            let v384: f32 = v355 * v213;
            let v385: f32 = v56 * v126;
            let v386: f32 = v43 * v357;
            let v387: f32 = v385 - v386;
            let v388: f32 = v384 + v387;
            let v389: f32 = v76 * v367;
            let v390: f32 = v79 * v364;
            let v391: f32 = v389 - v390;
            let v392: f32 = v388 + v391;
            let v393: f32 = v63 * v392;
            let v394: f32 = v383 - v393;
            let v395: f32 = v35 * v394;
            let v396: f32 = v373 + v395;
            let v397: f32 = v30 + v396;
            let v398: f32 = v355 * v72;
            let v399: f32 = v56 * v46;
            let v400: f32 = v43 * v359;
            let v401: f32 = v399 + v400;
            let v402: f32 = v398 + v401;
            let v403: f32 = v352 - v402;
            let v404: f32 = v57 * v403;
            let v405: f32 = v397 - v404;
            let v406: f32 = 8.393_f32;
            let v407: f32 = v406 * v203;
            let v408: f32 = v21 * v25;
            let v409: f32 = v25 * v408;
            let v410: f32 = v21 * v9;
            let v411: f32 = v9 * v410;
            let v412: f32 = v409 + v411;
            let v413: f32 = v407 - v412;
            let v414: f32 = v32 * v370;
            let v415: f32 = v35 * v392;
            let v416: f32 = v414 - v415;
            let v417: f32 = v413 + v416;
            let v418: f32 = v22 * v417;
            let v419: f32 = v405 + v418;
            let v420: f32 = v4 * v419;
            let v421: f32 = v5 * v25;
            let v422: f32 = v9 * v421;
            let v423: f32 = v25 * v14;
            let v424: f32 = v422 - v423;
            let v425: f32 = v16 * v38;
            let v426: f32 = v424 - v425;
            let v427: f32 = v32 * v394;
            let v428: f32 = v35 * v372;
            let v429: f32 = v427 - v428;
            let v430: f32 = v426 + v429;
            let v431: f32 = v406 * v192;
            let v432: f32 = v21 * v124;
            let v433: f32 = v8 * v408;
            let v434: f32 = v432 + v433;
            let v435: f32 = v431 + v434;
            let v436: f32 = v32 * v392;
            let v437: f32 = v35 * v370;
            let v438: f32 = v436 + v437;
            let v439: f32 = v435 + v438;
            let v440: f32 = v22 * v439;
            let v441: f32 = v430 - v440;
            let v442: f32 = v6 * v441;
            let v443: f32 = v420 + v442;
            let v444: f32 = v2 - v443;
            let v445: f32 = v5 * v124;
            let v446: f32 = v8 * v421;
            let v447: f32 = v25 * v17;
            let v448: f32 = v446 - v447;
            let v449: f32 = v445 + v448;
            let v450: f32 = v21 * v192;
            let v451: f32 = v449 + v450;
            let v452: f32 = v33 * v126;
            let v453: f32 = v68 * v52;
            let v454: f32 = v43 * v376;
            let v455: f32 = v453 - v454;
            let v456: f32 = v452 + v455;
            let v457: f32 = v56 * v213;
            let v458: f32 = v456 + v457;
            let v459: f32 = v94 * v128;
            let v460: f32 = v135 * v98;
            let v461: f32 = v89 * v301;
            let v462: f32 = v460 - v461;
            let v463: f32 = v459 + v462;
            let v464: f32 = v108 * v318;
            let v465: f32 = v106 * v334;
            let v466: f32 = v464 + v465;
            let v467: f32 = v463 + v466;
            let v468: f32 = v458 + v467;
            let v469: f32 = v214 * v391;
            let v470: f32 = v468 + v469;
            let v471: f32 = v451 + v470;
            let v472: f32 = v57 * v438;
            let v473: f32 = v471 + v472;
            (v331, v444, v467, v470, v473)
        };
        [v444, v473, v470, v467, v179, v331]
    }
    /// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 6]`: joint velocities qd (rad/s or m/s)
    /// - `tau: &[f32; 6]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
    ///
    /// # Output
    ///
    /// `qdd: [f32; 6]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// Operation count: 751 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn forward_dynamics(q: &[f32; 6], qd: &[f32; 6], tau: &[f32; 6]) -> [f32; 6] {
        let (
            v0,
            v2,
            v3,
            v4,
            v6,
            v7,
            v8,
            v10,
            v12,
            v13,
            v17,
            v18,
            v19,
            v21,
            v22,
            v26,
            v28,
            v29,
            v31,
            v32,
            v37,
            v40,
            v42,
            v43,
            v45,
            v46,
            v50,
            v51,
            v53,
            v57,
            v58,
            v62,
            v63,
            v66,
            v68,
            v70,
            v71,
            v73,
            v78,
            v83,
            v86,
            v88,
            v89,
            v90,
            v92,
            v95,
            v97,
            v99,
            v101,
            v104,
            v105,
            v107,
            v112,
            v113,
            v114,
            v115,
            v122,
            v124,
            v126,
            v131,
            v133,
            v138,
            v142,
            v145,
            v152,
            v156,
            v160,
            v163,
        ) = {
            let v0: f32 = tau[0];
            let v1: f32 = q[1];
            let (v4, v2): (f32, f32) = ::libm::sincosf(v1);
            let v3: f32 = 0.8849019_f32;
            let v5: f32 = qd[0];
            let v6: f32 = v4 * v5;
            let v7: f32 = qd[1];
            let v8: f32 = v6 * v7;
            let v9: f32 = v3 * v8;
            let v10: f32 = v3 * v7;
            let v11: f32 = v6 * v10;
            let v12: f32 = 0.0151074_f32;
            let v13: f32 = v12 * v6;
            let v14: f32 = v7 * v13;
            let v15: f32 = v11 - v14;
            let v16: f32 = v9 + v15;
            let v17: f32 = 2.35004_f32;
            let v18: f32 = 0.13585_f32;
            let v19: f32 = v18 * v6;
            let v20: f32 = v6 * v19;
            let v21: f32 = v2 * v5;
            let v22: f32 = v18 * v21;
            let v23: f32 = v21 * v22;
            let v24: f32 = v20 + v23;
            let v25: f32 = v17 * v24;
            let v26: f32 = v16 + v25;
            let v27: f32 = q[2];
            let (v31, v28): (f32, f32) = ::libm::sincosf(v27);
            let v29: f32 = 0.19163081_f32;
            let v30: f32 = v28 * v8;
            let v32: f32 = v21 * v7;
            let v33: f32 = v31 * v32;
            let v34: f32 = v30 + v33;
            let v35: f32 = v31 * v21;
            let v36: f32 = v28 * v6;
            let v37: f32 = v35 + v36;
            let v38: f32 = qd[2];
            let v39: f32 = v37 * v38;
            let v40: f32 = v34 + v39;
            let v41: f32 = v29 * v40;
            let v42: f32 = v7 + v38;
            let v43: f32 = v29 * v42;
            let v44: f32 = v37 * v43;
            let v45: f32 = 0.004095_f32;
            let v46: f32 = v45 * v37;
            let v47: f32 = v42 * v46;
            let v48: f32 = v44 - v47;
            let v49: f32 = v41 + v48;
            let v50: f32 = 0.56875_f32;
            let v51: f32 = 0.425_f32;
            let v52: f32 = v51 * v8;
            let v53: f32 = v51 * v7;
            let v54: f32 = v6 * v53;
            let v55: f32 = v52 + v54;
            let v56: f32 = v24 + v55;
            let v57: f32 = -0.1197_f32;
            let v58: f32 = v57 * v37;
            let v59: f32 = v37 * v58;
            let v60: f32 = v31 * v6;
            let v61: f32 = v28 * v21;
            let v62: f32 = v60 - v61;
            let v63: f32 = v57 * v62;
            let v64: f32 = v62 * v63;
            let v65: f32 = v59 + v64;
            let v66: f32 = v56 + v65;
            let v67: f32 = v50 * v66;
            let v68: f32 = v49 + v67;
            let v69: f32 = q[3];
            let (v73, v70): (f32, f32) = ::libm::sincosf(v69);
            let v71: f32 = 0.21942_f32;
            let v72: f32 = v70 * v40;
            let v74: f32 = v31 * v8;
            let v75: f32 = v28 * v32;
            let v76: f32 = v74 - v75;
            let v77: f32 = v62 * v38;
            let v78: f32 = v76 + v77;
            let v79: f32 = v73 * v78;
            let v80: f32 = v72 - v79;
            let v81: f32 = v70 * v37;
            let v82: f32 = v73 * v62;
            let v83: f32 = v81 - v82;
            let v84: f32 = qd[3];
            let v85: f32 = v83 * v84;
            let v86: f32 = v80 + v85;
            let v87: f32 = v71 * v86;
            let v88: f32 = 0.11117276_f32;
            let v89: f32 = v42 + v84;
            let v90: f32 = v88 * v89;
            let v91: f32 = v83 * v90;
            let v92: f32 = v88 * v83;
            let v93: f32 = v89 * v92;
            let v94: f32 = v91 - v93;
            let v95: f32 = v87 + v94;
            let v96: f32 = q[4];
            let (v99, v97): (f32, f32) = ::libm::sincosf(v96);
            let v98: f32 = v97 * v83;
            let v100: f32 = v99 * v89;
            let v101: f32 = v98 + v100;
            let v102: f32 = v97 * v89;
            let v103: f32 = v99 * v83;
            let v104: f32 = v102 - v103;
            let v105: f32 = v88 * v104;
            let v106: f32 = v101 * v105;
            let v107: f32 = v88 * v101;
            let v108: f32 = v104 * v107;
            let v109: f32 = v106 - v108;
            let v110: f32 = v87 + v109;
            let v111: f32 = q[5];
            let (v114, v112): (f32, f32) = ::libm::sincosf(v111);
            let v113: f32 = 0.033822_f32;
            let v115: f32 = qd[4];
            let v116: f32 = v104 * v115;
            let v117: f32 = v73 * v40;
            let v118: f32 = v70 * v78;
            let v119: f32 = v117 + v118;
            let v120: f32 = v70 * v62;
            let v121: f32 = v73 * v37;
            let v122: f32 = v120 + v121;
            let v123: f32 = v122 * v84;
            let v124: f32 = v119 + v123;
            let v125: f32 = v97 * v124;
            let v126: f32 = v116 - v125;
            let v127: f32 = v114 * v126;
            let v128: f32 = v112 * v86;
            let v129: f32 = v127 + v128;
            let v130: f32 = v112 * v101;
            let v131: f32 = v122 + v115;
            let v132: f32 = v114 * v131;
            let v133: f32 = v130 - v132;
            let v134: f32 = qd[5];
            let v135: f32 = v133 * v134;
            let v136: f32 = v129 + v135;
            let v137: f32 = v113 * v136;
            let v138: f32 = 0.017136473_f32;
            let v139: f32 = v104 + v134;
            let v140: f32 = v138 * v139;
            let v141: f32 = v133 * v140;
            let v142: f32 = v138 * v133;
            let v143: f32 = v139 * v142;
            let v144: f32 = v141 - v143;
            let v145: f32 = v137 + v144;
            let v146: f32 = v112 * v145;
            let v147: f32 = v112 * v126;
            let v148: f32 = v114 * v86;
            let v149: f32 = v147 - v148;
            let v150: f32 = v114 * v101;
            let v151: f32 = v112 * v131;
            let v152: f32 = v150 + v151;
            let v153: f32 = v152 * v134;
            let v154: f32 = v149 - v153;
            let v155: f32 = v138 * v154;
            let v156: f32 = v113 * v152;
            let v157: f32 = v139 * v156;
            let v158: f32 = v152 * v140;
            let v159: f32 = v157 - v158;
            let v160: f32 = v155 + v159;
            let v161: f32 = v114 * v160;
            let v162: f32 = v146 - v161;
            let v163: f32 = v110 + v162;
            (
                v0,
                v2,
                v3,
                v4,
                v6,
                v7,
                v8,
                v10,
                v12,
                v13,
                v17,
                v18,
                v19,
                v21,
                v22,
                v26,
                v28,
                v29,
                v31,
                v32,
                v37,
                v40,
                v42,
                v43,
                v45,
                v46,
                v50,
                v51,
                v53,
                v57,
                v58,
                v62,
                v63,
                v66,
                v68,
                v70,
                v71,
                v73,
                v78,
                v83,
                v86,
                v88,
                v89,
                v90,
                v92,
                v95,
                v97,
                v99,
                v101,
                v104,
                v105,
                v107,
                v112,
                v113,
                v114,
                v115,
                v122,
                v124,
                v126,
                v131,
                v133,
                v138,
                v142,
                v145,
                v152,
                v156,
                v160,
                v163,
            )
        };
        let (
            v166,
            v176,
            v185,
            v195,
            v196,
            v207,
            v214,
            v242,
            v275,
            v277,
            v279,
            v296,
            v307,
            v310,
            v318,
            v320,
            v323,
            v326,
            v327,
        ) = {
            let v164: f32 = v95 + v163;
            let v165: f32 = 0.093_f32;
            let v166: f32 = 1.219_f32;
            let v167: f32 = v165 * v83;
            let v168: f32 = v89 * v167;
            let v169: f32 = v165 * v86;
            let v170: f32 = v168 - v169;
            let v171: f32 = v18 * v32;
            let v172: f32 = v7 * v22;
            let v173: f32 = v171 - v172;
            let v174: f32 = 9.81_f32;
            let v175: f32 = v174 * v2;
            let v176: f32 = v173 - v175;
            let v177: f32 = v51 * v21;
            let v178: f32 = v6 * v177;
            let v179: f32 = v176 + v178;
            let v180: f32 = v28 * v179;
            let v181: f32 = v18 * v8;
            let v182: f32 = v7 * v19;
            let v183: f32 = v181 - v182;
            let v184: f32 = v174 * v4;
            let v185: f32 = v183 - v184;
            let v186: f32 = v21 * v177;
            let v187: f32 = v7 * v53;
            let v188: f32 = v186 + v187;
            let v189: f32 = v185 - v188;
            let v190: f32 = v31 * v189;
            let v191: f32 = v180 - v190;
            let v192: f32 = v42 * v63;
            let v193: f32 = v57 * v78;
            let v194: f32 = v192 - v193;
            let v195: f32 = v191 + v194;
            let v196: f32 = 0.39225_f32;
            let v197: f32 = v196 * v62;
            let v198: f32 = v37 * v197;
            let v199: f32 = v195 - v198;
            let v200: f32 = v73 * v199;
            let v201: f32 = v31 * v179;
            let v202: f32 = v28 * v189;
            let v203: f32 = v201 + v202;
            let v204: f32 = v57 * v40;
            let v205: f32 = v42 * v58;
            let v206: f32 = v204 - v205;
            let v207: f32 = v203 + v206;
            let v208: f32 = v62 * v197;
            let v209: f32 = v196 * v42;
            let v210: f32 = v42 * v209;
            let v211: f32 = v208 + v210;
            let v212: f32 = v207 - v211;
            let v213: f32 = v70 * v212;
            let v214: f32 = v200 + v213;
            let v215: f32 = v170 - v214;
            let v216: f32 = v97 * v215;
            let v217: f32 = v196 * v40;
            let v218: f32 = v37 * v209;
            let v219: f32 = v217 + v218;
            let v220: f32 = v66 + v219;
            let v221: f32 = v165 * v122;
            let v222: f32 = v122 * v221;
            let v223: f32 = v83 * v167;
            let v224: f32 = v222 + v223;
            let v225: f32 = v220 + v224;
            let v226: f32 = v99 * v225;
            let v227: f32 = v216 - v226;
            let v228: f32 = v166 * v227;
            let v229: f32 = 0.1879_f32;
            let v230: f32 = 0.09465_f32;
            let v231: f32 = v99 * v124;
            let v232: f32 = v101 * v115;
            let v233: f32 = v231 - v232;
            let v234: f32 = v230 * v233;
            let v235: f32 = v230 * v101;
            let v236: f32 = v131 * v235;
            let v237: f32 = v234 + v236;
            let v238: f32 = v227 + v237;
            let v239: f32 = v112 * v238;
            let v240: f32 = v70 * v199;
            let v241: f32 = v73 * v212;
            let v242: f32 = v240 - v241;
            let v243: f32 = v89 * v221;
            let v244: f32 = v165 * v124;
            let v245: f32 = v243 - v244;
            let v246: f32 = v242 + v245;
            let v247: f32 = v101 * v235;
            let v248: f32 = v230 * v104;
            let v249: f32 = v104 * v248;
            let v250: f32 = v247 + v249;
            let v251: f32 = v246 - v250;
            let v252: f32 = v114 * v251;
            let v253: f32 = v239 - v252;
            let v254: f32 = v229 * v253;
            let v255: f32 = v112 * v254;
            let v256: f32 = v114 * v238;
            let v257: f32 = v112 * v251;
            let v258: f32 = v256 + v257;
            let v259: f32 = v229 * v258;
            let v260: f32 = v114 * v259;
            let v261: f32 = v255 + v260;
            let v262: f32 = v228 + v261;
            let v263: f32 = v97 * v262;
            let v264: f32 = v131 * v248;
            let v265: f32 = v230 * v126;
            let v266: f32 = v264 - v265;
            let v267: f32 = v99 * v215;
            let v268: f32 = v97 * v225;
            let v269: f32 = v267 + v268;
            let v270: f32 = v266 - v269;
            let v271: f32 = v229 * v270;
            let v272: f32 = v166 * v269;
            let v273: f32 = v271 - v272;
            let v274: f32 = v99 * v273;
            let v275: f32 = v263 - v274;
            let v276: f32 = v165 * v275;
            let v277: f32 = v164 - v276;
            let v278: f32 = v70 * v277;
            let v279: f32 = v71 * v122;
            let v280: f32 = v89 * v279;
            let v281: f32 = v122 * v90;
            let v282: f32 = v280 - v281;
            let v283: f32 = v88 * v124;
            let v284: f32 = v282 - v283;
            let v285: f32 = v88 * v126;
            let v286: f32 = v71 * v131;
            let v287: f32 = v104 * v286;
            let v288: f32 = v131 * v105;
            let v289: f32 = v287 - v288;
            let v290: f32 = v285 + v289;
            let v291: f32 = v112 * v160;
            let v292: f32 = v114 * v145;
            let v293: f32 = v291 + v292;
            let v294: f32 = v290 + v293;
            let v295: f32 = v230 * v271;
            let v296: f32 = v294 - v295;
            let v297: f32 = v97 * v296;
            let v298: f32 = v88 * v233;
            let v299: f32 = v131 * v107;
            let v300: f32 = v101 * v286;
            let v301: f32 = v299 - v300;
            let v302: f32 = v298 + v301;
            let v303: f32 = v138 * v233;
            let v304: f32 = v152 * v142;
            let v305: f32 = v133 * v156;
            let v306: f32 = v304 - v305;
            let v307: f32 = v303 + v306;
            let v308: f32 = v302 + v307;
            let v309: f32 = v230 * v261;
            let v310: f32 = v308 + v309;
            let v311: f32 = v99 * v310;
            let v312: f32 = v297 - v311;
            let v313: f32 = v284 + v312;
            let v314: f32 = v166 * v246;
            let v315: f32 = v112 * v259;
            let v316: f32 = v114 * v254;
            let v317: f32 = v315 - v316;
            let v318: f32 = v314 + v317;
            let v319: f32 = v165 * v318;
            let v320: f32 = v313 + v319;
            let v321: f32 = v73 * v320;
            let v322: f32 = v278 - v321;
            let v323: f32 = v68 + v322;
            let v324: f32 = v99 * v262;
            let v325: f32 = v97 * v273;
            let v326: f32 = v324 + v325;
            let v327: f32 = v166 * v220;
            (
                v166,
                v176,
                v185,
                v195,
                v196,
                v207,
                v214,
                v242,
                v275,
                v277,
                v279,
                v296,
                v307,
                v310,
                v318,
                v320,
                v323,
                v326,
                v327,
            )
        };
        let (
            v352,
            v365,
            v395,
            v410,
            v417,
            v429,
            v430,
            v432,
            v440,
            v446,
            v448,
            v451,
            v461,
            v462,
            v464,
            v466,
            v467,
            v470,
            v480,
            v481,
            v483,
            v484,
            v488,
            v489,
            v490,
            v491,
        ) = {
            let v328: f32 = v326 - v327;
            let v329: f32 = v196 * v328;
            let v330: f32 = v323 - v329;
            let v331: f32 = 2.275_f32;
            let v332: f32 = v331 * v207;
            let v333: f32 = v50 * v62;
            let v334: f32 = v62 * v333;
            let v335: f32 = v50 * v42;
            let v336: f32 = v42 * v335;
            let v337: f32 = v334 + v336;
            let v338: f32 = v332 - v337;
            let v339: f32 = v166 * v214;
            let v340: f32 = v275 - v339;
            let v341: f32 = v70 * v340;
            let v342: f32 = v166 * v242;
            let v343: f32 = v342 + v318;
            let v344: f32 = v73 * v343;
            let v345: f32 = v341 + v344;
            let v346: f32 = v338 - v345;
            let v347: f32 = v57 * v346;
            let v348: f32 = v330 + v347;
            let v349: f32 = v28 * v348;
            let v350: f32 = v45 * v78;
            let v351: f32 = v62 * v43;
            let v352: f32 = v29 * v62;
            let v353: f32 = v42 * v352;
            let v354: f32 = v351 - v353;
            let v355: f32 = v350 + v354;
            let v356: f32 = v70 * v320;
            let v357: f32 = v73 * v277;
            let v358: f32 = v356 + v357;
            let v359: f32 = v355 - v358;
            let v360: f32 = v331 * v195;
            let v361: f32 = v37 * v333;
            let v362: f32 = v360 - v361;
            let v363: f32 = v70 * v343;
            let v364: f32 = v73 * v340;
            let v365: f32 = v363 - v364;
            let v366: f32 = v362 + v365;
            let v367: f32 = v57 * v366;
            let v368: f32 = v359 - v367;
            let v369: f32 = v31 * v368;
            let v370: f32 = v349 + v369;
            let v371: f32 = v26 + v370;
            let v372: f32 = v331 * v66;
            let v373: f32 = v50 * v40;
            let v374: f32 = v37 * v335;
            let v375: f32 = v373 + v374;
            let v376: f32 = v372 + v375;
            let v377: f32 = v328 - v376;
            let v378: f32 = v51 * v377;
            let v379: f32 = v371 - v378;
            let v380: f32 = 8.393_f32;
            let v381: f32 = v380 * v185;
            let v382: f32 = v17 * v21;
            let v383: f32 = v21 * v382;
            let v384: f32 = v17 * v7;
            let v385: f32 = v7 * v384;
            let v386: f32 = v383 + v385;
            let v387: f32 = v381 - v386;
            let v388: f32 = v28 * v346;
            let v389: f32 = v31 * v366;
            let v390: f32 = v388 - v389;
            let v391: f32 = v387 + v390;
            let v392: f32 = v18 * v391;
            let v393: f32 = v379 + v392;
            let v394: f32 = v2 * v393;
            let v395: f32 = v3 * v21;
            let v396: f32 = v7 * v395;
            let v397: f32 = v21 * v10;
            let v398: f32 = v396 - v397;
            let v399: f32 = v12 * v32;
            let v400: f32 = v398 - v399;
            let v401: f32 = v28 * v368;
            let v402: f32 = v31 * v348;
            let v403: f32 = v401 - v402;
            let v404: f32 = v400 + v403;
            let v405: f32 = v380 * v176;
            let v406: f32 = v6 * v382;
            let v407: f32 = v405 + v406;
            let v408: f32 = v28 * v366;
            let v409: f32 = v31 * v346;
            let v410: f32 = v408 + v409;
            let v411: f32 = v407 + v410;
            let v412: f32 = v18 * v411;
            let v413: f32 = v404 - v412;
            let v414: f32 = v4 * v413;
            let v415: f32 = v394 + v414;
            let v416: f32 = v0 + v415;
            let v417: f32 = 58.355064_f32;
            let v418: f32 = v138 * v99;
            let v419: f32 = v73 * v418;
            let v420: f32 = v28 * v419;
            let v421: f32 = v70 * v418;
            let v422: f32 = v31 * v421;
            let v423: f32 = v420 + v422;
            let v424: f32 = v2 * v423;
            let v425: f32 = v28 * v421;
            let v426: f32 = v31 * v419;
            let v427: f32 = v425 - v426;
            let v428: f32 = v4 * v427;
            let v429: f32 = v424 + v428;
            let v430: f32 = v417 * v429;
            let v431: f32 = tau[5];
            let v432: f32 = v431 - v307;
            let v433: f32 = v430 * v432;
            let v434: f32 = v416 + v433;
            let v435: f32 = v138 * v114;
            let v436: f32 = v435 * v114;
            let v437: f32 = v113 * v112;
            let v438: f32 = v437 * v112;
            let v439: f32 = v436 + v438;
            let v440: f32 = v71 + v439;
            let v441: f32 = v70 * v440;
            let v442: f32 = v113 * v114;
            let v443: f32 = v442 * v112;
            let v444: f32 = v138 * v112;
            let v445: f32 = v444 * v114;
            let v446: f32 = v443 - v445;
            let v447: f32 = v97 * v446;
            let v448: f32 = v73 * v447;
            let v449: f32 = v441 - v448;
            let v450: f32 = v31 * v449;
            let v451: f32 = v70 * v447;
            let v452: f32 = v73 * v440;
            let v453: f32 = v451 + v452;
            let v454: f32 = v28 * v453;
            let v455: f32 = v450 + v454;
            let v456: f32 = v4 * v455;
            let v457: f32 = v28 * v449;
            let v458: f32 = v31 * v453;
            let v459: f32 = v457 - v458;
            let v460: f32 = v2 * v459;
            let v461: f32 = v456 - v460;
            let v462: f32 = v461 / v440;
            let v463: f32 = tau[4];
            let v464: f32 = v463 - v163;
            let v465: f32 = v462 * v464;
            let v466: f32 = v434 - v465;
            let v467: f32 = v429 * v97;
            let v468: f32 = v437 * v114;
            let v469: f32 = v435 * v112;
            let v470: f32 = v468 - v469;
            let v471: f32 = v470 * v99;
            let v472: f32 = 0.0016539803_f32;
            let v473: f32 = v471 - v472;
            let v474: f32 = v70 * v473;
            let v475: f32 = v444 * v112;
            let v476: f32 = v442 * v114;
            let v477: f32 = v475 + v476;
            let v478: f32 = 0.0016833252_f32;
            let v479: f32 = v477 + v478;
            let v480: f32 = v88 + v479;
            let v481: f32 = v97 * v480;
            let v482: f32 = v481 * v99;
            let v483: f32 = 0.12999256_f32;
            let v484: f32 = v483 * v99;
            let v485: f32 = v484 * v97;
            let v486: f32 = v482 - v485;
            let v487: f32 = v73 * v486;
            let v488: f32 = v474 - v487;
            let v489: f32 = v28 * v488;
            let v490: f32 = v70 * v486;
            let v491: f32 = v73 * v473;
            (
                v352,
                v365,
                v395,
                v410,
                v417,
                v429,
                v430,
                v432,
                v440,
                v446,
                v448,
                v451,
                v461,
                v462,
                v464,
                v466,
                v467,
                v470,
                v480,
                v481,
                v483,
                v484,
                v488,
                v489,
                v490,
                v491,
            )
        };
        let (
            v498,
            v521,
            v523,
            v531,
            v533,
            v534,
            v535,
            v545,
            v547,
            v548,
            v578,
            v582,
            v584,
            v585,
            v588,
            v594,
            v595,
            v604,
            v609,
            v611,
            v618,
            v636,
            v637,
            v640,
            v645,
            v646,
            v648,
            v650,
            v653,
            v654,
            v655,
        ) = {
            let v492: f32 = v490 + v491;
            let v493: f32 = v31 * v492;
            let v494: f32 = v489 - v493;
            let v495: f32 = 0.017784735_f32;
            let v496: f32 = v495 * v73;
            let v497: f32 = v31 * v496;
            let v498: f32 = v495 * v70;
            let v499: f32 = v28 * v498;
            let v500: f32 = v497 - v499;
            let v501: f32 = v57 * v500;
            let v502: f32 = v494 + v501;
            let v503: f32 = v2 * v502;
            let v504: f32 = v28 * v496;
            let v505: f32 = v31 * v498;
            let v506: f32 = v504 + v505;
            let v507: f32 = v57 * v506;
            let v508: f32 = v31 * v488;
            let v509: f32 = v28 * v492;
            let v510: f32 = v508 + v509;
            let v511: f32 = v507 - v510;
            let v512: f32 = v4 * v511;
            let v513: f32 = v503 + v512;
            let v514: f32 = v4 * v506;
            let v515: f32 = v2 * v500;
            let v516: f32 = v514 + v515;
            let v517: f32 = v18 * v516;
            let v518: f32 = v513 + v517;
            let v519: f32 = v467 - v518;
            let v520: f32 = v99 * v446;
            let v521: f32 = v520 / v440;
            let v522: f32 = v461 * v521;
            let v523: f32 = v519 - v522;
            let v524: f32 = v99 * v480;
            let v525: f32 = v524 * v99;
            let v526: f32 = v483 * v97;
            let v527: f32 = v526 * v97;
            let v528: f32 = v525 + v527;
            let v529: f32 = v88 + v528;
            let v530: f32 = v138 * v97;
            let v531: f32 = v530 * v97;
            let v532: f32 = v529 - v531;
            let v533: f32 = v520 * v521;
            let v534: f32 = v532 - v533;
            let v535: f32 = v523 / v534;
            let v536: f32 = tau[3];
            let v537: f32 = v122 * v92;
            let v538: f32 = v83 * v279;
            let v539: f32 = v537 - v538;
            let v540: f32 = v99 * v296;
            let v541: f32 = v97 * v310;
            let v542: f32 = v540 + v541;
            let v543: f32 = v539 + v542;
            let v544: f32 = v536 - v543;
            let v545: f32 = v97 * v432;
            let v546: f32 = v544 - v545;
            let v547: f32 = v521 * v464;
            let v548: f32 = v546 - v547;
            let v549: f32 = v535 * v548;
            let v550: f32 = v466 - v549;
            let v551: f32 = 0.051322658_f32;
            let v552: f32 = v492 + v551;
            let v553: f32 = v28 * v552;
            let v554: f32 = v508 + v553;
            let v555: f32 = 1.0300093_f32;
            let v556: f32 = v555 - v496;
            let v557: f32 = v50 + v556;
            let v558: f32 = v28 * v557;
            let v559: f32 = v558 - v505;
            let v560: f32 = v57 * v559;
            let v561: f32 = v554 + v560;
            let v562: f32 = v4 * v561;
            let v563: f32 = v31 * v552;
            let v564: f32 = v489 - v563;
            let v565: f32 = v31 * v557;
            let v566: f32 = v565 + v499;
            let v567: f32 = v57 * v566;
            let v568: f32 = v564 - v567;
            let v569: f32 = v2 * v568;
            let v570: f32 = v562 - v569;
            let v571: f32 = v4 * v559;
            let v572: f32 = v2 * v566;
            let v573: f32 = v571 + v572;
            let v574: f32 = v18 * v573;
            let v575: f32 = v570 + v574;
            let v576: f32 = v575 + v467;
            let v577: f32 = v576 - v522;
            let v578: f32 = v196 * v496;
            let v579: f32 = v529 - v578;
            let v580: f32 = v579 - v531;
            let v581: f32 = v580 - v533;
            let v582: f32 = v581 / v534;
            let v583: f32 = v523 * v582;
            let v584: f32 = v577 - v583;
            let v585: f32 = 0.40402114_f32;
            let v586: f32 = 2.0_f32;
            let v587: f32 = v586 * v578;
            let v588: f32 = v585 - v587;
            let v589: f32 = v529 + v588;
            let v590: f32 = v29 + v589;
            let v591: f32 = v590 - v531;
            let v592: f32 = v591 - v533;
            let v593: f32 = v581 * v582;
            let v594: f32 = v592 - v593;
            let v595: f32 = v584 / v594;
            let v596: f32 = tau[2];
            let v597: f32 = v62 * v46;
            let v598: f32 = v37 * v352;
            let v599: f32 = v597 - v598;
            let v600: f32 = v50 * v195;
            let v601: f32 = v599 + v600;
            let v602: f32 = v601 + v543;
            let v603: f32 = v196 * v365;
            let v604: f32 = v602 + v603;
            let v605: f32 = v596 - v604;
            let v606: f32 = v605 - v545;
            let v607: f32 = v606 - v547;
            let v608: f32 = v582 * v548;
            let v609: f32 = v607 - v608;
            let v610: f32 = v595 * v609;
            let v611: f32 = v550 - v610;
            let v612: f32 = -0.24932103_f32;
            let v613: f32 = v554 + v612;
            let v614: f32 = v613 + v560;
            let v615: f32 = 0.05560772_f32;
            let v616: f32 = v614 + v615;
            let v617: f32 = v4 * v616;
            let v618: f32 = v499 + v565;
            let v619: f32 = v57 * v618;
            let v620: f32 = v564 - v619;
            let v621: f32 = v2 * v620;
            let v622: f32 = v617 - v621;
            let v623: f32 = 2.0828824_f32;
            let v624: f32 = v559 + v623;
            let v625: f32 = v17 + v624;
            let v626: f32 = v4 * v625;
            let v627: f32 = v2 * v618;
            let v628: f32 = v626 + v627;
            let v629: f32 = v18 * v628;
            let v630: f32 = v622 + v629;
            let v631: f32 = v630 + v467;
            let v632: f32 = v631 - v522;
            let v633: f32 = v51 * v506;
            let v634: f32 = v579 - v633;
            let v635: f32 = v634 - v531;
            let v636: f32 = v635 - v533;
            let v637: f32 = v636 / v534;
            let v638: f32 = v523 * v637;
            let v639: f32 = v632 - v638;
            let v640: f32 = v51 * v559;
            let v641: f32 = v590 + v640;
            let v642: f32 = v641 - v531;
            let v643: f32 = v642 - v533;
            let v644: f32 = v636 * v582;
            let v645: f32 = v643 - v644;
            let v646: f32 = v645 / v594;
            let v647: f32 = v584 * v646;
            let v648: f32 = v639 - v647;
            let v649: f32 = 0.9554456_f32;
            let v650: f32 = -0.015661752_f32;
            let v651: f32 = v650 + v640;
            let v652: f32 = v586 * v651;
            let v653: f32 = v649 + v652;
            let v654: f32 = v590 + v653;
            let v655: f32 = 0.07022054_f32;
            (
                v498,
                v521,
                v523,
                v531,
                v533,
                v534,
                v535,
                v545,
                v547,
                v548,
                v578,
                v582,
                v584,
                v585,
                v588,
                v594,
                v595,
                v604,
                v609,
                v611,
                v618,
                v636,
                v637,
                v640,
                v645,
                v646,
                v648,
                v650,
                v653,
                v654,
                v655,
            )
        };
        let (v784, v787, v792, v799, v808, v817) = {
            let v656: f32 = v654 - v655;
            let v657: f32 = v656 - v650;
            let v658: f32 = v657 - v650;
            let v659: f32 = v3 + v658;
            let v660: f32 = v659 - v531;
            let v661: f32 = v660 - v533;
            let v662: f32 = v636 * v637;
            let v663: f32 = v661 - v662;
            let v664: f32 = v645 * v646;
            let v665: f32 = v663 - v664;
            let v666: f32 = v648 / v665;
            let v667: f32 = tau[1];
            let v668: f32 = v6 * v395;
            let v669: f32 = v21 * v13;
            let v670: f32 = v668 - v669;
            let v671: f32 = v17 * v176;
            let v672: f32 = v670 + v671;
            let v673: f32 = v672 + v604;
            let v674: f32 = v51 * v410;
            let v675: f32 = v673 + v674;
            let v676: f32 = v667 - v675;
            let v677: f32 = v676 - v545;
            let v678: f32 = v677 - v547;
            let v679: f32 = v637 * v548;
            let v680: f32 = v678 - v679;
            let v681: f32 = v646 * v609;
            let v682: f32 = v680 - v681;
            let v683: f32 = v666 * v682;
            let v684: f32 = v611 - v683;
            let v685: f32 = 0.00666_f32;
            let v686: f32 = 0.012168278_f32;
            let v687: f32 = v440 + v686;
            let v688: f32 = v71 + v687;
            let v689: f32 = v70 * v688;
            let v690: f32 = v689 - v448;
            let v691: f32 = v690 * v70;
            let v692: f32 = v470 * v97;
            let v693: f32 = v70 * v692;
            let v694: f32 = v481 * v97;
            let v695: f32 = v484 * v99;
            let v696: f32 = v694 + v695;
            let v697: f32 = v696 + v686;
            let v698: f32 = v88 + v697;
            let v699: f32 = v73 * v698;
            let v700: f32 = v693 - v699;
            let v701: f32 = v700 * v73;
            let v702: f32 = v691 - v701;
            let v703: f32 = v702 + v588;
            let v704: f32 = v29 + v703;
            let v705: f32 = v28 * v704;
            let v706: f32 = v70 * v698;
            let v707: f32 = v73 * v692;
            let v708: f32 = v706 + v707;
            let v709: f32 = v708 * v73;
            let v710: f32 = v73 * v688;
            let v711: f32 = v451 + v710;
            let v712: f32 = v711 * v70;
            let v713: f32 = v709 - v712;
            let v714: f32 = v196 * v498;
            let v715: f32 = v713 - v714;
            let v716: f32 = v31 * v715;
            let v717: f32 = v705 + v716;
            let v718: f32 = v717 * v28;
            let v719: f32 = v708 * v70;
            let v720: f32 = v711 * v73;
            let v721: f32 = v719 + v720;
            let v722: f32 = v721 + v588;
            let v723: f32 = v722 - v585;
            let v724: f32 = v723 + v578;
            let v725: f32 = v724 + v578;
            let v726: f32 = v45 + v725;
            let v727: f32 = v31 * v726;
            let v728: f32 = v700 * v70;
            let v729: f32 = v690 * v73;
            let v730: f32 = v728 + v729;
            let v731: f32 = v730 + v714;
            let v732: f32 = v28 * v731;
            let v733: f32 = v727 - v732;
            let v734: f32 = v733 * v31;
            let v735: f32 = v718 + v734;
            let v736: f32 = v735 + v653;
            let v737: f32 = v3 + v736;
            let v738: f32 = v2 * v737;
            let v739: f32 = v28 * v715;
            let v740: f32 = v31 * v704;
            let v741: f32 = v739 - v740;
            let v742: f32 = v741 * v28;
            let v743: f32 = v31 * v731;
            let v744: f32 = v28 * v726;
            let v745: f32 = v743 + v744;
            let v746: f32 = v745 * v31;
            let v747: f32 = v742 + v746;
            let v748: f32 = v51 * v618;
            let v749: f32 = v747 - v748;
            let v750: f32 = v4 * v749;
            let v751: f32 = v738 + v750;
            let v752: f32 = v751 * v2;
            let v753: f32 = v733 * v28;
            let v754: f32 = v717 * v31;
            let v755: f32 = v753 - v754;
            let v756: f32 = v755 - v748;
            let v757: f32 = v2 * v756;
            let v758: f32 = v745 * v28;
            let v759: f32 = v741 * v31;
            let v760: f32 = v758 - v759;
            let v761: f32 = v760 + v653;
            let v762: f32 = 0.88522506_f32;
            let v763: f32 = v761 - v762;
            let v764: f32 = v763 - v640;
            let v765: f32 = v764 - v640;
            let v766: f32 = v12 + v765;
            let v767: f32 = v4 * v766;
            let v768: f32 = v757 + v767;
            let v769: f32 = v768 * v4;
            let v770: f32 = v752 + v769;
            let v771: f32 = 0.1215021_f32;
            let v772: f32 = v770 + v771;
            let v773: f32 = v685 + v772;
            let v774: f32 = v429 * v430;
            let v775: f32 = v773 - v774;
            let v776: f32 = v461 * v462;
            let v777: f32 = v775 - v776;
            let v778: f32 = v523 * v535;
            let v779: f32 = v777 - v778;
            let v780: f32 = v584 * v595;
            let v781: f32 = v779 - v780;
            let v782: f32 = v648 * v666;
            let v783: f32 = v781 - v782;
            let v784: f32 = v684 / v783;
            let v785: f32 = v682 / v665;
            let v786: f32 = v666 * v784;
            let v787: f32 = v785 - v786;
            let v788: f32 = v609 / v594;
            let v789: f32 = v595 * v784;
            let v790: f32 = v788 - v789;
            let v791: f32 = v646 * v787;
            let v792: f32 = v790 - v791;
            let v793: f32 = v548 / v534;
            let v794: f32 = v535 * v784;
            let v795: f32 = v793 - v794;
            let v796: f32 = v637 * v787;
            let v797: f32 = v795 - v796;
            let v798: f32 = v582 * v792;
            let v799: f32 = v797 - v798;
            let v800: f32 = v464 / v440;
            let v801: f32 = v462 * v784;
            let v802: f32 = v800 - v801;
            let v803: f32 = v521 * v787;
            let v804: f32 = v802 - v803;
            let v805: f32 = v521 * v792;
            let v806: f32 = v804 - v805;
            let v807: f32 = v521 * v799;
            let v808: f32 = v806 - v807;
            let v809: f32 = v417 * v432;
            let v810: f32 = v430 * v784;
            let v811: f32 = v809 + v810;
            let v812: f32 = v97 * v787;
            let v813: f32 = v811 - v812;
            let v814: f32 = v97 * v792;
            let v815: f32 = v813 - v814;
            let v816: f32 = v97 * v799;
            let v817: f32 = v815 - v816;
            (v784, v787, v792, v799, v808, v817)
        };
        [v784, v787, v792, v799, v808, v817]
    }
    /// Mass matrix and bias in one pass: row i is `[M_i0, ..., M_i(n-1), c_i + g_i]`, the `M(q)` of `mass_matrix` with the bias `c(q, qd) + g(q)` of `coriolis` and `gravity` as a last column (what Pinocchio's `crba` and `nonLinearEffects` compute together). Common subexpressions, sin/cos included, are computed once for both.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 6]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `mass_matrix_and_bias: [[f32; 7]; 6]` (6 x 7, row-major): rows `[M(q) | c(q, qd) + g(q)]`: the symmetric positive definite M (kg m^2, kg m, kg), then the bias (N m or N)
    ///
    /// Operation count: 635 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn mass_matrix_and_bias(q: &[f32; 6], qd: &[f32; 6]) -> [[f32; 7]; 6] {
        let (
            v2,
            v3,
            v5,
            v6,
            v8,
            v9,
            v10,
            v12,
            v15,
            v16,
            v20,
            v25,
            v27,
            v32,
            v34,
            v42,
            v48,
            v51,
            v52,
            v64,
            v66,
            v67,
            v69,
            v73,
            v78,
            v89,
            v108,
            v109,
            v110,
            v115,
            v116,
            v117,
            v120,
            v124,
            v134,
            v135,
            v136,
            v147,
            v163,
            v166,
            v170,
            v172,
            v173,
        ) = {
            let v0: f32 = 0.00666_f32;
            let v1: f32 = q[1];
            let (v124, v2): (f32, f32) = ::libm::sincosf(v1);
            let v3: f32 = 0.8849019_f32;
            let v4: f32 = q[2];
            let (v73, v5): (f32, f32) = ::libm::sincosf(v4);
            let v6: f32 = 0.19163081_f32;
            let v7: f32 = q[3];
            let (v25, v8): (f32, f32) = ::libm::sincosf(v7);
            let v9: f32 = 0.21942_f32;
            let v10: f32 = 0.017136473_f32;
            let v11: f32 = q[5];
            let (v12, v16): (f32, f32) = ::libm::sincosf(v11);
            let v13: f32 = v10 * v12;
            let v14: f32 = v13 * v12;
            let v15: f32 = 0.033822_f32;
            let v17: f32 = v15 * v16;
            let v18: f32 = v17 * v16;
            let v19: f32 = v14 + v18;
            let v20: f32 = v9 + v19;
            let v21: f32 = 0.012168278_f32;
            let v22: f32 = v20 + v21;
            let v23: f32 = v9 + v22;
            let v24: f32 = v8 * v23;
            let v26: f32 = q[4];
            let (v52, v27): (f32, f32) = ::libm::sincosf(v26);
            let v28: f32 = v15 * v12;
            let v29: f32 = v28 * v16;
            let v30: f32 = v10 * v16;
            let v31: f32 = v30 * v12;
            let v32: f32 = v29 - v31;
            let v33: f32 = v27 * v32;
            let v34: f32 = v25 * v33;
            let v35: f32 = v24 - v34;
            let v36: f32 = v35 * v8;
            let v37: f32 = v17 * v12;
            let v38: f32 = v13 * v16;
            let v39: f32 = v37 - v38;
            let v40: f32 = v39 * v27;
            let v41: f32 = v8 * v40;
            let v42: f32 = 0.11117276_f32;
            let v43: f32 = v30 * v16;
            let v44: f32 = v28 * v12;
            let v45: f32 = v43 + v44;
            let v46: f32 = 0.0016833252_f32;
            let v47: f32 = v45 + v46;
            let v48: f32 = v42 + v47;
            let v49: f32 = v27 * v48;
            let v50: f32 = v49 * v27;
            let v51: f32 = 0.12999256_f32;
            let v53: f32 = v51 * v52;
            let v54: f32 = v53 * v52;
            let v55: f32 = v50 + v54;
            let v56: f32 = v55 + v21;
            let v57: f32 = v42 + v56;
            let v58: f32 = v25 * v57;
            let v59: f32 = v41 - v58;
            let v60: f32 = v59 * v25;
            let v61: f32 = v36 - v60;
            let v62: f32 = 0.40402114_f32;
            let v63: f32 = 2.0_f32;
            let v64: f32 = 0.39225_f32;
            let v65: f32 = 0.017784735_f32;
            let v66: f32 = v65 * v25;
            let v67: f32 = v64 * v66;
            let v68: f32 = v63 * v67;
            let v69: f32 = v62 - v68;
            let v70: f32 = v61 + v69;
            let v71: f32 = v6 + v70;
            let v72: f32 = v5 * v71;
            let v74: f32 = v8 * v57;
            let v75: f32 = v25 * v40;
            let v76: f32 = v74 + v75;
            let v77: f32 = v76 * v25;
            let v78: f32 = v8 * v33;
            let v79: f32 = v25 * v23;
            let v80: f32 = v78 + v79;
            let v81: f32 = v80 * v8;
            let v82: f32 = v77 - v81;
            let v83: f32 = v65 * v8;
            let v84: f32 = v64 * v83;
            let v85: f32 = v82 - v84;
            let v86: f32 = v73 * v85;
            let v87: f32 = v72 + v86;
            let v88: f32 = v87 * v5;
            let v89: f32 = 0.004095_f32;
            let v90: f32 = v76 * v8;
            let v91: f32 = v80 * v25;
            let v92: f32 = v90 + v91;
            let v93: f32 = v92 + v69;
            let v94: f32 = v93 - v62;
            let v95: f32 = v94 + v67;
            let v96: f32 = v95 + v67;
            let v97: f32 = v89 + v96;
            let v98: f32 = v73 * v97;
            let v99: f32 = v59 * v8;
            let v100: f32 = v35 * v25;
            let v101: f32 = v99 + v100;
            let v102: f32 = v101 + v84;
            let v103: f32 = v5 * v102;
            let v104: f32 = v98 - v103;
            let v105: f32 = v104 * v73;
            let v106: f32 = v88 + v105;
            let v107: f32 = 0.9554456_f32;
            let v108: f32 = -0.015661752_f32;
            let v109: f32 = 0.425_f32;
            let v110: f32 = 0.56875_f32;
            let v111: f32 = 1.0300093_f32;
            let v112: f32 = v111 - v66;
            let v113: f32 = v110 + v112;
            let v114: f32 = v5 * v113;
            let v115: f32 = v73 * v83;
            let v116: f32 = v114 - v115;
            let v117: f32 = v109 * v116;
            let v118: f32 = v108 + v117;
            let v119: f32 = v63 * v118;
            let v120: f32 = v107 + v119;
            let v121: f32 = v106 + v120;
            let v122: f32 = v3 + v121;
            let v123: f32 = v2 * v122;
            let v125: f32 = v5 * v85;
            let v126: f32 = v73 * v71;
            let v127: f32 = v125 - v126;
            let v128: f32 = v127 * v5;
            let v129: f32 = v73 * v102;
            let v130: f32 = v5 * v97;
            let v131: f32 = v129 + v130;
            let v132: f32 = v131 * v73;
            let v133: f32 = v128 + v132;
            let v134: f32 = v5 * v83;
            let v135: f32 = v73 * v113;
            let v136: f32 = v134 + v135;
            let v137: f32 = v109 * v136;
            let v138: f32 = v133 - v137;
            let v139: f32 = v124 * v138;
            let v140: f32 = v123 + v139;
            let v141: f32 = v140 * v2;
            let v142: f32 = v104 * v5;
            let v143: f32 = v87 * v73;
            let v144: f32 = v142 - v143;
            let v145: f32 = v144 - v137;
            let v146: f32 = v2 * v145;
            let v147: f32 = 0.0151074_f32;
            let v148: f32 = v131 * v5;
            let v149: f32 = v127 * v73;
            let v150: f32 = v148 - v149;
            let v151: f32 = v150 + v120;
            let v152: f32 = 0.88522506_f32;
            let v153: f32 = v151 - v152;
            let v154: f32 = v153 - v117;
            let v155: f32 = v154 - v117;
            let v156: f32 = v147 + v155;
            let v157: f32 = v124 * v156;
            let v158: f32 = v146 + v157;
            let v159: f32 = v158 * v124;
            let v160: f32 = v141 + v159;
            let v161: f32 = 0.1215021_f32;
            let v162: f32 = v160 + v161;
            let v163: f32 = v0 + v162;
            let v164: f32 = v39 * v52;
            let v165: f32 = 0.0016539803_f32;
            let v166: f32 = v164 - v165;
            let v167: f32 = v8 * v166;
            let v168: f32 = v49 * v52;
            let v169: f32 = v53 * v27;
            let v170: f32 = v168 - v169;
            let v171: f32 = v25 * v170;
            let v172: f32 = v167 - v171;
            let v173: f32 = v73 * v172;
            (
                v2,
                v3,
                v5,
                v6,
                v8,
                v9,
                v10,
                v12,
                v15,
                v16,
                v20,
                v25,
                v27,
                v32,
                v34,
                v42,
                v48,
                v51,
                v52,
                v64,
                v66,
                v67,
                v69,
                v73,
                v78,
                v89,
                v108,
                v109,
                v110,
                v115,
                v116,
                v117,
                v120,
                v124,
                v134,
                v135,
                v136,
                v147,
                v163,
                v166,
                v170,
                v172,
                v173,
            )
        };
        let (
            v183,
            v196,
            v197,
            v205,
            v217,
            v226,
            v238,
            v251,
            v264,
            v266,
            v267,
            v268,
            v270,
            v272,
            v276,
            v278,
            v279,
            v283,
            v285,
            v290,
            v293,
            v295,
            v296,
            v298,
            v303,
            v307,
            v311,
            v312,
            v315,
            v317,
            v323,
            v328,
            v329,
            v331,
            v332,
            v333,
            v334,
            v336,
            v339,
            v342,
            v345,
            v346,
            v347,
        ) = {
            let v174: f32 = v8 * v170;
            let v175: f32 = v25 * v166;
            let v176: f32 = v174 + v175;
            let v177: f32 = 0.051322658_f32;
            let v178: f32 = v176 + v177;
            let v179: f32 = v5 * v178;
            let v180: f32 = v173 + v179;
            let v181: f32 = -0.24932103_f32;
            let v182: f32 = v180 + v181;
            let v183: f32 = -0.1197_f32;
            let v184: f32 = v183 * v116;
            let v185: f32 = v182 + v184;
            let v186: f32 = 0.05560772_f32;
            let v187: f32 = v185 + v186;
            let v188: f32 = v124 * v187;
            let v189: f32 = v5 * v172;
            let v190: f32 = v73 * v178;
            let v191: f32 = v189 - v190;
            let v192: f32 = v183 * v136;
            let v193: f32 = v191 - v192;
            let v194: f32 = v2 * v193;
            let v195: f32 = v188 - v194;
            let v196: f32 = 0.13585_f32;
            let v197: f32 = 2.35004_f32;
            let v198: f32 = 2.0828824_f32;
            let v199: f32 = v116 + v198;
            let v200: f32 = v197 + v199;
            let v201: f32 = v124 * v200;
            let v202: f32 = v2 * v136;
            let v203: f32 = v201 + v202;
            let v204: f32 = v196 * v203;
            let v205: f32 = v195 + v204;
            let v206: f32 = v180 + v184;
            let v207: f32 = v124 * v206;
            let v208: f32 = v135 + v134;
            let v209: f32 = v183 * v208;
            let v210: f32 = v191 - v209;
            let v211: f32 = v2 * v210;
            let v212: f32 = v207 - v211;
            let v213: f32 = v124 * v116;
            let v214: f32 = v2 * v208;
            let v215: f32 = v213 + v214;
            let v216: f32 = v196 * v215;
            let v217: f32 = v212 + v216;
            let v218: f32 = v73 * v176;
            let v219: f32 = v189 - v218;
            let v220: f32 = v73 * v66;
            let v221: f32 = v220 - v134;
            let v222: f32 = v183 * v221;
            let v223: f32 = v219 + v222;
            let v224: f32 = v2 * v223;
            let v225: f32 = v5 * v66;
            let v226: f32 = v225 + v115;
            let v227: f32 = v183 * v226;
            let v228: f32 = v5 * v176;
            let v229: f32 = v173 + v228;
            let v230: f32 = v227 - v229;
            let v231: f32 = v124 * v230;
            let v232: f32 = v224 + v231;
            let v233: f32 = v124 * v226;
            let v234: f32 = v2 * v221;
            let v235: f32 = v233 + v234;
            let v236: f32 = v196 * v235;
            let v237: f32 = v232 + v236;
            let v238: f32 = -v237;
            let v239: f32 = v8 * v20;
            let v240: f32 = v239 - v34;
            let v241: f32 = v73 * v240;
            let v242: f32 = v25 * v20;
            let v243: f32 = v78 + v242;
            let v244: f32 = v5 * v243;
            let v245: f32 = v241 + v244;
            let v246: f32 = v124 * v245;
            let v247: f32 = v5 * v240;
            let v248: f32 = v73 * v243;
            let v249: f32 = v247 - v248;
            let v250: f32 = v2 * v249;
            let v251: f32 = v246 - v250;
            let v252: f32 = v10 * v52;
            let v253: f32 = v25 * v252;
            let v254: f32 = v5 * v253;
            let v255: f32 = v8 * v252;
            let v256: f32 = v73 * v255;
            let v257: f32 = v254 + v256;
            let v258: f32 = v2 * v257;
            let v259: f32 = v5 * v255;
            let v260: f32 = v73 * v253;
            let v261: f32 = v259 - v260;
            let v262: f32 = v124 * v261;
            let v263: f32 = v258 + v262;
            let v264: f32 = -v263;
            let v265: f32 = qd[0];
            let v266: f32 = v124 * v265;
            let v267: f32 = qd[1];
            let v268: f32 = v266 * v267;
            let v269: f32 = v3 * v268;
            let v270: f32 = v3 * v267;
            let v271: f32 = v266 * v270;
            let v272: f32 = v147 * v266;
            let v273: f32 = v267 * v272;
            let v274: f32 = v271 - v273;
            let v275: f32 = v269 + v274;
            let v276: f32 = v196 * v266;
            let v277: f32 = v266 * v276;
            let v278: f32 = v2 * v265;
            let v279: f32 = v196 * v278;
            let v280: f32 = v278 * v279;
            let v281: f32 = v277 + v280;
            let v282: f32 = v197 * v281;
            let v283: f32 = v275 + v282;
            let v284: f32 = v5 * v268;
            let v285: f32 = v278 * v267;
            let v286: f32 = v73 * v285;
            let v287: f32 = v284 + v286;
            let v288: f32 = v73 * v278;
            let v289: f32 = v5 * v266;
            let v290: f32 = v288 + v289;
            let v291: f32 = qd[2];
            let v292: f32 = v290 * v291;
            let v293: f32 = v287 + v292;
            let v294: f32 = v6 * v293;
            let v295: f32 = v267 + v291;
            let v296: f32 = v6 * v295;
            let v297: f32 = v290 * v296;
            let v298: f32 = v89 * v290;
            let v299: f32 = v295 * v298;
            let v300: f32 = v297 - v299;
            let v301: f32 = v294 + v300;
            let v302: f32 = v109 * v268;
            let v303: f32 = v109 * v267;
            let v304: f32 = v266 * v303;
            let v305: f32 = v302 + v304;
            let v306: f32 = v281 + v305;
            let v307: f32 = v183 * v290;
            let v308: f32 = v290 * v307;
            let v309: f32 = v73 * v266;
            let v310: f32 = v5 * v278;
            let v311: f32 = v309 - v310;
            let v312: f32 = v183 * v311;
            let v313: f32 = v311 * v312;
            let v314: f32 = v308 + v313;
            let v315: f32 = v306 + v314;
            let v316: f32 = v110 * v315;
            let v317: f32 = v301 + v316;
            let v318: f32 = v8 * v293;
            let v319: f32 = v73 * v268;
            let v320: f32 = v5 * v285;
            let v321: f32 = v319 - v320;
            let v322: f32 = v311 * v291;
            let v323: f32 = v321 + v322;
            let v324: f32 = v25 * v323;
            let v325: f32 = v318 - v324;
            let v326: f32 = v8 * v290;
            let v327: f32 = v25 * v311;
            let v328: f32 = v326 - v327;
            let v329: f32 = qd[3];
            let v330: f32 = v328 * v329;
            let v331: f32 = v325 + v330;
            let v332: f32 = v9 * v331;
            let v333: f32 = v295 + v329;
            let v334: f32 = v42 * v333;
            let v335: f32 = v328 * v334;
            let v336: f32 = v42 * v328;
            let v337: f32 = v333 * v336;
            let v338: f32 = v335 - v337;
            let v339: f32 = v332 + v338;
            let v340: f32 = v27 * v328;
            let v341: f32 = v52 * v333;
            let v342: f32 = v340 + v341;
            let v343: f32 = v27 * v333;
            let v344: f32 = v52 * v328;
            let v345: f32 = v343 - v344;
            let v346: f32 = v42 * v345;
            let v347: f32 = v342 * v346;
            (
                v183,
                v196,
                v197,
                v205,
                v217,
                v226,
                v238,
                v251,
                v264,
                v266,
                v267,
                v268,
                v270,
                v272,
                v276,
                v278,
                v279,
                v283,
                v285,
                v290,
                v293,
                v295,
                v296,
                v298,
                v303,
                v307,
                v311,
                v312,
                v315,
                v317,
                v323,
                v328,
                v329,
                v331,
                v332,
                v333,
                v334,
                v336,
                v339,
                v342,
                v345,
                v346,
                v347,
            )
        };
        let (
            v348,
            v359,
            v368,
            v370,
            v378,
            v381,
            v388,
            v392,
            v396,
            v399,
            v401,
            v402,
            v412,
            v421,
            v431,
            v442,
            v449,
            v455,
            v465,
            v468,
            v477,
            v481,
            v489,
            v494,
            v496,
            v497,
            v506,
            v508,
            v510,
            v512,
            v513,
            v514,
            v519,
            v520,
            v521,
        ) = {
            let v348: f32 = v42 * v342;
            let v349: f32 = v345 * v348;
            let v350: f32 = v347 - v349;
            let v351: f32 = v332 + v350;
            let v352: f32 = qd[4];
            let v353: f32 = v345 * v352;
            let v354: f32 = v25 * v293;
            let v355: f32 = v8 * v323;
            let v356: f32 = v354 + v355;
            let v357: f32 = v8 * v311;
            let v358: f32 = v25 * v290;
            let v359: f32 = v357 + v358;
            let v360: f32 = v359 * v329;
            let v361: f32 = v356 + v360;
            let v362: f32 = v27 * v361;
            let v363: f32 = v353 - v362;
            let v364: f32 = v12 * v363;
            let v365: f32 = v16 * v331;
            let v366: f32 = v364 + v365;
            let v367: f32 = v16 * v342;
            let v368: f32 = v359 + v352;
            let v369: f32 = v12 * v368;
            let v370: f32 = v367 - v369;
            let v371: f32 = qd[5];
            let v372: f32 = v370 * v371;
            let v373: f32 = v366 + v372;
            let v374: f32 = v15 * v373;
            let v375: f32 = v345 + v371;
            let v376: f32 = v10 * v375;
            let v377: f32 = v370 * v376;
            let v378: f32 = v10 * v370;
            let v379: f32 = v375 * v378;
            let v380: f32 = v377 - v379;
            let v381: f32 = v374 + v380;
            let v382: f32 = v16 * v381;
            let v383: f32 = v16 * v363;
            let v384: f32 = v12 * v331;
            let v385: f32 = v383 - v384;
            let v386: f32 = v12 * v342;
            let v387: f32 = v16 * v368;
            let v388: f32 = v386 + v387;
            let v389: f32 = v388 * v371;
            let v390: f32 = v385 - v389;
            let v391: f32 = v10 * v390;
            let v392: f32 = v15 * v388;
            let v393: f32 = v375 * v392;
            let v394: f32 = v388 * v376;
            let v395: f32 = v393 - v394;
            let v396: f32 = v391 + v395;
            let v397: f32 = v12 * v396;
            let v398: f32 = v382 - v397;
            let v399: f32 = v351 + v398;
            let v400: f32 = v339 + v399;
            let v401: f32 = 0.093_f32;
            let v402: f32 = 1.219_f32;
            let v403: f32 = v401 * v328;
            let v404: f32 = v333 * v403;
            let v405: f32 = v401 * v331;
            let v406: f32 = v404 - v405;
            let v407: f32 = v196 * v285;
            let v408: f32 = v267 * v279;
            let v409: f32 = v407 - v408;
            let v410: f32 = 9.81_f32;
            let v411: f32 = v410 * v2;
            let v412: f32 = v409 - v411;
            let v413: f32 = v109 * v278;
            let v414: f32 = v266 * v413;
            let v415: f32 = v412 + v414;
            let v416: f32 = v5 * v415;
            let v417: f32 = v196 * v268;
            let v418: f32 = v267 * v276;
            let v419: f32 = v417 - v418;
            let v420: f32 = v410 * v124;
            let v421: f32 = v419 - v420;
            let v422: f32 = v278 * v413;
            let v423: f32 = v267 * v303;
            let v424: f32 = v422 + v423;
            let v425: f32 = v421 - v424;
            let v426: f32 = v73 * v425;
            let v427: f32 = v416 - v426;
            let v428: f32 = v295 * v312;
            let v429: f32 = v183 * v323;
            let v430: f32 = v428 - v429;
            let v431: f32 = v427 + v430;
            let v432: f32 = v64 * v311;
            let v433: f32 = v290 * v432;
            let v434: f32 = v431 - v433;
            let v435: f32 = v25 * v434;
            let v436: f32 = v73 * v415;
            let v437: f32 = v5 * v425;
            let v438: f32 = v436 + v437;
            let v439: f32 = v183 * v293;
            let v440: f32 = v295 * v307;
            let v441: f32 = v439 - v440;
            let v442: f32 = v438 + v441;
            let v443: f32 = v311 * v432;
            let v444: f32 = v64 * v295;
            let v445: f32 = v295 * v444;
            let v446: f32 = v443 + v445;
            let v447: f32 = v442 - v446;
            let v448: f32 = v8 * v447;
            let v449: f32 = v435 + v448;
            let v450: f32 = v406 - v449;
            let v451: f32 = v27 * v450;
            let v452: f32 = v64 * v293;
            let v453: f32 = v290 * v444;
            let v454: f32 = v452 + v453;
            let v455: f32 = v315 + v454;
            let v456: f32 = v401 * v359;
            let v457: f32 = v359 * v456;
            let v458: f32 = v328 * v403;
            let v459: f32 = v457 + v458;
            let v460: f32 = v455 + v459;
            let v461: f32 = v52 * v460;
            let v462: f32 = v451 - v461;
            let v463: f32 = v402 * v462;
            let v464: f32 = 0.1879_f32;
            let v465: f32 = 0.09465_f32;
            let v466: f32 = v52 * v361;
            let v467: f32 = v342 * v352;
            let v468: f32 = v466 - v467;
            let v469: f32 = v465 * v468;
            let v470: f32 = v465 * v342;
            let v471: f32 = v368 * v470;
            let v472: f32 = v469 + v471;
            let v473: f32 = v462 + v472;
            let v474: f32 = v16 * v473;
            let v475: f32 = v8 * v434;
            let v476: f32 = v25 * v447;
            let v477: f32 = v475 - v476;
            let v478: f32 = v333 * v456;
            let v479: f32 = v401 * v361;
            let v480: f32 = v478 - v479;
            let v481: f32 = v477 + v480;
            let v482: f32 = v342 * v470;
            let v483: f32 = v465 * v345;
            let v484: f32 = v345 * v483;
            let v485: f32 = v482 + v484;
            let v486: f32 = v481 - v485;
            let v487: f32 = v12 * v486;
            let v488: f32 = v474 - v487;
            let v489: f32 = v464 * v488;
            let v490: f32 = v16 * v489;
            let v491: f32 = v12 * v473;
            let v492: f32 = v16 * v486;
            let v493: f32 = v491 + v492;
            let v494: f32 = v464 * v493;
            let v495: f32 = v12 * v494;
            let v496: f32 = v490 + v495;
            let v497: f32 = v463 + v496;
            let v498: f32 = v27 * v497;
            let v499: f32 = v368 * v483;
            let v500: f32 = v465 * v363;
            let v501: f32 = v499 - v500;
            let v502: f32 = v52 * v450;
            let v503: f32 = v27 * v460;
            let v504: f32 = v502 + v503;
            let v505: f32 = v501 - v504;
            let v506: f32 = v464 * v505;
            let v507: f32 = v402 * v504;
            let v508: f32 = v506 - v507;
            let v509: f32 = v52 * v508;
            let v510: f32 = v498 - v509;
            let v511: f32 = v401 * v510;
            let v512: f32 = v400 - v511;
            let v513: f32 = v8 * v512;
            let v514: f32 = v9 * v359;
            let v515: f32 = v333 * v514;
            let v516: f32 = v359 * v334;
            let v517: f32 = v515 - v516;
            let v518: f32 = v42 * v361;
            let v519: f32 = v517 - v518;
            let v520: f32 = v42 * v363;
            let v521: f32 = v9 * v368;
            (
                v348,
                v359,
                v368,
                v370,
                v378,
                v381,
                v388,
                v392,
                v396,
                v399,
                v401,
                v402,
                v412,
                v421,
                v431,
                v442,
                v449,
                v455,
                v465,
                v468,
                v477,
                v481,
                v489,
                v494,
                v496,
                v497,
                v506,
                v508,
                v510,
                v512,
                v513,
                v514,
                v519,
                v520,
                v521,
            )
        };
        let (
            v542,
            v651,
            v657,
            v659,
            v665,
            v666,
            v667,
            v669,
            v670,
            v671,
            v688,
            v691,
            v694,
            v695,
        ) = {
            let v522: f32 = v345 * v521;
            let v523: f32 = v368 * v346;
            let v524: f32 = v522 - v523;
            let v525: f32 = v520 + v524;
            let v526: f32 = v16 * v396;
            let v527: f32 = v12 * v381;
            let v528: f32 = v526 + v527;
            let v529: f32 = v525 + v528;
            let v530: f32 = v465 * v506;
            let v531: f32 = v529 - v530;
            let v532: f32 = v27 * v531;
            let v533: f32 = v42 * v468;
            let v534: f32 = v368 * v348;
            let v535: f32 = v342 * v521;
            let v536: f32 = v534 - v535;
            let v537: f32 = v533 + v536;
            let v538: f32 = v10 * v468;
            let v539: f32 = v388 * v378;
            let v540: f32 = v370 * v392;
            let v541: f32 = v539 - v540;
            let v542: f32 = v538 + v541;
            let v543: f32 = v537 + v542;
            let v544: f32 = v465 * v496;
            let v545: f32 = v543 + v544;
            let v546: f32 = v52 * v545;
            let v547: f32 = v532 - v546;
            let v548: f32 = v519 + v547;
            let v549: f32 = v402 * v481;
            let v550: f32 = v16 * v494;
            let v551: f32 = v12 * v489;
            let v552: f32 = v550 - v551;
            let v553: f32 = v549 + v552;
            let v554: f32 = v401 * v553;
            let v555: f32 = v548 + v554;
            let v556: f32 = v25 * v555;
            let v557: f32 = v513 - v556;
            let v558: f32 = v317 + v557;
            let v559: f32 = v52 * v497;
            let v560: f32 = v27 * v508;
            let v561: f32 = v559 + v560;
            let v562: f32 = v402 * v455;
            let v563: f32 = v561 - v562;
            let v564: f32 = v64 * v563;
            let v565: f32 = v558 - v564;
            let v566: f32 = 2.275_f32;
            let v567: f32 = v566 * v442;
            let v568: f32 = v110 * v311;
            let v569: f32 = v311 * v568;
            let v570: f32 = v110 * v295;
            let v571: f32 = v295 * v570;
            let v572: f32 = v569 + v571;
            let v573: f32 = v567 - v572;
            let v574: f32 = v402 * v449;
            let v575: f32 = v510 - v574;
            let v576: f32 = v8 * v575;
            let v577: f32 = v402 * v477;
            let v578: f32 = v577 + v553;
            let v579: f32 = v25 * v578;
            let v580: f32 = v576 + v579;
            let v581: f32 = v573 - v580;
            let v582: f32 = v183 * v581;
            let v583: f32 = v565 + v582;
            let v584: f32 = v5 * v583;
            let v585: f32 = v89 * v323;
            let v586: f32 = v311 * v296;
            let v587: f32 = v6 * v311;
            let v588: f32 = v295 * v587;
            let v589: f32 = v586 - v588;
            let v590: f32 = v585 + v589;
            let v591: f32 = v8 * v555;
            let v592: f32 = v25 * v512;
            let v593: f32 = v591 + v592;
            let v594: f32 = v590 - v593;
            let v595: f32 = v566 * v431;
            let v596: f32 = v290 * v568;
            let v597: f32 = v595 - v596;
            let v598: f32 = v8 * v578;
            let v599: f32 = v25 * v575;
            let v600: f32 = v598 - v599;
            let v601: f32 = v597 + v600;
            let v602: f32 = v183 * v601;
            let v603: f32 = v594 - v602;
            let v604: f32 = v73 * v603;
            let v605: f32 = v584 + v604;
            let v606: f32 = v283 + v605;
            let v607: f32 = v566 * v315;
            let v608: f32 = v110 * v293;
            let v609: f32 = v290 * v570;
            let v610: f32 = v608 + v609;
            let v611: f32 = v607 + v610;
            let v612: f32 = v563 - v611;
            let v613: f32 = v109 * v612;
            let v614: f32 = v606 - v613;
            let v615: f32 = 8.393_f32;
            let v616: f32 = v615 * v421;
            let v617: f32 = v197 * v278;
            let v618: f32 = v278 * v617;
            let v619: f32 = v197 * v267;
            let v620: f32 = v267 * v619;
            let v621: f32 = v618 + v620;
            let v622: f32 = v616 - v621;
            let v623: f32 = v5 * v581;
            let v624: f32 = v73 * v601;
            let v625: f32 = v623 - v624;
            let v626: f32 = v622 + v625;
            let v627: f32 = v196 * v626;
            let v628: f32 = v614 + v627;
            let v629: f32 = v2 * v628;
            let v630: f32 = v3 * v278;
            let v631: f32 = v267 * v630;
            let v632: f32 = v278 * v270;
            let v633: f32 = v631 - v632;
            let v634: f32 = v147 * v285;
            let v635: f32 = v633 - v634;
            let v636: f32 = v5 * v603;
            let v637: f32 = v73 * v583;
            let v638: f32 = v636 - v637;
            let v639: f32 = v635 + v638;
            let v640: f32 = v615 * v412;
            let v641: f32 = v266 * v617;
            let v642: f32 = v640 + v641;
            let v643: f32 = v5 * v601;
            let v644: f32 = v73 * v581;
            let v645: f32 = v643 + v644;
            let v646: f32 = v642 + v645;
            let v647: f32 = v196 * v646;
            let v648: f32 = v639 - v647;
            let v649: f32 = v124 * v648;
            let v650: f32 = v629 + v649;
            let v651: f32 = -v650;
            let v652: f32 = v52 * v48;
            let v653: f32 = v652 * v52;
            let v654: f32 = v51 * v27;
            let v655: f32 = v654 * v27;
            let v656: f32 = v653 + v655;
            let v657: f32 = v42 + v656;
            let v658: f32 = v657 + v69;
            let v659: f32 = v6 + v658;
            let v660: f32 = v659 + v120;
            let v661: f32 = 0.07022054_f32;
            let v662: f32 = v660 - v661;
            let v663: f32 = v662 - v108;
            let v664: f32 = v663 - v108;
            let v665: f32 = v3 + v664;
            let v666: f32 = v659 + v117;
            let v667: f32 = v657 - v67;
            let v668: f32 = v109 * v226;
            let v669: f32 = v667 - v668;
            let v670: f32 = v52 * v32;
            let v671: f32 = v10 * v27;
            let v672: f32 = v266 * v630;
            let v673: f32 = v278 * v272;
            let v674: f32 = v672 - v673;
            let v675: f32 = v197 * v412;
            let v676: f32 = v674 + v675;
            let v677: f32 = v311 * v298;
            let v678: f32 = v290 * v587;
            let v679: f32 = v677 - v678;
            let v680: f32 = v110 * v431;
            let v681: f32 = v679 + v680;
            let v682: f32 = v359 * v336;
            let v683: f32 = v328 * v514;
            let v684: f32 = v682 - v683;
            let v685: f32 = v52 * v531;
            let v686: f32 = v27 * v545;
            let v687: f32 = v685 + v686;
            let v688: f32 = v684 + v687;
            let v689: f32 = v681 + v688;
            let v690: f32 = v64 * v600;
            let v691: f32 = v689 + v690;
            let v692: f32 = v676 + v691;
            let v693: f32 = v109 * v645;
            let v694: f32 = v692 + v693;
            let v695: f32 = 0.0_f32;
            (
                v542,
                v651,
                v657,
                v659,
                v665,
                v666,
                v667,
                v669,
                v670,
                v671,
                v688,
                v691,
                v694,
                v695,
            )
        };
        [
            [v163, v205, v217, v238, v251, v264, v651],
            [v205, v665, v666, v669, v670, v671, v694],
            [v217, v666, v659, v667, v670, v671, v691],
            [v238, v669, v667, v657, v670, v671, v688],
            [v251, v670, v670, v670, v20, v695, v399],
            [v264, v671, v671, v671, v695, v10, v542],
        ]
    }
    /// Dynamic regressor: `inverse_dynamics(q, qd, qdd) = Y(q, qd, qdd) * standard_parameters()`.
    ///
    /// # Inputs
    ///
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 6]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[f32; 6]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `regressor: [[f32; 60]; 6]` (6 x 60, row-major): Y(q, qd, qdd), columns in the order of `standard_parameters`
    ///
    /// Operation count: 1123 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn regressor(q: &[f32; 6], qd: &[f32; 6], qdd: &[f32; 6]) -> [[f32; 60]; 6] {
        let (
            v0,
            v4,
            v7,
            v8,
            v17,
            v20,
            v23,
            v29,
            v32,
            v45,
            v47,
            v59,
            v66,
            v71,
            v79,
            v87,
            v88,
            v94,
            v97,
            v99,
            v100,
            v107,
            v116,
            v120,
            v127,
            v130,
            v136,
            v138,
            v146,
            v151,
            v152,
            v162,
            v166,
            v172,
            v174,
            v176,
            v180,
            v187,
            v191,
            v193,
        ) = {
            let v0: f32 = qdd[0];
            let v1: f32 = 0.13585_f32;
            let v2: f32 = q[1];
            let (v3, v5): (f32, f32) = ::libm::sincosf(v2);
            let v4: f32 = v3 * v0;
            let v6: f32 = qd[0];
            let v7: f32 = v5 * v6;
            let v8: f32 = qd[1];
            let v9: f32 = v7 * v8;
            let v10: f32 = v4 + v9;
            let v11: f32 = v1 * v10;
            let v12: f32 = v1 * v7;
            let v13: f32 = v8 * v12;
            let v14: f32 = v11 - v13;
            let v15: f32 = 9.81_f32;
            let v16: f32 = v15 * v5;
            let v17: f32 = v14 - v16;
            let v18: f32 = v1 * v3;
            let v19: f32 = v17 * v18;
            let v20: f32 = v3 * v6;
            let v21: f32 = v20 * v8;
            let v22: f32 = v5 * v0;
            let v23: f32 = v21 - v22;
            let v24: f32 = v1 * v23;
            let v25: f32 = v1 * v20;
            let v26: f32 = v8 * v25;
            let v27: f32 = v24 - v26;
            let v28: f32 = v15 * v3;
            let v29: f32 = v27 - v28;
            let v30: f32 = v1 * v5;
            let v31: f32 = v29 * v30;
            let v32: f32 = v19 - v31;
            let v33: f32 = v20 * v25;
            let v34: f32 = v7 * v12;
            let v35: f32 = v33 + v34;
            let v36: f32 = v35 * v3;
            let v37: f32 = v8 * v18;
            let v38: f32 = v8 * v37;
            let v39: f32 = v36 - v38;
            let v40: f32 = v20 * v18;
            let v41: f32 = v7 * v30;
            let v42: f32 = v40 + v41;
            let v43: f32 = v20 * v42;
            let v44: f32 = v39 - v43;
            let v45: f32 = qdd[1];
            let v46: f32 = v45 * v30;
            let v47: f32 = v44 + v46;
            let v48: f32 = v10 * v18;
            let v49: f32 = v7 * v37;
            let v50: f32 = v48 - v49;
            let v51: f32 = v17 * v3;
            let v52: f32 = v50 + v51;
            let v53: f32 = v8 * v30;
            let v54: f32 = v20 * v53;
            let v55: f32 = v52 + v54;
            let v56: f32 = v23 * v30;
            let v57: f32 = v55 - v56;
            let v58: f32 = v29 * v5;
            let v59: f32 = v57 - v58;
            let v60: f32 = v45 * v18;
            let v61: f32 = v8 * v53;
            let v62: f32 = v60 + v61;
            let v63: f32 = v7 * v42;
            let v64: f32 = v62 + v63;
            let v65: f32 = v35 * v5;
            let v66: f32 = v64 - v65;
            let v67: f32 = v8 * v3;
            let v68: f32 = v7 * v67;
            let v69: f32 = v23 * v5;
            let v70: f32 = v68 + v69;
            let v71: f32 = -v70;
            let v72: f32 = v8 * v67;
            let v73: f32 = v7 * v3;
            let v74: f32 = v20 * v5;
            let v75: f32 = v73 - v74;
            let v76: f32 = v7 * v75;
            let v77: f32 = v72 - v76;
            let v78: f32 = v45 * v5;
            let v79: f32 = v77 - v78;
            let v80: f32 = v8 * v5;
            let v81: f32 = v7 * v80;
            let v82: f32 = v20 * v67;
            let v83: f32 = v23 * v3;
            let v84: f32 = v82 + v83;
            let v85: f32 = v81 - v84;
            let v86: f32 = v10 * v5;
            let v87: f32 = v85 + v86;
            let v88: f32 = v8 * v75;
            let v89: f32 = v45 * v3;
            let v90: f32 = v20 * v75;
            let v91: f32 = v89 + v90;
            let v92: f32 = v8 * v80;
            let v93: f32 = v91 + v92;
            let v94: f32 = -v93;
            let v95: f32 = v10 * v3;
            let v96: f32 = v20 * v80;
            let v97: f32 = v95 + v96;
            let v98: f32 = q[2];
            let (v107, v99): (f32, f32) = ::libm::sincosf(v98);
            let v100: f32 = 0.425_f32;
            let v101: f32 = v100 * v45;
            let v102: f32 = v100 * v7;
            let v103: f32 = v20 * v102;
            let v104: f32 = v101 + v103;
            let v105: f32 = v17 + v104;
            let v106: f32 = v99 * v105;
            let v108: f32 = v7 * v102;
            let v109: f32 = v100 * v8;
            let v110: f32 = v8 * v109;
            let v111: f32 = v108 + v110;
            let v112: f32 = v29 - v111;
            let v113: f32 = v107 * v112;
            let v114: f32 = v106 - v113;
            let v115: f32 = qd[2];
            let v116: f32 = v8 + v115;
            let v117: f32 = -0.1197_f32;
            let v118: f32 = v107 * v20;
            let v119: f32 = v99 * v7;
            let v120: f32 = v118 - v119;
            let v121: f32 = v117 * v120;
            let v122: f32 = v116 * v121;
            let v123: f32 = v107 * v23;
            let v124: f32 = v99 * v10;
            let v125: f32 = v123 - v124;
            let v126: f32 = v120 * v115;
            let v127: f32 = v125 + v126;
            let v128: f32 = v117 * v127;
            let v129: f32 = v122 - v128;
            let v130: f32 = v114 + v129;
            let v131: f32 = v99 * v18;
            let v132: f32 = v107 * v30;
            let v133: f32 = v131 + v132;
            let v134: f32 = v99 * v3;
            let v135: f32 = v107 * v5;
            let v136: f32 = v134 + v135;
            let v137: f32 = v117 * v136;
            let v138: f32 = v133 + v137;
            let v139: f32 = v130 * v138;
            let v140: f32 = v100 * v23;
            let v141: f32 = v20 * v109;
            let v142: f32 = v140 + v141;
            let v143: f32 = v35 + v142;
            let v144: f32 = v107 * v7;
            let v145: f32 = v99 * v20;
            let v146: f32 = v144 + v145;
            let v147: f32 = v117 * v146;
            let v148: f32 = v146 * v147;
            let v149: f32 = v120 * v121;
            let v150: f32 = v148 + v149;
            let v151: f32 = v143 + v150;
            let v152: f32 = v100 * v5;
            let v153: f32 = v151 * v152;
            let v154: f32 = v139 - v153;
            let v155: f32 = v107 * v105;
            let v156: f32 = v99 * v112;
            let v157: f32 = v155 + v156;
            let v158: f32 = v99 * v23;
            let v159: f32 = v107 * v10;
            let v160: f32 = v158 + v159;
            let v161: f32 = v146 * v115;
            let v162: f32 = v160 + v161;
            let v163: f32 = v117 * v162;
            let v164: f32 = v116 * v147;
            let v165: f32 = v163 - v164;
            let v166: f32 = v157 + v165;
            let v167: f32 = v107 * v18;
            let v168: f32 = v99 * v30;
            let v169: f32 = v167 - v168;
            let v170: f32 = v107 * v3;
            let v171: f32 = v99 * v5;
            let v172: f32 = v170 - v171;
            let v173: f32 = v117 * v172;
            let v174: f32 = v169 + v173;
            let v175: f32 = v166 * v174;
            let v176: f32 = v154 + v175;
            let v177: f32 = v127 * v152;
            let v178: f32 = v116 * v138;
            let v179: f32 = v120 * v152;
            let v180: f32 = v178 - v179;
            let v181: f32 = v116 * v180;
            let v182: f32 = v177 - v181;
            let v183: f32 = v151 * v136;
            let v184: f32 = v182 + v183;
            let v185: f32 = v146 * v138;
            let v186: f32 = v120 * v174;
            let v187: f32 = v185 + v186;
            let v188: f32 = v146 * v187;
            let v189: f32 = v184 - v188;
            let v190: f32 = qdd[2];
            let v191: f32 = v45 + v190;
            let v192: f32 = v191 * v174;
            let v193: f32 = v189 - v192;
            (
                v0,
                v4,
                v7,
                v8,
                v17,
                v20,
                v23,
                v29,
                v32,
                v45,
                v47,
                v59,
                v66,
                v71,
                v79,
                v87,
                v88,
                v94,
                v97,
                v99,
                v100,
                v107,
                v116,
                v120,
                v127,
                v130,
                v136,
                v138,
                v146,
                v151,
                v152,
                v162,
                v166,
                v172,
                v174,
                v176,
                v180,
                v187,
                v191,
                v193,
            )
        };
        let (
            v207,
            v216,
            v220,
            v228,
            v236,
            v237,
            v242,
            v246,
            v248,
            v249,
            v256,
            v263,
            v270,
            v273,
            v279,
            v281,
            v283,
            v286,
            v289,
            v295,
            v299,
            v309,
            v314,
            v316,
            v322,
            v334,
            v338,
            v347,
            v352,
            v360,
            v368,
            v369,
            v374,
            v377,
            v378,
            v379,
            v383,
            v385,
            v386,
            v387,
        ) = {
            let v194: f32 = v120 * v180;
            let v195: f32 = v127 * v138;
            let v196: f32 = v194 - v195;
            let v197: f32 = v130 * v136;
            let v198: f32 = v196 + v197;
            let v199: f32 = v146 * v152;
            let v200: f32 = v116 * v174;
            let v201: f32 = v199 + v200;
            let v202: f32 = v146 * v201;
            let v203: f32 = v198 - v202;
            let v204: f32 = v162 * v174;
            let v205: f32 = v203 + v204;
            let v206: f32 = v166 * v172;
            let v207: f32 = v205 + v206;
            let v208: f32 = v191 * v138;
            let v209: f32 = v162 * v152;
            let v210: f32 = v208 - v209;
            let v211: f32 = v116 * v201;
            let v212: f32 = v210 - v211;
            let v213: f32 = v120 * v187;
            let v214: f32 = v212 - v213;
            let v215: f32 = v151 * v172;
            let v216: f32 = v214 + v215;
            let v217: f32 = v116 * v136;
            let v218: f32 = v120 * v217;
            let v219: f32 = v162 * v172;
            let v220: f32 = v218 + v219;
            let v221: f32 = v116 * v217;
            let v222: f32 = v146 * v172;
            let v223: f32 = v120 * v136;
            let v224: f32 = v222 - v223;
            let v225: f32 = v120 * v224;
            let v226: f32 = v221 + v225;
            let v227: f32 = v191 * v172;
            let v228: f32 = v226 + v227;
            let v229: f32 = v116 * v172;
            let v230: f32 = v120 * v229;
            let v231: f32 = v146 * v217;
            let v232: f32 = v162 * v136;
            let v233: f32 = v231 + v232;
            let v234: f32 = v230 - v233;
            let v235: f32 = v127 * v172;
            let v236: f32 = v234 + v235;
            let v237: f32 = v116 * v224;
            let v238: f32 = v116 * v229;
            let v239: f32 = v191 * v136;
            let v240: f32 = v146 * v224;
            let v241: f32 = v239 + v240;
            let v242: f32 = v238 - v241;
            let v243: f32 = v127 * v136;
            let v244: f32 = v146 * v229;
            let v245: f32 = v243 + v244;
            let v246: f32 = -v245;
            let v247: f32 = q[3];
            let (v256, v248): (f32, f32) = ::libm::sincosf(v247);
            let v249: f32 = 0.39225_f32;
            let v250: f32 = v249 * v191;
            let v251: f32 = v249 * v120;
            let v252: f32 = v146 * v251;
            let v253: f32 = v250 - v252;
            let v254: f32 = v130 + v253;
            let v255: f32 = v248 * v254;
            let v257: f32 = v120 * v251;
            let v258: f32 = v249 * v116;
            let v259: f32 = v116 * v258;
            let v260: f32 = v257 + v259;
            let v261: f32 = v166 - v260;
            let v262: f32 = v256 * v261;
            let v263: f32 = v255 - v262;
            let v264: f32 = v248 * v138;
            let v265: f32 = v256 * v174;
            let v266: f32 = v264 - v265;
            let v267: f32 = v263 * v266;
            let v268: f32 = v256 * v254;
            let v269: f32 = v248 * v261;
            let v270: f32 = v268 + v269;
            let v271: f32 = v256 * v138;
            let v272: f32 = v248 * v174;
            let v273: f32 = v271 + v272;
            let v274: f32 = v270 * v273;
            let v275: f32 = v267 + v274;
            let v276: f32 = v249 * v162;
            let v277: f32 = v146 * v258;
            let v278: f32 = v276 + v277;
            let v279: f32 = v151 + v278;
            let v280: f32 = v249 * v172;
            let v281: f32 = v152 - v280;
            let v282: f32 = v279 * v281;
            let v283: f32 = v275 - v282;
            let v284: f32 = v248 * v120;
            let v285: f32 = v256 * v146;
            let v286: f32 = v284 + v285;
            let v287: f32 = v248 * v146;
            let v288: f32 = v256 * v120;
            let v289: f32 = v287 - v288;
            let v290: f32 = v289 * v266;
            let v291: f32 = v286 * v273;
            let v292: f32 = v290 + v291;
            let v293: f32 = v286 * v292;
            let v294: f32 = qdd[3];
            let v295: f32 = v191 + v294;
            let v296: f32 = v295 * v266;
            let v297: f32 = v293 - v296;
            let v298: f32 = qd[3];
            let v299: f32 = v116 + v298;
            let v300: f32 = v299 * v273;
            let v301: f32 = v289 * v281;
            let v302: f32 = v300 + v301;
            let v303: f32 = v299 * v302;
            let v304: f32 = v297 + v303;
            let v305: f32 = v248 * v162;
            let v306: f32 = v256 * v127;
            let v307: f32 = v305 - v306;
            let v308: f32 = v289 * v298;
            let v309: f32 = v307 + v308;
            let v310: f32 = v309 * v281;
            let v311: f32 = v304 + v310;
            let v312: f32 = v256 * v136;
            let v313: f32 = v248 * v172;
            let v314: f32 = v312 + v313;
            let v315: f32 = v279 * v314;
            let v316: f32 = v311 - v315;
            let v317: f32 = v309 * v273;
            let v318: f32 = v256 * v162;
            let v319: f32 = v248 * v127;
            let v320: f32 = v318 + v319;
            let v321: f32 = v286 * v298;
            let v322: f32 = v320 + v321;
            let v323: f32 = v322 * v266;
            let v324: f32 = v317 - v323;
            let v325: f32 = v289 * v302;
            let v326: f32 = v324 - v325;
            let v327: f32 = v286 * v281;
            let v328: f32 = v299 * v266;
            let v329: f32 = v327 - v328;
            let v330: f32 = v286 * v329;
            let v331: f32 = v326 - v330;
            let v332: f32 = v248 * v136;
            let v333: f32 = v256 * v172;
            let v334: f32 = v332 - v333;
            let v335: f32 = v263 * v334;
            let v336: f32 = v331 + v335;
            let v337: f32 = v270 * v314;
            let v338: f32 = v336 + v337;
            let v339: f32 = v299 * v329;
            let v340: f32 = v289 * v292;
            let v341: f32 = v295 * v273;
            let v342: f32 = v340 + v341;
            let v343: f32 = v339 - v342;
            let v344: f32 = v322 * v281;
            let v345: f32 = v343 + v344;
            let v346: f32 = v279 * v334;
            let v347: f32 = v345 + v346;
            let v348: f32 = v322 * v334;
            let v349: f32 = v299 * v314;
            let v350: f32 = v289 * v349;
            let v351: f32 = v348 + v350;
            let v352: f32 = -v351;
            let v353: f32 = v295 * v334;
            let v354: f32 = v299 * v349;
            let v355: f32 = v353 - v354;
            let v356: f32 = v289 * v314;
            let v357: f32 = v286 * v334;
            let v358: f32 = v356 - v357;
            let v359: f32 = v289 * v358;
            let v360: f32 = v355 + v359;
            let v361: f32 = v299 * v334;
            let v362: f32 = v289 * v361;
            let v363: f32 = v309 * v334;
            let v364: f32 = v362 + v363;
            let v365: f32 = v286 * v349;
            let v366: f32 = v364 - v365;
            let v367: f32 = v322 * v314;
            let v368: f32 = v366 - v367;
            let v369: f32 = v299 * v358;
            let v370: f32 = v299 * v361;
            let v371: f32 = v286 * v358;
            let v372: f32 = v370 + v371;
            let v373: f32 = v295 * v314;
            let v374: f32 = v372 + v373;
            let v375: f32 = v286 * v361;
            let v376: f32 = v309 * v314;
            let v377: f32 = v375 + v376;
            let v378: f32 = 0.093_f32;
            let v379: f32 = v378 * v286;
            let v380: f32 = v299 * v379;
            let v381: f32 = v378 * v322;
            let v382: f32 = v380 - v381;
            let v383: f32 = v263 + v382;
            let v384: f32 = v378 * v334;
            let v385: f32 = v266 + v384;
            let v386: f32 = v383 * v385;
            let v387: f32 = q[4];
            (
                v207,
                v216,
                v220,
                v228,
                v236,
                v237,
                v242,
                v246,
                v248,
                v249,
                v256,
                v263,
                v270,
                v273,
                v279,
                v281,
                v283,
                v286,
                v289,
                v295,
                v299,
                v309,
                v314,
                v316,
                v322,
                v334,
                v338,
                v347,
                v352,
                v360,
                v368,
                v369,
                v374,
                v377,
                v378,
                v379,
                v383,
                v385,
                v386,
                v387,
            )
        };
        let (
            v388,
            v395,
            v401,
            v411,
            v416,
            v417,
            v424,
            v427,
            v431,
            v434,
            v442,
            v449,
            v454,
            v456,
            v469,
            v480,
            v486,
            v496,
            v506,
            v509,
            v516,
            v519,
            v520,
            v525,
            v527,
            v530,
            v537,
            v543,
            v548,
            v553,
            v556,
            v558,
            v565,
            v566,
            v568,
            v572,
            v574,
            v577,
            v580,
            v581,
        ) = {
            let (v388, v395): (f32, f32) = ::libm::sincosf(v387);
            let v389: f32 = v378 * v289;
            let v390: f32 = v299 * v389;
            let v391: f32 = v378 * v309;
            let v392: f32 = v390 - v391;
            let v393: f32 = v392 - v270;
            let v394: f32 = v388 * v393;
            let v396: f32 = v286 * v379;
            let v397: f32 = v289 * v389;
            let v398: f32 = v396 + v397;
            let v399: f32 = v279 + v398;
            let v400: f32 = v395 * v399;
            let v401: f32 = v394 + v400;
            let v402: f32 = v395 * v281;
            let v403: f32 = v378 * v314;
            let v404: f32 = v273 + v403;
            let v405: f32 = v388 * v404;
            let v406: f32 = v402 + v405;
            let v407: f32 = v401 * v406;
            let v408: f32 = v386 - v407;
            let v409: f32 = v395 * v393;
            let v410: f32 = v388 * v399;
            let v411: f32 = v409 - v410;
            let v412: f32 = v388 * v281;
            let v413: f32 = v395 * v404;
            let v414: f32 = v412 - v413;
            let v415: f32 = v411 * v414;
            let v416: f32 = v408 + v415;
            let v417: f32 = v388 * v334;
            let v418: f32 = v383 * v417;
            let v419: f32 = v388 * v322;
            let v420: f32 = v395 * v295;
            let v421: f32 = v419 + v420;
            let v422: f32 = v395 * v289;
            let v423: f32 = v388 * v299;
            let v424: f32 = v422 + v423;
            let v425: f32 = qd[4];
            let v426: f32 = v424 * v425;
            let v427: f32 = v421 - v426;
            let v428: f32 = v427 * v385;
            let v429: f32 = v418 - v428;
            let v430: f32 = qdd[4];
            let v431: f32 = v309 + v430;
            let v432: f32 = v431 * v406;
            let v433: f32 = v429 + v432;
            let v434: f32 = v286 + v425;
            let v435: f32 = v424 * v385;
            let v436: f32 = v434 * v414;
            let v437: f32 = v435 - v436;
            let v438: f32 = v434 * v437;
            let v439: f32 = v433 + v438;
            let v440: f32 = v395 * v299;
            let v441: f32 = v388 * v289;
            let v442: f32 = v440 - v441;
            let v443: f32 = v442 * v414;
            let v444: f32 = v424 * v406;
            let v445: f32 = v443 - v444;
            let v446: f32 = v442 * v445;
            let v447: f32 = v439 - v446;
            let v448: f32 = v401 * v314;
            let v449: f32 = v447 - v448;
            let v450: f32 = v388 * v295;
            let v451: f32 = v395 * v322;
            let v452: f32 = v450 - v451;
            let v453: f32 = v442 * v425;
            let v454: f32 = v452 + v453;
            let v455: f32 = v454 * v385;
            let v456: f32 = v395 * v334;
            let v457: f32 = v383 * v456;
            let v458: f32 = v455 + v457;
            let v459: f32 = v434 * v406;
            let v460: f32 = v442 * v385;
            let v461: f32 = v459 - v460;
            let v462: f32 = v434 * v461;
            let v463: f32 = v458 - v462;
            let v464: f32 = v424 * v445;
            let v465: f32 = v463 + v464;
            let v466: f32 = v431 * v414;
            let v467: f32 = v465 - v466;
            let v468: f32 = v411 * v314;
            let v469: f32 = v467 - v468;
            let v470: f32 = v401 * v456;
            let v471: f32 = v411 * v417;
            let v472: f32 = v470 - v471;
            let v473: f32 = v442 * v461;
            let v474: f32 = v472 + v473;
            let v475: f32 = v454 * v406;
            let v476: f32 = v474 - v475;
            let v477: f32 = v424 * v437;
            let v478: f32 = v476 - v477;
            let v479: f32 = v427 * v414;
            let v480: f32 = v478 + v479;
            let v481: f32 = v454 * v456;
            let v482: f32 = v434 * v417;
            let v483: f32 = v442 * v314;
            let v484: f32 = v482 + v483;
            let v485: f32 = v424 * v484;
            let v486: f32 = v481 - v485;
            let v487: f32 = v427 * v456;
            let v488: f32 = v454 * v417;
            let v489: f32 = v487 - v488;
            let v490: f32 = v442 * v484;
            let v491: f32 = v489 - v490;
            let v492: f32 = v424 * v314;
            let v493: f32 = v434 * v456;
            let v494: f32 = v492 - v493;
            let v495: f32 = v424 * v494;
            let v496: f32 = v491 + v495;
            let v497: f32 = v424 * v417;
            let v498: f32 = v442 * v456;
            let v499: f32 = v497 + v498;
            let v500: f32 = v424 * v499;
            let v501: f32 = v431 * v456;
            let v502: f32 = v500 + v501;
            let v503: f32 = v434 * v484;
            let v504: f32 = v502 - v503;
            let v505: f32 = v454 * v314;
            let v506: f32 = v504 + v505;
            let v507: f32 = v442 * v494;
            let v508: f32 = v427 * v417;
            let v509: f32 = v507 - v508;
            let v510: f32 = v442 * v499;
            let v511: f32 = v431 * v417;
            let v512: f32 = v510 - v511;
            let v513: f32 = v434 * v494;
            let v514: f32 = v512 + v513;
            let v515: f32 = v427 * v314;
            let v516: f32 = v514 + v515;
            let v517: f32 = v434 * v499;
            let v518: f32 = v431 * v314;
            let v519: f32 = v517 + v518;
            let v520: f32 = 0.09465_f32;
            let v521: f32 = v520 * v442;
            let v522: f32 = v434 * v521;
            let v523: f32 = v520 * v454;
            let v524: f32 = v522 - v523;
            let v525: f32 = v524 - v401;
            let v526: f32 = v520 * v456;
            let v527: f32 = v406 - v526;
            let v528: f32 = v525 * v527;
            let v529: f32 = q[5];
            let (v530, v537): (f32, f32) = ::libm::sincosf(v529);
            let v531: f32 = v520 * v427;
            let v532: f32 = v520 * v424;
            let v533: f32 = v434 * v532;
            let v534: f32 = v531 + v533;
            let v535: f32 = v411 + v534;
            let v536: f32 = v530 * v535;
            let v538: f32 = v424 * v532;
            let v539: f32 = v442 * v521;
            let v540: f32 = v538 + v539;
            let v541: f32 = v383 - v540;
            let v542: f32 = v537 * v541;
            let v543: f32 = v536 + v542;
            let v544: f32 = v537 * v385;
            let v545: f32 = v520 * v417;
            let v546: f32 = v414 - v545;
            let v547: f32 = v530 * v546;
            let v548: f32 = v544 + v547;
            let v549: f32 = v543 * v548;
            let v550: f32 = v528 + v549;
            let v551: f32 = v537 * v535;
            let v552: f32 = v530 * v541;
            let v553: f32 = v551 - v552;
            let v554: f32 = v537 * v546;
            let v555: f32 = v530 * v385;
            let v556: f32 = v554 - v555;
            let v557: f32 = v553 * v556;
            let v558: f32 = v550 + v557;
            let v559: f32 = v543 * v417;
            let v560: f32 = v530 * v454;
            let v561: f32 = v537 * v431;
            let v562: f32 = v560 + v561;
            let v563: f32 = v537 * v424;
            let v564: f32 = v530 * v434;
            let v565: f32 = v563 - v564;
            let v566: f32 = qd[5];
            let v567: f32 = v565 * v566;
            let v568: f32 = v562 + v567;
            let v569: f32 = v568 * v527;
            let v570: f32 = v559 + v569;
            let v571: f32 = qdd[5];
            let v572: f32 = v427 + v571;
            let v573: f32 = v572 * v548;
            let v574: f32 = v570 - v573;
            let v575: f32 = v530 * v424;
            let v576: f32 = v537 * v434;
            let v577: f32 = v575 + v576;
            let v578: f32 = v565 * v548;
            let v579: f32 = v577 * v556;
            let v580: f32 = v578 - v579;
            let v581: f32 = v577 * v580;
            (
                v388,
                v395,
                v401,
                v411,
                v416,
                v417,
                v424,
                v427,
                v431,
                v434,
                v442,
                v449,
                v454,
                v456,
                v469,
                v480,
                v486,
                v496,
                v506,
                v509,
                v516,
                v519,
                v520,
                v525,
                v527,
                v530,
                v537,
                v543,
                v548,
                v553,
                v556,
                v558,
                v565,
                v566,
                v568,
                v572,
                v574,
                v577,
                v580,
                v581,
            )
        };
        let (
            v583,
            v593,
            v598,
            v615,
            v626,
            v632,
            v642,
            v652,
            v655,
            v662,
            v665,
            v666,
            v667,
            v669,
            v672,
            v673,
            v675,
            v680,
            v691,
            v699,
            v705,
            v707,
            v709,
            v712,
            v714,
            v715,
            v719,
            v725,
            v735,
            v743,
            v750,
            v751,
            v753,
            v756,
            v758,
            v760,
            v762,
            v765,
            v767,
            v770,
            v772,
            v775,
        ) = {
            let v582: f32 = v574 + v581;
            let v583: f32 = v442 + v566;
            let v584: f32 = v583 * v556;
            let v585: f32 = v565 * v527;
            let v586: f32 = v584 - v585;
            let v587: f32 = v583 * v586;
            let v588: f32 = v582 - v587;
            let v589: f32 = v530 * v456;
            let v590: f32 = v537 * v314;
            let v591: f32 = v589 + v590;
            let v592: f32 = v525 * v591;
            let v593: f32 = v588 + v592;
            let v594: f32 = v537 * v454;
            let v595: f32 = v530 * v431;
            let v596: f32 = v594 - v595;
            let v597: f32 = v577 * v566;
            let v598: f32 = v596 - v597;
            let v599: f32 = v598 * v548;
            let v600: f32 = v577 * v527;
            let v601: f32 = v583 * v548;
            let v602: f32 = v600 - v601;
            let v603: f32 = v577 * v602;
            let v604: f32 = v599 - v603;
            let v605: f32 = v565 * v586;
            let v606: f32 = v604 + v605;
            let v607: f32 = v568 * v556;
            let v608: f32 = v606 - v607;
            let v609: f32 = v537 * v456;
            let v610: f32 = v530 * v314;
            let v611: f32 = v609 - v610;
            let v612: f32 = v543 * v611;
            let v613: f32 = v608 + v612;
            let v614: f32 = v553 * v591;
            let v615: f32 = v613 - v614;
            let v616: f32 = v583 * v602;
            let v617: f32 = v553 * v417;
            let v618: f32 = v598 * v527;
            let v619: f32 = v617 + v618;
            let v620: f32 = v616 - v619;
            let v621: f32 = v565 * v580;
            let v622: f32 = v620 - v621;
            let v623: f32 = v572 * v556;
            let v624: f32 = v622 + v623;
            let v625: f32 = v525 * v611;
            let v626: f32 = v624 - v625;
            let v627: f32 = v598 * v611;
            let v628: f32 = v577 * v417;
            let v629: f32 = v583 * v591;
            let v630: f32 = v628 + v629;
            let v631: f32 = v565 * v630;
            let v632: f32 = v627 - v631;
            let v633: f32 = v572 * v611;
            let v634: f32 = v598 * v417;
            let v635: f32 = v633 - v634;
            let v636: f32 = v583 * v630;
            let v637: f32 = v635 - v636;
            let v638: f32 = v565 * v591;
            let v639: f32 = v577 * v611;
            let v640: f32 = v638 - v639;
            let v641: f32 = v565 * v640;
            let v642: f32 = v637 + v641;
            let v643: f32 = v565 * v417;
            let v644: f32 = v583 * v611;
            let v645: f32 = v643 + v644;
            let v646: f32 = v565 * v645;
            let v647: f32 = v568 * v611;
            let v648: f32 = v646 + v647;
            let v649: f32 = v577 * v630;
            let v650: f32 = v648 - v649;
            let v651: f32 = v598 * v591;
            let v652: f32 = v650 + v651;
            let v653: f32 = v583 * v640;
            let v654: f32 = v572 * v417;
            let v655: f32 = v653 - v654;
            let v656: f32 = v583 * v645;
            let v657: f32 = v568 * v417;
            let v658: f32 = v656 - v657;
            let v659: f32 = v577 * v640;
            let v660: f32 = v658 + v659;
            let v661: f32 = v572 * v591;
            let v662: f32 = v660 + v661;
            let v663: f32 = v577 * v645;
            let v664: f32 = v568 * v591;
            let v665: f32 = v663 + v664;
            let v666: f32 = -v29;
            let v667: f32 = v7 * v20;
            let v668: f32 = v8 * v20;
            let v669: f32 = v23 - v668;
            let v670: f32 = v20 * v20;
            let v671: f32 = v7 * v7;
            let v672: f32 = v670 - v671;
            let v673: f32 = -v4;
            let v674: f32 = v20 * v7;
            let v675: f32 = -v674;
            let v676: f32 = v100 * v99;
            let v677: f32 = v130 * v676;
            let v678: f32 = v100 * v107;
            let v679: f32 = v166 * v678;
            let v680: f32 = v677 + v679;
            let v681: f32 = v116 * v676;
            let v682: f32 = v116 * v681;
            let v683: f32 = v166 + v682;
            let v684: f32 = v146 * v676;
            let v685: f32 = v120 * v678;
            let v686: f32 = v684 + v685;
            let v687: f32 = v146 * v686;
            let v688: f32 = v683 + v687;
            let v689: f32 = v191 * v678;
            let v690: f32 = v688 + v689;
            let v691: f32 = -v690;
            let v692: f32 = v120 * v681;
            let v693: f32 = v127 * v676;
            let v694: f32 = v692 - v693;
            let v695: f32 = v116 * v678;
            let v696: f32 = v146 * v695;
            let v697: f32 = v694 - v696;
            let v698: f32 = v162 * v678;
            let v699: f32 = v697 + v698;
            let v700: f32 = v191 * v676;
            let v701: f32 = v130 + v700;
            let v702: f32 = v116 * v695;
            let v703: f32 = v701 - v702;
            let v704: f32 = v120 * v686;
            let v705: f32 = v703 - v704;
            let v706: f32 = v120 * v146;
            let v707: f32 = -v706;
            let v708: f32 = v116 * v146;
            let v709: f32 = v162 - v708;
            let v710: f32 = v146 * v146;
            let v711: f32 = v120 * v120;
            let v712: f32 = v710 - v711;
            let v713: f32 = v116 * v120;
            let v714: f32 = v127 - v713;
            let v715: f32 = v146 * v120;
            let v716: f32 = v249 + v676;
            let v717: f32 = v248 * v716;
            let v718: f32 = v256 * v678;
            let v719: f32 = v717 - v718;
            let v720: f32 = v263 * v719;
            let v721: f32 = v256 * v716;
            let v722: f32 = v248 * v678;
            let v723: f32 = v721 + v722;
            let v724: f32 = v270 * v723;
            let v725: f32 = v720 + v724;
            let v726: f32 = v289 * v719;
            let v727: f32 = v286 * v723;
            let v728: f32 = v726 + v727;
            let v729: f32 = v286 * v728;
            let v730: f32 = v295 * v719;
            let v731: f32 = v263 + v730;
            let v732: f32 = v729 - v731;
            let v733: f32 = v299 * v723;
            let v734: f32 = v299 * v733;
            let v735: f32 = v732 + v734;
            let v736: f32 = v309 * v723;
            let v737: f32 = v322 * v719;
            let v738: f32 = v736 - v737;
            let v739: f32 = v289 * v733;
            let v740: f32 = v738 - v739;
            let v741: f32 = v299 * v719;
            let v742: f32 = v286 * v741;
            let v743: f32 = v740 + v742;
            let v744: f32 = v289 * v728;
            let v745: f32 = v270 + v744;
            let v746: f32 = v295 * v723;
            let v747: f32 = v745 + v746;
            let v748: f32 = v299 * v741;
            let v749: f32 = v747 + v748;
            let v750: f32 = -v749;
            let v751: f32 = v289 * v286;
            let v752: f32 = v299 * v286;
            let v753: f32 = v752 - v322;
            let v754: f32 = v286 * v286;
            let v755: f32 = v289 * v289;
            let v756: f32 = v754 - v755;
            let v757: f32 = v299 * v289;
            let v758: f32 = v309 - v757;
            let v759: f32 = v286 * v289;
            let v760: f32 = -v759;
            let v761: f32 = v383 * v719;
            let v762: f32 = v388 * v723;
            let v763: f32 = v401 * v762;
            let v764: f32 = v761 - v763;
            let v765: f32 = v395 * v723;
            let v766: f32 = v411 * v765;
            let v767: f32 = v764 - v766;
            let v768: f32 = v431 * v762;
            let v769: f32 = v427 * v719;
            let v770: f32 = v383 * v395;
            let v771: f32 = v769 + v770;
            let v772: f32 = v768 - v771;
            let v773: f32 = v424 * v719;
            let v774: f32 = v434 * v765;
            let v775: f32 = v773 + v774;
            (
                v583,
                v593,
                v598,
                v615,
                v626,
                v632,
                v642,
                v652,
                v655,
                v662,
                v665,
                v666,
                v667,
                v669,
                v672,
                v673,
                v675,
                v680,
                v691,
                v699,
                v705,
                v707,
                v709,
                v712,
                v714,
                v715,
                v719,
                v725,
                v735,
                v743,
                v750,
                v751,
                v753,
                v756,
                v758,
                v760,
                v762,
                v765,
                v767,
                v770,
                v772,
                v775,
            )
        };
        let (
            v782,
            v784,
            v794,
            v797,
            v805,
            v809,
            v817,
            v825,
            v828,
            v833,
            v834,
            v835,
            v839,
            v849,
            v851,
            v866,
            v867,
            v879,
            v881,
            v882,
            v883,
            v892,
            v893,
            v899,
            v909,
            v919,
            v922,
            v929,
            v932,
            v933,
            v934,
            v939,
            v949,
            v957,
            v963,
            v965,
            v967,
            v968,
            v969,
        ) = {
            let v776: f32 = v434 * v775;
            let v777: f32 = v772 + v776;
            let v778: f32 = v424 * v762;
            let v779: f32 = v442 * v765;
            let v780: f32 = v778 + v779;
            let v781: f32 = v442 * v780;
            let v782: f32 = v777 + v781;
            let v783: f32 = v454 * v719;
            let v784: f32 = v383 * v388;
            let v785: f32 = v783 + v784;
            let v786: f32 = v434 * v762;
            let v787: f32 = v442 * v719;
            let v788: f32 = v786 - v787;
            let v789: f32 = v434 * v788;
            let v790: f32 = v785 - v789;
            let v791: f32 = v424 * v780;
            let v792: f32 = v790 - v791;
            let v793: f32 = v431 * v765;
            let v794: f32 = v792 + v793;
            let v795: f32 = v411 * v395;
            let v796: f32 = v401 * v388;
            let v797: f32 = v795 + v796;
            let v798: f32 = v442 * v788;
            let v799: f32 = v797 + v798;
            let v800: f32 = v454 * v762;
            let v801: f32 = v799 - v800;
            let v802: f32 = v424 * v775;
            let v803: f32 = v801 - v802;
            let v804: f32 = v427 * v765;
            let v805: f32 = v803 - v804;
            let v806: f32 = v454 * v388;
            let v807: f32 = v434 * v395;
            let v808: f32 = v424 * v807;
            let v809: f32 = v806 + v808;
            let v810: f32 = v454 * v395;
            let v811: f32 = v427 * v388;
            let v812: f32 = v810 + v811;
            let v813: f32 = v442 * v807;
            let v814: f32 = v812 + v813;
            let v815: f32 = v434 * v388;
            let v816: f32 = v424 * v815;
            let v817: f32 = v814 - v816;
            let v818: f32 = v442 * v388;
            let v819: f32 = v424 * v395;
            let v820: f32 = v818 - v819;
            let v821: f32 = v424 * v820;
            let v822: f32 = v431 * v388;
            let v823: f32 = v821 + v822;
            let v824: f32 = v434 * v807;
            let v825: f32 = v823 + v824;
            let v826: f32 = v427 * v395;
            let v827: f32 = v442 * v815;
            let v828: f32 = v826 - v827;
            let v829: f32 = v431 * v395;
            let v830: f32 = v442 * v820;
            let v831: f32 = v829 + v830;
            let v832: f32 = v434 * v815;
            let v833: f32 = v831 - v832;
            let v834: f32 = v434 * v820;
            let v835: f32 = v520 * v388;
            let v836: f32 = v762 - v835;
            let v837: f32 = v525 * v836;
            let v838: f32 = v537 * v719;
            let v839: f32 = v520 * v395;
            let v840: f32 = v839 - v765;
            let v841: f32 = v530 * v840;
            let v842: f32 = v838 + v841;
            let v843: f32 = v543 * v842;
            let v844: f32 = v837 + v843;
            let v845: f32 = v537 * v840;
            let v846: f32 = v530 * v719;
            let v847: f32 = v845 - v846;
            let v848: f32 = v553 * v847;
            let v849: f32 = v844 + v848;
            let v850: f32 = v568 * v836;
            let v851: f32 = v543 * v395;
            let v852: f32 = v850 - v851;
            let v853: f32 = v572 * v842;
            let v854: f32 = v852 - v853;
            let v855: f32 = v565 * v842;
            let v856: f32 = v577 * v847;
            let v857: f32 = v855 - v856;
            let v858: f32 = v577 * v857;
            let v859: f32 = v854 + v858;
            let v860: f32 = v583 * v847;
            let v861: f32 = v565 * v836;
            let v862: f32 = v860 - v861;
            let v863: f32 = v583 * v862;
            let v864: f32 = v859 - v863;
            let v865: f32 = v530 * v388;
            let v866: f32 = v525 * v865;
            let v867: f32 = v864 + v866;
            let v868: f32 = v598 * v842;
            let v869: f32 = v577 * v836;
            let v870: f32 = v583 * v842;
            let v871: f32 = v869 - v870;
            let v872: f32 = v577 * v871;
            let v873: f32 = v868 - v872;
            let v874: f32 = v565 * v862;
            let v875: f32 = v873 + v874;
            let v876: f32 = v568 * v847;
            let v877: f32 = v875 - v876;
            let v878: f32 = v537 * v388;
            let v879: f32 = v543 * v878;
            let v880: f32 = v877 + v879;
            let v881: f32 = v553 * v865;
            let v882: f32 = v880 - v881;
            let v883: f32 = v553 * v395;
            let v884: f32 = v598 * v836;
            let v885: f32 = v883 - v884;
            let v886: f32 = v583 * v871;
            let v887: f32 = v885 + v886;
            let v888: f32 = v565 * v857;
            let v889: f32 = v887 - v888;
            let v890: f32 = v572 * v847;
            let v891: f32 = v889 + v890;
            let v892: f32 = v525 * v878;
            let v893: f32 = v891 - v892;
            let v894: f32 = v598 * v878;
            let v895: f32 = v577 * v395;
            let v896: f32 = v583 * v865;
            let v897: f32 = v895 - v896;
            let v898: f32 = v565 * v897;
            let v899: f32 = v894 + v898;
            let v900: f32 = v598 * v395;
            let v901: f32 = v572 * v878;
            let v902: f32 = v900 + v901;
            let v903: f32 = v583 * v897;
            let v904: f32 = v902 + v903;
            let v905: f32 = v565 * v865;
            let v906: f32 = v577 * v878;
            let v907: f32 = v905 - v906;
            let v908: f32 = v565 * v907;
            let v909: f32 = v904 + v908;
            let v910: f32 = v583 * v878;
            let v911: f32 = v565 * v395;
            let v912: f32 = v910 - v911;
            let v913: f32 = v565 * v912;
            let v914: f32 = v568 * v878;
            let v915: f32 = v913 + v914;
            let v916: f32 = v577 * v897;
            let v917: f32 = v915 + v916;
            let v918: f32 = v598 * v865;
            let v919: f32 = v917 + v918;
            let v920: f32 = v572 * v395;
            let v921: f32 = v583 * v907;
            let v922: f32 = v920 + v921;
            let v923: f32 = v568 * v395;
            let v924: f32 = v583 * v912;
            let v925: f32 = v923 + v924;
            let v926: f32 = v577 * v907;
            let v927: f32 = v925 + v926;
            let v928: f32 = v572 * v865;
            let v929: f32 = v927 + v928;
            let v930: f32 = v577 * v912;
            let v931: f32 = v568 * v865;
            let v932: f32 = v930 + v931;
            let v933: f32 = -v166;
            let v934: f32 = v249 * v248;
            let v935: f32 = v263 * v934;
            let v936: f32 = -0.39225_f32;
            let v937: f32 = v936 * v256;
            let v938: f32 = v270 * v937;
            let v939: f32 = v935 - v938;
            let v940: f32 = v289 * v934;
            let v941: f32 = v286 * v937;
            let v942: f32 = v940 - v941;
            let v943: f32 = v286 * v942;
            let v944: f32 = v295 * v934;
            let v945: f32 = v263 + v944;
            let v946: f32 = v943 - v945;
            let v947: f32 = v299 * v937;
            let v948: f32 = v299 * v947;
            let v949: f32 = v946 - v948;
            let v950: f32 = v289 * v947;
            let v951: f32 = v322 * v934;
            let v952: f32 = v309 * v937;
            let v953: f32 = v951 + v952;
            let v954: f32 = v950 - v953;
            let v955: f32 = v299 * v934;
            let v956: f32 = v286 * v955;
            let v957: f32 = v954 + v956;
            let v958: f32 = v295 * v937;
            let v959: f32 = v289 * v942;
            let v960: f32 = v270 + v959;
            let v961: f32 = v958 - v960;
            let v962: f32 = v299 * v955;
            let v963: f32 = v961 - v962;
            let v964: f32 = v383 * v934;
            let v965: f32 = v388 * v937;
            let v966: f32 = v401 * v965;
            let v967: f32 = v964 + v966;
            let v968: f32 = v395 * v937;
            let v969: f32 = v411 * v968;
            (
                v782,
                v784,
                v794,
                v797,
                v805,
                v809,
                v817,
                v825,
                v828,
                v833,
                v834,
                v835,
                v839,
                v849,
                v851,
                v866,
                v867,
                v879,
                v881,
                v882,
                v883,
                v892,
                v893,
                v899,
                v909,
                v919,
                v922,
                v929,
                v932,
                v933,
                v934,
                v939,
                v949,
                v957,
                v963,
                v965,
                v967,
                v968,
                v969,
            )
        };
        let (
            v970,
            v984,
            v995,
            v1003,
            v1016,
            v1031,
            v1043,
            v1052,
            v1053,
            v1054,
            v1055,
            v1062,
            v1077,
            v1089,
            v1098,
            v1099,
            v1100,
            v1102,
            v1105,
            v1107,
            v1108,
            v1110,
            v1111,
            v1115,
            v1116,
            v1121,
            v1129,
            v1137,
            v1138,
            v1143,
            v1146,
            v1147,
            v1148,
            v1150,
            v1153,
            v1155,
            v1157,
            v1158,
        ) = {
            let v970: f32 = v967 + v969;
            let v971: f32 = v424 * v934;
            let v972: f32 = v434 * v968;
            let v973: f32 = v971 - v972;
            let v974: f32 = v434 * v973;
            let v975: f32 = v427 * v934;
            let v976: f32 = v975 + v770;
            let v977: f32 = v431 * v965;
            let v978: f32 = v976 + v977;
            let v979: f32 = v974 - v978;
            let v980: f32 = v424 * v965;
            let v981: f32 = v442 * v968;
            let v982: f32 = v980 + v981;
            let v983: f32 = v442 * v982;
            let v984: f32 = v979 - v983;
            let v985: f32 = v454 * v934;
            let v986: f32 = v985 + v784;
            let v987: f32 = v442 * v934;
            let v988: f32 = v434 * v965;
            let v989: f32 = v987 + v988;
            let v990: f32 = v434 * v989;
            let v991: f32 = v986 + v990;
            let v992: f32 = v424 * v982;
            let v993: f32 = v991 + v992;
            let v994: f32 = v431 * v968;
            let v995: f32 = v993 - v994;
            let v996: f32 = v442 * v989;
            let v997: f32 = v797 - v996;
            let v998: f32 = v454 * v965;
            let v999: f32 = v997 + v998;
            let v1000: f32 = v424 * v973;
            let v1001: f32 = v999 - v1000;
            let v1002: f32 = v427 * v968;
            let v1003: f32 = v1001 + v1002;
            let v1004: f32 = v537 * v934;
            let v1005: f32 = v839 + v968;
            let v1006: f32 = v530 * v1005;
            let v1007: f32 = v1004 + v1006;
            let v1008: f32 = v543 * v1007;
            let v1009: f32 = v835 + v965;
            let v1010: f32 = v525 * v1009;
            let v1011: f32 = v1008 - v1010;
            let v1012: f32 = v537 * v1005;
            let v1013: f32 = v530 * v934;
            let v1014: f32 = v1012 - v1013;
            let v1015: f32 = v553 * v1014;
            let v1016: f32 = v1011 + v1015;
            let v1017: f32 = v565 * v1007;
            let v1018: f32 = v577 * v1014;
            let v1019: f32 = v1017 - v1018;
            let v1020: f32 = v577 * v1019;
            let v1021: f32 = v568 * v1009;
            let v1022: f32 = v851 + v1021;
            let v1023: f32 = v572 * v1007;
            let v1024: f32 = v1022 + v1023;
            let v1025: f32 = v1020 - v1024;
            let v1026: f32 = v565 * v1009;
            let v1027: f32 = v583 * v1014;
            let v1028: f32 = v1026 + v1027;
            let v1029: f32 = v583 * v1028;
            let v1030: f32 = v1025 - v1029;
            let v1031: f32 = v1030 + v866;
            let v1032: f32 = v577 * v1009;
            let v1033: f32 = v583 * v1007;
            let v1034: f32 = v1032 + v1033;
            let v1035: f32 = v577 * v1034;
            let v1036: f32 = v598 * v1007;
            let v1037: f32 = v1035 + v1036;
            let v1038: f32 = v565 * v1028;
            let v1039: f32 = v1037 + v1038;
            let v1040: f32 = v568 * v1014;
            let v1041: f32 = v1039 - v1040;
            let v1042: f32 = v1041 + v879;
            let v1043: f32 = v1042 - v881;
            let v1044: f32 = v598 * v1009;
            let v1045: f32 = v883 + v1044;
            let v1046: f32 = v583 * v1034;
            let v1047: f32 = v1045 - v1046;
            let v1048: f32 = v565 * v1019;
            let v1049: f32 = v1047 - v1048;
            let v1050: f32 = v572 * v1014;
            let v1051: f32 = v1049 + v1050;
            let v1052: f32 = v1051 - v892;
            let v1053: f32 = -v263;
            let v1054: f32 = -v270;
            let v1055: f32 = -v770;
            let v1056: f32 = v530 * v839;
            let v1057: f32 = v543 * v1056;
            let v1058: f32 = v525 * v835;
            let v1059: f32 = v1057 - v1058;
            let v1060: f32 = v537 * v839;
            let v1061: f32 = v553 * v1060;
            let v1062: f32 = v1059 + v1061;
            let v1063: f32 = v565 * v1056;
            let v1064: f32 = v577 * v1060;
            let v1065: f32 = v1063 - v1064;
            let v1066: f32 = v577 * v1065;
            let v1067: f32 = v568 * v835;
            let v1068: f32 = v851 + v1067;
            let v1069: f32 = v572 * v1056;
            let v1070: f32 = v1068 + v1069;
            let v1071: f32 = v1066 - v1070;
            let v1072: f32 = v565 * v835;
            let v1073: f32 = v583 * v1060;
            let v1074: f32 = v1072 + v1073;
            let v1075: f32 = v583 * v1074;
            let v1076: f32 = v1071 - v1075;
            let v1077: f32 = v1076 + v866;
            let v1078: f32 = v577 * v835;
            let v1079: f32 = v583 * v1056;
            let v1080: f32 = v1078 + v1079;
            let v1081: f32 = v577 * v1080;
            let v1082: f32 = v598 * v1056;
            let v1083: f32 = v1081 + v1082;
            let v1084: f32 = v565 * v1074;
            let v1085: f32 = v1083 + v1084;
            let v1086: f32 = v568 * v1060;
            let v1087: f32 = v1085 - v1086;
            let v1088: f32 = v1087 + v879;
            let v1089: f32 = v1088 - v881;
            let v1090: f32 = v598 * v835;
            let v1091: f32 = v883 + v1090;
            let v1092: f32 = v583 * v1080;
            let v1093: f32 = v1091 - v1092;
            let v1094: f32 = v565 * v1065;
            let v1095: f32 = v1093 - v1094;
            let v1096: f32 = v572 * v1060;
            let v1097: f32 = v1095 + v1096;
            let v1098: f32 = v1097 - v892;
            let v1099: f32 = -v401;
            let v1100: f32 = -v411;
            let v1101: f32 = v424 * v442;
            let v1102: f32 = -v1101;
            let v1103: f32 = v424 * v424;
            let v1104: f32 = v442 * v442;
            let v1105: f32 = v1103 - v1104;
            let v1106: f32 = v434 * v442;
            let v1107: f32 = v454 - v1106;
            let v1108: f32 = v442 * v424;
            let v1109: f32 = v434 * v424;
            let v1110: f32 = v1109 + v427;
            let v1111: f32 = v525 * v537;
            let v1112: f32 = v543 * v530;
            let v1113: f32 = v553 * v537;
            let v1114: f32 = v1112 + v1113;
            let v1115: f32 = -v1114;
            let v1116: f32 = v525 * v530;
            let v1117: f32 = v598 * v530;
            let v1118: f32 = v583 * v537;
            let v1119: f32 = v565 * v1118;
            let v1120: f32 = v1117 + v1119;
            let v1121: f32 = -v1120;
            let v1122: f32 = v577 * v530;
            let v1123: f32 = v565 * v537;
            let v1124: f32 = v1122 + v1123;
            let v1125: f32 = v565 * v1124;
            let v1126: f32 = v572 * v530;
            let v1127: f32 = v583 * v1118;
            let v1128: f32 = v1126 + v1127;
            let v1129: f32 = v1125 - v1128;
            let v1130: f32 = v598 * v537;
            let v1131: f32 = v583 * v530;
            let v1132: f32 = v565 * v1131;
            let v1133: f32 = v568 * v530;
            let v1134: f32 = v1132 + v1133;
            let v1135: f32 = v577 * v1118;
            let v1136: f32 = v1134 + v1135;
            let v1137: f32 = v1130 - v1136;
            let v1138: f32 = v583 * v1124;
            let v1139: f32 = v577 * v1124;
            let v1140: f32 = v583 * v1131;
            let v1141: f32 = v1139 - v1140;
            let v1142: f32 = v572 * v537;
            let v1143: f32 = v1141 + v1142;
            let v1144: f32 = v568 * v537;
            let v1145: f32 = v577 * v1131;
            let v1146: f32 = v1144 - v1145;
            let v1147: f32 = -v543;
            let v1148: f32 = v565 * v577;
            let v1149: f32 = v583 * v577;
            let v1150: f32 = v598 + v1149;
            let v1151: f32 = v577 * v577;
            let v1152: f32 = v565 * v565;
            let v1153: f32 = v1151 - v1152;
            let v1154: f32 = v583 * v565;
            let v1155: f32 = v568 - v1154;
            let v1156: f32 = v577 * v565;
            let v1157: f32 = -v1156;
            let v1158: f32 = 0.0_f32;
            (
                v970,
                v984,
                v995,
                v1003,
                v1016,
                v1031,
                v1043,
                v1052,
                v1053,
                v1054,
                v1055,
                v1062,
                v1077,
                v1089,
                v1098,
                v1099,
                v1100,
                v1102,
                v1105,
                v1107,
                v1108,
                v1110,
                v1111,
                v1115,
                v1116,
                v1121,
                v1129,
                v1137,
                v1138,
                v1143,
                v1146,
                v1147,
                v1148,
                v1150,
                v1153,
                v1155,
                v1157,
                v1158,
            )
        };
        [
            [
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v0,
                v32,
                v47,
                v59,
                v66,
                v71,
                v79,
                v87,
                v88,
                v94,
                v97,
                v176,
                v193,
                v207,
                v216,
                v220,
                v228,
                v236,
                v237,
                v242,
                v246,
                v283,
                v316,
                v338,
                v347,
                v352,
                v360,
                v368,
                v369,
                v374,
                v377,
                v416,
                v449,
                v469,
                v480,
                v486,
                v496,
                v506,
                v509,
                v516,
                v519,
                v558,
                v593,
                v615,
                v626,
                v632,
                v642,
                v652,
                v655,
                v662,
                v665,
            ],
            [
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v666,
                v1158,
                v17,
                v667,
                v669,
                v672,
                v45,
                v673,
                v675,
                v680,
                v691,
                v699,
                v705,
                v707,
                v709,
                v712,
                v191,
                v714,
                v715,
                v725,
                v735,
                v743,
                v750,
                v751,
                v753,
                v756,
                v295,
                v758,
                v760,
                v767,
                v782,
                v794,
                v805,
                v809,
                v817,
                v825,
                v828,
                v833,
                v834,
                v849,
                v867,
                v882,
                v893,
                v899,
                v909,
                v919,
                v922,
                v929,
                v932,
            ],
            [
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v933,
                v1158,
                v130,
                v707,
                v709,
                v712,
                v191,
                v714,
                v715,
                v939,
                v949,
                v957,
                v963,
                v751,
                v753,
                v756,
                v295,
                v758,
                v760,
                v970,
                v984,
                v995,
                v1003,
                v809,
                v817,
                v825,
                v828,
                v833,
                v834,
                v1016,
                v1031,
                v1043,
                v1052,
                v899,
                v909,
                v919,
                v922,
                v929,
                v932,
            ],
            [
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1053,
                v1158,
                v1054,
                v751,
                v753,
                v756,
                v295,
                v758,
                v760,
                v1158,
                v1055,
                v784,
                v797,
                v809,
                v817,
                v825,
                v828,
                v833,
                v834,
                v1062,
                v1077,
                v1089,
                v1098,
                v899,
                v909,
                v919,
                v922,
                v929,
                v932,
            ],
            [
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1099,
                v1100,
                v1158,
                v1102,
                v1105,
                v1107,
                v1108,
                v1110,
                v431,
                v1158,
                v1111,
                v1115,
                v1116,
                v1121,
                v1129,
                v1137,
                v1138,
                v1143,
                v1146,
            ],
            [
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1147,
                v1158,
                v553,
                v1148,
                v1150,
                v1153,
                v572,
                v1155,
                v1157,
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
    /// `params: [f32; 60]`: per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2, inertia about the link frame origin)
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
    pub fn standard_parameters() -> [f32; 60] {
        let v0: f32 = 3.7_f32;
        let v1: f32 = 0.0_f32;
        let v2: f32 = 0.010267496_f32;
        let v3: f32 = 0.00666_f32;
        let v4: f32 = 8.393_f32;
        let v5: f32 = 2.35004_f32;
        let v6: f32 = 0.8849019_f32;
        let v7: f32 = 0.0151074_f32;
        let v8: f32 = 2.275_f32;
        let v9: f32 = 0.56875_f32;
        let v10: f32 = 0.19163081_f32;
        let v11: f32 = 0.004095_f32;
        let v12: f32 = 1.219_f32;
        let v13: f32 = 0.11117276_f32;
        let v14: f32 = 0.21942_f32;
        let v15: f32 = 0.1879_f32;
        let v16: f32 = 0.017136473_f32;
        let v17: f32 = 0.033822_f32;
        [
            v0,
            v1,
            v1,
            v1,
            v2,
            v1,
            v1,
            v2,
            v1,
            v3,
            v4,
            v1,
            v1,
            v5,
            v6,
            v1,
            v1,
            v6,
            v1,
            v7,
            v8,
            v1,
            v1,
            v9,
            v10,
            v1,
            v1,
            v10,
            v1,
            v11,
            v12,
            v1,
            v1,
            v1,
            v13,
            v1,
            v1,
            v13,
            v1,
            v14,
            v12,
            v1,
            v1,
            v1,
            v13,
            v1,
            v1,
            v13,
            v1,
            v14,
            v15,
            v1,
            v1,
            v1,
            v16,
            v1,
            v1,
            v16,
            v1,
            v17,
        ]
    }
}
/// The same functions over several states at once, generic over the lane type
/// `L: crate::lanes::Lane` (`wide::f64x2`, `wide::f64x4`, or `f64`): input `i`
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
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `poses: [[[L; 4]; 4]; 6]` (6 x 4 x 4, row-major): homogeneous transforms T_0i of the description's frames 1..n in the base frame (m)
    ///
    /// Operation count: 113 floating-point operations, 12 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn frame_poses<L: crate::lanes::Lane>(q: &[L; 6]) -> [[[L; 4]; 4]; 6] {
        let v0: L = q[0];
        let (v2, v1): (L, L) = L::sincos(v0);
        let v3: L = -v2;
        let v4: L = L::splat(0.0_f64);
        let v5: L = L::splat(1.0_f64);
        let v6: L = L::splat(0.089159_f64);
        let v7: L = q[1];
        let (v8, v11): (L, L) = L::sincos(v7);
        let v9: L = v1 * v8;
        let v10: L = -v9;
        let v12: L = v1 * v11;
        let v13: L = L::splat(0.13585_f64);
        let v14: L = v13 * v2;
        let v15: L = -v14;
        let v16: L = v2 * v8;
        let v17: L = -v16;
        let v18: L = v2 * v11;
        let v19: L = v13 * v1;
        let v20: L = -v11;
        let v21: L = -v8;
        let v22: L = q[2];
        let (v25, v23): (L, L) = L::sincos(v22);
        let v24: L = v9 * v23;
        let v26: L = v12 * v25;
        let v27: L = v24 + v26;
        let v28: L = -v27;
        let v29: L = v12 * v23;
        let v30: L = v9 * v25;
        let v31: L = v29 - v30;
        let v32: L = L::splat(0.425_f64);
        let v33: L = v32 * v12;
        let v34: L = -L::splat(0.1197_f64);
        let v35: L = v34 * v2;
        let v36: L = v33 - v35;
        let v37: L = v36 - v14;
        let v38: L = v16 * v23;
        let v39: L = v18 * v25;
        let v40: L = v38 + v39;
        let v41: L = -v40;
        let v42: L = v18 * v23;
        let v43: L = v16 * v25;
        let v44: L = v42 - v43;
        let v45: L = v34 * v1;
        let v46: L = v32 * v18;
        let v47: L = v45 + v46;
        let v48: L = v19 + v47;
        let v49: L = v8 * v25;
        let v50: L = v11 * v23;
        let v51: L = v49 - v50;
        let v52: L = v11 * v25;
        let v53: L = v8 * v23;
        let v54: L = v52 + v53;
        let v55: L = -v54;
        let v56: L = v32 * v8;
        let v57: L = v6 - v56;
        let v58: L = q[3];
        let (v59, v61): (L, L) = L::sincos(v58);
        let v60: L = v27 * v59;
        let v62: L = v31 * v61;
        let v63: L = v60 - v62;
        let v64: L = v27 * v61;
        let v65: L = v31 * v59;
        let v66: L = v64 + v65;
        let v67: L = -v66;
        let v68: L = L::splat(0.39225_f64);
        let v69: L = v68 * v31;
        let v70: L = v37 + v69;
        let v71: L = v40 * v59;
        let v72: L = v44 * v61;
        let v73: L = v71 - v72;
        let v74: L = v40 * v61;
        let v75: L = v44 * v59;
        let v76: L = v74 + v75;
        let v77: L = -v76;
        let v78: L = v68 * v44;
        let v79: L = v48 + v78;
        let v80: L = v54 * v61;
        let v81: L = v51 * v59;
        let v82: L = v80 - v81;
        let v83: L = v51 * v61;
        let v84: L = v54 * v59;
        let v85: L = v83 + v84;
        let v86: L = v68 * v54;
        let v87: L = v57 - v86;
        let v88: L = q[4];
        let (v91, v89): (L, L) = L::sincos(v88);
        let v90: L = v63 * v89;
        let v92: L = v2 * v91;
        let v93: L = v90 - v92;
        let v94: L = v63 * v91;
        let v95: L = v2 * v89;
        let v96: L = v94 + v95;
        let v97: L = -v96;
        let v98: L = L::splat(0.093_f64);
        let v99: L = v98 * v2;
        let v100: L = v70 - v99;
        let v101: L = v73 * v89;
        let v102: L = v1 * v91;
        let v103: L = v101 + v102;
        let v104: L = v1 * v89;
        let v105: L = v73 * v91;
        let v106: L = v104 - v105;
        let v107: L = v98 * v1;
        let v108: L = v79 + v107;
        let v109: L = v82 * v89;
        let v110: L = v82 * v91;
        let v111: L = -v110;
        let v112: L = q[5];
        let (v115, v113): (L, L) = L::sincos(v112);
        let v114: L = v93 * v113;
        let v116: L = v66 * v115;
        let v117: L = v114 + v116;
        let v118: L = v93 * v115;
        let v119: L = v66 * v113;
        let v120: L = v118 - v119;
        let v121: L = L::splat(0.09465_f64);
        let v122: L = v121 * v66;
        let v123: L = v100 - v122;
        let v124: L = v103 * v113;
        let v125: L = v76 * v115;
        let v126: L = v124 + v125;
        let v127: L = v103 * v115;
        let v128: L = v76 * v113;
        let v129: L = v127 - v128;
        let v130: L = v121 * v76;
        let v131: L = v108 - v130;
        let v132: L = v109 * v113;
        let v133: L = v85 * v115;
        let v134: L = v132 - v133;
        let v135: L = v109 * v115;
        let v136: L = v85 * v113;
        let v137: L = v135 + v136;
        let v138: L = v121 * v85;
        let v139: L = v87 + v138;
        [
            [[v1, v3, v4, v4], [v2, v1, v4, v4], [v4, v4, v5, v6], [v4, v4, v4, v5]],
            [
                [v10, v3, v12, v15],
                [v17, v1, v18, v19],
                [v20, v4, v21, v6],
                [v4, v4, v4, v5],
            ],
            [
                [v28, v3, v31, v37],
                [v41, v1, v44, v48],
                [v51, v4, v55, v57],
                [v4, v4, v4, v5],
            ],
            [
                [v63, v3, v67, v70],
                [v73, v1, v77, v79],
                [v82, v4, v85, v87],
                [v4, v4, v4, v5],
            ],
            [
                [v93, v97, v67, v100],
                [v103, v106, v77, v108],
                [v109, v111, v85, v87],
                [v4, v4, v4, v5],
            ],
            [
                [v117, v97, v120, v123],
                [v126, v106, v129, v131],
                [v134, v111, v137, v139],
                [v4, v4, v4, v5],
            ],
        ]
    }
    /// End-effector pose, forward kinematics `T_0n` (thesis eq. 3.7).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `pose: [[L; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the base frame (m)
    ///
    /// Operation count: 111 floating-point operations, 12 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn end_effector_pose<L: crate::lanes::Lane>(q: &[L; 6]) -> [[L; 4]; 4] {
        let v0: L = q[0];
        let (v25, v1): (L, L) = L::sincos(v0);
        let v2: L = q[1];
        let (v3, v8): (L, L) = L::sincos(v2);
        let v4: L = v1 * v3;
        let v5: L = q[2];
        let (v10, v6): (L, L) = L::sincos(v5);
        let v7: L = v4 * v6;
        let v9: L = v1 * v8;
        let v11: L = v9 * v10;
        let v12: L = v7 + v11;
        let v13: L = q[3];
        let (v14, v19): (L, L) = L::sincos(v13);
        let v15: L = v12 * v14;
        let v16: L = v9 * v6;
        let v17: L = v4 * v10;
        let v18: L = v16 - v17;
        let v20: L = v18 * v19;
        let v21: L = v15 - v20;
        let v22: L = q[4];
        let (v23, v26): (L, L) = L::sincos(v22);
        let v24: L = v21 * v23;
        let v27: L = v25 * v26;
        let v28: L = v24 + v27;
        let v29: L = -v28;
        let v30: L = v21 * v26;
        let v31: L = v25 * v23;
        let v32: L = v30 - v31;
        let v33: L = q[5];
        let (v39, v34): (L, L) = L::sincos(v33);
        let v35: L = v32 * v34;
        let v36: L = v12 * v19;
        let v37: L = v18 * v14;
        let v38: L = v36 + v37;
        let v40: L = v38 * v39;
        let v41: L = v35 + v40;
        let v42: L = -v41;
        let v43: L = v32 * v39;
        let v44: L = v38 * v34;
        let v45: L = v43 - v44;
        let v46: L = L::splat(0.425_f64);
        let v47: L = v46 * v9;
        let v48: L = -L::splat(0.1197_f64);
        let v49: L = v48 * v25;
        let v50: L = v47 - v49;
        let v51: L = L::splat(0.13585_f64);
        let v52: L = v51 * v25;
        let v53: L = v50 - v52;
        let v54: L = L::splat(0.39225_f64);
        let v55: L = v54 * v18;
        let v56: L = v53 + v55;
        let v57: L = L::splat(0.093_f64);
        let v58: L = v57 * v25;
        let v59: L = v56 - v58;
        let v60: L = L::splat(0.09465_f64);
        let v61: L = v60 * v38;
        let v62: L = v59 - v61;
        let v63: L = L::splat(0.0823_f64);
        let v64: L = v63 * v28;
        let v65: L = v62 - v64;
        let v66: L = v1 * v26;
        let v67: L = v25 * v3;
        let v68: L = v67 * v6;
        let v69: L = v25 * v8;
        let v70: L = v69 * v10;
        let v71: L = v68 + v70;
        let v72: L = v71 * v14;
        let v73: L = v69 * v6;
        let v74: L = v67 * v10;
        let v75: L = v73 - v74;
        let v76: L = v75 * v19;
        let v77: L = v72 - v76;
        let v78: L = v77 * v23;
        let v79: L = v66 - v78;
        let v80: L = v77 * v26;
        let v81: L = v1 * v23;
        let v82: L = v80 + v81;
        let v83: L = v82 * v34;
        let v84: L = v71 * v19;
        let v85: L = v75 * v14;
        let v86: L = v84 + v85;
        let v87: L = v86 * v39;
        let v88: L = v83 + v87;
        let v89: L = -v88;
        let v90: L = v82 * v39;
        let v91: L = v86 * v34;
        let v92: L = v90 - v91;
        let v93: L = v51 * v1;
        let v94: L = v48 * v1;
        let v95: L = v46 * v69;
        let v96: L = v94 + v95;
        let v97: L = v93 + v96;
        let v98: L = v54 * v75;
        let v99: L = v97 + v98;
        let v100: L = v57 * v1;
        let v101: L = v99 + v100;
        let v102: L = v60 * v86;
        let v103: L = v101 - v102;
        let v104: L = v63 * v79;
        let v105: L = v103 + v104;
        let v106: L = v8 * v10;
        let v107: L = v3 * v6;
        let v108: L = v106 + v107;
        let v109: L = v108 * v19;
        let v110: L = v3 * v10;
        let v111: L = v8 * v6;
        let v112: L = v110 - v111;
        let v113: L = v112 * v14;
        let v114: L = v109 - v113;
        let v115: L = v114 * v23;
        let v116: L = -v115;
        let v117: L = v114 * v26;
        let v118: L = v117 * v34;
        let v119: L = v112 * v19;
        let v120: L = v108 * v14;
        let v121: L = v119 + v120;
        let v122: L = v121 * v39;
        let v123: L = v118 - v122;
        let v124: L = -v123;
        let v125: L = v117 * v39;
        let v126: L = v121 * v34;
        let v127: L = v125 + v126;
        let v128: L = L::splat(0.089159_f64);
        let v129: L = v46 * v3;
        let v130: L = v128 - v129;
        let v131: L = v54 * v108;
        let v132: L = v130 - v131;
        let v133: L = v60 * v121;
        let v134: L = v132 + v133;
        let v135: L = v63 * v115;
        let v136: L = v134 - v135;
        let v137: L = L::splat(0.0_f64);
        let v138: L = L::splat(1.0_f64);
        [
            [v29, v42, v45, v65],
            [v79, v89, v92, v105],
            [v116, v124, v127, v136],
            [v137, v137, v137, v138],
        ]
    }
    /// Geometric Jacobian of the end-effector frame origin in the base frame (thesis eq. 3.29).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian: [[L; 6]; 6]` (6 x 6, row-major): rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame
    ///
    /// Operation count: 113 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jacobian<L: crate::lanes::Lane>(q: &[L; 6]) -> [[L; 6]; 6] {
        let v0: L = -L::splat(0.10915_f64);
        let v1: L = L::splat(0.0823_f64);
        let v2: L = q[4];
        let (v13, v3): (L, L) = L::sincos(v2);
        let v4: L = v1 * v3;
        let v5: L = v0 - v4;
        let v6: L = q[0];
        let (v43, v7): (L, L) = L::sincos(v6);
        let v8: L = v5 * v7;
        let v9: L = L::splat(0.09465_f64);
        let v10: L = q[3];
        let (v15, v11): (L, L) = L::sincos(v10);
        let v12: L = v9 * v11;
        let v14: L = v1 * v13;
        let v16: L = v14 * v15;
        let v17: L = v12 + v16;
        let v18: L = q[2];
        let (v26, v19): (L, L) = L::sincos(v18);
        let v20: L = v17 * v19;
        let v21: L = L::splat(0.39225_f64);
        let v22: L = v14 * v11;
        let v23: L = v21 + v22;
        let v24: L = v9 * v15;
        let v25: L = v23 - v24;
        let v27: L = v25 * v26;
        let v28: L = v20 + v27;
        let v29: L = q[1];
        let (v30, v40): (L, L) = L::sincos(v29);
        let v31: L = v28 * v30;
        let v32: L = -L::splat(0.425_f64);
        let v33: L = v17 * v26;
        let v34: L = v32 + v33;
        let v35: L = -L::splat(0.39225_f64);
        let v36: L = v35 - v22;
        let v37: L = v36 + v24;
        let v38: L = v37 * v19;
        let v39: L = v34 + v38;
        let v41: L = v39 * v40;
        let v42: L = v31 + v41;
        let v44: L = v42 * v43;
        let v45: L = v8 + v44;
        let v46: L = v37 * v26;
        let v47: L = v46 - v20;
        let v48: L = v47 * v40;
        let v49: L = v39 * v30;
        let v50: L = v48 + v49;
        let v51: L = v50 * v7;
        let v52: L = v33 + v38;
        let v53: L = v52 * v30;
        let v54: L = v48 + v53;
        let v55: L = v54 * v7;
        let v56: L = v24 - v22;
        let v57: L = v56 * v26;
        let v58: L = v57 - v20;
        let v59: L = v58 * v40;
        let v60: L = v56 * v19;
        let v61: L = v60 + v33;
        let v62: L = v61 * v30;
        let v63: L = v59 + v62;
        let v64: L = v63 * v7;
        let v65: L = v14 * v43;
        let v66: L = v1 * v11;
        let v67: L = v66 * v19;
        let v68: L = v1 * v15;
        let v69: L = v68 * v26;
        let v70: L = v67 - v69;
        let v71: L = v70 * v40;
        let v72: L = v68 * v19;
        let v73: L = v66 * v26;
        let v74: L = v72 + v73;
        let v75: L = v74 * v30;
        let v76: L = v71 - v75;
        let v77: L = v76 * v3;
        let v78: L = v77 * v7;
        let v79: L = v65 + v78;
        let v80: L = L::splat(0.0_f64);
        let v81: L = v5 * v43;
        let v82: L = v47 * v30;
        let v83: L = L::splat(0.425_f64);
        let v84: L = v83 - v33;
        let v85: L = v25 * v19;
        let v86: L = v84 + v85;
        let v87: L = v86 * v40;
        let v88: L = v82 + v87;
        let v89: L = v88 * v7;
        let v90: L = v81 + v89;
        let v91: L = v50 * v43;
        let v92: L = v54 * v43;
        let v93: L = v63 * v43;
        let v94: L = v77 * v43;
        let v95: L = v14 * v7;
        let v96: L = v94 - v95;
        let v97: L = v52 * v40;
        let v98: L = v97 + v31;
        let v99: L = v61 * v40;
        let v100: L = v22 - v24;
        let v101: L = v100 * v26;
        let v102: L = v20 + v101;
        let v103: L = v102 * v30;
        let v104: L = v99 + v103;
        let v105: L = v69 - v67;
        let v106: L = v105 * v30;
        let v107: L = v74 * v40;
        let v108: L = v106 - v107;
        let v109: L = v108 * v3;
        let v110: L = -v43;
        let v111: L = v15 * v26;
        let v112: L = v11 * v19;
        let v113: L = v111 - v112;
        let v114: L = v113 * v30;
        let v115: L = v15 * v19;
        let v116: L = v11 * v26;
        let v117: L = v115 + v116;
        let v118: L = v117 * v40;
        let v119: L = v114 - v118;
        let v120: L = v119 * v7;
        let v121: L = v112 - v111;
        let v122: L = v121 * v40;
        let v123: L = v117 * v30;
        let v124: L = v122 - v123;
        let v125: L = v124 * v13;
        let v126: L = v125 * v7;
        let v127: L = v3 * v43;
        let v128: L = v126 - v127;
        let v129: L = v119 * v43;
        let v130: L = v3 * v7;
        let v131: L = v125 * v43;
        let v132: L = v130 + v131;
        let v133: L = L::splat(1.0_f64);
        let v134: L = v113 * v40;
        let v135: L = v134 + v123;
        let v136: L = v119 * v13;
        [
            [v45, v51, v55, v64, v79, v80],
            [v90, v91, v92, v93, v96, v80],
            [v80, v42, v98, v104, v109, v80],
            [v80, v110, v110, v110, v120, v128],
            [v80, v7, v7, v7, v129, v132],
            [v133, v80, v80, v80, v135, v136],
        ]
    }
    /// Jacobian and tool position in one pass: `[J | p; 0]`, row r is `[J_r0, ..., J_r(n-1), p_r]` with `J` the geometric Jacobian of `jacobian` and `p` the end-effector origin of `end_effector_pose` (rows 0-2; the last column of rows 3-5 is 0), the same operations as those two functions (bit-identical results), with common subexpressions, sin/cos included, computed once for both and the pose's rotation not computed.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian_and_position: [[L; 7]; 6]` (6 x 7, row-major): rows `[J(q) | p(q); 0]`: the geometric Jacobian of `jacobian` (rows vx vy vz per unit joint velocity, then wx wy wz, base frame), then the end-effector origin (m, base frame) in rows 0-2 of the last column, 0 in rows 3-5
    ///
    /// Operation count: 194 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jacobian_and_position<L: crate::lanes::Lane>(q: &[L; 6]) -> [[L; 7]; 6] {
        let (
            v1,
            v3,
            v5,
            v7,
            v9,
            v11,
            v13,
            v14,
            v15,
            v19,
            v20,
            v21,
            v22,
            v24,
            v25,
            v26,
            v30,
            v31,
            v33,
            v40,
            v42,
            v43,
            v45,
            v47,
            v50,
            v51,
            v52,
            v54,
            v55,
            v61,
            v63,
            v64,
            v67,
            v69,
            v74,
            v77,
            v79,
            v80,
            v81,
            v84,
            v87,
            v96,
            v106,
            v110,
        ) = {
            let v0: L = -L::splat(0.10915_f64);
            let v1: L = L::splat(0.0823_f64);
            let v2: L = q[4];
            let (v13, v3): (L, L) = L::sincos(v2);
            let v4: L = v1 * v3;
            let v5: L = v0 - v4;
            let v6: L = q[0];
            let (v43, v7): (L, L) = L::sincos(v6);
            let v8: L = v5 * v7;
            let v9: L = L::splat(0.09465_f64);
            let v10: L = q[3];
            let (v15, v11): (L, L) = L::sincos(v10);
            let v12: L = v9 * v11;
            let v14: L = v1 * v13;
            let v16: L = v14 * v15;
            let v17: L = v12 + v16;
            let v18: L = q[2];
            let (v26, v19): (L, L) = L::sincos(v18);
            let v20: L = v17 * v19;
            let v21: L = L::splat(0.39225_f64);
            let v22: L = v14 * v11;
            let v23: L = v21 + v22;
            let v24: L = v9 * v15;
            let v25: L = v23 - v24;
            let v27: L = v25 * v26;
            let v28: L = v20 + v27;
            let v29: L = q[1];
            let (v30, v40): (L, L) = L::sincos(v29);
            let v31: L = v28 * v30;
            let v32: L = -L::splat(0.425_f64);
            let v33: L = v17 * v26;
            let v34: L = v32 + v33;
            let v35: L = -L::splat(0.39225_f64);
            let v36: L = v35 - v22;
            let v37: L = v36 + v24;
            let v38: L = v37 * v19;
            let v39: L = v34 + v38;
            let v41: L = v39 * v40;
            let v42: L = v31 + v41;
            let v44: L = v42 * v43;
            let v45: L = v8 + v44;
            let v46: L = v37 * v26;
            let v47: L = v46 - v20;
            let v48: L = v47 * v40;
            let v49: L = v39 * v30;
            let v50: L = v48 + v49;
            let v51: L = v50 * v7;
            let v52: L = v33 + v38;
            let v53: L = v52 * v30;
            let v54: L = v48 + v53;
            let v55: L = v54 * v7;
            let v56: L = v24 - v22;
            let v57: L = v56 * v26;
            let v58: L = v57 - v20;
            let v59: L = v58 * v40;
            let v60: L = v56 * v19;
            let v61: L = v60 + v33;
            let v62: L = v61 * v30;
            let v63: L = v59 + v62;
            let v64: L = v63 * v7;
            let v65: L = v14 * v43;
            let v66: L = v1 * v11;
            let v67: L = v66 * v19;
            let v68: L = v1 * v15;
            let v69: L = v68 * v26;
            let v70: L = v67 - v69;
            let v71: L = v70 * v40;
            let v72: L = v68 * v19;
            let v73: L = v66 * v26;
            let v74: L = v72 + v73;
            let v75: L = v74 * v30;
            let v76: L = v71 - v75;
            let v77: L = v76 * v3;
            let v78: L = v77 * v7;
            let v79: L = v65 + v78;
            let v80: L = L::splat(0.0_f64);
            let v81: L = L::splat(0.425_f64);
            let v82: L = v7 * v40;
            let v83: L = v81 * v82;
            let v84: L = -L::splat(0.1197_f64);
            let v85: L = v84 * v43;
            let v86: L = v83 - v85;
            let v87: L = L::splat(0.13585_f64);
            let v88: L = v87 * v43;
            let v89: L = v86 - v88;
            let v90: L = v82 * v19;
            let v91: L = v7 * v30;
            let v92: L = v91 * v26;
            let v93: L = v90 - v92;
            let v94: L = v21 * v93;
            let v95: L = v89 + v94;
            let v96: L = L::splat(0.093_f64);
            let v97: L = v96 * v43;
            let v98: L = v95 - v97;
            let v99: L = v91 * v19;
            let v100: L = v82 * v26;
            let v101: L = v99 + v100;
            let v102: L = v101 * v11;
            let v103: L = v93 * v15;
            let v104: L = v102 + v103;
            let v105: L = v9 * v104;
            let v106: L = v98 - v105;
            let v107: L = v101 * v15;
            let v108: L = v93 * v11;
            let v109: L = v107 - v108;
            let v110: L = v109 * v13;
            (
                v1,
                v3,
                v5,
                v7,
                v9,
                v11,
                v13,
                v14,
                v15,
                v19,
                v20,
                v21,
                v22,
                v24,
                v25,
                v26,
                v30,
                v31,
                v33,
                v40,
                v42,
                v43,
                v45,
                v47,
                v50,
                v51,
                v52,
                v54,
                v55,
                v61,
                v63,
                v64,
                v67,
                v69,
                v74,
                v77,
                v79,
                v80,
                v81,
                v84,
                v87,
                v96,
                v106,
                v110,
            )
        };
        let (
            v114,
            v123,
            v124,
            v125,
            v126,
            v129,
            v159,
            v161,
            v167,
            v172,
            v194,
            v195,
            v205,
            v213,
            v214,
            v217,
            v218,
            v220,
            v221,
        ) = {
            let v111: L = v43 * v3;
            let v112: L = v110 + v111;
            let v113: L = v1 * v112;
            let v114: L = v106 - v113;
            let v115: L = v5 * v43;
            let v116: L = v47 * v30;
            let v117: L = v81 - v33;
            let v118: L = v25 * v19;
            let v119: L = v117 + v118;
            let v120: L = v119 * v40;
            let v121: L = v116 + v120;
            let v122: L = v121 * v7;
            let v123: L = v115 + v122;
            let v124: L = v50 * v43;
            let v125: L = v54 * v43;
            let v126: L = v63 * v43;
            let v127: L = v77 * v43;
            let v128: L = v14 * v7;
            let v129: L = v127 - v128;
            let v130: L = v87 * v7;
            let v131: L = v84 * v7;
            let v132: L = v43 * v40;
            let v133: L = v81 * v132;
            let v134: L = v131 + v133;
            let v135: L = v130 + v134;
            let v136: L = v132 * v19;
            let v137: L = v43 * v30;
            let v138: L = v137 * v26;
            let v139: L = v136 - v138;
            let v140: L = v21 * v139;
            let v141: L = v135 + v140;
            let v142: L = v96 * v7;
            let v143: L = v141 + v142;
            let v144: L = v137 * v19;
            let v145: L = v132 * v26;
            let v146: L = v144 + v145;
            let v147: L = v146 * v11;
            let v148: L = v139 * v15;
            let v149: L = v147 + v148;
            let v150: L = v9 * v149;
            let v151: L = v143 - v150;
            let v152: L = v7 * v3;
            let v153: L = v146 * v15;
            let v154: L = v139 * v11;
            let v155: L = v153 - v154;
            let v156: L = v155 * v13;
            let v157: L = v152 - v156;
            let v158: L = v1 * v157;
            let v159: L = v151 + v158;
            let v160: L = v52 * v40;
            let v161: L = v160 + v31;
            let v162: L = v61 * v40;
            let v163: L = v22 - v24;
            let v164: L = v163 * v26;
            let v165: L = v20 + v164;
            let v166: L = v165 * v30;
            let v167: L = v162 + v166;
            let v168: L = v69 - v67;
            let v169: L = v168 * v30;
            let v170: L = v74 * v40;
            let v171: L = v169 - v170;
            let v172: L = v171 * v3;
            let v173: L = L::splat(0.089159_f64);
            let v174: L = v81 * v30;
            let v175: L = v173 - v174;
            let v176: L = v40 * v26;
            let v177: L = v30 * v19;
            let v178: L = v176 + v177;
            let v179: L = v21 * v178;
            let v180: L = v175 - v179;
            let v181: L = v30 * v26;
            let v182: L = v40 * v19;
            let v183: L = v181 - v182;
            let v184: L = v183 * v11;
            let v185: L = v178 * v15;
            let v186: L = v184 + v185;
            let v187: L = v9 * v186;
            let v188: L = v180 + v187;
            let v189: L = v178 * v11;
            let v190: L = v183 * v15;
            let v191: L = v189 - v190;
            let v192: L = v191 * v13;
            let v193: L = v1 * v192;
            let v194: L = v188 - v193;
            let v195: L = -v43;
            let v196: L = v15 * v26;
            let v197: L = v11 * v19;
            let v198: L = v196 - v197;
            let v199: L = v198 * v30;
            let v200: L = v15 * v19;
            let v201: L = v11 * v26;
            let v202: L = v200 + v201;
            let v203: L = v202 * v40;
            let v204: L = v199 - v203;
            let v205: L = v204 * v7;
            let v206: L = v197 - v196;
            let v207: L = v206 * v40;
            let v208: L = v202 * v30;
            let v209: L = v207 - v208;
            let v210: L = v209 * v13;
            let v211: L = v210 * v7;
            let v212: L = v3 * v43;
            let v213: L = v211 - v212;
            let v214: L = v204 * v43;
            let v215: L = v3 * v7;
            let v216: L = v210 * v43;
            let v217: L = v215 + v216;
            let v218: L = L::splat(1.0_f64);
            let v219: L = v198 * v40;
            let v220: L = v219 + v208;
            let v221: L = v204 * v13;
            (
                v114,
                v123,
                v124,
                v125,
                v126,
                v129,
                v159,
                v161,
                v167,
                v172,
                v194,
                v195,
                v205,
                v213,
                v214,
                v217,
                v218,
                v220,
                v221,
            )
        };
        [
            [v45, v51, v55, v64, v79, v80, v114],
            [v123, v124, v125, v126, v129, v80, v159],
            [v80, v42, v161, v167, v172, v80, v194],
            [v80, v195, v195, v195, v205, v213, v80],
            [v80, v7, v7, v7, v214, v217, v80],
            [v218, v80, v80, v80, v220, v221, v80],
        ]
    }
    /// Acceleration term of the end-effector twist: `d/dt (J qd) = J qdd + Jdot qd`.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 6]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `jdot_qd: [L; 6]`: Jdot(q, qd) qd: m/s^2 (rows 0-2) and rad/s^2 (rows 3-5), base frame
    ///
    /// Operation count: 263 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn jdot_qd<L: crate::lanes::Lane>(q: &[L; 6], qd: &[L; 6]) -> [L; 6] {
        let (
            v1,
            v5,
            v6,
            v8,
            v10,
            v13,
            v15,
            v18,
            v21,
            v24,
            v34,
            v35,
            v37,
            v39,
            v46,
            v50,
            v54,
            v58,
            v60,
            v65,
            v71,
            v72,
            v77,
            v83,
            v87,
            v96,
            v101,
            v106,
            v113,
            v119,
            v122,
            v124,
            v127,
            v130,
            v137,
            v141,
            v145,
            v146,
            v152,
        ) = {
            let v0: L = L::splat(0.0823_f64);
            let v1: L = qd[4];
            let v2: L = v0 * v1;
            let v3: L = v2 * v1;
            let v4: L = q[4];
            let (v21, v5): (L, L) = L::sincos(v4);
            let v6: L = v3 * v5;
            let v7: L = L::splat(0.10915_f64);
            let v8: L = v0 * v5;
            let v9: L = v7 + v8;
            let v10: L = qd[0];
            let v11: L = v9 * v10;
            let v12: L = L::splat(0.1646_f64);
            let v13: L = qd[3];
            let v14: L = v12 * v13;
            let v15: L = qd[2];
            let v16: L = v12 * v15;
            let v17: L = v14 + v16;
            let v18: L = qd[1];
            let v19: L = v12 * v18;
            let v20: L = v17 + v19;
            let v22: L = v20 * v21;
            let v23: L = q[3];
            let (v24, v35): (L, L) = L::sincos(v23);
            let v25: L = v22 * v24;
            let v26: L = L::splat(0.1893_f64);
            let v27: L = v26 * v13;
            let v28: L = v26 * v15;
            let v29: L = v27 + v28;
            let v30: L = v26 * v18;
            let v31: L = v29 + v30;
            let v32: L = v12 * v1;
            let v33: L = v32 * v5;
            let v34: L = v31 - v33;
            let v36: L = v34 * v35;
            let v37: L = v25 + v36;
            let v38: L = q[2];
            let (v50, v39): (L, L) = L::sincos(v38);
            let v40: L = v37 * v39;
            let v41: L = L::splat(0.7845_f64);
            let v42: L = v41 * v15;
            let v43: L = v41 * v18;
            let v44: L = v42 + v43;
            let v45: L = v22 * v35;
            let v46: L = v44 + v45;
            let v47: L = v33 - v31;
            let v48: L = v47 * v24;
            let v49: L = v46 + v48;
            let v51: L = v49 * v50;
            let v52: L = v40 + v51;
            let v53: L = q[1];
            let (v65, v54): (L, L) = L::sincos(v53);
            let v55: L = v52 * v54;
            let v56: L = v11 + v55;
            let v57: L = L::splat(0.85_f64);
            let v58: L = v57 * v18;
            let v59: L = v47 * v35;
            let v60: L = v59 - v25;
            let v61: L = v60 * v50;
            let v62: L = v58 + v61;
            let v63: L = v49 * v39;
            let v64: L = v62 + v63;
            let v66: L = v64 * v65;
            let v67: L = v56 + v66;
            let v68: L = v67 * v10;
            let v69: L = v6 + v68;
            let v70: L = q[0];
            let (v71, v152): (L, L) = L::sincos(v70);
            let v72: L = v69 * v71;
            let v73: L = v32 * v10;
            let v74: L = v73 * v21;
            let v75: L = v0 * v13;
            let v76: L = v75 * v13;
            let v77: L = v3 + v76;
            let v78: L = v0 * v10;
            let v79: L = v78 * v10;
            let v80: L = v77 + v79;
            let v81: L = v0 * v15;
            let v82: L = v14 + v81;
            let v83: L = v82 * v15;
            let v84: L = v80 + v83;
            let v85: L = v0 * v18;
            let v86: L = v17 + v85;
            let v87: L = v86 * v18;
            let v88: L = v84 + v87;
            let v89: L = v88 * v21;
            let v90: L = v89 * v24;
            let v91: L = L::splat(0.09465_f64);
            let v92: L = v91 * v10;
            let v93: L = v92 * v10;
            let v94: L = v91 * v13;
            let v95: L = v94 - v33;
            let v96: L = v95 * v13;
            let v97: L = v93 + v96;
            let v98: L = v91 * v15;
            let v99: L = v27 + v98;
            let v100: L = v99 - v33;
            let v101: L = v100 * v15;
            let v102: L = v97 + v101;
            let v103: L = v91 * v18;
            let v104: L = v29 + v103;
            let v105: L = v104 - v33;
            let v106: L = v105 * v18;
            let v107: L = v102 + v106;
            let v108: L = v107 * v35;
            let v109: L = v90 + v108;
            let v110: L = v109 * v39;
            let v111: L = L::splat(0.39225_f64);
            let v112: L = v111 * v15;
            let v113: L = v112 * v15;
            let v114: L = v111 * v10;
            let v115: L = v114 * v10;
            let v116: L = v113 + v115;
            let v117: L = v111 * v18;
            let v118: L = v42 + v117;
            let v119: L = v118 * v18;
            let v120: L = v116 + v119;
            let v121: L = v89 * v35;
            let v122: L = v120 + v121;
            let v123: L = v33 - v94;
            let v124: L = v123 * v13;
            let v125: L = v124 - v93;
            let v126: L = v33 - v99;
            let v127: L = v126 * v15;
            let v128: L = v125 + v127;
            let v129: L = v33 - v104;
            let v130: L = v129 * v18;
            let v131: L = v128 + v130;
            let v132: L = v131 * v24;
            let v133: L = v122 + v132;
            let v134: L = v133 * v50;
            let v135: L = v110 + v134;
            let v136: L = v135 * v65;
            let v137: L = v74 + v136;
            let v138: L = v109 * v50;
            let v139: L = L::splat(0.425_f64);
            let v140: L = v139 * v18;
            let v141: L = v140 * v18;
            let v142: L = v139 * v10;
            let v143: L = v142 * v10;
            let v144: L = v141 + v143;
            let v145: L = v138 - v144;
            let v146: L = v107 * v24;
            (
                v1,
                v5,
                v6,
                v8,
                v10,
                v13,
                v15,
                v18,
                v21,
                v24,
                v34,
                v35,
                v37,
                v39,
                v46,
                v50,
                v54,
                v58,
                v60,
                v65,
                v71,
                v72,
                v77,
                v83,
                v87,
                v96,
                v101,
                v106,
                v113,
                v119,
                v122,
                v124,
                v127,
                v130,
                v137,
                v141,
                v145,
                v146,
                v152,
            )
        };
        let (v154, v175, v202, v262, v274, v293) = {
            let v147: L = v146 - v122;
            let v148: L = v147 * v39;
            let v149: L = v145 + v148;
            let v150: L = v149 * v54;
            let v151: L = v137 + v150;
            let v153: L = v151 * v152;
            let v154: L = v72 + v153;
            let v155: L = -L::splat(0.10915_f64);
            let v156: L = v155 - v8;
            let v157: L = v156 * v10;
            let v158: L = v60 * v39;
            let v159: L = v34 * v24;
            let v160: L = v159 - v46;
            let v161: L = v160 * v50;
            let v162: L = v158 + v161;
            let v163: L = v162 * v54;
            let v164: L = v157 + v163;
            let v165: L = v37 * v50;
            let v166: L = v165 - v58;
            let v167: L = v160 * v39;
            let v168: L = v166 + v167;
            let v169: L = v168 * v65;
            let v170: L = v164 + v169;
            let v171: L = v170 * v10;
            let v172: L = v171 - v6;
            let v173: L = v172 * v152;
            let v174: L = v151 * v71;
            let v175: L = v173 + v174;
            let v176: L = v77 + v83;
            let v177: L = v176 + v87;
            let v178: L = v177 * v21;
            let v179: L = v178 * v24;
            let v180: L = v96 + v101;
            let v181: L = v180 + v106;
            let v182: L = v181 * v35;
            let v183: L = v179 + v182;
            let v184: L = v183 * v39;
            let v185: L = v113 + v119;
            let v186: L = v178 * v35;
            let v187: L = v185 + v186;
            let v188: L = v124 + v127;
            let v189: L = v188 + v130;
            let v190: L = v189 * v24;
            let v191: L = v187 + v190;
            let v192: L = v191 * v50;
            let v193: L = v184 + v192;
            let v194: L = v193 * v54;
            let v195: L = v189 * v35;
            let v196: L = v195 - v179;
            let v197: L = v196 * v50;
            let v198: L = v141 + v197;
            let v199: L = v191 * v39;
            let v200: L = v198 + v199;
            let v201: L = v200 * v65;
            let v202: L = v194 + v201;
            let v203: L = qd[5];
            let v204: L = v203 * v1;
            let v205: L = v204 * v21;
            let v206: L = v1 * v24;
            let v207: L = v203 * v21;
            let v208: L = v207 * v35;
            let v209: L = v206 - v208;
            let v210: L = v209 * v39;
            let v211: L = v1 * v35;
            let v212: L = v207 * v24;
            let v213: L = v211 + v212;
            let v214: L = v213 * v50;
            let v215: L = v210 + v214;
            let v216: L = v215 * v54;
            let v217: L = v213 * v39;
            let v218: L = v208 - v206;
            let v219: L = v218 * v50;
            let v220: L = v217 + v219;
            let v221: L = v220 * v65;
            let v222: L = v216 + v221;
            let v223: L = v222 * v10;
            let v224: L = v205 + v223;
            let v225: L = v224 * v71;
            let v226: L = v13 + v15;
            let v227: L = v226 + v18;
            let v228: L = v227 * v24;
            let v229: L = v228 * v50;
            let v230: L = v227 * v35;
            let v231: L = v230 * v39;
            let v232: L = v229 - v231;
            let v233: L = v232 * v54;
            let v234: L = v228 * v39;
            let v235: L = v230 * v50;
            let v236: L = v234 + v235;
            let v237: L = v236 * v65;
            let v238: L = v233 + v237;
            let v239: L = v238 * v1;
            let v240: L = v227 * v10;
            let v241: L = v239 - v240;
            let v242: L = v35 * v39;
            let v243: L = v24 * v50;
            let v244: L = v242 - v243;
            let v245: L = v244 * v54;
            let v246: L = v24 * v39;
            let v247: L = v35 * v50;
            let v248: L = v246 + v247;
            let v249: L = v248 * v65;
            let v250: L = v245 - v249;
            let v251: L = v250 * v1;
            let v252: L = v251 - v10;
            let v253: L = v252 * v5;
            let v254: L = v232 * v65;
            let v255: L = v236 * v54;
            let v256: L = v254 - v255;
            let v257: L = v256 * v21;
            let v258: L = v253 + v257;
            let v259: L = v258 * v203;
            let v260: L = v241 + v259;
            let v261: L = v260 * v152;
            let v262: L = v225 + v261;
            let v263: L = v218 * v39;
            let v264: L = v263 - v214;
            let v265: L = v264 * v54;
            let v266: L = v209 * v50;
            let v267: L = v266 - v217;
            let v268: L = v267 * v65;
            let v269: L = v265 + v268;
            let v270: L = v269 * v10;
            let v271: L = v270 - v205;
            let v272: L = v271 * v152;
            let v273: L = v260 * v71;
            let v274: L = v272 + v273;
            let v275: L = v238 * v203;
            let v276: L = v275 * v21;
            let v277: L = v203 * v5;
            let v278: L = v227 - v277;
            let v279: L = v278 * v24;
            let v280: L = v279 * v39;
            let v281: L = v278 * v35;
            let v282: L = v281 * v50;
            let v283: L = v280 + v282;
            let v284: L = v283 * v54;
            let v285: L = v281 * v39;
            let v286: L = v277 - v227;
            let v287: L = v286 * v24;
            let v288: L = v287 * v50;
            let v289: L = v285 + v288;
            let v290: L = v289 * v65;
            let v291: L = v284 + v290;
            let v292: L = v291 * v1;
            let v293: L = v276 + v292;
            (v154, v175, v202, v262, v274, v293)
        };
        [v154, v175, v202, v262, v274, v293]
    }
    /// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `mass_matrix: [[L; 6]; 6]` (6 x 6, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
    ///
    /// Operation count: 238 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn mass_matrix<L: crate::lanes::Lane>(q: &[L; 6]) -> [[L; 6]; 6] {
        let (
            v0,
            v2,
            v3,
            v5,
            v6,
            v8,
            v10,
            v20,
            v25,
            v27,
            v32,
            v34,
            v39,
            v42,
            v48,
            v49,
            v51,
            v52,
            v53,
            v66,
            v67,
            v69,
            v73,
            v78,
            v87,
            v108,
            v109,
            v115,
            v116,
            v117,
            v120,
            v124,
            v127,
            v131,
            v134,
            v135,
            v136,
            v137,
            v141,
            v142,
        ) = {
            let v0: L = L::splat(0.00666_f64);
            let v1: L = q[1];
            let (v124, v2): (L, L) = L::sincos(v1);
            let v3: L = L::splat(0.88490187591_f64);
            let v4: L = q[2];
            let (v73, v5): (L, L) = L::sincos(v4);
            let v6: L = L::splat(0.191630813556_f64);
            let v7: L = q[3];
            let (v25, v8): (L, L) = L::sincos(v7);
            let v9: L = L::splat(0.21942_f64);
            let v10: L = L::splat(0.0171364731454_f64);
            let v11: L = q[5];
            let (v12, v16): (L, L) = L::sincos(v11);
            let v13: L = v10 * v12;
            let v14: L = v13 * v12;
            let v15: L = L::splat(0.033822_f64);
            let v17: L = v15 * v16;
            let v18: L = v17 * v16;
            let v19: L = v14 + v18;
            let v20: L = v9 + v19;
            let v21: L = L::splat(0.0121682781_f64);
            let v22: L = v20 + v21;
            let v23: L = v9 + v22;
            let v24: L = v8 * v23;
            let v26: L = q[4];
            let (v52, v27): (L, L) = L::sincos(v26);
            let v28: L = v15 * v12;
            let v29: L = v28 * v16;
            let v30: L = v10 * v16;
            let v31: L = v30 * v12;
            let v32: L = v29 - v31;
            let v33: L = v27 * v32;
            let v34: L = v25 * v33;
            let v35: L = v24 - v34;
            let v36: L = v35 * v8;
            let v37: L = v17 * v12;
            let v38: L = v13 * v16;
            let v39: L = v37 - v38;
            let v40: L = v39 * v27;
            let v41: L = v8 * v40;
            let v42: L = L::splat(0.111172755531_f64);
            let v43: L = v30 * v16;
            let v44: L = v28 * v12;
            let v45: L = v43 + v44;
            let v46: L = L::splat(0.00168332516775_f64);
            let v47: L = v45 + v46;
            let v48: L = v42 + v47;
            let v49: L = v27 * v48;
            let v50: L = v49 * v27;
            let v51: L = L::splat(0.12999255384415_f64);
            let v53: L = v51 * v52;
            let v54: L = v53 * v52;
            let v55: L = v50 + v54;
            let v56: L = v55 + v21;
            let v57: L = v42 + v56;
            let v58: L = v25 * v57;
            let v59: L = v41 - v58;
            let v60: L = v59 * v25;
            let v61: L = v36 - v60;
            let v62: L = L::splat(0.40402113811874996_f64);
            let v63: L = L::splat(2.0_f64);
            let v64: L = L::splat(0.39225_f64);
            let v65: L = L::splat(0.017784735_f64);
            let v66: L = v65 * v25;
            let v67: L = v64 * v66;
            let v68: L = v63 * v67;
            let v69: L = v62 - v68;
            let v70: L = v61 + v69;
            let v71: L = v6 + v70;
            let v72: L = v5 * v71;
            let v74: L = v8 * v57;
            let v75: L = v25 * v40;
            let v76: L = v74 + v75;
            let v77: L = v76 * v25;
            let v78: L = v8 * v33;
            let v79: L = v25 * v23;
            let v80: L = v78 + v79;
            let v81: L = v80 * v8;
            let v82: L = v77 - v81;
            let v83: L = v65 * v8;
            let v84: L = v64 * v83;
            let v85: L = v82 - v84;
            let v86: L = v73 * v85;
            let v87: L = v72 + v86;
            let v88: L = v87 * v5;
            let v89: L = L::splat(0.004095_f64);
            let v90: L = v76 * v8;
            let v91: L = v80 * v25;
            let v92: L = v90 + v91;
            let v93: L = v92 + v69;
            let v94: L = v93 - v62;
            let v95: L = v94 + v67;
            let v96: L = v95 + v67;
            let v97: L = v89 + v96;
            let v98: L = v73 * v97;
            let v99: L = v59 * v8;
            let v100: L = v35 * v25;
            let v101: L = v99 + v100;
            let v102: L = v101 + v84;
            let v103: L = v5 * v102;
            let v104: L = v98 - v103;
            let v105: L = v104 * v73;
            let v106: L = v88 + v105;
            let v107: L = L::splat(0.9554455987809999_f64);
            let v108: L = -L::splat(0.01566175149_f64);
            let v109: L = L::splat(0.425_f64);
            let v110: L = L::splat(0.56875_f64);
            let v111: L = L::splat(1.030009275_f64);
            let v112: L = v111 - v66;
            let v113: L = v110 + v112;
            let v114: L = v5 * v113;
            let v115: L = v73 * v83;
            let v116: L = v114 - v115;
            let v117: L = v109 * v116;
            let v118: L = v108 + v117;
            let v119: L = v63 * v118;
            let v120: L = v107 + v119;
            let v121: L = v106 + v120;
            let v122: L = v3 + v121;
            let v123: L = v2 * v122;
            let v125: L = v5 * v85;
            let v126: L = v73 * v71;
            let v127: L = v125 - v126;
            let v128: L = v127 * v5;
            let v129: L = v73 * v102;
            let v130: L = v5 * v97;
            let v131: L = v129 + v130;
            let v132: L = v131 * v73;
            let v133: L = v128 + v132;
            let v134: L = v5 * v83;
            let v135: L = v73 * v113;
            let v136: L = v134 + v135;
            let v137: L = v109 * v136;
            let v138: L = v133 - v137;
            let v139: L = v124 * v138;
            let v140: L = v123 + v139;
            let v141: L = v140 * v2;
            let v142: L = v104 * v5;
            (
                v0,
                v2,
                v3,
                v5,
                v6,
                v8,
                v10,
                v20,
                v25,
                v27,
                v32,
                v34,
                v39,
                v42,
                v48,
                v49,
                v51,
                v52,
                v53,
                v66,
                v67,
                v69,
                v73,
                v78,
                v87,
                v108,
                v109,
                v115,
                v116,
                v117,
                v120,
                v124,
                v127,
                v131,
                v134,
                v135,
                v136,
                v137,
                v141,
                v142,
            )
        };
        let (
            v163,
            v205,
            v217,
            v238,
            v251,
            v264,
            v270,
            v272,
            v278,
            v279,
            v280,
            v282,
            v283,
            v284,
            v285,
        ) = {
            let v143: L = v87 * v73;
            let v144: L = v142 - v143;
            let v145: L = v144 - v137;
            let v146: L = v2 * v145;
            let v147: L = L::splat(0.0151074_f64);
            let v148: L = v131 * v5;
            let v149: L = v127 * v73;
            let v150: L = v148 - v149;
            let v151: L = v150 + v120;
            let v152: L = L::splat(0.8852250624999999_f64);
            let v153: L = v151 - v152;
            let v154: L = v153 - v117;
            let v155: L = v154 - v117;
            let v156: L = v147 + v155;
            let v157: L = v124 * v156;
            let v158: L = v146 + v157;
            let v159: L = v158 * v124;
            let v160: L = v141 + v159;
            let v161: L = L::splat(0.12150210104175002_f64);
            let v162: L = v160 + v161;
            let v163: L = v0 + v162;
            let v164: L = v39 * v52;
            let v165: L = L::splat(0.0016539803549999999_f64);
            let v166: L = v164 - v165;
            let v167: L = v8 * v166;
            let v168: L = v49 * v52;
            let v169: L = v53 * v27;
            let v170: L = v168 - v169;
            let v171: L = v25 * v170;
            let v172: L = v167 - v171;
            let v173: L = v73 * v172;
            let v174: L = v8 * v170;
            let v175: L = v25 * v166;
            let v176: L = v174 + v175;
            let v177: L = L::splat(0.051322656825_f64);
            let v178: L = v176 + v177;
            let v179: L = v5 * v178;
            let v180: L = v173 + v179;
            let v181: L = -L::splat(0.24932103525000002_f64);
            let v182: L = v180 + v181;
            let v183: L = -L::splat(0.1197_f64);
            let v184: L = v183 * v116;
            let v185: L = v182 + v184;
            let v186: L = L::splat(0.0556077225_f64);
            let v187: L = v185 + v186;
            let v188: L = v124 * v187;
            let v189: L = v5 * v172;
            let v190: L = v73 * v178;
            let v191: L = v189 - v190;
            let v192: L = v183 * v136;
            let v193: L = v191 - v192;
            let v194: L = v2 * v193;
            let v195: L = v188 - v194;
            let v196: L = L::splat(0.13585_f64);
            let v197: L = L::splat(2.35004_f64);
            let v198: L = L::splat(2.0828824999999997_f64);
            let v199: L = v116 + v198;
            let v200: L = v197 + v199;
            let v201: L = v124 * v200;
            let v202: L = v2 * v136;
            let v203: L = v201 + v202;
            let v204: L = v196 * v203;
            let v205: L = v195 + v204;
            let v206: L = v180 + v184;
            let v207: L = v124 * v206;
            let v208: L = v135 + v134;
            let v209: L = v183 * v208;
            let v210: L = v191 - v209;
            let v211: L = v2 * v210;
            let v212: L = v207 - v211;
            let v213: L = v124 * v116;
            let v214: L = v2 * v208;
            let v215: L = v213 + v214;
            let v216: L = v196 * v215;
            let v217: L = v212 + v216;
            let v218: L = v73 * v176;
            let v219: L = v189 - v218;
            let v220: L = v73 * v66;
            let v221: L = v220 - v134;
            let v222: L = v183 * v221;
            let v223: L = v219 + v222;
            let v224: L = v2 * v223;
            let v225: L = v5 * v66;
            let v226: L = v225 + v115;
            let v227: L = v183 * v226;
            let v228: L = v5 * v176;
            let v229: L = v173 + v228;
            let v230: L = v227 - v229;
            let v231: L = v124 * v230;
            let v232: L = v224 + v231;
            let v233: L = v124 * v226;
            let v234: L = v2 * v221;
            let v235: L = v233 + v234;
            let v236: L = v196 * v235;
            let v237: L = v232 + v236;
            let v238: L = -v237;
            let v239: L = v8 * v20;
            let v240: L = v239 - v34;
            let v241: L = v73 * v240;
            let v242: L = v25 * v20;
            let v243: L = v78 + v242;
            let v244: L = v5 * v243;
            let v245: L = v241 + v244;
            let v246: L = v124 * v245;
            let v247: L = v5 * v240;
            let v248: L = v73 * v243;
            let v249: L = v247 - v248;
            let v250: L = v2 * v249;
            let v251: L = v246 - v250;
            let v252: L = v10 * v52;
            let v253: L = v25 * v252;
            let v254: L = v5 * v253;
            let v255: L = v8 * v252;
            let v256: L = v73 * v255;
            let v257: L = v254 + v256;
            let v258: L = v2 * v257;
            let v259: L = v5 * v255;
            let v260: L = v73 * v253;
            let v261: L = v259 - v260;
            let v262: L = v124 * v261;
            let v263: L = v258 + v262;
            let v264: L = -v263;
            let v265: L = v52 * v48;
            let v266: L = v265 * v52;
            let v267: L = v51 * v27;
            let v268: L = v267 * v27;
            let v269: L = v266 + v268;
            let v270: L = v42 + v269;
            let v271: L = v270 + v69;
            let v272: L = v6 + v271;
            let v273: L = v272 + v120;
            let v274: L = L::splat(0.070220536281_f64);
            let v275: L = v273 - v274;
            let v276: L = v275 - v108;
            let v277: L = v276 - v108;
            let v278: L = v3 + v277;
            let v279: L = v272 + v117;
            let v280: L = v270 - v67;
            let v281: L = v109 * v226;
            let v282: L = v280 - v281;
            let v283: L = v52 * v32;
            let v284: L = v10 * v27;
            let v285: L = L::splat(0.0_f64);
            (
                v163,
                v205,
                v217,
                v238,
                v251,
                v264,
                v270,
                v272,
                v278,
                v279,
                v280,
                v282,
                v283,
                v284,
                v285,
            )
        };
        [
            [v163, v205, v217, v238, v251, v264],
            [v205, v278, v279, v282, v283, v284],
            [v217, v279, v272, v280, v283, v284],
            [v238, v282, v280, v270, v283, v284],
            [v251, v283, v283, v283, v20, v285],
            [v264, v284, v284, v284, v285, v10],
        ]
    }
    /// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 6]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis_matrix: [[L; 6]; 6]` (6 x 6, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
    ///
    /// Operation count: 1641 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn coriolis_matrix<L: crate::lanes::Lane>(
        q: &[L; 6],
        qd: &[L; 6],
    ) -> [[L; 6]; 6] {
        let (
            v0,
            v1,
            v3,
            v4,
            v5,
            v6,
            v9,
            v11,
            v12,
            v13,
            v15,
            v18,
            v20,
            v22,
            v26,
            v27,
            v28,
            v29,
            v31,
            v32,
            v33,
            v40,
            v45,
            v51,
            v53,
            v55,
            v57,
            v58,
            v59,
            v61,
            v62,
            v64,
            v66,
            v68,
            v69,
            v76,
            v77,
            v80,
            v82,
            v84,
            v90,
            v92,
            v94,
            v97,
            v102,
            v108,
            v109,
            v110,
            v115,
            v116,
            v120,
            v122,
            v125,
            v126,
            v133,
            v136,
            v139,
            v143,
            v146,
            v148,
            v153,
            v158,
            v160,
            v161,
            v163,
            v167,
            v168,
            v169,
            v171,
            v172,
            v185,
            v188,
            v189,
        ) = {
            let v0: L = L::splat(0.679472691875_f64);
            let v1: L = L::splat(0.007558512375_f64);
            let v2: L = q[3];
            let (v3, v55): (L, L) = L::sincos(v2);
            let v4: L = v1 * v3;
            let v5: L = v0 - v4;
            let v6: L = qd[1];
            let v7: L = v5 * v6;
            let v8: L = q[2];
            let (v9, v90): (L, L) = L::sincos(v8);
            let v10: L = v7 * v9;
            let v11: L = L::splat(0.0166855268546_f64);
            let v12: L = qd[4];
            let v13: L = v11 * v12;
            let v14: L = q[5];
            let (v32, v15): (L, L) = L::sincos(v14);
            let v16: L = v13 * v15;
            let v17: L = q[4];
            let (v18, v29): (L, L) = L::sincos(v17);
            let v19: L = v16 * v18;
            let v20: L = qd[3];
            let v21: L = v11 * v20;
            let v22: L = qd[2];
            let v23: L = v11 * v22;
            let v24: L = v21 + v23;
            let v25: L = v11 * v6;
            let v26: L = v24 + v25;
            let v27: L = qd[5];
            let v28: L = v11 * v27;
            let v30: L = v28 * v29;
            let v31: L = v26 + v30;
            let v33: L = v31 * v32;
            let v34: L = v19 + v33;
            let v35: L = v34 * v15;
            let v36: L = v13 * v18;
            let v37: L = v35 - v36;
            let v38: L = v37 * v29;
            let v39: L = v10 + v38;
            let v40: L = L::splat(0.0333710537092_f64);
            let v41: L = v40 * v20;
            let v42: L = v40 * v22;
            let v43: L = v41 + v42;
            let v44: L = v40 * v6;
            let v45: L = v43 + v44;
            let v46: L = v45 + v30;
            let v47: L = v46 * v32;
            let v48: L = v19 + v47;
            let v49: L = v48 * v15;
            let v50: L = v36 - v49;
            let v51: L = v50 * v29;
            let v52: L = v28 * v15;
            let v53: L = v52 * v32;
            let v54: L = v51 - v53;
            let v56: L = v54 * v55;
            let v57: L = L::splat(0.00697606230375_f64);
            let v58: L = v57 * v20;
            let v59: L = v57 * v22;
            let v60: L = v58 + v59;
            let v61: L = v57 * v6;
            let v62: L = v60 + v61;
            let v63: L = v56 - v62;
            let v64: L = v13 * v32;
            let v65: L = v64 * v18;
            let v66: L = v26 * v15;
            let v67: L = v65 - v66;
            let v68: L = v67 * v15;
            let v69: L = L::splat(0.21481116377025_f64);
            let v70: L = v69 * v20;
            let v71: L = v69 * v22;
            let v72: L = v70 + v71;
            let v73: L = v69 * v6;
            let v74: L = v72 + v73;
            let v75: L = v68 - v74;
            let v76: L = v40 * v15;
            let v77: L = v76 * v15;
            let v78: L = v11 - v77;
            let v79: L = v78 * v27;
            let v80: L = v66 * v15;
            let v81: L = v26 - v80;
            let v82: L = v81 * v29;
            let v83: L = v79 + v82;
            let v84: L = v83 * v29;
            let v85: L = v75 + v84;
            let v86: L = v85 * v3;
            let v87: L = v63 + v86;
            let v88: L = v87 * v55;
            let v89: L = v39 + v88;
            let v91: L = v54 * v90;
            let v92: L = L::splat(0.3767457879045_f64);
            let v93: L = v92 * v22;
            let v94: L = v93 - v70;
            let v95: L = v92 * v6;
            let v96: L = v94 + v95;
            let v97: L = L::splat(0.0139521246075_f64);
            let v98: L = v97 * v22;
            let v99: L = v58 + v98;
            let v100: L = v97 * v6;
            let v101: L = v99 + v100;
            let v102: L = v101 * v3;
            let v103: L = v96 - v102;
            let v104: L = v103 + v68;
            let v105: L = v104 + v84;
            let v106: L = v105 * v9;
            let v107: L = v91 + v106;
            let v108: L = v1 * v6;
            let v109: L = L::splat(0.4296223275405_f64);
            let v110: L = v109 * v20;
            let v111: L = v109 * v22;
            let v112: L = v110 + v111;
            let v113: L = v109 * v6;
            let v114: L = v112 + v113;
            let v115: L = v45 * v15;
            let v116: L = v40 * v12;
            let v117: L = v116 * v32;
            let v118: L = v117 * v18;
            let v119: L = v115 - v118;
            let v120: L = v119 * v15;
            let v121: L = v114 + v120;
            let v122: L = v121 * v55;
            let v123: L = v40 * v27;
            let v124: L = v123 * v15;
            let v125: L = v124 * v32;
            let v126: L = v125 * v3;
            let v127: L = v122 - v126;
            let v128: L = v127 * v9;
            let v129: L = v108 + v128;
            let v130: L = v125 * v55;
            let v131: L = v101 + v130;
            let v132: L = v121 * v3;
            let v133: L = v131 + v132;
            let v134: L = v133 * v90;
            let v135: L = v129 + v134;
            let v136: L = v116 * v18;
            let v137: L = v136 * v3;
            let v138: L = v123 * v55;
            let v139: L = v137 - v138;
            let v140: L = v139 * v9;
            let v141: L = v136 * v55;
            let v142: L = v123 * v3;
            let v143: L = v141 + v142;
            let v144: L = v143 * v90;
            let v145: L = v140 - v144;
            let v146: L = v45 * v3;
            let v147: L = v146 * v90;
            let v148: L = v45 * v55;
            let v149: L = v148 * v9;
            let v150: L = v147 + v149;
            let v151: L = v150 * v29;
            let v152: L = v145 - v151;
            let v153: L = L::splat(0.0667421074184_f64);
            let v154: L = v153 * v20;
            let v155: L = v153 * v22;
            let v156: L = v154 + v155;
            let v157: L = v153 * v6;
            let v158: L = v156 + v157;
            let v159: L = v123 * v29;
            let v160: L = v158 + v159;
            let v161: L = v160 * v55;
            let v162: L = v161 * v90;
            let v163: L = v160 * v3;
            let v164: L = v163 * v9;
            let v165: L = v162 - v164;
            let v166: L = v165 * v32;
            let v167: L = v153 * v27;
            let v168: L = v167 * v3;
            let v169: L = v141 + v168;
            let v170: L = v169 * v90;
            let v171: L = v167 * v55;
            let v172: L = v171 - v137;
            let v173: L = v172 * v9;
            let v174: L = v170 + v173;
            let v175: L = v174 + v151;
            let v176: L = v175 * v15;
            let v177: L = v166 + v176;
            let v178: L = v177 * v15;
            let v179: L = v152 + v178;
            let v180: L = v179 * v29;
            let v181: L = v135 + v180;
            let v182: L = v181 * v55;
            let v183: L = v107 + v182;
            let v184: L = v183 * v90;
            let v185: L = v89 + v184;
            let v186: L = v1 * v20;
            let v187: L = v1 * v22;
            let v188: L = v186 + v187;
            let v189: L = L::splat(0.01511702475_f64);
            (
                v0,
                v1,
                v3,
                v4,
                v5,
                v6,
                v9,
                v11,
                v12,
                v13,
                v15,
                v18,
                v20,
                v22,
                v26,
                v27,
                v28,
                v29,
                v31,
                v32,
                v33,
                v40,
                v45,
                v51,
                v53,
                v55,
                v57,
                v58,
                v59,
                v61,
                v62,
                v64,
                v66,
                v68,
                v69,
                v76,
                v77,
                v80,
                v82,
                v84,
                v90,
                v92,
                v94,
                v97,
                v102,
                v108,
                v109,
                v110,
                v115,
                v116,
                v120,
                v122,
                v125,
                v126,
                v133,
                v136,
                v139,
                v143,
                v146,
                v148,
                v153,
                v158,
                v160,
                v161,
                v163,
                v167,
                v168,
                v169,
                v171,
                v172,
                v185,
                v188,
                v189,
            )
        };
        let (
            v193,
            v194,
            v202,
            v204,
            v210,
            v242,
            v252,
            v258,
            v266,
            v267,
            v268,
            v288,
            v298,
            v325,
            v345,
            v346,
            v347,
            v352,
            v353,
            v372,
            v375,
            v376,
            v378,
            v379,
        ) = {
            let v190: L = v189 * v6;
            let v191: L = v188 + v190;
            let v192: L = v191 * v3;
            let v193: L = v0 * v22;
            let v194: L = L::splat(1.35894538375_f64);
            let v195: L = v194 * v6;
            let v196: L = v193 + v195;
            let v197: L = v192 - v196;
            let v198: L = v197 * v9;
            let v199: L = v198 - v53;
            let v200: L = v199 + v51;
            let v201: L = q[1];
            let (v210, v202): (L, L) = L::sincos(v201);
            let v203: L = v200 * v202;
            let v204: L = L::splat(1.3782737505055_f64);
            let v205: L = v204 * v6;
            let v206: L = v94 - v205;
            let v207: L = v206 - v102;
            let v208: L = v207 + v68;
            let v209: L = v208 + v84;
            let v211: L = v209 * v210;
            let v212: L = v203 + v211;
            let v213: L = v133 * v202;
            let v214: L = v191 * v9;
            let v215: L = v214 - v126;
            let v216: L = v215 + v122;
            let v217: L = v216 * v210;
            let v218: L = v213 + v217;
            let v219: L = v139 * v210;
            let v220: L = v143 * v202;
            let v221: L = v219 - v220;
            let v222: L = v146 * v202;
            let v223: L = v148 * v210;
            let v224: L = v222 + v223;
            let v225: L = v224 * v29;
            let v226: L = v221 - v225;
            let v227: L = v161 * v202;
            let v228: L = v163 * v210;
            let v229: L = v227 - v228;
            let v230: L = v229 * v32;
            let v231: L = v169 * v202;
            let v232: L = v172 * v210;
            let v233: L = v231 + v232;
            let v234: L = v233 + v225;
            let v235: L = v234 * v15;
            let v236: L = v230 + v235;
            let v237: L = v236 * v15;
            let v238: L = v226 + v237;
            let v239: L = v238 * v29;
            let v240: L = v218 + v239;
            let v241: L = v240 * v55;
            let v242: L = v212 + v241;
            let v243: L = v116 * v15;
            let v244: L = v243 * v18;
            let v245: L = v160 * v32;
            let v246: L = v244 + v245;
            let v247: L = v246 * v15;
            let v248: L = v247 - v136;
            let v249: L = v248 * v29;
            let v250: L = v125 + v249;
            let v251: L = v250 * v90;
            let v252: L = L::splat(0.753491575809_f64);
            let v253: L = v252 * v22;
            let v254: L = v110 - v253;
            let v255: L = v252 * v6;
            let v256: L = v254 - v255;
            let v257: L = v97 * v20;
            let v258: L = L::splat(0.027904249215_f64);
            let v259: L = v258 * v22;
            let v260: L = v257 + v259;
            let v261: L = v258 * v6;
            let v262: L = v260 + v261;
            let v263: L = v262 * v3;
            let v264: L = v256 + v263;
            let v265: L = v264 + v120;
            let v266: L = -L::splat(0.0333710537092_f64);
            let v267: L = v153 * v15;
            let v268: L = v267 * v15;
            let v269: L = v266 + v268;
            let v270: L = v269 * v27;
            let v271: L = v115 * v15;
            let v272: L = v271 - v45;
            let v273: L = v272 * v29;
            let v274: L = v270 + v273;
            let v275: L = v274 * v29;
            let v276: L = v265 + v275;
            let v277: L = v276 * v9;
            let v278: L = v251 + v277;
            let v279: L = v278 * v202;
            let v280: L = v136 - v247;
            let v281: L = v280 * v29;
            let v282: L = v281 - v125;
            let v283: L = v282 * v9;
            let v284: L = v197 + v283;
            let v285: L = v276 * v90;
            let v286: L = v284 + v285;
            let v287: L = v286 * v210;
            let v288: L = v279 + v287;
            let v289: L = v167 * v15;
            let v290: L = v289 * v32;
            let v291: L = v290 * v3;
            let v292: L = v153 * v12;
            let v293: L = v292 * v32;
            let v294: L = v293 * v18;
            let v295: L = v158 * v15;
            let v296: L = v294 - v295;
            let v297: L = v296 * v15;
            let v298: L = L::splat(0.859244655081_f64);
            let v299: L = v298 * v20;
            let v300: L = v298 * v22;
            let v301: L = v299 + v300;
            let v302: L = v298 * v6;
            let v303: L = v301 + v302;
            let v304: L = v297 - v303;
            let v305: L = v304 * v55;
            let v306: L = v291 + v305;
            let v307: L = v306 * v90;
            let v308: L = v290 * v55;
            let v309: L = v262 + v308;
            let v310: L = v295 - v294;
            let v311: L = v310 * v15;
            let v312: L = v303 + v311;
            let v313: L = v312 * v3;
            let v314: L = v309 + v313;
            let v315: L = v314 * v9;
            let v316: L = v307 + v315;
            let v317: L = v316 * v210;
            let v318: L = v306 * v9;
            let v319: L = v318 - v191;
            let v320: L = v304 * v3;
            let v321: L = v320 - v309;
            let v322: L = v321 * v90;
            let v323: L = v319 + v322;
            let v324: L = v323 * v202;
            let v325: L = v317 + v324;
            let v326: L = v292 * v18;
            let v327: L = v326 * v55;
            let v328: L = v327 + v168;
            let v329: L = v328 * v90;
            let v330: L = v326 * v3;
            let v331: L = v171 - v330;
            let v332: L = v331 * v9;
            let v333: L = v329 + v332;
            let v334: L = v333 * v202;
            let v335: L = v331 * v90;
            let v336: L = v328 * v9;
            let v337: L = v335 - v336;
            let v338: L = v337 * v210;
            let v339: L = v334 + v338;
            let v340: L = v158 * v3;
            let v341: L = v340 * v90;
            let v342: L = v158 * v55;
            let v343: L = v342 * v9;
            let v344: L = v341 + v343;
            let v345: L = v344 * v202;
            let v346: L = v342 * v90;
            let v347: L = v340 * v9;
            let v348: L = v346 - v347;
            let v349: L = v348 * v210;
            let v350: L = v345 + v349;
            let v351: L = v350 * v29;
            let v352: L = v339 + v351;
            let v353: L = L::splat(0.1334842148368_f64);
            let v354: L = v353 * v20;
            let v355: L = v353 * v22;
            let v356: L = v354 + v355;
            let v357: L = v353 * v6;
            let v358: L = v356 + v357;
            let v359: L = v167 * v29;
            let v360: L = v358 + v359;
            let v361: L = v360 * v3;
            let v362: L = v361 * v9;
            let v363: L = v360 * v55;
            let v364: L = v363 * v90;
            let v365: L = v362 - v364;
            let v366: L = v365 * v202;
            let v367: L = v361 * v90;
            let v368: L = v363 * v9;
            let v369: L = v367 + v368;
            let v370: L = v369 * v210;
            let v371: L = v366 + v370;
            let v372: L = v371 * v32;
            let v373: L = v353 * v27;
            let v374: L = v373 * v55;
            let v375: L = v330 - v374;
            let v376: L = v375 * v9;
            let v377: L = v373 * v3;
            let v378: L = v327 + v377;
            let v379: L = v378 * v90;
            (
                v193,
                v194,
                v202,
                v204,
                v210,
                v242,
                v252,
                v258,
                v266,
                v267,
                v268,
                v288,
                v298,
                v325,
                v345,
                v346,
                v347,
                v352,
                v353,
                v372,
                v375,
                v376,
                v378,
                v379,
            )
        };
        let (
            v403,
            v404,
            v406,
            v407,
            v409,
            v411,
            v412,
            v415,
            v416,
            v417,
            v419,
            v420,
            v423,
            v426,
            v428,
            v430,
            v431,
            v432,
            v435,
            v439,
            v440,
            v442,
            v444,
            v446,
            v448,
            v454,
            v456,
            v458,
            v465,
            v471,
            v472,
            v474,
            v475,
            v486,
            v487,
            v489,
            v491,
            v493,
            v495,
            v497,
            v501,
            v502,
            v514,
            v516,
            v517,
            v525,
            v532,
            v533,
            v536,
            v544,
            v547,
            v551,
            v553,
            v560,
            v565,
            v566,
            v567,
            v569,
        ) = {
            let v380: L = v376 - v379;
            let v381: L = v380 * v202;
            let v382: L = v375 * v90;
            let v383: L = v378 * v9;
            let v384: L = v382 + v383;
            let v385: L = v384 * v210;
            let v386: L = v381 + v385;
            let v387: L = v347 - v346;
            let v388: L = v387 * v210;
            let v389: L = v388 - v345;
            let v390: L = v389 * v29;
            let v391: L = v386 + v390;
            let v392: L = v391 * v15;
            let v393: L = v372 + v392;
            let v394: L = v393 * v15;
            let v395: L = v352 + v394;
            let v396: L = v395 * v29;
            let v397: L = v325 + v396;
            let v398: L = v397 * v55;
            let v399: L = v288 + v398;
            let v400: L = v399 * v90;
            let v401: L = v242 + v400;
            let v402: L = v401 * v202;
            let v403: L = v185 + v402;
            let v404: L = v11 * v15;
            let v405: L = v404 * v32;
            let v406: L = v405 * v29;
            let v407: L = v5 * v9;
            let v408: L = v406 + v407;
            let v409: L = -L::splat(0.00697606230375_f64);
            let v410: L = v76 * v32;
            let v411: L = v410 * v29;
            let v412: L = v411 * v55;
            let v413: L = v409 - v412;
            let v414: L = -L::splat(0.21481116377025_f64);
            let v415: L = v404 * v15;
            let v416: L = v414 - v415;
            let v417: L = v11 - v415;
            let v418: L = v417 * v29;
            let v419: L = v418 * v29;
            let v420: L = v416 + v419;
            let v421: L = v420 * v3;
            let v422: L = v413 + v421;
            let v423: L = v422 * v55;
            let v424: L = v408 + v423;
            let v425: L = v92 - v415;
            let v426: L = v97 * v3;
            let v427: L = v425 - v426;
            let v428: L = v427 + v419;
            let v429: L = v428 * v9;
            let v430: L = v411 * v90;
            let v431: L = v429 - v430;
            let v432: L = v109 + v77;
            let v433: L = v266 + v77;
            let v434: L = v433 * v29;
            let v435: L = v434 * v29;
            let v436: L = v432 + v435;
            let v437: L = v436 * v55;
            let v438: L = v267 * v32;
            let v439: L = v438 * v29;
            let v440: L = v439 * v3;
            let v441: L = v437 - v440;
            let v442: L = v441 * v9;
            let v443: L = v1 + v442;
            let v444: L = v439 * v55;
            let v445: L = v97 + v444;
            let v446: L = v436 * v3;
            let v447: L = v445 + v446;
            let v448: L = v447 * v90;
            let v449: L = v443 + v448;
            let v450: L = v449 * v55;
            let v451: L = v431 + v450;
            let v452: L = v451 * v90;
            let v453: L = v424 + v452;
            let v454: L = qd[0];
            let v455: L = v453 * v454;
            let v456: L = L::splat(0.1099354731454_f64);
            let v457: L = v456 + v415;
            let v458: L = v457 + v419;
            let v459: L = v458 * v12;
            let v460: L = L::splat(0.00194120382525_f64);
            let v461: L = v460 * v20;
            let v462: L = v460 * v22;
            let v463: L = v461 + v462;
            let v464: L = v460 * v6;
            let v465: L = v463 + v464;
            let v466: L = v459 - v465;
            let v467: L = v466 * v55;
            let v468: L = v467 * v90;
            let v469: L = -L::splat(0.1099354731454_f64);
            let v470: L = v469 - v415;
            let v471: L = -L::splat(0.0166855268546_f64);
            let v472: L = v471 + v415;
            let v473: L = v472 * v29;
            let v474: L = v473 * v29;
            let v475: L = v470 + v474;
            let v476: L = v475 * v12;
            let v477: L = v465 + v476;
            let v478: L = v477 * v3;
            let v479: L = L::splat(0.07714261911625_f64);
            let v480: L = v479 * v22;
            let v481: L = v479 * v6;
            let v482: L = v480 + v481;
            let v483: L = v478 - v482;
            let v484: L = v483 * v9;
            let v485: L = v468 + v484;
            let v486: L = L::splat(0.0002254731454_f64);
            let v487: L = v486 * v3;
            let v488: L = v487 * v90;
            let v489: L = v486 * v55;
            let v490: L = v489 * v9;
            let v491: L = v488 + v490;
            let v492: L = v491 * v27;
            let v493: L = v26 * v3;
            let v494: L = v493 * v90;
            let v495: L = v26 * v55;
            let v496: L = v495 * v9;
            let v497: L = v494 + v496;
            let v498: L = v497 * v29;
            let v499: L = v492 - v498;
            let v500: L = v33 * v55;
            let v501: L = v26 * v29;
            let v502: L = v28 + v501;
            let v503: L = v502 * v15;
            let v504: L = v503 * v3;
            let v505: L = v500 + v504;
            let v506: L = v505 * v90;
            let v507: L = v503 * v55;
            let v508: L = v33 * v3;
            let v509: L = v507 - v508;
            let v510: L = v509 * v9;
            let v511: L = v506 + v510;
            let v512: L = v511 * v15;
            let v513: L = v499 + v512;
            let v514: L = v513 * v18;
            let v515: L = v485 + v514;
            let v516: L = v515 * v210;
            let v517: L = v455 + v516;
            let v518: L = L::splat(0.408499208875_f64);
            let v519: L = v518 * v6;
            let v520: L = -L::splat(1.3782737505055_f64);
            let v521: L = v520 - v415;
            let v522: L = v521 - v426;
            let v523: L = v522 + v419;
            let v524: L = v523 * v210;
            let v525: L = v411 * v202;
            let v526: L = v524 - v525;
            let v527: L = v526 * v454;
            let v528: L = v519 + v527;
            let v529: L = v189 * v454;
            let v530: L = v529 * v202;
            let v531: L = v486 + v415;
            let v532: L = v531 * v27;
            let v533: L = v80 - v26;
            let v534: L = v533 * v29;
            let v535: L = v532 + v534;
            let v536: L = v535 * v18;
            let v537: L = v530 + v536;
            let v538: L = v537 * v3;
            let v539: L = v194 * v454;
            let v540: L = v539 * v202;
            let v541: L = v538 - v540;
            let v542: L = v541 * v9;
            let v543: L = v528 + v542;
            let v544: L = v441 * v210;
            let v545: L = v447 * v202;
            let v546: L = v544 + v545;
            let v547: L = v546 * v454;
            let v548: L = v529 * v210;
            let v549: L = v548 - v465;
            let v550: L = v11 * v29;
            let v551: L = v550 * v29;
            let v552: L = v456 + v551;
            let v553: L = v552 * v12;
            let v554: L = v549 + v553;
            let v555: L = v11 - v551;
            let v556: L = v555 * v12;
            let v557: L = v556 * v15;
            let v558: L = v33 * v18;
            let v559: L = v557 + v558;
            let v560: L = v559 * v15;
            let v561: L = v554 + v560;
            let v562: L = v561 * v9;
            let v563: L = v547 + v562;
            let v564: L = v563 * v55;
            let v565: L = v543 + v564;
            let v566: L = v466 * v3;
            let v567: L = v482 + v566;
            let v568: L = v31 * v15;
            let v569: L = v568 * v32;
            (
                v403,
                v404,
                v406,
                v407,
                v409,
                v411,
                v412,
                v415,
                v416,
                v417,
                v419,
                v420,
                v423,
                v426,
                v428,
                v430,
                v431,
                v432,
                v435,
                v439,
                v440,
                v442,
                v444,
                v446,
                v448,
                v454,
                v456,
                v458,
                v465,
                v471,
                v472,
                v474,
                v475,
                v486,
                v487,
                v489,
                v491,
                v493,
                v495,
                v497,
                v501,
                v502,
                v514,
                v516,
                v517,
                v525,
                v532,
                v533,
                v536,
                v544,
                v547,
                v551,
                v553,
                v560,
                v565,
                v566,
                v567,
                v569,
            )
        };
        let (
            v579,
            v582,
            v589,
            v591,
            v597,
            v600,
            v617,
            v619,
            v629,
            v641,
            v671,
            v676,
            v688,
            v689,
            v717,
            v732,
            v745,
            v749,
            v751,
            v759,
        ) = {
            let v570: L = v569 * v3;
            let v571: L = -L::splat(0.0002254731454_f64);
            let v572: L = v571 - v415;
            let v573: L = v572 * v27;
            let v574: L = v573 + v82;
            let v575: L = v574 * v55;
            let v576: L = v570 + v575;
            let v577: L = v576 * v18;
            let v578: L = v567 + v577;
            let v579: L = v439 * v90;
            let v580: L = -L::splat(0.753491575809_f64);
            let v581: L = v580 + v77;
            let v582: L = v258 * v3;
            let v583: L = v581 + v582;
            let v584: L = v583 + v435;
            let v585: L = v584 * v9;
            let v586: L = v579 + v585;
            let v587: L = v586 * v202;
            let v588: L = -L::splat(1.35894538375_f64);
            let v589: L = v189 * v3;
            let v590: L = v588 + v589;
            let v591: L = v439 * v9;
            let v592: L = v590 - v591;
            let v593: L = v584 * v90;
            let v594: L = v592 + v593;
            let v595: L = v594 * v210;
            let v596: L = v587 + v595;
            let v597: L = v353 * v15;
            let v598: L = v597 * v32;
            let v599: L = v598 * v29;
            let v600: L = v599 * v3;
            let v601: L = -L::splat(0.859244655081_f64);
            let v602: L = v601 - v268;
            let v603: L = v153 - v268;
            let v604: L = v603 * v29;
            let v605: L = v604 * v29;
            let v606: L = v602 + v605;
            let v607: L = v606 * v55;
            let v608: L = v600 + v607;
            let v609: L = v608 * v90;
            let v610: L = v599 * v55;
            let v611: L = v258 + v610;
            let v612: L = v298 + v268;
            let v613: L = -L::splat(0.0667421074184_f64);
            let v614: L = v613 + v268;
            let v615: L = v614 * v29;
            let v616: L = v615 * v29;
            let v617: L = v612 + v616;
            let v618: L = v617 * v3;
            let v619: L = v611 + v618;
            let v620: L = v619 * v9;
            let v621: L = v609 + v620;
            let v622: L = v621 * v210;
            let v623: L = -L::splat(0.01511702475_f64);
            let v624: L = v608 * v9;
            let v625: L = v623 + v624;
            let v626: L = -L::splat(0.027904249215_f64);
            let v627: L = v626 - v610;
            let v628: L = v606 * v3;
            let v629: L = v627 + v628;
            let v630: L = v629 * v90;
            let v631: L = v625 + v630;
            let v632: L = v631 * v202;
            let v633: L = v622 + v632;
            let v634: L = v633 * v55;
            let v635: L = v596 + v634;
            let v636: L = v635 * v454;
            let v637: L = v578 + v636;
            let v638: L = v637 * v90;
            let v639: L = v565 + v638;
            let v640: L = v639 * v202;
            let v641: L = v517 + v640;
            let v642: L = v406 + v423;
            let v643: L = v442 + v448;
            let v644: L = v643 * v55;
            let v645: L = v431 + v644;
            let v646: L = v645 * v90;
            let v647: L = v642 + v646;
            let v648: L = v647 * v454;
            let v649: L = v648 + v516;
            let v650: L = v428 * v210;
            let v651: L = v650 - v525;
            let v652: L = v651 * v454;
            let v653: L = v1 * v454;
            let v654: L = v653 * v202;
            let v655: L = v654 + v536;
            let v656: L = v655 * v3;
            let v657: L = v0 * v454;
            let v658: L = v657 * v202;
            let v659: L = v656 - v658;
            let v660: L = v659 * v9;
            let v661: L = v652 + v660;
            let v662: L = v653 * v210;
            let v663: L = v662 - v465;
            let v664: L = v663 + v553;
            let v665: L = v664 + v560;
            let v666: L = v665 * v9;
            let v667: L = v547 + v666;
            let v668: L = v667 * v55;
            let v669: L = v661 + v668;
            let v670: L = -L::splat(0.679472691875_f64);
            let v671: L = v670 + v4;
            let v672: L = v671 - v591;
            let v673: L = v672 + v593;
            let v674: L = v673 * v210;
            let v675: L = v587 + v674;
            let v676: L = -L::splat(0.007558512375_f64);
            let v677: L = v676 + v624;
            let v678: L = v677 + v630;
            let v679: L = v678 * v202;
            let v680: L = v622 + v679;
            let v681: L = v680 * v55;
            let v682: L = v675 + v681;
            let v683: L = v682 * v454;
            let v684: L = v578 + v683;
            let v685: L = v684 * v90;
            let v686: L = v669 + v685;
            let v687: L = v686 * v202;
            let v688: L = v649 + v687;
            let v689: L = v57 * v3;
            let v690: L = v416 - v689;
            let v691: L = v690 + v419;
            let v692: L = v691 * v9;
            let v693: L = v692 - v430;
            let v694: L = v57 + v444;
            let v695: L = v694 + v446;
            let v696: L = v695 * v90;
            let v697: L = v442 + v696;
            let v698: L = v697 * v55;
            let v699: L = v693 + v698;
            let v700: L = v699 * v90;
            let v701: L = v642 + v700;
            let v702: L = v701 * v454;
            let v703: L = v465 * v3;
            let v704: L = v703 * v9;
            let v705: L = v465 * v55;
            let v706: L = v705 * v90;
            let v707: L = v704 - v706;
            let v708: L = v458 * v55;
            let v709: L = v708 * v90;
            let v710: L = v475 * v3;
            let v711: L = v710 * v9;
            let v712: L = v709 + v711;
            let v713: L = v712 * v12;
            let v714: L = v707 + v713;
            let v715: L = v714 + v514;
            let v716: L = v715 * v210;
            let v717: L = v702 + v716;
            let v718: L = v420 * v210;
            let v719: L = v718 - v525;
            let v720: L = v719 * v454;
            let v721: L = v655 * v9;
            let v722: L = v57 * v454;
            let v723: L = v722 * v210;
            let v724: L = v721 - v723;
            let v725: L = v724 * v3;
            let v726: L = v720 + v725;
            let v727: L = v695 * v202;
            let v728: L = v544 + v727;
            let v729: L = v728 * v454;
            let v730: L = v729 + v666;
            let v731: L = v730 * v55;
            let v732: L = v726 + v731;
            let v733: L = v566 + v577;
            let v734: L = v432 + v426;
            let v735: L = v734 + v435;
            let v736: L = v735 * v9;
            let v737: L = v579 + v736;
            let v738: L = v737 * v202;
            let v739: L = v4 - v591;
            let v740: L = v735 * v90;
            let v741: L = v739 + v740;
            let v742: L = v741 * v210;
            let v743: L = v738 + v742;
            let v744: L = v97 + v610;
            let v745: L = v744 + v618;
            let v746: L = v745 * v9;
            let v747: L = v609 + v746;
            let v748: L = v747 * v210;
            let v749: L = -L::splat(0.0139521246075_f64);
            let v750: L = v749 - v610;
            let v751: L = v750 + v628;
            let v752: L = v751 * v90;
            let v753: L = v677 + v752;
            let v754: L = v753 * v202;
            let v755: L = v748 + v754;
            let v756: L = v755 * v55;
            let v757: L = v743 + v756;
            let v758: L = v757 * v454;
            let v759: L = v733 + v758;
            (
                v579,
                v582,
                v589,
                v591,
                v597,
                v600,
                v617,
                v619,
                v629,
                v641,
                v671,
                v676,
                v688,
                v689,
                v717,
                v732,
                v745,
                v749,
                v751,
                v759,
            )
        };
        let (
            v763,
            v783,
            v793,
            v794,
            v795,
            v796,
            v797,
            v798,
            v799,
            v803,
            v804,
            v810,
            v811,
            v814,
            v816,
            v833,
            v841,
            v855,
            v860,
            v861,
            v863,
            v865,
            v866,
            v867,
            v868,
            v870,
            v875,
            v880,
            v881,
            v882,
            v883,
            v884,
            v888,
            v890,
            v892,
            v895,
            v907,
            v913,
            v914,
            v916,
            v920,
            v922,
            v934,
            v948,
            v949,
        ) = {
            let v760: L = v759 * v90;
            let v761: L = v732 + v760;
            let v762: L = v761 * v202;
            let v763: L = v717 + v762;
            let v764: L = v456 * v20;
            let v765: L = v456 * v22;
            let v766: L = v764 + v765;
            let v767: L = v456 * v6;
            let v768: L = v766 + v767;
            let v769: L = v768 * v3;
            let v770: L = v769 * v90;
            let v771: L = v768 * v55;
            let v772: L = v771 * v9;
            let v773: L = v770 + v772;
            let v774: L = v773 * v202;
            let v775: L = v771 * v90;
            let v776: L = v769 * v9;
            let v777: L = v775 - v776;
            let v778: L = v777 * v210;
            let v779: L = v774 + v778;
            let v780: L = v11 * v55;
            let v781: L = v780 * v55;
            let v782: L = v471 + v781;
            let v783: L = v40 * v55;
            let v784: L = v783 * v3;
            let v785: L = v784 * v9;
            let v786: L = v783 * v55;
            let v787: L = v11 - v786;
            let v788: L = v787 * v90;
            let v789: L = v785 + v788;
            let v790: L = v789 * v90;
            let v791: L = v782 + v790;
            let v792: L = v791 * v454;
            let v793: L = v792 * v18;
            let v794: L = L::splat(0.016911_f64);
            let v795: L = v794 * v3;
            let v796: L = v795 * v9;
            let v797: L = v794 * v55;
            let v798: L = v797 * v90;
            let v799: L = v796 - v798;
            let v800: L = v799 * v27;
            let v801: L = v495 * v90;
            let v802: L = v493 * v9;
            let v803: L = v801 - v802;
            let v804: L = v803 * v29;
            let v805: L = v800 + v804;
            let v806: L = v805 * v210;
            let v807: L = v793 + v806;
            let v808: L = v11 * v454;
            let v809: L = v808 * v18;
            let v810: L = v809 * v202;
            let v811: L = v40 * v3;
            let v812: L = v811 * v210;
            let v813: L = v783 * v202;
            let v814: L = v812 - v813;
            let v815: L = v814 * v454;
            let v816: L = v815 * v18;
            let v817: L = v794 * v27;
            let v818: L = v501 - v817;
            let v819: L = v818 * v9;
            let v820: L = v816 + v819;
            let v821: L = v820 * v55;
            let v822: L = v810 + v821;
            let v823: L = v153 * v55;
            let v824: L = v823 * v55;
            let v825: L = v266 + v824;
            let v826: L = v825 * v90;
            let v827: L = v826 * v202;
            let v828: L = v40 - v824;
            let v829: L = v828 * v9;
            let v830: L = v829 * v210;
            let v831: L = v827 + v830;
            let v832: L = v831 * v454;
            let v833: L = v832 * v18;
            let v834: L = v153 * v9;
            let v835: L = v834 * v202;
            let v836: L = v153 * v90;
            let v837: L = v836 * v210;
            let v838: L = v835 + v837;
            let v839: L = v838 * v454;
            let v840: L = v839 * v18;
            let v841: L = v840 * v55;
            let v842: L = v817 + v841;
            let v843: L = v501 - v842;
            let v844: L = v843 * v3;
            let v845: L = v833 + v844;
            let v846: L = v845 * v90;
            let v847: L = v822 + v846;
            let v848: L = v847 * v202;
            let v849: L = v807 + v848;
            let v850: L = v849 * v29;
            let v851: L = v779 + v850;
            let v852: L = v780 * v90;
            let v853: L = v11 * v3;
            let v854: L = v853 * v9;
            let v855: L = v852 - v854;
            let v856: L = v855 * v202;
            let v857: L = v853 * v90;
            let v858: L = v780 * v9;
            let v859: L = v857 + v858;
            let v860: L = v859 * v210;
            let v861: L = v856 - v860;
            let v862: L = v861 * v27;
            let v863: L = v854 - v852;
            let v864: L = v863 * v210;
            let v865: L = v859 * v202;
            let v866: L = v864 - v865;
            let v867: L = v866 * v12;
            let v868: L = v780 * v3;
            let v869: L = v787 * v9;
            let v870: L = v784 * v90;
            let v871: L = v869 - v870;
            let v872: L = v871 * v90;
            let v873: L = v868 + v872;
            let v874: L = v787 * v210;
            let v875: L = v784 * v202;
            let v876: L = v874 - v875;
            let v877: L = v153 * v3;
            let v878: L = v877 * v90;
            let v879: L = v823 * v9;
            let v880: L = v878 + v879;
            let v881: L = v880 * v202;
            let v882: L = v823 * v90;
            let v883: L = v877 * v9;
            let v884: L = v882 - v883;
            let v885: L = v884 * v210;
            let v886: L = v881 + v885;
            let v887: L = v886 * v55;
            let v888: L = v40 * v9;
            let v889: L = v888 * v202;
            let v890: L = v40 * v90;
            let v891: L = v890 * v210;
            let v892: L = v889 + v891;
            let v893: L = v887 - v892;
            let v894: L = v893 * v90;
            let v895: L = v876 + v894;
            let v896: L = v895 * v202;
            let v897: L = v873 + v896;
            let v898: L = v897 * v454;
            let v899: L = v867 + v898;
            let v900: L = v899 * v18;
            let v901: L = v862 + v900;
            let v902: L = v901 * v32;
            let v903: L = v497 * v202;
            let v904: L = v803 * v210;
            let v905: L = v903 + v904;
            let v906: L = v11 - v781;
            let v907: L = v471 + v786;
            let v908: L = v907 * v90;
            let v909: L = v908 - v785;
            let v910: L = v909 * v90;
            let v911: L = v906 + v910;
            let v912: L = v911 * v454;
            let v913: L = v912 * v18;
            let v914: L = v855 * v27;
            let v915: L = v802 - v801;
            let v916: L = v915 * v29;
            let v917: L = v914 + v916;
            let v918: L = v917 * v210;
            let v919: L = v913 + v918;
            let v920: L = v813 - v812;
            let v921: L = v920 * v454;
            let v922: L = v921 * v18;
            let v923: L = v28 - v501;
            let v924: L = v923 * v9;
            let v925: L = v922 + v924;
            let v926: L = v925 * v55;
            let v927: L = v926 - v810;
            let v928: L = v828 * v90;
            let v929: L = v928 * v202;
            let v930: L = v825 * v9;
            let v931: L = v930 * v210;
            let v932: L = v929 + v931;
            let v933: L = v932 * v454;
            let v934: L = v933 * v18;
            let v935: L = v28 + v841;
            let v936: L = v935 - v501;
            let v937: L = v936 * v3;
            let v938: L = v934 + v937;
            let v939: L = v938 * v90;
            let v940: L = v927 + v939;
            let v941: L = v940 * v202;
            let v942: L = v919 + v941;
            let v943: L = v942 * v29;
            let v944: L = v905 + v943;
            let v945: L = v944 * v15;
            let v946: L = v902 + v945;
            let v947: L = v946 * v15;
            let v948: L = v851 + v947;
            let v949: L = v873 * v454;
            (
                v763,
                v783,
                v793,
                v794,
                v795,
                v796,
                v797,
                v798,
                v799,
                v803,
                v804,
                v810,
                v811,
                v814,
                v816,
                v833,
                v841,
                v855,
                v860,
                v861,
                v863,
                v865,
                v866,
                v867,
                v868,
                v870,
                v875,
                v880,
                v881,
                v882,
                v883,
                v884,
                v888,
                v890,
                v892,
                v895,
                v907,
                v913,
                v914,
                v916,
                v920,
                v922,
                v934,
                v948,
                v949,
            )
        };
        let (
            v957,
            v974,
            v983,
            v988,
            v997,
            v1002,
            v1003,
            v1009,
            v1012,
            v1013,
            v1017,
            v1018,
            v1025,
            v1027,
            v1028,
            v1038,
            v1039,
            v1040,
            v1041,
            v1043,
            v1045,
            v1050,
            v1055,
            v1063,
            v1064,
            v1065,
            v1073,
            v1074,
            v1080,
            v1081,
            v1082,
            v1088,
            v1090,
            v1095,
            v1096,
            v1102,
            v1106,
            v1121,
            v1122,
            v1124,
            v1126,
            v1132,
            v1133,
            v1134,
            v1137,
            v1139,
        ) = {
            let v950: L = v949 * v29;
            let v951: L = v799 * v12;
            let v952: L = v951 * v29;
            let v953: L = v486 * v20;
            let v954: L = v486 * v22;
            let v955: L = v953 + v954;
            let v956: L = v486 * v6;
            let v957: L = v955 + v956;
            let v958: L = v957 * v3;
            let v959: L = v958 * v90;
            let v960: L = v957 * v55;
            let v961: L = v960 * v9;
            let v962: L = v959 + v961;
            let v963: L = v962 * v18;
            let v964: L = v952 + v963;
            let v965: L = v964 * v210;
            let v966: L = v950 + v965;
            let v967: L = v958 * v9;
            let v968: L = v960 * v90;
            let v969: L = v967 - v968;
            let v970: L = v969 * v18;
            let v971: L = v895 * v454;
            let v972: L = v795 * v90;
            let v973: L = v797 * v9;
            let v974: L = v972 + v973;
            let v975: L = v974 * v12;
            let v976: L = v971 - v975;
            let v977: L = v976 * v29;
            let v978: L = v970 + v977;
            let v979: L = v978 * v202;
            let v980: L = v966 + v979;
            let v981: L = v11 * v32;
            let v982: L = v981 * v29;
            let v983: L = v982 * v29;
            let v984: L = v471 - v551;
            let v985: L = v984 * v32;
            let v986: L = v985 * v55;
            let v987: L = v76 * v29;
            let v988: L = v987 * v3;
            let v989: L = v986 - v988;
            let v990: L = v989 * v55;
            let v991: L = v983 + v990;
            let v992: L = v991 * v454;
            let v993: L = v66 * v55;
            let v994: L = v26 * v32;
            let v995: L = v994 * v29;
            let v996: L = v995 * v3;
            let v997: L = v993 - v996;
            let v998: L = v997 * v18;
            let v999: L = v981 * v55;
            let v1000: L = v404 * v29;
            let v1001: L = v1000 * v3;
            let v1002: L = v999 + v1001;
            let v1003: L = v1002 * v12;
            let v1004: L = v998 - v1003;
            let v1005: L = v1004 * v9;
            let v1006: L = v1005 * v210;
            let v1007: L = v992 + v1006;
            let v1008: L = v985 * v90;
            let v1009: L = v987 * v9;
            let v1010: L = v1008 - v1009;
            let v1011: L = v1010 * v454;
            let v1012: L = v66 * v18;
            let v1013: L = v1012 - v64;
            let v1014: L = v1013 * v3;
            let v1015: L = v1014 * v210;
            let v1016: L = v1011 + v1015;
            let v1017: L = v783 * v90;
            let v1018: L = v811 * v9;
            let v1019: L = v1017 - v1018;
            let v1020: L = v1019 * v454;
            let v1021: L = v1020 * v32;
            let v1022: L = v13 * v210;
            let v1023: L = v880 * v454;
            let v1024: L = v1022 + v1023;
            let v1025: L = v1024 * v15;
            let v1026: L = v1020 * v29;
            let v1027: L = v26 * v18;
            let v1028: L = v1027 * v210;
            let v1029: L = v1026 + v1028;
            let v1030: L = v1029 * v32;
            let v1031: L = v1025 + v1030;
            let v1032: L = v1031 * v29;
            let v1033: L = v1021 + v1032;
            let v1034: L = v1033 * v55;
            let v1035: L = v1016 + v1034;
            let v1036: L = v1035 * v90;
            let v1037: L = v1007 + v1036;
            let v1038: L = v1002 * v90;
            let v1039: L = v1000 * v55;
            let v1040: L = v981 * v3;
            let v1041: L = v1039 - v1040;
            let v1042: L = v1041 * v9;
            let v1043: L = v1038 + v1042;
            let v1044: L = v1043 * v12;
            let v1045: L = v996 - v993;
            let v1046: L = v1045 * v90;
            let v1047: L = v995 * v55;
            let v1048: L = v66 * v3;
            let v1049: L = v1047 + v1048;
            let v1050: L = v1049 * v9;
            let v1051: L = v1046 + v1050;
            let v1052: L = v1051 * v18;
            let v1053: L = v1044 + v1052;
            let v1054: L = v985 * v202;
            let v1055: L = v987 * v210;
            let v1056: L = v1054 - v1055;
            let v1057: L = v920 * v32;
            let v1058: L = v40 * v32;
            let v1059: L = v1058 * v29;
            let v1060: L = v1059 * v55;
            let v1061: L = v267 * v3;
            let v1062: L = v1060 + v1061;
            let v1063: L = v1062 * v202;
            let v1064: L = v267 * v55;
            let v1065: L = v1059 * v3;
            let v1066: L = v1064 - v1065;
            let v1067: L = v1066 * v210;
            let v1068: L = v1063 + v1067;
            let v1069: L = v1068 * v29;
            let v1070: L = v1057 + v1069;
            let v1071: L = v1070 * v55;
            let v1072: L = v1056 + v1071;
            let v1073: L = v890 * v202;
            let v1074: L = v888 * v210;
            let v1075: L = v1073 - v1074;
            let v1076: L = v1075 * v32;
            let v1077: L = v1059 * v90;
            let v1078: L = v267 * v9;
            let v1079: L = v1077 + v1078;
            let v1080: L = v1079 * v202;
            let v1081: L = v267 * v90;
            let v1082: L = v1059 * v9;
            let v1083: L = v1081 - v1082;
            let v1084: L = v1083 * v210;
            let v1085: L = v1080 + v1084;
            let v1086: L = v1085 * v29;
            let v1087: L = v1076 + v1086;
            let v1088: L = v883 - v882;
            let v1089: L = v1088 * v202;
            let v1090: L = v880 * v210;
            let v1091: L = v1089 + v1090;
            let v1092: L = v1091 * v32;
            let v1093: L = v153 * v32;
            let v1094: L = v1093 * v29;
            let v1095: L = v1094 * v3;
            let v1096: L = v597 * v55;
            let v1097: L = v1095 - v1096;
            let v1098: L = v1097 * v9;
            let v1099: L = v1094 * v55;
            let v1100: L = v597 * v3;
            let v1101: L = v1099 + v1100;
            let v1102: L = v1101 * v90;
            let v1103: L = v1098 - v1102;
            let v1104: L = v1103 * v202;
            let v1105: L = v1097 * v90;
            let v1106: L = v1101 * v9;
            let v1107: L = v1105 + v1106;
            let v1108: L = v1107 * v210;
            let v1109: L = v1104 + v1108;
            let v1110: L = v1109 * v29;
            let v1111: L = v1092 + v1110;
            let v1112: L = v1111 * v55;
            let v1113: L = v1087 + v1112;
            let v1114: L = v1113 * v90;
            let v1115: L = v1072 + v1114;
            let v1116: L = v1115 * v454;
            let v1117: L = v1053 + v1116;
            let v1118: L = v1117 * v202;
            let v1119: L = v1037 + v1118;
            let v1120: L = v1119 * v15;
            let v1121: L = v980 + v1120;
            let v1122: L = L::splat(0.126621_f64);
            let v1123: L = v1122 * v3;
            let v1124: L = v1123 * v9;
            let v1125: L = v1122 * v55;
            let v1126: L = v1125 * v90;
            let v1127: L = v1124 - v1126;
            let v1128: L = v1127 * v210;
            let v1129: L = v1123 * v90;
            let v1130: L = v1125 * v9;
            let v1131: L = v1129 + v1130;
            let v1132: L = v1131 * v202;
            let v1133: L = v1128 - v1132;
            let v1134: L = v1133 * v12;
            let v1135: L = v794 - v415;
            let v1136: L = v1135 * v55;
            let v1137: L = v1136 * v90;
            let v1138: L = -L::splat(0.016911_f64);
            let v1139: L = v1138 + v415;
            (
                v957,
                v974,
                v983,
                v988,
                v997,
                v1002,
                v1003,
                v1009,
                v1012,
                v1013,
                v1017,
                v1018,
                v1025,
                v1027,
                v1028,
                v1038,
                v1039,
                v1040,
                v1041,
                v1043,
                v1045,
                v1050,
                v1055,
                v1063,
                v1064,
                v1065,
                v1073,
                v1074,
                v1080,
                v1081,
                v1082,
                v1088,
                v1090,
                v1095,
                v1096,
                v1102,
                v1106,
                v1121,
                v1122,
                v1124,
                v1126,
                v1132,
                v1133,
                v1134,
                v1137,
                v1139,
            )
        };
        let (
            v1181,
            v1185,
            v1189,
            v1194,
            v1196,
            v1198,
            v1201,
            v1203,
            v1205,
            v1208,
            v1210,
            v1225,
            v1238,
            v1240,
            v1246,
            v1249,
            v1250,
            v1252,
            v1263,
            v1268,
            v1269,
            v1277,
            v1288,
            v1293,
            v1298,
            v1301,
            v1304,
            v1307,
            v1313,
            v1316,
            v1319,
            v1324,
            v1329,
        ) = {
            let v1140: L = v1139 * v3;
            let v1141: L = v1140 * v9;
            let v1142: L = v1137 + v1141;
            let v1143: L = v1142 * v202;
            let v1144: L = v1140 * v90;
            let v1145: L = v1139 * v55;
            let v1146: L = v1145 * v9;
            let v1147: L = v1144 + v1146;
            let v1148: L = v1147 * v210;
            let v1149: L = v1143 + v1148;
            let v1150: L = v1149 * v27;
            let v1151: L = v1150 * v18;
            let v1152: L = v1134 + v1151;
            let v1153: L = v855 * v210;
            let v1154: L = v865 + v1153;
            let v1155: L = v1154 * v12;
            let v1156: L = v1155 * v29;
            let v1157: L = v867 * v15;
            let v1158: L = v1157 * v29;
            let v1159: L = v28 * v18;
            let v1160: L = v1159 * v3;
            let v1161: L = v13 * v55;
            let v1162: L = v1160 - v1161;
            let v1163: L = v1162 * v90;
            let v1164: L = v1159 * v55;
            let v1165: L = v13 * v3;
            let v1166: L = v1164 + v1165;
            let v1167: L = v1166 * v9;
            let v1168: L = v1163 + v1167;
            let v1169: L = v1168 * v202;
            let v1170: L = v1166 * v90;
            let v1171: L = v1161 - v1160;
            let v1172: L = v1171 * v9;
            let v1173: L = v1170 + v1172;
            let v1174: L = v1173 * v210;
            let v1175: L = v1169 + v1174;
            let v1176: L = v1175 * v32;
            let v1177: L = v1158 + v1176;
            let v1178: L = v1177 * v15;
            let v1179: L = v1156 + v1178;
            let v1180: L = v1179 * v29;
            let v1181: L = v1152 + v1180;
            let v1182: L = v671 * v9;
            let v1183: L = v1182 - v406;
            let v1184: L = v57 + v412;
            let v1185: L = v69 + v415;
            let v1186: L = v1185 + v474;
            let v1187: L = v1186 * v3;
            let v1188: L = v1184 + v1187;
            let v1189: L = v1188 * v55;
            let v1190: L = v1183 + v1189;
            let v1191: L = -L::splat(0.3767457879045_f64);
            let v1192: L = v1191 + v415;
            let v1193: L = v1192 + v426;
            let v1194: L = v1193 + v474;
            let v1195: L = v1194 * v9;
            let v1196: L = v430 + v1195;
            let v1197: L = -L::splat(0.4296223275405_f64);
            let v1198: L = v1197 - v77;
            let v1199: L = v40 - v77;
            let v1200: L = v1199 * v29;
            let v1201: L = v1200 * v29;
            let v1202: L = v1198 + v1201;
            let v1203: L = v1202 * v55;
            let v1204: L = v440 + v1203;
            let v1205: L = v1204 * v9;
            let v1206: L = v676 + v1205;
            let v1207: L = v749 - v444;
            let v1208: L = v1202 * v3;
            let v1209: L = v1207 + v1208;
            let v1210: L = v1209 * v90;
            let v1211: L = v1206 + v1210;
            let v1212: L = v1211 * v55;
            let v1213: L = v1196 + v1212;
            let v1214: L = v1213 * v90;
            let v1215: L = v1190 + v1214;
            let v1216: L = v194 - v589;
            let v1217: L = v1216 * v9;
            let v1218: L = v411 + v1217;
            let v1219: L = v1218 * v202;
            let v1220: L = v204 + v415;
            let v1221: L = v1220 + v426;
            let v1222: L = v1221 + v474;
            let v1223: L = v1222 * v210;
            let v1224: L = v1219 + v1223;
            let v1225: L = v1209 * v202;
            let v1226: L = v189 * v9;
            let v1227: L = v440 - v1226;
            let v1228: L = v1227 + v1203;
            let v1229: L = v1228 * v210;
            let v1230: L = v1225 + v1229;
            let v1231: L = v1230 * v55;
            let v1232: L = v1224 + v1231;
            let v1233: L = v252 - v77;
            let v1234: L = v1233 - v582;
            let v1235: L = v1234 + v1201;
            let v1236: L = v1235 * v9;
            let v1237: L = v1236 - v579;
            let v1238: L = v1237 * v202;
            let v1239: L = v1216 + v591;
            let v1240: L = v1235 * v90;
            let v1241: L = v1239 + v1240;
            let v1242: L = v1241 * v210;
            let v1243: L = v1238 + v1242;
            let v1244: L = v617 * v55;
            let v1245: L = v1244 - v600;
            let v1246: L = v1245 * v90;
            let v1247: L = v629 * v9;
            let v1248: L = v1246 + v1247;
            let v1249: L = v1248 * v210;
            let v1250: L = v1245 * v9;
            let v1251: L = v189 + v1250;
            let v1252: L = v619 * v90;
            let v1253: L = v1251 + v1252;
            let v1254: L = v1253 * v202;
            let v1255: L = v1249 + v1254;
            let v1256: L = v1255 * v55;
            let v1257: L = v1243 + v1256;
            let v1258: L = v1257 * v90;
            let v1259: L = v1232 + v1258;
            let v1260: L = v1259 * v202;
            let v1261: L = v1215 + v1260;
            let v1262: L = v1261 * v454;
            let v1263: L = v1181 + v1262;
            let v1264: L = v417 * v12;
            let v1265: L = v1264 * v18;
            let v1266: L = v53 * v29;
            let v1267: L = v1265 - v1266;
            let v1268: L = v1267 * v29;
            let v1269: L = v53 + v1268;
            let v1270: L = v188 * v90;
            let v1271: L = v58 + v1270;
            let v1272: L = v1271 * v55;
            let v1273: L = v1269 - v1272;
            let v1274: L = v188 * v3;
            let v1275: L = v1274 - v193;
            let v1276: L = v1275 * v9;
            let v1277: L = v1273 + v1276;
            let v1278: L = v188 + v108;
            let v1279: L = v1278 * v90;
            let v1280: L = v58 + v1279;
            let v1281: L = v1280 * v55;
            let v1282: L = v1269 - v1281;
            let v1283: L = v1278 * v3;
            let v1284: L = v0 * v6;
            let v1285: L = v193 + v1284;
            let v1286: L = v1283 - v1285;
            let v1287: L = v1286 * v9;
            let v1288: L = v1282 + v1287;
            let v1289: L = v1283 * v9;
            let v1290: L = v1269 + v1289;
            let v1291: L = v62 + v1279;
            let v1292: L = v1291 * v55;
            let v1293: L = v1290 - v1292;
            let v1294: L = v1139 * v27;
            let v1295: L = v1294 * v18;
            let v1296: L = v1133 * v454;
            let v1297: L = v1295 + v1296;
            let v1298: L = v1154 * v454;
            let v1299: L = v1298 * v29;
            let v1300: L = v1027 + v1299;
            let v1301: L = v64 - v1012;
            let v1302: L = v1040 - v1039;
            let v1303: L = v1302 * v9;
            let v1304: L = v1303 - v1038;
            let v1305: L = v1304 * v202;
            let v1306: L = v1302 * v90;
            let v1307: L = v1002 * v9;
            let v1308: L = v1306 + v1307;
            let v1309: L = v1308 * v210;
            let v1310: L = v1305 + v1309;
            let v1311: L = v1310 * v454;
            let v1312: L = v1301 + v1311;
            let v1313: L = v1312 * v15;
            let v1314: L = v1300 + v1313;
            let v1315: L = v1314 * v29;
            let v1316: L = v1297 + v1315;
            let v1317: L = v798 - v796;
            let v1318: L = v1317 * v202;
            let v1319: L = v974 * v210;
            let v1320: L = v1318 - v1319;
            let v1321: L = v1320 * v454;
            let v1322: L = v794 * v12;
            let v1323: L = v1321 - v1322;
            let v1324: L = v1323 * v18;
            let v1325: L = v863 * v202;
            let v1326: L = v1325 + v860;
            let v1327: L = v1326 * v454;
            let v1328: L = v13 + v1327;
            let v1329: L = v1328 * v15;
            (
                v1181,
                v1185,
                v1189,
                v1194,
                v1196,
                v1198,
                v1201,
                v1203,
                v1205,
                v1208,
                v1210,
                v1225,
                v1238,
                v1240,
                v1246,
                v1249,
                v1250,
                v1252,
                v1263,
                v1268,
                v1269,
                v1277,
                v1288,
                v1293,
                v1298,
                v1301,
                v1304,
                v1307,
                v1313,
                v1316,
                v1319,
                v1324,
                v1329,
            )
        };
        let (
            v1338,
            v1371,
            v1379,
            v1380,
            v1382,
            v1428,
            v1438,
            v1442,
            v1447,
            v1478,
            v1485,
            v1486,
            v1487,
            v1488,
            v1506,
            v1510,
            v1513,
            v1517,
            v1519,
        ) = {
            let v1330: L = v1329 * v18;
            let v1331: L = v1298 * v18;
            let v1332: L = v1331 - v501;
            let v1333: L = v1332 * v29;
            let v1334: L = v26 + v1333;
            let v1335: L = v1334 * v32;
            let v1336: L = v1330 + v1335;
            let v1337: L = v1336 * v15;
            let v1338: L = v1324 + v1337;
            let v1339: L = v1189 - v406;
            let v1340: L = v1205 + v1210;
            let v1341: L = v1340 * v55;
            let v1342: L = v1196 + v1341;
            let v1343: L = v1342 * v90;
            let v1344: L = v1339 + v1343;
            let v1345: L = v411 + v407;
            let v1346: L = v1345 * v202;
            let v1347: L = v1194 * v210;
            let v1348: L = v1346 + v1347;
            let v1349: L = v1 * v9;
            let v1350: L = v440 - v1349;
            let v1351: L = v1350 + v1203;
            let v1352: L = v1351 * v210;
            let v1353: L = v1225 + v1352;
            let v1354: L = v1353 * v55;
            let v1355: L = v1348 + v1354;
            let v1356: L = v5 + v591;
            let v1357: L = v1356 + v1240;
            let v1358: L = v1357 * v210;
            let v1359: L = v1238 + v1358;
            let v1360: L = v1 + v1250;
            let v1361: L = v1360 + v1252;
            let v1362: L = v1361 * v202;
            let v1363: L = v1249 + v1362;
            let v1364: L = v1363 * v55;
            let v1365: L = v1359 + v1364;
            let v1366: L = v1365 * v90;
            let v1367: L = v1355 + v1366;
            let v1368: L = v1367 * v202;
            let v1369: L = v1344 + v1368;
            let v1370: L = v1369 * v454;
            let v1371: L = v1181 + v1370;
            let v1372: L = v58 * v55;
            let v1373: L = v53 - v1372;
            let v1374: L = v1 * v55;
            let v1375: L = v1374 * v90;
            let v1376: L = v1375 + v407;
            let v1377: L = v1376 * v6;
            let v1378: L = v1373 + v1377;
            let v1379: L = v1378 + v1268;
            let v1380: L = v1373 + v1268;
            let v1381: L = v62 * v55;
            let v1382: L = v1269 - v1381;
            let v1383: L = v1185 + v689;
            let v1384: L = v1383 + v474;
            let v1385: L = v1384 * v9;
            let v1386: L = v430 + v1385;
            let v1387: L = v409 - v444;
            let v1388: L = v1387 + v1208;
            let v1389: L = v1388 * v90;
            let v1390: L = v1205 + v1389;
            let v1391: L = v1390 * v55;
            let v1392: L = v1386 + v1391;
            let v1393: L = v1392 * v90;
            let v1394: L = v1339 + v1393;
            let v1395: L = v4 * v9;
            let v1396: L = v411 - v1395;
            let v1397: L = v1396 * v202;
            let v1398: L = v1384 * v210;
            let v1399: L = v1397 + v1398;
            let v1400: L = v1388 * v202;
            let v1401: L = v1400 + v1352;
            let v1402: L = v1401 * v55;
            let v1403: L = v1399 + v1402;
            let v1404: L = v1198 - v426;
            let v1405: L = v1404 + v1201;
            let v1406: L = v1405 * v9;
            let v1407: L = v1406 - v579;
            let v1408: L = v1407 * v202;
            let v1409: L = v591 - v4;
            let v1410: L = v1405 * v90;
            let v1411: L = v1409 + v1410;
            let v1412: L = v1411 * v210;
            let v1413: L = v1408 + v1412;
            let v1414: L = v751 * v9;
            let v1415: L = v1246 + v1414;
            let v1416: L = v1415 * v210;
            let v1417: L = v745 * v90;
            let v1418: L = v1360 + v1417;
            let v1419: L = v1418 * v202;
            let v1420: L = v1416 + v1419;
            let v1421: L = v1420 * v55;
            let v1422: L = v1413 + v1421;
            let v1423: L = v1422 * v90;
            let v1424: L = v1403 + v1423;
            let v1425: L = v1424 * v202;
            let v1426: L = v1394 + v1425;
            let v1427: L = v1426 * v454;
            let v1428: L = v1181 + v1427;
            let v1429: L = v108 * v3;
            let v1430: L = v1429 * v9;
            let v1431: L = v53 - v1430;
            let v1432: L = v1431 + v1268;
            let v1433: L = v1 * v90;
            let v1434: L = v57 + v1433;
            let v1435: L = v1434 * v6;
            let v1436: L = v59 + v1435;
            let v1437: L = v1436 * v55;
            let v1438: L = v1432 + v1437;
            let v1439: L = v59 + v61;
            let v1440: L = v1439 * v55;
            let v1441: L = v53 + v1440;
            let v1442: L = v1441 + v1268;
            let v1443: L = v907 * v9;
            let v1444: L = v870 + v1443;
            let v1445: L = v1444 * v90;
            let v1446: L = v1445 - v868;
            let v1447: L = v1446 * v454;
            let v1448: L = v1447 * v15;
            let v1449: L = v1448 * v32;
            let v1450: L = v1449 * v18;
            let v1451: L = v1122 * v20;
            let v1452: L = v1122 * v22;
            let v1453: L = v1451 + v1452;
            let v1454: L = v1122 * v6;
            let v1455: L = v1453 + v1454;
            let v1456: L = v1455 * v55;
            let v1457: L = v53 * v3;
            let v1458: L = v1456 - v1457;
            let v1459: L = v1458 * v90;
            let v1460: L = v53 * v55;
            let v1461: L = v1455 * v3;
            let v1462: L = v1460 + v1461;
            let v1463: L = v1462 * v9;
            let v1464: L = v1459 - v1463;
            let v1465: L = v1464 * v210;
            let v1466: L = v1450 + v1465;
            let v1467: L = v1461 * v90;
            let v1468: L = v1456 * v9;
            let v1469: L = v1467 + v1468;
            let v1470: L = v907 * v210;
            let v1471: L = v875 + v1470;
            let v1472: L = v1088 * v210;
            let v1473: L = v1472 - v881;
            let v1474: L = v1473 * v55;
            let v1475: L = v892 + v1474;
            let v1476: L = v1475 * v90;
            let v1477: L = v1471 + v1476;
            let v1478: L = v1477 * v454;
            let v1479: L = v1478 * v18;
            let v1480: L = v914 + v1479;
            let v1481: L = v1480 * v15;
            let v1482: L = v1481 * v32;
            let v1483: L = v1469 + v1482;
            let v1484: L = v1483 * v202;
            let v1485: L = v1466 + v1484;
            let v1486: L = v489 * v90;
            let v1487: L = v487 * v9;
            let v1488: L = v1486 - v1487;
            let v1489: L = v1488 * v27;
            let v1490: L = v1489 + v916;
            let v1491: L = v1490 * v210;
            let v1492: L = v913 + v1491;
            let v1493: L = v486 * v27;
            let v1494: L = v1493 - v501;
            let v1495: L = v1494 * v9;
            let v1496: L = v922 + v1495;
            let v1497: L = v1496 * v55;
            let v1498: L = v1497 - v810;
            let v1499: L = v1493 + v841;
            let v1500: L = v1499 - v501;
            let v1501: L = v1500 * v3;
            let v1502: L = v934 + v1501;
            let v1503: L = v1502 * v90;
            let v1504: L = v1498 + v1503;
            let v1505: L = v1504 * v202;
            let v1506: L = v1492 + v1505;
            let v1507: L = v803 * v202;
            let v1508: L = v497 * v210;
            let v1509: L = v1507 - v1508;
            let v1510: L = v1509 * v32;
            let v1511: L = v914 + v804;
            let v1512: L = v1511 * v210;
            let v1513: L = v793 + v1512;
            let v1514: L = v502 * v9;
            let v1515: L = v816 + v1514;
            let v1516: L = v1515 * v55;
            let v1517: L = v810 + v1516;
            let v1518: L = v28 - v841;
            let v1519: L = v1518 + v501;
            (
                v1338,
                v1371,
                v1379,
                v1380,
                v1382,
                v1428,
                v1438,
                v1442,
                v1447,
                v1478,
                v1485,
                v1486,
                v1487,
                v1488,
                v1506,
                v1510,
                v1513,
                v1517,
                v1519,
            )
        };
        let (v1531, v1558, v1559, v1575, v1679, v1698, v1704, v1705) = {
            let v1520: L = v1519 * v3;
            let v1521: L = v833 + v1520;
            let v1522: L = v1521 * v90;
            let v1523: L = v1517 + v1522;
            let v1524: L = v1523 * v202;
            let v1525: L = v1513 + v1524;
            let v1526: L = v1525 * v15;
            let v1527: L = v1510 + v1526;
            let v1528: L = v1527 * v15;
            let v1529: L = v1506 + v1528;
            let v1530: L = v1529 * v29;
            let v1531: L = v1485 + v1530;
            let v1532: L = v532 * v18;
            let v1533: L = v1126 - v1124;
            let v1534: L = v1533 * v210;
            let v1535: L = v1132 + v1534;
            let v1536: L = v1535 * v454;
            let v1537: L = v1532 + v1536;
            let v1538: L = v533 * v18;
            let v1539: L = v861 * v15;
            let v1540: L = v1539 * v32;
            let v1541: L = v472 * v3;
            let v1542: L = v1541 * v90;
            let v1543: L = v472 * v55;
            let v1544: L = v1543 * v9;
            let v1545: L = v1542 + v1544;
            let v1546: L = v1545 * v202;
            let v1547: L = v1543 * v90;
            let v1548: L = v417 * v3;
            let v1549: L = v1548 * v9;
            let v1550: L = v1547 + v1549;
            let v1551: L = v1550 * v210;
            let v1552: L = v1546 + v1551;
            let v1553: L = v1552 * v29;
            let v1554: L = v1540 + v1553;
            let v1555: L = v1554 * v454;
            let v1556: L = v1538 + v1555;
            let v1557: L = v1556 * v29;
            let v1558: L = v1537 + v1557;
            let v1559: L = -v53;
            let v1560: L = v957 * v18;
            let v1561: L = v491 * v202;
            let v1562: L = v1488 * v210;
            let v1563: L = v1561 + v1562;
            let v1564: L = v1563 * v454;
            let v1565: L = v1564 * v29;
            let v1566: L = v1560 + v1565;
            let v1567: L = v1043 * v202;
            let v1568: L = v1041 * v90;
            let v1569: L = v1568 - v1307;
            let v1570: L = v1569 * v210;
            let v1571: L = v1567 + v1570;
            let v1572: L = v1571 * v454;
            let v1573: L = v1013 + v1572;
            let v1574: L = v1573 * v15;
            let v1575: L = v1566 + v1574;
            let v1576: L = v1447 * v29;
            let v1577: L = v1487 - v1486;
            let v1578: L = v1577 * v12;
            let v1579: L = v1578 * v29;
            let v1580: L = v794 * v20;
            let v1581: L = v794 * v22;
            let v1582: L = v1580 + v1581;
            let v1583: L = v794 * v6;
            let v1584: L = v1582 + v1583;
            let v1585: L = v1584 * v3;
            let v1586: L = v1585 * v90;
            let v1587: L = v1584 * v55;
            let v1588: L = v1587 * v9;
            let v1589: L = v1586 + v1588;
            let v1590: L = v1589 * v18;
            let v1591: L = v1579 + v1590;
            let v1592: L = v1591 * v210;
            let v1593: L = v1576 + v1592;
            let v1594: L = v1585 * v9;
            let v1595: L = v1587 * v90;
            let v1596: L = v1594 - v1595;
            let v1597: L = v1596 * v18;
            let v1598: L = v491 * v12;
            let v1599: L = v1478 - v1598;
            let v1600: L = v1599 * v29;
            let v1601: L = v1597 + v1600;
            let v1602: L = v1601 * v202;
            let v1603: L = v1593 + v1602;
            let v1604: L = v11 + v551;
            let v1605: L = v1604 * v32;
            let v1606: L = v1605 * v55;
            let v1607: L = v988 + v1606;
            let v1608: L = v1607 * v55;
            let v1609: L = v1608 - v983;
            let v1610: L = v1609 * v454;
            let v1611: L = v1045 * v18;
            let v1612: L = v1003 + v1611;
            let v1613: L = v1612 * v9;
            let v1614: L = v1613 * v210;
            let v1615: L = v1610 + v1614;
            let v1616: L = v1605 * v90;
            let v1617: L = v1009 + v1616;
            let v1618: L = v1617 * v454;
            let v1619: L = v1301 * v3;
            let v1620: L = v1619 * v210;
            let v1621: L = v1618 + v1620;
            let v1622: L = v1018 - v1017;
            let v1623: L = v1622 * v454;
            let v1624: L = v1623 * v32;
            let v1625: L = v1623 * v29;
            let v1626: L = v1625 - v1028;
            let v1627: L = v1626 * v32;
            let v1628: L = v1627 - v1025;
            let v1629: L = v1628 * v29;
            let v1630: L = v1624 + v1629;
            let v1631: L = v1630 * v55;
            let v1632: L = v1621 + v1631;
            let v1633: L = v1632 * v90;
            let v1634: L = v1615 + v1633;
            let v1635: L = v1304 * v12;
            let v1636: L = v997 * v90;
            let v1637: L = v1636 - v1050;
            let v1638: L = v1637 * v18;
            let v1639: L = v1635 + v1638;
            let v1640: L = v1605 * v202;
            let v1641: L = v1055 + v1640;
            let v1642: L = v814 * v32;
            let v1643: L = v1065 - v1064;
            let v1644: L = v1643 * v210;
            let v1645: L = v1644 - v1063;
            let v1646: L = v1645 * v29;
            let v1647: L = v1642 + v1646;
            let v1648: L = v1647 * v55;
            let v1649: L = v1641 + v1648;
            let v1650: L = v1074 - v1073;
            let v1651: L = v1650 * v32;
            let v1652: L = v1082 - v1081;
            let v1653: L = v1652 * v210;
            let v1654: L = v1653 - v1080;
            let v1655: L = v1654 * v29;
            let v1656: L = v1651 + v1655;
            let v1657: L = v884 * v202;
            let v1658: L = v1657 - v1090;
            let v1659: L = v1658 * v32;
            let v1660: L = v1096 - v1095;
            let v1661: L = v1660 * v9;
            let v1662: L = v1102 + v1661;
            let v1663: L = v1662 * v202;
            let v1664: L = v1660 * v90;
            let v1665: L = v1664 - v1106;
            let v1666: L = v1665 * v210;
            let v1667: L = v1663 + v1666;
            let v1668: L = v1667 * v29;
            let v1669: L = v1659 + v1668;
            let v1670: L = v1669 * v55;
            let v1671: L = v1656 + v1670;
            let v1672: L = v1671 * v90;
            let v1673: L = v1649 + v1672;
            let v1674: L = v1673 * v454;
            let v1675: L = v1639 + v1674;
            let v1676: L = v1675 * v202;
            let v1677: L = v1634 + v1676;
            let v1678: L = v1677 * v15;
            let v1679: L = v1603 + v1678;
            let v1680: L = v799 * v202;
            let v1681: L = v1680 + v1319;
            let v1682: L = v1681 * v454;
            let v1683: L = v486 * v12;
            let v1684: L = v1682 - v1683;
            let v1685: L = v1684 * v18;
            let v1686: L = v861 * v454;
            let v1687: L = v1686 - v13;
            let v1688: L = v1687 * v15;
            let v1689: L = v1688 * v18;
            let v1690: L = v866 * v454;
            let v1691: L = v1690 * v18;
            let v1692: L = v501 + v1691;
            let v1693: L = v1692 * v29;
            let v1694: L = v1693 - v26;
            let v1695: L = v1694 * v32;
            let v1696: L = v1689 + v1695;
            let v1697: L = v1696 * v15;
            let v1698: L = v1685 + v1697;
            let v1699: L = v1577 * v210;
            let v1700: L = v1699 - v1561;
            let v1701: L = v1700 * v454;
            let v1702: L = v1701 * v29;
            let v1703: L = v1702 - v1560;
            let v1704: L = v1703 + v1313;
            let v1705: L = L::splat(0.0_f64);
            (v1531, v1558, v1559, v1575, v1679, v1698, v1704, v1705)
        };
        [
            [v403, v641, v688, v763, v948, v1121],
            [v1263, v1277, v1288, v1293, v1316, v1338],
            [v1371, v1379, v1380, v1382, v1316, v1338],
            [v1428, v1438, v1442, v1269, v1316, v1338],
            [v1531, v1558, v1558, v1558, v1559, v1575],
            [v1679, v1698, v1698, v1698, v1704, v1705],
        ]
    }
    /// Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 6]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis: [L; 6]`: c(q, qd) = C(q, qd) qd (N m or N)
    ///
    /// Operation count: 393 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn coriolis<L: crate::lanes::Lane>(q: &[L; 6], qd: &[L; 6]) -> [L; 6] {
        let (
            v1,
            v2,
            v3,
            v5,
            v6,
            v7,
            v9,
            v11,
            v12,
            v16,
            v17,
            v18,
            v20,
            v21,
            v25,
            v27,
            v28,
            v30,
            v31,
            v36,
            v39,
            v41,
            v42,
            v44,
            v45,
            v49,
            v50,
            v52,
            v56,
            v57,
            v61,
            v62,
            v65,
            v67,
            v69,
            v70,
            v72,
            v77,
            v82,
            v85,
            v87,
            v88,
            v89,
            v91,
            v94,
            v96,
            v98,
            v100,
            v103,
            v104,
            v106,
            v109,
            v111,
            v112,
            v113,
            v114,
            v121,
            v123,
            v125,
            v130,
            v132,
            v133,
            v137,
            v138,
            v139,
            v141,
            v144,
        ) = {
            let v0: L = q[1];
            let (v3, v1): (L, L) = L::sincos(v0);
            let v2: L = L::splat(0.88490187591_f64);
            let v4: L = qd[0];
            let v5: L = v3 * v4;
            let v6: L = qd[1];
            let v7: L = v5 * v6;
            let v8: L = v2 * v7;
            let v9: L = v2 * v6;
            let v10: L = v5 * v9;
            let v11: L = L::splat(0.0151074_f64);
            let v12: L = v11 * v5;
            let v13: L = v6 * v12;
            let v14: L = v10 - v13;
            let v15: L = v8 + v14;
            let v16: L = L::splat(2.35004_f64);
            let v17: L = L::splat(0.13585_f64);
            let v18: L = v17 * v5;
            let v19: L = v5 * v18;
            let v20: L = v1 * v4;
            let v21: L = v17 * v20;
            let v22: L = v20 * v21;
            let v23: L = v19 + v22;
            let v24: L = v16 * v23;
            let v25: L = v15 + v24;
            let v26: L = q[2];
            let (v30, v27): (L, L) = L::sincos(v26);
            let v28: L = L::splat(0.191630813556_f64);
            let v29: L = v27 * v7;
            let v31: L = v20 * v6;
            let v32: L = v30 * v31;
            let v33: L = v29 + v32;
            let v34: L = v30 * v20;
            let v35: L = v27 * v5;
            let v36: L = v34 + v35;
            let v37: L = qd[2];
            let v38: L = v36 * v37;
            let v39: L = v33 + v38;
            let v40: L = v28 * v39;
            let v41: L = v6 + v37;
            let v42: L = v28 * v41;
            let v43: L = v36 * v42;
            let v44: L = L::splat(0.004095_f64);
            let v45: L = v44 * v36;
            let v46: L = v41 * v45;
            let v47: L = v43 - v46;
            let v48: L = v40 + v47;
            let v49: L = L::splat(0.56875_f64);
            let v50: L = L::splat(0.425_f64);
            let v51: L = v50 * v7;
            let v52: L = v50 * v6;
            let v53: L = v5 * v52;
            let v54: L = v51 + v53;
            let v55: L = v23 + v54;
            let v56: L = -L::splat(0.1197_f64);
            let v57: L = v56 * v36;
            let v58: L = v36 * v57;
            let v59: L = v30 * v5;
            let v60: L = v27 * v20;
            let v61: L = v59 - v60;
            let v62: L = v56 * v61;
            let v63: L = v61 * v62;
            let v64: L = v58 + v63;
            let v65: L = v55 + v64;
            let v66: L = v49 * v65;
            let v67: L = v48 + v66;
            let v68: L = q[3];
            let (v72, v69): (L, L) = L::sincos(v68);
            let v70: L = L::splat(0.21942_f64);
            let v71: L = v69 * v39;
            let v73: L = v30 * v7;
            let v74: L = v27 * v31;
            let v75: L = v73 - v74;
            let v76: L = v61 * v37;
            let v77: L = v75 + v76;
            let v78: L = v72 * v77;
            let v79: L = v71 - v78;
            let v80: L = v69 * v36;
            let v81: L = v72 * v61;
            let v82: L = v80 - v81;
            let v83: L = qd[3];
            let v84: L = v82 * v83;
            let v85: L = v79 + v84;
            let v86: L = v70 * v85;
            let v87: L = L::splat(0.111172755531_f64);
            let v88: L = v41 + v83;
            let v89: L = v87 * v88;
            let v90: L = v82 * v89;
            let v91: L = v87 * v82;
            let v92: L = v88 * v91;
            let v93: L = v90 - v92;
            let v94: L = v86 + v93;
            let v95: L = q[4];
            let (v98, v96): (L, L) = L::sincos(v95);
            let v97: L = v96 * v82;
            let v99: L = v98 * v88;
            let v100: L = v97 + v99;
            let v101: L = v96 * v88;
            let v102: L = v98 * v82;
            let v103: L = v101 - v102;
            let v104: L = v87 * v103;
            let v105: L = v100 * v104;
            let v106: L = v87 * v100;
            let v107: L = v103 * v106;
            let v108: L = v105 - v107;
            let v109: L = v86 + v108;
            let v110: L = q[5];
            let (v113, v111): (L, L) = L::sincos(v110);
            let v112: L = L::splat(0.033822_f64);
            let v114: L = qd[4];
            let v115: L = v103 * v114;
            let v116: L = v72 * v39;
            let v117: L = v69 * v77;
            let v118: L = v116 + v117;
            let v119: L = v69 * v61;
            let v120: L = v72 * v36;
            let v121: L = v119 + v120;
            let v122: L = v121 * v83;
            let v123: L = v118 + v122;
            let v124: L = v96 * v123;
            let v125: L = v115 - v124;
            let v126: L = v113 * v125;
            let v127: L = v111 * v85;
            let v128: L = v126 + v127;
            let v129: L = v111 * v100;
            let v130: L = v121 + v114;
            let v131: L = v113 * v130;
            let v132: L = v129 - v131;
            let v133: L = qd[5];
            let v134: L = v132 * v133;
            let v135: L = v128 + v134;
            let v136: L = v112 * v135;
            let v137: L = L::splat(0.0171364731454_f64);
            let v138: L = v103 + v133;
            let v139: L = v137 * v138;
            let v140: L = v132 * v139;
            let v141: L = v137 * v132;
            let v142: L = v138 * v141;
            let v143: L = v140 - v142;
            let v144: L = v136 + v143;
            (
                v1,
                v2,
                v3,
                v5,
                v6,
                v7,
                v9,
                v11,
                v12,
                v16,
                v17,
                v18,
                v20,
                v21,
                v25,
                v27,
                v28,
                v30,
                v31,
                v36,
                v39,
                v41,
                v42,
                v44,
                v45,
                v49,
                v50,
                v52,
                v56,
                v57,
                v61,
                v62,
                v65,
                v67,
                v69,
                v70,
                v72,
                v77,
                v82,
                v85,
                v87,
                v88,
                v89,
                v91,
                v94,
                v96,
                v98,
                v100,
                v103,
                v104,
                v106,
                v109,
                v111,
                v112,
                v113,
                v114,
                v121,
                v123,
                v125,
                v130,
                v132,
                v133,
                v137,
                v138,
                v139,
                v141,
                v144,
            )
        };
        let (
            v151,
            v155,
            v162,
            v164,
            v165,
            v172,
            v179,
            v189,
            v190,
            v201,
            v208,
            v214,
            v224,
            v227,
            v236,
            v240,
            v248,
            v253,
            v255,
            v256,
            v267,
            v269,
            v271,
            v272,
            v273,
            v278,
            v280,
            v288,
            v289,
        ) = {
            let v145: L = v111 * v144;
            let v146: L = v111 * v125;
            let v147: L = v113 * v85;
            let v148: L = v146 - v147;
            let v149: L = v113 * v100;
            let v150: L = v111 * v130;
            let v151: L = v149 + v150;
            let v152: L = v151 * v133;
            let v153: L = v148 - v152;
            let v154: L = v137 * v153;
            let v155: L = v112 * v151;
            let v156: L = v138 * v155;
            let v157: L = v151 * v139;
            let v158: L = v156 - v157;
            let v159: L = v154 + v158;
            let v160: L = v113 * v159;
            let v161: L = v145 - v160;
            let v162: L = v109 + v161;
            let v163: L = v94 + v162;
            let v164: L = L::splat(0.093_f64);
            let v165: L = L::splat(1.219_f64);
            let v166: L = v164 * v82;
            let v167: L = v88 * v166;
            let v168: L = v164 * v85;
            let v169: L = v167 - v168;
            let v170: L = v17 * v31;
            let v171: L = v6 * v21;
            let v172: L = v170 - v171;
            let v173: L = v50 * v20;
            let v174: L = v5 * v173;
            let v175: L = v172 + v174;
            let v176: L = v27 * v175;
            let v177: L = v17 * v7;
            let v178: L = v6 * v18;
            let v179: L = v177 - v178;
            let v180: L = v20 * v173;
            let v181: L = v6 * v52;
            let v182: L = v180 + v181;
            let v183: L = v179 - v182;
            let v184: L = v30 * v183;
            let v185: L = v176 - v184;
            let v186: L = v41 * v62;
            let v187: L = v56 * v77;
            let v188: L = v186 - v187;
            let v189: L = v185 + v188;
            let v190: L = L::splat(0.39225_f64);
            let v191: L = v190 * v61;
            let v192: L = v36 * v191;
            let v193: L = v189 - v192;
            let v194: L = v72 * v193;
            let v195: L = v30 * v175;
            let v196: L = v27 * v183;
            let v197: L = v195 + v196;
            let v198: L = v56 * v39;
            let v199: L = v41 * v57;
            let v200: L = v198 - v199;
            let v201: L = v197 + v200;
            let v202: L = v61 * v191;
            let v203: L = v190 * v41;
            let v204: L = v41 * v203;
            let v205: L = v202 + v204;
            let v206: L = v201 - v205;
            let v207: L = v69 * v206;
            let v208: L = v194 + v207;
            let v209: L = v169 - v208;
            let v210: L = v96 * v209;
            let v211: L = v190 * v39;
            let v212: L = v36 * v203;
            let v213: L = v211 + v212;
            let v214: L = v65 + v213;
            let v215: L = v164 * v121;
            let v216: L = v121 * v215;
            let v217: L = v82 * v166;
            let v218: L = v216 + v217;
            let v219: L = v214 + v218;
            let v220: L = v98 * v219;
            let v221: L = v210 - v220;
            let v222: L = v165 * v221;
            let v223: L = L::splat(0.1879_f64);
            let v224: L = L::splat(0.09465_f64);
            let v225: L = v98 * v123;
            let v226: L = v100 * v114;
            let v227: L = v225 - v226;
            let v228: L = v224 * v227;
            let v229: L = v224 * v100;
            let v230: L = v130 * v229;
            let v231: L = v228 + v230;
            let v232: L = v221 + v231;
            let v233: L = v111 * v232;
            let v234: L = v69 * v193;
            let v235: L = v72 * v206;
            let v236: L = v234 - v235;
            let v237: L = v88 * v215;
            let v238: L = v164 * v123;
            let v239: L = v237 - v238;
            let v240: L = v236 + v239;
            let v241: L = v100 * v229;
            let v242: L = v224 * v103;
            let v243: L = v103 * v242;
            let v244: L = v241 + v243;
            let v245: L = v240 - v244;
            let v246: L = v113 * v245;
            let v247: L = v233 - v246;
            let v248: L = v223 * v247;
            let v249: L = v111 * v248;
            let v250: L = v113 * v232;
            let v251: L = v111 * v245;
            let v252: L = v250 + v251;
            let v253: L = v223 * v252;
            let v254: L = v113 * v253;
            let v255: L = v249 + v254;
            let v256: L = v222 + v255;
            let v257: L = v96 * v256;
            let v258: L = v130 * v242;
            let v259: L = v224 * v125;
            let v260: L = v258 - v259;
            let v261: L = v98 * v209;
            let v262: L = v96 * v219;
            let v263: L = v261 + v262;
            let v264: L = v260 - v263;
            let v265: L = v223 * v264;
            let v266: L = v165 * v263;
            let v267: L = v265 - v266;
            let v268: L = v98 * v267;
            let v269: L = v257 - v268;
            let v270: L = v164 * v269;
            let v271: L = v163 - v270;
            let v272: L = v69 * v271;
            let v273: L = v70 * v121;
            let v274: L = v88 * v273;
            let v275: L = v121 * v89;
            let v276: L = v274 - v275;
            let v277: L = v87 * v123;
            let v278: L = v276 - v277;
            let v279: L = v87 * v125;
            let v280: L = v70 * v130;
            let v281: L = v103 * v280;
            let v282: L = v130 * v104;
            let v283: L = v281 - v282;
            let v284: L = v279 + v283;
            let v285: L = v111 * v159;
            let v286: L = v113 * v144;
            let v287: L = v285 + v286;
            let v288: L = v284 + v287;
            let v289: L = v224 * v265;
            (
                v151,
                v155,
                v162,
                v164,
                v165,
                v172,
                v179,
                v189,
                v190,
                v201,
                v208,
                v214,
                v224,
                v227,
                v236,
                v240,
                v248,
                v253,
                v255,
                v256,
                v267,
                v269,
                v271,
                v272,
                v273,
                v278,
                v280,
                v288,
                v289,
            )
        };
        let (v301, v410, v427, v430, v433) = {
            let v290: L = v288 - v289;
            let v291: L = v96 * v290;
            let v292: L = v87 * v227;
            let v293: L = v130 * v106;
            let v294: L = v100 * v280;
            let v295: L = v293 - v294;
            let v296: L = v292 + v295;
            let v297: L = v137 * v227;
            let v298: L = v151 * v141;
            let v299: L = v132 * v155;
            let v300: L = v298 - v299;
            let v301: L = v297 + v300;
            let v302: L = v296 + v301;
            let v303: L = v224 * v255;
            let v304: L = v302 + v303;
            let v305: L = v98 * v304;
            let v306: L = v291 - v305;
            let v307: L = v278 + v306;
            let v308: L = v165 * v240;
            let v309: L = v111 * v253;
            let v310: L = v113 * v248;
            let v311: L = v309 - v310;
            let v312: L = v308 + v311;
            let v313: L = v164 * v312;
            let v314: L = v307 + v313;
            let v315: L = v72 * v314;
            let v316: L = v272 - v315;
            let v317: L = v67 + v316;
            let v318: L = v98 * v256;
            let v319: L = v96 * v267;
            let v320: L = v318 + v319;
            let v321: L = v165 * v214;
            let v322: L = v320 - v321;
            let v323: L = v190 * v322;
            let v324: L = v317 - v323;
            let v325: L = L::splat(2.275_f64);
            let v326: L = v325 * v201;
            let v327: L = v49 * v61;
            let v328: L = v61 * v327;
            let v329: L = v49 * v41;
            let v330: L = v41 * v329;
            let v331: L = v328 + v330;
            let v332: L = v326 - v331;
            let v333: L = v165 * v208;
            let v334: L = v269 - v333;
            let v335: L = v69 * v334;
            let v336: L = v165 * v236;
            let v337: L = v336 + v312;
            let v338: L = v72 * v337;
            let v339: L = v335 + v338;
            let v340: L = v332 - v339;
            let v341: L = v56 * v340;
            let v342: L = v324 + v341;
            let v343: L = v27 * v342;
            let v344: L = v44 * v77;
            let v345: L = v61 * v42;
            let v346: L = v28 * v61;
            let v347: L = v41 * v346;
            let v348: L = v345 - v347;
            let v349: L = v344 + v348;
            let v350: L = v69 * v314;
            let v351: L = v72 * v271;
            let v352: L = v350 + v351;
            let v353: L = v349 - v352;
            let v354: L = v325 * v189;
            let v355: L = v36 * v327;
            let v356: L = v354 - v355;
            let v357: L = v69 * v337;
            let v358: L = v72 * v334;
            let v359: L = v357 - v358;
            let v360: L = v356 + v359;
            let v361: L = v56 * v360;
            let v362: L = v353 - v361;
            let v363: L = v30 * v362;
            let v364: L = v343 + v363;
            let v365: L = v25 + v364;
            let v366: L = v325 * v65;
            let v367: L = v49 * v39;
            let v368: L = v36 * v329;
            let v369: L = v367 + v368;
            let v370: L = v366 + v369;
            let v371: L = v322 - v370;
            let v372: L = v50 * v371;
            let v373: L = v365 - v372;
            let v374: L = L::splat(8.393_f64);
            let v375: L = v374 * v179;
            let v376: L = v16 * v20;
            let v377: L = v20 * v376;
            let v378: L = v16 * v6;
            let v379: L = v6 * v378;
            let v380: L = v377 + v379;
            let v381: L = v375 - v380;
            let v382: L = v27 * v340;
            let v383: L = v30 * v360;
            let v384: L = v382 - v383;
            let v385: L = v381 + v384;
            let v386: L = v17 * v385;
            let v387: L = v373 + v386;
            let v388: L = v1 * v387;
            let v389: L = v2 * v20;
            let v390: L = v6 * v389;
            let v391: L = v20 * v9;
            let v392: L = v390 - v391;
            let v393: L = v11 * v31;
            let v394: L = v392 - v393;
            let v395: L = v27 * v362;
            let v396: L = v30 * v342;
            let v397: L = v395 - v396;
            let v398: L = v394 + v397;
            let v399: L = v374 * v172;
            let v400: L = v5 * v376;
            let v401: L = v399 + v400;
            let v402: L = v27 * v360;
            let v403: L = v30 * v340;
            let v404: L = v402 + v403;
            let v405: L = v401 + v404;
            let v406: L = v17 * v405;
            let v407: L = v398 - v406;
            let v408: L = v3 * v407;
            let v409: L = v388 + v408;
            let v410: L = -v409;
            let v411: L = v5 * v389;
            let v412: L = v20 * v12;
            let v413: L = v411 - v412;
            let v414: L = v16 * v172;
            let v415: L = v413 + v414;
            let v416: L = v61 * v45;
            let v417: L = v36 * v346;
            let v418: L = v416 - v417;
            let v419: L = v49 * v189;
            let v420: L = v418 + v419;
            let v421: L = v121 * v91;
            let v422: L = v82 * v273;
            let v423: L = v421 - v422;
            let v424: L = v98 * v290;
            let v425: L = v96 * v304;
            let v426: L = v424 + v425;
            let v427: L = v423 + v426;
            let v428: L = v420 + v427;
            let v429: L = v190 * v359;
            let v430: L = v428 + v429;
            let v431: L = v415 + v430;
            let v432: L = v50 * v404;
            let v433: L = v431 + v432;
            (v301, v410, v427, v430, v433)
        };
        [v410, v433, v430, v427, v162, v301]
    }
    /// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `gravity: [L; 6]`: g(q), joint torques (N m) or forces (N) that hold the robot still
    ///
    /// Operation count: 24 floating-point operations, 6 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn gravity<L: crate::lanes::Lane>(q: &[L; 6]) -> [L; 6] {
        let v0: L = L::splat(0.0_f64);
        let v1: L = L::splat(0.17446825035_f64);
        let v2: L = q[3];
        let (v9, v3): (L, L) = L::sincos(v2);
        let v4: L = v1 * v3;
        let v5: L = q[2];
        let (v12, v6): (L, L) = L::sincos(v5);
        let v7: L = v4 * v6;
        let v8: L = L::splat(15.68382848775_f64);
        let v10: L = v1 * v9;
        let v11: L = v8 - v10;
        let v13: L = v11 * v12;
        let v14: L = v7 + v13;
        let v15: L = q[1];
        let (v16, v25): (L, L) = L::sincos(v15);
        let v17: L = v14 * v16;
        let v18: L = -L::splat(43.486969725_f64);
        let v19: L = v4 * v12;
        let v20: L = v18 + v19;
        let v21: L = -L::splat(15.68382848775_f64);
        let v22: L = v21 + v10;
        let v23: L = v22 * v6;
        let v24: L = v20 + v23;
        let v26: L = v24 * v25;
        let v27: L = v17 + v26;
        let v28: L = v19 + v23;
        let v29: L = v28 * v25;
        let v30: L = v29 + v17;
        let v31: L = v10 * v6;
        let v32: L = v31 + v19;
        let v33: L = v32 * v25;
        let v34: L = v10 * v12;
        let v35: L = v7 - v34;
        let v36: L = v35 * v16;
        let v37: L = v33 + v36;
        [v0, v27, v30, v37, v0, v0]
    }
    /// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 6]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[L; 6]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `tau: [L; 6]`: joint torques (N m) or forces (N), no external wrench
    ///
    /// Operation count: 425 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn inverse_dynamics<L: crate::lanes::Lane>(
        q: &[L; 6],
        qd: &[L; 6],
        qdd: &[L; 6],
    ) -> [L; 6] {
        let (
            v2,
            v4,
            v5,
            v6,
            v8,
            v9,
            v12,
            v14,
            v16,
            v17,
            v21,
            v22,
            v23,
            v25,
            v26,
            v30,
            v32,
            v33,
            v35,
            v38,
            v43,
            v46,
            v48,
            v49,
            v51,
            v52,
            v56,
            v57,
            v59,
            v63,
            v64,
            v68,
            v69,
            v72,
            v74,
            v76,
            v77,
            v79,
            v84,
            v89,
            v92,
            v94,
            v95,
            v96,
            v98,
            v101,
            v103,
            v106,
            v108,
            v110,
            v113,
            v114,
            v116,
            v119,
            v121,
            v122,
            v123,
            v124,
            v126,
            v128,
            v135,
            v137,
            v140,
            v142,
            v147,
            v149,
            v150,
            v153,
            v154,
            v155,
            v156,
            v157,
        ) = {
            let v0: L = L::splat(0.00666_f64);
            let v1: L = qdd[0];
            let v2: L = v0 * v1;
            let v3: L = q[1];
            let (v6, v4): (L, L) = L::sincos(v3);
            let v5: L = L::splat(0.88490187591_f64);
            let v7: L = qd[0];
            let v8: L = v6 * v7;
            let v9: L = qd[1];
            let v10: L = v8 * v9;
            let v11: L = v4 * v1;
            let v12: L = v10 - v11;
            let v13: L = v5 * v12;
            let v14: L = v5 * v9;
            let v15: L = v8 * v14;
            let v16: L = L::splat(0.0151074_f64);
            let v17: L = v16 * v8;
            let v18: L = v9 * v17;
            let v19: L = v15 - v18;
            let v20: L = v13 + v19;
            let v21: L = L::splat(2.35004_f64);
            let v22: L = L::splat(0.13585_f64);
            let v23: L = v22 * v8;
            let v24: L = v8 * v23;
            let v25: L = v4 * v7;
            let v26: L = v22 * v25;
            let v27: L = v25 * v26;
            let v28: L = v24 + v27;
            let v29: L = v21 * v28;
            let v30: L = v20 + v29;
            let v31: L = q[2];
            let (v35, v32): (L, L) = L::sincos(v31);
            let v33: L = L::splat(0.191630813556_f64);
            let v34: L = v32 * v12;
            let v36: L = v6 * v1;
            let v37: L = v25 * v9;
            let v38: L = v36 + v37;
            let v39: L = v35 * v38;
            let v40: L = v34 + v39;
            let v41: L = v35 * v25;
            let v42: L = v32 * v8;
            let v43: L = v41 + v42;
            let v44: L = qd[2];
            let v45: L = v43 * v44;
            let v46: L = v40 + v45;
            let v47: L = v33 * v46;
            let v48: L = v9 + v44;
            let v49: L = v33 * v48;
            let v50: L = v43 * v49;
            let v51: L = L::splat(0.004095_f64);
            let v52: L = v51 * v43;
            let v53: L = v48 * v52;
            let v54: L = v50 - v53;
            let v55: L = v47 + v54;
            let v56: L = L::splat(0.56875_f64);
            let v57: L = L::splat(0.425_f64);
            let v58: L = v57 * v12;
            let v59: L = v57 * v9;
            let v60: L = v8 * v59;
            let v61: L = v58 + v60;
            let v62: L = v28 + v61;
            let v63: L = -L::splat(0.1197_f64);
            let v64: L = v63 * v43;
            let v65: L = v43 * v64;
            let v66: L = v35 * v8;
            let v67: L = v32 * v25;
            let v68: L = v66 - v67;
            let v69: L = v63 * v68;
            let v70: L = v68 * v69;
            let v71: L = v65 + v70;
            let v72: L = v62 + v71;
            let v73: L = v56 * v72;
            let v74: L = v55 + v73;
            let v75: L = q[3];
            let (v79, v76): (L, L) = L::sincos(v75);
            let v77: L = L::splat(0.21942_f64);
            let v78: L = v76 * v46;
            let v80: L = v35 * v12;
            let v81: L = v32 * v38;
            let v82: L = v80 - v81;
            let v83: L = v68 * v44;
            let v84: L = v82 + v83;
            let v85: L = v79 * v84;
            let v86: L = v78 - v85;
            let v87: L = v76 * v43;
            let v88: L = v79 * v68;
            let v89: L = v87 - v88;
            let v90: L = qd[3];
            let v91: L = v89 * v90;
            let v92: L = v86 + v91;
            let v93: L = v77 * v92;
            let v94: L = L::splat(0.111172755531_f64);
            let v95: L = v48 + v90;
            let v96: L = v94 * v95;
            let v97: L = v89 * v96;
            let v98: L = v94 * v89;
            let v99: L = v95 * v98;
            let v100: L = v97 - v99;
            let v101: L = v93 + v100;
            let v102: L = qdd[4];
            let v103: L = v92 + v102;
            let v104: L = v77 * v103;
            let v105: L = q[4];
            let (v108, v106): (L, L) = L::sincos(v105);
            let v107: L = v106 * v89;
            let v109: L = v108 * v95;
            let v110: L = v107 + v109;
            let v111: L = v106 * v95;
            let v112: L = v108 * v89;
            let v113: L = v111 - v112;
            let v114: L = v94 * v113;
            let v115: L = v110 * v114;
            let v116: L = v94 * v110;
            let v117: L = v113 * v116;
            let v118: L = v115 - v117;
            let v119: L = v104 + v118;
            let v120: L = q[5];
            let (v123, v121): (L, L) = L::sincos(v120);
            let v122: L = L::splat(0.033822_f64);
            let v124: L = qdd[1];
            let v125: L = qdd[2];
            let v126: L = v124 + v125;
            let v127: L = qdd[3];
            let v128: L = v126 + v127;
            let v129: L = v108 * v128;
            let v130: L = v79 * v46;
            let v131: L = v76 * v84;
            let v132: L = v130 + v131;
            let v133: L = v76 * v68;
            let v134: L = v79 * v43;
            let v135: L = v133 + v134;
            let v136: L = v135 * v90;
            let v137: L = v132 + v136;
            let v138: L = v106 * v137;
            let v139: L = v129 - v138;
            let v140: L = qd[4];
            let v141: L = v113 * v140;
            let v142: L = v139 + v141;
            let v143: L = v123 * v142;
            let v144: L = v121 * v103;
            let v145: L = v143 + v144;
            let v146: L = v121 * v110;
            let v147: L = v135 + v140;
            let v148: L = v123 * v147;
            let v149: L = v146 - v148;
            let v150: L = qd[5];
            let v151: L = v149 * v150;
            let v152: L = v145 + v151;
            let v153: L = v122 * v152;
            let v154: L = L::splat(0.0171364731454_f64);
            let v155: L = v113 + v150;
            let v156: L = v154 * v155;
            let v157: L = v149 * v156;
            (
                v2,
                v4,
                v5,
                v6,
                v8,
                v9,
                v12,
                v14,
                v16,
                v17,
                v21,
                v22,
                v23,
                v25,
                v26,
                v30,
                v32,
                v33,
                v35,
                v38,
                v43,
                v46,
                v48,
                v49,
                v51,
                v52,
                v56,
                v57,
                v59,
                v63,
                v64,
                v68,
                v69,
                v72,
                v74,
                v76,
                v77,
                v79,
                v84,
                v89,
                v92,
                v94,
                v95,
                v96,
                v98,
                v101,
                v103,
                v106,
                v108,
                v110,
                v113,
                v114,
                v116,
                v119,
                v121,
                v122,
                v123,
                v124,
                v126,
                v128,
                v135,
                v137,
                v140,
                v142,
                v147,
                v149,
                v150,
                v153,
                v154,
                v155,
                v156,
                v157,
            )
        };
        let (
            v158,
            v168,
            v172,
            v179,
            v181,
            v182,
            v192,
            v203,
            v213,
            v214,
            v227,
            v234,
            v240,
            v250,
            v255,
            v264,
            v268,
            v276,
            v281,
            v283,
            v284,
            v293,
            v295,
            v297,
            v299,
            v300,
            v301,
            v306,
            v308,
            v312,
            v315,
        ) = {
            let v158: L = v154 * v149;
            let v159: L = v155 * v158;
            let v160: L = v157 - v159;
            let v161: L = v153 + v160;
            let v162: L = v121 * v161;
            let v163: L = v121 * v142;
            let v164: L = v123 * v103;
            let v165: L = v163 - v164;
            let v166: L = v123 * v110;
            let v167: L = v121 * v147;
            let v168: L = v166 + v167;
            let v169: L = v168 * v150;
            let v170: L = v165 - v169;
            let v171: L = v154 * v170;
            let v172: L = v122 * v168;
            let v173: L = v155 * v172;
            let v174: L = v168 * v156;
            let v175: L = v173 - v174;
            let v176: L = v171 + v175;
            let v177: L = v123 * v176;
            let v178: L = v162 - v177;
            let v179: L = v119 + v178;
            let v180: L = v101 + v179;
            let v181: L = L::splat(0.093_f64);
            let v182: L = L::splat(1.219_f64);
            let v183: L = v181 * v89;
            let v184: L = v95 * v183;
            let v185: L = v181 * v92;
            let v186: L = v184 - v185;
            let v187: L = v22 * v38;
            let v188: L = v9 * v26;
            let v189: L = v187 - v188;
            let v190: L = L::splat(9.81_f64);
            let v191: L = v190 * v4;
            let v192: L = v189 - v191;
            let v193: L = v57 * v124;
            let v194: L = v57 * v25;
            let v195: L = v8 * v194;
            let v196: L = v193 + v195;
            let v197: L = v192 + v196;
            let v198: L = v32 * v197;
            let v199: L = v22 * v12;
            let v200: L = v9 * v23;
            let v201: L = v199 - v200;
            let v202: L = v190 * v6;
            let v203: L = v201 - v202;
            let v204: L = v25 * v194;
            let v205: L = v9 * v59;
            let v206: L = v204 + v205;
            let v207: L = v203 - v206;
            let v208: L = v35 * v207;
            let v209: L = v198 - v208;
            let v210: L = v48 * v69;
            let v211: L = v63 * v84;
            let v212: L = v210 - v211;
            let v213: L = v209 + v212;
            let v214: L = L::splat(0.39225_f64);
            let v215: L = v214 * v126;
            let v216: L = v214 * v68;
            let v217: L = v43 * v216;
            let v218: L = v215 - v217;
            let v219: L = v213 + v218;
            let v220: L = v79 * v219;
            let v221: L = v35 * v197;
            let v222: L = v32 * v207;
            let v223: L = v221 + v222;
            let v224: L = v63 * v46;
            let v225: L = v48 * v64;
            let v226: L = v224 - v225;
            let v227: L = v223 + v226;
            let v228: L = v68 * v216;
            let v229: L = v214 * v48;
            let v230: L = v48 * v229;
            let v231: L = v228 + v230;
            let v232: L = v227 - v231;
            let v233: L = v76 * v232;
            let v234: L = v220 + v233;
            let v235: L = v186 - v234;
            let v236: L = v106 * v235;
            let v237: L = v214 * v46;
            let v238: L = v43 * v229;
            let v239: L = v237 + v238;
            let v240: L = v72 + v239;
            let v241: L = v181 * v135;
            let v242: L = v135 * v241;
            let v243: L = v89 * v183;
            let v244: L = v242 + v243;
            let v245: L = v240 + v244;
            let v246: L = v108 * v245;
            let v247: L = v236 - v246;
            let v248: L = v182 * v247;
            let v249: L = L::splat(0.1879_f64);
            let v250: L = L::splat(0.09465_f64);
            let v251: L = v108 * v137;
            let v252: L = v106 * v128;
            let v253: L = v251 + v252;
            let v254: L = v110 * v140;
            let v255: L = v253 - v254;
            let v256: L = v250 * v255;
            let v257: L = v250 * v110;
            let v258: L = v147 * v257;
            let v259: L = v256 + v258;
            let v260: L = v247 + v259;
            let v261: L = v121 * v260;
            let v262: L = v76 * v219;
            let v263: L = v79 * v232;
            let v264: L = v262 - v263;
            let v265: L = v95 * v241;
            let v266: L = v181 * v137;
            let v267: L = v265 - v266;
            let v268: L = v264 + v267;
            let v269: L = v110 * v257;
            let v270: L = v250 * v113;
            let v271: L = v113 * v270;
            let v272: L = v269 + v271;
            let v273: L = v268 - v272;
            let v274: L = v123 * v273;
            let v275: L = v261 - v274;
            let v276: L = v249 * v275;
            let v277: L = v121 * v276;
            let v278: L = v123 * v260;
            let v279: L = v121 * v273;
            let v280: L = v278 + v279;
            let v281: L = v249 * v280;
            let v282: L = v123 * v281;
            let v283: L = v277 + v282;
            let v284: L = v248 + v283;
            let v285: L = v106 * v284;
            let v286: L = v147 * v270;
            let v287: L = v250 * v142;
            let v288: L = v286 - v287;
            let v289: L = v108 * v235;
            let v290: L = v106 * v245;
            let v291: L = v289 + v290;
            let v292: L = v288 - v291;
            let v293: L = v249 * v292;
            let v294: L = v182 * v291;
            let v295: L = v293 - v294;
            let v296: L = v108 * v295;
            let v297: L = v285 - v296;
            let v298: L = v181 * v297;
            let v299: L = v180 - v298;
            let v300: L = v76 * v299;
            let v301: L = v77 * v135;
            let v302: L = v95 * v301;
            let v303: L = v135 * v96;
            let v304: L = v302 - v303;
            let v305: L = v94 * v137;
            let v306: L = v304 - v305;
            let v307: L = v94 * v142;
            let v308: L = v77 * v147;
            let v309: L = v113 * v308;
            let v310: L = v147 * v114;
            let v311: L = v309 - v310;
            let v312: L = v307 + v311;
            let v313: L = v121 * v176;
            let v314: L = v123 * v161;
            let v315: L = v313 + v314;
            (
                v158,
                v168,
                v172,
                v179,
                v181,
                v182,
                v192,
                v203,
                v213,
                v214,
                v227,
                v234,
                v240,
                v250,
                v255,
                v264,
                v268,
                v276,
                v281,
                v283,
                v284,
                v293,
                v295,
                v297,
                v299,
                v300,
                v301,
                v306,
                v308,
                v312,
                v315,
            )
        };
        let (v331, v444, v467, v470, v473) = {
            let v316: L = v312 + v315;
            let v317: L = v250 * v293;
            let v318: L = v316 - v317;
            let v319: L = v106 * v318;
            let v320: L = v94 * v255;
            let v321: L = v147 * v116;
            let v322: L = v110 * v308;
            let v323: L = v321 - v322;
            let v324: L = v320 + v323;
            let v325: L = qdd[5];
            let v326: L = v255 + v325;
            let v327: L = v154 * v326;
            let v328: L = v168 * v158;
            let v329: L = v149 * v172;
            let v330: L = v328 - v329;
            let v331: L = v327 + v330;
            let v332: L = v324 + v331;
            let v333: L = v250 * v283;
            let v334: L = v332 + v333;
            let v335: L = v108 * v334;
            let v336: L = v319 - v335;
            let v337: L = v306 + v336;
            let v338: L = v182 * v268;
            let v339: L = v121 * v281;
            let v340: L = v123 * v276;
            let v341: L = v339 - v340;
            let v342: L = v338 + v341;
            let v343: L = v181 * v342;
            let v344: L = v337 + v343;
            let v345: L = v79 * v344;
            let v346: L = v300 - v345;
            let v347: L = v74 + v346;
            let v348: L = v108 * v284;
            let v349: L = v106 * v295;
            let v350: L = v348 + v349;
            let v351: L = v182 * v240;
            let v352: L = v350 - v351;
            let v353: L = v214 * v352;
            let v354: L = v347 - v353;
            let v355: L = L::splat(2.275_f64);
            let v356: L = v355 * v227;
            let v357: L = v56 * v68;
            let v358: L = v68 * v357;
            let v359: L = v56 * v48;
            let v360: L = v48 * v359;
            let v361: L = v358 + v360;
            let v362: L = v356 - v361;
            let v363: L = v182 * v234;
            let v364: L = v297 - v363;
            let v365: L = v76 * v364;
            let v366: L = v182 * v264;
            let v367: L = v366 + v342;
            let v368: L = v79 * v367;
            let v369: L = v365 + v368;
            let v370: L = v362 - v369;
            let v371: L = v63 * v370;
            let v372: L = v354 + v371;
            let v373: L = v32 * v372;
            let v374: L = v51 * v84;
            let v375: L = v68 * v49;
            let v376: L = v33 * v68;
            let v377: L = v48 * v376;
            let v378: L = v375 - v377;
            let v379: L = v374 + v378;
            let v380: L = v76 * v344;
            let v381: L = v79 * v299;
            let v382: L = v380 + v381;
            let v383: L = v379 - v382;
            let v384: L = v355 * v213;
            let v385: L = v56 * v126;
            let v386: L = v43 * v357;
            let v387: L = v385 - v386;
            let v388: L = v384 + v387;
            let v389: L = v76 * v367;
            let v390: L = v79 * v364;
            let v391: L = v389 - v390;
            let v392: L = v388 + v391;
            let v393: L = v63 * v392;
            let v394: L = v383 - v393;
            let v395: L = v35 * v394;
            let v396: L = v373 + v395;
            let v397: L = v30 + v396;
            let v398: L = v355 * v72;
            let v399: L = v56 * v46;
            let v400: L = v43 * v359;
            let v401: L = v399 + v400;
            let v402: L = v398 + v401;
            let v403: L = v352 - v402;
            let v404: L = v57 * v403;
            let v405: L = v397 - v404;
            let v406: L = L::splat(8.393_f64);
            let v407: L = v406 * v203;
            let v408: L = v21 * v25;
            let v409: L = v25 * v408;
            let v410: L = v21 * v9;
            let v411: L = v9 * v410;
            let v412: L = v409 + v411;
            let v413: L = v407 - v412;
            let v414: L = v32 * v370;
            let v415: L = v35 * v392;
            let v416: L = v414 - v415;
            let v417: L = v413 + v416;
            let v418: L = v22 * v417;
            let v419: L = v405 + v418;
            let v420: L = v4 * v419;
            let v421: L = v5 * v25;
            let v422: L = v9 * v421;
            let v423: L = v25 * v14;
            let v424: L = v422 - v423;
            let v425: L = v16 * v38;
            let v426: L = v424 - v425;
            let v427: L = v32 * v394;
            let v428: L = v35 * v372;
            let v429: L = v427 - v428;
            let v430: L = v426 + v429;
            let v431: L = v406 * v192;
            let v432: L = v21 * v124;
            let v433: L = v8 * v408;
            let v434: L = v432 + v433;
            let v435: L = v431 + v434;
            let v436: L = v32 * v392;
            let v437: L = v35 * v370;
            let v438: L = v436 + v437;
            let v439: L = v435 + v438;
            let v440: L = v22 * v439;
            let v441: L = v430 - v440;
            let v442: L = v6 * v441;
            let v443: L = v420 + v442;
            let v444: L = v2 - v443;
            let v445: L = v5 * v124;
            let v446: L = v8 * v421;
            let v447: L = v25 * v17;
            let v448: L = v446 - v447;
            let v449: L = v445 + v448;
            let v450: L = v21 * v192;
            let v451: L = v449 + v450;
            let v452: L = v33 * v126;
            let v453: L = v68 * v52;
            let v454: L = v43 * v376;
            let v455: L = v453 - v454;
            let v456: L = v452 + v455;
            let v457: L = v56 * v213;
            let v458: L = v456 + v457;
            let v459: L = v94 * v128;
            let v460: L = v135 * v98;
            let v461: L = v89 * v301;
            let v462: L = v460 - v461;
            let v463: L = v459 + v462;
            let v464: L = v108 * v318;
            let v465: L = v106 * v334;
            let v466: L = v464 + v465;
            let v467: L = v463 + v466;
            let v468: L = v458 + v467;
            let v469: L = v214 * v391;
            let v470: L = v468 + v469;
            let v471: L = v451 + v470;
            let v472: L = v57 * v438;
            let v473: L = v471 + v472;
            (v331, v444, v467, v470, v473)
        };
        [v444, v473, v470, v467, v179, v331]
    }
    /// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 6]`: joint velocities qd (rad/s or m/s)
    /// - `tau: &[L; 6]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
    ///
    /// # Output
    ///
    /// `qdd: [L; 6]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// Operation count: 751 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn forward_dynamics<L: crate::lanes::Lane>(
        q: &[L; 6],
        qd: &[L; 6],
        tau: &[L; 6],
    ) -> [L; 6] {
        let (
            v0,
            v2,
            v3,
            v4,
            v6,
            v7,
            v8,
            v10,
            v12,
            v13,
            v17,
            v18,
            v19,
            v21,
            v22,
            v26,
            v28,
            v29,
            v31,
            v32,
            v37,
            v40,
            v42,
            v43,
            v45,
            v46,
            v50,
            v51,
            v53,
            v57,
            v58,
            v62,
            v63,
            v66,
            v68,
            v70,
            v71,
            v73,
            v78,
            v83,
            v86,
            v88,
            v89,
            v90,
            v92,
            v95,
            v97,
            v99,
            v101,
            v104,
            v105,
            v107,
            v112,
            v113,
            v114,
            v115,
            v122,
            v124,
            v126,
            v131,
            v133,
            v138,
            v142,
            v145,
            v152,
            v156,
            v160,
            v163,
        ) = {
            let v0: L = tau[0];
            let v1: L = q[1];
            let (v4, v2): (L, L) = L::sincos(v1);
            let v3: L = L::splat(0.88490187591_f64);
            let v5: L = qd[0];
            let v6: L = v4 * v5;
            let v7: L = qd[1];
            let v8: L = v6 * v7;
            let v9: L = v3 * v8;
            let v10: L = v3 * v7;
            let v11: L = v6 * v10;
            let v12: L = L::splat(0.0151074_f64);
            let v13: L = v12 * v6;
            let v14: L = v7 * v13;
            let v15: L = v11 - v14;
            let v16: L = v9 + v15;
            let v17: L = L::splat(2.35004_f64);
            let v18: L = L::splat(0.13585_f64);
            let v19: L = v18 * v6;
            let v20: L = v6 * v19;
            let v21: L = v2 * v5;
            let v22: L = v18 * v21;
            let v23: L = v21 * v22;
            let v24: L = v20 + v23;
            let v25: L = v17 * v24;
            let v26: L = v16 + v25;
            let v27: L = q[2];
            let (v31, v28): (L, L) = L::sincos(v27);
            let v29: L = L::splat(0.191630813556_f64);
            let v30: L = v28 * v8;
            let v32: L = v21 * v7;
            let v33: L = v31 * v32;
            let v34: L = v30 + v33;
            let v35: L = v31 * v21;
            let v36: L = v28 * v6;
            let v37: L = v35 + v36;
            let v38: L = qd[2];
            let v39: L = v37 * v38;
            let v40: L = v34 + v39;
            let v41: L = v29 * v40;
            let v42: L = v7 + v38;
            let v43: L = v29 * v42;
            let v44: L = v37 * v43;
            let v45: L = L::splat(0.004095_f64);
            let v46: L = v45 * v37;
            let v47: L = v42 * v46;
            let v48: L = v44 - v47;
            let v49: L = v41 + v48;
            let v50: L = L::splat(0.56875_f64);
            let v51: L = L::splat(0.425_f64);
            let v52: L = v51 * v8;
            let v53: L = v51 * v7;
            let v54: L = v6 * v53;
            let v55: L = v52 + v54;
            let v56: L = v24 + v55;
            let v57: L = -L::splat(0.1197_f64);
            let v58: L = v57 * v37;
            let v59: L = v37 * v58;
            let v60: L = v31 * v6;
            let v61: L = v28 * v21;
            let v62: L = v60 - v61;
            let v63: L = v57 * v62;
            let v64: L = v62 * v63;
            let v65: L = v59 + v64;
            let v66: L = v56 + v65;
            let v67: L = v50 * v66;
            let v68: L = v49 + v67;
            let v69: L = q[3];
            let (v73, v70): (L, L) = L::sincos(v69);
            let v71: L = L::splat(0.21942_f64);
            let v72: L = v70 * v40;
            let v74: L = v31 * v8;
            let v75: L = v28 * v32;
            let v76: L = v74 - v75;
            let v77: L = v62 * v38;
            let v78: L = v76 + v77;
            let v79: L = v73 * v78;
            let v80: L = v72 - v79;
            let v81: L = v70 * v37;
            let v82: L = v73 * v62;
            let v83: L = v81 - v82;
            let v84: L = qd[3];
            let v85: L = v83 * v84;
            let v86: L = v80 + v85;
            let v87: L = v71 * v86;
            let v88: L = L::splat(0.111172755531_f64);
            let v89: L = v42 + v84;
            let v90: L = v88 * v89;
            let v91: L = v83 * v90;
            let v92: L = v88 * v83;
            let v93: L = v89 * v92;
            let v94: L = v91 - v93;
            let v95: L = v87 + v94;
            let v96: L = q[4];
            let (v99, v97): (L, L) = L::sincos(v96);
            let v98: L = v97 * v83;
            let v100: L = v99 * v89;
            let v101: L = v98 + v100;
            let v102: L = v97 * v89;
            let v103: L = v99 * v83;
            let v104: L = v102 - v103;
            let v105: L = v88 * v104;
            let v106: L = v101 * v105;
            let v107: L = v88 * v101;
            let v108: L = v104 * v107;
            let v109: L = v106 - v108;
            let v110: L = v87 + v109;
            let v111: L = q[5];
            let (v114, v112): (L, L) = L::sincos(v111);
            let v113: L = L::splat(0.033822_f64);
            let v115: L = qd[4];
            let v116: L = v104 * v115;
            let v117: L = v73 * v40;
            let v118: L = v70 * v78;
            let v119: L = v117 + v118;
            let v120: L = v70 * v62;
            let v121: L = v73 * v37;
            let v122: L = v120 + v121;
            let v123: L = v122 * v84;
            let v124: L = v119 + v123;
            let v125: L = v97 * v124;
            let v126: L = v116 - v125;
            let v127: L = v114 * v126;
            let v128: L = v112 * v86;
            let v129: L = v127 + v128;
            let v130: L = v112 * v101;
            let v131: L = v122 + v115;
            let v132: L = v114 * v131;
            let v133: L = v130 - v132;
            let v134: L = qd[5];
            let v135: L = v133 * v134;
            let v136: L = v129 + v135;
            let v137: L = v113 * v136;
            let v138: L = L::splat(0.0171364731454_f64);
            let v139: L = v104 + v134;
            let v140: L = v138 * v139;
            let v141: L = v133 * v140;
            let v142: L = v138 * v133;
            let v143: L = v139 * v142;
            let v144: L = v141 - v143;
            let v145: L = v137 + v144;
            let v146: L = v112 * v145;
            let v147: L = v112 * v126;
            let v148: L = v114 * v86;
            let v149: L = v147 - v148;
            let v150: L = v114 * v101;
            let v151: L = v112 * v131;
            let v152: L = v150 + v151;
            let v153: L = v152 * v134;
            let v154: L = v149 - v153;
            let v155: L = v138 * v154;
            let v156: L = v113 * v152;
            let v157: L = v139 * v156;
            let v158: L = v152 * v140;
            let v159: L = v157 - v158;
            let v160: L = v155 + v159;
            let v161: L = v114 * v160;
            let v162: L = v146 - v161;
            let v163: L = v110 + v162;
            (
                v0,
                v2,
                v3,
                v4,
                v6,
                v7,
                v8,
                v10,
                v12,
                v13,
                v17,
                v18,
                v19,
                v21,
                v22,
                v26,
                v28,
                v29,
                v31,
                v32,
                v37,
                v40,
                v42,
                v43,
                v45,
                v46,
                v50,
                v51,
                v53,
                v57,
                v58,
                v62,
                v63,
                v66,
                v68,
                v70,
                v71,
                v73,
                v78,
                v83,
                v86,
                v88,
                v89,
                v90,
                v92,
                v95,
                v97,
                v99,
                v101,
                v104,
                v105,
                v107,
                v112,
                v113,
                v114,
                v115,
                v122,
                v124,
                v126,
                v131,
                v133,
                v138,
                v142,
                v145,
                v152,
                v156,
                v160,
                v163,
            )
        };
        let (
            v166,
            v176,
            v185,
            v195,
            v196,
            v207,
            v214,
            v242,
            v275,
            v277,
            v279,
            v296,
            v307,
            v310,
            v318,
            v320,
            v323,
            v326,
            v327,
        ) = {
            let v164: L = v95 + v163;
            let v165: L = L::splat(0.093_f64);
            let v166: L = L::splat(1.219_f64);
            let v167: L = v165 * v83;
            let v168: L = v89 * v167;
            let v169: L = v165 * v86;
            let v170: L = v168 - v169;
            let v171: L = v18 * v32;
            let v172: L = v7 * v22;
            let v173: L = v171 - v172;
            let v174: L = L::splat(9.81_f64);
            let v175: L = v174 * v2;
            let v176: L = v173 - v175;
            let v177: L = v51 * v21;
            let v178: L = v6 * v177;
            let v179: L = v176 + v178;
            let v180: L = v28 * v179;
            let v181: L = v18 * v8;
            let v182: L = v7 * v19;
            let v183: L = v181 - v182;
            let v184: L = v174 * v4;
            let v185: L = v183 - v184;
            let v186: L = v21 * v177;
            let v187: L = v7 * v53;
            let v188: L = v186 + v187;
            let v189: L = v185 - v188;
            let v190: L = v31 * v189;
            let v191: L = v180 - v190;
            let v192: L = v42 * v63;
            let v193: L = v57 * v78;
            let v194: L = v192 - v193;
            let v195: L = v191 + v194;
            let v196: L = L::splat(0.39225_f64);
            let v197: L = v196 * v62;
            let v198: L = v37 * v197;
            let v199: L = v195 - v198;
            let v200: L = v73 * v199;
            let v201: L = v31 * v179;
            let v202: L = v28 * v189;
            let v203: L = v201 + v202;
            let v204: L = v57 * v40;
            let v205: L = v42 * v58;
            let v206: L = v204 - v205;
            let v207: L = v203 + v206;
            let v208: L = v62 * v197;
            let v209: L = v196 * v42;
            let v210: L = v42 * v209;
            let v211: L = v208 + v210;
            let v212: L = v207 - v211;
            let v213: L = v70 * v212;
            let v214: L = v200 + v213;
            let v215: L = v170 - v214;
            let v216: L = v97 * v215;
            let v217: L = v196 * v40;
            let v218: L = v37 * v209;
            let v219: L = v217 + v218;
            let v220: L = v66 + v219;
            let v221: L = v165 * v122;
            let v222: L = v122 * v221;
            let v223: L = v83 * v167;
            let v224: L = v222 + v223;
            let v225: L = v220 + v224;
            let v226: L = v99 * v225;
            let v227: L = v216 - v226;
            let v228: L = v166 * v227;
            let v229: L = L::splat(0.1879_f64);
            let v230: L = L::splat(0.09465_f64);
            let v231: L = v99 * v124;
            let v232: L = v101 * v115;
            let v233: L = v231 - v232;
            let v234: L = v230 * v233;
            let v235: L = v230 * v101;
            let v236: L = v131 * v235;
            let v237: L = v234 + v236;
            let v238: L = v227 + v237;
            let v239: L = v112 * v238;
            let v240: L = v70 * v199;
            let v241: L = v73 * v212;
            let v242: L = v240 - v241;
            let v243: L = v89 * v221;
            let v244: L = v165 * v124;
            let v245: L = v243 - v244;
            let v246: L = v242 + v245;
            let v247: L = v101 * v235;
            let v248: L = v230 * v104;
            let v249: L = v104 * v248;
            let v250: L = v247 + v249;
            let v251: L = v246 - v250;
            let v252: L = v114 * v251;
            let v253: L = v239 - v252;
            let v254: L = v229 * v253;
            let v255: L = v112 * v254;
            let v256: L = v114 * v238;
            let v257: L = v112 * v251;
            let v258: L = v256 + v257;
            let v259: L = v229 * v258;
            let v260: L = v114 * v259;
            let v261: L = v255 + v260;
            let v262: L = v228 + v261;
            let v263: L = v97 * v262;
            let v264: L = v131 * v248;
            let v265: L = v230 * v126;
            let v266: L = v264 - v265;
            let v267: L = v99 * v215;
            let v268: L = v97 * v225;
            let v269: L = v267 + v268;
            let v270: L = v266 - v269;
            let v271: L = v229 * v270;
            let v272: L = v166 * v269;
            let v273: L = v271 - v272;
            let v274: L = v99 * v273;
            let v275: L = v263 - v274;
            let v276: L = v165 * v275;
            let v277: L = v164 - v276;
            let v278: L = v70 * v277;
            let v279: L = v71 * v122;
            let v280: L = v89 * v279;
            let v281: L = v122 * v90;
            let v282: L = v280 - v281;
            let v283: L = v88 * v124;
            let v284: L = v282 - v283;
            let v285: L = v88 * v126;
            let v286: L = v71 * v131;
            let v287: L = v104 * v286;
            let v288: L = v131 * v105;
            let v289: L = v287 - v288;
            let v290: L = v285 + v289;
            let v291: L = v112 * v160;
            let v292: L = v114 * v145;
            let v293: L = v291 + v292;
            let v294: L = v290 + v293;
            let v295: L = v230 * v271;
            let v296: L = v294 - v295;
            let v297: L = v97 * v296;
            let v298: L = v88 * v233;
            let v299: L = v131 * v107;
            let v300: L = v101 * v286;
            let v301: L = v299 - v300;
            let v302: L = v298 + v301;
            let v303: L = v138 * v233;
            let v304: L = v152 * v142;
            let v305: L = v133 * v156;
            let v306: L = v304 - v305;
            let v307: L = v303 + v306;
            let v308: L = v302 + v307;
            let v309: L = v230 * v261;
            let v310: L = v308 + v309;
            let v311: L = v99 * v310;
            let v312: L = v297 - v311;
            let v313: L = v284 + v312;
            let v314: L = v166 * v246;
            let v315: L = v112 * v259;
            let v316: L = v114 * v254;
            let v317: L = v315 - v316;
            let v318: L = v314 + v317;
            let v319: L = v165 * v318;
            let v320: L = v313 + v319;
            let v321: L = v73 * v320;
            let v322: L = v278 - v321;
            let v323: L = v68 + v322;
            let v324: L = v99 * v262;
            let v325: L = v97 * v273;
            let v326: L = v324 + v325;
            let v327: L = v166 * v220;
            (
                v166,
                v176,
                v185,
                v195,
                v196,
                v207,
                v214,
                v242,
                v275,
                v277,
                v279,
                v296,
                v307,
                v310,
                v318,
                v320,
                v323,
                v326,
                v327,
            )
        };
        let (
            v352,
            v365,
            v395,
            v410,
            v417,
            v429,
            v430,
            v432,
            v440,
            v446,
            v448,
            v451,
            v461,
            v462,
            v464,
            v466,
            v467,
            v470,
            v480,
            v481,
            v483,
            v484,
            v488,
            v489,
            v490,
            v491,
        ) = {
            let v328: L = v326 - v327;
            let v329: L = v196 * v328;
            let v330: L = v323 - v329;
            let v331: L = L::splat(2.275_f64);
            let v332: L = v331 * v207;
            let v333: L = v50 * v62;
            let v334: L = v62 * v333;
            let v335: L = v50 * v42;
            let v336: L = v42 * v335;
            let v337: L = v334 + v336;
            let v338: L = v332 - v337;
            let v339: L = v166 * v214;
            let v340: L = v275 - v339;
            let v341: L = v70 * v340;
            let v342: L = v166 * v242;
            let v343: L = v342 + v318;
            let v344: L = v73 * v343;
            let v345: L = v341 + v344;
            let v346: L = v338 - v345;
            let v347: L = v57 * v346;
            let v348: L = v330 + v347;
            let v349: L = v28 * v348;
            let v350: L = v45 * v78;
            let v351: L = v62 * v43;
            let v352: L = v29 * v62;
            let v353: L = v42 * v352;
            let v354: L = v351 - v353;
            let v355: L = v350 + v354;
            let v356: L = v70 * v320;
            let v357: L = v73 * v277;
            let v358: L = v356 + v357;
            let v359: L = v355 - v358;
            let v360: L = v331 * v195;
            let v361: L = v37 * v333;
            let v362: L = v360 - v361;
            let v363: L = v70 * v343;
            let v364: L = v73 * v340;
            let v365: L = v363 - v364;
            let v366: L = v362 + v365;
            let v367: L = v57 * v366;
            let v368: L = v359 - v367;
            let v369: L = v31 * v368;
            let v370: L = v349 + v369;
            let v371: L = v26 + v370;
            let v372: L = v331 * v66;
            let v373: L = v50 * v40;
            let v374: L = v37 * v335;
            let v375: L = v373 + v374;
            let v376: L = v372 + v375;
            let v377: L = v328 - v376;
            let v378: L = v51 * v377;
            let v379: L = v371 - v378;
            let v380: L = L::splat(8.393_f64);
            let v381: L = v380 * v185;
            let v382: L = v17 * v21;
            let v383: L = v21 * v382;
            let v384: L = v17 * v7;
            let v385: L = v7 * v384;
            let v386: L = v383 + v385;
            let v387: L = v381 - v386;
            let v388: L = v28 * v346;
            let v389: L = v31 * v366;
            let v390: L = v388 - v389;
            let v391: L = v387 + v390;
            let v392: L = v18 * v391;
            let v393: L = v379 + v392;
            let v394: L = v2 * v393;
            let v395: L = v3 * v21;
            let v396: L = v7 * v395;
            let v397: L = v21 * v10;
            let v398: L = v396 - v397;
            let v399: L = v12 * v32;
            let v400: L = v398 - v399;
            let v401: L = v28 * v368;
            let v402: L = v31 * v348;
            let v403: L = v401 - v402;
            let v404: L = v400 + v403;
            let v405: L = v380 * v176;
            let v406: L = v6 * v382;
            let v407: L = v405 + v406;
            let v408: L = v28 * v366;
            let v409: L = v31 * v346;
            let v410: L = v408 + v409;
            let v411: L = v407 + v410;
            let v412: L = v18 * v411;
            let v413: L = v404 - v412;
            let v414: L = v4 * v413;
            let v415: L = v394 + v414;
            let v416: L = v0 + v415;
            let v417: L = L::splat(58.355064750790525_f64);
            let v418: L = v138 * v99;
            let v419: L = v73 * v418;
            let v420: L = v28 * v419;
            let v421: L = v70 * v418;
            let v422: L = v31 * v421;
            let v423: L = v420 + v422;
            let v424: L = v2 * v423;
            let v425: L = v28 * v421;
            let v426: L = v31 * v419;
            let v427: L = v425 - v426;
            let v428: L = v4 * v427;
            let v429: L = v424 + v428;
            let v430: L = v417 * v429;
            let v431: L = tau[5];
            let v432: L = v431 - v307;
            let v433: L = v430 * v432;
            let v434: L = v416 + v433;
            let v435: L = v138 * v114;
            let v436: L = v435 * v114;
            let v437: L = v113 * v112;
            let v438: L = v437 * v112;
            let v439: L = v436 + v438;
            let v440: L = v71 + v439;
            let v441: L = v70 * v440;
            let v442: L = v113 * v114;
            let v443: L = v442 * v112;
            let v444: L = v138 * v112;
            let v445: L = v444 * v114;
            let v446: L = v443 - v445;
            let v447: L = v97 * v446;
            let v448: L = v73 * v447;
            let v449: L = v441 - v448;
            let v450: L = v31 * v449;
            let v451: L = v70 * v447;
            let v452: L = v73 * v440;
            let v453: L = v451 + v452;
            let v454: L = v28 * v453;
            let v455: L = v450 + v454;
            let v456: L = v4 * v455;
            let v457: L = v28 * v449;
            let v458: L = v31 * v453;
            let v459: L = v457 - v458;
            let v460: L = v2 * v459;
            let v461: L = v456 - v460;
            let v462: L = v461 / v440;
            let v463: L = tau[4];
            let v464: L = v463 - v163;
            let v465: L = v462 * v464;
            let v466: L = v434 - v465;
            let v467: L = v429 * v97;
            let v468: L = v437 * v114;
            let v469: L = v435 * v112;
            let v470: L = v468 - v469;
            let v471: L = v470 * v99;
            let v472: L = L::splat(0.0016539803549999999_f64);
            let v473: L = v471 - v472;
            let v474: L = v70 * v473;
            let v475: L = v444 * v112;
            let v476: L = v442 * v114;
            let v477: L = v475 + v476;
            let v478: L = L::splat(0.00168332516775_f64);
            let v479: L = v477 + v478;
            let v480: L = v88 + v479;
            let v481: L = v97 * v480;
            let v482: L = v481 * v99;
            let v483: L = L::splat(0.12999255384415_f64);
            let v484: L = v483 * v99;
            let v485: L = v484 * v97;
            let v486: L = v482 - v485;
            let v487: L = v73 * v486;
            let v488: L = v474 - v487;
            let v489: L = v28 * v488;
            let v490: L = v70 * v486;
            let v491: L = v73 * v473;
            (
                v352,
                v365,
                v395,
                v410,
                v417,
                v429,
                v430,
                v432,
                v440,
                v446,
                v448,
                v451,
                v461,
                v462,
                v464,
                v466,
                v467,
                v470,
                v480,
                v481,
                v483,
                v484,
                v488,
                v489,
                v490,
                v491,
            )
        };
        let (
            v498,
            v521,
            v523,
            v531,
            v533,
            v534,
            v535,
            v545,
            v547,
            v548,
            v578,
            v582,
            v584,
            v585,
            v588,
            v594,
            v595,
            v604,
            v609,
            v611,
            v618,
            v636,
            v637,
            v640,
            v645,
            v646,
            v648,
            v650,
            v653,
            v654,
            v655,
        ) = {
            let v492: L = v490 + v491;
            let v493: L = v31 * v492;
            let v494: L = v489 - v493;
            let v495: L = L::splat(0.017784735_f64);
            let v496: L = v495 * v73;
            let v497: L = v31 * v496;
            let v498: L = v495 * v70;
            let v499: L = v28 * v498;
            let v500: L = v497 - v499;
            let v501: L = v57 * v500;
            let v502: L = v494 + v501;
            let v503: L = v2 * v502;
            let v504: L = v28 * v496;
            let v505: L = v31 * v498;
            let v506: L = v504 + v505;
            let v507: L = v57 * v506;
            let v508: L = v31 * v488;
            let v509: L = v28 * v492;
            let v510: L = v508 + v509;
            let v511: L = v507 - v510;
            let v512: L = v4 * v511;
            let v513: L = v503 + v512;
            let v514: L = v4 * v506;
            let v515: L = v2 * v500;
            let v516: L = v514 + v515;
            let v517: L = v18 * v516;
            let v518: L = v513 + v517;
            let v519: L = v467 - v518;
            let v520: L = v99 * v446;
            let v521: L = v520 / v440;
            let v522: L = v461 * v521;
            let v523: L = v519 - v522;
            let v524: L = v99 * v480;
            let v525: L = v524 * v99;
            let v526: L = v483 * v97;
            let v527: L = v526 * v97;
            let v528: L = v525 + v527;
            let v529: L = v88 + v528;
            let v530: L = v138 * v97;
            let v531: L = v530 * v97;
            let v532: L = v529 - v531;
            let v533: L = v520 * v521;
            let v534: L = v532 - v533;
            let v535: L = v523 / v534;
            let v536: L = tau[3];
            let v537: L = v122 * v92;
            let v538: L = v83 * v279;
            let v539: L = v537 - v538;
            let v540: L = v99 * v296;
            let v541: L = v97 * v310;
            let v542: L = v540 + v541;
            let v543: L = v539 + v542;
            let v544: L = v536 - v543;
            let v545: L = v97 * v432;
            let v546: L = v544 - v545;
            let v547: L = v521 * v464;
            let v548: L = v546 - v547;
            let v549: L = v535 * v548;
            let v550: L = v466 - v549;
            let v551: L = L::splat(0.051322656825_f64);
            let v552: L = v492 + v551;
            let v553: L = v28 * v552;
            let v554: L = v508 + v553;
            let v555: L = L::splat(1.030009275_f64);
            let v556: L = v555 - v496;
            let v557: L = v50 + v556;
            let v558: L = v28 * v557;
            let v559: L = v558 - v505;
            let v560: L = v57 * v559;
            let v561: L = v554 + v560;
            let v562: L = v4 * v561;
            let v563: L = v31 * v552;
            let v564: L = v489 - v563;
            let v565: L = v31 * v557;
            let v566: L = v565 + v499;
            let v567: L = v57 * v566;
            let v568: L = v564 - v567;
            let v569: L = v2 * v568;
            let v570: L = v562 - v569;
            let v571: L = v4 * v559;
            let v572: L = v2 * v566;
            let v573: L = v571 + v572;
            let v574: L = v18 * v573;
            let v575: L = v570 + v574;
            let v576: L = v575 + v467;
            let v577: L = v576 - v522;
            let v578: L = v196 * v496;
            let v579: L = v529 - v578;
            let v580: L = v579 - v531;
            let v581: L = v580 - v533;
            let v582: L = v581 / v534;
            let v583: L = v523 * v582;
            let v584: L = v577 - v583;
            let v585: L = L::splat(0.40402113811874996_f64);
            let v586: L = L::splat(2.0_f64);
            let v587: L = v586 * v578;
            let v588: L = v585 - v587;
            let v589: L = v529 + v588;
            let v590: L = v29 + v589;
            let v591: L = v590 - v531;
            let v592: L = v591 - v533;
            let v593: L = v581 * v582;
            let v594: L = v592 - v593;
            let v595: L = v584 / v594;
            let v596: L = tau[2];
            let v597: L = v62 * v46;
            let v598: L = v37 * v352;
            let v599: L = v597 - v598;
            let v600: L = v50 * v195;
            let v601: L = v599 + v600;
            let v602: L = v601 + v543;
            let v603: L = v196 * v365;
            let v604: L = v602 + v603;
            let v605: L = v596 - v604;
            let v606: L = v605 - v545;
            let v607: L = v606 - v547;
            let v608: L = v582 * v548;
            let v609: L = v607 - v608;
            let v610: L = v595 * v609;
            let v611: L = v550 - v610;
            let v612: L = -L::splat(0.24932103525000002_f64);
            let v613: L = v554 + v612;
            let v614: L = v613 + v560;
            let v615: L = L::splat(0.0556077225_f64);
            let v616: L = v614 + v615;
            let v617: L = v4 * v616;
            let v618: L = v499 + v565;
            let v619: L = v57 * v618;
            let v620: L = v564 - v619;
            let v621: L = v2 * v620;
            let v622: L = v617 - v621;
            let v623: L = L::splat(2.0828824999999997_f64);
            let v624: L = v559 + v623;
            let v625: L = v17 + v624;
            let v626: L = v4 * v625;
            let v627: L = v2 * v618;
            let v628: L = v626 + v627;
            let v629: L = v18 * v628;
            let v630: L = v622 + v629;
            let v631: L = v630 + v467;
            let v632: L = v631 - v522;
            let v633: L = v51 * v506;
            let v634: L = v579 - v633;
            let v635: L = v634 - v531;
            let v636: L = v635 - v533;
            let v637: L = v636 / v534;
            let v638: L = v523 * v637;
            let v639: L = v632 - v638;
            let v640: L = v51 * v559;
            let v641: L = v590 + v640;
            let v642: L = v641 - v531;
            let v643: L = v642 - v533;
            let v644: L = v636 * v582;
            let v645: L = v643 - v644;
            let v646: L = v645 / v594;
            let v647: L = v584 * v646;
            let v648: L = v639 - v647;
            let v649: L = L::splat(0.9554455987809999_f64);
            let v650: L = -L::splat(0.01566175149_f64);
            let v651: L = v650 + v640;
            let v652: L = v586 * v651;
            let v653: L = v649 + v652;
            let v654: L = v590 + v653;
            let v655: L = L::splat(0.070220536281_f64);
            (
                v498,
                v521,
                v523,
                v531,
                v533,
                v534,
                v535,
                v545,
                v547,
                v548,
                v578,
                v582,
                v584,
                v585,
                v588,
                v594,
                v595,
                v604,
                v609,
                v611,
                v618,
                v636,
                v637,
                v640,
                v645,
                v646,
                v648,
                v650,
                v653,
                v654,
                v655,
            )
        };
        let (v784, v787, v792, v799, v808, v817) = {
            let v656: L = v654 - v655;
            let v657: L = v656 - v650;
            let v658: L = v657 - v650;
            let v659: L = v3 + v658;
            let v660: L = v659 - v531;
            let v661: L = v660 - v533;
            let v662: L = v636 * v637;
            let v663: L = v661 - v662;
            let v664: L = v645 * v646;
            let v665: L = v663 - v664;
            let v666: L = v648 / v665;
            let v667: L = tau[1];
            let v668: L = v6 * v395;
            let v669: L = v21 * v13;
            let v670: L = v668 - v669;
            let v671: L = v17 * v176;
            let v672: L = v670 + v671;
            let v673: L = v672 + v604;
            let v674: L = v51 * v410;
            let v675: L = v673 + v674;
            let v676: L = v667 - v675;
            let v677: L = v676 - v545;
            let v678: L = v677 - v547;
            let v679: L = v637 * v548;
            let v680: L = v678 - v679;
            let v681: L = v646 * v609;
            let v682: L = v680 - v681;
            let v683: L = v666 * v682;
            let v684: L = v611 - v683;
            let v685: L = L::splat(0.00666_f64);
            let v686: L = L::splat(0.0121682781_f64);
            let v687: L = v440 + v686;
            let v688: L = v71 + v687;
            let v689: L = v70 * v688;
            let v690: L = v689 - v448;
            let v691: L = v690 * v70;
            let v692: L = v470 * v97;
            let v693: L = v70 * v692;
            let v694: L = v481 * v97;
            let v695: L = v484 * v99;
            let v696: L = v694 + v695;
            let v697: L = v696 + v686;
            let v698: L = v88 + v697;
            let v699: L = v73 * v698;
            let v700: L = v693 - v699;
            let v701: L = v700 * v73;
            let v702: L = v691 - v701;
            let v703: L = v702 + v588;
            let v704: L = v29 + v703;
            let v705: L = v28 * v704;
            let v706: L = v70 * v698;
            let v707: L = v73 * v692;
            let v708: L = v706 + v707;
            let v709: L = v708 * v73;
            let v710: L = v73 * v688;
            let v711: L = v451 + v710;
            let v712: L = v711 * v70;
            let v713: L = v709 - v712;
            let v714: L = v196 * v498;
            let v715: L = v713 - v714;
            let v716: L = v31 * v715;
            let v717: L = v705 + v716;
            let v718: L = v717 * v28;
            let v719: L = v708 * v70;
            let v720: L = v711 * v73;
            let v721: L = v719 + v720;
            let v722: L = v721 + v588;
            let v723: L = v722 - v585;
            let v724: L = v723 + v578;
            let v725: L = v724 + v578;
            let v726: L = v45 + v725;
            let v727: L = v31 * v726;
            let v728: L = v700 * v70;
            let v729: L = v690 * v73;
            let v730: L = v728 + v729;
            let v731: L = v730 + v714;
            let v732: L = v28 * v731;
            let v733: L = v727 - v732;
            let v734: L = v733 * v31;
            let v735: L = v718 + v734;
            let v736: L = v735 + v653;
            let v737: L = v3 + v736;
            let v738: L = v2 * v737;
            let v739: L = v28 * v715;
            let v740: L = v31 * v704;
            let v741: L = v739 - v740;
            let v742: L = v741 * v28;
            let v743: L = v31 * v731;
            let v744: L = v28 * v726;
            let v745: L = v743 + v744;
            let v746: L = v745 * v31;
            let v747: L = v742 + v746;
            let v748: L = v51 * v618;
            let v749: L = v747 - v748;
            let v750: L = v4 * v749;
            let v751: L = v738 + v750;
            let v752: L = v751 * v2;
            let v753: L = v733 * v28;
            let v754: L = v717 * v31;
            let v755: L = v753 - v754;
            let v756: L = v755 - v748;
            let v757: L = v2 * v756;
            let v758: L = v745 * v28;
            let v759: L = v741 * v31;
            let v760: L = v758 - v759;
            let v761: L = v760 + v653;
            let v762: L = L::splat(0.8852250624999999_f64);
            let v763: L = v761 - v762;
            let v764: L = v763 - v640;
            let v765: L = v764 - v640;
            let v766: L = v12 + v765;
            let v767: L = v4 * v766;
            let v768: L = v757 + v767;
            let v769: L = v768 * v4;
            let v770: L = v752 + v769;
            let v771: L = L::splat(0.12150210104175002_f64);
            let v772: L = v770 + v771;
            let v773: L = v685 + v772;
            let v774: L = v429 * v430;
            let v775: L = v773 - v774;
            let v776: L = v461 * v462;
            let v777: L = v775 - v776;
            let v778: L = v523 * v535;
            let v779: L = v777 - v778;
            let v780: L = v584 * v595;
            let v781: L = v779 - v780;
            let v782: L = v648 * v666;
            let v783: L = v781 - v782;
            let v784: L = v684 / v783;
            let v785: L = v682 / v665;
            let v786: L = v666 * v784;
            let v787: L = v785 - v786;
            let v788: L = v609 / v594;
            let v789: L = v595 * v784;
            let v790: L = v788 - v789;
            let v791: L = v646 * v787;
            let v792: L = v790 - v791;
            let v793: L = v548 / v534;
            let v794: L = v535 * v784;
            let v795: L = v793 - v794;
            let v796: L = v637 * v787;
            let v797: L = v795 - v796;
            let v798: L = v582 * v792;
            let v799: L = v797 - v798;
            let v800: L = v464 / v440;
            let v801: L = v462 * v784;
            let v802: L = v800 - v801;
            let v803: L = v521 * v787;
            let v804: L = v802 - v803;
            let v805: L = v521 * v792;
            let v806: L = v804 - v805;
            let v807: L = v521 * v799;
            let v808: L = v806 - v807;
            let v809: L = v417 * v432;
            let v810: L = v430 * v784;
            let v811: L = v809 + v810;
            let v812: L = v97 * v787;
            let v813: L = v811 - v812;
            let v814: L = v97 * v792;
            let v815: L = v813 - v814;
            let v816: L = v97 * v799;
            let v817: L = v815 - v816;
            (v784, v787, v792, v799, v808, v817)
        };
        [v784, v787, v792, v799, v808, v817]
    }
    /// Mass matrix and bias in one pass: row i is `[M_i0, ..., M_i(n-1), c_i + g_i]`, the `M(q)` of `mass_matrix` with the bias `c(q, qd) + g(q)` of `coriolis` and `gravity` as a last column (what Pinocchio's `crba` and `nonLinearEffects` compute together). Common subexpressions, sin/cos included, are computed once for both.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 6]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `mass_matrix_and_bias: [[L; 7]; 6]` (6 x 7, row-major): rows `[M(q) | c(q, qd) + g(q)]`: the symmetric positive definite M (kg m^2, kg m, kg), then the bias (N m or N)
    ///
    /// Operation count: 635 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn mass_matrix_and_bias<L: crate::lanes::Lane>(
        q: &[L; 6],
        qd: &[L; 6],
    ) -> [[L; 7]; 6] {
        let (
            v2,
            v3,
            v5,
            v6,
            v8,
            v9,
            v10,
            v12,
            v15,
            v16,
            v20,
            v25,
            v27,
            v32,
            v34,
            v42,
            v48,
            v51,
            v52,
            v64,
            v66,
            v67,
            v69,
            v73,
            v78,
            v89,
            v108,
            v109,
            v110,
            v115,
            v116,
            v117,
            v120,
            v124,
            v134,
            v135,
            v136,
            v147,
            v163,
            v166,
            v170,
            v172,
            v173,
        ) = {
            let v0: L = L::splat(0.00666_f64);
            let v1: L = q[1];
            let (v124, v2): (L, L) = L::sincos(v1);
            let v3: L = L::splat(0.88490187591_f64);
            let v4: L = q[2];
            let (v73, v5): (L, L) = L::sincos(v4);
            let v6: L = L::splat(0.191630813556_f64);
            let v7: L = q[3];
            let (v25, v8): (L, L) = L::sincos(v7);
            let v9: L = L::splat(0.21942_f64);
            let v10: L = L::splat(0.0171364731454_f64);
            let v11: L = q[5];
            let (v12, v16): (L, L) = L::sincos(v11);
            let v13: L = v10 * v12;
            let v14: L = v13 * v12;
            let v15: L = L::splat(0.033822_f64);
            let v17: L = v15 * v16;
            let v18: L = v17 * v16;
            let v19: L = v14 + v18;
            let v20: L = v9 + v19;
            let v21: L = L::splat(0.0121682781_f64);
            let v22: L = v20 + v21;
            let v23: L = v9 + v22;
            let v24: L = v8 * v23;
            let v26: L = q[4];
            let (v52, v27): (L, L) = L::sincos(v26);
            let v28: L = v15 * v12;
            let v29: L = v28 * v16;
            let v30: L = v10 * v16;
            let v31: L = v30 * v12;
            let v32: L = v29 - v31;
            let v33: L = v27 * v32;
            let v34: L = v25 * v33;
            let v35: L = v24 - v34;
            let v36: L = v35 * v8;
            let v37: L = v17 * v12;
            let v38: L = v13 * v16;
            let v39: L = v37 - v38;
            let v40: L = v39 * v27;
            let v41: L = v8 * v40;
            let v42: L = L::splat(0.111172755531_f64);
            let v43: L = v30 * v16;
            let v44: L = v28 * v12;
            let v45: L = v43 + v44;
            let v46: L = L::splat(0.00168332516775_f64);
            let v47: L = v45 + v46;
            let v48: L = v42 + v47;
            let v49: L = v27 * v48;
            let v50: L = v49 * v27;
            let v51: L = L::splat(0.12999255384415_f64);
            let v53: L = v51 * v52;
            let v54: L = v53 * v52;
            let v55: L = v50 + v54;
            let v56: L = v55 + v21;
            let v57: L = v42 + v56;
            let v58: L = v25 * v57;
            let v59: L = v41 - v58;
            let v60: L = v59 * v25;
            let v61: L = v36 - v60;
            let v62: L = L::splat(0.40402113811874996_f64);
            let v63: L = L::splat(2.0_f64);
            let v64: L = L::splat(0.39225_f64);
            let v65: L = L::splat(0.017784735_f64);
            let v66: L = v65 * v25;
            let v67: L = v64 * v66;
            let v68: L = v63 * v67;
            let v69: L = v62 - v68;
            let v70: L = v61 + v69;
            let v71: L = v6 + v70;
            let v72: L = v5 * v71;
            let v74: L = v8 * v57;
            let v75: L = v25 * v40;
            let v76: L = v74 + v75;
            let v77: L = v76 * v25;
            let v78: L = v8 * v33;
            let v79: L = v25 * v23;
            let v80: L = v78 + v79;
            let v81: L = v80 * v8;
            let v82: L = v77 - v81;
            let v83: L = v65 * v8;
            let v84: L = v64 * v83;
            let v85: L = v82 - v84;
            let v86: L = v73 * v85;
            let v87: L = v72 + v86;
            let v88: L = v87 * v5;
            let v89: L = L::splat(0.004095_f64);
            let v90: L = v76 * v8;
            let v91: L = v80 * v25;
            let v92: L = v90 + v91;
            let v93: L = v92 + v69;
            let v94: L = v93 - v62;
            let v95: L = v94 + v67;
            let v96: L = v95 + v67;
            let v97: L = v89 + v96;
            let v98: L = v73 * v97;
            let v99: L = v59 * v8;
            let v100: L = v35 * v25;
            let v101: L = v99 + v100;
            let v102: L = v101 + v84;
            let v103: L = v5 * v102;
            let v104: L = v98 - v103;
            let v105: L = v104 * v73;
            let v106: L = v88 + v105;
            let v107: L = L::splat(0.9554455987809999_f64);
            let v108: L = -L::splat(0.01566175149_f64);
            let v109: L = L::splat(0.425_f64);
            let v110: L = L::splat(0.56875_f64);
            let v111: L = L::splat(1.030009275_f64);
            let v112: L = v111 - v66;
            let v113: L = v110 + v112;
            let v114: L = v5 * v113;
            let v115: L = v73 * v83;
            let v116: L = v114 - v115;
            let v117: L = v109 * v116;
            let v118: L = v108 + v117;
            let v119: L = v63 * v118;
            let v120: L = v107 + v119;
            let v121: L = v106 + v120;
            let v122: L = v3 + v121;
            let v123: L = v2 * v122;
            let v125: L = v5 * v85;
            let v126: L = v73 * v71;
            let v127: L = v125 - v126;
            let v128: L = v127 * v5;
            let v129: L = v73 * v102;
            let v130: L = v5 * v97;
            let v131: L = v129 + v130;
            let v132: L = v131 * v73;
            let v133: L = v128 + v132;
            let v134: L = v5 * v83;
            let v135: L = v73 * v113;
            let v136: L = v134 + v135;
            let v137: L = v109 * v136;
            let v138: L = v133 - v137;
            let v139: L = v124 * v138;
            let v140: L = v123 + v139;
            let v141: L = v140 * v2;
            let v142: L = v104 * v5;
            let v143: L = v87 * v73;
            let v144: L = v142 - v143;
            let v145: L = v144 - v137;
            let v146: L = v2 * v145;
            let v147: L = L::splat(0.0151074_f64);
            let v148: L = v131 * v5;
            let v149: L = v127 * v73;
            let v150: L = v148 - v149;
            let v151: L = v150 + v120;
            let v152: L = L::splat(0.8852250624999999_f64);
            let v153: L = v151 - v152;
            let v154: L = v153 - v117;
            let v155: L = v154 - v117;
            let v156: L = v147 + v155;
            let v157: L = v124 * v156;
            let v158: L = v146 + v157;
            let v159: L = v158 * v124;
            let v160: L = v141 + v159;
            let v161: L = L::splat(0.12150210104175002_f64);
            let v162: L = v160 + v161;
            let v163: L = v0 + v162;
            let v164: L = v39 * v52;
            let v165: L = L::splat(0.0016539803549999999_f64);
            let v166: L = v164 - v165;
            let v167: L = v8 * v166;
            let v168: L = v49 * v52;
            let v169: L = v53 * v27;
            let v170: L = v168 - v169;
            let v171: L = v25 * v170;
            let v172: L = v167 - v171;
            let v173: L = v73 * v172;
            (
                v2,
                v3,
                v5,
                v6,
                v8,
                v9,
                v10,
                v12,
                v15,
                v16,
                v20,
                v25,
                v27,
                v32,
                v34,
                v42,
                v48,
                v51,
                v52,
                v64,
                v66,
                v67,
                v69,
                v73,
                v78,
                v89,
                v108,
                v109,
                v110,
                v115,
                v116,
                v117,
                v120,
                v124,
                v134,
                v135,
                v136,
                v147,
                v163,
                v166,
                v170,
                v172,
                v173,
            )
        };
        let (
            v183,
            v196,
            v197,
            v205,
            v217,
            v226,
            v238,
            v251,
            v264,
            v266,
            v267,
            v268,
            v270,
            v272,
            v276,
            v278,
            v279,
            v283,
            v285,
            v290,
            v293,
            v295,
            v296,
            v298,
            v303,
            v307,
            v311,
            v312,
            v315,
            v317,
            v323,
            v328,
            v329,
            v331,
            v332,
            v333,
            v334,
            v336,
            v339,
            v342,
            v345,
            v346,
            v347,
        ) = {
            let v174: L = v8 * v170;
            let v175: L = v25 * v166;
            let v176: L = v174 + v175;
            let v177: L = L::splat(0.051322656825_f64);
            let v178: L = v176 + v177;
            let v179: L = v5 * v178;
            let v180: L = v173 + v179;
            let v181: L = -L::splat(0.24932103525000002_f64);
            let v182: L = v180 + v181;
            let v183: L = -L::splat(0.1197_f64);
            let v184: L = v183 * v116;
            let v185: L = v182 + v184;
            let v186: L = L::splat(0.0556077225_f64);
            let v187: L = v185 + v186;
            let v188: L = v124 * v187;
            let v189: L = v5 * v172;
            let v190: L = v73 * v178;
            let v191: L = v189 - v190;
            let v192: L = v183 * v136;
            let v193: L = v191 - v192;
            let v194: L = v2 * v193;
            let v195: L = v188 - v194;
            let v196: L = L::splat(0.13585_f64);
            let v197: L = L::splat(2.35004_f64);
            let v198: L = L::splat(2.0828824999999997_f64);
            let v199: L = v116 + v198;
            let v200: L = v197 + v199;
            let v201: L = v124 * v200;
            let v202: L = v2 * v136;
            let v203: L = v201 + v202;
            let v204: L = v196 * v203;
            let v205: L = v195 + v204;
            let v206: L = v180 + v184;
            let v207: L = v124 * v206;
            let v208: L = v135 + v134;
            let v209: L = v183 * v208;
            let v210: L = v191 - v209;
            let v211: L = v2 * v210;
            let v212: L = v207 - v211;
            let v213: L = v124 * v116;
            let v214: L = v2 * v208;
            let v215: L = v213 + v214;
            let v216: L = v196 * v215;
            let v217: L = v212 + v216;
            let v218: L = v73 * v176;
            let v219: L = v189 - v218;
            let v220: L = v73 * v66;
            let v221: L = v220 - v134;
            let v222: L = v183 * v221;
            let v223: L = v219 + v222;
            let v224: L = v2 * v223;
            let v225: L = v5 * v66;
            let v226: L = v225 + v115;
            let v227: L = v183 * v226;
            let v228: L = v5 * v176;
            let v229: L = v173 + v228;
            let v230: L = v227 - v229;
            let v231: L = v124 * v230;
            let v232: L = v224 + v231;
            let v233: L = v124 * v226;
            let v234: L = v2 * v221;
            let v235: L = v233 + v234;
            let v236: L = v196 * v235;
            let v237: L = v232 + v236;
            let v238: L = -v237;
            let v239: L = v8 * v20;
            let v240: L = v239 - v34;
            let v241: L = v73 * v240;
            let v242: L = v25 * v20;
            let v243: L = v78 + v242;
            let v244: L = v5 * v243;
            let v245: L = v241 + v244;
            let v246: L = v124 * v245;
            let v247: L = v5 * v240;
            let v248: L = v73 * v243;
            let v249: L = v247 - v248;
            let v250: L = v2 * v249;
            let v251: L = v246 - v250;
            let v252: L = v10 * v52;
            let v253: L = v25 * v252;
            let v254: L = v5 * v253;
            let v255: L = v8 * v252;
            let v256: L = v73 * v255;
            let v257: L = v254 + v256;
            let v258: L = v2 * v257;
            let v259: L = v5 * v255;
            let v260: L = v73 * v253;
            let v261: L = v259 - v260;
            let v262: L = v124 * v261;
            let v263: L = v258 + v262;
            let v264: L = -v263;
            let v265: L = qd[0];
            let v266: L = v124 * v265;
            let v267: L = qd[1];
            let v268: L = v266 * v267;
            let v269: L = v3 * v268;
            let v270: L = v3 * v267;
            let v271: L = v266 * v270;
            let v272: L = v147 * v266;
            let v273: L = v267 * v272;
            let v274: L = v271 - v273;
            let v275: L = v269 + v274;
            let v276: L = v196 * v266;
            let v277: L = v266 * v276;
            let v278: L = v2 * v265;
            let v279: L = v196 * v278;
            let v280: L = v278 * v279;
            let v281: L = v277 + v280;
            let v282: L = v197 * v281;
            let v283: L = v275 + v282;
            let v284: L = v5 * v268;
            let v285: L = v278 * v267;
            let v286: L = v73 * v285;
            let v287: L = v284 + v286;
            let v288: L = v73 * v278;
            let v289: L = v5 * v266;
            let v290: L = v288 + v289;
            let v291: L = qd[2];
            let v292: L = v290 * v291;
            let v293: L = v287 + v292;
            let v294: L = v6 * v293;
            let v295: L = v267 + v291;
            let v296: L = v6 * v295;
            let v297: L = v290 * v296;
            let v298: L = v89 * v290;
            let v299: L = v295 * v298;
            let v300: L = v297 - v299;
            let v301: L = v294 + v300;
            let v302: L = v109 * v268;
            let v303: L = v109 * v267;
            let v304: L = v266 * v303;
            let v305: L = v302 + v304;
            let v306: L = v281 + v305;
            let v307: L = v183 * v290;
            let v308: L = v290 * v307;
            let v309: L = v73 * v266;
            let v310: L = v5 * v278;
            let v311: L = v309 - v310;
            let v312: L = v183 * v311;
            let v313: L = v311 * v312;
            let v314: L = v308 + v313;
            let v315: L = v306 + v314;
            let v316: L = v110 * v315;
            let v317: L = v301 + v316;
            let v318: L = v8 * v293;
            let v319: L = v73 * v268;
            let v320: L = v5 * v285;
            let v321: L = v319 - v320;
            let v322: L = v311 * v291;
            let v323: L = v321 + v322;
            let v324: L = v25 * v323;
            let v325: L = v318 - v324;
            let v326: L = v8 * v290;
            let v327: L = v25 * v311;
            let v328: L = v326 - v327;
            let v329: L = qd[3];
            let v330: L = v328 * v329;
            let v331: L = v325 + v330;
            let v332: L = v9 * v331;
            let v333: L = v295 + v329;
            let v334: L = v42 * v333;
            let v335: L = v328 * v334;
            let v336: L = v42 * v328;
            let v337: L = v333 * v336;
            let v338: L = v335 - v337;
            let v339: L = v332 + v338;
            let v340: L = v27 * v328;
            let v341: L = v52 * v333;
            let v342: L = v340 + v341;
            let v343: L = v27 * v333;
            let v344: L = v52 * v328;
            let v345: L = v343 - v344;
            let v346: L = v42 * v345;
            let v347: L = v342 * v346;
            (
                v183,
                v196,
                v197,
                v205,
                v217,
                v226,
                v238,
                v251,
                v264,
                v266,
                v267,
                v268,
                v270,
                v272,
                v276,
                v278,
                v279,
                v283,
                v285,
                v290,
                v293,
                v295,
                v296,
                v298,
                v303,
                v307,
                v311,
                v312,
                v315,
                v317,
                v323,
                v328,
                v329,
                v331,
                v332,
                v333,
                v334,
                v336,
                v339,
                v342,
                v345,
                v346,
                v347,
            )
        };
        let (
            v348,
            v359,
            v368,
            v370,
            v378,
            v381,
            v388,
            v392,
            v396,
            v399,
            v401,
            v402,
            v412,
            v421,
            v431,
            v442,
            v449,
            v455,
            v465,
            v468,
            v477,
            v481,
            v489,
            v494,
            v496,
            v497,
            v506,
            v508,
            v510,
            v512,
            v513,
            v514,
            v519,
            v520,
            v521,
        ) = {
            let v348: L = v42 * v342;
            let v349: L = v345 * v348;
            let v350: L = v347 - v349;
            let v351: L = v332 + v350;
            let v352: L = qd[4];
            let v353: L = v345 * v352;
            let v354: L = v25 * v293;
            let v355: L = v8 * v323;
            let v356: L = v354 + v355;
            let v357: L = v8 * v311;
            let v358: L = v25 * v290;
            let v359: L = v357 + v358;
            let v360: L = v359 * v329;
            let v361: L = v356 + v360;
            let v362: L = v27 * v361;
            let v363: L = v353 - v362;
            let v364: L = v12 * v363;
            let v365: L = v16 * v331;
            let v366: L = v364 + v365;
            let v367: L = v16 * v342;
            let v368: L = v359 + v352;
            let v369: L = v12 * v368;
            let v370: L = v367 - v369;
            let v371: L = qd[5];
            let v372: L = v370 * v371;
            let v373: L = v366 + v372;
            let v374: L = v15 * v373;
            let v375: L = v345 + v371;
            let v376: L = v10 * v375;
            let v377: L = v370 * v376;
            let v378: L = v10 * v370;
            let v379: L = v375 * v378;
            let v380: L = v377 - v379;
            let v381: L = v374 + v380;
            let v382: L = v16 * v381;
            let v383: L = v16 * v363;
            let v384: L = v12 * v331;
            let v385: L = v383 - v384;
            let v386: L = v12 * v342;
            let v387: L = v16 * v368;
            let v388: L = v386 + v387;
            let v389: L = v388 * v371;
            let v390: L = v385 - v389;
            let v391: L = v10 * v390;
            let v392: L = v15 * v388;
            let v393: L = v375 * v392;
            let v394: L = v388 * v376;
            let v395: L = v393 - v394;
            let v396: L = v391 + v395;
            let v397: L = v12 * v396;
            let v398: L = v382 - v397;
            let v399: L = v351 + v398;
            let v400: L = v339 + v399;
            let v401: L = L::splat(0.093_f64);
            let v402: L = L::splat(1.219_f64);
            let v403: L = v401 * v328;
            let v404: L = v333 * v403;
            let v405: L = v401 * v331;
            let v406: L = v404 - v405;
            let v407: L = v196 * v285;
            let v408: L = v267 * v279;
            let v409: L = v407 - v408;
            let v410: L = L::splat(9.81_f64);
            let v411: L = v410 * v2;
            let v412: L = v409 - v411;
            let v413: L = v109 * v278;
            let v414: L = v266 * v413;
            let v415: L = v412 + v414;
            let v416: L = v5 * v415;
            let v417: L = v196 * v268;
            let v418: L = v267 * v276;
            let v419: L = v417 - v418;
            let v420: L = v410 * v124;
            let v421: L = v419 - v420;
            let v422: L = v278 * v413;
            let v423: L = v267 * v303;
            let v424: L = v422 + v423;
            let v425: L = v421 - v424;
            let v426: L = v73 * v425;
            let v427: L = v416 - v426;
            let v428: L = v295 * v312;
            let v429: L = v183 * v323;
            let v430: L = v428 - v429;
            let v431: L = v427 + v430;
            let v432: L = v64 * v311;
            let v433: L = v290 * v432;
            let v434: L = v431 - v433;
            let v435: L = v25 * v434;
            let v436: L = v73 * v415;
            let v437: L = v5 * v425;
            let v438: L = v436 + v437;
            let v439: L = v183 * v293;
            let v440: L = v295 * v307;
            let v441: L = v439 - v440;
            let v442: L = v438 + v441;
            let v443: L = v311 * v432;
            let v444: L = v64 * v295;
            let v445: L = v295 * v444;
            let v446: L = v443 + v445;
            let v447: L = v442 - v446;
            let v448: L = v8 * v447;
            let v449: L = v435 + v448;
            let v450: L = v406 - v449;
            let v451: L = v27 * v450;
            let v452: L = v64 * v293;
            let v453: L = v290 * v444;
            let v454: L = v452 + v453;
            let v455: L = v315 + v454;
            let v456: L = v401 * v359;
            let v457: L = v359 * v456;
            let v458: L = v328 * v403;
            let v459: L = v457 + v458;
            let v460: L = v455 + v459;
            let v461: L = v52 * v460;
            let v462: L = v451 - v461;
            let v463: L = v402 * v462;
            let v464: L = L::splat(0.1879_f64);
            let v465: L = L::splat(0.09465_f64);
            let v466: L = v52 * v361;
            let v467: L = v342 * v352;
            let v468: L = v466 - v467;
            let v469: L = v465 * v468;
            let v470: L = v465 * v342;
            let v471: L = v368 * v470;
            let v472: L = v469 + v471;
            let v473: L = v462 + v472;
            let v474: L = v16 * v473;
            let v475: L = v8 * v434;
            let v476: L = v25 * v447;
            let v477: L = v475 - v476;
            let v478: L = v333 * v456;
            let v479: L = v401 * v361;
            let v480: L = v478 - v479;
            let v481: L = v477 + v480;
            let v482: L = v342 * v470;
            let v483: L = v465 * v345;
            let v484: L = v345 * v483;
            let v485: L = v482 + v484;
            let v486: L = v481 - v485;
            let v487: L = v12 * v486;
            let v488: L = v474 - v487;
            let v489: L = v464 * v488;
            let v490: L = v16 * v489;
            let v491: L = v12 * v473;
            let v492: L = v16 * v486;
            let v493: L = v491 + v492;
            let v494: L = v464 * v493;
            let v495: L = v12 * v494;
            let v496: L = v490 + v495;
            let v497: L = v463 + v496;
            let v498: L = v27 * v497;
            let v499: L = v368 * v483;
            let v500: L = v465 * v363;
            let v501: L = v499 - v500;
            let v502: L = v52 * v450;
            let v503: L = v27 * v460;
            let v504: L = v502 + v503;
            let v505: L = v501 - v504;
            let v506: L = v464 * v505;
            let v507: L = v402 * v504;
            let v508: L = v506 - v507;
            let v509: L = v52 * v508;
            let v510: L = v498 - v509;
            let v511: L = v401 * v510;
            let v512: L = v400 - v511;
            let v513: L = v8 * v512;
            let v514: L = v9 * v359;
            let v515: L = v333 * v514;
            let v516: L = v359 * v334;
            let v517: L = v515 - v516;
            let v518: L = v42 * v361;
            let v519: L = v517 - v518;
            let v520: L = v42 * v363;
            let v521: L = v9 * v368;
            (
                v348,
                v359,
                v368,
                v370,
                v378,
                v381,
                v388,
                v392,
                v396,
                v399,
                v401,
                v402,
                v412,
                v421,
                v431,
                v442,
                v449,
                v455,
                v465,
                v468,
                v477,
                v481,
                v489,
                v494,
                v496,
                v497,
                v506,
                v508,
                v510,
                v512,
                v513,
                v514,
                v519,
                v520,
                v521,
            )
        };
        let (
            v542,
            v651,
            v657,
            v659,
            v665,
            v666,
            v667,
            v669,
            v670,
            v671,
            v688,
            v691,
            v694,
            v695,
        ) = {
            let v522: L = v345 * v521;
            let v523: L = v368 * v346;
            let v524: L = v522 - v523;
            let v525: L = v520 + v524;
            let v526: L = v16 * v396;
            let v527: L = v12 * v381;
            let v528: L = v526 + v527;
            let v529: L = v525 + v528;
            let v530: L = v465 * v506;
            let v531: L = v529 - v530;
            let v532: L = v27 * v531;
            let v533: L = v42 * v468;
            let v534: L = v368 * v348;
            let v535: L = v342 * v521;
            let v536: L = v534 - v535;
            let v537: L = v533 + v536;
            let v538: L = v10 * v468;
            let v539: L = v388 * v378;
            let v540: L = v370 * v392;
            let v541: L = v539 - v540;
            let v542: L = v538 + v541;
            let v543: L = v537 + v542;
            let v544: L = v465 * v496;
            let v545: L = v543 + v544;
            let v546: L = v52 * v545;
            let v547: L = v532 - v546;
            let v548: L = v519 + v547;
            let v549: L = v402 * v481;
            let v550: L = v16 * v494;
            let v551: L = v12 * v489;
            let v552: L = v550 - v551;
            let v553: L = v549 + v552;
            let v554: L = v401 * v553;
            let v555: L = v548 + v554;
            let v556: L = v25 * v555;
            let v557: L = v513 - v556;
            let v558: L = v317 + v557;
            let v559: L = v52 * v497;
            let v560: L = v27 * v508;
            let v561: L = v559 + v560;
            let v562: L = v402 * v455;
            let v563: L = v561 - v562;
            let v564: L = v64 * v563;
            let v565: L = v558 - v564;
            let v566: L = L::splat(2.275_f64);
            let v567: L = v566 * v442;
            let v568: L = v110 * v311;
            let v569: L = v311 * v568;
            let v570: L = v110 * v295;
            let v571: L = v295 * v570;
            let v572: L = v569 + v571;
            let v573: L = v567 - v572;
            let v574: L = v402 * v449;
            let v575: L = v510 - v574;
            let v576: L = v8 * v575;
            let v577: L = v402 * v477;
            let v578: L = v577 + v553;
            let v579: L = v25 * v578;
            let v580: L = v576 + v579;
            let v581: L = v573 - v580;
            let v582: L = v183 * v581;
            let v583: L = v565 + v582;
            let v584: L = v5 * v583;
            let v585: L = v89 * v323;
            let v586: L = v311 * v296;
            let v587: L = v6 * v311;
            let v588: L = v295 * v587;
            let v589: L = v586 - v588;
            let v590: L = v585 + v589;
            let v591: L = v8 * v555;
            let v592: L = v25 * v512;
            let v593: L = v591 + v592;
            let v594: L = v590 - v593;
            let v595: L = v566 * v431;
            let v596: L = v290 * v568;
            let v597: L = v595 - v596;
            let v598: L = v8 * v578;
            let v599: L = v25 * v575;
            let v600: L = v598 - v599;
            let v601: L = v597 + v600;
            let v602: L = v183 * v601;
            let v603: L = v594 - v602;
            let v604: L = v73 * v603;
            let v605: L = v584 + v604;
            let v606: L = v283 + v605;
            let v607: L = v566 * v315;
            let v608: L = v110 * v293;
            let v609: L = v290 * v570;
            let v610: L = v608 + v609;
            let v611: L = v607 + v610;
            let v612: L = v563 - v611;
            let v613: L = v109 * v612;
            let v614: L = v606 - v613;
            let v615: L = L::splat(8.393_f64);
            let v616: L = v615 * v421;
            let v617: L = v197 * v278;
            let v618: L = v278 * v617;
            let v619: L = v197 * v267;
            let v620: L = v267 * v619;
            let v621: L = v618 + v620;
            let v622: L = v616 - v621;
            let v623: L = v5 * v581;
            let v624: L = v73 * v601;
            let v625: L = v623 - v624;
            let v626: L = v622 + v625;
            let v627: L = v196 * v626;
            let v628: L = v614 + v627;
            let v629: L = v2 * v628;
            let v630: L = v3 * v278;
            let v631: L = v267 * v630;
            let v632: L = v278 * v270;
            let v633: L = v631 - v632;
            let v634: L = v147 * v285;
            let v635: L = v633 - v634;
            let v636: L = v5 * v603;
            let v637: L = v73 * v583;
            let v638: L = v636 - v637;
            let v639: L = v635 + v638;
            let v640: L = v615 * v412;
            let v641: L = v266 * v617;
            let v642: L = v640 + v641;
            let v643: L = v5 * v601;
            let v644: L = v73 * v581;
            let v645: L = v643 + v644;
            let v646: L = v642 + v645;
            let v647: L = v196 * v646;
            let v648: L = v639 - v647;
            let v649: L = v124 * v648;
            let v650: L = v629 + v649;
            let v651: L = -v650;
            let v652: L = v52 * v48;
            let v653: L = v652 * v52;
            let v654: L = v51 * v27;
            let v655: L = v654 * v27;
            let v656: L = v653 + v655;
            let v657: L = v42 + v656;
            let v658: L = v657 + v69;
            let v659: L = v6 + v658;
            let v660: L = v659 + v120;
            let v661: L = L::splat(0.070220536281_f64);
            let v662: L = v660 - v661;
            let v663: L = v662 - v108;
            let v664: L = v663 - v108;
            let v665: L = v3 + v664;
            let v666: L = v659 + v117;
            let v667: L = v657 - v67;
            let v668: L = v109 * v226;
            let v669: L = v667 - v668;
            let v670: L = v52 * v32;
            let v671: L = v10 * v27;
            let v672: L = v266 * v630;
            let v673: L = v278 * v272;
            let v674: L = v672 - v673;
            let v675: L = v197 * v412;
            let v676: L = v674 + v675;
            let v677: L = v311 * v298;
            let v678: L = v290 * v587;
            let v679: L = v677 - v678;
            let v680: L = v110 * v431;
            let v681: L = v679 + v680;
            let v682: L = v359 * v336;
            let v683: L = v328 * v514;
            let v684: L = v682 - v683;
            let v685: L = v52 * v531;
            let v686: L = v27 * v545;
            let v687: L = v685 + v686;
            let v688: L = v684 + v687;
            let v689: L = v681 + v688;
            let v690: L = v64 * v600;
            let v691: L = v689 + v690;
            let v692: L = v676 + v691;
            let v693: L = v109 * v645;
            let v694: L = v692 + v693;
            let v695: L = L::splat(0.0_f64);
            (
                v542,
                v651,
                v657,
                v659,
                v665,
                v666,
                v667,
                v669,
                v670,
                v671,
                v688,
                v691,
                v694,
                v695,
            )
        };
        [
            [v163, v205, v217, v238, v251, v264, v651],
            [v205, v665, v666, v669, v670, v671, v694],
            [v217, v666, v659, v667, v670, v671, v691],
            [v238, v669, v667, v657, v670, v671, v688],
            [v251, v670, v670, v670, v20, v695, v399],
            [v264, v671, v671, v671, v695, v10, v542],
        ]
    }
    /// Dynamic regressor: `inverse_dynamics(q, qd, qdd) = Y(q, qd, qdd) * standard_parameters()`.
    ///
    /// # Inputs
    ///
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 6]`: joint velocities qd (rad/s or m/s)
    /// - `qdd: &[L; 6]`: joint accelerations qdd (rad/s^2 or m/s^2)
    ///
    /// # Output
    ///
    /// `regressor: [[L; 60]; 6]` (6 x 60, row-major): Y(q, qd, qdd), columns in the order of `standard_parameters`
    ///
    /// Operation count: 1123 floating-point operations, 10 trig calls.
    #[inline]
    #[must_use]
    #[allow(
        unused_variables,
        non_snake_case,
        clippy::all,
        clippy::pedantic,
        clippy::nursery
    )]
    pub fn regressor<L: crate::lanes::Lane>(
        q: &[L; 6],
        qd: &[L; 6],
        qdd: &[L; 6],
    ) -> [[L; 60]; 6] {
        let (
            v0,
            v4,
            v7,
            v8,
            v17,
            v20,
            v23,
            v29,
            v32,
            v45,
            v47,
            v59,
            v66,
            v71,
            v79,
            v87,
            v88,
            v94,
            v97,
            v99,
            v100,
            v107,
            v116,
            v120,
            v127,
            v130,
            v136,
            v138,
            v146,
            v151,
            v152,
            v162,
            v166,
            v172,
            v174,
            v176,
            v180,
            v187,
            v191,
            v193,
        ) = {
            let v0: L = qdd[0];
            let v1: L = L::splat(0.13585_f64);
            let v2: L = q[1];
            let (v3, v5): (L, L) = L::sincos(v2);
            let v4: L = v3 * v0;
            let v6: L = qd[0];
            let v7: L = v5 * v6;
            let v8: L = qd[1];
            let v9: L = v7 * v8;
            let v10: L = v4 + v9;
            let v11: L = v1 * v10;
            let v12: L = v1 * v7;
            let v13: L = v8 * v12;
            let v14: L = v11 - v13;
            let v15: L = L::splat(9.81_f64);
            let v16: L = v15 * v5;
            let v17: L = v14 - v16;
            let v18: L = v1 * v3;
            let v19: L = v17 * v18;
            let v20: L = v3 * v6;
            let v21: L = v20 * v8;
            let v22: L = v5 * v0;
            let v23: L = v21 - v22;
            let v24: L = v1 * v23;
            let v25: L = v1 * v20;
            let v26: L = v8 * v25;
            let v27: L = v24 - v26;
            let v28: L = v15 * v3;
            let v29: L = v27 - v28;
            let v30: L = v1 * v5;
            let v31: L = v29 * v30;
            let v32: L = v19 - v31;
            let v33: L = v20 * v25;
            let v34: L = v7 * v12;
            let v35: L = v33 + v34;
            let v36: L = v35 * v3;
            let v37: L = v8 * v18;
            let v38: L = v8 * v37;
            let v39: L = v36 - v38;
            let v40: L = v20 * v18;
            let v41: L = v7 * v30;
            let v42: L = v40 + v41;
            let v43: L = v20 * v42;
            let v44: L = v39 - v43;
            let v45: L = qdd[1];
            let v46: L = v45 * v30;
            let v47: L = v44 + v46;
            let v48: L = v10 * v18;
            let v49: L = v7 * v37;
            let v50: L = v48 - v49;
            let v51: L = v17 * v3;
            let v52: L = v50 + v51;
            let v53: L = v8 * v30;
            let v54: L = v20 * v53;
            let v55: L = v52 + v54;
            let v56: L = v23 * v30;
            let v57: L = v55 - v56;
            let v58: L = v29 * v5;
            let v59: L = v57 - v58;
            let v60: L = v45 * v18;
            let v61: L = v8 * v53;
            let v62: L = v60 + v61;
            let v63: L = v7 * v42;
            let v64: L = v62 + v63;
            let v65: L = v35 * v5;
            let v66: L = v64 - v65;
            let v67: L = v8 * v3;
            let v68: L = v7 * v67;
            let v69: L = v23 * v5;
            let v70: L = v68 + v69;
            let v71: L = -v70;
            let v72: L = v8 * v67;
            let v73: L = v7 * v3;
            let v74: L = v20 * v5;
            let v75: L = v73 - v74;
            let v76: L = v7 * v75;
            let v77: L = v72 - v76;
            let v78: L = v45 * v5;
            let v79: L = v77 - v78;
            let v80: L = v8 * v5;
            let v81: L = v7 * v80;
            let v82: L = v20 * v67;
            let v83: L = v23 * v3;
            let v84: L = v82 + v83;
            let v85: L = v81 - v84;
            let v86: L = v10 * v5;
            let v87: L = v85 + v86;
            let v88: L = v8 * v75;
            let v89: L = v45 * v3;
            let v90: L = v20 * v75;
            let v91: L = v89 + v90;
            let v92: L = v8 * v80;
            let v93: L = v91 + v92;
            let v94: L = -v93;
            let v95: L = v10 * v3;
            let v96: L = v20 * v80;
            let v97: L = v95 + v96;
            let v98: L = q[2];
            let (v107, v99): (L, L) = L::sincos(v98);
            let v100: L = L::splat(0.425_f64);
            let v101: L = v100 * v45;
            let v102: L = v100 * v7;
            let v103: L = v20 * v102;
            let v104: L = v101 + v103;
            let v105: L = v17 + v104;
            let v106: L = v99 * v105;
            let v108: L = v7 * v102;
            let v109: L = v100 * v8;
            let v110: L = v8 * v109;
            let v111: L = v108 + v110;
            let v112: L = v29 - v111;
            let v113: L = v107 * v112;
            let v114: L = v106 - v113;
            let v115: L = qd[2];
            let v116: L = v8 + v115;
            let v117: L = -L::splat(0.1197_f64);
            let v118: L = v107 * v20;
            let v119: L = v99 * v7;
            let v120: L = v118 - v119;
            let v121: L = v117 * v120;
            let v122: L = v116 * v121;
            let v123: L = v107 * v23;
            let v124: L = v99 * v10;
            let v125: L = v123 - v124;
            let v126: L = v120 * v115;
            let v127: L = v125 + v126;
            let v128: L = v117 * v127;
            let v129: L = v122 - v128;
            let v130: L = v114 + v129;
            let v131: L = v99 * v18;
            let v132: L = v107 * v30;
            let v133: L = v131 + v132;
            let v134: L = v99 * v3;
            let v135: L = v107 * v5;
            let v136: L = v134 + v135;
            let v137: L = v117 * v136;
            let v138: L = v133 + v137;
            let v139: L = v130 * v138;
            let v140: L = v100 * v23;
            let v141: L = v20 * v109;
            let v142: L = v140 + v141;
            let v143: L = v35 + v142;
            let v144: L = v107 * v7;
            let v145: L = v99 * v20;
            let v146: L = v144 + v145;
            let v147: L = v117 * v146;
            let v148: L = v146 * v147;
            let v149: L = v120 * v121;
            let v150: L = v148 + v149;
            let v151: L = v143 + v150;
            let v152: L = v100 * v5;
            let v153: L = v151 * v152;
            let v154: L = v139 - v153;
            let v155: L = v107 * v105;
            let v156: L = v99 * v112;
            let v157: L = v155 + v156;
            let v158: L = v99 * v23;
            let v159: L = v107 * v10;
            let v160: L = v158 + v159;
            let v161: L = v146 * v115;
            let v162: L = v160 + v161;
            let v163: L = v117 * v162;
            let v164: L = v116 * v147;
            let v165: L = v163 - v164;
            let v166: L = v157 + v165;
            let v167: L = v107 * v18;
            let v168: L = v99 * v30;
            let v169: L = v167 - v168;
            let v170: L = v107 * v3;
            let v171: L = v99 * v5;
            let v172: L = v170 - v171;
            let v173: L = v117 * v172;
            let v174: L = v169 + v173;
            let v175: L = v166 * v174;
            let v176: L = v154 + v175;
            let v177: L = v127 * v152;
            let v178: L = v116 * v138;
            let v179: L = v120 * v152;
            let v180: L = v178 - v179;
            let v181: L = v116 * v180;
            let v182: L = v177 - v181;
            let v183: L = v151 * v136;
            let v184: L = v182 + v183;
            let v185: L = v146 * v138;
            let v186: L = v120 * v174;
            let v187: L = v185 + v186;
            let v188: L = v146 * v187;
            let v189: L = v184 - v188;
            let v190: L = qdd[2];
            let v191: L = v45 + v190;
            let v192: L = v191 * v174;
            let v193: L = v189 - v192;
            (
                v0,
                v4,
                v7,
                v8,
                v17,
                v20,
                v23,
                v29,
                v32,
                v45,
                v47,
                v59,
                v66,
                v71,
                v79,
                v87,
                v88,
                v94,
                v97,
                v99,
                v100,
                v107,
                v116,
                v120,
                v127,
                v130,
                v136,
                v138,
                v146,
                v151,
                v152,
                v162,
                v166,
                v172,
                v174,
                v176,
                v180,
                v187,
                v191,
                v193,
            )
        };
        let (
            v207,
            v216,
            v220,
            v228,
            v236,
            v237,
            v242,
            v246,
            v248,
            v249,
            v256,
            v263,
            v270,
            v273,
            v279,
            v281,
            v283,
            v286,
            v289,
            v295,
            v299,
            v309,
            v314,
            v316,
            v322,
            v334,
            v338,
            v347,
            v352,
            v360,
            v368,
            v369,
            v374,
            v377,
            v378,
            v379,
            v383,
            v385,
            v386,
            v387,
        ) = {
            let v194: L = v120 * v180;
            let v195: L = v127 * v138;
            let v196: L = v194 - v195;
            let v197: L = v130 * v136;
            let v198: L = v196 + v197;
            let v199: L = v146 * v152;
            let v200: L = v116 * v174;
            let v201: L = v199 + v200;
            let v202: L = v146 * v201;
            let v203: L = v198 - v202;
            let v204: L = v162 * v174;
            let v205: L = v203 + v204;
            let v206: L = v166 * v172;
            let v207: L = v205 + v206;
            let v208: L = v191 * v138;
            let v209: L = v162 * v152;
            let v210: L = v208 - v209;
            let v211: L = v116 * v201;
            let v212: L = v210 - v211;
            let v213: L = v120 * v187;
            let v214: L = v212 - v213;
            let v215: L = v151 * v172;
            let v216: L = v214 + v215;
            let v217: L = v116 * v136;
            let v218: L = v120 * v217;
            let v219: L = v162 * v172;
            let v220: L = v218 + v219;
            let v221: L = v116 * v217;
            let v222: L = v146 * v172;
            let v223: L = v120 * v136;
            let v224: L = v222 - v223;
            let v225: L = v120 * v224;
            let v226: L = v221 + v225;
            let v227: L = v191 * v172;
            let v228: L = v226 + v227;
            let v229: L = v116 * v172;
            let v230: L = v120 * v229;
            let v231: L = v146 * v217;
            let v232: L = v162 * v136;
            let v233: L = v231 + v232;
            let v234: L = v230 - v233;
            let v235: L = v127 * v172;
            let v236: L = v234 + v235;
            let v237: L = v116 * v224;
            let v238: L = v116 * v229;
            let v239: L = v191 * v136;
            let v240: L = v146 * v224;
            let v241: L = v239 + v240;
            let v242: L = v238 - v241;
            let v243: L = v127 * v136;
            let v244: L = v146 * v229;
            let v245: L = v243 + v244;
            let v246: L = -v245;
            let v247: L = q[3];
            let (v256, v248): (L, L) = L::sincos(v247);
            let v249: L = L::splat(0.39225_f64);
            let v250: L = v249 * v191;
            let v251: L = v249 * v120;
            let v252: L = v146 * v251;
            let v253: L = v250 - v252;
            let v254: L = v130 + v253;
            let v255: L = v248 * v254;
            let v257: L = v120 * v251;
            let v258: L = v249 * v116;
            let v259: L = v116 * v258;
            let v260: L = v257 + v259;
            let v261: L = v166 - v260;
            let v262: L = v256 * v261;
            let v263: L = v255 - v262;
            let v264: L = v248 * v138;
            let v265: L = v256 * v174;
            let v266: L = v264 - v265;
            let v267: L = v263 * v266;
            let v268: L = v256 * v254;
            let v269: L = v248 * v261;
            let v270: L = v268 + v269;
            let v271: L = v256 * v138;
            let v272: L = v248 * v174;
            let v273: L = v271 + v272;
            let v274: L = v270 * v273;
            let v275: L = v267 + v274;
            let v276: L = v249 * v162;
            let v277: L = v146 * v258;
            let v278: L = v276 + v277;
            let v279: L = v151 + v278;
            let v280: L = v249 * v172;
            let v281: L = v152 - v280;
            let v282: L = v279 * v281;
            let v283: L = v275 - v282;
            let v284: L = v248 * v120;
            let v285: L = v256 * v146;
            let v286: L = v284 + v285;
            let v287: L = v248 * v146;
            let v288: L = v256 * v120;
            let v289: L = v287 - v288;
            let v290: L = v289 * v266;
            let v291: L = v286 * v273;
            let v292: L = v290 + v291;
            let v293: L = v286 * v292;
            let v294: L = qdd[3];
            let v295: L = v191 + v294;
            let v296: L = v295 * v266;
            let v297: L = v293 - v296;
            let v298: L = qd[3];
            let v299: L = v116 + v298;
            let v300: L = v299 * v273;
            let v301: L = v289 * v281;
            let v302: L = v300 + v301;
            let v303: L = v299 * v302;
            let v304: L = v297 + v303;
            let v305: L = v248 * v162;
            let v306: L = v256 * v127;
            let v307: L = v305 - v306;
            let v308: L = v289 * v298;
            let v309: L = v307 + v308;
            let v310: L = v309 * v281;
            let v311: L = v304 + v310;
            let v312: L = v256 * v136;
            let v313: L = v248 * v172;
            let v314: L = v312 + v313;
            let v315: L = v279 * v314;
            let v316: L = v311 - v315;
            let v317: L = v309 * v273;
            let v318: L = v256 * v162;
            let v319: L = v248 * v127;
            let v320: L = v318 + v319;
            let v321: L = v286 * v298;
            let v322: L = v320 + v321;
            let v323: L = v322 * v266;
            let v324: L = v317 - v323;
            let v325: L = v289 * v302;
            let v326: L = v324 - v325;
            let v327: L = v286 * v281;
            let v328: L = v299 * v266;
            let v329: L = v327 - v328;
            let v330: L = v286 * v329;
            let v331: L = v326 - v330;
            let v332: L = v248 * v136;
            let v333: L = v256 * v172;
            let v334: L = v332 - v333;
            let v335: L = v263 * v334;
            let v336: L = v331 + v335;
            let v337: L = v270 * v314;
            let v338: L = v336 + v337;
            let v339: L = v299 * v329;
            let v340: L = v289 * v292;
            let v341: L = v295 * v273;
            let v342: L = v340 + v341;
            let v343: L = v339 - v342;
            let v344: L = v322 * v281;
            let v345: L = v343 + v344;
            let v346: L = v279 * v334;
            let v347: L = v345 + v346;
            let v348: L = v322 * v334;
            let v349: L = v299 * v314;
            let v350: L = v289 * v349;
            let v351: L = v348 + v350;
            let v352: L = -v351;
            let v353: L = v295 * v334;
            let v354: L = v299 * v349;
            let v355: L = v353 - v354;
            let v356: L = v289 * v314;
            let v357: L = v286 * v334;
            let v358: L = v356 - v357;
            let v359: L = v289 * v358;
            let v360: L = v355 + v359;
            let v361: L = v299 * v334;
            let v362: L = v289 * v361;
            let v363: L = v309 * v334;
            let v364: L = v362 + v363;
            let v365: L = v286 * v349;
            let v366: L = v364 - v365;
            let v367: L = v322 * v314;
            let v368: L = v366 - v367;
            let v369: L = v299 * v358;
            let v370: L = v299 * v361;
            let v371: L = v286 * v358;
            let v372: L = v370 + v371;
            let v373: L = v295 * v314;
            let v374: L = v372 + v373;
            let v375: L = v286 * v361;
            let v376: L = v309 * v314;
            let v377: L = v375 + v376;
            let v378: L = L::splat(0.093_f64);
            let v379: L = v378 * v286;
            let v380: L = v299 * v379;
            let v381: L = v378 * v322;
            let v382: L = v380 - v381;
            let v383: L = v263 + v382;
            let v384: L = v378 * v334;
            let v385: L = v266 + v384;
            let v386: L = v383 * v385;
            let v387: L = q[4];
            (
                v207,
                v216,
                v220,
                v228,
                v236,
                v237,
                v242,
                v246,
                v248,
                v249,
                v256,
                v263,
                v270,
                v273,
                v279,
                v281,
                v283,
                v286,
                v289,
                v295,
                v299,
                v309,
                v314,
                v316,
                v322,
                v334,
                v338,
                v347,
                v352,
                v360,
                v368,
                v369,
                v374,
                v377,
                v378,
                v379,
                v383,
                v385,
                v386,
                v387,
            )
        };
        let (
            v388,
            v395,
            v401,
            v411,
            v416,
            v417,
            v424,
            v427,
            v431,
            v434,
            v442,
            v449,
            v454,
            v456,
            v469,
            v480,
            v486,
            v496,
            v506,
            v509,
            v516,
            v519,
            v520,
            v525,
            v527,
            v530,
            v537,
            v543,
            v548,
            v553,
            v556,
            v558,
            v565,
            v566,
            v568,
            v572,
            v574,
            v577,
            v580,
            v581,
        ) = {
            let (v388, v395): (L, L) = L::sincos(v387);
            let v389: L = v378 * v289;
            let v390: L = v299 * v389;
            let v391: L = v378 * v309;
            let v392: L = v390 - v391;
            let v393: L = v392 - v270;
            let v394: L = v388 * v393;
            let v396: L = v286 * v379;
            let v397: L = v289 * v389;
            let v398: L = v396 + v397;
            let v399: L = v279 + v398;
            let v400: L = v395 * v399;
            let v401: L = v394 + v400;
            let v402: L = v395 * v281;
            let v403: L = v378 * v314;
            let v404: L = v273 + v403;
            let v405: L = v388 * v404;
            let v406: L = v402 + v405;
            let v407: L = v401 * v406;
            let v408: L = v386 - v407;
            let v409: L = v395 * v393;
            let v410: L = v388 * v399;
            let v411: L = v409 - v410;
            let v412: L = v388 * v281;
            let v413: L = v395 * v404;
            let v414: L = v412 - v413;
            let v415: L = v411 * v414;
            let v416: L = v408 + v415;
            let v417: L = v388 * v334;
            let v418: L = v383 * v417;
            let v419: L = v388 * v322;
            let v420: L = v395 * v295;
            let v421: L = v419 + v420;
            let v422: L = v395 * v289;
            let v423: L = v388 * v299;
            let v424: L = v422 + v423;
            let v425: L = qd[4];
            let v426: L = v424 * v425;
            let v427: L = v421 - v426;
            let v428: L = v427 * v385;
            let v429: L = v418 - v428;
            let v430: L = qdd[4];
            let v431: L = v309 + v430;
            let v432: L = v431 * v406;
            let v433: L = v429 + v432;
            let v434: L = v286 + v425;
            let v435: L = v424 * v385;
            let v436: L = v434 * v414;
            let v437: L = v435 - v436;
            let v438: L = v434 * v437;
            let v439: L = v433 + v438;
            let v440: L = v395 * v299;
            let v441: L = v388 * v289;
            let v442: L = v440 - v441;
            let v443: L = v442 * v414;
            let v444: L = v424 * v406;
            let v445: L = v443 - v444;
            let v446: L = v442 * v445;
            let v447: L = v439 - v446;
            let v448: L = v401 * v314;
            let v449: L = v447 - v448;
            let v450: L = v388 * v295;
            let v451: L = v395 * v322;
            let v452: L = v450 - v451;
            let v453: L = v442 * v425;
            let v454: L = v452 + v453;
            let v455: L = v454 * v385;
            let v456: L = v395 * v334;
            let v457: L = v383 * v456;
            let v458: L = v455 + v457;
            let v459: L = v434 * v406;
            let v460: L = v442 * v385;
            let v461: L = v459 - v460;
            let v462: L = v434 * v461;
            let v463: L = v458 - v462;
            let v464: L = v424 * v445;
            let v465: L = v463 + v464;
            let v466: L = v431 * v414;
            let v467: L = v465 - v466;
            let v468: L = v411 * v314;
            let v469: L = v467 - v468;
            let v470: L = v401 * v456;
            let v471: L = v411 * v417;
            let v472: L = v470 - v471;
            let v473: L = v442 * v461;
            let v474: L = v472 + v473;
            let v475: L = v454 * v406;
            let v476: L = v474 - v475;
            let v477: L = v424 * v437;
            let v478: L = v476 - v477;
            let v479: L = v427 * v414;
            let v480: L = v478 + v479;
            let v481: L = v454 * v456;
            let v482: L = v434 * v417;
            let v483: L = v442 * v314;
            let v484: L = v482 + v483;
            let v485: L = v424 * v484;
            let v486: L = v481 - v485;
            let v487: L = v427 * v456;
            let v488: L = v454 * v417;
            let v489: L = v487 - v488;
            let v490: L = v442 * v484;
            let v491: L = v489 - v490;
            let v492: L = v424 * v314;
            let v493: L = v434 * v456;
            let v494: L = v492 - v493;
            let v495: L = v424 * v494;
            let v496: L = v491 + v495;
            let v497: L = v424 * v417;
            let v498: L = v442 * v456;
            let v499: L = v497 + v498;
            let v500: L = v424 * v499;
            let v501: L = v431 * v456;
            let v502: L = v500 + v501;
            let v503: L = v434 * v484;
            let v504: L = v502 - v503;
            let v505: L = v454 * v314;
            let v506: L = v504 + v505;
            let v507: L = v442 * v494;
            let v508: L = v427 * v417;
            let v509: L = v507 - v508;
            let v510: L = v442 * v499;
            let v511: L = v431 * v417;
            let v512: L = v510 - v511;
            let v513: L = v434 * v494;
            let v514: L = v512 + v513;
            let v515: L = v427 * v314;
            let v516: L = v514 + v515;
            let v517: L = v434 * v499;
            let v518: L = v431 * v314;
            let v519: L = v517 + v518;
            let v520: L = L::splat(0.09465_f64);
            let v521: L = v520 * v442;
            let v522: L = v434 * v521;
            let v523: L = v520 * v454;
            let v524: L = v522 - v523;
            let v525: L = v524 - v401;
            let v526: L = v520 * v456;
            let v527: L = v406 - v526;
            let v528: L = v525 * v527;
            let v529: L = q[5];
            let (v530, v537): (L, L) = L::sincos(v529);
            let v531: L = v520 * v427;
            let v532: L = v520 * v424;
            let v533: L = v434 * v532;
            let v534: L = v531 + v533;
            let v535: L = v411 + v534;
            let v536: L = v530 * v535;
            let v538: L = v424 * v532;
            let v539: L = v442 * v521;
            let v540: L = v538 + v539;
            let v541: L = v383 - v540;
            let v542: L = v537 * v541;
            let v543: L = v536 + v542;
            let v544: L = v537 * v385;
            let v545: L = v520 * v417;
            let v546: L = v414 - v545;
            let v547: L = v530 * v546;
            let v548: L = v544 + v547;
            let v549: L = v543 * v548;
            let v550: L = v528 + v549;
            let v551: L = v537 * v535;
            let v552: L = v530 * v541;
            let v553: L = v551 - v552;
            let v554: L = v537 * v546;
            let v555: L = v530 * v385;
            let v556: L = v554 - v555;
            let v557: L = v553 * v556;
            let v558: L = v550 + v557;
            let v559: L = v543 * v417;
            let v560: L = v530 * v454;
            let v561: L = v537 * v431;
            let v562: L = v560 + v561;
            let v563: L = v537 * v424;
            let v564: L = v530 * v434;
            let v565: L = v563 - v564;
            let v566: L = qd[5];
            let v567: L = v565 * v566;
            let v568: L = v562 + v567;
            let v569: L = v568 * v527;
            let v570: L = v559 + v569;
            let v571: L = qdd[5];
            let v572: L = v427 + v571;
            let v573: L = v572 * v548;
            let v574: L = v570 - v573;
            let v575: L = v530 * v424;
            let v576: L = v537 * v434;
            let v577: L = v575 + v576;
            let v578: L = v565 * v548;
            let v579: L = v577 * v556;
            let v580: L = v578 - v579;
            let v581: L = v577 * v580;
            (
                v388,
                v395,
                v401,
                v411,
                v416,
                v417,
                v424,
                v427,
                v431,
                v434,
                v442,
                v449,
                v454,
                v456,
                v469,
                v480,
                v486,
                v496,
                v506,
                v509,
                v516,
                v519,
                v520,
                v525,
                v527,
                v530,
                v537,
                v543,
                v548,
                v553,
                v556,
                v558,
                v565,
                v566,
                v568,
                v572,
                v574,
                v577,
                v580,
                v581,
            )
        };
        let (
            v583,
            v593,
            v598,
            v615,
            v626,
            v632,
            v642,
            v652,
            v655,
            v662,
            v665,
            v666,
            v667,
            v669,
            v672,
            v673,
            v675,
            v680,
            v691,
            v699,
            v705,
            v707,
            v709,
            v712,
            v714,
            v715,
            v719,
            v725,
            v735,
            v743,
            v750,
            v751,
            v753,
            v756,
            v758,
            v760,
            v762,
            v765,
            v767,
            v770,
            v772,
            v775,
        ) = {
            let v582: L = v574 + v581;
            let v583: L = v442 + v566;
            let v584: L = v583 * v556;
            let v585: L = v565 * v527;
            let v586: L = v584 - v585;
            let v587: L = v583 * v586;
            let v588: L = v582 - v587;
            let v589: L = v530 * v456;
            let v590: L = v537 * v314;
            let v591: L = v589 + v590;
            let v592: L = v525 * v591;
            let v593: L = v588 + v592;
            let v594: L = v537 * v454;
            let v595: L = v530 * v431;
            let v596: L = v594 - v595;
            let v597: L = v577 * v566;
            let v598: L = v596 - v597;
            let v599: L = v598 * v548;
            let v600: L = v577 * v527;
            let v601: L = v583 * v548;
            let v602: L = v600 - v601;
            let v603: L = v577 * v602;
            let v604: L = v599 - v603;
            let v605: L = v565 * v586;
            let v606: L = v604 + v605;
            let v607: L = v568 * v556;
            let v608: L = v606 - v607;
            let v609: L = v537 * v456;
            let v610: L = v530 * v314;
            let v611: L = v609 - v610;
            let v612: L = v543 * v611;
            let v613: L = v608 + v612;
            let v614: L = v553 * v591;
            let v615: L = v613 - v614;
            let v616: L = v583 * v602;
            let v617: L = v553 * v417;
            let v618: L = v598 * v527;
            let v619: L = v617 + v618;
            let v620: L = v616 - v619;
            let v621: L = v565 * v580;
            let v622: L = v620 - v621;
            let v623: L = v572 * v556;
            let v624: L = v622 + v623;
            let v625: L = v525 * v611;
            let v626: L = v624 - v625;
            let v627: L = v598 * v611;
            let v628: L = v577 * v417;
            let v629: L = v583 * v591;
            let v630: L = v628 + v629;
            let v631: L = v565 * v630;
            let v632: L = v627 - v631;
            let v633: L = v572 * v611;
            let v634: L = v598 * v417;
            let v635: L = v633 - v634;
            let v636: L = v583 * v630;
            let v637: L = v635 - v636;
            let v638: L = v565 * v591;
            let v639: L = v577 * v611;
            let v640: L = v638 - v639;
            let v641: L = v565 * v640;
            let v642: L = v637 + v641;
            let v643: L = v565 * v417;
            let v644: L = v583 * v611;
            let v645: L = v643 + v644;
            let v646: L = v565 * v645;
            let v647: L = v568 * v611;
            let v648: L = v646 + v647;
            let v649: L = v577 * v630;
            let v650: L = v648 - v649;
            let v651: L = v598 * v591;
            let v652: L = v650 + v651;
            let v653: L = v583 * v640;
            let v654: L = v572 * v417;
            let v655: L = v653 - v654;
            let v656: L = v583 * v645;
            let v657: L = v568 * v417;
            let v658: L = v656 - v657;
            let v659: L = v577 * v640;
            let v660: L = v658 + v659;
            let v661: L = v572 * v591;
            let v662: L = v660 + v661;
            let v663: L = v577 * v645;
            let v664: L = v568 * v591;
            let v665: L = v663 + v664;
            let v666: L = -v29;
            let v667: L = v7 * v20;
            let v668: L = v8 * v20;
            let v669: L = v23 - v668;
            let v670: L = v20 * v20;
            let v671: L = v7 * v7;
            let v672: L = v670 - v671;
            let v673: L = -v4;
            let v674: L = v20 * v7;
            let v675: L = -v674;
            let v676: L = v100 * v99;
            let v677: L = v130 * v676;
            let v678: L = v100 * v107;
            let v679: L = v166 * v678;
            let v680: L = v677 + v679;
            let v681: L = v116 * v676;
            let v682: L = v116 * v681;
            let v683: L = v166 + v682;
            let v684: L = v146 * v676;
            let v685: L = v120 * v678;
            let v686: L = v684 + v685;
            let v687: L = v146 * v686;
            let v688: L = v683 + v687;
            let v689: L = v191 * v678;
            let v690: L = v688 + v689;
            let v691: L = -v690;
            let v692: L = v120 * v681;
            let v693: L = v127 * v676;
            let v694: L = v692 - v693;
            let v695: L = v116 * v678;
            let v696: L = v146 * v695;
            let v697: L = v694 - v696;
            let v698: L = v162 * v678;
            let v699: L = v697 + v698;
            let v700: L = v191 * v676;
            let v701: L = v130 + v700;
            let v702: L = v116 * v695;
            let v703: L = v701 - v702;
            let v704: L = v120 * v686;
            let v705: L = v703 - v704;
            let v706: L = v120 * v146;
            let v707: L = -v706;
            let v708: L = v116 * v146;
            let v709: L = v162 - v708;
            let v710: L = v146 * v146;
            let v711: L = v120 * v120;
            let v712: L = v710 - v711;
            let v713: L = v116 * v120;
            let v714: L = v127 - v713;
            let v715: L = v146 * v120;
            let v716: L = v249 + v676;
            let v717: L = v248 * v716;
            let v718: L = v256 * v678;
            let v719: L = v717 - v718;
            let v720: L = v263 * v719;
            let v721: L = v256 * v716;
            let v722: L = v248 * v678;
            let v723: L = v721 + v722;
            let v724: L = v270 * v723;
            let v725: L = v720 + v724;
            let v726: L = v289 * v719;
            let v727: L = v286 * v723;
            let v728: L = v726 + v727;
            let v729: L = v286 * v728;
            let v730: L = v295 * v719;
            let v731: L = v263 + v730;
            let v732: L = v729 - v731;
            let v733: L = v299 * v723;
            let v734: L = v299 * v733;
            let v735: L = v732 + v734;
            let v736: L = v309 * v723;
            let v737: L = v322 * v719;
            let v738: L = v736 - v737;
            let v739: L = v289 * v733;
            let v740: L = v738 - v739;
            let v741: L = v299 * v719;
            let v742: L = v286 * v741;
            let v743: L = v740 + v742;
            let v744: L = v289 * v728;
            let v745: L = v270 + v744;
            let v746: L = v295 * v723;
            let v747: L = v745 + v746;
            let v748: L = v299 * v741;
            let v749: L = v747 + v748;
            let v750: L = -v749;
            let v751: L = v289 * v286;
            let v752: L = v299 * v286;
            let v753: L = v752 - v322;
            let v754: L = v286 * v286;
            let v755: L = v289 * v289;
            let v756: L = v754 - v755;
            let v757: L = v299 * v289;
            let v758: L = v309 - v757;
            let v759: L = v286 * v289;
            let v760: L = -v759;
            let v761: L = v383 * v719;
            let v762: L = v388 * v723;
            let v763: L = v401 * v762;
            let v764: L = v761 - v763;
            let v765: L = v395 * v723;
            let v766: L = v411 * v765;
            let v767: L = v764 - v766;
            let v768: L = v431 * v762;
            let v769: L = v427 * v719;
            let v770: L = v383 * v395;
            let v771: L = v769 + v770;
            let v772: L = v768 - v771;
            let v773: L = v424 * v719;
            let v774: L = v434 * v765;
            let v775: L = v773 + v774;
            (
                v583,
                v593,
                v598,
                v615,
                v626,
                v632,
                v642,
                v652,
                v655,
                v662,
                v665,
                v666,
                v667,
                v669,
                v672,
                v673,
                v675,
                v680,
                v691,
                v699,
                v705,
                v707,
                v709,
                v712,
                v714,
                v715,
                v719,
                v725,
                v735,
                v743,
                v750,
                v751,
                v753,
                v756,
                v758,
                v760,
                v762,
                v765,
                v767,
                v770,
                v772,
                v775,
            )
        };
        let (
            v782,
            v784,
            v794,
            v797,
            v805,
            v809,
            v817,
            v825,
            v828,
            v833,
            v834,
            v835,
            v839,
            v849,
            v851,
            v866,
            v867,
            v879,
            v881,
            v882,
            v883,
            v892,
            v893,
            v899,
            v909,
            v919,
            v922,
            v929,
            v932,
            v933,
            v934,
            v939,
            v949,
            v957,
            v963,
            v965,
            v967,
            v968,
            v969,
        ) = {
            let v776: L = v434 * v775;
            let v777: L = v772 + v776;
            let v778: L = v424 * v762;
            let v779: L = v442 * v765;
            let v780: L = v778 + v779;
            let v781: L = v442 * v780;
            let v782: L = v777 + v781;
            let v783: L = v454 * v719;
            let v784: L = v383 * v388;
            let v785: L = v783 + v784;
            let v786: L = v434 * v762;
            let v787: L = v442 * v719;
            let v788: L = v786 - v787;
            let v789: L = v434 * v788;
            let v790: L = v785 - v789;
            let v791: L = v424 * v780;
            let v792: L = v790 - v791;
            let v793: L = v431 * v765;
            let v794: L = v792 + v793;
            let v795: L = v411 * v395;
            let v796: L = v401 * v388;
            let v797: L = v795 + v796;
            let v798: L = v442 * v788;
            let v799: L = v797 + v798;
            let v800: L = v454 * v762;
            let v801: L = v799 - v800;
            let v802: L = v424 * v775;
            let v803: L = v801 - v802;
            let v804: L = v427 * v765;
            let v805: L = v803 - v804;
            let v806: L = v454 * v388;
            let v807: L = v434 * v395;
            let v808: L = v424 * v807;
            let v809: L = v806 + v808;
            let v810: L = v454 * v395;
            let v811: L = v427 * v388;
            let v812: L = v810 + v811;
            let v813: L = v442 * v807;
            let v814: L = v812 + v813;
            let v815: L = v434 * v388;
            let v816: L = v424 * v815;
            let v817: L = v814 - v816;
            let v818: L = v442 * v388;
            let v819: L = v424 * v395;
            let v820: L = v818 - v819;
            let v821: L = v424 * v820;
            let v822: L = v431 * v388;
            let v823: L = v821 + v822;
            let v824: L = v434 * v807;
            let v825: L = v823 + v824;
            let v826: L = v427 * v395;
            let v827: L = v442 * v815;
            let v828: L = v826 - v827;
            let v829: L = v431 * v395;
            let v830: L = v442 * v820;
            let v831: L = v829 + v830;
            let v832: L = v434 * v815;
            let v833: L = v831 - v832;
            let v834: L = v434 * v820;
            let v835: L = v520 * v388;
            let v836: L = v762 - v835;
            let v837: L = v525 * v836;
            let v838: L = v537 * v719;
            let v839: L = v520 * v395;
            let v840: L = v839 - v765;
            let v841: L = v530 * v840;
            let v842: L = v838 + v841;
            let v843: L = v543 * v842;
            let v844: L = v837 + v843;
            let v845: L = v537 * v840;
            let v846: L = v530 * v719;
            let v847: L = v845 - v846;
            let v848: L = v553 * v847;
            let v849: L = v844 + v848;
            let v850: L = v568 * v836;
            let v851: L = v543 * v395;
            let v852: L = v850 - v851;
            let v853: L = v572 * v842;
            let v854: L = v852 - v853;
            let v855: L = v565 * v842;
            let v856: L = v577 * v847;
            let v857: L = v855 - v856;
            let v858: L = v577 * v857;
            let v859: L = v854 + v858;
            let v860: L = v583 * v847;
            let v861: L = v565 * v836;
            let v862: L = v860 - v861;
            let v863: L = v583 * v862;
            let v864: L = v859 - v863;
            let v865: L = v530 * v388;
            let v866: L = v525 * v865;
            let v867: L = v864 + v866;
            let v868: L = v598 * v842;
            let v869: L = v577 * v836;
            let v870: L = v583 * v842;
            let v871: L = v869 - v870;
            let v872: L = v577 * v871;
            let v873: L = v868 - v872;
            let v874: L = v565 * v862;
            let v875: L = v873 + v874;
            let v876: L = v568 * v847;
            let v877: L = v875 - v876;
            let v878: L = v537 * v388;
            let v879: L = v543 * v878;
            let v880: L = v877 + v879;
            let v881: L = v553 * v865;
            let v882: L = v880 - v881;
            let v883: L = v553 * v395;
            let v884: L = v598 * v836;
            let v885: L = v883 - v884;
            let v886: L = v583 * v871;
            let v887: L = v885 + v886;
            let v888: L = v565 * v857;
            let v889: L = v887 - v888;
            let v890: L = v572 * v847;
            let v891: L = v889 + v890;
            let v892: L = v525 * v878;
            let v893: L = v891 - v892;
            let v894: L = v598 * v878;
            let v895: L = v577 * v395;
            let v896: L = v583 * v865;
            let v897: L = v895 - v896;
            let v898: L = v565 * v897;
            let v899: L = v894 + v898;
            let v900: L = v598 * v395;
            let v901: L = v572 * v878;
            let v902: L = v900 + v901;
            let v903: L = v583 * v897;
            let v904: L = v902 + v903;
            let v905: L = v565 * v865;
            let v906: L = v577 * v878;
            let v907: L = v905 - v906;
            let v908: L = v565 * v907;
            let v909: L = v904 + v908;
            let v910: L = v583 * v878;
            let v911: L = v565 * v395;
            let v912: L = v910 - v911;
            let v913: L = v565 * v912;
            let v914: L = v568 * v878;
            let v915: L = v913 + v914;
            let v916: L = v577 * v897;
            let v917: L = v915 + v916;
            let v918: L = v598 * v865;
            let v919: L = v917 + v918;
            let v920: L = v572 * v395;
            let v921: L = v583 * v907;
            let v922: L = v920 + v921;
            let v923: L = v568 * v395;
            let v924: L = v583 * v912;
            let v925: L = v923 + v924;
            let v926: L = v577 * v907;
            let v927: L = v925 + v926;
            let v928: L = v572 * v865;
            let v929: L = v927 + v928;
            let v930: L = v577 * v912;
            let v931: L = v568 * v865;
            let v932: L = v930 + v931;
            let v933: L = -v166;
            let v934: L = v249 * v248;
            let v935: L = v263 * v934;
            let v936: L = -L::splat(0.39225_f64);
            let v937: L = v936 * v256;
            let v938: L = v270 * v937;
            let v939: L = v935 - v938;
            let v940: L = v289 * v934;
            let v941: L = v286 * v937;
            let v942: L = v940 - v941;
            let v943: L = v286 * v942;
            let v944: L = v295 * v934;
            let v945: L = v263 + v944;
            let v946: L = v943 - v945;
            let v947: L = v299 * v937;
            let v948: L = v299 * v947;
            let v949: L = v946 - v948;
            let v950: L = v289 * v947;
            let v951: L = v322 * v934;
            let v952: L = v309 * v937;
            let v953: L = v951 + v952;
            let v954: L = v950 - v953;
            let v955: L = v299 * v934;
            let v956: L = v286 * v955;
            let v957: L = v954 + v956;
            let v958: L = v295 * v937;
            let v959: L = v289 * v942;
            let v960: L = v270 + v959;
            let v961: L = v958 - v960;
            let v962: L = v299 * v955;
            let v963: L = v961 - v962;
            let v964: L = v383 * v934;
            let v965: L = v388 * v937;
            let v966: L = v401 * v965;
            let v967: L = v964 + v966;
            let v968: L = v395 * v937;
            let v969: L = v411 * v968;
            (
                v782,
                v784,
                v794,
                v797,
                v805,
                v809,
                v817,
                v825,
                v828,
                v833,
                v834,
                v835,
                v839,
                v849,
                v851,
                v866,
                v867,
                v879,
                v881,
                v882,
                v883,
                v892,
                v893,
                v899,
                v909,
                v919,
                v922,
                v929,
                v932,
                v933,
                v934,
                v939,
                v949,
                v957,
                v963,
                v965,
                v967,
                v968,
                v969,
            )
        };
        let (
            v970,
            v984,
            v995,
            v1003,
            v1016,
            v1031,
            v1043,
            v1052,
            v1053,
            v1054,
            v1055,
            v1062,
            v1077,
            v1089,
            v1098,
            v1099,
            v1100,
            v1102,
            v1105,
            v1107,
            v1108,
            v1110,
            v1111,
            v1115,
            v1116,
            v1121,
            v1129,
            v1137,
            v1138,
            v1143,
            v1146,
            v1147,
            v1148,
            v1150,
            v1153,
            v1155,
            v1157,
            v1158,
        ) = {
            let v970: L = v967 + v969;
            let v971: L = v424 * v934;
            let v972: L = v434 * v968;
            let v973: L = v971 - v972;
            let v974: L = v434 * v973;
            let v975: L = v427 * v934;
            let v976: L = v975 + v770;
            let v977: L = v431 * v965;
            let v978: L = v976 + v977;
            let v979: L = v974 - v978;
            let v980: L = v424 * v965;
            let v981: L = v442 * v968;
            let v982: L = v980 + v981;
            let v983: L = v442 * v982;
            let v984: L = v979 - v983;
            let v985: L = v454 * v934;
            let v986: L = v985 + v784;
            let v987: L = v442 * v934;
            let v988: L = v434 * v965;
            let v989: L = v987 + v988;
            let v990: L = v434 * v989;
            let v991: L = v986 + v990;
            let v992: L = v424 * v982;
            let v993: L = v991 + v992;
            let v994: L = v431 * v968;
            let v995: L = v993 - v994;
            let v996: L = v442 * v989;
            let v997: L = v797 - v996;
            let v998: L = v454 * v965;
            let v999: L = v997 + v998;
            let v1000: L = v424 * v973;
            let v1001: L = v999 - v1000;
            let v1002: L = v427 * v968;
            let v1003: L = v1001 + v1002;
            let v1004: L = v537 * v934;
            let v1005: L = v839 + v968;
            let v1006: L = v530 * v1005;
            let v1007: L = v1004 + v1006;
            let v1008: L = v543 * v1007;
            let v1009: L = v835 + v965;
            let v1010: L = v525 * v1009;
            let v1011: L = v1008 - v1010;
            let v1012: L = v537 * v1005;
            let v1013: L = v530 * v934;
            let v1014: L = v1012 - v1013;
            let v1015: L = v553 * v1014;
            let v1016: L = v1011 + v1015;
            let v1017: L = v565 * v1007;
            let v1018: L = v577 * v1014;
            let v1019: L = v1017 - v1018;
            let v1020: L = v577 * v1019;
            let v1021: L = v568 * v1009;
            let v1022: L = v851 + v1021;
            let v1023: L = v572 * v1007;
            let v1024: L = v1022 + v1023;
            let v1025: L = v1020 - v1024;
            let v1026: L = v565 * v1009;
            let v1027: L = v583 * v1014;
            let v1028: L = v1026 + v1027;
            let v1029: L = v583 * v1028;
            let v1030: L = v1025 - v1029;
            let v1031: L = v1030 + v866;
            let v1032: L = v577 * v1009;
            let v1033: L = v583 * v1007;
            let v1034: L = v1032 + v1033;
            let v1035: L = v577 * v1034;
            let v1036: L = v598 * v1007;
            let v1037: L = v1035 + v1036;
            let v1038: L = v565 * v1028;
            let v1039: L = v1037 + v1038;
            let v1040: L = v568 * v1014;
            let v1041: L = v1039 - v1040;
            let v1042: L = v1041 + v879;
            let v1043: L = v1042 - v881;
            let v1044: L = v598 * v1009;
            let v1045: L = v883 + v1044;
            let v1046: L = v583 * v1034;
            let v1047: L = v1045 - v1046;
            let v1048: L = v565 * v1019;
            let v1049: L = v1047 - v1048;
            let v1050: L = v572 * v1014;
            let v1051: L = v1049 + v1050;
            let v1052: L = v1051 - v892;
            let v1053: L = -v263;
            let v1054: L = -v270;
            let v1055: L = -v770;
            let v1056: L = v530 * v839;
            let v1057: L = v543 * v1056;
            let v1058: L = v525 * v835;
            let v1059: L = v1057 - v1058;
            let v1060: L = v537 * v839;
            let v1061: L = v553 * v1060;
            let v1062: L = v1059 + v1061;
            let v1063: L = v565 * v1056;
            let v1064: L = v577 * v1060;
            let v1065: L = v1063 - v1064;
            let v1066: L = v577 * v1065;
            let v1067: L = v568 * v835;
            let v1068: L = v851 + v1067;
            let v1069: L = v572 * v1056;
            let v1070: L = v1068 + v1069;
            let v1071: L = v1066 - v1070;
            let v1072: L = v565 * v835;
            let v1073: L = v583 * v1060;
            let v1074: L = v1072 + v1073;
            let v1075: L = v583 * v1074;
            let v1076: L = v1071 - v1075;
            let v1077: L = v1076 + v866;
            let v1078: L = v577 * v835;
            let v1079: L = v583 * v1056;
            let v1080: L = v1078 + v1079;
            let v1081: L = v577 * v1080;
            let v1082: L = v598 * v1056;
            let v1083: L = v1081 + v1082;
            let v1084: L = v565 * v1074;
            let v1085: L = v1083 + v1084;
            let v1086: L = v568 * v1060;
            let v1087: L = v1085 - v1086;
            let v1088: L = v1087 + v879;
            let v1089: L = v1088 - v881;
            let v1090: L = v598 * v835;
            let v1091: L = v883 + v1090;
            let v1092: L = v583 * v1080;
            let v1093: L = v1091 - v1092;
            let v1094: L = v565 * v1065;
            let v1095: L = v1093 - v1094;
            let v1096: L = v572 * v1060;
            let v1097: L = v1095 + v1096;
            let v1098: L = v1097 - v892;
            let v1099: L = -v401;
            let v1100: L = -v411;
            let v1101: L = v424 * v442;
            let v1102: L = -v1101;
            let v1103: L = v424 * v424;
            let v1104: L = v442 * v442;
            let v1105: L = v1103 - v1104;
            let v1106: L = v434 * v442;
            let v1107: L = v454 - v1106;
            let v1108: L = v442 * v424;
            let v1109: L = v434 * v424;
            let v1110: L = v1109 + v427;
            let v1111: L = v525 * v537;
            let v1112: L = v543 * v530;
            let v1113: L = v553 * v537;
            let v1114: L = v1112 + v1113;
            let v1115: L = -v1114;
            let v1116: L = v525 * v530;
            let v1117: L = v598 * v530;
            let v1118: L = v583 * v537;
            let v1119: L = v565 * v1118;
            let v1120: L = v1117 + v1119;
            let v1121: L = -v1120;
            let v1122: L = v577 * v530;
            let v1123: L = v565 * v537;
            let v1124: L = v1122 + v1123;
            let v1125: L = v565 * v1124;
            let v1126: L = v572 * v530;
            let v1127: L = v583 * v1118;
            let v1128: L = v1126 + v1127;
            let v1129: L = v1125 - v1128;
            let v1130: L = v598 * v537;
            let v1131: L = v583 * v530;
            let v1132: L = v565 * v1131;
            let v1133: L = v568 * v530;
            let v1134: L = v1132 + v1133;
            let v1135: L = v577 * v1118;
            let v1136: L = v1134 + v1135;
            let v1137: L = v1130 - v1136;
            let v1138: L = v583 * v1124;
            let v1139: L = v577 * v1124;
            let v1140: L = v583 * v1131;
            let v1141: L = v1139 - v1140;
            let v1142: L = v572 * v537;
            let v1143: L = v1141 + v1142;
            let v1144: L = v568 * v537;
            let v1145: L = v577 * v1131;
            let v1146: L = v1144 - v1145;
            let v1147: L = -v543;
            let v1148: L = v565 * v577;
            let v1149: L = v583 * v577;
            let v1150: L = v598 + v1149;
            let v1151: L = v577 * v577;
            let v1152: L = v565 * v565;
            let v1153: L = v1151 - v1152;
            let v1154: L = v583 * v565;
            let v1155: L = v568 - v1154;
            let v1156: L = v577 * v565;
            let v1157: L = -v1156;
            let v1158: L = L::splat(0.0_f64);
            (
                v970,
                v984,
                v995,
                v1003,
                v1016,
                v1031,
                v1043,
                v1052,
                v1053,
                v1054,
                v1055,
                v1062,
                v1077,
                v1089,
                v1098,
                v1099,
                v1100,
                v1102,
                v1105,
                v1107,
                v1108,
                v1110,
                v1111,
                v1115,
                v1116,
                v1121,
                v1129,
                v1137,
                v1138,
                v1143,
                v1146,
                v1147,
                v1148,
                v1150,
                v1153,
                v1155,
                v1157,
                v1158,
            )
        };
        [
            [
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v0,
                v32,
                v47,
                v59,
                v66,
                v71,
                v79,
                v87,
                v88,
                v94,
                v97,
                v176,
                v193,
                v207,
                v216,
                v220,
                v228,
                v236,
                v237,
                v242,
                v246,
                v283,
                v316,
                v338,
                v347,
                v352,
                v360,
                v368,
                v369,
                v374,
                v377,
                v416,
                v449,
                v469,
                v480,
                v486,
                v496,
                v506,
                v509,
                v516,
                v519,
                v558,
                v593,
                v615,
                v626,
                v632,
                v642,
                v652,
                v655,
                v662,
                v665,
            ],
            [
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v666,
                v1158,
                v17,
                v667,
                v669,
                v672,
                v45,
                v673,
                v675,
                v680,
                v691,
                v699,
                v705,
                v707,
                v709,
                v712,
                v191,
                v714,
                v715,
                v725,
                v735,
                v743,
                v750,
                v751,
                v753,
                v756,
                v295,
                v758,
                v760,
                v767,
                v782,
                v794,
                v805,
                v809,
                v817,
                v825,
                v828,
                v833,
                v834,
                v849,
                v867,
                v882,
                v893,
                v899,
                v909,
                v919,
                v922,
                v929,
                v932,
            ],
            [
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v933,
                v1158,
                v130,
                v707,
                v709,
                v712,
                v191,
                v714,
                v715,
                v939,
                v949,
                v957,
                v963,
                v751,
                v753,
                v756,
                v295,
                v758,
                v760,
                v970,
                v984,
                v995,
                v1003,
                v809,
                v817,
                v825,
                v828,
                v833,
                v834,
                v1016,
                v1031,
                v1043,
                v1052,
                v899,
                v909,
                v919,
                v922,
                v929,
                v932,
            ],
            [
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1053,
                v1158,
                v1054,
                v751,
                v753,
                v756,
                v295,
                v758,
                v760,
                v1158,
                v1055,
                v784,
                v797,
                v809,
                v817,
                v825,
                v828,
                v833,
                v834,
                v1062,
                v1077,
                v1089,
                v1098,
                v899,
                v909,
                v919,
                v922,
                v929,
                v932,
            ],
            [
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1099,
                v1100,
                v1158,
                v1102,
                v1105,
                v1107,
                v1108,
                v1110,
                v431,
                v1158,
                v1111,
                v1115,
                v1116,
                v1121,
                v1129,
                v1137,
                v1138,
                v1143,
                v1146,
            ],
            [
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1158,
                v1147,
                v1158,
                v553,
                v1148,
                v1150,
                v1153,
                v572,
                v1155,
                v1157,
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
    /// `params: [L; 60]`: per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2, inertia about the link frame origin)
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
    pub fn standard_parameters<L: crate::lanes::Lane>() -> [L; 60] {
        let v0: L = L::splat(3.7_f64);
        let v1: L = L::splat(0.0_f64);
        let v2: L = L::splat(0.010267495893_f64);
        let v3: L = L::splat(0.00666_f64);
        let v4: L = L::splat(8.393_f64);
        let v5: L = L::splat(2.35004_f64);
        let v6: L = L::splat(0.88490187591_f64);
        let v7: L = L::splat(0.0151074_f64);
        let v8: L = L::splat(2.275_f64);
        let v9: L = L::splat(0.56875_f64);
        let v10: L = L::splat(0.191630813556_f64);
        let v11: L = L::splat(0.004095_f64);
        let v12: L = L::splat(1.219_f64);
        let v13: L = L::splat(0.111172755531_f64);
        let v14: L = L::splat(0.21942_f64);
        let v15: L = L::splat(0.1879_f64);
        let v16: L = L::splat(0.0171364731454_f64);
        let v17: L = L::splat(0.033822_f64);
        [
            v0,
            v1,
            v1,
            v1,
            v2,
            v1,
            v1,
            v2,
            v1,
            v3,
            v4,
            v1,
            v1,
            v5,
            v6,
            v1,
            v1,
            v6,
            v1,
            v7,
            v8,
            v1,
            v1,
            v9,
            v10,
            v1,
            v1,
            v10,
            v1,
            v11,
            v12,
            v1,
            v1,
            v1,
            v13,
            v1,
            v1,
            v13,
            v1,
            v14,
            v12,
            v1,
            v1,
            v1,
            v13,
            v1,
            v1,
            v13,
            v1,
            v14,
            v15,
            v1,
            v1,
            v1,
            v16,
            v1,
            v1,
            v16,
            v1,
            v17,
        ]
    }
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/ur5.json")
);
