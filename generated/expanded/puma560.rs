// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `scara_derive::robot_model!("models/puma560.json", f32, lanes)` in the `generated` crate,
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
pub const OPERATION_COUNTS: [(&str, u32, u32); 14] = [
    ("frame_poses", 115, 12),
    ("end_effector_pose", 102, 12),
    ("jacobian", 73, 10),
    ("jacobian_and_position", 78, 10),
    ("jdot_qd", 208, 10),
    ("mass_matrix", 263, 8),
    ("coriolis_matrix", 1471, 8),
    ("coriolis", 479, 10),
    ("gravity", 39, 8),
    ("inverse_dynamics", 519, 10),
    ("forward_dynamics", 867, 10),
    ("mass_matrix_and_bias", 746, 10),
    ("regressor", 1216, 10),
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
    let (v3, v1): (f64, f64) = ::libm::sincos(v0);
    let v2: f64 = 0.0_f64;
    let v4: f64 = -v1;
    let v5: f64 = 1.0_f64;
    let v6: f64 = 0.6718_f64;
    let v7: f64 = q[1];
    let (v10, v8): (f64, f64) = ::libm::sincos(v7);
    let v9: f64 = v1 * v8;
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
    let (v25, v23): (f64, f64) = ::libm::sincos(v22);
    let v24: f64 = v9 * v23;
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
    let (v69, v67): (f64, f64) = ::libm::sincos(v66);
    let v68: f64 = v27 * v67;
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
    let (v92, v90): (f64, f64) = ::libm::sincos(v89);
    let v91: f64 = v71 * v90;
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
    let (v118, v116): (f64, f64) = ::libm::sincos(v115);
    let v117: f64 = v94 * v116;
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
/// `pose: [[f64; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the base frame (m)
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
    let (v1, v5): (f64, f64) = ::libm::sincos(v0);
    let v2: f64 = q[1];
    let (v3, v6): (f64, f64) = ::libm::sincos(v2);
    let v4: f64 = v1 * v3;
    let v7: f64 = v5 * v6;
    let v8: f64 = v4 - v7;
    let v9: f64 = q[5];
    let (v10, v29): (f64, f64) = ::libm::sincos(v9);
    let v11: f64 = v8 * v10;
    let v12: f64 = q[3];
    let (v13, v17): (f64, f64) = ::libm::sincos(v12);
    let v14: f64 = v11 * v13;
    let v15: f64 = q[4];
    let (v20, v16): (f64, f64) = ::libm::sincos(v15);
    let v18: f64 = v16 * v17;
    let v19: f64 = v18 * v5;
    let v21: f64 = v20 * v1;
    let v22: f64 = v19 - v21;
    let v23: f64 = v22 * v6;
    let v24: f64 = v20 * v5;
    let v25: f64 = v18 * v1;
    let v26: f64 = v24 + v25;
    let v27: f64 = v26 * v3;
    let v28: f64 = v23 - v27;
    let v30: f64 = v28 * v29;
    let v31: f64 = v14 + v30;
    let v32: f64 = q[0];
    let (v39, v33): (f64, f64) = ::libm::sincos(v32);
    let v34: f64 = v31 * v33;
    let v35: f64 = v10 * v17;
    let v36: f64 = v29 * v16;
    let v37: f64 = v36 * v13;
    let v38: f64 = v35 + v37;
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
    let (v23, v2): (f64, f64) = ::libm::sincos(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = 0.4318_f64;
    let v5: f64 = q[2];
    let (v9, v6): (f64, f64) = ::libm::sincos(v5);
    let v7: f64 = v4 * v6;
    let v8: f64 = 0.0203_f64;
    let v10: f64 = v8 * v9;
    let v11: f64 = v7 + v10;
    let v12: f64 = q[1];
    let (v13, v20): (f64, f64) = ::libm::sincos(v12);
    let v14: f64 = v11 * v13;
    let v15: f64 = -0.4318_f64;
    let v16: f64 = v8 * v6;
    let v17: f64 = v15 - v16;
    let v18: f64 = v4 * v9;
    let v19: f64 = v17 + v18;
    let v21: f64 = v19 * v20;
    let v22: f64 = v14 + v21;
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
    let (v58, v53): (f64, f64) = ::libm::sincos(v52);
    let v54: f64 = v53 * v23;
    let v55: f64 = v6 * v20;
    let v56: f64 = v9 * v13;
    let v57: f64 = v55 - v56;
    let v59: f64 = v57 * v58;
    let v60: f64 = v59 * v2;
    let v61: f64 = v54 + v60;
    let v62: f64 = q[4];
    let (v63, v68): (f64, f64) = ::libm::sincos(v62);
    let v64: f64 = v63 * v58;
    let v65: f64 = v64 * v23;
    let v66: f64 = v63 * v53;
    let v67: f64 = v66 * v9;
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
/// Operation count: 78 floating-point operations, 10 trig calls.
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
    let v0: f64 = 0.15005_f64;
    let v1: f64 = q[0];
    let (v23, v2): (f64, f64) = ::libm::sincos(v1);
    let v3: f64 = v0 * v2;
    let v4: f64 = 0.4318_f64;
    let v5: f64 = q[2];
    let (v9, v6): (f64, f64) = ::libm::sincos(v5);
    let v7: f64 = v4 * v6;
    let v8: f64 = 0.0203_f64;
    let v10: f64 = v8 * v9;
    let v11: f64 = v7 + v10;
    let v12: f64 = q[1];
    let (v13, v20): (f64, f64) = ::libm::sincos(v12);
    let v14: f64 = v11 * v13;
    let v15: f64 = -0.4318_f64;
    let v16: f64 = v8 * v6;
    let v17: f64 = v15 - v16;
    let v18: f64 = v4 * v9;
    let v19: f64 = v17 + v18;
    let v21: f64 = v19 * v20;
    let v22: f64 = v14 + v21;
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
    let v44: f64 = v39 * v23;
    let v45: f64 = v44 - v3;
    let v46: f64 = v16 - v18;
    let v47: f64 = v46 * v20;
    let v48: f64 = v47 - v14;
    let v49: f64 = 0.6718_f64;
    let v50: f64 = v49 + v27;
    let v51: f64 = v37 * v13;
    let v52: f64 = v50 + v51;
    let v53: f64 = v9 * v20;
    let v54: f64 = v6 * v13;
    let v55: f64 = v53 + v54;
    let v56: f64 = v55 * v2;
    let v57: f64 = -v56;
    let v58: f64 = q[3];
    let (v64, v59): (f64, f64) = ::libm::sincos(v58);
    let v60: f64 = v59 * v23;
    let v61: f64 = v6 * v20;
    let v62: f64 = v9 * v13;
    let v63: f64 = v61 - v62;
    let v65: f64 = v63 * v64;
    let v66: f64 = v65 * v2;
    let v67: f64 = v60 + v66;
    let v68: f64 = q[4];
    let (v69, v74): (f64, f64) = ::libm::sincos(v68);
    let v70: f64 = v69 * v64;
    let v71: f64 = v70 * v23;
    let v72: f64 = v69 * v59;
    let v73: f64 = v72 * v9;
    let v75: f64 = v74 * v6;
    let v76: f64 = v73 - v75;
    let v77: f64 = v76 * v13;
    let v78: f64 = v72 * v6;
    let v79: f64 = v74 * v9;
    let v80: f64 = v78 + v79;
    let v81: f64 = v80 * v20;
    let v82: f64 = v77 - v81;
    let v83: f64 = v82 * v2;
    let v84: f64 = v71 + v83;
    let v85: f64 = -v2;
    let v86: f64 = v55 * v23;
    let v87: f64 = -v86;
    let v88: f64 = v65 * v23;
    let v89: f64 = v59 * v2;
    let v90: f64 = v88 - v89;
    let v91: f64 = v82 * v23;
    let v92: f64 = v70 * v2;
    let v93: f64 = v91 - v92;
    let v94: f64 = 1.0_f64;
    let v95: f64 = v55 * v64;
    let v96: f64 = v75 - v73;
    let v97: f64 = v96 * v20;
    let v98: f64 = v80 * v13;
    let v99: f64 = v97 - v98;
    [
        [v25, v29, v33, v34, v34, v34, v41],
        [v41, v42, v43, v34, v34, v34, v45],
        [v34, v39, v48, v34, v34, v34, v52],
        [v34, v23, v23, v57, v67, v84, v34],
        [v34, v85, v85, v87, v90, v93, v34],
        [v94, v34, v34, v63, v95, v99, v34],
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
        v116,
        v117,
        v121,
    ) = {
        let v0: f64 = 0.8636_f64;
        let v1: f64 = qd[2];
        let v2: f64 = v0 * v1;
        let v3: f64 = qd[1];
        let v4: f64 = v0 * v3;
        let v5: f64 = v2 + v4;
        let v6: f64 = q[2];
        let (v13, v7): (f64, f64) = ::libm::sincos(v6);
        let v8: f64 = v5 * v7;
        let v9: f64 = 0.0406_f64;
        let v10: f64 = v9 * v1;
        let v11: f64 = v9 * v3;
        let v12: f64 = v10 + v11;
        let v14: f64 = v12 * v13;
        let v15: f64 = v8 + v14;
        let v16: f64 = q[1];
        let (v31, v17): (f64, f64) = ::libm::sincos(v16);
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
        let v32: f64 = v30 * v31;
        let v33: f64 = v22 + v32;
        let v34: f64 = v33 * v20;
        let v35: f64 = q[0];
        let (v36, v81): (f64, f64) = ::libm::sincos(v35);
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
        let (v116, v121): (f64, f64) = ::libm::sincos(v115);
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
            v116,
            v117,
            v121,
        )
    };
    let (v196, v212, v235) = {
        let v118: f64 = q[3];
        let (v126, v119): (f64, f64) = ::libm::sincos(v118);
        let v120: f64 = v117 * v119;
        let v122: f64 = v112 * v121;
        let v123: f64 = v122 - v113;
        let v124: f64 = qd[4];
        let v125: f64 = v123 * v124;
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
        let (v15, v3): (f64, f64) = ::libm::sincos(v2);
        let v4: f64 = v1 * v3;
        let v5: f64 = v4 * v3;
        let v6: f64 = v0 - v5;
        let v7: f64 = 0.000864288_f64;
        let v8: f64 = q[3];
        let (v9, v12): (f64, f64) = ::libm::sincos(v8);
        let v10: f64 = v7 * v9;
        let v11: f64 = 0.000116928_f64;
        let v13: f64 = v11 * v12;
        let v14: f64 = v10 - v13;
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
        let (v29, v43): (f64, f64) = ::libm::sincos(v28);
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
        let (v59, v78): (f64, f64) = ::libm::sincos(v58);
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
        v212,
    ) = {
        let v0: f64 = -0.004173999_f64;
        let v1: f64 = 0.010956925_f64;
        let v2: f64 = q[2];
        let (v3, v96): (f64, f64) = ::libm::sincos(v2);
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
        let (v14, v17): (f64, f64) = ::libm::sincos(v13);
        let v15: f64 = v12 * v14;
        let v16: f64 = 5.8464e-05_f64;
        let v18: f64 = v16 * v17;
        let v19: f64 = v15 - v18;
        let v20: f64 = qd[4];
        let v21: f64 = v19 * v20;
        let v22: f64 = v16 * v9;
        let v23: f64 = v16 * v6;
        let v24: f64 = v22 + v23;
        let v25: f64 = v21 - v24;
        let v26: f64 = q[4];
        let (v49, v27): (f64, f64) = ::libm::sincos(v26);
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
        let (v212, v172): (f64, f64) = ::libm::sincos(v171);
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
            v212,
        )
    };
    let (
        v197,
        v201,
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
/// Operation count: 479 floating-point operations, 10 trig calls.
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
        v10,
        v11,
        v14,
        v16,
        v21,
        v24,
        v28,
        v32,
        v33,
        v37,
        v39,
        v41,
        v44,
        v46,
        v47,
        v49,
        v54,
        v57,
        v59,
        v65,
        v67,
        v70,
        v72,
        v75,
        v77,
        v79,
        v85,
        v89,
        v92,
        v96,
        v98,
        v105,
        v107,
        v116,
        v119,
        v121,
        v122,
        v124,
        v127,
        v128,
        v130,
        v132,
        v133,
        v135,
        v136,
        v140,
        v149,
        v154,
        v157,
        v159,
        v161,
        v162,
        v164,
        v170,
        v172,
        v173,
        v175,
        v176,
        v177,
    ) = {
        let v0: f64 = q[1];
        let (v1, v3): (f64, f64) = ::libm::sincos(v0);
        let v2: f64 = 1.03118515_f64;
        let v4: f64 = qd[0];
        let v5: f64 = v3 * v4;
        let v6: f64 = qd[1];
        let v7: f64 = v5 * v6;
        let v8: f64 = v2 * v7;
        let v9: f64 = 0.03798072_f64;
        let v10: f64 = v1 * v4;
        let v11: f64 = v10 * v6;
        let v12: f64 = v9 * v11;
        let v13: f64 = v8 - v12;
        let v14: f64 = 1.4401023_f64;
        let v15: f64 = v14 * v10;
        let v16: f64 = -0.023751_f64;
        let v17: f64 = v16 * v5;
        let v18: f64 = v15 + v17;
        let v19: f64 = 2.842524056_f64;
        let v20: f64 = v19 * v6;
        let v21: f64 = v18 + v20;
        let v22: f64 = v5 * v21;
        let v23: f64 = v9 * v10;
        let v24: f64 = 3.727456406_f64;
        let v25: f64 = v24 * v5;
        let v26: f64 = v23 + v25;
        let v27: f64 = v16 * v6;
        let v28: f64 = v26 + v27;
        let v29: f64 = v6 * v28;
        let v30: f64 = v22 - v29;
        let v31: f64 = v13 + v30;
        let v32: f64 = 0.1044_f64;
        let v33: f64 = 0.4318_f64;
        let v34: f64 = v33 * v11;
        let v35: f64 = v33 * v6;
        let v36: f64 = v10 * v35;
        let v37: f64 = v34 + v36;
        let v38: f64 = v32 * v37;
        let v39: f64 = 3.9585_f64;
        let v40: f64 = v33 * v5;
        let v41: f64 = v10 * v40;
        let v42: f64 = v39 * v41;
        let v43: f64 = v38 - v42;
        let v44: f64 = v31 + v43;
        let v45: f64 = q[2];
        let (v49, v46): (f64, f64) = ::libm::sincos(v45);
        let v47: f64 = 0.090474288_f64;
        let v48: f64 = v46 * v7;
        let v50: f64 = v49 * v11;
        let v51: f64 = v48 - v50;
        let v52: f64 = v46 * v5;
        let v53: f64 = v49 * v10;
        let v54: f64 = v52 - v53;
        let v55: f64 = qd[2];
        let v56: f64 = v54 * v55;
        let v57: f64 = v51 + v56;
        let v58: f64 = v47 * v57;
        let v59: f64 = 0.0068208_f64;
        let v60: f64 = v49 * v7;
        let v61: f64 = v46 * v11;
        let v62: f64 = v60 + v61;
        let v63: f64 = v46 * v10;
        let v64: f64 = v49 * v5;
        let v65: f64 = v63 + v64;
        let v66: f64 = v65 * v55;
        let v67: f64 = v62 + v66;
        let v68: f64 = v59 * v67;
        let v69: f64 = v58 - v68;
        let v70: f64 = v6 + v55;
        let v71: f64 = v59 * v65;
        let v72: f64 = 0.0047376_f64;
        let v73: f64 = v72 * v70;
        let v74: f64 = v71 - v73;
        let v75: f64 = 0.01543232_f64;
        let v76: f64 = v75 * v54;
        let v77: f64 = v74 + v76;
        let v78: f64 = v70 * v77;
        let v79: f64 = -0.001373904_f64;
        let v80: f64 = v79 * v65;
        let v81: f64 = 0.111498032_f64;
        let v82: f64 = v81 * v70;
        let v83: f64 = v80 - v82;
        let v84: f64 = v72 * v54;
        let v85: f64 = v83 + v84;
        let v86: f64 = v54 * v85;
        let v87: f64 = v78 + v86;
        let v88: f64 = v69 - v87;
        let v89: f64 = -0.06768_f64;
        let v90: f64 = v5 * v40;
        let v91: f64 = v6 * v35;
        let v92: f64 = v90 + v91;
        let v93: f64 = v49 * v92;
        let v94: f64 = v46 * v41;
        let v95: f64 = v93 + v94;
        let v96: f64 = -0.15005_f64;
        let v97: f64 = v96 * v57;
        let v98: f64 = 0.0203_f64;
        let v99: f64 = v98 * v54;
        let v100: f64 = v65 * v99;
        let v101: f64 = v96 * v54;
        let v102: f64 = v70 * v101;
        let v103: f64 = v100 - v102;
        let v104: f64 = v97 + v103;
        let v105: f64 = v95 + v104;
        let v106: f64 = v89 * v105;
        let v107: f64 = 0.336_f64;
        let v108: f64 = v98 * v67;
        let v109: f64 = v54 * v101;
        let v110: f64 = v96 * v65;
        let v111: f64 = v98 * v70;
        let v112: f64 = v110 + v111;
        let v113: f64 = v65 * v112;
        let v114: f64 = v109 + v113;
        let v115: f64 = v108 + v114;
        let v116: f64 = v37 + v115;
        let v117: f64 = v107 * v116;
        let v118: f64 = v106 + v117;
        let v119: f64 = v88 + v118;
        let v120: f64 = q[3];
        let (v124, v121): (f64, f64) = ::libm::sincos(v120);
        let v122: f64 = 0.00209602_f64;
        let v123: f64 = v121 * v57;
        let v125: f64 = v124 * v65;
        let v126: f64 = v121 * v70;
        let v127: f64 = v125 + v126;
        let v128: f64 = qd[3];
        let v129: f64 = v127 * v128;
        let v130: f64 = v123 - v129;
        let v131: f64 = v122 * v130;
        let v132: f64 = v54 + v128;
        let v133: f64 = v122 * v127;
        let v134: f64 = v132 * v133;
        let v135: f64 = 0.0013_f64;
        let v136: f64 = v135 * v132;
        let v137: f64 = v127 * v136;
        let v138: f64 = v134 - v137;
        let v139: f64 = v131 + v138;
        let v140: f64 = 0.01558_f64;
        let v141: f64 = v49 * v41;
        let v142: f64 = v46 * v92;
        let v143: f64 = v141 - v142;
        let v144: f64 = v96 * v67;
        let v145: f64 = v70 * v112;
        let v146: f64 = v54 * v99;
        let v147: f64 = v145 + v146;
        let v148: f64 = v144 - v147;
        let v149: f64 = v143 + v148;
        let v150: f64 = v124 * v149;
        let v151: f64 = v121 * v116;
        let v152: f64 = v150 + v151;
        let v153: f64 = v33 * v130;
        let v154: f64 = v33 * v127;
        let v155: f64 = v132 * v154;
        let v156: f64 = v153 + v155;
        let v157: f64 = v152 + v156;
        let v158: f64 = v140 * v157;
        let v159: f64 = v139 + v158;
        let v160: f64 = q[4];
        let (v164, v161): (f64, f64) = ::libm::sincos(v160);
        let v162: f64 = 0.0003_f64;
        let v163: f64 = v161 * v130;
        let v165: f64 = v164 * v67;
        let v166: f64 = v163 - v165;
        let v167: f64 = v161 * v132;
        let v168: f64 = v121 * v65;
        let v169: f64 = v124 * v70;
        let v170: f64 = v168 - v169;
        let v171: f64 = v164 * v170;
        let v172: f64 = v167 - v171;
        let v173: f64 = qd[4];
        let v174: f64 = v172 * v173;
        let v175: f64 = v166 + v174;
        let v176: f64 = v162 * v175;
        let v177: f64 = 0.0004_f64;
        (
            v1,
            v2,
            v3,
            v5,
            v6,
            v7,
            v9,
            v10,
            v11,
            v14,
            v16,
            v21,
            v24,
            v28,
            v32,
            v33,
            v37,
            v39,
            v41,
            v44,
            v46,
            v47,
            v49,
            v54,
            v57,
            v59,
            v65,
            v67,
            v70,
            v72,
            v75,
            v77,
            v79,
            v85,
            v89,
            v92,
            v96,
            v98,
            v105,
            v107,
            v116,
            v119,
            v121,
            v122,
            v124,
            v127,
            v128,
            v130,
            v132,
            v133,
            v135,
            v136,
            v140,
            v149,
            v154,
            v157,
            v159,
            v161,
            v162,
            v164,
            v170,
            v172,
            v173,
            v175,
            v176,
            v177,
        )
    };
    let (
        v226,
        v256,
        v273,
        v274,
        v278,
        v281,
        v304,
        v306,
        v310,
        v324,
        v327,
        v336,
        v347,
        v350,
        v352,
        v355,
    ) = {
        let v178: f64 = v127 + v173;
        let v179: f64 = v177 * v178;
        let v180: f64 = v172 * v179;
        let v181: f64 = v162 * v172;
        let v182: f64 = v178 * v181;
        let v183: f64 = v180 - v182;
        let v184: f64 = v176 + v183;
        let v185: f64 = q[5];
        let (v189, v186): (f64, f64) = ::libm::sincos(v185);
        let v187: f64 = 0.00024216_f64;
        let v188: f64 = v186 * v175;
        let v190: f64 = v124 * v57;
        let v191: f64 = v170 * v128;
        let v192: f64 = v190 + v191;
        let v193: f64 = v189 * v192;
        let v194: f64 = v188 - v193;
        let v195: f64 = v161 * v170;
        let v196: f64 = v164 * v132;
        let v197: f64 = v195 + v196;
        let v198: f64 = v189 * v197;
        let v199: f64 = v186 * v178;
        let v200: f64 = v198 + v199;
        let v201: f64 = qd[5];
        let v202: f64 = v200 * v201;
        let v203: f64 = v194 - v202;
        let v204: f64 = v187 * v203;
        let v205: f64 = v172 + v201;
        let v206: f64 = v187 * v200;
        let v207: f64 = v205 * v206;
        let v208: f64 = 4e-05_f64;
        let v209: f64 = v208 * v205;
        let v210: f64 = v200 * v209;
        let v211: f64 = v207 - v210;
        let v212: f64 = v204 + v211;
        let v213: f64 = 0.00288_f64;
        let v214: f64 = v121 * v149;
        let v215: f64 = v124 * v116;
        let v216: f64 = v214 - v215;
        let v217: f64 = v33 * v170;
        let v218: f64 = v132 * v217;
        let v219: f64 = v33 * v192;
        let v220: f64 = v218 - v219;
        let v221: f64 = v216 + v220;
        let v222: f64 = v161 * v221;
        let v223: f64 = v127 * v154;
        let v224: f64 = v170 * v217;
        let v225: f64 = v223 + v224;
        let v226: f64 = v105 - v225;
        let v227: f64 = v164 * v226;
        let v228: f64 = v222 + v227;
        let v229: f64 = v189 * v228;
        let v230: f64 = v186 * v157;
        let v231: f64 = v229 + v230;
        let v232: f64 = v213 * v231;
        let v233: f64 = v212 + v232;
        let v234: f64 = v186 * v233;
        let v235: f64 = v186 * v197;
        let v236: f64 = v189 * v178;
        let v237: f64 = v235 - v236;
        let v238: f64 = v187 * v237;
        let v239: f64 = v205 * v238;
        let v240: f64 = v237 * v209;
        let v241: f64 = v239 - v240;
        let v242: f64 = v189 * v175;
        let v243: f64 = v186 * v192;
        let v244: f64 = v242 + v243;
        let v245: f64 = v237 * v201;
        let v246: f64 = v244 + v245;
        let v247: f64 = v187 * v246;
        let v248: f64 = v241 - v247;
        let v249: f64 = v186 * v228;
        let v250: f64 = v189 * v157;
        let v251: f64 = v249 - v250;
        let v252: f64 = v213 * v251;
        let v253: f64 = v248 + v252;
        let v254: f64 = v189 * v253;
        let v255: f64 = v234 - v254;
        let v256: f64 = v184 + v255;
        let v257: f64 = v161 * v256;
        let v258: f64 = v162 * v197;
        let v259: f64 = v178 * v258;
        let v260: f64 = v197 * v179;
        let v261: f64 = v259 - v260;
        let v262: f64 = v164 * v130;
        let v263: f64 = v161 * v67;
        let v264: f64 = v262 + v263;
        let v265: f64 = v197 * v173;
        let v266: f64 = v264 + v265;
        let v267: f64 = v162 * v266;
        let v268: f64 = v261 - v267;
        let v269: f64 = v200 * v238;
        let v270: f64 = v237 * v206;
        let v271: f64 = v269 - v270;
        let v272: f64 = v208 * v266;
        let v273: f64 = v271 - v272;
        let v274: f64 = v268 + v273;
        let v275: f64 = v164 * v274;
        let v276: f64 = v257 - v275;
        let v277: f64 = v159 + v276;
        let v278: f64 = 0.82_f64;
        let v279: f64 = v278 * v157;
        let v280: f64 = v140 * v130;
        let v281: f64 = v140 * v127;
        let v282: f64 = v132 * v281;
        let v283: f64 = v280 + v282;
        let v284: f64 = v279 + v283;
        let v285: f64 = 0.09_f64;
        let v286: f64 = v285 * v251;
        let v287: f64 = v213 * v237;
        let v288: f64 = v205 * v287;
        let v289: f64 = v213 * v246;
        let v290: f64 = v288 - v289;
        let v291: f64 = v286 + v290;
        let v292: f64 = v189 * v291;
        let v293: f64 = v285 * v231;
        let v294: f64 = v213 * v203;
        let v295: f64 = v213 * v200;
        let v296: f64 = v205 * v295;
        let v297: f64 = v294 + v296;
        let v298: f64 = v293 + v297;
        let v299: f64 = v186 * v298;
        let v300: f64 = v292 - v299;
        let v301: f64 = 0.34_f64;
        let v302: f64 = v301 * v157;
        let v303: f64 = v300 - v302;
        let v304: f64 = v284 - v303;
        let v305: f64 = v33 * v304;
        let v306: f64 = v277 + v305;
        let v307: f64 = v121 * v306;
        let v308: f64 = v122 * v192;
        let v309: f64 = v170 * v136;
        let v310: f64 = v122 * v170;
        let v311: f64 = v132 * v310;
        let v312: f64 = v309 - v311;
        let v313: f64 = v308 + v312;
        let v314: f64 = v140 * v221;
        let v315: f64 = v313 - v314;
        let v316: f64 = v172 * v258;
        let v317: f64 = v197 * v181;
        let v318: f64 = v316 - v317;
        let v319: f64 = v177 * v192;
        let v320: f64 = v318 - v319;
        let v321: f64 = v189 * v233;
        let v322: f64 = v186 * v253;
        let v323: f64 = v321 + v322;
        let v324: f64 = v320 + v323;
        let v325: f64 = v315 - v324;
        let v326: f64 = v278 * v221;
        let v327: f64 = v140 * v170;
        let v328: f64 = v132 * v327;
        let v329: f64 = v140 * v192;
        let v330: f64 = v328 - v329;
        let v331: f64 = v326 + v330;
        let v332: f64 = v301 * v228;
        let v333: f64 = v186 * v291;
        let v334: f64 = v189 * v298;
        let v335: f64 = v333 + v334;
        let v336: f64 = v332 + v335;
        let v337: f64 = v161 * v336;
        let v338: f64 = v161 * v226;
        let v339: f64 = v164 * v221;
        let v340: f64 = v338 - v339;
        let v341: f64 = v301 * v340;
        let v342: f64 = v285 * v340;
        let v343: f64 = v237 * v287;
        let v344: f64 = v200 * v295;
        let v345: f64 = v343 + v344;
        let v346: f64 = v342 - v345;
        let v347: f64 = v341 + v346;
        let v348: f64 = v164 * v347;
        let v349: f64 = v337 - v348;
        let v350: f64 = v331 + v349;
        let v351: f64 = v33 * v350;
        let v352: f64 = v325 - v351;
        let v353: f64 = v124 * v352;
        let v354: f64 = v307 + v353;
        let v355: f64 = v119 + v354;
        (
            v226,
            v256,
            v273,
            v274,
            v278,
            v281,
            v304,
            v306,
            v310,
            v324,
            v327,
            v336,
            v347,
            v350,
            v352,
            v355,
        )
    };
    let (v408, v486, v531, v532, v533) = {
        let v356: f64 = 4.8_f64;
        let v357: f64 = v356 * v105;
        let v358: f64 = v89 * v57;
        let v359: f64 = -0.09744_f64;
        let v360: f64 = v359 * v54;
        let v361: f64 = v107 * v65;
        let v362: f64 = v360 - v361;
        let v363: f64 = v65 * v362;
        let v364: f64 = v107 * v70;
        let v365: f64 = v89 * v54;
        let v366: f64 = v364 + v365;
        let v367: f64 = v70 * v366;
        let v368: f64 = v363 - v367;
        let v369: f64 = v358 + v368;
        let v370: f64 = v357 + v369;
        let v371: f64 = v278 * v226;
        let v372: f64 = v127 * v281;
        let v373: f64 = v170 * v327;
        let v374: f64 = v372 + v373;
        let v375: f64 = v371 - v374;
        let v376: f64 = v164 * v336;
        let v377: f64 = v161 * v347;
        let v378: f64 = v376 + v377;
        let v379: f64 = v375 + v378;
        let v380: f64 = v370 + v379;
        let v381: f64 = v96 * v380;
        let v382: f64 = v355 + v381;
        let v383: f64 = v46 * v382;
        let v384: f64 = v59 * v57;
        let v385: f64 = v75 * v67;
        let v386: f64 = v384 - v385;
        let v387: f64 = v65 * v85;
        let v388: f64 = v47 * v65;
        let v389: f64 = v79 * v70;
        let v390: f64 = v388 - v389;
        let v391: f64 = v59 * v54;
        let v392: f64 = v390 + v391;
        let v393: f64 = v70 * v392;
        let v394: f64 = v387 + v393;
        let v395: f64 = v386 + v394;
        let v396: f64 = v359 * v116;
        let v397: f64 = v89 * v149;
        let v398: f64 = v396 + v397;
        let v399: f64 = v395 - v398;
        let v400: f64 = v127 * v310;
        let v401: f64 = v170 * v133;
        let v402: f64 = v400 - v401;
        let v403: f64 = v135 * v67;
        let v404: f64 = v402 - v403;
        let v405: f64 = v164 * v256;
        let v406: f64 = v161 * v274;
        let v407: f64 = v405 + v406;
        let v408: f64 = v404 + v407;
        let v409: f64 = v399 + v408;
        let v410: f64 = v124 * v350;
        let v411: f64 = v121 * v304;
        let v412: f64 = v410 - v411;
        let v413: f64 = v356 * v116;
        let v414: f64 = v359 * v67;
        let v415: f64 = v107 * v57;
        let v416: f64 = v414 + v415;
        let v417: f64 = v54 * v366;
        let v418: f64 = v89 * v65;
        let v419: f64 = v359 * v70;
        let v420: f64 = v418 + v419;
        let v421: f64 = v65 * v420;
        let v422: f64 = v417 + v421;
        let v423: f64 = v416 + v422;
        let v424: f64 = v413 + v423;
        let v425: f64 = v412 - v424;
        let v426: f64 = v98 * v425;
        let v427: f64 = v356 * v149;
        let v428: f64 = v89 * v67;
        let v429: f64 = v70 * v420;
        let v430: f64 = v54 * v362;
        let v431: f64 = v429 + v430;
        let v432: f64 = v428 - v431;
        let v433: f64 = v427 + v432;
        let v434: f64 = v121 * v350;
        let v435: f64 = v124 * v304;
        let v436: f64 = v434 + v435;
        let v437: f64 = v433 + v436;
        let v438: f64 = v96 * v437;
        let v439: f64 = v426 - v438;
        let v440: f64 = v409 + v439;
        let v441: f64 = v49 * v440;
        let v442: f64 = v383 - v441;
        let v443: f64 = v44 + v442;
        let v444: f64 = v1 * v443;
        let v445: f64 = v9 * v7;
        let v446: f64 = v24 * v11;
        let v447: f64 = v445 - v446;
        let v448: f64 = v2 * v10;
        let v449: f64 = v9 * v5;
        let v450: f64 = v448 + v449;
        let v451: f64 = v14 * v6;
        let v452: f64 = v450 + v451;
        let v453: f64 = v6 * v452;
        let v454: f64 = v10 * v21;
        let v455: f64 = v453 - v454;
        let v456: f64 = v447 + v455;
        let v457: f64 = v39 * v92;
        let v458: f64 = -6.33012_f64;
        let v459: f64 = v458 * v37;
        let v460: f64 = v457 + v459;
        let v461: f64 = v456 - v460;
        let v462: f64 = v49 * v382;
        let v463: f64 = v46 * v440;
        let v464: f64 = v462 + v463;
        let v465: f64 = v461 + v464;
        let v466: f64 = 17.4_f64;
        let v467: f64 = v466 * v37;
        let v468: f64 = v32 * v7;
        let v469: f64 = v458 * v11;
        let v470: f64 = v468 + v469;
        let v471: f64 = v458 * v6;
        let v472: f64 = v39 * v10;
        let v473: f64 = v471 - v472;
        let v474: f64 = v10 * v473;
        let v475: f64 = v39 * v5;
        let v476: f64 = v32 * v6;
        let v477: f64 = v475 - v476;
        let v478: f64 = v5 * v477;
        let v479: f64 = v474 - v478;
        let v480: f64 = v470 + v479;
        let v481: f64 = v467 + v480;
        let v482: f64 = v481 - v425;
        let v483: f64 = v33 * v482;
        let v484: f64 = v465 - v483;
        let v485: f64 = v3 * v484;
        let v486: f64 = v444 + v485;
        let v487: f64 = v14 * v7;
        let v488: f64 = v16 * v11;
        let v489: f64 = v487 - v488;
        let v490: f64 = v10 * v28;
        let v491: f64 = v5 * v452;
        let v492: f64 = v490 - v491;
        let v493: f64 = v489 + v492;
        let v494: f64 = v458 * v41;
        let v495: f64 = v32 * v92;
        let v496: f64 = v494 + v495;
        let v497: f64 = v493 + v496;
        let v498: f64 = v79 * v57;
        let v499: f64 = v72 * v67;
        let v500: f64 = v498 - v499;
        let v501: f64 = v54 * v392;
        let v502: f64 = v65 * v77;
        let v503: f64 = v501 - v502;
        let v504: f64 = v500 + v503;
        let v505: f64 = v107 * v149;
        let v506: f64 = v359 * v105;
        let v507: f64 = v505 - v506;
        let v508: f64 = v504 + v507;
        let v509: f64 = v124 * v306;
        let v510: f64 = v121 * v352;
        let v511: f64 = v509 - v510;
        let v512: f64 = v508 + v511;
        let v513: f64 = v98 * v380;
        let v514: f64 = v512 - v513;
        let v515: f64 = v497 - v514;
        let v516: f64 = v466 * v41;
        let v517: f64 = v6 * v477;
        let v518: f64 = v32 * v10;
        let v519: f64 = v458 * v5;
        let v520: f64 = v518 - v519;
        let v521: f64 = v10 * v520;
        let v522: f64 = v517 - v521;
        let v523: f64 = v39 * v7;
        let v524: f64 = v522 - v523;
        let v525: f64 = v516 + v524;
        let v526: f64 = v49 * v437;
        let v527: f64 = v46 * v380;
        let v528: f64 = v526 + v527;
        let v529: f64 = v525 + v528;
        let v530: f64 = v33 * v529;
        let v531: f64 = v515 + v530;
        let v532: f64 = -v514;
        let v533: f64 = -v324;
        (v408, v486, v531, v532, v533)
    };
    [v486, v531, v532, v408, v533, v273]
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
    let (v5, v16): (f64, f64) = ::libm::sincos(v4);
    let v6: f64 = v3 * v5;
    let v7: f64 = q[3];
    let (v46, v8): (f64, f64) = ::libm::sincos(v7);
    let v9: f64 = v6 * v8;
    let v10: f64 = v2 - v9;
    let v11: f64 = q[2];
    let (v19, v12): (f64, f64) = ::libm::sincos(v11);
    let v13: f64 = v10 * v12;
    let v14: f64 = v1 + v13;
    let v15: f64 = -8.7439473_f64;
    let v17: f64 = v3 * v16;
    let v18: f64 = v15 - v17;
    let v20: f64 = v18 * v19;
    let v21: f64 = v14 + v20;
    let v22: f64 = q[1];
    let (v32, v23): (f64, f64) = ::libm::sincos(v22);
    let v24: f64 = v21 * v23;
    let v25: f64 = -1.024164_f64;
    let v26: f64 = v18 * v12;
    let v27: f64 = v25 + v26;
    let v28: f64 = -0.24892875_f64;
    let v29: f64 = v28 + v9;
    let v30: f64 = v29 * v19;
    let v31: f64 = v27 + v30;
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
/// Operation count: 519 floating-point operations, 10 trig calls.
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
        v7,
        v9,
        v10,
        v12,
        v14,
        v16,
        v18,
        v21,
        v22,
        v26,
        v29,
        v31,
        v34,
        v38,
        v42,
        v43,
        v47,
        v49,
        v56,
        v59,
        v61,
        v62,
        v64,
        v69,
        v72,
        v74,
        v76,
        v79,
        v85,
        v87,
        v90,
        v92,
        v95,
        v97,
        v100,
        v104,
        v108,
        v114,
        v117,
        v119,
        v128,
        v130,
        v139,
        v142,
        v144,
        v145,
        v147,
        v152,
        v153,
        v155,
        v157,
        v158,
        v160,
        v161,
        v165,
        v174,
        v179,
        v182,
        v184,
        v186,
        v187,
        v189,
        v191,
        v193,
    ) = {
        let v0: f64 = 0.35_f64;
        let v1: f64 = qdd[0];
        let v2: f64 = v0 * v1;
        let v3: f64 = q[1];
        let (v4, v7): (f64, f64) = ::libm::sincos(v3);
        let v5: f64 = 1.03118515_f64;
        let v6: f64 = v4 * v1;
        let v8: f64 = qd[0];
        let v9: f64 = v7 * v8;
        let v10: f64 = qd[1];
        let v11: f64 = v9 * v10;
        let v12: f64 = v6 + v11;
        let v13: f64 = v5 * v12;
        let v14: f64 = 0.03798072_f64;
        let v15: f64 = v7 * v1;
        let v16: f64 = v4 * v8;
        let v17: f64 = v16 * v10;
        let v18: f64 = v15 - v17;
        let v19: f64 = v14 * v18;
        let v20: f64 = v13 + v19;
        let v21: f64 = 1.4401023_f64;
        let v22: f64 = qdd[1];
        let v23: f64 = v21 * v22;
        let v24: f64 = v20 + v23;
        let v25: f64 = v21 * v16;
        let v26: f64 = -0.023751_f64;
        let v27: f64 = v26 * v9;
        let v28: f64 = v25 + v27;
        let v29: f64 = 2.842524056_f64;
        let v30: f64 = v29 * v10;
        let v31: f64 = v28 + v30;
        let v32: f64 = v9 * v31;
        let v33: f64 = v14 * v16;
        let v34: f64 = 3.727456406_f64;
        let v35: f64 = v34 * v9;
        let v36: f64 = v33 + v35;
        let v37: f64 = v26 * v10;
        let v38: f64 = v36 + v37;
        let v39: f64 = v10 * v38;
        let v40: f64 = v32 - v39;
        let v41: f64 = v24 + v40;
        let v42: f64 = 0.1044_f64;
        let v43: f64 = 0.4318_f64;
        let v44: f64 = v43 * v10;
        let v45: f64 = v16 * v44;
        let v46: f64 = v43 * v18;
        let v47: f64 = v45 - v46;
        let v48: f64 = v42 * v47;
        let v49: f64 = 3.9585_f64;
        let v50: f64 = 9.81_f64;
        let v51: f64 = v50 * v7;
        let v52: f64 = v43 * v22;
        let v53: f64 = v43 * v9;
        let v54: f64 = v16 * v53;
        let v55: f64 = v52 + v54;
        let v56: f64 = v51 + v55;
        let v57: f64 = v49 * v56;
        let v58: f64 = v48 - v57;
        let v59: f64 = v41 + v58;
        let v60: f64 = q[2];
        let (v64, v61): (f64, f64) = ::libm::sincos(v60);
        let v62: f64 = 0.090474288_f64;
        let v63: f64 = v61 * v12;
        let v65: f64 = v64 * v18;
        let v66: f64 = v63 + v65;
        let v67: f64 = v61 * v9;
        let v68: f64 = v64 * v16;
        let v69: f64 = v67 - v68;
        let v70: f64 = qd[2];
        let v71: f64 = v69 * v70;
        let v72: f64 = v66 + v71;
        let v73: f64 = v62 * v72;
        let v74: f64 = -0.001373904_f64;
        let v75: f64 = qdd[2];
        let v76: f64 = v22 + v75;
        let v77: f64 = v74 * v76;
        let v78: f64 = v73 - v77;
        let v79: f64 = 0.0068208_f64;
        let v80: f64 = v61 * v18;
        let v81: f64 = v64 * v12;
        let v82: f64 = v80 - v81;
        let v83: f64 = v61 * v16;
        let v84: f64 = v64 * v9;
        let v85: f64 = v83 + v84;
        let v86: f64 = v85 * v70;
        let v87: f64 = v82 - v86;
        let v88: f64 = v79 * v87;
        let v89: f64 = v78 + v88;
        let v90: f64 = v10 + v70;
        let v91: f64 = v79 * v85;
        let v92: f64 = 0.0047376_f64;
        let v93: f64 = v92 * v90;
        let v94: f64 = v91 - v93;
        let v95: f64 = 0.01543232_f64;
        let v96: f64 = v95 * v69;
        let v97: f64 = v94 + v96;
        let v98: f64 = v90 * v97;
        let v99: f64 = v74 * v85;
        let v100: f64 = 0.111498032_f64;
        let v101: f64 = v100 * v90;
        let v102: f64 = v99 - v101;
        let v103: f64 = v92 * v69;
        let v104: f64 = v102 + v103;
        let v105: f64 = v69 * v104;
        let v106: f64 = v98 + v105;
        let v107: f64 = v89 - v106;
        let v108: f64 = -0.06768_f64;
        let v109: f64 = v61 * v56;
        let v110: f64 = v50 * v4;
        let v111: f64 = v9 * v53;
        let v112: f64 = v10 * v44;
        let v113: f64 = v111 + v112;
        let v114: f64 = v110 - v113;
        let v115: f64 = v64 * v114;
        let v116: f64 = v109 - v115;
        let v117: f64 = -0.15005_f64;
        let v118: f64 = v117 * v72;
        let v119: f64 = 0.0203_f64;
        let v120: f64 = v119 * v76;
        let v121: f64 = v118 + v120;
        let v122: f64 = v119 * v69;
        let v123: f64 = v85 * v122;
        let v124: f64 = v117 * v69;
        let v125: f64 = v90 * v124;
        let v126: f64 = v123 - v125;
        let v127: f64 = v121 + v126;
        let v128: f64 = v116 + v127;
        let v129: f64 = v108 * v128;
        let v130: f64 = 0.336_f64;
        let v131: f64 = v119 * v87;
        let v132: f64 = v69 * v124;
        let v133: f64 = v117 * v85;
        let v134: f64 = v119 * v90;
        let v135: f64 = v133 + v134;
        let v136: f64 = v85 * v135;
        let v137: f64 = v132 + v136;
        let v138: f64 = v131 - v137;
        let v139: f64 = v138 - v47;
        let v140: f64 = v130 * v139;
        let v141: f64 = v129 - v140;
        let v142: f64 = v107 + v141;
        let v143: f64 = q[3];
        let (v147, v144): (f64, f64) = ::libm::sincos(v143);
        let v145: f64 = 0.00209602_f64;
        let v146: f64 = v144 * v72;
        let v148: f64 = v147 * v76;
        let v149: f64 = v146 - v148;
        let v150: f64 = v147 * v85;
        let v151: f64 = v144 * v90;
        let v152: f64 = v150 + v151;
        let v153: f64 = qd[3];
        let v154: f64 = v152 * v153;
        let v155: f64 = v149 - v154;
        let v156: f64 = v145 * v155;
        let v157: f64 = v69 + v153;
        let v158: f64 = v145 * v152;
        let v159: f64 = v157 * v158;
        let v160: f64 = 0.0013_f64;
        let v161: f64 = v160 * v157;
        let v162: f64 = v152 * v161;
        let v163: f64 = v159 - v162;
        let v164: f64 = v156 + v163;
        let v165: f64 = 0.01558_f64;
        let v166: f64 = v61 * v114;
        let v167: f64 = v64 * v56;
        let v168: f64 = v166 + v167;
        let v169: f64 = v117 * v87;
        let v170: f64 = v90 * v135;
        let v171: f64 = v69 * v122;
        let v172: f64 = v170 + v171;
        let v173: f64 = v169 + v172;
        let v174: f64 = v168 - v173;
        let v175: f64 = v147 * v174;
        let v176: f64 = v144 * v139;
        let v177: f64 = v175 - v176;
        let v178: f64 = v43 * v155;
        let v179: f64 = v43 * v152;
        let v180: f64 = v157 * v179;
        let v181: f64 = v178 + v180;
        let v182: f64 = v177 + v181;
        let v183: f64 = v165 * v182;
        let v184: f64 = v164 + v183;
        let v185: f64 = q[4];
        let (v189, v186): (f64, f64) = ::libm::sincos(v185);
        let v187: f64 = 0.0003_f64;
        let v188: f64 = v186 * v155;
        let v190: f64 = qdd[3];
        let v191: f64 = v87 + v190;
        let v192: f64 = v189 * v191;
        let v193: f64 = v188 + v192;
        (
            v2,
            v4,
            v5,
            v7,
            v9,
            v10,
            v12,
            v14,
            v16,
            v18,
            v21,
            v22,
            v26,
            v29,
            v31,
            v34,
            v38,
            v42,
            v43,
            v47,
            v49,
            v56,
            v59,
            v61,
            v62,
            v64,
            v69,
            v72,
            v74,
            v76,
            v79,
            v85,
            v87,
            v90,
            v92,
            v95,
            v97,
            v100,
            v104,
            v108,
            v114,
            v117,
            v119,
            v128,
            v130,
            v139,
            v142,
            v144,
            v145,
            v147,
            v152,
            v153,
            v155,
            v157,
            v158,
            v160,
            v161,
            v165,
            v174,
            v179,
            v182,
            v184,
            v186,
            v187,
            v189,
            v191,
            v193,
        )
    };
    let (
        v197,
        v257,
        v287,
        v306,
        v307,
        v311,
        v314,
        v337,
        v339,
        v343,
        v357,
        v360,
        v369,
        v380,
        v383,
        v385,
        v387,
    ) = {
        let v194: f64 = v186 * v157;
        let v195: f64 = v144 * v85;
        let v196: f64 = v147 * v90;
        let v197: f64 = v195 - v196;
        let v198: f64 = v189 * v197;
        let v199: f64 = v194 - v198;
        let v200: f64 = qd[4];
        let v201: f64 = v199 * v200;
        let v202: f64 = v193 + v201;
        let v203: f64 = v187 * v202;
        let v204: f64 = 0.0004_f64;
        let v205: f64 = v152 + v200;
        let v206: f64 = v204 * v205;
        let v207: f64 = v199 * v206;
        let v208: f64 = v187 * v199;
        let v209: f64 = v205 * v208;
        let v210: f64 = v207 - v209;
        let v211: f64 = v203 + v210;
        let v212: f64 = q[5];
        let (v216, v213): (f64, f64) = ::libm::sincos(v212);
        let v214: f64 = 0.00024216_f64;
        let v215: f64 = v213 * v202;
        let v217: f64 = v147 * v72;
        let v218: f64 = v144 * v76;
        let v219: f64 = v217 + v218;
        let v220: f64 = v197 * v153;
        let v221: f64 = v219 + v220;
        let v222: f64 = qdd[4];
        let v223: f64 = v221 + v222;
        let v224: f64 = v216 * v223;
        let v225: f64 = v215 - v224;
        let v226: f64 = v186 * v197;
        let v227: f64 = v189 * v157;
        let v228: f64 = v226 + v227;
        let v229: f64 = v216 * v228;
        let v230: f64 = v213 * v205;
        let v231: f64 = v229 + v230;
        let v232: f64 = qd[5];
        let v233: f64 = v231 * v232;
        let v234: f64 = v225 - v233;
        let v235: f64 = v214 * v234;
        let v236: f64 = v199 + v232;
        let v237: f64 = v214 * v231;
        let v238: f64 = v236 * v237;
        let v239: f64 = 4e-05_f64;
        let v240: f64 = v239 * v236;
        let v241: f64 = v231 * v240;
        let v242: f64 = v238 - v241;
        let v243: f64 = v235 + v242;
        let v244: f64 = 0.00288_f64;
        let v245: f64 = v144 * v174;
        let v246: f64 = v147 * v139;
        let v247: f64 = v245 + v246;
        let v248: f64 = v43 * v197;
        let v249: f64 = v157 * v248;
        let v250: f64 = v43 * v221;
        let v251: f64 = v249 - v250;
        let v252: f64 = v247 + v251;
        let v253: f64 = v186 * v252;
        let v254: f64 = v152 * v179;
        let v255: f64 = v197 * v248;
        let v256: f64 = v254 + v255;
        let v257: f64 = v128 - v256;
        let v258: f64 = v189 * v257;
        let v259: f64 = v253 + v258;
        let v260: f64 = v216 * v259;
        let v261: f64 = v213 * v182;
        let v262: f64 = v260 + v261;
        let v263: f64 = v244 * v262;
        let v264: f64 = v243 + v263;
        let v265: f64 = v213 * v264;
        let v266: f64 = v213 * v228;
        let v267: f64 = v216 * v205;
        let v268: f64 = v266 - v267;
        let v269: f64 = v214 * v268;
        let v270: f64 = v236 * v269;
        let v271: f64 = v268 * v240;
        let v272: f64 = v270 - v271;
        let v273: f64 = v216 * v202;
        let v274: f64 = v213 * v223;
        let v275: f64 = v273 + v274;
        let v276: f64 = v268 * v232;
        let v277: f64 = v275 + v276;
        let v278: f64 = v214 * v277;
        let v279: f64 = v272 - v278;
        let v280: f64 = v213 * v259;
        let v281: f64 = v216 * v182;
        let v282: f64 = v280 - v281;
        let v283: f64 = v244 * v282;
        let v284: f64 = v279 + v283;
        let v285: f64 = v216 * v284;
        let v286: f64 = v265 - v285;
        let v287: f64 = v211 + v286;
        let v288: f64 = v186 * v287;
        let v289: f64 = v186 * v191;
        let v290: f64 = v189 * v155;
        let v291: f64 = v289 - v290;
        let v292: f64 = v228 * v200;
        let v293: f64 = v291 - v292;
        let v294: f64 = v187 * v293;
        let v295: f64 = v187 * v228;
        let v296: f64 = v205 * v295;
        let v297: f64 = v228 * v206;
        let v298: f64 = v296 - v297;
        let v299: f64 = v294 + v298;
        let v300: f64 = qdd[5];
        let v301: f64 = v293 + v300;
        let v302: f64 = v239 * v301;
        let v303: f64 = v231 * v269;
        let v304: f64 = v268 * v237;
        let v305: f64 = v303 - v304;
        let v306: f64 = v302 + v305;
        let v307: f64 = v299 + v306;
        let v308: f64 = v189 * v307;
        let v309: f64 = v288 - v308;
        let v310: f64 = v184 + v309;
        let v311: f64 = 0.82_f64;
        let v312: f64 = v311 * v182;
        let v313: f64 = v165 * v155;
        let v314: f64 = v165 * v152;
        let v315: f64 = v157 * v314;
        let v316: f64 = v313 + v315;
        let v317: f64 = v312 + v316;
        let v318: f64 = 0.09_f64;
        let v319: f64 = v318 * v282;
        let v320: f64 = v244 * v268;
        let v321: f64 = v236 * v320;
        let v322: f64 = v244 * v277;
        let v323: f64 = v321 - v322;
        let v324: f64 = v319 + v323;
        let v325: f64 = v216 * v324;
        let v326: f64 = v318 * v262;
        let v327: f64 = v244 * v234;
        let v328: f64 = v244 * v231;
        let v329: f64 = v236 * v328;
        let v330: f64 = v327 + v329;
        let v331: f64 = v326 + v330;
        let v332: f64 = v213 * v331;
        let v333: f64 = v325 - v332;
        let v334: f64 = 0.34_f64;
        let v335: f64 = v334 * v182;
        let v336: f64 = v333 - v335;
        let v337: f64 = v317 - v336;
        let v338: f64 = v43 * v337;
        let v339: f64 = v310 + v338;
        let v340: f64 = v144 * v339;
        let v341: f64 = v145 * v221;
        let v342: f64 = v197 * v161;
        let v343: f64 = v145 * v197;
        let v344: f64 = v157 * v343;
        let v345: f64 = v342 - v344;
        let v346: f64 = v341 + v345;
        let v347: f64 = v165 * v252;
        let v348: f64 = v346 - v347;
        let v349: f64 = v199 * v295;
        let v350: f64 = v228 * v208;
        let v351: f64 = v349 - v350;
        let v352: f64 = v204 * v223;
        let v353: f64 = v351 - v352;
        let v354: f64 = v216 * v264;
        let v355: f64 = v213 * v284;
        let v356: f64 = v354 + v355;
        let v357: f64 = v353 + v356;
        let v358: f64 = v348 - v357;
        let v359: f64 = v311 * v252;
        let v360: f64 = v165 * v197;
        let v361: f64 = v157 * v360;
        let v362: f64 = v165 * v221;
        let v363: f64 = v361 - v362;
        let v364: f64 = v359 + v363;
        let v365: f64 = v334 * v259;
        let v366: f64 = v213 * v324;
        let v367: f64 = v216 * v331;
        let v368: f64 = v366 + v367;
        let v369: f64 = v365 + v368;
        let v370: f64 = v186 * v369;
        let v371: f64 = v186 * v257;
        let v372: f64 = v189 * v252;
        let v373: f64 = v371 - v372;
        let v374: f64 = v334 * v373;
        let v375: f64 = v318 * v373;
        let v376: f64 = v268 * v320;
        let v377: f64 = v231 * v328;
        let v378: f64 = v376 + v377;
        let v379: f64 = v375 - v378;
        let v380: f64 = v374 + v379;
        let v381: f64 = v189 * v380;
        let v382: f64 = v370 - v381;
        let v383: f64 = v364 + v382;
        let v384: f64 = v43 * v383;
        let v385: f64 = v358 - v384;
        let v386: f64 = v147 * v385;
        let v387: f64 = v340 + v386;
        (
            v197,
            v257,
            v287,
            v306,
            v307,
            v311,
            v314,
            v337,
            v339,
            v343,
            v357,
            v360,
            v369,
            v380,
            v383,
            v385,
            v387,
        )
    };
    let (v445, v528, v579, v580, v581) = {
        let v388: f64 = v142 + v387;
        let v389: f64 = 4.8_f64;
        let v390: f64 = v389 * v128;
        let v391: f64 = v108 * v72;
        let v392: f64 = -0.09744_f64;
        let v393: f64 = v392 * v76;
        let v394: f64 = v391 + v393;
        let v395: f64 = v392 * v69;
        let v396: f64 = v130 * v85;
        let v397: f64 = v395 - v396;
        let v398: f64 = v85 * v397;
        let v399: f64 = v130 * v90;
        let v400: f64 = v108 * v69;
        let v401: f64 = v399 + v400;
        let v402: f64 = v90 * v401;
        let v403: f64 = v398 - v402;
        let v404: f64 = v394 + v403;
        let v405: f64 = v390 + v404;
        let v406: f64 = v311 * v257;
        let v407: f64 = v152 * v314;
        let v408: f64 = v197 * v360;
        let v409: f64 = v407 + v408;
        let v410: f64 = v406 - v409;
        let v411: f64 = v189 * v369;
        let v412: f64 = v186 * v380;
        let v413: f64 = v411 + v412;
        let v414: f64 = v410 + v413;
        let v415: f64 = v405 + v414;
        let v416: f64 = v117 * v415;
        let v417: f64 = v388 + v416;
        let v418: f64 = v61 * v417;
        let v419: f64 = v79 * v72;
        let v420: f64 = v92 * v76;
        let v421: f64 = v419 - v420;
        let v422: f64 = v95 * v87;
        let v423: f64 = v421 + v422;
        let v424: f64 = v85 * v104;
        let v425: f64 = v62 * v85;
        let v426: f64 = v74 * v90;
        let v427: f64 = v425 - v426;
        let v428: f64 = v79 * v69;
        let v429: f64 = v427 + v428;
        let v430: f64 = v90 * v429;
        let v431: f64 = v424 + v430;
        let v432: f64 = v423 + v431;
        let v433: f64 = v392 * v139;
        let v434: f64 = v108 * v174;
        let v435: f64 = v433 - v434;
        let v436: f64 = v432 + v435;
        let v437: f64 = v160 * v191;
        let v438: f64 = v152 * v343;
        let v439: f64 = v197 * v158;
        let v440: f64 = v438 - v439;
        let v441: f64 = v437 + v440;
        let v442: f64 = v189 * v287;
        let v443: f64 = v186 * v307;
        let v444: f64 = v442 + v443;
        let v445: f64 = v441 + v444;
        let v446: f64 = v436 + v445;
        let v447: f64 = v389 * v139;
        let v448: f64 = v392 * v87;
        let v449: f64 = v130 * v72;
        let v450: f64 = v448 - v449;
        let v451: f64 = v69 * v401;
        let v452: f64 = v108 * v85;
        let v453: f64 = v392 * v90;
        let v454: f64 = v452 + v453;
        let v455: f64 = v85 * v454;
        let v456: f64 = v451 + v455;
        let v457: f64 = v450 - v456;
        let v458: f64 = v447 + v457;
        let v459: f64 = v147 * v383;
        let v460: f64 = v144 * v337;
        let v461: f64 = v459 - v460;
        let v462: f64 = v458 + v461;
        let v463: f64 = v119 * v462;
        let v464: f64 = v389 * v174;
        let v465: f64 = v130 * v76;
        let v466: f64 = v108 * v87;
        let v467: f64 = v465 + v466;
        let v468: f64 = v90 * v454;
        let v469: f64 = v69 * v397;
        let v470: f64 = v468 + v469;
        let v471: f64 = v467 + v470;
        let v472: f64 = v464 - v471;
        let v473: f64 = v144 * v383;
        let v474: f64 = v147 * v337;
        let v475: f64 = v473 + v474;
        let v476: f64 = v472 + v475;
        let v477: f64 = v117 * v476;
        let v478: f64 = v463 - v477;
        let v479: f64 = v446 + v478;
        let v480: f64 = v64 * v479;
        let v481: f64 = v418 - v480;
        let v482: f64 = v59 + v481;
        let v483: f64 = v4 * v482;
        let v484: f64 = v14 * v12;
        let v485: f64 = v34 * v18;
        let v486: f64 = v484 + v485;
        let v487: f64 = v26 * v22;
        let v488: f64 = v486 + v487;
        let v489: f64 = v5 * v16;
        let v490: f64 = v14 * v9;
        let v491: f64 = v489 + v490;
        let v492: f64 = v21 * v10;
        let v493: f64 = v491 + v492;
        let v494: f64 = v10 * v493;
        let v495: f64 = v16 * v31;
        let v496: f64 = v494 - v495;
        let v497: f64 = v488 + v496;
        let v498: f64 = v49 * v114;
        let v499: f64 = -6.33012_f64;
        let v500: f64 = v499 * v47;
        let v501: f64 = v498 - v500;
        let v502: f64 = v497 + v501;
        let v503: f64 = v64 * v417;
        let v504: f64 = v61 * v479;
        let v505: f64 = v503 + v504;
        let v506: f64 = v502 + v505;
        let v507: f64 = 17.4_f64;
        let v508: f64 = v507 * v47;
        let v509: f64 = v42 * v12;
        let v510: f64 = v499 * v18;
        let v511: f64 = v509 - v510;
        let v512: f64 = v499 * v10;
        let v513: f64 = v49 * v16;
        let v514: f64 = v512 - v513;
        let v515: f64 = v16 * v514;
        let v516: f64 = v49 * v9;
        let v517: f64 = v42 * v10;
        let v518: f64 = v516 - v517;
        let v519: f64 = v9 * v518;
        let v520: f64 = v515 - v519;
        let v521: f64 = v511 + v520;
        let v522: f64 = v508 + v521;
        let v523: f64 = v522 - v462;
        let v524: f64 = v43 * v523;
        let v525: f64 = v506 - v524;
        let v526: f64 = v7 * v525;
        let v527: f64 = v483 + v526;
        let v528: f64 = v2 + v527;
        let v529: f64 = v21 * v12;
        let v530: f64 = v26 * v18;
        let v531: f64 = v529 + v530;
        let v532: f64 = v29 * v22;
        let v533: f64 = v531 + v532;
        let v534: f64 = v16 * v38;
        let v535: f64 = v9 * v493;
        let v536: f64 = v534 - v535;
        let v537: f64 = v533 + v536;
        let v538: f64 = v499 * v56;
        let v539: f64 = v42 * v114;
        let v540: f64 = v538 - v539;
        let v541: f64 = v537 + v540;
        let v542: f64 = v74 * v72;
        let v543: f64 = v100 * v76;
        let v544: f64 = v542 - v543;
        let v545: f64 = v92 * v87;
        let v546: f64 = v544 + v545;
        let v547: f64 = v69 * v429;
        let v548: f64 = v85 * v97;
        let v549: f64 = v547 - v548;
        let v550: f64 = v546 + v549;
        let v551: f64 = v130 * v174;
        let v552: f64 = v392 * v128;
        let v553: f64 = v551 - v552;
        let v554: f64 = v550 + v553;
        let v555: f64 = v147 * v339;
        let v556: f64 = v144 * v385;
        let v557: f64 = v555 - v556;
        let v558: f64 = v554 + v557;
        let v559: f64 = v119 * v415;
        let v560: f64 = v558 - v559;
        let v561: f64 = v541 - v560;
        let v562: f64 = v507 * v56;
        let v563: f64 = v499 * v22;
        let v564: f64 = v49 * v12;
        let v565: f64 = v563 - v564;
        let v566: f64 = v10 * v518;
        let v567: f64 = v42 * v16;
        let v568: f64 = v499 * v9;
        let v569: f64 = v567 - v568;
        let v570: f64 = v16 * v569;
        let v571: f64 = v566 - v570;
        let v572: f64 = v565 + v571;
        let v573: f64 = v562 + v572;
        let v574: f64 = v64 * v476;
        let v575: f64 = v61 * v415;
        let v576: f64 = v574 + v575;
        let v577: f64 = v573 + v576;
        let v578: f64 = v43 * v577;
        let v579: f64 = v561 + v578;
        let v580: f64 = -v560;
        let v581: f64 = -v357;
        (v445, v528, v579, v580, v581)
    };
    [v528, v579, v580, v445, v581, v306]
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
/// Operation count: 867 floating-point operations, 10 trig calls.
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
        v11,
        v12,
        v15,
        v17,
        v22,
        v25,
        v29,
        v33,
        v34,
        v38,
        v40,
        v45,
        v48,
        v50,
        v51,
        v53,
        v58,
        v61,
        v63,
        v69,
        v71,
        v74,
        v76,
        v79,
        v81,
        v83,
        v89,
        v93,
        v99,
        v102,
        v104,
        v111,
        v113,
        v122,
        v125,
        v127,
        v128,
        v130,
        v133,
        v134,
        v136,
        v138,
        v139,
        v141,
        v142,
        v146,
        v155,
        v160,
        v163,
        v165,
        v167,
        v168,
        v170,
        v176,
        v178,
        v179,
        v181,
        v183,
        v184,
        v185,
        v187,
        v190,
        v192,
        v193,
        v194,
        v195,
    ) = {
        let v0: f64 = tau[0];
        let v1: f64 = q[1];
        let (v2, v4): (f64, f64) = ::libm::sincos(v1);
        let v3: f64 = 1.03118515_f64;
        let v5: f64 = qd[0];
        let v6: f64 = v4 * v5;
        let v7: f64 = qd[1];
        let v8: f64 = v6 * v7;
        let v9: f64 = v3 * v8;
        let v10: f64 = 0.03798072_f64;
        let v11: f64 = v2 * v5;
        let v12: f64 = v11 * v7;
        let v13: f64 = v10 * v12;
        let v14: f64 = v9 - v13;
        let v15: f64 = 1.4401023_f64;
        let v16: f64 = v15 * v11;
        let v17: f64 = -0.023751_f64;
        let v18: f64 = v17 * v6;
        let v19: f64 = v16 + v18;
        let v20: f64 = 2.842524056_f64;
        let v21: f64 = v20 * v7;
        let v22: f64 = v19 + v21;
        let v23: f64 = v6 * v22;
        let v24: f64 = v10 * v11;
        let v25: f64 = 3.727456406_f64;
        let v26: f64 = v25 * v6;
        let v27: f64 = v24 + v26;
        let v28: f64 = v17 * v7;
        let v29: f64 = v27 + v28;
        let v30: f64 = v7 * v29;
        let v31: f64 = v23 - v30;
        let v32: f64 = v14 + v31;
        let v33: f64 = 0.1044_f64;
        let v34: f64 = 0.4318_f64;
        let v35: f64 = v34 * v12;
        let v36: f64 = v34 * v7;
        let v37: f64 = v11 * v36;
        let v38: f64 = v35 + v37;
        let v39: f64 = v33 * v38;
        let v40: f64 = 3.9585_f64;
        let v41: f64 = 9.81_f64;
        let v42: f64 = v41 * v4;
        let v43: f64 = v34 * v6;
        let v44: f64 = v11 * v43;
        let v45: f64 = v42 + v44;
        let v46: f64 = v40 * v45;
        let v47: f64 = v39 - v46;
        let v48: f64 = v32 + v47;
        let v49: f64 = q[2];
        let (v53, v50): (f64, f64) = ::libm::sincos(v49);
        let v51: f64 = 0.090474288_f64;
        let v52: f64 = v50 * v8;
        let v54: f64 = v53 * v12;
        let v55: f64 = v52 - v54;
        let v56: f64 = v50 * v6;
        let v57: f64 = v53 * v11;
        let v58: f64 = v56 - v57;
        let v59: f64 = qd[2];
        let v60: f64 = v58 * v59;
        let v61: f64 = v55 + v60;
        let v62: f64 = v51 * v61;
        let v63: f64 = 0.0068208_f64;
        let v64: f64 = v53 * v8;
        let v65: f64 = v50 * v12;
        let v66: f64 = v64 + v65;
        let v67: f64 = v50 * v11;
        let v68: f64 = v53 * v6;
        let v69: f64 = v67 + v68;
        let v70: f64 = v69 * v59;
        let v71: f64 = v66 + v70;
        let v72: f64 = v63 * v71;
        let v73: f64 = v62 - v72;
        let v74: f64 = v7 + v59;
        let v75: f64 = v63 * v69;
        let v76: f64 = 0.0047376_f64;
        let v77: f64 = v76 * v74;
        let v78: f64 = v75 - v77;
        let v79: f64 = 0.01543232_f64;
        let v80: f64 = v79 * v58;
        let v81: f64 = v78 + v80;
        let v82: f64 = v74 * v81;
        let v83: f64 = -0.001373904_f64;
        let v84: f64 = v83 * v69;
        let v85: f64 = 0.111498032_f64;
        let v86: f64 = v85 * v74;
        let v87: f64 = v84 - v86;
        let v88: f64 = v76 * v58;
        let v89: f64 = v87 + v88;
        let v90: f64 = v58 * v89;
        let v91: f64 = v82 + v90;
        let v92: f64 = v73 - v91;
        let v93: f64 = -0.06768_f64;
        let v94: f64 = v50 * v45;
        let v95: f64 = v41 * v2;
        let v96: f64 = v6 * v43;
        let v97: f64 = v7 * v36;
        let v98: f64 = v96 + v97;
        let v99: f64 = v95 - v98;
        let v100: f64 = v53 * v99;
        let v101: f64 = v94 - v100;
        let v102: f64 = -0.15005_f64;
        let v103: f64 = v102 * v61;
        let v104: f64 = 0.0203_f64;
        let v105: f64 = v104 * v58;
        let v106: f64 = v69 * v105;
        let v107: f64 = v102 * v58;
        let v108: f64 = v74 * v107;
        let v109: f64 = v106 - v108;
        let v110: f64 = v103 + v109;
        let v111: f64 = v101 + v110;
        let v112: f64 = v93 * v111;
        let v113: f64 = 0.336_f64;
        let v114: f64 = v104 * v71;
        let v115: f64 = v58 * v107;
        let v116: f64 = v102 * v69;
        let v117: f64 = v104 * v74;
        let v118: f64 = v116 + v117;
        let v119: f64 = v69 * v118;
        let v120: f64 = v115 + v119;
        let v121: f64 = v114 + v120;
        let v122: f64 = v38 + v121;
        let v123: f64 = v113 * v122;
        let v124: f64 = v112 + v123;
        let v125: f64 = v92 + v124;
        let v126: f64 = q[3];
        let (v130, v127): (f64, f64) = ::libm::sincos(v126);
        let v128: f64 = 0.00209602_f64;
        let v129: f64 = v127 * v61;
        let v131: f64 = v130 * v69;
        let v132: f64 = v127 * v74;
        let v133: f64 = v131 + v132;
        let v134: f64 = qd[3];
        let v135: f64 = v133 * v134;
        let v136: f64 = v129 - v135;
        let v137: f64 = v128 * v136;
        let v138: f64 = v58 + v134;
        let v139: f64 = v128 * v133;
        let v140: f64 = v138 * v139;
        let v141: f64 = 0.0013_f64;
        let v142: f64 = v141 * v138;
        let v143: f64 = v133 * v142;
        let v144: f64 = v140 - v143;
        let v145: f64 = v137 + v144;
        let v146: f64 = 0.01558_f64;
        let v147: f64 = v50 * v99;
        let v148: f64 = v53 * v45;
        let v149: f64 = v147 + v148;
        let v150: f64 = v102 * v71;
        let v151: f64 = v74 * v118;
        let v152: f64 = v58 * v105;
        let v153: f64 = v151 + v152;
        let v154: f64 = v150 - v153;
        let v155: f64 = v149 + v154;
        let v156: f64 = v130 * v155;
        let v157: f64 = v127 * v122;
        let v158: f64 = v156 + v157;
        let v159: f64 = v34 * v136;
        let v160: f64 = v34 * v133;
        let v161: f64 = v138 * v160;
        let v162: f64 = v159 + v161;
        let v163: f64 = v158 + v162;
        let v164: f64 = v146 * v163;
        let v165: f64 = v145 + v164;
        let v166: f64 = q[4];
        let (v170, v167): (f64, f64) = ::libm::sincos(v166);
        let v168: f64 = 0.0003_f64;
        let v169: f64 = v167 * v136;
        let v171: f64 = v170 * v71;
        let v172: f64 = v169 - v171;
        let v173: f64 = v167 * v138;
        let v174: f64 = v127 * v69;
        let v175: f64 = v130 * v74;
        let v176: f64 = v174 - v175;
        let v177: f64 = v170 * v176;
        let v178: f64 = v173 - v177;
        let v179: f64 = qd[4];
        let v180: f64 = v178 * v179;
        let v181: f64 = v172 + v180;
        let v182: f64 = v168 * v181;
        let v183: f64 = 0.0004_f64;
        let v184: f64 = v133 + v179;
        let v185: f64 = v183 * v184;
        let v186: f64 = v178 * v185;
        let v187: f64 = v168 * v178;
        let v188: f64 = v184 * v187;
        let v189: f64 = v186 - v188;
        let v190: f64 = v182 + v189;
        let v191: f64 = q[5];
        let (v195, v192): (f64, f64) = ::libm::sincos(v191);
        let v193: f64 = 0.00024216_f64;
        let v194: f64 = v192 * v181;
        (
            v0,
            v2,
            v3,
            v4,
            v6,
            v7,
            v8,
            v10,
            v11,
            v12,
            v15,
            v17,
            v22,
            v25,
            v29,
            v33,
            v34,
            v38,
            v40,
            v45,
            v48,
            v50,
            v51,
            v53,
            v58,
            v61,
            v63,
            v69,
            v71,
            v74,
            v76,
            v79,
            v81,
            v83,
            v89,
            v93,
            v99,
            v102,
            v104,
            v111,
            v113,
            v122,
            v125,
            v127,
            v128,
            v130,
            v133,
            v134,
            v136,
            v138,
            v139,
            v141,
            v142,
            v146,
            v155,
            v160,
            v163,
            v165,
            v167,
            v168,
            v170,
            v176,
            v178,
            v179,
            v181,
            v183,
            v184,
            v185,
            v187,
            v190,
            v192,
            v193,
            v194,
            v195,
        )
    };
    let (
        v214,
        v262,
        v279,
        v280,
        v310,
        v312,
        v316,
        v330,
        v356,
        v358,
        v362,
        v365,
        v368,
        v372,
        v386,
        v388,
        v389,
    ) = {
        let v196: f64 = v130 * v61;
        let v197: f64 = v176 * v134;
        let v198: f64 = v196 + v197;
        let v199: f64 = v195 * v198;
        let v200: f64 = v194 - v199;
        let v201: f64 = v167 * v176;
        let v202: f64 = v170 * v138;
        let v203: f64 = v201 + v202;
        let v204: f64 = v195 * v203;
        let v205: f64 = v192 * v184;
        let v206: f64 = v204 + v205;
        let v207: f64 = qd[5];
        let v208: f64 = v206 * v207;
        let v209: f64 = v200 - v208;
        let v210: f64 = v193 * v209;
        let v211: f64 = v178 + v207;
        let v212: f64 = v193 * v206;
        let v213: f64 = v211 * v212;
        let v214: f64 = 4e-05_f64;
        let v215: f64 = v214 * v211;
        let v216: f64 = v206 * v215;
        let v217: f64 = v213 - v216;
        let v218: f64 = v210 + v217;
        let v219: f64 = 0.00288_f64;
        let v220: f64 = v127 * v155;
        let v221: f64 = v130 * v122;
        let v222: f64 = v220 - v221;
        let v223: f64 = v34 * v176;
        let v224: f64 = v138 * v223;
        let v225: f64 = v34 * v198;
        let v226: f64 = v224 - v225;
        let v227: f64 = v222 + v226;
        let v228: f64 = v167 * v227;
        let v229: f64 = v133 * v160;
        let v230: f64 = v176 * v223;
        let v231: f64 = v229 + v230;
        let v232: f64 = v111 - v231;
        let v233: f64 = v170 * v232;
        let v234: f64 = v228 + v233;
        let v235: f64 = v195 * v234;
        let v236: f64 = v192 * v163;
        let v237: f64 = v235 + v236;
        let v238: f64 = v219 * v237;
        let v239: f64 = v218 + v238;
        let v240: f64 = v192 * v239;
        let v241: f64 = v192 * v203;
        let v242: f64 = v195 * v184;
        let v243: f64 = v241 - v242;
        let v244: f64 = v193 * v243;
        let v245: f64 = v211 * v244;
        let v246: f64 = v243 * v215;
        let v247: f64 = v245 - v246;
        let v248: f64 = v195 * v181;
        let v249: f64 = v192 * v198;
        let v250: f64 = v248 + v249;
        let v251: f64 = v243 * v207;
        let v252: f64 = v250 + v251;
        let v253: f64 = v193 * v252;
        let v254: f64 = v247 - v253;
        let v255: f64 = v192 * v234;
        let v256: f64 = v195 * v163;
        let v257: f64 = v255 - v256;
        let v258: f64 = v219 * v257;
        let v259: f64 = v254 + v258;
        let v260: f64 = v195 * v259;
        let v261: f64 = v240 - v260;
        let v262: f64 = v190 + v261;
        let v263: f64 = v167 * v262;
        let v264: f64 = v168 * v203;
        let v265: f64 = v184 * v264;
        let v266: f64 = v203 * v185;
        let v267: f64 = v265 - v266;
        let v268: f64 = v170 * v136;
        let v269: f64 = v167 * v71;
        let v270: f64 = v268 + v269;
        let v271: f64 = v203 * v179;
        let v272: f64 = v270 + v271;
        let v273: f64 = v168 * v272;
        let v274: f64 = v267 - v273;
        let v275: f64 = v206 * v244;
        let v276: f64 = v243 * v212;
        let v277: f64 = v275 - v276;
        let v278: f64 = v214 * v272;
        let v279: f64 = v277 - v278;
        let v280: f64 = v274 + v279;
        let v281: f64 = v170 * v280;
        let v282: f64 = v263 - v281;
        let v283: f64 = v165 + v282;
        let v284: f64 = 0.82_f64;
        let v285: f64 = v284 * v163;
        let v286: f64 = v146 * v136;
        let v287: f64 = v146 * v133;
        let v288: f64 = v138 * v287;
        let v289: f64 = v286 + v288;
        let v290: f64 = v285 + v289;
        let v291: f64 = 0.09_f64;
        let v292: f64 = v291 * v257;
        let v293: f64 = v219 * v243;
        let v294: f64 = v211 * v293;
        let v295: f64 = v219 * v252;
        let v296: f64 = v294 - v295;
        let v297: f64 = v292 + v296;
        let v298: f64 = v195 * v297;
        let v299: f64 = v291 * v237;
        let v300: f64 = v219 * v209;
        let v301: f64 = v219 * v206;
        let v302: f64 = v211 * v301;
        let v303: f64 = v300 + v302;
        let v304: f64 = v299 + v303;
        let v305: f64 = v192 * v304;
        let v306: f64 = v298 - v305;
        let v307: f64 = 0.34_f64;
        let v308: f64 = v307 * v163;
        let v309: f64 = v306 - v308;
        let v310: f64 = v290 - v309;
        let v311: f64 = v34 * v310;
        let v312: f64 = v283 + v311;
        let v313: f64 = v127 * v312;
        let v314: f64 = v128 * v198;
        let v315: f64 = v176 * v142;
        let v316: f64 = v128 * v176;
        let v317: f64 = v138 * v316;
        let v318: f64 = v315 - v317;
        let v319: f64 = v314 + v318;
        let v320: f64 = v146 * v227;
        let v321: f64 = v319 - v320;
        let v322: f64 = v178 * v264;
        let v323: f64 = v203 * v187;
        let v324: f64 = v322 - v323;
        let v325: f64 = v183 * v198;
        let v326: f64 = v324 - v325;
        let v327: f64 = v195 * v239;
        let v328: f64 = v192 * v259;
        let v329: f64 = v327 + v328;
        let v330: f64 = v326 + v329;
        let v331: f64 = v321 - v330;
        let v332: f64 = v284 * v227;
        let v333: f64 = v146 * v176;
        let v334: f64 = v138 * v333;
        let v335: f64 = v146 * v198;
        let v336: f64 = v334 - v335;
        let v337: f64 = v332 + v336;
        let v338: f64 = v307 * v234;
        let v339: f64 = v192 * v297;
        let v340: f64 = v195 * v304;
        let v341: f64 = v339 + v340;
        let v342: f64 = v338 + v341;
        let v343: f64 = v167 * v342;
        let v344: f64 = v167 * v232;
        let v345: f64 = v170 * v227;
        let v346: f64 = v344 - v345;
        let v347: f64 = v307 * v346;
        let v348: f64 = v291 * v346;
        let v349: f64 = v243 * v293;
        let v350: f64 = v206 * v301;
        let v351: f64 = v349 + v350;
        let v352: f64 = v348 - v351;
        let v353: f64 = v347 + v352;
        let v354: f64 = v170 * v353;
        let v355: f64 = v343 - v354;
        let v356: f64 = v337 + v355;
        let v357: f64 = v34 * v356;
        let v358: f64 = v331 - v357;
        let v359: f64 = v130 * v358;
        let v360: f64 = v313 + v359;
        let v361: f64 = v125 + v360;
        let v362: f64 = 4.8_f64;
        let v363: f64 = v362 * v111;
        let v364: f64 = v93 * v61;
        let v365: f64 = -0.09744_f64;
        let v366: f64 = v365 * v58;
        let v367: f64 = v113 * v69;
        let v368: f64 = v366 - v367;
        let v369: f64 = v69 * v368;
        let v370: f64 = v113 * v74;
        let v371: f64 = v93 * v58;
        let v372: f64 = v370 + v371;
        let v373: f64 = v74 * v372;
        let v374: f64 = v369 - v373;
        let v375: f64 = v364 + v374;
        let v376: f64 = v363 + v375;
        let v377: f64 = v284 * v232;
        let v378: f64 = v133 * v287;
        let v379: f64 = v176 * v333;
        let v380: f64 = v378 + v379;
        let v381: f64 = v377 - v380;
        let v382: f64 = v170 * v342;
        let v383: f64 = v167 * v353;
        let v384: f64 = v382 + v383;
        let v385: f64 = v381 + v384;
        let v386: f64 = v376 + v385;
        let v387: f64 = v102 * v386;
        let v388: f64 = v361 + v387;
        let v389: f64 = v50 * v388;
        (
            v214,
            v262,
            v279,
            v280,
            v310,
            v312,
            v316,
            v330,
            v356,
            v358,
            v362,
            v365,
            v368,
            v372,
            v386,
            v388,
            v389,
        )
    };
    let (
        v398,
        v414,
        v443,
        v458,
        v464,
        v472,
        v483,
        v494,
        v495,
        v497,
        v506,
        v507,
        v509,
        v512,
        v514,
        v516,
        v526,
        v532,
        v533,
        v534,
        v535,
        v538,
        v539,
        v541,
        v548,
        v549,
        v551,
        v553,
        v555,
        v556,
        v557,
        v558,
        v576,
        v577,
        v583,
        v584,
    ) = {
        let v390: f64 = v63 * v61;
        let v391: f64 = v79 * v71;
        let v392: f64 = v390 - v391;
        let v393: f64 = v69 * v89;
        let v394: f64 = v51 * v69;
        let v395: f64 = v83 * v74;
        let v396: f64 = v394 - v395;
        let v397: f64 = v63 * v58;
        let v398: f64 = v396 + v397;
        let v399: f64 = v74 * v398;
        let v400: f64 = v393 + v399;
        let v401: f64 = v392 + v400;
        let v402: f64 = v365 * v122;
        let v403: f64 = v93 * v155;
        let v404: f64 = v402 + v403;
        let v405: f64 = v401 - v404;
        let v406: f64 = v133 * v316;
        let v407: f64 = v176 * v139;
        let v408: f64 = v406 - v407;
        let v409: f64 = v141 * v71;
        let v410: f64 = v408 - v409;
        let v411: f64 = v170 * v262;
        let v412: f64 = v167 * v280;
        let v413: f64 = v411 + v412;
        let v414: f64 = v410 + v413;
        let v415: f64 = v405 + v414;
        let v416: f64 = v130 * v356;
        let v417: f64 = v127 * v310;
        let v418: f64 = v416 - v417;
        let v419: f64 = v362 * v122;
        let v420: f64 = v365 * v71;
        let v421: f64 = v113 * v61;
        let v422: f64 = v420 + v421;
        let v423: f64 = v58 * v372;
        let v424: f64 = v93 * v69;
        let v425: f64 = v365 * v74;
        let v426: f64 = v424 + v425;
        let v427: f64 = v69 * v426;
        let v428: f64 = v423 + v427;
        let v429: f64 = v422 + v428;
        let v430: f64 = v419 + v429;
        let v431: f64 = v418 - v430;
        let v432: f64 = v104 * v431;
        let v433: f64 = v362 * v155;
        let v434: f64 = v93 * v71;
        let v435: f64 = v74 * v426;
        let v436: f64 = v58 * v368;
        let v437: f64 = v435 + v436;
        let v438: f64 = v434 - v437;
        let v439: f64 = v433 + v438;
        let v440: f64 = v127 * v356;
        let v441: f64 = v130 * v310;
        let v442: f64 = v440 + v441;
        let v443: f64 = v439 + v442;
        let v444: f64 = v102 * v443;
        let v445: f64 = v432 - v444;
        let v446: f64 = v415 + v445;
        let v447: f64 = v53 * v446;
        let v448: f64 = v389 - v447;
        let v449: f64 = v48 + v448;
        let v450: f64 = v2 * v449;
        let v451: f64 = v10 * v8;
        let v452: f64 = v25 * v12;
        let v453: f64 = v451 - v452;
        let v454: f64 = v3 * v11;
        let v455: f64 = v10 * v6;
        let v456: f64 = v454 + v455;
        let v457: f64 = v15 * v7;
        let v458: f64 = v456 + v457;
        let v459: f64 = v7 * v458;
        let v460: f64 = v11 * v22;
        let v461: f64 = v459 - v460;
        let v462: f64 = v453 + v461;
        let v463: f64 = v40 * v99;
        let v464: f64 = -6.33012_f64;
        let v465: f64 = v464 * v38;
        let v466: f64 = v463 - v465;
        let v467: f64 = v462 + v466;
        let v468: f64 = v53 * v388;
        let v469: f64 = v50 * v446;
        let v470: f64 = v468 + v469;
        let v471: f64 = v467 + v470;
        let v472: f64 = 17.4_f64;
        let v473: f64 = v472 * v38;
        let v474: f64 = v33 * v8;
        let v475: f64 = v464 * v12;
        let v476: f64 = v474 + v475;
        let v477: f64 = v464 * v7;
        let v478: f64 = v40 * v11;
        let v479: f64 = v477 - v478;
        let v480: f64 = v11 * v479;
        let v481: f64 = v40 * v6;
        let v482: f64 = v33 * v7;
        let v483: f64 = v481 - v482;
        let v484: f64 = v6 * v483;
        let v485: f64 = v480 - v484;
        let v486: f64 = v476 + v485;
        let v487: f64 = v473 + v486;
        let v488: f64 = v487 - v431;
        let v489: f64 = v34 * v488;
        let v490: f64 = v471 - v489;
        let v491: f64 = v4 * v490;
        let v492: f64 = v450 + v491;
        let v493: f64 = v0 - v492;
        let v494: f64 = 24999.999999999996_f64;
        let v495: f64 = v214 * v167;
        let v496: f64 = v495 * v50;
        let v497: f64 = v214 * v170;
        let v498: f64 = v497 * v127;
        let v499: f64 = v498 * v53;
        let v500: f64 = v496 - v499;
        let v501: f64 = v500 * v4;
        let v502: f64 = v498 * v50;
        let v503: f64 = v495 * v53;
        let v504: f64 = v502 + v503;
        let v505: f64 = v504 * v2;
        let v506: f64 = v501 - v505;
        let v507: f64 = v494 * v506;
        let v508: f64 = tau[5];
        let v509: f64 = v508 - v279;
        let v510: f64 = v507 * v509;
        let v511: f64 = v493 - v510;
        let v512: f64 = 1557.24430048586_f64;
        let v513: f64 = 0.000432144_f64;
        let v514: f64 = v513 * v170;
        let v515: f64 = v514 * v53;
        let v516: f64 = v513 * v167;
        let v517: f64 = v516 * v127;
        let v518: f64 = v517 * v50;
        let v519: f64 = v515 - v518;
        let v520: f64 = v519 * v4;
        let v521: f64 = v514 * v50;
        let v522: f64 = v517 * v53;
        let v523: f64 = v521 + v522;
        let v524: f64 = v523 * v2;
        let v525: f64 = v520 + v524;
        let v526: f64 = 0.00064216_f64;
        let v527: f64 = v526 * v53;
        let v528: f64 = v527 * v4;
        let v529: f64 = v526 * v50;
        let v530: f64 = v529 * v2;
        let v531: f64 = v528 + v530;
        let v532: f64 = 0.001243584_f64;
        let v533: f64 = v532 * v50;
        let v534: f64 = 5.8464e-05_f64;
        let v535: f64 = v534 * v53;
        let v536: f64 = v533 + v535;
        let v537: f64 = v536 * v2;
        let v538: f64 = -0.001243584_f64;
        let v539: f64 = v534 * v50;
        let v540: f64 = v538 - v539;
        let v541: f64 = v532 * v53;
        let v542: f64 = v540 + v541;
        let v543: f64 = v542 * v4;
        let v544: f64 = v537 + v543;
        let v545: f64 = v544 * v167;
        let v546: f64 = v531 + v545;
        let v547: f64 = v546 * v130;
        let v548: f64 = v525 + v547;
        let v549: f64 = v512 * v548;
        let v550: f64 = tau[4];
        let v551: f64 = v550 + v330;
        let v552: f64 = v549 * v551;
        let v553: f64 = v511 - v552;
        let v554: f64 = 0.00184216_f64;
        let v555: f64 = 0.00020216_f64;
        let v556: f64 = v555 * v167;
        let v557: f64 = v556 * v167;
        let v558: f64 = v554 - v557;
        let v559: f64 = v558 * v50;
        let v560: f64 = v559 * v4;
        let v561: f64 = -0.00184216_f64;
        let v562: f64 = v561 + v557;
        let v563: f64 = v562 * v53;
        let v564: f64 = v563 * v2;
        let v565: f64 = v560 + v564;
        let v566: f64 = v513 * v50;
        let v567: f64 = v566 * v4;
        let v568: f64 = v513 * v53;
        let v569: f64 = v568 * v2;
        let v570: f64 = v567 - v569;
        let v571: f64 = v570 * v130;
        let v572: f64 = v532 + v556;
        let v573: f64 = v572 * v50;
        let v574: f64 = v535 + v573;
        let v575: f64 = v574 * v2;
        let v576: f64 = v572 * v53;
        let v577: f64 = v540 + v576;
        let v578: f64 = v577 * v4;
        let v579: f64 = v575 + v578;
        let v580: f64 = v579 * v127;
        let v581: f64 = v571 + v580;
        let v582: f64 = v581 * v170;
        let v583: f64 = v565 + v582;
        let v584: f64 = v494 * v495;
        (
            v398,
            v414,
            v443,
            v458,
            v464,
            v472,
            v483,
            v494,
            v495,
            v497,
            v506,
            v507,
            v509,
            v512,
            v514,
            v516,
            v526,
            v532,
            v533,
            v534,
            v535,
            v538,
            v539,
            v541,
            v548,
            v549,
            v551,
            v553,
            v555,
            v556,
            v557,
            v558,
            v576,
            v577,
            v583,
            v584,
        )
    };
    let (
        v586,
        v588,
        v589,
        v593,
        v612,
        v632,
        v640,
        v647,
        v649,
        v651,
        v653,
        v656,
        v657,
        v666,
        v667,
        v685,
        v687,
        v692,
        v694,
        v723,
        v730,
        v753,
        v755,
        v757,
        v761,
        v763,
        v779,
    ) = {
        let v585: f64 = v506 * v584;
        let v586: f64 = v583 - v585;
        let v587: f64 = v495 * v584;
        let v588: f64 = v558 - v587;
        let v589: f64 = v586 / v588;
        let v590: f64 = tau[3];
        let v591: f64 = v590 - v414;
        let v592: f64 = v584 * v509;
        let v593: f64 = v591 - v592;
        let v594: f64 = v589 * v593;
        let v595: f64 = v553 - v594;
        let v596: f64 = -0.1384816665_f64;
        let v597: f64 = v596 - v516;
        let v598: f64 = v597 * v50;
        let v599: f64 = -0.00380751875_f64;
        let v600: f64 = v514 * v127;
        let v601: f64 = v599 + v600;
        let v602: f64 = v601 * v53;
        let v603: f64 = v598 + v602;
        let v604: f64 = v603 * v4;
        let v605: f64 = v601 * v50;
        let v606: f64 = 0.1384816665_f64;
        let v607: f64 = v606 + v516;
        let v608: f64 = v607 * v53;
        let v609: f64 = v605 + v608;
        let v610: f64 = v609 * v2;
        let v611: f64 = v604 + v610;
        let v612: f64 = 0.00030216_f64;
        let v613: f64 = v612 - v557;
        let v614: f64 = v613 * v53;
        let v615: f64 = v614 * v4;
        let v616: f64 = v613 * v50;
        let v617: f64 = v616 * v2;
        let v618: f64 = v615 + v617;
        let v619: f64 = v618 * v127;
        let v620: f64 = v538 - v556;
        let v621: f64 = v620 * v50;
        let v622: f64 = v621 - v535;
        let v623: f64 = v622 * v4;
        let v624: f64 = v576 - v539;
        let v625: f64 = v624 * v2;
        let v626: f64 = v623 + v625;
        let v627: f64 = v626 * v170;
        let v628: f64 = v619 + v627;
        let v629: f64 = v628 * v130;
        let v630: f64 = v611 + v629;
        let v631: f64 = v497 * v130;
        let v632: f64 = v494 * v631;
        let v633: f64 = v506 * v632;
        let v634: f64 = v630 - v633;
        let v635: f64 = v532 * v167;
        let v636: f64 = v526 + v635;
        let v637: f64 = v636 * v127;
        let v638: f64 = v534 * v170;
        let v639: f64 = v637 - v638;
        let v640: f64 = v512 * v639;
        let v641: f64 = v548 * v640;
        let v642: f64 = v634 - v641;
        let v643: f64 = v620 * v170;
        let v644: f64 = v643 * v130;
        let v645: f64 = v631 * v584;
        let v646: f64 = v644 - v645;
        let v647: f64 = v646 / v588;
        let v648: f64 = v586 * v647;
        let v649: f64 = v642 - v648;
        let v650: f64 = 0.3589900705_f64;
        let v651: f64 = 0.002487168_f64;
        let v652: f64 = v651 + v556;
        let v653: f64 = v652 * v167;
        let v654: f64 = v650 + v653;
        let v655: f64 = v613 * v127;
        let v656: f64 = 0.000116928_f64;
        let v657: f64 = v656 * v170;
        let v658: f64 = v655 - v657;
        let v659: f64 = v658 * v127;
        let v660: f64 = v654 + v659;
        let v661: f64 = v631 * v632;
        let v662: f64 = v660 - v661;
        let v663: f64 = v639 * v640;
        let v664: f64 = v662 - v663;
        let v665: f64 = v646 * v647;
        let v666: f64 = v664 - v665;
        let v667: f64 = v649 / v666;
        let v668: f64 = tau[2];
        let v669: f64 = v83 * v61;
        let v670: f64 = v76 * v71;
        let v671: f64 = v669 - v670;
        let v672: f64 = v58 * v398;
        let v673: f64 = v69 * v81;
        let v674: f64 = v672 - v673;
        let v675: f64 = v671 + v674;
        let v676: f64 = v113 * v155;
        let v677: f64 = v365 * v111;
        let v678: f64 = v676 - v677;
        let v679: f64 = v675 + v678;
        let v680: f64 = v130 * v312;
        let v681: f64 = v127 * v358;
        let v682: f64 = v680 - v681;
        let v683: f64 = v679 + v682;
        let v684: f64 = v104 * v386;
        let v685: f64 = v683 - v684;
        let v686: f64 = v668 + v685;
        let v687: f64 = v632 * v509;
        let v688: f64 = v686 - v687;
        let v689: f64 = v640 * v551;
        let v690: f64 = v688 - v689;
        let v691: f64 = v647 * v593;
        let v692: f64 = v690 - v691;
        let v693: f64 = v667 * v692;
        let v694: f64 = v595 - v693;
        let v695: f64 = v597 + v644;
        let v696: f64 = v695 * v50;
        let v697: f64 = v17 + v696;
        let v698: f64 = v655 - v638;
        let v699: f64 = v698 * v130;
        let v700: f64 = v601 + v699;
        let v701: f64 = v700 * v53;
        let v702: f64 = v697 + v701;
        let v703: f64 = v702 * v4;
        let v704: f64 = -0.6903913435_f64;
        let v705: f64 = v704 + v605;
        let v706: f64 = v705 + v608;
        let v707: f64 = v655 * v50;
        let v708: f64 = v577 * v170;
        let v709: f64 = v707 + v708;
        let v710: f64 = v709 * v130;
        let v711: f64 = v706 + v710;
        let v712: f64 = v711 * v2;
        let v713: f64 = v703 + v712;
        let v714: f64 = v713 - v633;
        let v715: f64 = -5.8464e-05_f64;
        let v716: f64 = v715 - v533;
        let v717: f64 = v716 * v170;
        let v718: f64 = v532 - v541;
        let v719: f64 = v718 * v167;
        let v720: f64 = v526 + v719;
        let v721: f64 = v720 * v127;
        let v722: f64 = v717 + v721;
        let v723: f64 = v512 * v722;
        let v724: f64 = v548 * v723;
        let v725: f64 = v714 - v724;
        let v726: f64 = v620 + v541;
        let v727: f64 = v726 * v170;
        let v728: f64 = v727 * v130;
        let v729: f64 = v728 - v645;
        let v730: f64 = v729 / v588;
        let v731: f64 = v586 * v730;
        let v732: f64 = v725 - v731;
        let v733: f64 = 0.010956925_f64;
        let v734: f64 = v733 * v50;
        let v735: f64 = v650 + v734;
        let v736: f64 = 0.384876294_f64;
        let v737: f64 = v736 * v53;
        let v738: f64 = v735 - v737;
        let v739: f64 = v652 - v541;
        let v740: f64 = v739 * v167;
        let v741: f64 = v738 + v740;
        let v742: f64 = -0.000116928_f64;
        let v743: f64 = v742 - v533;
        let v744: f64 = v743 * v170;
        let v745: f64 = v744 + v655;
        let v746: f64 = v745 * v127;
        let v747: f64 = v741 + v746;
        let v748: f64 = v747 - v661;
        let v749: f64 = v722 * v640;
        let v750: f64 = v748 - v749;
        let v751: f64 = v729 * v647;
        let v752: f64 = v750 - v751;
        let v753: f64 = v752 / v666;
        let v754: f64 = v649 * v753;
        let v755: f64 = v732 - v754;
        let v756: f64 = 2.1071040725_f64;
        let v757: f64 = 0.02191385_f64;
        let v758: f64 = v757 * v50;
        let v759: f64 = v756 + v758;
        let v760: f64 = 0.769752588_f64;
        let v761: f64 = v760 * v53;
        let v762: f64 = v759 - v761;
        let v763: f64 = v651 * v53;
        let v764: f64 = v652 - v763;
        let v765: f64 = v764 * v167;
        let v766: f64 = v762 + v765;
        let v767: f64 = v651 * v50;
        let v768: f64 = v742 - v767;
        let v769: f64 = v768 * v170;
        let v770: f64 = v769 + v655;
        let v771: f64 = v770 * v127;
        let v772: f64 = v766 + v771;
        let v773: f64 = v772 - v661;
        let v774: f64 = v722 * v723;
        let v775: f64 = v773 - v774;
        let v776: f64 = v729 * v730;
        let v777: f64 = v775 - v776;
        let v778: f64 = v752 * v753;
        let v779: f64 = v777 - v778;
        (
            v586,
            v588,
            v589,
            v593,
            v612,
            v632,
            v640,
            v647,
            v649,
            v651,
            v653,
            v656,
            v657,
            v666,
            v667,
            v685,
            v687,
            v692,
            v694,
            v723,
            v730,
            v753,
            v755,
            v757,
            v761,
            v763,
            v779,
        )
    };
    let (v941, v944, v949, v956, v963, v972) = {
        let v780: f64 = v755 / v779;
        let v781: f64 = tau[1];
        let v782: f64 = v15 * v8;
        let v783: f64 = v17 * v12;
        let v784: f64 = v782 - v783;
        let v785: f64 = v11 * v29;
        let v786: f64 = v6 * v458;
        let v787: f64 = v785 - v786;
        let v788: f64 = v784 + v787;
        let v789: f64 = v464 * v45;
        let v790: f64 = v33 * v99;
        let v791: f64 = v789 - v790;
        let v792: f64 = v788 + v791;
        let v793: f64 = v792 - v685;
        let v794: f64 = v472 * v45;
        let v795: f64 = v7 * v483;
        let v796: f64 = v33 * v11;
        let v797: f64 = v464 * v6;
        let v798: f64 = v796 - v797;
        let v799: f64 = v11 * v798;
        let v800: f64 = v795 - v799;
        let v801: f64 = v40 * v8;
        let v802: f64 = v800 - v801;
        let v803: f64 = v794 + v802;
        let v804: f64 = v53 * v443;
        let v805: f64 = v50 * v386;
        let v806: f64 = v804 + v805;
        let v807: f64 = v803 + v806;
        let v808: f64 = v34 * v807;
        let v809: f64 = v793 + v808;
        let v810: f64 = v781 - v809;
        let v811: f64 = v810 - v687;
        let v812: f64 = v723 * v551;
        let v813: f64 = v811 - v812;
        let v814: f64 = v730 * v593;
        let v815: f64 = v813 - v814;
        let v816: f64 = v753 * v692;
        let v817: f64 = v815 - v816;
        let v818: f64 = v780 * v817;
        let v819: f64 = v694 - v818;
        let v820: f64 = 1.553523243625_f64;
        let v821: f64 = v820 - v557;
        let v822: f64 = 0.000864288_f64;
        let v823: f64 = v822 * v130;
        let v824: f64 = v656 * v127;
        let v825: f64 = v823 - v824;
        let v826: f64 = v825 * v170;
        let v827: f64 = v821 + v826;
        let v828: f64 = 0.022546398_f64;
        let v829: f64 = v656 * v167;
        let v830: f64 = v828 + v829;
        let v831: f64 = -0.002487168_f64;
        let v832: f64 = 0.00040432_f64;
        let v833: f64 = v832 * v167;
        let v834: f64 = v831 - v833;
        let v835: f64 = v834 * v170;
        let v836: f64 = v835 * v127;
        let v837: f64 = v830 + v836;
        let v838: f64 = v837 * v53;
        let v839: f64 = 0.3239198455_f64;
        let v840: f64 = v839 + v653;
        let v841: f64 = -0.00030216_f64;
        let v842: f64 = v841 + v557;
        let v843: f64 = v842 * v127;
        let v844: f64 = v657 + v843;
        let v845: f64 = v844 * v127;
        let v846: f64 = v840 + v845;
        let v847: f64 = v846 * v50;
        let v848: f64 = v838 + v847;
        let v849: f64 = v848 * v50;
        let v850: f64 = v827 + v849;
        let v851: f64 = 0.008347998_f64;
        let v852: f64 = v851 + v829;
        let v853: f64 = v757 * v53;
        let v854: f64 = v852 - v853;
        let v855: f64 = v834 + v763;
        let v856: f64 = v855 * v170;
        let v857: f64 = v856 * v127;
        let v858: f64 = v854 + v857;
        let v859: f64 = v858 * v2;
        let v860: f64 = 1.9257810475_f64;
        let v861: f64 = v860 - v761;
        let v862: f64 = v612 * v127;
        let v863: f64 = v657 - v862;
        let v864: f64 = v863 * v127;
        let v865: f64 = v861 + v864;
        let v866: f64 = v651 - v763;
        let v867: f64 = v555 * v127;
        let v868: f64 = v867 * v127;
        let v869: f64 = v555 + v868;
        let v870: f64 = v869 * v167;
        let v871: f64 = v866 + v870;
        let v872: f64 = v871 * v167;
        let v873: f64 = v865 + v872;
        let v874: f64 = v873 * v4;
        let v875: f64 = v859 + v874;
        let v876: f64 = v651 * v170;
        let v877: f64 = v876 * v127;
        let v878: f64 = v757 - v877;
        let v879: f64 = -0.045092796_f64;
        let v880: f64 = 0.000233856_f64;
        let v881: f64 = v880 * v167;
        let v882: f64 = v879 - v881;
        let v883: f64 = 0.004974336_f64;
        let v884: f64 = 0.00080864_f64;
        let v885: f64 = v884 * v167;
        let v886: f64 = v883 + v885;
        let v887: f64 = v886 * v170;
        let v888: f64 = v887 * v127;
        let v889: f64 = v882 + v888;
        let v890: f64 = v889 * v53;
        let v891: f64 = v878 + v890;
        let v892: f64 = -0.647839691_f64;
        let v893: f64 = -0.004974336_f64;
        let v894: f64 = v893 - v833;
        let v895: f64 = v894 * v167;
        let v896: f64 = v892 + v895;
        let v897: f64 = 0.00060432_f64;
        let v898: f64 = v833 * v167;
        let v899: f64 = v897 - v898;
        let v900: f64 = v899 * v127;
        let v901: f64 = v880 * v170;
        let v902: f64 = v900 - v901;
        let v903: f64 = v902 * v127;
        let v904: f64 = v896 + v903;
        let v905: f64 = v904 * v50;
        let v906: f64 = v891 + v905;
        let v907: f64 = v906 * v4;
        let v908: f64 = -0.769752588_f64;
        let v909: f64 = v651 * v167;
        let v910: f64 = v908 - v909;
        let v911: f64 = v889 * v50;
        let v912: f64 = v910 + v911;
        let v913: f64 = 0.647839691_f64;
        let v914: f64 = v883 + v833;
        let v915: f64 = v914 * v167;
        let v916: f64 = v913 + v915;
        let v917: f64 = -0.00060432_f64;
        let v918: f64 = v917 + v898;
        let v919: f64 = v918 * v127;
        let v920: f64 = v901 + v919;
        let v921: f64 = v920 * v127;
        let v922: f64 = v916 + v921;
        let v923: f64 = v922 * v53;
        let v924: f64 = v912 + v923;
        let v925: f64 = v924 * v2;
        let v926: f64 = v907 + v925;
        let v927: f64 = v926 * v50;
        let v928: f64 = v875 + v927;
        let v929: f64 = v928 * v4;
        let v930: f64 = v850 + v929;
        let v931: f64 = v506 * v507;
        let v932: f64 = v930 - v931;
        let v933: f64 = v548 * v549;
        let v934: f64 = v932 - v933;
        let v935: f64 = v586 * v589;
        let v936: f64 = v934 - v935;
        let v937: f64 = v649 * v667;
        let v938: f64 = v936 - v937;
        let v939: f64 = v755 * v780;
        let v940: f64 = v938 - v939;
        let v941: f64 = v819 / v940;
        let v942: f64 = v817 / v779;
        let v943: f64 = v780 * v941;
        let v944: f64 = v942 - v943;
        let v945: f64 = v692 / v666;
        let v946: f64 = v667 * v941;
        let v947: f64 = v945 - v946;
        let v948: f64 = v753 * v944;
        let v949: f64 = v947 - v948;
        let v950: f64 = v593 / v588;
        let v951: f64 = v589 * v941;
        let v952: f64 = v950 - v951;
        let v953: f64 = v730 * v944;
        let v954: f64 = v952 - v953;
        let v955: f64 = v647 * v949;
        let v956: f64 = v954 - v955;
        let v957: f64 = v512 * v551;
        let v958: f64 = v549 * v941;
        let v959: f64 = v957 - v958;
        let v960: f64 = v723 * v944;
        let v961: f64 = v959 - v960;
        let v962: f64 = v640 * v949;
        let v963: f64 = v961 - v962;
        let v964: f64 = v494 * v509;
        let v965: f64 = v507 * v941;
        let v966: f64 = v964 - v965;
        let v967: f64 = v632 * v944;
        let v968: f64 = v966 - v967;
        let v969: f64 = v632 * v949;
        let v970: f64 = v968 - v969;
        let v971: f64 = v584 * v956;
        let v972: f64 = v970 - v971;
        (v941, v944, v949, v956, v963, v972)
    };
    [v941, v944, v949, v956, v963, v972]
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
/// Operation count: 746 floating-point operations, 10 trig calls.
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
        v136,
        v138,
        v139,
        v140,
        v141,
        v142,
        v144,
        v149,
        v151,
        v152,
        v153,
        v154,
        v155,
        v161,
        v163,
        v167,
        v168,
    ) = {
        let v0: f64 = 1.553523243625_f64;
        let v1: f64 = 0.00020216_f64;
        let v2: f64 = q[4];
        let (v15, v3): (f64, f64) = ::libm::sincos(v2);
        let v4: f64 = v1 * v3;
        let v5: f64 = v4 * v3;
        let v6: f64 = v0 - v5;
        let v7: f64 = 0.000864288_f64;
        let v8: f64 = q[3];
        let (v9, v12): (f64, f64) = ::libm::sincos(v8);
        let v10: f64 = v7 * v9;
        let v11: f64 = 0.000116928_f64;
        let v13: f64 = v11 * v12;
        let v14: f64 = v10 - v13;
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
        let (v29, v43): (f64, f64) = ::libm::sincos(v28);
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
        let (v59, v78): (f64, f64) = ::libm::sincos(v58);
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
        let v160: f64 = v147 + v159;
        let v161: f64 = v160 * v78;
        let v162: f64 = -0.6903913435_f64;
        let v163: f64 = v151 * v43;
        let v164: f64 = v162 + v163;
        let v165: f64 = 0.1384816665_f64;
        let v166: f64 = v165 + v139;
        let v167: f64 = v166 * v29;
        let v168: f64 = v164 + v167;
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
            v136,
            v138,
            v139,
            v140,
            v141,
            v142,
            v144,
            v149,
            v151,
            v152,
            v153,
            v154,
            v155,
            v161,
            v163,
            v167,
            v168,
        )
    };
    let (
        v172,
        v181,
        v205,
        v207,
        v229,
        v240,
        v246,
        v249,
        v256,
        v257,
        v258,
        v260,
        v269,
        v270,
        v272,
        v273,
        v274,
        v276,
        v277,
        v278,
        v281,
        v287,
        v290,
        v294,
        v298,
        v299,
        v301,
        v303,
        v305,
        v306,
        v308,
        v310,
        v313,
        v314,
        v320,
        v323,
        v325,
        v331,
        v333,
        v335,
        v336,
        v337,
    ) = {
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
        let v270: f64 = 1.03118515_f64;
        let v271: f64 = qd[0];
        let v272: f64 = v78 * v271;
        let v273: f64 = qd[1];
        let v274: f64 = v272 * v273;
        let v275: f64 = v270 * v274;
        let v276: f64 = 0.03798072_f64;
        let v277: f64 = v59 * v271;
        let v278: f64 = v277 * v273;
        let v279: f64 = v276 * v278;
        let v280: f64 = v275 - v279;
        let v281: f64 = 1.4401023_f64;
        let v282: f64 = v281 * v277;
        let v283: f64 = v136 * v272;
        let v284: f64 = v282 + v283;
        let v285: f64 = 2.842524056_f64;
        let v286: f64 = v285 * v273;
        let v287: f64 = v284 + v286;
        let v288: f64 = v272 * v287;
        let v289: f64 = v276 * v277;
        let v290: f64 = 3.727456406_f64;
        let v291: f64 = v290 * v272;
        let v292: f64 = v289 + v291;
        let v293: f64 = v136 * v273;
        let v294: f64 = v292 + v293;
        let v295: f64 = v273 * v294;
        let v296: f64 = v288 - v295;
        let v297: f64 = v280 + v296;
        let v298: f64 = 0.1044_f64;
        let v299: f64 = 0.4318_f64;
        let v300: f64 = v299 * v278;
        let v301: f64 = v299 * v273;
        let v302: f64 = v277 * v301;
        let v303: f64 = v300 + v302;
        let v304: f64 = v298 * v303;
        let v305: f64 = 3.9585_f64;
        let v306: f64 = 9.81_f64;
        let v307: f64 = v306 * v78;
        let v308: f64 = v299 * v272;
        let v309: f64 = v277 * v308;
        let v310: f64 = v307 + v309;
        let v311: f64 = v305 * v310;
        let v312: f64 = v304 - v311;
        let v313: f64 = v297 + v312;
        let v314: f64 = 0.090474288_f64;
        let v315: f64 = v43 * v274;
        let v316: f64 = v29 * v278;
        let v317: f64 = v315 - v316;
        let v318: f64 = v43 * v272;
        let v319: f64 = v29 * v277;
        let v320: f64 = v318 - v319;
        let v321: f64 = qd[2];
        let v322: f64 = v320 * v321;
        let v323: f64 = v317 + v322;
        let v324: f64 = v314 * v323;
        let v325: f64 = 0.0068208_f64;
        let v326: f64 = v29 * v274;
        let v327: f64 = v43 * v278;
        let v328: f64 = v326 + v327;
        let v329: f64 = v43 * v277;
        let v330: f64 = v29 * v272;
        let v331: f64 = v329 + v330;
        let v332: f64 = v331 * v321;
        let v333: f64 = v328 + v332;
        let v334: f64 = v325 * v333;
        let v335: f64 = v324 - v334;
        let v336: f64 = v273 + v321;
        let v337: f64 = v325 * v331;
        (
            v172,
            v181,
            v205,
            v207,
            v229,
            v240,
            v246,
            v249,
            v256,
            v257,
            v258,
            v260,
            v269,
            v270,
            v272,
            v273,
            v274,
            v276,
            v277,
            v278,
            v281,
            v287,
            v290,
            v294,
            v298,
            v299,
            v301,
            v303,
            v305,
            v306,
            v308,
            v310,
            v313,
            v314,
            v320,
            v323,
            v325,
            v331,
            v333,
            v335,
            v336,
            v337,
        )
    };
    let (
        v338,
        v341,
        v343,
        v345,
        v351,
        v355,
        v361,
        v364,
        v366,
        v373,
        v375,
        v384,
        v387,
        v388,
        v392,
        v395,
        v397,
        v398,
        v400,
        v401,
        v405,
        v414,
        v422,
        v424,
        v425,
        v432,
        v434,
        v435,
        v439,
        v440,
        v441,
        v443,
        v446,
        v448,
        v449,
        v451,
        v454,
        v459,
        v462,
        v465,
        v467,
        v468,
        v474,
        v482,
        v487,
        v489,
        v492,
        v494,
        v495,
        v498,
        v499,
        v502,
        v505,
        v506,
    ) = {
        let v338: f64 = 0.0047376_f64;
        let v339: f64 = v338 * v336;
        let v340: f64 = v337 - v339;
        let v341: f64 = 0.01543232_f64;
        let v342: f64 = v341 * v320;
        let v343: f64 = v340 + v342;
        let v344: f64 = v336 * v343;
        let v345: f64 = -0.001373904_f64;
        let v346: f64 = v345 * v331;
        let v347: f64 = 0.111498032_f64;
        let v348: f64 = v347 * v336;
        let v349: f64 = v346 - v348;
        let v350: f64 = v338 * v320;
        let v351: f64 = v349 + v350;
        let v352: f64 = v320 * v351;
        let v353: f64 = v344 + v352;
        let v354: f64 = v335 - v353;
        let v355: f64 = -0.06768_f64;
        let v356: f64 = v43 * v310;
        let v357: f64 = v306 * v59;
        let v358: f64 = v272 * v308;
        let v359: f64 = v273 * v301;
        let v360: f64 = v358 + v359;
        let v361: f64 = v357 - v360;
        let v362: f64 = v29 * v361;
        let v363: f64 = v356 - v362;
        let v364: f64 = -0.15005_f64;
        let v365: f64 = v364 * v323;
        let v366: f64 = 0.0203_f64;
        let v367: f64 = v366 * v320;
        let v368: f64 = v331 * v367;
        let v369: f64 = v364 * v320;
        let v370: f64 = v336 * v369;
        let v371: f64 = v368 - v370;
        let v372: f64 = v365 + v371;
        let v373: f64 = v363 + v372;
        let v374: f64 = v355 * v373;
        let v375: f64 = 0.336_f64;
        let v376: f64 = v366 * v333;
        let v377: f64 = v320 * v369;
        let v378: f64 = v364 * v331;
        let v379: f64 = v366 * v336;
        let v380: f64 = v378 + v379;
        let v381: f64 = v331 * v380;
        let v382: f64 = v377 + v381;
        let v383: f64 = v376 + v382;
        let v384: f64 = v303 + v383;
        let v385: f64 = v375 * v384;
        let v386: f64 = v374 + v385;
        let v387: f64 = v354 + v386;
        let v388: f64 = 0.00209602_f64;
        let v389: f64 = v12 * v323;
        let v390: f64 = v9 * v331;
        let v391: f64 = v12 * v336;
        let v392: f64 = v390 + v391;
        let v393: f64 = qd[3];
        let v394: f64 = v392 * v393;
        let v395: f64 = v389 - v394;
        let v396: f64 = v388 * v395;
        let v397: f64 = v320 + v393;
        let v398: f64 = v388 * v392;
        let v399: f64 = v397 * v398;
        let v400: f64 = 0.0013_f64;
        let v401: f64 = v400 * v397;
        let v402: f64 = v392 * v401;
        let v403: f64 = v399 - v402;
        let v404: f64 = v396 + v403;
        let v405: f64 = 0.01558_f64;
        let v406: f64 = v43 * v361;
        let v407: f64 = v29 * v310;
        let v408: f64 = v406 + v407;
        let v409: f64 = v364 * v333;
        let v410: f64 = v336 * v380;
        let v411: f64 = v320 * v367;
        let v412: f64 = v410 + v411;
        let v413: f64 = v409 - v412;
        let v414: f64 = v408 + v413;
        let v415: f64 = v9 * v414;
        let v416: f64 = v12 * v384;
        let v417: f64 = v415 + v416;
        let v418: f64 = v299 * v395;
        let v419: f64 = v299 * v392;
        let v420: f64 = v397 * v419;
        let v421: f64 = v418 + v420;
        let v422: f64 = v417 + v421;
        let v423: f64 = v405 * v422;
        let v424: f64 = v404 + v423;
        let v425: f64 = 0.0003_f64;
        let v426: f64 = v3 * v395;
        let v427: f64 = v15 * v333;
        let v428: f64 = v426 - v427;
        let v429: f64 = v3 * v397;
        let v430: f64 = v12 * v331;
        let v431: f64 = v9 * v336;
        let v432: f64 = v430 - v431;
        let v433: f64 = v15 * v432;
        let v434: f64 = v429 - v433;
        let v435: f64 = qd[4];
        let v436: f64 = v434 * v435;
        let v437: f64 = v428 + v436;
        let v438: f64 = v425 * v437;
        let v439: f64 = 0.0004_f64;
        let v440: f64 = v392 + v435;
        let v441: f64 = v439 * v440;
        let v442: f64 = v434 * v441;
        let v443: f64 = v425 * v434;
        let v444: f64 = v440 * v443;
        let v445: f64 = v442 - v444;
        let v446: f64 = v438 + v445;
        let v447: f64 = q[5];
        let (v451, v448): (f64, f64) = ::libm::sincos(v447);
        let v449: f64 = 0.00024216_f64;
        let v450: f64 = v448 * v437;
        let v452: f64 = v9 * v323;
        let v453: f64 = v432 * v393;
        let v454: f64 = v452 + v453;
        let v455: f64 = v451 * v454;
        let v456: f64 = v450 - v455;
        let v457: f64 = v3 * v432;
        let v458: f64 = v15 * v397;
        let v459: f64 = v457 + v458;
        let v460: f64 = v451 * v459;
        let v461: f64 = v448 * v440;
        let v462: f64 = v460 + v461;
        let v463: f64 = qd[5];
        let v464: f64 = v462 * v463;
        let v465: f64 = v456 - v464;
        let v466: f64 = v449 * v465;
        let v467: f64 = v434 + v463;
        let v468: f64 = v449 * v462;
        let v469: f64 = v467 * v468;
        let v470: f64 = v257 * v467;
        let v471: f64 = v462 * v470;
        let v472: f64 = v469 - v471;
        let v473: f64 = v466 + v472;
        let v474: f64 = 0.00288_f64;
        let v475: f64 = v12 * v414;
        let v476: f64 = v9 * v384;
        let v477: f64 = v475 - v476;
        let v478: f64 = v299 * v432;
        let v479: f64 = v397 * v478;
        let v480: f64 = v299 * v454;
        let v481: f64 = v479 - v480;
        let v482: f64 = v477 + v481;
        let v483: f64 = v3 * v482;
        let v484: f64 = v392 * v419;
        let v485: f64 = v432 * v478;
        let v486: f64 = v484 + v485;
        let v487: f64 = v373 - v486;
        let v488: f64 = v15 * v487;
        let v489: f64 = v483 + v488;
        let v490: f64 = v451 * v489;
        let v491: f64 = v448 * v422;
        let v492: f64 = v490 + v491;
        let v493: f64 = v474 * v492;
        let v494: f64 = v473 + v493;
        let v495: f64 = v448 * v494;
        let v496: f64 = v448 * v459;
        let v497: f64 = v451 * v440;
        let v498: f64 = v496 - v497;
        let v499: f64 = v449 * v498;
        let v500: f64 = v467 * v499;
        let v501: f64 = v498 * v470;
        let v502: f64 = v500 - v501;
        let v503: f64 = v451 * v437;
        let v504: f64 = v448 * v454;
        let v505: f64 = v503 + v504;
        let v506: f64 = v498 * v463;
        (
            v338,
            v341,
            v343,
            v345,
            v351,
            v355,
            v361,
            v364,
            v366,
            v373,
            v375,
            v384,
            v387,
            v388,
            v392,
            v395,
            v397,
            v398,
            v400,
            v401,
            v405,
            v414,
            v422,
            v424,
            v425,
            v432,
            v434,
            v435,
            v439,
            v440,
            v441,
            v443,
            v446,
            v448,
            v449,
            v451,
            v454,
            v459,
            v462,
            v465,
            v467,
            v468,
            v474,
            v482,
            v487,
            v489,
            v492,
            v494,
            v495,
            v498,
            v499,
            v502,
            v505,
            v506,
        )
    };
    let (
        v534,
        v565,
        v567,
        v585,
        v611,
        v613,
        v617,
        v620,
        v623,
        v627,
        v641,
        v643,
        v644,
        v653,
        v669,
        v670,
        v673,
        v674,
        v675,
    ) = {
        let v507: f64 = v505 + v506;
        let v508: f64 = v449 * v507;
        let v509: f64 = v502 - v508;
        let v510: f64 = v448 * v489;
        let v511: f64 = v451 * v422;
        let v512: f64 = v510 - v511;
        let v513: f64 = v474 * v512;
        let v514: f64 = v509 + v513;
        let v515: f64 = v451 * v514;
        let v516: f64 = v495 - v515;
        let v517: f64 = v446 + v516;
        let v518: f64 = v3 * v517;
        let v519: f64 = v425 * v459;
        let v520: f64 = v440 * v519;
        let v521: f64 = v459 * v441;
        let v522: f64 = v520 - v521;
        let v523: f64 = v15 * v395;
        let v524: f64 = v3 * v333;
        let v525: f64 = v523 + v524;
        let v526: f64 = v459 * v435;
        let v527: f64 = v525 + v526;
        let v528: f64 = v425 * v527;
        let v529: f64 = v522 - v528;
        let v530: f64 = v462 * v499;
        let v531: f64 = v498 * v468;
        let v532: f64 = v530 - v531;
        let v533: f64 = v257 * v527;
        let v534: f64 = v532 - v533;
        let v535: f64 = v529 + v534;
        let v536: f64 = v15 * v535;
        let v537: f64 = v518 - v536;
        let v538: f64 = v424 + v537;
        let v539: f64 = 0.82_f64;
        let v540: f64 = v539 * v422;
        let v541: f64 = v405 * v395;
        let v542: f64 = v405 * v392;
        let v543: f64 = v397 * v542;
        let v544: f64 = v541 + v543;
        let v545: f64 = v540 + v544;
        let v546: f64 = 0.09_f64;
        let v547: f64 = v546 * v512;
        let v548: f64 = v474 * v498;
        let v549: f64 = v467 * v548;
        let v550: f64 = v474 * v507;
        let v551: f64 = v549 - v550;
        let v552: f64 = v547 + v551;
        let v553: f64 = v451 * v552;
        let v554: f64 = v546 * v492;
        let v555: f64 = v474 * v465;
        let v556: f64 = v474 * v462;
        let v557: f64 = v467 * v556;
        let v558: f64 = v555 + v557;
        let v559: f64 = v554 + v558;
        let v560: f64 = v448 * v559;
        let v561: f64 = v553 - v560;
        let v562: f64 = 0.34_f64;
        let v563: f64 = v562 * v422;
        let v564: f64 = v561 - v563;
        let v565: f64 = v545 - v564;
        let v566: f64 = v299 * v565;
        let v567: f64 = v538 + v566;
        let v568: f64 = v12 * v567;
        let v569: f64 = v388 * v454;
        let v570: f64 = v432 * v401;
        let v571: f64 = v388 * v432;
        let v572: f64 = v397 * v571;
        let v573: f64 = v570 - v572;
        let v574: f64 = v569 + v573;
        let v575: f64 = v405 * v482;
        let v576: f64 = v574 - v575;
        let v577: f64 = v434 * v519;
        let v578: f64 = v459 * v443;
        let v579: f64 = v577 - v578;
        let v580: f64 = v439 * v454;
        let v581: f64 = v579 - v580;
        let v582: f64 = v451 * v494;
        let v583: f64 = v448 * v514;
        let v584: f64 = v582 + v583;
        let v585: f64 = v581 + v584;
        let v586: f64 = v576 - v585;
        let v587: f64 = v539 * v482;
        let v588: f64 = v405 * v432;
        let v589: f64 = v397 * v588;
        let v590: f64 = v405 * v454;
        let v591: f64 = v589 - v590;
        let v592: f64 = v587 + v591;
        let v593: f64 = v562 * v489;
        let v594: f64 = v448 * v552;
        let v595: f64 = v451 * v559;
        let v596: f64 = v594 + v595;
        let v597: f64 = v593 + v596;
        let v598: f64 = v3 * v597;
        let v599: f64 = v3 * v487;
        let v600: f64 = v15 * v482;
        let v601: f64 = v599 - v600;
        let v602: f64 = v562 * v601;
        let v603: f64 = v546 * v601;
        let v604: f64 = v498 * v548;
        let v605: f64 = v462 * v556;
        let v606: f64 = v604 + v605;
        let v607: f64 = v603 - v606;
        let v608: f64 = v602 + v607;
        let v609: f64 = v15 * v608;
        let v610: f64 = v598 - v609;
        let v611: f64 = v592 + v610;
        let v612: f64 = v299 * v611;
        let v613: f64 = v586 - v612;
        let v614: f64 = v9 * v613;
        let v615: f64 = v568 + v614;
        let v616: f64 = v387 + v615;
        let v617: f64 = 4.8_f64;
        let v618: f64 = v617 * v373;
        let v619: f64 = v355 * v323;
        let v620: f64 = -0.09744_f64;
        let v621: f64 = v620 * v320;
        let v622: f64 = v375 * v331;
        let v623: f64 = v621 - v622;
        let v624: f64 = v331 * v623;
        let v625: f64 = v375 * v336;
        let v626: f64 = v355 * v320;
        let v627: f64 = v625 + v626;
        let v628: f64 = v336 * v627;
        let v629: f64 = v624 - v628;
        let v630: f64 = v619 + v629;
        let v631: f64 = v618 + v630;
        let v632: f64 = v539 * v487;
        let v633: f64 = v392 * v542;
        let v634: f64 = v432 * v588;
        let v635: f64 = v633 + v634;
        let v636: f64 = v632 - v635;
        let v637: f64 = v15 * v597;
        let v638: f64 = v3 * v608;
        let v639: f64 = v637 + v638;
        let v640: f64 = v636 + v639;
        let v641: f64 = v631 + v640;
        let v642: f64 = v364 * v641;
        let v643: f64 = v616 + v642;
        let v644: f64 = v43 * v643;
        let v645: f64 = v325 * v323;
        let v646: f64 = v341 * v333;
        let v647: f64 = v645 - v646;
        let v648: f64 = v331 * v351;
        let v649: f64 = v314 * v331;
        let v650: f64 = v345 * v336;
        let v651: f64 = v649 - v650;
        let v652: f64 = v325 * v320;
        let v653: f64 = v651 + v652;
        let v654: f64 = v336 * v653;
        let v655: f64 = v648 + v654;
        let v656: f64 = v647 + v655;
        let v657: f64 = v620 * v384;
        let v658: f64 = v355 * v414;
        let v659: f64 = v657 + v658;
        let v660: f64 = v656 - v659;
        let v661: f64 = v392 * v571;
        let v662: f64 = v432 * v398;
        let v663: f64 = v661 - v662;
        let v664: f64 = v400 * v333;
        let v665: f64 = v663 - v664;
        let v666: f64 = v15 * v517;
        let v667: f64 = v3 * v535;
        let v668: f64 = v666 + v667;
        let v669: f64 = v665 + v668;
        let v670: f64 = v660 + v669;
        let v671: f64 = v9 * v611;
        let v672: f64 = v12 * v565;
        let v673: f64 = v671 - v672;
        let v674: f64 = v617 * v384;
        let v675: f64 = v620 * v333;
        (
            v534,
            v565,
            v567,
            v585,
            v611,
            v613,
            v617,
            v620,
            v623,
            v627,
            v641,
            v643,
            v644,
            v653,
            v669,
            v670,
            v673,
            v674,
            v675,
        )
    };
    let (v747, v761, v776, v779, v787, v788, v833, v837, v841, v842, v843, v844) = {
        let v676: f64 = v375 * v323;
        let v677: f64 = v675 + v676;
        let v678: f64 = v320 * v627;
        let v679: f64 = v355 * v331;
        let v680: f64 = v620 * v336;
        let v681: f64 = v679 + v680;
        let v682: f64 = v331 * v681;
        let v683: f64 = v678 + v682;
        let v684: f64 = v677 + v683;
        let v685: f64 = v674 + v684;
        let v686: f64 = v673 - v685;
        let v687: f64 = v366 * v686;
        let v688: f64 = v617 * v414;
        let v689: f64 = v355 * v333;
        let v690: f64 = v336 * v681;
        let v691: f64 = v320 * v623;
        let v692: f64 = v690 + v691;
        let v693: f64 = v689 - v692;
        let v694: f64 = v688 + v693;
        let v695: f64 = v12 * v611;
        let v696: f64 = v9 * v565;
        let v697: f64 = v695 + v696;
        let v698: f64 = v694 + v697;
        let v699: f64 = v364 * v698;
        let v700: f64 = v687 - v699;
        let v701: f64 = v670 + v700;
        let v702: f64 = v29 * v701;
        let v703: f64 = v644 - v702;
        let v704: f64 = v313 + v703;
        let v705: f64 = v59 * v704;
        let v706: f64 = v276 * v274;
        let v707: f64 = v290 * v278;
        let v708: f64 = v706 - v707;
        let v709: f64 = v270 * v277;
        let v710: f64 = v276 * v272;
        let v711: f64 = v709 + v710;
        let v712: f64 = v281 * v273;
        let v713: f64 = v711 + v712;
        let v714: f64 = v273 * v713;
        let v715: f64 = v277 * v287;
        let v716: f64 = v714 - v715;
        let v717: f64 = v708 + v716;
        let v718: f64 = v305 * v361;
        let v719: f64 = -6.33012_f64;
        let v720: f64 = v719 * v303;
        let v721: f64 = v718 - v720;
        let v722: f64 = v717 + v721;
        let v723: f64 = v29 * v643;
        let v724: f64 = v43 * v701;
        let v725: f64 = v723 + v724;
        let v726: f64 = v722 + v725;
        let v727: f64 = 17.4_f64;
        let v728: f64 = v727 * v303;
        let v729: f64 = v298 * v274;
        let v730: f64 = v719 * v278;
        let v731: f64 = v729 + v730;
        let v732: f64 = v719 * v273;
        let v733: f64 = v305 * v277;
        let v734: f64 = v732 - v733;
        let v735: f64 = v277 * v734;
        let v736: f64 = v305 * v272;
        let v737: f64 = v298 * v273;
        let v738: f64 = v736 - v737;
        let v739: f64 = v272 * v738;
        let v740: f64 = v735 - v739;
        let v741: f64 = v731 + v740;
        let v742: f64 = v728 + v741;
        let v743: f64 = v742 - v686;
        let v744: f64 = v299 * v743;
        let v745: f64 = v726 - v744;
        let v746: f64 = v78 * v745;
        let v747: f64 = v705 + v746;
        let v748: f64 = 2.1071040725_f64;
        let v749: f64 = v50 * v43;
        let v750: f64 = v748 + v749;
        let v751: f64 = v750 - v63;
        let v752: f64 = v33 - v53;
        let v753: f64 = v752 * v3;
        let v754: f64 = v751 + v753;
        let v755: f64 = -0.000116928_f64;
        let v756: f64 = v32 * v43;
        let v757: f64 = v755 - v756;
        let v758: f64 = v757 * v15;
        let v759: f64 = v758 + v153;
        let v760: f64 = v759 * v12;
        let v761: f64 = v754 + v760;
        let v762: f64 = 0.3589900705_f64;
        let v763: f64 = 0.010956925_f64;
        let v764: f64 = v763 * v43;
        let v765: f64 = v762 + v764;
        let v766: f64 = 0.384876294_f64;
        let v767: f64 = v766 * v29;
        let v768: f64 = v765 - v767;
        let v769: f64 = v33 - v249;
        let v770: f64 = v769 * v3;
        let v771: f64 = v768 + v770;
        let v772: f64 = v755 - v246;
        let v773: f64 = v772 * v15;
        let v774: f64 = v773 + v153;
        let v775: f64 = v774 * v12;
        let v776: f64 = v771 + v775;
        let v777: f64 = v142 + v249;
        let v778: f64 = v777 * v15;
        let v779: f64 = v778 * v9;
        let v780: f64 = -5.8464e-05_f64;
        let v781: f64 = v780 - v246;
        let v782: f64 = v781 * v15;
        let v783: f64 = v172 - v249;
        let v784: f64 = v783 * v3;
        let v785: f64 = v240 + v784;
        let v786: f64 = v785 * v12;
        let v787: f64 = v782 + v786;
        let v788: f64 = v260 * v9;
        let v789: f64 = v281 * v274;
        let v790: f64 = v136 * v278;
        let v791: f64 = v789 - v790;
        let v792: f64 = v277 * v294;
        let v793: f64 = v272 * v713;
        let v794: f64 = v792 - v793;
        let v795: f64 = v791 + v794;
        let v796: f64 = v719 * v310;
        let v797: f64 = v298 * v361;
        let v798: f64 = v796 - v797;
        let v799: f64 = v795 + v798;
        let v800: f64 = v345 * v323;
        let v801: f64 = v338 * v333;
        let v802: f64 = v800 - v801;
        let v803: f64 = v320 * v653;
        let v804: f64 = v331 * v343;
        let v805: f64 = v803 - v804;
        let v806: f64 = v802 + v805;
        let v807: f64 = v375 * v414;
        let v808: f64 = v620 * v373;
        let v809: f64 = v807 - v808;
        let v810: f64 = v806 + v809;
        let v811: f64 = v9 * v567;
        let v812: f64 = v12 * v613;
        let v813: f64 = v811 - v812;
        let v814: f64 = v810 + v813;
        let v815: f64 = v366 * v641;
        let v816: f64 = v814 - v815;
        let v817: f64 = v799 - v816;
        let v818: f64 = v727 * v310;
        let v819: f64 = v273 * v738;
        let v820: f64 = v298 * v277;
        let v821: f64 = v719 * v272;
        let v822: f64 = v820 - v821;
        let v823: f64 = v277 * v822;
        let v824: f64 = v819 - v823;
        let v825: f64 = v305 * v274;
        let v826: f64 = v824 - v825;
        let v827: f64 = v818 + v826;
        let v828: f64 = v29 * v698;
        let v829: f64 = v43 * v641;
        let v830: f64 = v828 + v829;
        let v831: f64 = v827 + v830;
        let v832: f64 = v299 * v831;
        let v833: f64 = v817 + v832;
        let v834: f64 = v762 + v34;
        let v835: f64 = v153 - v36;
        let v836: f64 = v835 * v12;
        let v837: f64 = v834 + v836;
        let v838: f64 = v172 * v3;
        let v839: f64 = v240 + v838;
        let v840: f64 = v839 * v12;
        let v841: f64 = v840 - v155;
        let v842: f64 = -v816;
        let v843: f64 = 0.0_f64;
        let v844: f64 = -v585;
        (v747, v761, v776, v779, v787, v788, v833, v837, v841, v842, v843, v844)
    };
    [
        [v135, v181, v205, v229, v256, v269, v747],
        [v181, v761, v776, v779, v787, v788, v833],
        [v205, v776, v837, v144, v841, v788, v842],
        [v229, v779, v144, v207, v843, v258, v669],
        [v256, v787, v841, v843, v240, v843, v844],
        [v269, v788, v788, v258, v843, v257, v534],
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
/// Operation count: 1216 floating-point operations, 10 trig calls.
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
        v7,
        v10,
        v17,
        v23,
        v25,
        v28,
        v30,
        v33,
        v41,
        v43,
        v47,
        v48,
        v51,
        v53,
        v57,
        v65,
        v73,
        v76,
        v81,
        v82,
        v83,
        v85,
        v87,
        v92,
        v95,
        v99,
        v104,
        v110,
        v113,
        v115,
        v126,
        v127,
        v137,
        v140,
        v141,
        v147,
        v150,
        v151,
        v153,
        v164,
        v168,
        v176,
        v178,
    ) = {
        let v0: f64 = qdd[0];
        let v1: f64 = q[1];
        let (v2, v9): (f64, f64) = ::libm::sincos(v1);
        let v3: f64 = qd[0];
        let v4: f64 = v2 * v3;
        let v5: f64 = 0.4318_f64;
        let v6: f64 = qd[1];
        let v7: f64 = v5 * v6;
        let v8: f64 = v4 * v7;
        let v10: f64 = v9 * v0;
        let v11: f64 = v4 * v6;
        let v12: f64 = v10 - v11;
        let v13: f64 = v5 * v12;
        let v14: f64 = v8 - v13;
        let v15: f64 = v5 * v9;
        let v16: f64 = v14 * v15;
        let v17: f64 = -v16;
        let v18: f64 = v12 * v15;
        let v19: f64 = v4 * v15;
        let v20: f64 = v6 * v19;
        let v21: f64 = v18 - v20;
        let v22: f64 = v14 * v9;
        let v23: f64 = v21 - v22;
        let v24: f64 = v14 * v2;
        let v25: f64 = v9 * v3;
        let v26: f64 = v25 * v15;
        let v27: f64 = v6 * v26;
        let v28: f64 = v2 * v0;
        let v29: f64 = v25 * v6;
        let v30: f64 = v28 + v29;
        let v31: f64 = v30 * v15;
        let v32: f64 = v27 + v31;
        let v33: f64 = v24 - v32;
        let v34: f64 = v25 * v26;
        let v35: f64 = v4 * v19;
        let v36: f64 = v34 + v35;
        let v37: f64 = 9.81_f64;
        let v38: f64 = v37 * v2;
        let v39: f64 = v5 * v25;
        let v40: f64 = v25 * v39;
        let v41: f64 = v6 * v7;
        let v42: f64 = v40 + v41;
        let v43: f64 = v38 - v42;
        let v44: f64 = v43 * v9;
        let v45: f64 = v36 + v44;
        let v46: f64 = v37 * v9;
        let v47: f64 = qdd[1];
        let v48: f64 = v5 * v47;
        let v49: f64 = v4 * v39;
        let v50: f64 = v48 + v49;
        let v51: f64 = v46 + v50;
        let v52: f64 = v51 * v2;
        let v53: f64 = v45 - v52;
        let v54: f64 = v6 * v9;
        let v55: f64 = v4 * v54;
        let v56: f64 = v30 * v2;
        let v57: f64 = v55 + v56;
        let v58: f64 = v25 * v54;
        let v59: f64 = v30 * v9;
        let v60: f64 = v58 + v59;
        let v61: f64 = v6 * v2;
        let v62: f64 = v4 * v61;
        let v63: f64 = v60 - v62;
        let v64: f64 = v12 * v2;
        let v65: f64 = v63 + v64;
        let v66: f64 = v6 * v54;
        let v67: f64 = v25 * v2;
        let v68: f64 = v4 * v9;
        let v69: f64 = v67 - v68;
        let v70: f64 = v4 * v69;
        let v71: f64 = v66 + v70;
        let v72: f64 = v47 * v2;
        let v73: f64 = v71 + v72;
        let v74: f64 = v12 * v9;
        let v75: f64 = v25 * v61;
        let v76: f64 = v74 - v75;
        let v77: f64 = v47 * v9;
        let v78: f64 = v6 * v61;
        let v79: f64 = v77 - v78;
        let v80: f64 = v25 * v69;
        let v81: f64 = v79 + v80;
        let v82: f64 = v6 * v69;
        let v83: f64 = 0.0203_f64;
        let v84: f64 = q[2];
        let (v87, v85): (f64, f64) = ::libm::sincos(v84);
        let v86: f64 = v85 * v12;
        let v88: f64 = v87 * v30;
        let v89: f64 = v86 - v88;
        let v90: f64 = v85 * v4;
        let v91: f64 = v87 * v25;
        let v92: f64 = v90 + v91;
        let v93: f64 = qd[2];
        let v94: f64 = v92 * v93;
        let v95: f64 = v89 - v94;
        let v96: f64 = v83 * v95;
        let v97: f64 = v85 * v25;
        let v98: f64 = v87 * v4;
        let v99: f64 = v97 - v98;
        let v100: f64 = -0.15005_f64;
        let v101: f64 = v100 * v99;
        let v102: f64 = v99 * v101;
        let v103: f64 = v100 * v92;
        let v104: f64 = v6 + v93;
        let v105: f64 = v83 * v104;
        let v106: f64 = v103 + v105;
        let v107: f64 = v92 * v106;
        let v108: f64 = v102 + v107;
        let v109: f64 = v96 - v108;
        let v110: f64 = v109 - v14;
        let v111: f64 = v85 * v9;
        let v112: f64 = v87 * v2;
        let v113: f64 = v111 - v112;
        let v114: f64 = v83 * v113;
        let v115: f64 = v15 + v114;
        let v116: f64 = v110 * v115;
        let v117: f64 = v85 * v43;
        let v118: f64 = v87 * v51;
        let v119: f64 = v117 + v118;
        let v120: f64 = v100 * v95;
        let v121: f64 = v104 * v106;
        let v122: f64 = v83 * v99;
        let v123: f64 = v99 * v122;
        let v124: f64 = v121 + v123;
        let v125: f64 = v120 + v124;
        let v126: f64 = v119 - v125;
        let v127: f64 = v100 * v113;
        let v128: f64 = v126 * v127;
        let v129: f64 = v116 - v128;
        let v130: f64 = v85 * v51;
        let v131: f64 = v87 * v43;
        let v132: f64 = v130 - v131;
        let v133: f64 = v85 * v30;
        let v134: f64 = v87 * v12;
        let v135: f64 = v133 + v134;
        let v136: f64 = v99 * v93;
        let v137: f64 = v135 + v136;
        let v138: f64 = v100 * v137;
        let v139: f64 = qdd[2];
        let v140: f64 = v47 + v139;
        let v141: f64 = v83 * v140;
        let v142: f64 = v138 + v141;
        let v143: f64 = v92 * v122;
        let v144: f64 = v104 * v101;
        let v145: f64 = v143 - v144;
        let v146: f64 = v142 + v145;
        let v147: f64 = v132 + v146;
        let v148: f64 = v87 * v9;
        let v149: f64 = v85 * v2;
        let v150: f64 = v148 + v149;
        let v151: f64 = v100 * v150;
        let v152: f64 = v147 * v151;
        let v153: f64 = v129 + v152;
        let v154: f64 = v104 * v127;
        let v155: f64 = v92 * v115;
        let v156: f64 = v154 - v155;
        let v157: f64 = v104 * v156;
        let v158: f64 = v95 * v115;
        let v159: f64 = v157 + v158;
        let v160: f64 = v110 * v113;
        let v161: f64 = v159 + v160;
        let v162: f64 = v99 * v127;
        let v163: f64 = v92 * v151;
        let v164: f64 = v162 + v163;
        let v165: f64 = v99 * v164;
        let v166: f64 = v161 + v165;
        let v167: f64 = v140 * v151;
        let v168: f64 = v166 + v167;
        let v169: f64 = v95 * v127;
        let v170: f64 = v92 * v156;
        let v171: f64 = v169 + v170;
        let v172: f64 = v126 * v113;
        let v173: f64 = v171 - v172;
        let v174: f64 = v99 * v115;
        let v175: f64 = v104 * v151;
        let v176: f64 = v174 + v175;
        let v177: f64 = v99 * v176;
        let v178: f64 = v173 - v177;
        (
            v0,
            v4,
            v5,
            v7,
            v10,
            v17,
            v23,
            v25,
            v28,
            v30,
            v33,
            v41,
            v43,
            v47,
            v48,
            v51,
            v53,
            v57,
            v65,
            v73,
            v76,
            v81,
            v82,
            v83,
            v85,
            v87,
            v92,
            v95,
            v99,
            v104,
            v110,
            v113,
            v115,
            v126,
            v127,
            v137,
            v140,
            v141,
            v147,
            v150,
            v151,
            v153,
            v164,
            v168,
            v176,
            v178,
        )
    };
    let (
        v182,
        v191,
        v195,
        v203,
        v211,
        v213,
        v218,
        v221,
        v223,
        v225,
        v227,
        v232,
        v236,
        v242,
        v248,
        v251,
        v255,
        v257,
        v267,
        v271,
        v272,
        v277,
        v278,
        v279,
        v296,
        v298,
        v312,
        v323,
        v329,
        v339,
        v345,
        v349,
        v352,
        v357,
    ) = {
        let v179: f64 = v137 * v151;
        let v180: f64 = v178 + v179;
        let v181: f64 = v147 * v150;
        let v182: f64 = v180 + v181;
        let v183: f64 = v140 * v127;
        let v184: f64 = v137 * v115;
        let v185: f64 = v183 - v184;
        let v186: f64 = v104 * v176;
        let v187: f64 = v185 - v186;
        let v188: f64 = v92 * v164;
        let v189: f64 = v187 - v188;
        let v190: f64 = v110 * v150;
        let v191: f64 = v189 - v190;
        let v192: f64 = v104 * v113;
        let v193: f64 = v92 * v192;
        let v194: f64 = v137 * v150;
        let v195: f64 = v193 + v194;
        let v196: f64 = v92 * v113;
        let v197: f64 = v99 * v150;
        let v198: f64 = v196 - v197;
        let v199: f64 = v92 * v198;
        let v200: f64 = v104 * v192;
        let v201: f64 = v199 - v200;
        let v202: f64 = v140 * v150;
        let v203: f64 = v201 - v202;
        let v204: f64 = v99 * v192;
        let v205: f64 = v137 * v113;
        let v206: f64 = v204 + v205;
        let v207: f64 = v104 * v150;
        let v208: f64 = v92 * v207;
        let v209: f64 = v206 - v208;
        let v210: f64 = v95 * v150;
        let v211: f64 = v209 + v210;
        let v212: f64 = v104 * v198;
        let v213: f64 = -v212;
        let v214: f64 = v99 * v198;
        let v215: f64 = v140 * v113;
        let v216: f64 = v214 - v215;
        let v217: f64 = v104 * v207;
        let v218: f64 = v216 + v217;
        let v219: f64 = v95 * v113;
        let v220: f64 = v99 * v207;
        let v221: f64 = v219 - v220;
        let v222: f64 = q[3];
        let (v223, v225): (f64, f64) = ::libm::sincos(v222);
        let v224: f64 = v223 * v92;
        let v226: f64 = v225 * v104;
        let v227: f64 = v224 + v226;
        let v228: f64 = v5 * v227;
        let v229: f64 = v227 * v228;
        let v230: f64 = v225 * v92;
        let v231: f64 = v223 * v104;
        let v232: f64 = v230 - v231;
        let v233: f64 = v5 * v232;
        let v234: f64 = v232 * v233;
        let v235: f64 = v229 + v234;
        let v236: f64 = v147 - v235;
        let v237: f64 = v236 * v151;
        let v238: f64 = v225 * v126;
        let v239: f64 = v223 * v110;
        let v240: f64 = v238 + v239;
        let v241: f64 = qd[3];
        let v242: f64 = v99 + v241;
        let v243: f64 = v242 * v233;
        let v244: f64 = v223 * v137;
        let v245: f64 = v225 * v140;
        let v246: f64 = v244 + v245;
        let v247: f64 = v232 * v241;
        let v248: f64 = v246 + v247;
        let v249: f64 = v5 * v248;
        let v250: f64 = v243 - v249;
        let v251: f64 = v240 + v250;
        let v252: f64 = v223 * v115;
        let v253: f64 = v225 * v127;
        let v254: f64 = v252 - v253;
        let v255: f64 = v223 * v150;
        let v256: f64 = v5 * v255;
        let v257: f64 = v254 - v256;
        let v258: f64 = v251 * v257;
        let v259: f64 = v237 + v258;
        let v260: f64 = v223 * v126;
        let v261: f64 = v225 * v110;
        let v262: f64 = v260 - v261;
        let v263: f64 = v225 * v137;
        let v264: f64 = v223 * v140;
        let v265: f64 = v263 - v264;
        let v266: f64 = v227 * v241;
        let v267: f64 = v265 - v266;
        let v268: f64 = v5 * v267;
        let v269: f64 = v242 * v228;
        let v270: f64 = v268 + v269;
        let v271: f64 = v262 + v270;
        let v272: f64 = v225 * v150;
        let v273: f64 = v5 * v272;
        let v274: f64 = v223 * v127;
        let v275: f64 = v225 * v115;
        let v276: f64 = v274 + v275;
        let v277: f64 = v273 - v276;
        let v278: f64 = v271 * v277;
        let v279: f64 = v259 + v278;
        let v280: f64 = v248 * v151;
        let v281: f64 = v271 * v113;
        let v282: f64 = v280 - v281;
        let v283: f64 = v242 * v257;
        let v284: f64 = v232 * v151;
        let v285: f64 = v283 - v284;
        let v286: f64 = v242 * v285;
        let v287: f64 = v282 - v286;
        let v288: f64 = v236 * v255;
        let v289: f64 = v287 + v288;
        let v290: f64 = v232 * v277;
        let v291: f64 = v227 * v257;
        let v292: f64 = v290 - v291;
        let v293: f64 = v227 * v292;
        let v294: f64 = v289 + v293;
        let v295: f64 = qdd[3];
        let v296: f64 = v95 + v295;
        let v297: f64 = v296 * v277;
        let v298: f64 = v294 - v297;
        let v299: f64 = v232 * v285;
        let v300: f64 = v248 * v257;
        let v301: f64 = v299 - v300;
        let v302: f64 = v251 * v255;
        let v303: f64 = v301 - v302;
        let v304: f64 = v227 * v151;
        let v305: f64 = v242 * v277;
        let v306: f64 = v304 - v305;
        let v307: f64 = v227 * v306;
        let v308: f64 = v303 - v307;
        let v309: f64 = v267 * v277;
        let v310: f64 = v308 + v309;
        let v311: f64 = v271 * v272;
        let v312: f64 = v310 + v311;
        let v313: f64 = v251 * v113;
        let v314: f64 = v267 * v151;
        let v315: f64 = v313 - v314;
        let v316: f64 = v296 * v257;
        let v317: f64 = v315 + v316;
        let v318: f64 = v242 * v306;
        let v319: f64 = v317 + v318;
        let v320: f64 = v232 * v292;
        let v321: f64 = v319 - v320;
        let v322: f64 = v236 * v272;
        let v323: f64 = v321 - v322;
        let v324: f64 = v227 * v113;
        let v325: f64 = v242 * v255;
        let v326: f64 = v324 - v325;
        let v327: f64 = v232 * v326;
        let v328: f64 = v267 * v272;
        let v329: f64 = v327 + v328;
        let v330: f64 = v267 * v113;
        let v331: f64 = v242 * v326;
        let v332: f64 = v330 + v331;
        let v333: f64 = v232 * v255;
        let v334: f64 = v227 * v272;
        let v335: f64 = v333 - v334;
        let v336: f64 = v232 * v335;
        let v337: f64 = v332 + v336;
        let v338: f64 = v296 * v272;
        let v339: f64 = v337 + v338;
        let v340: f64 = v227 * v326;
        let v341: f64 = v267 * v255;
        let v342: f64 = v340 + v341;
        let v343: f64 = v242 * v272;
        let v344: f64 = v232 * v113;
        let v345: f64 = v343 - v344;
        let v346: f64 = v232 * v345;
        let v347: f64 = v342 + v346;
        let v348: f64 = v248 * v272;
        let v349: f64 = v347 + v348;
        let v350: f64 = v296 * v113;
        let v351: f64 = v242 * v335;
        let v352: f64 = v350 + v351;
        let v353: f64 = v248 * v113;
        let v354: f64 = v296 * v255;
        let v355: f64 = v353 + v354;
        let v356: f64 = v227 * v335;
        let v357: f64 = v355 + v356;
        (
            v182,
            v191,
            v195,
            v203,
            v211,
            v213,
            v218,
            v221,
            v223,
            v225,
            v227,
            v232,
            v236,
            v242,
            v248,
            v251,
            v255,
            v257,
            v267,
            v271,
            v272,
            v277,
            v278,
            v279,
            v296,
            v298,
            v312,
            v323,
            v329,
            v339,
            v345,
            v349,
            v352,
            v357,
        )
    };
    let (
        v359,
        v362,
        v364,
        v366,
        v368,
        v371,
        v375,
        v381,
        v383,
        v387,
        v390,
        v399,
        v409,
        v414,
        v416,
        v421,
        v436,
        v438,
        v449,
        v455,
        v465,
        v475,
        v478,
        v485,
        v488,
        v490,
        v492,
        v494,
        v497,
        v502,
        v505,
        v507,
        v513,
        v514,
        v516,
        v519,
        v522,
        v525,
        v530,
        v533,
        v535,
        v536,
    ) = {
        let v358: f64 = v242 * v345;
        let v359: f64 = v357 + v358;
        let v360: f64 = v248 * v255;
        let v361: f64 = v227 * v345;
        let v362: f64 = v360 + v361;
        let v363: f64 = q[4];
        let (v366, v364): (f64, f64) = ::libm::sincos(v363);
        let v365: f64 = v364 * v236;
        let v367: f64 = v366 * v251;
        let v368: f64 = v365 - v367;
        let v369: f64 = v364 * v151;
        let v370: f64 = v366 * v257;
        let v371: f64 = v369 - v370;
        let v372: f64 = v368 * v371;
        let v373: f64 = v364 * v251;
        let v374: f64 = v366 * v236;
        let v375: f64 = v373 + v374;
        let v376: f64 = v366 * v151;
        let v377: f64 = v364 * v257;
        let v378: f64 = v376 + v377;
        let v379: f64 = v375 * v378;
        let v380: f64 = v372 + v379;
        let v381: f64 = v380 + v278;
        let v382: f64 = qdd[4];
        let v383: f64 = v248 + v382;
        let v384: f64 = v383 * v371;
        let v385: f64 = v364 * v242;
        let v386: f64 = v366 * v232;
        let v387: f64 = v385 - v386;
        let v388: f64 = v364 * v232;
        let v389: f64 = v366 * v242;
        let v390: f64 = v388 + v389;
        let v391: f64 = v390 * v371;
        let v392: f64 = v387 * v378;
        let v393: f64 = v391 - v392;
        let v394: f64 = v387 * v393;
        let v395: f64 = v384 + v394;
        let v396: f64 = v368 * v255;
        let v397: f64 = v395 + v396;
        let v398: f64 = qd[4];
        let v399: f64 = v227 + v398;
        let v400: f64 = v390 * v277;
        let v401: f64 = v399 * v378;
        let v402: f64 = v400 - v401;
        let v403: f64 = v399 * v402;
        let v404: f64 = v397 + v403;
        let v405: f64 = v364 * v296;
        let v406: f64 = v366 * v267;
        let v407: f64 = v405 - v406;
        let v408: f64 = v390 * v398;
        let v409: f64 = v407 - v408;
        let v410: f64 = v409 * v277;
        let v411: f64 = v404 - v410;
        let v412: f64 = v364 * v113;
        let v413: f64 = v366 * v272;
        let v414: f64 = v412 - v413;
        let v415: f64 = v271 * v414;
        let v416: f64 = v411 - v415;
        let v417: f64 = v364 * v267;
        let v418: f64 = v366 * v296;
        let v419: f64 = v417 + v418;
        let v420: f64 = v387 * v398;
        let v421: f64 = v419 + v420;
        let v422: f64 = v421 * v371;
        let v423: f64 = v409 * v378;
        let v424: f64 = v422 - v423;
        let v425: f64 = v390 * v402;
        let v426: f64 = v424 + v425;
        let v427: f64 = v387 * v277;
        let v428: f64 = v399 * v371;
        let v429: f64 = v427 - v428;
        let v430: f64 = v387 * v429;
        let v431: f64 = v426 + v430;
        let v432: f64 = v375 * v414;
        let v433: f64 = v431 - v432;
        let v434: f64 = v366 * v113;
        let v435: f64 = v364 * v272;
        let v436: f64 = v434 + v435;
        let v437: f64 = v368 * v436;
        let v438: f64 = v433 + v437;
        let v439: f64 = v399 * v429;
        let v440: f64 = v390 * v393;
        let v441: f64 = v383 * v378;
        let v442: f64 = v440 + v441;
        let v443: f64 = v375 * v255;
        let v444: f64 = v442 + v443;
        let v445: f64 = v439 - v444;
        let v446: f64 = v421 * v277;
        let v447: f64 = v445 + v446;
        let v448: f64 = v271 * v436;
        let v449: f64 = v447 + v448;
        let v450: f64 = v399 * v414;
        let v451: f64 = v387 * v255;
        let v452: f64 = v450 - v451;
        let v453: f64 = v390 * v452;
        let v454: f64 = v421 * v436;
        let v455: f64 = v453 + v454;
        let v456: f64 = v390 * v414;
        let v457: f64 = v387 * v436;
        let v458: f64 = v456 - v457;
        let v459: f64 = v390 * v458;
        let v460: f64 = v421 * v255;
        let v461: f64 = v399 * v452;
        let v462: f64 = v460 + v461;
        let v463: f64 = v459 - v462;
        let v464: f64 = v383 * v436;
        let v465: f64 = v463 - v464;
        let v466: f64 = v387 * v452;
        let v467: f64 = v421 * v414;
        let v468: f64 = v466 + v467;
        let v469: f64 = v390 * v255;
        let v470: f64 = v399 * v436;
        let v471: f64 = v469 - v470;
        let v472: f64 = v390 * v471;
        let v473: f64 = v468 + v472;
        let v474: f64 = v409 * v436;
        let v475: f64 = v473 + v474;
        let v476: f64 = v383 * v255;
        let v477: f64 = v399 * v458;
        let v478: f64 = v476 - v477;
        let v479: f64 = v387 * v458;
        let v480: f64 = v409 * v255;
        let v481: f64 = v383 * v414;
        let v482: f64 = v480 + v481;
        let v483: f64 = v479 - v482;
        let v484: f64 = v399 * v471;
        let v485: f64 = v483 - v484;
        let v486: f64 = v409 * v414;
        let v487: f64 = v387 * v471;
        let v488: f64 = v486 + v487;
        let v489: f64 = q[5];
        let (v490, v492): (f64, f64) = ::libm::sincos(v489);
        let v491: f64 = v490 * v375;
        let v493: f64 = v492 * v271;
        let v494: f64 = v491 + v493;
        let v495: f64 = v490 * v378;
        let v496: f64 = v492 * v277;
        let v497: f64 = v495 + v496;
        let v498: f64 = v494 * v497;
        let v499: f64 = v372 + v498;
        let v500: f64 = v492 * v375;
        let v501: f64 = v490 * v271;
        let v502: f64 = v500 - v501;
        let v503: f64 = v492 * v378;
        let v504: f64 = v490 * v277;
        let v505: f64 = v503 - v504;
        let v506: f64 = v502 * v505;
        let v507: f64 = v499 + v506;
        let v508: f64 = v490 * v421;
        let v509: f64 = v492 * v383;
        let v510: f64 = v508 + v509;
        let v511: f64 = v492 * v390;
        let v512: f64 = v490 * v399;
        let v513: f64 = v511 - v512;
        let v514: f64 = qd[5];
        let v515: f64 = v513 * v514;
        let v516: f64 = v510 + v515;
        let v517: f64 = v516 * v371;
        let v518: f64 = qdd[5];
        let v519: f64 = v409 + v518;
        let v520: f64 = v519 * v497;
        let v521: f64 = v517 - v520;
        let v522: f64 = v387 + v514;
        let v523: f64 = v513 * v371;
        let v524: f64 = v522 * v505;
        let v525: f64 = v523 - v524;
        let v526: f64 = v522 * v525;
        let v527: f64 = v521 + v526;
        let v528: f64 = v490 * v390;
        let v529: f64 = v492 * v399;
        let v530: f64 = v528 + v529;
        let v531: f64 = v513 * v497;
        let v532: f64 = v530 * v505;
        let v533: f64 = v531 - v532;
        let v534: f64 = v530 * v533;
        let v535: f64 = v527 + v534;
        let v536: f64 = v494 * v414;
        (
            v359,
            v362,
            v364,
            v366,
            v368,
            v371,
            v375,
            v381,
            v383,
            v387,
            v390,
            v399,
            v409,
            v414,
            v416,
            v421,
            v436,
            v438,
            v449,
            v455,
            v465,
            v475,
            v478,
            v485,
            v488,
            v490,
            v492,
            v494,
            v497,
            v502,
            v505,
            v507,
            v513,
            v514,
            v516,
            v519,
            v522,
            v525,
            v530,
            v533,
            v535,
            v536,
        )
    };
    let (
        v542,
        v547,
        v564,
        v575,
        v581,
        v591,
        v601,
        v604,
        v611,
        v614,
        v615,
        v620,
        v623,
        v626,
        v628,
        v631,
        v632,
        v636,
        v638,
        v648,
        v656,
        v663,
        v665,
        v667,
        v670,
        v673,
        v674,
        v677,
        v678,
        v682,
        v683,
        v684,
        v685,
        v692,
        v696,
        v700,
        v704,
        v708,
        v713,
        v714,
        v715,
    ) = {
        let v537: f64 = v535 - v536;
        let v538: f64 = v492 * v255;
        let v539: f64 = v490 * v436;
        let v540: f64 = v538 + v539;
        let v541: f64 = v368 * v540;
        let v542: f64 = v537 + v541;
        let v543: f64 = v492 * v421;
        let v544: f64 = v490 * v383;
        let v545: f64 = v543 - v544;
        let v546: f64 = v530 * v514;
        let v547: f64 = v545 - v546;
        let v548: f64 = v547 * v371;
        let v549: f64 = v522 * v497;
        let v550: f64 = v530 * v371;
        let v551: f64 = v549 - v550;
        let v552: f64 = v522 * v551;
        let v553: f64 = v548 + v552;
        let v554: f64 = v513 * v533;
        let v555: f64 = v553 + v554;
        let v556: f64 = v519 * v505;
        let v557: f64 = v555 - v556;
        let v558: f64 = v502 * v414;
        let v559: f64 = v557 - v558;
        let v560: f64 = v492 * v436;
        let v561: f64 = v490 * v255;
        let v562: f64 = v560 - v561;
        let v563: f64 = v368 * v562;
        let v564: f64 = v559 + v563;
        let v565: f64 = v530 * v551;
        let v566: f64 = v547 * v497;
        let v567: f64 = v565 + v566;
        let v568: f64 = v513 * v525;
        let v569: f64 = v567 - v568;
        let v570: f64 = v516 * v505;
        let v571: f64 = v569 - v570;
        let v572: f64 = v502 * v540;
        let v573: f64 = v571 - v572;
        let v574: f64 = v494 * v562;
        let v575: f64 = v573 + v574;
        let v576: f64 = v530 * v414;
        let v577: f64 = v522 * v540;
        let v578: f64 = v576 - v577;
        let v579: f64 = v513 * v578;
        let v580: f64 = v547 * v562;
        let v581: f64 = v579 + v580;
        let v582: f64 = v513 * v414;
        let v583: f64 = v522 * v562;
        let v584: f64 = v582 - v583;
        let v585: f64 = v513 * v584;
        let v586: f64 = v530 * v578;
        let v587: f64 = v547 * v540;
        let v588: f64 = v586 + v587;
        let v589: f64 = v585 - v588;
        let v590: f64 = v516 * v562;
        let v591: f64 = v589 - v590;
        let v592: f64 = v547 * v414;
        let v593: f64 = v522 * v578;
        let v594: f64 = v592 + v593;
        let v595: f64 = v513 * v540;
        let v596: f64 = v530 * v562;
        let v597: f64 = v595 - v596;
        let v598: f64 = v513 * v597;
        let v599: f64 = v594 + v598;
        let v600: f64 = v519 * v562;
        let v601: f64 = v599 + v600;
        let v602: f64 = v516 * v540;
        let v603: f64 = v530 * v584;
        let v604: f64 = v602 - v603;
        let v605: f64 = v522 * v584;
        let v606: f64 = v516 * v414;
        let v607: f64 = v519 * v540;
        let v608: f64 = v606 + v607;
        let v609: f64 = v605 - v608;
        let v610: f64 = v530 * v597;
        let v611: f64 = v609 - v610;
        let v612: f64 = v519 * v414;
        let v613: f64 = v522 * v597;
        let v614: f64 = v612 + v613;
        let v615: f64 = v5 * v51;
        let v616: f64 = -0.4318_f64;
        let v617: f64 = v616 * v4;
        let v618: f64 = v25 * v617;
        let v619: f64 = v48 - v618;
        let v620: f64 = v619 + v51;
        let v621: f64 = v4 * v617;
        let v622: f64 = v621 - v43;
        let v623: f64 = v622 - v41;
        let v624: f64 = v616 * v30;
        let v625: f64 = v25 * v7;
        let v626: f64 = v624 + v625;
        let v627: f64 = v4 * v25;
        let v628: f64 = -v627;
        let v629: f64 = v4 * v4;
        let v630: f64 = v25 * v25;
        let v631: f64 = v629 - v630;
        let v632: f64 = v25 * v4;
        let v633: f64 = v5 * v87;
        let v634: f64 = v126 * v633;
        let v635: f64 = v5 * v85;
        let v636: f64 = v635 + v83;
        let v637: f64 = v147 * v636;
        let v638: f64 = v634 + v637;
        let v639: f64 = v104 * v633;
        let v640: f64 = v104 * v639;
        let v641: f64 = v147 - v640;
        let v642: f64 = v92 * v636;
        let v643: f64 = v99 * v633;
        let v644: f64 = v642 - v643;
        let v645: f64 = v99 * v644;
        let v646: f64 = v641 + v645;
        let v647: f64 = v140 * v636;
        let v648: f64 = v646 + v647;
        let v649: f64 = v137 * v636;
        let v650: f64 = v95 * v633;
        let v651: f64 = v92 * v639;
        let v652: f64 = v650 + v651;
        let v653: f64 = v104 * v636;
        let v654: f64 = v99 * v653;
        let v655: f64 = v652 + v654;
        let v656: f64 = v649 - v655;
        let v657: f64 = v140 * v633;
        let v658: f64 = v126 + v657;
        let v659: f64 = v104 * v653;
        let v660: f64 = v658 + v659;
        let v661: f64 = v92 * v644;
        let v662: f64 = v660 + v661;
        let v663: f64 = -v662;
        let v664: f64 = v92 * v99;
        let v665: f64 = -v664;
        let v666: f64 = v104 * v99;
        let v667: f64 = v666 - v137;
        let v668: f64 = v92 * v92;
        let v669: f64 = v99 * v99;
        let v670: f64 = v668 - v669;
        let v671: f64 = v104 * v92;
        let v672: f64 = v95 + v671;
        let v673: f64 = -v672;
        let v674: f64 = v99 * v92;
        let v675: f64 = v236 * v636;
        let v676: f64 = v225 * v633;
        let v677: f64 = v5 * v225;
        let v678: f64 = v676 - v677;
        let v679: f64 = v251 * v678;
        let v680: f64 = v675 + v679;
        let v681: f64 = v223 * v633;
        let v682: f64 = v5 * v223;
        let v683: f64 = v681 - v682;
        let v684: f64 = v271 * v683;
        let v685: f64 = v680 + v684;
        let v686: f64 = v248 * v636;
        let v687: f64 = v242 * v678;
        let v688: f64 = v232 * v636;
        let v689: f64 = v687 - v688;
        let v690: f64 = v242 * v689;
        let v691: f64 = v686 - v690;
        let v692: f64 = v236 * v225;
        let v693: f64 = v691 + v692;
        let v694: f64 = v232 * v683;
        let v695: f64 = v227 * v678;
        let v696: f64 = v694 - v695;
        let v697: f64 = v227 * v696;
        let v698: f64 = v693 + v697;
        let v699: f64 = v296 * v683;
        let v700: f64 = v698 - v699;
        let v701: f64 = v232 * v689;
        let v702: f64 = v248 * v678;
        let v703: f64 = v701 - v702;
        let v704: f64 = v251 * v225;
        let v705: f64 = v703 - v704;
        let v706: f64 = v227 * v636;
        let v707: f64 = v242 * v683;
        let v708: f64 = v706 - v707;
        let v709: f64 = v227 * v708;
        let v710: f64 = v705 - v709;
        let v711: f64 = v267 * v683;
        let v712: f64 = v710 + v711;
        let v713: f64 = v271 * v223;
        let v714: f64 = v712 - v713;
        let v715: f64 = v296 * v678;
        (
            v542,
            v547,
            v564,
            v575,
            v581,
            v591,
            v601,
            v604,
            v611,
            v614,
            v615,
            v620,
            v623,
            v626,
            v628,
            v631,
            v632,
            v636,
            v638,
            v648,
            v656,
            v663,
            v665,
            v667,
            v670,
            v673,
            v674,
            v677,
            v678,
            v682,
            v683,
            v684,
            v685,
            v692,
            v696,
            v700,
            v704,
            v708,
            v713,
            v714,
            v715,
        )
    };
    let (
        v722,
        v723,
        v728,
        v736,
        v744,
        v745,
        v750,
        v753,
        v763,
        v770,
        v779,
        v780,
        v781,
        v792,
        v795,
        v796,
        v801,
        v806,
        v807,
        v813,
        v823,
        v833,
        v836,
        v843,
        v846,
        v849,
        v854,
        v856,
        v862,
        v870,
        v874,
        v875,
        v876,
        v887,
        v891,
        v892,
        v893,
        v894,
    ) = {
        let v716: f64 = v267 * v636;
        let v717: f64 = v715 - v716;
        let v718: f64 = v242 * v708;
        let v719: f64 = v717 + v718;
        let v720: f64 = v232 * v696;
        let v721: f64 = v719 - v720;
        let v722: f64 = v236 * v223;
        let v723: f64 = v721 + v722;
        let v724: f64 = v242 * v225;
        let v725: f64 = v232 * v724;
        let v726: f64 = v267 * v223;
        let v727: f64 = v725 + v726;
        let v728: f64 = -v727;
        let v729: f64 = v232 * v225;
        let v730: f64 = v227 * v223;
        let v731: f64 = v729 + v730;
        let v732: f64 = v232 * v731;
        let v733: f64 = v242 * v724;
        let v734: f64 = v732 - v733;
        let v735: f64 = v296 * v223;
        let v736: f64 = v734 - v735;
        let v737: f64 = v267 * v225;
        let v738: f64 = v227 * v724;
        let v739: f64 = v737 - v738;
        let v740: f64 = v242 * v223;
        let v741: f64 = v232 * v740;
        let v742: f64 = v739 - v741;
        let v743: f64 = v248 * v223;
        let v744: f64 = v742 - v743;
        let v745: f64 = v242 * v731;
        let v746: f64 = v296 * v225;
        let v747: f64 = v227 * v731;
        let v748: f64 = v746 + v747;
        let v749: f64 = v242 * v740;
        let v750: f64 = v748 - v749;
        let v751: f64 = v248 * v225;
        let v752: f64 = v227 * v740;
        let v753: f64 = v751 - v752;
        let v754: f64 = v364 * v636;
        let v755: f64 = v366 * v678;
        let v756: f64 = v754 - v755;
        let v757: f64 = v368 * v756;
        let v758: f64 = v366 * v636;
        let v759: f64 = v364 * v678;
        let v760: f64 = v758 + v759;
        let v761: f64 = v375 * v760;
        let v762: f64 = v757 + v761;
        let v763: f64 = v762 + v684;
        let v764: f64 = v383 * v756;
        let v765: f64 = v390 * v756;
        let v766: f64 = v387 * v760;
        let v767: f64 = v765 - v766;
        let v768: f64 = v387 * v767;
        let v769: f64 = v764 + v768;
        let v770: f64 = v368 * v225;
        let v771: f64 = v769 + v770;
        let v772: f64 = v390 * v683;
        let v773: f64 = v399 * v760;
        let v774: f64 = v772 - v773;
        let v775: f64 = v399 * v774;
        let v776: f64 = v771 + v775;
        let v777: f64 = v409 * v683;
        let v778: f64 = v776 - v777;
        let v779: f64 = v366 * v223;
        let v780: f64 = v271 * v779;
        let v781: f64 = v778 - v780;
        let v782: f64 = v421 * v756;
        let v783: f64 = v409 * v760;
        let v784: f64 = v782 - v783;
        let v785: f64 = v390 * v774;
        let v786: f64 = v784 + v785;
        let v787: f64 = v387 * v683;
        let v788: f64 = v399 * v756;
        let v789: f64 = v787 - v788;
        let v790: f64 = v387 * v789;
        let v791: f64 = v786 + v790;
        let v792: f64 = v375 * v779;
        let v793: f64 = v791 - v792;
        let v794: f64 = v364 * v223;
        let v795: f64 = v368 * v794;
        let v796: f64 = v793 - v795;
        let v797: f64 = v399 * v789;
        let v798: f64 = v390 * v767;
        let v799: f64 = v383 * v760;
        let v800: f64 = v798 + v799;
        let v801: f64 = v375 * v225;
        let v802: f64 = v800 + v801;
        let v803: f64 = v797 - v802;
        let v804: f64 = v421 * v683;
        let v805: f64 = v803 + v804;
        let v806: f64 = v271 * v794;
        let v807: f64 = v805 - v806;
        let v808: f64 = v399 * v779;
        let v809: f64 = v387 * v225;
        let v810: f64 = v808 - v809;
        let v811: f64 = v390 * v810;
        let v812: f64 = v421 * v794;
        let v813: f64 = v811 - v812;
        let v814: f64 = v390 * v779;
        let v815: f64 = v387 * v794;
        let v816: f64 = v814 + v815;
        let v817: f64 = v390 * v816;
        let v818: f64 = v421 * v225;
        let v819: f64 = v399 * v810;
        let v820: f64 = v818 + v819;
        let v821: f64 = v817 - v820;
        let v822: f64 = v383 * v794;
        let v823: f64 = v821 + v822;
        let v824: f64 = v387 * v810;
        let v825: f64 = v421 * v779;
        let v826: f64 = v824 + v825;
        let v827: f64 = v390 * v225;
        let v828: f64 = v399 * v794;
        let v829: f64 = v827 + v828;
        let v830: f64 = v390 * v829;
        let v831: f64 = v826 + v830;
        let v832: f64 = v409 * v794;
        let v833: f64 = v831 - v832;
        let v834: f64 = v383 * v225;
        let v835: f64 = v399 * v816;
        let v836: f64 = v834 - v835;
        let v837: f64 = v387 * v816;
        let v838: f64 = v409 * v225;
        let v839: f64 = v383 * v779;
        let v840: f64 = v838 + v839;
        let v841: f64 = v837 - v840;
        let v842: f64 = v399 * v829;
        let v843: f64 = v841 - v842;
        let v844: f64 = v409 * v779;
        let v845: f64 = v387 * v829;
        let v846: f64 = v844 + v845;
        let v847: f64 = v490 * v760;
        let v848: f64 = v492 * v683;
        let v849: f64 = v847 + v848;
        let v850: f64 = v494 * v849;
        let v851: f64 = v757 + v850;
        let v852: f64 = v492 * v760;
        let v853: f64 = v490 * v683;
        let v854: f64 = v852 - v853;
        let v855: f64 = v502 * v854;
        let v856: f64 = v851 + v855;
        let v857: f64 = v516 * v756;
        let v858: f64 = v519 * v849;
        let v859: f64 = v857 - v858;
        let v860: f64 = v513 * v756;
        let v861: f64 = v522 * v854;
        let v862: f64 = v860 - v861;
        let v863: f64 = v522 * v862;
        let v864: f64 = v859 + v863;
        let v865: f64 = v513 * v849;
        let v866: f64 = v530 * v854;
        let v867: f64 = v865 - v866;
        let v868: f64 = v530 * v867;
        let v869: f64 = v864 + v868;
        let v870: f64 = v494 * v779;
        let v871: f64 = v869 - v870;
        let v872: f64 = v490 * v794;
        let v873: f64 = v492 * v225;
        let v874: f64 = v872 - v873;
        let v875: f64 = v368 * v874;
        let v876: f64 = v871 - v875;
        let v877: f64 = v547 * v756;
        let v878: f64 = v522 * v849;
        let v879: f64 = v530 * v756;
        let v880: f64 = v878 - v879;
        let v881: f64 = v522 * v880;
        let v882: f64 = v877 + v881;
        let v883: f64 = v513 * v867;
        let v884: f64 = v882 + v883;
        let v885: f64 = v519 * v854;
        let v886: f64 = v884 - v885;
        let v887: f64 = v502 * v779;
        let v888: f64 = v886 - v887;
        let v889: f64 = v490 * v225;
        let v890: f64 = v492 * v794;
        let v891: f64 = v889 + v890;
        let v892: f64 = v368 * v891;
        let v893: f64 = v888 - v892;
        let v894: f64 = v530 * v880;
        (
            v722,
            v723,
            v728,
            v736,
            v744,
            v745,
            v750,
            v753,
            v763,
            v770,
            v779,
            v780,
            v781,
            v792,
            v795,
            v796,
            v801,
            v806,
            v807,
            v813,
            v823,
            v833,
            v836,
            v843,
            v846,
            v849,
            v854,
            v856,
            v862,
            v870,
            v874,
            v875,
            v876,
            v887,
            v891,
            v892,
            v893,
            v894,
        )
    };
    let (
        v901,
        v903,
        v904,
        v910,
        v920,
        v930,
        v934,
        v941,
        v944,
        v945,
        v949,
        v954,
        v958,
        v963,
        v977,
        v989,
        v997,
        v1007,
        v1022,
        v1034,
        v1044,
        v1047,
        v1052,
        v1054,
        v1060,
        v1065,
        v1069,
        v1070,
        v1073,
    ) = {
        let v895: f64 = v547 * v849;
        let v896: f64 = v894 + v895;
        let v897: f64 = v513 * v862;
        let v898: f64 = v896 - v897;
        let v899: f64 = v516 * v854;
        let v900: f64 = v898 - v899;
        let v901: f64 = v502 * v874;
        let v902: f64 = v900 + v901;
        let v903: f64 = v494 * v891;
        let v904: f64 = v902 - v903;
        let v905: f64 = v530 * v779;
        let v906: f64 = v522 * v874;
        let v907: f64 = v905 + v906;
        let v908: f64 = v513 * v907;
        let v909: f64 = v547 * v891;
        let v910: f64 = v908 - v909;
        let v911: f64 = v547 * v874;
        let v912: f64 = v530 * v907;
        let v913: f64 = v911 - v912;
        let v914: f64 = v513 * v779;
        let v915: f64 = v522 * v891;
        let v916: f64 = v914 + v915;
        let v917: f64 = v513 * v916;
        let v918: f64 = v913 + v917;
        let v919: f64 = v516 * v891;
        let v920: f64 = v918 + v919;
        let v921: f64 = v547 * v779;
        let v922: f64 = v522 * v907;
        let v923: f64 = v921 + v922;
        let v924: f64 = v530 * v891;
        let v925: f64 = v513 * v874;
        let v926: f64 = v924 - v925;
        let v927: f64 = v513 * v926;
        let v928: f64 = v923 + v927;
        let v929: f64 = v519 * v891;
        let v930: f64 = v928 - v929;
        let v931: f64 = v516 * v874;
        let v932: f64 = v530 * v916;
        let v933: f64 = v931 + v932;
        let v934: f64 = -v933;
        let v935: f64 = v519 * v874;
        let v936: f64 = v516 * v779;
        let v937: f64 = v935 - v936;
        let v938: f64 = v522 * v916;
        let v939: f64 = v937 + v938;
        let v940: f64 = v530 * v926;
        let v941: f64 = v939 - v940;
        let v942: f64 = v519 * v779;
        let v943: f64 = v522 * v926;
        let v944: f64 = v942 + v943;
        let v945: f64 = v83 * v147;
        let v946: f64 = v83 * v92;
        let v947: f64 = v99 * v946;
        let v948: f64 = v147 + v947;
        let v949: f64 = v948 + v141;
        let v950: f64 = -0.0203_f64;
        let v951: f64 = v950 * v104;
        let v952: f64 = v99 * v951;
        let v953: f64 = v83 * v137;
        let v954: f64 = v952 + v953;
        let v955: f64 = v104 * v951;
        let v956: f64 = v955 - v126;
        let v957: f64 = v92 * v946;
        let v958: f64 = v956 - v957;
        let v959: f64 = v83 * v236;
        let v960: f64 = v251 * v677;
        let v961: f64 = v959 - v960;
        let v962: f64 = v271 * v682;
        let v963: f64 = v961 - v962;
        let v964: f64 = v83 * v248;
        let v965: f64 = v950 * v232;
        let v966: f64 = v242 * v677;
        let v967: f64 = v965 - v966;
        let v968: f64 = v242 * v967;
        let v969: f64 = v964 - v968;
        let v970: f64 = v969 + v692;
        let v971: f64 = v227 * v677;
        let v972: f64 = v232 * v682;
        let v973: f64 = v971 - v972;
        let v974: f64 = v227 * v973;
        let v975: f64 = v970 + v974;
        let v976: f64 = v296 * v682;
        let v977: f64 = v975 + v976;
        let v978: f64 = v232 * v967;
        let v979: f64 = v248 * v677;
        let v980: f64 = v978 + v979;
        let v981: f64 = v980 - v704;
        let v982: f64 = v83 * v227;
        let v983: f64 = v242 * v682;
        let v984: f64 = v982 + v983;
        let v985: f64 = v227 * v984;
        let v986: f64 = v981 - v985;
        let v987: f64 = v267 * v682;
        let v988: f64 = v986 - v987;
        let v989: f64 = v988 - v713;
        let v990: f64 = v950 * v267;
        let v991: f64 = v296 * v677;
        let v992: f64 = v990 - v991;
        let v993: f64 = v242 * v984;
        let v994: f64 = v992 + v993;
        let v995: f64 = v232 * v973;
        let v996: f64 = v994 - v995;
        let v997: f64 = v996 + v722;
        let v998: f64 = v83 * v364;
        let v999: f64 = v366 * v677;
        let v1000: f64 = v998 + v999;
        let v1001: f64 = v368 * v1000;
        let v1002: f64 = v83 * v366;
        let v1003: f64 = v364 * v677;
        let v1004: f64 = v1002 - v1003;
        let v1005: f64 = v375 * v1004;
        let v1006: f64 = v1001 + v1005;
        let v1007: f64 = v1006 - v962;
        let v1008: f64 = v383 * v1000;
        let v1009: f64 = v390 * v1000;
        let v1010: f64 = v387 * v1004;
        let v1011: f64 = v1009 - v1010;
        let v1012: f64 = v387 * v1011;
        let v1013: f64 = v1008 + v1012;
        let v1014: f64 = v1013 + v770;
        let v1015: f64 = v399 * v1004;
        let v1016: f64 = v390 * v682;
        let v1017: f64 = v1015 + v1016;
        let v1018: f64 = v399 * v1017;
        let v1019: f64 = v1014 - v1018;
        let v1020: f64 = v409 * v682;
        let v1021: f64 = v1019 + v1020;
        let v1022: f64 = v1021 - v780;
        let v1023: f64 = v421 * v1000;
        let v1024: f64 = v409 * v1004;
        let v1025: f64 = v1023 - v1024;
        let v1026: f64 = v390 * v1017;
        let v1027: f64 = v1025 - v1026;
        let v1028: f64 = v399 * v1000;
        let v1029: f64 = v387 * v682;
        let v1030: f64 = v1028 + v1029;
        let v1031: f64 = v387 * v1030;
        let v1032: f64 = v1027 - v1031;
        let v1033: f64 = v1032 - v792;
        let v1034: f64 = v1033 - v795;
        let v1035: f64 = v390 * v1011;
        let v1036: f64 = v383 * v1004;
        let v1037: f64 = v1035 + v1036;
        let v1038: f64 = v1037 + v801;
        let v1039: f64 = v399 * v1030;
        let v1040: f64 = v1038 + v1039;
        let v1041: f64 = v421 * v682;
        let v1042: f64 = v1040 + v1041;
        let v1043: f64 = v1042 + v806;
        let v1044: f64 = -v1043;
        let v1045: f64 = v492 * v682;
        let v1046: f64 = v490 * v1004;
        let v1047: f64 = v1045 - v1046;
        let v1048: f64 = v494 * v1047;
        let v1049: f64 = v1001 - v1048;
        let v1050: f64 = v492 * v1004;
        let v1051: f64 = v490 * v682;
        let v1052: f64 = v1050 + v1051;
        let v1053: f64 = v502 * v1052;
        let v1054: f64 = v1049 + v1053;
        let v1055: f64 = v516 * v1000;
        let v1056: f64 = v519 * v1047;
        let v1057: f64 = v1055 + v1056;
        let v1058: f64 = v513 * v1000;
        let v1059: f64 = v522 * v1052;
        let v1060: f64 = v1058 - v1059;
        let v1061: f64 = v522 * v1060;
        let v1062: f64 = v1057 + v1061;
        let v1063: f64 = v513 * v1047;
        let v1064: f64 = v530 * v1052;
        let v1065: f64 = v1063 + v1064;
        let v1066: f64 = v530 * v1065;
        let v1067: f64 = v1062 - v1066;
        let v1068: f64 = v1067 - v870;
        let v1069: f64 = v1068 - v875;
        let v1070: f64 = v547 * v1000;
        let v1071: f64 = v530 * v1000;
        let v1072: f64 = v522 * v1047;
        let v1073: f64 = v1071 + v1072;
        (
            v901,
            v903,
            v904,
            v910,
            v920,
            v930,
            v934,
            v941,
            v944,
            v945,
            v949,
            v954,
            v958,
            v963,
            v977,
            v989,
            v997,
            v1007,
            v1022,
            v1034,
            v1044,
            v1047,
            v1052,
            v1054,
            v1060,
            v1065,
            v1069,
            v1070,
            v1073,
        )
    };
    let (
        v1081,
        v1090,
        v1091,
        v1092,
        v1094,
        v1097,
        v1099,
        v1101,
        v1103,
        v1106,
        v1107,
        v1111,
        v1119,
        v1127,
        v1129,
        v1134,
        v1137,
        v1141,
        v1145,
        v1148,
        v1154,
        v1164,
        v1174,
        v1177,
        v1184,
        v1187,
        v1188,
        v1190,
        v1192,
        v1195,
        v1198,
        v1199,
        v1200,
        v1202,
        v1206,
        v1211,
        v1219,
        v1227,
        v1230,
        v1235,
        v1236,
        v1237,
        v1238,
        v1239,
        v1242,
        v1244,
        v1246,
        v1248,
        v1249,
    ) = {
        let v1074: f64 = v522 * v1073;
        let v1075: f64 = v1070 - v1074;
        let v1076: f64 = v513 * v1065;
        let v1077: f64 = v1075 - v1076;
        let v1078: f64 = v519 * v1052;
        let v1079: f64 = v1077 - v1078;
        let v1080: f64 = v1079 - v887;
        let v1081: f64 = v1080 - v892;
        let v1082: f64 = v530 * v1073;
        let v1083: f64 = v547 * v1047;
        let v1084: f64 = v1082 + v1083;
        let v1085: f64 = v513 * v1060;
        let v1086: f64 = v1084 + v1085;
        let v1087: f64 = v516 * v1052;
        let v1088: f64 = v1086 + v1087;
        let v1089: f64 = v901 - v1088;
        let v1090: f64 = v1089 - v903;
        let v1091: f64 = -v271;
        let v1092: f64 = v232 * v227;
        let v1093: f64 = v242 * v227;
        let v1094: f64 = v267 + v1093;
        let v1095: f64 = v227 * v227;
        let v1096: f64 = v232 * v232;
        let v1097: f64 = v1095 - v1096;
        let v1098: f64 = v242 * v232;
        let v1099: f64 = v248 - v1098;
        let v1100: f64 = v227 * v232;
        let v1101: f64 = -v1100;
        let v1102: f64 = v271 * v364;
        let v1103: f64 = -v1102;
        let v1104: f64 = v368 * v366;
        let v1105: f64 = v375 * v364;
        let v1106: f64 = v1104 - v1105;
        let v1107: f64 = v271 * v366;
        let v1108: f64 = v399 * v364;
        let v1109: f64 = v390 * v1108;
        let v1110: f64 = v421 * v366;
        let v1111: f64 = v1109 + v1110;
        let v1112: f64 = v390 * v364;
        let v1113: f64 = v387 * v366;
        let v1114: f64 = v1112 - v1113;
        let v1115: f64 = v390 * v1114;
        let v1116: f64 = v399 * v1108;
        let v1117: f64 = v1115 - v1116;
        let v1118: f64 = v383 * v366;
        let v1119: f64 = v1117 - v1118;
        let v1120: f64 = v387 * v1108;
        let v1121: f64 = v421 * v364;
        let v1122: f64 = v1120 + v1121;
        let v1123: f64 = v399 * v366;
        let v1124: f64 = v390 * v1123;
        let v1125: f64 = v1122 - v1124;
        let v1126: f64 = v409 * v366;
        let v1127: f64 = v1125 + v1126;
        let v1128: f64 = v399 * v1114;
        let v1129: f64 = -v1128;
        let v1130: f64 = v387 * v1114;
        let v1131: f64 = v383 * v364;
        let v1132: f64 = v1130 - v1131;
        let v1133: f64 = v399 * v1123;
        let v1134: f64 = v1132 + v1133;
        let v1135: f64 = v409 * v364;
        let v1136: f64 = v387 * v1123;
        let v1137: f64 = v1135 - v1136;
        let v1138: f64 = v490 * v366;
        let v1139: f64 = v368 * v1138;
        let v1140: f64 = v494 * v364;
        let v1141: f64 = v1139 - v1140;
        let v1142: f64 = v492 * v366;
        let v1143: f64 = v368 * v1142;
        let v1144: f64 = v502 * v364;
        let v1145: f64 = v1143 - v1144;
        let v1146: f64 = v494 * v1142;
        let v1147: f64 = v502 * v1138;
        let v1148: f64 = v1146 - v1147;
        let v1149: f64 = v530 * v364;
        let v1150: f64 = v522 * v1138;
        let v1151: f64 = v1149 - v1150;
        let v1152: f64 = v513 * v1151;
        let v1153: f64 = v547 * v1142;
        let v1154: f64 = v1152 + v1153;
        let v1155: f64 = v513 * v364;
        let v1156: f64 = v522 * v1142;
        let v1157: f64 = v1155 - v1156;
        let v1158: f64 = v513 * v1157;
        let v1159: f64 = v530 * v1151;
        let v1160: f64 = v547 * v1138;
        let v1161: f64 = v1159 + v1160;
        let v1162: f64 = v1158 - v1161;
        let v1163: f64 = v516 * v1142;
        let v1164: f64 = v1162 - v1163;
        let v1165: f64 = v547 * v364;
        let v1166: f64 = v522 * v1151;
        let v1167: f64 = v1165 + v1166;
        let v1168: f64 = v513 * v1138;
        let v1169: f64 = v530 * v1142;
        let v1170: f64 = v1168 - v1169;
        let v1171: f64 = v513 * v1170;
        let v1172: f64 = v1167 + v1171;
        let v1173: f64 = v519 * v1142;
        let v1174: f64 = v1172 + v1173;
        let v1175: f64 = v516 * v1138;
        let v1176: f64 = v530 * v1157;
        let v1177: f64 = v1175 - v1176;
        let v1178: f64 = v522 * v1157;
        let v1179: f64 = v516 * v364;
        let v1180: f64 = v519 * v1138;
        let v1181: f64 = v1179 + v1180;
        let v1182: f64 = v1178 - v1181;
        let v1183: f64 = v530 * v1170;
        let v1184: f64 = v1182 - v1183;
        let v1185: f64 = v519 * v364;
        let v1186: f64 = v522 * v1170;
        let v1187: f64 = v1185 + v1186;
        let v1188: f64 = -v375;
        let v1189: f64 = v390 * v387;
        let v1190: f64 = -v1189;
        let v1191: f64 = v399 * v387;
        let v1192: f64 = v1191 - v421;
        let v1193: f64 = v390 * v390;
        let v1194: f64 = v387 * v387;
        let v1195: f64 = v1193 - v1194;
        let v1196: f64 = v399 * v390;
        let v1197: f64 = v409 + v1196;
        let v1198: f64 = -v1197;
        let v1199: f64 = v387 * v390;
        let v1200: f64 = v368 * v492;
        let v1201: f64 = v368 * v490;
        let v1202: f64 = -v1201;
        let v1203: f64 = v502 * v492;
        let v1204: f64 = v494 * v490;
        let v1205: f64 = v1203 + v1204;
        let v1206: f64 = -v1205;
        let v1207: f64 = v522 * v492;
        let v1208: f64 = v513 * v1207;
        let v1209: f64 = v547 * v490;
        let v1210: f64 = v1208 + v1209;
        let v1211: f64 = -v1210;
        let v1212: f64 = v530 * v1207;
        let v1213: f64 = v547 * v492;
        let v1214: f64 = v1212 - v1213;
        let v1215: f64 = v522 * v490;
        let v1216: f64 = v513 * v1215;
        let v1217: f64 = v1214 + v1216;
        let v1218: f64 = v516 * v490;
        let v1219: f64 = v1217 + v1218;
        let v1220: f64 = v513 * v492;
        let v1221: f64 = v530 * v490;
        let v1222: f64 = v1220 + v1221;
        let v1223: f64 = v513 * v1222;
        let v1224: f64 = v522 * v1207;
        let v1225: f64 = v1223 - v1224;
        let v1226: f64 = v519 * v490;
        let v1227: f64 = v1225 - v1226;
        let v1228: f64 = v516 * v492;
        let v1229: f64 = v530 * v1215;
        let v1230: f64 = v1228 - v1229;
        let v1231: f64 = v522 * v1215;
        let v1232: f64 = v519 * v492;
        let v1233: f64 = v1231 - v1232;
        let v1234: f64 = v530 * v1222;
        let v1235: f64 = v1233 - v1234;
        let v1236: f64 = v522 * v1222;
        let v1237: f64 = -v494;
        let v1238: f64 = -v502;
        let v1239: f64 = v513 * v530;
        let v1240: f64 = v513 * v513;
        let v1241: f64 = v530 * v530;
        let v1242: f64 = v1240 - v1241;
        let v1243: f64 = v522 * v530;
        let v1244: f64 = v547 + v1243;
        let v1245: f64 = v530 * v513;
        let v1246: f64 = -v1245;
        let v1247: f64 = v522 * v513;
        let v1248: f64 = v1247 - v516;
        let v1249: f64 = 0.0_f64;
        (
            v1081,
            v1090,
            v1091,
            v1092,
            v1094,
            v1097,
            v1099,
            v1101,
            v1103,
            v1106,
            v1107,
            v1111,
            v1119,
            v1127,
            v1129,
            v1134,
            v1137,
            v1141,
            v1145,
            v1148,
            v1154,
            v1164,
            v1174,
            v1177,
            v1184,
            v1187,
            v1188,
            v1190,
            v1192,
            v1195,
            v1198,
            v1199,
            v1200,
            v1202,
            v1206,
            v1211,
            v1219,
            v1227,
            v1230,
            v1235,
            v1236,
            v1237,
            v1238,
            v1239,
            v1242,
            v1244,
            v1246,
            v1248,
            v1249,
        )
    };
    [
        [
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v0,
            v1249,
            v1249,
            v17,
            v23,
            v33,
            v53,
            v57,
            v65,
            v73,
            v76,
            v81,
            v82,
            v153,
            v168,
            v182,
            v191,
            v195,
            v203,
            v211,
            v213,
            v218,
            v221,
            v279,
            v298,
            v312,
            v323,
            v329,
            v339,
            v349,
            v352,
            v359,
            v362,
            v381,
            v416,
            v438,
            v449,
            v455,
            v465,
            v475,
            v478,
            v485,
            v488,
            v507,
            v542,
            v564,
            v575,
            v581,
            v591,
            v601,
            v604,
            v611,
            v614,
        ],
        [
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v615,
            v620,
            v623,
            v626,
            v628,
            v631,
            v28,
            v632,
            v10,
            v47,
            v638,
            v648,
            v656,
            v663,
            v665,
            v667,
            v670,
            v140,
            v673,
            v674,
            v685,
            v700,
            v714,
            v723,
            v728,
            v736,
            v744,
            v745,
            v750,
            v753,
            v763,
            v781,
            v796,
            v807,
            v813,
            v823,
            v833,
            v836,
            v843,
            v846,
            v856,
            v876,
            v893,
            v904,
            v910,
            v920,
            v930,
            v934,
            v941,
            v944,
        ],
        [
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v945,
            v949,
            v954,
            v958,
            v665,
            v667,
            v670,
            v140,
            v673,
            v674,
            v963,
            v977,
            v989,
            v997,
            v728,
            v736,
            v744,
            v745,
            v750,
            v753,
            v1007,
            v1022,
            v1034,
            v1044,
            v813,
            v823,
            v833,
            v836,
            v843,
            v846,
            v1054,
            v1069,
            v1081,
            v1090,
            v910,
            v920,
            v930,
            v934,
            v941,
            v944,
        ],
        [
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1091,
            v1249,
            v251,
            v1092,
            v1094,
            v1097,
            v296,
            v1099,
            v1101,
            v1249,
            v1103,
            v1106,
            v1107,
            v1111,
            v1119,
            v1127,
            v1129,
            v1134,
            v1137,
            v1249,
            v1141,
            v1145,
            v1148,
            v1154,
            v1164,
            v1174,
            v1177,
            v1184,
            v1187,
        ],
        [
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v368,
            v1249,
            v1188,
            v1190,
            v1192,
            v1195,
            v383,
            v1198,
            v1199,
            v1249,
            v1200,
            v1202,
            v1206,
            v1211,
            v1219,
            v1227,
            v1230,
            v1235,
            v1236,
        ],
        [
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1249,
            v1237,
            v1238,
            v1249,
            v1239,
            v1242,
            v1244,
            v1246,
            v1248,
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
    pub fn frame_poses(q: &[f32; 6]) -> [[[f32; 4]; 4]; 6] {
        let v0: f32 = q[0];
        let (v3, v1): (f32, f32) = ::libm::sincosf(v0);
        let v2: f32 = 0.0_f32;
        let v4: f32 = -v1;
        let v5: f32 = 1.0_f32;
        let v6: f32 = 0.6718_f32;
        let v7: f32 = q[1];
        let (v10, v8): (f32, f32) = ::libm::sincosf(v7);
        let v9: f32 = v1 * v8;
        let v11: f32 = v1 * v10;
        let v12: f32 = -v11;
        let v13: f32 = 0.4318_f32;
        let v14: f32 = v13 * v8;
        let v15: f32 = v1 * v14;
        let v16: f32 = v3 * v8;
        let v17: f32 = v3 * v10;
        let v18: f32 = -v17;
        let v19: f32 = v3 * v14;
        let v20: f32 = v13 * v10;
        let v21: f32 = v6 + v20;
        let v22: f32 = q[2];
        let (v25, v23): (f32, f32) = ::libm::sincosf(v22);
        let v24: f32 = v9 * v23;
        let v26: f32 = v11 * v25;
        let v27: f32 = v24 - v26;
        let v28: f32 = -v3;
        let v29: f32 = v9 * v25;
        let v30: f32 = v11 * v23;
        let v31: f32 = v29 + v30;
        let v32: f32 = -v31;
        let v33: f32 = 0.0203_f32;
        let v34: f32 = v33 * v23;
        let v35: f32 = v9 * v34;
        let v36: f32 = v33 * v25;
        let v37: f32 = v11 * v36;
        let v38: f32 = v35 - v37;
        let v39: f32 = 0.15005_f32;
        let v40: f32 = v39 * v3;
        let v41: f32 = v38 + v40;
        let v42: f32 = v15 + v41;
        let v43: f32 = v16 * v23;
        let v44: f32 = v17 * v25;
        let v45: f32 = v43 - v44;
        let v46: f32 = v16 * v25;
        let v47: f32 = v17 * v23;
        let v48: f32 = v46 + v47;
        let v49: f32 = -v48;
        let v50: f32 = v16 * v34;
        let v51: f32 = v17 * v36;
        let v52: f32 = v50 - v51;
        let v53: f32 = v39 * v1;
        let v54: f32 = v52 - v53;
        let v55: f32 = v19 + v54;
        let v56: f32 = v10 * v23;
        let v57: f32 = v8 * v25;
        let v58: f32 = v56 + v57;
        let v59: f32 = v8 * v23;
        let v60: f32 = v10 * v25;
        let v61: f32 = v59 - v60;
        let v62: f32 = v10 * v34;
        let v63: f32 = v8 * v36;
        let v64: f32 = v62 + v63;
        let v65: f32 = v21 + v64;
        let v66: f32 = q[3];
        let (v69, v67): (f32, f32) = ::libm::sincosf(v66);
        let v68: f32 = v27 * v67;
        let v70: f32 = v3 * v69;
        let v71: f32 = v68 - v70;
        let v72: f32 = v27 * v69;
        let v73: f32 = v3 * v67;
        let v74: f32 = v72 + v73;
        let v75: f32 = v13 * v31;
        let v76: f32 = v42 - v75;
        let v77: f32 = v45 * v67;
        let v78: f32 = v1 * v69;
        let v79: f32 = v77 + v78;
        let v80: f32 = v45 * v69;
        let v81: f32 = v1 * v67;
        let v82: f32 = v80 - v81;
        let v83: f32 = v13 * v48;
        let v84: f32 = v55 - v83;
        let v85: f32 = v58 * v67;
        let v86: f32 = v58 * v69;
        let v87: f32 = v13 * v61;
        let v88: f32 = v65 + v87;
        let v89: f32 = q[4];
        let (v92, v90): (f32, f32) = ::libm::sincosf(v89);
        let v91: f32 = v71 * v90;
        let v93: f32 = v31 * v92;
        let v94: f32 = v91 - v93;
        let v95: f32 = -v74;
        let v96: f32 = v71 * v92;
        let v97: f32 = v31 * v90;
        let v98: f32 = v96 + v97;
        let v99: f32 = -v98;
        let v100: f32 = v79 * v90;
        let v101: f32 = v48 * v92;
        let v102: f32 = v100 - v101;
        let v103: f32 = -v82;
        let v104: f32 = v79 * v92;
        let v105: f32 = v48 * v90;
        let v106: f32 = v104 + v105;
        let v107: f32 = -v106;
        let v108: f32 = v85 * v90;
        let v109: f32 = v61 * v92;
        let v110: f32 = v108 + v109;
        let v111: f32 = -v86;
        let v112: f32 = v61 * v90;
        let v113: f32 = v85 * v92;
        let v114: f32 = v112 - v113;
        let v115: f32 = q[5];
        let (v118, v116): (f32, f32) = ::libm::sincosf(v115);
        let v117: f32 = v94 * v116;
        let v119: f32 = v74 * v118;
        let v120: f32 = v117 - v119;
        let v121: f32 = v94 * v118;
        let v122: f32 = v74 * v116;
        let v123: f32 = v121 + v122;
        let v124: f32 = -v123;
        let v125: f32 = v102 * v116;
        let v126: f32 = v82 * v118;
        let v127: f32 = v125 - v126;
        let v128: f32 = v102 * v118;
        let v129: f32 = v82 * v116;
        let v130: f32 = v128 + v129;
        let v131: f32 = -v130;
        let v132: f32 = v110 * v116;
        let v133: f32 = v86 * v118;
        let v134: f32 = v132 - v133;
        let v135: f32 = v110 * v118;
        let v136: f32 = v86 * v116;
        let v137: f32 = v135 + v136;
        let v138: f32 = -v137;
        [
            [[v1, v2, v3, v2], [v3, v2, v4, v2], [v2, v5, v2, v6], [v2, v2, v2, v5]],
            [
                [v9, v12, v3, v15],
                [v16, v18, v4, v19],
                [v10, v8, v2, v21],
                [v2, v2, v2, v5],
            ],
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
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `pose: [[f32; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the base frame (m)
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
    pub fn end_effector_pose(q: &[f32; 6]) -> [[f32; 4]; 4] {
        let v0: f32 = q[2];
        let (v1, v5): (f32, f32) = ::libm::sincosf(v0);
        let v2: f32 = q[1];
        let (v3, v6): (f32, f32) = ::libm::sincosf(v2);
        let v4: f32 = v1 * v3;
        let v7: f32 = v5 * v6;
        let v8: f32 = v4 - v7;
        let v9: f32 = q[5];
        let (v10, v29): (f32, f32) = ::libm::sincosf(v9);
        let v11: f32 = v8 * v10;
        let v12: f32 = q[3];
        let (v13, v17): (f32, f32) = ::libm::sincosf(v12);
        let v14: f32 = v11 * v13;
        let v15: f32 = q[4];
        let (v20, v16): (f32, f32) = ::libm::sincosf(v15);
        let v18: f32 = v16 * v17;
        let v19: f32 = v18 * v5;
        let v21: f32 = v20 * v1;
        let v22: f32 = v19 - v21;
        let v23: f32 = v22 * v6;
        let v24: f32 = v20 * v5;
        let v25: f32 = v18 * v1;
        let v26: f32 = v24 + v25;
        let v27: f32 = v26 * v3;
        let v28: f32 = v23 - v27;
        let v30: f32 = v28 * v29;
        let v31: f32 = v14 + v30;
        let v32: f32 = q[0];
        let (v39, v33): (f32, f32) = ::libm::sincosf(v32);
        let v34: f32 = v31 * v33;
        let v35: f32 = v10 * v17;
        let v36: f32 = v29 * v16;
        let v37: f32 = v36 * v13;
        let v38: f32 = v35 + v37;
        let v40: f32 = v38 * v39;
        let v41: f32 = v34 - v40;
        let v42: f32 = v10 * v16;
        let v43: f32 = v42 * v13;
        let v44: f32 = v29 * v17;
        let v45: f32 = v43 - v44;
        let v46: f32 = v45 * v39;
        let v47: f32 = v8 * v29;
        let v48: f32 = v47 * v13;
        let v49: f32 = v21 - v19;
        let v50: f32 = v49 * v6;
        let v51: f32 = v50 + v27;
        let v52: f32 = v51 * v10;
        let v53: f32 = v48 + v52;
        let v54: f32 = v53 * v33;
        let v55: f32 = v46 + v54;
        let v56: f32 = v20 * v13;
        let v57: f32 = v56 * v39;
        let v58: f32 = v20 * v17;
        let v59: f32 = v58 * v1;
        let v60: f32 = v16 * v5;
        let v61: f32 = v59 - v60;
        let v62: f32 = v61 * v3;
        let v63: f32 = v58 * v5;
        let v64: f32 = v16 * v1;
        let v65: f32 = v63 + v64;
        let v66: f32 = v65 * v6;
        let v67: f32 = v62 - v66;
        let v68: f32 = v67 * v33;
        let v69: f32 = v57 + v68;
        let v70: f32 = 0.15005_f32;
        let v71: f32 = v70 * v39;
        let v72: f32 = 0.4318_f32;
        let v73: f32 = 0.0203_f32;
        let v74: f32 = v73 * v5;
        let v75: f32 = v72 + v74;
        let v76: f32 = v72 * v1;
        let v77: f32 = v75 - v76;
        let v78: f32 = v77 * v6;
        let v79: f32 = v72 * v5;
        let v80: f32 = v73 * v1;
        let v81: f32 = v79 + v80;
        let v82: f32 = v81 * v3;
        let v83: f32 = v78 - v82;
        let v84: f32 = v83 * v33;
        let v85: f32 = v71 + v84;
        let v86: f32 = v38 * v33;
        let v87: f32 = v31 * v39;
        let v88: f32 = v86 + v87;
        let v89: f32 = v44 - v43;
        let v90: f32 = v89 * v33;
        let v91: f32 = v53 * v39;
        let v92: f32 = v90 + v91;
        let v93: f32 = v67 * v39;
        let v94: f32 = v56 * v33;
        let v95: f32 = v93 - v94;
        let v96: f32 = v83 * v39;
        let v97: f32 = v70 * v33;
        let v98: f32 = v96 - v97;
        let v99: f32 = v26 * v6;
        let v100: f32 = v22 * v3;
        let v101: f32 = v99 + v100;
        let v102: f32 = v101 * v29;
        let v103: f32 = v1 * v6;
        let v104: f32 = v5 * v3;
        let v105: f32 = v103 + v104;
        let v106: f32 = v105 * v10;
        let v107: f32 = v106 * v13;
        let v108: f32 = v102 - v107;
        let v109: f32 = v49 * v3;
        let v110: f32 = v109 - v99;
        let v111: f32 = v110 * v10;
        let v112: f32 = v105 * v29;
        let v113: f32 = v112 * v13;
        let v114: f32 = v111 - v113;
        let v115: f32 = v60 - v59;
        let v116: f32 = v115 * v6;
        let v117: f32 = v65 * v3;
        let v118: f32 = v116 - v117;
        let v119: f32 = 0.6718_f32;
        let v120: f32 = v81 * v6;
        let v121: f32 = v119 + v120;
        let v122: f32 = v77 * v3;
        let v123: f32 = v121 + v122;
        let v124: f32 = 0.0_f32;
        let v125: f32 = 1.0_f32;
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
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian: [[f32; 6]; 6]` (6 x 6, row-major): rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame
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
    pub fn jacobian(q: &[f32; 6]) -> [[f32; 6]; 6] {
        let v0: f32 = 0.15005_f32;
        let v1: f32 = q[0];
        let (v23, v2): (f32, f32) = ::libm::sincosf(v1);
        let v3: f32 = v0 * v2;
        let v4: f32 = 0.4318_f32;
        let v5: f32 = q[2];
        let (v9, v6): (f32, f32) = ::libm::sincosf(v5);
        let v7: f32 = v4 * v6;
        let v8: f32 = 0.0203_f32;
        let v10: f32 = v8 * v9;
        let v11: f32 = v7 + v10;
        let v12: f32 = q[1];
        let (v13, v20): (f32, f32) = ::libm::sincosf(v12);
        let v14: f32 = v11 * v13;
        let v15: f32 = -0.4318_f32;
        let v16: f32 = v8 * v6;
        let v17: f32 = v15 - v16;
        let v18: f32 = v4 * v9;
        let v19: f32 = v17 + v18;
        let v21: f32 = v19 * v20;
        let v22: f32 = v14 + v21;
        let v24: f32 = v22 * v23;
        let v25: f32 = v3 + v24;
        let v26: f32 = v19 * v13;
        let v27: f32 = v11 * v20;
        let v28: f32 = v26 - v27;
        let v29: f32 = v28 * v2;
        let v30: f32 = v18 - v16;
        let v31: f32 = v30 * v13;
        let v32: f32 = v31 - v27;
        let v33: f32 = v32 * v2;
        let v34: f32 = 0.0_f32;
        let v35: f32 = v0 * v23;
        let v36: f32 = v4 + v16;
        let v37: f32 = v36 - v18;
        let v38: f32 = v37 * v20;
        let v39: f32 = v38 - v14;
        let v40: f32 = v39 * v2;
        let v41: f32 = v35 + v40;
        let v42: f32 = v28 * v23;
        let v43: f32 = v32 * v23;
        let v44: f32 = v16 - v18;
        let v45: f32 = v44 * v20;
        let v46: f32 = v45 - v14;
        let v47: f32 = v9 * v20;
        let v48: f32 = v6 * v13;
        let v49: f32 = v47 + v48;
        let v50: f32 = v49 * v2;
        let v51: f32 = -v50;
        let v52: f32 = q[3];
        let (v58, v53): (f32, f32) = ::libm::sincosf(v52);
        let v54: f32 = v53 * v23;
        let v55: f32 = v6 * v20;
        let v56: f32 = v9 * v13;
        let v57: f32 = v55 - v56;
        let v59: f32 = v57 * v58;
        let v60: f32 = v59 * v2;
        let v61: f32 = v54 + v60;
        let v62: f32 = q[4];
        let (v63, v68): (f32, f32) = ::libm::sincosf(v62);
        let v64: f32 = v63 * v58;
        let v65: f32 = v64 * v23;
        let v66: f32 = v63 * v53;
        let v67: f32 = v66 * v9;
        let v69: f32 = v68 * v6;
        let v70: f32 = v67 - v69;
        let v71: f32 = v70 * v13;
        let v72: f32 = v66 * v6;
        let v73: f32 = v68 * v9;
        let v74: f32 = v72 + v73;
        let v75: f32 = v74 * v20;
        let v76: f32 = v71 - v75;
        let v77: f32 = v76 * v2;
        let v78: f32 = v65 + v77;
        let v79: f32 = -v2;
        let v80: f32 = v49 * v23;
        let v81: f32 = -v80;
        let v82: f32 = v59 * v23;
        let v83: f32 = v53 * v2;
        let v84: f32 = v82 - v83;
        let v85: f32 = v76 * v23;
        let v86: f32 = v64 * v2;
        let v87: f32 = v85 - v86;
        let v88: f32 = 1.0_f32;
        let v89: f32 = v49 * v58;
        let v90: f32 = v69 - v67;
        let v91: f32 = v90 * v20;
        let v92: f32 = v74 * v13;
        let v93: f32 = v91 - v92;
        [
            [v25, v29, v33, v34, v34, v34],
            [v41, v42, v43, v34, v34, v34],
            [v34, v39, v46, v34, v34, v34],
            [v34, v23, v23, v51, v61, v78],
            [v34, v79, v79, v81, v84, v87],
            [v88, v34, v34, v57, v89, v93],
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
    /// Operation count: 78 floating-point operations, 10 trig calls.
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
        let v0: f32 = 0.15005_f32;
        let v1: f32 = q[0];
        let (v23, v2): (f32, f32) = ::libm::sincosf(v1);
        let v3: f32 = v0 * v2;
        let v4: f32 = 0.4318_f32;
        let v5: f32 = q[2];
        let (v9, v6): (f32, f32) = ::libm::sincosf(v5);
        let v7: f32 = v4 * v6;
        let v8: f32 = 0.0203_f32;
        let v10: f32 = v8 * v9;
        let v11: f32 = v7 + v10;
        let v12: f32 = q[1];
        let (v13, v20): (f32, f32) = ::libm::sincosf(v12);
        let v14: f32 = v11 * v13;
        let v15: f32 = -0.4318_f32;
        let v16: f32 = v8 * v6;
        let v17: f32 = v15 - v16;
        let v18: f32 = v4 * v9;
        let v19: f32 = v17 + v18;
        let v21: f32 = v19 * v20;
        let v22: f32 = v14 + v21;
        let v24: f32 = v22 * v23;
        let v25: f32 = v3 + v24;
        let v26: f32 = v19 * v13;
        let v27: f32 = v11 * v20;
        let v28: f32 = v26 - v27;
        let v29: f32 = v28 * v2;
        let v30: f32 = v18 - v16;
        let v31: f32 = v30 * v13;
        let v32: f32 = v31 - v27;
        let v33: f32 = v32 * v2;
        let v34: f32 = 0.0_f32;
        let v35: f32 = v0 * v23;
        let v36: f32 = v4 + v16;
        let v37: f32 = v36 - v18;
        let v38: f32 = v37 * v20;
        let v39: f32 = v38 - v14;
        let v40: f32 = v39 * v2;
        let v41: f32 = v35 + v40;
        let v42: f32 = v28 * v23;
        let v43: f32 = v32 * v23;
        let v44: f32 = v39 * v23;
        let v45: f32 = v44 - v3;
        let v46: f32 = v16 - v18;
        let v47: f32 = v46 * v20;
        let v48: f32 = v47 - v14;
        let v49: f32 = 0.6718_f32;
        let v50: f32 = v49 + v27;
        let v51: f32 = v37 * v13;
        let v52: f32 = v50 + v51;
        let v53: f32 = v9 * v20;
        let v54: f32 = v6 * v13;
        let v55: f32 = v53 + v54;
        let v56: f32 = v55 * v2;
        let v57: f32 = -v56;
        let v58: f32 = q[3];
        let (v64, v59): (f32, f32) = ::libm::sincosf(v58);
        let v60: f32 = v59 * v23;
        let v61: f32 = v6 * v20;
        let v62: f32 = v9 * v13;
        let v63: f32 = v61 - v62;
        let v65: f32 = v63 * v64;
        let v66: f32 = v65 * v2;
        let v67: f32 = v60 + v66;
        let v68: f32 = q[4];
        let (v69, v74): (f32, f32) = ::libm::sincosf(v68);
        let v70: f32 = v69 * v64;
        let v71: f32 = v70 * v23;
        let v72: f32 = v69 * v59;
        let v73: f32 = v72 * v9;
        let v75: f32 = v74 * v6;
        let v76: f32 = v73 - v75;
        let v77: f32 = v76 * v13;
        let v78: f32 = v72 * v6;
        let v79: f32 = v74 * v9;
        let v80: f32 = v78 + v79;
        let v81: f32 = v80 * v20;
        let v82: f32 = v77 - v81;
        let v83: f32 = v82 * v2;
        let v84: f32 = v71 + v83;
        let v85: f32 = -v2;
        let v86: f32 = v55 * v23;
        let v87: f32 = -v86;
        let v88: f32 = v65 * v23;
        let v89: f32 = v59 * v2;
        let v90: f32 = v88 - v89;
        let v91: f32 = v82 * v23;
        let v92: f32 = v70 * v2;
        let v93: f32 = v91 - v92;
        let v94: f32 = 1.0_f32;
        let v95: f32 = v55 * v64;
        let v96: f32 = v75 - v73;
        let v97: f32 = v96 * v20;
        let v98: f32 = v80 * v13;
        let v99: f32 = v97 - v98;
        [
            [v25, v29, v33, v34, v34, v34, v41],
            [v41, v42, v43, v34, v34, v34, v45],
            [v34, v39, v48, v34, v34, v34, v52],
            [v34, v23, v23, v57, v67, v84, v34],
            [v34, v85, v85, v87, v90, v93, v34],
            [v94, v34, v34, v63, v95, v99, v34],
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
    pub fn jdot_qd(q: &[f32; 6], qd: &[f32; 6]) -> [f32; 6] {
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
            v116,
            v117,
            v121,
        ) = {
            let v0: f32 = 0.8636_f32;
            let v1: f32 = qd[2];
            let v2: f32 = v0 * v1;
            let v3: f32 = qd[1];
            let v4: f32 = v0 * v3;
            let v5: f32 = v2 + v4;
            let v6: f32 = q[2];
            let (v13, v7): (f32, f32) = ::libm::sincosf(v6);
            let v8: f32 = v5 * v7;
            let v9: f32 = 0.0406_f32;
            let v10: f32 = v9 * v1;
            let v11: f32 = v9 * v3;
            let v12: f32 = v10 + v11;
            let v14: f32 = v12 * v13;
            let v15: f32 = v8 + v14;
            let v16: f32 = q[1];
            let (v31, v17): (f32, f32) = ::libm::sincosf(v16);
            let v18: f32 = v15 * v17;
            let v19: f32 = 0.15005_f32;
            let v20: f32 = qd[0];
            let v21: f32 = v19 * v20;
            let v22: f32 = v18 - v21;
            let v23: f32 = v9 * v7;
            let v24: f32 = v0 * v13;
            let v25: f32 = v23 - v24;
            let v26: f32 = v25 * v1;
            let v27: f32 = v0 + v23;
            let v28: f32 = v27 - v24;
            let v29: f32 = v28 * v3;
            let v30: f32 = v26 + v29;
            let v32: f32 = v30 * v31;
            let v33: f32 = v22 + v32;
            let v34: f32 = v33 * v20;
            let v35: f32 = q[0];
            let (v36, v81): (f32, f32) = ::libm::sincosf(v35);
            let v37: f32 = v34 * v36;
            let v38: f32 = 0.4318_f32;
            let v39: f32 = v38 * v1;
            let v40: f32 = v39 * v1;
            let v41: f32 = v38 * v20;
            let v42: f32 = v41 * v20;
            let v43: f32 = v40 + v42;
            let v44: f32 = v38 * v3;
            let v45: f32 = v2 + v44;
            let v46: f32 = v45 * v3;
            let v47: f32 = v43 + v46;
            let v48: f32 = v47 * v7;
            let v49: f32 = 0.0203_f32;
            let v50: f32 = v49 * v1;
            let v51: f32 = v50 * v1;
            let v52: f32 = v49 * v20;
            let v53: f32 = v52 * v20;
            let v54: f32 = v51 + v53;
            let v55: f32 = v49 * v3;
            let v56: f32 = v10 + v55;
            let v57: f32 = v56 * v3;
            let v58: f32 = v54 + v57;
            let v59: f32 = v58 * v13;
            let v60: f32 = v48 + v59;
            let v61: f32 = v60 * v31;
            let v62: f32 = v38 * v13;
            let v63: f32 = v49 * v7;
            let v64: f32 = v62 - v63;
            let v65: f32 = v64 * v1;
            let v66: f32 = v65 * v1;
            let v67: f32 = -0.4318_f32;
            let v68: f32 = v67 - v63;
            let v69: f32 = v68 + v62;
            let v70: f32 = v69 * v20;
            let v71: f32 = v70 * v20;
            let v72: f32 = v66 + v71;
            let v73: f32 = v24 - v23;
            let v74: f32 = v73 * v1;
            let v75: f32 = v69 * v3;
            let v76: f32 = v74 + v75;
            let v77: f32 = v76 * v3;
            let v78: f32 = v72 + v77;
            let v79: f32 = v78 * v17;
            let v80: f32 = v61 + v79;
            let v82: f32 = v80 * v81;
            let v83: f32 = v37 + v82;
            let v84: f32 = v21 - v18;
            let v85: f32 = -0.8636_f32;
            let v86: f32 = v85 - v23;
            let v87: f32 = v86 + v24;
            let v88: f32 = v87 * v3;
            let v89: f32 = v74 + v88;
            let v90: f32 = v89 * v31;
            let v91: f32 = v84 + v90;
            let v92: f32 = v91 * v20;
            let v93: f32 = v92 * v81;
            let v94: f32 = v80 * v36;
            let v95: f32 = v93 + v94;
            let v96: f32 = v64 * v31;
            let v97: f32 = v38 * v7;
            let v98: f32 = v49 * v13;
            let v99: f32 = v97 + v98;
            let v100: f32 = v99 * v17;
            let v101: f32 = v96 - v100;
            let v102: f32 = v101 * v1;
            let v103: f32 = v102 * v1;
            let v104: f32 = v76 * v31;
            let v105: f32 = v45 * v7;
            let v106: f32 = v56 * v13;
            let v107: f32 = v105 + v106;
            let v108: f32 = v107 * v17;
            let v109: f32 = v104 - v108;
            let v110: f32 = v109 * v3;
            let v111: f32 = v103 + v110;
            let v112: f32 = qd[5];
            let v113: f32 = qd[3];
            let v114: f32 = v112 * v113;
            let v115: f32 = q[4];
            let (v116, v121): (f32, f32) = ::libm::sincosf(v115);
            let v117: f32 = v114 * v116;
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
                v116,
                v117,
                v121,
            )
        };
        let (v196, v212, v235) = {
            let v118: f32 = q[3];
            let (v126, v119): (f32, f32) = ::libm::sincosf(v118);
            let v120: f32 = v117 * v119;
            let v122: f32 = v112 * v121;
            let v123: f32 = v122 - v113;
            let v124: f32 = qd[4];
            let v125: f32 = v123 * v124;
            let v127: f32 = v125 * v126;
            let v128: f32 = v120 + v127;
            let v129: f32 = v112 * v116;
            let v130: f32 = v129 * v119;
            let v131: f32 = v124 * v126;
            let v132: f32 = v130 - v131;
            let v133: f32 = v132 * v7;
            let v134: f32 = v113 + v122;
            let v135: f32 = v134 * v13;
            let v136: f32 = v133 + v135;
            let v137: f32 = v136 * v17;
            let v138: f32 = v134 * v7;
            let v139: f32 = v131 - v130;
            let v140: f32 = v139 * v13;
            let v141: f32 = v138 + v140;
            let v142: f32 = v141 * v31;
            let v143: f32 = v137 + v142;
            let v144: f32 = v143 * v20;
            let v145: f32 = v128 + v144;
            let v146: f32 = v145 * v36;
            let v147: f32 = v1 + v3;
            let v148: f32 = v147 * v20;
            let v149: f32 = v147 * v13;
            let v150: f32 = v149 * v31;
            let v151: f32 = v147 * v7;
            let v152: f32 = v151 * v17;
            let v153: f32 = v150 - v152;
            let v154: f32 = v153 * v113;
            let v155: f32 = v148 + v154;
            let v156: f32 = v7 * v17;
            let v157: f32 = v13 * v31;
            let v158: f32 = v156 - v157;
            let v159: f32 = v158 * v113;
            let v160: f32 = v20 + v159;
            let v161: f32 = v160 * v119;
            let v162: f32 = v149 * v17;
            let v163: f32 = v151 * v31;
            let v164: f32 = v162 + v163;
            let v165: f32 = v164 * v126;
            let v166: f32 = v161 - v165;
            let v167: f32 = v166 * v124;
            let v168: f32 = v155 + v167;
            let v169: f32 = v124 * v119;
            let v170: f32 = v147 + v169;
            let v171: f32 = v170 * v13;
            let v172: f32 = v171 * v31;
            let v173: f32 = v170 * v7;
            let v174: f32 = v173 * v17;
            let v175: f32 = v172 - v174;
            let v176: f32 = v175 * v121;
            let v177: f32 = v20 * v126;
            let v178: f32 = v113 * v126;
            let v179: f32 = v178 * v7;
            let v180: f32 = v147 * v119;
            let v181: f32 = v124 + v180;
            let v182: f32 = v181 * v13;
            let v183: f32 = v179 + v182;
            let v184: f32 = v183 * v17;
            let v185: f32 = v177 + v184;
            let v186: f32 = v181 * v7;
            let v187: f32 = v178 * v13;
            let v188: f32 = v186 - v187;
            let v189: f32 = v188 * v31;
            let v190: f32 = v185 + v189;
            let v191: f32 = v190 * v116;
            let v192: f32 = v176 + v191;
            let v193: f32 = v192 * v112;
            let v194: f32 = v168 + v193;
            let v195: f32 = v194 * v81;
            let v196: f32 = v146 + v195;
            let v197: f32 = v113 - v122;
            let v198: f32 = v197 * v124;
            let v199: f32 = v198 * v126;
            let v200: f32 = v199 - v120;
            let v201: f32 = v139 * v7;
            let v202: f32 = v201 - v135;
            let v203: f32 = v202 * v17;
            let v204: f32 = v132 * v13;
            let v205: f32 = v204 - v138;
            let v206: f32 = v205 * v31;
            let v207: f32 = v203 + v206;
            let v208: f32 = v207 * v20;
            let v209: f32 = v200 + v208;
            let v210: f32 = v209 * v81;
            let v211: f32 = v194 * v36;
            let v212: f32 = v210 + v211;
            let v213: f32 = v152 - v150;
            let v214: f32 = v213 * v124;
            let v215: f32 = v214 * v126;
            let v216: f32 = v169 - v147;
            let v217: f32 = v216 * v13;
            let v218: f32 = v217 * v17;
            let v219: f32 = v216 * v7;
            let v220: f32 = v219 * v31;
            let v221: f32 = v218 + v220;
            let v222: f32 = v221 * v113;
            let v223: f32 = v215 + v222;
            let v224: f32 = v187 - v186;
            let v225: f32 = v224 * v17;
            let v226: f32 = v183 * v31;
            let v227: f32 = v225 + v226;
            let v228: f32 = v227 * v116;
            let v229: f32 = v171 * v17;
            let v230: f32 = v173 * v31;
            let v231: f32 = v229 + v230;
            let v232: f32 = v231 * v121;
            let v233: f32 = v228 - v232;
            let v234: f32 = v233 * v112;
            let v235: f32 = v223 + v234;
            (v196, v212, v235)
        };
        [v83, v95, v111, v196, v212, v235]
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
    pub fn mass_matrix(q: &[f32; 6]) -> [[f32; 6]; 6] {
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
            let v0: f32 = 1.5535233_f32;
            let v1: f32 = 0.00020216_f32;
            let v2: f32 = q[4];
            let (v15, v3): (f32, f32) = ::libm::sincosf(v2);
            let v4: f32 = v1 * v3;
            let v5: f32 = v4 * v3;
            let v6: f32 = v0 - v5;
            let v7: f32 = 0.000864288_f32;
            let v8: f32 = q[3];
            let (v9, v12): (f32, f32) = ::libm::sincosf(v8);
            let v10: f32 = v7 * v9;
            let v11: f32 = 0.000116928_f32;
            let v13: f32 = v11 * v12;
            let v14: f32 = v10 - v13;
            let v16: f32 = v14 * v15;
            let v17: f32 = v6 + v16;
            let v18: f32 = 0.022546398_f32;
            let v19: f32 = v11 * v3;
            let v20: f32 = v18 + v19;
            let v21: f32 = -0.002487168_f32;
            let v22: f32 = 0.00040432_f32;
            let v23: f32 = v22 * v3;
            let v24: f32 = v21 - v23;
            let v25: f32 = v24 * v15;
            let v26: f32 = v25 * v12;
            let v27: f32 = v20 + v26;
            let v28: f32 = q[2];
            let (v29, v43): (f32, f32) = ::libm::sincosf(v28);
            let v30: f32 = v27 * v29;
            let v31: f32 = 0.32391983_f32;
            let v32: f32 = 0.002487168_f32;
            let v33: f32 = v32 + v4;
            let v34: f32 = v33 * v3;
            let v35: f32 = v31 + v34;
            let v36: f32 = v11 * v15;
            let v37: f32 = -0.00030216_f32;
            let v38: f32 = v37 + v5;
            let v39: f32 = v38 * v12;
            let v40: f32 = v36 + v39;
            let v41: f32 = v40 * v12;
            let v42: f32 = v35 + v41;
            let v44: f32 = v42 * v43;
            let v45: f32 = v30 + v44;
            let v46: f32 = v45 * v43;
            let v47: f32 = v17 + v46;
            let v48: f32 = 0.008347998_f32;
            let v49: f32 = v48 + v19;
            let v50: f32 = 0.02191385_f32;
            let v51: f32 = v50 * v29;
            let v52: f32 = v49 - v51;
            let v53: f32 = v32 * v29;
            let v54: f32 = v24 + v53;
            let v55: f32 = v54 * v15;
            let v56: f32 = v55 * v12;
            let v57: f32 = v52 + v56;
            let v58: f32 = q[1];
            let (v59, v78): (f32, f32) = ::libm::sincosf(v58);
            let v60: f32 = v57 * v59;
            let v61: f32 = 1.925781_f32;
            let v62: f32 = 0.76975256_f32;
            let v63: f32 = v62 * v29;
            let v64: f32 = v61 - v63;
            let v65: f32 = 0.00030216_f32;
            let v66: f32 = v65 * v12;
            let v67: f32 = v36 - v66;
            let v68: f32 = v67 * v12;
            let v69: f32 = v64 + v68;
            let v70: f32 = v32 - v53;
            let v71: f32 = v1 * v12;
            let v72: f32 = v71 * v12;
            let v73: f32 = v1 + v72;
            let v74: f32 = v73 * v3;
            let v75: f32 = v70 + v74;
            let v76: f32 = v75 * v3;
            let v77: f32 = v69 + v76;
            let v79: f32 = v77 * v78;
            let v80: f32 = v60 + v79;
            let v81: f32 = v32 * v15;
            let v82: f32 = v81 * v12;
            let v83: f32 = v50 - v82;
            let v84: f32 = -0.045092795_f32;
            let v85: f32 = 0.000233856_f32;
            let v86: f32 = v85 * v3;
            let v87: f32 = v84 - v86;
            let v88: f32 = 0.004974336_f32;
            let v89: f32 = 0.00080864_f32;
            let v90: f32 = v89 * v3;
            let v91: f32 = v88 + v90;
            let v92: f32 = v91 * v15;
            let v93: f32 = v92 * v12;
            let v94: f32 = v87 + v93;
            let v95: f32 = v94 * v29;
            let v96: f32 = v83 + v95;
            let v97: f32 = -0.64783967_f32;
            let v98: f32 = -0.004974336_f32;
            let v99: f32 = v98 - v23;
            let v100: f32 = v99 * v3;
            let v101: f32 = v97 + v100;
            let v102: f32 = 0.00060432_f32;
            let v103: f32 = v23 * v3;
            let v104: f32 = v102 - v103;
            let v105: f32 = v104 * v12;
            let v106: f32 = v85 * v15;
            let v107: f32 = v105 - v106;
            let v108: f32 = v107 * v12;
            let v109: f32 = v101 + v108;
            let v110: f32 = v109 * v43;
            let v111: f32 = v96 + v110;
            let v112: f32 = v111 * v78;
            let v113: f32 = -0.76975256_f32;
            let v114: f32 = v32 * v3;
            let v115: f32 = v113 - v114;
            let v116: f32 = v94 * v43;
            let v117: f32 = v115 + v116;
            let v118: f32 = 0.64783967_f32;
            let v119: f32 = v88 + v23;
            let v120: f32 = v119 * v3;
            let v121: f32 = v118 + v120;
            let v122: f32 = -0.00060432_f32;
            let v123: f32 = v122 + v103;
            let v124: f32 = v123 * v12;
            let v125: f32 = v106 + v124;
            let v126: f32 = v125 * v12;
            let v127: f32 = v121 + v126;
            let v128: f32 = v127 * v29;
            let v129: f32 = v117 + v128;
            let v130: f32 = v129 * v59;
            let v131: f32 = v112 + v130;
            let v132: f32 = v131 * v43;
            let v133: f32 = v80 + v132;
            let v134: f32 = v133 * v78;
            let v135: f32 = v47 + v134;
            let v136: f32 = -0.023751_f32;
            let v137: f32 = -0.13848166_f32;
            let v138: f32 = 0.000432144_f32;
            let v139: f32 = v138 * v3;
            let v140: f32 = v137 - v139;
            let v141: f32 = -0.001243584_f32;
            let v142: f32 = v141 - v4;
            let v143: f32 = v142 * v15;
            let v144: f32 = v143 * v9;
            let v145: f32 = v140 + v144;
            let v146: f32 = v145 * v43;
            let v147: f32 = v136 + v146;
            let v148: f32 = -0.0038075189_f32;
            let v149: f32 = v138 * v15;
            let v150: f32 = v149 * v12;
            let v151: f32 = v148 + v150;
            let v152: f32 = v65 - v5;
            let v153: f32 = v152 * v12;
            let v154: f32 = 5.8464e-5_f32;
            let v155: f32 = v154 * v15;
            let v156: f32 = v153 - v155;
            let v157: f32 = v156 * v9;
            let v158: f32 = v151 + v157;
            let v159: f32 = v158 * v29;
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
            let v160: f32 = v147 + v159;
            let v161: f32 = v160 * v78;
            let v162: f32 = -0.69039136_f32;
            let v163: f32 = v151 * v43;
            let v164: f32 = v162 + v163;
            let v165: f32 = 0.13848166_f32;
            let v166: f32 = v165 + v139;
            let v167: f32 = v166 * v29;
            let v168: f32 = v164 + v167;
            let v169: f32 = v153 * v43;
            let v170: f32 = v154 * v43;
            let v171: f32 = v141 - v170;
            let v172: f32 = 0.001243584_f32;
            let v173: f32 = v172 + v4;
            let v174: f32 = v173 * v29;
            let v175: f32 = v171 + v174;
            let v176: f32 = v175 * v15;
            let v177: f32 = v169 + v176;
            let v178: f32 = v177 * v9;
            let v179: f32 = v168 + v178;
            let v180: f32 = v179 * v59;
            let v181: f32 = v161 + v180;
            let v182: f32 = v140 * v43;
            let v183: f32 = v151 * v29;
            let v184: f32 = v182 + v183;
            let v185: f32 = v184 * v78;
            let v186: f32 = v163 + v167;
            let v187: f32 = v186 * v59;
            let v188: f32 = v185 + v187;
            let v189: f32 = v152 * v29;
            let v190: f32 = v189 * v78;
            let v191: f32 = v152 * v43;
            let v192: f32 = v191 * v59;
            let v193: f32 = v190 + v192;
            let v194: f32 = v193 * v12;
            let v195: f32 = v142 * v43;
            let v196: f32 = v154 * v29;
            let v197: f32 = v195 - v196;
            let v198: f32 = v197 * v78;
            let v199: f32 = v174 - v170;
            let v200: f32 = v199 * v59;
            let v201: f32 = v198 + v200;
            let v202: f32 = v201 * v15;
            let v203: f32 = v194 + v202;
            let v204: f32 = v203 * v9;
            let v205: f32 = v188 + v204;
            let v206: f32 = 0.00184216_f32;
            let v207: f32 = v206 - v5;
            let v208: f32 = v207 * v43;
            let v209: f32 = v208 * v78;
            let v210: f32 = -0.00184216_f32;
            let v211: f32 = v210 + v5;
            let v212: f32 = v211 * v29;
            let v213: f32 = v212 * v59;
            let v214: f32 = v209 + v213;
            let v215: f32 = v138 * v43;
            let v216: f32 = v215 * v78;
            let v217: f32 = v138 * v29;
            let v218: f32 = v217 * v59;
            let v219: f32 = v216 - v218;
            let v220: f32 = v219 * v9;
            let v221: f32 = v173 * v43;
            let v222: f32 = v196 + v221;
            let v223: f32 = v222 * v59;
            let v224: f32 = v175 * v78;
            let v225: f32 = v223 + v224;
            let v226: f32 = v225 * v12;
            let v227: f32 = v220 + v226;
            let v228: f32 = v227 * v15;
            let v229: f32 = v214 + v228;
            let v230: f32 = v149 * v29;
            let v231: f32 = v139 * v12;
            let v232: f32 = v231 * v43;
            let v233: f32 = v230 - v232;
            let v234: f32 = v233 * v78;
            let v235: f32 = v149 * v43;
            let v236: f32 = v231 * v29;
            let v237: f32 = v235 + v236;
            let v238: f32 = v237 * v59;
            let v239: f32 = v234 + v238;
            let v240: f32 = 0.00064216_f32;
            let v241: f32 = v240 * v29;
            let v242: f32 = v241 * v78;
            let v243: f32 = v240 * v43;
            let v244: f32 = v243 * v59;
            let v245: f32 = v242 + v244;
            let v246: f32 = v172 * v43;
            let v247: f32 = v246 + v196;
            let v248: f32 = v247 * v59;
            let v249: f32 = v172 * v29;
            let v250: f32 = v171 + v249;
            let v251: f32 = v250 * v78;
            let v252: f32 = v248 + v251;
            let v253: f32 = v252 * v3;
            let v254: f32 = v245 + v253;
            let v255: f32 = v254 * v9;
            let v256: f32 = v239 + v255;
            let v257: f32 = 4e-5_f32;
            let v258: f32 = v257 * v3;
            let v259: f32 = v258 * v43;
            let v260: f32 = v257 * v15;
            let v261: f32 = v260 * v12;
            let v262: f32 = v261 * v29;
            let v263: f32 = v259 - v262;
            let v264: f32 = v263 * v78;
            let v265: f32 = v261 * v43;
            let v266: f32 = v258 * v29;
            let v267: f32 = v265 + v266;
            let v268: f32 = v267 * v59;
            let v269: f32 = v264 - v268;
            let v270: f32 = 2.107104_f32;
            let v271: f32 = v50 * v43;
            let v272: f32 = v270 + v271;
            let v273: f32 = v272 - v63;
            let v274: f32 = v33 - v53;
            let v275: f32 = v274 * v3;
            let v276: f32 = v273 + v275;
            let v277: f32 = -0.000116928_f32;
            let v278: f32 = v32 * v43;
            let v279: f32 = v277 - v278;
            let v280: f32 = v279 * v15;
            let v281: f32 = v280 + v153;
            let v282: f32 = v281 * v12;
            let v283: f32 = v276 + v282;
            let v284: f32 = 0.35899007_f32;
            let v285: f32 = 0.010956925_f32;
            let v286: f32 = v285 * v43;
            let v287: f32 = v284 + v286;
            let v288: f32 = 0.38487628_f32;
            let v289: f32 = v288 * v29;
            let v290: f32 = v287 - v289;
            let v291: f32 = v33 - v249;
            let v292: f32 = v291 * v3;
            let v293: f32 = v290 + v292;
            let v294: f32 = v277 - v246;
            let v295: f32 = v294 * v15;
            let v296: f32 = v295 + v153;
            let v297: f32 = v296 * v12;
            let v298: f32 = v293 + v297;
            let v299: f32 = v142 + v249;
            let v300: f32 = v299 * v15;
            let v301: f32 = v300 * v9;
            let v302: f32 = -5.8464e-5_f32;
            let v303: f32 = v302 - v246;
            let v304: f32 = v303 * v15;
            let v305: f32 = v172 - v249;
            let v306: f32 = v305 * v3;
            let v307: f32 = v240 + v306;
            let v308: f32 = v307 * v12;
            let v309: f32 = v304 + v308;
            let v310: f32 = v260 * v9;
            let v311: f32 = v284 + v34;
            let v312: f32 = v153 - v36;
            let v313: f32 = v312 * v12;
            let v314: f32 = v311 + v313;
            let v315: f32 = v172 * v3;
            let v316: f32 = v240 + v315;
            let v317: f32 = v316 * v12;
            let v318: f32 = v317 - v155;
            let v319: f32 = 0.0_f32;
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
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 6]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis_matrix: [[f32; 6]; 6]` (6 x 6, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
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
    pub fn coriolis_matrix(q: &[f32; 6], qd: &[f32; 6]) -> [[f32; 6]; 6] {
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
            v212,
        ) = {
            let v0: f32 = -0.004173999_f32;
            let v1: f32 = 0.010956925_f32;
            let v2: f32 = q[2];
            let (v3, v96): (f32, f32) = ::libm::sincosf(v2);
            let v4: f32 = v1 * v3;
            let v5: f32 = v0 + v4;
            let v6: f32 = qd[1];
            let v7: f32 = v5 * v6;
            let v8: f32 = 0.011273199_f32;
            let v9: f32 = qd[2];
            let v10: f32 = v8 * v9;
            let v11: f32 = v7 - v10;
            let v12: f32 = 0.000432144_f32;
            let v13: f32 = q[3];
            let (v14, v17): (f32, f32) = ::libm::sincosf(v13);
            let v15: f32 = v12 * v14;
            let v16: f32 = 5.8464e-5_f32;
            let v18: f32 = v16 * v17;
            let v19: f32 = v15 - v18;
            let v20: f32 = qd[4];
            let v21: f32 = v19 * v20;
            let v22: f32 = v16 * v9;
            let v23: f32 = v16 * v6;
            let v24: f32 = v22 + v23;
            let v25: f32 = v21 - v24;
            let v26: f32 = q[4];
            let (v49, v27): (f32, f32) = ::libm::sincosf(v26);
            let v28: f32 = v25 * v27;
            let v29: f32 = v11 + v28;
            let v30: f32 = 0.00020216_f32;
            let v31: f32 = v30 * v20;
            let v32: f32 = v31 * v27;
            let v33: f32 = qd[3];
            let v34: f32 = v16 * v33;
            let v35: f32 = v34 * v14;
            let v36: f32 = v32 + v35;
            let v37: f32 = v12 * v33;
            let v38: f32 = 0.001243584_f32;
            let v39: f32 = v30 * v27;
            let v40: f32 = v38 + v39;
            let v41: f32 = v40 * v9;
            let v42: f32 = v37 + v41;
            let v43: f32 = v38 * v3;
            let v44: f32 = v40 - v43;
            let v45: f32 = v44 * v6;
            let v46: f32 = v42 + v45;
            let v47: f32 = v46 * v17;
            let v48: f32 = v36 + v47;
            let v50: f32 = v48 * v49;
            let v51: f32 = v29 + v50;
            let v52: f32 = 0.38487628_f32;
            let v53: f32 = v38 * v27;
            let v54: f32 = v52 + v53;
            let v55: f32 = v54 * v6;
            let v56: f32 = 0.022546398_f32;
            let v57: f32 = v56 * v9;
            let v58: f32 = v56 * v6;
            let v59: f32 = v57 + v58;
            let v60: f32 = 0.000116928_f32;
            let v61: f32 = v60 * v9;
            let v62: f32 = v60 * v6;
            let v63: f32 = v61 + v62;
            let v64: f32 = v63 * v27;
            let v65: f32 = v59 + v64;
            let v66: f32 = -0.001243584_f32;
            let v67: f32 = v66 - v39;
            let v68: f32 = v67 * v20;
            let v69: f32 = v68 - v35;
            let v70: f32 = v69 * v49;
            let v71: f32 = v65 + v70;
            let v72: f32 = v16 * v20;
            let v73: f32 = v72 * v27;
            let v74: f32 = 0.00030216_f32;
            let v75: f32 = v39 * v27;
            let v76: f32 = v74 - v75;
            let v77: f32 = v76 * v33;
            let v78: f32 = v77 * v14;
            let v79: f32 = v73 + v78;
            let v80: f32 = 0.002487168_f32;
            let v81: f32 = v80 * v9;
            let v82: f32 = v80 * v6;
            let v83: f32 = v81 + v82;
            let v84: f32 = 0.00040432_f32;
            let v85: f32 = v84 * v9;
            let v86: f32 = v84 * v6;
            let v87: f32 = v85 + v86;
            let v88: f32 = v31 * v17;
            let v89: f32 = v87 + v88;
            let v90: f32 = v89 * v27;
            let v91: f32 = v83 + v90;
            let v92: f32 = v91 * v49;
            let v93: f32 = v79 - v92;
            let v94: f32 = v93 * v17;
            let v95: f32 = v71 + v94;
            let v97: f32 = v95 * v96;
            let v98: f32 = v55 + v97;
            let v99: f32 = v38 * v33;
            let v100: f32 = v99 * v14;
            let v101: f32 = v100 - v72;
            let v102: f32 = v101 * v49;
            let v103: f32 = 0.32391983_f32;
            let v104: f32 = v103 * v9;
            let v105: f32 = v103 * v6;
            let v106: f32 = v104 + v105;
            let v107: f32 = v102 - v106;
            let v108: f32 = v30 * v33;
            let v109: f32 = v108 * v49;
            let v110: f32 = v109 * v14;
            let v111: f32 = v110 - v83;
            let v112: f32 = v30 * v9;
            let v113: f32 = v30 * v6;
            let v114: f32 = v112 + v113;
            let v115: f32 = v114 * v27;
            let v116: f32 = v111 - v115;
            let v117: f32 = v116 * v27;
            let v118: f32 = v107 + v117;
            let v119: f32 = v84 * v27;
            let v120: f32 = v66 - v119;
            let v121: f32 = v120 * v27;
            let v122: f32 = v30 + v121;
            let v123: f32 = v122 * v20;
            let v124: f32 = v63 * v49;
            let v125: f32 = v123 - v124;
            let v126: f32 = v74 * v9;
            let v127: f32 = v74 * v6;
            let v128: f32 = v126 + v127;
            let v129: f32 = v115 * v27;
            let v130: f32 = v128 - v129;
            let v131: f32 = v130 * v17;
            let v132: f32 = v125 + v131;
            let v133: f32 = v132 * v17;
            let v134: f32 = v118 + v133;
            let v135: f32 = v134 * v3;
            let v136: f32 = v98 + v135;
            let v137: f32 = v136 * v96;
            let v138: f32 = v51 + v137;
            let v139: f32 = 0.008347998_f32;
            let v140: f32 = v139 * v6;
            let v141: f32 = v57 + v140;
            let v142: f32 = v74 * v33;
            let v143: f32 = v142 * v17;
            let v144: f32 = v143 * v14;
            let v145: f32 = v141 + v144;
            let v146: f32 = v1 * v9;
            let v147: f32 = 0.02191385_f32;
            let v148: f32 = v147 * v6;
            let v149: f32 = v146 + v148;
            let v150: f32 = v149 * v3;
            let v151: f32 = v145 - v150;
            let v152: f32 = v108 * v27;
            let v153: f32 = v152 * v14;
            let v154: f32 = v72 - v153;
            let v155: f32 = v154 * v17;
            let v156: f32 = v63 + v155;
            let v157: f32 = v156 * v27;
            let v158: f32 = v151 + v157;
            let v159: f32 = v67 + v43;
            let v160: f32 = v159 * v20;
            let v161: f32 = v160 - v35;
            let v162: f32 = v38 * v9;
            let v163: f32 = v162 + v82;
            let v164: f32 = v163 * v3;
            let v165: f32 = v164 - v83;
            let v166: f32 = v165 - v90;
            let v167: f32 = v166 * v17;
            let v168: f32 = v161 + v167;
            let v169: f32 = v168 * v49;
            let v170: f32 = v158 + v169;
            let v171: f32 = q[1];
            let (v212, v172): (f32, f32) = ::libm::sincosf(v171);
            let v173: f32 = v170 * v172;
            let v174: f32 = 1.925781_f32;
            let v175: f32 = v174 * v6;
            let v176: f32 = v104 + v175;
            let v177: f32 = v102 - v176;
            let v178: f32 = v52 * v9;
            let v179: f32 = 0.76975256_f32;
            let v180: f32 = v179 * v6;
            let v181: f32 = v178 + v180;
            let v182: f32 = v99 * v49;
            let v183: f32 = v182 * v14;
            let v184: f32 = v181 - v183;
            let v185: f32 = v184 * v3;
            let v186: f32 = v177 + v185;
            let v187: f32 = v31 - v124;
            let v188: f32 = v128 * v17;
            let v189: f32 = v187 + v188;
            let v190: f32 = v189 * v17;
            let v191: f32 = v186 + v190;
            let v192: f32 = -0.002487168_f32;
            let v193: f32 = v192 - v39;
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
                v212,
            )
        };
        let (
            v197,
            v201,
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
            let v194: f32 = v193 + v43;
            let v195: f32 = v194 * v9;
            let v196: f32 = v110 + v195;
            let v197: f32 = v80 * v3;
            let v198: f32 = v193 + v197;
            let v199: f32 = v198 * v6;
            let v200: f32 = v196 + v199;
            let v201: f32 = v66 + v43;
            let v202: f32 = v201 * v20;
            let v203: f32 = v84 * v20;
            let v204: f32 = v114 * v17;
            let v205: f32 = v203 + v204;
            let v206: f32 = v205 * v27;
            let v207: f32 = v202 - v206;
            let v208: f32 = v207 * v17;
            let v209: f32 = v200 + v208;
            let v210: f32 = v209 * v27;
            let v211: f32 = v191 + v210;
            let v213: f32 = v211 * v212;
            let v214: f32 = v173 + v213;
            let v215: f32 = v38 * v20;
            let v216: f32 = v215 * v49;
            let v217: f32 = v216 - v149;
            let v218: f32 = 0.045092795_f32;
            let v219: f32 = v218 * v9;
            let v220: f32 = v218 * v6;
            let v221: f32 = v219 + v220;
            let v222: f32 = 0.000233856_f32;
            let v223: f32 = v222 * v9;
            let v224: f32 = v222 * v6;
            let v225: f32 = v223 + v224;
            let v226: f32 = v225 * v27;
            let v227: f32 = v221 + v226;
            let v228: f32 = v192 - v119;
            let v229: f32 = v228 * v20;
            let v230: f32 = v60 * v33;
            let v231: f32 = v230 * v14;
            let v232: f32 = v229 - v231;
            let v233: f32 = v232 * v49;
            let v234: f32 = v227 + v233;
            let v235: f32 = v234 * v3;
            let v236: f32 = v217 + v235;
            let v237: f32 = 0.64783967_f32;
            let v238: f32 = v237 * v9;
            let v239: f32 = v237 * v6;
            let v240: f32 = v238 + v239;
            let v241: f32 = v60 * v20;
            let v242: f32 = v80 * v33;
            let v243: f32 = v242 * v14;
            let v244: f32 = v241 - v243;
            let v245: f32 = v244 * v49;
            let v246: f32 = v240 + v245;
            let v247: f32 = 0.004974336_f32;
            let v248: f32 = v247 * v9;
            let v249: f32 = v247 * v6;
            let v250: f32 = v248 + v249;
            let v251: f32 = v84 * v33;
            let v252: f32 = v251 * v49;
            let v253: f32 = v252 * v14;
            let v254: f32 = v250 - v253;
            let v255: f32 = v87 * v27;
            let v256: f32 = v254 + v255;
            let v257: f32 = v256 * v27;
            let v258: f32 = v246 + v257;
            let v259: f32 = v258 * v96;
            let v260: f32 = v236 + v259;
            let v261: f32 = v163 * v49;
            let v262: f32 = v241 * v27;
            let v263: f32 = 0.00060432_f32;
            let v264: f32 = v119 * v27;
            let v265: f32 = v263 - v264;
            let v266: f32 = v265 * v33;
            let v267: f32 = v266 * v14;
            let v268: f32 = v262 + v267;
            let v269: f32 = 0.00080864_f32;
            let v270: f32 = v269 * v9;
            let v271: f32 = v269 * v6;
            let v272: f32 = v270 + v271;
            let v273: f32 = v203 * v17;
            let v274: f32 = v272 + v273;
            let v275: f32 = v274 * v27;
            let v276: f32 = v250 + v275;
            let v277: f32 = v276 * v49;
            let v278: f32 = v268 - v277;
            let v279: f32 = v278 * v3;
            let v280: f32 = v261 + v279;
            let v281: f32 = v225 * v49;
            let v282: f32 = -0.00040432_f32;
            let v283: f32 = v269 * v27;
            let v284: f32 = v80 + v283;
            let v285: f32 = v284 * v27;
            let v286: f32 = v282 + v285;
            let v287: f32 = v286 * v20;
            let v288: f32 = v281 + v287;
            let v289: f32 = v255 * v27;
            let v290: f32 = v263 * v9;
            let v291: f32 = v263 * v6;
            let v292: f32 = v290 + v291;
            let v293: f32 = v289 - v292;
            let v294: f32 = v293 * v17;
            let v295: f32 = v288 + v294;
            let v296: f32 = v295 * v96;
            let v297: f32 = v280 + v296;
            let v298: f32 = v297 * v17;
            let v299: f32 = v260 + v298;
            let v300: f32 = v299 * v212;
            let v301: f32 = v183 - v181;
            let v302: f32 = v80 * v20;
            let v303: f32 = v302 + v231;
            let v304: f32 = v250 * v17;
            let v305: f32 = v303 + v304;
            let v306: f32 = v305 * v49;
            let v307: f32 = v263 * v33;
            let v308: f32 = v307 * v17;
            let v309: f32 = v308 * v14;
            let v310: f32 = v221 + v309;
            let v311: f32 = v306 - v310;
            let v312: f32 = v311 * v96;
            let v313: f32 = v301 + v312;
            let v314: f32 = v281 - v203;
            let v315: f32 = v292 * v17;
            let v316: f32 = v314 - v315;
            let v317: f32 = v316 * v17;
            let v318: f32 = v246 + v317;
            let v319: f32 = v318 * v3;
            let v320: f32 = v313 + v319;
            let v321: f32 = v203 * v49;
            let v322: f32 = v321 - v225;
            let v323: f32 = v322 * v96;
            let v324: f32 = v323 - v163;
            let v325: f32 = v256 * v3;
            let v326: f32 = v324 + v325;
            let v327: f32 = v269 * v20;
            let v328: f32 = v87 * v17;
            let v329: f32 = v327 + v328;
            let v330: f32 = v329 * v27;
            let v331: f32 = v302 + v330;
            let v332: f32 = v331 * v3;
            let v333: f32 = v332 - v215;
            let v334: f32 = v251 * v27;
            let v335: f32 = v334 * v14;
            let v336: f32 = v335 - v241;
            let v337: f32 = v274 * v49;
            let v338: f32 = v336 + v337;
            let v339: f32 = v338 * v96;
            let v340: f32 = v333 + v339;
            let v341: f32 = v340 * v17;
            let v342: f32 = v326 + v341;
            let v343: f32 = v342 * v27;
            let v344: f32 = v320 + v343;
            let v345: f32 = v344 * v172;
            let v346: f32 = v300 + v345;
            let v347: f32 = v346 * v96;
            let v348: f32 = v214 + v347;
            let v349: f32 = v348 * v172;
            let v350: f32 = v138 + v349;
            let v351: f32 = v16 * v27;
            let v352: f32 = v0 - v351;
            let v353: f32 = v352 + v4;
            let v354: f32 = v44 * v49;
            let v355: f32 = v354 * v17;
            let v356: f32 = v353 + v355;
            let v357: f32 = v60 * v27;
            let v358: f32 = v56 + v357;
            let v359: f32 = v228 * v49;
            let v360: f32 = v359 * v17;
            let v361: f32 = v358 + v360;
            let v362: f32 = v361 * v96;
            let v363: f32 = v54 + v362;
            let v364: f32 = -0.32391983_f32;
            let v365: f32 = v193 * v27;
            let v366: f32 = v364 + v365;
            let v367: f32 = v76 * v17;
            let v368: f32 = v60 * v49;
            let v369: f32 = v367 - v368;
            let v370: f32 = v369 * v17;
            let v371: f32 = v366 + v370;
            let v372: f32 = v371 * v3;
            let v373: f32 = v363 + v372;
            let v374: f32 = v373 * v96;
            let v375: f32 = v356 + v374;
            let v376: f32 = qd[0];
            let v377: f32 = v375 * v376;
            let v378: f32 = 0.023751_f32;
            let v379: f32 = v378 * v6;
            let v380: f32 = 0.0038075189_f32;
            let v381: f32 = v380 * v9;
            let v382: f32 = v380 * v6;
            let v383: f32 = v381 + v382;
            let v384: f32 = 2e-5_f32;
            let v385: f32 = qd[5];
            let v386: f32 = v384 * v385;
            let v387: f32 = v12 * v9;
            (
                v197,
                v201,
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
            let v388: f32 = v386 - v387;
            let v389: f32 = v12 * v6;
            let v390: f32 = v388 - v389;
            let v391: f32 = v390 * v17;
            let v392: f32 = v12 * v20;
            let v393: f32 = v391 - v392;
            let v394: f32 = v393 * v49;
            let v395: f32 = v383 + v394;
            let v396: f32 = -0.00042216_f32;
            let v397: f32 = v396 + v75;
            let v398: f32 = v397 * v20;
            let v399: f32 = v24 * v49;
            let v400: f32 = v398 + v399;
            let v401: f32 = v129 - v128;
            let v402: f32 = v401 * v17;
            let v403: f32 = v400 + v402;
            let v404: f32 = v403 * v14;
            let v405: f32 = v395 + v404;
            let v406: f32 = v405 * v3;
            let v407: f32 = v379 + v406;
            let v408: f32 = 0.13848166_f32;
            let v409: f32 = v408 * v9;
            let v410: f32 = v408 * v6;
            let v411: f32 = v409 + v410;
            let v412: f32 = -0.00107216_f32;
            let v413: f32 = v74 * v17;
            let v414: f32 = v413 * v17;
            let v415: f32 = v412 + v414;
            let v416: f32 = v415 * v33;
            let v417: f32 = v411 + v416;
            let v418: f32 = v162 - v37;
            let v419: f32 = v38 * v6;
            let v420: f32 = v418 + v419;
            let v421: f32 = v420 * v49;
            let v422: f32 = v421 * v14;
            let v423: f32 = v417 + v422;
            let v424: f32 = v387 - v386;
            let v425: f32 = v424 + v389;
            let v426: f32 = v425 + v152;
            let v427: f32 = v152 * v17;
            let v428: f32 = v392 - v427;
            let v429: f32 = v428 * v17;
            let v430: f32 = v426 + v429;
            let v431: f32 = v114 + v88;
            let v432: f32 = v431 * v49;
            let v433: f32 = v432 * v14;
            let v434: f32 = v430 + v433;
            let v435: f32 = v434 * v27;
            let v436: f32 = v423 + v435;
            let v437: f32 = v436 * v96;
            let v438: f32 = v407 + v437;
            let v439: f32 = v438 * v212;
            let v440: f32 = v377 + v439;
            let v441: f32 = -0.69039136_f32;
            let v442: f32 = v38 * v49;
            let v443: f32 = v442 * v14;
            let v444: f32 = v441 - v443;
            let v445: f32 = v444 * v6;
            let v446: f32 = v139 + v357;
            let v447: f32 = v446 + v360;
            let v448: f32 = v447 * v172;
            let v449: f32 = -1.925781_f32;
            let v450: f32 = v449 + v365;
            let v451: f32 = v450 + v370;
            let v452: f32 = v451 * v212;
            let v453: f32 = v448 + v452;
            let v454: f32 = v453 * v376;
            let v455: f32 = v445 + v454;
            let v456: f32 = v179 * v212;
            let v457: f32 = v147 * v172;
            let v458: f32 = v456 - v457;
            let v459: f32 = v458 * v376;
            let v460: f32 = v417 + v459;
            let v461: f32 = v80 * v376;
            let v462: f32 = v461 * v17;
            let v463: f32 = v462 * v172;
            let v464: f32 = v420 * v14;
            let v465: f32 = v463 + v464;
            let v466: f32 = v465 * v49;
            let v467: f32 = v460 + v466;
            let v468: f32 = v461 * v212;
            let v469: f32 = v426 + v468;
            let v470: f32 = v469 + v429;
            let v471: f32 = v470 + v433;
            let v472: f32 = v471 * v27;
            let v473: f32 = v467 + v472;
            let v474: f32 = v473 * v3;
            let v475: f32 = v455 + v474;
            let v476: f32 = v425 * v17;
            let v477: f32 = v392 + v476;
            let v478: f32 = v477 * v49;
            let v479: f32 = v478 - v383;
            let v480: f32 = 0.00042216_f32;
            let v481: f32 = v480 - v75;
            let v482: f32 = v481 * v20;
            let v483: f32 = v482 - v399;
            let v484: f32 = v483 + v131;
            let v485: f32 = v484 * v14;
            let v486: f32 = v479 + v485;
            let v487: f32 = -0.76975256_f32;
            let v488: f32 = v80 * v27;
            let v489: f32 = v487 - v488;
            let v490: f32 = -0.045092795_f32;
            let v491: f32 = v222 * v27;
            let v492: f32 = v490 - v491;
            let v493: f32 = v247 + v283;
            let v494: f32 = v493 * v49;
            let v495: f32 = v494 * v17;
            let v496: f32 = v492 + v495;
            let v497: f32 = v496 * v96;
            let v498: f32 = v489 + v497;
            let v499: f32 = v247 + v119;
            let v500: f32 = v499 * v27;
            let v501: f32 = v237 + v500;
            let v502: f32 = v222 * v49;
            let v503: f32 = -0.00060432_f32;
            let v504: f32 = v503 + v264;
            let v505: f32 = v504 * v17;
            let v506: f32 = v502 + v505;
            let v507: f32 = v506 * v17;
            let v508: f32 = v501 + v507;
            let v509: f32 = v508 * v3;
            let v510: f32 = v498 + v509;
            let v511: f32 = v510 * v172;
            let v512: f32 = -0.02191385_f32;
            let v513: f32 = v80 * v49;
            let v514: f32 = v513 * v17;
            let v515: f32 = v512 + v514;
            let v516: f32 = v218 + v491;
            let v517: f32 = -0.004974336_f32;
            let v518: f32 = v517 - v283;
            let v519: f32 = v518 * v49;
            let v520: f32 = v519 * v17;
            let v521: f32 = v516 + v520;
            let v522: f32 = v521 * v3;
            let v523: f32 = v515 + v522;
            let v524: f32 = v508 * v96;
            let v525: f32 = v523 + v524;
            let v526: f32 = v525 * v212;
            let v527: f32 = v511 + v526;
            let v528: f32 = v527 * v376;
            let v529: f32 = v486 + v528;
            let v530: f32 = v529 * v96;
            let v531: f32 = v475 + v530;
            let v532: f32 = v531 * v172;
            let v533: f32 = v440 + v532;
            let v534: f32 = -0.011273199_f32;
            let v535: f32 = v534 - v351;
            let v536: f32 = v40 * v49;
            let v537: f32 = v536 * v17;
            let v538: f32 = v535 + v537;
            let v539: f32 = v362 + v372;
            let v540: f32 = v539 * v96;
            let v541: f32 = v538 + v540;
            let v542: f32 = v541 * v376;
            let v543: f32 = v406 + v437;
            let v544: f32 = v543 * v212;
            let v545: f32 = v542 + v544;
            let v546: f32 = v361 * v172;
            let v547: f32 = v371 * v212;
            let v548: f32 = v546 + v547;
            let v549: f32 = v548 * v376;
            let v550: f32 = v52 * v212;
            let v551: f32 = v1 * v172;
            let v552: f32 = v550 - v551;
            let v553: f32 = v552 * v376;
            let v554: f32 = v417 + v553;
            let v555: f32 = v38 * v376;
            let v556: f32 = v555 * v17;
            let v557: f32 = v556 * v172;
            let v558: f32 = v557 + v464;
            let v559: f32 = v558 * v49;
            let v560: f32 = v554 + v559;
            let v561: f32 = v555 * v212;
            let v562: f32 = v426 + v561;
            let v563: f32 = v562 + v429;
            let v564: f32 = v563 + v433;
            let v565: f32 = v564 * v27;
            let v566: f32 = v560 + v565;
            let v567: f32 = v566 * v3;
            let v568: f32 = v549 + v567;
            let v569: f32 = -0.38487628_f32;
            let v570: f32 = v569 - v53;
            let v571: f32 = v570 + v497;
            let v572: f32 = v571 + v509;
            let v573: f32 = v572 * v172;
            let v574: f32 = -0.010956925_f32;
            let v575: f32 = v442 * v17;
            let v576: f32 = v574 + v575;
            let v577: f32 = v576 + v522;
            let v578: f32 = v577 + v524;
            let v579: f32 = v578 * v212;
            let v580: f32 = v573 + v579;
            let v581: f32 = v580 * v376;
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
            let v582: f32 = v486 + v581;
            let v583: f32 = v582 * v96;
            let v584: f32 = v568 + v583;
            let v585: f32 = v584 * v172;
            let v586: f32 = v545 + v585;
            let v587: f32 = v12 * v49;
            let v588: f32 = v587 * v17;
            let v589: f32 = v16 * v49;
            let v590: f32 = v536 * v3;
            let v591: f32 = v367 - v589;
            let v592: f32 = v591 * v96;
            let v593: f32 = v590 + v592;
            let v594: f32 = v593 * v96;
            let v595: f32 = v589 + v594;
            let v596: f32 = v595 * v14;
            let v597: f32 = v588 + v596;
            let v598: f32 = v597 * v376;
            let v599: f32 = v18 - v15;
            let v600: f32 = v599 * v20;
            let v601: f32 = v600 * v27;
            let v602: f32 = v12 * v17;
            let v603: f32 = v16 * v14;
            let v604: f32 = v602 + v603;
            let v605: f32 = v604 * v33;
            let v606: f32 = v32 + v605;
            let v607: f32 = v606 * v49;
            let v608: f32 = v601 - v607;
            let v609: f32 = v608 * v3;
            let v610: f32 = 0.00107216_f32;
            let v611: f32 = v610 * v9;
            let v612: f32 = v610 * v6;
            let v613: f32 = v611 + v612;
            let v614: f32 = v129 - v613;
            let v615: f32 = v67 * v33;
            let v616: f32 = v390 + v615;
            let v617: f32 = v616 * v49;
            let v618: f32 = v617 * v14;
            let v619: f32 = v614 + v618;
            let v620: f32 = 0.00022_f32;
            let v621: f32 = v40 * v27;
            let v622: f32 = v620 + v621;
            let v623: f32 = v622 * v20;
            let v624: f32 = v623 + v131;
            let v625: f32 = v624 * v17;
            let v626: f32 = v619 + v625;
            let v627: f32 = v626 * v96;
            let v628: f32 = v609 + v627;
            let v629: f32 = v628 * v212;
            let v630: f32 = v598 + v629;
            let v631: f32 = v32 * v49;
            let v632: f32 = v37 * v49;
            let v633: f32 = v632 - v73;
            let v634: f32 = v633 * v17;
            let v635: f32 = v631 + v634;
            let v636: f32 = v635 * v96;
            let v637: f32 = v215 * v27;
            let v638: f32 = v637 * v17;
            let v639: f32 = v636 - v638;
            let v640: f32 = v614 + v625;
            let v641: f32 = v640 * v3;
            let v642: f32 = v639 + v641;
            let v643: f32 = v392 * v27;
            let v644: f32 = v643 * v96;
            let v645: f32 = v265 * v96;
            let v646: f32 = v645 * v3;
            let v647: f32 = v646 * v212;
            let v648: f32 = v504 * v96;
            let v649: f32 = v648 * v96;
            let v650: f32 = v76 + v649;
            let v651: f32 = v650 * v172;
            let v652: f32 = v647 + v651;
            let v653: f32 = v652 * v376;
            let v654: f32 = v653 * v17;
            let v655: f32 = v644 + v654;
            let v656: f32 = v16 * v96;
            let v657: f32 = v38 + v656;
            let v658: f32 = v657 * v33;
            let v659: f32 = v616 * v3;
            let v660: f32 = v658 + v659;
            let v661: f32 = v44 * v212;
            let v662: f32 = v16 * v172;
            let v663: f32 = v661 - v662;
            let v664: f32 = v228 * v96;
            let v665: f32 = v60 * v3;
            let v666: f32 = v664 - v665;
            let v667: f32 = v666 * v212;
            let v668: f32 = v60 * v96;
            let v669: f32 = v38 + v668;
            let v670: f32 = v228 * v3;
            let v671: f32 = v669 + v670;
            let v672: f32 = v671 * v172;
            let v673: f32 = v667 + v672;
            let v674: f32 = v673 * v96;
            let v675: f32 = v663 + v674;
            let v676: f32 = v675 * v376;
            let v677: f32 = v660 + v676;
            let v678: f32 = v677 * v49;
            let v679: f32 = v655 + v678;
            let v680: f32 = v679 * v14;
            let v681: f32 = v642 + v680;
            let v682: f32 = v681 * v172;
            let v683: f32 = v630 + v682;
            let v684: f32 = v30 * v49;
            let v685: f32 = v684 - v18;
            let v686: f32 = v685 + v15;
            let v687: f32 = v686 * v27;
            let v688: f32 = v67 * v96;
            let v689: f32 = v16 * v3;
            let v690: f32 = v688 - v689;
            let v691: f32 = v690 * v49;
            let v692: f32 = v30 * v3;
            let v693: f32 = v684 * v17;
            let v694: f32 = v16 - v693;
            let v695: f32 = v694 * v96;
            let v696: f32 = v120 * v3;
            let v697: f32 = v695 + v696;
            let v698: f32 = v697 * v27;
            let v699: f32 = v692 + v698;
            let v700: f32 = v699 * v17;
            let v701: f32 = v691 + v700;
            let v702: f32 = v701 * v96;
            let v703: f32 = v687 + v702;
            let v704: f32 = v703 * v376;
            let v705: f32 = v620 * v33;
            let v706: f32 = v705 * v17;
            let v707: f32 = v216 * v14;
            let v708: f32 = v706 - v707;
            let v709: f32 = v708 * v96;
            let v710: f32 = v604 * v20;
            let v711: f32 = v390 - v710;
            let v712: f32 = v711 * v49;
            let v713: f32 = v480 * v9;
            let v714: f32 = v480 * v6;
            let v715: f32 = v713 + v714;
            let v716: f32 = v715 * v14;
            let v717: f32 = v712 - v716;
            let v718: f32 = v717 * v3;
            let v719: f32 = v709 + v718;
            let v720: f32 = v18 - v684;
            let v721: f32 = v720 * v33;
            let v722: f32 = v115 - v37;
            let v723: f32 = v722 * v14;
            let v724: f32 = v721 + v723;
            let v725: f32 = v724 * v3;
            let v726: f32 = v40 * v33;
            let v727: f32 = v425 + v726;
            let v728: f32 = v114 * v49;
            let v729: f32 = v728 * v14;
            let v730: f32 = v727 + v729;
            let v731: f32 = v730 * v17;
            let v732: f32 = v392 + v731;
            let v733: f32 = v732 * v96;
            let v734: f32 = v725 + v733;
            let v735: f32 = v734 * v27;
            let v736: f32 = v719 + v735;
            let v737: f32 = v736 * v212;
            let v738: f32 = v704 + v737;
            let v739: f32 = v705 * v3;
            let v740: f32 = v30 * v376;
            let v741: f32 = v740 * v212;
            let v742: f32 = v739 + v741;
            let v743: f32 = v742 * v17;
            let v744: f32 = v84 * v3;
            let v745: f32 = v744 * v172;
            let v746: f32 = v84 * v96;
            let v747: f32 = v746 * v212;
            let v748: f32 = v745 + v747;
            let v749: f32 = v748 * v376;
            let v750: f32 = v749 * v17;
            let v751: f32 = v716 - v750;
            let v752: f32 = v751 * v96;
            let v753: f32 = v743 + v752;
            let v754: f32 = v38 - v43;
            let v755: f32 = v754 * v20;
            let v756: f32 = v755 * v14;
            let v757: f32 = v201 * v172;
            let v758: f32 = v16 * v212;
            let v759: f32 = v757 - v758;
            let v760: f32 = v759 * v376;
            let v761: f32 = v756 + v760;
            let v762: f32 = v425 + v710;
            let v763: f32 = v80 * v96;
            let v764: f32 = v763 + v665;
            let v765: f32 = v764 * v172;
            let v766: f32 = v669 - v197;
            let v767: f32 = v766 * v212;
            let v768: f32 = v765 + v767;
            let v769: f32 = v768 * v376;
            let v770: f32 = v762 + v769;
            let v771: f32 = v770 * v96;
            let v772: f32 = v761 + v771;
            let v773: f32 = v772 * v49;
            let v774: f32 = v753 + v773;
            let v775: f32 = v392 * v3;
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
            let v776: f32 = v740 * v49;
            let v777: f32 = v776 * v172;
            let v778: f32 = v775 - v777;
            let v779: f32 = v746 * v172;
            let v780: f32 = v744 * v212;
            let v781: f32 = v779 - v780;
            let v782: f32 = v781 * v376;
            let v783: f32 = v108 + v782;
            let v784: f32 = v783 * v49;
            let v785: f32 = v37 - v115;
            let v786: f32 = v785 * v14;
            let v787: f32 = v784 + v786;
            let v788: f32 = v787 * v96;
            let v789: f32 = v778 + v788;
            let v790: f32 = v66 - v656;
            let v791: f32 = v790 * v33;
            let v792: f32 = v730 * v3;
            let v793: f32 = v791 + v792;
            let v794: f32 = v694 * v172;
            let v795: f32 = v120 + v43;
            let v796: f32 = v795 * v212;
            let v797: f32 = v794 + v796;
            let v798: f32 = v284 * v96;
            let v799: f32 = v84 * v49;
            let v800: f32 = v799 * v17;
            let v801: f32 = v60 - v800;
            let v802: f32 = v801 * v3;
            let v803: f32 = v798 + v802;
            let v804: f32 = v803 * v212;
            let v805: f32 = -0.000116928_f32;
            let v806: f32 = v805 + v800;
            let v807: f32 = v806 * v96;
            let v808: f32 = v66 + v807;
            let v809: f32 = v284 * v3;
            let v810: f32 = v808 + v809;
            let v811: f32 = v810 * v172;
            let v812: f32 = v804 + v811;
            let v813: f32 = v812 * v96;
            let v814: f32 = v797 + v813;
            let v815: f32 = v814 * v376;
            let v816: f32 = v793 + v815;
            let v817: f32 = v816 * v17;
            let v818: f32 = v789 + v817;
            let v819: f32 = v818 * v27;
            let v820: f32 = v774 + v819;
            let v821: f32 = v820 * v172;
            let v822: f32 = v738 + v821;
            let v823: f32 = v384 * v33;
            let v824: f32 = v823 * v14;
            let v825: f32 = v824 * v3;
            let v826: f32 = v384 * v20;
            let v827: f32 = v384 * v9;
            let v828: f32 = v384 * v6;
            let v829: f32 = v827 + v828;
            let v830: f32 = v829 * v17;
            let v831: f32 = v826 + v830;
            let v832: f32 = v831 * v96;
            let v833: f32 = v825 - v832;
            let v834: f32 = v833 * v172;
            let v835: f32 = v824 * v96;
            let v836: f32 = v831 * v3;
            let v837: f32 = v835 + v836;
            let v838: f32 = v837 * v212;
            let v839: f32 = v834 + v838;
            let v840: f32 = v839 * v49;
            let v841: f32 = v826 * v17;
            let v842: f32 = v829 + v841;
            let v843: f32 = v842 * v3;
            let v844: f32 = v843 * v172;
            let v845: f32 = v842 * v96;
            let v846: f32 = v845 * v212;
            let v847: f32 = v844 + v846;
            let v848: f32 = v847 * v27;
            let v849: f32 = v840 - v848;
            let v850: f32 = v386 + v615;
            let v851: f32 = v850 * v49;
            let v852: f32 = v851 * v17;
            let v853: f32 = -0.00022_f32;
            let v854: f32 = v67 * v27;
            let v855: f32 = v853 + v854;
            let v856: f32 = v855 * v20;
            let v857: f32 = v856 * v14;
            let v858: f32 = v852 + v857;
            let v859: f32 = v858 * v96;
            let v860: f32 = 0.00077_f32;
            let v861: f32 = v860 * v33;
            let v862: f32 = v72 * v14;
            let v863: f32 = v386 - v862;
            let v864: f32 = v863 * v27;
            let v865: f32 = v861 + v864;
            let v866: f32 = v631 * v14;
            let v867: f32 = v591 * v33;
            let v868: f32 = v866 + v867;
            let v869: f32 = v868 * v17;
            let v870: f32 = v865 + v869;
            let v871: f32 = v870 * v3;
            let v872: f32 = v859 + v871;
            let v873: f32 = v872 * v172;
            let v874: f32 = v386 * v27;
            let v875: f32 = v861 + v874;
            let v876: f32 = v875 * v96;
            let v877: f32 = v620 * v3;
            let v878: f32 = v40 * v3;
            let v879: f32 = v790 + v878;
            let v880: f32 = v879 * v27;
            let v881: f32 = v877 + v880;
            let v882: f32 = v881 * v20;
            let v883: f32 = v882 * v14;
            let v884: f32 = v876 + v883;
            let v885: f32 = v77 * v17;
            let v886: f32 = v885 * v96;
            let v887: f32 = v32 * v14;
            let v888: f32 = v887 * v96;
            let v889: f32 = v386 * v3;
            let v890: f32 = v888 - v889;
            let v891: f32 = v879 * v33;
            let v892: f32 = v890 + v891;
            let v893: f32 = v892 * v49;
            let v894: f32 = v886 + v893;
            let v895: f32 = v894 * v17;
            let v896: f32 = v884 + v895;
            let v897: f32 = v896 * v212;
            let v898: f32 = v873 + v897;
            let v899: f32 = 0.004173999_f32;
            let v900: f32 = v899 + v351;
            let v901: f32 = v900 - v4;
            let v902: f32 = v159 * v49;
            let v903: f32 = v902 * v17;
            let v904: f32 = v901 + v903;
            let v905: f32 = -0.022546398_f32;
            let v906: f32 = v905 - v357;
            let v907: f32 = v80 + v119;
            let v908: f32 = v907 * v49;
            let v909: f32 = v908 * v17;
            let v910: f32 = v906 + v909;
            let v911: f32 = v910 * v96;
            let v912: f32 = v570 + v911;
            let v913: f32 = v80 + v39;
            let v914: f32 = v913 * v27;
            let v915: f32 = v103 + v914;
            let v916: f32 = -0.00030216_f32;
            let v917: f32 = v916 + v75;
            let v918: f32 = v917 * v17;
            let v919: f32 = v368 + v918;
            let v920: f32 = v919 * v17;
            let v921: f32 = v915 + v920;
            let v922: f32 = v921 * v3;
            let v923: f32 = v912 + v922;
            let v924: f32 = v923 * v96;
            let v925: f32 = v904 + v924;
            let v926: f32 = -0.008347998_f32;
            let v927: f32 = v926 - v357;
            let v928: f32 = v147 * v3;
            let v929: f32 = v927 + v928;
            let v930: f32 = v907 - v197;
            let v931: f32 = v930 * v49;
            let v932: f32 = v931 * v17;
            let v933: f32 = v929 + v932;
            let v934: f32 = v933 * v172;
            let v935: f32 = v179 * v3;
            let v936: f32 = v174 - v935;
            let v937: f32 = v368 - v413;
            let v938: f32 = v937 * v17;
            let v939: f32 = v936 + v938;
            let v940: f32 = v80 - v197;
            let v941: f32 = v30 * v17;
            let v942: f32 = v941 * v17;
            let v943: f32 = v30 + v942;
            let v944: f32 = v943 * v27;
            let v945: f32 = v940 + v944;
            let v946: f32 = v945 * v27;
            let v947: f32 = v939 + v946;
            let v948: f32 = v947 * v212;
            let v949: f32 = v934 + v948;
            let v950: f32 = v179 + v488;
            let v951: f32 = v521 * v96;
            let v952: f32 = v950 + v951;
            let v953: f32 = -0.64783967_f32;
            let v954: f32 = v517 - v119;
            let v955: f32 = v954 * v27;
            let v956: f32 = v953 + v955;
            let v957: f32 = v265 * v17;
            let v958: f32 = v957 - v502;
            let v959: f32 = v958 * v17;
            let v960: f32 = v956 + v959;
            let v961: f32 = v960 * v3;
            let v962: f32 = v952 + v961;
            let v963: f32 = v962 * v172;
            let v964: f32 = v147 - v514;
            let v965: f32 = v496 * v3;
            let v966: f32 = v964 + v965;
            let v967: f32 = v960 * v96;
            let v968: f32 = v966 + v967;
            let v969: f32 = v968 * v212;
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
            let v970: f32 = v963 + v969;
            let v971: f32 = v970 * v96;
            let v972: f32 = v949 + v971;
            let v973: f32 = v972 * v172;
            let v974: f32 = v925 + v973;
            let v975: f32 = v974 * v376;
            let v976: f32 = v898 + v975;
            let v977: f32 = v570 * v96;
            let v978: f32 = v977 - v4;
            let v979: f32 = v978 * v9;
            let v980: f32 = -5.8464e-5_f32;
            let v981: f32 = v38 * v96;
            let v982: f32 = v980 - v981;
            let v983: f32 = v982 * v20;
            let v984: f32 = v153 + v983;
            let v985: f32 = v984 * v27;
            let v986: f32 = v142 * v14;
            let v987: f32 = v985 - v986;
            let v988: f32 = v987 * v17;
            let v989: f32 = v979 + v988;
            let v990: f32 = v162 * v17;
            let v991: f32 = v990 * v3;
            let v992: f32 = v16 + v981;
            let v993: f32 = v992 * v33;
            let v994: f32 = v993 * v14;
            let v995: f32 = v991 + v994;
            let v996: f32 = -0.00020216_f32;
            let v997: f32 = v996 + v942;
            let v998: f32 = v997 * v27;
            let v999: f32 = v201 + v998;
            let v1000: f32 = v999 * v20;
            let v1001: f32 = v995 + v1000;
            let v1002: f32 = v1001 * v49;
            let v1003: f32 = v989 + v1002;
            let v1004: f32 = v917 * v33;
            let v1005: f32 = v1004 * v14;
            let v1006: f32 = v1005 - v73;
            let v1007: f32 = v1006 * v17;
            let v1008: f32 = v1 * v6;
            let v1009: f32 = v146 + v1008;
            let v1010: f32 = v1009 * v3;
            let v1011: f32 = v1007 - v1010;
            let v1012: f32 = v52 * v6;
            let v1013: f32 = v178 + v1012;
            let v1014: f32 = v162 + v419;
            let v1015: f32 = v215 * v17;
            let v1016: f32 = v1014 + v1015;
            let v1017: f32 = v1016 * v27;
            let v1018: f32 = v1013 + v1017;
            let v1019: f32 = v1018 * v96;
            let v1020: f32 = v1011 - v1019;
            let v1021: f32 = v1014 * v17;
            let v1022: f32 = v1021 * v3;
            let v1023: f32 = v994 + v1022;
            let v1024: f32 = v1023 + v1000;
            let v1025: f32 = v1024 * v49;
            let v1026: f32 = v1020 + v1025;
            let v1027: f32 = v860 * v3;
            let v1028: f32 = v1027 * v172;
            let v1029: f32 = v860 * v96;
            let v1030: f32 = v1029 * v212;
            let v1031: f32 = v1028 + v1030;
            let v1032: f32 = v1031 * v376;
            let v1033: f32 = v159 * v27;
            let v1034: f32 = v853 + v1033;
            let v1035: f32 = v1034 * v20;
            let v1036: f32 = v1014 * v96;
            let v1037: f32 = v24 + v1036;
            let v1038: f32 = v1037 * v49;
            let v1039: f32 = v1035 + v1038;
            let v1040: f32 = v1039 * v14;
            let v1041: f32 = v1032 + v1040;
            let v1042: f32 = v76 * v3;
            let v1043: f32 = v1042 * v172;
            let v1044: f32 = v76 * v96;
            let v1045: f32 = v1044 * v212;
            let v1046: f32 = v1043 + v1045;
            let v1047: f32 = v1046 * v376;
            let v1048: f32 = v1047 * v17;
            let v1049: f32 = v401 * v14;
            let v1050: f32 = v1048 + v1049;
            let v1051: f32 = v159 * v33;
            let v1052: f32 = v386 + v1051;
            let v1053: f32 = v690 * v172;
            let v1054: f32 = v879 * v212;
            let v1055: f32 = v1053 + v1054;
            let v1056: f32 = v1055 * v376;
            let v1057: f32 = v1052 + v1056;
            let v1058: f32 = v1057 * v49;
            let v1059: f32 = v1050 + v1058;
            let v1060: f32 = v1059 * v17;
            let v1061: f32 = v1041 + v1060;
            let v1062: f32 = v877 * v212;
            let v1063: f32 = v620 * v96;
            let v1064: f32 = v1063 * v172;
            let v1065: f32 = v1062 - v1064;
            let v1066: f32 = v1065 * v376;
            let v1067: f32 = v1066 - v705;
            let v1068: f32 = v1067 * v14;
            let v1069: f32 = v1016 * v3;
            let v1070: f32 = v1069 - v1016;
            let v1071: f32 = v1070 * v49;
            let v1072: f32 = v1068 + v1071;
            let v1073: f32 = v983 - v728;
            let v1074: f32 = v980 + v693;
            let v1075: f32 = v1074 - v981;
            let v1076: f32 = v1075 * v9;
            let v1077: f32 = v1075 * v6;
            let v1078: f32 = v1076 + v1077;
            let v1079: f32 = v1078 * v17;
            let v1080: f32 = v1073 + v1079;
            let v1081: f32 = v1074 * v3;
            let v1082: f32 = v688 + v1081;
            let v1083: f32 = v1082 * v172;
            let v1084: f32 = v1074 * v96;
            let v1085: f32 = v66 + v1084;
            let v1086: f32 = v1085 + v878;
            let v1087: f32 = v1086 * v212;
            let v1088: f32 = v1083 + v1087;
            let v1089: f32 = v1088 * v376;
            let v1090: f32 = v1052 + v1089;
            let v1091: f32 = v1090 * v14;
            let v1092: f32 = v1080 + v1091;
            let v1093: f32 = v1092 * v27;
            let v1094: f32 = v1072 + v1093;
            let v1095: f32 = v823 * v49;
            let v1096: f32 = v1095 * v17;
            let v1097: f32 = v826 * v27;
            let v1098: f32 = v1097 * v14;
            let v1099: f32 = v1096 + v1098;
            let v1100: f32 = v384 * v49;
            let v1101: f32 = v1100 * v17;
            let v1102: f32 = v1101 * v96;
            let v1103: f32 = v384 * v27;
            let v1104: f32 = v1103 * v3;
            let v1105: f32 = v1102 + v1104;
            let v1106: f32 = v1105 * v172;
            let v1107: f32 = v1103 * v96;
            let v1108: f32 = v1101 * v3;
            let v1109: f32 = v1107 - v1108;
            let v1110: f32 = v1109 * v212;
            let v1111: f32 = v1106 + v1110;
            let v1112: f32 = v1111 * v376;
            let v1113: f32 = v1099 + v1112;
            let v1114: f32 = v875 * v3;
            let v1115: f32 = v1114 * v172;
            let v1116: f32 = v876 * v212;
            let v1117: f32 = v1115 + v1116;
            let v1118: f32 = v878 - v656;
            let v1119: f32 = v1118 * v212;
            let v1120: f32 = v1053 + v1119;
            let v1121: f32 = v1120 * v27;
            let v1122: f32 = v1065 + v1121;
            let v1123: f32 = v1122 * v20;
            let v1124: f32 = v1123 * v14;
            let v1125: f32 = v1117 + v1124;
            let v1126: f32 = v1046 * v33;
            let v1127: f32 = v1126 * v17;
            let v1128: f32 = v386 * v96;
            let v1129: f32 = v887 * v3;
            let v1130: f32 = v1128 + v1129;
            let v1131: f32 = v1130 * v172;
            let v1132: f32 = v890 * v212;
            let v1133: f32 = v1131 + v1132;
            let v1134: f32 = v1120 * v33;
            let v1135: f32 = v1133 + v1134;
            let v1136: f32 = v1135 * v49;
            let v1137: f32 = v1127 + v1136;
            let v1138: f32 = v1137 * v17;
            let v1139: f32 = v1125 + v1138;
            let v1140: f32 = v8 + v351;
            let v1141: f32 = v67 * v49;
            let v1142: f32 = v1141 * v17;
            let v1143: f32 = v1140 + v1142;
            let v1144: f32 = v911 + v922;
            let v1145: f32 = v1144 * v96;
            let v1146: f32 = v1143 + v1145;
            let v1147: f32 = v906 + v4;
            let v1148: f32 = v907 - v43;
            let v1149: f32 = v1148 * v49;
            let v1150: f32 = v1149 * v17;
            let v1151: f32 = v1147 + v1150;
            let v1152: f32 = v1151 * v172;
            let v1153: f32 = v52 * v3;
            let v1154: f32 = v103 - v1153;
            let v1155: f32 = v1154 + v938;
            let v1156: f32 = v80 - v43;
            let v1157: f32 = v1156 + v944;
            let v1158: f32 = v1157 * v27;
            let v1159: f32 = v1155 + v1158;
            let v1160: f32 = v1159 * v212;
            let v1161: f32 = v1152 + v1160;
            let v1162: f32 = v54 + v951;
            let v1163: f32 = v1162 + v961;
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
            let v1164: f32 = v1163 * v172;
            let v1165: f32 = v1 - v575;
            let v1166: f32 = v1165 + v965;
            let v1167: f32 = v1166 + v967;
            let v1168: f32 = v1167 * v212;
            let v1169: f32 = v1164 + v1168;
            let v1170: f32 = v1169 * v96;
            let v1171: f32 = v1161 + v1170;
            let v1172: f32 = v1171 * v172;
            let v1173: f32 = v1146 + v1172;
            let v1174: f32 = v1173 * v376;
            let v1175: f32 = v1139 + v1174;
            let v1176: f32 = v54 * v96;
            let v1177: f32 = v4 + v1176;
            let v1178: f32 = v1177 * v6;
            let v1179: f32 = v35 + v68;
            let v1180: f32 = v1179 * v49;
            let v1181: f32 = v1178 + v1180;
            let v1182: f32 = v1074 * v20;
            let v1183: f32 = v153 + v1182;
            let v1184: f32 = v1183 * v27;
            let v1185: f32 = v419 * v49;
            let v1186: f32 = v1185 * v3;
            let v1187: f32 = v986 + v1186;
            let v1188: f32 = v1184 - v1187;
            let v1189: f32 = v1188 * v17;
            let v1190: f32 = v1181 + v1189;
            let v1191: f32 = v1184 - v986;
            let v1192: f32 = v1191 * v17;
            let v1193: f32 = v1180 + v1192;
            let v1194: f32 = v399 + v856;
            let v1195: f32 = v1194 * v14;
            let v1196: f32 = v1032 + v1195;
            let v1197: f32 = v851 + v1049;
            let v1198: f32 = v1046 * v17;
            let v1199: f32 = v1120 * v49;
            let v1200: f32 = v1198 + v1199;
            let v1201: f32 = v1200 * v376;
            let v1202: f32 = v1197 + v1201;
            let v1203: f32 = v1202 * v17;
            let v1204: f32 = v1196 + v1203;
            let v1205: f32 = v1016 * v49;
            let v1206: f32 = v1068 - v1205;
            let v1207: f32 = v728 * v17;
            let v1208: f32 = v1207 - v24;
            let v1209: f32 = v1208 * v17;
            let v1210: f32 = v72 + v728;
            let v1211: f32 = v1209 - v1210;
            let v1212: f32 = v1084 + v878;
            let v1213: f32 = v1212 * v212;
            let v1214: f32 = v1083 + v1213;
            let v1215: f32 = v1214 * v376;
            let v1216: f32 = v850 + v1215;
            let v1217: f32 = v1216 * v14;
            let v1218: f32 = v1211 + v1217;
            let v1219: f32 = v1218 * v27;
            let v1220: f32 = v1206 + v1219;
            let v1221: f32 = v30 * v96;
            let v1222: f32 = v1221 * v172;
            let v1223: f32 = v692 * v212;
            let v1224: f32 = v1222 - v1223;
            let v1225: f32 = v1224 * v20;
            let v1226: f32 = v1225 * v27;
            let v1227: f32 = v67 * v3;
            let v1228: f32 = v656 + v1227;
            let v1229: f32 = v1228 * v96;
            let v1230: f32 = v980 + v1229;
            let v1231: f32 = v159 * v212;
            let v1232: f32 = v662 + v1231;
            let v1233: f32 = v907 * v96;
            let v1234: f32 = v665 + v1233;
            let v1235: f32 = v1234 * v212;
            let v1236: f32 = v66 - v668;
            let v1237: f32 = v907 * v3;
            let v1238: f32 = v1236 + v1237;
            let v1239: f32 = v1238 * v172;
            let v1240: f32 = v1235 + v1239;
            let v1241: f32 = v1240 * v96;
            let v1242: f32 = v1232 + v1241;
            let v1243: f32 = v1242 * v172;
            let v1244: f32 = v1230 + v1243;
            let v1245: f32 = v1244 * v376;
            let v1246: f32 = v384 * v3;
            let v1247: f32 = v1246 * v172;
            let v1248: f32 = v384 * v96;
            let v1249: f32 = v1248 * v212;
            let v1250: f32 = v1247 + v1249;
            let v1251: f32 = v1250 * v385;
            let v1252: f32 = v1245 - v1251;
            let v1253: f32 = v1252 * v14;
            let v1254: f32 = v1226 + v1253;
            let v1255: f32 = v1254 * v49;
            let v1256: f32 = v860 * v9;
            let v1257: f32 = v860 * v6;
            let v1258: f32 = v1256 + v1257;
            let v1259: f32 = v1258 * v3;
            let v1260: f32 = v1259 * v172;
            let v1261: f32 = v1258 * v96;
            let v1262: f32 = v1261 * v212;
            let v1263: f32 = v1260 + v1262;
            let v1264: f32 = v1255 - v1263;
            let v1265: f32 = v917 * v14;
            let v1266: f32 = v1265 * v96;
            let v1267: f32 = v1266 * v96;
            let v1268: f32 = v1267 - v587;
            let v1269: f32 = v1268 * v376;
            let v1270: f32 = v1014 + v115;
            let v1271: f32 = v1270 * v3;
            let v1272: f32 = v419 - v1271;
            let v1273: f32 = v1272 * v49;
            let v1274: f32 = v403 * v96;
            let v1275: f32 = v1273 + v1274;
            let v1276: f32 = v1275 * v212;
            let v1277: f32 = v1269 + v1276;
            let v1278: f32 = v917 * v376;
            let v1279: f32 = v1278 * v14;
            let v1280: f32 = v1279 * v172;
            let v1281: f32 = v265 * v376;
            let v1282: f32 = v1281 * v14;
            let v1283: f32 = v1282 * v96;
            let v1284: f32 = v1283 * v172;
            let v1285: f32 = v1270 * v49;
            let v1286: f32 = v1284 + v1285;
            let v1287: f32 = v1286 * v96;
            let v1288: f32 = v1280 + v1287;
            let v1289: f32 = v504 * v376;
            let v1290: f32 = v1289 * v14;
            let v1291: f32 = v1290 * v96;
            let v1292: f32 = v1291 * v212;
            let v1293: f32 = v400 + v1292;
            let v1294: f32 = v1293 + v402;
            let v1295: f32 = v1294 * v3;
            let v1296: f32 = v1288 + v1295;
            let v1297: f32 = v1296 * v172;
            let v1298: f32 = v1277 + v1297;
            let v1299: f32 = v1298 * v17;
            let v1300: f32 = v1264 + v1299;
            let v1301: f32 = v982 * v6;
            let v1302: f32 = v1301 - v22;
            let v1303: f32 = v1302 * v49;
            let v1304: f32 = v482 + v1303;
            let v1305: f32 = v1304 * v14;
            let v1306: f32 = v1305 - v1032;
            let v1307: f32 = v130 * v14;
            let v1308: f32 = v386 * v49;
            let v1309: f32 = v1307 - v1308;
            let v1310: f32 = v917 * v3;
            let v1311: f32 = v1310 * v172;
            let v1312: f32 = v917 * v96;
            let v1313: f32 = v1312 * v212;
            let v1314: f32 = v1311 + v1313;
            let v1315: f32 = v1314 * v17;
            let v1316: f32 = v40 * v96;
            let v1317: f32 = v689 + v1316;
            let v1318: f32 = v1317 * v172;
            let v1319: f32 = v657 + v1227;
            let v1320: f32 = v1319 * v212;
            let v1321: f32 = v1318 + v1320;
            let v1322: f32 = v1321 * v49;
            let v1323: f32 = v1315 + v1322;
            let v1324: f32 = v1323 * v376;
            let v1325: f32 = v1309 + v1324;
            let v1326: f32 = v1325 * v17;
            let v1327: f32 = v1306 + v1326;
            let v1328: f32 = v483 * v14;
            let v1329: f32 = v1328 - v1032;
            let v1330: f32 = v1228 * v212;
            let v1331: f32 = v1318 + v1330;
            let v1332: f32 = v1331 * v49;
            let v1333: f32 = v1315 + v1332;
            let v1334: f32 = v1333 * v376;
            let v1335: f32 = v1309 + v1334;
            let v1336: f32 = v1335 * v17;
            let v1337: f32 = v1329 + v1336;
            let v1338: f32 = v480 * v3;
            let v1339: f32 = v1338 * v172;
            let v1340: f32 = v480 * v96;
            let v1341: f32 = v1340 * v212;
            let v1342: f32 = v1339 + v1341;
            let v1343: f32 = v1342 * v376;
            let v1344: f32 = v1343 * v17;
            let v1345: f32 = v1308 + v1344;
            let v1346: f32 = v716 - v1345;
            let v1347: f32 = v1224 * v376;
            let v1348: f32 = v108 + v1347;
            let v1349: f32 = v1348 * v49;
            let v1350: f32 = v692 * v172;
            let v1351: f32 = v1221 * v212;
            let v1352: f32 = v1350 + v1351;
            let v1353: f32 = v1352 * v376;
            let v1354: f32 = v1353 * v17;
            let v1355: f32 = v114 * v14;
            let v1356: f32 = v1354 - v1355;
            let v1357: f32 = v1356 * v27;
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
        let (
            v1360,
            v1365,
            v1470,
            v1496,
            v1509,
            v1519,
            v1520,
            v1531,
            v1536,
            v1539,
            v1546,
        ) = {
            let v1358: f32 = v1349 + v1357;
            let v1359: f32 = v1358 * v27;
            let v1360: f32 = v1346 + v1359;
            let v1361: f32 = v1250 * v376;
            let v1362: f32 = v1361 * v14;
            let v1363: f32 = v831 + v1362;
            let v1364: f32 = v1363 * v49;
            let v1365: f32 = -v1364;
            let v1366: f32 = v555 * v49;
            let v1367: f32 = v1366 * v96;
            let v1368: f32 = v480 * v33;
            let v1369: f32 = v1368 * v17;
            let v1370: f32 = v1369 * v212;
            let v1371: f32 = v1367 + v1370;
            let v1372: f32 = v1371 * v96;
            let v1373: f32 = v589 - v941;
            let v1374: f32 = v1373 * v376;
            let v1375: f32 = v1374 * v96;
            let v1376: f32 = v620 * v9;
            let v1377: f32 = v620 * v6;
            let v1378: f32 = v1376 + v1377;
            let v1379: f32 = v1378 * v14;
            let v1380: f32 = v1308 + v1379;
            let v1381: f32 = v1380 * v212;
            let v1382: f32 = v1375 - v1381;
            let v1383: f32 = v1382 * v3;
            let v1384: f32 = v1372 + v1383;
            let v1385: f32 = v1369 * v3;
            let v1386: f32 = v1380 * v96;
            let v1387: f32 = v1385 + v1386;
            let v1388: f32 = v746 * v3;
            let v1389: f32 = v1388 * v172;
            let v1390: f32 = v746 * v96;
            let v1391: f32 = v996 + v1390;
            let v1392: f32 = v1391 * v212;
            let v1393: f32 = v1389 + v1392;
            let v1394: f32 = v1393 * v17;
            let v1395: f32 = v754 * v172;
            let v1396: f32 = v758 + v1395;
            let v1397: f32 = v1236 + v197;
            let v1398: f32 = v1397 * v212;
            let v1399: f32 = v1398 - v765;
            let v1400: f32 = v1399 * v96;
            let v1401: f32 = v1396 + v1400;
            let v1402: f32 = v1401 * v49;
            let v1403: f32 = v1394 + v1402;
            let v1404: f32 = v1403 * v376;
            let v1405: f32 = v1387 + v1404;
            let v1406: f32 = v1405 * v172;
            let v1407: f32 = v1384 + v1406;
            let v1408: f32 = v720 - v15;
            let v1409: f32 = v684 * v96;
            let v1410: f32 = v38 + v119;
            let v1411: f32 = v1410 * v3;
            let v1412: f32 = v1084 + v1411;
            let v1413: f32 = v1412 * v17;
            let v1414: f32 = v1409 + v1413;
            let v1415: f32 = v1414 * v96;
            let v1416: f32 = v1408 + v1415;
            let v1417: f32 = v1416 * v376;
            let v1418: f32 = v109 * v3;
            let v1419: f32 = v386 - v152;
            let v1420: f32 = v1419 * v17;
            let v1421: f32 = v1420 * v96;
            let v1422: f32 = v1418 + v1421;
            let v1423: f32 = v695 + v1227;
            let v1424: f32 = v1423 * v9;
            let v1425: f32 = v38 + v695;
            let v1426: f32 = v1425 + v1227;
            let v1427: f32 = v1426 * v6;
            let v1428: f32 = v1424 + v1427;
            let v1429: f32 = v1428 * v14;
            let v1430: f32 = v1422 + v1429;
            let v1431: f32 = v1430 * v212;
            let v1432: f32 = v1417 + v1431;
            let v1433: f32 = v24 * v14;
            let v1434: f32 = v1433 * v3;
            let v1435: f32 = v777 + v1434;
            let v1436: f32 = v780 - v779;
            let v1437: f32 = v1436 * v376;
            let v1438: f32 = v1437 - v108;
            let v1439: f32 = v1438 * v49;
            let v1440: f32 = v1270 * v14;
            let v1441: f32 = v1439 + v1440;
            let v1442: f32 = v1441 * v96;
            let v1443: f32 = v1435 + v1442;
            let v1444: f32 = v1419 - v729;
            let v1445: f32 = v1444 * v3;
            let v1446: f32 = v1074 * v172;
            let v1447: f32 = v1410 - v43;
            let v1448: f32 = v1447 * v212;
            let v1449: f32 = v1446 + v1448;
            let v1450: f32 = v192 - v283;
            let v1451: f32 = v1450 * v96;
            let v1452: f32 = v806 * v3;
            let v1453: f32 = v1451 + v1452;
            let v1454: f32 = v1453 * v212;
            let v1455: f32 = v801 * v96;
            let v1456: f32 = v38 + v1455;
            let v1457: f32 = v1450 * v3;
            let v1458: f32 = v1456 + v1457;
            let v1459: f32 = v1458 * v172;
            let v1460: f32 = v1454 + v1459;
            let v1461: f32 = v1460 * v96;
            let v1462: f32 = v1449 + v1461;
            let v1463: f32 = v1462 * v376;
            let v1464: f32 = v1445 + v1463;
            let v1465: f32 = v1464 * v17;
            let v1466: f32 = v1443 + v1465;
            let v1467: f32 = v1466 * v172;
            let v1468: f32 = v1432 + v1467;
            let v1469: f32 = v1468 * v27;
            let v1470: f32 = v1407 + v1469;
            let v1471: f32 = v754 * v6;
            let v1472: f32 = v162 + v1471;
            let v1473: f32 = v1472 * v49;
            let v1474: f32 = v1064 - v1062;
            let v1475: f32 = v1474 * v376;
            let v1476: f32 = v1475 - v1368;
            let v1477: f32 = v1476 * v14;
            let v1478: f32 = v1473 + v1477;
            let v1479: f32 = v694 * v9;
            let v1480: f32 = v694 + v981;
            let v1481: f32 = v1480 * v6;
            let v1482: f32 = v1479 + v1481;
            let v1483: f32 = v1482 * v17;
            let v1484: f32 = v728 + v1483;
            let v1485: f32 = v152 - v386;
            let v1486: f32 = v694 * v3;
            let v1487: f32 = v1316 + v1486;
            let v1488: f32 = v1487 * v172;
            let v1489: f32 = v1426 * v212;
            let v1490: f32 = v1488 + v1489;
            let v1491: f32 = v1490 * v376;
            let v1492: f32 = v1485 + v1491;
            let v1493: f32 = v1492 * v14;
            let v1494: f32 = v1484 + v1493;
            let v1495: f32 = v1494 * v27;
            let v1496: f32 = v1478 + v1495;
            let v1497: f32 = v1014 * v49;
            let v1498: f32 = v1497 + v1477;
            let v1499: f32 = v24 - v1207;
            let v1500: f32 = v1499 * v17;
            let v1501: f32 = v728 + v1500;
            let v1502: f32 = v1423 * v212;
            let v1503: f32 = v1488 + v1502;
            let v1504: f32 = v1503 * v376;
            let v1505: f32 = v1485 + v1504;
            let v1506: f32 = v1505 * v14;
            let v1507: f32 = v1501 + v1506;
            let v1508: f32 = v1507 * v27;
            let v1509: f32 = v1498 + v1508;
            let v1510: f32 = v1345 - v716;
            let v1511: f32 = v1223 - v1222;
            let v1512: f32 = v1511 * v376;
            let v1513: f32 = v1512 - v108;
            let v1514: f32 = v1513 * v49;
            let v1515: f32 = v1355 - v1354;
            let v1516: f32 = v1515 * v27;
            let v1517: f32 = v1514 + v1516;
            let v1518: f32 = v1517 * v27;
            let v1519: f32 = v1510 + v1518;
            let v1520: f32 = 0.0_f32;
            let v1521: f32 = v1248 * v172;
            let v1522: f32 = v1246 * v212;
            let v1523: f32 = v1521 - v1522;
            let v1524: f32 = v1523 * v376;
            let v1525: f32 = v823 + v1524;
            let v1526: f32 = v1525 * v49;
            let v1527: f32 = v1361 * v17;
            let v1528: f32 = v829 * v14;
            let v1529: f32 = v1527 - v1528;
            let v1530: f32 = v1529 * v27;
            let v1531: f32 = v1526 + v1530;
            let v1532: f32 = v1108 - v1107;
            let v1533: f32 = v1532 * v212;
            let v1534: f32 = v1533 - v1106;
            let v1535: f32 = v1534 * v376;
            let v1536: f32 = v1099 + v1535;
            let v1537: f32 = v830 - v826;
            let v1538: f32 = v1537 + v1362;
            let v1539: f32 = v1538 * v49;
            let v1540: f32 = v1522 - v1521;
            let v1541: f32 = v1540 * v376;
            let v1542: f32 = v1541 - v823;
            let v1543: f32 = v1542 * v49;
            let v1544: f32 = v1528 - v1527;
            let v1545: f32 = v1544 * v27;
            let v1546: f32 = v1543 + v1545;
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
    /// - `q: &[f32; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[f32; 6]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis: [f32; 6]`: c(q, qd) = C(q, qd) qd (N m or N)
    ///
    /// Operation count: 479 floating-point operations, 10 trig calls.
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
            v10,
            v11,
            v14,
            v16,
            v21,
            v24,
            v28,
            v32,
            v33,
            v37,
            v39,
            v41,
            v44,
            v46,
            v47,
            v49,
            v54,
            v57,
            v59,
            v65,
            v67,
            v70,
            v72,
            v75,
            v77,
            v79,
            v85,
            v89,
            v92,
            v96,
            v98,
            v105,
            v107,
            v116,
            v119,
            v121,
            v122,
            v124,
            v127,
            v128,
            v130,
            v132,
            v133,
            v135,
            v136,
            v140,
            v149,
            v154,
            v157,
            v159,
            v161,
            v162,
            v164,
            v170,
            v172,
            v173,
            v175,
            v176,
            v177,
        ) = {
            let v0: f32 = q[1];
            let (v1, v3): (f32, f32) = ::libm::sincosf(v0);
            let v2: f32 = 1.0311852_f32;
            let v4: f32 = qd[0];
            let v5: f32 = v3 * v4;
            let v6: f32 = qd[1];
            let v7: f32 = v5 * v6;
            let v8: f32 = v2 * v7;
            let v9: f32 = 0.03798072_f32;
            let v10: f32 = v1 * v4;
            let v11: f32 = v10 * v6;
            let v12: f32 = v9 * v11;
            let v13: f32 = v8 - v12;
            let v14: f32 = 1.4401023_f32;
            let v15: f32 = v14 * v10;
            let v16: f32 = -0.023751_f32;
            let v17: f32 = v16 * v5;
            let v18: f32 = v15 + v17;
            let v19: f32 = 2.842524_f32;
            let v20: f32 = v19 * v6;
            let v21: f32 = v18 + v20;
            let v22: f32 = v5 * v21;
            let v23: f32 = v9 * v10;
            let v24: f32 = 3.7274563_f32;
            let v25: f32 = v24 * v5;
            let v26: f32 = v23 + v25;
            let v27: f32 = v16 * v6;
            let v28: f32 = v26 + v27;
            let v29: f32 = v6 * v28;
            let v30: f32 = v22 - v29;
            let v31: f32 = v13 + v30;
            let v32: f32 = 0.1044_f32;
            let v33: f32 = 0.4318_f32;
            let v34: f32 = v33 * v11;
            let v35: f32 = v33 * v6;
            let v36: f32 = v10 * v35;
            let v37: f32 = v34 + v36;
            let v38: f32 = v32 * v37;
            let v39: f32 = 3.9585_f32;
            let v40: f32 = v33 * v5;
            let v41: f32 = v10 * v40;
            let v42: f32 = v39 * v41;
            let v43: f32 = v38 - v42;
            let v44: f32 = v31 + v43;
            let v45: f32 = q[2];
            let (v49, v46): (f32, f32) = ::libm::sincosf(v45);
            let v47: f32 = 0.090474285_f32;
            let v48: f32 = v46 * v7;
            let v50: f32 = v49 * v11;
            let v51: f32 = v48 - v50;
            let v52: f32 = v46 * v5;
            let v53: f32 = v49 * v10;
            let v54: f32 = v52 - v53;
            let v55: f32 = qd[2];
            let v56: f32 = v54 * v55;
            let v57: f32 = v51 + v56;
            let v58: f32 = v47 * v57;
            let v59: f32 = 0.0068208_f32;
            let v60: f32 = v49 * v7;
            let v61: f32 = v46 * v11;
            let v62: f32 = v60 + v61;
            let v63: f32 = v46 * v10;
            let v64: f32 = v49 * v5;
            let v65: f32 = v63 + v64;
            let v66: f32 = v65 * v55;
            let v67: f32 = v62 + v66;
            let v68: f32 = v59 * v67;
            let v69: f32 = v58 - v68;
            let v70: f32 = v6 + v55;
            let v71: f32 = v59 * v65;
            let v72: f32 = 0.0047376_f32;
            let v73: f32 = v72 * v70;
            let v74: f32 = v71 - v73;
            let v75: f32 = 0.01543232_f32;
            let v76: f32 = v75 * v54;
            let v77: f32 = v74 + v76;
            let v78: f32 = v70 * v77;
            let v79: f32 = -0.001373904_f32;
            let v80: f32 = v79 * v65;
            let v81: f32 = 0.111498035_f32;
            let v82: f32 = v81 * v70;
            let v83: f32 = v80 - v82;
            let v84: f32 = v72 * v54;
            let v85: f32 = v83 + v84;
            let v86: f32 = v54 * v85;
            let v87: f32 = v78 + v86;
            let v88: f32 = v69 - v87;
            let v89: f32 = -0.06768_f32;
            let v90: f32 = v5 * v40;
            let v91: f32 = v6 * v35;
            let v92: f32 = v90 + v91;
            let v93: f32 = v49 * v92;
            let v94: f32 = v46 * v41;
            let v95: f32 = v93 + v94;
            let v96: f32 = -0.15005_f32;
            let v97: f32 = v96 * v57;
            let v98: f32 = 0.0203_f32;
            let v99: f32 = v98 * v54;
            let v100: f32 = v65 * v99;
            let v101: f32 = v96 * v54;
            let v102: f32 = v70 * v101;
            let v103: f32 = v100 - v102;
            let v104: f32 = v97 + v103;
            let v105: f32 = v95 + v104;
            let v106: f32 = v89 * v105;
            let v107: f32 = 0.336_f32;
            let v108: f32 = v98 * v67;
            let v109: f32 = v54 * v101;
            let v110: f32 = v96 * v65;
            let v111: f32 = v98 * v70;
            let v112: f32 = v110 + v111;
            let v113: f32 = v65 * v112;
            let v114: f32 = v109 + v113;
            let v115: f32 = v108 + v114;
            let v116: f32 = v37 + v115;
            let v117: f32 = v107 * v116;
            let v118: f32 = v106 + v117;
            let v119: f32 = v88 + v118;
            let v120: f32 = q[3];
            let (v124, v121): (f32, f32) = ::libm::sincosf(v120);
            let v122: f32 = 0.00209602_f32;
            let v123: f32 = v121 * v57;
            let v125: f32 = v124 * v65;
            let v126: f32 = v121 * v70;
            let v127: f32 = v125 + v126;
            let v128: f32 = qd[3];
            let v129: f32 = v127 * v128;
            let v130: f32 = v123 - v129;
            let v131: f32 = v122 * v130;
            let v132: f32 = v54 + v128;
            let v133: f32 = v122 * v127;
            let v134: f32 = v132 * v133;
            let v135: f32 = 0.0013_f32;
            let v136: f32 = v135 * v132;
            let v137: f32 = v127 * v136;
            let v138: f32 = v134 - v137;
            let v139: f32 = v131 + v138;
            let v140: f32 = 0.01558_f32;
            let v141: f32 = v49 * v41;
            let v142: f32 = v46 * v92;
            let v143: f32 = v141 - v142;
            let v144: f32 = v96 * v67;
            let v145: f32 = v70 * v112;
            let v146: f32 = v54 * v99;
            let v147: f32 = v145 + v146;
            let v148: f32 = v144 - v147;
            let v149: f32 = v143 + v148;
            let v150: f32 = v124 * v149;
            let v151: f32 = v121 * v116;
            let v152: f32 = v150 + v151;
            let v153: f32 = v33 * v130;
            let v154: f32 = v33 * v127;
            let v155: f32 = v132 * v154;
            let v156: f32 = v153 + v155;
            let v157: f32 = v152 + v156;
            let v158: f32 = v140 * v157;
            let v159: f32 = v139 + v158;
            let v160: f32 = q[4];
            let (v164, v161): (f32, f32) = ::libm::sincosf(v160);
            let v162: f32 = 0.0003_f32;
            let v163: f32 = v161 * v130;
            let v165: f32 = v164 * v67;
            let v166: f32 = v163 - v165;
            let v167: f32 = v161 * v132;
            let v168: f32 = v121 * v65;
            let v169: f32 = v124 * v70;
            let v170: f32 = v168 - v169;
            let v171: f32 = v164 * v170;
            let v172: f32 = v167 - v171;
            let v173: f32 = qd[4];
            let v174: f32 = v172 * v173;
            let v175: f32 = v166 + v174;
            let v176: f32 = v162 * v175;
            let v177: f32 = 0.0004_f32;
            (
                v1,
                v2,
                v3,
                v5,
                v6,
                v7,
                v9,
                v10,
                v11,
                v14,
                v16,
                v21,
                v24,
                v28,
                v32,
                v33,
                v37,
                v39,
                v41,
                v44,
                v46,
                v47,
                v49,
                v54,
                v57,
                v59,
                v65,
                v67,
                v70,
                v72,
                v75,
                v77,
                v79,
                v85,
                v89,
                v92,
                v96,
                v98,
                v105,
                v107,
                v116,
                v119,
                v121,
                v122,
                v124,
                v127,
                v128,
                v130,
                v132,
                v133,
                v135,
                v136,
                v140,
                v149,
                v154,
                v157,
                v159,
                v161,
                v162,
                v164,
                v170,
                v172,
                v173,
                v175,
                v176,
                v177,
            )
        };
        let (
            v226,
            v256,
            v273,
            v274,
            v278,
            v281,
            v304,
            v306,
            v310,
            v324,
            v327,
            v336,
            v347,
            v350,
            v352,
            v355,
        ) = {
            let v178: f32 = v127 + v173;
            let v179: f32 = v177 * v178;
            let v180: f32 = v172 * v179;
            let v181: f32 = v162 * v172;
            let v182: f32 = v178 * v181;
            let v183: f32 = v180 - v182;
            let v184: f32 = v176 + v183;
            let v185: f32 = q[5];
            let (v189, v186): (f32, f32) = ::libm::sincosf(v185);
            let v187: f32 = 0.00024216_f32;
            let v188: f32 = v186 * v175;
            let v190: f32 = v124 * v57;
            let v191: f32 = v170 * v128;
            let v192: f32 = v190 + v191;
            let v193: f32 = v189 * v192;
            let v194: f32 = v188 - v193;
            let v195: f32 = v161 * v170;
            let v196: f32 = v164 * v132;
            let v197: f32 = v195 + v196;
            let v198: f32 = v189 * v197;
            let v199: f32 = v186 * v178;
            let v200: f32 = v198 + v199;
            let v201: f32 = qd[5];
            let v202: f32 = v200 * v201;
            let v203: f32 = v194 - v202;
            let v204: f32 = v187 * v203;
            let v205: f32 = v172 + v201;
            let v206: f32 = v187 * v200;
            let v207: f32 = v205 * v206;
            let v208: f32 = 4e-5_f32;
            let v209: f32 = v208 * v205;
            let v210: f32 = v200 * v209;
            let v211: f32 = v207 - v210;
            let v212: f32 = v204 + v211;
            let v213: f32 = 0.00288_f32;
            let v214: f32 = v121 * v149;
            let v215: f32 = v124 * v116;
            let v216: f32 = v214 - v215;
            let v217: f32 = v33 * v170;
            let v218: f32 = v132 * v217;
            let v219: f32 = v33 * v192;
            let v220: f32 = v218 - v219;
            let v221: f32 = v216 + v220;
            let v222: f32 = v161 * v221;
            let v223: f32 = v127 * v154;
            let v224: f32 = v170 * v217;
            let v225: f32 = v223 + v224;
            let v226: f32 = v105 - v225;
            let v227: f32 = v164 * v226;
            let v228: f32 = v222 + v227;
            let v229: f32 = v189 * v228;
            let v230: f32 = v186 * v157;
            let v231: f32 = v229 + v230;
            let v232: f32 = v213 * v231;
            let v233: f32 = v212 + v232;
            let v234: f32 = v186 * v233;
            let v235: f32 = v186 * v197;
            let v236: f32 = v189 * v178;
            let v237: f32 = v235 - v236;
            let v238: f32 = v187 * v237;
            let v239: f32 = v205 * v238;
            let v240: f32 = v237 * v209;
            let v241: f32 = v239 - v240;
            let v242: f32 = v189 * v175;
            let v243: f32 = v186 * v192;
            let v244: f32 = v242 + v243;
            let v245: f32 = v237 * v201;
            let v246: f32 = v244 + v245;
            let v247: f32 = v187 * v246;
            let v248: f32 = v241 - v247;
            let v249: f32 = v186 * v228;
            let v250: f32 = v189 * v157;
            let v251: f32 = v249 - v250;
            let v252: f32 = v213 * v251;
            let v253: f32 = v248 + v252;
            let v254: f32 = v189 * v253;
            let v255: f32 = v234 - v254;
            let v256: f32 = v184 + v255;
            let v257: f32 = v161 * v256;
            let v258: f32 = v162 * v197;
            let v259: f32 = v178 * v258;
            let v260: f32 = v197 * v179;
            let v261: f32 = v259 - v260;
            let v262: f32 = v164 * v130;
            let v263: f32 = v161 * v67;
            let v264: f32 = v262 + v263;
            let v265: f32 = v197 * v173;
            let v266: f32 = v264 + v265;
            let v267: f32 = v162 * v266;
            let v268: f32 = v261 - v267;
            let v269: f32 = v200 * v238;
            let v270: f32 = v237 * v206;
            let v271: f32 = v269 - v270;
            let v272: f32 = v208 * v266;
            let v273: f32 = v271 - v272;
            let v274: f32 = v268 + v273;
            let v275: f32 = v164 * v274;
            let v276: f32 = v257 - v275;
            let v277: f32 = v159 + v276;
            let v278: f32 = 0.82_f32;
            let v279: f32 = v278 * v157;
            let v280: f32 = v140 * v130;
            let v281: f32 = v140 * v127;
            let v282: f32 = v132 * v281;
            let v283: f32 = v280 + v282;
            let v284: f32 = v279 + v283;
            let v285: f32 = 0.09_f32;
            let v286: f32 = v285 * v251;
            let v287: f32 = v213 * v237;
            let v288: f32 = v205 * v287;
            let v289: f32 = v213 * v246;
            let v290: f32 = v288 - v289;
            let v291: f32 = v286 + v290;
            let v292: f32 = v189 * v291;
            let v293: f32 = v285 * v231;
            let v294: f32 = v213 * v203;
            let v295: f32 = v213 * v200;
            let v296: f32 = v205 * v295;
            let v297: f32 = v294 + v296;
            let v298: f32 = v293 + v297;
            let v299: f32 = v186 * v298;
            let v300: f32 = v292 - v299;
            let v301: f32 = 0.34_f32;
            let v302: f32 = v301 * v157;
            let v303: f32 = v300 - v302;
            let v304: f32 = v284 - v303;
            let v305: f32 = v33 * v304;
            let v306: f32 = v277 + v305;
            let v307: f32 = v121 * v306;
            let v308: f32 = v122 * v192;
            let v309: f32 = v170 * v136;
            let v310: f32 = v122 * v170;
            let v311: f32 = v132 * v310;
            let v312: f32 = v309 - v311;
            let v313: f32 = v308 + v312;
            let v314: f32 = v140 * v221;
            let v315: f32 = v313 - v314;
            let v316: f32 = v172 * v258;
            let v317: f32 = v197 * v181;
            let v318: f32 = v316 - v317;
            let v319: f32 = v177 * v192;
            let v320: f32 = v318 - v319;
            let v321: f32 = v189 * v233;
            let v322: f32 = v186 * v253;
            let v323: f32 = v321 + v322;
            let v324: f32 = v320 + v323;
            let v325: f32 = v315 - v324;
            let v326: f32 = v278 * v221;
            let v327: f32 = v140 * v170;
            let v328: f32 = v132 * v327;
            let v329: f32 = v140 * v192;
            let v330: f32 = v328 - v329;
            let v331: f32 = v326 + v330;
            let v332: f32 = v301 * v228;
            let v333: f32 = v186 * v291;
            let v334: f32 = v189 * v298;
            let v335: f32 = v333 + v334;
            let v336: f32 = v332 + v335;
            let v337: f32 = v161 * v336;
            let v338: f32 = v161 * v226;
            let v339: f32 = v164 * v221;
            let v340: f32 = v338 - v339;
            let v341: f32 = v301 * v340;
            let v342: f32 = v285 * v340;
            let v343: f32 = v237 * v287;
            let v344: f32 = v200 * v295;
            let v345: f32 = v343 + v344;
            let v346: f32 = v342 - v345;
            let v347: f32 = v341 + v346;
            let v348: f32 = v164 * v347;
            let v349: f32 = v337 - v348;
            let v350: f32 = v331 + v349;
            let v351: f32 = v33 * v350;
            let v352: f32 = v325 - v351;
            let v353: f32 = v124 * v352;
            let v354: f32 = v307 + v353;
            let v355: f32 = v119 + v354;
            (
                v226,
                v256,
                v273,
                v274,
                v278,
                v281,
                v304,
                v306,
                v310,
                v324,
                v327,
                v336,
                v347,
                v350,
                v352,
                v355,
            )
        };
        let (v408, v486, v531, v532, v533) = {
            let v356: f32 = 4.8_f32;
            let v357: f32 = v356 * v105;
            let v358: f32 = v89 * v57;
            let v359: f32 = -0.09744_f32;
            let v360: f32 = v359 * v54;
            let v361: f32 = v107 * v65;
            let v362: f32 = v360 - v361;
            let v363: f32 = v65 * v362;
            let v364: f32 = v107 * v70;
            let v365: f32 = v89 * v54;
            let v366: f32 = v364 + v365;
            let v367: f32 = v70 * v366;
            let v368: f32 = v363 - v367;
            let v369: f32 = v358 + v368;
            let v370: f32 = v357 + v369;
            let v371: f32 = v278 * v226;
            let v372: f32 = v127 * v281;
            let v373: f32 = v170 * v327;
            let v374: f32 = v372 + v373;
            let v375: f32 = v371 - v374;
            let v376: f32 = v164 * v336;
            let v377: f32 = v161 * v347;
            let v378: f32 = v376 + v377;
            let v379: f32 = v375 + v378;
            let v380: f32 = v370 + v379;
            let v381: f32 = v96 * v380;
            let v382: f32 = v355 + v381;
            let v383: f32 = v46 * v382;
            let v384: f32 = v59 * v57;
            let v385: f32 = v75 * v67;
            let v386: f32 = v384 - v385;
            let v387: f32 = v65 * v85;
            let v388: f32 = v47 * v65;
            let v389: f32 = v79 * v70;
            let v390: f32 = v388 - v389;
            let v391: f32 = v59 * v54;
            let v392: f32 = v390 + v391;
            let v393: f32 = v70 * v392;
            let v394: f32 = v387 + v393;
            let v395: f32 = v386 + v394;
            let v396: f32 = v359 * v116;
            let v397: f32 = v89 * v149;
            let v398: f32 = v396 + v397;
            let v399: f32 = v395 - v398;
            let v400: f32 = v127 * v310;
            let v401: f32 = v170 * v133;
            let v402: f32 = v400 - v401;
            let v403: f32 = v135 * v67;
            let v404: f32 = v402 - v403;
            let v405: f32 = v164 * v256;
            let v406: f32 = v161 * v274;
            let v407: f32 = v405 + v406;
            let v408: f32 = v404 + v407;
            let v409: f32 = v399 + v408;
            let v410: f32 = v124 * v350;
            let v411: f32 = v121 * v304;
            let v412: f32 = v410 - v411;
            let v413: f32 = v356 * v116;
            let v414: f32 = v359 * v67;
            let v415: f32 = v107 * v57;
            let v416: f32 = v414 + v415;
            let v417: f32 = v54 * v366;
            let v418: f32 = v89 * v65;
            let v419: f32 = v359 * v70;
            let v420: f32 = v418 + v419;
            let v421: f32 = v65 * v420;
            let v422: f32 = v417 + v421;
            let v423: f32 = v416 + v422;
            let v424: f32 = v413 + v423;
            let v425: f32 = v412 - v424;
            let v426: f32 = v98 * v425;
            let v427: f32 = v356 * v149;
            let v428: f32 = v89 * v67;
            let v429: f32 = v70 * v420;
            let v430: f32 = v54 * v362;
            let v431: f32 = v429 + v430;
            let v432: f32 = v428 - v431;
            let v433: f32 = v427 + v432;
            let v434: f32 = v121 * v350;
            let v435: f32 = v124 * v304;
            let v436: f32 = v434 + v435;
            let v437: f32 = v433 + v436;
            let v438: f32 = v96 * v437;
            let v439: f32 = v426 - v438;
            let v440: f32 = v409 + v439;
            let v441: f32 = v49 * v440;
            let v442: f32 = v383 - v441;
            let v443: f32 = v44 + v442;
            let v444: f32 = v1 * v443;
            let v445: f32 = v9 * v7;
            let v446: f32 = v24 * v11;
            let v447: f32 = v445 - v446;
            let v448: f32 = v2 * v10;
            let v449: f32 = v9 * v5;
            let v450: f32 = v448 + v449;
            let v451: f32 = v14 * v6;
            let v452: f32 = v450 + v451;
            let v453: f32 = v6 * v452;
            let v454: f32 = v10 * v21;
            let v455: f32 = v453 - v454;
            let v456: f32 = v447 + v455;
            let v457: f32 = v39 * v92;
            let v458: f32 = -6.33012_f32;
            let v459: f32 = v458 * v37;
            let v460: f32 = v457 + v459;
            let v461: f32 = v456 - v460;
            let v462: f32 = v49 * v382;
            let v463: f32 = v46 * v440;
            let v464: f32 = v462 + v463;
            let v465: f32 = v461 + v464;
            let v466: f32 = 17.4_f32;
            let v467: f32 = v466 * v37;
            let v468: f32 = v32 * v7;
            let v469: f32 = v458 * v11;
            let v470: f32 = v468 + v469;
            let v471: f32 = v458 * v6;
            let v472: f32 = v39 * v10;
            let v473: f32 = v471 - v472;
            let v474: f32 = v10 * v473;
            let v475: f32 = v39 * v5;
            let v476: f32 = v32 * v6;
            let v477: f32 = v475 - v476;
            let v478: f32 = v5 * v477;
            let v479: f32 = v474 - v478;
            let v480: f32 = v470 + v479;
            let v481: f32 = v467 + v480;
            let v482: f32 = v481 - v425;
            let v483: f32 = v33 * v482;
            let v484: f32 = v465 - v483;
            let v485: f32 = v3 * v484;
            let v486: f32 = v444 + v485;
            let v487: f32 = v14 * v7;
            let v488: f32 = v16 * v11;
            let v489: f32 = v487 - v488;
            let v490: f32 = v10 * v28;
            let v491: f32 = v5 * v452;
            let v492: f32 = v490 - v491;
            let v493: f32 = v489 + v492;
            let v494: f32 = v458 * v41;
            let v495: f32 = v32 * v92;
            let v496: f32 = v494 + v495;
            let v497: f32 = v493 + v496;
            let v498: f32 = v79 * v57;
            let v499: f32 = v72 * v67;
            let v500: f32 = v498 - v499;
            let v501: f32 = v54 * v392;
            let v502: f32 = v65 * v77;
            let v503: f32 = v501 - v502;
            let v504: f32 = v500 + v503;
            let v505: f32 = v107 * v149;
            let v506: f32 = v359 * v105;
            let v507: f32 = v505 - v506;
            let v508: f32 = v504 + v507;
            let v509: f32 = v124 * v306;
            let v510: f32 = v121 * v352;
            let v511: f32 = v509 - v510;
            let v512: f32 = v508 + v511;
            let v513: f32 = v98 * v380;
            let v514: f32 = v512 - v513;
            let v515: f32 = v497 - v514;
            let v516: f32 = v466 * v41;
            let v517: f32 = v6 * v477;
            let v518: f32 = v32 * v10;
            let v519: f32 = v458 * v5;
            let v520: f32 = v518 - v519;
            let v521: f32 = v10 * v520;
            let v522: f32 = v517 - v521;
            let v523: f32 = v39 * v7;
            let v524: f32 = v522 - v523;
            let v525: f32 = v516 + v524;
            let v526: f32 = v49 * v437;
            let v527: f32 = v46 * v380;
            let v528: f32 = v526 + v527;
            let v529: f32 = v525 + v528;
            let v530: f32 = v33 * v529;
            let v531: f32 = v515 + v530;
            let v532: f32 = -v514;
            let v533: f32 = -v324;
            (v408, v486, v531, v532, v533)
        };
        [v486, v531, v532, v408, v533, v273]
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
    pub fn gravity(q: &[f32; 6]) -> [f32; 6] {
        let v0: f32 = 0.0_f32;
        let v1: f32 = 37.234737_f32;
        let v2: f32 = 0.24892876_f32;
        let v3: f32 = 0.0282528_f32;
        let v4: f32 = q[4];
        let (v5, v16): (f32, f32) = ::libm::sincosf(v4);
        let v6: f32 = v3 * v5;
        let v7: f32 = q[3];
        let (v46, v8): (f32, f32) = ::libm::sincosf(v7);
        let v9: f32 = v6 * v8;
        let v10: f32 = v2 - v9;
        let v11: f32 = q[2];
        let (v19, v12): (f32, f32) = ::libm::sincosf(v11);
        let v13: f32 = v10 * v12;
        let v14: f32 = v1 + v13;
        let v15: f32 = -8.743947_f32;
        let v17: f32 = v3 * v16;
        let v18: f32 = v15 - v17;
        let v20: f32 = v18 * v19;
        let v21: f32 = v14 + v20;
        let v22: f32 = q[1];
        let (v32, v23): (f32, f32) = ::libm::sincosf(v22);
        let v24: f32 = v21 * v23;
        let v25: f32 = -1.024164_f32;
        let v26: f32 = v18 * v12;
        let v27: f32 = v25 + v26;
        let v28: f32 = -0.24892876_f32;
        let v29: f32 = v28 + v9;
        let v30: f32 = v29 * v19;
        let v31: f32 = v27 + v30;
        let v33: f32 = v31 * v32;
        let v34: f32 = v24 + v33;
        let v35: f32 = v13 + v20;
        let v36: f32 = v35 * v23;
        let v37: f32 = v26 + v30;
        let v38: f32 = v37 * v32;
        let v39: f32 = v36 + v38;
        let v40: f32 = v3 * v19;
        let v41: f32 = v40 * v23;
        let v42: f32 = v3 * v12;
        let v43: f32 = v42 * v32;
        let v44: f32 = v41 + v43;
        let v45: f32 = v44 * v5;
        let v47: f32 = v45 * v46;
        let v48: f32 = v6 * v19;
        let v49: f32 = v17 * v8;
        let v50: f32 = v49 * v12;
        let v51: f32 = v48 - v50;
        let v52: f32 = v51 * v32;
        let v53: f32 = v6 * v12;
        let v54: f32 = v49 * v19;
        let v55: f32 = v53 + v54;
        let v56: f32 = v55 * v23;
        let v57: f32 = v52 - v56;
        [v0, v34, v39, v47, v57, v0]
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
    /// Operation count: 519 floating-point operations, 10 trig calls.
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
            v7,
            v9,
            v10,
            v12,
            v14,
            v16,
            v18,
            v21,
            v22,
            v26,
            v29,
            v31,
            v34,
            v38,
            v42,
            v43,
            v47,
            v49,
            v56,
            v59,
            v61,
            v62,
            v64,
            v69,
            v72,
            v74,
            v76,
            v79,
            v85,
            v87,
            v90,
            v92,
            v95,
            v97,
            v100,
            v104,
            v108,
            v114,
            v117,
            v119,
            v128,
            v130,
            v139,
            v142,
            v144,
            v145,
            v147,
            v152,
            v153,
            v155,
            v157,
            v158,
            v160,
            v161,
            v165,
            v174,
            v179,
            v182,
            v184,
            v186,
            v187,
            v189,
            v191,
            v193,
        ) = {
            let v0: f32 = 0.35_f32;
            let v1: f32 = qdd[0];
            let v2: f32 = v0 * v1;
            let v3: f32 = q[1];
            let (v4, v7): (f32, f32) = ::libm::sincosf(v3);
            let v5: f32 = 1.0311852_f32;
            let v6: f32 = v4 * v1;
            let v8: f32 = qd[0];
            let v9: f32 = v7 * v8;
            let v10: f32 = qd[1];
            let v11: f32 = v9 * v10;
            let v12: f32 = v6 + v11;
            let v13: f32 = v5 * v12;
            let v14: f32 = 0.03798072_f32;
            let v15: f32 = v7 * v1;
            let v16: f32 = v4 * v8;
            let v17: f32 = v16 * v10;
            let v18: f32 = v15 - v17;
            let v19: f32 = v14 * v18;
            let v20: f32 = v13 + v19;
            let v21: f32 = 1.4401023_f32;
            let v22: f32 = qdd[1];
            let v23: f32 = v21 * v22;
            let v24: f32 = v20 + v23;
            let v25: f32 = v21 * v16;
            let v26: f32 = -0.023751_f32;
            let v27: f32 = v26 * v9;
            let v28: f32 = v25 + v27;
            let v29: f32 = 2.842524_f32;
            let v30: f32 = v29 * v10;
            let v31: f32 = v28 + v30;
            let v32: f32 = v9 * v31;
            let v33: f32 = v14 * v16;
            let v34: f32 = 3.7274563_f32;
            let v35: f32 = v34 * v9;
            let v36: f32 = v33 + v35;
            let v37: f32 = v26 * v10;
            let v38: f32 = v36 + v37;
            let v39: f32 = v10 * v38;
            let v40: f32 = v32 - v39;
            let v41: f32 = v24 + v40;
            let v42: f32 = 0.1044_f32;
            let v43: f32 = 0.4318_f32;
            let v44: f32 = v43 * v10;
            let v45: f32 = v16 * v44;
            let v46: f32 = v43 * v18;
            let v47: f32 = v45 - v46;
            let v48: f32 = v42 * v47;
            let v49: f32 = 3.9585_f32;
            let v50: f32 = 9.81_f32;
            let v51: f32 = v50 * v7;
            let v52: f32 = v43 * v22;
            let v53: f32 = v43 * v9;
            let v54: f32 = v16 * v53;
            let v55: f32 = v52 + v54;
            let v56: f32 = v51 + v55;
            let v57: f32 = v49 * v56;
            let v58: f32 = v48 - v57;
            let v59: f32 = v41 + v58;
            let v60: f32 = q[2];
            let (v64, v61): (f32, f32) = ::libm::sincosf(v60);
            let v62: f32 = 0.090474285_f32;
            let v63: f32 = v61 * v12;
            let v65: f32 = v64 * v18;
            let v66: f32 = v63 + v65;
            let v67: f32 = v61 * v9;
            let v68: f32 = v64 * v16;
            let v69: f32 = v67 - v68;
            let v70: f32 = qd[2];
            let v71: f32 = v69 * v70;
            let v72: f32 = v66 + v71;
            let v73: f32 = v62 * v72;
            let v74: f32 = -0.001373904_f32;
            let v75: f32 = qdd[2];
            let v76: f32 = v22 + v75;
            let v77: f32 = v74 * v76;
            let v78: f32 = v73 - v77;
            let v79: f32 = 0.0068208_f32;
            let v80: f32 = v61 * v18;
            let v81: f32 = v64 * v12;
            let v82: f32 = v80 - v81;
            let v83: f32 = v61 * v16;
            let v84: f32 = v64 * v9;
            let v85: f32 = v83 + v84;
            let v86: f32 = v85 * v70;
            let v87: f32 = v82 - v86;
            let v88: f32 = v79 * v87;
            let v89: f32 = v78 + v88;
            let v90: f32 = v10 + v70;
            let v91: f32 = v79 * v85;
            let v92: f32 = 0.0047376_f32;
            let v93: f32 = v92 * v90;
            let v94: f32 = v91 - v93;
            let v95: f32 = 0.01543232_f32;
            let v96: f32 = v95 * v69;
            let v97: f32 = v94 + v96;
            let v98: f32 = v90 * v97;
            let v99: f32 = v74 * v85;
            let v100: f32 = 0.111498035_f32;
            let v101: f32 = v100 * v90;
            let v102: f32 = v99 - v101;
            let v103: f32 = v92 * v69;
            let v104: f32 = v102 + v103;
            let v105: f32 = v69 * v104;
            let v106: f32 = v98 + v105;
            let v107: f32 = v89 - v106;
            let v108: f32 = -0.06768_f32;
            let v109: f32 = v61 * v56;
            let v110: f32 = v50 * v4;
            let v111: f32 = v9 * v53;
            let v112: f32 = v10 * v44;
            let v113: f32 = v111 + v112;
            let v114: f32 = v110 - v113;
            let v115: f32 = v64 * v114;
            let v116: f32 = v109 - v115;
            let v117: f32 = -0.15005_f32;
            let v118: f32 = v117 * v72;
            let v119: f32 = 0.0203_f32;
            let v120: f32 = v119 * v76;
            let v121: f32 = v118 + v120;
            let v122: f32 = v119 * v69;
            let v123: f32 = v85 * v122;
            let v124: f32 = v117 * v69;
            let v125: f32 = v90 * v124;
            let v126: f32 = v123 - v125;
            let v127: f32 = v121 + v126;
            let v128: f32 = v116 + v127;
            let v129: f32 = v108 * v128;
            let v130: f32 = 0.336_f32;
            let v131: f32 = v119 * v87;
            let v132: f32 = v69 * v124;
            let v133: f32 = v117 * v85;
            let v134: f32 = v119 * v90;
            let v135: f32 = v133 + v134;
            let v136: f32 = v85 * v135;
            let v137: f32 = v132 + v136;
            let v138: f32 = v131 - v137;
            let v139: f32 = v138 - v47;
            let v140: f32 = v130 * v139;
            let v141: f32 = v129 - v140;
            let v142: f32 = v107 + v141;
            let v143: f32 = q[3];
            let (v147, v144): (f32, f32) = ::libm::sincosf(v143);
            let v145: f32 = 0.00209602_f32;
            let v146: f32 = v144 * v72;
            let v148: f32 = v147 * v76;
            let v149: f32 = v146 - v148;
            let v150: f32 = v147 * v85;
            let v151: f32 = v144 * v90;
            let v152: f32 = v150 + v151;
            let v153: f32 = qd[3];
            let v154: f32 = v152 * v153;
            let v155: f32 = v149 - v154;
            let v156: f32 = v145 * v155;
            let v157: f32 = v69 + v153;
            let v158: f32 = v145 * v152;
            let v159: f32 = v157 * v158;
            let v160: f32 = 0.0013_f32;
            let v161: f32 = v160 * v157;
            let v162: f32 = v152 * v161;
            let v163: f32 = v159 - v162;
            let v164: f32 = v156 + v163;
            let v165: f32 = 0.01558_f32;
            let v166: f32 = v61 * v114;
            let v167: f32 = v64 * v56;
            let v168: f32 = v166 + v167;
            let v169: f32 = v117 * v87;
            let v170: f32 = v90 * v135;
            let v171: f32 = v69 * v122;
            let v172: f32 = v170 + v171;
            let v173: f32 = v169 + v172;
            let v174: f32 = v168 - v173;
            let v175: f32 = v147 * v174;
            let v176: f32 = v144 * v139;
            let v177: f32 = v175 - v176;
            let v178: f32 = v43 * v155;
            let v179: f32 = v43 * v152;
            let v180: f32 = v157 * v179;
            let v181: f32 = v178 + v180;
            let v182: f32 = v177 + v181;
            let v183: f32 = v165 * v182;
            let v184: f32 = v164 + v183;
            let v185: f32 = q[4];
            let (v189, v186): (f32, f32) = ::libm::sincosf(v185);
            let v187: f32 = 0.0003_f32;
            let v188: f32 = v186 * v155;
            let v190: f32 = qdd[3];
            let v191: f32 = v87 + v190;
            let v192: f32 = v189 * v191;
            let v193: f32 = v188 + v192;
            (
                v2,
                v4,
                v5,
                v7,
                v9,
                v10,
                v12,
                v14,
                v16,
                v18,
                v21,
                v22,
                v26,
                v29,
                v31,
                v34,
                v38,
                v42,
                v43,
                v47,
                v49,
                v56,
                v59,
                v61,
                v62,
                v64,
                v69,
                v72,
                v74,
                v76,
                v79,
                v85,
                v87,
                v90,
                v92,
                v95,
                v97,
                v100,
                v104,
                v108,
                v114,
                v117,
                v119,
                v128,
                v130,
                v139,
                v142,
                v144,
                v145,
                v147,
                v152,
                v153,
                v155,
                v157,
                v158,
                v160,
                v161,
                v165,
                v174,
                v179,
                v182,
                v184,
                v186,
                v187,
                v189,
                v191,
                v193,
            )
        };
        let (
            v197,
            v257,
            v287,
            v306,
            v307,
            v311,
            v314,
            v337,
            v339,
            v343,
            v357,
            v360,
            v369,
            v380,
            v383,
            v385,
            v387,
        ) = {
            let v194: f32 = v186 * v157;
            let v195: f32 = v144 * v85;
            let v196: f32 = v147 * v90;
            let v197: f32 = v195 - v196;
            let v198: f32 = v189 * v197;
            let v199: f32 = v194 - v198;
            let v200: f32 = qd[4];
            let v201: f32 = v199 * v200;
            let v202: f32 = v193 + v201;
            let v203: f32 = v187 * v202;
            let v204: f32 = 0.0004_f32;
            let v205: f32 = v152 + v200;
            let v206: f32 = v204 * v205;
            let v207: f32 = v199 * v206;
            let v208: f32 = v187 * v199;
            let v209: f32 = v205 * v208;
            let v210: f32 = v207 - v209;
            let v211: f32 = v203 + v210;
            let v212: f32 = q[5];
            let (v216, v213): (f32, f32) = ::libm::sincosf(v212);
            let v214: f32 = 0.00024216_f32;
            let v215: f32 = v213 * v202;
            let v217: f32 = v147 * v72;
            let v218: f32 = v144 * v76;
            let v219: f32 = v217 + v218;
            let v220: f32 = v197 * v153;
            let v221: f32 = v219 + v220;
            let v222: f32 = qdd[4];
            let v223: f32 = v221 + v222;
            let v224: f32 = v216 * v223;
            let v225: f32 = v215 - v224;
            let v226: f32 = v186 * v197;
            let v227: f32 = v189 * v157;
            let v228: f32 = v226 + v227;
            let v229: f32 = v216 * v228;
            let v230: f32 = v213 * v205;
            let v231: f32 = v229 + v230;
            let v232: f32 = qd[5];
            let v233: f32 = v231 * v232;
            let v234: f32 = v225 - v233;
            let v235: f32 = v214 * v234;
            let v236: f32 = v199 + v232;
            let v237: f32 = v214 * v231;
            let v238: f32 = v236 * v237;
            let v239: f32 = 4e-5_f32;
            let v240: f32 = v239 * v236;
            let v241: f32 = v231 * v240;
            let v242: f32 = v238 - v241;
            let v243: f32 = v235 + v242;
            let v244: f32 = 0.00288_f32;
            let v245: f32 = v144 * v174;
            let v246: f32 = v147 * v139;
            let v247: f32 = v245 + v246;
            let v248: f32 = v43 * v197;
            let v249: f32 = v157 * v248;
            let v250: f32 = v43 * v221;
            let v251: f32 = v249 - v250;
            let v252: f32 = v247 + v251;
            let v253: f32 = v186 * v252;
            let v254: f32 = v152 * v179;
            let v255: f32 = v197 * v248;
            let v256: f32 = v254 + v255;
            let v257: f32 = v128 - v256;
            let v258: f32 = v189 * v257;
            let v259: f32 = v253 + v258;
            let v260: f32 = v216 * v259;
            let v261: f32 = v213 * v182;
            let v262: f32 = v260 + v261;
            let v263: f32 = v244 * v262;
            let v264: f32 = v243 + v263;
            let v265: f32 = v213 * v264;
            let v266: f32 = v213 * v228;
            let v267: f32 = v216 * v205;
            let v268: f32 = v266 - v267;
            let v269: f32 = v214 * v268;
            let v270: f32 = v236 * v269;
            let v271: f32 = v268 * v240;
            let v272: f32 = v270 - v271;
            let v273: f32 = v216 * v202;
            let v274: f32 = v213 * v223;
            let v275: f32 = v273 + v274;
            let v276: f32 = v268 * v232;
            let v277: f32 = v275 + v276;
            let v278: f32 = v214 * v277;
            let v279: f32 = v272 - v278;
            let v280: f32 = v213 * v259;
            let v281: f32 = v216 * v182;
            let v282: f32 = v280 - v281;
            let v283: f32 = v244 * v282;
            let v284: f32 = v279 + v283;
            let v285: f32 = v216 * v284;
            let v286: f32 = v265 - v285;
            let v287: f32 = v211 + v286;
            let v288: f32 = v186 * v287;
            let v289: f32 = v186 * v191;
            let v290: f32 = v189 * v155;
            let v291: f32 = v289 - v290;
            let v292: f32 = v228 * v200;
            let v293: f32 = v291 - v292;
            let v294: f32 = v187 * v293;
            let v295: f32 = v187 * v228;
            let v296: f32 = v205 * v295;
            let v297: f32 = v228 * v206;
            let v298: f32 = v296 - v297;
            let v299: f32 = v294 + v298;
            let v300: f32 = qdd[5];
            let v301: f32 = v293 + v300;
            let v302: f32 = v239 * v301;
            let v303: f32 = v231 * v269;
            let v304: f32 = v268 * v237;
            let v305: f32 = v303 - v304;
            let v306: f32 = v302 + v305;
            let v307: f32 = v299 + v306;
            let v308: f32 = v189 * v307;
            let v309: f32 = v288 - v308;
            let v310: f32 = v184 + v309;
            let v311: f32 = 0.82_f32;
            let v312: f32 = v311 * v182;
            let v313: f32 = v165 * v155;
            let v314: f32 = v165 * v152;
            let v315: f32 = v157 * v314;
            let v316: f32 = v313 + v315;
            let v317: f32 = v312 + v316;
            let v318: f32 = 0.09_f32;
            let v319: f32 = v318 * v282;
            let v320: f32 = v244 * v268;
            let v321: f32 = v236 * v320;
            let v322: f32 = v244 * v277;
            let v323: f32 = v321 - v322;
            let v324: f32 = v319 + v323;
            let v325: f32 = v216 * v324;
            let v326: f32 = v318 * v262;
            let v327: f32 = v244 * v234;
            let v328: f32 = v244 * v231;
            let v329: f32 = v236 * v328;
            let v330: f32 = v327 + v329;
            let v331: f32 = v326 + v330;
            let v332: f32 = v213 * v331;
            let v333: f32 = v325 - v332;
            let v334: f32 = 0.34_f32;
            let v335: f32 = v334 * v182;
            let v336: f32 = v333 - v335;
            let v337: f32 = v317 - v336;
            let v338: f32 = v43 * v337;
            let v339: f32 = v310 + v338;
            let v340: f32 = v144 * v339;
            let v341: f32 = v145 * v221;
            let v342: f32 = v197 * v161;
            let v343: f32 = v145 * v197;
            let v344: f32 = v157 * v343;
            let v345: f32 = v342 - v344;
            let v346: f32 = v341 + v345;
            let v347: f32 = v165 * v252;
            let v348: f32 = v346 - v347;
            let v349: f32 = v199 * v295;
            let v350: f32 = v228 * v208;
            let v351: f32 = v349 - v350;
            let v352: f32 = v204 * v223;
            let v353: f32 = v351 - v352;
            let v354: f32 = v216 * v264;
            let v355: f32 = v213 * v284;
            let v356: f32 = v354 + v355;
            let v357: f32 = v353 + v356;
            let v358: f32 = v348 - v357;
            let v359: f32 = v311 * v252;
            let v360: f32 = v165 * v197;
            let v361: f32 = v157 * v360;
            let v362: f32 = v165 * v221;
            let v363: f32 = v361 - v362;
            let v364: f32 = v359 + v363;
            let v365: f32 = v334 * v259;
            let v366: f32 = v213 * v324;
            let v367: f32 = v216 * v331;
            let v368: f32 = v366 + v367;
            let v369: f32 = v365 + v368;
            let v370: f32 = v186 * v369;
            let v371: f32 = v186 * v257;
            let v372: f32 = v189 * v252;
            let v373: f32 = v371 - v372;
            let v374: f32 = v334 * v373;
            let v375: f32 = v318 * v373;
            let v376: f32 = v268 * v320;
            let v377: f32 = v231 * v328;
            let v378: f32 = v376 + v377;
            let v379: f32 = v375 - v378;
            let v380: f32 = v374 + v379;
            let v381: f32 = v189 * v380;
            let v382: f32 = v370 - v381;
            let v383: f32 = v364 + v382;
            let v384: f32 = v43 * v383;
            let v385: f32 = v358 - v384;
            let v386: f32 = v147 * v385;
            let v387: f32 = v340 + v386;
            (
                v197,
                v257,
                v287,
                v306,
                v307,
                v311,
                v314,
                v337,
                v339,
                v343,
                v357,
                v360,
                v369,
                v380,
                v383,
                v385,
                v387,
            )
        };
        let (v445, v528, v579, v580, v581) = {
            let v388: f32 = v142 + v387;
            let v389: f32 = 4.8_f32;
            let v390: f32 = v389 * v128;
            let v391: f32 = v108 * v72;
            let v392: f32 = -0.09744_f32;
            let v393: f32 = v392 * v76;
            let v394: f32 = v391 + v393;
            let v395: f32 = v392 * v69;
            let v396: f32 = v130 * v85;
            let v397: f32 = v395 - v396;
            let v398: f32 = v85 * v397;
            let v399: f32 = v130 * v90;
            let v400: f32 = v108 * v69;
            let v401: f32 = v399 + v400;
            let v402: f32 = v90 * v401;
            let v403: f32 = v398 - v402;
            let v404: f32 = v394 + v403;
            let v405: f32 = v390 + v404;
            let v406: f32 = v311 * v257;
            let v407: f32 = v152 * v314;
            let v408: f32 = v197 * v360;
            let v409: f32 = v407 + v408;
            let v410: f32 = v406 - v409;
            let v411: f32 = v189 * v369;
            let v412: f32 = v186 * v380;
            let v413: f32 = v411 + v412;
            let v414: f32 = v410 + v413;
            let v415: f32 = v405 + v414;
            let v416: f32 = v117 * v415;
            let v417: f32 = v388 + v416;
            let v418: f32 = v61 * v417;
            let v419: f32 = v79 * v72;
            let v420: f32 = v92 * v76;
            let v421: f32 = v419 - v420;
            let v422: f32 = v95 * v87;
            let v423: f32 = v421 + v422;
            let v424: f32 = v85 * v104;
            let v425: f32 = v62 * v85;
            let v426: f32 = v74 * v90;
            let v427: f32 = v425 - v426;
            let v428: f32 = v79 * v69;
            let v429: f32 = v427 + v428;
            let v430: f32 = v90 * v429;
            let v431: f32 = v424 + v430;
            let v432: f32 = v423 + v431;
            let v433: f32 = v392 * v139;
            let v434: f32 = v108 * v174;
            let v435: f32 = v433 - v434;
            let v436: f32 = v432 + v435;
            let v437: f32 = v160 * v191;
            let v438: f32 = v152 * v343;
            let v439: f32 = v197 * v158;
            let v440: f32 = v438 - v439;
            let v441: f32 = v437 + v440;
            let v442: f32 = v189 * v287;
            let v443: f32 = v186 * v307;
            let v444: f32 = v442 + v443;
            let v445: f32 = v441 + v444;
            let v446: f32 = v436 + v445;
            let v447: f32 = v389 * v139;
            let v448: f32 = v392 * v87;
            let v449: f32 = v130 * v72;
            let v450: f32 = v448 - v449;
            let v451: f32 = v69 * v401;
            let v452: f32 = v108 * v85;
            let v453: f32 = v392 * v90;
            let v454: f32 = v452 + v453;
            let v455: f32 = v85 * v454;
            let v456: f32 = v451 + v455;
            let v457: f32 = v450 - v456;
            let v458: f32 = v447 + v457;
            let v459: f32 = v147 * v383;
            let v460: f32 = v144 * v337;
            let v461: f32 = v459 - v460;
            let v462: f32 = v458 + v461;
            let v463: f32 = v119 * v462;
            let v464: f32 = v389 * v174;
            let v465: f32 = v130 * v76;
            let v466: f32 = v108 * v87;
            let v467: f32 = v465 + v466;
            let v468: f32 = v90 * v454;
            let v469: f32 = v69 * v397;
            let v470: f32 = v468 + v469;
            let v471: f32 = v467 + v470;
            let v472: f32 = v464 - v471;
            let v473: f32 = v144 * v383;
            let v474: f32 = v147 * v337;
            let v475: f32 = v473 + v474;
            let v476: f32 = v472 + v475;
            let v477: f32 = v117 * v476;
            let v478: f32 = v463 - v477;
            let v479: f32 = v446 + v478;
            let v480: f32 = v64 * v479;
            let v481: f32 = v418 - v480;
            let v482: f32 = v59 + v481;
            let v483: f32 = v4 * v482;
            let v484: f32 = v14 * v12;
            let v485: f32 = v34 * v18;
            let v486: f32 = v484 + v485;
            let v487: f32 = v26 * v22;
            let v488: f32 = v486 + v487;
            let v489: f32 = v5 * v16;
            let v490: f32 = v14 * v9;
            let v491: f32 = v489 + v490;
            let v492: f32 = v21 * v10;
            let v493: f32 = v491 + v492;
            let v494: f32 = v10 * v493;
            let v495: f32 = v16 * v31;
            let v496: f32 = v494 - v495;
            let v497: f32 = v488 + v496;
            let v498: f32 = v49 * v114;
            let v499: f32 = -6.33012_f32;
            let v500: f32 = v499 * v47;
            let v501: f32 = v498 - v500;
            let v502: f32 = v497 + v501;
            let v503: f32 = v64 * v417;
            let v504: f32 = v61 * v479;
            let v505: f32 = v503 + v504;
            let v506: f32 = v502 + v505;
            let v507: f32 = 17.4_f32;
            let v508: f32 = v507 * v47;
            let v509: f32 = v42 * v12;
            let v510: f32 = v499 * v18;
            let v511: f32 = v509 - v510;
            let v512: f32 = v499 * v10;
            let v513: f32 = v49 * v16;
            let v514: f32 = v512 - v513;
            let v515: f32 = v16 * v514;
            let v516: f32 = v49 * v9;
            let v517: f32 = v42 * v10;
            let v518: f32 = v516 - v517;
            let v519: f32 = v9 * v518;
            let v520: f32 = v515 - v519;
            let v521: f32 = v511 + v520;
            let v522: f32 = v508 + v521;
            let v523: f32 = v522 - v462;
            let v524: f32 = v43 * v523;
            let v525: f32 = v506 - v524;
            let v526: f32 = v7 * v525;
            let v527: f32 = v483 + v526;
            let v528: f32 = v2 + v527;
            let v529: f32 = v21 * v12;
            let v530: f32 = v26 * v18;
            let v531: f32 = v529 + v530;
            let v532: f32 = v29 * v22;
            let v533: f32 = v531 + v532;
            let v534: f32 = v16 * v38;
            let v535: f32 = v9 * v493;
            let v536: f32 = v534 - v535;
            let v537: f32 = v533 + v536;
            let v538: f32 = v499 * v56;
            let v539: f32 = v42 * v114;
            let v540: f32 = v538 - v539;
            let v541: f32 = v537 + v540;
            let v542: f32 = v74 * v72;
            let v543: f32 = v100 * v76;
            let v544: f32 = v542 - v543;
            let v545: f32 = v92 * v87;
            let v546: f32 = v544 + v545;
            let v547: f32 = v69 * v429;
            let v548: f32 = v85 * v97;
            let v549: f32 = v547 - v548;
            let v550: f32 = v546 + v549;
            let v551: f32 = v130 * v174;
            let v552: f32 = v392 * v128;
            let v553: f32 = v551 - v552;
            let v554: f32 = v550 + v553;
            let v555: f32 = v147 * v339;
            let v556: f32 = v144 * v385;
            let v557: f32 = v555 - v556;
            let v558: f32 = v554 + v557;
            let v559: f32 = v119 * v415;
            let v560: f32 = v558 - v559;
            let v561: f32 = v541 - v560;
            let v562: f32 = v507 * v56;
            let v563: f32 = v499 * v22;
            let v564: f32 = v49 * v12;
            let v565: f32 = v563 - v564;
            let v566: f32 = v10 * v518;
            let v567: f32 = v42 * v16;
            let v568: f32 = v499 * v9;
            let v569: f32 = v567 - v568;
            let v570: f32 = v16 * v569;
            let v571: f32 = v566 - v570;
            let v572: f32 = v565 + v571;
            let v573: f32 = v562 + v572;
            let v574: f32 = v64 * v476;
            let v575: f32 = v61 * v415;
            let v576: f32 = v574 + v575;
            let v577: f32 = v573 + v576;
            let v578: f32 = v43 * v577;
            let v579: f32 = v561 + v578;
            let v580: f32 = -v560;
            let v581: f32 = -v357;
            (v445, v528, v579, v580, v581)
        };
        [v528, v579, v580, v445, v581, v306]
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
    /// Operation count: 867 floating-point operations, 10 trig calls.
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
            v11,
            v12,
            v15,
            v17,
            v22,
            v25,
            v29,
            v33,
            v34,
            v38,
            v40,
            v45,
            v48,
            v50,
            v51,
            v53,
            v58,
            v61,
            v63,
            v69,
            v71,
            v74,
            v76,
            v79,
            v81,
            v83,
            v89,
            v93,
            v99,
            v102,
            v104,
            v111,
            v113,
            v122,
            v125,
            v127,
            v128,
            v130,
            v133,
            v134,
            v136,
            v138,
            v139,
            v141,
            v142,
            v146,
            v155,
            v160,
            v163,
            v165,
            v167,
            v168,
            v170,
            v176,
            v178,
            v179,
            v181,
            v183,
            v184,
            v185,
            v187,
            v190,
            v192,
            v193,
            v194,
            v195,
        ) = {
            let v0: f32 = tau[0];
            let v1: f32 = q[1];
            let (v2, v4): (f32, f32) = ::libm::sincosf(v1);
            let v3: f32 = 1.0311852_f32;
            let v5: f32 = qd[0];
            let v6: f32 = v4 * v5;
            let v7: f32 = qd[1];
            let v8: f32 = v6 * v7;
            let v9: f32 = v3 * v8;
            let v10: f32 = 0.03798072_f32;
            let v11: f32 = v2 * v5;
            let v12: f32 = v11 * v7;
            let v13: f32 = v10 * v12;
            let v14: f32 = v9 - v13;
            let v15: f32 = 1.4401023_f32;
            let v16: f32 = v15 * v11;
            let v17: f32 = -0.023751_f32;
            let v18: f32 = v17 * v6;
            let v19: f32 = v16 + v18;
            let v20: f32 = 2.842524_f32;
            let v21: f32 = v20 * v7;
            let v22: f32 = v19 + v21;
            let v23: f32 = v6 * v22;
            let v24: f32 = v10 * v11;
            let v25: f32 = 3.7274563_f32;
            let v26: f32 = v25 * v6;
            let v27: f32 = v24 + v26;
            let v28: f32 = v17 * v7;
            let v29: f32 = v27 + v28;
            let v30: f32 = v7 * v29;
            let v31: f32 = v23 - v30;
            let v32: f32 = v14 + v31;
            let v33: f32 = 0.1044_f32;
            let v34: f32 = 0.4318_f32;
            let v35: f32 = v34 * v12;
            let v36: f32 = v34 * v7;
            let v37: f32 = v11 * v36;
            let v38: f32 = v35 + v37;
            let v39: f32 = v33 * v38;
            let v40: f32 = 3.9585_f32;
            let v41: f32 = 9.81_f32;
            let v42: f32 = v41 * v4;
            let v43: f32 = v34 * v6;
            let v44: f32 = v11 * v43;
            let v45: f32 = v42 + v44;
            let v46: f32 = v40 * v45;
            let v47: f32 = v39 - v46;
            let v48: f32 = v32 + v47;
            let v49: f32 = q[2];
            let (v53, v50): (f32, f32) = ::libm::sincosf(v49);
            let v51: f32 = 0.090474285_f32;
            let v52: f32 = v50 * v8;
            let v54: f32 = v53 * v12;
            let v55: f32 = v52 - v54;
            let v56: f32 = v50 * v6;
            let v57: f32 = v53 * v11;
            let v58: f32 = v56 - v57;
            let v59: f32 = qd[2];
            let v60: f32 = v58 * v59;
            let v61: f32 = v55 + v60;
            let v62: f32 = v51 * v61;
            let v63: f32 = 0.0068208_f32;
            let v64: f32 = v53 * v8;
            let v65: f32 = v50 * v12;
            let v66: f32 = v64 + v65;
            let v67: f32 = v50 * v11;
            let v68: f32 = v53 * v6;
            let v69: f32 = v67 + v68;
            let v70: f32 = v69 * v59;
            let v71: f32 = v66 + v70;
            let v72: f32 = v63 * v71;
            let v73: f32 = v62 - v72;
            let v74: f32 = v7 + v59;
            let v75: f32 = v63 * v69;
            let v76: f32 = 0.0047376_f32;
            let v77: f32 = v76 * v74;
            let v78: f32 = v75 - v77;
            let v79: f32 = 0.01543232_f32;
            let v80: f32 = v79 * v58;
            let v81: f32 = v78 + v80;
            let v82: f32 = v74 * v81;
            let v83: f32 = -0.001373904_f32;
            let v84: f32 = v83 * v69;
            let v85: f32 = 0.111498035_f32;
            let v86: f32 = v85 * v74;
            let v87: f32 = v84 - v86;
            let v88: f32 = v76 * v58;
            let v89: f32 = v87 + v88;
            let v90: f32 = v58 * v89;
            let v91: f32 = v82 + v90;
            let v92: f32 = v73 - v91;
            let v93: f32 = -0.06768_f32;
            let v94: f32 = v50 * v45;
            let v95: f32 = v41 * v2;
            let v96: f32 = v6 * v43;
            let v97: f32 = v7 * v36;
            let v98: f32 = v96 + v97;
            let v99: f32 = v95 - v98;
            let v100: f32 = v53 * v99;
            let v101: f32 = v94 - v100;
            let v102: f32 = -0.15005_f32;
            let v103: f32 = v102 * v61;
            let v104: f32 = 0.0203_f32;
            let v105: f32 = v104 * v58;
            let v106: f32 = v69 * v105;
            let v107: f32 = v102 * v58;
            let v108: f32 = v74 * v107;
            let v109: f32 = v106 - v108;
            let v110: f32 = v103 + v109;
            let v111: f32 = v101 + v110;
            let v112: f32 = v93 * v111;
            let v113: f32 = 0.336_f32;
            let v114: f32 = v104 * v71;
            let v115: f32 = v58 * v107;
            let v116: f32 = v102 * v69;
            let v117: f32 = v104 * v74;
            let v118: f32 = v116 + v117;
            let v119: f32 = v69 * v118;
            let v120: f32 = v115 + v119;
            let v121: f32 = v114 + v120;
            let v122: f32 = v38 + v121;
            let v123: f32 = v113 * v122;
            let v124: f32 = v112 + v123;
            let v125: f32 = v92 + v124;
            let v126: f32 = q[3];
            let (v130, v127): (f32, f32) = ::libm::sincosf(v126);
            let v128: f32 = 0.00209602_f32;
            let v129: f32 = v127 * v61;
            let v131: f32 = v130 * v69;
            let v132: f32 = v127 * v74;
            let v133: f32 = v131 + v132;
            let v134: f32 = qd[3];
            let v135: f32 = v133 * v134;
            let v136: f32 = v129 - v135;
            let v137: f32 = v128 * v136;
            let v138: f32 = v58 + v134;
            let v139: f32 = v128 * v133;
            let v140: f32 = v138 * v139;
            let v141: f32 = 0.0013_f32;
            let v142: f32 = v141 * v138;
            let v143: f32 = v133 * v142;
            let v144: f32 = v140 - v143;
            let v145: f32 = v137 + v144;
            let v146: f32 = 0.01558_f32;
            let v147: f32 = v50 * v99;
            let v148: f32 = v53 * v45;
            let v149: f32 = v147 + v148;
            let v150: f32 = v102 * v71;
            let v151: f32 = v74 * v118;
            let v152: f32 = v58 * v105;
            let v153: f32 = v151 + v152;
            let v154: f32 = v150 - v153;
            let v155: f32 = v149 + v154;
            let v156: f32 = v130 * v155;
            let v157: f32 = v127 * v122;
            let v158: f32 = v156 + v157;
            let v159: f32 = v34 * v136;
            let v160: f32 = v34 * v133;
            let v161: f32 = v138 * v160;
            let v162: f32 = v159 + v161;
            let v163: f32 = v158 + v162;
            let v164: f32 = v146 * v163;
            let v165: f32 = v145 + v164;
            let v166: f32 = q[4];
            let (v170, v167): (f32, f32) = ::libm::sincosf(v166);
            let v168: f32 = 0.0003_f32;
            let v169: f32 = v167 * v136;
            let v171: f32 = v170 * v71;
            let v172: f32 = v169 - v171;
            let v173: f32 = v167 * v138;
            let v174: f32 = v127 * v69;
            let v175: f32 = v130 * v74;
            let v176: f32 = v174 - v175;
            let v177: f32 = v170 * v176;
            let v178: f32 = v173 - v177;
            let v179: f32 = qd[4];
            let v180: f32 = v178 * v179;
            let v181: f32 = v172 + v180;
            let v182: f32 = v168 * v181;
            let v183: f32 = 0.0004_f32;
            let v184: f32 = v133 + v179;
            let v185: f32 = v183 * v184;
            let v186: f32 = v178 * v185;
            let v187: f32 = v168 * v178;
            let v188: f32 = v184 * v187;
            let v189: f32 = v186 - v188;
            let v190: f32 = v182 + v189;
            let v191: f32 = q[5];
            let (v195, v192): (f32, f32) = ::libm::sincosf(v191);
            let v193: f32 = 0.00024216_f32;
            let v194: f32 = v192 * v181;
            (
                v0,
                v2,
                v3,
                v4,
                v6,
                v7,
                v8,
                v10,
                v11,
                v12,
                v15,
                v17,
                v22,
                v25,
                v29,
                v33,
                v34,
                v38,
                v40,
                v45,
                v48,
                v50,
                v51,
                v53,
                v58,
                v61,
                v63,
                v69,
                v71,
                v74,
                v76,
                v79,
                v81,
                v83,
                v89,
                v93,
                v99,
                v102,
                v104,
                v111,
                v113,
                v122,
                v125,
                v127,
                v128,
                v130,
                v133,
                v134,
                v136,
                v138,
                v139,
                v141,
                v142,
                v146,
                v155,
                v160,
                v163,
                v165,
                v167,
                v168,
                v170,
                v176,
                v178,
                v179,
                v181,
                v183,
                v184,
                v185,
                v187,
                v190,
                v192,
                v193,
                v194,
                v195,
            )
        };
        let (
            v214,
            v262,
            v279,
            v280,
            v310,
            v312,
            v316,
            v330,
            v356,
            v358,
            v362,
            v365,
            v368,
            v372,
            v386,
            v388,
            v389,
        ) = {
            let v196: f32 = v130 * v61;
            let v197: f32 = v176 * v134;
            let v198: f32 = v196 + v197;
            let v199: f32 = v195 * v198;
            let v200: f32 = v194 - v199;
            let v201: f32 = v167 * v176;
            let v202: f32 = v170 * v138;
            let v203: f32 = v201 + v202;
            let v204: f32 = v195 * v203;
            let v205: f32 = v192 * v184;
            let v206: f32 = v204 + v205;
            let v207: f32 = qd[5];
            let v208: f32 = v206 * v207;
            let v209: f32 = v200 - v208;
            let v210: f32 = v193 * v209;
            let v211: f32 = v178 + v207;
            let v212: f32 = v193 * v206;
            let v213: f32 = v211 * v212;
            let v214: f32 = 4e-5_f32;
            let v215: f32 = v214 * v211;
            let v216: f32 = v206 * v215;
            let v217: f32 = v213 - v216;
            let v218: f32 = v210 + v217;
            let v219: f32 = 0.00288_f32;
            let v220: f32 = v127 * v155;
            let v221: f32 = v130 * v122;
            let v222: f32 = v220 - v221;
            let v223: f32 = v34 * v176;
            let v224: f32 = v138 * v223;
            let v225: f32 = v34 * v198;
            let v226: f32 = v224 - v225;
            let v227: f32 = v222 + v226;
            let v228: f32 = v167 * v227;
            let v229: f32 = v133 * v160;
            let v230: f32 = v176 * v223;
            let v231: f32 = v229 + v230;
            let v232: f32 = v111 - v231;
            let v233: f32 = v170 * v232;
            let v234: f32 = v228 + v233;
            let v235: f32 = v195 * v234;
            let v236: f32 = v192 * v163;
            let v237: f32 = v235 + v236;
            let v238: f32 = v219 * v237;
            let v239: f32 = v218 + v238;
            let v240: f32 = v192 * v239;
            let v241: f32 = v192 * v203;
            let v242: f32 = v195 * v184;
            let v243: f32 = v241 - v242;
            let v244: f32 = v193 * v243;
            let v245: f32 = v211 * v244;
            let v246: f32 = v243 * v215;
            let v247: f32 = v245 - v246;
            let v248: f32 = v195 * v181;
            let v249: f32 = v192 * v198;
            let v250: f32 = v248 + v249;
            let v251: f32 = v243 * v207;
            let v252: f32 = v250 + v251;
            let v253: f32 = v193 * v252;
            let v254: f32 = v247 - v253;
            let v255: f32 = v192 * v234;
            let v256: f32 = v195 * v163;
            let v257: f32 = v255 - v256;
            let v258: f32 = v219 * v257;
            let v259: f32 = v254 + v258;
            let v260: f32 = v195 * v259;
            let v261: f32 = v240 - v260;
            let v262: f32 = v190 + v261;
            let v263: f32 = v167 * v262;
            let v264: f32 = v168 * v203;
            let v265: f32 = v184 * v264;
            let v266: f32 = v203 * v185;
            let v267: f32 = v265 - v266;
            let v268: f32 = v170 * v136;
            let v269: f32 = v167 * v71;
            let v270: f32 = v268 + v269;
            let v271: f32 = v203 * v179;
            let v272: f32 = v270 + v271;
            let v273: f32 = v168 * v272;
            let v274: f32 = v267 - v273;
            let v275: f32 = v206 * v244;
            let v276: f32 = v243 * v212;
            let v277: f32 = v275 - v276;
            let v278: f32 = v214 * v272;
            let v279: f32 = v277 - v278;
            let v280: f32 = v274 + v279;
            let v281: f32 = v170 * v280;
            let v282: f32 = v263 - v281;
            let v283: f32 = v165 + v282;
            let v284: f32 = 0.82_f32;
            let v285: f32 = v284 * v163;
            let v286: f32 = v146 * v136;
            let v287: f32 = v146 * v133;
            let v288: f32 = v138 * v287;
            let v289: f32 = v286 + v288;
            let v290: f32 = v285 + v289;
            let v291: f32 = 0.09_f32;
            let v292: f32 = v291 * v257;
            let v293: f32 = v219 * v243;
            let v294: f32 = v211 * v293;
            let v295: f32 = v219 * v252;
            let v296: f32 = v294 - v295;
            let v297: f32 = v292 + v296;
            let v298: f32 = v195 * v297;
            let v299: f32 = v291 * v237;
            let v300: f32 = v219 * v209;
            let v301: f32 = v219 * v206;
            let v302: f32 = v211 * v301;
            let v303: f32 = v300 + v302;
            let v304: f32 = v299 + v303;
            let v305: f32 = v192 * v304;
            let v306: f32 = v298 - v305;
            let v307: f32 = 0.34_f32;
            let v308: f32 = v307 * v163;
            let v309: f32 = v306 - v308;
            let v310: f32 = v290 - v309;
            let v311: f32 = v34 * v310;
            let v312: f32 = v283 + v311;
            let v313: f32 = v127 * v312;
            let v314: f32 = v128 * v198;
            let v315: f32 = v176 * v142;
            let v316: f32 = v128 * v176;
            let v317: f32 = v138 * v316;
            let v318: f32 = v315 - v317;
            let v319: f32 = v314 + v318;
            let v320: f32 = v146 * v227;
            let v321: f32 = v319 - v320;
            let v322: f32 = v178 * v264;
            let v323: f32 = v203 * v187;
            let v324: f32 = v322 - v323;
            let v325: f32 = v183 * v198;
            let v326: f32 = v324 - v325;
            let v327: f32 = v195 * v239;
            let v328: f32 = v192 * v259;
            let v329: f32 = v327 + v328;
            let v330: f32 = v326 + v329;
            let v331: f32 = v321 - v330;
            let v332: f32 = v284 * v227;
            let v333: f32 = v146 * v176;
            let v334: f32 = v138 * v333;
            let v335: f32 = v146 * v198;
            let v336: f32 = v334 - v335;
            let v337: f32 = v332 + v336;
            let v338: f32 = v307 * v234;
            let v339: f32 = v192 * v297;
            let v340: f32 = v195 * v304;
            let v341: f32 = v339 + v340;
            let v342: f32 = v338 + v341;
            let v343: f32 = v167 * v342;
            let v344: f32 = v167 * v232;
            let v345: f32 = v170 * v227;
            let v346: f32 = v344 - v345;
            let v347: f32 = v307 * v346;
            let v348: f32 = v291 * v346;
            let v349: f32 = v243 * v293;
            let v350: f32 = v206 * v301;
            let v351: f32 = v349 + v350;
            let v352: f32 = v348 - v351;
            let v353: f32 = v347 + v352;
            let v354: f32 = v170 * v353;
            let v355: f32 = v343 - v354;
            let v356: f32 = v337 + v355;
            let v357: f32 = v34 * v356;
            let v358: f32 = v331 - v357;
            let v359: f32 = v130 * v358;
            let v360: f32 = v313 + v359;
            let v361: f32 = v125 + v360;
            let v362: f32 = 4.8_f32;
            let v363: f32 = v362 * v111;
            let v364: f32 = v93 * v61;
            let v365: f32 = -0.09744_f32;
            let v366: f32 = v365 * v58;
            let v367: f32 = v113 * v69;
            let v368: f32 = v366 - v367;
            let v369: f32 = v69 * v368;
            let v370: f32 = v113 * v74;
            let v371: f32 = v93 * v58;
            let v372: f32 = v370 + v371;
            let v373: f32 = v74 * v372;
            let v374: f32 = v369 - v373;
            let v375: f32 = v364 + v374;
            let v376: f32 = v363 + v375;
            let v377: f32 = v284 * v232;
            let v378: f32 = v133 * v287;
            let v379: f32 = v176 * v333;
            let v380: f32 = v378 + v379;
            let v381: f32 = v377 - v380;
            let v382: f32 = v170 * v342;
            let v383: f32 = v167 * v353;
            let v384: f32 = v382 + v383;
            let v385: f32 = v381 + v384;
            let v386: f32 = v376 + v385;
            let v387: f32 = v102 * v386;
            let v388: f32 = v361 + v387;
            let v389: f32 = v50 * v388;
            (
                v214,
                v262,
                v279,
                v280,
                v310,
                v312,
                v316,
                v330,
                v356,
                v358,
                v362,
                v365,
                v368,
                v372,
                v386,
                v388,
                v389,
            )
        };
        let (
            v398,
            v414,
            v443,
            v458,
            v464,
            v472,
            v483,
            v494,
            v495,
            v497,
            v506,
            v507,
            v509,
            v512,
            v514,
            v516,
            v526,
            v532,
            v533,
            v534,
            v535,
            v538,
            v539,
            v541,
            v548,
            v549,
            v551,
            v553,
            v555,
            v556,
            v557,
            v558,
            v576,
            v577,
            v583,
            v584,
        ) = {
            let v390: f32 = v63 * v61;
            let v391: f32 = v79 * v71;
            let v392: f32 = v390 - v391;
            let v393: f32 = v69 * v89;
            let v394: f32 = v51 * v69;
            let v395: f32 = v83 * v74;
            let v396: f32 = v394 - v395;
            let v397: f32 = v63 * v58;
            let v398: f32 = v396 + v397;
            let v399: f32 = v74 * v398;
            let v400: f32 = v393 + v399;
            let v401: f32 = v392 + v400;
            let v402: f32 = v365 * v122;
            let v403: f32 = v93 * v155;
            let v404: f32 = v402 + v403;
            let v405: f32 = v401 - v404;
            let v406: f32 = v133 * v316;
            let v407: f32 = v176 * v139;
            let v408: f32 = v406 - v407;
            let v409: f32 = v141 * v71;
            let v410: f32 = v408 - v409;
            let v411: f32 = v170 * v262;
            let v412: f32 = v167 * v280;
            let v413: f32 = v411 + v412;
            let v414: f32 = v410 + v413;
            let v415: f32 = v405 + v414;
            let v416: f32 = v130 * v356;
            let v417: f32 = v127 * v310;
            let v418: f32 = v416 - v417;
            let v419: f32 = v362 * v122;
            let v420: f32 = v365 * v71;
            let v421: f32 = v113 * v61;
            let v422: f32 = v420 + v421;
            let v423: f32 = v58 * v372;
            let v424: f32 = v93 * v69;
            let v425: f32 = v365 * v74;
            let v426: f32 = v424 + v425;
            let v427: f32 = v69 * v426;
            let v428: f32 = v423 + v427;
            let v429: f32 = v422 + v428;
            let v430: f32 = v419 + v429;
            let v431: f32 = v418 - v430;
            let v432: f32 = v104 * v431;
            let v433: f32 = v362 * v155;
            let v434: f32 = v93 * v71;
            let v435: f32 = v74 * v426;
            let v436: f32 = v58 * v368;
            let v437: f32 = v435 + v436;
            let v438: f32 = v434 - v437;
            let v439: f32 = v433 + v438;
            let v440: f32 = v127 * v356;
            let v441: f32 = v130 * v310;
            let v442: f32 = v440 + v441;
            let v443: f32 = v439 + v442;
            let v444: f32 = v102 * v443;
            let v445: f32 = v432 - v444;
            let v446: f32 = v415 + v445;
            let v447: f32 = v53 * v446;
            let v448: f32 = v389 - v447;
            let v449: f32 = v48 + v448;
            let v450: f32 = v2 * v449;
            let v451: f32 = v10 * v8;
            let v452: f32 = v25 * v12;
            let v453: f32 = v451 - v452;
            let v454: f32 = v3 * v11;
            let v455: f32 = v10 * v6;
            let v456: f32 = v454 + v455;
            let v457: f32 = v15 * v7;
            let v458: f32 = v456 + v457;
            let v459: f32 = v7 * v458;
            let v460: f32 = v11 * v22;
            let v461: f32 = v459 - v460;
            let v462: f32 = v453 + v461;
            let v463: f32 = v40 * v99;
            let v464: f32 = -6.33012_f32;
            let v465: f32 = v464 * v38;
            let v466: f32 = v463 - v465;
            let v467: f32 = v462 + v466;
            let v468: f32 = v53 * v388;
            let v469: f32 = v50 * v446;
            let v470: f32 = v468 + v469;
            let v471: f32 = v467 + v470;
            let v472: f32 = 17.4_f32;
            let v473: f32 = v472 * v38;
            let v474: f32 = v33 * v8;
            let v475: f32 = v464 * v12;
            let v476: f32 = v474 + v475;
            let v477: f32 = v464 * v7;
            let v478: f32 = v40 * v11;
            let v479: f32 = v477 - v478;
            let v480: f32 = v11 * v479;
            let v481: f32 = v40 * v6;
            let v482: f32 = v33 * v7;
            let v483: f32 = v481 - v482;
            let v484: f32 = v6 * v483;
            let v485: f32 = v480 - v484;
            let v486: f32 = v476 + v485;
            let v487: f32 = v473 + v486;
            let v488: f32 = v487 - v431;
            let v489: f32 = v34 * v488;
            let v490: f32 = v471 - v489;
            let v491: f32 = v4 * v490;
            let v492: f32 = v450 + v491;
            let v493: f32 = v0 - v492;
            let v494: f32 = 25000.0_f32;
            let v495: f32 = v214 * v167;
            let v496: f32 = v495 * v50;
            let v497: f32 = v214 * v170;
            let v498: f32 = v497 * v127;
            let v499: f32 = v498 * v53;
            let v500: f32 = v496 - v499;
            let v501: f32 = v500 * v4;
            let v502: f32 = v498 * v50;
            let v503: f32 = v495 * v53;
            let v504: f32 = v502 + v503;
            let v505: f32 = v504 * v2;
            let v506: f32 = v501 - v505;
            let v507: f32 = v494 * v506;
            let v508: f32 = tau[5];
            let v509: f32 = v508 - v279;
            let v510: f32 = v507 * v509;
            let v511: f32 = v493 - v510;
            let v512: f32 = 1557.2443_f32;
            let v513: f32 = 0.000432144_f32;
            let v514: f32 = v513 * v170;
            let v515: f32 = v514 * v53;
            let v516: f32 = v513 * v167;
            let v517: f32 = v516 * v127;
            let v518: f32 = v517 * v50;
            let v519: f32 = v515 - v518;
            let v520: f32 = v519 * v4;
            let v521: f32 = v514 * v50;
            let v522: f32 = v517 * v53;
            let v523: f32 = v521 + v522;
            let v524: f32 = v523 * v2;
            let v525: f32 = v520 + v524;
            let v526: f32 = 0.00064216_f32;
            let v527: f32 = v526 * v53;
            let v528: f32 = v527 * v4;
            let v529: f32 = v526 * v50;
            let v530: f32 = v529 * v2;
            let v531: f32 = v528 + v530;
            let v532: f32 = 0.001243584_f32;
            let v533: f32 = v532 * v50;
            let v534: f32 = 5.8464e-5_f32;
            let v535: f32 = v534 * v53;
            let v536: f32 = v533 + v535;
            let v537: f32 = v536 * v2;
            let v538: f32 = -0.001243584_f32;
            let v539: f32 = v534 * v50;
            let v540: f32 = v538 - v539;
            let v541: f32 = v532 * v53;
            let v542: f32 = v540 + v541;
            let v543: f32 = v542 * v4;
            let v544: f32 = v537 + v543;
            let v545: f32 = v544 * v167;
            let v546: f32 = v531 + v545;
            let v547: f32 = v546 * v130;
            let v548: f32 = v525 + v547;
            let v549: f32 = v512 * v548;
            let v550: f32 = tau[4];
            let v551: f32 = v550 + v330;
            let v552: f32 = v549 * v551;
            let v553: f32 = v511 - v552;
            let v554: f32 = 0.00184216_f32;
            let v555: f32 = 0.00020216_f32;
            let v556: f32 = v555 * v167;
            let v557: f32 = v556 * v167;
            let v558: f32 = v554 - v557;
            let v559: f32 = v558 * v50;
            let v560: f32 = v559 * v4;
            let v561: f32 = -0.00184216_f32;
            let v562: f32 = v561 + v557;
            let v563: f32 = v562 * v53;
            let v564: f32 = v563 * v2;
            let v565: f32 = v560 + v564;
            let v566: f32 = v513 * v50;
            let v567: f32 = v566 * v4;
            let v568: f32 = v513 * v53;
            let v569: f32 = v568 * v2;
            let v570: f32 = v567 - v569;
            let v571: f32 = v570 * v130;
            let v572: f32 = v532 + v556;
            let v573: f32 = v572 * v50;
            let v574: f32 = v535 + v573;
            let v575: f32 = v574 * v2;
            let v576: f32 = v572 * v53;
            let v577: f32 = v540 + v576;
            let v578: f32 = v577 * v4;
            let v579: f32 = v575 + v578;
            let v580: f32 = v579 * v127;
            let v581: f32 = v571 + v580;
            let v582: f32 = v581 * v170;
            let v583: f32 = v565 + v582;
            let v584: f32 = v494 * v495;
            (
                v398,
                v414,
                v443,
                v458,
                v464,
                v472,
                v483,
                v494,
                v495,
                v497,
                v506,
                v507,
                v509,
                v512,
                v514,
                v516,
                v526,
                v532,
                v533,
                v534,
                v535,
                v538,
                v539,
                v541,
                v548,
                v549,
                v551,
                v553,
                v555,
                v556,
                v557,
                v558,
                v576,
                v577,
                v583,
                v584,
            )
        };
        let (
            v586,
            v588,
            v589,
            v593,
            v612,
            v632,
            v640,
            v647,
            v649,
            v651,
            v653,
            v656,
            v657,
            v666,
            v667,
            v685,
            v687,
            v692,
            v694,
            v723,
            v730,
            v753,
            v755,
            v757,
            v761,
            v763,
            v779,
        ) = {
            let v585: f32 = v506 * v584;
            let v586: f32 = v583 - v585;
            let v587: f32 = v495 * v584;
            let v588: f32 = v558 - v587;
            let v589: f32 = v586 / v588;
            let v590: f32 = tau[3];
            let v591: f32 = v590 - v414;
            let v592: f32 = v584 * v509;
            let v593: f32 = v591 - v592;
            let v594: f32 = v589 * v593;
            let v595: f32 = v553 - v594;
            let v596: f32 = -0.13848166_f32;
            let v597: f32 = v596 - v516;
            let v598: f32 = v597 * v50;
            let v599: f32 = -0.0038075189_f32;
            let v600: f32 = v514 * v127;
            let v601: f32 = v599 + v600;
            let v602: f32 = v601 * v53;
            let v603: f32 = v598 + v602;
            let v604: f32 = v603 * v4;
            let v605: f32 = v601 * v50;
            let v606: f32 = 0.13848166_f32;
            let v607: f32 = v606 + v516;
            let v608: f32 = v607 * v53;
            let v609: f32 = v605 + v608;
            let v610: f32 = v609 * v2;
            let v611: f32 = v604 + v610;
            let v612: f32 = 0.00030216_f32;
            let v613: f32 = v612 - v557;
            let v614: f32 = v613 * v53;
            let v615: f32 = v614 * v4;
            let v616: f32 = v613 * v50;
            let v617: f32 = v616 * v2;
            let v618: f32 = v615 + v617;
            let v619: f32 = v618 * v127;
            let v620: f32 = v538 - v556;
            let v621: f32 = v620 * v50;
            let v622: f32 = v621 - v535;
            let v623: f32 = v622 * v4;
            let v624: f32 = v576 - v539;
            let v625: f32 = v624 * v2;
            let v626: f32 = v623 + v625;
            let v627: f32 = v626 * v170;
            let v628: f32 = v619 + v627;
            let v629: f32 = v628 * v130;
            let v630: f32 = v611 + v629;
            let v631: f32 = v497 * v130;
            let v632: f32 = v494 * v631;
            let v633: f32 = v506 * v632;
            let v634: f32 = v630 - v633;
            let v635: f32 = v532 * v167;
            let v636: f32 = v526 + v635;
            let v637: f32 = v636 * v127;
            let v638: f32 = v534 * v170;
            let v639: f32 = v637 - v638;
            let v640: f32 = v512 * v639;
            let v641: f32 = v548 * v640;
            let v642: f32 = v634 - v641;
            let v643: f32 = v620 * v170;
            let v644: f32 = v643 * v130;
            let v645: f32 = v631 * v584;
            let v646: f32 = v644 - v645;
            let v647: f32 = v646 / v588;
            let v648: f32 = v586 * v647;
            let v649: f32 = v642 - v648;
            let v650: f32 = 0.35899007_f32;
            let v651: f32 = 0.002487168_f32;
            let v652: f32 = v651 + v556;
            let v653: f32 = v652 * v167;
            let v654: f32 = v650 + v653;
            let v655: f32 = v613 * v127;
            let v656: f32 = 0.000116928_f32;
            let v657: f32 = v656 * v170;
            let v658: f32 = v655 - v657;
            let v659: f32 = v658 * v127;
            let v660: f32 = v654 + v659;
            let v661: f32 = v631 * v632;
            let v662: f32 = v660 - v661;
            let v663: f32 = v639 * v640;
            let v664: f32 = v662 - v663;
            let v665: f32 = v646 * v647;
            let v666: f32 = v664 - v665;
            let v667: f32 = v649 / v666;
            let v668: f32 = tau[2];
            let v669: f32 = v83 * v61;
            let v670: f32 = v76 * v71;
            let v671: f32 = v669 - v670;
            let v672: f32 = v58 * v398;
            let v673: f32 = v69 * v81;
            let v674: f32 = v672 - v673;
            let v675: f32 = v671 + v674;
            let v676: f32 = v113 * v155;
            let v677: f32 = v365 * v111;
            let v678: f32 = v676 - v677;
            let v679: f32 = v675 + v678;
            let v680: f32 = v130 * v312;
            let v681: f32 = v127 * v358;
            let v682: f32 = v680 - v681;
            let v683: f32 = v679 + v682;
            let v684: f32 = v104 * v386;
            let v685: f32 = v683 - v684;
            let v686: f32 = v668 + v685;
            let v687: f32 = v632 * v509;
            let v688: f32 = v686 - v687;
            let v689: f32 = v640 * v551;
            let v690: f32 = v688 - v689;
            let v691: f32 = v647 * v593;
            let v692: f32 = v690 - v691;
            let v693: f32 = v667 * v692;
            let v694: f32 = v595 - v693;
            let v695: f32 = v597 + v644;
            let v696: f32 = v695 * v50;
            let v697: f32 = v17 + v696;
            let v698: f32 = v655 - v638;
            let v699: f32 = v698 * v130;
            let v700: f32 = v601 + v699;
            let v701: f32 = v700 * v53;
            let v702: f32 = v697 + v701;
            let v703: f32 = v702 * v4;
            let v704: f32 = -0.69039136_f32;
            let v705: f32 = v704 + v605;
            let v706: f32 = v705 + v608;
            let v707: f32 = v655 * v50;
            let v708: f32 = v577 * v170;
            let v709: f32 = v707 + v708;
            let v710: f32 = v709 * v130;
            let v711: f32 = v706 + v710;
            let v712: f32 = v711 * v2;
            let v713: f32 = v703 + v712;
            let v714: f32 = v713 - v633;
            let v715: f32 = -5.8464e-5_f32;
            let v716: f32 = v715 - v533;
            let v717: f32 = v716 * v170;
            let v718: f32 = v532 - v541;
            let v719: f32 = v718 * v167;
            let v720: f32 = v526 + v719;
            let v721: f32 = v720 * v127;
            let v722: f32 = v717 + v721;
            let v723: f32 = v512 * v722;
            let v724: f32 = v548 * v723;
            let v725: f32 = v714 - v724;
            let v726: f32 = v620 + v541;
            let v727: f32 = v726 * v170;
            let v728: f32 = v727 * v130;
            let v729: f32 = v728 - v645;
            let v730: f32 = v729 / v588;
            let v731: f32 = v586 * v730;
            let v732: f32 = v725 - v731;
            let v733: f32 = 0.010956925_f32;
            let v734: f32 = v733 * v50;
            let v735: f32 = v650 + v734;
            let v736: f32 = 0.38487628_f32;
            let v737: f32 = v736 * v53;
            let v738: f32 = v735 - v737;
            let v739: f32 = v652 - v541;
            let v740: f32 = v739 * v167;
            let v741: f32 = v738 + v740;
            let v742: f32 = -0.000116928_f32;
            let v743: f32 = v742 - v533;
            let v744: f32 = v743 * v170;
            let v745: f32 = v744 + v655;
            let v746: f32 = v745 * v127;
            let v747: f32 = v741 + v746;
            let v748: f32 = v747 - v661;
            let v749: f32 = v722 * v640;
            let v750: f32 = v748 - v749;
            let v751: f32 = v729 * v647;
            let v752: f32 = v750 - v751;
            let v753: f32 = v752 / v666;
            let v754: f32 = v649 * v753;
            let v755: f32 = v732 - v754;
            let v756: f32 = 2.107104_f32;
            let v757: f32 = 0.02191385_f32;
            let v758: f32 = v757 * v50;
            let v759: f32 = v756 + v758;
            let v760: f32 = 0.76975256_f32;
            let v761: f32 = v760 * v53;
            let v762: f32 = v759 - v761;
            let v763: f32 = v651 * v53;
            let v764: f32 = v652 - v763;
            let v765: f32 = v764 * v167;
            let v766: f32 = v762 + v765;
            let v767: f32 = v651 * v50;
            let v768: f32 = v742 - v767;
            let v769: f32 = v768 * v170;
            let v770: f32 = v769 + v655;
            let v771: f32 = v770 * v127;
            let v772: f32 = v766 + v771;
            let v773: f32 = v772 - v661;
            let v774: f32 = v722 * v723;
            let v775: f32 = v773 - v774;
            let v776: f32 = v729 * v730;
            let v777: f32 = v775 - v776;
            let v778: f32 = v752 * v753;
            let v779: f32 = v777 - v778;
            (
                v586,
                v588,
                v589,
                v593,
                v612,
                v632,
                v640,
                v647,
                v649,
                v651,
                v653,
                v656,
                v657,
                v666,
                v667,
                v685,
                v687,
                v692,
                v694,
                v723,
                v730,
                v753,
                v755,
                v757,
                v761,
                v763,
                v779,
            )
        };
        let (v941, v944, v949, v956, v963, v972) = {
            let v780: f32 = v755 / v779;
            let v781: f32 = tau[1];
            let v782: f32 = v15 * v8;
            let v783: f32 = v17 * v12;
            let v784: f32 = v782 - v783;
            let v785: f32 = v11 * v29;
            let v786: f32 = v6 * v458;
            let v787: f32 = v785 - v786;
            let v788: f32 = v784 + v787;
            let v789: f32 = v464 * v45;
            let v790: f32 = v33 * v99;
            let v791: f32 = v789 - v790;
            let v792: f32 = v788 + v791;
            let v793: f32 = v792 - v685;
            let v794: f32 = v472 * v45;
            let v795: f32 = v7 * v483;
            let v796: f32 = v33 * v11;
            let v797: f32 = v464 * v6;
            let v798: f32 = v796 - v797;
            let v799: f32 = v11 * v798;
            let v800: f32 = v795 - v799;
            let v801: f32 = v40 * v8;
            let v802: f32 = v800 - v801;
            let v803: f32 = v794 + v802;
            let v804: f32 = v53 * v443;
            let v805: f32 = v50 * v386;
            let v806: f32 = v804 + v805;
            let v807: f32 = v803 + v806;
            let v808: f32 = v34 * v807;
            let v809: f32 = v793 + v808;
            let v810: f32 = v781 - v809;
            let v811: f32 = v810 - v687;
            let v812: f32 = v723 * v551;
            let v813: f32 = v811 - v812;
            let v814: f32 = v730 * v593;
            let v815: f32 = v813 - v814;
            let v816: f32 = v753 * v692;
            let v817: f32 = v815 - v816;
            let v818: f32 = v780 * v817;
            let v819: f32 = v694 - v818;
            let v820: f32 = 1.5535233_f32;
            let v821: f32 = v820 - v557;
            let v822: f32 = 0.000864288_f32;
            let v823: f32 = v822 * v130;
            let v824: f32 = v656 * v127;
            let v825: f32 = v823 - v824;
            let v826: f32 = v825 * v170;
            let v827: f32 = v821 + v826;
            let v828: f32 = 0.022546398_f32;
            let v829: f32 = v656 * v167;
            let v830: f32 = v828 + v829;
            let v831: f32 = -0.002487168_f32;
            let v832: f32 = 0.00040432_f32;
            let v833: f32 = v832 * v167;
            let v834: f32 = v831 - v833;
            let v835: f32 = v834 * v170;
            let v836: f32 = v835 * v127;
            let v837: f32 = v830 + v836;
            let v838: f32 = v837 * v53;
            let v839: f32 = 0.32391983_f32;
            let v840: f32 = v839 + v653;
            let v841: f32 = -0.00030216_f32;
            let v842: f32 = v841 + v557;
            let v843: f32 = v842 * v127;
            let v844: f32 = v657 + v843;
            let v845: f32 = v844 * v127;
            let v846: f32 = v840 + v845;
            let v847: f32 = v846 * v50;
            let v848: f32 = v838 + v847;
            let v849: f32 = v848 * v50;
            let v850: f32 = v827 + v849;
            let v851: f32 = 0.008347998_f32;
            let v852: f32 = v851 + v829;
            let v853: f32 = v757 * v53;
            let v854: f32 = v852 - v853;
            let v855: f32 = v834 + v763;
            let v856: f32 = v855 * v170;
            let v857: f32 = v856 * v127;
            let v858: f32 = v854 + v857;
            let v859: f32 = v858 * v2;
            let v860: f32 = 1.925781_f32;
            let v861: f32 = v860 - v761;
            let v862: f32 = v612 * v127;
            let v863: f32 = v657 - v862;
            let v864: f32 = v863 * v127;
            let v865: f32 = v861 + v864;
            let v866: f32 = v651 - v763;
            let v867: f32 = v555 * v127;
            let v868: f32 = v867 * v127;
            let v869: f32 = v555 + v868;
            let v870: f32 = v869 * v167;
            let v871: f32 = v866 + v870;
            let v872: f32 = v871 * v167;
            let v873: f32 = v865 + v872;
            let v874: f32 = v873 * v4;
            let v875: f32 = v859 + v874;
            let v876: f32 = v651 * v170;
            let v877: f32 = v876 * v127;
            let v878: f32 = v757 - v877;
            let v879: f32 = -0.045092795_f32;
            let v880: f32 = 0.000233856_f32;
            let v881: f32 = v880 * v167;
            let v882: f32 = v879 - v881;
            let v883: f32 = 0.004974336_f32;
            let v884: f32 = 0.00080864_f32;
            let v885: f32 = v884 * v167;
            let v886: f32 = v883 + v885;
            let v887: f32 = v886 * v170;
            let v888: f32 = v887 * v127;
            let v889: f32 = v882 + v888;
            let v890: f32 = v889 * v53;
            let v891: f32 = v878 + v890;
            let v892: f32 = -0.64783967_f32;
            let v893: f32 = -0.004974336_f32;
            let v894: f32 = v893 - v833;
            let v895: f32 = v894 * v167;
            let v896: f32 = v892 + v895;
            let v897: f32 = 0.00060432_f32;
            let v898: f32 = v833 * v167;
            let v899: f32 = v897 - v898;
            let v900: f32 = v899 * v127;
            let v901: f32 = v880 * v170;
            let v902: f32 = v900 - v901;
            let v903: f32 = v902 * v127;
            let v904: f32 = v896 + v903;
            let v905: f32 = v904 * v50;
            let v906: f32 = v891 + v905;
            let v907: f32 = v906 * v4;
            let v908: f32 = -0.76975256_f32;
            let v909: f32 = v651 * v167;
            let v910: f32 = v908 - v909;
            let v911: f32 = v889 * v50;
            let v912: f32 = v910 + v911;
            let v913: f32 = 0.64783967_f32;
            let v914: f32 = v883 + v833;
            let v915: f32 = v914 * v167;
            let v916: f32 = v913 + v915;
            let v917: f32 = -0.00060432_f32;
            let v918: f32 = v917 + v898;
            let v919: f32 = v918 * v127;
            let v920: f32 = v901 + v919;
            let v921: f32 = v920 * v127;
            let v922: f32 = v916 + v921;
            let v923: f32 = v922 * v53;
            let v924: f32 = v912 + v923;
            let v925: f32 = v924 * v2;
            let v926: f32 = v907 + v925;
            let v927: f32 = v926 * v50;
            let v928: f32 = v875 + v927;
            let v929: f32 = v928 * v4;
            let v930: f32 = v850 + v929;
            let v931: f32 = v506 * v507;
            let v932: f32 = v930 - v931;
            let v933: f32 = v548 * v549;
            let v934: f32 = v932 - v933;
            let v935: f32 = v586 * v589;
            let v936: f32 = v934 - v935;
            let v937: f32 = v649 * v667;
            let v938: f32 = v936 - v937;
            let v939: f32 = v755 * v780;
            let v940: f32 = v938 - v939;
            let v941: f32 = v819 / v940;
            let v942: f32 = v817 / v779;
            let v943: f32 = v780 * v941;
            let v944: f32 = v942 - v943;
            let v945: f32 = v692 / v666;
            let v946: f32 = v667 * v941;
            let v947: f32 = v945 - v946;
            let v948: f32 = v753 * v944;
            let v949: f32 = v947 - v948;
            let v950: f32 = v593 / v588;
            let v951: f32 = v589 * v941;
            let v952: f32 = v950 - v951;
            let v953: f32 = v730 * v944;
            let v954: f32 = v952 - v953;
            let v955: f32 = v647 * v949;
            let v956: f32 = v954 - v955;
            let v957: f32 = v512 * v551;
            let v958: f32 = v549 * v941;
            let v959: f32 = v957 - v958;
            let v960: f32 = v723 * v944;
            let v961: f32 = v959 - v960;
            let v962: f32 = v640 * v949;
            let v963: f32 = v961 - v962;
            let v964: f32 = v494 * v509;
            let v965: f32 = v507 * v941;
            let v966: f32 = v964 - v965;
            let v967: f32 = v632 * v944;
            let v968: f32 = v966 - v967;
            let v969: f32 = v632 * v949;
            let v970: f32 = v968 - v969;
            let v971: f32 = v584 * v956;
            let v972: f32 = v970 - v971;
            (v941, v944, v949, v956, v963, v972)
        };
        [v941, v944, v949, v956, v963, v972]
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
    /// Operation count: 746 floating-point operations, 10 trig calls.
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
            v136,
            v138,
            v139,
            v140,
            v141,
            v142,
            v144,
            v149,
            v151,
            v152,
            v153,
            v154,
            v155,
            v161,
            v163,
            v167,
            v168,
        ) = {
            let v0: f32 = 1.5535233_f32;
            let v1: f32 = 0.00020216_f32;
            let v2: f32 = q[4];
            let (v15, v3): (f32, f32) = ::libm::sincosf(v2);
            let v4: f32 = v1 * v3;
            let v5: f32 = v4 * v3;
            let v6: f32 = v0 - v5;
            let v7: f32 = 0.000864288_f32;
            let v8: f32 = q[3];
            let (v9, v12): (f32, f32) = ::libm::sincosf(v8);
            let v10: f32 = v7 * v9;
            let v11: f32 = 0.000116928_f32;
            let v13: f32 = v11 * v12;
            let v14: f32 = v10 - v13;
            let v16: f32 = v14 * v15;
            let v17: f32 = v6 + v16;
            let v18: f32 = 0.022546398_f32;
            let v19: f32 = v11 * v3;
            let v20: f32 = v18 + v19;
            let v21: f32 = -0.002487168_f32;
            let v22: f32 = 0.00040432_f32;
            let v23: f32 = v22 * v3;
            let v24: f32 = v21 - v23;
            let v25: f32 = v24 * v15;
            let v26: f32 = v25 * v12;
            let v27: f32 = v20 + v26;
            let v28: f32 = q[2];
            let (v29, v43): (f32, f32) = ::libm::sincosf(v28);
            let v30: f32 = v27 * v29;
            let v31: f32 = 0.32391983_f32;
            let v32: f32 = 0.002487168_f32;
            let v33: f32 = v32 + v4;
            let v34: f32 = v33 * v3;
            let v35: f32 = v31 + v34;
            let v36: f32 = v11 * v15;
            let v37: f32 = -0.00030216_f32;
            let v38: f32 = v37 + v5;
            let v39: f32 = v38 * v12;
            let v40: f32 = v36 + v39;
            let v41: f32 = v40 * v12;
            let v42: f32 = v35 + v41;
            let v44: f32 = v42 * v43;
            let v45: f32 = v30 + v44;
            let v46: f32 = v45 * v43;
            let v47: f32 = v17 + v46;
            let v48: f32 = 0.008347998_f32;
            let v49: f32 = v48 + v19;
            let v50: f32 = 0.02191385_f32;
            let v51: f32 = v50 * v29;
            let v52: f32 = v49 - v51;
            let v53: f32 = v32 * v29;
            let v54: f32 = v24 + v53;
            let v55: f32 = v54 * v15;
            let v56: f32 = v55 * v12;
            let v57: f32 = v52 + v56;
            let v58: f32 = q[1];
            let (v59, v78): (f32, f32) = ::libm::sincosf(v58);
            let v60: f32 = v57 * v59;
            let v61: f32 = 1.925781_f32;
            let v62: f32 = 0.76975256_f32;
            let v63: f32 = v62 * v29;
            let v64: f32 = v61 - v63;
            let v65: f32 = 0.00030216_f32;
            let v66: f32 = v65 * v12;
            let v67: f32 = v36 - v66;
            let v68: f32 = v67 * v12;
            let v69: f32 = v64 + v68;
            let v70: f32 = v32 - v53;
            let v71: f32 = v1 * v12;
            let v72: f32 = v71 * v12;
            let v73: f32 = v1 + v72;
            let v74: f32 = v73 * v3;
            let v75: f32 = v70 + v74;
            let v76: f32 = v75 * v3;
            let v77: f32 = v69 + v76;
            let v79: f32 = v77 * v78;
            let v80: f32 = v60 + v79;
            let v81: f32 = v32 * v15;
            let v82: f32 = v81 * v12;
            let v83: f32 = v50 - v82;
            let v84: f32 = -0.045092795_f32;
            let v85: f32 = 0.000233856_f32;
            let v86: f32 = v85 * v3;
            let v87: f32 = v84 - v86;
            let v88: f32 = 0.004974336_f32;
            let v89: f32 = 0.00080864_f32;
            let v90: f32 = v89 * v3;
            let v91: f32 = v88 + v90;
            let v92: f32 = v91 * v15;
            let v93: f32 = v92 * v12;
            let v94: f32 = v87 + v93;
            let v95: f32 = v94 * v29;
            let v96: f32 = v83 + v95;
            let v97: f32 = -0.64783967_f32;
            let v98: f32 = -0.004974336_f32;
            let v99: f32 = v98 - v23;
            let v100: f32 = v99 * v3;
            let v101: f32 = v97 + v100;
            let v102: f32 = 0.00060432_f32;
            let v103: f32 = v23 * v3;
            let v104: f32 = v102 - v103;
            let v105: f32 = v104 * v12;
            let v106: f32 = v85 * v15;
            let v107: f32 = v105 - v106;
            let v108: f32 = v107 * v12;
            let v109: f32 = v101 + v108;
            let v110: f32 = v109 * v43;
            let v111: f32 = v96 + v110;
            let v112: f32 = v111 * v78;
            let v113: f32 = -0.76975256_f32;
            let v114: f32 = v32 * v3;
            let v115: f32 = v113 - v114;
            let v116: f32 = v94 * v43;
            let v117: f32 = v115 + v116;
            let v118: f32 = 0.64783967_f32;
            let v119: f32 = v88 + v23;
            let v120: f32 = v119 * v3;
            let v121: f32 = v118 + v120;
            let v122: f32 = -0.00060432_f32;
            let v123: f32 = v122 + v103;
            let v124: f32 = v123 * v12;
            let v125: f32 = v106 + v124;
            let v126: f32 = v125 * v12;
            let v127: f32 = v121 + v126;
            let v128: f32 = v127 * v29;
            let v129: f32 = v117 + v128;
            let v130: f32 = v129 * v59;
            let v131: f32 = v112 + v130;
            let v132: f32 = v131 * v43;
            let v133: f32 = v80 + v132;
            let v134: f32 = v133 * v78;
            let v135: f32 = v47 + v134;
            let v136: f32 = -0.023751_f32;
            let v137: f32 = -0.13848166_f32;
            let v138: f32 = 0.000432144_f32;
            let v139: f32 = v138 * v3;
            let v140: f32 = v137 - v139;
            let v141: f32 = -0.001243584_f32;
            let v142: f32 = v141 - v4;
            let v143: f32 = v142 * v15;
            let v144: f32 = v143 * v9;
            let v145: f32 = v140 + v144;
            let v146: f32 = v145 * v43;
            let v147: f32 = v136 + v146;
            let v148: f32 = -0.0038075189_f32;
            let v149: f32 = v138 * v15;
            let v150: f32 = v149 * v12;
            let v151: f32 = v148 + v150;
            let v152: f32 = v65 - v5;
            let v153: f32 = v152 * v12;
            let v154: f32 = 5.8464e-5_f32;
            let v155: f32 = v154 * v15;
            let v156: f32 = v153 - v155;
            let v157: f32 = v156 * v9;
            let v158: f32 = v151 + v157;
            let v159: f32 = v158 * v29;
            let v160: f32 = v147 + v159;
            let v161: f32 = v160 * v78;
            let v162: f32 = -0.69039136_f32;
            let v163: f32 = v151 * v43;
            let v164: f32 = v162 + v163;
            let v165: f32 = 0.13848166_f32;
            let v166: f32 = v165 + v139;
            let v167: f32 = v166 * v29;
            let v168: f32 = v164 + v167;
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
                v136,
                v138,
                v139,
                v140,
                v141,
                v142,
                v144,
                v149,
                v151,
                v152,
                v153,
                v154,
                v155,
                v161,
                v163,
                v167,
                v168,
            )
        };
        let (
            v172,
            v181,
            v205,
            v207,
            v229,
            v240,
            v246,
            v249,
            v256,
            v257,
            v258,
            v260,
            v269,
            v270,
            v272,
            v273,
            v274,
            v276,
            v277,
            v278,
            v281,
            v287,
            v290,
            v294,
            v298,
            v299,
            v301,
            v303,
            v305,
            v306,
            v308,
            v310,
            v313,
            v314,
            v320,
            v323,
            v325,
            v331,
            v333,
            v335,
            v336,
            v337,
        ) = {
            let v169: f32 = v153 * v43;
            let v170: f32 = v154 * v43;
            let v171: f32 = v141 - v170;
            let v172: f32 = 0.001243584_f32;
            let v173: f32 = v172 + v4;
            let v174: f32 = v173 * v29;
            let v175: f32 = v171 + v174;
            let v176: f32 = v175 * v15;
            let v177: f32 = v169 + v176;
            let v178: f32 = v177 * v9;
            let v179: f32 = v168 + v178;
            let v180: f32 = v179 * v59;
            let v181: f32 = v161 + v180;
            let v182: f32 = v140 * v43;
            let v183: f32 = v151 * v29;
            let v184: f32 = v182 + v183;
            let v185: f32 = v184 * v78;
            let v186: f32 = v163 + v167;
            let v187: f32 = v186 * v59;
            let v188: f32 = v185 + v187;
            let v189: f32 = v152 * v29;
            let v190: f32 = v189 * v78;
            let v191: f32 = v152 * v43;
            let v192: f32 = v191 * v59;
            let v193: f32 = v190 + v192;
            let v194: f32 = v193 * v12;
            let v195: f32 = v142 * v43;
            let v196: f32 = v154 * v29;
            let v197: f32 = v195 - v196;
            let v198: f32 = v197 * v78;
            let v199: f32 = v174 - v170;
            let v200: f32 = v199 * v59;
            let v201: f32 = v198 + v200;
            let v202: f32 = v201 * v15;
            let v203: f32 = v194 + v202;
            let v204: f32 = v203 * v9;
            let v205: f32 = v188 + v204;
            let v206: f32 = 0.00184216_f32;
            let v207: f32 = v206 - v5;
            let v208: f32 = v207 * v43;
            let v209: f32 = v208 * v78;
            let v210: f32 = -0.00184216_f32;
            let v211: f32 = v210 + v5;
            let v212: f32 = v211 * v29;
            let v213: f32 = v212 * v59;
            let v214: f32 = v209 + v213;
            let v215: f32 = v138 * v43;
            let v216: f32 = v215 * v78;
            let v217: f32 = v138 * v29;
            let v218: f32 = v217 * v59;
            let v219: f32 = v216 - v218;
            let v220: f32 = v219 * v9;
            let v221: f32 = v173 * v43;
            let v222: f32 = v196 + v221;
            let v223: f32 = v222 * v59;
            let v224: f32 = v175 * v78;
            let v225: f32 = v223 + v224;
            let v226: f32 = v225 * v12;
            let v227: f32 = v220 + v226;
            let v228: f32 = v227 * v15;
            let v229: f32 = v214 + v228;
            let v230: f32 = v149 * v29;
            let v231: f32 = v139 * v12;
            let v232: f32 = v231 * v43;
            let v233: f32 = v230 - v232;
            let v234: f32 = v233 * v78;
            let v235: f32 = v149 * v43;
            let v236: f32 = v231 * v29;
            let v237: f32 = v235 + v236;
            let v238: f32 = v237 * v59;
            let v239: f32 = v234 + v238;
            let v240: f32 = 0.00064216_f32;
            let v241: f32 = v240 * v29;
            let v242: f32 = v241 * v78;
            let v243: f32 = v240 * v43;
            let v244: f32 = v243 * v59;
            let v245: f32 = v242 + v244;
            let v246: f32 = v172 * v43;
            let v247: f32 = v246 + v196;
            let v248: f32 = v247 * v59;
            let v249: f32 = v172 * v29;
            let v250: f32 = v171 + v249;
            let v251: f32 = v250 * v78;
            let v252: f32 = v248 + v251;
            let v253: f32 = v252 * v3;
            let v254: f32 = v245 + v253;
            let v255: f32 = v254 * v9;
            let v256: f32 = v239 + v255;
            let v257: f32 = 4e-5_f32;
            let v258: f32 = v257 * v3;
            let v259: f32 = v258 * v43;
            let v260: f32 = v257 * v15;
            let v261: f32 = v260 * v12;
            let v262: f32 = v261 * v29;
            let v263: f32 = v259 - v262;
            let v264: f32 = v263 * v78;
            let v265: f32 = v261 * v43;
            let v266: f32 = v258 * v29;
            let v267: f32 = v265 + v266;
            let v268: f32 = v267 * v59;
            let v269: f32 = v264 - v268;
            let v270: f32 = 1.0311852_f32;
            let v271: f32 = qd[0];
            let v272: f32 = v78 * v271;
            let v273: f32 = qd[1];
            let v274: f32 = v272 * v273;
            let v275: f32 = v270 * v274;
            let v276: f32 = 0.03798072_f32;
            let v277: f32 = v59 * v271;
            let v278: f32 = v277 * v273;
            let v279: f32 = v276 * v278;
            let v280: f32 = v275 - v279;
            let v281: f32 = 1.4401023_f32;
            let v282: f32 = v281 * v277;
            let v283: f32 = v136 * v272;
            let v284: f32 = v282 + v283;
            let v285: f32 = 2.842524_f32;
            let v286: f32 = v285 * v273;
            let v287: f32 = v284 + v286;
            let v288: f32 = v272 * v287;
            let v289: f32 = v276 * v277;
            let v290: f32 = 3.7274563_f32;
            let v291: f32 = v290 * v272;
            let v292: f32 = v289 + v291;
            let v293: f32 = v136 * v273;
            let v294: f32 = v292 + v293;
            let v295: f32 = v273 * v294;
            let v296: f32 = v288 - v295;
            let v297: f32 = v280 + v296;
            let v298: f32 = 0.1044_f32;
            let v299: f32 = 0.4318_f32;
            let v300: f32 = v299 * v278;
            let v301: f32 = v299 * v273;
            let v302: f32 = v277 * v301;
            let v303: f32 = v300 + v302;
            let v304: f32 = v298 * v303;
            let v305: f32 = 3.9585_f32;
            let v306: f32 = 9.81_f32;
            let v307: f32 = v306 * v78;
            let v308: f32 = v299 * v272;
            let v309: f32 = v277 * v308;
            let v310: f32 = v307 + v309;
            let v311: f32 = v305 * v310;
            let v312: f32 = v304 - v311;
            let v313: f32 = v297 + v312;
            let v314: f32 = 0.090474285_f32;
            let v315: f32 = v43 * v274;
            let v316: f32 = v29 * v278;
            let v317: f32 = v315 - v316;
            let v318: f32 = v43 * v272;
            let v319: f32 = v29 * v277;
            let v320: f32 = v318 - v319;
            let v321: f32 = qd[2];
            let v322: f32 = v320 * v321;
            let v323: f32 = v317 + v322;
            let v324: f32 = v314 * v323;
            let v325: f32 = 0.0068208_f32;
            let v326: f32 = v29 * v274;
            let v327: f32 = v43 * v278;
            let v328: f32 = v326 + v327;
            let v329: f32 = v43 * v277;
            let v330: f32 = v29 * v272;
            let v331: f32 = v329 + v330;
            let v332: f32 = v331 * v321;
            let v333: f32 = v328 + v332;
            let v334: f32 = v325 * v333;
            let v335: f32 = v324 - v334;
            let v336: f32 = v273 + v321;
            let v337: f32 = v325 * v331;
            (
                v172,
                v181,
                v205,
                v207,
                v229,
                v240,
                v246,
                v249,
                v256,
                v257,
                v258,
                v260,
                v269,
                v270,
                v272,
                v273,
                v274,
                v276,
                v277,
                v278,
                v281,
                v287,
                v290,
                v294,
                v298,
                v299,
                v301,
                v303,
                v305,
                v306,
                v308,
                v310,
                v313,
                v314,
                v320,
                v323,
                v325,
                v331,
                v333,
                v335,
                v336,
                v337,
            )
        };
        let (
            v338,
            v341,
            v343,
            v345,
            v351,
            v355,
            v361,
            v364,
            v366,
            v373,
            v375,
            v384,
            v387,
            v388,
            v392,
            v395,
            v397,
            v398,
            v400,
            v401,
            v405,
            v414,
            v422,
            v424,
            v425,
            v432,
            v434,
            v435,
            v439,
            v440,
            v441,
            v443,
            v446,
            v448,
            v449,
            v451,
            v454,
            v459,
            v462,
            v465,
            v467,
            v468,
            v474,
            v482,
            v487,
            v489,
            v492,
            v494,
            v495,
            v498,
            v499,
            v502,
            v505,
            v506,
        ) = {
            let v338: f32 = 0.0047376_f32;
            let v339: f32 = v338 * v336;
            let v340: f32 = v337 - v339;
            let v341: f32 = 0.01543232_f32;
            let v342: f32 = v341 * v320;
            let v343: f32 = v340 + v342;
            let v344: f32 = v336 * v343;
            let v345: f32 = -0.001373904_f32;
            let v346: f32 = v345 * v331;
            let v347: f32 = 0.111498035_f32;
            let v348: f32 = v347 * v336;
            let v349: f32 = v346 - v348;
            let v350: f32 = v338 * v320;
            let v351: f32 = v349 + v350;
            let v352: f32 = v320 * v351;
            let v353: f32 = v344 + v352;
            let v354: f32 = v335 - v353;
            let v355: f32 = -0.06768_f32;
            let v356: f32 = v43 * v310;
            let v357: f32 = v306 * v59;
            let v358: f32 = v272 * v308;
            let v359: f32 = v273 * v301;
            let v360: f32 = v358 + v359;
            let v361: f32 = v357 - v360;
            let v362: f32 = v29 * v361;
            let v363: f32 = v356 - v362;
            let v364: f32 = -0.15005_f32;
            let v365: f32 = v364 * v323;
            let v366: f32 = 0.0203_f32;
            let v367: f32 = v366 * v320;
            let v368: f32 = v331 * v367;
            let v369: f32 = v364 * v320;
            let v370: f32 = v336 * v369;
            let v371: f32 = v368 - v370;
            let v372: f32 = v365 + v371;
            let v373: f32 = v363 + v372;
            let v374: f32 = v355 * v373;
            let v375: f32 = 0.336_f32;
            let v376: f32 = v366 * v333;
            let v377: f32 = v320 * v369;
            let v378: f32 = v364 * v331;
            let v379: f32 = v366 * v336;
            let v380: f32 = v378 + v379;
            let v381: f32 = v331 * v380;
            let v382: f32 = v377 + v381;
            let v383: f32 = v376 + v382;
            let v384: f32 = v303 + v383;
            let v385: f32 = v375 * v384;
            let v386: f32 = v374 + v385;
            let v387: f32 = v354 + v386;
            let v388: f32 = 0.00209602_f32;
            let v389: f32 = v12 * v323;
            let v390: f32 = v9 * v331;
            let v391: f32 = v12 * v336;
            let v392: f32 = v390 + v391;
            let v393: f32 = qd[3];
            let v394: f32 = v392 * v393;
            let v395: f32 = v389 - v394;
            let v396: f32 = v388 * v395;
            let v397: f32 = v320 + v393;
            let v398: f32 = v388 * v392;
            let v399: f32 = v397 * v398;
            let v400: f32 = 0.0013_f32;
            let v401: f32 = v400 * v397;
            let v402: f32 = v392 * v401;
            let v403: f32 = v399 - v402;
            let v404: f32 = v396 + v403;
            let v405: f32 = 0.01558_f32;
            let v406: f32 = v43 * v361;
            let v407: f32 = v29 * v310;
            let v408: f32 = v406 + v407;
            let v409: f32 = v364 * v333;
            let v410: f32 = v336 * v380;
            let v411: f32 = v320 * v367;
            let v412: f32 = v410 + v411;
            let v413: f32 = v409 - v412;
            let v414: f32 = v408 + v413;
            let v415: f32 = v9 * v414;
            let v416: f32 = v12 * v384;
            let v417: f32 = v415 + v416;
            let v418: f32 = v299 * v395;
            let v419: f32 = v299 * v392;
            let v420: f32 = v397 * v419;
            let v421: f32 = v418 + v420;
            let v422: f32 = v417 + v421;
            let v423: f32 = v405 * v422;
            let v424: f32 = v404 + v423;
            let v425: f32 = 0.0003_f32;
            let v426: f32 = v3 * v395;
            let v427: f32 = v15 * v333;
            let v428: f32 = v426 - v427;
            let v429: f32 = v3 * v397;
            let v430: f32 = v12 * v331;
            let v431: f32 = v9 * v336;
            let v432: f32 = v430 - v431;
            let v433: f32 = v15 * v432;
            let v434: f32 = v429 - v433;
            let v435: f32 = qd[4];
            let v436: f32 = v434 * v435;
            let v437: f32 = v428 + v436;
            let v438: f32 = v425 * v437;
            let v439: f32 = 0.0004_f32;
            let v440: f32 = v392 + v435;
            let v441: f32 = v439 * v440;
            let v442: f32 = v434 * v441;
            let v443: f32 = v425 * v434;
            let v444: f32 = v440 * v443;
            let v445: f32 = v442 - v444;
            let v446: f32 = v438 + v445;
            let v447: f32 = q[5];
            let (v451, v448): (f32, f32) = ::libm::sincosf(v447);
            let v449: f32 = 0.00024216_f32;
            let v450: f32 = v448 * v437;
            let v452: f32 = v9 * v323;
            let v453: f32 = v432 * v393;
            let v454: f32 = v452 + v453;
            let v455: f32 = v451 * v454;
            let v456: f32 = v450 - v455;
            let v457: f32 = v3 * v432;
            let v458: f32 = v15 * v397;
            let v459: f32 = v457 + v458;
            let v460: f32 = v451 * v459;
            let v461: f32 = v448 * v440;
            let v462: f32 = v460 + v461;
            let v463: f32 = qd[5];
            let v464: f32 = v462 * v463;
            let v465: f32 = v456 - v464;
            let v466: f32 = v449 * v465;
            let v467: f32 = v434 + v463;
            let v468: f32 = v449 * v462;
            let v469: f32 = v467 * v468;
            let v470: f32 = v257 * v467;
            let v471: f32 = v462 * v470;
            let v472: f32 = v469 - v471;
            let v473: f32 = v466 + v472;
            let v474: f32 = 0.00288_f32;
            let v475: f32 = v12 * v414;
            let v476: f32 = v9 * v384;
            let v477: f32 = v475 - v476;
            let v478: f32 = v299 * v432;
            let v479: f32 = v397 * v478;
            let v480: f32 = v299 * v454;
            let v481: f32 = v479 - v480;
            let v482: f32 = v477 + v481;
            let v483: f32 = v3 * v482;
            let v484: f32 = v392 * v419;
            let v485: f32 = v432 * v478;
            let v486: f32 = v484 + v485;
            let v487: f32 = v373 - v486;
            let v488: f32 = v15 * v487;
            let v489: f32 = v483 + v488;
            let v490: f32 = v451 * v489;
            let v491: f32 = v448 * v422;
            let v492: f32 = v490 + v491;
            let v493: f32 = v474 * v492;
            let v494: f32 = v473 + v493;
            let v495: f32 = v448 * v494;
            let v496: f32 = v448 * v459;
            let v497: f32 = v451 * v440;
            let v498: f32 = v496 - v497;
            let v499: f32 = v449 * v498;
            let v500: f32 = v467 * v499;
            let v501: f32 = v498 * v470;
            let v502: f32 = v500 - v501;
            let v503: f32 = v451 * v437;
            let v504: f32 = v448 * v454;
            let v505: f32 = v503 + v504;
            let v506: f32 = v498 * v463;
            (
                v338,
                v341,
                v343,
                v345,
                v351,
                v355,
                v361,
                v364,
                v366,
                v373,
                v375,
                v384,
                v387,
                v388,
                v392,
                v395,
                v397,
                v398,
                v400,
                v401,
                v405,
                v414,
                v422,
                v424,
                v425,
                v432,
                v434,
                v435,
                v439,
                v440,
                v441,
                v443,
                v446,
                v448,
                v449,
                v451,
                v454,
                v459,
                v462,
                v465,
                v467,
                v468,
                v474,
                v482,
                v487,
                v489,
                v492,
                v494,
                v495,
                v498,
                v499,
                v502,
                v505,
                v506,
            )
        };
        let (
            v534,
            v565,
            v567,
            v585,
            v611,
            v613,
            v617,
            v620,
            v623,
            v627,
            v641,
            v643,
            v644,
            v653,
            v669,
            v670,
            v673,
            v674,
            v675,
        ) = {
            let v507: f32 = v505 + v506;
            let v508: f32 = v449 * v507;
            let v509: f32 = v502 - v508;
            let v510: f32 = v448 * v489;
            let v511: f32 = v451 * v422;
            let v512: f32 = v510 - v511;
            let v513: f32 = v474 * v512;
            let v514: f32 = v509 + v513;
            let v515: f32 = v451 * v514;
            let v516: f32 = v495 - v515;
            let v517: f32 = v446 + v516;
            let v518: f32 = v3 * v517;
            let v519: f32 = v425 * v459;
            let v520: f32 = v440 * v519;
            let v521: f32 = v459 * v441;
            let v522: f32 = v520 - v521;
            let v523: f32 = v15 * v395;
            let v524: f32 = v3 * v333;
            let v525: f32 = v523 + v524;
            let v526: f32 = v459 * v435;
            let v527: f32 = v525 + v526;
            let v528: f32 = v425 * v527;
            let v529: f32 = v522 - v528;
            let v530: f32 = v462 * v499;
            let v531: f32 = v498 * v468;
            let v532: f32 = v530 - v531;
            let v533: f32 = v257 * v527;
            let v534: f32 = v532 - v533;
            let v535: f32 = v529 + v534;
            let v536: f32 = v15 * v535;
            let v537: f32 = v518 - v536;
            let v538: f32 = v424 + v537;
            let v539: f32 = 0.82_f32;
            let v540: f32 = v539 * v422;
            let v541: f32 = v405 * v395;
            let v542: f32 = v405 * v392;
            let v543: f32 = v397 * v542;
            let v544: f32 = v541 + v543;
            let v545: f32 = v540 + v544;
            let v546: f32 = 0.09_f32;
            let v547: f32 = v546 * v512;
            let v548: f32 = v474 * v498;
            let v549: f32 = v467 * v548;
            let v550: f32 = v474 * v507;
            let v551: f32 = v549 - v550;
            let v552: f32 = v547 + v551;
            let v553: f32 = v451 * v552;
            let v554: f32 = v546 * v492;
            let v555: f32 = v474 * v465;
            let v556: f32 = v474 * v462;
            let v557: f32 = v467 * v556;
            let v558: f32 = v555 + v557;
            let v559: f32 = v554 + v558;
            let v560: f32 = v448 * v559;
            let v561: f32 = v553 - v560;
            let v562: f32 = 0.34_f32;
            let v563: f32 = v562 * v422;
            let v564: f32 = v561 - v563;
            let v565: f32 = v545 - v564;
            let v566: f32 = v299 * v565;
            let v567: f32 = v538 + v566;
            let v568: f32 = v12 * v567;
            let v569: f32 = v388 * v454;
            let v570: f32 = v432 * v401;
            let v571: f32 = v388 * v432;
            let v572: f32 = v397 * v571;
            let v573: f32 = v570 - v572;
            let v574: f32 = v569 + v573;
            let v575: f32 = v405 * v482;
            let v576: f32 = v574 - v575;
            let v577: f32 = v434 * v519;
            let v578: f32 = v459 * v443;
            let v579: f32 = v577 - v578;
            let v580: f32 = v439 * v454;
            let v581: f32 = v579 - v580;
            let v582: f32 = v451 * v494;
            let v583: f32 = v448 * v514;
            let v584: f32 = v582 + v583;
            let v585: f32 = v581 + v584;
            let v586: f32 = v576 - v585;
            let v587: f32 = v539 * v482;
            let v588: f32 = v405 * v432;
            let v589: f32 = v397 * v588;
            let v590: f32 = v405 * v454;
            let v591: f32 = v589 - v590;
            let v592: f32 = v587 + v591;
            let v593: f32 = v562 * v489;
            let v594: f32 = v448 * v552;
            let v595: f32 = v451 * v559;
            let v596: f32 = v594 + v595;
            let v597: f32 = v593 + v596;
            let v598: f32 = v3 * v597;
            let v599: f32 = v3 * v487;
            let v600: f32 = v15 * v482;
            let v601: f32 = v599 - v600;
            let v602: f32 = v562 * v601;
            let v603: f32 = v546 * v601;
            let v604: f32 = v498 * v548;
            let v605: f32 = v462 * v556;
            let v606: f32 = v604 + v605;
            let v607: f32 = v603 - v606;
            let v608: f32 = v602 + v607;
            let v609: f32 = v15 * v608;
            let v610: f32 = v598 - v609;
            let v611: f32 = v592 + v610;
            let v612: f32 = v299 * v611;
            let v613: f32 = v586 - v612;
            let v614: f32 = v9 * v613;
            let v615: f32 = v568 + v614;
            let v616: f32 = v387 + v615;
            let v617: f32 = 4.8_f32;
            let v618: f32 = v617 * v373;
            let v619: f32 = v355 * v323;
            let v620: f32 = -0.09744_f32;
            let v621: f32 = v620 * v320;
            let v622: f32 = v375 * v331;
            let v623: f32 = v621 - v622;
            let v624: f32 = v331 * v623;
            let v625: f32 = v375 * v336;
            let v626: f32 = v355 * v320;
            let v627: f32 = v625 + v626;
            let v628: f32 = v336 * v627;
            let v629: f32 = v624 - v628;
            let v630: f32 = v619 + v629;
            let v631: f32 = v618 + v630;
            let v632: f32 = v539 * v487;
            let v633: f32 = v392 * v542;
            let v634: f32 = v432 * v588;
            let v635: f32 = v633 + v634;
            let v636: f32 = v632 - v635;
            let v637: f32 = v15 * v597;
            let v638: f32 = v3 * v608;
            let v639: f32 = v637 + v638;
            let v640: f32 = v636 + v639;
            let v641: f32 = v631 + v640;
            let v642: f32 = v364 * v641;
            let v643: f32 = v616 + v642;
            let v644: f32 = v43 * v643;
            let v645: f32 = v325 * v323;
            let v646: f32 = v341 * v333;
            let v647: f32 = v645 - v646;
            let v648: f32 = v331 * v351;
            let v649: f32 = v314 * v331;
            let v650: f32 = v345 * v336;
            let v651: f32 = v649 - v650;
            let v652: f32 = v325 * v320;
            let v653: f32 = v651 + v652;
            let v654: f32 = v336 * v653;
            let v655: f32 = v648 + v654;
            let v656: f32 = v647 + v655;
            let v657: f32 = v620 * v384;
            let v658: f32 = v355 * v414;
            let v659: f32 = v657 + v658;
            let v660: f32 = v656 - v659;
            let v661: f32 = v392 * v571;
            let v662: f32 = v432 * v398;
            let v663: f32 = v661 - v662;
            let v664: f32 = v400 * v333;
            let v665: f32 = v663 - v664;
            let v666: f32 = v15 * v517;
            let v667: f32 = v3 * v535;
            let v668: f32 = v666 + v667;
            let v669: f32 = v665 + v668;
            let v670: f32 = v660 + v669;
            let v671: f32 = v9 * v611;
            let v672: f32 = v12 * v565;
            let v673: f32 = v671 - v672;
            let v674: f32 = v617 * v384;
            let v675: f32 = v620 * v333;
            (
                v534,
                v565,
                v567,
                v585,
                v611,
                v613,
                v617,
                v620,
                v623,
                v627,
                v641,
                v643,
                v644,
                v653,
                v669,
                v670,
                v673,
                v674,
                v675,
            )
        };
        let (v747, v761, v776, v779, v787, v788, v833, v837, v841, v842, v843, v844) = {
            let v676: f32 = v375 * v323;
            let v677: f32 = v675 + v676;
            let v678: f32 = v320 * v627;
            let v679: f32 = v355 * v331;
            let v680: f32 = v620 * v336;
            let v681: f32 = v679 + v680;
            let v682: f32 = v331 * v681;
            let v683: f32 = v678 + v682;
            let v684: f32 = v677 + v683;
            let v685: f32 = v674 + v684;
            let v686: f32 = v673 - v685;
            let v687: f32 = v366 * v686;
            let v688: f32 = v617 * v414;
            let v689: f32 = v355 * v333;
            let v690: f32 = v336 * v681;
            let v691: f32 = v320 * v623;
            let v692: f32 = v690 + v691;
            let v693: f32 = v689 - v692;
            let v694: f32 = v688 + v693;
            let v695: f32 = v12 * v611;
            let v696: f32 = v9 * v565;
            let v697: f32 = v695 + v696;
            let v698: f32 = v694 + v697;
            let v699: f32 = v364 * v698;
            let v700: f32 = v687 - v699;
            let v701: f32 = v670 + v700;
            let v702: f32 = v29 * v701;
            let v703: f32 = v644 - v702;
            let v704: f32 = v313 + v703;
            let v705: f32 = v59 * v704;
            let v706: f32 = v276 * v274;
            let v707: f32 = v290 * v278;
            let v708: f32 = v706 - v707;
            let v709: f32 = v270 * v277;
            let v710: f32 = v276 * v272;
            let v711: f32 = v709 + v710;
            let v712: f32 = v281 * v273;
            let v713: f32 = v711 + v712;
            let v714: f32 = v273 * v713;
            let v715: f32 = v277 * v287;
            let v716: f32 = v714 - v715;
            let v717: f32 = v708 + v716;
            let v718: f32 = v305 * v361;
            let v719: f32 = -6.33012_f32;
            let v720: f32 = v719 * v303;
            let v721: f32 = v718 - v720;
            let v722: f32 = v717 + v721;
            let v723: f32 = v29 * v643;
            let v724: f32 = v43 * v701;
            let v725: f32 = v723 + v724;
            let v726: f32 = v722 + v725;
            let v727: f32 = 17.4_f32;
            let v728: f32 = v727 * v303;
            let v729: f32 = v298 * v274;
            let v730: f32 = v719 * v278;
            let v731: f32 = v729 + v730;
            let v732: f32 = v719 * v273;
            let v733: f32 = v305 * v277;
            let v734: f32 = v732 - v733;
            let v735: f32 = v277 * v734;
            let v736: f32 = v305 * v272;
            let v737: f32 = v298 * v273;
            let v738: f32 = v736 - v737;
            let v739: f32 = v272 * v738;
            let v740: f32 = v735 - v739;
            let v741: f32 = v731 + v740;
            let v742: f32 = v728 + v741;
            let v743: f32 = v742 - v686;
            let v744: f32 = v299 * v743;
            let v745: f32 = v726 - v744;
            let v746: f32 = v78 * v745;
            let v747: f32 = v705 + v746;
            let v748: f32 = 2.107104_f32;
            let v749: f32 = v50 * v43;
            let v750: f32 = v748 + v749;
            let v751: f32 = v750 - v63;
            let v752: f32 = v33 - v53;
            let v753: f32 = v752 * v3;
            let v754: f32 = v751 + v753;
            let v755: f32 = -0.000116928_f32;
            let v756: f32 = v32 * v43;
            let v757: f32 = v755 - v756;
            let v758: f32 = v757 * v15;
            let v759: f32 = v758 + v153;
            let v760: f32 = v759 * v12;
            let v761: f32 = v754 + v760;
            let v762: f32 = 0.35899007_f32;
            let v763: f32 = 0.010956925_f32;
            let v764: f32 = v763 * v43;
            let v765: f32 = v762 + v764;
            let v766: f32 = 0.38487628_f32;
            let v767: f32 = v766 * v29;
            let v768: f32 = v765 - v767;
            let v769: f32 = v33 - v249;
            let v770: f32 = v769 * v3;
            let v771: f32 = v768 + v770;
            let v772: f32 = v755 - v246;
            let v773: f32 = v772 * v15;
            let v774: f32 = v773 + v153;
            let v775: f32 = v774 * v12;
            let v776: f32 = v771 + v775;
            let v777: f32 = v142 + v249;
            let v778: f32 = v777 * v15;
            let v779: f32 = v778 * v9;
            let v780: f32 = -5.8464e-5_f32;
            let v781: f32 = v780 - v246;
            let v782: f32 = v781 * v15;
            let v783: f32 = v172 - v249;
            let v784: f32 = v783 * v3;
            let v785: f32 = v240 + v784;
            let v786: f32 = v785 * v12;
            let v787: f32 = v782 + v786;
            let v788: f32 = v260 * v9;
            let v789: f32 = v281 * v274;
            let v790: f32 = v136 * v278;
            let v791: f32 = v789 - v790;
            let v792: f32 = v277 * v294;
            let v793: f32 = v272 * v713;
            let v794: f32 = v792 - v793;
            let v795: f32 = v791 + v794;
            let v796: f32 = v719 * v310;
            let v797: f32 = v298 * v361;
            let v798: f32 = v796 - v797;
            let v799: f32 = v795 + v798;
            let v800: f32 = v345 * v323;
            let v801: f32 = v338 * v333;
            let v802: f32 = v800 - v801;
            let v803: f32 = v320 * v653;
            let v804: f32 = v331 * v343;
            let v805: f32 = v803 - v804;
            let v806: f32 = v802 + v805;
            let v807: f32 = v375 * v414;
            let v808: f32 = v620 * v373;
            let v809: f32 = v807 - v808;
            let v810: f32 = v806 + v809;
            let v811: f32 = v9 * v567;
            let v812: f32 = v12 * v613;
            let v813: f32 = v811 - v812;
            let v814: f32 = v810 + v813;
            let v815: f32 = v366 * v641;
            let v816: f32 = v814 - v815;
            let v817: f32 = v799 - v816;
            let v818: f32 = v727 * v310;
            let v819: f32 = v273 * v738;
            let v820: f32 = v298 * v277;
            let v821: f32 = v719 * v272;
            let v822: f32 = v820 - v821;
            let v823: f32 = v277 * v822;
            let v824: f32 = v819 - v823;
            let v825: f32 = v305 * v274;
            let v826: f32 = v824 - v825;
            let v827: f32 = v818 + v826;
            let v828: f32 = v29 * v698;
            let v829: f32 = v43 * v641;
            let v830: f32 = v828 + v829;
            let v831: f32 = v827 + v830;
            let v832: f32 = v299 * v831;
            let v833: f32 = v817 + v832;
            let v834: f32 = v762 + v34;
            let v835: f32 = v153 - v36;
            let v836: f32 = v835 * v12;
            let v837: f32 = v834 + v836;
            let v838: f32 = v172 * v3;
            let v839: f32 = v240 + v838;
            let v840: f32 = v839 * v12;
            let v841: f32 = v840 - v155;
            let v842: f32 = -v816;
            let v843: f32 = 0.0_f32;
            let v844: f32 = -v585;
            (v747, v761, v776, v779, v787, v788, v833, v837, v841, v842, v843, v844)
        };
        [
            [v135, v181, v205, v229, v256, v269, v747],
            [v181, v761, v776, v779, v787, v788, v833],
            [v205, v776, v837, v144, v841, v788, v842],
            [v229, v779, v144, v207, v843, v258, v669],
            [v256, v787, v841, v843, v240, v843, v844],
            [v269, v788, v788, v258, v843, v257, v534],
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
    /// Operation count: 1216 floating-point operations, 10 trig calls.
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
            v5,
            v7,
            v10,
            v17,
            v23,
            v25,
            v28,
            v30,
            v33,
            v41,
            v43,
            v47,
            v48,
            v51,
            v53,
            v57,
            v65,
            v73,
            v76,
            v81,
            v82,
            v83,
            v85,
            v87,
            v92,
            v95,
            v99,
            v104,
            v110,
            v113,
            v115,
            v126,
            v127,
            v137,
            v140,
            v141,
            v147,
            v150,
            v151,
            v153,
            v164,
            v168,
            v176,
            v178,
        ) = {
            let v0: f32 = qdd[0];
            let v1: f32 = q[1];
            let (v2, v9): (f32, f32) = ::libm::sincosf(v1);
            let v3: f32 = qd[0];
            let v4: f32 = v2 * v3;
            let v5: f32 = 0.4318_f32;
            let v6: f32 = qd[1];
            let v7: f32 = v5 * v6;
            let v8: f32 = v4 * v7;
            let v10: f32 = v9 * v0;
            let v11: f32 = v4 * v6;
            let v12: f32 = v10 - v11;
            let v13: f32 = v5 * v12;
            let v14: f32 = v8 - v13;
            let v15: f32 = v5 * v9;
            let v16: f32 = v14 * v15;
            let v17: f32 = -v16;
            let v18: f32 = v12 * v15;
            let v19: f32 = v4 * v15;
            let v20: f32 = v6 * v19;
            let v21: f32 = v18 - v20;
            let v22: f32 = v14 * v9;
            let v23: f32 = v21 - v22;
            let v24: f32 = v14 * v2;
            let v25: f32 = v9 * v3;
            let v26: f32 = v25 * v15;
            let v27: f32 = v6 * v26;
            let v28: f32 = v2 * v0;
            let v29: f32 = v25 * v6;
            let v30: f32 = v28 + v29;
            let v31: f32 = v30 * v15;
            let v32: f32 = v27 + v31;
            let v33: f32 = v24 - v32;
            let v34: f32 = v25 * v26;
            let v35: f32 = v4 * v19;
            let v36: f32 = v34 + v35;
            let v37: f32 = 9.81_f32;
            let v38: f32 = v37 * v2;
            let v39: f32 = v5 * v25;
            let v40: f32 = v25 * v39;
            let v41: f32 = v6 * v7;
            let v42: f32 = v40 + v41;
            let v43: f32 = v38 - v42;
            let v44: f32 = v43 * v9;
            let v45: f32 = v36 + v44;
            let v46: f32 = v37 * v9;
            let v47: f32 = qdd[1];
            let v48: f32 = v5 * v47;
            let v49: f32 = v4 * v39;
            let v50: f32 = v48 + v49;
            let v51: f32 = v46 + v50;
            let v52: f32 = v51 * v2;
            let v53: f32 = v45 - v52;
            let v54: f32 = v6 * v9;
            let v55: f32 = v4 * v54;
            let v56: f32 = v30 * v2;
            let v57: f32 = v55 + v56;
            let v58: f32 = v25 * v54;
            let v59: f32 = v30 * v9;
            let v60: f32 = v58 + v59;
            let v61: f32 = v6 * v2;
            let v62: f32 = v4 * v61;
            let v63: f32 = v60 - v62;
            let v64: f32 = v12 * v2;
            let v65: f32 = v63 + v64;
            let v66: f32 = v6 * v54;
            let v67: f32 = v25 * v2;
            let v68: f32 = v4 * v9;
            let v69: f32 = v67 - v68;
            let v70: f32 = v4 * v69;
            let v71: f32 = v66 + v70;
            let v72: f32 = v47 * v2;
            let v73: f32 = v71 + v72;
            let v74: f32 = v12 * v9;
            let v75: f32 = v25 * v61;
            let v76: f32 = v74 - v75;
            let v77: f32 = v47 * v9;
            let v78: f32 = v6 * v61;
            let v79: f32 = v77 - v78;
            let v80: f32 = v25 * v69;
            let v81: f32 = v79 + v80;
            let v82: f32 = v6 * v69;
            let v83: f32 = 0.0203_f32;
            let v84: f32 = q[2];
            let (v87, v85): (f32, f32) = ::libm::sincosf(v84);
            let v86: f32 = v85 * v12;
            let v88: f32 = v87 * v30;
            let v89: f32 = v86 - v88;
            let v90: f32 = v85 * v4;
            let v91: f32 = v87 * v25;
            let v92: f32 = v90 + v91;
            let v93: f32 = qd[2];
            let v94: f32 = v92 * v93;
            let v95: f32 = v89 - v94;
            let v96: f32 = v83 * v95;
            let v97: f32 = v85 * v25;
            let v98: f32 = v87 * v4;
            let v99: f32 = v97 - v98;
            let v100: f32 = -0.15005_f32;
            let v101: f32 = v100 * v99;
            let v102: f32 = v99 * v101;
            let v103: f32 = v100 * v92;
            let v104: f32 = v6 + v93;
            let v105: f32 = v83 * v104;
            let v106: f32 = v103 + v105;
            let v107: f32 = v92 * v106;
            let v108: f32 = v102 + v107;
            let v109: f32 = v96 - v108;
            let v110: f32 = v109 - v14;
            let v111: f32 = v85 * v9;
            let v112: f32 = v87 * v2;
            let v113: f32 = v111 - v112;
            let v114: f32 = v83 * v113;
            let v115: f32 = v15 + v114;
            let v116: f32 = v110 * v115;
            let v117: f32 = v85 * v43;
            let v118: f32 = v87 * v51;
            let v119: f32 = v117 + v118;
            let v120: f32 = v100 * v95;
            let v121: f32 = v104 * v106;
            let v122: f32 = v83 * v99;
            let v123: f32 = v99 * v122;
            let v124: f32 = v121 + v123;
            let v125: f32 = v120 + v124;
            let v126: f32 = v119 - v125;
            let v127: f32 = v100 * v113;
            let v128: f32 = v126 * v127;
            let v129: f32 = v116 - v128;
            let v130: f32 = v85 * v51;
            let v131: f32 = v87 * v43;
            let v132: f32 = v130 - v131;
            let v133: f32 = v85 * v30;
            let v134: f32 = v87 * v12;
            let v135: f32 = v133 + v134;
            let v136: f32 = v99 * v93;
            let v137: f32 = v135 + v136;
            let v138: f32 = v100 * v137;
            let v139: f32 = qdd[2];
            let v140: f32 = v47 + v139;
            let v141: f32 = v83 * v140;
            let v142: f32 = v138 + v141;
            let v143: f32 = v92 * v122;
            let v144: f32 = v104 * v101;
            let v145: f32 = v143 - v144;
            let v146: f32 = v142 + v145;
            let v147: f32 = v132 + v146;
            let v148: f32 = v87 * v9;
            let v149: f32 = v85 * v2;
            let v150: f32 = v148 + v149;
            let v151: f32 = v100 * v150;
            let v152: f32 = v147 * v151;
            let v153: f32 = v129 + v152;
            let v154: f32 = v104 * v127;
            let v155: f32 = v92 * v115;
            let v156: f32 = v154 - v155;
            let v157: f32 = v104 * v156;
            let v158: f32 = v95 * v115;
            let v159: f32 = v157 + v158;
            let v160: f32 = v110 * v113;
            let v161: f32 = v159 + v160;
            let v162: f32 = v99 * v127;
            let v163: f32 = v92 * v151;
            let v164: f32 = v162 + v163;
            let v165: f32 = v99 * v164;
            let v166: f32 = v161 + v165;
            let v167: f32 = v140 * v151;
            let v168: f32 = v166 + v167;
            let v169: f32 = v95 * v127;
            let v170: f32 = v92 * v156;
            let v171: f32 = v169 + v170;
            let v172: f32 = v126 * v113;
            let v173: f32 = v171 - v172;
            let v174: f32 = v99 * v115;
            let v175: f32 = v104 * v151;
            let v176: f32 = v174 + v175;
            let v177: f32 = v99 * v176;
            let v178: f32 = v173 - v177;
            (
                v0,
                v4,
                v5,
                v7,
                v10,
                v17,
                v23,
                v25,
                v28,
                v30,
                v33,
                v41,
                v43,
                v47,
                v48,
                v51,
                v53,
                v57,
                v65,
                v73,
                v76,
                v81,
                v82,
                v83,
                v85,
                v87,
                v92,
                v95,
                v99,
                v104,
                v110,
                v113,
                v115,
                v126,
                v127,
                v137,
                v140,
                v141,
                v147,
                v150,
                v151,
                v153,
                v164,
                v168,
                v176,
                v178,
            )
        };
        let (
            v182,
            v191,
            v195,
            v203,
            v211,
            v213,
            v218,
            v221,
            v223,
            v225,
            v227,
            v232,
            v236,
            v242,
            v248,
            v251,
            v255,
            v257,
            v267,
            v271,
            v272,
            v277,
            v278,
            v279,
            v296,
            v298,
            v312,
            v323,
            v329,
            v339,
            v345,
            v349,
            v352,
            v357,
        ) = {
            let v179: f32 = v137 * v151;
            let v180: f32 = v178 + v179;
            let v181: f32 = v147 * v150;
            let v182: f32 = v180 + v181;
            let v183: f32 = v140 * v127;
            let v184: f32 = v137 * v115;
            let v185: f32 = v183 - v184;
            let v186: f32 = v104 * v176;
            let v187: f32 = v185 - v186;
            let v188: f32 = v92 * v164;
            let v189: f32 = v187 - v188;
            let v190: f32 = v110 * v150;
            let v191: f32 = v189 - v190;
            let v192: f32 = v104 * v113;
            let v193: f32 = v92 * v192;
            let v194: f32 = v137 * v150;
            let v195: f32 = v193 + v194;
            let v196: f32 = v92 * v113;
            let v197: f32 = v99 * v150;
            let v198: f32 = v196 - v197;
            let v199: f32 = v92 * v198;
            let v200: f32 = v104 * v192;
            let v201: f32 = v199 - v200;
            let v202: f32 = v140 * v150;
            let v203: f32 = v201 - v202;
            let v204: f32 = v99 * v192;
            let v205: f32 = v137 * v113;
            let v206: f32 = v204 + v205;
            let v207: f32 = v104 * v150;
            let v208: f32 = v92 * v207;
            let v209: f32 = v206 - v208;
            let v210: f32 = v95 * v150;
            let v211: f32 = v209 + v210;
            let v212: f32 = v104 * v198;
            let v213: f32 = -v212;
            let v214: f32 = v99 * v198;
            let v215: f32 = v140 * v113;
            let v216: f32 = v214 - v215;
            let v217: f32 = v104 * v207;
            let v218: f32 = v216 + v217;
            let v219: f32 = v95 * v113;
            let v220: f32 = v99 * v207;
            let v221: f32 = v219 - v220;
            let v222: f32 = q[3];
            let (v223, v225): (f32, f32) = ::libm::sincosf(v222);
            let v224: f32 = v223 * v92;
            let v226: f32 = v225 * v104;
            let v227: f32 = v224 + v226;
            let v228: f32 = v5 * v227;
            let v229: f32 = v227 * v228;
            let v230: f32 = v225 * v92;
            let v231: f32 = v223 * v104;
            let v232: f32 = v230 - v231;
            let v233: f32 = v5 * v232;
            let v234: f32 = v232 * v233;
            let v235: f32 = v229 + v234;
            let v236: f32 = v147 - v235;
            let v237: f32 = v236 * v151;
            let v238: f32 = v225 * v126;
            let v239: f32 = v223 * v110;
            let v240: f32 = v238 + v239;
            let v241: f32 = qd[3];
            let v242: f32 = v99 + v241;
            let v243: f32 = v242 * v233;
            let v244: f32 = v223 * v137;
            let v245: f32 = v225 * v140;
            let v246: f32 = v244 + v245;
            let v247: f32 = v232 * v241;
            let v248: f32 = v246 + v247;
            let v249: f32 = v5 * v248;
            let v250: f32 = v243 - v249;
            let v251: f32 = v240 + v250;
            let v252: f32 = v223 * v115;
            let v253: f32 = v225 * v127;
            let v254: f32 = v252 - v253;
            let v255: f32 = v223 * v150;
            let v256: f32 = v5 * v255;
            let v257: f32 = v254 - v256;
            let v258: f32 = v251 * v257;
            let v259: f32 = v237 + v258;
            let v260: f32 = v223 * v126;
            let v261: f32 = v225 * v110;
            let v262: f32 = v260 - v261;
            let v263: f32 = v225 * v137;
            let v264: f32 = v223 * v140;
            let v265: f32 = v263 - v264;
            let v266: f32 = v227 * v241;
            let v267: f32 = v265 - v266;
            let v268: f32 = v5 * v267;
            let v269: f32 = v242 * v228;
            let v270: f32 = v268 + v269;
            let v271: f32 = v262 + v270;
            let v272: f32 = v225 * v150;
            let v273: f32 = v5 * v272;
            let v274: f32 = v223 * v127;
            let v275: f32 = v225 * v115;
            let v276: f32 = v274 + v275;
            let v277: f32 = v273 - v276;
            let v278: f32 = v271 * v277;
            let v279: f32 = v259 + v278;
            let v280: f32 = v248 * v151;
            let v281: f32 = v271 * v113;
            let v282: f32 = v280 - v281;
            let v283: f32 = v242 * v257;
            let v284: f32 = v232 * v151;
            let v285: f32 = v283 - v284;
            let v286: f32 = v242 * v285;
            let v287: f32 = v282 - v286;
            let v288: f32 = v236 * v255;
            let v289: f32 = v287 + v288;
            let v290: f32 = v232 * v277;
            let v291: f32 = v227 * v257;
            let v292: f32 = v290 - v291;
            let v293: f32 = v227 * v292;
            let v294: f32 = v289 + v293;
            let v295: f32 = qdd[3];
            let v296: f32 = v95 + v295;
            let v297: f32 = v296 * v277;
            let v298: f32 = v294 - v297;
            let v299: f32 = v232 * v285;
            let v300: f32 = v248 * v257;
            let v301: f32 = v299 - v300;
            let v302: f32 = v251 * v255;
            let v303: f32 = v301 - v302;
            let v304: f32 = v227 * v151;
            let v305: f32 = v242 * v277;
            let v306: f32 = v304 - v305;
            let v307: f32 = v227 * v306;
            let v308: f32 = v303 - v307;
            let v309: f32 = v267 * v277;
            let v310: f32 = v308 + v309;
            let v311: f32 = v271 * v272;
            let v312: f32 = v310 + v311;
            let v313: f32 = v251 * v113;
            let v314: f32 = v267 * v151;
            let v315: f32 = v313 - v314;
            let v316: f32 = v296 * v257;
            let v317: f32 = v315 + v316;
            let v318: f32 = v242 * v306;
            let v319: f32 = v317 + v318;
            let v320: f32 = v232 * v292;
            let v321: f32 = v319 - v320;
            let v322: f32 = v236 * v272;
            let v323: f32 = v321 - v322;
            let v324: f32 = v227 * v113;
            let v325: f32 = v242 * v255;
            let v326: f32 = v324 - v325;
            let v327: f32 = v232 * v326;
            let v328: f32 = v267 * v272;
            let v329: f32 = v327 + v328;
            let v330: f32 = v267 * v113;
            let v331: f32 = v242 * v326;
            let v332: f32 = v330 + v331;
            let v333: f32 = v232 * v255;
            let v334: f32 = v227 * v272;
            let v335: f32 = v333 - v334;
            let v336: f32 = v232 * v335;
            let v337: f32 = v332 + v336;
            let v338: f32 = v296 * v272;
            let v339: f32 = v337 + v338;
            let v340: f32 = v227 * v326;
            let v341: f32 = v267 * v255;
            let v342: f32 = v340 + v341;
            let v343: f32 = v242 * v272;
            let v344: f32 = v232 * v113;
            let v345: f32 = v343 - v344;
            let v346: f32 = v232 * v345;
            let v347: f32 = v342 + v346;
            let v348: f32 = v248 * v272;
            let v349: f32 = v347 + v348;
            let v350: f32 = v296 * v113;
            let v351: f32 = v242 * v335;
            let v352: f32 = v350 + v351;
            let v353: f32 = v248 * v113;
            let v354: f32 = v296 * v255;
            let v355: f32 = v353 + v354;
            let v356: f32 = v227 * v335;
            let v357: f32 = v355 + v356;
            (
                v182,
                v191,
                v195,
                v203,
                v211,
                v213,
                v218,
                v221,
                v223,
                v225,
                v227,
                v232,
                v236,
                v242,
                v248,
                v251,
                v255,
                v257,
                v267,
                v271,
                v272,
                v277,
                v278,
                v279,
                v296,
                v298,
                v312,
                v323,
                v329,
                v339,
                v345,
                v349,
                v352,
                v357,
            )
        };
        let (
            v359,
            v362,
            v364,
            v366,
            v368,
            v371,
            v375,
            v381,
            v383,
            v387,
            v390,
            v399,
            v409,
            v414,
            v416,
            v421,
            v436,
            v438,
            v449,
            v455,
            v465,
            v475,
            v478,
            v485,
            v488,
            v490,
            v492,
            v494,
            v497,
            v502,
            v505,
            v507,
            v513,
            v514,
            v516,
            v519,
            v522,
            v525,
            v530,
            v533,
            v535,
            v536,
        ) = {
            let v358: f32 = v242 * v345;
            let v359: f32 = v357 + v358;
            let v360: f32 = v248 * v255;
            let v361: f32 = v227 * v345;
            let v362: f32 = v360 + v361;
            let v363: f32 = q[4];
            let (v366, v364): (f32, f32) = ::libm::sincosf(v363);
            let v365: f32 = v364 * v236;
            let v367: f32 = v366 * v251;
            let v368: f32 = v365 - v367;
            let v369: f32 = v364 * v151;
            let v370: f32 = v366 * v257;
            let v371: f32 = v369 - v370;
            let v372: f32 = v368 * v371;
            let v373: f32 = v364 * v251;
            let v374: f32 = v366 * v236;
            let v375: f32 = v373 + v374;
            let v376: f32 = v366 * v151;
            let v377: f32 = v364 * v257;
            let v378: f32 = v376 + v377;
            let v379: f32 = v375 * v378;
            let v380: f32 = v372 + v379;
            let v381: f32 = v380 + v278;
            let v382: f32 = qdd[4];
            let v383: f32 = v248 + v382;
            let v384: f32 = v383 * v371;
            let v385: f32 = v364 * v242;
            let v386: f32 = v366 * v232;
            let v387: f32 = v385 - v386;
            let v388: f32 = v364 * v232;
            let v389: f32 = v366 * v242;
            let v390: f32 = v388 + v389;
            let v391: f32 = v390 * v371;
            let v392: f32 = v387 * v378;
            let v393: f32 = v391 - v392;
            let v394: f32 = v387 * v393;
            let v395: f32 = v384 + v394;
            let v396: f32 = v368 * v255;
            let v397: f32 = v395 + v396;
            let v398: f32 = qd[4];
            let v399: f32 = v227 + v398;
            let v400: f32 = v390 * v277;
            let v401: f32 = v399 * v378;
            let v402: f32 = v400 - v401;
            let v403: f32 = v399 * v402;
            let v404: f32 = v397 + v403;
            let v405: f32 = v364 * v296;
            let v406: f32 = v366 * v267;
            let v407: f32 = v405 - v406;
            let v408: f32 = v390 * v398;
            let v409: f32 = v407 - v408;
            let v410: f32 = v409 * v277;
            let v411: f32 = v404 - v410;
            let v412: f32 = v364 * v113;
            let v413: f32 = v366 * v272;
            let v414: f32 = v412 - v413;
            let v415: f32 = v271 * v414;
            let v416: f32 = v411 - v415;
            let v417: f32 = v364 * v267;
            let v418: f32 = v366 * v296;
            let v419: f32 = v417 + v418;
            let v420: f32 = v387 * v398;
            let v421: f32 = v419 + v420;
            let v422: f32 = v421 * v371;
            let v423: f32 = v409 * v378;
            let v424: f32 = v422 - v423;
            let v425: f32 = v390 * v402;
            let v426: f32 = v424 + v425;
            let v427: f32 = v387 * v277;
            let v428: f32 = v399 * v371;
            let v429: f32 = v427 - v428;
            let v430: f32 = v387 * v429;
            let v431: f32 = v426 + v430;
            let v432: f32 = v375 * v414;
            let v433: f32 = v431 - v432;
            let v434: f32 = v366 * v113;
            let v435: f32 = v364 * v272;
            let v436: f32 = v434 + v435;
            let v437: f32 = v368 * v436;
            let v438: f32 = v433 + v437;
            let v439: f32 = v399 * v429;
            let v440: f32 = v390 * v393;
            let v441: f32 = v383 * v378;
            let v442: f32 = v440 + v441;
            let v443: f32 = v375 * v255;
            let v444: f32 = v442 + v443;
            let v445: f32 = v439 - v444;
            let v446: f32 = v421 * v277;
            let v447: f32 = v445 + v446;
            let v448: f32 = v271 * v436;
            let v449: f32 = v447 + v448;
            let v450: f32 = v399 * v414;
            let v451: f32 = v387 * v255;
            let v452: f32 = v450 - v451;
            let v453: f32 = v390 * v452;
            let v454: f32 = v421 * v436;
            let v455: f32 = v453 + v454;
            let v456: f32 = v390 * v414;
            let v457: f32 = v387 * v436;
            let v458: f32 = v456 - v457;
            let v459: f32 = v390 * v458;
            let v460: f32 = v421 * v255;
            let v461: f32 = v399 * v452;
            let v462: f32 = v460 + v461;
            let v463: f32 = v459 - v462;
            let v464: f32 = v383 * v436;
            let v465: f32 = v463 - v464;
            let v466: f32 = v387 * v452;
            let v467: f32 = v421 * v414;
            let v468: f32 = v466 + v467;
            let v469: f32 = v390 * v255;
            let v470: f32 = v399 * v436;
            let v471: f32 = v469 - v470;
            let v472: f32 = v390 * v471;
            let v473: f32 = v468 + v472;
            let v474: f32 = v409 * v436;
            let v475: f32 = v473 + v474;
            let v476: f32 = v383 * v255;
            let v477: f32 = v399 * v458;
            let v478: f32 = v476 - v477;
            let v479: f32 = v387 * v458;
            let v480: f32 = v409 * v255;
            let v481: f32 = v383 * v414;
            let v482: f32 = v480 + v481;
            let v483: f32 = v479 - v482;
            let v484: f32 = v399 * v471;
            let v485: f32 = v483 - v484;
            let v486: f32 = v409 * v414;
            let v487: f32 = v387 * v471;
            let v488: f32 = v486 + v487;
            let v489: f32 = q[5];
            let (v490, v492): (f32, f32) = ::libm::sincosf(v489);
            let v491: f32 = v490 * v375;
            let v493: f32 = v492 * v271;
            let v494: f32 = v491 + v493;
            let v495: f32 = v490 * v378;
            let v496: f32 = v492 * v277;
            let v497: f32 = v495 + v496;
            let v498: f32 = v494 * v497;
            let v499: f32 = v372 + v498;
            let v500: f32 = v492 * v375;
            let v501: f32 = v490 * v271;
            let v502: f32 = v500 - v501;
            let v503: f32 = v492 * v378;
            let v504: f32 = v490 * v277;
            let v505: f32 = v503 - v504;
            let v506: f32 = v502 * v505;
            let v507: f32 = v499 + v506;
            let v508: f32 = v490 * v421;
            let v509: f32 = v492 * v383;
            let v510: f32 = v508 + v509;
            let v511: f32 = v492 * v390;
            let v512: f32 = v490 * v399;
            let v513: f32 = v511 - v512;
            let v514: f32 = qd[5];
            let v515: f32 = v513 * v514;
            let v516: f32 = v510 + v515;
            let v517: f32 = v516 * v371;
            let v518: f32 = qdd[5];
            let v519: f32 = v409 + v518;
            let v520: f32 = v519 * v497;
            let v521: f32 = v517 - v520;
            let v522: f32 = v387 + v514;
            let v523: f32 = v513 * v371;
            let v524: f32 = v522 * v505;
            let v525: f32 = v523 - v524;
            let v526: f32 = v522 * v525;
            let v527: f32 = v521 + v526;
            let v528: f32 = v490 * v390;
            let v529: f32 = v492 * v399;
            let v530: f32 = v528 + v529;
            let v531: f32 = v513 * v497;
            let v532: f32 = v530 * v505;
            let v533: f32 = v531 - v532;
            let v534: f32 = v530 * v533;
            let v535: f32 = v527 + v534;
            let v536: f32 = v494 * v414;
            (
                v359,
                v362,
                v364,
                v366,
                v368,
                v371,
                v375,
                v381,
                v383,
                v387,
                v390,
                v399,
                v409,
                v414,
                v416,
                v421,
                v436,
                v438,
                v449,
                v455,
                v465,
                v475,
                v478,
                v485,
                v488,
                v490,
                v492,
                v494,
                v497,
                v502,
                v505,
                v507,
                v513,
                v514,
                v516,
                v519,
                v522,
                v525,
                v530,
                v533,
                v535,
                v536,
            )
        };
        let (
            v542,
            v547,
            v564,
            v575,
            v581,
            v591,
            v601,
            v604,
            v611,
            v614,
            v615,
            v620,
            v623,
            v626,
            v628,
            v631,
            v632,
            v636,
            v638,
            v648,
            v656,
            v663,
            v665,
            v667,
            v670,
            v673,
            v674,
            v677,
            v678,
            v682,
            v683,
            v684,
            v685,
            v692,
            v696,
            v700,
            v704,
            v708,
            v713,
            v714,
            v715,
        ) = {
            let v537: f32 = v535 - v536;
            let v538: f32 = v492 * v255;
            let v539: f32 = v490 * v436;
            let v540: f32 = v538 + v539;
            let v541: f32 = v368 * v540;
            let v542: f32 = v537 + v541;
            let v543: f32 = v492 * v421;
            let v544: f32 = v490 * v383;
            let v545: f32 = v543 - v544;
            let v546: f32 = v530 * v514;
            let v547: f32 = v545 - v546;
            let v548: f32 = v547 * v371;
            let v549: f32 = v522 * v497;
            let v550: f32 = v530 * v371;
            let v551: f32 = v549 - v550;
            let v552: f32 = v522 * v551;
            let v553: f32 = v548 + v552;
            let v554: f32 = v513 * v533;
            let v555: f32 = v553 + v554;
            let v556: f32 = v519 * v505;
            let v557: f32 = v555 - v556;
            let v558: f32 = v502 * v414;
            let v559: f32 = v557 - v558;
            let v560: f32 = v492 * v436;
            let v561: f32 = v490 * v255;
            let v562: f32 = v560 - v561;
            let v563: f32 = v368 * v562;
            let v564: f32 = v559 + v563;
            let v565: f32 = v530 * v551;
            let v566: f32 = v547 * v497;
            let v567: f32 = v565 + v566;
            let v568: f32 = v513 * v525;
            let v569: f32 = v567 - v568;
            let v570: f32 = v516 * v505;
            let v571: f32 = v569 - v570;
            let v572: f32 = v502 * v540;
            let v573: f32 = v571 - v572;
            let v574: f32 = v494 * v562;
            let v575: f32 = v573 + v574;
            let v576: f32 = v530 * v414;
            let v577: f32 = v522 * v540;
            let v578: f32 = v576 - v577;
            let v579: f32 = v513 * v578;
            let v580: f32 = v547 * v562;
            let v581: f32 = v579 + v580;
            let v582: f32 = v513 * v414;
            let v583: f32 = v522 * v562;
            let v584: f32 = v582 - v583;
            let v585: f32 = v513 * v584;
            let v586: f32 = v530 * v578;
            let v587: f32 = v547 * v540;
            let v588: f32 = v586 + v587;
            let v589: f32 = v585 - v588;
            let v590: f32 = v516 * v562;
            let v591: f32 = v589 - v590;
            let v592: f32 = v547 * v414;
            let v593: f32 = v522 * v578;
            let v594: f32 = v592 + v593;
            let v595: f32 = v513 * v540;
            let v596: f32 = v530 * v562;
            let v597: f32 = v595 - v596;
            let v598: f32 = v513 * v597;
            let v599: f32 = v594 + v598;
            let v600: f32 = v519 * v562;
            let v601: f32 = v599 + v600;
            let v602: f32 = v516 * v540;
            let v603: f32 = v530 * v584;
            let v604: f32 = v602 - v603;
            let v605: f32 = v522 * v584;
            let v606: f32 = v516 * v414;
            let v607: f32 = v519 * v540;
            let v608: f32 = v606 + v607;
            let v609: f32 = v605 - v608;
            let v610: f32 = v530 * v597;
            let v611: f32 = v609 - v610;
            let v612: f32 = v519 * v414;
            let v613: f32 = v522 * v597;
            let v614: f32 = v612 + v613;
            let v615: f32 = v5 * v51;
            let v616: f32 = -0.4318_f32;
            let v617: f32 = v616 * v4;
            let v618: f32 = v25 * v617;
            let v619: f32 = v48 - v618;
            let v620: f32 = v619 + v51;
            let v621: f32 = v4 * v617;
            let v622: f32 = v621 - v43;
            let v623: f32 = v622 - v41;
            let v624: f32 = v616 * v30;
            let v625: f32 = v25 * v7;
            let v626: f32 = v624 + v625;
            let v627: f32 = v4 * v25;
            let v628: f32 = -v627;
            let v629: f32 = v4 * v4;
            let v630: f32 = v25 * v25;
            let v631: f32 = v629 - v630;
            let v632: f32 = v25 * v4;
            let v633: f32 = v5 * v87;
            let v634: f32 = v126 * v633;
            let v635: f32 = v5 * v85;
            let v636: f32 = v635 + v83;
            let v637: f32 = v147 * v636;
            let v638: f32 = v634 + v637;
            let v639: f32 = v104 * v633;
            let v640: f32 = v104 * v639;
            let v641: f32 = v147 - v640;
            let v642: f32 = v92 * v636;
            let v643: f32 = v99 * v633;
            let v644: f32 = v642 - v643;
            let v645: f32 = v99 * v644;
            let v646: f32 = v641 + v645;
            let v647: f32 = v140 * v636;
            let v648: f32 = v646 + v647;
            let v649: f32 = v137 * v636;
            let v650: f32 = v95 * v633;
            let v651: f32 = v92 * v639;
            let v652: f32 = v650 + v651;
            let v653: f32 = v104 * v636;
            let v654: f32 = v99 * v653;
            let v655: f32 = v652 + v654;
            let v656: f32 = v649 - v655;
            let v657: f32 = v140 * v633;
            let v658: f32 = v126 + v657;
            let v659: f32 = v104 * v653;
            let v660: f32 = v658 + v659;
            let v661: f32 = v92 * v644;
            let v662: f32 = v660 + v661;
            let v663: f32 = -v662;
            let v664: f32 = v92 * v99;
            let v665: f32 = -v664;
            let v666: f32 = v104 * v99;
            let v667: f32 = v666 - v137;
            let v668: f32 = v92 * v92;
            let v669: f32 = v99 * v99;
            let v670: f32 = v668 - v669;
            let v671: f32 = v104 * v92;
            let v672: f32 = v95 + v671;
            let v673: f32 = -v672;
            let v674: f32 = v99 * v92;
            let v675: f32 = v236 * v636;
            let v676: f32 = v225 * v633;
            let v677: f32 = v5 * v225;
            let v678: f32 = v676 - v677;
            let v679: f32 = v251 * v678;
            let v680: f32 = v675 + v679;
            let v681: f32 = v223 * v633;
            let v682: f32 = v5 * v223;
            let v683: f32 = v681 - v682;
            let v684: f32 = v271 * v683;
            let v685: f32 = v680 + v684;
            let v686: f32 = v248 * v636;
            let v687: f32 = v242 * v678;
            let v688: f32 = v232 * v636;
            let v689: f32 = v687 - v688;
            let v690: f32 = v242 * v689;
            let v691: f32 = v686 - v690;
            let v692: f32 = v236 * v225;
            let v693: f32 = v691 + v692;
            let v694: f32 = v232 * v683;
            let v695: f32 = v227 * v678;
            let v696: f32 = v694 - v695;
            let v697: f32 = v227 * v696;
            let v698: f32 = v693 + v697;
            let v699: f32 = v296 * v683;
            let v700: f32 = v698 - v699;
            let v701: f32 = v232 * v689;
            let v702: f32 = v248 * v678;
            let v703: f32 = v701 - v702;
            let v704: f32 = v251 * v225;
            let v705: f32 = v703 - v704;
            let v706: f32 = v227 * v636;
            let v707: f32 = v242 * v683;
            let v708: f32 = v706 - v707;
            let v709: f32 = v227 * v708;
            let v710: f32 = v705 - v709;
            let v711: f32 = v267 * v683;
            let v712: f32 = v710 + v711;
            let v713: f32 = v271 * v223;
            let v714: f32 = v712 - v713;
            let v715: f32 = v296 * v678;
            (
                v542,
                v547,
                v564,
                v575,
                v581,
                v591,
                v601,
                v604,
                v611,
                v614,
                v615,
                v620,
                v623,
                v626,
                v628,
                v631,
                v632,
                v636,
                v638,
                v648,
                v656,
                v663,
                v665,
                v667,
                v670,
                v673,
                v674,
                v677,
                v678,
                v682,
                v683,
                v684,
                v685,
                v692,
                v696,
                v700,
                v704,
                v708,
                v713,
                v714,
                v715,
            )
        };
        let (
            v722,
            v723,
            v728,
            v736,
            v744,
            v745,
            v750,
            v753,
            v763,
            v770,
            v779,
            v780,
            v781,
            v792,
            v795,
            v796,
            v801,
            v806,
            v807,
            v813,
            v823,
            v833,
            v836,
            v843,
            v846,
            v849,
            v854,
            v856,
            v862,
            v870,
            v874,
            v875,
            v876,
            v887,
            v891,
            v892,
            v893,
            v894,
        ) = {
            let v716: f32 = v267 * v636;
            let v717: f32 = v715 - v716;
            let v718: f32 = v242 * v708;
            let v719: f32 = v717 + v718;
            let v720: f32 = v232 * v696;
            let v721: f32 = v719 - v720;
            let v722: f32 = v236 * v223;
            let v723: f32 = v721 + v722;
            let v724: f32 = v242 * v225;
            let v725: f32 = v232 * v724;
            let v726: f32 = v267 * v223;
            let v727: f32 = v725 + v726;
            let v728: f32 = -v727;
            let v729: f32 = v232 * v225;
            let v730: f32 = v227 * v223;
            let v731: f32 = v729 + v730;
            let v732: f32 = v232 * v731;
            let v733: f32 = v242 * v724;
            let v734: f32 = v732 - v733;
            let v735: f32 = v296 * v223;
            let v736: f32 = v734 - v735;
            let v737: f32 = v267 * v225;
            let v738: f32 = v227 * v724;
            let v739: f32 = v737 - v738;
            let v740: f32 = v242 * v223;
            let v741: f32 = v232 * v740;
            let v742: f32 = v739 - v741;
            let v743: f32 = v248 * v223;
            let v744: f32 = v742 - v743;
            let v745: f32 = v242 * v731;
            let v746: f32 = v296 * v225;
            let v747: f32 = v227 * v731;
            let v748: f32 = v746 + v747;
            let v749: f32 = v242 * v740;
            let v750: f32 = v748 - v749;
            let v751: f32 = v248 * v225;
            let v752: f32 = v227 * v740;
            let v753: f32 = v751 - v752;
            let v754: f32 = v364 * v636;
            let v755: f32 = v366 * v678;
            let v756: f32 = v754 - v755;
            let v757: f32 = v368 * v756;
            let v758: f32 = v366 * v636;
            let v759: f32 = v364 * v678;
            let v760: f32 = v758 + v759;
            let v761: f32 = v375 * v760;
            let v762: f32 = v757 + v761;
            let v763: f32 = v762 + v684;
            let v764: f32 = v383 * v756;
            let v765: f32 = v390 * v756;
            let v766: f32 = v387 * v760;
            let v767: f32 = v765 - v766;
            let v768: f32 = v387 * v767;
            let v769: f32 = v764 + v768;
            let v770: f32 = v368 * v225;
            let v771: f32 = v769 + v770;
            let v772: f32 = v390 * v683;
            let v773: f32 = v399 * v760;
            let v774: f32 = v772 - v773;
            let v775: f32 = v399 * v774;
            let v776: f32 = v771 + v775;
            let v777: f32 = v409 * v683;
            let v778: f32 = v776 - v777;
            let v779: f32 = v366 * v223;
            let v780: f32 = v271 * v779;
            let v781: f32 = v778 - v780;
            let v782: f32 = v421 * v756;
            let v783: f32 = v409 * v760;
            let v784: f32 = v782 - v783;
            let v785: f32 = v390 * v774;
            let v786: f32 = v784 + v785;
            let v787: f32 = v387 * v683;
            let v788: f32 = v399 * v756;
            let v789: f32 = v787 - v788;
            let v790: f32 = v387 * v789;
            let v791: f32 = v786 + v790;
            let v792: f32 = v375 * v779;
            let v793: f32 = v791 - v792;
            let v794: f32 = v364 * v223;
            let v795: f32 = v368 * v794;
            let v796: f32 = v793 - v795;
            let v797: f32 = v399 * v789;
            let v798: f32 = v390 * v767;
            let v799: f32 = v383 * v760;
            let v800: f32 = v798 + v799;
            let v801: f32 = v375 * v225;
            let v802: f32 = v800 + v801;
            let v803: f32 = v797 - v802;
            let v804: f32 = v421 * v683;
            let v805: f32 = v803 + v804;
            let v806: f32 = v271 * v794;
            let v807: f32 = v805 - v806;
            let v808: f32 = v399 * v779;
            let v809: f32 = v387 * v225;
            let v810: f32 = v808 - v809;
            let v811: f32 = v390 * v810;
            let v812: f32 = v421 * v794;
            let v813: f32 = v811 - v812;
            let v814: f32 = v390 * v779;
            let v815: f32 = v387 * v794;
            let v816: f32 = v814 + v815;
            let v817: f32 = v390 * v816;
            let v818: f32 = v421 * v225;
            let v819: f32 = v399 * v810;
            let v820: f32 = v818 + v819;
            let v821: f32 = v817 - v820;
            let v822: f32 = v383 * v794;
            let v823: f32 = v821 + v822;
            let v824: f32 = v387 * v810;
            let v825: f32 = v421 * v779;
            let v826: f32 = v824 + v825;
            let v827: f32 = v390 * v225;
            let v828: f32 = v399 * v794;
            let v829: f32 = v827 + v828;
            let v830: f32 = v390 * v829;
            let v831: f32 = v826 + v830;
            let v832: f32 = v409 * v794;
            let v833: f32 = v831 - v832;
            let v834: f32 = v383 * v225;
            let v835: f32 = v399 * v816;
            let v836: f32 = v834 - v835;
            let v837: f32 = v387 * v816;
            let v838: f32 = v409 * v225;
            let v839: f32 = v383 * v779;
            let v840: f32 = v838 + v839;
            let v841: f32 = v837 - v840;
            let v842: f32 = v399 * v829;
            let v843: f32 = v841 - v842;
            let v844: f32 = v409 * v779;
            let v845: f32 = v387 * v829;
            let v846: f32 = v844 + v845;
            let v847: f32 = v490 * v760;
            let v848: f32 = v492 * v683;
            let v849: f32 = v847 + v848;
            let v850: f32 = v494 * v849;
            let v851: f32 = v757 + v850;
            let v852: f32 = v492 * v760;
            let v853: f32 = v490 * v683;
            let v854: f32 = v852 - v853;
            let v855: f32 = v502 * v854;
            let v856: f32 = v851 + v855;
            let v857: f32 = v516 * v756;
            let v858: f32 = v519 * v849;
            let v859: f32 = v857 - v858;
            let v860: f32 = v513 * v756;
            let v861: f32 = v522 * v854;
            let v862: f32 = v860 - v861;
            let v863: f32 = v522 * v862;
            let v864: f32 = v859 + v863;
            let v865: f32 = v513 * v849;
            let v866: f32 = v530 * v854;
            let v867: f32 = v865 - v866;
            let v868: f32 = v530 * v867;
            let v869: f32 = v864 + v868;
            let v870: f32 = v494 * v779;
            let v871: f32 = v869 - v870;
            let v872: f32 = v490 * v794;
            let v873: f32 = v492 * v225;
            let v874: f32 = v872 - v873;
            let v875: f32 = v368 * v874;
            let v876: f32 = v871 - v875;
            let v877: f32 = v547 * v756;
            let v878: f32 = v522 * v849;
            let v879: f32 = v530 * v756;
            let v880: f32 = v878 - v879;
            let v881: f32 = v522 * v880;
            let v882: f32 = v877 + v881;
            let v883: f32 = v513 * v867;
            let v884: f32 = v882 + v883;
            let v885: f32 = v519 * v854;
            let v886: f32 = v884 - v885;
            let v887: f32 = v502 * v779;
            let v888: f32 = v886 - v887;
            let v889: f32 = v490 * v225;
            let v890: f32 = v492 * v794;
            let v891: f32 = v889 + v890;
            let v892: f32 = v368 * v891;
            let v893: f32 = v888 - v892;
            let v894: f32 = v530 * v880;
            (
                v722,
                v723,
                v728,
                v736,
                v744,
                v745,
                v750,
                v753,
                v763,
                v770,
                v779,
                v780,
                v781,
                v792,
                v795,
                v796,
                v801,
                v806,
                v807,
                v813,
                v823,
                v833,
                v836,
                v843,
                v846,
                v849,
                v854,
                v856,
                v862,
                v870,
                v874,
                v875,
                v876,
                v887,
                v891,
                v892,
                v893,
                v894,
            )
        };
        let (
            v901,
            v903,
            v904,
            v910,
            v920,
            v930,
            v934,
            v941,
            v944,
            v945,
            v949,
            v954,
            v958,
            v963,
            v977,
            v989,
            v997,
            v1007,
            v1022,
            v1034,
            v1044,
            v1047,
            v1052,
            v1054,
            v1060,
            v1065,
            v1069,
            v1070,
            v1073,
        ) = {
            let v895: f32 = v547 * v849;
            let v896: f32 = v894 + v895;
            let v897: f32 = v513 * v862;
            let v898: f32 = v896 - v897;
            let v899: f32 = v516 * v854;
            let v900: f32 = v898 - v899;
            let v901: f32 = v502 * v874;
            let v902: f32 = v900 + v901;
            let v903: f32 = v494 * v891;
            let v904: f32 = v902 - v903;
            let v905: f32 = v530 * v779;
            let v906: f32 = v522 * v874;
            let v907: f32 = v905 + v906;
            let v908: f32 = v513 * v907;
            let v909: f32 = v547 * v891;
            let v910: f32 = v908 - v909;
            let v911: f32 = v547 * v874;
            let v912: f32 = v530 * v907;
            let v913: f32 = v911 - v912;
            let v914: f32 = v513 * v779;
            let v915: f32 = v522 * v891;
            let v916: f32 = v914 + v915;
            let v917: f32 = v513 * v916;
            let v918: f32 = v913 + v917;
            let v919: f32 = v516 * v891;
            let v920: f32 = v918 + v919;
            let v921: f32 = v547 * v779;
            let v922: f32 = v522 * v907;
            let v923: f32 = v921 + v922;
            let v924: f32 = v530 * v891;
            let v925: f32 = v513 * v874;
            let v926: f32 = v924 - v925;
            let v927: f32 = v513 * v926;
            let v928: f32 = v923 + v927;
            let v929: f32 = v519 * v891;
            let v930: f32 = v928 - v929;
            let v931: f32 = v516 * v874;
            let v932: f32 = v530 * v916;
            let v933: f32 = v931 + v932;
            let v934: f32 = -v933;
            let v935: f32 = v519 * v874;
            let v936: f32 = v516 * v779;
            let v937: f32 = v935 - v936;
            let v938: f32 = v522 * v916;
            let v939: f32 = v937 + v938;
            let v940: f32 = v530 * v926;
            let v941: f32 = v939 - v940;
            let v942: f32 = v519 * v779;
            let v943: f32 = v522 * v926;
            let v944: f32 = v942 + v943;
            let v945: f32 = v83 * v147;
            let v946: f32 = v83 * v92;
            let v947: f32 = v99 * v946;
            let v948: f32 = v147 + v947;
            let v949: f32 = v948 + v141;
            let v950: f32 = -0.0203_f32;
            let v951: f32 = v950 * v104;
            let v952: f32 = v99 * v951;
            let v953: f32 = v83 * v137;
            let v954: f32 = v952 + v953;
            let v955: f32 = v104 * v951;
            let v956: f32 = v955 - v126;
            let v957: f32 = v92 * v946;
            let v958: f32 = v956 - v957;
            let v959: f32 = v83 * v236;
            let v960: f32 = v251 * v677;
            let v961: f32 = v959 - v960;
            let v962: f32 = v271 * v682;
            let v963: f32 = v961 - v962;
            let v964: f32 = v83 * v248;
            let v965: f32 = v950 * v232;
            let v966: f32 = v242 * v677;
            let v967: f32 = v965 - v966;
            let v968: f32 = v242 * v967;
            let v969: f32 = v964 - v968;
            let v970: f32 = v969 + v692;
            let v971: f32 = v227 * v677;
            let v972: f32 = v232 * v682;
            let v973: f32 = v971 - v972;
            let v974: f32 = v227 * v973;
            let v975: f32 = v970 + v974;
            let v976: f32 = v296 * v682;
            let v977: f32 = v975 + v976;
            let v978: f32 = v232 * v967;
            let v979: f32 = v248 * v677;
            let v980: f32 = v978 + v979;
            let v981: f32 = v980 - v704;
            let v982: f32 = v83 * v227;
            let v983: f32 = v242 * v682;
            let v984: f32 = v982 + v983;
            let v985: f32 = v227 * v984;
            let v986: f32 = v981 - v985;
            let v987: f32 = v267 * v682;
            let v988: f32 = v986 - v987;
            let v989: f32 = v988 - v713;
            let v990: f32 = v950 * v267;
            let v991: f32 = v296 * v677;
            let v992: f32 = v990 - v991;
            let v993: f32 = v242 * v984;
            let v994: f32 = v992 + v993;
            let v995: f32 = v232 * v973;
            let v996: f32 = v994 - v995;
            let v997: f32 = v996 + v722;
            let v998: f32 = v83 * v364;
            let v999: f32 = v366 * v677;
            let v1000: f32 = v998 + v999;
            let v1001: f32 = v368 * v1000;
            let v1002: f32 = v83 * v366;
            let v1003: f32 = v364 * v677;
            let v1004: f32 = v1002 - v1003;
            let v1005: f32 = v375 * v1004;
            let v1006: f32 = v1001 + v1005;
            let v1007: f32 = v1006 - v962;
            let v1008: f32 = v383 * v1000;
            let v1009: f32 = v390 * v1000;
            let v1010: f32 = v387 * v1004;
            let v1011: f32 = v1009 - v1010;
            let v1012: f32 = v387 * v1011;
            let v1013: f32 = v1008 + v1012;
            let v1014: f32 = v1013 + v770;
            let v1015: f32 = v399 * v1004;
            let v1016: f32 = v390 * v682;
            let v1017: f32 = v1015 + v1016;
            let v1018: f32 = v399 * v1017;
            let v1019: f32 = v1014 - v1018;
            let v1020: f32 = v409 * v682;
            let v1021: f32 = v1019 + v1020;
            let v1022: f32 = v1021 - v780;
            let v1023: f32 = v421 * v1000;
            let v1024: f32 = v409 * v1004;
            let v1025: f32 = v1023 - v1024;
            let v1026: f32 = v390 * v1017;
            let v1027: f32 = v1025 - v1026;
            let v1028: f32 = v399 * v1000;
            let v1029: f32 = v387 * v682;
            let v1030: f32 = v1028 + v1029;
            let v1031: f32 = v387 * v1030;
            let v1032: f32 = v1027 - v1031;
            let v1033: f32 = v1032 - v792;
            let v1034: f32 = v1033 - v795;
            let v1035: f32 = v390 * v1011;
            let v1036: f32 = v383 * v1004;
            let v1037: f32 = v1035 + v1036;
            let v1038: f32 = v1037 + v801;
            let v1039: f32 = v399 * v1030;
            let v1040: f32 = v1038 + v1039;
            let v1041: f32 = v421 * v682;
            let v1042: f32 = v1040 + v1041;
            let v1043: f32 = v1042 + v806;
            let v1044: f32 = -v1043;
            let v1045: f32 = v492 * v682;
            let v1046: f32 = v490 * v1004;
            let v1047: f32 = v1045 - v1046;
            let v1048: f32 = v494 * v1047;
            let v1049: f32 = v1001 - v1048;
            let v1050: f32 = v492 * v1004;
            let v1051: f32 = v490 * v682;
            let v1052: f32 = v1050 + v1051;
            let v1053: f32 = v502 * v1052;
            let v1054: f32 = v1049 + v1053;
            let v1055: f32 = v516 * v1000;
            let v1056: f32 = v519 * v1047;
            let v1057: f32 = v1055 + v1056;
            let v1058: f32 = v513 * v1000;
            let v1059: f32 = v522 * v1052;
            let v1060: f32 = v1058 - v1059;
            let v1061: f32 = v522 * v1060;
            let v1062: f32 = v1057 + v1061;
            let v1063: f32 = v513 * v1047;
            let v1064: f32 = v530 * v1052;
            let v1065: f32 = v1063 + v1064;
            let v1066: f32 = v530 * v1065;
            let v1067: f32 = v1062 - v1066;
            let v1068: f32 = v1067 - v870;
            let v1069: f32 = v1068 - v875;
            let v1070: f32 = v547 * v1000;
            let v1071: f32 = v530 * v1000;
            let v1072: f32 = v522 * v1047;
            let v1073: f32 = v1071 + v1072;
            (
                v901,
                v903,
                v904,
                v910,
                v920,
                v930,
                v934,
                v941,
                v944,
                v945,
                v949,
                v954,
                v958,
                v963,
                v977,
                v989,
                v997,
                v1007,
                v1022,
                v1034,
                v1044,
                v1047,
                v1052,
                v1054,
                v1060,
                v1065,
                v1069,
                v1070,
                v1073,
            )
        };
        let (
            v1081,
            v1090,
            v1091,
            v1092,
            v1094,
            v1097,
            v1099,
            v1101,
            v1103,
            v1106,
            v1107,
            v1111,
            v1119,
            v1127,
            v1129,
            v1134,
            v1137,
            v1141,
            v1145,
            v1148,
            v1154,
            v1164,
            v1174,
            v1177,
            v1184,
            v1187,
            v1188,
            v1190,
            v1192,
            v1195,
            v1198,
            v1199,
            v1200,
            v1202,
            v1206,
            v1211,
            v1219,
            v1227,
            v1230,
            v1235,
            v1236,
            v1237,
            v1238,
            v1239,
            v1242,
            v1244,
            v1246,
            v1248,
            v1249,
        ) = {
            let v1074: f32 = v522 * v1073;
            let v1075: f32 = v1070 - v1074;
            let v1076: f32 = v513 * v1065;
            let v1077: f32 = v1075 - v1076;
            let v1078: f32 = v519 * v1052;
            let v1079: f32 = v1077 - v1078;
            let v1080: f32 = v1079 - v887;
            let v1081: f32 = v1080 - v892;
            let v1082: f32 = v530 * v1073;
            let v1083: f32 = v547 * v1047;
            let v1084: f32 = v1082 + v1083;
            let v1085: f32 = v513 * v1060;
            let v1086: f32 = v1084 + v1085;
            let v1087: f32 = v516 * v1052;
            let v1088: f32 = v1086 + v1087;
            let v1089: f32 = v901 - v1088;
            let v1090: f32 = v1089 - v903;
            let v1091: f32 = -v271;
            let v1092: f32 = v232 * v227;
            let v1093: f32 = v242 * v227;
            let v1094: f32 = v267 + v1093;
            let v1095: f32 = v227 * v227;
            let v1096: f32 = v232 * v232;
            let v1097: f32 = v1095 - v1096;
            let v1098: f32 = v242 * v232;
            let v1099: f32 = v248 - v1098;
            let v1100: f32 = v227 * v232;
            let v1101: f32 = -v1100;
            let v1102: f32 = v271 * v364;
            let v1103: f32 = -v1102;
            let v1104: f32 = v368 * v366;
            let v1105: f32 = v375 * v364;
            let v1106: f32 = v1104 - v1105;
            let v1107: f32 = v271 * v366;
            let v1108: f32 = v399 * v364;
            let v1109: f32 = v390 * v1108;
            let v1110: f32 = v421 * v366;
            let v1111: f32 = v1109 + v1110;
            let v1112: f32 = v390 * v364;
            let v1113: f32 = v387 * v366;
            let v1114: f32 = v1112 - v1113;
            let v1115: f32 = v390 * v1114;
            let v1116: f32 = v399 * v1108;
            let v1117: f32 = v1115 - v1116;
            let v1118: f32 = v383 * v366;
            let v1119: f32 = v1117 - v1118;
            let v1120: f32 = v387 * v1108;
            let v1121: f32 = v421 * v364;
            let v1122: f32 = v1120 + v1121;
            let v1123: f32 = v399 * v366;
            let v1124: f32 = v390 * v1123;
            let v1125: f32 = v1122 - v1124;
            let v1126: f32 = v409 * v366;
            let v1127: f32 = v1125 + v1126;
            let v1128: f32 = v399 * v1114;
            let v1129: f32 = -v1128;
            let v1130: f32 = v387 * v1114;
            let v1131: f32 = v383 * v364;
            let v1132: f32 = v1130 - v1131;
            let v1133: f32 = v399 * v1123;
            let v1134: f32 = v1132 + v1133;
            let v1135: f32 = v409 * v364;
            let v1136: f32 = v387 * v1123;
            let v1137: f32 = v1135 - v1136;
            let v1138: f32 = v490 * v366;
            let v1139: f32 = v368 * v1138;
            let v1140: f32 = v494 * v364;
            let v1141: f32 = v1139 - v1140;
            let v1142: f32 = v492 * v366;
            let v1143: f32 = v368 * v1142;
            let v1144: f32 = v502 * v364;
            let v1145: f32 = v1143 - v1144;
            let v1146: f32 = v494 * v1142;
            let v1147: f32 = v502 * v1138;
            let v1148: f32 = v1146 - v1147;
            let v1149: f32 = v530 * v364;
            let v1150: f32 = v522 * v1138;
            let v1151: f32 = v1149 - v1150;
            let v1152: f32 = v513 * v1151;
            let v1153: f32 = v547 * v1142;
            let v1154: f32 = v1152 + v1153;
            let v1155: f32 = v513 * v364;
            let v1156: f32 = v522 * v1142;
            let v1157: f32 = v1155 - v1156;
            let v1158: f32 = v513 * v1157;
            let v1159: f32 = v530 * v1151;
            let v1160: f32 = v547 * v1138;
            let v1161: f32 = v1159 + v1160;
            let v1162: f32 = v1158 - v1161;
            let v1163: f32 = v516 * v1142;
            let v1164: f32 = v1162 - v1163;
            let v1165: f32 = v547 * v364;
            let v1166: f32 = v522 * v1151;
            let v1167: f32 = v1165 + v1166;
            let v1168: f32 = v513 * v1138;
            let v1169: f32 = v530 * v1142;
            let v1170: f32 = v1168 - v1169;
            let v1171: f32 = v513 * v1170;
            let v1172: f32 = v1167 + v1171;
            let v1173: f32 = v519 * v1142;
            let v1174: f32 = v1172 + v1173;
            let v1175: f32 = v516 * v1138;
            let v1176: f32 = v530 * v1157;
            let v1177: f32 = v1175 - v1176;
            let v1178: f32 = v522 * v1157;
            let v1179: f32 = v516 * v364;
            let v1180: f32 = v519 * v1138;
            let v1181: f32 = v1179 + v1180;
            let v1182: f32 = v1178 - v1181;
            let v1183: f32 = v530 * v1170;
            let v1184: f32 = v1182 - v1183;
            let v1185: f32 = v519 * v364;
            let v1186: f32 = v522 * v1170;
            let v1187: f32 = v1185 + v1186;
            let v1188: f32 = -v375;
            let v1189: f32 = v390 * v387;
            let v1190: f32 = -v1189;
            let v1191: f32 = v399 * v387;
            let v1192: f32 = v1191 - v421;
            let v1193: f32 = v390 * v390;
            let v1194: f32 = v387 * v387;
            let v1195: f32 = v1193 - v1194;
            let v1196: f32 = v399 * v390;
            let v1197: f32 = v409 + v1196;
            let v1198: f32 = -v1197;
            let v1199: f32 = v387 * v390;
            let v1200: f32 = v368 * v492;
            let v1201: f32 = v368 * v490;
            let v1202: f32 = -v1201;
            let v1203: f32 = v502 * v492;
            let v1204: f32 = v494 * v490;
            let v1205: f32 = v1203 + v1204;
            let v1206: f32 = -v1205;
            let v1207: f32 = v522 * v492;
            let v1208: f32 = v513 * v1207;
            let v1209: f32 = v547 * v490;
            let v1210: f32 = v1208 + v1209;
            let v1211: f32 = -v1210;
            let v1212: f32 = v530 * v1207;
            let v1213: f32 = v547 * v492;
            let v1214: f32 = v1212 - v1213;
            let v1215: f32 = v522 * v490;
            let v1216: f32 = v513 * v1215;
            let v1217: f32 = v1214 + v1216;
            let v1218: f32 = v516 * v490;
            let v1219: f32 = v1217 + v1218;
            let v1220: f32 = v513 * v492;
            let v1221: f32 = v530 * v490;
            let v1222: f32 = v1220 + v1221;
            let v1223: f32 = v513 * v1222;
            let v1224: f32 = v522 * v1207;
            let v1225: f32 = v1223 - v1224;
            let v1226: f32 = v519 * v490;
            let v1227: f32 = v1225 - v1226;
            let v1228: f32 = v516 * v492;
            let v1229: f32 = v530 * v1215;
            let v1230: f32 = v1228 - v1229;
            let v1231: f32 = v522 * v1215;
            let v1232: f32 = v519 * v492;
            let v1233: f32 = v1231 - v1232;
            let v1234: f32 = v530 * v1222;
            let v1235: f32 = v1233 - v1234;
            let v1236: f32 = v522 * v1222;
            let v1237: f32 = -v494;
            let v1238: f32 = -v502;
            let v1239: f32 = v513 * v530;
            let v1240: f32 = v513 * v513;
            let v1241: f32 = v530 * v530;
            let v1242: f32 = v1240 - v1241;
            let v1243: f32 = v522 * v530;
            let v1244: f32 = v547 + v1243;
            let v1245: f32 = v530 * v513;
            let v1246: f32 = -v1245;
            let v1247: f32 = v522 * v513;
            let v1248: f32 = v1247 - v516;
            let v1249: f32 = 0.0_f32;
            (
                v1081,
                v1090,
                v1091,
                v1092,
                v1094,
                v1097,
                v1099,
                v1101,
                v1103,
                v1106,
                v1107,
                v1111,
                v1119,
                v1127,
                v1129,
                v1134,
                v1137,
                v1141,
                v1145,
                v1148,
                v1154,
                v1164,
                v1174,
                v1177,
                v1184,
                v1187,
                v1188,
                v1190,
                v1192,
                v1195,
                v1198,
                v1199,
                v1200,
                v1202,
                v1206,
                v1211,
                v1219,
                v1227,
                v1230,
                v1235,
                v1236,
                v1237,
                v1238,
                v1239,
                v1242,
                v1244,
                v1246,
                v1248,
                v1249,
            )
        };
        [
            [
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v0,
                v1249,
                v1249,
                v17,
                v23,
                v33,
                v53,
                v57,
                v65,
                v73,
                v76,
                v81,
                v82,
                v153,
                v168,
                v182,
                v191,
                v195,
                v203,
                v211,
                v213,
                v218,
                v221,
                v279,
                v298,
                v312,
                v323,
                v329,
                v339,
                v349,
                v352,
                v359,
                v362,
                v381,
                v416,
                v438,
                v449,
                v455,
                v465,
                v475,
                v478,
                v485,
                v488,
                v507,
                v542,
                v564,
                v575,
                v581,
                v591,
                v601,
                v604,
                v611,
                v614,
            ],
            [
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v615,
                v620,
                v623,
                v626,
                v628,
                v631,
                v28,
                v632,
                v10,
                v47,
                v638,
                v648,
                v656,
                v663,
                v665,
                v667,
                v670,
                v140,
                v673,
                v674,
                v685,
                v700,
                v714,
                v723,
                v728,
                v736,
                v744,
                v745,
                v750,
                v753,
                v763,
                v781,
                v796,
                v807,
                v813,
                v823,
                v833,
                v836,
                v843,
                v846,
                v856,
                v876,
                v893,
                v904,
                v910,
                v920,
                v930,
                v934,
                v941,
                v944,
            ],
            [
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v945,
                v949,
                v954,
                v958,
                v665,
                v667,
                v670,
                v140,
                v673,
                v674,
                v963,
                v977,
                v989,
                v997,
                v728,
                v736,
                v744,
                v745,
                v750,
                v753,
                v1007,
                v1022,
                v1034,
                v1044,
                v813,
                v823,
                v833,
                v836,
                v843,
                v846,
                v1054,
                v1069,
                v1081,
                v1090,
                v910,
                v920,
                v930,
                v934,
                v941,
                v944,
            ],
            [
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1091,
                v1249,
                v251,
                v1092,
                v1094,
                v1097,
                v296,
                v1099,
                v1101,
                v1249,
                v1103,
                v1106,
                v1107,
                v1111,
                v1119,
                v1127,
                v1129,
                v1134,
                v1137,
                v1249,
                v1141,
                v1145,
                v1148,
                v1154,
                v1164,
                v1174,
                v1177,
                v1184,
                v1187,
            ],
            [
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v368,
                v1249,
                v1188,
                v1190,
                v1192,
                v1195,
                v383,
                v1198,
                v1199,
                v1249,
                v1200,
                v1202,
                v1206,
                v1211,
                v1219,
                v1227,
                v1230,
                v1235,
                v1236,
            ],
            [
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1237,
                v1238,
                v1249,
                v1239,
                v1242,
                v1244,
                v1246,
                v1248,
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
        let v0: f32 = 0.0_f32;
        let v1: f32 = 0.35_f32;
        let v2: f32 = 17.4_f32;
        let v3: f32 = -6.33012_f32;
        let v4: f32 = 0.1044_f32;
        let v5: f32 = 3.9585_f32;
        let v6: f32 = 1.0311852_f32;
        let v7: f32 = 0.03798072_f32;
        let v8: f32 = 1.4401023_f32;
        let v9: f32 = 3.7274563_f32;
        let v10: f32 = -0.023751_f32;
        let v11: f32 = 2.842524_f32;
        let v12: f32 = 4.8_f32;
        let v13: f32 = -0.09744_f32;
        let v14: f32 = -0.06768_f32;
        let v15: f32 = 0.336_f32;
        let v16: f32 = 0.090474285_f32;
        let v17: f32 = -0.001373904_f32;
        let v18: f32 = 0.0068208_f32;
        let v19: f32 = 0.111498035_f32;
        let v20: f32 = 0.0047376_f32;
        let v21: f32 = 0.01543232_f32;
        let v22: f32 = 0.82_f32;
        let v23: f32 = 0.01558_f32;
        let v24: f32 = 0.00209602_f32;
        let v25: f32 = 0.0013_f32;
        let v26: f32 = 0.34_f32;
        let v27: f32 = 0.0003_f32;
        let v28: f32 = 0.0004_f32;
        let v29: f32 = 0.09_f32;
        let v30: f32 = 0.00288_f32;
        let v31: f32 = 0.00024216_f32;
        let v32: f32 = 4e-5_f32;
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
    pub fn frame_poses<L: crate::lanes::Lane>(q: &[L; 6]) -> [[[L; 4]; 4]; 6] {
        let v0: L = q[0];
        let (v3, v1): (L, L) = L::sincos(v0);
        let v2: L = L::splat(0.0_f64);
        let v4: L = -v1;
        let v5: L = L::splat(1.0_f64);
        let v6: L = L::splat(0.6718_f64);
        let v7: L = q[1];
        let (v10, v8): (L, L) = L::sincos(v7);
        let v9: L = v1 * v8;
        let v11: L = v1 * v10;
        let v12: L = -v11;
        let v13: L = L::splat(0.4318_f64);
        let v14: L = v13 * v8;
        let v15: L = v1 * v14;
        let v16: L = v3 * v8;
        let v17: L = v3 * v10;
        let v18: L = -v17;
        let v19: L = v3 * v14;
        let v20: L = v13 * v10;
        let v21: L = v6 + v20;
        let v22: L = q[2];
        let (v25, v23): (L, L) = L::sincos(v22);
        let v24: L = v9 * v23;
        let v26: L = v11 * v25;
        let v27: L = v24 - v26;
        let v28: L = -v3;
        let v29: L = v9 * v25;
        let v30: L = v11 * v23;
        let v31: L = v29 + v30;
        let v32: L = -v31;
        let v33: L = L::splat(0.0203_f64);
        let v34: L = v33 * v23;
        let v35: L = v9 * v34;
        let v36: L = v33 * v25;
        let v37: L = v11 * v36;
        let v38: L = v35 - v37;
        let v39: L = L::splat(0.15005_f64);
        let v40: L = v39 * v3;
        let v41: L = v38 + v40;
        let v42: L = v15 + v41;
        let v43: L = v16 * v23;
        let v44: L = v17 * v25;
        let v45: L = v43 - v44;
        let v46: L = v16 * v25;
        let v47: L = v17 * v23;
        let v48: L = v46 + v47;
        let v49: L = -v48;
        let v50: L = v16 * v34;
        let v51: L = v17 * v36;
        let v52: L = v50 - v51;
        let v53: L = v39 * v1;
        let v54: L = v52 - v53;
        let v55: L = v19 + v54;
        let v56: L = v10 * v23;
        let v57: L = v8 * v25;
        let v58: L = v56 + v57;
        let v59: L = v8 * v23;
        let v60: L = v10 * v25;
        let v61: L = v59 - v60;
        let v62: L = v10 * v34;
        let v63: L = v8 * v36;
        let v64: L = v62 + v63;
        let v65: L = v21 + v64;
        let v66: L = q[3];
        let (v69, v67): (L, L) = L::sincos(v66);
        let v68: L = v27 * v67;
        let v70: L = v3 * v69;
        let v71: L = v68 - v70;
        let v72: L = v27 * v69;
        let v73: L = v3 * v67;
        let v74: L = v72 + v73;
        let v75: L = v13 * v31;
        let v76: L = v42 - v75;
        let v77: L = v45 * v67;
        let v78: L = v1 * v69;
        let v79: L = v77 + v78;
        let v80: L = v45 * v69;
        let v81: L = v1 * v67;
        let v82: L = v80 - v81;
        let v83: L = v13 * v48;
        let v84: L = v55 - v83;
        let v85: L = v58 * v67;
        let v86: L = v58 * v69;
        let v87: L = v13 * v61;
        let v88: L = v65 + v87;
        let v89: L = q[4];
        let (v92, v90): (L, L) = L::sincos(v89);
        let v91: L = v71 * v90;
        let v93: L = v31 * v92;
        let v94: L = v91 - v93;
        let v95: L = -v74;
        let v96: L = v71 * v92;
        let v97: L = v31 * v90;
        let v98: L = v96 + v97;
        let v99: L = -v98;
        let v100: L = v79 * v90;
        let v101: L = v48 * v92;
        let v102: L = v100 - v101;
        let v103: L = -v82;
        let v104: L = v79 * v92;
        let v105: L = v48 * v90;
        let v106: L = v104 + v105;
        let v107: L = -v106;
        let v108: L = v85 * v90;
        let v109: L = v61 * v92;
        let v110: L = v108 + v109;
        let v111: L = -v86;
        let v112: L = v61 * v90;
        let v113: L = v85 * v92;
        let v114: L = v112 - v113;
        let v115: L = q[5];
        let (v118, v116): (L, L) = L::sincos(v115);
        let v117: L = v94 * v116;
        let v119: L = v74 * v118;
        let v120: L = v117 - v119;
        let v121: L = v94 * v118;
        let v122: L = v74 * v116;
        let v123: L = v121 + v122;
        let v124: L = -v123;
        let v125: L = v102 * v116;
        let v126: L = v82 * v118;
        let v127: L = v125 - v126;
        let v128: L = v102 * v118;
        let v129: L = v82 * v116;
        let v130: L = v128 + v129;
        let v131: L = -v130;
        let v132: L = v110 * v116;
        let v133: L = v86 * v118;
        let v134: L = v132 - v133;
        let v135: L = v110 * v118;
        let v136: L = v86 * v116;
        let v137: L = v135 + v136;
        let v138: L = -v137;
        [
            [[v1, v2, v3, v2], [v3, v2, v4, v2], [v2, v5, v2, v6], [v2, v2, v2, v5]],
            [
                [v9, v12, v3, v15],
                [v16, v18, v4, v19],
                [v10, v8, v2, v21],
                [v2, v2, v2, v5],
            ],
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
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `pose: [[L; 4]; 4]` (4 x 4, row-major): homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the base frame (m)
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
    pub fn end_effector_pose<L: crate::lanes::Lane>(q: &[L; 6]) -> [[L; 4]; 4] {
        let v0: L = q[2];
        let (v1, v5): (L, L) = L::sincos(v0);
        let v2: L = q[1];
        let (v3, v6): (L, L) = L::sincos(v2);
        let v4: L = v1 * v3;
        let v7: L = v5 * v6;
        let v8: L = v4 - v7;
        let v9: L = q[5];
        let (v10, v29): (L, L) = L::sincos(v9);
        let v11: L = v8 * v10;
        let v12: L = q[3];
        let (v13, v17): (L, L) = L::sincos(v12);
        let v14: L = v11 * v13;
        let v15: L = q[4];
        let (v20, v16): (L, L) = L::sincos(v15);
        let v18: L = v16 * v17;
        let v19: L = v18 * v5;
        let v21: L = v20 * v1;
        let v22: L = v19 - v21;
        let v23: L = v22 * v6;
        let v24: L = v20 * v5;
        let v25: L = v18 * v1;
        let v26: L = v24 + v25;
        let v27: L = v26 * v3;
        let v28: L = v23 - v27;
        let v30: L = v28 * v29;
        let v31: L = v14 + v30;
        let v32: L = q[0];
        let (v39, v33): (L, L) = L::sincos(v32);
        let v34: L = v31 * v33;
        let v35: L = v10 * v17;
        let v36: L = v29 * v16;
        let v37: L = v36 * v13;
        let v38: L = v35 + v37;
        let v40: L = v38 * v39;
        let v41: L = v34 - v40;
        let v42: L = v10 * v16;
        let v43: L = v42 * v13;
        let v44: L = v29 * v17;
        let v45: L = v43 - v44;
        let v46: L = v45 * v39;
        let v47: L = v8 * v29;
        let v48: L = v47 * v13;
        let v49: L = v21 - v19;
        let v50: L = v49 * v6;
        let v51: L = v50 + v27;
        let v52: L = v51 * v10;
        let v53: L = v48 + v52;
        let v54: L = v53 * v33;
        let v55: L = v46 + v54;
        let v56: L = v20 * v13;
        let v57: L = v56 * v39;
        let v58: L = v20 * v17;
        let v59: L = v58 * v1;
        let v60: L = v16 * v5;
        let v61: L = v59 - v60;
        let v62: L = v61 * v3;
        let v63: L = v58 * v5;
        let v64: L = v16 * v1;
        let v65: L = v63 + v64;
        let v66: L = v65 * v6;
        let v67: L = v62 - v66;
        let v68: L = v67 * v33;
        let v69: L = v57 + v68;
        let v70: L = L::splat(0.15005_f64);
        let v71: L = v70 * v39;
        let v72: L = L::splat(0.4318_f64);
        let v73: L = L::splat(0.0203_f64);
        let v74: L = v73 * v5;
        let v75: L = v72 + v74;
        let v76: L = v72 * v1;
        let v77: L = v75 - v76;
        let v78: L = v77 * v6;
        let v79: L = v72 * v5;
        let v80: L = v73 * v1;
        let v81: L = v79 + v80;
        let v82: L = v81 * v3;
        let v83: L = v78 - v82;
        let v84: L = v83 * v33;
        let v85: L = v71 + v84;
        let v86: L = v38 * v33;
        let v87: L = v31 * v39;
        let v88: L = v86 + v87;
        let v89: L = v44 - v43;
        let v90: L = v89 * v33;
        let v91: L = v53 * v39;
        let v92: L = v90 + v91;
        let v93: L = v67 * v39;
        let v94: L = v56 * v33;
        let v95: L = v93 - v94;
        let v96: L = v83 * v39;
        let v97: L = v70 * v33;
        let v98: L = v96 - v97;
        let v99: L = v26 * v6;
        let v100: L = v22 * v3;
        let v101: L = v99 + v100;
        let v102: L = v101 * v29;
        let v103: L = v1 * v6;
        let v104: L = v5 * v3;
        let v105: L = v103 + v104;
        let v106: L = v105 * v10;
        let v107: L = v106 * v13;
        let v108: L = v102 - v107;
        let v109: L = v49 * v3;
        let v110: L = v109 - v99;
        let v111: L = v110 * v10;
        let v112: L = v105 * v29;
        let v113: L = v112 * v13;
        let v114: L = v111 - v113;
        let v115: L = v60 - v59;
        let v116: L = v115 * v6;
        let v117: L = v65 * v3;
        let v118: L = v116 - v117;
        let v119: L = L::splat(0.6718_f64);
        let v120: L = v81 * v6;
        let v121: L = v119 + v120;
        let v122: L = v77 * v3;
        let v123: L = v121 + v122;
        let v124: L = L::splat(0.0_f64);
        let v125: L = L::splat(1.0_f64);
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
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    ///
    /// # Output
    ///
    /// `jacobian: [[L; 6]; 6]` (6 x 6, row-major): rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame
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
    pub fn jacobian<L: crate::lanes::Lane>(q: &[L; 6]) -> [[L; 6]; 6] {
        let v0: L = L::splat(0.15005_f64);
        let v1: L = q[0];
        let (v23, v2): (L, L) = L::sincos(v1);
        let v3: L = v0 * v2;
        let v4: L = L::splat(0.4318_f64);
        let v5: L = q[2];
        let (v9, v6): (L, L) = L::sincos(v5);
        let v7: L = v4 * v6;
        let v8: L = L::splat(0.0203_f64);
        let v10: L = v8 * v9;
        let v11: L = v7 + v10;
        let v12: L = q[1];
        let (v13, v20): (L, L) = L::sincos(v12);
        let v14: L = v11 * v13;
        let v15: L = -L::splat(0.4318_f64);
        let v16: L = v8 * v6;
        let v17: L = v15 - v16;
        let v18: L = v4 * v9;
        let v19: L = v17 + v18;
        let v21: L = v19 * v20;
        let v22: L = v14 + v21;
        let v24: L = v22 * v23;
        let v25: L = v3 + v24;
        let v26: L = v19 * v13;
        let v27: L = v11 * v20;
        let v28: L = v26 - v27;
        let v29: L = v28 * v2;
        let v30: L = v18 - v16;
        let v31: L = v30 * v13;
        let v32: L = v31 - v27;
        let v33: L = v32 * v2;
        let v34: L = L::splat(0.0_f64);
        let v35: L = v0 * v23;
        let v36: L = v4 + v16;
        let v37: L = v36 - v18;
        let v38: L = v37 * v20;
        let v39: L = v38 - v14;
        let v40: L = v39 * v2;
        let v41: L = v35 + v40;
        let v42: L = v28 * v23;
        let v43: L = v32 * v23;
        let v44: L = v16 - v18;
        let v45: L = v44 * v20;
        let v46: L = v45 - v14;
        let v47: L = v9 * v20;
        let v48: L = v6 * v13;
        let v49: L = v47 + v48;
        let v50: L = v49 * v2;
        let v51: L = -v50;
        let v52: L = q[3];
        let (v58, v53): (L, L) = L::sincos(v52);
        let v54: L = v53 * v23;
        let v55: L = v6 * v20;
        let v56: L = v9 * v13;
        let v57: L = v55 - v56;
        let v59: L = v57 * v58;
        let v60: L = v59 * v2;
        let v61: L = v54 + v60;
        let v62: L = q[4];
        let (v63, v68): (L, L) = L::sincos(v62);
        let v64: L = v63 * v58;
        let v65: L = v64 * v23;
        let v66: L = v63 * v53;
        let v67: L = v66 * v9;
        let v69: L = v68 * v6;
        let v70: L = v67 - v69;
        let v71: L = v70 * v13;
        let v72: L = v66 * v6;
        let v73: L = v68 * v9;
        let v74: L = v72 + v73;
        let v75: L = v74 * v20;
        let v76: L = v71 - v75;
        let v77: L = v76 * v2;
        let v78: L = v65 + v77;
        let v79: L = -v2;
        let v80: L = v49 * v23;
        let v81: L = -v80;
        let v82: L = v59 * v23;
        let v83: L = v53 * v2;
        let v84: L = v82 - v83;
        let v85: L = v76 * v23;
        let v86: L = v64 * v2;
        let v87: L = v85 - v86;
        let v88: L = L::splat(1.0_f64);
        let v89: L = v49 * v58;
        let v90: L = v69 - v67;
        let v91: L = v90 * v20;
        let v92: L = v74 * v13;
        let v93: L = v91 - v92;
        [
            [v25, v29, v33, v34, v34, v34],
            [v41, v42, v43, v34, v34, v34],
            [v34, v39, v46, v34, v34, v34],
            [v34, v23, v23, v51, v61, v78],
            [v34, v79, v79, v81, v84, v87],
            [v88, v34, v34, v57, v89, v93],
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
    /// Operation count: 78 floating-point operations, 10 trig calls.
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
        let v0: L = L::splat(0.15005_f64);
        let v1: L = q[0];
        let (v23, v2): (L, L) = L::sincos(v1);
        let v3: L = v0 * v2;
        let v4: L = L::splat(0.4318_f64);
        let v5: L = q[2];
        let (v9, v6): (L, L) = L::sincos(v5);
        let v7: L = v4 * v6;
        let v8: L = L::splat(0.0203_f64);
        let v10: L = v8 * v9;
        let v11: L = v7 + v10;
        let v12: L = q[1];
        let (v13, v20): (L, L) = L::sincos(v12);
        let v14: L = v11 * v13;
        let v15: L = -L::splat(0.4318_f64);
        let v16: L = v8 * v6;
        let v17: L = v15 - v16;
        let v18: L = v4 * v9;
        let v19: L = v17 + v18;
        let v21: L = v19 * v20;
        let v22: L = v14 + v21;
        let v24: L = v22 * v23;
        let v25: L = v3 + v24;
        let v26: L = v19 * v13;
        let v27: L = v11 * v20;
        let v28: L = v26 - v27;
        let v29: L = v28 * v2;
        let v30: L = v18 - v16;
        let v31: L = v30 * v13;
        let v32: L = v31 - v27;
        let v33: L = v32 * v2;
        let v34: L = L::splat(0.0_f64);
        let v35: L = v0 * v23;
        let v36: L = v4 + v16;
        let v37: L = v36 - v18;
        let v38: L = v37 * v20;
        let v39: L = v38 - v14;
        let v40: L = v39 * v2;
        let v41: L = v35 + v40;
        let v42: L = v28 * v23;
        let v43: L = v32 * v23;
        let v44: L = v39 * v23;
        let v45: L = v44 - v3;
        let v46: L = v16 - v18;
        let v47: L = v46 * v20;
        let v48: L = v47 - v14;
        let v49: L = L::splat(0.6718_f64);
        let v50: L = v49 + v27;
        let v51: L = v37 * v13;
        let v52: L = v50 + v51;
        let v53: L = v9 * v20;
        let v54: L = v6 * v13;
        let v55: L = v53 + v54;
        let v56: L = v55 * v2;
        let v57: L = -v56;
        let v58: L = q[3];
        let (v64, v59): (L, L) = L::sincos(v58);
        let v60: L = v59 * v23;
        let v61: L = v6 * v20;
        let v62: L = v9 * v13;
        let v63: L = v61 - v62;
        let v65: L = v63 * v64;
        let v66: L = v65 * v2;
        let v67: L = v60 + v66;
        let v68: L = q[4];
        let (v69, v74): (L, L) = L::sincos(v68);
        let v70: L = v69 * v64;
        let v71: L = v70 * v23;
        let v72: L = v69 * v59;
        let v73: L = v72 * v9;
        let v75: L = v74 * v6;
        let v76: L = v73 - v75;
        let v77: L = v76 * v13;
        let v78: L = v72 * v6;
        let v79: L = v74 * v9;
        let v80: L = v78 + v79;
        let v81: L = v80 * v20;
        let v82: L = v77 - v81;
        let v83: L = v82 * v2;
        let v84: L = v71 + v83;
        let v85: L = -v2;
        let v86: L = v55 * v23;
        let v87: L = -v86;
        let v88: L = v65 * v23;
        let v89: L = v59 * v2;
        let v90: L = v88 - v89;
        let v91: L = v82 * v23;
        let v92: L = v70 * v2;
        let v93: L = v91 - v92;
        let v94: L = L::splat(1.0_f64);
        let v95: L = v55 * v64;
        let v96: L = v75 - v73;
        let v97: L = v96 * v20;
        let v98: L = v80 * v13;
        let v99: L = v97 - v98;
        [
            [v25, v29, v33, v34, v34, v34, v41],
            [v41, v42, v43, v34, v34, v34, v45],
            [v34, v39, v48, v34, v34, v34, v52],
            [v34, v23, v23, v57, v67, v84, v34],
            [v34, v85, v85, v87, v90, v93, v34],
            [v94, v34, v34, v63, v95, v99, v34],
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
    pub fn jdot_qd<L: crate::lanes::Lane>(q: &[L; 6], qd: &[L; 6]) -> [L; 6] {
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
            v116,
            v117,
            v121,
        ) = {
            let v0: L = L::splat(0.8636_f64);
            let v1: L = qd[2];
            let v2: L = v0 * v1;
            let v3: L = qd[1];
            let v4: L = v0 * v3;
            let v5: L = v2 + v4;
            let v6: L = q[2];
            let (v13, v7): (L, L) = L::sincos(v6);
            let v8: L = v5 * v7;
            let v9: L = L::splat(0.0406_f64);
            let v10: L = v9 * v1;
            let v11: L = v9 * v3;
            let v12: L = v10 + v11;
            let v14: L = v12 * v13;
            let v15: L = v8 + v14;
            let v16: L = q[1];
            let (v31, v17): (L, L) = L::sincos(v16);
            let v18: L = v15 * v17;
            let v19: L = L::splat(0.15005_f64);
            let v20: L = qd[0];
            let v21: L = v19 * v20;
            let v22: L = v18 - v21;
            let v23: L = v9 * v7;
            let v24: L = v0 * v13;
            let v25: L = v23 - v24;
            let v26: L = v25 * v1;
            let v27: L = v0 + v23;
            let v28: L = v27 - v24;
            let v29: L = v28 * v3;
            let v30: L = v26 + v29;
            let v32: L = v30 * v31;
            let v33: L = v22 + v32;
            let v34: L = v33 * v20;
            let v35: L = q[0];
            let (v36, v81): (L, L) = L::sincos(v35);
            let v37: L = v34 * v36;
            let v38: L = L::splat(0.4318_f64);
            let v39: L = v38 * v1;
            let v40: L = v39 * v1;
            let v41: L = v38 * v20;
            let v42: L = v41 * v20;
            let v43: L = v40 + v42;
            let v44: L = v38 * v3;
            let v45: L = v2 + v44;
            let v46: L = v45 * v3;
            let v47: L = v43 + v46;
            let v48: L = v47 * v7;
            let v49: L = L::splat(0.0203_f64);
            let v50: L = v49 * v1;
            let v51: L = v50 * v1;
            let v52: L = v49 * v20;
            let v53: L = v52 * v20;
            let v54: L = v51 + v53;
            let v55: L = v49 * v3;
            let v56: L = v10 + v55;
            let v57: L = v56 * v3;
            let v58: L = v54 + v57;
            let v59: L = v58 * v13;
            let v60: L = v48 + v59;
            let v61: L = v60 * v31;
            let v62: L = v38 * v13;
            let v63: L = v49 * v7;
            let v64: L = v62 - v63;
            let v65: L = v64 * v1;
            let v66: L = v65 * v1;
            let v67: L = -L::splat(0.4318_f64);
            let v68: L = v67 - v63;
            let v69: L = v68 + v62;
            let v70: L = v69 * v20;
            let v71: L = v70 * v20;
            let v72: L = v66 + v71;
            let v73: L = v24 - v23;
            let v74: L = v73 * v1;
            let v75: L = v69 * v3;
            let v76: L = v74 + v75;
            let v77: L = v76 * v3;
            let v78: L = v72 + v77;
            let v79: L = v78 * v17;
            let v80: L = v61 + v79;
            let v82: L = v80 * v81;
            let v83: L = v37 + v82;
            let v84: L = v21 - v18;
            let v85: L = -L::splat(0.8636_f64);
            let v86: L = v85 - v23;
            let v87: L = v86 + v24;
            let v88: L = v87 * v3;
            let v89: L = v74 + v88;
            let v90: L = v89 * v31;
            let v91: L = v84 + v90;
            let v92: L = v91 * v20;
            let v93: L = v92 * v81;
            let v94: L = v80 * v36;
            let v95: L = v93 + v94;
            let v96: L = v64 * v31;
            let v97: L = v38 * v7;
            let v98: L = v49 * v13;
            let v99: L = v97 + v98;
            let v100: L = v99 * v17;
            let v101: L = v96 - v100;
            let v102: L = v101 * v1;
            let v103: L = v102 * v1;
            let v104: L = v76 * v31;
            let v105: L = v45 * v7;
            let v106: L = v56 * v13;
            let v107: L = v105 + v106;
            let v108: L = v107 * v17;
            let v109: L = v104 - v108;
            let v110: L = v109 * v3;
            let v111: L = v103 + v110;
            let v112: L = qd[5];
            let v113: L = qd[3];
            let v114: L = v112 * v113;
            let v115: L = q[4];
            let (v116, v121): (L, L) = L::sincos(v115);
            let v117: L = v114 * v116;
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
                v116,
                v117,
                v121,
            )
        };
        let (v196, v212, v235) = {
            let v118: L = q[3];
            let (v126, v119): (L, L) = L::sincos(v118);
            let v120: L = v117 * v119;
            let v122: L = v112 * v121;
            let v123: L = v122 - v113;
            let v124: L = qd[4];
            let v125: L = v123 * v124;
            let v127: L = v125 * v126;
            let v128: L = v120 + v127;
            let v129: L = v112 * v116;
            let v130: L = v129 * v119;
            let v131: L = v124 * v126;
            let v132: L = v130 - v131;
            let v133: L = v132 * v7;
            let v134: L = v113 + v122;
            let v135: L = v134 * v13;
            let v136: L = v133 + v135;
            let v137: L = v136 * v17;
            let v138: L = v134 * v7;
            let v139: L = v131 - v130;
            let v140: L = v139 * v13;
            let v141: L = v138 + v140;
            let v142: L = v141 * v31;
            let v143: L = v137 + v142;
            let v144: L = v143 * v20;
            let v145: L = v128 + v144;
            let v146: L = v145 * v36;
            let v147: L = v1 + v3;
            let v148: L = v147 * v20;
            let v149: L = v147 * v13;
            let v150: L = v149 * v31;
            let v151: L = v147 * v7;
            let v152: L = v151 * v17;
            let v153: L = v150 - v152;
            let v154: L = v153 * v113;
            let v155: L = v148 + v154;
            let v156: L = v7 * v17;
            let v157: L = v13 * v31;
            let v158: L = v156 - v157;
            let v159: L = v158 * v113;
            let v160: L = v20 + v159;
            let v161: L = v160 * v119;
            let v162: L = v149 * v17;
            let v163: L = v151 * v31;
            let v164: L = v162 + v163;
            let v165: L = v164 * v126;
            let v166: L = v161 - v165;
            let v167: L = v166 * v124;
            let v168: L = v155 + v167;
            let v169: L = v124 * v119;
            let v170: L = v147 + v169;
            let v171: L = v170 * v13;
            let v172: L = v171 * v31;
            let v173: L = v170 * v7;
            let v174: L = v173 * v17;
            let v175: L = v172 - v174;
            let v176: L = v175 * v121;
            let v177: L = v20 * v126;
            let v178: L = v113 * v126;
            let v179: L = v178 * v7;
            let v180: L = v147 * v119;
            let v181: L = v124 + v180;
            let v182: L = v181 * v13;
            let v183: L = v179 + v182;
            let v184: L = v183 * v17;
            let v185: L = v177 + v184;
            let v186: L = v181 * v7;
            let v187: L = v178 * v13;
            let v188: L = v186 - v187;
            let v189: L = v188 * v31;
            let v190: L = v185 + v189;
            let v191: L = v190 * v116;
            let v192: L = v176 + v191;
            let v193: L = v192 * v112;
            let v194: L = v168 + v193;
            let v195: L = v194 * v81;
            let v196: L = v146 + v195;
            let v197: L = v113 - v122;
            let v198: L = v197 * v124;
            let v199: L = v198 * v126;
            let v200: L = v199 - v120;
            let v201: L = v139 * v7;
            let v202: L = v201 - v135;
            let v203: L = v202 * v17;
            let v204: L = v132 * v13;
            let v205: L = v204 - v138;
            let v206: L = v205 * v31;
            let v207: L = v203 + v206;
            let v208: L = v207 * v20;
            let v209: L = v200 + v208;
            let v210: L = v209 * v81;
            let v211: L = v194 * v36;
            let v212: L = v210 + v211;
            let v213: L = v152 - v150;
            let v214: L = v213 * v124;
            let v215: L = v214 * v126;
            let v216: L = v169 - v147;
            let v217: L = v216 * v13;
            let v218: L = v217 * v17;
            let v219: L = v216 * v7;
            let v220: L = v219 * v31;
            let v221: L = v218 + v220;
            let v222: L = v221 * v113;
            let v223: L = v215 + v222;
            let v224: L = v187 - v186;
            let v225: L = v224 * v17;
            let v226: L = v183 * v31;
            let v227: L = v225 + v226;
            let v228: L = v227 * v116;
            let v229: L = v171 * v17;
            let v230: L = v173 * v31;
            let v231: L = v229 + v230;
            let v232: L = v231 * v121;
            let v233: L = v228 - v232;
            let v234: L = v233 * v112;
            let v235: L = v223 + v234;
            (v196, v212, v235)
        };
        [v83, v95, v111, v196, v212, v235]
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
    pub fn mass_matrix<L: crate::lanes::Lane>(q: &[L; 6]) -> [[L; 6]; 6] {
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
            let v0: L = L::splat(1.553523243625_f64);
            let v1: L = L::splat(0.00020216_f64);
            let v2: L = q[4];
            let (v15, v3): (L, L) = L::sincos(v2);
            let v4: L = v1 * v3;
            let v5: L = v4 * v3;
            let v6: L = v0 - v5;
            let v7: L = L::splat(0.000864288_f64);
            let v8: L = q[3];
            let (v9, v12): (L, L) = L::sincos(v8);
            let v10: L = v7 * v9;
            let v11: L = L::splat(0.000116928_f64);
            let v13: L = v11 * v12;
            let v14: L = v10 - v13;
            let v16: L = v14 * v15;
            let v17: L = v6 + v16;
            let v18: L = L::splat(0.022546398_f64);
            let v19: L = v11 * v3;
            let v20: L = v18 + v19;
            let v21: L = -L::splat(0.002487168_f64);
            let v22: L = L::splat(0.00040432_f64);
            let v23: L = v22 * v3;
            let v24: L = v21 - v23;
            let v25: L = v24 * v15;
            let v26: L = v25 * v12;
            let v27: L = v20 + v26;
            let v28: L = q[2];
            let (v29, v43): (L, L) = L::sincos(v28);
            let v30: L = v27 * v29;
            let v31: L = L::splat(0.3239198455_f64);
            let v32: L = L::splat(0.002487168_f64);
            let v33: L = v32 + v4;
            let v34: L = v33 * v3;
            let v35: L = v31 + v34;
            let v36: L = v11 * v15;
            let v37: L = -L::splat(0.00030216_f64);
            let v38: L = v37 + v5;
            let v39: L = v38 * v12;
            let v40: L = v36 + v39;
            let v41: L = v40 * v12;
            let v42: L = v35 + v41;
            let v44: L = v42 * v43;
            let v45: L = v30 + v44;
            let v46: L = v45 * v43;
            let v47: L = v17 + v46;
            let v48: L = L::splat(0.008347998_f64);
            let v49: L = v48 + v19;
            let v50: L = L::splat(0.02191385_f64);
            let v51: L = v50 * v29;
            let v52: L = v49 - v51;
            let v53: L = v32 * v29;
            let v54: L = v24 + v53;
            let v55: L = v54 * v15;
            let v56: L = v55 * v12;
            let v57: L = v52 + v56;
            let v58: L = q[1];
            let (v59, v78): (L, L) = L::sincos(v58);
            let v60: L = v57 * v59;
            let v61: L = L::splat(1.9257810475_f64);
            let v62: L = L::splat(0.769752588_f64);
            let v63: L = v62 * v29;
            let v64: L = v61 - v63;
            let v65: L = L::splat(0.00030216_f64);
            let v66: L = v65 * v12;
            let v67: L = v36 - v66;
            let v68: L = v67 * v12;
            let v69: L = v64 + v68;
            let v70: L = v32 - v53;
            let v71: L = v1 * v12;
            let v72: L = v71 * v12;
            let v73: L = v1 + v72;
            let v74: L = v73 * v3;
            let v75: L = v70 + v74;
            let v76: L = v75 * v3;
            let v77: L = v69 + v76;
            let v79: L = v77 * v78;
            let v80: L = v60 + v79;
            let v81: L = v32 * v15;
            let v82: L = v81 * v12;
            let v83: L = v50 - v82;
            let v84: L = -L::splat(0.045092796_f64);
            let v85: L = L::splat(0.000233856_f64);
            let v86: L = v85 * v3;
            let v87: L = v84 - v86;
            let v88: L = L::splat(0.004974336_f64);
            let v89: L = L::splat(0.00080864_f64);
            let v90: L = v89 * v3;
            let v91: L = v88 + v90;
            let v92: L = v91 * v15;
            let v93: L = v92 * v12;
            let v94: L = v87 + v93;
            let v95: L = v94 * v29;
            let v96: L = v83 + v95;
            let v97: L = -L::splat(0.647839691_f64);
            let v98: L = -L::splat(0.004974336_f64);
            let v99: L = v98 - v23;
            let v100: L = v99 * v3;
            let v101: L = v97 + v100;
            let v102: L = L::splat(0.00060432_f64);
            let v103: L = v23 * v3;
            let v104: L = v102 - v103;
            let v105: L = v104 * v12;
            let v106: L = v85 * v15;
            let v107: L = v105 - v106;
            let v108: L = v107 * v12;
            let v109: L = v101 + v108;
            let v110: L = v109 * v43;
            let v111: L = v96 + v110;
            let v112: L = v111 * v78;
            let v113: L = -L::splat(0.769752588_f64);
            let v114: L = v32 * v3;
            let v115: L = v113 - v114;
            let v116: L = v94 * v43;
            let v117: L = v115 + v116;
            let v118: L = L::splat(0.647839691_f64);
            let v119: L = v88 + v23;
            let v120: L = v119 * v3;
            let v121: L = v118 + v120;
            let v122: L = -L::splat(0.00060432_f64);
            let v123: L = v122 + v103;
            let v124: L = v123 * v12;
            let v125: L = v106 + v124;
            let v126: L = v125 * v12;
            let v127: L = v121 + v126;
            let v128: L = v127 * v29;
            let v129: L = v117 + v128;
            let v130: L = v129 * v59;
            let v131: L = v112 + v130;
            let v132: L = v131 * v43;
            let v133: L = v80 + v132;
            let v134: L = v133 * v78;
            let v135: L = v47 + v134;
            let v136: L = -L::splat(0.023751_f64);
            let v137: L = -L::splat(0.1384816665_f64);
            let v138: L = L::splat(0.000432144_f64);
            let v139: L = v138 * v3;
            let v140: L = v137 - v139;
            let v141: L = -L::splat(0.001243584_f64);
            let v142: L = v141 - v4;
            let v143: L = v142 * v15;
            let v144: L = v143 * v9;
            let v145: L = v140 + v144;
            let v146: L = v145 * v43;
            let v147: L = v136 + v146;
            let v148: L = -L::splat(0.00380751875_f64);
            let v149: L = v138 * v15;
            let v150: L = v149 * v12;
            let v151: L = v148 + v150;
            let v152: L = v65 - v5;
            let v153: L = v152 * v12;
            let v154: L = L::splat(5.8464e-05_f64);
            let v155: L = v154 * v15;
            let v156: L = v153 - v155;
            let v157: L = v156 * v9;
            let v158: L = v151 + v157;
            let v159: L = v158 * v29;
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
            let v160: L = v147 + v159;
            let v161: L = v160 * v78;
            let v162: L = -L::splat(0.6903913435_f64);
            let v163: L = v151 * v43;
            let v164: L = v162 + v163;
            let v165: L = L::splat(0.1384816665_f64);
            let v166: L = v165 + v139;
            let v167: L = v166 * v29;
            let v168: L = v164 + v167;
            let v169: L = v153 * v43;
            let v170: L = v154 * v43;
            let v171: L = v141 - v170;
            let v172: L = L::splat(0.001243584_f64);
            let v173: L = v172 + v4;
            let v174: L = v173 * v29;
            let v175: L = v171 + v174;
            let v176: L = v175 * v15;
            let v177: L = v169 + v176;
            let v178: L = v177 * v9;
            let v179: L = v168 + v178;
            let v180: L = v179 * v59;
            let v181: L = v161 + v180;
            let v182: L = v140 * v43;
            let v183: L = v151 * v29;
            let v184: L = v182 + v183;
            let v185: L = v184 * v78;
            let v186: L = v163 + v167;
            let v187: L = v186 * v59;
            let v188: L = v185 + v187;
            let v189: L = v152 * v29;
            let v190: L = v189 * v78;
            let v191: L = v152 * v43;
            let v192: L = v191 * v59;
            let v193: L = v190 + v192;
            let v194: L = v193 * v12;
            let v195: L = v142 * v43;
            let v196: L = v154 * v29;
            let v197: L = v195 - v196;
            let v198: L = v197 * v78;
            let v199: L = v174 - v170;
            let v200: L = v199 * v59;
            let v201: L = v198 + v200;
            let v202: L = v201 * v15;
            let v203: L = v194 + v202;
            let v204: L = v203 * v9;
            let v205: L = v188 + v204;
            let v206: L = L::splat(0.00184216_f64);
            let v207: L = v206 - v5;
            let v208: L = v207 * v43;
            let v209: L = v208 * v78;
            let v210: L = -L::splat(0.00184216_f64);
            let v211: L = v210 + v5;
            let v212: L = v211 * v29;
            let v213: L = v212 * v59;
            let v214: L = v209 + v213;
            let v215: L = v138 * v43;
            let v216: L = v215 * v78;
            let v217: L = v138 * v29;
            let v218: L = v217 * v59;
            let v219: L = v216 - v218;
            let v220: L = v219 * v9;
            let v221: L = v173 * v43;
            let v222: L = v196 + v221;
            let v223: L = v222 * v59;
            let v224: L = v175 * v78;
            let v225: L = v223 + v224;
            let v226: L = v225 * v12;
            let v227: L = v220 + v226;
            let v228: L = v227 * v15;
            let v229: L = v214 + v228;
            let v230: L = v149 * v29;
            let v231: L = v139 * v12;
            let v232: L = v231 * v43;
            let v233: L = v230 - v232;
            let v234: L = v233 * v78;
            let v235: L = v149 * v43;
            let v236: L = v231 * v29;
            let v237: L = v235 + v236;
            let v238: L = v237 * v59;
            let v239: L = v234 + v238;
            let v240: L = L::splat(0.00064216_f64);
            let v241: L = v240 * v29;
            let v242: L = v241 * v78;
            let v243: L = v240 * v43;
            let v244: L = v243 * v59;
            let v245: L = v242 + v244;
            let v246: L = v172 * v43;
            let v247: L = v246 + v196;
            let v248: L = v247 * v59;
            let v249: L = v172 * v29;
            let v250: L = v171 + v249;
            let v251: L = v250 * v78;
            let v252: L = v248 + v251;
            let v253: L = v252 * v3;
            let v254: L = v245 + v253;
            let v255: L = v254 * v9;
            let v256: L = v239 + v255;
            let v257: L = L::splat(4e-05_f64);
            let v258: L = v257 * v3;
            let v259: L = v258 * v43;
            let v260: L = v257 * v15;
            let v261: L = v260 * v12;
            let v262: L = v261 * v29;
            let v263: L = v259 - v262;
            let v264: L = v263 * v78;
            let v265: L = v261 * v43;
            let v266: L = v258 * v29;
            let v267: L = v265 + v266;
            let v268: L = v267 * v59;
            let v269: L = v264 - v268;
            let v270: L = L::splat(2.1071040725_f64);
            let v271: L = v50 * v43;
            let v272: L = v270 + v271;
            let v273: L = v272 - v63;
            let v274: L = v33 - v53;
            let v275: L = v274 * v3;
            let v276: L = v273 + v275;
            let v277: L = -L::splat(0.000116928_f64);
            let v278: L = v32 * v43;
            let v279: L = v277 - v278;
            let v280: L = v279 * v15;
            let v281: L = v280 + v153;
            let v282: L = v281 * v12;
            let v283: L = v276 + v282;
            let v284: L = L::splat(0.3589900705_f64);
            let v285: L = L::splat(0.010956925_f64);
            let v286: L = v285 * v43;
            let v287: L = v284 + v286;
            let v288: L = L::splat(0.384876294_f64);
            let v289: L = v288 * v29;
            let v290: L = v287 - v289;
            let v291: L = v33 - v249;
            let v292: L = v291 * v3;
            let v293: L = v290 + v292;
            let v294: L = v277 - v246;
            let v295: L = v294 * v15;
            let v296: L = v295 + v153;
            let v297: L = v296 * v12;
            let v298: L = v293 + v297;
            let v299: L = v142 + v249;
            let v300: L = v299 * v15;
            let v301: L = v300 * v9;
            let v302: L = -L::splat(5.8464e-05_f64);
            let v303: L = v302 - v246;
            let v304: L = v303 * v15;
            let v305: L = v172 - v249;
            let v306: L = v305 * v3;
            let v307: L = v240 + v306;
            let v308: L = v307 * v12;
            let v309: L = v304 + v308;
            let v310: L = v260 * v9;
            let v311: L = v284 + v34;
            let v312: L = v153 - v36;
            let v313: L = v312 * v12;
            let v314: L = v311 + v313;
            let v315: L = v172 * v3;
            let v316: L = v240 + v315;
            let v317: L = v316 * v12;
            let v318: L = v317 - v155;
            let v319: L = L::splat(0.0_f64);
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
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 6]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis_matrix: [[L; 6]; 6]` (6 x 6, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
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
    pub fn coriolis_matrix<L: crate::lanes::Lane>(
        q: &[L; 6],
        qd: &[L; 6],
    ) -> [[L; 6]; 6] {
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
            v212,
        ) = {
            let v0: L = -L::splat(0.004173999_f64);
            let v1: L = L::splat(0.010956925_f64);
            let v2: L = q[2];
            let (v3, v96): (L, L) = L::sincos(v2);
            let v4: L = v1 * v3;
            let v5: L = v0 + v4;
            let v6: L = qd[1];
            let v7: L = v5 * v6;
            let v8: L = L::splat(0.011273199_f64);
            let v9: L = qd[2];
            let v10: L = v8 * v9;
            let v11: L = v7 - v10;
            let v12: L = L::splat(0.000432144_f64);
            let v13: L = q[3];
            let (v14, v17): (L, L) = L::sincos(v13);
            let v15: L = v12 * v14;
            let v16: L = L::splat(5.8464e-05_f64);
            let v18: L = v16 * v17;
            let v19: L = v15 - v18;
            let v20: L = qd[4];
            let v21: L = v19 * v20;
            let v22: L = v16 * v9;
            let v23: L = v16 * v6;
            let v24: L = v22 + v23;
            let v25: L = v21 - v24;
            let v26: L = q[4];
            let (v49, v27): (L, L) = L::sincos(v26);
            let v28: L = v25 * v27;
            let v29: L = v11 + v28;
            let v30: L = L::splat(0.00020216_f64);
            let v31: L = v30 * v20;
            let v32: L = v31 * v27;
            let v33: L = qd[3];
            let v34: L = v16 * v33;
            let v35: L = v34 * v14;
            let v36: L = v32 + v35;
            let v37: L = v12 * v33;
            let v38: L = L::splat(0.001243584_f64);
            let v39: L = v30 * v27;
            let v40: L = v38 + v39;
            let v41: L = v40 * v9;
            let v42: L = v37 + v41;
            let v43: L = v38 * v3;
            let v44: L = v40 - v43;
            let v45: L = v44 * v6;
            let v46: L = v42 + v45;
            let v47: L = v46 * v17;
            let v48: L = v36 + v47;
            let v50: L = v48 * v49;
            let v51: L = v29 + v50;
            let v52: L = L::splat(0.384876294_f64);
            let v53: L = v38 * v27;
            let v54: L = v52 + v53;
            let v55: L = v54 * v6;
            let v56: L = L::splat(0.022546398_f64);
            let v57: L = v56 * v9;
            let v58: L = v56 * v6;
            let v59: L = v57 + v58;
            let v60: L = L::splat(0.000116928_f64);
            let v61: L = v60 * v9;
            let v62: L = v60 * v6;
            let v63: L = v61 + v62;
            let v64: L = v63 * v27;
            let v65: L = v59 + v64;
            let v66: L = -L::splat(0.001243584_f64);
            let v67: L = v66 - v39;
            let v68: L = v67 * v20;
            let v69: L = v68 - v35;
            let v70: L = v69 * v49;
            let v71: L = v65 + v70;
            let v72: L = v16 * v20;
            let v73: L = v72 * v27;
            let v74: L = L::splat(0.00030216_f64);
            let v75: L = v39 * v27;
            let v76: L = v74 - v75;
            let v77: L = v76 * v33;
            let v78: L = v77 * v14;
            let v79: L = v73 + v78;
            let v80: L = L::splat(0.002487168_f64);
            let v81: L = v80 * v9;
            let v82: L = v80 * v6;
            let v83: L = v81 + v82;
            let v84: L = L::splat(0.00040432_f64);
            let v85: L = v84 * v9;
            let v86: L = v84 * v6;
            let v87: L = v85 + v86;
            let v88: L = v31 * v17;
            let v89: L = v87 + v88;
            let v90: L = v89 * v27;
            let v91: L = v83 + v90;
            let v92: L = v91 * v49;
            let v93: L = v79 - v92;
            let v94: L = v93 * v17;
            let v95: L = v71 + v94;
            let v97: L = v95 * v96;
            let v98: L = v55 + v97;
            let v99: L = v38 * v33;
            let v100: L = v99 * v14;
            let v101: L = v100 - v72;
            let v102: L = v101 * v49;
            let v103: L = L::splat(0.3239198455_f64);
            let v104: L = v103 * v9;
            let v105: L = v103 * v6;
            let v106: L = v104 + v105;
            let v107: L = v102 - v106;
            let v108: L = v30 * v33;
            let v109: L = v108 * v49;
            let v110: L = v109 * v14;
            let v111: L = v110 - v83;
            let v112: L = v30 * v9;
            let v113: L = v30 * v6;
            let v114: L = v112 + v113;
            let v115: L = v114 * v27;
            let v116: L = v111 - v115;
            let v117: L = v116 * v27;
            let v118: L = v107 + v117;
            let v119: L = v84 * v27;
            let v120: L = v66 - v119;
            let v121: L = v120 * v27;
            let v122: L = v30 + v121;
            let v123: L = v122 * v20;
            let v124: L = v63 * v49;
            let v125: L = v123 - v124;
            let v126: L = v74 * v9;
            let v127: L = v74 * v6;
            let v128: L = v126 + v127;
            let v129: L = v115 * v27;
            let v130: L = v128 - v129;
            let v131: L = v130 * v17;
            let v132: L = v125 + v131;
            let v133: L = v132 * v17;
            let v134: L = v118 + v133;
            let v135: L = v134 * v3;
            let v136: L = v98 + v135;
            let v137: L = v136 * v96;
            let v138: L = v51 + v137;
            let v139: L = L::splat(0.008347998_f64);
            let v140: L = v139 * v6;
            let v141: L = v57 + v140;
            let v142: L = v74 * v33;
            let v143: L = v142 * v17;
            let v144: L = v143 * v14;
            let v145: L = v141 + v144;
            let v146: L = v1 * v9;
            let v147: L = L::splat(0.02191385_f64);
            let v148: L = v147 * v6;
            let v149: L = v146 + v148;
            let v150: L = v149 * v3;
            let v151: L = v145 - v150;
            let v152: L = v108 * v27;
            let v153: L = v152 * v14;
            let v154: L = v72 - v153;
            let v155: L = v154 * v17;
            let v156: L = v63 + v155;
            let v157: L = v156 * v27;
            let v158: L = v151 + v157;
            let v159: L = v67 + v43;
            let v160: L = v159 * v20;
            let v161: L = v160 - v35;
            let v162: L = v38 * v9;
            let v163: L = v162 + v82;
            let v164: L = v163 * v3;
            let v165: L = v164 - v83;
            let v166: L = v165 - v90;
            let v167: L = v166 * v17;
            let v168: L = v161 + v167;
            let v169: L = v168 * v49;
            let v170: L = v158 + v169;
            let v171: L = q[1];
            let (v212, v172): (L, L) = L::sincos(v171);
            let v173: L = v170 * v172;
            let v174: L = L::splat(1.9257810475_f64);
            let v175: L = v174 * v6;
            let v176: L = v104 + v175;
            let v177: L = v102 - v176;
            let v178: L = v52 * v9;
            let v179: L = L::splat(0.769752588_f64);
            let v180: L = v179 * v6;
            let v181: L = v178 + v180;
            let v182: L = v99 * v49;
            let v183: L = v182 * v14;
            let v184: L = v181 - v183;
            let v185: L = v184 * v3;
            let v186: L = v177 + v185;
            let v187: L = v31 - v124;
            let v188: L = v128 * v17;
            let v189: L = v187 + v188;
            let v190: L = v189 * v17;
            let v191: L = v186 + v190;
            let v192: L = -L::splat(0.002487168_f64);
            let v193: L = v192 - v39;
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
                v212,
            )
        };
        let (
            v197,
            v201,
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
            let v194: L = v193 + v43;
            let v195: L = v194 * v9;
            let v196: L = v110 + v195;
            let v197: L = v80 * v3;
            let v198: L = v193 + v197;
            let v199: L = v198 * v6;
            let v200: L = v196 + v199;
            let v201: L = v66 + v43;
            let v202: L = v201 * v20;
            let v203: L = v84 * v20;
            let v204: L = v114 * v17;
            let v205: L = v203 + v204;
            let v206: L = v205 * v27;
            let v207: L = v202 - v206;
            let v208: L = v207 * v17;
            let v209: L = v200 + v208;
            let v210: L = v209 * v27;
            let v211: L = v191 + v210;
            let v213: L = v211 * v212;
            let v214: L = v173 + v213;
            let v215: L = v38 * v20;
            let v216: L = v215 * v49;
            let v217: L = v216 - v149;
            let v218: L = L::splat(0.045092796_f64);
            let v219: L = v218 * v9;
            let v220: L = v218 * v6;
            let v221: L = v219 + v220;
            let v222: L = L::splat(0.000233856_f64);
            let v223: L = v222 * v9;
            let v224: L = v222 * v6;
            let v225: L = v223 + v224;
            let v226: L = v225 * v27;
            let v227: L = v221 + v226;
            let v228: L = v192 - v119;
            let v229: L = v228 * v20;
            let v230: L = v60 * v33;
            let v231: L = v230 * v14;
            let v232: L = v229 - v231;
            let v233: L = v232 * v49;
            let v234: L = v227 + v233;
            let v235: L = v234 * v3;
            let v236: L = v217 + v235;
            let v237: L = L::splat(0.647839691_f64);
            let v238: L = v237 * v9;
            let v239: L = v237 * v6;
            let v240: L = v238 + v239;
            let v241: L = v60 * v20;
            let v242: L = v80 * v33;
            let v243: L = v242 * v14;
            let v244: L = v241 - v243;
            let v245: L = v244 * v49;
            let v246: L = v240 + v245;
            let v247: L = L::splat(0.004974336_f64);
            let v248: L = v247 * v9;
            let v249: L = v247 * v6;
            let v250: L = v248 + v249;
            let v251: L = v84 * v33;
            let v252: L = v251 * v49;
            let v253: L = v252 * v14;
            let v254: L = v250 - v253;
            let v255: L = v87 * v27;
            let v256: L = v254 + v255;
            let v257: L = v256 * v27;
            let v258: L = v246 + v257;
            let v259: L = v258 * v96;
            let v260: L = v236 + v259;
            let v261: L = v163 * v49;
            let v262: L = v241 * v27;
            let v263: L = L::splat(0.00060432_f64);
            let v264: L = v119 * v27;
            let v265: L = v263 - v264;
            let v266: L = v265 * v33;
            let v267: L = v266 * v14;
            let v268: L = v262 + v267;
            let v269: L = L::splat(0.00080864_f64);
            let v270: L = v269 * v9;
            let v271: L = v269 * v6;
            let v272: L = v270 + v271;
            let v273: L = v203 * v17;
            let v274: L = v272 + v273;
            let v275: L = v274 * v27;
            let v276: L = v250 + v275;
            let v277: L = v276 * v49;
            let v278: L = v268 - v277;
            let v279: L = v278 * v3;
            let v280: L = v261 + v279;
            let v281: L = v225 * v49;
            let v282: L = -L::splat(0.00040432_f64);
            let v283: L = v269 * v27;
            let v284: L = v80 + v283;
            let v285: L = v284 * v27;
            let v286: L = v282 + v285;
            let v287: L = v286 * v20;
            let v288: L = v281 + v287;
            let v289: L = v255 * v27;
            let v290: L = v263 * v9;
            let v291: L = v263 * v6;
            let v292: L = v290 + v291;
            let v293: L = v289 - v292;
            let v294: L = v293 * v17;
            let v295: L = v288 + v294;
            let v296: L = v295 * v96;
            let v297: L = v280 + v296;
            let v298: L = v297 * v17;
            let v299: L = v260 + v298;
            let v300: L = v299 * v212;
            let v301: L = v183 - v181;
            let v302: L = v80 * v20;
            let v303: L = v302 + v231;
            let v304: L = v250 * v17;
            let v305: L = v303 + v304;
            let v306: L = v305 * v49;
            let v307: L = v263 * v33;
            let v308: L = v307 * v17;
            let v309: L = v308 * v14;
            let v310: L = v221 + v309;
            let v311: L = v306 - v310;
            let v312: L = v311 * v96;
            let v313: L = v301 + v312;
            let v314: L = v281 - v203;
            let v315: L = v292 * v17;
            let v316: L = v314 - v315;
            let v317: L = v316 * v17;
            let v318: L = v246 + v317;
            let v319: L = v318 * v3;
            let v320: L = v313 + v319;
            let v321: L = v203 * v49;
            let v322: L = v321 - v225;
            let v323: L = v322 * v96;
            let v324: L = v323 - v163;
            let v325: L = v256 * v3;
            let v326: L = v324 + v325;
            let v327: L = v269 * v20;
            let v328: L = v87 * v17;
            let v329: L = v327 + v328;
            let v330: L = v329 * v27;
            let v331: L = v302 + v330;
            let v332: L = v331 * v3;
            let v333: L = v332 - v215;
            let v334: L = v251 * v27;
            let v335: L = v334 * v14;
            let v336: L = v335 - v241;
            let v337: L = v274 * v49;
            let v338: L = v336 + v337;
            let v339: L = v338 * v96;
            let v340: L = v333 + v339;
            let v341: L = v340 * v17;
            let v342: L = v326 + v341;
            let v343: L = v342 * v27;
            let v344: L = v320 + v343;
            let v345: L = v344 * v172;
            let v346: L = v300 + v345;
            let v347: L = v346 * v96;
            let v348: L = v214 + v347;
            let v349: L = v348 * v172;
            let v350: L = v138 + v349;
            let v351: L = v16 * v27;
            let v352: L = v0 - v351;
            let v353: L = v352 + v4;
            let v354: L = v44 * v49;
            let v355: L = v354 * v17;
            let v356: L = v353 + v355;
            let v357: L = v60 * v27;
            let v358: L = v56 + v357;
            let v359: L = v228 * v49;
            let v360: L = v359 * v17;
            let v361: L = v358 + v360;
            let v362: L = v361 * v96;
            let v363: L = v54 + v362;
            let v364: L = -L::splat(0.3239198455_f64);
            let v365: L = v193 * v27;
            let v366: L = v364 + v365;
            let v367: L = v76 * v17;
            let v368: L = v60 * v49;
            let v369: L = v367 - v368;
            let v370: L = v369 * v17;
            let v371: L = v366 + v370;
            let v372: L = v371 * v3;
            let v373: L = v363 + v372;
            let v374: L = v373 * v96;
            let v375: L = v356 + v374;
            let v376: L = qd[0];
            let v377: L = v375 * v376;
            let v378: L = L::splat(0.023751_f64);
            let v379: L = v378 * v6;
            let v380: L = L::splat(0.00380751875_f64);
            let v381: L = v380 * v9;
            let v382: L = v380 * v6;
            let v383: L = v381 + v382;
            let v384: L = L::splat(2e-05_f64);
            let v385: L = qd[5];
            let v386: L = v384 * v385;
            let v387: L = v12 * v9;
            (
                v197,
                v201,
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
            let v388: L = v386 - v387;
            let v389: L = v12 * v6;
            let v390: L = v388 - v389;
            let v391: L = v390 * v17;
            let v392: L = v12 * v20;
            let v393: L = v391 - v392;
            let v394: L = v393 * v49;
            let v395: L = v383 + v394;
            let v396: L = -L::splat(0.00042216_f64);
            let v397: L = v396 + v75;
            let v398: L = v397 * v20;
            let v399: L = v24 * v49;
            let v400: L = v398 + v399;
            let v401: L = v129 - v128;
            let v402: L = v401 * v17;
            let v403: L = v400 + v402;
            let v404: L = v403 * v14;
            let v405: L = v395 + v404;
            let v406: L = v405 * v3;
            let v407: L = v379 + v406;
            let v408: L = L::splat(0.1384816665_f64);
            let v409: L = v408 * v9;
            let v410: L = v408 * v6;
            let v411: L = v409 + v410;
            let v412: L = -L::splat(0.00107216_f64);
            let v413: L = v74 * v17;
            let v414: L = v413 * v17;
            let v415: L = v412 + v414;
            let v416: L = v415 * v33;
            let v417: L = v411 + v416;
            let v418: L = v162 - v37;
            let v419: L = v38 * v6;
            let v420: L = v418 + v419;
            let v421: L = v420 * v49;
            let v422: L = v421 * v14;
            let v423: L = v417 + v422;
            let v424: L = v387 - v386;
            let v425: L = v424 + v389;
            let v426: L = v425 + v152;
            let v427: L = v152 * v17;
            let v428: L = v392 - v427;
            let v429: L = v428 * v17;
            let v430: L = v426 + v429;
            let v431: L = v114 + v88;
            let v432: L = v431 * v49;
            let v433: L = v432 * v14;
            let v434: L = v430 + v433;
            let v435: L = v434 * v27;
            let v436: L = v423 + v435;
            let v437: L = v436 * v96;
            let v438: L = v407 + v437;
            let v439: L = v438 * v212;
            let v440: L = v377 + v439;
            let v441: L = -L::splat(0.6903913435_f64);
            let v442: L = v38 * v49;
            let v443: L = v442 * v14;
            let v444: L = v441 - v443;
            let v445: L = v444 * v6;
            let v446: L = v139 + v357;
            let v447: L = v446 + v360;
            let v448: L = v447 * v172;
            let v449: L = -L::splat(1.9257810475_f64);
            let v450: L = v449 + v365;
            let v451: L = v450 + v370;
            let v452: L = v451 * v212;
            let v453: L = v448 + v452;
            let v454: L = v453 * v376;
            let v455: L = v445 + v454;
            let v456: L = v179 * v212;
            let v457: L = v147 * v172;
            let v458: L = v456 - v457;
            let v459: L = v458 * v376;
            let v460: L = v417 + v459;
            let v461: L = v80 * v376;
            let v462: L = v461 * v17;
            let v463: L = v462 * v172;
            let v464: L = v420 * v14;
            let v465: L = v463 + v464;
            let v466: L = v465 * v49;
            let v467: L = v460 + v466;
            let v468: L = v461 * v212;
            let v469: L = v426 + v468;
            let v470: L = v469 + v429;
            let v471: L = v470 + v433;
            let v472: L = v471 * v27;
            let v473: L = v467 + v472;
            let v474: L = v473 * v3;
            let v475: L = v455 + v474;
            let v476: L = v425 * v17;
            let v477: L = v392 + v476;
            let v478: L = v477 * v49;
            let v479: L = v478 - v383;
            let v480: L = L::splat(0.00042216_f64);
            let v481: L = v480 - v75;
            let v482: L = v481 * v20;
            let v483: L = v482 - v399;
            let v484: L = v483 + v131;
            let v485: L = v484 * v14;
            let v486: L = v479 + v485;
            let v487: L = -L::splat(0.769752588_f64);
            let v488: L = v80 * v27;
            let v489: L = v487 - v488;
            let v490: L = -L::splat(0.045092796_f64);
            let v491: L = v222 * v27;
            let v492: L = v490 - v491;
            let v493: L = v247 + v283;
            let v494: L = v493 * v49;
            let v495: L = v494 * v17;
            let v496: L = v492 + v495;
            let v497: L = v496 * v96;
            let v498: L = v489 + v497;
            let v499: L = v247 + v119;
            let v500: L = v499 * v27;
            let v501: L = v237 + v500;
            let v502: L = v222 * v49;
            let v503: L = -L::splat(0.00060432_f64);
            let v504: L = v503 + v264;
            let v505: L = v504 * v17;
            let v506: L = v502 + v505;
            let v507: L = v506 * v17;
            let v508: L = v501 + v507;
            let v509: L = v508 * v3;
            let v510: L = v498 + v509;
            let v511: L = v510 * v172;
            let v512: L = -L::splat(0.02191385_f64);
            let v513: L = v80 * v49;
            let v514: L = v513 * v17;
            let v515: L = v512 + v514;
            let v516: L = v218 + v491;
            let v517: L = -L::splat(0.004974336_f64);
            let v518: L = v517 - v283;
            let v519: L = v518 * v49;
            let v520: L = v519 * v17;
            let v521: L = v516 + v520;
            let v522: L = v521 * v3;
            let v523: L = v515 + v522;
            let v524: L = v508 * v96;
            let v525: L = v523 + v524;
            let v526: L = v525 * v212;
            let v527: L = v511 + v526;
            let v528: L = v527 * v376;
            let v529: L = v486 + v528;
            let v530: L = v529 * v96;
            let v531: L = v475 + v530;
            let v532: L = v531 * v172;
            let v533: L = v440 + v532;
            let v534: L = -L::splat(0.011273199_f64);
            let v535: L = v534 - v351;
            let v536: L = v40 * v49;
            let v537: L = v536 * v17;
            let v538: L = v535 + v537;
            let v539: L = v362 + v372;
            let v540: L = v539 * v96;
            let v541: L = v538 + v540;
            let v542: L = v541 * v376;
            let v543: L = v406 + v437;
            let v544: L = v543 * v212;
            let v545: L = v542 + v544;
            let v546: L = v361 * v172;
            let v547: L = v371 * v212;
            let v548: L = v546 + v547;
            let v549: L = v548 * v376;
            let v550: L = v52 * v212;
            let v551: L = v1 * v172;
            let v552: L = v550 - v551;
            let v553: L = v552 * v376;
            let v554: L = v417 + v553;
            let v555: L = v38 * v376;
            let v556: L = v555 * v17;
            let v557: L = v556 * v172;
            let v558: L = v557 + v464;
            let v559: L = v558 * v49;
            let v560: L = v554 + v559;
            let v561: L = v555 * v212;
            let v562: L = v426 + v561;
            let v563: L = v562 + v429;
            let v564: L = v563 + v433;
            let v565: L = v564 * v27;
            let v566: L = v560 + v565;
            let v567: L = v566 * v3;
            let v568: L = v549 + v567;
            let v569: L = -L::splat(0.384876294_f64);
            let v570: L = v569 - v53;
            let v571: L = v570 + v497;
            let v572: L = v571 + v509;
            let v573: L = v572 * v172;
            let v574: L = -L::splat(0.010956925_f64);
            let v575: L = v442 * v17;
            let v576: L = v574 + v575;
            let v577: L = v576 + v522;
            let v578: L = v577 + v524;
            let v579: L = v578 * v212;
            let v580: L = v573 + v579;
            let v581: L = v580 * v376;
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
            let v582: L = v486 + v581;
            let v583: L = v582 * v96;
            let v584: L = v568 + v583;
            let v585: L = v584 * v172;
            let v586: L = v545 + v585;
            let v587: L = v12 * v49;
            let v588: L = v587 * v17;
            let v589: L = v16 * v49;
            let v590: L = v536 * v3;
            let v591: L = v367 - v589;
            let v592: L = v591 * v96;
            let v593: L = v590 + v592;
            let v594: L = v593 * v96;
            let v595: L = v589 + v594;
            let v596: L = v595 * v14;
            let v597: L = v588 + v596;
            let v598: L = v597 * v376;
            let v599: L = v18 - v15;
            let v600: L = v599 * v20;
            let v601: L = v600 * v27;
            let v602: L = v12 * v17;
            let v603: L = v16 * v14;
            let v604: L = v602 + v603;
            let v605: L = v604 * v33;
            let v606: L = v32 + v605;
            let v607: L = v606 * v49;
            let v608: L = v601 - v607;
            let v609: L = v608 * v3;
            let v610: L = L::splat(0.00107216_f64);
            let v611: L = v610 * v9;
            let v612: L = v610 * v6;
            let v613: L = v611 + v612;
            let v614: L = v129 - v613;
            let v615: L = v67 * v33;
            let v616: L = v390 + v615;
            let v617: L = v616 * v49;
            let v618: L = v617 * v14;
            let v619: L = v614 + v618;
            let v620: L = L::splat(0.00022_f64);
            let v621: L = v40 * v27;
            let v622: L = v620 + v621;
            let v623: L = v622 * v20;
            let v624: L = v623 + v131;
            let v625: L = v624 * v17;
            let v626: L = v619 + v625;
            let v627: L = v626 * v96;
            let v628: L = v609 + v627;
            let v629: L = v628 * v212;
            let v630: L = v598 + v629;
            let v631: L = v32 * v49;
            let v632: L = v37 * v49;
            let v633: L = v632 - v73;
            let v634: L = v633 * v17;
            let v635: L = v631 + v634;
            let v636: L = v635 * v96;
            let v637: L = v215 * v27;
            let v638: L = v637 * v17;
            let v639: L = v636 - v638;
            let v640: L = v614 + v625;
            let v641: L = v640 * v3;
            let v642: L = v639 + v641;
            let v643: L = v392 * v27;
            let v644: L = v643 * v96;
            let v645: L = v265 * v96;
            let v646: L = v645 * v3;
            let v647: L = v646 * v212;
            let v648: L = v504 * v96;
            let v649: L = v648 * v96;
            let v650: L = v76 + v649;
            let v651: L = v650 * v172;
            let v652: L = v647 + v651;
            let v653: L = v652 * v376;
            let v654: L = v653 * v17;
            let v655: L = v644 + v654;
            let v656: L = v16 * v96;
            let v657: L = v38 + v656;
            let v658: L = v657 * v33;
            let v659: L = v616 * v3;
            let v660: L = v658 + v659;
            let v661: L = v44 * v212;
            let v662: L = v16 * v172;
            let v663: L = v661 - v662;
            let v664: L = v228 * v96;
            let v665: L = v60 * v3;
            let v666: L = v664 - v665;
            let v667: L = v666 * v212;
            let v668: L = v60 * v96;
            let v669: L = v38 + v668;
            let v670: L = v228 * v3;
            let v671: L = v669 + v670;
            let v672: L = v671 * v172;
            let v673: L = v667 + v672;
            let v674: L = v673 * v96;
            let v675: L = v663 + v674;
            let v676: L = v675 * v376;
            let v677: L = v660 + v676;
            let v678: L = v677 * v49;
            let v679: L = v655 + v678;
            let v680: L = v679 * v14;
            let v681: L = v642 + v680;
            let v682: L = v681 * v172;
            let v683: L = v630 + v682;
            let v684: L = v30 * v49;
            let v685: L = v684 - v18;
            let v686: L = v685 + v15;
            let v687: L = v686 * v27;
            let v688: L = v67 * v96;
            let v689: L = v16 * v3;
            let v690: L = v688 - v689;
            let v691: L = v690 * v49;
            let v692: L = v30 * v3;
            let v693: L = v684 * v17;
            let v694: L = v16 - v693;
            let v695: L = v694 * v96;
            let v696: L = v120 * v3;
            let v697: L = v695 + v696;
            let v698: L = v697 * v27;
            let v699: L = v692 + v698;
            let v700: L = v699 * v17;
            let v701: L = v691 + v700;
            let v702: L = v701 * v96;
            let v703: L = v687 + v702;
            let v704: L = v703 * v376;
            let v705: L = v620 * v33;
            let v706: L = v705 * v17;
            let v707: L = v216 * v14;
            let v708: L = v706 - v707;
            let v709: L = v708 * v96;
            let v710: L = v604 * v20;
            let v711: L = v390 - v710;
            let v712: L = v711 * v49;
            let v713: L = v480 * v9;
            let v714: L = v480 * v6;
            let v715: L = v713 + v714;
            let v716: L = v715 * v14;
            let v717: L = v712 - v716;
            let v718: L = v717 * v3;
            let v719: L = v709 + v718;
            let v720: L = v18 - v684;
            let v721: L = v720 * v33;
            let v722: L = v115 - v37;
            let v723: L = v722 * v14;
            let v724: L = v721 + v723;
            let v725: L = v724 * v3;
            let v726: L = v40 * v33;
            let v727: L = v425 + v726;
            let v728: L = v114 * v49;
            let v729: L = v728 * v14;
            let v730: L = v727 + v729;
            let v731: L = v730 * v17;
            let v732: L = v392 + v731;
            let v733: L = v732 * v96;
            let v734: L = v725 + v733;
            let v735: L = v734 * v27;
            let v736: L = v719 + v735;
            let v737: L = v736 * v212;
            let v738: L = v704 + v737;
            let v739: L = v705 * v3;
            let v740: L = v30 * v376;
            let v741: L = v740 * v212;
            let v742: L = v739 + v741;
            let v743: L = v742 * v17;
            let v744: L = v84 * v3;
            let v745: L = v744 * v172;
            let v746: L = v84 * v96;
            let v747: L = v746 * v212;
            let v748: L = v745 + v747;
            let v749: L = v748 * v376;
            let v750: L = v749 * v17;
            let v751: L = v716 - v750;
            let v752: L = v751 * v96;
            let v753: L = v743 + v752;
            let v754: L = v38 - v43;
            let v755: L = v754 * v20;
            let v756: L = v755 * v14;
            let v757: L = v201 * v172;
            let v758: L = v16 * v212;
            let v759: L = v757 - v758;
            let v760: L = v759 * v376;
            let v761: L = v756 + v760;
            let v762: L = v425 + v710;
            let v763: L = v80 * v96;
            let v764: L = v763 + v665;
            let v765: L = v764 * v172;
            let v766: L = v669 - v197;
            let v767: L = v766 * v212;
            let v768: L = v765 + v767;
            let v769: L = v768 * v376;
            let v770: L = v762 + v769;
            let v771: L = v770 * v96;
            let v772: L = v761 + v771;
            let v773: L = v772 * v49;
            let v774: L = v753 + v773;
            let v775: L = v392 * v3;
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
            let v776: L = v740 * v49;
            let v777: L = v776 * v172;
            let v778: L = v775 - v777;
            let v779: L = v746 * v172;
            let v780: L = v744 * v212;
            let v781: L = v779 - v780;
            let v782: L = v781 * v376;
            let v783: L = v108 + v782;
            let v784: L = v783 * v49;
            let v785: L = v37 - v115;
            let v786: L = v785 * v14;
            let v787: L = v784 + v786;
            let v788: L = v787 * v96;
            let v789: L = v778 + v788;
            let v790: L = v66 - v656;
            let v791: L = v790 * v33;
            let v792: L = v730 * v3;
            let v793: L = v791 + v792;
            let v794: L = v694 * v172;
            let v795: L = v120 + v43;
            let v796: L = v795 * v212;
            let v797: L = v794 + v796;
            let v798: L = v284 * v96;
            let v799: L = v84 * v49;
            let v800: L = v799 * v17;
            let v801: L = v60 - v800;
            let v802: L = v801 * v3;
            let v803: L = v798 + v802;
            let v804: L = v803 * v212;
            let v805: L = -L::splat(0.000116928_f64);
            let v806: L = v805 + v800;
            let v807: L = v806 * v96;
            let v808: L = v66 + v807;
            let v809: L = v284 * v3;
            let v810: L = v808 + v809;
            let v811: L = v810 * v172;
            let v812: L = v804 + v811;
            let v813: L = v812 * v96;
            let v814: L = v797 + v813;
            let v815: L = v814 * v376;
            let v816: L = v793 + v815;
            let v817: L = v816 * v17;
            let v818: L = v789 + v817;
            let v819: L = v818 * v27;
            let v820: L = v774 + v819;
            let v821: L = v820 * v172;
            let v822: L = v738 + v821;
            let v823: L = v384 * v33;
            let v824: L = v823 * v14;
            let v825: L = v824 * v3;
            let v826: L = v384 * v20;
            let v827: L = v384 * v9;
            let v828: L = v384 * v6;
            let v829: L = v827 + v828;
            let v830: L = v829 * v17;
            let v831: L = v826 + v830;
            let v832: L = v831 * v96;
            let v833: L = v825 - v832;
            let v834: L = v833 * v172;
            let v835: L = v824 * v96;
            let v836: L = v831 * v3;
            let v837: L = v835 + v836;
            let v838: L = v837 * v212;
            let v839: L = v834 + v838;
            let v840: L = v839 * v49;
            let v841: L = v826 * v17;
            let v842: L = v829 + v841;
            let v843: L = v842 * v3;
            let v844: L = v843 * v172;
            let v845: L = v842 * v96;
            let v846: L = v845 * v212;
            let v847: L = v844 + v846;
            let v848: L = v847 * v27;
            let v849: L = v840 - v848;
            let v850: L = v386 + v615;
            let v851: L = v850 * v49;
            let v852: L = v851 * v17;
            let v853: L = -L::splat(0.00022_f64);
            let v854: L = v67 * v27;
            let v855: L = v853 + v854;
            let v856: L = v855 * v20;
            let v857: L = v856 * v14;
            let v858: L = v852 + v857;
            let v859: L = v858 * v96;
            let v860: L = L::splat(0.00077_f64);
            let v861: L = v860 * v33;
            let v862: L = v72 * v14;
            let v863: L = v386 - v862;
            let v864: L = v863 * v27;
            let v865: L = v861 + v864;
            let v866: L = v631 * v14;
            let v867: L = v591 * v33;
            let v868: L = v866 + v867;
            let v869: L = v868 * v17;
            let v870: L = v865 + v869;
            let v871: L = v870 * v3;
            let v872: L = v859 + v871;
            let v873: L = v872 * v172;
            let v874: L = v386 * v27;
            let v875: L = v861 + v874;
            let v876: L = v875 * v96;
            let v877: L = v620 * v3;
            let v878: L = v40 * v3;
            let v879: L = v790 + v878;
            let v880: L = v879 * v27;
            let v881: L = v877 + v880;
            let v882: L = v881 * v20;
            let v883: L = v882 * v14;
            let v884: L = v876 + v883;
            let v885: L = v77 * v17;
            let v886: L = v885 * v96;
            let v887: L = v32 * v14;
            let v888: L = v887 * v96;
            let v889: L = v386 * v3;
            let v890: L = v888 - v889;
            let v891: L = v879 * v33;
            let v892: L = v890 + v891;
            let v893: L = v892 * v49;
            let v894: L = v886 + v893;
            let v895: L = v894 * v17;
            let v896: L = v884 + v895;
            let v897: L = v896 * v212;
            let v898: L = v873 + v897;
            let v899: L = L::splat(0.004173999_f64);
            let v900: L = v899 + v351;
            let v901: L = v900 - v4;
            let v902: L = v159 * v49;
            let v903: L = v902 * v17;
            let v904: L = v901 + v903;
            let v905: L = -L::splat(0.022546398_f64);
            let v906: L = v905 - v357;
            let v907: L = v80 + v119;
            let v908: L = v907 * v49;
            let v909: L = v908 * v17;
            let v910: L = v906 + v909;
            let v911: L = v910 * v96;
            let v912: L = v570 + v911;
            let v913: L = v80 + v39;
            let v914: L = v913 * v27;
            let v915: L = v103 + v914;
            let v916: L = -L::splat(0.00030216_f64);
            let v917: L = v916 + v75;
            let v918: L = v917 * v17;
            let v919: L = v368 + v918;
            let v920: L = v919 * v17;
            let v921: L = v915 + v920;
            let v922: L = v921 * v3;
            let v923: L = v912 + v922;
            let v924: L = v923 * v96;
            let v925: L = v904 + v924;
            let v926: L = -L::splat(0.008347998_f64);
            let v927: L = v926 - v357;
            let v928: L = v147 * v3;
            let v929: L = v927 + v928;
            let v930: L = v907 - v197;
            let v931: L = v930 * v49;
            let v932: L = v931 * v17;
            let v933: L = v929 + v932;
            let v934: L = v933 * v172;
            let v935: L = v179 * v3;
            let v936: L = v174 - v935;
            let v937: L = v368 - v413;
            let v938: L = v937 * v17;
            let v939: L = v936 + v938;
            let v940: L = v80 - v197;
            let v941: L = v30 * v17;
            let v942: L = v941 * v17;
            let v943: L = v30 + v942;
            let v944: L = v943 * v27;
            let v945: L = v940 + v944;
            let v946: L = v945 * v27;
            let v947: L = v939 + v946;
            let v948: L = v947 * v212;
            let v949: L = v934 + v948;
            let v950: L = v179 + v488;
            let v951: L = v521 * v96;
            let v952: L = v950 + v951;
            let v953: L = -L::splat(0.647839691_f64);
            let v954: L = v517 - v119;
            let v955: L = v954 * v27;
            let v956: L = v953 + v955;
            let v957: L = v265 * v17;
            let v958: L = v957 - v502;
            let v959: L = v958 * v17;
            let v960: L = v956 + v959;
            let v961: L = v960 * v3;
            let v962: L = v952 + v961;
            let v963: L = v962 * v172;
            let v964: L = v147 - v514;
            let v965: L = v496 * v3;
            let v966: L = v964 + v965;
            let v967: L = v960 * v96;
            let v968: L = v966 + v967;
            let v969: L = v968 * v212;
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
            let v970: L = v963 + v969;
            let v971: L = v970 * v96;
            let v972: L = v949 + v971;
            let v973: L = v972 * v172;
            let v974: L = v925 + v973;
            let v975: L = v974 * v376;
            let v976: L = v898 + v975;
            let v977: L = v570 * v96;
            let v978: L = v977 - v4;
            let v979: L = v978 * v9;
            let v980: L = -L::splat(5.8464e-05_f64);
            let v981: L = v38 * v96;
            let v982: L = v980 - v981;
            let v983: L = v982 * v20;
            let v984: L = v153 + v983;
            let v985: L = v984 * v27;
            let v986: L = v142 * v14;
            let v987: L = v985 - v986;
            let v988: L = v987 * v17;
            let v989: L = v979 + v988;
            let v990: L = v162 * v17;
            let v991: L = v990 * v3;
            let v992: L = v16 + v981;
            let v993: L = v992 * v33;
            let v994: L = v993 * v14;
            let v995: L = v991 + v994;
            let v996: L = -L::splat(0.00020216_f64);
            let v997: L = v996 + v942;
            let v998: L = v997 * v27;
            let v999: L = v201 + v998;
            let v1000: L = v999 * v20;
            let v1001: L = v995 + v1000;
            let v1002: L = v1001 * v49;
            let v1003: L = v989 + v1002;
            let v1004: L = v917 * v33;
            let v1005: L = v1004 * v14;
            let v1006: L = v1005 - v73;
            let v1007: L = v1006 * v17;
            let v1008: L = v1 * v6;
            let v1009: L = v146 + v1008;
            let v1010: L = v1009 * v3;
            let v1011: L = v1007 - v1010;
            let v1012: L = v52 * v6;
            let v1013: L = v178 + v1012;
            let v1014: L = v162 + v419;
            let v1015: L = v215 * v17;
            let v1016: L = v1014 + v1015;
            let v1017: L = v1016 * v27;
            let v1018: L = v1013 + v1017;
            let v1019: L = v1018 * v96;
            let v1020: L = v1011 - v1019;
            let v1021: L = v1014 * v17;
            let v1022: L = v1021 * v3;
            let v1023: L = v994 + v1022;
            let v1024: L = v1023 + v1000;
            let v1025: L = v1024 * v49;
            let v1026: L = v1020 + v1025;
            let v1027: L = v860 * v3;
            let v1028: L = v1027 * v172;
            let v1029: L = v860 * v96;
            let v1030: L = v1029 * v212;
            let v1031: L = v1028 + v1030;
            let v1032: L = v1031 * v376;
            let v1033: L = v159 * v27;
            let v1034: L = v853 + v1033;
            let v1035: L = v1034 * v20;
            let v1036: L = v1014 * v96;
            let v1037: L = v24 + v1036;
            let v1038: L = v1037 * v49;
            let v1039: L = v1035 + v1038;
            let v1040: L = v1039 * v14;
            let v1041: L = v1032 + v1040;
            let v1042: L = v76 * v3;
            let v1043: L = v1042 * v172;
            let v1044: L = v76 * v96;
            let v1045: L = v1044 * v212;
            let v1046: L = v1043 + v1045;
            let v1047: L = v1046 * v376;
            let v1048: L = v1047 * v17;
            let v1049: L = v401 * v14;
            let v1050: L = v1048 + v1049;
            let v1051: L = v159 * v33;
            let v1052: L = v386 + v1051;
            let v1053: L = v690 * v172;
            let v1054: L = v879 * v212;
            let v1055: L = v1053 + v1054;
            let v1056: L = v1055 * v376;
            let v1057: L = v1052 + v1056;
            let v1058: L = v1057 * v49;
            let v1059: L = v1050 + v1058;
            let v1060: L = v1059 * v17;
            let v1061: L = v1041 + v1060;
            let v1062: L = v877 * v212;
            let v1063: L = v620 * v96;
            let v1064: L = v1063 * v172;
            let v1065: L = v1062 - v1064;
            let v1066: L = v1065 * v376;
            let v1067: L = v1066 - v705;
            let v1068: L = v1067 * v14;
            let v1069: L = v1016 * v3;
            let v1070: L = v1069 - v1016;
            let v1071: L = v1070 * v49;
            let v1072: L = v1068 + v1071;
            let v1073: L = v983 - v728;
            let v1074: L = v980 + v693;
            let v1075: L = v1074 - v981;
            let v1076: L = v1075 * v9;
            let v1077: L = v1075 * v6;
            let v1078: L = v1076 + v1077;
            let v1079: L = v1078 * v17;
            let v1080: L = v1073 + v1079;
            let v1081: L = v1074 * v3;
            let v1082: L = v688 + v1081;
            let v1083: L = v1082 * v172;
            let v1084: L = v1074 * v96;
            let v1085: L = v66 + v1084;
            let v1086: L = v1085 + v878;
            let v1087: L = v1086 * v212;
            let v1088: L = v1083 + v1087;
            let v1089: L = v1088 * v376;
            let v1090: L = v1052 + v1089;
            let v1091: L = v1090 * v14;
            let v1092: L = v1080 + v1091;
            let v1093: L = v1092 * v27;
            let v1094: L = v1072 + v1093;
            let v1095: L = v823 * v49;
            let v1096: L = v1095 * v17;
            let v1097: L = v826 * v27;
            let v1098: L = v1097 * v14;
            let v1099: L = v1096 + v1098;
            let v1100: L = v384 * v49;
            let v1101: L = v1100 * v17;
            let v1102: L = v1101 * v96;
            let v1103: L = v384 * v27;
            let v1104: L = v1103 * v3;
            let v1105: L = v1102 + v1104;
            let v1106: L = v1105 * v172;
            let v1107: L = v1103 * v96;
            let v1108: L = v1101 * v3;
            let v1109: L = v1107 - v1108;
            let v1110: L = v1109 * v212;
            let v1111: L = v1106 + v1110;
            let v1112: L = v1111 * v376;
            let v1113: L = v1099 + v1112;
            let v1114: L = v875 * v3;
            let v1115: L = v1114 * v172;
            let v1116: L = v876 * v212;
            let v1117: L = v1115 + v1116;
            let v1118: L = v878 - v656;
            let v1119: L = v1118 * v212;
            let v1120: L = v1053 + v1119;
            let v1121: L = v1120 * v27;
            let v1122: L = v1065 + v1121;
            let v1123: L = v1122 * v20;
            let v1124: L = v1123 * v14;
            let v1125: L = v1117 + v1124;
            let v1126: L = v1046 * v33;
            let v1127: L = v1126 * v17;
            let v1128: L = v386 * v96;
            let v1129: L = v887 * v3;
            let v1130: L = v1128 + v1129;
            let v1131: L = v1130 * v172;
            let v1132: L = v890 * v212;
            let v1133: L = v1131 + v1132;
            let v1134: L = v1120 * v33;
            let v1135: L = v1133 + v1134;
            let v1136: L = v1135 * v49;
            let v1137: L = v1127 + v1136;
            let v1138: L = v1137 * v17;
            let v1139: L = v1125 + v1138;
            let v1140: L = v8 + v351;
            let v1141: L = v67 * v49;
            let v1142: L = v1141 * v17;
            let v1143: L = v1140 + v1142;
            let v1144: L = v911 + v922;
            let v1145: L = v1144 * v96;
            let v1146: L = v1143 + v1145;
            let v1147: L = v906 + v4;
            let v1148: L = v907 - v43;
            let v1149: L = v1148 * v49;
            let v1150: L = v1149 * v17;
            let v1151: L = v1147 + v1150;
            let v1152: L = v1151 * v172;
            let v1153: L = v52 * v3;
            let v1154: L = v103 - v1153;
            let v1155: L = v1154 + v938;
            let v1156: L = v80 - v43;
            let v1157: L = v1156 + v944;
            let v1158: L = v1157 * v27;
            let v1159: L = v1155 + v1158;
            let v1160: L = v1159 * v212;
            let v1161: L = v1152 + v1160;
            let v1162: L = v54 + v951;
            let v1163: L = v1162 + v961;
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
            let v1164: L = v1163 * v172;
            let v1165: L = v1 - v575;
            let v1166: L = v1165 + v965;
            let v1167: L = v1166 + v967;
            let v1168: L = v1167 * v212;
            let v1169: L = v1164 + v1168;
            let v1170: L = v1169 * v96;
            let v1171: L = v1161 + v1170;
            let v1172: L = v1171 * v172;
            let v1173: L = v1146 + v1172;
            let v1174: L = v1173 * v376;
            let v1175: L = v1139 + v1174;
            let v1176: L = v54 * v96;
            let v1177: L = v4 + v1176;
            let v1178: L = v1177 * v6;
            let v1179: L = v35 + v68;
            let v1180: L = v1179 * v49;
            let v1181: L = v1178 + v1180;
            let v1182: L = v1074 * v20;
            let v1183: L = v153 + v1182;
            let v1184: L = v1183 * v27;
            let v1185: L = v419 * v49;
            let v1186: L = v1185 * v3;
            let v1187: L = v986 + v1186;
            let v1188: L = v1184 - v1187;
            let v1189: L = v1188 * v17;
            let v1190: L = v1181 + v1189;
            let v1191: L = v1184 - v986;
            let v1192: L = v1191 * v17;
            let v1193: L = v1180 + v1192;
            let v1194: L = v399 + v856;
            let v1195: L = v1194 * v14;
            let v1196: L = v1032 + v1195;
            let v1197: L = v851 + v1049;
            let v1198: L = v1046 * v17;
            let v1199: L = v1120 * v49;
            let v1200: L = v1198 + v1199;
            let v1201: L = v1200 * v376;
            let v1202: L = v1197 + v1201;
            let v1203: L = v1202 * v17;
            let v1204: L = v1196 + v1203;
            let v1205: L = v1016 * v49;
            let v1206: L = v1068 - v1205;
            let v1207: L = v728 * v17;
            let v1208: L = v1207 - v24;
            let v1209: L = v1208 * v17;
            let v1210: L = v72 + v728;
            let v1211: L = v1209 - v1210;
            let v1212: L = v1084 + v878;
            let v1213: L = v1212 * v212;
            let v1214: L = v1083 + v1213;
            let v1215: L = v1214 * v376;
            let v1216: L = v850 + v1215;
            let v1217: L = v1216 * v14;
            let v1218: L = v1211 + v1217;
            let v1219: L = v1218 * v27;
            let v1220: L = v1206 + v1219;
            let v1221: L = v30 * v96;
            let v1222: L = v1221 * v172;
            let v1223: L = v692 * v212;
            let v1224: L = v1222 - v1223;
            let v1225: L = v1224 * v20;
            let v1226: L = v1225 * v27;
            let v1227: L = v67 * v3;
            let v1228: L = v656 + v1227;
            let v1229: L = v1228 * v96;
            let v1230: L = v980 + v1229;
            let v1231: L = v159 * v212;
            let v1232: L = v662 + v1231;
            let v1233: L = v907 * v96;
            let v1234: L = v665 + v1233;
            let v1235: L = v1234 * v212;
            let v1236: L = v66 - v668;
            let v1237: L = v907 * v3;
            let v1238: L = v1236 + v1237;
            let v1239: L = v1238 * v172;
            let v1240: L = v1235 + v1239;
            let v1241: L = v1240 * v96;
            let v1242: L = v1232 + v1241;
            let v1243: L = v1242 * v172;
            let v1244: L = v1230 + v1243;
            let v1245: L = v1244 * v376;
            let v1246: L = v384 * v3;
            let v1247: L = v1246 * v172;
            let v1248: L = v384 * v96;
            let v1249: L = v1248 * v212;
            let v1250: L = v1247 + v1249;
            let v1251: L = v1250 * v385;
            let v1252: L = v1245 - v1251;
            let v1253: L = v1252 * v14;
            let v1254: L = v1226 + v1253;
            let v1255: L = v1254 * v49;
            let v1256: L = v860 * v9;
            let v1257: L = v860 * v6;
            let v1258: L = v1256 + v1257;
            let v1259: L = v1258 * v3;
            let v1260: L = v1259 * v172;
            let v1261: L = v1258 * v96;
            let v1262: L = v1261 * v212;
            let v1263: L = v1260 + v1262;
            let v1264: L = v1255 - v1263;
            let v1265: L = v917 * v14;
            let v1266: L = v1265 * v96;
            let v1267: L = v1266 * v96;
            let v1268: L = v1267 - v587;
            let v1269: L = v1268 * v376;
            let v1270: L = v1014 + v115;
            let v1271: L = v1270 * v3;
            let v1272: L = v419 - v1271;
            let v1273: L = v1272 * v49;
            let v1274: L = v403 * v96;
            let v1275: L = v1273 + v1274;
            let v1276: L = v1275 * v212;
            let v1277: L = v1269 + v1276;
            let v1278: L = v917 * v376;
            let v1279: L = v1278 * v14;
            let v1280: L = v1279 * v172;
            let v1281: L = v265 * v376;
            let v1282: L = v1281 * v14;
            let v1283: L = v1282 * v96;
            let v1284: L = v1283 * v172;
            let v1285: L = v1270 * v49;
            let v1286: L = v1284 + v1285;
            let v1287: L = v1286 * v96;
            let v1288: L = v1280 + v1287;
            let v1289: L = v504 * v376;
            let v1290: L = v1289 * v14;
            let v1291: L = v1290 * v96;
            let v1292: L = v1291 * v212;
            let v1293: L = v400 + v1292;
            let v1294: L = v1293 + v402;
            let v1295: L = v1294 * v3;
            let v1296: L = v1288 + v1295;
            let v1297: L = v1296 * v172;
            let v1298: L = v1277 + v1297;
            let v1299: L = v1298 * v17;
            let v1300: L = v1264 + v1299;
            let v1301: L = v982 * v6;
            let v1302: L = v1301 - v22;
            let v1303: L = v1302 * v49;
            let v1304: L = v482 + v1303;
            let v1305: L = v1304 * v14;
            let v1306: L = v1305 - v1032;
            let v1307: L = v130 * v14;
            let v1308: L = v386 * v49;
            let v1309: L = v1307 - v1308;
            let v1310: L = v917 * v3;
            let v1311: L = v1310 * v172;
            let v1312: L = v917 * v96;
            let v1313: L = v1312 * v212;
            let v1314: L = v1311 + v1313;
            let v1315: L = v1314 * v17;
            let v1316: L = v40 * v96;
            let v1317: L = v689 + v1316;
            let v1318: L = v1317 * v172;
            let v1319: L = v657 + v1227;
            let v1320: L = v1319 * v212;
            let v1321: L = v1318 + v1320;
            let v1322: L = v1321 * v49;
            let v1323: L = v1315 + v1322;
            let v1324: L = v1323 * v376;
            let v1325: L = v1309 + v1324;
            let v1326: L = v1325 * v17;
            let v1327: L = v1306 + v1326;
            let v1328: L = v483 * v14;
            let v1329: L = v1328 - v1032;
            let v1330: L = v1228 * v212;
            let v1331: L = v1318 + v1330;
            let v1332: L = v1331 * v49;
            let v1333: L = v1315 + v1332;
            let v1334: L = v1333 * v376;
            let v1335: L = v1309 + v1334;
            let v1336: L = v1335 * v17;
            let v1337: L = v1329 + v1336;
            let v1338: L = v480 * v3;
            let v1339: L = v1338 * v172;
            let v1340: L = v480 * v96;
            let v1341: L = v1340 * v212;
            let v1342: L = v1339 + v1341;
            let v1343: L = v1342 * v376;
            let v1344: L = v1343 * v17;
            let v1345: L = v1308 + v1344;
            let v1346: L = v716 - v1345;
            let v1347: L = v1224 * v376;
            let v1348: L = v108 + v1347;
            let v1349: L = v1348 * v49;
            let v1350: L = v692 * v172;
            let v1351: L = v1221 * v212;
            let v1352: L = v1350 + v1351;
            let v1353: L = v1352 * v376;
            let v1354: L = v1353 * v17;
            let v1355: L = v114 * v14;
            let v1356: L = v1354 - v1355;
            let v1357: L = v1356 * v27;
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
        let (
            v1360,
            v1365,
            v1470,
            v1496,
            v1509,
            v1519,
            v1520,
            v1531,
            v1536,
            v1539,
            v1546,
        ) = {
            let v1358: L = v1349 + v1357;
            let v1359: L = v1358 * v27;
            let v1360: L = v1346 + v1359;
            let v1361: L = v1250 * v376;
            let v1362: L = v1361 * v14;
            let v1363: L = v831 + v1362;
            let v1364: L = v1363 * v49;
            let v1365: L = -v1364;
            let v1366: L = v555 * v49;
            let v1367: L = v1366 * v96;
            let v1368: L = v480 * v33;
            let v1369: L = v1368 * v17;
            let v1370: L = v1369 * v212;
            let v1371: L = v1367 + v1370;
            let v1372: L = v1371 * v96;
            let v1373: L = v589 - v941;
            let v1374: L = v1373 * v376;
            let v1375: L = v1374 * v96;
            let v1376: L = v620 * v9;
            let v1377: L = v620 * v6;
            let v1378: L = v1376 + v1377;
            let v1379: L = v1378 * v14;
            let v1380: L = v1308 + v1379;
            let v1381: L = v1380 * v212;
            let v1382: L = v1375 - v1381;
            let v1383: L = v1382 * v3;
            let v1384: L = v1372 + v1383;
            let v1385: L = v1369 * v3;
            let v1386: L = v1380 * v96;
            let v1387: L = v1385 + v1386;
            let v1388: L = v746 * v3;
            let v1389: L = v1388 * v172;
            let v1390: L = v746 * v96;
            let v1391: L = v996 + v1390;
            let v1392: L = v1391 * v212;
            let v1393: L = v1389 + v1392;
            let v1394: L = v1393 * v17;
            let v1395: L = v754 * v172;
            let v1396: L = v758 + v1395;
            let v1397: L = v1236 + v197;
            let v1398: L = v1397 * v212;
            let v1399: L = v1398 - v765;
            let v1400: L = v1399 * v96;
            let v1401: L = v1396 + v1400;
            let v1402: L = v1401 * v49;
            let v1403: L = v1394 + v1402;
            let v1404: L = v1403 * v376;
            let v1405: L = v1387 + v1404;
            let v1406: L = v1405 * v172;
            let v1407: L = v1384 + v1406;
            let v1408: L = v720 - v15;
            let v1409: L = v684 * v96;
            let v1410: L = v38 + v119;
            let v1411: L = v1410 * v3;
            let v1412: L = v1084 + v1411;
            let v1413: L = v1412 * v17;
            let v1414: L = v1409 + v1413;
            let v1415: L = v1414 * v96;
            let v1416: L = v1408 + v1415;
            let v1417: L = v1416 * v376;
            let v1418: L = v109 * v3;
            let v1419: L = v386 - v152;
            let v1420: L = v1419 * v17;
            let v1421: L = v1420 * v96;
            let v1422: L = v1418 + v1421;
            let v1423: L = v695 + v1227;
            let v1424: L = v1423 * v9;
            let v1425: L = v38 + v695;
            let v1426: L = v1425 + v1227;
            let v1427: L = v1426 * v6;
            let v1428: L = v1424 + v1427;
            let v1429: L = v1428 * v14;
            let v1430: L = v1422 + v1429;
            let v1431: L = v1430 * v212;
            let v1432: L = v1417 + v1431;
            let v1433: L = v24 * v14;
            let v1434: L = v1433 * v3;
            let v1435: L = v777 + v1434;
            let v1436: L = v780 - v779;
            let v1437: L = v1436 * v376;
            let v1438: L = v1437 - v108;
            let v1439: L = v1438 * v49;
            let v1440: L = v1270 * v14;
            let v1441: L = v1439 + v1440;
            let v1442: L = v1441 * v96;
            let v1443: L = v1435 + v1442;
            let v1444: L = v1419 - v729;
            let v1445: L = v1444 * v3;
            let v1446: L = v1074 * v172;
            let v1447: L = v1410 - v43;
            let v1448: L = v1447 * v212;
            let v1449: L = v1446 + v1448;
            let v1450: L = v192 - v283;
            let v1451: L = v1450 * v96;
            let v1452: L = v806 * v3;
            let v1453: L = v1451 + v1452;
            let v1454: L = v1453 * v212;
            let v1455: L = v801 * v96;
            let v1456: L = v38 + v1455;
            let v1457: L = v1450 * v3;
            let v1458: L = v1456 + v1457;
            let v1459: L = v1458 * v172;
            let v1460: L = v1454 + v1459;
            let v1461: L = v1460 * v96;
            let v1462: L = v1449 + v1461;
            let v1463: L = v1462 * v376;
            let v1464: L = v1445 + v1463;
            let v1465: L = v1464 * v17;
            let v1466: L = v1443 + v1465;
            let v1467: L = v1466 * v172;
            let v1468: L = v1432 + v1467;
            let v1469: L = v1468 * v27;
            let v1470: L = v1407 + v1469;
            let v1471: L = v754 * v6;
            let v1472: L = v162 + v1471;
            let v1473: L = v1472 * v49;
            let v1474: L = v1064 - v1062;
            let v1475: L = v1474 * v376;
            let v1476: L = v1475 - v1368;
            let v1477: L = v1476 * v14;
            let v1478: L = v1473 + v1477;
            let v1479: L = v694 * v9;
            let v1480: L = v694 + v981;
            let v1481: L = v1480 * v6;
            let v1482: L = v1479 + v1481;
            let v1483: L = v1482 * v17;
            let v1484: L = v728 + v1483;
            let v1485: L = v152 - v386;
            let v1486: L = v694 * v3;
            let v1487: L = v1316 + v1486;
            let v1488: L = v1487 * v172;
            let v1489: L = v1426 * v212;
            let v1490: L = v1488 + v1489;
            let v1491: L = v1490 * v376;
            let v1492: L = v1485 + v1491;
            let v1493: L = v1492 * v14;
            let v1494: L = v1484 + v1493;
            let v1495: L = v1494 * v27;
            let v1496: L = v1478 + v1495;
            let v1497: L = v1014 * v49;
            let v1498: L = v1497 + v1477;
            let v1499: L = v24 - v1207;
            let v1500: L = v1499 * v17;
            let v1501: L = v728 + v1500;
            let v1502: L = v1423 * v212;
            let v1503: L = v1488 + v1502;
            let v1504: L = v1503 * v376;
            let v1505: L = v1485 + v1504;
            let v1506: L = v1505 * v14;
            let v1507: L = v1501 + v1506;
            let v1508: L = v1507 * v27;
            let v1509: L = v1498 + v1508;
            let v1510: L = v1345 - v716;
            let v1511: L = v1223 - v1222;
            let v1512: L = v1511 * v376;
            let v1513: L = v1512 - v108;
            let v1514: L = v1513 * v49;
            let v1515: L = v1355 - v1354;
            let v1516: L = v1515 * v27;
            let v1517: L = v1514 + v1516;
            let v1518: L = v1517 * v27;
            let v1519: L = v1510 + v1518;
            let v1520: L = L::splat(0.0_f64);
            let v1521: L = v1248 * v172;
            let v1522: L = v1246 * v212;
            let v1523: L = v1521 - v1522;
            let v1524: L = v1523 * v376;
            let v1525: L = v823 + v1524;
            let v1526: L = v1525 * v49;
            let v1527: L = v1361 * v17;
            let v1528: L = v829 * v14;
            let v1529: L = v1527 - v1528;
            let v1530: L = v1529 * v27;
            let v1531: L = v1526 + v1530;
            let v1532: L = v1108 - v1107;
            let v1533: L = v1532 * v212;
            let v1534: L = v1533 - v1106;
            let v1535: L = v1534 * v376;
            let v1536: L = v1099 + v1535;
            let v1537: L = v830 - v826;
            let v1538: L = v1537 + v1362;
            let v1539: L = v1538 * v49;
            let v1540: L = v1522 - v1521;
            let v1541: L = v1540 * v376;
            let v1542: L = v1541 - v823;
            let v1543: L = v1542 * v49;
            let v1544: L = v1528 - v1527;
            let v1545: L = v1544 * v27;
            let v1546: L = v1543 + v1545;
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
    /// - `q: &[L; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
    /// - `qd: &[L; 6]`: joint velocities qd (rad/s or m/s)
    ///
    /// # Output
    ///
    /// `coriolis: [L; 6]`: c(q, qd) = C(q, qd) qd (N m or N)
    ///
    /// Operation count: 479 floating-point operations, 10 trig calls.
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
            v10,
            v11,
            v14,
            v16,
            v21,
            v24,
            v28,
            v32,
            v33,
            v37,
            v39,
            v41,
            v44,
            v46,
            v47,
            v49,
            v54,
            v57,
            v59,
            v65,
            v67,
            v70,
            v72,
            v75,
            v77,
            v79,
            v85,
            v89,
            v92,
            v96,
            v98,
            v105,
            v107,
            v116,
            v119,
            v121,
            v122,
            v124,
            v127,
            v128,
            v130,
            v132,
            v133,
            v135,
            v136,
            v140,
            v149,
            v154,
            v157,
            v159,
            v161,
            v162,
            v164,
            v170,
            v172,
            v173,
            v175,
            v176,
            v177,
        ) = {
            let v0: L = q[1];
            let (v1, v3): (L, L) = L::sincos(v0);
            let v2: L = L::splat(1.03118515_f64);
            let v4: L = qd[0];
            let v5: L = v3 * v4;
            let v6: L = qd[1];
            let v7: L = v5 * v6;
            let v8: L = v2 * v7;
            let v9: L = L::splat(0.03798072_f64);
            let v10: L = v1 * v4;
            let v11: L = v10 * v6;
            let v12: L = v9 * v11;
            let v13: L = v8 - v12;
            let v14: L = L::splat(1.4401023_f64);
            let v15: L = v14 * v10;
            let v16: L = -L::splat(0.023751_f64);
            let v17: L = v16 * v5;
            let v18: L = v15 + v17;
            let v19: L = L::splat(2.842524056_f64);
            let v20: L = v19 * v6;
            let v21: L = v18 + v20;
            let v22: L = v5 * v21;
            let v23: L = v9 * v10;
            let v24: L = L::splat(3.727456406_f64);
            let v25: L = v24 * v5;
            let v26: L = v23 + v25;
            let v27: L = v16 * v6;
            let v28: L = v26 + v27;
            let v29: L = v6 * v28;
            let v30: L = v22 - v29;
            let v31: L = v13 + v30;
            let v32: L = L::splat(0.1044_f64);
            let v33: L = L::splat(0.4318_f64);
            let v34: L = v33 * v11;
            let v35: L = v33 * v6;
            let v36: L = v10 * v35;
            let v37: L = v34 + v36;
            let v38: L = v32 * v37;
            let v39: L = L::splat(3.9585_f64);
            let v40: L = v33 * v5;
            let v41: L = v10 * v40;
            let v42: L = v39 * v41;
            let v43: L = v38 - v42;
            let v44: L = v31 + v43;
            let v45: L = q[2];
            let (v49, v46): (L, L) = L::sincos(v45);
            let v47: L = L::splat(0.090474288_f64);
            let v48: L = v46 * v7;
            let v50: L = v49 * v11;
            let v51: L = v48 - v50;
            let v52: L = v46 * v5;
            let v53: L = v49 * v10;
            let v54: L = v52 - v53;
            let v55: L = qd[2];
            let v56: L = v54 * v55;
            let v57: L = v51 + v56;
            let v58: L = v47 * v57;
            let v59: L = L::splat(0.0068208_f64);
            let v60: L = v49 * v7;
            let v61: L = v46 * v11;
            let v62: L = v60 + v61;
            let v63: L = v46 * v10;
            let v64: L = v49 * v5;
            let v65: L = v63 + v64;
            let v66: L = v65 * v55;
            let v67: L = v62 + v66;
            let v68: L = v59 * v67;
            let v69: L = v58 - v68;
            let v70: L = v6 + v55;
            let v71: L = v59 * v65;
            let v72: L = L::splat(0.0047376_f64);
            let v73: L = v72 * v70;
            let v74: L = v71 - v73;
            let v75: L = L::splat(0.01543232_f64);
            let v76: L = v75 * v54;
            let v77: L = v74 + v76;
            let v78: L = v70 * v77;
            let v79: L = -L::splat(0.001373904_f64);
            let v80: L = v79 * v65;
            let v81: L = L::splat(0.111498032_f64);
            let v82: L = v81 * v70;
            let v83: L = v80 - v82;
            let v84: L = v72 * v54;
            let v85: L = v83 + v84;
            let v86: L = v54 * v85;
            let v87: L = v78 + v86;
            let v88: L = v69 - v87;
            let v89: L = -L::splat(0.06768_f64);
            let v90: L = v5 * v40;
            let v91: L = v6 * v35;
            let v92: L = v90 + v91;
            let v93: L = v49 * v92;
            let v94: L = v46 * v41;
            let v95: L = v93 + v94;
            let v96: L = -L::splat(0.15005_f64);
            let v97: L = v96 * v57;
            let v98: L = L::splat(0.0203_f64);
            let v99: L = v98 * v54;
            let v100: L = v65 * v99;
            let v101: L = v96 * v54;
            let v102: L = v70 * v101;
            let v103: L = v100 - v102;
            let v104: L = v97 + v103;
            let v105: L = v95 + v104;
            let v106: L = v89 * v105;
            let v107: L = L::splat(0.336_f64);
            let v108: L = v98 * v67;
            let v109: L = v54 * v101;
            let v110: L = v96 * v65;
            let v111: L = v98 * v70;
            let v112: L = v110 + v111;
            let v113: L = v65 * v112;
            let v114: L = v109 + v113;
            let v115: L = v108 + v114;
            let v116: L = v37 + v115;
            let v117: L = v107 * v116;
            let v118: L = v106 + v117;
            let v119: L = v88 + v118;
            let v120: L = q[3];
            let (v124, v121): (L, L) = L::sincos(v120);
            let v122: L = L::splat(0.00209602_f64);
            let v123: L = v121 * v57;
            let v125: L = v124 * v65;
            let v126: L = v121 * v70;
            let v127: L = v125 + v126;
            let v128: L = qd[3];
            let v129: L = v127 * v128;
            let v130: L = v123 - v129;
            let v131: L = v122 * v130;
            let v132: L = v54 + v128;
            let v133: L = v122 * v127;
            let v134: L = v132 * v133;
            let v135: L = L::splat(0.0013_f64);
            let v136: L = v135 * v132;
            let v137: L = v127 * v136;
            let v138: L = v134 - v137;
            let v139: L = v131 + v138;
            let v140: L = L::splat(0.01558_f64);
            let v141: L = v49 * v41;
            let v142: L = v46 * v92;
            let v143: L = v141 - v142;
            let v144: L = v96 * v67;
            let v145: L = v70 * v112;
            let v146: L = v54 * v99;
            let v147: L = v145 + v146;
            let v148: L = v144 - v147;
            let v149: L = v143 + v148;
            let v150: L = v124 * v149;
            let v151: L = v121 * v116;
            let v152: L = v150 + v151;
            let v153: L = v33 * v130;
            let v154: L = v33 * v127;
            let v155: L = v132 * v154;
            let v156: L = v153 + v155;
            let v157: L = v152 + v156;
            let v158: L = v140 * v157;
            let v159: L = v139 + v158;
            let v160: L = q[4];
            let (v164, v161): (L, L) = L::sincos(v160);
            let v162: L = L::splat(0.0003_f64);
            let v163: L = v161 * v130;
            let v165: L = v164 * v67;
            let v166: L = v163 - v165;
            let v167: L = v161 * v132;
            let v168: L = v121 * v65;
            let v169: L = v124 * v70;
            let v170: L = v168 - v169;
            let v171: L = v164 * v170;
            let v172: L = v167 - v171;
            let v173: L = qd[4];
            let v174: L = v172 * v173;
            let v175: L = v166 + v174;
            let v176: L = v162 * v175;
            let v177: L = L::splat(0.0004_f64);
            (
                v1,
                v2,
                v3,
                v5,
                v6,
                v7,
                v9,
                v10,
                v11,
                v14,
                v16,
                v21,
                v24,
                v28,
                v32,
                v33,
                v37,
                v39,
                v41,
                v44,
                v46,
                v47,
                v49,
                v54,
                v57,
                v59,
                v65,
                v67,
                v70,
                v72,
                v75,
                v77,
                v79,
                v85,
                v89,
                v92,
                v96,
                v98,
                v105,
                v107,
                v116,
                v119,
                v121,
                v122,
                v124,
                v127,
                v128,
                v130,
                v132,
                v133,
                v135,
                v136,
                v140,
                v149,
                v154,
                v157,
                v159,
                v161,
                v162,
                v164,
                v170,
                v172,
                v173,
                v175,
                v176,
                v177,
            )
        };
        let (
            v226,
            v256,
            v273,
            v274,
            v278,
            v281,
            v304,
            v306,
            v310,
            v324,
            v327,
            v336,
            v347,
            v350,
            v352,
            v355,
        ) = {
            let v178: L = v127 + v173;
            let v179: L = v177 * v178;
            let v180: L = v172 * v179;
            let v181: L = v162 * v172;
            let v182: L = v178 * v181;
            let v183: L = v180 - v182;
            let v184: L = v176 + v183;
            let v185: L = q[5];
            let (v189, v186): (L, L) = L::sincos(v185);
            let v187: L = L::splat(0.00024216_f64);
            let v188: L = v186 * v175;
            let v190: L = v124 * v57;
            let v191: L = v170 * v128;
            let v192: L = v190 + v191;
            let v193: L = v189 * v192;
            let v194: L = v188 - v193;
            let v195: L = v161 * v170;
            let v196: L = v164 * v132;
            let v197: L = v195 + v196;
            let v198: L = v189 * v197;
            let v199: L = v186 * v178;
            let v200: L = v198 + v199;
            let v201: L = qd[5];
            let v202: L = v200 * v201;
            let v203: L = v194 - v202;
            let v204: L = v187 * v203;
            let v205: L = v172 + v201;
            let v206: L = v187 * v200;
            let v207: L = v205 * v206;
            let v208: L = L::splat(4e-05_f64);
            let v209: L = v208 * v205;
            let v210: L = v200 * v209;
            let v211: L = v207 - v210;
            let v212: L = v204 + v211;
            let v213: L = L::splat(0.00288_f64);
            let v214: L = v121 * v149;
            let v215: L = v124 * v116;
            let v216: L = v214 - v215;
            let v217: L = v33 * v170;
            let v218: L = v132 * v217;
            let v219: L = v33 * v192;
            let v220: L = v218 - v219;
            let v221: L = v216 + v220;
            let v222: L = v161 * v221;
            let v223: L = v127 * v154;
            let v224: L = v170 * v217;
            let v225: L = v223 + v224;
            let v226: L = v105 - v225;
            let v227: L = v164 * v226;
            let v228: L = v222 + v227;
            let v229: L = v189 * v228;
            let v230: L = v186 * v157;
            let v231: L = v229 + v230;
            let v232: L = v213 * v231;
            let v233: L = v212 + v232;
            let v234: L = v186 * v233;
            let v235: L = v186 * v197;
            let v236: L = v189 * v178;
            let v237: L = v235 - v236;
            let v238: L = v187 * v237;
            let v239: L = v205 * v238;
            let v240: L = v237 * v209;
            let v241: L = v239 - v240;
            let v242: L = v189 * v175;
            let v243: L = v186 * v192;
            let v244: L = v242 + v243;
            let v245: L = v237 * v201;
            let v246: L = v244 + v245;
            let v247: L = v187 * v246;
            let v248: L = v241 - v247;
            let v249: L = v186 * v228;
            let v250: L = v189 * v157;
            let v251: L = v249 - v250;
            let v252: L = v213 * v251;
            let v253: L = v248 + v252;
            let v254: L = v189 * v253;
            let v255: L = v234 - v254;
            let v256: L = v184 + v255;
            let v257: L = v161 * v256;
            let v258: L = v162 * v197;
            let v259: L = v178 * v258;
            let v260: L = v197 * v179;
            let v261: L = v259 - v260;
            let v262: L = v164 * v130;
            let v263: L = v161 * v67;
            let v264: L = v262 + v263;
            let v265: L = v197 * v173;
            let v266: L = v264 + v265;
            let v267: L = v162 * v266;
            let v268: L = v261 - v267;
            let v269: L = v200 * v238;
            let v270: L = v237 * v206;
            let v271: L = v269 - v270;
            let v272: L = v208 * v266;
            let v273: L = v271 - v272;
            let v274: L = v268 + v273;
            let v275: L = v164 * v274;
            let v276: L = v257 - v275;
            let v277: L = v159 + v276;
            let v278: L = L::splat(0.82_f64);
            let v279: L = v278 * v157;
            let v280: L = v140 * v130;
            let v281: L = v140 * v127;
            let v282: L = v132 * v281;
            let v283: L = v280 + v282;
            let v284: L = v279 + v283;
            let v285: L = L::splat(0.09_f64);
            let v286: L = v285 * v251;
            let v287: L = v213 * v237;
            let v288: L = v205 * v287;
            let v289: L = v213 * v246;
            let v290: L = v288 - v289;
            let v291: L = v286 + v290;
            let v292: L = v189 * v291;
            let v293: L = v285 * v231;
            let v294: L = v213 * v203;
            let v295: L = v213 * v200;
            let v296: L = v205 * v295;
            let v297: L = v294 + v296;
            let v298: L = v293 + v297;
            let v299: L = v186 * v298;
            let v300: L = v292 - v299;
            let v301: L = L::splat(0.34_f64);
            let v302: L = v301 * v157;
            let v303: L = v300 - v302;
            let v304: L = v284 - v303;
            let v305: L = v33 * v304;
            let v306: L = v277 + v305;
            let v307: L = v121 * v306;
            let v308: L = v122 * v192;
            let v309: L = v170 * v136;
            let v310: L = v122 * v170;
            let v311: L = v132 * v310;
            let v312: L = v309 - v311;
            let v313: L = v308 + v312;
            let v314: L = v140 * v221;
            let v315: L = v313 - v314;
            let v316: L = v172 * v258;
            let v317: L = v197 * v181;
            let v318: L = v316 - v317;
            let v319: L = v177 * v192;
            let v320: L = v318 - v319;
            let v321: L = v189 * v233;
            let v322: L = v186 * v253;
            let v323: L = v321 + v322;
            let v324: L = v320 + v323;
            let v325: L = v315 - v324;
            let v326: L = v278 * v221;
            let v327: L = v140 * v170;
            let v328: L = v132 * v327;
            let v329: L = v140 * v192;
            let v330: L = v328 - v329;
            let v331: L = v326 + v330;
            let v332: L = v301 * v228;
            let v333: L = v186 * v291;
            let v334: L = v189 * v298;
            let v335: L = v333 + v334;
            let v336: L = v332 + v335;
            let v337: L = v161 * v336;
            let v338: L = v161 * v226;
            let v339: L = v164 * v221;
            let v340: L = v338 - v339;
            let v341: L = v301 * v340;
            let v342: L = v285 * v340;
            let v343: L = v237 * v287;
            let v344: L = v200 * v295;
            let v345: L = v343 + v344;
            let v346: L = v342 - v345;
            let v347: L = v341 + v346;
            let v348: L = v164 * v347;
            let v349: L = v337 - v348;
            let v350: L = v331 + v349;
            let v351: L = v33 * v350;
            let v352: L = v325 - v351;
            let v353: L = v124 * v352;
            let v354: L = v307 + v353;
            let v355: L = v119 + v354;
            (
                v226,
                v256,
                v273,
                v274,
                v278,
                v281,
                v304,
                v306,
                v310,
                v324,
                v327,
                v336,
                v347,
                v350,
                v352,
                v355,
            )
        };
        let (v408, v486, v531, v532, v533) = {
            let v356: L = L::splat(4.8_f64);
            let v357: L = v356 * v105;
            let v358: L = v89 * v57;
            let v359: L = -L::splat(0.09744_f64);
            let v360: L = v359 * v54;
            let v361: L = v107 * v65;
            let v362: L = v360 - v361;
            let v363: L = v65 * v362;
            let v364: L = v107 * v70;
            let v365: L = v89 * v54;
            let v366: L = v364 + v365;
            let v367: L = v70 * v366;
            let v368: L = v363 - v367;
            let v369: L = v358 + v368;
            let v370: L = v357 + v369;
            let v371: L = v278 * v226;
            let v372: L = v127 * v281;
            let v373: L = v170 * v327;
            let v374: L = v372 + v373;
            let v375: L = v371 - v374;
            let v376: L = v164 * v336;
            let v377: L = v161 * v347;
            let v378: L = v376 + v377;
            let v379: L = v375 + v378;
            let v380: L = v370 + v379;
            let v381: L = v96 * v380;
            let v382: L = v355 + v381;
            let v383: L = v46 * v382;
            let v384: L = v59 * v57;
            let v385: L = v75 * v67;
            let v386: L = v384 - v385;
            let v387: L = v65 * v85;
            let v388: L = v47 * v65;
            let v389: L = v79 * v70;
            let v390: L = v388 - v389;
            let v391: L = v59 * v54;
            let v392: L = v390 + v391;
            let v393: L = v70 * v392;
            let v394: L = v387 + v393;
            let v395: L = v386 + v394;
            let v396: L = v359 * v116;
            let v397: L = v89 * v149;
            let v398: L = v396 + v397;
            let v399: L = v395 - v398;
            let v400: L = v127 * v310;
            let v401: L = v170 * v133;
            let v402: L = v400 - v401;
            let v403: L = v135 * v67;
            let v404: L = v402 - v403;
            let v405: L = v164 * v256;
            let v406: L = v161 * v274;
            let v407: L = v405 + v406;
            let v408: L = v404 + v407;
            let v409: L = v399 + v408;
            let v410: L = v124 * v350;
            let v411: L = v121 * v304;
            let v412: L = v410 - v411;
            let v413: L = v356 * v116;
            let v414: L = v359 * v67;
            let v415: L = v107 * v57;
            let v416: L = v414 + v415;
            let v417: L = v54 * v366;
            let v418: L = v89 * v65;
            let v419: L = v359 * v70;
            let v420: L = v418 + v419;
            let v421: L = v65 * v420;
            let v422: L = v417 + v421;
            let v423: L = v416 + v422;
            let v424: L = v413 + v423;
            let v425: L = v412 - v424;
            let v426: L = v98 * v425;
            let v427: L = v356 * v149;
            let v428: L = v89 * v67;
            let v429: L = v70 * v420;
            let v430: L = v54 * v362;
            let v431: L = v429 + v430;
            let v432: L = v428 - v431;
            let v433: L = v427 + v432;
            let v434: L = v121 * v350;
            let v435: L = v124 * v304;
            let v436: L = v434 + v435;
            let v437: L = v433 + v436;
            let v438: L = v96 * v437;
            let v439: L = v426 - v438;
            let v440: L = v409 + v439;
            let v441: L = v49 * v440;
            let v442: L = v383 - v441;
            let v443: L = v44 + v442;
            let v444: L = v1 * v443;
            let v445: L = v9 * v7;
            let v446: L = v24 * v11;
            let v447: L = v445 - v446;
            let v448: L = v2 * v10;
            let v449: L = v9 * v5;
            let v450: L = v448 + v449;
            let v451: L = v14 * v6;
            let v452: L = v450 + v451;
            let v453: L = v6 * v452;
            let v454: L = v10 * v21;
            let v455: L = v453 - v454;
            let v456: L = v447 + v455;
            let v457: L = v39 * v92;
            let v458: L = -L::splat(6.33012_f64);
            let v459: L = v458 * v37;
            let v460: L = v457 + v459;
            let v461: L = v456 - v460;
            let v462: L = v49 * v382;
            let v463: L = v46 * v440;
            let v464: L = v462 + v463;
            let v465: L = v461 + v464;
            let v466: L = L::splat(17.4_f64);
            let v467: L = v466 * v37;
            let v468: L = v32 * v7;
            let v469: L = v458 * v11;
            let v470: L = v468 + v469;
            let v471: L = v458 * v6;
            let v472: L = v39 * v10;
            let v473: L = v471 - v472;
            let v474: L = v10 * v473;
            let v475: L = v39 * v5;
            let v476: L = v32 * v6;
            let v477: L = v475 - v476;
            let v478: L = v5 * v477;
            let v479: L = v474 - v478;
            let v480: L = v470 + v479;
            let v481: L = v467 + v480;
            let v482: L = v481 - v425;
            let v483: L = v33 * v482;
            let v484: L = v465 - v483;
            let v485: L = v3 * v484;
            let v486: L = v444 + v485;
            let v487: L = v14 * v7;
            let v488: L = v16 * v11;
            let v489: L = v487 - v488;
            let v490: L = v10 * v28;
            let v491: L = v5 * v452;
            let v492: L = v490 - v491;
            let v493: L = v489 + v492;
            let v494: L = v458 * v41;
            let v495: L = v32 * v92;
            let v496: L = v494 + v495;
            let v497: L = v493 + v496;
            let v498: L = v79 * v57;
            let v499: L = v72 * v67;
            let v500: L = v498 - v499;
            let v501: L = v54 * v392;
            let v502: L = v65 * v77;
            let v503: L = v501 - v502;
            let v504: L = v500 + v503;
            let v505: L = v107 * v149;
            let v506: L = v359 * v105;
            let v507: L = v505 - v506;
            let v508: L = v504 + v507;
            let v509: L = v124 * v306;
            let v510: L = v121 * v352;
            let v511: L = v509 - v510;
            let v512: L = v508 + v511;
            let v513: L = v98 * v380;
            let v514: L = v512 - v513;
            let v515: L = v497 - v514;
            let v516: L = v466 * v41;
            let v517: L = v6 * v477;
            let v518: L = v32 * v10;
            let v519: L = v458 * v5;
            let v520: L = v518 - v519;
            let v521: L = v10 * v520;
            let v522: L = v517 - v521;
            let v523: L = v39 * v7;
            let v524: L = v522 - v523;
            let v525: L = v516 + v524;
            let v526: L = v49 * v437;
            let v527: L = v46 * v380;
            let v528: L = v526 + v527;
            let v529: L = v525 + v528;
            let v530: L = v33 * v529;
            let v531: L = v515 + v530;
            let v532: L = -v514;
            let v533: L = -v324;
            (v408, v486, v531, v532, v533)
        };
        [v486, v531, v532, v408, v533, v273]
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
    pub fn gravity<L: crate::lanes::Lane>(q: &[L; 6]) -> [L; 6] {
        let v0: L = L::splat(0.0_f64);
        let v1: L = L::splat(37.2347379_f64);
        let v2: L = L::splat(0.24892875_f64);
        let v3: L = L::splat(0.0282528_f64);
        let v4: L = q[4];
        let (v5, v16): (L, L) = L::sincos(v4);
        let v6: L = v3 * v5;
        let v7: L = q[3];
        let (v46, v8): (L, L) = L::sincos(v7);
        let v9: L = v6 * v8;
        let v10: L = v2 - v9;
        let v11: L = q[2];
        let (v19, v12): (L, L) = L::sincos(v11);
        let v13: L = v10 * v12;
        let v14: L = v1 + v13;
        let v15: L = -L::splat(8.7439473_f64);
        let v17: L = v3 * v16;
        let v18: L = v15 - v17;
        let v20: L = v18 * v19;
        let v21: L = v14 + v20;
        let v22: L = q[1];
        let (v32, v23): (L, L) = L::sincos(v22);
        let v24: L = v21 * v23;
        let v25: L = -L::splat(1.024164_f64);
        let v26: L = v18 * v12;
        let v27: L = v25 + v26;
        let v28: L = -L::splat(0.24892875_f64);
        let v29: L = v28 + v9;
        let v30: L = v29 * v19;
        let v31: L = v27 + v30;
        let v33: L = v31 * v32;
        let v34: L = v24 + v33;
        let v35: L = v13 + v20;
        let v36: L = v35 * v23;
        let v37: L = v26 + v30;
        let v38: L = v37 * v32;
        let v39: L = v36 + v38;
        let v40: L = v3 * v19;
        let v41: L = v40 * v23;
        let v42: L = v3 * v12;
        let v43: L = v42 * v32;
        let v44: L = v41 + v43;
        let v45: L = v44 * v5;
        let v47: L = v45 * v46;
        let v48: L = v6 * v19;
        let v49: L = v17 * v8;
        let v50: L = v49 * v12;
        let v51: L = v48 - v50;
        let v52: L = v51 * v32;
        let v53: L = v6 * v12;
        let v54: L = v49 * v19;
        let v55: L = v53 + v54;
        let v56: L = v55 * v23;
        let v57: L = v52 - v56;
        [v0, v34, v39, v47, v57, v0]
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
    /// Operation count: 519 floating-point operations, 10 trig calls.
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
            v7,
            v9,
            v10,
            v12,
            v14,
            v16,
            v18,
            v21,
            v22,
            v26,
            v29,
            v31,
            v34,
            v38,
            v42,
            v43,
            v47,
            v49,
            v56,
            v59,
            v61,
            v62,
            v64,
            v69,
            v72,
            v74,
            v76,
            v79,
            v85,
            v87,
            v90,
            v92,
            v95,
            v97,
            v100,
            v104,
            v108,
            v114,
            v117,
            v119,
            v128,
            v130,
            v139,
            v142,
            v144,
            v145,
            v147,
            v152,
            v153,
            v155,
            v157,
            v158,
            v160,
            v161,
            v165,
            v174,
            v179,
            v182,
            v184,
            v186,
            v187,
            v189,
            v191,
            v193,
        ) = {
            let v0: L = L::splat(0.35_f64);
            let v1: L = qdd[0];
            let v2: L = v0 * v1;
            let v3: L = q[1];
            let (v4, v7): (L, L) = L::sincos(v3);
            let v5: L = L::splat(1.03118515_f64);
            let v6: L = v4 * v1;
            let v8: L = qd[0];
            let v9: L = v7 * v8;
            let v10: L = qd[1];
            let v11: L = v9 * v10;
            let v12: L = v6 + v11;
            let v13: L = v5 * v12;
            let v14: L = L::splat(0.03798072_f64);
            let v15: L = v7 * v1;
            let v16: L = v4 * v8;
            let v17: L = v16 * v10;
            let v18: L = v15 - v17;
            let v19: L = v14 * v18;
            let v20: L = v13 + v19;
            let v21: L = L::splat(1.4401023_f64);
            let v22: L = qdd[1];
            let v23: L = v21 * v22;
            let v24: L = v20 + v23;
            let v25: L = v21 * v16;
            let v26: L = -L::splat(0.023751_f64);
            let v27: L = v26 * v9;
            let v28: L = v25 + v27;
            let v29: L = L::splat(2.842524056_f64);
            let v30: L = v29 * v10;
            let v31: L = v28 + v30;
            let v32: L = v9 * v31;
            let v33: L = v14 * v16;
            let v34: L = L::splat(3.727456406_f64);
            let v35: L = v34 * v9;
            let v36: L = v33 + v35;
            let v37: L = v26 * v10;
            let v38: L = v36 + v37;
            let v39: L = v10 * v38;
            let v40: L = v32 - v39;
            let v41: L = v24 + v40;
            let v42: L = L::splat(0.1044_f64);
            let v43: L = L::splat(0.4318_f64);
            let v44: L = v43 * v10;
            let v45: L = v16 * v44;
            let v46: L = v43 * v18;
            let v47: L = v45 - v46;
            let v48: L = v42 * v47;
            let v49: L = L::splat(3.9585_f64);
            let v50: L = L::splat(9.81_f64);
            let v51: L = v50 * v7;
            let v52: L = v43 * v22;
            let v53: L = v43 * v9;
            let v54: L = v16 * v53;
            let v55: L = v52 + v54;
            let v56: L = v51 + v55;
            let v57: L = v49 * v56;
            let v58: L = v48 - v57;
            let v59: L = v41 + v58;
            let v60: L = q[2];
            let (v64, v61): (L, L) = L::sincos(v60);
            let v62: L = L::splat(0.090474288_f64);
            let v63: L = v61 * v12;
            let v65: L = v64 * v18;
            let v66: L = v63 + v65;
            let v67: L = v61 * v9;
            let v68: L = v64 * v16;
            let v69: L = v67 - v68;
            let v70: L = qd[2];
            let v71: L = v69 * v70;
            let v72: L = v66 + v71;
            let v73: L = v62 * v72;
            let v74: L = -L::splat(0.001373904_f64);
            let v75: L = qdd[2];
            let v76: L = v22 + v75;
            let v77: L = v74 * v76;
            let v78: L = v73 - v77;
            let v79: L = L::splat(0.0068208_f64);
            let v80: L = v61 * v18;
            let v81: L = v64 * v12;
            let v82: L = v80 - v81;
            let v83: L = v61 * v16;
            let v84: L = v64 * v9;
            let v85: L = v83 + v84;
            let v86: L = v85 * v70;
            let v87: L = v82 - v86;
            let v88: L = v79 * v87;
            let v89: L = v78 + v88;
            let v90: L = v10 + v70;
            let v91: L = v79 * v85;
            let v92: L = L::splat(0.0047376_f64);
            let v93: L = v92 * v90;
            let v94: L = v91 - v93;
            let v95: L = L::splat(0.01543232_f64);
            let v96: L = v95 * v69;
            let v97: L = v94 + v96;
            let v98: L = v90 * v97;
            let v99: L = v74 * v85;
            let v100: L = L::splat(0.111498032_f64);
            let v101: L = v100 * v90;
            let v102: L = v99 - v101;
            let v103: L = v92 * v69;
            let v104: L = v102 + v103;
            let v105: L = v69 * v104;
            let v106: L = v98 + v105;
            let v107: L = v89 - v106;
            let v108: L = -L::splat(0.06768_f64);
            let v109: L = v61 * v56;
            let v110: L = v50 * v4;
            let v111: L = v9 * v53;
            let v112: L = v10 * v44;
            let v113: L = v111 + v112;
            let v114: L = v110 - v113;
            let v115: L = v64 * v114;
            let v116: L = v109 - v115;
            let v117: L = -L::splat(0.15005_f64);
            let v118: L = v117 * v72;
            let v119: L = L::splat(0.0203_f64);
            let v120: L = v119 * v76;
            let v121: L = v118 + v120;
            let v122: L = v119 * v69;
            let v123: L = v85 * v122;
            let v124: L = v117 * v69;
            let v125: L = v90 * v124;
            let v126: L = v123 - v125;
            let v127: L = v121 + v126;
            let v128: L = v116 + v127;
            let v129: L = v108 * v128;
            let v130: L = L::splat(0.336_f64);
            let v131: L = v119 * v87;
            let v132: L = v69 * v124;
            let v133: L = v117 * v85;
            let v134: L = v119 * v90;
            let v135: L = v133 + v134;
            let v136: L = v85 * v135;
            let v137: L = v132 + v136;
            let v138: L = v131 - v137;
            let v139: L = v138 - v47;
            let v140: L = v130 * v139;
            let v141: L = v129 - v140;
            let v142: L = v107 + v141;
            let v143: L = q[3];
            let (v147, v144): (L, L) = L::sincos(v143);
            let v145: L = L::splat(0.00209602_f64);
            let v146: L = v144 * v72;
            let v148: L = v147 * v76;
            let v149: L = v146 - v148;
            let v150: L = v147 * v85;
            let v151: L = v144 * v90;
            let v152: L = v150 + v151;
            let v153: L = qd[3];
            let v154: L = v152 * v153;
            let v155: L = v149 - v154;
            let v156: L = v145 * v155;
            let v157: L = v69 + v153;
            let v158: L = v145 * v152;
            let v159: L = v157 * v158;
            let v160: L = L::splat(0.0013_f64);
            let v161: L = v160 * v157;
            let v162: L = v152 * v161;
            let v163: L = v159 - v162;
            let v164: L = v156 + v163;
            let v165: L = L::splat(0.01558_f64);
            let v166: L = v61 * v114;
            let v167: L = v64 * v56;
            let v168: L = v166 + v167;
            let v169: L = v117 * v87;
            let v170: L = v90 * v135;
            let v171: L = v69 * v122;
            let v172: L = v170 + v171;
            let v173: L = v169 + v172;
            let v174: L = v168 - v173;
            let v175: L = v147 * v174;
            let v176: L = v144 * v139;
            let v177: L = v175 - v176;
            let v178: L = v43 * v155;
            let v179: L = v43 * v152;
            let v180: L = v157 * v179;
            let v181: L = v178 + v180;
            let v182: L = v177 + v181;
            let v183: L = v165 * v182;
            let v184: L = v164 + v183;
            let v185: L = q[4];
            let (v189, v186): (L, L) = L::sincos(v185);
            let v187: L = L::splat(0.0003_f64);
            let v188: L = v186 * v155;
            let v190: L = qdd[3];
            let v191: L = v87 + v190;
            let v192: L = v189 * v191;
            let v193: L = v188 + v192;
            (
                v2,
                v4,
                v5,
                v7,
                v9,
                v10,
                v12,
                v14,
                v16,
                v18,
                v21,
                v22,
                v26,
                v29,
                v31,
                v34,
                v38,
                v42,
                v43,
                v47,
                v49,
                v56,
                v59,
                v61,
                v62,
                v64,
                v69,
                v72,
                v74,
                v76,
                v79,
                v85,
                v87,
                v90,
                v92,
                v95,
                v97,
                v100,
                v104,
                v108,
                v114,
                v117,
                v119,
                v128,
                v130,
                v139,
                v142,
                v144,
                v145,
                v147,
                v152,
                v153,
                v155,
                v157,
                v158,
                v160,
                v161,
                v165,
                v174,
                v179,
                v182,
                v184,
                v186,
                v187,
                v189,
                v191,
                v193,
            )
        };
        let (
            v197,
            v257,
            v287,
            v306,
            v307,
            v311,
            v314,
            v337,
            v339,
            v343,
            v357,
            v360,
            v369,
            v380,
            v383,
            v385,
            v387,
        ) = {
            let v194: L = v186 * v157;
            let v195: L = v144 * v85;
            let v196: L = v147 * v90;
            let v197: L = v195 - v196;
            let v198: L = v189 * v197;
            let v199: L = v194 - v198;
            let v200: L = qd[4];
            let v201: L = v199 * v200;
            let v202: L = v193 + v201;
            let v203: L = v187 * v202;
            let v204: L = L::splat(0.0004_f64);
            let v205: L = v152 + v200;
            let v206: L = v204 * v205;
            let v207: L = v199 * v206;
            let v208: L = v187 * v199;
            let v209: L = v205 * v208;
            let v210: L = v207 - v209;
            let v211: L = v203 + v210;
            let v212: L = q[5];
            let (v216, v213): (L, L) = L::sincos(v212);
            let v214: L = L::splat(0.00024216_f64);
            let v215: L = v213 * v202;
            let v217: L = v147 * v72;
            let v218: L = v144 * v76;
            let v219: L = v217 + v218;
            let v220: L = v197 * v153;
            let v221: L = v219 + v220;
            let v222: L = qdd[4];
            let v223: L = v221 + v222;
            let v224: L = v216 * v223;
            let v225: L = v215 - v224;
            let v226: L = v186 * v197;
            let v227: L = v189 * v157;
            let v228: L = v226 + v227;
            let v229: L = v216 * v228;
            let v230: L = v213 * v205;
            let v231: L = v229 + v230;
            let v232: L = qd[5];
            let v233: L = v231 * v232;
            let v234: L = v225 - v233;
            let v235: L = v214 * v234;
            let v236: L = v199 + v232;
            let v237: L = v214 * v231;
            let v238: L = v236 * v237;
            let v239: L = L::splat(4e-05_f64);
            let v240: L = v239 * v236;
            let v241: L = v231 * v240;
            let v242: L = v238 - v241;
            let v243: L = v235 + v242;
            let v244: L = L::splat(0.00288_f64);
            let v245: L = v144 * v174;
            let v246: L = v147 * v139;
            let v247: L = v245 + v246;
            let v248: L = v43 * v197;
            let v249: L = v157 * v248;
            let v250: L = v43 * v221;
            let v251: L = v249 - v250;
            let v252: L = v247 + v251;
            let v253: L = v186 * v252;
            let v254: L = v152 * v179;
            let v255: L = v197 * v248;
            let v256: L = v254 + v255;
            let v257: L = v128 - v256;
            let v258: L = v189 * v257;
            let v259: L = v253 + v258;
            let v260: L = v216 * v259;
            let v261: L = v213 * v182;
            let v262: L = v260 + v261;
            let v263: L = v244 * v262;
            let v264: L = v243 + v263;
            let v265: L = v213 * v264;
            let v266: L = v213 * v228;
            let v267: L = v216 * v205;
            let v268: L = v266 - v267;
            let v269: L = v214 * v268;
            let v270: L = v236 * v269;
            let v271: L = v268 * v240;
            let v272: L = v270 - v271;
            let v273: L = v216 * v202;
            let v274: L = v213 * v223;
            let v275: L = v273 + v274;
            let v276: L = v268 * v232;
            let v277: L = v275 + v276;
            let v278: L = v214 * v277;
            let v279: L = v272 - v278;
            let v280: L = v213 * v259;
            let v281: L = v216 * v182;
            let v282: L = v280 - v281;
            let v283: L = v244 * v282;
            let v284: L = v279 + v283;
            let v285: L = v216 * v284;
            let v286: L = v265 - v285;
            let v287: L = v211 + v286;
            let v288: L = v186 * v287;
            let v289: L = v186 * v191;
            let v290: L = v189 * v155;
            let v291: L = v289 - v290;
            let v292: L = v228 * v200;
            let v293: L = v291 - v292;
            let v294: L = v187 * v293;
            let v295: L = v187 * v228;
            let v296: L = v205 * v295;
            let v297: L = v228 * v206;
            let v298: L = v296 - v297;
            let v299: L = v294 + v298;
            let v300: L = qdd[5];
            let v301: L = v293 + v300;
            let v302: L = v239 * v301;
            let v303: L = v231 * v269;
            let v304: L = v268 * v237;
            let v305: L = v303 - v304;
            let v306: L = v302 + v305;
            let v307: L = v299 + v306;
            let v308: L = v189 * v307;
            let v309: L = v288 - v308;
            let v310: L = v184 + v309;
            let v311: L = L::splat(0.82_f64);
            let v312: L = v311 * v182;
            let v313: L = v165 * v155;
            let v314: L = v165 * v152;
            let v315: L = v157 * v314;
            let v316: L = v313 + v315;
            let v317: L = v312 + v316;
            let v318: L = L::splat(0.09_f64);
            let v319: L = v318 * v282;
            let v320: L = v244 * v268;
            let v321: L = v236 * v320;
            let v322: L = v244 * v277;
            let v323: L = v321 - v322;
            let v324: L = v319 + v323;
            let v325: L = v216 * v324;
            let v326: L = v318 * v262;
            let v327: L = v244 * v234;
            let v328: L = v244 * v231;
            let v329: L = v236 * v328;
            let v330: L = v327 + v329;
            let v331: L = v326 + v330;
            let v332: L = v213 * v331;
            let v333: L = v325 - v332;
            let v334: L = L::splat(0.34_f64);
            let v335: L = v334 * v182;
            let v336: L = v333 - v335;
            let v337: L = v317 - v336;
            let v338: L = v43 * v337;
            let v339: L = v310 + v338;
            let v340: L = v144 * v339;
            let v341: L = v145 * v221;
            let v342: L = v197 * v161;
            let v343: L = v145 * v197;
            let v344: L = v157 * v343;
            let v345: L = v342 - v344;
            let v346: L = v341 + v345;
            let v347: L = v165 * v252;
            let v348: L = v346 - v347;
            let v349: L = v199 * v295;
            let v350: L = v228 * v208;
            let v351: L = v349 - v350;
            let v352: L = v204 * v223;
            let v353: L = v351 - v352;
            let v354: L = v216 * v264;
            let v355: L = v213 * v284;
            let v356: L = v354 + v355;
            let v357: L = v353 + v356;
            let v358: L = v348 - v357;
            let v359: L = v311 * v252;
            let v360: L = v165 * v197;
            let v361: L = v157 * v360;
            let v362: L = v165 * v221;
            let v363: L = v361 - v362;
            let v364: L = v359 + v363;
            let v365: L = v334 * v259;
            let v366: L = v213 * v324;
            let v367: L = v216 * v331;
            let v368: L = v366 + v367;
            let v369: L = v365 + v368;
            let v370: L = v186 * v369;
            let v371: L = v186 * v257;
            let v372: L = v189 * v252;
            let v373: L = v371 - v372;
            let v374: L = v334 * v373;
            let v375: L = v318 * v373;
            let v376: L = v268 * v320;
            let v377: L = v231 * v328;
            let v378: L = v376 + v377;
            let v379: L = v375 - v378;
            let v380: L = v374 + v379;
            let v381: L = v189 * v380;
            let v382: L = v370 - v381;
            let v383: L = v364 + v382;
            let v384: L = v43 * v383;
            let v385: L = v358 - v384;
            let v386: L = v147 * v385;
            let v387: L = v340 + v386;
            (
                v197,
                v257,
                v287,
                v306,
                v307,
                v311,
                v314,
                v337,
                v339,
                v343,
                v357,
                v360,
                v369,
                v380,
                v383,
                v385,
                v387,
            )
        };
        let (v445, v528, v579, v580, v581) = {
            let v388: L = v142 + v387;
            let v389: L = L::splat(4.8_f64);
            let v390: L = v389 * v128;
            let v391: L = v108 * v72;
            let v392: L = -L::splat(0.09744_f64);
            let v393: L = v392 * v76;
            let v394: L = v391 + v393;
            let v395: L = v392 * v69;
            let v396: L = v130 * v85;
            let v397: L = v395 - v396;
            let v398: L = v85 * v397;
            let v399: L = v130 * v90;
            let v400: L = v108 * v69;
            let v401: L = v399 + v400;
            let v402: L = v90 * v401;
            let v403: L = v398 - v402;
            let v404: L = v394 + v403;
            let v405: L = v390 + v404;
            let v406: L = v311 * v257;
            let v407: L = v152 * v314;
            let v408: L = v197 * v360;
            let v409: L = v407 + v408;
            let v410: L = v406 - v409;
            let v411: L = v189 * v369;
            let v412: L = v186 * v380;
            let v413: L = v411 + v412;
            let v414: L = v410 + v413;
            let v415: L = v405 + v414;
            let v416: L = v117 * v415;
            let v417: L = v388 + v416;
            let v418: L = v61 * v417;
            let v419: L = v79 * v72;
            let v420: L = v92 * v76;
            let v421: L = v419 - v420;
            let v422: L = v95 * v87;
            let v423: L = v421 + v422;
            let v424: L = v85 * v104;
            let v425: L = v62 * v85;
            let v426: L = v74 * v90;
            let v427: L = v425 - v426;
            let v428: L = v79 * v69;
            let v429: L = v427 + v428;
            let v430: L = v90 * v429;
            let v431: L = v424 + v430;
            let v432: L = v423 + v431;
            let v433: L = v392 * v139;
            let v434: L = v108 * v174;
            let v435: L = v433 - v434;
            let v436: L = v432 + v435;
            let v437: L = v160 * v191;
            let v438: L = v152 * v343;
            let v439: L = v197 * v158;
            let v440: L = v438 - v439;
            let v441: L = v437 + v440;
            let v442: L = v189 * v287;
            let v443: L = v186 * v307;
            let v444: L = v442 + v443;
            let v445: L = v441 + v444;
            let v446: L = v436 + v445;
            let v447: L = v389 * v139;
            let v448: L = v392 * v87;
            let v449: L = v130 * v72;
            let v450: L = v448 - v449;
            let v451: L = v69 * v401;
            let v452: L = v108 * v85;
            let v453: L = v392 * v90;
            let v454: L = v452 + v453;
            let v455: L = v85 * v454;
            let v456: L = v451 + v455;
            let v457: L = v450 - v456;
            let v458: L = v447 + v457;
            let v459: L = v147 * v383;
            let v460: L = v144 * v337;
            let v461: L = v459 - v460;
            let v462: L = v458 + v461;
            let v463: L = v119 * v462;
            let v464: L = v389 * v174;
            let v465: L = v130 * v76;
            let v466: L = v108 * v87;
            let v467: L = v465 + v466;
            let v468: L = v90 * v454;
            let v469: L = v69 * v397;
            let v470: L = v468 + v469;
            let v471: L = v467 + v470;
            let v472: L = v464 - v471;
            let v473: L = v144 * v383;
            let v474: L = v147 * v337;
            let v475: L = v473 + v474;
            let v476: L = v472 + v475;
            let v477: L = v117 * v476;
            let v478: L = v463 - v477;
            let v479: L = v446 + v478;
            let v480: L = v64 * v479;
            let v481: L = v418 - v480;
            let v482: L = v59 + v481;
            let v483: L = v4 * v482;
            let v484: L = v14 * v12;
            let v485: L = v34 * v18;
            let v486: L = v484 + v485;
            let v487: L = v26 * v22;
            let v488: L = v486 + v487;
            let v489: L = v5 * v16;
            let v490: L = v14 * v9;
            let v491: L = v489 + v490;
            let v492: L = v21 * v10;
            let v493: L = v491 + v492;
            let v494: L = v10 * v493;
            let v495: L = v16 * v31;
            let v496: L = v494 - v495;
            let v497: L = v488 + v496;
            let v498: L = v49 * v114;
            let v499: L = -L::splat(6.33012_f64);
            let v500: L = v499 * v47;
            let v501: L = v498 - v500;
            let v502: L = v497 + v501;
            let v503: L = v64 * v417;
            let v504: L = v61 * v479;
            let v505: L = v503 + v504;
            let v506: L = v502 + v505;
            let v507: L = L::splat(17.4_f64);
            let v508: L = v507 * v47;
            let v509: L = v42 * v12;
            let v510: L = v499 * v18;
            let v511: L = v509 - v510;
            let v512: L = v499 * v10;
            let v513: L = v49 * v16;
            let v514: L = v512 - v513;
            let v515: L = v16 * v514;
            let v516: L = v49 * v9;
            let v517: L = v42 * v10;
            let v518: L = v516 - v517;
            let v519: L = v9 * v518;
            let v520: L = v515 - v519;
            let v521: L = v511 + v520;
            let v522: L = v508 + v521;
            let v523: L = v522 - v462;
            let v524: L = v43 * v523;
            let v525: L = v506 - v524;
            let v526: L = v7 * v525;
            let v527: L = v483 + v526;
            let v528: L = v2 + v527;
            let v529: L = v21 * v12;
            let v530: L = v26 * v18;
            let v531: L = v529 + v530;
            let v532: L = v29 * v22;
            let v533: L = v531 + v532;
            let v534: L = v16 * v38;
            let v535: L = v9 * v493;
            let v536: L = v534 - v535;
            let v537: L = v533 + v536;
            let v538: L = v499 * v56;
            let v539: L = v42 * v114;
            let v540: L = v538 - v539;
            let v541: L = v537 + v540;
            let v542: L = v74 * v72;
            let v543: L = v100 * v76;
            let v544: L = v542 - v543;
            let v545: L = v92 * v87;
            let v546: L = v544 + v545;
            let v547: L = v69 * v429;
            let v548: L = v85 * v97;
            let v549: L = v547 - v548;
            let v550: L = v546 + v549;
            let v551: L = v130 * v174;
            let v552: L = v392 * v128;
            let v553: L = v551 - v552;
            let v554: L = v550 + v553;
            let v555: L = v147 * v339;
            let v556: L = v144 * v385;
            let v557: L = v555 - v556;
            let v558: L = v554 + v557;
            let v559: L = v119 * v415;
            let v560: L = v558 - v559;
            let v561: L = v541 - v560;
            let v562: L = v507 * v56;
            let v563: L = v499 * v22;
            let v564: L = v49 * v12;
            let v565: L = v563 - v564;
            let v566: L = v10 * v518;
            let v567: L = v42 * v16;
            let v568: L = v499 * v9;
            let v569: L = v567 - v568;
            let v570: L = v16 * v569;
            let v571: L = v566 - v570;
            let v572: L = v565 + v571;
            let v573: L = v562 + v572;
            let v574: L = v64 * v476;
            let v575: L = v61 * v415;
            let v576: L = v574 + v575;
            let v577: L = v573 + v576;
            let v578: L = v43 * v577;
            let v579: L = v561 + v578;
            let v580: L = -v560;
            let v581: L = -v357;
            (v445, v528, v579, v580, v581)
        };
        [v528, v579, v580, v445, v581, v306]
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
    /// Operation count: 867 floating-point operations, 10 trig calls.
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
            v11,
            v12,
            v15,
            v17,
            v22,
            v25,
            v29,
            v33,
            v34,
            v38,
            v40,
            v45,
            v48,
            v50,
            v51,
            v53,
            v58,
            v61,
            v63,
            v69,
            v71,
            v74,
            v76,
            v79,
            v81,
            v83,
            v89,
            v93,
            v99,
            v102,
            v104,
            v111,
            v113,
            v122,
            v125,
            v127,
            v128,
            v130,
            v133,
            v134,
            v136,
            v138,
            v139,
            v141,
            v142,
            v146,
            v155,
            v160,
            v163,
            v165,
            v167,
            v168,
            v170,
            v176,
            v178,
            v179,
            v181,
            v183,
            v184,
            v185,
            v187,
            v190,
            v192,
            v193,
            v194,
            v195,
        ) = {
            let v0: L = tau[0];
            let v1: L = q[1];
            let (v2, v4): (L, L) = L::sincos(v1);
            let v3: L = L::splat(1.03118515_f64);
            let v5: L = qd[0];
            let v6: L = v4 * v5;
            let v7: L = qd[1];
            let v8: L = v6 * v7;
            let v9: L = v3 * v8;
            let v10: L = L::splat(0.03798072_f64);
            let v11: L = v2 * v5;
            let v12: L = v11 * v7;
            let v13: L = v10 * v12;
            let v14: L = v9 - v13;
            let v15: L = L::splat(1.4401023_f64);
            let v16: L = v15 * v11;
            let v17: L = -L::splat(0.023751_f64);
            let v18: L = v17 * v6;
            let v19: L = v16 + v18;
            let v20: L = L::splat(2.842524056_f64);
            let v21: L = v20 * v7;
            let v22: L = v19 + v21;
            let v23: L = v6 * v22;
            let v24: L = v10 * v11;
            let v25: L = L::splat(3.727456406_f64);
            let v26: L = v25 * v6;
            let v27: L = v24 + v26;
            let v28: L = v17 * v7;
            let v29: L = v27 + v28;
            let v30: L = v7 * v29;
            let v31: L = v23 - v30;
            let v32: L = v14 + v31;
            let v33: L = L::splat(0.1044_f64);
            let v34: L = L::splat(0.4318_f64);
            let v35: L = v34 * v12;
            let v36: L = v34 * v7;
            let v37: L = v11 * v36;
            let v38: L = v35 + v37;
            let v39: L = v33 * v38;
            let v40: L = L::splat(3.9585_f64);
            let v41: L = L::splat(9.81_f64);
            let v42: L = v41 * v4;
            let v43: L = v34 * v6;
            let v44: L = v11 * v43;
            let v45: L = v42 + v44;
            let v46: L = v40 * v45;
            let v47: L = v39 - v46;
            let v48: L = v32 + v47;
            let v49: L = q[2];
            let (v53, v50): (L, L) = L::sincos(v49);
            let v51: L = L::splat(0.090474288_f64);
            let v52: L = v50 * v8;
            let v54: L = v53 * v12;
            let v55: L = v52 - v54;
            let v56: L = v50 * v6;
            let v57: L = v53 * v11;
            let v58: L = v56 - v57;
            let v59: L = qd[2];
            let v60: L = v58 * v59;
            let v61: L = v55 + v60;
            let v62: L = v51 * v61;
            let v63: L = L::splat(0.0068208_f64);
            let v64: L = v53 * v8;
            let v65: L = v50 * v12;
            let v66: L = v64 + v65;
            let v67: L = v50 * v11;
            let v68: L = v53 * v6;
            let v69: L = v67 + v68;
            let v70: L = v69 * v59;
            let v71: L = v66 + v70;
            let v72: L = v63 * v71;
            let v73: L = v62 - v72;
            let v74: L = v7 + v59;
            let v75: L = v63 * v69;
            let v76: L = L::splat(0.0047376_f64);
            let v77: L = v76 * v74;
            let v78: L = v75 - v77;
            let v79: L = L::splat(0.01543232_f64);
            let v80: L = v79 * v58;
            let v81: L = v78 + v80;
            let v82: L = v74 * v81;
            let v83: L = -L::splat(0.001373904_f64);
            let v84: L = v83 * v69;
            let v85: L = L::splat(0.111498032_f64);
            let v86: L = v85 * v74;
            let v87: L = v84 - v86;
            let v88: L = v76 * v58;
            let v89: L = v87 + v88;
            let v90: L = v58 * v89;
            let v91: L = v82 + v90;
            let v92: L = v73 - v91;
            let v93: L = -L::splat(0.06768_f64);
            let v94: L = v50 * v45;
            let v95: L = v41 * v2;
            let v96: L = v6 * v43;
            let v97: L = v7 * v36;
            let v98: L = v96 + v97;
            let v99: L = v95 - v98;
            let v100: L = v53 * v99;
            let v101: L = v94 - v100;
            let v102: L = -L::splat(0.15005_f64);
            let v103: L = v102 * v61;
            let v104: L = L::splat(0.0203_f64);
            let v105: L = v104 * v58;
            let v106: L = v69 * v105;
            let v107: L = v102 * v58;
            let v108: L = v74 * v107;
            let v109: L = v106 - v108;
            let v110: L = v103 + v109;
            let v111: L = v101 + v110;
            let v112: L = v93 * v111;
            let v113: L = L::splat(0.336_f64);
            let v114: L = v104 * v71;
            let v115: L = v58 * v107;
            let v116: L = v102 * v69;
            let v117: L = v104 * v74;
            let v118: L = v116 + v117;
            let v119: L = v69 * v118;
            let v120: L = v115 + v119;
            let v121: L = v114 + v120;
            let v122: L = v38 + v121;
            let v123: L = v113 * v122;
            let v124: L = v112 + v123;
            let v125: L = v92 + v124;
            let v126: L = q[3];
            let (v130, v127): (L, L) = L::sincos(v126);
            let v128: L = L::splat(0.00209602_f64);
            let v129: L = v127 * v61;
            let v131: L = v130 * v69;
            let v132: L = v127 * v74;
            let v133: L = v131 + v132;
            let v134: L = qd[3];
            let v135: L = v133 * v134;
            let v136: L = v129 - v135;
            let v137: L = v128 * v136;
            let v138: L = v58 + v134;
            let v139: L = v128 * v133;
            let v140: L = v138 * v139;
            let v141: L = L::splat(0.0013_f64);
            let v142: L = v141 * v138;
            let v143: L = v133 * v142;
            let v144: L = v140 - v143;
            let v145: L = v137 + v144;
            let v146: L = L::splat(0.01558_f64);
            let v147: L = v50 * v99;
            let v148: L = v53 * v45;
            let v149: L = v147 + v148;
            let v150: L = v102 * v71;
            let v151: L = v74 * v118;
            let v152: L = v58 * v105;
            let v153: L = v151 + v152;
            let v154: L = v150 - v153;
            let v155: L = v149 + v154;
            let v156: L = v130 * v155;
            let v157: L = v127 * v122;
            let v158: L = v156 + v157;
            let v159: L = v34 * v136;
            let v160: L = v34 * v133;
            let v161: L = v138 * v160;
            let v162: L = v159 + v161;
            let v163: L = v158 + v162;
            let v164: L = v146 * v163;
            let v165: L = v145 + v164;
            let v166: L = q[4];
            let (v170, v167): (L, L) = L::sincos(v166);
            let v168: L = L::splat(0.0003_f64);
            let v169: L = v167 * v136;
            let v171: L = v170 * v71;
            let v172: L = v169 - v171;
            let v173: L = v167 * v138;
            let v174: L = v127 * v69;
            let v175: L = v130 * v74;
            let v176: L = v174 - v175;
            let v177: L = v170 * v176;
            let v178: L = v173 - v177;
            let v179: L = qd[4];
            let v180: L = v178 * v179;
            let v181: L = v172 + v180;
            let v182: L = v168 * v181;
            let v183: L = L::splat(0.0004_f64);
            let v184: L = v133 + v179;
            let v185: L = v183 * v184;
            let v186: L = v178 * v185;
            let v187: L = v168 * v178;
            let v188: L = v184 * v187;
            let v189: L = v186 - v188;
            let v190: L = v182 + v189;
            let v191: L = q[5];
            let (v195, v192): (L, L) = L::sincos(v191);
            let v193: L = L::splat(0.00024216_f64);
            let v194: L = v192 * v181;
            (
                v0,
                v2,
                v3,
                v4,
                v6,
                v7,
                v8,
                v10,
                v11,
                v12,
                v15,
                v17,
                v22,
                v25,
                v29,
                v33,
                v34,
                v38,
                v40,
                v45,
                v48,
                v50,
                v51,
                v53,
                v58,
                v61,
                v63,
                v69,
                v71,
                v74,
                v76,
                v79,
                v81,
                v83,
                v89,
                v93,
                v99,
                v102,
                v104,
                v111,
                v113,
                v122,
                v125,
                v127,
                v128,
                v130,
                v133,
                v134,
                v136,
                v138,
                v139,
                v141,
                v142,
                v146,
                v155,
                v160,
                v163,
                v165,
                v167,
                v168,
                v170,
                v176,
                v178,
                v179,
                v181,
                v183,
                v184,
                v185,
                v187,
                v190,
                v192,
                v193,
                v194,
                v195,
            )
        };
        let (
            v214,
            v262,
            v279,
            v280,
            v310,
            v312,
            v316,
            v330,
            v356,
            v358,
            v362,
            v365,
            v368,
            v372,
            v386,
            v388,
            v389,
        ) = {
            let v196: L = v130 * v61;
            let v197: L = v176 * v134;
            let v198: L = v196 + v197;
            let v199: L = v195 * v198;
            let v200: L = v194 - v199;
            let v201: L = v167 * v176;
            let v202: L = v170 * v138;
            let v203: L = v201 + v202;
            let v204: L = v195 * v203;
            let v205: L = v192 * v184;
            let v206: L = v204 + v205;
            let v207: L = qd[5];
            let v208: L = v206 * v207;
            let v209: L = v200 - v208;
            let v210: L = v193 * v209;
            let v211: L = v178 + v207;
            let v212: L = v193 * v206;
            let v213: L = v211 * v212;
            let v214: L = L::splat(4e-05_f64);
            let v215: L = v214 * v211;
            let v216: L = v206 * v215;
            let v217: L = v213 - v216;
            let v218: L = v210 + v217;
            let v219: L = L::splat(0.00288_f64);
            let v220: L = v127 * v155;
            let v221: L = v130 * v122;
            let v222: L = v220 - v221;
            let v223: L = v34 * v176;
            let v224: L = v138 * v223;
            let v225: L = v34 * v198;
            let v226: L = v224 - v225;
            let v227: L = v222 + v226;
            let v228: L = v167 * v227;
            let v229: L = v133 * v160;
            let v230: L = v176 * v223;
            let v231: L = v229 + v230;
            let v232: L = v111 - v231;
            let v233: L = v170 * v232;
            let v234: L = v228 + v233;
            let v235: L = v195 * v234;
            let v236: L = v192 * v163;
            let v237: L = v235 + v236;
            let v238: L = v219 * v237;
            let v239: L = v218 + v238;
            let v240: L = v192 * v239;
            let v241: L = v192 * v203;
            let v242: L = v195 * v184;
            let v243: L = v241 - v242;
            let v244: L = v193 * v243;
            let v245: L = v211 * v244;
            let v246: L = v243 * v215;
            let v247: L = v245 - v246;
            let v248: L = v195 * v181;
            let v249: L = v192 * v198;
            let v250: L = v248 + v249;
            let v251: L = v243 * v207;
            let v252: L = v250 + v251;
            let v253: L = v193 * v252;
            let v254: L = v247 - v253;
            let v255: L = v192 * v234;
            let v256: L = v195 * v163;
            let v257: L = v255 - v256;
            let v258: L = v219 * v257;
            let v259: L = v254 + v258;
            let v260: L = v195 * v259;
            let v261: L = v240 - v260;
            let v262: L = v190 + v261;
            let v263: L = v167 * v262;
            let v264: L = v168 * v203;
            let v265: L = v184 * v264;
            let v266: L = v203 * v185;
            let v267: L = v265 - v266;
            let v268: L = v170 * v136;
            let v269: L = v167 * v71;
            let v270: L = v268 + v269;
            let v271: L = v203 * v179;
            let v272: L = v270 + v271;
            let v273: L = v168 * v272;
            let v274: L = v267 - v273;
            let v275: L = v206 * v244;
            let v276: L = v243 * v212;
            let v277: L = v275 - v276;
            let v278: L = v214 * v272;
            let v279: L = v277 - v278;
            let v280: L = v274 + v279;
            let v281: L = v170 * v280;
            let v282: L = v263 - v281;
            let v283: L = v165 + v282;
            let v284: L = L::splat(0.82_f64);
            let v285: L = v284 * v163;
            let v286: L = v146 * v136;
            let v287: L = v146 * v133;
            let v288: L = v138 * v287;
            let v289: L = v286 + v288;
            let v290: L = v285 + v289;
            let v291: L = L::splat(0.09_f64);
            let v292: L = v291 * v257;
            let v293: L = v219 * v243;
            let v294: L = v211 * v293;
            let v295: L = v219 * v252;
            let v296: L = v294 - v295;
            let v297: L = v292 + v296;
            let v298: L = v195 * v297;
            let v299: L = v291 * v237;
            let v300: L = v219 * v209;
            let v301: L = v219 * v206;
            let v302: L = v211 * v301;
            let v303: L = v300 + v302;
            let v304: L = v299 + v303;
            let v305: L = v192 * v304;
            let v306: L = v298 - v305;
            let v307: L = L::splat(0.34_f64);
            let v308: L = v307 * v163;
            let v309: L = v306 - v308;
            let v310: L = v290 - v309;
            let v311: L = v34 * v310;
            let v312: L = v283 + v311;
            let v313: L = v127 * v312;
            let v314: L = v128 * v198;
            let v315: L = v176 * v142;
            let v316: L = v128 * v176;
            let v317: L = v138 * v316;
            let v318: L = v315 - v317;
            let v319: L = v314 + v318;
            let v320: L = v146 * v227;
            let v321: L = v319 - v320;
            let v322: L = v178 * v264;
            let v323: L = v203 * v187;
            let v324: L = v322 - v323;
            let v325: L = v183 * v198;
            let v326: L = v324 - v325;
            let v327: L = v195 * v239;
            let v328: L = v192 * v259;
            let v329: L = v327 + v328;
            let v330: L = v326 + v329;
            let v331: L = v321 - v330;
            let v332: L = v284 * v227;
            let v333: L = v146 * v176;
            let v334: L = v138 * v333;
            let v335: L = v146 * v198;
            let v336: L = v334 - v335;
            let v337: L = v332 + v336;
            let v338: L = v307 * v234;
            let v339: L = v192 * v297;
            let v340: L = v195 * v304;
            let v341: L = v339 + v340;
            let v342: L = v338 + v341;
            let v343: L = v167 * v342;
            let v344: L = v167 * v232;
            let v345: L = v170 * v227;
            let v346: L = v344 - v345;
            let v347: L = v307 * v346;
            let v348: L = v291 * v346;
            let v349: L = v243 * v293;
            let v350: L = v206 * v301;
            let v351: L = v349 + v350;
            let v352: L = v348 - v351;
            let v353: L = v347 + v352;
            let v354: L = v170 * v353;
            let v355: L = v343 - v354;
            let v356: L = v337 + v355;
            let v357: L = v34 * v356;
            let v358: L = v331 - v357;
            let v359: L = v130 * v358;
            let v360: L = v313 + v359;
            let v361: L = v125 + v360;
            let v362: L = L::splat(4.8_f64);
            let v363: L = v362 * v111;
            let v364: L = v93 * v61;
            let v365: L = -L::splat(0.09744_f64);
            let v366: L = v365 * v58;
            let v367: L = v113 * v69;
            let v368: L = v366 - v367;
            let v369: L = v69 * v368;
            let v370: L = v113 * v74;
            let v371: L = v93 * v58;
            let v372: L = v370 + v371;
            let v373: L = v74 * v372;
            let v374: L = v369 - v373;
            let v375: L = v364 + v374;
            let v376: L = v363 + v375;
            let v377: L = v284 * v232;
            let v378: L = v133 * v287;
            let v379: L = v176 * v333;
            let v380: L = v378 + v379;
            let v381: L = v377 - v380;
            let v382: L = v170 * v342;
            let v383: L = v167 * v353;
            let v384: L = v382 + v383;
            let v385: L = v381 + v384;
            let v386: L = v376 + v385;
            let v387: L = v102 * v386;
            let v388: L = v361 + v387;
            let v389: L = v50 * v388;
            (
                v214,
                v262,
                v279,
                v280,
                v310,
                v312,
                v316,
                v330,
                v356,
                v358,
                v362,
                v365,
                v368,
                v372,
                v386,
                v388,
                v389,
            )
        };
        let (
            v398,
            v414,
            v443,
            v458,
            v464,
            v472,
            v483,
            v494,
            v495,
            v497,
            v506,
            v507,
            v509,
            v512,
            v514,
            v516,
            v526,
            v532,
            v533,
            v534,
            v535,
            v538,
            v539,
            v541,
            v548,
            v549,
            v551,
            v553,
            v555,
            v556,
            v557,
            v558,
            v576,
            v577,
            v583,
            v584,
        ) = {
            let v390: L = v63 * v61;
            let v391: L = v79 * v71;
            let v392: L = v390 - v391;
            let v393: L = v69 * v89;
            let v394: L = v51 * v69;
            let v395: L = v83 * v74;
            let v396: L = v394 - v395;
            let v397: L = v63 * v58;
            let v398: L = v396 + v397;
            let v399: L = v74 * v398;
            let v400: L = v393 + v399;
            let v401: L = v392 + v400;
            let v402: L = v365 * v122;
            let v403: L = v93 * v155;
            let v404: L = v402 + v403;
            let v405: L = v401 - v404;
            let v406: L = v133 * v316;
            let v407: L = v176 * v139;
            let v408: L = v406 - v407;
            let v409: L = v141 * v71;
            let v410: L = v408 - v409;
            let v411: L = v170 * v262;
            let v412: L = v167 * v280;
            let v413: L = v411 + v412;
            let v414: L = v410 + v413;
            let v415: L = v405 + v414;
            let v416: L = v130 * v356;
            let v417: L = v127 * v310;
            let v418: L = v416 - v417;
            let v419: L = v362 * v122;
            let v420: L = v365 * v71;
            let v421: L = v113 * v61;
            let v422: L = v420 + v421;
            let v423: L = v58 * v372;
            let v424: L = v93 * v69;
            let v425: L = v365 * v74;
            let v426: L = v424 + v425;
            let v427: L = v69 * v426;
            let v428: L = v423 + v427;
            let v429: L = v422 + v428;
            let v430: L = v419 + v429;
            let v431: L = v418 - v430;
            let v432: L = v104 * v431;
            let v433: L = v362 * v155;
            let v434: L = v93 * v71;
            let v435: L = v74 * v426;
            let v436: L = v58 * v368;
            let v437: L = v435 + v436;
            let v438: L = v434 - v437;
            let v439: L = v433 + v438;
            let v440: L = v127 * v356;
            let v441: L = v130 * v310;
            let v442: L = v440 + v441;
            let v443: L = v439 + v442;
            let v444: L = v102 * v443;
            let v445: L = v432 - v444;
            let v446: L = v415 + v445;
            let v447: L = v53 * v446;
            let v448: L = v389 - v447;
            let v449: L = v48 + v448;
            let v450: L = v2 * v449;
            let v451: L = v10 * v8;
            let v452: L = v25 * v12;
            let v453: L = v451 - v452;
            let v454: L = v3 * v11;
            let v455: L = v10 * v6;
            let v456: L = v454 + v455;
            let v457: L = v15 * v7;
            let v458: L = v456 + v457;
            let v459: L = v7 * v458;
            let v460: L = v11 * v22;
            let v461: L = v459 - v460;
            let v462: L = v453 + v461;
            let v463: L = v40 * v99;
            let v464: L = -L::splat(6.33012_f64);
            let v465: L = v464 * v38;
            let v466: L = v463 - v465;
            let v467: L = v462 + v466;
            let v468: L = v53 * v388;
            let v469: L = v50 * v446;
            let v470: L = v468 + v469;
            let v471: L = v467 + v470;
            let v472: L = L::splat(17.4_f64);
            let v473: L = v472 * v38;
            let v474: L = v33 * v8;
            let v475: L = v464 * v12;
            let v476: L = v474 + v475;
            let v477: L = v464 * v7;
            let v478: L = v40 * v11;
            let v479: L = v477 - v478;
            let v480: L = v11 * v479;
            let v481: L = v40 * v6;
            let v482: L = v33 * v7;
            let v483: L = v481 - v482;
            let v484: L = v6 * v483;
            let v485: L = v480 - v484;
            let v486: L = v476 + v485;
            let v487: L = v473 + v486;
            let v488: L = v487 - v431;
            let v489: L = v34 * v488;
            let v490: L = v471 - v489;
            let v491: L = v4 * v490;
            let v492: L = v450 + v491;
            let v493: L = v0 - v492;
            let v494: L = L::splat(24999.999999999996_f64);
            let v495: L = v214 * v167;
            let v496: L = v495 * v50;
            let v497: L = v214 * v170;
            let v498: L = v497 * v127;
            let v499: L = v498 * v53;
            let v500: L = v496 - v499;
            let v501: L = v500 * v4;
            let v502: L = v498 * v50;
            let v503: L = v495 * v53;
            let v504: L = v502 + v503;
            let v505: L = v504 * v2;
            let v506: L = v501 - v505;
            let v507: L = v494 * v506;
            let v508: L = tau[5];
            let v509: L = v508 - v279;
            let v510: L = v507 * v509;
            let v511: L = v493 - v510;
            let v512: L = L::splat(1557.24430048586_f64);
            let v513: L = L::splat(0.000432144_f64);
            let v514: L = v513 * v170;
            let v515: L = v514 * v53;
            let v516: L = v513 * v167;
            let v517: L = v516 * v127;
            let v518: L = v517 * v50;
            let v519: L = v515 - v518;
            let v520: L = v519 * v4;
            let v521: L = v514 * v50;
            let v522: L = v517 * v53;
            let v523: L = v521 + v522;
            let v524: L = v523 * v2;
            let v525: L = v520 + v524;
            let v526: L = L::splat(0.00064216_f64);
            let v527: L = v526 * v53;
            let v528: L = v527 * v4;
            let v529: L = v526 * v50;
            let v530: L = v529 * v2;
            let v531: L = v528 + v530;
            let v532: L = L::splat(0.001243584_f64);
            let v533: L = v532 * v50;
            let v534: L = L::splat(5.8464e-05_f64);
            let v535: L = v534 * v53;
            let v536: L = v533 + v535;
            let v537: L = v536 * v2;
            let v538: L = -L::splat(0.001243584_f64);
            let v539: L = v534 * v50;
            let v540: L = v538 - v539;
            let v541: L = v532 * v53;
            let v542: L = v540 + v541;
            let v543: L = v542 * v4;
            let v544: L = v537 + v543;
            let v545: L = v544 * v167;
            let v546: L = v531 + v545;
            let v547: L = v546 * v130;
            let v548: L = v525 + v547;
            let v549: L = v512 * v548;
            let v550: L = tau[4];
            let v551: L = v550 + v330;
            let v552: L = v549 * v551;
            let v553: L = v511 - v552;
            let v554: L = L::splat(0.00184216_f64);
            let v555: L = L::splat(0.00020216_f64);
            let v556: L = v555 * v167;
            let v557: L = v556 * v167;
            let v558: L = v554 - v557;
            let v559: L = v558 * v50;
            let v560: L = v559 * v4;
            let v561: L = -L::splat(0.00184216_f64);
            let v562: L = v561 + v557;
            let v563: L = v562 * v53;
            let v564: L = v563 * v2;
            let v565: L = v560 + v564;
            let v566: L = v513 * v50;
            let v567: L = v566 * v4;
            let v568: L = v513 * v53;
            let v569: L = v568 * v2;
            let v570: L = v567 - v569;
            let v571: L = v570 * v130;
            let v572: L = v532 + v556;
            let v573: L = v572 * v50;
            let v574: L = v535 + v573;
            let v575: L = v574 * v2;
            let v576: L = v572 * v53;
            let v577: L = v540 + v576;
            let v578: L = v577 * v4;
            let v579: L = v575 + v578;
            let v580: L = v579 * v127;
            let v581: L = v571 + v580;
            let v582: L = v581 * v170;
            let v583: L = v565 + v582;
            let v584: L = v494 * v495;
            (
                v398,
                v414,
                v443,
                v458,
                v464,
                v472,
                v483,
                v494,
                v495,
                v497,
                v506,
                v507,
                v509,
                v512,
                v514,
                v516,
                v526,
                v532,
                v533,
                v534,
                v535,
                v538,
                v539,
                v541,
                v548,
                v549,
                v551,
                v553,
                v555,
                v556,
                v557,
                v558,
                v576,
                v577,
                v583,
                v584,
            )
        };
        let (
            v586,
            v588,
            v589,
            v593,
            v612,
            v632,
            v640,
            v647,
            v649,
            v651,
            v653,
            v656,
            v657,
            v666,
            v667,
            v685,
            v687,
            v692,
            v694,
            v723,
            v730,
            v753,
            v755,
            v757,
            v761,
            v763,
            v779,
        ) = {
            let v585: L = v506 * v584;
            let v586: L = v583 - v585;
            let v587: L = v495 * v584;
            let v588: L = v558 - v587;
            let v589: L = v586 / v588;
            let v590: L = tau[3];
            let v591: L = v590 - v414;
            let v592: L = v584 * v509;
            let v593: L = v591 - v592;
            let v594: L = v589 * v593;
            let v595: L = v553 - v594;
            let v596: L = -L::splat(0.1384816665_f64);
            let v597: L = v596 - v516;
            let v598: L = v597 * v50;
            let v599: L = -L::splat(0.00380751875_f64);
            let v600: L = v514 * v127;
            let v601: L = v599 + v600;
            let v602: L = v601 * v53;
            let v603: L = v598 + v602;
            let v604: L = v603 * v4;
            let v605: L = v601 * v50;
            let v606: L = L::splat(0.1384816665_f64);
            let v607: L = v606 + v516;
            let v608: L = v607 * v53;
            let v609: L = v605 + v608;
            let v610: L = v609 * v2;
            let v611: L = v604 + v610;
            let v612: L = L::splat(0.00030216_f64);
            let v613: L = v612 - v557;
            let v614: L = v613 * v53;
            let v615: L = v614 * v4;
            let v616: L = v613 * v50;
            let v617: L = v616 * v2;
            let v618: L = v615 + v617;
            let v619: L = v618 * v127;
            let v620: L = v538 - v556;
            let v621: L = v620 * v50;
            let v622: L = v621 - v535;
            let v623: L = v622 * v4;
            let v624: L = v576 - v539;
            let v625: L = v624 * v2;
            let v626: L = v623 + v625;
            let v627: L = v626 * v170;
            let v628: L = v619 + v627;
            let v629: L = v628 * v130;
            let v630: L = v611 + v629;
            let v631: L = v497 * v130;
            let v632: L = v494 * v631;
            let v633: L = v506 * v632;
            let v634: L = v630 - v633;
            let v635: L = v532 * v167;
            let v636: L = v526 + v635;
            let v637: L = v636 * v127;
            let v638: L = v534 * v170;
            let v639: L = v637 - v638;
            let v640: L = v512 * v639;
            let v641: L = v548 * v640;
            let v642: L = v634 - v641;
            let v643: L = v620 * v170;
            let v644: L = v643 * v130;
            let v645: L = v631 * v584;
            let v646: L = v644 - v645;
            let v647: L = v646 / v588;
            let v648: L = v586 * v647;
            let v649: L = v642 - v648;
            let v650: L = L::splat(0.3589900705_f64);
            let v651: L = L::splat(0.002487168_f64);
            let v652: L = v651 + v556;
            let v653: L = v652 * v167;
            let v654: L = v650 + v653;
            let v655: L = v613 * v127;
            let v656: L = L::splat(0.000116928_f64);
            let v657: L = v656 * v170;
            let v658: L = v655 - v657;
            let v659: L = v658 * v127;
            let v660: L = v654 + v659;
            let v661: L = v631 * v632;
            let v662: L = v660 - v661;
            let v663: L = v639 * v640;
            let v664: L = v662 - v663;
            let v665: L = v646 * v647;
            let v666: L = v664 - v665;
            let v667: L = v649 / v666;
            let v668: L = tau[2];
            let v669: L = v83 * v61;
            let v670: L = v76 * v71;
            let v671: L = v669 - v670;
            let v672: L = v58 * v398;
            let v673: L = v69 * v81;
            let v674: L = v672 - v673;
            let v675: L = v671 + v674;
            let v676: L = v113 * v155;
            let v677: L = v365 * v111;
            let v678: L = v676 - v677;
            let v679: L = v675 + v678;
            let v680: L = v130 * v312;
            let v681: L = v127 * v358;
            let v682: L = v680 - v681;
            let v683: L = v679 + v682;
            let v684: L = v104 * v386;
            let v685: L = v683 - v684;
            let v686: L = v668 + v685;
            let v687: L = v632 * v509;
            let v688: L = v686 - v687;
            let v689: L = v640 * v551;
            let v690: L = v688 - v689;
            let v691: L = v647 * v593;
            let v692: L = v690 - v691;
            let v693: L = v667 * v692;
            let v694: L = v595 - v693;
            let v695: L = v597 + v644;
            let v696: L = v695 * v50;
            let v697: L = v17 + v696;
            let v698: L = v655 - v638;
            let v699: L = v698 * v130;
            let v700: L = v601 + v699;
            let v701: L = v700 * v53;
            let v702: L = v697 + v701;
            let v703: L = v702 * v4;
            let v704: L = -L::splat(0.6903913435_f64);
            let v705: L = v704 + v605;
            let v706: L = v705 + v608;
            let v707: L = v655 * v50;
            let v708: L = v577 * v170;
            let v709: L = v707 + v708;
            let v710: L = v709 * v130;
            let v711: L = v706 + v710;
            let v712: L = v711 * v2;
            let v713: L = v703 + v712;
            let v714: L = v713 - v633;
            let v715: L = -L::splat(5.8464e-05_f64);
            let v716: L = v715 - v533;
            let v717: L = v716 * v170;
            let v718: L = v532 - v541;
            let v719: L = v718 * v167;
            let v720: L = v526 + v719;
            let v721: L = v720 * v127;
            let v722: L = v717 + v721;
            let v723: L = v512 * v722;
            let v724: L = v548 * v723;
            let v725: L = v714 - v724;
            let v726: L = v620 + v541;
            let v727: L = v726 * v170;
            let v728: L = v727 * v130;
            let v729: L = v728 - v645;
            let v730: L = v729 / v588;
            let v731: L = v586 * v730;
            let v732: L = v725 - v731;
            let v733: L = L::splat(0.010956925_f64);
            let v734: L = v733 * v50;
            let v735: L = v650 + v734;
            let v736: L = L::splat(0.384876294_f64);
            let v737: L = v736 * v53;
            let v738: L = v735 - v737;
            let v739: L = v652 - v541;
            let v740: L = v739 * v167;
            let v741: L = v738 + v740;
            let v742: L = -L::splat(0.000116928_f64);
            let v743: L = v742 - v533;
            let v744: L = v743 * v170;
            let v745: L = v744 + v655;
            let v746: L = v745 * v127;
            let v747: L = v741 + v746;
            let v748: L = v747 - v661;
            let v749: L = v722 * v640;
            let v750: L = v748 - v749;
            let v751: L = v729 * v647;
            let v752: L = v750 - v751;
            let v753: L = v752 / v666;
            let v754: L = v649 * v753;
            let v755: L = v732 - v754;
            let v756: L = L::splat(2.1071040725_f64);
            let v757: L = L::splat(0.02191385_f64);
            let v758: L = v757 * v50;
            let v759: L = v756 + v758;
            let v760: L = L::splat(0.769752588_f64);
            let v761: L = v760 * v53;
            let v762: L = v759 - v761;
            let v763: L = v651 * v53;
            let v764: L = v652 - v763;
            let v765: L = v764 * v167;
            let v766: L = v762 + v765;
            let v767: L = v651 * v50;
            let v768: L = v742 - v767;
            let v769: L = v768 * v170;
            let v770: L = v769 + v655;
            let v771: L = v770 * v127;
            let v772: L = v766 + v771;
            let v773: L = v772 - v661;
            let v774: L = v722 * v723;
            let v775: L = v773 - v774;
            let v776: L = v729 * v730;
            let v777: L = v775 - v776;
            let v778: L = v752 * v753;
            let v779: L = v777 - v778;
            (
                v586,
                v588,
                v589,
                v593,
                v612,
                v632,
                v640,
                v647,
                v649,
                v651,
                v653,
                v656,
                v657,
                v666,
                v667,
                v685,
                v687,
                v692,
                v694,
                v723,
                v730,
                v753,
                v755,
                v757,
                v761,
                v763,
                v779,
            )
        };
        let (v941, v944, v949, v956, v963, v972) = {
            let v780: L = v755 / v779;
            let v781: L = tau[1];
            let v782: L = v15 * v8;
            let v783: L = v17 * v12;
            let v784: L = v782 - v783;
            let v785: L = v11 * v29;
            let v786: L = v6 * v458;
            let v787: L = v785 - v786;
            let v788: L = v784 + v787;
            let v789: L = v464 * v45;
            let v790: L = v33 * v99;
            let v791: L = v789 - v790;
            let v792: L = v788 + v791;
            let v793: L = v792 - v685;
            let v794: L = v472 * v45;
            let v795: L = v7 * v483;
            let v796: L = v33 * v11;
            let v797: L = v464 * v6;
            let v798: L = v796 - v797;
            let v799: L = v11 * v798;
            let v800: L = v795 - v799;
            let v801: L = v40 * v8;
            let v802: L = v800 - v801;
            let v803: L = v794 + v802;
            let v804: L = v53 * v443;
            let v805: L = v50 * v386;
            let v806: L = v804 + v805;
            let v807: L = v803 + v806;
            let v808: L = v34 * v807;
            let v809: L = v793 + v808;
            let v810: L = v781 - v809;
            let v811: L = v810 - v687;
            let v812: L = v723 * v551;
            let v813: L = v811 - v812;
            let v814: L = v730 * v593;
            let v815: L = v813 - v814;
            let v816: L = v753 * v692;
            let v817: L = v815 - v816;
            let v818: L = v780 * v817;
            let v819: L = v694 - v818;
            let v820: L = L::splat(1.553523243625_f64);
            let v821: L = v820 - v557;
            let v822: L = L::splat(0.000864288_f64);
            let v823: L = v822 * v130;
            let v824: L = v656 * v127;
            let v825: L = v823 - v824;
            let v826: L = v825 * v170;
            let v827: L = v821 + v826;
            let v828: L = L::splat(0.022546398_f64);
            let v829: L = v656 * v167;
            let v830: L = v828 + v829;
            let v831: L = -L::splat(0.002487168_f64);
            let v832: L = L::splat(0.00040432_f64);
            let v833: L = v832 * v167;
            let v834: L = v831 - v833;
            let v835: L = v834 * v170;
            let v836: L = v835 * v127;
            let v837: L = v830 + v836;
            let v838: L = v837 * v53;
            let v839: L = L::splat(0.3239198455_f64);
            let v840: L = v839 + v653;
            let v841: L = -L::splat(0.00030216_f64);
            let v842: L = v841 + v557;
            let v843: L = v842 * v127;
            let v844: L = v657 + v843;
            let v845: L = v844 * v127;
            let v846: L = v840 + v845;
            let v847: L = v846 * v50;
            let v848: L = v838 + v847;
            let v849: L = v848 * v50;
            let v850: L = v827 + v849;
            let v851: L = L::splat(0.008347998_f64);
            let v852: L = v851 + v829;
            let v853: L = v757 * v53;
            let v854: L = v852 - v853;
            let v855: L = v834 + v763;
            let v856: L = v855 * v170;
            let v857: L = v856 * v127;
            let v858: L = v854 + v857;
            let v859: L = v858 * v2;
            let v860: L = L::splat(1.9257810475_f64);
            let v861: L = v860 - v761;
            let v862: L = v612 * v127;
            let v863: L = v657 - v862;
            let v864: L = v863 * v127;
            let v865: L = v861 + v864;
            let v866: L = v651 - v763;
            let v867: L = v555 * v127;
            let v868: L = v867 * v127;
            let v869: L = v555 + v868;
            let v870: L = v869 * v167;
            let v871: L = v866 + v870;
            let v872: L = v871 * v167;
            let v873: L = v865 + v872;
            let v874: L = v873 * v4;
            let v875: L = v859 + v874;
            let v876: L = v651 * v170;
            let v877: L = v876 * v127;
            let v878: L = v757 - v877;
            let v879: L = -L::splat(0.045092796_f64);
            let v880: L = L::splat(0.000233856_f64);
            let v881: L = v880 * v167;
            let v882: L = v879 - v881;
            let v883: L = L::splat(0.004974336_f64);
            let v884: L = L::splat(0.00080864_f64);
            let v885: L = v884 * v167;
            let v886: L = v883 + v885;
            let v887: L = v886 * v170;
            let v888: L = v887 * v127;
            let v889: L = v882 + v888;
            let v890: L = v889 * v53;
            let v891: L = v878 + v890;
            let v892: L = -L::splat(0.647839691_f64);
            let v893: L = -L::splat(0.004974336_f64);
            let v894: L = v893 - v833;
            let v895: L = v894 * v167;
            let v896: L = v892 + v895;
            let v897: L = L::splat(0.00060432_f64);
            let v898: L = v833 * v167;
            let v899: L = v897 - v898;
            let v900: L = v899 * v127;
            let v901: L = v880 * v170;
            let v902: L = v900 - v901;
            let v903: L = v902 * v127;
            let v904: L = v896 + v903;
            let v905: L = v904 * v50;
            let v906: L = v891 + v905;
            let v907: L = v906 * v4;
            let v908: L = -L::splat(0.769752588_f64);
            let v909: L = v651 * v167;
            let v910: L = v908 - v909;
            let v911: L = v889 * v50;
            let v912: L = v910 + v911;
            let v913: L = L::splat(0.647839691_f64);
            let v914: L = v883 + v833;
            let v915: L = v914 * v167;
            let v916: L = v913 + v915;
            let v917: L = -L::splat(0.00060432_f64);
            let v918: L = v917 + v898;
            let v919: L = v918 * v127;
            let v920: L = v901 + v919;
            let v921: L = v920 * v127;
            let v922: L = v916 + v921;
            let v923: L = v922 * v53;
            let v924: L = v912 + v923;
            let v925: L = v924 * v2;
            let v926: L = v907 + v925;
            let v927: L = v926 * v50;
            let v928: L = v875 + v927;
            let v929: L = v928 * v4;
            let v930: L = v850 + v929;
            let v931: L = v506 * v507;
            let v932: L = v930 - v931;
            let v933: L = v548 * v549;
            let v934: L = v932 - v933;
            let v935: L = v586 * v589;
            let v936: L = v934 - v935;
            let v937: L = v649 * v667;
            let v938: L = v936 - v937;
            let v939: L = v755 * v780;
            let v940: L = v938 - v939;
            let v941: L = v819 / v940;
            let v942: L = v817 / v779;
            let v943: L = v780 * v941;
            let v944: L = v942 - v943;
            let v945: L = v692 / v666;
            let v946: L = v667 * v941;
            let v947: L = v945 - v946;
            let v948: L = v753 * v944;
            let v949: L = v947 - v948;
            let v950: L = v593 / v588;
            let v951: L = v589 * v941;
            let v952: L = v950 - v951;
            let v953: L = v730 * v944;
            let v954: L = v952 - v953;
            let v955: L = v647 * v949;
            let v956: L = v954 - v955;
            let v957: L = v512 * v551;
            let v958: L = v549 * v941;
            let v959: L = v957 - v958;
            let v960: L = v723 * v944;
            let v961: L = v959 - v960;
            let v962: L = v640 * v949;
            let v963: L = v961 - v962;
            let v964: L = v494 * v509;
            let v965: L = v507 * v941;
            let v966: L = v964 - v965;
            let v967: L = v632 * v944;
            let v968: L = v966 - v967;
            let v969: L = v632 * v949;
            let v970: L = v968 - v969;
            let v971: L = v584 * v956;
            let v972: L = v970 - v971;
            (v941, v944, v949, v956, v963, v972)
        };
        [v941, v944, v949, v956, v963, v972]
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
    /// Operation count: 746 floating-point operations, 10 trig calls.
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
            v136,
            v138,
            v139,
            v140,
            v141,
            v142,
            v144,
            v149,
            v151,
            v152,
            v153,
            v154,
            v155,
            v161,
            v163,
            v167,
            v168,
        ) = {
            let v0: L = L::splat(1.553523243625_f64);
            let v1: L = L::splat(0.00020216_f64);
            let v2: L = q[4];
            let (v15, v3): (L, L) = L::sincos(v2);
            let v4: L = v1 * v3;
            let v5: L = v4 * v3;
            let v6: L = v0 - v5;
            let v7: L = L::splat(0.000864288_f64);
            let v8: L = q[3];
            let (v9, v12): (L, L) = L::sincos(v8);
            let v10: L = v7 * v9;
            let v11: L = L::splat(0.000116928_f64);
            let v13: L = v11 * v12;
            let v14: L = v10 - v13;
            let v16: L = v14 * v15;
            let v17: L = v6 + v16;
            let v18: L = L::splat(0.022546398_f64);
            let v19: L = v11 * v3;
            let v20: L = v18 + v19;
            let v21: L = -L::splat(0.002487168_f64);
            let v22: L = L::splat(0.00040432_f64);
            let v23: L = v22 * v3;
            let v24: L = v21 - v23;
            let v25: L = v24 * v15;
            let v26: L = v25 * v12;
            let v27: L = v20 + v26;
            let v28: L = q[2];
            let (v29, v43): (L, L) = L::sincos(v28);
            let v30: L = v27 * v29;
            let v31: L = L::splat(0.3239198455_f64);
            let v32: L = L::splat(0.002487168_f64);
            let v33: L = v32 + v4;
            let v34: L = v33 * v3;
            let v35: L = v31 + v34;
            let v36: L = v11 * v15;
            let v37: L = -L::splat(0.00030216_f64);
            let v38: L = v37 + v5;
            let v39: L = v38 * v12;
            let v40: L = v36 + v39;
            let v41: L = v40 * v12;
            let v42: L = v35 + v41;
            let v44: L = v42 * v43;
            let v45: L = v30 + v44;
            let v46: L = v45 * v43;
            let v47: L = v17 + v46;
            let v48: L = L::splat(0.008347998_f64);
            let v49: L = v48 + v19;
            let v50: L = L::splat(0.02191385_f64);
            let v51: L = v50 * v29;
            let v52: L = v49 - v51;
            let v53: L = v32 * v29;
            let v54: L = v24 + v53;
            let v55: L = v54 * v15;
            let v56: L = v55 * v12;
            let v57: L = v52 + v56;
            let v58: L = q[1];
            let (v59, v78): (L, L) = L::sincos(v58);
            let v60: L = v57 * v59;
            let v61: L = L::splat(1.9257810475_f64);
            let v62: L = L::splat(0.769752588_f64);
            let v63: L = v62 * v29;
            let v64: L = v61 - v63;
            let v65: L = L::splat(0.00030216_f64);
            let v66: L = v65 * v12;
            let v67: L = v36 - v66;
            let v68: L = v67 * v12;
            let v69: L = v64 + v68;
            let v70: L = v32 - v53;
            let v71: L = v1 * v12;
            let v72: L = v71 * v12;
            let v73: L = v1 + v72;
            let v74: L = v73 * v3;
            let v75: L = v70 + v74;
            let v76: L = v75 * v3;
            let v77: L = v69 + v76;
            let v79: L = v77 * v78;
            let v80: L = v60 + v79;
            let v81: L = v32 * v15;
            let v82: L = v81 * v12;
            let v83: L = v50 - v82;
            let v84: L = -L::splat(0.045092796_f64);
            let v85: L = L::splat(0.000233856_f64);
            let v86: L = v85 * v3;
            let v87: L = v84 - v86;
            let v88: L = L::splat(0.004974336_f64);
            let v89: L = L::splat(0.00080864_f64);
            let v90: L = v89 * v3;
            let v91: L = v88 + v90;
            let v92: L = v91 * v15;
            let v93: L = v92 * v12;
            let v94: L = v87 + v93;
            let v95: L = v94 * v29;
            let v96: L = v83 + v95;
            let v97: L = -L::splat(0.647839691_f64);
            let v98: L = -L::splat(0.004974336_f64);
            let v99: L = v98 - v23;
            let v100: L = v99 * v3;
            let v101: L = v97 + v100;
            let v102: L = L::splat(0.00060432_f64);
            let v103: L = v23 * v3;
            let v104: L = v102 - v103;
            let v105: L = v104 * v12;
            let v106: L = v85 * v15;
            let v107: L = v105 - v106;
            let v108: L = v107 * v12;
            let v109: L = v101 + v108;
            let v110: L = v109 * v43;
            let v111: L = v96 + v110;
            let v112: L = v111 * v78;
            let v113: L = -L::splat(0.769752588_f64);
            let v114: L = v32 * v3;
            let v115: L = v113 - v114;
            let v116: L = v94 * v43;
            let v117: L = v115 + v116;
            let v118: L = L::splat(0.647839691_f64);
            let v119: L = v88 + v23;
            let v120: L = v119 * v3;
            let v121: L = v118 + v120;
            let v122: L = -L::splat(0.00060432_f64);
            let v123: L = v122 + v103;
            let v124: L = v123 * v12;
            let v125: L = v106 + v124;
            let v126: L = v125 * v12;
            let v127: L = v121 + v126;
            let v128: L = v127 * v29;
            let v129: L = v117 + v128;
            let v130: L = v129 * v59;
            let v131: L = v112 + v130;
            let v132: L = v131 * v43;
            let v133: L = v80 + v132;
            let v134: L = v133 * v78;
            let v135: L = v47 + v134;
            let v136: L = -L::splat(0.023751_f64);
            let v137: L = -L::splat(0.1384816665_f64);
            let v138: L = L::splat(0.000432144_f64);
            let v139: L = v138 * v3;
            let v140: L = v137 - v139;
            let v141: L = -L::splat(0.001243584_f64);
            let v142: L = v141 - v4;
            let v143: L = v142 * v15;
            let v144: L = v143 * v9;
            let v145: L = v140 + v144;
            let v146: L = v145 * v43;
            let v147: L = v136 + v146;
            let v148: L = -L::splat(0.00380751875_f64);
            let v149: L = v138 * v15;
            let v150: L = v149 * v12;
            let v151: L = v148 + v150;
            let v152: L = v65 - v5;
            let v153: L = v152 * v12;
            let v154: L = L::splat(5.8464e-05_f64);
            let v155: L = v154 * v15;
            let v156: L = v153 - v155;
            let v157: L = v156 * v9;
            let v158: L = v151 + v157;
            let v159: L = v158 * v29;
            let v160: L = v147 + v159;
            let v161: L = v160 * v78;
            let v162: L = -L::splat(0.6903913435_f64);
            let v163: L = v151 * v43;
            let v164: L = v162 + v163;
            let v165: L = L::splat(0.1384816665_f64);
            let v166: L = v165 + v139;
            let v167: L = v166 * v29;
            let v168: L = v164 + v167;
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
                v136,
                v138,
                v139,
                v140,
                v141,
                v142,
                v144,
                v149,
                v151,
                v152,
                v153,
                v154,
                v155,
                v161,
                v163,
                v167,
                v168,
            )
        };
        let (
            v172,
            v181,
            v205,
            v207,
            v229,
            v240,
            v246,
            v249,
            v256,
            v257,
            v258,
            v260,
            v269,
            v270,
            v272,
            v273,
            v274,
            v276,
            v277,
            v278,
            v281,
            v287,
            v290,
            v294,
            v298,
            v299,
            v301,
            v303,
            v305,
            v306,
            v308,
            v310,
            v313,
            v314,
            v320,
            v323,
            v325,
            v331,
            v333,
            v335,
            v336,
            v337,
        ) = {
            let v169: L = v153 * v43;
            let v170: L = v154 * v43;
            let v171: L = v141 - v170;
            let v172: L = L::splat(0.001243584_f64);
            let v173: L = v172 + v4;
            let v174: L = v173 * v29;
            let v175: L = v171 + v174;
            let v176: L = v175 * v15;
            let v177: L = v169 + v176;
            let v178: L = v177 * v9;
            let v179: L = v168 + v178;
            let v180: L = v179 * v59;
            let v181: L = v161 + v180;
            let v182: L = v140 * v43;
            let v183: L = v151 * v29;
            let v184: L = v182 + v183;
            let v185: L = v184 * v78;
            let v186: L = v163 + v167;
            let v187: L = v186 * v59;
            let v188: L = v185 + v187;
            let v189: L = v152 * v29;
            let v190: L = v189 * v78;
            let v191: L = v152 * v43;
            let v192: L = v191 * v59;
            let v193: L = v190 + v192;
            let v194: L = v193 * v12;
            let v195: L = v142 * v43;
            let v196: L = v154 * v29;
            let v197: L = v195 - v196;
            let v198: L = v197 * v78;
            let v199: L = v174 - v170;
            let v200: L = v199 * v59;
            let v201: L = v198 + v200;
            let v202: L = v201 * v15;
            let v203: L = v194 + v202;
            let v204: L = v203 * v9;
            let v205: L = v188 + v204;
            let v206: L = L::splat(0.00184216_f64);
            let v207: L = v206 - v5;
            let v208: L = v207 * v43;
            let v209: L = v208 * v78;
            let v210: L = -L::splat(0.00184216_f64);
            let v211: L = v210 + v5;
            let v212: L = v211 * v29;
            let v213: L = v212 * v59;
            let v214: L = v209 + v213;
            let v215: L = v138 * v43;
            let v216: L = v215 * v78;
            let v217: L = v138 * v29;
            let v218: L = v217 * v59;
            let v219: L = v216 - v218;
            let v220: L = v219 * v9;
            let v221: L = v173 * v43;
            let v222: L = v196 + v221;
            let v223: L = v222 * v59;
            let v224: L = v175 * v78;
            let v225: L = v223 + v224;
            let v226: L = v225 * v12;
            let v227: L = v220 + v226;
            let v228: L = v227 * v15;
            let v229: L = v214 + v228;
            let v230: L = v149 * v29;
            let v231: L = v139 * v12;
            let v232: L = v231 * v43;
            let v233: L = v230 - v232;
            let v234: L = v233 * v78;
            let v235: L = v149 * v43;
            let v236: L = v231 * v29;
            let v237: L = v235 + v236;
            let v238: L = v237 * v59;
            let v239: L = v234 + v238;
            let v240: L = L::splat(0.00064216_f64);
            let v241: L = v240 * v29;
            let v242: L = v241 * v78;
            let v243: L = v240 * v43;
            let v244: L = v243 * v59;
            let v245: L = v242 + v244;
            let v246: L = v172 * v43;
            let v247: L = v246 + v196;
            let v248: L = v247 * v59;
            let v249: L = v172 * v29;
            let v250: L = v171 + v249;
            let v251: L = v250 * v78;
            let v252: L = v248 + v251;
            let v253: L = v252 * v3;
            let v254: L = v245 + v253;
            let v255: L = v254 * v9;
            let v256: L = v239 + v255;
            let v257: L = L::splat(4e-05_f64);
            let v258: L = v257 * v3;
            let v259: L = v258 * v43;
            let v260: L = v257 * v15;
            let v261: L = v260 * v12;
            let v262: L = v261 * v29;
            let v263: L = v259 - v262;
            let v264: L = v263 * v78;
            let v265: L = v261 * v43;
            let v266: L = v258 * v29;
            let v267: L = v265 + v266;
            let v268: L = v267 * v59;
            let v269: L = v264 - v268;
            let v270: L = L::splat(1.03118515_f64);
            let v271: L = qd[0];
            let v272: L = v78 * v271;
            let v273: L = qd[1];
            let v274: L = v272 * v273;
            let v275: L = v270 * v274;
            let v276: L = L::splat(0.03798072_f64);
            let v277: L = v59 * v271;
            let v278: L = v277 * v273;
            let v279: L = v276 * v278;
            let v280: L = v275 - v279;
            let v281: L = L::splat(1.4401023_f64);
            let v282: L = v281 * v277;
            let v283: L = v136 * v272;
            let v284: L = v282 + v283;
            let v285: L = L::splat(2.842524056_f64);
            let v286: L = v285 * v273;
            let v287: L = v284 + v286;
            let v288: L = v272 * v287;
            let v289: L = v276 * v277;
            let v290: L = L::splat(3.727456406_f64);
            let v291: L = v290 * v272;
            let v292: L = v289 + v291;
            let v293: L = v136 * v273;
            let v294: L = v292 + v293;
            let v295: L = v273 * v294;
            let v296: L = v288 - v295;
            let v297: L = v280 + v296;
            let v298: L = L::splat(0.1044_f64);
            let v299: L = L::splat(0.4318_f64);
            let v300: L = v299 * v278;
            let v301: L = v299 * v273;
            let v302: L = v277 * v301;
            let v303: L = v300 + v302;
            let v304: L = v298 * v303;
            let v305: L = L::splat(3.9585_f64);
            let v306: L = L::splat(9.81_f64);
            let v307: L = v306 * v78;
            let v308: L = v299 * v272;
            let v309: L = v277 * v308;
            let v310: L = v307 + v309;
            let v311: L = v305 * v310;
            let v312: L = v304 - v311;
            let v313: L = v297 + v312;
            let v314: L = L::splat(0.090474288_f64);
            let v315: L = v43 * v274;
            let v316: L = v29 * v278;
            let v317: L = v315 - v316;
            let v318: L = v43 * v272;
            let v319: L = v29 * v277;
            let v320: L = v318 - v319;
            let v321: L = qd[2];
            let v322: L = v320 * v321;
            let v323: L = v317 + v322;
            let v324: L = v314 * v323;
            let v325: L = L::splat(0.0068208_f64);
            let v326: L = v29 * v274;
            let v327: L = v43 * v278;
            let v328: L = v326 + v327;
            let v329: L = v43 * v277;
            let v330: L = v29 * v272;
            let v331: L = v329 + v330;
            let v332: L = v331 * v321;
            let v333: L = v328 + v332;
            let v334: L = v325 * v333;
            let v335: L = v324 - v334;
            let v336: L = v273 + v321;
            let v337: L = v325 * v331;
            (
                v172,
                v181,
                v205,
                v207,
                v229,
                v240,
                v246,
                v249,
                v256,
                v257,
                v258,
                v260,
                v269,
                v270,
                v272,
                v273,
                v274,
                v276,
                v277,
                v278,
                v281,
                v287,
                v290,
                v294,
                v298,
                v299,
                v301,
                v303,
                v305,
                v306,
                v308,
                v310,
                v313,
                v314,
                v320,
                v323,
                v325,
                v331,
                v333,
                v335,
                v336,
                v337,
            )
        };
        let (
            v338,
            v341,
            v343,
            v345,
            v351,
            v355,
            v361,
            v364,
            v366,
            v373,
            v375,
            v384,
            v387,
            v388,
            v392,
            v395,
            v397,
            v398,
            v400,
            v401,
            v405,
            v414,
            v422,
            v424,
            v425,
            v432,
            v434,
            v435,
            v439,
            v440,
            v441,
            v443,
            v446,
            v448,
            v449,
            v451,
            v454,
            v459,
            v462,
            v465,
            v467,
            v468,
            v474,
            v482,
            v487,
            v489,
            v492,
            v494,
            v495,
            v498,
            v499,
            v502,
            v505,
            v506,
        ) = {
            let v338: L = L::splat(0.0047376_f64);
            let v339: L = v338 * v336;
            let v340: L = v337 - v339;
            let v341: L = L::splat(0.01543232_f64);
            let v342: L = v341 * v320;
            let v343: L = v340 + v342;
            let v344: L = v336 * v343;
            let v345: L = -L::splat(0.001373904_f64);
            let v346: L = v345 * v331;
            let v347: L = L::splat(0.111498032_f64);
            let v348: L = v347 * v336;
            let v349: L = v346 - v348;
            let v350: L = v338 * v320;
            let v351: L = v349 + v350;
            let v352: L = v320 * v351;
            let v353: L = v344 + v352;
            let v354: L = v335 - v353;
            let v355: L = -L::splat(0.06768_f64);
            let v356: L = v43 * v310;
            let v357: L = v306 * v59;
            let v358: L = v272 * v308;
            let v359: L = v273 * v301;
            let v360: L = v358 + v359;
            let v361: L = v357 - v360;
            let v362: L = v29 * v361;
            let v363: L = v356 - v362;
            let v364: L = -L::splat(0.15005_f64);
            let v365: L = v364 * v323;
            let v366: L = L::splat(0.0203_f64);
            let v367: L = v366 * v320;
            let v368: L = v331 * v367;
            let v369: L = v364 * v320;
            let v370: L = v336 * v369;
            let v371: L = v368 - v370;
            let v372: L = v365 + v371;
            let v373: L = v363 + v372;
            let v374: L = v355 * v373;
            let v375: L = L::splat(0.336_f64);
            let v376: L = v366 * v333;
            let v377: L = v320 * v369;
            let v378: L = v364 * v331;
            let v379: L = v366 * v336;
            let v380: L = v378 + v379;
            let v381: L = v331 * v380;
            let v382: L = v377 + v381;
            let v383: L = v376 + v382;
            let v384: L = v303 + v383;
            let v385: L = v375 * v384;
            let v386: L = v374 + v385;
            let v387: L = v354 + v386;
            let v388: L = L::splat(0.00209602_f64);
            let v389: L = v12 * v323;
            let v390: L = v9 * v331;
            let v391: L = v12 * v336;
            let v392: L = v390 + v391;
            let v393: L = qd[3];
            let v394: L = v392 * v393;
            let v395: L = v389 - v394;
            let v396: L = v388 * v395;
            let v397: L = v320 + v393;
            let v398: L = v388 * v392;
            let v399: L = v397 * v398;
            let v400: L = L::splat(0.0013_f64);
            let v401: L = v400 * v397;
            let v402: L = v392 * v401;
            let v403: L = v399 - v402;
            let v404: L = v396 + v403;
            let v405: L = L::splat(0.01558_f64);
            let v406: L = v43 * v361;
            let v407: L = v29 * v310;
            let v408: L = v406 + v407;
            let v409: L = v364 * v333;
            let v410: L = v336 * v380;
            let v411: L = v320 * v367;
            let v412: L = v410 + v411;
            let v413: L = v409 - v412;
            let v414: L = v408 + v413;
            let v415: L = v9 * v414;
            let v416: L = v12 * v384;
            let v417: L = v415 + v416;
            let v418: L = v299 * v395;
            let v419: L = v299 * v392;
            let v420: L = v397 * v419;
            let v421: L = v418 + v420;
            let v422: L = v417 + v421;
            let v423: L = v405 * v422;
            let v424: L = v404 + v423;
            let v425: L = L::splat(0.0003_f64);
            let v426: L = v3 * v395;
            let v427: L = v15 * v333;
            let v428: L = v426 - v427;
            let v429: L = v3 * v397;
            let v430: L = v12 * v331;
            let v431: L = v9 * v336;
            let v432: L = v430 - v431;
            let v433: L = v15 * v432;
            let v434: L = v429 - v433;
            let v435: L = qd[4];
            let v436: L = v434 * v435;
            let v437: L = v428 + v436;
            let v438: L = v425 * v437;
            let v439: L = L::splat(0.0004_f64);
            let v440: L = v392 + v435;
            let v441: L = v439 * v440;
            let v442: L = v434 * v441;
            let v443: L = v425 * v434;
            let v444: L = v440 * v443;
            let v445: L = v442 - v444;
            let v446: L = v438 + v445;
            let v447: L = q[5];
            let (v451, v448): (L, L) = L::sincos(v447);
            let v449: L = L::splat(0.00024216_f64);
            let v450: L = v448 * v437;
            let v452: L = v9 * v323;
            let v453: L = v432 * v393;
            let v454: L = v452 + v453;
            let v455: L = v451 * v454;
            let v456: L = v450 - v455;
            let v457: L = v3 * v432;
            let v458: L = v15 * v397;
            let v459: L = v457 + v458;
            let v460: L = v451 * v459;
            let v461: L = v448 * v440;
            let v462: L = v460 + v461;
            let v463: L = qd[5];
            let v464: L = v462 * v463;
            let v465: L = v456 - v464;
            let v466: L = v449 * v465;
            let v467: L = v434 + v463;
            let v468: L = v449 * v462;
            let v469: L = v467 * v468;
            let v470: L = v257 * v467;
            let v471: L = v462 * v470;
            let v472: L = v469 - v471;
            let v473: L = v466 + v472;
            let v474: L = L::splat(0.00288_f64);
            let v475: L = v12 * v414;
            let v476: L = v9 * v384;
            let v477: L = v475 - v476;
            let v478: L = v299 * v432;
            let v479: L = v397 * v478;
            let v480: L = v299 * v454;
            let v481: L = v479 - v480;
            let v482: L = v477 + v481;
            let v483: L = v3 * v482;
            let v484: L = v392 * v419;
            let v485: L = v432 * v478;
            let v486: L = v484 + v485;
            let v487: L = v373 - v486;
            let v488: L = v15 * v487;
            let v489: L = v483 + v488;
            let v490: L = v451 * v489;
            let v491: L = v448 * v422;
            let v492: L = v490 + v491;
            let v493: L = v474 * v492;
            let v494: L = v473 + v493;
            let v495: L = v448 * v494;
            let v496: L = v448 * v459;
            let v497: L = v451 * v440;
            let v498: L = v496 - v497;
            let v499: L = v449 * v498;
            let v500: L = v467 * v499;
            let v501: L = v498 * v470;
            let v502: L = v500 - v501;
            let v503: L = v451 * v437;
            let v504: L = v448 * v454;
            let v505: L = v503 + v504;
            let v506: L = v498 * v463;
            (
                v338,
                v341,
                v343,
                v345,
                v351,
                v355,
                v361,
                v364,
                v366,
                v373,
                v375,
                v384,
                v387,
                v388,
                v392,
                v395,
                v397,
                v398,
                v400,
                v401,
                v405,
                v414,
                v422,
                v424,
                v425,
                v432,
                v434,
                v435,
                v439,
                v440,
                v441,
                v443,
                v446,
                v448,
                v449,
                v451,
                v454,
                v459,
                v462,
                v465,
                v467,
                v468,
                v474,
                v482,
                v487,
                v489,
                v492,
                v494,
                v495,
                v498,
                v499,
                v502,
                v505,
                v506,
            )
        };
        let (
            v534,
            v565,
            v567,
            v585,
            v611,
            v613,
            v617,
            v620,
            v623,
            v627,
            v641,
            v643,
            v644,
            v653,
            v669,
            v670,
            v673,
            v674,
            v675,
        ) = {
            let v507: L = v505 + v506;
            let v508: L = v449 * v507;
            let v509: L = v502 - v508;
            let v510: L = v448 * v489;
            let v511: L = v451 * v422;
            let v512: L = v510 - v511;
            let v513: L = v474 * v512;
            let v514: L = v509 + v513;
            let v515: L = v451 * v514;
            let v516: L = v495 - v515;
            let v517: L = v446 + v516;
            let v518: L = v3 * v517;
            let v519: L = v425 * v459;
            let v520: L = v440 * v519;
            let v521: L = v459 * v441;
            let v522: L = v520 - v521;
            let v523: L = v15 * v395;
            let v524: L = v3 * v333;
            let v525: L = v523 + v524;
            let v526: L = v459 * v435;
            let v527: L = v525 + v526;
            let v528: L = v425 * v527;
            let v529: L = v522 - v528;
            let v530: L = v462 * v499;
            let v531: L = v498 * v468;
            let v532: L = v530 - v531;
            let v533: L = v257 * v527;
            let v534: L = v532 - v533;
            let v535: L = v529 + v534;
            let v536: L = v15 * v535;
            let v537: L = v518 - v536;
            let v538: L = v424 + v537;
            let v539: L = L::splat(0.82_f64);
            let v540: L = v539 * v422;
            let v541: L = v405 * v395;
            let v542: L = v405 * v392;
            let v543: L = v397 * v542;
            let v544: L = v541 + v543;
            let v545: L = v540 + v544;
            let v546: L = L::splat(0.09_f64);
            let v547: L = v546 * v512;
            let v548: L = v474 * v498;
            let v549: L = v467 * v548;
            let v550: L = v474 * v507;
            let v551: L = v549 - v550;
            let v552: L = v547 + v551;
            let v553: L = v451 * v552;
            let v554: L = v546 * v492;
            let v555: L = v474 * v465;
            let v556: L = v474 * v462;
            let v557: L = v467 * v556;
            let v558: L = v555 + v557;
            let v559: L = v554 + v558;
            let v560: L = v448 * v559;
            let v561: L = v553 - v560;
            let v562: L = L::splat(0.34_f64);
            let v563: L = v562 * v422;
            let v564: L = v561 - v563;
            let v565: L = v545 - v564;
            let v566: L = v299 * v565;
            let v567: L = v538 + v566;
            let v568: L = v12 * v567;
            let v569: L = v388 * v454;
            let v570: L = v432 * v401;
            let v571: L = v388 * v432;
            let v572: L = v397 * v571;
            let v573: L = v570 - v572;
            let v574: L = v569 + v573;
            let v575: L = v405 * v482;
            let v576: L = v574 - v575;
            let v577: L = v434 * v519;
            let v578: L = v459 * v443;
            let v579: L = v577 - v578;
            let v580: L = v439 * v454;
            let v581: L = v579 - v580;
            let v582: L = v451 * v494;
            let v583: L = v448 * v514;
            let v584: L = v582 + v583;
            let v585: L = v581 + v584;
            let v586: L = v576 - v585;
            let v587: L = v539 * v482;
            let v588: L = v405 * v432;
            let v589: L = v397 * v588;
            let v590: L = v405 * v454;
            let v591: L = v589 - v590;
            let v592: L = v587 + v591;
            let v593: L = v562 * v489;
            let v594: L = v448 * v552;
            let v595: L = v451 * v559;
            let v596: L = v594 + v595;
            let v597: L = v593 + v596;
            let v598: L = v3 * v597;
            let v599: L = v3 * v487;
            let v600: L = v15 * v482;
            let v601: L = v599 - v600;
            let v602: L = v562 * v601;
            let v603: L = v546 * v601;
            let v604: L = v498 * v548;
            let v605: L = v462 * v556;
            let v606: L = v604 + v605;
            let v607: L = v603 - v606;
            let v608: L = v602 + v607;
            let v609: L = v15 * v608;
            let v610: L = v598 - v609;
            let v611: L = v592 + v610;
            let v612: L = v299 * v611;
            let v613: L = v586 - v612;
            let v614: L = v9 * v613;
            let v615: L = v568 + v614;
            let v616: L = v387 + v615;
            let v617: L = L::splat(4.8_f64);
            let v618: L = v617 * v373;
            let v619: L = v355 * v323;
            let v620: L = -L::splat(0.09744_f64);
            let v621: L = v620 * v320;
            let v622: L = v375 * v331;
            let v623: L = v621 - v622;
            let v624: L = v331 * v623;
            let v625: L = v375 * v336;
            let v626: L = v355 * v320;
            let v627: L = v625 + v626;
            let v628: L = v336 * v627;
            let v629: L = v624 - v628;
            let v630: L = v619 + v629;
            let v631: L = v618 + v630;
            let v632: L = v539 * v487;
            let v633: L = v392 * v542;
            let v634: L = v432 * v588;
            let v635: L = v633 + v634;
            let v636: L = v632 - v635;
            let v637: L = v15 * v597;
            let v638: L = v3 * v608;
            let v639: L = v637 + v638;
            let v640: L = v636 + v639;
            let v641: L = v631 + v640;
            let v642: L = v364 * v641;
            let v643: L = v616 + v642;
            let v644: L = v43 * v643;
            let v645: L = v325 * v323;
            let v646: L = v341 * v333;
            let v647: L = v645 - v646;
            let v648: L = v331 * v351;
            let v649: L = v314 * v331;
            let v650: L = v345 * v336;
            let v651: L = v649 - v650;
            let v652: L = v325 * v320;
            let v653: L = v651 + v652;
            let v654: L = v336 * v653;
            let v655: L = v648 + v654;
            let v656: L = v647 + v655;
            let v657: L = v620 * v384;
            let v658: L = v355 * v414;
            let v659: L = v657 + v658;
            let v660: L = v656 - v659;
            let v661: L = v392 * v571;
            let v662: L = v432 * v398;
            let v663: L = v661 - v662;
            let v664: L = v400 * v333;
            let v665: L = v663 - v664;
            let v666: L = v15 * v517;
            let v667: L = v3 * v535;
            let v668: L = v666 + v667;
            let v669: L = v665 + v668;
            let v670: L = v660 + v669;
            let v671: L = v9 * v611;
            let v672: L = v12 * v565;
            let v673: L = v671 - v672;
            let v674: L = v617 * v384;
            let v675: L = v620 * v333;
            (
                v534,
                v565,
                v567,
                v585,
                v611,
                v613,
                v617,
                v620,
                v623,
                v627,
                v641,
                v643,
                v644,
                v653,
                v669,
                v670,
                v673,
                v674,
                v675,
            )
        };
        let (v747, v761, v776, v779, v787, v788, v833, v837, v841, v842, v843, v844) = {
            let v676: L = v375 * v323;
            let v677: L = v675 + v676;
            let v678: L = v320 * v627;
            let v679: L = v355 * v331;
            let v680: L = v620 * v336;
            let v681: L = v679 + v680;
            let v682: L = v331 * v681;
            let v683: L = v678 + v682;
            let v684: L = v677 + v683;
            let v685: L = v674 + v684;
            let v686: L = v673 - v685;
            let v687: L = v366 * v686;
            let v688: L = v617 * v414;
            let v689: L = v355 * v333;
            let v690: L = v336 * v681;
            let v691: L = v320 * v623;
            let v692: L = v690 + v691;
            let v693: L = v689 - v692;
            let v694: L = v688 + v693;
            let v695: L = v12 * v611;
            let v696: L = v9 * v565;
            let v697: L = v695 + v696;
            let v698: L = v694 + v697;
            let v699: L = v364 * v698;
            let v700: L = v687 - v699;
            let v701: L = v670 + v700;
            let v702: L = v29 * v701;
            let v703: L = v644 - v702;
            let v704: L = v313 + v703;
            let v705: L = v59 * v704;
            let v706: L = v276 * v274;
            let v707: L = v290 * v278;
            let v708: L = v706 - v707;
            let v709: L = v270 * v277;
            let v710: L = v276 * v272;
            let v711: L = v709 + v710;
            let v712: L = v281 * v273;
            let v713: L = v711 + v712;
            let v714: L = v273 * v713;
            let v715: L = v277 * v287;
            let v716: L = v714 - v715;
            let v717: L = v708 + v716;
            let v718: L = v305 * v361;
            let v719: L = -L::splat(6.33012_f64);
            let v720: L = v719 * v303;
            let v721: L = v718 - v720;
            let v722: L = v717 + v721;
            let v723: L = v29 * v643;
            let v724: L = v43 * v701;
            let v725: L = v723 + v724;
            let v726: L = v722 + v725;
            let v727: L = L::splat(17.4_f64);
            let v728: L = v727 * v303;
            let v729: L = v298 * v274;
            let v730: L = v719 * v278;
            let v731: L = v729 + v730;
            let v732: L = v719 * v273;
            let v733: L = v305 * v277;
            let v734: L = v732 - v733;
            let v735: L = v277 * v734;
            let v736: L = v305 * v272;
            let v737: L = v298 * v273;
            let v738: L = v736 - v737;
            let v739: L = v272 * v738;
            let v740: L = v735 - v739;
            let v741: L = v731 + v740;
            let v742: L = v728 + v741;
            let v743: L = v742 - v686;
            let v744: L = v299 * v743;
            let v745: L = v726 - v744;
            let v746: L = v78 * v745;
            let v747: L = v705 + v746;
            let v748: L = L::splat(2.1071040725_f64);
            let v749: L = v50 * v43;
            let v750: L = v748 + v749;
            let v751: L = v750 - v63;
            let v752: L = v33 - v53;
            let v753: L = v752 * v3;
            let v754: L = v751 + v753;
            let v755: L = -L::splat(0.000116928_f64);
            let v756: L = v32 * v43;
            let v757: L = v755 - v756;
            let v758: L = v757 * v15;
            let v759: L = v758 + v153;
            let v760: L = v759 * v12;
            let v761: L = v754 + v760;
            let v762: L = L::splat(0.3589900705_f64);
            let v763: L = L::splat(0.010956925_f64);
            let v764: L = v763 * v43;
            let v765: L = v762 + v764;
            let v766: L = L::splat(0.384876294_f64);
            let v767: L = v766 * v29;
            let v768: L = v765 - v767;
            let v769: L = v33 - v249;
            let v770: L = v769 * v3;
            let v771: L = v768 + v770;
            let v772: L = v755 - v246;
            let v773: L = v772 * v15;
            let v774: L = v773 + v153;
            let v775: L = v774 * v12;
            let v776: L = v771 + v775;
            let v777: L = v142 + v249;
            let v778: L = v777 * v15;
            let v779: L = v778 * v9;
            let v780: L = -L::splat(5.8464e-05_f64);
            let v781: L = v780 - v246;
            let v782: L = v781 * v15;
            let v783: L = v172 - v249;
            let v784: L = v783 * v3;
            let v785: L = v240 + v784;
            let v786: L = v785 * v12;
            let v787: L = v782 + v786;
            let v788: L = v260 * v9;
            let v789: L = v281 * v274;
            let v790: L = v136 * v278;
            let v791: L = v789 - v790;
            let v792: L = v277 * v294;
            let v793: L = v272 * v713;
            let v794: L = v792 - v793;
            let v795: L = v791 + v794;
            let v796: L = v719 * v310;
            let v797: L = v298 * v361;
            let v798: L = v796 - v797;
            let v799: L = v795 + v798;
            let v800: L = v345 * v323;
            let v801: L = v338 * v333;
            let v802: L = v800 - v801;
            let v803: L = v320 * v653;
            let v804: L = v331 * v343;
            let v805: L = v803 - v804;
            let v806: L = v802 + v805;
            let v807: L = v375 * v414;
            let v808: L = v620 * v373;
            let v809: L = v807 - v808;
            let v810: L = v806 + v809;
            let v811: L = v9 * v567;
            let v812: L = v12 * v613;
            let v813: L = v811 - v812;
            let v814: L = v810 + v813;
            let v815: L = v366 * v641;
            let v816: L = v814 - v815;
            let v817: L = v799 - v816;
            let v818: L = v727 * v310;
            let v819: L = v273 * v738;
            let v820: L = v298 * v277;
            let v821: L = v719 * v272;
            let v822: L = v820 - v821;
            let v823: L = v277 * v822;
            let v824: L = v819 - v823;
            let v825: L = v305 * v274;
            let v826: L = v824 - v825;
            let v827: L = v818 + v826;
            let v828: L = v29 * v698;
            let v829: L = v43 * v641;
            let v830: L = v828 + v829;
            let v831: L = v827 + v830;
            let v832: L = v299 * v831;
            let v833: L = v817 + v832;
            let v834: L = v762 + v34;
            let v835: L = v153 - v36;
            let v836: L = v835 * v12;
            let v837: L = v834 + v836;
            let v838: L = v172 * v3;
            let v839: L = v240 + v838;
            let v840: L = v839 * v12;
            let v841: L = v840 - v155;
            let v842: L = -v816;
            let v843: L = L::splat(0.0_f64);
            let v844: L = -v585;
            (v747, v761, v776, v779, v787, v788, v833, v837, v841, v842, v843, v844)
        };
        [
            [v135, v181, v205, v229, v256, v269, v747],
            [v181, v761, v776, v779, v787, v788, v833],
            [v205, v776, v837, v144, v841, v788, v842],
            [v229, v779, v144, v207, v843, v258, v669],
            [v256, v787, v841, v843, v240, v843, v844],
            [v269, v788, v788, v258, v843, v257, v534],
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
    /// Operation count: 1216 floating-point operations, 10 trig calls.
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
            v5,
            v7,
            v10,
            v17,
            v23,
            v25,
            v28,
            v30,
            v33,
            v41,
            v43,
            v47,
            v48,
            v51,
            v53,
            v57,
            v65,
            v73,
            v76,
            v81,
            v82,
            v83,
            v85,
            v87,
            v92,
            v95,
            v99,
            v104,
            v110,
            v113,
            v115,
            v126,
            v127,
            v137,
            v140,
            v141,
            v147,
            v150,
            v151,
            v153,
            v164,
            v168,
            v176,
            v178,
        ) = {
            let v0: L = qdd[0];
            let v1: L = q[1];
            let (v2, v9): (L, L) = L::sincos(v1);
            let v3: L = qd[0];
            let v4: L = v2 * v3;
            let v5: L = L::splat(0.4318_f64);
            let v6: L = qd[1];
            let v7: L = v5 * v6;
            let v8: L = v4 * v7;
            let v10: L = v9 * v0;
            let v11: L = v4 * v6;
            let v12: L = v10 - v11;
            let v13: L = v5 * v12;
            let v14: L = v8 - v13;
            let v15: L = v5 * v9;
            let v16: L = v14 * v15;
            let v17: L = -v16;
            let v18: L = v12 * v15;
            let v19: L = v4 * v15;
            let v20: L = v6 * v19;
            let v21: L = v18 - v20;
            let v22: L = v14 * v9;
            let v23: L = v21 - v22;
            let v24: L = v14 * v2;
            let v25: L = v9 * v3;
            let v26: L = v25 * v15;
            let v27: L = v6 * v26;
            let v28: L = v2 * v0;
            let v29: L = v25 * v6;
            let v30: L = v28 + v29;
            let v31: L = v30 * v15;
            let v32: L = v27 + v31;
            let v33: L = v24 - v32;
            let v34: L = v25 * v26;
            let v35: L = v4 * v19;
            let v36: L = v34 + v35;
            let v37: L = L::splat(9.81_f64);
            let v38: L = v37 * v2;
            let v39: L = v5 * v25;
            let v40: L = v25 * v39;
            let v41: L = v6 * v7;
            let v42: L = v40 + v41;
            let v43: L = v38 - v42;
            let v44: L = v43 * v9;
            let v45: L = v36 + v44;
            let v46: L = v37 * v9;
            let v47: L = qdd[1];
            let v48: L = v5 * v47;
            let v49: L = v4 * v39;
            let v50: L = v48 + v49;
            let v51: L = v46 + v50;
            let v52: L = v51 * v2;
            let v53: L = v45 - v52;
            let v54: L = v6 * v9;
            let v55: L = v4 * v54;
            let v56: L = v30 * v2;
            let v57: L = v55 + v56;
            let v58: L = v25 * v54;
            let v59: L = v30 * v9;
            let v60: L = v58 + v59;
            let v61: L = v6 * v2;
            let v62: L = v4 * v61;
            let v63: L = v60 - v62;
            let v64: L = v12 * v2;
            let v65: L = v63 + v64;
            let v66: L = v6 * v54;
            let v67: L = v25 * v2;
            let v68: L = v4 * v9;
            let v69: L = v67 - v68;
            let v70: L = v4 * v69;
            let v71: L = v66 + v70;
            let v72: L = v47 * v2;
            let v73: L = v71 + v72;
            let v74: L = v12 * v9;
            let v75: L = v25 * v61;
            let v76: L = v74 - v75;
            let v77: L = v47 * v9;
            let v78: L = v6 * v61;
            let v79: L = v77 - v78;
            let v80: L = v25 * v69;
            let v81: L = v79 + v80;
            let v82: L = v6 * v69;
            let v83: L = L::splat(0.0203_f64);
            let v84: L = q[2];
            let (v87, v85): (L, L) = L::sincos(v84);
            let v86: L = v85 * v12;
            let v88: L = v87 * v30;
            let v89: L = v86 - v88;
            let v90: L = v85 * v4;
            let v91: L = v87 * v25;
            let v92: L = v90 + v91;
            let v93: L = qd[2];
            let v94: L = v92 * v93;
            let v95: L = v89 - v94;
            let v96: L = v83 * v95;
            let v97: L = v85 * v25;
            let v98: L = v87 * v4;
            let v99: L = v97 - v98;
            let v100: L = -L::splat(0.15005_f64);
            let v101: L = v100 * v99;
            let v102: L = v99 * v101;
            let v103: L = v100 * v92;
            let v104: L = v6 + v93;
            let v105: L = v83 * v104;
            let v106: L = v103 + v105;
            let v107: L = v92 * v106;
            let v108: L = v102 + v107;
            let v109: L = v96 - v108;
            let v110: L = v109 - v14;
            let v111: L = v85 * v9;
            let v112: L = v87 * v2;
            let v113: L = v111 - v112;
            let v114: L = v83 * v113;
            let v115: L = v15 + v114;
            let v116: L = v110 * v115;
            let v117: L = v85 * v43;
            let v118: L = v87 * v51;
            let v119: L = v117 + v118;
            let v120: L = v100 * v95;
            let v121: L = v104 * v106;
            let v122: L = v83 * v99;
            let v123: L = v99 * v122;
            let v124: L = v121 + v123;
            let v125: L = v120 + v124;
            let v126: L = v119 - v125;
            let v127: L = v100 * v113;
            let v128: L = v126 * v127;
            let v129: L = v116 - v128;
            let v130: L = v85 * v51;
            let v131: L = v87 * v43;
            let v132: L = v130 - v131;
            let v133: L = v85 * v30;
            let v134: L = v87 * v12;
            let v135: L = v133 + v134;
            let v136: L = v99 * v93;
            let v137: L = v135 + v136;
            let v138: L = v100 * v137;
            let v139: L = qdd[2];
            let v140: L = v47 + v139;
            let v141: L = v83 * v140;
            let v142: L = v138 + v141;
            let v143: L = v92 * v122;
            let v144: L = v104 * v101;
            let v145: L = v143 - v144;
            let v146: L = v142 + v145;
            let v147: L = v132 + v146;
            let v148: L = v87 * v9;
            let v149: L = v85 * v2;
            let v150: L = v148 + v149;
            let v151: L = v100 * v150;
            let v152: L = v147 * v151;
            let v153: L = v129 + v152;
            let v154: L = v104 * v127;
            let v155: L = v92 * v115;
            let v156: L = v154 - v155;
            let v157: L = v104 * v156;
            let v158: L = v95 * v115;
            let v159: L = v157 + v158;
            let v160: L = v110 * v113;
            let v161: L = v159 + v160;
            let v162: L = v99 * v127;
            let v163: L = v92 * v151;
            let v164: L = v162 + v163;
            let v165: L = v99 * v164;
            let v166: L = v161 + v165;
            let v167: L = v140 * v151;
            let v168: L = v166 + v167;
            let v169: L = v95 * v127;
            let v170: L = v92 * v156;
            let v171: L = v169 + v170;
            let v172: L = v126 * v113;
            let v173: L = v171 - v172;
            let v174: L = v99 * v115;
            let v175: L = v104 * v151;
            let v176: L = v174 + v175;
            let v177: L = v99 * v176;
            let v178: L = v173 - v177;
            (
                v0,
                v4,
                v5,
                v7,
                v10,
                v17,
                v23,
                v25,
                v28,
                v30,
                v33,
                v41,
                v43,
                v47,
                v48,
                v51,
                v53,
                v57,
                v65,
                v73,
                v76,
                v81,
                v82,
                v83,
                v85,
                v87,
                v92,
                v95,
                v99,
                v104,
                v110,
                v113,
                v115,
                v126,
                v127,
                v137,
                v140,
                v141,
                v147,
                v150,
                v151,
                v153,
                v164,
                v168,
                v176,
                v178,
            )
        };
        let (
            v182,
            v191,
            v195,
            v203,
            v211,
            v213,
            v218,
            v221,
            v223,
            v225,
            v227,
            v232,
            v236,
            v242,
            v248,
            v251,
            v255,
            v257,
            v267,
            v271,
            v272,
            v277,
            v278,
            v279,
            v296,
            v298,
            v312,
            v323,
            v329,
            v339,
            v345,
            v349,
            v352,
            v357,
        ) = {
            let v179: L = v137 * v151;
            let v180: L = v178 + v179;
            let v181: L = v147 * v150;
            let v182: L = v180 + v181;
            let v183: L = v140 * v127;
            let v184: L = v137 * v115;
            let v185: L = v183 - v184;
            let v186: L = v104 * v176;
            let v187: L = v185 - v186;
            let v188: L = v92 * v164;
            let v189: L = v187 - v188;
            let v190: L = v110 * v150;
            let v191: L = v189 - v190;
            let v192: L = v104 * v113;
            let v193: L = v92 * v192;
            let v194: L = v137 * v150;
            let v195: L = v193 + v194;
            let v196: L = v92 * v113;
            let v197: L = v99 * v150;
            let v198: L = v196 - v197;
            let v199: L = v92 * v198;
            let v200: L = v104 * v192;
            let v201: L = v199 - v200;
            let v202: L = v140 * v150;
            let v203: L = v201 - v202;
            let v204: L = v99 * v192;
            let v205: L = v137 * v113;
            let v206: L = v204 + v205;
            let v207: L = v104 * v150;
            let v208: L = v92 * v207;
            let v209: L = v206 - v208;
            let v210: L = v95 * v150;
            let v211: L = v209 + v210;
            let v212: L = v104 * v198;
            let v213: L = -v212;
            let v214: L = v99 * v198;
            let v215: L = v140 * v113;
            let v216: L = v214 - v215;
            let v217: L = v104 * v207;
            let v218: L = v216 + v217;
            let v219: L = v95 * v113;
            let v220: L = v99 * v207;
            let v221: L = v219 - v220;
            let v222: L = q[3];
            let (v223, v225): (L, L) = L::sincos(v222);
            let v224: L = v223 * v92;
            let v226: L = v225 * v104;
            let v227: L = v224 + v226;
            let v228: L = v5 * v227;
            let v229: L = v227 * v228;
            let v230: L = v225 * v92;
            let v231: L = v223 * v104;
            let v232: L = v230 - v231;
            let v233: L = v5 * v232;
            let v234: L = v232 * v233;
            let v235: L = v229 + v234;
            let v236: L = v147 - v235;
            let v237: L = v236 * v151;
            let v238: L = v225 * v126;
            let v239: L = v223 * v110;
            let v240: L = v238 + v239;
            let v241: L = qd[3];
            let v242: L = v99 + v241;
            let v243: L = v242 * v233;
            let v244: L = v223 * v137;
            let v245: L = v225 * v140;
            let v246: L = v244 + v245;
            let v247: L = v232 * v241;
            let v248: L = v246 + v247;
            let v249: L = v5 * v248;
            let v250: L = v243 - v249;
            let v251: L = v240 + v250;
            let v252: L = v223 * v115;
            let v253: L = v225 * v127;
            let v254: L = v252 - v253;
            let v255: L = v223 * v150;
            let v256: L = v5 * v255;
            let v257: L = v254 - v256;
            let v258: L = v251 * v257;
            let v259: L = v237 + v258;
            let v260: L = v223 * v126;
            let v261: L = v225 * v110;
            let v262: L = v260 - v261;
            let v263: L = v225 * v137;
            let v264: L = v223 * v140;
            let v265: L = v263 - v264;
            let v266: L = v227 * v241;
            let v267: L = v265 - v266;
            let v268: L = v5 * v267;
            let v269: L = v242 * v228;
            let v270: L = v268 + v269;
            let v271: L = v262 + v270;
            let v272: L = v225 * v150;
            let v273: L = v5 * v272;
            let v274: L = v223 * v127;
            let v275: L = v225 * v115;
            let v276: L = v274 + v275;
            let v277: L = v273 - v276;
            let v278: L = v271 * v277;
            let v279: L = v259 + v278;
            let v280: L = v248 * v151;
            let v281: L = v271 * v113;
            let v282: L = v280 - v281;
            let v283: L = v242 * v257;
            let v284: L = v232 * v151;
            let v285: L = v283 - v284;
            let v286: L = v242 * v285;
            let v287: L = v282 - v286;
            let v288: L = v236 * v255;
            let v289: L = v287 + v288;
            let v290: L = v232 * v277;
            let v291: L = v227 * v257;
            let v292: L = v290 - v291;
            let v293: L = v227 * v292;
            let v294: L = v289 + v293;
            let v295: L = qdd[3];
            let v296: L = v95 + v295;
            let v297: L = v296 * v277;
            let v298: L = v294 - v297;
            let v299: L = v232 * v285;
            let v300: L = v248 * v257;
            let v301: L = v299 - v300;
            let v302: L = v251 * v255;
            let v303: L = v301 - v302;
            let v304: L = v227 * v151;
            let v305: L = v242 * v277;
            let v306: L = v304 - v305;
            let v307: L = v227 * v306;
            let v308: L = v303 - v307;
            let v309: L = v267 * v277;
            let v310: L = v308 + v309;
            let v311: L = v271 * v272;
            let v312: L = v310 + v311;
            let v313: L = v251 * v113;
            let v314: L = v267 * v151;
            let v315: L = v313 - v314;
            let v316: L = v296 * v257;
            let v317: L = v315 + v316;
            let v318: L = v242 * v306;
            let v319: L = v317 + v318;
            let v320: L = v232 * v292;
            let v321: L = v319 - v320;
            let v322: L = v236 * v272;
            let v323: L = v321 - v322;
            let v324: L = v227 * v113;
            let v325: L = v242 * v255;
            let v326: L = v324 - v325;
            let v327: L = v232 * v326;
            let v328: L = v267 * v272;
            let v329: L = v327 + v328;
            let v330: L = v267 * v113;
            let v331: L = v242 * v326;
            let v332: L = v330 + v331;
            let v333: L = v232 * v255;
            let v334: L = v227 * v272;
            let v335: L = v333 - v334;
            let v336: L = v232 * v335;
            let v337: L = v332 + v336;
            let v338: L = v296 * v272;
            let v339: L = v337 + v338;
            let v340: L = v227 * v326;
            let v341: L = v267 * v255;
            let v342: L = v340 + v341;
            let v343: L = v242 * v272;
            let v344: L = v232 * v113;
            let v345: L = v343 - v344;
            let v346: L = v232 * v345;
            let v347: L = v342 + v346;
            let v348: L = v248 * v272;
            let v349: L = v347 + v348;
            let v350: L = v296 * v113;
            let v351: L = v242 * v335;
            let v352: L = v350 + v351;
            let v353: L = v248 * v113;
            let v354: L = v296 * v255;
            let v355: L = v353 + v354;
            let v356: L = v227 * v335;
            let v357: L = v355 + v356;
            (
                v182,
                v191,
                v195,
                v203,
                v211,
                v213,
                v218,
                v221,
                v223,
                v225,
                v227,
                v232,
                v236,
                v242,
                v248,
                v251,
                v255,
                v257,
                v267,
                v271,
                v272,
                v277,
                v278,
                v279,
                v296,
                v298,
                v312,
                v323,
                v329,
                v339,
                v345,
                v349,
                v352,
                v357,
            )
        };
        let (
            v359,
            v362,
            v364,
            v366,
            v368,
            v371,
            v375,
            v381,
            v383,
            v387,
            v390,
            v399,
            v409,
            v414,
            v416,
            v421,
            v436,
            v438,
            v449,
            v455,
            v465,
            v475,
            v478,
            v485,
            v488,
            v490,
            v492,
            v494,
            v497,
            v502,
            v505,
            v507,
            v513,
            v514,
            v516,
            v519,
            v522,
            v525,
            v530,
            v533,
            v535,
            v536,
        ) = {
            let v358: L = v242 * v345;
            let v359: L = v357 + v358;
            let v360: L = v248 * v255;
            let v361: L = v227 * v345;
            let v362: L = v360 + v361;
            let v363: L = q[4];
            let (v366, v364): (L, L) = L::sincos(v363);
            let v365: L = v364 * v236;
            let v367: L = v366 * v251;
            let v368: L = v365 - v367;
            let v369: L = v364 * v151;
            let v370: L = v366 * v257;
            let v371: L = v369 - v370;
            let v372: L = v368 * v371;
            let v373: L = v364 * v251;
            let v374: L = v366 * v236;
            let v375: L = v373 + v374;
            let v376: L = v366 * v151;
            let v377: L = v364 * v257;
            let v378: L = v376 + v377;
            let v379: L = v375 * v378;
            let v380: L = v372 + v379;
            let v381: L = v380 + v278;
            let v382: L = qdd[4];
            let v383: L = v248 + v382;
            let v384: L = v383 * v371;
            let v385: L = v364 * v242;
            let v386: L = v366 * v232;
            let v387: L = v385 - v386;
            let v388: L = v364 * v232;
            let v389: L = v366 * v242;
            let v390: L = v388 + v389;
            let v391: L = v390 * v371;
            let v392: L = v387 * v378;
            let v393: L = v391 - v392;
            let v394: L = v387 * v393;
            let v395: L = v384 + v394;
            let v396: L = v368 * v255;
            let v397: L = v395 + v396;
            let v398: L = qd[4];
            let v399: L = v227 + v398;
            let v400: L = v390 * v277;
            let v401: L = v399 * v378;
            let v402: L = v400 - v401;
            let v403: L = v399 * v402;
            let v404: L = v397 + v403;
            let v405: L = v364 * v296;
            let v406: L = v366 * v267;
            let v407: L = v405 - v406;
            let v408: L = v390 * v398;
            let v409: L = v407 - v408;
            let v410: L = v409 * v277;
            let v411: L = v404 - v410;
            let v412: L = v364 * v113;
            let v413: L = v366 * v272;
            let v414: L = v412 - v413;
            let v415: L = v271 * v414;
            let v416: L = v411 - v415;
            let v417: L = v364 * v267;
            let v418: L = v366 * v296;
            let v419: L = v417 + v418;
            let v420: L = v387 * v398;
            let v421: L = v419 + v420;
            let v422: L = v421 * v371;
            let v423: L = v409 * v378;
            let v424: L = v422 - v423;
            let v425: L = v390 * v402;
            let v426: L = v424 + v425;
            let v427: L = v387 * v277;
            let v428: L = v399 * v371;
            let v429: L = v427 - v428;
            let v430: L = v387 * v429;
            let v431: L = v426 + v430;
            let v432: L = v375 * v414;
            let v433: L = v431 - v432;
            let v434: L = v366 * v113;
            let v435: L = v364 * v272;
            let v436: L = v434 + v435;
            let v437: L = v368 * v436;
            let v438: L = v433 + v437;
            let v439: L = v399 * v429;
            let v440: L = v390 * v393;
            let v441: L = v383 * v378;
            let v442: L = v440 + v441;
            let v443: L = v375 * v255;
            let v444: L = v442 + v443;
            let v445: L = v439 - v444;
            let v446: L = v421 * v277;
            let v447: L = v445 + v446;
            let v448: L = v271 * v436;
            let v449: L = v447 + v448;
            let v450: L = v399 * v414;
            let v451: L = v387 * v255;
            let v452: L = v450 - v451;
            let v453: L = v390 * v452;
            let v454: L = v421 * v436;
            let v455: L = v453 + v454;
            let v456: L = v390 * v414;
            let v457: L = v387 * v436;
            let v458: L = v456 - v457;
            let v459: L = v390 * v458;
            let v460: L = v421 * v255;
            let v461: L = v399 * v452;
            let v462: L = v460 + v461;
            let v463: L = v459 - v462;
            let v464: L = v383 * v436;
            let v465: L = v463 - v464;
            let v466: L = v387 * v452;
            let v467: L = v421 * v414;
            let v468: L = v466 + v467;
            let v469: L = v390 * v255;
            let v470: L = v399 * v436;
            let v471: L = v469 - v470;
            let v472: L = v390 * v471;
            let v473: L = v468 + v472;
            let v474: L = v409 * v436;
            let v475: L = v473 + v474;
            let v476: L = v383 * v255;
            let v477: L = v399 * v458;
            let v478: L = v476 - v477;
            let v479: L = v387 * v458;
            let v480: L = v409 * v255;
            let v481: L = v383 * v414;
            let v482: L = v480 + v481;
            let v483: L = v479 - v482;
            let v484: L = v399 * v471;
            let v485: L = v483 - v484;
            let v486: L = v409 * v414;
            let v487: L = v387 * v471;
            let v488: L = v486 + v487;
            let v489: L = q[5];
            let (v490, v492): (L, L) = L::sincos(v489);
            let v491: L = v490 * v375;
            let v493: L = v492 * v271;
            let v494: L = v491 + v493;
            let v495: L = v490 * v378;
            let v496: L = v492 * v277;
            let v497: L = v495 + v496;
            let v498: L = v494 * v497;
            let v499: L = v372 + v498;
            let v500: L = v492 * v375;
            let v501: L = v490 * v271;
            let v502: L = v500 - v501;
            let v503: L = v492 * v378;
            let v504: L = v490 * v277;
            let v505: L = v503 - v504;
            let v506: L = v502 * v505;
            let v507: L = v499 + v506;
            let v508: L = v490 * v421;
            let v509: L = v492 * v383;
            let v510: L = v508 + v509;
            let v511: L = v492 * v390;
            let v512: L = v490 * v399;
            let v513: L = v511 - v512;
            let v514: L = qd[5];
            let v515: L = v513 * v514;
            let v516: L = v510 + v515;
            let v517: L = v516 * v371;
            let v518: L = qdd[5];
            let v519: L = v409 + v518;
            let v520: L = v519 * v497;
            let v521: L = v517 - v520;
            let v522: L = v387 + v514;
            let v523: L = v513 * v371;
            let v524: L = v522 * v505;
            let v525: L = v523 - v524;
            let v526: L = v522 * v525;
            let v527: L = v521 + v526;
            let v528: L = v490 * v390;
            let v529: L = v492 * v399;
            let v530: L = v528 + v529;
            let v531: L = v513 * v497;
            let v532: L = v530 * v505;
            let v533: L = v531 - v532;
            let v534: L = v530 * v533;
            let v535: L = v527 + v534;
            let v536: L = v494 * v414;
            (
                v359,
                v362,
                v364,
                v366,
                v368,
                v371,
                v375,
                v381,
                v383,
                v387,
                v390,
                v399,
                v409,
                v414,
                v416,
                v421,
                v436,
                v438,
                v449,
                v455,
                v465,
                v475,
                v478,
                v485,
                v488,
                v490,
                v492,
                v494,
                v497,
                v502,
                v505,
                v507,
                v513,
                v514,
                v516,
                v519,
                v522,
                v525,
                v530,
                v533,
                v535,
                v536,
            )
        };
        let (
            v542,
            v547,
            v564,
            v575,
            v581,
            v591,
            v601,
            v604,
            v611,
            v614,
            v615,
            v620,
            v623,
            v626,
            v628,
            v631,
            v632,
            v636,
            v638,
            v648,
            v656,
            v663,
            v665,
            v667,
            v670,
            v673,
            v674,
            v677,
            v678,
            v682,
            v683,
            v684,
            v685,
            v692,
            v696,
            v700,
            v704,
            v708,
            v713,
            v714,
            v715,
        ) = {
            let v537: L = v535 - v536;
            let v538: L = v492 * v255;
            let v539: L = v490 * v436;
            let v540: L = v538 + v539;
            let v541: L = v368 * v540;
            let v542: L = v537 + v541;
            let v543: L = v492 * v421;
            let v544: L = v490 * v383;
            let v545: L = v543 - v544;
            let v546: L = v530 * v514;
            let v547: L = v545 - v546;
            let v548: L = v547 * v371;
            let v549: L = v522 * v497;
            let v550: L = v530 * v371;
            let v551: L = v549 - v550;
            let v552: L = v522 * v551;
            let v553: L = v548 + v552;
            let v554: L = v513 * v533;
            let v555: L = v553 + v554;
            let v556: L = v519 * v505;
            let v557: L = v555 - v556;
            let v558: L = v502 * v414;
            let v559: L = v557 - v558;
            let v560: L = v492 * v436;
            let v561: L = v490 * v255;
            let v562: L = v560 - v561;
            let v563: L = v368 * v562;
            let v564: L = v559 + v563;
            let v565: L = v530 * v551;
            let v566: L = v547 * v497;
            let v567: L = v565 + v566;
            let v568: L = v513 * v525;
            let v569: L = v567 - v568;
            let v570: L = v516 * v505;
            let v571: L = v569 - v570;
            let v572: L = v502 * v540;
            let v573: L = v571 - v572;
            let v574: L = v494 * v562;
            let v575: L = v573 + v574;
            let v576: L = v530 * v414;
            let v577: L = v522 * v540;
            let v578: L = v576 - v577;
            let v579: L = v513 * v578;
            let v580: L = v547 * v562;
            let v581: L = v579 + v580;
            let v582: L = v513 * v414;
            let v583: L = v522 * v562;
            let v584: L = v582 - v583;
            let v585: L = v513 * v584;
            let v586: L = v530 * v578;
            let v587: L = v547 * v540;
            let v588: L = v586 + v587;
            let v589: L = v585 - v588;
            let v590: L = v516 * v562;
            let v591: L = v589 - v590;
            let v592: L = v547 * v414;
            let v593: L = v522 * v578;
            let v594: L = v592 + v593;
            let v595: L = v513 * v540;
            let v596: L = v530 * v562;
            let v597: L = v595 - v596;
            let v598: L = v513 * v597;
            let v599: L = v594 + v598;
            let v600: L = v519 * v562;
            let v601: L = v599 + v600;
            let v602: L = v516 * v540;
            let v603: L = v530 * v584;
            let v604: L = v602 - v603;
            let v605: L = v522 * v584;
            let v606: L = v516 * v414;
            let v607: L = v519 * v540;
            let v608: L = v606 + v607;
            let v609: L = v605 - v608;
            let v610: L = v530 * v597;
            let v611: L = v609 - v610;
            let v612: L = v519 * v414;
            let v613: L = v522 * v597;
            let v614: L = v612 + v613;
            let v615: L = v5 * v51;
            let v616: L = -L::splat(0.4318_f64);
            let v617: L = v616 * v4;
            let v618: L = v25 * v617;
            let v619: L = v48 - v618;
            let v620: L = v619 + v51;
            let v621: L = v4 * v617;
            let v622: L = v621 - v43;
            let v623: L = v622 - v41;
            let v624: L = v616 * v30;
            let v625: L = v25 * v7;
            let v626: L = v624 + v625;
            let v627: L = v4 * v25;
            let v628: L = -v627;
            let v629: L = v4 * v4;
            let v630: L = v25 * v25;
            let v631: L = v629 - v630;
            let v632: L = v25 * v4;
            let v633: L = v5 * v87;
            let v634: L = v126 * v633;
            let v635: L = v5 * v85;
            let v636: L = v635 + v83;
            let v637: L = v147 * v636;
            let v638: L = v634 + v637;
            let v639: L = v104 * v633;
            let v640: L = v104 * v639;
            let v641: L = v147 - v640;
            let v642: L = v92 * v636;
            let v643: L = v99 * v633;
            let v644: L = v642 - v643;
            let v645: L = v99 * v644;
            let v646: L = v641 + v645;
            let v647: L = v140 * v636;
            let v648: L = v646 + v647;
            let v649: L = v137 * v636;
            let v650: L = v95 * v633;
            let v651: L = v92 * v639;
            let v652: L = v650 + v651;
            let v653: L = v104 * v636;
            let v654: L = v99 * v653;
            let v655: L = v652 + v654;
            let v656: L = v649 - v655;
            let v657: L = v140 * v633;
            let v658: L = v126 + v657;
            let v659: L = v104 * v653;
            let v660: L = v658 + v659;
            let v661: L = v92 * v644;
            let v662: L = v660 + v661;
            let v663: L = -v662;
            let v664: L = v92 * v99;
            let v665: L = -v664;
            let v666: L = v104 * v99;
            let v667: L = v666 - v137;
            let v668: L = v92 * v92;
            let v669: L = v99 * v99;
            let v670: L = v668 - v669;
            let v671: L = v104 * v92;
            let v672: L = v95 + v671;
            let v673: L = -v672;
            let v674: L = v99 * v92;
            let v675: L = v236 * v636;
            let v676: L = v225 * v633;
            let v677: L = v5 * v225;
            let v678: L = v676 - v677;
            let v679: L = v251 * v678;
            let v680: L = v675 + v679;
            let v681: L = v223 * v633;
            let v682: L = v5 * v223;
            let v683: L = v681 - v682;
            let v684: L = v271 * v683;
            let v685: L = v680 + v684;
            let v686: L = v248 * v636;
            let v687: L = v242 * v678;
            let v688: L = v232 * v636;
            let v689: L = v687 - v688;
            let v690: L = v242 * v689;
            let v691: L = v686 - v690;
            let v692: L = v236 * v225;
            let v693: L = v691 + v692;
            let v694: L = v232 * v683;
            let v695: L = v227 * v678;
            let v696: L = v694 - v695;
            let v697: L = v227 * v696;
            let v698: L = v693 + v697;
            let v699: L = v296 * v683;
            let v700: L = v698 - v699;
            let v701: L = v232 * v689;
            let v702: L = v248 * v678;
            let v703: L = v701 - v702;
            let v704: L = v251 * v225;
            let v705: L = v703 - v704;
            let v706: L = v227 * v636;
            let v707: L = v242 * v683;
            let v708: L = v706 - v707;
            let v709: L = v227 * v708;
            let v710: L = v705 - v709;
            let v711: L = v267 * v683;
            let v712: L = v710 + v711;
            let v713: L = v271 * v223;
            let v714: L = v712 - v713;
            let v715: L = v296 * v678;
            (
                v542,
                v547,
                v564,
                v575,
                v581,
                v591,
                v601,
                v604,
                v611,
                v614,
                v615,
                v620,
                v623,
                v626,
                v628,
                v631,
                v632,
                v636,
                v638,
                v648,
                v656,
                v663,
                v665,
                v667,
                v670,
                v673,
                v674,
                v677,
                v678,
                v682,
                v683,
                v684,
                v685,
                v692,
                v696,
                v700,
                v704,
                v708,
                v713,
                v714,
                v715,
            )
        };
        let (
            v722,
            v723,
            v728,
            v736,
            v744,
            v745,
            v750,
            v753,
            v763,
            v770,
            v779,
            v780,
            v781,
            v792,
            v795,
            v796,
            v801,
            v806,
            v807,
            v813,
            v823,
            v833,
            v836,
            v843,
            v846,
            v849,
            v854,
            v856,
            v862,
            v870,
            v874,
            v875,
            v876,
            v887,
            v891,
            v892,
            v893,
            v894,
        ) = {
            let v716: L = v267 * v636;
            let v717: L = v715 - v716;
            let v718: L = v242 * v708;
            let v719: L = v717 + v718;
            let v720: L = v232 * v696;
            let v721: L = v719 - v720;
            let v722: L = v236 * v223;
            let v723: L = v721 + v722;
            let v724: L = v242 * v225;
            let v725: L = v232 * v724;
            let v726: L = v267 * v223;
            let v727: L = v725 + v726;
            let v728: L = -v727;
            let v729: L = v232 * v225;
            let v730: L = v227 * v223;
            let v731: L = v729 + v730;
            let v732: L = v232 * v731;
            let v733: L = v242 * v724;
            let v734: L = v732 - v733;
            let v735: L = v296 * v223;
            let v736: L = v734 - v735;
            let v737: L = v267 * v225;
            let v738: L = v227 * v724;
            let v739: L = v737 - v738;
            let v740: L = v242 * v223;
            let v741: L = v232 * v740;
            let v742: L = v739 - v741;
            let v743: L = v248 * v223;
            let v744: L = v742 - v743;
            let v745: L = v242 * v731;
            let v746: L = v296 * v225;
            let v747: L = v227 * v731;
            let v748: L = v746 + v747;
            let v749: L = v242 * v740;
            let v750: L = v748 - v749;
            let v751: L = v248 * v225;
            let v752: L = v227 * v740;
            let v753: L = v751 - v752;
            let v754: L = v364 * v636;
            let v755: L = v366 * v678;
            let v756: L = v754 - v755;
            let v757: L = v368 * v756;
            let v758: L = v366 * v636;
            let v759: L = v364 * v678;
            let v760: L = v758 + v759;
            let v761: L = v375 * v760;
            let v762: L = v757 + v761;
            let v763: L = v762 + v684;
            let v764: L = v383 * v756;
            let v765: L = v390 * v756;
            let v766: L = v387 * v760;
            let v767: L = v765 - v766;
            let v768: L = v387 * v767;
            let v769: L = v764 + v768;
            let v770: L = v368 * v225;
            let v771: L = v769 + v770;
            let v772: L = v390 * v683;
            let v773: L = v399 * v760;
            let v774: L = v772 - v773;
            let v775: L = v399 * v774;
            let v776: L = v771 + v775;
            let v777: L = v409 * v683;
            let v778: L = v776 - v777;
            let v779: L = v366 * v223;
            let v780: L = v271 * v779;
            let v781: L = v778 - v780;
            let v782: L = v421 * v756;
            let v783: L = v409 * v760;
            let v784: L = v782 - v783;
            let v785: L = v390 * v774;
            let v786: L = v784 + v785;
            let v787: L = v387 * v683;
            let v788: L = v399 * v756;
            let v789: L = v787 - v788;
            let v790: L = v387 * v789;
            let v791: L = v786 + v790;
            let v792: L = v375 * v779;
            let v793: L = v791 - v792;
            let v794: L = v364 * v223;
            let v795: L = v368 * v794;
            let v796: L = v793 - v795;
            let v797: L = v399 * v789;
            let v798: L = v390 * v767;
            let v799: L = v383 * v760;
            let v800: L = v798 + v799;
            let v801: L = v375 * v225;
            let v802: L = v800 + v801;
            let v803: L = v797 - v802;
            let v804: L = v421 * v683;
            let v805: L = v803 + v804;
            let v806: L = v271 * v794;
            let v807: L = v805 - v806;
            let v808: L = v399 * v779;
            let v809: L = v387 * v225;
            let v810: L = v808 - v809;
            let v811: L = v390 * v810;
            let v812: L = v421 * v794;
            let v813: L = v811 - v812;
            let v814: L = v390 * v779;
            let v815: L = v387 * v794;
            let v816: L = v814 + v815;
            let v817: L = v390 * v816;
            let v818: L = v421 * v225;
            let v819: L = v399 * v810;
            let v820: L = v818 + v819;
            let v821: L = v817 - v820;
            let v822: L = v383 * v794;
            let v823: L = v821 + v822;
            let v824: L = v387 * v810;
            let v825: L = v421 * v779;
            let v826: L = v824 + v825;
            let v827: L = v390 * v225;
            let v828: L = v399 * v794;
            let v829: L = v827 + v828;
            let v830: L = v390 * v829;
            let v831: L = v826 + v830;
            let v832: L = v409 * v794;
            let v833: L = v831 - v832;
            let v834: L = v383 * v225;
            let v835: L = v399 * v816;
            let v836: L = v834 - v835;
            let v837: L = v387 * v816;
            let v838: L = v409 * v225;
            let v839: L = v383 * v779;
            let v840: L = v838 + v839;
            let v841: L = v837 - v840;
            let v842: L = v399 * v829;
            let v843: L = v841 - v842;
            let v844: L = v409 * v779;
            let v845: L = v387 * v829;
            let v846: L = v844 + v845;
            let v847: L = v490 * v760;
            let v848: L = v492 * v683;
            let v849: L = v847 + v848;
            let v850: L = v494 * v849;
            let v851: L = v757 + v850;
            let v852: L = v492 * v760;
            let v853: L = v490 * v683;
            let v854: L = v852 - v853;
            let v855: L = v502 * v854;
            let v856: L = v851 + v855;
            let v857: L = v516 * v756;
            let v858: L = v519 * v849;
            let v859: L = v857 - v858;
            let v860: L = v513 * v756;
            let v861: L = v522 * v854;
            let v862: L = v860 - v861;
            let v863: L = v522 * v862;
            let v864: L = v859 + v863;
            let v865: L = v513 * v849;
            let v866: L = v530 * v854;
            let v867: L = v865 - v866;
            let v868: L = v530 * v867;
            let v869: L = v864 + v868;
            let v870: L = v494 * v779;
            let v871: L = v869 - v870;
            let v872: L = v490 * v794;
            let v873: L = v492 * v225;
            let v874: L = v872 - v873;
            let v875: L = v368 * v874;
            let v876: L = v871 - v875;
            let v877: L = v547 * v756;
            let v878: L = v522 * v849;
            let v879: L = v530 * v756;
            let v880: L = v878 - v879;
            let v881: L = v522 * v880;
            let v882: L = v877 + v881;
            let v883: L = v513 * v867;
            let v884: L = v882 + v883;
            let v885: L = v519 * v854;
            let v886: L = v884 - v885;
            let v887: L = v502 * v779;
            let v888: L = v886 - v887;
            let v889: L = v490 * v225;
            let v890: L = v492 * v794;
            let v891: L = v889 + v890;
            let v892: L = v368 * v891;
            let v893: L = v888 - v892;
            let v894: L = v530 * v880;
            (
                v722,
                v723,
                v728,
                v736,
                v744,
                v745,
                v750,
                v753,
                v763,
                v770,
                v779,
                v780,
                v781,
                v792,
                v795,
                v796,
                v801,
                v806,
                v807,
                v813,
                v823,
                v833,
                v836,
                v843,
                v846,
                v849,
                v854,
                v856,
                v862,
                v870,
                v874,
                v875,
                v876,
                v887,
                v891,
                v892,
                v893,
                v894,
            )
        };
        let (
            v901,
            v903,
            v904,
            v910,
            v920,
            v930,
            v934,
            v941,
            v944,
            v945,
            v949,
            v954,
            v958,
            v963,
            v977,
            v989,
            v997,
            v1007,
            v1022,
            v1034,
            v1044,
            v1047,
            v1052,
            v1054,
            v1060,
            v1065,
            v1069,
            v1070,
            v1073,
        ) = {
            let v895: L = v547 * v849;
            let v896: L = v894 + v895;
            let v897: L = v513 * v862;
            let v898: L = v896 - v897;
            let v899: L = v516 * v854;
            let v900: L = v898 - v899;
            let v901: L = v502 * v874;
            let v902: L = v900 + v901;
            let v903: L = v494 * v891;
            let v904: L = v902 - v903;
            let v905: L = v530 * v779;
            let v906: L = v522 * v874;
            let v907: L = v905 + v906;
            let v908: L = v513 * v907;
            let v909: L = v547 * v891;
            let v910: L = v908 - v909;
            let v911: L = v547 * v874;
            let v912: L = v530 * v907;
            let v913: L = v911 - v912;
            let v914: L = v513 * v779;
            let v915: L = v522 * v891;
            let v916: L = v914 + v915;
            let v917: L = v513 * v916;
            let v918: L = v913 + v917;
            let v919: L = v516 * v891;
            let v920: L = v918 + v919;
            let v921: L = v547 * v779;
            let v922: L = v522 * v907;
            let v923: L = v921 + v922;
            let v924: L = v530 * v891;
            let v925: L = v513 * v874;
            let v926: L = v924 - v925;
            let v927: L = v513 * v926;
            let v928: L = v923 + v927;
            let v929: L = v519 * v891;
            let v930: L = v928 - v929;
            let v931: L = v516 * v874;
            let v932: L = v530 * v916;
            let v933: L = v931 + v932;
            let v934: L = -v933;
            let v935: L = v519 * v874;
            let v936: L = v516 * v779;
            let v937: L = v935 - v936;
            let v938: L = v522 * v916;
            let v939: L = v937 + v938;
            let v940: L = v530 * v926;
            let v941: L = v939 - v940;
            let v942: L = v519 * v779;
            let v943: L = v522 * v926;
            let v944: L = v942 + v943;
            let v945: L = v83 * v147;
            let v946: L = v83 * v92;
            let v947: L = v99 * v946;
            let v948: L = v147 + v947;
            let v949: L = v948 + v141;
            let v950: L = -L::splat(0.0203_f64);
            let v951: L = v950 * v104;
            let v952: L = v99 * v951;
            let v953: L = v83 * v137;
            let v954: L = v952 + v953;
            let v955: L = v104 * v951;
            let v956: L = v955 - v126;
            let v957: L = v92 * v946;
            let v958: L = v956 - v957;
            let v959: L = v83 * v236;
            let v960: L = v251 * v677;
            let v961: L = v959 - v960;
            let v962: L = v271 * v682;
            let v963: L = v961 - v962;
            let v964: L = v83 * v248;
            let v965: L = v950 * v232;
            let v966: L = v242 * v677;
            let v967: L = v965 - v966;
            let v968: L = v242 * v967;
            let v969: L = v964 - v968;
            let v970: L = v969 + v692;
            let v971: L = v227 * v677;
            let v972: L = v232 * v682;
            let v973: L = v971 - v972;
            let v974: L = v227 * v973;
            let v975: L = v970 + v974;
            let v976: L = v296 * v682;
            let v977: L = v975 + v976;
            let v978: L = v232 * v967;
            let v979: L = v248 * v677;
            let v980: L = v978 + v979;
            let v981: L = v980 - v704;
            let v982: L = v83 * v227;
            let v983: L = v242 * v682;
            let v984: L = v982 + v983;
            let v985: L = v227 * v984;
            let v986: L = v981 - v985;
            let v987: L = v267 * v682;
            let v988: L = v986 - v987;
            let v989: L = v988 - v713;
            let v990: L = v950 * v267;
            let v991: L = v296 * v677;
            let v992: L = v990 - v991;
            let v993: L = v242 * v984;
            let v994: L = v992 + v993;
            let v995: L = v232 * v973;
            let v996: L = v994 - v995;
            let v997: L = v996 + v722;
            let v998: L = v83 * v364;
            let v999: L = v366 * v677;
            let v1000: L = v998 + v999;
            let v1001: L = v368 * v1000;
            let v1002: L = v83 * v366;
            let v1003: L = v364 * v677;
            let v1004: L = v1002 - v1003;
            let v1005: L = v375 * v1004;
            let v1006: L = v1001 + v1005;
            let v1007: L = v1006 - v962;
            let v1008: L = v383 * v1000;
            let v1009: L = v390 * v1000;
            let v1010: L = v387 * v1004;
            let v1011: L = v1009 - v1010;
            let v1012: L = v387 * v1011;
            let v1013: L = v1008 + v1012;
            let v1014: L = v1013 + v770;
            let v1015: L = v399 * v1004;
            let v1016: L = v390 * v682;
            let v1017: L = v1015 + v1016;
            let v1018: L = v399 * v1017;
            let v1019: L = v1014 - v1018;
            let v1020: L = v409 * v682;
            let v1021: L = v1019 + v1020;
            let v1022: L = v1021 - v780;
            let v1023: L = v421 * v1000;
            let v1024: L = v409 * v1004;
            let v1025: L = v1023 - v1024;
            let v1026: L = v390 * v1017;
            let v1027: L = v1025 - v1026;
            let v1028: L = v399 * v1000;
            let v1029: L = v387 * v682;
            let v1030: L = v1028 + v1029;
            let v1031: L = v387 * v1030;
            let v1032: L = v1027 - v1031;
            let v1033: L = v1032 - v792;
            let v1034: L = v1033 - v795;
            let v1035: L = v390 * v1011;
            let v1036: L = v383 * v1004;
            let v1037: L = v1035 + v1036;
            let v1038: L = v1037 + v801;
            let v1039: L = v399 * v1030;
            let v1040: L = v1038 + v1039;
            let v1041: L = v421 * v682;
            let v1042: L = v1040 + v1041;
            let v1043: L = v1042 + v806;
            let v1044: L = -v1043;
            let v1045: L = v492 * v682;
            let v1046: L = v490 * v1004;
            let v1047: L = v1045 - v1046;
            let v1048: L = v494 * v1047;
            let v1049: L = v1001 - v1048;
            let v1050: L = v492 * v1004;
            let v1051: L = v490 * v682;
            let v1052: L = v1050 + v1051;
            let v1053: L = v502 * v1052;
            let v1054: L = v1049 + v1053;
            let v1055: L = v516 * v1000;
            let v1056: L = v519 * v1047;
            let v1057: L = v1055 + v1056;
            let v1058: L = v513 * v1000;
            let v1059: L = v522 * v1052;
            let v1060: L = v1058 - v1059;
            let v1061: L = v522 * v1060;
            let v1062: L = v1057 + v1061;
            let v1063: L = v513 * v1047;
            let v1064: L = v530 * v1052;
            let v1065: L = v1063 + v1064;
            let v1066: L = v530 * v1065;
            let v1067: L = v1062 - v1066;
            let v1068: L = v1067 - v870;
            let v1069: L = v1068 - v875;
            let v1070: L = v547 * v1000;
            let v1071: L = v530 * v1000;
            let v1072: L = v522 * v1047;
            let v1073: L = v1071 + v1072;
            (
                v901,
                v903,
                v904,
                v910,
                v920,
                v930,
                v934,
                v941,
                v944,
                v945,
                v949,
                v954,
                v958,
                v963,
                v977,
                v989,
                v997,
                v1007,
                v1022,
                v1034,
                v1044,
                v1047,
                v1052,
                v1054,
                v1060,
                v1065,
                v1069,
                v1070,
                v1073,
            )
        };
        let (
            v1081,
            v1090,
            v1091,
            v1092,
            v1094,
            v1097,
            v1099,
            v1101,
            v1103,
            v1106,
            v1107,
            v1111,
            v1119,
            v1127,
            v1129,
            v1134,
            v1137,
            v1141,
            v1145,
            v1148,
            v1154,
            v1164,
            v1174,
            v1177,
            v1184,
            v1187,
            v1188,
            v1190,
            v1192,
            v1195,
            v1198,
            v1199,
            v1200,
            v1202,
            v1206,
            v1211,
            v1219,
            v1227,
            v1230,
            v1235,
            v1236,
            v1237,
            v1238,
            v1239,
            v1242,
            v1244,
            v1246,
            v1248,
            v1249,
        ) = {
            let v1074: L = v522 * v1073;
            let v1075: L = v1070 - v1074;
            let v1076: L = v513 * v1065;
            let v1077: L = v1075 - v1076;
            let v1078: L = v519 * v1052;
            let v1079: L = v1077 - v1078;
            let v1080: L = v1079 - v887;
            let v1081: L = v1080 - v892;
            let v1082: L = v530 * v1073;
            let v1083: L = v547 * v1047;
            let v1084: L = v1082 + v1083;
            let v1085: L = v513 * v1060;
            let v1086: L = v1084 + v1085;
            let v1087: L = v516 * v1052;
            let v1088: L = v1086 + v1087;
            let v1089: L = v901 - v1088;
            let v1090: L = v1089 - v903;
            let v1091: L = -v271;
            let v1092: L = v232 * v227;
            let v1093: L = v242 * v227;
            let v1094: L = v267 + v1093;
            let v1095: L = v227 * v227;
            let v1096: L = v232 * v232;
            let v1097: L = v1095 - v1096;
            let v1098: L = v242 * v232;
            let v1099: L = v248 - v1098;
            let v1100: L = v227 * v232;
            let v1101: L = -v1100;
            let v1102: L = v271 * v364;
            let v1103: L = -v1102;
            let v1104: L = v368 * v366;
            let v1105: L = v375 * v364;
            let v1106: L = v1104 - v1105;
            let v1107: L = v271 * v366;
            let v1108: L = v399 * v364;
            let v1109: L = v390 * v1108;
            let v1110: L = v421 * v366;
            let v1111: L = v1109 + v1110;
            let v1112: L = v390 * v364;
            let v1113: L = v387 * v366;
            let v1114: L = v1112 - v1113;
            let v1115: L = v390 * v1114;
            let v1116: L = v399 * v1108;
            let v1117: L = v1115 - v1116;
            let v1118: L = v383 * v366;
            let v1119: L = v1117 - v1118;
            let v1120: L = v387 * v1108;
            let v1121: L = v421 * v364;
            let v1122: L = v1120 + v1121;
            let v1123: L = v399 * v366;
            let v1124: L = v390 * v1123;
            let v1125: L = v1122 - v1124;
            let v1126: L = v409 * v366;
            let v1127: L = v1125 + v1126;
            let v1128: L = v399 * v1114;
            let v1129: L = -v1128;
            let v1130: L = v387 * v1114;
            let v1131: L = v383 * v364;
            let v1132: L = v1130 - v1131;
            let v1133: L = v399 * v1123;
            let v1134: L = v1132 + v1133;
            let v1135: L = v409 * v364;
            let v1136: L = v387 * v1123;
            let v1137: L = v1135 - v1136;
            let v1138: L = v490 * v366;
            let v1139: L = v368 * v1138;
            let v1140: L = v494 * v364;
            let v1141: L = v1139 - v1140;
            let v1142: L = v492 * v366;
            let v1143: L = v368 * v1142;
            let v1144: L = v502 * v364;
            let v1145: L = v1143 - v1144;
            let v1146: L = v494 * v1142;
            let v1147: L = v502 * v1138;
            let v1148: L = v1146 - v1147;
            let v1149: L = v530 * v364;
            let v1150: L = v522 * v1138;
            let v1151: L = v1149 - v1150;
            let v1152: L = v513 * v1151;
            let v1153: L = v547 * v1142;
            let v1154: L = v1152 + v1153;
            let v1155: L = v513 * v364;
            let v1156: L = v522 * v1142;
            let v1157: L = v1155 - v1156;
            let v1158: L = v513 * v1157;
            let v1159: L = v530 * v1151;
            let v1160: L = v547 * v1138;
            let v1161: L = v1159 + v1160;
            let v1162: L = v1158 - v1161;
            let v1163: L = v516 * v1142;
            let v1164: L = v1162 - v1163;
            let v1165: L = v547 * v364;
            let v1166: L = v522 * v1151;
            let v1167: L = v1165 + v1166;
            let v1168: L = v513 * v1138;
            let v1169: L = v530 * v1142;
            let v1170: L = v1168 - v1169;
            let v1171: L = v513 * v1170;
            let v1172: L = v1167 + v1171;
            let v1173: L = v519 * v1142;
            let v1174: L = v1172 + v1173;
            let v1175: L = v516 * v1138;
            let v1176: L = v530 * v1157;
            let v1177: L = v1175 - v1176;
            let v1178: L = v522 * v1157;
            let v1179: L = v516 * v364;
            let v1180: L = v519 * v1138;
            let v1181: L = v1179 + v1180;
            let v1182: L = v1178 - v1181;
            let v1183: L = v530 * v1170;
            let v1184: L = v1182 - v1183;
            let v1185: L = v519 * v364;
            let v1186: L = v522 * v1170;
            let v1187: L = v1185 + v1186;
            let v1188: L = -v375;
            let v1189: L = v390 * v387;
            let v1190: L = -v1189;
            let v1191: L = v399 * v387;
            let v1192: L = v1191 - v421;
            let v1193: L = v390 * v390;
            let v1194: L = v387 * v387;
            let v1195: L = v1193 - v1194;
            let v1196: L = v399 * v390;
            let v1197: L = v409 + v1196;
            let v1198: L = -v1197;
            let v1199: L = v387 * v390;
            let v1200: L = v368 * v492;
            let v1201: L = v368 * v490;
            let v1202: L = -v1201;
            let v1203: L = v502 * v492;
            let v1204: L = v494 * v490;
            let v1205: L = v1203 + v1204;
            let v1206: L = -v1205;
            let v1207: L = v522 * v492;
            let v1208: L = v513 * v1207;
            let v1209: L = v547 * v490;
            let v1210: L = v1208 + v1209;
            let v1211: L = -v1210;
            let v1212: L = v530 * v1207;
            let v1213: L = v547 * v492;
            let v1214: L = v1212 - v1213;
            let v1215: L = v522 * v490;
            let v1216: L = v513 * v1215;
            let v1217: L = v1214 + v1216;
            let v1218: L = v516 * v490;
            let v1219: L = v1217 + v1218;
            let v1220: L = v513 * v492;
            let v1221: L = v530 * v490;
            let v1222: L = v1220 + v1221;
            let v1223: L = v513 * v1222;
            let v1224: L = v522 * v1207;
            let v1225: L = v1223 - v1224;
            let v1226: L = v519 * v490;
            let v1227: L = v1225 - v1226;
            let v1228: L = v516 * v492;
            let v1229: L = v530 * v1215;
            let v1230: L = v1228 - v1229;
            let v1231: L = v522 * v1215;
            let v1232: L = v519 * v492;
            let v1233: L = v1231 - v1232;
            let v1234: L = v530 * v1222;
            let v1235: L = v1233 - v1234;
            let v1236: L = v522 * v1222;
            let v1237: L = -v494;
            let v1238: L = -v502;
            let v1239: L = v513 * v530;
            let v1240: L = v513 * v513;
            let v1241: L = v530 * v530;
            let v1242: L = v1240 - v1241;
            let v1243: L = v522 * v530;
            let v1244: L = v547 + v1243;
            let v1245: L = v530 * v513;
            let v1246: L = -v1245;
            let v1247: L = v522 * v513;
            let v1248: L = v1247 - v516;
            let v1249: L = L::splat(0.0_f64);
            (
                v1081,
                v1090,
                v1091,
                v1092,
                v1094,
                v1097,
                v1099,
                v1101,
                v1103,
                v1106,
                v1107,
                v1111,
                v1119,
                v1127,
                v1129,
                v1134,
                v1137,
                v1141,
                v1145,
                v1148,
                v1154,
                v1164,
                v1174,
                v1177,
                v1184,
                v1187,
                v1188,
                v1190,
                v1192,
                v1195,
                v1198,
                v1199,
                v1200,
                v1202,
                v1206,
                v1211,
                v1219,
                v1227,
                v1230,
                v1235,
                v1236,
                v1237,
                v1238,
                v1239,
                v1242,
                v1244,
                v1246,
                v1248,
                v1249,
            )
        };
        [
            [
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v0,
                v1249,
                v1249,
                v17,
                v23,
                v33,
                v53,
                v57,
                v65,
                v73,
                v76,
                v81,
                v82,
                v153,
                v168,
                v182,
                v191,
                v195,
                v203,
                v211,
                v213,
                v218,
                v221,
                v279,
                v298,
                v312,
                v323,
                v329,
                v339,
                v349,
                v352,
                v359,
                v362,
                v381,
                v416,
                v438,
                v449,
                v455,
                v465,
                v475,
                v478,
                v485,
                v488,
                v507,
                v542,
                v564,
                v575,
                v581,
                v591,
                v601,
                v604,
                v611,
                v614,
            ],
            [
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v615,
                v620,
                v623,
                v626,
                v628,
                v631,
                v28,
                v632,
                v10,
                v47,
                v638,
                v648,
                v656,
                v663,
                v665,
                v667,
                v670,
                v140,
                v673,
                v674,
                v685,
                v700,
                v714,
                v723,
                v728,
                v736,
                v744,
                v745,
                v750,
                v753,
                v763,
                v781,
                v796,
                v807,
                v813,
                v823,
                v833,
                v836,
                v843,
                v846,
                v856,
                v876,
                v893,
                v904,
                v910,
                v920,
                v930,
                v934,
                v941,
                v944,
            ],
            [
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v945,
                v949,
                v954,
                v958,
                v665,
                v667,
                v670,
                v140,
                v673,
                v674,
                v963,
                v977,
                v989,
                v997,
                v728,
                v736,
                v744,
                v745,
                v750,
                v753,
                v1007,
                v1022,
                v1034,
                v1044,
                v813,
                v823,
                v833,
                v836,
                v843,
                v846,
                v1054,
                v1069,
                v1081,
                v1090,
                v910,
                v920,
                v930,
                v934,
                v941,
                v944,
            ],
            [
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1091,
                v1249,
                v251,
                v1092,
                v1094,
                v1097,
                v296,
                v1099,
                v1101,
                v1249,
                v1103,
                v1106,
                v1107,
                v1111,
                v1119,
                v1127,
                v1129,
                v1134,
                v1137,
                v1249,
                v1141,
                v1145,
                v1148,
                v1154,
                v1164,
                v1174,
                v1177,
                v1184,
                v1187,
            ],
            [
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v368,
                v1249,
                v1188,
                v1190,
                v1192,
                v1195,
                v383,
                v1198,
                v1199,
                v1249,
                v1200,
                v1202,
                v1206,
                v1211,
                v1219,
                v1227,
                v1230,
                v1235,
                v1236,
            ],
            [
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1249,
                v1237,
                v1238,
                v1249,
                v1239,
                v1242,
                v1244,
                v1246,
                v1248,
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
        let v0: L = L::splat(0.0_f64);
        let v1: L = L::splat(0.35_f64);
        let v2: L = L::splat(17.4_f64);
        let v3: L = -L::splat(6.33012_f64);
        let v4: L = L::splat(0.1044_f64);
        let v5: L = L::splat(3.9585_f64);
        let v6: L = L::splat(1.03118515_f64);
        let v7: L = L::splat(0.03798072_f64);
        let v8: L = L::splat(1.4401023_f64);
        let v9: L = L::splat(3.727456406_f64);
        let v10: L = -L::splat(0.023751_f64);
        let v11: L = L::splat(2.842524056_f64);
        let v12: L = L::splat(4.8_f64);
        let v13: L = -L::splat(0.09744_f64);
        let v14: L = -L::splat(0.06768_f64);
        let v15: L = L::splat(0.336_f64);
        let v16: L = L::splat(0.090474288_f64);
        let v17: L = -L::splat(0.001373904_f64);
        let v18: L = L::splat(0.0068208_f64);
        let v19: L = L::splat(0.111498032_f64);
        let v20: L = L::splat(0.0047376_f64);
        let v21: L = L::splat(0.01543232_f64);
        let v22: L = L::splat(0.82_f64);
        let v23: L = L::splat(0.01558_f64);
        let v24: L = L::splat(0.00209602_f64);
        let v25: L = L::splat(0.0013_f64);
        let v26: L = L::splat(0.34_f64);
        let v27: L = L::splat(0.0003_f64);
        let v28: L = L::splat(0.0004_f64);
        let v29: L = L::splat(0.09_f64);
        let v30: L = L::splat(0.00288_f64);
        let v31: L = L::splat(0.00024216_f64);
        let v32: L = L::splat(4e-05_f64);
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
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/puma560.json")
);
