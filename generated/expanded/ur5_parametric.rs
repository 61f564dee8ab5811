// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// Expansion of `armdyn_derive::robot_model!("models/ur5_parametric.json")` in the `generated` crate,
// formatted with prettyplease. Not compiled: for reading and review.

/// Name of the robot (`robot.name` in the model file).
pub const ROBOT_NAME: &str = "ur5";
/// Description of the robot, from the model file.
pub const DESCRIPTION: &str = "Universal Robots UR5, 6R, from the URDF of example-robot-data";
/// Degrees of freedom: the number of joints.
pub const DOF: usize = 6;
/// Name and version of the generator that wrote the model file.
pub const GENERATOR: &str = "armdyn-codegen 0.1.0";
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
/// The task: the rows of the geometric Jacobian (`vx vy vz wx wy wz`) its end
/// effector is controlled in (the description's `task`).
pub const TASK_ROWS: [usize; 6] = [0, 1, 2, 3, 4, 5];
/// `(function, flops, trig)` for every function, in file order: floating-point
/// operations (add, sub, mul, div, neg, sq, twice, inv, sqrt, fabs) and trig calls
/// (sin, cos, atan2) in its body.
pub const OPERATION_COUNTS: [(&str, u32, u32); 6] = [
    ("mass_matrix", 447, 10),
    ("coriolis_matrix", 4324, 10),
    ("coriolis", 679, 10),
    ("gravity", 132, 10),
    ("inverse_dynamics", 730, 10),
    ("forward_dynamics", 1286, 10),
];
/// Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67).
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `params: &[f64; 60]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `mass_matrix: [[f64; 6]; 6]` (6 x 6, row-major): symmetric positive definite M(q) (kg m^2, kg m, kg)
///
/// Operation count: 447 floating-point operations, 10 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn mass_matrix(q: &[f64; 6], params: &[f64; 60]) -> [[f64; 6]; 6] {
    let (
        v0,
        v2,
        v3,
        v5,
        v8,
        v29,
        v35,
        v36,
        v43,
        v46,
        v47,
        v48,
        v50,
        v52,
        v53,
        v56,
        v57,
        v61,
        v62,
        v63,
        v65,
        v67,
        v69,
        v81,
        v91,
        v93,
        v94,
        v96,
        v102,
        v106,
        v108,
        v111,
        v119,
        v125,
        v127,
        v131,
        v132,
        v135,
        v137,
        v139,
        v145,
        v150,
        v151,
        v152,
        v156,
        v157,
        v158,
        v163,
        v164,
        v165,
        v166,
        v167,
        v169,
        v171,
        v172,
        v173,
        v174,
        v175,
        v241,
    ) = {
        let v0: f64 = params[9];
        let v1: f64 = q[1];
        let (v241, v2): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
        let v3: f64 = params[14];
        let v4: f64 = q[2];
        let (v173, v5): (f64, f64) = ::armdyn_runtime::libm::sincos(v4);
        let v6: f64 = params[24];
        let v7: f64 = q[3];
        let (v69, v8): (f64, f64) = ::armdyn_runtime::libm::sincos(v7);
        let v9: f64 = params[39];
        let v10: f64 = params[49];
        let v11: f64 = q[5];
        let (v15, v12): (f64, f64) = ::armdyn_runtime::libm::sincos(v11);
        let v13: f64 = params[59];
        let v14: f64 = v12 * v13;
        let v16: f64 = params[56];
        let v17: f64 = v15 * v16;
        let v18: f64 = v14 - v17;
        let v19: f64 = v18 * v12;
        let v20: f64 = v12 * v16;
        let v21: f64 = params[54];
        let v22: f64 = v15 * v21;
        let v23: f64 = v20 - v22;
        let v24: f64 = v23 * v15;
        let v25: f64 = v19 - v24;
        let v26: f64 = 0.0089586225_f64;
        let v27: f64 = params[50];
        let v28: f64 = v26 * v27;
        let v29: f64 = 2.0_f64;
        let v30: f64 = 0.09465_f64;
        let v31: f64 = params[53];
        let v32: f64 = v12 * v31;
        let v33: f64 = params[51];
        let v34: f64 = v15 * v33;
        let v35: f64 = v32 - v34;
        let v36: f64 = v30 * v35;
        let v37: f64 = v29 * v36;
        let v38: f64 = v28 + v37;
        let v39: f64 = v25 + v38;
        let v40: f64 = v39 - v28;
        let v41: f64 = v40 - v36;
        let v42: f64 = v41 - v36;
        let v43: f64 = v10 + v42;
        let v44: f64 = 0.008649_f64;
        let v45: f64 = params[40];
        let v46: f64 = v45 + v27;
        let v47: f64 = v44 * v46;
        let v48: f64 = 0.093_f64;
        let v49: f64 = q[4];
        let (v50, v57): (f64, f64) = ::armdyn_runtime::libm::sincos(v49);
        let v51: f64 = params[41];
        let v52: f64 = v12 * v33;
        let v53: f64 = v15 * v31;
        let v54: f64 = v52 + v53;
        let v55: f64 = v51 + v54;
        let v56: f64 = v50 * v55;
        let v58: f64 = params[42];
        let v59: f64 = params[52];
        let v60: f64 = v58 + v59;
        let v61: f64 = v57 * v60;
        let v62: f64 = v56 + v61;
        let v63: f64 = v48 * v62;
        let v64: f64 = v29 * v63;
        let v65: f64 = v47 + v64;
        let v66: f64 = v43 + v65;
        let v67: f64 = v9 + v66;
        let v68: f64 = v8 * v67;
        let v70: f64 = params[36];
        let v71: f64 = params[46];
        let v72: f64 = v15 * v13;
        let v73: f64 = v20 + v72;
        let v74: f64 = v73 * v12;
        let v75: f64 = v12 * v21;
        let v76: f64 = v75 + v17;
        let v77: f64 = v76 * v15;
        let v78: f64 = v74 - v77;
        let v79: f64 = v30 * v54;
        let v80: f64 = v78 - v79;
        let v81: f64 = v71 + v80;
        let v82: f64 = v57 * v81;
        let v83: f64 = params[48];
        let v84: f64 = params[58];
        let v85: f64 = v84 * v12;
        let v86: f64 = params[55];
        let v87: f64 = v86 * v15;
        let v88: f64 = v85 - v87;
        let v89: f64 = v30 * v59;
        let v90: f64 = v88 - v89;
        let v91: f64 = v83 + v90;
        let v92: f64 = v50 * v91;
        let v93: f64 = v82 - v92;
        let v94: f64 = v70 + v93;
        let v95: f64 = v69 * v94;
        let v96: f64 = v68 - v95;
        let v97: f64 = v96 * v8;
        let v98: f64 = v23 * v12;
        let v99: f64 = v18 * v15;
        let v100: f64 = v98 + v99;
        let v101: f64 = v100 - v79;
        let v102: f64 = v71 + v101;
        let v103: f64 = v102 * v57;
        let v104: f64 = v12 * v84;
        let v105: f64 = v15 * v86;
        let v106: f64 = v104 - v105;
        let v107: f64 = v106 - v89;
        let v108: f64 = v83 + v107;
        let v109: f64 = v108 * v50;
        let v110: f64 = v103 - v109;
        let v111: f64 = v70 + v110;
        let v112: f64 = v8 * v111;
        let v113: f64 = params[34];
        let v114: f64 = params[44];
        let v115: f64 = v76 * v12;
        let v116: f64 = v73 * v15;
        let v117: f64 = v115 + v116;
        let v118: f64 = v117 + v38;
        let v119: f64 = v114 + v118;
        let v120: f64 = v57 * v119;
        let v121: f64 = params[45];
        let v122: f64 = v86 * v12;
        let v123: f64 = v84 * v15;
        let v124: f64 = v122 + v123;
        let v125: f64 = v121 + v124;
        let v126: f64 = v50 * v125;
        let v127: f64 = v120 - v126;
        let v128: f64 = v127 * v57;
        let v129: f64 = v12 * v86;
        let v130: f64 = v15 * v84;
        let v131: f64 = v129 + v130;
        let v132: f64 = v121 + v131;
        let v133: f64 = v57 * v132;
        let v134: f64 = params[47];
        let v135: f64 = params[57];
        let v136: f64 = v135 + v38;
        let v137: f64 = v134 + v136;
        let v138: f64 = v50 * v137;
        let v139: f64 = v133 - v138;
        let v140: f64 = v139 * v50;
        let v141: f64 = v128 - v140;
        let v142: f64 = v141 + v65;
        let v143: f64 = v113 + v142;
        let v144: f64 = v69 * v143;
        let v145: f64 = v112 - v144;
        let v146: f64 = v145 * v69;
        let v147: f64 = v97 - v146;
        let v148: f64 = 0.15386006249999998_f64;
        let v149: f64 = params[30];
        let v150: f64 = v149 + v46;
        let v151: f64 = v148 * v150;
        let v152: f64 = 0.39225_f64;
        let v153: f64 = params[31];
        let v154: f64 = v57 * v55;
        let v155: f64 = v50 * v60;
        let v156: f64 = v154 - v155;
        let v157: f64 = v153 + v156;
        let v158: f64 = v8 * v157;
        let v159: f64 = params[33];
        let v160: f64 = params[43];
        let v161: f64 = v30 * v27;
        let v162: f64 = v35 + v161;
        let v163: f64 = v160 + v162;
        let v164: f64 = v159 + v163;
        let v165: f64 = v69 * v164;
        let v166: f64 = v158 + v165;
        let v167: f64 = v152 * v166;
        let v168: f64 = v29 * v167;
        let v169: f64 = v151 - v168;
        let v170: f64 = v147 + v169;
        let v171: f64 = v6 + v170;
        let v172: f64 = v5 * v171;
        let v174: f64 = params[26];
        let v175: f64 = v8 * v143;
        (
            v0,
            v2,
            v3,
            v5,
            v8,
            v29,
            v35,
            v36,
            v43,
            v46,
            v47,
            v48,
            v50,
            v52,
            v53,
            v56,
            v57,
            v61,
            v62,
            v63,
            v65,
            v67,
            v69,
            v81,
            v91,
            v93,
            v94,
            v96,
            v102,
            v106,
            v108,
            v111,
            v119,
            v125,
            v127,
            v131,
            v132,
            v135,
            v137,
            v139,
            v145,
            v150,
            v151,
            v152,
            v156,
            v157,
            v158,
            v163,
            v164,
            v165,
            v166,
            v167,
            v169,
            v171,
            v172,
            v173,
            v174,
            v175,
            v241,
        )
    };
    let (
        v184,
        v185,
        v214,
        v216,
        v223,
        v224,
        v233,
        v234,
        v237,
        v252,
        v253,
        v286,
        v295,
        v305,
        v324,
        v330,
        v335,
        v339,
        v343,
        v347,
        v351,
    ) = {
        let v176: f64 = v69 * v111;
        let v177: f64 = v175 + v176;
        let v178: f64 = v177 * v69;
        let v179: f64 = v8 * v94;
        let v180: f64 = v69 * v67;
        let v181: f64 = v179 + v180;
        let v182: f64 = v181 * v8;
        let v183: f64 = v178 - v182;
        let v184: f64 = v8 * v164;
        let v185: f64 = v69 * v157;
        let v186: f64 = v184 - v185;
        let v187: f64 = v152 * v186;
        let v188: f64 = v183 - v187;
        let v189: f64 = v174 + v188;
        let v190: f64 = v173 * v189;
        let v191: f64 = v172 + v190;
        let v192: f64 = v191 * v5;
        let v193: f64 = v145 * v8;
        let v194: f64 = v96 * v69;
        let v195: f64 = v193 + v194;
        let v196: f64 = v195 + v187;
        let v197: f64 = v174 - v196;
        let v198: f64 = v5 * v197;
        let v199: f64 = params[29];
        let v200: f64 = v177 * v8;
        let v201: f64 = v181 * v69;
        let v202: f64 = v200 + v201;
        let v203: f64 = v202 + v169;
        let v204: f64 = v203 - v151;
        let v205: f64 = v204 + v167;
        let v206: f64 = v205 + v167;
        let v207: f64 = v199 + v206;
        let v208: f64 = v173 * v207;
        let v209: f64 = v198 + v208;
        let v210: f64 = v209 * v173;
        let v211: f64 = v192 + v210;
        let v212: f64 = 0.19495308999999997_f64;
        let v213: f64 = params[20];
        let v214: f64 = v213 + v150;
        let v215: f64 = v212 * v214;
        let v216: f64 = -0.1197_f64;
        let v217: f64 = params[22];
        let v218: f64 = params[32];
        let v219: f64 = v48 * v46;
        let v220: f64 = v62 + v219;
        let v221: f64 = v218 + v220;
        let v222: f64 = v217 + v221;
        let v223: f64 = v216 * v222;
        let v224: f64 = 0.425_f64;
        let v225: f64 = params[23];
        let v226: f64 = v152 * v150;
        let v227: f64 = v226 - v166;
        let v228: f64 = v225 + v227;
        let v229: f64 = v5 * v228;
        let v230: f64 = params[21];
        let v231: f64 = v230 + v186;
        let v232: f64 = v173 * v231;
        let v233: f64 = v229 - v232;
        let v234: f64 = v224 * v233;
        let v235: f64 = v223 + v234;
        let v236: f64 = v29 * v235;
        let v237: f64 = v215 + v236;
        let v238: f64 = v211 + v237;
        let v239: f64 = v3 + v238;
        let v240: f64 = v2 * v239;
        let v242: f64 = params[16];
        let v243: f64 = v5 * v189;
        let v244: f64 = v173 * v171;
        let v245: f64 = v243 - v244;
        let v246: f64 = v245 * v5;
        let v247: f64 = v5 * v207;
        let v248: f64 = v173 * v197;
        let v249: f64 = v247 - v248;
        let v250: f64 = v249 * v173;
        let v251: f64 = v246 + v250;
        let v252: f64 = v5 * v231;
        let v253: f64 = v173 * v228;
        let v254: f64 = v252 + v253;
        let v255: f64 = v224 * v254;
        let v256: f64 = v251 - v255;
        let v257: f64 = v242 + v256;
        let v258: f64 = v241 * v257;
        let v259: f64 = v240 + v258;
        let v260: f64 = v259 * v2;
        let v261: f64 = v209 * v5;
        let v262: f64 = v191 * v173;
        let v263: f64 = v261 - v262;
        let v264: f64 = v263 - v255;
        let v265: f64 = v242 + v264;
        let v266: f64 = v2 * v265;
        let v267: f64 = params[19];
        let v268: f64 = v249 * v5;
        let v269: f64 = v245 * v173;
        let v270: f64 = v268 - v269;
        let v271: f64 = v270 + v237;
        let v272: f64 = 0.18062499999999998_f64;
        let v273: f64 = v272 * v214;
        let v274: f64 = v271 - v273;
        let v275: f64 = v274 - v234;
        let v276: f64 = v275 - v234;
        let v277: f64 = v267 + v276;
        let v278: f64 = v241 * v277;
        let v279: f64 = v266 + v278;
        let v280: f64 = v279 * v241;
        let v281: f64 = v260 + v280;
        let v282: f64 = 0.0184552225_f64;
        let v283: f64 = params[10];
        let v284: f64 = v283 + v214;
        let v285: f64 = v282 * v284;
        let v286: f64 = 0.13585_f64;
        let v287: f64 = params[12];
        let v288: f64 = v216 * v214;
        let v289: f64 = v222 + v288;
        let v290: f64 = v287 + v289;
        let v291: f64 = v286 * v290;
        let v292: f64 = v29 * v291;
        let v293: f64 = v285 + v292;
        let v294: f64 = v281 + v293;
        let v295: f64 = v0 + v294;
        let v296: f64 = params[13];
        let v297: f64 = v224 * v214;
        let v298: f64 = v233 + v297;
        let v299: f64 = v296 + v298;
        let v300: f64 = v241 * v299;
        let v301: f64 = params[11];
        let v302: f64 = v301 + v254;
        let v303: f64 = v2 * v302;
        let v304: f64 = v300 + v303;
        let v305: f64 = v286 * v304;
        let v306: f64 = params[15];
        let v307: f64 = params[25];
        let v308: f64 = params[38];
        let v309: f64 = v102 * v50;
        let v310: f64 = v108 * v57;
        let v311: f64 = v309 + v310;
        let v312: f64 = v48 * v163;
        let v313: f64 = v311 - v312;
        let v314: f64 = v308 + v313;
        let v315: f64 = v8 * v314;
        let v316: f64 = params[35];
        let v317: f64 = v127 * v50;
        let v318: f64 = v139 * v57;
        let v319: f64 = v317 + v318;
        let v320: f64 = v48 * v156;
        let v321: f64 = v319 - v320;
        let v322: f64 = v316 + v321;
        let v323: f64 = v69 * v322;
        let v324: f64 = v315 - v323;
        let v325: f64 = v307 + v324;
        let v326: f64 = v5 * v325;
        let v327: f64 = params[28];
        let v328: f64 = v8 * v322;
        let v329: f64 = v69 * v314;
        let v330: f64 = v328 + v329;
        let v331: f64 = v152 * v221;
        let v332: f64 = v330 + v331;
        let v333: f64 = v327 - v332;
        let v334: f64 = v173 * v333;
        let v335: f64 = v326 + v334;
        let v336: f64 = v216 * v254;
        let v337: f64 = v335 - v336;
        let v338: f64 = v306 + v337;
        let v339: f64 = v2 * v338;
        let v340: f64 = params[18];
        let v341: f64 = v5 * v333;
        let v342: f64 = v173 * v325;
        let v343: f64 = v341 - v342;
        let v344: f64 = -0.0508725_f64;
        let v345: f64 = v344 * v214;
        let v346: f64 = v343 - v345;
        let v347: f64 = v216 * v233;
        let v348: f64 = v346 - v347;
        let v349: f64 = v224 * v222;
        let v350: f64 = v348 - v349;
        let v351: f64 = v340 + v350;
        (
            v184,
            v185,
            v214,
            v216,
            v223,
            v224,
            v233,
            v234,
            v237,
            v252,
            v253,
            v286,
            v295,
            v305,
            v324,
            v330,
            v335,
            v339,
            v343,
            v347,
            v351,
        )
    };
    let (
        v354,
        v366,
        v392,
        v431,
        v482,
        v499,
        v501,
        v508,
        v509,
        v511,
        v513,
        v516,
        v518,
        v520,
        v523,
        v525,
        v527,
    ) = {
        let v352: f64 = v241 * v351;
        let v353: f64 = v339 + v352;
        let v354: f64 = v305 - v353;
        let v355: f64 = v241 * v233;
        let v356: f64 = v253 + v252;
        let v357: f64 = v2 * v356;
        let v358: f64 = v355 + v357;
        let v359: f64 = v286 * v358;
        let v360: f64 = v216 * v356;
        let v361: f64 = v335 - v360;
        let v362: f64 = v2 * v361;
        let v363: f64 = v343 - v347;
        let v364: f64 = v241 * v363;
        let v365: f64 = v362 + v364;
        let v366: f64 = v359 - v365;
        let v367: f64 = v173 * v324;
        let v368: f64 = v5 * v330;
        let v369: f64 = v367 + v368;
        let v370: f64 = v185 - v184;
        let v371: f64 = v173 * v370;
        let v372: f64 = v165 + v158;
        let v373: f64 = v5 * v372;
        let v374: f64 = v371 - v373;
        let v375: f64 = v216 * v374;
        let v376: f64 = v369 + v375;
        let v377: f64 = v241 * v376;
        let v378: f64 = v5 * v324;
        let v379: f64 = v173 * v330;
        let v380: f64 = v378 - v379;
        let v381: f64 = v173 * v372;
        let v382: f64 = v5 * v370;
        let v383: f64 = v381 + v382;
        let v384: f64 = v216 * v383;
        let v385: f64 = v380 + v384;
        let v386: f64 = v2 * v385;
        let v387: f64 = v377 - v386;
        let v388: f64 = v2 * v383;
        let v389: f64 = v241 * v374;
        let v390: f64 = v388 - v389;
        let v391: f64 = v286 * v390;
        let v392: f64 = v387 - v391;
        let v393: f64 = v61 + v56;
        let v394: f64 = v48 * v393;
        let v395: f64 = v43 + v394;
        let v396: f64 = v8 * v395;
        let v397: f64 = v69 * v93;
        let v398: f64 = v396 - v397;
        let v399: f64 = v152 * v156;
        let v400: f64 = v398 - v399;
        let v401: f64 = v173 * v400;
        let v402: f64 = v8 * v93;
        let v403: f64 = v69 * v395;
        let v404: f64 = v402 + v403;
        let v405: f64 = v5 * v404;
        let v406: f64 = v401 + v405;
        let v407: f64 = v69 * v393;
        let v408: f64 = v5 * v407;
        let v409: f64 = v8 * v393;
        let v410: f64 = v173 * v409;
        let v411: f64 = v408 + v410;
        let v412: f64 = v216 * v411;
        let v413: f64 = v406 + v412;
        let v414: f64 = v241 * v413;
        let v415: f64 = v5 * v400;
        let v416: f64 = v173 * v404;
        let v417: f64 = v415 - v416;
        let v418: f64 = v5 * v409;
        let v419: f64 = v173 * v407;
        let v420: f64 = v418 - v419;
        let v421: f64 = v216 * v420;
        let v422: f64 = v224 * v156;
        let v423: f64 = v421 - v422;
        let v424: f64 = v417 + v423;
        let v425: f64 = v2 * v424;
        let v426: f64 = v414 - v425;
        let v427: f64 = v2 * v420;
        let v428: f64 = v241 * v411;
        let v429: f64 = v427 - v428;
        let v430: f64 = v286 * v429;
        let v431: f64 = v426 - v430;
        let v432: f64 = v57 * v35;
        let v433: f64 = v48 * v432;
        let v434: f64 = v106 - v433;
        let v435: f64 = v8 * v434;
        let v436: f64 = v57 * v131;
        let v437: f64 = v135 + v36;
        let v438: f64 = v50 * v437;
        let v439: f64 = v436 - v438;
        let v440: f64 = v53 + v52;
        let v441: f64 = v48 * v440;
        let v442: f64 = v439 - v441;
        let v443: f64 = v69 * v442;
        let v444: f64 = v435 - v443;
        let v445: f64 = v50 * v35;
        let v446: f64 = v152 * v445;
        let v447: f64 = v444 - v446;
        let v448: f64 = v173 * v447;
        let v449: f64 = v8 * v442;
        let v450: f64 = v69 * v434;
        let v451: f64 = v449 + v450;
        let v452: f64 = v5 * v451;
        let v453: f64 = v448 + v452;
        let v454: f64 = v69 * v440;
        let v455: f64 = v8 * v432;
        let v456: f64 = v454 - v455;
        let v457: f64 = v173 * v456;
        let v458: f64 = v69 * v432;
        let v459: f64 = v8 * v440;
        let v460: f64 = v458 + v459;
        let v461: f64 = v5 * v460;
        let v462: f64 = v457 - v461;
        let v463: f64 = v216 * v462;
        let v464: f64 = v453 + v463;
        let v465: f64 = v241 * v464;
        let v466: f64 = v5 * v447;
        let v467: f64 = v173 * v451;
        let v468: f64 = v466 - v467;
        let v469: f64 = v173 * v460;
        let v470: f64 = v5 * v456;
        let v471: f64 = v469 + v470;
        let v472: f64 = v216 * v471;
        let v473: f64 = v224 * v445;
        let v474: f64 = v472 - v473;
        let v475: f64 = v468 + v474;
        let v476: f64 = v2 * v475;
        let v477: f64 = v465 - v476;
        let v478: f64 = v2 * v471;
        let v479: f64 = v241 * v462;
        let v480: f64 = v478 - v479;
        let v481: f64 = v286 * v480;
        let v482: f64 = v477 - v481;
        let v483: f64 = params[17];
        let v484: f64 = params[27];
        let v485: f64 = params[37];
        let v486: f64 = v50 * v119;
        let v487: f64 = v57 * v125;
        let v488: f64 = v486 + v487;
        let v489: f64 = v488 * v50;
        let v490: f64 = v50 * v132;
        let v491: f64 = v57 * v137;
        let v492: f64 = v490 + v491;
        let v493: f64 = v492 * v57;
        let v494: f64 = v489 + v493;
        let v495: f64 = v494 + v65;
        let v496: f64 = v495 - v47;
        let v497: f64 = v496 - v63;
        let v498: f64 = v497 - v63;
        let v499: f64 = v485 + v498;
        let v500: f64 = v499 + v169;
        let v501: f64 = v484 + v500;
        let v502: f64 = v501 + v237;
        let v503: f64 = 0.01432809_f64;
        let v504: f64 = v503 * v214;
        let v505: f64 = v502 - v504;
        let v506: f64 = v505 - v223;
        let v507: f64 = v506 - v223;
        let v508: f64 = v483 + v507;
        let v509: f64 = v501 + v234;
        let v510: f64 = v152 * v372;
        let v511: f64 = v499 - v510;
        let v512: f64 = v224 * v374;
        let v513: f64 = v511 + v512;
        let v514: f64 = v50 * v81;
        let v515: f64 = v57 * v91;
        let v516: f64 = v514 + v515;
        let v517: f64 = v152 * v407;
        let v518: f64 = v516 + v517;
        let v519: f64 = v224 * v411;
        let v520: f64 = v518 + v519;
        let v521: f64 = v50 * v131;
        let v522: f64 = v57 * v437;
        let v523: f64 = v521 + v522;
        let v524: f64 = v152 * v460;
        let v525: f64 = v523 - v524;
        let v526: f64 = v224 * v462;
        let v527: f64 = v525 + v526;
        (
            v354,
            v366,
            v392,
            v431,
            v482,
            v499,
            v501,
            v508,
            v509,
            v511,
            v513,
            v516,
            v518,
            v520,
            v523,
            v525,
            v527,
        )
    };
    [
        [v295, v354, v366, v392, v431, v482],
        [v354, v508, v509, v513, v520, v527],
        [v366, v509, v501, v511, v518, v525],
        [v392, v513, v511, v499, v516, v523],
        [v431, v520, v518, v516, v43, v106],
        [v482, v527, v525, v523, v106, v135],
    ]
}
/// Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M.
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 6]`: joint velocities qd (rad/s or m/s)
/// - `params: &[f64; 60]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `coriolis_matrix: [[f64; 6]; 6]` (6 x 6, row-major): C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric
///
/// Operation count: 4324 floating-point operations, 10 trig calls.
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
    q: &[f64; 6],
    qd: &[f64; 6],
    params: &[f64; 60],
) -> [[f64; 6]; 6] {
    let (
        v0,
        v2,
        v4,
        v5,
        v6,
        v8,
        v10,
        v12,
        v13,
        v14,
        v15,
        v18,
        v19,
        v20,
        v21,
        v22,
        v23,
        v25,
        v26,
        v27,
        v29,
        v30,
        v31,
        v34,
        v36,
        v37,
        v38,
        v39,
        v41,
        v43,
        v44,
        v46,
        v49,
        v50,
        v51,
        v54,
        v57,
        v59,
        v60,
        v62,
        v66,
        v68,
        v69,
        v71,
        v72,
        v73,
        v76,
        v79,
        v81,
        v85,
        v87,
        v90,
        v95,
        v96,
        v98,
        v100,
        v102,
        v105,
        v108,
        v111,
        v112,
        v116,
        v122,
        v124,
        v126,
        v129,
        v131,
        v133,
        v140,
        v142,
        v145,
        v148,
        v150,
        v154,
        v157,
        v162,
        v168,
        v170,
        v171,
        v182,
        v183,
        v185,
        v187,
        v188,
        v190,
        v194,
        v197,
        v198,
        v199,
    ) = {
        let v0: f64 = 0.5_f64;
        let v1: f64 = q[1];
        let (v8, v2): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
        let v3: f64 = q[2];
        let (v6, v4): (f64, f64) = ::armdyn_runtime::libm::sincos(v3);
        let v5: f64 = params[24];
        let v7: f64 = v6 * v2;
        let v9: f64 = v4 * v8;
        let v10: f64 = v7 + v9;
        let v11: f64 = v5 * v10;
        let v12: f64 = params[26];
        let v13: f64 = v4 * v2;
        let v14: f64 = v6 * v8;
        let v15: f64 = v13 - v14;
        let v16: f64 = v12 * v15;
        let v17: f64 = v11 - v16;
        let v18: f64 = params[22];
        let v19: f64 = 0.13585_f64;
        let v20: f64 = v19 * v2;
        let v21: f64 = v6 * v20;
        let v22: f64 = v19 * v8;
        let v23: f64 = v4 * v22;
        let v24: f64 = v21 + v23;
        let v25: f64 = -0.1197_f64;
        let v26: f64 = v25 * v10;
        let v27: f64 = v24 + v26;
        let v28: f64 = v18 * v27;
        let v29: f64 = params[23];
        let v30: f64 = 0.425_f64;
        let v31: f64 = v30 * v8;
        let v32: f64 = v29 * v31;
        let v33: f64 = v28 + v32;
        let v34: f64 = v17 + v33;
        let v35: f64 = q[3];
        let (v39, v36): (f64, f64) = ::armdyn_runtime::libm::sincos(v35);
        let v37: f64 = params[39];
        let v38: f64 = v36 * v10;
        let v40: f64 = v39 * v15;
        let v41: f64 = v38 + v40;
        let v42: f64 = v37 * v41;
        let v43: f64 = params[36];
        let v44: f64 = v39 * v10;
        let v45: f64 = v36 * v15;
        let v46: f64 = v44 - v45;
        let v47: f64 = v43 * v46;
        let v48: f64 = v42 - v47;
        let v49: f64 = params[32];
        let v50: f64 = v4 * v20;
        let v51: f64 = v6 * v22;
        let v52: f64 = v50 - v51;
        let v53: f64 = v25 * v15;
        let v54: f64 = v52 + v53;
        let v55: f64 = v39 * v54;
        let v56: f64 = v36 * v27;
        let v57: f64 = v55 + v56;
        let v58: f64 = v49 * v57;
        let v59: f64 = params[31];
        let v60: f64 = 0.39225_f64;
        let v61: f64 = v60 * v10;
        let v62: f64 = v61 + v31;
        let v63: f64 = v59 * v62;
        let v64: f64 = v58 - v63;
        let v65: f64 = v48 + v64;
        let v66: f64 = params[48];
        let v67: f64 = q[4];
        let (v68, v72): (f64, f64) = ::armdyn_runtime::libm::sincos(v67);
        let v69: f64 = v68 * v46;
        let v70: f64 = v66 * v69;
        let v71: f64 = params[46];
        let v73: f64 = v72 * v46;
        let v74: f64 = v71 * v73;
        let v75: f64 = v70 - v74;
        let v76: f64 = params[49];
        let v77: f64 = v76 * v41;
        let v78: f64 = v75 + v77;
        let v79: f64 = params[41];
        let v80: f64 = v72 * v62;
        let v81: f64 = 0.093_f64;
        let v82: f64 = v81 * v41;
        let v83: f64 = v82 + v57;
        let v84: f64 = v68 * v83;
        let v85: f64 = v80 - v84;
        let v86: f64 = v79 * v85;
        let v87: f64 = params[42];
        let v88: f64 = v72 * v83;
        let v89: f64 = v68 * v62;
        let v90: f64 = v88 + v89;
        let v91: f64 = v87 * v90;
        let v92: f64 = v86 - v91;
        let v93: f64 = v78 - v92;
        let v94: f64 = q[5];
        let (v100, v95): (f64, f64) = ::armdyn_runtime::libm::sincos(v94);
        let v96: f64 = params[58];
        let v97: f64 = v96 * v69;
        let v98: f64 = params[56];
        let v99: f64 = v95 * v73;
        let v101: f64 = v100 * v41;
        let v102: f64 = v99 + v101;
        let v103: f64 = v98 * v102;
        let v104: f64 = v97 - v103;
        let v105: f64 = params[59];
        let v106: f64 = v95 * v41;
        let v107: f64 = v100 * v73;
        let v108: f64 = v106 - v107;
        let v109: f64 = v105 * v108;
        let v110: f64 = v104 + v109;
        let v111: f64 = params[51];
        let v112: f64 = 0.09465_f64;
        let v113: f64 = v112 * v73;
        let v114: f64 = v113 - v85;
        let v115: f64 = v111 * v114;
        let v116: f64 = params[52];
        let v117: f64 = v112 * v69;
        let v118: f64 = v117 - v90;
        let v119: f64 = v95 * v118;
        let v120: f64 = v36 * v54;
        let v121: f64 = v39 * v27;
        let v122: f64 = v120 - v121;
        let v123: f64 = v81 * v46;
        let v124: f64 = v122 - v123;
        let v125: f64 = v100 * v124;
        let v126: f64 = v119 - v125;
        let v127: f64 = v116 * v126;
        let v128: f64 = v115 - v127;
        let v129: f64 = v110 + v128;
        let v130: f64 = v95 * v129;
        let v131: f64 = params[55];
        let v132: f64 = v131 * v69;
        let v133: f64 = params[54];
        let v134: f64 = v133 * v102;
        let v135: f64 = v132 - v134;
        let v136: f64 = v98 * v108;
        let v137: f64 = v135 + v136;
        let v138: f64 = v100 * v118;
        let v139: f64 = v95 * v124;
        let v140: f64 = v138 + v139;
        let v141: f64 = v116 * v140;
        let v142: f64 = params[53];
        let v143: f64 = v142 * v114;
        let v144: f64 = v141 - v143;
        let v145: f64 = v137 + v144;
        let v146: f64 = v100 * v145;
        let v147: f64 = v130 - v146;
        let v148: f64 = v93 + v147;
        let v149: f64 = v65 + v148;
        let v150: f64 = params[43];
        let v151: f64 = v150 * v69;
        let v152: f64 = v87 * v41;
        let v153: f64 = v151 - v152;
        let v154: f64 = params[40];
        let v155: f64 = v154 * v90;
        let v156: f64 = v153 - v155;
        let v157: f64 = params[50];
        let v158: f64 = v157 * v126;
        let v159: f64 = v142 * v69;
        let v160: f64 = v116 * v108;
        let v161: f64 = v159 - v160;
        let v162: f64 = v158 + v161;
        let v163: f64 = v95 * v162;
        let v164: f64 = v157 * v140;
        let v165: f64 = v116 * v102;
        let v166: f64 = v111 * v69;
        let v167: f64 = v165 + v166;
        let v168: f64 = v164 - v167;
        let v169: f64 = v100 * v168;
        let v170: f64 = v163 + v169;
        let v171: f64 = v156 + v170;
        let v172: f64 = v72 * v171;
        let v173: f64 = v79 * v41;
        let v174: f64 = v150 * v73;
        let v175: f64 = v173 + v174;
        let v176: f64 = v154 * v85;
        let v177: f64 = v175 - v176;
        let v178: f64 = v157 * v114;
        let v179: f64 = v111 * v108;
        let v180: f64 = v142 * v102;
        let v181: f64 = v179 + v180;
        let v182: f64 = v178 + v181;
        let v183: f64 = v177 + v182;
        let v184: f64 = v68 * v183;
        let v185: f64 = v172 - v184;
        let v186: f64 = v81 * v185;
        let v187: f64 = v149 - v186;
        let v188: f64 = v36 * v187;
        let v189: f64 = v43 * v41;
        let v190: f64 = params[34];
        let v191: f64 = v190 * v46;
        let v192: f64 = v189 - v191;
        let v193: f64 = v49 * v122;
        let v194: f64 = params[33];
        let v195: f64 = v194 * v62;
        let v196: f64 = v193 + v195;
        let v197: f64 = v192 + v196;
        let v198: f64 = params[45];
        let v199: f64 = v198 * v69;
        (
            v0,
            v2,
            v4,
            v5,
            v6,
            v8,
            v10,
            v12,
            v13,
            v14,
            v15,
            v18,
            v19,
            v20,
            v21,
            v22,
            v23,
            v25,
            v26,
            v27,
            v29,
            v30,
            v31,
            v34,
            v36,
            v37,
            v38,
            v39,
            v41,
            v43,
            v44,
            v46,
            v49,
            v50,
            v51,
            v54,
            v57,
            v59,
            v60,
            v62,
            v66,
            v68,
            v69,
            v71,
            v72,
            v73,
            v76,
            v79,
            v81,
            v85,
            v87,
            v90,
            v95,
            v96,
            v98,
            v100,
            v102,
            v105,
            v108,
            v111,
            v112,
            v116,
            v122,
            v124,
            v126,
            v129,
            v131,
            v133,
            v140,
            v142,
            v145,
            v148,
            v150,
            v154,
            v157,
            v162,
            v168,
            v170,
            v171,
            v182,
            v183,
            v185,
            v187,
            v188,
            v190,
            v194,
            v197,
            v198,
            v199,
        )
    };
    let (
        v200,
        v214,
        v216,
        v226,
        v235,
        v238,
        v259,
        v268,
        v270,
        v283,
        v285,
        v288,
        v292,
        v305,
        v306,
        v308,
        v311,
        v312,
        v313,
        v316,
        v317,
        v331,
        v334,
        v338,
        v339,
        v344,
        v346,
        v349,
        v351,
        v354,
        v358,
        v361,
        v364,
        v367,
        v368,
        v370,
        v377,
        v379,
        v383,
        v386,
        v390,
        v395,
        v397,
        v399,
    ) = {
        let v200: f64 = params[44];
        let v201: f64 = v200 * v73;
        let v202: f64 = v199 - v201;
        let v203: f64 = v71 * v41;
        let v204: f64 = v202 + v203;
        let v205: f64 = v87 * v124;
        let v206: f64 = v150 * v85;
        let v207: f64 = v205 + v206;
        let v208: f64 = v204 + v207;
        let v209: f64 = v95 * v145;
        let v210: f64 = v100 * v129;
        let v211: f64 = v209 + v210;
        let v212: f64 = v208 + v211;
        let v213: f64 = v112 * v182;
        let v214: f64 = v212 - v213;
        let v215: f64 = v72 * v214;
        let v216: f64 = params[47];
        let v217: f64 = v216 * v69;
        let v218: f64 = v198 * v73;
        let v219: f64 = v217 - v218;
        let v220: f64 = v66 * v41;
        let v221: f64 = v219 + v220;
        let v222: f64 = v150 * v90;
        let v223: f64 = v79 * v124;
        let v224: f64 = v222 + v223;
        let v225: f64 = v221 - v224;
        let v226: f64 = params[57];
        let v227: f64 = v226 * v69;
        let v228: f64 = v131 * v102;
        let v229: f64 = v227 - v228;
        let v230: f64 = v96 * v108;
        let v231: f64 = v229 + v230;
        let v232: f64 = v142 * v126;
        let v233: f64 = v111 * v140;
        let v234: f64 = v232 - v233;
        let v235: f64 = v231 + v234;
        let v236: f64 = v225 + v235;
        let v237: f64 = v112 * v170;
        let v238: f64 = v236 + v237;
        let v239: f64 = v68 * v238;
        let v240: f64 = v215 - v239;
        let v241: f64 = v197 + v240;
        let v242: f64 = v154 * v124;
        let v243: f64 = v87 * v73;
        let v244: f64 = v79 * v69;
        let v245: f64 = v243 + v244;
        let v246: f64 = v242 - v245;
        let v247: f64 = v95 * v168;
        let v248: f64 = v100 * v162;
        let v249: f64 = v247 - v248;
        let v250: f64 = v246 + v249;
        let v251: f64 = v81 * v250;
        let v252: f64 = v241 + v251;
        let v253: f64 = v39 * v252;
        let v254: f64 = v188 - v253;
        let v255: f64 = v34 + v254;
        let v256: f64 = v59 * v41;
        let v257: f64 = v194 * v46;
        let v258: f64 = v256 + v257;
        let v259: f64 = params[30];
        let v260: f64 = v259 * v62;
        let v261: f64 = v258 - v260;
        let v262: f64 = v68 * v171;
        let v263: f64 = v72 * v183;
        let v264: f64 = v262 + v263;
        let v265: f64 = v261 + v264;
        let v266: f64 = v60 * v265;
        let v267: f64 = v255 - v266;
        let v268: f64 = params[20];
        let v269: f64 = v268 * v27;
        let v270: f64 = v18 * v10;
        let v271: f64 = v269 + v270;
        let v272: f64 = v49 * v41;
        let v273: f64 = v259 * v57;
        let v274: f64 = v272 + v273;
        let v275: f64 = v185 - v274;
        let v276: f64 = v36 * v275;
        let v277: f64 = v259 * v122;
        let v278: f64 = v49 * v46;
        let v279: f64 = v277 - v278;
        let v280: f64 = v279 + v250;
        let v281: f64 = v39 * v280;
        let v282: f64 = v276 + v281;
        let v283: f64 = v271 - v282;
        let v284: f64 = v25 * v283;
        let v285: f64 = v267 + v284;
        let v286: f64 = v4 * v285;
        let v287: f64 = v12 * v10;
        let v288: f64 = params[29];
        let v289: f64 = v288 * v15;
        let v290: f64 = v287 - v289;
        let v291: f64 = v18 * v54;
        let v292: f64 = params[21];
        let v293: f64 = v292 * v31;
        let v294: f64 = v291 + v293;
        let v295: f64 = v290 - v294;
        let v296: f64 = v36 * v252;
        let v297: f64 = v39 * v187;
        let v298: f64 = v296 + v297;
        let v299: f64 = v295 - v298;
        let v300: f64 = v268 * v54;
        let v301: f64 = v18 * v15;
        let v302: f64 = v300 + v301;
        let v303: f64 = v36 * v280;
        let v304: f64 = v39 * v275;
        let v305: f64 = v303 - v304;
        let v306: f64 = v302 + v305;
        let v307: f64 = v25 * v306;
        let v308: f64 = v299 - v307;
        let v309: f64 = v6 * v308;
        let v310: f64 = v286 + v309;
        let v311: f64 = params[16];
        let v312: f64 = v311 * v2;
        let v313: f64 = params[14];
        let v314: f64 = v313 * v8;
        let v315: f64 = v312 - v314;
        let v316: f64 = params[12];
        let v317: f64 = v316 * v22;
        let v318: f64 = v315 - v317;
        let v319: f64 = v310 - v318;
        let v320: f64 = v268 * v31;
        let v321: f64 = v292 * v15;
        let v322: f64 = v29 * v10;
        let v323: f64 = v321 + v322;
        let v324: f64 = v320 + v323;
        let v325: f64 = v265 - v324;
        let v326: f64 = v30 * v325;
        let v327: f64 = v319 - v326;
        let v328: f64 = v4 * v283;
        let v329: f64 = v6 * v306;
        let v330: f64 = v328 - v329;
        let v331: f64 = params[10];
        let v332: f64 = v331 * v22;
        let v333: f64 = v316 * v8;
        let v334: f64 = v332 + v333;
        let v335: f64 = v330 + v334;
        let v336: f64 = v19 * v335;
        let v337: f64 = v327 + v336;
        let v338: f64 = v2 * v337;
        let v339: f64 = v14 - v13;
        let v340: f64 = v5 * v339;
        let v341: f64 = v340 - v287;
        let v342: f64 = v51 - v50;
        let v343: f64 = v25 * v339;
        let v344: f64 = v342 + v343;
        let v345: f64 = v18 * v344;
        let v346: f64 = v30 * v2;
        let v347: f64 = v29 * v346;
        let v348: f64 = v345 - v347;
        let v349: f64 = v341 + v348;
        let v350: f64 = v36 * v339;
        let v351: f64 = v350 + v44;
        let v352: f64 = v37 * v351;
        let v353: f64 = v39 * v339;
        let v354: f64 = v353 - v38;
        let v355: f64 = v43 * v354;
        let v356: f64 = v352 - v355;
        let v357: f64 = v23 + v21;
        let v358: f64 = v357 + v26;
        let v359: f64 = v39 * v358;
        let v360: f64 = v36 * v344;
        let v361: f64 = v359 + v360;
        let v362: f64 = v49 * v361;
        let v363: f64 = v60 * v339;
        let v364: f64 = v363 - v346;
        let v365: f64 = v59 * v364;
        let v366: f64 = v362 - v365;
        let v367: f64 = v356 + v366;
        let v368: f64 = v68 * v354;
        let v369: f64 = v66 * v368;
        let v370: f64 = v72 * v354;
        let v371: f64 = v71 * v370;
        let v372: f64 = v369 - v371;
        let v373: f64 = v76 * v351;
        let v374: f64 = v372 + v373;
        let v375: f64 = v72 * v364;
        let v376: f64 = v81 * v351;
        let v377: f64 = v376 + v361;
        let v378: f64 = v68 * v377;
        let v379: f64 = v375 - v378;
        let v380: f64 = v79 * v379;
        let v381: f64 = v72 * v377;
        let v382: f64 = v68 * v364;
        let v383: f64 = v381 + v382;
        let v384: f64 = v87 * v383;
        let v385: f64 = v380 - v384;
        let v386: f64 = v374 - v385;
        let v387: f64 = v96 * v368;
        let v388: f64 = v95 * v370;
        let v389: f64 = v100 * v351;
        let v390: f64 = v388 + v389;
        let v391: f64 = v98 * v390;
        let v392: f64 = v387 - v391;
        let v393: f64 = v95 * v351;
        let v394: f64 = v100 * v370;
        let v395: f64 = v393 - v394;
        let v396: f64 = v105 * v395;
        let v397: f64 = v392 + v396;
        let v398: f64 = v112 * v370;
        let v399: f64 = v398 - v379;
        (
            v200,
            v214,
            v216,
            v226,
            v235,
            v238,
            v259,
            v268,
            v270,
            v283,
            v285,
            v288,
            v292,
            v305,
            v306,
            v308,
            v311,
            v312,
            v313,
            v316,
            v317,
            v331,
            v334,
            v338,
            v339,
            v344,
            v346,
            v349,
            v351,
            v354,
            v358,
            v361,
            v364,
            v367,
            v368,
            v370,
            v377,
            v379,
            v383,
            v386,
            v390,
            v395,
            v397,
            v399,
        )
    };
    let (
        v402,
        v408,
        v413,
        v426,
        v440,
        v446,
        v449,
        v461,
        v465,
        v488,
        v510,
        v524,
        v545,
        v550,
        v553,
        v555,
        v573,
        v575,
        v579,
        v581,
        v591,
        v597,
        v599,
    ) = {
        let v400: f64 = v111 * v399;
        let v401: f64 = v112 * v368;
        let v402: f64 = v401 - v383;
        let v403: f64 = v95 * v402;
        let v404: f64 = v36 * v358;
        let v405: f64 = v39 * v344;
        let v406: f64 = v404 - v405;
        let v407: f64 = v81 * v354;
        let v408: f64 = v406 - v407;
        let v409: f64 = v100 * v408;
        let v410: f64 = v403 - v409;
        let v411: f64 = v116 * v410;
        let v412: f64 = v400 - v411;
        let v413: f64 = v397 + v412;
        let v414: f64 = v95 * v413;
        let v415: f64 = v131 * v368;
        let v416: f64 = v133 * v390;
        let v417: f64 = v415 - v416;
        let v418: f64 = v98 * v395;
        let v419: f64 = v417 + v418;
        let v420: f64 = v100 * v402;
        let v421: f64 = v95 * v408;
        let v422: f64 = v420 + v421;
        let v423: f64 = v116 * v422;
        let v424: f64 = v142 * v399;
        let v425: f64 = v423 - v424;
        let v426: f64 = v419 + v425;
        let v427: f64 = v100 * v426;
        let v428: f64 = v414 - v427;
        let v429: f64 = v386 + v428;
        let v430: f64 = v367 + v429;
        let v431: f64 = v150 * v368;
        let v432: f64 = v87 * v351;
        let v433: f64 = v431 - v432;
        let v434: f64 = v154 * v383;
        let v435: f64 = v433 - v434;
        let v436: f64 = v157 * v410;
        let v437: f64 = v142 * v368;
        let v438: f64 = v116 * v395;
        let v439: f64 = v437 - v438;
        let v440: f64 = v436 + v439;
        let v441: f64 = v95 * v440;
        let v442: f64 = v157 * v422;
        let v443: f64 = v116 * v390;
        let v444: f64 = v111 * v368;
        let v445: f64 = v443 + v444;
        let v446: f64 = v442 - v445;
        let v447: f64 = v100 * v446;
        let v448: f64 = v441 + v447;
        let v449: f64 = v435 + v448;
        let v450: f64 = v72 * v449;
        let v451: f64 = v79 * v351;
        let v452: f64 = v150 * v370;
        let v453: f64 = v451 + v452;
        let v454: f64 = v154 * v379;
        let v455: f64 = v453 - v454;
        let v456: f64 = v157 * v399;
        let v457: f64 = v111 * v395;
        let v458: f64 = v142 * v390;
        let v459: f64 = v457 + v458;
        let v460: f64 = v456 + v459;
        let v461: f64 = v455 + v460;
        let v462: f64 = v68 * v461;
        let v463: f64 = v450 - v462;
        let v464: f64 = v81 * v463;
        let v465: f64 = v430 - v464;
        let v466: f64 = v36 * v465;
        let v467: f64 = v43 * v351;
        let v468: f64 = v190 * v354;
        let v469: f64 = v467 - v468;
        let v470: f64 = v49 * v406;
        let v471: f64 = v194 * v364;
        let v472: f64 = v470 + v471;
        let v473: f64 = v469 + v472;
        let v474: f64 = v198 * v368;
        let v475: f64 = v200 * v370;
        let v476: f64 = v474 - v475;
        let v477: f64 = v71 * v351;
        let v478: f64 = v476 + v477;
        let v479: f64 = v87 * v408;
        let v480: f64 = v150 * v379;
        let v481: f64 = v479 + v480;
        let v482: f64 = v478 + v481;
        let v483: f64 = v95 * v426;
        let v484: f64 = v100 * v413;
        let v485: f64 = v483 + v484;
        let v486: f64 = v482 + v485;
        let v487: f64 = v112 * v460;
        let v488: f64 = v486 - v487;
        let v489: f64 = v72 * v488;
        let v490: f64 = v216 * v368;
        let v491: f64 = v198 * v370;
        let v492: f64 = v490 - v491;
        let v493: f64 = v66 * v351;
        let v494: f64 = v492 + v493;
        let v495: f64 = v150 * v383;
        let v496: f64 = v79 * v408;
        let v497: f64 = v495 + v496;
        let v498: f64 = v494 - v497;
        let v499: f64 = v226 * v368;
        let v500: f64 = v131 * v390;
        let v501: f64 = v499 - v500;
        let v502: f64 = v96 * v395;
        let v503: f64 = v501 + v502;
        let v504: f64 = v142 * v410;
        let v505: f64 = v111 * v422;
        let v506: f64 = v504 - v505;
        let v507: f64 = v503 + v506;
        let v508: f64 = v498 + v507;
        let v509: f64 = v112 * v448;
        let v510: f64 = v508 + v509;
        let v511: f64 = v68 * v510;
        let v512: f64 = v489 - v511;
        let v513: f64 = v473 + v512;
        let v514: f64 = v154 * v408;
        let v515: f64 = v87 * v370;
        let v516: f64 = v79 * v368;
        let v517: f64 = v515 + v516;
        let v518: f64 = v514 - v517;
        let v519: f64 = v95 * v446;
        let v520: f64 = v100 * v440;
        let v521: f64 = v519 - v520;
        let v522: f64 = v518 + v521;
        let v523: f64 = v81 * v522;
        let v524: f64 = v513 + v523;
        let v525: f64 = v39 * v524;
        let v526: f64 = v466 - v525;
        let v527: f64 = v349 + v526;
        let v528: f64 = v59 * v351;
        let v529: f64 = v194 * v354;
        let v530: f64 = v528 + v529;
        let v531: f64 = v259 * v364;
        let v532: f64 = v530 - v531;
        let v533: f64 = v68 * v449;
        let v534: f64 = v72 * v461;
        let v535: f64 = v533 + v534;
        let v536: f64 = v532 + v535;
        let v537: f64 = v60 * v536;
        let v538: f64 = v527 - v537;
        let v539: f64 = v268 * v344;
        let v540: f64 = v18 * v339;
        let v541: f64 = v539 + v540;
        let v542: f64 = v49 * v351;
        let v543: f64 = v259 * v361;
        let v544: f64 = v542 + v543;
        let v545: f64 = v463 - v544;
        let v546: f64 = v36 * v545;
        let v547: f64 = v259 * v406;
        let v548: f64 = v49 * v354;
        let v549: f64 = v547 - v548;
        let v550: f64 = v549 + v522;
        let v551: f64 = v39 * v550;
        let v552: f64 = v546 + v551;
        let v553: f64 = v541 - v552;
        let v554: f64 = v25 * v553;
        let v555: f64 = v538 + v554;
        let v556: f64 = v4 * v555;
        let v557: f64 = v12 * v339;
        let v558: f64 = v288 * v10;
        let v559: f64 = v557 - v558;
        let v560: f64 = v18 * v358;
        let v561: f64 = v292 * v346;
        let v562: f64 = v560 - v561;
        let v563: f64 = v559 - v562;
        let v564: f64 = v36 * v524;
        let v565: f64 = v39 * v465;
        let v566: f64 = v564 + v565;
        let v567: f64 = v563 - v566;
        let v568: f64 = v268 * v358;
        let v569: f64 = v568 + v270;
        let v570: f64 = v36 * v550;
        let v571: f64 = v39 * v545;
        let v572: f64 = v570 - v571;
        let v573: f64 = v569 + v572;
        let v574: f64 = v25 * v573;
        let v575: f64 = v567 - v574;
        let v576: f64 = v6 * v575;
        let v577: f64 = v556 + v576;
        let v578: f64 = v313 * v2;
        let v579: f64 = v311 * v8;
        let v580: f64 = v578 + v579;
        let v581: f64 = v316 * v20;
        let v582: f64 = v580 + v581;
        let v583: f64 = v577 - v582;
        let v584: f64 = v268 * v346;
        let v585: f64 = v292 * v10;
        let v586: f64 = v29 * v339;
        let v587: f64 = v585 + v586;
        let v588: f64 = v584 - v587;
        let v589: f64 = v588 + v536;
        let v590: f64 = v30 * v589;
        let v591: f64 = v583 - v590;
        let v592: f64 = v4 * v553;
        let v593: f64 = v6 * v573;
        let v594: f64 = v592 - v593;
        let v595: f64 = v331 * v20;
        let v596: f64 = v316 * v2;
        let v597: f64 = v595 + v596;
        let v598: f64 = v594 - v597;
        let v599: f64 = v19 * v598;
        (
            v402,
            v408,
            v413,
            v426,
            v440,
            v446,
            v449,
            v461,
            v465,
            v488,
            v510,
            v524,
            v545,
            v550,
            v553,
            v555,
            v573,
            v575,
            v579,
            v581,
            v591,
            v597,
            v599,
        )
    };
    let (
        v627,
        v634,
        v635,
        v636,
        v639,
        v643,
        v650,
        v652,
        v655,
        v659,
        v666,
        v669,
        v671,
        v675,
        v677,
        v690,
        v697,
        v702,
        v713,
        v715,
        v717,
        v729,
        v736,
        v747,
        v753,
        v755,
        v756,
        v768,
        v770,
        v772,
        v773,
        v780,
        v795,
        v796,
        v799,
    ) = {
        let v600: f64 = v591 + v599;
        let v601: f64 = v600 * v8;
        let v602: f64 = v338 - v601;
        let v603: f64 = v4 * v575;
        let v604: f64 = v6 * v555;
        let v605: f64 = v603 - v604;
        let v606: f64 = params[19];
        let v607: f64 = v606 * v8;
        let v608: f64 = v312 + v607;
        let v609: f64 = v608 + v317;
        let v610: f64 = v605 - v609;
        let v611: f64 = v4 * v573;
        let v612: f64 = v6 * v553;
        let v613: f64 = v611 + v612;
        let v614: f64 = v334 + v613;
        let v615: f64 = v19 * v614;
        let v616: f64 = v610 - v615;
        let v617: f64 = v616 * v2;
        let v618: f64 = v4 * v308;
        let v619: f64 = v6 * v285;
        let v620: f64 = v618 - v619;
        let v621: f64 = v606 * v2;
        let v622: f64 = v621 - v579;
        let v623: f64 = v622 + v581;
        let v624: f64 = v620 - v623;
        let v625: f64 = v4 * v306;
        let v626: f64 = v6 * v283;
        let v627: f64 = v625 + v626;
        let v628: f64 = v597 + v627;
        let v629: f64 = v19 * v628;
        let v630: f64 = v624 - v629;
        let v631: f64 = v8 * v630;
        let v632: f64 = v617 + v631;
        let v633: f64 = v602 + v632;
        let v634: f64 = v0 * v633;
        let v635: f64 = qd[1];
        let v636: f64 = v634 * v635;
        let v637: f64 = v8 * v4;
        let v638: f64 = v2 * v6;
        let v639: f64 = v637 + v638;
        let v640: f64 = v5 * v639;
        let v641: f64 = v2 * v4;
        let v642: f64 = v8 * v6;
        let v643: f64 = v641 - v642;
        let v644: f64 = v12 * v643;
        let v645: f64 = v640 - v644;
        let v646: f64 = v22 * v4;
        let v647: f64 = v20 * v6;
        let v648: f64 = v646 + v647;
        let v649: f64 = v25 * v639;
        let v650: f64 = v648 + v649;
        let v651: f64 = v18 * v650;
        let v652: f64 = v645 + v651;
        let v653: f64 = v36 * v639;
        let v654: f64 = v39 * v643;
        let v655: f64 = v653 + v654;
        let v656: f64 = v37 * v655;
        let v657: f64 = v39 * v639;
        let v658: f64 = v36 * v643;
        let v659: f64 = v657 - v658;
        let v660: f64 = v43 * v659;
        let v661: f64 = v656 - v660;
        let v662: f64 = v20 * v4;
        let v663: f64 = v22 * v6;
        let v664: f64 = v662 - v663;
        let v665: f64 = v25 * v643;
        let v666: f64 = v664 + v665;
        let v667: f64 = v39 * v666;
        let v668: f64 = v36 * v650;
        let v669: f64 = v667 + v668;
        let v670: f64 = v49 * v669;
        let v671: f64 = v60 * v639;
        let v672: f64 = v59 * v671;
        let v673: f64 = v670 - v672;
        let v674: f64 = v661 + v673;
        let v675: f64 = v68 * v659;
        let v676: f64 = v66 * v675;
        let v677: f64 = v72 * v659;
        let v678: f64 = v71 * v677;
        let v679: f64 = v676 - v678;
        let v680: f64 = v76 * v655;
        let v681: f64 = v679 + v680;
        let v682: f64 = v72 * v671;
        let v683: f64 = v81 * v655;
        let v684: f64 = v683 + v669;
        let v685: f64 = v68 * v684;
        let v686: f64 = v682 - v685;
        let v687: f64 = v79 * v686;
        let v688: f64 = v72 * v684;
        let v689: f64 = v68 * v671;
        let v690: f64 = v688 + v689;
        let v691: f64 = v87 * v690;
        let v692: f64 = v687 - v691;
        let v693: f64 = v681 - v692;
        let v694: f64 = v96 * v675;
        let v695: f64 = v95 * v677;
        let v696: f64 = v100 * v655;
        let v697: f64 = v695 + v696;
        let v698: f64 = v98 * v697;
        let v699: f64 = v694 - v698;
        let v700: f64 = v95 * v655;
        let v701: f64 = v100 * v677;
        let v702: f64 = v700 - v701;
        let v703: f64 = v105 * v702;
        let v704: f64 = v699 + v703;
        let v705: f64 = v112 * v677;
        let v706: f64 = v705 - v686;
        let v707: f64 = v111 * v706;
        let v708: f64 = v112 * v675;
        let v709: f64 = v708 - v690;
        let v710: f64 = v95 * v709;
        let v711: f64 = v36 * v666;
        let v712: f64 = v39 * v650;
        let v713: f64 = v711 - v712;
        let v714: f64 = v81 * v659;
        let v715: f64 = v713 - v714;
        let v716: f64 = v100 * v715;
        let v717: f64 = v710 - v716;
        let v718: f64 = v116 * v717;
        let v719: f64 = v707 - v718;
        let v720: f64 = v704 + v719;
        let v721: f64 = v95 * v720;
        let v722: f64 = v131 * v675;
        let v723: f64 = v133 * v697;
        let v724: f64 = v722 - v723;
        let v725: f64 = v98 * v702;
        let v726: f64 = v724 + v725;
        let v727: f64 = v100 * v709;
        let v728: f64 = v95 * v715;
        let v729: f64 = v727 + v728;
        let v730: f64 = v116 * v729;
        let v731: f64 = v142 * v706;
        let v732: f64 = v730 - v731;
        let v733: f64 = v726 + v732;
        let v734: f64 = v100 * v733;
        let v735: f64 = v721 - v734;
        let v736: f64 = v693 + v735;
        let v737: f64 = v674 + v736;
        let v738: f64 = v150 * v675;
        let v739: f64 = v87 * v655;
        let v740: f64 = v738 - v739;
        let v741: f64 = v154 * v690;
        let v742: f64 = v740 - v741;
        let v743: f64 = v157 * v717;
        let v744: f64 = v142 * v675;
        let v745: f64 = v116 * v702;
        let v746: f64 = v744 - v745;
        let v747: f64 = v743 + v746;
        let v748: f64 = v95 * v747;
        let v749: f64 = v157 * v729;
        let v750: f64 = v116 * v697;
        let v751: f64 = v111 * v675;
        let v752: f64 = v750 + v751;
        let v753: f64 = v749 - v752;
        let v754: f64 = v100 * v753;
        let v755: f64 = v748 + v754;
        let v756: f64 = v742 + v755;
        let v757: f64 = v72 * v756;
        let v758: f64 = v79 * v655;
        let v759: f64 = v150 * v677;
        let v760: f64 = v758 + v759;
        let v761: f64 = v154 * v686;
        let v762: f64 = v760 - v761;
        let v763: f64 = v157 * v706;
        let v764: f64 = v111 * v702;
        let v765: f64 = v142 * v697;
        let v766: f64 = v764 + v765;
        let v767: f64 = v763 + v766;
        let v768: f64 = v762 + v767;
        let v769: f64 = v68 * v768;
        let v770: f64 = v757 - v769;
        let v771: f64 = v81 * v770;
        let v772: f64 = v737 - v771;
        let v773: f64 = v36 * v772;
        let v774: f64 = v43 * v655;
        let v775: f64 = v190 * v659;
        let v776: f64 = v774 - v775;
        let v777: f64 = v49 * v713;
        let v778: f64 = v194 * v671;
        let v779: f64 = v777 + v778;
        let v780: f64 = v776 + v779;
        let v781: f64 = v198 * v675;
        let v782: f64 = v200 * v677;
        let v783: f64 = v781 - v782;
        let v784: f64 = v71 * v655;
        let v785: f64 = v783 + v784;
        let v786: f64 = v87 * v715;
        let v787: f64 = v150 * v686;
        let v788: f64 = v786 + v787;
        let v789: f64 = v785 + v788;
        let v790: f64 = v95 * v733;
        let v791: f64 = v100 * v720;
        let v792: f64 = v790 + v791;
        let v793: f64 = v789 + v792;
        let v794: f64 = v112 * v767;
        let v795: f64 = v793 - v794;
        let v796: f64 = v72 * v795;
        let v797: f64 = v216 * v675;
        let v798: f64 = v198 * v677;
        let v799: f64 = v797 - v798;
        (
            v627,
            v634,
            v635,
            v636,
            v639,
            v643,
            v650,
            v652,
            v655,
            v659,
            v666,
            v669,
            v671,
            v675,
            v677,
            v690,
            v697,
            v702,
            v713,
            v715,
            v717,
            v729,
            v736,
            v747,
            v753,
            v755,
            v756,
            v768,
            v770,
            v772,
            v773,
            v780,
            v795,
            v796,
            v799,
        )
    };
    let (
        v814,
        v817,
        v881,
        v917,
        v922,
        v923,
        v925,
        v928,
        v932,
        v937,
        v940,
        v942,
        v949,
        v951,
        v958,
        v963,
        v967,
        v974,
        v976,
        v978,
        v981,
        v990,
        v994,
        v997,
        v998,
        v999,
    ) = {
        let v800: f64 = v66 * v655;
        let v801: f64 = v799 + v800;
        let v802: f64 = v150 * v690;
        let v803: f64 = v79 * v715;
        let v804: f64 = v802 + v803;
        let v805: f64 = v801 - v804;
        let v806: f64 = v226 * v675;
        let v807: f64 = v131 * v697;
        let v808: f64 = v806 - v807;
        let v809: f64 = v96 * v702;
        let v810: f64 = v808 + v809;
        let v811: f64 = v142 * v717;
        let v812: f64 = v111 * v729;
        let v813: f64 = v811 - v812;
        let v814: f64 = v810 + v813;
        let v815: f64 = v805 + v814;
        let v816: f64 = v112 * v755;
        let v817: f64 = v815 + v816;
        let v818: f64 = v68 * v817;
        let v819: f64 = v796 - v818;
        let v820: f64 = v780 + v819;
        let v821: f64 = v154 * v715;
        let v822: f64 = v87 * v677;
        let v823: f64 = v79 * v675;
        let v824: f64 = v822 + v823;
        let v825: f64 = v821 - v824;
        let v826: f64 = v95 * v753;
        let v827: f64 = v100 * v747;
        let v828: f64 = v826 - v827;
        let v829: f64 = v825 + v828;
        let v830: f64 = v81 * v829;
        let v831: f64 = v820 + v830;
        let v832: f64 = v39 * v831;
        let v833: f64 = v773 - v832;
        let v834: f64 = v652 + v833;
        let v835: f64 = v59 * v655;
        let v836: f64 = v194 * v659;
        let v837: f64 = v835 + v836;
        let v838: f64 = v259 * v671;
        let v839: f64 = v837 - v838;
        let v840: f64 = v68 * v756;
        let v841: f64 = v72 * v768;
        let v842: f64 = v840 + v841;
        let v843: f64 = v839 + v842;
        let v844: f64 = v60 * v843;
        let v845: f64 = v834 - v844;
        let v846: f64 = v268 * v650;
        let v847: f64 = v18 * v639;
        let v848: f64 = v846 + v847;
        let v849: f64 = v49 * v655;
        let v850: f64 = v259 * v669;
        let v851: f64 = v849 + v850;
        let v852: f64 = v770 - v851;
        let v853: f64 = v36 * v852;
        let v854: f64 = v259 * v713;
        let v855: f64 = v49 * v659;
        let v856: f64 = v854 - v855;
        let v857: f64 = v856 + v829;
        let v858: f64 = v39 * v857;
        let v859: f64 = v853 + v858;
        let v860: f64 = v848 - v859;
        let v861: f64 = v25 * v860;
        let v862: f64 = v845 + v861;
        let v863: f64 = v4 * v862;
        let v864: f64 = v555 * v6;
        let v865: f64 = v863 - v864;
        let v866: f64 = v575 * v4;
        let v867: f64 = v12 * v639;
        let v868: f64 = v288 * v643;
        let v869: f64 = v867 - v868;
        let v870: f64 = v18 * v666;
        let v871: f64 = v869 - v870;
        let v872: f64 = v36 * v831;
        let v873: f64 = v39 * v772;
        let v874: f64 = v872 + v873;
        let v875: f64 = v871 - v874;
        let v876: f64 = v268 * v666;
        let v877: f64 = v18 * v643;
        let v878: f64 = v876 + v877;
        let v879: f64 = v36 * v857;
        let v880: f64 = v39 * v852;
        let v881: f64 = v879 - v880;
        let v882: f64 = v878 + v881;
        let v883: f64 = v25 * v882;
        let v884: f64 = v875 - v883;
        let v885: f64 = v6 * v884;
        let v886: f64 = v866 + v885;
        let v887: f64 = v865 + v886;
        let v888: f64 = v292 * v643;
        let v889: f64 = v29 * v639;
        let v890: f64 = v888 + v889;
        let v891: f64 = v843 - v890;
        let v892: f64 = v30 * v891;
        let v893: f64 = v887 - v892;
        let v894: f64 = v4 * v860;
        let v895: f64 = v553 * v6;
        let v896: f64 = v894 - v895;
        let v897: f64 = v573 * v4;
        let v898: f64 = v6 * v882;
        let v899: f64 = v897 + v898;
        let v900: f64 = v896 - v899;
        let v901: f64 = v19 * v900;
        let v902: f64 = v893 + v901;
        let v903: f64 = v2 * v902;
        let v904: f64 = v4 * v884;
        let v905: f64 = v575 * v6;
        let v906: f64 = v904 - v905;
        let v907: f64 = v555 * v4;
        let v908: f64 = v6 * v862;
        let v909: f64 = v907 + v908;
        let v910: f64 = v906 - v909;
        let v911: f64 = v4 * v882;
        let v912: f64 = v573 * v6;
        let v913: f64 = v911 - v912;
        let v914: f64 = v553 * v4;
        let v915: f64 = v6 * v860;
        let v916: f64 = v914 + v915;
        let v917: f64 = v913 + v916;
        let v918: f64 = v19 * v917;
        let v919: f64 = v910 - v918;
        let v920: f64 = v8 * v919;
        let v921: f64 = v903 + v920;
        let v922: f64 = v0 * v921;
        let v923: f64 = qd[2];
        let v924: f64 = v922 * v923;
        let v925: f64 = v636 + v924;
        let v926: f64 = v10 * v36;
        let v927: f64 = v339 * v39;
        let v928: f64 = v926 - v927;
        let v929: f64 = v37 * v928;
        let v930: f64 = v339 * v36;
        let v931: f64 = v10 * v39;
        let v932: f64 = v930 + v931;
        let v933: f64 = v43 * v932;
        let v934: f64 = v929 - v933;
        let v935: f64 = v358 * v36;
        let v936: f64 = v344 * v39;
        let v937: f64 = v935 - v936;
        let v938: f64 = v49 * v937;
        let v939: f64 = v934 + v938;
        let v940: f64 = v68 * v932;
        let v941: f64 = v66 * v940;
        let v942: f64 = v72 * v932;
        let v943: f64 = v71 * v942;
        let v944: f64 = v941 - v943;
        let v945: f64 = v76 * v928;
        let v946: f64 = v944 + v945;
        let v947: f64 = v81 * v928;
        let v948: f64 = v947 + v937;
        let v949: f64 = v68 * v948;
        let v950: f64 = v79 * v949;
        let v951: f64 = v72 * v948;
        let v952: f64 = v87 * v951;
        let v953: f64 = v950 + v952;
        let v954: f64 = v946 + v953;
        let v955: f64 = v96 * v940;
        let v956: f64 = v95 * v942;
        let v957: f64 = v100 * v928;
        let v958: f64 = v956 + v957;
        let v959: f64 = v98 * v958;
        let v960: f64 = v955 - v959;
        let v961: f64 = v95 * v928;
        let v962: f64 = v100 * v942;
        let v963: f64 = v961 - v962;
        let v964: f64 = v105 * v963;
        let v965: f64 = v960 + v964;
        let v966: f64 = v112 * v942;
        let v967: f64 = v966 + v949;
        let v968: f64 = v111 * v967;
        let v969: f64 = v112 * v940;
        let v970: f64 = v969 - v951;
        let v971: f64 = v95 * v970;
        let v972: f64 = v358 * v39;
        let v973: f64 = v344 * v36;
        let v974: f64 = v972 + v973;
        let v975: f64 = v81 * v932;
        let v976: f64 = v974 + v975;
        let v977: f64 = v100 * v976;
        let v978: f64 = v971 + v977;
        let v979: f64 = v116 * v978;
        let v980: f64 = v968 - v979;
        let v981: f64 = v965 + v980;
        let v982: f64 = v95 * v981;
        let v983: f64 = v131 * v940;
        let v984: f64 = v133 * v958;
        let v985: f64 = v983 - v984;
        let v986: f64 = v98 * v963;
        let v987: f64 = v985 + v986;
        let v988: f64 = v100 * v970;
        let v989: f64 = v95 * v976;
        let v990: f64 = v988 - v989;
        let v991: f64 = v116 * v990;
        let v992: f64 = v142 * v967;
        let v993: f64 = v991 - v992;
        let v994: f64 = v987 + v993;
        let v995: f64 = v100 * v994;
        let v996: f64 = v982 - v995;
        let v997: f64 = v954 + v996;
        let v998: f64 = v939 + v997;
        let v999: f64 = v150 * v940;
        (
            v814,
            v817,
            v881,
            v917,
            v922,
            v923,
            v925,
            v928,
            v932,
            v937,
            v940,
            v942,
            v949,
            v951,
            v958,
            v963,
            v967,
            v974,
            v976,
            v978,
            v981,
            v990,
            v994,
            v997,
            v998,
            v999,
        )
    };
    let (
        v1057,
        v1076,
        v1079,
        v1137,
        v1155,
        v1160,
        v1161,
        v1163,
        v1164,
        v1166,
        v1171,
        v1175,
        v1178,
        v1180,
        v1183,
        v1187,
        v1190,
        v1191,
        v1194,
        v1195,
        v1198,
        v1199,
    ) = {
        let v1000: f64 = v87 * v928;
        let v1001: f64 = v999 - v1000;
        let v1002: f64 = v154 * v951;
        let v1003: f64 = v1001 - v1002;
        let v1004: f64 = v157 * v978;
        let v1005: f64 = v142 * v940;
        let v1006: f64 = v116 * v963;
        let v1007: f64 = v1005 - v1006;
        let v1008: f64 = v1004 + v1007;
        let v1009: f64 = v95 * v1008;
        let v1010: f64 = v157 * v990;
        let v1011: f64 = v116 * v958;
        let v1012: f64 = v111 * v940;
        let v1013: f64 = v1011 + v1012;
        let v1014: f64 = v1010 - v1013;
        let v1015: f64 = v100 * v1014;
        let v1016: f64 = v1009 + v1015;
        let v1017: f64 = v1003 + v1016;
        let v1018: f64 = v72 * v1017;
        let v1019: f64 = v79 * v928;
        let v1020: f64 = v150 * v942;
        let v1021: f64 = v1019 + v1020;
        let v1022: f64 = v154 * v949;
        let v1023: f64 = v1021 + v1022;
        let v1024: f64 = v157 * v967;
        let v1025: f64 = v111 * v963;
        let v1026: f64 = v142 * v958;
        let v1027: f64 = v1025 + v1026;
        let v1028: f64 = v1024 + v1027;
        let v1029: f64 = v1023 + v1028;
        let v1030: f64 = v68 * v1029;
        let v1031: f64 = v1018 - v1030;
        let v1032: f64 = v81 * v1031;
        let v1033: f64 = v998 - v1032;
        let v1034: f64 = v36 * v1033;
        let v1035: f64 = v465 * v39;
        let v1036: f64 = v1034 - v1035;
        let v1037: f64 = v524 * v36;
        let v1038: f64 = v43 * v928;
        let v1039: f64 = v190 * v932;
        let v1040: f64 = v1038 - v1039;
        let v1041: f64 = v49 * v974;
        let v1042: f64 = v1040 - v1041;
        let v1043: f64 = v198 * v940;
        let v1044: f64 = v200 * v942;
        let v1045: f64 = v1043 - v1044;
        let v1046: f64 = v71 * v928;
        let v1047: f64 = v1045 + v1046;
        let v1048: f64 = v87 * v976;
        let v1049: f64 = v150 * v949;
        let v1050: f64 = v1048 + v1049;
        let v1051: f64 = v1047 - v1050;
        let v1052: f64 = v95 * v994;
        let v1053: f64 = v100 * v981;
        let v1054: f64 = v1052 + v1053;
        let v1055: f64 = v1051 + v1054;
        let v1056: f64 = v112 * v1028;
        let v1057: f64 = v1055 - v1056;
        let v1058: f64 = v72 * v1057;
        let v1059: f64 = v216 * v940;
        let v1060: f64 = v198 * v942;
        let v1061: f64 = v1059 - v1060;
        let v1062: f64 = v66 * v928;
        let v1063: f64 = v1061 + v1062;
        let v1064: f64 = v150 * v951;
        let v1065: f64 = v79 * v976;
        let v1066: f64 = v1064 - v1065;
        let v1067: f64 = v1063 - v1066;
        let v1068: f64 = v226 * v940;
        let v1069: f64 = v131 * v958;
        let v1070: f64 = v1068 - v1069;
        let v1071: f64 = v96 * v963;
        let v1072: f64 = v1070 + v1071;
        let v1073: f64 = v142 * v978;
        let v1074: f64 = v111 * v990;
        let v1075: f64 = v1073 - v1074;
        let v1076: f64 = v1072 + v1075;
        let v1077: f64 = v1067 + v1076;
        let v1078: f64 = v112 * v1016;
        let v1079: f64 = v1077 + v1078;
        let v1080: f64 = v68 * v1079;
        let v1081: f64 = v1058 - v1080;
        let v1082: f64 = v1042 + v1081;
        let v1083: f64 = v95 * v1014;
        let v1084: f64 = v100 * v1008;
        let v1085: f64 = v1083 - v1084;
        let v1086: f64 = v154 * v976;
        let v1087: f64 = v87 * v942;
        let v1088: f64 = v79 * v940;
        let v1089: f64 = v1087 + v1088;
        let v1090: f64 = v1086 + v1089;
        let v1091: f64 = v1085 - v1090;
        let v1092: f64 = v81 * v1091;
        let v1093: f64 = v1082 + v1092;
        let v1094: f64 = v39 * v1093;
        let v1095: f64 = v1037 + v1094;
        let v1096: f64 = v1036 - v1095;
        let v1097: f64 = v59 * v928;
        let v1098: f64 = v194 * v932;
        let v1099: f64 = v1097 + v1098;
        let v1100: f64 = v68 * v1017;
        let v1101: f64 = v72 * v1029;
        let v1102: f64 = v1100 + v1101;
        let v1103: f64 = v1099 + v1102;
        let v1104: f64 = v60 * v1103;
        let v1105: f64 = v1096 - v1104;
        let v1106: f64 = v49 * v928;
        let v1107: f64 = v259 * v937;
        let v1108: f64 = v1106 + v1107;
        let v1109: f64 = v1031 - v1108;
        let v1110: f64 = v36 * v1109;
        let v1111: f64 = v545 * v39;
        let v1112: f64 = v1110 - v1111;
        let v1113: f64 = v550 * v36;
        let v1114: f64 = v259 * v974;
        let v1115: f64 = v49 * v932;
        let v1116: f64 = v1114 + v1115;
        let v1117: f64 = v1091 - v1116;
        let v1118: f64 = v39 * v1117;
        let v1119: f64 = v1113 + v1118;
        let v1120: f64 = v1112 + v1119;
        let v1121: f64 = v25 * v1120;
        let v1122: f64 = v1105 - v1121;
        let v1123: f64 = v4 * v1122;
        let v1124: f64 = v36 * v1093;
        let v1125: f64 = v524 * v39;
        let v1126: f64 = v1124 - v1125;
        let v1127: f64 = v465 * v36;
        let v1128: f64 = v39 * v1033;
        let v1129: f64 = v1127 + v1128;
        let v1130: f64 = v1126 + v1129;
        let v1131: f64 = v36 * v1117;
        let v1132: f64 = v550 * v39;
        let v1133: f64 = v1131 - v1132;
        let v1134: f64 = v545 * v36;
        let v1135: f64 = v39 * v1109;
        let v1136: f64 = v1134 + v1135;
        let v1137: f64 = v1133 - v1136;
        let v1138: f64 = v25 * v1137;
        let v1139: f64 = v1130 + v1138;
        let v1140: f64 = v6 * v1139;
        let v1141: f64 = v1123 - v1140;
        let v1142: f64 = v30 * v1103;
        let v1143: f64 = v1141 - v1142;
        let v1144: f64 = v4 * v1120;
        let v1145: f64 = v6 * v1137;
        let v1146: f64 = v1144 + v1145;
        let v1147: f64 = v19 * v1146;
        let v1148: f64 = v1143 - v1147;
        let v1149: f64 = v2 * v1148;
        let v1150: f64 = v4 * v1139;
        let v1151: f64 = v6 * v1122;
        let v1152: f64 = v1150 + v1151;
        let v1153: f64 = v4 * v1137;
        let v1154: f64 = v6 * v1120;
        let v1155: f64 = v1153 - v1154;
        let v1156: f64 = v19 * v1155;
        let v1157: f64 = v1152 + v1156;
        let v1158: f64 = v8 * v1157;
        let v1159: f64 = v1149 - v1158;
        let v1160: f64 = v0 * v1159;
        let v1161: f64 = qd[3];
        let v1162: f64 = v1160 * v1161;
        let v1163: f64 = v925 + v1162;
        let v1164: f64 = v354 * v72;
        let v1165: f64 = v66 * v1164;
        let v1166: f64 = v354 * v68;
        let v1167: f64 = v71 * v1166;
        let v1168: f64 = v1165 + v1167;
        let v1169: f64 = v364 * v68;
        let v1170: f64 = v377 * v72;
        let v1171: f64 = v1169 + v1170;
        let v1172: f64 = v79 * v1171;
        let v1173: f64 = v364 * v72;
        let v1174: f64 = v377 * v68;
        let v1175: f64 = v1173 - v1174;
        let v1176: f64 = v87 * v1175;
        let v1177: f64 = v1172 + v1176;
        let v1178: f64 = v1168 + v1177;
        let v1179: f64 = v96 * v1164;
        let v1180: f64 = v95 * v1166;
        let v1181: f64 = v98 * v1180;
        let v1182: f64 = v1179 + v1181;
        let v1183: f64 = v100 * v1166;
        let v1184: f64 = v105 * v1183;
        let v1185: f64 = v1182 + v1184;
        let v1186: f64 = v112 * v1166;
        let v1187: f64 = v1171 - v1186;
        let v1188: f64 = v111 * v1187;
        let v1189: f64 = v112 * v1164;
        let v1190: f64 = v1189 - v1175;
        let v1191: f64 = v95 * v1190;
        let v1192: f64 = v116 * v1191;
        let v1193: f64 = v1188 - v1192;
        let v1194: f64 = v1185 + v1193;
        let v1195: f64 = v95 * v1194;
        let v1196: f64 = v131 * v1164;
        let v1197: f64 = v133 * v1180;
        let v1198: f64 = v1196 + v1197;
        let v1199: f64 = v98 * v1183;
        (
            v1057,
            v1076,
            v1079,
            v1137,
            v1155,
            v1160,
            v1161,
            v1163,
            v1164,
            v1166,
            v1171,
            v1175,
            v1178,
            v1180,
            v1183,
            v1187,
            v1190,
            v1191,
            v1194,
            v1195,
            v1198,
            v1199,
        )
    };
    let (
        v1208,
        v1255,
        v1273,
        v1276,
        v1311,
        v1329,
        v1334,
        v1335,
        v1337,
        v1340,
        v1344,
        v1348,
        v1358,
        v1366,
        v1369,
        v1376,
        v1379,
        v1383,
        v1385,
        v1387,
        v1388,
        v1397,
        v1398,
        v1399,
    ) = {
        let v1200: f64 = v1198 + v1199;
        let v1201: f64 = v100 * v1190;
        let v1202: f64 = v116 * v1201;
        let v1203: f64 = v142 * v1187;
        let v1204: f64 = v1202 - v1203;
        let v1205: f64 = v1200 + v1204;
        let v1206: f64 = v100 * v1205;
        let v1207: f64 = v1195 - v1206;
        let v1208: f64 = v1178 + v1207;
        let v1209: f64 = v150 * v1164;
        let v1210: f64 = v154 * v1175;
        let v1211: f64 = v1209 - v1210;
        let v1212: f64 = v157 * v1191;
        let v1213: f64 = v142 * v1164;
        let v1214: f64 = v116 * v1183;
        let v1215: f64 = v1213 - v1214;
        let v1216: f64 = v1212 + v1215;
        let v1217: f64 = v95 * v1216;
        let v1218: f64 = v157 * v1201;
        let v1219: f64 = v111 * v1164;
        let v1220: f64 = v116 * v1180;
        let v1221: f64 = v1219 - v1220;
        let v1222: f64 = v1218 - v1221;
        let v1223: f64 = v100 * v1222;
        let v1224: f64 = v1217 + v1223;
        let v1225: f64 = v1211 + v1224;
        let v1226: f64 = v72 * v1225;
        let v1227: f64 = v449 * v68;
        let v1228: f64 = v1226 - v1227;
        let v1229: f64 = v461 * v72;
        let v1230: f64 = v154 * v1171;
        let v1231: f64 = v150 * v1166;
        let v1232: f64 = v1230 - v1231;
        let v1233: f64 = v157 * v1187;
        let v1234: f64 = v111 * v1183;
        let v1235: f64 = v142 * v1180;
        let v1236: f64 = v1234 - v1235;
        let v1237: f64 = v1233 + v1236;
        let v1238: f64 = v1232 + v1237;
        let v1239: f64 = v68 * v1238;
        let v1240: f64 = v1229 + v1239;
        let v1241: f64 = v1228 - v1240;
        let v1242: f64 = v81 * v1241;
        let v1243: f64 = v1208 - v1242;
        let v1244: f64 = v36 * v1243;
        let v1245: f64 = v198 * v1164;
        let v1246: f64 = v200 * v1166;
        let v1247: f64 = v1245 + v1246;
        let v1248: f64 = v150 * v1171;
        let v1249: f64 = v1247 - v1248;
        let v1250: f64 = v95 * v1205;
        let v1251: f64 = v100 * v1194;
        let v1252: f64 = v1250 + v1251;
        let v1253: f64 = v1249 + v1252;
        let v1254: f64 = v112 * v1237;
        let v1255: f64 = v1253 - v1254;
        let v1256: f64 = v72 * v1255;
        let v1257: f64 = v488 * v68;
        let v1258: f64 = v1256 - v1257;
        let v1259: f64 = v510 * v72;
        let v1260: f64 = v216 * v1164;
        let v1261: f64 = v198 * v1166;
        let v1262: f64 = v1260 + v1261;
        let v1263: f64 = v150 * v1175;
        let v1264: f64 = v1262 - v1263;
        let v1265: f64 = v226 * v1164;
        let v1266: f64 = v131 * v1180;
        let v1267: f64 = v1265 + v1266;
        let v1268: f64 = v96 * v1183;
        let v1269: f64 = v1267 + v1268;
        let v1270: f64 = v142 * v1191;
        let v1271: f64 = v111 * v1201;
        let v1272: f64 = v1270 - v1271;
        let v1273: f64 = v1269 + v1272;
        let v1274: f64 = v1264 + v1273;
        let v1275: f64 = v112 * v1224;
        let v1276: f64 = v1274 + v1275;
        let v1277: f64 = v68 * v1276;
        let v1278: f64 = v1259 + v1277;
        let v1279: f64 = v1258 - v1278;
        let v1280: f64 = v95 * v1222;
        let v1281: f64 = v100 * v1216;
        let v1282: f64 = v1280 - v1281;
        let v1283: f64 = v79 * v1164;
        let v1284: f64 = v87 * v1166;
        let v1285: f64 = v1283 - v1284;
        let v1286: f64 = v1282 - v1285;
        let v1287: f64 = v81 * v1286;
        let v1288: f64 = v1279 + v1287;
        let v1289: f64 = v39 * v1288;
        let v1290: f64 = v1244 - v1289;
        let v1291: f64 = v449 * v72;
        let v1292: f64 = v68 * v1225;
        let v1293: f64 = v1291 + v1292;
        let v1294: f64 = v72 * v1238;
        let v1295: f64 = v461 * v68;
        let v1296: f64 = v1294 - v1295;
        let v1297: f64 = v1293 + v1296;
        let v1298: f64 = v60 * v1297;
        let v1299: f64 = v1290 - v1298;
        let v1300: f64 = v36 * v1241;
        let v1301: f64 = v39 * v1286;
        let v1302: f64 = v1300 + v1301;
        let v1303: f64 = v25 * v1302;
        let v1304: f64 = v1299 - v1303;
        let v1305: f64 = v4 * v1304;
        let v1306: f64 = v36 * v1288;
        let v1307: f64 = v39 * v1243;
        let v1308: f64 = v1306 + v1307;
        let v1309: f64 = v36 * v1286;
        let v1310: f64 = v39 * v1241;
        let v1311: f64 = v1309 - v1310;
        let v1312: f64 = v25 * v1311;
        let v1313: f64 = v1308 + v1312;
        let v1314: f64 = v6 * v1313;
        let v1315: f64 = v1305 - v1314;
        let v1316: f64 = v30 * v1297;
        let v1317: f64 = v1315 - v1316;
        let v1318: f64 = v4 * v1302;
        let v1319: f64 = v6 * v1311;
        let v1320: f64 = v1318 + v1319;
        let v1321: f64 = v19 * v1320;
        let v1322: f64 = v1317 - v1321;
        let v1323: f64 = v2 * v1322;
        let v1324: f64 = v4 * v1313;
        let v1325: f64 = v6 * v1304;
        let v1326: f64 = v1324 + v1325;
        let v1327: f64 = v4 * v1311;
        let v1328: f64 = v6 * v1302;
        let v1329: f64 = v1327 - v1328;
        let v1330: f64 = v19 * v1329;
        let v1331: f64 = v1326 + v1330;
        let v1332: f64 = v8 * v1331;
        let v1333: f64 = v1323 - v1332;
        let v1334: f64 = v0 * v1333;
        let v1335: f64 = qd[4];
        let v1336: f64 = v1334 * v1335;
        let v1337: f64 = v1163 + v1336;
        let v1338: f64 = v402 * v100;
        let v1339: f64 = v408 * v95;
        let v1340: f64 = v1338 + v1339;
        let v1341: f64 = v116 * v1340;
        let v1342: f64 = v351 * v95;
        let v1343: f64 = v370 * v100;
        let v1344: f64 = v1342 - v1343;
        let v1345: f64 = v98 * v1344;
        let v1346: f64 = v351 * v100;
        let v1347: f64 = v370 * v95;
        let v1348: f64 = v1346 + v1347;
        let v1349: f64 = v105 * v1348;
        let v1350: f64 = v1345 + v1349;
        let v1351: f64 = v1341 - v1350;
        let v1352: f64 = v95 * v1351;
        let v1353: f64 = v413 * v100;
        let v1354: f64 = v1352 - v1353;
        let v1355: f64 = v426 * v95;
        let v1356: f64 = v402 * v95;
        let v1357: f64 = v408 * v100;
        let v1358: f64 = v1356 - v1357;
        let v1359: f64 = v116 * v1358;
        let v1360: f64 = v133 * v1344;
        let v1361: f64 = v98 * v1348;
        let v1362: f64 = v1360 + v1361;
        let v1363: f64 = v1359 - v1362;
        let v1364: f64 = v100 * v1363;
        let v1365: f64 = v1355 + v1364;
        let v1366: f64 = v1354 - v1365;
        let v1367: f64 = v116 * v1348;
        let v1368: f64 = v157 * v1340;
        let v1369: f64 = v1367 - v1368;
        let v1370: f64 = v95 * v1369;
        let v1371: f64 = v440 * v100;
        let v1372: f64 = v1370 - v1371;
        let v1373: f64 = v446 * v95;
        let v1374: f64 = v157 * v1358;
        let v1375: f64 = v116 * v1344;
        let v1376: f64 = v1374 - v1375;
        let v1377: f64 = v100 * v1376;
        let v1378: f64 = v1373 + v1377;
        let v1379: f64 = v1372 + v1378;
        let v1380: f64 = v72 * v1379;
        let v1381: f64 = v142 * v1344;
        let v1382: f64 = v111 * v1348;
        let v1383: f64 = v1381 - v1382;
        let v1384: f64 = v68 * v1383;
        let v1385: f64 = v1380 - v1384;
        let v1386: f64 = v81 * v1385;
        let v1387: f64 = v1366 - v1386;
        let v1388: f64 = v36 * v1387;
        let v1389: f64 = v95 * v1363;
        let v1390: f64 = v426 * v100;
        let v1391: f64 = v1389 - v1390;
        let v1392: f64 = v413 * v95;
        let v1393: f64 = v100 * v1351;
        let v1394: f64 = v1392 + v1393;
        let v1395: f64 = v1391 + v1394;
        let v1396: f64 = v112 * v1383;
        let v1397: f64 = v1395 - v1396;
        let v1398: f64 = v72 * v1397;
        let v1399: f64 = v112 * v1379;
        (
            v1208,
            v1255,
            v1273,
            v1276,
            v1311,
            v1329,
            v1334,
            v1335,
            v1337,
            v1340,
            v1344,
            v1348,
            v1358,
            v1366,
            v1369,
            v1376,
            v1379,
            v1383,
            v1385,
            v1387,
            v1388,
            v1397,
            v1398,
            v1399,
        )
    };
    let (
        v1406,
        v1407,
        v1437,
        v1455,
        v1460,
        v1461,
        v1464,
        v1465,
        v1468,
        v1475,
        v1476,
        v1478,
        v1482,
        v1488,
        v1493,
        v1498,
        v1502,
        v1503,
        v1508,
        v1509,
        v1512,
        v1516,
        v1519,
        v1520,
        v1524,
        v1526,
        v1528,
        v1529,
        v1535,
        v1537,
        v1539,
        v1544,
        v1551,
        v1557,
        v1563,
        v1571,
        v1573,
        v1575,
        v1577,
        v1584,
        v1586,
        v1596,
        v1599,
    ) = {
        let v1400: f64 = v131 * v1344;
        let v1401: f64 = v96 * v1348;
        let v1402: f64 = v1400 + v1401;
        let v1403: f64 = v142 * v1340;
        let v1404: f64 = v111 * v1358;
        let v1405: f64 = v1403 + v1404;
        let v1406: f64 = v1402 + v1405;
        let v1407: f64 = v1399 - v1406;
        let v1408: f64 = v68 * v1407;
        let v1409: f64 = v1398 - v1408;
        let v1410: f64 = v95 * v1376;
        let v1411: f64 = v446 * v100;
        let v1412: f64 = v1410 - v1411;
        let v1413: f64 = v440 * v95;
        let v1414: f64 = v100 * v1369;
        let v1415: f64 = v1413 + v1414;
        let v1416: f64 = v1412 - v1415;
        let v1417: f64 = v81 * v1416;
        let v1418: f64 = v1409 + v1417;
        let v1419: f64 = v39 * v1418;
        let v1420: f64 = v1388 - v1419;
        let v1421: f64 = v68 * v1379;
        let v1422: f64 = v72 * v1383;
        let v1423: f64 = v1421 + v1422;
        let v1424: f64 = v60 * v1423;
        let v1425: f64 = v1420 - v1424;
        let v1426: f64 = v36 * v1385;
        let v1427: f64 = v39 * v1416;
        let v1428: f64 = v1426 + v1427;
        let v1429: f64 = v25 * v1428;
        let v1430: f64 = v1425 - v1429;
        let v1431: f64 = v4 * v1430;
        let v1432: f64 = v36 * v1418;
        let v1433: f64 = v39 * v1387;
        let v1434: f64 = v1432 + v1433;
        let v1435: f64 = v36 * v1416;
        let v1436: f64 = v39 * v1385;
        let v1437: f64 = v1435 - v1436;
        let v1438: f64 = v25 * v1437;
        let v1439: f64 = v1434 + v1438;
        let v1440: f64 = v6 * v1439;
        let v1441: f64 = v1431 - v1440;
        let v1442: f64 = v30 * v1423;
        let v1443: f64 = v1441 - v1442;
        let v1444: f64 = v4 * v1428;
        let v1445: f64 = v6 * v1437;
        let v1446: f64 = v1444 + v1445;
        let v1447: f64 = v19 * v1446;
        let v1448: f64 = v1443 - v1447;
        let v1449: f64 = v2 * v1448;
        let v1450: f64 = v4 * v1439;
        let v1451: f64 = v6 * v1430;
        let v1452: f64 = v1450 + v1451;
        let v1453: f64 = v4 * v1437;
        let v1454: f64 = v6 * v1428;
        let v1455: f64 = v1453 - v1454;
        let v1456: f64 = v19 * v1455;
        let v1457: f64 = v1452 + v1456;
        let v1458: f64 = v8 * v1457;
        let v1459: f64 = v1449 - v1458;
        let v1460: f64 = v0 * v1459;
        let v1461: f64 = qd[5];
        let v1462: f64 = v1460 * v1461;
        let v1463: f64 = v1337 + v1462;
        let v1464: f64 = -v1463;
        let v1465: f64 = params[38];
        let v1466: f64 = v71 * v68;
        let v1467: f64 = v66 * v72;
        let v1468: f64 = v1466 + v1467;
        let v1469: f64 = v95 * v68;
        let v1470: f64 = v98 * v1469;
        let v1471: f64 = v96 * v72;
        let v1472: f64 = v1470 + v1471;
        let v1473: f64 = v100 * v68;
        let v1474: f64 = v105 * v1473;
        let v1475: f64 = v1472 + v1474;
        let v1476: f64 = v112 * v68;
        let v1477: f64 = v111 * v1476;
        let v1478: f64 = v112 * v72;
        let v1479: f64 = v95 * v1478;
        let v1480: f64 = v116 * v1479;
        let v1481: f64 = v1477 + v1480;
        let v1482: f64 = v1475 - v1481;
        let v1483: f64 = v95 * v1482;
        let v1484: f64 = v133 * v1469;
        let v1485: f64 = v131 * v72;
        let v1486: f64 = v1484 + v1485;
        let v1487: f64 = v98 * v1473;
        let v1488: f64 = v1486 + v1487;
        let v1489: f64 = v100 * v1478;
        let v1490: f64 = v116 * v1489;
        let v1491: f64 = v142 * v1476;
        let v1492: f64 = v1490 + v1491;
        let v1493: f64 = v1488 + v1492;
        let v1494: f64 = v100 * v1493;
        let v1495: f64 = v1483 - v1494;
        let v1496: f64 = v1468 + v1495;
        let v1497: f64 = v1465 + v1496;
        let v1498: f64 = v150 * v72;
        let v1499: f64 = v157 * v1479;
        let v1500: f64 = v142 * v72;
        let v1501: f64 = v116 * v1473;
        let v1502: f64 = v1500 - v1501;
        let v1503: f64 = v1499 + v1502;
        let v1504: f64 = v95 * v1503;
        let v1505: f64 = v157 * v1489;
        let v1506: f64 = v116 * v1469;
        let v1507: f64 = v111 * v72;
        let v1508: f64 = v1506 - v1507;
        let v1509: f64 = v1505 + v1508;
        let v1510: f64 = v100 * v1509;
        let v1511: f64 = v1504 + v1510;
        let v1512: f64 = v1498 + v1511;
        let v1513: f64 = v72 * v1512;
        let v1514: f64 = v111 * v1473;
        let v1515: f64 = v142 * v1469;
        let v1516: f64 = v1514 - v1515;
        let v1517: f64 = v157 * v1476;
        let v1518: f64 = v1516 - v1517;
        let v1519: f64 = v150 * v68;
        let v1520: f64 = v1518 - v1519;
        let v1521: f64 = v68 * v1520;
        let v1522: f64 = v1513 - v1521;
        let v1523: f64 = v81 * v1522;
        let v1524: f64 = v1497 - v1523;
        let v1525: f64 = v36 * v1524;
        let v1526: f64 = params[35];
        let v1527: f64 = v200 * v68;
        let v1528: f64 = v198 * v72;
        let v1529: f64 = v1527 + v1528;
        let v1530: f64 = v95 * v1493;
        let v1531: f64 = v100 * v1482;
        let v1532: f64 = v1530 + v1531;
        let v1533: f64 = v1529 + v1532;
        let v1534: f64 = v112 * v1518;
        let v1535: f64 = v1533 - v1534;
        let v1536: f64 = v72 * v1535;
        let v1537: f64 = v198 * v68;
        let v1538: f64 = v216 * v72;
        let v1539: f64 = v1537 + v1538;
        let v1540: f64 = v131 * v1469;
        let v1541: f64 = v226 * v72;
        let v1542: f64 = v1540 + v1541;
        let v1543: f64 = v96 * v1473;
        let v1544: f64 = v1542 + v1543;
        let v1545: f64 = v142 * v1479;
        let v1546: f64 = v111 * v1489;
        let v1547: f64 = v1545 - v1546;
        let v1548: f64 = v1544 + v1547;
        let v1549: f64 = v1539 + v1548;
        let v1550: f64 = v112 * v1511;
        let v1551: f64 = v1549 + v1550;
        let v1552: f64 = v68 * v1551;
        let v1553: f64 = v1536 - v1552;
        let v1554: f64 = v1526 + v1553;
        let v1555: f64 = v87 * v68;
        let v1556: f64 = v79 * v72;
        let v1557: f64 = v1555 - v1556;
        let v1558: f64 = v95 * v1509;
        let v1559: f64 = v100 * v1503;
        let v1560: f64 = v1558 - v1559;
        let v1561: f64 = v1557 + v1560;
        let v1562: f64 = v81 * v1561;
        let v1563: f64 = v1554 + v1562;
        let v1564: f64 = v39 * v1563;
        let v1565: f64 = v1525 - v1564;
        let v1566: f64 = v68 * v1512;
        let v1567: f64 = v72 * v1520;
        let v1568: f64 = v1566 + v1567;
        let v1569: f64 = v60 * v1568;
        let v1570: f64 = v1565 - v1569;
        let v1571: f64 = v194 + v1522;
        let v1572: f64 = v36 * v1571;
        let v1573: f64 = v1561 - v59;
        let v1574: f64 = v39 * v1573;
        let v1575: f64 = v1572 + v1574;
        let v1576: f64 = v25 * v1575;
        let v1577: f64 = v1570 - v1576;
        let v1578: f64 = v4 * v1577;
        let v1579: f64 = v36 * v1563;
        let v1580: f64 = v39 * v1524;
        let v1581: f64 = v1579 + v1580;
        let v1582: f64 = v36 * v1573;
        let v1583: f64 = v39 * v1571;
        let v1584: f64 = v1582 - v1583;
        let v1585: f64 = v25 * v1584;
        let v1586: f64 = v1581 + v1585;
        let v1587: f64 = v6 * v1586;
        let v1588: f64 = v1578 - v1587;
        let v1589: f64 = v30 * v1568;
        let v1590: f64 = v1588 - v1589;
        let v1591: f64 = v4 * v1575;
        let v1592: f64 = v6 * v1584;
        let v1593: f64 = v1591 + v1592;
        let v1594: f64 = v19 * v1593;
        let v1595: f64 = v1590 - v1594;
        let v1596: f64 = v1595 * v8;
        let v1597: f64 = v4 * v1586;
        let v1598: f64 = v6 * v1577;
        let v1599: f64 = v1597 + v1598;
        (
            v1406,
            v1407,
            v1437,
            v1455,
            v1460,
            v1461,
            v1464,
            v1465,
            v1468,
            v1475,
            v1476,
            v1478,
            v1482,
            v1488,
            v1493,
            v1498,
            v1502,
            v1503,
            v1508,
            v1509,
            v1512,
            v1516,
            v1519,
            v1520,
            v1524,
            v1526,
            v1528,
            v1529,
            v1535,
            v1537,
            v1539,
            v1544,
            v1551,
            v1557,
            v1563,
            v1571,
            v1573,
            v1575,
            v1577,
            v1584,
            v1586,
            v1596,
            v1599,
        )
    };
    let (
        v1606,
        v1607,
        v1610,
        v1612,
        v1622,
        v1637,
        v1653,
        v1656,
        v1657,
        v1668,
        v1671,
        v1672,
        v1677,
        v1685,
        v1693,
        v1696,
        v1699,
        v1705,
        v1709,
        v1723,
        v1735,
        v1746,
        v1756,
        v1760,
        v1766,
        v1777,
        v1783,
        v1785,
        v1787,
        v1791,
        v1793,
        v1796,
        v1797,
        v1799,
    ) = {
        let v1600: f64 = v4 * v1584;
        let v1601: f64 = v6 * v1575;
        let v1602: f64 = v1600 - v1601;
        let v1603: f64 = v19 * v1602;
        let v1604: f64 = v1599 + v1603;
        let v1605: f64 = v1604 * v2;
        let v1606: f64 = v1596 + v1605;
        let v1607: f64 = v30 * v4;
        let v1608: f64 = v1607 + v60;
        let v1609: f64 = v1608 * v36;
        let v1610: f64 = v30 * v6;
        let v1611: f64 = v1610 * v39;
        let v1612: f64 = v1609 - v1611;
        let v1613: f64 = v49 * v1612;
        let v1614: f64 = v68 * v1612;
        let v1615: f64 = v79 * v1614;
        let v1616: f64 = v72 * v1612;
        let v1617: f64 = v87 * v1616;
        let v1618: f64 = v1615 + v1617;
        let v1619: f64 = v111 * v1614;
        let v1620: f64 = v1608 * v39;
        let v1621: f64 = v1610 * v36;
        let v1622: f64 = v1620 + v1621;
        let v1623: f64 = v100 * v1622;
        let v1624: f64 = v95 * v1616;
        let v1625: f64 = v1623 - v1624;
        let v1626: f64 = v116 * v1625;
        let v1627: f64 = v1619 - v1626;
        let v1628: f64 = v95 * v1627;
        let v1629: f64 = v100 * v1616;
        let v1630: f64 = v95 * v1622;
        let v1631: f64 = v1629 + v1630;
        let v1632: f64 = v116 * v1631;
        let v1633: f64 = v142 * v1614;
        let v1634: f64 = v1632 + v1633;
        let v1635: f64 = v100 * v1634;
        let v1636: f64 = v1628 + v1635;
        let v1637: f64 = v1618 + v1636;
        let v1638: f64 = v1613 + v1637;
        let v1639: f64 = v157 * v1625;
        let v1640: f64 = v95 * v1639;
        let v1641: f64 = v157 * v1631;
        let v1642: f64 = v100 * v1641;
        let v1643: f64 = v1640 - v1642;
        let v1644: f64 = v154 * v1616;
        let v1645: f64 = v1643 - v1644;
        let v1646: f64 = v72 * v1645;
        let v1647: f64 = v154 * v1614;
        let v1648: f64 = v157 * v1614;
        let v1649: f64 = v1647 + v1648;
        let v1650: f64 = v68 * v1649;
        let v1651: f64 = v1646 - v1650;
        let v1652: f64 = v81 * v1651;
        let v1653: f64 = v1638 - v1652;
        let v1654: f64 = v36 * v1653;
        let v1655: f64 = v39 * v1608;
        let v1656: f64 = v36 * v1610;
        let v1657: f64 = v1655 + v1656;
        let v1658: f64 = v49 * v1657;
        let v1659: f64 = v1465 + v1658;
        let v1660: f64 = v68 * v1657;
        let v1661: f64 = v79 * v1660;
        let v1662: f64 = v72 * v1657;
        let v1663: f64 = v87 * v1662;
        let v1664: f64 = v1661 + v1663;
        let v1665: f64 = v1468 + v1664;
        let v1666: f64 = v1660 - v1476;
        let v1667: f64 = v111 * v1666;
        let v1668: f64 = v1478 - v1662;
        let v1669: f64 = v95 * v1668;
        let v1670: f64 = v36 * v1608;
        let v1671: f64 = v39 * v1610;
        let v1672: f64 = v1670 - v1671;
        let v1673: f64 = v100 * v1672;
        let v1674: f64 = v1669 - v1673;
        let v1675: f64 = v116 * v1674;
        let v1676: f64 = v1667 - v1675;
        let v1677: f64 = v1475 + v1676;
        let v1678: f64 = v95 * v1677;
        let v1679: f64 = v100 * v1668;
        let v1680: f64 = v95 * v1672;
        let v1681: f64 = v1679 + v1680;
        let v1682: f64 = v116 * v1681;
        let v1683: f64 = v142 * v1666;
        let v1684: f64 = v1682 - v1683;
        let v1685: f64 = v1488 + v1684;
        let v1686: f64 = v100 * v1685;
        let v1687: f64 = v1678 - v1686;
        let v1688: f64 = v1665 + v1687;
        let v1689: f64 = v1659 + v1688;
        let v1690: f64 = v154 * v1662;
        let v1691: f64 = v1498 - v1690;
        let v1692: f64 = v157 * v1674;
        let v1693: f64 = v1692 + v1502;
        let v1694: f64 = v95 * v1693;
        let v1695: f64 = v157 * v1681;
        let v1696: f64 = v1695 + v1508;
        let v1697: f64 = v100 * v1696;
        let v1698: f64 = v1694 + v1697;
        let v1699: f64 = v1691 + v1698;
        let v1700: f64 = v72 * v1699;
        let v1701: f64 = v154 * v1660;
        let v1702: f64 = v1701 - v1519;
        let v1703: f64 = v157 * v1666;
        let v1704: f64 = v1703 + v1516;
        let v1705: f64 = v1702 + v1704;
        let v1706: f64 = v68 * v1705;
        let v1707: f64 = v1700 - v1706;
        let v1708: f64 = v81 * v1707;
        let v1709: f64 = v1689 - v1708;
        let v1710: f64 = v1709 * v39;
        let v1711: f64 = v1654 - v1710;
        let v1712: f64 = v49 * v1672;
        let v1713: f64 = v1526 + v1712;
        let v1714: f64 = v87 * v1672;
        let v1715: f64 = v150 * v1660;
        let v1716: f64 = v1714 - v1715;
        let v1717: f64 = v1529 + v1716;
        let v1718: f64 = v95 * v1685;
        let v1719: f64 = v100 * v1677;
        let v1720: f64 = v1718 + v1719;
        let v1721: f64 = v1717 + v1720;
        let v1722: f64 = v112 * v1704;
        let v1723: f64 = v1721 - v1722;
        let v1724: f64 = v72 * v1723;
        let v1725: f64 = v150 * v1662;
        let v1726: f64 = v79 * v1672;
        let v1727: f64 = v1725 + v1726;
        let v1728: f64 = v1539 - v1727;
        let v1729: f64 = v142 * v1674;
        let v1730: f64 = v111 * v1681;
        let v1731: f64 = v1729 - v1730;
        let v1732: f64 = v1544 + v1731;
        let v1733: f64 = v1728 + v1732;
        let v1734: f64 = v112 * v1698;
        let v1735: f64 = v1733 + v1734;
        let v1736: f64 = v68 * v1735;
        let v1737: f64 = v1724 - v1736;
        let v1738: f64 = v1713 + v1737;
        let v1739: f64 = v154 * v1672;
        let v1740: f64 = v1739 + v1557;
        let v1741: f64 = v95 * v1696;
        let v1742: f64 = v100 * v1693;
        let v1743: f64 = v1741 - v1742;
        let v1744: f64 = v1740 + v1743;
        let v1745: f64 = v81 * v1744;
        let v1746: f64 = v1738 + v1745;
        let v1747: f64 = v1746 * v36;
        let v1748: f64 = v100 * v1627;
        let v1749: f64 = v95 * v1634;
        let v1750: f64 = v1748 - v1749;
        let v1751: f64 = v87 * v1622;
        let v1752: f64 = v150 * v1614;
        let v1753: f64 = v1751 + v1752;
        let v1754: f64 = v1750 - v1753;
        let v1755: f64 = v112 * v1648;
        let v1756: f64 = v1754 - v1755;
        let v1757: f64 = v72 * v1756;
        let v1758: f64 = v142 * v1625;
        let v1759: f64 = v111 * v1631;
        let v1760: f64 = v1758 + v1759;
        let v1761: f64 = v150 * v1616;
        let v1762: f64 = v79 * v1622;
        let v1763: f64 = v1761 - v1762;
        let v1764: f64 = v1760 - v1763;
        let v1765: f64 = v112 * v1643;
        let v1766: f64 = v1764 + v1765;
        let v1767: f64 = v68 * v1766;
        let v1768: f64 = v1757 - v1767;
        let v1769: f64 = v49 * v1622;
        let v1770: f64 = v1768 - v1769;
        let v1771: f64 = v154 * v1622;
        let v1772: f64 = v95 * v1641;
        let v1773: f64 = v100 * v1639;
        let v1774: f64 = v1772 + v1773;
        let v1775: f64 = v1771 + v1774;
        let v1776: f64 = v81 * v1775;
        let v1777: f64 = v1770 - v1776;
        let v1778: f64 = v39 * v1777;
        let v1779: f64 = v1747 + v1778;
        let v1780: f64 = v1711 - v1779;
        let v1781: f64 = v68 * v1645;
        let v1782: f64 = v72 * v1649;
        let v1783: f64 = v1781 + v1782;
        let v1784: f64 = v60 * v1783;
        let v1785: f64 = v1780 - v1784;
        let v1786: f64 = v259 * v1612;
        let v1787: f64 = v1651 - v1786;
        let v1788: f64 = v36 * v1787;
        let v1789: f64 = v259 * v1657;
        let v1790: f64 = v194 - v1789;
        let v1791: f64 = v1790 + v1707;
        let v1792: f64 = v1791 * v39;
        let v1793: f64 = v1788 - v1792;
        let v1794: f64 = v259 * v1672;
        let v1795: f64 = v1794 - v59;
        let v1796: f64 = v1795 + v1744;
        let v1797: f64 = v1796 * v36;
        let v1798: f64 = v259 * v1622;
        let v1799: f64 = v1798 + v1775;
        (
            v1606,
            v1607,
            v1610,
            v1612,
            v1622,
            v1637,
            v1653,
            v1656,
            v1657,
            v1668,
            v1671,
            v1672,
            v1677,
            v1685,
            v1693,
            v1696,
            v1699,
            v1705,
            v1709,
            v1723,
            v1735,
            v1746,
            v1756,
            v1760,
            v1766,
            v1777,
            v1783,
            v1785,
            v1787,
            v1791,
            v1793,
            v1796,
            v1797,
            v1799,
        )
    };
    let (
        v1812,
        v1837,
        v1841,
        v1843,
        v1844,
        v1845,
        v1846,
        v1847,
        v1848,
        v1855,
        v1860,
        v1862,
        v1864,
        v1865,
        v1876,
        v1881,
        v1883,
        v1887,
        v1895,
        v1905,
        v1910,
        v1914,
        v1916,
        v1925,
        v1940,
        v1956,
        v1966,
        v1970,
        v1976,
        v1985,
        v1987,
        v1993,
        v1995,
        v1997,
        v1998,
        v1999,
    ) = {
        let v1800: f64 = v39 * v1799;
        let v1801: f64 = v1797 - v1800;
        let v1802: f64 = v1793 + v1801;
        let v1803: f64 = v25 * v1802;
        let v1804: f64 = v1785 - v1803;
        let v1805: f64 = v4 * v1804;
        let v1806: f64 = v1796 * v39;
        let v1807: f64 = v36 * v1799;
        let v1808: f64 = v1806 + v1807;
        let v1809: f64 = v1791 * v36;
        let v1810: f64 = v39 * v1787;
        let v1811: f64 = v1809 + v1810;
        let v1812: f64 = v1808 + v1811;
        let v1813: f64 = v25 * v1812;
        let v1814: f64 = v36 * v1777;
        let v1815: f64 = v1746 * v39;
        let v1816: f64 = v1814 - v1815;
        let v1817: f64 = v1709 * v36;
        let v1818: f64 = v39 * v1653;
        let v1819: f64 = v1817 + v1818;
        let v1820: f64 = v1816 + v1819;
        let v1821: f64 = v1813 - v1820;
        let v1822: f64 = v6 * v1821;
        let v1823: f64 = v1805 + v1822;
        let v1824: f64 = v30 * v1783;
        let v1825: f64 = v1823 - v1824;
        let v1826: f64 = v6 * v1812;
        let v1827: f64 = v4 * v1802;
        let v1828: f64 = v1826 - v1827;
        let v1829: f64 = v19 * v1828;
        let v1830: f64 = v1825 + v1829;
        let v1831: f64 = v2 * v1830;
        let v1832: f64 = v4 * v1821;
        let v1833: f64 = v6 * v1804;
        let v1834: f64 = v1832 - v1833;
        let v1835: f64 = v4 * v1812;
        let v1836: f64 = v6 * v1802;
        let v1837: f64 = v1835 + v1836;
        let v1838: f64 = v19 * v1837;
        let v1839: f64 = v1834 + v1838;
        let v1840: f64 = v8 * v1839;
        let v1841: f64 = v1831 + v1840;
        let v1842: f64 = v1606 - v1841;
        let v1843: f64 = v0 * v1842;
        let v1844: f64 = v1843 * v1161;
        let v1845: f64 = qd[0];
        let v1846: f64 = v634 * v1845;
        let v1847: f64 = params[18];
        let v1848: f64 = params[28];
        let v1849: f64 = v18 * v1607;
        let v1850: f64 = v1848 - v1849;
        let v1851: f64 = v36 * v1746;
        let v1852: f64 = v39 * v1709;
        let v1853: f64 = v1851 + v1852;
        let v1854: f64 = v1850 - v1853;
        let v1855: f64 = v268 * v1607;
        let v1856: f64 = v1855 + v29;
        let v1857: f64 = v36 * v1796;
        let v1858: f64 = v39 * v1791;
        let v1859: f64 = v1857 - v1858;
        let v1860: f64 = v1856 + v1859;
        let v1861: f64 = v25 * v1860;
        let v1862: f64 = v1854 - v1861;
        let v1863: f64 = v4 * v1862;
        let v1864: f64 = params[25];
        let v1865: f64 = v18 * v1610;
        let v1866: f64 = v1864 + v1865;
        let v1867: f64 = v36 * v1709;
        let v1868: f64 = v39 * v1746;
        let v1869: f64 = v1867 - v1868;
        let v1870: f64 = v1866 + v1869;
        let v1871: f64 = v68 * v1699;
        let v1872: f64 = v72 * v1705;
        let v1873: f64 = v1871 + v1872;
        let v1874: f64 = v60 * v1873;
        let v1875: f64 = v1870 - v1874;
        let v1876: f64 = v268 * v1610;
        let v1877: f64 = v1876 - v292;
        let v1878: f64 = v36 * v1791;
        let v1879: f64 = v39 * v1796;
        let v1880: f64 = v1878 + v1879;
        let v1881: f64 = v1877 - v1880;
        let v1882: f64 = v25 * v1881;
        let v1883: f64 = v1875 + v1882;
        let v1884: f64 = v6 * v1883;
        let v1885: f64 = v1863 - v1884;
        let v1886: f64 = v1847 + v1885;
        let v1887: f64 = params[13];
        let v1888: f64 = v4 * v1860;
        let v1889: f64 = v6 * v1881;
        let v1890: f64 = v1888 + v1889;
        let v1891: f64 = v1887 + v1890;
        let v1892: f64 = v19 * v1891;
        let v1893: f64 = v1886 - v1892;
        let v1894: f64 = v1893 * v2;
        let v1895: f64 = params[15];
        let v1896: f64 = v4 * v1883;
        let v1897: f64 = v6 * v1862;
        let v1898: f64 = v1896 + v1897;
        let v1899: f64 = v1895 + v1898;
        let v1900: f64 = v30 * v1873;
        let v1901: f64 = v1899 - v1900;
        let v1902: f64 = v4 * v1881;
        let v1903: f64 = v6 * v1860;
        let v1904: f64 = v1902 - v1903;
        let v1905: f64 = params[11];
        let v1906: f64 = v1904 - v1905;
        let v1907: f64 = v19 * v1906;
        let v1908: f64 = v1901 + v1907;
        let v1909: f64 = v1908 * v8;
        let v1910: f64 = v1894 - v1909;
        let v1911: f64 = v1910 + v1910;
        let v1912: f64 = v0 * v1911;
        let v1913: f64 = v1912 * v635;
        let v1914: f64 = v1846 + v1913;
        let v1915: f64 = v36 * v1607;
        let v1916: f64 = v1915 - v1671;
        let v1917: f64 = v49 * v1916;
        let v1918: f64 = v68 * v1916;
        let v1919: f64 = v79 * v1918;
        let v1920: f64 = v72 * v1916;
        let v1921: f64 = v87 * v1920;
        let v1922: f64 = v1919 + v1921;
        let v1923: f64 = v111 * v1918;
        let v1924: f64 = v39 * v1607;
        let v1925: f64 = v1656 + v1924;
        let v1926: f64 = v100 * v1925;
        let v1927: f64 = v95 * v1920;
        let v1928: f64 = v1926 - v1927;
        let v1929: f64 = v116 * v1928;
        let v1930: f64 = v1923 - v1929;
        let v1931: f64 = v95 * v1930;
        let v1932: f64 = v100 * v1920;
        let v1933: f64 = v95 * v1925;
        let v1934: f64 = v1932 + v1933;
        let v1935: f64 = v116 * v1934;
        let v1936: f64 = v142 * v1918;
        let v1937: f64 = v1935 + v1936;
        let v1938: f64 = v100 * v1937;
        let v1939: f64 = v1931 + v1938;
        let v1940: f64 = v1922 + v1939;
        let v1941: f64 = v1917 + v1940;
        let v1942: f64 = v157 * v1928;
        let v1943: f64 = v95 * v1942;
        let v1944: f64 = v157 * v1934;
        let v1945: f64 = v100 * v1944;
        let v1946: f64 = v1943 - v1945;
        let v1947: f64 = v154 * v1920;
        let v1948: f64 = v1946 - v1947;
        let v1949: f64 = v72 * v1948;
        let v1950: f64 = v154 * v1918;
        let v1951: f64 = v157 * v1918;
        let v1952: f64 = v1950 + v1951;
        let v1953: f64 = v68 * v1952;
        let v1954: f64 = v1949 - v1953;
        let v1955: f64 = v81 * v1954;
        let v1956: f64 = v1941 - v1955;
        let v1957: f64 = v36 * v1956;
        let v1958: f64 = v100 * v1930;
        let v1959: f64 = v95 * v1937;
        let v1960: f64 = v1958 - v1959;
        let v1961: f64 = v87 * v1925;
        let v1962: f64 = v150 * v1918;
        let v1963: f64 = v1961 + v1962;
        let v1964: f64 = v1960 - v1963;
        let v1965: f64 = v112 * v1951;
        let v1966: f64 = v1964 - v1965;
        let v1967: f64 = v72 * v1966;
        let v1968: f64 = v142 * v1928;
        let v1969: f64 = v111 * v1934;
        let v1970: f64 = v1968 + v1969;
        let v1971: f64 = v150 * v1920;
        let v1972: f64 = v79 * v1925;
        let v1973: f64 = v1971 - v1972;
        let v1974: f64 = v1970 - v1973;
        let v1975: f64 = v112 * v1946;
        let v1976: f64 = v1974 + v1975;
        let v1977: f64 = v68 * v1976;
        let v1978: f64 = v1967 - v1977;
        let v1979: f64 = v49 * v1925;
        let v1980: f64 = v1978 - v1979;
        let v1981: f64 = v154 * v1925;
        let v1982: f64 = v95 * v1944;
        let v1983: f64 = v100 * v1942;
        let v1984: f64 = v1982 + v1983;
        let v1985: f64 = v1981 + v1984;
        let v1986: f64 = v81 * v1985;
        let v1987: f64 = v1980 - v1986;
        let v1988: f64 = v39 * v1987;
        let v1989: f64 = v1957 - v1988;
        let v1990: f64 = v1849 + v1989;
        let v1991: f64 = v68 * v1948;
        let v1992: f64 = v72 * v1952;
        let v1993: f64 = v1991 + v1992;
        let v1994: f64 = v60 * v1993;
        let v1995: f64 = v1990 - v1994;
        let v1996: f64 = v259 * v1916;
        let v1997: f64 = v1954 - v1996;
        let v1998: f64 = v36 * v1997;
        let v1999: f64 = v259 * v1925;
        (
            v1812,
            v1837,
            v1841,
            v1843,
            v1844,
            v1845,
            v1846,
            v1847,
            v1848,
            v1855,
            v1860,
            v1862,
            v1864,
            v1865,
            v1876,
            v1881,
            v1883,
            v1887,
            v1895,
            v1905,
            v1910,
            v1914,
            v1916,
            v1925,
            v1940,
            v1956,
            v1966,
            v1970,
            v1976,
            v1985,
            v1987,
            v1993,
            v1995,
            v1997,
            v1998,
            v1999,
        )
    };
    let (
        v2016,
        v2048,
        v2052,
        v2053,
        v2054,
        v2057,
        v2063,
        v2071,
        v2079,
        v2086,
        v2098,
        v2101,
        v2105,
        v2116,
        v2118,
        v2131,
        v2135,
        v2139,
        v2143,
        v2145,
        v2147,
        v2149,
        v2152,
        v2154,
        v2168,
        v2170,
        v2190,
        v2195,
        v2197,
        v2198,
        v2199,
    ) = {
        let v2000: f64 = v1999 + v1985;
        let v2001: f64 = v39 * v2000;
        let v2002: f64 = v1998 - v2001;
        let v2003: f64 = v1855 - v2002;
        let v2004: f64 = v25 * v2003;
        let v2005: f64 = v1995 + v2004;
        let v2006: f64 = v4 * v2005;
        let v2007: f64 = v1883 * v6;
        let v2008: f64 = v2006 - v2007;
        let v2009: f64 = v1862 * v4;
        let v2010: f64 = v36 * v1987;
        let v2011: f64 = v39 * v1956;
        let v2012: f64 = v2010 + v2011;
        let v2013: f64 = v1865 - v2012;
        let v2014: f64 = v36 * v2000;
        let v2015: f64 = v39 * v1997;
        let v2016: f64 = v2014 + v2015;
        let v2017: f64 = v1876 + v2016;
        let v2018: f64 = v25 * v2017;
        let v2019: f64 = v2013 + v2018;
        let v2020: f64 = v6 * v2019;
        let v2021: f64 = v2009 + v2020;
        let v2022: f64 = v2008 + v2021;
        let v2023: f64 = v30 * v1993;
        let v2024: f64 = v2022 - v2023;
        let v2025: f64 = v4 * v2003;
        let v2026: f64 = v1881 * v6;
        let v2027: f64 = v2025 - v2026;
        let v2028: f64 = v1860 * v4;
        let v2029: f64 = v6 * v2017;
        let v2030: f64 = v2028 - v2029;
        let v2031: f64 = v2027 - v2030;
        let v2032: f64 = v19 * v2031;
        let v2033: f64 = v2024 + v2032;
        let v2034: f64 = v2 * v2033;
        let v2035: f64 = v4 * v2019;
        let v2036: f64 = v1862 * v6;
        let v2037: f64 = v2035 - v2036;
        let v2038: f64 = v1883 * v4;
        let v2039: f64 = v6 * v2005;
        let v2040: f64 = v2038 + v2039;
        let v2041: f64 = v2037 - v2040;
        let v2042: f64 = v1881 * v4;
        let v2043: f64 = v6 * v2003;
        let v2044: f64 = v2042 + v2043;
        let v2045: f64 = v1860 * v6;
        let v2046: f64 = v4 * v2017;
        let v2047: f64 = v2045 + v2046;
        let v2048: f64 = v2044 - v2047;
        let v2049: f64 = v19 * v2048;
        let v2050: f64 = v2041 - v2049;
        let v2051: f64 = v8 * v2050;
        let v2052: f64 = v2034 + v2051;
        let v2053: f64 = v60 * v36;
        let v2054: f64 = v49 * v2053;
        let v2055: f64 = v1526 + v2054;
        let v2056: f64 = v87 * v2053;
        let v2057: f64 = v60 * v39;
        let v2058: f64 = v68 * v2057;
        let v2059: f64 = v150 * v2058;
        let v2060: f64 = v2056 - v2059;
        let v2061: f64 = v1529 + v2060;
        let v2062: f64 = v72 * v2057;
        let v2063: f64 = v1478 - v2062;
        let v2064: f64 = v100 * v2063;
        let v2065: f64 = v95 * v2053;
        let v2066: f64 = v2064 + v2065;
        let v2067: f64 = v116 * v2066;
        let v2068: f64 = v2058 - v1476;
        let v2069: f64 = v142 * v2068;
        let v2070: f64 = v2067 - v2069;
        let v2071: f64 = v1488 + v2070;
        let v2072: f64 = v95 * v2071;
        let v2073: f64 = v111 * v2068;
        let v2074: f64 = v95 * v2063;
        let v2075: f64 = v100 * v2053;
        let v2076: f64 = v2074 - v2075;
        let v2077: f64 = v116 * v2076;
        let v2078: f64 = v2073 - v2077;
        let v2079: f64 = v1475 + v2078;
        let v2080: f64 = v100 * v2079;
        let v2081: f64 = v2072 + v2080;
        let v2082: f64 = v2061 + v2081;
        let v2083: f64 = v157 * v2068;
        let v2084: f64 = v2083 + v1516;
        let v2085: f64 = v112 * v2084;
        let v2086: f64 = v2082 - v2085;
        let v2087: f64 = v72 * v2086;
        let v2088: f64 = v150 * v2062;
        let v2089: f64 = v79 * v2053;
        let v2090: f64 = v2088 + v2089;
        let v2091: f64 = v1539 - v2090;
        let v2092: f64 = v142 * v2076;
        let v2093: f64 = v111 * v2066;
        let v2094: f64 = v2092 - v2093;
        let v2095: f64 = v1544 + v2094;
        let v2096: f64 = v2091 + v2095;
        let v2097: f64 = v157 * v2076;
        let v2098: f64 = v2097 + v1502;
        let v2099: f64 = v95 * v2098;
        let v2100: f64 = v157 * v2066;
        let v2101: f64 = v2100 + v1508;
        let v2102: f64 = v100 * v2101;
        let v2103: f64 = v2099 + v2102;
        let v2104: f64 = v112 * v2103;
        let v2105: f64 = v2096 + v2104;
        let v2106: f64 = v68 * v2105;
        let v2107: f64 = v2087 - v2106;
        let v2108: f64 = v2055 + v2107;
        let v2109: f64 = v154 * v2053;
        let v2110: f64 = v2109 + v1557;
        let v2111: f64 = v95 * v2101;
        let v2112: f64 = v100 * v2098;
        let v2113: f64 = v2111 - v2112;
        let v2114: f64 = v2110 + v2113;
        let v2115: f64 = v81 * v2114;
        let v2116: f64 = v2108 + v2115;
        let v2117: f64 = v36 * v2116;
        let v2118: f64 = v49 * v2057;
        let v2119: f64 = v1465 + v2118;
        let v2120: f64 = v79 * v2058;
        let v2121: f64 = v87 * v2062;
        let v2122: f64 = v2120 + v2121;
        let v2123: f64 = v1468 + v2122;
        let v2124: f64 = v95 * v2079;
        let v2125: f64 = v100 * v2071;
        let v2126: f64 = v2124 - v2125;
        let v2127: f64 = v2123 + v2126;
        let v2128: f64 = v2119 + v2127;
        let v2129: f64 = v154 * v2062;
        let v2130: f64 = v1498 - v2129;
        let v2131: f64 = v2130 + v2103;
        let v2132: f64 = v72 * v2131;
        let v2133: f64 = v154 * v2058;
        let v2134: f64 = v2133 - v1519;
        let v2135: f64 = v2134 + v2084;
        let v2136: f64 = v68 * v2135;
        let v2137: f64 = v2132 - v2136;
        let v2138: f64 = v81 * v2137;
        let v2139: f64 = v2128 - v2138;
        let v2140: f64 = v39 * v2139;
        let v2141: f64 = v2117 + v2140;
        let v2142: f64 = v1848 - v2141;
        let v2143: f64 = v259 * v2053;
        let v2144: f64 = v2143 - v59;
        let v2145: f64 = v2144 + v2114;
        let v2146: f64 = v36 * v2145;
        let v2147: f64 = v259 * v2057;
        let v2148: f64 = v194 - v2147;
        let v2149: f64 = v2148 + v2137;
        let v2150: f64 = v39 * v2149;
        let v2151: f64 = v2146 - v2150;
        let v2152: f64 = v29 + v2151;
        let v2153: f64 = v25 * v2152;
        let v2154: f64 = v2142 - v2153;
        let v2155: f64 = v4 * v2154;
        let v2156: f64 = v36 * v2139;
        let v2157: f64 = v39 * v2116;
        let v2158: f64 = v2156 - v2157;
        let v2159: f64 = v1864 + v2158;
        let v2160: f64 = v68 * v2131;
        let v2161: f64 = v72 * v2135;
        let v2162: f64 = v2160 + v2161;
        let v2163: f64 = v60 * v2162;
        let v2164: f64 = v2159 - v2163;
        let v2165: f64 = v36 * v2149;
        let v2166: f64 = v39 * v2145;
        let v2167: f64 = v2165 + v2166;
        let v2168: f64 = v292 + v2167;
        let v2169: f64 = v25 * v2168;
        let v2170: f64 = v2164 - v2169;
        let v2171: f64 = v6 * v2170;
        let v2172: f64 = v2155 - v2171;
        let v2173: f64 = v4 * v2152;
        let v2174: f64 = v6 * v2168;
        let v2175: f64 = v2173 - v2174;
        let v2176: f64 = v19 * v2175;
        let v2177: f64 = v2172 - v2176;
        let v2178: f64 = v2177 * v2;
        let v2179: f64 = v4 * v2170;
        let v2180: f64 = v6 * v2154;
        let v2181: f64 = v2179 + v2180;
        let v2182: f64 = v30 * v2162;
        let v2183: f64 = v2181 - v2182;
        let v2184: f64 = v4 * v2168;
        let v2185: f64 = v6 * v2152;
        let v2186: f64 = v2184 + v2185;
        let v2187: f64 = v19 * v2186;
        let v2188: f64 = v2183 - v2187;
        let v2189: f64 = v2188 * v8;
        let v2190: f64 = v2178 - v2189;
        let v2191: f64 = v2052 + v2190;
        let v2192: f64 = v0 * v2191;
        let v2193: f64 = v2192 * v923;
        let v2194: f64 = v1914 + v2193;
        let v2195: f64 = v1844 - v2194;
        let v2196: f64 = v105 * v95;
        let v2197: f64 = v98 * v100;
        let v2198: f64 = v2196 - v2197;
        let v2199: f64 = v95 * v2198;
        (
            v2016,
            v2048,
            v2052,
            v2053,
            v2054,
            v2057,
            v2063,
            v2071,
            v2079,
            v2086,
            v2098,
            v2101,
            v2105,
            v2116,
            v2118,
            v2131,
            v2135,
            v2139,
            v2143,
            v2145,
            v2147,
            v2149,
            v2152,
            v2154,
            v2168,
            v2170,
            v2190,
            v2195,
            v2197,
            v2198,
            v2199,
        )
    };
    let (
        v2200,
        v2202,
        v2206,
        v2207,
        v2208,
        v2209,
        v2211,
        v2213,
        v2214,
        v2216,
        v2218,
        v2220,
        v2227,
        v2231,
        v2234,
        v2237,
        v2238,
        v2239,
        v2241,
        v2251,
        v2253,
        v2260,
        v2262,
        v2282,
        v2285,
        v2298,
        v2311,
        v2319,
        v2325,
        v2331,
        v2345,
        v2347,
        v2350,
        v2352,
        v2355,
        v2363,
        v2369,
        v2376,
        v2380,
        v2383,
        v2389,
        v2393,
        v2395,
        v2397,
        v2398,
        v2399,
    ) = {
        let v2200: f64 = v98 * v95;
        let v2201: f64 = v133 * v100;
        let v2202: f64 = v2200 - v2201;
        let v2203: f64 = v100 * v2202;
        let v2204: f64 = v2199 - v2203;
        let v2205: f64 = v76 + v2204;
        let v2206: f64 = v116 * v95;
        let v2207: f64 = v95 * v2206;
        let v2208: f64 = v116 * v100;
        let v2209: f64 = v100 * v2208;
        let v2210: f64 = v2207 + v2209;
        let v2211: f64 = v87 + v2210;
        let v2212: f64 = v72 * v2211;
        let v2213: f64 = v111 * v95;
        let v2214: f64 = v142 * v100;
        let v2215: f64 = v2213 + v2214;
        let v2216: f64 = v79 + v2215;
        let v2217: f64 = v68 * v2216;
        let v2218: f64 = v2212 + v2217;
        let v2219: f64 = v81 * v2218;
        let v2220: f64 = v2205 + v2219;
        let v2221: f64 = v36 * v2220;
        let v2222: f64 = v95 * v2202;
        let v2223: f64 = v100 * v2198;
        let v2224: f64 = v2222 + v2223;
        let v2225: f64 = v71 + v2224;
        let v2226: f64 = v112 * v2215;
        let v2227: f64 = v2225 - v2226;
        let v2228: f64 = v72 * v2227;
        let v2229: f64 = v96 * v95;
        let v2230: f64 = v131 * v100;
        let v2231: f64 = v2229 - v2230;
        let v2232: f64 = v66 + v2231;
        let v2233: f64 = v112 * v2210;
        let v2234: f64 = v2232 - v2233;
        let v2235: f64 = v68 * v2234;
        let v2236: f64 = v2228 - v2235;
        let v2237: f64 = v100 * v2206;
        let v2238: f64 = v95 * v2208;
        let v2239: f64 = v2237 - v2238;
        let v2240: f64 = v81 * v2239;
        let v2241: f64 = v2236 + v2240;
        let v2242: f64 = v39 * v2241;
        let v2243: f64 = v2221 - v2242;
        let v2244: f64 = v72 * v2216;
        let v2245: f64 = v68 * v2211;
        let v2246: f64 = v2244 - v2245;
        let v2247: f64 = v60 * v2246;
        let v2248: f64 = v2243 - v2247;
        let v2249: f64 = v39 * v2239;
        let v2250: f64 = v36 * v2218;
        let v2251: f64 = v2249 - v2250;
        let v2252: f64 = v25 * v2251;
        let v2253: f64 = v2248 - v2252;
        let v2254: f64 = v4 * v2253;
        let v2255: f64 = v36 * v2241;
        let v2256: f64 = v39 * v2220;
        let v2257: f64 = v2255 + v2256;
        let v2258: f64 = v36 * v2239;
        let v2259: f64 = v39 * v2218;
        let v2260: f64 = v2258 + v2259;
        let v2261: f64 = v25 * v2260;
        let v2262: f64 = v2257 + v2261;
        let v2263: f64 = v6 * v2262;
        let v2264: f64 = v2254 - v2263;
        let v2265: f64 = v30 * v2246;
        let v2266: f64 = v2264 - v2265;
        let v2267: f64 = v4 * v2251;
        let v2268: f64 = v6 * v2260;
        let v2269: f64 = v2267 + v2268;
        let v2270: f64 = v19 * v2269;
        let v2271: f64 = v2266 - v2270;
        let v2272: f64 = v2271 * v8;
        let v2273: f64 = v4 * v2262;
        let v2274: f64 = v6 * v2253;
        let v2275: f64 = v2273 + v2274;
        let v2276: f64 = v4 * v2260;
        let v2277: f64 = v6 * v2251;
        let v2278: f64 = v2276 - v2277;
        let v2279: f64 = v19 * v2278;
        let v2280: f64 = v2275 + v2279;
        let v2281: f64 = v2280 * v2;
        let v2282: f64 = v2272 + v2281;
        let v2283: f64 = v71 * v72;
        let v2284: f64 = v66 * v68;
        let v2285: f64 = v2283 - v2284;
        let v2286: f64 = v1657 * v72;
        let v2287: f64 = v79 * v2286;
        let v2288: f64 = v1657 * v68;
        let v2289: f64 = v87 * v2288;
        let v2290: f64 = v2287 - v2289;
        let v2291: f64 = v2285 + v2290;
        let v2292: f64 = v95 * v72;
        let v2293: f64 = v98 * v2292;
        let v2294: f64 = v96 * v68;
        let v2295: f64 = v2293 - v2294;
        let v2296: f64 = v100 * v72;
        let v2297: f64 = v105 * v2296;
        let v2298: f64 = v2295 + v2297;
        let v2299: f64 = v2286 - v1478;
        let v2300: f64 = v111 * v2299;
        let v2301: f64 = v2288 - v1476;
        let v2302: f64 = v95 * v2301;
        let v2303: f64 = v116 * v2302;
        let v2304: f64 = v2300 - v2303;
        let v2305: f64 = v2298 + v2304;
        let v2306: f64 = v95 * v2305;
        let v2307: f64 = v133 * v2292;
        let v2308: f64 = v131 * v68;
        let v2309: f64 = v2307 - v2308;
        let v2310: f64 = v98 * v2296;
        let v2311: f64 = v2309 + v2310;
        let v2312: f64 = v100 * v2301;
        let v2313: f64 = v116 * v2312;
        let v2314: f64 = v142 * v2299;
        let v2315: f64 = v2313 - v2314;
        let v2316: f64 = v2311 + v2315;
        let v2317: f64 = v100 * v2316;
        let v2318: f64 = v2306 - v2317;
        let v2319: f64 = v2291 + v2318;
        let v2320: f64 = v154 * v2288;
        let v2321: f64 = v2320 - v1519;
        let v2322: f64 = v157 * v2302;
        let v2323: f64 = v142 * v68;
        let v2324: f64 = v116 * v2296;
        let v2325: f64 = v2323 + v2324;
        let v2326: f64 = v2322 - v2325;
        let v2327: f64 = v95 * v2326;
        let v2328: f64 = v157 * v2312;
        let v2329: f64 = v116 * v2292;
        let v2330: f64 = v111 * v68;
        let v2331: f64 = v2329 + v2330;
        let v2332: f64 = v2328 + v2331;
        let v2333: f64 = v100 * v2332;
        let v2334: f64 = v2327 + v2333;
        let v2335: f64 = v2321 + v2334;
        let v2336: f64 = v72 * v2335;
        let v2337: f64 = v1699 * v68;
        let v2338: f64 = v2336 - v2337;
        let v2339: f64 = v1705 * v72;
        let v2340: f64 = v154 * v2286;
        let v2341: f64 = v2340 - v1498;
        let v2342: f64 = v157 * v2299;
        let v2343: f64 = v111 * v2296;
        let v2344: f64 = v142 * v2292;
        let v2345: f64 = v2343 - v2344;
        let v2346: f64 = v2342 + v2345;
        let v2347: f64 = v2341 + v2346;
        let v2348: f64 = v68 * v2347;
        let v2349: f64 = v2339 + v2348;
        let v2350: f64 = v2338 - v2349;
        let v2351: f64 = v81 * v2350;
        let v2352: f64 = v2319 - v2351;
        let v2353: f64 = v36 * v2352;
        let v2354: f64 = v200 * v72;
        let v2355: f64 = v2354 - v1537;
        let v2356: f64 = v150 * v2286;
        let v2357: f64 = v2355 - v2356;
        let v2358: f64 = v95 * v2316;
        let v2359: f64 = v100 * v2305;
        let v2360: f64 = v2358 + v2359;
        let v2361: f64 = v2357 + v2360;
        let v2362: f64 = v112 * v2346;
        let v2363: f64 = v2361 - v2362;
        let v2364: f64 = v72 * v2363;
        let v2365: f64 = v1723 * v68;
        let v2366: f64 = v2364 - v2365;
        let v2367: f64 = v1735 * v72;
        let v2368: f64 = v216 * v68;
        let v2369: f64 = v1528 - v2368;
        let v2370: f64 = v150 * v2288;
        let v2371: f64 = v2369 + v2370;
        let v2372: f64 = v131 * v2292;
        let v2373: f64 = v226 * v68;
        let v2374: f64 = v2372 - v2373;
        let v2375: f64 = v96 * v2296;
        let v2376: f64 = v2374 + v2375;
        let v2377: f64 = v142 * v2302;
        let v2378: f64 = v111 * v2312;
        let v2379: f64 = v2377 - v2378;
        let v2380: f64 = v2376 + v2379;
        let v2381: f64 = v2371 + v2380;
        let v2382: f64 = v112 * v2334;
        let v2383: f64 = v2381 + v2382;
        let v2384: f64 = v68 * v2383;
        let v2385: f64 = v2367 + v2384;
        let v2386: f64 = v2366 - v2385;
        let v2387: f64 = v87 * v72;
        let v2388: f64 = v79 * v68;
        let v2389: f64 = v2387 + v2388;
        let v2390: f64 = v95 * v2332;
        let v2391: f64 = v100 * v2326;
        let v2392: f64 = v2390 - v2391;
        let v2393: f64 = v2389 + v2392;
        let v2394: f64 = v81 * v2393;
        let v2395: f64 = v2386 + v2394;
        let v2396: f64 = v39 * v2395;
        let v2397: f64 = v2353 - v2396;
        let v2398: f64 = v1699 * v72;
        let v2399: f64 = v68 * v2335;
        (
            v2200,
            v2202,
            v2206,
            v2207,
            v2208,
            v2209,
            v2211,
            v2213,
            v2214,
            v2216,
            v2218,
            v2220,
            v2227,
            v2231,
            v2234,
            v2237,
            v2238,
            v2239,
            v2241,
            v2251,
            v2253,
            v2260,
            v2262,
            v2282,
            v2285,
            v2298,
            v2311,
            v2319,
            v2325,
            v2331,
            v2345,
            v2347,
            v2350,
            v2352,
            v2355,
            v2363,
            v2369,
            v2376,
            v2380,
            v2383,
            v2389,
            v2393,
            v2395,
            v2397,
            v2398,
            v2399,
        )
    };
    let (
        v2418,
        v2436,
        v2440,
        v2442,
        v2444,
        v2449,
        v2461,
        v2469,
        v2472,
        v2478,
        v2487,
        v2499,
        v2500,
        v2504,
        v2508,
        v2510,
        v2525,
        v2540,
        v2558,
        v2562,
        v2565,
        v2569,
        v2570,
        v2572,
        v2576,
        v2579,
        v2583,
        v2589,
        v2592,
        v2593,
        v2597,
        v2599,
    ) = {
        let v2400: f64 = v2398 + v2399;
        let v2401: f64 = v72 * v2347;
        let v2402: f64 = v1705 * v68;
        let v2403: f64 = v2401 - v2402;
        let v2404: f64 = v2400 + v2403;
        let v2405: f64 = v60 * v2404;
        let v2406: f64 = v2397 - v2405;
        let v2407: f64 = v36 * v2350;
        let v2408: f64 = v39 * v2393;
        let v2409: f64 = v2407 + v2408;
        let v2410: f64 = v25 * v2409;
        let v2411: f64 = v2406 - v2410;
        let v2412: f64 = v4 * v2411;
        let v2413: f64 = v36 * v2395;
        let v2414: f64 = v39 * v2352;
        let v2415: f64 = v2413 + v2414;
        let v2416: f64 = v36 * v2393;
        let v2417: f64 = v39 * v2350;
        let v2418: f64 = v2416 - v2417;
        let v2419: f64 = v25 * v2418;
        let v2420: f64 = v2415 + v2419;
        let v2421: f64 = v6 * v2420;
        let v2422: f64 = v2412 - v2421;
        let v2423: f64 = v30 * v2404;
        let v2424: f64 = v2422 - v2423;
        let v2425: f64 = v4 * v2409;
        let v2426: f64 = v6 * v2418;
        let v2427: f64 = v2425 + v2426;
        let v2428: f64 = v19 * v2427;
        let v2429: f64 = v2424 - v2428;
        let v2430: f64 = v2 * v2429;
        let v2431: f64 = v4 * v2420;
        let v2432: f64 = v6 * v2411;
        let v2433: f64 = v2431 + v2432;
        let v2434: f64 = v4 * v2418;
        let v2435: f64 = v6 * v2409;
        let v2436: f64 = v2434 - v2435;
        let v2437: f64 = v19 * v2436;
        let v2438: f64 = v2433 + v2437;
        let v2439: f64 = v8 * v2438;
        let v2440: f64 = v2430 - v2439;
        let v2441: f64 = v2282 - v2440;
        let v2442: f64 = v0 * v2441;
        let v2443: f64 = v2442 * v1335;
        let v2444: f64 = v2195 + v2443;
        let v2445: f64 = v68 * v95;
        let v2446: f64 = v105 * v2445;
        let v2447: f64 = v68 * v100;
        let v2448: f64 = v98 * v2447;
        let v2449: f64 = v2446 - v2448;
        let v2450: f64 = v1668 * v100;
        let v2451: f64 = v1672 * v95;
        let v2452: f64 = v2450 + v2451;
        let v2453: f64 = v116 * v2452;
        let v2454: f64 = v2449 + v2453;
        let v2455: f64 = v95 * v2454;
        let v2456: f64 = v1677 * v100;
        let v2457: f64 = v2455 - v2456;
        let v2458: f64 = v1685 * v95;
        let v2459: f64 = v98 * v2445;
        let v2460: f64 = v133 * v2447;
        let v2461: f64 = v2459 - v2460;
        let v2462: f64 = v1668 * v95;
        let v2463: f64 = v1672 * v100;
        let v2464: f64 = v2462 - v2463;
        let v2465: f64 = v116 * v2464;
        let v2466: f64 = v2461 + v2465;
        let v2467: f64 = v100 * v2466;
        let v2468: f64 = v2458 + v2467;
        let v2469: f64 = v2457 - v2468;
        let v2470: f64 = v1696 * v95;
        let v2471: f64 = v157 * v2464;
        let v2472: f64 = v116 * v2447;
        let v2473: f64 = v2471 - v2472;
        let v2474: f64 = v100 * v2473;
        let v2475: f64 = v2470 + v2474;
        let v2476: f64 = v1693 * v100;
        let v2477: f64 = v157 * v2452;
        let v2478: f64 = v116 * v2445;
        let v2479: f64 = v2477 + v2478;
        let v2480: f64 = v95 * v2479;
        let v2481: f64 = v2476 + v2480;
        let v2482: f64 = v2475 - v2481;
        let v2483: f64 = v72 * v2482;
        let v2484: f64 = v111 * v2445;
        let v2485: f64 = v142 * v2447;
        let v2486: f64 = v2484 + v2485;
        let v2487: f64 = v68 * v2486;
        let v2488: f64 = v2483 - v2487;
        let v2489: f64 = v81 * v2488;
        let v2490: f64 = v2469 - v2489;
        let v2491: f64 = v36 * v2490;
        let v2492: f64 = v95 * v2466;
        let v2493: f64 = v1685 * v100;
        let v2494: f64 = v2492 - v2493;
        let v2495: f64 = v1677 * v95;
        let v2496: f64 = v100 * v2454;
        let v2497: f64 = v2495 + v2496;
        let v2498: f64 = v2494 + v2497;
        let v2499: f64 = v112 * v2486;
        let v2500: f64 = v2498 - v2499;
        let v2501: f64 = v72 * v2500;
        let v2502: f64 = v96 * v2445;
        let v2503: f64 = v131 * v2447;
        let v2504: f64 = v2502 - v2503;
        let v2505: f64 = v142 * v2452;
        let v2506: f64 = v111 * v2464;
        let v2507: f64 = v2505 + v2506;
        let v2508: f64 = v2504 - v2507;
        let v2509: f64 = v112 * v2482;
        let v2510: f64 = v2508 + v2509;
        let v2511: f64 = v68 * v2510;
        let v2512: f64 = v2501 - v2511;
        let v2513: f64 = v95 * v2473;
        let v2514: f64 = v1696 * v100;
        let v2515: f64 = v2513 - v2514;
        let v2516: f64 = v1693 * v95;
        let v2517: f64 = v100 * v2479;
        let v2518: f64 = v2516 - v2517;
        let v2519: f64 = v2515 - v2518;
        let v2520: f64 = v81 * v2519;
        let v2521: f64 = v2512 + v2520;
        let v2522: f64 = v39 * v2521;
        let v2523: f64 = v2491 - v2522;
        let v2524: f64 = v68 * v2482;
        let v2525: f64 = v72 * v2486;
        let v2526: f64 = v2524 + v2525;
        let v2527: f64 = v60 * v2526;
        let v2528: f64 = v2523 - v2527;
        let v2529: f64 = v36 * v2488;
        let v2530: f64 = v39 * v2519;
        let v2531: f64 = v2529 + v2530;
        let v2532: f64 = v25 * v2531;
        let v2533: f64 = v2528 - v2532;
        let v2534: f64 = v4 * v2533;
        let v2535: f64 = v36 * v2521;
        let v2536: f64 = v39 * v2490;
        let v2537: f64 = v2535 + v2536;
        let v2538: f64 = v36 * v2519;
        let v2539: f64 = v39 * v2488;
        let v2540: f64 = v2538 - v2539;
        let v2541: f64 = v25 * v2540;
        let v2542: f64 = v2537 + v2541;
        let v2543: f64 = v6 * v2542;
        let v2544: f64 = v2534 - v2543;
        let v2545: f64 = v30 * v2526;
        let v2546: f64 = v2544 - v2545;
        let v2547: f64 = v4 * v2531;
        let v2548: f64 = v6 * v2540;
        let v2549: f64 = v2547 + v2548;
        let v2550: f64 = v19 * v2549;
        let v2551: f64 = v2546 - v2550;
        let v2552: f64 = v2 * v2551;
        let v2553: f64 = v4 * v2542;
        let v2554: f64 = v6 * v2533;
        let v2555: f64 = v2553 + v2554;
        let v2556: f64 = v4 * v2540;
        let v2557: f64 = v6 * v2531;
        let v2558: f64 = v2556 - v2557;
        let v2559: f64 = v19 * v2558;
        let v2560: f64 = v2555 + v2559;
        let v2561: f64 = v8 * v2560;
        let v2562: f64 = v2552 - v2561;
        let v2563: f64 = v95 * v111;
        let v2564: f64 = v100 * v142;
        let v2565: f64 = v2563 + v2564;
        let v2566: f64 = v36 * v2565;
        let v2567: f64 = v95 * v142;
        let v2568: f64 = v100 * v111;
        let v2569: f64 = v2567 - v2568;
        let v2570: f64 = v72 * v2569;
        let v2571: f64 = v39 * v2570;
        let v2572: f64 = v2566 + v2571;
        let v2573: f64 = v25 * v2572;
        let v2574: f64 = v95 * v131;
        let v2575: f64 = v100 * v96;
        let v2576: f64 = v2574 + v2575;
        let v2577: f64 = v72 * v2576;
        let v2578: f64 = v112 * v2569;
        let v2579: f64 = v226 + v2578;
        let v2580: f64 = v68 * v2579;
        let v2581: f64 = v2577 - v2580;
        let v2582: f64 = v81 * v2565;
        let v2583: f64 = v2581 - v2582;
        let v2584: f64 = v36 * v2583;
        let v2585: f64 = v95 * v96;
        let v2586: f64 = v100 * v131;
        let v2587: f64 = v2585 - v2586;
        let v2588: f64 = v81 * v2570;
        let v2589: f64 = v2587 - v2588;
        let v2590: f64 = v39 * v2589;
        let v2591: f64 = v2584 + v2590;
        let v2592: f64 = v2573 - v2591;
        let v2593: f64 = v4 * v2592;
        let v2594: f64 = v36 * v2589;
        let v2595: f64 = v39 * v2583;
        let v2596: f64 = v2594 - v2595;
        let v2597: f64 = v68 * v2569;
        let v2598: f64 = v60 * v2597;
        let v2599: f64 = v2596 - v2598;
        (
            v2418,
            v2436,
            v2440,
            v2442,
            v2444,
            v2449,
            v2461,
            v2469,
            v2472,
            v2478,
            v2487,
            v2499,
            v2500,
            v2504,
            v2508,
            v2510,
            v2525,
            v2540,
            v2558,
            v2562,
            v2565,
            v2569,
            v2570,
            v2572,
            v2576,
            v2579,
            v2583,
            v2589,
            v2592,
            v2593,
            v2597,
            v2599,
        )
    };
    let (
        v2602,
        v2604,
        v2624,
        v2628,
        v2643,
        v2647,
        v2668,
        v2697,
        v2701,
        v2707,
        v2744,
        v2769,
        v2773,
        v2775,
        v2776,
        v2777,
        v2781,
        v2790,
        v2793,
        v2799,
    ) = {
        let v2600: f64 = v36 * v2570;
        let v2601: f64 = v39 * v2565;
        let v2602: f64 = v2600 - v2601;
        let v2603: f64 = v25 * v2602;
        let v2604: f64 = v2599 - v2603;
        let v2605: f64 = v6 * v2604;
        let v2606: f64 = v2593 - v2605;
        let v2607: f64 = v4 * v2572;
        let v2608: f64 = v6 * v2602;
        let v2609: f64 = v2607 + v2608;
        let v2610: f64 = v19 * v2609;
        let v2611: f64 = v2606 + v2610;
        let v2612: f64 = v2611 * v2;
        let v2613: f64 = v4 * v2604;
        let v2614: f64 = v6 * v2592;
        let v2615: f64 = v2613 + v2614;
        let v2616: f64 = v30 * v2597;
        let v2617: f64 = v2615 - v2616;
        let v2618: f64 = v6 * v2572;
        let v2619: f64 = v4 * v2602;
        let v2620: f64 = v2618 - v2619;
        let v2621: f64 = v19 * v2620;
        let v2622: f64 = v2617 + v2621;
        let v2623: f64 = v2622 * v8;
        let v2624: f64 = v2612 - v2623;
        let v2625: f64 = v2562 + v2624;
        let v2626: f64 = v0 * v2625;
        let v2627: f64 = v2626 * v1461;
        let v2628: f64 = v2444 - v2627;
        let v2629: f64 = v1577 * v6;
        let v2630: f64 = v1586 * v4;
        let v2631: f64 = v2629 + v2630;
        let v2632: f64 = v1584 * v4;
        let v2633: f64 = v1575 * v6;
        let v2634: f64 = v2632 - v2633;
        let v2635: f64 = v19 * v2634;
        let v2636: f64 = v2631 + v2635;
        let v2637: f64 = v2 * v2636;
        let v2638: f64 = v1577 * v4;
        let v2639: f64 = v1586 * v6;
        let v2640: f64 = v2638 - v2639;
        let v2641: f64 = v1584 * v6;
        let v2642: f64 = v1575 * v4;
        let v2643: f64 = v2641 + v2642;
        let v2644: f64 = v19 * v2643;
        let v2645: f64 = v2640 - v2644;
        let v2646: f64 = v8 * v2645;
        let v2647: f64 = v2637 + v2646;
        let v2648: f64 = v68 * v2053;
        let v2649: f64 = v79 * v2648;
        let v2650: f64 = v72 * v2053;
        let v2651: f64 = v87 * v2650;
        let v2652: f64 = v2649 + v2651;
        let v2653: f64 = v111 * v2648;
        let v2654: f64 = v100 * v2057;
        let v2655: f64 = v95 * v2650;
        let v2656: f64 = v2654 - v2655;
        let v2657: f64 = v116 * v2656;
        let v2658: f64 = v2653 - v2657;
        let v2659: f64 = v95 * v2658;
        let v2660: f64 = v100 * v2650;
        let v2661: f64 = v95 * v2057;
        let v2662: f64 = v2660 + v2661;
        let v2663: f64 = v116 * v2662;
        let v2664: f64 = v142 * v2648;
        let v2665: f64 = v2663 + v2664;
        let v2666: f64 = v100 * v2665;
        let v2667: f64 = v2659 + v2666;
        let v2668: f64 = v2652 + v2667;
        let v2669: f64 = v2054 + v2668;
        let v2670: f64 = v157 * v2656;
        let v2671: f64 = v95 * v2670;
        let v2672: f64 = v157 * v2662;
        let v2673: f64 = v100 * v2672;
        let v2674: f64 = v2671 - v2673;
        let v2675: f64 = v154 * v2650;
        let v2676: f64 = v2674 - v2675;
        let v2677: f64 = v72 * v2676;
        let v2678: f64 = v154 * v2648;
        let v2679: f64 = v157 * v2648;
        let v2680: f64 = v2678 + v2679;
        let v2681: f64 = v68 * v2680;
        let v2682: f64 = v2677 - v2681;
        let v2683: f64 = v81 * v2682;
        let v2684: f64 = v2669 - v2683;
        let v2685: f64 = v36 * v2684;
        let v2686: f64 = v2139 * v39;
        let v2687: f64 = v2685 - v2686;
        let v2688: f64 = v2116 * v36;
        let v2689: f64 = v100 * v2658;
        let v2690: f64 = v95 * v2665;
        let v2691: f64 = v2689 - v2690;
        let v2692: f64 = v87 * v2057;
        let v2693: f64 = v150 * v2648;
        let v2694: f64 = v2692 + v2693;
        let v2695: f64 = v2691 - v2694;
        let v2696: f64 = v112 * v2679;
        let v2697: f64 = v2695 - v2696;
        let v2698: f64 = v72 * v2697;
        let v2699: f64 = v142 * v2656;
        let v2700: f64 = v111 * v2662;
        let v2701: f64 = v2699 + v2700;
        let v2702: f64 = v150 * v2650;
        let v2703: f64 = v79 * v2057;
        let v2704: f64 = v2702 - v2703;
        let v2705: f64 = v2701 - v2704;
        let v2706: f64 = v112 * v2674;
        let v2707: f64 = v2705 + v2706;
        let v2708: f64 = v68 * v2707;
        let v2709: f64 = v2698 - v2708;
        let v2710: f64 = v2709 - v2118;
        let v2711: f64 = v154 * v2057;
        let v2712: f64 = v95 * v2672;
        let v2713: f64 = v100 * v2670;
        let v2714: f64 = v2712 + v2713;
        let v2715: f64 = v2711 + v2714;
        let v2716: f64 = v81 * v2715;
        let v2717: f64 = v2710 - v2716;
        let v2718: f64 = v39 * v2717;
        let v2719: f64 = v2688 + v2718;
        let v2720: f64 = v2687 - v2719;
        let v2721: f64 = v68 * v2676;
        let v2722: f64 = v72 * v2680;
        let v2723: f64 = v2721 + v2722;
        let v2724: f64 = v60 * v2723;
        let v2725: f64 = v2720 - v2724;
        let v2726: f64 = v2682 - v2143;
        let v2727: f64 = v36 * v2726;
        let v2728: f64 = v2149 * v39;
        let v2729: f64 = v2727 - v2728;
        let v2730: f64 = v2145 * v36;
        let v2731: f64 = v2147 + v2715;
        let v2732: f64 = v39 * v2731;
        let v2733: f64 = v2730 - v2732;
        let v2734: f64 = v2729 + v2733;
        let v2735: f64 = v25 * v2734;
        let v2736: f64 = v2725 - v2735;
        let v2737: f64 = v4 * v2736;
        let v2738: f64 = v2145 * v39;
        let v2739: f64 = v36 * v2731;
        let v2740: f64 = v2738 + v2739;
        let v2741: f64 = v2149 * v36;
        let v2742: f64 = v39 * v2726;
        let v2743: f64 = v2741 + v2742;
        let v2744: f64 = v2740 + v2743;
        let v2745: f64 = v25 * v2744;
        let v2746: f64 = v36 * v2717;
        let v2747: f64 = v2116 * v39;
        let v2748: f64 = v2746 - v2747;
        let v2749: f64 = v2139 * v36;
        let v2750: f64 = v39 * v2684;
        let v2751: f64 = v2749 + v2750;
        let v2752: f64 = v2748 + v2751;
        let v2753: f64 = v2745 - v2752;
        let v2754: f64 = v6 * v2753;
        let v2755: f64 = v2737 + v2754;
        let v2756: f64 = v30 * v2723;
        let v2757: f64 = v2755 - v2756;
        let v2758: f64 = v4 * v2734;
        let v2759: f64 = v6 * v2744;
        let v2760: f64 = v2758 - v2759;
        let v2761: f64 = v19 * v2760;
        let v2762: f64 = v2757 - v2761;
        let v2763: f64 = v2 * v2762;
        let v2764: f64 = v4 * v2753;
        let v2765: f64 = v6 * v2736;
        let v2766: f64 = v2764 - v2765;
        let v2767: f64 = v4 * v2744;
        let v2768: f64 = v6 * v2734;
        let v2769: f64 = v2767 + v2768;
        let v2770: f64 = v19 * v2769;
        let v2771: f64 = v2766 + v2770;
        let v2772: f64 = v8 * v2771;
        let v2773: f64 = v2763 + v2772;
        let v2774: f64 = v2647 - v2773;
        let v2775: f64 = v0 * v2774;
        let v2776: f64 = v2775 * v1161;
        let v2777: f64 = v922 * v1845;
        let v2778: f64 = v2190 + v2052;
        let v2779: f64 = v0 * v2778;
        let v2780: f64 = v2779 * v635;
        let v2781: f64 = v2777 + v2780;
        let v2782: f64 = v2154 * v4;
        let v2783: f64 = v2170 * v6;
        let v2784: f64 = v2782 - v2783;
        let v2785: f64 = v2152 * v4;
        let v2786: f64 = v2168 * v6;
        let v2787: f64 = v2785 - v2786;
        let v2788: f64 = v19 * v2787;
        let v2789: f64 = v2784 - v2788;
        let v2790: f64 = v2 * v2789;
        let v2791: f64 = v2152 * v6;
        let v2792: f64 = v2168 * v4;
        let v2793: f64 = v2791 + v2792;
        let v2794: f64 = v19 * v2793;
        let v2795: f64 = v2154 * v6;
        let v2796: f64 = v2170 * v4;
        let v2797: f64 = v2795 + v2796;
        let v2798: f64 = v2794 - v2797;
        let v2799: f64 = v8 * v2798;
        (
            v2602,
            v2604,
            v2624,
            v2628,
            v2643,
            v2647,
            v2668,
            v2697,
            v2701,
            v2707,
            v2744,
            v2769,
            v2773,
            v2775,
            v2776,
            v2777,
            v2781,
            v2790,
            v2793,
            v2799,
        )
    };
    let (
        v2800,
        v2820,
        v2824,
        v2846,
        v2879,
        v2889,
        v2892,
        v2924,
        v2942,
        v2946,
        v2948,
        v2950,
        v2967,
        v2970,
        v2975,
        v2978,
        v2980,
        v2982,
        v2983,
        v2991,
        v2992,
        v2996,
        v2998,
        v2999,
    ) = {
        let v2800: f64 = v2790 + v2799;
        let v2801: f64 = v2800 + v2800;
        let v2802: f64 = v0 * v2801;
        let v2803: f64 = v2802 * v923;
        let v2804: f64 = v2781 + v2803;
        let v2805: f64 = v2776 - v2804;
        let v2806: f64 = v2253 * v6;
        let v2807: f64 = v2262 * v4;
        let v2808: f64 = v2806 + v2807;
        let v2809: f64 = v2260 * v4;
        let v2810: f64 = v2251 * v6;
        let v2811: f64 = v2809 - v2810;
        let v2812: f64 = v19 * v2811;
        let v2813: f64 = v2808 + v2812;
        let v2814: f64 = v2 * v2813;
        let v2815: f64 = v2253 * v4;
        let v2816: f64 = v2262 * v6;
        let v2817: f64 = v2815 - v2816;
        let v2818: f64 = v2260 * v6;
        let v2819: f64 = v2251 * v4;
        let v2820: f64 = v2818 + v2819;
        let v2821: f64 = v19 * v2820;
        let v2822: f64 = v2817 - v2821;
        let v2823: f64 = v8 * v2822;
        let v2824: f64 = v2814 + v2823;
        let v2825: f64 = v2057 * v72;
        let v2826: f64 = v79 * v2825;
        let v2827: f64 = v2057 * v68;
        let v2828: f64 = v87 * v2827;
        let v2829: f64 = v2826 - v2828;
        let v2830: f64 = v2285 + v2829;
        let v2831: f64 = v2825 - v1478;
        let v2832: f64 = v111 * v2831;
        let v2833: f64 = v2827 - v1476;
        let v2834: f64 = v95 * v2833;
        let v2835: f64 = v116 * v2834;
        let v2836: f64 = v2832 - v2835;
        let v2837: f64 = v2298 + v2836;
        let v2838: f64 = v95 * v2837;
        let v2839: f64 = v100 * v2833;
        let v2840: f64 = v116 * v2839;
        let v2841: f64 = v142 * v2831;
        let v2842: f64 = v2840 - v2841;
        let v2843: f64 = v2311 + v2842;
        let v2844: f64 = v100 * v2843;
        let v2845: f64 = v2838 - v2844;
        let v2846: f64 = v2830 + v2845;
        let v2847: f64 = v154 * v2827;
        let v2848: f64 = v2847 - v1519;
        let v2849: f64 = v157 * v2834;
        let v2850: f64 = v2849 - v2325;
        let v2851: f64 = v95 * v2850;
        let v2852: f64 = v157 * v2839;
        let v2853: f64 = v2852 + v2331;
        let v2854: f64 = v100 * v2853;
        let v2855: f64 = v2851 + v2854;
        let v2856: f64 = v2848 + v2855;
        let v2857: f64 = v72 * v2856;
        let v2858: f64 = v2131 * v68;
        let v2859: f64 = v2857 - v2858;
        let v2860: f64 = v2135 * v72;
        let v2861: f64 = v154 * v2825;
        let v2862: f64 = v2861 - v1498;
        let v2863: f64 = v157 * v2831;
        let v2864: f64 = v2863 + v2345;
        let v2865: f64 = v2862 + v2864;
        let v2866: f64 = v68 * v2865;
        let v2867: f64 = v2860 + v2866;
        let v2868: f64 = v2859 - v2867;
        let v2869: f64 = v81 * v2868;
        let v2870: f64 = v2846 - v2869;
        let v2871: f64 = v36 * v2870;
        let v2872: f64 = v150 * v2825;
        let v2873: f64 = v2355 - v2872;
        let v2874: f64 = v95 * v2843;
        let v2875: f64 = v100 * v2837;
        let v2876: f64 = v2874 + v2875;
        let v2877: f64 = v2873 + v2876;
        let v2878: f64 = v112 * v2864;
        let v2879: f64 = v2877 - v2878;
        let v2880: f64 = v72 * v2879;
        let v2881: f64 = v2086 * v68;
        let v2882: f64 = v2880 - v2881;
        let v2883: f64 = v2105 * v72;
        let v2884: f64 = v150 * v2827;
        let v2885: f64 = v2369 + v2884;
        let v2886: f64 = v142 * v2834;
        let v2887: f64 = v111 * v2839;
        let v2888: f64 = v2886 - v2887;
        let v2889: f64 = v2376 + v2888;
        let v2890: f64 = v2885 + v2889;
        let v2891: f64 = v112 * v2855;
        let v2892: f64 = v2890 + v2891;
        let v2893: f64 = v68 * v2892;
        let v2894: f64 = v2883 + v2893;
        let v2895: f64 = v2882 - v2894;
        let v2896: f64 = v95 * v2853;
        let v2897: f64 = v100 * v2850;
        let v2898: f64 = v2896 - v2897;
        let v2899: f64 = v2389 + v2898;
        let v2900: f64 = v81 * v2899;
        let v2901: f64 = v2895 + v2900;
        let v2902: f64 = v39 * v2901;
        let v2903: f64 = v2871 - v2902;
        let v2904: f64 = v2131 * v72;
        let v2905: f64 = v68 * v2856;
        let v2906: f64 = v2904 + v2905;
        let v2907: f64 = v72 * v2865;
        let v2908: f64 = v2135 * v68;
        let v2909: f64 = v2907 - v2908;
        let v2910: f64 = v2906 + v2909;
        let v2911: f64 = v60 * v2910;
        let v2912: f64 = v2903 - v2911;
        let v2913: f64 = v36 * v2868;
        let v2914: f64 = v39 * v2899;
        let v2915: f64 = v2913 + v2914;
        let v2916: f64 = v25 * v2915;
        let v2917: f64 = v2912 - v2916;
        let v2918: f64 = v4 * v2917;
        let v2919: f64 = v36 * v2901;
        let v2920: f64 = v39 * v2870;
        let v2921: f64 = v2919 + v2920;
        let v2922: f64 = v36 * v2899;
        let v2923: f64 = v39 * v2868;
        let v2924: f64 = v2922 - v2923;
        let v2925: f64 = v25 * v2924;
        let v2926: f64 = v2921 + v2925;
        let v2927: f64 = v6 * v2926;
        let v2928: f64 = v2918 - v2927;
        let v2929: f64 = v30 * v2910;
        let v2930: f64 = v2928 - v2929;
        let v2931: f64 = v4 * v2915;
        let v2932: f64 = v6 * v2924;
        let v2933: f64 = v2931 + v2932;
        let v2934: f64 = v19 * v2933;
        let v2935: f64 = v2930 - v2934;
        let v2936: f64 = v2 * v2935;
        let v2937: f64 = v4 * v2926;
        let v2938: f64 = v6 * v2917;
        let v2939: f64 = v2937 + v2938;
        let v2940: f64 = v4 * v2924;
        let v2941: f64 = v6 * v2915;
        let v2942: f64 = v2940 - v2941;
        let v2943: f64 = v19 * v2942;
        let v2944: f64 = v2939 + v2943;
        let v2945: f64 = v8 * v2944;
        let v2946: f64 = v2936 - v2945;
        let v2947: f64 = v2824 - v2946;
        let v2948: f64 = v0 * v2947;
        let v2949: f64 = v2948 * v1335;
        let v2950: f64 = v2805 + v2949;
        let v2951: f64 = v2063 * v100;
        let v2952: f64 = v2053 * v95;
        let v2953: f64 = v2951 + v2952;
        let v2954: f64 = v116 * v2953;
        let v2955: f64 = v2449 + v2954;
        let v2956: f64 = v95 * v2955;
        let v2957: f64 = v2079 * v100;
        let v2958: f64 = v2956 - v2957;
        let v2959: f64 = v2071 * v95;
        let v2960: f64 = v2063 * v95;
        let v2961: f64 = v2053 * v100;
        let v2962: f64 = v2960 - v2961;
        let v2963: f64 = v116 * v2962;
        let v2964: f64 = v2461 + v2963;
        let v2965: f64 = v100 * v2964;
        let v2966: f64 = v2959 + v2965;
        let v2967: f64 = v2958 - v2966;
        let v2968: f64 = v2101 * v95;
        let v2969: f64 = v157 * v2962;
        let v2970: f64 = v2969 - v2472;
        let v2971: f64 = v100 * v2970;
        let v2972: f64 = v2968 + v2971;
        let v2973: f64 = v2098 * v100;
        let v2974: f64 = v157 * v2953;
        let v2975: f64 = v2974 + v2478;
        let v2976: f64 = v95 * v2975;
        let v2977: f64 = v2973 + v2976;
        let v2978: f64 = v2972 - v2977;
        let v2979: f64 = v72 * v2978;
        let v2980: f64 = v2979 - v2487;
        let v2981: f64 = v81 * v2980;
        let v2982: f64 = v2967 - v2981;
        let v2983: f64 = v36 * v2982;
        let v2984: f64 = v95 * v2964;
        let v2985: f64 = v2071 * v100;
        let v2986: f64 = v2984 - v2985;
        let v2987: f64 = v2079 * v95;
        let v2988: f64 = v100 * v2955;
        let v2989: f64 = v2987 + v2988;
        let v2990: f64 = v2986 + v2989;
        let v2991: f64 = v2990 - v2499;
        let v2992: f64 = v72 * v2991;
        let v2993: f64 = v142 * v2953;
        let v2994: f64 = v111 * v2962;
        let v2995: f64 = v2993 + v2994;
        let v2996: f64 = v2504 - v2995;
        let v2997: f64 = v112 * v2978;
        let v2998: f64 = v2996 + v2997;
        let v2999: f64 = v68 * v2998;
        (
            v2800,
            v2820,
            v2824,
            v2846,
            v2879,
            v2889,
            v2892,
            v2924,
            v2942,
            v2946,
            v2948,
            v2950,
            v2967,
            v2970,
            v2975,
            v2978,
            v2980,
            v2982,
            v2983,
            v2991,
            v2992,
            v2996,
            v2998,
            v2999,
        )
    };
    let (
        v3027,
        v3045,
        v3049,
        v3061,
        v3068,
        v3072,
        v3074,
        v3092,
        v3108,
        v3112,
        v3116,
        v3131,
        v3147,
        v3151,
        v3165,
        v3167,
        v3170,
        v3172,
        v3173,
        v3180,
        v3183,
        v3185,
        v3186,
        v3192,
        v3195,
        v3196,
        v3199,
    ) = {
        let v3000: f64 = v2992 - v2999;
        let v3001: f64 = v95 * v2970;
        let v3002: f64 = v2101 * v100;
        let v3003: f64 = v3001 - v3002;
        let v3004: f64 = v2098 * v95;
        let v3005: f64 = v100 * v2975;
        let v3006: f64 = v3004 - v3005;
        let v3007: f64 = v3003 - v3006;
        let v3008: f64 = v81 * v3007;
        let v3009: f64 = v3000 + v3008;
        let v3010: f64 = v39 * v3009;
        let v3011: f64 = v2983 - v3010;
        let v3012: f64 = v68 * v2978;
        let v3013: f64 = v3012 + v2525;
        let v3014: f64 = v60 * v3013;
        let v3015: f64 = v3011 - v3014;
        let v3016: f64 = v36 * v2980;
        let v3017: f64 = v39 * v3007;
        let v3018: f64 = v3016 + v3017;
        let v3019: f64 = v25 * v3018;
        let v3020: f64 = v3015 - v3019;
        let v3021: f64 = v4 * v3020;
        let v3022: f64 = v36 * v3009;
        let v3023: f64 = v39 * v2982;
        let v3024: f64 = v3022 + v3023;
        let v3025: f64 = v36 * v3007;
        let v3026: f64 = v39 * v2980;
        let v3027: f64 = v3025 - v3026;
        let v3028: f64 = v25 * v3027;
        let v3029: f64 = v3024 + v3028;
        let v3030: f64 = v6 * v3029;
        let v3031: f64 = v3021 - v3030;
        let v3032: f64 = v30 * v3013;
        let v3033: f64 = v3031 - v3032;
        let v3034: f64 = v4 * v3018;
        let v3035: f64 = v6 * v3027;
        let v3036: f64 = v3034 + v3035;
        let v3037: f64 = v19 * v3036;
        let v3038: f64 = v3033 - v3037;
        let v3039: f64 = v2 * v3038;
        let v3040: f64 = v4 * v3029;
        let v3041: f64 = v6 * v3020;
        let v3042: f64 = v3040 + v3041;
        let v3043: f64 = v4 * v3027;
        let v3044: f64 = v6 * v3018;
        let v3045: f64 = v3043 - v3044;
        let v3046: f64 = v19 * v3045;
        let v3047: f64 = v3042 + v3046;
        let v3048: f64 = v8 * v3047;
        let v3049: f64 = v3039 - v3048;
        let v3050: f64 = v2592 * v4;
        let v3051: f64 = v2604 * v6;
        let v3052: f64 = v3050 - v3051;
        let v3053: f64 = v2572 * v4;
        let v3054: f64 = v2602 * v6;
        let v3055: f64 = v3053 + v3054;
        let v3056: f64 = v19 * v3055;
        let v3057: f64 = v3052 + v3056;
        let v3058: f64 = v2 * v3057;
        let v3059: f64 = v2602 * v4;
        let v3060: f64 = v2572 * v6;
        let v3061: f64 = v3059 - v3060;
        let v3062: f64 = v19 * v3061;
        let v3063: f64 = v2592 * v6;
        let v3064: f64 = v2604 * v4;
        let v3065: f64 = v3063 + v3064;
        let v3066: f64 = v3062 - v3065;
        let v3067: f64 = v8 * v3066;
        let v3068: f64 = v3058 + v3067;
        let v3069: f64 = v3049 + v3068;
        let v3070: f64 = v0 * v3069;
        let v3071: f64 = v3070 * v1461;
        let v3072: f64 = v2950 - v3071;
        let v3073: f64 = v1843 * v635;
        let v3074: f64 = v1160 * v1845;
        let v3075: f64 = v3073 - v3074;
        let v3076: f64 = v2775 * v923;
        let v3077: f64 = v3075 + v3076;
        let v3078: f64 = v1524 * v39;
        let v3079: f64 = v1563 * v36;
        let v3080: f64 = v3078 + v3079;
        let v3081: f64 = v1573 * v36;
        let v3082: f64 = v1571 * v39;
        let v3083: f64 = v3081 - v3082;
        let v3084: f64 = v25 * v3083;
        let v3085: f64 = v3080 + v3084;
        let v3086: f64 = v4 * v3085;
        let v3087: f64 = v1524 * v36;
        let v3088: f64 = v1563 * v39;
        let v3089: f64 = v3087 - v3088;
        let v3090: f64 = v1573 * v39;
        let v3091: f64 = v1571 * v36;
        let v3092: f64 = v3090 + v3091;
        let v3093: f64 = v25 * v3092;
        let v3094: f64 = v3089 - v3093;
        let v3095: f64 = v6 * v3094;
        let v3096: f64 = v3086 + v3095;
        let v3097: f64 = v4 * v3083;
        let v3098: f64 = v6 * v3092;
        let v3099: f64 = v3097 - v3098;
        let v3100: f64 = v19 * v3099;
        let v3101: f64 = v3096 + v3100;
        let v3102: f64 = v2 * v3101;
        let v3103: f64 = v4 * v3094;
        let v3104: f64 = v6 * v3085;
        let v3105: f64 = v3103 - v3104;
        let v3106: f64 = v4 * v3092;
        let v3107: f64 = v6 * v3083;
        let v3108: f64 = v3106 + v3107;
        let v3109: f64 = v19 * v3108;
        let v3110: f64 = v3105 - v3109;
        let v3111: f64 = v8 * v3110;
        let v3112: f64 = v3102 + v3111;
        let v3113: f64 = v3112 + v3112;
        let v3114: f64 = v0 * v3113;
        let v3115: f64 = v3114 * v1161;
        let v3116: f64 = v3077 + v3115;
        let v3117: f64 = v2220 * v39;
        let v3118: f64 = v2241 * v36;
        let v3119: f64 = v3117 + v3118;
        let v3120: f64 = v2239 * v36;
        let v3121: f64 = v2218 * v39;
        let v3122: f64 = v3120 + v3121;
        let v3123: f64 = v25 * v3122;
        let v3124: f64 = v3119 + v3123;
        let v3125: f64 = v4 * v3124;
        let v3126: f64 = v2220 * v36;
        let v3127: f64 = v2241 * v39;
        let v3128: f64 = v3126 - v3127;
        let v3129: f64 = v2218 * v36;
        let v3130: f64 = v2239 * v39;
        let v3131: f64 = v3129 - v3130;
        let v3132: f64 = v25 * v3131;
        let v3133: f64 = v3128 + v3132;
        let v3134: f64 = v6 * v3133;
        let v3135: f64 = v3125 + v3134;
        let v3136: f64 = v4 * v3122;
        let v3137: f64 = v6 * v3131;
        let v3138: f64 = v3136 + v3137;
        let v3139: f64 = v19 * v3138;
        let v3140: f64 = v3135 + v3139;
        let v3141: f64 = v2 * v3140;
        let v3142: f64 = v4 * v3133;
        let v3143: f64 = v6 * v3124;
        let v3144: f64 = v3142 - v3143;
        let v3145: f64 = v4 * v3131;
        let v3146: f64 = v6 * v3122;
        let v3147: f64 = v3145 - v3146;
        let v3148: f64 = v19 * v3147;
        let v3149: f64 = v3144 + v3148;
        let v3150: f64 = v8 * v3149;
        let v3151: f64 = v3141 + v3150;
        let v3152: f64 = v111 * v1478;
        let v3153: f64 = v95 * v1476;
        let v3154: f64 = v116 * v3153;
        let v3155: f64 = v3152 - v3154;
        let v3156: f64 = v2298 - v3155;
        let v3157: f64 = v95 * v3156;
        let v3158: f64 = v142 * v1478;
        let v3159: f64 = v100 * v1476;
        let v3160: f64 = v116 * v3159;
        let v3161: f64 = v3158 - v3160;
        let v3162: f64 = v2311 + v3161;
        let v3163: f64 = v100 * v3162;
        let v3164: f64 = v3157 - v3163;
        let v3165: f64 = v2285 + v3164;
        let v3166: f64 = v157 * v3159;
        let v3167: f64 = v2331 - v3166;
        let v3168: f64 = v100 * v3167;
        let v3169: f64 = v157 * v3153;
        let v3170: f64 = v3169 + v2325;
        let v3171: f64 = v95 * v3170;
        let v3172: f64 = v3168 - v3171;
        let v3173: f64 = v3172 - v1519;
        let v3174: f64 = v72 * v3173;
        let v3175: f64 = v1512 * v68;
        let v3176: f64 = v3174 - v3175;
        let v3177: f64 = v1520 * v72;
        let v3178: f64 = v157 * v1478;
        let v3179: f64 = v2345 - v3178;
        let v3180: f64 = v3179 - v1498;
        let v3181: f64 = v68 * v3180;
        let v3182: f64 = v3177 + v3181;
        let v3183: f64 = v3176 - v3182;
        let v3184: f64 = v81 * v3183;
        let v3185: f64 = v3165 - v3184;
        let v3186: f64 = v36 * v3185;
        let v3187: f64 = v95 * v3162;
        let v3188: f64 = v100 * v3156;
        let v3189: f64 = v3187 + v3188;
        let v3190: f64 = v2355 + v3189;
        let v3191: f64 = v112 * v3179;
        let v3192: f64 = v3190 - v3191;
        let v3193: f64 = v72 * v3192;
        let v3194: f64 = v1535 * v68;
        let v3195: f64 = v3193 - v3194;
        let v3196: f64 = v1551 * v72;
        let v3197: f64 = v111 * v3159;
        let v3198: f64 = v142 * v3153;
        let v3199: f64 = v3197 - v3198;
        (
            v3027,
            v3045,
            v3049,
            v3061,
            v3068,
            v3072,
            v3074,
            v3092,
            v3108,
            v3112,
            v3116,
            v3131,
            v3147,
            v3151,
            v3165,
            v3167,
            v3170,
            v3172,
            v3173,
            v3180,
            v3183,
            v3185,
            v3186,
            v3192,
            v3195,
            v3196,
            v3199,
        )
    };
    let (
        v3200,
        v3203,
        v3235,
        v3253,
        v3257,
        v3259,
        v3274,
        v3298,
        v3303,
        v3305,
        v3334,
        v3352,
        v3356,
        v3368,
        v3387,
        v3391,
        v3395,
        v3397,
        v3398,
        v3399,
    ) = {
        let v3200: f64 = v2376 + v3199;
        let v3201: f64 = v2369 + v3200;
        let v3202: f64 = v112 * v3172;
        let v3203: f64 = v3201 + v3202;
        let v3204: f64 = v68 * v3203;
        let v3205: f64 = v3196 + v3204;
        let v3206: f64 = v3195 - v3205;
        let v3207: f64 = v95 * v3167;
        let v3208: f64 = v100 * v3170;
        let v3209: f64 = v3207 + v3208;
        let v3210: f64 = v2389 + v3209;
        let v3211: f64 = v81 * v3210;
        let v3212: f64 = v3206 + v3211;
        let v3213: f64 = v39 * v3212;
        let v3214: f64 = v3186 - v3213;
        let v3215: f64 = v1512 * v72;
        let v3216: f64 = v68 * v3173;
        let v3217: f64 = v3215 + v3216;
        let v3218: f64 = v72 * v3180;
        let v3219: f64 = v1520 * v68;
        let v3220: f64 = v3218 - v3219;
        let v3221: f64 = v3217 + v3220;
        let v3222: f64 = v60 * v3221;
        let v3223: f64 = v3214 - v3222;
        let v3224: f64 = v36 * v3183;
        let v3225: f64 = v39 * v3210;
        let v3226: f64 = v3224 + v3225;
        let v3227: f64 = v25 * v3226;
        let v3228: f64 = v3223 - v3227;
        let v3229: f64 = v4 * v3228;
        let v3230: f64 = v36 * v3212;
        let v3231: f64 = v39 * v3185;
        let v3232: f64 = v3230 + v3231;
        let v3233: f64 = v36 * v3210;
        let v3234: f64 = v39 * v3183;
        let v3235: f64 = v3233 - v3234;
        let v3236: f64 = v25 * v3235;
        let v3237: f64 = v3232 + v3236;
        let v3238: f64 = v6 * v3237;
        let v3239: f64 = v3229 - v3238;
        let v3240: f64 = v30 * v3221;
        let v3241: f64 = v3239 - v3240;
        let v3242: f64 = v4 * v3226;
        let v3243: f64 = v6 * v3235;
        let v3244: f64 = v3242 + v3243;
        let v3245: f64 = v19 * v3244;
        let v3246: f64 = v3241 - v3245;
        let v3247: f64 = v2 * v3246;
        let v3248: f64 = v4 * v3237;
        let v3249: f64 = v6 * v3228;
        let v3250: f64 = v3248 + v3249;
        let v3251: f64 = v4 * v3235;
        let v3252: f64 = v6 * v3226;
        let v3253: f64 = v3251 - v3252;
        let v3254: f64 = v19 * v3253;
        let v3255: f64 = v3250 + v3254;
        let v3256: f64 = v8 * v3255;
        let v3257: f64 = v3247 - v3256;
        let v3258: f64 = v3151 - v3257;
        let v3259: f64 = v0 * v3258;
        let v3260: f64 = v3259 * v1335;
        let v3261: f64 = v3116 + v3260;
        let v3262: f64 = v1478 * v100;
        let v3263: f64 = v116 * v3262;
        let v3264: f64 = v2449 + v3263;
        let v3265: f64 = v95 * v3264;
        let v3266: f64 = v1482 * v100;
        let v3267: f64 = v3265 - v3266;
        let v3268: f64 = v1493 * v95;
        let v3269: f64 = v1478 * v95;
        let v3270: f64 = v116 * v3269;
        let v3271: f64 = v2461 + v3270;
        let v3272: f64 = v100 * v3271;
        let v3273: f64 = v3268 + v3272;
        let v3274: f64 = v3267 - v3273;
        let v3275: f64 = v1509 * v95;
        let v3276: f64 = v157 * v3269;
        let v3277: f64 = v3276 - v2472;
        let v3278: f64 = v100 * v3277;
        let v3279: f64 = v3275 + v3278;
        let v3280: f64 = v1503 * v100;
        let v3281: f64 = v157 * v3262;
        let v3282: f64 = v3281 + v2478;
        let v3283: f64 = v95 * v3282;
        let v3284: f64 = v3280 + v3283;
        let v3285: f64 = v3279 - v3284;
        let v3286: f64 = v72 * v3285;
        let v3287: f64 = v3286 - v2487;
        let v3288: f64 = v81 * v3287;
        let v3289: f64 = v3274 - v3288;
        let v3290: f64 = v36 * v3289;
        let v3291: f64 = v95 * v3271;
        let v3292: f64 = v1493 * v100;
        let v3293: f64 = v3291 - v3292;
        let v3294: f64 = v1482 * v95;
        let v3295: f64 = v100 * v3264;
        let v3296: f64 = v3294 + v3295;
        let v3297: f64 = v3293 + v3296;
        let v3298: f64 = v3297 - v2499;
        let v3299: f64 = v72 * v3298;
        let v3300: f64 = v142 * v3262;
        let v3301: f64 = v111 * v3269;
        let v3302: f64 = v3300 + v3301;
        let v3303: f64 = v2504 - v3302;
        let v3304: f64 = v112 * v3285;
        let v3305: f64 = v3303 + v3304;
        let v3306: f64 = v68 * v3305;
        let v3307: f64 = v3299 - v3306;
        let v3308: f64 = v95 * v3277;
        let v3309: f64 = v1509 * v100;
        let v3310: f64 = v3308 - v3309;
        let v3311: f64 = v1503 * v95;
        let v3312: f64 = v100 * v3282;
        let v3313: f64 = v3311 - v3312;
        let v3314: f64 = v3310 - v3313;
        let v3315: f64 = v81 * v3314;
        let v3316: f64 = v3307 + v3315;
        let v3317: f64 = v39 * v3316;
        let v3318: f64 = v3290 - v3317;
        let v3319: f64 = v68 * v3285;
        let v3320: f64 = v3319 + v2525;
        let v3321: f64 = v60 * v3320;
        let v3322: f64 = v3318 - v3321;
        let v3323: f64 = v36 * v3287;
        let v3324: f64 = v39 * v3314;
        let v3325: f64 = v3323 + v3324;
        let v3326: f64 = v25 * v3325;
        let v3327: f64 = v3322 - v3326;
        let v3328: f64 = v4 * v3327;
        let v3329: f64 = v36 * v3316;
        let v3330: f64 = v39 * v3289;
        let v3331: f64 = v3329 + v3330;
        let v3332: f64 = v36 * v3314;
        let v3333: f64 = v39 * v3287;
        let v3334: f64 = v3332 - v3333;
        let v3335: f64 = v25 * v3334;
        let v3336: f64 = v3331 + v3335;
        let v3337: f64 = v6 * v3336;
        let v3338: f64 = v3328 - v3337;
        let v3339: f64 = v30 * v3320;
        let v3340: f64 = v3338 - v3339;
        let v3341: f64 = v4 * v3325;
        let v3342: f64 = v6 * v3334;
        let v3343: f64 = v3341 + v3342;
        let v3344: f64 = v19 * v3343;
        let v3345: f64 = v3340 - v3344;
        let v3346: f64 = v2 * v3345;
        let v3347: f64 = v4 * v3336;
        let v3348: f64 = v6 * v3327;
        let v3349: f64 = v3347 + v3348;
        let v3350: f64 = v4 * v3334;
        let v3351: f64 = v6 * v3325;
        let v3352: f64 = v3350 - v3351;
        let v3353: f64 = v19 * v3352;
        let v3354: f64 = v3349 + v3353;
        let v3355: f64 = v8 * v3354;
        let v3356: f64 = v3346 - v3355;
        let v3357: f64 = v2570 * v39;
        let v3358: f64 = v2565 * v36;
        let v3359: f64 = v3357 + v3358;
        let v3360: f64 = v25 * v3359;
        let v3361: f64 = v2589 * v39;
        let v3362: f64 = v2583 * v36;
        let v3363: f64 = v3361 + v3362;
        let v3364: f64 = v3360 - v3363;
        let v3365: f64 = v4 * v3364;
        let v3366: f64 = v2570 * v36;
        let v3367: f64 = v2565 * v39;
        let v3368: f64 = v3366 - v3367;
        let v3369: f64 = v25 * v3368;
        let v3370: f64 = v2589 * v36;
        let v3371: f64 = v2583 * v39;
        let v3372: f64 = v3370 - v3371;
        let v3373: f64 = v3369 - v3372;
        let v3374: f64 = v6 * v3373;
        let v3375: f64 = v3365 + v3374;
        let v3376: f64 = v6 * v3368;
        let v3377: f64 = v4 * v3359;
        let v3378: f64 = v3376 + v3377;
        let v3379: f64 = v19 * v3378;
        let v3380: f64 = v3375 + v3379;
        let v3381: f64 = v2 * v3380;
        let v3382: f64 = v4 * v3373;
        let v3383: f64 = v6 * v3364;
        let v3384: f64 = v3382 - v3383;
        let v3385: f64 = v4 * v3368;
        let v3386: f64 = v6 * v3359;
        let v3387: f64 = v3385 - v3386;
        let v3388: f64 = v19 * v3387;
        let v3389: f64 = v3384 + v3388;
        let v3390: f64 = v8 * v3389;
        let v3391: f64 = v3381 + v3390;
        let v3392: f64 = v3356 + v3391;
        let v3393: f64 = v0 * v3392;
        let v3394: f64 = v3393 * v1461;
        let v3395: f64 = v3261 - v3394;
        let v3396: f64 = v2442 * v635;
        let v3397: f64 = v1334 * v1845;
        let v3398: f64 = v3396 - v3397;
        let v3399: f64 = v2948 * v923;
        (
            v3200,
            v3203,
            v3235,
            v3253,
            v3257,
            v3259,
            v3274,
            v3298,
            v3303,
            v3305,
            v3334,
            v3352,
            v3356,
            v3368,
            v3387,
            v3391,
            v3395,
            v3397,
            v3398,
            v3399,
        )
    };
    let (
        v3425,
        v3443,
        v3447,
        v3460,
        v3474,
        v3485,
        v3489,
        v3491,
        v3519,
        v3537,
        v3541,
        v3557,
        v3578,
        v3582,
        v3586,
        v3587,
        v3599,
    ) = {
        let v3400: f64 = v3398 + v3399;
        let v3401: f64 = v3259 * v1161;
        let v3402: f64 = v3400 + v3401;
        let v3403: f64 = v2216 * v72;
        let v3404: f64 = v2211 * v68;
        let v3405: f64 = v3403 - v3404;
        let v3406: f64 = v81 * v3405;
        let v3407: f64 = v36 * v3406;
        let v3408: f64 = v2227 * v68;
        let v3409: f64 = v2234 * v72;
        let v3410: f64 = v3408 + v3409;
        let v3411: f64 = v39 * v3410;
        let v3412: f64 = v3407 + v3411;
        let v3413: f64 = v2216 * v68;
        let v3414: f64 = v2211 * v72;
        let v3415: f64 = v3413 + v3414;
        let v3416: f64 = v60 * v3415;
        let v3417: f64 = v3412 + v3416;
        let v3418: f64 = v36 * v3405;
        let v3419: f64 = v25 * v3418;
        let v3420: f64 = v3417 + v3419;
        let v3421: f64 = v4 * v3420;
        let v3422: f64 = v39 * v3406;
        let v3423: f64 = v36 * v3410;
        let v3424: f64 = v3422 - v3423;
        let v3425: f64 = v39 * v3405;
        let v3426: f64 = v25 * v3425;
        let v3427: f64 = v3424 + v3426;
        let v3428: f64 = v6 * v3427;
        let v3429: f64 = v3421 - v3428;
        let v3430: f64 = v30 * v3415;
        let v3431: f64 = v3429 + v3430;
        let v3432: f64 = v6 * v3425;
        let v3433: f64 = v4 * v3418;
        let v3434: f64 = v3432 - v3433;
        let v3435: f64 = v19 * v3434;
        let v3436: f64 = v3431 - v3435;
        let v3437: f64 = v2 * v3436;
        let v3438: f64 = v4 * v3427;
        let v3439: f64 = v6 * v3420;
        let v3440: f64 = v3438 + v3439;
        let v3441: f64 = v4 * v3425;
        let v3442: f64 = v6 * v3418;
        let v3443: f64 = v3441 + v3442;
        let v3444: f64 = v19 * v3443;
        let v3445: f64 = v3440 + v3444;
        let v3446: f64 = v8 * v3445;
        let v3447: f64 = v3437 - v3446;
        let v3448: f64 = v3447 + v3447;
        let v3449: f64 = v0 * v3448;
        let v3450: f64 = v3449 * v1335;
        let v3451: f64 = v3402 - v3450;
        let v3452: f64 = v2208 * v95;
        let v3453: f64 = v3452 + v2237;
        let v3454: f64 = v2206 * v100;
        let v3455: f64 = v3454 + v2238;
        let v3456: f64 = v3453 - v3455;
        let v3457: f64 = v72 * v3456;
        let v3458: f64 = v142 * v95;
        let v3459: f64 = v111 * v100;
        let v3460: f64 = v3458 - v3459;
        let v3461: f64 = v68 * v3460;
        let v3462: f64 = v3457 + v3461;
        let v3463: f64 = v81 * v3462;
        let v3464: f64 = v2198 * v100;
        let v3465: f64 = v105 * v100;
        let v3466: f64 = v3465 + v2200;
        let v3467: f64 = v95 * v3466;
        let v3468: f64 = v3464 + v3467;
        let v3469: f64 = v2202 * v95;
        let v3470: f64 = v133 * v95;
        let v3471: f64 = v2197 + v3470;
        let v3472: f64 = v100 * v3471;
        let v3473: f64 = v3469 - v3472;
        let v3474: f64 = v3468 + v3473;
        let v3475: f64 = v3463 - v3474;
        let v3476: f64 = v36 * v3475;
        let v3477: f64 = v2198 * v95;
        let v3478: f64 = v100 * v3466;
        let v3479: f64 = v3477 - v3478;
        let v3480: f64 = v2202 * v100;
        let v3481: f64 = v95 * v3471;
        let v3482: f64 = v3480 + v3481;
        let v3483: f64 = v3479 - v3482;
        let v3484: f64 = v112 * v3460;
        let v3485: f64 = v3483 - v3484;
        let v3486: f64 = v72 * v3485;
        let v3487: f64 = v96 * v100;
        let v3488: f64 = v131 * v95;
        let v3489: f64 = v3487 + v3488;
        let v3490: f64 = v112 * v3456;
        let v3491: f64 = v3489 + v3490;
        let v3492: f64 = v68 * v3491;
        let v3493: f64 = v3486 + v3492;
        let v3494: f64 = v2206 * v95;
        let v3495: f64 = v3494 - v2209;
        let v3496: f64 = v2208 * v100;
        let v3497: f64 = v2207 - v3496;
        let v3498: f64 = v3495 - v3497;
        let v3499: f64 = v81 * v3498;
        let v3500: f64 = v3493 + v3499;
        let v3501: f64 = v39 * v3500;
        let v3502: f64 = v3476 - v3501;
        let v3503: f64 = v72 * v3460;
        let v3504: f64 = v68 * v3456;
        let v3505: f64 = v3503 - v3504;
        let v3506: f64 = v60 * v3505;
        let v3507: f64 = v3502 - v3506;
        let v3508: f64 = v39 * v3498;
        let v3509: f64 = v36 * v3462;
        let v3510: f64 = v3508 - v3509;
        let v3511: f64 = v25 * v3510;
        let v3512: f64 = v3507 - v3511;
        let v3513: f64 = v4 * v3512;
        let v3514: f64 = v36 * v3500;
        let v3515: f64 = v39 * v3475;
        let v3516: f64 = v3514 + v3515;
        let v3517: f64 = v36 * v3498;
        let v3518: f64 = v39 * v3462;
        let v3519: f64 = v3517 + v3518;
        let v3520: f64 = v25 * v3519;
        let v3521: f64 = v3516 + v3520;
        let v3522: f64 = v6 * v3521;
        let v3523: f64 = v3513 - v3522;
        let v3524: f64 = v30 * v3505;
        let v3525: f64 = v3523 - v3524;
        let v3526: f64 = v4 * v3510;
        let v3527: f64 = v6 * v3519;
        let v3528: f64 = v3526 + v3527;
        let v3529: f64 = v19 * v3528;
        let v3530: f64 = v3525 - v3529;
        let v3531: f64 = v2 * v3530;
        let v3532: f64 = v4 * v3521;
        let v3533: f64 = v6 * v3512;
        let v3534: f64 = v3532 + v3533;
        let v3535: f64 = v4 * v3519;
        let v3536: f64 = v6 * v3510;
        let v3537: f64 = v3535 - v3536;
        let v3538: f64 = v19 * v3537;
        let v3539: f64 = v3534 + v3538;
        let v3540: f64 = v8 * v3539;
        let v3541: f64 = v3531 - v3540;
        let v3542: f64 = v2569 * v68;
        let v3543: f64 = v81 * v3542;
        let v3544: f64 = v36 * v3543;
        let v3545: f64 = v2576 * v68;
        let v3546: f64 = v2579 * v72;
        let v3547: f64 = v3545 + v3546;
        let v3548: f64 = v39 * v3547;
        let v3549: f64 = v3544 + v3548;
        let v3550: f64 = v2569 * v72;
        let v3551: f64 = v60 * v3550;
        let v3552: f64 = v3549 - v3551;
        let v3553: f64 = v36 * v3542;
        let v3554: f64 = v25 * v3553;
        let v3555: f64 = v3552 + v3554;
        let v3556: f64 = v4 * v3555;
        let v3557: f64 = v39 * v3542;
        let v3558: f64 = v25 * v3557;
        let v3559: f64 = v39 * v3543;
        let v3560: f64 = v36 * v3547;
        let v3561: f64 = v3559 - v3560;
        let v3562: f64 = v3558 + v3561;
        let v3563: f64 = v6 * v3562;
        let v3564: f64 = v3556 - v3563;
        let v3565: f64 = v30 * v3550;
        let v3566: f64 = v3564 - v3565;
        let v3567: f64 = v4 * v3553;
        let v3568: f64 = v6 * v3557;
        let v3569: f64 = v3567 - v3568;
        let v3570: f64 = v19 * v3569;
        let v3571: f64 = v3566 + v3570;
        let v3572: f64 = v2 * v3571;
        let v3573: f64 = v4 * v3562;
        let v3574: f64 = v6 * v3555;
        let v3575: f64 = v3573 + v3574;
        let v3576: f64 = v4 * v3557;
        let v3577: f64 = v6 * v3553;
        let v3578: f64 = v3576 + v3577;
        let v3579: f64 = v19 * v3578;
        let v3580: f64 = v3575 + v3579;
        let v3581: f64 = v8 * v3580;
        let v3582: f64 = v3572 - v3581;
        let v3583: f64 = v3541 + v3582;
        let v3584: f64 = v0 * v3583;
        let v3585: f64 = v3584 * v1461;
        let v3586: f64 = v3451 - v3585;
        let v3587: f64 = v1460 * v1845;
        let v3588: f64 = v2624 + v2562;
        let v3589: f64 = v0 * v3588;
        let v3590: f64 = v3589 * v635;
        let v3591: f64 = v3587 + v3590;
        let v3592: f64 = v3068 + v3049;
        let v3593: f64 = v0 * v3592;
        let v3594: f64 = v3593 * v923;
        let v3595: f64 = v3591 + v3594;
        let v3596: f64 = v3391 + v3356;
        let v3597: f64 = v0 * v3596;
        let v3598: f64 = v3597 * v1161;
        let v3599: f64 = v3595 + v3598;
        (
            v3425,
            v3443,
            v3447,
            v3460,
            v3474,
            v3485,
            v3489,
            v3491,
            v3519,
            v3537,
            v3541,
            v3557,
            v3578,
            v3582,
            v3586,
            v3587,
            v3599,
        )
    };
    let (
        v3610,
        v3628,
        v3649,
        v3653,
        v3658,
        v3676,
        v3679,
        v3681,
        v3699,
        v3702,
        v3717,
        v3719,
        v3721,
        v3732,
        v3734,
        v3736,
        v3743,
        v3745,
        v3747,
        v3751,
        v3771,
        v3777,
        v3780,
        v3789,
        v3791,
        v3794,
        v3796,
        v3799,
    ) = {
        let v3600: f64 = v3582 + v3541;
        let v3601: f64 = v0 * v3600;
        let v3602: f64 = v3601 * v1335;
        let v3603: f64 = v3599 + v3602;
        let v3604: f64 = v2214 + v2213;
        let v3605: f64 = v72 * v3604;
        let v3606: f64 = v81 * v3605;
        let v3607: f64 = v3606 - v3489;
        let v3608: f64 = v36 * v3607;
        let v3609: f64 = v72 * v2231;
        let v3610: f64 = v112 * v3604;
        let v3611: f64 = v68 * v3610;
        let v3612: f64 = v3609 + v3611;
        let v3613: f64 = v81 * v3460;
        let v3614: f64 = v3612 - v3613;
        let v3615: f64 = v39 * v3614;
        let v3616: f64 = v3608 - v3615;
        let v3617: f64 = v68 * v3604;
        let v3618: f64 = v60 * v3617;
        let v3619: f64 = v3616 + v3618;
        let v3620: f64 = v36 * v3605;
        let v3621: f64 = v39 * v3460;
        let v3622: f64 = v3620 + v3621;
        let v3623: f64 = v25 * v3622;
        let v3624: f64 = v3619 + v3623;
        let v3625: f64 = v4 * v3624;
        let v3626: f64 = v36 * v3460;
        let v3627: f64 = v39 * v3605;
        let v3628: f64 = v3626 - v3627;
        let v3629: f64 = v25 * v3628;
        let v3630: f64 = v36 * v3614;
        let v3631: f64 = v39 * v3607;
        let v3632: f64 = v3630 + v3631;
        let v3633: f64 = v3629 - v3632;
        let v3634: f64 = v6 * v3633;
        let v3635: f64 = v3625 + v3634;
        let v3636: f64 = v30 * v3617;
        let v3637: f64 = v3635 + v3636;
        let v3638: f64 = v6 * v3628;
        let v3639: f64 = v4 * v3622;
        let v3640: f64 = v3638 + v3639;
        let v3641: f64 = v19 * v3640;
        let v3642: f64 = v3637 + v3641;
        let v3643: f64 = v2 * v3642;
        let v3644: f64 = v4 * v3633;
        let v3645: f64 = v6 * v3624;
        let v3646: f64 = v3644 - v3645;
        let v3647: f64 = v4 * v3628;
        let v3648: f64 = v6 * v3622;
        let v3649: f64 = v3647 - v3648;
        let v3650: f64 = v19 * v3649;
        let v3651: f64 = v3646 + v3650;
        let v3652: f64 = v8 * v3651;
        let v3653: f64 = v3643 + v3652;
        let v3654: f64 = v3653 + v3653;
        let v3655: f64 = v0 * v3654;
        let v3656: f64 = v3655 * v1461;
        let v3657: f64 = v3603 + v3656;
        let v3658: f64 = -v3657;
        let v3659: f64 = v1864 * v639;
        let v3660: f64 = v1848 * v643;
        let v3661: f64 = v3659 - v3660;
        let v3662: f64 = v29 * v666;
        let v3663: f64 = v292 * v650;
        let v3664: f64 = v3662 - v3663;
        let v3665: f64 = v3661 + v3664;
        let v3666: f64 = v1465 * v655;
        let v3667: f64 = v1526 * v659;
        let v3668: f64 = v3666 - v3667;
        let v3669: f64 = v194 * v669;
        let v3670: f64 = v59 * v713;
        let v3671: f64 = v3669 + v3670;
        let v3672: f64 = v3668 - v3671;
        let v3673: f64 = v68 * v795;
        let v3674: f64 = v72 * v817;
        let v3675: f64 = v3673 + v3674;
        let v3676: f64 = v3672 + v3675;
        let v3677: f64 = v3665 + v3676;
        let v3678: f64 = v60 * v881;
        let v3679: f64 = v3677 + v3678;
        let v3680: f64 = v30 * v917;
        let v3681: f64 = v3679 + v3680;
        let v3682: f64 = v1864 * v10;
        let v3683: f64 = v1848 * v15;
        let v3684: f64 = v3682 - v3683;
        let v3685: f64 = v29 * v54;
        let v3686: f64 = v292 * v27;
        let v3687: f64 = v3685 - v3686;
        let v3688: f64 = v3684 + v3687;
        let v3689: f64 = v1465 * v41;
        let v3690: f64 = v1526 * v46;
        let v3691: f64 = v3689 - v3690;
        let v3692: f64 = v194 * v57;
        let v3693: f64 = v59 * v122;
        let v3694: f64 = v3692 + v3693;
        let v3695: f64 = v3691 - v3694;
        let v3696: f64 = v68 * v214;
        let v3697: f64 = v72 * v238;
        let v3698: f64 = v3696 + v3697;
        let v3699: f64 = v3695 + v3698;
        let v3700: f64 = v3688 + v3699;
        let v3701: f64 = v60 * v305;
        let v3702: f64 = v3700 + v3701;
        let v3703: f64 = v3681 - v3702;
        let v3704: f64 = v0 * v3703;
        let v3705: f64 = v3704 * v923;
        let v3706: f64 = v1846 + v3705;
        let v3707: f64 = v1465 * v928;
        let v3708: f64 = v1526 * v932;
        let v3709: f64 = v3707 - v3708;
        let v3710: f64 = v194 * v937;
        let v3711: f64 = v59 * v974;
        let v3712: f64 = v3710 - v3711;
        let v3713: f64 = v3709 - v3712;
        let v3714: f64 = v68 * v1057;
        let v3715: f64 = v72 * v1079;
        let v3716: f64 = v3714 + v3715;
        let v3717: f64 = v3713 + v3716;
        let v3718: f64 = v60 * v1137;
        let v3719: f64 = v3717 + v3718;
        let v3720: f64 = v30 * v1155;
        let v3721: f64 = v3719 + v3720;
        let v3722: f64 = v3721 - v3699;
        let v3723: f64 = v0 * v3722;
        let v3724: f64 = v3723 * v1161;
        let v3725: f64 = v3706 + v3724;
        let v3726: f64 = v488 * v72;
        let v3727: f64 = v68 * v1255;
        let v3728: f64 = v3726 + v3727;
        let v3729: f64 = v72 * v1276;
        let v3730: f64 = v510 * v68;
        let v3731: f64 = v3729 - v3730;
        let v3732: f64 = v3728 + v3731;
        let v3733: f64 = v60 * v1311;
        let v3734: f64 = v3732 + v3733;
        let v3735: f64 = v30 * v1329;
        let v3736: f64 = v3734 + v3735;
        let v3737: f64 = v3736 - v148;
        let v3738: f64 = v0 * v3737;
        let v3739: f64 = v3738 * v1335;
        let v3740: f64 = v3725 + v3739;
        let v3741: f64 = v68 * v1397;
        let v3742: f64 = v72 * v1407;
        let v3743: f64 = v3741 + v3742;
        let v3744: f64 = v60 * v1437;
        let v3745: f64 = v3743 + v3744;
        let v3746: f64 = v30 * v1455;
        let v3747: f64 = v3745 + v3746;
        let v3748: f64 = v3747 - v235;
        let v3749: f64 = v0 * v3748;
        let v3750: f64 = v3749 * v1461;
        let v3751: f64 = v3740 + v3750;
        let v3752: f64 = v1887 * v20;
        let v3753: f64 = v1905 * v22;
        let v3754: f64 = v3752 - v3753;
        let v3755: f64 = v1847 * v2;
        let v3756: f64 = v1895 * v8;
        let v3757: f64 = v3755 - v3756;
        let v3758: f64 = v3754 - v3757;
        let v3759: f64 = v3758 + v3702;
        let v3760: f64 = v30 * v627;
        let v3761: f64 = v3759 + v3760;
        let v3762: f64 = v3761 + v1910;
        let v3763: f64 = v0 * v3762;
        let v3764: f64 = v3763 * v1845;
        let v3765: f64 = v68 * v1966;
        let v3766: f64 = v72 * v1976;
        let v3767: f64 = v3765 + v3766;
        let v3768: f64 = v194 * v1916;
        let v3769: f64 = v59 * v1925;
        let v3770: f64 = v3768 - v3769;
        let v3771: f64 = v3767 - v3770;
        let v3772: f64 = v29 * v1610;
        let v3773: f64 = v292 * v1607;
        let v3774: f64 = v3772 + v3773;
        let v3775: f64 = v3771 - v3774;
        let v3776: f64 = v60 * v2016;
        let v3777: f64 = v3775 - v3776;
        let v3778: f64 = v30 * v2048;
        let v3779: f64 = v3777 + v3778;
        let v3780: f64 = v0 * v3779;
        let v3781: f64 = v3780 * v923;
        let v3782: f64 = v3764 + v3781;
        let v3783: f64 = v68 * v1756;
        let v3784: f64 = v72 * v1766;
        let v3785: f64 = v3783 + v3784;
        let v3786: f64 = v194 * v1612;
        let v3787: f64 = v59 * v1622;
        let v3788: f64 = v3786 - v3787;
        let v3789: f64 = v3785 - v3788;
        let v3790: f64 = v60 * v1812;
        let v3791: f64 = v3789 - v3790;
        let v3792: f64 = v30 * v1837;
        let v3793: f64 = v3791 - v3792;
        let v3794: f64 = v0 * v3793;
        let v3795: f64 = v3794 * v1161;
        let v3796: f64 = v3782 + v3795;
        let v3797: f64 = v1723 * v72;
        let v3798: f64 = v68 * v2363;
        let v3799: f64 = v3797 + v3798;
        (
            v3610,
            v3628,
            v3649,
            v3653,
            v3658,
            v3676,
            v3679,
            v3681,
            v3699,
            v3702,
            v3717,
            v3719,
            v3721,
            v3732,
            v3734,
            v3736,
            v3743,
            v3745,
            v3747,
            v3751,
            v3771,
            v3777,
            v3780,
            v3789,
            v3791,
            v3794,
            v3796,
            v3799,
        )
    };
    let (
        v3803,
        v3805,
        v3813,
        v3815,
        v3820,
        v3824,
        v3826,
        v3837,
        v3839,
        v3841,
        v3842,
        v3853,
        v3855,
        v3857,
        v3858,
        v3865,
        v3867,
        v3869,
        v3870,
        v3874,
        v3878,
        v3882,
        v3884,
        v3895,
        v3897,
        v3899,
        v3900,
        v3902,
        v3909,
        v3911,
        v3913,
        v3914,
        v3916,
        v3920,
        v3924,
        v3934,
        v3936,
        v3938,
        v3945,
        v3947,
        v3949,
        v3952,
        v3954,
        v3956,
        v3960,
        v3964,
        v3976,
        v3978,
        v3980,
        v3984,
        v3996,
        v3999,
    ) = {
        let v3800: f64 = v72 * v2383;
        let v3801: f64 = v1735 * v68;
        let v3802: f64 = v3800 - v3801;
        let v3803: f64 = v3799 + v3802;
        let v3804: f64 = v60 * v2418;
        let v3805: f64 = v3803 + v3804;
        let v3806: f64 = v30 * v2436;
        let v3807: f64 = v3805 + v3806;
        let v3808: f64 = v0 * v3807;
        let v3809: f64 = v3808 * v1335;
        let v3810: f64 = v3796 + v3809;
        let v3811: f64 = v68 * v2500;
        let v3812: f64 = v72 * v2510;
        let v3813: f64 = v3811 + v3812;
        let v3814: f64 = v60 * v2540;
        let v3815: f64 = v3813 + v3814;
        let v3816: f64 = v30 * v2558;
        let v3817: f64 = v3815 + v3816;
        let v3818: f64 = v0 * v3817;
        let v3819: f64 = v3818 * v1461;
        let v3820: f64 = v3810 + v3819;
        let v3821: f64 = v3681 + v2190;
        let v3822: f64 = v0 * v3821;
        let v3823: f64 = v3822 * v1845;
        let v3824: f64 = v3780 * v635;
        let v3825: f64 = v3823 + v3824;
        let v3826: f64 = v30 * v2793;
        let v3827: f64 = v3826 + v3826;
        let v3828: f64 = v0 * v3827;
        let v3829: f64 = v3828 * v923;
        let v3830: f64 = v3825 - v3829;
        let v3831: f64 = v68 * v2697;
        let v3832: f64 = v72 * v2707;
        let v3833: f64 = v3831 + v3832;
        let v3834: f64 = v194 * v2053;
        let v3835: f64 = v59 * v2057;
        let v3836: f64 = v3834 - v3835;
        let v3837: f64 = v3833 - v3836;
        let v3838: f64 = v60 * v2744;
        let v3839: f64 = v3837 - v3838;
        let v3840: f64 = v30 * v2769;
        let v3841: f64 = v3839 - v3840;
        let v3842: f64 = v30 * v2643;
        let v3843: f64 = v3841 - v3842;
        let v3844: f64 = v0 * v3843;
        let v3845: f64 = v3844 * v1161;
        let v3846: f64 = v3830 + v3845;
        let v3847: f64 = v2086 * v72;
        let v3848: f64 = v68 * v2879;
        let v3849: f64 = v3847 + v3848;
        let v3850: f64 = v72 * v2892;
        let v3851: f64 = v2105 * v68;
        let v3852: f64 = v3850 - v3851;
        let v3853: f64 = v3849 + v3852;
        let v3854: f64 = v60 * v2924;
        let v3855: f64 = v3853 + v3854;
        let v3856: f64 = v30 * v2942;
        let v3857: f64 = v3855 + v3856;
        let v3858: f64 = v30 * v2820;
        let v3859: f64 = v3857 - v3858;
        let v3860: f64 = v0 * v3859;
        let v3861: f64 = v3860 * v1335;
        let v3862: f64 = v3846 + v3861;
        let v3863: f64 = v68 * v2991;
        let v3864: f64 = v72 * v2998;
        let v3865: f64 = v3863 + v3864;
        let v3866: f64 = v60 * v3027;
        let v3867: f64 = v3865 + v3866;
        let v3868: f64 = v30 * v3045;
        let v3869: f64 = v3867 + v3868;
        let v3870: f64 = v30 * v3061;
        let v3871: f64 = v3869 - v3870;
        let v3872: f64 = v0 * v3871;
        let v3873: f64 = v3872 * v1461;
        let v3874: f64 = v3862 + v3873;
        let v3875: f64 = v3721 - v1606;
        let v3876: f64 = v0 * v3875;
        let v3877: f64 = v3876 * v1845;
        let v3878: f64 = v3794 * v635;
        let v3879: f64 = v3877 + v3878;
        let v3880: f64 = v3844 * v923;
        let v3881: f64 = v3879 + v3880;
        let v3882: f64 = v60 * v3092;
        let v3883: f64 = v30 * v3108;
        let v3884: f64 = v3882 + v3883;
        let v3885: f64 = v3884 + v3884;
        let v3886: f64 = v0 * v3885;
        let v3887: f64 = v3886 * v1161;
        let v3888: f64 = v3881 - v3887;
        let v3889: f64 = v1535 * v72;
        let v3890: f64 = v68 * v3192;
        let v3891: f64 = v3889 + v3890;
        let v3892: f64 = v72 * v3203;
        let v3893: f64 = v1551 * v68;
        let v3894: f64 = v3892 - v3893;
        let v3895: f64 = v3891 + v3894;
        let v3896: f64 = v60 * v3235;
        let v3897: f64 = v3895 + v3896;
        let v3898: f64 = v30 * v3253;
        let v3899: f64 = v3897 + v3898;
        let v3900: f64 = v60 * v3131;
        let v3901: f64 = v30 * v3147;
        let v3902: f64 = v3900 + v3901;
        let v3903: f64 = v3899 + v3902;
        let v3904: f64 = v0 * v3903;
        let v3905: f64 = v3904 * v1335;
        let v3906: f64 = v3888 + v3905;
        let v3907: f64 = v68 * v3298;
        let v3908: f64 = v72 * v3305;
        let v3909: f64 = v3907 + v3908;
        let v3910: f64 = v60 * v3334;
        let v3911: f64 = v3909 + v3910;
        let v3912: f64 = v30 * v3352;
        let v3913: f64 = v3911 + v3912;
        let v3914: f64 = v60 * v3368;
        let v3915: f64 = v30 * v3387;
        let v3916: f64 = v3914 + v3915;
        let v3917: f64 = v3913 - v3916;
        let v3918: f64 = v0 * v3917;
        let v3919: f64 = v3918 * v1461;
        let v3920: f64 = v3906 + v3919;
        let v3921: f64 = v3736 - v2282;
        let v3922: f64 = v0 * v3921;
        let v3923: f64 = v3922 * v1845;
        let v3924: f64 = v3808 * v635;
        let v3925: f64 = v3923 + v3924;
        let v3926: f64 = v3860 * v923;
        let v3927: f64 = v3925 + v3926;
        let v3928: f64 = v3902 + v3899;
        let v3929: f64 = v0 * v3928;
        let v3930: f64 = v3929 * v1161;
        let v3931: f64 = v3927 + v3930;
        let v3932: f64 = v2227 * v72;
        let v3933: f64 = v2234 * v68;
        let v3934: f64 = v3932 - v3933;
        let v3935: f64 = v60 * v3425;
        let v3936: f64 = v3934 + v3935;
        let v3937: f64 = v30 * v3443;
        let v3938: f64 = v3936 + v3937;
        let v3939: f64 = v3938 + v3938;
        let v3940: f64 = v0 * v3939;
        let v3941: f64 = v3940 * v1335;
        let v3942: f64 = v3931 + v3941;
        let v3943: f64 = v68 * v3485;
        let v3944: f64 = v72 * v3491;
        let v3945: f64 = v3943 - v3944;
        let v3946: f64 = v60 * v3519;
        let v3947: f64 = v3945 + v3946;
        let v3948: f64 = v30 * v3537;
        let v3949: f64 = v3947 + v3948;
        let v3950: f64 = v2576 * v72;
        let v3951: f64 = v2579 * v68;
        let v3952: f64 = v3950 - v3951;
        let v3953: f64 = v60 * v3557;
        let v3954: f64 = v3952 + v3953;
        let v3955: f64 = v30 * v3578;
        let v3956: f64 = v3954 + v3955;
        let v3957: f64 = v3949 + v3956;
        let v3958: f64 = v0 * v3957;
        let v3959: f64 = v3958 * v1461;
        let v3960: f64 = v3942 + v3959;
        let v3961: f64 = v3747 + v2624;
        let v3962: f64 = v0 * v3961;
        let v3963: f64 = v3962 * v1845;
        let v3964: f64 = v3818 * v635;
        let v3965: f64 = v3963 + v3964;
        let v3966: f64 = v3872 * v923;
        let v3967: f64 = v3965 + v3966;
        let v3968: f64 = v3918 * v1161;
        let v3969: f64 = v3967 + v3968;
        let v3970: f64 = v3956 + v3949;
        let v3971: f64 = v0 * v3970;
        let v3972: f64 = v3971 * v1335;
        let v3973: f64 = v3969 + v3972;
        let v3974: f64 = v68 * v2231;
        let v3975: f64 = v72 * v3610;
        let v3976: f64 = v3974 - v3975;
        let v3977: f64 = v60 * v3628;
        let v3978: f64 = v3976 - v3977;
        let v3979: f64 = v30 * v3649;
        let v3980: f64 = v3978 - v3979;
        let v3981: f64 = v3980 + v3980;
        let v3982: f64 = v0 * v3981;
        let v3983: f64 = v3982 * v1461;
        let v3984: f64 = v3973 + v3983;
        let v3985: f64 = v3702 - v3681;
        let v3986: f64 = v0 * v3985;
        let v3987: f64 = v3986 * v635;
        let v3988: f64 = v2777 + v3987;
        let v3989: f64 = v3719 - v3676;
        let v3990: f64 = v0 * v3989;
        let v3991: f64 = v3990 * v1161;
        let v3992: f64 = v3988 + v3991;
        let v3993: f64 = v3734 - v736;
        let v3994: f64 = v0 * v3993;
        let v3995: f64 = v3994 * v1335;
        let v3996: f64 = v3992 + v3995;
        let v3997: f64 = v3745 - v814;
        let v3998: f64 = v0 * v3997;
        let v3999: f64 = v3998 * v1461;
        (
            v3803,
            v3805,
            v3813,
            v3815,
            v3820,
            v3824,
            v3826,
            v3837,
            v3839,
            v3841,
            v3842,
            v3853,
            v3855,
            v3857,
            v3858,
            v3865,
            v3867,
            v3869,
            v3870,
            v3874,
            v3878,
            v3882,
            v3884,
            v3895,
            v3897,
            v3899,
            v3900,
            v3902,
            v3909,
            v3911,
            v3913,
            v3914,
            v3916,
            v3920,
            v3924,
            v3934,
            v3936,
            v3938,
            v3945,
            v3947,
            v3949,
            v3952,
            v3954,
            v3956,
            v3960,
            v3964,
            v3976,
            v3978,
            v3980,
            v3984,
            v3996,
            v3999,
        )
    };
    let (
        v4000,
        v4016,
        v4032,
        v4053,
        v4061,
        v4074,
        v4082,
        v4093,
        v4109,
        v4125,
        v4141,
        v4158,
        v4170,
        v4179,
        v4191,
        v4196,
        v4199,
    ) = {
        let v4000: f64 = v3996 + v3999;
        let v4001: f64 = v3702 + v2052;
        let v4002: f64 = v0 * v4001;
        let v4003: f64 = v4002 * v1845;
        let v4004: f64 = v4003 - v3824;
        let v4005: f64 = v3791 - v3771;
        let v4006: f64 = v0 * v4005;
        let v4007: f64 = v4006 * v1161;
        let v4008: f64 = v4004 + v4007;
        let v4009: f64 = v3805 - v1940;
        let v4010: f64 = v0 * v4009;
        let v4011: f64 = v4010 * v1335;
        let v4012: f64 = v4008 + v4011;
        let v4013: f64 = v3815 - v1970;
        let v4014: f64 = v0 * v4013;
        let v4015: f64 = v4014 * v1461;
        let v4016: f64 = v4012 + v4015;
        let v4017: f64 = v3679 + v2800;
        let v4018: f64 = v0 * v4017;
        let v4019: f64 = v4018 * v1845;
        let v4020: f64 = v3777 + v3826;
        let v4021: f64 = v0 * v4020;
        let v4022: f64 = v4021 * v635;
        let v4023: f64 = v4019 + v4022;
        let v4024: f64 = v0 * v3839;
        let v4025: f64 = v4024 * v1161;
        let v4026: f64 = v4023 + v4025;
        let v4027: f64 = v0 * v3855;
        let v4028: f64 = v4027 * v1335;
        let v4029: f64 = v4026 + v4028;
        let v4030: f64 = v0 * v3867;
        let v4031: f64 = v4030 * v1461;
        let v4032: f64 = v4029 + v4031;
        let v4033: f64 = v3719 - v2647;
        let v4034: f64 = v0 * v4033;
        let v4035: f64 = v4034 * v1845;
        let v4036: f64 = v3791 + v3842;
        let v4037: f64 = v0 * v4036;
        let v4038: f64 = v4037 * v635;
        let v4039: f64 = v4035 + v4038;
        let v4040: f64 = v4024 * v923;
        let v4041: f64 = v4039 + v4040;
        let v4042: f64 = v3882 + v3882;
        let v4043: f64 = v0 * v4042;
        let v4044: f64 = v4043 * v1161;
        let v4045: f64 = v4041 - v4044;
        let v4046: f64 = v3897 + v3900;
        let v4047: f64 = v0 * v4046;
        let v4048: f64 = v4047 * v1335;
        let v4049: f64 = v4045 + v4048;
        let v4050: f64 = v3911 - v3914;
        let v4051: f64 = v0 * v4050;
        let v4052: f64 = v4051 * v1461;
        let v4053: f64 = v4049 + v4052;
        let v4054: f64 = v3734 - v2824;
        let v4055: f64 = v0 * v4054;
        let v4056: f64 = v4055 * v1845;
        let v4057: f64 = v3805 + v3858;
        let v4058: f64 = v0 * v4057;
        let v4059: f64 = v4058 * v635;
        let v4060: f64 = v4056 + v4059;
        let v4061: f64 = v4027 * v923;
        let v4062: f64 = v4060 + v4061;
        let v4063: f64 = v3900 + v3897;
        let v4064: f64 = v0 * v4063;
        let v4065: f64 = v4064 * v1161;
        let v4066: f64 = v4062 + v4065;
        let v4067: f64 = v3936 + v3936;
        let v4068: f64 = v0 * v4067;
        let v4069: f64 = v4068 * v1335;
        let v4070: f64 = v4066 + v4069;
        let v4071: f64 = v3947 + v3954;
        let v4072: f64 = v0 * v4071;
        let v4073: f64 = v4072 * v1461;
        let v4074: f64 = v4070 + v4073;
        let v4075: f64 = v3745 + v3068;
        let v4076: f64 = v0 * v4075;
        let v4077: f64 = v4076 * v1845;
        let v4078: f64 = v3815 + v3870;
        let v4079: f64 = v0 * v4078;
        let v4080: f64 = v4079 * v635;
        let v4081: f64 = v4077 + v4080;
        let v4082: f64 = v4030 * v923;
        let v4083: f64 = v4081 + v4082;
        let v4084: f64 = v4051 * v1161;
        let v4085: f64 = v4083 + v4084;
        let v4086: f64 = v3954 + v3947;
        let v4087: f64 = v0 * v4086;
        let v4088: f64 = v4087 * v1335;
        let v4089: f64 = v4085 + v4088;
        let v4090: f64 = v3978 + v3978;
        let v4091: f64 = v0 * v4090;
        let v4092: f64 = v4091 * v1461;
        let v4093: f64 = v4089 + v4092;
        let v4094: f64 = v3699 - v3721;
        let v4095: f64 = v0 * v4094;
        let v4096: f64 = v4095 * v635;
        let v4097: f64 = v3074 + v4096;
        let v4098: f64 = v3676 - v3719;
        let v4099: f64 = v0 * v4098;
        let v4100: f64 = v4099 * v923;
        let v4101: f64 = v4097 + v4100;
        let v4102: f64 = v3732 - v997;
        let v4103: f64 = v0 * v4102;
        let v4104: f64 = v4103 * v1335;
        let v4105: f64 = v4101 + v4104;
        let v4106: f64 = v3743 - v1076;
        let v4107: f64 = v0 * v4106;
        let v4108: f64 = v4107 * v1461;
        let v4109: f64 = v4105 + v4108;
        let v4110: f64 = v3699 + v1841;
        let v4111: f64 = v0 * v4110;
        let v4112: f64 = v4111 * v1845;
        let v4113: f64 = v4112 - v3878;
        let v4114: f64 = v3771 - v3791;
        let v4115: f64 = v0 * v4114;
        let v4116: f64 = v4115 * v923;
        let v4117: f64 = v4113 + v4116;
        let v4118: f64 = v3803 - v1637;
        let v4119: f64 = v0 * v4118;
        let v4120: f64 = v4119 * v1335;
        let v4121: f64 = v4117 + v4120;
        let v4122: f64 = v3813 - v1760;
        let v4123: f64 = v0 * v4122;
        let v4124: f64 = v4123 * v1461;
        let v4125: f64 = v4121 + v4124;
        let v4126: f64 = v3676 + v2773;
        let v4127: f64 = v0 * v4126;
        let v4128: f64 = v4127 * v1845;
        let v4129: f64 = v3771 - v3841;
        let v4130: f64 = v0 * v4129;
        let v4131: f64 = v4130 * v635;
        let v4132: f64 = v4128 + v4131;
        let v4133: f64 = v4132 - v4040;
        let v4134: f64 = v3853 - v2668;
        let v4135: f64 = v0 * v4134;
        let v4136: f64 = v4135 * v1335;
        let v4137: f64 = v4133 + v4136;
        let v4138: f64 = v3865 - v2701;
        let v4139: f64 = v0 * v4138;
        let v4140: f64 = v4139 * v1461;
        let v4141: f64 = v4137 + v4140;
        let v4142: f64 = v3717 - v3112;
        let v4143: f64 = v0 * v4142;
        let v4144: f64 = v4143 * v1845;
        let v4145: f64 = v3789 + v3884;
        let v4146: f64 = v0 * v4145;
        let v4147: f64 = v4146 * v635;
        let v4148: f64 = v4144 + v4147;
        let v4149: f64 = v3837 + v3882;
        let v4150: f64 = v0 * v4149;
        let v4151: f64 = v4150 * v923;
        let v4152: f64 = v4148 + v4151;
        let v4153: f64 = v0 * v3895;
        let v4154: f64 = v4153 * v1335;
        let v4155: f64 = v4152 + v4154;
        let v4156: f64 = v0 * v3909;
        let v4157: f64 = v4156 * v1461;
        let v4158: f64 = v4155 + v4157;
        let v4159: f64 = v3732 - v3151;
        let v4160: f64 = v0 * v4159;
        let v4161: f64 = v4160 * v1845;
        let v4162: f64 = v3803 - v3902;
        let v4163: f64 = v0 * v4162;
        let v4164: f64 = v4163 * v635;
        let v4165: f64 = v4161 + v4164;
        let v4166: f64 = v3853 - v3900;
        let v4167: f64 = v0 * v4166;
        let v4168: f64 = v4167 * v923;
        let v4169: f64 = v4165 + v4168;
        let v4170: f64 = v4153 * v1161;
        let v4171: f64 = v4169 + v4170;
        let v4172: f64 = v3934 + v3934;
        let v4173: f64 = v0 * v4172;
        let v4174: f64 = v4173 * v1335;
        let v4175: f64 = v4171 + v4174;
        let v4176: f64 = v3945 + v3952;
        let v4177: f64 = v0 * v4176;
        let v4178: f64 = v4177 * v1461;
        let v4179: f64 = v4175 + v4178;
        let v4180: f64 = v3743 + v3391;
        let v4181: f64 = v0 * v4180;
        let v4182: f64 = v4181 * v1845;
        let v4183: f64 = v3813 + v3916;
        let v4184: f64 = v0 * v4183;
        let v4185: f64 = v4184 * v635;
        let v4186: f64 = v4182 + v4185;
        let v4187: f64 = v3865 + v3914;
        let v4188: f64 = v0 * v4187;
        let v4189: f64 = v4188 * v923;
        let v4190: f64 = v4186 + v4189;
        let v4191: f64 = v4156 * v1161;
        let v4192: f64 = v4190 + v4191;
        let v4193: f64 = v3952 + v3945;
        let v4194: f64 = v0 * v4193;
        let v4195: f64 = v4194 * v1335;
        let v4196: f64 = v4192 + v4195;
        let v4197: f64 = v3976 + v3976;
        let v4198: f64 = v0 * v4197;
        let v4199: f64 = v4198 * v1461;
        (
            v4000,
            v4016,
            v4032,
            v4053,
            v4061,
            v4074,
            v4082,
            v4093,
            v4109,
            v4125,
            v4141,
            v4158,
            v4170,
            v4179,
            v4191,
            v4196,
            v4199,
        )
    };
    let (
        v4200,
        v4216,
        v4232,
        v4248,
        v4264,
        v4282,
        v4303,
        v4319,
        v4335,
        v4351,
        v4367,
        v4383,
        v4398,
    ) = {
        let v4200: f64 = v4196 + v4199;
        let v4201: f64 = v148 - v3736;
        let v4202: f64 = v0 * v4201;
        let v4203: f64 = v4202 * v635;
        let v4204: f64 = v3397 + v4203;
        let v4205: f64 = v736 - v3734;
        let v4206: f64 = v0 * v4205;
        let v4207: f64 = v4206 * v923;
        let v4208: f64 = v4204 + v4207;
        let v4209: f64 = v997 - v3732;
        let v4210: f64 = v0 * v4209;
        let v4211: f64 = v4210 * v1161;
        let v4212: f64 = v4208 + v4211;
        let v4213: f64 = v1366 - v1273;
        let v4214: f64 = v0 * v4213;
        let v4215: f64 = v4214 * v1461;
        let v4216: f64 = v4212 + v4215;
        let v4217: f64 = v148 + v2440;
        let v4218: f64 = v0 * v4217;
        let v4219: f64 = v4218 * v1845;
        let v4220: f64 = v4219 - v3924;
        let v4221: f64 = v1940 - v3805;
        let v4222: f64 = v0 * v4221;
        let v4223: f64 = v4222 * v923;
        let v4224: f64 = v4220 + v4223;
        let v4225: f64 = v1637 - v3803;
        let v4226: f64 = v0 * v4225;
        let v4227: f64 = v4226 * v1161;
        let v4228: f64 = v4224 + v4227;
        let v4229: f64 = v2469 - v2380;
        let v4230: f64 = v0 * v4229;
        let v4231: f64 = v4230 * v1461;
        let v4232: f64 = v4228 + v4231;
        let v4233: f64 = v736 + v2946;
        let v4234: f64 = v0 * v4233;
        let v4235: f64 = v4234 * v1845;
        let v4236: f64 = v1940 - v3857;
        let v4237: f64 = v0 * v4236;
        let v4238: f64 = v4237 * v635;
        let v4239: f64 = v4235 + v4238;
        let v4240: f64 = v4239 - v4061;
        let v4241: f64 = v2668 - v3853;
        let v4242: f64 = v0 * v4241;
        let v4243: f64 = v4242 * v1161;
        let v4244: f64 = v4240 + v4243;
        let v4245: f64 = v2967 - v2889;
        let v4246: f64 = v0 * v4245;
        let v4247: f64 = v4246 * v1461;
        let v4248: f64 = v4244 + v4247;
        let v4249: f64 = v997 + v3257;
        let v4250: f64 = v0 * v4249;
        let v4251: f64 = v4250 * v1845;
        let v4252: f64 = v1637 - v3899;
        let v4253: f64 = v0 * v4252;
        let v4254: f64 = v4253 * v635;
        let v4255: f64 = v4251 + v4254;
        let v4256: f64 = v2668 - v3897;
        let v4257: f64 = v0 * v4256;
        let v4258: f64 = v4257 * v923;
        let v4259: f64 = v4255 + v4258;
        let v4260: f64 = v4259 - v4170;
        let v4261: f64 = v3274 - v3200;
        let v4262: f64 = v0 * v4261;
        let v4263: f64 = v4262 * v1461;
        let v4264: f64 = v4260 + v4263;
        let v4265: f64 = v1208 + v3447;
        let v4266: f64 = v0 * v4265;
        let v4267: f64 = v4266 * v1845;
        let v4268: f64 = v2319 - v3938;
        let v4269: f64 = v0 * v4268;
        let v4270: f64 = v4269 * v635;
        let v4271: f64 = v4267 + v4270;
        let v4272: f64 = v2846 - v3936;
        let v4273: f64 = v0 * v4272;
        let v4274: f64 = v4273 * v923;
        let v4275: f64 = v4271 + v4274;
        let v4276: f64 = v3165 - v3934;
        let v4277: f64 = v0 * v4276;
        let v4278: f64 = v4277 * v1161;
        let v4279: f64 = v4275 + v4278;
        let v4280: f64 = v0 * v3474;
        let v4281: f64 = v4280 * v1461;
        let v4282: f64 = v4279 - v4281;
        let v4283: f64 = v1366 + v3582;
        let v4284: f64 = v0 * v4283;
        let v4285: f64 = v4284 * v1845;
        let v4286: f64 = v2469 - v3956;
        let v4287: f64 = v0 * v4286;
        let v4288: f64 = v4287 * v635;
        let v4289: f64 = v4285 + v4288;
        let v4290: f64 = v2967 - v3954;
        let v4291: f64 = v0 * v4290;
        let v4292: f64 = v4291 * v923;
        let v4293: f64 = v4289 + v4292;
        let v4294: f64 = v3274 - v3952;
        let v4295: f64 = v0 * v4294;
        let v4296: f64 = v4295 * v1161;
        let v4297: f64 = v4293 + v4296;
        let v4298: f64 = v4280 * v1335;
        let v4299: f64 = v4297 - v4298;
        let v4300: f64 = v3489 + v3489;
        let v4301: f64 = v0 * v4300;
        let v4302: f64 = v4301 * v1461;
        let v4303: f64 = v4299 - v4302;
        let v4304: f64 = v235 - v3747;
        let v4305: f64 = v0 * v4304;
        let v4306: f64 = v4305 * v635;
        let v4307: f64 = v3587 + v4306;
        let v4308: f64 = v814 - v3745;
        let v4309: f64 = v0 * v4308;
        let v4310: f64 = v4309 * v923;
        let v4311: f64 = v4307 + v4310;
        let v4312: f64 = v1076 - v3743;
        let v4313: f64 = v0 * v4312;
        let v4314: f64 = v4313 * v1161;
        let v4315: f64 = v4311 + v4314;
        let v4316: f64 = v1273 - v1366;
        let v4317: f64 = v0 * v4316;
        let v4318: f64 = v4317 * v1335;
        let v4319: f64 = v4315 + v4318;
        let v4320: f64 = v235 + v2562;
        let v4321: f64 = v0 * v4320;
        let v4322: f64 = v4321 * v1845;
        let v4323: f64 = v4322 - v3964;
        let v4324: f64 = v1970 - v3815;
        let v4325: f64 = v0 * v4324;
        let v4326: f64 = v4325 * v923;
        let v4327: f64 = v4323 + v4326;
        let v4328: f64 = v1760 - v3813;
        let v4329: f64 = v0 * v4328;
        let v4330: f64 = v4329 * v1161;
        let v4331: f64 = v4327 + v4330;
        let v4332: f64 = v2380 - v2469;
        let v4333: f64 = v0 * v4332;
        let v4334: f64 = v4333 * v1335;
        let v4335: f64 = v4331 + v4334;
        let v4336: f64 = v814 + v3049;
        let v4337: f64 = v0 * v4336;
        let v4338: f64 = v4337 * v1845;
        let v4339: f64 = v1970 - v3869;
        let v4340: f64 = v0 * v4339;
        let v4341: f64 = v4340 * v635;
        let v4342: f64 = v4338 + v4341;
        let v4343: f64 = v4342 - v4082;
        let v4344: f64 = v2701 - v3865;
        let v4345: f64 = v0 * v4344;
        let v4346: f64 = v4345 * v1161;
        let v4347: f64 = v4343 + v4346;
        let v4348: f64 = v2889 - v2967;
        let v4349: f64 = v0 * v4348;
        let v4350: f64 = v4349 * v1335;
        let v4351: f64 = v4347 + v4350;
        let v4352: f64 = v1076 + v3356;
        let v4353: f64 = v0 * v4352;
        let v4354: f64 = v4353 * v1845;
        let v4355: f64 = v1760 - v3913;
        let v4356: f64 = v0 * v4355;
        let v4357: f64 = v4356 * v635;
        let v4358: f64 = v4354 + v4357;
        let v4359: f64 = v2701 - v3911;
        let v4360: f64 = v0 * v4359;
        let v4361: f64 = v4360 * v923;
        let v4362: f64 = v4358 + v4361;
        let v4363: f64 = v4362 - v4191;
        let v4364: f64 = v3200 - v3274;
        let v4365: f64 = v0 * v4364;
        let v4366: f64 = v4365 * v1335;
        let v4367: f64 = v4363 + v4366;
        let v4368: f64 = v1273 + v3541;
        let v4369: f64 = v0 * v4368;
        let v4370: f64 = v4369 * v1845;
        let v4371: f64 = v2380 - v3949;
        let v4372: f64 = v0 * v4371;
        let v4373: f64 = v4372 * v635;
        let v4374: f64 = v4370 + v4373;
        let v4375: f64 = v2889 - v3947;
        let v4376: f64 = v0 * v4375;
        let v4377: f64 = v4376 * v923;
        let v4378: f64 = v4374 + v4377;
        let v4379: f64 = v3200 - v3945;
        let v4380: f64 = v0 * v4379;
        let v4381: f64 = v4380 * v1161;
        let v4382: f64 = v4378 + v4381;
        let v4383: f64 = v4382 + v4298;
        let v4384: f64 = v3653 - v1406;
        let v4385: f64 = v0 * v4384;
        let v4386: f64 = v4385 * v1845;
        let v4387: f64 = v2508 - v3980;
        let v4388: f64 = v0 * v4387;
        let v4389: f64 = v4388 * v635;
        let v4390: f64 = v4386 + v4389;
        let v4391: f64 = v2996 - v3978;
        let v4392: f64 = v0 * v4391;
        let v4393: f64 = v4392 * v923;
        let v4394: f64 = v4390 + v4393;
        let v4395: f64 = v3303 - v3976;
        let v4396: f64 = v0 * v4395;
        let v4397: f64 = v4396 * v1161;
        let v4398: f64 = v4394 + v4397;
        (
            v4200,
            v4216,
            v4232,
            v4248,
            v4264,
            v4282,
            v4303,
            v4319,
            v4335,
            v4351,
            v4367,
            v4383,
            v4398,
        )
    };
    [
        [v1464, v2628, v3072, v3395, v3586, v3658],
        [v3751, v3820, v3874, v3920, v3960, v3984],
        [v4000, v4016, v4032, v4053, v4074, v4093],
        [v4109, v4125, v4141, v4158, v4179, v4200],
        [v4216, v4232, v4248, v4264, v4282, v4303],
        [v4319, v4335, v4351, v4367, v4383, v4398],
    ]
}
/// Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53).
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 6]`: joint velocities qd (rad/s or m/s)
/// - `params: &[f64; 60]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `coriolis: [f64; 6]`: c(q, qd) = C(q, qd) qd (N m or N)
///
/// Operation count: 679 floating-point operations, 10 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn coriolis(q: &[f64; 6], qd: &[f64; 6], params: &[f64; 60]) -> [f64; 6] {
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
        v18,
        v20,
        v24,
        v28,
        v32,
        v33,
        v37,
        v39,
        v43,
        v46,
        v48,
        v49,
        v51,
        v56,
        v59,
        v61,
        v67,
        v69,
        v72,
        v74,
        v77,
        v79,
        v81,
        v87,
        v91,
        v94,
        v95,
        v107,
        v112,
        v114,
        v123,
        v126,
        v128,
        v129,
        v131,
        v136,
        v139,
        v141,
        v147,
        v149,
        v152,
        v155,
        v158,
        v160,
        v162,
        v167,
        v170,
        v171,
        v178,
        v179,
        v182,
        v183,
        v185,
        v188,
    ) = {
        let v0: f64 = q[1];
        let (v3, v1): (f64, f64) = ::armdyn_runtime::libm::sincos(v0);
        let v2: f64 = params[14];
        let v4: f64 = qd[0];
        let v5: f64 = v3 * v4;
        let v6: f64 = qd[1];
        let v7: f64 = v5 * v6;
        let v8: f64 = v2 * v7;
        let v9: f64 = params[16];
        let v10: f64 = v1 * v4;
        let v11: f64 = v10 * v6;
        let v12: f64 = v9 * v11;
        let v13: f64 = v8 - v12;
        let v14: f64 = params[18];
        let v15: f64 = v14 * v6;
        let v16: f64 = v9 * v10;
        let v17: f64 = v15 - v16;
        let v18: f64 = params[19];
        let v19: f64 = v18 * v5;
        let v20: f64 = v17 - v19;
        let v21: f64 = v6 * v20;
        let v22: f64 = params[17];
        let v23: f64 = v22 * v6;
        let v24: f64 = params[15];
        let v25: f64 = v24 * v10;
        let v26: f64 = v23 - v25;
        let v27: f64 = v14 * v5;
        let v28: f64 = v26 - v27;
        let v29: f64 = v5 * v28;
        let v30: f64 = v21 + v29;
        let v31: f64 = v13 + v30;
        let v32: f64 = params[12];
        let v33: f64 = 0.13585_f64;
        let v34: f64 = v33 * v7;
        let v35: f64 = v33 * v5;
        let v36: f64 = v6 * v35;
        let v37: f64 = v34 - v36;
        let v38: f64 = v32 * v37;
        let v39: f64 = params[13];
        let v40: f64 = v5 * v35;
        let v41: f64 = v33 * v10;
        let v42: f64 = v10 * v41;
        let v43: f64 = v40 + v42;
        let v44: f64 = v39 * v43;
        let v45: f64 = v38 + v44;
        let v46: f64 = v31 + v45;
        let v47: f64 = q[2];
        let (v51, v48): (f64, f64) = ::armdyn_runtime::libm::sincos(v47);
        let v49: f64 = params[24];
        let v50: f64 = v48 * v7;
        let v52: f64 = v51 * v11;
        let v53: f64 = v50 + v52;
        let v54: f64 = v51 * v10;
        let v55: f64 = v48 * v5;
        let v56: f64 = v54 + v55;
        let v57: f64 = qd[2];
        let v58: f64 = v56 * v57;
        let v59: f64 = v53 + v58;
        let v60: f64 = v49 * v59;
        let v61: f64 = params[26];
        let v62: f64 = v51 * v7;
        let v63: f64 = v48 * v11;
        let v64: f64 = v62 - v63;
        let v65: f64 = v51 * v5;
        let v66: f64 = v48 * v10;
        let v67: f64 = v65 - v66;
        let v68: f64 = v67 * v57;
        let v69: f64 = v64 + v68;
        let v70: f64 = v61 * v69;
        let v71: f64 = v60 + v70;
        let v72: f64 = v6 + v57;
        let v73: f64 = v61 * v67;
        let v74: f64 = params[28];
        let v75: f64 = v74 * v72;
        let v76: f64 = v73 + v75;
        let v77: f64 = params[29];
        let v78: f64 = v77 * v56;
        let v79: f64 = v76 - v78;
        let v80: f64 = v72 * v79;
        let v81: f64 = params[25];
        let v82: f64 = v81 * v67;
        let v83: f64 = params[27];
        let v84: f64 = v83 * v72;
        let v85: f64 = v82 + v84;
        let v86: f64 = v74 * v56;
        let v87: f64 = v85 - v86;
        let v88: f64 = v56 * v87;
        let v89: f64 = v80 + v88;
        let v90: f64 = v71 + v89;
        let v91: f64 = params[22];
        let v92: f64 = v33 * v11;
        let v93: f64 = v6 * v41;
        let v94: f64 = v92 - v93;
        let v95: f64 = 0.425_f64;
        let v96: f64 = v95 * v10;
        let v97: f64 = v5 * v96;
        let v98: f64 = v94 + v97;
        let v99: f64 = v51 * v98;
        let v100: f64 = v10 * v96;
        let v101: f64 = v95 * v6;
        let v102: f64 = v6 * v101;
        let v103: f64 = v100 + v102;
        let v104: f64 = v37 - v103;
        let v105: f64 = v48 * v104;
        let v106: f64 = v99 + v105;
        let v107: f64 = -0.1197_f64;
        let v108: f64 = v107 * v59;
        let v109: f64 = v107 * v56;
        let v110: f64 = v72 * v109;
        let v111: f64 = v108 - v110;
        let v112: f64 = v106 + v111;
        let v113: f64 = v91 * v112;
        let v114: f64 = params[23];
        let v115: f64 = v95 * v7;
        let v116: f64 = v5 * v101;
        let v117: f64 = v115 + v116;
        let v118: f64 = v43 + v117;
        let v119: f64 = v56 * v109;
        let v120: f64 = v107 * v67;
        let v121: f64 = v67 * v120;
        let v122: f64 = v119 + v121;
        let v123: f64 = v118 + v122;
        let v124: f64 = v114 * v123;
        let v125: f64 = v113 + v124;
        let v126: f64 = v90 + v125;
        let v127: f64 = q[3];
        let (v131, v128): (f64, f64) = ::armdyn_runtime::libm::sincos(v127);
        let v129: f64 = params[39];
        let v130: f64 = v128 * v59;
        let v132: f64 = v131 * v69;
        let v133: f64 = v130 - v132;
        let v134: f64 = v128 * v56;
        let v135: f64 = v131 * v67;
        let v136: f64 = v134 - v135;
        let v137: f64 = qd[3];
        let v138: f64 = v136 * v137;
        let v139: f64 = v133 + v138;
        let v140: f64 = v129 * v139;
        let v141: f64 = params[36];
        let v142: f64 = v131 * v59;
        let v143: f64 = v128 * v69;
        let v144: f64 = v142 + v143;
        let v145: f64 = v128 * v67;
        let v146: f64 = v131 * v56;
        let v147: f64 = v145 + v146;
        let v148: f64 = v147 * v137;
        let v149: f64 = v144 + v148;
        let v150: f64 = v141 * v149;
        let v151: f64 = v140 - v150;
        let v152: f64 = params[35];
        let v153: f64 = v152 * v136;
        let v154: f64 = params[37];
        let v155: f64 = v72 + v137;
        let v156: f64 = v154 * v155;
        let v157: f64 = v153 + v156;
        let v158: f64 = params[38];
        let v159: f64 = v158 * v147;
        let v160: f64 = v157 + v159;
        let v161: f64 = v136 * v160;
        let v162: f64 = params[34];
        let v163: f64 = v162 * v136;
        let v164: f64 = v152 * v155;
        let v165: f64 = v163 + v164;
        let v166: f64 = v141 * v147;
        let v167: f64 = v165 + v166;
        let v168: f64 = v155 * v167;
        let v169: f64 = v161 - v168;
        let v170: f64 = v151 + v169;
        let v171: f64 = params[32];
        let v172: f64 = v48 * v98;
        let v173: f64 = v51 * v104;
        let v174: f64 = v172 - v173;
        let v175: f64 = v72 * v120;
        let v176: f64 = v107 * v69;
        let v177: f64 = v175 - v176;
        let v178: f64 = v174 + v177;
        let v179: f64 = 0.39225_f64;
        let v180: f64 = v179 * v67;
        let v181: f64 = v56 * v180;
        let v182: f64 = v178 - v181;
        let v183: f64 = v131 * v182;
        let v184: f64 = v67 * v180;
        let v185: f64 = v179 * v72;
        let v186: f64 = v72 * v185;
        let v187: f64 = v184 + v186;
        let v188: f64 = v112 - v187;
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
            v18,
            v20,
            v24,
            v28,
            v32,
            v33,
            v37,
            v39,
            v43,
            v46,
            v48,
            v49,
            v51,
            v56,
            v59,
            v61,
            v67,
            v69,
            v72,
            v74,
            v77,
            v79,
            v81,
            v87,
            v91,
            v94,
            v95,
            v107,
            v112,
            v114,
            v123,
            v126,
            v128,
            v129,
            v131,
            v136,
            v139,
            v141,
            v147,
            v149,
            v152,
            v155,
            v158,
            v160,
            v162,
            v167,
            v170,
            v171,
            v178,
            v179,
            v182,
            v183,
            v185,
            v188,
        )
    };
    let (
        v190,
        v192,
        v196,
        v200,
        v202,
        v204,
        v206,
        v210,
        v212,
        v216,
        v218,
        v221,
        v224,
        v226,
        v229,
        v231,
        v233,
        v238,
        v242,
        v243,
        v256,
        v258,
        v261,
        v266,
        v269,
        v274,
        v277,
        v279,
        v288,
        v290,
        v293,
        v295,
        v296,
        v307,
        v311,
        v312,
        v317,
        v319,
        v328,
        v332,
        v338,
        v341,
        v352,
        v359,
        v361,
        v364,
        v367,
        v368,
        v369,
        v370,
        v371,
        v374,
        v377,
    ) = {
        let v189: f64 = v128 * v188;
        let v190: f64 = v183 + v189;
        let v191: f64 = v171 * v190;
        let v192: f64 = params[31];
        let v193: f64 = v179 * v59;
        let v194: f64 = v56 * v185;
        let v195: f64 = v193 + v194;
        let v196: f64 = v123 + v195;
        let v197: f64 = v192 * v196;
        let v198: f64 = v191 - v197;
        let v199: f64 = v170 + v198;
        let v200: f64 = params[46];
        let v201: f64 = q[4];
        let (v204, v202): (f64, f64) = ::armdyn_runtime::libm::sincos(v201);
        let v203: f64 = v202 * v155;
        let v205: f64 = v204 * v136;
        let v206: f64 = v203 - v205;
        let v207: f64 = qd[4];
        let v208: f64 = v206 * v207;
        let v209: f64 = v202 * v149;
        let v210: f64 = v208 - v209;
        let v211: f64 = v200 * v210;
        let v212: f64 = params[48];
        let v213: f64 = v204 * v149;
        let v214: f64 = v202 * v136;
        let v215: f64 = v204 * v155;
        let v216: f64 = v214 + v215;
        let v217: f64 = v216 * v207;
        let v218: f64 = v213 - v217;
        let v219: f64 = v212 * v218;
        let v220: f64 = v211 + v219;
        let v221: f64 = params[49];
        let v222: f64 = v221 * v139;
        let v223: f64 = v220 + v222;
        let v224: f64 = params[45];
        let v225: f64 = v224 * v216;
        let v226: f64 = params[47];
        let v227: f64 = v226 * v206;
        let v228: f64 = v225 + v227;
        let v229: f64 = v147 + v207;
        let v230: f64 = v212 * v229;
        let v231: f64 = v228 + v230;
        let v232: f64 = v216 * v231;
        let v233: f64 = params[44];
        let v234: f64 = v233 * v216;
        let v235: f64 = v224 * v206;
        let v236: f64 = v234 + v235;
        let v237: f64 = v200 * v229;
        let v238: f64 = v236 + v237;
        let v239: f64 = v206 * v238;
        let v240: f64 = v232 - v239;
        let v241: f64 = v223 + v240;
        let v242: f64 = params[41];
        let v243: f64 = 0.093_f64;
        let v244: f64 = v243 * v136;
        let v245: f64 = v155 * v244;
        let v246: f64 = v243 * v139;
        let v247: f64 = v245 - v246;
        let v248: f64 = v247 - v190;
        let v249: f64 = v204 * v248;
        let v250: f64 = v243 * v147;
        let v251: f64 = v147 * v250;
        let v252: f64 = v136 * v244;
        let v253: f64 = v251 + v252;
        let v254: f64 = v196 + v253;
        let v255: f64 = v202 * v254;
        let v256: f64 = v249 + v255;
        let v257: f64 = v242 * v256;
        let v258: f64 = params[42];
        let v259: f64 = v202 * v248;
        let v260: f64 = v204 * v254;
        let v261: f64 = v259 - v260;
        let v262: f64 = v258 * v261;
        let v263: f64 = v257 + v262;
        let v264: f64 = v241 - v263;
        let v265: f64 = q[5];
        let (v269, v266): (f64, f64) = ::armdyn_runtime::libm::sincos(v265);
        let v267: f64 = params[56];
        let v268: f64 = v266 * v210;
        let v270: f64 = v269 * v139;
        let v271: f64 = v268 - v270;
        let v272: f64 = v269 * v216;
        let v273: f64 = v266 * v229;
        let v274: f64 = v272 + v273;
        let v275: f64 = qd[5];
        let v276: f64 = v274 * v275;
        let v277: f64 = v271 - v276;
        let v278: f64 = v267 * v277;
        let v279: f64 = params[58];
        let v280: f64 = v279 * v218;
        let v281: f64 = v278 + v280;
        let v282: f64 = params[59];
        let v283: f64 = v269 * v210;
        let v284: f64 = v266 * v139;
        let v285: f64 = v283 + v284;
        let v286: f64 = v266 * v216;
        let v287: f64 = v269 * v229;
        let v288: f64 = v286 - v287;
        let v289: f64 = v288 * v275;
        let v290: f64 = v285 + v289;
        let v291: f64 = v282 * v290;
        let v292: f64 = v281 + v291;
        let v293: f64 = params[55];
        let v294: f64 = v293 * v288;
        let v295: f64 = params[57];
        let v296: f64 = v206 + v275;
        let v297: f64 = v295 * v296;
        let v298: f64 = v294 + v297;
        let v299: f64 = v279 * v274;
        let v300: f64 = v298 + v299;
        let v301: f64 = v288 * v300;
        let v302: f64 = params[54];
        let v303: f64 = v302 * v288;
        let v304: f64 = v293 * v296;
        let v305: f64 = v303 + v304;
        let v306: f64 = v267 * v274;
        let v307: f64 = v305 + v306;
        let v308: f64 = v296 * v307;
        let v309: f64 = v301 - v308;
        let v310: f64 = v292 + v309;
        let v311: f64 = params[51];
        let v312: f64 = 0.09465_f64;
        let v313: f64 = v312 * v206;
        let v314: f64 = v229 * v313;
        let v315: f64 = v312 * v210;
        let v316: f64 = v314 - v315;
        let v317: f64 = v316 - v256;
        let v318: f64 = v311 * v317;
        let v319: f64 = params[52];
        let v320: f64 = v312 * v218;
        let v321: f64 = v312 * v216;
        let v322: f64 = v229 * v321;
        let v323: f64 = v320 + v322;
        let v324: f64 = v261 + v323;
        let v325: f64 = v266 * v324;
        let v326: f64 = v128 * v182;
        let v327: f64 = v131 * v188;
        let v328: f64 = v326 - v327;
        let v329: f64 = v155 * v250;
        let v330: f64 = v243 * v149;
        let v331: f64 = v329 - v330;
        let v332: f64 = v328 + v331;
        let v333: f64 = v216 * v321;
        let v334: f64 = v206 * v313;
        let v335: f64 = v333 + v334;
        let v336: f64 = v332 - v335;
        let v337: f64 = v269 * v336;
        let v338: f64 = v325 - v337;
        let v339: f64 = v319 * v338;
        let v340: f64 = v318 - v339;
        let v341: f64 = v310 + v340;
        let v342: f64 = v266 * v341;
        let v343: f64 = v302 * v277;
        let v344: f64 = v293 * v218;
        let v345: f64 = v343 + v344;
        let v346: f64 = v267 * v290;
        let v347: f64 = v345 + v346;
        let v348: f64 = v267 * v288;
        let v349: f64 = v279 * v296;
        let v350: f64 = v348 + v349;
        let v351: f64 = v282 * v274;
        let v352: f64 = v350 + v351;
        let v353: f64 = v296 * v352;
        let v354: f64 = v274 * v300;
        let v355: f64 = v353 - v354;
        let v356: f64 = v347 + v355;
        let v357: f64 = v269 * v324;
        let v358: f64 = v266 * v336;
        let v359: f64 = v357 + v358;
        let v360: f64 = v319 * v359;
        let v361: f64 = params[53];
        let v362: f64 = v361 * v317;
        let v363: f64 = v360 - v362;
        let v364: f64 = v356 + v363;
        let v365: f64 = v269 * v364;
        let v366: f64 = v342 - v365;
        let v367: f64 = v264 + v366;
        let v368: f64 = v199 + v367;
        let v369: f64 = params[40];
        let v370: f64 = v369 * v261;
        let v371: f64 = params[43];
        let v372: f64 = v218 * v371;
        let v373: f64 = v139 * v258;
        let v374: f64 = v372 - v373;
        let v375: f64 = v216 * v258;
        let v376: f64 = v206 * v242;
        let v377: f64 = v375 - v376;
        (
            v190,
            v192,
            v196,
            v200,
            v202,
            v204,
            v206,
            v210,
            v212,
            v216,
            v218,
            v221,
            v224,
            v226,
            v229,
            v231,
            v233,
            v238,
            v242,
            v243,
            v256,
            v258,
            v261,
            v266,
            v269,
            v274,
            v277,
            v279,
            v288,
            v290,
            v293,
            v295,
            v296,
            v307,
            v311,
            v312,
            v317,
            v319,
            v328,
            v332,
            v338,
            v341,
            v352,
            v359,
            v361,
            v364,
            v367,
            v368,
            v369,
            v370,
            v371,
            v374,
            v377,
        )
    };
    let (
        v442,
        v444,
        v453,
        v459,
        v486,
        v513,
        v516,
        v532,
        v534,
        v543,
        v547,
        v551,
        v557,
        v559,
        v560,
        v561,
        v562,
        v563,
        v566,
    ) = {
        let v378: f64 = v206 * v377;
        let v379: f64 = v229 * v242;
        let v380: f64 = v216 * v371;
        let v381: f64 = v379 - v380;
        let v382: f64 = v229 * v381;
        let v383: f64 = v378 - v382;
        let v384: f64 = v374 + v383;
        let v385: f64 = v370 + v384;
        let v386: f64 = params[50];
        let v387: f64 = v386 * v338;
        let v388: f64 = v218 * v361;
        let v389: f64 = v290 * v319;
        let v390: f64 = v388 - v389;
        let v391: f64 = v288 * v319;
        let v392: f64 = v296 * v311;
        let v393: f64 = v391 - v392;
        let v394: f64 = v296 * v393;
        let v395: f64 = v274 * v311;
        let v396: f64 = v288 * v361;
        let v397: f64 = v395 - v396;
        let v398: f64 = v274 * v397;
        let v399: f64 = v394 - v398;
        let v400: f64 = v390 + v399;
        let v401: f64 = v387 + v400;
        let v402: f64 = v266 * v401;
        let v403: f64 = v386 * v359;
        let v404: f64 = v277 * v319;
        let v405: f64 = v218 * v311;
        let v406: f64 = v404 - v405;
        let v407: f64 = v288 * v397;
        let v408: f64 = v296 * v361;
        let v409: f64 = v274 * v319;
        let v410: f64 = v408 - v409;
        let v411: f64 = v296 * v410;
        let v412: f64 = v407 - v411;
        let v413: f64 = v406 + v412;
        let v414: f64 = v403 + v413;
        let v415: f64 = v269 * v414;
        let v416: f64 = v402 + v415;
        let v417: f64 = v385 + v416;
        let v418: f64 = v202 * v417;
        let v419: f64 = v139 * v242;
        let v420: f64 = v210 * v371;
        let v421: f64 = v419 - v420;
        let v422: f64 = v206 * v371;
        let v423: f64 = v229 * v258;
        let v424: f64 = v422 - v423;
        let v425: f64 = v229 * v424;
        let v426: f64 = v216 * v377;
        let v427: f64 = v425 - v426;
        let v428: f64 = v421 + v427;
        let v429: f64 = v369 * v256;
        let v430: f64 = v428 - v429;
        let v431: f64 = v386 * v317;
        let v432: f64 = v290 * v311;
        let v433: f64 = v277 * v361;
        let v434: f64 = v432 - v433;
        let v435: f64 = v274 * v410;
        let v436: f64 = v288 * v393;
        let v437: f64 = v435 - v436;
        let v438: f64 = v434 + v437;
        let v439: f64 = v431 + v438;
        let v440: f64 = v430 + v439;
        let v441: f64 = v204 * v440;
        let v442: f64 = v418 - v441;
        let v443: f64 = v243 * v442;
        let v444: f64 = v368 - v443;
        let v445: f64 = v128 * v444;
        let v446: f64 = v141 * v139;
        let v447: f64 = v162 * v149;
        let v448: f64 = v446 - v447;
        let v449: f64 = v141 * v136;
        let v450: f64 = v158 * v155;
        let v451: f64 = v449 + v450;
        let v452: f64 = v129 * v147;
        let v453: f64 = v451 + v452;
        let v454: f64 = v155 * v453;
        let v455: f64 = v147 * v160;
        let v456: f64 = v454 - v455;
        let v457: f64 = v448 + v456;
        let v458: f64 = v171 * v328;
        let v459: f64 = params[33];
        let v460: f64 = v459 * v196;
        let v461: f64 = v458 + v460;
        let v462: f64 = v457 + v461;
        let v463: f64 = v233 * v210;
        let v464: f64 = v224 * v218;
        let v465: f64 = v463 + v464;
        let v466: f64 = v200 * v139;
        let v467: f64 = v465 + v466;
        let v468: f64 = v200 * v216;
        let v469: f64 = v212 * v206;
        let v470: f64 = v468 + v469;
        let v471: f64 = v221 * v229;
        let v472: f64 = v470 + v471;
        let v473: f64 = v206 * v472;
        let v474: f64 = v229 * v231;
        let v475: f64 = v473 - v474;
        let v476: f64 = v467 + v475;
        let v477: f64 = v258 * v332;
        let v478: f64 = v371 * v256;
        let v479: f64 = v477 + v478;
        let v480: f64 = v476 + v479;
        let v481: f64 = v266 * v364;
        let v482: f64 = v269 * v341;
        let v483: f64 = v481 + v482;
        let v484: f64 = v480 + v483;
        let v485: f64 = v312 * v439;
        let v486: f64 = v484 - v485;
        let v487: f64 = v202 * v486;
        let v488: f64 = v224 * v210;
        let v489: f64 = v226 * v218;
        let v490: f64 = v488 + v489;
        let v491: f64 = v212 * v139;
        let v492: f64 = v490 + v491;
        let v493: f64 = v229 * v238;
        let v494: f64 = v216 * v472;
        let v495: f64 = v493 - v494;
        let v496: f64 = v492 + v495;
        let v497: f64 = v371 * v261;
        let v498: f64 = v242 * v332;
        let v499: f64 = v497 - v498;
        let v500: f64 = v496 + v499;
        let v501: f64 = v293 * v277;
        let v502: f64 = v295 * v218;
        let v503: f64 = v501 + v502;
        let v504: f64 = v279 * v290;
        let v505: f64 = v503 + v504;
        let v506: f64 = v274 * v307;
        let v507: f64 = v288 * v352;
        let v508: f64 = v506 - v507;
        let v509: f64 = v505 + v508;
        let v510: f64 = v361 * v338;
        let v511: f64 = v311 * v359;
        let v512: f64 = v510 - v511;
        let v513: f64 = v509 + v512;
        let v514: f64 = v500 + v513;
        let v515: f64 = v312 * v416;
        let v516: f64 = v514 + v515;
        let v517: f64 = v204 * v516;
        let v518: f64 = v487 - v517;
        let v519: f64 = v462 + v518;
        let v520: f64 = v369 * v332;
        let v521: f64 = v210 * v258;
        let v522: f64 = v218 * v242;
        let v523: f64 = v521 - v522;
        let v524: f64 = v216 * v381;
        let v525: f64 = v206 * v424;
        let v526: f64 = v524 - v525;
        let v527: f64 = v523 + v526;
        let v528: f64 = v520 + v527;
        let v529: f64 = v266 * v414;
        let v530: f64 = v269 * v401;
        let v531: f64 = v529 - v530;
        let v532: f64 = v528 + v531;
        let v533: f64 = v243 * v532;
        let v534: f64 = v519 + v533;
        let v535: f64 = v131 * v534;
        let v536: f64 = v445 - v535;
        let v537: f64 = v126 + v536;
        let v538: f64 = v139 * v192;
        let v539: f64 = v149 * v459;
        let v540: f64 = v538 + v539;
        let v541: f64 = v155 * v459;
        let v542: f64 = v147 * v171;
        let v543: f64 = v541 - v542;
        let v544: f64 = v147 * v543;
        let v545: f64 = v136 * v171;
        let v546: f64 = v155 * v192;
        let v547: f64 = v545 - v546;
        let v548: f64 = v136 * v547;
        let v549: f64 = v544 - v548;
        let v550: f64 = v540 + v549;
        let v551: f64 = params[30];
        let v552: f64 = v551 * v196;
        let v553: f64 = v550 - v552;
        let v554: f64 = v204 * v417;
        let v555: f64 = v202 * v440;
        let v556: f64 = v554 + v555;
        let v557: f64 = v553 + v556;
        let v558: f64 = v179 * v557;
        let v559: f64 = v537 - v558;
        let v560: f64 = params[20];
        let v561: f64 = v560 * v112;
        let v562: f64 = v59 * v91;
        let v563: f64 = params[21];
        let v564: f64 = v56 * v563;
        let v565: f64 = v67 * v114;
        let v566: f64 = v564 + v565;
        (
            v442,
            v444,
            v453,
            v459,
            v486,
            v513,
            v516,
            v532,
            v534,
            v543,
            v547,
            v551,
            v557,
            v559,
            v560,
            v561,
            v562,
            v563,
            v566,
        )
    };
    let (v712, v749, v752, v755) = {
        let v567: f64 = v67 * v566;
        let v568: f64 = v72 * v114;
        let v569: f64 = v56 * v91;
        let v570: f64 = v568 + v569;
        let v571: f64 = v72 * v570;
        let v572: f64 = v567 + v571;
        let v573: f64 = v562 - v572;
        let v574: f64 = v561 + v573;
        let v575: f64 = v155 * v547;
        let v576: f64 = v147 * v192;
        let v577: f64 = v136 * v459;
        let v578: f64 = v576 - v577;
        let v579: f64 = v147 * v578;
        let v580: f64 = v575 - v579;
        let v581: f64 = v139 * v171;
        let v582: f64 = v580 - v581;
        let v583: f64 = v551 * v190;
        let v584: f64 = v582 - v583;
        let v585: f64 = v584 + v442;
        let v586: f64 = v128 * v585;
        let v587: f64 = v551 * v328;
        let v588: f64 = v136 * v578;
        let v589: f64 = v155 * v543;
        let v590: f64 = v588 - v589;
        let v591: f64 = v149 * v171;
        let v592: f64 = v590 - v591;
        let v593: f64 = v587 + v592;
        let v594: f64 = v593 + v532;
        let v595: f64 = v131 * v594;
        let v596: f64 = v586 + v595;
        let v597: f64 = v574 - v596;
        let v598: f64 = v107 * v597;
        let v599: f64 = v559 + v598;
        let v600: f64 = v48 * v599;
        let v601: f64 = v61 * v59;
        let v602: f64 = v77 * v69;
        let v603: f64 = v601 + v602;
        let v604: f64 = v67 * v87;
        let v605: f64 = v49 * v67;
        let v606: f64 = v81 * v72;
        let v607: f64 = v605 + v606;
        let v608: f64 = v61 * v56;
        let v609: f64 = v607 - v608;
        let v610: f64 = v72 * v609;
        let v611: f64 = v604 - v610;
        let v612: f64 = v603 + v611;
        let v613: f64 = v563 * v123;
        let v614: f64 = v91 * v178;
        let v615: f64 = v613 + v614;
        let v616: f64 = v612 - v615;
        let v617: f64 = v128 * v534;
        let v618: f64 = v131 * v444;
        let v619: f64 = v617 + v618;
        let v620: f64 = v616 - v619;
        let v621: f64 = v560 * v178;
        let v622: f64 = v67 * v91;
        let v623: f64 = v72 * v563;
        let v624: f64 = v622 - v623;
        let v625: f64 = v72 * v624;
        let v626: f64 = v56 * v566;
        let v627: f64 = v625 - v626;
        let v628: f64 = v69 * v91;
        let v629: f64 = v627 - v628;
        let v630: f64 = v621 + v629;
        let v631: f64 = v128 * v594;
        let v632: f64 = v131 * v585;
        let v633: f64 = v631 - v632;
        let v634: f64 = v630 + v633;
        let v635: f64 = v107 * v634;
        let v636: f64 = v620 - v635;
        let v637: f64 = v51 * v636;
        let v638: f64 = v600 + v637;
        let v639: f64 = v46 + v638;
        let v640: f64 = v69 * v563;
        let v641: f64 = v59 * v114;
        let v642: f64 = v640 - v641;
        let v643: f64 = v56 * v570;
        let v644: f64 = v67 * v624;
        let v645: f64 = v643 + v644;
        let v646: f64 = v642 - v645;
        let v647: f64 = v560 * v123;
        let v648: f64 = v646 - v647;
        let v649: f64 = v648 + v557;
        let v650: f64 = v95 * v649;
        let v651: f64 = v639 - v650;
        let v652: f64 = params[10];
        let v653: f64 = v652 * v37;
        let v654: f64 = v7 * v32;
        let v655: f64 = v10 * v39;
        let v656: f64 = params[11];
        let v657: f64 = v5 * v656;
        let v658: f64 = v655 - v657;
        let v659: f64 = v10 * v658;
        let v660: f64 = v6 * v39;
        let v661: f64 = v5 * v32;
        let v662: f64 = v660 + v661;
        let v663: f64 = v6 * v662;
        let v664: f64 = v659 + v663;
        let v665: f64 = v654 - v664;
        let v666: f64 = v653 + v665;
        let v667: f64 = v48 * v597;
        let v668: f64 = v51 * v634;
        let v669: f64 = v667 - v668;
        let v670: f64 = v666 + v669;
        let v671: f64 = v33 * v670;
        let v672: f64 = v651 + v671;
        let v673: f64 = v1 * v672;
        let v674: f64 = v9 * v7;
        let v675: f64 = v18 * v11;
        let v676: f64 = v674 - v675;
        let v677: f64 = v10 * v28;
        let v678: f64 = v24 * v6;
        let v679: f64 = v2 * v10;
        let v680: f64 = v678 - v679;
        let v681: f64 = v9 * v5;
        let v682: f64 = v680 - v681;
        let v683: f64 = v6 * v682;
        let v684: f64 = v677 + v683;
        let v685: f64 = v676 - v684;
        let v686: f64 = v656 * v43;
        let v687: f64 = v32 * v94;
        let v688: f64 = v686 + v687;
        let v689: f64 = v685 - v688;
        let v690: f64 = v48 * v636;
        let v691: f64 = v51 * v599;
        let v692: f64 = v690 - v691;
        let v693: f64 = v689 + v692;
        let v694: f64 = v652 * v94;
        let v695: f64 = v11 * v32;
        let v696: f64 = v5 * v658;
        let v697: f64 = v10 * v32;
        let v698: f64 = v6 * v656;
        let v699: f64 = v697 + v698;
        let v700: f64 = v6 * v699;
        let v701: f64 = v696 - v700;
        let v702: f64 = v695 + v701;
        let v703: f64 = v694 + v702;
        let v704: f64 = v48 * v634;
        let v705: f64 = v51 * v597;
        let v706: f64 = v704 + v705;
        let v707: f64 = v703 + v706;
        let v708: f64 = v33 * v707;
        let v709: f64 = v693 - v708;
        let v710: f64 = v3 * v709;
        let v711: f64 = v673 + v710;
        let v712: f64 = -v711;
        let v713: f64 = v24 * v7;
        let v714: f64 = v14 * v11;
        let v715: f64 = v713 - v714;
        let v716: f64 = v10 * v20;
        let v717: f64 = v5 * v682;
        let v718: f64 = v716 - v717;
        let v719: f64 = v715 + v718;
        let v720: f64 = v39 * v94;
        let v721: f64 = v656 * v37;
        let v722: f64 = v720 - v721;
        let v723: f64 = v719 + v722;
        let v724: f64 = v81 * v59;
        let v725: f64 = v74 * v69;
        let v726: f64 = v724 + v725;
        let v727: f64 = v56 * v609;
        let v728: f64 = v67 * v79;
        let v729: f64 = v727 + v728;
        let v730: f64 = v726 - v729;
        let v731: f64 = v114 * v178;
        let v732: f64 = v563 * v112;
        let v733: f64 = v731 - v732;
        let v734: f64 = v730 + v733;
        let v735: f64 = v158 * v139;
        let v736: f64 = v152 * v149;
        let v737: f64 = v735 - v736;
        let v738: f64 = v147 * v167;
        let v739: f64 = v136 * v453;
        let v740: f64 = v738 - v739;
        let v741: f64 = v737 + v740;
        let v742: f64 = v459 * v190;
        let v743: f64 = v192 * v328;
        let v744: f64 = v742 + v743;
        let v745: f64 = v741 - v744;
        let v746: f64 = v204 * v486;
        let v747: f64 = v202 * v516;
        let v748: f64 = v746 + v747;
        let v749: f64 = v745 + v748;
        let v750: f64 = v734 + v749;
        let v751: f64 = v179 * v633;
        let v752: f64 = v750 + v751;
        let v753: f64 = v723 + v752;
        let v754: f64 = v95 * v706;
        let v755: f64 = v753 + v754;
        (v712, v749, v752, v755)
    };
    [v712, v755, v752, v749, v367, v513]
}
/// Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68).
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `params: &[f64; 60]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `gravity: [f64; 6]`: g(q), joint torques (N m) or forces (N) that hold the robot still
///
/// Operation count: 132 floating-point operations, 10 trig calls.
#[inline]
#[must_use]
#[allow(
    unused_variables,
    non_snake_case,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
pub fn gravity(q: &[f64; 6], params: &[f64; 60]) -> [f64; 6] {
    let v0: f64 = 0.0_f64;
    let v1: f64 = 9.81_f64;
    let v2: f64 = params[11];
    let v3: f64 = v1 * v2;
    let v4: f64 = params[21];
    let v5: f64 = v1 * v4;
    let v6: f64 = 0.9285165_f64;
    let v7: f64 = params[50];
    let v8: f64 = v6 * v7;
    let v9: f64 = params[43];
    let v10: f64 = v1 * v9;
    let v11: f64 = v8 + v10;
    let v12: f64 = params[33];
    let v13: f64 = v1 * v12;
    let v14: f64 = v11 + v13;
    let v15: f64 = params[53];
    let v16: f64 = v1 * v15;
    let v17: f64 = q[5];
    let (v23, v18): (f64, f64) = ::armdyn_runtime::libm::sincos(v17);
    let v19: f64 = v16 * v18;
    let v20: f64 = v14 + v19;
    let v21: f64 = params[51];
    let v22: f64 = v1 * v21;
    let v24: f64 = v22 * v23;
    let v25: f64 = v20 - v24;
    let v26: f64 = q[3];
    let (v50, v27): (f64, f64) = ::armdyn_runtime::libm::sincos(v26);
    let v28: f64 = v25 * v27;
    let v29: f64 = v5 + v28;
    let v30: f64 = params[52];
    let v31: f64 = v1 * v30;
    let v32: f64 = params[42];
    let v33: f64 = v1 * v32;
    let v34: f64 = v31 + v33;
    let v35: f64 = q[4];
    let (v36, v47): (f64, f64) = ::armdyn_runtime::libm::sincos(v35);
    let v37: f64 = v34 * v36;
    let v38: f64 = params[31];
    let v39: f64 = v1 * v38;
    let v40: f64 = v37 - v39;
    let v41: f64 = params[41];
    let v42: f64 = v1 * v41;
    let v43: f64 = v22 * v18;
    let v44: f64 = v42 + v43;
    let v45: f64 = v16 * v23;
    let v46: f64 = v44 + v45;
    let v48: f64 = v46 * v47;
    let v49: f64 = v40 - v48;
    let v51: f64 = v49 * v50;
    let v52: f64 = v29 + v51;
    let v53: f64 = q[2];
    let (v73, v54): (f64, f64) = ::armdyn_runtime::libm::sincos(v53);
    let v55: f64 = v52 * v54;
    let v56: f64 = v3 + v55;
    let v57: f64 = 3.8479725_f64;
    let v58: f64 = v57 * v7;
    let v59: f64 = params[40];
    let v60: f64 = v57 * v59;
    let v61: f64 = v58 + v60;
    let v62: f64 = params[30];
    let v63: f64 = v57 * v62;
    let v64: f64 = v61 + v63;
    let v65: f64 = params[23];
    let v66: f64 = v1 * v65;
    let v67: f64 = v64 + v66;
    let v68: f64 = v24 - v20;
    let v69: f64 = v68 * v50;
    let v70: f64 = v67 + v69;
    let v71: f64 = v49 * v27;
    let v72: f64 = v70 + v71;
    let v74: f64 = v72 * v73;
    let v75: f64 = v56 + v74;
    let v76: f64 = q[1];
    let (v77, v101): (f64, f64) = ::armdyn_runtime::libm::sincos(v76);
    let v78: f64 = v75 * v77;
    let v79: f64 = v52 * v73;
    let v80: f64 = 4.16925_f64;
    let v81: f64 = v80 * v7;
    let v82: f64 = v80 * v59;
    let v83: f64 = v81 + v82;
    let v84: f64 = v80 * v62;
    let v85: f64 = v83 + v84;
    let v86: f64 = params[20];
    let v87: f64 = v80 * v86;
    let v88: f64 = v85 + v87;
    let v89: f64 = params[13];
    let v90: f64 = v1 * v89;
    let v91: f64 = v88 + v90;
    let v92: f64 = v79 - v91;
    let v93: f64 = v25 * v50;
    let v94: f64 = v93 - v67;
    let v95: f64 = v39 - v37;
    let v96: f64 = v95 + v48;
    let v97: f64 = v96 * v27;
    let v98: f64 = v94 + v97;
    let v99: f64 = v98 * v54;
    let v100: f64 = v92 + v99;
    let v102: f64 = v100 * v101;
    let v103: f64 = v78 + v102;
    let v104: f64 = v79 + v99;
    let v105: f64 = v104 * v101;
    let v106: f64 = v55 + v74;
    let v107: f64 = v106 * v77;
    let v108: f64 = v105 + v107;
    let v109: f64 = v93 + v97;
    let v110: f64 = v109 * v54;
    let v111: f64 = v28 + v51;
    let v112: f64 = v111 * v73;
    let v113: f64 = v110 + v112;
    let v114: f64 = v113 * v101;
    let v115: f64 = v111 * v54;
    let v116: f64 = v69 + v71;
    let v117: f64 = v116 * v73;
    let v118: f64 = v115 + v117;
    let v119: f64 = v118 * v77;
    let v120: f64 = v114 + v119;
    let v121: f64 = v34 * v50;
    let v122: f64 = v121 * v73;
    let v123: f64 = v34 * v27;
    let v124: f64 = v123 * v54;
    let v125: f64 = v122 - v124;
    let v126: f64 = v125 * v77;
    let v127: f64 = v121 * v54;
    let v128: f64 = v123 * v73;
    let v129: f64 = v127 + v128;
    let v130: f64 = v129 * v101;
    let v131: f64 = v126 - v130;
    let v132: f64 = v131 * v47;
    let v133: f64 = v46 * v50;
    let v134: f64 = v133 * v73;
    let v135: f64 = v46 * v27;
    let v136: f64 = v135 * v54;
    let v137: f64 = v134 - v136;
    let v138: f64 = v137 * v77;
    let v139: f64 = v133 * v54;
    let v140: f64 = v135 * v73;
    let v141: f64 = v139 + v140;
    let v142: f64 = v141 * v101;
    let v143: f64 = v138 - v142;
    let v144: f64 = v143 * v36;
    let v145: f64 = v132 + v144;
    let v146: f64 = v43 + v45;
    let v147: f64 = v146 * v27;
    let v148: f64 = v19 - v24;
    let v149: f64 = v148 * v47;
    let v150: f64 = v149 * v50;
    let v151: f64 = v147 + v150;
    let v152: f64 = v151 * v54;
    let v153: f64 = v149 * v27;
    let v154: f64 = v146 * v50;
    let v155: f64 = v153 - v154;
    let v156: f64 = v155 * v73;
    let v157: f64 = v152 + v156;
    let v158: f64 = v157 * v101;
    let v159: f64 = v155 * v54;
    let v160: f64 = v24 - v19;
    let v161: f64 = v160 * v47;
    let v162: f64 = v161 * v50;
    let v163: f64 = v162 - v147;
    let v164: f64 = v163 * v73;
    let v165: f64 = v159 + v164;
    let v166: f64 = v165 * v77;
    let v167: f64 = v158 + v166;
    [v0, v103, v108, v120, v145, v167]
}
/// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler).
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 6]`: joint velocities qd (rad/s or m/s)
/// - `qdd: &[f64; 6]`: joint accelerations qdd (rad/s^2 or m/s^2)
/// - `params: &[f64; 60]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `tau: [f64; 6]`: joint torques (N m) or forces (N), no external wrench
///
/// Operation count: 730 floating-point operations, 10 trig calls.
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
    q: &[f64; 6],
    qd: &[f64; 6],
    qdd: &[f64; 6],
    params: &[f64; 60],
) -> [f64; 6] {
    let (
        v2,
        v4,
        v5,
        v6,
        v8,
        v9,
        v12,
        v14,
        v15,
        v18,
        v20,
        v22,
        v25,
        v29,
        v31,
        v33,
        v38,
        v42,
        v43,
        v50,
        v52,
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
        v113,
        v114,
        v119,
        v125,
        v128,
        v133,
        v135,
        v141,
        v144,
        v147,
        v149,
        v150,
        v152,
        v153,
        v154,
        v155,
        v158,
        v161,
        v162,
    ) = {
        let v0: f64 = params[9];
        let v1: f64 = qdd[0];
        let v2: f64 = v0 * v1;
        let v3: f64 = q[1];
        let (v6, v4): (f64, f64) = ::armdyn_runtime::libm::sincos(v3);
        let v5: f64 = params[14];
        let v7: f64 = qd[0];
        let v8: f64 = v6 * v7;
        let v9: f64 = qd[1];
        let v10: f64 = v8 * v9;
        let v11: f64 = v4 * v1;
        let v12: f64 = v10 - v11;
        let v13: f64 = v5 * v12;
        let v14: f64 = params[15];
        let v15: f64 = qdd[1];
        let v16: f64 = v14 * v15;
        let v17: f64 = v13 + v16;
        let v18: f64 = params[16];
        let v19: f64 = v6 * v1;
        let v20: f64 = v4 * v7;
        let v21: f64 = v20 * v9;
        let v22: f64 = v19 + v21;
        let v23: f64 = v18 * v22;
        let v24: f64 = v17 - v23;
        let v25: f64 = params[18];
        let v26: f64 = v25 * v9;
        let v27: f64 = v18 * v20;
        let v28: f64 = v26 - v27;
        let v29: f64 = params[19];
        let v30: f64 = v29 * v8;
        let v31: f64 = v28 - v30;
        let v32: f64 = v9 * v31;
        let v33: f64 = params[17];
        let v34: f64 = v33 * v9;
        let v35: f64 = v14 * v20;
        let v36: f64 = v34 - v35;
        let v37: f64 = v25 * v8;
        let v38: f64 = v36 - v37;
        let v39: f64 = v8 * v38;
        let v40: f64 = v32 + v39;
        let v41: f64 = v24 + v40;
        let v42: f64 = params[12];
        let v43: f64 = 0.13585_f64;
        let v44: f64 = v43 * v12;
        let v45: f64 = v43 * v8;
        let v46: f64 = v9 * v45;
        let v47: f64 = v44 - v46;
        let v48: f64 = 9.81_f64;
        let v49: f64 = v48 * v6;
        let v50: f64 = v47 - v49;
        let v51: f64 = v42 * v50;
        let v52: f64 = params[13];
        let v53: f64 = v8 * v45;
        let v54: f64 = v43 * v20;
        let v55: f64 = v20 * v54;
        let v56: f64 = v53 + v55;
        let v57: f64 = v52 * v56;
        let v58: f64 = v51 + v57;
        let v59: f64 = v41 + v58;
        let v60: f64 = q[2];
        let (v64, v61): (f64, f64) = ::armdyn_runtime::libm::sincos(v60);
        let v62: f64 = params[24];
        let v63: f64 = v61 * v12;
        let v65: f64 = v64 * v22;
        let v66: f64 = v63 + v65;
        let v67: f64 = v64 * v20;
        let v68: f64 = v61 * v8;
        let v69: f64 = v67 + v68;
        let v70: f64 = qd[2];
        let v71: f64 = v69 * v70;
        let v72: f64 = v66 + v71;
        let v73: f64 = v62 * v72;
        let v74: f64 = params[25];
        let v75: f64 = qdd[2];
        let v76: f64 = v15 + v75;
        let v77: f64 = v74 * v76;
        let v78: f64 = v73 + v77;
        let v79: f64 = params[26];
        let v80: f64 = v64 * v12;
        let v81: f64 = v61 * v22;
        let v82: f64 = v80 - v81;
        let v83: f64 = v64 * v8;
        let v84: f64 = v61 * v20;
        let v85: f64 = v83 - v84;
        let v86: f64 = v85 * v70;
        let v87: f64 = v82 + v86;
        let v88: f64 = v79 * v87;
        let v89: f64 = v78 + v88;
        let v90: f64 = v9 + v70;
        let v91: f64 = v79 * v85;
        let v92: f64 = params[28];
        let v93: f64 = v92 * v90;
        let v94: f64 = v91 + v93;
        let v95: f64 = params[29];
        let v96: f64 = v95 * v69;
        let v97: f64 = v94 - v96;
        let v98: f64 = v90 * v97;
        let v99: f64 = v74 * v85;
        let v100: f64 = params[27];
        let v101: f64 = v100 * v90;
        let v102: f64 = v99 + v101;
        let v103: f64 = v92 * v69;
        let v104: f64 = v102 - v103;
        let v105: f64 = v69 * v104;
        let v106: f64 = v98 + v105;
        let v107: f64 = v89 + v106;
        let v108: f64 = params[22];
        let v109: f64 = v43 * v22;
        let v110: f64 = v9 * v54;
        let v111: f64 = v109 - v110;
        let v112: f64 = v48 * v4;
        let v113: f64 = v111 - v112;
        let v114: f64 = 0.425_f64;
        let v115: f64 = v114 * v15;
        let v116: f64 = v114 * v20;
        let v117: f64 = v8 * v116;
        let v118: f64 = v115 + v117;
        let v119: f64 = v113 + v118;
        let v120: f64 = v64 * v119;
        let v121: f64 = v20 * v116;
        let v122: f64 = v114 * v9;
        let v123: f64 = v9 * v122;
        let v124: f64 = v121 + v123;
        let v125: f64 = v50 - v124;
        let v126: f64 = v61 * v125;
        let v127: f64 = v120 + v126;
        let v128: f64 = -0.1197_f64;
        let v129: f64 = v128 * v72;
        let v130: f64 = v128 * v69;
        let v131: f64 = v90 * v130;
        let v132: f64 = v129 - v131;
        let v133: f64 = v127 + v132;
        let v134: f64 = v108 * v133;
        let v135: f64 = params[23];
        let v136: f64 = v114 * v12;
        let v137: f64 = v8 * v122;
        let v138: f64 = v136 + v137;
        let v139: f64 = v56 + v138;
        let v140: f64 = v69 * v130;
        let v141: f64 = v128 * v85;
        let v142: f64 = v85 * v141;
        let v143: f64 = v140 + v142;
        let v144: f64 = v139 + v143;
        let v145: f64 = v135 * v144;
        let v146: f64 = v134 + v145;
        let v147: f64 = v107 + v146;
        let v148: f64 = q[3];
        let (v155, v149): (f64, f64) = ::armdyn_runtime::libm::sincos(v148);
        let v150: f64 = params[38];
        let v151: f64 = qdd[3];
        let v152: f64 = v76 + v151;
        let v153: f64 = v150 * v152;
        let v154: f64 = params[36];
        let v156: f64 = v155 * v72;
        let v157: f64 = v149 * v87;
        let v158: f64 = v156 + v157;
        let v159: f64 = v149 * v85;
        let v160: f64 = v155 * v69;
        let v161: f64 = v159 + v160;
        let v162: f64 = qd[3];
        (
            v2,
            v4,
            v5,
            v6,
            v8,
            v9,
            v12,
            v14,
            v15,
            v18,
            v20,
            v22,
            v25,
            v29,
            v31,
            v33,
            v38,
            v42,
            v43,
            v50,
            v52,
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
            v113,
            v114,
            v119,
            v125,
            v128,
            v133,
            v135,
            v141,
            v144,
            v147,
            v149,
            v150,
            v152,
            v153,
            v154,
            v155,
            v158,
            v161,
            v162,
        )
    };
    let (
        v164,
        v167,
        v173,
        v175,
        v178,
        v180,
        v181,
        v185,
        v187,
        v192,
        v196,
        v203,
        v204,
        v209,
        v215,
        v217,
        v219,
        v223,
        v226,
        v227,
        v229,
        v231,
        v236,
        v239,
        v241,
        v247,
        v249,
        v252,
        v254,
        v257,
        v259,
        v262,
        v264,
        v266,
        v271,
        v275,
        v276,
        v283,
        v289,
        v291,
        v294,
        v297,
        v299,
        v300,
        v302,
        v307,
        v308,
        v310,
        v312,
        v314,
        v316,
        v317,
        v323,
        v325,
    ) = {
        let v163: f64 = v161 * v162;
        let v164: f64 = v158 + v163;
        let v165: f64 = v154 * v164;
        let v166: f64 = v153 - v165;
        let v167: f64 = params[39];
        let v168: f64 = v149 * v72;
        let v169: f64 = v155 * v87;
        let v170: f64 = v168 - v169;
        let v171: f64 = v149 * v69;
        let v172: f64 = v155 * v85;
        let v173: f64 = v171 - v172;
        let v174: f64 = v173 * v162;
        let v175: f64 = v170 + v174;
        let v176: f64 = v167 * v175;
        let v177: f64 = v166 + v176;
        let v178: f64 = params[35];
        let v179: f64 = v178 * v173;
        let v180: f64 = params[37];
        let v181: f64 = v90 + v162;
        let v182: f64 = v180 * v181;
        let v183: f64 = v179 + v182;
        let v184: f64 = v150 * v161;
        let v185: f64 = v183 + v184;
        let v186: f64 = v173 * v185;
        let v187: f64 = params[34];
        let v188: f64 = v187 * v173;
        let v189: f64 = v178 * v181;
        let v190: f64 = v188 + v189;
        let v191: f64 = v154 * v161;
        let v192: f64 = v190 + v191;
        let v193: f64 = v181 * v192;
        let v194: f64 = v186 - v193;
        let v195: f64 = v177 + v194;
        let v196: f64 = params[32];
        let v197: f64 = v61 * v119;
        let v198: f64 = v64 * v125;
        let v199: f64 = v197 - v198;
        let v200: f64 = v90 * v141;
        let v201: f64 = v128 * v87;
        let v202: f64 = v200 - v201;
        let v203: f64 = v199 + v202;
        let v204: f64 = 0.39225_f64;
        let v205: f64 = v204 * v76;
        let v206: f64 = v204 * v85;
        let v207: f64 = v69 * v206;
        let v208: f64 = v205 - v207;
        let v209: f64 = v203 + v208;
        let v210: f64 = v155 * v209;
        let v211: f64 = v85 * v206;
        let v212: f64 = v204 * v90;
        let v213: f64 = v90 * v212;
        let v214: f64 = v211 + v213;
        let v215: f64 = v133 - v214;
        let v216: f64 = v149 * v215;
        let v217: f64 = v210 + v216;
        let v218: f64 = v196 * v217;
        let v219: f64 = params[31];
        let v220: f64 = v204 * v72;
        let v221: f64 = v69 * v212;
        let v222: f64 = v220 + v221;
        let v223: f64 = v144 + v222;
        let v224: f64 = v219 * v223;
        let v225: f64 = v218 - v224;
        let v226: f64 = v195 + v225;
        let v227: f64 = params[46];
        let v228: f64 = q[4];
        let (v229, v231): (f64, f64) = ::armdyn_runtime::libm::sincos(v228);
        let v230: f64 = v229 * v152;
        let v232: f64 = v231 * v164;
        let v233: f64 = v230 - v232;
        let v234: f64 = v231 * v181;
        let v235: f64 = v229 * v173;
        let v236: f64 = v234 - v235;
        let v237: f64 = qd[4];
        let v238: f64 = v236 * v237;
        let v239: f64 = v233 + v238;
        let v240: f64 = v227 * v239;
        let v241: f64 = params[48];
        let v242: f64 = v229 * v164;
        let v243: f64 = v231 * v152;
        let v244: f64 = v242 + v243;
        let v245: f64 = v231 * v173;
        let v246: f64 = v229 * v181;
        let v247: f64 = v245 + v246;
        let v248: f64 = v247 * v237;
        let v249: f64 = v244 - v248;
        let v250: f64 = v241 * v249;
        let v251: f64 = v240 + v250;
        let v252: f64 = params[49];
        let v253: f64 = qdd[4];
        let v254: f64 = v175 + v253;
        let v255: f64 = v252 * v254;
        let v256: f64 = v251 + v255;
        let v257: f64 = params[45];
        let v258: f64 = v257 * v247;
        let v259: f64 = params[47];
        let v260: f64 = v259 * v236;
        let v261: f64 = v258 + v260;
        let v262: f64 = v161 + v237;
        let v263: f64 = v241 * v262;
        let v264: f64 = v261 + v263;
        let v265: f64 = v247 * v264;
        let v266: f64 = params[44];
        let v267: f64 = v266 * v247;
        let v268: f64 = v257 * v236;
        let v269: f64 = v267 + v268;
        let v270: f64 = v227 * v262;
        let v271: f64 = v269 + v270;
        let v272: f64 = v236 * v271;
        let v273: f64 = v265 - v272;
        let v274: f64 = v256 + v273;
        let v275: f64 = params[41];
        let v276: f64 = 0.093_f64;
        let v277: f64 = v276 * v173;
        let v278: f64 = v181 * v277;
        let v279: f64 = v276 * v175;
        let v280: f64 = v278 - v279;
        let v281: f64 = v280 - v217;
        let v282: f64 = v229 * v281;
        let v283: f64 = v276 * v161;
        let v284: f64 = v161 * v283;
        let v285: f64 = v173 * v277;
        let v286: f64 = v284 + v285;
        let v287: f64 = v223 + v286;
        let v288: f64 = v231 * v287;
        let v289: f64 = v282 + v288;
        let v290: f64 = v275 * v289;
        let v291: f64 = params[42];
        let v292: f64 = v231 * v281;
        let v293: f64 = v229 * v287;
        let v294: f64 = v292 - v293;
        let v295: f64 = v291 * v294;
        let v296: f64 = v290 + v295;
        let v297: f64 = v274 - v296;
        let v298: f64 = q[5];
        let (v302, v299): (f64, f64) = ::armdyn_runtime::libm::sincos(v298);
        let v300: f64 = params[56];
        let v301: f64 = v299 * v239;
        let v303: f64 = v302 * v254;
        let v304: f64 = v301 - v303;
        let v305: f64 = v302 * v247;
        let v306: f64 = v299 * v262;
        let v307: f64 = v305 + v306;
        let v308: f64 = qd[5];
        let v309: f64 = v307 * v308;
        let v310: f64 = v304 - v309;
        let v311: f64 = v300 * v310;
        let v312: f64 = params[58];
        let v313: f64 = qdd[5];
        let v314: f64 = v249 + v313;
        let v315: f64 = v312 * v314;
        let v316: f64 = v311 + v315;
        let v317: f64 = params[59];
        let v318: f64 = v302 * v239;
        let v319: f64 = v299 * v254;
        let v320: f64 = v318 + v319;
        let v321: f64 = v299 * v247;
        let v322: f64 = v302 * v262;
        let v323: f64 = v321 - v322;
        let v324: f64 = v323 * v308;
        let v325: f64 = v320 + v324;
        (
            v164,
            v167,
            v173,
            v175,
            v178,
            v180,
            v181,
            v185,
            v187,
            v192,
            v196,
            v203,
            v204,
            v209,
            v215,
            v217,
            v219,
            v223,
            v226,
            v227,
            v229,
            v231,
            v236,
            v239,
            v241,
            v247,
            v249,
            v252,
            v254,
            v257,
            v259,
            v262,
            v264,
            v266,
            v271,
            v275,
            v276,
            v283,
            v289,
            v291,
            v294,
            v297,
            v299,
            v300,
            v302,
            v307,
            v308,
            v310,
            v312,
            v314,
            v316,
            v317,
            v323,
            v325,
        )
    };
    let (
        v328,
        v330,
        v342,
        v346,
        v347,
        v363,
        v367,
        v373,
        v376,
        v387,
        v394,
        v396,
        v399,
        v402,
        v404,
        v406,
        v416,
        v436,
        v449,
        v451,
        v452,
        v459,
        v474,
        v475,
        v477,
        v479,
        v480,
        v485,
        v488,
    ) = {
        let v326: f64 = v317 * v325;
        let v327: f64 = v316 + v326;
        let v328: f64 = params[55];
        let v329: f64 = v328 * v323;
        let v330: f64 = params[57];
        let v331: f64 = v236 + v308;
        let v332: f64 = v330 * v331;
        let v333: f64 = v329 + v332;
        let v334: f64 = v312 * v307;
        let v335: f64 = v333 + v334;
        let v336: f64 = v323 * v335;
        let v337: f64 = params[54];
        let v338: f64 = v337 * v323;
        let v339: f64 = v328 * v331;
        let v340: f64 = v338 + v339;
        let v341: f64 = v300 * v307;
        let v342: f64 = v340 + v341;
        let v343: f64 = v331 * v342;
        let v344: f64 = v336 - v343;
        let v345: f64 = v327 + v344;
        let v346: f64 = params[51];
        let v347: f64 = 0.09465_f64;
        let v348: f64 = v347 * v236;
        let v349: f64 = v262 * v348;
        let v350: f64 = v347 * v239;
        let v351: f64 = v349 - v350;
        let v352: f64 = v351 - v289;
        let v353: f64 = v346 * v352;
        let v354: f64 = params[52];
        let v355: f64 = v347 * v249;
        let v356: f64 = v347 * v247;
        let v357: f64 = v262 * v356;
        let v358: f64 = v355 + v357;
        let v359: f64 = v294 + v358;
        let v360: f64 = v299 * v359;
        let v361: f64 = v149 * v209;
        let v362: f64 = v155 * v215;
        let v363: f64 = v361 - v362;
        let v364: f64 = v181 * v283;
        let v365: f64 = v276 * v164;
        let v366: f64 = v364 - v365;
        let v367: f64 = v363 + v366;
        let v368: f64 = v247 * v356;
        let v369: f64 = v236 * v348;
        let v370: f64 = v368 + v369;
        let v371: f64 = v367 - v370;
        let v372: f64 = v302 * v371;
        let v373: f64 = v360 - v372;
        let v374: f64 = v354 * v373;
        let v375: f64 = v353 - v374;
        let v376: f64 = v345 + v375;
        let v377: f64 = v299 * v376;
        let v378: f64 = v337 * v310;
        let v379: f64 = v328 * v314;
        let v380: f64 = v378 + v379;
        let v381: f64 = v300 * v325;
        let v382: f64 = v380 + v381;
        let v383: f64 = v300 * v323;
        let v384: f64 = v312 * v331;
        let v385: f64 = v383 + v384;
        let v386: f64 = v317 * v307;
        let v387: f64 = v385 + v386;
        let v388: f64 = v331 * v387;
        let v389: f64 = v307 * v335;
        let v390: f64 = v388 - v389;
        let v391: f64 = v382 + v390;
        let v392: f64 = v302 * v359;
        let v393: f64 = v299 * v371;
        let v394: f64 = v392 + v393;
        let v395: f64 = v354 * v394;
        let v396: f64 = params[53];
        let v397: f64 = v396 * v352;
        let v398: f64 = v395 - v397;
        let v399: f64 = v391 + v398;
        let v400: f64 = v302 * v399;
        let v401: f64 = v377 - v400;
        let v402: f64 = v297 + v401;
        let v403: f64 = v226 + v402;
        let v404: f64 = params[40];
        let v405: f64 = v404 * v294;
        let v406: f64 = params[43];
        let v407: f64 = v249 * v406;
        let v408: f64 = v254 * v291;
        let v409: f64 = v407 - v408;
        let v410: f64 = v247 * v291;
        let v411: f64 = v236 * v275;
        let v412: f64 = v410 - v411;
        let v413: f64 = v236 * v412;
        let v414: f64 = v262 * v275;
        let v415: f64 = v247 * v406;
        let v416: f64 = v414 - v415;
        let v417: f64 = v262 * v416;
        let v418: f64 = v413 - v417;
        let v419: f64 = v409 + v418;
        let v420: f64 = v405 + v419;
        let v421: f64 = params[50];
        let v422: f64 = v421 * v373;
        let v423: f64 = v314 * v396;
        let v424: f64 = v325 * v354;
        let v425: f64 = v423 - v424;
        let v426: f64 = v323 * v354;
        let v427: f64 = v331 * v346;
        let v428: f64 = v426 - v427;
        let v429: f64 = v331 * v428;
        let v430: f64 = v307 * v346;
        let v431: f64 = v323 * v396;
        let v432: f64 = v430 - v431;
        let v433: f64 = v307 * v432;
        let v434: f64 = v429 - v433;
        let v435: f64 = v425 + v434;
        let v436: f64 = v422 + v435;
        let v437: f64 = v299 * v436;
        let v438: f64 = v421 * v394;
        let v439: f64 = v310 * v354;
        let v440: f64 = v314 * v346;
        let v441: f64 = v439 - v440;
        let v442: f64 = v323 * v432;
        let v443: f64 = v331 * v396;
        let v444: f64 = v307 * v354;
        let v445: f64 = v443 - v444;
        let v446: f64 = v331 * v445;
        let v447: f64 = v442 - v446;
        let v448: f64 = v441 + v447;
        let v449: f64 = v438 + v448;
        let v450: f64 = v302 * v449;
        let v451: f64 = v437 + v450;
        let v452: f64 = v420 + v451;
        let v453: f64 = v231 * v452;
        let v454: f64 = v254 * v275;
        let v455: f64 = v239 * v406;
        let v456: f64 = v454 - v455;
        let v457: f64 = v236 * v406;
        let v458: f64 = v262 * v291;
        let v459: f64 = v457 - v458;
        let v460: f64 = v262 * v459;
        let v461: f64 = v247 * v412;
        let v462: f64 = v460 - v461;
        let v463: f64 = v456 + v462;
        let v464: f64 = v404 * v289;
        let v465: f64 = v463 - v464;
        let v466: f64 = v421 * v352;
        let v467: f64 = v325 * v346;
        let v468: f64 = v310 * v396;
        let v469: f64 = v467 - v468;
        let v470: f64 = v307 * v445;
        let v471: f64 = v323 * v428;
        let v472: f64 = v470 - v471;
        let v473: f64 = v469 + v472;
        let v474: f64 = v466 + v473;
        let v475: f64 = v465 + v474;
        let v476: f64 = v229 * v475;
        let v477: f64 = v453 - v476;
        let v478: f64 = v276 * v477;
        let v479: f64 = v403 - v478;
        let v480: f64 = v149 * v479;
        let v481: f64 = v178 * v152;
        let v482: f64 = v187 * v164;
        let v483: f64 = v481 - v482;
        let v484: f64 = v154 * v175;
        let v485: f64 = v483 + v484;
        let v486: f64 = v154 * v173;
        let v487: f64 = v150 * v181;
        let v488: f64 = v486 + v487;
        (
            v328,
            v330,
            v342,
            v346,
            v347,
            v363,
            v367,
            v373,
            v376,
            v387,
            v394,
            v396,
            v399,
            v402,
            v404,
            v406,
            v416,
            v436,
            v449,
            v451,
            v452,
            v459,
            v474,
            v475,
            v477,
            v479,
            v480,
            v485,
            v488,
        )
    };
    let (
        v490,
        v496,
        v523,
        v550,
        v553,
        v571,
        v594,
        v597,
        v600,
        v605,
        v609,
        v626,
        v637,
        v640,
        v642,
        v643,
        v648,
        v649,
        v650,
        v651,
    ) = {
        let v489: f64 = v167 * v161;
        let v490: f64 = v488 + v489;
        let v491: f64 = v181 * v490;
        let v492: f64 = v161 * v185;
        let v493: f64 = v491 - v492;
        let v494: f64 = v485 + v493;
        let v495: f64 = v196 * v363;
        let v496: f64 = params[33];
        let v497: f64 = v496 * v223;
        let v498: f64 = v495 + v497;
        let v499: f64 = v494 + v498;
        let v500: f64 = v266 * v239;
        let v501: f64 = v257 * v249;
        let v502: f64 = v500 + v501;
        let v503: f64 = v227 * v254;
        let v504: f64 = v502 + v503;
        let v505: f64 = v227 * v247;
        let v506: f64 = v241 * v236;
        let v507: f64 = v505 + v506;
        let v508: f64 = v252 * v262;
        let v509: f64 = v507 + v508;
        let v510: f64 = v236 * v509;
        let v511: f64 = v262 * v264;
        let v512: f64 = v510 - v511;
        let v513: f64 = v504 + v512;
        let v514: f64 = v291 * v367;
        let v515: f64 = v406 * v289;
        let v516: f64 = v514 + v515;
        let v517: f64 = v513 + v516;
        let v518: f64 = v299 * v399;
        let v519: f64 = v302 * v376;
        let v520: f64 = v518 + v519;
        let v521: f64 = v517 + v520;
        let v522: f64 = v347 * v474;
        let v523: f64 = v521 - v522;
        let v524: f64 = v231 * v523;
        let v525: f64 = v257 * v239;
        let v526: f64 = v259 * v249;
        let v527: f64 = v525 + v526;
        let v528: f64 = v241 * v254;
        let v529: f64 = v527 + v528;
        let v530: f64 = v262 * v271;
        let v531: f64 = v247 * v509;
        let v532: f64 = v530 - v531;
        let v533: f64 = v529 + v532;
        let v534: f64 = v406 * v294;
        let v535: f64 = v275 * v367;
        let v536: f64 = v534 - v535;
        let v537: f64 = v533 + v536;
        let v538: f64 = v328 * v310;
        let v539: f64 = v330 * v314;
        let v540: f64 = v538 + v539;
        let v541: f64 = v312 * v325;
        let v542: f64 = v540 + v541;
        let v543: f64 = v307 * v342;
        let v544: f64 = v323 * v387;
        let v545: f64 = v543 - v544;
        let v546: f64 = v542 + v545;
        let v547: f64 = v396 * v373;
        let v548: f64 = v346 * v394;
        let v549: f64 = v547 - v548;
        let v550: f64 = v546 + v549;
        let v551: f64 = v537 + v550;
        let v552: f64 = v347 * v451;
        let v553: f64 = v551 + v552;
        let v554: f64 = v229 * v553;
        let v555: f64 = v524 - v554;
        let v556: f64 = v499 + v555;
        let v557: f64 = v404 * v367;
        let v558: f64 = v239 * v291;
        let v559: f64 = v249 * v275;
        let v560: f64 = v558 - v559;
        let v561: f64 = v247 * v416;
        let v562: f64 = v236 * v459;
        let v563: f64 = v561 - v562;
        let v564: f64 = v560 + v563;
        let v565: f64 = v557 + v564;
        let v566: f64 = v299 * v449;
        let v567: f64 = v302 * v436;
        let v568: f64 = v566 - v567;
        let v569: f64 = v565 + v568;
        let v570: f64 = v276 * v569;
        let v571: f64 = v556 + v570;
        let v572: f64 = v155 * v571;
        let v573: f64 = v480 - v572;
        let v574: f64 = v147 + v573;
        let v575: f64 = v175 * v219;
        let v576: f64 = v164 * v496;
        let v577: f64 = v575 + v576;
        let v578: f64 = v181 * v496;
        let v579: f64 = v161 * v196;
        let v580: f64 = v578 - v579;
        let v581: f64 = v161 * v580;
        let v582: f64 = v173 * v196;
        let v583: f64 = v181 * v219;
        let v584: f64 = v582 - v583;
        let v585: f64 = v173 * v584;
        let v586: f64 = v581 - v585;
        let v587: f64 = v577 + v586;
        let v588: f64 = params[30];
        let v589: f64 = v588 * v223;
        let v590: f64 = v587 - v589;
        let v591: f64 = v229 * v452;
        let v592: f64 = v231 * v475;
        let v593: f64 = v591 + v592;
        let v594: f64 = v590 + v593;
        let v595: f64 = v204 * v594;
        let v596: f64 = v574 - v595;
        let v597: f64 = params[20];
        let v598: f64 = v597 * v133;
        let v599: f64 = v72 * v108;
        let v600: f64 = params[21];
        let v601: f64 = v76 * v600;
        let v602: f64 = v599 - v601;
        let v603: f64 = v69 * v600;
        let v604: f64 = v85 * v135;
        let v605: f64 = v603 + v604;
        let v606: f64 = v85 * v605;
        let v607: f64 = v90 * v135;
        let v608: f64 = v69 * v108;
        let v609: f64 = v607 + v608;
        let v610: f64 = v90 * v609;
        let v611: f64 = v606 + v610;
        let v612: f64 = v602 - v611;
        let v613: f64 = v598 + v612;
        let v614: f64 = v152 * v496;
        let v615: f64 = v175 * v196;
        let v616: f64 = v614 - v615;
        let v617: f64 = v181 * v584;
        let v618: f64 = v161 * v219;
        let v619: f64 = v173 * v496;
        let v620: f64 = v618 - v619;
        let v621: f64 = v161 * v620;
        let v622: f64 = v617 - v621;
        let v623: f64 = v616 + v622;
        let v624: f64 = v588 * v217;
        let v625: f64 = v623 - v624;
        let v626: f64 = v625 + v477;
        let v627: f64 = v149 * v626;
        let v628: f64 = v588 * v363;
        let v629: f64 = v173 * v620;
        let v630: f64 = v181 * v580;
        let v631: f64 = v629 - v630;
        let v632: f64 = v164 * v196;
        let v633: f64 = v152 * v219;
        let v634: f64 = v632 + v633;
        let v635: f64 = v631 - v634;
        let v636: f64 = v628 + v635;
        let v637: f64 = v636 + v569;
        let v638: f64 = v155 * v637;
        let v639: f64 = v627 + v638;
        let v640: f64 = v613 - v639;
        let v641: f64 = v128 * v640;
        let v642: f64 = v596 + v641;
        let v643: f64 = v61 * v642;
        let v644: f64 = v79 * v72;
        let v645: f64 = v92 * v76;
        let v646: f64 = v644 + v645;
        let v647: f64 = v95 * v87;
        let v648: f64 = v646 + v647;
        let v649: f64 = v85 * v104;
        let v650: f64 = v62 * v85;
        let v651: f64 = v74 * v90;
        (
            v490,
            v496,
            v523,
            v550,
            v553,
            v571,
            v594,
            v597,
            v600,
            v605,
            v609,
            v626,
            v637,
            v640,
            v642,
            v643,
            v648,
            v649,
            v650,
            v651,
        )
    };
    let (v765, v808, v811, v814) = {
        let v652: f64 = v650 + v651;
        let v653: f64 = v79 * v69;
        let v654: f64 = v652 - v653;
        let v655: f64 = v90 * v654;
        let v656: f64 = v649 - v655;
        let v657: f64 = v648 + v656;
        let v658: f64 = v600 * v144;
        let v659: f64 = v108 * v203;
        let v660: f64 = v658 + v659;
        let v661: f64 = v657 - v660;
        let v662: f64 = v149 * v571;
        let v663: f64 = v155 * v479;
        let v664: f64 = v662 + v663;
        let v665: f64 = v661 - v664;
        let v666: f64 = v597 * v203;
        let v667: f64 = v76 * v135;
        let v668: f64 = v87 * v108;
        let v669: f64 = v667 - v668;
        let v670: f64 = v85 * v108;
        let v671: f64 = v90 * v600;
        let v672: f64 = v670 - v671;
        let v673: f64 = v90 * v672;
        let v674: f64 = v69 * v605;
        let v675: f64 = v673 - v674;
        let v676: f64 = v669 + v675;
        let v677: f64 = v666 + v676;
        let v678: f64 = v149 * v637;
        let v679: f64 = v155 * v626;
        let v680: f64 = v678 - v679;
        let v681: f64 = v677 + v680;
        let v682: f64 = v128 * v681;
        let v683: f64 = v665 - v682;
        let v684: f64 = v64 * v683;
        let v685: f64 = v643 + v684;
        let v686: f64 = v59 + v685;
        let v687: f64 = v87 * v600;
        let v688: f64 = v72 * v135;
        let v689: f64 = v687 - v688;
        let v690: f64 = v69 * v609;
        let v691: f64 = v85 * v672;
        let v692: f64 = v690 + v691;
        let v693: f64 = v689 - v692;
        let v694: f64 = v597 * v144;
        let v695: f64 = v693 - v694;
        let v696: f64 = v695 + v594;
        let v697: f64 = v114 * v696;
        let v698: f64 = v686 - v697;
        let v699: f64 = params[10];
        let v700: f64 = v699 * v50;
        let v701: f64 = v12 * v42;
        let v702: f64 = params[11];
        let v703: f64 = v15 * v702;
        let v704: f64 = v701 - v703;
        let v705: f64 = v20 * v52;
        let v706: f64 = v8 * v702;
        let v707: f64 = v705 - v706;
        let v708: f64 = v20 * v707;
        let v709: f64 = v9 * v52;
        let v710: f64 = v8 * v42;
        let v711: f64 = v709 + v710;
        let v712: f64 = v9 * v711;
        let v713: f64 = v708 + v712;
        let v714: f64 = v704 - v713;
        let v715: f64 = v700 + v714;
        let v716: f64 = v61 * v640;
        let v717: f64 = v64 * v681;
        let v718: f64 = v716 - v717;
        let v719: f64 = v715 + v718;
        let v720: f64 = v43 * v719;
        let v721: f64 = v698 + v720;
        let v722: f64 = v4 * v721;
        let v723: f64 = v18 * v12;
        let v724: f64 = v25 * v15;
        let v725: f64 = v723 + v724;
        let v726: f64 = v29 * v22;
        let v727: f64 = v725 - v726;
        let v728: f64 = v20 * v38;
        let v729: f64 = v14 * v9;
        let v730: f64 = v5 * v20;
        let v731: f64 = v729 - v730;
        let v732: f64 = v18 * v8;
        let v733: f64 = v731 - v732;
        let v734: f64 = v9 * v733;
        let v735: f64 = v728 + v734;
        let v736: f64 = v727 - v735;
        let v737: f64 = v702 * v56;
        let v738: f64 = v42 * v113;
        let v739: f64 = v737 + v738;
        let v740: f64 = v736 - v739;
        let v741: f64 = v61 * v683;
        let v742: f64 = v64 * v642;
        let v743: f64 = v741 - v742;
        let v744: f64 = v740 + v743;
        let v745: f64 = v699 * v113;
        let v746: f64 = v15 * v52;
        let v747: f64 = v22 * v42;
        let v748: f64 = v746 + v747;
        let v749: f64 = v8 * v707;
        let v750: f64 = v20 * v42;
        let v751: f64 = v9 * v702;
        let v752: f64 = v750 + v751;
        let v753: f64 = v9 * v752;
        let v754: f64 = v749 - v753;
        let v755: f64 = v748 + v754;
        let v756: f64 = v745 + v755;
        let v757: f64 = v61 * v681;
        let v758: f64 = v64 * v640;
        let v759: f64 = v757 + v758;
        let v760: f64 = v756 + v759;
        let v761: f64 = v43 * v760;
        let v762: f64 = v744 - v761;
        let v763: f64 = v6 * v762;
        let v764: f64 = v722 + v763;
        let v765: f64 = v2 - v764;
        let v766: f64 = v14 * v12;
        let v767: f64 = v33 * v15;
        let v768: f64 = v766 + v767;
        let v769: f64 = v25 * v22;
        let v770: f64 = v768 - v769;
        let v771: f64 = v20 * v31;
        let v772: f64 = v8 * v733;
        let v773: f64 = v771 - v772;
        let v774: f64 = v770 + v773;
        let v775: f64 = v52 * v113;
        let v776: f64 = v702 * v50;
        let v777: f64 = v775 - v776;
        let v778: f64 = v774 + v777;
        let v779: f64 = v74 * v72;
        let v780: f64 = v100 * v76;
        let v781: f64 = v779 + v780;
        let v782: f64 = v92 * v87;
        let v783: f64 = v781 + v782;
        let v784: f64 = v69 * v654;
        let v785: f64 = v85 * v97;
        let v786: f64 = v784 + v785;
        let v787: f64 = v783 - v786;
        let v788: f64 = v135 * v203;
        let v789: f64 = v600 * v133;
        let v790: f64 = v788 - v789;
        let v791: f64 = v787 + v790;
        let v792: f64 = v180 * v152;
        let v793: f64 = v178 * v164;
        let v794: f64 = v792 - v793;
        let v795: f64 = v150 * v175;
        let v796: f64 = v794 + v795;
        let v797: f64 = v161 * v192;
        let v798: f64 = v173 * v490;
        let v799: f64 = v797 - v798;
        let v800: f64 = v796 + v799;
        let v801: f64 = v496 * v217;
        let v802: f64 = v219 * v363;
        let v803: f64 = v801 + v802;
        let v804: f64 = v800 - v803;
        let v805: f64 = v229 * v523;
        let v806: f64 = v231 * v553;
        let v807: f64 = v805 + v806;
        let v808: f64 = v804 + v807;
        let v809: f64 = v791 + v808;
        let v810: f64 = v204 * v680;
        let v811: f64 = v809 + v810;
        let v812: f64 = v778 + v811;
        let v813: f64 = v114 * v759;
        let v814: f64 = v812 + v813;
        (v765, v808, v811, v814)
    };
    [v765, v814, v811, v808, v402, v550]
}
/// Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g. The pivots `D_k` of the factorisation depend on `params`, which must therefore give a positive definite mass matrix (any physical parameter set does: positive masses, inertias that satisfy the triangle inequalities); nothing is checked, and parameters that make a pivot zero give a non-finite result.
///
/// # Inputs
///
/// - `q: &[f64; 6]`: joint positions q (rad for revolute joints, m for prismatic joints)
/// - `qd: &[f64; 6]`: joint velocities qd (rad/s or m/s)
/// - `tau: &[f64; 6]`: joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench
/// - `params: &[f64; 60]`: standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)
///
/// # Output
///
/// `qdd: [f64; 6]`: joint accelerations qdd (rad/s^2 or m/s^2)
///
/// Operation count: 1286 floating-point operations, 10 trig calls.
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
    q: &[f64; 6],
    qd: &[f64; 6],
    tau: &[f64; 6],
    params: &[f64; 60],
) -> [f64; 6] {
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
        v19,
        v21,
        v23,
        v25,
        v29,
        v33,
        v34,
        v41,
        v43,
        v47,
        v50,
        v52,
        v53,
        v55,
        v60,
        v63,
        v65,
        v71,
        v73,
        v76,
        v78,
        v81,
        v83,
        v85,
        v87,
        v91,
        v95,
        v100,
        v101,
        v113,
        v118,
        v120,
        v129,
        v132,
        v134,
        v135,
        v137,
        v142,
        v145,
        v147,
        v153,
        v155,
        v158,
        v160,
        v161,
        v164,
        v166,
        v168,
        v173,
        v176,
        v177,
        v184,
        v185,
        v188,
        v191,
        v194,
        v196,
        v197,
    ) = {
        let v0: f64 = tau[0];
        let v1: f64 = q[1];
        let (v4, v2): (f64, f64) = ::armdyn_runtime::libm::sincos(v1);
        let v3: f64 = params[14];
        let v5: f64 = qd[0];
        let v6: f64 = v4 * v5;
        let v7: f64 = qd[1];
        let v8: f64 = v6 * v7;
        let v9: f64 = v3 * v8;
        let v10: f64 = params[16];
        let v11: f64 = v2 * v5;
        let v12: f64 = v11 * v7;
        let v13: f64 = v10 * v12;
        let v14: f64 = v9 - v13;
        let v15: f64 = params[18];
        let v16: f64 = v15 * v7;
        let v17: f64 = v10 * v11;
        let v18: f64 = v16 - v17;
        let v19: f64 = params[19];
        let v20: f64 = v19 * v6;
        let v21: f64 = v18 - v20;
        let v22: f64 = v7 * v21;
        let v23: f64 = params[17];
        let v24: f64 = v23 * v7;
        let v25: f64 = params[15];
        let v26: f64 = v25 * v11;
        let v27: f64 = v24 - v26;
        let v28: f64 = v15 * v6;
        let v29: f64 = v27 - v28;
        let v30: f64 = v6 * v29;
        let v31: f64 = v22 + v30;
        let v32: f64 = v14 + v31;
        let v33: f64 = params[12];
        let v34: f64 = 0.13585_f64;
        let v35: f64 = v34 * v8;
        let v36: f64 = v34 * v6;
        let v37: f64 = v7 * v36;
        let v38: f64 = v35 - v37;
        let v39: f64 = 9.81_f64;
        let v40: f64 = v39 * v4;
        let v41: f64 = v38 - v40;
        let v42: f64 = v33 * v41;
        let v43: f64 = params[13];
        let v44: f64 = v6 * v36;
        let v45: f64 = v34 * v11;
        let v46: f64 = v11 * v45;
        let v47: f64 = v44 + v46;
        let v48: f64 = v43 * v47;
        let v49: f64 = v42 + v48;
        let v50: f64 = v32 + v49;
        let v51: f64 = q[2];
        let (v55, v52): (f64, f64) = ::armdyn_runtime::libm::sincos(v51);
        let v53: f64 = params[24];
        let v54: f64 = v52 * v8;
        let v56: f64 = v55 * v12;
        let v57: f64 = v54 + v56;
        let v58: f64 = v55 * v11;
        let v59: f64 = v52 * v6;
        let v60: f64 = v58 + v59;
        let v61: f64 = qd[2];
        let v62: f64 = v60 * v61;
        let v63: f64 = v57 + v62;
        let v64: f64 = v53 * v63;
        let v65: f64 = params[26];
        let v66: f64 = v55 * v8;
        let v67: f64 = v52 * v12;
        let v68: f64 = v66 - v67;
        let v69: f64 = v55 * v6;
        let v70: f64 = v52 * v11;
        let v71: f64 = v69 - v70;
        let v72: f64 = v71 * v61;
        let v73: f64 = v68 + v72;
        let v74: f64 = v65 * v73;
        let v75: f64 = v64 + v74;
        let v76: f64 = v7 + v61;
        let v77: f64 = v65 * v71;
        let v78: f64 = params[28];
        let v79: f64 = v78 * v76;
        let v80: f64 = v77 + v79;
        let v81: f64 = params[29];
        let v82: f64 = v81 * v60;
        let v83: f64 = v80 - v82;
        let v84: f64 = v76 * v83;
        let v85: f64 = params[25];
        let v86: f64 = v85 * v71;
        let v87: f64 = params[27];
        let v88: f64 = v87 * v76;
        let v89: f64 = v86 + v88;
        let v90: f64 = v78 * v60;
        let v91: f64 = v89 - v90;
        let v92: f64 = v60 * v91;
        let v93: f64 = v84 + v92;
        let v94: f64 = v75 + v93;
        let v95: f64 = params[22];
        let v96: f64 = v34 * v12;
        let v97: f64 = v7 * v45;
        let v98: f64 = v96 - v97;
        let v99: f64 = v39 * v2;
        let v100: f64 = v98 - v99;
        let v101: f64 = 0.425_f64;
        let v102: f64 = v101 * v11;
        let v103: f64 = v6 * v102;
        let v104: f64 = v100 + v103;
        let v105: f64 = v55 * v104;
        let v106: f64 = v11 * v102;
        let v107: f64 = v101 * v7;
        let v108: f64 = v7 * v107;
        let v109: f64 = v106 + v108;
        let v110: f64 = v41 - v109;
        let v111: f64 = v52 * v110;
        let v112: f64 = v105 + v111;
        let v113: f64 = -0.1197_f64;
        let v114: f64 = v113 * v63;
        let v115: f64 = v113 * v60;
        let v116: f64 = v76 * v115;
        let v117: f64 = v114 - v116;
        let v118: f64 = v112 + v117;
        let v119: f64 = v95 * v118;
        let v120: f64 = params[23];
        let v121: f64 = v101 * v8;
        let v122: f64 = v6 * v107;
        let v123: f64 = v121 + v122;
        let v124: f64 = v47 + v123;
        let v125: f64 = v60 * v115;
        let v126: f64 = v113 * v71;
        let v127: f64 = v71 * v126;
        let v128: f64 = v125 + v127;
        let v129: f64 = v124 + v128;
        let v130: f64 = v120 * v129;
        let v131: f64 = v119 + v130;
        let v132: f64 = v94 + v131;
        let v133: f64 = q[3];
        let (v137, v134): (f64, f64) = ::armdyn_runtime::libm::sincos(v133);
        let v135: f64 = params[39];
        let v136: f64 = v134 * v63;
        let v138: f64 = v137 * v73;
        let v139: f64 = v136 - v138;
        let v140: f64 = v134 * v60;
        let v141: f64 = v137 * v71;
        let v142: f64 = v140 - v141;
        let v143: f64 = qd[3];
        let v144: f64 = v142 * v143;
        let v145: f64 = v139 + v144;
        let v146: f64 = v135 * v145;
        let v147: f64 = params[36];
        let v148: f64 = v137 * v63;
        let v149: f64 = v134 * v73;
        let v150: f64 = v148 + v149;
        let v151: f64 = v134 * v71;
        let v152: f64 = v137 * v60;
        let v153: f64 = v151 + v152;
        let v154: f64 = v153 * v143;
        let v155: f64 = v150 + v154;
        let v156: f64 = v147 * v155;
        let v157: f64 = v146 - v156;
        let v158: f64 = params[35];
        let v159: f64 = v158 * v142;
        let v160: f64 = params[37];
        let v161: f64 = v76 + v143;
        let v162: f64 = v160 * v161;
        let v163: f64 = v159 + v162;
        let v164: f64 = params[38];
        let v165: f64 = v164 * v153;
        let v166: f64 = v163 + v165;
        let v167: f64 = v142 * v166;
        let v168: f64 = params[34];
        let v169: f64 = v168 * v142;
        let v170: f64 = v158 * v161;
        let v171: f64 = v169 + v170;
        let v172: f64 = v147 * v153;
        let v173: f64 = v171 + v172;
        let v174: f64 = v161 * v173;
        let v175: f64 = v167 - v174;
        let v176: f64 = v157 + v175;
        let v177: f64 = params[32];
        let v178: f64 = v52 * v104;
        let v179: f64 = v55 * v110;
        let v180: f64 = v178 - v179;
        let v181: f64 = v76 * v126;
        let v182: f64 = v113 * v73;
        let v183: f64 = v181 - v182;
        let v184: f64 = v180 + v183;
        let v185: f64 = 0.39225_f64;
        let v186: f64 = v185 * v71;
        let v187: f64 = v60 * v186;
        let v188: f64 = v184 - v187;
        let v189: f64 = v137 * v188;
        let v190: f64 = v71 * v186;
        let v191: f64 = v185 * v76;
        let v192: f64 = v76 * v191;
        let v193: f64 = v190 + v192;
        let v194: f64 = v118 - v193;
        let v195: f64 = v134 * v194;
        let v196: f64 = v189 + v195;
        let v197: f64 = v177 * v196;
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
            v19,
            v21,
            v23,
            v25,
            v29,
            v33,
            v34,
            v41,
            v43,
            v47,
            v50,
            v52,
            v53,
            v55,
            v60,
            v63,
            v65,
            v71,
            v73,
            v76,
            v78,
            v81,
            v83,
            v85,
            v87,
            v91,
            v95,
            v100,
            v101,
            v113,
            v118,
            v120,
            v129,
            v132,
            v134,
            v135,
            v137,
            v142,
            v145,
            v147,
            v153,
            v155,
            v158,
            v160,
            v161,
            v164,
            v166,
            v168,
            v173,
            v176,
            v177,
            v184,
            v185,
            v188,
            v191,
            v194,
            v196,
            v197,
        )
    };
    let (
        v198,
        v202,
        v206,
        v208,
        v210,
        v212,
        v216,
        v218,
        v222,
        v224,
        v227,
        v230,
        v232,
        v235,
        v237,
        v239,
        v244,
        v248,
        v249,
        v262,
        v264,
        v267,
        v272,
        v273,
        v275,
        v280,
        v283,
        v285,
        v288,
        v294,
        v296,
        v299,
        v301,
        v302,
        v308,
        v313,
        v317,
        v318,
        v323,
        v325,
        v334,
        v338,
        v344,
        v347,
        v358,
        v365,
        v367,
        v370,
        v373,
        v374,
        v375,
        v377,
        v383,
        v387,
        v391,
        v392,
        v393,
        v394,
        v395,
    ) = {
        let v198: f64 = params[31];
        let v199: f64 = v185 * v63;
        let v200: f64 = v60 * v191;
        let v201: f64 = v199 + v200;
        let v202: f64 = v129 + v201;
        let v203: f64 = v198 * v202;
        let v204: f64 = v197 - v203;
        let v205: f64 = v176 + v204;
        let v206: f64 = params[46];
        let v207: f64 = q[4];
        let (v210, v208): (f64, f64) = ::armdyn_runtime::libm::sincos(v207);
        let v209: f64 = v208 * v161;
        let v211: f64 = v210 * v142;
        let v212: f64 = v209 - v211;
        let v213: f64 = qd[4];
        let v214: f64 = v212 * v213;
        let v215: f64 = v208 * v155;
        let v216: f64 = v214 - v215;
        let v217: f64 = v206 * v216;
        let v218: f64 = params[48];
        let v219: f64 = v210 * v155;
        let v220: f64 = v208 * v142;
        let v221: f64 = v210 * v161;
        let v222: f64 = v220 + v221;
        let v223: f64 = v222 * v213;
        let v224: f64 = v219 - v223;
        let v225: f64 = v218 * v224;
        let v226: f64 = v217 + v225;
        let v227: f64 = params[49];
        let v228: f64 = v227 * v145;
        let v229: f64 = v226 + v228;
        let v230: f64 = params[45];
        let v231: f64 = v230 * v222;
        let v232: f64 = params[47];
        let v233: f64 = v232 * v212;
        let v234: f64 = v231 + v233;
        let v235: f64 = v153 + v213;
        let v236: f64 = v218 * v235;
        let v237: f64 = v234 + v236;
        let v238: f64 = v222 * v237;
        let v239: f64 = params[44];
        let v240: f64 = v239 * v222;
        let v241: f64 = v230 * v212;
        let v242: f64 = v240 + v241;
        let v243: f64 = v206 * v235;
        let v244: f64 = v242 + v243;
        let v245: f64 = v212 * v244;
        let v246: f64 = v238 - v245;
        let v247: f64 = v229 + v246;
        let v248: f64 = params[41];
        let v249: f64 = 0.093_f64;
        let v250: f64 = v249 * v142;
        let v251: f64 = v161 * v250;
        let v252: f64 = v249 * v145;
        let v253: f64 = v251 - v252;
        let v254: f64 = v253 - v196;
        let v255: f64 = v210 * v254;
        let v256: f64 = v249 * v153;
        let v257: f64 = v153 * v256;
        let v258: f64 = v142 * v250;
        let v259: f64 = v257 + v258;
        let v260: f64 = v202 + v259;
        let v261: f64 = v208 * v260;
        let v262: f64 = v255 + v261;
        let v263: f64 = v248 * v262;
        let v264: f64 = params[42];
        let v265: f64 = v208 * v254;
        let v266: f64 = v210 * v260;
        let v267: f64 = v265 - v266;
        let v268: f64 = v264 * v267;
        let v269: f64 = v263 + v268;
        let v270: f64 = v247 - v269;
        let v271: f64 = q[5];
        let (v275, v272): (f64, f64) = ::armdyn_runtime::libm::sincos(v271);
        let v273: f64 = params[56];
        let v274: f64 = v272 * v216;
        let v276: f64 = v275 * v145;
        let v277: f64 = v274 - v276;
        let v278: f64 = v275 * v222;
        let v279: f64 = v272 * v235;
        let v280: f64 = v278 + v279;
        let v281: f64 = qd[5];
        let v282: f64 = v280 * v281;
        let v283: f64 = v277 - v282;
        let v284: f64 = v273 * v283;
        let v285: f64 = params[58];
        let v286: f64 = v285 * v224;
        let v287: f64 = v284 + v286;
        let v288: f64 = params[59];
        let v289: f64 = v275 * v216;
        let v290: f64 = v272 * v145;
        let v291: f64 = v289 + v290;
        let v292: f64 = v272 * v222;
        let v293: f64 = v275 * v235;
        let v294: f64 = v292 - v293;
        let v295: f64 = v294 * v281;
        let v296: f64 = v291 + v295;
        let v297: f64 = v288 * v296;
        let v298: f64 = v287 + v297;
        let v299: f64 = params[55];
        let v300: f64 = v299 * v294;
        let v301: f64 = params[57];
        let v302: f64 = v212 + v281;
        let v303: f64 = v301 * v302;
        let v304: f64 = v300 + v303;
        let v305: f64 = v285 * v280;
        let v306: f64 = v304 + v305;
        let v307: f64 = v294 * v306;
        let v308: f64 = params[54];
        let v309: f64 = v308 * v294;
        let v310: f64 = v299 * v302;
        let v311: f64 = v309 + v310;
        let v312: f64 = v273 * v280;
        let v313: f64 = v311 + v312;
        let v314: f64 = v302 * v313;
        let v315: f64 = v307 - v314;
        let v316: f64 = v298 + v315;
        let v317: f64 = params[51];
        let v318: f64 = 0.09465_f64;
        let v319: f64 = v318 * v212;
        let v320: f64 = v235 * v319;
        let v321: f64 = v318 * v216;
        let v322: f64 = v320 - v321;
        let v323: f64 = v322 - v262;
        let v324: f64 = v317 * v323;
        let v325: f64 = params[52];
        let v326: f64 = v318 * v224;
        let v327: f64 = v318 * v222;
        let v328: f64 = v235 * v327;
        let v329: f64 = v326 + v328;
        let v330: f64 = v267 + v329;
        let v331: f64 = v272 * v330;
        let v332: f64 = v134 * v188;
        let v333: f64 = v137 * v194;
        let v334: f64 = v332 - v333;
        let v335: f64 = v161 * v256;
        let v336: f64 = v249 * v155;
        let v337: f64 = v335 - v336;
        let v338: f64 = v334 + v337;
        let v339: f64 = v222 * v327;
        let v340: f64 = v212 * v319;
        let v341: f64 = v339 + v340;
        let v342: f64 = v338 - v341;
        let v343: f64 = v275 * v342;
        let v344: f64 = v331 - v343;
        let v345: f64 = v325 * v344;
        let v346: f64 = v324 - v345;
        let v347: f64 = v316 + v346;
        let v348: f64 = v272 * v347;
        let v349: f64 = v308 * v283;
        let v350: f64 = v299 * v224;
        let v351: f64 = v349 + v350;
        let v352: f64 = v273 * v296;
        let v353: f64 = v351 + v352;
        let v354: f64 = v273 * v294;
        let v355: f64 = v285 * v302;
        let v356: f64 = v354 + v355;
        let v357: f64 = v288 * v280;
        let v358: f64 = v356 + v357;
        let v359: f64 = v302 * v358;
        let v360: f64 = v280 * v306;
        let v361: f64 = v359 - v360;
        let v362: f64 = v353 + v361;
        let v363: f64 = v275 * v330;
        let v364: f64 = v272 * v342;
        let v365: f64 = v363 + v364;
        let v366: f64 = v325 * v365;
        let v367: f64 = params[53];
        let v368: f64 = v367 * v323;
        let v369: f64 = v366 - v368;
        let v370: f64 = v362 + v369;
        let v371: f64 = v275 * v370;
        let v372: f64 = v348 - v371;
        let v373: f64 = v270 + v372;
        let v374: f64 = v205 + v373;
        let v375: f64 = params[40];
        let v376: f64 = v375 * v267;
        let v377: f64 = params[43];
        let v378: f64 = v224 * v377;
        let v379: f64 = v145 * v264;
        let v380: f64 = v378 - v379;
        let v381: f64 = v222 * v264;
        let v382: f64 = v212 * v248;
        let v383: f64 = v381 - v382;
        let v384: f64 = v212 * v383;
        let v385: f64 = v235 * v248;
        let v386: f64 = v222 * v377;
        let v387: f64 = v385 - v386;
        let v388: f64 = v235 * v387;
        let v389: f64 = v384 - v388;
        let v390: f64 = v380 + v389;
        let v391: f64 = v376 + v390;
        let v392: f64 = params[50];
        let v393: f64 = v392 * v344;
        let v394: f64 = v224 * v367;
        let v395: f64 = v296 * v325;
        (
            v198,
            v202,
            v206,
            v208,
            v210,
            v212,
            v216,
            v218,
            v222,
            v224,
            v227,
            v230,
            v232,
            v235,
            v237,
            v239,
            v244,
            v248,
            v249,
            v262,
            v264,
            v267,
            v272,
            v273,
            v275,
            v280,
            v283,
            v285,
            v288,
            v294,
            v296,
            v299,
            v301,
            v302,
            v308,
            v313,
            v317,
            v318,
            v323,
            v325,
            v334,
            v338,
            v344,
            v347,
            v358,
            v365,
            v367,
            v370,
            v373,
            v374,
            v375,
            v377,
            v383,
            v387,
            v391,
            v392,
            v393,
            v394,
            v395,
        )
    };
    let (
        v450,
        v459,
        v465,
        v492,
        v519,
        v522,
        v538,
        v540,
        v549,
        v557,
        v563,
        v565,
        v566,
        v569,
        v572,
        v576,
        v580,
        v584,
        v591,
        v592,
        v593,
    ) = {
        let v396: f64 = v394 - v395;
        let v397: f64 = v294 * v325;
        let v398: f64 = v302 * v317;
        let v399: f64 = v397 - v398;
        let v400: f64 = v302 * v399;
        let v401: f64 = v280 * v317;
        let v402: f64 = v294 * v367;
        let v403: f64 = v401 - v402;
        let v404: f64 = v280 * v403;
        let v405: f64 = v400 - v404;
        let v406: f64 = v396 + v405;
        let v407: f64 = v393 + v406;
        let v408: f64 = v272 * v407;
        let v409: f64 = v392 * v365;
        let v410: f64 = v283 * v325;
        let v411: f64 = v224 * v317;
        let v412: f64 = v410 - v411;
        let v413: f64 = v294 * v403;
        let v414: f64 = v302 * v367;
        let v415: f64 = v280 * v325;
        let v416: f64 = v414 - v415;
        let v417: f64 = v302 * v416;
        let v418: f64 = v413 - v417;
        let v419: f64 = v412 + v418;
        let v420: f64 = v409 + v419;
        let v421: f64 = v275 * v420;
        let v422: f64 = v408 + v421;
        let v423: f64 = v391 + v422;
        let v424: f64 = v208 * v423;
        let v425: f64 = v145 * v248;
        let v426: f64 = v216 * v377;
        let v427: f64 = v425 - v426;
        let v428: f64 = v212 * v377;
        let v429: f64 = v235 * v264;
        let v430: f64 = v428 - v429;
        let v431: f64 = v235 * v430;
        let v432: f64 = v222 * v383;
        let v433: f64 = v431 - v432;
        let v434: f64 = v427 + v433;
        let v435: f64 = v375 * v262;
        let v436: f64 = v434 - v435;
        let v437: f64 = v392 * v323;
        let v438: f64 = v296 * v317;
        let v439: f64 = v283 * v367;
        let v440: f64 = v438 - v439;
        let v441: f64 = v280 * v416;
        let v442: f64 = v294 * v399;
        let v443: f64 = v441 - v442;
        let v444: f64 = v440 + v443;
        let v445: f64 = v437 + v444;
        let v446: f64 = v436 + v445;
        let v447: f64 = v210 * v446;
        let v448: f64 = v424 - v447;
        let v449: f64 = v249 * v448;
        let v450: f64 = v374 - v449;
        let v451: f64 = v134 * v450;
        let v452: f64 = v147 * v145;
        let v453: f64 = v168 * v155;
        let v454: f64 = v452 - v453;
        let v455: f64 = v147 * v142;
        let v456: f64 = v164 * v161;
        let v457: f64 = v455 + v456;
        let v458: f64 = v135 * v153;
        let v459: f64 = v457 + v458;
        let v460: f64 = v161 * v459;
        let v461: f64 = v153 * v166;
        let v462: f64 = v460 - v461;
        let v463: f64 = v454 + v462;
        let v464: f64 = v177 * v334;
        let v465: f64 = params[33];
        let v466: f64 = v465 * v202;
        let v467: f64 = v464 + v466;
        let v468: f64 = v463 + v467;
        let v469: f64 = v239 * v216;
        let v470: f64 = v230 * v224;
        let v471: f64 = v469 + v470;
        let v472: f64 = v206 * v145;
        let v473: f64 = v471 + v472;
        let v474: f64 = v206 * v222;
        let v475: f64 = v218 * v212;
        let v476: f64 = v474 + v475;
        let v477: f64 = v227 * v235;
        let v478: f64 = v476 + v477;
        let v479: f64 = v212 * v478;
        let v480: f64 = v235 * v237;
        let v481: f64 = v479 - v480;
        let v482: f64 = v473 + v481;
        let v483: f64 = v264 * v338;
        let v484: f64 = v377 * v262;
        let v485: f64 = v483 + v484;
        let v486: f64 = v482 + v485;
        let v487: f64 = v272 * v370;
        let v488: f64 = v275 * v347;
        let v489: f64 = v487 + v488;
        let v490: f64 = v486 + v489;
        let v491: f64 = v318 * v445;
        let v492: f64 = v490 - v491;
        let v493: f64 = v208 * v492;
        let v494: f64 = v230 * v216;
        let v495: f64 = v232 * v224;
        let v496: f64 = v494 + v495;
        let v497: f64 = v218 * v145;
        let v498: f64 = v496 + v497;
        let v499: f64 = v235 * v244;
        let v500: f64 = v222 * v478;
        let v501: f64 = v499 - v500;
        let v502: f64 = v498 + v501;
        let v503: f64 = v377 * v267;
        let v504: f64 = v248 * v338;
        let v505: f64 = v503 - v504;
        let v506: f64 = v502 + v505;
        let v507: f64 = v299 * v283;
        let v508: f64 = v301 * v224;
        let v509: f64 = v507 + v508;
        let v510: f64 = v285 * v296;
        let v511: f64 = v509 + v510;
        let v512: f64 = v280 * v313;
        let v513: f64 = v294 * v358;
        let v514: f64 = v512 - v513;
        let v515: f64 = v511 + v514;
        let v516: f64 = v367 * v344;
        let v517: f64 = v317 * v365;
        let v518: f64 = v516 - v517;
        let v519: f64 = v515 + v518;
        let v520: f64 = v506 + v519;
        let v521: f64 = v318 * v422;
        let v522: f64 = v520 + v521;
        let v523: f64 = v210 * v522;
        let v524: f64 = v493 - v523;
        let v525: f64 = v468 + v524;
        let v526: f64 = v375 * v338;
        let v527: f64 = v216 * v264;
        let v528: f64 = v224 * v248;
        let v529: f64 = v527 - v528;
        let v530: f64 = v222 * v387;
        let v531: f64 = v212 * v430;
        let v532: f64 = v530 - v531;
        let v533: f64 = v529 + v532;
        let v534: f64 = v526 + v533;
        let v535: f64 = v272 * v420;
        let v536: f64 = v275 * v407;
        let v537: f64 = v535 - v536;
        let v538: f64 = v534 + v537;
        let v539: f64 = v249 * v538;
        let v540: f64 = v525 + v539;
        let v541: f64 = v137 * v540;
        let v542: f64 = v451 - v541;
        let v543: f64 = v132 + v542;
        let v544: f64 = v145 * v198;
        let v545: f64 = v155 * v465;
        let v546: f64 = v544 + v545;
        let v547: f64 = v161 * v465;
        let v548: f64 = v153 * v177;
        let v549: f64 = v547 - v548;
        let v550: f64 = v153 * v549;
        let v551: f64 = v142 * v177;
        let v552: f64 = v161 * v198;
        let v553: f64 = v551 - v552;
        let v554: f64 = v142 * v553;
        let v555: f64 = v550 - v554;
        let v556: f64 = v546 + v555;
        let v557: f64 = params[30];
        let v558: f64 = v557 * v202;
        let v559: f64 = v556 - v558;
        let v560: f64 = v210 * v423;
        let v561: f64 = v208 * v446;
        let v562: f64 = v560 + v561;
        let v563: f64 = v559 + v562;
        let v564: f64 = v185 * v563;
        let v565: f64 = v543 - v564;
        let v566: f64 = params[20];
        let v567: f64 = v566 * v118;
        let v568: f64 = v63 * v95;
        let v569: f64 = params[21];
        let v570: f64 = v60 * v569;
        let v571: f64 = v71 * v120;
        let v572: f64 = v570 + v571;
        let v573: f64 = v71 * v572;
        let v574: f64 = v76 * v120;
        let v575: f64 = v60 * v95;
        let v576: f64 = v574 + v575;
        let v577: f64 = v76 * v576;
        let v578: f64 = v573 + v577;
        let v579: f64 = v568 - v578;
        let v580: f64 = v567 + v579;
        let v581: f64 = v161 * v553;
        let v582: f64 = v153 * v198;
        let v583: f64 = v142 * v465;
        let v584: f64 = v582 - v583;
        let v585: f64 = v153 * v584;
        let v586: f64 = v581 - v585;
        let v587: f64 = v145 * v177;
        let v588: f64 = v586 - v587;
        let v589: f64 = v557 * v196;
        let v590: f64 = v588 - v589;
        let v591: f64 = v590 + v448;
        let v592: f64 = v134 * v591;
        let v593: f64 = v557 * v334;
        (
            v450,
            v459,
            v465,
            v492,
            v519,
            v522,
            v538,
            v540,
            v549,
            v557,
            v563,
            v565,
            v566,
            v569,
            v572,
            v576,
            v580,
            v584,
            v591,
            v592,
            v593,
        )
    };
    let (
        v615,
        v639,
        v658,
        v662,
        v688,
        v712,
        v721,
        v724,
        v731,
        v733,
        v734,
        v737,
        v738,
        v759,
        v761,
        v781,
        v782,
        v784,
        v786,
        v788,
        v789,
        v790,
        v791,
    ) = {
        let v594: f64 = v142 * v584;
        let v595: f64 = v161 * v549;
        let v596: f64 = v594 - v595;
        let v597: f64 = v155 * v177;
        let v598: f64 = v596 - v597;
        let v599: f64 = v593 + v598;
        let v600: f64 = v599 + v538;
        let v601: f64 = v137 * v600;
        let v602: f64 = v592 + v601;
        let v603: f64 = v580 - v602;
        let v604: f64 = v113 * v603;
        let v605: f64 = v565 + v604;
        let v606: f64 = v52 * v605;
        let v607: f64 = v65 * v63;
        let v608: f64 = v81 * v73;
        let v609: f64 = v607 + v608;
        let v610: f64 = v71 * v91;
        let v611: f64 = v53 * v71;
        let v612: f64 = v85 * v76;
        let v613: f64 = v611 + v612;
        let v614: f64 = v65 * v60;
        let v615: f64 = v613 - v614;
        let v616: f64 = v76 * v615;
        let v617: f64 = v610 - v616;
        let v618: f64 = v609 + v617;
        let v619: f64 = v569 * v129;
        let v620: f64 = v95 * v184;
        let v621: f64 = v619 + v620;
        let v622: f64 = v618 - v621;
        let v623: f64 = v134 * v540;
        let v624: f64 = v137 * v450;
        let v625: f64 = v623 + v624;
        let v626: f64 = v622 - v625;
        let v627: f64 = v566 * v184;
        let v628: f64 = v71 * v95;
        let v629: f64 = v76 * v569;
        let v630: f64 = v628 - v629;
        let v631: f64 = v76 * v630;
        let v632: f64 = v60 * v572;
        let v633: f64 = v631 - v632;
        let v634: f64 = v73 * v95;
        let v635: f64 = v633 - v634;
        let v636: f64 = v627 + v635;
        let v637: f64 = v134 * v600;
        let v638: f64 = v137 * v591;
        let v639: f64 = v637 - v638;
        let v640: f64 = v636 + v639;
        let v641: f64 = v113 * v640;
        let v642: f64 = v626 - v641;
        let v643: f64 = v55 * v642;
        let v644: f64 = v606 + v643;
        let v645: f64 = v50 + v644;
        let v646: f64 = v73 * v569;
        let v647: f64 = v63 * v120;
        let v648: f64 = v646 - v647;
        let v649: f64 = v60 * v576;
        let v650: f64 = v71 * v630;
        let v651: f64 = v649 + v650;
        let v652: f64 = v648 - v651;
        let v653: f64 = v566 * v129;
        let v654: f64 = v652 - v653;
        let v655: f64 = v654 + v563;
        let v656: f64 = v101 * v655;
        let v657: f64 = v645 - v656;
        let v658: f64 = params[10];
        let v659: f64 = v658 * v41;
        let v660: f64 = v8 * v33;
        let v661: f64 = v11 * v43;
        let v662: f64 = params[11];
        let v663: f64 = v6 * v662;
        let v664: f64 = v661 - v663;
        let v665: f64 = v11 * v664;
        let v666: f64 = v7 * v43;
        let v667: f64 = v6 * v33;
        let v668: f64 = v666 + v667;
        let v669: f64 = v7 * v668;
        let v670: f64 = v665 + v669;
        let v671: f64 = v660 - v670;
        let v672: f64 = v659 + v671;
        let v673: f64 = v52 * v603;
        let v674: f64 = v55 * v640;
        let v675: f64 = v673 - v674;
        let v676: f64 = v672 + v675;
        let v677: f64 = v34 * v676;
        let v678: f64 = v657 + v677;
        let v679: f64 = v2 * v678;
        let v680: f64 = v10 * v8;
        let v681: f64 = v19 * v12;
        let v682: f64 = v680 - v681;
        let v683: f64 = v11 * v29;
        let v684: f64 = v25 * v7;
        let v685: f64 = v3 * v11;
        let v686: f64 = v684 - v685;
        let v687: f64 = v10 * v6;
        let v688: f64 = v686 - v687;
        let v689: f64 = v7 * v688;
        let v690: f64 = v683 + v689;
        let v691: f64 = v682 - v690;
        let v692: f64 = v662 * v47;
        let v693: f64 = v33 * v100;
        let v694: f64 = v692 + v693;
        let v695: f64 = v691 - v694;
        let v696: f64 = v52 * v642;
        let v697: f64 = v55 * v605;
        let v698: f64 = v696 - v697;
        let v699: f64 = v695 + v698;
        let v700: f64 = v658 * v100;
        let v701: f64 = v12 * v33;
        let v702: f64 = v6 * v664;
        let v703: f64 = v11 * v33;
        let v704: f64 = v7 * v662;
        let v705: f64 = v703 + v704;
        let v706: f64 = v7 * v705;
        let v707: f64 = v702 - v706;
        let v708: f64 = v701 + v707;
        let v709: f64 = v700 + v708;
        let v710: f64 = v52 * v640;
        let v711: f64 = v55 * v603;
        let v712: f64 = v710 + v711;
        let v713: f64 = v709 + v712;
        let v714: f64 = v34 * v713;
        let v715: f64 = v699 - v714;
        let v716: f64 = v4 * v715;
        let v717: f64 = v679 + v716;
        let v718: f64 = v0 + v717;
        let v719: f64 = v272 * v285;
        let v720: f64 = v275 * v299;
        let v721: f64 = v719 - v720;
        let v722: f64 = v272 * v367;
        let v723: f64 = v275 * v317;
        let v724: f64 = v722 - v723;
        let v725: f64 = v208 * v724;
        let v726: f64 = v249 * v725;
        let v727: f64 = v721 - v726;
        let v728: f64 = v134 * v727;
        let v729: f64 = v272 * v299;
        let v730: f64 = v275 * v285;
        let v731: f64 = v729 + v730;
        let v732: f64 = v208 * v731;
        let v733: f64 = v318 * v724;
        let v734: f64 = v301 + v733;
        let v735: f64 = v210 * v734;
        let v736: f64 = v732 - v735;
        let v737: f64 = v275 * v367;
        let v738: f64 = v272 * v317;
        let v739: f64 = v737 + v738;
        let v740: f64 = v249 * v739;
        let v741: f64 = v736 - v740;
        let v742: f64 = v137 * v741;
        let v743: f64 = v728 - v742;
        let v744: f64 = v210 * v724;
        let v745: f64 = v185 * v744;
        let v746: f64 = v743 - v745;
        let v747: f64 = v55 * v746;
        let v748: f64 = v134 * v741;
        let v749: f64 = v137 * v727;
        let v750: f64 = v748 + v749;
        let v751: f64 = v52 * v750;
        let v752: f64 = v747 + v751;
        let v753: f64 = v137 * v739;
        let v754: f64 = v134 * v725;
        let v755: f64 = v753 - v754;
        let v756: f64 = v55 * v755;
        let v757: f64 = v137 * v725;
        let v758: f64 = v134 * v739;
        let v759: f64 = v757 + v758;
        let v760: f64 = v52 * v759;
        let v761: f64 = v756 - v760;
        let v762: f64 = v113 * v761;
        let v763: f64 = v752 + v762;
        let v764: f64 = v4 * v763;
        let v765: f64 = v52 * v746;
        let v766: f64 = v55 * v750;
        let v767: f64 = v765 - v766;
        let v768: f64 = v55 * v759;
        let v769: f64 = v52 * v755;
        let v770: f64 = v768 + v769;
        let v771: f64 = v113 * v770;
        let v772: f64 = v101 * v744;
        let v773: f64 = v771 - v772;
        let v774: f64 = v767 + v773;
        let v775: f64 = v2 * v774;
        let v776: f64 = v764 - v775;
        let v777: f64 = v2 * v770;
        let v778: f64 = v4 * v761;
        let v779: f64 = v777 - v778;
        let v780: f64 = v34 * v779;
        let v781: f64 = v776 - v780;
        let v782: f64 = v781 / v301;
        let v783: f64 = tau[5];
        let v784: f64 = v783 - v519;
        let v785: f64 = v782 * v784;
        let v786: f64 = v718 - v785;
        let v787: f64 = v272 * v288;
        let v788: f64 = v275 * v273;
        let v789: f64 = v787 - v788;
        let v790: f64 = v789 * v272;
        let v791: f64 = v272 * v273;
        (
            v615,
            v639,
            v658,
            v662,
            v688,
            v712,
            v721,
            v724,
            v731,
            v733,
            v734,
            v737,
            v738,
            v759,
            v761,
            v781,
            v782,
            v784,
            v786,
            v788,
            v789,
            v790,
            v791,
        )
    };
    let (
        v798,
        v805,
        v833,
        v847,
        v851,
        v872,
        v874,
        v876,
        v877,
        v881,
        v883,
        v888,
        v891,
        v912,
        v919,
        v926,
        v930,
        v934,
        v936,
        v939,
        v940,
        v941,
        v943,
        v964,
        v965,
        v970,
        v972,
        v973,
        v975,
        v984,
        v986,
        v987,
        v988,
        v989,
    ) = {
        let v792: f64 = v275 * v308;
        let v793: f64 = v791 - v792;
        let v794: f64 = v793 * v275;
        let v795: f64 = v790 - v794;
        let v796: f64 = 0.0089586225_f64;
        let v797: f64 = v796 * v392;
        let v798: f64 = 2.0_f64;
        let v799: f64 = v798 * v733;
        let v800: f64 = v797 + v799;
        let v801: f64 = v795 + v800;
        let v802: f64 = v801 - v797;
        let v803: f64 = v802 - v733;
        let v804: f64 = v803 - v733;
        let v805: f64 = v227 + v804;
        let v806: f64 = v264 + v325;
        let v807: f64 = v208 * v806;
        let v808: f64 = v738 + v737;
        let v809: f64 = v248 + v808;
        let v810: f64 = v210 * v809;
        let v811: f64 = v807 + v810;
        let v812: f64 = v249 * v811;
        let v813: f64 = v805 + v812;
        let v814: f64 = v134 * v813;
        let v815: f64 = v275 * v288;
        let v816: f64 = v791 + v815;
        let v817: f64 = v816 * v272;
        let v818: f64 = v272 * v308;
        let v819: f64 = v818 + v788;
        let v820: f64 = v819 * v275;
        let v821: f64 = v817 - v820;
        let v822: f64 = v318 * v808;
        let v823: f64 = v821 - v822;
        let v824: f64 = v206 + v823;
        let v825: f64 = v208 * v824;
        let v826: f64 = v285 * v272;
        let v827: f64 = v299 * v275;
        let v828: f64 = v826 - v827;
        let v829: f64 = v318 * v325;
        let v830: f64 = v828 - v829;
        let v831: f64 = v218 + v830;
        let v832: f64 = v210 * v831;
        let v833: f64 = v825 - v832;
        let v834: f64 = v137 * v833;
        let v835: f64 = v814 - v834;
        let v836: f64 = v208 * v809;
        let v837: f64 = v210 * v806;
        let v838: f64 = v836 - v837;
        let v839: f64 = v185 * v838;
        let v840: f64 = v835 - v839;
        let v841: f64 = v55 * v840;
        let v842: f64 = v134 * v833;
        let v843: f64 = v137 * v813;
        let v844: f64 = v842 + v843;
        let v845: f64 = v52 * v844;
        let v846: f64 = v841 + v845;
        let v847: f64 = v137 * v811;
        let v848: f64 = v52 * v847;
        let v849: f64 = v134 * v811;
        let v850: f64 = v55 * v849;
        let v851: f64 = v848 + v850;
        let v852: f64 = v113 * v851;
        let v853: f64 = v846 + v852;
        let v854: f64 = v4 * v853;
        let v855: f64 = v52 * v840;
        let v856: f64 = v55 * v844;
        let v857: f64 = v855 - v856;
        let v858: f64 = v52 * v849;
        let v859: f64 = v55 * v847;
        let v860: f64 = v858 - v859;
        let v861: f64 = v113 * v860;
        let v862: f64 = v101 * v838;
        let v863: f64 = v861 - v862;
        let v864: f64 = v857 + v863;
        let v865: f64 = v2 * v864;
        let v866: f64 = v854 - v865;
        let v867: f64 = v2 * v860;
        let v868: f64 = v4 * v851;
        let v869: f64 = v867 - v868;
        let v870: f64 = v34 * v869;
        let v871: f64 = v866 - v870;
        let v872: f64 = v721 / v301;
        let v873: f64 = v781 * v872;
        let v874: f64 = v871 - v873;
        let v875: f64 = v721 * v872;
        let v876: f64 = v805 - v875;
        let v877: f64 = v874 / v876;
        let v878: f64 = tau[4];
        let v879: f64 = v878 - v373;
        let v880: f64 = v872 * v784;
        let v881: f64 = v879 - v880;
        let v882: f64 = v877 * v881;
        let v883: f64 = v786 - v882;
        let v884: f64 = v793 * v272;
        let v885: f64 = v789 * v275;
        let v886: f64 = v884 + v885;
        let v887: f64 = v886 - v822;
        let v888: f64 = v206 + v887;
        let v889: f64 = v888 * v210;
        let v890: f64 = v721 - v829;
        let v891: f64 = v218 + v890;
        let v892: f64 = v891 * v208;
        let v893: f64 = v889 + v892;
        let v894: f64 = v318 * v392;
        let v895: f64 = v724 + v894;
        let v896: f64 = v377 + v895;
        let v897: f64 = v249 * v896;
        let v898: f64 = v893 - v897;
        let v899: f64 = v164 + v898;
        let v900: f64 = v134 * v899;
        let v901: f64 = v819 * v272;
        let v902: f64 = v816 * v275;
        let v903: f64 = v901 + v902;
        let v904: f64 = v903 + v800;
        let v905: f64 = v239 + v904;
        let v906: f64 = v208 * v905;
        let v907: f64 = v299 * v272;
        let v908: f64 = v285 * v275;
        let v909: f64 = v907 + v908;
        let v910: f64 = v230 + v909;
        let v911: f64 = v210 * v910;
        let v912: f64 = v906 - v911;
        let v913: f64 = v912 * v210;
        let v914: f64 = v230 + v731;
        let v915: f64 = v208 * v914;
        let v916: f64 = v301 + v800;
        let v917: f64 = v232 + v916;
        let v918: f64 = v210 * v917;
        let v919: f64 = v915 - v918;
        let v920: f64 = v919 * v208;
        let v921: f64 = v913 + v920;
        let v922: f64 = v249 * v838;
        let v923: f64 = v921 - v922;
        let v924: f64 = v158 + v923;
        let v925: f64 = v137 * v924;
        let v926: f64 = v900 - v925;
        let v927: f64 = v55 * v926;
        let v928: f64 = v134 * v924;
        let v929: f64 = v137 * v899;
        let v930: f64 = v928 + v929;
        let v931: f64 = v52 * v930;
        let v932: f64 = v927 + v931;
        let v933: f64 = v198 + v838;
        let v934: f64 = v137 * v933;
        let v935: f64 = v465 + v896;
        let v936: f64 = v134 * v935;
        let v937: f64 = v934 - v936;
        let v938: f64 = v55 * v937;
        let v939: f64 = v137 * v935;
        let v940: f64 = v134 * v933;
        let v941: f64 = v939 + v940;
        let v942: f64 = v52 * v941;
        let v943: f64 = v938 - v942;
        let v944: f64 = v113 * v943;
        let v945: f64 = v932 + v944;
        let v946: f64 = v4 * v945;
        let v947: f64 = v52 * v926;
        let v948: f64 = v55 * v930;
        let v949: f64 = v947 - v948;
        let v950: f64 = v55 * v941;
        let v951: f64 = v52 * v937;
        let v952: f64 = v950 + v951;
        let v953: f64 = v113 * v952;
        let v954: f64 = v949 + v953;
        let v955: f64 = v2 * v954;
        let v956: f64 = v946 - v955;
        let v957: f64 = v2 * v952;
        let v958: f64 = v4 * v943;
        let v959: f64 = v957 - v958;
        let v960: f64 = v34 * v959;
        let v961: f64 = v956 - v960;
        let v962: f64 = v210 * v731;
        let v963: f64 = v208 * v734;
        let v964: f64 = v962 + v963;
        let v965: f64 = v964 / v301;
        let v966: f64 = v781 * v965;
        let v967: f64 = v961 - v966;
        let v968: f64 = v210 * v824;
        let v969: f64 = v208 * v831;
        let v970: f64 = v968 + v969;
        let v971: f64 = v964 * v872;
        let v972: f64 = v970 - v971;
        let v973: f64 = v972 / v876;
        let v974: f64 = v874 * v973;
        let v975: f64 = v967 - v974;
        let v976: f64 = v210 * v905;
        let v977: f64 = v208 * v910;
        let v978: f64 = v976 + v977;
        let v979: f64 = v978 * v210;
        let v980: f64 = v210 * v914;
        let v981: f64 = v208 * v917;
        let v982: f64 = v980 + v981;
        let v983: f64 = v982 * v208;
        let v984: f64 = v979 + v983;
        let v985: f64 = 0.008649_f64;
        let v986: f64 = v375 + v392;
        let v987: f64 = v985 * v986;
        let v988: f64 = v810 + v807;
        let v989: f64 = v249 * v988;
        (
            v798,
            v805,
            v833,
            v847,
            v851,
            v872,
            v874,
            v876,
            v877,
            v881,
            v883,
            v888,
            v891,
            v912,
            v919,
            v926,
            v930,
            v934,
            v936,
            v939,
            v940,
            v941,
            v943,
            v964,
            v965,
            v970,
            v972,
            v973,
            v975,
            v984,
            v986,
            v987,
            v988,
            v989,
        )
    };
    let (
        v991,
        v1000,
        v1001,
        v1022,
        v1031,
        v1065,
        v1072,
        v1081,
        v1083,
        v1085,
        v1086,
        v1088,
        v1096,
        v1097,
        v1112,
        v1119,
        v1121,
        v1122,
        v1127,
        v1140,
        v1148,
        v1149,
        v1155,
        v1156,
        v1164,
        v1165,
        v1168,
        v1175,
        v1176,
        v1178,
        v1181,
        v1184,
        v1185,
        v1187,
    ) = {
        let v990: f64 = v798 * v989;
        let v991: f64 = v987 + v990;
        let v992: f64 = v984 + v991;
        let v993: f64 = v992 - v987;
        let v994: f64 = v993 - v989;
        let v995: f64 = v994 - v989;
        let v996: f64 = v160 + v995;
        let v997: f64 = v964 * v965;
        let v998: f64 = v996 - v997;
        let v999: f64 = v972 * v973;
        let v1000: f64 = v998 - v999;
        let v1001: f64 = v975 / v1000;
        let v1002: f64 = tau[3];
        let v1003: f64 = v164 * v145;
        let v1004: f64 = v158 * v155;
        let v1005: f64 = v1003 - v1004;
        let v1006: f64 = v153 * v173;
        let v1007: f64 = v142 * v459;
        let v1008: f64 = v1006 - v1007;
        let v1009: f64 = v1005 + v1008;
        let v1010: f64 = v465 * v196;
        let v1011: f64 = v198 * v334;
        let v1012: f64 = v1010 + v1011;
        let v1013: f64 = v1009 - v1012;
        let v1014: f64 = v210 * v492;
        let v1015: f64 = v208 * v522;
        let v1016: f64 = v1014 + v1015;
        let v1017: f64 = v1013 + v1016;
        let v1018: f64 = v1002 - v1017;
        let v1019: f64 = v965 * v784;
        let v1020: f64 = v1018 - v1019;
        let v1021: f64 = v973 * v881;
        let v1022: f64 = v1020 - v1021;
        let v1023: f64 = v1001 * v1022;
        let v1024: f64 = v883 - v1023;
        let v1025: f64 = v557 + v986;
        let v1026: f64 = v185 * v1025;
        let v1027: f64 = v940 + v939;
        let v1028: f64 = v1026 - v1027;
        let v1029: f64 = v120 + v1028;
        let v1030: f64 = v52 * v1029;
        let v1031: f64 = v936 - v934;
        let v1032: f64 = v569 + v1031;
        let v1033: f64 = v55 * v1032;
        let v1034: f64 = v1030 - v1033;
        let v1035: f64 = v4 * v1034;
        let v1036: f64 = v55 * v1029;
        let v1037: f64 = v52 * v1032;
        let v1038: f64 = v1036 + v1037;
        let v1039: f64 = v2 * v1038;
        let v1040: f64 = v1035 + v1039;
        let v1041: f64 = v34 * v1040;
        let v1042: f64 = v85 + v926;
        let v1043: f64 = v52 * v1042;
        let v1044: f64 = v249 * v986;
        let v1045: f64 = v988 + v1044;
        let v1046: f64 = v177 + v1045;
        let v1047: f64 = v185 * v1046;
        let v1048: f64 = v930 + v1047;
        let v1049: f64 = v78 - v1048;
        let v1050: f64 = v55 * v1049;
        let v1051: f64 = v1043 + v1050;
        let v1052: f64 = v113 * v1038;
        let v1053: f64 = v1051 - v1052;
        let v1054: f64 = v2 * v1053;
        let v1055: f64 = v52 * v1049;
        let v1056: f64 = v55 * v1042;
        let v1057: f64 = v1055 - v1056;
        let v1058: f64 = v113 * v1034;
        let v1059: f64 = v1057 - v1058;
        let v1060: f64 = v4 * v1059;
        let v1061: f64 = v1054 + v1060;
        let v1062: f64 = v1041 - v1061;
        let v1063: f64 = v185 * v759;
        let v1064: f64 = v964 - v1063;
        let v1065: f64 = v1064 / v301;
        let v1066: f64 = v781 * v1065;
        let v1067: f64 = v1062 - v1066;
        let v1068: f64 = v185 * v847;
        let v1069: f64 = v970 + v1068;
        let v1070: f64 = v1064 * v872;
        let v1071: f64 = v1069 - v1070;
        let v1072: f64 = v1071 / v876;
        let v1073: f64 = v874 * v1072;
        let v1074: f64 = v1067 - v1073;
        let v1075: f64 = v185 * v941;
        let v1076: f64 = v996 - v1075;
        let v1077: f64 = v1064 * v965;
        let v1078: f64 = v1076 - v1077;
        let v1079: f64 = v1071 * v973;
        let v1080: f64 = v1078 - v1079;
        let v1081: f64 = v1080 / v1000;
        let v1082: f64 = v975 * v1081;
        let v1083: f64 = v1074 - v1082;
        let v1084: f64 = 0.15386006249999998_f64;
        let v1085: f64 = v1084 * v1025;
        let v1086: f64 = v185 * v1027;
        let v1087: f64 = v798 * v1086;
        let v1088: f64 = v1085 - v1087;
        let v1089: f64 = v996 + v1088;
        let v1090: f64 = v87 + v1089;
        let v1091: f64 = v1064 * v1065;
        let v1092: f64 = v1090 - v1091;
        let v1093: f64 = v1071 * v1072;
        let v1094: f64 = v1092 - v1093;
        let v1095: f64 = v1080 * v1081;
        let v1096: f64 = v1094 - v1095;
        let v1097: f64 = v1083 / v1096;
        let v1098: f64 = tau[2];
        let v1099: f64 = v85 * v63;
        let v1100: f64 = v78 * v73;
        let v1101: f64 = v1099 + v1100;
        let v1102: f64 = v60 * v615;
        let v1103: f64 = v71 * v83;
        let v1104: f64 = v1102 + v1103;
        let v1105: f64 = v1101 - v1104;
        let v1106: f64 = v120 * v184;
        let v1107: f64 = v569 * v118;
        let v1108: f64 = v1106 - v1107;
        let v1109: f64 = v1105 + v1108;
        let v1110: f64 = v1109 + v1017;
        let v1111: f64 = v185 * v639;
        let v1112: f64 = v1110 + v1111;
        let v1113: f64 = v1098 - v1112;
        let v1114: f64 = v1065 * v784;
        let v1115: f64 = v1113 - v1114;
        let v1116: f64 = v1072 * v881;
        let v1117: f64 = v1115 - v1116;
        let v1118: f64 = v1081 * v1022;
        let v1119: f64 = v1117 - v1118;
        let v1120: f64 = v1097 * v1119;
        let v1121: f64 = v1024 - v1120;
        let v1122: f64 = v566 + v1025;
        let v1123: f64 = v101 * v1122;
        let v1124: f64 = v1034 + v1123;
        let v1125: f64 = v43 + v1124;
        let v1126: f64 = v4 * v1125;
        let v1127: f64 = v1037 + v1036;
        let v1128: f64 = v662 + v1127;
        let v1129: f64 = v2 * v1128;
        let v1130: f64 = v1126 + v1129;
        let v1131: f64 = v34 * v1130;
        let v1132: f64 = v113 * v1127;
        let v1133: f64 = v1051 - v1132;
        let v1134: f64 = v25 + v1133;
        let v1135: f64 = v2 * v1134;
        let v1136: f64 = -0.0508725_f64;
        let v1137: f64 = v1136 * v1122;
        let v1138: f64 = v1057 - v1137;
        let v1139: f64 = v1138 - v1058;
        let v1140: f64 = v95 + v1046;
        let v1141: f64 = v101 * v1140;
        let v1142: f64 = v1139 - v1141;
        let v1143: f64 = v15 + v1142;
        let v1144: f64 = v4 * v1143;
        let v1145: f64 = v1135 + v1144;
        let v1146: f64 = v1131 - v1145;
        let v1147: f64 = v101 * v761;
        let v1148: f64 = v1064 + v1147;
        let v1149: f64 = v1148 / v301;
        let v1150: f64 = v781 * v1149;
        let v1151: f64 = v1146 - v1150;
        let v1152: f64 = v101 * v851;
        let v1153: f64 = v1069 + v1152;
        let v1154: f64 = v1148 * v872;
        let v1155: f64 = v1153 - v1154;
        let v1156: f64 = v1155 / v876;
        let v1157: f64 = v874 * v1156;
        let v1158: f64 = v1151 - v1157;
        let v1159: f64 = v101 * v943;
        let v1160: f64 = v1076 + v1159;
        let v1161: f64 = v1148 * v965;
        let v1162: f64 = v1160 - v1161;
        let v1163: f64 = v1155 * v973;
        let v1164: f64 = v1162 - v1163;
        let v1165: f64 = v1164 / v1000;
        let v1166: f64 = v975 * v1165;
        let v1167: f64 = v1158 - v1166;
        let v1168: f64 = v101 * v1034;
        let v1169: f64 = v1090 + v1168;
        let v1170: f64 = v1148 * v1065;
        let v1171: f64 = v1169 - v1170;
        let v1172: f64 = v1155 * v1072;
        let v1173: f64 = v1171 - v1172;
        let v1174: f64 = v1164 * v1081;
        let v1175: f64 = v1173 - v1174;
        let v1176: f64 = v1175 / v1096;
        let v1177: f64 = v1083 * v1176;
        let v1178: f64 = v1167 - v1177;
        let v1179: f64 = 0.19495308999999997_f64;
        let v1180: f64 = v1179 * v1122;
        let v1181: f64 = v113 * v1140;
        let v1182: f64 = v1181 + v1168;
        let v1183: f64 = v798 * v1182;
        let v1184: f64 = v1180 + v1183;
        let v1185: f64 = v1090 + v1184;
        let v1186: f64 = 0.01432809_f64;
        let v1187: f64 = v1186 * v1122;
        (
            v991,
            v1000,
            v1001,
            v1022,
            v1031,
            v1065,
            v1072,
            v1081,
            v1083,
            v1085,
            v1086,
            v1088,
            v1096,
            v1097,
            v1112,
            v1119,
            v1121,
            v1122,
            v1127,
            v1140,
            v1148,
            v1149,
            v1155,
            v1156,
            v1164,
            v1165,
            v1168,
            v1175,
            v1176,
            v1178,
            v1181,
            v1184,
            v1185,
            v1187,
        )
    };
    let (v1344, v1347, v1352, v1359, v1368, v1379) = {
        let v1188: f64 = v1185 - v1187;
        let v1189: f64 = v1188 - v1181;
        let v1190: f64 = v1189 - v1181;
        let v1191: f64 = v23 + v1190;
        let v1192: f64 = v1148 * v1149;
        let v1193: f64 = v1191 - v1192;
        let v1194: f64 = v1155 * v1156;
        let v1195: f64 = v1193 - v1194;
        let v1196: f64 = v1164 * v1165;
        let v1197: f64 = v1195 - v1196;
        let v1198: f64 = v1175 * v1176;
        let v1199: f64 = v1197 - v1198;
        let v1200: f64 = v1178 / v1199;
        let v1201: f64 = tau[1];
        let v1202: f64 = v25 * v8;
        let v1203: f64 = v15 * v12;
        let v1204: f64 = v1202 - v1203;
        let v1205: f64 = v11 * v21;
        let v1206: f64 = v6 * v688;
        let v1207: f64 = v1205 - v1206;
        let v1208: f64 = v1204 + v1207;
        let v1209: f64 = v43 * v100;
        let v1210: f64 = v662 * v41;
        let v1211: f64 = v1209 - v1210;
        let v1212: f64 = v1208 + v1211;
        let v1213: f64 = v1212 + v1112;
        let v1214: f64 = v101 * v712;
        let v1215: f64 = v1213 + v1214;
        let v1216: f64 = v1201 - v1215;
        let v1217: f64 = v1149 * v784;
        let v1218: f64 = v1216 - v1217;
        let v1219: f64 = v1156 * v881;
        let v1220: f64 = v1218 - v1219;
        let v1221: f64 = v1165 * v1022;
        let v1222: f64 = v1220 - v1221;
        let v1223: f64 = v1176 * v1119;
        let v1224: f64 = v1222 - v1223;
        let v1225: f64 = v1200 * v1224;
        let v1226: f64 = v1121 - v1225;
        let v1227: f64 = params[9];
        let v1228: f64 = v805 + v991;
        let v1229: f64 = v135 + v1228;
        let v1230: f64 = v134 * v1229;
        let v1231: f64 = v147 + v833;
        let v1232: f64 = v137 * v1231;
        let v1233: f64 = v1230 - v1232;
        let v1234: f64 = v1233 * v134;
        let v1235: f64 = v888 * v208;
        let v1236: f64 = v891 * v210;
        let v1237: f64 = v1235 - v1236;
        let v1238: f64 = v147 + v1237;
        let v1239: f64 = v134 * v1238;
        let v1240: f64 = v912 * v208;
        let v1241: f64 = v919 * v210;
        let v1242: f64 = v1240 - v1241;
        let v1243: f64 = v1242 + v991;
        let v1244: f64 = v168 + v1243;
        let v1245: f64 = v137 * v1244;
        let v1246: f64 = v1239 - v1245;
        let v1247: f64 = v1246 * v137;
        let v1248: f64 = v1234 - v1247;
        let v1249: f64 = v1248 + v1088;
        let v1250: f64 = v53 + v1249;
        let v1251: f64 = v52 * v1250;
        let v1252: f64 = v134 * v1244;
        let v1253: f64 = v137 * v1238;
        let v1254: f64 = v1252 + v1253;
        let v1255: f64 = v1254 * v137;
        let v1256: f64 = v134 * v1231;
        let v1257: f64 = v137 * v1229;
        let v1258: f64 = v1256 + v1257;
        let v1259: f64 = v1258 * v134;
        let v1260: f64 = v1255 - v1259;
        let v1261: f64 = v185 * v1031;
        let v1262: f64 = v1260 - v1261;
        let v1263: f64 = v65 + v1262;
        let v1264: f64 = v55 * v1263;
        let v1265: f64 = v1251 + v1264;
        let v1266: f64 = v1265 * v52;
        let v1267: f64 = v1246 * v134;
        let v1268: f64 = v1233 * v137;
        let v1269: f64 = v1267 + v1268;
        let v1270: f64 = v1269 + v1261;
        let v1271: f64 = v65 - v1270;
        let v1272: f64 = v52 * v1271;
        let v1273: f64 = v1254 * v134;
        let v1274: f64 = v1258 * v137;
        let v1275: f64 = v1273 + v1274;
        let v1276: f64 = v1275 + v1088;
        let v1277: f64 = v1276 - v1085;
        let v1278: f64 = v1277 + v1086;
        let v1279: f64 = v1278 + v1086;
        let v1280: f64 = v81 + v1279;
        let v1281: f64 = v55 * v1280;
        let v1282: f64 = v1272 + v1281;
        let v1283: f64 = v1282 * v55;
        let v1284: f64 = v1266 + v1283;
        let v1285: f64 = v1284 + v1184;
        let v1286: f64 = v3 + v1285;
        let v1287: f64 = v2 * v1286;
        let v1288: f64 = v52 * v1263;
        let v1289: f64 = v55 * v1250;
        let v1290: f64 = v1288 - v1289;
        let v1291: f64 = v1290 * v52;
        let v1292: f64 = v52 * v1280;
        let v1293: f64 = v55 * v1271;
        let v1294: f64 = v1292 - v1293;
        let v1295: f64 = v1294 * v55;
        let v1296: f64 = v1291 + v1295;
        let v1297: f64 = v101 * v1127;
        let v1298: f64 = v1296 - v1297;
        let v1299: f64 = v10 + v1298;
        let v1300: f64 = v4 * v1299;
        let v1301: f64 = v1287 + v1300;
        let v1302: f64 = v1301 * v2;
        let v1303: f64 = v1282 * v52;
        let v1304: f64 = v1265 * v55;
        let v1305: f64 = v1303 - v1304;
        let v1306: f64 = v1305 - v1297;
        let v1307: f64 = v10 + v1306;
        let v1308: f64 = v2 * v1307;
        let v1309: f64 = v1294 * v52;
        let v1310: f64 = v1290 * v55;
        let v1311: f64 = v1309 - v1310;
        let v1312: f64 = v1311 + v1184;
        let v1313: f64 = 0.18062499999999998_f64;
        let v1314: f64 = v1313 * v1122;
        let v1315: f64 = v1312 - v1314;
        let v1316: f64 = v1315 - v1168;
        let v1317: f64 = v1316 - v1168;
        let v1318: f64 = v19 + v1317;
        let v1319: f64 = v4 * v1318;
        let v1320: f64 = v1308 + v1319;
        let v1321: f64 = v1320 * v4;
        let v1322: f64 = v1302 + v1321;
        let v1323: f64 = 0.0184552225_f64;
        let v1324: f64 = v658 + v1122;
        let v1325: f64 = v1323 * v1324;
        let v1326: f64 = v113 * v1122;
        let v1327: f64 = v1140 + v1326;
        let v1328: f64 = v33 + v1327;
        let v1329: f64 = v34 * v1328;
        let v1330: f64 = v798 * v1329;
        let v1331: f64 = v1325 + v1330;
        let v1332: f64 = v1322 + v1331;
        let v1333: f64 = v1227 + v1332;
        let v1334: f64 = v781 * v782;
        let v1335: f64 = v1333 - v1334;
        let v1336: f64 = v874 * v877;
        let v1337: f64 = v1335 - v1336;
        let v1338: f64 = v975 * v1001;
        let v1339: f64 = v1337 - v1338;
        let v1340: f64 = v1083 * v1097;
        let v1341: f64 = v1339 - v1340;
        let v1342: f64 = v1178 * v1200;
        let v1343: f64 = v1341 - v1342;
        let v1344: f64 = v1226 / v1343;
        let v1345: f64 = v1224 / v1199;
        let v1346: f64 = v1200 * v1344;
        let v1347: f64 = v1345 - v1346;
        let v1348: f64 = v1119 / v1096;
        let v1349: f64 = v1097 * v1344;
        let v1350: f64 = v1348 - v1349;
        let v1351: f64 = v1176 * v1347;
        let v1352: f64 = v1350 - v1351;
        let v1353: f64 = v1022 / v1000;
        let v1354: f64 = v1001 * v1344;
        let v1355: f64 = v1353 - v1354;
        let v1356: f64 = v1165 * v1347;
        let v1357: f64 = v1355 - v1356;
        let v1358: f64 = v1081 * v1352;
        let v1359: f64 = v1357 - v1358;
        let v1360: f64 = v881 / v876;
        let v1361: f64 = v877 * v1344;
        let v1362: f64 = v1360 - v1361;
        let v1363: f64 = v1156 * v1347;
        let v1364: f64 = v1362 - v1363;
        let v1365: f64 = v1072 * v1352;
        let v1366: f64 = v1364 - v1365;
        let v1367: f64 = v973 * v1359;
        let v1368: f64 = v1366 - v1367;
        let v1369: f64 = v784 / v301;
        let v1370: f64 = v782 * v1344;
        let v1371: f64 = v1369 - v1370;
        let v1372: f64 = v1149 * v1347;
        let v1373: f64 = v1371 - v1372;
        let v1374: f64 = v1065 * v1352;
        let v1375: f64 = v1373 - v1374;
        let v1376: f64 = v965 * v1359;
        let v1377: f64 = v1375 - v1376;
        let v1378: f64 = v872 * v1368;
        let v1379: f64 = v1377 - v1378;
        (v1344, v1347, v1352, v1359, v1368, v1379)
    };
    [v1344, v1347, v1352, v1359, v1368, v1379]
}
const _: &str = include_str!(
    concat!(env!("CARGO_MANIFEST_DIR"), "/", "models/ur5_parametric.json")
);
